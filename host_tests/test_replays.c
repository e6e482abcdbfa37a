/* Regression replays: every host_tests/replays/NAME.replay (found from the repo root, the
 * test runner's working directory) is replayed with the double-precision property checker
 * on every frame; it must show no hard failure and end in the stored final state for this
 * architecture (bitwise), or, for an architecture without a stored state, within a
 * tolerance of another architecture's. host_tests/replays/open/ holds replays of still-open
 * bugs: they are only parsed here, not run. Also tests the checker itself. */
#define _FILE_OFFSET_BITS 64 /* 32-bit MIPS under qemu: readdir with 64-bit directory offsets */
#include "unity.h"
#include "soak_sim.h"
#include "coll/char_body_internal.h" /* CB_FLAG_*: to fake states a buggy step could leave */
#include <dirent.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#define REPLAY_DIR "host_tests/replays"
#define MAX_FRAMES (1u << 15)
/* Across architectures (no stored state for this one): positions within this, m. */
#define CROSS_ARCH_TOL 0.05f

static soak_level_t lvl;
static soak_frame_t frames[MAX_FRAMES];
static int stale; /* replays whose stored state is from another library version */

void setUp(void) {}
void tearDown(void) {}

/* ---------------------------------------------------------------- the checker itself */

static void test_checker_segment_triangle_distance(void)
{
    double a[3] = {0, 0, 0}, b[3] = {2, 0, 0}, c[3] = {0, 0, 2};
    double p0[3] = {0.5, 1, 0.5}, p1[3] = {0.5, 3, 0.5};
    TEST_ASSERT_DOUBLE_WITHIN(1e-12, 1.0, soak_seg_tri_dist(p0, p1, a, b, c));   /* above the face */
    double q0[3] = {0.5, -1, 0.5}, q1[3] = {0.5, 1, 0.5};
    TEST_ASSERT_DOUBLE_WITHIN(1e-12, 0.0, soak_seg_tri_dist(q0, q1, a, b, c));   /* through it */
    double r0[3] = {3, 0, -1}, r1[3] = {3, 0, 1};
    TEST_ASSERT_DOUBLE_WITHIN(1e-12, 1.0, soak_seg_tri_dist(r0, r1, a, b, c));   /* beside a vertex */
    double s0[3] = {-1, 1, -1}, s1[3] = {-1, 1, 3};
    TEST_ASSERT_DOUBLE_WITHIN(1e-12, sqrt(2.0), soak_seg_tri_dist(s0, s1, a, b, c)); /* along an edge */
    double t0[3] = {1, 0, -1}, t1[3] = {1, 0, 3};
    TEST_ASSERT_DOUBLE_WITHIN(1e-12, 0.0, soak_seg_tri_dist(t0, t1, a, b, c));   /* coplanar crossing */
}

/* A capsule placed into the room's floor or wall is caught with the right depth, one
 * placed clear of it is not, and the floor reach is measured from the full capsule. */
static void test_checker_sees_penetration_and_floor_reach(void)
{
    TEST_ASSERT_EQUAL_INT(0, soak_level_generate(&lvl, 3));
    lvl.nwtris = lvl.pieces[0].ntris; /* the room only: piece 0's triangles come first */
    lvl.npieces = 1;
    lvl.nbodies = 0;
    static char_body_t body;
    fm_vec3_t owner = {{0.0f, 0.0f, 0.0f}};
    char_body_init(&body, &owner);
    char_body_settings_t s = CHAR_BODY_SETTINGS_DEFAULT; /* r 0.5, height 2, step 0.25 */
    s.center_offset.y = 1.0f;                              /* foot at the owner origin */
    char_body_configure(&body, &s);
    soak_capsule_t full, sweep;
    int32_t tri = -1;
    double raw = 0;

    owner.x = 0.0f; owner.y = 0.5f; owner.z = -23.7f;       /* 0.3 m from the wall z = -24 */
    soak_body_capsules(&body, &full, &sweep);
    TEST_ASSERT_DOUBLE_WITHIN(1e-5, 0.2, soak_check_static_pen(&lvl, &body.settings, &sweep, &tri, &raw));
    TEST_ASSERT_TRUE(tri >= 0);

    owner.z = -20.0f; owner.y = -0.05f;   /* sweep capsule bottom 0.2 m above the floor */
    soak_body_capsules(&body, &full, &sweep);
    TEST_ASSERT_DOUBLE_WITHIN(1e-9, 0.0, soak_check_static_pen(&lvl, &body.settings, &sweep, &tri, &raw));
    TEST_ASSERT_DOUBLE_WITHIN(1e-5, -0.05, soak_check_nearest(&lvl, &body.settings, &full));

    owner.y = -0.4f;                      /* sweep capsule 15 cm into the floor */
    soak_body_capsules(&body, &full, &sweep);
    TEST_ASSERT_DOUBLE_WITHIN(1e-5, 0.15, soak_check_static_pen(&lvl, &body.settings, &sweep, &tri, &raw));

    owner.y = 3.0f;                       /* foot 3 m above the floor */
    soak_body_capsules(&body, &full, &sweep);
    TEST_ASSERT_DOUBLE_WITHIN(1e-5, 3.0, soak_check_nearest(&lvl, &body.settings, &full));
}

/* soak_sim_check flags each bad state it is shown (the body's private flags are set by
 * hand, as a buggy step could leave them), and excuses what it should. */
static void test_checker_flags_bad_body_states(void)
{
    static soak_sim_t sim;
    TEST_ASSERT_EQUAL_INT(0, soak_level_generate(&lvl, 3));
    lvl.nwtris = lvl.pieces[0].ntris; /* the room only */
    lvl.npieces = 1;
    lvl.nbodies = 0;
    char_body_settings_t s = CHAR_BODY_SETTINGS_DEFAULT; /* r 0.5, height 2, step 0.25, snap 0.3 */
    s.center_offset.y = 1.0f;                              /* foot at the owner origin */
    fm_vec3_t start = {{0.0f, 0.0f, 0.0f}};
    soak_sim_begin(&sim, &lvl, &s, start);
    sim.excused = false;
    char_body_t *b = &sim.body;
    fm_vec3_t up = {{0.0f, 1.0f, 0.0f}};

    /* standing 0.2 m above the floor, snap 0.3: fine */
    sim.owner.y = 0.2f;
    b->flags = CB_FLAG_GROUNDED; b->floor_id = 1; b->floor_normal = up;
    TEST_ASSERT_EQUAL_INT(SOAK_FAIL_NONE, soak_sim_check(&sim, false, true));
    /* "on floor" 5 m up */
    sim.owner.y = 5.0f;
    TEST_ASSERT_EQUAL_INT(SOAK_FAIL_FLOOR, soak_sim_check(&sim, false, true));
    /* ... unless the step did not run (stale state after dt <= 0) */
    TEST_ASSERT_EQUAL_INT(SOAK_FAIL_NONE, soak_sim_check(&sim, false, false));
    /* on the floor with no floor id, or not on it with one */
    sim.owner.y = 0.0f;
    b->floor_id = -1;
    TEST_ASSERT_EQUAL_INT(SOAK_FAIL_STATE, soak_sim_check(&sim, false, true));
    b->flags = 0; b->floor_id = 1;
    TEST_ASSERT_EQUAL_INT(SOAK_FAIL_STATE, soak_sim_check(&sim, false, true));
    b->floor_id = -1;
    TEST_ASSERT_EQUAL_INT(SOAK_FAIL_NONE, soak_sim_check(&sim, false, true));
    /* sweep capsule 15 cm into the floor: a failure, or excused after a teleport */
    sim.owner.y = -0.4f;
    TEST_ASSERT_EQUAL_INT(SOAK_FAIL_PENETRATION, soak_sim_check(&sim, false, true));
    uint64_t soft = sim.st.soft_pen_frames;
    TEST_ASSERT_EQUAL_INT(SOAK_FAIL_NONE, soak_sim_check(&sim, true, true));
    TEST_ASSERT_TRUE(sim.st.soft_pen_frames == soft + 1); /* no 64-bit asserts on 32-bit MIPS */
    /* below the lowest floor: an escape, not excused once clear of the overlap state */
    sim.excused = false;
    sim.owner.y = -3.0f;
    TEST_ASSERT_EQUAL_INT(SOAK_FAIL_ESCAPE, soak_sim_check(&sim, false, true));
    sim.owner.y = 0.0f;
    sim.owner.x = NAN;
    TEST_ASSERT_EQUAL_INT(SOAK_FAIL_NONFINITE, soak_sim_check(&sim, false, true));
    sim.owner.x = 0.0f;
    b->velocity.z = INFINITY;
    TEST_ASSERT_EQUAL_INT(SOAK_FAIL_NONFINITE, soak_sim_check(&sim, false, true));
}

/* The walkable-slope allowance: a ball whose foot point stands on a 40-degree ramp with a
 * step too small for the seed's rule is tolerated exactly r - (r + step) cos(40 deg). */
static void test_checker_allowance_follows_the_seed_rule(void)
{
    TEST_ASSERT_EQUAL_INT(0, soak_level_generate(&lvl, 3));
    /* replace the static triangle list by one 40-degree slope through the origin */
    double ang = 40.0 * 3.14159265358979323846 / 180.0, cs = cos(ang), sn = sin(ang);
    soak_wtri_t *w = &lvl.wtris[0];
    double v[3][3] = {{-5, -5 * sn / cs, 0}, {5, 5 * sn / cs, -5}, {5, 5 * sn / cs, 5}};
    memcpy(w->v, v, sizeof v);
    w->c[0] = 5.0 / 3; w->c[1] = 5 * sn / cs / 3; w->c[2] = 0; w->rad = 20;
    w->mask = 0x01;
    lvl.nwtris = 1;
    static char_body_t body;
    fm_vec3_t owner = {{0.0f, 0.0f, 0.0f}}; /* foot point on the slope */
    char_body_init(&body, &owner);
    char_body_settings_t s = CHAR_BODY_SETTINGS_DEFAULT;
    s.radius = 0.5f; s.height = 2.0f; s.step_height = 0.05f; s.floor_snap_distance = 0.3f;
    s.center_offset.y = 1.0f;
    s.floor_max_angle = (float)(45.0 * 3.14159265358979323846 / 180.0);
    char_body_configure(&body, &s);
    soak_capsule_t full, sweep;
    int32_t tri;
    double raw = 0;
    soak_body_capsules(&body, &full, &sweep);
    double ex = soak_check_static_pen(&lvl, &body.settings, &sweep, &tri, &raw);
    double expect_raw = 0.5 - 0.55 * cs;
    TEST_ASSERT_DOUBLE_WITHIN(1e-6, expect_raw, raw);
    TEST_ASSERT_DOUBLE_WITHIN(1e-6, 0.0, ex);
    /* the same slope steeper than floor_max_angle gets no allowance */
    s.floor_max_angle = (float)(30.0 * 3.14159265358979323846 / 180.0);
    char_body_configure(&body, &s);
    soak_body_capsules(&body, &full, &sweep);
    ex = soak_check_static_pen(&lvl, &body.settings, &sweep, &tri, &raw);
    TEST_ASSERT_DOUBLE_WITHIN(1e-6, expect_raw, ex);
}

static void test_replay_format_round_trips_special_values(void)
{
    soak_replay_t rp;
    memset(&rp, 0, sizeof rp);
    rp.level_seed = 0xFEDCBA9876543210ull;
    rp.settings = CHAR_BODY_SETTINGS_DEFAULT;
    rp.settings.radius = 0.1f + 1e-7f;
    rp.start.x = -0.0f; rp.start.y = 1e-30f; rp.start.z = 3.4e38f;
    static soak_frame_t fr[3];
    memset(fr, 0, sizeof fr);
    fr[0].dt = NAN; fr[0].input.x = INFINITY; fr[0].input.y = -INFINITY; fr[0].input.z = 1.0f / 3.0f;
    fr[1].dt = 1.0f / 240; fr[1].ops = SOAK_OP_JUMP | SOAK_OP_TELEPORT | SOAK_OP_UP | SOAK_OP_VEL;
    fr[1].jump = 7.5f; fr[1].tele.y = 2.0f; fr[1].tele_reset = 1; fr[1].up.x = NAN; fr[1].vel.z = -1e20f;
    fr[2].dt = 0.2f;
    rp.frames = fr; rp.nframes = 3; rp.cap = 3;
    rp.nexpect = 1;
    snprintf(rp.expect[0].arch, sizeof rp.expect[0].arch, "%s", soak_arch());
    rp.expect[0].pos.x = 1.5f; rp.expect[0].on_floor = 1;
    snprintf(rp.note, sizeof rp.note, "round trip test");
    char path[64];
    snprintf(path, sizeof path, "/tmp/soak_rt_%ld.replay", (long)getpid());
    TEST_ASSERT_EQUAL_INT(0, soak_replay_write(path, &rp));
    static soak_frame_t back[4];
    soak_replay_t rd;
    rd.frames = back; rd.cap = 4;
    int line = 0;
    int rc = soak_replay_read(path, &rd, &line);
    remove(path);
    TEST_ASSERT_EQUAL_INT(0, rc);
    TEST_ASSERT_TRUE(rd.level_seed == rp.level_seed);
    TEST_ASSERT_EQUAL_UINT32(3, rd.nframes);
    TEST_ASSERT_EQUAL_MEMORY(&rp.settings.radius, &rd.settings.radius, sizeof(float));
    TEST_ASSERT_EQUAL_MEMORY(&rp.start, &rd.start, sizeof rp.start);
    TEST_ASSERT_TRUE(isnan(back[0].dt));
    TEST_ASSERT_TRUE(isinf(back[0].input.x) && back[0].input.x > 0);
    TEST_ASSERT_TRUE(isinf(back[0].input.y) && back[0].input.y < 0);
    TEST_ASSERT_EQUAL_MEMORY(&fr[0].input.z, &back[0].input.z, sizeof(float));
    TEST_ASSERT_EQUAL_UINT8(fr[1].ops, back[1].ops);
    TEST_ASSERT_EQUAL_MEMORY(&fr[1].vel, &back[1].vel, sizeof fr[1].vel);
    TEST_ASSERT_TRUE(isnan(back[1].up.x));
    TEST_ASSERT_EQUAL_UINT8(1, back[1].tele_reset);
    TEST_ASSERT_EQUAL_UINT32(1, rd.nexpect);
    TEST_ASSERT_NOT_NULL(soak_replay_expect_for(&rd, soak_arch()));
    TEST_ASSERT_EQUAL_STRING("round trip test", rd.note);
}

/* ---------------------------------------------------------------- the replays */

static bool is_replay(const char *name)
{
    size_t l = strlen(name);
    return l > 7 && strcmp(name + l - 7, ".replay") == 0;
}

/* Runs one file; returns true when it passes. */
static bool check_replay(const char *path)
{
    soak_replay_t rp;
    rp.frames = frames;
    rp.cap = MAX_FRAMES;
    int line = 0;
    if (soak_replay_read(path, &rp, &line) != 0) {
        printf("%s:%d: replay does not parse\n", path, line);
        return false;
    }
    soak_replay_result_t res;
    if (soak_replay_run(&rp, &lvl, &res) != 0) {
        printf("%s: level does not build\n", path);
        return false;
    }
    bool ok = true;
    if (res.fails) {
        printf("%s: %d hard failure(s), first at frame %u: %s: %s\n", path, res.fails, (unsigned)res.first_fail_frame,
               soak_fail_name(res.first_fail_kind), res.first_msg);
        ok = false;
    }
    const soak_expect_t *e = soak_replay_expect_for(&rp, soak_arch());
    const soak_expect_t *other = NULL;
    for (uint32_t i = 0; i < rp.nexpect; i++)
        if (!other && strcmp(rp.expect[i].lib, soak_lib_version()) == 0) other = &rp.expect[i];
    if (e && strcmp(e->lib, soak_lib_version()) != 0) {
        /* stored with another library version: behaviour may legitimately differ */
        printf("%s: stored %s state is from library %s, this is %s: not compared (make soak-bless)\n", path,
               soak_arch(), e->lib, soak_lib_version());
        stale++;
        e = NULL;
        other = NULL;
    }
    if (e) {
        if (memcmp(&e->pos, &res.pos, sizeof e->pos) != 0 || memcmp(&e->vel, &res.vel, sizeof e->vel) != 0 ||
            e->on_floor != res.on_floor) {
            printf("%s: final state differs from the stored %s state (behaviour changed; if intended, "
                   "re-store with `make soak-bless`): pos %a %a %a, stored %a %a %a\n",
                   path, soak_arch(), (double)res.pos.x, (double)res.pos.y, (double)res.pos.z, (double)e->pos.x,
                   (double)e->pos.y, (double)e->pos.z);
            ok = false;
        }
    } else if (other) {
        fm_vec3_t d;
        fm_vec3_sub(&d, &res.pos, &other->pos);
        if (!(fm_vec3_len(&d) <= CROSS_ARCH_TOL)) {
            printf("%s: no stored %s state; %.4f m from the %s state\n", path, soak_arch(), (double)fm_vec3_len(&d),
                   other->arch);
            ok = false;
        }
    }
    return ok;
}

static void test_every_replay_passes(void)
{
    DIR *d = opendir(REPLAY_DIR);
    TEST_ASSERT_NOT_NULL_MESSAGE(d, "cannot open " REPLAY_DIR " (run from the repository root)");
    struct dirent *de;
    int n = 0, bad = 0;
    char path[512];
    while ((de = readdir(d)) != NULL) {
        if (!is_replay(de->d_name)) continue;
        snprintf(path, sizeof path, "%s/%s", REPLAY_DIR, de->d_name);
        n++;
        if (!check_replay(path)) bad++;
    }
    closedir(d);
    printf("%d replay(s) in %s, %d failing, %d with stored states of another library version (%s)\n", n,
           REPLAY_DIR, bad, stale, soak_lib_version());
    TEST_ASSERT_TRUE_MESSAGE(n > 0, "no replays found");
    TEST_ASSERT_EQUAL_INT_MESSAGE(0, bad, "failing replays (listed above)");
}

/* Open-bug replays are not run (they fail until fixed) but must stay valid files. */
static void test_open_replays_parse(void)
{
    DIR *d = opendir(REPLAY_DIR "/open");
    if (!d) TEST_IGNORE_MESSAGE("no open replays");
    struct dirent *de;
    int bad = 0;
    char path[512];
    while ((de = readdir(d)) != NULL) {
        if (!is_replay(de->d_name)) continue;
        snprintf(path, sizeof path, "%s/open/%s", REPLAY_DIR, de->d_name);
        soak_replay_t rp;
        rp.frames = frames;
        rp.cap = MAX_FRAMES;
        int line = 0;
        if (soak_replay_read(path, &rp, &line) != 0 || rp.nframes == 0) {
            printf("%s:%d: does not parse\n", path, line);
            bad++;
        }
    }
    closedir(d);
    TEST_ASSERT_EQUAL_INT(0, bad);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_checker_segment_triangle_distance);
    RUN_TEST(test_checker_sees_penetration_and_floor_reach);
    RUN_TEST(test_checker_flags_bad_body_states);
    RUN_TEST(test_checker_allowance_follows_the_seed_rule);
    RUN_TEST(test_replay_format_round_trips_special_values);
    RUN_TEST(test_every_replay_passes);
    RUN_TEST(test_open_replays_parse);
    return UNITY_END();
}
