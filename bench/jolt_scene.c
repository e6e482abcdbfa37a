/* Jolt CharacterVirtual performance scene, rebuilt for this library (docs/JOLT-SCENE.md).
 *
 * Our own C version of the scene in Jolt Physics' PerformanceTest/CharacterVirtualScene.h
 * (read, not copied): 100 characters on a 100 x 100 cell sine heightfield of 0.5 m cells, a
 * pyramid of ten 0.3 m stair slabs and a wall of ten pillars, each walking to a target that
 * changes every 2 s at 5-9.5 m/s, dt 1/60. Character-vs-character contacts are off; Jolt's
 * 100 dynamic boxes are left out (no rigid bodies here).
 *
 *   jolt_scene STEPS [CELL [MAX_SLIDES]]
 *       CELL: grid cell in meters, 0 or absent = automatic
 *       MAX_SLIDES: sweep-and-slide iterations per step, absent = the library's default (4)
 *
 * Prints key=value lines. Instructions are counted by callgrind with
 * --toggle-collect=jolt_step_all: that function is the per-step character loop (target
 * logic + char_body_move_and_slide_in for all 100 bodies) and nothing else; the scene build
 * and the accuracy checks run outside it.
 *
 * Accuracy: after every step each body's sweep capsule (the capsule the library keeps out of
 * geometry: the full capsule shortened from the bottom by step_height) is measured against
 * the scene's triangles in double precision by host_tests/support/soak_check.c's
 * segment-triangle distance, never by the library's queries. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "coll/char_body.h"
#include "coll/mesh.h"
#include "mesh_format.h" /* the effective grid cell (the builder may coarsen a request) */
#include "coll/scene.h"
#include "soak_sim.h"         /* soak_seg_tri_dist, soak_body_capsules (independent checker) */

/* ---- the scene's numbers (CharacterVirtualScene.h) ---- */
#define HF_N          100      /* cells per side */
#define HF_CELL       0.5      /* m */
#define HF_MAX_HEIGHT 2.0      /* m: height = 2 sin(20 x / n) cos(20 z / n), x, z vertex indices */
#define HF_CENTER     (HF_N * HF_CELL / 2.0) /* the mesh is placed at (-25, 0, -25) */
#define NSTAIRS       10
#define STAIR_H       0.3      /* cStairsStepHeight */
#define NPILLARS      10
#define NCHAR_X       10
#define NCHAR_Y       10
#define NCHARS        (NCHAR_X * NCHAR_Y)
#define CH_HEIGHT_STANDING 1.35f /* Jolt: length of the capsule's cylinder part */
#define CH_RADIUS     0.3f
#define DT            (1.0f / 60.0f)
#define TARGET_STEPS  120      /* targets change every 2 s = 120 steps of 1/60 s */
#define SETTLE_STEPS  120      /* after the measured steps: inputs stop for 2 s (not measured) */
#define REST_SPEED    0.2      /* m/s: a body slower than this is at rest */

#define NBOXES   (NSTAIRS + NPILLARS)
#define NVERTS   ((HF_N + 1) * (HF_N + 1) + NBOXES * 8)
#define NTRIS    (HF_N * HF_N * 2 + NBOXES * 12)
#define HF_TRIS  (HF_N * HF_N * 2)

static float g_verts[NVERTS * 3];
static uint32_t g_idx[NTRIS * 3];
static double g_tri[NTRIS][3][3];       /* world-space triangles in double (checker) */
static double g_box_c[NBOXES][3], g_box_r[NBOXES]; /* box bounding spheres (checker) */
static _Alignas(16) unsigned char g_pool[16u << 20];

static coll_scene_t g_scene;
static coll_query_stats_t g_stats; /* the measured steps' query counters */
static coll_mesh_instance_t g_inst;
static char_body_t g_body[NCHARS];
static fm_vec3_t g_owner[NCHARS];

/* ------------------------------------------------------------------ geometry */
static uint32_t g_nv, g_nt;

static void add_box(double cx, double cy, double cz, double hx, double hy, double hz)
{
    uint32_t b = g_nv;
    for (int k = 0; k < 8; k++) {
        g_verts[g_nv * 3 + 0] = (float)(cx + ((k & 1) ? hx : -hx));
        g_verts[g_nv * 3 + 1] = (float)(cy + ((k & 2) ? hy : -hy));
        g_verts[g_nv * 3 + 2] = (float)(cz + ((k & 4) ? hz : -hz));
        g_nv++;
    }
    /* 6 faces, 2 triangles each, wound outwards (triangles are two-sided anyway) */
    static const uint8_t f[12][3] = {
        {0, 4, 6}, {0, 6, 2}, /* -x */ {1, 3, 7}, {1, 7, 5}, /* +x */
        {0, 1, 5}, {0, 5, 4}, /* -y */ {2, 6, 7}, {2, 7, 3}, /* +y */
        {0, 2, 3}, {0, 3, 1}, /* -z */ {4, 5, 7}, {4, 7, 6}, /* +z */
    };
    for (int t = 0; t < 12; t++) {
        for (int j = 0; j < 3; j++) g_idx[g_nt * 3 + (uint32_t)j] = b + f[t][j];
        g_nt++;
    }
}

static void build_geometry(void)
{
    g_nv = g_nt = 0;
    /* heightfield: vertex (x, z) at index z * (n + 1) + x, world (0.5 x - 25, h, 0.5 z - 25) */
    for (int z = 0; z <= HF_N; z++)
        for (int x = 0; x <= HF_N; x++) {
            double h = HF_MAX_HEIGHT * sin(x * 20.0 / HF_N) * cos(z * 20.0 / HF_N);
            uint32_t v = (uint32_t)(z * (HF_N + 1) + x);
            g_verts[v * 3 + 0] = (float)(HF_CELL * x - HF_CENTER);
            g_verts[v * 3 + 1] = (float)h;
            g_verts[v * 3 + 2] = (float)(HF_CELL * z - HF_CENTER);
        }
    g_nv = (HF_N + 1) * (HF_N + 1);
    /* two triangles per cell, split along the (x+1, z) - (x, z+1) diagonal as Jolt's */
    for (int x = 0; x < HF_N; x++)
        for (int z = 0; z < HF_N; z++) {
            uint32_t s = (uint32_t)((HF_N + 1) * z + x), t = (uint32_t)(x * HF_N + z) * 2u;
            uint32_t *i = &g_idx[t * 3];
            i[0] = s; i[1] = s + HF_N + 1; i[2] = s + 1;
            i[3] = s + 1; i[4] = s + HF_N + 1; i[5] = s + HF_N + 2;
        }
    g_nt = HF_TRIS;
    /* pyramid stairs: Jolt's BoxShape takes half extents: slab i is (8 - 0.8 i) m square,
     * 0.3 m thick, centred at (-4, -1 + 0.3 i, 0) */
    for (int i = 0; i < NSTAIRS; i++) {
        double w = 4.0 - 0.4 * i;
        add_box(-4.0, -1.0 + i * STAIR_H, 0.0, w, 0.5 * STAIR_H, w);
    }
    /* wall: pillars of half extents (0.1, 2.5, 0.1) at (2, 1, 2 + 0.2 z): they touch, a
     * continuous 0.2 m thick, 5 m high wall from z = 1.9 to 3.9 */
    for (int z = 0; z < NPILLARS; z++) add_box(2.0, 1.0, 2.0 + 0.2 * z, 0.1, 2.5, 0.1);

    /* checker copy: the float vertices the library sees, in double */
    for (uint32_t t = 0; t < g_nt; t++)
        for (int j = 0; j < 3; j++)
            for (int k = 0; k < 3; k++) g_tri[t][j][k] = g_verts[g_idx[t * 3 + (uint32_t)j] * 3 + (uint32_t)k];
    for (int b = 0; b < NBOXES; b++) {
        const float *v0 = &g_verts[((HF_N + 1) * (HF_N + 1) + b * 8) * 3];
        const float *v7 = v0 + 7 * 3;
        double r2 = 0;
        for (int k = 0; k < 3; k++) {
            g_box_c[b][k] = 0.5 * ((double)v0[k] + v7[k]);
            double d = 0.5 * ((double)v7[k] - v0[k]);
            r2 += d * d;
        }
        g_box_r[b] = sqrt(r2);
    }
}

/* ------------------------------------------------------------------ target logic */
/* Deterministic random input (our own: xorshift64* of a Weyl-scrambled counter; Jolt uses
 * its Hash<uint64> of the same counter). */
static uint64_t jolt_hash(uint64_t v)
{
    uint64_t x = v * 0x9E3779B97F4A7C15ull + 0x6A09E667F3BCC909ull;
    x ^= x >> 12;
    x ^= x << 25;
    x ^= x >> 27;
    return x * 0x2545F4914F6CDD1Dull;
}

static uint32_t g_step; /* steps taken so far */
/* JOLT_GATHER_CACHE=1 in the environment: each body gets a gather cache of its own
 * (char_body_set_gather_cache; the printed gather_cache_* lines count its use). */
static coll_gather_cache_t g_cache[NCHARS];

/* The measured region: one step of all 100 characters. Kept out of line so callgrind's
 * --toggle-collect=jolt_step_all counts exactly this loop. */
__attribute__((noinline)) void jolt_step_all(char_body_t *bodies, fm_vec3_t *owners, const coll_scene_t *scene,
                                            uint32_t step, float dt);
__attribute__((noinline)) void jolt_step_all(char_body_t *bodies, fm_vec3_t *owners, const coll_scene_t *scene,
                                            uint32_t step, float dt)
{
    /* Jolt: count = uint64(time / 2) * 100, time advanced before the loop; +1 per character */
    uint64_t count = (uint64_t)((step + 1u) / TARGET_STEPS) * NCHARS;
    for (int i = 0; i < NCHARS; i++, count++) {
        uint64_t h = jolt_hash(count);
        int tx = (int)(h % 10u), ty = (int)((h / 10u) % 10u), speed = (int)((h / 100u) % 10u);
        /* target (4 x - 20, 5, 4 y - 20); direction normalized in 3D, then its vertical part
         * dropped (as Jolt's scene: the horizontal speed is below 5-9.5 m/s when the target is
         * far above or below) */
        fm_vec3_t d = {{(float)(4 * tx - 20) - owners[i].x, 5.0f - owners[i].y, (float)(4 * ty - 20) - owners[i].z}};
        float l2 = d.x * d.x + d.y * d.y + d.z * d.z;
        float s = l2 > 1.0e-12f ? (5.0f + 0.5f * (float)speed) / sqrtf(l2) : 0.0f;
        bodies[i].input_velocity = (fm_vec3_t){{d.x * s, 0.0f, d.z * s}};
        /* vertical velocity: Jolt zeroes it on the ground and adds gravity; the body does both */
        char_body_move_and_slide_in(&bodies[i], scene, dt);
    }
}

/* ------------------------------------------------------------------ checker */
typedef struct {
    double max_pen_sweep;
    double min_clear_sweep;   /* smallest distance of the sweep capsule's surface to a triangle */
    double max_pen_full_terrain, max_pen_full_box; /* full capsule (informational) */
    uint64_t pen_samples;     /* body-steps with the sweep capsule > 1 mm into a triangle */
    uint64_t samples;
    uint64_t airborne_samples;
    uint64_t stepped, hit_wall;   /* body-steps with a STEPPED / HIT_WALL event */
    uint64_t near_boxes;          /* body-steps with the full capsule within 5 cm of the stairs or wall */
    double min_foot_y;
    int worst_body; uint32_t worst_step;
} check_t;

/* Smallest distance of capsule segment a..b to the scene's triangles within reach (the
 * heightfield cells under the capsule's bounding box, boxes by bounding sphere). */
static double cap_dist2(const soak_capsule_t *c, double reach, double *box_out)
{
    double best = 1e300, bbest = 1e300;
    double lo[2], hi[2];
    for (int k = 0; k < 2; k++) {
        int a = k ? 2 : 0;
        lo[k] = fmin(c->a[a], c->b[a]) - reach;
        hi[k] = fmax(c->a[a], c->b[a]) + reach;
    }
    int x0 = (int)floor((lo[0] + HF_CENTER) / HF_CELL), x1 = (int)floor((hi[0] + HF_CENTER) / HF_CELL);
    int z0 = (int)floor((lo[1] + HF_CENTER) / HF_CELL), z1 = (int)floor((hi[1] + HF_CENTER) / HF_CELL);
    if (x0 < 0) x0 = 0;
    if (z0 < 0) z0 = 0;
    if (x1 > HF_N - 1) x1 = HF_N - 1;
    if (z1 > HF_N - 1) z1 = HF_N - 1;
    for (int x = x0; x <= x1; x++)
        for (int z = z0; z <= z1; z++)
            for (int j = 0; j < 2; j++) {
                double (*t)[3] = g_tri[(x * HF_N + z) * 2 + j];
                double d = soak_seg_tri_dist(c->a, c->b, t[0], t[1], t[2]);
                if (d < best) best = d;
            }
    double mid[3], half = 0;
    for (int k = 0; k < 3; k++) {
        mid[k] = 0.5 * (c->a[k] + c->b[k]);
        half += (c->b[k] - c->a[k]) * (c->b[k] - c->a[k]);
    }
    half = 0.5 * sqrt(half);
    for (int b = 0; b < NBOXES; b++) {
        double dc = 0;
        for (int k = 0; k < 3; k++) dc += (mid[k] - g_box_c[b][k]) * (mid[k] - g_box_c[b][k]);
        if (sqrt(dc) > half + reach + g_box_r[b]) continue;
        for (int t = 0; t < 12; t++) {
            double (*v)[3] = g_tri[HF_TRIS + b * 12 + t];
            double d = soak_seg_tri_dist(c->a, c->b, v[0], v[1], v[2]);
            if (d < bbest) bbest = d;
        }
    }
    if (box_out) *box_out = bbest;
    return best < bbest ? best : bbest;
}

static double cap_dist(const soak_capsule_t *c, double reach) { return cap_dist2(c, reach, NULL); }

static void check_step(check_t *ck, uint32_t step)
{
    for (int i = 0; i < NCHARS; i++) {
        soak_capsule_t full, sweep;
        soak_body_capsules(&g_body[i], &full, &sweep);
        double ps = sweep.r - cap_dist(&sweep, sweep.r), dbox;
        double pf = full.r - cap_dist2(&full, full.r, &dbox), pfb = full.r - dbox;
        if (-ps < ck->min_clear_sweep) ck->min_clear_sweep = -ps;
        if (ps > ck->max_pen_sweep) { ck->max_pen_sweep = ps; ck->worst_body = i; ck->worst_step = step; }
        if (pfb > ck->max_pen_full_box) ck->max_pen_full_box = pfb;
        if (pfb > -0.05) ck->near_boxes++;
        const char_body_events_t *ev = char_body_events(&g_body[i]);
        ck->stepped += (ev->flags & CHAR_BODY_EVENT_STEPPED) != 0;
        ck->hit_wall += (ev->flags & CHAR_BODY_EVENT_HIT_WALL) != 0;
        if (pf > pfb && pf > ck->max_pen_full_terrain) ck->max_pen_full_terrain = pf;
        if (ps > 1e-3) ck->pen_samples++;
        if (char_body_ground_state(&g_body[i]) == CHAR_BODY_AIRBORNE) ck->airborne_samples++;
        if (g_owner[i].y < ck->min_foot_y) ck->min_foot_y = g_owner[i].y;
        ck->samples++;
    }
}

/* Ground states of all bodies; "at rest" = resolved speed below 0.2 m/s. */
typedef struct {
    int on_floor, steep, air, rest, rest_grounded, floor_far;
    uint64_t hash; /* FNV-1a of the owner positions (determinism) */
} ground_t;

static ground_t ground_report(void)
{
    ground_t g = {0};
    g.hash = 1469598103934665603ull;
    for (int i = 0; i < NCHARS; i++) {
        char_body_ground_state_t gs = char_body_ground_state(&g_body[i]);
        fm_vec3_t v = char_body_get_velocity(&g_body[i]);
        double sp = sqrt((double)v.x * v.x + (double)v.y * v.y + (double)v.z * v.z);
        g.on_floor += gs == CHAR_BODY_ON_FLOOR;
        g.steep += gs == CHAR_BODY_ON_STEEP;
        g.air += gs == CHAR_BODY_AIRBORNE;
        if (sp < REST_SPEED) {
            g.rest++;
            g.rest_grounded += gs == CHAR_BODY_ON_FLOOR;
        }
        if (gs != CHAR_BODY_AIRBORNE) {
            /* independent: geometry within the floor probe's reach of the full capsule */
            soak_capsule_t full, sweep;
            soak_body_capsules(&g_body[i], &full, &sweep);
            double snap = g_body[i].settings.floor_snap_distance + 0.01;
            if (cap_dist(&full, full.r + snap) - full.r > snap) g.floor_far++;
        }
        const unsigned char *p = (const unsigned char *)&g_owner[i];
        for (size_t k = 0; k < sizeof g_owner[i]; k++) g.hash = (g.hash ^ p[k]) * 1099511628211ull;
    }
    return g;
}

static void print_ground(const char *tag, const ground_t *g)
{
    printf("%s_on_floor=%d\n", tag, g->on_floor);
    printf("%s_steep=%d\n", tag, g->steep);
    printf("%s_airborne=%d\n", tag, g->air);
    printf("%s_at_rest=%d\n", tag, g->rest);
    printf("%s_at_rest_grounded=%d\n", tag, g->rest_grounded);
    printf("%s_grounded_no_floor_in_reach=%d\n", tag, g->floor_far);
    printf("%s_hash=%016llx\n", tag, (unsigned long long)g->hash);
}

/* ------------------------------------------------------------------ main */
int main(int argc, char **argv)
{
    if (argc < 2) {
        fprintf(stderr, "usage: %s STEPS [CELL [MAX_SLIDES]]   (CELL 0 or absent: automatic grid cell)\n", argv[0]);
        return 2;
    }
    uint32_t steps = (uint32_t)strtoul(argv[1], NULL, 10);
    float cell = argc > 2 ? strtof(argv[2], NULL) : 0.0f;
    int max_slides = argc > 3 ? atoi(argv[3]) : 0;

    build_geometry();
    coll_mesh_build_opts_t opts = {cell, 0};
    const coll_mesh_build_opts_t *op = cell > 0.0f ? &opts : NULL;
    size_t need = coll_mesh_build_size(g_nv, g_nt, op);
    if (need > sizeof g_pool) {
        fprintf(stderr, "mesh needs %zu bytes, pool has %zu\n", need, sizeof g_pool);
        return 1;
    }
    const coll_mesh_t *mesh = NULL;
    coll_err_t e = coll_mesh_build(g_pool, sizeof g_pool, g_verts, g_nv, g_idx, g_nt, op, &mesh);
    if (e != COLL_OK || !mesh) {
        fprintf(stderr, "coll_mesh_build failed (%d)\n", (int)e);
        return 1;
    }
    const char *gc_env = getenv("JOLT_GATHER_CACHE");
    const bool gather_cache = gc_env && gc_env[0] == '1';
    coll_scene_init(&g_scene);
    coll_scene_set_stats(&g_scene, &g_stats);
    g_inst = (coll_mesh_instance_t){.mesh = mesh, .xf = COLL_TRANSFORM_IDENTITY, .write_mask = 0x01, .id = 1};
    if (coll_scene_add_mesh(&g_scene, &g_inst) != COLL_OK) return 1;

    /* Jolt's standing shape: CapsuleShape(half cylinder 0.675, radius 0.3) raised by
     * 0.675 + 0.3 so the character position is the capsule's bottom. Ours: total height
     * incl. caps 1.35 + 2 * 0.3 = 1.95 m, centre 0.975 m above the owner origin (the foot). */
    char_body_settings_t s = CHAR_BODY_SETTINGS_DEFAULT;
    s.radius = CH_RADIUS;
    s.height = CH_HEIGHT_STANDING + 2.0f * CH_RADIUS;
    s.center_offset = (fm_vec3_t){{0.0f, 0.5f * CH_HEIGHT_STANDING + CH_RADIUS, 0.0f}};
    s.gravity = 9.81f;                          /* PhysicsSystem default gravity */
    s.floor_max_angle = 50.0f * 3.14159265f / 180.0f; /* CharacterBaseSettings::mMaxSlopeAngle */
    s.step_height = 0.4f;                       /* ExtendedUpdateSettings::mWalkStairsStepUp */
    s.floor_snap_distance = 0.5f;               /* ExtendedUpdateSettings::mStickToFloorStepDown */
    s.coll_types = COLL_TYPE_MESH;              /* character vs character off */
    if (max_slides > 0) s.max_slides = (uint8_t)max_slides;
    for (int y = 0; y < NCHAR_Y; y++)
        for (int x = 0; x < NCHAR_X; x++) {
            int i = y * NCHAR_X + x;
            g_owner[i] = (fm_vec3_t){{4.0f * (float)x - 20.0f, 2.0f, 4.0f * (float)y - 20.0f}};
            char_body_init(&g_body[i], &g_owner[i]);
            char_body_configure(&g_body[i], &s);
            if (gather_cache) char_body_set_gather_cache(&g_body[i], &g_cache[i]);
        }

    check_t ck = {0};
    ck.min_foot_y = 1e300;
    ck.min_clear_sweep = 1e300;
    ck.worst_body = -1;
    for (uint32_t st = 0; st < steps; st++) {
        jolt_step_all(g_body, g_owner, &g_scene, g_step, DT);
        g_step++;
        check_step(&ck, st);
    }

    ground_t end = ground_report();
    uint64_t air_samples = ck.airborne_samples, samples = ck.samples;
    uint64_t stepped = ck.stepped, hit_wall = ck.hit_wall, near_boxes = ck.near_boxes;
    coll_query_stats_t qs = g_stats; /* the measured steps only */

    /* settle (not measured): inputs stop; every body should come to rest on a floor */
    for (uint32_t st = 0; st < SETTLE_STEPS; st++) {
        for (int i = 0; i < NCHARS; i++) {
            g_body[i].input_velocity = (fm_vec3_t){{0.0f, 0.0f, 0.0f}};
            char_body_move_and_slide_in(&g_body[i], &g_scene, DT);
        }
        check_step(&ck, steps + st);
    }
    ground_t settled = ground_report();

    printf("steps=%u\n", steps);
    printf("bodies=%d\n", NCHARS);
    printf("updates=%llu\n", (unsigned long long)steps * NCHARS);
    printf("cell_request=%g\n", (double)cell);
    printf("cell=%.4g\n", (double)mesh->cell_size);
    printf("max_slides=%d\n", (int)g_body[0].settings.max_slides);
    printf("triangles=%u\n", coll_mesh_triangle_count(mesh));
    printf("mesh_bytes=%zu\n", coll_mesh_size(mesh));
    printf("overflows=%u\n", qs.dedup_overflows + qs.gather_overflows);
    printf("dedup_overflows=%u\ngathers=%u\ngather_overflows=%u\ngather_queries=%u\ngather_misses=%u\nscene_queries=%u\n",
           qs.dedup_overflows, qs.gathers, qs.gather_overflows, qs.gather_queries, qs.gather_misses, qs.queries);
    if (gather_cache) {
        uint64_t h = 0, fl = 0, ov = 0;
        for (int i = 0; i < NCHARS; i++) {
            h += g_cache[i].hits;
            fl += g_cache[i].fills;
            ov += g_cache[i].overflows;
        }
        printf("gather_cache_hits=%llu\ngather_cache_fills=%llu\ngather_cache_overflows=%llu\n",
               (unsigned long long)h, (unsigned long long)fl, (unsigned long long)ov);
    }
    printf("max_pen_sweep_mm=%.4f\n", ck.max_pen_sweep * 1e3);
    printf("min_clearance_sweep_mm=%.4f\n", ck.min_clear_sweep * 1e3);
    printf("worst=body %d step %u\n", ck.worst_body, ck.worst_step);
    printf("checked_steps=%u\n", steps + SETTLE_STEPS);
    printf("pen_samples_over_1mm=%llu\n", (unsigned long long)ck.pen_samples);
    printf("max_pen_full_terrain_mm=%.4f\n", ck.max_pen_full_terrain * 1e3);
    printf("max_pen_full_stairs_wall_mm=%.4f\n", ck.max_pen_full_box * 1e3);
    printf("samples=%llu\n", (unsigned long long)samples);
    printf("airborne_samples=%llu\n", (unsigned long long)air_samples);
    printf("stepped_samples=%llu\n", (unsigned long long)stepped);
    printf("hit_wall_samples=%llu\n", (unsigned long long)hit_wall);
    printf("near_stairs_wall_samples=%llu\n", (unsigned long long)near_boxes);
    printf("min_foot_y=%.4f\n", ck.min_foot_y);
    print_ground("end", &end);
    print_ground("settled", &settled);
    printf("settle_steps=%d\n", SETTLE_STEPS);
    return 0;
}
