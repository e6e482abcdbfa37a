/**
 * @file gather.c
 * @brief The step gather (gather.h): one walk of the grid cells under a character step's
 *        box (grid_walk.h), keeping the triangles that meet it in query-relative form. The
 *        queries on the gathered triangles are in query.c, beside the scene's.
 */
#include "vec3.h"
#include "gather.h"
#include "grid_walk.h"
#include <float.h>

/* A kept triangle's box lo..hi meets the gathered box (the walk's test below, fused there with the box's computation). */
static inline bool box_meets(const fm_vec3_t *lo, const fm_vec3_t *hi, const coll_gather_t *g)
{
    bool out = false;
    for (int a = 0; a < 3; a++) out |= hi->v[a] < g->lo.v[a] || lo->v[a] > g->hi.v[a];
    return !out;
}

/* The buffer is full and one more triangle (box lo..hi) meets the gathered box: shrinks the
 * box about its centre until the buffer has room or the new triangle is out, dropping the
 * kept triangles the smaller box misses (the walk's own test, so every triangle that meets
 * the final box is kept: the box only shrinks, and the walk goes on with it). Each round
 * takes 3/4 of the smallest scale that still keeps every triangle, so at least the farthest
 * goes. GATHER_FULL when the box would fall below half the asked one (g->scale: the part
 * left): a dense spot under the body itself, where the scene path is the better one.
 * Out of line, with the box by value: the walk's loop must not pay for it. */
enum { GATHER_ADD, GATHER_SKIP, GATHER_FULL };
__attribute__((noinline)) static int gather_shrink(coll_gather_t *g, fm_vec3_t lo, fm_vec3_t hi, grid_walk_t *w,
                                                  const xf3_t *x, const fm_vec3_t *o_l)
{
    int r = GATHER_FULL;
    for (;;) {
        /* the scale of the box (relative to now) at which each triangle starts to meet it */
        float smax = 0.0f;
        for (int a = 0; a < 3; a++) {
            float h = g->hi.v[a];
            if (!(h > 0.0f)) return GATHER_FULL;
            float inv = 1.0f / h;
            smax = f_max(smax, f_max(-hi.v[a] * inv, lo.v[a] * inv));
            for (uint16_t k = 0; k < g->ntris; k++) {
                const coll_gather_tri_t *gt = &g->tris[k];
                smax = f_max(smax, f_max(-gt->hi.v[a] * inv, gt->lo.v[a] * inv));
            }
        }
        float f = 0.75f * f_min(smax, 1.0f);
        if (!(g->scale * f >= 0.5f)) return GATHER_FULL;
        g->scale *= f;
        for (int a = 0; a < 3; a++) {
            g->hi.v[a] *= f;
            g->lo.v[a] = -g->hi.v[a];
        }
        uint16_t n = 0;
        for (uint16_t k = 0; k < g->ntris; k++)
            if (box_meets(&g->tris[k].lo, &g->tris[k].hi, g)) g->tris[n++] = g->tris[k];
        g->ntris = n;
        if (!box_meets(&lo, &hi, g)) { r = GATHER_SKIP; break; }
        if (n < COLL_GATHER_MAX) { r = GATHER_ADD; break; }
    }
    /* the rest of the walk on the smaller box: its local box (local_box's for a box centred
     * on the origin; not a call to it, which the console build then outlined for both
     * callers) in the caller's llo / lhi, which w points to; the cells it misses skipped */
    fm_vec3_t hl = x->simple ? g->hi : mul3_abs(x->inv, &g->hi);
    fm_vec3_t *llo = (fm_vec3_t *)(uintptr_t)w->llo, *lhi = (fm_vec3_t *)(uintptr_t)w->lhi;
    for (int a = 0; a < 3; a++) {
        llo->v[a] = o_l->v[a] - hl.v[a] - w->m->grid_margin;
        lhi->v[a] = o_l->v[a] + hl.v[a] + w->m->grid_margin;
    }
    w->skip_missed = true;
    return r;
}

/* One axis of a kept triangle's box (first vertex w, the others w + a1, w + a2) into
 * *lo..*hi; true when it misses the gathered box glo..ghi on that axis. */
CAND_INLINE bool tri_axis_box(float w, float a1, float a2, float glo, float ghi, float *lo, float *hi)
{
    float v1 = w + a1, v2 = w + a2, v0 = w + 0.0f;
    float l = f_min(v0, f_min(v1, v2)), h = f_max(v0, f_max(v1, v2));
    *lo = l;
    *hi = h;
    return h < glo || l > ghi;
}

/* gather_walk's dedup mask: a register wide (a 64-bit mask on the 32-bit console costs
 * its shifts and ands twice over: stairs +0.75 %, platform +0.77 %; a 32-bit one on a
 * 64-bit host collides more on the Jolt scene's ~18 kept of ~70 listings: +1.5 %) */
#if UINTPTR_MAX > 0xFFFFFFFFu
typedef uint64_t dedup_mask_t;
#define DEDUP_BITS 6
#else
typedef uint32_t dedup_mask_t;
#define DEDUP_BITS 5
#endif

/* gather_walk's dedup on a hash collision: triangle t of inst kept after slot i (the first
 * kept with its hash; out of line: the walk's loop must not pay for it). */
__attribute__((noinline)) static bool kept_later(const coll_gather_t *g, uint32_t i, const coll_mesh_instance_t *inst,
                                                uint32_t t)
{
    for (uint32_t k = i + 1u; k < g->ntris; k++)
        if (g->tris[k].tri == (int32_t)t && g->tris[k].inst == inst) return true;
    return false;
}

/* The walk of one instance, with the mesh layout lay a constant at each call below (the
 * per-entry fetch then carries no flag tests) and, for the common instance (no rotation,
 * unit scale), simple a constant true (the kept triangle's relative form in straight
 * code); false when the buffer overflowed. The walk's box is kept in locals (blo, bhi:
 * reloaded only after gather_shrink, the one place that changes it), so the per-entry test
 * reads it from registers, not through the walk after each kept triangle's stores.
 *
 * coded (a dense grid with sub-cell codes, COLL_MESHF_RCODE): each cell entered gets the
 * quarters of the walk's box in it across X and Z (coll_mesh_quarter, the builder's
 * function): from its low side's quarter in the first cell of the walk's range on that
 * axis, else 0, to its high side's in the last, else 3 (in a cell between, the box covers
 * the whole cell; all four is a superset either way). An entry whose code shares no
 * quarter with them on either axis is rejected from its code byte alone: its triangle's
 * box (grown by the grid margin) lies wholly on one side of the walk's box on that axis
 * (the quarter is monotone), so the box test below would reject it too. The same
 * triangles, in the same order; the dedup sees only what passes the box test, as before.
 * A box shrunk during the walk keeps the quarters of the larger one (a superset). */
CAND_INLINE bool gather_walk(coll_gather_t *g, grid_walk_t *w, const coll_mesh_instance_t *inst, const xf3_t *x,
                             const fm_vec3_t *o_l, const bool dedup, const uint32_t lay, const bool simple,
                             const bool coded)
{
    /* The dedup (a triangle listed in several of the walk's cells is taken once, at its
     * first listing) against the triangles this walk kept, not the walk's table: a listing
     * is a repeat exactly when its triangle was kept (a repeat of one the box tests rejected
     * is rejected again by the same tests on the same values: the box only shrinks). mask
     * has the bit of each kept triangle's hash (DEDUP_BITS), at[h] the first kept with hash h (read
     * only under its bit: no table to clear, where the walk's cost 128 words a gather, ~210
     * console instructions); a listing whose bit is clear is new, one whose bit is set is
     * at[h]'s or else (a collision) looked up in the kept triangles. */
    uint8_t at[1u << DEDUP_BITS];
    dedup_mask_t mask = 0u;
    const coll_scene_t *scene = g->scene;
    fm_vec3_t blo = *w->llo, bhi = *w->lhi;
    fm_vec3_t glo = g->lo, ghi = g->hi; /* the gathered box (changed only by gather_shrink) */
    float ytop = g->ytop;
    coll_gather_tri_t spare;           /* a triangle that meets it with the buffer full */
    const coll_mesh_t *m = w->m;
    const uint8_t *codes = NULL;
    uint32_t qx0 = 0u, qx1 = 0u, qz0 = 0u, qz1 = 0u; /* the box's quarters in its first / last cells */
    if (coded) {
        codes = coll_mesh_codes(m);
        const float inv4 = 4.0f / m->cell_size;
        qx0 = coll_mesh_quarter(blo.x, m->grid_origin[0] + (float)(int32_t)w->clo[0] * m->cell_size, inv4);
        qx1 = coll_mesh_quarter(bhi.x, m->grid_origin[0] + (float)(int32_t)w->chi[0] * m->cell_size, inv4);
        qz0 = coll_mesh_quarter(blo.z, m->grid_origin[2] + (float)(int32_t)w->clo[2] * m->cell_size, inv4);
        qz1 = coll_mesh_quarter(bhi.z, m->grid_origin[2] + (float)(int32_t)w->chi[2] * m->cell_size, inv4);
    }
    while (grid_walk_next_cell(w)) {
        uint32_t qx = 0u, qz = 0u;
        if (coded) {
            qx = coll_mesh_quarter_bits(w->c[0] == w->clo[0] ? qx0 : 0u, w->c[0] == w->chi[0] ? qx1 : 3u);
            qz = coll_mesh_quarter_bits(w->c[2] == w->clo[2] ? qz0 : 0u, w->c[2] == w->chi[2] ? qz1 : 3u) << 4;
        }
        for (uint32_t k = w->k, kend = w->kend; k < kend; k++) {
            uint32_t t;
            fm_vec3_t v[3];
            if (coded) {
                uint32_t cd = codes[k];
                if (!(cd & qx) || !(cd & qz)) continue;
            }
            if (!grid_walk_take_box_o(w, lay, k, &t, v, &blo, &bhi, coded)) continue;
            const uint32_t th = (t * 2654435761u) >> (32 - DEDUP_BITS);
            const dedup_mask_t tb = (dedup_mask_t)1u << th;
            if (dedup && (mask & tb)) {
                const coll_gather_tri_t *kt = &g->tris[at[th]];
                if (kt->tri == (int32_t)t && kt->inst == inst) continue;
                if (kept_later(g, at[th], inst, t)) continue;
            }
            /* made in the next free slot (the scratch when the buffer is full): no copy */
            coll_gather_tri_t *gt = g->ntris < COLL_GATHER_MAX ? &g->tris[g->ntris] : &spare;
            if (simple) { /* tri_rel_of's expressions for an identity transform */
                fm_vec3_sub(&gt->w0, &v[0], o_l);
                fm_vec3_sub(&gt->e1, &v[1], &v[0]);
                fm_vec3_sub(&gt->e2, &v[2], &v[0]);
            } else {
                fm_vec3_t shape[3];
                tri_rel_of(v, x, o_l, &gt->w0, shape);
                gt->e1 = shape[1];
                gt->e2 = shape[2];
            }
            /* The triangle's box, then the box test on it: all three vertices below the
             * gathered box on an axis is their largest below it (tri_box_reject's test, for
             * finite coordinates), and the box is what the queries keep anyway. The first
             * vertex is w0 + 0 (the shape's first vertex; + 0.0f turns a -0 into +0, as
             * the sum always did). */
            bool out = tri_axis_box(gt->w0.x, gt->e1.x, gt->e2.x, glo.x, ghi.x, &gt->lo.x, &gt->hi.x) |
                       tri_axis_box(gt->w0.y, gt->e1.y, gt->e2.y, glo.y, ghi.y, &gt->lo.y, &gt->hi.y) |
                       tri_axis_box(gt->w0.z, gt->e1.z, gt->e2.z, glo.z, ghi.z, &gt->lo.z, &gt->hi.z);
            if (out) continue;
            if (gt == &spare) {
                /* too many: a smaller box around the same centre (queries outside it go to
                 * the scene), or when that would be too small, every query to the scene */
                int r = gather_shrink(g, spare.lo, spare.hi, w, x, o_l);
                /* (the kept triangles moved: their hashes again) */
                mask = 0u;
                for (uint16_t i = 0; i < g->ntris; i++) {
                    if (g->tris[i].inst != inst) continue;
                    const uint32_t h = ((uint32_t)g->tris[i].tri * 2654435761u) >> (32 - DEDUP_BITS);
                    if (!(mask & ((dedup_mask_t)1u << h))) at[h] = (uint8_t)i;
                    mask |= (dedup_mask_t)1u << h;
                }
                if (r == GATHER_FULL) {
                    STATS_ADD(scene, gather_overflows);
                    g->valid = false;
                    return false;
                }
                blo = *w->llo;
                bhi = *w->lhi;
                glo = g->lo;
                ghi = g->hi;
                if (r == GATHER_SKIP) continue;
                g->tris[g->ntris] = spare;
                gt = &g->tris[g->ntris];
            }
            if (!(mask & tb)) at[th] = (uint8_t)g->ntris;
            mask |= tb;
            g->ntris++;
            gt->inst = inst;
            gt->tri = (int32_t)t;
            gt->prep.ready = false; /* filled by the first exact test */
            ytop = f_max(ytop, gt->hi.y);
        }
    }
    g->ytop = ytop;
    return true;
}

void coll_gather_begin(coll_gather_t *g, const coll_scene_t *scene, fm_vec3_t lo, fm_vec3_t hi, uint8_t read_mask,
                       uint8_t types)
{
    g->scene = scene;
    g->read_mask = read_mask;
    g->types = types;
    g->ntris = 0;
    g->ytop = -FLT_MAX;
    g->valid = false;
    if (!scene || !vfin(&lo) || !vfin(&hi)) return;
    for (int a = 0; a < 3; a++) {
        g->origin.v[a] = 0.5f * (lo.v[a] + hi.v[a]);
        g->hi.v[a] = 0.5f * (hi.v[a] - lo.v[a]);
        g->lo.v[a] = -g->hi.v[a];
    }
    g->valid = true;
    g->scale = 1.0f;
    STATS_ADD(scene, gathers);
    if (!(types & COLL_TYPE_MESH)) return;
    /* (the walk's table is never used: gather_walk dedups on its own; ready, so that the
     * walk does not clear it) */
    seen_t seen;
    seen_init(&seen);
    seen.ready = true;
    for (uint16_t i = 0; i < scene->mesh_count; i++) {
        const coll_mesh_instance_t *inst = scene->meshes[i];
        if (!inst || !(inst->write_mask & read_mask)) continue;
        const coll_mesh_t *m = inst->mesh;
        xf3_t x;
        if (!m || m->ntris == 0 || !xf_prepare(&inst->xf, &x)) continue;
        fm_vec3_t o_l = to_local_point(&x, &inst->xf, m, &g->origin);
        fm_vec3_t llo, lhi;
        local_box(m, &x, &o_l, &g->lo, &g->hi, &llo, &lhi);
        grid_walk_t w;
        if (!grid_walk_box(&w, m, &llo, &lhi, &seen)) continue;
        const bool dd = w.dedup;
        w.dedup = false;
        /* the baker's small-mesh layouts (16-bit indices and refs; float or quantized
         * vertices) under an identity transform get their own loops (float: with the
         * sub-cell codes of a dense grid, or without: a hashed grid's), any other the
         * generic one */
        const uint32_t I16 = COLL_MESHF_IDX16 | COLL_MESHF_REF16;
        bool ok;
        uint32_t lay = grid_walk_layout(&w);
        bool coded = (m->flags & COLL_MESHF_RCODE) && !w.walk_all;
        if (lay == I16 && x.simple && coded) ok = gather_walk(g, &w, inst, &x, &o_l, dd, I16, true, true);
        else if (lay == I16 && x.simple) ok = gather_walk(g, &w, inst, &x, &o_l, dd, I16, true, false);
        else if (lay == (COLL_MESHF_QUANT | I16) && x.simple)
            ok = gather_walk(g, &w, inst, &x, &o_l, dd, COLL_MESHF_QUANT | I16, true, false);
        else ok = gather_walk(g, &w, inst, &x, &o_l, dd, lay, x.simple, coded);
        if (!ok) return;
    }
}

/* ------------------------------------------------------------------ the cache ------ */
#ifdef GATHER_CACHE_CHECK
void gather_cache_check(const coll_gather_t *g, const coll_scene_t *scene, fm_vec3_t lo, fm_vec3_t hi, uint8_t rm, uint8_t ty);
#endif

_Static_assert(COLL_GATHER_CACHE_TRIS <= 64, "a refill marks the step's triangles in a 64-bit mask");
_Static_assert(COLL_GATHER_CACHE_TRIS <= COLL_GATHER_MAX, "a gather from the cache never fills the buffer (emit_tri)");
_Static_assert(COLL_GATHER_CACHE_INSTANCES <= 255, "instance counts are 8-bit");

/* After a refill overflows, the next misses take the uncached gather without trying. */
#define CACHE_BACKOFF 8u

void coll_gather_cache_reset(coll_gather_cache_t *cache)
{
    if (!cache) return;
    cache->scene = NULL;
    cache->ninst = cache->ntris = 0;
    cache->valid = 0;
    cache->backoff = 0;
    cache->since = cache->wasted = 0;
    cache->hits = cache->fills = cache->overflows = 0;
}

/* The gathered box's centre and half size from lo..hi, as coll_gather_begin sets them. */
static inline void box_of(fm_vec3_t lo, fm_vec3_t hi, fm_vec3_t *origin, fm_vec3_t *glo, fm_vec3_t *ghi)
{
    for (int a = 0; a < 3; a++) {
        origin->v[a] = 0.5f * (lo.v[a] + hi.v[a]);
        ghi->v[a] = 0.5f * (hi.v[a] - lo.v[a]);
        glo->v[a] = -ghi->v[a];
    }
}

/* An instance coll_gather_begin walks: seen, on a mesh with triangles, a valid transform. */
static inline bool inst_walked(const coll_mesh_instance_t *inst, uint8_t read_mask, xf3_t *x)
{
    if (!inst || !(inst->write_mask & read_mask)) return false;
    const coll_mesh_t *m = inst->mesh;
    return m && m->ntris != 0 && xf_prepare(&inst->xf, x);
}

/* The cache's slot of triangle t among the ones kept so far for this instance (a small
 * open-addressed table, slot + 1, 0 empty), or the place to put it. */
#define FILL_HASH_BITS 7
CAND_INLINE uint32_t fill_probe(const uint8_t *tab, const coll_gather_cache_t *c, uint32_t t)
{
    uint32_t h = (t * 2654435761u) >> (32 - FILL_HASH_BITS);
    while (tab[h] != 0u && c->tris[tab[h] - 1u].tri != t) h = (h + 1u) & ((1u << FILL_HASH_BITS) - 1u);
    return h;
}

/* The step's side of a refill's walk of one instance: the gather being made (its box,
 * origin), the instance, its transform and the step's local origin and box, and the step's
 * cells as bits of the refill's (0: the step's box misses the mesh). */
typedef struct {
    coll_gather_t *g;
    const coll_mesh_instance_t *inst;
    const xf3_t *x;
    fm_vec3_t o_l, llo, lhi;
    uint64_t cells;
} fill_step_t;

/* Appends cached triangle ct to the step's gather when its relative form's box meets the
 * gathered box (gather_walk's expressions, on tri_rel_of's local differences). */
CAND_INLINE void emit_tri(coll_gather_t *g, const coll_gather_cache_tri_t *ct, const coll_mesh_instance_t *inst,
                          const xf3_t *x, const fm_vec3_t *o_l)
{
    /* made in the next slot, as gather_walk does (the cache holds COLL_GATHER_CACHE_TRIS,
     * fewer than the buffer: there is room) */
    coll_gather_tri_t *gt = &g->tris[g->ntris];
    if (x->simple) {
        fm_vec3_sub(&gt->w0, &ct->v0, o_l);
        gt->e1 = ct->d1;
        gt->e2 = ct->d2;
    } else {
        fm_vec3_t d;
        fm_vec3_sub(&d, &ct->v0, o_l);
        gt->w0 = mul3(x->m, &d);
        gt->e1 = mul3(x->m, &ct->d1);
        gt->e2 = mul3(x->m, &ct->d2);
    }
    bool out = tri_axis_box(gt->w0.x, gt->e1.x, gt->e2.x, g->lo.x, g->hi.x, &gt->lo.x, &gt->hi.x) |
               tri_axis_box(gt->w0.y, gt->e1.y, gt->e2.y, g->lo.y, g->hi.y, &gt->lo.y, &gt->hi.y) |
               tri_axis_box(gt->w0.z, gt->e1.z, gt->e2.z, g->lo.z, g->hi.z, &gt->lo.z, &gt->hi.z);
    if (out) return;
    g->ntris++;
    gt->inst = inst;
    gt->tri = (int32_t)ct->tri;
    gt->prep.ready = false; /* filled by the first exact test */
    g->ytop = f_max(g->ytop, gt->hi.y);
}

/* A cached triangle's local box meets a local box (tri_box_reject's test: all three
 * vertices below (above) the box on an axis is their largest below (smallest above) it). */
CAND_INLINE bool ctri_meets(const coll_gather_cache_tri_t *ct, const fm_vec3_t *llo, const fm_vec3_t *lhi)
{
    return !(ct->bhi.x < llo->x || ct->blo.x > lhi->x || ct->bhi.z < llo->z || ct->blo.z > lhi->z ||
             ct->bhi.y < llo->y || ct->blo.y > lhi->y);
}

/* One instance's walk of a refill (the layout a constant at each call, as gather_walk):
 * every listing of a triangle whose box meets the walk's box sets its cell's bit; a new one
 * takes the next slot and its place in order[] by triangle index. The same walk makes the
 * step's gather: the step's cells are some of the refill's, entered in the same order, so
 * a triangle listed in one of them that meets the step's local box is the step's at its
 * first such listing, exactly where the step's own walk would take it. False: the cache is
 * full. */
CAND_INLINE bool fill_walk(coll_gather_cache_t *c, grid_walk_t *w, uint32_t *np, uint32_t first, fill_step_t *st,
                           const uint32_t lay)
{
    uint8_t tab[1u << FILL_HASH_BITS];
    memset(tab, 0, sizeof(tab));
    uint64_t emitted = 0u;
    uint32_t n = *np;
    const uint32_t nx = w->chi[0] - w->clo[0] + 1u, ny = w->chi[1] - w->clo[1] + 1u;
    const fm_vec3_t blo = *w->llo, bhi = *w->lhi;
    while (grid_walk_next_cell(w)) {
        const uint64_t bit = 1ull << (((w->c[2] - w->clo[2]) * ny + (w->c[1] - w->clo[1])) * nx + (w->c[0] - w->clo[0]));
        const bool in_step = (bit & st->cells) != 0u;
        for (uint32_t k = w->k, kend = w->kend; k < kend; k++) {
            uint32_t t;
            fm_vec3_t v[3];
            if (!grid_walk_take_box(w, lay, k, &t, v, &blo, &bhi)) continue;
            uint32_t h = fill_probe(tab, c, t), slot;
            if (tab[h] != 0u) {
                slot = tab[h] - 1u;
                c->tris[slot].cells |= bit;
            } else {
                if (n >= COLL_GATHER_CACHE_TRIS) return false;
                slot = n;
                tab[h] = (uint8_t)(n + 1u);
                coll_gather_cache_tri_t *ct = &c->tris[n];
                ct->v0 = v[0];
                fm_vec3_sub(&ct->d1, &v[1], &v[0]); /* tri_rel_of's local differences */
                fm_vec3_sub(&ct->d2, &v[2], &v[0]);
                for (int a = 0; a < 3; a++) {
                    ct->blo.v[a] = f_min(v[0].v[a], f_min(v[1].v[a], v[2].v[a]));
                    ct->bhi.v[a] = f_max(v[0].v[a], f_max(v[1].v[a], v[2].v[a]));
                }
                ct->tri = t;
                ct->cells = bit;
                /* its place by triangle index (a cell lists its triangles in order: mostly last) */
                uint32_t j = n;
                while (j > first && c->tris[c->order[j - 1u]].tri > t) {
                    c->order[j] = c->order[j - 1u];
                    j--;
                }
                c->order[j] = (uint8_t)n;
                n++;
            }
            const uint64_t sb = 1ull << slot;
            if (!in_step || (emitted & sb)) continue;
            const coll_gather_cache_tri_t *ct = &c->tris[slot];
            if (!ctri_meets(ct, &st->llo, &st->lhi)) continue;
            emitted |= sb; /* (the step's walk takes a triangle once: its dedup) */
            emit_tri(st->g, ct, st->inst, st->x, &st->o_l);
        }
    }
    *np = n;
    return true;
}

/* The step's local box under instance x (local_box's expressions; an identity transform's
 * inline). */
CAND_INLINE void step_local_box(const coll_mesh_t *m, const xf3_t *x, const fm_vec3_t *o_l, const coll_gather_t *g,
                                fm_vec3_t *llo, fm_vec3_t *lhi)
{
    if (x->simple) {
        float mg = m->grid_margin;
        for (int a = 0; a < 3; a++) {
            float cc = 0.5f * (g->lo.v[a] + g->hi.v[a]), h = 0.5f * (g->hi.v[a] - g->lo.v[a]);
            llo->v[a] = o_l->v[a] + cc - h - mg;
            lhi->v[a] = o_l->v[a] + cc + h + mg;
        }
    } else local_box(m, x, o_l, &g->lo, &g->hi, llo, lhi);
}

/* The step's cells (grid_walk_box's, for its local box llo..lhi), as bits of the cells
 * ci walked; 0 when the box misses the mesh. Its box lies inside ci's (the caller checks),
 * so its cells lie inside ci's: cell coordinates are monotone. */
CAND_INLINE uint64_t step_cells(const coll_mesh_t *m, const coll_gather_cache_inst_t *ci, const fm_vec3_t *llo,
                                const fm_vec3_t *lhi)
{
    if (ci->clo[0] == ci->chi[0] && ci->clo[1] == ci->chi[1] && ci->clo[2] == ci->chi[2]) {
        bool misses = false; /* instance_cells' test; the one cell is the fill's */
        for (int a = 0; a < 3; a++) misses |= lhi->v[a] < m->bmin[a] || llo->v[a] > m->bmax[a];
        return misses ? 0u : 1u;
    }
    uint32_t clo[3], chi[3];
    if (!instance_cells(m, llo, lhi, clo, chi)) return 0u;
    uint32_t nx = ci->chi[0] - ci->clo[0] + 1u, ny = ci->chi[1] - ci->clo[1] + 1u;
    uint64_t row = ((2ull << (chi[0] - clo[0])) - 1u) << (clo[0] - ci->clo[0]), cells = 0u;
    for (uint32_t z = clo[2]; z <= chi[2]; z++)
        for (uint32_t y = clo[1]; y <= chi[1]; y++) cells |= row << (((z - ci->clo[2]) * ny + (y - ci->clo[1])) * nx);
    return cells;
}

/* Refills the cache with the mesh-local triangles of the world box lo..hi: each walked
 * instance's local box (coll_gather_begin's) and its grid cells (at most 64 of them), every
 * triangle a cell under it lists whose box meets it (the walk's own test), with the cells
 * that list it, ordered by triangle index within the instance; and makes the step's gather
 * g (its head set) on the way (fill_walk). False when the triangles are more than the cache
 * holds, or the step's box is not inside the refill's (rounding): g is then not usable. */
static bool cache_fill(coll_gather_cache_t *c, const coll_scene_t *scene, fm_vec3_t lo, fm_vec3_t hi,
                       uint8_t read_mask, coll_gather_t *g)
{
    c->valid = 0;
    c->scene = scene;
    c->ntris = 0;
    c->ninst = (uint8_t)scene->mesh_count;
    fm_vec3_t origin, glo, ghi;
    box_of(lo, hi, &origin, &glo, &ghi);
    seen_t seen;
    seen_init(&seen);
    uint32_t n = 0;
    for (uint16_t i = 0; i < scene->mesh_count; i++) {
        const coll_mesh_instance_t *inst = scene->meshes[i];
        coll_gather_cache_inst_t *ci = &c->inst[i];
        ci->inst = inst;
        ci->mesh = inst ? inst->mesh : NULL;
        ci->walked = 0;
        ci->first = (uint8_t)n;
        ci->count = 0;
        xf3_t x;
        if (!inst_walked(inst, read_mask, &x)) continue;
        const coll_mesh_t *m = inst->mesh;
        fm_vec3_t o_l = to_local_point(&x, &inst->xf, m, &origin);
        local_box(m, &x, &o_l, &glo, &ghi, &ci->llo, &ci->lhi);
        ci->walked = 1;
        fill_step_t st;
        st.g = g;
        st.inst = inst;
        st.x = &x;
        st.o_l = to_local_point(&x, &inst->xf, m, &g->origin);
        step_local_box(m, &x, &st.o_l, g, &st.llo, &st.lhi);
        for (int a = 0; a < 3; a++)
            if (!(st.llo.v[a] >= ci->llo.v[a]) || !(st.lhi.v[a] <= ci->lhi.v[a])) return false;
        grid_walk_t w;
        if (!grid_walk_box(&w, m, &ci->llo, &ci->lhi, &seen)) {
            ci->clo[0] = ci->clo[1] = ci->clo[2] = 1u; /* no cells: a box inside it misses the mesh too */
            ci->chi[0] = ci->chi[1] = ci->chi[2] = 0u;
            continue;
        }
        uint32_t nx = w.chi[0] - w.clo[0] + 1u, ny = w.chi[1] - w.clo[1] + 1u, nz = w.chi[2] - w.clo[2] + 1u;
        if (w.walk_all || (uint64_t)nx * ny * nz > 64u) return false;
        for (int a = 0; a < 3; a++) {
            ci->clo[a] = w.clo[a];
            ci->chi[a] = w.chi[a];
        }
        st.cells = step_cells(m, ci, &st.llo, &st.lhi);
        w.dedup = false; /* every listing is wanted: its cell's bit */
        const uint32_t I16 = COLL_MESHF_IDX16 | COLL_MESHF_REF16;
        uint32_t lay = grid_walk_layout(&w);
        bool ok;
        if (lay == I16 && x.simple) ok = fill_walk(c, &w, &n, ci->first, &st, I16);
        else ok = fill_walk(c, &w, &n, ci->first, &st, lay);
        if (!ok) return false;
        ci->count = (uint8_t)(n - ci->first);
    }
    c->ntris = (uint8_t)n;
    c->valid = 1;
    return true;
}

/* The step's gather from the cache: per instance, coll_gather_begin's transform, local
 * origin, local box and grid cells, then the cached triangles listed in one of those cells
 * through the walk's local box test and the gather's relative form and box test
 * (gather_walk's expressions). False, with g not usable, when the cache does not cover the
 * box (a refill is needed). */
static bool gather_from_cache(coll_gather_t *g, const coll_gather_cache_t *c)
{
    const coll_scene_t *scene = g->scene;
    if (!c->valid || c->scene != scene || c->ninst != scene->mesh_count) return false;
    g->ntris = 0;
    g->ytop = -FLT_MAX;
    for (uint16_t i = 0; i < scene->mesh_count; i++) {
        const coll_mesh_instance_t *inst = scene->meshes[i];
        const coll_gather_cache_inst_t *ci = &c->inst[i];
        if (ci->inst != inst) return false;
        xf3_t x;
        if (!inst_walked(inst, g->read_mask, &x)) continue;
        const coll_mesh_t *m = inst->mesh;
        if (!ci->walked || ci->mesh != m) return false;
        fm_vec3_t o_l = to_local_point(&x, &inst->xf, m, &g->origin);
        fm_vec3_t llo, lhi;
        step_local_box(m, &x, &o_l, g, &llo, &lhi);
        for (int a = 0; a < 3; a++)
            if (!(llo.v[a] >= ci->llo.v[a]) || !(lhi.v[a] <= ci->lhi.v[a])) return false;
        if (ci->count == 0u) continue;
        uint64_t cells = step_cells(m, ci, &llo, &lhi);
        if (!cells) continue;
        /* The walk's candidates in the walk's order: the walk enters the cells in the order
         * of their bits (x fastest, then y, then z, in the fill's cells as in its own) and
         * a cell lists its triangles by index, so a triangle comes at the first of its
         * cells the walk enters (the dedup drops the later ones), by index within it. The
         * cached triangles are by index: a stable sort on that first cell's bit. */
        uint64_t key[COLL_GATHER_CACHE_TRIS];
        uint8_t idx[COLL_GATHER_CACHE_TRIS];
        uint32_t nk = 0;
        for (uint32_t k = ci->first, kend = k + ci->count; k < kend; k++) {
            const coll_gather_cache_tri_t *ct = &c->tris[c->order[k]];
            uint64_t in = ct->cells & cells;
            if (!in || !ctri_meets(ct, &llo, &lhi)) continue;
            uint64_t kb = in & (0u - in); /* the first cell's bit */
            uint32_t j = nk++;
            for (; j > 0u && key[j - 1u] > kb; j--) {
                key[j] = key[j - 1u];
                idx[j] = idx[j - 1u];
            }
            key[j] = kb;
            idx[j] = c->order[k];
        }
        for (uint32_t j = 0; j < nk; j++) emit_tri(g, &c->tris[idx[j]], inst, &x, &o_l);
    }
    return true;
}

/* The cache can serve a gather of this scene and types at all. */
static inline bool cache_usable(const coll_gather_cache_t *cache, const coll_scene_t *scene, fm_vec3_t lo,
                                fm_vec3_t hi, uint8_t types)
{
    return cache && scene && (types & COLL_TYPE_MESH) && scene->mesh_count <= COLL_GATHER_CACHE_INSTANCES &&
           vfin(&lo) && vfin(&hi);
}

static inline void gather_head(coll_gather_t *g, const coll_scene_t *scene, fm_vec3_t lo, fm_vec3_t hi,
                               uint8_t read_mask, uint8_t types)
{
    g->scene = scene;
    g->read_mask = read_mask;
    g->types = types;
    g->ntris = 0;
    g->ytop = -FLT_MAX;
    g->valid = true;
    g->scale = 1.0f;
    box_of(lo, hi, &g->origin, &g->lo, &g->hi);
}

bool coll_gather_from_cache(coll_gather_t *g, coll_gather_cache_t *cache, const coll_scene_t *scene, fm_vec3_t lo,
                            fm_vec3_t hi, uint8_t read_mask, uint8_t types)
{
    if (!cache_usable(cache, scene, lo, hi, types) || !cache->valid) return false;
    gather_head(g, scene, lo, hi, read_mask, types);
    if (!gather_from_cache(g, cache)) return false;
    cache->hits++;
    if (cache->since < 255u) cache->since++;
    STATS_ADD(scene, gathers);
#ifdef GATHER_CACHE_CHECK
    gather_cache_check(g, scene, lo, hi, read_mask, types);
#endif
    return true;
}

void coll_gather_refill(coll_gather_t *g, coll_gather_cache_t *cache, const coll_scene_t *scene, fm_vec3_t lo,
                        fm_vec3_t hi, fm_vec3_t flo, fm_vec3_t fhi, uint8_t read_mask, uint8_t types)
{
    if (!cache_usable(cache, scene, lo, hi, types)) {
        coll_gather_begin(g, scene, lo, hi, read_mask, types);
        return;
    }
    if (cache->backoff) {
        cache->backoff--;
        coll_gather_begin(g, scene, lo, hi, read_mask, types);
        return;
    }
    /* a refill costs about twice a gather: after refills that served no other step (a body
     * riding a fast turntable, the level turning under it) the next misses take the
     * uncached gather, 4, 8, then 16 of them */
    if (cache->valid && cache->since == 0u) {
        if (cache->wasted < 3u) cache->wasted++;
        cache->valid = 0;
        cache->backoff = (uint8_t)((2u << cache->wasted) - 1u);
        coll_gather_begin(g, scene, lo, hi, read_mask, types);
        return;
    }
    if (cache->since) cache->wasted = 0;
    cache->since = 0;
    for (int a = 0; a < 3; a++) {
        flo.v[a] = f_min(flo.v[a], lo.v[a]);
        fhi.v[a] = f_max(fhi.v[a], hi.v[a]);
    }
    gather_head(g, scene, lo, hi, read_mask, types);
    if (!vfin(&flo) || !vfin(&fhi) || !cache_fill(cache, scene, flo, fhi, read_mask, g)) {
        cache->valid = 0;
        cache->overflows++;
        cache->backoff = CACHE_BACKOFF;
        coll_gather_begin(g, scene, lo, hi, read_mask, types);
        return;
    }
    cache->fills++;
    STATS_ADD(scene, gathers);
#ifdef GATHER_CACHE_CHECK
    gather_cache_check(g, scene, lo, hi, read_mask, types);
#endif
}

void coll_gather_begin_cached(coll_gather_t *g, coll_gather_cache_t *cache, const coll_scene_t *scene, fm_vec3_t lo,
                              fm_vec3_t hi, fm_vec3_t flo, fm_vec3_t fhi, uint8_t read_mask, uint8_t types)
{
    if (!coll_gather_from_cache(g, cache, scene, lo, hi, read_mask, types))
        coll_gather_refill(g, cache, scene, lo, hi, flo, fhi, read_mask, types);
}

/* Debug aid: built with -DGATHER_CACHE_CHECK, every gather made through a cache is
 * compared with a fresh one (the same triangles, in order, bit for bit; stderr). */
#ifdef GATHER_CACHE_CHECK
#include <stdio.h>
#include <string.h>
void gather_cache_check(const coll_gather_t *g, const coll_scene_t *scene, fm_vec3_t lo, fm_vec3_t hi, uint8_t rm, uint8_t ty);
void gather_cache_check(const coll_gather_t *g, const coll_scene_t *scene, fm_vec3_t lo, fm_vec3_t hi, uint8_t rm, uint8_t ty)
{
    static coll_gather_t f;
    coll_gather_begin(&f, scene, lo, hi, rm, ty);
    int bad = f.ntris != g->ntris;
    for (int i = 0; i < f.ntris && !bad; i++)
        if (g->tris[i].inst != f.tris[i].inst || g->tris[i].tri != f.tris[i].tri) bad = 4;
    for (int i = 0; i < f.ntris && !bad; i++) {
        int found = 0;
        for (int j = 0; j < g->ntris; j++)
            if (g->tris[j].inst == f.tris[i].inst && g->tris[j].tri == f.tris[i].tri) {
                found = 1;
                if (memcmp(&g->tris[j].w0, &f.tris[i].w0, 5 * sizeof(fm_vec3_t))) { bad = 2; fprintf(stderr, "w0 %g %g\n", (double)g->tris[j].w0.x, (double)f.tris[i].w0.x);}
            }
        if (!found) bad = 3;
    }
    if (bad) {
        fprintf(stderr, "GATHER CACHE MISMATCH %d: fresh %d cached %d\n", bad, f.ntris, g->ntris);
        for (int i = 0; i < f.ntris; i++) fprintf(stderr, " f %p %d\n", (const void *)f.tris[i].inst, (int)f.tris[i].tri);
        for (int i = 0; i < g->ntris; i++) fprintf(stderr, " c %p %d\n", (const void *)g->tris[i].inst, (int)g->tris[i].tri);
    }
}
#endif
