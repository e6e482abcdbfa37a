/* fm_math: every function, including aliasing (out == input) and degenerate inputs. */
#include "unity.h"
#include "alloc_guard.h"
#include "fm_math.h"
#include <math.h>

void setUp(void) {}
void tearDown(void) {}

#define EPS 1e-5f
static fm_vec3_t V(float x, float y, float z) { return (fm_vec3_t){{x, y, z}}; }
static fm_quat_t Q(float x, float y, float z, float w) { return (fm_quat_t){{x, y, z, w}}; }

static void assert_vec(fm_vec3_t e, fm_vec3_t a, float eps)
{
    for (int i = 0; i < 3; i++) TEST_ASSERT_FLOAT_WITHIN(eps, e.v[i], a.v[i]);
}
static void assert_quat_same_rotation(fm_quat_t e, fm_quat_t a, float eps)
{
    float s = fm_quat_dot(&e, &a) < 0.0f ? -1.0f : 1.0f; /* q and -q are the same rotation */
    for (int i = 0; i < 4; i++) TEST_ASSERT_FLOAT_WITHIN(eps, e.v[i], s * a.v[i]);
}

static void test_union_layout(void)
{
    fm_vec3_t v = V(1, 2, 3);
    TEST_ASSERT_EQUAL_FLOAT(2.0f, v.v[1]);
    TEST_ASSERT_EQUAL_FLOAT(3.0f, v.z);
    TEST_ASSERT_EQUAL(12, sizeof(fm_vec3_t));
    TEST_ASSERT_EQUAL(16, sizeof(fm_quat_t));
    TEST_ASSERT_EQUAL(64, sizeof(fm_mat4_t));
}

static void test_vec3_componentwise_and_aliasing(void)
{
    fm_vec3_t a = V(1, -2, 3), b = V(4, 5, -6), o;
    fm_vec3_add(&o, &a, &b); assert_vec(V(5, 3, -3), o, 0);
    fm_vec3_sub(&o, &a, &b); assert_vec(V(-3, -7, 9), o, 0);
    fm_vec3_mul(&o, &a, &b); assert_vec(V(4, -10, -18), o, 0);
    fm_vec3_div(&o, &b, &a); assert_vec(V(4, -2.5f, -2), o, 0);
    fm_vec3_scale(&o, &a, -2); assert_vec(V(-2, 4, -6), o, 0);
    fm_vec3_negate(&o, &a); assert_vec(V(-1, 2, -3), o, 0);
    /* out == a, out == b */
    o = a; fm_vec3_add(&o, &o, &b); assert_vec(V(5, 3, -3), o, 0);
    o = b; fm_vec3_sub(&o, &a, &o); assert_vec(V(-3, -7, 9), o, 0);
    o = a; fm_vec3_mul(&o, &o, &o); assert_vec(V(1, 4, 9), o, 0);
    o = b; fm_vec3_div(&o, &o, &a); assert_vec(V(4, -2.5f, -2), o, 0);
    o = a; fm_vec3_scale(&o, &o, 3); assert_vec(V(3, -6, 9), o, 0);
    o = a; fm_vec3_negate(&o, &o); assert_vec(V(-1, 2, -3), o, 0);
}

static void test_vec3_dot_len_distance(void)
{
    fm_vec3_t a = V(1, 2, 2), b = V(3, 0, -4);
    TEST_ASSERT_EQUAL_FLOAT(-5.0f, fm_vec3_dot(&a, &b));
    TEST_ASSERT_EQUAL_FLOAT(9.0f, fm_vec3_len2(&a));
    TEST_ASSERT_EQUAL_FLOAT(3.0f, fm_vec3_len(&a));
    TEST_ASSERT_EQUAL_FLOAT(5.0f, fm_vec3_len(&b));
    TEST_ASSERT_EQUAL_FLOAT(4.0f + 4.0f + 36.0f, fm_vec3_distance2(&a, &b));
    TEST_ASSERT_FLOAT_WITHIN(EPS, sqrtf(44.0f), fm_vec3_distance(&a, &b));
    TEST_ASSERT_EQUAL_FLOAT(0.0f, fm_vec3_distance(&a, &a));
}

static void test_vec3_norm_including_zero_and_nan(void)
{
    fm_vec3_t o, a = V(0, 3, 4);
    fm_vec3_norm(&o, &a); assert_vec(V(0, 0.6f, 0.8f), o, EPS);
    o = a; fm_vec3_norm(&o, &o); assert_vec(V(0, 0.6f, 0.8f), o, EPS);      /* aliasing */
    fm_vec3_t z = V(0, 0, 0);
    fm_vec3_norm(&o, &z); assert_vec(V(0, 0, 0), o, 0);                     /* zero stays zero */
    fm_vec3_t tiny = V(1e-9f, 0, 0);
    fm_vec3_norm(&o, &tiny); assert_vec(V(0, 0, 0), o, 0);                  /* below FM_EPSILON */
    fm_vec3_t nan = V(NAN, 0, 0);
    fm_vec3_norm(&o, &nan); assert_vec(V(0, 0, 0), o, 0);                   /* NaN never escapes */
    fm_vec3_t big = V(1e18f, 1e18f, 0);
    fm_vec3_norm(&o, &big); TEST_ASSERT_FLOAT_WITHIN(EPS, 1.0f, fm_vec3_len(&o));
}

static void test_vec3_cross_lerp_reflect(void)
{
    fm_vec3_t x = V(1, 0, 0), y = V(0, 1, 0), o;
    fm_vec3_cross(&o, &x, &y); assert_vec(V(0, 0, 1), o, 0);
    fm_vec3_cross(&o, &y, &x); assert_vec(V(0, 0, -1), o, 0);
    o = x; fm_vec3_cross(&o, &o, &y); assert_vec(V(0, 0, 1), o, 0);   /* out == a */
    o = y; fm_vec3_cross(&o, &x, &o); assert_vec(V(0, 0, 1), o, 0);   /* out == b */
    fm_vec3_cross(&o, &x, &x); assert_vec(V(0, 0, 0), o, 0);
    fm_vec3_t a = V(0, 0, 0), b = V(2, 4, -8);
    fm_vec3_lerp(&o, &a, &b, 0.25f); assert_vec(V(0.5f, 1, -2), o, 0);
    o = a; fm_vec3_lerp(&o, &o, &b, 1.0f); assert_vec(b, o, 0);
    fm_vec3_t i = V(1, -1, 0), n = V(0, 1, 0);
    fm_vec3_reflect(&o, &i, &n); assert_vec(V(1, 1, 0), o, 0);
    o = i; fm_vec3_reflect(&o, &o, &n); assert_vec(V(1, 1, 0), o, 0);
}

static void test_quat_identity_axis_angle_rotate(void)
{
    fm_quat_t q; fm_vec3_t o, v = V(1, 2, 3);
    fm_quat_identity(&q);
    TEST_ASSERT_EQUAL_FLOAT(1.0f, q.w);
    fm_quat_rotate_vec3(&o, &q, &v); assert_vec(v, o, 0);
    fm_vec3_t up = V(0, 1, 0), x = V(1, 0, 0);
    fm_quat_from_axis_angle(&q, &up, FM_PI * 0.5f);        /* +90 deg about Y: X -> -Z */
    fm_quat_rotate_vec3(&o, &q, &x); assert_vec(V(0, 0, -1), o, EPS);
    fm_vec3_rotate(&o, &x, &q); assert_vec(V(0, 0, -1), o, EPS);  /* libdragon's order */
    o = x; fm_quat_rotate_vec3(&o, &q, &o); assert_vec(V(0, 0, -1), o, EPS);
    o = x; fm_vec3_rotate(&o, &o, &q); assert_vec(V(0, 0, -1), o, EPS);
    /* length preserved for an arbitrary rotation */
    fm_vec3_t axis = V(1, 1, 1); fm_vec3_norm(&axis, &axis);
    fm_quat_from_axis_angle(&q, &axis, 1.234f);
    fm_quat_rotate_vec3(&o, &q, &v);
    TEST_ASSERT_FLOAT_WITHIN(1e-4f, fm_vec3_len(&v), fm_vec3_len(&o));
    /* rotating about its own axis leaves the axis alone */
    fm_quat_rotate_vec3(&o, &q, &axis); assert_vec(axis, o, EPS);
}

static void test_quat_mul_inverse_norm(void)
{
    fm_vec3_t up = V(0, 1, 0), zx = V(0, 0, 1), x = V(1, 0, 0), o, o2;
    fm_quat_t a, b, ab, inv, id;
    fm_quat_from_axis_angle(&a, &up, 0.7f);
    fm_quat_from_axis_angle(&b, &zx, -1.1f);
    fm_quat_mul(&ab, &a, &b);                                /* b first, then a */
    fm_quat_rotate_vec3(&o, &ab, &x);
    fm_quat_rotate_vec3(&o2, &b, &x); fm_quat_rotate_vec3(&o2, &a, &o2);
    assert_vec(o2, o, EPS);
    fm_quat_t c = a; fm_quat_mul(&c, &c, &b); assert_quat_same_rotation(ab, c, EPS);   /* out == a */
    c = b; fm_quat_mul(&c, &a, &c); assert_quat_same_rotation(ab, c, EPS);            /* out == b */
    fm_quat_inverse(&inv, &ab);
    fm_quat_mul(&id, &ab, &inv); assert_quat_same_rotation(Q(0, 0, 0, 1), id, EPS);
    c = ab; fm_quat_inverse(&c, &c); assert_quat_same_rotation(inv, c, EPS);
    fm_quat_t zero = Q(0, 0, 0, 0);
    fm_quat_inverse(&c, &zero); assert_quat_same_rotation(Q(0, 0, 0, 1), c, 0);
    fm_quat_t s = Q(0, 0, 0, 2);
    fm_quat_inverse(&c, &s); TEST_ASSERT_FLOAT_WITHIN(EPS, 0.5f, c.w);
    fm_quat_norm(&c, &s); assert_quat_same_rotation(Q(0, 0, 0, 1), c, EPS);
    c = Q(1, 1, 1, 1); fm_quat_norm(&c, &c); TEST_ASSERT_FLOAT_WITHIN(EPS, 0.5f, c.x);
    fm_quat_norm(&c, &zero); assert_quat_same_rotation(Q(0, 0, 0, 1), c, 0);
    TEST_ASSERT_FLOAT_WITHIN(EPS, 1.0f, fm_quat_dot(&a, &a));
}

static void test_quat_rotate_composes(void)
{
    fm_vec3_t up = V(0, 1, 0), x = V(1, 0, 0), o;
    fm_quat_t q, r;
    fm_quat_identity(&q);
    fm_quat_rotate(&r, &q, &up, FM_PI * 0.5f);
    fm_quat_rotate(&r, &r, &up, FM_PI * 0.5f);             /* aliasing, 180 deg total */
    fm_quat_rotate_vec3(&o, &r, &x); assert_vec(V(-1, 0, 0), o, EPS);
}

static void test_quat_slerp_nlerp(void)
{
    fm_vec3_t up = V(0, 1, 0), x = V(1, 0, 0), o;
    fm_quat_t a, b, m;
    fm_quat_identity(&a);
    fm_quat_from_axis_angle(&b, &up, FM_PI * 0.5f);
    fm_quat_slerp(&m, &a, &b, 0.5f);
    fm_quat_t e; fm_quat_from_axis_angle(&e, &up, FM_PI * 0.25f);
    assert_quat_same_rotation(e, m, EPS);
    fm_quat_slerp(&m, &a, &b, 0.0f); assert_quat_same_rotation(a, m, EPS);
    fm_quat_slerp(&m, &a, &b, 1.0f); assert_quat_same_rotation(b, m, EPS);
    /* shortest arc: -b is the same rotation */
    fm_quat_t nb = Q(-b.x, -b.y, -b.z, -b.w);
    fm_quat_slerp(&m, &a, &nb, 0.5f); assert_quat_same_rotation(e, m, EPS);
    m = a; fm_quat_slerp(&m, &m, &b, 0.5f); assert_quat_same_rotation(e, m, EPS);  /* aliasing */
    /* nearly identical inputs take the nlerp path and stay unit */
    fm_quat_t c; fm_quat_from_axis_angle(&c, &up, 1e-4f);
    fm_quat_slerp(&m, &a, &c, 0.5f); TEST_ASSERT_FLOAT_WITHIN(EPS, 1.0f, fm_quat_dot(&m, &m));
    fm_quat_nlerp(&m, &a, &b, 0.5f); assert_quat_same_rotation(e, m, EPS); /* symmetric case exact */
    fm_quat_rotate_vec3(&o, &m, &x);
    TEST_ASSERT_FLOAT_WITHIN(EPS, 1.0f, fm_vec3_len(&o));
}

static void test_mat4_srt_mul_inverse(void)
{
    fm_mat4_t m, inv, id, t;
    fm_mat4_identity(&id);
    for (int c = 0; c < 4; c++) for (int r = 0; r < 4; r++)
        TEST_ASSERT_EQUAL_FLOAT(c == r ? 1.0f : 0.0f, id.m[c][r]);
    fm_vec3_t s = V(2, 3, 4), p = V(10, -5, 1), up = V(0, 1, 0), v = V(1, 1, 1), o, e;
    fm_quat_t q; fm_quat_from_axis_angle(&q, &up, 0.3f);
    fm_mat4_from_srt(&m, &s, &q, &p);
    fm_mat4_mul_point(&o, &m, &v);
    fm_vec3_mul(&e, &v, &s); fm_quat_rotate_vec3(&e, &q, &e); fm_vec3_add(&e, &e, &p);
    assert_vec(e, o, 1e-4f);
    fm_mat4_mul_dir(&o, &m, &v);
    fm_vec3_mul(&e, &v, &s); fm_quat_rotate_vec3(&e, &q, &e);
    assert_vec(e, o, 1e-4f);
    o = v; fm_mat4_mul_point(&o, &m, &o); fm_mat4_mul_point(&e, &m, &v); assert_vec(e, o, 0);
    TEST_ASSERT_TRUE(fm_mat4_affine_inverse(&inv, &m));
    fm_mat4_mul(&t, &m, &inv);
    for (int c = 0; c < 4; c++) for (int r = 0; r < 4; r++)
        TEST_ASSERT_FLOAT_WITHIN(1e-5f, id.m[c][r], t.m[c][r]);
    t = m; fm_mat4_mul(&t, &t, &inv);                       /* out == a */
    TEST_ASSERT_FLOAT_WITHIN(1e-5f, 1.0f, t.m[1][1]);
    t = inv; fm_mat4_mul(&t, &m, &t);                       /* out == b */
    TEST_ASSERT_FLOAT_WITHIN(1e-5f, 1.0f, t.m[2][2]);
    t = m; TEST_ASSERT_TRUE(fm_mat4_affine_inverse(&t, &t));
    TEST_ASSERT_FLOAT_WITHIN(1e-6f, inv.m[3][0], t.m[3][0]);
    fm_mat4_t sing = id; sing.m[1][1] = 0;
    TEST_ASSERT_FALSE(fm_mat4_affine_inverse(&t, &sing));
    TEST_ASSERT_EQUAL_FLOAT(1.0f, t.m[1][1]);
    fm_mat4_transpose(&t, &m);
    TEST_ASSERT_EQUAL_FLOAT(m.m[3][0], t.m[0][3]);
    t = m; fm_mat4_transpose(&t, &t);                       /* aliasing */
    TEST_ASSERT_EQUAL_FLOAT(m.m[1][2], t.m[2][1]);
    TEST_ASSERT_EQUAL_FLOAT(m.m[2][1], t.m[1][2]);
}

static void test_math_never_allocates(void)
{
    fm_vec3_t a = V(1, 2, 3), o; fm_quat_t q = Q(0, 0, 0, 1), r; fm_mat4_t m;
    ASSERT_NO_ALLOC({ fm_vec3_norm(&o, &a); fm_quat_slerp(&r, &q, &q, 0.5f);
                      fm_mat4_from_srt(&m, &a, &q, &a); fm_mat4_affine_inverse(&m, &m); });
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_union_layout);
    RUN_TEST(test_vec3_componentwise_and_aliasing);
    RUN_TEST(test_vec3_dot_len_distance);
    RUN_TEST(test_vec3_norm_including_zero_and_nan);
    RUN_TEST(test_vec3_cross_lerp_reflect);
    RUN_TEST(test_quat_identity_axis_angle_rotate);
    RUN_TEST(test_quat_mul_inverse_norm);
    RUN_TEST(test_quat_rotate_composes);
    RUN_TEST(test_quat_slerp_nlerp);
    RUN_TEST(test_mat4_srt_mul_inverse);
    RUN_TEST(test_math_never_allocates);
    return UNITY_END();
}
