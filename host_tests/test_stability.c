/*
 * Stability suite, reduced: every scenario of the benchmark's stability table
 * (host_tests/support/bench_scn.c, docs/BENCHMARKS.md) on the default exact sweep, so a
 * regression fails `make test`. The benchmark runs the same scenarios for every method.
 *
 * Each scenario measures an error (penetration, rest-point offset, bump, speed loss,
 * carry error) against a fixed limit; see the table in docs/BENCHMARKS.md.
 */
#include "unity.h"
#include "bench_scn.h"

#include <stdio.h>
#include <string.h>

/* Scenarios the current char body is known to fail (see docs/BENCHMARKS.md, "Findings").
 * They are run and reported, and ignored rather than failed until fixed; a known failure
 * that starts passing is reported too, so the list can be trimmed. */
static const char *const k_known_fail[] = {
    /* none at present. History: vcorner_120 (ping-pong between two rest points 5 cm apart
     * every frame) and seams_wall (one frame losing 77 % speed on a wall seam) failed on the
     * first char body; both pass since the creases / slide fixes. */
    NULL,
};

static _Alignas(8) unsigned char g_buf[BENCH_SCN_BUF];

void setUp(void) {}
void tearDown(void) {}

static bool known_fail(const char *name)
{
    for (size_t i = 0; i < sizeof(k_known_fail) / sizeof(k_known_fail[0]); i++)
        if (k_known_fail[i] && strcmp(name, k_known_fail[i]) == 0) return true;
    return false;
}

static void run_one(int i)
{
    bench_result_t r = bench_scn_run(i, true, g_buf, sizeof(g_buf));
    char msg[256];
    snprintf(msg, sizeof(msg), "%s: err %.4g %s (limit %.3g), max penetration %.3g m: %s", r.name, r.err,
             r.unit, r.limit, r.pen, r.pass ? "ok" : r.note);
    if (known_fail(r.name)) {
        if (r.pass) { char m2[300]; snprintf(m2, sizeof(m2), "known failure now passes: %s", msg); TEST_IGNORE_MESSAGE(m2); }
        TEST_IGNORE_MESSAGE(msg);
    }
    TEST_ASSERT_TRUE_MESSAGE(r.pass, msg);
}

#define SCN(i) static void test_scenario_##i(void) { if (i < bench_scn_count()) run_one(i); }
SCN(0) SCN(1) SCN(2) SCN(3) SCN(4) SCN(5) SCN(6) SCN(7) SCN(8) SCN(9) SCN(10) SCN(11) SCN(12)
SCN(13) SCN(14) SCN(15) SCN(16) SCN(17) SCN(18) SCN(19) SCN(20)

/* The suite must not silently shrink or grow past the functions above. */
static void test_scenario_count(void) { TEST_ASSERT_EQUAL_INT(21, bench_scn_count()); }

/* The reference itself: a known sweep (capsule falling onto a floor triangle). */
static void test_reference_sweep_is_exact(void)
{
    fm_vec3_t seg[2] = {{{0, 1, 0}}, {{0, 2, 0}}};
    fm_vec3_t disp = {{0, -2, 0}};
    fm_vec3_t tri[3] = {{{-5, 0, -5}}, {{5, 0, -5}}, {{0, 0, 5}}};
    coll_prim_hit_t h;
    TEST_ASSERT_TRUE(bench_ref_tri_sweep(NULL, seg, 0.5f, &disp, tri, 1.0f, &h));
    TEST_ASSERT_FLOAT_WITHIN(1e-6f, 0.25f, h.t);
    TEST_ASSERT_FLOAT_WITHIN(1e-6f, 1.0f, h.normal.y);
    /* and the exact analytic sweep agrees with it */
    coll_prim_hit_t e;
    TEST_ASSERT_TRUE(coll_capsule_triangle_sweep(seg, 0.5f, &disp, tri, 1.0f, &e));
    TEST_ASSERT_FLOAT_WITHIN(1e-5f, h.t, e.t);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_scenario_count);
    RUN_TEST(test_reference_sweep_is_exact);
    RUN_TEST(test_scenario_0); RUN_TEST(test_scenario_1); RUN_TEST(test_scenario_2);
    RUN_TEST(test_scenario_3); RUN_TEST(test_scenario_4); RUN_TEST(test_scenario_5);
    RUN_TEST(test_scenario_6); RUN_TEST(test_scenario_7); RUN_TEST(test_scenario_8);
    RUN_TEST(test_scenario_9); RUN_TEST(test_scenario_10); RUN_TEST(test_scenario_11);
    RUN_TEST(test_scenario_12); RUN_TEST(test_scenario_13); RUN_TEST(test_scenario_14);
    RUN_TEST(test_scenario_15); RUN_TEST(test_scenario_16); RUN_TEST(test_scenario_17);
    RUN_TEST(test_scenario_18); RUN_TEST(test_scenario_19); RUN_TEST(test_scenario_20);
    return UNITY_END();
}
