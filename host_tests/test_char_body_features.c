/* Character body features games expect beyond the seed: the floor's velocity kept on leaving
 * it, bodies that block each other through their own colliders, step events and the ground
 * state. Every step runs under the allocation guard (CB_STEP). */
#include "unity.h"
#include "alloc_guard.h"
#include "cb_levels.h"
#include <math.h>
#include <stdio.h>

#define TAU 6.2831853f

static char_body_t body;
static fm_vec3_t pos;

void setUp(void) { cb_world_reset(); }
void tearDown(void) {}

/* ---- 1. ground velocity and momentum on leaving ---- */

typedef enum { PLAT_STATIC, PLAT_TRANSLATE, PLAT_TURN, PLAT_LIFT } plat_kind_t;

static void place_platform(coll_mesh_instance_t *in, plat_kind_t kind, float t)
{
    in->xf.pos = cb_vec(0.0f, 0.0f, 0.0f);
    fm_quat_identity(&in->xf.rot);
    if (kind == PLAT_TRANSLATE) in->xf.pos.x = 4.0f * t;
    if (kind == PLAT_LIFT) in->xf.pos.y = 2.0f * t;
    if (kind == PLAT_TURN) {
        fm_vec3_t axis = cb_vec(0.0f, 1.0f, 0.0f);
        fm_quat_from_axis_angle(&in->xf.rot, &axis, TAU * t); /* 1 rev/s about +Y */
    }
}

/* Analytic velocity of the platform point p at time t. */
static fm_vec3_t platform_velocity(plat_kind_t kind, fm_vec3_t p)
{
    if (kind == PLAT_TRANSLATE) return cb_vec(4.0f, 0.0f, 0.0f);
    if (kind == PLAT_LIFT) return cb_vec(0.0f, 2.0f, 0.0f);
    if (kind == PLAT_TURN) return cb_vec(TAU * p.z, 0.0f, -TAU * p.x); /* (0, w, 0) x p */
    return cb_vec(0.0f, 0.0f, 0.0f);
}

#define JUMP_TRACK 40
/* Frames tracked after the jump: 0.3 s, before it comes down on the platform again. */
static int track_frames(float hz) { int n = (int)(0.3f * hz); return n < JUMP_TRACK ? n : JUMP_TRACK; }

/* Stands on the platform 2 m from its centre, jumps at 6 m/s; positions after the jump step
 * relative to the position at its end, and the platform's velocity at take-off. */
static void platform_jump(plat_kind_t kind, uint8_t leave, float hz, fm_vec3_t track[JUMP_TRACK], fm_vec3_t *v_take,
                          fm_vec3_t *gv_before)
{
    const float dt = 1.0f / hz;
    cb_world_reset();
    cb_geo_box(cb_vec(0.0f, -0.25f, 0.0f), cb_vec(40.0f, 0.25f, 40.0f), 0.0f); /* top at y = 0 */
    const coll_mesh_t *m = cb_geo_end();
    TEST_ASSERT_NOT_NULL(m);
    coll_transform_t xf = {cb_vec(0.0f, 0.0f, 0.0f), {{0.0f, 0.0f, 0.0f, 1.0f}}, cb_vec(1.0f, 1.0f, 1.0f)};
    coll_mesh_instance_t *in = cb_world_add_mesh(m, xf, 7);
    float t = 0.0f;
    place_platform(in, kind, t);
    cb_body_init(&body, &pos, cb_vec(2.0f, 0.0f, 0.0f));
    char_body_settings_t s = *char_body_get_settings(&body);
    s.leave_velocity = leave;
    char_body_configure(&body, &s);
    for (int i = 0; i < 30; i++) {
        t += dt;
        place_platform(in, kind, t);
        CB_STEP(&body, dt);
    }
    TEST_ASSERT_EQUAL_INT(CHAR_BODY_ON_FLOOR, char_body_ground_state(&body));
    *gv_before = char_body_ground_velocity(&body);
    /* jump */
    char_body_set_velocity(&body, cb_vec(0.0f, 6.0f, 0.0f));
    t += dt;
    place_platform(in, kind, t);
    CB_STEP(&body, dt);
    TEST_ASSERT_TRUE((char_body_events(&body)->flags & CHAR_BODY_EVENT_JUMPED) != 0);
    *v_take = platform_velocity(kind, char_body_foot_pos(&body));
    fm_vec3_t p0 = pos;
    for (int k = 0; k < track_frames(hz); k++) {
        t += dt;
        place_platform(in, kind, t);
        CB_STEP(&body, dt);
        if (leave == CHAR_BODY_LEAVE_ADD) { TEST_ASSERT_FALSE(char_body_is_on_floor(&body)); }
        track[k] = cb_vec(pos.x - p0.x, pos.y - p0.y, pos.z - p0.z);
    }
}

static void momentum_case(plat_kind_t kind, float hz, const char *name)
{
    fm_vec3_t ref[JUMP_TRACK], got[JUMP_TRACK], v_take, v_static, gv, gv_static;
    platform_jump(PLAT_STATIC, CHAR_BODY_LEAVE_ADD, hz, ref, &v_static, &gv_static);
    platform_jump(kind, CHAR_BODY_LEAVE_ADD, hz, got, &v_take, &gv);
    float worst = 0.0f;
    for (int k = 0; k < track_frames(hz); k++) {
        float tk = (float)(k + 1) / hz;
        fm_vec3_t want = cb_vec(ref[k].x + v_take.x * tk, ref[k].y + v_take.y * tk, ref[k].z + v_take.z * tk);
        float e = sqrtf((got[k].x - want.x) * (got[k].x - want.x) + (got[k].y - want.y) * (got[k].y - want.y) +
                        (got[k].z - want.z) * (got[k].z - want.z));
        if (e > worst) worst = e;
    }
    char label[96];
    snprintf(label, sizeof label, "jump off a %s platform at %.0f Hz: worst distance from the ballistic path", name,
             (double)hz);
    cb_report(label, worst, "m");
    TEST_ASSERT_TRUE(worst < 0.01f);
    float gl = sqrtf(gv.x * gv.x + gv.y * gv.y + gv.z * gv.z);
    TEST_ASSERT_TRUE(kind == PLAT_STATIC || gl > 1.0f);
}

static void test_jump_off_translating_platform(void)
{
    momentum_case(PLAT_TRANSLATE, 60.0f, "translating (4 m/s)");
    momentum_case(PLAT_TRANSLATE, 30.0f, "translating (4 m/s)");
}
static void test_jump_off_turning_platform(void)
{
    momentum_case(PLAT_TURN, 60.0f, "turning (1 rev/s)");
    momentum_case(PLAT_TURN, 120.0f, "turning (1 rev/s)");
}
static void test_jump_off_lift(void)
{
    momentum_case(PLAT_LIFT, 60.0f, "lifting (2 m/s)");
    momentum_case(PLAT_LIFT, 30.0f, "lifting (2 m/s)");
}

static void test_leave_velocity_settings(void)
{
    fm_vec3_t track[JUMP_TRACK], v, gv;
    platform_jump(PLAT_TRANSLATE, CHAR_BODY_LEAVE_DROP, 60.0f, track, &v, &gv);
    const int last = track_frames(60.0f) - 1;
    TEST_ASSERT_FLOAT_WITHIN(0.02f, 0.0f, track[last].x); /* dropped: no drift along x */
    platform_jump(PLAT_LIFT, CHAR_BODY_LEAVE_HORIZONTAL, 60.0f, track, &v, &gv);
    fm_vec3_t ref[JUMP_TRACK], vs, gs;
    platform_jump(PLAT_STATIC, CHAR_BODY_LEAVE_ADD, 60.0f, ref, &vs, &gs);
    /* the lift's rise dropped: the same jump as from static ground, until the lift catches up */
    TEST_ASSERT_FLOAT_WITHIN(0.002f, ref[8].y, track[8].y);
}

static void test_ground_velocity_zero_on_static_floor_and_in_air(void)
{
    cb_level_floor(20.0f);
    TEST_ASSERT_NOT_NULL(cb_world_add_geo(1));
    cb_body_init(&body, &pos, cb_vec(0.0f, 1.0f, 0.0f));
    CB_STEP(&body, 1.0f / 60.0f);
    fm_vec3_t g = char_body_ground_velocity(&body);
    TEST_ASSERT_EQUAL_FLOAT(0.0f, g.x + g.y + g.z);
    for (int i = 0; i < 60; i++) CB_STEP(&body, 1.0f / 60.0f);
    g = char_body_ground_velocity(&body);
    TEST_ASSERT_EQUAL_FLOAT(0.0f, fabsf(g.x) + fabsf(g.y) + fabsf(g.z));
}

/* A static floor is a static floor wherever the body stands on it: a body standing on an
 * instance that is turned (about up), far from the origin and from the instance's own origin,
 * stepped with a normal dt and with tiny ones, then jumping, reports no floor speed and keeps
 * none on the jump: the jump's velocity only. (Soak s61 l125: the carry anchor's
 * world-to-local-to-world round trip under such an instance left 1.02e-6 m at 14 m, which a
 * 1e-9 s step read as 1018 m/s of floor motion, reported as 200 m/s on a body that moved
 * 0.02 m/s.) The residue needs a local point about as far out as the world one (a small one
 * is lost in the final rounding), and it depends on the coordinates: 25 standing spots around
 * `at` on a floor of half size `half` placed at `o`. */
static float static_rotated_floor_worst(fm_vec3_t o, float yaw, fm_vec3_t at, float half, float last_dt, int *spots_over)
{
    const float steps_dt[] = {1.0f / 60.0f, 1e-9f, 1e-6f, 1e-9f, 1.0f / 30.0f, 1e-9f};
    float worst = 0.0f;
    *spots_over = 0;
    for (int sx = -3; sx <= 3; sx++) {
        for (int sz = -3; sz <= 3; sz++) {
            float worst_here = 0.0f;
            cb_world_reset();
            cb_geo_box(cb_vec(0.0f, at.y - o.y - 0.25f, 0.0f), cb_vec(half, 0.25f, half), 0.0f); /* top at y = at.y */
            const coll_mesh_t *m = cb_geo_end();
            TEST_ASSERT_NOT_NULL(m);
            coll_transform_t xf = COLL_TRANSFORM_IDENTITY;
            const fm_vec3_t yaxis = cb_vec(0.0f, 1.0f, 0.0f);
            fm_quat_from_axis_angle(&xf.rot, &yaxis, yaw);
            xf.pos = o;
            TEST_ASSERT_NOT_NULL(cb_world_add_mesh(m, xf, 7)); /* never moved */
            fm_vec3_t spot = cb_vec(0.731f * (float)sx, 0.0f, 0.677f * (float)sz);
            cb_body_init(&body, &pos, cb_vec(at.x + spot.x, at.y, at.z + spot.z));
            for (int i = 0; i < 10; i++) CB_STEP(&body, 1.0f / 60.0f);
            TEST_ASSERT_EQUAL_INT(CHAR_BODY_ON_FLOOR, char_body_ground_state(&body));
            TEST_ASSERT_EQUAL_INT32(7, char_body_floor_id(&body));
            /* standing, steps of every length: no floor speed, no speed */
            for (unsigned k = 0; k < sizeof steps_dt / sizeof steps_dt[0]; k++) {
                for (int i = 0; i < 3; i++) {
                    CB_STEP(&body, steps_dt[k]);
                    TEST_ASSERT_EQUAL_INT(CHAR_BODY_ON_FLOOR, char_body_ground_state(&body));
                    fm_vec3_t g = char_body_ground_velocity(&body), v = char_body_get_velocity(&body);
                    float e = fmaxf(sqrtf(g.x * g.x + g.y * g.y + g.z * g.z), sqrtf(v.x * v.x + v.y * v.y + v.z * v.z));
                    if (e > worst_here) worst_here = e;
                }
            }
            /* the last standing step, then the jump in a step of 0.05 s (s61 l125: 1e-9 s,
             * then the jump), then the air */
            CB_STEP(&body, last_dt);
            TEST_ASSERT_EQUAL_INT(CHAR_BODY_ON_FLOOR, char_body_ground_state(&body));
            char_body_set_velocity(&body, cb_vec(0.0f, 6.0f, 0.0f));
            CB_STEP(&body, 0.05f);
            TEST_ASSERT_TRUE((char_body_events(&body)->flags & CHAR_BODY_EVENT_JUMPED) != 0);
            /* along up: the jump's 6 m/s less one step of gravity */
            float g_step = char_body_get_settings(&body)->gravity * 0.05f;
            TEST_ASSERT_FLOAT_WITHIN(1e-3f, 6.0f - g_step, char_body_get_velocity(&body).y);
            for (int i = 0; i < 10; i++) {
                fm_vec3_t v = char_body_get_velocity(&body);
                float across = sqrtf(v.x * v.x + v.z * v.z);
                if (across > worst_here) worst_here = across;
                TEST_ASSERT_FALSE(char_body_is_on_floor(&body));
                CB_STEP(&body, 1.0f / 60.0f);
            }
            if (worst_here > 1e-3f) (*spots_over)++;
            if (worst_here > worst) worst = worst_here;
        }
    }
    return worst;
}

static void test_static_rotated_floor_far_away_has_no_speed(void)
{
    /* s61 l125's instance (pos, and its turn: quaternion y 0.4354, w -0.9002) and others */
    const struct { fm_vec3_t o; float yaw; fm_vec3_t at; float half; const char *name; } cases[] = {
        {{{-3.189f, 0.0f, 8.660f}}, 5.3822f, {{-0.8904f, 0.0785f, 13.9050f}}, 24.0f, "14 m (s61 l125's)"},
        {{{0.0f, 0.0f, 0.0f}}, 0.61f, {{10.0f, 0.37f, 10.0f}}, 24.0f, "14 m"},
        {{{0.0f, 1.7f, 0.0f}}, 2.3f, {{700.0f, 0.0f, -714.0f}}, 1100.0f, "1 km"},
        {{{0.0f, 0.0f, 0.0f}}, 0.61f, {{0.0f, 0.0f, 0.0f}}, 24.0f, "the origin"},
    };
    const float last_dts[] = {1e-9f, 1e-6f, 1.0f / 60.0f};
    float worst = 0.0f;
    for (unsigned i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        for (unsigned j = 0; j < sizeof last_dts / sizeof last_dts[0]; j++) {
            int over;
            float w = static_rotated_floor_worst(cases[i].o, cases[i].yaw, cases[i].at, cases[i].half, last_dts[j], &over);
            char label[144];
            snprintf(label, sizeof label, "static turned floor, body at %s, last step before the jump %g s: worst speed"
                     " standing or across the jump", cases[i].name, (double)last_dts[j]);
            cb_report(label, w, "m/s");
            snprintf(label, sizeof label, "static turned floor, body at %s, last step before the jump %g s: spots (of 49)"
                     " over 1 mm/s", cases[i].name, (double)last_dts[j]);
            cb_report(label, over, "");
            if (w > worst) worst = w;
        }
    }
    TEST_ASSERT_TRUE(worst < 1e-3f);
}

/* ---- 2. bodies that block each other ---- */

#define NB 32
static char_body_t bodies[NB];
static fm_vec3_t bpos[NB];
static coll_body_t colliders[NB];

static void add_body(int i, fm_vec3_t start, float radius)
{
    bpos[i] = start;
    char_body_init(&bodies[i], &bpos[i]);
    char_body_settings_t s = CHAR_BODY_SETTINGS_DEFAULT;
    s.radius = radius;
    s.height = 1.8f;
    s.center_offset = cb_vec(0.0f, 0.9f, 0.0f);
    s.coll_types = COLL_TYPE_ALL;
    char_body_configure(&bodies[i], &s);
    colliders[i] = (coll_body_t){0};
    colliders[i].write_mask = 0x01;
    colliders[i].id = (uint16_t)(100 + i);
    char_body_set_collider(&bodies[i], &colliders[i]);
    TEST_ASSERT_EQUAL_INT(COLL_OK, coll_scene_add_body(&cb_world.scene, &colliders[i]));
}

/* Overlap of two upright capsules (foot at p, height 1.8), m: > 0 when they interpenetrate. */
static float pair_overlap(int i, int j)
{
    const char_body_settings_t *a = char_body_get_settings(&bodies[i]), *b = char_body_get_settings(&bodies[j]);
    float dx = bpos[i].x - bpos[j].x, dz = bpos[i].z - bpos[j].z;
    float dy = bpos[i].y - bpos[j].y;
    float seg = 1.8f - 2.0f * a->radius; /* inner segment length (same height for all) */
    float vy = fabsf(dy) > seg ? fabsf(dy) - seg : 0.0f;
    float d = sqrtf(dx * dx + dz * dz + vy * vy);
    return a->radius + b->radius - d;
}

/* Overlap of body i's sweep capsule (the one that collides: the full capsule shortened from
 * the bottom by step_height) with body j's collider (its full capsule), m. The step zone
 * under a body is not collided by design (the seed's shortened capsule: the probe steps
 * onto what is there), so a body jumping past another's head may reach over it with its
 * step zone (13.9 mm in this test); the smaller of the two orders is the overlap neither
 * step zone explains. */
static float pair_sweep_overlap(int i, int j)
{
    const char_body_settings_t *a = char_body_get_settings(&bodies[i]), *b = char_body_get_settings(&bodies[j]);
    float dx = bpos[i].x - bpos[j].x, dz = bpos[i].z - bpos[j].z;
    float ilo = bpos[i].y + a->step_height + a->radius, ihi = bpos[i].y + 1.8f - a->radius;
    if (ilo > ihi) ilo = ihi;
    float jlo = bpos[j].y + b->radius, jhi = bpos[j].y + 1.8f - b->radius;
    float gy = ilo > jhi ? ilo - jhi : (jlo > ihi ? jlo - ihi : 0.0f);
    return a->radius + b->radius - sqrtf(dx * dx + dz * dz + gy * gy);
}

static void head_on(float speed, float hz, float offset_z, float *worst, float *passed_x)
{
    cb_world_reset();
    cb_level_floor(30.0f);
    TEST_ASSERT_NOT_NULL(cb_world_add_geo(1));
    add_body(0, cb_vec(-3.0f, 0.0f, 0.0f), 0.4f);
    add_body(1, cb_vec(3.0f, 0.0f, offset_z), 0.4f);
    const float dt = 1.0f / hz;
    for (int f = 0; f < (int)(2.0f * hz); f++) {
        bodies[0].input_velocity = cb_vec(speed, 0.0f, 0.0f);
        bodies[1].input_velocity = cb_vec(-speed, 0.0f, 0.0f);
        for (int i = 0; i < 2; i++) CB_STEP(&bodies[i], dt);
        float o = pair_overlap(0, 1);
        if (o > *worst) *worst = o;
        TEST_ASSERT_TRUE(cb_body_finite(&bodies[0]) && cb_body_finite(&bodies[1]));
    }
    *passed_x = bpos[0].x - bpos[1].x;
}

static void test_bodies_block_head_on(void)
{
    static const float speeds[3] = {1.0f, 3.0f, 10.0f};
    static const float rates[4] = {30.0f, 60.0f, 120.0f, 240.0f};
    float worst = 0.0f;
    for (int i = 0; i < 3; i++)
        for (int k = 0; k < 4; k++) {
            float passed;
            head_on(speeds[i], rates[k], 0.0f, &worst, &passed);
            TEST_ASSERT_TRUE(passed < 0.0f); /* still facing each other: nobody went through */
        }
    cb_report("two bodies head-on, 1-10 m/s, 30-240 Hz: deepest overlap", worst, "m");
    TEST_ASSERT_TRUE(worst <= 0.001f);
}

static void test_bodies_slide_past(void)
{
    float worst = 0.0f, passed;
    head_on(3.0f, 60.0f, 0.3f, &worst, &passed); /* offset by less than the sum of radii */
    cb_report("two bodies offset 0.3 m: deepest overlap", worst, "m");
    TEST_ASSERT_TRUE(worst <= 0.001f);
    TEST_ASSERT_TRUE(passed > 1.0f); /* slid past each other */
}

static uint32_t rng_state = 12345u;
static float frand(void)
{
    rng_state ^= rng_state << 13;
    rng_state ^= rng_state >> 17;
    rng_state ^= rng_state << 5;
    return (float)(rng_state & 0xFFFFFF) / 16777216.0f;
}

static void test_32_bodies_milling(void)
{
    cb_world_reset();
    cb_level_floor(12.0f);
    cb_geo_box(cb_vec(-8.5f, 1.5f, 0.0f), cb_vec(0.5f, 2.0f, 9.0f), 0.0f);
    cb_geo_box(cb_vec(8.5f, 1.5f, 0.0f), cb_vec(0.5f, 2.0f, 9.0f), 0.0f);
    cb_geo_box(cb_vec(0.0f, 1.5f, -8.5f), cb_vec(9.0f, 2.0f, 0.5f), 0.0f);
    cb_geo_box(cb_vec(0.0f, 1.5f, 8.5f), cb_vec(9.0f, 2.0f, 0.5f), 0.0f);
    cb_geo_box(cb_vec(0.0f, 0.25f, 0.0f), cb_vec(1.5f, 0.25f, 1.5f), 0.3f); /* a low block to climb */
    TEST_ASSERT_NOT_NULL(cb_world_add_geo(1));
    for (int i = 0; i < NB; i++)
        add_body(i, cb_vec(-6.0f + 1.6f * (float)(i % 8), 0.0f, -6.0f + 1.6f * (float)(i / 8) + (i / 8 >= 2 ? 4.0f : 0.0f)),
                 0.3f + 0.05f * (float)(i % 3));
    const float dt = 1.0f / 60.0f;
    float worst = 0.0f, worst_full = 0.0f;
    for (int f = 0; f < 10000; f++) {
        for (int i = 0; i < NB; i++) {
            if (f % 40 == i % 40) {
                float a = frand() * TAU, sp = 1.0f + 5.0f * frand();
                bodies[i].input_velocity = cb_vec(sp * cosf(a), 0.0f, sp * sinf(a));
                if (frand() < 0.2f && char_body_is_on_floor(&bodies[i])) char_body_set_velocity(&bodies[i], cb_vec(0.0f, 6.0f, 0.0f));
            }
            CB_STEP(&bodies[i], dt);
        }
        for (int i = 0; i < NB; i++) {
            TEST_ASSERT_TRUE(cb_body_finite(&bodies[i]));
            if (!(fabsf(bpos[i].x) < 8.0f && fabsf(bpos[i].z) < 8.0f && bpos[i].y > -0.01f))
                printf("body %d left the room at frame %d: %.3f %.3f %.3f\n", i, f, (double)bpos[i].x, (double)bpos[i].y,
                       (double)bpos[i].z);
            TEST_ASSERT_TRUE(fabsf(bpos[i].x) < 8.0f && fabsf(bpos[i].z) < 8.0f && bpos[i].y > -0.01f);
            for (int j = i + 1; j < NB; j++) {
                /* beyond either body's step zone: both sweep capsules' overlaps with the other */
                float oi = pair_sweep_overlap(i, j), oj = pair_sweep_overlap(j, i);
                float o = oi < oj ? oi : oj;
                if (o > worst) worst = o;
                if (pair_overlap(i, j) > worst_full) worst_full = pair_overlap(i, j);
            }
        }
    }
    cb_report("32 bodies milling 10000 frames: deepest overlap outside the step zones", worst, "m");
    cb_report("32 bodies milling 10000 frames: deepest full capsules overlap (step zone in the air)", worst_full, "m");
    TEST_ASSERT_TRUE(worst <= 0.001f);
}

/* ---- 4. step events and the ground state ---- */

static void test_events_landed_and_left(void)
{
    cb_geo_box(cb_vec(-10.0f, -0.5f, 0.0f), cb_vec(10.0f, 0.5f, 10.0f), 0.0f); /* ledge top y 0, edge x 0 */
    cb_geo_box(cb_vec(0.0f, -3.5f, 0.0f), cb_vec(30.0f, 0.5f, 30.0f), 0.0f);   /* ground y -3 */
    TEST_ASSERT_NOT_NULL(cb_world_add_geo(1));
    cb_body_init(&body, &pos, cb_vec(-2.0f, 1.25f, 0.0f));
    const float dt = 1.0f / 60.0f;
    int landed = 0;
    float speed = 0.0f;
    for (int i = 0; i < 60; i++) {
        CB_STEP(&body, dt);
        if (char_body_events(&body)->flags & CHAR_BODY_EVENT_LANDED) { landed++; speed = char_body_events(&body)->landing_speed; }
    }
    TEST_ASSERT_EQUAL_INT(1, landed);
    cb_report("landing speed after a 1.25 m fall (sqrt(2 g h) = 8.66)", speed, "m/s");
    TEST_ASSERT_FLOAT_WITHIN(0.6f, 8.66f, speed);
    TEST_ASSERT_EQUAL_INT(CHAR_BODY_ON_FLOOR, char_body_ground_state(&body));
    /* jump: left the floor, jumped */
    char_body_set_velocity(&body, cb_vec(0.0f, 5.0f, 0.0f));
    CB_STEP(&body, dt);
    uint8_t fl = char_body_events(&body)->flags;
    TEST_ASSERT_TRUE((fl & CHAR_BODY_EVENT_LEFT_FLOOR) && (fl & CHAR_BODY_EVENT_JUMPED));
    TEST_ASSERT_EQUAL_INT(CHAR_BODY_AIRBORNE, char_body_ground_state(&body));
    for (int i = 0; i < 60; i++) CB_STEP(&body, dt);
    /* walk off the ledge: left the floor, not a jump */
    body.input_velocity = cb_vec(3.0f, 0.0f, 0.0f);
    int left = 0, jumped = 0;
    for (int i = 0; i < 60; i++) {
        CB_STEP(&body, dt);
        fl = char_body_events(&body)->flags;
        if (fl & CHAR_BODY_EVENT_LEFT_FLOOR) left++;
        if (fl & CHAR_BODY_EVENT_JUMPED) jumped++;
    }
    TEST_ASSERT_EQUAL_INT(1, left);
    TEST_ASSERT_EQUAL_INT(0, jumped);
}

static void test_events_stepped(void)
{
    /* two risers of 0.2 m up on long treads, then back down */
    const float xs[6] = {-20.0f, 0.0f, 0.0f, 1.0f, 1.0f, 20.0f};
    const float ys[6] = {0.0f, 0.0f, 0.2f, 0.2f, 0.4f, 0.4f};
    cb_geo_profile(xs, ys, 6, -5.0f, 5.0f);
    TEST_ASSERT_NOT_NULL(cb_world_add_geo(1));
    cb_body_init(&body, &pos, cb_vec(-2.0f, 0.0f, 0.0f));
    const float dt = 1.0f / 60.0f;
    CB_STEP(&body, dt);
    body.input_velocity = cb_vec(3.0f, 0.0f, 0.0f);
    float up_sum = 0.0f, down_sum = 0.0f;
    int ups = 0, downs = 0;
    for (int i = 0; i < 90; i++) {
        CB_STEP(&body, dt);
        const char_body_events_t *e = char_body_events(&body);
        if (e->flags & CHAR_BODY_EVENT_STEPPED) { up_sum += e->step; ups++; }
    }
    body.input_velocity = cb_vec(-3.0f, 0.0f, 0.0f);
    for (int i = 0; i < 90; i++) {
        CB_STEP(&body, dt);
        const char_body_events_t *e = char_body_events(&body);
        if (e->flags & CHAR_BODY_EVENT_STEPPED) { down_sum += e->step; downs++; }
    }
    cb_report("stepped up: sum of step events (0.4 m of risers)", up_sum, "m");
    cb_report("stepped down: sum of step events", down_sum, "m");
    TEST_ASSERT_EQUAL_INT(2, ups);
    TEST_ASSERT_EQUAL_INT(2, downs);
    TEST_ASSERT_FLOAT_WITHIN(0.002f, 0.4f, up_sum);
    TEST_ASSERT_FLOAT_WITHIN(0.002f, -0.4f, down_sum);
}

static void test_events_no_steps_on_a_ramp(void)
{
    const float xs[4] = {-20.0f, 0.0f, 4.0f, 24.0f};
    const float ys[4] = {0.0f, 0.0f, 2.0f, 2.0f};
    cb_geo_profile(xs, ys, 4, -5.0f, 5.0f);
    TEST_ASSERT_NOT_NULL(cb_world_add_geo(1));
    cb_body_init(&body, &pos, cb_vec(-2.0f, 0.0f, 0.0f));
    body.input_velocity = cb_vec(4.0f, 0.0f, 0.0f);
    int steps = 0;
    for (int i = 0; i < 120; i++) {
        CB_STEP(&body, 1.0f / 60.0f);
        if (char_body_events(&body)->flags & CHAR_BODY_EVENT_STEPPED) steps++;
    }
    TEST_ASSERT_EQUAL_INT(0, steps);
    TEST_ASSERT_TRUE(pos.x > 5.0f);
}

static void test_events_ceiling_and_wall(void)
{
    cb_level_floor(20.0f);
    cb_geo_box(cb_vec(0.0f, 3.0f, 0.0f), cb_vec(20.0f, 0.5f, 20.0f), 0.0f); /* underside at 2.5 */
    cb_geo_box(cb_vec(3.5f, 1.0f, 0.0f), cb_vec(0.5f, 1.0f, 5.0f), 0.0f);  /* wall face at x = 3 */
    TEST_ASSERT_NOT_NULL(cb_world_add_geo(1));
    cb_body_init(&body, &pos, cb_vec(0.0f, 0.0f, 0.0f));
    const float dt = 1.0f / 60.0f;
    CB_STEP(&body, dt);
    char_body_set_velocity(&body, cb_vec(0.0f, 10.0f, 0.0f));
    int ceiling = 0;
    for (int i = 0; i < 30; i++) {
        CB_STEP(&body, dt);
        if (char_body_events(&body)->flags & CHAR_BODY_EVENT_HIT_CEILING) ceiling++;
    }
    TEST_ASSERT_TRUE(ceiling >= 1);
    body.input_velocity = cb_vec(3.0f, 0.0f, 1.0f);
    int wall = 0;
    fm_vec3_t n = cb_vec(0.0f, 0.0f, 0.0f);
    for (int i = 0; i < 90; i++) {
        CB_STEP(&body, dt);
        if (char_body_events(&body)->flags & CHAR_BODY_EVENT_HIT_WALL) { wall++; n = char_body_events(&body)->wall_normal; }
    }
    TEST_ASSERT_TRUE(wall >= 1);
    TEST_ASSERT_FLOAT_WITHIN(0.01f, -1.0f, n.x);
    TEST_ASSERT_FLOAT_WITHIN(0.01f, 0.0f, n.y);
    /* standing still on the floor: no events */
    body.input_velocity = cb_vec(0.0f, 0.0f, 0.0f);
    CB_STEP(&body, dt);
    CB_STEP(&body, dt);
    TEST_ASSERT_EQUAL_INT(0, char_body_events(&body)->flags);
}

/* ---- 3. one-way platforms ---- */

/* Floor at y = 0, a one-way slab with its top at y = 2 over x in [-3, 3]. */
static coll_mesh_instance_t *one_way_level(void)
{
    cb_level_floor(20.0f);
    TEST_ASSERT_NOT_NULL(cb_world_add_geo(1));
    cb_geo_box(cb_vec(0.0f, 1.9f, 0.0f), cb_vec(3.0f, 0.1f, 3.0f), 0.0f);
    coll_mesh_instance_t *in = cb_world_add_geo(2);
    TEST_ASSERT_NOT_NULL(in);
    in->flags = COLL_INSTANCE_ONE_WAY;
    return in;
}

static void jump_through(float hz, float x)
{
    cb_world_reset();
    one_way_level();
    const float dt = 1.0f / hz;
    cb_body_init(&body, &pos, cb_vec(x, 0.0f, 0.0f));
    CB_STEP(&body, dt);
    char_body_set_velocity(&body, cb_vec(0.0f, 12.0f, 0.0f)); /* apex 2.4 m */
    float max_y = 0.0f;
    for (int i = 0; i < (int)(2.0f * hz); i++) {
        CB_STEP(&body, dt);
        if (pos.y > max_y) max_y = pos.y;
    }
    /* rose freely through it (the discrete jump's apex is 2.2-2.4 m at 30-240 Hz), stands on it */
    TEST_ASSERT_TRUE(max_y > 2.15f);
    TEST_ASSERT_TRUE(char_body_is_on_floor(&body));
    TEST_ASSERT_FLOAT_WITHIN(0.001f, 2.0f, pos.y);
    TEST_ASSERT_EQUAL_INT(2, char_body_floor_id(&body));
}

static void test_one_way_jump_up_through(void)
{
    static const float rates[4] = {30.0f, 60.0f, 120.0f, 240.0f};
    for (int i = 0; i < 4; i++) {
        jump_through(rates[i], 0.0f);
        jump_through(rates[i], 2.8f);  /* under its edge: no snag on the way up */
    }
}

static void test_one_way_land_walk_and_drop(void)
{
    one_way_level();
    const float dt = 1.0f / 60.0f;
    cb_body_init(&body, &pos, cb_vec(0.0f, 4.0f, 0.0f));
    for (int i = 0; i < 90; i++) CB_STEP(&body, dt);
    TEST_ASSERT_TRUE(char_body_is_on_floor(&body));
    TEST_ASSERT_FLOAT_WITHIN(0.001f, 2.0f, pos.y);
    body.input_velocity = cb_vec(3.0f, 0.0f, 0.0f);
    for (int i = 0; i < 30; i++) {
        CB_STEP(&body, dt);
        TEST_ASSERT_TRUE(char_body_is_on_floor(&body));
        TEST_ASSERT_FLOAT_WITHIN(0.001f, 2.0f, pos.y);
    }
    TEST_ASSERT_TRUE(pos.x > 1.4f);
    body.input_velocity = cb_vec(0.0f, 0.0f, 0.0f);
    char_body_drop_through(&body);
    for (int i = 0; i < 90; i++) CB_STEP(&body, dt);
    TEST_ASSERT_TRUE(char_body_is_on_floor(&body));
    TEST_ASSERT_FLOAT_WITHIN(0.001f, 0.0f, pos.y);
    TEST_ASSERT_EQUAL_INT(1, char_body_floor_id(&body));
    /* and it is solid again from above: jump back up onto it */
    char_body_set_velocity(&body, cb_vec(0.0f, 12.0f, 0.0f));
    for (int i = 0; i < 120; i++) CB_STEP(&body, dt);
    TEST_ASSERT_FLOAT_WITHIN(0.001f, 2.0f, pos.y);
}

/* A jump that does not clear the top falls back down through it. */
static void test_one_way_short_jump_falls_back(void)
{
    one_way_level();
    const float dt = 1.0f / 60.0f;
    cb_body_init(&body, &pos, cb_vec(0.0f, 0.0f, 0.0f));
    CB_STEP(&body, dt);
    char_body_set_velocity(&body, cb_vec(0.0f, 9.0f, 0.0f)); /* apex 1.35 m: the top is at 2 */
    for (int i = 0; i < 120; i++) CB_STEP(&body, dt);
    TEST_ASSERT_TRUE(char_body_is_on_floor(&body));
    TEST_ASSERT_FLOAT_WITHIN(0.001f, 0.0f, pos.y);
}

/* ---- 4. the gather cache ---- */

/* A body with a gather cache moves exactly as one without: bit for bit, step after step, on
 * a level of a bumpy floor, stairs and boxes with a turning platform and a sliding one that
 * the test moves every frame, through walking in changing directions, jumps, a teleport,
 * a read_mask change and a platform taken out of the scene and put back. The two bodies
 * never see each other (meshes only). The cache is used (most steps come from it). */
static void test_gather_cache_moves_exactly_as_without(void)
{
    const float dt = 1.0f / 30.0f;
    cb_world_reset();
    cb_geo_begin();
    cb_geo_grid(12.0f, 48, 0.0f);
    cb_geo_stairs(0.35f, 0.15f, 8, -3.0f, -1.0f);
    cb_geo_box(cb_vec(-4.0f, 0.4f, 3.0f), cb_vec(0.6f, 0.4f, 0.6f), 0.3f);
    cb_geo_box(cb_vec(3.0f, 0.2f, -5.0f), cb_vec(1.0f, 0.2f, 0.5f), 0.0f);
    cb_world_add_geo(1);
    cb_geo_begin();
    cb_geo_box(cb_vec(0.0f, -0.1f, 0.0f), cb_vec(2.0f, 0.1f, 2.0f), 0.0f);
    const coll_mesh_t *pm = cb_geo_end();
    TEST_ASSERT_NOT_NULL(pm);
    coll_transform_t xf = {cb_vec(0.0f, 0.3f, 4.0f), {{0.0f, 0.0f, 0.0f, 1.0f}}, cb_vec(1.0f, 1.0f, 1.0f)};
    coll_mesh_instance_t *turn = cb_world_add_mesh(pm, xf, 2);
    xf.pos = cb_vec(4.0f, 0.3f, 0.0f);
    coll_mesh_instance_t *slide = cb_world_add_mesh(pm, xf, 3);
    static char_body_t a, b;
    static fm_vec3_t pa, pb;
    static coll_gather_cache_t cache;
    cb_body_init(&a, &pa, cb_vec(1.0f, 0.5f, 4.0f));
    cb_body_init(&b, &pb, cb_vec(1.0f, 0.5f, 4.0f));
    char_body_set_gather_cache(&a, &cache);
    fm_vec3_t axis = cb_vec(0.0f, 1.0f, 0.0f);
    for (int f = 0; f < 600; f++) {
        float t = (float)f * dt;
        fm_quat_from_axis_angle(&turn->xf.rot, &axis, 0.8f * t);
        slide->xf.pos.x = 4.0f + 2.0f * sinf(0.7f * t);
        float ang = 0.4f * t + (f / 90) * 1.3f;
        fm_vec3_t in = cb_vec(3.0f * cosf(ang), 0.0f, 3.0f * sinf(ang));
        if (f % 150 < 20) in = cb_vec(0.0f, 0.0f, 0.0f); /* standing (on a platform at first) */
        a.input_velocity = b.input_velocity = in;
        if (f % 97 == 50 && char_body_is_on_floor(&a)) {
            char_body_set_velocity(&a, cb_vec(0.0f, 6.0f, 0.0f));
            char_body_set_velocity(&b, cb_vec(0.0f, 6.0f, 0.0f));
        }
        if (f == 300) {
            char_body_teleport(&a, cb_vec(-2.0f, 1.0f, -2.0f), true);
            char_body_teleport(&b, cb_vec(-2.0f, 1.0f, -2.0f), true);
        }
        if (f == 360 || f == 420) { /* the sliding platform on layer 2 only, then the body reads it again */
            slide->write_mask = f == 360 ? 0x02 : 0x01;
        }
        if (f == 400) {
            char_body_settings_t s = *char_body_get_settings(&a);
            s.read_mask = 0x03;
            char_body_configure(&a, &s);
            char_body_configure(&b, &s);
        }
        if (f == 450) TEST_ASSERT_EQUAL_INT(COLL_OK, coll_scene_remove_mesh(&cb_world.scene, turn));
        if (f == 500) TEST_ASSERT_EQUAL_INT(COLL_OK, coll_scene_add_mesh(&cb_world.scene, turn));
        CB_STEP(&a, dt);
        CB_STEP(&b, dt);
        TEST_ASSERT_EQUAL_MEMORY(&pa, &pb, sizeof pa);
        TEST_ASSERT_EQUAL_MEMORY(&a.velocity, &b.velocity, sizeof a.velocity);
        TEST_ASSERT_EQUAL_MEMORY(&a.floor_normal, &b.floor_normal, sizeof a.floor_normal);
        TEST_ASSERT_EQUAL_MEMORY(&a.ground_velocity, &b.ground_velocity, sizeof a.ground_velocity);
        TEST_ASSERT_EQUAL_MEMORY(&a.events, &b.events, sizeof a.events);
        TEST_ASSERT_EQUAL_INT(a.flags, b.flags);
        TEST_ASSERT_EQUAL_INT(a.floor_id, b.floor_id);
        TEST_ASSERT_TRUE(a.floor_instance == b.floor_instance);
    }
    printf("gather cache over 600 steps: %u hits, %u refills, %u overflows\n", cache.hits, cache.fills,
           cache.overflows);
    TEST_ASSERT_TRUE(cache.hits > 300u);
    TEST_ASSERT_TRUE(cache.fills > 10u);
    /* detached: the uncached gather again (the cache is left as it was) */
    uint32_t hits = cache.hits, fills = cache.fills;
    char_body_set_gather_cache(&a, NULL);
    CB_STEP(&a, dt);
    CB_STEP(&b, dt);
    TEST_ASSERT_EQUAL_MEMORY(&pa, &pb, sizeof pa);
    TEST_ASSERT_EQUAL_UINT(hits, cache.hits);
    TEST_ASSERT_EQUAL_UINT(fills, cache.fills);
    /* attached again: emptied first */
    char_body_set_gather_cache(&a, &cache);
    TEST_ASSERT_EQUAL_UINT(0u, cache.hits + cache.fills);
    CB_STEP(&a, dt);
    CB_STEP(&b, dt);
    TEST_ASSERT_EQUAL_MEMORY(&pa, &pb, sizeof pa);
    TEST_ASSERT_EQUAL_UINT(1u, cache.fills);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_jump_off_translating_platform);
    RUN_TEST(test_jump_off_turning_platform);
    RUN_TEST(test_jump_off_lift);
    RUN_TEST(test_leave_velocity_settings);
    RUN_TEST(test_ground_velocity_zero_on_static_floor_and_in_air);
    RUN_TEST(test_static_rotated_floor_far_away_has_no_speed);
    RUN_TEST(test_bodies_block_head_on);
    RUN_TEST(test_bodies_slide_past);
    RUN_TEST(test_32_bodies_milling);
    RUN_TEST(test_one_way_jump_up_through);
    RUN_TEST(test_one_way_land_walk_and_drop);
    RUN_TEST(test_one_way_short_jump_falls_back);
    RUN_TEST(test_events_landed_and_left);
    RUN_TEST(test_events_stepped);
    RUN_TEST(test_events_no_steps_on_a_ramp);
    RUN_TEST(test_events_ceiling_and_wall);
    RUN_TEST(test_gather_cache_moves_exactly_as_without);
    return UNITY_END();
}
