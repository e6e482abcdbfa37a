/**
 * @file prim_ref.h
 * @brief Double-precision reference geometry for the primitive tests: segment-triangle
 *        and segment-segment distance, and sweeps by exact convex minimisation + bisection
 *        of the distance function (independent of the float implementation's method).
 */
#ifndef PRIM_REF_H
#define PRIM_REF_H
#include <stdbool.h>
#include <stdint.h>

typedef struct { double x, y, z; } prim_ref_v3;

prim_ref_v3 prim_ref_v(double x, double y, double z);
prim_ref_v3 prim_ref_add(prim_ref_v3 a, prim_ref_v3 b);
prim_ref_v3 prim_ref_sub(prim_ref_v3 a, prim_ref_v3 b);
prim_ref_v3 prim_ref_scale(prim_ref_v3 a, double s);
double prim_ref_dot(prim_ref_v3 a, prim_ref_v3 b);
prim_ref_v3 prim_ref_cross(prim_ref_v3 a, prim_ref_v3 b);
double prim_ref_len(prim_ref_v3 a);

/** Closest points of segments p0p1, q0q1; returns the distance. */
double prim_ref_seg_seg(prim_ref_v3 p0, prim_ref_v3 p1, prim_ref_v3 q0, prim_ref_v3 q1,
                        prim_ref_v3 *cp, prim_ref_v3 *cq);
/** Closest point of a triangle to p (Ericson's region test; degenerate triangles ok). */
prim_ref_v3 prim_ref_closest_pt_tri(prim_ref_v3 p, const prim_ref_v3 tri[3]);
/** Distance segment a..b to triangle, with closest points (ps on segment, pt on triangle). */
double prim_ref_seg_tri(prim_ref_v3 a, prim_ref_v3 b, const prim_ref_v3 tri[3],
                        prim_ref_v3 *ps, prim_ref_v3 *pt);

/** A convex distance function of t: dist(shape(t), collider). */
typedef double (*prim_ref_fn)(void *ctx, double t, prim_ref_v3 *normal);

typedef struct {
    double f0;      /* distance at t = 0 */
    double fmin;    /* minimum over [0, t_max] */
    double tmin;    /* where */
    double t_first; /* first t with f <= r, or -1 */
    prim_ref_v3 n;  /* normal (collider -> query) at t_first */
} prim_ref_sweep_t;

/** Golden-section minimum of the convex f on [0, t_max], then bisection for f = r. */
void prim_ref_sweep(prim_ref_fn f, void *ctx, double r, double t_max, prim_ref_sweep_t *out);

/** Capsule-vs-triangle distance context for prim_ref_sweep. */
typedef struct {
    prim_ref_v3 a, b, d;
    prim_ref_v3 tri[3];
} prim_ref_captri_t;
double prim_ref_captri_fn(void *ctx, double t, prim_ref_v3 *normal);

/** xorshift64 random source shared by the primitive test suites (each seeds its own). */
typedef struct { uint64_t s; } prim_ref_rng_t;
uint32_t prim_ref_rng_u32(prim_ref_rng_t *g);
/** Uniform in [a, b). */
double prim_ref_rng_range(prim_ref_rng_t *g, double a, double b);
/** Uniform direction (rejection sampling in the unit ball). */
prim_ref_v3 prim_ref_rng_unit(prim_ref_rng_t *g);

#endif
