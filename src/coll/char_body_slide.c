/**
 * @file char_body_slide.c
 * @brief Sweep-and-slide of the shortened capsule (Quake III bg_slidemove.c's clip planes
 *        and creases), overlap recovery (Box2D mover style) and the airborne foot guard.
 */
#include "char_body_internal.h"

/** v without its part going into plane n (a part leaving the plane is kept). */
static fm_vec3_t clip_plane(fm_vec3_t v, fm_vec3_t n)
{
    float d = cb_dot(v, n);
    return d < 0.0f ? cb_madd(v, n, -d) : v;
}

/**
 * v clipped against every plane hit this step (Quake III's PM_SlideMove): clip against
 * the first plane it enters; if that sends it into a second plane, follow the crease of
 * the two; if the crease enters a third plane, stop.
 */
static fm_vec3_t clip_planes(fm_vec3_t v, const fm_vec3_t *planes, int np)
{
    const float eps = -1e-6f;
    for (int i = 0; i < np; i++) {
        if (cb_dot(v, planes[i]) >= eps) continue;
        fm_vec3_t cv = clip_plane(v, planes[i]);
        for (int j = 0; j < np; j++) {
            if (j == i || cb_dot(cv, planes[j]) >= eps) continue;
            cv = clip_plane(cv, planes[j]);
            if (cb_dot(cv, planes[i]) >= eps) continue;
            fm_vec3_t dir = cb_norm(cb_cross(planes[i], planes[j]));
            cv = cb_scale(dir, cb_dot(dir, v));
            for (int k = 0; k < np; k++) {
                if (k == i || k == j) continue;
                if (cb_dot(cv, planes[k]) < eps) return cb_v(0.0f, 0.0f, 0.0f);
            }
        }
        /* The clipped vector may still enter an earlier plane (three walls): stop. */
        for (int k = 0; k < np; k++)
            if (cb_dot(cv, planes[k]) < -1e-4f) return cb_v(0.0f, 0.0f, 0.0f);
        return cv;
    }
    return v;
}

/**
 * The plane a grounded body slides along. The sweep capsule only ever meets walls while
 * walking (its bottom floats step_height above the floor), so a hit above the step zone
 * acts as a vertical wall: no climbing steep slopes or tall risers' rounded edges, no
 * being pushed into the floor by sloped ceilings. Hits inside the step zone keep their
 * real normal: the floor probe steps onto them.
 */
static fm_vec3_t walking_plane(const cb_ctx_t *c, fm_vec3_t pos, const coll_sweep_hit_t *hit)
{
    float nu = cb_dot(hit->normal, c->up);
    float h = cb_dot(cb_sub(hit->point, cb_foot(c, pos)), c->up);
    if (nu > 0.0f && h <= c->step + 0.01f) return hit->normal;
    fm_vec3_t nh = cb_norm(cb_reject(hit->normal, c->up));
    return cb_len(nh) > 0.5f ? nh : hit->normal;
}

/**
 * Airborne, the capsule's rounded bottom resting on an edge that the foot point is already
 * past: the foot is a point, so there is nothing to stand on. Push the capsule sideways off
 * the edge (a swept move) and report true; false when the ground under the foot point
 * supports the contact (a floor or slope).
 */
static bool slide_off_edge(const cb_ctx_t *c, fm_vec3_t *pos, const coll_sweep_hit_t *hit)
{
    const char_body_t *b = c->body;
    float nu = cb_dot(hit->normal, c->up);
    if (nu <= 0.05f) return false;
    fm_vec3_t ball = cb_madd(cb_sweep_center(c, *pos), c->up, -c->sweep_ihh);
    fm_vec3_t rel = cb_sub(ball, hit->point);
    if (cb_dot(rel, c->up) <= 1e-3f) return false; /* not under the bottom ball */
    /* A plane under the contact lies r / nu below the ball centre along the axis. */
    float reach = c->radius / (nu > 0.1f ? nu : 0.1f) + 0.02f;
    coll_ray_hit_t rh;
    if (coll_raycast(c->scene, ball, cb_scale(c->up, -1.0f), reach, b->settings.read_mask,
                     b->settings.coll_types, &rh))
        return false;
    fm_vec3_t h = cb_reject(rel, c->up);
    float hl = cb_len(h);
    fm_vec3_t dir = hl > 1e-5f ? cb_scale(h, 1.0f / hl) : cb_norm(cb_reject(hit->normal, c->up));
    if (cb_len(dir) < 0.5f) return false;
    float need = c->radius + CB_SKIN - hl;
    if (need <= 0.0f) return false;
    fm_vec3_t d = cb_scale(dir, need);
    coll_sweep_hit_t h2;
    if (coll_capsule_sweep(c->scene, cb_sweep_center(c, *pos), c->up, c->radius, c->sweep_ihh, d,
                           b->settings.read_mask, b->settings.coll_types, &h2)) {
        float travel = need * h2.t - CB_SKIN;
        if (travel > 0.0f) *pos = cb_madd(*pos, dir, travel);
    } else {
        *pos = cb_add(*pos, d);
    }
    return true;
}

/**
 * Walking, blocked by something above the step zone: if the foot point has already moved
 * over a higher tread (within step_height), stand on it now and report true, so the rest
 * of this step's motion continues from there instead of stopping at the next riser's edge.
 */
static bool step_up_now(const cb_ctx_t *c, fm_vec3_t *pos)
{
    const char_body_t *b = c->body;
    float above = c->radius + c->step;
    fm_vec3_t origin = cb_madd(cb_foot(c, *pos), c->up, above);
    coll_ray_hit_t rh;
    if (!coll_raycast(c->scene, origin, cb_scale(c->up, -1.0f), above, b->settings.read_mask,
                      b->settings.coll_types, &rh))
        return false;
    float lift = above - rh.distance;
    if (!(lift > 1e-4f) || cb_dot(rh.normal, c->up) < b->cos_floor_max_angle) return false;
    *pos = cb_madd(*pos, c->up, lift);
    return true;
}

void cb_slide(const cb_ctx_t *c, fm_vec3_t *pos, fm_vec3_t disp, fm_vec3_t *vel, bool grounded)
{
    int step_ups = 0;
    const char_body_t *b = c->body;
    fm_vec3_t planes[CB_MAX_PLANES];
    int np = 0;
    fm_vec3_t rem = disp;
    for (int it = 0; it < b->settings.max_slides; it++) {
        float len = cb_len(rem);
        if (!(len > 1e-6f)) break;
        coll_sweep_hit_t hit;
        if (!coll_capsule_sweep(c->scene, cb_sweep_center(c, *pos), c->up, c->radius, c->sweep_ihh, rem,
                                b->settings.read_mask, b->settings.coll_types, &hit)) {
            *pos = cb_add(*pos, rem);
            break;
        }
        if (!cb_finite(hit.normal) || !isfinite(hit.t)) break;
        float t = hit.t < 0.0f ? 0.0f : (hit.t > 1.0f ? 1.0f : hit.t);
        float done = 0.0f; /* fraction of rem actually travelled */
        if (t <= 0.0f && hit.depth > 0.0f) {
            /* Started inside: step out along the push-out direction first. */
            float d = hit.depth < c->radius ? hit.depth : c->radius;
            *pos = cb_madd(*pos, hit.normal, d + CB_SKIN * 0.5f);
        } else {
            /* Advance to the contact, backing off CB_SKIN along the motion. */
            float travel = len * t - CB_SKIN;
            if (travel > 0.0f) {
                done = travel / len;
                *pos = cb_madd(*pos, rem, done);
            }
        }
        /* The untravelled rest, skin included, slides on: no speed lost to the skin. */
        fm_vec3_t left = cb_scale(rem, 1.0f - done);
        if (!grounded && cb_dot(left, c->up) < 0.0f && slide_off_edge(c, pos, &hit)) {
            rem = left;
            continue;
        }
        fm_vec3_t n = grounded ? walking_plane(c, *pos, &hit) : hit.normal;
        if (grounded && step_ups < 2 && cb_dot(n, hit.normal) < 0.9999f && step_up_now(c, pos)) {
            step_ups++;
            rem = left;
            continue;
        }
        bool known = false;
        for (int i = 0; i < np; i++)
            if (cb_dot(planes[i], n) > 0.9999f) known = true;
        if (!known && np < CB_MAX_PLANES) planes[np++] = n;
        if (known) {
            /* Same plane again (numerical touch): nudge off it so the next sweep starts clear. */
            *pos = cb_madd(*pos, n, CB_SKIN * 0.1f);
        }
        rem = clip_planes(left, planes, np);
        if (vel) *vel = clip_planes(*vel, planes, np);
    }
}

void cb_recover(const cb_ctx_t *c, fm_vec3_t *pos, fm_vec3_t *vel)
{
    const char_body_t *b = c->body;
    for (int pass = 0; pass < 2; pass++) {
        coll_contact_t ct[CB_MAX_CONTACTS];
        uint32_t n = coll_capsule_overlaps(c->scene, cb_sweep_center(c, *pos), c->up, c->radius, c->sweep_ihh,
                                           b->settings.read_mask, b->settings.coll_types, ct, CB_MAX_CONTACTS);
        if (n > CB_MAX_CONTACTS) n = CB_MAX_CONTACTS;
        fm_vec3_t delta = cb_v(0.0f, 0.0f, 0.0f);
        bool any = false;
        /* Gauss-Seidel on positions: each contact wants depth + half a skin of separation. */
        for (int iter = 0; iter < 4; iter++) {
            for (uint32_t i = 0; i < n; i++) {
                if (!(ct[i].depth > CB_MIN_DEPTH) || !cb_finite(ct[i].normal)) continue;
                float want = ct[i].depth + 0.5f * CB_SKIN - cb_dot(delta, ct[i].normal);
                if (want > 0.0f) {
                    delta = cb_madd(delta, ct[i].normal, want);
                    any = true;
                }
            }
        }
        if (!any) return;
        float dl = cb_len(delta);
        float lim = 2.0f * c->radius + 2.0f * c->half_height;
        if (dl > lim) delta = cb_scale(delta, lim / dl);
        *pos = cb_add(*pos, delta);
        if (vel) {
            for (uint32_t i = 0; i < n; i++)
                if (ct[i].depth > CB_MIN_DEPTH && cb_finite(ct[i].normal)) *vel = clip_plane(*vel, ct[i].normal);
        }
    }
}

void cb_foot_guard(const cb_ctx_t *c, fm_vec3_t *pos, fm_vec3_t old_foot, fm_vec3_t *vel)
{
    const char_body_t *b = c->body;
    fm_vec3_t foot = cb_foot(c, *pos);
    fm_vec3_t o = cb_madd(old_foot, c->up, 0.002f);
    fm_vec3_t d = cb_sub(foot, o);
    float len = cb_len(d);
    if (!(len > 1e-5f)) return;
    fm_vec3_t dir = cb_scale(d, 1.0f / len);
    coll_ray_hit_t hit;
    if (!coll_raycast(c->scene, o, dir, len, b->settings.read_mask, b->settings.coll_types, &hit)) return;
    fm_vec3_t n = hit.normal;
    if (!cb_finite(n) || cb_dot(n, c->up) >= b->cos_floor_max_angle) return; /* landing: the probe's job */
    /* Slide the foot along the wall it would have entered. */
    fm_vec3_t after = cb_sub(foot, hit.point);
    fm_vec3_t target = cb_add(cb_madd(hit.point, n, CB_SKIN), clip_plane(after, n));
    *pos = cb_add(*pos, cb_sub(target, foot));
    if (vel) *vel = clip_plane(*vel, n);
}
