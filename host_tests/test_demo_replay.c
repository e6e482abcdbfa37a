/* The char_body example's committed replays, played headlessly on the baked sample levels:
 * every feature of the course is reached (stairs top, V-corner apex, steep slope with its
 * slowdown, coyote jump, each moving platform carrying the player), a full lap of the planet
 * under planet gravity, nobody falls out, and the game loop never allocates.
 * The example's sources are compiled into this suite directly (the Makefile links only
 * libcoll and host_tests/support into test binaries). */
#include "unity.h"
#include "alloc_guard.h"
#include "../examples/char_body/game.c"
#include "../examples/char_body/game_level.c"
#include "../examples/char_body/game_replay.c"
#include "../examples/char_body/demo_host.c"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define REPLAY_DIR "examples/char_body/replay"

typedef struct {
    bool ran, ok;
    game_t g;
    replay_t r;
    size_t allocs;          /* heap calls made by replay_input + game_step over the run */
    float min_foot_y;       /* course: lowest foot height seen */
    float min_radius, max_radius; /* planet: centre distance range while walking the lap */
    uint32_t lap_airborne;  /* planet: lap frames not on the floor */
    float vcorner_x_spread; /* course: x range over the last 0.5 s pushing into the V-corner */
} run_t;

static demo_assets_t assets;
static bool assets_ok;
static run_t course, planet;

void setUp(void) {}
void tearDown(void) {}

static const char *asset_dir(void)
{
    const char *d = getenv("COLL_ASSET_DIR");
    return d && *d ? d : "build/assets";
}

static void play(run_t *run, const game_level_t *level, const char *script)
{
    if (run->ran) return;
    run->ran = true;
    TEST_ASSERT_TRUE_MESSAGE(demo_replay_load(&run->r, script), script);
    game_init(&run->g, level);
    run->min_foot_y = 1e9f;
    run->min_radius = 1e9f;
    run->max_radius = 0.0f;
    float vx_min = 1e9f, vx_max = -1e9f;
    size_t allocs = 0;
    while (!replay_done(&run->r) && run->g.time < 600.0f) {
        game_input_t in;
        alloc_guard_begin();
        replay_input(&run->r, &run->g, &in, GAME_DT);
        game_step(&run->g, &in, GAME_DT);
        allocs += alloc_guard_end();
        fm_vec3_t foot = char_body_foot_pos(&run->g.body);
        if (foot.y < run->min_foot_y) run->min_foot_y = foot.y;
        const replay_cmd_t *c = replay_done(&run->r) ? NULL : &run->r.cmds[run->r.pc];
        if (c && c->op == REPLAY_PLANET_LAP && run->g.blend_t >= 1.0f) {
            float d = game_v3_len(game_v3_sub(run->g.pos, run->g.level.planet_center));
            if (d < run->min_radius) run->min_radius = d;
            if (d > run->max_radius) run->max_radius = d;
            if (!char_body_is_on_floor(&run->g.body)) run->lap_airborne++;
        }
        /* The V-corner push: the script pushes towards (4, 40) for 3 s. */
        if (c && c->op == REPLAY_PUSH && c->a[1] > 39.0f && run->r.cmd_time > c->a[2] - 0.5f) {
            if (run->g.pos.x < vx_min) vx_min = run->g.pos.x;
            if (run->g.pos.x > vx_max) vx_max = run->g.pos.x;
        }
    }
    run->allocs = allocs;
    run->vcorner_x_spread = vx_max - vx_min;
    run->ok = true;
}

static run_t *course_run(void)
{
    TEST_ASSERT_TRUE_MESSAGE(assets_ok, "baked levels missing (make assets)");
    game_level_t level;
    game_level_course(&level, assets.course, assets.platforms);
    play(&course, &level, REPLAY_DIR "/course.txt");
    TEST_ASSERT_TRUE(course.ok);
    return &course;
}

static run_t *planet_run(void)
{
    TEST_ASSERT_TRUE_MESSAGE(assets_ok, "baked levels missing (make assets)");
    game_level_t level;
    game_level_planet(&level, assets.planet);
    play(&planet, &level, REPLAY_DIR "/planet.txt");
    TEST_ASSERT_TRUE(planet.ok);
    return &planet;
}

static const replay_mark_t *mark(const run_t *run, const char *name)
{
    const replay_mark_t *m = replay_find_mark(&run->r, name);
    TEST_ASSERT_NOT_NULL_MESSAGE(m, name);
    return m;
}

/* ---- course ---- */

static void test_course_replay_completes_without_falling_out(void)
{
    run_t *c = course_run();
    TEST_ASSERT_TRUE(replay_done(&c->r));
    TEST_ASSERT_EQUAL_UINT32_MESSAGE(0, c->r.timeouts, "a waypoint was never reached");
    TEST_ASSERT_EQUAL_UINT32(0, c->g.stats.respawns);
    TEST_ASSERT_TRUE(c->min_foot_y > -0.05f); /* never sank through the floor */
    TEST_ASSERT_TRUE(c->g.time < 150.0f);
}

static void test_course_climbs_all_three_staircases(void)
{
    run_t *c = course_run();
    /* Feet on the flat tops: y 0.40, 0.80, 1.00 (risers 0.10, 0.20, 0.25 m). */
    static const struct { const char *name; float top; } st[] = {
        {"stairs1_top", 0.40f}, {"stairs2_top", 0.80f}, {"stairs_top", 1.00f},
    };
    for (int i = 0; i < 3; i++) {
        const replay_mark_t *m = mark(c, st[i].name);
        TEST_ASSERT_FLOAT_WITHIN_MESSAGE(0.06f, st[i].top + 1.0f, m->pos.y, st[i].name);
        TEST_ASSERT_EQUAL_INT_MESSAGE(CHAR_BODY_ON_FLOOR, m->state, st[i].name);
    }
}

static void test_course_hill_tops_and_vcorner(void)
{
    run_t *c = course_run();
    TEST_ASSERT_FLOAT_WITHIN(0.06f, 2.0f, mark(c, "hill10_top")->pos.y);
    TEST_ASSERT_FLOAT_WITHIN(0.06f, 2.0f, mark(c, "hill44_top")->pos.y);
    /* Pushed into the 90 deg V-corner (apex (4, 38)): deep inside, centred, not ping-ponging. */
    const replay_mark_t *v = mark(c, "vcorner");
    TEST_ASSERT_FLOAT_WITHIN(0.3f, 4.0f, v->pos.x);
    TEST_ASSERT_TRUE(v->pos.z > 36.5f);
    TEST_ASSERT_TRUE(c->vcorner_x_spread < 0.05f);
}

static void test_course_steep_slope_slows_then_recovers(void)
{
    run_t *c = course_run();
    /* Landed on the 50 deg slope from a hop and slid down it (a fraction of a second);
     * the speed factor falls at 2.5 / s while there and is back to 1 afterwards. */
    TEST_ASSERT_TRUE(c->g.stats.steep_time > 0.1f);
    TEST_ASSERT_TRUE(c->g.stats.min_speed_factor < 0.8f);
    TEST_ASSERT_EQUAL_FLOAT(1.0f, c->g.speed_factor);
    const replay_mark_t *m = mark(c, "steep_slope"); /* slid back down to the floor */
    TEST_ASSERT_FLOAT_WITHIN(0.05f, 1.0f, m->pos.y);
    TEST_ASSERT_TRUE(m->pos.z < 16.1f);
}

static void test_course_jumps_coyote_and_variable_height(void)
{
    run_t *c = course_run();
    TEST_ASSERT_TRUE(c->g.stats.coyote_jumps >= 1);   /* off the 1.3 m ledge, after leaving it */
    TEST_ASSERT_TRUE(c->g.stats.buffered_jumps >= 1); /* pressed just before landing */
    TEST_ASSERT_TRUE(c->g.stats.jump_cuts >= 1);      /* the short hop */
    TEST_ASSERT_TRUE(c->g.stats.jumps >= 5);
    const replay_mark_t *m = mark(c, "after_ledge");  /* down on the floor beyond the ledge */
    TEST_ASSERT_TRUE(m->pos.x < -22.0f);
    TEST_ASSERT_EQUAL_INT(CHAR_BODY_ON_FLOOR, m->state);
    TEST_ASSERT_FLOAT_WITHIN(0.05f, 1.0f, m->pos.y);
}

static void test_course_rides_every_platform(void)
{
    run_t *c = course_run();
    /* Meters the platform carried the player (its motion at the player's position). */
    static const float min_carry[4] = {6.0f, 4.0f, 0.8f, 5.5f};
    static const char *const names[4] = {"translate", "rotate", "scale", "lift"};
    for (int i = 0; i < 4; i++) {
        char msg[64];
        snprintf(msg, sizeof msg, "%s platform carried %.2f m", names[i], (double)c->g.stats.ride_distance[i]);
        TEST_ASSERT_TRUE_MESSAGE(c->g.stats.ride_distance[i] >= min_carry[i], msg);
        TEST_ASSERT_TRUE_MESSAGE(c->g.stats.ride_time[i] > 3.0f, msg);
    }
    /* The lift took the player up to its top (3.2 m above the floor, top face 0 local). */
    /* Issue-15 features in the example: a jump off the translating platform lands on it,
     * the one-way platform is jumped up through and dropped through, the player bumps into
     * a non-player body, the camera smooths the stair steps. */
    TEST_ASSERT_TRUE(c->g.stats.platform_jump_landings >= 1);
    TEST_ASSERT_EQUAL_INT(GAME_PLATFORM_ID0 + GAME_PLAT_TRANSLATE, mark(c, "translate_jump_landed")->floor_id);
    const replay_mark_t *ow = mark(c, "one_way_top");
    TEST_ASSERT_EQUAL_INT(GAME_ONE_WAY_ID, ow->floor_id);
    TEST_ASSERT_FLOAT_WITHIN(0.01f, 2.7f, ow->pos.y);
    TEST_ASSERT_EQUAL_INT(GAME_LEVEL_ID, mark(c, "one_way_dropped")->floor_id);
    TEST_ASSERT_EQUAL_UINT32(1, c->g.stats.drops);
    TEST_ASSERT_TRUE(c->g.stats.one_way_landings >= 1);
    TEST_ASSERT_TRUE(c->g.stats.npc_bumps >= 1);
    TEST_ASSERT_TRUE(c->g.stats.camera_steps >= 8);
    const replay_mark_t *m = mark(c, "lift_top");
    TEST_ASSERT_EQUAL_INT(GAME_PLATFORM_ID0 + GAME_PLAT_LIFT, m->floor_id);
    TEST_ASSERT_TRUE(m->pos.y > 4.0f);
}

static void test_course_game_loop_never_allocates(void)
{
    TEST_ASSERT_EQUAL_UINT(0, (unsigned)course_run()->allocs);
}

/* ---- planet ---- */

static void test_planet_lap_under_planet_gravity(void)
{
    run_t *p = planet_run();
    TEST_ASSERT_TRUE(replay_done(&p->r));
    TEST_ASSERT_EQUAL_UINT32(0, p->r.timeouts);
    TEST_ASSERT_EQUAL_UINT32(1, p->r.laps);
    TEST_ASSERT_EQUAL_UINT32(0, p->g.stats.respawns);
    TEST_ASSERT_EQUAL_UINT32(2, p->g.stats.gravity_toggles);
    /* Walked on the surface the whole way round: centre 1 m above a 19.94..20 m surface. */
    TEST_ASSERT_TRUE(p->min_radius > 20.8f);
    TEST_ASSERT_TRUE(p->max_radius < 21.2f);
    TEST_ASSERT_EQUAL_UINT32(0, p->lap_airborne);
    /* Back near the north pole, with normal gravity again. */
    const replay_mark_t *e = mark(p, "end");
    TEST_ASSERT_TRUE(e->pos.y > 20.5f);
    TEST_ASSERT_EQUAL_INT(CHAR_BODY_ON_FLOOR, e->state);
    TEST_ASSERT_FLOAT_WITHIN(1e-4f, 1.0f, p->g.up.y);
    TEST_ASSERT_EQUAL_UINT(0, (unsigned)p->allocs);
}

static void test_planet_replay_is_deterministic(void)
{
    run_t *p = planet_run();
    static run_t again;
    game_level_t level;
    game_level_planet(&level, assets.planet);
    play(&again, &level, REPLAY_DIR "/planet.txt");
    TEST_ASSERT_EQUAL_UINT32(p->g.stats.frames, again.g.stats.frames);
    TEST_ASSERT_EQUAL_MEMORY(&p->g.pos, &again.g.pos, sizeof p->g.pos);
}

/* ---- controller details, on the course floor ---- */

static game_t scratch;

static void course_game(game_t *g, fm_vec3_t start)
{
    TEST_ASSERT_TRUE_MESSAGE(assets_ok, "baked levels missing (make assets)");
    game_level_t level;
    game_level_course(&level, assets.course, assets.platforms);
    level.spawn = start;
    game_init(g, &level);
    game_input_t idle = {0};
    for (int i = 0; i < 30; i++) game_step(g, &idle, GAME_DT); /* settle on the floor */
    TEST_ASSERT_EQUAL_INT(CHAR_BODY_ON_FLOOR, game_body_state(g));
}

/* Peak height of a standing jump with the button held for `hold` frames. */
static float jump_peak(int hold)
{
    course_game(&scratch, game_v3(20.0f, 1.05f, -10.0f));
    float y0 = scratch.pos.y, peak = y0;
    for (int i = 0; i < 90; i++) {
        game_input_t in = { .jump = i < hold };
        game_step(&scratch, &in, GAME_DT);
        if (scratch.pos.y > peak) peak = scratch.pos.y;
    }
    TEST_ASSERT_EQUAL_INT(CHAR_BODY_ON_FLOOR, game_body_state(&scratch)); /* landed again */
    return peak - y0;
}

static void test_jump_height_depends_on_hold_time(void)
{
    float hop = jump_peak(3), full = jump_peak(60);
    /* Full jump: v^2 / 2g = 11^2 / 60 = 2.0 m; a tap cuts the rise early. */
    TEST_ASSERT_FLOAT_WITHIN(0.15f, 2.0f, full);
    TEST_ASSERT_TRUE(hop > 0.2f);
    TEST_ASSERT_TRUE(hop < 0.6f * full);
    TEST_ASSERT_EQUAL_UINT32(0, scratch.stats.jump_cuts); /* the last run held jump throughout */
}

/* Runs off the 1.3 m ledge (x = -18, top y = 1.3) and taps jump `delay` s after the floor
 * is gone (the fall takes about 0.29 s). */
static void ledge_jump(float delay)
{
    course_game(&scratch, game_v3(-16.5f, 2.35f, 30.0f));
    float air = -1.0f;
    for (int i = 0; i < 120; i++) {
        fm_vec3_t fwd, right;
        game_move_basis(&scratch, &fwd, &right);
        game_input_t in = { .stick_y = -fwd.x, .stick_x = -right.x }; /* run towards -x */
        if (air < 0.0f && game_body_state(&scratch) == CHAR_BODY_AIRBORNE) air = scratch.time;
        in.jump = air >= 0.0f && scratch.time - air >= delay && scratch.time - air < delay + 0.05f;
        game_step(&scratch, &in, GAME_DT);
    }
    TEST_ASSERT_TRUE(air > 0.0f);
}

static void test_coyote_time_and_jump_buffer(void)
{
    ledge_jump(0.05f); /* inside the 0.15 s coyote window: jumps in the air */
    TEST_ASSERT_EQUAL_UINT32(1, scratch.stats.jumps);
    TEST_ASSERT_EQUAL_UINT32(1, scratch.stats.coyote_jumps);
    ledge_jump(0.12f);
    TEST_ASSERT_EQUAL_UINT32(1, scratch.stats.coyote_jumps);
    /* Too late for coyote time, still falling: no jump in the air, but the press is
     * buffered and the jump happens on landing (within 0.15 s of the press). */
    ledge_jump(0.20f);
    TEST_ASSERT_EQUAL_UINT32(0, scratch.stats.coyote_jumps);
    TEST_ASSERT_EQUAL_UINT32(1, scratch.stats.buffered_jumps);
    TEST_ASSERT_EQUAL_UINT32(1, scratch.stats.jumps);
}

static void test_falling_out_respawns_at_the_spawn(void)
{
    course_game(&scratch, game_v3(-28.0f, 1.05f, -30.0f));
    char_body_teleport(&scratch.body, game_v3(60.0f, -25.0f, 60.0f), true); /* outside, below */
    game_input_t idle = {0};
    game_step(&scratch, &idle, GAME_DT);
    TEST_ASSERT_EQUAL_UINT32(1, scratch.stats.respawns);
    TEST_ASSERT_FLOAT_WITHIN(0.1f, -28.0f, scratch.pos.x);
    TEST_ASSERT_FLOAT_WITHIN(0.1f, -30.0f, scratch.pos.z);
    for (int i = 0; i < 60; i++) game_step(&scratch, &idle, GAME_DT);
    TEST_ASSERT_EQUAL_INT(CHAR_BODY_ON_FLOOR, game_body_state(&scratch));
    TEST_ASSERT_EQUAL_UINT32(1, scratch.stats.respawns);
}

static void test_gravity_toggle_turns_up_over_several_frames(void)
{
    TEST_ASSERT_TRUE_MESSAGE(assets_ok, "baked levels missing (make assets)");
    game_level_t level;
    game_level_planet(&level, assets.planet);
    level.spawn = game_v3(14.85f, 14.85f, 0.0f); /* 45 deg down the side, feet on the surface */
    game_init(&scratch, &level);
    game_input_t in = { .toggle_gravity = true };
    game_step(&scratch, &in, GAME_DT);
    fm_vec3_t target = game_v3_norm(scratch.pos);
    float first = game_v3_dot(scratch.up, target);
    TEST_ASSERT_TRUE(scratch.planet_gravity);
    TEST_ASSERT_TRUE(first > 0.7072f);  /* moved from straight up (dot 0.707) ... */
    TEST_ASSERT_TRUE(first < 0.99f);    /* ... but not all the way in one frame */
    in.toggle_gravity = false;
    int frames = 1;
    while (game_v3_dot(scratch.up, game_v3_norm(scratch.pos)) < 0.99999f && frames < 120) {
        game_step(&scratch, &in, GAME_DT);
        frames++;
    }
    TEST_ASSERT_TRUE(frames >= 10 && frames <= 30); /* 0.35 s at 60 Hz = 21 frames */
    TEST_ASSERT_FLOAT_WITHIN(1e-4f, 0.0f, game_v3_dot(scratch.cam_fwd, scratch.up));
    for (int i = 0; i < 60; i++) game_step(&scratch, &in, GAME_DT);
    TEST_ASSERT_EQUAL_INT(CHAR_BODY_ON_FLOOR, game_body_state(&scratch)); /* standing on the side of the planet */
}

/* ---- script parsing ---- */

static void test_replay_parser_reports_bad_lines(void)
{
    static replay_t r;
    const char good[] = "# comment\nwalk_to 1 -2.5\n\nmark here # trailing\nwait_phase 3 0.9 1\npush 1 2 3 4\n";
    TEST_ASSERT_TRUE(replay_parse(&r, good, (uint32_t)strlen(good)));
    TEST_ASSERT_EQUAL_UINT16(4, r.count);
    TEST_ASSERT_EQUAL_FLOAT(-2.5f, r.cmds[0].a[1]);
    TEST_ASSERT_EQUAL_FLOAT(-1.0f, r.cmds[0].a[2]); /* default: run speed */
    TEST_ASSERT_EQUAL_STRING("here", r.cmds[1].name);
    static const char *const bad[] = {
        "walk_to 1\n", "fly 1 2\n", "wait 1 2\n", "walk_to 1 x\n", "gravity sideways\n", "mark\n",
    };
    for (unsigned i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        char text[64];
        snprintf(text, sizeof text, "wait 1\n%s", bad[i]);
        TEST_ASSERT_FALSE_MESSAGE(replay_parse(&r, text, (uint32_t)strlen(text)), bad[i]);
        TEST_ASSERT_EQUAL_INT_MESSAGE(2, r.error_line, bad[i]);
    }
}

int main(void)
{
    assets_ok = demo_assets_load(&assets, asset_dir());
    UNITY_BEGIN();
    RUN_TEST(test_replay_parser_reports_bad_lines);
    RUN_TEST(test_course_replay_completes_without_falling_out);
    RUN_TEST(test_course_climbs_all_three_staircases);
    RUN_TEST(test_course_hill_tops_and_vcorner);
    RUN_TEST(test_course_steep_slope_slows_then_recovers);
    RUN_TEST(test_course_jumps_coyote_and_variable_height);
    RUN_TEST(test_course_rides_every_platform);
    RUN_TEST(test_course_game_loop_never_allocates);
    RUN_TEST(test_planet_lap_under_planet_gravity);
    RUN_TEST(test_planet_replay_is_deterministic);
    RUN_TEST(test_jump_height_depends_on_hold_time);
    RUN_TEST(test_coyote_time_and_jump_buffer);
    RUN_TEST(test_falling_out_respawns_at_the_spawn);
    RUN_TEST(test_gravity_toggle_turns_up_over_several_frames);
    int rc = UNITY_END();
    demo_assets_free(&assets);
    return rc;
}
