/**
 * @file grid_walk.h
 * @brief The candidate triangles of a mesh instance under a query (private): instance
 *        transforms, the grid's cells under a box, the per-query dedup, and one walk that
 *        every query (ray, sweep, overlaps) and the step gather take their candidates from.
 *
 * Precision: every candidate triangle is moved into world orientation RELATIVE TO THE
 * QUERY ORIGIN before it is tested: w = M * (v - o_local), where M = R * S and o_local is
 * the query origin in mesh-local space. Near the query the differences are small and
 * exact-ish, so levels kilometres from the world origin keep sub-millimetre accuracy, and
 * non-uniform scale stays exact (no approximation of the scaled capsule).
 * The grid is walked in mesh-local space; the game may change any transform every frame,
 * so everything derived from it is recomputed per query.
 *
 * Everything here is static inline: the walk runs once per visited cell entry, so it must
 * inline into its callers (query.c, gather.c).
 */
#ifndef COLL_GRID_WALK_H
#define COLL_GRID_WALK_H

#include "vec3.h"
#include "coll/scene.h"
#include "mesh_format.h"
#include "coll_libm.h"
#include <string.h>

/* Plain comparisons (libm's fminf/fmaxf are not on the console's libc allow-list). */

/* Code that runs once per visited cell entry or per survivor: inlined even where the
 * compiler's size heuristics would not (the console build outlined tri_rel_of otherwise). */
#if defined(__GNUC__)
#define CAND_INLINE static inline __attribute__((always_inline))
#else
#define CAND_INLINE static inline
#endif


typedef struct {
    float m[3][3];   /* world_rel = m * local_delta (m[row][col]) */
    float inv[3][3]; /* inverse of m */
    bool simple;     /* identity rotation and unit scale */
} xf3_t;

/* isfinite on the bit pattern (the exponent not all ones): on the console isfinite is a
 * move to the FPU, an unordered compare and a branch with two hazard slots per value; every
 * query checks a dozen of its arguments this way. */
static inline uint32_t f_inf_bits(float x)
{
    union { float f; uint32_t u; } b = { x }; /* a union: the console build has no memcpy inline */
    return (uint32_t)((b.u & 0x7f800000u) == 0x7f800000u);
}
static inline bool f_isfin(float x) { return f_inf_bits(x) == 0u; }
static inline bool vfin(const fm_vec3_t *v) { return (f_inf_bits(v->x) | f_inf_bits(v->y) | f_inf_bits(v->z)) == 0u; }

CAND_INLINE bool xf_prepare(const coll_transform_t *xf, xf3_t *o)
{
    const fm_quat_t *q = &xf->rot;
    const fm_vec3_t *s = &xf->scale;
    /* The common instance first (no rotation, unit scale: the tests below on fewer values,
     * with the same outcome): its rotation is valid when w is finite and not ~0. */
    if (q->x == 0.0f && q->y == 0.0f && q->z == 0.0f && s->x == 1.0f && s->y == 1.0f && s->z == 1.0f) {
        o->simple = true;
        return vfin(&xf->pos) && f_isfin(q->w) && q->w * q->w > 1e-12f;
    }
    if (!vfin(&xf->pos) || !vfin(s) || (f_inf_bits(q->x) | f_inf_bits(q->y) | f_inf_bits(q->z) | f_inf_bits(q->w)))
        return false;
    if (s->x == 0.0f || s->y == 0.0f || s->z == 0.0f) return false;
    float n2 = q->x * q->x + q->y * q->y + q->z * q->z + q->w * q->w;
    if (!(n2 > 1e-12f)) return false;
    o->simple = q->x == 0.0f && q->y == 0.0f && q->z == 0.0f && s->x == 1.0f && s->y == 1.0f &&
                s->z == 1.0f;
    if (o->simple) return true; /* m and inv are never read for a simple transform */
    float k = 1.0f / sqrtf(n2);
    float x = q->x * k, y = q->y * k, z = q->z * k, w = q->w * k;
    float r[3][3] = {
        { 1.0f - 2.0f * (y * y + z * z), 2.0f * (x * y - z * w), 2.0f * (x * z + y * w) },
        { 2.0f * (x * y + z * w), 1.0f - 2.0f * (x * x + z * z), 2.0f * (y * z - x * w) },
        { 2.0f * (x * z - y * w), 2.0f * (y * z + x * w), 1.0f - 2.0f * (x * x + y * y) },
    };
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            o->m[i][j] = r[i][j] * s->v[j];
            o->inv[i][j] = r[j][i] / s->v[i];
        }
    return true;
}

static inline fm_vec3_t mul3(const float m[3][3], const fm_vec3_t *v)
{
    fm_vec3_t o;
    for (int i = 0; i < 3; i++) o.v[i] = m[i][0] * v->x + m[i][1] * v->y + m[i][2] * v->z;
    return o;
}

static inline fm_vec3_t mul3_abs(const float m[3][3], const fm_vec3_t *v)
{
    fm_vec3_t o;
    for (int i = 0; i < 3; i++)
        o.v[i] = fabsf(m[i][0]) * v->x + fabsf(m[i][1]) * v->y + fabsf(m[i][2]) * v->z;
    return o;
}

/* Query origin in mesh-local space. Rotated/scaled instances go through a pivot at the
 * centre of the mesh bounds: o_local = c + M^-1 (p - (pos + M c)), so a query near the
 * mesh only pushes a short vector through M^-1 and meshes whose local coordinates are
 * far from their own origin do not lose the condition number of M in precision. */
CAND_INLINE fm_vec3_t to_local_point(const xf3_t *x, const coll_transform_t *xf, const coll_mesh_t *m,
                                const fm_vec3_t *p)
{
    fm_vec3_t d;
    fm_vec3_sub(&d, p, &xf->pos);
    if (x->simple) return d;
    fm_vec3_t c, mc, l;
    for (int a = 0; a < 3; a++) c.v[a] = 0.5f * (m->bmin[a] + m->bmax[a]);
    mc = mul3(x->m, &c);
    fm_vec3_sub(&d, &d, &mc);
    l = mul3(x->inv, &d);
    fm_vec3_add(&l, &l, &c);
    return l;
}

static inline fm_vec3_t to_local_dir(const xf3_t *x, const fm_vec3_t *d)
{
    return x->simple ? *d : mul3(x->inv, d);
}

/* Triangle i of the instance in world orientation, as its first vertex relative to the
 * query origin (*w0) plus a shape whose first vertex is the origin. The edges are
 * transformed from exact local differences, so the triangle's shape (and normal) stays
 * exact even when it is far from the query; only its placement carries rounding. */
CAND_INLINE void tri_rel_of(const fm_vec3_t v[3], const xf3_t *x, const fm_vec3_t *o_local, fm_vec3_t *w0,
                            fm_vec3_t out[3])
{
    fm_vec3_t d;
    fm_vec3_sub(&d, &v[0], o_local);
    *w0 = x->simple ? d : mul3(x->m, &d);
    out[0].x = out[0].y = out[0].z = 0.0f;
    for (int k = 1; k < 3; k++) {
        fm_vec3_sub(&d, &v[k], &v[0]);
        out[k] = x->simple ? d : mul3(x->m, &d);
    }
}

/* Query-relative copy of a triangle given as w0 + shape. */
static inline void tri_abs(const fm_vec3_t *w0, const fm_vec3_t shape[3], fm_vec3_t out[3])
{
    for (int k = 0; k < 3; k++) fm_vec3_add(&out[k], w0, &shape[k]);
}



/* Per-instance set of triangles already tested by this query: open addressing over a
 * fixed table. When it fills up, further triangles are simply tested again (harmless,
 * exact) and the query counts one in the scene's stats (dedup_overflows). */
#define SEEN_BITS 9
#define SEEN_SLOTS (1u << SEEN_BITS)
#define SEEN_MAX 384u

/* The table starts with its first SEEN_BITS0 bits only (most queries meet a few dozen
 * triangles; clearing all 2 KB per query was ~10% of a walking step) and grows to the
 * full table when it is half full (linear probing stays short). */
#define SEEN_BITS0 7

typedef struct {
    uint32_t slot[SEEN_SLOTS]; /* tri + 1, 0 = empty; only the first 1 << bits are in use */
    uint16_t used[SEEN_MAX];
    uint32_t n;
    uint32_t bits;
    uint32_t limit; /* n at which seen_check leaves its common path: the table grows at half
                     * full while it is small, and a full table overflows */
    bool overflow;
    bool ready; /* the table is cleared only when a query first needs it */
} seen_t;

static inline void seen_init(seen_t *s)
{
    s->n = 0;
    s->overflow = false;
    s->ready = false;
}

static inline void seen_ready(seen_t *s)
{
    if (s->ready) return;
    for (uint32_t i = 0; i < (1u << SEEN_BITS0); i++) s->slot[i] = 0u;
    s->bits = SEEN_BITS0;
    s->limit = (1u << SEEN_BITS0) / 2u < SEEN_MAX ? (1u << SEEN_BITS0) / 2u : SEEN_MAX;
    s->ready = true;
}

static inline uint32_t seen_probe(const seen_t *s, uint32_t key)
{
    uint32_t mask = (1u << s->bits) - 1u;
    uint32_t h = (key * 2654435761u) >> (32 - s->bits);
    while (s->slot[h] != 0u && s->slot[h] != key) h = (h + 1u) & mask;
    return h;
}

/* Moves the table to its full size (the n keys are re-inserted). */
static inline void seen_grow(seen_t *s)
{
    uint32_t keys[(1u << SEEN_BITS0) / 2u + 1u];
    uint32_t old = 1u << s->bits;
    for (uint32_t i = 0; i < s->n; i++) keys[i] = s->slot[s->used[i]];
    memset(s->slot, 0, sizeof(uint32_t) * old);
    memset(s->slot + old, 0, sizeof(uint32_t) * (SEEN_SLOTS - old));
    s->bits = SEEN_BITS;
    s->limit = SEEN_MAX;
    for (uint32_t i = 0; i < s->n; i++) {
        uint32_t h = seen_probe(s, keys[i]);
        s->slot[h] = keys[i];
        s->used[i] = (uint16_t)h;
    }
}

static inline void seen_clear(seen_t *s)
{
    if (!s->ready) return;
    for (uint32_t i = 0; i < s->n; i++) s->slot[s->used[i]] = 0;
    s->n = 0;
}

enum { SEEN_BEFORE = 0, SEEN_NEW = 1, SEEN_UNKNOWN = 2 };

/* SEEN_NEW when tri has not been seen yet (so it must be tested), SEEN_UNKNOWN when the
 * table is full and tri is not in it (test it; it may be a repeat). */
static inline int seen_check(seen_t *s, uint32_t tri)
{
    uint32_t key = tri + 1u;
    uint32_t h = seen_probe(s, key);
    if (s->slot[h] == key) return SEEN_BEFORE;
    if (s->n >= s->limit) { /* one compare on the common path (the two tests below) */
        if (s->n >= SEEN_MAX) {
            s->overflow = true;
            return SEEN_UNKNOWN;
        }
        if (s->bits < SEEN_BITS && s->n + 1u > (1u << s->bits) / 2u) {
            seen_grow(s);
            h = seen_probe(s, key);
        }
    }
    s->slot[h] = key;
    s->used[s->n++] = (uint16_t)h;
    return SEEN_NEW;
}

static inline bool seen_first(seen_t *s, uint32_t tri) { return seen_check(s, tri) != SEEN_BEFORE; }

/* Exact fallback for the overlap list when the table is full: tri is new in cell
 * (cx,cy,cz) unless a cell visited earlier in the same box walk lists it (cells keep
 * their triangles in ascending order: binary search). */
static inline bool in_cell(const coll_mesh_t *m, uint32_t ci, uint32_t tri)
{
    const uint32_t *cells = coll_mesh_cells(m);
    uint32_t lo = cells[ci], hi = cells[ci + 1u];
    while (lo < hi) {
        uint32_t mid = lo + (hi - lo) / 2u, v = coll_mesh_ref(m, mid);
        if (v == tri) return true;
        if (v < tri) lo = mid + 1u; else hi = mid;
    }
    return false;
}

static inline bool listed_earlier(const coll_mesh_t *m, bool walk_all, const uint32_t clo[3], const uint32_t chi[3],
                           uint32_t cx, uint32_t cy, uint32_t cz, uint32_t tri)
{
    if (walk_all) { /* entries 0..cx-1 were walked before entry cx */
        for (uint32_t e = 0; e < cx; e++)
            if (in_cell(m, e, tri)) return true;
        return false;
    }
    for (uint32_t z = clo[2]; z <= cz; z++)
        for (uint32_t y = clo[1]; y <= chi[1]; y++)
            for (uint32_t x = clo[0]; x <= chi[0]; x++) {
                if (z == cz && (y > cy || (y == cy && x >= cx))) return false;
                if (in_cell(m, coll_mesh_cell_index(m, x, y, z), tri)) return true;
            }
    return false;
}

/* Counters of the scene's attached stats record (the scene is const to the queries; the
 * record it points to is the caller's, not part of the scene). */
#define STATS_ADD(scene, field) do { if ((scene)->stats) (scene)->stats->field++; } while (0)

static inline void note_overflow(const coll_scene_t *scene, seen_t *s)
{
    if (s->overflow) {
        STATS_ADD(scene, dedup_overflows);
        s->overflow = false;
    }
}

static inline bool tri_box_reject(const fm_vec3_t tri[3], const fm_vec3_t *lo, const fm_vec3_t *hi)
{
    for (int a = 0; a < 3; a++) {
        if (tri[0].v[a] < lo->v[a] && tri[1].v[a] < lo->v[a] && tri[2].v[a] < lo->v[a]) return true;
        if (tri[0].v[a] > hi->v[a] && tri[1].v[a] > hi->v[a] && tri[2].v[a] > hi->v[a]) return true;
    }
    return false;
}

/* Conservative mesh-local box of a world-relative box (plus the grid margin). */
CAND_INLINE void local_box(const coll_mesh_t *m, const xf3_t *x, const fm_vec3_t *o_l, const fm_vec3_t *lo,
                      const fm_vec3_t *hi, fm_vec3_t *llo, fm_vec3_t *lhi)
{
    fm_vec3_t c, h;
    for (int a = 0; a < 3; a++) {
        c.v[a] = 0.5f * (lo->v[a] + hi->v[a]);
        h.v[a] = 0.5f * (hi->v[a] - lo->v[a]);
    }
    fm_vec3_t cl = x->simple ? c : mul3(x->inv, &c);
    fm_vec3_t hl = x->simple ? h : mul3_abs(x->inv, &h);
    float mg = m->grid_margin; /* the builder's registration margin (format version 3) */
    for (int a = 0; a < 3; a++) {
        llo->v[a] = o_l->v[a] + cl.v[a] - hl.v[a] - mg;
        lhi->v[a] = o_l->v[a] + cl.v[a] + hl.v[a] + mg;
    }
}

/* Cell range of a mesh-local box in an instance's grid; false when it misses the mesh. */
static inline bool instance_cells(const coll_mesh_t *m, const fm_vec3_t *llo, const fm_vec3_t *lhi, uint32_t clo[3],
                           uint32_t chi[3])
{
    float inv_cs = 1.0f / m->cell_size;
    for (int a = 0; a < 3; a++) {
        if (lhi->v[a] < m->bmin[a] || llo->v[a] > m->bmax[a]) return false;
        clo[a] = coll_mesh_cell_coord(llo->v[a], m->grid_origin[a], inv_cs, m->dims[a]);
        chi[a] = coll_mesh_cell_coord(lhi->v[a], m->grid_origin[a], inv_cs, m->dims[a]);
    }
    return true;
}

/* Hashed grid and a box of more cells than the grid has entries (a long sweep over fine
 * cells): walk the entries once each instead (every triangle is still a candidate, so
 * the result is the same); the loops then run cx over the entries with cy = cz = 0. */
static inline bool walk_entries(const coll_mesh_t *m, uint32_t clo[3], uint32_t chi[3])
{
    if (!(m->flags & COLL_MESHF_HASH)) return false;
    uint64_t n = (uint64_t)(chi[0] - clo[0] + 1u) * (chi[1] - clo[1] + 1u) * (chi[2] - clo[2] + 1u);
    if (n <= m->nbuckets) return false;
    clo[0] = clo[1] = clo[2] = 0u;
    chi[0] = m->nbuckets - 1u;
    chi[1] = chi[2] = 0u;
    return true;
}

/* Cell (cx,cy,cz) (clamped edge cells extend to infinity) misses the local box. */
static inline bool cell_misses(const coll_mesh_t *m, uint32_t cx, uint32_t cy, uint32_t cz, const fm_vec3_t *llo,
                        const fm_vec3_t *lhi)
{
    const uint32_t c[3] = { cx, cy, cz };
    for (int a = 0; a < 3; a++) {
        float lo = m->grid_origin[a] + (float)(int32_t)c[a] * m->cell_size;
        float hi = lo + m->cell_size;
        if (c[a] > 0u && lhi->v[a] < lo) return true;
        if (c[a] + 1u < m->dims[a] && llo->v[a] > hi) return true;
    }
    return false;
}

/* Candidate t of a grid walk: its local vertices into v, or false when their box misses
 * llo..lhi (exactly tri_box_reject's test). Every visited cell entry pays this, so the
 * common layout (float vertices) reads the coordinates in place, one axis at a time,
 * across axes first (the up axis rejects least on floors), and copies only survivors. */
/* The layout flags a walk's loops depend on (vertices, indices and refs: the dense or
 * hashed grid does not matter inside a cell). The _lay variants below take them as an
 * argument: a caller that passes a constant (grid_walk_layout() dispatched to a few
 * constant cases) gets a loop with the layout folded in, instead of two to three flag
 * tests per visited entry. */
#define GRID_LAYOUT_BITS (COLL_MESHF_QUANT | COLL_MESHF_IDX16 | COLL_MESHF_IDXBLK | COLL_MESHF_REF16)

/* Vertex indices of triangle t (coll_mesh_view_tri's, with the layout given). */
CAND_INLINE void view_idx_lay(const coll_mesh_view_t *mv, uint32_t lay, uint32_t t, uint32_t ix[3])
{
    if (lay & (COLL_MESHF_IDX16 | COLL_MESHF_IDXBLK)) {
        const uint16_t *ti = (const uint16_t *)(const void *)mv->tris + 3u * t;
        uint32_t b = (lay & COLL_MESHF_IDXBLK) ? mv->tbase[t >> COLL_MESH_TRI_BLOCK_SHIFT] : 0u;
        ix[0] = b + ti[0]; ix[1] = b + ti[1]; ix[2] = b + ti[2];
    } else {
        const uint32_t *ti = (const uint32_t *)(const void *)mv->tris + 3u * t;
        ix[0] = ti[0]; ix[1] = ti[1]; ix[2] = ti[2];
    }
}

/* (yfirst: the float test's axes in the order Y, X, Z, for a walk whose entries passed the
 * sub-cell codes' X and Z test already: what is left for the box test to reject is mostly
 * off along Y. The same answer in either order.) */
CAND_INLINE bool cand_tri_lay_o(const coll_mesh_view_t *mv, uint32_t lay, uint32_t t, const fm_vec3_t *llo,
                                const fm_vec3_t *lhi, fm_vec3_t v[3], const bool yfirst)
{
    if (lay & COLL_MESHF_QUANT) {
        uint32_t ix[3];
        view_idx_lay(mv, lay, t, ix);
        for (int k = 0; k < 3; k++) { /* exactly coll_mesh_view_tri()'s dequantization */
            const uint16_t *q = (const uint16_t *)(const void *)mv->verts + 3u * ix[k];
            v[k].x = mv->qo[0] + (float)q[0] * mv->qs[0];
            v[k].y = mv->qo[1] + (float)q[1] * mv->qs[1];
            v[k].z = mv->qo[2] + (float)q[2] * mv->qs[2];
        }
        return !tri_box_reject(v, llo, lhi);
    }
    uint32_t ix[3];
    view_idx_lay(mv, lay, t, ix);
    const uint32_t i0 = ix[0], i1 = ix[1], i2 = ix[2];
    const float *vs = (const float *)(const void *)mv->verts;
    const float *a = vs + 3u * i0, *b = vs + 3u * i1, *c = vs + 3u * i2;
    float lo, hi;
    if (yfirst) {
        lo = llo->y; hi = lhi->y;
        if ((a[1] < lo && b[1] < lo && c[1] < lo) || (a[1] > hi && b[1] > hi && c[1] > hi)) return false;
    }
    lo = llo->x; hi = lhi->x;
    if ((a[0] < lo && b[0] < lo && c[0] < lo) || (a[0] > hi && b[0] > hi && c[0] > hi)) return false;
    lo = llo->z; hi = lhi->z;
    if ((a[2] < lo && b[2] < lo && c[2] < lo) || (a[2] > hi && b[2] > hi && c[2] > hi)) return false;
    if (!yfirst) {
        lo = llo->y; hi = lhi->y;
        if ((a[1] < lo && b[1] < lo && c[1] < lo) || (a[1] > hi && b[1] > hi && c[1] > hi)) return false;
    }
    v[0].x = a[0]; v[0].y = a[1]; v[0].z = a[2];
    v[1].x = b[0]; v[1].y = b[1]; v[1].z = b[2];
    v[2].x = c[0]; v[2].y = c[1]; v[2].z = c[2];
    return true;
}

CAND_INLINE bool cand_tri_lay(const coll_mesh_view_t *mv, uint32_t lay, uint32_t t, const fm_vec3_t *llo,
                              const fm_vec3_t *lhi, fm_vec3_t v[3])
{
    return cand_tri_lay_o(mv, lay, t, llo, lhi, v, false);
}

CAND_INLINE bool cand_tri(const coll_mesh_view_t *mv, uint32_t t, const fm_vec3_t *llo, const fm_vec3_t *lhi,
                          fm_vec3_t v[3])
{
    return cand_tri_lay(mv, mv->flags, t, llo, lhi, v);
}

/* Ref k of a cell list (coll_mesh_view_ref with the layout given). */
CAND_INLINE uint32_t view_ref_lay(const coll_mesh_view_t *mv, uint32_t lay, uint32_t k)
{
    if (lay & COLL_MESHF_REF16) return ((const uint16_t *)(const void *)mv->refs)[k];
    return ((const uint32_t *)(const void *)mv->refs)[k];
}


/* ------------------------------------------------------------------ the walk ------- */

/* One walk over an instance's grid: the triangles listed in the cells it enters whose box
 * meets the walk's mesh-local box llo..lhi (the caller's; it may shrink during the walk,
 * never grow), each given once. Two ways to enter cells: every cell under the box in
 * order (grid_walk_box, grid_walk_next_cell), or cells chosen by the caller (a ray's 3D
 * DDA: grid_walk_cells, grid_walk_enter).
 *
 * The box test comes before the dedup (a triangle the box rejects is rejected on every
 * visit), so only survivors enter the dedup table. One cell of a plain grid lists a
 * triangle once, so a walk that turns out to enter one cell never touches the table. */
typedef struct {
    const coll_mesh_t *m;
    coll_mesh_view_t mv;
    const fm_vec3_t *llo, *lhi;
    seen_t *seen;
    uint32_t clo[3], chi[3], c[3];
    uint32_t k, kend;      /* the current cell entry's refs */
    uint32_t first;        /* lazy dedup: the first cell entry entered */
    uint32_t entered;      /* lazy dedup: cell entries entered so far (counts to 2) */
    bool walk_all;         /* hashed grid, more cells than entries: every entry once */
    bool dedup;
    bool lazy;             /* dedup starts with the second cell entry (grid_walk_cells) */
    bool skip_missed;      /* skip cells the (shrunk) box misses */
    bool started;
} grid_walk_t;

static inline void grid_walk_init(grid_walk_t *w, const coll_mesh_t *m, const fm_vec3_t *llo, const fm_vec3_t *lhi,
                                  seen_t *seen)
{
    w->m = m;
    coll_mesh_view_init(&w->mv, m);
    w->llo = llo;
    w->lhi = lhi;
    w->seen = seen;
    w->k = w->kend = 0u;
    w->entered = 0u;
    w->walk_all = false;
    w->skip_missed = false;
    w->started = false;
}

/* A walk over every cell under the box; false when the box misses the mesh. */
CAND_INLINE bool grid_walk_box(grid_walk_t *w, const coll_mesh_t *m, const fm_vec3_t *llo, const fm_vec3_t *lhi,
                                 seen_t *seen)
{
    grid_walk_init(w, m, llo, lhi, seen);
    if (!instance_cells(m, llo, lhi, w->clo, w->chi)) return false;
    w->walk_all = walk_entries(m, w->clo, w->chi);
    /* a hashed entry may list a triangle twice (see the builder): always dedup there */
    w->dedup = w->walk_all || (m->flags & COLL_MESHF_HASH) || w->clo[0] != w->chi[0] || w->clo[1] != w->chi[1] ||
               w->clo[2] != w->chi[2];
    w->lazy = false;
    if (w->dedup) seen_ready(seen);
    return true;
}

/* A walk over cells the caller enters (grid_walk_enter), deduplicating from the second. */
static inline void grid_walk_cells(grid_walk_t *w, const coll_mesh_t *m, const fm_vec3_t *llo, const fm_vec3_t *lhi,
                                   seen_t *seen)
{
    grid_walk_init(w, m, llo, lhi, seen);
    w->dedup = false;
    w->lazy = true;
}

/* Enters cell (x, y, z) (or entry x of a walk over every entry). A lazy walk entering its
 * second entry starts the table with the first entry's triangles that meet the box now
 * (those that did not are rejected again wherever they come back). */
static inline void grid_walk_enter_lazy(grid_walk_t *w, uint32_t ci)
{
    if (w->entered == 0u) {
        w->first = ci;
        w->entered = 1u;
    } else if (w->entered == 1u) {
        seen_ready(w->seen);
        for (uint32_t k = w->mv.cells[w->first]; k < w->mv.cells[w->first + 1u]; k++) {
            uint32_t t = coll_mesh_view_ref(&w->mv, k);
            fm_vec3_t v[3];
            if (cand_tri(&w->mv, t, w->llo, w->lhi, v)) (void)seen_check(w->seen, t);
        }
        w->entered = 2u;
        w->dedup = true;
    }
}

/* (the cell's refs inline: every visited cell pays this; the lazy dedup's start is rare) */
CAND_INLINE void grid_walk_enter(grid_walk_t *w, uint32_t x, uint32_t y, uint32_t z)
{
    w->c[0] = x; w->c[1] = y; w->c[2] = z;
    uint32_t ci = w->walk_all ? x : coll_mesh_cell_index(w->m, x, y, z);
    w->k = w->mv.cells[ci];
    w->kend = w->mv.cells[ci + 1u];
    if (w->lazy) grid_walk_enter_lazy(w, ci);
}

/* Next cell under the box (x fastest); false at the end. */
static inline bool grid_walk_next_cell(grid_walk_t *w)
{
    for (;;) {
        uint32_t x, y, z;
        if (!w->started) {
            w->started = true;
            x = w->clo[0]; y = w->clo[1]; z = w->clo[2];
        } else {
            x = w->c[0] + 1u; y = w->c[1]; z = w->c[2];
            if (x > w->chi[0]) {
                x = w->clo[0];
                if (++y > w->chi[1]) {
                    y = w->clo[1];
                    if (++z > w->chi[2]) return false;
                }
            }
        }
        w->c[0] = x; w->c[1] = y; w->c[2] = z;
        if (w->skip_missed && !w->walk_all && cell_misses(w->m, x, y, z, w->llo, w->lhi)) continue;
        grid_walk_enter(w, x, y, z);
        /* an empty cell (a dense grid's above and below a floor) has nothing to walk: the
         * next (a box walk's: never lazy, whose count of cells entered sees empty ones) */
        if (w->k == w->kend) continue;
        return true;
    }
}

/* Ref k of the current cell entry: true, with its triangle index and local vertices, when
 * its box meets the walk's box and the walk has not given it before. A full table: a
 * box walk looks the triangle up in the cells visited earlier (exact); a lazy walk (a ray)
 * gives it again (harmless, its test repeats). */
CAND_INLINE bool grid_walk_take_box(grid_walk_t *w, uint32_t lay, uint32_t k, uint32_t *t, fm_vec3_t v[3],
                                    const fm_vec3_t *llo, const fm_vec3_t *lhi);

CAND_INLINE bool grid_walk_take_lay(grid_walk_t *w, uint32_t lay, uint32_t k, uint32_t *t, fm_vec3_t v[3])
{
    return grid_walk_take_box(w, lay, k, t, v, w->llo, w->lhi);
}

/* grid_walk_take_lay with the walk's box given (llo..lhi: *w->llo..*w->lhi, or a copy of it
 * the caller keeps in locals, so that the per-entry test does not reload it through the
 * walk's pointers after every store the compiler cannot tell apart from them). */
CAND_INLINE bool grid_walk_take_box_o(grid_walk_t *w, uint32_t lay, uint32_t k, uint32_t *t, fm_vec3_t v[3],
                                      const fm_vec3_t *llo, const fm_vec3_t *lhi, const bool yfirst)
{
    *t = view_ref_lay(&w->mv, lay, k);
    if (!cand_tri_lay_o(&w->mv, lay, *t, llo, lhi, v, yfirst)) return false;
    if (!w->dedup) return true;
    int sc = seen_check(w->seen, *t);
    if (sc == SEEN_BEFORE) return false;
    if (sc == SEEN_UNKNOWN && !w->lazy) {
        /* copies: the walk's own address never escapes, so it stays in registers */
        const uint32_t clo[3] = { w->clo[0], w->clo[1], w->clo[2] }, chi[3] = { w->chi[0], w->chi[1], w->chi[2] };
        if (listed_earlier(w->m, w->walk_all, clo, chi, w->c[0], w->c[1], w->c[2], *t)) return false;
    }
    return true;
}

CAND_INLINE bool grid_walk_take_box(grid_walk_t *w, uint32_t lay, uint32_t k, uint32_t *t, fm_vec3_t v[3],
                                    const fm_vec3_t *llo, const fm_vec3_t *lhi)
{
    return grid_walk_take_box_o(w, lay, k, t, v, llo, lhi, false);
}

CAND_INLINE bool grid_walk_take(grid_walk_t *w, uint32_t k, uint32_t *t, fm_vec3_t v[3])
{
    return grid_walk_take_lay(w, w->mv.flags, k, t, v);
}

/* The walk's layout flags (GRID_LAYOUT_BITS), for a dispatch to constant cases. */
static inline uint32_t grid_walk_layout(const grid_walk_t *w) { return w->mv.flags & GRID_LAYOUT_BITS; }

/* grid_walk_take for a box query: the triangle relative to the query origin (w0 + shape,
 * as the per-triangle tests take it) and in absolute form (tri), false when it is not
 * taken or lies wholly outside the world-relative box lo..hi. */
CAND_INLINE bool grid_walk_take_in_box(grid_walk_t *w, uint32_t k, const xf3_t *x, const fm_vec3_t *o_l,
                                       const fm_vec3_t *lo, const fm_vec3_t *hi, uint32_t *t, fm_vec3_t *w0,
                                       fm_vec3_t shape[3], fm_vec3_t tri[3])
{
    fm_vec3_t v[3];
    if (!grid_walk_take_lay(w, w->mv.flags, k, t, v)) return false;
    tri_rel_of(v, x, o_l, w0, shape);
    tri_abs(w0, shape, tri);
    return !tri_box_reject(tri, lo, hi);
}

/* Ends the walk: the table is cleared for the next instance; an overflow is counted. */
static inline void grid_walk_end(grid_walk_t *w, const coll_scene_t *scene)
{
    seen_clear(w->seen);
    note_overflow(scene, w->seen);
}

#endif
