/*
 * Stand-in for libdragon's <fmath.h> (preview branch), written for charbody64's CI from
 * libdragon's documented API: the same macros, types and function signatures, simple
 * bodies of our own. Used only to check that the library and the example compile against
 * libdragon's math headers (make n64: n64-libdragon-api); never linked into anything.
 * Included with -isystem, as a toolchain install would be.
 */
#ifndef __LIBDRAGON_FMATH_H
#define __LIBDRAGON_FMATH_H

#include <math.h>
#include <string.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

#define FM_EPSILON      1e-4f
#define FM_PI           3.14159265358979f
#define FM_DEG2RAD(deg) ((deg) * 0.01745329252f)

#define BITCAST_F2I(f) ({ int32_t i; float _f = (f); memcpy(&i, &_f, 4); i; })
#define BITCAST_I2F(i) ({ float f;   memcpy(&f, &i, 4); f; })

static inline float fm_truncf(float x) { return (float)(int32_t)x; }
static inline float fm_ceilf(float x) { float t = fm_truncf(x); return t < x ? t + 1.0f : t; }
static inline float fm_floorf(float x) { float t = fm_truncf(x); return x < 0 ? t - 1.0f : t; }
static inline float fm_fmodf(float x, float y) { return x - fm_floorf(x * (1.0f / y)) * y; }

float fm_sinf(float x);
float fm_sinf_approx(float x, int approx);
float fm_cosf(float x);
void fm_sincosf(float x, float *sin, float *cos);
float fm_atan2f(float y, float x);

inline float fm_lerp(float a, float b, float t) { return a + (b - a) * t; }
float fm_lerp_angle(float a, float b, float t);

#ifdef LIBDRAGON_FAST_MATH
    #define truncf(x)      fm_truncf(x)
    #define floorf(x)      fm_floorf(x)
    #define ceilf(x)       fm_ceilf(x)
    #define fmodf(x, y)    ((__builtin_constant_p(x) && __builtin_constant_p(y)) ? fmodf(x,y) : fm_fmodf(x,y))
    #define sinf(x)        (__builtin_constant_p(x) ? sinf(x) : fm_sinf(x))
    #define cosf(x)        (__builtin_constant_p(x) ? cosf(x) : fm_cosf(x))
    #define atan2f(y, x)   ((__builtin_constant_p(x) && __builtin_constant_p(y)) ? atan2f(y, x) : fm_atan2f(y, x))
#endif

#ifdef __cplusplus
}
#endif
#endif
