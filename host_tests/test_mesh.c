/* Mesh builder: dropped triangles, size bound, grid completeness (cells hold every
 * triangle that passes through them), given cell size, quantization, bytes/triangle. */
#include "unity.h"
#include "alloc_guard.h"
#include "core_gen.h"
#include "coll/mesh.h"
#include "coll/scene.h"
#include "mesh_format.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

void setUp(void) {}
void tearDown(void) {}

#define BIG (8u << 20)
static uint64_t g_buf[BIG / 8];
static float g_verts[3 * 70000];
static uint32_t g_idx[3 * 140000];

static const coll_mesh_t *build(uint32_t nv, uint32_t nt, const coll_mesh_build_opts_t *o)
{
    const coll_mesh_t *m = NULL;
    size_t need = coll_mesh_build_size(nv, nt, o);
    TEST_ASSERT_TRUE(need > 0 && need <= sizeof g_buf);
    coll_err_t e;
    ASSERT_NO_ALLOC(e = coll_mesh_build(g_buf, need, g_verts, nv, g_idx, nt, o, &m));
    TEST_ASSERT_EQUAL_INT(COLL_OK, e);
    TEST_ASSERT_NOT_NULL(m);
    TEST_ASSERT_TRUE(coll_mesh_size(m) <= need);
    return m;
}

static bool cell_has(const coll_mesh_t *m, uint32_t cell, uint32_t tri)
{
    const uint32_t *cells = coll_mesh_cells(m);
    for (uint32_t k = cells[cell]; k < cells[cell + 1]; k++)
        if (coll_mesh_ref(m, k) == tri) return true;
    return false;
}

static uint32_t cell_coord_d(double x, double origin, double cs, uint32_t dim)
{
    double f = floor((x - origin) / cs);
    if (f < 0) f = 0;
    if (f > dim - 1) f = dim - 1;
    return (uint32_t)f;
}

/* Every point of every triangle (sampled densely, plus its corners and edge points) lies
 * in a cell that lists the triangle. */
static void check_grid_complete(const coll_mesh_t *m, int samples)
{
    for (uint32_t t = 0; t < coll_mesh_triangle_count(m); t++) {
        fm_vec3_t v[3];
        coll_mesh_triangle(m, t, v);
        for (int i = 0; i <= samples; i++)
            for (int j = 0; j <= samples - i; j++) {
                double a = (double)i / samples, b = (double)j / samples, c = 1.0 - a - b;
                uint32_t cc[3];
                for (int k = 0; k < 3; k++) {
                    double p = a * v[0].v[k] + b * v[1].v[k] + c * v[2].v[k];
                    cc[k] = cell_coord_d(p, m->grid_origin[k], m->cell_size, m->dims[k]);
                }
                uint32_t cell = coll_mesh_cell_index(m, cc[0], cc[1], cc[2]);
                if (!cell_has(m, cell, t)) {
                    char msg[128];
                    snprintf(msg, sizeof msg, "triangle %u missing from cell %u", t, cell);
                    TEST_FAIL_MESSAGE(msg);
                }
            }
    }
}

static void test_drops_degenerate_triangles(void)
{
    float v[] = { 0, 0, 0, 1, 0, 0, 0, 0, 1, 2, 0, 0, NAN, 0, 0, 1, 1, 1 };
    memcpy(g_verts, v, sizeof v);
    uint32_t idx[] = {
        0, 1, 2,  /* ok */
        0, 1, 3,  /* collinear: zero area */
        0, 0, 2,  /* repeated index */
        0, 1, 9,  /* out of range */
        0, 4, 2,  /* NaN vertex */
        1, 2, 5,  /* ok */
    };
    memcpy(g_idx, idx, sizeof idx);
    const coll_mesh_t *m = build(6, 6, NULL);
    TEST_ASSERT_EQUAL_UINT32(2, coll_mesh_triangle_count(m));
    fm_vec3_t t[3];
    coll_mesh_triangle(m, 1, t);
    TEST_ASSERT_EQUAL_FLOAT(1.0f, t[0].x);
    TEST_ASSERT_EQUAL_FLOAT(1.0f, t[2].y);
    coll_mesh_triangle(m, 2, t); /* out of range: zeros */
    TEST_ASSERT_EQUAL_FLOAT(0.0f, t[0].x);
    TEST_ASSERT_EQUAL_FLOAT(0.0f, t[2].z);
    fm_vec3_t lo, hi;
    coll_mesh_bounds(m, &lo, &hi);
    TEST_ASSERT_EQUAL_FLOAT(0.0f, lo.x);
    TEST_ASSERT_EQUAL_FLOAT(1.0f, hi.y);
    check_grid_complete(m, 8);
}

static void test_all_degenerate_gives_empty_mesh(void)
{
    float v[] = { 0, 0, 0, 1, 0, 0, 2, 0, 0 };
    memcpy(g_verts, v, sizeof v);
    uint32_t idx[] = { 0, 1, 2 };
    memcpy(g_idx, idx, sizeof idx);
    const coll_mesh_t *m = build(3, 1, NULL);
    TEST_ASSERT_EQUAL_UINT32(0, coll_mesh_triangle_count(m));
    m = build(0, 0, NULL);
    TEST_ASSERT_EQUAL_UINT32(0, coll_mesh_triangle_count(m));
}

static void test_argument_errors(void)
{
    const coll_mesh_t *m = NULL;
    float v[] = { 0, 0, 0, 1, 0, 0, 0, 0, 1 };
    uint32_t idx[] = { 0, 1, 2 };
    size_t need = coll_mesh_build_size(3, 1, NULL);
    TEST_ASSERT_EQUAL_INT(COLL_ERR_INVALID_ARG, coll_mesh_build(NULL, need, v, 3, idx, 1, NULL, &m));
    TEST_ASSERT_EQUAL_INT(COLL_ERR_INVALID_ARG, coll_mesh_build(g_buf, need, NULL, 3, idx, 1, NULL, &m));
    TEST_ASSERT_EQUAL_INT(COLL_ERR_INVALID_ARG, coll_mesh_build(g_buf, need, v, 3, idx, 1, NULL, NULL));
    coll_mesh_build_opts_t bad = { NAN, 0 };
    TEST_ASSERT_EQUAL_INT(COLL_ERR_INVALID_ARG, coll_mesh_build(g_buf, need, v, 3, idx, 1, &bad, &m));
    TEST_ASSERT_EQUAL_INT(COLL_ERR_ALIGNMENT,
                          coll_mesh_build((uint8_t *)g_buf + 4, need, v, 3, idx, 1, NULL, &m));
    TEST_ASSERT_NULL(m);
    TEST_ASSERT_EQUAL_INT(COLL_ERR_BUFFER_TOO_SMALL, coll_mesh_build(g_buf, 100, v, 3, idx, 1, NULL, &m));
    /* Any size from the exact need up works, anything below fails cleanly. */
    TEST_ASSERT_EQUAL_INT(COLL_OK, coll_mesh_build(g_buf, need, v, 3, idx, 1, NULL, &m));
    size_t exact = coll_mesh_size(m);
    for (size_t s = 0; s < exact; s += 4)
        TEST_ASSERT_NOT_EQUAL(COLL_OK, coll_mesh_build(g_buf, s, v, 3, idx, 1, NULL, &m));
    TEST_ASSERT_EQUAL_INT(COLL_OK, coll_mesh_build(g_buf, exact, v, 3, idx, 1, NULL, &m));
}

/* Random soups (long thin triangles, clusters, far from the origin): the size bound
 * holds for any cell size and the grid is complete. */
static void test_size_bound_and_grid_complete_random(void)
{
    core_rng_t r;
    core_rng_seed(&r, 42);
#ifdef __mips__
    const int rounds = 12;
#else
    const int rounds = 60;
#endif
    for (int round = 0; round < rounds; round++) {
        uint32_t nv = 3 + core_rng_u32(&r) % 300, nt = 1 + core_rng_u32(&r) % 300;
        double off = (round % 3 == 0) ? core_rng_range(&r, -2000, 2000) : 0.0;
        double spread = core_rng_range(&r, 0.5, 100);
        for (uint32_t i = 0; i < nv; i++)
            for (int k = 0; k < 3; k++)
                g_verts[3 * i + k] = (float)(off + core_rng_range(&r, -spread, spread) *
                                                       (round % 4 == 1 && k == 1 ? 0.01 : 1.0));
        for (uint32_t i = 0; i < 3 * nt; i++) g_idx[i] = core_rng_u32(&r) % nv;
        coll_mesh_build_opts_t o = { 0.0f, (round & 1) ? COLL_MESH_QUANTIZE : 0u };
        if (round % 5 == 2) o.cell_size = (float)core_rng_range(&r, 0.01, 5.0); /* tiny cells: grid must grow */
        const coll_mesh_t *m = build(nv, nt, &o);
        TEST_ASSERT_TRUE(coll_mesh_cell_count(m) <= 2 * nt + 64);
        TEST_ASSERT_TRUE(m->nrefs <= 8 * nt + 64);
        check_grid_complete(m, 6);
    }
}

static void test_given_cell_size_is_used(void)
{
    uint32_t nv;
    uint32_t nt = core_grid_level(g_verts, &nv, g_idx, 20, 20, 1.0f, -10, 0, -10);
    coll_mesh_build_opts_t o = { 2.5f, 0 };
    const coll_mesh_t *m = build(nv, nt, &o);
    TEST_ASSERT_EQUAL_FLOAT(2.5f, m->cell_size);
    TEST_ASSERT_EQUAL_UINT32(8, m->dims[0]);
    TEST_ASSERT_EQUAL_UINT32(8, m->dims[2]);
    check_grid_complete(m, 6);
}

static void test_huge_triangle_spans_many_cells(void)
{
    uint32_t nv;
    uint32_t nt = core_grid_level(g_verts, &nv, g_idx, 16, 16, 1.0f, 0, 0, 0);
    /* one huge sloped triangle over the whole level */
    float big[] = { -1, -3, -1, 17, 5, -1, -1, 4, 17 };
    memcpy(g_verts + 3 * nv, big, sizeof big);
    g_idx[3 * nt] = nv; g_idx[3 * nt + 1] = nv + 1; g_idx[3 * nt + 2] = nv + 2;
    coll_mesh_build_opts_t o = { 1.0f, 0 };
    const coll_mesh_t *m = build(nv + 3, nt + 1, &o);
    uint32_t count = 0, ncells = (uint32_t)coll_mesh_cell_count(m);
    for (uint32_t c = 0; c < ncells; c++) count += cell_has(m, c, nt);
    TEST_ASSERT_TRUE_MESSAGE(count > 50, "huge triangle should be listed in many cells");
    /* ...but not in every cell of its box: the plane/box test trims it */
    TEST_ASSERT_TRUE(count < ncells);
    check_grid_complete(m, 40);
}

static void test_triangles_on_cell_boundaries(void)
{
    /* Axis-aligned triangles lying exactly on the planes x = 2, y = 2, z = 2 of a 1 m grid */
    float v[] = { 0, 0, 0, 4, 0, 0, 0, 4, 4, /* spans, fixes bounds */
                  2, 0, 0, 2, 4, 0, 2, 0, 4,
                  0, 2, 0, 4, 2, 0, 0, 2, 4,
                  0, 0, 2, 4, 0, 2, 0, 4, 2,
                  1, 1, 1, 2, 1, 1, 1, 2, 1 };
    memcpy(g_verts, v, sizeof v);
    for (uint32_t i = 0; i < 15; i++) g_idx[i] = i;
    /* small filler triangles so the grid budget (which scales with the count) keeps 1 m cells */
    for (uint32_t i = 5; i < 60; i++) {
        float f[] = { 0.1f, 0.1f, 0.1f + 0.01f * (float)i, 0.3f, 0.1f, 0.1f, 0.1f, 0.3f, 0.1f };
        memcpy(g_verts + 9 * i, f, sizeof f);
        for (uint32_t k = 0; k < 3; k++) g_idx[3 * i + k] = 3 * i + k;
    }
    coll_mesh_build_opts_t o = { 1.0f, 0 };
    const coll_mesh_t *m = build(180, 60, &o);
    TEST_ASSERT_EQUAL_FLOAT(1.0f, m->cell_size);
    check_grid_complete(m, 16);
    /* The x = 2 triangle is registered on both sides of its plane. */
    uint32_t c_lo = coll_mesh_cell_index(m, 1, 1, 1), c_hi = coll_mesh_cell_index(m, 2, 1, 1);
    TEST_ASSERT_TRUE(cell_has(m, c_lo, 1));
    TEST_ASSERT_TRUE(cell_has(m, c_hi, 1));
}

static void test_quantized_vertices_close(void)
{
    uint32_t nv;
    uint32_t nt = core_grid_level(g_verts, &nv, g_idx, 30, 30, 1.7f, 5000, 10, -5000);
    coll_mesh_build_opts_t o = { 0.0f, COLL_MESH_QUANTIZE };
    const coll_mesh_t *m = build(nv, nt, &o);
    TEST_ASSERT_EQUAL_UINT32(nt, coll_mesh_triangle_count(m));
    for (uint32_t t = 0; t < nt; t++) {
        fm_vec3_t v[3];
        coll_mesh_triangle(m, t, v);
        for (int k = 0; k < 3; k++)
            for (int a = 0; a < 3; a++) {
                float want = g_verts[3 * g_idx[3 * t + k] + a];
                /* step = extent / 65535: 51 m / 65535 < 1 mm, plus float rounding at 5 km */
                TEST_ASSERT_FLOAT_WITHIN(1e-3f, want, v[k].v[a]);
            }
    }
    check_grid_complete(m, 4);
}

/* Bytes per triangle on a welded 10k-triangle grid-like level (the memory target). */
static void test_bytes_per_triangle(void)
{
    uint32_t nv;
    uint32_t nt = core_grid_level(g_verts, &nv, g_idx, 100, 50, 1.5f, -75, 0, -37);
    TEST_ASSERT_EQUAL_UINT32(10000, nt);
    const coll_mesh_t *m = build(nv, nt, NULL);
    double bf = (double)coll_mesh_size(m) / nt;
    coll_mesh_build_opts_t q = { 0.0f, COLL_MESH_QUANTIZE };
    m = build(nv, nt, &q);
    double bq = (double)coll_mesh_size(m) / nt;
    char msg[160];
    snprintf(msg, sizeof msg, "10k-tri welded level: %.2f B/tri float, %.2f B/tri quantized "
             "(cells %ux%ux%u, %.2f refs/tri)", bf, bq, m->dims[0], m->dims[1], m->dims[2],
             (double)m->nrefs / nt);
    printf("%s\n", msg);
    TEST_ASSERT_TRUE_MESSAGE(bf <= 24.0, msg);
    TEST_ASSERT_TRUE_MESSAGE(bq <= 14.0, msg);
}

/* Cells finer than a dense grid of the budget allows are hashed: the requested cell is
 * kept, the cell entries stay within the budget, every triangle is found from every cell
 * it touches, and the result is no bigger than coll_mesh_build_size(). */
static void test_fine_cells_are_hashed(void)
{
    uint32_t nv;
    uint32_t nt = core_grid_level(g_verts, &nv, g_idx, 60, 40, 1.0f, -30, 0, -20);
    for (uint32_t v = 0; v < nv; v++) g_verts[3 * v + 1] += g_verts[3 * v]; /* a 60 m high 45 deg ramp */
    coll_mesh_build_opts_t o = { 2.0f, 0 };
    const coll_mesh_t *m = build(nv, nt, &o); /* 30 x 31 x 20 cells > 2 nt + 64 */
    TEST_ASSERT_TRUE(m->flags & COLL_MESHF_HASH);
    TEST_ASSERT_EQUAL_FLOAT(2.0f, m->cell_size);
    TEST_ASSERT_TRUE(m->nbuckets <= 2 * nt + 64);
    TEST_ASSERT_EQUAL_UINT32(0, m->nbuckets & (m->nbuckets - 1));
    TEST_ASSERT_TRUE((uint64_t)m->dims[0] * m->dims[1] * m->dims[2] > m->nbuckets);
    check_grid_complete(m, 8);
    /* a coarse request stays a dense grid */
    o.cell_size = 8.0f;
    m = build(nv, nt, &o);
    TEST_ASSERT_FALSE(m->flags & COLL_MESHF_HASH);
    TEST_ASSERT_EQUAL_UINT32(0, m->nbuckets);
    check_grid_complete(m, 8);
}

/* Every stored triangle has exactly the input's vertices (nothing dropped here). */
static void same_triangles(const coll_mesh_t *m, uint32_t nt)
{
    TEST_ASSERT_EQUAL_UINT32(nt, coll_mesh_triangle_count(m));
    for (uint32_t t = 0; t < nt; t++) {
        fm_vec3_t v[3];
        coll_mesh_triangle(m, t, v);
        for (int k = 0; k < 3; k++)
            for (int a = 0; a < 3; a++)
                if (v[k].v[a] != g_verts[3 * g_idx[3 * t + k] + a]) TEST_FAIL_MESSAGE("triangle vertex differs");
    }
}

/* The scene queries (their grid walk decodes the indices itself) find each sampled
 * triangle of a height field straight under its centroid. */
static void rays_find_triangles(const coll_mesh_t *m, uint32_t nt)
{
    coll_mesh_instance_t inst = { .mesh = m, .xf = COLL_TRANSFORM_IDENTITY, .write_mask = 1, .id = 1 };
    coll_scene_t sc;
    coll_scene_init(&sc);
    TEST_ASSERT_EQUAL_INT(COLL_OK, coll_scene_add_mesh(&sc, &inst));
    for (uint32_t t = 0; t < nt; t += 997u) {
        fm_vec3_t v[3];
        coll_mesh_triangle(m, t, v);
        fm_vec3_t c = {{(v[0].x + v[1].x + v[2].x) / 3.0f, (v[0].y + v[1].y + v[2].y) / 3.0f + 10.0f,
                        (v[0].z + v[1].z + v[2].z) / 3.0f}};
        coll_ray_hit_t h;
        TEST_ASSERT_TRUE(coll_raycast(&sc, c, (fm_vec3_t){{0.0f, -1.0f, 0.0f}}, 20.0f, 1, COLL_TYPE_MESH, &h));
        TEST_ASSERT_EQUAL_INT32((int32_t)t, h.triangle);
        TEST_ASSERT_FLOAT_WITHIN(1e-3f, 10.0f, h.distance);
    }
}

/* The checksum of a native mesh, as mesh_format.h documents it (written here again, so a
 * test can change a value and keep the mesh otherwise valid). */
static uint32_t native_checksum(const coll_mesh_t *m)
{
    const uint8_t *b = (const uint8_t *)m;
    uint64_t ncells = coll_mesh_cell_count(m);
    coll_mesh_layout_t l = coll_mesh_layout_of(m->flags, m->nverts, m->ntris, ncells, m->nrefs);
    const struct { uint64_t off, n; unsigned es; } s[6] = {
        { l.off_verts, (uint64_t)m->nverts * 3u, (m->flags & COLL_MESHF_QUANT) ? 2u : 4u },
        { l.off_tris, (uint64_t)m->ntris * 3u, (m->flags & (COLL_MESHF_IDX16 | COLL_MESHF_IDXBLK)) ? 2u : 4u },
        { l.off_tbase, l.ntbase, 4u },
        { l.off_cells, ncells + 1u, 4u },
        { l.off_refs, m->nrefs, (m->flags & COLL_MESHF_REF16) ? 2u : 4u },
        { l.off_codes, (m->flags & COLL_MESHF_RCODE) ? m->nrefs : 0u, 1u },
    };
    uint32_t h = 2166136261u, w;
    for (uint32_t i = 1; i < sizeof(struct coll_mesh_s) / 4u; i++)
        if (i != 4) { memcpy(&w, b + 4 * i, 4); h = (h ^ w) * 16777619u; }
    for (int i = 0; i < 6; i++)
        for (uint64_t k = 0; k < s[i].n; k++) {
            uint16_t u16;
            if (s[i].es == 1) w = b[s[i].off + k];
            else if (s[i].es == 2) { memcpy(&u16, b + s[i].off + 2 * k, 2); w = u16; }
            else memcpy(&w, b + s[i].off + 4 * k, 4);
            h = (h ^ w) * 16777619u;
        }
    return h;
}

/* More than 65535 vertices: 16-bit indices from a base per block of 64 triangles (6 bytes
 * a triangle instead of 12), exact, through the big-endian blob and back, and validated. */
static void test_block_indices_when_many_vertices(void)
{
    uint32_t nv;
    uint32_t nt = core_grid_level(g_verts, &nv, g_idx, 300, 220, 1.0f, 0, 0, 0);
    TEST_ASSERT_TRUE(nv > 65535);
    for (int q = 0; q < 2; q++) {
        coll_mesh_build_opts_t o = { 0.0f, q ? COLL_MESH_QUANTIZE : 0u };
        const coll_mesh_t *m = build(nv, nt, &o);
        TEST_ASSERT_TRUE(m->flags & COLL_MESHF_IDXBLK);
        TEST_ASSERT_FALSE(m->flags & COLL_MESHF_IDX16);
        TEST_ASSERT_FALSE(m->flags & COLL_MESHF_REF16);
        TEST_ASSERT_EQUAL_UINT32(COLL_MESH_VERSION, m->version);
        coll_mesh_layout_t l = coll_mesh_layout_of(m->flags, m->nverts, m->ntris, coll_mesh_cell_count(m), m->nrefs);
        TEST_ASSERT_TRUE(l.ntbase == (nt + 63) / 64);
        TEST_ASSERT_TRUE(l.off_tbase == l.off_tris + ((6u * nt + 7u) & ~7u));
        if (!q) same_triangles(m, nt);
        /* issue 14's memory targets: 24 bytes a triangle as float, 14 quantized */
        TEST_ASSERT_TRUE((double)coll_mesh_size(m) / nt < (q ? 14.0 : 24.0));
        /* the grid walk and coll_mesh_triangle read the same indices */
        check_grid_complete(m, 4);
        rays_find_triangles(m, nt);
        /* big-endian blob and back, in a second buffer */
        size_t size = coll_mesh_size(m), w = 0;
        uint8_t *blob = (uint8_t *)g_buf + ((size + 15u) & ~(size_t)7u);
        TEST_ASSERT_TRUE(2 * size + 16 <= sizeof g_buf);
        TEST_ASSERT_EQUAL_INT(COLL_OK, coll_mesh_write_blob(m, blob, size, &w));
        const coll_mesh_t *lm = NULL;
        TEST_ASSERT_EQUAL_INT(COLL_OK, coll_mesh_load(blob, size, &lm));
        TEST_ASSERT_EQUAL_MEMORY(m, lm, size);
    }
    /* a block base pointing past the vertices is corrupt, also with a valid checksum */
    coll_mesh_t *m = (coll_mesh_t *)(void *)g_buf;
    const coll_mesh_t *lm;
    TEST_ASSERT_EQUAL_INT(COLL_OK, coll_mesh_load(m, coll_mesh_size(m), &lm));
    coll_mesh_layout_t l = coll_mesh_layout_of(m->flags, m->nverts, m->ntris, coll_mesh_cell_count(m), m->nrefs);
    uint32_t *tb = (uint32_t *)(void *)((uint8_t *)m + l.off_tbase);
    uint32_t keep = tb[l.ntbase - 1];
    tb[l.ntbase - 1] = m->nverts - 1u; /* + the block's offsets: past the last vertex */
    m->checksum = native_checksum(m);
    TEST_ASSERT_EQUAL_INT(COLL_ERR_CORRUPT, coll_mesh_load(m, coll_mesh_size(m), &lm));
    tb[l.ntbase - 1] = keep;
    m->checksum = native_checksum(m);
    TEST_ASSERT_EQUAL_INT(COLL_OK, coll_mesh_load(m, coll_mesh_size(m), &lm));
    /* block indices are version 4: a version 3 header with them is corrupt */
    m->version = 3;
    m->checksum = native_checksum(m);
    TEST_ASSERT_EQUAL_INT(COLL_ERR_CORRUPT, coll_mesh_load(m, coll_mesh_size(m), &lm));
    m->version = COLL_MESH_VERSION + 1u;
    m->checksum = native_checksum(m);
    TEST_ASSERT_EQUAL_INT(COLL_ERR_VERSION, coll_mesh_load(m, coll_mesh_size(m), &lm));
    /* a version 3 mesh (no block indices, no sub-cell codes) still loads; sub-cell codes
     * are version 5: a version 3 or 4 header with them is corrupt */
    nt = core_grid_level(g_verts, &nv, g_idx, 20, 20, 1.0f, 0, 0, 0);
    m = (coll_mesh_t *)(void *)build(nv, nt, NULL);
    TEST_ASSERT_FALSE(m->flags & COLL_MESHF_IDXBLK);
    TEST_ASSERT_TRUE(m->flags & COLL_MESHF_RCODE);
    for (uint32_t v = 3; v <= 4; v++) {
        m->version = v;
        m->checksum = native_checksum(m);
        TEST_ASSERT_EQUAL_INT(COLL_ERR_CORRUPT, coll_mesh_load(m, coll_mesh_size(m), &lm));
    }
    nt = core_grid_level(g_verts, &nv, g_idx, 20, 20, 1.0f, 0, 0, 0);
    coll_mesh_build_opts_t q = { 0.0f, COLL_MESH_QUANTIZE };
    m = (coll_mesh_t *)(void *)build(nv, nt, &q);
    TEST_ASSERT_FALSE(m->flags & (COLL_MESHF_IDXBLK | COLL_MESHF_RCODE));
    m->version = 3;
    m->checksum = native_checksum(m);
    TEST_ASSERT_EQUAL_INT(COLL_OK, coll_mesh_load(m, coll_mesh_size(m), &lm));
}

/* Vertices numbered with no locality (a block's triangles reach over more than 65535 of
 * them): 32-bit indices, still exact. A block whose reach is exactly 65535 keeps 16 bits. */
static void test_32bit_indices_when_blocks_reach_far(void)
{
    uint32_t nv;
    uint32_t nt = core_grid_level(g_verts, &nv, g_idx, 300, 220, 1.0f, 0, 0, 0);
    /* renumber the vertices v -> v * 7919 mod nv (a permutation: 7919 is a prime not dividing nv) */
    static float perm[3 * 70000];
    TEST_ASSERT_TRUE(nv % 7919u != 0);
    for (uint32_t v = 0; v < nv; v++) memcpy(perm + 3 * ((uint64_t)v * 7919u % nv), g_verts + 3 * v, 12);
    memcpy(g_verts, perm, 12u * nv);
    for (uint32_t k = 0; k < 3 * nt; k++) g_idx[k] = (uint32_t)((uint64_t)g_idx[k] * 7919u % nv);
    const coll_mesh_t *m = build(nv, nt, NULL);
    TEST_ASSERT_FALSE(m->flags & (COLL_MESHF_IDX16 | COLL_MESHF_IDXBLK));
    same_triangles(m, nt);
    check_grid_complete(m, 4);
    /* two triangles 65535 vertices apart in one block: exactly in reach */
    nt = core_grid_level(g_verts, &nv, g_idx, 300, 220, 1.0f, 0, 0, 0);
    uint32_t lo = UINT32_MAX;
    for (uint32_t k = 0; k < 3 * 64; k++)
        if (k != 3 && g_idx[k] < lo) lo = g_idx[k];
    uint32_t far = lo + 65535u;
    TEST_ASSERT_TRUE(far < nv);
    g_idx[3 * 1 + 0] = far;          /* triangle 1 of block 0 gets a vertex 65535 above */
    m = build(nv, nt, NULL);
    TEST_ASSERT_TRUE(m->flags & COLL_MESHF_IDXBLK);
    same_triangles(m, nt);
    g_idx[3 * 1 + 0] = far + 1u;     /* one further: 32-bit */
    m = build(nv, nt, NULL);
    TEST_ASSERT_FALSE(m->flags & COLL_MESHF_IDXBLK);
    same_triangles(m, nt);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_drops_degenerate_triangles);
    RUN_TEST(test_all_degenerate_gives_empty_mesh);
    RUN_TEST(test_argument_errors);
    RUN_TEST(test_size_bound_and_grid_complete_random);
    RUN_TEST(test_given_cell_size_is_used);
    RUN_TEST(test_huge_triangle_spans_many_cells);
    RUN_TEST(test_triangles_on_cell_boundaries);
    RUN_TEST(test_quantized_vertices_close);
    RUN_TEST(test_bytes_per_triangle);
    RUN_TEST(test_fine_cells_are_hashed);
    RUN_TEST(test_block_indices_when_many_vertices);
    RUN_TEST(test_32bit_indices_when_blocks_reach_far);
    return UNITY_END();
}
