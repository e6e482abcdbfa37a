/**
 * @file coll/mesh.h
 * @brief Immutable collision meshes: triangles plus a uniform grid spatial hash, in one
 *        caller-owned, relocatable, 8-byte-aligned block.
 *
 * Build one in memory with coll_mesh_build(), or bake it on the PC (tools/collbake) and use
 * the blob in place with coll_mesh_load(). Both produce the same layout.
 */
#ifndef COLL_MESH_H
#define COLL_MESH_H

#include "coll/common.h"

#ifdef __cplusplus
extern "C" {
#endif

/** Opaque: the layout lives in src/coll/mesh_format.h (shared with the bake tool). */
typedef struct coll_mesh_s coll_mesh_t;

/** Build flags. */
enum {
    /** Store vertices as 16-bit fixed point within the mesh bounds (smaller, slightly lossy). */
    COLL_MESH_QUANTIZE = 1u << 0,
};

/** Options for coll_mesh_build(); NULL means all defaults. */
typedef struct {
    float    cell_size; ///< grid cell edge in meters; <= 0 chooses one from the triangle sizes
    uint32_t flags;     ///< COLL_MESH_* flags
} coll_mesh_build_opts_t;

/** Upper bound of the bytes coll_mesh_build() needs for this many vertices and triangles. */
size_t coll_mesh_build_size(uint32_t nverts, uint32_t ntris, const coll_mesh_build_opts_t *opts);

/**
 * Builds a mesh into buf (8-byte aligned, at least coll_mesh_build_size() bytes).
 * Degenerate (zero-area, repeated-index, out-of-range-index or non-finite) triangles are
 * dropped. On success *out points into buf. Allocation-free.
 */
coll_err_t coll_mesh_build(void *buf, size_t buf_size, const float *verts_xyz, uint32_t nverts,
                           const uint32_t *indices, uint32_t ntris,
                           const coll_mesh_build_opts_t *opts, const coll_mesh_t **out);

/**
 * Validates a baked blob and uses it in place (no copy). A big-endian blob on a
 * little-endian machine is byte-swapped in place once; loading the same buffer again is
 * fine. Every count, offset and index is checked: a corrupt or hostile blob returns an
 * error and is never read out of bounds.
 */
coll_err_t coll_mesh_load(void *blob, size_t size, const coll_mesh_t **out);

/** Bytes the mesh occupies in its block (what the bake tool writes). */
size_t coll_mesh_size(const coll_mesh_t *mesh);

uint32_t coll_mesh_triangle_count(const coll_mesh_t *mesh);

/** The vertices of triangle i in mesh-local space; i out of range gives three zero vectors. */
void coll_mesh_triangle(const coll_mesh_t *mesh, uint32_t i, fm_vec3_t out[3]);

/** Mesh-local bounding box. */
void coll_mesh_bounds(const coll_mesh_t *mesh, fm_vec3_t *min, fm_vec3_t *max);

#ifdef __cplusplus
}
#endif
#endif
