#!/usr/bin/env python3
"""Generates the bundled sample levels under assets/levels/ (python3 standard library only).

    python3 tools/gen_levels.py [OUTDIR]      (default: assets/levels next to this script)

Writes, deterministically (the outputs are committed; re-running gives identical bytes):
  test_course.gltf          the test course: floor, stairs, ramps, steep slopes, V-corners,
                            ledges and drops, low ceiling, long and thin walls, pillars
  platform_translate.gltf   four moving platforms, one file each (the example places and moves them)
  platform_rotate.gltf
  platform_scale.gltf
  platform_lift.gltf
  planet.gltf               geodesic sphere, radius 20 m, centred at the origin
  stairs_cm.obj             a small staircase in CENTIMETERS (baked with --scale 0.01)
  <name>.expect             what the baked mesh must contain, computed here independently
                            of collbake: triangle count, bounds, surface area
  README.md                 feature coordinates, spawn point, suggested platform motions

glTF 2.0, Y up, meters, buffers embedded as base64 data URIs. Collision geometry lives in
nodes/meshes named *_coll; test_course.gltf also holds a decorative 'signpost_visual' node
that must NOT be baked (mk/bake.mk bakes it with --only '*_coll').
"""
import base64
import json
import math
import os
import struct
import sys

MAX_EDGE = 4.0  # long quads are split into tiles no longer than this (keeps grid cells light)


# ---------------------------------------------------------------- small vector helpers
def sub(a, b): return (a[0] - b[0], a[1] - b[1], a[2] - b[2])
def add(a, b): return (a[0] + b[0], a[1] + b[1], a[2] + b[2])
def scl(a, s): return (a[0] * s, a[1] * s, a[2] * s)
def cross(a, b): return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])
def length(a): return math.sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2])
def lerp(a, b, t): return add(a, scl(sub(b, a), t))
def r6(x):  # round coordinates so the files are stable and human-diffable
    v = round(x, 6)
    return 0.0 if v == 0 else v


class Mesh:
    """Indexed triangle list; identical positions are shared within a mesh."""

    def __init__(self, name, max_edge=MAX_EDGE):
        self.name = name
        self.max_edge = max_edge
        self.verts = []
        self.tris = []
        self._index = {}

    def v(self, p):
        key = (r6(p[0]), r6(p[1]), r6(p[2]))
        i = self._index.get(key)
        if i is None:
            i = len(self.verts)
            self.verts.append(key)
            self._index[key] = i
        return i

    def tri(self, a, b, c):
        ia, ib, ic = self.v(a), self.v(b), self.v(c)
        if len({ia, ib, ic}) < 3:
            raise ValueError("degenerate triangle in %s" % self.name)
        if length(cross(sub(self.verts[ib], self.verts[ia]), sub(self.verts[ic], self.verts[ia]))) < 1e-9:
            raise ValueError("zero-area triangle in %s" % self.name)
        self.tris.append((ia, ib, ic))

    def quad(self, a, b, c, d, max_edge=None):
        """Quad a-b-c-d (counter-clockwise seen from the front), split into <= max_edge tiles."""
        max_edge = max_edge or self.max_edge
        nu = max(1, int(math.ceil(max(length(sub(b, a)), length(sub(c, d))) / max_edge - 1e-9)))
        nv = max(1, int(math.ceil(max(length(sub(d, a)), length(sub(c, b))) / max_edge - 1e-9)))
        for i in range(nu):
            for j in range(nv):
                def at(u, w):
                    return lerp(lerp(a, b, u), lerp(d, c, u), w)
                p00, p10 = at(i / nu, j / nv), at((i + 1) / nu, j / nv)
                p11, p01 = at((i + 1) / nu, (j + 1) / nv), at(i / nu, (j + 1) / nv)
                self.tri(p00, p10, p11)
                self.tri(p00, p11, p01)

    def box(self, lo, hi, bottom=False):
        """Axis-aligned box, outward faces. bottom=False leaves out the face resting on the floor."""
        x0, y0, z0 = lo
        x1, y1, z1 = hi
        P = lambda x, y, z: (x, y, z)
        self.quad(P(x0, y1, z0), P(x0, y1, z1), P(x1, y1, z1), P(x1, y1, z0))  # top    +Y
        if bottom:
            self.quad(P(x0, y0, z0), P(x1, y0, z0), P(x1, y0, z1), P(x0, y0, z1))  # bottom -Y
        self.quad(P(x0, y0, z1), P(x1, y0, z1), P(x1, y1, z1), P(x0, y1, z1))  # +Z
        self.quad(P(x1, y0, z0), P(x0, y0, z0), P(x0, y1, z0), P(x1, y1, z0))  # -Z
        self.quad(P(x1, y0, z1), P(x1, y0, z0), P(x1, y1, z0), P(x1, y1, z1))  # +X
        self.quad(P(x0, y0, z0), P(x0, y0, z1), P(x0, y1, z1), P(x0, y1, z0))  # -X

    def oriented_box(self, center, half, yaw, bottom=False):
        """Box rotated by yaw (radians, about +Y) around its centre."""
        c, s = math.cos(yaw), math.sin(yaw)
        def P(sx, sy, sz):
            x, y, z = sx * half[0], sy * half[1], sz * half[2]
            return (center[0] + c * x + s * z, center[1] + y, center[2] - s * x + c * z)
        self.quad(P(-1, 1, -1), P(-1, 1, 1), P(1, 1, 1), P(1, 1, -1))
        if bottom:
            self.quad(P(-1, -1, -1), P(1, -1, -1), P(1, -1, 1), P(-1, -1, 1))
        self.quad(P(-1, -1, 1), P(1, -1, 1), P(1, 1, 1), P(-1, 1, 1))
        self.quad(P(1, -1, -1), P(-1, -1, -1), P(-1, 1, -1), P(1, 1, -1))
        self.quad(P(1, -1, 1), P(1, -1, -1), P(1, 1, -1), P(1, 1, 1))
        self.quad(P(-1, -1, -1), P(-1, -1, 1), P(-1, 1, 1), P(-1, 1, -1))

    def cylinder(self, center, radius, y0, y1, sides, top=True, bottom=False):
        ring = [(center[0] + radius * math.cos(2 * math.pi * k / sides), center[2] - radius * math.sin(2 * math.pi * k / sides))
                for k in range(sides)]
        for k in range(sides):
            (xa, za), (xb, zb) = ring[k], ring[(k + 1) % sides]
            self.quad((xa, y0, za), (xb, y0, zb), (xb, y1, zb), (xa, y1, za))
        for k in range(1, sides - 1):
            if top:
                self.tri((ring[0][0], y1, ring[0][1]), (ring[k][0], y1, ring[k][1]), (ring[k + 1][0], y1, ring[k + 1][1]))
            if bottom:
                self.tri((ring[0][0], y0, ring[0][1]), (ring[k + 1][0], y0, ring[k + 1][1]), (ring[k][0], y0, ring[k][1]))

    def extrude_profile(self, profile, origin, axis, width, skip_floor=True):
        """Profile: list of (u, y) points, a simple polygon counter-clockwise in the (u, y)
        plane, u along the travel direction `axis` ('+x', '-x', '+z', '-z') starting at
        `origin` (x, z), extruded `width` meters across (centred on the travel line).
        Edges lying on y = 0 (resting on the floor) are left out when skip_floor."""
        ox, oz = origin
        d = {'+x': (1, 0), '-x': (-1, 0), '+z': (0, 1), '-z': (0, -1)}[axis]
        lat = (-d[1], d[0])  # left of travel... any perpendicular works; sides get both caps
        def P(u, y, s):
            return (ox + d[0] * u + lat[0] * s, y, oz + d[1] * u + lat[1] * s)
        h = width / 2.0
        prof = simplify(profile)
        if sum(prof[k - 1][0] * prof[k][1] - prof[k][0] * prof[k - 1][1] for k in range(len(prof))) < 0:
            prof.reverse()  # counter-clockwise
        # sign of the map (u, s) -> (x, z) decides which cap faces which way
        n = len(prof)
        for k in range(n):
            (ua, ya), (ub, yb) = prof[k], prof[(k + 1) % n]
            if skip_floor and ya == 0 and yb == 0:
                continue
            self.quad(P(ua, ya, -h), P(ub, yb, -h), P(ub, yb, h), P(ua, ya, h))
        for (a, b, c) in ear_clip(prof):
            self.tri(P(a[0], a[1], -h), P(c[0], c[1], -h), P(b[0], b[1], -h))
            self.tri(P(a[0], a[1], h), P(b[0], b[1], h), P(c[0], c[1], h))


def simplify(poly):
    """Drops repeated and collinear points (they would make zero-area ears)."""
    out = []
    for p in poly:
        if not out or out[-1] != p:
            out.append(p)
    if out[0] == out[-1]:
        out.pop()
    changed = True
    while changed:
        changed = False
        for k in range(len(out)):
            a, b, c = out[k - 1], out[k], out[(k + 1) % len(out)]
            if abs((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])) < 1e-12:
                del out[k]
                changed = True
                break
    return out


def ear_clip(poly):
    """Triangulates a simple counter-clockwise polygon."""
    def area2(a, b, c):
        return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])
    def inside(p, a, b, c):
        return area2(a, b, p) >= 0 and area2(b, c, p) >= 0 and area2(c, a, p) >= 0
    pts = list(poly)
    s = sum(area2((0, 0), pts[k], pts[(k + 1) % len(pts)]) for k in range(len(pts)))
    if s < 0:
        pts.reverse()
    tris = []
    while len(pts) > 3:
        for k in range(len(pts)):
            a, b, c = pts[k - 1], pts[k], pts[(k + 1) % len(pts)]
            if area2(a, b, c) <= 1e-12:
                continue
            if any(inside(p, a, b, c) for p in pts if p not in (a, b, c)):
                continue
            tris.append((a, b, c))
            del pts[k]
            break
        else:
            raise ValueError("ear clipping failed")
    tris.append((pts[0], pts[1], pts[2]))
    return tris


# ---------------------------------------------------------------- transforms (column-major 4x4)
def mat_trs(t=(0, 0, 0), r=(0, 0, 0, 1), s=(1, 1, 1)):
    x, y, z, w = r
    R = [[1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
         [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
         [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)]]
    return [[R[i][0] * s[0], R[i][1] * s[1], R[i][2] * s[2], t[i]] for i in range(3)] + [[0, 0, 0, 1]]


def mat_mul(a, b):
    return [[sum(a[i][k] * b[k][j] for k in range(4)) for j in range(4)] for i in range(4)]


def mat_apply(m, p):
    return tuple(m[i][0] * p[0] + m[i][1] * p[1] + m[i][2] * p[2] + m[i][3] for i in range(3))


def quat_y(deg):
    a = math.radians(deg) / 2
    return (0.0, r6(math.sin(a)), 0.0, r6(math.cos(a)))


class Node:
    def __init__(self, name, mesh=None, t=None, r=None, s=None, children=()):
        self.name, self.mesh, self.t, self.r, self.s = name, mesh, t, r, s
        self.children = list(children)


# ---------------------------------------------------------------- writers
def write_gltf(path, roots):
    meshes, nodes, blob = [], [], bytearray()
    accessors, views = [], []
    mesh_ids = {}

    def add_view(data, target):
        while len(blob) % 4:
            blob.append(0)
        views.append({"buffer": 0, "byteOffset": len(blob), "byteLength": len(data), "target": target})
        blob.extend(data)
        return len(views) - 1

    def add_mesh(m):
        if id(m) in mesh_ids:
            return mesh_ids[id(m)]
        pos = b"".join(struct.pack("<3f", *p) for p in m.verts)
        idx_fmt, comp = ("<H", 5123) if len(m.verts) < 65536 else ("<I", 5125)
        idx = b"".join(struct.pack(idx_fmt, i) for t in m.tris for i in t)
        f32 = [struct.unpack("<3f", struct.pack("<3f", *p)) for p in m.verts]
        lo = [min(p[k] for p in f32) for k in range(3)]
        hi = [max(p[k] for p in f32) for k in range(3)]
        accessors.append({"bufferView": add_view(pos, 34962), "componentType": 5126, "count": len(m.verts),
                          "type": "VEC3", "min": lo, "max": hi})
        accessors.append({"bufferView": add_view(idx, 34963), "componentType": comp, "count": 3 * len(m.tris),
                          "type": "SCALAR"})
        meshes.append({"name": m.name, "primitives": [{"attributes": {"POSITION": len(accessors) - 2},
                                                       "indices": len(accessors) - 1, "mode": 4}]})
        mesh_ids[id(m)] = len(meshes) - 1
        return mesh_ids[id(m)]

    def add_node(n):
        d = {"name": n.name}
        nodes.append(d)
        k = len(nodes) - 1
        if n.mesh is not None:
            d["mesh"] = add_mesh(n.mesh)
        if n.t:
            d["translation"] = list(n.t)
        if n.r:
            d["rotation"] = list(n.r)
        if n.s:
            d["scale"] = list(n.s)
        if n.children:
            d["children"] = [add_node(c) for c in n.children]
        return k

    scene_nodes = [add_node(n) for n in roots]
    doc = {
        "asset": {"version": "2.0", "generator": "charbody64 tools/gen_levels.py"},
        "scene": 0,
        "scenes": [{"nodes": scene_nodes}],
        "nodes": nodes,
        "meshes": meshes,
        "accessors": accessors,
        "bufferViews": views,
        "buffers": [{"byteLength": len(blob),
                     "uri": "data:application/octet-stream;base64," + base64.b64encode(bytes(blob)).decode()}],
    }
    with open(path, "w") as f:
        json.dump(doc, f, indent=1)
        f.write("\n")


def collect(roots, pattern_suffix="_coll", scale=1.0):
    """World-space triangles of every mesh whose node, ancestor or mesh name ends in _coll."""
    out = []
    def walk(n, parent, inherited):
        m = mat_mul(parent, mat_trs(n.t or (0, 0, 0), n.r or (0, 0, 0, 1), n.s or (1, 1, 1)))
        sel = inherited or n.name.endswith(pattern_suffix)
        if n.mesh is not None and (sel or n.mesh.name.endswith(pattern_suffix)):
            f32 = [struct.unpack("<3f", struct.pack("<3f", *p)) for p in n.mesh.verts]
            for t in n.mesh.tris:
                out.append(tuple(scl(mat_apply(m, f32[i]), scale) for i in t))
        for c in n.children:
            walk(c, m, sel)
    ident = mat_trs()
    for r in roots:
        walk(r, ident, False)
    return out


def write_expect(path, tris, note):
    lo = [min(p[k] for t in tris for p in t) for k in range(3)]
    hi = [max(p[k] for t in tris for p in t) for k in range(3)]
    area = sum(length(cross(sub(t[1], t[0]), sub(t[2], t[0]))) / 2 for t in tris)
    with open(path, "w") as f:
        f.write("# %s\n# computed by tools/gen_levels.py from the source geometry (not by collbake)\n" % note)
        f.write("triangles %d\n" % len(tris))
        f.write("bounds %.6f %.6f %.6f %.6f %.6f %.6f\n" % (lo[0], lo[1], lo[2], hi[0], hi[1], hi[2]))
        f.write("area %.4f\n" % area)
    return len(tris), lo, hi


# ---------------------------------------------------------------- the test course
FEATURES = []  # (name, where, notes) rows for the README


def feature(name, where, notes):
    FEATURES.append((name, where, notes))


def stairs_profile(riser, steps, tread, top):
    """`steps` risers up (tread apart), a flat top `top` long from the last riser up to the
    first riser down, `steps` risers down. Returns the (u, y) outline and its length."""
    pts = [(0.0, 0.0)]
    u, y = 0.0, 0.0
    for k in range(steps):
        y += riser
        pts.append((u, y))
        u += top if k == steps - 1 else tread
        pts.append((u, y))
    for k in range(steps):
        y = 0.0 if k == steps - 1 else y - riser
        pts.append((u, y))
        if k < steps - 1:
            u += tread
            pts.append((u, y))
    return [(r6(a), r6(b)) for a, b in pts], u


def hill_profile(angle_deg, height, flat):
    run = height / math.tan(math.radians(angle_deg))
    pts = [(0.0, 0.0), (run, height), (run + flat, height), (2 * run + flat, 0.0)]
    return [(r6(a), r6(b)) for a, b in pts], 2 * run + flat


def build_course():
    floor = Mesh("floor_coll")
    floor.quad((-40, 0, -40), (-40, 0, 40), (40, 0, 40), (40, 0, -40))
    feature("floor", "x,z in [-40, 40], top y = 0", "tiled 4 m x 4 m; perimeter walls 3 m high just outside")

    walls = Mesh("walls_coll")
    walls.box((-40.5, 0, -40.5), (40.5, 3, -40))
    walls.box((-40.5, 0, 40), (40.5, 3, 40.5))
    walls.box((-40.5, 0, -40), (-40, 3, 40))
    walls.box((40, 0, -40), (40.5, 3, 40))

    # ---- leg A: z = -30, walking +x: stairs and the blocker
    stairs = Mesh("stairs_coll")
    x = -24.0
    for riser in (0.10, 0.20, 0.25):
        prof, L = stairs_profile(riser, 4, 0.5, 2.5)
        stairs.extrude_profile(prof, (x, -30.0), '+x', 4.0)
        feature("stairs riser %.2f m" % riser,
                "x %.1f .. %.1f, z -32 .. -28 (lane centre z = -30)" % (x, x + L),
                "risers up at x = %.1f, %.1f, %.1f, %.1f (tread 0.5); top y = %.2f from x %.1f to %.1f; "
                "risers down at x = %.1f, %.1f, %.1f, %.1f; walk +x"
                % ((x, x + 0.5, x + 1.0, x + 1.5, 4 * riser, x + 1.5, x + 4.0) + tuple(x + 4.0 + 0.5 * k for k in range(4))))
        x += 10.0
    stairs.box((8.0, 0, -32.0), (10.0, 0.35, -28.0))
    feature("blocker 0.35 m", "x 8 .. 10, z -32 .. -28, top y = 0.35",
            "one step higher than step_height 0.25: stops a walk +x along z = -30; go round via z = -26")

    # ---- leg B: x = 30, walking +z: ramps (hills 1 m high), then the steep wedges
    ramps = Mesh("ramps_coll")
    z = -24.0
    for ang in (10, 20, 30, 40, 44):
        prof, L = hill_profile(ang, 1.0, 1.0)
        ramps.extrude_profile(prof, (30.0, z), '+z', 4.0)
        run = 1.0 / math.tan(math.radians(ang))
        feature("ramp %d deg" % ang, "x 28 .. 32, z %.2f .. %.2f (top y = 1 from z %.2f to %.2f)"
                % (z, z + L, z + run, z + run + 1.0),
                "symmetric hill: up %d deg along +z, 1 m flat top, down %d deg" % (ang, ang))
        z = round(z + L + 1.5, 2)
    steep = Mesh("steep_coll")
    for ang, x0 in ((50, 28.0), (60, 30.0)):
        run = 2.0 / math.tan(math.radians(ang))
        steep.extrude_profile([(0.0, 0.0), (r6(run), 2.0), (r6(run), 0.0)], (x0 + 1.0, 16.0), '+z', 2.0)
        feature("steep slope %d deg" % ang, "x %.0f .. %.0f, z 16 .. %.2f, rising +z to y = 2 (vertical back)"
                % (x0, x0 + 2, 16 + run), "steeper than floor_max_angle 45: the body slides back down")

    # ---- leg C: z = 30, walking -x: V-corners (pockets on the +z side), ledges and drops
    vmesh = {}
    for ang in (30, 60, 90):
        m = Mesh("vcorner%d_coll" % ang)
        for sgn in (-1, 1):
            yaw = sgn * math.radians(ang / 2.0)
            L, t = 5.0, 0.2
            # wall from the apex (origin) along the local direction (sin yaw, cos yaw), outer side away from the V
            dx, dz = math.sin(yaw), math.cos(yaw)
            off = t / 2.0
            nx, nz = sgn * dz, -sgn * dx  # outward normal of the wall, away from the V's inside
            c = (dx * L / 2 + nx * off, 1.5, dz * L / 2 + nz * off)
            m.oriented_box(c, (t / 2, 1.5, L / 2), yaw)
        vmesh[ang] = m
    vnodes = []
    for ang, xc in ((30, 20.0), (60, 12.0), (90, 4.0)):
        vnodes.append(Node("vcorner%d_coll" % ang, vmesh[ang], t=(xc, 0.0, 0.0), r=quat_y(180)))
        depth = 5.0 * math.cos(math.radians(ang / 2.0))
        half = 5.0 * math.sin(math.radians(ang / 2.0))
        feature("V-corner %d deg" % ang, "apex (%.0f, 0, 38), mouth z = %.2f, x %.2f .. %.2f"
                % (xc, 38 - depth, xc - half, xc + half),
                "two 3 m walls meeting at %d deg, opening towards -z; walk +z from (%.0f, 0, 30) into it" % (ang, xc))

    ledges = Mesh("ledges_coll")
    run = 1.5 / math.tan(math.radians(15))
    prof = [(0.0, 0.0), (r6(run), 1.5), (r6(run + 6.4), 1.5), (r6(run + 6.4), 1.3), (r6(run + 10.4), 1.3),
            (r6(run + 10.4), 0.0)]
    ledges.extrude_profile(prof, (-2.0, 30.0), '-x', 4.0)
    x1 = -2.0 - run
    feature("ledge plateau", "x %.2f .. -2 ramp 15 deg up (-x) to y = 1.5; plateau y = 1.5 to x = %.2f; z 28 .. 32"
            % (x1, x1 - 6.4), "walk -x along z = 30")
    feature("small drop 0.2 m", "x = %.2f (y 1.5 -> 1.3), z 28 .. 32" % (x1 - 6.4),
            "below floor_snap_distance 0.3: the body stays on the floor")
    feature("large drop 1.3 m", "x = %.2f (y 1.3 -> 0), z 28 .. 32" % (x1 - 10.4),
            "ledge: the body leaves the floor and falls 1.3 m")

    # ---- leg D: x = -30, walking -z: low ceiling, long wall, thin wall
    ceil = Mesh("ceiling_coll")
    ceil.box((-33.0, 2.5, 14.0), (-27.0, 2.8, 22.0), bottom=True)
    for px in (-33.0, -27.4):
        for pz in (14.0, 21.6):
            ceil.box((px, 0.0, pz), (px + 0.4, 2.5, pz + 0.4))
    feature("low ceiling", "x -33 .. -27, z 14 .. 22, underside y = 2.5 (slab 0.3 m)",
            "0.5 m above a 2 m body; four 0.4 m posts at the slab corners, outside the lane x -32 .. -28")
    walls.box((-34.3, 0, -20.0), (-34.0, 3.0, 10.0))
    feature("long wall", "x -34.3 .. -34, z -20 .. 10, 3 m high", "slide along it walking -z with a -x component")
    walls.box((-34.0, 0, -0.005), (-30.0, 3.0, 0.005))
    feature("thin wall 1 cm", "x -34 .. -30, z -0.005 .. 0.005, 3 m high",
            "blocks x < -30 walking -z along x = -31; passes at x = -29 (tunnelling test)")
    walls.box((-12.0, 0, -4.005), (-8.0, 3.0, -3.995))
    feature("thin wall 1 cm (interior)", "x -12 .. -8, z -4.005 .. -3.995, 3 m high", "free-standing")
    walls.box((-15.0, 0, 14.85), (15.0, 3.0, 15.15))
    feature("long wall (interior)", "x -15 .. 15, z 14.85 .. 15.15, 3 m high", "30 m")

    pillar = Mesh("pillar_coll")
    pillar.cylinder((0, 0, 0), 0.4, 0.0, 3.0, 16)
    pillars = []
    for k, pz in enumerate((-4.0, -8.0, -12.0, -16.0, -20.0)):
        pillars.append(Node("pillar%d_coll" % k, pillar, t=(-25.0, 0.0, pz), s=(1.0, 1.5, 1.0) if k == 4 else None))
    feature("pillars", "x = -25, z = -4, -8, -12, -16, -20; radius 0.4",
            "16-sided, 3 m high (the one at z = -20 is 4.5 m: node scale y 1.5)")

    sign = Mesh("signpost_visual")
    sign.box((-0.1, 0.0, -0.5), (0.1, 6.0, 0.5))
    feature("signpost_visual", "(-26, 0, -26), 6 m high", "decoration, NOT collision: baked with --only '*_coll'")

    roots = [Node("test_course", children=[
        Node("floor_coll", floor), Node("walls_coll", walls), Node("stairs_coll", stairs),
        Node("ramps_coll", ramps), Node("steep_coll", steep), Node("ledges_coll", ledges),
        Node("ceiling_coll", ceil),
        Node("vcorners_coll", None, t=(0.0, 0.0, 38.0), children=vnodes),
        Node("pillars", None, children=pillars),
        Node("signpost_visual", sign, t=(-26.0, 0.0, -26.0)),
    ])]
    return roots


def build_platforms():
    out = {}
    m = Mesh("platform_translate_coll")
    m.box((-2, -0.3, -2), (2, 0, 2), bottom=True)
    out["platform_translate"] = (m, "4 x 4 m box, 0.3 m thick, top face at local y = 0",
                                 "centre (-10, 0.2, 0); x = -10 + 4 sin(2 pi t / 8 s)")
    m = Mesh("platform_rotate_coll")
    m.cylinder((0, 0, 0), 3.0, -0.3, 0.0, 24, bottom=True)
    m.box((1.5, 0.0, -0.25), (2.5, 0.5, 0.25))
    out["platform_rotate"] = (m, "turntable: 24-sided disc radius 3, 0.3 m thick, top at y = 0, with a 0.5 m bump at +x",
                              "centre (0, 0.2, 8); rotate about +y at 0.6 rad/s")
    m = Mesh("platform_scale_coll")
    m.box((-1.5, -0.3, -1.5), (1.5, 0, 1.5), bottom=True)
    out["platform_scale"] = (m, "3 x 3 m box, 0.3 m thick, top at y = 0",
                             "centre (10, 0.2, 0); scale x and z = 1 + 0.5 sin(2 pi t / 6 s), y = 1")
    m = Mesh("platform_lift_coll")
    m.box((-1.5, -0.3, -1.5), (1.5, 0, 1.5), bottom=True)
    out["platform_lift"] = (m, "3 x 3 m box, 0.3 m thick, top at y = 0",
                            "centre (0, 0.2, -10); y = 1.7 - 1.5 cos(2 pi t / 8 s) (0.2 .. 3.2 m)")
    return out


def build_planet(radius=20.0, freq=10):
    """Geodesic sphere: icosahedron faces split freq x freq, projected: 20 * freq^2 triangles."""
    p = (1 + math.sqrt(5)) / 2
    ico_v = [(-1, p, 0), (1, p, 0), (-1, -p, 0), (1, -p, 0), (0, -1, p), (0, 1, p), (0, -1, -p), (0, 1, -p),
             (p, 0, -1), (p, 0, 1), (-p, 0, -1), (-p, 0, 1)]
    ico_f = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9), (5, 11, 4), (11, 10, 2),
             (10, 7, 6), (7, 1, 8), (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8), (3, 8, 9), (4, 9, 5),
             (2, 4, 11), (6, 2, 10), (8, 6, 7), (9, 8, 1)]
    m = Mesh("planet_coll")
    def proj(q):
        L = length(q)
        return (q[0] * radius / L, q[1] * radius / L, q[2] * radius / L)
    for a, b, c in ico_f:
        A, B, C = ico_v[a], ico_v[b], ico_v[c]
        def pt(i, j):  # i steps towards B, j towards C
            return proj(add(A, add(scl(sub(B, A), i / freq), scl(sub(C, A), j / freq))))
        for i in range(freq):
            for j in range(freq - i):
                m.tri(pt(i, j), pt(i + 1, j), pt(i, j + 1))
                if i + j + 1 < freq:
                    m.tri(pt(i + 1, j), pt(i + 1, j + 1), pt(i, j + 1))
    PLANET_MIN_R[0] = min(length(scl(add(add(m.verts[a], m.verts[b]), m.verts[c]), 1 / 3.0)) for a, b, c in m.tris)
    return m


PLANET_MIN_R = [20.0]


def stairs_cm_obj(path):
    """A small OBJ staircase in centimeters (3 risers of 15 cm, 40 cm treads, 120 cm wide)."""
    m = Mesh("stairs_cm_coll", max_edge=400.0)
    prof, _ = stairs_profile(15.0, 3, 40.0, 120.0)
    m.extrude_profile(prof, (0.0, 0.0), '+x', 120.0)
    m.quad((-100, 0, -100), (-100, 0, 100), (400, 0, 100), (400, 0, -100), max_edge=400.0)
    with open(path, "w") as f:
        f.write("# charbody64 tools/gen_levels.py: staircase in centimeters, bake with --scale 0.01\n")
        f.write("o stairs_cm_coll\n")
        for v in m.verts:
            f.write("v %g %g %g\n" % v)
        for t in m.tris:
            f.write("f %d %d %d\n" % (t[0] + 1, t[1] + 1, t[2] + 1))
    return [Node("stairs_cm_coll", m)]


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    outdir = sys.argv[1] if len(sys.argv) > 1 else os.path.join(here, "..", "assets", "levels")
    os.makedirs(outdir, exist_ok=True)
    summary = []

    roots = build_course()
    write_gltf(os.path.join(outdir, "test_course.gltf"), roots)
    summary.append(("test_course", write_expect(os.path.join(outdir, "test_course.expect"), collect(roots),
                                                "test_course.gltf, nodes *_coll")))
    plats = build_platforms()
    for name, (m, _, _) in plats.items():
        r = [Node(name + "_coll", m)]
        write_gltf(os.path.join(outdir, name + ".gltf"), r)
        summary.append((name, write_expect(os.path.join(outdir, name + ".expect"), collect(r), name + ".gltf")))
    pl = [Node("planet_coll", build_planet())]
    write_gltf(os.path.join(outdir, "planet.gltf"), pl)
    summary.append(("planet", write_expect(os.path.join(outdir, "planet.expect"), collect(pl), "planet.gltf")))
    st = stairs_cm_obj(os.path.join(outdir, "stairs_cm.obj"))
    summary.append(("stairs_cm", write_expect(os.path.join(outdir, "stairs_cm.expect"), collect(st, scale=0.01),
                                              "stairs_cm.obj at --scale 0.01")))
    write_readme(os.path.join(outdir, "README.md"), plats, summary)
    for name, (n, lo, hi) in summary:
        print("%-20s %6d triangles  bounds (%.2f %.2f %.2f)..(%.2f %.2f %.2f)" % ((name, n) + tuple(lo) + tuple(hi)))


def write_readme(path, plats, summary):
    L = []
    L.append("# Sample levels\n")
    L.append("Generated by `python3 tools/gen_levels.py` (do not edit by hand; edit the script and re-run).")
    L.append("Baked by `make assets` (mk/bake.mk) to `$(BUILD)/assets/<name>.coll` (float vertices) and")
    L.append("`<name>.q.coll` (16-bit quantized). Y is up, units are meters. Collision geometry is in")
    L.append("nodes named `*_coll`; `test_course.gltf` is baked with `--only '*_coll' --cell-size 4`,")
    L.append("`planet.gltf` with `--cell-size 4` (see mk/bake.mk).\n")
    L.append("| level | triangles | bounds min | bounds max |")
    L.append("|---|---|---|---|")
    for name, (n, lo, hi) in summary:
        L.append("| %s | %d | (%.2f, %.2f, %.2f) | (%.2f, %.2f, %.2f) |" % ((name, n) + tuple(lo) + tuple(hi)))
    L.append("\n## test_course\n")
    L.append("Spawn: feet at **(-28, 0, -30)**, facing +x. The features sit on a square loop of 4 m wide")
    L.append("lanes around the centre, walked counter-clockwise seen from above: leg A along z = -30 (+x),")
    L.append("leg B along x = 30 (+z), leg C along z = 30 (-x), leg D along x = -30 (-z), back to the spawn.")
    L.append("The inside of the loop (|x|, |z| < 24) is open floor with pillars, walls and room for the")
    L.append("moving platforms. Character defaults assumed: radius 0.5, height 2, step 0.25, snap 0.3, 45 deg.\n")
    L.append("| feature | where | notes |")
    L.append("|---|---|---|")
    for name, where, notes in FEATURES:
        L.append("| %s | %s | %s |" % (name, where, notes))
    L.append("\ncollbake warns about 11 non-manifold edges in test_course; they are intended: the three")
    L.append("V-corner apexes, the four perimeter-wall corners and four feature edges lying on floor-tile edges.")
    L.append("\nA replay that visits everything: spawn -> +x through the three staircases (z = -30) ->")
    L.append("blocked by the 0.35 m blocker at x = 8 -> round it via z = -26 -> corner (30, -30) -> +z over")
    L.append("the 10..44 deg hills (x = 30) -> at z = 15 step to x = 29 and walk +z into the 50 deg slope")
    L.append("(slides back) -> round the wedges via x = 26 -> corner (30, 30) -> -x along z = 30, turning +z")
    L.append("into the 90 deg V-corner at x = 4 -> up the 15 deg ramp at x = -2, over the 0.2 m small drop")
    L.append("at x = -14 and off the 1.3 m ledge at x = -18 -> corner (-30, 30) -> -z under the low ceiling -> along")
    L.append("the long wall -> past the thin wall at z = 0 (x = -29) -> back to the spawn.\n")
    L.append("## Moving platforms (one file each, local origin at the centre of the top face)\n")
    L.append("| file | shape | suggested placement and motion |")
    L.append("|---|---|---|")
    for name, (_, shape, motion) in plats.items():
        L.append("| %s.gltf | %s | %s |" % (name, shape, motion))
    L.append("\nAll four sit with their top 0.2 m above the floor at rest (below step_height, so the body")
    L.append("steps on), inside the loop, reachable from leg A / leg C by walking towards the centre.\n")
    L.append("## planet\n")
    L.append("Geodesic sphere (icosahedron, frequency 10: 2000 triangles), radius 20 m, centred at the")
    L.append("origin (flat facets: the surface is %.2f .. 20 m from the centre). Spawn feet at (0, 20.5, 0)" % PLANET_MIN_R[0])
    L.append("with up = normalize(position) and gravity towards the origin; walk along any great circle.\n")
    L.append("## stairs_cm.obj\n")
    L.append("Three 15 cm risers in a centimeter-unit OBJ, baked with `--scale 0.01` (tests OBJ input and")
    L.append("scaling). `<name>.expect` files hold the triangle count, bounds and area the tests compare to.")
    with open(path, "w") as f:
        f.write("\n".join(L) + "\n")


if __name__ == "__main__":
    main()
