#!/usr/bin/env python3
"""Writes a tiny Quake III BSP (IBSP 46) and broken variants of it for collbake's tests
(tools/collbake/test_bsp.sh). Usage: make_test_bsp.py OUTDIR

good.bsp, world model (model 0):
  surface 0  planar, shader 0 (solid): floor quad x 0..100, y 0..100, z 0 -> 2 triangles
  surface 1  triangle soup, shader 0: one triangle                      -> 1 triangle
  surface 2  patch 3x3, shader 0: curved, z 0..64, y 200..300           -> 32 triangles (4x4 quads)
  surface 3  planar, shader 1 (water: no CONTENTS_SOLID)                -> skipped
  surface 4  planar, shader 2 (solid but SURF_NONSOLID)                 -> skipped
  surface 5  flare                                                      -> skipped
model 1 (a door): surface 6 planar, shader 0                            -> 2 triangles with --bsp-all-models
So: 35 triangles (world), 37 with --bsp-all-models. In metres (0.032 m/unit, Z up -> Y up):
x 0..3.2, y (up) 0..2.048, z -9.6..0.
"""
import os
import random
import struct
import sys

HDR = 8 + 17 * 8


def shader(name, surf, contents):
    return struct.pack("<64sii", name.encode(), surf, contents)


def vert(x, y, z):
    return struct.pack("<3f2f2f3f4B", x, y, z, 0, 0, 0, 0, 0, 0, 1, 255, 255, 255, 255)


def surface(shader_num, stype, first_vert, nverts, first_index, nindexes, pw=0, ph=0):
    return struct.pack("<12i3f9f2i", shader_num, -1, stype, first_vert, nverts, first_index, nindexes, 0, 0, 0, 0, 0,
                       *([0.0] * 12), pw, ph)


def build(mutate=None):
    shaders = [shader("textures/solid", 0, 1), shader("textures/water", 0, 32), shader("textures/nonsolid", 0x4000, 1)]
    verts, idx, surfs = [], [], []

    def add_planar(sh, pts, stype=1):
        fv, fi = len(verts), len(idx)
        verts.extend(vert(*p) for p in pts)
        tri = [0, 1, 2, 0, 2, 3] if len(pts) == 4 else [0, 1, 2]
        idx.extend(tri)
        surfs.append(surface(sh, stype, fv, len(pts), fi, len(tri)))

    add_planar(0, [(0, 0, 0), (100, 0, 0), (100, 100, 0), (0, 100, 0)])
    add_planar(0, [(0, 0, 32), (50, 0, 32), (0, 50, 32)], stype=3)
    fv = len(verts)
    for row, z in enumerate((64, 0, 64)):
        for col in range(3):
            verts.append(vert(col * 50, 200 + row * 50, z))
    surfs.append(surface(0, 2, fv, 9, 0, 0, 3, 3))
    add_planar(1, [(0, 0, -10), (100, 0, -10), (100, 100, -10), (0, 100, -10)])
    add_planar(2, [(0, 0, -20), (100, 0, -20), (100, 100, -20), (0, 100, -20)])
    surfs.append(surface(0, 4, 0, 0, 0, 0))
    add_planar(0, [(0, 0, 10), (10, 0, 10), (10, 0, 20), (0, 0, 20)])  # the door (model 1)
    models = [struct.pack("<6f4i", 0, 0, -64, 100, 300, 64, 0, 6, 0, 0),
              struct.pack("<6f4i", 0, 0, 10, 10, 0, 20, 6, 1, 0, 0)]
    lumps = {1: b"".join(shaders), 7: b"".join(models), 10: b"".join(verts),
             11: b"".join(struct.pack("<i", i) for i in idx), 13: b"".join(surfs)}
    if mutate:
        mutate(lumps)
    body, dirs, off = b"", [], HDR
    for k in range(17):
        data = lumps.get(k, b"")
        dirs.append((off, len(data)))
        body += data
        off += len(data)
    head = b"IBSP" + struct.pack("<i", 46) + b"".join(struct.pack("<ii", o, n) for o, n in dirs)
    return bytearray(head + body)


def patch_surface(lumps, k, **kw):
    s = bytearray(lumps[13])
    base = 104 * k
    fields = {"shader": 0, "type": 8, "first_vert": 12, "nverts": 16, "first_index": 20, "nindexes": 24,
              "pw": 96, "ph": 100}
    for name, val in kw.items():
        struct.pack_into("<i", s, base + fields[name], val)
    lumps[13] = bytes(s)


def main():
    out = sys.argv[1]
    os.makedirs(out, exist_ok=True)
    good = build()
    open(os.path.join(out, "good.bsp"), "wb").write(good)
    bad = {}
    # truncations: the header, inside the lump directory, and every 97th byte of the body
    for n in [0, 3, 4, 7, 8, 100, HDR - 1, HDR] + list(range(HDR + 1, len(good), 97)) + [len(good) - 1]:
        bad["trunc_%d" % n] = good[:n]
    v = bytearray(good); struct.pack_into("<i", v, 4, 47); bad["version_47"] = v
    v = bytearray(good); v[0:4] = b"IBSQ"; bad["magic"] = v  # not a BSP: assimp's turn, must be refused too
    v = bytearray(good); struct.pack_into("<i", v, 8 + 8 * 13, 0x7FFFFFF0); bad["lump_offset_huge"] = v
    v = bytearray(good); struct.pack_into("<i", v, 8 + 8 * 13 + 4, -104); bad["lump_length_negative"] = v
    v = bytearray(good); o, n = struct.unpack_from("<ii", v, 8 + 8 * 10); struct.pack_into("<i", v, 8 + 8 * 10 + 4, n - 4)
    bad["lump_length_not_multiple"] = v

    def idx_bad(l):
        l[11] = struct.pack("<i", 99) + l[11][4:]
    bad["index_outside"] = build(idx_bad)
    bad["index_negative"] = build(lambda l: l.__setitem__(11, struct.pack("<i", -1) + l[11][4:]))
    bad["patch_even_width"] = build(lambda l: patch_surface(l, 2, pw=4, nverts=12))
    bad["patch_wrong_count"] = build(lambda l: patch_surface(l, 2, nverts=8))
    bad["patch_huge"] = build(lambda l: patch_surface(l, 2, pw=99999, ph=3))
    bad["shader_outside"] = build(lambda l: patch_surface(l, 0, shader=99))
    bad["verts_outside"] = build(lambda l: patch_surface(l, 0, first_vert=1000))
    bad["indexes_outside"] = build(lambda l: patch_surface(l, 1, nindexes=3000))
    bad["indexes_not_triples"] = build(lambda l: patch_surface(l, 0, nindexes=5))

    def nan_vert(l):
        l[10] = struct.pack("<f", float("nan")) + l[10][4:]
    bad["nan_vertex"] = build(nan_vert)
    bad["world_surfaces_outside"] = build(lambda l: l.__setitem__(7, struct.pack("<6f4i", 0, 0, 0, 1, 1, 1, 5, 9, 0, 0)))
    bad["no_models"] = build(lambda l: l.__setitem__(7, b""))
    bad["only_water"] = build(lambda l: [patch_surface(l, k, shader=1) for k in range(3)])
    for name, data in bad.items():
        open(os.path.join(out, "bad_%s.bsp" % name), "wb").write(data)
    # random corruption: must bake or be refused, never crash (checked under ASan)
    rng = random.Random(12)
    for k in range(60):
        v = bytearray(good)
        for _ in range(rng.randint(1, 8)):
            i = rng.randrange(len(v))
            v[i] = rng.randrange(256)
        open(os.path.join(out, "fuzz_%02d.bsp" % k), "wb").write(v)
    # the loss rule: 1 good triangle and 3 that weld away (99 % of 4 lost)
    open(os.path.join(out, "lossy.obj"), "w").write(
        "v 0 0 0\nv 1 0 0\nv 0 0 1\nv 0.00001 0 0\nv 0 0.00001 0\nf 1 2 3\nf 1 4 5\nf 1 4 2\nf 5 1 4\n")
    open(os.path.join(out, "cluster.obj"), "w").write(cluster_obj())
    # a 4 x 4 m floor of 1 m quads: the runtime's automatic grid is dense (--cell-choice cost keeps it)
    open(os.path.join(out, "floor.obj"), "w").write(
        "".join("v %d 0 %d\n" % (x, z) for z in range(5) for x in range(5)) +
        "".join("f %d %d %d\nf %d %d %d\n" % (1 + x + 5 * z, 1 + x + 5 * (z + 1), 2 + x + 5 * (z + 1),
                                                1 + x + 5 * z, 2 + x + 5 * (z + 1), 2 + x + 5 * z)
                for z in range(4) for x in range(4)))


def cluster_obj():
    """--cell-choice cost: a 40 x 10 x 40 m room of 1 m quads (floor and ceiling) with a dense
    cluster of 4000 small triangles (20 layers of 10 x 10 quads of 0.2 m) in its middle; the
    runtime's automatic cell is a fine hashed grid there (1.25 m, 8192 buckets)."""
    vs, fs = [], []

    def quad(a, b, c, d):
        i = len(vs)
        vs.extend([a, b, c, d])
        fs.append((i + 1, i + 2, i + 3))
        fs.append((i + 1, i + 3, i + 4))
    for x in range(40):
        for z in range(40):
            quad((x, 0, z), (x, 0, z + 1), (x + 1, 0, z + 1), (x + 1, 0, z))
            quad((x, 10, z), (x + 1, 10, z), (x + 1, 10, z + 1), (x, 10, z + 1))
    for k in range(20):
        for i in range(10):
            for j in range(10):
                x, y, z = 19 + 0.2 * i, 0.5 + 0.1 * k, 19 + 0.2 * j
                quad((x, y, z), (x, y, z + 0.2), (x + 0.2, y, z + 0.2), (x + 0.2, y, z))
    return "".join("v %g %g %g\n" % v for v in vs) + "".join("f %d %d %d\n" % f for f in fs)


if __name__ == "__main__":
    main()
