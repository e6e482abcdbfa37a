/* Soak harness: random play, the per-frame simulation with property checks, replay files. */
#include "soak_sim.h"
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* ------------------------------------------------------------------ play */
static const float dt_choices[] = {1.0f / 240, 1.0f / 120, 1.0f / 60, 1.0f / 60, 1.0f / 30, 1.0f / 30, 1.0f / 20, 1.0f / 5};

void soak_play_init(soak_play_t *p, uint64_t seed)
{
    memset(p, 0, sizeof *p);
    soak_rng_seed(&p->rng, soak_mix64(seed ^ 0x9A7ull));
    p->base_dt = dt_choices[soak_rng_below(&p->rng, (uint32_t)(sizeof dt_choices / sizeof dt_choices[0]))];
}

static float huge_value(soak_rng_t *r)
{
    static const float vals[] = {1e3f, 3e4f, 1e6f, 1e9f, 1e20f, FLT_MAX};
    float v = vals[soak_rng_below(r, 6)];
    return soak_rng_chance(r, 0.5) ? -v : v;
}
static float weird_value(soak_rng_t *r)
{
    switch (soak_rng_below(r, 4)) {
    case 0: return NAN;
    case 1: return INFINITY;
    case 2: return -INFINITY;
    default: return huge_value(r);
    }
}

/* A point where the capsule centre is inside the room, possibly inside geometry. */
static fm_vec3_t teleport_target(soak_rng_t *r, const soak_level_t *lvl, const char_body_settings_t *s)
{
    double c[3];
    if (lvl->nwtris > 0 && soak_rng_chance(r, 0.5)) {
        const soak_wtri_t *w = &lvl->wtris[soak_rng_below(r, lvl->nwtris)];
        double u = soak_rng_unit(r), v = soak_rng_unit(r);
        if (u + v > 1) { u = 1 - u; v = 1 - v; }
        for (int k = 0; k < 3; k++)
            c[k] = w->v[0][k] + (w->v[1][k] - w->v[0][k]) * u + (w->v[2][k] - w->v[0][k]) * v +
                   soak_rng_range(r, -0.3, 0.3);
    } else {
        c[0] = soak_rng_range(r, -SOAK_ROOM_HALF, SOAK_ROOM_HALF);
        c[1] = soak_rng_range(r, 0, SOAK_ROOM_HEIGHT * 0.6);
        c[2] = soak_rng_range(r, -SOAK_ROOM_HALF, SOAK_ROOM_HALF);
    }
    const double m = 0.5 * (double)s->height + 0.1; /* the whole capsule inside, any up */
    const double lo[3] = {-SOAK_ROOM_HALF + m, m, -SOAK_ROOM_HALF + m};
    const double hi[3] = {SOAK_ROOM_HALF - m, SOAK_ROOM_HEIGHT - m, SOAK_ROOM_HALF - m};
    fm_vec3_t o;
    for (int k = 0; k < 3; k++) {
        if (c[k] < lo[k]) c[k] = lo[k];
        if (c[k] > hi[k]) c[k] = hi[k];
        o.v[k] = (float)(c[k] - s->center_offset.v[k]); /* owner = centre - offset */
    }
    return o;
}

static bool center_clear_of_room(const char_body_settings_t *s, fm_vec3_t owner)
{
    double m = 0.5 * (double)s->height + 0.1, c[3];
    for (int k = 0; k < 3; k++) c[k] = (double)owner.v[k] + s->center_offset.v[k];
    return c[0] > -SOAK_ROOM_HALF + m && c[0] < SOAK_ROOM_HALF - m && c[1] > m && c[1] < SOAK_ROOM_HEIGHT - m &&
           c[2] > -SOAK_ROOM_HALF + m && c[2] < SOAK_ROOM_HALF - m;
}

void soak_play_next(soak_play_t *p, const soak_level_t *lvl, const char_body_settings_t *s, fm_vec3_t owner,
                    soak_frame_t *f)
{
    soak_rng_t *r = &p->rng;
    memset(f, 0, sizeof *f);
    if (p->hold == 0) {
        double u = soak_rng_unit(r);
        double ang = soak_rng_range(r, 0, 6.283185307179586);
        double sp;
        if (u < 0.15) sp = 0;
        else if (u < 0.75) sp = soak_rng_range(r, 0.5, 8);
        else if (u < 0.94) sp = soak_rng_range(r, 8, 30);
        else sp = -1;
        if (sp >= 0) {
            p->input.x = (float)(soak_cos(ang) * sp);
            p->input.y = soak_rng_chance(r, 0.2) ? (float)soak_rng_range(r, -20, 20) : 0.0f; /* ignored part */
            p->input.z = (float)(soak_sin(ang) * sp);
        } else if (soak_rng_chance(r, 0.6)) {
            float h = huge_value(r);
            p->input.x = (float)(soak_cos(ang) * h);
            p->input.y = 0.0f;
            p->input.z = (float)(soak_sin(ang) * h);
        } else {
            p->input.x = soak_rng_chance(r, 0.5) ? weird_value(r) : 1.0f;
            p->input.y = soak_rng_chance(r, 0.3) ? weird_value(r) : 0.0f;
            p->input.z = soak_rng_chance(r, 0.5) ? weird_value(r) : 2.0f;
        }
        p->hold = 3 + soak_rng_below(r, sp < 0 ? 10 : 150);
        if (soak_rng_chance(r, 0.02))
            p->base_dt = dt_choices[soak_rng_below(r, (uint32_t)(sizeof dt_choices / sizeof dt_choices[0]))];
    }
    p->hold--;
    f->input = p->input;
    if (p->gentle) {
        /* real levels: plain walking (the input drawn above, tamed) and jumping */
        double l = sqrt((double)f->input.x * f->input.x + (double)f->input.z * f->input.z);
        if (!isfinite(l) || l > 8.0) {
            double a = soak_rng_range(r, 0, 6.283185307179586), sp = soak_rng_range(r, 0.5, 8);
            p->input.x = (float)(soak_cos(a) * sp); p->input.y = 0.0f; p->input.z = (float)(soak_sin(a) * sp);
        }
        p->input.y = 0.0f;
        f->input = p->input;
        f->dt = p->base_dt;
        if (soak_rng_chance(r, 0.015)) { f->ops |= SOAK_OP_JUMP; f->jump = (float)soak_rng_range(r, 2, 10); }
        (void)lvl; (void)s; (void)owner;
        return;
    }

    double u = soak_rng_unit(r);
    if (u < 0.80) f->dt = p->base_dt;
    else if (u < 0.995) f->dt = (float)soak_rng_range(r, 1.0 / 240, 1.0 / 5);
    else {
        static const float bad[] = {0.0f, -1.0f / 60, NAN, INFINITY, 1e-9f, 0.5f};
        f->dt = bad[soak_rng_below(r, 6)];
    }

    if (soak_rng_chance(r, 0.015)) {
        f->ops |= SOAK_OP_JUMP;
        f->jump = soak_rng_chance(r, 0.95) ? (float)soak_rng_range(r, 2, 16) : (float)soak_rng_range(r, 30, 200);
    }
    if (soak_rng_chance(r, 0.003)) {
        f->ops |= SOAK_OP_TELEPORT;
        f->tele = teleport_target(r, lvl, s);
        f->tele_reset = soak_rng_chance(r, 0.5) ? 1 : 0;
    }
    if (soak_rng_chance(r, 0.002) && center_clear_of_room(s, (f->ops & SOAK_OP_TELEPORT) ? f->tele : owner)) {
        f->ops |= SOAK_OP_UP;
        double v = soak_rng_unit(r);
        if (v < 0.4) { f->up.x = 0; f->up.y = 1; f->up.z = 0; }
        else if (v < 0.6) { /* a small tilt of +Y, scaled (set_up normalizes) */
            f->up.x = (float)soak_rng_range(r, -0.3, 0.3); f->up.y = (float)soak_rng_range(r, 0.5, 3);
            f->up.z = (float)soak_rng_range(r, -0.3, 0.3);
        } else if (v < 0.9) {
            for (int k = 0; k < 3; k++) f->up.v[k] = (float)soak_rng_range(r, -1, 1);
        } else { /* zero or non-finite: must be ignored */
            f->up.x = soak_rng_chance(r, 0.5) ? 0.0f : NAN; f->up.y = 0; f->up.z = 0;
        }
    }
    if (soak_rng_chance(r, 0.003)) {
        f->ops |= SOAK_OP_VEL;
        for (int k = 0; k < 3; k++) f->vel.v[k] = (float)soak_rng_range(r, -15, 15);
        if (soak_rng_chance(r, 0.2)) {
            uint32_t k = soak_rng_below(r, 3);
            f->vel.v[k] = weird_value(r);
        }
    }
}

/* ------------------------------------------------------------------ simulation */
const char *soak_fail_name(int kind)
{
    static const char *names[SOAK_FAIL_COUNT] = {"none", "nonfinite", "penetration", "escape", "floor", "state",
                                                 "direction", "progress", "footing", "support", "velocity"};
    return (kind >= 0 && kind < SOAK_FAIL_COUNT) ? names[kind] : "unknown";
}

static int fail_kind_from_name(const char *n)
{
    for (int k = 0; k < SOAK_FAIL_COUNT; k++)
        if (strcmp(n, soak_fail_name(k)) == 0) return k;
    return -1;
}

/* SOAK_GATHER_CACHE=1: the caches' counters over the run, printed to stderr at exit. */
static unsigned long long g_gc_hits, g_gc_fills, g_gc_overflows, g_gc_steps;
static void gather_cache_report(void)
{
    fprintf(stderr, "gather cache: %llu hits, %llu refills, %llu overflows\n", g_gc_hits, g_gc_fills, g_gc_overflows);
}

void soak_sim_begin(soak_sim_t *sim, soak_level_t *lvl, const char_body_settings_t *s, fm_vec3_t start)
{
    if (sim->body.gather_cache == &sim->gather_cache) {
        if (g_gc_steps++ == 0) atexit(gather_cache_report);
        g_gc_hits += sim->gather_cache.hits;
        g_gc_fills += sim->gather_cache.fills;
        g_gc_overflows += sim->gather_cache.overflows;
    }
    memset(sim, 0, sizeof *sim);
    sim->lvl = lvl;
    soak_level_animate(lvl, 0.0);
    sim->owner = start;
    char_body_init(&sim->body, &sim->owner);
    char_body_configure(&sim->body, s);
    char_body_teleport(&sim->body, start, true);
    const char *gc = getenv("SOAK_GATHER_CACHE"); /* the bodies' gather cache (perf14: answers bit for bit) */
    if (gc && gc[0] == '1') char_body_set_gather_cache(&sim->body, &sim->gather_cache);
    sim->excused = true; /* the start point may be inside geometry */
    sim->checks = SOAK_CHECKS_CURRENT;
    sim->oracles = SOAK_ORACLES_ALL;
}

static bool vfinite(fm_vec3_t v) { return isfinite(v.x) && isfinite(v.y) && isfinite(v.z); }

/* A moving platform or moving collider body close to (or carrying) the capsule. */
static bool mover_near(const soak_sim_t *sim, const soak_capsule_t *cap)
{
    const soak_level_t *l = sim->lvl;
    const char_body_settings_t *s = &sim->body.settings;
    double mid[3], half = 0;
    for (int k = 0; k < 3; k++) {
        mid[k] = (cap->a[k] + cap->b[k]) * 0.5;
        half += (cap->b[k] - cap->a[k]) * (cap->b[k] - cap->a[k]);
    }
    half = sqrt(half) * 0.5 + cap->r + 0.5; /* 0.5 m margin */
    for (uint32_t i = 0; i < l->npieces; i++) {
        const soak_piece_t *p = &l->pieces[i];
        if (!p->moving) continue;
        if (sim->body.floor_instance == &p->inst) return true;
        double sc = fabs(p->inst.xf.scale.x), d = 0;
        for (int k = 0; k < 3; k++) d += (mid[k] - p->inst.xf.pos.v[k]) * (mid[k] - p->inst.xf.pos.v[k]);
        if (sqrt(d) < half + p->bound_radius * sc) return true;
    }
    if (s->coll_types & COLL_TYPE_BODY)
        for (uint32_t i = 0; i < l->nbodies; i++) {
            const soak_lbody_t *b = &l->bodies[i];
            if (!b->moving) continue;
            double rad = sqrt((double)b->body.half_extents.x * b->body.half_extents.x +
                              (double)b->body.half_extents.y * b->body.half_extents.y +
                              (double)b->body.half_extents.z * b->body.half_extents.z) + b->body.half_extents.y;
            double d = 0;
            for (int k = 0; k < 3; k++) d += (mid[k] - b->body.xf.pos.v[k]) * (mid[k] - b->body.xf.pos.v[k]);
            if (sqrt(d) < half + rad) return true;
        }
    return false;
}

#define FAIL(kind, ...) do { snprintf(sim->msg, sizeof sim->msg, __VA_ARGS__); sim->last_fail = (kind); \
        sim->st.hard[(kind)]++; return (kind); } while (0)

int soak_sim_step(soak_sim_t *sim, const soak_frame_t *f, bool check)
{
    char_body_t *b = &sim->body;
    bool excuse = false;
    sim->last_fail = SOAK_FAIL_NONE;
    sim->msg[0] = 0;

    if (f->ops & SOAK_OP_UP) { char_body_set_up(b, f->up); excuse = true; sim->last_up = sim->frame + 1; }
    if (f->ops & SOAK_OP_TELEPORT) { char_body_teleport(b, f->tele, f->tele_reset != 0); excuse = true; sim->last_teleport = sim->frame + 1; }
    if (f->ops & SOAK_OP_VEL) char_body_set_velocity(b, f->vel);
    if (f->ops & SOAK_OP_JUMP) {
        fm_vec3_t v = char_body_get_velocity(b), up = char_body_get_settings(b)->up, j;
        fm_vec3_scale(&j, &up, f->jump);
        fm_vec3_add(&v, &v, &j);
        char_body_set_velocity(b, v);
    }
    b->input_velocity = f->input;
    if (isfinite(f->dt) && f->dt > 0.0f) sim->time += (double)f->dt;
    soak_level_animate(sim->lvl, sim->time);

    soak_capsule_t full, sweep;
    const char_body_settings_t *s = char_body_get_settings(b);
    soak_motion_t m;
    memset(&m, 0, sizeof m);
    if (check) {
        soak_body_capsules(b, &full, &sweep);
        if (mover_near(sim, &sweep)) { excuse = true; sim->last_mover = sim->frame + 1; }
        sim->pen_before = soak_check_static_pen(sim->lvl, s, &sweep, NULL, NULL);
        sim->pos_before = sim->owner;
        sim->vel_before = char_body_get_velocity(b);
        m.pos0 = sim->owner;
        m.input = f->input;
        m.dt = f->dt;
        m.grounded0 = char_body_is_on_floor(b);
        m.steep0 = char_body_is_on_steep_surface(b);
        m.pen0 = sim->excused || sim->pen_before > SOAK_PEN_TOL;
        /* the push-out's size: what the recover pushes out of, within the allowance too */
        m.pen_depth = soak_check_pushout_depth(sim->lvl, s, &sweep);
        if (m.pen_depth < sim->pen_before) m.pen_depth = sim->pen_before;
        m.launched = sim->vel_before.x * s->up.x + sim->vel_before.y * s->up.y + sim->vel_before.z * s->up.z > 1e-6f;
    }

    char_body_move_and_slide_in(b, &sim->lvl->scene, f->dt);
    sim->frame++;
    sim->st.frames++;
    if (!check || sim->escaped) return SOAK_FAIL_NONE;
    bool stepped = isfinite(f->dt) && f->dt > 0.0f;
    int k = soak_sim_check(sim, excuse, stepped);
    if (k != SOAK_FAIL_NONE || !stepped || sim->escaped || sim->checks < SOAK_CHECKS_CURRENT) return k;
    m.pos1 = sim->owner;
    m.vel1 = char_body_get_velocity(b);
    m.excuse = excuse;
    return soak_sim_check_motion(sim, &m);
}

static double dlen3(const double a[3]) { return sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]); }

/* The sweep capsule's centre at owner is inside a closed solid: with no face within its
 * radius (the state checks passed) the capsule is wholly in it. */
static bool sweep_inside(const soak_sim_t *sim, const char_body_settings_t *s, fm_vec3_t owner)
{
    soak_capsule_t full, sweep;
    soak_capsules_at(s, owner, &full, &sweep);
    double mid[3];
    for (int k = 0; k < 3; k++) mid[k] = (sweep.a[k] + sweep.b[k]) * 0.5;
    return soak_check_inside_closed(sim->lvl, s, mid);
}

/* Wholly inside a closed solid before or after the step (the game teleported the body into
 * a staircase's block, soak s4 l325, or a ramp, s9 l185): the body is in geometry, and no
 * oracle gives a verdict on the step (the inside faces of overlapping blocks are no floors a
 * player stands on). Asked only where an oracle would fail the step (the test runs over
 * every closed triangle: on every step it made the soak 1.5 times slower). */
static bool step_inside(soak_sim_t *sim, const char_body_settings_t *s, const soak_motion_t *m)
{
    bool in = sweep_inside(sim, s, m->pos1) || sweep_inside(sim, s, m->pos0);
    if (in) sim->st.inside_frames++;
    return in;
}
#define OFAIL(kind, ...) do { if (!step_inside(sim, s, m)) FAIL(kind, __VA_ARGS__); } while (0)

int soak_sim_check_motion(soak_sim_t *sim, const soak_motion_t *m)
{
    char_body_t *b = &sim->body;
    const char_body_settings_t *s = char_body_get_settings(b);
    sim->last_fail = SOAK_FAIL_NONE;
    sim->msg[0] = 0;
    if (sim->checks < SOAK_CHECKS_CURRENT || !(m->dt > 0.0f) || !isfinite(m->dt)) return SOAK_FAIL_NONE;
    double dt = m->dt < SOAK_BODY_MAX_DT ? m->dt : SOAK_BODY_MAX_DT;
    double up[3] = {s->up.x, s->up.y, s->up.z}, d[3], dh[3], in[3], inh[3];
    for (int k = 0; k < 3; k++) { d[k] = (double)m->pos1.v[k] - m->pos0.v[k]; in[k] = m->input.v[k]; }
    double dup = d[0] * up[0] + d[1] * up[1] + d[2] * up[2];
    double iup = in[0] * up[0] + in[1] * up[1] + in[2] * up[2];
    for (int k = 0; k < 3; k++) { dh[k] = d[k] - up[k] * dup; inh[k] = in[k] - up[k] * iup; }
    bool grounded1 = char_body_is_on_floor(b);
    /* every excuse of the state checks, plus: started overlapping (the recover push-out
     * moves the body without velocity), or ended in an excused overlap (and OFAIL below:
     * a step that started or ended wholly inside a closed solid) */
    bool excused = m->excuse || m->pen0 || sim->excused;
    double inl = dlen3(inh);
    /* walking: on a walkable floor and not launched off it by the game this step (a jump) */
    bool walking = !excused && m->grounded0 && !m->steep0 && !m->launched && isfinite(inl) && inl > 1e-6;
    double along = 0;
    if (walking) along = (dh[0] * inh[0] + dh[1] * inh[1] + dh[2] * inh[2]) / inl;

    /* A start overlap under SOAK_PEN_TOL (not excused) is still pushed out by the body's
     * recover, which moves every contact deeper than CB_MIN_DEPTH (0.1 mm) to half a
     * skin clear of it: a position correction, not motion (as the excused deeper ones).
     * Its size is allowed on top: the depth plus half the skin (CB_SKIN, at most 1 % of
     * the radius), doubled for a push out of two contacts at once. */
    double push = 0;
    if (m->pen_depth > 1e-4) {
        double skin = 0.01 * (double)s->radius < 1e-3 ? 0.01 * (double)s->radius : 1e-3;
        push = 2.0 * (m->pen_depth + 0.5 * skin);
    }

#define ON(k) (sim->oracles & (1u << (k)))
    /* (a) direction; the push-out is no walk against the input (soak s7 l411: a slide
     * into the room wall under a 27.8 m/s input ended 0.66 mm inside it, under the
     * checker's 1 mm, and the next step's recover pushed it 1.16 mm back out; s9 l208 the
     * same in a corner) */
    if (walking && ON(SOAK_FAIL_DIRECTION)) {
        sim->st.oracle_frames[SOAK_FAIL_DIRECTION]++;
        if (along < -(SOAK_DIR_TOL + push))
            OFAIL(SOAK_FAIL_DIRECTION, "walking: moved %.2f mm against the input (%.3f %.3f %.3f m/s), from (%.4f %.4f %.4f)",
                 -along * 1000.0, in[0], in[1], in[2], (double)m->pos0.x, (double)m->pos0.y, (double)m->pos0.z);
    }
    /* (b) progress */
    if (walking && ON(SOAK_FAIL_PROGRESS)) {
        double sp = inl < SOAK_BODY_MAX_SPEED ? inl : SOAK_BODY_MAX_SPEED, want = sp * dt;
        fm_vec3_t D;
        for (int k = 0; k < 3; k++) D.v[k] = (float)(inh[k] / inl * want);
        if (want >= 1e-3 && soak_check_free_flat(sim->lvl, s, m->pos0, D)) {
            sim->st.oracle_frames[SOAK_FAIL_PROGRESS]++;
            if (along < SOAK_PROGRESS_MIN * want)
                OFAIL(SOAK_FAIL_PROGRESS, "walking on free flat floor: covered %.2f of %.2f mm (%.0f %%), from (%.4f %.4f %.4f)%s",
                     along * 1000.0, want * 1000.0, 100.0 * along / want, (double)m->pos0.x, (double)m->pos0.y,
                     (double)m->pos0.z, inl > 1.8e19 ? " (huge input: its square overflows a float)" : "");
        }
    }
    /* (c) footing */
    if (!excused && grounded1 && ON(SOAK_FAIL_FOOTING)) {
        sim->st.oracle_frames[SOAK_FAIL_FOOTING]++;
        double ex = soak_check_footing_rounded(sim->lvl, s, m->pos1, char_body_is_on_steep_surface(b));
        if (ex > SOAK_FOOT_TOL)
            OFAIL(SOAK_FAIL_FOOTING, "grounded with the foot %.2f mm below the walkable surface under it, pos (%.4f %.4f %.4f)",
                 ex * 1000.0, (double)m->pos1.x, (double)m->pos1.y, (double)m->pos1.z);
    }
    /* (e) velocity = displacement / dt: across up always, along up when airborne before
     *     and after (a grounded body's along-up velocity is zeroed while the probe's snap
     *     and stair lift move it) */
    if (!excused && ON(SOAK_FAIL_VELOCITY)) {
        double v[3] = {m->vel1.x, m->vel1.y, m->vel1.z}, e[3];
        for (int k = 0; k < 3; k++) e[k] = d[k] / dt - v[k];
        double eup = e[0] * up[0] + e[1] * up[1] + e[2] * up[2], eh[3];
        for (int k = 0; k < 3; k++) eh[k] = e[k] - up[k] * eup;
        double sp = dlen3(v), real = dlen3(d) / dt;
        /* the recover's push-out of a start overlap under SOAK_PEN_TOL is allowed on top
         * (push, above) */
        double tol = (SOAK_VEL_TOL_POS + push) / dt;
        if (SOAK_VEL_TOL_REL * (sp > real ? sp : real) > tol) tol = SOAK_VEL_TOL_REL * (sp > real ? sp : real);
        sim->st.oracle_frames[SOAK_FAIL_VELOCITY]++;
        /* a tag for sorting the failures: [moved while still] the body moved but reports
         * no velocity there (a push); [still while moving] the reverse (blocked, or a
         * contact took the motion); [other] a different velocity (a mid-step slide) */
        double vu = v[0] * up[0] + v[1] * up[1] + v[2] * up[2], vh[3], rh[3];
        for (int k = 0; k < 3; k++) { vh[k] = v[k] - up[k] * vu; rh[k] = d[k] / dt - up[k] * (dup / dt); }
        if (dlen3(eh) > tol)
            OFAIL(SOAK_FAIL_VELOCITY, "across up %s: velocity (%.3f %.3f %.3f) but moved %.3f m/s off it (displacement/dt %.3f %.3f %.3f, tol %.3f)",
                 dlen3(vh) <= tol ? "[moved while still]" : dlen3(rh) <= tol ? "[still while moving]" : "[other]",
                 v[0], v[1], v[2], dlen3(eh), d[0] / dt, d[1] / dt, d[2] / dt, tol);
        if (!m->grounded0 && !grounded1 && fabs(eup) > tol)
            OFAIL(SOAK_FAIL_VELOCITY, "airborne, along up %s: velocity %.3f m/s but displacement/dt %.3f m/s (tol %.3f)",
                 fabs(vu) <= tol ? "[moved while still]" : fabs(dup / dt) <= tol ? "[still while moving]" : "[other]", vu,
                 dup / dt, tol);
    }
    /* (d) support */
    if (!excused && dlen3(d) <= SOAK_REST_MOVE) sim->rest_frames++;
    else sim->rest_frames = 0;
    /* a step the game launched along up (a jump) leaves the floor on purpose, even when a
     * wall stopped the rise (one slide): no verdict on it */
    if (sim->rest_frames >= SOAK_REST_FRAMES && !grounded1 && !m->launched && ON(SOAK_FAIL_SUPPORT)) {
        sim->st.oracle_frames[SOAK_FAIL_SUPPORT]++;
        if (soak_check_touches_walkable(sim->lvl, s, m->pos1))
            OFAIL(SOAK_FAIL_SUPPORT, "at rest for %u frames touching walkable geometry, not grounded, pos (%.4f %.4f %.4f)",
                 (unsigned)sim->rest_frames, (double)m->pos1.x, (double)m->pos1.y, (double)m->pos1.z);
    }
    return SOAK_FAIL_NONE;
}

/* The game put the body (a teleport, an up change, a mover: an excused overlap) where no
 * state of it passes both the footing and the support oracles, and no walk leads to one:
 * its foot is below the walkable surface under it (grounded, the footing fails), its full
 * capsule rests on walkable geometry (airborne at rest, the support fails), and there is
 * no room to stand anywhere near (soak_check_room_to_stand). The recover pushed the sweep
 * capsule clear, but the body is still in the game's overlap: a body (r 0.57, h 2.31)
 * teleported into a triangle soup, pushed out into a pocket whose walkable slope crosses
 * its step zone under a soup face 0.3 m over its head; the nearest place to stand, 1.29 m
 * away, is behind the pocket's wall (soak s43 l368). Both oracles at once ask the impossible there; the excuse lasts while
 * the body stays so wedged (counted, and as "stuck" past SOAK_RECOVER_FRAMES). Where a
 * state passes (the ball resting on nothing: airborne, soak s13 l195; a place to stand
 * near: s27 l164) the oracles judge the body as before. */
static bool wedged_by_game(const soak_sim_t *sim, const char_body_settings_t *s, fm_vec3_t pos)
{
    return soak_check_footing(sim->lvl, s, pos) > SOAK_FOOT_TOL && soak_check_touches_walkable(sim->lvl, s, pos) &&
           !soak_check_room_to_stand(sim->lvl, s, pos);
}

int soak_sim_check(soak_sim_t *sim, bool excuse, bool stepped)
{
    char_body_t *b = &sim->body;
    const char_body_settings_t *s = char_body_get_settings(b);
    soak_capsule_t full, sweep;
    sim->last_fail = SOAK_FAIL_NONE;
    sim->msg[0] = 0;
    fm_vec3_t pos = sim->owner, vel = char_body_get_velocity(b);
    if (!vfinite(pos) || !vfinite(vel))
        FAIL(SOAK_FAIL_NONFINITE, "pos (%g %g %g) vel (%g %g %g)", (double)pos.x, (double)pos.y, (double)pos.z,
             (double)vel.x, (double)vel.y, (double)vel.z);

    soak_body_capsules(b, &full, &sweep);
    double c[3];
    for (int k = 0; k < 3; k++) c[k] = (full.a[k] + full.b[k]) * 0.5;
    if (sim->lvl->loaded) {
        /* a real level has no room around it: falling out of its bounds (through a hole
         * where only an invisible clip brush was) ends the checks of this body, reported */
        const double m = 5.0;
        for (int k = 0; k < 3; k++)
            if (c[k] < sim->lvl->lo[k] - m || c[k] > sim->lvl->hi[k] + m) {
                sim->st.left_level++;
                sim->escaped = true;
                return SOAK_FAIL_NONE;
            }
    }
    const double et = 0.01;
    if (!sim->lvl->loaded && (c[0] < -SOAK_ROOM_HALF - et || c[0] > SOAK_ROOM_HALF + et || c[1] < -et || c[1] > SOAK_ROOM_HEIGHT + et ||
        c[2] < -SOAK_ROOM_HALF - et || c[2] > SOAK_ROOM_HALF + et))
    {
        if (excuse || sim->excused) {
            /* pushed out of an overlap it was put into (teleport, up change, mover) through
             * the room: reported separately; the run is over for the checks */
            sim->st.excused_escapes++;
            sim->escaped = true;
            return SOAK_FAIL_NONE;
        }
        FAIL(SOAK_FAIL_ESCAPE, "capsule centre (%.4f %.4f %.4f) outside the room", c[0], c[1], c[2]);
    }

    int32_t tri = -1;
    double raw = 0;
    double pen = soak_check_static_pen(sim->lvl, s, &sweep, &tri, &raw);
    sim->last_pen = pen;
    sim->last_raw = raw;
    sim->last_tri = tri;
    if (pen > SOAK_PEN_TOL) {
        if (excuse || sim->excused) {
            sim->excused = true;
            sim->st.soft_pen_frames++;
            if (pen > sim->st.max_soft_pen) sim->st.max_soft_pen = pen;
            if (++sim->excused_frames == SOAK_RECOVER_FRAMES) sim->st.stuck_events++;
        } else {
            if (pen > sim->st.max_hard_pen) sim->st.max_hard_pen = pen;
            FAIL(SOAK_FAIL_PENETRATION, "sweep capsule %.2f mm into static tri %d (%.2f mm past the slope allowance), pos (%.4f %.4f %.4f)",
                 raw * 1000.0, (int)tri, pen * 1000.0, (double)pos.x, (double)pos.y, (double)pos.z);
        }
    } else if ((excuse || sim->excused) &&
               (wedged_by_game(sim, s, pos) || soak_check_body_pen(sim->lvl, s, &sweep) > SOAK_PEN_TOL)) {
        /* still in the overlap the game made, though the sweep capsule is clear of the
         * triangles: wedged, or in a static collider body. A teleport (its step's dt < 0: no
         * motion) left the body 66 mm inside a static sphere; the next step's recover pushed
         * it out, a position correction the velocity oracle, no longer excused, read as
         * 1.2 m/s of motion (soak s101 l266). */
        sim->st.wedged_frames++;
        if (++sim->excused_frames == SOAK_RECOVER_FRAMES) sim->st.stuck_events++;
        sim->excused = true;
    } else {
        sim->excused = false;
        sim->excused_frames = 0;
    }

    if (!sim->excused) {
        double bp = soak_check_body_pen(sim->lvl, s, &sweep);
        if (bp > 0.01) {
            sim->st.body_pen_frames++;
            if (bp > sim->st.max_body_pen) sim->st.max_body_pen = bp;
        }
    }

    /* A skipped step (dt <= 0 or not finite) leaves the floor state of the last step. */
    if (!stepped) return SOAK_FAIL_NONE;
    bool on = char_body_is_on_floor(b), steep = char_body_is_on_steep_surface(b);
    if (steep && !on) FAIL(SOAK_FAIL_STATE, "on steep surface but not on floor");
    if (on) {
        sim->st.on_floor_frames++;
        if (steep) sim->st.steep_frames++;
        /* The probe's reach: the sweep capsule's bottom ball (step_height above the full
         * one: treads in the step zone are found by the probe) swept down to
         * floor_snap_distance below the foot. A ray along the axis and a sphere cast both
         * stay inside it. */
        soak_capsule_t reach = sweep;
        for (int k = 0; k < 3; k++) reach.b[k] = full.a[k] - (double)s->up.v[k] * (double)s->floor_snap_distance;
        double near = soak_check_nearest(sim->lvl, s, &reach);
        if (near > SOAK_FLOOR_TOL)
            FAIL(SOAK_FAIL_FLOOR, "is_on_floor but no seen surface within snap reach below the foot (%.4f m beyond; snap %.4f)",
                 near, (double)s->floor_snap_distance);
        fm_vec3_t n = char_body_floor_normal(b);
        float nl = fm_vec3_len(&n);
        if (!(nl > 0.99f && nl < 1.01f)) FAIL(SOAK_FAIL_STATE, "on floor with floor normal length %g", (double)nl);
        if (char_body_floor_id(b) < 0) FAIL(SOAK_FAIL_STATE, "on floor with floor id -1");
    } else if (char_body_floor_id(b) != -1) {
        FAIL(SOAK_FAIL_STATE, "not on floor but floor id %d", (int)char_body_floor_id(b));
    }
    return SOAK_FAIL_NONE;
}

/* ------------------------------------------------------------------ replay files */
const char *soak_arch(void)
{
#if defined(__mips__)
#if defined(__MIPSEB__)
    return "mips";
#else
    return "mipsel";
#endif
#elif defined(__x86_64__)
    return "x86_64";
#elif defined(__i386__)
    return "i386";
#elif defined(__aarch64__)
    return "aarch64";
#else
    return "other";
#endif
}

#define SOAK_STR2(x) #x
#define SOAK_STR(x) SOAK_STR2(x)
const char *soak_lib_version(void)
{
#ifdef SOAK_LIB_FP
    return SOAK_STR(SOAK_LIB_FP);
#else
    return "unknown";
#endif
}

static void wv(FILE *f, fm_vec3_t v) { fprintf(f, " %a %a %a", (double)v.x, (double)v.y, (double)v.z); }

int soak_replay_write(const char *path, const soak_replay_t *rp)
{
    FILE *f = fopen(path, "w");
    if (!f) return -1;
    const char_body_settings_t *s = &rp->settings;
    fprintf(f, "# charbody64 soak replay: regenerate level from seed, replay frames, check properties\n");
    fprintf(f, "soak-replay 1\n");
    if (rp->note[0]) fprintf(f, "note %s\n", rp->note);
    fprintf(f, "level 0x%016llx\n", (unsigned long long)rp->level_seed);
    if (rp->level_file[0]) fprintf(f, "levelfile %s\n", rp->level_file);
    if (rp->gen > 1) fprintf(f, "gen %d\n", rp->gen);
    if (rp->checks > 1) fprintf(f, "checks %d\n", rp->checks);
    if (rp->checks > 1 && rp->oracles && rp->oracles != SOAK_ORACLES_ALL) fprintf(f, "oracles 0x%x\n", (unsigned)rp->oracles);
    fprintf(f, "settings %a %a %a %a %a %a %a %u %u %u %u\n", (double)s->radius, (double)s->height,
            (double)s->step_height, (double)s->floor_snap_distance, (double)s->floor_max_angle, (double)s->gravity,
            (double)s->max_fall_speed, (unsigned)s->max_slides, (unsigned)s->coll_types, (unsigned)s->read_mask,
            (unsigned)s->follow_floor);
    fprintf(f, "up"); wv(f, s->up); fprintf(f, "\n");
    fprintf(f, "offset"); wv(f, s->center_offset); fprintf(f, "\n");
    fprintf(f, "start"); wv(f, rp->start); fprintf(f, "\n");
    if (rp->t0 != 0.0) fprintf(f, "time %a\n", rp->t0);
    if (rp->has_vel0) { fprintf(f, "velocity"); wv(f, rp->vel0); fprintf(f, "\n"); }
    if (rp->start_clear) fprintf(f, "clear 1\n");
    if (rp->fail_kind > 0) fprintf(f, "fail %s %u\n", soak_fail_name(rp->fail_kind), (unsigned)rp->fail_frame);
    fprintf(f, "frames %u\n", (unsigned)rp->nframes);
    for (uint32_t i = 0; i < rp->nframes; i++) {
        const soak_frame_t *fr = &rp->frames[i];
        fprintf(f, "f %a", (double)fr->dt); wv(f, fr->input);
        if (fr->ops & SOAK_OP_JUMP) fprintf(f, " J %a", (double)fr->jump);
        if (fr->ops & SOAK_OP_TELEPORT) { fprintf(f, " T"); wv(f, fr->tele); fprintf(f, " %u", (unsigned)fr->tele_reset); }
        if (fr->ops & SOAK_OP_UP) { fprintf(f, " U"); wv(f, fr->up); }
        if (fr->ops & SOAK_OP_VEL) { fprintf(f, " V"); wv(f, fr->vel); }
        fprintf(f, "\n");
    }
    for (uint32_t i = 0; i < rp->nexpect; i++) {
        const soak_expect_t *e = &rp->expect[i];
        fprintf(f, "expect %s %s", e->arch, e->lib[0] ? e->lib : "unknown"); wv(f, e->pos); wv(f, e->vel); fprintf(f, " %d\n", e->on_floor);
    }
    int bad = ferror(f);
    return (fclose(f) != 0 || bad) ? -1 : 0;
}

/* token reader over one line */
typedef struct { char *p; int ok; } tok_t;
static char *next_tok(tok_t *t)
{
    while (*t->p == ' ' || *t->p == '\t') t->p++;
    if (!*t->p || *t->p == '\n' || *t->p == '\r') { t->ok = 0; return NULL; }
    char *s = t->p;
    while (*t->p && *t->p != ' ' && *t->p != '\t' && *t->p != '\n' && *t->p != '\r') t->p++;
    if (*t->p) *t->p++ = 0;
    return s;
}
static float tok_f(tok_t *t)
{
    char *s = next_tok(t), *end;
    if (!s) return 0.0f;
    double d = strtod(s, &end);
    if (end == s) t->ok = 0;
    return (float)d;
}
static unsigned long tok_u(tok_t *t)
{
    char *s = next_tok(t), *end;
    if (!s) return 0;
    unsigned long v = strtoul(s, &end, 0);
    if (end == s) t->ok = 0;
    return v;
}
static fm_vec3_t tok_v(tok_t *t) { fm_vec3_t v; v.x = tok_f(t); v.y = tok_f(t); v.z = tok_f(t); return v; }

int soak_replay_read(const char *path, soak_replay_t *rp, int *err_line)
{
    FILE *f = fopen(path, "r");
    int line_no = 0;
    if (err_line) *err_line = 0;
    if (!f) return -1;
    soak_frame_t *frames = rp->frames;
    uint32_t cap = rp->cap;
    memset(rp, 0, sizeof *rp);
    rp->frames = frames;
    rp->cap = cap;
    rp->settings = CHAR_BODY_SETTINGS_DEFAULT;
    char line[1024];
    int have_magic = 0, rc = 0;
    while (fgets(line, sizeof line, f)) {
        line_no++;
        tok_t t = {line, 1};
        char *kw = next_tok(&t);
        if (!kw || kw[0] == '#') continue;
        t.ok = 1;
        if (strcmp(kw, "soak-replay") == 0) { have_magic = (tok_u(&t) == 1); }
        else if (strcmp(kw, "note") == 0) {
            while (*t.p == ' ') t.p++;
            snprintf(rp->note, sizeof rp->note, "%s", t.p);
            size_t n = strlen(rp->note);
            while (n && (rp->note[n - 1] == '\n' || rp->note[n - 1] == '\r')) rp->note[--n] = 0;
        } else if (strcmp(kw, "level") == 0) {
            char *s = next_tok(&t);
            if (s) rp->level_seed = (uint64_t)strtoull(s, NULL, 0); else t.ok = 0;
        } else if (strcmp(kw, "levelfile") == 0) {
            char *s = next_tok(&t);
            if (s && strlen(s) < sizeof rp->level_file) snprintf(rp->level_file, sizeof rp->level_file, "%s", s);
            else t.ok = 0;
        } else if (strcmp(kw, "gen") == 0) {
            rp->gen = (int)tok_u(&t);
            if (rp->gen < SOAK_GEN_V1 || rp->gen > SOAK_GEN_CURRENT) t.ok = 0;
        } else if (strcmp(kw, "oracles") == 0) {
            rp->oracles = (uint32_t)tok_u(&t);
        } else if (strcmp(kw, "checks") == 0) {
            rp->checks = (int)tok_u(&t);
            if (rp->checks < SOAK_CHECKS_V1 || rp->checks > SOAK_CHECKS_CURRENT) t.ok = 0;
        } else if (strcmp(kw, "settings") == 0) {
            char_body_settings_t *s = &rp->settings;
            s->radius = tok_f(&t); s->height = tok_f(&t); s->step_height = tok_f(&t);
            s->floor_snap_distance = tok_f(&t); s->floor_max_angle = tok_f(&t); s->gravity = tok_f(&t);
            s->max_fall_speed = tok_f(&t); s->max_slides = (uint8_t)tok_u(&t); s->coll_types = (uint8_t)tok_u(&t);
            s->read_mask = (uint8_t)tok_u(&t); s->follow_floor = tok_u(&t) != 0;
        } else if (strcmp(kw, "up") == 0) rp->settings.up = tok_v(&t);
        else if (strcmp(kw, "offset") == 0) rp->settings.center_offset = tok_v(&t);
        else if (strcmp(kw, "start") == 0) rp->start = tok_v(&t);
        else if (strcmp(kw, "time") == 0) {
            char *v = next_tok(&t), *end = NULL;
            rp->t0 = v ? strtod(v, &end) : 0.0;
            if (!v || end == v) t.ok = 0;
        } else if (strcmp(kw, "velocity") == 0) { rp->vel0 = tok_v(&t); rp->has_vel0 = true; }
        else if (strcmp(kw, "clear") == 0) rp->start_clear = tok_u(&t) != 0;
        else if (strcmp(kw, "fail") == 0) {
            char *n = next_tok(&t);
            rp->fail_kind = n ? fail_kind_from_name(n) : -1;
            rp->fail_frame = (uint32_t)tok_u(&t);
        } else if (strcmp(kw, "frames") == 0) {
            (void)tok_u(&t); /* informational; the f lines count */
        } else if (strcmp(kw, "f") == 0) {
            if (rp->nframes >= rp->cap) { rc = -3; break; }
            soak_frame_t *fr = &rp->frames[rp->nframes];
            memset(fr, 0, sizeof *fr);
            fr->dt = tok_f(&t);
            fr->input = tok_v(&t);
            char *op;
            while (t.ok && (op = next_tok(&t)) != NULL) {
                if (strcmp(op, "J") == 0) { fr->ops |= SOAK_OP_JUMP; fr->jump = tok_f(&t); }
                else if (strcmp(op, "T") == 0) { fr->ops |= SOAK_OP_TELEPORT; fr->tele = tok_v(&t); fr->tele_reset = (uint8_t)tok_u(&t); }
                else if (strcmp(op, "U") == 0) { fr->ops |= SOAK_OP_UP; fr->up = tok_v(&t); }
                else if (strcmp(op, "V") == 0) { fr->ops |= SOAK_OP_VEL; fr->vel = tok_v(&t); }
                else { t.ok = 0; break; }
            }
            t.ok = 1; /* end of line ends the op list */
            rp->nframes++;
        } else if (strcmp(kw, "expect") == 0) {
            if (rp->nexpect >= SOAK_MAX_EXPECT) { rc = -4; break; }
            soak_expect_t *e = &rp->expect[rp->nexpect++];
            char *a = next_tok(&t);
            snprintf(e->arch, sizeof e->arch, "%s", a ? a : "?");
            a = next_tok(&t);
            snprintf(e->lib, sizeof e->lib, "%s", a ? a : "?");
            e->pos = tok_v(&t); e->vel = tok_v(&t); e->on_floor = (int)tok_u(&t);
        } else {
            t.ok = 0;
        }
        if (!t.ok) { rc = -2; break; }
    }
    fclose(f);
    if (rc == 0 && !have_magic) rc = -5;
    if (rp->gen == 0) rp->gen = SOAK_GEN_V1;          /* files from before the field */
    if (rp->checks == 0) rp->checks = SOAK_CHECKS_V1;
    if (rc != 0 && err_line) *err_line = line_no;
    return rc;
}

const soak_expect_t *soak_replay_expect_for(const soak_replay_t *rp, const char *arch)
{
    for (uint32_t i = 0; i < rp->nexpect; i++)
        if (strcmp(rp->expect[i].arch, arch) == 0) return &rp->expect[i];
    return NULL;
}

int soak_replay_run(const soak_replay_t *rp, soak_level_t *lvl, soak_replay_result_t *res)
{
    return soak_replay_run_explain(rp, lvl, res, NULL);
}

int soak_replay_run_explain(const soak_replay_t *rp, soak_level_t *lvl, soak_replay_result_t *res, FILE *out)
{
    static soak_sim_t sim; /* large-ish; one replay at a time */
    memset(res, 0, sizeof *res);
    if (rp->level_file[0]) {
        /* a loaded level: keep it when it is already the one in lvl */
        char raw[sizeof rp->level_file + 8], err[256];
        size_t n = strlen(rp->level_file);
        if (n > 5 && strcmp(rp->level_file + n - 5, ".coll") == 0) n -= 5;
        snprintf(raw, sizeof raw, "%.*s.raw", (int)n, rp->level_file);
        if (!lvl->loaded || strcmp(lvl->file, rp->level_file) != 0) {
            if (soak_level_load(lvl, rp->level_file, raw, err, sizeof err) != 0) {
                if (out) fprintf(out, "  %s\n", err);
                return -1;
            }
        }
    } else if (soak_level_generate_v(lvl, rp->level_seed, rp->gen ? rp->gen : SOAK_GEN_V1) != 0) return -1;
    soak_sim_begin(&sim, lvl, &rp->settings, rp->start);
    sim.checks = rp->checks ? rp->checks : SOAK_CHECKS_V1;
    sim.oracles = rp->oracles ? rp->oracles : SOAK_ORACLES_ALL;
    if (rp->t0 != 0.0) { sim.time = rp->t0; soak_level_animate(lvl, rp->t0); }
    if (rp->has_vel0) char_body_set_velocity(&sim.body, rp->vel0);
    if (rp->start_clear) sim.excused = false;
    for (uint32_t i = 0; i < rp->nframes; i++) {
        int k = soak_sim_step(&sim, &rp->frames[i], true);
        if (k != SOAK_FAIL_NONE) {
            if (res->fails++ == 0) {
                res->first_fail_kind = k;
                res->first_fail_frame = i;
                snprintf(res->first_msg, sizeof res->first_msg, "%s", sim.msg);
                if (out) soak_sim_explain(&sim, out);
            }
        }
    }
    res->pos = sim.owner;
    res->vel = char_body_get_velocity(&sim.body);
    res->on_floor = char_body_is_on_floor(&sim.body) ? 1 : 0;
    res->st = sim.st;
    return 0;
}

void soak_sim_explain(const soak_sim_t *sim, FILE *out)
{
    const char_body_t *b = &sim->body;
    const char_body_settings_t *s = &b->settings;
    soak_capsule_t full, sweep;
    soak_body_capsules(b, &full, &sweep);
    fprintf(out, "  frame %u t %.4f: pos %.5f %.5f %.5f vel %.4f %.4f %.4f on_floor %d steep %d floor_id %d\n",
            (unsigned)sim->frame, sim->time, (double)sim->owner.x, (double)sim->owner.y, (double)sim->owner.z,
            (double)b->velocity.x, (double)b->velocity.y, (double)b->velocity.z, char_body_is_on_floor(b),
            char_body_is_on_steep_surface(b), (int)char_body_floor_id(b));
    fprintf(out, "  before the step: pos %.5f %.5f %.5f vel %.4f %.4f %.4f, penetration %.3f mm; input %.3f %.3f %.3f\n",
            (double)sim->pos_before.x, (double)sim->pos_before.y, (double)sim->pos_before.z, (double)sim->vel_before.x,
            (double)sim->vel_before.y, (double)sim->vel_before.z, sim->pen_before * 1000.0, (double)b->input_velocity.x,
            (double)b->input_velocity.y, (double)b->input_velocity.z);
    fprintf(out, "  excused %d for %u frames; last teleport frame %d, up change %d, mover near %d (-1: never)\n",
            sim->excused, (unsigned)sim->excused_frames, (int)sim->last_teleport - 1, (int)sim->last_up - 1,
            (int)sim->last_mover - 1);
    fprintf(out, "  settings: r %.4f h %.4f step %.4f snap %.4f angle %.1f deg slides %u types %u mask %u follow %d"
                 " up %.3f %.3f %.3f offset %.3f %.3f %.3f\n",
            (double)s->radius, (double)s->height, (double)s->step_height, (double)s->floor_snap_distance,
            (double)s->floor_max_angle * 57.29577951308232, (unsigned)s->max_slides, (unsigned)s->coll_types,
            (unsigned)s->read_mask, s->follow_floor, (double)s->up.x, (double)s->up.y, (double)s->up.z,
            (double)s->center_offset.x, (double)s->center_offset.y, (double)s->center_offset.z);
    fprintf(out, "  sweep capsule a %.5f %.5f %.5f b %.5f %.5f %.5f r %.4f\n", sweep.a[0], sweep.a[1], sweep.a[2],
            sweep.b[0], sweep.b[1], sweep.b[2], sweep.r);
    if (sim->last_tri >= 0) {
        const soak_wtri_t *w = &sim->lvl->wtris[sim->last_tri];
        fprintf(out, "  deepest static triangle %d (checker depth %.3f mm): (%.5f %.5f %.5f) (%.5f %.5f %.5f) (%.5f %.5f %.5f)\n",
                (int)sim->last_tri, sim->last_raw * 1000.0, w->v[0][0], w->v[0][1], w->v[0][2], w->v[1][0], w->v[1][1],
                w->v[1][2], w->v[2][0], w->v[2][1], w->v[2][2]);
    }
    if (sim->checks >= SOAK_CHECKS_CURRENT) {
        double ex = soak_check_footing_rounded(sim->lvl, s, sim->owner, char_body_is_on_steep_surface(b));
        fm_vec3_t foot = char_body_foot_pos(b);
        fprintf(out, "  footing: foot (%.5f %.5f %.5f) %.2f mm below the walkable surface under it", (double)foot.x,
                (double)foot.y, (double)foot.z, ex * 1000.0);
        if (soak_footing_tri >= 0) {
            const soak_wtri_t *w = &sim->lvl->wtris[soak_footing_tri];
            fprintf(out, " (triangle %d: (%.4f %.4f %.4f) (%.4f %.4f %.4f) (%.4f %.4f %.4f))", (int)soak_footing_tri,
                    w->v[0][0], w->v[0][1], w->v[0][2], w->v[1][0], w->v[1][1], w->v[1][2], w->v[2][0], w->v[2][1],
                    w->v[2][2]);
        }
        if (soak_footing_tri2 >= 0) {
            const soak_wtri_t *w = &sim->lvl->wtris[soak_footing_tri2];
            fprintf(out, " [crack: %d contacts around the foot, widest gap %.0f deg, deepest triangle %d: (%.4f %.4f %.4f) (%.4f %.4f %.4f) (%.4f %.4f %.4f)]",
                    soak_footing_ncontacts, soak_footing_widest * 57.29577951308232, (int)soak_footing_tri2, w->v[0][0], w->v[0][1], w->v[0][2], w->v[1][0], w->v[1][1], w->v[1][2],
                    w->v[2][0], w->v[2][1], w->v[2][2]);
        }
        fprintf(out, "; at rest %u frames, touches walkable geometry %d\n", (unsigned)sim->rest_frames,
                soak_check_touches_walkable(sim->lvl, s, sim->owner));
    }
    /* what the library itself says about the same capsule (diagnosis only) */
    fm_vec3_t c, up = s->up;
    for (int k = 0; k < 3; k++) c.v[k] = (float)((sweep.a[k] + sweep.b[k]) * 0.5);
    float ihh = (float)(b->inner_half_height - 0.5 * (double)s->step_height);
    if (ihh < 0.0f) ihh = 0.0f;
    coll_contact_t ct[4];
    uint32_t n = coll_capsule_overlaps(&sim->lvl->scene, c, up, s->radius, ihh, s->read_mask, s->coll_types, ct, 4);
    fprintf(out, "  library coll_capsule_overlaps on the sweep capsule: %u contact(s)", (unsigned)n);
    for (uint32_t i = 0; i < n && i < 4; i++)
        fprintf(out, "%s id %u tri %d depth %.3f mm n (%.3f %.3f %.3f)", i ? ";" : ":", (unsigned)ct[i].id,
                (int)ct[i].triangle, (double)ct[i].depth * 1000.0, (double)ct[i].normal.x, (double)ct[i].normal.y,
                (double)ct[i].normal.z);
    fprintf(out, "\n");
    fm_vec3_t fc, down;
    for (int k = 0; k < 3; k++) fc.v[k] = (float)((full.a[k] + full.b[k]) * 0.5);
    fm_vec3_scale(&down, &up, -1.0f);
    coll_ray_hit_t rh;
    float reach = 0.5f * s->height + s->floor_snap_distance;
    if (coll_raycast(&sim->lvl->scene, fc, down, reach + 5.0f, s->read_mask, s->coll_types, &rh))
        fprintf(out, "  library ray from the full centre along -up: hit id %u tri %d at %.4f m (foot at %.4f) n (%.3f %.3f %.3f)\n",
                (unsigned)rh.id, (int)rh.triangle, (double)rh.distance, 0.5 * (double)s->height, (double)rh.normal.x,
                (double)rh.normal.y, (double)rh.normal.z);
    else
        fprintf(out, "  library ray from the full centre along -up: no hit within %.3f m\n", (double)reach + 5.0);
    n = coll_capsule_overlaps(&sim->lvl->scene, fc, up, s->radius + s->floor_snap_distance + (float)SOAK_FLOOR_TOL,
                              b->inner_half_height, s->read_mask, s->coll_types, ct, 4);
    fprintf(out, "  library overlaps of the full capsule grown by snap+tol: %u; checker nearest %.4f m\n", (unsigned)n,
            soak_check_nearest(sim->lvl, s, &full));
}
