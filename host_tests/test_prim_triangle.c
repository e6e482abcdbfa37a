/* Capsule and ray against one triangle: specific features and random agreement with a
 * double-precision reference (prim_ref.c: convex minimisation + bisection of the exact
 * segment-triangle distance, independent of the analytic method under test). */
/* The method hooks (prim.h): this suite links libcoll_hooks.a ahead of libcoll.a. */
#define COLL_METHOD_HOOKS 1
#include "unity.h"
#include "alloc_guard.h"
#include "prim_ref.h"
#include "prim.h"
#include "prim_util.h"
#include <math.h>
#include <stdio.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#ifdef __mips__
#define N_RANDOM_SWEEPS 1500
#define N_RANDOM_RAYS 4000
#define N_EARLY_REJECT_RAYS 20000
#define N_BOUNDARY_OVERLAPS 4000
#else
#define N_RANDOM_SWEEPS 20000
#define N_RANDOM_RAYS 100000
#define N_EARLY_REJECT_RAYS 200000
#define N_BOUNDARY_OVERLAPS 40000
#endif

void setUp(void) {}
void tearDown(void) {}

static fm_vec3_t V(float x, float y, float z) { fm_vec3_t v; v.x = x; v.y = y; v.z = z; return v; }
static prim_ref_v3 R(fm_vec3_t v) { return prim_ref_v(v.x, v.y, v.z); }
static double ang(fm_vec3_t a, prim_ref_v3 b)
{
    double la = sqrt((double)a.x * a.x + (double)a.y * a.y + (double)a.z * a.z), lb = prim_ref_len(b);
    double c = ((double)a.x * b.x + (double)a.y * b.y + (double)a.z * b.z) / (la * lb);
    if (c > 1) c = 1;
    if (c < -1) c = -1;
    return acos(c);
}

/* ---- small deterministic RNG ---- */
static prim_ref_rng_t rng = {0x9E3779B97F4A7C15ull};
static uint32_t rnd_u32(void) { return prim_ref_rng_u32(&rng); }
static double rnd(void) { return rnd_u32() / 4294967296.0; }
static double rnd_range(double a, double b) { return prim_ref_rng_range(&rng, a, b); }
static prim_ref_v3 rnd_unit(void) { return prim_ref_rng_unit(&rng); }
static fm_vec3_t F(prim_ref_v3 v) { return V((float)v.x, (float)v.y, (float)v.z); }

static void random_triangle(prim_ref_v3 tri[3], double L);

static const fm_vec3_t floor_tri[3] = { {{-10, 0, -10}}, {{10, 0, -10}}, {{0, 0, 10}} };

/* ------------------------------------------------------------------ specific cases */

static void test_face_hit_vertical_capsule(void)
{
    fm_vec3_t seg[2] = { V(0, 2, 0), V(0, 3, 0) };
    fm_vec3_t d = V(0, -4, 0);
    coll_prim_hit_t h;
    TEST_ASSERT_TRUE(coll_capsule_triangle_sweep(seg, 0.5f, &d, floor_tri, 1.0f, &h));
    TEST_ASSERT_FLOAT_WITHIN(1e-6f, 1.5f / 4.0f, h.t);
    TEST_ASSERT_FLOAT_WITHIN(1e-6f, 0.0f, h.depth);
    TEST_ASSERT_FLOAT_WITHIN(1e-6f, 1.0f, h.normal.y);
    TEST_ASSERT_FLOAT_WITHIN(1e-5f, 0.0f, h.point.y);
    /* from below: normal flips (two-sided) */
    fm_vec3_t seg2[2] = { V(0, -2, 0), V(0, -3, 0) };
    fm_vec3_t up = V(0, 4, 0);
    TEST_ASSERT_TRUE(coll_capsule_triangle_sweep(seg2, 0.5f, &up, floor_tri, 1.0f, &h));
    TEST_ASSERT_FLOAT_WITHIN(1e-6f, 1.5f / 4.0f, h.t);
    TEST_ASSERT_FLOAT_WITHIN(1e-6f, -1.0f, h.normal.y);
    /* short of reach: miss */
    TEST_ASSERT_FALSE(coll_capsule_triangle_sweep(seg, 0.5f, &d, floor_tri, 0.3f, &h));
}

static void test_tilted_capsule_face_hit_uses_lower_end(void)
{
    fm_vec3_t seg[2] = { V(-1, 2, 0), V(1, 4, 0) };   /* lower end at y = 2 */
    fm_vec3_t d = V(0, -10, 0);
    coll_prim_hit_t h;
    TEST_ASSERT_TRUE(coll_capsule_triangle_sweep(seg, 0.25f, &d, floor_tri, 1.0f, &h));
    TEST_ASSERT_FLOAT_WITHIN(1e-6f, 0.175f, h.t);
    TEST_ASSERT_FLOAT_WITHIN(1e-5f, -1.0f, h.point.x);
}

static void test_edge_hit(void)
{
    /* triangle edge along z at x = 1, y = 0; horizontal capsule along x moving -x, at y = 0.3 */
    fm_vec3_t tri[3] = { V(1, 0, -1), V(1, 0, 1), V(-2, 0, 0) };
    fm_vec3_t seg[2] = { V(3, 0.3f, -0.2f), V(3, 0.3f, 0.2f) }; /* parallel to the edge */
    fm_vec3_t d = V(-4, 0, 0);
    coll_prim_hit_t h;
    TEST_ASSERT_TRUE(coll_capsule_triangle_sweep(seg, 0.5f, &d, tri, 1.0f, &h));
    /* touches when horizontal distance = sqrt(0.25 - 0.09) = 0.4 */
    TEST_ASSERT_FLOAT_WITHIN(1e-6f, (2.0f - 0.4f) / 4.0f, h.t);
    TEST_ASSERT_FLOAT_WITHIN(1e-5f, 0.8f, h.normal.x);
    TEST_ASSERT_FLOAT_WITHIN(1e-5f, 0.6f, h.normal.y);
    TEST_ASSERT_FLOAT_WITHIN(1e-5f, 1.0f, h.point.x);
    TEST_ASSERT_FLOAT_WITHIN(1e-5f, 0.0f, h.point.y);
    /* axis nearly parallel to the edge (tilted 1e-7 .. 1e-1 rad): the lower end leads */
    for (float tilt = 1e-7f; tilt < 0.2f; tilt *= 10.0f) {
        fm_vec3_t tseg[2] = { V(3, 0.3f, -0.2f), V(3 + 0.4f * tilt, 0.3f, 0.2f) };
        TEST_ASSERT_TRUE(coll_capsule_triangle_sweep(tseg, 0.5f, &d, tri, 1.0f, &h));
        TEST_ASSERT_FLOAT_WITHIN(2e-6f, 0.4f, h.t);
        TEST_ASSERT_FLOAT_WITHIN(1e-4f, 0.8f, h.normal.x);
        TEST_ASSERT_FLOAT_WITHIN(1e-4f, 0.6f, h.normal.y);
    }
    /* crossed edges: capsule axis along y crosses the edge line (edge-edge interior) */
    fm_vec3_t seg2[2] = { V(3, -0.5f, 0.1f), V(3, 0.5f, 0.1f) };
    TEST_ASSERT_TRUE(coll_capsule_triangle_sweep(seg2, 0.5f, &d, tri, 1.0f, &h));
    TEST_ASSERT_FLOAT_WITHIN(1e-6f, 1.5f / 4.0f, h.t);
    TEST_ASSERT_FLOAT_WITHIN(1e-5f, 1.0f, h.normal.x);
    TEST_ASSERT_FLOAT_WITHIN(1e-5f, 0.1f, h.point.z);
}

static void test_vertex_hit(void)
{
    fm_vec3_t tri[3] = { V(0, 0, 0), V(-1, 0, 1), V(-1, 0, -1) };  /* vertex at origin points +x */
    /* vertical capsule at x = 2 moving -x, segment spans y in [-1, 1]: the side hits the vertex */
    fm_vec3_t seg[2] = { V(2, -1, 0), V(2, 1, 0) };
    fm_vec3_t d = V(-2, 0, 0);
    coll_prim_hit_t h;
    TEST_ASSERT_TRUE(coll_capsule_triangle_sweep(seg, 0.5f, &d, tri, 1.0f, &h));
    TEST_ASSERT_FLOAT_WITHIN(1e-6f, 0.75f, h.t);
    TEST_ASSERT_FLOAT_WITHIN(1e-5f, 1.0f, h.normal.x);
    TEST_ASSERT_FLOAT_WITHIN(1e-6f, 0.0f, h.point.x);
    /* the capsule's end sphere against the vertex */
    fm_vec3_t seg2[2] = { V(2, 0.3f, 0), V(4, 0.3f, 0) };
    TEST_ASSERT_TRUE(coll_capsule_triangle_sweep(seg2, 0.5f, &d, tri, 1.0f, &h));
    TEST_ASSERT_FLOAT_WITHIN(1e-6f, (2.0f - 0.4f) / 2.0f, h.t);
    TEST_ASSERT_FLOAT_WITHIN(1e-5f, 0.8f, h.normal.x);
    TEST_ASSERT_FLOAT_WITHIN(1e-5f, 0.6f, h.normal.y);
}

static void test_sliding_along_face_does_not_block(void)
{
    /* resting exactly on the floor, and slightly inside (within the touch tolerance) */
    const float ys[] = { 0.5f, 0.5f - 1e-7f, 0.5f - 5e-5f, 0.5f + 1e-7f };
    for (unsigned i = 0; i < sizeof ys / sizeof ys[0]; i++) {
        fm_vec3_t seg[2] = { V(0, ys[i], 0), V(0, ys[i] + 1.0f, 0) };
        fm_vec3_t d = V(3, 0, 1);
        coll_prim_hit_t h;
        TEST_ASSERT_FALSE(coll_capsule_triangle_sweep(seg, 0.5f, &d, floor_tri, 1.0f, &h));
        /* lying capsule sliding along its own axis and sideways */
        fm_vec3_t seg2[2] = { V(-1, ys[i], 0), V(1, ys[i], 0) };
        fm_vec3_t d2 = V(2, 0, 0);
        TEST_ASSERT_FALSE(coll_capsule_triangle_sweep(seg2, 0.5f, &d2, floor_tri, 1.0f, &h));
        d2 = V(0, 0, 3);
        TEST_ASSERT_FALSE(coll_capsule_triangle_sweep(seg2, 0.5f, &d2, floor_tri, 1.0f, &h));
    }
    /* sliding across the shared edge of a flat quad: no ghost hit on the neighbour */
    fm_vec3_t q0[3] = { V(0, 0, 0), V(4, 0, 0), V(4, 0, 4) };
    fm_vec3_t q1[3] = { V(0, 0, 0), V(4, 0, 4), V(0, 0, 4) };
    for (int k = 0; k < 50; k++) {
        float y = 0.3f - (float)k * 1e-6f;
        fm_vec3_t seg[2] = { V(3.0f, y, 1.0f), V(3.0f, y + 0.8f, 1.0f) };
        fm_vec3_t d = V(-2.0f, 0.0f, 2.0f + (float)k * 0.01f);
        coll_prim_hit_t h;
        TEST_ASSERT_FALSE(coll_capsule_triangle_sweep(seg, 0.3f, &d, q0, 1.0f, &h));
        TEST_ASSERT_FALSE(coll_capsule_triangle_sweep(seg, 0.3f, &d, q1, 1.0f, &h));
    }
}

static void test_touching_and_moving_away_does_not_block(void)
{
    fm_vec3_t seg[2] = { V(0, 0.5f, 0), V(0, 1.5f, 0) };
    fm_vec3_t d = V(0.5f, 1.0f, 0);
    coll_prim_hit_t h;
    TEST_ASSERT_FALSE(coll_capsule_triangle_sweep(seg, 0.5f, &d, floor_tri, 1.0f, &h));
    fm_vec3_t seg2[2] = { V(0, 0.5f - 5e-5f, 0), V(0, 1.5f, 0) };
    TEST_ASSERT_FALSE(coll_capsule_triangle_sweep(seg2, 0.5f, &d, floor_tri, 1.0f, &h));
    /* touching an edge and moving away from it */
    fm_vec3_t tri[3] = { V(1, 0, -1), V(1, 0, 1), V(-2, 0, 0) };
    fm_vec3_t seg3[2] = { V(1.5f, 0, -0.2f), V(1.5f, 0, 0.2f) };
    fm_vec3_t away = V(1, 0.2f, 0.3f);
    TEST_ASSERT_FALSE(coll_capsule_triangle_sweep(seg3, 0.5f, &away, tri, 1.0f, &h));
    /* touching and moving in: blocked at t = 0 with depth 0 */
    fm_vec3_t in = V(0, -1, 0);
    TEST_ASSERT_TRUE(coll_capsule_triangle_sweep(seg, 0.5f, &in, floor_tri, 1.0f, &h));
    TEST_ASSERT_EQUAL_FLOAT(0.0f, h.t);
    TEST_ASSERT_EQUAL_FLOAT(0.0f, h.depth);
    TEST_ASSERT_FLOAT_WITHIN(1e-6f, 1.0f, h.normal.y);
    /* a motion that ends within the tolerance is not a hit either */
    fm_vec3_t seg4[2] = { V(0, 1.0f, 0), V(0, 2.0f, 0) };
    fm_vec3_t land = V(0, -0.50005f, 0);
    TEST_ASSERT_FALSE(coll_capsule_triangle_sweep(seg4, 0.5f, &land, floor_tri, 1.0f, &h));
    land = V(0, -0.5003f, 0);
    TEST_ASSERT_TRUE(coll_capsule_triangle_sweep(seg4, 0.5f, &land, floor_tri, 1.0f, &h));
    TEST_ASSERT_FLOAT_WITHIN(1e-6f, 0.5f / 0.5003f, h.t);
}

static void test_initial_overlap(void)
{
    coll_prim_hit_t h, o;
    fm_vec3_t d = V(1, -1, 0);
    /* end sphere 0.2 into the floor */
    fm_vec3_t seg[2] = { V(0, 0.3f, 0), V(0, 1.3f, 0) };
    TEST_ASSERT_TRUE(coll_capsule_triangle_sweep(seg, 0.5f, &d, floor_tri, 1.0f, &h));
    TEST_ASSERT_EQUAL_FLOAT(0.0f, h.t);
    TEST_ASSERT_FLOAT_WITHIN(1e-6f, 0.2f, h.depth);
    TEST_ASSERT_FLOAT_WITHIN(1e-6f, 1.0f, h.normal.y);
    TEST_ASSERT_TRUE(coll_capsule_triangle_overlap(seg, 0.5f, floor_tri, &o));
    TEST_ASSERT_FLOAT_WITHIN(1e-6f, 0.2f, o.depth);
    /* moving away still reports the overlap */
    fm_vec3_t up = V(0, 1, 0);
    TEST_ASSERT_TRUE(coll_capsule_triangle_sweep(seg, 0.5f, &up, floor_tri, 1.0f, &h));
    TEST_ASSERT_FLOAT_WITHIN(1e-6f, 0.2f, h.depth);
    /* segment crosses the plane: push to the centre's side, clearing the lower end by r */
    fm_vec3_t cross[2] = { V(0, -0.3f, 0), V(0.2f, 1.0f, 0) };
    TEST_ASSERT_TRUE(coll_capsule_triangle_overlap(cross, 0.5f, floor_tri, &o));
    TEST_ASSERT_FLOAT_WITHIN(1e-6f, 0.8f, o.depth);
    TEST_ASSERT_FLOAT_WITHIN(1e-6f, 1.0f, o.normal.y);
    fm_vec3_t cross2[2] = { V(0, 0.3f, 0), V(0.2f, -1.0f, 0) };
    TEST_ASSERT_TRUE(coll_capsule_triangle_overlap(cross2, 0.5f, floor_tri, &o));
    TEST_ASSERT_FLOAT_WITHIN(1e-6f, 0.8f, o.depth);
    TEST_ASSERT_FLOAT_WITHIN(1e-6f, -1.0f, o.normal.y);
    TEST_ASSERT_TRUE(coll_capsule_triangle_sweep(cross2, 0.5f, &d, floor_tri, 1.0f, &h));
    TEST_ASSERT_EQUAL_FLOAT(0.0f, h.t);
    TEST_ASSERT_FLOAT_WITHIN(1e-6f, 0.8f, h.depth);
    /* overlapping an edge from the side: push-out away from the edge */
    fm_vec3_t tri[3] = { V(1, 0, -1), V(1, 0, 1), V(-2, 0, 0) };
    fm_vec3_t side[2] = { V(1.3f, 0.4f, -0.2f), V(1.3f, 0.4f, 0.2f) };
    TEST_ASSERT_TRUE(coll_capsule_triangle_overlap(side, 0.6f, tri, &o));
    TEST_ASSERT_FLOAT_WITHIN(1e-6f, 0.1f, o.depth);
    TEST_ASSERT_FLOAT_WITHIN(1e-5f, 0.6f, o.normal.x);
    TEST_ASSERT_FLOAT_WITHIN(1e-5f, 0.8f, o.normal.y);
    /* within the touch tolerance: not an overlap */
    fm_vec3_t touch[2] = { V(0, 0.5f - 5e-5f, 0), V(0, 1.5f, 0) };
    TEST_ASSERT_FALSE(coll_capsule_triangle_overlap(touch, 0.5f, floor_tri, &o));
    fm_vec3_t pen[2] = { V(0, 0.5f - 3e-4f, 0), V(0, 1.5f, 0) };
    TEST_ASSERT_TRUE(coll_capsule_triangle_overlap(pen, 0.5f, floor_tri, &o));
    TEST_ASSERT_FLOAT_WITHIN(1e-6f, 3e-4f, o.depth);
}

static void test_sphere_and_zero_displacement(void)
{
    coll_prim_hit_t h;
    fm_vec3_t sph[2] = { V(0, 2, 0), V(0, 2, 0) };
    fm_vec3_t d = V(0, -4, 0);
    TEST_ASSERT_TRUE(coll_capsule_triangle_sweep(sph, 0.5f, &d, floor_tri, 1.0f, &h));
    TEST_ASSERT_FLOAT_WITHIN(1e-6f, 1.5f / 4.0f, h.t);
    /* sphere against an edge */
    fm_vec3_t tri[3] = { V(1, 0, -1), V(1, 0, 1), V(-2, 0, 0) };
    fm_vec3_t s2[2] = { V(3, 0.3f, 0), V(3, 0.3f, 0) };
    fm_vec3_t dx = V(-4, 0, 0);
    TEST_ASSERT_TRUE(coll_capsule_triangle_sweep(s2, 0.5f, &dx, tri, 1.0f, &h));
    TEST_ASSERT_FLOAT_WITHIN(1e-6f, 0.4f, h.t);
    /* zero displacement: only an overlap counts */
    fm_vec3_t z = V(0, 0, 0);
    TEST_ASSERT_FALSE(coll_capsule_triangle_sweep(sph, 0.5f, &z, floor_tri, 1.0f, &h));
    fm_vec3_t low[2] = { V(0, 0.2f, 0), V(0, 0.2f, 0) };
    TEST_ASSERT_TRUE(coll_capsule_triangle_sweep(low, 0.5f, &z, floor_tri, 1.0f, &h));
    TEST_ASSERT_FLOAT_WITHIN(1e-6f, 0.3f, h.depth);
    /* t_max = 0 behaves like zero displacement */
    TEST_ASSERT_FALSE(coll_capsule_triangle_sweep(sph, 0.5f, &d, floor_tri, 0.0f, &h));
}

static void test_degenerate_input_never_nan(void)
{
    coll_prim_hit_t h;
    fm_vec3_t pt[3] = { V(1, 1, 1), V(1, 1, 1), V(1, 1, 1) };
    fm_vec3_t line[3] = { V(0, 0, 0), V(1, 0, 0), V(2, 0, 0) };
    fm_vec3_t seg[2] = { V(0, 3, 0), V(0, 4, 0) };
    fm_vec3_t d = V(0.5f, -5, 0.2f);
    const fm_vec3_t *tris[2] = { pt, line };
    for (int i = 0; i < 2; i++) {
        if (coll_capsule_triangle_sweep(seg, 0.5f, &d, tris[i], 1.0f, &h)) {
            TEST_ASSERT_TRUE(isfinite(h.t) && isfinite(h.normal.x) && isfinite(h.normal.y) && isfinite(h.normal.z));
            TEST_ASSERT_FLOAT_WITHIN(1e-4f, 1.0f, sqrtf(h.normal.x * h.normal.x + h.normal.y * h.normal.y + h.normal.z * h.normal.z));
        }
        fm_vec3_t on[2] = { V(1, 1, 1), V(1, 1, 1) };
        if (coll_capsule_triangle_overlap(on, 0.5f, tris[i], &h)) {
            TEST_ASSERT_TRUE(isfinite(h.depth) && isfinite(h.normal.x) && isfinite(h.normal.y));
        }
        fm_vec3_t o = V(0.5f, 5, 0), rd = V(0, -1, 0);
        if (coll_ray_triangle(&o, &rd, tris[i], 100.0f, &h)) { TEST_ASSERT_TRUE(isfinite(h.t)); }
    }
    /* the degenerate (line) triangle is still hit as a segment */
    TEST_ASSERT_TRUE(coll_capsule_triangle_sweep(seg, 0.5f, &d, line, 1.0f, &h));
    /* NaN / inf / negative radius: rejected */
    fm_vec3_t nan_seg[2] = { V(NAN, 0, 0), V(0, 1, 0) };
    TEST_ASSERT_FALSE(coll_capsule_triangle_sweep(nan_seg, 0.5f, &d, floor_tri, 1.0f, &h));
    TEST_ASSERT_FALSE(coll_capsule_triangle_overlap(nan_seg, 0.5f, floor_tri, &h));
    TEST_ASSERT_FALSE(coll_capsule_triangle_sweep(seg, -1.0f, &d, floor_tri, 1.0f, &h));
    TEST_ASSERT_FALSE(coll_capsule_triangle_sweep(seg, NAN, &d, floor_tri, 1.0f, &h));
    fm_vec3_t inf_d = V(INFINITY, 0, 0);
    TEST_ASSERT_FALSE(coll_capsule_triangle_sweep(seg, 0.5f, &inf_d, floor_tri, 1.0f, &h));
    fm_vec3_t o = V(0, 5, 0), zero = V(0, 0, 0);
    TEST_ASSERT_FALSE(coll_ray_triangle(&o, &zero, floor_tri, 10.0f, &h));
    /* beyond 1e7 m from the query origin: rejected, not overflowed */
    fm_vec3_t huge[3] = { V(1e30f, 0, 0), V(0, 1e30f, 0), V(0, 0, 1e30f) };
    fm_vec3_t far_seg[2] = { V(-1e30f, 0, 0), V(1e30f, 0, 0) };
    TEST_ASSERT_FALSE(coll_capsule_triangle_sweep(seg, 0.5f, &d, huge, 1.0f, &h));
    TEST_ASSERT_FALSE(coll_capsule_triangle_sweep(far_seg, 0.5f, &d, floor_tri, 1.0f, &h));
    TEST_ASSERT_FALSE(coll_capsule_triangle_sweep(seg, 0.5f, &d, floor_tri, 1e30f, &h));
    TEST_ASSERT_FALSE(coll_capsule_triangle_overlap(far_seg, 0.5f, floor_tri, &h));
    TEST_ASSERT_FALSE(coll_ray_triangle(&o, &d, huge, 1e30f, &h));
}

/* Extreme but valid scales (1e-5 .. 1e5 m): every reported hit is finite with a unit normal. */
static void test_extreme_scales_finite(void)
{
    int hits = 0;
    for (int i = 0; i < 3000; i++) {
        double L = pow(10, rnd_range(-5, 5));
        prim_ref_v3 rt[3];
        random_triangle(rt, L);
        fm_vec3_t tri[3] = { F(rt[0]), F(rt[1]), F(rt[2]) };
        double r = pow(10, rnd_range(-5, 4)), hh = rnd() < 0.3 ? 0 : pow(10, rnd_range(-5, 4));
        prim_ref_v3 c = prim_ref_scale(rnd_unit(), pow(10, rnd_range(-5, 5))), a = rnd_unit();
        fm_vec3_t seg[2] = { F(prim_ref_sub(c, prim_ref_scale(a, hh))), F(prim_ref_add(c, prim_ref_scale(a, hh))) };
        fm_vec3_t d = F(prim_ref_scale(prim_ref_sub(rt[0], c), rnd_range(0, 2)));
        for (int k = 0; k < 3; k++) {
            coll_prim_hit_t h;
            bool got = k == 0 ? coll_capsule_triangle_sweep(seg, (float)r, &d, tri, 1.0f, &h)
                     : k == 1 ? coll_capsule_triangle_overlap(seg, (float)r, tri, &h)
                              : coll_ray_triangle(&seg[0], &d, tri, 1.0f, &h);
            if (!got) continue;
            hits++;
            float nl = sqrtf(h.normal.x * h.normal.x + h.normal.y * h.normal.y + h.normal.z * h.normal.z);
            TEST_ASSERT_TRUE(isfinite(h.t) && h.t >= 0.0f && h.t <= 1.0f && isfinite(h.depth) && h.depth >= 0.0f);
            TEST_ASSERT_FLOAT_WITHIN(1e-3f, 1.0f, nl);
            TEST_ASSERT_TRUE(isfinite(h.point.x) && isfinite(h.point.y) && isfinite(h.point.z));
        }
    }
    TEST_ASSERT_TRUE(hits > 100);
}

static bool g_custom_called;
static bool custom_sweep(void *ctx, const fm_vec3_t seg[2], float r, const fm_vec3_t *disp,
                         const fm_vec3_t tri[3], float t_max, coll_prim_hit_t *hit)
{
    (void)seg; (void)r; (void)disp; (void)tri; (void)t_max;
    g_custom_called = true;
    hit->t = *(float *)ctx;
    return true;
}

static void test_sweep_method_dispatch(void)
{
    fm_vec3_t seg[2] = { V(0, 2, 0), V(0, 3, 0) };
    fm_vec3_t d = V(0, -4, 0);
    coll_prim_hit_t h;
    TEST_ASSERT_TRUE(coll_tri_sweep(seg, 0.5f, &d, floor_tri, 1.0f, &h));
    TEST_ASSERT_FLOAT_WITHIN(1e-6f, 0.375f, h.t);
    float magic = 0.125f;
    coll_set_tri_sweep_method(custom_sweep, &magic);
    TEST_ASSERT_TRUE(coll_tri_sweep(seg, 0.5f, &d, floor_tri, 1.0f, &h));
    TEST_ASSERT_TRUE(g_custom_called);
    TEST_ASSERT_EQUAL_FLOAT(0.125f, h.t);
    coll_set_tri_sweep_method(NULL, NULL);
    TEST_ASSERT_TRUE(coll_tri_sweep(seg, 0.5f, &d, floor_tri, 1.0f, &h));
    TEST_ASSERT_FLOAT_WITHIN(1e-6f, 0.375f, h.t);
}

static void test_no_allocation(void)
{
    fm_vec3_t seg[2] = { V(0, 2, 0), V(0.3f, 3, 0) };
    fm_vec3_t d = V(0.2f, -4, 0.1f), o = V(0, 5, 0), rd = V(0.1f, -1, 0);
    coll_prim_hit_t h;
    ASSERT_NO_ALLOC(coll_capsule_triangle_sweep(seg, 0.5f, &d, floor_tri, 1.0f, &h));
    ASSERT_NO_ALLOC(coll_capsule_triangle_overlap(seg, 0.5f, floor_tri, &h));
    ASSERT_NO_ALLOC(coll_ray_triangle(&o, &rd, floor_tri, 10.0f, &h));
    ASSERT_NO_ALLOC(coll_tri_sweep(seg, 0.5f, &d, floor_tri, 1.0f, &h));
}

/* ------------------------------------------------------------------ random vs reference */

static void random_triangle(prim_ref_v3 tri[3], double L)
{
    int kind = (int)(rnd() * 5);
    prim_ref_v3 c = prim_ref_scale(rnd_unit(), L * rnd());
    if (kind <= 1) {                       /* ordinary */
        for (int i = 0; i < 3; i++) tri[i] = prim_ref_add(c, prim_ref_scale(rnd_unit(), L * rnd_range(0.2, 1)));
    } else if (kind == 2) {                /* long thin needle */
        prim_ref_v3 ax = rnd_unit(), side = prim_ref_cross(ax, rnd_unit());
        side = prim_ref_scale(side, 1 / prim_ref_len(side));
        double w = L * pow(10, rnd_range(-4, -1));
        tri[0] = prim_ref_add(c, prim_ref_scale(ax, -L));
        tri[1] = prim_ref_add(c, prim_ref_scale(ax, L));
        tri[2] = prim_ref_add(tri[rnd() < 0.5 ? 0 : 1], prim_ref_scale(side, w));
    } else if (kind == 3) {                /* flat sliver: apex near the long edge */
        prim_ref_v3 ax = rnd_unit(), side = prim_ref_cross(ax, rnd_unit());
        side = prim_ref_scale(side, 1 / prim_ref_len(side));
        double h = L * pow(10, rnd_range(-4, -1));
        tri[0] = prim_ref_add(c, prim_ref_scale(ax, -L));
        tri[1] = prim_ref_add(c, prim_ref_scale(ax, L));
        tri[2] = prim_ref_add(prim_ref_add(c, prim_ref_scale(ax, L * rnd_range(-0.9, 0.9))), prim_ref_scale(side, h));
    } else {                               /* large floor-like */
        prim_ref_v3 n = rnd_unit(), u = prim_ref_cross(n, rnd_unit());
        u = prim_ref_scale(u, 1 / prim_ref_len(u));
        prim_ref_v3 w = prim_ref_cross(n, u);
        for (int i = 0; i < 3; i++) {
            double a = 2.0944 * i + rnd_range(-0.5, 0.5);
            tri[i] = prim_ref_add(c, prim_ref_add(prim_ref_scale(u, 3 * L * cos(a)), prim_ref_scale(w, 3 * L * sin(a))));
        }
    }
}

static void dump_case(const fm_vec3_t seg[2], float r, fm_vec3_t d, const fm_vec3_t tri[3])
{
    printf("case: seg {%.9g,%.9g,%.9g} {%.9g,%.9g,%.9g} r %.9g d {%.9g,%.9g,%.9g}\n      tri {%.9g,%.9g,%.9g} {%.9g,%.9g,%.9g} {%.9g,%.9g,%.9g}\n",
           seg[0].x, seg[0].y, seg[0].z, seg[1].x, seg[1].y, seg[1].z, r, d.x, d.y, d.z,
           tri[0].x, tri[0].y, tri[0].z, tri[1].x, tri[1].y, tri[1].z, tri[2].x, tri[2].y, tri[2].z);
}

typedef struct {
    int n, hits, overlaps, grazing, ambiguous, checked_t;
    double max_dt_rel, max_dt_m, max_dt_rel_graze_perp, max_dn_face, max_dn_feat, max_depth_err, max_fdev;
} sweep_stats_t;

static void check_sweep_case(sweep_stats_t *st, const fm_vec3_t seg[2], float fr, fm_vec3_t fd, const fm_vec3_t tri[3]);

static void random_sweep_once(sweep_stats_t *st, double offset_scale, bool touching)
{
    prim_ref_v3 rt[3];
    double L = pow(10, rnd_range(-1, 1.2));
    random_triangle(rt, L);
    double r = exp(rnd_range(log(0.02), log(10.0)));
    double hh = rnd() < 0.15 ? 0 : rnd_range(0, 2) * (rnd() < 0.5 ? r : 1);
    prim_ref_v3 ax = rnd_unit();
    if (rnd() < 0.15) { /* capsule axis nearly parallel to an edge (1e-7 .. 1e-2 rad) */
        int k = (int)(rnd() * 3);
        prim_ref_v3 e = prim_ref_sub(rt[(k + 1) % 3], rt[k]);
        double el = prim_ref_len(e);
        if (el > 0) ax = prim_ref_add(prim_ref_scale(e, 1 / el), prim_ref_scale(rnd_unit(), pow(10, rnd_range(-7, -2))));
        ax = prim_ref_scale(ax, 1 / prim_ref_len(ax));
    }
    /* a point on the triangle as target */
    double b1 = rnd(), b2 = rnd();
    if (b1 + b2 > 1) { b1 = 1 - b1; b2 = 1 - b2; }
    prim_ref_v3 tp = prim_ref_add(rt[0], prim_ref_add(prim_ref_scale(prim_ref_sub(rt[1], rt[0]), b1),
                                                       prim_ref_scale(prim_ref_sub(rt[2], rt[0]), b2)));
    prim_ref_v3 start = prim_ref_add(tp, prim_ref_scale(rnd_unit(), (r + hh) * rnd_range(0.5, 3) + L * rnd_range(0, 0.5)));
    prim_ref_v3 dir = prim_ref_sub(prim_ref_add(tp, prim_ref_scale(rnd_unit(), rnd_range(0, r + hh + 0.3 * L))), start);
    double dl = prim_ref_len(dir);
    prim_ref_v3 d = prim_ref_scale(dir, rnd_range(0.3, 2.5));
    if (rnd() < 0.1) { /* motion parallel to the face */
        prim_ref_v3 n = prim_ref_cross(prim_ref_sub(rt[1], rt[0]), prim_ref_sub(rt[2], rt[0]));
        double nn = prim_ref_dot(n, n);
        if (nn > 0) d = prim_ref_sub(d, prim_ref_scale(n, prim_ref_dot(d, n) / nn));
    }
    (void)dl;
    if (touching) {
        /* Start exactly touching or within the tolerance, then slide along the contact
         * tangent, along the face, away from it, or slightly into it. */
        prim_ref_v3 ps, pt;
        prim_ref_v3 a0 = prim_ref_sub(start, prim_ref_scale(ax, hh)), b0 = prim_ref_add(start, prim_ref_scale(ax, hh));
        double dist = prim_ref_seg_tri(a0, b0, rt, &ps, &pt);
        if (dist < 1e-6) return;
        prim_ref_v3 n = prim_ref_scale(prim_ref_sub(ps, pt), 1 / dist);
        static const double deltas[] = { 0, 1e-6, -1e-6, 1e-5, -2e-5, -5e-5, -8e-5 };
        double delta = deltas[rnd_u32() % 7];
        start = prim_ref_add(start, prim_ref_scale(n, r + delta - dist));
        prim_ref_v3 tn = prim_ref_cross(prim_ref_sub(rt[1], rt[0]), prim_ref_sub(rt[2], rt[0]));
        double tl = prim_ref_len(tn);
        prim_ref_v3 v = prim_ref_scale(rnd_unit(), rnd_range(0.1, 3));
        switch (rnd_u32() % 4) {
        case 0: d = prim_ref_sub(v, prim_ref_scale(n, prim_ref_dot(v, n))); break;            /* tangent */
        case 1: d = tl > 0 ? prim_ref_sub(v, prim_ref_scale(tn, prim_ref_dot(v, tn) / (tl * tl))) : v; break; /* along face */
        case 2: d = prim_ref_add(prim_ref_sub(v, prim_ref_scale(n, prim_ref_dot(v, n))), prim_ref_scale(n, rnd_range(0, 1))); break;
        default: d = prim_ref_sub(prim_ref_sub(v, prim_ref_scale(n, prim_ref_dot(v, n))), prim_ref_scale(n, pow(10, rnd_range(-5, -1)))); break;
        }
    }
    /* World coordinates offset from the origin by up to offset_scale and rounded to float
     * there, then made relative to the capsule centre in float, as the scene code does. */
    prim_ref_v3 off = prim_ref_scale(rnd_unit(), offset_scale * rnd());
    fm_vec3_t tri[3], seg[2], fd;
    fm_vec3_t wc = F(prim_ref_add(start, off));
    for (int i = 0; i < 3; i++) {
        fm_vec3_t w = F(prim_ref_add(rt[i], off));
        tri[i] = V(w.x - wc.x, w.y - wc.y, w.z - wc.z);
    }
    fm_vec3_t fax = F(prim_ref_scale(ax, hh));
    seg[0] = V(-fax.x, -fax.y, -fax.z);
    seg[1] = fax;
    fd = F(d);
    check_sweep_case(st, seg, (float)r, fd, tri);
}

/* One float sweep against the double-precision reference (hit or miss, time, normal). */
static void check_sweep_case(sweep_stats_t *st, const fm_vec3_t seg[2], float fr, fm_vec3_t fd, const fm_vec3_t tri[3])
{
    /* the reference sees exactly the float inputs */
    prim_ref_captri_t ctx;
    ctx.a = R(seg[0]); ctx.b = R(seg[1]); ctx.d = R(fd);
    for (int i = 0; i < 3; i++) ctx.tri[i] = R(tri[i]);
    double rr = fr;
    double tol = fmin(1e-4, rr / 4);
    prim_ref_sweep_t ref;
    prim_ref_sweep(prim_ref_captri_fn, &ctx, rr, 1.0, &ref);

    double scale = 1.0;
    for (int i = 0; i < 3; i++) {
        scale = fmax(scale, fabs(tri[i].x)); scale = fmax(scale, fabs(tri[i].y)); scale = fmax(scale, fabs(tri[i].z));
    }
    for (int i = 0; i < 2; i++) {
        scale = fmax(scale, fabs(seg[i].x)); scale = fmax(scale, fabs(seg[i].y)); scale = fmax(scale, fabs(seg[i].z));
    }
    scale = fmax(scale, rr);
    double margin = 3e-6 * scale;  /* a few float ulps of the largest coordinate */

    coll_prim_hit_t h;
    bool got = coll_capsule_triangle_sweep(seg, fr, &fd, tri, 1.0f, &h);
    st->n++;
    bool expect = ref.fmin < rr - tol;
    if (fabs(ref.fmin - (rr - tol)) < margin || fabs(ref.f0 - (rr - tol)) < margin) { st->ambiguous++; return; }
    if (got != expect) {
        char msg[400];
        snprintf(msg, sizeof msg, "hit mismatch: got %d expect %d f0=%.9g fmin=%.9g r=%.9g t_first=%.9g",
                 got, expect, ref.f0, ref.fmin, rr, ref.t_first);
        TEST_FAIL_MESSAGE(msg);
    }
    if (!got) return;
    st->hits++;
    TEST_ASSERT_TRUE(isfinite(h.t) && h.t >= 0 && h.t <= 1);
    double nl = sqrt((double)h.normal.x * h.normal.x + (double)h.normal.y * h.normal.y + (double)h.normal.z * h.normal.z);
    TEST_ASSERT_DOUBLE_WITHIN(1e-5, 1.0, nl);
    if (ref.f0 < rr - tol) {          /* overlap */
        st->overlaps++;
        TEST_ASSERT_EQUAL_FLOAT(0.0f, h.t);
        TEST_ASSERT_TRUE(h.depth > 0);
        if (ref.f0 > 1e-3 * fmax(1, rr)) {
            double e = fabs(h.depth - (rr - ref.f0));
            if (e > st->max_depth_err) st->max_depth_err = e;
            TEST_ASSERT_TRUE_MESSAGE(e < 2 * margin + 1e-6, "overlap depth");
            prim_ref_v3 n0;
            prim_ref_captri_fn(&ctx, 0, &n0);
            double a = ang(h.normal, n0);
            if (a > st->max_dn_feat) st->max_dn_feat = a;
            if (!(a < 2e-3)) {
                char msg[400];
                snprintf(msg, sizeof msg, "overlap normal err %.3g: f0 %.9g r %.9g n (%g %g %g) ref (%g %g %g)",
                         a, ref.f0, rr, h.normal.x, h.normal.y, h.normal.z, n0.x, n0.y, n0.z);
                dump_case(seg, fr, fd, tri);
                TEST_FAIL_MESSAGE(msg);
            }
        } else {
            TEST_ASSERT_TRUE(h.depth >= rr - ref.f0 - margin);
        }
        return;
    }
    TEST_ASSERT_EQUAL_FLOAT(0.0f, h.depth);
    /* the reported time is a touching time: distance == r there (or t = 0 and <= r) */
    double ft = prim_ref_captri_fn(&ctx, h.t, NULL);
    double dev = h.t > 0 ? fabs(ft - rr) : fmax(0, ft - rr);
    if (dev > st->max_fdev) st->max_fdev = dev;
    TEST_ASSERT_TRUE_MESSAGE(dev < 4 * margin + 1e-6, "distance at reported t is not r");
    double dlen = prim_ref_len(ctx.d);
    double vn = -prim_ref_dot(ref.n, ctx.d) / dlen; /* approach speed along the normal, unit d */
    double dt = fabs(h.t - ref.t_first);
    if (vn > 0.05) {
        st->checked_t++;
        /* error in meters along d, and relative to |d| for non-tiny motions */
        if (dt * dlen > st->max_dt_m) st->max_dt_m = dt * dlen;
        if (dlen >= 0.1 && dt > st->max_dt_rel) st->max_dt_rel = dt;
        char msg[300];
        snprintf(msg, sizeof msg, "t %.9g vs ref %.9g (vn %.3g |d| %.3g r %.3g)", h.t, ref.t_first, vn, dlen, rr);
        if (getenv("PRIM_DUMP_T") && dt > atof(getenv("PRIM_DUMP_T"))) { printf("%s\n", msg); dump_case(seg, fr, fd, tri); }
        TEST_ASSERT_TRUE_MESSAGE(dt * dlen <= 1e-4 * fmax(1.0, dlen) * 0.1 + 4 * margin / vn, msg);
        double a = ang(h.normal, ref.n);
        if (a > st->max_dn_feat) st->max_dn_feat = a;
        if (!(a < 1e-3) || (getenv("PRIM_DUMP_N") && a > atof(getenv("PRIM_DUMP_N")))) {
            char msg2[400];
            snprintf(msg2, sizeof msg2, "contact normal err %.3g: t %.9g ref %.9g vn %.3g r %.9g n (%g %g %g) ref (%g %g %g)",
                     a, h.t, ref.t_first, vn, rr, h.normal.x, h.normal.y, h.normal.z, ref.n.x, ref.n.y, ref.n.z);
            dump_case(seg, fr, fd, tri);
            if (!(a < 1e-3)) TEST_FAIL_MESSAGE(msg2);
            printf("%s\n", msg2);
        }
    } else {
        st->grazing++;
        double perp = dt * dlen * fmax(vn, 0);
        if (perp > st->max_dt_rel_graze_perp) st->max_dt_rel_graze_perp = perp;
    }
}

static void report_sweep(const char *name, const sweep_stats_t *st)
{
    printf("%s: %d sweeps, %d hits (%d overlaps, %d grazing), %d ambiguous; t checked on %d: max |dt|*|d| %.3g m, "
           "max |dt| (|d| >= 0.1 m) %.3g, max normal err %.3g rad, max depth err %.3g m, max |dist(t)-r| %.3g m, "
           "grazing max dt*vn*|d| %.3g m\n",
           name, st->n, st->hits, st->overlaps, st->grazing, st->ambiguous, st->checked_t, st->max_dt_m, st->max_dt_rel,
           st->max_dn_feat, st->max_depth_err, st->max_fdev, st->max_dt_rel_graze_perp);
}

static void test_random_sweeps_match_reference(void)
{
    sweep_stats_t st = { 0 };
    for (int i = 0; i < N_RANDOM_SWEEPS; i++) random_sweep_once(&st, 0.0, false);
    report_sweep("near origin", &st);
    TEST_ASSERT_TRUE(st.hits > N_RANDOM_SWEEPS / 4);
    TEST_ASSERT_TRUE(st.ambiguous < N_RANDOM_SWEEPS / 100);
}

static void test_random_touching_sweeps(void)
{
    sweep_stats_t st = { 0 };
    for (int i = 0; i < N_RANDOM_SWEEPS / 2; i++) random_sweep_once(&st, 0.0, true);
    report_sweep("starting in touch (sliding, leaving, entering)", &st);
    TEST_ASSERT_TRUE(st.hits > N_RANDOM_SWEEPS / 40);
    TEST_ASSERT_TRUE(st.n - st.hits > N_RANDOM_SWEEPS / 10);
}

static void test_random_sweeps_far_from_origin(void)
{
    sweep_stats_t st = { 0 };
    for (int i = 0; i < N_RANDOM_SWEEPS / 4; i++) random_sweep_once(&st, 1000.0, false);
    report_sweep("world offset up to 1 km, relative to the capsule", &st);
    TEST_ASSERT_TRUE(st.hits > N_RANDOM_SWEEPS / 20);
}

/* ------------------------------------------------------------------ ray */

static bool ref_ray_tri(prim_ref_v3 o, prim_ref_v3 d, const prim_ref_v3 t[3], double *s, double *bmin)
{
    prim_ref_v3 e1 = prim_ref_sub(t[1], t[0]), e2 = prim_ref_sub(t[2], t[0]);
    prim_ref_v3 p = prim_ref_cross(d, e2);
    double det = prim_ref_dot(e1, p);
    if (det == 0) return false;
    prim_ref_v3 tv = prim_ref_sub(o, t[0]);
    double u = prim_ref_dot(tv, p) / det;
    prim_ref_v3 q = prim_ref_cross(tv, e1);
    double v = prim_ref_dot(d, q) / det;
    *s = prim_ref_dot(e2, q) / det;
    *bmin = fmin(u, fmin(v, 1 - u - v));
    return *bmin >= 0;
}

static void test_random_rays_match_reference(void)
{
    int hits = 0, amb = 0;
    double max_ds = 0, max_pt = 0, max_perp = 0;
    for (int i = 0; i < N_RANDOM_RAYS; i++) {
        prim_ref_v3 rt[3];
        double L = pow(10, rnd_range(-1, 1.2));
        random_triangle(rt, L);
        fm_vec3_t tri[3];
        for (int k = 0; k < 3; k++) { tri[k] = F(rt[k]); rt[k] = R(tri[k]); }
        prim_ref_v3 target = prim_ref_add(rt[0], prim_ref_add(prim_ref_scale(prim_ref_sub(rt[1], rt[0]), rnd_range(-0.2, 1)),
                                                               prim_ref_scale(prim_ref_sub(rt[2], rt[0]), rnd_range(-0.2, 1))));
        fm_vec3_t o = F(prim_ref_add(target, prim_ref_scale(rnd_unit(), L * rnd_range(0.1, 3))));
        fm_vec3_t d = F(prim_ref_scale(prim_ref_sub(target, R(o)), rnd_range(0.5, 2)));
        double s_ref = -1, bmin = -1;
        bool expect = ref_ray_tri(R(o), R(d), rt, &s_ref, &bmin) && s_ref >= 0 && s_ref <= 1;
        coll_prim_hit_t h;
        bool got = coll_ray_triangle(&o, &d, tri, 1.0f, &h);
        prim_ref_v3 n = prim_ref_cross(prim_ref_sub(rt[1], rt[0]), prim_ref_sub(rt[2], rt[0]));
        double cosang = fabs(prim_ref_dot(n, R(d))) / (prim_ref_len(n) * prim_ref_len(R(d)));
        double lm = 0;
        for (int k = 0; k < 3; k++) lm = fmax(lm, prim_ref_len(prim_ref_sub(rt[(k + 1) % 3], rt[k])));
        /* barycentric resolution of float edge functions on the projected triangle */
        double bres = 1e-5 + 16 * 1.2e-7 * lm * lm / (prim_ref_len(n) * fmax(cosang, 1e-9));
        if (fabs(bmin) < bres || fabs(s_ref) < 1e-5 || fabs(s_ref - 1) < 1e-5 || cosang < 1e-3 ||
            !isfinite(s_ref)) { amb++; continue; }
        if (expect != got) {
            char msg[300];
            snprintf(msg, sizeof msg, "ray hit mismatch: got %d expect %d (bmin %.3g s_ref %.9g s %.9g cos %.3g L %.3g)",
                     got, expect, bmin, s_ref, got ? h.t : -1.0f, cosang, L);
            TEST_FAIL_MESSAGE(msg);
        }
        if (!got) continue;
        hits++;
        double ds = fabs(h.t - s_ref) * prim_ref_len(R(d));
        if (ds > max_ds) max_ds = ds;
        /* float conditioning of the plane of a sliver: tilt ~ eps * Lmax / height */
        double lmax = 0;
        for (int k = 0; k < 3; k++) lmax = fmax(lmax, prim_ref_len(prim_ref_sub(rt[(k + 1) % 3], rt[k])));
        double height = prim_ref_len(n) / lmax;
        double bound = (1e-5 * fmax(1, L) + 8 * 1.2e-7 * lmax * lmax / height) / cosang;
        if (ds * cosang > max_perp) max_perp = ds * cosang;
        if (!(ds < bound)) {
            char msg[200];
            snprintf(msg, sizeof msg, "ray distance err %.3g (L %.3g cos %.3g s %.9g ref %.9g)", ds, L, cosang, h.t, s_ref);
            TEST_FAIL_MESSAGE(msg);
        }
        TEST_ASSERT_TRUE(prim_ref_dot(R(h.normal), R(d)) <= 0);
        prim_ref_v3 p = prim_ref_add(R(o), prim_ref_scale(R(d), s_ref));
        double pe = prim_ref_len(prim_ref_sub(p, R(h.point)));
        if (pe > max_pt) max_pt = pe;
    }
    printf("rays: %d random, %d hits, %d near edges/grazing skipped; max distance err %.3g m "
           "(perpendicular to the plane %.3g m), max point err %.3g m\n", N_RANDOM_RAYS, hits, amb, max_ds, max_perp, max_pt);
    TEST_ASSERT_TRUE(hits > N_RANDOM_RAYS / 10);
}

static void test_ray_watertight_on_shared_edge(void)
{
    int trials = 0, both = 0, fails = 0;
    for (int i = 0; i < N_RANDOM_RAYS / 4; i++) {
        double L = pow(10, rnd_range(-1, 1.5));
        prim_ref_v3 c = prim_ref_scale(rnd_unit(), L * rnd_range(0, 10));
        fm_vec3_t A = F(prim_ref_add(c, prim_ref_scale(rnd_unit(), L)));
        fm_vec3_t B = F(prim_ref_add(c, prim_ref_scale(rnd_unit(), L)));
        fm_vec3_t P = F(prim_ref_add(c, prim_ref_scale(rnd_unit(), L)));
        fm_vec3_t Q = F(prim_ref_add(c, prim_ref_scale(rnd_unit(), L)));
        /* a folded quad with consistent winding: (A,B,P) and (B,A,Q), the second rotated so
         * the shared edge sits in different vertex slots */
        fm_vec3_t t1[3] = { A, B, P };
        fm_vec3_t t2[3];
        switch (i % 3) {
        case 0: t2[0] = B; t2[1] = A; t2[2] = Q; break;
        case 1: t2[0] = Q; t2[1] = B; t2[2] = A; break;
        default: t2[0] = A; t2[1] = Q; t2[2] = B; break;
        }
        prim_ref_v3 n1 = prim_ref_cross(prim_ref_sub(R(B), R(A)), prim_ref_sub(R(P), R(A)));
        prim_ref_v3 n2 = prim_ref_cross(prim_ref_sub(R(A), R(B)), prim_ref_sub(R(Q), R(B)));
        double w = rnd_range(0.02, 0.98);
        fm_vec3_t e = F(prim_ref_add(R(A), prim_ref_scale(prim_ref_sub(R(B), R(A)), w)));
        fm_vec3_t o = F(prim_ref_add(R(e), prim_ref_scale(rnd_unit(), L * rnd_range(0.5, 5))));
        fm_vec3_t d = F(prim_ref_scale(prim_ref_sub(R(e), R(o)), 2.0));
        /* Seen along the ray, the two halves lie on opposite sides of the shared edge when
         * the ray meets both from the same side (both front or both back): then the closed
         * union covers the edge and the ray must hit. Otherwise the ray looks into the fold's
         * gap and may miss both in exact arithmetic too. */
        double c1 = prim_ref_dot(n1, R(d)) / (prim_ref_len(n1) * prim_ref_len(R(d)));
        double c2 = prim_ref_dot(n2, R(d)) / (prim_ref_len(n2) * prim_ref_len(R(d)));
        if (!(c1 * c2 > 0) || fabs(c1) < 1e-3 || fabs(c2) < 1e-3) continue;
        trials++;
        coll_prim_hit_t h1, h2;
        bool g1 = coll_ray_triangle(&o, &d, t1, 1.0f, &h1);
        bool g2 = coll_ray_triangle(&o, &d, t2, 1.0f, &h2);
        if (g1 && g2) both++;
        if (!g1 && !g2) fails++;
    }
    TEST_ASSERT_EQUAL_INT_MESSAGE(0, fails, "ray slipped through the shared edge of a folded quad");
    TEST_ASSERT_TRUE(trials > N_RANDOM_RAYS / 20);
    /* coplanar quad, rays aimed at points on the diagonal from many directions */
    fm_vec3_t q0[3] = { V(0, 0, 0), V(1.3f, 0.1f, 0.2f), V(1.1f, 0.7f, 2.9f) };
    fm_vec3_t q1[3] = { V(0, 0, 0), V(1.1f, 0.7f, 2.9f), V(0.58f, 0.66f, 2.82f) }; /* planar */
    int slips = 0;
    for (int i = 0; i < N_RANDOM_RAYS / 4; i++) {
        float w = (float)rnd_range(0.001, 0.999);
        fm_vec3_t e = V(q0[2].x * w, q0[2].y * w, q0[2].z * w);
        prim_ref_v3 dir = rnd_unit();
        fm_vec3_t o = F(prim_ref_add(R(e), prim_ref_scale(dir, rnd_range(0.1, 30))));
        fm_vec3_t d = V(e.x - o.x, e.y - o.y, e.z - o.z);
        coll_prim_hit_t h;
        if (!coll_ray_triangle(&o, &d, q0, 2.0f, &h) && !coll_ray_triangle(&o, &d, q1, 2.0f, &h)) slips++;
    }
    printf("watertight: %d folded-edge rays (%d hit both), %d coplanar-diagonal rays, %d slipped\n",
           trials, both, N_RANDOM_RAYS / 4, slips);
    TEST_ASSERT_EQUAL_INT(0, slips);
}

static void test_ray_triangle_basics(void)
{
    coll_prim_hit_t h;
    fm_vec3_t o = V(1, 5, 1), d = V(0, -2, 0);
    TEST_ASSERT_TRUE(coll_ray_triangle(&o, &d, floor_tri, 10.0f, &h));
    TEST_ASSERT_FLOAT_WITHIN(1e-6f, 2.5f, h.t);
    TEST_ASSERT_FLOAT_WITHIN(1e-6f, 1.0f, h.normal.y);
    TEST_ASSERT_FLOAT_WITHIN(1e-5f, 1.0f, h.point.x);
    TEST_ASSERT_FLOAT_WITHIN(1e-5f, 0.0f, h.point.y);
    TEST_ASSERT_FALSE(coll_ray_triangle(&o, &d, floor_tri, 2.0f, &h));
    fm_vec3_t o2 = V(1, -5, 1), d2 = V(0, 1, 0);
    TEST_ASSERT_TRUE(coll_ray_triangle(&o2, &d2, floor_tri, 10.0f, &h));
    TEST_ASSERT_FLOAT_WITHIN(1e-6f, -1.0f, h.normal.y);
    fm_vec3_t away = V(0, 1, 0);
    TEST_ASSERT_FALSE(coll_ray_triangle(&o, &away, floor_tri, 10.0f, &h));
    fm_vec3_t par = V(1, 0, 0), o3 = V(-20, 0, 0);
    TEST_ASSERT_FALSE(coll_ray_triangle(&o3, &par, floor_tri, 100.0f, &h));
}


/* A triangle's prep (prim.h), filled by the first test and used by the later ones, gives
 * the plain tests' results to the bit, for the ray (sheared once, as the gathered ray
 * does), the sweep (held or not) and the overlap, on the
 * random triangles (needles and slivers among them). The gather keeps one per triangle. */
static bool hits_equal(bool ga, const coll_prim_hit_t *a, bool gb, const coll_prim_hit_t *b)
{
    return ga == gb && (!ga || memcmp(a, b, sizeof *a) == 0);
}

static void test_prepared_triangle_is_bit_identical(void)
{
    int n_hits = 0, n_prepared = 0, n_ray_hits = 0;
    for (int i = 0; i < N_RANDOM_SWEEPS / 4; i++) {
        prim_ref_v3 rt[3];
        double L = pow(10, rnd_range(-1, 1.2));
        random_triangle(rt, L);
        fm_vec3_t tri[3] = { V(0, 0, 0), F(prim_ref_sub(rt[1], rt[0])), F(prim_ref_sub(rt[2], rt[0])) };
        coll_tri_prep_t prep;
        memset(&prep, 0xA5, sizeof prep); /* garbage, as on the stack: ready false is what counts */
        prep.ready = false;
        for (int k = 0; k < 4; k++) { /* one prep, several queries */
            double r = exp(rnd_range(log(0.02), log(2.0)));
            prim_ref_v3 c = prim_ref_scale(rnd_unit(), L * rnd_range(0, 1.5));
            prim_ref_v3 ax = prim_ref_scale(rnd_unit(), rnd() < 0.2 ? 0.0 : rnd_range(0, 1));
            fm_vec3_t seg[2] = { F(prim_ref_sub(c, ax)), F(prim_ref_add(c, ax)) };
            fm_vec3_t d = F(prim_ref_scale(rnd_unit(), L * rnd_range(0, 2)));
            float t_max = rnd() < 0.5f ? 1.0f : (float)rnd();
            coll_prim_hit_t a, b;
            /* a ray at a point of the triangle (or beside it) first: its hit fills the prep
             * when it is not ready, and the sweeps and overlaps below then use that one */
            double wa = rnd_range(-0.2, 1.2), wb = rnd_range(-0.2, 1.2) * (1.0 - wa);
            fm_vec3_t aim = F(prim_ref_add(prim_ref_scale(prim_ref_sub(rt[1], rt[0]), wa),
                                           prim_ref_scale(prim_ref_sub(rt[2], rt[0]), wb)));
            fm_vec3_t ro = seg[0], rd = V(aim.x - ro.x, aim.y - ro.y, aim.z - ro.z);
            float s_max = rnd() < 0.8f ? 2.0f : (float)rnd();
            memset(&a, 0, sizeof a);
            memset(&b, 0, sizeof b);
            coll_ray_shear_t sh;
            bool ga = coll_ray_triangle(&ro, &rd, tri, s_max, &a);
            bool gb = coll_ray_shear(&rd, &sh) && coll_ray_triangle_sheared(&ro, &rd, &sh, tri, s_max, &prep, &b);
            TEST_ASSERT_TRUE(hits_equal(ga, &a, gb, &b));
            n_ray_hits += ga;
            memset(&a, 0, sizeof a);
            memset(&b, 0, sizeof b);
            bool held = k & 1;
            ga = held ? coll_tri_sweep_before(seg, (float)r, &d, tri, t_max, &a)
                           : coll_tri_sweep(seg, (float)r, &d, tri, t_max, &a);
            const fm_vec3_t no_axis = V(0, 0, 0);
            gb = coll_tri_sweep_prep(seg, (float)r, &d, tri, &prep, t_max, held ? &no_axis : NULL, &b);
            TEST_ASSERT_TRUE(hits_equal(ga, &a, gb, &b));
            n_hits += ga;
            memset(&a, 0, sizeof a);
            memset(&b, 0, sizeof b);
            ga = coll_capsule_triangle_overlap(seg, (float)r, tri, &a);
            gb = coll_capsule_triangle_overlap_prep(seg, (float)r, tri, &prep, &b);
            TEST_ASSERT_TRUE(hits_equal(ga, &a, gb, &b));
            TEST_ASSERT_TRUE(prep.ready);
        }
        n_prepared++;
    }
    TEST_ASSERT_TRUE(n_hits > N_RANDOM_SWEEPS / 40);
    TEST_ASSERT_TRUE(n_ray_hits > N_RANDOM_SWEEPS / 8);
    /* a ready prep is what the tests use: a wrong one (the normal reversed) shows */
    coll_tri_prep_t prep = { { { 0, 0, 0 } }, { { 0, 0, 0 } }, false, false, 0 };
    fm_vec3_t seg[2] = { V(0, 2, 0), V(0, 3, 0) }, d = V(0, -4, 0);
    coll_prim_hit_t h;
    TEST_ASSERT_TRUE(coll_tri_sweep_prep(seg, 0.5f, &d, floor_tri, &prep, 1.0f, NULL, &h));
    TEST_ASSERT_TRUE(prep.ready && prep.has_face);
    TEST_ASSERT_FLOAT_WITHIN(1e-6f, 1.0f, fabsf(prep.n.y));
    TEST_ASSERT_FLOAT_WITHIN(1e-6f, 1.0f, h.normal.y);
    prep.has_face = false; /* as if no face: the face's cull and test are skipped, the edges answer */
    prep.n = V(0, 0, 0);
    TEST_ASSERT_FALSE(coll_tri_sweep_prep(seg, 0.5f, &d, floor_tri, &prep, 1.0f, NULL, &h));
    (void)n_prepared;
}

/* The sweep's inputs relative to triangle t's first vertex, the scene moved by off along x:
 * the triangle, and the capsule (centre c, half height hh along y) as its segment. */
static void rel_tri(const fm_vec3_t t[3], float off, fm_vec3_t out[3])
{
    for (int k = 0; k < 3; k++) out[k] = V(t[k].x + off - (t[0].x + off), t[k].y - t[0].y, t[k].z - t[0].z);
}

/* For a sweep that met triangle a at h0_t with normal n0 (the motion d, |aim - c| = dlen):
 * every triangle's held sweep, t_max at that contact time and deeper[m] x r after it, answers
 * what its plain sweep does, less a contact no sooner than t_max, with the held contact's
 * normal n0 for the sweep to try as an axis and with a random one (any axis is a valid
 * cull). Returns the cases; ties: b != a at m 0. */
static int held_cases_match_plain(const fm_vec3_t (*tris)[3], int n, int a, prim_ref_v3 c, float off, float hh,
                                  float r, fm_vec3_t d, double dlen, float h0_t, fm_vec3_t n0, const float *deeper,
                                  int ndeeper, const char *label, int *n_ties)
{
    int n_cases = 0;
    for (int b = 0; b < n; b++) {
        fm_vec3_t sb[2], tb[3];
        for (int k = 0; k < 2; k++)
            sb[k] = V((float)c.x + off - (tris[b][0].x + off), (float)c.y + (k ? hh : -hh) - tris[b][0].y,
                      (float)c.z - tris[b][0].z);
        rel_tri(tris[b], off, tb);
        for (int m = 0; m < ndeeper; m++) {
            float t_max = h0_t + (float)(deeper[m] * r / (dlen > 1e-6 ? dlen : 1.0));
            coll_prim_hit_t hp, hb;
            memset(&hp, 0, sizeof hp);
            memset(&hb, 0, sizeof hb);
            bool gp = coll_tri_sweep_prep(sb, r, &d, tb, NULL, t_max, NULL, &hp);
            if (gp && hp.t > 0.0f && !(hp.t < t_max)) gp = false; /* no sooner: may go unreported */
            fm_vec3_t axes[2] = { n0, F(rnd_unit()) };
            for (int x = 0; x < 2; x++) {
                memset(&hb, 0, sizeof hb);
                bool gb = coll_tri_sweep_prep(sb, r, &d, tb, NULL, t_max, &axes[x], &hb);
                if (!hits_equal(gp, &hp, gb, &hb)) {
                    printf("%s: a %d b %d m %d axis %d: plain %d t %.9g, held %d\n", label, a, b, m, x, gp,
                           (double)hp.t, gb);
                    dump_case(sb, r, d, tb);
                }
                TEST_ASSERT_TRUE(hits_equal(gp, &hp, gb, &hb));
            }
            if (n_ties) *n_ties += b != a && m == 0;
            n_cases++;
        }
    }
    return n_cases;
}

/* The held sweep's end cull (tri_sweep: with a hit held at t_max, a candidate clear of rin
 * along the closest pair's direction at t_max is dropped before its feature sweep) drops
 * nothing the sweep reports: the held sweep answers exactly what the plain one does at the
 * same t_max, less a contact after t = 0 no sooner than t_max. On a stair nosing and a
 * crack's edges (pairs of triangles sharing an edge: the tie the cull is for), capsules and
 * spheres swept at the edge from all sides, t_max at the contact time of each of the
 * triangles and a little after it (the capsule deeper by 1e-5 .. 5e-2 of its radius
 * there), in small coordinates (the cull runs) and 300 m from the triangles' first vertex. */
static void test_held_end_cull_matches_plain(void)
{
    /* a nosing: tread (y = 0, z < 0) and riser (z = 0, y < 0), two triangles each; a crack:
     * a floor's edge and the crack's side below it */
    const fm_vec3_t quads[2][2][4] = {
        { { V(-1, 0, 0), V(1, 0, 0), V(1, 0, -1), V(-1, 0, -1) }, { V(-1, 0, 0), V(1, 0, 0), V(1, -0.25f, 0), V(-1, -0.25f, 0) } },
        { { V(-1, 0, 0), V(1, 0, 0), V(1, 0, -2), V(-1, 0, -2) }, { V(-1, 0, 0), V(1, 0, 0), V(1, -1, 0), V(-1, -1, 0) } },
    };
    const float deeper[] = { 0.0f, 1e-5f, 1e-4f, 3e-4f, 1e-3f, 1e-2f, 5e-2f };
    int n_cases = 0, n_ties = 0, n_hits = 0;
    for (int g = 0; g < 2; g++)
    for (int o = 0; o < 2; o++)
    for (int i = 0; i < 300; i++) {
        float off = o ? 300.0f : 0.0f;
        fm_vec3_t tris[4][3];
        for (int q = 0; q < 2; q++) {
            const fm_vec3_t *v = quads[g][q];
            fm_vec3_t a[3] = { v[0], v[1], v[2] }, b[3] = { v[0], v[2], v[3] };
            for (int k = 0; k < 3; k++) { tris[2 * q][k] = a[k]; tris[2 * q + 1][k] = b[k]; }
        }
        /* aimed at a point of the front edge (x in -0.8 .. 0.8) from above and in front */
        float r = (float)rnd_range(0.05, 0.6);
        float hh = rnd() < 0.3 ? 0.0f : (float)rnd_range(0.1, 0.5);
        prim_ref_v3 aim = { rnd_range(-0.8, 0.8), 0, 0 };
        prim_ref_v3 dir = rnd_unit();
        if (dir.y < 0) dir.y = -dir.y;
        if (dir.z < 0) dir.z = -dir.z;
        if (rnd() < 0.3) dir = prim_ref_scale((prim_ref_v3){ rnd_range(-0.2, 0.2), rnd_range(0.2, 1), rnd_range(0, 1) }, 1.0);
        double dl = prim_ref_len(dir);
        dir = prim_ref_scale(dir, 1.0 / dl);
        prim_ref_v3 c = prim_ref_add(aim, prim_ref_scale(dir, r + hh + rnd_range(0.05, 1.0)));
        prim_ref_v3 lat = prim_ref_scale(rnd_unit(), rnd_range(0, 0.6 * r)); /* off the line through the edge */
        c = prim_ref_add(c, lat);
        fm_vec3_t d = F(prim_ref_scale(prim_ref_sub(aim, c), rnd_range(1.0, 1.6)));
        double dlen = prim_ref_len(prim_ref_sub(aim, c));
        for (int a = 0; a < 4; a++) {
            /* the sweep's inputs relative to the triangle's first vertex, moved by off */
            fm_vec3_t rt[3], seg[2]; /* (the first vertex at the origin) */
            seg[0] = V((float)c.x + off - (tris[a][0].x + off), (float)c.y - hh - tris[a][0].y, (float)c.z - tris[a][0].z);
            seg[1] = V(seg[0].x, seg[0].y + 2.0f * hh, seg[0].z);
            rel_tri(tris[a], off, rt);
            coll_prim_hit_t h0;
            if (!coll_tri_sweep_prep(seg, r, &d, rt, NULL, 1.0f, NULL, &h0) || !(h0.t > 0.0f)) continue;
            n_hits++;
            /* t_max at this triangle's contact time and after it, against every triangle */
            n_cases += held_cases_match_plain((const fm_vec3_t (*)[3])tris, 4, a, c, off, hh, r, d, dlen, h0.t, h0.normal, deeper,
                                              (int)(sizeof deeper / sizeof deeper[0]), "held end cull", &n_ties);
        }
    }
    printf("held end cull: %d contacts, %d cases (%d ties across triangles)\n", n_hits, n_cases, n_ties);
    TEST_ASSERT_TRUE(n_hits > 500);
}

/* The plane cull at rin (tri_sweep's plane_rin_separated, perf16): a ball or capsule that
 * rests against a wall within the touch tolerance and moves along it or away never goes
 * deeper than the tolerance, which is no hit; it is dropped before the closest pair. The
 * sweep still reports a hit exactly when the motion takes the capsule deeper than rin
 * (r less the touch tolerance) into the triangle, by the double-precision reference (a band
 * of 1e-6 r about rin left out): walls of two triangles, spheres and capsules whose
 * least height over the wall's plane over the motion is r - 2 tol .. r + tol, moved along
 * the wall, a little away and a little into it, near the first vertex and 100 m and 300 m
 * away. It fails with the cull's threshold loosened to 0.999 rin. */
static void test_plane_rin_cull_agrees_with_reference(void)
{
    const float offs[] = { 0.0f, 100.0f, 300.0f };
    /* a wall in the plane z = 0 (normal +z), x and y in -1 .. 1 */
    const fm_vec3_t wall[2][3] = { { V(-1, -1, 0), V(1, -1, 0), V(1, 1, 0) }, { V(-1, -1, 0), V(1, 1, 0), V(-1, 1, 0) } };
    int n_cases = 0, n_hits = 0, n_culled = 0;
    for (int o = 0; o < 3; o++)
    for (int i = 0; i < 2000; i++) {
        float off = offs[o];
        float r = (float)rnd_range(0.05, 0.6);
        float hh = rnd() < 0.4 ? 0.0f : (float)rnd_range(0.1, 0.5);
        double tol = fmin(1e-4, r / 4.0), rin = r - tol;
        /* the least height over the plane over the motion, and the motion's part along the normal */
        double hmin = r + tol * rnd_range(-2.0, 1.0);
        int kind = i % 3; /* along, away, into */
        double dz = kind == 0 ? 0.0 : (kind == 1 ? rnd_range(0.0, 0.05) : -rnd_range(0.0, 3.0 * tol));
        double h0 = dz < 0.0 ? hmin - dz : hmin;
        prim_ref_v3 c = { rnd_range(-0.4, 0.4), rnd_range(-0.3, 0.3), h0 };
        prim_ref_v3 along = { rnd_range(-1, 1), rnd_range(-1, 1), 0 };
        along = prim_ref_scale(along, rnd_range(0.02, 0.4) / fmax(prim_ref_len(along), 1e-9));
        fm_vec3_t d = V((float)along.x, (float)along.y, (float)dz);
        bool hit = false;
        double ref_min = 1e30;
        for (int t = 0; t < 2; t++) {
            fm_vec3_t seg[2], rt[3];
            for (int k = 0; k < 2; k++)
                seg[k] = V((float)c.x + off - (wall[t][0].x + off), (float)c.y + (k ? hh : -hh) - wall[t][0].y,
                           (float)c.z - wall[t][0].z);
            rel_tri(wall[t], off, rt);
            coll_prim_hit_t h;
            hit |= coll_tri_sweep_prep(seg, r, &d, rt, NULL, 1.0f, NULL, &h);
            prim_ref_captri_t ctx;
            ctx.a = R(seg[0]); ctx.b = R(seg[1]); ctx.d = R(d);
            for (int k = 0; k < 3; k++) ctx.tri[k] = R(rt[k]);
            prim_ref_sweep_t ref;
            prim_ref_sweep(prim_ref_captri_fn, &ctx, r, 1.0, &ref);
            if (ref.fmin < ref_min) ref_min = ref.fmin;
        }
        if (fabs(ref_min - rin) < 1e-6 * r) continue; /* at rin: either answer */
        n_cases++;
        if (hit != (ref_min < rin)) {
            printf("plane rin cull: r %.9g hh %.9g off %g hmin %.9g (rin %.9g) dz %.9g: hit %d, reference least "
                   "distance %.9g\n", (double)r, (double)hh, (double)off, hmin, rin, dz, hit, ref_min);
        }
        TEST_ASSERT_EQUAL(ref_min < rin, hit);
        n_hits += hit;
        n_culled += !hit && hmin > rin * 1.0001 + 1e-6;
    }
    printf("plane cull at rin: %d cases, %d hits, %d clear of rin by the plane\n", n_cases, n_hits, n_culled);
    TEST_ASSERT_TRUE(n_hits > 500 && n_culled > 500);
}

/* The overlap's plane cull at rin (tri_overlap, perf16): a capsule whose segment lies
 * farther than rin from a wall's plane, on one side, is no overlap without its closest
 * pair. The overlap is reported exactly when the reference distance is under rin (r less
 * the touch tolerance; a band of 1e-6 r about rin left out): spheres and capsules, upright
 * or tilted, at heights r - 2 tol .. r + tol over a wall of two triangles, near the first
 * vertex and 100 m and 300 m away. It fails with the cull's threshold loosened to 0.999 rin. */
static void test_overlap_plane_rin_cull_agrees_with_reference(void)
{
    const float offs[] = { 0.0f, 100.0f, 300.0f };
    const fm_vec3_t wall[2][3] = { { V(-1, -1, 0), V(1, -1, 0), V(1, 1, 0) }, { V(-1, -1, 0), V(1, 1, 0), V(-1, 1, 0) } };
    int n_cases = 0, n_over = 0, n_clear = 0;
    for (int o = 0; o < 3; o++)
    for (int i = 0; i < 2000; i++) {
        float off = offs[o];
        float r = (float)rnd_range(0.05, 0.6);
        double tol = fmin(1e-4, r / 4.0), rin = r - tol;
        double hh = rnd() < 0.3 ? 0.0 : rnd_range(0.05, 0.5);
        /* the segment's lower end at height hmin, the other up to 2 tol higher (tilted) */
        double hmin = r + tol * rnd_range(-2.0, 1.0), tilt = rnd() < 0.5 ? 0.0 : rnd_range(0.0, 2.0 * tol);
        prim_ref_v3 c = { rnd_range(-0.4, 0.4), rnd_range(-0.3, 0.3), hmin + 0.5 * tilt };
        prim_ref_v3 ax = { rnd_range(-1, 1), rnd_range(-1, 1), 0 };
        ax = prim_ref_scale(ax, hh / fmax(prim_ref_len(ax), 1e-9));
        ax.z = hh > 0.0 ? 0.5 * tilt : 0.0;
        bool over = false;
        double ref_min = 1e30;
        for (int t = 0; t < 2; t++) {
            fm_vec3_t seg[2], rt[3];
            for (int k = 0; k < 2; k++) {
                prim_ref_v3 e = k ? prim_ref_add(c, ax) : prim_ref_sub(c, ax);
                seg[k] = V((float)e.x + off - (wall[t][0].x + off), (float)e.y - wall[t][0].y, (float)e.z - wall[t][0].z);
            }
            rel_tri(wall[t], off, rt);
            coll_prim_hit_t h;
            over |= coll_capsule_triangle_overlap(seg, r, rt, &h);
            prim_ref_v3 rtr[3] = { R(rt[0]), R(rt[1]), R(rt[2]) }, ps, pt;
            double dist = prim_ref_seg_tri(R(seg[0]), R(seg[1]), rtr, &ps, &pt);
            if (dist < ref_min) ref_min = dist;
        }
        if (fabs(ref_min - rin) < 1e-6 * r) continue; /* at rin: either answer */
        n_cases++;
        if (over != (ref_min < rin))
            printf("overlap plane rin cull: r %.9g off %g hmin %.9g (rin %.9g): overlap %d, reference distance %.9g\n",
                   (double)r, (double)off, hmin, rin, over, ref_min);
        TEST_ASSERT_EQUAL(ref_min < rin, over);
        n_over += over;
        n_clear += !over && hmin > rin * 1.0001 + 1e-6;
    }
    printf("overlap plane cull at rin: %d cases, %d overlaps, %d clear of rin by the plane\n", n_cases, n_over, n_clear);
    TEST_ASSERT_TRUE(n_over > 500 && n_clear > 500);
}

/* The end cull in large coordinates (tri_sweep's sweep_separated_at: the end's closest pair
 * measured from its point on the triangle, the axis made perpendicular to the edge that point
 * lies on, its allowance the rounding of those local terms): the held sweep still answers what
 * the plain one does, less a contact after t = 0 no sooner than t_max. The crack course's
 * geometry: 40 m long edges (a floor's edge and the crack's side below it, a floor and the
 * floor across the crack), so the far vertices lie 20 m along the edge from the contact and
 * the coordinates' magnitude (80-160) makes the confirm culls' own allowance (1e-6 of it)
 * larger than the touch tolerance; spheres and capsules swept at an edge from above and
 * the sides, t_max at each triangle's contact time and a little after it, near the first
 * vertex and 100 m and 300 m away. */
static void test_held_end_cull_local_matches_plain(void)
{
    /* the two slabs' facing edges: slab A's top (y = 0, z in -20 .. -0.2) and side (z = -0.2,
     * y in -1 .. 0), slab B's top (z in 0.2 .. 20) and side (z = 0.2); each quad two
     * triangles, split as bench_geo_box splits a box's faces (both diagonals tried) */
    const fm_vec3_t quads[4][4] = {
        { V(-20, 0, -0.2f), V(20, 0, -0.2f), V(20, 0, -20), V(-20, 0, -20) },
        { V(-20, 0, -0.2f), V(20, 0, -0.2f), V(20, -1, -0.2f), V(-20, -1, -0.2f) },
        { V(-20, 0, 0.2f), V(20, 0, 0.2f), V(20, 0, 20), V(-20, 0, 20) },
        { V(-20, 0, 0.2f), V(20, 0, 0.2f), V(20, -1, 0.2f), V(-20, -1, 0.2f) },
    };
    const float deeper[] = { 0.0f, 1e-5f, 1e-4f, 3e-4f, 1e-3f, 1e-2f };
    const float offs[] = { 0.0f, 100.0f, 300.0f };
    int n_cases = 0, n_hits = 0;
    for (int o = 0; o < 3; o++)
    for (int split = 0; split < 2; split++)
    for (int i = 0; i < 150; i++) {
        float off = offs[o];
        fm_vec3_t tris[8][3];
        for (int q = 0; q < 4; q++) {
            const fm_vec3_t *v = quads[q];
            if (split) {
                fm_vec3_t a[3] = { v[0], v[1], v[2] }, b[3] = { v[0], v[2], v[3] };
                for (int k = 0; k < 3; k++) { tris[2 * q][k] = a[k]; tris[2 * q + 1][k] = b[k]; }
            } else {
                fm_vec3_t a[3] = { v[0], v[1], v[3] }, b[3] = { v[1], v[2], v[3] };
                for (int k = 0; k < 3; k++) { tris[2 * q][k] = a[k]; tris[2 * q + 1][k] = b[k]; }
            }
        }
        float r = (float)rnd_range(0.25, 0.6);
        float hh = rnd() < 0.5 ? 0.0f : (float)rnd_range(0.1, 0.5);
        /* at a point of one edge, from above the crack (a ball dropped into it, rolled
         * across it) or from anywhere above and beside */
        double ex = rnd_range(-15, 15), ez = rnd() < 0.5 ? -0.2 : 0.2;
        prim_ref_v3 aim = { ex, 0, ez };
        prim_ref_v3 dir;
        if (rnd() < 0.5) dir = (prim_ref_v3){ rnd_range(-0.1, 0.1), 1, -ez * rnd_range(0, 4) };
        else dir = rnd_unit();
        if (dir.y < 0.05) dir.y = 0.05 + rnd();
        dir = prim_ref_scale(dir, 1.0 / prim_ref_len(dir));
        prim_ref_v3 c = prim_ref_add(aim, prim_ref_scale(dir, r + hh + rnd_range(0.05, 1.0)));
        c = prim_ref_add(c, prim_ref_scale(rnd_unit(), rnd_range(0, 0.3 * r)));
        fm_vec3_t d = F(prim_ref_scale(prim_ref_sub(aim, c), rnd_range(1.0, 1.6)));
        double dlen = prim_ref_len(prim_ref_sub(aim, c));
        for (int a = 0; a < 8; a++) {
            fm_vec3_t seg[2], ta[3];
            seg[0] = V((float)c.x + off - (tris[a][0].x + off), (float)c.y - hh - tris[a][0].y, (float)c.z - tris[a][0].z);
            seg[1] = V(seg[0].x, seg[0].y + 2.0f * hh, seg[0].z);
            rel_tri(tris[a], off, ta);
            coll_prim_hit_t h0;
            if (!coll_tri_sweep_prep(seg, r, &d, ta, NULL, 1.0f, NULL, &h0) || !(h0.t > 0.0f)) continue;
            n_hits++;
            n_cases += held_cases_match_plain((const fm_vec3_t (*)[3])tris, 8, a, c, off, hh, r, d, dlen, h0.t, h0.normal, deeper,
                                              (int)(sizeof deeper / sizeof deeper[0]), "held end cull (local)", NULL);
        }
    }
    printf("held end cull (local): %d contacts, %d cases\n", n_hits, n_cases);
    TEST_ASSERT_TRUE(n_hits > 500);
}

/* The start pair's cull in large coordinates (tri_sweep: where only the allowance of 1e-6 of
 * the coordinates' magnitude kept the start's closest pair from separating, it is measured
 * again from the pair's point on the triangle, sweep_separated_at): a ball rolled along a
 * 40 m edge (the crack rule's roll beside a crack in a 100 m floor) near the first vertex and
 * 100 m and 300 m from it, starting at r - 1e-4 .. r + 3e-4 from the edge, its motion along
 * the tangent and slightly into or away from the edge. The float inputs' exact least
 * distance over the motion (double) decides: no hit when it stays 1e-5 above rin (never
 * deeper than the touch tolerance), a hit when it goes 1e-5 below rin. */
static void test_start_pair_local_cull_rolls(void)
{
    const prim_ref_v3 quads[2][4] = {
        { { -20, 0, -0.2 }, { 20, 0, -0.2 }, { 20, 0, -20 }, { -20, 0, -20 } },   /* slab A's top */
        { { -20, 0, -0.2 }, { 20, 0, -0.2 }, { 20, -1, -0.2 }, { -20, -1, -0.2 } }, /* its side */
    };
    const double offs[] = { 0.0, 100.0, 300.0 };
    int n_clear = 0, n_deep = 0, n_near = 0;
    for (int o = 0; o < 3; o++)
    for (int i = 0; i < 1500; i++) {
        double r = rnd_range(0.3, 0.6), tol = 1e-4, rin = r - tol;
        double x0 = rnd_range(-15, 15), th = rnd_range(0.15, 1.4);
        prim_ref_v3 n = { 0, cos(th), sin(th) }, tg = { 0, -sin(th), cos(th) };
        double clear = rnd_range(-1e-4, 3e-4), into = rnd() < 0.3 ? 0.0 : rnd_range(-2e-4, 6e-4);
        prim_ref_v3 c = prim_ref_add(prim_ref_v(x0 + offs[o], 0, -0.2), prim_ref_scale(n, r + clear));
        prim_ref_v3 dd = prim_ref_add(prim_ref_scale(tg, rnd() < 0.5 ? rnd_range(0.0, 0.02) : rnd_range(0.2, 1.0)),
                                      prim_ref_scale(n, -into));
        dd.x = rnd_range(-0.05, 0.05);
        int q = i & 1, split = (i >> 1) & 1;
        const prim_ref_v3 *v = quads[q];
        prim_ref_v3 tr[3] = { v[0], v[1], split ? v[2] : v[3] }; /* both splits hold the edge */
        for (int k = 0; k < 3; k++) tr[k].x += offs[o];
        /* float inputs relative to the first vertex, and their exact least distance */
        fm_vec3_t tri[3], seg[2], d = F(dd);
        for (int k = 0; k < 3; k++) tri[k] = F(prim_ref_sub(tr[k], tr[0]));
        seg[0] = seg[1] = F(prim_ref_sub(c, tr[0]));
        prim_ref_v3 rt[3], a = { seg[0].x, seg[0].y, seg[0].z }, dref = { d.x, d.y, d.z }, ps, pt;
        for (int k = 0; k < 3; k++) rt[k] = prim_ref_v(tri[k].x, tri[k].y, tri[k].z);
        if (prim_ref_seg_tri(a, a, rt, &ps, &pt) < rin + 1e-5) continue; /* starts deeper */
        double dmin = prim_ref_seg_tri(a, prim_ref_add(a, dref), rt, &ps, &pt);
        coll_prim_hit_t h;
        bool got = coll_tri_sweep_prep(seg, (float)r, &d, tri, NULL, 1.0f, NULL, &h);
        if (dmin > rin + 1e-5) {
            if (got) printf("start pair cull: o %d i %d: hit t %.9g, least distance rin + %.3g\n", o, i, (double)h.t, dmin - rin);
            TEST_ASSERT_FALSE(got);
            n_clear++;
        } else if (dmin < rin - 1e-5) {
            if (!got) printf("start pair cull: o %d i %d: no hit, least distance rin - %.3g\n", o, i, rin - dmin);
            TEST_ASSERT_TRUE(got);
            n_deep++;
        } else {
            n_near++;
        }
    }
    printf("start pair cull: %d clear, %d deeper than the tolerance, %d within 1e-5 of it\n", n_clear, n_deep, n_near);
    TEST_ASSERT_TRUE(n_clear > 1000 && n_deep > 300);
}

/* ray_sphere's early rejection (an entry after s_max found before the square root) must
 * agree bit for bit with the full root: the full test here (the code before it), run on
 * random rays whose s_max is put exactly at, just before and just after the entry, near
 * and far from the origin. */
static bool ray_sphere_full(fm_vec3_t o, fm_vec3_t d, fm_vec3_t c, float r, float s_max, float *s_out)
{
    fm_vec3_t m = V(o.x - c.x, o.y - c.y, o.z - c.z);
    float cc = m.x * m.x + m.y * m.y + m.z * m.z - r * r;
    if (cc <= 0.0f) { *s_out = 0.0f; return true; }
    float b = m.x * d.x + m.y * d.y + m.z * d.z;
    if (b >= 0.0f) return false;
    float a = d.x * d.x + d.y * d.y + d.z * d.z;
    float k = -b / a;
    fm_vec3_t w = V(m.x + d.x * k, m.y + d.y * k, m.z + d.z * k);
    float disc = a * (r * r - (w.x * w.x + w.y * w.y + w.z * w.z));
    if (!(disc >= 0.0f)) return false;
    *s_out = cc / (-b + sqrtf(disc));
    return *s_out <= s_max;
}

/* The next float after x towards `to` (nextafterf; the console's test ROM has no libm). */
static float float_toward(float x, float to)
{
    if (x == to || x != x) return x;
    uint32_t u;
    memcpy(&u, &x, sizeof u);
    if (x == 0.0f) u = to < 0.0f ? 0x80000001u : 1u;
    else if ((x < to) == (x > 0.0f)) u++;
    else u--;
    memcpy(&x, &u, sizeof x);
    return x;
}

static void test_ray_sphere_early_reject_is_exact(void)
{
    int n_hits = 0, n_edge_miss = 0;
    for (int i = 0; i < N_EARLY_REJECT_RAYS; i++) {
        float scale = (i & 1) ? 1.0f : 1000.0f;
        fm_vec3_t c = V(rnd_range(-scale, scale), rnd_range(-scale, scale), rnd_range(-scale, scale));
        float r = rnd_range(0.01f, 2.0f);
        /* aimed near the sphere: grazing and central entries */
        fm_vec3_t aim = V(c.x + rnd_range(-1.2f, 1.2f) * r, c.y + rnd_range(-1.2f, 1.2f) * r, c.z + rnd_range(-1.2f, 1.2f) * r);
        fm_vec3_t o = V(aim.x + rnd_range(-5, 5), aim.y + rnd_range(-5, 5), aim.z + rnd_range(-5, 5));
        float len = rnd_range(0.2f, 3.0f);
        fm_vec3_t d = V((aim.x - o.x) * len, (aim.y - o.y) * len, (aim.z - o.z) * len);
        float s_ref;
        if (!ray_sphere_full(o, d, c, r, 3.0e38f, &s_ref) || s_ref == 0.0f) continue;
        float cuts[5] = { s_ref, float_toward(s_ref, 0.0f), float_toward(s_ref, 1e30f), s_ref * 0.999f, s_ref * 0.5f };
        for (int k = 0; k < 5; k++) {
            float sr = 0.0f;
            bool want = ray_sphere_full(o, d, c, r, cuts[k], &sr);
            prim_ray_t h;
            bool got = coll_prim_ray_sphere(o, d, c, r, cuts[k], &h);
            TEST_ASSERT_EQUAL_INT(want, got);
            if (want) {
                uint32_t bw, bg;
                memcpy(&bw, &sr, 4);
                memcpy(&bg, &h.s, 4);
                TEST_ASSERT_EQUAL_UINT32(bw, bg);
                n_hits++;
            }
            else n_edge_miss++;
        }
    }
    TEST_ASSERT_TRUE(n_hits > N_EARLY_REJECT_RAYS / 20 && n_edge_miss > N_EARLY_REJECT_RAYS / 20);
}

/* The start beyond the face's offset plane skips the start's closest pair and culls on the
 * directions from the edge lines to the end nearer the plane: its edge cases against the
 * double-precision reference. A sphere or capsule above a triangle (a grazing pass beside
 * an edge line, down onto it, along it), its end at about r over the plane (the boundary
 * of that path), near and far from the origin, and degenerate triangles (no face: the path
 * is never taken). */
static void test_far_start_edge_axis_cull_cases(void)
{
    sweep_stats_t st = { 0 };
    const float r = 0.5f;
    /* lat: how far beside r from the edge line (< 0: within r); the first two: over the
     * face, beside a vertex. hgt: the near end's height over or under the plane. */
    const float lat[] = { 0, 0, -0.2f, -0.01f, -1e-3f, -1e-4f, -1e-5f, 0.0f, 1e-5f, 1e-4f, 1e-3f, 0.2f };
    const float hgt[] = { 0.4995f, 0.4997f, 0.4999f, 0.49995f, 0.5f, 0.50005f, 0.5001f, 0.5002f, 0.501f, 0.7f, 1.5f };
    const int n_lat = (int)(sizeof lat / sizeof lat[0]), n_hgt = (int)(sizeof hgt / sizeof hgt[0]);
    const float offs[] = { 0.0f, 300.0f };
    const fm_vec3_t dirs[] = { { { 0, -2, 0 } }, { { 0.3f, -2, 0 } }, { { 0, -2, 0.5f } }, { { 0, -2, -0.5f } },
                               { { 1.5f, -0.4f, 0 } }, { { 0, -0.5f, 1.5f } }, { { 0, 0.5f, 0 } } };
    int n_cases = 0;
    for (int shape = 0; shape < 4; shape++)
    for (int o = 0; o < 2; o++)
    for (int li = 0; li < n_lat; li++)
    for (int hi = 0; hi < n_hgt; hi++)
    for (int di = 0; di < 7; di++)
    for (int side = 0; side < 2; side++) {
        float ox = offs[o];
        /* the triangle y = 0, x, z >= 0, x + z <= 2 (shape 3: tilted about x) */
        fm_vec3_t tri[3] = { V(0, 0, 0), V(2, 0, 0), V(0, 0, 2) };
        if (shape == 3) { tri[2] = V(0, 0.6f, 2); }
        /* the world is offset by ox; the sweep's inputs are relative to the capsule centre */
        float h = side ? hgt[hi] : -hgt[hi];
        fm_vec3_t c = V(1.0f, h, -(r + lat[li]));          /* beside the edge z = 0 */
        if (li == 0) c = V(0.5f, h, 0.5f);                 /* over the face */
        if (li == 1) c = V(-0.3f, h, -0.3f);               /* beside the vertex 0 */
        float hh = shape == 0 ? 0.0f : 0.4f;               /* shape 0: a sphere */
        fm_vec3_t ax = shape == 2 ? V(1, 0, 0) : V(0, 1, 0); /* shape 2: lying along the edge */
        fm_vec3_t seg[2], rt[3];
        /* the end nearer the plane at height h (an upright capsule reaches down by hh) */
        fm_vec3_t cc = V(c.x, side ? c.y + (shape == 2 ? 0.0f : hh) : c.y - (shape == 2 ? 0.0f : hh), c.z);
        for (int k = 0; k < 3; k++) rt[k] = V(tri[k].x + ox - (cc.x + ox), tri[k].y - cc.y, tri[k].z - cc.z);
        seg[0] = V(-ax.x * hh, -ax.y * hh, -ax.z * hh);
        seg[1] = V(ax.x * hh, ax.y * hh, ax.z * hh);
        fm_vec3_t d = dirs[di];
        if (!side) d.y = -d.y;
        check_sweep_case(&st, seg, r, d, rt);
        n_cases++;
    }
    /* straight toward the edge line (along the cull's own axis), stopping at about r: the
     * end exactly at, just inside and just outside the touching distance */
    const float stops[] = { 0.49f, 0.495f, 0.4999f, 0.49995f, 0.5f, 0.50005f, 0.5001f, 0.51f };
    for (int shape = 0; shape < 4; shape++)
    for (int o = 0; o < 2; o++)
    for (int hi = 0; hi < n_hgt; hi++)
    for (int li = 2; li < n_lat; li++)
    for (int si = 0; si < 8; si++) {
        if (!(hgt[hi] > r)) continue;
        float ox = offs[o];
        fm_vec3_t tri[3] = { V(0, 0, 0), V(2, 0, 0), V(0, 0, 2) };
        if (shape == 3) tri[2] = V(0, 0.6f, 2);
        float hh = shape == 0 ? 0.0f : 0.4f;
        fm_vec3_t ax = shape == 2 ? V(1, 0, 0) : V(0, 1, 0);
        fm_vec3_t p = V(1.0f, hgt[hi], -(r + lat[li] + 0.3f));  /* the near end, beside the edge z = 0 */
        fm_vec3_t cen = shape == 2 ? p : V(p.x, p.y + hh, p.z);
        double ux = 0.0, uy = -(double)p.y, uz = -(double)p.z; /* to (1, 0, 0) */
        double L = sqrt(uy * uy + uz * uz);
        double k = (L - stops[si]) / L;
        fm_vec3_t d = V((float)(ux * k), (float)(uy * k), (float)(uz * k));
        fm_vec3_t seg[2] = { V(-ax.x * hh, -ax.y * hh, -ax.z * hh), V(ax.x * hh, ax.y * hh, ax.z * hh) }, rt[3];
        for (int m = 0; m < 3; m++) rt[m] = V(tri[m].x + ox - (cen.x + ox), tri[m].y - cen.y, tri[m].z - cen.z);
        check_sweep_case(&st, seg, r, d, rt);
        n_cases++;
    }
    /* degenerate triangles: collinear, a point, a sliver (its face kept or not by the setup) */
    const fm_vec3_t degs[3][3] = { { { { 0, 0, 0 } }, { { 1, 0, 0 } }, { { 2, 0, 0 } } },
                                   { { { 1, 0, 0 } }, { { 1, 0, 0 } }, { { 1, 0, 0 } } },
                                   { { { 0, 0, 0 } }, { { 2, 0, 0 } }, { { 1, 0, 1e-6f } } } };
    for (int g = 0; g < 3; g++)
    for (int li = 2; li < n_lat; li++)
    for (int di = 0; di < 7; di++) {
        fm_vec3_t cc = V(1.0f, 0.7f, -(r + lat[li]));
        fm_vec3_t rt[3], seg[2] = { V(0, 0, 0), V(0, 0.4f, 0) };
        for (int k = 0; k < 3; k++) rt[k] = V(degs[g][k].x - cc.x, degs[g][k].y - cc.y, degs[g][k].z - cc.z);
        check_sweep_case(&st, seg, r, dirs[di], rt);
        n_cases++;
    }
    report_sweep("far start, edge-axis cull cases", &st);
    TEST_ASSERT_TRUE(st.hits > n_cases / 10 && st.n - st.hits > n_cases / 10);
}

/* The static overlap's cull on the axis from the triangle's nearest boundary point to the
 * segment's end nearer the plane: agreement with the double-precision distance, on capsules
 * placed beside an edge or a vertex at distances around rin (random triangles, random
 * capsule directions), and on degenerate triangles. */
static void test_overlap_boundary_axis_cull(void)
{
    int n = 0, n_over = 0, n_amb = 0;
    for (int i = 0; i < N_BOUNDARY_OVERLAPS; i++) {
        prim_ref_v3 rt[3];
        random_triangle(rt, pow(10, rnd_range(-1, 1)));
        if (i % 50 == 0) rt[2] = prim_ref_add(rt[0], prim_ref_scale(prim_ref_sub(rt[1], rt[0]), rnd())); /* collinear */
        double r = exp(rnd_range(log(0.05), log(3.0)));
        double tol = fmin(1e-4, r / 4), rin = r - tol;
        /* a point of the boundary (an edge point or a vertex), pushed out by about rin */
        int k = (int)(rnd() * 3);
        double u = rnd() < 0.3 ? 0 : rnd();
        prim_ref_v3 bp = prim_ref_add(rt[k], prim_ref_scale(prim_ref_sub(rt[(k + 1) % 3], rt[k]), u));
        double dist = rin * (1 + (rnd() < 0.5 ? 1 : -1) * pow(10, rnd_range(-5.5, -1)));
        /* pushed outward: the edge's in-plane outward normal and the face normal mixed */
        prim_ref_v3 e = prim_ref_sub(rt[(k + 1) % 3], rt[k]);
        prim_ref_v3 fn = prim_ref_cross(prim_ref_sub(rt[1], rt[0]), prim_ref_sub(rt[2], rt[0]));
        if (!(prim_ref_len(fn) > 1e-12)) fn = prim_ref_cross(e, rnd_unit());
        prim_ref_v3 out = prim_ref_cross(e, fn);
        if (prim_ref_dot(out, prim_ref_sub(rt[(k + 2) % 3], rt[k])) > 0) out = prim_ref_scale(out, -1);
        out = prim_ref_scale(out, 1 / prim_ref_len(out));
        fn = prim_ref_scale(fn, (rnd() < 0.5 ? 1 : -1) / prim_ref_len(fn));
        double mix = rnd_range(0, 1.5);
        prim_ref_v3 dir = prim_ref_add(out, prim_ref_scale(fn, mix));
        dir = prim_ref_scale(dir, 1 / prim_ref_len(dir));
        prim_ref_v3 near = prim_ref_add(bp, prim_ref_scale(dir, dist));
        prim_ref_v3 ax = rnd_unit();
        if (prim_ref_dot(ax, dir) < 0 && rnd() < 0.8) ax = prim_ref_scale(ax, -1); /* mostly away */
        double hh = rnd() < 0.2 ? 0 : rnd_range(0, 2);
        fm_vec3_t seg[2], tri[3];
        fm_vec3_t c0 = F(near);
        for (int m = 0; m < 3; m++) { fm_vec3_t w = F(rt[m]); tri[m] = V(w.x - c0.x, w.y - c0.y, w.z - c0.z); }
        /* the segment starts at that point and runs away or along (its other end anywhere) */
        seg[0] = V(0, 0, 0);
        seg[1] = F(prim_ref_scale(ax, hh));
        prim_ref_captri_t ctx;
        ctx.a = R(seg[0]); ctx.b = R(seg[1]); ctx.d = prim_ref_v(0, 0, 0);
        for (int m = 0; m < 3; m++) ctx.tri[m] = R(tri[m]);
        double f0 = prim_ref_captri_fn(&ctx, 0, NULL);
        double scale = 1;
        for (int m = 0; m < 3; m++) scale = fmax(scale, fmax(fabs(tri[m].x), fmax(fabs(tri[m].y), fabs(tri[m].z))));
        scale = fmax(scale, fmax(hh, r));
        float fr = (float)r;
        double frin = (double)fr - fmin(1e-4, (double)fr / 4);
        if (fabs(f0 - frin) < 3e-6 * scale) { n_amb++; continue; }
        coll_prim_hit_t h;
        bool got = coll_capsule_triangle_overlap(seg, fr, tri, &h);
        bool want = f0 < frin;
        if (got != want) {
            char msg[300];
            snprintf(msg, sizeof msg, "overlap %d, want %d: distance %.9g rin %.9g", got, want, f0, frin);
            dump_case(seg, fr, V(0, 0, 0), tri);
            TEST_FAIL_MESSAGE(msg);
        }
        n++;
        n_over += got;
    }
    printf("overlap boundary-axis cases: %d (%d overlapping), %d ambiguous\n", n, n_over, n_amb);
    TEST_ASSERT_TRUE(n_over > n / 10 && n - n_over > n / 10 && n_amb < n / 4);
}

/* The overlap's boundary axis handed to a sweep of the same segment (the recovery's look and
 * the slide's first sweep from there: coll_tri_sweep_axis_culls): wherever it says the sweep's
 * own test would drop the triangle, that test finds nothing, whether the motion goes away,
 * along or into the triangle; and it does drop a good part of the clear starts. */
static void test_overlap_axis_culls_only_what_the_sweep_drops(void)
{
    int n = 0, n_cull = 0, n_hit = 0;
    for (int i = 0; i < N_BOUNDARY_OVERLAPS; i++) {
        prim_ref_v3 rt[3];
        random_triangle(rt, pow(10, rnd_range(-1, 1)));
        double r = exp(rnd_range(log(0.05), log(3.0)));
        int k = (int)(rnd() * 3);
        double u = rnd() < 0.3 ? 0 : rnd();
        prim_ref_v3 bp = prim_ref_add(rt[k], prim_ref_scale(prim_ref_sub(rt[(k + 1) % 3], rt[k]), u));
        prim_ref_v3 e = prim_ref_sub(rt[(k + 1) % 3], rt[k]);
        prim_ref_v3 fn = prim_ref_cross(prim_ref_sub(rt[1], rt[0]), prim_ref_sub(rt[2], rt[0]));
        if (!(prim_ref_len(fn) > 1e-12)) continue;
        prim_ref_v3 out = prim_ref_cross(e, fn);
        if (prim_ref_dot(out, prim_ref_sub(rt[(k + 2) % 3], rt[k])) > 0) out = prim_ref_scale(out, -1);
        out = prim_ref_scale(out, 1 / prim_ref_len(out));
        fn = prim_ref_scale(fn, (rnd() < 0.5 ? 1 : -1) / prim_ref_len(fn));
        prim_ref_v3 dir = prim_ref_add(out, prim_ref_scale(fn, rnd_range(0, 1.5)));
        dir = prim_ref_scale(dir, 1 / prim_ref_len(dir));
        /* clear of the triangle at the start: out by r and a little to twice r */
        prim_ref_v3 near = prim_ref_add(bp, prim_ref_scale(dir, r * (1 + pow(10, rnd_range(-4, 0)))));
        prim_ref_v3 ax = rnd_unit();
        if (prim_ref_dot(ax, dir) < 0) ax = prim_ref_scale(ax, -1);
        double hh = rnd_range(0.05, 2);
        fm_vec3_t seg[2], tri[3];
        fm_vec3_t c0 = F(near);
        for (int m = 0; m < 3; m++) { fm_vec3_t w = F(rt[m]); tri[m] = V(w.x - c0.x, w.y - c0.y, w.z - c0.z); }
        seg[0] = V(0, 0, 0);
        seg[1] = F(prim_ref_scale(ax, hh));
        /* the motion: into the triangle (against dir), along it or away, up to twice r */
        prim_ref_v3 dv = prim_ref_add(prim_ref_scale(dir, rnd_range(-1.5, 1)), rnd_unit());
        fm_vec3_t d = F(prim_ref_scale(dv, r * rnd_range(0.01, 2) / prim_ref_len(dv)));
        float t_max = rnd() < 0.3 ? (float)rnd() : 1.0f;
        float fr = (float)r;
        coll_tri_prep_t prep;
        memset(&prep, 0, sizeof prep);
        coll_prim_hit_t h;
        bool clear = false;
        coll_tri_axis_t axis;
        if (coll_capsule_triangle_overlap_clear(seg, fr, tri, &prep, &h, &clear, &axis) || !clear) continue;
        if (axis.u.x == 0.0f && axis.u.y == 0.0f && axis.u.z == 0.0f) continue;
        n++;
        bool culls = coll_tri_sweep_axis_culls(seg, fr, &d, tri, t_max, &axis);
        bool got = coll_tri_sweep_prep(seg, fr, &d, tri, &prep, t_max, NULL, &h);
        if (culls && got) {
            dump_case(seg, fr, d, tri);
            TEST_FAIL_MESSAGE("the overlap's axis dropped a triangle the sweep hits");
        }
        n_cull += culls;
        n_hit += got;
    }
    printf("overlap axis for the sweep: %d clear starts, %d dropped, %d hit\n", n, n_cull, n_hit);
    TEST_ASSERT_TRUE(n > N_BOUNDARY_OVERLAPS / 4 && n_cull > n / 10 && n_hit > n / 10);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_face_hit_vertical_capsule);
    RUN_TEST(test_prepared_triangle_is_bit_identical);
    RUN_TEST(test_tilted_capsule_face_hit_uses_lower_end);
    RUN_TEST(test_edge_hit);
    RUN_TEST(test_vertex_hit);
    RUN_TEST(test_sliding_along_face_does_not_block);
    RUN_TEST(test_touching_and_moving_away_does_not_block);
    RUN_TEST(test_initial_overlap);
    RUN_TEST(test_sphere_and_zero_displacement);
    RUN_TEST(test_degenerate_input_never_nan);
    RUN_TEST(test_extreme_scales_finite);
    RUN_TEST(test_sweep_method_dispatch);
    RUN_TEST(test_no_allocation);
    RUN_TEST(test_ray_triangle_basics);
    RUN_TEST(test_random_rays_match_reference);
    RUN_TEST(test_ray_watertight_on_shared_edge);
    RUN_TEST(test_random_sweeps_match_reference);
    RUN_TEST(test_random_sweeps_far_from_origin);
    RUN_TEST(test_random_touching_sweeps);
    RUN_TEST(test_ray_sphere_early_reject_is_exact);
    RUN_TEST(test_far_start_edge_axis_cull_cases);
    RUN_TEST(test_overlap_boundary_axis_cull);
    RUN_TEST(test_overlap_axis_culls_only_what_the_sweep_drops);
    RUN_TEST(test_held_end_cull_matches_plain);
    RUN_TEST(test_plane_rin_cull_agrees_with_reference);
    RUN_TEST(test_overlap_plane_rin_cull_agrees_with_reference);
    RUN_TEST(test_held_end_cull_local_matches_plain);
    RUN_TEST(test_start_pair_local_cull_rolls);
    return UNITY_END();
}
