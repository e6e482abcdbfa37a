/**
 * @file bench_scn.h
 * @brief Benchmark / stability support shared by host_tests/test_stability.c and bench/:
 *        procedural level geometry, a double-precision reference (capsule-triangle
 *        distance and sweep) and the stability scenarios.
 *
 * Every non-static symbol is prefixed bench_ (this file is linked into every test binary).
 * The scenarios run on whatever capsule-triangle sweep method is installed with
 * coll_set_tri_sweep_method(), so the benchmark runs them for every method.
 */
#ifndef BENCH_SCN_H
#define BENCH_SCN_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include "fm_math.h"
#include "coll/mesh.h"
#include "coll/scene.h"
#include "coll/char_body.h"
#include "prim.h"

/* ------------------------------------------------------------------ geometry */

/** Triangle soup under construction; caller-owned arrays. */
typedef struct {
    float *v;          ///< xyz per vertex
    uint32_t *idx;     ///< 3 per triangle
    uint32_t nv, nt;
    uint32_t cap_v, cap_t;
    bool overflow;     ///< set when an add did not fit
} bench_geo_t;

void bench_geo_init(bench_geo_t *g, float *v, uint32_t cap_v, uint32_t *idx, uint32_t cap_t);
uint32_t bench_geo_vert(bench_geo_t *g, double x, double y, double z);
void bench_geo_tri(bench_geo_t *g, uint32_t a, uint32_t b, uint32_t c);
/** Quad a,b,c,d (in order around it) as two triangles. */
void bench_geo_quad(bench_geo_t *g, fm_vec3_t a, fm_vec3_t b, fm_vec3_t c, fm_vec3_t d);
/** Axis-aligned box, 12 triangles. */
void bench_geo_box(bench_geo_t *g, fm_vec3_t mn, fm_vec3_t mx);
/** Horizontal floor at height y over [x0,x1]x[z0,z1], n x m cells, alternating diagonals. */
void bench_geo_grid(bench_geo_t *g, double x0, double z0, double x1, double z1, double y,
                    uint32_t n, uint32_t m);
/** Vertical wall quad from (x0,z0) to (x1,z1) between heights y0..y1. */
void bench_geo_wall(bench_geo_t *g, double x0, double z0, double x1, double z1, double y0, double y1);
/** Adds (dx,dy,dz) to every vertex. */
void bench_geo_offset(bench_geo_t *g, double dx, double dy, double dz);

/* ------------------------------------------------- double-precision reference */

typedef struct { double x, y, z; } bench_d3_t;

/** Distance between segment p0-p1 and triangle t; closest points to *ps, *pt (may be NULL). */
double bench_ref_seg_tri_dist(bench_d3_t p0, bench_d3_t p1, const bench_d3_t t[3],
                              bench_d3_t *ps, bench_d3_t *pt);

/**
 * Reference capsule-triangle sweep in double precision (conservative advancement on the
 * exact distance to 1e-7 m), with the coll_tri_sweep_fn signature. ctx is unused.
 */
bool bench_ref_tri_sweep(void *ctx, const fm_vec3_t seg[2], float r, const fm_vec3_t *disp,
                         const fm_vec3_t tri[3], float t_max, coll_prim_hit_t *hit);

/** A mesh instance's world-space triangles for the reference (geo in mesh-local space). */
typedef struct {
    const bench_geo_t *geo;
    const coll_transform_t *xf;   ///< NULL = identity
} bench_ref_part_t;

/**
 * Penetration (>= 0, meters) of the capsule seg p0-p1, radius r, into the triangles of the
 * parts, in double precision: max over triangles of r - distance.
 */
double bench_ref_penetration(const bench_ref_part_t *parts, int nparts, bench_d3_t p0, bench_d3_t p1,
                             double r);

/** Earliest reference time of impact of a capsule sweep against all parts; -1 when none. */
double bench_ref_sweep_t(const bench_ref_part_t *parts, int nparts, bench_d3_t c, bench_d3_t axis,
                         double r, double hh, bench_d3_t disp);

/* --------------------------------------------------------------- levels */

/** A one-mesh level with its scene. */
typedef struct {
    bench_geo_t geo;
    const coll_mesh_t *mesh;
    coll_mesh_instance_t inst;
    coll_scene_t scene;
    bench_ref_part_t part;
} bench_level_t;

/** Builds geo into buf (8-byte aligned) and a scene holding it. false on failure. */
bool bench_level_build(bench_level_t *lv, void *buf, size_t buf_size, float cell_size, uint32_t flags);

/** Sweep-capsule segment of a body (the capsule the body collides with), double. */
void bench_body_sweep_capsule(const char_body_t *b, bench_d3_t *p0, bench_d3_t *p1, double *r);

/* --------------------------------------------------------------- scenarios */

/** Outcome of one stability scenario. */
typedef struct {
    const char *name;   ///< short id, e.g. "vcorner_60"
    const char *what;   ///< what is measured
    bool pass;
    double err;         ///< the measured error (unit in .unit)
    double limit;       ///< pass threshold on err
    const char *unit;
    double pen;         ///< max penetration seen, meters
    char note[96];      ///< why it failed (empty when it passed)
} bench_result_t;

/** Number of scenarios in the full suite. */
int bench_scn_count(void);
/** Runs scenario i with the currently installed sweep method. reduced: reserved for a
 *  shorter variant (the full suite already runs in ~0.3 s natively, ~7 s under qemu, so both
 *  variants are the same today). buf: 8-byte aligned scratch of BENCH_SCN_BUF bytes. */
bench_result_t bench_scn_run(int i, bool reduced, void *buf, size_t buf_size);
#define BENCH_SCN_BUF (4u << 20)

#endif
