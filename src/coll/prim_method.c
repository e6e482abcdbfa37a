/**
 * @file prim_method.c
 * @brief The swappable capsule-vs-triangle sweep: benchmarks install another method
 *        (libccd conservative advancement, discrete sub-steps) and run the whole
 *        character body on it; NULL restores the exact analytic sweep.
 */
#include "prim.h"

static coll_tri_sweep_fn g_sweep_fn;
static void *g_sweep_ctx;

void coll_set_tri_sweep_method(coll_tri_sweep_fn fn, void *ctx)
{
    g_sweep_fn = fn;
    g_sweep_ctx = fn ? ctx : NULL;
}

bool coll_tri_sweep(const fm_vec3_t seg[2], float r, const fm_vec3_t *disp,
                    const fm_vec3_t tri[3], float t_max, coll_prim_hit_t *hit)
{
    if (g_sweep_fn) return g_sweep_fn(g_sweep_ctx, seg, r, disp, tri, t_max, hit);
    return coll_capsule_triangle_sweep(seg, r, disp, tri, t_max, hit);
}
