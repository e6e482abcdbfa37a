/**
 * @file query.c
 * @brief Scene queries: raycast (3D DDA through each instance's grid), capsule sweep and
 *        capsule overlaps (grid cells under the swept box), all exact and allocation-free;
 *        the same three on a step's gathered triangles (gather.h). The candidates come from
 *        one walk (grid_walk.h); each query's per-triangle test and its best hit are
 *        shared by both sources.
 */
#include "vec3.h"
#include "coll/scene.h"
#include "gather.h"
#include "grid_walk.h"
#include "prim.h"

/* ---------------------------------------------------------------- one-way ------- */

/* A one-way instance's up (local +Y in world orientation); zero for an ordinary instance,
 * which every test below then lets through. */
static fm_vec3_t one_way_up_rotated(const coll_mesh_instance_t *inst)
{
    fm_vec3_t u = {{0.0f, 0.0f, 0.0f}};
    fm_vec3_t y = {{0.0f, 1.0f, 0.0f}};
    fm_quat_t q = inst->xf.rot;
    fm_quat_norm(&q, &q);
    fm_quat_rotate_vec3(&u, &q, &y);
    return u;
}

/* (inline: the gathered queries ask once per triangle; nearly every instance is ordinary) */
CAND_INLINE fm_vec3_t one_way_up(const coll_mesh_instance_t *inst)
{
    if (inst->flags & COLL_INSTANCE_ONE_WAY) return one_way_up_rotated(inst);
    fm_vec3_t u = {{0.0f, 0.0f, 0.0f}};
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
    float d = f_min(fm_vec3_dot(&seg[0], &n), fm_vec3_dot(&seg[1], &n));
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

/* ------------------------------------------------------------------ raycast -------- */

/* The best hit of a query so far, one record for rays (best: the nearest distance) and
 * sweeps (best: the earliest fraction of the displacement), mesh triangles and bodies. */
typedef struct {
    bool have;
    float best;
    coll_prim_hit_t ph;
    const coll_mesh_instance_t *inst;
    const coll_body_t *body;
    int32_t tri;
} best_hit_t;

CAND_INLINE void best_init(best_hit_t *b, float limit)
{
    /* field by field (a memset call per query on the console); ph is read only once have */
    b->have = false;
    b->best = limit;
    b->ph.t = 0.0f;
    b->ph.depth = 0.0f;
    b->ph.normal.x = b->ph.normal.y = b->ph.normal.z = 0.0f;
    b->ph.point.x = b->ph.point.y = b->ph.point.z = 0.0f;
    b->inst = NULL;
    b->body = NULL;
    b->tri = -1;
}

/* ph (relative to the query origin) is the new best hit. */
static void best_take(best_hit_t *b, const coll_prim_hit_t *ph, const coll_mesh_instance_t *inst, const coll_body_t *body,
                      int32_t tri)
{
    b->have = true;
    b->best = ph->t;
    b->ph = *ph;
    b->inst = inst;
    b->body = body;
    b->tri = tri;
}

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

/* Mesh-local box of the ray piece o_l + d_l s, s in [s0, s1], grown by the grid margin
 * plus the rounding of the local ray itself: a triangle outside it cannot be hit. */
static void ray_local_box(const fm_vec3_t *o_l, const fm_vec3_t *d_l, float s0, float s1, float mg,
                          fm_vec3_t *lo, fm_vec3_t *hi)
{
    for (int a = 0; a < 3; a++) {
        float p0 = o_l->v[a] + d_l->v[a] * s0, p1 = o_l->v[a] + d_l->v[a] * s1;
        float slack = mg + 1e-6f * (fabsf(p0) + fabsf(p1) + fabsf(o_l->v[a]));
        lo->v[a] = f_min(p0, p1) - slack;
        hi->v[a] = f_max(p0, p1) + slack;
    }
}

/* One candidate triangle t of inst against the ray (its shear sh: coll_ray_shear, once per
 * ray): first vertex w0 relative to the ray's origin, shape with shape[0] = 0 (the scene
 * walk's; the gathered scan has its own, with the triangles' preps). */
static void ray_tri(const coll_mesh_instance_t *inst, int32_t t, const fm_vec3_t *w0, const fm_vec3_t shape[3],
                    const fm_vec3_t *dir, const coll_ray_shear_t *sh, best_hit_t *rb)
{
    if (!sh) return;
    fm_vec3_t o;
    coll_prim_hit_t ph;
    fm_vec3_negate(&o, w0);
    fm_vec3_t u = one_way_up(inst);
    if (!one_way_ray(&u, shape, &o, dir)) return;
    if (coll_ray_triangle_sheared(&o, dir, sh, shape, rb->best, NULL, &ph) && (!rb->have || ph.t < rb->best)) {
        fm_vec3_add(&ph.point, &ph.point, w0);
        best_take(rb, &ph, inst, NULL, t);
    }
}

static void ray_instance(const coll_scene_t *scene, const coll_mesh_instance_t *inst, const fm_vec3_t *origin,
                         const fm_vec3_t *dir, const coll_ray_shear_t *sh, seen_t *seen, best_hit_t *rb)
{
    const coll_mesh_t *m = inst->mesh;
    xf3_t x;
    if (!m || m->ntris == 0 || !xf_prepare(&inst->xf, &x)) return;
    fm_vec3_t o_l = to_local_point(&x, &inst->xf, m, origin);
    fm_vec3_t d_l = to_local_dir(&x, dir);
    float mg = m->grid_margin; /* the builder's registration margin (format version 3) */
    float lo[3], hi[3];
    for (int a = 0; a < 3; a++) { lo[a] = m->bmin[a] - mg; hi[a] = m->bmax[a] + mg; }
    float s0 = 0.0f, s1 = rb->best;
    if (!clip_box(&o_l, &d_l, lo, hi, &s0, &s1)) return;

    /* 3D DDA from the entry point. */
    fm_vec3_t rlo, rhi;
    float box_end = rb->best;
    ray_local_box(&o_l, &d_l, s0, box_end, mg, &rlo, &rhi);
    float cs = m->cell_size, inv_cs = 1.0f / cs;
    uint32_t c[3];
    int step[3];
    float inv_d[3];
    for (int a = 0; a < 3; a++) {
        float p = o_l.v[a] + d_l.v[a] * s0;
        c[a] = coll_mesh_cell_coord(p, m->grid_origin[a], inv_cs, m->dims[a]);
        step[a] = d_l.v[a] > 0.0f ? 1 : (d_l.v[a] < 0.0f ? -1 : 0);
        inv_d[a] = step[a] ? 1.0f / d_l.v[a] : 0.0f;
    }
    grid_walk_t w;
    grid_walk_cells(&w, m, &rlo, &rhi, seen);
    for (;;) {
        grid_walk_enter(&w, c[0], c[1], c[2]);
        for (uint32_t k = w.k; k < w.kend; k++) {
            if (rb->best < box_end) { /* the nearest hit shrank the ray: shrink its box */
                box_end = rb->best;
                ray_local_box(&o_l, &d_l, s0, box_end, mg, &rlo, &rhi);
            }
            uint32_t t;
            fm_vec3_t v[3], tri[3], w0;
            if (!grid_walk_take(&w, k, &t, v)) continue;
            tri_rel_of(v, &x, &o_l, &w0, tri);
            ray_tri(inst, (int32_t)t, &w0, tri, dir, sh, rb);
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
    grid_walk_end(&w, scene);
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
                       best_hit_t *rb)
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
        if (coll_ray_body(&zero, dir, b, &rel, rb->best, &ph) && (!rb->have || ph.t < rb->best))
            best_take(rb, &ph, NULL, b, -1);
    }
}

static bool ray_result(const best_hit_t *rb, const fm_vec3_t *origin, coll_ray_hit_t *hit)
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

CAND_INLINE bool ray_args_ok(const fm_vec3_t *origin, const fm_vec3_t *dir, float max_dist)
{
    return vfin(origin) && vfin(dir) && f_isfin(max_dist) && max_dist > 0.0f && fm_vec3_len2(dir) > 0.0f;
}

bool coll_raycast(const coll_scene_t *scene, fm_vec3_t origin, fm_vec3_t dir, float max_dist,
                  uint8_t read_mask, uint8_t coll_types, coll_ray_hit_t *hit)
{
    if (!scene || !ray_args_ok(&origin, &dir, max_dist)) return false;
    STATS_ADD(scene, queries);
    best_hit_t rb;
    best_init(&rb, max_dist);
    seen_t seen;
    if (coll_types & COLL_TYPE_MESH) {
        coll_ray_shear_t shear;
        const coll_ray_shear_t *sh = coll_ray_shear(&dir, &shear) ? &shear : NULL; /* NULL: no triangle is hit */
        seen_init(&seen);
        for (uint16_t i = 0; i < scene->mesh_count; i++) {
            const coll_mesh_instance_t *inst = scene->meshes[i];
            if (inst && (inst->write_mask & read_mask)) ray_instance(scene, inst, &origin, &dir, sh, &seen, &rb);
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

/* World-relative AABB of the capsule swept from 0 to t. Without a branch (the console has
 * no conditional moves; this runs for every query): the axis ends are -e and e
 * (capsule_setup), so their least and largest are -|e| and |e|, and min(d, 0) and max(d, 0)
 * are d/2 -+ |d|/2 (exact: halving and the sum are; a zero's sign, the only difference
 * from f_min/f_max, is lost in adding r). */
CAND_INLINE void swept_box(const capsule_q_t *q, float t, fm_vec3_t *lo, fm_vec3_t *hi)
{
    for (int a = 0; a < 3; a++) {
        float d = q->disp.v[a] * t, e = fabsf(q->seg[1].v[a]);
        float h = 0.5f * d, ha = 0.5f * fabsf(d);
        lo->v[a] = -e + (h - ha) - q->r - q->eps;
        hi->v[a] = e + (h + ha) + q->r + q->eps;
    }
}

/* One mesh instance's part of a capsule query: its transform, one-way up, the capsule's
 * centre in mesh space, and the box of the capsule swept to t (world-relative and local,
 * where the walk reads it: the sweep shrinks it in place as hits come nearer). */
typedef struct {
    xf3_t x;
    fm_vec3_t up1, o_l, lo, hi, llo, lhi;
} inst_walk_t;

static inline bool inst_walk_begin(const coll_mesh_instance_t *inst, const fm_vec3_t *center, const capsule_q_t *q,
                                   float t, inst_walk_t *iw, grid_walk_t *w, seen_t *seen)
{
    const coll_mesh_t *m = inst->mesh;
    if (!m || m->ntris == 0 || !xf_prepare(&inst->xf, &iw->x)) return false;
    iw->up1 = one_way_up(inst);
    iw->o_l = to_local_point(&iw->x, &inst->xf, m, center);
    swept_box(q, t, &iw->lo, &iw->hi);
    local_box(m, &iw->x, &iw->o_l, &iw->lo, &iw->hi, &iw->llo, &iw->lhi);
    return grid_walk_box(w, m, &iw->llo, &iw->lhi, seen);
}

static bool sweep_better(const coll_prim_hit_t *h, const best_hit_t *sb)
{
    if (!sb->have) return true;
    if (h->t < sb->ph.t) return true;
    return h->t == sb->ph.t && h->t == 0.0f && h->depth > sb->ph.depth;
}

/* The swept capsule (axis ends seg relative to the triangle's first vertex, moved by
 * disp * t) stays on one side of the triangle's plane, farther than r with an allowance for
 * rounding (0.1 % of r, 1e-4 of the coordinates' size): no contact is possible. The sweep's
 * own first test, without its setup (the edges' lengths, a square root and a division for
 * the unit normal): most candidates of a walking step are the floor under a capsule that
 * moves across it. A near-degenerate face (the two edges within 0.6 degrees) is left to the
 * exact test. */
CAND_INLINE bool sweep_plane_rejects(float r, const fm_vec3_t seg[2], const fm_vec3_t *disp, float t,
                                     const fm_vec3_t shape[3])
{
    fm_vec3_t n;
    fm_vec3_cross(&n, &shape[1], &shape[2]);
    float d0 = fm_vec3_dot(&n, &seg[0]), d1 = fm_vec3_dot(&n, &seg[1]), dd = fm_vec3_dot(&n, disp) * t;
    float lo = f_min(d0, d1), hi = f_max(d0, d1);
    if (dd < 0.0f) lo += dd;
    else hi += dd;
    /* the swept axis crosses the plane (the common case of a candidate kept): no more work */
    if (!(lo > 0.0f) && !(hi < 0.0f)) return false;
    float nn = fm_vec3_len2(&n);
    if (!(nn > 1e-4f * fm_vec3_len2(&shape[1]) * fm_vec3_len2(&shape[2]))) return false;
    float l1 = fabsf(seg[0].x) + fabsf(seg[0].y) + fabsf(seg[0].z) + fabsf(seg[1].x) + fabsf(seg[1].y) +
               fabsf(seg[1].z) + (fabsf(disp->x) + fabsf(disp->y) + fabsf(disp->z)) * t + fabsf(shape[1].x) +
               fabsf(shape[1].y) + fabsf(shape[1].z) + fabsf(shape[2].x) + fabsf(shape[2].y) + fabsf(shape[2].z);
    float rr = r * 1.001f + 1e-4f * l1 + 1e-6f;
    float mn = lo > 0.0f ? lo : -hi;
    return mn * mn > rr * rr * nn;
}

/* One candidate triangle t of inst (w0, shape as for ray_tri; u: the one-way up, zero for
 * an ordinary instance; gt: the gathered triangle, NULL on the scene's walk) against the
 * capsule sweep; true when it is the new best hit. */
static bool sweep_tri(const capsule_q_t *q, const coll_mesh_instance_t *inst, int32_t t, const fm_vec3_t *w0,
                      const fm_vec3_t shape[3], const fm_vec3_t *u, bool cull, coll_gather_tri_t *gt,
                      best_hit_t *sb)
{
    fm_vec3_t seg[2];
    fm_vec3_sub(&seg[0], &q->seg[0], w0);
    fm_vec3_sub(&seg[1], &q->seg[1], w0);
    if (cull && sweep_plane_rejects(q->r, seg, &q->disp, sb->best, shape)) return false;
    if (!one_way_capsule(u, shape, seg, q->r)) return false;
    coll_prim_hit_t ph;
    /* once a hit is held, one no sooner (after t = 0) could not be better: not refined */
    bool got = coll_tri_sweep_prep(seg, q->r, &q->disp, shape, gt ? &gt->prep : NULL, sb->best,
                                   sb->have ? &sb->ph.normal : NULL, &ph);
    if (!got || !sweep_better(&ph, sb)) return false;
    fm_vec3_add(&ph.point, &ph.point, w0);
    best_take(sb, &ph, inst, NULL, t);
    return true;
}

/* A candidate (first vertex w0 and shape, relative to the sweep's centre) lying wholly
 * within above's margin over its plane (ap: the plane's point from the sweep's centre), or
 * under it: at least that margin from a sweep that stays twice the margin above the plane
 * (coll_gather_above_t), so its exact test would find nothing. */
CAND_INLINE bool under_above(const coll_gather_above_t *above, const fm_vec3_t *ap, const fm_vec3_t *w0,
                             const fm_vec3_t shape[3])
{
    const fm_vec3_t *n = &above->n;
    float h0 = (w0->x - ap->x) * n->x + (w0->y - ap->y) * n->y + (w0->z - ap->z) * n->z;
    float h1 = h0 + fm_vec3_dot(&shape[1], n), h2 = h0 + fm_vec3_dot(&shape[2], n);
    return h0 <= above->margin && h1 <= above->margin && h2 <= above->margin;
}

/* (above: NULL, or a plane the sweep stays above: the candidates under it are not tested) */
static void sweep_instance(const coll_scene_t *scene, const coll_mesh_instance_t *inst, const fm_vec3_t *center,
                           const capsule_q_t *q, const coll_gather_above_t *above, seen_t *seen, best_hit_t *sb)
{
    inst_walk_t iw;
    grid_walk_t w;
    if (!inst_walk_begin(inst, center, q, sb->best, &iw, &w, seen)) return;
    fm_vec3_t ap = {{ 0.0f, 0.0f, 0.0f }};
    if (above) fm_vec3_sub(&ap, &above->p, center); /* the plane's point from the sweep's centre */
    while (grid_walk_next_cell(&w))
        for (uint32_t k = w.k; k < w.kend; k++) {
            uint32_t t;
            fm_vec3_t shape[3], w0, tri[3];
            if (!grid_walk_take_in_box(&w, k, &iw.x, &iw.o_l, &iw.lo, &iw.hi, &t, &w0, shape, tri)) continue;
            if (above && under_above(above, &ap, &w0, shape)) continue;
            if (sweep_tri(q, inst, (int32_t)t, &w0, shape, &iw.up1, true, NULL, sb)) {
                swept_box(q, sb->best, &iw.lo, &iw.hi); /* shrink the sweep, and skip cells it misses */
                local_box(inst->mesh, &iw.x, &iw.o_l, &iw.lo, &iw.hi, &iw.llo, &iw.lhi);
                w.skip_missed = true;
            }
        }
    grid_walk_end(&w, scene);
}

CAND_INLINE bool capsule_args_ok(const fm_vec3_t *center, const fm_vec3_t *axis, float radius, float hh)
{
    return vfin(center) && vfin(axis) && f_isfin(radius) && radius > 0.0f && f_isfin(hh) && hh >= 0.0f;
}

CAND_INLINE void capsule_setup(capsule_q_t *q, const fm_vec3_t *axis, float radius, float hh, const fm_vec3_t *disp)
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
                         best_hit_t *sb)
{
    for (uint16_t i = 0; i < scene->body_count; i++) {
        const coll_body_t *b = scene->bodies[i];
        if (!body_visible(b, read_mask)) continue;
        fm_vec3_t rel, lo, hi;
        fm_vec3_sub(&rel, &b->xf.pos, center);
        swept_box(q, sb->best, &lo, &hi);
        if (body_box_reject(b, &rel, &lo, &hi)) continue;
        coll_prim_hit_t ph;
        if (coll_capsule_body_sweep(q->seg, q->r, &q->disp, b, &rel, sb->best, &ph) && sweep_better(&ph, sb))
            best_take(sb, &ph, NULL, b, -1);
    }
}

static bool sweep_result(const best_hit_t *sb, const fm_vec3_t *center, coll_sweep_hit_t *hit)
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

/* coll_capsule_sweep; above: NULL, or a plane the sweep stays above (coll_gather_above_t) */
static bool capsule_sweep_above(const coll_scene_t *scene, fm_vec3_t center, fm_vec3_t axis, float radius,
                                float inner_half_height, fm_vec3_t displacement, uint8_t read_mask,
                                uint8_t coll_types, const coll_gather_above_t *above, coll_sweep_hit_t *hit)
{
    if (!scene || !capsule_args_ok(&center, &axis, radius, inner_half_height) || !vfin(&displacement))
        return false;
    STATS_ADD(scene, queries);
    capsule_q_t q;
    capsule_setup(&q, &axis, radius, inner_half_height, &displacement);
    best_hit_t sb;
    best_init(&sb, 1.0f);
    seen_t seen;
    if (coll_types & COLL_TYPE_MESH) {
        seen_init(&seen);
        for (uint16_t i = 0; i < scene->mesh_count; i++) {
            const coll_mesh_instance_t *inst = scene->meshes[i];
            if (inst && (inst->write_mask & read_mask)) sweep_instance(scene, inst, &center, &q, above, &seen, &sb);
        }
    }
    if (coll_types & COLL_TYPE_BODY) sweep_bodies(scene, &center, &q, read_mask, &sb);
    return sweep_result(&sb, &center, hit);
}

bool coll_capsule_sweep(const coll_scene_t *scene, fm_vec3_t center, fm_vec3_t axis, float radius,
                        float inner_half_height, fm_vec3_t displacement, uint8_t read_mask,
                        uint8_t coll_types, coll_sweep_hit_t *hit)
{
    return capsule_sweep_above(scene, center, axis, radius, inner_half_height, displacement, read_mask, coll_types,
                               NULL, hit);
}

/* ------------------------------------------------------------------ overlaps ------- */

typedef struct {
    coll_contact_t *out;
    uint32_t max_out, kept, total;
    fm_vec3_t center;
    bool distinct; /* one contact per point and normal (coll_capsule_overlaps_distinct) */
} contacts_t;

/* The kept contact that ph (relative to the centre) is a copy of: the same point within
 * COLL_PRIM_TOUCH_TOL and the same normal within about 0.8 degrees; c->kept if none. (A NaN
 * point or normal compares false: not a copy, kept on its own as before.) */
static uint32_t contact_copy(const contacts_t *c, const coll_prim_hit_t *ph)
{
    fm_vec3_t p, d;
    fm_vec3_add(&p, &c->center, &ph->point);
    for (uint32_t i = 0; i < c->kept; i++) {
        const coll_contact_t *o = &c->out[i];
        fm_vec3_sub(&d, &p, &o->point);
        if (fm_vec3_len2(&d) <= COLL_PRIM_TOUCH_TOL * COLL_PRIM_TOUCH_TOL &&
            fm_vec3_dot(&ph->normal, &o->normal) >= 0.9999f)
            return i;
    }
    return c->kept;
}

static void contact_add(contacts_t *c, const coll_prim_hit_t *ph, const coll_mesh_instance_t *inst,
                        const coll_body_t *body, int32_t tri)
{
    c->total++;
    if (c->max_out == 0u || !c->out) return;
    uint32_t pos;
    if (c->distinct && (pos = contact_copy(c, ph)) < c->kept) {
        c->total--; /* a copy of a kept contact: the deeper stays, counted once */
        if (!(ph->depth > c->out[pos].depth)) return;
    } else if (c->kept == c->max_out) {
        if (!(ph->depth > c->out[c->kept - 1u].depth)) return;
        pos = c->kept - 1u; /* drop the shallowest */
    } else {
        pos = c->kept++;
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
/* 1: rejected; 2: not farther than r but farther than rin (r less the touch tolerance) with
 * the same allowance: no overlap either, the exact test's closest pair would find it clear
 * (coll_capsule_triangle_overlap_clear's *clear: a capsule resting against a wall); 0: neither. */
static int plane_rejects(float r, const fm_vec3_t seg[2], const fm_vec3_t shape[3])
{
    fm_vec3_t n;
    fm_vec3_cross(&n, &shape[1], &shape[2]);
    float d0 = fm_vec3_dot(&n, &seg[0]), d1 = fm_vec3_dot(&n, &seg[1]);
    if (!(d0 * d1 > 0.0f)) return 0;
    float mn = f_min(d0 * d0, d1 * d1);
    float l1 = fabsf(seg[0].x) + fabsf(seg[0].y) + fabsf(seg[0].z) + fabsf(seg[1].x) + fabsf(seg[1].y) +
               fabsf(seg[1].z);
    float nn = fm_vec3_len2(&n);
    float rr = r * 1.001f + 1e-6f * l1 + 1e-7f;
    if (mn > rr * rr * nn) return 1;
    float rc = (r - f_min(COLL_PRIM_TOUCH_TOL, 0.25f * r)) * 1.0001f + 1e-6f * l1 + 1e-7f;
    return mn > rc * rc * nn ? 2 : 0;
}

/* One candidate triangle t of inst (w0, shape, u as for sweep_tri) against the overlap query;
 * true when the exact test computed its closest pair and found no overlap
 * (coll_capsule_triangle_overlap_clear; gathered triangles only). */
static bool overlap_tri(const capsule_q_t *q, const coll_mesh_instance_t *inst, int32_t t, const fm_vec3_t *w0,
                        const fm_vec3_t shape[3], const fm_vec3_t *u, coll_gather_tri_t *gt, contacts_t *c,
                        coll_tri_axis_t *axis)
{
    fm_vec3_t seg[2];
    fm_vec3_sub(&seg[0], &q->seg[0], w0);
    fm_vec3_sub(&seg[1], &q->seg[1], w0);
    if (axis) axis->u.x = axis->u.y = axis->u.z = 0.0f;
    int pr = plane_rejects(q->r, seg, shape);
    if (pr) return pr == 2 && gt; /* (2: clear of rin: no overlap, remembered as clear) */
    if (!one_way_capsule(u, shape, seg, q->r)) return false;
    coll_prim_hit_t ph;
    bool clear = false;
    bool got = gt ? coll_capsule_triangle_overlap_clear(seg, q->r, shape, &gt->prep, &ph, &clear, axis)
                  : coll_capsule_triangle_overlap(seg, q->r, shape, &ph);
    if (got && ph.depth > 0.0f) {
        fm_vec3_add(&ph.point, &ph.point, w0);
        contact_add(c, &ph, inst, NULL, t);
    }
    return clear;
}

static void overlap_instance(const coll_scene_t *scene, const coll_mesh_instance_t *inst, const capsule_q_t *q,
                             seen_t *seen, contacts_t *c)
{
    inst_walk_t iw;
    grid_walk_t w;
    if (!inst_walk_begin(inst, &c->center, q, 0.0f, &iw, &w, seen)) return;
    while (grid_walk_next_cell(&w))
        for (uint32_t k = w.k; k < w.kend; k++) {
            uint32_t t;
            fm_vec3_t shape[3], w0, tri[3];
            if (!grid_walk_take_in_box(&w, k, &iw.x, &iw.o_l, &iw.lo, &iw.hi, &t, &w0, shape, tri)) continue;
            overlap_tri(q, inst, (int32_t)t, &w0, shape, &iw.up1, NULL, c, NULL);
        }
    grid_walk_end(&w, scene);
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

static uint32_t capsule_overlaps(const coll_scene_t *scene, fm_vec3_t center, fm_vec3_t axis, float radius,
                                 float inner_half_height, uint8_t read_mask, uint8_t coll_types,
                                 coll_contact_t *out, uint32_t max_out, bool distinct)
{
    if (!scene || !capsule_args_ok(&center, &axis, radius, inner_half_height)) return 0;
    STATS_ADD(scene, queries);
    static const fm_vec3_t zero = {{0.0f, 0.0f, 0.0f}};
    capsule_q_t q;
    capsule_setup(&q, &axis, radius, inner_half_height, &zero);
    contacts_t c = { out, max_out, 0, 0, center, distinct };
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

uint32_t coll_capsule_overlaps(const coll_scene_t *scene, fm_vec3_t center, fm_vec3_t axis, float radius,
                               float inner_half_height, uint8_t read_mask, uint8_t coll_types,
                               coll_contact_t *out, uint32_t max_out)
{
    return capsule_overlaps(scene, center, axis, radius, inner_half_height, read_mask, coll_types, out, max_out,
                            false);
}

uint32_t coll_capsule_overlaps_distinct(const coll_scene_t *scene, fm_vec3_t center, fm_vec3_t axis, float radius,
                                        float inner_half_height, uint8_t read_mask, uint8_t coll_types,
                                        coll_contact_t *out, uint32_t max_out)
{
    return capsule_overlaps(scene, center, axis, radius, inner_half_height, read_mask, coll_types, out, max_out,
                            true);
}

/* ------------------------------------------------------------------ gathered ------- */

/* A query box lo..hi (relative to the query origin at rel from the gather's) in the
 * gather's frame, where the gathered box and the gathered triangles' boxes are: each
 * candidate then costs two compares an axis, not two subtractions more. */
CAND_INLINE void gather_box(const fm_vec3_t *rel, const fm_vec3_t *lo, const fm_vec3_t *hi, fm_vec3_t *glo,
                            fm_vec3_t *ghi)
{
    fm_vec3_add(glo, lo, rel);
    fm_vec3_add(ghi, hi, rel);
}

/* The query box glo..ghi (gather_box: in the gather's frame) lies inside the gathered box:
 * every triangle that can touch the query was gathered. (On the box the scan then uses: the
 * console paid its six sums twice when this test made its own.) */
CAND_INLINE bool gather_inside(const coll_gather_t *g, const fm_vec3_t *glo, const fm_vec3_t *ghi)
{
    for (int a = 0; a < 3; a++)
        if (!(glo->v[a] >= g->lo.v[a]) || !(ghi->v[a] <= g->hi.v[a])) return false;
    return true;
}

/* gather_inside for a query answered here or on the scene, counted as one or the other
 * (an overflowed gather answers nothing: not counted). */
CAND_INLINE bool gather_covers(const coll_gather_t *g, const fm_vec3_t *glo, const fm_vec3_t *ghi)
{
    if (!g->valid) return false;
    if (!gather_inside(g, glo, ghi)) {
        STATS_ADD(g->scene, gather_misses);
        return false;
    }
    STATS_ADD(g->scene, gather_queries);
    return true;
}

/* A gathered triangle relative to a query origin at rel (from the gather's): first vertex
 * w0 and shape (shape[0] = 0). */
CAND_INLINE void gather_tri_place(const coll_gather_tri_t *gt, const fm_vec3_t *rel, fm_vec3_t *w0,
                                  fm_vec3_t shape[3])
{
    fm_vec3_sub(w0, &gt->w0, rel);
    shape[0].x = shape[0].y = shape[0].z = 0.0f;
    shape[1] = gt->e1;
    shape[2] = gt->e2;
}

/* Gathered triangle gt relative to a query origin at rel (from the gather's): first vertex
 * w0 and shape (shape[0] = 0); false when its box misses glo..ghi (gather_box). */
CAND_INLINE bool gather_tri(const coll_gather_tri_t *gt, const fm_vec3_t *rel, const fm_vec3_t *glo,
                            const fm_vec3_t *ghi, fm_vec3_t *w0, fm_vec3_t shape[3])
{
    /* height first: the slide's shortened capsule floats over the floor triangles gathered
     * for the probe, and a box beside them in height rejects them in one compare */
    if (gt->hi.y < glo->y || gt->lo.y > ghi->y || gt->hi.x < glo->x || gt->lo.x > ghi->x || gt->hi.z < glo->z ||
        gt->lo.z > ghi->z)
        return false;
    gather_tri_place(gt, rel, w0, shape);
    return true;
}

/* gather_tri for a ray: its box is thin across its direction (the foot ray's along up: the
 * floor triangles beside it are out of its box across up, while their heights span its
 * reach), so across first; the same test, in another order. */
CAND_INLINE bool gather_tri_ray(const coll_gather_tri_t *gt, const fm_vec3_t *rel, const fm_vec3_t *glo,
                                const fm_vec3_t *ghi, fm_vec3_t *w0, fm_vec3_t shape[3])
{
    if (gt->hi.x < glo->x || gt->lo.x > ghi->x || gt->hi.z < glo->z || gt->lo.z > ghi->z || gt->hi.y < glo->y ||
        gt->lo.y > ghi->y)
        return false;
    gather_tri_place(gt, rel, w0, shape);
    return true;
}

/* The float just below x, a hit's distance (finite, >= 0): s <= f_below(x) is s < x; -1 for
 * 0 (no distance is below it). */
CAND_INLINE float f_below(float x)
{
    if (!(x > 0.0f)) return -1.0f;
    union { float f; uint32_t u; } b = { x };
    b.u -= 1u;
    return b.f;
}

bool coll_gather_raycast(coll_gather_t *g, fm_vec3_t origin, fm_vec3_t dir, float max_dist, coll_ray_hit_t *hit)
{
    if (!g || !g->scene) return false;
    if (!ray_args_ok(&origin, &dir, max_dist)) return false;
    fm_vec3_t rel, lo, hi;
    fm_vec3_sub(&rel, &origin, &g->origin);
    for (int a = 0; a < 3; a++) {
        float e = dir.v[a] * max_dist, slack = 1e-4f * max_dist + 1e-6f;
        lo.v[a] = f_min(0.0f, e) - slack;
        hi.v[a] = f_max(0.0f, e) + slack;
    }
    fm_vec3_t glo, ghi;
    gather_box(&rel, &lo, &hi, &glo, &ghi);
    if (!(g->types & COLL_TYPE_MESH) || !gather_covers(g, &glo, &ghi))
        return coll_raycast(g->scene, origin, dir, max_dist, g->read_mask, g->types, hit);
    best_hit_t rb;
    best_init(&rb, max_dist);
    /* ray_tri on each candidate, with the ray's shear worked out once and each triangle's
     * raw normal (and a hit's unit normal) from its prep: the same expressions */
    coll_ray_shear_t sh;
    bool sheared = coll_ray_shear(&dir, &sh);
    /* The farthest distance a candidate's hit could be taken at: the limit, then, once a
     * hit is held, the float just below it (a hit must be nearer: at the same distance,
     * a ray down the edge two triangles share, the second would compute its plane
     * distance, point and normal only to be dropped). */
    float smax = rb.best;
    coll_gather_tri_t *gt = g->tris, *gend = sheared ? gt + g->ntris : gt;
    for (; gt < gend; gt++) {
        fm_vec3_t w0, shape[3];
        if (!gather_tri_ray(gt, &rel, &glo, &ghi, &w0, shape)) continue;
        fm_vec3_t o;
        coll_prim_hit_t ph;
        fm_vec3_negate(&o, &w0);
        if (gt->inst->flags & COLL_INSTANCE_ONE_WAY) {
            fm_vec3_t u = one_way_up_rotated(gt->inst);
            if (!one_way_ray(&u, shape, &o, &dir)) continue;
        }
        if (coll_ray_triangle_sheared(&o, &dir, &sh, shape, smax, &gt->prep, &ph) && (!rb.have || ph.t < rb.best)) {
            fm_vec3_add(&ph.point, &ph.point, &w0);
            best_take(&rb, &ph, gt->inst, NULL, gt->tri);
            smax = f_below(ph.t);
        }
    }
    if (g->types & COLL_TYPE_BODY) ray_bodies(g->scene, &origin, &dir, g->read_mask, &rb);
    return ray_result(&rb, &origin, hit);
}

/* The memo is of this gather and of this very capsule (coll_gather_memo_for); NULL when not. */
CAND_INLINE const coll_gather_memo_t *memo_for(const coll_gather_memo_t *memo, const coll_gather_t *g,
                                               const fm_vec3_t *center, const fm_vec3_t *axis, float radius,
                                               float ihh)
{
    return memo && coll_gather_memo_for(memo, g, *center, *axis, radius, ihh) ? memo : NULL;
}

/* The memo is of this gather and of a capsule of this shape (axis, radius, inner half
 * height: the same values bit for bit) wherever it was: its boundary axes are axes like any
 * other for a sweep of that capsule from elsewhere (memo_axis_culls with moff); NULL when not. */
CAND_INLINE const coll_gather_memo_t *memo_shape_for(const coll_gather_memo_t *memo, const coll_gather_t *g,
                                                     const fm_vec3_t *axis, float radius, float ihh)
{
    return memo && memo->g == g && memo->n > 0 && coll_same_bits(memo->radius, radius) &&
                   coll_same_bits(memo->ihh, ihh) && coll_same_bits(memo->axis.x, axis->x) &&
                   coll_same_bits(memo->axis.y, axis->y) && coll_same_bits(memo->axis.z, axis->z)
               ? memo
               : NULL;
}

/* The box test's corners (perf20's test): gathered triangle gt, whose box passed the
 * per-axis test against the sweep's box glo..ghi (the swept axis's box grown by R = r + eps
 * on every side), is farther than R from the swept axis's box itself (its gaps on the axes,
 * squared and summed): every point of the triangle is then farther than r + eps from the
 * swept axis, the box test's own allowance, and the exact test would find no contact. A
 * riser's or a tread's edge diagonally beside the capsule on a stair (the stair step's up,
 * forward and down sweeps: a box test reaches past the corner by up to R (sqrt 2 - 1)). For
 * triangles flat along an axis only, whose box is as tight as the triangle. */
CAND_INLINE bool gather_corner_clear(const coll_gather_tri_t *gt, const fm_vec3_t *glo, const fm_vec3_t *ghi,
                                     float R)
{
    /* Each gap is at most R (the box test passed), so one alone never clears: across up
     * first (x, z), and a triangle whose box meets the swept axis's box on both (the floor
     * under a capsule) is given up before its height is read. */
    float mx = f_max(glo->x - gt->hi.x, gt->lo.x - ghi->x) + R;
    float mz = f_max(glo->z - gt->hi.z, gt->lo.z - ghi->z) + R;
    if (!(mx > 0.0f) && !(mz > 0.0f)) return false;
    float my = f_max(glo->y - gt->hi.y, gt->lo.y - ghi->y) + R;
    float s = 0.0f;
    if (mx > 0.0f) s += mx * mx;
    if (my > 0.0f) s += my * my;
    if (mz > 0.0f) s += mz * mz;
    return s > R * R;
}

CAND_INLINE bool memo_clear(const coll_gather_memo_t *memo, uint16_t k)
{
    for (uint8_t i = 0; i < memo->n; i++)
        if (memo->clear[i] == k) return true;
    return false;
}

/* The memo's overlap found gathered triangle gt (w0, shape: placed for this sweep) clear
 * along its boundary axis: the sweep's exact test would take that axis first (the same
 * segment, triangle and expressions: coll_tri_sweep_axis_culls); true when it separates
 * over the sweep's motion to t_max, where that test would find nothing. The recovery's
 * look and the slide's first sweep from the same place: a stair's riser and tread halves
 * beyond their diagonals beside the capsule, ~1.1k console instructions each. */
CAND_INLINE bool memo_axis_culls(const coll_gather_memo_t *memo, const coll_gather_t *g, const coll_gather_tri_t *gt,
                                 const capsule_q_t *q, const fm_vec3_t *w0, const fm_vec3_t shape[3], float t_max,
                                 const fm_vec3_t *moff, uint8_t *mj)
{
    /* (the memo's triangles are in the gather's order, as the scan visits them: a cursor) */
    uint8_t k = (uint8_t)(gt - g->tris), i = *mj;
    while (i < memo->n && memo->clear[i] < k) i++;
    *mj = i;
    if (!(i < memo->n && memo->clear[i] == k)) return false;
    const coll_tri_axis_t *ax = &memo->axis_of[i];
    /* first the separation along it, roughly (its own test follows where this passes; one
     * this rejects the sweep's test finds too close along it, within rounding, and tests
     * on): the triangles the motion goes into (the hit, its tie across the nosing) stop here */
    const fm_vec3_t *u = &ax->u;
    float uu = fm_vec3_dot(u, u);
    if (!(uu > 0.0f)) return false;
    float sep = ax->seg0 + f_min(fm_vec3_dot(u, &q->disp) * t_max, 0.0f) - ax->top;
    /* (moff: the sweep starts there from the memo's capsule; the stored extents moved by it
     * for this rough test only, the cull below is made of the sweep's own values) */
    if (moff) sep += fm_vec3_dot(u, moff);
    float rin = q->r - f_min(COLL_PRIM_TOUCH_TOL, 0.25f * q->r);
    if (!(sep > 0.0f) || !(sep * sep > rin * rin * uu)) return false;
    fm_vec3_t seg[2];
    fm_vec3_sub(&seg[0], &q->seg[0], w0);
    fm_vec3_sub(&seg[1], &q->seg[1], w0);
    return coll_tri_sweep_axis_culls(seg, q->r, &q->disp, shape, t_max, ax);
}

/* The gathered triangles against a capsule sweep (rel: its centre from the gather's origin;
 * lo..hi: its box swept to sb's limit) into sb. memo: memo_for's (NULL: none). corner (a
 * constant at each call): the box test's corners (gather_corner_clear) for the triangles
 * flat along an axis; only coll_gather_capsule_sweep_corner's copy of this loop asks it (the
 * stair step's sweeps), so every other query keeps its code (perf20: the test in every copy
 * cost the crack course 1.3-2.8 %; asked by every capsule sweep, the walk 0.3 %). */
CAND_INLINE void gather_sweep_scan(coll_gather_t *g, const capsule_q_t *q, const fm_vec3_t *rel,
                                   fm_vec3_t lo, fm_vec3_t hi, fm_vec3_t glo, fm_vec3_t ghi,
                                   const coll_gather_above_t *above, const fm_vec3_t *center,
                                   const coll_gather_memo_t *memo, const fm_vec3_t *moff, bool corner,
                                   best_hit_t *sb)
{
    fm_vec3_t ap;
    if (above) fm_vec3_sub(&ap, &above->p, center); /* the plane's point from the sweep's centre */
    /* (memo: set once a hit at t = 0 is held, below) */
    const coll_gather_memo_t *skip = NULL;
    uint8_t mj = 0; /* (memo_axis_culls' cursor) */
    /* every gathered triangle below the swept box (the slide's shortened capsule over a
     * floor): gather_tri's first compare would reject each */
    if (g->ytop < glo.y) return;
    /* (a pointer walk: the console's loop over a uint16_t index paid its wrap and the
     * address product at every triangle) */
    for (coll_gather_tri_t *gt = g->tris, *gend = gt + g->ntris; gt < gend; gt++) {
        fm_vec3_t w0, shape[3];
        if (!gather_tri(gt, rel, &glo, &ghi, &w0, shape)) continue;
        /* A hit held at t = 0: this triangle is tested over t_max = 0, where tri_sweep
         * computes the closest pair at the start and, no overlap, stops: the memo's overlap
         * query computed that pair (the same values) and found no overlap. */
        if (skip && memo_clear(skip, (uint16_t)(gt - g->tris))) continue;
        if (memo && !skip && memo_axis_culls(memo, g, gt, q, &w0, shape, sb->best, moff, &mj)) continue;
        fm_vec3_t u = one_way_up(gt->inst);
        /* the plane cull only where it can beat the box test just passed: a triangle flat
         * along an axis (a level floor, an upright wall of a grid-aligned level) has a box
         * as tight as its plane */
        bool tilted = gt->hi.x - gt->lo.x > q->eps && gt->hi.y - gt->lo.y > q->eps && gt->hi.z - gt->lo.z > q->eps;
        if (corner && !tilted && gather_corner_clear(gt, &glo, &ghi, q->r + q->eps)) continue;
        /* Wholly within margin above the plane the sweep stays 2 x margin above: at least
         * margin from the swept capsule, so the exact test, which reports contacts within
         * the radius only, would find nothing (under_above). The crack rule's first look
         * asks it of the tilted candidates only, as the plane cull below (a floor flat along
         * an axis under its drop is out of its box already): the neighbours of a sloping
         * floor's triangle under the ball, which that cull keeps (the ball crosses their
         * planes' extensions). Its roll along a contact's tangent plane asks it of every
         * candidate (above->all): the faces behind the edge it rolls off, level or upright. */
        if (above && (tilted || above->all) && under_above(above, &ap, &w0, shape)) continue;
        if (sweep_tri(q, gt->inst, gt->tri, &w0, shape, &u, tilted, gt, sb)) {
            swept_box(q, sb->best, &lo, &hi); /* shrink the sweep */
            gather_box(rel, &lo, &hi, &glo, &ghi);
            if (sb->best == 0.0f && !moff) skip = memo; /* (its pairs are of its own place) */
        }
    }
}

/* A sweep whose box reaches outside the gathered box (the crack rule's roll): the largest
 * fraction t of it whose swept box (swept_box(q, t)) still lies inside, verified with that
 * box itself; -1 when not even the start's does. A triangle the sweep meets at or before t
 * meets that box (what lets the scene sweep shrink its box to the best hit), so it was
 * gathered: a gathered hit no later than t is the sweep's hit. */
static float gather_covered_part(const coll_gather_t *g, const fm_vec3_t *rel, const capsule_q_t *q)
{
    fm_vec3_t lo, hi, glo, ghi;
    swept_box(q, 0.0f, &lo, &hi);
    gather_box(rel, &lo, &hi, &glo, &ghi);
    if (!gather_inside(g, &glo, &ghi)) return -1.0f;
    float t = 1.0f;
    for (int a = 0; a < 3; a++) {
        float d = q->disp.v[a];
        float room = d > 0.0f ? g->hi.v[a] - (hi.v[a] + rel->v[a]) : (lo.v[a] + rel->v[a]) - g->lo.v[a];
        float ta = d != 0.0f ? room / fabsf(d) : 1.0f;
        if (ta < t) t = ta;
    }
    t *= 0.999f; /* below the rounding of the division; the box check below decides */
    if (!(t > 0.0f)) return 0.0f;
    swept_box(q, t, &lo, &hi);
    gather_box(rel, &lo, &hi, &glo, &ghi);
    return gather_inside(g, &glo, &ghi) ? t : 0.0f;
}

/* A gathered sweep whose box reaches outside the gathered box (the crack rule's roll): the
 * gathered triangles still answer when one is met before the sweep leaves the box (the scan
 * looks no further); else the scene does. Not tried when the sweep leaves within its first
 * tenth: that scan, paid on top of the scene's when it meets nothing (about half the time,
 * at every covered part: soak seed 1), made a stair climb's worst step costlier. */
#if defined(__GNUC__)
__attribute__((noinline)) /* (out of the common path's code) */
#endif
static bool gather_sweep_outside(coll_gather_t *g, fm_vec3_t center, fm_vec3_t axis, float radius,
                                 float inner_half_height, fm_vec3_t displacement, const capsule_q_t *q,
                                 const fm_vec3_t *rel, const coll_gather_above_t *above,
                                 const coll_gather_memo_t *memo, coll_sweep_hit_t *hit)
{
    if ((g->types & COLL_TYPE_MESH) && g->valid) {
        float covered = gather_covered_part(g, rel, q);
        if (covered >= 0.1f) {
            best_hit_t sb;
            best_init(&sb, covered);
            fm_vec3_t lo, hi, glo, ghi;
            swept_box(q, covered, &lo, &hi);
            gather_box(rel, &lo, &hi, &glo, &ghi);
            gather_sweep_scan(g, q, rel, lo, hi, glo, ghi, above, &center, memo, NULL, false, &sb);
            if (sb.have) {
                STATS_ADD(g->scene, gather_queries);
                if (g->types & COLL_TYPE_BODY) sweep_bodies(g->scene, &center, q, g->read_mask, &sb);
                return sweep_result(&sb, &center, hit);
            }
        }
        STATS_ADD(g->scene, gather_misses);
    }
    return capsule_sweep_above(g->scene, center, axis, radius, inner_half_height, displacement, g->read_mask,
                               g->types, above, hit);
}

CAND_INLINE bool gather_capsule_sweep(coll_gather_t *g, fm_vec3_t center, fm_vec3_t axis, float radius,
                                      float inner_half_height, fm_vec3_t displacement,
                                      const coll_gather_above_t *above, const coll_gather_memo_t *memo,
                                      bool moved, bool corner, coll_sweep_hit_t *hit)
{
    if (!g || !g->scene) return false;
    if (!capsule_args_ok(&center, &axis, radius, inner_half_height) || !vfin(&displacement)) return false;
    capsule_q_t q;
    capsule_setup(&q, &axis, radius, inner_half_height, &displacement);
    fm_vec3_t rel, lo, hi, glo, ghi;
    fm_vec3_sub(&rel, &center, &g->origin);
    swept_box(&q, 1.0f, &lo, &hi);
    gather_box(&rel, &lo, &hi, &glo, &ghi);
    /* moved (a constant at each call): the memo's capsule was elsewhere (memo_shape_for) */
    fm_vec3_t moff;
    memo = moved ? memo_shape_for(memo, g, &axis, radius, inner_half_height)
                 : memo_for(memo, g, &center, &axis, radius, inner_half_height);
    if (moved && memo) fm_vec3_sub(&moff, &center, &memo->center);
    if (!(g->types & COLL_TYPE_MESH) || !g->valid || !gather_inside(g, &glo, &ghi))
        return gather_sweep_outside(g, center, axis, radius, inner_half_height, displacement, &q, &rel, above,
                                    moved ? NULL : memo, hit);
    STATS_ADD(g->scene, gather_queries);
    best_hit_t sb;
    best_init(&sb, 1.0f);
    gather_sweep_scan(g, &q, &rel, lo, hi, glo, ghi, above, &center, memo, moved && memo ? &moff : NULL, corner,
                      &sb);
    if (g->types & COLL_TYPE_BODY) sweep_bodies(g->scene, &center, &q, g->read_mask, &sb);
    return sweep_result(&sb, &center, hit);
}

bool coll_gather_capsule_sweep(coll_gather_t *g, fm_vec3_t center, fm_vec3_t axis, float radius,
                               float inner_half_height, fm_vec3_t displacement, coll_sweep_hit_t *hit)
{
    return gather_capsule_sweep(g, center, axis, radius, inner_half_height, displacement, NULL, NULL, false, false, hit);
}

bool coll_gather_capsule_sweep_corner(coll_gather_t *g, fm_vec3_t center, fm_vec3_t axis, float radius,
                                      float inner_half_height, fm_vec3_t displacement, coll_sweep_hit_t *hit)
{
    return gather_capsule_sweep(g, center, axis, radius, inner_half_height, displacement, NULL, NULL, false, true, hit);
}

bool coll_gather_capsule_sweep_above(coll_gather_t *g, fm_vec3_t center, fm_vec3_t axis, float radius,
                                     float inner_half_height, fm_vec3_t displacement,
                                     const coll_gather_above_t *above, coll_sweep_hit_t *hit)
{
    return gather_capsule_sweep(g, center, axis, radius, inner_half_height, displacement, above, NULL, false, false, hit);
}

bool coll_gather_capsule_sweep_m(coll_gather_t *g, fm_vec3_t center, fm_vec3_t axis, float radius,
                                 float inner_half_height, fm_vec3_t displacement, const coll_gather_above_t *above,
                                 const coll_gather_memo_t *memo, coll_sweep_hit_t *hit)
{
    return gather_capsule_sweep(g, center, axis, radius, inner_half_height, displacement, above, memo, false, false, hit);
}

bool coll_gather_capsule_sweep_corner_m(coll_gather_t *g, fm_vec3_t center, fm_vec3_t axis, float radius,
                                        float inner_half_height, fm_vec3_t displacement,
                                        const coll_gather_memo_t *memo, coll_sweep_hit_t *hit)
{
    return gather_capsule_sweep(g, center, axis, radius, inner_half_height, displacement, NULL, memo, true, true, hit);
}

CAND_INLINE uint32_t gather_capsule_overlaps(coll_gather_t *g, fm_vec3_t center, fm_vec3_t axis, float radius,
                                             float inner_half_height, coll_contact_t *out, uint32_t max_out,
                                             coll_gather_memo_t *memo, bool distinct)
{
    if (!g || !g->scene) return 0;
    if (!capsule_args_ok(&center, &axis, radius, inner_half_height)) return 0;
    static const fm_vec3_t zero = {{0.0f, 0.0f, 0.0f}};
    capsule_q_t q;
    capsule_setup(&q, &axis, radius, inner_half_height, &zero);
    fm_vec3_t rel, lo, hi;
    fm_vec3_sub(&rel, &center, &g->origin);
    swept_box(&q, 0.0f, &lo, &hi);
    fm_vec3_t glo, ghi;
    gather_box(&rel, &lo, &hi, &glo, &ghi);
    if (!(g->types & COLL_TYPE_MESH) || !gather_covers(g, &glo, &ghi))
        return capsule_overlaps(g->scene, center, axis, radius, inner_half_height, g->read_mask, g->types, out,
                                max_out, distinct);
    /* (the memo's old record is replaced as this one is written: its key, below) */
    contacts_t c = { out, max_out, 0, 0, center, distinct };
    uint32_t nm = 0;
    for (coll_gather_tri_t *gt = g->tris, *gend = gt + g->ntris; gt < gend; gt++) {
        fm_vec3_t w0, shape[3];
        if (!gather_tri(gt, &rel, &glo, &ghi, &w0, shape)) continue;
        fm_vec3_t u = one_way_up(gt->inst);
        coll_tri_axis_t ax;
        if (overlap_tri(&q, gt->inst, gt->tri, &w0, shape, &u, gt, &c, &ax) && memo && nm < COLL_GATHER_MEMO_MAX) {
            memo->axis_of[nm] = ax;
            memo->clear[nm++] = (uint8_t)(gt - g->tris);
        }
    }
    /* (not for a near-zero inner half height: tri_sweep makes such a segment its midpoint,
     * the overlap test does not) */
    if (nm > 0) {
        memo->g = NULL;
        if (inner_half_height == 0.0f || inner_half_height > 1e-6f) {
            memo->g = g;
            memo->center = center;
            memo->axis = axis;
            memo->radius = radius;
            memo->ihh = inner_half_height;
            memo->n = (uint8_t)nm;
        }
    }
    if (g->types & COLL_TYPE_BODY) overlap_bodies(g->scene, &q, g->read_mask, &c);
    return c.total;
}

uint32_t coll_gather_capsule_overlaps(coll_gather_t *g, fm_vec3_t center, fm_vec3_t axis, float radius,
                                      float inner_half_height, coll_contact_t *out, uint32_t max_out)
{
    return gather_capsule_overlaps(g, center, axis, radius, inner_half_height, out, max_out, NULL, false);
}

uint32_t coll_gather_capsule_overlaps_distinct(coll_gather_t *g, fm_vec3_t center, fm_vec3_t axis, float radius,
                                               float inner_half_height, coll_contact_t *out, uint32_t max_out)
{
    return gather_capsule_overlaps(g, center, axis, radius, inner_half_height, out, max_out, NULL, true);
}

uint32_t coll_gather_capsule_overlaps_m(coll_gather_t *g, fm_vec3_t center, fm_vec3_t axis, float radius,
                                        float inner_half_height, coll_contact_t *out, uint32_t max_out,
                                        coll_gather_memo_t *memo)
{
    return gather_capsule_overlaps(g, center, axis, radius, inner_half_height, out, max_out, memo, false);
}
