/*
 * bench_run: the benchmark driver. One process per measurement, so callgrind (host) and
 * the qemu exec trace (big-endian MIPS) each count exactly one configuration.
 *
 *   bench_run cost METHOD SCENARIO [ASSETDIR [CELL]]  measured char body steps (bench_step /
 *                                              bench_frame); CELL > 0 rebuilds the level's grid
 *   bench_run accuracy METHOD [ASSETDIR]       errors against the double-precision reference (CSV row)
 *   bench_run stability METHOD...              the stability suite for each method (CSV rows)
 *   bench_run scaling NTRIS CELL               procedural terrain: moves + rays (+ blob sizes)
 *   bench_run sizes                            sizeof of the runtime structs
 *
 * METHOD: exact | ref | ccd-gjk:ITERS:TOL | ccd-mpr:ITERS:TOL | disc:N
 * SCENARIO: walk | stairs | vcorner | platform | crowd32 | crowd32_col | stairs_real | crack | course | empty
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bench_hooks.h"
#include "bench_methods.h"
#include "bench_scn.h"
#include "coll/mesh.h"
#include "mesh_format.h"   /* the effective grid cell (builders may coarsen a request) */

/* Callgrind runs with --instr-atstart=no: instrumentation starts just before the measured
 * part, so building a 1M-triangle level is not simulated at callgrind's full cost. */
#if defined(__has_include)
#if __has_include(<valgrind/callgrind.h>)
#include <valgrind/callgrind.h>
#define BENCH_CG_START() CALLGRIND_START_INSTRUMENTATION
#endif
#endif
#ifndef BENCH_CG_START
#define BENCH_CG_START() ((void)0)
#endif

#define DT (1.0f / 30.0f)

static fm_vec3_t V(double x, double y, double z)
{
    fm_vec3_t r = {{(float)x, (float)y, (float)z}};
    return r;
}

/* ------------------------------------------------------------------ levels */

typedef struct {
    coll_scene_t scene;
    coll_mesh_instance_t inst[2];
    bench_geo_t geo[2];
    bench_ref_part_t part[2];
    int nparts;
    bool real;          /* the baked sample level, not the procedural fallback */
} world_t;

static void *xaligned(size_t n)
{
    void *p = NULL;
    if (posix_memalign(&p, 64, n ? n : 8) != 0) { fprintf(stderr, "out of memory\n"); exit(2); }
    return p;
}

static bool load_blob(const char *path, const coll_mesh_t **out)
{
    FILE *f = fopen(path, "rb");
    if (!f) return false;
    fseek(f, 0, SEEK_END);
    long n = ftell(f);
    fseek(f, 0, SEEK_SET);
    void *buf = xaligned((size_t)n);
    bool ok = n > 0 && fread(buf, 1, (size_t)n, f) == (size_t)n;
    fclose(f);
    return ok && coll_mesh_load(buf, (size_t)n, out) == COLL_OK;
}

/* The mesh's triangles as a soup, for the reference. */
static void geo_of_mesh(bench_geo_t *g, const coll_mesh_t *m)
{
    uint32_t nt = coll_mesh_triangle_count(m);
    bench_geo_init(g, xaligned(nt * 36u), nt * 3u, xaligned(nt * 12u), nt);
    for (uint32_t i = 0; i < nt; i++) {
        fm_vec3_t t[3];
        coll_mesh_triangle(m, i, t);
        uint32_t a = bench_geo_vert(g, t[0].x, t[0].y, t[0].z), b = bench_geo_vert(g, t[1].x, t[1].y, t[1].z);
        uint32_t c = bench_geo_vert(g, t[2].x, t[2].y, t[2].z);
        bench_geo_tri(g, a, b, c);
    }
}

static bool g_need_geo = true;   /* the reference needs the triangles; cost runs do not */

static void add_part(world_t *w, const coll_mesh_t *m, fm_vec3_t pos, uint16_t id)
{
    int k = w->nparts++;
    coll_transform_t idt = COLL_TRANSFORM_IDENTITY;
    w->inst[k].mesh = m;
    w->inst[k].xf = idt;
    w->inst[k].xf.pos = pos;
    w->inst[k].write_mask = 0x01;
    w->inst[k].id = id;
    if (coll_scene_add_mesh(&w->scene, &w->inst[k]) != COLL_OK) { fprintf(stderr, "scene add failed\n"); exit(2); }
    if (g_need_geo) geo_of_mesh(&w->geo[k], m);
    w->part[k].geo = &w->geo[k];
    w->part[k].xf = &w->inst[k].xf;
}

/* Procedural stand-in for the sample course when build/assets is missing: floor, the 0.2 m
 * stairs, a blocker, a 60 degree V-corner; coordinates as in assets/levels/README.md. */
static const coll_mesh_t *procedural_course(void)
{
    static bench_level_t lv;
    bench_geo_init(&lv.geo, xaligned(20000 * 12), 20000, xaligned(20000 * 12), 20000);
    bench_geo_grid(&lv.geo, -40, -40, 40, 40, 0, 20, 20);
    for (int k = 0; k < 4; k++)
        bench_geo_box(&lv.geo, V(-14 + 0.5 * k, 0, -32), V(-8.5 - 0.5 * k, 0.2 * (k + 1), -28));
    bench_geo_box(&lv.geo, V(8, 0, -32), V(10, 0.35, -28));
    double h = 30.0 * 3.14159265358979 / 180.0;
    bench_geo_wall(&lv.geo, 12, 38, 12 + 6 * sin(h), 38 - 6 * cos(h), -0.5, 3);
    bench_geo_wall(&lv.geo, 12, 38, 12 - 6 * sin(h), 38 - 6 * cos(h), -0.5, 3);
    size_t n = coll_mesh_build_size(lv.geo.nv, lv.geo.nt, NULL);
    const coll_mesh_t *m;
    if (coll_mesh_build(xaligned(n), n, lv.geo.v, lv.geo.nv, lv.geo.idx, lv.geo.nt, NULL, &m) != COLL_OK) {
        fprintf(stderr, "procedural course build failed\n");
        exit(2);
    }
    return m;
}

static const coll_mesh_t *procedural_turntable(void)
{
    static bench_level_t lv;
    bench_geo_init(&lv.geo, xaligned(200 * 12), 200, xaligned(200 * 12), 200);
    uint32_t c = bench_geo_vert(&lv.geo, 0, 0, 0), prev = 0;
    for (int k = 0; k <= 24; k++) {
        double a = 2 * 3.14159265358979 * k / 24;
        uint32_t q = bench_geo_vert(&lv.geo, 3 * cos(a), 0, 3 * sin(a));
        if (k > 0) bench_geo_tri(&lv.geo, c, q, prev);
        prev = q;
    }
    size_t n = coll_mesh_build_size(lv.geo.nv, lv.geo.nt, NULL);
    const coll_mesh_t *m;
    if (coll_mesh_build(xaligned(n), n, lv.geo.v, lv.geo.nv, lv.geo.idx, lv.geo.nt, NULL, &m) != COLL_OK) exit(2);
    return m;
}

/* Real-geometry scenes of the character body (the real-geometry issue): ten steps of tread
 * 0.28 m / riser 0.18 m rising along +x from x = 0 (the default capsule cannot climb them
 * with the seed's shortened capsule alone), and two floor slabs with a 0.4 m crack along x
 * at z = 0 (narrower than the capsule: the body walks along it held by its edges). */
static const coll_mesh_t *procedural_real(bool crack)
{
    static bench_level_t lv[2];
    bench_level_t *l = &lv[crack ? 1 : 0];
    bench_geo_init(&l->geo, xaligned(4000 * 12), 4000, xaligned(4000 * 12), 4000);
    if (crack) {
        bench_geo_box(&l->geo, V(-20, -1, -20), V(20, 0, -0.2));
        bench_geo_box(&l->geo, V(-20, -1, 0.2), V(20, 0, 20));
    } else {
        /* the staircase as a level mesh has it: one strip of treads and risers, z -5 .. 5 */
        double xs[24], ys[24];
        int np = 0;
        xs[np] = -20; ys[np++] = 0;
        for (int k = 0; k < 10; k++) {
            xs[np] = 0.28 * k; ys[np++] = 0.18 * k;
            xs[np] = 0.28 * k; ys[np++] = 0.18 * (k + 1);
        }
        xs[np] = 20; ys[np++] = 1.8;
        for (int i = 0; i + 1 < np; i++) {
            uint32_t a = bench_geo_vert(&l->geo, xs[i], ys[i], -5), b = bench_geo_vert(&l->geo, xs[i], ys[i], 5);
            uint32_t c = bench_geo_vert(&l->geo, xs[i + 1], ys[i + 1], 5), d = bench_geo_vert(&l->geo, xs[i + 1], ys[i + 1], -5);
            bench_geo_tri(&l->geo, a, b, c);
            bench_geo_tri(&l->geo, a, c, d);
        }
    }
    size_t n = coll_mesh_build_size(l->geo.nv, l->geo.nt, NULL);
    const coll_mesh_t *m;
    if (coll_mesh_build(xaligned(n), n, l->geo.v, l->geo.nv, l->geo.idx, l->geo.nt, NULL, &m) != COLL_OK) exit(2);
    return m;
}

static float g_cell = 0.0f;   /* > 0: rebuild the level with this grid cell (cost runs) */
static float g_cell_eff = 0.0f; /* the level's grid cell as built */

static const coll_mesh_t *rebuild(const coll_mesh_t *m, float cell)
{
    bench_geo_t g;
    geo_of_mesh(&g, m);
    coll_mesh_build_opts_t o = {cell, 0};
    size_t n = coll_mesh_build_size(g.nv, g.nt, &o);
    const coll_mesh_t *out;
    if (coll_mesh_build(xaligned(n), n, g.v, g.nv, g.idx, g.nt, &o, &out) != COLL_OK) {
        fprintf(stderr, "rebuild with cell %g failed\n", cell);
        exit(2);
    }
    return out;
}

/* What the measured queries did (fallbacks, overflows): printed by the cost command. */
static coll_query_stats_t g_stats;

static void world_init(world_t *w, const char *assets, bool platform)
{
    memset(w, 0, sizeof(*w));
    coll_scene_init(&w->scene);
    char path[512];
    const coll_mesh_t *m = NULL;
    snprintf(path, sizeof(path), "%s/test_course.coll", assets ? assets : "build/assets");
    w->real = load_blob(path, &m);
    if (!w->real) m = procedural_course();
    if (g_cell > 0.0f) m = rebuild(m, g_cell);
    add_part(w, m, V(0, 0, 0), 1);
    g_cell_eff = m->cell_size;
    if (platform) {
        const coll_mesh_t *p = NULL;
        snprintf(path, sizeof(path), "%s/platform_rotate.coll", assets ? assets : "build/assets");
        if (!load_blob(path, &p)) p = procedural_turntable();
        add_part(w, p, V(0, 0.2, 8), 2);
    }
}

/* BENCH_GATHER_CACHE=1 in the environment: every body made here gets a gather cache of its
 * own (char_body_set_gather_cache; the bench's bodies are made in array order, at most 32). */
static coll_gather_cache_t g_gather_caches[32];
static int g_gather_cache_next;
static bool gather_cache_on(void)
{
    const char *e = getenv("BENCH_GATHER_CACHE");
    return e && e[0] == '1';
}

static void body_make(char_body_t *b, fm_vec3_t *pos, fm_vec3_t foot)
{
    *pos = foot;
    char_body_init(b, pos);
    if (gather_cache_on() && g_gather_cache_next < 32)
        char_body_set_gather_cache(b, &g_gather_caches[g_gather_cache_next++]);
    char_body_settings_t s = CHAR_BODY_SETTINGS_DEFAULT;
    s.center_offset = V(0, 1, 0);
    char_body_configure(b, &s);
    char_body_teleport(b, foot, true);
}

/* ------------------------------------------------------------- scenarios */

/* Input of the scripted course at time t (leg A of the test course: three staircases,
 * into the blocker, a slide along it, back out). */
static fm_vec3_t course_input(float t)
{
    if (t < 9.5f) return V(4, 0, 0);
    if (t < 11.0f) return V(2, 0, 4);
    return V(-3, 0, -1);
}
#define COURSE_FRAMES 360

typedef struct {
    double max_pen;
    fm_vec3_t final;
    int calls;
} run_out_t;

/* Runs a scenario; every measured step goes through bench_step / bench_frame. */
static run_out_t run_scenario(const char *scn, const char *assets, bool measure_pen)
{
    static world_t w;
    static char_body_t bodies[32];
    static fm_vec3_t pos[32];
    run_out_t o = {0, {{0, 0, 0}}, 0};
    bool plat = strcmp(scn, "platform") == 0;
    bool real_stairs = strcmp(scn, "stairs_real") == 0, crack = strcmp(scn, "crack") == 0;
    if (real_stairs || crack) {
        memset(&w, 0, sizeof(w));
        coll_scene_init(&w.scene);
        add_part(&w, procedural_real(crack), V(0, 0, 0), 1);
    } else {
        world_init(&w, assets, plat);
    }
    coll_scene_set_stats(&w.scene, &g_stats);
    int frames = 90, nb = 1;
    fm_vec3_t in = V(0, 0, 0);
    if (strcmp(scn, "walk") == 0) { body_make(&bodies[0], &pos[0], V(-28, 0, -26)); in = V(5, 0, 0); frames = 30; }
    else if (strcmp(scn, "stairs") == 0) { body_make(&bodies[0], &pos[0], V(-15, 0, -30)); in = V(4, 0, 0); frames = 45; }
    else if (strcmp(scn, "vcorner") == 0) { body_make(&bodies[0], &pos[0], V(12, 0, 30)); in = V(0, 0, 5); frames = 60; }
    else if (plat) {
        body_make(&bodies[0], &pos[0], V(-1.5, 0.2, 8)); frames = 30;
        char_body_move_and_slide_in(&bodies[0], &w.scene, DT);   /* stand on it first (not measured) */
    }
    else if (strcmp(scn, "course") == 0) { body_make(&bodies[0], &pos[0], V(-28, 0, -30)); frames = COURSE_FRAMES; }
    else if (real_stairs) { body_make(&bodies[0], &pos[0], V(-1, 0, 0)); in = V(3, 0, 0); frames = 60; }
    else if (crack) { body_make(&bodies[0], &pos[0], V(-5, 0, 0)); in = V(3, 0, 0); frames = 60; }
    else if (strcmp(scn, "crowd32_col") == 0) {
        /* 32 bodies that block each other: each owns a capsule collider in the scene */
        static coll_body_t col[32];
        nb = 32; frames = 2;
        for (int i = 0; i < nb; i++) {
            body_make(&bodies[i], &pos[i], V(-20 + 1.2 * (i % 8), 0, -20 + 1.2 * (i / 8)));
            char_body_settings_t st = *char_body_get_settings(&bodies[i]);
            st.coll_types = COLL_TYPE_ALL;
            char_body_configure(&bodies[i], &st);
            col[i] = (coll_body_t){0};
            col[i].write_mask = 0x01;
            col[i].id = (uint16_t)(100 + i);
            char_body_set_collider(&bodies[i], &col[i]);
            if (coll_scene_add_body(&w.scene, &col[i]) != COLL_OK) exit(2);
            double a = i * 2.39996;
            bodies[i].input_velocity = V(4 * cos(a), 0, 4 * sin(a));
        }
        for (int i = 0; i < nb; i++) char_body_move_and_slide_in(&bodies[i], &w.scene, DT);
    }
    else if (strcmp(scn, "crowd32") == 0) {
        nb = 32; frames = 2;
        for (int i = 0; i < nb; i++) {
            body_make(&bodies[i], &pos[i], V(-20 + 2.5 * (i % 8), 0, -20 + 3.0 * (i / 8)));
            double a = i * 2.39996;   /* golden angle: a spread of directions */
            bodies[i].input_velocity = V(4 * cos(a), 0, 4 * sin(a));
        }
        for (int f = 0; f < 1; f++)   /* settle onto the floor first (not measured) */
            for (int i = 0; i < nb; i++) char_body_move_and_slide_in(&bodies[i], &w.scene, DT);
    } else if (strcmp(scn, "empty") == 0) {
        BENCH_CG_START();
        for (int i = 0; i < 100; i++) bench_empty();
        o.calls = 100;
        return o;
    } else { fprintf(stderr, "unknown scenario %s\n", scn); exit(2); }

    fm_vec3_t axis = V(0, 1, 0);
    BENCH_CG_START();
    for (int f = 0; f < frames; f++) {
        if (plat) fm_quat_from_axis_angle(&w.inst[1].xf.rot, &axis, 2.0f * 3.14159265f * (float)(f + 1) * DT);
        if (nb > 1) {
            bench_frame(bodies, nb, &w.scene, DT);
            o.calls += nb;
            continue;
        }
        bodies[0].input_velocity = strcmp(scn, "course") == 0 ? course_input((float)f * DT) : in;
        bench_step(&bodies[0], &w.scene, DT);
        o.calls++;
        if (measure_pen) {
            bench_d3_t p0, p1;
            double r;
            bench_body_sweep_capsule(&bodies[0], &p0, &p1, &r);
            double p = bench_ref_penetration(w.part, w.nparts, p0, p1, r);
            if (p > o.max_pen) o.max_pen = p;
        }
    }
    o.final = pos[0];
    return o;
}

/* --------------------------------------------------------------- accuracy */

static uint32_t g_rng = 12345u;
static double frand(void)
{
    g_rng = g_rng * 1664525u + 1013904223u;
    return (g_rng >> 8) * (1.0 / 16777216.0);
}

static int cmd_accuracy(const char *method, const char *assets)
{
    /* reference trajectory first */
    if (!bench_method_install("ref")) return 2;
    run_out_t ref = run_scenario("course", assets, false);
    if (!bench_method_install(method)) { fprintf(stderr, "unknown method %s\n", method); return 2; }
    run_out_t m = run_scenario("course", assets, true);
    double fe = fm_vec3_distance(&ref.final, &m.final);

    /* time of impact: random sweeps of the default sweep capsule over the course */
    static world_t w;
    world_init(&w, assets, false);
    const int N = 1500;
    double toi_max = 0, toi_sum = 0;
    int misses = 0, extra = 0, n = 0;
    g_rng = 777u;
    for (int i = 0; i < N; i++) {
        bench_d3_t c = {-38 + 76 * frand(), 0.55 + 2.5 * frand(), -38 + 76 * frand()};
        double len = 0.1 + 3.0 * frand(), az = 6.2831853 * frand(), el = (frand() - 0.5) * 1.2;
        bench_d3_t d = {len * cos(el) * cos(az), len * sin(el), len * cos(el) * sin(az)};
        bench_d3_t ax = {0, 1, 0};
        const double r = 0.5, hh = 0.375;
        fm_vec3_t cf = V(c.x, c.y, c.z), df = V(d.x, d.y, d.z);
        c.x = cf.x; c.y = cf.y; c.z = cf.z; d.x = df.x; d.y = df.y; d.z = df.z; /* same float inputs */
        bench_d3_t p0 = {c.x, c.y - hh, c.z}, p1 = {c.x, c.y + hh, c.z};
        if (bench_ref_penetration(w.part, w.nparts, p0, p1, r) > 0) continue; /* starts inside */
        double tr = bench_ref_sweep_t(w.part, w.nparts, c, ax, r, hh, d);
        coll_sweep_hit_t h;
        bool hm = coll_capsule_sweep(&w.scene, cf, V(0, 1, 0), (float)r, (float)hh, df, 0x01, COLL_TYPE_MESH, &h);
        double e = 0;
        if (tr >= 0 && hm) e = fabs(h.t - tr) * len;
        else if (tr >= 0) { e = (1 - tr) * len; misses++; }
        else if (hm) { e = (1 - h.t) * len; extra++; }
        n++;
        toi_sum += e;
        if (e > toi_max) toi_max = e;
    }
    printf("method,max_pen_m,toi_err_max_m,toi_err_mean_m,toi_missed,toi_false,sweeps,final_err_m,real_level\n");
    printf("%s,%.9g,%.9g,%.9g,%d,%d,%d,%.9g,%d\n", method, m.max_pen, toi_max, n ? toi_sum / n : 0, misses, extra,
           n, fe, w.real ? 1 : 0);
    return 0;
}

/* --------------------------------------------------------------- stability */

static int cmd_stability(int argc, char **argv)
{
    void *buf = xaligned(BENCH_SCN_BUF);
    printf("scenario,method,pass,err,limit,unit,max_pen_m,note\n");
    for (int a = 0; a < argc; a++) {
        if (!bench_method_install(argv[a])) { fprintf(stderr, "unknown method %s\n", argv[a]); return 2; }
        for (int i = 0; i < bench_scn_count(); i++) {
            bench_result_t r = bench_scn_run(i, false, buf, BENCH_SCN_BUF);
            printf("%s,%s,%d,%.6g,%.6g,%s,%.6g,%s\n", r.name, argv[a], r.pass ? 1 : 0, r.err, r.limit, r.unit,
                   r.pen, r.note);
            fflush(stdout);
        }
    }
    coll_set_tri_sweep_method(NULL, NULL);
    return 0;
}

/* ----------------------------------------------------------------- scaling */

/* Bumpy terrain (80 % of the triangles) and boxes (20 %). */
static void gen_terrain(bench_geo_t *g, uint32_t ntris)
{
    uint32_t nterr = ntris * 4 / 5, n = (uint32_t)sqrt(nterr / 2.0);
    if (n < 2) n = 2;
    bench_geo_init(g, xaligned((size_t)(n + 1) * (n + 1) * 12 + (size_t)ntris * 12), (n + 1) * (n + 1) + ntris,
                   xaligned((size_t)ntris * 12 + 4096), ntris + 300);
    for (uint32_t j = 0; j <= n; j++)
        for (uint32_t i = 0; i <= n; i++)
            bench_geo_vert(g, i, 0.3 * sin(i * 0.7) * cos(j * 0.53) + 0.1 * sin(i * 2.1 + j * 1.7), j);
    for (uint32_t j = 0; j < n; j++)
        for (uint32_t i = 0; i < n; i++) {
            uint32_t a = j * (n + 1) + i, b = a + 1, c = a + n + 1, d = c + 1;
            bench_geo_tri(g, a, b, c);
            bench_geo_tri(g, b, d, c);
        }
    /* Boxes by 8 m tile, each tile's from its own seed: every level has the same boxes in
     * the same places wherever it has that tile, so bodies and rays in the common corner
     * (SCALE_REGION) meet the same geometry at every level size and the cost compares
     * level sizes alone. 2.67 boxes a tile: a fifth of the triangles. */
    uint32_t tiles = (n - 3) / 8u;
    for (uint32_t tz = 0; tz < tiles; tz++)
        for (uint32_t tx = 0; tx < tiles; tx++) {
            g_rng = (tx * 73856093u) ^ (tz * 19349663u) ^ 99u;
            int nb = frand() < 2.0 / 3.0 ? 3 : 2;
            for (int k = 0; k < nb && g->nt + 12 <= ntris; k++) {
                double x = 8.0 * tx + frand() * 8.0, z = 8.0 * tz + frand() * 8.0, s = 0.3 + 2.0 * frand();
                bench_geo_box(g, V(x, -0.5, z), V(x + s, 0.2 + 1.5 * frand(), z + s));
            }
        }
}

/* Side of the corner of a scaling level where its bodies walk and its rays go (the same
 * geometry at every level size, see gen_terrain): the 10k-triangle level's tiles. */
#define SCALE_REGION 56.0

static int cmd_scaling(uint32_t ntris, float cell)
{
    bench_geo_t g;
    gen_terrain(&g, ntris);
    coll_mesh_build_opts_t of = {cell, 0}, oq = {cell, COLL_MESH_QUANTIZE};
    size_t nf = coll_mesh_build_size(g.nv, g.nt, &of), nq = coll_mesh_build_size(g.nv, g.nt, &oq);
    const coll_mesh_t *mf, *mq;
    if (coll_mesh_build(xaligned(nf), nf, g.v, g.nv, g.idx, g.nt, &of, &mf) != COLL_OK ||
        coll_mesh_build(xaligned(nq), nq, g.v, g.nv, g.idx, g.nt, &oq, &mq) != COLL_OK) {
        fprintf(stderr, "build failed (%u tris)\n", g.nt);
        return 2;
    }
    static coll_scene_t sc;
    static coll_mesh_instance_t inst;
    coll_transform_t idt = COLL_TRANSFORM_IDENTITY;
    coll_scene_init(&sc);
    static coll_query_stats_t st;
    coll_scene_set_stats(&sc, &st);
    inst.mesh = mf; inst.xf = idt; inst.write_mask = 1; inst.id = 1;
    coll_scene_add_mesh(&sc, &inst);
    fm_vec3_t bmin, bmax;
    coll_mesh_bounds(mf, &bmin, &bmax);
    double side = bmax.x - bmin.x;
    if (side > SCALE_REGION) side = SCALE_REGION;

    /* 16 bodies walking 30 frames, spread over the common corner */
    static char_body_t b[16];
    static fm_vec3_t pos[16];
    g_rng = 5u;
    for (int i = 0; i < 16; i++) {
        body_make(&b[i], &pos[i], V(2 + frand() * (side - 4), 0.5, 2 + frand() * (side - 4)));
        double a = frand() * 6.2831853;
        b[i].input_velocity = V(4 * cos(a), 0, 4 * sin(a));
        for (int f = 0; f < 3; f++) char_body_move_and_slide_in(&b[i], &sc, DT);
    }
    int moves = 0, rays = 0, rayhits = 0;
    BENCH_CG_START();
    for (int f = 0; f < 30; f++)
        for (int i = 0; i < 16; i++) { bench_step(&b[i], &sc, DT); moves++; }
    for (int i = 0; i < 1000; i++) {
        fm_vec3_t o = V(frand() * side, 3.0, frand() * side), d;
        if (i & 1) d = V(0, -1, 0);
        else { double a = frand() * 6.2831853; d = V(cos(a) * 0.98, -0.2, sin(a) * 0.98); fm_vec3_norm(&d, &d); }
        coll_ray_hit_t h;
        rayhits += bench_ray(&sc, o, d, 20.0f, &h);
        rays++;
    }
    printf("ntris,cell,moves,rays,rayhits,bytes_float,bytes_quant,bytes_per_tri_float,bytes_per_tri_quant,overflows,cell_eff\n");
    printf("%u,%g,%d,%d,%d,%zu,%zu,%.2f,%.2f,%u,%.4g\n", coll_mesh_triangle_count(mf), cell, moves, rays, rayhits,
           coll_mesh_size(mf), coll_mesh_size(mq), (double)coll_mesh_size(mf) / coll_mesh_triangle_count(mf),
           (double)coll_mesh_size(mq) / coll_mesh_triangle_count(mq), st.dedup_overflows + st.gather_overflows, mf->cell_size);
    return 0;
}

int main(int argc, char **argv)
{
    if (argc < 2) { fprintf(stderr, "usage: see bench/bench_main.c\n"); return 2; }
    if (strcmp(argv[1], "cost") == 0 && argc >= 4) {
        if (!bench_method_install(argv[2])) { fprintf(stderr, "unknown method %s\n", argv[2]); return 2; }
        if (argc > 5) g_cell = strtof(argv[5], NULL);
        g_need_geo = false;
        run_out_t o = run_scenario(argv[3], argc > 4 ? argv[4] : NULL, false);
        printf("calls=%d final=%.6f,%.6f,%.6f cell=%.4g\n", o.calls, o.final.x, o.final.y, o.final.z, g_cell_eff);
        printf("stats queries=%u gathers=%u gather_overflows=%u gather_queries=%u gather_misses=%u dedup_overflows=%u\n",
               g_stats.queries, g_stats.gathers, g_stats.gather_overflows, g_stats.gather_queries, g_stats.gather_misses,
               g_stats.dedup_overflows);
        if (g_gather_cache_next > 0) {
            uint32_t h = 0, fl = 0, ov = 0;
            for (int i = 0; i < g_gather_cache_next; i++) {
                h += g_gather_caches[i].hits;
                fl += g_gather_caches[i].fills;
                ov += g_gather_caches[i].overflows;
            }
            printf("gather_cache bodies=%d hits=%u fills=%u overflows=%u\n", g_gather_cache_next, h, fl, ov);
        }
        return 0;
    }
    if (strcmp(argv[1], "accuracy") == 0 && argc >= 3) return cmd_accuracy(argv[2], argc > 3 ? argv[3] : NULL);
    if (strcmp(argv[1], "stability") == 0) return cmd_stability(argc - 2, argv + 2);
    if (strcmp(argv[1], "scaling") == 0 && argc >= 4) return cmd_scaling((uint32_t)atol(argv[2]), strtof(argv[3], NULL));
    if (strcmp(argv[1], "sizes") == 0) {
        printf("struct,bytes\nchar_body_t,%zu\ncoll_scene_t,%zu\ncoll_mesh_instance_t,%zu\ncoll_body_t,%zu\n",
               sizeof(char_body_t), sizeof(coll_scene_t), sizeof(coll_mesh_instance_t), sizeof(coll_body_t));
        return 0;
    }
    fprintf(stderr, "bad arguments\n");
    return 2;
}
