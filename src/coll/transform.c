/**
 * @file transform.c
 * @brief The one transform apply/inverse for single points (coll/common.h).
 *
 * The queries keep their own precomputed matrix form (query.c's xf3_t) because they map
 * many points per instance; these serve single points: a platform's anchor, a carry.
 */
#include "coll_libm.h"
#include "coll/common.h"

/* No rotation and unit scale: a level placed where it was baked (most instances). The
 * general formulas give bit-identical results there; these skip the quaternion work
 * (the probe anchors every grounded step to its floor's instance). */
static inline bool is_translation(const coll_transform_t *xf)
{
    return xf->rot.x == 0.0f && xf->rot.y == 0.0f && xf->rot.z == 0.0f && xf->rot.w == 1.0f &&
           xf->scale.x == 1.0f && xf->scale.y == 1.0f && xf->scale.z == 1.0f;
}

/* The two ways of placing a point; coll_transform_point and coll_transform_point_anchor
 * both use these, so the same local point under the same xf lands on the same bits. */
static inline fm_vec3_t place_translated(const coll_transform_t *xf, fm_vec3_t local)
{
    return (fm_vec3_t){{local.x + xf->pos.x, local.y + xf->pos.y, local.z + xf->pos.z}};
}

static inline fm_vec3_t place_general(const coll_transform_t *xf, fm_vec3_t local)
{
    fm_vec3_t s = {{local.x * xf->scale.x, local.y * xf->scale.y, local.z * xf->scale.z}};
    fm_vec3_t r;
    fm_quat_rotate_vec3(&r, &xf->rot, &s);
    return (fm_vec3_t){{r.x + xf->pos.x, r.y + xf->pos.y, r.z + xf->pos.z}};
}

fm_vec3_t coll_transform_point(const coll_transform_t *xf, fm_vec3_t local)
{
    return is_translation(xf) ? place_translated(xf, local) : place_general(xf, local);
}

/* The inverse under a translation only, and under the rest (rotation, scale). */
static inline bool unplace_translated(const coll_transform_t *xf, fm_vec3_t world, fm_vec3_t *local)
{
    fm_vec3_t l = {{world.x - xf->pos.x, world.y - xf->pos.y, world.z - xf->pos.z}};
    if (!isfinite(l.x) || !isfinite(l.y) || !isfinite(l.z)) return false;
    *local = l;
    return true;
}

static inline bool unplace_general(const coll_transform_t *xf, fm_vec3_t world, fm_vec3_t *local)
{
    const fm_vec3_t *sc = &xf->scale;
    if (!(fabsf(sc->x) > 1e-12f) || !(fabsf(sc->y) > 1e-12f) || !(fabsf(sc->z) > 1e-12f)) return false;
    fm_quat_t inv;
    fm_quat_inverse(&inv, &xf->rot);
    fm_quat_norm(&inv, &inv);
    fm_vec3_t d = {{world.x - xf->pos.x, world.y - xf->pos.y, world.z - xf->pos.z}};
    fm_vec3_t r;
    fm_quat_rotate_vec3(&r, &inv, &d);
    fm_vec3_t l = {{r.x / sc->x, r.y / sc->y, r.z / sc->z}};
    if (!isfinite(l.x) || !isfinite(l.y) || !isfinite(l.z)) return false;
    *local = l;
    return true;
}

bool coll_transform_point_inverse(const coll_transform_t *xf, fm_vec3_t world, fm_vec3_t *local)
{
    return is_translation(xf) ? unplace_translated(xf, world, local) : unplace_general(xf, world, local);
}

bool coll_transform_point_anchor(const coll_transform_t *xf, fm_vec3_t world, fm_vec3_t *local, fm_vec3_t *placed)
{
    if (is_translation(xf)) {
        if (!unplace_translated(xf, world, local)) return false;
        *placed = place_translated(xf, *local);
    } else {
        if (!unplace_general(xf, world, local)) return false;
        *placed = place_general(xf, *local);
    }
    return true;
}
