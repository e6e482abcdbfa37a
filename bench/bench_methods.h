/**
 * @file bench_methods.h
 * @brief Capsule-vs-triangle sweep methods compared by the benchmark. Each has the
 *        coll_tri_sweep_fn signature, so coll_set_tri_sweep_method() runs the whole scene
 *        and character body on it. Benchmark code only, not runtime code.
 */
#ifndef BENCH_METHODS_H
#define BENCH_METHODS_H

#include "prim.h"

/** libccd sweep: bisection on the swept-hull intersection test (GJK or MPR). */
typedef struct {
    int use_mpr;        ///< 0: ccdGJKIntersect, 1: ccdMPRIntersect
    int iters;          ///< bisection steps at most
    float tol;          ///< stop when the bracket is shorter than this, meters
    unsigned long ccd_max_iter; ///< libccd's own GJK iteration cap
} bench_ccd_ctx_t;

bool bench_ccd_tri_sweep(void *ctx, const fm_vec3_t seg[2], float r, const fm_vec3_t *disp,
                         const fm_vec3_t tri[3], float t_max, coll_prim_hit_t *hit);

/** Discrete sub-stepping: overlap tests at n steps along the displacement, no time of impact. */
typedef struct {
    int n;              ///< sub-steps per sweep (>= 1)
} bench_disc_ctx_t;

bool bench_disc_tri_sweep(void *ctx, const fm_vec3_t seg[2], float r, const fm_vec3_t *disp,
                          const fm_vec3_t tri[3], float t_max, coll_prim_hit_t *hit);

/** A method by name, for command lines: "exact", "ref", "ccd-gjk:ITERS:TOL",
 *  "ccd-mpr:ITERS:TOL", "disc:N". Installs it; false for an unknown name. */
bool bench_method_install(const char *spec);

#endif
