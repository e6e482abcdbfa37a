/**
 * @file prim_util.h
 * @brief Shared building blocks of prim_*.c
 *        (ray vs sphere / cylinder / capsule, closest points of two segments).
 *        Not part of any public header; float only.
 */
#ifndef COLL_PRIM_UTIL_H
#define COLL_PRIM_UTIL_H

#include "coll_libm.h"
#include <stdint.h>
#include "prim.h"
#include "vec3.h"

/** Largest coordinate magnitude the primitives accept (inputs are relative to a nearby
 *  origin; beyond this products overflow float and the answer means nothing). */
#define PRIM_MAX_COORD 1.0e7f
/** Finite, and every component within +-PRIM_MAX_COORD (false for NaN too). */
static inline bool prim_sane(float x) { return x >= -PRIM_MAX_COORD && x <= PRIM_MAX_COORD; }
/* The same test on the bit patterns, without a branch per compare: |x| <= PRIM_MAX_COORD
 * exactly when the magnitude bits are at most its bits (NaNs and infinities are above). */
static inline uint32_t prim_over_bits(float x)
{
    /* a union, not memcpy: the console build is freestanding, where memcpy is a call */
    union { float f; uint32_t u; } b = { x };
    return (uint32_t)((b.u & 0x7fffffffu) > 0x4b189680u); /* 0x4b189680u: 1.0e7f */
}
static inline bool prim_sane3(fm_vec3_t v)
{
    return (prim_over_bits(v.x) | prim_over_bits(v.y) | prim_over_bits(v.z)) == 0u;
}
/* prim_sane on many values with one branch: 1.0e7f's bits less |x|'s bits, negative (as a
 * signed 32-bit value: both are below 2^31, so no overflow) exactly when prim_over_bits(x);
 * OR them and test the sign once. */
static inline uint32_t prim_room_bits(float x)
{
    union { float f; uint32_t u; } b = { x };
    return 0x4b189680u - (b.u & 0x7fffffffu);
}
static inline uint32_t prim_room3(fm_vec3_t v)
{
    return prim_room_bits(v.x) | prim_room_bits(v.y) | prim_room_bits(v.z);
}
/* the OR of prim_room_* values: true when every one was sane */
static inline bool prim_room_ok(uint32_t room) { return (room & 0x80000000u) == 0u; }

/**
 * Sufficient (cheap) test that a contact goes deeper than the tolerance: the query's
 * closest point q sits at distance `dist` from the collider's point p along unit n
 * (q - p = dist * n); moving on by s*d, s in [0, s_left], brings q closer than rin to p
 * (so closer than rin to the collider). False means "not proven", not "no".
 */
static inline bool prim_goes_deeper(float dist, fm_vec3_t n, fm_vec3_t d, float rin, float s_left)
{
    float A = v3_dot(d, d), B = -dist * v3_dot(n, d), C = dist * dist - rin * rin;
    if (!(A > 0.0f) || !(B > 0.0f) || !(s_left > 0.0f)) return false;
    if (C <= 0.0f) return true;
    float disc = B * B - A * C;
    if (!(disc > 0.01f * B * B)) return false;   /* near-tangent: leave it to the exact test */
    float s = C / (B + sqrtf(disc));
    return s * 1.01f < s_left;
}

/** Result of one elementary ray test: parameter, unit outward normal of the primitive. */
typedef struct {
    float s;
    fm_vec3_t n;
} prim_ray_t;

/*
 * Elementary ray tests, shared by the triangle sweep and the bodies. All return the
 * earliest s in [0, s_max] at which o + s*d is on the primitive's surface while entering;
 * an origin already inside gives s = 0 with the normal at the nearest surface point.
 * The normal is the primitive's outward unit normal at the hit.
 */
bool coll_prim_ray_sphere(fm_vec3_t o, fm_vec3_t d, fm_vec3_t c, float r, float s_max, prim_ray_t *out);
/** Side of the finite cylinder around c0..c1 only (no caps). */
bool coll_prim_ray_cylinder_side(fm_vec3_t o, fm_vec3_t d, fm_vec3_t c0, fm_vec3_t c1, float r, float s_max,
                            prim_ray_t *out);
/** Capsule = side + two spheres. */
bool coll_prim_ray_capsule(fm_vec3_t o, fm_vec3_t d, fm_vec3_t c0, fm_vec3_t c1, float r, float s_max,
                      prim_ray_t *out);
/** Closest points of segments p0..p1 and q0..q1 (degenerate segments allowed); returns dist^2. */
float coll_prim_closest_seg_seg(fm_vec3_t p0, fm_vec3_t p1, fm_vec3_t q0, fm_vec3_t q1,
                           float *u, float *v, fm_vec3_t *cp, fm_vec3_t *cq);

/** Squared distance of segment a..b to a triangle, with closest points (ps on a..b). */
float coll_prim_seg_tri_closest(const fm_vec3_t tri[3], fm_vec3_t a, fm_vec3_t b, fm_vec3_t *ps, fm_vec3_t *pt);

/**
 * coll_capsule_triangle_sweep with the touch-tolerance confirmation optional: with
 * confirm = false it reports the first contact (distance r) even when the motion never
 * goes deeper than the tolerance into this triangle. Unions of triangles (a box) confirm
 * on the whole union instead.
 */
bool coll_prim_tri_sweep_ex(const fm_vec3_t seg[2], float r, const fm_vec3_t *disp, const fm_vec3_t tri[3],
                       float t_max, bool confirm, coll_prim_hit_t *hit);

/**
 * coll_capsule_triangle_sweep on a prepared triangle (p: its prep, filled when not ready;
 * NULL: none kept), for a caller that may already hold a contact at t_max (held): then a
 * contact after t = 0 no sooner than t_max is no hit (it could not be better). Contacts at
 * t = 0 (overlaps, touches) are reported as before. held: NULL (none) or the held contact's
 * normal (any vector; zero for none): tried as a separating axis, one cull more.
 */
bool coll_prim_tri_sweep_prep(const fm_vec3_t seg[2], float r, const fm_vec3_t *disp, const fm_vec3_t tri[3],
                              coll_tri_prep_t *p, float t_max, const fm_vec3_t *held, coll_prim_hit_t *hit);

#endif
