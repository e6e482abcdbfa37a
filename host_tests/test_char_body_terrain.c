/* Character body on terrain: ramps, drops, stairs, slopes, ledges, coplanar seams.
 * Every step runs under the allocation guard (CB_STEP). */
#include "unity.h"
#include "alloc_guard.h"
#include "cb_levels.h"
#include <math.h>
#include <stdio.h>

#define DT (1.0f / 30.0f)
#define DEG (3.14159265f / 180.0f)

static char_body_t body;
static fm_vec3_t pos;

void setUp(void) { cb_world_reset(); }
void tearDown(void) {}

/* 5. Ramps: up and down at 4 m/s, on floor every frame, ground speed within 5 %. */
static void ramp(float deg)
{
    cb_world_reset();
    const float len = 6.0f, h = len * tanf(deg * DEG);
    const float xs[4] = {-30.0f, 0.0f, len, len + 30.0f};
    const float ys[4] = {0.0f, 0.0f, h, h};
    cb_geo_profile(xs, ys, 4, -5.0f, 5.0f);
    TEST_ASSERT_NOT_NULL(cb_world_add_geo(1));
    cb_body_init(&body, &pos, cb_vec(-4.0f, 0.0f, 0.0f));
    CB_STEP(&body, DT);
    TEST_ASSERT_TRUE(char_body_is_on_floor(&body));
    float worst_up = 0.0f, worst_down = 0.0f, max_gap = 0.0f;
    for (int dir = 1; dir >= -1; dir -= 2) {
        body.input_velocity = cb_vec(4.0f * (float)dir, 0.0f, 0.0f);
        for (int i = 0; i < 150; i++) {
            fm_vec3_t before = pos;
            CB_STEP(&body, DT);
            TEST_ASSERT_TRUE_MESSAGE(char_body_is_on_floor(&body), "left the ground on a ramp walk");
            /* foot on the surface */
            float surf = pos.x <= 0.0f ? 0.0f : (pos.x >= len ? h : pos.x * tanf(deg * DEG));
            float gap = fabsf(pos.y - surf);
            if (gap > max_gap) max_gap = gap;
            /* ground speed while both ends of the step are on the slope */
            if (before.x > 0.05f && before.x < len - 0.05f && pos.x > 0.05f && pos.x < len - 0.05f) {
                float dx = pos.x - before.x, dy = pos.y - before.y;
                float err = fabsf(sqrtf(dx * dx + dy * dy) / DT / 4.0f - 1.0f);
                if (dir > 0 && err > worst_up) worst_up = err;
                if (dir < 0 && err > worst_down) worst_down = err;
            }
        }
        TEST_ASSERT_TRUE(dir > 0 ? pos.x > len + 5.0f : pos.x < -3.0f);
    }
    char name[96];
    snprintf(name, sizeof name, "ramp %.0f deg: worst ground speed error up", deg);
    cb_report(name, worst_up * 100.0f, "%");
    snprintf(name, sizeof name, "ramp %.0f deg: worst ground speed error down", deg);
    cb_report(name, worst_down * 100.0f, "%");
    snprintf(name, sizeof name, "ramp %.0f deg: worst foot-surface gap", deg);
    cb_report(name, max_gap, "m");
    TEST_ASSERT_TRUE(worst_up < 0.05f);
    TEST_ASSERT_TRUE(worst_down < 0.05f);
    TEST_ASSERT_TRUE(max_gap < 0.001f);
}
static void test_ramp_20(void) { ramp(20.0f); }
static void test_ramp_40(void) { ramp(40.0f); }

/* 6. Drops: larger than floor_snap_distance falls, smaller snaps and stays grounded. */
static int walk_off_drop(float drop, float *min_y)
{
    cb_world_reset();
    const float xs[4] = {-20.0f, 0.0f, 0.0f, 20.0f};
    const float ys[4] = {0.0f, 0.0f, -drop, -drop};
    cb_geo_profile(xs, ys, 4, -5.0f, 5.0f);
    TEST_ASSERT_NOT_NULL(cb_world_add_geo(1));
    cb_body_init(&body, &pos, cb_vec(-3.0f, 0.0f, 0.0f));
    CB_STEP(&body, DT);
    body.input_velocity = cb_vec(4.0f, 0.0f, 0.0f);
    int airborne = 0;
    *min_y = 1e9f;
    for (int i = 0; i < 60; i++) {
        CB_STEP(&body, DT);
        if (!char_body_is_on_floor(&body)) airborne++;
        if (pos.y < *min_y) *min_y = pos.y;
    }
    TEST_ASSERT_TRUE(char_body_is_on_floor(&body));
    TEST_ASSERT_FLOAT_WITHIN(0.001f, -drop, pos.y);
    return airborne;
}
static void test_drop_large_falls(void)
{
    float min_y;
    int air = walk_off_drop(0.5f, &min_y);
    cb_report("drop 0.5 m: airborne frames", air, "");
    cb_report("drop 0.5 m: lowest foot (floor -0.5)", min_y, "m");
    TEST_ASSERT_TRUE(air >= 2);
    TEST_ASSERT_TRUE(min_y > -0.501f);
}
static void test_drop_small_snaps(void)
{
    float min_y;
    int air = walk_off_drop(0.2f, &min_y);
    cb_report("drop 0.2 m: airborne frames", air, "");
    TEST_ASSERT_EQUAL_INT(0, air);
    TEST_ASSERT_TRUE(min_y > -0.201f);
}

/* 7. Stairs: climbed and descended at 4 m/s without stopping, grounded on every tread. */
static void stairs(float riser)
{
    cb_world_reset();
    const int steps = 8;
    const float tread = 0.5f;
    cb_geo_stairs(tread, riser, steps, -5.0f, 5.0f);
    TEST_ASSERT_NOT_NULL(cb_world_add_geo(1));
    cb_body_init(&body, &pos, cb_vec(-3.0f, 0.0f, 0.0f));
    CB_STEP(&body, DT);
    float top = (float)steps * riser;
    int slow_frames = 0, air_frames = 0;
    float worst_tread_err = 0.0f;
    for (int dir = 1; dir >= -1; dir -= 2) {
        body.input_velocity = cb_vec(4.0f * (float)dir, 0.0f, 0.0f);
        for (int i = 0; i < 90; i++) {
            float x0 = pos.x;
            CB_STEP(&body, DT);
            if (fabsf(pos.x - x0) < 0.9f * 4.0f * DT) slow_frames++;
            if (!char_body_is_on_floor(&body)) air_frames++;
            /* the foot stands on the tread under the axis */
            float expect = pos.x < 0.0f ? 0.0f : (pos.x >= (float)steps * tread ? top : (floorf(pos.x / tread) + 1.0f) * riser);
            float err = fabsf(pos.y - expect);
            if (err > worst_tread_err) worst_tread_err = err;
        }
        TEST_ASSERT_TRUE(dir > 0 ? pos.x > (float)steps * tread + 3.0f : pos.x < -2.0f);
    }
    char name[96];
    snprintf(name, sizeof name, "stairs %.2f m: frames slower than 90%% of 4 m/s", riser);
    cb_report(name, slow_frames, "");
    snprintf(name, sizeof name, "stairs %.2f m: airborne frames", riser);
    cb_report(name, air_frames, "");
    snprintf(name, sizeof name, "stairs %.2f m: worst foot-tread error", riser);
    cb_report(name, worst_tread_err, "m");
    TEST_ASSERT_EQUAL_INT(0, slow_frames);
    TEST_ASSERT_EQUAL_INT(0, air_frames);
    TEST_ASSERT_TRUE(worst_tread_err < 0.001f);
}
static void test_stairs_010(void) { stairs(0.10f); }
static void test_stairs_020(void) { stairs(0.20f); }
static void test_stairs_025(void) { stairs(0.25f); }

static void test_riser_035_blocks(void)
{
    const float xs[4] = {-20.0f, 0.0f, 0.0f, 20.0f};
    const float ys[4] = {0.0f, 0.0f, 0.35f, 0.35f};
    cb_geo_profile(xs, ys, 4, -5.0f, 5.0f);
    TEST_ASSERT_NOT_NULL(cb_world_add_geo(1));
    cb_body_init(&body, &pos, cb_vec(-3.0f, 0.0f, 0.0f));
    CB_STEP(&body, DT);
    body.input_velocity = cb_vec(4.0f, 0.0f, 0.0f);
    float max_x = -1e9f, max_y = -1e9f;
    for (int i = 0; i < 90; i++) {
        CB_STEP(&body, DT);
        if (pos.x > max_x) max_x = pos.x;
        if (pos.y > max_y) max_y = pos.y;
    }
    /* The sweep capsule's bottom ball (centre 0.75 m up) meets the riser's top edge 0.3 m out. */
    cb_report("riser 0.35 m: furthest x (contact at -0.3)", max_x, "m");
    cb_report("riser 0.35 m: highest foot", max_y, "m");
    TEST_ASSERT_TRUE(max_x < -0.3f);
    TEST_ASSERT_TRUE(max_x > -0.31f);
    TEST_ASSERT_TRUE(max_y < 0.001f);
    TEST_ASSERT_TRUE(char_body_is_on_floor(&body));
}

/* 8. Slopes: standing on 44 degrees does not drift; on 50 degrees the body slides. */
static void slope_level(float deg)
{
    float t = tanf(deg * DEG);
    const float xs[2] = {-60.0f, 20.0f};
    const float ys[2] = {-60.0f * t, 20.0f * t};
    cb_geo_profile(xs, ys, 2, -10.0f, 10.0f);
    TEST_ASSERT_NOT_NULL(cb_world_add_geo(1));
}
static void test_slope_44_no_drift(void)
{
    slope_level(44.0f);
    cb_body_init(&body, &pos, cb_vec(0.0f, 0.05f, 0.0f));
    for (int i = 0; i < 15; i++) CB_STEP(&body, DT);
    TEST_ASSERT_TRUE(char_body_is_on_floor(&body));
    TEST_ASSERT_FALSE(char_body_is_on_steep_surface(&body));
    fm_vec3_t start = pos;
    for (int i = 0; i < 300; i++) {
        CB_STEP(&body, DT);
        TEST_ASSERT_TRUE(char_body_is_on_floor(&body));
    }
    float dx = pos.x - start.x, dy = pos.y - start.y, dz = pos.z - start.z;
    float drift = sqrtf(dx * dx + dy * dy + dz * dz);
    cb_report("slope 44 deg: drift over 10 s", drift, "m");
    cb_report("slope 44 deg: foot-surface gap", pos.y - pos.x * tanf(44.0f * DEG), "m");
    TEST_ASSERT_TRUE(drift < 0.001f);
    TEST_ASSERT_FLOAT_WITHIN(0.001f, pos.x * tanf(44.0f * DEG), pos.y);
}
static void slope_50_slides(float dt, int frames)
{
    cb_world_reset();
    slope_level(50.0f);
    cb_body_init(&body, &pos, cb_vec(0.0f, 0.05f, 0.0f));
    int steep_frames = 0, first_steep = -1;
    float max_pen = -1e9f;
    const float t50 = tanf(50.0f * DEG), s50 = sinf(50.0f * DEG);
    for (int i = 0; i < frames; i++) {
        CB_STEP(&body, dt);
        bool steep = char_body_is_on_steep_surface(&body) && char_body_is_on_floor(&body);
        if (steep && first_steep < 0) first_steep = i;
        if (first_steep >= 0 && steep) steep_frames++;
        /* the sweep capsule's bottom ball must stay out of the plane */
        float cx = pos.x, cy = pos.y + 0.75f;
        float dist = (cy - cx * t50) * cosf(50.0f * DEG);
        if (0.5f - dist > max_pen) max_pen = 0.5f - dist;
    }
    fm_vec3_t v = char_body_get_velocity(&body);
    float speed = sqrtf(v.x * v.x + v.y * v.y + v.z * v.z);
    float expect = 30.0f * s50 * dt * (float)(frames - first_steep); /* g sin(slope) t */
    char name[96];
    snprintf(name, sizeof name, "slope 50 deg (dt 1/%.0f): frames to steep contact", 1.0f / dt);
    cb_report(name, first_steep, "");
    snprintf(name, sizeof name, "slope 50 deg (dt 1/%.0f): steep frames after contact (of %d)", 1.0f / dt, frames - first_steep);
    cb_report(name, steep_frames, "");
    snprintf(name, sizeof name, "slope 50 deg (dt 1/%.0f): slide speed vs g sin(50) t", 1.0f / dt);
    cb_report(name, speed / expect, "");
    snprintf(name, sizeof name, "slope 50 deg (dt 1/%.0f): drop", 1.0f / dt);
    cb_report(name, -pos.y, "m");
    snprintf(name, sizeof name, "slope 50 deg (dt 1/%.0f): sweep capsule penetration", 1.0f / dt);
    cb_report(name, max_pen, "m");
    TEST_ASSERT_TRUE(first_steep >= 0 && first_steep < frames / 4);
    TEST_ASSERT_EQUAL_INT(frames - first_steep, steep_frames);
    TEST_ASSERT_FLOAT_WITHIN(0.05f * expect, expect, speed);
    TEST_ASSERT_TRUE(pos.y < -1.0f);
    TEST_ASSERT_TRUE(pos.x < -0.8f);
    TEST_ASSERT_TRUE(max_pen < 0.001f);
    TEST_ASSERT_TRUE(char_body_is_on_floor(&body));
    TEST_ASSERT_TRUE(char_body_is_on_steep_surface(&body));
}
static void test_slope_50_slides(void)
{
    slope_50_slides(DT, 45);
    slope_50_slides(1.0f / 60.0f, 90); /* the same slide at another frame rate */
}

/* Pushing uphill on a steep slope does not climb it. */
static void test_slope_50_no_climbing(void)
{
    slope_level(50.0f);
    cb_body_init(&body, &pos, cb_vec(0.0f, 0.05f, 0.0f));
    for (int i = 0; i < 3; i++) CB_STEP(&body, DT);
    TEST_ASSERT_TRUE(char_body_is_on_steep_surface(&body));
    float y0 = pos.y, max_y = pos.y;
    body.input_velocity = cb_vec(6.0f, 0.0f, 1.0f); /* uphill, a little sideways */
    for (int i = 0; i < 60; i++) {
        CB_STEP(&body, DT);
        if (pos.y > max_y) max_y = pos.y;
    }
    cb_report("slope 50 deg pushing uphill: highest rise", max_y - y0, "m");
    cb_report("slope 50 deg pushing uphill: height change after 2 s", pos.y - y0, "m");
    TEST_ASSERT_TRUE(max_y - y0 < 0.001f);
    TEST_ASSERT_TRUE(pos.y < y0 - 0.5f);
    TEST_ASSERT_TRUE(pos.z > 1.0f); /* the sideways part still moves */
    TEST_ASSERT_TRUE(char_body_is_on_steep_surface(&body));
}

/* Pushing into a steep slope while airborne does not climb it either (seen on big-endian
 * MIPS in the example: 3 m/s into a 50 deg slope carried the body from 1.7 m to 3.1 m and
 * over the top): the clip against a steep plane may not turn the motion upwards. */
static void airborne_push(float dt, float speed, float jump)
{
    cb_world_reset();
    slope_level(50.0f);
    cb_body_init(&body, &pos, cb_vec(-1.5f, 0.0f, 0.0f));
    body.input_velocity = cb_vec(speed, 0.0f, 0.0f);
    if (jump > 0.0f) char_body_set_velocity(&body, cb_vec(0.0f, jump, 0.0f));
    /* highest the body can get on its own: the jump's apex */
    float apex = jump * jump / (2.0f * 30.0f);
    float max_y = pos.y, max_over = -1e9f;
    int frames = (int)(2.0f / dt);
    for (int i = 0; i < frames; i++) {
        CB_STEP(&body, dt);
        if (pos.y > max_y) max_y = pos.y;
        if (pos.y - apex > max_over) max_over = pos.y - apex;
    }
    char name[96];
    snprintf(name, sizeof name, "slope 50 deg airborne push %.0f m/s jump %.0f (dt 1/%.0f): highest foot over the apex",
             speed, jump, 1.0f / dt);
    cb_report(name, max_over, "m");
    snprintf(name, sizeof name, "slope 50 deg airborne push %.0f m/s jump %.0f (dt 1/%.0f): height after 2 s",
             speed, jump, 1.0f / dt);
    cb_report(name, pos.y, "m");
    TEST_ASSERT_TRUE(max_y <= apex + 0.001f);
    TEST_ASSERT_TRUE(pos.y < -0.5f);  /* slid down, not up */
    TEST_ASSERT_TRUE(pos.x < -1.0f);
}
static void test_slope_50_airborne_push_no_climbing(void)
{
    airborne_push(1.0f / 60.0f, 3.0f, 0.0f);
    airborne_push(1.0f / 30.0f, 3.0f, 0.0f);
    airborne_push(1.0f / 60.0f, 8.0f, 0.0f);
    airborne_push(1.0f / 60.0f, 3.0f, 6.0f); /* jumping into it: no higher than the jump */
}

/* 9. Walking slowly off a ledge: falls once past the edge, cannot walk back up. */
static void test_ledge(void)
{
    cb_geo_box(cb_vec(-10.0f, -2.5f, 0.0f), cb_vec(10.0f, 2.5f, 10.0f), 0.0f); /* top y 0, edge x 0 */
    cb_geo_box(cb_vec(0.0f, -5.5f, 0.0f), cb_vec(30.0f, 0.5f, 30.0f), 0.0f);   /* ground y -5 */
    TEST_ASSERT_NOT_NULL(cb_world_add_geo(1));
    cb_body_init(&body, &pos, cb_vec(-1.0f, 0.0f, 0.0f));
    CB_STEP(&body, DT);
    body.input_velocity = cb_vec(0.5f, 0.0f, 0.0f);
    int past = -1, left_floor = -1, grounded_past = 0;
    float prev_y = 0.0f;
    for (int i = 0; i < 300 && left_floor < 0; i++) {
        CB_STEP(&body, DT);
        if (past < 0 && pos.x > 0.0f) past = i;
        if (past >= 0 && char_body_is_on_floor(&body)) grounded_past++;
        if (past >= 0 && !char_body_is_on_floor(&body)) left_floor = i;
    }
    TEST_ASSERT_TRUE(past >= 0 && left_floor >= 0);
    cb_report("ledge: frames on floor with the centre past the edge", grounded_past, "");
    TEST_ASSERT_TRUE(grounded_past <= 2);
    /* keeps falling: never stalls on the edge */
    int stalled = 0;
    prev_y = pos.y;
    float x_fall = pos.x;
    for (int i = 0; i < 12; i++) {
        CB_STEP(&body, DT);
        if (pos.y >= prev_y - 1e-4f) stalled++;
        prev_y = pos.y;
    }
    cb_report("ledge: frames without descending in the first 12 of the fall", stalled, "");
    cb_report("ledge: sideways push while falling off", pos.x - x_fall, "m");
    TEST_ASSERT_TRUE(stalled <= 2);
    TEST_ASSERT_TRUE(pos.y < -0.8f);
    /* walking back towards the ledge while falling never gets back onto it */
    body.input_velocity = cb_vec(-4.0f, 0.0f, 0.0f);
    float max_y_back = -1e9f;
    for (int i = 0; i < 60; i++) {
        CB_STEP(&body, DT);
        if (pos.y > max_y_back) max_y_back = pos.y;
        TEST_ASSERT_TRUE(pos.x > -0.001f || pos.y > -0.001f); /* foot never inside the block */
    }
    cb_report("ledge: highest foot while pushing back (ledge top 0)", max_y_back, "m");
    TEST_ASSERT_TRUE(max_y_back < -0.5f);
    TEST_ASSERT_FLOAT_WITHIN(0.001f, -5.0f, pos.y);
    TEST_ASSERT_TRUE(char_body_is_on_floor(&body));
}

/* Placed with the centre just past the edge (the full capsule half over it): falls at once. */
static void test_ledge_start_past_edge_falls(void)
{
    cb_geo_box(cb_vec(-10.0f, -2.5f, 0.0f), cb_vec(10.0f, 2.5f, 10.0f), 0.0f);
    cb_geo_box(cb_vec(0.0f, -5.5f, 0.0f), cb_vec(30.0f, 0.5f, 30.0f), 0.0f);
    TEST_ASSERT_NOT_NULL(cb_world_add_geo(1));
    cb_body_init(&body, &pos, cb_vec(0.05f, 0.0f, 0.0f)); /* centre just past the edge */
    for (int i = 0; i < 3; i++) CB_STEP(&body, DT);
    TEST_ASSERT_FALSE(char_body_is_on_floor(&body));
    TEST_ASSERT_TRUE(pos.y < 0.0f);
}

/* Walking off the ledge fast and turning back at once, while the foot is still within the
 * step zone below the ledge top: the foot point may not re-enter the ledge from the side. */
static void test_ledge_no_walk_back_early(void)
{
    cb_geo_box(cb_vec(-10.0f, -2.5f, 0.0f), cb_vec(10.0f, 2.5f, 10.0f), 0.0f);
    cb_geo_box(cb_vec(0.0f, -5.5f, 0.0f), cb_vec(30.0f, 0.5f, 30.0f), 0.0f);
    TEST_ASSERT_NOT_NULL(cb_world_add_geo(1));
    cb_body_init(&body, &pos, cb_vec(-1.0f, 0.0f, 0.0f));
    CB_STEP(&body, DT);
    body.input_velocity = cb_vec(4.0f, 0.0f, 0.0f);
    int guard = 0;
    while (char_body_is_on_floor(&body) && guard++ < 60) CB_STEP(&body, DT);
    CB_STEP(&body, DT);
    float turn_y = pos.y;
    body.input_velocity = cb_vec(-4.0f, 0.0f, 0.0f);
    float max_y = -1e9f;
    int on_ledge = 0;
    for (int i = 0; i < 60; i++) {
        CB_STEP(&body, DT);
        if (pos.y > max_y) max_y = pos.y;
        if (char_body_is_on_floor(&body) && pos.y > -1.0f) on_ledge++;
    }
    cb_report("ledge early turn-back: foot height when turning (ledge top 0)", turn_y, "m");
    cb_report("ledge early turn-back: highest foot afterwards", max_y, "m");
    TEST_ASSERT_TRUE(turn_y < 0.0f && turn_y > -0.25f);
    TEST_ASSERT_EQUAL_INT(0, on_ledge);
    TEST_ASSERT_TRUE(max_y < 0.0f);
    TEST_ASSERT_FLOAT_WITHIN(0.001f, -5.0f, pos.y);
}

/* Coplanar seams: a floor of many small triangles is as smooth as one quad. */
static void test_coplanar_seams(void)
{
    cb_geo_grid(20.0f, 80, 0.0f); /* 0.5 m cells, 12800 triangles */
    TEST_ASSERT_NOT_NULL(cb_world_add_geo(1));
    cb_body_init(&body, &pos, cb_vec(-10.0f, 0.0f, -10.0f)); /* on a vertex */
    CB_STEP(&body, DT);
    const float sp = 4.0f, c45 = 0.70710678f;
    body.input_velocity = cb_vec(sp * c45, 0.0f, sp * c45); /* diagonal: through vertices and edges */
    float min_y = 1e9f, max_y = -1e9f;
    const int frames = 120;
    for (int i = 0; i < frames; i++) {
        CB_STEP(&body, DT);
        TEST_ASSERT_TRUE(char_body_is_on_floor(&body));
        if (pos.y < min_y) min_y = pos.y;
        if (pos.y > max_y) max_y = pos.y;
    }
    float dx = pos.x + 10.0f, dz = pos.z + 10.0f;
    float dist = sqrtf(dx * dx + dz * dz), expect = sp * DT * (float)frames;
    cb_report("seams: height variation", max_y - min_y, "m");
    cb_report("seams: distance error", (dist / expect - 1.0f) * 100.0f, "%");
    cb_report("seams: lateral error", dx - dz, "m");
    TEST_ASSERT_TRUE(max_y - min_y < 0.0001f);
    TEST_ASSERT_FLOAT_WITHIN(0.001f * expect, expect, dist);
}

/* Sliding along a wall tessellated into 0.5 m squares with alternating diagonals, pushed
 * into it at ~27 degrees: no speed lost at any seam, no creeping into the wall. */
static void test_tessellated_wall_slide(void)
{
    cb_geo_grid(20.0f, 40, 0.0f);
    for (int j = 0; j < 8; j++)
        for (int i = 0; i < 80; i++) {
            float z0 = -10.0f + 0.5f * (float)i, y0 = -0.5f + 0.5f * (float)j;
            fm_vec3_t a = cb_vec(3.0f, y0, z0), b = cb_vec(3.0f, y0, z0 + 0.5f);
            fm_vec3_t c = cb_vec(3.0f, y0 + 0.5f, z0 + 0.5f), d = cb_vec(3.0f, y0 + 0.5f, z0);
            if ((i + j) & 1) { cb_geo_tri(a, b, c); cb_geo_tri(a, c, d); }
            else { cb_geo_tri(a, b, d); cb_geo_tri(b, c, d); }
        }
    TEST_ASSERT_NOT_NULL(cb_world_add_geo(1));
    cb_body_init(&body, &pos, cb_vec(3.0f - 0.52f, 0.0f, -8.0f));
    body.input_velocity = cb_vec(2.5f, 0.0f, 5.0f);
    float worst_loss = 0.0f, max_x = -1e9f, max_bump = 0.0f;
    for (int f = 0; f < 90; f++) {
        fm_vec3_t before = pos;
        CB_STEP(&body, DT);
        TEST_ASSERT_TRUE(char_body_is_on_floor(&body));
        if (f > 2) {
            float loss = 1.0f - (pos.z - before.z) / DT / 5.0f;
            if (loss > worst_loss) worst_loss = loss;
        }
        if (pos.x > max_x) max_x = pos.x;
        if (fabsf(pos.y) > max_bump) max_bump = fabsf(pos.y);
    }
    cb_report("tessellated wall: worst per-frame speed loss", worst_loss * 100.0f, "%");
    cb_report("tessellated wall: penetration (negative = gap)", max_x + 0.5f - 3.0f, "m");
    cb_report("tessellated wall: bump", max_bump, "m");
    TEST_ASSERT_TRUE(worst_loss < 0.01f);
    TEST_ASSERT_TRUE(max_x + 0.5f - 3.0f < 0.0f);
    TEST_ASSERT_TRUE(max_bump < 0.0001f);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_ramp_20);
    RUN_TEST(test_ramp_40);
    RUN_TEST(test_drop_large_falls);
    RUN_TEST(test_drop_small_snaps);
    RUN_TEST(test_stairs_010);
    RUN_TEST(test_stairs_020);
    RUN_TEST(test_stairs_025);
    RUN_TEST(test_riser_035_blocks);
    RUN_TEST(test_slope_44_no_drift);
    RUN_TEST(test_slope_50_slides);
    RUN_TEST(test_ledge);
    RUN_TEST(test_ledge_start_past_edge_falls);
    RUN_TEST(test_ledge_no_walk_back_early);
    RUN_TEST(test_slope_50_no_climbing);
    RUN_TEST(test_slope_50_airborne_push_no_climbing);
    RUN_TEST(test_coplanar_seams);
    RUN_TEST(test_tessellated_wall_slide);
    return UNITY_END();
}
