/* Determinism: the same level, settings and inputs give bit-identical positions on every
 * run of one build (fresh level at another address, interleaved with another body, through
 * a replay file); the soak generator gives the same level on every platform; the runtime
 * does not allocate while stepping. See docs/RELIABILITY.md. */
#include "unity.h"
#include "alloc_guard.h"
#include "soak_sim.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#ifdef __mips__
#define FRAMES 600u   /* qemu is 10-30x slower */
#else
#define FRAMES 2500u
#endif

static soak_level_t lvl_a, lvl_b;
static soak_sim_t sim_a, sim_b;
static soak_frame_t frames[FRAMES];
static fm_vec3_t traj_a[FRAMES], traj_b[FRAMES];

void setUp(void) {}
void tearDown(void) {}

/* Settings, start and FRAMES frames of play for level seed, generated on lvl. */
static void make_play(soak_level_t *lvl, uint64_t seed, char_body_settings_t *s, fm_vec3_t *start)
{
    TEST_ASSERT_EQUAL_INT(0, soak_level_generate(lvl, seed));
    soak_rng_t r;
    soak_rng_seed(&r, soak_mix64(seed ^ 0x5E77ull));
    soak_settings_random(&r, s, start);
    soak_play_t play;
    soak_play_init(&play, seed);
    /* play depends on the body position (teleport/up-change guards): generate it along a run */
    soak_sim_begin(&sim_a, lvl, s, *start);
    for (uint32_t i = 0; i < FRAMES; i++) {
        soak_play_next(&play, lvl, s, sim_a.owner, &frames[i]);
        soak_sim_step(&sim_a, &frames[i], false);
    }
}

static void run(soak_level_t *lvl, uint64_t seed, const char_body_settings_t *s, fm_vec3_t start, fm_vec3_t *traj)
{
    TEST_ASSERT_EQUAL_INT(0, soak_level_generate(lvl, seed));
    soak_sim_begin(&sim_b, lvl, s, start);
    for (uint32_t i = 0; i < FRAMES; i++) {
        soak_sim_step(&sim_b, &frames[i], false);
        traj[i] = sim_b.owner;
    }
}

static void assert_same_bits(const fm_vec3_t *a, const fm_vec3_t *b, const char *what)
{
    for (uint32_t i = 0; i < FRAMES; i++) {
        if (memcmp(&a[i], &b[i], sizeof a[i]) != 0) {
            char msg[200];
            snprintf(msg, sizeof msg, "%s: frame %u differs: (%a %a %a) vs (%a %a %a)", what, (unsigned)i,
                     (double)a[i].x, (double)a[i].y, (double)a[i].z, (double)b[i].x, (double)b[i].y, (double)b[i].z);
            TEST_FAIL_MESSAGE(msg);
        }
    }
}

static void test_prng_is_splitmix64(void)
{
    soak_rng_t r;
    soak_rng_seed(&r, 0);
    TEST_ASSERT_TRUE(soak_rng_next(&r) == 0xE220A8397B1DCDAFull);
    TEST_ASSERT_TRUE(soak_rng_next(&r) == 0x6E789E6AA1B965F4ull);
    TEST_ASSERT_TRUE(soak_rng_next(&r) == 0x06C45D188009454Full);
    for (int i = 0; i < 1000; i++) {
        double u = soak_rng_unit(&r);
        TEST_ASSERT_TRUE(u >= 0.0 && u < 1.0);
        TEST_ASSERT_TRUE(soak_rng_below(&r, 7) < 7);
    }
}

static void test_own_trig_matches_libm(void)
{
    for (int i = -2000; i <= 2000; i++) {
        double x = i * 0.0123;
        TEST_ASSERT_DOUBLE_WITHIN(1e-14, sin(x), soak_sin(x));
        TEST_ASSERT_DOUBLE_WITHIN(1e-14, cos(x), soak_cos(x));
    }
}

typedef struct { uint64_t seed, hash; } level_hash_t;

/* Every reference seed of generator version `gen` builds the level with the recorded hash. */
static void check_level_hashes(int gen, const level_hash_t *ref, unsigned n)
{
    for (unsigned i = 0; i < n; i++) {
        TEST_ASSERT_EQUAL_INT(0, soak_level_generate_v(&lvl_a, ref[i].seed, gen));
        uint64_t h = soak_level_hash(&lvl_a);
        if (h != ref[i].hash) {
            char msg[120];
            snprintf(msg, sizeof msg, "gen %d seed %llu: level hash 0x%016llxull", gen,
                     (unsigned long long)ref[i].seed, (unsigned long long)h);
            TEST_FAIL_MESSAGE(msg);
        }
    }
}

/* Hashes recorded on x86-64; big-endian MIPS under qemu must produce the same levels, or
 * replay files (which store only the level seed) would not reproduce across platforms. */
static void test_level_generation_is_platform_independent(void)
{
    static const level_hash_t ref1[] = {
        {1, 0xb8788e1298f95662ull}, {2, 0x43c55ba4119d0bf2ull}, {0xDEADBEEFull, 0x687431ff67e92df6ull},
    };
    check_level_hashes(SOAK_GEN_V1, ref1, sizeof ref1 / sizeof ref1[0]);
    /* generator version 2 (cracks, slots, tiles, overhangs, staircases); version 1 above
     * must stay as it is: replays without a `gen` line regenerate their level with it */
    static const level_hash_t ref2[] = {
        {1, 0x1cf74c5cc5811629ull}, {2, 0x82540a32be551c5eull}, {0xDEADBEEFull, 0x98fa62cb41e44f05ull},
    };
    check_level_hashes(SOAK_GEN_CURRENT, ref2, sizeof ref2 / sizeof ref2[0]);
}

static void test_level_has_every_piece_kind_somewhere(void)
{
    /* over a few seeds the generator makes moving platforms, bodies, other-layer pieces */
    bool moving = false, bodies = false, layer2 = false, scaled = false;
    for (uint64_t seed = 1; seed <= 12; seed++) {
        TEST_ASSERT_EQUAL_INT(0, soak_level_generate(&lvl_a, seed));
        TEST_ASSERT_TRUE(lvl_a.nwtris > 80);
        for (uint32_t i = 0; i < lvl_a.npieces; i++) {
            moving |= lvl_a.pieces[i].moving;
            layer2 |= lvl_a.pieces[i].inst.write_mask == 0x02;
            scaled |= lvl_a.pieces[i].inst.xf.scale.x != 1.0f;
        }
        bodies |= lvl_a.nbodies > 0;
    }
    TEST_ASSERT_TRUE(moving);
    TEST_ASSERT_TRUE(bodies);
    TEST_ASSERT_TRUE(layer2);
    TEST_ASSERT_TRUE(scaled);
}

static void test_same_inputs_give_identical_bits(void)
{
    static const uint64_t seeds[] = {11, 0xC0FFEEull, 424242};
    for (unsigned k = 0; k < sizeof seeds / sizeof seeds[0]; k++) {
        char_body_settings_t s;
        fm_vec3_t start;
        make_play(&lvl_a, seeds[k], &s, &start);
        run(&lvl_a, seeds[k], &s, start, traj_a);   /* same storage, rebuilt */
        run(&lvl_b, seeds[k], &s, start, traj_b);   /* other storage: other addresses */
        assert_same_bits(traj_a, traj_b, "second level copy");
        run(&lvl_a, seeds[k], &s, start, traj_b);
        assert_same_bits(traj_a, traj_b, "rerun");
    }
}

/* Two bodies stepped alternately match the same bodies stepped alone: no hidden state
 * (static scratch, caches) leaks from one body or scene into another. */
static void test_interleaved_bodies_do_not_interfere(void)
{
    char_body_settings_t sa, sb;
    fm_vec3_t st_a, st_b;
    static soak_frame_t frames_b[FRAMES];
    make_play(&lvl_b, 77, &sb, &st_b);
    memcpy(frames_b, frames, sizeof frames);
    run(&lvl_b, 77, &sb, st_b, traj_b);
    static fm_vec3_t alone_b[FRAMES];
    memcpy(alone_b, traj_b, sizeof alone_b);
    make_play(&lvl_a, 78, &sa, &st_a);
    run(&lvl_a, 78, &sa, st_a, traj_a);

    TEST_ASSERT_EQUAL_INT(0, soak_level_generate(&lvl_a, 78));
    TEST_ASSERT_EQUAL_INT(0, soak_level_generate(&lvl_b, 77));
    soak_sim_begin(&sim_a, &lvl_a, &sa, st_a);
    soak_sim_begin(&sim_b, &lvl_b, &sb, st_b);
    for (uint32_t i = 0; i < FRAMES; i++) {
        soak_sim_step(&sim_b, &frames_b[i], false);
        soak_sim_step(&sim_a, &frames[i], false);
        traj_b[i] = sim_b.owner;
        if (memcmp(&sim_a.owner, &traj_a[i], sizeof traj_a[i]) != 0) {
            char msg[80];
            snprintf(msg, sizeof msg, "body A differs at frame %u when interleaved", (unsigned)i);
            TEST_FAIL_MESSAGE(msg);
        }
    }
    assert_same_bits(alone_b, traj_b, "body B interleaved");
}

static void test_replay_file_reproduces_the_run_bitwise(void)
{
    char_body_settings_t s;
    fm_vec3_t start;
    make_play(&lvl_a, 99, &s, &start);
    run(&lvl_a, 99, &s, start, traj_a);
    soak_replay_t rp;
    memset(&rp, 0, sizeof rp);
    rp.level_seed = 99;
    rp.settings = s;
    rp.start = start;
    rp.frames = frames;
    rp.nframes = FRAMES;
    rp.cap = FRAMES;
    char path[64];
    snprintf(path, sizeof path, "/tmp/soak_det_%ld.replay", (long)getpid());
    TEST_ASSERT_EQUAL_INT(0, soak_replay_write(path, &rp));
    static soak_frame_t back[FRAMES];
    soak_replay_t rd;
    rd.frames = back;
    rd.cap = FRAMES;
    int line = 0;
    int rc = soak_replay_read(path, &rd, &line);
    remove(path);
    TEST_ASSERT_EQUAL_INT_MESSAGE(0, rc, "replay parse");
    TEST_ASSERT_EQUAL_UINT32(FRAMES, rd.nframes);
    TEST_ASSERT_TRUE(rd.level_seed == 99);
    TEST_ASSERT_EQUAL_MEMORY(&s.up, &rd.settings.up, sizeof s.up);
    TEST_ASSERT_EQUAL_MEMORY(&s.center_offset, &rd.settings.center_offset, sizeof s.center_offset);
    TEST_ASSERT_EQUAL_MEMORY(&s.gravity, &rd.settings.gravity, 7 * sizeof(float));
    TEST_ASSERT_EQUAL_UINT8(s.coll_types, rd.settings.coll_types);
    TEST_ASSERT_EQUAL_UINT8(s.max_slides, rd.settings.max_slides);
    TEST_ASSERT_EQUAL_UINT8(s.read_mask, rd.settings.read_mask);
    TEST_ASSERT_EQUAL(s.follow_floor, rd.settings.follow_floor);
    for (uint32_t i = 0; i < FRAMES; i++) {
        TEST_ASSERT_EQUAL_UINT8(frames[i].ops, back[i].ops);
        if (!isnan(frames[i].dt)) TEST_ASSERT_EQUAL_MEMORY(&frames[i].dt, &back[i].dt, sizeof(float));
    }
    soak_replay_result_t res;
    TEST_ASSERT_EQUAL_INT(0, soak_replay_run(&rd, &lvl_b, &res));
    TEST_ASSERT_EQUAL_MEMORY(&traj_a[FRAMES - 1], &res.pos, sizeof res.pos);
}

static void test_stepping_soak_levels_does_not_allocate(void)
{
    char_body_settings_t s;
    fm_vec3_t start;
    make_play(&lvl_a, 5, &s, &start);
    TEST_ASSERT_EQUAL_INT(0, soak_level_generate(&lvl_a, 5));
    soak_sim_begin(&sim_a, &lvl_a, &s, start);
    alloc_guard_begin();
    for (uint32_t i = 0; i < FRAMES; i++) soak_sim_step(&sim_a, &frames[i], false);
    TEST_ASSERT_EQUAL_UINT(0u, (unsigned)alloc_guard_end());
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_prng_is_splitmix64);
    RUN_TEST(test_own_trig_matches_libm);
    RUN_TEST(test_level_generation_is_platform_independent);
    RUN_TEST(test_level_has_every_piece_kind_somewhere);
    RUN_TEST(test_same_inputs_give_identical_bits);
    RUN_TEST(test_interleaved_bodies_do_not_interfere);
    RUN_TEST(test_replay_file_reproduces_the_run_bitwise);
    RUN_TEST(test_stepping_soak_levels_does_not_allocate);
    return UNITY_END();
}
