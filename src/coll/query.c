/**
 * @file query.c
 * @brief Scene queries: raycast (3D DDA through each instance's grid), capsule sweep and
 *        capsule overlaps (grid cells under the swept box), all exact and allocation-free.
 *
 * Precision: every candidate triangle is moved into world orientation RELATIVE TO THE
 * QUERY ORIGIN before it is tested: w = M * (v - o_local), where M = R * S and o_local is
 * the query origin in mesh-local space. Near the query the differences are small and
 * exact-ish, so levels kilometres from the world origin keep sub-millimetre accuracy, and
 * non-uniform scale stays exact (no approximation of the scaled capsule).
 * The grid is walked in mesh-local space; the game may change any transform every frame,
 * so everything derived from it is recomputed per query.
 */
#include "coll/scene.h"
#include "gather.h"
#include "mesh_format.h"
#include "prim.h"
#include <math.h>
#include <string.h>

/* Plain comparisons (libm's fminf/fmaxf are not on the console's libc allow-list). */
static inline float min_f(float a, float b) { return a < b ? a : b; }
static inline float max_f(float a, float b) { return a > b ? a : b; }

/* ------------------------------------------------------------------ transforms ----- */

typedef struct {
    float m[3][3];   /* world_rel = m * local_delta (m[row][col]) */
    float inv[3][3]; /* inverse of m */
    bool simple;     /* identity rotation and unit scale */
} xf3_t;

static bool vfin(const fm_vec3_t *v) { return isfinite(v->x) && isfinite(v->y) && isfinite(v->z); }

static bool xf_prepare(const coll_transform_t *xf, xf3_t *o)
{
    const fm_quat_t *q = &xf->rot;
    const fm_vec3_t *s = &xf->scale;
    if (!vfin(&xf->pos) || !vfin(s) || !isfinite(q->x) || !isfinite(q->y) || !isfinite(q->z) ||
        !isfinite(q->w))
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

static fm_vec3_t mul3(const float m[3][3], const fm_vec3_t *v)
{
    fm_vec3_t o;
    for (int i = 0; i < 3; i++) o.v[i] = m[i][0] * v->x + m[i][1] * v->y + m[i][2] * v->z;
    return o;
}

static fm_vec3_t mul3_abs(const float m[3][3], const fm_vec3_t *v)
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
static fm_vec3_t to_local_point(const xf3_t *x, const coll_transform_t *xf, const coll_mesh_t *m,
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

static fm_vec3_t to_local_dir(const xf3_t *x, const fm_vec3_t *d)
{
    return x->simple ? *d : mul3(x->inv, d);
}

/* Triangle i of the instance in world orientation, as its first vertex relative to the
 * query origin (*w0) plus a shape whose first vertex is the origin. The edges are
 * transformed from exact local differences, so the triangle's shape (and normal) stays
 * exact even when it is far from the query; only its placement carries rounding. */
static void tri_rel_of(const fm_vec3_t v[3], const xf3_t *x, const fm_vec3_t *o_local, fm_vec3_t *w0,
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
static void tri_abs(const fm_vec3_t *w0, const fm_vec3_t shape[3], fm_vec3_t out[3])
{
    for (int k = 0; k < 3; k++) fm_vec3_add(&out[k], w0, &shape[k]);
}

/* ---------------------------------------------------------------- one-way ------- */

/* A one-way instance's up (local +Y in world orientation); zero for an ordinary instance,
 * which every test below then lets through. */
static fm_vec3_t one_way_up(const coll_mesh_instance_t *inst)
{
    fm_vec3_t u = {{0.0f, 0.0f, 0.0f}};
    if (!(inst->flags & COLL_INSTANCE_ONE_WAY)) return u;
    fm_vec3_t y = {{0.0f, 1.0f, 0.0f}};
    fm_quat_t q = inst->xf.rot;
    fm_quat_norm(&q, &q);
    fm_quat_rotate_vec3(&u, &q, &y);
    return u;
}

/* Unit normal of a query-relative triangle shape (first vertex at the origin) facing along
 * the one-way up u, or false when the face does not look up along u (a side or underside of
 * a one-way platform: it never collides). */
static bool one_way_normal(const fm_vec3_t *u, const fm_vec3_t shape[3], fm_vec3_t *n)
{
    fm_vec3_cross(n, &shape[1], &shape[2]);
    float l = fm_vec3_len(n);
    if (!(l > 0.0f)) return false;
    fm_vec3_scale(n, n, (fm_vec3_dot(n, u) < 0.0f ? -1.0f : 1.0f) / l);
    return fm_vec3_dot(n, u) > 0.1f;
}

/* One-way test for a capsule (axis ends seg, relative to the triangle's first vertex):
 * true when the triangle collides with it, i.e. the instance is ordinary, or the face looks
 * up and both axis ends lie in front of its plane, no more than 5 % of r short of touching. */
static bool one_way_capsule(const fm_vec3_t *u, const fm_vec3_t shape[3], const fm_vec3_t seg[2], float r)
{
    if (u->x == 0.0f && u->y == 0.0f && u->z == 0.0f) return true;
    fm_vec3_t n;
    if (!one_way_normal(u, shape, &n)) return false;
    float d = min_f(fm_vec3_dot(&seg[0], &n), fm_vec3_dot(&seg[1], &n));
    return d >= 0.95f * r;
}

/* One-way test for a ray (origin o relative to the triangle's first vertex). */
static bool one_way_ray(const fm_vec3_t *u, const fm_vec3_t shape[3], const fm_vec3_t *o, const fm_vec3_t *dir)
{
    if (u->x == 0.0f && u->y == 0.0f && u->z == 0.0f) return true;
    fm_vec3_t n;
    if (!one_way_normal(u, shape, &n)) return false;
    return fm_vec3_dot(o, &n) > 0.0f && fm_vec3_dot(dir, &n) < 0.0f;
}

/* Registration margin of the grid (same formula as the builder) plus rounding slack. */
static float mesh_margin(const coll_mesh_t *m)
{
    float maxabs = 0.0f;
    for (int a = 0; a < 3; a++) maxabs = max_f(maxabs, max_f(fabsf(m->bmin[a]), fabsf(m->bmax[a])));
    return m->cell_size * 1e-3f + maxabs * 2e-6f;
}

/* Grid indices and counts are converted as (float)(int32_t): they fit in an int32, and a
 * uint32_t converts through double-precision code on MIPS (cvt.d.w, add.d, cvt.s.d). */
static uint32_t cell_of(float x, float origin, float inv, uint32_t dim)
{
    float f = (x - origin) * inv;
    if (!(f > 0.0f)) return 0;
    if (f >= (float)(int32_t)dim) return dim - 1u;
    uint32_t c = (uint32_t)f;
    return c < dim ? c : dim - 1u;
}

/* ------------------------------------------------------------------ dedup ---------- */

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
    bool overflow;
    bool ready; /* the table is cleared only when a query first needs it */
} seen_t;

static void seen_init(seen_t *s)
{
    s->n = 0;
    s->overflow = false;
    s->ready = false;
}

static void seen_ready(seen_t *s)
{
    if (s->ready) return;
    for (uint32_t i = 0; i < (1u << SEEN_BITS0); i++) s->slot[i] = 0u;
    s->bits = SEEN_BITS0;
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
static void seen_grow(seen_t *s)
{
    uint32_t keys[(1u << SEEN_BITS0) / 2u + 1u];
    uint32_t old = 1u << s->bits;
    for (uint32_t i = 0; i < s->n; i++) keys[i] = s->slot[s->used[i]];
    memset(s->slot, 0, sizeof(uint32_t) * old);
    memset(s->slot + old, 0, sizeof(uint32_t) * (SEEN_SLOTS - old));
    s->bits = SEEN_BITS;
    for (uint32_t i = 0; i < s->n; i++) {
        uint32_t h = seen_probe(s, keys[i]);
        s->slot[h] = keys[i];
        s->used[i] = (uint16_t)h;
    }
}

static void seen_clear(seen_t *s)
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
    if (s->n >= SEEN_MAX) {
        s->overflow = true;
        return SEEN_UNKNOWN;
    }
    if (s->bits < SEEN_BITS && s->n + 1u > (1u << s->bits) / 2u) {
        seen_grow(s);
        h = seen_probe(s, key);
    }
    s->slot[h] = key;
    s->used[s->n++] = (uint16_t)h;
    return SEEN_NEW;
}

static bool seen_first(seen_t *s, uint32_t tri) { return seen_check(s, tri) != SEEN_BEFORE; }

/* Within the first cell entry a query visits no triangle can repeat (a cell lists each
 * triangle once), so the table is not used there: it is started (cleared, and given the
 * first entry's triangles, all of which were candidates) only when a second entry comes.
 * Single-cell queries never touch it. */
typedef struct {
    uint32_t ncell, first;
} lazy_seen_t;

/* Call once per cell entry ci before its triangles; true when they must be deduplicated. */
static bool lazy_enter(lazy_seen_t *z, seen_t *s, const coll_mesh_view_t *mv, uint32_t ci)
{
    if (z->ncell == 0u) {
        z->first = ci;
        z->ncell = 1u;
        return false;
    }
    if (z->ncell == 1u) {
        seen_ready(s);
        for (uint32_t k = mv->cells[z->first]; k < mv->cells[z->first + 1u]; k++)
            (void)seen_check(s, coll_mesh_view_ref(mv, k));
        z->ncell = 2u;
    }
    return true;
}

/* Exact fallback for the overlap list when the table is full: tri is new in cell
 * (cx,cy,cz) unless a cell visited earlier in the same box walk lists it (cells keep
 * their triangles in ascending order: binary search). */
static bool in_cell(const coll_mesh_t *m, uint32_t ci, uint32_t tri)
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

static bool listed_earlier(const coll_mesh_t *m, bool walk_all, const uint32_t clo[3], const uint32_t chi[3],
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

static void note_overflow(const coll_scene_t *scene, seen_t *s)
{
    if (s->overflow) {
        STATS_ADD(scene, dedup_overflows);
        s->overflow = false;
    }
}

/* ------------------------------------------------------------------ raycast -------- */

typedef struct {
    bool have;
    float best;          /* current nearest distance */
    coll_prim_hit_t ph;
    const coll_mesh_instance_t *inst;
    const coll_body_t *body;
    int32_t tri;
} ray_best_t;

/* Slab clip of o + d s, s in [*s0, *s1], against a box. */
static bool clip_box(const fm_vec3_t *o, const fm_vec3_t *d, const float lo[3], const float hi[3],
                     float *s0, float *s1)
{
    for (int a = 0; a < 3; a++) {
        if (d->v[a] == 0.0f) {
            if (o->v[a] < lo[a] || o->v[a] > hi[a]) return false;
            continue;
        }
        float inv = 1.0f / d->v[a];
        float t0 = (lo[a] - o->v[a]) * inv, t1 = (hi[a] - o->v[a]) * inv;
        if (t0 > t1) { float t = t0; t0 = t1; t1 = t; }
        if (t0 > *s0) *s0 = t0;
        if (t1 < *s1) *s1 = t1;
        if (*s0 > *s1) return false;
    }
    return true;
}

static bool tri_box_reject(const fm_vec3_t tri[3], const fm_vec3_t *lo, const fm_vec3_t *hi);

/* Candidate t of a grid walk: its local vertices into v, or false when their box misses
 * llo..lhi (exactly tri_box_reject's test). Every visited cell entry pays this, so the
 * common layout (float vertices) reads the coordinates in place, one axis at a time,
 * across axes first (the up axis rejects least on floors), and copies only survivors. */
#if defined(__GNUC__)
#define CAND_INLINE static inline __attribute__((always_inline))
#else
#define CAND_INLINE static inline
#endif
CAND_INLINE bool cand_tri(const coll_mesh_view_t *mv, uint32_t t, const fm_vec3_t *llo, const fm_vec3_t *lhi,
                            fm_vec3_t v[3])
{
    if (mv->flags & COLL_MESHF_QUANT) {
        coll_mesh_view_tri(mv, t, v);
        return !tri_box_reject(v, llo, lhi);
    }
    uint32_t i0, i1, i2;
    if (mv->flags & COLL_MESHF_IDX16) {
        const uint16_t *ix = (const uint16_t *)(const void *)mv->tris + 3u * t;
        i0 = ix[0]; i1 = ix[1]; i2 = ix[2];
    } else {
        const uint32_t *ix = (const uint32_t *)(const void *)mv->tris + 3u * t;
        i0 = ix[0]; i1 = ix[1]; i2 = ix[2];
    }
    const float *vs = (const float *)(const void *)mv->verts;
    const float *a = vs + 3u * i0, *b = vs + 3u * i1, *c = vs + 3u * i2;
    float lo = llo->x, hi = lhi->x;
    if ((a[0] < lo && b[0] < lo && c[0] < lo) || (a[0] > hi && b[0] > hi && c[0] > hi)) return false;
    lo = llo->z; hi = lhi->z;
    if ((a[2] < lo && b[2] < lo && c[2] < lo) || (a[2] > hi && b[2] > hi && c[2] > hi)) return false;
    lo = llo->y; hi = lhi->y;
    if ((a[1] < lo && b[1] < lo && c[1] < lo) || (a[1] > hi && b[1] > hi && c[1] > hi)) return false;
    v[0].x = a[0]; v[0].y = a[1]; v[0].z = a[2];
    v[1].x = b[0]; v[1].y = b[1]; v[1].z = b[2];
    v[2].x = c[0]; v[2].y = c[1]; v[2].z = c[2];
    return true;
}

/* Mesh-local box of the ray piece o_l + d_l s, s in [s0, s1], grown by the grid margin
 * plus the rounding of the local ray itself: a triangle outside it cannot be hit. */
static void ray_local_box(const fm_vec3_t *o_l, const fm_vec3_t *d_l, float s0, float s1, float mg,
                          fm_vec3_t *lo, fm_vec3_t *hi)
{
    for (int a = 0; a < 3; a++) {
        float p0 = o_l->v[a] + d_l->v[a] * s0, p1 = o_l->v[a] + d_l->v[a] * s1;
        float slack = mg + 1e-6f * (fabsf(p0) + fabsf(p1) + fabsf(o_l->v[a]));
        lo->v[a] = min_f(p0, p1) - slack;
        hi->v[a] = max_f(p0, p1) + slack;
    }
}

/* One candidate triangle t of inst against the ray: first vertex w0 relative to the ray's
 * origin, shape with shape[0] = 0 (the scene walk and the gathered scan both end here). */
static void ray_tri(const coll_mesh_instance_t *inst, int32_t t, const fm_vec3_t *w0, const fm_vec3_t shape[3],
                    const fm_vec3_t *dir, ray_best_t *rb)
{
    fm_vec3_t o;
    coll_prim_hit_t ph;
    fm_vec3_negate(&o, w0);
    fm_vec3_t u = one_way_up(inst);
    if (!one_way_ray(&u, shape, &o, dir)) return;
    if (coll_ray_triangle(&o, dir, shape, rb->best, &ph) && (!rb->have || ph.t < rb->best)) {
        fm_vec3_add(&ph.point, &ph.point, w0);
        rb->have = true;
        rb->best = ph.t;
        rb->ph = ph;
        rb->inst = inst;
        rb->body = NULL;
        rb->tri = t;
    }
}

static void ray_test_tri(const coll_mesh_instance_t *inst, const coll_mesh_view_t *mv, const xf3_t *x,
                         const fm_vec3_t *o_l, const fm_vec3_t *dir, const fm_vec3_t *llo, const fm_vec3_t *lhi,
                         uint32_t t, ray_best_t *rb)
{
    fm_vec3_t v[3], tri[3], w0;
    if (!cand_tri(mv, t, llo, lhi, v)) return; /* cheap local reject first */
    tri_rel_of(v, x, o_l, &w0, tri);
    ray_tri(inst, (int32_t)t, &w0, tri, dir, rb);
}

static void ray_instance(const coll_scene_t *scene, const coll_mesh_instance_t *inst, const fm_vec3_t *origin,
                         const fm_vec3_t *dir, seen_t *seen, ray_best_t *rb)
{
    const coll_mesh_t *m = inst->mesh;
    xf3_t x;
    if (!m || m->ntris == 0 || !xf_prepare(&inst->xf, &x)) return;
    fm_vec3_t o_l = to_local_point(&x, &inst->xf, m, origin);
    fm_vec3_t d_l = to_local_dir(&x, dir);
    float mg = mesh_margin(m);
    float lo[3], hi[3];
    for (int a = 0; a < 3; a++) { lo[a] = m->bmin[a] - mg; hi[a] = m->bmax[a] + mg; }
    float s0 = 0.0f, s1 = rb->best;
    if (!clip_box(&o_l, &d_l, lo, hi, &s0, &s1)) return;

    /* 3D DDA from the entry point. */
    coll_mesh_view_t mv;
    coll_mesh_view_init(&mv, m);
    const uint32_t *cells = mv.cells;
    fm_vec3_t rlo, rhi;
    float box_end = rb->best;
    ray_local_box(&o_l, &d_l, s0, box_end, mg, &rlo, &rhi);
    float cs = m->cell_size, inv_cs = 1.0f / cs;
    uint32_t c[3];
    int step[3];
    float inv_d[3];
    for (int a = 0; a < 3; a++) {
        float p = o_l.v[a] + d_l.v[a] * s0;
        c[a] = cell_of(p, m->grid_origin[a], inv_cs, m->dims[a]);
        step[a] = d_l.v[a] > 0.0f ? 1 : (d_l.v[a] < 0.0f ? -1 : 0);
        inv_d[a] = step[a] ? 1.0f / d_l.v[a] : 0.0f;
    }
    lazy_seen_t lz = { 0u, 0u };
    for (;;) {
        uint32_t ci = coll_mesh_cell_index(m, c[0], c[1], c[2]);
        bool dedup = lazy_enter(&lz, seen, &mv, ci);
        for (uint32_t k = cells[ci]; k < cells[ci + 1u]; k++) {
            uint32_t t = coll_mesh_view_ref(&mv, k);
            if (dedup && !seen_first(seen, t)) continue;
            if (rb->best < box_end) { /* the nearest hit shrank the ray: shrink its box */
                box_end = rb->best;
                ray_local_box(&o_l, &d_l, s0, box_end, mg, &rlo, &rhi);
            }
            ray_test_tri(inst, &mv, &x, &o_l, dir, &rlo, &rhi, t, rb);
        }
        /* Parameter where the ray leaves this cell: recomputed from the cell index (no
         * accumulated error). A hit no farther than that is the nearest: every point of
         * the ray before it lies in a visited cell. */
        float s_exit = INFINITY;
        int axis = -1;
        for (int a = 0; a < 3; a++) {
            if (!step[a]) continue;
            float bound = m->grid_origin[a] + (float)(int32_t)(c[a] + (step[a] > 0 ? 1u : 0u)) * cs;
            float s = (bound - o_l.v[a]) * inv_d[a];
            if (s < s_exit) { s_exit = s; axis = a; }
        }
        if (axis < 0 || s_exit >= s1 || s_exit >= rb->best) break;
        if (step[axis] > 0) {
            if (c[axis] + 1u >= m->dims[axis]) break;
            c[axis]++;
        } else {
            if (c[axis] == 0u) break;
            c[axis]--;
        }
    }
    seen_clear(seen);
    note_overflow(scene, seen);
}

/* Radius of a sphere round the body's centre that contains it (scale is not part of a body). */
static float body_bound_radius(const coll_body_t *b)
{
    float x = fabsf(b->half_extents.x), y = fabsf(b->half_extents.y), z = fabsf(b->half_extents.z);
    switch (b->shape) {
    case COLL_SHAPE_SPHERE: return x;
    case COLL_SHAPE_CAPSULE: return x + y;
    case COLL_SHAPE_CYLINDER: return sqrtf(x * x + y * y);
    default: return sqrtf(x * x + y * y + z * z);
    }
}

static bool body_visible(const coll_body_t *b, uint8_t read_mask)
{
    return b && (b->write_mask & read_mask) && vfin(&b->xf.pos);
}

/* Collider bodies of the scene along a ray (origin-relative results into rb). */
static void ray_bodies(const coll_scene_t *scene, const fm_vec3_t *origin, const fm_vec3_t *dir, uint8_t read_mask,
                       ray_best_t *rb)
{
    static const fm_vec3_t zero = {{0.0f, 0.0f, 0.0f}};
    float dl2 = fm_vec3_len2(dir);
    for (uint16_t i = 0; i < scene->body_count; i++) {
        const coll_body_t *b = scene->bodies[i];
        if (!body_visible(b, read_mask)) continue;
        fm_vec3_t rel;
        fm_vec3_sub(&rel, &b->xf.pos, origin);
        /* Bounding-sphere reject: distance from the centre to the ray segment. */
        float s = fm_vec3_dot(&rel, dir) / dl2;
        if (s < 0.0f) s = 0.0f;
        if (s > rb->best) s = rb->best;
        fm_vec3_t cp;
        fm_vec3_scale(&cp, dir, s);
        float R = body_bound_radius(b);
        if (fm_vec3_distance2(&cp, &rel) > R * R * 1.0001f + 1e-6f) continue;
        coll_prim_hit_t ph;
        if (coll_ray_body(&zero, dir, b, &rel, rb->best, &ph) && (!rb->have || ph.t < rb->best)) {
            rb->have = true;
            rb->best = ph.t;
            rb->ph = ph;
            rb->inst = NULL;
            rb->body = b;
            rb->tri = -1;
        }
    }
}

static bool ray_result(const ray_best_t *rb, const fm_vec3_t *origin, coll_ray_hit_t *hit)
{
    if (!rb->have) return false;
    if (hit) {
        fm_vec3_add(&hit->point, origin, &rb->ph.point);
        hit->normal = rb->ph.normal;
        hit->distance = rb->ph.t;
        hit->instance = rb->inst;
        hit->body = rb->body;
        hit->triangle = rb->tri;
        hit->type = rb->inst ? COLL_TYPE_MESH : COLL_TYPE_BODY;
        hit->id = rb->inst ? rb->inst->id : rb->body->id;
    }
    return true;
}

static bool ray_args_ok(const fm_vec3_t *origin, const fm_vec3_t *dir, float max_dist)
{
    return vfin(origin) && vfin(dir) && isfinite(max_dist) && max_dist > 0.0f && fm_vec3_len2(dir) > 0.0f;
}

bool coll_raycast(const coll_scene_t *scene, fm_vec3_t origin, fm_vec3_t dir, float max_dist,
                  uint8_t read_mask, uint8_t coll_types, coll_ray_hit_t *hit)
{
    if (!scene || !ray_args_ok(&origin, &dir, max_dist)) return false;
    STATS_ADD(scene, queries);
    ray_best_t rb;
    memset(&rb, 0, sizeof rb);
    rb.best = max_dist;
    rb.tri = -1;
    seen_t seen;
    if (coll_types & COLL_TYPE_MESH) {
        seen_init(&seen);
        for (uint16_t i = 0; i < scene->mesh_count; i++) {
            const coll_mesh_instance_t *inst = scene->meshes[i];
            if (inst && (inst->write_mask & read_mask)) ray_instance(scene, inst, &origin, &dir, &seen, &rb);
        }
    }
    if (coll_types & COLL_TYPE_BODY) ray_bodies(scene, &origin, &dir, read_mask, &rb);
    return ray_result(&rb, &origin, hit);
}

/* ------------------------------------------------------------------ capsule -------- */

typedef struct {
    fm_vec3_t seg[2];   /* relative to the capsule centre */
    float r;
    fm_vec3_t disp;
    float eps;          /* AABB slack */
} capsule_q_t;

/* World-relative AABB of the capsule swept from 0 to t. */
static void swept_box(const capsule_q_t *q, float t, fm_vec3_t *lo, fm_vec3_t *hi)
{
    for (int a = 0; a < 3; a++) {
        float d = q->disp.v[a] * t;
        float mn = min_f(q->seg[0].v[a], q->seg[1].v[a]), mx = max_f(q->seg[0].v[a], q->seg[1].v[a]);
        lo->v[a] = mn + min_f(d, 0.0f) - q->r - q->eps;
        hi->v[a] = mx + max_f(d, 0.0f) + q->r + q->eps;
    }
}

static bool tri_box_reject(const fm_vec3_t tri[3], const fm_vec3_t *lo, const fm_vec3_t *hi)
{
    for (int a = 0; a < 3; a++) {
        if (tri[0].v[a] < lo->v[a] && tri[1].v[a] < lo->v[a] && tri[2].v[a] < lo->v[a]) return true;
        if (tri[0].v[a] > hi->v[a] && tri[1].v[a] > hi->v[a] && tri[2].v[a] > hi->v[a]) return true;
    }
    return false;
}

/* Conservative mesh-local box of a world-relative box (plus the grid margin). */
static void local_box(const coll_mesh_t *m, const xf3_t *x, const fm_vec3_t *o_l, const fm_vec3_t *lo,
                      const fm_vec3_t *hi, fm_vec3_t *llo, fm_vec3_t *lhi)
{
    fm_vec3_t c, h;
    for (int a = 0; a < 3; a++) {
        c.v[a] = 0.5f * (lo->v[a] + hi->v[a]);
        h.v[a] = 0.5f * (hi->v[a] - lo->v[a]);
    }
    fm_vec3_t cl = x->simple ? c : mul3(x->inv, &c);
    fm_vec3_t hl = x->simple ? h : mul3_abs(x->inv, &h);
    float mg = mesh_margin(m);
    for (int a = 0; a < 3; a++) {
        llo->v[a] = o_l->v[a] + cl.v[a] - hl.v[a] - mg;
        lhi->v[a] = o_l->v[a] + cl.v[a] + hl.v[a] + mg;
    }
}

/* Cell range of a mesh-local box in an instance's grid; false when it misses the mesh. */
static bool instance_cells(const coll_mesh_t *m, const fm_vec3_t *llo, const fm_vec3_t *lhi, uint32_t clo[3],
                           uint32_t chi[3])
{
    float inv_cs = 1.0f / m->cell_size;
    for (int a = 0; a < 3; a++) {
        if (lhi->v[a] < m->bmin[a] || llo->v[a] > m->bmax[a]) return false;
        clo[a] = cell_of(llo->v[a], m->grid_origin[a], inv_cs, m->dims[a]);
        chi[a] = cell_of(lhi->v[a], m->grid_origin[a], inv_cs, m->dims[a]);
    }
    return true;
}

/* Hashed grid and a box of more cells than the grid has entries (a long sweep over fine
 * cells): walk the entries once each instead (every triangle is still a candidate, so
 * the result is the same); the loops then run cx over the entries with cy = cz = 0. */
static bool walk_entries(const coll_mesh_t *m, uint32_t clo[3], uint32_t chi[3])
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
static bool cell_misses(const coll_mesh_t *m, uint32_t cx, uint32_t cy, uint32_t cz, const fm_vec3_t *llo,
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

typedef struct {
    bool have;
    float best_t;
    coll_prim_hit_t ph;
    const coll_mesh_instance_t *inst;
    const coll_body_t *body;
    int32_t tri;
} sweep_best_t;

static bool sweep_better(const coll_prim_hit_t *h, const sweep_best_t *sb)
{
    if (!sb->have) return true;
    if (h->t < sb->ph.t) return true;
    return h->t == sb->ph.t && h->t == 0.0f && h->depth > sb->ph.depth;
}

/* One candidate triangle t of inst (w0, shape as for ray_tri; u: the one-way up, zero for
 * an ordinary instance) against the capsule sweep; true when it is the new best hit. */
static bool sweep_tri(const capsule_q_t *q, const coll_mesh_instance_t *inst, int32_t t, const fm_vec3_t *w0,
                      const fm_vec3_t shape[3], const fm_vec3_t *u, sweep_best_t *sb)
{
    fm_vec3_t seg[2];
    fm_vec3_sub(&seg[0], &q->seg[0], w0);
    fm_vec3_sub(&seg[1], &q->seg[1], w0);
    if (!one_way_capsule(u, shape, seg, q->r)) return false;
    coll_prim_hit_t ph;
    if (!coll_tri_sweep(seg, q->r, &q->disp, shape, sb->best_t, &ph) || !sweep_better(&ph, sb)) return false;
    fm_vec3_add(&ph.point, &ph.point, w0);
    sb->have = true;
    sb->best_t = ph.t;
    sb->ph = ph;
    sb->inst = inst;
    sb->body = NULL;
    sb->tri = t;
    return true;
}

static void sweep_instance(const coll_scene_t *scene, const coll_mesh_instance_t *inst, const fm_vec3_t *center,
                           const capsule_q_t *q, seen_t *seen, sweep_best_t *sb)
{
    const coll_mesh_t *m = inst->mesh;
    xf3_t x;
    if (!m || m->ntris == 0 || !xf_prepare(&inst->xf, &x)) return;
    const fm_vec3_t up1 = one_way_up(inst);
    fm_vec3_t o_l = to_local_point(&x, &inst->xf, m, center);
    fm_vec3_t lo, hi, llo, lhi;
    swept_box(q, sb->best_t, &lo, &hi);
    local_box(m, &x, &o_l, &lo, &hi, &llo, &lhi);
    uint32_t clo[3], chi[3];
    if (!instance_cells(m, &llo, &lhi, clo, chi)) return;
    bool walk_all = walk_entries(m, clo, chi);
    coll_mesh_view_t mv;
    coll_mesh_view_init(&mv, m);
    const uint32_t *cells = mv.cells;
    /* Box reject first, dedup of the survivors only (see coll_gather_begin; the box only
     * shrinks, so a triangle it rejected once stays rejected). */
    bool dedup = walk_all || (m->flags & COLL_MESHF_HASH) || clo[0] != chi[0] || clo[1] != chi[1] || clo[2] != chi[2];
    if (dedup) seen_ready(seen);
    for (uint32_t cz = clo[2]; cz <= chi[2]; cz++)
        for (uint32_t cy = clo[1]; cy <= chi[1]; cy++)
            for (uint32_t cx = clo[0]; cx <= chi[0]; cx++) {
                /* the sweep may have shrunk since the range was computed */
                if (!walk_all && sb->inst == inst && cell_misses(m, cx, cy, cz, &llo, &lhi)) continue;
                uint32_t ci = walk_all ? cx : coll_mesh_cell_index(m, cx, cy, cz);
                for (uint32_t k = cells[ci], kend = cells[ci + 1u]; k < kend; k++) {
                    uint32_t t = coll_mesh_view_ref(&mv, k);
                    fm_vec3_t v[3], shape[3], w0, tri[3];
                    if (!cand_tri(&mv, t, &llo, &lhi, v)) continue; /* cheap local reject first */
                    if (dedup && !seen_first(seen, t)) continue;
                    tri_rel_of(v, &x, &o_l, &w0, shape);
                    tri_abs(&w0, shape, tri);
                    if (tri_box_reject(tri, &lo, &hi)) continue;
                    if (sweep_tri(q, inst, (int32_t)t, &w0, shape, &up1, sb)) {
                        swept_box(q, sb->best_t, &lo, &hi); /* shrink the sweep */
                        local_box(m, &x, &o_l, &lo, &hi, &llo, &lhi);
                    }
                }
            }
    seen_clear(seen);
    note_overflow(scene, seen);
}

static bool capsule_args_ok(const fm_vec3_t *center, const fm_vec3_t *axis, float radius, float hh)
{
    return vfin(center) && vfin(axis) && isfinite(radius) && radius > 0.0f && isfinite(hh) && hh >= 0.0f;
}

static void capsule_setup(capsule_q_t *q, const fm_vec3_t *axis, float radius, float hh, const fm_vec3_t *disp)
{
    fm_vec3_scale(&q->seg[1], axis, hh);
    fm_vec3_negate(&q->seg[0], &q->seg[1]);
    q->r = radius;
    q->disp = *disp;
    q->eps = 1e-4f * (radius + hh + fm_vec3_len(disp)) + 1e-6f;
}

/* Body bounding sphere against a world-relative box. */
static bool body_box_reject(const coll_body_t *b, const fm_vec3_t *rel, const fm_vec3_t *lo, const fm_vec3_t *hi)
{
    float R = body_bound_radius(b) * 1.0001f + 1e-5f;
    for (int a = 0; a < 3; a++)
        if (rel->v[a] + R < lo->v[a] || rel->v[a] - R > hi->v[a]) return true;
    return false;
}

/* Collider bodies of the scene against a capsule sweep (centre-relative results into sb). */
static void sweep_bodies(const coll_scene_t *scene, const fm_vec3_t *center, const capsule_q_t *q, uint8_t read_mask,
                         sweep_best_t *sb)
{
    for (uint16_t i = 0; i < scene->body_count; i++) {
        const coll_body_t *b = scene->bodies[i];
        if (!body_visible(b, read_mask)) continue;
        fm_vec3_t rel, lo, hi;
        fm_vec3_sub(&rel, &b->xf.pos, center);
        swept_box(q, sb->best_t, &lo, &hi);
        if (body_box_reject(b, &rel, &lo, &hi)) continue;
        coll_prim_hit_t ph;
        if (coll_capsule_body_sweep(q->seg, q->r, &q->disp, b, &rel, sb->best_t, &ph) && sweep_better(&ph, sb)) {
            sb->have = true;
            sb->best_t = ph.t;
            sb->ph = ph;
            sb->inst = NULL;
            sb->body = b;
            sb->tri = -1;
        }
    }
}

static bool sweep_result(const sweep_best_t *sb, const fm_vec3_t *center, coll_sweep_hit_t *hit)
{
    if (!sb->have) return false;
    if (hit) {
        fm_vec3_add(&hit->point, center, &sb->ph.point);
        hit->normal = sb->ph.normal;
        hit->t = sb->ph.t;
        hit->depth = sb->ph.t == 0.0f ? sb->ph.depth : 0.0f;
        hit->instance = sb->inst;
        hit->body = sb->body;
        hit->triangle = sb->tri;
        hit->type = sb->inst ? COLL_TYPE_MESH : COLL_TYPE_BODY;
        hit->id = sb->inst ? sb->inst->id : sb->body->id;
    }
    return true;
}

bool coll_capsule_sweep(const coll_scene_t *scene, fm_vec3_t center, fm_vec3_t axis, float radius,
                        float inner_half_height, fm_vec3_t displacement, uint8_t read_mask,
                        uint8_t coll_types, coll_sweep_hit_t *hit)
{
    if (!scene || !capsule_args_ok(&center, &axis, radius, inner_half_height) || !vfin(&displacement))
        return false;
    STATS_ADD(scene, queries);
    capsule_q_t q;
    capsule_setup(&q, &axis, radius, inner_half_height, &displacement);
    sweep_best_t sb;
    memset(&sb, 0, sizeof sb);
    sb.best_t = 1.0f;
    sb.tri = -1;
    seen_t seen;
    if (coll_types & COLL_TYPE_MESH) {
        seen_init(&seen);
        for (uint16_t i = 0; i < scene->mesh_count; i++) {
            const coll_mesh_instance_t *inst = scene->meshes[i];
            if (inst && (inst->write_mask & read_mask)) sweep_instance(scene, inst, &center, &q, &seen, &sb);
        }
    }
    if (coll_types & COLL_TYPE_BODY) sweep_bodies(scene, &center, &q, read_mask, &sb);
    return sweep_result(&sb, &center, hit);
}

/* ------------------------------------------------------------------ overlaps ------- */

typedef struct {
    coll_contact_t *out;
    uint32_t max_out, kept, total;
    fm_vec3_t center;
} contacts_t;

static void contact_add(contacts_t *c, const coll_prim_hit_t *ph, const coll_mesh_instance_t *inst,
                        const coll_body_t *body, int32_t tri)
{
    c->total++;
    if (c->max_out == 0u || !c->out) return;
    uint32_t pos = c->kept;
    if (c->kept == c->max_out) {
        if (!(ph->depth > c->out[c->kept - 1u].depth)) return;
        pos = c->kept - 1u; /* drop the shallowest */
    } else {
        c->kept++;
    }
    while (pos > 0u && c->out[pos - 1u].depth < ph->depth) {
        c->out[pos] = c->out[pos - 1u];
        pos--;
    }
    coll_contact_t *o = &c->out[pos];
    o->normal = ph->normal;
    fm_vec3_add(&o->point, &c->center, &ph->point);
    o->depth = ph->depth;
    o->instance = inst;
    o->body = body;
    o->triangle = tri;
    o->type = inst ? COLL_TYPE_MESH : COLL_TYPE_BODY;
    o->id = inst ? inst->id : body->id;
}

/* The capsule segment (relative to the triangle's first vertex, shape[0] = 0) lies
 * entirely on one side of the triangle's plane, farther than r (with a relative and a
 * rounding allowance): no overlap is possible, without any closest-point work. */
static bool plane_rejects(float r, const fm_vec3_t seg[2], const fm_vec3_t shape[3])
{
    fm_vec3_t n;
    fm_vec3_cross(&n, &shape[1], &shape[2]);
    float d0 = fm_vec3_dot(&n, &seg[0]), d1 = fm_vec3_dot(&n, &seg[1]);
    if (!(d0 * d1 > 0.0f)) return false;
    float mn = min_f(d0 * d0, d1 * d1);
    float l1 = fabsf(seg[0].x) + fabsf(seg[0].y) + fabsf(seg[0].z) + fabsf(seg[1].x) + fabsf(seg[1].y) +
               fabsf(seg[1].z);
    float rr = r * 1.001f + 1e-6f * l1 + 1e-7f;
    return mn > rr * rr * fm_vec3_len2(&n);
}

/* One candidate triangle t of inst (w0, shape, u as for sweep_tri) against the overlap query. */
static void overlap_tri(const capsule_q_t *q, const coll_mesh_instance_t *inst, int32_t t, const fm_vec3_t *w0,
                        const fm_vec3_t shape[3], const fm_vec3_t *u, contacts_t *c)
{
    fm_vec3_t seg[2];
    fm_vec3_sub(&seg[0], &q->seg[0], w0);
    fm_vec3_sub(&seg[1], &q->seg[1], w0);
    if (plane_rejects(q->r, seg, shape)) return;
    if (!one_way_capsule(u, shape, seg, q->r)) return;
    coll_prim_hit_t ph;
    if (coll_capsule_triangle_overlap(seg, q->r, shape, &ph) && ph.depth > 0.0f) {
        fm_vec3_add(&ph.point, &ph.point, w0);
        contact_add(c, &ph, inst, NULL, t);
    }
}

static void overlap_instance(const coll_scene_t *scene, const coll_mesh_instance_t *inst, const capsule_q_t *q,
                             seen_t *seen, contacts_t *c)
{
    const coll_mesh_t *m = inst->mesh;
    xf3_t x;
    if (!m || m->ntris == 0 || !xf_prepare(&inst->xf, &x)) return;
    const fm_vec3_t up1 = one_way_up(inst);
    fm_vec3_t o_l = to_local_point(&x, &inst->xf, m, &c->center);
    fm_vec3_t lo, hi, llo, lhi;
    swept_box(q, 0.0f, &lo, &hi);
    local_box(m, &x, &o_l, &lo, &hi, &llo, &lhi);
    uint32_t clo[3], chi[3];
    if (!instance_cells(m, &llo, &lhi, clo, chi)) return;
    bool walk_all = walk_entries(m, clo, chi);
    coll_mesh_view_t mv;
    coll_mesh_view_init(&mv, m);
    const uint32_t *cells = mv.cells;
    /* Box reject first, dedup of the survivors only (see coll_gather_begin); a hashed entry
     * may list a triangle twice (see the builder), so hashed grids always deduplicate. */
    bool dedup = walk_all || (m->flags & COLL_MESHF_HASH) || clo[0] != chi[0] || clo[1] != chi[1] || clo[2] != chi[2];
    if (dedup) seen_ready(seen);
    for (uint32_t cz = clo[2]; cz <= chi[2]; cz++)
        for (uint32_t cy = clo[1]; cy <= chi[1]; cy++)
            for (uint32_t cx = clo[0]; cx <= chi[0]; cx++) {
                uint32_t ci = walk_all ? cx : coll_mesh_cell_index(m, cx, cy, cz);
                for (uint32_t k = cells[ci], kend = cells[ci + 1u]; k < kend; k++) {
                    uint32_t t = coll_mesh_view_ref(&mv, k);
                    fm_vec3_t v[3], shape[3], w0, tri[3];
                    if (!cand_tri(&mv, t, &llo, &lhi, v)) continue;
                    if (dedup) {
                        int sc = seen_check(seen, t);
                        if (sc == SEEN_BEFORE) continue;
                        if (sc == SEEN_UNKNOWN && listed_earlier(m, walk_all, clo, chi, cx, cy, cz, t)) continue;
                    }
                    tri_rel_of(v, &x, &o_l, &w0, shape);
                    tri_abs(&w0, shape, tri);
                    if (tri_box_reject(tri, &lo, &hi)) continue;
                    overlap_tri(q, inst, (int32_t)t, &w0, shape, &up1, c);
                }
            }
    seen_clear(seen);
    note_overflow(scene, seen);
}

/* Collider bodies of the scene overlapping a capsule. */
static void overlap_bodies(const coll_scene_t *scene, const capsule_q_t *q, uint8_t read_mask, contacts_t *c)
{
    for (uint16_t i = 0; i < scene->body_count; i++) {
        const coll_body_t *b = scene->bodies[i];
        if (!body_visible(b, read_mask)) continue;
        fm_vec3_t rel, lo, hi;
        fm_vec3_sub(&rel, &b->xf.pos, &c->center);
        swept_box(q, 0.0f, &lo, &hi);
        if (body_box_reject(b, &rel, &lo, &hi)) continue;
        coll_prim_hit_t ph;
        if (coll_capsule_body_overlap(q->seg, q->r, b, &rel, &ph) && ph.depth > 0.0f) contact_add(c, &ph, NULL, b, -1);
    }
}

uint32_t coll_capsule_overlaps(const coll_scene_t *scene, fm_vec3_t center, fm_vec3_t axis, float radius,
                               float inner_half_height, uint8_t read_mask, uint8_t coll_types,
                               coll_contact_t *out, uint32_t max_out)
{
    if (!scene || !capsule_args_ok(&center, &axis, radius, inner_half_height)) return 0;
    STATS_ADD(scene, queries);
    static const fm_vec3_t zero = {{0.0f, 0.0f, 0.0f}};
    capsule_q_t q;
    capsule_setup(&q, &axis, radius, inner_half_height, &zero);
    contacts_t c = { out, max_out, 0, 0, center };
    seen_t seen;
    if (coll_types & COLL_TYPE_MESH) {
        seen_init(&seen);
        for (uint16_t i = 0; i < scene->mesh_count; i++) {
            const coll_mesh_instance_t *inst = scene->meshes[i];
            if (inst && (inst->write_mask & read_mask)) overlap_instance(scene, inst, &q, &seen, &c);
        }
    }
    if (coll_types & COLL_TYPE_BODY) overlap_bodies(scene, &q, read_mask, &c);
    return c.total;
}

/* ------------------------------------------------------------------ gather --------- */

void coll_gather_begin(coll_gather_t *g, const coll_scene_t *scene, fm_vec3_t lo, fm_vec3_t hi, uint8_t read_mask,
                       uint8_t types)
{
    g->scene = scene;
    g->read_mask = read_mask;
    g->types = types;
    g->ntris = 0;
    g->valid = false;
    if (!scene || !vfin(&lo) || !vfin(&hi)) return;
    for (int a = 0; a < 3; a++) {
        g->origin.v[a] = 0.5f * (lo.v[a] + hi.v[a]);
        g->hi.v[a] = 0.5f * (hi.v[a] - lo.v[a]);
        g->lo.v[a] = -g->hi.v[a];
    }
    g->valid = true;
    STATS_ADD(scene, gathers);
    if (!(types & COLL_TYPE_MESH)) return;
    seen_t seen;
    seen_init(&seen);
    for (uint16_t i = 0; i < scene->mesh_count; i++) {
        const coll_mesh_instance_t *inst = scene->meshes[i];
        if (!inst || !(inst->write_mask & read_mask)) continue;
        const coll_mesh_t *m = inst->mesh;
        xf3_t x;
        if (!m || m->ntris == 0 || !xf_prepare(&inst->xf, &x)) continue;
        fm_vec3_t o_l = to_local_point(&x, &inst->xf, m, &g->origin);
        fm_vec3_t llo, lhi;
        local_box(m, &x, &o_l, &g->lo, &g->hi, &llo, &lhi);
        uint32_t clo[3], chi[3];
        if (!instance_cells(m, &llo, &lhi, clo, chi)) continue;
        bool walk_all = walk_entries(m, clo, chi);
        coll_mesh_view_t mv;
        coll_mesh_view_init(&mv, m);
        const uint32_t *cells = mv.cells;
        /* The box reject comes first (a triangle it rejects is rejected on every visit), and
         * only the survivors are deduplicated: on dense meshes most candidates of a cell
         * lie outside the box. One cell of a plain grid lists a triangle once: no dedup. */
        bool dedup = walk_all || (m->flags & COLL_MESHF_HASH) || clo[0] != chi[0] || clo[1] != chi[1] ||
                     clo[2] != chi[2];
        if (dedup) seen_ready(&seen);
        for (uint32_t cz = clo[2]; cz <= chi[2]; cz++)
            for (uint32_t cy = clo[1]; cy <= chi[1]; cy++)
                for (uint32_t cx = clo[0]; cx <= chi[0]; cx++) {
                    uint32_t ci = walk_all ? cx : coll_mesh_cell_index(m, cx, cy, cz);
                    for (uint32_t k = cells[ci], kend = cells[ci + 1u]; k < kend; k++) {
                        uint32_t t = coll_mesh_view_ref(&mv, k);
                        fm_vec3_t v[3], shape[3], w0, tri[3];
                        if (!cand_tri(&mv, t, &llo, &lhi, v)) continue;
                        if (dedup) {
                            int sc = seen_check(&seen, t);
                            if (sc == SEEN_BEFORE) continue;
                            if (sc == SEEN_UNKNOWN && listed_earlier(m, walk_all, clo, chi, cx, cy, cz, t)) continue;
                        }
                        tri_rel_of(v, &x, &o_l, &w0, shape);
                        tri_abs(&w0, shape, tri);
                        if (tri_box_reject(tri, &g->lo, &g->hi)) continue;
                        if (g->ntris >= COLL_GATHER_MAX) { /* too many: every query goes to the scene */
                            STATS_ADD(scene, gather_overflows);
                            g->valid = false;
                            seen_clear(&seen);
                            return;
                        }
                        coll_gather_tri_t *gt = &g->tris[g->ntris++];
                        gt->w0 = w0;
                        gt->e1 = shape[1];
                        gt->e2 = shape[2];
                        for (int a = 0; a < 3; a++) {
                            gt->lo.v[a] = min_f(tri[0].v[a], min_f(tri[1].v[a], tri[2].v[a]));
                            gt->hi.v[a] = max_f(tri[0].v[a], max_f(tri[1].v[a], tri[2].v[a]));
                        }
                        gt->inst = inst;
                        gt->tri = (int32_t)t;
                    }
                }
        seen_clear(&seen);
        note_overflow(scene, &seen);
    }
}

/* The query box lo..hi (relative to the query's own origin at rel from the gather's) lies
 * inside the gathered box: every triangle that can touch the query was gathered. */
static bool gather_covers(const coll_gather_t *g, const fm_vec3_t *rel, const fm_vec3_t *lo, const fm_vec3_t *hi)
{
    if (!g->valid) return false;
    for (int a = 0; a < 3; a++)
        if (!(lo->v[a] + rel->v[a] >= g->lo.v[a]) || !(hi->v[a] + rel->v[a] <= g->hi.v[a])) {
            STATS_ADD(g->scene, gather_misses);
            return false;
        }
    STATS_ADD(g->scene, gather_queries);
    return true;
}

/* Gathered triangle k relative to a query origin at rel (from the gather's): first vertex
 * w0 and shape (shape[0] = 0); false when its box misses lo..hi (query-relative). */
static bool gather_tri(const coll_gather_t *g, uint16_t k, const fm_vec3_t *rel, const fm_vec3_t *lo,
                       const fm_vec3_t *hi, fm_vec3_t *w0, fm_vec3_t shape[3])
{
    const coll_gather_tri_t *gt = &g->tris[k];
    for (int a = 0; a < 3; a++)
        if (gt->hi.v[a] - rel->v[a] < lo->v[a] || gt->lo.v[a] - rel->v[a] > hi->v[a]) return false;
    fm_vec3_sub(w0, &gt->w0, rel);
    shape[0].x = shape[0].y = shape[0].z = 0.0f;
    shape[1] = gt->e1;
    shape[2] = gt->e2;
    return true;
}

bool coll_gather_raycast(const coll_gather_t *g, fm_vec3_t origin, fm_vec3_t dir, float max_dist, coll_ray_hit_t *hit)
{
    if (!g || !g->scene) return false;
    if (!ray_args_ok(&origin, &dir, max_dist)) return false;
    fm_vec3_t rel, lo, hi;
    fm_vec3_sub(&rel, &origin, &g->origin);
    for (int a = 0; a < 3; a++) {
        float e = dir.v[a] * max_dist, slack = 1e-4f * max_dist + 1e-6f;
        lo.v[a] = min_f(0.0f, e) - slack;
        hi.v[a] = max_f(0.0f, e) + slack;
    }
    if (!(g->types & COLL_TYPE_MESH) || !gather_covers(g, &rel, &lo, &hi))
        return coll_raycast(g->scene, origin, dir, max_dist, g->read_mask, g->types, hit);
    ray_best_t rb;
    memset(&rb, 0, sizeof rb);
    rb.best = max_dist;
    rb.tri = -1;
    for (uint16_t k = 0; k < g->ntris; k++) {
        fm_vec3_t w0, shape[3];
        if (gather_tri(g, k, &rel, &lo, &hi, &w0, shape)) ray_tri(g->tris[k].inst, g->tris[k].tri, &w0, shape, &dir, &rb);
    }
    if (g->types & COLL_TYPE_BODY) ray_bodies(g->scene, &origin, &dir, g->read_mask, &rb);
    return ray_result(&rb, &origin, hit);
}

bool coll_gather_capsule_sweep(const coll_gather_t *g, fm_vec3_t center, fm_vec3_t axis, float radius,
                               float inner_half_height, fm_vec3_t displacement, coll_sweep_hit_t *hit)
{
    if (!g || !g->scene) return false;
    if (!capsule_args_ok(&center, &axis, radius, inner_half_height) || !vfin(&displacement)) return false;
    capsule_q_t q;
    capsule_setup(&q, &axis, radius, inner_half_height, &displacement);
    fm_vec3_t rel, lo, hi;
    fm_vec3_sub(&rel, &center, &g->origin);
    swept_box(&q, 1.0f, &lo, &hi);
    if (!(g->types & COLL_TYPE_MESH) || !gather_covers(g, &rel, &lo, &hi))
        return coll_capsule_sweep(g->scene, center, axis, radius, inner_half_height, displacement, g->read_mask,
                                  g->types, hit);
    sweep_best_t sb;
    memset(&sb, 0, sizeof sb);
    sb.best_t = 1.0f;
    sb.tri = -1;
    for (uint16_t k = 0; k < g->ntris; k++) {
        fm_vec3_t w0, shape[3];
        if (!gather_tri(g, k, &rel, &lo, &hi, &w0, shape)) continue;
        fm_vec3_t u = one_way_up(g->tris[k].inst);
        if (sweep_tri(&q, g->tris[k].inst, g->tris[k].tri, &w0, shape, &u, &sb))
            swept_box(&q, sb.best_t, &lo, &hi); /* shrink the sweep */
    }
    if (g->types & COLL_TYPE_BODY) sweep_bodies(g->scene, &center, &q, g->read_mask, &sb);
    return sweep_result(&sb, &center, hit);
}

uint32_t coll_gather_capsule_overlaps(const coll_gather_t *g, fm_vec3_t center, fm_vec3_t axis, float radius,
                                      float inner_half_height, coll_contact_t *out, uint32_t max_out)
{
    if (!g || !g->scene) return 0;
    if (!capsule_args_ok(&center, &axis, radius, inner_half_height)) return 0;
    static const fm_vec3_t zero = {{0.0f, 0.0f, 0.0f}};
    capsule_q_t q;
    capsule_setup(&q, &axis, radius, inner_half_height, &zero);
    fm_vec3_t rel, lo, hi;
    fm_vec3_sub(&rel, &center, &g->origin);
    swept_box(&q, 0.0f, &lo, &hi);
    if (!(g->types & COLL_TYPE_MESH) || !gather_covers(g, &rel, &lo, &hi))
        return coll_capsule_overlaps(g->scene, center, axis, radius, inner_half_height, g->read_mask, g->types, out,
                                     max_out);
    contacts_t c = { out, max_out, 0, 0, center };
    for (uint16_t k = 0; k < g->ntris; k++) {
        fm_vec3_t w0, shape[3];
        if (!gather_tri(g, k, &rel, &lo, &hi, &w0, shape)) continue;
        fm_vec3_t u = one_way_up(g->tris[k].inst);
        overlap_tri(&q, g->tris[k].inst, g->tris[k].tri, &w0, shape, &u, &c);
    }
    if (g->types & COLL_TYPE_BODY) overlap_bodies(g->scene, &q, g->read_mask, &c);
    return c.total;
}
