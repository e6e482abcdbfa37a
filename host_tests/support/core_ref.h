/**
 * @file core_ref.h
 * @brief Double-precision brute-force references for the scene-query suite: every
 *        triangle of every instance and every body, no grid, no float shortcuts.
 */
#ifndef CORE_REF_H
#define CORE_REF_H
#include <stdbool.h>
#include <stdint.h>
#include "coll/scene.h"

typedef struct { double x, y, z; } core_d3;

core_d3 core_d3_of(fm_vec3_t v);
core_d3 core_d3_add(core_d3 a, core_d3 b);
core_d3 core_d3_sub(core_d3 a, core_d3 b);
core_d3 core_d3_scale(core_d3 a, double s);
double core_d3_dot(core_d3 a, core_d3 b);
core_d3 core_d3_cross(core_d3 a, core_d3 b);
double core_d3_len(core_d3 a);

/** World position of a mesh-local point under xf (scale, rotate, translate), in double. */
core_d3 core_xf_point(const coll_transform_t *xf, core_d3 p);
/** Rotates a vector by xf's (normalised) rotation. */
core_d3 core_xf_rotate(const coll_transform_t *xf, core_d3 v);
/** Inverse rotation. */
core_d3 core_xf_unrotate(const coll_transform_t *xf, core_d3 v);

/** World-space vertices of triangle t of a mesh instance. */
void core_world_tri(const coll_mesh_instance_t *inst, uint32_t t, core_d3 out[3]);

/**
 * Two-sided ray vs triangle. Returns true with *s and *min_bary (the smallest barycentric
 * coordinate: near 0 means the ray grazes an edge) when the line hits within [0, s_max]
 * with every barycentric >= -slack.
 */
bool core_ray_tri(core_d3 o, core_d3 d, const core_d3 tri[3], double s_max, double slack, double *s,
                  double *min_bary, core_d3 *n);

/** Ray vs body; origin must be outside. */
bool core_ray_body(core_d3 o, core_d3 d, const coll_body_t *b, double s_max, double *s, core_d3 *n);

/** Distance between segments, with closest points. */
double core_seg_seg(core_d3 p0, core_d3 p1, core_d3 q0, core_d3 q1, core_d3 *cp, core_d3 *cq);
/** Distance segment - triangle, with closest points (on segment, on triangle). */
double core_seg_tri(core_d3 p0, core_d3 p1, const core_d3 tri[3], core_d3 *cp, core_d3 *ct);
/** Distance segment - sphere/capsule body surface core (segment or point), negative never. */
double core_seg_body_core(core_d3 p0, core_d3 p1, const coll_body_t *b, double *body_r, core_d3 *cp,
                          core_d3 *cb);

/** Convex 1-D analysis of f(t) = dist(t) - r on [0,1] for a moving capsule. */
typedef struct {
    double f0;     ///< f(0) (negative: initial overlap of depth -f0)
    double fmin;   ///< min over [0,1]
    double t_touch; ///< first t with f(t) <= 0 (valid when fmin <= 0)
} core_sweep_ref_t;

typedef double (*core_dist_fn)(void *ctx, double t);
void core_sweep_analyse(core_dist_fn f, void *ctx, double reach, core_sweep_ref_t *out);
#endif
