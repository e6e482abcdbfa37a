/**
 * @file prim.h
 * @brief Exact geometric primitives: ray and capsule against one triangle or one convex
 *        body. Plain functions on plain values, usable without a scene (and testable so).
 *
 * Conventions shared by every primitive:
 *  - Coordinates are relative to a caller-chosen origin near the query (the scene code
 *    subtracts the capsule centre first), so float precision holds far from the world origin.
 *  - A capsule is the segment seg[0]..seg[1] swept by a sphere of radius r.
 *  - Normals are unit and point from the collider towards the query shape.
 *  - Sweeps return the earliest t in [0, t_max] at which the moving capsule touches;
 *    when the capsule already overlaps at t = 0, they return t = 0 and depth > 0 with the
 *    normal that pushes it out (the minimum-translation direction).
 *  - Triangles are two-sided. Degenerate triangles never produce NaN (they may be missed).
 */
#ifndef COLL_PRIM_H
#define COLL_PRIM_H

#include "coll/common.h"
#include "coll/scene.h"

typedef struct {
    float t;          ///< time of impact in [0, t_max]
    float depth;      ///< > 0 only for an initial overlap (then t = 0)
    fm_vec3_t normal; ///< unit, collider -> query
    fm_vec3_t point;  ///< contact point, same frame as the inputs
} coll_prim_hit_t;

/** Ray o + d*s, s in [0, s_max] (d need not be unit: s is in units of |d|). Two-sided. */
bool coll_ray_triangle(const fm_vec3_t *o, const fm_vec3_t *d, const fm_vec3_t tri[3],
                       float s_max, coll_prim_hit_t *hit);

/** Moving capsule against a triangle: face, edge and vertex features, exact time of impact. */
bool coll_capsule_triangle_sweep(const fm_vec3_t seg[2], float r, const fm_vec3_t *disp,
                                 const fm_vec3_t tri[3], float t_max, coll_prim_hit_t *hit);

/** Static capsule against a triangle: true with depth > 0 when they overlap. */
bool coll_capsule_triangle_overlap(const fm_vec3_t seg[2], float r, const fm_vec3_t tri[3],
                                   coll_prim_hit_t *hit);

/** Ray against a convex collider body; body position given relative to the same origin. */
bool coll_ray_body(const fm_vec3_t *o, const fm_vec3_t *d, const coll_body_t *body,
                   const fm_vec3_t *body_pos_rel, float s_max, coll_prim_hit_t *hit);

/** Moving capsule against a convex collider body (libccd, no EPA on this path). */
bool coll_capsule_body_sweep(const fm_vec3_t seg[2], float r, const fm_vec3_t *disp,
                             const coll_body_t *body, const fm_vec3_t *body_pos_rel,
                             float t_max, coll_prim_hit_t *hit);

/** Static capsule against a convex collider body. */
bool coll_capsule_body_overlap(const fm_vec3_t seg[2], float r, const coll_body_t *body,
                               const fm_vec3_t *body_pos_rel, coll_prim_hit_t *hit);


/* ---- additions (prim part) ---- */

/**
 * Touch tolerance, meters: a capsule closer than r but no closer than r - tol (tol =
 * min(COLL_PRIM_TOUCH_TOL, r/4)) is touching, not overlapping. Sweeps report a hit only
 * when the motion takes the capsule deeper than tol, at the first time it reaches r: a
 * capsule sliding along a surface it touches, or touching and moving away, is not blocked.
 */
#define COLL_PRIM_TOUCH_TOL 1e-4f
/*
 * Notes for callers (prim part):
 *  - The tolerance is judged per call: a caller taking the minimum over several triangles
 *    may get a time up to "tol deep" later than the exact first contact with their union
 *    (when the first-touched triangle is only grazed while another is entered); the
 *    capsule never penetrates any triangle deeper than tol before the reported time.
 *    Box bodies judge it on the whole box.
 *  - Coordinates (and disp * t_max, radii) beyond +-1e7 m are rejected (false), as are
 *    NaN and infinities. A ray starting inside a body hits at s = 0 with the normal of
 *    the nearest surface.
 */

/**
 * The triangle sweep the scene code calls: coll_capsule_triangle_sweep, or, in a
 * COLL_METHOD_HOOKS build, the installed method. Same contract as that function.
 */
bool coll_tri_sweep(const fm_vec3_t seg[2], float r, const fm_vec3_t *disp,
                    const fm_vec3_t tri[3], float t_max, coll_prim_hit_t *hit);

/**
 * coll_tri_sweep for a caller that already holds a contact at t_max: a contact after
 * t = 0 no sooner than t_max may be left unreported (it could not be better).
 */
bool coll_tri_sweep_before(const fm_vec3_t seg[2], float r, const fm_vec3_t *disp,
                           const fm_vec3_t tri[3], float t_max, coll_prim_hit_t *hit);

/**
 * What the triangle tests compute from the three vertices alone, independent of the query
 * (prim_triangle.c): the raw normal (the two shortest edges crossed, exactly for a flat
 * sliver), the unit normal (a square root and a division) and whether there is a face. A
 * caller that tests the same triangle (the same three vertex values) against several
 * queries keeps one (a step's gather: gather.h), ready = false at first: the first *_prep
 * test (or coll_ray_triangle_sheared's first hit) fills it, the later ones use it. Results
 * are bit-identical to the plain tests'.
 */
typedef struct {
    fm_vec3_t nraw;   ///< (edge ia) x (edge ib), the two shortest edges
    fm_vec3_t n;      ///< unit normal when has_face, else zero
    bool has_face;
    bool ready;       ///< false: not filled yet
    uint8_t apex;     ///< the vertex the two shortest edges share (the ray's plane point)
} coll_tri_prep_t;

/**
 * The ray's part of coll_ray_triangle (its shear to +z: the axes and two divisions),
 * independent of the triangle: worked out once for a ray tested against many
 * (coll_ray_shear; false: nothing can be hit, a direction with no length or out of
 * range), then coll_ray_triangle_sheared per triangle, through the triangle's prep p (the
 * raw normal, and on a hit its unit normal, made and kept when not ready; NULL: none).
 * The same expressions as coll_ray_triangle's: bit-identical results.
 */
typedef struct {
    uint8_t kz;       ///< the axis of d's largest component (x and y follow it)
    float sx, sy;
} coll_ray_shear_t;
bool coll_ray_shear(const fm_vec3_t *d, coll_ray_shear_t *sh);
bool coll_ray_triangle_sheared(const fm_vec3_t *o, const fm_vec3_t *d, const coll_ray_shear_t *sh,
                               const fm_vec3_t tri[3], float s_max, coll_tri_prep_t *p, coll_prim_hit_t *hit);

/** coll_tri_sweep (held NULL) or coll_tri_sweep_before (held not NULL), and
 *  coll_capsule_triangle_overlap, through the triangle's prep p (filled when not ready;
 *  NULL: the plain tests). *held: the held contact's normal (any vector; zero: none), which
 *  the sweep tries as a separating axis before its closest pairs (a held hit's neighbour
 *  across their shared edge meets the capsule only at t_max and lies behind it): one cull
 *  more, the same answers. */
bool coll_tri_sweep_prep(const fm_vec3_t seg[2], float r, const fm_vec3_t *disp, const fm_vec3_t tri[3],
                         coll_tri_prep_t *p, float t_max, const fm_vec3_t *held, coll_prim_hit_t *hit);
bool coll_capsule_triangle_overlap_prep(const fm_vec3_t seg[2], float r, const fm_vec3_t tri[3],
                                        coll_tri_prep_t *p, coll_prim_hit_t *hit);
/** A segment's and a triangle's boundary axis u (tri_sweep's first separating axis; zero:
 *  none) and their extents along it: the segment's lower end seg0, the triangle's upper end
 *  top (u . the points, as the sweep's own cull computes them). */
typedef struct {
    fm_vec3_t u;
    float seg0, top;
} coll_tri_axis_t;
/** coll_capsule_triangle_overlap_prep, telling too (*clear) when it found no overlap by the
 *  closest pair (not within r less the touch tolerance) or by a separating axis with an
 *  allowance far above that pair's rounding: then a sweep of the same segment (the same seg
 *  values) and radius against the same triangle (the same tri values) with t_max = 0, which
 *  computes that pair (coll_tri_sweep_prep: no motion), finds no overlap and nothing. */
bool coll_capsule_triangle_overlap_clear(const fm_vec3_t seg[2], float r, const fm_vec3_t tri[3],
                                         coll_tri_prep_t *p, coll_prim_hit_t *hit, bool *clear,
                                         coll_tri_axis_t *axis);
/** With axis (not NULL) set by coll_capsule_triangle_overlap_clear for a segment and
 *  triangle (zero when it found them clear otherwise than by the boundary axis): true when
 *  coll_tri_sweep_prep of that very segment, radius and triangle (the same values, its prep
 *  ready) moved by disp over t_max would be dropped by its boundary-axis cull (the same
 *  axis, the same expressions: sweep_separated_start), so would find nothing. False
 *  when it cannot tell. */
bool coll_tri_sweep_axis_culls(const fm_vec3_t seg[2], float r, const fm_vec3_t *disp, const fm_vec3_t tri[3],
                               float t_max, const coll_tri_axis_t *axis);

#ifdef COLL_METHOD_HOOKS
/*
 * Method hooks, for benchmarks and tests only. The library proper has no runtime switch
 * (no global checked per triangle): prim_method.c and prim_body.c built with
 * -DCOLL_METHOD_HOOKS make libcoll_hooks.a, which a benchmark or suite that defines
 * COLL_METHOD_HOOKS links ahead of libcoll.a.
 */

/** Another capsule-vs-triangle sweep (libccd conservative advancement, sub-steps, ...). */
typedef bool (*coll_tri_sweep_fn)(void *ctx, const fm_vec3_t seg[2], float r, const fm_vec3_t *disp,
                                  const fm_vec3_t tri[3], float t_max, coll_prim_hit_t *hit);

/** Installs a triangle-sweep method; fn = NULL restores the exact analytic one. */
void coll_set_tri_sweep_method(coll_tri_sweep_fn fn, void *ctx);

/**
 * Forces the libccd MPR path (bisection on the swept capsule) for cylinder-body sweeps
 * instead of the Newton-on-exact-distance path. Default false.
 */
void coll_set_body_sweep_mpr(bool force);
#endif

#endif
