/**
 * @file fm_math.h
 * @brief Float vector, quaternion and matrix math with libdragon's `fgeom.h` names.
 *
 * User code written against libdragon's fgeom.h compiles against this header and the
 * other way round. Every function takes its output pointer first and works when the
 * output aliases an input. Build with -DCOLL_USE_LIBDRAGON_FMATH to take the types and
 * functions from libdragon instead (on the console, inside a libdragon build).
 *
 * Everything is single precision: the VR4300 runs double math in slow software paths
 * under the N64 ABI, so no double may appear here (-Wdouble-promotion guards it).
 */
#ifndef FM_MATH_H
#define FM_MATH_H

#include <stdbool.h>

#ifdef COLL_USE_LIBDRAGON_FMATH
#include <fgeom.h>
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
void  fm_vec3_negate(fm_vec3_t *out, const fm_vec3_t *v);
void  fm_vec3_add(fm_vec3_t *out, const fm_vec3_t *a, const fm_vec3_t *b);
void  fm_vec3_sub(fm_vec3_t *out, const fm_vec3_t *a, const fm_vec3_t *b);
/** Component-wise product. */
void  fm_vec3_mul(fm_vec3_t *out, const fm_vec3_t *a, const fm_vec3_t *b);
/** Component-wise quotient. */
void  fm_vec3_div(fm_vec3_t *out, const fm_vec3_t *a, const fm_vec3_t *b);
void  fm_vec3_scale(fm_vec3_t *out, const fm_vec3_t *a, float s);
float fm_vec3_dot(const fm_vec3_t *a, const fm_vec3_t *b);
float fm_vec3_len2(const fm_vec3_t *a);
float fm_vec3_len(const fm_vec3_t *a);
float fm_vec3_distance2(const fm_vec3_t *a, const fm_vec3_t *b);
float fm_vec3_distance(const fm_vec3_t *a, const fm_vec3_t *b);
/** Unit vector along a; the zero vector (length < FM_EPSILON) gives {0,0,0}. */
void  fm_vec3_norm(fm_vec3_t *out, const fm_vec3_t *a);
void  fm_vec3_cross(fm_vec3_t *out, const fm_vec3_t *a, const fm_vec3_t *b);
/** a + (b - a) * t */
void  fm_vec3_lerp(fm_vec3_t *out, const fm_vec3_t *a, const fm_vec3_t *b, float t);
/** Reflects incident i about the unit normal n. */
void  fm_vec3_reflect(fm_vec3_t *out, const fm_vec3_t *i, const fm_vec3_t *n);
/** libdragon's argument order: rotates i by q. */
void  fm_vec3_rotate(fm_vec3_t *out, const fm_vec3_t *i, const fm_quat_t *q);

/* ---- quat ---- */
void  fm_quat_identity(fm_quat_t *out);
/** axis must be unit length; angle in radians. */
void  fm_quat_from_axis_angle(fm_quat_t *out, const fm_vec3_t *axis, float angle);
/** Hamilton product a*b: applies b first, then a. */
void  fm_quat_mul(fm_quat_t *out, const fm_quat_t *a, const fm_quat_t *b);
/** q followed by a rotation about axis by angle (libdragon semantics). */
void  fm_quat_rotate(fm_quat_t *out, const fm_quat_t *q, const fm_vec3_t *axis, float angle);
float fm_quat_dot(const fm_quat_t *a, const fm_quat_t *b);
/** Inverse; a zero quaternion gives the identity. */
void  fm_quat_inverse(fm_quat_t *out, const fm_quat_t *q);
/** Unit quaternion; a zero quaternion gives the identity. */
void  fm_quat_norm(fm_quat_t *out, const fm_quat_t *q);
void  fm_quat_nlerp(fm_quat_t *out, const fm_quat_t *a, const fm_quat_t *b, float t);
/** Shortest-arc spherical interpolation, t in [0,1]. */
void  fm_quat_slerp(fm_quat_t *out, const fm_quat_t *a, const fm_quat_t *b, float t);

/* ---- mat4 (subset) ---- */
void  fm_mat4_identity(fm_mat4_t *out);
/** Scale, then rotate, then translate (libdragon's fm_mat4_from_srt). */
void  fm_mat4_from_srt(fm_mat4_t *out, const fm_vec3_t *scale, const fm_quat_t *quat, const fm_vec3_t *translate);
void  fm_mat4_mul(fm_mat4_t *out, const fm_mat4_t *a, const fm_mat4_t *b);
void  fm_mat4_transpose(fm_mat4_t *out, const fm_mat4_t *m);

#ifdef __cplusplus
}
#endif
#endif /* COLL_USE_LIBDRAGON_FMATH */

/* ---- helpers libdragon lacks: ours in both builds ---- */
#ifdef __cplusplus
extern "C" {
#endif
/** Rotate a vector by a unit quaternion (q first, like the other quat calls). */
void  fm_quat_rotate_vec3(fm_vec3_t *out, const fm_quat_t *q, const fm_vec3_t *v);
/** Transforms a point (w = 1), dropping w (affine matrices). */
void  fm_mat4_mul_point(fm_vec3_t *out, const fm_mat4_t *m, const fm_vec3_t *p);
/** Transforms a direction (w = 0). */
void  fm_mat4_mul_dir(fm_vec3_t *out, const fm_mat4_t *m, const fm_vec3_t *d);
/** Inverse of an affine matrix; returns false (out = identity) when singular. */
bool  fm_mat4_affine_inverse(fm_mat4_t *out, const fm_mat4_t *m);
#ifdef __cplusplus
}
#endif
#endif /* FM_MATH_H */
