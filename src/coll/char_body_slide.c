/**
 * @file char_body_slide.c
 * @brief Sweep-and-slide of the shortened capsule (Quake III bg_slidemove.c's clip planes
 *        and creases), overlap recovery (Box2D mover style) and the airborne foot guard.
 */
#include "char_body_internal.h"

/** v without its part going into plane n (a part leaving the plane is kept). */
static fm_vec3_t clip_plane(fm_vec3_t v, fm_vec3_t n)
{
    float d = v3_dot(v, n);
    return d < 0.0f ? v3_madd(v, n, -d) : v;
}

static bool outside_all(fm_vec3_t v, const fm_vec3_t *planes, int np, float tol)
{
    for (int k = 0; k < np; k++)
        if (v3_dot(v, planes[k]) < -tol) return false;
    return true;
}

/**
 * v clipped against every plane hit this step: the vector closest to v that enters none of
 * them. Like Quake III's PM_SlideMove (clip against a plane; two planes: follow their
 * crease, the cross product of the normals; three: stop), but choosing among those
 * candidates exactly: the closest valid one is the longest, since each is an orthogonal
 * projection of v. Trying one plane after another instead can slide a wide V-corner's
 * input out along the second wall and ping-pong between the walls every frame.
 */
static fm_vec3_t clip_planes(fm_vec3_t v, const fm_vec3_t *planes, int np)
{
    float tol = 1e-5f * v3_len(v);
    if (outside_all(v, planes, np, tol)) return v;
    fm_vec3_t best = v3(0.0f, 0.0f, 0.0f);
    float best_l2 = 0.0f;
    for (int i = 0; i < np; i++) {
        float d = v3_dot(v, planes[i]);
        if (d >= 0.0f) continue;
        fm_vec3_t cv = v3_madd(v, planes[i], -d);
        float l2 = v3_dot(cv, cv);
        if (l2 > best_l2 && outside_all(cv, planes, np, tol)) { best = cv; best_l2 = l2; }
    }
    for (int i = 0; i < np; i++)
        for (int j = i + 1; j < np; j++) {
            fm_vec3_t dir = v3_norm(v3_cross(planes[i], planes[j]));
            if (v3_len(dir) < 0.5f) continue;
            fm_vec3_t cv = v3_scale(dir, v3_dot(dir, v));
            float l2 = v3_dot(cv, cv);
            if (l2 > best_l2 && outside_all(cv, planes, np, tol)) { best = cv; best_l2 = l2; }
        }
    return best;
}

/**
 * Airborne, a clip against a steep (non-walkable, upward-facing) plane may not turn the
 * motion upwards: pushing into a steep slope would otherwise convert the push into climbing
 * speed every step (faster than gravity takes it back at a few m/s) and carry the body over
 * the top. When the clipped v rises faster than v0 did (or rises at all while v0 fell),
 * keep v0's rate along up and slide along the steep plane at that rate instead: away from
 * it and down while falling. v0: before clipping, v: clip_planes' result.
 */
static fm_vec3_t no_climb(const cb_ctx_t *c, fm_vec3_t v0, fm_vec3_t v, const fm_vec3_t *planes, int np)
{
    float u0 = v3_dot(v0, c->up);
    float cap = u0 > 0.0f ? u0 : 0.0f;
    if (!(v3_dot(v, c->up) > cap + 1e-6f * v3_len(v0))) return v;
    for (int k = np - 1; k >= 0; k--) {
        fm_vec3_t n = planes[k];
        float nu = v3_dot(n, c->up);
        if (nu <= 0.0f || nu >= c->body->cos_floor_max_angle) continue;
        fm_vec3_t nh = v3_norm(v3_reject(n, c->up));
        float nn = v3_dot(n, nh);
        if (!(nn > 1e-3f)) continue;
        fm_vec3_t side = v3_norm(v3_cross(n, c->up));
        /* on the plane (w.n = 0) with w.up = u0: a nh + u0 up, plus v's part along the plane's level line */
        fm_vec3_t w = v3_madd(v3_madd(v3_scale(side, v3_dot(v, side)), nh, -u0 * nu / nn), c->up, u0);
        if (outside_all(w, planes, np, 1e-5f * v3_len(v0))) return w;
        return v3(0.0f, 0.0f, 0.0f);
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
static fm_vec3_t walking_plane(const cb_ctx_t *c, fm_vec3_t pos, const coll_sweep_hit_t *hit, fm_vec3_t rem)
{
    float nu = v3_dot(hit->normal, c->up);
    float h = v3_dot(v3_sub(hit->point, cb_foot(c, pos)), c->up);
    if (nu > 0.0f && h <= c->step + cb_len_tol(c, CB_MARGIN)) return hit->normal;
    fm_vec3_t nh = v3_norm(v3_reject(hit->normal, c->up));
    /* Under the ball and the motion leaves it across up: only its part along up (down,
     * following a floor) goes into the contact, and the real normal takes just that (the
     * motion along it rises no more than it was sinking: nothing is climbed). As a wall it
     * clipped nothing and the motion met it again: with step 0 and the ball resting on a
     * 75 mm edge at a tilted up, the body stood still on free floor (soak s11 l256). */
    if (nu > 0.0f && v3_dot(rem, nh) >= 0.0f && v3_len(nh) > 0.5f) return hit->normal;
    return v3_len(nh) > 0.5f ? nh : hit->normal;
}

/* coll_cb_move_swept (step: coll_cb_step_swept, through cb_sweep_step); where it stops
 * short, *normal (when not NULL) is the normal of what
 * stopped it. */
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline float move_swept_in(const cb_ctx_t *c, fm_vec3_t *pos, fm_vec3_t d, fm_vec3_t *normal, bool step)
{
    float len = v3_len(d);
    if (!(len > c->tiny) || !isfinite(len)) {
        if (isfinite(len)) *pos = v3_add(*pos, d); /* sub-micrometre: below every tolerance */
        return 1.0f;
    }
    coll_sweep_hit_t hit;
    if (!(step ? cb_sweep_step(c, cb_sweep_center(c, *pos), c->radius, c->sweep_ihh, d, &hit)
               : cb_sweep(c, cb_sweep_center(c, *pos), c->radius, c->sweep_ihh, d, &hit)) ||
        !isfinite(hit.t)) {
        *pos = v3_add(*pos, d);
        return 1.0f;
    }
    float t = hit.t < 0.0f ? 0.0f : (hit.t > 1.0f ? 1.0f : hit.t);
    float reach = len * t;
    if (reach >= len - c->skin && !(t <= 0.0f && hit.depth > 0.0f) && v3_dot(d, c->up) <= 0.0f) {
        /* Touches only at the very end, within the skin: that is the target itself (going
         * down onto a floor; a lift's target is under the sweep capsule, what it meets above
         * is an overhang: soak s1 l347, lifted 1.04 mm into its underside). */
        *pos = v3_add(*pos, d);
        return 1.0f;
    }
    float travel = reach - c->skin;
    if (normal) *normal = hit.normal;
    if (!(travel > 0.0f)) return 0.0f;
    *pos = v3_madd(*pos, d, travel / len);
    return travel / len;
}

float coll_cb_move_swept(const cb_ctx_t *c, fm_vec3_t *pos, fm_vec3_t d)
{
    return move_swept_in(c, pos, d, NULL, false);
}

float coll_cb_step_swept(const cb_ctx_t *c, fm_vec3_t *pos, fm_vec3_t d)
{
    return move_swept_in(c, pos, d, NULL, true);
}

/**
 * Airborne, the capsule's rounded bottom resting on an edge that the foot point is already
 * past: the foot is a point, so there is nothing to stand on. Push the capsule sideways off
 * the edge (a swept move) and return how far (>= 0); -1 when the ground under the foot point
 * supports the contact (a floor or slope). The push is motion (the honest velocity shows
 * it): at most `room`, what the speed limit leaves of the step beside its other motion (a
 * 0.83 m push in a 4 ms step, soak s2 l359, went at 209 m/s); the rest is for the next step.
 */
static float slide_off_edge(const cb_ctx_t *c, fm_vec3_t *pos, const coll_sweep_hit_t *hit, float room)
{
    float nu = v3_dot(hit->normal, c->up);
    if (nu <= 0.05f) return -1.0f;
    fm_vec3_t ball = v3_madd(cb_sweep_center(c, *pos), c->up, -c->sweep_ihh);
    fm_vec3_t rel = v3_sub(ball, hit->point);
    if (v3_dot(rel, c->up) <= cb_len_tol(c, CB_STEP_EPS)) return -1.0f; /* not under the bottom ball */
    /* A plane under the contact lies r / nu below the ball centre along the axis. */
    float reach = c->radius / (nu > 0.1f ? nu : 0.1f) + 2.0f * cb_len_tol(c, CB_MARGIN);
    coll_ray_hit_t rh;
    if (cb_ray(c, ball, v3_scale(c->up, -1.0f), reach, &rh))
        return -1.0f;
    fm_vec3_t h = v3_reject(rel, c->up);
    float hl = v3_len(h);
    fm_vec3_t dir = hl > cb_len_tol(c, 1e-5f) ? v3_scale(h, 1.0f / hl) : v3_norm(v3_reject(hit->normal, c->up));
    if (v3_len(dir) < 0.5f) return -1.0f;
    float need = cb_off_edge_push(c, hl);
    if (need <= 0.0f) return -1.0f;
    if (need > room) need = room;
    if (!(need > c->tiny)) return -1.0f;
    fm_vec3_t d = v3_scale(dir, need);
    coll_sweep_hit_t h2;
    if (cb_sweep(c, cb_sweep_center(c, *pos), c->radius, c->sweep_ihh, d, &h2)) {
        float travel = need * h2.t - c->skin;
        if (!(travel > 0.0f)) return 0.0f;
        *pos = v3_madd(*pos, dir, travel);
        return travel;
    }
    *pos = v3_add(*pos, d);
    return need;
}

/** Height along up of the walkable floor under point p (searched from `above` over it down
 *  to `below` under it), relative to ref; false when there is none. foot: the ray is
 *  remembered (cb_foot_ray). */
static bool floor_height(const cb_ctx_t *c, fm_vec3_t p, float above, float below, fm_vec3_t ref, float *h,
                         bool foot)
{
    const char_body_t *b = c->body;
    coll_ray_hit_t rh;
    fm_vec3_t o = v3_madd(p, c->up, above);
    if (!(foot ? cb_foot_ray(c, o, above + below, &rh, true) : cb_ray(c, o, v3_scale(c->up, -1.0f), above + below, &rh)) ||
        v3_dot(rh.normal, c->up) < b->cos_floor_max_angle)
        return false;
    *h = v3_dot(v3_sub(rh.point, ref), c->up);
    return true;
}

/**
 * Walking, blocked by the rounded edge of something low (the contact is under the bottom
 * ball's centre): step over it as Quake III's PM_StepSlideMove does. Lift the sweep capsule
 * by step_height, move the rest of the motion across up, come back down by the lift. The
 * seed's shortened capsule alone stops at the edge of the riser after the next one before
 * the foot reaches the next tread on ordinary stairs (treads under about 0.45 m with the
 * default capsule). The result is kept when, measured from the floor under the foot at the
 * start (`base`; the body may be riding on a nosing above it):
 *  - the foot came down onto walkable floor at most step_height above base: it is lifted
 *    onto it at once, so the rest of the step goes on from the tread; or
 *  - the capsule came down onto the nosing of a later riser, at most step_height above
 *    base, and between the foot and that nosing lies a tread higher than base and at most
 *    step_height above it: the body rides the nosing until the foot is over that tread
 *    (its foot stays below the tread height meanwhile, as the geometry guarantees).
 * A riser taller than step_height is never climbed, at any rate: there is no tread in reach.
 * left: the motion still to do. *moved: the fraction of its part across up travelled.
 */
static bool try_step(const cb_ctx_t *c, fm_vec3_t *pos, fm_vec3_t left, const coll_sweep_hit_t *hit, float *moved)
{
    if (!(v3_dot(hit->normal, c->up) > 0.0f) || !(c->step > 0.0f)) return false;
    fm_vec3_t h = v3_reject(left, c->up);
    float hl = v3_len(h);
    if (!(hl > cb_len_tol(c, 1e-5f))) return false;
    const float above = c->radius + c->step, eps = cb_len_tol(c, CB_STEP_EPS);
    fm_vec3_t foot0 = cb_foot(c, *pos);
    float base;
    if (!floor_height(c, foot0, above, c->snap, foot0, &base, false)) return false;
    fm_vec3_t p = *pos;
    float lift = c->step * coll_cb_step_swept(c, &p, v3_scale(c->up, c->step));
    if (!(lift > cb_len_tol(c, 1e-4f))) return false;
    float f = coll_cb_step_swept(c, &p, h);
    if (!(f * hl > cb_len_tol(c, 1e-4f))) return false;
    /* down by the lift, keeping the contact that stops it */
    coll_sweep_hit_t dh;
    bool hung = coll_cb_sweep_down(c, p, lift, &dh) && isfinite(dh.t);
    float travel = hung ? lift * (dh.t > 0.0f ? dh.t : 0.0f) - c->skin : lift;
    if (travel > 0.0f) {
        p = v3_madd(p, c->up, -travel);
        coll_cb_down_moved(c, p, -travel); /* the probe's ball drops from here: what it meets is known */
    }
    fm_vec3_t foot = cb_foot(c, p);
    float rise = v3_dot(v3_sub(foot, foot0), c->up) - base;
    float floor_h;
    /* (the probe's foot ray, when the body stays here) */
    if (!floor_height(c, foot, above, c->snap, foot0, &floor_h, true)) return false;
    floor_h -= base;
    if (floor_h > c->step + eps || rise > c->step + eps) return false;
    if (rise > floor_h + c->skin + eps) {
        /* riding a nosing: a higher tread within a step must lie between foot and contact */
        fm_vec3_t ahead = v3_reject(v3_sub(dh.point, foot), c->up);
        fm_vec3_t probe = v3_madd(foot, ahead, 0.75f);
        float tread;
        if (!hung || v3_len(ahead) > c->radius + eps ||
            !floor_height(c, probe, above + rise, c->snap, foot0, &tread, false))
            return false;
        tread -= base;
        if (!(tread > eps) || tread > c->step + eps) return false;
    } else if (floor_h > rise) {
        /* Up onto the tread. Within the way the lift just came down it needs no sweep: the
         * down sweep met nothing on it (nothing closer than the touch tolerance: it would
         * have stopped there), so going back up it meets nothing either. */
        fm_vec3_t d = v3_scale(c->up, floor_h - rise);
        if (travel > 0.0f && floor_h - rise <= travel) {
            p = v3_add(p, d);
            coll_cb_down_moved(c, p, floor_h - rise);
        }
        else if (coll_cb_move_swept(c, &p, d) < 1.0f) return false;
    }
    if (c->ev) c->ev->step += v3_dot(v3_sub(p, *pos), c->up);
    *pos = p;
    *moved = f;
    return true;
}

/**
 * A contact normal within ~2.5 degrees of its triangle's face normal is on that face:
 * *face is the face normal (turned to the contact's side). Grazing a flat wall or floor
 * tessellated into many triangles, the sweep can meet a seam's edge or vertex a hair before
 * the face and report a normal tilted by a few thousandths; sliding along that tilt walks
 * the capsule into the wall and costs speed, so the slide takes the face normal.
 */
bool coll_cb_face_normal(const coll_sweep_hit_t *hit, fm_vec3_t *face)
{
    fm_vec3_t n = hit->normal;
    const coll_mesh_instance_t *in = hit->instance;
    if (!in || !in->mesh || hit->triangle < 0) return false;
    fm_vec3_t v[3];
    coll_mesh_triangle(in->mesh, (uint32_t)hit->triangle, v);
    /* world-space face normal: local normal through the inverse scale, then the rotation */
    fm_vec3_t ln = v3_cross(v3_sub(v[1], v[0]), v3_sub(v[2], v[0]));
    const fm_vec3_t *sc = &in->xf.scale;
    if (sc->x == 0.0f || sc->y == 0.0f || sc->z == 0.0f) return false;
    ln = v3(ln.x / sc->x, ln.y / sc->y, ln.z / sc->z);
    fm_vec3_t wn;
    fm_quat_rotate_vec3(&wn, &in->xf.rot, &ln);
    wn = v3_norm(wn);
    float d = v3_dot(wn, n);
    if (d < 0.0f) { wn = v3_scale(wn, -1.0f); d = -d; }
    if (!(d > 0.999f)) return false;
    *face = wn;
    return true;
}

/** Step events of a slide hit: a ceiling met moving up, a wall (the plane slid along). */
static void record_hit(const cb_ctx_t *c, fm_vec3_t motion, fm_vec3_t plane, fm_vec3_t normal)
{
    float nu = v3_dot(normal, c->up);
    if (nu < -0.3f) {
        if (v3_dot(motion, c->up) > 0.0f) c->ev->flags |= CHAR_BODY_EVENT_HIT_CEILING;
    } else if (v3_dot(plane, c->up) < c->body->cos_floor_max_angle) {
        c->ev->flags |= CHAR_BODY_EVENT_HIT_WALL;
        c->ev->wall_normal = plane;
    }
}

/**
 * Walking, a slide never ends up against the input across up (Quake III's PM_SlideMove
 * stops a move that turns against the primal velocity). Its clips cannot turn the motion
 * back (each is a projection of the intended motion), but its position corrections can:
 * the skin top-ups along a contact's real normal and the nudges off a plane met again
 * add up in a corner or wedge, and under a tilted up a wall that leans over the body is
 * slid along as a vertical one, so the motion climbing it moves away from it. Where that
 * left the body behind its start along the input, it goes back to the start and makes only
 * the rest of the slide's motion (swept, with nothing along the input): it stops rather
 * than walks backwards. start: where the slide began; disp: its intended motion. True when
 * the slide was redone.
 */
static bool no_backwards(const cb_ctx_t *c, fm_vec3_t *pos, fm_vec3_t start, fm_vec3_t disp)
{
    fm_vec3_t ih = v3_reject(disp, c->up);
    float il = v3_len(ih);
    if (!(il > c->tiny)) return false;
    fm_vec3_t dir = v3_scale(ih, 1.0f / il), d = v3_sub(*pos, start);
    float along = v3_dot(d, dir);
    if (!(along < -cb_len_tol(c, CB_BACK_TOL))) return false;
    *pos = start;
    coll_cb_move_swept(c, pos, v3_madd(d, dir, -along));
    return true;
}

/* fall_on runs only when a slide in the air is stopped dead: out of the slide loop */
#if defined(__GNUC__)
#define FALL_ON_COLD __attribute__((noinline, cold))
#else
#define FALL_ON_COLD
#endif

/**
 * Stopped dead in the air (nothing of the motion is left: rem) while falling, the input
 * across up pushing the body into a corner whose only way on is up a crease blocked above
 * (a walkable edge or vertex under the ball, a wall, a face over it): the input does not
 * hold the body up against gravity. The fall alone (the motion's part along up, want's)
 * slides on, with a sweep of its own; the velocity keeps its part along up, clipped the
 * same way. Else the body hung at rest 1.1 m over the floor for ever, its velocity clipped
 * to 0 every step (soak s9 l80: r 0.97, max_slides 2, 11 m/s into a soup's vertex 67
 * degrees off up, the room wall beside it, a soup face over it). True when it slides on.
 */
static FALL_ON_COLD bool fall_on(const cb_ctx_t *c, fm_vec3_t want, fm_vec3_t vel0, const fm_vec3_t *planes, int np,
                                fm_vec3_t *rem, fm_vec3_t *vel)
{
    const float fall = v3_dot(want, c->up);
    if (v3_len(*rem) > c->tiny || !(fall < 0.0f) || !(v3_len(v3_reject(want, c->up)) > c->tiny)) return false;
    const fm_vec3_t wf = v3_scale(c->up, fall);
    const fm_vec3_t r = no_climb(c, wf, clip_planes(wf, planes, np), planes, np);
    if (!(v3_len(r) > c->tiny)) return false;
    *rem = r;
    if (vel) {
        const fm_vec3_t vf = v3_scale(c->up, v3_dot(vel0, c->up));
        *vel = no_climb(c, vf, clip_planes(vf, planes, np), planes, np);
    }
    return true;
}

/**
 * Each skin top-up or nudge is checked by the next sweep (which then starts inside and
 * takes it back), but those after the slide's last sweep by nothing: they must not end in
 * a plane the slide met before. In a slot a hair wider than the capsule, between the room
 * wall and a face 1.2 degrees off it, the last top-up and nudge off the face went 1.17 mm
 * into the wall met two sweeps earlier (soak s100 l255). Their part into such a plane is
 * dropped (the place before them, a sweep's end, was clear).
 */
static void last_corr_clear(const cb_ctx_t *c, fm_vec3_t *pos, fm_vec3_t corr, const fm_vec3_t *planes, int np)
{
    fm_vec3_t t = corr;
    bool cut = false;
    for (int i = 0; i < np; i++) {
        const float into = v3_dot(t, planes[i]);
        if (into < -c->tiny) { /* more than rounding */
            t = v3_madd(t, planes[i], -into);
            cut = true;
        }
    }
    if (cut) *pos = v3_add(v3_sub(*pos, corr), t);
}

void coll_cb_slide(const cb_ctx_t *c, fm_vec3_t *pos, fm_vec3_t disp, fm_vec3_t *vel, bool grounded)
{
    const fm_vec3_t start = *pos;
    bool touched = false; /* a sweep met something: only then can the slide have gone back */
    int step_ups = 0;
    const char_body_t *b = c->body;
    fm_vec3_t planes[CB_MAX_PLANES];
    int np = 0;
    fm_vec3_t rem = disp;
    /* Each clip starts from the intended motion and velocity (scaled by the time left), not
     * from the last clipped one: clipping an already-clipped leftover again can turn it
     * back out of a wide corner and ping-pong (Quake's primal_velocity check, made exact). */
    const fm_vec3_t vel0 = vel ? *vel : v3(0.0f, 0.0f, 0.0f);
    float time_left = 1.0f;
    float pushed = 0.0f; /* by slide_off_edge, within the speed limit */
    fm_vec3_t topup = v3(0.0f, 0.0f, 0.0f); /* the last sweep's skin top-up, if nothing moved since */
    fm_vec3_t untopped = *pos;                /* where that top-up started */
    fm_vec3_t corr = v3(0.0f, 0.0f, 0.0f);    /* top-up and nudges since the last swept or verified move */
    int slides = b->settings.max_slides;
    bool fell = false; /* stopped dead in the air, the fall alone slid on (below) */
    bool wall_at_once = false; /* the first sweep met at once, in the air, what cannot hold the body up */
    bool under_edge = false, over_face = false; /* contacts met in the air (the same) */
    for (int it = 0; it < slides; it++) {
        float len = v3_len(rem);
        if (!(len > c->tiny)) break;
        coll_sweep_hit_t hit;
        if (!cb_sweep_slide(c, cb_sweep_center(c, *pos), rem, &hit)) {
            *pos = v3_add(*pos, rem);
            corr = v3(0.0f, 0.0f, 0.0f); /* the free sweep started clear of everything */
            break;
        }
        if (!v3_finite(hit.normal) || !isfinite(hit.t)) break;
        touched = true;
        fm_vec3_t fn;
        if (coll_cb_face_normal(&hit, &fn)) hit.normal = fn;
        float t = hit.t < 0.0f ? 0.0f : (hit.t > 1.0f ? 1.0f : hit.t);
        float done = 0.0f; /* fraction of rem actually travelled */
        if (t <= 0.0f && hit.depth > 0.0f) {
            /* Started inside: step out along the push-out direction first, verified
             * (not swept: a sweep from inside stops at once); a push that would end
             * inside something else ends the slide here instead. */
            if (v3_dot(topup, topup) > 0.0f && hit.depth <= v3_len(topup) + c->min_depth) {
                /* Only the last skin top-up put it there (the place before it was clear:
                 * the sweep that led there met nothing sooner): take the top-up back and
                 * slide along this plane too. In a crease the top-up off one wall goes
                 * into the other; pushing out of that one goes into the first again.
                 * "Clear" is within the sweep's touch tolerance (min_depth): a body resting
                 * 0.05 mm into an overhang, topped up 1 mm off the floor under it, was
                 * 1.01 mm in and not recognised (soak s3 l385, a 1.01 mm penetration). */
                *pos = untopped;
            } else {
                float d = hit.depth < c->radius ? hit.depth : c->radius;
                /* Where half a skin more has no room (a crease narrower than the capsule
                 * plus that), a shallow overlap (under the skin: a top-up's creep) is pushed
                 * out to touching, verified the same way: every sweep from inside it starts
                 * inside, so else the slide ended here on every step whatever the input.
                 * Against the room wall and a box stack's vertical edge 0.15 mm beside the
                 * capsule, top-ups off a tile's edge under the ball crept it 0.113 mm into
                 * the wall, and it never moved again, the input turned away included (soak
                 * s69 l158). */
                if (!coll_cb_push_verified(c, pos, v3_scale(hit.normal, d + c->skin * 0.5f)) &&
                    !(hit.depth < c->skin && coll_cb_push_verified(c, pos, v3_scale(hit.normal, d)))) {
                    /* No way out along the push: where the skin top-up and nudges since the
                     * last swept move went into this contact, take them back (the place
                     * before them was no deeper: the sweep that led there met nothing
                     * sooner). In a slot a hair wider than the capsule, between a wall and
                     * a vertex leaning over the body under a tilted up, the top-up and the
                     * nudge off the wall put the capsule 1.07 mm into the vertex, the nudge
                     * hid the top-up from the test above, and the slide ended there (soak
                     * s11 l137; 0.07 mm after the take-back). */
                    if (v3_dot(corr, hit.normal) < 0.0f) *pos = v3_sub(*pos, corr);
                    corr = v3(0.0f, 0.0f, 0.0f);
                    break;
                }
            }
            topup = v3(0.0f, 0.0f, 0.0f);
            corr = topup;
        } else {
            /* Advance to the contact, backing off the skin along the motion; at grazing
             * angles that leaves less than the skin between capsule and plane, so top the
             * separation up along the normal (sliding along a wall never creeps into it). */
            float travel = len * t - c->skin;
            float back = c->skin;
            if (travel > 0.0f) {
                done = travel / len;
                *pos = v3_madd(*pos, rem, done);
            } else {
                back = len * t;
            }
            float sep = back * -v3_dot(rem, hit.normal) / len;
            topup = sep < c->skin ? v3_scale(hit.normal, c->skin - (sep > 0.0f ? sep : 0.0f)) : v3(0.0f, 0.0f, 0.0f);
            untopped = *pos;
            *pos = v3_add(*pos, topup);
            corr = topup;
        }
        /* In the air, a first sweep that met at once what the body already rests against
         * (it travelled no more than the skin) is not a slide: the clipped motion still gets its sweep.
         * Else with max_slides 1 a body touching a wall, a steep face or an edge never
         * moves again, not even to fall along it (soak: 10 bodies hung at rest). Nor is a
         * second one right after it where the slides would end there, when neither contact
         * can hold the body up (walls, steep faces, ceilings: not walkable): pressed into a
         * corner, the crease between them, the fall along it, still gets its sweep. With one
         * slide, pushed by its input into the room wall and a staircase block's vertical
         * edge, a body hung at rest 1.8 m over the floor for ever, its fall clipped to the
         * vertical crease and never swept (soak s136 l236). (A walkable contact holds it: the
         * floor probe's edge rules stand it there, soak s89 l214.) */
        if (!grounded && len * t <= 2.0f * c->skin) {
            const bool holds = v3_dot(hit.normal, c->up) >= b->cos_floor_max_angle;
            if (it == 0) {
                slides++;
                wall_at_once = !holds;
            } else if (it == 1 && wall_at_once && !holds && it + 1 >= slides) {
                slides++;
            }
        }
        /* The untravelled rest, skin included, slides on: no speed lost to the skin. */
        fm_vec3_t left = v3_scale(rem, 1.0f - done);
        time_left *= 1.0f - done;
        if (!grounded && v3_dot(left, c->up) < 0.0f) {
            float off = slide_off_edge(c, pos, &hit, c->max_speed * c->dt - v3_len(disp) - pushed);
            if (off >= 0.0f) {
                pushed += off;
                topup = corr = v3(0.0f, 0.0f, 0.0f);
                rem = left;
                continue;
            }
        }
        fm_vec3_t n = grounded ? walking_plane(c, *pos, &hit, rem) : hit.normal;
        /* Walking, a first sweep that met a walkable floor in the step zone (the foot of a
         * ramp) is the body following the floor, not a slide off an obstacle: the motion
         * along that floor still gets its sweep. Else with max_slides 1 a body stops at the
         * foot of every ramp, step after step (soak s3 l438: a 5 degree ramp). */
        if (it == 0 && grounded && v3_dot(n, c->up) >= b->cos_floor_max_angle) slides++;
        if (c->ev) record_hit(c, rem, n, hit.normal);
        float stepped = 0.0f;
        if (grounded && step_ups < 2 && v3_dot(n, hit.normal) < 0.9999f && try_step(c, pos, left, &hit, &stepped)) {
            step_ups++;
            topup = corr = v3(0.0f, 0.0f, 0.0f);
            rem = v3_scale(v3_reject(left, c->up), 1.0f - stepped);
            time_left *= 1.0f - stepped;
            continue;
        }
        bool known = false;
        for (int i = 0; i < np; i++)
            if (v3_dot(planes[i], n) > 0.9999f) known = true;
        if (!known && np < CB_MAX_PLANES) planes[np++] = n;
        if (known) {
            /* Same plane again (numerical touch): nudge off it so the next sweep starts clear. */
            *pos = v3_madd(*pos, n, c->skin * 0.1f);
            corr = v3_madd(corr, n, c->skin * 0.1f);
            topup = v3(0.0f, 0.0f, 0.0f);
        }
        fm_vec3_t want = v3_scale(disp, time_left);
        rem = clip_planes(want, planes, np);
        if (vel) *vel = clip_planes(vel0, planes, np);
        if (!grounded) {
            rem = no_climb(c, want, rem, planes, np);
            if (vel) *vel = no_climb(c, vel0, *vel, planes, np);
            /* stopped dead, wedged by the input: the fall alone slides on, once (fall_on) */
            const float hn = v3_dot(hit.normal, c->up);
            if (hn >= b->cos_floor_max_angle && !coll_cb_face_normal(&hit, &fn)) under_edge = true; /* an edge */
            if (hn < 0.0f) over_face = true;
            if (under_edge && over_face && !fell && fall_on(c, want, vel0, planes, np, &rem, vel)) {
                fell = true;
                if (it + 1 >= slides) slides++;
            }
        }
    }
    if (np > 1) last_corr_clear(c, pos, corr, planes, np); /* one plane: corr is off it */
    const fm_vec3_t slid = *pos;
    if (grounded && touched && no_backwards(c, pos, start, disp) && step_ups > 0 && c->ev)
        c->ev->step += v3_dot(v3_sub(*pos, slid), c->up); /* a stair step redone: its height as done */
}

/** Contacts of the sweep capsule at pos (at most CB_MAX_CONTACTS). */
static uint32_t overlaps_at(const cb_ctx_t *c, fm_vec3_t pos, coll_contact_t *ct)
{
    uint32_t n = cb_overlaps(c, cb_sweep_center(c, pos), ct, CB_MAX_CONTACTS);
    return n > CB_MAX_CONTACTS ? CB_MAX_CONTACTS : n;
}

/**
 * True when the contacts after a push (ct, n) are no worse than before (ct0, n0): every
 * contact deeper than CB_MIN_DEPTH is a feature (same triangle of the same instance, or the
 * same body) that already overlapped at least as deep. A push out of one thing must not
 * put the capsule into another (a slope's overhang, the wall behind, a mesh behind a
 * collider body).
 */
static bool no_worse(const coll_contact_t *ct, uint32_t n, const coll_contact_t *ct0, uint32_t n0, float min_depth)
{
    for (uint32_t i = 0; i < n; i++) {
        if (!(ct[i].depth > min_depth)) continue;
        bool ok = false;
        for (uint32_t j = 0; j < n0 && !ok; j++)
            ok = ct0[j].instance == ct[i].instance && ct0[j].body == ct[i].body &&
                 ct0[j].triangle == ct[i].triangle && ct[i].depth <= ct0[j].depth + min_depth;
        if (!ok) return false;
    }
    return true;
}

bool coll_cb_push_verified(const cb_ctx_t *c, fm_vec3_t *pos, fm_vec3_t delta)
{
    coll_contact_t ct0[CB_MAX_CONTACTS], ct[CB_MAX_CONTACTS];
    uint32_t n0 = overlaps_at(c, *pos, ct0);
    fm_vec3_t np = v3_add(*pos, delta);
    uint32_t n = overlaps_at(c, np, ct);
    if (!v3_finite(np) || !no_worse(ct, n, ct0, n0, c->min_depth)) return false;
    *pos = np;
    return true;
}

/** True when a contact of ct is deeper than depth. */
static bool deeper_than(const coll_contact_t *ct, uint32_t n, float depth)
{
    for (uint32_t i = 0; i < n; i++)
        if (ct[i].depth > depth) return true;
    return false;
}

/** True when the sweep capsule at pos overlaps nothing deeper than CB_MIN_DEPTH. */
static bool free_at(const cb_ctx_t *c, fm_vec3_t pos)
{
    coll_contact_t ct[CB_MAX_CONTACTS];
    uint32_t n = overlaps_at(c, pos, ct);
    for (uint32_t i = 0; i < n; i++)
        if (ct[i].depth > c->min_depth) return false;
    return true;
}

/**
 * True when the straight way from the sweep capsule's centre at `from` to its centre at `to`
 * crosses no surface outside the part of the capsule that is already in geometry: along the
 * axis segment always (a body teleported into a stack of slabs leaves along up through the
 * faces its axis is through), and within the whole capsule when it is deep in something
 * (`deep`: half a radius or more). A surface beside the axis that a shallowly overlapping
 * capsule only grazes -- a wall it was squeezed into by a millimetre -- is never crossed:
 * the free spot behind it would be through the wall or inside a solid. Winding is not
 * trusted to tell inside from outside.
 */
static bool reachable(const cb_ctx_t *c, fm_vec3_t from, fm_vec3_t to, bool deep)
{
    const char_body_t *b = c->body;
    fm_vec3_t o = cb_sweep_center(c, from), e = cb_sweep_center(c, to);
    fm_vec3_t d = v3_sub(e, o);
    float len = v3_len(d);
    if (!(len > c->tiny)) return true;
    fm_vec3_t dir = v3_scale(d, 1.0f / len);
    float axial = fabsf(v3_dot(dir, c->up)), radial = sqrtf(axial < 1.0f ? 1.0f - axial * axial : 0.0f);
    float reach = axial > 0.999f ? c->sweep_ihh : 0.0f;
    if (deep) {
        /* where the ray leaves the capsule: through the cylinder or through a cap */
        float in = c->radius - c->skin;
        float cyl = radial > 1e-6f ? in / radial : 1e30f, cap = axial > 1e-6f ? (c->sweep_ihh + in) / axial : 1e30f;
        reach = cyl < cap ? cyl : cap;
    }
    if (reach >= len) return true;
    coll_ray_hit_t h;
    return !coll_raycast(c->scene, v3_madd(o, dir, reach), dir, len - reach, b->settings.read_mask, COLL_TYPE_MESH, &h);
}

/**
 * True when moving the body from `from` to `to` pushes it down along up (by more than the
 * contact tolerance) so that its foot ends below a walkable floor right under it, by more
 * than that tolerance: the sweep capsule, short by step_height, clears that floor, the full
 * capsule stands inside it. A push out of an overhang lower than the body (a teleport under
 * it) did so, and the floor probe, with no room to lift the body back, left it standing
 * with its foot up to step_height inside the floor.
 */
static bool sinks_foot(const cb_ctx_t *c, fm_vec3_t from, fm_vec3_t to)
{
    if (!(v3_dot(v3_sub(from, to), c->up) > c->contact_eps)) return false;
    fm_vec3_t foot = cb_foot(c, to);
    float h;
    return floor_height(c, foot, c->step + c->radius, 0.0f, foot, &h, false) && h > c->contact_eps;
}

/**
 * Last resort for a body the verified recovery could not free (the game teleported it deep
 * into geometry, an up change swung it into a wall, a platform pressed it into one): move it
 * to free space -- verified free, so never into something else. Candidates, shortest first
 * within each kind: the push out along the contact normals, where those are trustworthy
 * (the capsule's axis is still in front of the surface: depth <= r; deeper, a two-sided
 * triangle's normal may point further in) and none points down hard; then rings of growing
 * distance (a quarter of the height to twice it): lifts along up first (the way games
 * unstick a player), unless a ceiling presses on it, then eight directions across up.
 * Never down: a body is not pushed through the floor, and never through a surface it does
 * not already overlap (reachable). At most 37 overlap queries, only on steps that start more than a
 * skin deep in something after the verified recovery.
 */
static void unstick(const cb_ctx_t *c, fm_vec3_t *pos, fm_vec3_t *vel)
{
    coll_contact_t ct[CB_MAX_CONTACTS];
    uint32_t n = overlaps_at(c, *pos, ct);
    const float min_depth = c->min_depth;
    float deepest = 0.0f;
    bool trust = true, ceiling = false;
    for (uint32_t i = 0; i < n; i++) {
        if (!(ct[i].depth > min_depth) || !v3_finite(ct[i].normal)) continue;
        if (ct[i].depth > deepest) deepest = ct[i].depth;
        if (ct[i].depth > c->radius) trust = false;
        float nu = v3_dot(ct[i].normal, c->up);
        if (nu < -0.1f) trust = false;
        if (nu < -0.3f) ceiling = true;
    }
    if (!(deepest > c->skin)) return;
    const bool deep = deepest >= 0.5f * c->radius;
    if (trust) {
        fm_vec3_t delta = v3(0.0f, 0.0f, 0.0f);
        for (int iter = 0; iter < 4; iter++)
            for (uint32_t i = 0; i < n; i++) {
                if (!(ct[i].depth > min_depth)) continue;
                float want = ct[i].depth + c->skin - v3_dot(delta, ct[i].normal);
                if (want > 0.0f) delta = v3_madd(delta, ct[i].normal, want);
            }
        fm_vec3_t p = v3_add(*pos, delta);
        if (v3_finite(p) && free_at(c, p) && reachable(c, *pos, p, deep) && !sinks_foot(c, *pos, p)) {
            *pos = p;
            if (vel) *vel = v3(0.0f, 0.0f, 0.0f);
            return;
        }
    }
    /* Search rings of growing distance: up first (unless a ceiling presses on it), then
     * eight directions across up. Never down. */
    fm_vec3_t side = v3_norm(v3_reject(v3(1.0f, 0.0f, 0.0f), c->up));
    if (v3_len(side) < 0.5f) side = v3_norm(v3_reject(v3(0.0f, 0.0f, 1.0f), c->up));
    fm_vec3_t side2 = v3_cross(c->up, side);
    const float h = 2.0f * c->half_height;
    const float dists[4] = {0.25f * h, 0.5f * h, h, 2.0f * h};
    for (int k = 0; k < 4; k++) {
        for (int dir = ceiling && !deep ? 1 : 0; dir < 9; dir++) {
            fm_vec3_t d = c->up;
            if (dir > 0) {
                float a = (float)(dir - 1) * (0.25f * FM_PI);
                d = v3_madd(v3_scale(side, cosf(a)), side2, sinf(a));
            }
            fm_vec3_t p = v3_madd(*pos, d, dists[k]);
            /* deep in a solid, up is the way out even through other faces (a slab stack) */
            if (v3_finite(p) && free_at(c, p) && ((deep && dir == 0) || reachable(c, *pos, p, deep))) {
                *pos = p;
                if (vel) *vel = v3(0.0f, 0.0f, 0.0f);
                return;
            }
        }
    }
}

/* The full capsule stands at *p: a walkable floor under the foot within `below` under it
 * or the step height above it, and room to lift the body onto a floor above the foot
 * (swept). *p is moved onto that floor. A lift stopped short by an overhang's underside
 * (what it met leans over the body: its normal points down and across up) is tried again
 * from beside it, moved back across up by what the lift lacked, to first order, along that
 * normal (at most r / 2 a time, CB_BACK_TRIES times; the move swept): in a triangle soup the
 * game teleported a body (r 0.19, step 0.23) into, a pocket over a 20-degree face, under
 * two faces leaning over it, the only place to stand there is 3 cm wide, 0.2 m away; the
 * search's ways ended beside it, lifted 28-86 % of the way, and the body stood grounded on
 * the face with its foot 132 mm under it (soak s118 l131). */
#define CB_BACK_TRIES 3
static bool stands_at(const cb_ctx_t *c, fm_vec3_t *p, float below)
{
    const float step_eps = cb_len_tol(c, CB_STEP_EPS);
    fm_vec3_t at = *p; /* (*p is written only where it stands: a place to fall from is the way's end) */
    for (int k = 0;; k++) {
        fm_vec3_t foot = cb_foot(c, at);
        float rise;
        if (!floor_height(c, foot, c->radius + c->step, below, foot, &rise, false)) return false;
        float gap = -rise;
        if (!(gap < -step_eps)) {
            *p = at;
            return true;
        }
        fm_vec3_t q = at, n = v3(0.0f, 0.0f, 0.0f);
        const float f = move_swept_in(c, &q, v3_scale(c->up, -gap), &n, false);
        if (!(f * -gap < -gap - step_eps)) {
            *p = q;
            return true;
        }
        const float nu = v3_dot(n, c->up);
        const fm_vec3_t na = v3_reject(n, c->up);
        const float la = v3_len(na);
        if (k >= CB_BACK_TRIES || !(nu < 0.0f) || !(la > 1e-3f)) return false;
        float m = (1.0f - f) * -gap * -nu / la + c->skin;
        if (m > 0.5f * c->radius) m = 0.5f * c->radius;
        if (move_swept_in(c, &at, v3_scale(na, m / la), NULL, false) < 1.0f || !v3_finite(at)) return false;
    }
}

/* Nothing (a floor, a slope, any face) between the foot at p and r + step above it: the
 * foot is in no floor there, the body may fall from there. */
static bool foot_free_at(const cb_ctx_t *c, fm_vec3_t p)
{
    const float above = c->radius + c->step;
    coll_ray_hit_t rh;
    return !cb_ray(c, v3_madd(cb_foot(c, p), c->up, above), v3_scale(c->up, -1.0f), above, &rh);
}

bool coll_cb_stand_search(const cb_ctx_t *c, fm_vec3_t *pos, fm_vec3_t input, bool airborne, int *next)
{
    fm_vec3_t side = v3_norm(v3_reject(v3(1.0f, 0.0f, 0.0f), c->up));
    if (v3_len(side) < 0.5f) side = v3_norm(v3_reject(v3(0.0f, 0.0f, 1.0f), c->up));
    fm_vec3_t side2 = v3_cross(c->up, side);
    const float r = c->radius;
    const float dists[4] = {0.5f * r, r, 2.0f * r, 4.0f * r};
    fm_vec3_t in = airborne ? v3(0.0f, 0.0f, 0.0f) : v3_reject(input, c->up);
    for (int k = 0; k < 4; k++)
        for (int dir = 0; dir < 8; dir++) {
            if (k * 8 + dir < *next) continue; /* tried already */
            *next = k * 8 + dir + 1;
            float a = (float)dir * (0.25f * FM_PI);
            fm_vec3_t d = v3_madd(v3_scale(side, cosf(a)), side2, sinf(a));
            if (v3_dot(d, in) < 0.0f) continue; /* never against the input */
            /* Nor faster than the velocity can say: a ring beyond the speed limit's reach in
             * one step is searched at that reach (once). A body (r 0.84, step 0.67, up 94
             * degrees off y, dt 1/240: 0.833 m in a step) on a ramp, its head against the
             * room's wall that leans over it for that up, its foot 0.61 m in the ramp with no
             * room for the lift: r / 2 up the ramp is 0.35 m short of room, the ring at r
             * (1 % past the reach) was never tried, and it stood grounded in the ramp (soak
             * s29 l365); 0.83 m up the ramp it stands. */
            const float reach = c->max_speed * c->dt;
            if (k > 0 && dists[k - 1] >= reach) return false;
            fm_vec3_t p = *pos, n;
            const fm_vec3_t way = v3_scale(d, dists[k] < reach ? dists[k] : reach);
            const float f = move_swept_in(c, &p, way, &n, false);
            if (f < 1.0f) {
                /* Stopped by something walkable (a floor's face or an edge it could stand
                 * on; under a tilted up the way across up goes down into the level floor the
                 * capsule rests on): the rest of the way along its plane, as walking goes;
                 * stopped by anything else, no place this way. A body the game teleported
                 * (r 0.65, up 11 degrees off y) with its foot 0.41 m in a stair block, its
                 * sweep capsule 2 mm over the block's top, 13 mm from the next block's edge
                 * and leaning against a collider capsule above (no room for the lift): four
                 * ways went into the collider, the other four met that top or that edge
                 * within 6 cm, and it stood grounded in the block for ever (soak s27 l164);
                 * 0.19 m along the top it stands. The slide moves it along up too, which
                 * only a floor within touching reach of the foot (the probe grounds it
                 * there, airborne or not) makes no motion: an airborne body slid up a slope
                 * to a place to fall from, or over a floor farther down, moved along up
                 * with no velocity to say so (soak s3 l46). */
                if (!(v3_dot(n, c->up) >= c->body->cos_floor_max_angle)) continue;
                const fm_vec3_t rest = v3_scale(way, 1.0f - f);
                if (move_swept_in(c, &p, v3_madd(rest, n, -v3_dot(rest, n)), NULL, false) < 1.0f ||
                    !v3_finite(p) || !stands_at(c, &p, c->contact_eps) ||
                    v3_len(v3_reject(v3_sub(p, *pos), c->up)) > reach)
                    continue;
                *pos = p;
                return true;
            }
            if (v3_finite(p) && (stands_at(c, &p, c->snap) || (airborne && foot_free_at(c, p))) &&
                v3_len(v3_reject(v3_sub(p, *pos), c->up)) <= reach) {
                *pos = p;
                return true;
            }
        }
    return false;
}

/* The full capsule's bottom ball (at the foot of the body at pos, grown by contact_eps)
 * rests on something: a contact below its centre whose direction to the centre is within
 * the walkable angle (a floor's face under it, or an edge under it; not a wall beside it,
 * nor a face above its centre that the step zone is through). */
static bool foot_ball_rests(const cb_ctx_t *c, fm_vec3_t pos)
{
    const char_body_t *b = c->body;
    const fm_vec3_t up = c->up, bc = v3_madd(cb_foot(c, pos), up, c->radius);
    coll_contact_t ct[CB_BALL_CONTACTS];
    const uint32_t n = cb_ball_overlaps(c, bc, c->radius + c->contact_eps, ct);
    for (uint32_t i = 0; i < n; i++) {
        const fm_vec3_t d = v3_sub(bc, ct[i].point);
        const float du = v3_dot(d, up);
        if (v3_finite(d) && du > c->tiny && du >= b->cos_floor_max_angle * v3_len(d)) return true;
    }
    return false;
}

/* Where the stand search's ways start: the start, or, where the sweep capsule is there in a
 * shallow overlap (under the skin) that the recovery could not push it out of, the start
 * pushed out of it to touching, verified, as the slide does (soak s69 l158): a sweep from
 * inside stops at once whichever way it goes, so every way of the search was "blocked".
 * The game teleported a body (r 0.88, step 0.021) with its foot 20 mm in a block 0.238 m
 * high, the sweep capsule's bottom 0.5 mm over the block's top and its top ball 0.5 mm
 * into a triangle soup's edge leaning over it: the recovery's push out of the edge went
 * into the top, the push out of the top into the edge again (0.25 mm left); no room for
 * the lift onto the top, the search's 16 ways all met the edge at t = 0, and the body
 * stood on the top with its foot 20 mm under it (soak s102 l296). */
static fm_vec3_t search_from(const cb_ctx_t *c, fm_vec3_t start)
{
    coll_contact_t ct[CB_MAX_CONTACTS];
    const uint32_t n = overlaps_at(c, start, ct);
    const coll_contact_t *deep = NULL;
    for (uint32_t i = 0; i < n; i++)
        if (ct[i].depth > c->min_depth && v3_finite(ct[i].normal) && (!deep || ct[i].depth > deep->depth))
            deep = &ct[i];
    fm_vec3_t p = start;
    if (deep && deep->depth < c->skin) coll_cb_push_verified(c, &p, v3_scale(deep->normal, deep->depth));
    return p;
}

bool coll_cb_unwedge(const cb_ctx_t *c, fm_vec3_t *pos, fm_vec3_t start, fm_vec3_t in_h, bool was_grounded,
                     bool rising)
{
    char_body_t *b = c->body;
    /* No room to stand at the start either (the game teleported the body with its foot in
     * a raised floor under an overhang: the sweep capsule is free, so no recovery ran): the
     * nearest place where it stands, moved to as motion. The search's places are checked
     * by the probe itself (a crack's edges it has no room to be lifted onto: the next place,
     * along a V valley's slot, soak s3 l374). */
    c->mem->edges_no_room = false;
    bool stands = coll_cb_probe_floor(c, pos, was_grounded, rising);
    /* Falling at the start only because the crack rule's edges had no room to lift the body
     * onto them, while the step (its fall included) was undone: the fall towards the floor
     * under the foot never happens (the foot goes into the floor under the crack, where the
     * edges hold the ball again), and the body hung at rest in the crack for ever. It is
     * wedged: the search looks for a place to stand (or to fall from, airborne) that is not
     * such a crack. A body (r 0.12, height 2.60, step 0.15) in a crack between tiles 0.108 m
     * high, its foot 2.09 mm over the room floor, its head under a triangle soup's face that
     * stopped the lift onto the tile edges 4.3 mm short (soak s25 l34). Found nothing: as
     * before (falling where it is). */
    /* Likewise airborne at the start (it "fits" only falling), where this step's probe failed
     * because the crack rule alone held the ball on edges it had no room to be lifted onto,
     * with no floor in the foot ray's reach: the fall that never happens again. A body (r
     * 0.78, up tilted 10 degrees) hung over a ramp's top corner in a room's corner, the wall
     * under it leaning back into the fall, the one over it overhanging the lift, the floor
     * 2.2 m down, out of reach (soak s30 l14): the search finds it a place it falls from. */
    const bool held_nowhere =
        stands && (c->mem->edges_no_room ||
                   (c->mem->crack_no_floor && !was_grounded && !(b->flags & CB_FLAG_GROUNDED)));
    if (held_nowhere) stands = false;
    const fm_vec3_t held = *pos;
    int next = 0;
    bool tried = false;
    const fm_vec3_t from = stands ? start : search_from(c, start);
    fm_vec3_t p = from;
    while (!stands && coll_cb_stand_search(c, &p, in_h, !was_grounded, &next)) {
        *pos = p;
        c->mem->edges_no_room = false;
        stands = coll_cb_probe_floor(c, pos, was_grounded, rising) && !c->mem->edges_no_room;
        if (stands) b->velocity = v3_scale(v3_reject(v3_sub(*pos, start), c->up), 1.0f / c->dt);
        p = from;
        tried = true;
    }
    if (!stands && (tried || held_nowhere)) {
        *pos = held;
        stands = coll_cb_probe_floor(c, pos, was_grounded, rising);
    }
    /* Nowhere to stand the way the input goes (walls), but a way out behind or beside it:
     * the foot in a floor it has no room to be lifted onto is not standing on it, it is
     * wedged there. Airborne, the next step's search takes that way (back from under the
     * overhang, down the ramp): there is no walk to keep to then (soak s2 l229, s3 l175:
     * grounded, the foot 0.18-0.23 m inside the floor, for ever). With no way out at all it
     * stays as it stands (s2 l193). */
    fm_vec3_t q = from;
    int first = 0;
    if (!stands && was_grounded && coll_cb_stand_search(c, &q, in_h, true, &first)) {
        *pos = start; /* nor lifted part of the way: that was no motion */
        return true;
    }
    /* Nowhere to stand and no way out (airborne, or grounded and the search any way found
     * nothing either), and the full capsule's bottom ball rests on nothing: the floor the
     * probe found over the foot is no support, the body is not standing on it. The game
     * teleported a body (r 0.31, step 1.16, up tilted 50 degrees) into the solid under a V
     * valley's slope; its sweep capsule fits in there, the slope's inside face is walkable
     * for that up and crosses the step zone 1.03 m over the foot, the lift has no room, the
     * search no place: it stood grounded with its foot 1.03 m in the slope (soak s13 l195).
     * Grounded at the step's start the same: a body (r 0.2, height 3.95, step 1.36) the
     * game teleported with its foot in a tile under a ledge slab 0.83-0.93 m high, lifted
     * out of the tile as far as a triangle soup over the slab let it (0.31 m) and grounded
     * on the slab's top, stood there on the next steps with its foot 0.52 m under that top
     * in the air, the slab through its step zone, no room above it and no place within the
     * search's reach (soak s15 l288). Where the ball does rest on something (a stair's
     * nosings, s2 l193) it stays as it stands. */
    if (!stands && !foot_ball_rests(c, start)) {
        *pos = start;
        return true;
    }
    return false;
}

/** Notes the recover's move from `from` to `to` in the step's memory (cb_mem_t.push). */
static void note_push(const cb_ctx_t *c, fm_vec3_t from, fm_vec3_t to)
{
    cb_mem_t *m = c->mem;
    if (!m->pushed) m->push = v3(0.0f, 0.0f, 0.0f);
    m->pushed = true;
    m->push = v3_add(m->push, v3_sub(to, from));
}

void coll_cb_recover(const cb_ctx_t *c, fm_vec3_t *pos, fm_vec3_t *vel)
{
    coll_contact_t ct0[CB_MAX_CONTACTS], ct[CB_MAX_CONTACTS];
    /* (remembered: the slide's first sweep starts here when nothing pushes the body out,
     * maybe against a wall touched at the start: the V corner's wedged steps) */
    uint32_t n0 = cb_overlaps_remember(c, cb_sweep_center(c, *pos), ct0, CB_MAX_CONTACTS);
    if (n0 > CB_MAX_CONTACTS) n0 = CB_MAX_CONTACTS;
    uint32_t n = n0;
    for (uint32_t i = 0; i < n; i++) ct[i] = ct0[i];
    fm_vec3_t p = *pos;
    fm_vec3_t v = vel ? *vel : v3(0.0f, 0.0f, 0.0f);
    const float min_depth = c->min_depth;
    bool stuck = deeper_than(ct0, n0, c->skin); /* at the last kept position */
    for (int pass = 0; pass < 3; pass++) {
        fm_vec3_t delta = v3(0.0f, 0.0f, 0.0f);
        bool any = false;
        /* Gauss-Seidel on positions: each contact wants depth + half a skin of separation. */
        for (int iter = 0; iter < 4; iter++) {
            for (uint32_t i = 0; i < n; i++) {
                if (!(ct[i].depth > min_depth) || !v3_finite(ct[i].normal)) continue;
                float want = ct[i].depth + 0.5f * c->skin - v3_dot(delta, ct[i].normal);
                if (want > 0.0f) {
                    delta = v3_madd(delta, ct[i].normal, want);
                    any = true;
                }
            }
        }
        if (!any) break;
        float dl = v3_len(delta);
        float lim = 2.0f * c->radius + 2.0f * c->half_height;
        if (dl > lim) delta = v3_scale(delta, lim / dl);
        for (uint32_t i = 0; i < n; i++)
            if (ct[i].depth > min_depth && v3_finite(ct[i].normal)) v = clip_plane(v, ct[i].normal);
        /* A push-out never turns into speed along up: clipping a walk against a nosing the
         * capsule touches would otherwise launch it (a "jump" that skips the floor probe). */
        float v_up0 = vel ? v3_dot(*vel, c->up) : 0.0f, cap = v_up0 > 0.0f ? v_up0 : 0.0f;
        float v_up = v3_dot(v, c->up);
        if (v_up > cap) v = v3_madd(v, c->up, cap - v_up);
        p = v3_add(p, delta);
        if (!v3_finite(p)) return;
        n = overlaps_at(c, p, ct);
        /* Verified result (the push is not swept): a pass's position is kept only when it
         * overlaps nothing new or deeper than the start did. Otherwise the last verified
         * one stays: still in what we were in, nothing worse; the next pass may get there.
         * No exception for deep overlaps: "deep, so the game put it there" also holds for
         * a body wedged between a slab's faces that the game never put there, and pushing
         * through ended 126 mm inside the other face (soak seed 12 level 382). A body the
         * game put deep into geometry may therefore stay there until it moves out. */
        if (no_worse(ct, n, ct0, n0, c->min_depth) && reachable(c, *pos, p, deeper_than(ct0, n0, 0.5f * c->radius)) &&
            !sinks_foot(c, *pos, p)) {
            note_push(c, *pos, p);
            *pos = p;
            if (vel) *vel = v;
            stuck = deeper_than(ct, n, c->skin);
        }
    }
    if (stuck) {
        const fm_vec3_t was = *pos;
        unstick(c, pos, vel);
        note_push(c, was, *pos);
    }
}

/**
 * Airborne, the foot guard took the body back out of a block whose top the sweep capsule
 * was passing over (a top within the step zone, the foot point against the block's side):
 * the fall the slide spent on that top is lost, and the capsule's bottom ball ends balanced
 * on the block's edge with the foot point short of it, for ever (real map oa_dm1: a block
 * one step high, the ball 1 mm off its edge, the foot 18 mm over the floor). The rest of
 * the step's fall is made from there (swept), sliding off the edge the foot is not over as
 * the slide does (slide_off_edge, within the speed limit's room), then falling on.
 */
void coll_cb_guard_fall(const cb_ctx_t *c, fm_vec3_t *pos, float fall, float room)
{
    if (!(fall > c->tiny)) return;
    for (int k = 0; k < 2; k++) {
        fm_vec3_t d = v3_scale(c->up, -fall);
        coll_sweep_hit_t hit;
        if (!cb_sweep(c, cb_sweep_center(c, *pos), c->radius, c->sweep_ihh, d, &hit)) {
            *pos = v3_add(*pos, d);
            return;
        }
        if (!v3_finite(hit.normal) || !isfinite(hit.t)) return;
        float t = hit.t < 0.0f ? 0.0f : (hit.t > 1.0f ? 1.0f : hit.t);
        float travel = fall * t - c->skin;
        if (travel > 0.0f) {
            *pos = v3_madd(*pos, c->up, -travel);
            fall -= travel;
        }
        if (k > 0) return;
        fm_vec3_t fn;
        if (coll_cb_face_normal(&hit, &fn)) hit.normal = fn;
        /* only as far off as lets the ball (its centre hl across and h above the edge) drop
         * by the rest of the fall: it rolls off over a few steps, not in one shove */
        fm_vec3_t rel = v3_sub(v3_madd(cb_sweep_center(c, *pos), c->up, -c->sweep_ihh), hit.point);
        float h = v3_dot(rel, c->up), hl = v3_len(v3_reject(rel, c->up)), lo = h - fall;
        float need = c->radius + c->skin - hl;
        if (lo > 0.0f && lo < c->radius) need = sqrtf(c->radius * c->radius - lo * lo) - hl + c->skin;
        float off = slide_off_edge(c, pos, &hit, need < room ? need : room);
        if (!(off > 0.0f)) return;
    }
}

bool coll_cb_foot_guard(const cb_ctx_t *c, fm_vec3_t *pos, fm_vec3_t old_foot, fm_vec3_t *vel)
{
    const char_body_t *b = c->body;
    fm_vec3_t foot = cb_foot(c, *pos);
    fm_vec3_t o = v3_madd(old_foot, c->up, c->contact_eps);
    fm_vec3_t d = v3_sub(foot, o);
    float len = v3_len(d);
    if (!(len > cb_len_tol(c, 1e-5f))) return false;
    fm_vec3_t dir = v3_scale(d, 1.0f / len);
    coll_ray_hit_t hit;
    if (!cb_ray(c, o, dir, len, &hit)) return false;
    fm_vec3_t n = hit.normal;
    if (!v3_finite(n)) return false;
    if (v3_dot(n, c->up) >= b->cos_floor_max_angle) return true; /* landing: the probe's job */
    /* Slide the foot along the wall it would have entered. */
    fm_vec3_t after = v3_sub(foot, hit.point);
    fm_vec3_t target = v3_add(v3_madd(hit.point, n, c->skin), clip_plane(after, n));
    /* Swept, like every positional change: the push must not put the capsule into
     * something else (a slope or wall on the other side). */
    fm_vec3_t move = v3_sub(target, foot);
    /* It is motion: within the speed limit (its ray starts contact_eps above the old foot,
     * so a 1 ns step against a wall under a tilted up was moved 2 mm: soak s1 l164) */
    float ml = v3_len(move), room = c->max_speed * c->dt;
    if (ml > room) move = v3_scale(move, room / ml);
    coll_cb_move_swept(c, pos, move);
    if (vel) *vel = clip_plane(*vel, n);
    return false;
}
