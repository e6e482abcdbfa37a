/**
 * @file game_replay.c
 * @brief Script parser and waypoint autopilot for the char_body example (see game_replay.h).
 */
#include "game_replay.h"
#include <math.h>

static const char *const op_names[] = {
    "walk_to", "jump", "coyote_jump", "wait", "board", "ride", "wait_phase", "gravity",
    "planet_lap", "mark", "push", "land_jump",
};

const char *replay_op_name(replay_op_t op)
{
    return (unsigned)op < sizeof op_names / sizeof op_names[0] ? op_names[op] : "?";
}

/* ---- parsing (no libc: the console build has none to spare) ---- */

typedef struct {
    const char *p, *end;
} cursor_t;

static bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r'; }

/* Next word on the line into buf; false at end of line. */
static bool next_word(cursor_t *c, char *buf, int cap)
{
    while (c->p < c->end && is_space(*c->p)) c->p++;
    if (c->p >= c->end || *c->p == '\n' || *c->p == '#') return false;
    int n = 0;
    while (c->p < c->end && !is_space(*c->p) && *c->p != '\n' && *c->p != '#') {
        if (n < cap - 1) buf[n++] = *c->p;
        c->p++;
    }
    buf[n] = 0;
    return true;
}

static bool str_eq(const char *a, const char *b)
{
    while (*a && *a == *b) { a++; b++; }
    return *a == *b;
}

/* Decimal float: [-]digits[.digits]. */
static bool parse_float(const char *s, float *out)
{
    float sign = 1.0f, v = 0.0f, scale = 1.0f;
    bool digits = false, dot = false;
    if (*s == '-') { sign = -1.0f; s++; } else if (*s == '+') s++;
    for (; *s; s++) {
        if (*s >= '0' && *s <= '9') {
            digits = true;
            if (dot) { scale *= 0.1f; v += (float)(*s - '0') * scale; }
            else v = v * 10.0f + (float)(*s - '0');
        } else if (*s == '.' && !dot) {
            dot = true;
        } else {
            return false;
        }
    }
    *out = sign * v;
    return digits;
}

typedef struct {
    const char *word;
    replay_op_t op;
    uint8_t min_args, max_args; /* numeric arguments */
    bool has_name;              /* a word argument first */
} op_syntax_t;

static const op_syntax_t syntax[] = {
    {"walk_to", REPLAY_WALK_TO, 2, 3, false},
    {"jump", REPLAY_JUMP, 0, 1, false},
    {"coyote_jump", REPLAY_COYOTE_JUMP, 2, 3, false},
    {"wait", REPLAY_WAIT, 1, 1, false},
    {"board", REPLAY_BOARD, 1, 3, false},
    {"ride", REPLAY_RIDE, 2, 4, false},
    {"wait_phase", REPLAY_WAIT_PHASE, 3, 3, false},
    {"gravity", REPLAY_GRAVITY, 0, 0, true},
    {"planet_lap", REPLAY_PLANET_LAP, 0, 1, false},
    {"mark", REPLAY_MARK, 0, 0, true},
    {"push", REPLAY_PUSH, 3, 4, false},
    {"land_jump", REPLAY_LAND_JUMP, 0, 1, false},
    {"drop", REPLAY_DROP, 0, 0, false},
};

bool replay_parse(replay_t *r, const char *text, uint32_t len)
{
    *r = (replay_t){0};
    cursor_t c = { text, text + len };
    uint16_t line = 0;
    char w[REPLAY_NAME_LEN];
    while (c.p < c.end) {
        line++;
        const char *eol = c.p;
        while (eol < c.end && *eol != '\n') eol++;
        cursor_t lc = { c.p, eol };
        c.p = eol < c.end ? eol + 1 : eol;
        if (!next_word(&lc, w, sizeof w)) continue;
        const op_syntax_t *sx = 0;
        for (unsigned i = 0; i < sizeof syntax / sizeof syntax[0]; i++)
            if (str_eq(w, syntax[i].word)) sx = &syntax[i];
        if (!sx || r->count >= REPLAY_MAX_COMMANDS) { r->error_line = line; return false; }
        replay_cmd_t *cmd = &r->cmds[r->count];
        *cmd = (replay_cmd_t){ .op = sx->op, .line = line };
        if (sx->has_name && !next_word(&lc, cmd->name, sizeof cmd->name)) { r->error_line = line; return false; }
        int n = 0;
        while (next_word(&lc, w, sizeof w)) {
            if (n >= sx->max_args || !parse_float(w, &cmd->a[n])) { r->error_line = line; return false; }
            n++;
        }
        if (n < sx->min_args) { r->error_line = line; return false; }
        /* defaults */
        if (sx->op == REPLAY_WALK_TO && n < 3) cmd->a[2] = -1.0f;    /* run speed */
        if (sx->op == REPLAY_JUMP && n < 1) cmd->a[0] = 0.5f;
        if (sx->op == REPLAY_COYOTE_JUMP && n < 3) cmd->a[2] = 0.07f;
        if (sx->op == REPLAY_PLANET_LAP && n < 1) cmd->a[0] = -1.0f;
        if (sx->op == REPLAY_LAND_JUMP && n < 1) cmd->a[0] = 0.4f;
        if (sx->op == REPLAY_GRAVITY && !str_eq(cmd->name, "planet") && !str_eq(cmd->name, "normal")) {
            r->error_line = line;
            return false;
        }
        r->count++;
    }
    return true;
}

bool replay_done(const replay_t *r) { return r->pc >= r->count; }

const replay_mark_t *replay_find_mark(const replay_t *r, const char *name)
{
    for (uint16_t i = 0; i < r->mark_count; i++)
        if (str_eq(r->marks[i].name, name)) return &r->marks[i];
    return 0;
}

/* ---- autopilot ---- */

/* Stick for a world-space wish direction (across up) at `speed` m/s. */
static void steer(const game_t *g, game_input_t *in, fm_vec3_t dir, float speed)
{
    fm_vec3_t fwd, right;
    game_move_basis(g, &fwd, &right);
    dir = game_v3_norm(game_v3_reject(dir, g->up));
    float s = game_clampf(speed / g->tuning.run_speed, 0.0f, 1.0f);
    in->stick_y = game_v3_dot(dir, fwd) * s;
    in->stick_x = game_v3_dot(dir, right) * s;
    /* Swing the camera round behind the motion, as a player would. */
    float side = game_v3_dot(dir, right), ahead = game_v3_dot(dir, fwd);
    float ang = atan2f(side, ahead);
    in->cam_x = game_clampf(ang * 0.8f, -0.6f, 0.6f);
}

/* Horizontal offset from the player to a point, across up. */
static fm_vec3_t flat_to(const game_t *g, fm_vec3_t p)
{
    return game_v3_reject(game_v3_sub(p, g->pos), g->up);
}

/* Steers to p; true once within `radius`. When the body stops dead while steering hard
 * (a bump on a turntable, a post), it sidesteps at 75 degrees for a moment, alternating
 * sides, like a player walking round the obstacle (not for `push`, which leans on walls). */
static bool go_to(replay_t *r, const game_t *g, game_input_t *in, fm_vec3_t p, float speed, float radius, float dt,
                  bool detour)
{
    fm_vec3_t d = flat_to(g, p);
    float dist = game_v3_len(d);
    if (dist < radius) return true;
    if (speed <= 0.0f) speed = g->tuning.run_speed;
    speed = game_clampf(0.6f + 4.0f * dist, 0.0f, speed);
    float moving = game_v3_len(game_v3_reject(char_body_get_velocity(&g->body), g->up));
    if (detour && r->detour_time <= 0.0f && speed > 2.0f && moving < 0.3f && game_body_state(g) == CHAR_BODY_ON_FLOOR) {
        r->stuck_time += dt;
        if (r->stuck_time > 0.3f) {
            r->detour_time = 0.6f;
            r->detour_sign = r->detour_sign > 0.0f ? -1.0f : 1.0f;
            r->detours++;
        }
    } else {
        r->stuck_time = 0.0f;
    }
    if (detour && r->detour_time > 0.0f) {
        r->detour_time -= dt;
        fm_quat_t q;
        fm_quat_from_axis_angle(&q, &g->up, r->detour_sign * 1.309f);
        fm_quat_rotate_vec3(&d, &q, &d);
    }
    steer(g, in, d, speed);
    return false;
}

static fm_vec3_t platform_point(const game_t *g, int n, float dx, float dz)
{
    const coll_transform_t *xf = &g->level.platforms[n].inst.xf;
    fm_vec3_t l = game_v3(dx * xf->scale.x, 0.0f, dz * xf->scale.z), w;
    fm_quat_rotate_vec3(&w, &xf->rot, &l);
    return game_v3_add(w, xf->pos);
}

static float time_limit(replay_op_t op)
{
    switch (op) {
    case REPLAY_WAIT: case REPLAY_PUSH: case REPLAY_JUMP: case REPLAY_MARK: case REPLAY_GRAVITY: case REPLAY_DROP: return 1e9f;
    case REPLAY_PLANET_LAP: return 90.0f;
    default: return 30.0f;
    }
}

static void add_mark(replay_t *r, const game_t *g, const char *name)
{
    if (r->mark_count >= REPLAY_MAX_MARKS) return;
    replay_mark_t *m = &r->marks[r->mark_count++];
    int i = 0;
    for (; name[i] && i < REPLAY_NAME_LEN - 1; i++) m->name[i] = name[i];
    m->name[i] = 0;
    m->time = g->time;
    m->pos = g->pos;
    m->state = game_body_state(g);
    m->floor_id = char_body_floor_id(&g->body);
}

static void next_cmd(replay_t *r)
{
    r->pc++;
    r->cmd_time = 0.0f;
    r->sub_time = 0.0f;
    r->sub_state = 0;
}

void replay_input(replay_t *r, const game_t *g, game_input_t *in, float dt)
{
    *in = (game_input_t){0};
    /* Instant commands run back to back; at most a handful per frame. */
    for (int guard = 0; guard < 8 && r->pc < r->count; guard++) {
        const replay_cmd_t *c = &r->cmds[r->pc];
        bool done = false, instant = false;
        switch (c->op) {
        case REPLAY_WALK_TO:
            done = go_to(r, g, in, game_v3(c->a[0], g->pos.y, c->a[1]), c->a[2], 0.35f, dt, true);
            instant = done;
            break;
        case REPLAY_JUMP:
            r->jump_hold = c->a[0] > 0.0f ? c->a[0] : GAME_DT;
            done = instant = true;
            break;
        case REPLAY_COYOTE_JUMP: {
            /* phase 0: run until the floor is gone; 1: count DELAY, then jump. */
            fm_vec3_t target = game_v3(c->a[0], g->pos.y, c->a[1]);
            steer(g, in, flat_to(g, target), g->tuning.run_speed);
            if (r->sub_state == 0 && game_body_state(g) == CHAR_BODY_AIRBORNE) { r->sub_state = 1; r->sub_time = 0.0f; }
            if (r->sub_state == 1) {
                r->sub_time += dt;
                if (r->sub_time >= c->a[2]) { r->jump_hold = 0.5f; done = true; }
            }
            break;
        }
        case REPLAY_PUSH:
            (void)go_to(r, g, in, game_v3(c->a[0], g->pos.y, c->a[1]), c->a[3], 0.05f, dt, false); /* pushes into walls on purpose */
            done = r->cmd_time + 0.5f * dt >= c->a[2];
            break;
        case REPLAY_LAND_JUMP: {
            /* Keep the current heading; press jump just before touching down. */
            fm_vec3_t v = char_body_get_velocity(&g->body);
            if (game_v3_len(game_v3_reject(v, g->up)) > 0.5f) steer(g, in, v, game_v3_len(game_v3_reject(v, g->up)));
            coll_ray_hit_t hit;
            fm_vec3_t down = game_v3_scale(g->up, -1.0f);
            if (game_body_state(g) == CHAR_BODY_AIRBORNE && game_v3_dot(v, g->up) < 0.0f &&
                coll_raycast(&g->scene, char_body_foot_pos(&g->body), down, c->a[0], 0x01, COLL_TYPE_MESH, &hit)) {
                r->jump_hold = 0.5f;
                done = true;
            }
            break;
        }
        case REPLAY_WAIT:
            done = r->cmd_time + 0.5f * dt >= c->a[0];
            break;
        case REPLAY_BOARD:
        case REPLAY_RIDE: {
            int n = (int)c->a[0];
            if (n < 0 || n >= g->level.platform_count) { done = instant = true; r->timeouts++; break; }
            float dx = c->op == REPLAY_RIDE ? c->a[2] : c->a[1];
            float dz = c->op == REPLAY_RIDE ? c->a[3] : c->a[2];
            bool on = char_body_floor_id(&g->body) == GAME_PLATFORM_ID0 + n;
            if (r->sub_state == 0) {
                bool there = go_to(r, g, in, platform_point(g, n, dx, dz), 0.0f, 0.3f, dt, true);
                if (on && there) {
                    r->sub_state = 1;
                    r->sub_time = 0.0f;
                    if (c->op == REPLAY_BOARD) done = instant = true;
                }
            } else {
                r->sub_time += dt;
                done = r->sub_time + 0.5f * dt >= c->a[1];
            }
            break;
        }
        case REPLAY_WAIT_PHASE: {
            int n = (int)c->a[0];
            if (n < 0 || n >= g->level.platform_count) { done = instant = true; r->timeouts++; break; }
            const game_platform_t *p = &g->level.platforms[n];
            float period = p->period > 0.0f ? p->period : (p->amount > 0.0f ? 2.0f * FM_PI / p->amount : 1.0f);
            float ph = fmodf(g->time, period) / period;
            done = ph >= c->a[1] && ph < c->a[2];
            instant = done && r->cmd_time == 0.0f;
            break;
        }
        case REPLAY_GRAVITY: {
            bool want = str_eq(c->name, "planet");
            if (g->planet_gravity != want && !r->gravity_press) {
                in->toggle_gravity = true;
                r->gravity_press = true;
                r->cmd_time += dt;
                goto out; /* release next frame, then re-check */
            }
            r->gravity_press = false;
            done = instant = true;
            break;
        }
        case REPLAY_PLANET_LAP: {
            fm_vec3_t radial = game_v3_norm(game_v3_sub(g->pos, g->level.planet_center));
            if (r->sub_state == 0) {
                fm_vec3_t fwd, right;
                game_move_basis(g, &fwd, &right);
                r->lap_axis = game_v3_norm(game_v3_cross(radial, fwd));
                r->lap_prev = radial;
                r->lap_angle = 0.0f;
                r->sub_state = 1;
            }
            /* Travel along the great circle; pull back towards its plane when drifting. */
            fm_vec3_t along = game_v3_cross(r->lap_axis, radial);
            float off = game_v3_dot(game_v3_sub(g->pos, g->level.planet_center), r->lap_axis);
            fm_vec3_t dir = game_v3_sub(along, game_v3_scale(r->lap_axis, game_clampf(off * 0.3f, -0.7f, 0.7f)));
            steer(g, in, dir, c->a[0] > 0.0f ? c->a[0] : g->tuning.run_speed);
            fm_vec3_t a = game_v3_norm(game_v3_reject(r->lap_prev, r->lap_axis));
            fm_vec3_t b = game_v3_norm(game_v3_reject(radial, r->lap_axis));
            r->lap_angle += atan2f(game_v3_dot(game_v3_cross(a, b), r->lap_axis), game_v3_dot(a, b));
            r->lap_prev = radial;
            if (fabsf(r->lap_angle) >= 2.0f * FM_PI) { r->laps++; done = true; }
            break;
        }
        case REPLAY_MARK:
            add_mark(r, g, c->name);
            done = instant = true;
            break;
        case REPLAY_DROP:
            in->drop = true;
            done = true; /* one frame held */
            break;
        }
        if (r->jump_hold > 0.0f) in->jump = true;
        if (done) {
            next_cmd(r);
            if (!instant) break;
            continue;
        }
        r->cmd_time += dt;
        if (r->cmd_time > time_limit(c->op)) {
            if (r->timeouts++ == 0) r->timeout_line = c->line;
            next_cmd(r);
        }
        break;
    }
out:
    if (r->jump_hold > 0.0f) {
        in->jump = true;
        r->jump_hold -= dt;
    }
}
