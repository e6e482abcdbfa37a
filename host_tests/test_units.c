/* Any length unit: the same course in metres and scaled by S (centimetres: S = 100, every
 * length, speed and acceleration x 100; millimetres: S = 1000; decimetres the other way:
 * S = 0.1) gives the same motion, scaled. Each frame the scaled run's foot position / S is
 * within 1 mm per metre travelled (at least 1 mm) of the metres run's, and both agree on
 * the ground state (airborne, on a floor, on a steep surface). The scaled runs set
 * settings.units_per_meter = S; nothing else differs. At 128 units a metre (a power of two
 * scales every float operation exactly) the runs must be bit-identical, scaled, but for the
 * one course the primitives' absolute touch tolerance decides.
 * Every step runs under the allocation guard (CB_STEP). -DUNITS_BEFORE builds it against a
 * library without the setting (how the numbers before it were measured). */
#include "unity.h"
#include "alloc_guard.h"
#include "cb_levels.h"
#include <math.h>
#include <stdio.h>

void setUp(void) { cb_world_reset(); }
void tearDown(void) {}

#define HZ 60.0f
#define MAX_FRAMES 600

/* ---- the level, every length times S ---- */

static float S = 1.0f;
static fm_vec3_t sv(float x, float y, float z) { return cb_vec(x * S, y * S, z * S); }

static void box(float cx, float cy, float cz, float hx, float hy, float hz, float yaw)
{
    cb_geo_box(sv(cx, cy, cz), sv(hx, hy, hz), yaw);
}

static void profile(const float *xs, const float *ys, int n, float z0, float z1)
{
    float x[32], y[32];
    for (int i = 0; i < n && i < 32; i++) { x[i] = xs[i] * S; y[i] = ys[i] * S; }
    cb_geo_profile(x, y, n, z0 * S, z1 * S);
}

static coll_mesh_instance_t *platform;

/* The moving platform's position at time t (metres): 4 m across x and back, 2 m/s. */
static fm_vec3_t platform_at(float t)
{
    float ph = fmodf(t, 4.0f);
    float x = ph < 2.0f ? 2.0f * ph : 8.0f - 2.0f * ph;
    return sv(30.0f + x, 0.0f, -30.0f);
}

static void build_level(void)
{
    cb_world_reset();
    /* ground: 120 m square slab, top at y = 0 */
    box(0.0f, -0.5f, 0.0f, 60.0f, 0.5f, 60.0f, 0.0f);
    /* a long wall, face at z = 5, x in [-20, 20] */
    box(0.0f, 1.5f, 5.25f, 20.0f, 1.5f, 0.25f, 0.0f);
    /* an acute V corner (a crease) opening towards -x, apex near (40, 0, 20) */
    box(36.0f, 1.5f, 18.0f, 4.5f, 1.5f, 0.25f, 0.45f);
    box(36.0f, 1.5f, 22.0f, 4.5f, 1.5f, 0.25f, -0.45f);
    /* ramp up (26.6 deg) to a 3 m high top, then a ledge: z in [-20, -10] */
    {
        const float xs[] = {0.0f, 6.0f, 10.0f, 10.0f}, ys[] = {0.0f, 3.0f, 3.0f, 0.0f};
        profile(xs, ys, 4, -20.0f, -10.0f);
    }
    /* a steep 60 deg slope facing +x, from 5.8 m down to a 0.6 m lip over the ground (its
     * toe on the ground would be a wedge whose outcome turns on rounding, in metres alone):
     * z in [-40, -30], x in [-30, -27] */
    {
        const float xs[] = {-30.0f, -30.0f, -27.0f, -27.0f}, ys[] = {0.0f, 5.796f, 0.6f, 0.0f};
        profile(xs, ys, 4, -40.0f, -30.0f);
    }
    /* stairs: 8 risers of 0.2 m, treads 0.35 m, a landing to x = 10, then a drop: z in [10, 20] */
    {
        float xs[20], ys[20];
        int n = 0;
        for (int k = 0; k < 8; k++) {
            xs[n] = 0.35f * (float)k; ys[n++] = 0.2f * (float)k;
            xs[n] = 0.35f * (float)k; ys[n++] = 0.2f * (float)(k + 1);
        }
        xs[n] = 10.0f; ys[n++] = 1.6f;
        xs[n] = 10.0f; ys[n++] = 0.0f;
        profile(xs, ys, n, 10.0f, 20.0f);
    }
    /* kerbs around step_height (0.25 m), z in [37, 43]: 0.245 m, and 0.26 m, which is within
     * CB_MARGIN (1 cm) of the step zone: its edge counts as in it, so it is climbed too */
    box(-10.0f, 0.1225f, 40.0f, 2.0f, 0.1225f, 3.0f, 0.0f);
    box(0.0f, 0.13f, 40.0f, 2.0f, 0.13f, 3.0f, 0.0f);
    TEST_ASSERT_NOT_NULL(cb_world_add_geo(1));
    /* a moving platform (its own instance): 4 x 0.5 x 4 m, top 0.5 m above the ground */
    box(0.0f, 0.25f, 0.0f, 2.0f, 0.25f, 2.0f, 0.0f);
    const coll_mesh_t *m = cb_geo_end();
    TEST_ASSERT_NOT_NULL(m);
    coll_transform_t xf = COLL_TRANSFORM_IDENTITY;
    xf.pos = platform_at(0.0f);
    platform = cb_world_add_mesh(m, xf, 2);
    TEST_ASSERT_NOT_NULL(platform);
}

/* ---- the scripted runs ---- */

typedef struct {
    const char *name;
    float start[3];        ///< foot position, m
    int frames;
    /** Input (m/s) and a jump (set velocity up, m/s; 0: none) at frame f. */
    void (*script)(int f, float in[3], float *jump);
} course_t;

static void walk_wall(int f, float in[3], float *jump)
{
    /* into the wall at an angle (slides along it), then a jump while sliding */
    in[0] = 4.0f; in[1] = 0.0f; in[2] = 3.0f;
    *jump = (f == 150) ? 7.0f : 0.0f;
}
static void crease(int f, float in[3], float *jump)
{
    (void)f;
    in[0] = 5.0f; in[1] = 0.0f; in[2] = 0.3f;
    *jump = 0.0f;
}
static void ramp_ledge(int f, float in[3], float *jump)
{
    /* up the ramp, over its top, off the ledge, land; then back and jump onto it */
    in[0] = f < 200 ? 5.0f : -5.0f; in[1] = 0.0f; in[2] = 0.0f;
    *jump = (f == 300) ? 9.0f : 0.0f;
}
static void steep(int f, float in[3], float *jump)
{
    /* jump onto the steep slope, push into it, slide down it and off its lip, walk away */
    in[0] = f < 120 ? -4.0f : 1.0f; in[1] = 0.0f; in[2] = 0.37f;
    *jump = (f == 5) ? 10.0f : 0.0f;
}
static void stairs(int f, float in[3], float *jump)
{
    in[0] = f < 260 ? 3.0f : -3.0f; in[1] = 0.0f; in[2] = 0.2f;
    *jump = 0.0f;
}
static void hops(int f, float in[3], float *jump)
{
    in[0] = 3.0f * cosf(0.01f * (float)f); in[1] = 0.0f; in[2] = 3.0f * sinf(0.01f * (float)f);
    *jump = (f % 50 == 5) ? 6.0f : 0.0f;
}
static void kerbs(int f, float in[3], float *jump)
{
    /* onto the low kerb, off it, onto the high one at an angle */
    in[0] = 3.0f; in[1] = 0.0f; in[2] = f < 150 ? 0.4f : 1.5f;
    *jump = 0.0f;
}
static void ride(int f, float in[3], float *jump)
{
    /* stand on the moving platform, walk across it, jump off it */
    in[0] = 0.0f; in[1] = 0.0f; in[2] = f > 200 ? 0.8f : 0.0f;
    *jump = (f == 300) ? 6.0f : 0.0f;
}

/* Start points are off the round numbers the level and the speeds are made of: a foot
 * exactly at an edge at the end of a frame (-0.0 in one run, +0.0 in the other) decides
 * that frame by rounding, in metres alone as much as between units. */
static const course_t courses[] = {
    {"walk and wall slide", {-10.0f, 0.0f, 2.0093f}, 240, walk_wall},
    {"crease", {28.0f, 0.0f, 20.0f}, 180, crease},
    {"slope and ledge fall", {-3.0137f, 0.0f, -15.0f}, 420, ramp_ledge},
    {"steep slope", {-25.2f, 0.0f, -35.0f}, 240, steep},
    {"stairs", {-2.0071f, 0.0f, 15.0f}, 480, stairs},
    {"jump and land", {-20.0f, 0.0f, 30.0f}, 400, hops},
    {"kerbs", {-14.0071f, 0.0f, 38.0f}, 300, kerbs},
    {"moving platform", {30.0f, 0.5f, -30.0113f}, 420, ride},
};
#define NCOURSES (int)(sizeof courses / sizeof courses[0])

typedef struct {
    fm_vec3_t p[MAX_FRAMES]; ///< foot, in metres (divided by S)
    uint8_t state[MAX_FRAMES]; ///< char_body_ground_state()
} track_t;

static char_body_t body;
static fm_vec3_t pos;
static track_t ref_track, got_track;

/* Runs course c with every length times `scale`; fills tr in metres. */
static void run(const course_t *c, float scale, track_t *tr)
{
    S = scale;
    build_level();
    char_body_settings_t s = CHAR_BODY_SETTINGS_DEFAULT;
    s.radius *= S;
    s.height *= S;
    s.step_height *= S;
    s.floor_snap_distance *= S;
    s.gravity *= S;
    s.max_fall_speed *= S;
    s.center_offset = cb_vec(0.0f, 0.5f * s.height, 0.0f);
#ifndef UNITS_BEFORE
    s.units_per_meter = S;
#endif
    pos = sv(c->start[0], c->start[1], c->start[2]);
    char_body_init(&body, &pos);
    char_body_configure(&body, &s);
    const float dt = 1.0f / HZ;
    float t = 0.0f;
    TEST_ASSERT_TRUE(c->frames <= MAX_FRAMES);
    for (int f = 0; f < c->frames; f++) {
        float in[3], jump;
        c->script(f, in, &jump);
        body.input_velocity = sv(in[0], in[1], in[2]);
        if (jump > 0.0f && char_body_is_on_floor(&body)) {
            fm_vec3_t v = char_body_get_velocity(&body);
            v.y = jump * S;
            char_body_set_velocity(&body, v);
        }
        t += dt;
        platform->xf.pos = platform_at(t);
        CB_STEP(&body, dt);
        TEST_ASSERT_TRUE(cb_body_finite(&body));
        fm_vec3_t foot = char_body_foot_pos(&body);
        tr->p[f] = cb_vec(foot.x / S, foot.y / S, foot.z / S);
        tr->state[f] = (uint8_t)char_body_ground_state(&body);
    }
    S = 1.0f;
}

static float dist(fm_vec3_t a, fm_vec3_t b)
{
    float dx = a.x - b.x, dy = a.y - b.y, dz = a.z - b.z;
    return sqrtf(dx * dx + dy * dy + dz * dz);
}

/* Course c at scale against metres: the worst error over (1 mm + 1 mm per metre travelled),
 * <= 1 passes; the frames whose ground state differs are counted. */
static float compare(const course_t *c, float scale, int *floor_diff, float *worst_m, float *travelled)
{
    run(c, 1.0f, &ref_track);
    run(c, scale, &got_track);
    float walked = 0.0f, worst = 0.0f, worst_abs = 0.0f;
    int diff = 0;
    fm_vec3_t prev = sv(c->start[0], c->start[1], c->start[2]);
    for (int f = 0; f < c->frames; f++) {
        walked += dist(ref_track.p[f], prev);
        prev = ref_track.p[f];
        float e = dist(ref_track.p[f], got_track.p[f]);
        float ratio = e / (0.001f + 0.001f * walked);
        if (ratio > worst) worst = ratio;
        if (e > worst_abs) worst_abs = e;
        if (ref_track.state[f] != got_track.state[f]) diff++;
    }
    *floor_diff = diff;
    *worst_m = worst_abs;
    *travelled = walked;
    return worst;
}

static void check_scale(float scale, const char *unit)
{
    bool ok = true;
    for (int i = 0; i < NCOURSES; i++) {
        int fd;
        float worst_m, walked;
        float ratio = compare(&courses[i], scale, &fd, &worst_m, &walked);
        char label[128];
        snprintf(label, sizeof label, "%s in %s: worst distance from the metres run (over %.1f m)", courses[i].name,
                 unit, (double)walked);
        cb_report(label, worst_m, "m");
        snprintf(label, sizeof label, "%s in %s: frames standing differently", courses[i].name, unit);
        cb_report(label, fd, "frames");
        if (!(ratio <= 1.0f) || fd != 0) {
            printf("  FAIL %s in %s: error %.2f x (1 mm + 1 mm/m), %d frames differ\n", courses[i].name, unit,
                   (double)ratio, fd);
            ok = false;
        }
    }
    TEST_ASSERT_TRUE_MESSAGE(ok, "a scaled course moved differently from the metres one");
}

/* The courses do what they are meant to (in metres): a test of the comparison's reach. */
static void test_courses_exercise_the_features(void)
{
    /* wall slide: stopped at the wall, still moving along it */
    run(&courses[0], 1.0f, &ref_track);
    TEST_ASSERT_TRUE(ref_track.p[100].z > 4.4f && ref_track.p[100].z < 4.6f);
    TEST_ASSERT_TRUE(ref_track.p[140].x - ref_track.p[100].x > 2.0f);
    /* slope and ledge: up 3 m, off the ledge, down on the ground again */
    run(&courses[2], 1.0f, &ref_track);
    float top = 0.0f;
    for (int f = 0; f < 200; f++) if (ref_track.p[f].y > top) top = ref_track.p[f].y;
    TEST_ASSERT_TRUE(top > 2.9f);
    TEST_ASSERT_TRUE(ref_track.p[199].x > 11.0f && fabsf(ref_track.p[199].y) < 0.01f);
    /* steep slope: stood on it (sliding) for a while, then back on the ground */
    run(&courses[3], 1.0f, &ref_track);
    int steep = 0;
    for (int f = 0; f < courses[3].frames; f++) steep += ref_track.state[f] == CHAR_BODY_ON_STEEP;
    TEST_ASSERT_TRUE(steep >= 3);
    TEST_ASSERT_EQUAL_INT(CHAR_BODY_ON_FLOOR, ref_track.state[courses[3].frames - 1]);
    /* stairs: climbed to the landing */
    run(&courses[4], 1.0f, &ref_track);
    TEST_ASSERT_FLOAT_WITHIN(0.01f, 1.6f, ref_track.p[200].y);
    /* kerbs: both climbed */
    run(&courses[6], 1.0f, &ref_track);
    TEST_ASSERT_FLOAT_WITHIN(0.002f, 0.245f, ref_track.p[60].y);
    TEST_ASSERT_FLOAT_WITHIN(0.002f, 0.26f, ref_track.p[280].y);
    /* moving platform: carried (x changes while the input is zero) */
    run(&courses[7], 1.0f, &ref_track);
    TEST_ASSERT_TRUE(fabsf(ref_track.p[100].x - ref_track.p[10].x) > 1.0f);
    TEST_ASSERT_EQUAL_INT(CHAR_BODY_ON_FLOOR, ref_track.state[100]);
}

/* The setting itself: bad values mean metres, the clamps and fallbacks scale with it, and a
 * centimetre body is not slowed to 200 units/s (the "half speed"). */
static void test_unit_setting_and_clamps(void)
{
#ifdef UNITS_BEFORE
    TEST_IGNORE_MESSAGE("library without units_per_meter");
#else
    char_body_settings_t s = CHAR_BODY_SETTINGS_DEFAULT;
    TEST_ASSERT_EQUAL_FLOAT(1.0f, s.units_per_meter);
    const float bad[] = {0.0f, -100.0f, NAN, INFINITY};
    for (int i = 0; i < 4; i++) {
        s = CHAR_BODY_SETTINGS_DEFAULT;
        s.units_per_meter = bad[i];
        s.gravity = 5000.0f;
        char_body_init(&body, &pos);
        char_body_configure(&body, &s);
        TEST_ASSERT_EQUAL_FLOAT(1.0f, char_body_get_settings(&body)->units_per_meter);
        TEST_ASSERT_EQUAL_FLOAT(1000.0f, char_body_get_settings(&body)->gravity);
    }
    /* metres: a centimetre game that forgot the setting is clamped (as before) */
    s = CHAR_BODY_SETTINGS_DEFAULT;
    s.gravity = 3000.0f; s.max_fall_speed = 5500.0f; s.radius = 50.0f; s.height = 200.0f;
    char_body_configure(&body, &s);
    TEST_ASSERT_EQUAL_FLOAT(1000.0f, char_body_get_settings(&body)->gravity);
    TEST_ASSERT_EQUAL_FLOAT(200.0f, char_body_get_settings(&body)->max_fall_speed);
    /* centimetres: nothing clamped; NaN falls back to the seed's defaults in centimetres */
    s.units_per_meter = 100.0f;
    char_body_configure(&body, &s);
    TEST_ASSERT_EQUAL_FLOAT(3000.0f, char_body_get_settings(&body)->gravity);
    TEST_ASSERT_EQUAL_FLOAT(5500.0f, char_body_get_settings(&body)->max_fall_speed);
    s.units_per_meter = 1e6f; /* clamped to 1e4 */
    char_body_configure(&body, &s);
    TEST_ASSERT_EQUAL_FLOAT(1e4f, char_body_get_settings(&body)->units_per_meter);
    s.units_per_meter = 100.0f;
    s.gravity = NAN; s.radius = NAN; s.height = NAN; s.floor_snap_distance = NAN;
    char_body_configure(&body, &s);
    TEST_ASSERT_EQUAL_FLOAT(3000.0f, char_body_get_settings(&body)->gravity);
    TEST_ASSERT_EQUAL_FLOAT(50.0f, char_body_get_settings(&body)->radius);
    TEST_ASSERT_EQUAL_FLOAT(100.0f, char_body_get_settings(&body)->height);
    TEST_ASSERT_EQUAL_FLOAT(30.0f, char_body_get_settings(&body)->floor_snap_distance);
    /* 10 m/s in centimetres on a flat floor: 1000 units/s, not 200 */
    S = 100.0f;
    build_level();
    cb_body_init(&body, &pos, sv(-20.0f, 0.0f, -50.0f));
    s = *char_body_get_settings(&body);
    s.units_per_meter = 100.0f; s.radius = 50.0f; s.height = 200.0f; s.center_offset = cb_vec(0.0f, 100.0f, 0.0f);
    s.step_height = 25.0f; s.floor_snap_distance = 30.0f; s.gravity = 3000.0f; s.max_fall_speed = 5500.0f;
    char_body_configure(&body, &s);
    for (int f = 0; f < 60; f++) {
        body.input_velocity = cb_vec(1000.0f, 0.0f, 0.0f);
        CB_STEP(&body, 1.0f / HZ);
    }
    S = 1.0f;
    TEST_ASSERT_TRUE(char_body_is_on_floor(&body));
    TEST_ASSERT_FLOAT_WITHIN(1.0f, -1000.0f, pos.x); /* 10 m in 1 s: from -20 m to -10 m */
    TEST_ASSERT_FLOAT_WITHIN(1.0f, 1000.0f, char_body_get_velocity(&body).x);
#endif
}

/* A power-of-two unit (128 units a metre) scales every float operation exactly: every
 * course moves bit for bit the same, scaled, except where the primitives' touch tolerance
 * (COLL_PRIM_TOUCH_TOL, absolute: docs/ARCHITECTURE.md) decides, which is only the crease
 * (there it is held to the 1 mm per metre). Any body tolerance left in metres that the
 * courses meet shows here as a difference, however small. */
static void test_power_of_two_unit_is_exact(void)
{
#ifdef UNITS_BEFORE
    TEST_IGNORE_MESSAGE("library without units_per_meter");
#else
    bool ok = true;
    for (int i = 0; i < NCOURSES; i++) {
        int fd;
        float worst_m, walked;
        float ratio = compare(&courses[i], 128.0f, &fd, &worst_m, &walked);
        bool exact = true;
        for (int f = 0; f < courses[i].frames; f++)
            exact = exact && ref_track.p[f].x == got_track.p[f].x && ref_track.p[f].y == got_track.p[f].y &&
                    ref_track.p[f].z == got_track.p[f].z && ref_track.state[f] == got_track.state[f];
        char label[128];
        snprintf(label, sizeof label, "%s at 128 units a metre: worst distance from the metres run", courses[i].name);
        cb_report(label, worst_m, "m");
        bool is_crease = courses[i].script == crease;
        if (is_crease ? !(ratio <= 1.0f) || fd != 0 : !exact) {
            printf("  FAIL %s at 128 units a metre: not %s (worst %.3g m)\n", courses[i].name,
                   is_crease ? "within 1 mm per metre" : "bit-exact", (double)worst_m);
            ok = false;
        }
    }
    TEST_ASSERT_TRUE_MESSAGE(ok, "a power-of-two unit changed the motion");
#endif
}

static void test_same_course_in_centimetres(void) { check_scale(100.0f, "centimetres"); }
static void test_same_course_in_millimetres(void) { check_scale(1000.0f, "millimetres"); }
static void test_same_course_in_decimetres_per_ten(void) { check_scale(0.1f, "tens of metres"); }

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_courses_exercise_the_features);
    RUN_TEST(test_unit_setting_and_clamps);
    RUN_TEST(test_power_of_two_unit_is_exact);
    RUN_TEST(test_same_course_in_centimetres);
    RUN_TEST(test_same_course_in_millimetres);
    RUN_TEST(test_same_course_in_decimetres_per_ten);
    return UNITY_END();
}
