/**
 * @file prim_method.c
 * @brief The capsule-vs-triangle sweep the scene calls. Built with -DCOLL_METHOD_HOOKS
 *        (libcoll_hooks.a, benchmarks and tests only), another method can be installed
 *        and the whole character body runs on it (libccd conservative advancement,
 *        discrete sub-steps); NULL restores the exact analytic sweep.
 */
#include "prim.h"
#include "prim_util.h"

#ifdef COLL_METHOD_HOOKS
static coll_tri_sweep_fn g_sweep_fn;
static void *g_sweep_ctx;

void coll_set_tri_sweep_method(coll_tri_sweep_fn fn, void *ctx)
{
    g_sweep_fn = fn;
    g_sweep_ctx = fn ? ctx : NULL;
}
#endif

/* An installed method answers every form: it has no use for the caller's held hit or the
 * triangle's prep. p NULL: no prep kept. */
static bool tri_sweep_method(const fm_vec3_t seg[2], float r, const fm_vec3_t *disp, const fm_vec3_t tri[3],
                             coll_tri_prep_t *p, float t_max, const fm_vec3_t *held, coll_prim_hit_t *hit)
{
#ifdef COLL_METHOD_HOOKS
    if (g_sweep_fn) return g_sweep_fn(g_sweep_ctx, seg, r, disp, tri, t_max, hit);
#endif
    return coll_prim_tri_sweep_prep(seg, r, disp, tri, p, t_max, held, hit);
}

bool coll_tri_sweep(const fm_vec3_t seg[2], float r, const fm_vec3_t *disp,
                    const fm_vec3_t tri[3], float t_max, coll_prim_hit_t *hit)
{
    return tri_sweep_method(seg, r, disp, tri, NULL, t_max, NULL, hit);
}

bool coll_tri_sweep_before(const fm_vec3_t seg[2], float r, const fm_vec3_t *disp,
                           const fm_vec3_t tri[3], float t_max, coll_prim_hit_t *hit)
{
    static const fm_vec3_t no_axis = { { 0.0f, 0.0f, 0.0f } }; /* held, no normal to try */
    return tri_sweep_method(seg, r, disp, tri, NULL, t_max, &no_axis, hit);
}

bool coll_tri_sweep_prep(const fm_vec3_t seg[2], float r, const fm_vec3_t *disp, const fm_vec3_t tri[3],
                         coll_tri_prep_t *p, float t_max, const fm_vec3_t *held, coll_prim_hit_t *hit)
{
    return tri_sweep_method(seg, r, disp, tri, p, t_max, held, hit);
}
