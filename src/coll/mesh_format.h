/**
 * @file mesh_format.h
 * @brief The one definition of the collision-mesh layout, shared by the runtime
 *        (src/coll/mesh.c) and the bake tool.
 *
 * A mesh is one contiguous, relocatable block (offsets, never pointers), 8-byte aligned:
 *
 *     header (coll_mesh_s, 136 bytes)
 *     vertices   nverts x {float x,y,z}            (12 B each), or, with COLL_MESHF_QUANT,
 *                nverts x {uint16 x,y,z}           (6 B each): local = qorigin + q * qscale
 *     triangles  ntris x 3 vertex indices, uint16 with COLL_MESHF_IDX16 or COLL_MESHF_IDXBLK,
 *                else uint32
 *     tri bases  with COLL_MESHF_IDXBLK (version 4) only: one uint32 per block of
 *                COLL_MESH_TRI_BLOCK triangles; a triangle's vertex index is its block's
 *                base plus its stored uint16 (a mesh of more than 65535 vertices whose
 *                triangles each reach over fewer than 65536 vertices of their block's base:
 *                6 bytes a triangle instead of 12)
 *     cells      (ncells + 1) x uint32 prefix array: the triangles of cell entry c are
 *                refs[cells[c] .. cells[c+1]). Dense grid: ncells = dims[0] * dims[1] *
 *                dims[2], cell (x,y,z) has entry x + dims[0] * (y + dims[1] * z).
 *                Hashed grid (COLL_MESHF_HASH, version 2): ncells = nbuckets (a power of
 *                two), cell (x,y,z) has entry coll_mesh_cell_index(): cells that collide
 *                share their entry (its list is the union, each triangle once per cell it
 *                was registered from, ascending), so fine cells cost memory only where
 *                there are triangles; queries test every candidate exactly anyway.
 *     refs       nrefs triangle indices, uint16 with COLL_MESHF_REF16, else uint32
 *     codes      with COLL_MESHF_RCODE (version 5) only: nrefs bytes, one per ref: where in
 *                its cell the triangle lies, across the cell's X and Z in quarters
 *                (coll_mesh_ref_code): bits 0-3 the X quarters, bits 4-7 the Z quarters its
 *                box grown by grid_margin reaches (clamped to the cell). A query rejects a
 *                ref whose quarters miss its own box's quarters in the cell without reading
 *                the triangle (exactly: its box test would reject it too). Dense grids of
 *                float meshes only (the builder adds them where the blob stays within 24
 *                bytes a triangle; quantized and hashed meshes have none).
 *
 * Every section starts at an 8-byte aligned offset that is a pure function of the counts
 * and flags (coll_mesh_layout_of()); loaders recompute it and demand equality; the gaps
 * are zero. Per-triangle normals are not stored: they are recomputed exactly from the
 * vertices when a triangle is tested (0 bytes instead of 6).
 *
 * Byte order: the baked file (coll_mesh_write_blob()) is big-endian with magic
 * COLL_MESH_MAGIC_BLOB ("CMSH"). A mesh in use (built, or loaded and byte-swapped in
 * place) is in the machine's byte order with magic COLL_MESH_MAGIC_NATIVE ("CMSN"), so a
 * second coll_mesh_load() of the same buffer recognises it and only re-validates.
 *
 * Checksum: FNV-1a style over element VALUES (not bytes), so it is the same in both byte
 * orders: h = 2166136261; for each 32-bit header word from `version` on (skipping
 * `checksum` itself), then every vertex component, index, cell entry and ref in section
 * order (tri bases after the indices): h = (h ^ value) * 16777619. Every single-element
 * change alters it.
 */
#ifndef COLL_MESH_FORMAT_H
#define COLL_MESH_FORMAT_H

#include "coll/mesh.h"

#define COLL_MESH_MAGIC_BLOB   0x434D5348u /**< "CMSH": big-endian baked file, not yet loaded */
#define COLL_MESH_MAGIC_NATIVE 0x434D534Eu /**< "CMSN": native byte order, ready to use */
/** 2: hashed grid (COLL_MESHF_HASH, nbuckets). 3: the grid's registration margin is stored
 *  (grid_margin), so the queries use what the builder used. 4: block-based 16-bit vertex
 *  indices (COLL_MESHF_IDXBLK). 5: per-ref sub-cell codes (COLL_MESHF_RCODE). Version 3 blobs (which never have that flag) still load;
 *  older ones are refused (COLL_ERR_VERSION: bake them again). */
#define COLL_MESH_VERSION      5u
#define COLL_MESH_VERSION_MIN  3u
/** Triangles per block of COLL_MESHF_IDXBLK (one uint32 base each). */
#define COLL_MESH_TRI_BLOCK_SHIFT 6u
#define COLL_MESH_TRI_BLOCK       (1u << COLL_MESH_TRI_BLOCK_SHIFT)

enum {
    COLL_MESHF_QUANT = 1u << 0, /**< vertices are uint16 fixed point */
    COLL_MESHF_IDX16 = 1u << 1, /**< triangle vertex indices are uint16 (nverts <= 65535) */
    COLL_MESHF_REF16 = 1u << 2, /**< grid refs are uint16 (ntris <= 65535) */
    COLL_MESHF_HASH  = 1u << 3, /**< cells are nbuckets hash buckets, not the dense grid */
    COLL_MESHF_IDXBLK = 1u << 4, /**< uint16 vertex indices from a uint32 base per block of
                                      COLL_MESH_TRI_BLOCK triangles (version 4; not with IDX16) */
    COLL_MESHF_RCODE = 1u << 5, /**< a sub-cell code byte per ref (version 5; dense grid only) */
    COLL_MESHF_ALL   = 63u,
};

/** Header. All fields are 32-bit words (floats are IEEE-754 binary32). */
struct coll_mesh_s {
    uint32_t magic;       /**< COLL_MESH_MAGIC_BLOB on disk, _NATIVE in use */
    uint32_t version;     /**< COLL_MESH_VERSION */
    uint32_t flags;       /**< COLL_MESHF_* */
    uint32_t total_size;  /**< bytes of the whole block, header included */
    uint32_t checksum;    /**< see file comment */
    uint32_t nverts;
    uint32_t ntris;
    uint32_t nrefs;
    float bmin[3];        /**< local bounds of the stored triangles */
    float bmax[3];
    float grid_origin[3]; /**< corner of cell (0,0,0) */
    float cell_size;      /**< cubic cell edge, meters, > 0 */
    uint32_t dims[3];     /**< cells per axis, each >= 1 */
    float qorigin[3];     /**< quantization origin (COLL_MESHF_QUANT), else 0 */
    float qscale[3];      /**< quantization step per axis (COLL_MESHF_QUANT), else 0 */
    uint32_t off_verts;   /**< byte offsets from the start of the header */
    uint32_t off_tris;
    uint32_t off_cells;
    uint32_t off_refs;
    uint32_t nbuckets;    /**< COLL_MESHF_HASH: cell entries (power of two), else 0 */
    float grid_margin;    /**< every triangle is listed in each cell its bounds grown by this
                               reach (>= 0, < cell_size): the queries grow their boxes by it */
    uint32_t reserved;    /**< 0 (keeps the sections 8-byte aligned) */
};
_Static_assert(sizeof(struct coll_mesh_s) == 136, "on-disk mesh header is 136 bytes (version 3)");

/** Offsets of a layout, computed from the counts (64-bit so nothing overflows). */
typedef struct {
    uint64_t off_verts, off_tris, off_tbase, off_cells, off_refs, off_codes, total;
    uint64_t ntbase; /**< tri bases (COLL_MESHF_IDXBLK), else 0 (and off_tbase = off_cells) */
} coll_mesh_layout_t;

/** Tri-base blocks of ntris triangles. */
static inline uint64_t coll_mesh_tri_blocks(uint64_t ntris)
{
    return (ntris + COLL_MESH_TRI_BLOCK - 1u) >> COLL_MESH_TRI_BLOCK_SHIFT;
}

/** Canonical layout for these counts and flags. */
static inline coll_mesh_layout_t coll_mesh_layout_of(uint32_t flags, uint64_t nverts, uint64_t ntris,
                                                     uint64_t ncells, uint64_t nrefs)
{
    coll_mesh_layout_t l;
#define COLL_MESH_ALIGN8(x) (((x) + 7u) & ~(uint64_t)7u)
    l.off_verts = sizeof(struct coll_mesh_s);
    l.off_tris  = COLL_MESH_ALIGN8(l.off_verts + nverts * ((flags & COLL_MESHF_QUANT) ? 6u : 12u));
    l.off_tbase = COLL_MESH_ALIGN8(l.off_tris + ntris * ((flags & (COLL_MESHF_IDX16 | COLL_MESHF_IDXBLK)) ? 6u : 12u));
    l.ntbase    = (flags & COLL_MESHF_IDXBLK) ? coll_mesh_tri_blocks(ntris) : 0u;
    l.off_cells = COLL_MESH_ALIGN8(l.off_tbase + l.ntbase * 4u);
    l.off_refs  = COLL_MESH_ALIGN8(l.off_cells + (ncells + 1u) * 4u);
    l.off_codes = COLL_MESH_ALIGN8(l.off_refs + nrefs * ((flags & COLL_MESHF_REF16) ? 2u : 4u));
    l.total     = COLL_MESH_ALIGN8(l.off_codes + ((flags & COLL_MESHF_RCODE) ? nrefs : 0u));
#undef COLL_MESH_ALIGN8
    return l;
}

/**
 * Writes the big-endian, checksummed blob of a built (or loaded) mesh to out (any
 * alignment). *written = coll_mesh_size(m) on success; COLL_ERR_BUFFER_TOO_SMALL when
 * out_size is smaller (written still tells the size needed). This is what the bake tool
 * stores; coll_mesh_load() takes it back.
 */
coll_err_t coll_mesh_write_blob(const coll_mesh_t *m, void *out, size_t out_size, size_t *written);

/* ---- internal accessors for the scene queries (src/coll only) ---- */

/** Number of cell entries (the cells array holds one more). */
static inline uint64_t coll_mesh_cell_count(const coll_mesh_t *m)
{
    if (m->flags & COLL_MESHF_HASH) return m->nbuckets;
    return (uint64_t)m->dims[0] * m->dims[1] * m->dims[2];
}

/** Hash bucket of grid cell (x,y,z) in a hashed grid of nbuckets (a power of two). */
static inline uint32_t coll_mesh_hash_cell(uint32_t x, uint32_t y, uint32_t z, uint32_t nbuckets)
{
    return ((x * 73856093u) ^ (y * 19349663u) ^ (z * 83492791u)) & (nbuckets - 1u);
}

/** Cell entry of grid cell (x,y,z) (each coordinate < dims, unchecked). */
static inline uint32_t coll_mesh_cell_index(const coll_mesh_t *m, uint32_t x, uint32_t y, uint32_t z)
{
    if (m->flags & COLL_MESHF_HASH) return coll_mesh_hash_cell(x, y, z, m->nbuckets);
    return x + m->dims[0] * (y + m->dims[1] * z);
}

/**
 * Grid coordinate along one axis of local coordinate x (inv = 1 / cell size), clamped to
 * [0, dim). The builder registers and the queries look up through this one function.
 * Converted as (float)(int32_t): dims fit in an int32, and a uint32_t converts through
 * double-precision code on MIPS (cvt.d.w, add.d, cvt.s.d).
 */
static inline uint32_t coll_mesh_cell_coord(float x, float origin, float inv, uint32_t dim)
{
    float f = (x - origin) * inv;
    if (!(f > 0.0f)) return 0;
    if (f >= (float)(int32_t)dim) return dim - 1u;
    uint32_t c = (uint32_t)f;
    return c < dim ? c : dim - 1u;
}

/**
 * Sub-cell quarter (0..3) of local coordinate x along an axis in a cell whose low corner on
 * that axis is lo (grid_origin + c * cell_size, computed as (float)(int32_t)c * cell_size),
 * inv4 = 4 / cell_size; clamped. Monotone in x: a box's quarters cover the quarters of
 * every box inside it, so two boxes whose quarter ranges are disjoint are disjoint.
 */
static inline uint32_t coll_mesh_quarter(float x, float lo, float inv4)
{
    float f = (x - lo) * inv4;
    if (!(f > 0.0f)) return 0u;
    if (f >= 3.0f) return 3u;
    return (uint32_t)(int32_t)f;
}

/** The quarters a..b (a <= b) of one axis as bits a..b of a nibble. */
static inline uint32_t coll_mesh_quarter_bits(uint32_t a, uint32_t b) { return (2u << b) - (1u << a); }

/** A ref's code (COLL_MESHF_RCODE) or a query's: the X quarters of lo..hi in bits 0-3, the
 *  Z quarters in bits 4-7, in the cell whose low corner is c (see coll_mesh_quarter). */
static inline uint32_t coll_mesh_ref_code(float lox, float hix, float loz, float hiz, float cx, float cz, float inv4)
{
    return coll_mesh_quarter_bits(coll_mesh_quarter(lox, cx, inv4), coll_mesh_quarter(hix, cx, inv4)) |
           coll_mesh_quarter_bits(coll_mesh_quarter(loz, cz, inv4), coll_mesh_quarter(hiz, cz, inv4)) << 4;
}

/** The code bytes (COLL_MESHF_RCODE), or NULL. */
static inline const uint8_t *coll_mesh_codes(const coll_mesh_t *m)
{
    if (!(m->flags & COLL_MESHF_RCODE)) return NULL;
    coll_mesh_layout_t l = coll_mesh_layout_of(m->flags, 0u, 0u, 0u, m->nrefs);
    return (const uint8_t *)m + m->off_refs + (l.off_codes - l.off_refs);
}

/** Grid cell triangles: refs[begin..end). */
static inline uint32_t coll_mesh_ref(const coll_mesh_t *m, uint32_t k)
{
    const uint8_t *base = (const uint8_t *)m;
    if (m->flags & COLL_MESHF_REF16) return ((const uint16_t *)(const void *)(base + m->off_refs))[k];
    return ((const uint32_t *)(const void *)(base + m->off_refs))[k];
}

static inline const uint32_t *coll_mesh_cells(const coll_mesh_t *m)
{
    return (const uint32_t *)(const void *)((const uint8_t *)m + m->off_cells);
}

/** The block bases of a COLL_MESHF_IDXBLK mesh (they follow the indices). */
static inline const uint32_t *coll_mesh_tri_bases(const coll_mesh_t *m)
{
    coll_mesh_layout_t l = coll_mesh_layout_of(m->flags, m->nverts, m->ntris, 0u, 0u);
    return (const uint32_t *)(const void *)((const uint8_t *)m + l.off_tbase);
}

/** Local-space vertices of triangle i (i < ntris, unchecked). */
void coll_mesh_tri_local(const coll_mesh_t *m, uint32_t i, fm_vec3_t out[3]);

/**
 * Read-only view of a mesh's sections for the query loops: the section pointers and the
 * layout flags are resolved once per query instead of once per vertex, and the fetch is
 * inline (coll_mesh_tri_local() costs a call plus three calls and a flag test per vertex).
 * Gives exactly the same vertices as coll_mesh_tri_local().
 */
typedef struct {
    const uint8_t *verts, *tris, *refs;
    const uint32_t *cells;
    const uint32_t *tbase; /* COLL_MESHF_IDXBLK: the blocks' base vertex indices */
    uint32_t flags;
    float qo[3], qs[3];
} coll_mesh_view_t;

static inline void coll_mesh_view_init(coll_mesh_view_t *v, const coll_mesh_t *m)
{
    const uint8_t *b = (const uint8_t *)m;
    v->verts = b + m->off_verts;
    v->tris = b + m->off_tris;
    v->refs = b + m->off_refs;
    v->cells = (const uint32_t *)(const void *)(b + m->off_cells);
    v->tbase = (m->flags & COLL_MESHF_IDXBLK) ? coll_mesh_tri_bases(m) : NULL;
    v->flags = m->flags;
    for (int a = 0; a < 3; a++) { v->qo[a] = m->qorigin[a]; v->qs[a] = m->qscale[a]; }
}

static inline uint32_t coll_mesh_view_ref(const coll_mesh_view_t *v, uint32_t k)
{
    if (v->flags & COLL_MESHF_REF16) return ((const uint16_t *)(const void *)v->refs)[k];
    return ((const uint32_t *)(const void *)v->refs)[k];
}

static inline void coll_mesh_view_tri(const coll_mesh_view_t *v, uint32_t i, fm_vec3_t out[3])
{
    uint32_t ix[3];
    if (v->flags & COLL_MESHF_IDX16) {
        const uint16_t *t = (const uint16_t *)(const void *)v->tris + 3u * i;
        ix[0] = t[0]; ix[1] = t[1]; ix[2] = t[2];
    } else if (v->flags & COLL_MESHF_IDXBLK) {
        const uint16_t *t = (const uint16_t *)(const void *)v->tris + 3u * i;
        uint32_t b = v->tbase[i >> COLL_MESH_TRI_BLOCK_SHIFT];
        ix[0] = b + t[0]; ix[1] = b + t[1]; ix[2] = b + t[2];
    } else {
        const uint32_t *t = (const uint32_t *)(const void *)v->tris + 3u * i;
        ix[0] = t[0]; ix[1] = t[1]; ix[2] = t[2];
    }
    if (v->flags & COLL_MESHF_QUANT) {
        for (int k = 0; k < 3; k++) {
            const uint16_t *q = (const uint16_t *)(const void *)v->verts + 3u * ix[k];
            out[k].x = v->qo[0] + (float)q[0] * v->qs[0];
            out[k].y = v->qo[1] + (float)q[1] * v->qs[1];
            out[k].z = v->qo[2] + (float)q[2] * v->qs[2];
        }
    } else {
        for (int k = 0; k < 3; k++) {
            const float *f = (const float *)(const void *)v->verts + 3u * ix[k];
            out[k].x = f[0]; out[k].y = f[1]; out[k].z = f[2];
        }
    }
}

#endif
