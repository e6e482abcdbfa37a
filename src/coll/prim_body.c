/**
 * @file prim_body.c
 * @brief Ray and capsule against convex collider bodies (sphere, box, capsule, cylinder).
 *        Placeholder: reports no contact until the real implementation lands.
 */
#include "prim_util.h"

bool coll_ray_body(const fm_vec3_t *o, const fm_vec3_t *d, const coll_body_t *body,
                   const fm_vec3_t *body_pos_rel, float s_max, coll_prim_hit_t *hit)
{
    (void)o; (void)d; (void)body; (void)body_pos_rel; (void)s_max; (void)hit;
    return false;
}

bool coll_capsule_body_sweep(const fm_vec3_t seg[2], float r, const fm_vec3_t *disp,
                             const coll_body_t *body, const fm_vec3_t *body_pos_rel,
                             float t_max, coll_prim_hit_t *hit)
{
    (void)seg; (void)r; (void)disp; (void)body; (void)body_pos_rel; (void)t_max; (void)hit;
    return false;
}

bool coll_capsule_body_overlap(const fm_vec3_t seg[2], float r, const coll_body_t *body,
                               const fm_vec3_t *body_pos_rel, coll_prim_hit_t *hit)
{
    (void)seg; (void)r; (void)body; (void)body_pos_rel; (void)hit;
    return false;
}
