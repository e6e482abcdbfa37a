/**
 * @file gather.h
 * @brief The candidate triangles of one character step, gathered once (private).
 *
 * A step asks the scene for a handful of queries around one place (the overlap recovery,
 * the slide's sweeps, the floor probe ray). Each scene query walks the grid cells of every
 * instance, deduplicates, and transforms the candidates again. A gather walks the cells of
 * the step's box once and keeps the triangles that meet it, in query-relative form (an
 * exact shape and the first vertex's offset from the gather's origin), in a fixed buffer;
 * the queries below then scan that buffer. A query whose box is not inside the gathered box,
 * or any query after the buffer overflowed, goes to the scene query instead: results are
 * the same either way (exact nearest hits, all candidates). A sweep that leaves the box (the
 * crack rule's roll) is still answered by the gathered triangles when one of them is met
 * before its swept box leaves the gathered one: nothing else can be met sooner.
 * A box that meets more triangles than the buffer holds shrinks about its centre (to no less
 * than half its size on each axis), dropping the triangles the smaller box misses; only when
 * that is not enough does the gather overflow (gather.c, gather_shrink).
 */
#ifndef COLL_GATHER_H
#define COLL_GATHER_H

#include "coll/scene.h"
#include "coll/char_body.h"
#include "prim.h"

/** Triangles a gather keeps (96 bytes each on the console: the gather is 12.3 KB, on the
 *  stack of coll_cb_step). */
#define COLL_GATHER_MAX 128

typedef struct {
    fm_vec3_t w0;        ///< first vertex relative to the gather's origin
    fm_vec3_t e1, e2;    ///< the other two vertices relative to the first (exact shape)
    fm_vec3_t lo, hi;    ///< box of the triangle relative to the gather's origin
    const coll_mesh_instance_t *inst;
    int32_t tri;
    /** The exact tests' setup of the shape (0, e1, e2) (prim.h: its normal, a square root
     *  and a division), made by the first query that tests the triangle exactly (or the
     *  first ray that hits it) and used by the step's later ones (5-15 queries over the
     *  same triangles; the ray's raw normal and plane point too). */
    coll_tri_prep_t prep;
} coll_gather_tri_t;

typedef struct {
    const coll_scene_t *scene;
    fm_vec3_t origin;    ///< world centre of the gathered box
    fm_vec3_t lo, hi;    ///< the gathered box, relative to origin (maybe shrunk: gather_shrink)
    uint8_t read_mask, types;
    bool valid;          ///< false: overflowed (or nothing gathered): every query goes to the scene
    float scale;         ///< the gathered box's size against the one asked (gather_shrink)
    uint16_t ntris;
    coll_gather_tri_t tris[COLL_GATHER_MAX];
    /** At least every gathered triangle's hi.y (the largest a triangle kept had; a shrink
     *  keeps it): a query box whose low y is above it meets none of them (gather_sweep_scan).
     *  (After tris: ahead of them it moved their offset, and the console's query loops
     *  over them got dearer.) */
    float ytop;
} coll_gather_t;

/** Gathers the mesh triangles (seen through read_mask, when types has COLL_TYPE_MESH) that
 *  meet the world box lo..hi. Collider bodies are not gathered: queries test them as usual. */
void coll_gather_begin(coll_gather_t *g, const coll_scene_t *scene, fm_vec3_t lo, fm_vec3_t hi, uint8_t read_mask,
                       uint8_t types);

/** coll_gather_begin through a gather cache (coll_gather_cache_t, char_body.h): when the
 *  cache covers the box (the same scene and mesh list, each walked instance on the same
 *  mesh, and the box's mesh-local box under each instance's transform now inside the one
 *  the cache walked), the gather is filtered from the cached triangles; otherwise the cache
 *  is refilled for fill_lo..fill_hi (the caller's, around lo..hi) first. The gather is
 *  coll_gather_begin's: the same triangles in the same order, each with the same w0, e1,
 *  e2, lo, hi bit for bit. A refill that meets more than COLL_GATHER_CACHE_TRIS triangles
 *  or 64 cells of an instance (or a scene of more than COLL_GATHER_CACHE_INSTANCES
 *  instances) gives coll_gather_begin's gather, and the next few misses skip the refill. */
void coll_gather_begin_cached(coll_gather_t *g, coll_gather_cache_t *cache, const coll_scene_t *scene, fm_vec3_t lo,
                              fm_vec3_t hi, fm_vec3_t fill_lo, fm_vec3_t fill_hi, uint8_t read_mask, uint8_t types);
/** coll_gather_begin_cached's two halves: the gather from the cache when it covers the box
 *  (true; false: g not usable), and the refill for fill_lo..fill_hi then the gather from it
 *  (or coll_gather_begin's gather). The caller computes the refill's box only on a miss. */
bool coll_gather_from_cache(coll_gather_t *g, coll_gather_cache_t *cache, const coll_scene_t *scene, fm_vec3_t lo,
                            fm_vec3_t hi, uint8_t read_mask, uint8_t types);
void coll_gather_refill(coll_gather_t *g, coll_gather_cache_t *cache, const coll_scene_t *scene, fm_vec3_t lo,
                        fm_vec3_t hi, fm_vec3_t fill_lo, fm_vec3_t fill_hi, uint8_t read_mask, uint8_t types);
/** Empties a cache (its counters too). */
void coll_gather_cache_reset(coll_gather_cache_t *cache);

/** coll_raycast / coll_capsule_sweep / coll_capsule_overlaps on the gathered scene (its
 *  read_mask and types). g NULL or invalid: nothing (use the scene functions). Not const:
 *  they fill the triangles' prep as they need it. */
bool coll_gather_raycast(coll_gather_t *g, fm_vec3_t origin, fm_vec3_t dir_unit, float max_dist,
                         coll_ray_hit_t *hit);
bool coll_gather_capsule_sweep(coll_gather_t *g, fm_vec3_t center, fm_vec3_t axis_up_unit, float radius,
                               float inner_half_height, fm_vec3_t displacement, coll_sweep_hit_t *hit);
/** coll_gather_capsule_sweep, the same answer, with a cull that pays where a capsule moves
 *  diagonally beside the edges of triangles flat along an axis (a stair step's lift, move
 *  across and come down beside the next riser and tread: the box test's corners) and costs
 *  a few instructions on every other such triangle. */
bool coll_gather_capsule_sweep_corner(coll_gather_t *g, fm_vec3_t center, fm_vec3_t axis_up_unit, float radius,
                                      float inner_half_height, fm_vec3_t displacement, coll_sweep_hit_t *hit);
/** A plane the caller knows a sweep stays above: every point of the swept capsule more than
 *  2 x margin above the plane through p with unit normal n, over the whole motion (the
 *  crack rule's ball dropped to two skins over the floor the foot ray found; its roll along
 *  the tangent plane of the contact it rests on). all: every candidate is checked against
 *  it; else only the tilted ones (a triangle flat along an axis under a drop is out of its
 *  box already). */
typedef struct {
    fm_vec3_t n, p;
    float margin;
    bool all;
} coll_gather_above_t;

/** coll_gather_capsule_sweep for a sweep that stays above `above`: a gathered triangle lying
 *  wholly within margin above that plane (or below it) is at least margin from the swept
 *  capsule, so its exact test (which reports contacts within the radius only) would find
 *  nothing; it is not made. The answer is the sweep's, also when it leaves the gathered box
 *  (the scene's walk skips them too). */
bool coll_gather_capsule_sweep_above(coll_gather_t *g, fm_vec3_t center, fm_vec3_t axis_up_unit, float radius,
                                     float inner_half_height, fm_vec3_t displacement,
                                     const coll_gather_above_t *above, coll_sweep_hit_t *hit);
uint32_t coll_gather_capsule_overlaps(coll_gather_t *g, fm_vec3_t center, fm_vec3_t axis_up_unit, float radius,
                                      float inner_half_height, coll_contact_t *out, uint32_t max_out);

/**
 * coll_capsule_overlaps / coll_gather_capsule_overlaps keeping one contact per point and
 * normal: a contact at the point of a kept one (within COLL_PRIM_TOUCH_TOL) with its normal
 * (within about 0.8 degrees) is a copy, counted once, the deeper kept. Coplanar duplicates
 * of a triangle (overlapping brushes, a level's near copies) and the edge or vertex its
 * neighbours share otherwise fill the buffer with one contact many times, and the deepest
 * max_out drop a shallower one elsewhere (the character body's look around its bottom ball:
 * soak s47 l73, the far side of a hole). The total counts the distinct contacts (those
 * dropped past max_out are counted even if copies of each other).
 */
uint32_t coll_capsule_overlaps_distinct(const coll_scene_t *scene, fm_vec3_t center, fm_vec3_t axis_up_unit,
                                        float radius, float inner_half_height, uint8_t read_mask, uint8_t coll_types,
                                        coll_contact_t *out, uint32_t max_out);
uint32_t coll_gather_capsule_overlaps_distinct(coll_gather_t *g, fm_vec3_t center, fm_vec3_t axis_up_unit,
                                               float radius, float inner_half_height, coll_contact_t *out,
                                               uint32_t max_out);

/** Gathered triangles a memo keeps (COLL_GATHER_MEMO_MAX: more are not kept, only tested). */
#define COLL_GATHER_MEMO_MAX 16

/**
 * What the last overlap query on a gather learnt (coll_gather_capsule_overlaps_m): the
 * capsule (centre, axis, radius, inner half height: the same values bit for bit) and the
 * gathered triangles whose closest pair to it the exact test computed and found no overlap
 * (clear of the touch tolerance). A sweep of that capsule from that very place that holds
 * a hit at t = 0 (the slide's first sweep after the recovery's overlap, into a wall it
 * touches: its later candidates are tested over t_max = 0) would test each such triangle
 * only to compute the same pair and find nothing (no motion, no overlap): it skips them.
 * g NULL: nothing known. The caller keeps it (the step's memory) and passes it to both. An
 * overlap query that found no such triangle leaves the record as it was: what it says about
 * its own capsule stays true (the same values, the same pairs).
 */
typedef struct {
    const coll_gather_t *g;
    fm_vec3_t center, axis;
    float radius, ihh;
    uint8_t n;
    uint8_t clear[COLL_GATHER_MEMO_MAX]; ///< indices into g->tris
    /** clear[i]'s boundary axis, when the exact test found it clear along that axis (else
     *  zero): a sweep of that capsule from there tests it over its motion first, as its own
     *  exact test would (coll_tri_sweep_axis_culls), and skips the triangle where it separates. */
    coll_tri_axis_t axis_of[COLL_GATHER_MEMO_MAX];
} coll_gather_memo_t;
_Static_assert(COLL_GATHER_MAX <= 256, "coll_gather_memo_t stores gathered-triangle indices in a byte");

/* The bits of a and b are the same (not ==: -0 and 0 differ, and may round apart later). */
static inline bool coll_same_bits(float a, float b)
{
    union { float f; uint32_t u; } x = { a }, y = { b }; /* (the console build has no memcpy inline) */
    return x.u == y.u;
}

/** The memo is of gather g and of this very capsule (the same values bit for bit): its clear
 *  triangles' closest pairs are the ones a sweep of it from there would compute. */
static inline bool coll_gather_memo_for(const coll_gather_memo_t *memo, const coll_gather_t *g, fm_vec3_t center,
                                        fm_vec3_t axis, float radius, float ihh)
{
    return memo->g == g && memo->n > 0 && coll_same_bits(memo->center.x, center.x) &&
           coll_same_bits(memo->center.y, center.y) && coll_same_bits(memo->center.z, center.z) &&
           coll_same_bits(memo->radius, radius) && coll_same_bits(memo->ihh, ihh) &&
           coll_same_bits(memo->axis.x, axis.x) && coll_same_bits(memo->axis.y, axis.y) &&
           coll_same_bits(memo->axis.z, axis.z);
}

/** coll_gather_capsule_sweep(_above) (above may be NULL) using memo (may be NULL). */
bool coll_gather_capsule_sweep_m(coll_gather_t *g, fm_vec3_t center, fm_vec3_t axis_up_unit, float radius,
                                 float inner_half_height, fm_vec3_t displacement, const coll_gather_above_t *above,
                                 const coll_gather_memo_t *memo, coll_sweep_hit_t *hit);
/** coll_gather_capsule_sweep_corner using memo (may be NULL) from wherever its capsule was
 *  (the same gather, axis, radius and inner half height; any centre): a triangle the memo's
 *  overlap found clear along its boundary axis is first tested along that axis over this
 *  sweep's motion (coll_tri_sweep_axis_culls, with this sweep's own segment), and skipped
 *  where that separates (a separating axis like tri_sweep's own culls). The stair step's
 *  down sweep, beside the recovery's look at the step's start. */
bool coll_gather_capsule_sweep_corner_m(coll_gather_t *g, fm_vec3_t center, fm_vec3_t axis_up_unit, float radius,
                                        float inner_half_height, fm_vec3_t displacement,
                                        const coll_gather_memo_t *memo, coll_sweep_hit_t *hit);
/** coll_gather_capsule_overlaps, filling memo (may be NULL) with what it learnt. */
uint32_t coll_gather_capsule_overlaps_m(coll_gather_t *g, fm_vec3_t center, fm_vec3_t axis_up_unit, float radius,
                                        float inner_half_height, coll_contact_t *out, uint32_t max_out,
                                        coll_gather_memo_t *memo);

#endif
