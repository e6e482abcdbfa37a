/**
 * @file fm_math.h
 * @brief Float vector, quaternion and matrix math with libdragon's `fgeom.h` names.
 *
 * User code written against libdragon's fgeom.h compiles against this header and the
 * other way round. Every function takes its output pointer first and works when the
 * output aliases an input.
 *
 * Every function is `static inline` here, as libdragon's are in its headers: the library
 * archive defines no fm_ symbol, so it links into a libdragon game without "multiple
 * definition" errors, whichever header the game uses.
 *
 * Compile with -DCOLL_USE_LIBDRAGON_FMATH (required in a source that also includes
 * libdragon.h) to take the types and functions from libdragon's fgeom.h instead; the types
 * have the same layout, so code built either way links together. In that mode edge cases
 * follow libdragon: FM_EPSILON is 1e-4, and its norm/inverse do not guard NaN or a zero
 * quaternion. `make n64 COLL_USE_LIBDRAGON_FMATH=1` builds the library itself that way
 * (the default when N64_INST holds an fgeom.h).
 *
 * Everything is single precision: the VR4300 runs double math in slow software paths
 * under the N64 ABI, so no double may appear here (-Wdouble-promotion guards it).
 */
#ifndef FM_MATH_H
#define FM_MATH_H

#include <stdbool.h>
#include <math.h>

#ifdef COLL_USE_LIBDRAGON_FMATH
#include <fgeom.h>
#ifndef FM_PI /* libdragon before fmath.h had it */
#define FM_PI 3.14159265358979f
#endif
#else

#ifdef __cplusplus
extern "C" {
#endif

/** Smallest length treated as non-zero by the normalizers. */
#define FM_EPSILON 1e-6f
/** Pi as a float. */
#define FM_PI 3.14159265358979f

/** Three floats: named x, y, z or indexed v[0..2]. */
typedef union {
    struct { float x, y, z; };
    float v[3];
} fm_vec3_t;

/** Four floats: named x, y, z, w or indexed v[0..3]. */
typedef union {
    struct { float x, y, z, w; };
    float v[4];
} fm_vec4_t;

/** Rotation quaternion {x,y,z,w}; identity is {0,0,0,1}. */
typedef union {
    struct { float x, y, z, w; };
    float v[4];
} fm_quat_t;

/** 4x4 matrix, column-major: m[column][row], translation in m[3][0..2]. */
typedef struct {
    float m[4][4];
} fm_mat4_t;

/* ---- vec3 ---- */
static inline void fm_vec3_negate(fm_vec3_t *out, const fm_vec3_t *v)
{
    for (int i = 0; i < 3; i++) out->v[i] = -v->v[i];
}

static inline void fm_vec3_add(fm_vec3_t *out, const fm_vec3_t *a, const fm_vec3_t *b)
{
    for (int i = 0; i < 3; i++) out->v[i] = a->v[i] + b->v[i];
}

static inline void fm_vec3_sub(fm_vec3_t *out, const fm_vec3_t *a, const fm_vec3_t *b)
{
    for (int i = 0; i < 3; i++) out->v[i] = a->v[i] - b->v[i];
}

/** Component-wise product. */
static inline void fm_vec3_mul(fm_vec3_t *out, const fm_vec3_t *a, const fm_vec3_t *b)
{
    for (int i = 0; i < 3; i++) out->v[i] = a->v[i] * b->v[i];
}

/** Component-wise quotient. */
static inline void fm_vec3_div(fm_vec3_t *out, const fm_vec3_t *a, const fm_vec3_t *b)
{
    for (int i = 0; i < 3; i++) out->v[i] = a->v[i] / b->v[i];
}

static inline void fm_vec3_scale(fm_vec3_t *out, const fm_vec3_t *a, float s)
{
    for (int i = 0; i < 3; i++) out->v[i] = a->v[i] * s;
}

static inline float fm_vec3_dot(const fm_vec3_t *a, const fm_vec3_t *b)
{
    return a->x * b->x + a->y * b->y + a->z * b->z;
}

static inline float fm_vec3_len2(const fm_vec3_t *a) { return fm_vec3_dot(a, a); }
static inline float fm_vec3_len(const fm_vec3_t *a) { return sqrtf(fm_vec3_len2(a)); }

static inline float fm_vec3_distance2(const fm_vec3_t *a, const fm_vec3_t *b)
{
    fm_vec3_t d;
    fm_vec3_sub(&d, a, b);
    return fm_vec3_len2(&d);
}

static inline float fm_vec3_distance(const fm_vec3_t *a, const fm_vec3_t *b) { return sqrtf(fm_vec3_distance2(a, b)); }

/** Unit vector along a; the zero vector (length < FM_EPSILON) gives {0,0,0}. */
static inline void fm_vec3_norm(fm_vec3_t *out, const fm_vec3_t *a)
{
    float len = fm_vec3_len(a);
    if (!(len >= FM_EPSILON)) { /* also catches NaN */
        *out = (fm_vec3_t){{0.0f, 0.0f, 0.0f}};
        return;
    }
    fm_vec3_scale(out, a, 1.0f / len);
}

static inline void fm_vec3_cross(fm_vec3_t *out, const fm_vec3_t *a, const fm_vec3_t *b)
{
    fm_vec3_t r = {{ a->y * b->z - a->z * b->y,
                     a->z * b->x - a->x * b->z,
                     a->x * b->y - a->y * b->x }};
    *out = r;
}

/** a + (b - a) * t */
static inline void fm_vec3_lerp(fm_vec3_t *out, const fm_vec3_t *a, const fm_vec3_t *b, float t)
{
    for (int i = 0; i < 3; i++) out->v[i] = a->v[i] + (b->v[i] - a->v[i]) * t;
}

/** Reflects incident i about the unit normal n. */
static inline void fm_vec3_reflect(fm_vec3_t *out, const fm_vec3_t *i, const fm_vec3_t *n)
{
    float d = 2.0f * fm_vec3_dot(i, n);
    fm_vec3_t r = {{ i->x - d * n->x, i->y - d * n->y, i->z - d * n->z }};
    *out = r;
}

static inline void fm_quat_rotate_vec3(fm_vec3_t *out, const fm_quat_t *q, const fm_vec3_t *v);

/** libdragon's argument order: rotates i by q. */
static inline void fm_vec3_rotate(fm_vec3_t *out, const fm_vec3_t *i, const fm_quat_t *q)
{
    fm_quat_rotate_vec3(out, q, i);
}

/* ---- quat ---- */
static inline void fm_quat_identity(fm_quat_t *out) { *out = (fm_quat_t){{0.0f, 0.0f, 0.0f, 1.0f}}; }

/** axis must be unit length; angle in radians. */
static inline void fm_quat_from_axis_angle(fm_quat_t *out, const fm_vec3_t *axis, float angle)
{
    float s = sinf(angle * 0.5f), c = cosf(angle * 0.5f);
    fm_quat_t r = {{ axis->x * s, axis->y * s, axis->z * s, c }};
    *out = r;
}

/** Hamilton product a*b: applies b first, then a. */
static inline void fm_quat_mul(fm_quat_t *out, const fm_quat_t *a, const fm_quat_t *b)
{
    fm_quat_t r = {{
        a->w * b->x + a->x * b->w + a->y * b->z - a->z * b->y,
        a->w * b->y - a->x * b->z + a->y * b->w + a->z * b->x,
        a->w * b->z + a->x * b->y - a->y * b->x + a->z * b->w,
        a->w * b->w - a->x * b->x - a->y * b->y - a->z * b->z,
    }};
    *out = r;
}

/** q followed by a rotation about axis by angle (libdragon semantics). */
static inline void fm_quat_rotate(fm_quat_t *out, const fm_quat_t *q, const fm_vec3_t *axis, float angle)
{
    fm_quat_t r;
    fm_quat_from_axis_angle(&r, axis, angle);
    fm_quat_mul(out, &r, q);
}

static inline float fm_quat_dot(const fm_quat_t *a, const fm_quat_t *b)
{
    return a->x * b->x + a->y * b->y + a->z * b->z + a->w * b->w;
}

/** Inverse; a zero quaternion gives the identity. */
static inline void fm_quat_inverse(fm_quat_t *out, const fm_quat_t *q)
{
    float m2 = fm_quat_dot(q, q);
    if (!(m2 >= FM_EPSILON * FM_EPSILON)) { fm_quat_identity(out); return; }
    float inv = 1.0f / m2;
    fm_quat_t r = {{ -q->x * inv, -q->y * inv, -q->z * inv, q->w * inv }};
    *out = r;
}

/** Unit quaternion; a zero quaternion gives the identity. */
static inline void fm_quat_norm(fm_quat_t *out, const fm_quat_t *q)
{
    float len = sqrtf(fm_quat_dot(q, q));
    if (!(len >= FM_EPSILON)) { fm_quat_identity(out); return; }
    float inv = 1.0f / len;
    for (int i = 0; i < 4; i++) out->v[i] = q->v[i] * inv;
}

static inline void fm_quat_nlerp(fm_quat_t *out, const fm_quat_t *a, const fm_quat_t *b, float t)
{
    float s = fm_quat_dot(a, b) < 0.0f ? -1.0f : 1.0f; /* shortest arc */
    fm_quat_t r;
    for (int i = 0; i < 4; i++) r.v[i] = a->v[i] + (s * b->v[i] - a->v[i]) * t;
    fm_quat_norm(out, &r);
}

/** Shortest-arc spherical interpolation, t in [0,1]. */
static inline void fm_quat_slerp(fm_quat_t *out, const fm_quat_t *a, const fm_quat_t *b, float t)
{
    float d = fm_quat_dot(a, b);
    float s = 1.0f;
    if (d < 0.0f) { d = -d; s = -1.0f; }
    if (d > 0.9995f) { fm_quat_nlerp(out, a, b, t); return; } /* nearly equal: lerp is exact enough */
    float theta = acosf(d);
    float sin_theta = sinf(theta);
    float wa = sinf((1.0f - t) * theta) / sin_theta;
    float wb = s * sinf(t * theta) / sin_theta;
    fm_quat_t r;
    for (int i = 0; i < 4; i++) r.v[i] = wa * a->v[i] + wb * b->v[i];
    *out = r;
}

/* ---- mat4 (subset) ---- */
static inline void fm_mat4_identity(fm_mat4_t *out)
{
    for (int c = 0; c < 4; c++)
        for (int r = 0; r < 4; r++) out->m[c][r] = (c == r) ? 1.0f : 0.0f;
}

/** Scale, then rotate, then translate (libdragon's fm_mat4_from_srt). */
static inline void fm_mat4_from_srt(fm_mat4_t *out, const fm_vec3_t *scale, const fm_quat_t *q, const fm_vec3_t *t)
{
    float xx = q->x * q->x, yy = q->y * q->y, zz = q->z * q->z;
    float xy = q->x * q->y, xz = q->x * q->z, yz = q->y * q->z;
    float wx = q->w * q->x, wy = q->w * q->y, wz = q->w * q->z;
    fm_mat4_t r = {{
        { (1.0f - 2.0f * (yy + zz)) * scale->x, 2.0f * (xy + wz) * scale->x, 2.0f * (xz - wy) * scale->x, 0.0f },
        { 2.0f * (xy - wz) * scale->y, (1.0f - 2.0f * (xx + zz)) * scale->y, 2.0f * (yz + wx) * scale->y, 0.0f },
        { 2.0f * (xz + wy) * scale->z, 2.0f * (yz - wx) * scale->z, (1.0f - 2.0f * (xx + yy)) * scale->z, 0.0f },
        { t->x, t->y, t->z, 1.0f },
    }};
    *out = r;
}

static inline void fm_mat4_mul(fm_mat4_t *out, const fm_mat4_t *a, const fm_mat4_t *b)
{
    fm_mat4_t r;
    for (int c = 0; c < 4; c++)
        for (int row = 0; row < 4; row++)
            r.m[c][row] = a->m[0][row] * b->m[c][0] + a->m[1][row] * b->m[c][1] +
                          a->m[2][row] * b->m[c][2] + a->m[3][row] * b->m[c][3];
    *out = r;
}

static inline void fm_mat4_transpose(fm_mat4_t *out, const fm_mat4_t *m)
{
    fm_mat4_t r;
    for (int c = 0; c < 4; c++)
        for (int row = 0; row < 4; row++) r.m[c][row] = m->m[row][c];
    *out = r;
}

#ifdef __cplusplus
}
#endif
#endif /* COLL_USE_LIBDRAGON_FMATH */

/* ---- helpers libdragon lacks: ours in both builds ---- */
#ifdef __cplusplus
extern "C" {
#endif
/** Rotate a vector by a unit quaternion (q first, like the other quat calls). */
static inline void fm_quat_rotate_vec3(fm_vec3_t *out, const fm_quat_t *q, const fm_vec3_t *v)
{
    /* v' = v + 2w (u x v) + 2 u x (u x v), u = q.xyz: 15 mul instead of a full q v q* */
    fm_vec3_t u = {{q->x, q->y, q->z}}, t, c;
    fm_vec3_cross(&t, &u, v);
    fm_vec3_scale(&t, &t, 2.0f);
    fm_vec3_cross(&c, &u, &t);
    fm_vec3_t r = {{ v->x + q->w * t.x + c.x, v->y + q->w * t.y + c.y, v->z + q->w * t.z + c.z }};
    *out = r;
}

/** Transforms a point (w = 1), dropping w (affine matrices). */
static inline void fm_mat4_mul_point(fm_vec3_t *out, const fm_mat4_t *m, const fm_vec3_t *p)
{
    fm_vec3_t r;
    for (int i = 0; i < 3; i++)
        r.v[i] = m->m[0][i] * p->x + m->m[1][i] * p->y + m->m[2][i] * p->z + m->m[3][i];
    *out = r;
}

/** Transforms a direction (w = 0). */
static inline void fm_mat4_mul_dir(fm_vec3_t *out, const fm_mat4_t *m, const fm_vec3_t *d)
{
    fm_vec3_t r;
    for (int i = 0; i < 3; i++)
        r.v[i] = m->m[0][i] * d->x + m->m[1][i] * d->y + m->m[2][i] * d->z;
    *out = r;
}

/** Inverse of an affine matrix; returns false (out = identity) when singular. */
static inline bool fm_mat4_affine_inverse(fm_mat4_t *out, const fm_mat4_t *m)
{
    /* Inverse of the upper 3x3 by cofactors, then the translation. */
    const float a = m->m[0][0], b = m->m[1][0], c = m->m[2][0];
    const float d = m->m[0][1], e = m->m[1][1], f = m->m[2][1];
    const float g = m->m[0][2], h = m->m[1][2], k = m->m[2][2];
    float A = e * k - f * h, B = -(d * k - f * g), C = d * h - e * g;
    float det = a * A + b * B + c * C;
    if (!(fabsf(det) > 1e-30f) || !isfinite(det)) { fm_mat4_identity(out); return false; }
    float inv = 1.0f / det;
    fm_mat4_t r;
    /* row-major inverse elements, stored column-major */
    float i00 = A * inv, i01 = -(b * k - c * h) * inv, i02 = (b * f - c * e) * inv;
    float i10 = B * inv, i11 = (a * k - c * g) * inv, i12 = -(a * f - c * d) * inv;
    float i20 = C * inv, i21 = -(a * h - b * g) * inv, i22 = (a * e - b * d) * inv;
    r.m[0][0] = i00; r.m[1][0] = i01; r.m[2][0] = i02;
    r.m[0][1] = i10; r.m[1][1] = i11; r.m[2][1] = i12;
    r.m[0][2] = i20; r.m[1][2] = i21; r.m[2][2] = i22;
    r.m[0][3] = r.m[1][3] = r.m[2][3] = 0.0f;
    float tx = m->m[3][0], ty = m->m[3][1], tz = m->m[3][2];
    r.m[3][0] = -(i00 * tx + i01 * ty + i02 * tz);
    r.m[3][1] = -(i10 * tx + i11 * ty + i12 * tz);
    r.m[3][2] = -(i20 * tx + i21 * ty + i22 * tz);
    r.m[3][3] = 1.0f;
    *out = r;
    return true;
}

#ifdef __cplusplus
}
#endif
#endif /* FM_MATH_H */
