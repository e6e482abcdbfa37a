/* Baked blobs: big-endian writer round trip, load in place (twice), and hostile input:
 * every truncation, random bit flips, corrupted fields with a re-forged checksum. */
#include "unity.h"
#include "alloc_guard.h"
#include "core_gen.h"
#include "coll/mesh.h"
#include "mesh_format.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

void setUp(void) {}
void tearDown(void) {}

static uint64_t g_build[1 << 15];
static uint64_t g_blob[1 << 15];
static uint64_t g_work[1 << 15];
static size_t g_blob_size;
static float g_verts[3 * 2000];
static uint32_t g_idx[3 * 4000];

/* A small level with both index widths exercised by callers. */
static const coll_mesh_t *make_mesh(uint32_t flags, uint32_t nx)
{
    uint32_t nv;
    uint32_t nt = core_grid_level(g_verts, &nv, g_idx, nx, 6, 1.25f, -3, 1, 2);
    coll_mesh_build_opts_t o = { 0.0f, flags };
    const coll_mesh_t *m = NULL;
    TEST_ASSERT_EQUAL_INT(COLL_OK, coll_mesh_build(g_build, sizeof g_build, g_verts, nv, g_idx, nt, &o, &m));
    size_t w = 0;
    TEST_ASSERT_EQUAL_INT(COLL_OK, coll_mesh_write_blob(m, g_blob, sizeof g_blob, &w));
    TEST_ASSERT_EQUAL_UINT32(coll_mesh_size(m), w);
    g_blob_size = w;
    return m;
}

static void same_mesh(const coll_mesh_t *a, const coll_mesh_t *b)
{
    TEST_ASSERT_EQUAL_UINT32(coll_mesh_triangle_count(a), coll_mesh_triangle_count(b));
    TEST_ASSERT_EQUAL_UINT32(coll_mesh_size(a), coll_mesh_size(b));
    TEST_ASSERT_EQUAL_MEMORY(a, b, coll_mesh_size(a)); /* native layout identical */
    for (uint32_t t = 0; t < coll_mesh_triangle_count(a); t++) {
        fm_vec3_t x[3], y[3];
        coll_mesh_triangle(a, t, x);
        coll_mesh_triangle(b, t, y);
        TEST_ASSERT_EQUAL_MEMORY(x, y, sizeof x);
    }
}

static void test_round_trip_big_endian_blob(void)
{
    for (uint32_t flags = 0; flags < 2; flags++) {
        const coll_mesh_t *m = make_mesh(flags ? COLL_MESH_QUANTIZE : 0u, 10);
        /* float: with the sub-cell codes (a dense grid), quantized: without */
        TEST_ASSERT_EQUAL_INT(!flags, (m->flags & COLL_MESHF_RCODE) != 0u);
        const uint8_t *b = (const uint8_t *)g_blob;
        TEST_ASSERT_EQUAL_MEMORY("CMSH", b, 4); /* big-endian on disk, on any host */
        TEST_ASSERT_EQUAL_UINT8(0, b[4]);
        TEST_ASSERT_EQUAL_UINT8(COLL_MESH_VERSION, b[7]);
        memcpy(g_work, g_blob, g_blob_size);
        const coll_mesh_t *l = NULL;
        coll_err_t e;
        ASSERT_NO_ALLOC(e = coll_mesh_load(g_work, g_blob_size, &l));
        TEST_ASSERT_EQUAL_INT(COLL_OK, e);
        TEST_ASSERT_EQUAL_PTR(g_work, l);
        same_mesh(m, l);
        /* loading the same buffer again is recognised and still fine */
        const coll_mesh_t *l2 = NULL;
        TEST_ASSERT_EQUAL_INT(COLL_OK, coll_mesh_load(g_work, g_blob_size, &l2));
        same_mesh(m, l2);
        /* a bigger buffer than the blob is fine too */
        TEST_ASSERT_EQUAL_INT(COLL_OK, coll_mesh_load(g_work, g_blob_size + 64, &l2));
        /* a built mesh loads in place as well */
        TEST_ASSERT_EQUAL_INT(COLL_OK, coll_mesh_load(g_build, coll_mesh_size(m), &l2));
        /* relocatable: copy the loaded mesh elsewhere and use it there */
        memcpy(g_blob, g_work, g_blob_size);
        TEST_ASSERT_EQUAL_INT(COLL_OK, coll_mesh_load(g_blob, g_blob_size, &l2));
        same_mesh(m, l2);
    }
}

static void test_write_blob_errors(void)
{
    const coll_mesh_t *m = make_mesh(0, 4);
    size_t w = 0;
    TEST_ASSERT_EQUAL_INT(COLL_ERR_BUFFER_TOO_SMALL, coll_mesh_write_blob(m, g_blob, 64, &w));
    TEST_ASSERT_EQUAL_UINT32(coll_mesh_size(m), w);
    TEST_ASSERT_EQUAL_INT(COLL_ERR_INVALID_ARG, coll_mesh_write_blob(NULL, g_blob, sizeof g_blob, &w));
    /* unaligned output is fine for the writer */
    TEST_ASSERT_EQUAL_INT(COLL_OK, coll_mesh_write_blob(m, (uint8_t *)g_blob + 1, sizeof g_blob - 1, &w));
}

static void test_load_argument_errors(void)
{
    make_mesh(0, 4);
    const coll_mesh_t *l = (const coll_mesh_t *)1;
    TEST_ASSERT_EQUAL_INT(COLL_ERR_INVALID_ARG, coll_mesh_load(NULL, g_blob_size, &l));
    TEST_ASSERT_EQUAL_INT(COLL_ERR_INVALID_ARG, coll_mesh_load(g_blob, g_blob_size, NULL));
    memcpy((uint8_t *)g_work + 4, g_blob, g_blob_size);
    TEST_ASSERT_EQUAL_INT(COLL_ERR_ALIGNMENT, coll_mesh_load((uint8_t *)g_work + 4, g_blob_size, &l));
    TEST_ASSERT_NULL(l);
    memcpy(g_work, g_blob, g_blob_size);
    ((uint8_t *)g_work)[0] = 'X';
    TEST_ASSERT_EQUAL_INT(COLL_ERR_BAD_MAGIC, coll_mesh_load(g_work, g_blob_size, &l));
    memcpy(g_work, g_blob, g_blob_size);
    ((uint8_t *)g_work)[7] = 99;
    TEST_ASSERT_EQUAL_INT(COLL_ERR_VERSION, coll_mesh_load(g_work, g_blob_size, &l));
    /* a little-endian "loaded" magic on a big-endian host and vice versa is not a blob */
    memcpy(g_work, g_blob, g_blob_size);
    uint8_t *b = (uint8_t *)g_work;
    b[0] = 'N'; b[1] = 'S'; b[2] = 'M'; b[3] = 'C';
    uint32_t native;
    memcpy(&native, b, 4);
    if (native != COLL_MESH_MAGIC_NATIVE)
        TEST_ASSERT_EQUAL_INT(COLL_ERR_BAD_MAGIC, coll_mesh_load(g_work, g_blob_size, &l));
}

static void test_every_truncation_fails(void)
{
    make_mesh(0, 10);
    for (size_t s = 0; s < g_blob_size; s++) {
        memcpy(g_work, g_blob, g_blob_size);
        const coll_mesh_t *l = NULL;
        coll_err_t e = coll_mesh_load(g_work, s, &l);
        TEST_ASSERT_EQUAL_INT(s < 4 ? COLL_ERR_TRUNCATED : COLL_ERR_TRUNCATED, e);
        TEST_ASSERT_NULL(l);
        /* nothing was swapped or marked: the full blob still loads */
        TEST_ASSERT_EQUAL_MEMORY(g_blob, g_work, g_blob_size);
    }
}

/* Checks a loaded mesh is internally consistent (only called when load said OK). */
static void walk_mesh(const coll_mesh_t *l)
{
    for (uint32_t t = 0; t < coll_mesh_triangle_count(l); t++) {
        fm_vec3_t v[3];
        coll_mesh_triangle(l, t, v);
    }
    const uint32_t *cells = coll_mesh_cells(l);
    uint32_t n = (uint32_t)coll_mesh_cell_count(l);
    for (uint32_t c = 0; c < n; c++)
        for (uint32_t k = cells[c]; k < cells[c + 1]; k++) TEST_ASSERT_TRUE(coll_mesh_ref(l, k) < l->ntris);
}

static void test_random_bit_flips_detected(void)
{
    core_rng_t r;
    core_rng_seed(&r, 7);
#ifdef __mips__
    const int flips = 400;
#else
    const int flips = 4000;
#endif
    for (int q = 0; q < 2; q++) {
        make_mesh(q ? COLL_MESH_QUANTIZE : 0u, 12);
        int ok = 0;
        for (int i = 0; i < flips; i++) {
            memcpy(g_work, g_blob, g_blob_size);
            int nflip = 1 + (int)(core_rng_u32(&r) % 3);
            for (int f = 0; f < nflip; f++) {
                uint32_t bit = core_rng_u32(&r) % (uint32_t)(g_blob_size * 8);
                ((uint8_t *)g_work)[bit / 8] ^= (uint8_t)(1u << (bit % 8));
            }
            const coll_mesh_t *l = NULL;
            coll_err_t e = coll_mesh_load(g_work, g_blob_size, &l);
            if (e == COLL_OK) {
                ok++;
                walk_mesh(l);
            } else {
                TEST_ASSERT_NULL(l);
            }
        }
        /* only flips in the zero padding between sections can go unseen */
        TEST_ASSERT_TRUE(ok < flips / 20);
    }
}

/* ---- re-forging the checksum so field corruption reaches the deeper checks ---- */

/* Header words of format versions 3 and 4 (136 bytes): magic .. nbuckets, grid_margin, reserved. */
#define HDR_WORDS 34
#define HDR_GRID_MARGIN 32 /* word index */
#define HDR_CELL_SIZE 17

static uint32_t be32(const uint8_t *p) { return (uint32_t)p[0] << 24 | (uint32_t)p[1] << 16 | (uint32_t)p[2] << 8 | p[3]; }
static void put_be32(uint8_t *p, uint32_t v) { p[0] = (uint8_t)(v >> 24); p[1] = (uint8_t)(v >> 16); p[2] = (uint8_t)(v >> 8); p[3] = (uint8_t)v; }

/* Recomputes the checksum of a big-endian blob from its (possibly corrupt) header when
 * the sections it describes fit in size (independent re-implementation of the format
 * doc in mesh_format.h). */
static void forge_checksum(uint8_t *b, size_t size)
{
    uint32_t flags = be32(b + 8), nverts = be32(b + 20), ntris = be32(b + 24), nrefs = be32(b + 28);
    uint64_t ncells = (flags & 8) ? be32(b + 124) : (uint64_t)be32(b + 72) * be32(b + 76) * be32(b + 80);
    if (ncells > size) return;
    /* version 4: with block indices (flag 16) a uint32 base per 64 triangles follows them */
    uint64_t tb = be32(b + 112) + (((uint64_t)ntris * 6u + 7u) & ~(uint64_t)7u);
    /* version 5: with sub-cell codes (flag 32) a byte per ref follows the refs (8-aligned) */
    uint64_t cb = be32(b + 120) + (((uint64_t)nrefs * ((flags & 4) ? 2u : 4u) + 7u) & ~(uint64_t)7u);
    uint64_t off[6] = { be32(b + 108), be32(b + 112), tb, be32(b + 116), be32(b + 120), cb };
    uint64_t cnt[6] = { (uint64_t)nverts * 3, (uint64_t)ntris * 3, (flags & 16) ? ((uint64_t)ntris + 63) / 64 : 0,
                        ncells + 1, nrefs, (flags & 32) ? nrefs : 0 };
    uint32_t es[6] = { (flags & 1) ? 2u : 4u, (flags & 18) ? 2u : 4u, 4u, 4u, (flags & 4) ? 2u : 4u, 1u };
    for (int i = 0; i < 6; i++)
        if (off[i] + cnt[i] * es[i] > size) return;
    uint32_t h = 2166136261u;
    for (int w = 1; w < HDR_WORDS; w++)
        if (w != 4) h = (h ^ be32(b + 4 * w)) * 16777619u;
    for (int i = 0; i < 6; i++)
        for (uint64_t k = 0; k < cnt[i]; k++) {
            const uint8_t *p = b + off[i] + k * es[i];
            uint32_t v = es[i] == 1 ? p[0] : es[i] == 2 ? (uint32_t)(p[0] << 8 | p[1]) : be32(p);
            h = (h ^ v) * 16777619u;
        }
    put_be32(b + 16, h);
}

/* Version 2 blobs (128-byte header, no stored grid margin) are refused as another version,
 * also when cut to their old header length; a stored margin that is negative, not
 * finite or not below the cell size is corrupt. */
static void test_old_version_and_bad_margin_refused(void)
{
    make_mesh(0, 6);
    const coll_mesh_t *l = (const coll_mesh_t *)1;
    uint8_t *b = (uint8_t *)g_work;
    memcpy(g_work, g_blob, g_blob_size);
    put_be32(b + 4, 2);
    forge_checksum(b, g_blob_size);
    uint8_t head[136];
    memcpy(head, b, sizeof head);
    TEST_ASSERT_EQUAL_INT(COLL_ERR_VERSION, coll_mesh_load(g_work, g_blob_size, &l));
    TEST_ASSERT_NULL(l);
    TEST_ASSERT_EQUAL_INT(COLL_ERR_VERSION, coll_mesh_load(g_work, 128, &l));
    TEST_ASSERT_EQUAL_INT(COLL_ERR_VERSION, coll_mesh_load(g_work, 8, &l));
    TEST_ASSERT_EQUAL_MEMORY(head, b, sizeof head); /* left intact */
    float cell;
    uint32_t cw = be32((const uint8_t *)g_blob + 4 * HDR_CELL_SIZE);
    memcpy(&cell, &cw, 4);
    TEST_ASSERT_TRUE(cell > 0.0f);
    const float bad[] = { -1e-6f, cell, 2.0f * cell, INFINITY, NAN };
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        memcpy(g_work, g_blob, g_blob_size);
        uint32_t v;
        memcpy(&v, &bad[i], 4);
        put_be32(b + 4 * HDR_GRID_MARGIN, v);
        forge_checksum(b, g_blob_size);
        TEST_ASSERT_EQUAL_INT(COLL_ERR_CORRUPT, coll_mesh_load(g_work, g_blob_size, &l));
    }
    memcpy(g_work, g_blob, g_blob_size);
    put_be32(b + 4 * (HDR_GRID_MARGIN + 1), 1); /* reserved */
    forge_checksum(b, g_blob_size);
    TEST_ASSERT_EQUAL_INT(COLL_ERR_CORRUPT, coll_mesh_load(g_work, g_blob_size, &l));
    memcpy(g_work, g_blob, g_blob_size);
    TEST_ASSERT_EQUAL_INT(COLL_OK, coll_mesh_load(g_work, g_blob_size, &l));
    TEST_ASSERT_TRUE(l->grid_margin > 0.0f && l->grid_margin < l->cell_size);
}

static void test_forged_checksum_matches_writer(void)
{
    make_mesh(0, 5);
    uint32_t orig = be32((const uint8_t *)g_blob + 16);
    memcpy(g_work, g_blob, g_blob_size);
    forge_checksum((uint8_t *)g_work, g_blob_size);
    TEST_ASSERT_EQUAL_HEX32(orig, be32((const uint8_t *)g_work + 16));
}

static void test_corrupt_fields_with_valid_checksum(void)
{
    static const uint32_t values[] = { 0, 1, 2, 3, 7, 8, 0x7F, 0x80, 0xFFFF, 0x10000, 0x7FFFFFFF, 0x80000000u,
                                       0xFFFFFFFFu, 0xFFFFFFF8u, 0x7F800000u /* inf */, 0x7FC00000u /* nan */,
                                       0xFF800000u, 0x3F800000u /* 1.0f */, 0xBF800000u /* -1.0f */ };
    core_rng_t r;
    core_rng_seed(&r, 99);
    for (int q = 0; q < 2; q++) {
        make_mesh(q ? COLL_MESH_QUANTIZE : 0u, 8);
        /* every header word (not magic/checksum) with every interesting value */
        for (int w = 1; w < HDR_WORDS; w++) {
            if (w == 4) continue;
            for (size_t vi = 0; vi < sizeof values / sizeof values[0] + 2; vi++) {
                memcpy(g_work, g_blob, g_blob_size);
                uint8_t *b = (uint8_t *)g_work;
                uint32_t old = be32(b + 4 * w);
                uint32_t v = vi < sizeof values / sizeof values[0] ? values[vi] : (vi & 1 ? old + 1 : old - 1);
                if (v == old) continue;
                put_be32(b + 4 * w, v);
                forge_checksum(b, g_blob_size);
                const coll_mesh_t *l = NULL;
                coll_err_t e = coll_mesh_load(g_work, g_blob_size, &l);
                if (e == COLL_OK) walk_mesh(l); /* e.g. a bounds float that stays consistent */
            }
        }
        /* payload elements: indices, cell ranges, refs pushed out of range */
        for (int i = 0; i < 3000; i++) {
            memcpy(g_work, g_blob, g_blob_size);
            uint8_t *b = (uint8_t *)g_work;
            uint32_t pos = 4 * HDR_WORDS + core_rng_u32(&r) % (uint32_t)(g_blob_size - 4 * HDR_WORDS);
            pos &= ~1u;
            b[pos] = (uint8_t)core_rng_u32(&r);
            b[pos + 1] ^= 0xFF;
            forge_checksum(b, g_blob_size);
            const coll_mesh_t *l = NULL;
            if (coll_mesh_load(g_work, g_blob_size, &l) == COLL_OK) walk_mesh(l);
        }
    }
    /* targeted: a triangle index = nverts, a ref = ntris, a decreasing cell range */
    make_mesh(0, 8);
    uint8_t *b = (uint8_t *)g_work;
    uint32_t off_tris = be32((uint8_t *)g_blob + 112), off_cells = be32((uint8_t *)g_blob + 116),
             off_refs = be32((uint8_t *)g_blob + 120), nverts = be32((uint8_t *)g_blob + 20),
             ntris = be32((uint8_t *)g_blob + 24);
    const coll_mesh_t *l;
    memcpy(g_work, g_blob, g_blob_size);
    b[off_tris] = (uint8_t)(nverts >> 8); b[off_tris + 1] = (uint8_t)nverts; /* idx16 */
    forge_checksum(b, g_blob_size);
    TEST_ASSERT_EQUAL_INT(COLL_ERR_CORRUPT, coll_mesh_load(g_work, g_blob_size, &l));
    memcpy(g_work, g_blob, g_blob_size);
    b[off_refs] = (uint8_t)(ntris >> 8); b[off_refs + 1] = (uint8_t)ntris; /* ref16 */
    forge_checksum(b, g_blob_size);
    TEST_ASSERT_EQUAL_INT(COLL_ERR_CORRUPT, coll_mesh_load(g_work, g_blob_size, &l));
    memcpy(g_work, g_blob, g_blob_size);
    put_be32(b + off_cells + 4, 0xFFFFu);
    forge_checksum(b, g_blob_size);
    TEST_ASSERT_EQUAL_INT(COLL_ERR_CORRUPT, coll_mesh_load(g_work, g_blob_size, &l));
    /* sub-cell codes (version 5): each nibble a run of one to four quarters; on a version 4
     * header, or on a hashed grid, the flag itself is corrupt */
    TEST_ASSERT_TRUE(be32((uint8_t *)g_blob + 8) & COLL_MESHF_RCODE);
    uint32_t nrefs = be32((uint8_t *)g_blob + 28), off_codes = off_refs + ((nrefs * 2u + 7u) & ~7u);
    static const uint8_t bad_codes[] = { 0x00, 0x0F, 0xF0, 0x5F, 0xF9, 0xAF };
    for (size_t i = 0; i < sizeof bad_codes; i++) {
        memcpy(g_work, g_blob, g_blob_size);
        b[off_codes + nrefs / 2u] = bad_codes[i];
        forge_checksum(b, g_blob_size);
        TEST_ASSERT_EQUAL_INT(COLL_ERR_CORRUPT, coll_mesh_load(g_work, g_blob_size, &l));
    }
    memcpy(g_work, g_blob, g_blob_size);
    b[off_codes + nrefs / 2u] = 0x36; /* another valid code: loads */
    forge_checksum(b, g_blob_size);
    TEST_ASSERT_EQUAL_INT(COLL_OK, coll_mesh_load(g_work, g_blob_size, &l));
    memcpy(g_work, g_blob, g_blob_size);
    put_be32(b + 4, 4);
    forge_checksum(b, g_blob_size);
    TEST_ASSERT_EQUAL_INT(COLL_ERR_CORRUPT, coll_mesh_load(g_work, g_blob_size, &l));
    memcpy(g_work, g_blob, g_blob_size);
    put_be32(b + 16, be32(b + 16) ^ 1u); /* checksum itself */
    TEST_ASSERT_EQUAL_INT(COLL_ERR_CORRUPT, coll_mesh_load(g_work, g_blob_size, &l));
    memcpy(g_work, g_blob, g_blob_size);
    put_be32(b + 12, be32(b + 12) + 8); /* total_size beyond the buffer */
    forge_checksum(b, g_blob_size);
    TEST_ASSERT_EQUAL_INT(COLL_ERR_TRUNCATED, coll_mesh_load(g_work, g_blob_size, &l));
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_round_trip_big_endian_blob);
    RUN_TEST(test_write_blob_errors);
    RUN_TEST(test_load_argument_errors);
    RUN_TEST(test_every_truncation_fails);
    RUN_TEST(test_random_bit_flips_detected);
    RUN_TEST(test_forged_checksum_matches_writer);
    RUN_TEST(test_old_version_and_bad_margin_refused);
    RUN_TEST(test_corrupt_fields_with_valid_checksum);
    return UNITY_END();
}
