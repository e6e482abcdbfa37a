/**
 * @file vec3.h
 * @brief The library's private by-value vector helpers over fm_vec3_t (the one vector
 *        dialect of src/coll: primitives, queries and the character body). Header-inline,
 *        so the archive exports nothing of them; float only, no libm beyond sqrtf.
 */
#ifndef COLL_VEC3_H
#define COLL_VEC3_H

#include "coll_libm.h"
#include <stdbool.h>
#include "fm_math.h"

/** Squared length below which a vector has no direction (length 1e-15 m). */
#define V3_TINY_LEN2 1e-30f

static inline fm_vec3_t v3(float x, float y, float z) { fm_vec3_t v = {{x, y, z}}; return v; }
static inline fm_vec3_t v3_add(fm_vec3_t a, fm_vec3_t b) { return v3(a.x + b.x, a.y + b.y, a.z + b.z); }
static inline fm_vec3_t v3_sub(fm_vec3_t a, fm_vec3_t b) { return v3(a.x - b.x, a.y - b.y, a.z - b.z); }
static inline fm_vec3_t v3_scale(fm_vec3_t a, float s) { return v3(a.x * s, a.y * s, a.z * s); }
/** a + b * s */
static inline fm_vec3_t v3_madd(fm_vec3_t a, fm_vec3_t b, float s) { return v3(a.x + b.x * s, a.y + b.y * s, a.z + b.z * s); }
static inline fm_vec3_t v3_neg(fm_vec3_t a) { return v3(-a.x, -a.y, -a.z); }
static inline float v3_dot(fm_vec3_t a, fm_vec3_t b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static inline float v3_len2(fm_vec3_t a) { return v3_dot(a, a); }
static inline float v3_len(fm_vec3_t a) { return sqrtf(v3_dot(a, a)); }
static inline fm_vec3_t v3_cross(fm_vec3_t a, fm_vec3_t b)
{
    return v3(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}
/** a without its component along unit n. */
static inline fm_vec3_t v3_reject(fm_vec3_t a, fm_vec3_t n) { return v3_madd(a, n, -v3_dot(a, n)); }

/** True for a finite float (NaN and infinities give false); needs no libm. */
static inline bool f_finite(float x) { return (x - x) == 0.0f; }
static inline bool v3_finite(fm_vec3_t v) { return f_finite(v.x) && f_finite(v.y) && f_finite(v.z); }
static inline float f_min(float a, float b) { return a < b ? a : b; }
static inline float f_max(float a, float b) { return a > b ? a : b; }
static inline float f_clamp01(float x) { return x < 0.0f ? 0.0f : (x > 1.0f ? 1.0f : x); }

/** Unit vector along a, or `fallback` when a has no direction (tiny or not finite). */
static inline fm_vec3_t v3_unit_or(fm_vec3_t a, fm_vec3_t fallback)
{
    float l2 = v3_len2(a);
    if (!(l2 > V3_TINY_LEN2) || !f_finite(l2)) return fallback;
    return v3_scale(a, 1.0f / sqrtf(l2));
}
/** v3_unit_or(a, v3_unit_or(-d, +y)): a normal, or away from d when a has no direction,
 *  with the fallback worked out only when it is used (as an argument it would cost a
 *  square root and a division on every call). */
static inline fm_vec3_t v3_unit_or_against(fm_vec3_t a, fm_vec3_t d)
{
    float l2 = v3_len2(a);
    if (!(l2 > V3_TINY_LEN2) || !f_finite(l2)) return v3_unit_or(v3_neg(d), v3(0.0f, 1.0f, 0.0f));
    return v3_scale(a, 1.0f / sqrtf(l2));
}
/** Unit vector along a, or the zero vector when a has no direction. */
static inline fm_vec3_t v3_norm(fm_vec3_t a) { return v3_unit_or(a, v3(0.0f, 0.0f, 0.0f)); }

#endif
