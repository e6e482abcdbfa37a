/**
 * @file char_body_floor.c
 * @brief Floor probe (grounding, steep state, snapping, stair lift) and moving-platform carry.
 *
 * The probe is a ray along the capsule axis from the centre of the sweep capsule's bottom
 * ball (free space: the sweep capsule was just swept there) down to floor_snap_distance
 * below the foot. The foot is therefore a single point: past a ledge edge the ray misses
 * and the body falls instead of balancing on its rounded bottom.
 */
#include "char_body_internal.h"

fm_vec3_t cb_xf_apply(const coll_transform_t *xf, fm_vec3_t local)
{
    fm_vec3_t s = cb_v(local.x * xf->scale.x, local.y * xf->scale.y, local.z * xf->scale.z);
    fm_vec3_t r;
    fm_quat_rotate_vec3(&r, &xf->rot, &s);
    return cb_add(r, xf->pos);
}

bool cb_xf_inverse(const coll_transform_t *xf, fm_vec3_t world, fm_vec3_t *local)
{
    const fm_vec3_t *sc = &xf->scale;
    if (!(fabsf(sc->x) > 1e-12f) || !(fabsf(sc->y) > 1e-12f) || !(fabsf(sc->z) > 1e-12f)) return false;
    fm_quat_t inv;
    fm_quat_inverse(&inv, &xf->rot);
    fm_quat_norm(&inv, &inv);
    fm_vec3_t d = cb_sub(world, xf->pos);
    fm_vec3_t r;
    fm_quat_rotate_vec3(&r, &inv, &d);
    *local = cb_v(r.x / sc->x, r.y / sc->y, r.z / sc->z);
    return cb_finite(*local);
}

void cb_carry(const cb_ctx_t *c, fm_vec3_t *pos)
{
    char_body_t *b = c->body;
    if (!(b->flags & CB_FLAG_CARRY) || !b->floor_instance) return;
    /* Only an instance still in the scene carries (it may have been removed since). */
    bool present = false;
    for (uint16_t i = 0; i < c->scene->mesh_count && i < COLL_SCENE_MAX_MESHES; i++)
        if (c->scene->meshes[i] == b->floor_instance) present = true;
    if (!present) return;
    fm_vec3_t now = cb_xf_apply(&b->floor_instance->xf, b->floor_local_point);
    fm_vec3_t delta = cb_sub(now, b->floor_world_point);
    if (!cb_finite(delta)) return;
    /* Swept, so a platform cannot carry the body through a wall. */
    cb_slide(c, pos, delta, NULL, false);
}

void cb_probe_floor(const cb_ctx_t *c, fm_vec3_t *pos, bool was_grounded, bool jumping)
{
    char_body_t *b = c->body;
    fm_vec3_t up = c->up;
    float above = c->radius + c->step;            /* ray origin above the foot */
    fm_vec3_t origin = cb_madd(cb_foot(c, *pos), up, above);
    coll_ray_hit_t hit;
    bool found = !jumping &&
                 coll_raycast(c->scene, origin, cb_scale(up, -1.0f), above + c->snap, b->settings.read_mask,
                              b->settings.coll_types, &hit) &&
                 cb_finite(hit.normal) && cb_finite(hit.point);
    bool grounded = false;
    bool steep = false;
    if (found) {
        float gap = hit.distance - above; /* > 0: floor below the foot; < 0: above it (a step) */
        float nu = cb_dot(hit.normal, up);
        bool walkable = nu >= b->cos_floor_max_angle;
        if (walkable) {
            if (gap <= CB_CONTACT_EPS || (was_grounded && gap <= c->snap)) {
                /* Stand exactly on it: lift onto a tread, snap down a ramp or small drop.
                 * Swept: the capsule is wider than the foot point, so walking off a ledge
                 * its edge, or a slope or ceiling above a tread, may stop it short. */
                cb_move_swept(c, pos, cb_scale(up, -gap));
                grounded = true;
            }
        } else if (nu > 0.0f) {
            /* Steep: the sweep capsule rests on it, its bottom ball r away from the plane,
             * which puts the plane r / cos - (r + step) below the foot along up. Only
             * that close (plus 1 cm) is standing on it; higher up the body is falling. */
            float rest = c->radius / nu - (c->radius + c->step);
            if (gap <= (rest > 0.0f ? rest : 0.0f) + 0.01f) {
                grounded = true;
                steep = true;
            }
        }
    }

    b->flags &= (uint8_t)~(CB_FLAG_GROUNDED | CB_FLAG_STEEP | CB_FLAG_CARRY);
    b->floor_instance = NULL;
    if (!grounded) {
        b->floor_id = -1;
        b->floor_normal = up;
        return;
    }
    b->flags |= CB_FLAG_GROUNDED;
    if (steep) b->flags |= CB_FLAG_STEEP;
    b->floor_normal = hit.normal;
    b->floor_id = hit.id;
    if (!steep) {
        /* Floor contact ends any motion along up: no creep, no bounce. */
        b->velocity = cb_reject(b->velocity, up);
    } else {
        float into = cb_dot(b->velocity, hit.normal);
        if (into < 0.0f) b->velocity = cb_madd(b->velocity, hit.normal, -into);
    }
    if (hit.instance && b->settings.follow_floor) {
        fm_vec3_t anchor = steep ? hit.point : cb_foot(c, *pos);
        fm_vec3_t local;
        if (cb_xf_inverse(&hit.instance->xf, anchor, &local)) {
            b->floor_instance = hit.instance;
            b->floor_local_point = local;
            b->floor_world_point = anchor;
            b->flags |= CB_FLAG_CARRY;
        }
    }
}
