/*
 * Bake round trip: the blobs collbake wrote (mk/bake.mk, before the tests run) against
 *  - the numbers tools/gen_levels.py computed from the source geometry (assets/levels/NAME.expect):
 *    triangle count, bounds, surface area;
 *  - a mesh built in memory with coll_mesh_build() from the same welded triangles
 *    (collbake --dump-raw): byte-identical after loading, and >= 1000 raycasts per level
 *    hitting the same triangle at the same distance, and the nearest hit agreeing with a
 *    brute-force loop over every triangle (so the baked grid misses nothing);
 *  - the quantized blobs: every vertex and every ray hit within the error bound collbake
 *    reported (<name>.q.report);
 *  - Debian's assimp-testmodels and a few hostile inputs, baked by an ASan build of collbake
 *    (tools/collbake/bake_testmodels.sh): each baked blob loads, the rest were refused with
 *    an ERROR line, none crashed or tripped a sanitizer; near-duplicate vertices were welded.
 * Runs natively, big-endian under qemu (the blobs are big-endian: this is the swap path on
 * little-endian hosts and the no-swap path on MIPS) and under ASan/UBSan.
 * Files come from $COLL_ASSET_DIR (exported by mk/bake.mk), else build/assets.
 */
#include "unity.h"
#include "coll/mesh.h"
#include "coll/scene.h"
#include "prim.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

void setUp(void) {}
void tearDown(void) {}

static const char *const LEVELS[] = {
    "test_course", "planet", "platform_translate", "platform_rotate", "platform_scale", "platform_lift",
    "stairs_cm",
};
#define NLEVELS (sizeof LEVELS / sizeof LEVELS[0])

#ifdef __mips__
#define RAYS_PER_LEVEL 1000
#define BRUTE_RAYS 200
#else
#define RAYS_PER_LEVEL 2000
#define BRUTE_RAYS 600
#endif

/* ------------------------------------------------------------------ files -------- */

static const char *asset_dir(void)
{
    const char *d = getenv("COLL_ASSET_DIR");
    return d && *d ? d : "build/assets";
}

/* Whole file into an 8-byte aligned block (malloc is 8-aligned on every host we run). */
static void *read_file(const char *path, size_t *size)
{
    FILE *f = fopen(path, "rb");
    if (!f) return NULL;
    fseek(f, 0, SEEK_END);
    long n = ftell(f);
    fseek(f, 0, SEEK_SET);
    void *buf = malloc(n > 0 ? (size_t)n : 1u);
    if (!buf) { fclose(f); return NULL; }
    size_t got = fread(buf, 1, (size_t)n, f);
    fclose(f);
    if (got != (size_t)n) { free(buf); return NULL; }
    *size = got;
    return buf;
}

/* Whole file as a NUL-terminated string, or NULL. */
static char *read_text(const char *path)
{
    size_t size = 0;
    char *txt = read_file(path, &size);
    if (!txt) return NULL;
    char *t = realloc(txt, size + 1);
    if (!t) { free(txt); return NULL; }
    t[size] = 0;
    return t;
}

static void *read_asset(const char *name, const char *suffix, size_t *size)
{
    char path[512];
    snprintf(path, sizeof path, "%s/%s%s", asset_dir(), name, suffix);
    void *b = read_file(path, size);
    if (!b) {
        char msg[600];
        snprintf(msg, sizeof msg, "cannot read %s (run `make assets`)", path);
        TEST_FAIL_MESSAGE(msg);
    }
    return b;
}

static const coll_mesh_t *load_asset(const char *name, const char *suffix, void **block)
{
    size_t size = 0;
    *block = read_asset(name, suffix, &size);
    const coll_mesh_t *m = NULL;
    coll_err_t err = coll_mesh_load(*block, size, &m);
    char msg[200];
    snprintf(msg, sizeof msg, "%s%s: %s", name, suffix, coll_strerror(err));
    TEST_ASSERT_EQUAL_INT_MESSAGE(COLL_OK, err, msg);
    TEST_ASSERT_EQUAL_UINT_MESSAGE(size, coll_mesh_size(m), msg);
    return m;
}

/* "key value..." line of a small text file; returns how many floats were parsed. */
static int find_key(const char *path, const char *key, double *vals, int maxvals)
{
    char *t = read_text(path);
    if (!t) return -1;
    int n = 0;
    size_t klen = strlen(key);
    for (char *line = t; line && *line; line = strchr(line, '\n') ? strchr(line, '\n') + 1 : NULL) {
        if (strncmp(line, key, klen) == 0 && line[klen] == ' ') {
            char *p = line + klen;
            while (n < maxvals) {
                char *end;
                double v = strtod(p, &end);
                if (end == p) break;
                vals[n++] = v;
                p = end;
            }
            break;
        }
    }
    free(t);
    return n;
}

typedef struct {
    uint32_t nverts, ntris;
    float *verts;
    uint32_t *idx;
} raw_t;

static uint32_t le32(const uint8_t *p)
{
    return (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 | (uint32_t)p[3] << 24;
}

static void read_raw(const char *name, raw_t *r)
{
    size_t size = 0;
    uint8_t *b = read_asset(name, ".raw", &size);
    TEST_ASSERT_TRUE(size >= 16);
    TEST_ASSERT_EQUAL_MEMORY("CRAW", b, 4);
    TEST_ASSERT_EQUAL_UINT32(1, le32(b + 4));
    r->nverts = le32(b + 8);
    r->ntris = le32(b + 12);
    TEST_ASSERT_EQUAL_UINT((size_t)16 + (size_t)r->nverts * 12 + (size_t)r->ntris * 12, size);
    r->verts = malloc((size_t)r->nverts * 12 + 4);
    r->idx = malloc((size_t)r->ntris * 12 + 4);
    TEST_ASSERT_NOT_NULL(r->verts);
    TEST_ASSERT_NOT_NULL(r->idx);
    const uint8_t *p = b + 16;
    for (size_t k = 0; k < (size_t)r->nverts * 3; k++, p += 4) {
        uint32_t u = le32(p);
        memcpy(&r->verts[k], &u, 4);
    }
    for (size_t k = 0; k < (size_t)r->ntris * 3; k++, p += 4) r->idx[k] = le32(p);
    free(b);
}

/* Builds in memory with the options the level was baked with (its --cell-size, if any,
 * recorded in <name>.report; 0 = automatic). */
static const coll_mesh_t *build_raw(const char *name, const raw_t *r, void **block)
{
    char path[512];
    double cell = -1.0;
    snprintf(path, sizeof path, "%s/%s.report", asset_dir(), name);
    TEST_ASSERT_EQUAL_INT_MESSAGE(1, find_key(path, "cell_size_requested", &cell, 1), path);
    coll_mesh_build_opts_t opts = { (float)cell, 0u };
    size_t need = coll_mesh_build_size(r->nverts, r->ntris, &opts);
    TEST_ASSERT_TRUE(need > 0);
    *block = malloc(need);
    TEST_ASSERT_NOT_NULL(*block);
    const coll_mesh_t *m = NULL;
    TEST_ASSERT_EQUAL_INT(COLL_OK, coll_mesh_build(*block, need, r->verts, r->nverts, r->idx, r->ntris, &opts, &m));
    return m;
}

/* ------------------------------------------------------------------ geometry ----- */

static uint32_t rng_state;
static float frand(void) /* [0, 1) */
{
    rng_state = rng_state * 1664525u + 1013904223u;
    return (float)(rng_state >> 8) * (1.0f / 16777216.0f);
}

static fm_vec3_t rand_dir(void)
{
    for (;;) {
        fm_vec3_t d = {{2.0f * frand() - 1.0f, 2.0f * frand() - 1.0f, 2.0f * frand() - 1.0f}};
        float l = fm_vec3_len(&d);
        if (l > 0.1f && l <= 1.0f) {
            fm_vec3_scale(&d, &d, 1.0f / l);
            return d;
        }
    }
}

static double tri_area(const fm_vec3_t t[3])
{
    double e1[3], e2[3];
    for (int a = 0; a < 3; a++) { e1[a] = (double)t[1].v[a] - t[0].v[a]; e2[a] = (double)t[2].v[a] - t[0].v[a]; }
    double n0 = e1[1] * e2[2] - e1[2] * e2[1], n1 = e1[2] * e2[0] - e1[0] * e2[2], n2 = e1[0] * e2[1] - e1[1] * e2[0];
    return 0.5 * sqrt(n0 * n0 + n1 * n1 + n2 * n2);
}

/* A ray origin and direction: half aimed at a random point of a random triangle (so most
 * hit), half from random points of the padded bounds in random directions. */
static void make_ray(const coll_mesh_t *m, int k, fm_vec3_t *o, fm_vec3_t *d, float *max_dist)
{
    fm_vec3_t lo, hi;
    coll_mesh_bounds(m, &lo, &hi);
    float diag = fm_vec3_distance(&lo, &hi) + 1.0f;
    for (int a = 0; a < 3; a++) o->v[a] = lo.v[a] - 1.0f + (hi.v[a] - lo.v[a] + 2.0f) * frand();
    if (k & 1) {
        fm_vec3_t t[3];
        coll_mesh_triangle(m, (uint32_t)(frand() * (float)coll_mesh_triangle_count(m)), t);
        float u = frand(), v = frand();
        if (u + v > 1.0f) { u = 1.0f - u; v = 1.0f - v; }
        fm_vec3_t target;
        for (int a = 0; a < 3; a++) target.v[a] = t[0].v[a] + u * (t[1].v[a] - t[0].v[a]) + v * (t[2].v[a] - t[0].v[a]);
        fm_vec3_sub(d, &target, o);
        float l = fm_vec3_len(d);
        if (l < 1e-3f) *d = rand_dir();
        else fm_vec3_scale(d, d, 1.0f / l);
    } else {
        *d = rand_dir();
    }
    *max_dist = 2.0f * diag;
}

/* Nearest hit over every triangle, no grid. */
static bool brute_raycast(const coll_mesh_t *m, const fm_vec3_t *o, const fm_vec3_t *d, float max_dist,
                          float *dist, int32_t *tri)
{
    bool any = false;
    float best = max_dist;
    for (uint32_t i = 0; i < coll_mesh_triangle_count(m); i++) {
        fm_vec3_t t[3];
        coll_mesh_triangle(m, i, t);
        coll_prim_hit_t h;
        if (coll_ray_triangle(o, d, t, best, &h) && h.t <= best) {
            best = h.t;
            *tri = (int32_t)i;
            any = true;
        }
    }
    *dist = best;
    return any;
}

typedef struct {
    coll_scene_t scene;
    coll_mesh_instance_t inst;
} one_mesh_scene_t;

static void scene_of(one_mesh_scene_t *s, const coll_mesh_t *m)
{
    coll_transform_t id = COLL_TRANSFORM_IDENTITY;
    coll_scene_init(&s->scene);
    memset(&s->inst, 0, sizeof s->inst);
    s->inst.mesh = m;
    s->inst.xf = id;
    s->inst.write_mask = 0xFF;
    s->inst.id = 7;
    TEST_ASSERT_EQUAL_INT(COLL_OK, coll_scene_add_mesh(&s->scene, &s->inst));
}

/* ------------------------------------------------------------------ tests -------- */

/* Every baked level holds exactly the source geometry gen_levels.py computed. */
static void test_baked_levels_match_the_source_geometry(void)
{
    for (size_t l = 0; l < NLEVELS; l++) {
        void *block;
        const coll_mesh_t *m = load_asset(LEVELS[l], ".coll", &block);
        char path[256], msg[300];
        snprintf(path, sizeof path, "assets/levels/%s.expect", LEVELS[l]);
        double tris = 0, b[6], area = 0;
        TEST_ASSERT_EQUAL_INT_MESSAGE(1, find_key(path, "triangles", &tris, 1), path);
        TEST_ASSERT_EQUAL_INT_MESSAGE(6, find_key(path, "bounds", b, 6), path);
        TEST_ASSERT_EQUAL_INT_MESSAGE(1, find_key(path, "area", &area, 1), path);
        snprintf(msg, sizeof msg, "%s: triangle count", LEVELS[l]);
        TEST_ASSERT_EQUAL_UINT32_MESSAGE((uint32_t)tris, coll_mesh_triangle_count(m), msg);
        fm_vec3_t lo, hi;
        coll_mesh_bounds(m, &lo, &hi);
        snprintf(msg, sizeof msg, "%s: bounds", LEVELS[l]);
        for (int a = 0; a < 3; a++) {
            TEST_ASSERT_DOUBLE_WITHIN_MESSAGE(1e-4 + 1e-6 * fabs(b[a]), b[a], lo.v[a], msg);
            TEST_ASSERT_DOUBLE_WITHIN_MESSAGE(1e-4 + 1e-6 * fabs(b[3 + a]), b[3 + a], hi.v[a], msg);
        }
        double sum = 0.0;
        for (uint32_t i = 0; i < coll_mesh_triangle_count(m); i++) {
            fm_vec3_t t[3];
            coll_mesh_triangle(m, i, t);
            sum += tri_area(t);
        }
        snprintf(msg, sizeof msg, "%s: surface area", LEVELS[l]);
        TEST_ASSERT_DOUBLE_WITHIN_MESSAGE(1e-5 * area + 1e-6, area, sum, msg);
        free(block);
    }
}

/* Loading the baked blob gives the very bytes coll_mesh_build() makes from the same
 * triangles in memory (one layout, one builder; the loader's swap restores it exactly). */
static void test_loaded_blob_equals_in_memory_build(void)
{
    for (size_t l = 0; l < NLEVELS; l++) {
        void *block, *built_block;
        raw_t r;
        const coll_mesh_t *m = load_asset(LEVELS[l], ".coll", &block);
        read_raw(LEVELS[l], &r);
        const coll_mesh_t *b = build_raw(LEVELS[l], &r, &built_block);
        TEST_ASSERT_EQUAL_UINT32_MESSAGE(coll_mesh_triangle_count(b), coll_mesh_triangle_count(m), LEVELS[l]);
        TEST_ASSERT_EQUAL_UINT_MESSAGE(coll_mesh_size(b), coll_mesh_size(m), LEVELS[l]);
        TEST_ASSERT_EQUAL_MEMORY_MESSAGE(b, m, coll_mesh_size(m), LEVELS[l]);
        /* Loading the already-loaded buffer again is fine and changes nothing. */
        const coll_mesh_t *again = NULL;
        TEST_ASSERT_EQUAL_INT(COLL_OK, coll_mesh_load(block, coll_mesh_size(m), &again));
        TEST_ASSERT_EQUAL_MEMORY_MESSAGE(b, again, coll_mesh_size(m), LEVELS[l]);
        free(r.verts);
        free(r.idx);
        free(built_block);
        free(block);
    }
}

/* Raycasts through a scene: the baked mesh and the in-memory mesh hit the same triangle at
 * the same distance, and (on a subset) the nearest hit of a brute-force loop over every
 * triangle, so the baked grid hides no triangle from the query. */
static void test_raycasts_agree_with_in_memory_build_and_brute_force(void)
{
    uint32_t total = 0, hits = 0, brute = 0;
    for (size_t l = 0; l < NLEVELS; l++) {
        void *block, *built_block;
        raw_t r;
        const coll_mesh_t *m = load_asset(LEVELS[l], ".coll", &block);
        read_raw(LEVELS[l], &r);
        const coll_mesh_t *b = build_raw(LEVELS[l], &r, &built_block);
        one_mesh_scene_t sa, sb;
        scene_of(&sa, m);
        scene_of(&sb, b);
        rng_state = 12345u + (uint32_t)l;
        uint32_t level_hits = 0;
        for (int k = 0; k < RAYS_PER_LEVEL; k++) {
            fm_vec3_t o, d;
            float maxd;
            make_ray(m, k, &o, &d, &maxd);
            coll_ray_hit_t ha, hb;
            bool a = coll_raycast(&sa.scene, o, d, maxd, 0xFF, COLL_TYPE_ALL, &ha);
            bool bb = coll_raycast(&sb.scene, o, d, maxd, 0xFF, COLL_TYPE_ALL, &hb);
            char msg[200];
            snprintf(msg, sizeof msg, "%s ray %d", LEVELS[l], k);
            TEST_ASSERT_EQUAL_INT_MESSAGE(bb, a, msg);
            total++;
            if (a) {
                level_hits++;
                TEST_ASSERT_EQUAL_INT32_MESSAGE(hb.triangle, ha.triangle, msg);
                TEST_ASSERT_EQUAL_FLOAT_MESSAGE(hb.distance, ha.distance, msg);
                TEST_ASSERT_EQUAL_UINT16_MESSAGE(7, ha.id, msg);
            }
            if (k < BRUTE_RAYS) {
                float bd;
                int32_t bt = -1;
                bool bh = brute_raycast(m, &o, &d, maxd, &bd, &bt);
                TEST_ASSERT_EQUAL_INT_MESSAGE(bh, a, msg);
                if (bh) {
                    TEST_ASSERT_FLOAT_WITHIN_MESSAGE(1e-4f * (1.0f + bd), bd, ha.distance, msg);
                    brute++;
                }
            }
        }
        /* Half the rays aim at triangles: most must hit, or the test proves nothing. */
        TEST_ASSERT_TRUE_MESSAGE(level_hits > RAYS_PER_LEVEL / 3, LEVELS[l]);
        hits += level_hits;
        free(r.verts);
        free(r.idx);
        free(built_block);
        free(block);
    }
    printf("bake roundtrip: %u rays, %u hits, %u checked against brute force\n", (unsigned)total,
           (unsigned)hits, (unsigned)brute);
}

/* Barycentric coordinates of p in triangle t (p assumed on its plane). */
static void barycentric(const fm_vec3_t t[3], const fm_vec3_t *p, double w[3])
{
    double e0[3], e1[3], ep[3];
    for (int a = 0; a < 3; a++) {
        e0[a] = (double)t[1].v[a] - t[0].v[a];
        e1[a] = (double)t[2].v[a] - t[0].v[a];
        ep[a] = (double)p->v[a] - t[0].v[a];
    }
    double d00 = e0[0] * e0[0] + e0[1] * e0[1] + e0[2] * e0[2];
    double d01 = e0[0] * e1[0] + e0[1] * e1[1] + e0[2] * e1[2];
    double d11 = e1[0] * e1[0] + e1[1] * e1[1] + e1[2] * e1[2];
    double d20 = ep[0] * e0[0] + ep[1] * e0[1] + ep[2] * e0[2];
    double d21 = ep[0] * e1[0] + ep[1] * e1[1] + ep[2] * e1[2];
    double den = d00 * d11 - d01 * d01;
    w[1] = (d11 * d20 - d01 * d21) / den;
    w[2] = (d00 * d21 - d01 * d20) / den;
    w[0] = 1.0 - w[1] - w[2];
}

/* Quantized blobs: smaller, same triangles, every vertex and every ray hit within the
 * worst-case error collbake printed and stored in <name>.q.report. */
static void test_quantized_blobs_stay_within_the_reported_error(void)
{
    for (size_t l = 0; l < NLEVELS; l++) {
        void *fb, *qb;
        const coll_mesh_t *f = load_asset(LEVELS[l], ".coll", &fb);
        const coll_mesh_t *q = load_asset(LEVELS[l], ".q.coll", &qb);
        char path[512], msg[300];
        snprintf(path, sizeof path, "%s/%s.q.report", asset_dir(), LEVELS[l]);
        double quantized = 0, eps = -1;
        TEST_ASSERT_EQUAL_INT_MESSAGE(1, find_key(path, "quantized", &quantized, 1), path);
        TEST_ASSERT_EQUAL_INT_MESSAGE(1, find_key(path, "quant_error", &eps, 1), path);
        TEST_ASSERT_EQUAL_INT_MESSAGE(1, (int)quantized, LEVELS[l]);
        TEST_ASSERT_TRUE_MESSAGE(eps >= 0.0 && eps < 0.005, LEVELS[l]);
        TEST_ASSERT_TRUE_MESSAGE(coll_mesh_size(q) < coll_mesh_size(f), LEVELS[l]);
        TEST_ASSERT_EQUAL_UINT32_MESSAGE(coll_mesh_triangle_count(f), coll_mesh_triangle_count(q), LEVELS[l]);
        double worst = 0.0;
        for (uint32_t i = 0; i < coll_mesh_triangle_count(f); i++) {
            fm_vec3_t tf[3], tq[3];
            coll_mesh_triangle(f, i, tf);
            coll_mesh_triangle(q, i, tq);
            for (int k = 0; k < 3; k++) {
                double dd = fm_vec3_distance(&tf[k], &tq[k]);
                if (dd > worst) worst = dd;
            }
        }
        snprintf(msg, sizeof msg, "%s: vertex error %.3g > reported %.3g", LEVELS[l], worst, eps);
        TEST_ASSERT_TRUE_MESSAGE(worst <= eps * 1.0001 + 1e-7, msg);

        one_mesh_scene_t sf, sq;
        scene_of(&sf, f);
        scene_of(&sq, q);
        rng_state = 777u + (uint32_t)l;
        int same = 0, both = 0, n = RAYS_PER_LEVEL / 2;
        float tol = (float)eps + 2e-5f;
        for (int k = 0; k < n; k++) {
            fm_vec3_t o, d;
            float maxd;
            make_ray(f, 2 * k + 1, &o, &d, &maxd);
            coll_ray_hit_t hf, hq;
            bool a = coll_raycast(&sf.scene, o, d, maxd, 0xFF, COLL_TYPE_ALL, &hf);
            bool b = coll_raycast(&sq.scene, o, d, maxd, 0xFF, COLL_TYPE_ALL, &hq);
            if (!b) continue;
            snprintf(msg, sizeof msg, "%s quantized ray %d", LEVELS[l], k);
            /* The quantized hit lies on quantized triangle i; the same barycentric point of
             * float triangle i is within eps of it. */
            fm_vec3_t tq[3], tf[3], pf;
            coll_mesh_triangle(q, (uint32_t)hq.triangle, tq);
            coll_mesh_triangle(f, (uint32_t)hq.triangle, tf);
            double w[3];
            barycentric(tq, &hq.point, w);
            for (int a2 = 0; a2 < 3; a2++)
                pf.v[a2] = (float)(w[0] * tf[0].v[a2] + w[1] * tf[1].v[a2] + w[2] * tf[2].v[a2]);
            TEST_ASSERT_FLOAT_WITHIN_MESSAGE(tol * (1.0f + 1e-3f * hq.distance), 0.0f,
                                             fm_vec3_distance(&pf, &hq.point), msg);
            if (a) {
                both++;
                if (hf.triangle == hq.triangle) {
                    /* Same triangle: distances differ by at most eps / |cos(ray, normal)|. */
                    same++;
                    float c = fabsf(fm_vec3_dot(&d, &hf.normal));
                    if (c > 0.05f)
                        TEST_ASSERT_FLOAT_WITHIN_MESSAGE(tol / c + 1e-4f * hf.distance, hf.distance, hq.distance, msg);
                }
            }
        }
        snprintf(msg, sizeof msg, "%s: only %d of %d quantized hits on the same triangle", LEVELS[l], same, both);
        TEST_ASSERT_TRUE_MESSAGE(both > n / 2 && same >= both * 9 / 10, msg);
        free(fb);
        free(qb);
    }
}

/* A tool test's results.tsv (assets/<sub>/results.tsv) as text; fails the test naming
 * the make target that writes it when it is missing. */
static char *read_results(const char *sub, const char *missing)
{
    char path[512];
    snprintf(path, sizeof path, "%s/%s/results.tsv", asset_dir(), sub);
    char *t = read_text(path);
    TEST_ASSERT_NOT_NULL_MESSAGE(t, missing);
    return t;
}

/* collbake's Quake III BSP reader and loss rule (tools/collbake/test_bsp.sh, ASan build):
 * the tiny generated BSP bakes to the expected triangles and bounds, every broken copy is
 * refused with an ERROR line naming the file, random corruption never crashes, and a bake
 * keeping under half its input triangles is refused. */
static void test_bsp_reader_and_loss_rule(void)
{
    char *t = read_results("bsp", "no BSP test results (make bsp-test)");
    int ok = 0, bad = 0, refused = 0;
    bool good = false, loss = false;
    char *save = NULL;
    for (char *line = strtok_r(t, "\n", &save); line; line = strtok_r(NULL, "\n", &save)) {
        if (strncmp(line, "ok\t", 3) == 0) {
            ok++;
            if (strncmp(line + 3, "good\t", 5) == 0) good = true;
            if (strncmp(line + 3, "loss_rule\t", 10) == 0) loss = true;
            if (strncmp(line + 3, "bad_", 4) == 0) refused++;
        } else {
            printf("%s\n", line);
            bad++;
        }
    }
    free(t);
    printf("BSP reader: %d checks ok (%d broken files refused), %d failed\n", ok, refused, bad);
    TEST_ASSERT_TRUE(good);
    TEST_ASSERT_TRUE(loss);
    TEST_ASSERT_TRUE(refused >= 20);
    TEST_ASSERT_EQUAL_INT_MESSAGE(0, bad, "BSP checks failed (listed above)");
}

/* assimp-testmodels and the must-refuse inputs: no crash, every baked blob loads. */
static void test_testmodels_bake_and_load_or_are_refused(void)
{
    char *t = read_results("testmodels", "no testmodels results (make bake-testmodels)");
    int baked = 0, refused = 0, crashed = 0, must_refuse = 0, must_weld = 0, loaded = 0;
    uint64_t tris = 0;
    char *save = NULL;
    for (char *line = strtok_r(t, "\n", &save); line; line = strtok_r(NULL, "\n", &save)) {
        char *f[5] = { 0 };
        char *p = line;
        for (int k = 0; k < 5 && p; k++) {
            f[k] = p;
            p = strchr(p, '\t');
            if (p) *p++ = 0;
        }
        TEST_ASSERT_NOT_NULL_MESSAGE(f[3], "malformed results line");
        bool must = strncmp(f[3], "must-refuse:", 12) == 0;
        if (strncmp(f[3], "must-weld:", 10) == 0) {
            must_weld++;
            char wmsg[700];
            snprintf(wmsg, sizeof wmsg, "%s: %s %s", f[3], f[0], f[4] ? f[4] : "");
            TEST_ASSERT_EQUAL_STRING_MESSAGE("baked", f[0], wmsg);
        }
        char msg[700];
        snprintf(msg, sizeof msg, "%s: %s %s", f[3], f[0], f[4] ? f[4] : "");
        if (!strcmp(f[0], "crash")) { crashed++; TEST_FAIL_MESSAGE(msg); }
        if (must) {
            must_refuse++;
            TEST_ASSERT_EQUAL_STRING_MESSAGE("refused", f[0], msg);
            TEST_ASSERT_NOT_NULL_MESSAGE(strstr(f[4] ? f[4] : "", "ERROR: "), msg);
        }
        if (!strcmp(f[0], "refused")) {
            refused++;
            TEST_ASSERT_NOT_NULL_MESSAGE(f[4], msg);
            TEST_ASSERT_EQUAL_INT_MESSAGE(0, strncmp(f[4], "ERROR: ", 7), msg);
        } else if (!strcmp(f[0], "baked")) {
            baked++;
            char name[64];
            snprintf(name, sizeof name, "testmodels/%s", f[2]);
            void *block;
            const coll_mesh_t *m = load_asset(name, "", &block);
            uint32_t n = coll_mesh_triangle_count(m);
            TEST_ASSERT_TRUE_MESSAGE(n > 0, msg);
            fm_vec3_t lo, hi, tv[3];
            coll_mesh_bounds(m, &lo, &hi);
            for (int a = 0; a < 3; a++) TEST_ASSERT_TRUE_MESSAGE(isfinite(lo.v[a]) && lo.v[a] <= hi.v[a], msg);
            coll_mesh_triangle(m, n - 1, tv);
            for (int k = 0; k < 3; k++)
                for (int a = 0; a < 3; a++)
                    TEST_ASSERT_TRUE_MESSAGE(tv[k].v[a] >= lo.v[a] - 1e-3f && tv[k].v[a] <= hi.v[a] + 1e-3f, msg);
            tris += n;
            loaded++;
            free(block);
        }
    }
    free(t);
    printf("assimp-testmodels: %d baked and loaded (%llu triangles), %d refused with an ERROR line "
           "(%d of them must-refuse inputs), %d crashed\n",
           loaded, (unsigned long long)tris, refused, must_refuse, crashed);
    TEST_ASSERT_EQUAL_INT(0, crashed);
    TEST_ASSERT_EQUAL_INT(7, must_refuse);
    TEST_ASSERT_EQUAL_INT(2, must_weld);
    TEST_ASSERT_TRUE_MESSAGE(baked >= 20, "assimp-testmodels missing? fewer than 20 models baked");
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_baked_levels_match_the_source_geometry);
    RUN_TEST(test_loaded_blob_equals_in_memory_build);
    RUN_TEST(test_raycasts_agree_with_in_memory_build_and_brute_force);
    RUN_TEST(test_quantized_blobs_stay_within_the_reported_error);
    RUN_TEST(test_testmodels_bake_and_load_or_are_refused);
    RUN_TEST(test_bsp_reader_and_loss_rule);
    return UNITY_END();
}
