/**
 * @file char_body.c
 * @brief Character body: settings, state queries and the per-step driver.
 *
 * One step (char_body_move_and_slide_in) runs these phases in order:
 *  1. carry      - move with the mesh instance stood on last step (char_body_floor.c)
 *  2. recover    - push the sweep capsule out of anything it overlaps (char_body_slide.c)
 *  3. velocity   - input across up, gravity along -up, slope following on walkable floors
 *  4. slide      - sweep-and-slide of the shortened capsule, creases (char_body_slide.c)
 *  5. foot guard - airborne: the foot point may not enter walls (char_body_slide.c)
 *  6. probe      - floor ray at the foot: grounding, snapping, stair lift (char_body_floor.c)
 */
#include "char_body_internal.h"
#include "coll_assert.h"

_Static_assert(sizeof(char_body_t) <= 256, "char_body_t must stay within 256 bytes");

static void sync_collider(char_body_t *body);

/* ---- settings ---- */

/** v clamped to [lo, hi]; NaN gives fallback. */
static float clampf(float v, float lo, float hi, float fallback)
{
    if (v != v) return fallback;
    if (v < lo) return lo;
    if (v > hi) return hi;
    return v;
}

void char_body_init(char_body_t *body, fm_vec3_t *owner_pos)
{
    if (!body) return;
    *body = (char_body_t){0};
    body->owner_pos = owner_pos;
    if (owner_pos && v3_finite(*owner_pos)) body->origin = *owner_pos;
    body->settings.up = v3(0.0f, 1.0f, 0.0f);
    body->floor_id = -1;
    char_body_settings_t s = CHAR_BODY_SETTINGS_DEFAULT;
    char_body_configure(body, &s);
    body->floor_normal = body->settings.up;
}

void char_body_configure(char_body_t *body, const char_body_settings_t *settings)
{
    if (!body || !settings) return;
    char_body_settings_t s = *settings;
    fm_vec3_t prev_up = body->settings.up;

    fm_vec3_t up = v3_norm(s.up);
    if (!v3_finite(s.up) || v3_len(up) < 0.5f) {
        up = v3_norm(prev_up);
        if (v3_len(up) < 0.5f) up = v3(0.0f, 1.0f, 0.0f);
    }
    s.up = up;
    if (!v3_finite(s.center_offset)) s.center_offset = v3(0.0f, 0.0f, 0.0f);

    /* The length unit first: every length, speed and acceleration limit is metres times it
     * (and so are the fallbacks for NaN settings, the seed's defaults in metres). */
    const float u = s.units_per_meter = clampf(isfinite(s.units_per_meter) && s.units_per_meter > 0.0f
                                                   ? s.units_per_meter : 1.0f, 1e-3f, 1e4f, 1.0f);
    s.radius = clampf(s.radius, CB_MIN_RADIUS * u, CB_MAX_LENGTH * u, 0.5f * u);
    s.height = clampf(s.height, 2.0f * s.radius, 4.0f * CB_MAX_LENGTH * u, 2.0f * s.radius);
    s.gravity = clampf(s.gravity, 0.0f, CB_MAX_GRAVITY * u, 30.0f * u);
    s.max_fall_speed = clampf(s.max_fall_speed, 0.0f, CB_MAX_SPEED * u, 55.0f * u);
    s.floor_max_angle = clampf(s.floor_max_angle, 0.0f, 0.5f * FM_PI, 0.25f * FM_PI);
    s.floor_snap_distance = clampf(s.floor_snap_distance, 0.0f, CB_MAX_LENGTH * u, 0.30f * u);
    float inner = 0.5f * s.height - s.radius;
    s.step_height = clampf(s.step_height, 0.0f, inner, 0.0f);
    if (s.step_height > s.floor_snap_distance) s.step_height = s.floor_snap_distance;
    if (s.max_slides < 1) s.max_slides = 1;
    if (s.max_slides > CB_MAX_PLANES) s.max_slides = CB_MAX_PLANES;

    if (s.leave_velocity > CHAR_BODY_LEAVE_DROP) s.leave_velocity = CHAR_BODY_LEAVE_ADD;

    body->settings = s;
    body->cos_floor_max_angle = cosf(s.floor_max_angle);
    body->inner_half_height = inner;
    sync_collider(body);
}

const char_body_settings_t *char_body_get_settings(const char_body_t *body)
{
    return body ? &body->settings : NULL;
}

void char_body_set_up(char_body_t *body, fm_vec3_t up)
{
    if (!body || !v3_finite(up)) return;
    fm_vec3_t n = v3_norm(up);
    if (v3_len(n) < 0.5f) return;
    body->settings.up = n;
    sync_collider(body);
}

void char_body_set_center_offset(char_body_t *body, fm_vec3_t offset)
{
    if (!body || !v3_finite(offset)) return;
    body->settings.center_offset = offset;
    sync_collider(body);
}

/* ---- state ---- */

bool char_body_is_on_floor(const char_body_t *body)
{
    return body && (body->flags & CB_FLAG_GROUNDED);
}

bool char_body_is_on_steep_surface(const char_body_t *body)
{
    return body && (body->flags & CB_FLAG_GROUNDED) && (body->flags & CB_FLAG_STEEP);
}

fm_vec3_t char_body_floor_normal(const char_body_t *body)
{
    return body ? body->floor_normal : v3(0.0f, 0.0f, 0.0f);
}

fm_vec3_t char_body_get_velocity(const char_body_t *body)
{
    return body ? body->velocity : v3(0.0f, 0.0f, 0.0f);
}

void char_body_set_velocity(char_body_t *body, fm_vec3_t velocity)
{
    if (!body || !v3_finite(velocity)) return;
    body->velocity = velocity;
}

fm_vec3_t char_body_foot_pos(const char_body_t *body)
{
    if (!body) return v3(0.0f, 0.0f, 0.0f);
    fm_vec3_t c = v3_add(owner_position(body), body->settings.center_offset);
    return v3_madd(c, body->settings.up, -0.5f * body->settings.height);
}

int32_t char_body_floor_id(const char_body_t *body)
{
    return body ? body->floor_id : -1;
}

char_body_ground_state_t char_body_ground_state(const char_body_t *body)
{
    if (!body || !(body->flags & CB_FLAG_GROUNDED)) return CHAR_BODY_AIRBORNE;
    return (body->flags & CB_FLAG_STEEP) ? CHAR_BODY_ON_STEEP : CHAR_BODY_ON_FLOOR;
}

fm_vec3_t char_body_ground_velocity(const char_body_t *body)
{
    return body ? body->ground_velocity : v3(0.0f, 0.0f, 0.0f);
}

const char_body_events_t *char_body_events(const char_body_t *body)
{
    return body ? &body->events : NULL;
}

/** Rotation taking +Y to unit u (shortest arc). */
static fm_quat_t quat_y_to(fm_vec3_t u)
{
    fm_vec3_t y = v3(0.0f, 1.0f, 0.0f);
    float d = v3_dot(y, u);
    fm_quat_t q;
    if (d < -0.999999f) {
        q = (fm_quat_t){{1.0f, 0.0f, 0.0f, 0.0f}}; /* half turn about X */
        return q;
    }
    fm_vec3_t a = v3_cross(y, u);
    q = (fm_quat_t){{a.x, a.y, a.z, 1.0f + d}};
    fm_quat_norm(&q, &q);
    return q;
}

/** The own collider as the full capsule at the body's position. */
static void sync_collider(char_body_t *body)
{
    coll_body_t *k = body->collider;
    if (!k) return;
    k->shape = COLL_SHAPE_CAPSULE;
    k->half_extents = v3(body->settings.radius, body->inner_half_height, body->settings.radius);
    k->xf.pos = v3_add(owner_position(body), body->settings.center_offset);
    k->xf.rot = quat_y_to(body->settings.up);
    k->xf.scale = v3(1.0f, 1.0f, 1.0f);
}

void char_body_set_collider(char_body_t *body, coll_body_t *collider)
{
    if (!body) return;
    body->collider = collider;
    sync_collider(body);
}

void char_body_set_gather_cache(char_body_t *body, coll_gather_cache_t *cache)
{
    if (!body) return;
    body->gather_cache = cache;
    if (cache) coll_gather_cache_reset(cache);
}

void char_body_drop_through(char_body_t *body)
{
    if (!body) return;
    const char_body_settings_t *s = &body->settings;
    float g_min = 1e-3f * s->units_per_meter; /* m/s^2: no gravity falls in two seconds */
    float g = s->gravity > g_min ? s->gravity : g_min;
    body->drop_time = sqrtf(2.0f * (s->height + s->floor_snap_distance) / g) + 0.05f;
    if (body->drop_time > 2.0f) body->drop_time = 2.0f;
}

/** Takes the one-way platforms off every layer for this step (on == true) or puts them back
 *  (masks saved in saved[], in scene order). */
static void hide_one_way(const coll_scene_t *scene, bool on, uint8_t *saved)
{
    for (uint16_t i = 0; i < scene->mesh_count && i < COLL_SCENE_MAX_MESHES; i++) {
        coll_mesh_instance_t *in = scene->meshes[i];
        if (!in || !(in->flags & COLL_INSTANCE_ONE_WAY)) continue;
        if (on) { saved[i] = in->write_mask; in->write_mask = 0; }
        else in->write_mask = saved[i];
    }
}

static void clear_floor(char_body_t *body)
{
    body->flags &= (uint8_t)~(CB_FLAG_GROUNDED | CB_FLAG_STEEP | CB_FLAG_CARRY);
    body->floor_instance = NULL;
    body->floor_id = -1;
    body->floor_normal = body->settings.up;
}

void char_body_teleport(char_body_t *body, fm_vec3_t owner_pos, bool reset_forces)
{
    if (!body || !v3_finite(owner_pos)) return;
    body->origin = owner_pos;
    if (body->owner_pos) *body->owner_pos = owner_pos;
    /* The carry anchor belongs to the old place either way. */
    body->flags &= (uint8_t)~(CB_FLAG_CARRY | CB_FLAG_CARRIED);
    body->floor_instance = NULL;
    body->ground_velocity = v3(0.0f, 0.0f, 0.0f);
    if (reset_forces) {
        body->air_velocity = v3(0.0f, 0.0f, 0.0f);
        body->velocity = v3(0.0f, 0.0f, 0.0f);
        body->slide_speed = 0.0f;
        clear_floor(body);
    }
    sync_collider(body);
}

/* ---- the step ---- */

static fm_vec3_t clamp_speed(fm_vec3_t v, float max_speed)
{
    /* finite first: no ordered compare of a NaN (the console emulator stops on the invalid
     * operation: test_bad_velocities_and_walls on the N64 ROM) */
    if (!v3_finite(v)) return v3(0.0f, 0.0f, 0.0f);
    /* Well under the limit (the common case), without the square root: its rounded square
     * root is below max_speed, so the test below would keep v as it is. */
    if (v3_len2(v) <= 0.98f * max_speed * max_speed) return v;
    float l = v3_len(v);
    if (l > max_speed) v = v3_scale(v, max_speed / l);
    return v;
}

/**
 * The reported velocity's limit: its part across up to max_speed (no motion across up is
 * faster) and its part along up to max_speed, each on its own, so the report stays the
 * motion. A walk at the speed limit across a ramp and off its side in the same step moves at
 * the limit across up plus its rise along up: the whole vector clamped to max_speed cut the
 * part across up by 2.5 % under the motion (soak s141 l56: r 0.16, 200 m/s across up over a
 * 35.7 degree ramp, 1.55 m of rise in one step, 205 m/s in all).
 */
static fm_vec3_t clamp_report(fm_vec3_t v, fm_vec3_t up, float max_speed)
{
    if (!v3_finite(v)) return v3(0.0f, 0.0f, 0.0f);
    if (v3_len2(v) <= 0.98f * max_speed * max_speed) return v; /* the common case, as clamp_speed */
    float vu = v3_dot(v, up);
    fm_vec3_t h = clamp_speed(v3_madd(v, up, -vu), max_speed);
    if (vu > max_speed) vu = max_speed;
    if (vu < -max_speed) vu = -max_speed;
    return v3_madd(h, up, vu);
}

/**
 * Input reshaped onto the floor plane: moved along up until it lies in the plane, then
 * rescaled so the speed along the ground equals the input speed (up and down ramps alike).
 */
static fm_vec3_t follow_slope(fm_vec3_t in_h, fm_vec3_t up, fm_vec3_t n, float unit)
{
    float speed = v3_len(in_h);
    float nu = v3_dot(n, up);
    if (speed <= 0.0f || nu < 1e-3f) return in_h;
    fm_vec3_t v = v3_madd(in_h, up, -v3_dot(in_h, n) / nu);
    float l = v3_len(v);
    if (!(l > 1e-9f * unit)) return in_h;
    return v3_scale(v, speed / l);
}

/** Gathers the candidates of a step that starts at pos (see cb_ctx_t.gather). */
static void gather_step(const cb_ctx_t *c, coll_gather_t *g, fm_vec3_t pos, fm_vec3_t input, fm_vec3_t carry_d,
                        float dt)
{
    const char_body_t *b = c->body;
    fm_vec3_t center = cb_center(c, pos), up = c->up;
    /* The step's velocity (step 3 below) is at most the input across up, plus the air
     * velocity kept and the speed along up (airborne) or down a steep floor, plus a step of
     * gravity; the velocity across up is the input's again, so it is not counted twice. */
    float speed = v3_len(v3_reject(input, up)) + v3_len(b->air_velocity) + fabsf(v3_dot(b->velocity, up)) +
                  b->slide_speed + b->settings.gravity * dt;
    float carry = v3_len(carry_d);
    float move = speed * dt + carry + 4.0f * c->skin;
    /* the floor probe's reach, and the crack rule's ball dropped from the foot (it reaches
     * half a radius below the probe: ball_held in char_body_floor.c) */
    float below = c->snap + 0.5f * c->radius + 2.0f * c->skin;
    fm_vec3_t lo, hi;
    for (int a = 0; a < 3; a++) {
        float ext = fabsf(up.v[a]) * (c->half_height - c->radius) + c->radius + move;
        lo.v[a] = center.v[a] - ext + (up.v[a] > 0.0f ? -up.v[a] * below : -up.v[a] * c->step);
        hi.v[a] = center.v[a] + ext + (up.v[a] > 0.0f ? up.v[a] * c->step : -up.v[a] * below);
    }
    if (!b->gather_cache) {
        coll_gather_begin(g, c->scene, lo, hi, b->settings.read_mask, b->settings.coll_types);
        return;
    }
    if (coll_gather_from_cache(g, b->gather_cache, c->scene, lo, hi, b->settings.read_mask, b->settings.coll_types))
        return;
    /* With a cache, a refill keeps the triangles of a larger box: this step's, and where it
     * will be CB_GATHER_CACHE_STEPS steps on at this velocity (the input across up, along
     * the floor walked, or the velocity along up in the air; plus the platform's carry; at
     * most CB_GATHER_CACHE_AHEAD ahead), grown by CB_GATHER_CACHE_MARGIN. */
    fm_vec3_t in_h = v3_reject(input, up), vel;
    if ((b->flags & (CB_FLAG_GROUNDED | CB_FLAG_STEEP)) == CB_FLAG_GROUNDED)
        vel = follow_slope(in_h, up, b->floor_normal, c->unit); /* up or down the floor walked */
    else vel = v3_madd(in_h, up, v3_dot(b->velocity, up));
    /* (a platform's carry too: its steps are as long as the last one) */
    fm_vec3_t ahead = v3_scale(v3_madd(carry_d, vel, dt), (float)CB_GATHER_CACHE_STEPS);
    float la = v3_len(ahead), amax = CB_GATHER_CACHE_AHEAD * c->unit;
    if (!(la <= amax)) ahead = la > 0.0f && isfinite(la) ? v3_scale(ahead, amax / la) : v3(0.0f, 0.0f, 0.0f);
    float mg = CB_GATHER_CACHE_MARGIN * c->unit;
    fm_vec3_t flo, fhi;
    for (int a = 0; a < 3; a++) {
        flo.v[a] = lo.v[a] + (ahead.v[a] < 0.0f ? ahead.v[a] : 0.0f) - mg;
        fhi.v[a] = hi.v[a] + (ahead.v[a] > 0.0f ? ahead.v[a] : 0.0f) + mg;
    }
    coll_gather_refill(g, b->gather_cache, c->scene, lo, hi, flo, fhi, b->settings.read_mask, b->settings.coll_types);
}

/**
 * Turns this step's floor state change and the heights collected by the slide and the probe
 * into events. A height change counts as a step (stairs, a kerb: what a camera smooths)
 * when it is at least a tenth of step_height and the floor stood on keeps its orientation
 * (parallel treads); a ramp's crest or foot changes the floor normal and is not a step.
 */
static void record_events(char_body_t *body, bool was_grounded, fm_vec3_t was_normal, float v_up, bool jumping)
{
    char_body_events_t *ev = &body->events;
    bool grounded = (body->flags & CB_FLAG_GROUNDED) != 0;
    if (!was_grounded && grounded) {
        ev->flags |= CHAR_BODY_EVENT_LANDED;
        ev->landing_speed = v_up < 0.0f ? -v_up : 0.0f;
    }
    if (was_grounded && !grounded) {
        ev->flags |= CHAR_BODY_EVENT_LEFT_FLOOR;
        if (jumping) ev->flags |= CHAR_BODY_EVENT_JUMPED;
    }
    float step = ev->step;
    ev->step = 0.0f;
    if (was_grounded && grounded && fabsf(step) >= 0.1f * body->settings.step_height && fabsf(step) > 0.0f &&
        v3_dot(was_normal, body->floor_normal) > 0.9998f) {
        ev->flags |= CHAR_BODY_EVENT_STEPPED;
        ev->step = step;
    }
}

void char_body_move_and_slide(char_body_t *body, float dt)
{
    const coll_scene_t *scene = coll_scene_current();
    /* No current scene is a game bug (coll_scene_set_current never called, or cleared):
     * debug builds stop here; release builds leave the body untouched, as documented. */
    COLL_DEBUG_ASSERT(scene != NULL, "char_body_move_and_slide: no current scene (call coll_scene_set_current)");
    char_body_move_and_slide_in(body, scene, dt);
}

void char_body_move_and_slide_in(char_body_t *body, const coll_scene_t *scene, float dt)
{
    if (!body || !scene) return;
    if (!(dt > 0.0f) || !isfinite(dt)) return;
    if (dt > CB_MAX_DT) dt = CB_MAX_DT;

    const char_body_settings_t *s = &body->settings;
    cb_ctx_t c;
    c.scene = scene;
    c.body = body;
    c.up = s->up;
    c.radius = s->radius;
    c.half_height = 0.5f * s->height;
    c.step = s->step_height;
    c.snap = s->floor_snap_distance;
    c.sweep_ihh = body->inner_half_height - 0.5f * s->step_height;
    if (c.sweep_ihh < 0.0f) c.sweep_ihh = 0.0f;
    c.sweep_lift = 0.5f * s->step_height;
    c.unit = s->units_per_meter;
    c.contact_eps = CB_CONTACT_EPS * c.unit;
    c.min_depth = CB_MIN_DEPTH * c.unit;
    c.tiny = CB_TINY * c.unit;
    c.skin = 0.01f * s->radius < CB_SKIN * c.unit ? 0.01f * s->radius : CB_SKIN * c.unit;
    const float max_speed = CB_MAX_SPEED * c.unit;
    c.dt = dt;
    c.max_speed = max_speed;
    c.ev = NULL;
    c.gather = NULL;
    cb_mem_t mem;
    mem.down.valid = false;
    mem.ray_valid = false;
    mem.pairs.g = NULL;
    mem.crack_no_floor = false;
    mem.pushed = false;
    c.mem = &mem;
    body->events = (char_body_events_t){0};
    /* Never collide with the own collider: off every layer while this body steps. */
    uint8_t own_mask = body->collider ? body->collider->write_mask : 0;
    if (body->collider) body->collider->write_mask = 0;
    uint8_t one_way_masks[COLL_SCENE_MAX_MESHES];
    const bool dropping = body->drop_time > 0.0f;
    if (dropping) {
        hide_one_way(scene, true, one_way_masks);
        body->drop_time -= dt;
    }

    fm_vec3_t pos = owner_position(body);
    body->velocity = clamp_speed(body->velocity, max_speed);
    fm_vec3_t input = v3_finite(body->input_velocity) ? body->input_velocity : v3(0.0f, 0.0f, 0.0f);
    /* Only the part across up is used. A huge one (its square overflows a float) is
     * scaled down first, keeping its direction: it asks for the fastest motion, not none. */
    input = v3_reject(input, s->up);
    float big = fabsf(input.x) > fabsf(input.y) ? fabsf(input.x) : fabsf(input.y);
    if (fabsf(input.z) > big) big = fabsf(input.z);
    if (big > max_speed) input = v3_scale(input, max_speed / big);
    if (!v3_finite(input)) input = v3(0.0f, 0.0f, 0.0f);

    bool was_grounded = (body->flags & CB_FLAG_GROUNDED) != 0;
    bool was_steep = (body->flags & CB_FLAG_STEEP) != 0;
    const fm_vec3_t was_floor_normal = body->floor_normal;
    fm_vec3_t up = c.up;

    /* The step's candidate triangles, gathered once where it will look: the full capsule
     * grown by this step's reach of motion (the platform's carry included), a stair step's
     * lift above and the floor probe below. Queries beyond it (an unstick; the crack rule's
     * roll, unless what it meets lies inside) go to the scene. */
    fm_vec3_t carry = v3(0.0f, 0.0f, 0.0f);
    bool carried = was_grounded && s->follow_floor && coll_cb_carry_delta(&c, &carry);
    coll_gather_t gather;
    gather_step(&c, &gather, pos, input, carry, dt);
    c.gather = &gather;

    /* 1. carry */
    fm_vec3_t ground_v = v3(0.0f, 0.0f, 0.0f);
    if (carried) ground_v = coll_cb_carry(&c, &pos, carry);
    else body->flags &= (uint8_t)~CB_FLAG_CARRIED;

    /* 2. recover */
    coll_cb_recover(&c, &pos, &body->velocity);

    /* 3. velocity: input across up, the along-up part from the resolved velocity */
    fm_vec3_t in_h = v3_reject(input, up);
    float v_up = v3_dot(body->velocity, up);
    fm_vec3_t v;
    /* (a float rejection along a tilted up leaves a residue of either sign: not a jump) */
    bool walking = was_grounded && !was_steep && v_up <= c.tiny / dt;
    if (walking) {
        v_up = 0.0f;
        v = follow_slope(in_h, up, body->floor_normal, c.unit);
    } else {
        v_up -= s->gravity * dt;
        if (v_up < -s->max_fall_speed) v_up = -s->max_fall_speed;
        /* airborne: the input, plus what was kept of the floor's velocity on leaving it */
        v = v3_madd(v3_add(in_h, body->air_velocity), up, v_up);
        fm_vec3_t n = body->floor_normal;
        fm_vec3_t down_hill = v3_norm(v3_reject(v3_scale(up, -1.0f), n));
        float sin_slope = -v3_dot(down_hill, up);
        if (was_grounded && was_steep && v_up <= 0.0f && sin_slope > 1e-3f) {
            /* Steep floor: gravity acts along it. The body keeps its speed down the slope
             * and gains g sin(slope) per second; input moves it across, never uphill. */
            fm_vec3_t nh = v3_norm(v3_reject(n, up));
            float into = v3_dot(in_h, nh);
            if (into < 0.0f) in_h = v3_madd(in_h, nh, -into);
            float speed = body->slide_speed + s->gravity * sin_slope * dt;
            float cap = s->max_fall_speed / sin_slope;
            body->slide_speed = speed < cap ? speed : cap;
            v = v3_madd(in_h, down_hill, body->slide_speed);
            v_up = v3_dot(v, up);
        } else {
            body->slide_speed = 0.0f;
        }
    }
    bool jumping = v_up > 0.0f;
    v = clamp_speed(v, max_speed);
    body->velocity = v;

    /* 4. slide */
    c.ev = &body->events;
    const fm_vec3_t start = pos;
    fm_vec3_t old_foot = cb_foot(&c, pos);
    coll_cb_slide(&c, &pos, v3_scale(v, dt), &body->velocity, walking);
    if (body->slide_speed > 0.0f) {
        /* Whatever blocked the slide down the slope also took its speed. */
        fm_vec3_t down_hill = v3_norm(v3_reject(v3_scale(up, -1.0f), body->floor_normal));
        float kept = v3_dot(body->velocity, down_hill);
        if (kept < body->slide_speed) body->slide_speed = kept > 0.0f ? kept : 0.0f;
    }

    /* 5. foot guard */
    const fm_vec3_t unguarded = pos;
    const bool foot_landed = !walking && coll_cb_foot_guard(&c, &pos, old_foot, &body->velocity);
    if (!walking && !jumping && !foot_landed && v3_len2(v3_sub(pos, unguarded)) > 0.0f) {
        /* the guard moved it: the fall the slide spent on what it passed over is made now
         * (no more than the step's own fall: a guard's move up along a wall is not undone) */
        float want = -v_up * dt, fell = -v3_dot(v3_sub(pos, start), up);
        float rest = fell > 0.0f ? want - fell : want;
        coll_cb_guard_fall(&c, &pos, rest, max_speed * dt - v3_len(v) * dt);
    }

    /* Honest velocity: where the step's motion fell short of the velocity (a wall, a
     * ceiling, a wedge, a crack's edges stopped it) the velocity is the one the body moved
     * with, so no fall speed accumulates at rest, and a rise stopped by a ceiling shows on
     * the next step (it moves no further up). Unobstructed, the velocity stays exact. The
     * floor probe then drops the part along up on a walkable floor. */
    fm_vec3_t moved = v3_scale(v3_sub(pos, start), 1.0f / dt);
    if (v3_finite(moved) && v3_len(v3_sub(moved, body->velocity)) * dt > 1e-4f * c.radius) body->velocity = moved;

    /* 6. probe; where the body cannot stand (no room for the lift onto the floor under
     *    a ledge or an overhang) it does not go: back to the start of the slide. */
    const fm_vec3_t slid = pos;
    /* A jump skips the probe (it is not snapped back to the floor it leaves), but only
     * while it rises: a rise that an overhang's slope turned downwards this step is not
     * leaving anything, and without the probe it ended with the foot inside the floor it
     * started from (the step zone hides a floor from the sweep). Nor is a rise whose foot
     * went into a walkable floor: under a tilted up the input across up can point into the
     * floor more than the jump lifts off it, and the step zone, unswept, sank up to 0.7 m
     * into the floor over the rise, too deep to lift out of at its top (soak s1 l302). */
    const bool rising = jumping && !foot_landed && v3_dot(v3_sub(slid, start), up) > 0.0f && !coll_cb_rise_sunk(&c, pos);
    if (!coll_cb_probe_floor(&c, &pos, was_grounded, rising)) {
        /* Falling, only the move across up is undone: the body still falls straight down
         * from where it was (landing in front of a kerb it has no room to climb, under an
         * overhang, instead of hanging in the air at the start of every step). */
        float fall = v3_dot(v3_sub(slid, start), up);
        /* and where the slide went up (the input pushed it up a slope or a face into a
         * place it has no room to stand), the step's own fall along up: else it hung at
         * rest 6 mm over the floor for ever (soak s6 l426) */
        if (fall > v_up * dt) fall = v_up * dt;
        bool kept = false;
        if (!walking && !jumping && fall < -c.tiny) {
            pos = start;
            /* Where the crack rule alone held the ball on edges it had no room to be lifted
             * onto (no floor in reach), the fall slides along what it meets: straight down,
             * a wall leaning back into the fall under a tilted up stopped it at once, and the
             * body hung at rest in the air for ever (soak s30 l14; coll_cb_unwedge too). */
            if (mem.crack_no_floor) coll_cb_slide(&c, &pos, v3_scale(up, fall), NULL, false);
            else coll_cb_move_swept(&c, &pos, v3_scale(up, fall));
            body->velocity = v3_scale(v3_sub(pos, start), 1.0f / dt);
            /* That slide stopped dead (under a tenth of the fall: the ball on an edge its
             * foot is past, the push off the edge straight into a wall beside it) is no fall:
             * the start "fits" only falling, the fall that never happens. Not kept: the
             * search of coll_cb_unwedge (an airborne start, crack_no_floor) finds a way. A
             * body (r 0.60, step 0.44) jumped beside an overhang's ledge 1.89 m high and
             * came down with its sweep capsule's bottom on the ledge's end, 6 cm past its
             * edge, a triangle soup's sloping edge against its other side: it hung there at
             * rest in the air, its foot 0.44 m under the ledge's top, for ever (soak s44
             * l175). */
            if (!(mem.crack_no_floor && -v3_dot(v3_sub(pos, start), up) < -0.1f * fall)) {
                const fm_vec3_t fell_to = pos;
                const bool held_alone = mem.crack_no_floor;
                mem.crack_no_floor = false; /* the probe says again whether the crack rule alone held it */
                kept = coll_cb_probe_floor(&c, &pos, was_grounded, rising);
                const bool held_alone_again = mem.crack_no_floor;
                /* A fall that went somewhere (a tenth of it or more, swept along what it met)
                 * and landed where, again, only the crack rule alone held the ball, on edges
                 * with no room to be lifted onto: those edges do not hold it there either, so
                 * the body is falling, and the fall is kept (airborne, the velocity it moved
                 * with). Undone, every step fell the same 10 mm and went back: a body (r 0.32,
                 * step 0.048, one slide) in a pocket of a floating triangle soup, its ball 20
                 * mm into a soup edge (walkable contact, 61 degrees off up) with no room for
                 * the crack rule's 36-43 mm lift, the room floor 3.2 m down, and no place for
                 * coll_cb_unwedge's search from there: it hung at rest in the air for ever
                 * (soak s87 l7). From 10 mm lower the search finds the soup face it stands on. */
                if (!kept && held_alone && held_alone_again) {
                    pos = fell_to;
                    body->velocity = v3_scale(v3_sub(pos, start), 1.0f / dt);
                    clear_floor(body);
                    kept = true;
                }
                mem.crack_no_floor = held_alone || held_alone_again; /* for coll_cb_unwedge */
            }
        }
        if (!kept) {
            pos = start;
            body->velocity = v3(0.0f, 0.0f, 0.0f);
            /* No room to stand at the start either: the nearest place where it stands
             * (char_body_slide.c); wedged where it is, with a way out, it is not standing. */
            if (coll_cb_unwedge(&c, &pos, start, in_h, was_grounded, rising)) clear_floor(body);
        }
    }

    /* The recover's push across up, beyond the skin (no slide's own overshoot), is motion the
     * body made. A body the game teleported 0.64 m into a thin slab, walkable under its tilted
     * up, beside a room wall leaning over it: each step's push out of the slab went into the
     * wall and back out, 67 mm along the crease, at 8 m/s with velocity 0 (soak s134 l270).
     * Along up it is a correction (a push-out never launches the body), except in the air
     * (before and after the step) a push no more than a step of gravity, g dt^2: a body
     * squeezed up a crease a few mm a step moves, and reports it, and the next step's
     * gravity takes that speed back (no launch). A teleport left a body (r 0.57, step 0.44)
     * 18.6 mm in a triangle soup's crease, a 66-degree face (walkable) against a vertical
     * one: the recover pushed it 10.6 mm up a step for 7 steps, velocity along up 0 (soak
     * s148 l265); a push-out of a teleport's deep overlap stays a correction. */
    if (mem.pushed) {
        const fm_vec3_t pushed = v3_reject(mem.push, up);
        if (v3_len2(pushed) > c.skin * c.skin) body->velocity = v3_madd(body->velocity, pushed, 1.0f / dt);
        const float pu = v3_dot(mem.push, up);
        if (!was_grounded && !(body->flags & CB_FLAG_GROUNDED) && fabsf(pu) > c.skin && fabsf(pu) <= s->gravity * dt * dt)
            body->velocity = v3_madd(body->velocity, up, pu / dt);
    }

    /* Leaving the floor (a jump, walking off an edge) keeps the floor's velocity, as
     * settings.leave_velocity says; on a floor, ground_velocity is its velocity. */
    bool grounded = (body->flags & CB_FLAG_GROUNDED) != 0;
    if (was_grounded && !grounded) {
        fm_vec3_t keep = ground_v;
        if (s->leave_velocity == CHAR_BODY_LEAVE_HORIZONTAL) keep = v3_reject(keep, up);
        if (s->leave_velocity == CHAR_BODY_LEAVE_DROP) keep = v3(0.0f, 0.0f, 0.0f);
        body->velocity = v3_add(body->velocity, keep);
        body->air_velocity = v3_reject(keep, up); /* the part along up is in the velocity */
        body->flags &= (uint8_t)~CB_FLAG_CARRIED;
    } else if (grounded) {
        body->air_velocity = v3(0.0f, 0.0f, 0.0f);
    } else if (body->events.flags & CHAR_BODY_EVENT_HIT_WALL) {
        /* a wall met in the air stops the kept velocity going into it */
        fm_vec3_t n = body->events.wall_normal;
        float into = v3_dot(body->air_velocity, n);
        if (into < 0.0f) body->air_velocity = v3_madd(body->air_velocity, n, -into);
    }
    body->ground_velocity = grounded ? ground_v : v3(0.0f, 0.0f, 0.0f);
    record_events(body, was_grounded, was_floor_normal, v_up, jumping);

    body->velocity = clamp_report(body->velocity, up, max_speed);
    if (v3_finite(pos)) {
        body->origin = pos;
        if (body->owner_pos) *body->owner_pos = pos;
    }
    if (body->collider) {
        body->collider->write_mask = own_mask;
        sync_collider(body);
    }
    if (dropping) hide_one_way(scene, false, one_way_masks);
}
