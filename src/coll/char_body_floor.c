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

/**
 * The velocity half a step after the chord velocity `cur`, given the chord `prev` of the
 * step before: turned on by half the turn from prev to cur (about their common normal),
 * and with its length changed by half the change. Exact for a steady turn (a turntable),
 * a steady translation and a steady acceleration along a line.
 */
static fm_vec3_t extrapolate_half_step(fm_vec3_t prev, fm_vec3_t cur, float still)
{
    float lp = v3_len(prev), lc = v3_len(cur);
    if (!(lp > still) || !(lc > still)) return v3_madd(cur, v3_sub(cur, prev), 0.5f);
    fm_vec3_t axis = v3_cross(prev, cur);
    float s = v3_len(axis) / (lp * lc), co = v3_dot(prev, cur) / (lp * lc);
    fm_vec3_t v = cur;
    if (s > 1e-7f) {
        axis = v3_scale(axis, 1.0f / (s * lp * lc));
        float ch = sqrtf(0.5f * (1.0f + co) > 0.0f ? 0.5f * (1.0f + co) : 0.0f), sh = sqrtf(0.5f * (1.0f - co) > 0.0f ? 0.5f * (1.0f - co) : 0.0f);
        /* Rodrigues, by half the angle; axis is perpendicular to cur */
        v = v3_add(v3_scale(cur, ch), v3_scale(v3_cross(axis, cur), sh));
    }
    float grow = lc + 0.5f * (lc - lp);
    return v3_scale(v, (grow > 0.0f ? grow : 0.0f) / lc);
}

bool coll_cb_carry_delta(const cb_ctx_t *c, fm_vec3_t *delta)
{
    char_body_t *b = c->body;
    if (!(b->flags & CB_FLAG_CARRY) || !b->floor_instance) return false;
    /* Only an instance still in the scene carries (it may have been removed since). */
    bool present = false;
    for (uint16_t i = 0; i < c->scene->mesh_count && i < COLL_SCENE_MAX_MESHES; i++)
        if (c->scene->meshes[i] == b->floor_instance) present = true;
    if (!present) return false;
    fm_vec3_t now = coll_transform_point(&b->floor_instance->xf, b->floor_local_point);
    *delta = v3_sub(now, b->floor_world_point);
    return v3_finite(*delta);
}

fm_vec3_t coll_cb_carry(const cb_ctx_t *c, fm_vec3_t *pos, fm_vec3_t delta)
{
    char_body_t *b = c->body;
    /* Swept, so a platform cannot carry the body through a wall. A floor that did not move
     * (a static level's: delta 0, or rounding) moves nothing: the slide would stop at once.
     * delta is finite (coll_cb_carry_delta), so the compare is never of a NaN. */
    bool moved = v3_len(delta) > c->tiny;
    if (moved) coll_cb_slide(c, pos, delta, NULL, false);
    /* The floor point's velocity at the end of the step: the chord delta / dt is its mean
     * velocity over the step (at mid-step); extrapolated by half a step from the previous
     * chord, a turning platform's tangent at take-off is right to second order (a jump off
     * a turntable at 1 rev/s would otherwise leave rotated by half a step). A floor that
     * moved nothing has no velocity either: its rounding residue over a tiny dt would read
     * as metres per second (s31 l439: 5e-8 m over 1e-9 s kept as 14.9 m/s on leaving it). */
    fm_vec3_t chord = moved ? v3_scale(delta, 1.0f / c->dt) : v3(0.0f, 0.0f, 0.0f);
    fm_vec3_t v = chord;
    if (b->flags & CB_FLAG_CARRIED) v = extrapolate_half_step(b->carry_velocity, chord, c->tiny);
    b->carry_velocity = chord;
    b->flags |= CB_FLAG_CARRIED;
    return v3_finite(v) ? v : v3(0.0f, 0.0f, 0.0f);
}

bool coll_cb_sweep_down(const cb_ctx_t *c, fm_vec3_t pos, float len, coll_sweep_hit_t *hit)
{
    bool found;
    if (cb_down_known(c, pos, len, &found, hit)) return found;
    /* (on the gather: the recovery's boundary axes tried first, coll_gather_capsule_sweep_corner_m) */
    found = c->gather ? coll_gather_capsule_sweep_corner_m(c->gather, cb_sweep_center(c, pos), c->up, c->radius,
                                                           c->sweep_ihh, v3_scale(c->up, -len), &c->mem->pairs, hit)
                      : cb_sweep_step(c, cb_sweep_center(c, pos), c->radius, c->sweep_ihh, v3_scale(c->up, -len), hit);
    cb_down_t *d = &c->mem->down;
    d->valid = true;
    d->pos = pos;
    d->len = len;
    d->hit = found && isfinite(hit->t);
    d->dist = d->hit ? (hit->t > 0.0f ? hit->t : 0.0f) * len : 0.0f;
    if (d->hit) d->h = *hit;
    return found;
}

void coll_cb_down_moved(const cb_ctx_t *c, fm_vec3_t pos, float by)
{
    cb_down_t *d = &c->mem->down;
    d->pos = pos;
    d->len += by;
    d->dist += by;
    if (!(d->len >= 0.0f)) d->valid = false;
}

/** The crack rule's ball (radius r) dropped from b0, the sweep capsule's bottom ball at
 *  pos, by len along -up: answered from the step's down sweep there when it is known.
 *  step: through cb_sweep_step (the same answer; ball_reaches_floor's drop over a level
 *  floor, beside a stair's risers and treads). */
static inline bool ball_drop(const cb_ctx_t *c, fm_vec3_t pos, fm_vec3_t b0, float len, coll_sweep_hit_t *hit,
                             bool step)
{
    bool found;
    if (cb_down_known(c, pos, len, &found, hit)) return found;
    return step ? cb_sweep_step(c, b0, c->radius, 0.0f, v3_scale(c->up, -len), hit)
                : cb_sweep(c, b0, c->radius, 0.0f, v3_scale(c->up, -len), hit);
}

/** ball_drop for a drop that stays above a plane (above: the first look's, over the foot
 *  ray's floor): the same answer, without the exact tests of the triangles under it. */
static inline bool ball_drop_above(const cb_ctx_t *c, fm_vec3_t pos, fm_vec3_t b0, float len,
                                   const coll_gather_above_t *above, coll_sweep_hit_t *hit)
{
    bool found;
    if (cb_down_known(c, pos, len, &found, hit)) return found;
    return cb_sweep_above(c, b0, c->radius, 0.0f, v3_scale(c->up, -len), above, hit);
}

/** What holds the body up at the end of a step. */
typedef struct {
    bool found;
    bool steep;
    float gap;            ///< floor below the foot along up (> 0), or above it (< 0)
    fm_vec3_t normal;     ///< floor normal (walkable floors), or the steep surface's
    fm_vec3_t point;      ///< contact on the floor
    uint16_t id;
    const coll_mesh_instance_t *instance;
} support_t;

/**
 * The crack rule. The foot point found no floor within reach (none under it, or deeper than
 * floor_snap_distance: a floor the foot point can step down onto is a step, as in the
 * seed), but the full capsule's bottom ball may rest on geometry on both sides
 * of a gap narrower than the capsule: a crack between floor pieces, a slot at the bottom of
 * a valley, a slot between a ledge and a wall. The ball is dropped from where the sweep
 * capsule's bottom ball is (free space) by step + reach + r/2; from where it first touches,
 * it rolls down the contact's tangent plane by up to a diameter. It is held when that roll
 * meets geometry on the other side (the horizontal parts of the two contact normals
 * oppose: a wedge) or a walkable floor, within half a radius of descent, and when the lower
 * contact is within reach of the foot. The body then stands where the ball rests: touching
 * the higher edge of a crack (sunk below it by at most the sag of a round capsule resting on
 * both edges, r - sqrt(r^2 - (gap/2)^2)). Only its height changes: it is not pulled
 * sideways into the crack. A roll onto a floor counts within a tenth of a radius of descent
 * (across a crack too narrow for the ball to dip into; not down a ledge onto a lower floor). At a ledge the roll meets nothing, or
 * nothing it can stand on, and the foot-as-a-point rule stands: the body falls. Over a floor
 * the foot ray found (floor_gap), the ball holds only above it: contacts at one level, or
 * on opposite sides (a narrow wedge, or a roll across the foot point onto a floor).
 */
/* Where the crack rule drops the full capsule's bottom ball from: the sweep capsule's
 * bottom ball centre (free space: the sweep capsule was just swept there). */
static inline fm_vec3_t ball_drop_start(const cb_ctx_t *c, fm_vec3_t pos)
{
    return v3_madd(cb_foot(c, pos), c->up, c->radius + c->step);
}

/**
 * The crack rule's drop met, at its very start, a wall along up (its normal across up) that
 * the ball overlaps by less than the skin: a creep of skin top-ups, not a place the ball is
 * stuck in. The drop goes along that wall, not into it, and the overlap is no contact below
 * the ball: the ball is moved out of it (by the depth, to touching, across up) and dropped
 * again from there. Deeper than min_depth every sweep from the ball starts inside the wall,
 * so without this the rule gave up there, while 0.05 mm in the same wall it held the ball.
 * Against the room wall, the input into it and into a box stack's vertical edge 0.15 mm
 * beside the capsule (a crease too narrow for the push-out's half skin off both), the
 * sweep capsule's bottom ball on a tile's edge 4.6 degrees off up, its foot 5.6 cm past
 * the edge over the room floor 0.235 m below: the top-ups off that edge crept the capsule
 * 0.03 mm per step into the wall, and once 0.113 mm in (over min_depth) the rule no longer
 * held the ball on the edge; the slide, its push-out refused, never moved it again, and the
 * body hung at rest in the air for ever (soak s69 l158). Out of line: taken only there.
 */
static __attribute__((noinline)) bool drop_off_wall(const cb_ctx_t *c, fm_vec3_t *b0, float len,
                                                    coll_sweep_hit_t *h1)
{
    const fm_vec3_t push = v3_reject(v3_scale(h1->normal, h1->depth), c->up);
    const fm_vec3_t b1 = v3_add(*b0, push);
    coll_sweep_hit_t h;
    if (!cb_sweep(c, b1, c->radius, 0.0f, v3_scale(c->up, -len), &h) || !isfinite(h.t) || !(h.t > 0.0f))
        return false;
    *b0 = b1;
    *h1 = h;
    return true;
}

/** The contact is on the face of a triangle too steep to stand on (a wall). */
static bool steep_face(const cb_ctx_t *c, const coll_sweep_hit_t *h)
{
    fm_vec3_t fn;
    return coll_cb_face_normal(h, &fn) && v3_dot(fn, c->up) < c->body->cos_floor_max_angle;
}

/* A hit on the face of a floor: a face (not only an edge or a vertex) walkable under the
 * current up. */
static bool floor_face(const cb_ctx_t *c, const coll_sweep_hit_t *h)
{
    fm_vec3_t fn;
    return coll_cb_face_normal(h, &fn) && v3_dot(fn, c->up) >= c->body->cos_floor_max_angle;
}

/* A walkable contact (an edge or a face) whose normal leans across up against from's: the
 * other side of a groove from the contact the ball slid down past. */
static bool edge_across(const cb_ctx_t *c, const coll_sweep_hit_t *h, const coll_sweep_hit_t *from)
{
    return v3_finite(h->normal) && v3_finite(from->normal) &&
           v3_dot(h->normal, c->up) >= c->body->cos_floor_max_angle &&
           v3_dot(v3_reject(h->normal, c->up), v3_reject(from->normal, c->up)) < 0.0f;
}

/**
 * The crack rule's roll (the ball at b1, moved by way) along the tangent plane of the contact
 * h1 it rests on, lifted off it by a fifth of the skin: the ball stays above that plane, so
 * the faces behind the edge it rolls off (the tread and riser of a nosing, a crack's top and
 * side) lie under it and need no exact test (coll_gather_above_t, every candidate). The
 * clearance is measured, not assumed (after drop_past_side the ball may sit closer), at the
 * roll's start and end, less an allowance far above the rounding of these dot products
 * (b1 - p is a difference of nearby points, exact or within half an ulp of a radius). False
 * when it leaves no room: the plain sweep.
 */
static bool roll_above(const cb_ctx_t *c, fm_vec3_t b1, fm_vec3_t way, const coll_sweep_hit_t *h1,
                       coll_gather_above_t *out)
{
    const fm_vec3_t n = h1->normal;
    const float hs = v3_dot(v3_sub(b1, h1->point), n) - c->radius, he = hs + v3_dot(way, n);
    const float room = f_min(hs, he) - 1e-6f * (c->radius + fabsf(way.x) + fabsf(way.y) + fabsf(way.z));
    if (!(room > 0.0f)) return false;
    out->n = n;
    out->p = h1->point;
    out->margin = 0.49f * room;
    out->all = true;
    return true;
}

/* A walkable contact nearly level: its normal within asin sqrt 0.1 = 18 degrees of up, the
 * bound of a nearly level first contact (level_off, drop_off_level: n.up^2 >= 0.9). */
static bool level_edge(const cb_ctx_t *c, const coll_sweep_hit_t *h)
{
    const float nu = v3_finite(h->normal) ? v3_dot(h->normal, c->up) : 0.0f;
    return nu * nu >= 0.9f && nu >= c->body->cos_floor_max_angle && nu > 0.0f;
}

/* The ball (lifted off its contacts by lift) slid along down (sinking: -dot(down, up) > 0.1) by the rest
 * of the drop's length along up; what it meets is the first contact (drop_past_side). */
static bool slide_down(const cb_ctx_t *c, fm_vec3_t *b0, float len, fm_vec3_t lift, fm_vec3_t down,
                       coll_sweep_hit_t *h1, float *d1)
{
    const fm_vec3_t up = c->up;
    const float r = c->radius;
    const fm_vec3_t bc = v3_add(v3_madd(*b0, up, -*d1), lift);
    const float rest = len - *d1;
    if (!(rest > c->tiny)) return false;
    float sink = -v3_dot(down, up);
    if (!(sink > 0.1f)) return false;
    fm_vec3_t way = v3_scale(down, rest / sink);
    coll_sweep_hit_t h;
    /* The ball slides along the tangent plane of the contact it was lifted off (h1: the
     * side it slid past; in a groove, the wall it slid against): lifted off that plane by
     * a fifth of the skin, it stays above it, so what lies under it (the face slid along
     * and everything behind it) needs no exact test (roll_above: the clearance measured at
     * both ends). Its sweep runs up to ten times the drop across up (sink 0.1): on oa_dm5
     * (soak seed 1) 7 left the step's gathered box, one a step of 350k x86 instructions,
     * 262k of them this sweep's exact tests on the scene (docs/BENCHMARKS.md, perf33). */
    coll_gather_above_t plane;
    if (!(roll_above(c, bc, way, h1, &plane) ? cb_sweep_above(c, bc, r, 0.0f, way, &plane, &h)
                                             : cb_sweep(c, bc, r, 0.0f, way, &h)) ||
        !isfinite(h.t) || !v3_finite(h.normal) || !v3_finite(h.point))
        return false;
    float t = h.t > 0.0f ? h.t : 0.0f;
    *b0 = v3_madd(*b0, v3_reject(way, up), t); /* where the ball went across up */
    *d1 += t * rest;
    *h1 = h;
    h1->t = *d1 / len;
    return true;
}

/**
 * The crack rule's drop, over a floor the foot ray found, met the side of something first:
 * a contact too steep to stand on (a block's or a wall's edge beside the ball, well above
 * the floor), whose tangent the roll then followed into nothing, so the rule gave up and the
 * foot went down into the crack under the ball (soak s1 l184, l257, s3 l318, l400: tiles
 * around the foot, a block or a slab's edge beside). The ball slides down past it, swept
 * down the contact's tangent plane by the rest of the drop's length along up, and what it
 * meets there is the first contact (at most twice: a second side). The ball's centre moves
 * across up with the slide; the body does not, only the height it rests at comes from
 * here.
 */
static bool drop_past_side(const cb_ctx_t *c, fm_vec3_t *b0, float len, coll_sweep_hit_t *h1, float *d1)
{
    /* down its tangent plane (dropped straight past an edge, the ball met the same
     * leaning edge again a few centimetres lower, twice: soak s3 l400) */
    const fm_vec3_t down = v3_madd(v3_scale(c->up, -1.0f), h1->normal, v3_dot(h1->normal, c->up));
    return slide_down(c, b0, len, v3_scale(h1->normal, 0.2f * c->skin), down, h1, d1);
}

/* drop_past_side for a nearly level first contact (its tangent plane sinks too little for
 * slide_down; foot: the foot point, floor_gap: the floor under it): the ball (b1: lifted off
 * the contact) moved off it across up by a radius, when nothing stops that move, then
 * dropped straight down by the rest of the drop's length; what it meets is the first
 * contact when it is a floor's face above the floor under the foot (by more than the step
 * tolerance: soak s34 l341, off a 0.35 m block's top edge over two slabs 0.17 m high with a
 * 16 mm crack between them, the foot in the crack; the foot stood on the room floor 173 mm
 * under the slabs). A ray down from the moved centre's point over the foot's level to that
 * floor decides first whether there is such a face: the move and the drop reach a radius
 * past the step's gathered box and go to the scene (two scene sweeps: 34k instructions),
 * the ray stays in it; walking down stairs, every step off a nosing onto the next tread is
 * such a contact over a floor, and the drop met only that tread (the Jolt scene: +0.66 % at
 * 300 steps with the sweeps alone). */
static bool drop_off_level(const cb_ctx_t *c, fm_vec3_t b1, fm_vec3_t across, fm_vec3_t foot, float floor_gap,
                           float len, fm_vec3_t *b0, coll_sweep_hit_t *h1, float *d1)
{
    const fm_vec3_t up = c->up;
    const float r = c->radius, rest = len - *d1, tol = cb_len_tol(c, CB_STEP_EPS);
    const fm_vec3_t off = v3_scale(across, r);
    const float above = v3_dot(v3_sub(b1, foot), up); /* the centre's height over the foot */
    coll_ray_hit_t ray;
    coll_sweep_hit_t h;
    if (!(rest > c->tiny) || !(above + floor_gap - tol > 0.0f) ||
        !cb_ray(c, v3_madd(v3_add(foot, off), up, above), v3_scale(up, -1.0f), above + floor_gap - tol, &ray) ||
        !(v3_dot(ray.normal, up) >= c->body->cos_floor_max_angle))
        return false;
    if (cb_sweep(c, b1, r, 0.0f, off, &h)) return false;
    if (!cb_sweep(c, v3_add(b1, off), r, 0.0f, v3_scale(up, -rest), &h) || !isfinite(h.t) ||
        !v3_finite(h.normal) || !v3_finite(h.point) || !(v3_dot(v3_sub(h.point, foot), up) > tol - floor_gap))
        return false;
    *b0 = v3_add(*b0, off);
    *d1 += (h.t > 0.0f ? h.t : 0.0f) * rest;
    *h1 = h;
    h1->t = *d1 / len;
    return true;
}

/** Directions across up dir[0..m) (unit) leave no gap of 180 degrees or more around up: no
 *  one of them has all the others on one side of it. One opposite it within rounding (a
 *  straight crack's two edges) closes both sides: the gap beside it is 180 degrees, no more,
 *  and a ball rests on both edges (the checker allows SOAK_CRACK_OPEN, half a degree).
 *  Decided by the sign of a sine of ~1e-7, soak s15 l315 (a 0.86 m ball on a crack between
 *  two tiles, 2 more edges of near copies on each side) was held only while a duplicate
 *  contact's rounding tipped it. */
static inline bool dirs_around(const cb_ctx_t *c, const fm_vec3_t *dir, uint32_t m)
{
    const fm_vec3_t up = c->up;
    for (uint32_t i = 0; i < m; i++) {
        bool left = true, right = true;
        for (uint32_t j = 0; j < m && (left || right); j++) {
            float s = v3_dot(v3_cross(dir[i], dir[j]), up);
            const bool opposite = v3_dot(dir[i], dir[j]) < 0.0f && fabsf(s) <= 1e-3f;
            if (s < 0.0f || opposite) left = false;
            if (s > 0.0f || opposite) right = false;
        }
        if (left || right) return false;
    }
    return true;
}

/* Where the body's own ball, at the foot, rests on the pieces drop_off_level found from an
 * edge ahead (the ball moved a radius across up from that edge, behind the foot): placed on
 * the floor under the foot (floor_gap below it), its contacts at or below the level found
 * (level, over the foot; not the edge ahead, higher, in the step zone) and above that floor
 * are those pieces' nearest parts; resting on one l across up from the foot, the ball's
 * lowest point is r - sqrt(r^2 - l^2) under it. The highest such rest over the foot, or
 * false when the ball there touches none of them (it rests on the floor). around (when
 * asked): those contacts hold the ball from all sides, two or more whose directions across
 * up (their normals') leave no gap of 180 degrees or more (dirs_around): it cannot roll off
 * them down onto the floor. under (when given): the floor's plane is no side either (as in
 * hole_around): under a tilted up the ball lowered onto it touches it off the foot's column,
 * a contact above the foot's floor level, leaning across up (soak s30 l188, below). */
static bool rest_at_foot(const cb_ctx_t *c, fm_vec3_t foot, float floor_gap, float level, const coll_ray_hit_t *under,
                         float *rest, bool *around)
{
    const fm_vec3_t up = c->up;
    const float r = c->radius, tol = cb_len_tol(c, CB_STEP_EPS);
    coll_contact_t ct[CB_BALL_CONTACTS];
    fm_vec3_t dir[CB_BALL_CONTACTS];
    const uint32_t n = cb_ball_overlaps(c, v3_madd(foot, up, r - floor_gap), r, ct);
    uint32_t m = 0;
    bool found = false;
    *rest = 0.0f;
    for (uint32_t i = 0; i < n; i++) {
        const fm_vec3_t d = v3_sub(ct[i].point, foot);
        const float h = v3_dot(d, up), l2 = v3_len2(v3_reject(d, up));
        if (!v3_finite(ct[i].normal) || !(v3_dot(ct[i].normal, up) > 0.02f) || !(h <= level + tol) ||
            !(h + floor_gap > tol) || !(l2 < r * r) ||
            (under && fabsf(v3_dot(v3_sub(ct[i].point, under->point), under->normal)) <= c->contact_eps))
            continue;
        const float hr = h - (r - sqrtf(r * r - l2));
        if (!found || hr > *rest) *rest = hr;
        found = true;
        const fm_vec3_t s = v3_reject(ct[i].normal, up);
        if (v3_len2(s) > 1e-6f) dir[m++] = v3_norm(s); /* (a face right under the centre: no side) */
    }
    if (around) *around = m >= 2 && dirs_around(c, dir, m);
    return found;
}

/* rest_at_foot at the level of contact h, answered only where the contacts hold the ball
 * from all sides (around): the body's own ball at the foot rests there, *rest over the
 * foot. ball_held's looks after its drop went astray (foot40, foot63, foot67) all ask it. */
static bool surrounded_at_foot(const cb_ctx_t *c, fm_vec3_t foot, float floor_gap, const coll_sweep_hit_t *h,
                               float *rest)
{
    bool around = false;
    return rest_at_foot(c, foot, floor_gap, v3_dot(v3_sub(h->point, foot), c->up), NULL, rest, &around) && around;
}

/* rest_at_foot at the level the foot was at before the step (pos: the body now), answered only
 * where the contacts hold the ball from all sides (around): what the foot went down past this
 * step, never higher than where it was (as edges_over_foot); under: rest_at_foot's (the floor's
 * own plane no side). ball_held's looks where its slide past a steep first contact ran into a
 * wall (foot78) or its drop slid onto the floor under the foot (foot77) ask it. */
static bool surrounded_below_old_foot(const cb_ctx_t *c, fm_vec3_t pos, fm_vec3_t foot, float floor_gap,
                                      const coll_ray_hit_t *under, float *rest)
{
    bool around = false;
    return rest_at_foot(c, foot, floor_gap, v3_dot(v3_sub(owner_position(c->body), pos), c->up), under, rest,
                        &around) &&
           around;
}

/** The point of a gathered triangle's box closest to o (both relative to the gather's origin). */
static inline fm_vec3_t box_closest(const coll_gather_tri_t *t, fm_vec3_t o)
{
    return v3(f_min(f_max(o.x, t->lo.x), t->hi.x), f_min(f_max(o.y, t->lo.y), t->hi.y),
              f_min(f_max(o.z, t->lo.z), t->hi.z));
}

/** ball_in_hole's surround test on the contacts ct[0..n) of the ball lowered in the hole: with
 *  the first contact's direction `side`, three or more directions across up leaving no gap of
 *  180 degrees or more. */
static bool hole_around(const cb_ctx_t *c, fm_vec3_t side, const coll_ray_hit_t *under, const coll_contact_t *ct,
                        uint32_t n, fm_vec3_t *dir /* n + 1 */)
{
    const fm_vec3_t up = c->up;
    uint32_t m = 0;
    /* the contact the ball rests on (ball_held's first): lowered half a radius below it,
     * the ball meets a taller piece's edge it first touched on that piece's side, its
     * normal no longer under the ball (soak s5 l30: a hole between pieces 0.17 and 0.50 m
     * high under a tilted up, that edge the only contact on its side) */
    dir[m++] = side;
    for (uint32_t i = 0; i < n; i++) {
        if (!v3_finite(ct[i].normal) || !(v3_dot(ct[i].normal, up) > 0.02f)) continue; /* not under the ball */
        /* the plane the foot is over is no side of a hole (the next tread down, and its
         * triangles' edges, under a ball lowered between two nosings) */
        if (under && fabsf(v3_dot(v3_sub(ct[i].point, under->point), under->normal)) <= c->contact_eps) continue;
        fm_vec3_t d = v3_reject(ct[i].normal, up);
        if (!(v3_len2(d) > 1e-6f)) continue; /* a face right under the centre: no side */
        dir[m++] = v3_norm(d);
    }
    if (m < 3) return false;
    return dirs_around(c, dir, m); /* a gap of more than 180 degrees: not a hole */
}

/**
 * The crack rule's ball held in a hole between three or more pieces (tile corners around a
 * gap, blocks of different heights): its roll from the first contact meets nothing, or
 * nothing it can stand on, but the ball (centre bc, resting on that contact, side: the
 * contact's direction across up, from it towards the centre) rests on edges all around it:
 * three or more contacts within a tenth of a radius whose directions across up leave no gap
 * of 180 degrees or more. It cannot roll out without climbing: a hole, not a ledge (soak s3
 * l94, l283, s2 l273, oa_dm5 l29). A stair's nosing under the ball as the foot steps off it
 * is the same first contact, so the gathered triangles tell it from a hole before any
 * query: a hole has a piece beyond the centre, within reach of the ball (a nosing has the
 * next tread a rise below).
 */
static bool ball_in_hole(const cb_ctx_t *c, fm_vec3_t bc, fm_vec3_t side, const coll_ray_hit_t *under)
{
    const fm_vec3_t up = c->up;
    const float reach = c->radius;
    const coll_gather_t *g = c->gather;
    /* under: a floor the foot is over; a steep face the foot ray found (wall_under_crack's)
     * is none, and its plane holds the edges of the piece it is the side of (soak s5 l30) */
    if (under && !(v3_dot(under->normal, up) >= c->body->cos_floor_max_angle)) under = NULL;
    if (g && g->valid) {
        const fm_vec3_t o = v3_sub(bc, g->origin);
        bool beyond = false;
        for (uint16_t i = 0; i < g->ntris && !beyond; i++) {
            const coll_gather_tri_t *t = &g->tris[i];
            /* its box reaches beyond the centre, and within reach of it */
            fm_vec3_t far = v3(side.x > 0.0f ? t->hi.x : t->lo.x, side.y > 0.0f ? t->hi.y : t->lo.y,
                               side.z > 0.0f ? t->hi.z : t->lo.z);
            if (!(v3_dot(v3_sub(far, o), side) > 0.0f)) continue;
            fm_vec3_t q = box_closest(t, o);
            if (!(v3_len2(v3_sub(q, o)) <= reach * reach)) continue;
            /* and is no part of the floor the foot ray found (the next tread down under a
             * ball over a nosing): a triangle in its plane */
            beyond = true;
            if (under) {
                fm_vec3_t n = v3_cross(t->e1, t->e2);
                float nn = v3_len(n);
                beyond = !(fabsf(v3_dot(n, under->normal)) > 0.999f * nn &&
                           fabsf(v3_dot(v3_sub(v3_add(t->w0, g->origin), under->point), under->normal)) <= c->contact_eps);
            }
        }
        if (!beyond) return false;
    }
    /* (one contact per point and normal: near copies of a slab, each edge met by several
     * triangles, filled the deepest 16 with copies, and a tile's edge on the hole's other
     * side, shallower, was dropped; the rest lay on one side, no hole, and the foot stood on
     * the floor 61 mm under the ball resting on the slab's edge, the tile's and a second
     * slab's corner: soak s47 l73) */
    coll_contact_t ct[CB_BALL_CONTACTS];
    const uint32_t n = cb_ball_overlaps(c, bc, reach, ct);
    fm_vec3_t dir[CB_BALL_CONTACTS + 1];
    return hole_around(c, side, under, ct, n, dir);
}

/* ball_held's hole test again, over a floor: where the ball lowered half a radius below its
 * first contact (*bc) went through the floor under the foot (`floor_gap` below the foot), the
 * same ball with its bottom on that floor. A piece's side edge rising beside the ball touches
 * the ball lowered past the floor above its centre (no side of a hole), the one at the floor
 * below it. Walking into a bay of tiles 0.22-0.23 m high (r 0.67, step 0.18: the sweep
 * capsule's ball on the north tile's edge 22 mm ahead, too level to roll off towards
 * anything but a ramp's steep side), the ball lowered 0.11 m into the room floor met the
 * ramp's side edge, east of the foot, above its centre; the tiles' edges north, west and
 * north-east left a gap of 182 degrees across up, no hole, and the foot stood 131 mm under the
 * ball resting on the west tile's corner with that ramp edge opposite (soak s71 l422).
 * So too where the lowered ball stopped short of the floor, for a first contact almost under
 * the ball's centre (n.up > 0.99, piece_beyond's bound): a lower side of the hole far across
 * up touches only a ball lower than half a radius under the first contact. Running (r 0.37,
 * step 0.53) on the room floor into a pocket 0.58 m wide between a single-sided ramp's free
 * top edge, 0.196 m high 0.31 m west of the foot, and a tile's corner 0.242 m high east of
 * it, a tile 0.258 m high 46 mm ahead: the first contact was that tile's edge, 0.993 along
 * up; lowered half a radius the ball, its bottom 73 mm over the floor, met only the tiles
 * (north and east), no hole, and the foot stood on the floor 25.6 mm under the ball resting
 * on the ramp's edge with the corner opposite (soak s76 l68). On the floor it meets the
 * ramp's edge too. Out of line: a rare path (ball_in_hole has failed over a floor). False
 * where the lowered ball is on the floor already (nothing to try again). */
static __attribute__((noinline)) bool hole_at_floor(const cb_ctx_t *c, fm_vec3_t foot, float floor_gap, float n1u,
                                                    fm_vec3_t *bc)
{
    const float below = -floor_gap - (v3_dot(v3_sub(*bc, foot), c->up) - c->radius), tol = cb_len_tol(c, CB_STEP_EPS);
    /* (through the floor: n.up > 0.995, as s71 l422's 0.998; short of it: > 0.99, s76 l68's
     * 0.993. For any first contact, the console's stairs course paid +0.39 %) */
    if (below > tol ? !(n1u > 0.995f) : !(below < -tol && n1u > 0.99f)) return false;
    *bc = v3_madd(*bc, c->up, below);
    return true;
}

/** ball_held's answer: the ball rests on its first contact h1 (lowest contact `contact`
 *  above the foot, within reach), the body `gap` below where it is; far: its other contact. */
static bool held_at(float contact, float reach, float gap, fm_vec3_t normal, fm_vec3_t far,
                    const coll_sweep_hit_t *h1, support_t *out, fm_vec3_t *far_out)
{
    if (-contact > reach) return false;
    out->found = true;
    out->steep = false;
    out->gap = gap;
    out->normal = normal;
    out->point = h1->point;
    out->id = h1->id;
    out->instance = h1->instance;
    if (far_out) *far_out = far; /* the ball's other contact (its roll's end) */
    return true;
}

/**
 * Two contacts (normals n1, n2, from each contact to the ball's centre) hold the ball in a
 * groove that runs at a slope to up: the groove's line (n1 x n2, along which the ball keeps
 * both contacts) rises against up no more steeply than a walkable floor, and within the
 * plane of the two normals (up with its part along that line taken out) they lie on either
 * side of up. With up at right angles to the groove that is ball_held's wedge test (sides
 * across up opposite). Under an up tilted along a crack, both normals of a ball resting on
 * the crack's two level edges lean the same way across up (the crack rises along up like a
 * ramp, 26 degrees here), so the plain test saw no wedge: the rule gave up and the foot stood
 * on a low block 0.23 m down in the crack (soak s21 l216: r 0.26, up 27 degrees off y
 * along an 11 cm crack between blocks 0.29 m high). Only asked where the plain test fails.
 */
static bool groove_wedge(const cb_ctx_t *c, const coll_sweep_hit_t *h1, const coll_sweep_hit_t *h2)
{
    const fm_vec3_t n1 = h1->normal, n2 = h2->normal;
    const fm_vec3_t t = v3_cross(n1, n2);
    const float tl = v3_len(t);
    if (!(tl > 1e-3f)) return false; /* one normal: no groove */
    const fm_vec3_t u = v3_madd(c->up, t, -v3_dot(t, c->up) / (tl * tl));
    const float ul = v3_len(u);
    if (!(ul >= c->body->cos_floor_max_angle)) return false; /* a groove too steep to stand in */
    const fm_vec3_t un = v3_scale(u, 1.0f / ul);
    const fm_vec3_t s1 = v3_reject(n1, un), s2 = v3_reject(n2, un);
    /* (a normal within 3 degrees of up has no side: its direction across is rounding) */
    if (!(v3_len2(s1) > 0.0025f) || !(v3_len2(s2) > 0.0025f)) return false;
    /* the two contacts at one level along that up (as ball_held's "at one level", a tenth
     * of a radius): the groove's two edges, not an edge and the floor the roll went down
     * onto beside a block (soak s22 l271: up 18 degrees off y, the room floor 0.41 m under
     * the block's edge; held at the edge's height, the foot stood 127 mm inside a hole) */
    if (!(fabsf(v3_dot(v3_sub(h2->point, h1->point), un)) <= 0.1f * c->radius)) return false;
    return v3_dot(v3_norm(s1), v3_norm(s2)) < -0.05f;
}

/* A contact the crack rule's roll met that is too steep to stand on and not on a face (a taller
 * piece's top edge), beside the roll: its normal across up not against the roll's way across
 * (ball_held's wedge test, -0.05, says no wedge). As a wall's face there, it stops the roll
 * before the gap's far side, and the ball rolls on along it. Running along a 0.47 m crack
 * between two blocks 0.29 m high (r 0.39, walkable to 37.8 degrees) into its dead end, a
 * block 0.49 m high lying across it, the drop met that block's top edge, slid past it onto the
 * near block's edge, and the roll from there into the crack met the same top edge again
 * (0.42 along up, at right angles to the roll): no wedge, no hole, the rule gave up and the
 * foot stood on the room floor in the crack, 54 mm under the ball resting on both edges (soak
 * s72 l418). A steep edge against the roll is the gap's far side (the wedge test decides). */
static bool steep_edge_beside(const cb_ctx_t *c, const coll_sweep_hit_t *h, fm_vec3_t across)
{
    const fm_vec3_t s = v3_reject(h->normal, c->up);
    return v3_dot(h->normal, c->up) < c->body->cos_floor_max_angle && v3_dot(s, across) >= -0.05f * v3_len(s) &&
           !floor_face(c, h);
}

static void edges_over_foot(const cb_ctx_t *c, fm_vec3_t pos, bool highest, support_t *s); /* (below) */

/* The contact h lies on the plane of the floor the foot ray found under the foot (under; none:
 * false): its normal within 2.6 degrees of that floor's, its point within half the step
 * tolerance of its plane (ball_held: soak s45 l366, s61 l294, s133 l423). */
static inline bool on_floor_plane(const cb_ctx_t *c, const coll_ray_hit_t *under, const coll_sweep_hit_t *h)
{
    return under && v3_dot(under->normal, h->normal) > 0.999f &&
           fabsf(v3_dot(v3_sub(under->point, h->point), under->normal)) < cb_len_tol(c, 0.5f * CB_STEP_EPS);
}

/* h2 lies on the straight edge the ball touches at h1, further along it: both contact
 * normals are at right angles to that edge, so the line through h1 along their cross
 * product passes through h2 (within the skin: the far side's own test, below, asks more
 * than a skin across, so under an up square to the edges a parallel edge beyond a gap is
 * never taken for this one). Such a contact is no far side of a gap: a ball is not held
 * between two points of one straight edge. Normals within about half a degree of each
 * other give no line: false (as before). */
static inline bool on_edge_line(const cb_ctx_t *c, const coll_sweep_hit_t *h1, const coll_sweep_hit_t *h2)
{
    const fm_vec3_t e = v3_cross(h1->normal, h2->normal);
    const float el = v3_len(e);
    if (!(el > 1e-2f)) return false;
    return v3_len(v3_reject(v3_sub(h2->point, h1->point), v3_scale(e, 1.0f / el))) <= c->skin;
}

/* hole_only: the ball is held only in a hole (ball_in_hole), its roll is not looked at
 * (piece_beyond let a body standing on the floor under its foot through). past_side: with no floor
 * under the foot too (wall_under_crack's: the foot ray found a steep face through the gap),
 * the drop slides down past a wall face the ball leans on (drop_past_side); not past an
 * edge, which may be a hole's side (soak s5 l30), nor a face the ball fell onto. */
static bool ball_held(const cb_ctx_t *c, fm_vec3_t pos, float reach, const coll_ray_hit_t *under, float floor_gap,
                      const coll_sweep_hit_t *first, float first_len, bool hole_only, bool past_side, support_t *out,
                      fm_vec3_t *far_out)
{
    const bool over_floor = floor_gap < 1e29f;
    const char_body_t *b = c->body;
    const fm_vec3_t up = c->up;
    const float r = c->radius, len = c->step + reach + 0.5f * r;
    const fm_vec3_t foot = cb_foot(c, pos);
    fm_vec3_t b0 = ball_drop_start(c, pos);
    coll_sweep_hit_t h1;
    if (first_len > 0.0f) {
        /* the first look dropped the ball from b0 too and met *first: the same first contact */
        h1 = *first;
        h1.t = first->t * first_len / len;
        if (!(h1.t <= 1.0f)) return false;
    } else if (!ball_drop(c, pos, b0, len, &h1, false)) {
        return false;
    }
    if (!isfinite(h1.t) || !v3_finite(h1.normal) || !v3_finite(h1.point)) return false;
    float n1u = v3_dot(h1.normal, up);
    if (!(h1.t > 0.0f) && h1.depth > 0.0f && h1.depth < c->skin && fabsf(n1u) <= 0.02f && first_len <= 0.0f &&
        drop_off_wall(c, &b0, len, &h1))
        n1u = v3_dot(h1.normal, up);
    float d1 = h1.t > 0.0f ? h1.t * len : 0.0f;
    /* Over a floor, a wall along up that the ball touches beside it (its normal across up)
     * does not stop the drop: the ball slides down along it (drop_past_side) onto what is
     * under it (soak s9 l92: the end face of a V valley's slope beside the ball, the foot
     * gone down the slot between the slopes, 181 mm below their edges) */
    if (over_floor && fabsf(n1u) <= 0.02f && drop_past_side(c, &b0, len, &h1, &d1)) n1u = v3_dot(h1.normal, up);
    if (!(n1u > 0.02f)) return false; /* not under the ball */
    /* Resting on the very plane the foot ray found out of reach below the foot: the body
     * hovers over a slope (its capsule is too wide for it), it is not over a gap. (The
     * contact's distance from that plane along the plane's normal: on the shared edge of
     * two coplanar triangles the contact normal is 0.3 degrees off, and along it a point
     * 0.6 m away on the same plane was 1.9 mm off it; the rule lifted a body walking on a
     * slope too steep for its capsule 0.27 m off it, and it fell.) Within half the step
     * tolerance, not 1e-3 (1 + r): a tile 1.3 mm over the floor is another plane, and the
     * ball in a 19 mm crack between two such tiles rests on their edges; taken for the
     * floor's plane (r 0.72: 1.72 mm), the foot stood on the floor in the crack, 1.09 mm
     * under the ball resting on both (soak s45 l366). */
    if (on_floor_plane(c, under, &h1)) return false;
    /* (past_side: once, off a wall face the ball leans on at the drop's start, within
     * CB_MARGIN across it) */
    const bool slide = over_floor || (past_side && n1u < b->cos_floor_max_angle &&
                                      d1 * n1u <= cb_len_tol(c, CB_MARGIN) && steep_face(c, &h1));
    bool slid_past_steep = false; /* the loop slid the ball past a steep first contact (below) */
    bool slid_into_wall = false;  /* ... into a wall, and went back to that contact (below) */
    for (int k = 0; k < (over_floor ? 2 : 1) && slide && n1u < b->cos_floor_max_angle; k++) {
        const coll_sweep_hit_t h0 = h1;
        const float d0 = d1, n0u = n1u;
        const fm_vec3_t b0_0 = b0;
        if (!drop_past_side(c, &b0, len, &h1, &d1)) break;
        slid_past_steep = true;
        n1u = v3_dot(h1.normal, up);
        /* Over a floor, the second slide, off a steep edge (not a face) the first slide down
         * a wall met, went straight back into a wall's face, no lower: the slid ball sits in
         * the groove between that wall and the edge, beside the foot, and says nothing about
         * it. The body's own ball at the foot decides, as below (rest_at_foot, around). Under
         * an up 5.3 degrees off y a wall 87 degrees off up leaning under the body (in the
         * step zone: the full ball at the foot 31 mm in it) took the drop first, its slide
         * met a 0.53 m block's top edge 52.6 degrees off up, and the slide off that edge went
         * back into the wall: the rule gave up, the snap to the room floor stopped on the
         * wall, and the foot stood 10.2 mm under the ball resting on a 0.29 m block's corner
         * and the taller block's edge, 180 degrees apart across the foot (soak s95 l293). */
        if (over_floor && k == 1 && !(d1 > d0) && steep_face(c, &h1) && !steep_face(c, &h0)) {
            float rest = 0.0f;
            if (surrounded_at_foot(c, foot, floor_gap, &h0, &rest))
                return held_at(rest, reach, -rest, up, h0.point, &h0, out, far_out);
        }
        /* Over a floor, slid past a steep first contact out of the foot's column (more than
         * a radius across up) onto the very floor the foot ray found under the foot: the
         * slid ball says nothing about the foot (the body is not moved across, and the snap
         * to that floor stops on the same contact). When the body's own ball at the foot,
         * lowered onto that floor, meets pieces above it that hold it from all sides (their
         * directions across up leave no gap of 180 degrees: rest_at_foot's around, the
         * surround test of hole_around), it cannot roll off them down to the floor: it
         * rests on them, where rest_at_foot says (foot40's rule). Pieces on one side only
         * (a slope's low edge beside the foot) do not hold it: it rolls off them onto the
         * floor, and the old path runs (the foot stands on the floor or falls). A tall
         * ramp's top edge 1.22 m over the foot, 0.38 m behind it, held the sweep capsule's
         * bottom ball; the slide down that edge's tangent went 0.96 m across up, out of the
         * open end of a V valley's 0.13 m slot between two 18-degree ramps the foot was in,
         * onto the room floor: the rule gave up, the snap to that floor stopped on the edge,
         * and the foot stood 25 mm under the ball resting on both ramps (soak s61 l294). */
        if (over_floor && k == 0 && on_floor_plane(c, under, &h1) &&
            v3_len2(v3_reject(v3_sub(b0, b0_0), up)) > r * r) {
            float rest = 0.0f;
            if (surrounded_at_foot(c, foot, floor_gap, &h0, &rest))
                return held_at(rest, reach, -rest, up, h0.point, &h0, out, far_out);
        }
        /* Over a floor, the slide past a steep contact ran into a wall beside the ball (a
         * face along up): the wall stops it, the ball stays on that contact and the roll
         * below decides (it rolls on along a wall). In a crack 1.13 m wide between two
         * blocks 0.44 m high (r 0.86, floor angle 40.6 degrees) both edges hold the ball
         * 41.4 degrees off up, steeper than walkable; at the crack's mouth against the room
         * wall the slide off one edge met the wall, the rule gave up, and the foot stood on
         * the floor in the crack, 221 mm under the ball resting on both (soak s15 l315). */
        if (over_floor && !(n1u > 0.02f) && n1u > -0.1f) {
            /* ... unless the ball, held against that wall by the contact it slid off, slides
             * down the groove between the two onto a floor's face (soak s25 l233). A taller
             * piece's edge along up (its vertical corner: no face) is such a wall for that
             * groove too. Walking (r 0.78, step 0.57) off a tile field's edge (tops 0.097)
             * towards a staircase's top block (0.655 high, 0.69 m across up), a ramp's
             * vertical corner 6 mm beside the ball: the slide down the block's top edge met
             * that corner at once, the rule gave up, and the foot stood on the room floor
             * 67 mm under the ball resting on the tiles' edges and the block's (soak s103
             * l399). Down the groove between the two the ball lands on the tile's top. */
            const fm_vec3_t g = v3_cross(h0.normal, h1.normal);
            const float gl = v3_len(g), gu = v3_dot(g, up);
            fm_vec3_t b0g = b0;
            coll_sweep_hit_t hg = h1;
            float d1g = d1;
            if (gl > 1e-3f &&
                slide_down(c, &b0g, len, v3_scale(v3_add(h0.normal, h1.normal), 0.2f * c->skin),
                           v3_scale(g, (gu > 0.0f ? -1.0f : 1.0f) / gl), &hg, &d1g) &&
                floor_face(c, &hg) && v3_dot(hg.normal, up) > 0.02f) {
                /* ... and where the groove took it out of the foot's column (more than a
                 * radius across up) down to the very floor under the foot, the slid ball says
                 * nothing about the foot either: the body's own ball decides, as below where
                 * the groove goes nowhere (soak s133 l2's walk on, down the crack between two
                 * tiles: the groove off the ramp's face and a staircase block's vertical
                 * corner ended on the room floor beyond the tile field, 1.5 m away) */
                float rest = 0.0f;
                if (on_floor_plane(c, under, &hg) && v3_len2(v3_reject(v3_sub(b0g, foot), up)) > r * r &&
                    surrounded_below_old_foot(c, pos, foot, floor_gap, NULL, &rest))
                    return held_at(rest, reach, -rest, up, h0.point, &h0, out, far_out);
                b0 = b0g;
                h1 = hg;
                d1 = d1g;
                n1u = v3_dot(h1.normal, up);
                break;
            }
            if (!steep_face(c, &h1)) return false; /* (an edge: the groove only, else as before) */
            slid_into_wall = true;
            h1 = h0;
            d1 = d0;
            n1u = n0u;
            b0 = b0_0;
            break;
        }
        if (!(n1u > 0.02f)) return false;
        /* Over a floor, slid down past a higher piece's edge (not a wall face) onto a
         * walkable face leaning back towards it, within half a radius of descent and a
         * diameter across up: the two hold the ball between them, a wedge, as the roll
         * along the edge's tangent finds it when there is no floor under the foot. The
         * ball rests on the edge (the higher contact), as there. Rolled on down that face
         * the ball went out of the wedge's open end, beside the edge's piece, onto the
         * floor under the foot, and the foot stood on it, 95 mm inside both (soak s10
         * l392: a block's corner 0.48 m high and a stair's tread 15 degrees off up, half
         * under the floor, 176 degrees apart around the foot; the frame before, landing
         * with no floor in reach, the roll held the ball in that wedge). */
        if (over_floor && k == 0 && n1u >= b->cos_floor_max_angle && !steep_face(c, &h0)) {
            const fm_vec3_t s0 = v3_reject(h0.normal, up), s1 = v3_reject(h1.normal, up);
            const float l0 = v3_len(s0), l1 = v3_len(s1);
            const float c0 = v3_dot(v3_sub(h0.point, foot), up), c1 = v3_dot(v3_sub(h1.point, foot), up);
            if (l1 > 1e-3f && v3_dot(s0, s1) < -0.05f * l0 * l1 && d1 - d0 <= 0.5f * r &&
                v3_len(v3_reject(v3_sub(h1.point, h0.point), up)) < 2.0f * r &&
                -c1 <= floor_gap - cb_len_tol(c, CB_STEP_EPS)) {
                fm_vec3_t wn = v3_norm(v3_add(h0.normal, h1.normal));
                if (v3_dot(wn, up) < b->cos_floor_max_angle) wn = up;
                return held_at(f_min(c0, c1), reach, d0 - c->step, wn, h1.point, &h0, out, far_out);
            }
        }
    }
    /* the walkable contact that slide ended on, for the look at the give-up (below) */
    const bool slid_onto = over_floor && slid_past_steep && n1u >= b->cos_floor_max_angle;
    const coll_sweep_hit_t landed = h1;
    int past = 0; /* drops past a first contact beside the sweep capsule (below) */
    bool rolled_off = false; /* dropped on past the first contact its roll fell off (below) */
    bool slid_far = false; /* that drop went out of the foot's column (below) */
again:;
    float contact = v3_dot(v3_sub(h1.point, foot), up); /* lowest contact height above the foot */
    float c1 = contact;
    float gap = d1 - c->step; /* resting on the first contact (the body is not moved sideways) */
    fm_vec3_t normal = h1.normal, far = h1.point;
    fm_vec3_t tangent = v3_madd(v3_scale(up, -1.0f), h1.normal, n1u); /* length: sine of the tilt */
    if (v3_len(tangent) > 1e-4f) { /* else a face right under the centre: held */
        fm_vec3_t downhill = v3_norm(tangent);
        /* lifted off the first contact by more than the queries' touch tolerance */
        fm_vec3_t b1 = v3_madd(v3_madd(b0, up, -d1), h1.normal, 0.2f * c->skin);
        if (hole_only) /* no groove's side (level_beyond): no roll */
            goto hole;
    roll:;
        coll_sweep_hit_t h2;
        fm_vec3_t across = v3_norm(v3_reject(downhill, up));
        /* Resting on an edge almost under its centre the tangent barely descends: rolled
         * along it by a diameter the ball would pass over the far side of a gap a few
         * millimetres lower than this edge (a tile beside a tile, a block beside a block)
         * and meet whatever stands beyond (a ramp a metre away). */
        bool flat = n1u > 0.995f && v3_len(across) > 0.5f;
        /* The roll counts only within half a radius of descent (below), so on a tilted
         * contact it ends there: a shorter sweep meets fewer triangles and stays inside the
         * step's gathered box more often (tilts under 0.25, flat ones among them, keep the
         * whole diameter). */
        float sink = -v3_dot(downhill, up);
        float roll = 2.0f * r;
        if (sink > 0.25f) roll = f_min(roll, 0.5f * r * 1.01f / sink + c->skin);
        const fm_vec3_t way = v3_scale(downhill, roll);
        coll_gather_above_t plane;
        bool walled = false; /* the roll met a wall and rolled on along it (below) */
        bool met = !flat && (roll_above(c, b1, way, &h1, &plane) ? cb_sweep_above(c, b1, r, 0.0f, way, &plane, &h2)
                                                                 : cb_sweep(c, b1, r, 0.0f, way, &h2));
        float descent = met ? (h2.t > 0.0f ? h2.t : 0.0f) * roll * sink : 0.0f;
        if (over_floor && met && isfinite(h2.t) && v3_finite(h2.normal) && v3_dot(h2.normal, up) > -0.1f &&
            (steep_face(c, &h2) || steep_edge_beside(c, &h2, across))) {
            /* Over a floor, a wall the ball touches beside it (a body against a room wall or
             * a block's side over a crack) stops the roll before the gap's far side: the ball
             * rolls on along the wall (soak s2 l333, s3 l3, l172: held by nothing, the foot
             * stood on the floor under the crack, 0.1-0.2 m inside both sides). With no
             * floor under the foot, the wall holds the ball with the edge (the slot between
             * a ledge and a wall), as before. */
            float t = h2.t > 0.0f ? h2.t : 0.0f;
            fm_vec3_t rest = v3_scale(downhill, roll * (1.0f - t));
            rest = v3_madd(rest, h2.normal, -v3_dot(rest, h2.normal));
            fm_vec3_t bw = v3_madd(v3_madd(b1, downhill, roll * t), h2.normal, 0.2f * c->skin);
            coll_sweep_hit_t h3;
            if (v3_len(rest) > c->tiny && cb_sweep(c, bw, r, 0.0f, rest, &h3) && isfinite(h3.t) &&
                v3_finite(h3.normal) && !steep_face(c, &h3)) {
                descent += (h3.t > 0.0f ? h3.t : 0.0f) * -v3_dot(rest, up);
                h2 = h3;
                walled = true;
            }
        }
        /* An edge nearly under the centre (tilted less than asin sqrt 0.1 = 18 degrees: too
         * level for drop_past_side's slide too), whose roll met nothing: the ball rolled
         * along a nearly level tangent over the far side of the gap, which lies lower than
         * the roll went, and on into nothing. It rolls off the edge and drops: as off a
         * flat edge, moved off across up by a radius and dropped by half a radius, it meets
         * that far side, when it is a floor's face (soak s13 l221: r 0.53, the foot 6 cm off the
         * end of a 0.39 m block at a crack's mouth, a tile 0.17 m high 0.24 m ahead, the
         * contact 0.993 along up; the foot stood on the floor between them, 108 mm under the
         * ball resting on both). Not a roll along the body's motion: walking down stairs,
         * the nosing just left is such an edge every few steps, the ball rolls over the next
         * nosing and meets nothing; its move and drop (outside the step's gathered box: on
         * the scene) cost the bench's stairs 7 %. */
        const bool level_off = !met && !flat && n1u * n1u >= 0.9f && v3_len(across) > 0.5f &&
                               !(v3_dot(across, b->velocity) > 0.0f);
        if (level_off) flat = true;
        if (flat) {
            /* The ball would roll off it and drop: move it off across up by a radius, then
             * down by half a radius; the far side of such a gap is met on the way. What
             * the move across meets above this edge's level (a wall, a taller block
             * beyond the gap) is not that far side: the ball drops from where it stopped. */
            fm_vec3_t off = v3_scale(across, r);
            met = cb_sweep(c, b1, r, 0.0f, off, &h2);
            if (met && isfinite(h2.t) && v3_dot(v3_sub(h2.point, foot), up) > c1 + 0.1f * r) {
                float t = h2.t * r - c->skin;
                off = v3_scale(across, t > 0.0f ? t : 0.0f);
                met = false;
            }
            if (!met && cb_sweep(c, v3_add(b1, off), r, 0.0f, v3_scale(up, -0.5f * r), &h2)) {
                met = true;
                descent = (h2.t > 0.0f ? h2.t : 0.0f) * 0.5f * r;
                /* Over a floor, the drop a radius across met the floor under the foot: the
                 * far side of the gap may be a piece narrower than a radius, passed over by
                 * the move. Moved a half and then a quarter radius across, the drop meets it
                 * (soak s33 l1: an 18 mm crack between tiles 44 and 29 mm high, the lower
                 * one 0.6 m wide, r 0.98; the foot stood on the floor in the crack, 29 mm
                 * under that tile's top, the ball held in no hole: the edges are parallel).
                 * Only what the drop meets beyond the first contact (across it, by more than
                 * the skin) is such a far side: moved a quarter radius off an edge 47 mm over
                 * the floor, the ball dropped back onto that very edge (0.97 along up), was
                 * held on it, and the body, not lifted there, hung at rest 18.5 mm over the
                 * floor, not grounded (soak s36 l164, r 0.64); a shorter move meets it too.
                 * Nor a point further along that same straight edge (on_edge_line): under an
                 * up 4.2 degrees off y the edge of a slab 94 mm high rises against up, and
                 * the move "across" off it (0.997 along up, its across-up part mostly the
                 * tilt) ran 52 degrees along the edge; the half-radius drop met the edge
                 * again 0.17 m on, taken for a crack's far side. The body, its foot on the
                 * room floor 2 cm beside the slab, was held at the slab's top, had no room
                 * for that lift (its top ball on the room wall), and hung at rest 7.7 mm
                 * over the floor for ever (soak s132 l377). */
                for (int k = 0; k < 2 && over_floor && isfinite(h2.t) && v3_finite(h2.point) &&
                                -v3_dot(v3_sub(h2.point, foot), up) > floor_gap - cb_len_tol(c, CB_STEP_EPS);
                     k++) {
                    coll_sweep_hit_t hk;
                    off = v3_scale(off, 0.5f);
                    if (!cb_sweep(c, v3_add(b1, off), r, 0.0f, v3_scale(up, -0.5f * r), &hk) || !isfinite(hk.t) ||
                        !v3_finite(hk.point))
                        continue;
                    if (!(v3_dot(v3_sub(hk.point, h1.point), across) > c->skin) || on_edge_line(c, &h1, &hk)) break;
                    h2 = hk;
                    descent = (h2.t > 0.0f ? h2.t : 0.0f) * 0.5f * r;
                }
            }
            /* (rolled off a nearly level edge: only a floor's face met there is the far side;
             * anything else, and the roll's answer stands) */
            if (level_off && !(met && isfinite(h2.t) && floor_face(c, &h2))) {
                met = false;
                flat = false;
            }
        }
        if (!met) {
            /* Over a floor, the ball rolled off an edge higher above it than the roll
             * descends (half a radius): it falls on past that edge, and when what it meets
             * further down is a floor's face (a tile's top around the foot), that is the
             * first contact (once; soak s10 l161: the top edge of a ledge 0.82 m over tiles
             * with 9 mm gaps between them, the foot in one, 43 mm below the tiles). Not a
             * contact ahead of the body's motion: climbing stairs, the ball rolled off the
             * nosing two risers ahead onto the next tread and lifted the foot there early,
             * over the lower tread (soak s5 l315, 14 mm in a later step). A nearly level
             * edge's tangent plane sinks too little to slide down: the ball is moved off it
             * and dropped (drop_off_level, soak s34 l341). */
            fm_vec3_t b0p = b0;
            coll_sweep_hit_t h1p = h1;
            float d1p = d1;
            /* A contact ahead of the motion counts only where the ball slides down past it
             * onto a floor's face that is not ahead of the motion (behind or beside the
             * foot): the piece the foot just walked off. Walking off a tile 0.16 m high
             * towards a ramp's low side edge 0.47 m above the foot, the ball rested on that
             * edge, ahead; slid down past it, it met the tile's top behind the foot, which
             * holds it with the edge; the rule gave up and the foot stood on the floor
             * beside the tile, 81 mm under the ball resting on both (soak s41 l275). The
             * next tread met climbing stairs lies ahead: not counted, as before. What the
             * slide meets may be another piece's walkable edge on the groove's other side
             * across up (not a face): the two edges hold the ball. Walking at 12 m/s off a
             * ramp's side (r 0.52) into a pocket between it, a second ramp's low end rising
             * the other way and a tile, the slide past the first ramp's side edge met the
             * second ramp's slope-and-side edge; the rule gave up and the foot stood on the
             * room floor, 88 mm under the ball resting on the edges (soak s42 l217).
             * Ahead across up: the velocity's part along up (a body lifted in the step,
             * landing, climbing) says nothing about which side of the foot a contact lies
             * on; in s42 l217 +2.25 m/s along up made that first ramp's edge, behind the foot
             * across up, count as ahead. From a contact ahead, the slide may also meet a
             * nearly level edge (level_edge) leaning the same way as the first contact, not
             * ahead of the motion: neither a face nor edge_across, but the ball rests on it
             * from above as on a face. Past a slab's top edge ahead the slide crossed a tile
             * and met its far edge, 53 mm over the floor (0.996 along up), or, from the foot
             * a few centimetres further on, the far corner of the tile beside it, 61 mm over
             * the floor (0.987); the rule gave up and the foot stood on the floor, 50-52 mm
             * under the ball resting on the slab's edge and the tiles (soak s52 l244). A
             * nearly level edge ahead is moved off and dropped (drop_off_level) as one
             * behind, under the same test of where the drop lands:
             * walking into a slab's side (r 0.47) over a 2 cm crack between tiles 0.25 m
             * high, the slab's top edge 0.38 m over the tiles and 11 mm across up from the
             * foot, ahead, the ball rested on it (0.9997 along up), too level to slide
             * down; the rule gave up, the snap to the room floor under the crack stopped
             * on that edge, and the foot stood 161 mm under the tiles (soak s54 l58). Moved
             * off the edge away from the slab, the ball met the tile behind the foot; the
             * body's own ball then rests where rest_at_foot says (below). */
            const fm_vec3_t vel = v3_reject(b->velocity, up);
            const bool ahead = v3_dot(v3_sub(h1.point, foot), vel) > 0.0f;
            bool level = false; /* counted as a nearly level edge (level_edge), not a face */
            bool moved_off = false; /* moved off a nearly level first contact (drop_off_level) */
            const bool level_first = n1u * n1u >= 0.9f && v3_len(across) > 0.5f;
            bool slid = false; /* drop_past_side's slide went somewhere (below) */
            if (over_floor && !rolled_off && c1 + floor_gap > 0.5f * r &&
                ((slid = drop_past_side(c, &b0p, len, &h1p, &d1p)) ||
                 (level_first &&
                  (moved_off = drop_off_level(c, b1, across, foot, floor_gap, len, &b0p, &h1p, &d1p)))) &&
                !(ahead && v3_dot(v3_sub(h1p.point, foot), vel) > 0.0f) &&
                (floor_face(c, &h1p) || edge_across(c, &h1p, &h1) || (level = ahead && level_edge(c, &h1p)))) {
                /* Moved off a nearly level edge ahead (too level to slide down past: soak s52
                 * l244, a slab's top edge 0.98 along up 0.13 m ahead of the foot, 0.41 m over
                 * tiles 0.19 m behind it): the piece found behind holds the ball, the edge
                 * ahead is a ledge in the step zone (no ball rests on both). The body's own
                 * ball at the foot rests on that piece's nearest part (rest_at_foot), not at
                 * the level found a radius across (the tile's top: 36.6 mm over the ball's
                 * rest at the foot, 24.2 mm up); touching none of it, it rests on the floor. */
                const bool off_ahead = moved_off && ahead;
                if (off_ahead) {
                    float rest = 0.0f;
                    if (!rest_at_foot(c, foot, floor_gap, v3_dot(v3_sub(h1p.point, foot), up), NULL, &rest, NULL))
                        goto hole;
                    d1p = c->step - rest;
                }
                /* A nearly level edge counts as the face it bounds: the foot stands at its
                 * level. d1p is the drop along up of the slid ball, moved across up to where
                 * the slide met the edge; resting there on the edge its lowest point, where
                 * the foot would stand, is r (1 - n.up) under it. The body is not moved
                 * across: its own ball, at the foot, rests on the same piece elsewhere, under
                 * it by r - sqrt(r^2 - l^2) for l its distance across up from the piece, not
                 * by the slid ball's sag (s52 l244: the slid ball 54 mm from the tile's far
                 * edge sags 2.35 mm; at the foot, 35 mm from the tile's corner, the checker's
                 * ball rests 0.95 mm under the tile's top; without the raise the foot stood
                 * 1.58 mm under it; the slid ball on the other tile's corner, 0.987 along up,
                 * sags 8.5 mm). The edge's level is what a foot on that face (a tile's top)
                 * stands at and the highest any ball resting on the edge reaches: the raise
                 * never puts the foot under a ball resting on the edge, and over the slid
                 * ball's rest by at most r (1 - sqrt 0.9), 5 % of a radius. */
                if (level && !off_ahead) d1p -= r * (1.0f - v3_dot(h1p.normal, up)); /* (off_ahead: exact, above) */
                slid_far = v3_len2(v3_reject(v3_sub(b0p, foot), up)) > r * r;
                /* Slid down past the first contact out of the foot's column (more than a radius
                 * across up) onto the very floor the foot ray found under the foot: the slid ball
                 * says nothing about the foot (held on that floor it holds the body nowhere above
                 * it, and the snap down to it stops on the first contact). The body's own ball at
                 * the foot decides, as after the slide past a steep contact (above, soak s61 l294),
                 * on the contacts no higher than the foot was at the step's start (as
                 * edges_over_foot: the rule never lifts the body over where it was), the floor's
                 * own plane not counted: held from all sides by them (a crack's two edges), it
                 * rests there. An edge in the step zone beside the foot is what the sweep capsule
                 * passes over, not what holds the ball at the foot. Walking (r 0.80, step 0.52) off
                 * a tile's top into an 18 mm crack beside it, a block 0.27 m across up (its top
                 * edge 0.405 m over the tiles, ahead), the drop met that edge (20 degrees off up),
                 * the roll off it met nothing, and the slide down its tangent went 1.58 m across up
                 * past the tile field's end onto the room floor; the snap to that floor stopped on
                 * the block's edge, and the foot stood 165 mm under the tiles' tops (soak s133
                 * l423). With the floor's plane counted, a body falling (r 0.23, step 1.02, up 4.9
                 * degrees off y) beside a block's vertical corner, its foot in the step zone 0.2 mm
                 * inside the block, stood 97 mm over the floor: the floor's contact, off the foot's
                 * column under the tilted up, and the block's sides "surrounded" the ball (soak s30
                 * l188, a branch run). */
                if (slid && slid_far && on_floor_plane(c, under, &h1p)) {
                    float rest = 0.0f;
                    if (surrounded_below_old_foot(c, pos, foot, floor_gap, under, &rest))
                        return held_at(rest, reach, -rest, up, h1.point, &h1, out, far_out);
                }
                b0 = b0p;
                h1 = h1p;
                d1 = d1p;
                rolled_off = true;
                n1u = v3_dot(h1.normal, up);
                if (!(n1u > 0.02f)) return false;
                goto again;
            }
            /* Slid past a contact ahead onto a walkable one ahead too, the foot over a gap
             * (not on its floor: climbing stairs the foot is on its tread, and the stairs'
             * gate above stands): the body's own ball at the foot decides, as after foot40's
             * move off an edge ahead. Held from all sides (rest_at_foot's around: a crack's
             * two edges), it rests on what it meets; on one side only, the old path runs.
             * Walking (r 0.48) across a 0.29 m crack between slabs 0.242 and 0.249 m high
             * towards the higher, beside a V valley's end: the drop met a valley block's
             * side edge first (0.59 m over the foot, 0.43 m across up, walkable), the roll
             * off it met nothing, and the slide down its tangent met the higher slab's edge,
             * ahead like the block's: not counted, the rule gave up and the foot stood on the
             * room floor in the crack, 171 mm under the ball resting on the edges (soak s113
             * l98). */
            if (slid && ahead && floor_gap > cb_len_tol(c, CB_STEP_EPS) &&
                v3_dot(v3_sub(h1p.point, foot), vel) > 0.0f && v3_dot(h1p.normal, up) >= b->cos_floor_max_angle) {
                float rest = 0.0f;
                if (surrounded_at_foot(c, foot, floor_gap, &h1p, &rest))
                    return held_at(rest, reach, -rest, up, h1p.point, &h1p, out, far_out);
            }
            goto hole; /* rolls off (a ledge), unless the ball is in a hole */
        }
        if (!isfinite(h2.t) || !v3_finite(h2.normal) || v3_dot(h2.normal, up) < -0.1f)
            return false; /* rolls into a ceiling */
        if (descent > 0.5f * r) {
            /* Over a floor, the roll went down the first contact's tangent plane onto a
             * floor's face more than half a radius below it, above the floor under the foot:
             * as drop_past_side's slide would (the same sweep), that face is the first
             * contact (once; soak s25 l380) */
            if (over_floor && !rolled_off && !flat && !walled && floor_face(c, &h2) && v3_dot(h2.normal, up) > 0.02f &&
                -v3_dot(v3_sub(h2.point, foot), up) < floor_gap - cb_len_tol(c, CB_STEP_EPS)) {
                goto roll_on;
            }
            goto hole;
        }
        far = h2.point;
        float c2 = v3_dot(v3_sub(h2.point, foot), up);
        if (c2 < contact) contact = c2;
        fm_vec3_t side1 = v3_norm(v3_reject(h1.normal, up)), side2 = v3_norm(v3_reject(h2.normal, up));
        const bool wedge = v3_dot(side1, side2) < -0.05f || groove_wedge(c, &h1, &h2);
        const bool onto_floor = !wedge && v3_dot(h2.normal, up) >= b->cos_floor_max_angle;
        /* the roll went from one side of the foot point to the other: across the groove it
         * is over (from a stair's nosing it ends on the edge of the tread just left, on the
         * same side: the foot steps down off it) */
        const bool across_foot =
            v3_dot(v3_reject(v3_sub(h1.point, foot), up), v3_reject(v3_sub(h2.point, foot), up)) < 0.0f;
        /* Over a floor the foot could step down to, the ball is held only above it (not on
         * a stair's nosings: the roll from one ends on the tread the foot is over or one
         * below it). A gap between surfaces at one level holds it (tiles, a slab beside a
         * slab); so does, at any levels, a gap narrower than the capsule between surfaces
         * on opposite sides (blocks of different heights, a valley's slopes) or a groove
         * the ball rolls across onto a floor beyond (a lower block): the foot would
         * otherwise stand at its bottom, inside both sides. */
        /* (a wall, a face too steep to stand on, is never a side of such a gap: a body
         * pushed into the corner of a floor and a wall that leans over it under a tilted up
         * stands on the floor, it is not lifted into the corner) */
        const bool narrow = wedge && v3_len(v3_reject(v3_sub(h2.point, h1.point), up)) < 2.0f * r &&
                            !steep_face(c, &h1) && !steep_face(c, &h2);
        /* (at the floor: within the step tolerance the caller's "higher than the floor"
         * uses, not the contact tolerance: a roll across a crack onto a tile 1.4 mm over
         * the floor the foot ray found through it holds the ball, soak s6 l211) */
        if (over_floor && -contact > floor_gap - cb_len_tol(c, CB_STEP_EPS)) {
            /* The roll ended at the floor more than a radius across up from the foot: out
             * of the gap the ball is over, not down into it (soak s4 l202: from a taller
             * block's edge in the step zone, 2r along a nearly level tangent, along a 0.54
             * m crack between two lower blocks and out of its mouth, 1.5 m away; the foot
             * stood on the floor 45 mm under the crack's sag). As a roll that met nothing:
             * the ball is held only in a hole. A flat first contact's "roll" is a move a
             * radius across up and a drop: one direction, far beyond the edges around the
             * ball. Under a tilted up the ball over a notch where two raised tiles meet
             * corner to corner cannot go down along up in any direction (soak s7 l291: r
             * 0.92, up 5 degrees off y, the foot on the lower tile 14 mm under the ball
             * resting on the corners); the move over the notch found the lower tile. The
             * hole rule decides then too. */
            if (flat || v3_len2(v3_reject(v3_sub(h2.point, foot), up)) > r * r) goto hole;
            return false;
        }
        if (over_floor && !narrow && !(onto_floor && across_foot) && fabsf(c1 - c2) > 0.1f * r) {
            /* Over a floor, the roll went down onto a walkable contact on the same side of
             * the foot, lower than the first by more than a tenth of a radius and above the
             * floor under the foot (an edge of a lower piece beside a higher one): the ball
             * rolls on from there, as from a floor's face more than half a radius down
             * (above), and that contact is the first (once). Given up, the foot stood on
             * nothing: the snap down to the floor under it was stopped by the higher
             * piece's corner on the sweep capsule, 0.45 m over that floor, the full ball
             * between the lower piece's edge and a slab's corner across the foot, 36 mm
             * under the ball resting on them (soak s36 l72: r 0.97, three wedge-shaped
             * prisms 0.88-1.16 m high side by side, a 0.72 m slab 0.76 m from their side).
             * Not onto a contact ahead of the body's motion: climbing stairs, the roll from
             * the nosing two risers ahead goes down onto the next one, and rolling on from
             * it (onto the tread under the foot: nothing held) cost the console's
             * stairs_real 7 %. */
            if (onto_floor && c2 < c1 && !rolled_off && !flat && !walled &&
                -c2 < floor_gap - cb_len_tol(c, CB_STEP_EPS) &&
                !(v3_dot(v3_sub(h2.point, foot), b->velocity) > 0.0f)) {
                goto roll_on;
            }
            goto hole;
        }
        if (wedge) {
            normal = v3_norm(v3_add(h1.normal, h2.normal)); /* a wedge */
            if (v3_dot(normal, up) < b->cos_floor_max_angle) normal = up;
        } else if (onto_floor && (descent <= 0.1f * r || (over_floor && across_foot))) {
            normal = h2.normal; /* rolled across a narrow crack onto the floor beyond it */
        } else {
            goto hole;
        }
        /* the same for a flat first contact whose move-and-drop went out of reach (the
         * floor beyond a notch lower than the snap reaches; over a floor, above): else a
         * body the hole rule held there on landing is not held there standing, and falls
         * back into it every other step, at rest in the air (soak s7 l293) */
        if (flat && -contact > reach) goto hole;
        return held_at(contact, reach, gap, normal, far, &h1, out, far_out);
    roll_on: { /* the roll's contact h2 becomes the first contact (once): roll on from it */
        const float t = h2.t > 0.0f ? h2.t : 0.0f;
        b0 = v3_madd(b0, v3_reject(way, up), t);
        d1 += descent;
        h1 = h2;
        h1.t = d1 / len;
        rolled_off = true;
        n1u = v3_dot(h1.normal, up);
        goto again;
    }
    hole: /* the roll found nothing to hold the ball: held only in a hole (ball_in_hole) */
        for (fm_vec3_t bh = v3_madd(b1, up, -0.5f * r);;) {
            if (ball_in_hole(c, bh, v3_norm(v3_reject(h1.normal, up)), under)) {
                if (over_floor && -c1 > floor_gap - c->contact_eps) return false;
                return held_at(c1, reach, gap, up, h1.point, &h1, out, far_out);
            }
            /* (once more with its bottom on the floor under the foot, for a first contact
             * nearly under the ball's centre, as s71 l422's, 0.998 along up, and s76 l68's,
             * 0.993: hole_at_floor) */
            if (!over_floor || !under || !(n1u > 0.99f) || !hole_at_floor(c, foot, floor_gap, n1u, &bh)) break;
        }
        if (hole_only) { /* no hole holds it: its roll may (a groove, a wedge: soak s35 l296) */
            hole_only = false;
            goto roll;
        }
        /* Over a floor, a first contact above the step zone (a stair's top nosing beside
         * the body, met by the part of the ball the sweep capsule's bottom ball covers too)
         * that the ball rolls off, down more than half a radius, holds nothing; what it
         * rolls down onto may: the ball slides down past it as past a steep side
         * (drop_past_side), and what it meets there is the first contact, at most twice
         * (soak s7 l56: a 0.5 m crack between two tiles 44 mm high beside a staircase, r
         * 0.96; the foot stood on the floor in the crack, 4 mm under the ball resting on the
         * tile edges). Not a contact ahead of the body's motion: climbing stairs, the nosing
         * two risers ahead is such a contact every few steps (the stair step climbs it),
         * and looking past it cost 17 queries in a 90-step climb (486 -> 503). A first
         * contact on a collider body (no triangle) is looked past in the step zone too
         * (soak s31 l179: a rounded body beside a crack between two slabs, the slab edges
         * 0.24 m under it). */
        if (over_floor && past < 2 &&
            ((c1 > c->step && !(v3_dot(v3_sub(h1.point, foot), b->velocity) > 0.0f)) || h1.triangle < 0) &&
            drop_past_side(c, &b0, len, &h1, &d1)) {
            past++;
            n1u = v3_dot(h1.normal, up);
            if (!(n1u > 0.02f)) return false;
            goto again;
        }
        /* Over a floor, the drop past the contact the roll fell off went out of the foot's
         * column (more than a radius across up): what the slid ball met says nothing about
         * the foot, and neither does its giving up. The body's own ball at the foot decides:
         * where the walkable edges the foot went down past this step hold it from all sides,
         * it rests on the highest of them (edges_over_foot, highest). Walking at 5 m/s (r
         * 0.19, step 0.85) down a V valley's 38-degree slope across its 0.147 m slot (edges
         * 0.307 m over the room floor), beside a single-sided ramp's free top edge 1.01 m high, 0.11 m across up
         * from the foot: the drop met that edge first (34 degrees off up, walkable), the roll
         * off it met nothing, the slide down its tangent went 0.50 m across up onto the far
         * slope 0.45 m over the foot, whose roll (half a radius of descent) never came back
         * down to the slot; the rule gave up, the snap to the room floor stopped on the
         * ramp's edge, and the foot stood 159 mm under the ball resting on the slot's edges
         * (soak s102 l395). Out of line: a rare path. */
        if (over_floor && slid_far) {
            out->found = false;
            edges_over_foot(c, pos, true, out);
            if (out->found && far_out) *far_out = out->point;
            return out->found;
        }
        /* Over a floor, the slide past a steep first contact (a taller piece's top edge
         * beside the foot, above) ended on a walkable contact outside the foot's gap, and
         * the rule gave up from there: the slid ball says nothing about the foot. The body's
         * own ball at the foot decides (rest_at_foot, around), at the level of the contact
         * the slide ended on: at the steep contact's level that taller edge, 0.52 m across
         * up, would count as a point the ball rests on (a lift of 0.34 m). Running at 28 m/s
         * (r 0.93, step 0.50) across a 0.14 m crack between two tiles 0.14 m high, a V
         * valley's block 0.51 m beside the foot: the drop met the block's top edge (38
         * degrees off up), the slide down its tangent went 0.46 m across up onto the near
         * tile's outer edge, the move off that edge dropped onto the room floor, the rule
         * gave up and the foot stood on the floor in the crack, 137 mm under the ball resting
         * on both tiles' edges (soak s128 l322). Only a contact no higher than the foot was
         * before the step (as edges_over_foot: the rule does not lift the body over where it
         * was): walking across a staircase's tread under a tilted up, 49 mm before the next
         * riser, the slide ended on that riser's nosing 0.26 m up, and the nosing, the
         * block's corner and, under the tilted up, the tread's own face surrounded the ball:
         * the body was lifted onto the next tread early (soak s128 l44, in this branch's
         * soak). */
        if (slid_onto && v3_dot(v3_sub(landed.point, foot), up) <=
                             v3_dot(v3_sub(owner_position(b), pos), up) + cb_len_tol(c, CB_STEP_EPS)) {
            float rest = 0.0f;
            if (surrounded_at_foot(c, foot, floor_gap, &landed, &rest))
                return held_at(rest, reach, -rest, up, landed.point, &landed, out, far_out);
        }
        /* Over a floor, the slide past a steep first contact ran into a wall and went back
         * to that contact, and the rule gave up from there: the ball dropped from the sweep
         * capsule met only steep pieces beside the foot and says nothing about the gap under
         * it. The body's own ball at the foot decides (surrounded_below_old_foot), at the level
         * the foot was at before the step (the rule does not lift the body over where it
         * was; the steep pieces' contacts lie above it). Walking (r 0.93, step 0.78) off a
         * tile 94 mm high into a 14 mm crack beside a lower tile, a 66-degree ramp's foot
         * 0.23 m ahead of the foot in the step zone: the drop met the ramp's face, the slide
         * down it met a staircase's side, the rule gave up, and the snap to the room floor
         * stopped on the ramp: the foot stood 33 mm under the tiles' tops, in the crack
         * (soak s133 l2). */
        if (slid_into_wall) {
            float rest = 0.0f;
            if (surrounded_below_old_foot(c, pos, foot, floor_gap, NULL, &rest))
                return held_at(rest, reach, -rest, up, h1.point, &h1, out, far_out);
        }
        return false;
    }
    return held_at(contact, reach, gap, normal, far, &h1, out, far_out);
}

/**
 * The crack rule's cheap first look over a floor the foot ray found: the ball dropped from
 * where ball_held drops it reaches (to within twice the skin; a skin over a level floor)
 * the plane of that floor without touching anything. Then nothing above the floor can hold
 * it (no groove edge, no tile beside the gap) and the full rule, whose sweeps would meet
 * every floor triangle under the ball, is skipped. The stop short of the plane keeps its
 * triangles out of reach, so their sweeps end in the early plane reject. Otherwise *edge is what the ball met first.
 */
/* Inline in crack_held, itself inline in both its callers: every grounded step asks it from
 * coll_cb_probe_floor (a call of its own, once held_over calls it too, cost the console's
 * walk +0.6 %). */
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline bool ball_reaches_floor(const cb_ctx_t *c, fm_vec3_t pos, const coll_ray_hit_t *floor,
                               coll_sweep_hit_t *edge, float *edge_len)
{
    const fm_vec3_t up = c->up;
    const float r = c->radius;
    edge->normal = up; /* no first look: an edge right under the ball (the full rule decides) */
    *edge_len = 0.0f;  /* > 0: *edge is the drop's first contact over that length */
    float nu = v3_dot(floor->normal, up);
    if (!(nu > 0.02f)) return false;
    fm_vec3_t b0 = ball_drop_start(c, pos);
    /* Level: up within the rounding of a unit normal. A level face's normal can come out
     * 0.99999994 along up, not 1 (a tile instance turned about up: its rotation and the
     * normalisation round): taken for tilted, it got two skins and tile edges 1.3 mm over
     * it went unseen (soak s54 l269). */
    const bool level = nu >= CB_LEVEL_NU;
    /* descent along up at which the ball would touch the floor's plane, less the margin:
     * over a level floor a skin, the footing tolerance, not two (edges 1.48 mm over a
     * floor, a tile field's near copy 1.5 mm higher with its 6 mm slit over the foot, lay
     * within two skins of the plane, unseen, and the foot stood on the floor in the slit:
     * soak s22 l347); over a tilted one two (a skin there brings the ball within reach of
     * a heightfield's next triangles: the Jolt scene +1.3 %) */
    float s = (v3_dot(v3_sub(b0, floor->point), floor->normal) - r) / nu -
              (level ? 1.0f : 2.0f) * c->skin;
    if (!(s > c->tiny)) return false;
    /* The ball ends two skins (along up: 2 skin nu along the normal) over a tilted floor's plane
     * and starts higher: what lies within half that over the plane it never reaches (the
     * sloping floor's tilted neighbours, tested exactly otherwise). Over a level floor (a
     * grid-aligned level's) the plain sweep: its neighbours are level or upright, out of the
     * ball's box or above the plane, and the plane only costs there. The same answer. */
    bool met;
    if (!level) {
        const coll_gather_above_t above = { floor->normal, floor->point, c->skin * nu, false };
        met = ball_drop_above(c, pos, b0, s, &above, edge);
    } else {
        met = ball_drop(c, pos, b0, s, edge, true);
    }
    if (!met) {
        /* level, or tilted less than 45 degrees: the ball touches the plane within a radius
         * (r tan of the tilt) of the foot ray's point; not looked at (cost: walkable ramps
         * under the bench's up; stairs_real +0.7 % with every tilted floor looked at) */
        if (!(nu < 0.70710678f)) return true;
        /* Tilted against up, the ball touches the plane off the foot ray's point: it reaches
         * the floor only where that touch point is on the floor (or a face in its plane).
         * A tile's side, walkable under a tilted up, found by the foot ray in a 4 mm crack
         * between tiles: its plane runs on under the tiles beside the crack, which the ball
         * never reaches (soak s4 l142: 2.4 mm). Otherwise the full rule decides. */
        coll_ray_hit_t t;
        fm_vec3_t b1 = v3_madd(b0, up, -s);
        /* first the found triangle itself (in its mesh's frame: the instance's transform is
         * affine); a touch point beyond its edges may be on a neighbour in its plane: the ray */
        fm_vec3_t q;
        if (floor->instance && floor->triangle >= 0 &&
            coll_transform_point_inverse(&floor->instance->xf, v3_madd(b1, floor->normal, -r), &q)) {
            fm_vec3_t v[3];
            coll_mesh_triangle(floor->instance->mesh, (uint32_t)floor->triangle, v);
            fm_vec3_t e1 = v3_sub(v[1], v[0]), e2 = v3_sub(v[2], v[0]), tn = v3_cross(e1, e2);
            if (v3_dot(v3_cross(e1, v3_sub(q, v[0])), tn) >= 0.0f &&
                v3_dot(v3_cross(v3_sub(v[2], v[1]), v3_sub(q, v[1])), tn) >= 0.0f &&
                v3_dot(v3_cross(v3_sub(v[0], v[2]), v3_sub(q, v[2])), tn) >= 0.0f)
                return true;
        }
        float want = r + 2.0f * c->skin * nu;
        if (cb_ray(c, b1, v3_scale(floor->normal, -1.0f), want + c->contact_eps, &t) && isfinite(t.distance) &&
            v3_finite(t.normal) && v3_dot(t.normal, floor->normal) > 0.999f &&
            fabsf(t.distance - want) <= c->contact_eps)
            return true;
        return false;
    }
    if (!isfinite(edge->t) || !v3_finite(edge->normal) || !v3_finite(edge->point)) edge->normal = up;
    else *edge_len = s;
    return false;
}

/**
 * level_beyond's ray met the floor at the foot's level (or lower) a radius beyond the edge,
 * so the edge is no groove's side; but the ball may still sit in a hole whose other pieces
 * are not straight across from the edge: tile corners of different heights beside the
 * ball on either side, the floor between them (soak s2 l273: the edge a tenth of a radius
 * across up from the ball's centre, contact normal 0.994 along up; the ray went out of the
 * hole's open mouth, 171 degrees wide). A walkable gathered triangle whose box rises above
 * the foot and the floor under it, reaches beyond the full ball's centre (away from the
 * edge) and comes within a radius of it may be such a piece: then the hole rule
 * (ball_in_hole) alone decides (ball_held's hole_only: no roll, so no groove or wedge hold
 * the old gate did not allow). A stair's nosing ahead has nothing above the foot behind it
 * (the tread the foot is on and the lower ones): no query, one pass over the step's
 * gathered boxes. Looked at only for an edge almost under the ball's centre (contact normal
 * over 0.99 along up, within a seventh of a radius across up): that pass costs 30-40
 * instructions a triangle, and every stair nosing ahead is such an edge for a few steps as
 * the foot walks up to it (0.65-0.97 along up on the bench's stairs, 16 and 26 steps a
 * course; over 0.99 3 and 1). Without a valid gather, no (as before).
 */
static bool piece_beyond_at(const cb_ctx_t *c, fm_vec3_t pos, const coll_sweep_hit_t *edge, const coll_ray_hit_t *under,
                            float min_nu)
{
    const coll_gather_t *g = c->gather;
    const fm_vec3_t up = c->up;
    if (!g || !g->valid || !(v3_dot(edge->normal, up) > min_nu)) return false;
    const fm_vec3_t side = v3_norm(v3_reject(edge->normal, up)); /* from the edge towards the ball */
    const float r = c->radius;
    const fm_vec3_t f = v3_sub(cb_foot(c, pos), g->origin), o = v3_madd(f, up, r);
    const float lift = f_max(v3_dot(f, up), v3_dot(v3_sub(under->point, g->origin), up)) + c->contact_eps;
    const float reach = v3_dot(o, side);
    /* a box's highest point along up, farthest along side: hi where positive, lo where not */
    const fm_vec3_t up_hi = v3(f_max(up.x, 0.0f), f_max(up.y, 0.0f), f_max(up.z, 0.0f)), up_lo = v3_sub(up, up_hi);
    const fm_vec3_t side_hi = v3(f_max(side.x, 0.0f), f_max(side.y, 0.0f), f_max(side.z, 0.0f)),
                    side_lo = v3_sub(side, side_hi);
    for (uint16_t i = 0; i < g->ntris; i++) {
        const coll_gather_tri_t *t = &g->tris[i];
        /* its box rises above the foot and the floor under it */
        if (!(v3_dot(t->hi, up_hi) + v3_dot(t->lo, up_lo) > lift)) continue;
        /* reaches beyond the centre, away from the edge */
        if (!(v3_dot(t->hi, side_hi) + v3_dot(t->lo, side_lo) > reach)) continue;
        /* within reach of the full ball */
        fm_vec3_t q = box_closest(t, o);
        if (!(v3_len2(v3_sub(q, o)) < r * r)) continue;
        /* walkable (either face): a piece's top, not a wall beside the body; and not in the
         * plane of the floor under the foot (the tread a lift steps onto) */
        fm_vec3_t n = v3_cross(t->e1, t->e2);
        float nn = v3_len(n);
        if (fabsf(v3_dot(n, up)) >= c->body->cos_floor_max_angle * nn &&
            !(fabsf(v3_dot(n, under->normal)) > 0.999f * nn &&
              fabsf(v3_dot(v3_sub(t->w0, v3_sub(under->point, g->origin)), under->normal)) <= c->contact_eps))
            return true;
    }
    return false;
}

static inline bool piece_beyond(const cb_ctx_t *c, fm_vec3_t pos, const coll_sweep_hit_t *edge, const coll_ray_hit_t *under)
{
    return piece_beyond_at(c, pos, edge, under, 0.99f);
}

/**
 * level_beyond's ray found no groove's far side, and the edge the first look met is off
 * the ball's centre (piece_beyond does not look): the far side may still be a piece the
 * ray, a line a radius long along the edge's side, went past: a tile corner beside the
 * line, which the ball (wide: r 0.99) meets rolling off the edge (soak s6 l429: a hole
 * between rotated tiles 0.15-0.16 m high, the foot on the floor under a 11 degree tilted
 * up, the contact normal 0.92 along up; the ray met nothing at all, the floor being lower
 * along up a radius across it; the roll met the far tile 0.2 m from the foot: a narrow
 * wedge, 0.16 m above the floor). Then the full rule decides (its roll), not the hole rule
 * alone. The same box pass as piece_beyond, only for an edge behind the body's motion
 * (a stair's nosing ahead is such an edge every few steps: the cost gate foot13b's
 * drop_past_side uses too), only when the first look met it (edge_len > 0), and only
 * where the ray could not see the foot's own floor beyond the edge: that floor tilted
 * against up, a radius along the edge's side below the ray's end (r (side . n) > contact_eps
 * (n . up)). On the bench's stairs (up = y, level treads) the pass ran for 4 nosings behind
 * a descending body, +0.64 % of the course, and found nothing; the same hole under an up
 * along the floor's normal is looked at only for an edge of another piece than the floor
 * (soak s84 l357, below; the stairs' nosings are the staircase's own).
 */
#if defined(__GNUC__)
__attribute__((always_inline)) /* as ball_reaches_floor: inline in crack_held */
#endif
static inline bool piece_behind(const cb_ctx_t *c, fm_vec3_t pos, const coll_sweep_hit_t *edge, float edge_len,
                         const coll_ray_hit_t *under)
{
    const fm_vec3_t up = c->up;
    if (!(edge_len > 0.0f) || v3_dot(edge->normal, up) > 0.99f) return false; /* piece_beyond looked */
    const fm_vec3_t rel = v3_sub(edge->point, cb_foot(c, pos));
    /* An edge above the step zone of another piece than the floor the foot stands on is
     * looked at wherever it lies and however level that floor is: over the room floor, a
     * 0.55 m gap between the corners of two blocks 0.33 and 0.18 m high, the ball (r 0.98)
     * on both, the body walking into the higher one along a wall; the ray a radius beyond
     * its edge went past the lower block's corner, 0.16 m from the foot, onto the floor,
     * and the foot stood on the floor 156 mm under the ball (soak s14 l37). A staircase's
     * nosings ahead of a body climbing it are edges of the piece it stands on (one mesh):
     * not looked at (the pass on every second step of the bench's real stairs: +0.64 %). */
    const bool other_piece_above = v3_dot(rel, up) > c->step && edge->instance != under->instance;
    if (!other_piece_above) {
        /* An edge ahead of the motion of the very piece the foot stands on (a staircase's
         * nosing ahead) is not looked at; one of another piece is: the ray a radius beyond it
         * is one line straight across, and the far side of a V (a gap between two pieces whose
         * edges are not parallel) is not there. Running (r 0.60, step 1.19) on the room floor
         * into a 51-degree V between a tile field's straight border (tops 0.4617) 0.27 m north
         * of the foot and a block's edge (0.4863) 0.39 m south of it, the first look met the
         * border 30 degrees off the motion; the ray, a radius from the foot, met the floor 11
         * mm short of the block's edge (0.619 m along it), the rule was not asked, and the foot
         * stood on the floor 6.6 mm under the ball resting on the two tiles' corners and the
         * block (soak s94 l71). The full rule holds the ball on the border and the block. */
        if (v3_dot(rel, c->body->velocity) > 0.0f && edge->instance == under->instance) return false;
        /* the foot's floor a radius beyond the edge lies below the ray's end (tilted against up) */
        const fm_vec3_t side = v3_norm(v3_reject(edge->normal, up));
        const float nu = v3_dot(under->normal, up);
        /* Over a level floor too, for an edge of another piece than the floor (in the step
         * zone: above it other_piece_above looks already): the ray, one line a radius long,
         * may pass beside the gap's far side and out of its open end onto the foot's own
         * floor. Walking at 4.6 m/s (r 0.48, step 0.91) into the open end of a 0.50 m slot
         * between two blocks 0.47 m high, the first look dropped the ball onto the edge of
         * a third block 0.83 m high standing in the north one (-z), 0.42 m across up behind the
         * motion; the ray beyond it went past the south block's corner onto the room floor,
         * the rule was not asked, and the foot stood on the floor in the slot, 282 mm under
         * the ball resting on the south block's edge (soak s84 l357). The full rule holds
         * the ball over the slot. A staircase's own nosings behind a body walking down it
         * are edges of the piece it stands on (one mesh): still not looked at. */
        if ((!(nu > 0.0f) || !(c->radius * v3_dot(side, under->normal) > c->contact_eps * nu)) &&
            edge->instance == under->instance)
            return false;
    }
    /* a piece's edge, not a face: the ball resting on a face (a rolling terrain's next
     * triangle in a concave spot, everywhere on Jolt's heightfield: the pass and the full
     * rule there cost 14 % of the scene and found nothing) is no tile's corner. Unless
     * that face is walkable, above the step zone and of another piece than the floor: the
     * body walked (dt 0.12) into a narrow crack between two tiles 67 mm high beside a
     * triangle soup, the ball's first contact a soup face 0.55 m up (54 degrees off up,
     * walkable to 63), and the foot stood on the floor in the crack, 67 mm under the tiles
     * (soak s17 l53). */
    fm_vec3_t fn;
    if (coll_cb_face_normal(edge, &fn) && !(other_piece_above && v3_dot(fn, up) >= c->body->cos_floor_max_angle))
        return false;
    return piece_beyond_at(c, pos, edge, under, 0.02f);
}

/**
 * level_beyond's ray, one point a radius beyond the edge, found no piece over the floor under
 * the foot, and the edge is at that floor's level (within level_beyond's tenth of a radius)
 * but over it by more than the step tolerance (what crack_held lifts by): the ray may have
 * gone down the next gap of a tile field whose tiles are about a radius wide. The far side of
 * a crack narrow enough to hold such a ball is near: a ray half a radius beyond looks for a
 * piece more than `piece` over the foot (the step tolerance over that floor). Running (r
 * 0.87) across a 4.2 mm crack between tiles 0.864 m wide, tops 0.2693, over a near copy of
 * the field 1.6 mm lower whose tile top showed through the crack: the sweep capsule came to
 * rest on the two edges, the foot ray found that lower top, the first look met the north
 * edge 3.2 mm from the foot's column, the ray a radius beyond went down the next crack of
 * both fields and met nothing, the step's gather had overflowed (piece_beyond does not look),
 * and the foot stood on the lower top, 1.59 mm under the ball resting on both edges (soak
 * s97 l248). Not for a stair's nosing: a riser over the tread (the bench's 0.18-0.36 m, r
 * 0.5; 16 and 26 calls a course get here). Out of line: a rare path.
 */
static __attribute__((noinline)) bool piece_half_beyond(const cb_ctx_t *c, fm_vec3_t pos, const coll_sweep_hit_t *edge,
                                                        float piece)
{
    const fm_vec3_t up = c->up, side = v3_norm(v3_reject(edge->normal, up));
    const float top = c->radius + c->step;
    coll_ray_hit_t h;
    return cb_ray(c, v3_madd(v3_madd(cb_foot(c, pos), side, 0.5f * c->radius), up, top), v3_scale(up, -1.0f),
                  top - piece, &h) &&
           isfinite(h.distance) && top - h.distance > piece;
}

/**
 * For a body standing on the floor the foot ray found (not stepping down onto it): can the
 * edge the ball met be one side of a groove? Only if, a radius away on the other side, a
 * surface lies at that edge's level (within the tenth of a radius ball_held allows), or
 * both lie above the foot: the groove's far block. A stair's nosing ahead has the lower
 * tread behind; a bump of uneven ground has ground at another height. One ray instead of
 * the full rule's sweeps (two where the first may have gone down another gap:
 * piece_half_beyond).
 */
__attribute__((noinline)) static bool level_beyond(const cb_ctx_t *c, fm_vec3_t pos, const coll_sweep_hit_t *edge, float gap)
{
    const fm_vec3_t up = c->up, foot = cb_foot(c, pos);
    fm_vec3_t side = v3_norm(v3_reject(edge->normal, up)); /* from the edge towards the ball */
    if (v3_len2(side) < 0.5f) return true; /* met right under its centre: the full rule decides */
    float c1 = v3_dot(v3_sub(edge->point, foot), up), top = c->radius + c->step;
    /* Stepping up onto the floor found (gap < 0), the ball's first contact still above the
     * step zone over that floor: no next tread (a stair's nosing ahead is within a step
     * of the tread stepped onto: 0.2 of 0.25 on the bench's stairs), something holds the
     * ball higher; the full rule decides. A 45-degree staircase climbing a V valley's slot,
     * r 0.926: the first tread 6 cm up, the first contact the nosing two treads higher
     * (0.70 m over that tread, step 0.56); the slopes on both sides hold the ball 0.52 m
     * up, and the foot stood on the tread 176 mm under them (soak s32 l339). Out of line
     * (noinline): inlined, the extra argument cost every walk step 45 instructions. */
    if (gap < -c->contact_eps && c1 + gap > c->step) return true;
    fm_vec3_t o = v3_madd(v3_madd(foot, side, c->radius), up, top);
    coll_ray_hit_t h;
    const bool met = cb_ray(c, o, v3_scale(up, -1.0f), top + c->contact_eps, &h) && isfinite(h.distance);
    /* or both above the foot: it stands at the bottom of a groove between blocks of
     * different heights, inside both (a stair's tread behind is at or below the foot) */
    const float beyond = met ? top - h.distance : 0.0f;
    if (met && (fabsf(beyond - c1) <= 0.1f * c->radius || (beyond > c->contact_eps && c1 > c->contact_eps)))
        return true;
    /* An edge at the floor's level (within that tenth of a radius) and over the floor under
     * the foot by more than the step tolerance, while the ray found no piece over that
     * floor: it may have gone down another gap (piece_half_beyond). */
    const float piece = cb_len_tol(c, CB_STEP_EPS) - gap; /* over the floor under the foot */
    return c1 + gap <= 0.1f * c->radius && c1 > piece && !(met && beyond > piece) &&
           piece_half_beyond(c, pos, edge, piece);
}

/**
 * How far along `left` a slide off an edge may go before the foot meets the plane of the
 * floor the snap is for (normal n, through the foot's target `dist` below it along up):
 * sliding off across up over a sloping floor, the rest of the snap's descent went below
 * that floor where it rises (soak s3 l91: r 0.13, the foot 17 mm into a 32 degree slope).
 * A fraction of `left` in [0, 1].
 */
static inline float slide_off_above(const cb_ctx_t *c, fm_vec3_t pos, fm_vec3_t target, fm_vec3_t n, fm_vec3_t left)
{
    float into = -v3_dot(left, n), above = v3_dot(v3_sub(cb_foot(c, pos), target), n);
    if (!(into > above)) return 1.0f;
    return above > 0.0f ? above / into : 0.0f;
}

/**
 * Snaps the body down by dist along -up, swept. Where the capsule's rounded bottom catches
 * on an edge on the way (the nosing of the stair behind, walking down short treads), it
 * slides down off it along the contact plane, as a resting ball would, instead of hanging
 * on it above the floor: the way it was going (b->velocity, this step's motion), and never
 * against the input across up. Sliding off is motion (the velocity says so), so it is no
 * faster than the speed limit with the step's motion so far (b->velocity): a step of 1 ns
 * does not slide 9 cm off a nosing (soak s2 l381), it stays on it until the next step.
 * Nor does it slide below the floor it snaps to (normal n): the slide stops where the foot
 * meets that floor's plane (slide_off_above).
 */
static void snap_down(const cb_ctx_t *c, fm_vec3_t *pos, float dist, fm_vec3_t n)
{
    const char_body_t *b = c->body;
    fm_vec3_t left = v3_scale(c->up, -dist);
    const fm_vec3_t target = v3_add(cb_foot(c, *pos), left);
    float budget = -1.0f; /* across up, for sliding off: computed at the first slide off */
    for (int it = 0; it < 3; it++) {
        if (it > 0) {
            if (budget < 0.0f) budget = f_max(0.0f, (c->max_speed - v3_len(b->velocity)) * c->dt);
            float across = v3_len(v3_reject(left, c->up));
            if (across > budget) {
                if (!(budget > c->tiny)) return;
                left = v3_scale(left, budget / across);
            }
            left = v3_scale(left, slide_off_above(c, *pos, target, n, left));
        }
        float len = v3_len(left);
        if (!(len > c->tiny)) return;
        coll_sweep_hit_t hit;
        /* (the first: known where the stair step came down to) */
        bool found;
        if (!(it == 0 && cb_down_known(c, *pos, dist, &found, &hit)))
            found = cb_sweep(c, cb_sweep_center(c, *pos), c->radius, c->sweep_ihh, left, &hit);
        if (!found ||
            !isfinite(hit.t) || !v3_finite(hit.normal)) {
            *pos = v3_add(*pos, left);
            /* Slid off the edge into the open: the slide along the edge's plane came down
             * less than the snap's rest (the projection shortened it), so the rest goes on
             * straight down to the floor's plane (swept, the next look). Stopping there left
             * the body grounded in the air, its foot 0.21 m over the floor the probe found
             * (step 0, snap 0.078: soak s28 l171). */
            float nu = v3_dot(n, c->up), above = v3_dot(v3_sub(cb_foot(c, *pos), target), n);
            if (it == 0 || it == 2 || !(nu > 0.0f) || !(above > c->tiny)) return;
            left = v3_scale(c->up, -above / nu);
            continue;
        }
        if (hit.t <= 0.0f && hit.depth > 0.0f) return;
        float travel = len * hit.t - c->skin;
        if (travel >= len - c->skin) {
            *pos = v3_add(*pos, left); /* the contact is the target itself */
            return;
        }
        if (travel > 0.0f) {
            *pos = v3_madd(*pos, left, travel / len);
            if (it > 0) budget -= v3_len(v3_reject(left, c->up)) * travel / len;
        }
        left = v3_scale(left, 1.0f - (travel > 0.0f ? travel / len : 0.0f));
        /* Only an edge under the capsule is slid off, and only onwards (the way the body
         * moved this step: never back, off the nosing ahead of a body climbing stairs). */
        if (!(v3_dot(hit.normal, c->up) > 0.05f)) return;
        /* Not the floor it snaps to: the sweep capsule rests on that floor's plane (a slope
         * steeper than its bottom allows holds it r / cos - (r + step) over the foot's
         * point: the snap's target is out of its reach), and sliding along it is no slide
         * off an edge: it went 0.28 m across up every step, 4 times the walk, and off the
         * slope onto a piece beside it, 21 mm short of it (soak s7 l262, floor). */
        if (v3_dot(hit.normal, n) > 0.999f && fabsf(v3_dot(v3_sub(hit.point, target), n)) <= c->contact_eps) return;
        left = v3_madd(left, hit.normal, -v3_dot(left, hit.normal));
        /* onwards: across up, within 60 degrees of the velocity (not down a steep face
         * beside a body sliding along a wall: that is back, or sideways, off it); a body
         * moving only along up keeps the old rule: along its velocity */
        fm_vec3_t la = v3_reject(left, c->up), va = v3_reject(b->velocity, c->up);
        float lv = v3_len(la) * v3_len(va);
        if (lv > 0.0f ? !(v3_dot(la, va) > 0.5f * lv) : !(v3_dot(left, b->velocity) > 0.0f)) return;
        /* nor against the input: the velocity may be the sub-millimetre residue of a slide
         * stopped by a wall or a steep face, not a way the body goes (soak s2 l75: 49 mm
         * back down a steep face it was pushed against) */
        if (v3_dot(la, b->input_velocity) < 0.0f) return;
        if (!(v3_dot(left, c->up) < -c->tiny)) return;
    }
}

/** True when the sweep capsule at pos touches a plane of normal n right below it (within
 * the contact tolerance): what holds it up is that plane. Looked for along -n, not -up: a
 * wall the capsule touches beside it (wedged) is then not met first (soak s2 l336). */
static bool resting_on(const cb_ctx_t *c, fm_vec3_t pos, fm_vec3_t n)
{
    coll_sweep_hit_t h;
    return cb_sweep(c, cb_sweep_center(c, pos), c->radius, c->sweep_ihh, v3_scale(n, -c->contact_eps), &h) &&
           isfinite(h.t) && v3_finite(h.normal) && v3_dot(h.normal, n) > 0.999f;
}

/**
 * Landing, the foot point over a walkable floor gap below it (out of the contact reach),
 * while the sweep capsule's rounded bottom rests on an upward-facing edge beside it (a
 * kerb taller than the step): the slide does not push the body off that edge, because the
 * floor under the foot supports it (slide_off_edge: within r / cos of the contact + 2 cm
 * of the bottom ball's centre), so it is standing, not falling. Without this the body hung
 * there at rest in the air, its foot 3 mm over the floor (soak s1 l217). Never true where
 * r / cos(floor_max_angle) + 2 cm <= r + step (the defaults): no query then.
 */
static bool resting_beside(const cb_ctx_t *c, fm_vec3_t pos, float gap)
{
    const char_body_t *b = c->body;
    const float margin = 2.0f * cb_len_tol(c, CB_MARGIN), lift = c->radius + c->step;
    if (!(gap <= c->radius / b->cos_floor_max_angle + margin - lift)) return false;
    /* Touching is within contact_eps along the contact's normal, not along up: the slide
     * leaves the ball a skin off the edge along that normal, skin / cos along up. A ball a
     * skin off a block's top edge 57 degrees off up (walkable at 68.3) was 2.05 mm from it
     * along up, out of a contact_eps sweep: at rest there, pressed into a box's side, never
     * grounded (soak s133 l204). The sweep reaches contact_eps / cos of the steepest
     * walkable contact (at most 4 contact_eps). */
    const float cmax = b->cos_floor_max_angle > 0.25f ? b->cos_floor_max_angle : 0.25f;
    const float len = c->contact_eps / cmax;
    coll_sweep_hit_t h;
    if (!cb_sweep(c, cb_sweep_center(c, pos), c->radius, c->sweep_ihh, v3_scale(c->up, -len), &h) ||
        !isfinite(h.t) || !v3_finite(h.normal))
        return false;
    float nu = v3_dot(h.normal, c->up);
    return nu >= b->cos_floor_max_angle && h.t * len * nu <= c->contact_eps && gap <= c->radius / nu + margin - lift;
}

/**
 * Landing, the foot point over a walkable floor just out of the contact reach (the caller
 * allows up to twice it), while a wall or a steep face stops the capsule going down along up
 * to it: under a tilted up in a room's corner the fall along up goes into one wall and the
 * lift back along up into the other, so the body hung at rest in the air 2.6 mm over the
 * floor for ever (soak s3 l110). It is held there, standing: the snap slides it down as far
 * as it goes. (Allowed as far as the snap distance it also grounded bodies whose foot was
 * below a raised floor: 2 new footing failures at 1M frames, seed 1.) The caller allows it
 * also as far as the full capsule's bottom ball reaches the floor's plane, r (1 - cos) /
 * cos: the body leans on a wall under a tilted up, that ball on a floor 30 degrees off up,
 * its foot 15 mm over it (soak s4 l138).
 */
static bool held_over_floor(const cb_ctx_t *c, fm_vec3_t pos, float gap)
{
    coll_sweep_hit_t h;
    if (!cb_sweep(c, cb_sweep_center(c, pos), c->radius, c->sweep_ihh, v3_scale(c->up, -gap), &h) ||
        !isfinite(h.t) || !v3_finite(h.normal))
        return false;
    return h.t < 1.0f && v3_dot(h.normal, c->up) < c->body->cos_floor_max_angle;
}

/**
 * Airborne, the foot point over a walkable floor tilted against up, out of the contact
 * reach but within the reach of the full capsule's bottom ball (r (1 - cos) / cos +
 * contact_eps: the ball's lowest point along the floor's normal is below the foot), and the
 * step did not move the body (at most a tenth of the skin since the step began): the ball
 * rests on that floor. Nothing stops the way down along up (held_over_floor), but the slide
 * does: under a tilted up in a room's corner, the input across up pushes into both walls,
 * which lean back from the body, clipped to their crease it climbs it faster than gravity
 * falls, and the slide stops the body; it hung at rest 3.5 mm over the floor, its ball on
 * it, for ever (soak s7 l48). Touching is checked: the ball grown by contact_eps overlaps
 * a face in that floor's plane (its normal).
 */
static bool at_rest_on(const cb_ctx_t *c, fm_vec3_t pos, const coll_ray_hit_t *hit, float gap)
{
    const char_body_t *b = c->body;
    fm_vec3_t before = owner_position(b);
    fm_vec3_t moved = v3_sub(pos, before);
    if (!(v3_dot(moved, moved) <= 0.01f * c->skin * c->skin)) return false;
    const float r = c->radius, nu = v3_dot(hit->normal, c->up);
    if (!((r + gap) * nu - r < c->contact_eps)) return false; /* the ball over the floor's plane */
    /* and it touches that floor (a wall the ball's side is in may be deeper: overlaps) */
    coll_contact_t ct[CB_BALL_CONTACTS];
    const fm_vec3_t bc = v3_madd(cb_foot(c, pos), c->up, r);
    const uint32_t n = cb_ball_overlaps(c, bc, r + c->contact_eps, ct);
    for (uint32_t i = 0; i < n; i++)
        if (v3_finite(ct[i].normal) && v3_dot(ct[i].normal, hit->normal) > 0.999f) return true;
    return false;
}

/**
 * Not moved this step (at most `still` since it began) and the sweep capsule's rounded
 * bottom touching a walkable edge or face along -up (within contact_eps): h is that contact.
 * held_on_edge and held_on_edge_alone both start from it.
 */
static bool resting_on_walkable(const cb_ctx_t *c, fm_vec3_t pos, float still, coll_sweep_hit_t *h)
{
    const char_body_t *b = c->body;
    fm_vec3_t moved = v3_sub(pos, owner_position(b));
    if (!(v3_dot(moved, moved) <= still * still)) return false;
    if (!cb_sweep(c, cb_sweep_center(c, pos), c->radius, c->sweep_ihh, v3_scale(c->up, -c->contact_eps), h) ||
        !isfinite(h->t) || !v3_finite(h->normal) || !v3_finite(h->point))
        return false;
    return v3_dot(h->normal, c->up) >= b->cos_floor_max_angle;
}

/**
 * Airborne and not moved this step (at most a tenth of the skin, as at_rest_on), the foot
 * over a walkable floor out of reach below, while the sweep capsule's rounded bottom rests
 * on a walkable edge or face (touching it along -up within contact_eps, its normal within
 * the walkable angle) that the slide could not push it off (slide_off_edge: a wall on the
 * other side stops the push at once): the body rests on that edge, it is standing, not
 * falling. Without this it hung at rest in the air, the foot 56 mm over the floor, the
 * ball on a 0.16 m slab's edge 2 degrees off up and a wall against the capsule's other
 * side, for ever (soak s26 l95: r 0.63, step 0.16). The probe then snaps it towards that
 * floor, swept: the edge stops it where it rests.
 */
static bool held_on_edge(const cb_ctx_t *c, fm_vec3_t pos)
{
    coll_sweep_hit_t h;
    return resting_on_walkable(c, pos, 0.1f * c->skin, &h);
}

/**
 * held_on_edge with no floor anywhere in the foot ray's reach: not moved this step (a tenth
 * of the skin; the skin when it stood on such an edge last step: the walking slide's clip
 * and top-up against what wedges it move it a fraction of a millimetre), the sweep capsule's
 * rounded bottom touching a walkable edge or vertex along -up, and no room to be pushed off
 * it across up (slide_off_edge's push, away from the contact, blocked within the contact
 * tolerance). The body stands on that edge where it is (gap 0: the foot beside it, over
 * nothing). Under an up 120 degrees off the room floor's normal (the room floor an overhang
 * for it), a jump's input across up pressed the capsule's top against the room floor and
 * its bottom ball onto a slab's lower corner (the contact 27 degrees off up); the way off
 * the corner went into the room floor, and with one slide the body hung at rest in the air
 * for ever, no floor within 7 m along -up (soak s89 l214). On a walkable face (the contact
 * on the face itself) there is no edge to be pushed off: it stands, no push asked (s130 l310).
 * Out of line: only a body at rest with no floor under it gets here.
 */
static __attribute__((noinline)) void held_on_edge_alone(const cb_ctx_t *c, fm_vec3_t pos, bool was_grounded,
                                                         support_t *s)
{
    coll_sweep_hit_t h, h2;
    if (!resting_on_walkable(c, pos, was_grounded ? c->skin : 0.1f * c->skin, &h)) return;
    const fm_vec3_t sc = cb_sweep_center(c, pos);
    /* On a walkable face (the contact on the face, not its edge or vertex) the ball is held
     * wherever a push would go: there is no edge to be pushed off. The push across up, from
     * the contact to the ball's centre, is the way down the face: it is free, lifting the
     * ball off the face it falls back onto. The ball (r 0.92, step 0.51) on a soup face 29
     * degrees off up, its foot 4 cm past the face's side edge over nothing (the room floor
     * 4.79 m down), a face over its top ball: every slide down the face put the foot under
     * the face with no room to be lifted onto it and was undone, and the body hung at rest
     * in the air for ever (soak s130 l310). Resting on it, not inside it: a body the game
     * teleported into a closed solid (its sweep capsule 0.3 m into a 27-degree face, s130 l77)
     * is not standing on what it overlaps. */
    fm_vec3_t fn;
    if (!(h.depth > c->min_depth) && coll_cb_face_normal(&h, &fn) && v3_dot(fn, h.normal) > CB_FACE_ON) {
        *s = (support_t){true, false, 0.0f, h.normal, h.point, h.id, h.instance};
        return;
    }
    /* the way off the edge: across up, from the contact to the bottom ball's centre */
    fm_vec3_t off = v3_reject(v3_sub(v3_madd(sc, c->up, -c->sweep_ihh), h.point), c->up);
    const float ol = v3_len(off);
    const float need = cb_off_edge_push(c, ol);
    if (!(ol > cb_len_tol(c, 1e-5f)) || !(need > c->tiny)) return;
    if (!cb_sweep(c, sc, c->radius, c->sweep_ihh, v3_scale(off, need / ol), &h2) || !isfinite(h2.t) ||
        need * h2.t - c->skin > c->contact_eps)
        return;
    *s = (support_t){true, false, 0.0f, h.normal, h.point, h.id, h.instance};
}

/* wall_under_crack stood the foot (s->gap below it) on the top of the piece whose side the
 * foot ray met. That top is the piece's on the face's side of the gap the foot is in; the
 * gap's other side may be higher, and the ball rests there, not on the lower top. The ball
 * dropped as the crack rule drops it: where its first contact is a walkable face (it rests
 * on a floor), that face's plane extended to the foot is where the foot stands when it is
 * higher than the top. Under an up 13 degrees off y, the foot in a 6.4 mm crack between a
 * tile and one 18.5 mm higher, 4 mm past where four tiles' corners meet: the foot ray went
 * down the crack past the corners onto a third tile's side 0.12 m under the foot; the crack
 * rule's first contact was the higher tile's top, 0.18 m across up from the foot (the tilt),
 * and its roll ran level along that top for 1.56 m into a slab's underside (a ceiling: it
 * gave up); the ray down from over the face, drifting along the face with the tilted up,
 * came down past the third tile's corner onto the lower tile: the foot stood on its top,
 * 12.39 mm under the ball resting on the higher tiles (soak s68 l50). Out of line, and the
 * drop swept directly: a rare path; written inline in wall_under_crack through ball_drop
 * (which the compiler then put out of line for all its callers) it cost every step, the
 * console's walk +0.65 %, crowd32 +0.63 %, stairs +0.35 %. */
static __attribute__((noinline)) void face_over_top(const cb_ctx_t *c, fm_vec3_t pos, float reach, support_t *s)
{
    coll_sweep_hit_t bh;
    fm_vec3_t fn;
    const float len = c->step + reach + 0.5f * c->radius, step_eps = cb_len_tol(c, CB_STEP_EPS);
    if (!cb_sweep(c, ball_drop_start(c, pos), c->radius, 0.0f, v3_scale(c->up, -len), &bh) || !isfinite(bh.t) ||
        !v3_finite(bh.point) || !coll_cb_face_normal(&bh, &fn))
        return;
    const float fu = v3_dot(fn, c->up);
    if (!(fu >= c->body->cos_floor_max_angle)) return;
    const float gb = v3_dot(v3_sub(cb_foot(c, pos), bh.point), fn) / fu;
    if (gb < s->gap - step_eps && gb > -c->step) *s = (support_t){true, false, gb, fn, bh.point, bh.id, bh.instance};
}

/**
 * The foot ray found a face too steep to stand on, nearly along up (within 60 degrees: a
 * wall, a tile's side), within reach. Under a tilted up the ray through a crack between
 * tiles meets a tile's side, and the body stood "steep" on it with its foot 14-85 mm
 * below the tile tops around it (soak s2 l117, l356, l375, s3 l369). Where the crack rule
 * holds the ball higher (on the edges of the gap), the body stands there instead. Its drop
 * slides down past a wall it meets first, as over a floor (drop_past_side): under a tilted
 * up the room's floor, a wall 79 degrees off up, stopped the ball beside the open end of a
 * V valley's slot, the roll along it met nothing, and the body stood steep on the slot's
 * side with its foot 66 mm below the valley's end faces around the slot (soak s8 l115).
 */
static void wall_under_crack(const cb_ctx_t *c, fm_vec3_t pos, float reach, const coll_ray_hit_t *hit, support_t *s)
{
    if (!(fabsf(v3_dot(s->normal, c->up)) < 0.5f)) return;
    const float step_eps = cb_len_tol(c, CB_STEP_EPS);
    support_t w; /* written by ball_held when it returns true: read only then */
    if (ball_held(c, pos, reach, hit, 1e30f, NULL, 0.0f, false, true, &w, NULL)) {
        if (w.gap < s->gap - step_eps) *s = w;
        return;
    }
    /* The crack rule holds nothing (its ball, dropped from above the step zone, met a taller
     * piece's edge beside the foot first and never reached the crack), and the face is below
     * the foot, the foot close to its plane: the piece's top, extended to the foot, is where
     * the foot stands when it is higher than the face's hit. The foot is gap * n.up from the
     * face's plane (the ray is along up through the foot); within sqrt(2 r step_eps) of that
     * plane a ball resting on the piece's top edge sags at most the step tolerance under the
     * edge's level, so standing at that level puts the foot under no ball resting there and
     * over a pit beside the piece hovers at most that far past its edge. The top is met by a
     * ray down along up from a step over the face's hit, just inside the face (moved across
     * up into the piece by the gap and two skins). Under an up 15
     * degrees off y, the foot walked off a tile into a 10.6 mm crack between it and a tile 2.2
     * mm lower, beside a third tile's corner and a block 0.84 m high 0.33 m away; the ray met
     * the lower tile's side 11.7 mm under the foot, the crack rule's drop met the block's top
     * edge first and slid past it onto the third tile 0.6 m away, which held nothing, and the
     * body slid down the side, its foot 8.5 mm under the tile tops around it (soak s55 l203). */
    const float nu = v3_dot(hit->normal, c->up), d = s->gap * nu;
    const fm_vec3_t across = v3_reject(hit->normal, c->up);
    const float al = v3_len(across);
    if (!(s->gap > 0.0f) || !(nu > 0.0f) || !(d * d <= 2.0f * c->radius * step_eps) || !(al > 1e-3f)) return;
    const float h = s->gap + c->step;
    coll_ray_hit_t top;
    if (!cb_ray(c, v3_madd(v3_madd(hit->point, across, -(s->gap + 2.0f * c->skin) / al), c->up, h),
                v3_scale(c->up, -1.0f), h + 4.0f * c->skin, &top) ||
        !v3_finite(top.normal) || !v3_finite(top.point))
        return;
    const float tu = v3_dot(top.normal, c->up);
    if (!(tu >= c->body->cos_floor_max_angle)) return;
    const float g = v3_dot(v3_sub(cb_foot(c, pos), top.point), top.normal) / tu; /* > 0: below the foot */
    if (!(g < s->gap - step_eps && g > -c->step)) return;
    *s = (support_t){true, false, g, top.normal, top.point, top.id, top.instance};
    face_over_top(c, pos, reach, s);
}

/**
 * The steep face found above the foot belongs to a collider body (a slab, a box) and the ray
 * continued past the face starts inside it: a ray from inside a solid meets it at once, so
 * the loop that looks past the face for a floor advanced a skin at a time and gave up, and
 * the body stood on the face with its foot 0.11 m in the floor under the slab's low edge
 * (soak s1 l351: r 0.13, step 1.07). Looked for from the foot instead, along up, as far as
 * the face: a walkable floor the foot is under (either face of a triangle) is the one to
 * stand on (lifted onto it, as in the loop).
 */
static void floor_over_foot(const cb_ctx_t *c, fm_vec3_t pos, float height, support_t *s)
{
    const float step_eps = cb_len_tol(c, CB_STEP_EPS);
    coll_ray_hit_t h;
    if (!(height > step_eps) ||
        !cb_ray(c, cb_foot(c, pos), c->up, height, &h) || !v3_finite(h.normal) || !v3_finite(h.point) ||
        !isfinite(h.distance))
        return;
    if (!(h.distance > step_eps) || h.triangle < 0) {
        /* The foot itself is inside the collider body (the ray from it meets the body at
         * once): the meshes inside the body, looked at along the line from the face down to
         * the foot; the first one met, walkable, is the floor the foot is under. Falling
         * beside a collider body that stands on a tile (r 0.15, step 0.45), the foot went
         * through the tile's top and the room floor into the body, and the body stood steep
         * on its face with the foot 48 mm under the tile top (soak s12 l28).
         * So too where the ray meets a collider body from below: a convex solid met from
         * outside along up is met on its underside, never on a floor (a mesh triangle is
         * two-sided, a body is not). A cylinder tilted 31 degrees, sunk in the room floor,
         * its bottom cap's rim 13 mm under the floor beside the steep side the foot ray
         * met: the body stood on that cap turned up, its foot 12.9 mm under the floor
         * (soak s63 l245). */
        const char_body_settings_t *st = &c->body->settings;
        const uint8_t mesh = (uint8_t)(st->coll_types & COLL_TYPE_MESH);
        if (h.triangle >= 0 || !mesh ||
            !coll_raycast(c->scene, v3_madd(cb_foot(c, pos), c->up, height), v3_scale(c->up, -1.0f), height,
                          st->read_mask, mesh, &h) ||
            !v3_finite(h.normal) || !v3_finite(h.point) || !isfinite(h.distance) ||
            !(height - h.distance > step_eps) || v3_dot(h.normal, c->up) < c->body->cos_floor_max_angle)
            return;
        *s = (support_t){true, false, h.distance - height, h.normal, h.point, h.id, h.instance};
        return;
    }
    fm_vec3_t n = v3_scale(h.normal, -1.0f); /* met from below: turned to face up */
    if (v3_dot(n, c->up) < c->body->cos_floor_max_angle) return;
    *s = (support_t){true, false, -h.distance, n, h.point, h.id, h.instance};
}

/**
 * The foot ray's hit is a walkable floor below the foot (out of the landing reach when the
 * probe gets here). Where the crack rule holds the ball on edges above the foot instead, but
 * the body has no room to be lifted onto them (a wall or an overhang over it), it is not
 * held by them: it falls on towards that floor, the foot a point as everywhere else.
 * Undoing the step (no room to stand) instead left it hanging at rest in the air for ever:
 * under a tilted up in a room's corner beside a tile taller than the step, the full
 * capsule's bottom ball over the tile's edge, the lift blocked by the wall (soak s1 l347).
 * above: the ray's origin above the foot.
 */
static bool floor_below(const cb_ctx_t *c, fm_vec3_t pos, const coll_ray_hit_t *hit, float above)
{
    float gap = hit->distance - above;
    if (!(gap > 0.0f) || v3_dot(hit->normal, c->up) < c->body->cos_floor_max_angle) return false;
    /* and it can fall there: wedged between stair nosings under an overhang (soak s2 l193)
     * or in a V valley (s3 l374) it cannot, and the step is undone as before (the stand
     * search frees it) */
    return coll_cb_move_swept(c, &pos, v3_scale(c->up, -gap)) * gap >= gap - c->contact_eps;
}

/* Stands the body exactly on a floor gap below its foot (< 0: above it): snapped down, or
 * lifted onto it, swept. False when a lift has no room (a ledge or an overhang above).
 * Inline: every grounded step runs it (a call of its own cost the walk 35 instructions). */
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline bool stand_on(const cb_ctx_t *c, fm_vec3_t *pos, float gap, fm_vec3_t n)
{
    if (gap == 0.0f) return true; /* already on it (the move by 0 would not move it) */
    if (gap > 0.0f) {
        snap_down(c, pos, gap, n);
        return true;
    }
    const float step_eps = cb_len_tol(c, CB_STEP_EPS);
    float done = coll_cb_step_swept(c, pos, v3_scale(c->up, -gap)); /* (a lift onto a tread) */
    return !(gap < -step_eps && done * -gap < -gap - step_eps);
}

/* The snap made straight down from where it began (before), no slide across up: where a
 * slide off an edge took the foot somewhere the snap must not go (snap_kept_over, and the
 * probe's two checks after it). */
static void snap_straight(const cb_ctx_t *c, fm_vec3_t *pos, fm_vec3_t before, float gap)
{
    *pos = before;
    coll_cb_move_swept(c, pos, v3_scale(c->up, -gap));
}

/**
 * The snap onto s (from `before`, s->gap below the foot) slid the body down a walkable slope
 * steeper than the capsule's bottom allows (r / cos > r + step: the sweep capsule rests on
 * it with the foot r / cos - (r + step) above it): the foot must still be over that floor.
 * At a slope's low edge the slide took it past the edge, over the slot of a V valley, and
 * the body stood on the slope with its foot in the slot and the full ball deep in the
 * other slope (soak s6 l146: 54 mm, s4 l245: 10.7 mm, both 0.1 m slots between 38-41
 * degree ramps). The foot ray from the slid foot down to where the floor's plane is (the
 * snap's rest of the way, plus what the slide went downhill, plus contact_eps) finds no
 * floor: the snap is made straight down instead (no slide across up), the foot stays over
 * the slope, and the next step's probe sees the slot (the crack rule). Nothing on floors the
 * capsule stands on with its foot (r / cos <= r + step: every stair tread).
 */
static void snap_kept_over(const cb_ctx_t *c, fm_vec3_t *pos, fm_vec3_t before, const support_t *s)
{
    const fm_vec3_t up = c->up;
    const float nu = v3_dot(s->normal, up);
    if (!(c->radius > (c->radius + c->step) * nu)) return;
    const fm_vec3_t moved = v3_sub(*pos, before), across = v3_reject(moved, up);
    const float al = v3_len(across);
    if (!(al > 0.0f)) return;
    const float above = c->radius + c->step;
    const float hold = s->gap + v3_dot(moved, up) + al * sqrtf(f_max(0.0f, 1.0f - nu * nu)) / nu + c->contact_eps;
    coll_ray_hit_t h;
    if (cb_ray(c, v3_madd(cb_foot(c, *pos), up, above), v3_scale(up, -1.0f), above + f_max(hold, 0.0f), &h) &&
        isfinite(h.distance))
        return;
    snap_straight(c, pos, before, s->gap);
}

/* A jump's rise skips the probe, so nothing looks at a walkable face the step zone (unswept)
 * went under. Where the capsule has room to be lifted onto it, the step after the rise does
 * so. Where it has none (an overhang over it), no later step can: the body rose into a place
 * it cannot stand, and the probe undoes the step as any other. Under an up 38.9 degrees
 * off a room's wall (walkable, 0.0007 inside the floor angle's cosine), the body at rest on
 * the steep floor beside it, its foot in the crease under the wall's bottom edge, a low
 * overhang 1.92 m over the floor: a jump moved the foot 0.28 m along the wall, under it,
 * the overhang stopped the rise, and the body stood grounded on the wall with its foot
 * 348 mm inside it (soak s40 l110). The foot ray of the probe, and a lift only where it
 * finds such a face. */
bool coll_cb_rise_sunk(const cb_ctx_t *c, fm_vec3_t pos)
{
    const fm_vec3_t up = c->up;
    const float above = c->radius + c->step, step_eps = cb_len_tol(c, CB_STEP_EPS);
    coll_ray_hit_t hit;
    if (!cb_ray(c, v3_madd(cb_foot(c, pos), up, above), v3_scale(up, -1.0f), above, &hit) ||
        !v3_finite(hit.normal) || !isfinite(hit.distance))
        return false;
    const float gap = hit.distance - above;
    if (!(gap < -step_eps) || !(v3_dot(hit.normal, up) >= c->body->cos_floor_max_angle)) return false;
    if (hit.instance && (hit.instance->flags & COLL_INSTANCE_ONE_WAY)) return false; /* jumped up through */
    fm_vec3_t p = pos;
    return !stand_on(c, &p, gap, hit.normal);
}

/* The crack rule over a walkable floor `hit`, `gap` below the foot (< 0: above it), as
 * coll_cb_probe_floor asks it over the floor its foot ray finds directly and held_over over
 * one found past a steep face: the ball does not reach that floor (ball_reaches_floor), the
 * edge it met first may be a side of a gap or hole (level_beyond, piece_beyond,
 * piece_behind), and the edges hold it (ball_held) higher than the floor by more than the
 * step tolerance: then *w is where it is held and *far its far contact. Inline in both
 * callers (ball_reaches_floor is asked on every grounded step: as it, a call of its own on
 * that path costs the console's walk). */
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline bool crack_held(const cb_ctx_t *c, fm_vec3_t pos, float reach, const coll_ray_hit_t *hit, float gap,
                              support_t *w, fm_vec3_t *far)
{
    coll_sweep_hit_t edge;
    float edge_len;
    bool hole_only = false; /* only a hole can hold it (piece_beyond) */
    return !ball_reaches_floor(c, pos, hit, &edge, &edge_len) &&
           (gap > c->contact_eps || level_beyond(c, pos, &edge, gap) ||
            (hole_only = piece_beyond(c, pos, &edge, hit)) || piece_behind(c, pos, &edge, edge_len, hit)) &&
           ball_held(c, pos, reach, hit, gap, &edge, edge_len, hole_only, false, w, far) &&
           w->gap < gap - cb_len_tol(c, CB_STEP_EPS);
}

/* The crack rule (crack_held) over a walkable floor found past a steep face `gap` below the
 * foot: where the edges hold the ball, *s is where. Kept out of line: a rare path, and
 * inlined its locals grew the caller's frame (every walking step paid for it: the
 * console's walk +0.7 %). */
static __attribute__((noinline)) void held_over(const cb_ctx_t *c, fm_vec3_t pos, float reach,
                                                const coll_ray_hit_t *hit, float gap, support_t *s)
{
    support_t w;
    fm_vec3_t far;
    if (crack_held(c, pos, reach, hit, gap, &w, &far)) *s = w;
}

/* Standing steep on a face over the foot with no floor in reach under it: the walkable
 * edges the foot went down past this step, that hold the body's own ball at the foot above
 * it. The ball, its bottom at the foot, overlaps them; resting on one l across up from the
 * foot, its bottom is r - sqrt(r^2 - l^2) under that contact (on a walkable face: where it
 * clears the face's plane). Only walkable contacts no higher than the foot was before the
 * step (a face's: its rest; the rule never lifts the body over where it was). The lowest rest at which those up to it hold the ball from all sides (dirs_around:
 * a crack's two edges) is *s, not steep: the foot is in the step zone, inside the steep
 * piece itself, and the ball meets that piece's edges 0.15-0.30 m deep (what the body
 * stands on, not what holds it up): the highest rest would lift it out of the piece.
 * highest (ball_held's last look, the body not on a steep piece): the highest rest, where
 * they all hold the ball from all sides: a ball lowered along up at the foot stops on the
 * highest of them. In a V valley's slot the top edges of the slot's walls (edge contacts
 * of steep faces, with walkable normals) surround the foot first, lower than the slopes'
 * faces beside them, which the ball rests on: held on those edges the foot stood 3.17 mm
 * under the checker's least rest, on the faces (soak s102 l395, the seed's run). */
static __attribute__((noinline)) void edges_over_foot(const cb_ctx_t *c, fm_vec3_t pos, bool highest, support_t *s)
{
    const fm_vec3_t up = c->up, foot = cb_foot(c, pos);
    const float r = c->radius;
    const char_body_t *b = c->body;
    const fm_vec3_t before = owner_position(b);
    const float level = v3_dot(v3_sub(before, pos), up) + cb_len_tol(c, CB_STEP_EPS);
    if (!(level > 0.0f)) return;
    coll_contact_t ct[CB_BALL_CONTACTS];
    fm_vec3_t dir[CB_BALL_CONTACTS];
    float rest[CB_BALL_CONTACTS];
    uint32_t at[CB_BALL_CONTACTS];
    const uint32_t n = cb_ball_overlaps(c, v3_madd(foot, up, r), r, ct);
    const float tol = cb_len_tol(c, 1e-5f);
    uint32_t m = 0;
    for (uint32_t i = 0; i < n; i++) {
        const fm_vec3_t d = v3_sub(ct[i].point, foot), side = v3_reject(d, up);
        const float h = v3_dot(d, up), l2 = v3_len2(side);
        /* its side: where the contact is across up from the foot (an edge's normal leans
         * the other way; an edge 0.4 mm off the foot's column left the normal's lean at
         * rounding, where the point's own offset is still exact) */
        const float nu = v3_finite(ct[i].normal) ? v3_dot(ct[i].normal, up) : 0.0f;
        if (!(nu >= b->cos_floor_max_angle) || !(l2 < r * r) || !(h > 0.0f) ||
            !(l2 > tol * tol)) /* (right under the foot: no side) */
            continue;
        /* On a walkable face (not an edge or a corner) the ball rests where it clears the
         * face's plane, raised depth / n.up; through the contact point alone it stays in the
         * face. That rest, not the sunk ball's nearest point of the face (anywhere up the
         * slope), is what may not be over where the foot was. Walking at 6.4 m/s (r 0.35)
         * down a V valley's 43-degree slope across its 0.12 m slot, the step zone's slide
         * sank the foot 71 mm under the slot's edges; the faces' nearest points lay over
         * the foot's old level, the slot's edges alone were counted, and the foot stood on
         * them, 52.5 mm under the ball resting on the 36-degree face ahead (soak s127 l14). */
        const coll_sweep_hit_t on = {ct[i].point, ct[i].normal, 0.0f, ct[i].depth, ct[i].id, ct[i].type,
                                     ct[i].triangle, ct[i].instance, ct[i].body};
        fm_vec3_t fn;
        const bool face = coll_cb_face_normal(&on, &fn);
        const float hr = face ? ct[i].depth / nu : h - (r - sqrtf(r * r - l2));
        if (!((face ? hr : h) <= level)) continue;
        /* sorted by rest, lowest first */
        uint32_t k = m++;
        for (; k > 0 && rest[k - 1] > hr; k--) {
            rest[k] = rest[k - 1];
            dir[k] = dir[k - 1];
            at[k] = at[k - 1];
        }
        rest[k] = hr;
        dir[k] = v3_scale(side, 1.0f / sqrtf(l2));
        at[k] = i;
    }
    for (uint32_t k = highest && m > 2 ? m : 2; k <= m; k++)
        if (dirs_around(c, dir, k)) {
            const coll_contact_t *e = &ct[at[k - 1]];
            *s = (support_t){true, false, -rest[k - 1], up, e->point, e->id, NULL};
            return;
        }
}

/* Still on a steep face found above the foot, with no walkable face between it and the foot:
 * the foot may be over a crack, and the look past the face (which reaches down to the foot
 * only) never meets the floor through it. The foot ray continued below the foot, within
 * reach: a walkable floor there is asked the crack rule (held_over), and where the edges
 * around the foot hold the ball above the foot (by more than half the step tolerance, as a
 * floor over the foot past the face is taken) and no higher than the steep face over it
 * (else the rule's ball rests on something above the face, up to a step over the foot: not
 * a crack under it; ungated it lifted bodies 0.26-0.63 m and left one hanging at rest beside
 * walkable geometry, soak s30 l391), the body stands on them, lifted. Running
 * into a rotated box's face 51 degrees off up (steep for 31.6) that rises through a field of
 * floor tiles with 6.8 mm gaps (r 0.54, step 0.67), the body stood steep on the face and
 * slid down it; the foot guard put the foot into a gap beside a tile's side, and the foot
 * stood 24 mm under the tile tops around it, 0.31 m under the face (soak s65 l209). Kept
 * out of line: a rare path (a steep face over the foot). With no walkable floor in reach
 * under the foot, or one the crack rule's ball does not rest over at or under the face, the
 * edges the foot went down past (edges_over_foot): the body stood steep on a rotated
 * slab's face 36 degrees off up (steep for 35.2) that dips into a field of floor tiles 0.10
 * m high with 15 mm cracks between them; sliding down it the foot went off a tile's edge
 * into a crack, over a lower face of the same slab 3.5 mm under it, 10.4 mm under the tile
 * tops (soak s67 l164: r 0.41, not grounded before, so the foot ray's reach was contact_eps;
 * later, falling back onto that face, the foot landed in the crack 26.9 mm under them; and
 * sliding along the face's foot, 54 mm down another crack in one step, the room floor in
 * reach through it, the rule's ball dropped from the sweep capsule rested on nothing; or
 * held it 0.30 m over the foot, higher than the face). */
/* steep_over_crack's gate: the edges hold the body walkable, above the foot (by more than
 * half the step tolerance) and no higher than the steep face `face` over it. */
static inline bool lifts_under_face(const support_t *w, const support_t *face, float step_eps)
{
    return !w->steep && w->gap < -0.5f * step_eps && w->gap >= face->gap - step_eps;
}

static __attribute__((noinline)) void steep_over_crack(const cb_ctx_t *c, fm_vec3_t pos, float reach, support_t *s)
{
    const float step_eps = cb_len_tol(c, CB_STEP_EPS);
    coll_ray_hit_t h;
    support_t w = *s; /* written only where the edges hold the ball */
    if (cb_ray(c, v3_madd(cb_foot(c, pos), c->up, step_eps), v3_scale(c->up, -1.0f), reach + step_eps, &h) &&
        v3_finite(h.normal) && v3_finite(h.point) && isfinite(h.distance) &&
        v3_dot(h.normal, c->up) >= c->body->cos_floor_max_angle) {
        held_over(c, pos, reach, &h, h.distance - step_eps, &w);
        if (lifts_under_face(&w, s, step_eps)) {
            *s = w;
            return;
        }
        w = *s;
    }
    edges_over_foot(c, pos, false, &w);
    if (lifts_under_face(&w, s, step_eps)) *s = w;
}

bool coll_cb_probe_floor(const cb_ctx_t *c, fm_vec3_t *pos, bool was_grounded, bool jumping)
{
    char_body_t *b = c->body;
    fm_vec3_t up = c->up;
    float above = c->radius + c->step;            /* ray origin above the foot */
    const float contact_eps = c->contact_eps, step_eps = cb_len_tol(c, CB_STEP_EPS);
    float reach = was_grounded ? c->snap : contact_eps;
    support_t s; /* only what is read is written: the rest when found */
    s.found = false;
    /* the foot ray's floor, where the crack rule held the ball between an edge and it */
    support_t floor_s;
    bool edge_and_floor = false;
    bool fits = true;
    if (!jumping) {
        fm_vec3_t origin = v3_madd(cb_foot(c, *pos), up, above);
        coll_ray_hit_t hit;
        /* The ray reaches floor_snap_distance below the foot, and where the settings let the
         * sweep capsule rest on a walkable slope farther below the foot than that (r / cos of
         * the steepest walkable angle - (r + step) > snap, below), that far: else a body
         * resting on such a slope never sees it (soak s1 l7: 0.37 m, snap 0.29). */
        float depth = c->snap;
        if (c->radius > (c->radius + c->step + c->snap - contact_eps) * b->cos_floor_max_angle)
            depth = (c->radius + contact_eps) / b->cos_floor_max_angle - (c->radius + c->step);
        bool found = cb_foot_ray(c, origin, above + depth, &hit, false) &&
                     v3_finite(hit.normal) && v3_finite(hit.point);
        if (found) {
            float gap = hit.distance - above; /* > 0: floor below the foot; < 0: above it (a step) */
            float nu = v3_dot(hit.normal, up);
            if (nu >= b->cos_floor_max_angle) {
                /* A one-way platform is a floor within a step of the foot, not one the
                 * body fell back into after jumping up through it short of its top. */
                bool one_way_deep = hit.instance && (hit.instance->flags & COLL_INSTANCE_ONE_WAY) && gap < -c->step;
                /* A walkable slope steeper than the capsule's bottom allows (r / cos > r +
                 * step: the seed's "radius and stepping height must allow the angle") holds
                 * the sweep capsule's bottom ball r / cos - (r + step) above the foot's
                 * point on it: landing there is standing on it, as walking onto it is.
                 * Touching it is within contact_eps of its plane, contact_eps / cos along
                 * up (contact_eps along up missed a body resting a skin off a slope 62
                 * degrees off up, wedged against a steep wall, for ever: soak s4 l385). */
                float rest = c->radius / nu - (c->radius + c->step);
                if (gap > reach && rest > reach && gap <= rest + contact_eps / nu && !one_way_deep &&
                    resting_on(c, *pos, hit.normal))
                    reach = gap;
                else if (gap > reach && !one_way_deep && resting_beside(c, *pos, gap))
                    reach = gap;
                else if (gap > reach && !one_way_deep &&
                         (gap <= 2.0f * contact_eps || gap <= c->radius * (1.0f - nu) / nu + contact_eps) &&
                         (held_over_floor(c, *pos, gap) || at_rest_on(c, *pos, &hit, gap)))
                    reach = gap;
                else if (gap > reach && !one_way_deep && !was_grounded && held_on_edge(c, *pos))
                    reach = gap;
                if (gap <= reach && !one_way_deep) {
                    s = (support_t){true, false, gap, hit.normal, hit.point, hit.id, hit.instance};
                    /* A gap between two surfaces at one level narrower than the capsule
                     * (modular tiles over a base floor, a groove between two low blocks):
                     * the capsule rests on their edges, not on the floor the foot point
                     * finds through the gap, however it came there (stepping down into
                     * it, landing in it, walking along the floor into it); a stair's next
                     * tread stays a step down. */
                    support_t w;
                    fm_vec3_t far;
                    if (crack_held(c, *pos, reach, &hit, gap, &w, &far)) {
                        /* the ball between an edge and the very floor under the foot:
                         * either of its contacts on it (the first, or the roll's end;
                         * only the roll's end counted, soak s3 l124) */
                        if (fabsf(v3_dot(v3_sub(far, hit.point), hit.normal)) <= contact_eps ||
                            fabsf(v3_dot(v3_sub(w.point, hit.point), hit.normal)) <= contact_eps) {
                            floor_s = s;
                            edge_and_floor = true;
                        }
                        s = w;
                    }
                }
            } else if (nu > 0.0f) {
                /* Steep: the sweep capsule rests on it, its bottom ball r away from the plane,
                 * which puts the plane r / cos - (r + step) below the foot along up. Only
                 * that close (plus CB_MARGIN, 1 cm) is standing on it; higher up the body is falling.
                 * Within the snap distance only (the ray's longer reach is for walkable slopes). */
                float rest = c->radius / nu - (c->radius + c->step);
                if (gap <= (rest > 0.0f ? rest : 0.0f) + cb_len_tol(c, CB_MARGIN) && gap <= c->snap)
                    s = (support_t){true, true, gap, hit.normal, hit.point, hit.id, hit.instance};
                /* The steep face's low edge over a walkable floor (the wedge under a ramp or
                 * overhang): the face is found above the foot, and the floor, found by the
                 * same ray continued past it, is above the foot too. The body stands on that
                 * floor (lifted onto it; no room for the lift reverts the step), not on the
                 * face with its foot sunk into the floor. */
                coll_ray_hit_t under;
                float past = hit.distance + c->skin;
                /* (up to six faces: in a triangle soup and its near copy every steep face
                 * comes twice; over a foot inside the soup, four steep faces lay above the
                 * walkable one 0.18 m over it, and with three looks the body stood steep,
                 * its foot 179 mm under that floor: soak s22 l192) */
                for (int k = 0; k < 6 && s.found && s.steep && gap < -step_eps && past < above - step_eps; k++) {
                    if (!cb_ray(c, v3_madd(origin, up, -past), v3_scale(up, -1.0f), above - past, &under) ||
                        !v3_finite(under.normal) || !v3_finite(under.point) || !isfinite(under.distance))
                        break;
                    if (!(under.distance > 0.0f) && under.triangle < 0) {
                        floor_over_foot(c, *pos, -gap, &s); /* inside a collider body's slab */
                        break;
                    }
                    float g2 = under.distance + past - above;
                    if (v3_dot(under.normal, up) >= b->cos_floor_max_angle) {
                        /* (over the foot by more than half the step tolerance: at a whole
                         * one, standing steep on a wall under an up 41 degrees off the room
                         * floor's normal, the foot stayed 1.00 mm under that floor, the
                         * footing oracle's limit: soak s49 l433) */
                        if (g2 < -0.5f * step_eps) {
                            s = (support_t){true, false, g2, under.normal, under.point, under.id, under.instance};
                            /* The floor past the steep face, as one the foot ray found
                             * directly: the crack rule asks whether edges around the foot
                             * hold the ball above it. Under an up 5 degrees off y the ray
                             * from over the foot met a tile's side (steep for that up) and,
                             * past it, the room floor in a hole between four tiles 0.18-0.20
                             * m high (r 0.77); the foot stood on that floor, 182 mm under the
                             * ball resting on the tiles' edges (soak s41 l186). */
                            held_over(c, *pos, reach, &under, g2, &s);
                            /* A walkable face at the steep face's low edge, level with it
                             * within the skin (a tile whose top meets a slope's bottom):
                             * the look past the face started under it. The first face met
                             * from the floor found up to the steep hit is the floor there,
                             * not the one under it (soak s18 l121: a walking step stood on
                             * the room floor 56 mm under the tile's top). */
                            coll_ray_hit_t top;
                            const float len = under.distance + 2.0f * c->skin - step_eps;
                            if (len > 0.0f &&
                                cb_ray(c, v3_madd(under.point, up, step_eps), up, len, &top) &&
                                v3_finite(top.normal) && v3_finite(top.point) && isfinite(top.distance) &&
                                top.distance > 0.0f && -v3_dot(top.normal, up) >= b->cos_floor_max_angle) {
                                float g3 = g2 - step_eps - top.distance;
                                if (g3 < -step_eps)
                                    s = (support_t){true, false, g3, v3_scale(top.normal, -1.0f), top.point, top.id,
                                                    top.instance};
                            }
                        }
                        break;
                    }
                    past += under.distance + c->skin; /* another steep face (a slab's underside) */
                }
                /* Still on the steep face above the foot (the look past it found no floor):
                 * the foot itself under a walkable face, the first along up from the foot
                 * below the steep face (floor_over_foot), stands on it, lifted. Under a
                 * tilted up the foot slid down a steep floor into a crossing of cracks
                 * between tiles, 2 mm into a tile's side that is walkable for this up (43
                 * degrees off it); the look past the face met the sides of three other
                 * tiles on its way down and never reached it (soak s4 l20: 3.1 mm). On a
                 * triangle soup half buried in the room floor the body stood on a steep
                 * soup face, its foot 34 mm under the floor (s5 l134). */
                if (s.found && s.steep && gap < -step_eps) {
                    floor_over_foot(c, *pos, -gap, &s);
                    if (s.steep) steep_over_crack(c, *pos, reach, &s);
                }
            }
        }
        /* held by the crack rule alone, over a floor the foot ray found out of reach below */
        bool edges_over_floor = false, alone = false;
        if (!s.found) {
            ball_held(c, *pos, reach, found ? &hit : NULL, 1e30f, NULL, 0.0f, false, false, &s, NULL);
            alone = s.found;
            edges_over_floor = s.found && found && floor_below(c, *pos, &hit, above);
            /* No floor in the ray's reach, or only one too steep to stand on (not a floor
             * for this up): the ball may rest on a walkable vertex there all the same. Under
             * an up 28.5 degrees off y the room floor was steep 0.245 m under the foot and
             * the ball sat on a soup face's corner (contact 21.9 degrees off up), its way off
             * into another face: at rest, never grounded (soak s124 l182). Nor over a
             * walkable floor out of reach when the body stood last step: held_on_edge (which
             * grounded it, airborne) is not asked then, and the snap does not reach. With
             * snap 0 a ball at rest on a slab's top edge (contact 5.4 degrees off up), its
             * push off blocked by a block's lower edge at its top ball, the room floor 0.112
             * m under the foot, stood one step and fell the next, for ever (soak s123 l362). */
            if (!s.found && (!found || v3_dot(hit.normal, up) < b->cos_floor_max_angle || was_grounded))
                held_on_edge_alone(c, *pos, was_grounded, &s);
        } else if (s.steep)
            wall_under_crack(c, *pos, reach, &hit, &s);
        if (s.found && !s.steep) {
            /* Stand exactly on it: lift onto a tread, snap down a ramp or small drop.
             * Swept: the capsule is wider than the foot point, so walking off a ledge its
             * edge may stop it short. A lift the capsule has no room for (a ledge or an
             * overhang above) means the body cannot stand here at all. */
            fm_vec3_t before = *pos;
            fits = stand_on(c, pos, s.gap, s.normal);
            if (!fits && (edges_over_floor || edge_and_floor)) {
                /* No room to be lifted onto the crack rule's edges: they do not hold it.
                 * Where the ball was held between an edge and the floor under the foot
                 * itself (no gap: a tile's edge beside it, seen as a wedge with the floor
                 * under a tilted up), that floor does (lifted onto it where there is room:
                 * the same test); with no floor in reach it falls on towards the one below.
                 * Over a real gap the step is still undone. */
                *pos = before;
                if (edge_and_floor) s = floor_s;
                else {
                    s.found = false;
                    c->mem->edges_no_room = true;
                }
                fits = !s.found || stand_on(c, pos, s.gap, s.normal);
            } else if (!fits && alone) {
                /* the crack rule alone held it, no floor it falls straight onto (none in the
                 * foot ray's reach at all, or one floor_below's straight fall cannot reach),
                 * and no room to be lifted onto its edges: the step is undone, and the
                 * step's retry and coll_cb_unwedge know why (soak s30 l14). Not only with no
                 * floor: under an up tilted 7.5 degrees, beside a column's vertical edge
                 * leaning into the fall, the full ball 66.8 degrees off a block's top corner
                 * (walkable at 68.2), the room floor 0.44 m under the foot (in the ray's
                 * reach, out of the airborne one): the straight retry fell 0 m, was kept,
                 * and the body hung at rest in the air for ever (soak s59 l264) */
                c->mem->crack_no_floor = true;
            }
            if (s.found && s.gap > 0.0f) snap_kept_over(c, pos, before, &s);
            /* A snap is no more than the snap distance down. Sliding off an edge into the
             * open, then straight down to the floor's plane, went 0.733 m (snap 0.696) past
             * the edge of a soup face 54 degrees off a nearly horizontal up: its plane went on,
             * the face did not, and the body stood grounded with no surface in the snap's reach
             * (soak s124 l135). The slide is not made; the snap goes straight down (as
             * snap_kept_over). */
            if (s.found && s.gap > 0.0f && v3_dot(v3_sub(before, *pos), up) > c->snap + contact_eps) {
                snap_straight(c, pos, before, s.gap);
            }
            if (c->ev) c->ev->step += v3_dot(v3_sub(*pos, before), up);
            /* sliding off a nosing on the way down moved the body across up too: that is
             * motion, and the velocity says so */
            fm_vec3_t across = v3_reject(v3_sub(*pos, before), up);
            if (v3_dot(across, across) > 0.0f) {
                b->velocity = v3_madd(b->velocity, across, 1.0f / c->dt);
                /* The snap slid off an edge across up: the foot may now be under another
                 * floor, one the step zone hid from the sweep (a tile lower than the step
                 * at a ramp's foot: soak s4 l229, the foot 202 mm inside it). The foot ray
                 * again, down to the foot: a walkable floor over the foot lifts it there. */
                coll_ray_hit_t h2;
                fm_vec3_t o2 = v3_madd(cb_foot(c, *pos), up, above);
                if (cb_ray(c, o2, v3_scale(up, -1.0f), above, &h2) && v3_finite(h2.normal) &&
                    v3_finite(h2.point) && isfinite(h2.distance) &&
                    v3_dot(h2.normal, up) >= b->cos_floor_max_angle) {
                    float g2 = h2.distance - above;
                    fm_vec3_t slid_to = *pos;
                    if (g2 < -step_eps && stand_on(c, pos, g2, h2.normal)) {
                        if (c->ev) c->ev->step += v3_dot(v3_sub(*pos, slid_to), up);
                        s = (support_t){true, false, g2, h2.normal, h2.point, h2.id, h2.instance};
                    } else if (g2 < -step_eps && s.gap > 0.0f) {
                        /* No room for that lift: the slide off took the foot under a floor
                         * it cannot stand on, so it is not made; the snap goes straight
                         * down instead (as snap_kept_over). The ball on a thin steep
                         * sliver's top edge in a triangle soup slid off it 14 mm across
                         * up, its foot under a 25-degree face of the soup the step zone
                         * hid, a face leaning over the head leaving no room: it stood
                         * 8.8 mm under that face (soak s90 l174). */
                        b->velocity = v3_madd(b->velocity, across, -1.0f / c->dt);
                        snap_straight(c, pos, before, s.gap);
                        if (c->ev) c->ev->step += v3_dot(v3_sub(*pos, slid_to), up);
                    } else if (g2 >= -step_eps) {
                        /* The foot is now over a crack the step zone hid from the snap's
                         * sweep: the crack rule again, at the foot the slide off left. The
                         * snap slid the ball off a staircase's corner 0.10 m across onto
                         * the room floor between two tiles 0.18 m high (in the step zone)
                         * 0.53 m apart, the foot 3.4 mm under the least rest on their
                         * edges (soak s148 l182). No room for that lift: it stands where the
                         * slide left it. */
                        support_t w;
                        w.found = false;
                        held_over(c, *pos, reach, &h2, g2, &w);
                        if (w.found && !w.steep && stand_on(c, pos, w.gap, w.normal)) {
                            if (c->ev) c->ev->step += v3_dot(v3_sub(*pos, slid_to), up);
                            s = w;
                        } else {
                            *pos = slid_to;
                        }
                    } else {
                        *pos = slid_to;
                    }
                }
            }
        }
    }

    b->flags &= (uint8_t)~(CB_FLAG_GROUNDED | CB_FLAG_STEEP | CB_FLAG_CARRY);
    b->floor_instance = NULL;
    if (!s.found) {
        b->floor_id = -1;
        b->floor_normal = up;
        return fits;
    }
    b->flags |= CB_FLAG_GROUNDED;
    if (s.steep) b->flags |= CB_FLAG_STEEP;
    b->floor_normal = s.normal;
    b->floor_id = s.id;
    /* A walkable floor ends any motion along up: no creep, no bounce. On a steep surface
     * the velocity stays the one the body moved with (the slide took what went into it). */
    if (!s.steep) b->velocity = v3_reject(b->velocity, up);
    if (s.instance && b->settings.follow_floor) {
        fm_vec3_t anchor = s.steep ? s.point : cb_foot(c, *pos);
        /* The world point is the local one placed again, not the anchor: the round trip
         * (world to local to world under a turned instance) leaves a residue of an ulp of
         * the coordinates, 1.02e-6 m at 14 m, over `tiny`, and the next step read it as the
         * floor's motion: over a 1e-9 s step a chord of 1018 m/s, kept on a jump off the
         * static floor (soak s61 l125). Placed by the transform coll_cb_carry_delta uses, a
         * floor that did not move has a chord of exactly 0 at any scale. */
        if (coll_transform_point_anchor(&s.instance->xf, anchor, &b->floor_local_point, &b->floor_world_point)) {
            b->floor_instance = s.instance;
            b->flags |= CB_FLAG_CARRY;
        }
    }
    return fits;
}
