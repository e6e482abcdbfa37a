/**
 * @file game.c
 * @brief Player controller of the char_body example: camera-relative movement with
 *        acceleration, jump with coyote time, buffering and variable height, steep-surface
 *        slowdown, normal/planet gravity toggle with a blended up vector, respawn.
 */
#include "game.h"
#include <math.h>

/* ---- vector helpers (by value: the example reads better this way) ---- */
fm_vec3_t game_v3(float x, float y, float z) { return (fm_vec3_t){{x, y, z}}; }
fm_vec3_t game_v3_add(fm_vec3_t a, fm_vec3_t b) { return game_v3(a.x + b.x, a.y + b.y, a.z + b.z); }
fm_vec3_t game_instance_point(const coll_mesh_instance_t *inst, fm_vec3_t local)
{
    fm_vec3_t s;
    fm_vec3_mul(&s, &local, &inst->xf.scale);
    fm_quat_rotate_vec3(&s, &inst->xf.rot, &s);
    return game_v3_add(s, inst->xf.pos);
}
fm_vec3_t game_v3_sub(fm_vec3_t a, fm_vec3_t b) { return game_v3(a.x - b.x, a.y - b.y, a.z - b.z); }
fm_vec3_t game_v3_scale(fm_vec3_t a, float s) { return game_v3(a.x * s, a.y * s, a.z * s); }
float game_v3_dot(fm_vec3_t a, fm_vec3_t b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
fm_vec3_t game_v3_cross(fm_vec3_t a, fm_vec3_t b)
{
    return game_v3(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}
float game_v3_len(fm_vec3_t a) { return sqrtf(game_v3_dot(a, a)); }
fm_vec3_t game_v3_norm(fm_vec3_t a)
{
    float l = game_v3_len(a);
    return l > FM_EPSILON ? game_v3_scale(a, 1.0f / l) : game_v3(0.0f, 0.0f, 0.0f);
}
fm_vec3_t game_v3_reject(fm_vec3_t a, fm_vec3_t n) { return game_v3_sub(a, game_v3_scale(n, game_v3_dot(a, n))); }

fm_vec3_t game_v3_transport(fm_vec3_t v, fm_vec3_t a, fm_vec3_t b)
{
    /* Quaternion of the shortest arc a -> b: (cross(a,b), 1 + dot(a,b)), normalized. */
    float d = game_v3_dot(a, b);
    if (d > 0.999999f) return v;
    fm_vec3_t c = game_v3_cross(a, b);
    fm_quat_t q;
    if (d < -0.9999f) {
        /* Opposite: half turn about any axis across a. */
        fm_vec3_t axis = game_v3_norm(game_v3_cross(a, fabsf(a.x) < 0.9f ? game_v3(1, 0, 0) : game_v3(0, 0, 1)));
        q = (fm_quat_t){{axis.x, axis.y, axis.z, 0.0f}};
    } else {
        q = (fm_quat_t){{c.x, c.y, c.z, 1.0f + d}};
        fm_quat_norm(&q, &q);
    }
    fm_vec3_t out;
    fm_quat_rotate_vec3(&out, &q, &v);
    return out;
}

fm_vec3_t game_v3_slerp(fm_vec3_t a, fm_vec3_t b, float t)
{
    float d = game_v3_dot(a, b);
    if (d > 0.9995f) return game_v3_norm(game_v3_add(a, game_v3_scale(game_v3_sub(b, a), t)));
    if (d < -1.0f) d = -1.0f;
    float ang = acosf(d);
    /* Component of b across a; for opposite vectors pick any perpendicular. */
    fm_vec3_t perp = game_v3_norm(game_v3_reject(b, a));
    if (game_v3_dot(perp, perp) < 0.5f)
        perp = game_v3_norm(game_v3_cross(a, fabsf(a.x) < 0.9f ? game_v3(1, 0, 0) : game_v3(0, 0, 1)));
    float s = ang * t;
    return game_v3_norm(game_v3_add(game_v3_scale(a, cosf(s)), game_v3_scale(perp, sinf(s))));
}

float game_clampf(float x, float lo, float hi) { return x < lo ? lo : (x > hi ? hi : x); }

/* Any unit vector across up, preferring `hint`. */
static fm_vec3_t across(fm_vec3_t hint, fm_vec3_t up)
{
    fm_vec3_t f = game_v3_norm(game_v3_reject(hint, up));
    if (game_v3_dot(f, f) > 0.5f) return f;
    f = game_v3_norm(game_v3_reject(game_v3(0, 0, -1), up));
    if (game_v3_dot(f, f) > 0.5f) return f;
    return game_v3_norm(game_v3_reject(game_v3(1, 0, 0), up));
}

/* ---- setup ---- */

void game_init(game_t *g, const game_level_t *level)
{
    *g = (game_t){0};
    g->level = *level;
    g->tuning = GAME_TUNING_DEFAULT;
    coll_scene_init(&g->scene);

    g->level_inst = (coll_mesh_instance_t){ .mesh = level->level, .xf = COLL_TRANSFORM_IDENTITY,
                                            .write_mask = 0x01, .id = GAME_LEVEL_ID };
    if (g->level_inst.mesh) coll_scene_add_mesh(&g->scene, &g->level_inst);

    for (uint8_t i = 0; i < g->level.platform_count; i++) {
        game_platform_t *p = &g->level.platforms[i];
        p->inst.mesh = p->mesh;
        p->inst.write_mask = 0x01;
        p->inst.id = (uint16_t)(GAME_PLATFORM_ID0 + i);
    }
    game_update_platforms(g, 0.0f);
    for (uint8_t i = 0; i < g->level.platform_count; i++)
        if (g->level.platforms[i].inst.mesh) coll_scene_add_mesh(&g->scene, &g->level.platforms[i].inst);

    if (level->one_way_mesh) {
        g->one_way_inst = (coll_mesh_instance_t){ .mesh = level->one_way_mesh, .xf = COLL_TRANSFORM_IDENTITY,
                                                  .write_mask = 0x01, .id = GAME_ONE_WAY_ID,
                                                  .flags = COLL_INSTANCE_ONE_WAY };
        g->one_way_inst.xf.pos = level->one_way_pos;
        coll_scene_add_mesh(&g->scene, &g->one_way_inst);
    }

    /* The player and the non-player bodies see meshes and each other's colliders. */
    char_body_settings_t s = CHAR_BODY_SETTINGS_DEFAULT;
    s.coll_types = COLL_TYPE_MESH | COLL_TYPE_BODY;
    g->pos = level->spawn;
    char_body_init(&g->body, &g->pos);
    char_body_configure(&g->body, &s);
    char_body_teleport(&g->body, level->spawn, true);
    /* each body keeps the triangles around it across steps (the same answers, fewer grid walks) */
    char_body_set_gather_cache(&g->body, &g->gather_cache);
    g->collider = (coll_body_t){ .write_mask = 0x01, .id = GAME_PLAYER_COLLIDER_ID };
    char_body_set_collider(&g->body, &g->collider);
    coll_scene_add_body(&g->scene, &g->collider);
    for (uint8_t i = 0; i < level->npc_count && i < GAME_MAX_NPCS; i++) {
        game_npc_state_t *n = &g->npcs[i];
        n->pos = game_v3_add(level->npcs[i].a, game_v3(0.0f, 0.5f * s.height, 0.0f));
        char_body_init(&n->body, &n->pos);
        char_body_configure(&n->body, &s);
        char_body_teleport(&n->body, n->pos, true);
        char_body_set_gather_cache(&n->body, &n->gather_cache);
        n->collider = (coll_body_t){ .write_mask = 0x01, .id = (uint16_t)(GAME_NPC_ID0 + i) };
        char_body_set_collider(&n->body, &n->collider);
        coll_scene_add_body(&g->scene, &n->collider);
        n->to_b = true;
    }
    g->jump_floor_id = -1;

    g->up = game_v3(0, 1, 0);
    g->cam_fwd = game_v3(sinf(level->spawn_yaw), 0.0f, -cosf(level->spawn_yaw));
    g->facing = g->cam_fwd;
    g->cam_pitch = 0.5f;
    g->cam_dist = 9.0f;
    g->speed_factor = 1.0f;
    g->blend_t = 1.0f;
    g->prev_pos = g->pos;
    g->prev_floor_id = -1;
    g->stats.min_speed_factor = 1.0f;
}

/* ---- platforms ---- */

static coll_transform_t platform_pose(const game_platform_t *p, float t)
{
    coll_transform_t xf = COLL_TRANSFORM_IDENTITY;
    xf.pos = p->base_pos;
    xf.scale = p->base_scale;
    float w = p->period > 0.0f ? 2.0f * FM_PI * t / p->period : 0.0f;
    fm_vec3_t yaxis = game_v3(0, 1, 0);
    switch (p->kind) {
    case GAME_PLATFORM_TRANSLATE:
        xf.pos = game_v3_add(p->base_pos, game_v3_scale(p->axis, p->amount * sinf(w)));
        break;
    case GAME_PLATFORM_ROTATE:
        fm_quat_from_axis_angle(&xf.rot, &yaxis, fmodf(p->amount * t, 2.0f * FM_PI));
        break;
    case GAME_PLATFORM_SCALE: {
        float s = 1.0f + p->amount * sinf(w);
        xf.scale.x = p->base_scale.x * s; /* wider and deeper; the top stays put */
        xf.scale.z = p->base_scale.z * s;
        break;
    }
    case GAME_PLATFORM_LIFT:
        xf.pos.y += p->amount * 0.5f * (1.0f - cosf(w));
        break;
    }
    return xf;
}

void game_update_platforms(game_t *g, float t)
{
    for (uint8_t i = 0; i < g->level.platform_count; i++)
        g->level.platforms[i].inst.xf = platform_pose(&g->level.platforms[i], t);
}

/* World point p carried by a transform change a -> b (p fixed in the moving frame). */
static fm_vec3_t carry_point(const coll_transform_t *a, const coll_transform_t *b, fm_vec3_t p)
{
    fm_quat_t inv;
    fm_quat_inverse(&inv, &a->rot);
    fm_vec3_t l = game_v3_sub(p, a->pos), r;
    fm_quat_rotate_vec3(&r, &inv, &l);
    r = game_v3(r.x / a->scale.x, r.y / a->scale.y, r.z / a->scale.z);
    r = game_v3(r.x * b->scale.x, r.y * b->scale.y, r.z * b->scale.z);
    fm_quat_rotate_vec3(&l, &b->rot, &r);
    return game_v3_add(l, b->pos);
}

/* ---- the step ---- */

char_body_ground_state_t game_body_state(const game_t *g)
{
    return char_body_ground_state(&g->body);
}

/* The non-player bodies walk their patrols (flat, normal gravity levels only). */
static void step_npcs(game_t *g, float dt)
{
    for (uint8_t i = 0; i < g->level.npc_count && i < GAME_MAX_NPCS; i++) {
        game_npc_state_t *n = &g->npcs[i];
        const game_npc_t *d = &g->level.npcs[i];
        fm_vec3_t foot = char_body_foot_pos(&n->body);
        fm_vec3_t to = game_v3_reject(game_v3_sub(n->to_b ? d->b : d->a, foot), game_v3(0, 1, 0));
        if (game_v3_len(to) < 0.3f) n->to_b = !n->to_b;
        n->body.input_velocity = game_v3_scale(game_v3_norm(to), d->speed);
        char_body_move_and_slide_in(&n->body, &g->scene, dt);
        /* the player touching this body (capsules, same height): a bump */
        fm_vec3_t dpos = game_v3_reject(game_v3_sub(n->pos, g->pos), g->up);
        float dy = fabsf(game_v3_dot(game_v3_sub(n->pos, g->pos), g->up));
        float reach = char_body_get_settings(&n->body)->radius + char_body_get_settings(&g->body)->radius + 0.01f;
        if (game_v3_len(dpos) < reach && dy < 1.0f) g->stats.npc_bumps++;
    }
}

void game_move_basis(const game_t *g, fm_vec3_t *fwd, fm_vec3_t *right)
{
    *fwd = g->cam_fwd;
    *right = game_v3_cross(g->cam_fwd, g->up);
}

static void set_up(game_t *g, fm_vec3_t new_up)
{
    new_up = game_v3_norm(new_up);
    if (game_v3_dot(new_up, new_up) < 0.5f) return;
    /* Carry the camera, facing and horizontal velocity along with the turn of up. */
    g->cam_fwd = across(game_v3_transport(g->cam_fwd, g->up, new_up), new_up);
    g->facing = across(game_v3_transport(g->facing, g->up, new_up), new_up);
    g->move_vel = game_v3_reject(game_v3_transport(g->move_vel, g->up, new_up), new_up);
    g->up = new_up;
    char_body_set_up(&g->body, new_up);
}

static fm_vec3_t gravity_target(const game_t *g)
{
    if (g->planet_gravity) {
        fm_vec3_t d = game_v3_norm(game_v3_sub(g->pos, g->level.planet_center));
        if (game_v3_dot(d, d) > 0.5f) return d;
        return g->up;
    }
    return game_v3(0, 1, 0);
}

static void respawn(game_t *g)
{
    g->planet_gravity = false;
    g->blend_t = 1.0f;
    set_up(g, game_v3(0, 1, 0));
    g->move_vel = game_v3(0, 0, 0);
    g->speed_factor = 1.0f;
    g->jumping = false;
    g->coyote_timer = 0.0f;
    g->jump_buffer_timer = 0.0f;
    char_body_teleport(&g->body, g->level.spawn, true);
    g->stats.respawns++;
}

void game_step(game_t *g, const game_input_t *in, float dt)
{
    const game_tuning_t *tu = &g->tuning;
    if (!(dt > 0.0f)) return;

    /* Platforms first: the body reads their new pose and is carried by the change. */
    coll_transform_t prev_xf[GAME_MAX_PLATFORMS];
    for (uint8_t i = 0; i < g->level.platform_count; i++) prev_xf[i] = g->level.platforms[i].inst.xf;
    g->time += dt;
    game_update_platforms(g, g->time);

    /* Gravity toggle: blend up from where it is to the new target over gravity_blend s. */
    if (in->toggle_gravity && !g->toggle_held_prev && g->level.has_planet) {
        g->planet_gravity = !g->planet_gravity;
        g->blend_from = g->up;
        g->blend_t = 0.0f;
        g->stats.gravity_toggles++;
    }
    g->toggle_held_prev = in->toggle_gravity;
    fm_vec3_t target = gravity_target(g);
    if (g->blend_t < 1.0f) {
        g->blend_t = game_clampf(g->blend_t + dt / tu->gravity_blend, 0.0f, 1.0f);
        set_up(g, game_v3_slerp(g->blend_from, target, g->blend_t));
    } else {
        set_up(g, target);
    }

    /* Camera orbit. */
    fm_quat_t yaw;
    fm_quat_from_axis_angle(&yaw, &g->up, -game_clampf(in->cam_x, -1, 1) * tu->cam_yaw_rate * dt);
    fm_quat_rotate_vec3(&g->cam_fwd, &yaw, &g->cam_fwd);
    g->cam_fwd = across(g->cam_fwd, g->up);
    g->cam_pitch = game_clampf(g->cam_pitch + game_clampf(in->cam_y, -1, 1) * tu->cam_pitch_rate * dt, -0.3f, 1.35f);

    /* Grounded state of the last step. */
    bool on_floor = char_body_is_on_floor(&g->body);
    bool steep = char_body_is_on_steep_surface(&g->body);
    bool grounded = on_floor && !steep;

    /* Steep surfaces slow the player down; normal ground restores full speed. */
    if (on_floor) {
        float goal = steep ? tu->steep_min_factor : 1.0f;
        float stepv = tu->steep_rate * dt;
        g->speed_factor = g->speed_factor < goal ? game_clampf(g->speed_factor + stepv, 0.0f, goal)
                                                 : game_clampf(g->speed_factor - stepv, goal, 1.0f);
    }
    if (steep) g->stats.steep_time += dt;
    if (g->speed_factor < g->stats.min_speed_factor) g->stats.min_speed_factor = g->speed_factor;

    /* Camera-relative stick -> wished velocity; accelerate towards it. */
    float sx = game_clampf(in->stick_x, -1, 1), sy = game_clampf(in->stick_y, -1, 1);
    float mag = sqrtf(sx * sx + sy * sy);
    if (mag > 1.0f) { sx /= mag; sy /= mag; }
    fm_vec3_t fwd, right;
    game_move_basis(g, &fwd, &right);
    fm_vec3_t wish = game_v3_scale(game_v3_add(game_v3_scale(fwd, sy), game_v3_scale(right, sx)),
                                   tu->run_speed * g->speed_factor);
    float accel = (grounded ? tu->ground_accel : tu->air_accel) * dt;
    fm_vec3_t dv = game_v3_sub(wish, g->move_vel);
    float dl = game_v3_len(dv);
    if (dl > accel) dv = game_v3_scale(dv, accel / dl);
    g->move_vel = game_v3_reject(game_v3_add(g->move_vel, dv), g->up);
    if (game_v3_len(wish) > 0.1f) g->facing = game_v3_norm(wish);
    g->body.input_velocity = g->move_vel;

    /* Jump: buffered press, coyote window, variable height. */
    bool pressed = in->jump && !g->jump_held_prev;
    g->jump_held_prev = in->jump;
    if (pressed) g->jump_buffer_timer = tu->jump_buffer;
    if (grounded) g->coyote_timer = tu->coyote_time;
    if ((pressed || g->jump_buffer_timer > 0.0f) && g->coyote_timer > 0.0f) {
        fm_vec3_t v = game_v3_reject(char_body_get_velocity(&g->body), g->up);
        char_body_set_velocity(&g->body, game_v3_add(v, game_v3_scale(g->up, tu->jump_speed)));
        g->stats.jumps++;
        if (!grounded) g->stats.coyote_jumps++;
        if (!pressed) g->stats.buffered_jumps++;
        g->jump_buffer_timer = 0.0f;
        g->coyote_timer = 0.0f;
        g->jumping = true;
        g->jump_floor_id = char_body_floor_id(&g->body);
    } else if (g->jumping) {
        fm_vec3_t v = char_body_get_velocity(&g->body);
        float vup = game_v3_dot(v, g->up);
        if (vup <= 0.0f) {
            g->jumping = false;
        } else if (!in->jump) {
            char_body_set_velocity(&g->body, game_v3_sub(v, game_v3_scale(g->up, vup * (1.0f - tu->jump_cut))));
            g->stats.jump_cuts++;
            g->jumping = false;
        }
    }
    g->jump_buffer_timer -= dt;
    if (!grounded) g->coyote_timer -= dt;

    /* Drop through the one-way platform stood on. */
    if (in->drop && !g->drop_held_prev && char_body_floor_id(&g->body) == GAME_ONE_WAY_ID) {
        char_body_drop_through(&g->body);
        g->stats.drops++;
    }
    g->drop_held_prev = in->drop;

    char_body_move_and_slide_in(&g->body, &g->scene, dt);
    step_npcs(g, dt);

    /* Step events: the camera absorbs stair steps and eases back (as Quake III's view
     * height smoothing); landings count the one-way platform and jumps off a moving
     * platform that came down on it again. */
    const char_body_events_t *ev = char_body_events(&g->body);
    if (ev->flags & CHAR_BODY_EVENT_STEPPED) {
        g->cam_step -= ev->step;
        g->stats.camera_steps++;
    }
    g->cam_step -= g->cam_step * game_clampf(12.0f * dt, 0.0f, 1.0f); /* eases back at 12 /s */
    if (ev->flags & CHAR_BODY_EVENT_LANDED) {
        int32_t f = char_body_floor_id(&g->body);
        if (f == GAME_ONE_WAY_ID) g->stats.one_way_landings++;
        if (f >= GAME_PLATFORM_ID0 && f < GAME_PLATFORM_ID0 + GAME_MAX_PLATFORMS && f == g->jump_floor_id)
            g->stats.platform_jump_landings++;
        g->jump_floor_id = -1;
    }

    /* Ride measurement: how far the player actually moved along with the platform stood on
     * (its motion at the player's position), not counting the player's own walking. */
    int32_t fid = char_body_floor_id(&g->body);
    int32_t pi = g->prev_floor_id - GAME_PLATFORM_ID0;
    if (fid == g->prev_floor_id && pi >= 0 && pi < g->level.platform_count) {
        fm_vec3_t plat = game_v3_sub(carry_point(&prev_xf[pi], &g->level.platforms[pi].inst.xf, g->prev_pos),
                                     g->prev_pos);
        float pl = game_v3_len(plat);
        if (pl > 1e-6f) {
            float along = game_v3_dot(game_v3_sub(g->pos, g->prev_pos), plat) / pl;
            g->stats.ride_distance[pi] += game_clampf(along, 0.0f, pl);
        }
        g->stats.ride_time[pi] += dt;
    }

    /* Fell out of the level? */
    bool out = g->pos.y < g->level.kill_height;
    if (g->level.has_planet)
        out = game_v3_len(game_v3_sub(g->pos, g->level.planet_center)) > g->level.kill_distance;
    if (out) respawn(g);

    g->prev_pos = g->pos;
    g->prev_floor_id = char_body_floor_id(&g->body);
    g->stats.frames++;
}

void game_camera(const game_t *g, fm_vec3_t *eye, fm_vec3_t *target, fm_vec3_t *cam_up)
{
    fm_vec3_t t = game_v3_add(g->pos, game_v3_scale(g->up, 0.6f + g->cam_step));
    fm_vec3_t back = game_v3_add(game_v3_scale(g->cam_fwd, -cosf(g->cam_pitch)),
                                 game_v3_scale(g->up, sinf(g->cam_pitch)));
    *eye = game_v3_add(t, game_v3_scale(back, g->cam_dist));
    *target = t;
    *cam_up = g->up;
}
