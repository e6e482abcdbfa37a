/**
 * @file coll/common.h
 * @brief Error codes, collider type flags and transforms shared by every coll module.
 */
#ifndef COLL_COMMON_H
#define COLL_COMMON_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include "fm_math.h"

#ifdef __cplusplus
extern "C" {
#endif

/** Result of every fallible coll call. New codes are only ever added at the end. */
typedef enum {
    COLL_OK = 0,
    COLL_ERR_INVALID_ARG,      ///< NULL, NaN, negative size or otherwise unusable argument
    COLL_ERR_FULL,             ///< a fixed-capacity container is full; nothing was changed
    COLL_ERR_BUFFER_TOO_SMALL, ///< caller's buffer is smaller than the required size
    COLL_ERR_BAD_MAGIC,        ///< not a coll blob (or loaded twice at different addresses)
    COLL_ERR_VERSION,          ///< blob from another format version
    COLL_ERR_TRUNCATED,        ///< blob shorter than its header says
    COLL_ERR_CORRUPT,          ///< a count, offset, index or checksum is out of bounds or wrong
    COLL_ERR_ALIGNMENT,        ///< buffer not 8-byte aligned
    COLL_ERR_NOT_FOUND,        ///< remove of something that was never added
} coll_err_t;

/** Static English text for an error code ("unknown error" for out-of-range values). */
const char *coll_strerror(coll_err_t err);

/** Which collider kinds a query sees. */
typedef enum {
    COLL_TYPE_MESH = 1,   ///< triangle mesh instances
    COLL_TYPE_BODY = 2,   ///< convex collider bodies
    COLL_TYPE_ALL  = 0xFF
} coll_type_flags_t;

/** Placement of a mesh instance or collider body: scale, then rotate, then translate. */
typedef struct {
    fm_vec3_t pos;   ///< world position, meters
    fm_quat_t rot;   ///< unit rotation quaternion
    fm_vec3_t scale; ///< per-axis scale; {1,1,1} for none. Zero components are invalid.
} coll_transform_t;

/** Identity transform initializer. */
#define COLL_TRANSFORM_IDENTITY {{{0.0f, 0.0f, 0.0f}}, {{0.0f, 0.0f, 0.0f, 1.0f}}, {{1.0f, 1.0f, 1.0f}}}

/** World position of the local point `local` under `xf` (scale, rotate, translate). */
fm_vec3_t coll_transform_point(const coll_transform_t *xf, fm_vec3_t local);

/**
 * Local position of the world point `world` under `xf` (the inverse of coll_transform_point).
 * Returns false, leaving *local untouched, when a scale component is zero or the result
 * is not finite.
 */
bool coll_transform_point_inverse(const coll_transform_t *xf, fm_vec3_t world, fm_vec3_t *local);

/**
 * coll_transform_point_inverse, and *placed = coll_transform_point(xf, *local) (the same
 * bits): where the local point is placed again, which the round trip leaves up to an ulp or
 * so of the coordinates away from `world`. A point anchored by its placement, not by
 * `world`, stays exactly where coll_transform_point puts it while xf does not change.
 * Returns false, leaving both untouched, as coll_transform_point_inverse does.
 */
bool coll_transform_point_anchor(const coll_transform_t *xf, fm_vec3_t world, fm_vec3_t *local, fm_vec3_t *placed);

#ifdef __cplusplus
}
#endif
#endif
