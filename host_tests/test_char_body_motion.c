/* Character body on moving platforms, on a planet with a changing up vector, and 5 km from
 * the origin. Every step runs under the allocation guard (CB_STEP). */
#include "unity.h"
#include "alloc_guard.h"
#include "cb_levels.h"
#include <math.h>
#include <stdio.h>

#define DT (1.0f / 30.0f)
#define PI_F 3.14159265f

static char_body_t body;
static fm_vec3_t pos;

void setUp(void) { cb_world_reset(); }
void tearDown(void) {}

static fm_vec3_t cb_norm_test(fm_vec3_t a)
{
    float l = sqrtf(a.x * a.x + a.y * a.y + a.z * a.z);
    return cb_vec(a.x / l, a.y / l, a.z / l);
}

static float dist3(fm_vec3_t a, fm_vec3_t b)
{
    float dx = a.x - b.x, dy = a.y - b.y, dz = a.z - b.z;
    return sqrtf(dx * dx + dy * dy + dz * dz);
}

/* A 6 x 6 m platform, top at local y = 0, placed with its top at y = 1. */
static coll_mesh_instance_t *platform(void)
{
    cb_geo_box(cb_vec(0.0f, -0.25f, 0.0f), cb_vec(3.0f, 0.25f, 3.0f), 0.0f);
    const coll_mesh_t *m = cb_geo_end();
    TEST_ASSERT_NOT_NULL(m);
    coll_transform_t xf = COLL_TRANSFORM_IDENTITY;
    xf.pos = cb_vec(0.0f, 1.0f, 0.0f);
    coll_mesh_instance_t *in = cb_world_add_mesh(m, xf, 7);
    TEST_ASSERT_NOT_NULL(in);
    return in;
}

static void settle(void)
{
    for (int i = 0; i < 3; i++) CB_STEP(&body, DT);
    TEST_ASSERT_TRUE(char_body_is_on_floor(&body));
}

/* 10a. Translating 3 m/s. */
static void test_platform_translate(void)
{
    coll_mesh_instance_t *in = platform();
    cb_body_init(&body, &pos, cb_vec(0.0f, 1.0f, 0.0f));
    settle();
    TEST_ASSERT_EQUAL_INT32(7, char_body_floor_id(&body));
    const int frames = 90;
    for (int i = 1; i <= frames; i++) {
        in->xf.pos.x = 3.0f * DT * (float)i;
        CB_STEP(&body, DT);
        TEST_ASSERT_TRUE(char_body_is_on_floor(&body));
    }
    fm_vec3_t expect = cb_vec(9.0f, 1.0f, 0.0f);
    cb_report("platform translate: error after 3 s", dist3(pos, expect), "m");
    TEST_ASSERT_TRUE(dist3(pos, expect) < 0.001f);
}

/* 10b. Rotating 90 deg/s about the vertical axis through the centre, body 2 m off-axis. */
static void test_platform_rotate(void)
{
    coll_mesh_instance_t *in = platform();
    cb_body_init(&body, &pos, cb_vec(2.0f, 1.0f, 0.0f));
    settle();
    const fm_vec3_t yaxis = cb_vec(0.0f, 1.0f, 0.0f);
    const int frames = 90;
    float worst = 0.0f;
    for (int i = 1; i <= frames; i++) {
        float ang = 0.5f * PI_F * DT * (float)i;
        fm_quat_from_axis_angle(&in->xf.rot, &yaxis, ang);
        CB_STEP(&body, DT);
        TEST_ASSERT_TRUE(char_body_is_on_floor(&body));
        fm_vec3_t local = cb_vec(2.0f, 0.0f, 0.0f), rotated;
        fm_quat_rotate_vec3(&rotated, &in->xf.rot, &local);
        fm_vec3_t expect = cb_vec(rotated.x, 1.0f, rotated.z);
        float e = dist3(pos, expect);
        if (e > worst) worst = e;
    }
    cb_report("platform rotate: worst error over 3 s (270 deg)", worst, "m");
    cb_report("platform rotate: final x (expect 0)", pos.x, "m");
    cb_report("platform rotate: final z (expect 2)", pos.z, "m");
    TEST_ASSERT_TRUE(worst < 0.001f);
}

/* 10c. Scaling by 2 over 2 s (then held for 1 s). */
static void test_platform_scale(void)
{
    coll_mesh_instance_t *in = platform();
    cb_body_init(&body, &pos, cb_vec(1.5f, 1.0f, 1.0f));
    settle();
    const int frames = 90;
    for (int i = 1; i <= frames; i++) {
        float t = DT * (float)i;
        float s = t < 2.0f ? 1.0f + 0.5f * t : 2.0f;
        in->xf.scale = cb_vec(s, s, s);
        CB_STEP(&body, DT);
        TEST_ASSERT_TRUE(char_body_is_on_floor(&body));
    }
    fm_vec3_t expect = cb_vec(3.0f, 1.0f, 2.0f);
    cb_report("platform scale: error after 3 s", dist3(pos, expect), "m");
    TEST_ASSERT_TRUE(dist3(pos, expect) < 0.001f);
}

/* 10d. An elevator carries up and down. */
static void test_platform_elevator(void)
{
    coll_mesh_instance_t *in = platform();
    cb_body_init(&body, &pos, cb_vec(0.5f, 1.0f, 0.5f));
    settle();
    float worst = 0.0f;
    for (int i = 1; i <= 90; i++) {
        float t = DT * (float)i;
        in->xf.pos.y = 1.0f + 2.0f * sinf(PI_F * t / 1.5f); /* up 2 m and back, +-2.1 m/s */
        CB_STEP(&body, DT);
        TEST_ASSERT_TRUE(char_body_is_on_floor(&body));
        float e = fabsf(pos.y - in->xf.pos.y);
        if (e > worst) worst = e;
    }
    cb_report("elevator: worst foot-platform gap", worst, "m");
    TEST_ASSERT_TRUE(worst < 0.001f);
}

/* 10e. follow_floor off: not carried. */
static void test_platform_no_follow(void)
{
    coll_mesh_instance_t *in = platform();
    cb_body_init(&body, &pos, cb_vec(0.0f, 1.0f, 0.0f));
    char_body_settings_t s = cb_foot_settings();
    s.follow_floor = false;
    char_body_configure(&body, &s);
    settle();
    for (int i = 1; i <= 15; i++) {
        in->xf.pos.x = 3.0f * DT * (float)i;
        CB_STEP(&body, DT);
        TEST_ASSERT_TRUE(char_body_is_on_floor(&body));
    }
    cb_report("follow_floor off: body moved", dist3(pos, cb_vec(0.0f, 1.0f, 0.0f)), "m");
    TEST_ASSERT_TRUE(dist3(pos, cb_vec(0.0f, 1.0f, 0.0f)) < 0.001f);
}

/* 10f. A moving collider body blocks and supports but does not carry. */
static void test_collider_body_not_carried(void)
{
    coll_body_t *box = cb_world_add_box_body(cb_vec(0.0f, 0.75f, 0.0f), cb_vec(3.0f, 0.25f, 3.0f), 9);
    TEST_ASSERT_NOT_NULL(box);
    coll_ray_hit_t probe;
    if (!coll_raycast(&cb_world.scene, cb_vec(0.0f, 3.0f, 0.0f), cb_vec(0.0f, -1.0f, 0.0f), 5.0f, 0x01, COLL_TYPE_ALL,
                      &probe))
        TEST_IGNORE_MESSAGE("collider-body raycasts not available yet (prim_body.c placeholder)");
    cb_body_init(&body, &pos, cb_vec(0.0f, 1.0f, 0.0f));
    char_body_settings_t s = cb_foot_settings();
    s.coll_types = COLL_TYPE_ALL;
    char_body_configure(&body, &s);
    settle();
    TEST_ASSERT_EQUAL_INT32(9, char_body_floor_id(&body));
    for (int i = 1; i <= 15; i++) {
        box->xf.pos.x = 3.0f * DT * (float)i;
        CB_STEP(&body, DT);
        TEST_ASSERT_TRUE(char_body_is_on_floor(&body));
    }
    cb_report("collider body: body moved (expect 0)", dist3(pos, cb_vec(0.0f, 1.0f, 0.0f)), "m");
    TEST_ASSERT_TRUE(dist3(pos, cb_vec(0.0f, 1.0f, 0.0f)) < 0.001f);
}

/* A wall instance moving into the standing body pushes it (overlap recovery every step). */
static void test_moving_wall_pushes(void)
{
    cb_level_floor(30.0f);
    TEST_ASSERT_NOT_NULL(cb_world_add_geo(1));
    cb_geo_box(cb_vec(0.0f, 2.0f, 0.0f), cb_vec(0.5f, 2.0f, 5.0f), 0.0f);
    const coll_mesh_t *m = cb_geo_end();
    TEST_ASSERT_NOT_NULL(m);
    coll_transform_t xf = COLL_TRANSFORM_IDENTITY;
    xf.pos = cb_vec(-3.0f, 0.0f, 0.0f); /* face at x = -2.5 */
    coll_mesh_instance_t *wall = cb_world_add_mesh(m, xf, 2);
    TEST_ASSERT_NOT_NULL(wall);
    cb_body_init(&body, &pos, cb_vec(0.0f, 0.0f, 0.0f));
    settle();
    float worst = 0.0f;
    for (int i = 1; i <= 60; i++) {
        wall->xf.pos.x = -3.0f + 1.5f * DT * (float)i; /* 1.5 m/s, face reaches the body at 1.33 s */
        CB_STEP(&body, DT);
        float pen = (wall->xf.pos.x + 0.5f) - (pos.x - 0.5f);
        if (pen > worst) worst = pen;
        TEST_ASSERT_TRUE(char_body_is_on_floor(&body));
    }
    cb_report("moving wall: worst penetration after a step (1.5 m/s push)", worst, "m");
    cb_report("moving wall: body pushed to x", pos.x, "m");
    TEST_ASSERT_TRUE(worst < 0.001f);
    TEST_ASSERT_FLOAT_WITHIN(0.01f, -3.0f + 1.5f * 2.0f + 1.0f, pos.x);
    /* removed from the scene: a platform no longer carries */
    TEST_ASSERT_EQUAL_INT(COLL_OK, coll_scene_remove_mesh(&cb_world.scene, wall));
}

/* A platform removed from the scene stops carrying at once. */
static void test_removed_platform_does_not_carry(void)
{
    coll_mesh_instance_t *in = platform();
    cb_level_floor(30.0f); /* ground below at y = 0 */
    TEST_ASSERT_NOT_NULL(cb_world_add_geo(1));
    cb_body_init(&body, &pos, cb_vec(0.0f, 1.0f, 0.0f));
    settle();
    TEST_ASSERT_EQUAL_INT32(7, char_body_floor_id(&body));
    TEST_ASSERT_EQUAL_INT(COLL_OK, coll_scene_remove_mesh(&cb_world.scene, in));
    in->xf.pos.x = 100.0f; /* would carry the body 100 m */
    CB_STEP(&body, DT);
    cb_report("removed platform: x after its instance moved 100 m", pos.x, "m");
    TEST_ASSERT_FLOAT_WITHIN(0.001f, 0.0f, pos.x);
    for (int i = 0; i < 30; i++) CB_STEP(&body, DT);
    TEST_ASSERT_TRUE(char_body_is_on_floor(&body));
    TEST_ASSERT_FLOAT_WITHIN(0.001f, 0.0f, pos.y);
}

/* 11a. Planet: walking a full great circle of a 20 m sphere with up = radial. */
static void test_planet_walk_around(void)
{
    cb_geo_sphere(cb_vec(0.0f, 0.0f, 0.0f), 20.0f, 64, 32);
    TEST_ASSERT_NOT_NULL(cb_world_add_geo(1));
    const fm_vec3_t start = cb_vec(0.0f, 20.0f, 0.0f);
    cb_body_init(&body, &pos, start);
    const fm_vec3_t axis = cb_vec(0.0f, 0.0f, 1.0f);
    float angle = 0.0f, prev_a = atan2f(pos.x, pos.y);
    float closest = 1e9f, max_lat = 0.0f, min_r = 1e9f, max_r = 0.0f;
    int frames = 0, air = 0;
    bool around = false;
    fm_vec3_t prev = pos;
    while (!around && frames < 1200) {
        fm_vec3_t up = cb_norm_test(pos);
        char_body_set_up(&body, up);
        char_body_set_center_offset(&body, cb_vec(up.x, up.y, up.z)); /* height 2: centre 1 m up */
        fm_vec3_t fwd;
        fm_vec3_cross(&fwd, &axis, &up);
        body.input_velocity = cb_vec(4.0f * fwd.x, 4.0f * fwd.y, 4.0f * fwd.z);
        prev = pos;
        CB_STEP(&body, DT);
        frames++;
        if (frames > 2 && !char_body_is_on_floor(&body)) air++;
        float a = atan2f(pos.x, pos.y);
        float da = a - prev_a;
        if (da > PI_F) da -= 2.0f * PI_F;
        if (da < -PI_F) da += 2.0f * PI_F;
        angle += da;
        prev_a = a;
        if (fabsf(pos.z) > max_lat) max_lat = fabsf(pos.z);
        float r = sqrtf(pos.x * pos.x + pos.y * pos.y + pos.z * pos.z);
        if (frames > 2 && r < min_r) min_r = r;
        if (frames > 2 && r > max_r) max_r = r;
        if (fabsf(angle) >= 2.0f * PI_F) {
            around = true;
            /* closest approach of the last segment to the start */
            fm_vec3_t d = cb_vec(pos.x - prev.x, pos.y - prev.y, pos.z - prev.z);
            fm_vec3_t w = cb_vec(start.x - prev.x, start.y - prev.y, start.z - prev.z);
            float t = (w.x * d.x + w.y * d.y + w.z * d.z) / (d.x * d.x + d.y * d.y + d.z * d.z);
            t = t < 0.0f ? 0.0f : (t > 1.0f ? 1.0f : t);
            closest = dist3(cb_vec(prev.x + d.x * t, prev.y + d.y * t, prev.z + d.z * t), start);
        }
    }
    cb_report("planet: frames for one lap", frames, "");
    cb_report("planet: airborne frames", air, "");
    cb_report("planet: distance from the start when the lap closes", closest, "m");
    cb_report("planet: largest sideways deviation", max_lat, "m");
    cb_report("planet: foot radius min", min_r, "m");
    cb_report("planet: foot radius max", max_r, "m");
    TEST_ASSERT_TRUE(around);
    TEST_ASSERT_EQUAL_INT(0, air);
    TEST_ASSERT_TRUE(closest < 0.05f);
    TEST_ASSERT_TRUE(max_lat < 0.05f);
    TEST_ASSERT_TRUE(max_r < 20.001f);
    TEST_ASSERT_TRUE(min_r > 19.9f);
    /* ~ 2 pi 20 / (4 / 30) frames */
    TEST_ASSERT_INT_WITHIN(20, 942, frames);
}

/* 11b. Changing up mid-air changes the fall direction. */
static void test_up_change_midair(void)
{
    cb_body_init(&body, &pos, cb_vec(0.0f, 10.0f, 0.0f));
    for (int i = 0; i < 10; i++) CB_STEP(&body, DT);
    TEST_ASSERT_TRUE(pos.y < 10.0f);
    fm_vec3_t before = pos;
    char_body_set_up(&body, cb_vec(2.0f, 0.0f, 0.0f)); /* not normalized on purpose */
    TEST_ASSERT_FLOAT_WITHIN(1e-6f, 1.0f, char_body_get_settings(&body)->up.x);
    for (int i = 0; i < 10; i++) CB_STEP(&body, DT);
    fm_vec3_t v = char_body_get_velocity(&body);
    cb_report("up change: x travelled after up = +x (falls towards -x)", pos.x - before.x, "m");
    cb_report("up change: y travelled", pos.y - before.y, "m");
    TEST_ASSERT_TRUE(pos.x < before.x - 1.0f);
    TEST_ASSERT_TRUE(v.x < -5.0f);
    TEST_ASSERT_FLOAT_WITHIN(1e-4f, 0.0f, v.y);
}

/* 5 km from the origin: walking, standing and a wall are exact to < 1 mm. */
static void test_far_from_origin(void)
{
    cb_level_floor(30.0f);
    cb_geo_box(cb_vec(0.0f, 2.0f, 10.5f), cb_vec(30.0f, 2.0f, 0.5f), 0.0f); /* wall face z = 10 */
    const coll_mesh_t *m = cb_geo_end();
    TEST_ASSERT_NOT_NULL(m);
    coll_transform_t xf = COLL_TRANSFORM_IDENTITY;
    const fm_vec3_t o = cb_vec(4000.0f, 3000.0f, 0.0f); /* 5 km */
    xf.pos = o;
    TEST_ASSERT_NOT_NULL(cb_world_add_mesh(m, xf, 1));
    cb_body_init(&body, &pos, cb_vec(o.x - 10.0f, o.y, o.z));
    settle();
    fm_vec3_t still = pos;
    for (int i = 0; i < 90; i++) { CB_STEP(&body, DT); TEST_ASSERT_TRUE(char_body_is_on_floor(&body)); }
    float drift = dist3(pos, still);
    body.input_velocity = cb_vec(4.0f, 0.0f, 0.0f);
    float hmin = 1e9f, hmax = -1e9f;
    float x0 = pos.x;
    for (int i = 0; i < 90; i++) {
        CB_STEP(&body, DT);
        TEST_ASSERT_TRUE(char_body_is_on_floor(&body));
        if (pos.y < hmin) hmin = pos.y;
        if (pos.y > hmax) hmax = pos.y;
    }
    float walked = pos.x - x0;
    body.input_velocity = cb_vec(0.0f, 0.0f, 4.0f);
    float max_z = -1e9f;
    for (int i = 0; i < 90; i++) {
        CB_STEP(&body, DT);
        if (pos.z > max_z) max_z = pos.z;
    }
    cb_report("5 km: standing drift over 3 s", drift, "m");
    cb_report("5 km: walking height error max", fmaxf(fabsf(hmax - o.y), fabsf(hmin - o.y)), "m");
    cb_report("5 km: walked in 3 s (expect 12)", walked, "m");
    cb_report("5 km: wall penetration (negative = gap)", max_z + 0.5f - 10.0f, "m");
    TEST_ASSERT_TRUE(drift < 0.001f);
    TEST_ASSERT_FLOAT_WITHIN(0.001f, o.y, hmin);
    TEST_ASSERT_FLOAT_WITHIN(0.001f, o.y, hmax);
    TEST_ASSERT_FLOAT_WITHIN(0.12f, 12.0f, walked);
    TEST_ASSERT_TRUE(max_z + 0.5f - 10.0f < 0.001f);
    TEST_ASSERT_TRUE(max_z + 0.5f - 10.0f > -0.005f);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_platform_translate);
    RUN_TEST(test_platform_rotate);
    RUN_TEST(test_platform_scale);
    RUN_TEST(test_platform_elevator);
    RUN_TEST(test_platform_no_follow);
    RUN_TEST(test_collider_body_not_carried);
    RUN_TEST(test_moving_wall_pushes);
    RUN_TEST(test_removed_platform_does_not_carry);
    RUN_TEST(test_planet_walk_around);
    RUN_TEST(test_up_change_midair);
    RUN_TEST(test_far_from_origin);
    return UNITY_END();
}
