/*
 * libFuzzer target for coll_mesh_load(): any byte string, loaded in place from an
 * exact-size heap block (so ASan flags a read one byte past the end), must either be
 * refused with an error or give a mesh that every accessor and a few scene queries can
 * walk without reading out of bounds.
 *
 * Random mutations almost never keep the checksum right, which would stop the fuzzer at
 * the checksum test. So each input is also tried a second time with its checksum
 * recomputed (when its header describes a layout that fits), which lets mutations of
 * counts, offsets, indices, cells and refs reach the deeper validation and the queries.
 * The recomputation follows the checksum rule written in src/coll/mesh_format.h.
 *
 * Built with clang -fsanitize=fuzzer,address,undefined by mk/fuzz.mk; `make fuzz`.
 */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <math.h>

#include "coll/mesh.h"
#include "mesh_format.h"
#include "coll/scene.h"

static uint32_t be32(const uint8_t *p)
{
    return (uint32_t)p[0] << 24 | (uint32_t)p[1] << 16 | (uint32_t)p[2] << 8 | p[3];
}

static void put_be32(uint8_t *p, uint32_t v)
{
    p[0] = (uint8_t)(v >> 24); p[1] = (uint8_t)(v >> 16); p[2] = (uint8_t)(v >> 8); p[3] = (uint8_t)v;
}

/* Recomputes the checksum of a big-endian blob in place; false when the header's layout
 * does not fit the buffer (then the loader must refuse it anyway). */
static int fix_checksum(uint8_t *b, size_t size)
{
    if (size < sizeof(struct coll_mesh_s)) return 0;
    uint32_t flags = be32(b + offsetof(struct coll_mesh_s, flags));
    uint64_t nverts = be32(b + offsetof(struct coll_mesh_s, nverts));
    uint64_t ntris = be32(b + offsetof(struct coll_mesh_s, ntris));
    uint64_t nrefs = be32(b + offsetof(struct coll_mesh_s, nrefs));
    uint64_t ncells = 1;
    for (int a = 0; a < 3; a++) {
        ncells *= be32(b + offsetof(struct coll_mesh_s, dims) + 4u * (unsigned)a);
        if (ncells > size) ncells = size + 1u; /* no overflow; hashed grids ignore it */
    }
    if (flags & COLL_MESHF_HASH) ncells = be32(b + offsetof(struct coll_mesh_s, nbuckets));
    if (ncells > size) return 0;
    if (nverts > size || ntris > size || nrefs > size) return 0;
    coll_mesh_layout_t l = coll_mesh_layout_of(flags, nverts, ntris, ncells, nrefs);
    if (l.total > size) return 0;
    const struct { uint64_t off, count; unsigned esize; } s[5] = {
        { l.off_verts, nverts * 3u, (flags & COLL_MESHF_QUANT) ? 2u : 4u },
        { l.off_tris, ntris * 3u, (flags & (COLL_MESHF_IDX16 | COLL_MESHF_IDXBLK)) ? 2u : 4u },
        { l.off_tbase, l.ntbase, 4u },
        { l.off_cells, ncells + 1u, 4u },
        { l.off_refs, nrefs, (flags & COLL_MESHF_REF16) ? 2u : 4u },
    };
    uint32_t h = 2166136261u;
    for (uint32_t w = 1; w < sizeof(struct coll_mesh_s) / 4u; w++)
        if (w != offsetof(struct coll_mesh_s, checksum) / 4u) h = (h ^ be32(b + 4u * w)) * 16777619u;
    for (int i = 0; i < 5; i++)
        for (uint64_t k = 0; k < s[i].count; k++) {
            const uint8_t *p = b + s[i].off + s[i].esize * k;
            uint32_t v = s[i].esize == 2u ? (uint32_t)(p[0] << 8 | p[1]) : be32(p);
            h = (h ^ v) * 16777619u;
        }
    put_be32(b + offsetof(struct coll_mesh_s, checksum), h);
    return 1;
}

static volatile float sink;

/* Walks a mesh the loader accepted the way a game would. */
static void exercise(void *blob, size_t size, const coll_mesh_t *m)
{
    if (coll_mesh_size(m) > size) abort();
    uint32_t n = coll_mesh_triangle_count(m);
    fm_vec3_t lo, hi, t[3];
    coll_mesh_bounds(m, &lo, &hi);
    float acc = 0.0f;
    for (uint32_t i = 0; i < n && i < 200000u; i++) {
        coll_mesh_triangle(m, i, t);
        acc += t[0].x + t[1].y + t[2].z;
    }
    coll_mesh_triangle(m, n, t); /* out of range: zeros */
    if (t[0].x != 0.0f || t[2].z != 0.0f) abort();

    /* Loading the loaded buffer again only re-validates. */
    const coll_mesh_t *again = NULL;
    if (coll_mesh_load(blob, size, &again) != COLL_OK || again != m) abort();

    /* Queries over the grid the blob brought. */
    coll_scene_t scene;
    coll_mesh_instance_t inst;
    coll_transform_t id = COLL_TRANSFORM_IDENTITY;
    memset(&inst, 0, sizeof inst);
    inst.mesh = m;
    inst.xf = id;
    inst.write_mask = 1;
    coll_scene_init(&scene);
    if (coll_scene_add_mesh(&scene, &inst) != COLL_OK) return;
    fm_vec3_t c;
    for (int a = 0; a < 3; a++) c.v[a] = 0.5f * lo.v[a] + 0.5f * hi.v[a];
    float reach = fm_vec3_distance(&lo, &hi) + 1.0f;
    if (!isfinite(reach) || !isfinite(c.x + c.y + c.z)) return;
    static const fm_vec3_t dirs[6] = {
        {{0, -1, 0}}, {{0, 1, 0}}, {{1, 0, 0}}, {{0, 0, -1}}, {{0.57735f, 0.57735f, 0.57735f}}, {{-0.6f, 0.0f, 0.8f}},
    };
    for (int k = 0; k < 6; k++) {
        fm_vec3_t o;
        for (int a = 0; a < 3; a++) o.v[a] = c.v[a] - dirs[k].v[a] * reach;
        coll_ray_hit_t hit;
        if (coll_raycast(&scene, o, dirs[k], 2.0f * reach, 1, COLL_TYPE_ALL, &hit)) {
            if (hit.triangle < 0 || (uint32_t)hit.triangle >= n || !isfinite(hit.distance)) abort();
            acc += hit.distance;
        }
    }
    fm_vec3_t up = {{0, 1, 0}}, disp = {{0.0f, -1.0f, 0.3f}};
    coll_sweep_hit_t sh;
    if (coll_capsule_sweep(&scene, c, up, 0.5f, 0.5f, disp, 1, COLL_TYPE_ALL, &sh))
        acc += sh.t;
    sink = acc;
}

static void try_load(const uint8_t *data, size_t size, int fix)
{
    uint8_t *blob = malloc(size ? size : 1); /* glibc/ASan malloc: 8-byte aligned */
    if (!blob) return;
    memcpy(blob, data, size);
    if (fix && !fix_checksum(blob, size)) { free(blob); return; }
    const coll_mesh_t *m = NULL;
    coll_err_t err = coll_mesh_load(blob, size, &m);
    if (err == COLL_OK) {
        if (!m) abort();
        exercise(blob, size, m);
    } else if (m) {
        abort(); /* an error must leave *out NULL */
    }
    free(blob);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    try_load(data, size, 0);
    try_load(data, size, 1);
    return 0;
}
