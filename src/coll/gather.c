/**
 * @file gather.c
 * @brief The step gather (gather.h): one walk of the grid cells under a character step's
 *        box (grid_walk.h), keeping the triangles that meet it in query-relative form. The
 *        queries on the gathered triangles are in query.c, beside the scene's.
 */
#include "vec3.h"
#include "gather.h"
#include "grid_walk.h"

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

/* The walk of one instance, with the mesh layout lay a constant at each call below (the
 * per-entry fetch then carries no flag tests) and, for the common instance (no rotation,
 * unit scale), simple a constant true (the kept triangle's relative form in straight
 * code); false when the buffer overflowed. The walk's box is kept in locals (blo, bhi:
 * reloaded only after gather_shrink, the one place that changes it), so the per-entry test
 * reads it from registers, not through the walk after each kept triangle's stores. */
CAND_INLINE bool gather_walk(coll_gather_t *g, grid_walk_t *w, const coll_mesh_instance_t *inst, const xf3_t *x,
                             const fm_vec3_t *o_l, seen_t *seen, const uint32_t lay, const bool simple)
{
    const coll_scene_t *scene = g->scene;
    fm_vec3_t blo = *w->llo, bhi = *w->lhi;
    while (grid_walk_next_cell(w))
        for (uint32_t k = w->k, kend = w->kend; k < kend; k++) {
            uint32_t t;
            fm_vec3_t w0, e1, e2, v[3], lo, hi;
            if (!grid_walk_take_box(w, lay, k, &t, v, &blo, &bhi)) continue;
            if (simple) { /* tri_rel_of's expressions for an identity transform */
                fm_vec3_sub(&w0, &v[0], o_l);
                fm_vec3_sub(&e1, &v[1], &v[0]);
                fm_vec3_sub(&e2, &v[2], &v[0]);
            } else {
                fm_vec3_t shape[3];
                tri_rel_of(v, x, o_l, &w0, shape);
                e1 = shape[1];
                e2 = shape[2];
            }
            /* The triangle's box, then the box test on it: all three vertices below the
             * gathered box on an axis is their largest below it (tri_box_reject's test, for
             * finite coordinates), and the box is what the queries keep anyway. The first
             * vertex is w0 + 0 (the shape's first vertex; + 0.0f turns a -0 into +0, as
             * the sum always did). */
            bool out = tri_axis_box(w0.x, e1.x, e2.x, g->lo.x, g->hi.x, &lo.x, &hi.x) |
                       tri_axis_box(w0.y, e1.y, e2.y, g->lo.y, g->hi.y, &lo.y, &hi.y) |
                       tri_axis_box(w0.z, e1.z, e2.z, g->lo.z, g->hi.z, &lo.z, &hi.z);
            if (out) continue;
            if (g->ntris >= COLL_GATHER_MAX) {
                /* too many: a smaller box around the same centre (queries outside it go to
                 * the scene), or when that would be too small, every query to the scene */
                int r = gather_shrink(g, lo, hi, w, x, o_l);
                if (r == GATHER_FULL) {
                    STATS_ADD(scene, gather_overflows);
                    g->valid = false;
                    seen_clear(seen);
                    return false;
                }
                blo = *w->llo;
                bhi = *w->lhi;
                if (r == GATHER_SKIP) continue;
            }
            coll_gather_tri_t *gt = &g->tris[g->ntris++];
            gt->w0 = w0;
            gt->e1 = e1;
            gt->e2 = e2;
            gt->lo = lo;
            gt->hi = hi;
            gt->inst = inst;
            gt->tri = (int32_t)t;
            gt->prep.ready = false; /* filled by the first exact test */
        }
    return true;
}

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
    g->scale = 1.0f;
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
        grid_walk_t w;
        if (!grid_walk_box(&w, m, &llo, &lhi, &seen)) continue;
        /* the baker's small-mesh layouts (16-bit indices and refs; float or quantized
         * vertices) under an identity transform get their own loops, any other the
         * generic one */
        const uint32_t I16 = COLL_MESHF_IDX16 | COLL_MESHF_REF16;
        bool ok;
        uint32_t lay = grid_walk_layout(&w);
        if (lay == I16 && x.simple) ok = gather_walk(g, &w, inst, &x, &o_l, &seen, I16, true);
        else if (lay == (COLL_MESHF_QUANT | I16) && x.simple)
            ok = gather_walk(g, &w, inst, &x, &o_l, &seen, COLL_MESHF_QUANT | I16, true);
        else ok = gather_walk(g, &w, inst, &x, &o_l, &seen, lay, x.simple);
        if (!ok) return;
        grid_walk_end(&w, scene);
    }
}
