/* Character body robustness: thin geometry at terminal speed, bad input, settings clamping,
 * debug drawing. Every step runs under the allocation guard (CB_STEP). */
#include "unity.h"
#include "alloc_guard.h"
#include "cb_levels.h"
#include <math.h>
#include <stdio.h>
#include <string.h>

#define DT (1.0f / 30.0f)

static char_body_t body;
static fm_vec3_t pos;

void setUp(void) { cb_world_reset(); }
void tearDown(void) {}

/* 14. Terminal speed with dt = 1/20 onto a single triangle and onto a 1 cm slab. */
static void test_fall_onto_single_triangle(void)
{
    cb_geo_tri(cb_vec(-50.0f, 0.0f, -50.0f), cb_vec(50.0f, 0.0f, -50.0f), cb_vec(0.0f, 0.0f, 80.0f));
    TEST_ASSERT_NOT_NULL(cb_world_add_geo(1));
    for (int k = 0; k < 8; k++) {
        cb_body_init(&body, &pos, cb_vec(0.37f * (float)k, 30.0f + 0.41f * (float)k, 0.23f * (float)k));
        char_body_set_velocity(&body, cb_vec(0.0f, -55.0f, 0.0f));
        float min_y = 1e9f;
        for (int i = 0; i < 40; i++) {
            CB_STEP(&body, 1.0f / 20.0f);
            if (pos.y < min_y) min_y = pos.y;
        }
        if (k == 0) cb_report("single triangle: lowest foot after a 55 m/s fall", min_y, "m");
        TEST_ASSERT_TRUE(min_y > -0.26f); /* the foot may dip into the step zone for one frame, never through */
        TEST_ASSERT_TRUE(char_body_is_on_floor(&body));
        TEST_ASSERT_FLOAT_WITHIN(0.001f, 0.0f, pos.y);
    }
}

static void test_fall_onto_thin_slab_and_wall(void)
{
    cb_geo_box(cb_vec(0.0f, -0.005f, 0.0f), cb_vec(40.0f, 0.005f, 40.0f), 0.0f); /* 1 cm floor */
    cb_geo_box(cb_vec(5.0f, 5.0f, 0.0f), cb_vec(0.005f, 5.0f, 40.0f), 0.0f);    /* 1 cm wall, x 4.995..5.005 */
    TEST_ASSERT_NOT_NULL(cb_world_add_geo(1));
    cb_body_init(&body, &pos, cb_vec(0.0f, 30.0f, 0.0f));
    char_body_set_velocity(&body, cb_vec(0.0f, -55.0f, 0.0f));
    float min_y = 1e9f;
    for (int i = 0; i < 30; i++) {
        CB_STEP(&body, 1.0f / 20.0f);
        if (pos.y < min_y) min_y = pos.y;
    }
    cb_report("1 cm slab: lowest foot after a 55 m/s fall (top 0)", min_y, "m");
    TEST_ASSERT_TRUE(char_body_is_on_floor(&body));
    TEST_ASSERT_FLOAT_WITHIN(0.001f, 0.0f, pos.y);
    /* into the wall at the speed limit, grounded and airborne */
    body.input_velocity = cb_vec(1000.0f, 0.0f, 0.0f);
    float max_x = -1e9f;
    for (int i = 0; i < 30; i++) {
        CB_STEP(&body, 1.0f / 20.0f);
        if (pos.x > max_x) max_x = pos.x;
    }
    char_body_set_velocity(&body, cb_vec(0.0f, 20.0f, 0.0f));
    body.input_velocity = cb_vec(55.0f, 0.0f, 3.0f);
    for (int i = 0; i < 30; i++) {
        CB_STEP(&body, 1.0f / 20.0f);
        if (pos.x > max_x) max_x = pos.x;
    }
    cb_report("1 cm wall: closest capsule surface to the wall face 4.995 (negative = gap)", max_x + 0.5f - 4.995f, "m");
    TEST_ASSERT_TRUE(max_x + 0.5f <= 4.995f + 1e-4f);
    TEST_ASSERT_TRUE(pos.y > -0.001f);
}

/* 15. Bad input never produces NaN, never moves on bad dt, never passes through geometry. */
static void test_bad_dt(void)
{
    cb_level_floor(20.0f);
    TEST_ASSERT_NOT_NULL(cb_world_add_geo(1));
    cb_body_init(&body, &pos, cb_vec(0.0f, 0.0f, 0.0f));
    CB_STEP(&body, DT);
    body.input_velocity = cb_vec(4.0f, 0.0f, 0.0f);
    const float bad[] = {0.0f, -1.0f, NAN, INFINITY, -INFINITY};
    for (unsigned i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        fm_vec3_t before = pos;
        CB_STEP(&body, bad[i]);
        TEST_ASSERT_EQUAL_MEMORY(&before, &pos, sizeof pos);
    }
    /* 10 s steps are clamped to 0.1 s: the body moves 0.4 m per call and stays on the floor */
    fm_vec3_t before = pos;
    CB_STEP(&body, 10.0f);
    cb_report("dt = 10 s: distance moved in one call", pos.x - before.x, "m");
    TEST_ASSERT_FLOAT_WITHIN(0.001f, 0.4f, pos.x - before.x);
    TEST_ASSERT_TRUE(char_body_is_on_floor(&body));
    TEST_ASSERT_FLOAT_WITHIN(0.0001f, 0.0f, pos.y);
}

static void test_bad_velocities_and_walls(void)
{
    /* A closed room: huge finite inputs ask for the fastest motion (200 m/s), so the body
     * crosses it in one step and must stop at every wall, never pass one. */
    cb_level_floor(20.0f);
    cb_geo_box(cb_vec(3.0f, 20.0f, 0.0f), cb_vec(0.5f, 20.0f, 20.0f), 0.0f);  /* face x = 2.5 */
    cb_geo_box(cb_vec(-8.0f, 20.0f, 0.0f), cb_vec(0.5f, 20.0f, 20.0f), 0.0f); /* face x = -7.5 */
    cb_geo_box(cb_vec(0.0f, 20.0f, 8.0f), cb_vec(20.0f, 20.0f, 0.5f), 0.0f);  /* face z = 7.5 */
    cb_geo_box(cb_vec(0.0f, 20.0f, -8.0f), cb_vec(20.0f, 20.0f, 0.5f), 0.0f); /* face z = -7.5 */
    cb_geo_box(cb_vec(0.0f, 40.5f, 0.0f), cb_vec(20.0f, 0.5f, 20.0f), 0.0f);  /* ceiling at 40 */
    TEST_ASSERT_NOT_NULL(cb_world_add_geo(1));
    cb_body_init(&body, &pos, cb_vec(0.0f, 0.0f, 0.0f));
    CB_STEP(&body, DT);
    const float vals[] = {NAN, INFINITY, -INFINITY, 1e30f, -1e30f, 1e6f};
    float max_x = -1e9f, min_y = 1e9f;
    for (unsigned i = 0; i < sizeof vals / sizeof vals[0]; i++) {
        for (unsigned j = 0; j < sizeof vals / sizeof vals[0]; j++) {
            body.input_velocity = cb_vec(vals[i], vals[j], 1.0f);
            body.velocity = cb_vec(vals[j], vals[i], -vals[j]);
            CB_STEP(&body, i == j ? 10.0f : DT);
            TEST_ASSERT_TRUE(cb_body_finite(&body));
            TEST_ASSERT_TRUE(pos.x >= -7.0f - 1e-4f && fabsf(pos.z) <= 7.0f + 1e-4f);
            if (pos.x > max_x) max_x = pos.x;
            if (pos.y < min_y) min_y = pos.y;
        }
    }
    /* big finite input into the wall */
    body.input_velocity = cb_vec(1e30f, 0.0f, 0.0f);
    for (int i = 0; i < 20; i++) {
        CB_STEP(&body, 10.0f);
        TEST_ASSERT_TRUE(cb_body_finite(&body));
        if (pos.x > max_x) max_x = pos.x;
        if (pos.y < min_y) min_y = pos.y;
    }
    fm_vec3_t v = char_body_get_velocity(&body);
    cb_report("bad velocities: furthest capsule surface past the wall face (negative = gap)", max_x + 0.5f - 2.5f, "m");
    cb_report("bad velocities: lowest foot", min_y, "m");
    cb_report("bad velocities: speed after huge input", sqrtf(v.x * v.x + v.y * v.y + v.z * v.z), "m/s");
    TEST_ASSERT_TRUE(max_x + 0.5f <= 2.5f + 1e-4f);
    TEST_ASSERT_TRUE(min_y > -0.26f);
    TEST_ASSERT_TRUE(sqrtf(v.x * v.x + v.y * v.y + v.z * v.z) <= 200.0f + 1e-3f);
    /* and it recovers: still stands on the floor */
    body.input_velocity = cb_vec(0.0f, 0.0f, 0.0f);
    for (int i = 0; i < 20; i++) CB_STEP(&body, DT);
    TEST_ASSERT_TRUE(char_body_is_on_floor(&body));
    TEST_ASSERT_FLOAT_WITHIN(0.001f, 0.0f, pos.y);
    /* huge finite velocities are clamped to 200 m/s */
    char_body_teleport(&body, cb_vec(0.0f, 50.0f, 0.0f), true);
    body.velocity = cb_vec(-1e6f, 3e5f, 1e6f);
    CB_STEP(&body, DT);
    v = char_body_get_velocity(&body);
    cb_report("bad velocities: speed after a 1.4e6 m/s velocity", sqrtf(v.x * v.x + v.y * v.y + v.z * v.z), "m/s");
    TEST_ASSERT_TRUE(sqrtf(v.x * v.x + v.y * v.y + v.z * v.z) <= 200.0f + 1e-3f);
    TEST_ASSERT_TRUE(cb_body_finite(&body));
    char_body_teleport(&body, cb_vec(0.0f, 0.0f, 0.0f), true);
    /* set_velocity ignores non-finite values */
    char_body_set_velocity(&body, cb_vec(1.0f, 2.0f, 3.0f));
    char_body_set_velocity(&body, cb_vec(NAN, 0.0f, 0.0f));
    TEST_ASSERT_EQUAL_FLOAT(2.0f, char_body_get_velocity(&body).y);
}

static void test_settings_clamped(void)
{
    cb_level_floor(20.0f);
    TEST_ASSERT_NOT_NULL(cb_world_add_geo(1));
    cb_body_init(&body, &pos, cb_vec(0.0f, 1.0f, 0.0f));
    char_body_settings_t s = CHAR_BODY_SETTINGS_DEFAULT;
    s.radius = 0.0f;
    s.height = 0.0f;
    s.up = cb_vec(0.0f, 0.0f, 0.0f);
    s.step_height = -1.0f;
    s.floor_snap_distance = NAN;
    s.max_slides = 0;
    s.floor_max_angle = 7.0f;
    char_body_configure(&body, &s);
    const char_body_settings_t *g = char_body_get_settings(&body);
    TEST_ASSERT_TRUE(g->radius > 0.0f);
    TEST_ASSERT_TRUE(g->height >= 2.0f * g->radius);
    TEST_ASSERT_EQUAL_FLOAT(1.0f, g->up.y); /* zero up keeps the previous one */
    TEST_ASSERT_TRUE(g->step_height >= 0.0f && g->step_height <= 0.5f * g->height - g->radius);
    TEST_ASSERT_TRUE(g->floor_snap_distance >= g->step_height && isfinite(g->floor_snap_distance));
    TEST_ASSERT_TRUE(g->max_slides >= 1 && g->max_slides <= 8);
    TEST_ASSERT_TRUE(g->floor_max_angle <= 1.5708f);
    for (int i = 0; i < 20; i++) { CB_STEP(&body, DT); TEST_ASSERT_TRUE(cb_body_finite(&body)); }
    cb_report("zero-size body: foot height after 20 frames (floor 0)", char_body_foot_pos(&body).y, "m");
    TEST_ASSERT_TRUE(char_body_is_on_floor(&body));
    TEST_ASSERT_FLOAT_WITHIN(0.0001f, 0.0f, char_body_foot_pos(&body).y);
    s = CHAR_BODY_SETTINGS_DEFAULT;
    s.gravity = -5.0f;
    s.step_height = 5.0f;           /* > inner half height and > snap */
    s.max_slides = 200;
    s.up = cb_vec(0.0f, 3.0f, 4.0f);
    s.radius = NAN;
    char_body_configure(&body, &s);
    TEST_ASSERT_FLOAT_WITHIN(1e-6f, 0.6f, g->up.y);
    TEST_ASSERT_FLOAT_WITHIN(1e-6f, 0.8f, g->up.z);
    TEST_ASSERT_TRUE(g->step_height <= 0.5f + 1e-6f && g->step_height <= g->floor_snap_distance);
    TEST_ASSERT_EQUAL_UINT8(8, g->max_slides);
    TEST_ASSERT_TRUE(g->gravity >= 0.0f);
    TEST_ASSERT_TRUE(isfinite(g->radius) && g->radius > 0.0f);
    char_body_set_up(&body, cb_vec(0.0f, 0.0f, 0.0f));
    char_body_set_up(&body, cb_vec(NAN, 1.0f, 0.0f));
    TEST_ASSERT_FLOAT_WITHIN(1e-6f, 0.6f, g->up.y);
    /* defaults */
    char_body_init(&body, &pos);
    g = char_body_get_settings(&body);
    TEST_ASSERT_EQUAL_FLOAT(0.5f, g->radius);
    TEST_ASSERT_EQUAL_FLOAT(2.0f, g->height);
    TEST_ASSERT_EQUAL_FLOAT(0.25f, g->step_height);
    TEST_ASSERT_EQUAL_FLOAT(0.30f, g->floor_snap_distance);
    TEST_ASSERT_EQUAL_INT32(-1, char_body_floor_id(&body));
    TEST_ASSERT_FALSE(char_body_is_on_floor(&body));
    TEST_ASSERT_TRUE(sizeof(char_body_t) <= 256);
}

static void test_null_owner_and_null_scene(void)
{
    cb_level_floor(20.0f);
    TEST_ASSERT_NOT_NULL(cb_world_add_geo(1));
    char_body_init(&body, NULL);
    char_body_settings_t s = cb_foot_settings();
    char_body_configure(&body, &s);
    char_body_teleport(&body, cb_vec(0.0f, 0.5f, 0.0f), true);
    for (int i = 0; i < 20; i++) CB_STEP(&body, DT);
    TEST_ASSERT_TRUE(char_body_is_on_floor(&body));
    TEST_ASSERT_FLOAT_WITHIN(0.001f, 0.0f, char_body_foot_pos(&body).y);
    coll_scene_set_current(&cb_world.scene);
    ASSERT_NO_ALLOC(char_body_move_and_slide(&body, DT));
    TEST_ASSERT_TRUE(char_body_is_on_floor(&body));
    char_body_move_and_slide_in(&body, NULL, DT);  /* no scene: nothing happens */
    char_body_move_and_slide_in(NULL, &cb_world.scene, DT);
    TEST_ASSERT_FLOAT_WITHIN(0.001f, 0.0f, char_body_foot_pos(&body).y);
}

/* Small and large capsules rest against a wall where they should (the skin scales down). */
static void size_into_wall(float r, float h, float step, float snap, float wall_x, float speed)
{
    cb_world_reset();
    cb_level_floor(wall_x * 4.0f);
    cb_geo_box(cb_vec(wall_x + 0.5f, 20.0f, 0.0f), cb_vec(0.5f, 20.0f, wall_x * 4.0f), 0.0f);
    TEST_ASSERT_NOT_NULL(cb_world_add_geo(1));
    cb_body_init(&body, &pos, cb_vec(0.0f, 0.0f, 0.0f));
    char_body_settings_t s = CHAR_BODY_SETTINGS_DEFAULT;
    s.radius = r; s.height = h; s.step_height = step; s.floor_snap_distance = snap;
    s.center_offset = cb_vec(0.0f, 0.5f * h, 0.0f);
    char_body_configure(&body, &s);
    body.input_velocity = cb_vec(speed, 0.0f, 0.0f);
    float max_x = -1e9f;
    for (int i = 0; i < 120; i++) {
        CB_STEP(&body, DT);
        if (pos.x > max_x) max_x = pos.x;
        TEST_ASSERT_TRUE(char_body_is_on_floor(&body));
    }
    float err = (wall_x - r - pos.x) / r;
    char name[96];
    snprintf(name, sizeof name, "radius %.2f m into a wall: rest gap relative to r", r);
    cb_report(name, err, "");
    TEST_ASSERT_TRUE(err >= 0.0f && err < 0.02f);
    TEST_ASSERT_TRUE(max_x <= wall_x - r);
}
static void test_tiny_and_huge_capsules(void)
{
    size_into_wall(0.02f, 0.08f, 0.01f, 0.02f, 0.5f, 0.3f);
    size_into_wall(10.0f, 40.0f, 0.25f, 0.30f, 40.0f, 12.0f);
}

/* 18. Debug draw: colours per state, capsule along a non-Y up. */
typedef struct { fm_vec3_t a, b; uint32_t c; } dl_t;
static dl_t lines[512];
static int nlines;
static void rec(void *user, fm_vec3_t a, fm_vec3_t b, uint32_t rgba)
{
    (void)user;
    if (nlines < 512) { lines[nlines].a = a; lines[nlines].b = b; lines[nlines].c = rgba; nlines++; }
}
static int count(uint32_t c)
{
    int n = 0;
    for (int i = 0; i < nlines; i++) n += lines[i].c == c;
    return n;
}
static void draw(void)
{
    coll_debug_draw_t dd = {rec, NULL};
    nlines = 0;
    char_body_debug_draw(&body, &dd);
}
/* Distance of p from the segment c +- up * h. */
static float seg_dist(fm_vec3_t p, fm_vec3_t c, fm_vec3_t up, float h)
{
    fm_vec3_t d = cb_vec(p.x - c.x, p.y - c.y, p.z - c.z);
    float t = d.x * up.x + d.y * up.y + d.z * up.z;
    t = t < -h ? -h : (t > h ? h : t);
    fm_vec3_t q = cb_vec(d.x - up.x * t, d.y - up.y * t, d.z - up.z * t);
    return sqrtf(q.x * q.x + q.y * q.y + q.z * q.z);
}

static void test_debug_draw_colours(void)
{
    const float t50 = tanf(50.0f * 3.14159265f / 180.0f);
    const float xs[4] = {-20.0f, 10.0f, 10.0f + 10.0f, 10.0f + 20.0f};
    const float ys[4] = {0.0f, 0.0f, 10.0f * t50, 10.0f * t50};
    cb_geo_profile(xs, ys, 4, -10.0f, 10.0f);
    TEST_ASSERT_NOT_NULL(cb_world_add_geo(1));
    cb_body_init(&body, &pos, cb_vec(0.0f, 3.0f, 0.0f));
    CB_STEP(&body, DT);
    draw();
    int full = count(CHAR_BODY_COLOR_FULL);
    cb_report("debug draw: lines per frame", nlines, "");
    TEST_ASSERT_TRUE(count(CHAR_BODY_COLOR_AIRBORNE) > 8);
    TEST_ASSERT_EQUAL_INT(full, count(CHAR_BODY_COLOR_AIRBORNE)); /* same wireframe, state colour */
    TEST_ASSERT_EQUAL_INT(0, count(CHAR_BODY_COLOR_FLOOR));
    TEST_ASSERT_EQUAL_INT(0, count(CHAR_BODY_COLOR_NORMAL));
    TEST_ASSERT_TRUE(count(CHAR_BODY_COLOR_STEP_ZONE) >= 1);
    TEST_ASSERT_EQUAL_INT(1, count(CHAR_BODY_COLOR_PROBE));
    for (int i = 0; i < 60 && !char_body_is_on_floor(&body); i++) CB_STEP(&body, DT);
    draw();
    TEST_ASSERT_EQUAL_INT(full, count(CHAR_BODY_COLOR_FLOOR));
    TEST_ASSERT_EQUAL_INT(0, count(CHAR_BODY_COLOR_AIRBORNE));
    TEST_ASSERT_EQUAL_INT(1, count(CHAR_BODY_COLOR_NORMAL));
    /* the probe line runs from the capsule centre down past the foot by the snap distance */
    for (int i = 0; i < nlines; i++)
        if (lines[i].c == CHAR_BODY_COLOR_PROBE) {
            TEST_ASSERT_FLOAT_WITHIN(1e-5f, pos.y + 1.0f, lines[i].a.y);
            TEST_ASSERT_FLOAT_WITHIN(1e-5f, pos.y - 0.3f, lines[i].b.y);
        }
    /* steep: onto the 50 degree slope */
    char_body_teleport(&body, cb_vec(14.0f, 4.0f * t50 + 0.02f, 0.0f), true);
    for (int i = 0; i < 5; i++) CB_STEP(&body, DT);
    TEST_ASSERT_TRUE(char_body_is_on_steep_surface(&body));
    draw();
    TEST_ASSERT_EQUAL_INT(full, count(CHAR_BODY_COLOR_STEEP));
    TEST_ASSERT_EQUAL_INT(0, count(CHAR_BODY_COLOR_FLOOR));
}

static void test_debug_draw_follows_up(void)
{
    char_body_init(&body, &pos);
    pos = cb_vec(1.0f, 2.0f, 3.0f);
    char_body_set_up(&body, cb_vec(1.0f, 1.0f, 0.0f));
    fm_vec3_t up = char_body_get_settings(&body)->up;
    draw();
    int checked = 0;
    float worst_full = 0.0f, worst_sweep = 0.0f;
    /* full capsule: centre = pos (zero offset), inner half height 0.5; sweep capsule raised by
     * step/2 with inner half height 0.5 - step/2 */
    fm_vec3_t sc = cb_vec(pos.x + up.x * 0.125f, pos.y + up.y * 0.125f, pos.z + up.z * 0.125f);
    for (int i = 0; i < nlines; i++) {
        if (lines[i].c == CHAR_BODY_COLOR_FULL) {
            float e = fmaxf(fabsf(seg_dist(lines[i].a, pos, up, 0.5f) - 0.5f), fabsf(seg_dist(lines[i].b, pos, up, 0.5f) - 0.5f));
            if (e > worst_full) worst_full = e;
            checked++;
        } else if (lines[i].c == CHAR_BODY_COLOR_AIRBORNE) {
            float e = fmaxf(fabsf(seg_dist(lines[i].a, sc, up, 0.375f) - 0.5f), fabsf(seg_dist(lines[i].b, sc, up, 0.375f) - 0.5f));
            if (e > worst_sweep) worst_sweep = e;
            checked++;
        }
    }
    cb_report("debug draw (up = (1,1,0)/sqrt2): full capsule line end off its surface", worst_full, "m");
    cb_report("debug draw (up = (1,1,0)/sqrt2): sweep capsule line end off its surface", worst_sweep, "m");
    TEST_ASSERT_TRUE(checked > 20);
    TEST_ASSERT_TRUE(worst_full < 1e-5f);
    TEST_ASSERT_TRUE(worst_sweep < 1e-5f);
    /* the capsule reaches along up: the furthest drawn point is 1 m along up from the centre */
    float reach = 0.0f;
    for (int i = 0; i < nlines; i++) {
        if (lines[i].c != CHAR_BODY_COLOR_FULL) continue;
        fm_vec3_t d = cb_vec(lines[i].a.x - pos.x, lines[i].a.y - pos.y, lines[i].a.z - pos.z);
        float t = d.x * up.x + d.y * up.y + d.z * up.z;
        if (t > reach) reach = t;
    }
    TEST_ASSERT_FLOAT_WITHIN(1e-5f, 1.0f, reach);
    char_body_debug_draw(&body, NULL);
    char_body_debug_draw(NULL, NULL);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_fall_onto_single_triangle);
    RUN_TEST(test_fall_onto_thin_slab_and_wall);
    RUN_TEST(test_bad_dt);
    RUN_TEST(test_bad_velocities_and_walls);
    RUN_TEST(test_settings_clamped);
    RUN_TEST(test_null_owner_and_null_scene);
    RUN_TEST(test_tiny_and_huge_capsules);
    RUN_TEST(test_debug_draw_colours);
    RUN_TEST(test_debug_draw_follows_up);
    return UNITY_END();
}
