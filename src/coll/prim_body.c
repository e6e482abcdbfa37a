/**
 * @file prim_body.c
 * @brief Ray and capsule against convex collider bodies (sphere, box, capsule, cylinder).
 *
 *  - Rays: analytic for every shape (sphere, capsule, slab test for the box, side +
 *    caps for the cylinder). An origin inside the body hits at s = 0 with the normal of
 *    the nearest surface.
 *  - Sphere and capsule bodies: exact, through the triangle sweep on a degenerate
 *    "triangle" (the body's inner segment) with the radii added.
 *  - Box: exact, the sweep against the triangles of the faces that face the motion (the
 *    first contact with a solid box from outside is on its surface); a segment crossing
 *    the box gets its push-out from the separating-axis test (box axes and segment x box
 *    axes), which is the exact penetration of a segment into a box.
 *  - Cylinder: the exact segment-cylinder distance (bisection on the sign of its
 *    derivative along the segment) drives Newton steps on the distance as a function of
 *    time (convex, derivative n . d, so steps from the left never pass the root); the
 *    normal comes from the closest points. When Newton does not settle (or, in a
 *    COLL_METHOD_HOOKS build, coll_set_body_sweep_mpr(true) forces it), libccd MPR takes over: bisection on the
 *    intersection of the body with the capsule swept over [0, t] (a convex shape that
 *    only grows with t, so the test is monotone). A segment inside the cylinder gets its
 *    push-out from ccdMPRPenetration (no EPA, no allocation). libccd's portal refinement
 *    has no iteration cap, so the support function caps the number of calls and then
 *    answers "no intersection".
 * Every path rejects non-finite input and zero-size bodies before doing any work.
 */
#include "prim_util.h"
#include <ccd/ccd.h>

/* ---------------------------------------------------------------- body frame */

typedef struct {
    coll_shape_t shape;
    fm_vec3_t he;      /* half extents */
    fm_vec3_t pos;     /* relative position */
    fm_quat_t q;       /* unit rotation */
} body_frame_t;

static fm_vec3_t q_rot(const fm_quat_t *q, fm_vec3_t v)
{
    fm_vec3_t u = v3(q->x, q->y, q->z);
    fm_vec3_t t = v3_scale(v3_cross(u, v), 2.0f);
    return v3_add(v3_madd(v, t, q->w), v3_cross(u, t));
}

static fm_vec3_t q_rot_inv(const fm_quat_t *q, fm_vec3_t v)
{
    fm_quat_t c = { { -q->x, -q->y, -q->z, q->w } };
    return q_rot(&c, v);
}

static bool body_setup(const coll_body_t *body, const fm_vec3_t *pos, body_frame_t *f)
{
    if (!body || !pos || !prim_sane3(*pos) || !v3_finite(body->half_extents)) return false;
    const fm_quat_t *q = &body->xf.rot;
    if (!f_finite(q->x) || !f_finite(q->y) || !f_finite(q->z) || !f_finite(q->w)) return false;
    float qq = q->x * q->x + q->y * q->y + q->z * q->z + q->w * q->w;
    if (!(qq > 1e-12f)) return false;
    float inv = 1.0f / sqrtf(qq);
    f->q.x = q->x * inv; f->q.y = q->y * inv; f->q.z = q->z * inv; f->q.w = q->w * inv;
    f->shape = body->shape;
    f->he = body->half_extents;
    f->pos = *pos;
    const float minsz = 1e-6f, maxsz = 1e6f;
    switch (body->shape) {
    case COLL_SHAPE_SPHERE:
        return f->he.x > minsz && f->he.x < maxsz;
    case COLL_SHAPE_BOX:
        return f->he.x > minsz && f->he.y > minsz && f->he.z > minsz &&
               f->he.x < maxsz && f->he.y < maxsz && f->he.z < maxsz;
    case COLL_SHAPE_CAPSULE:
        return f->he.x > minsz && f->he.y >= 0.0f && f->he.x < maxsz && f->he.y < maxsz;
    case COLL_SHAPE_CYLINDER:
        return f->he.x > minsz && f->he.y > minsz && f->he.x < maxsz && f->he.y < maxsz;
    default:
        return false;
    }
}

static bool seg_ok(const fm_vec3_t seg[2], float r)
{
    return seg && prim_sane3(seg[0]) && prim_sane3(seg[1]) && r >= 0.0f && prim_sane(r);
}

/** World inner segment of a capsule body (local Y axis). */
static void capsule_axis(const body_frame_t *f, fm_vec3_t out[3])
{
    fm_vec3_t up = q_rot(&f->q, v3(0.0f, f->he.y, 0.0f));
    out[0] = v3_sub(f->pos, up);
    out[1] = v3_add(f->pos, up);
    out[2] = out[1];
}

/* The inner segment of a round body (sphere: a point) as a degenerate triangle: the body
 * is everything within he.x of it. */
static void round_axis(const body_frame_t *f, fm_vec3_t out[3])
{
    if (f->shape == COLL_SHAPE_SPHERE) out[0] = out[1] = out[2] = f->pos;
    else capsule_axis(f, out);
}

/* Squared distance between the capsule's segment and a round body's axis (ax, filled
 * here), with the closest points cp (on the segment) and cq (on the axis). */
static float round_axis_dist2(const body_frame_t *f, const fm_vec3_t seg[2], fm_vec3_t ax[3], fm_vec3_t *cp,
                              fm_vec3_t *cq)
{
    round_axis(f, ax);
    float u, v;
    return coll_prim_closest_seg_seg(seg[0], seg[1], ax[0], ax[1], &u, &v, cp, cq);
}

/* ---------------------------------------------------------------- rays */

static bool ray_box_local(fm_vec3_t o, fm_vec3_t d, fm_vec3_t he, float s_max, prim_ray_t *out)
{
    float tmin = 0.0f, tmax = s_max;
    int axis = -1;
    float sign = 0.0f;
    bool inside = true;
    for (int i = 0; i < 3; i++) {
        if (o.v[i] < -he.v[i] || o.v[i] > he.v[i]) inside = false;
        if (d.v[i] == 0.0f) {
            if (o.v[i] < -he.v[i] || o.v[i] > he.v[i]) return false;
            continue;
        }
        float inv = 1.0f / d.v[i];
        float t1 = (-he.v[i] - o.v[i]) * inv, t2 = (he.v[i] - o.v[i]) * inv;
        float sg = -1.0f;
        if (t1 > t2) { float tmp = t1; t1 = t2; t2 = tmp; sg = 1.0f; }
        if (t1 > tmin) { tmin = t1; axis = i; sign = sg; }
        if (t2 < tmax) tmax = t2;
        if (tmin > tmax) return false;
    }
    out->n = v3(0.0f, 0.0f, 0.0f);
    if (inside || axis < 0) {
        /* origin inside: nearest face */
        float best = 3.0e38f;
        for (int i = 0; i < 3; i++) {
            float dp = he.v[i] - o.v[i], dn = o.v[i] + he.v[i];
            if (dp < best) { best = dp; out->n = v3(0.0f, 0.0f, 0.0f); out->n.v[i] = 1.0f; }
            if (dn < best) { best = dn; out->n = v3(0.0f, 0.0f, 0.0f); out->n.v[i] = -1.0f; }
        }
        out->s = 0.0f;
        return true;
    }
    out->s = tmin;
    out->n.v[axis] = sign;
    return true;
}

/** Solid cylinder around local Y: radius R, half height hh. */
static bool ray_cylinder_local(fm_vec3_t o, fm_vec3_t d, float R, float hh, float s_max, prim_ray_t *out)
{
    float rr = o.x * o.x + o.z * o.z;
    if (rr <= R * R && o.y >= -hh && o.y <= hh) {
        float side = R - sqrtf(rr), cap = hh - fabsf(o.y);
        out->s = 0.0f;
        if (cap < side) out->n = v3(0.0f, o.y >= 0.0f ? 1.0f : -1.0f, 0.0f);
        else out->n = v3_unit_or(v3(o.x, 0.0f, o.z), v3(1.0f, 0.0f, 0.0f));
        return true;
    }
    bool any = false;
    /* caps */
    if (d.y != 0.0f) {
        for (int k = 0; k < 2; k++) {
            float y = k ? hh : -hh;
            /* only the cap facing the origin can be entered */
            if ((k && o.y < hh) || (!k && o.y > -hh)) continue;
            float s = (y - o.y) / d.y;
            if (!(s >= 0.0f) || !(s <= s_max)) continue;
            float x = o.x + d.x * s, z = o.z + d.z * s;
            if (x * x + z * z > R * R) continue;
            if (!any || s < out->s) { any = true; out->s = s; out->n = v3(0.0f, k ? 1.0f : -1.0f, 0.0f); }
        }
    }
    /* side */
    float a = d.x * d.x + d.z * d.z;
    float b = o.x * d.x + o.z * d.z;
    float c = rr - R * R;
    if (a > 0.0f && c > 0.0f && b < 0.0f) {
        float wx = o.x - d.x * (b / a), wz = o.z - d.z * (b / a); /* closest approach */
        float disc = a * (R * R - (wx * wx + wz * wz));
        if (disc >= 0.0f) {
            float s = c / (-b + sqrtf(disc));
            float y = o.y + d.y * s;
            if (s <= s_max && y >= -hh && y <= hh && (!any || s < out->s)) {
                any = true;
                out->s = s;
                out->n = v3_unit_or(v3(o.x + d.x * s, 0.0f, o.z + d.z * s), v3(1.0f, 0.0f, 0.0f));
            }
        }
    }
    return any;
}

bool coll_ray_body(const fm_vec3_t *o, const fm_vec3_t *d, const coll_body_t *body,
                   const fm_vec3_t *body_pos_rel, float s_max, coll_prim_hit_t *hit)
{
    body_frame_t f;
    if (!o || !d || !hit || !prim_sane3(*o) || !prim_sane3(*d) || !(s_max >= 0.0f)) return false;
    if (!body_setup(body, body_pos_rel, &f)) return false;
    if (!(v3_len2(*d) > 0.0f)) return false;
    prim_ray_t h;
    bool got;
    switch (f.shape) {
    case COLL_SHAPE_SPHERE:
        got = coll_prim_ray_sphere(*o, *d, f.pos, f.he.x, s_max, &h);
        break;
    case COLL_SHAPE_CAPSULE: {
        fm_vec3_t ax[3];
        capsule_axis(&f, ax);
        got = coll_prim_ray_capsule(*o, *d, ax[0], ax[1], f.he.x, s_max, &h);
        break;
    }
    case COLL_SHAPE_BOX:
    case COLL_SHAPE_CYLINDER:
    default: {
        fm_vec3_t ol = q_rot_inv(&f.q, v3_sub(*o, f.pos)), dl = q_rot_inv(&f.q, *d);
        got = f.shape == COLL_SHAPE_BOX ? ray_box_local(ol, dl, f.he, s_max, &h)
                                        : ray_cylinder_local(ol, dl, f.he.x, f.he.y, s_max, &h);
        if (got) h.n = q_rot(&f.q, h.n);
        break;
    }
    }
    if (!got) return false;
    hit->t = h.s;
    hit->depth = 0.0f;
    hit->normal = h.n;
    hit->point = v3_madd(*o, *d, h.s);
    return true;
}

/* ---------------------------------------------------------------- box */

static const int box_tris[12][3] = {
    /* per face: two triangles of its corners; corners indexed by bits x,y,z (1 = +) */
    { 1, 3, 7 }, { 1, 7, 5 },   /* +x */
    { 0, 4, 6 }, { 0, 6, 2 },   /* -x */
    { 2, 6, 7 }, { 2, 7, 3 },   /* +y */
    { 0, 1, 5 }, { 0, 5, 4 },   /* -y */
    { 4, 5, 7 }, { 4, 7, 6 },   /* +z */
    { 0, 2, 3 }, { 0, 3, 1 },   /* -z */
};

static fm_vec3_t box_corner(fm_vec3_t he, int i)
{
    return v3(i & 1 ? he.x : -he.x, i & 2 ? he.y : -he.y, i & 4 ? he.z : -he.z);
}

/** Penetration of segment a..b (local frame) into the box by separating axes; false when
 *  separated. depth is the segment's (add r), normal local, box -> segment. */
static bool seg_box_sat(fm_vec3_t a, fm_vec3_t b, fm_vec3_t he, float *depth, fm_vec3_t *normal)
{
    fm_vec3_t s = v3_sub(b, a), c = v3_scale(v3_add(a, b), 0.5f);
    float best = 3.0e38f;
    fm_vec3_t bn = v3(0.0f, 1.0f, 0.0f);
    for (int i = 0; i < 6; i++) {
        fm_vec3_t ax;
        if (i < 3) {
            ax = v3(0.0f, 0.0f, 0.0f);
            ax.v[i] = 1.0f;
        } else {
            fm_vec3_t e = v3(0.0f, 0.0f, 0.0f);
            e.v[i - 3] = 1.0f;
            ax = v3_cross(s, e);
            float l2 = v3_len2(ax);
            if (!(l2 > 1e-10f * v3_len2(s)) || !(l2 > 1e-20f)) continue;
            ax = v3_scale(ax, 1.0f / sqrtf(l2));
        }
        float rb = he.x * fabsf(ax.x) + he.y * fabsf(ax.y) + he.z * fabsf(ax.z);
        float rs = 0.5f * fabsf(v3_dot(s, ax));
        float cp = v3_dot(c, ax);
        float ov = rb + rs - fabsf(cp);
        if (ov < 0.0f) return false;
        if (ov < best) { best = ov; bn = cp >= 0.0f ? ax : v3_neg(ax); }
    }
    *depth = best;
    *normal = bn;
    return true;
}

/** Static capsule vs box in the box frame. */
static bool box_overlap_local(const fm_vec3_t seg[2], float r, fm_vec3_t he, float tol, coll_prim_hit_t *hit)
{
    float depth;
    fm_vec3_t n;
    /* quick reject: separated even from the box grown by r */
    if (!seg_box_sat(seg[0], seg[1], v3(he.x + r, he.y + r, he.z + r), &depth, &n)) return false;
    if (seg_box_sat(seg[0], seg[1], he, &depth, &n)) {
        hit->t = 0.0f;
        hit->depth = depth + r;
        hit->normal = n;
        /* closest point of the box to the segment centre, projected along n */
        fm_vec3_t c = v3_scale(v3_add(seg[0], seg[1]), 0.5f);
        for (int i = 0; i < 3; i++) c.v[i] = f_max(-he.v[i], f_min(he.v[i], c.v[i]));
        hit->point = c;
        return true;
    }
    float best = 3.0e38f;
    fm_vec3_t bps = seg[0], bpt = seg[0];
    for (int k = 0; k < 12; k++) {
        fm_vec3_t tri[3] = { box_corner(he, box_tris[k][0]), box_corner(he, box_tris[k][1]),
                             box_corner(he, box_tris[k][2]) };
        fm_vec3_t ps, pt;
        float d2 = coll_prim_seg_tri_closest(tri, seg[0], seg[1], &ps, &pt);
        if (d2 < best) { best = d2; bps = ps; bpt = pt; }
    }
    float rin = r - tol;
    if (!(best < rin * rin)) return false;
    float dist = sqrtf(best);
    hit->t = 0.0f;
    hit->depth = r - dist;
    hit->normal = v3_unit_or(v3_sub(bps, bpt), v3(0.0f, 1.0f, 0.0f));
    hit->point = bpt;
    return true;
}

static bool box_sweep_local(const fm_vec3_t seg[2], float r, fm_vec3_t d, fm_vec3_t he, float t_max,
                            float tol, coll_prim_hit_t *hit)
{
    /* quick reject: the swept segment's bounds miss the box grown by r */
    for (int i = 0; i < 3; i++) {
        float a0 = seg[0].v[i], a1 = seg[1].v[i], m = d.v[i] * t_max;
        float lo = f_min(f_min(a0, a1), f_min(a0 + m, a1 + m));
        float hi = f_max(f_max(a0, a1), f_max(a0 + m, a1 + m));
        if (lo > he.v[i] + r || hi < -he.v[i] - r) return false;
    }
    if (box_overlap_local(seg, r, he, tol, hit)) return true;
    /* First contact over the faces that face the motion (a back face's points can only be
     * met after a front face's), then the touch tolerance on the whole box: the motion
     * must go deeper than tol into the box somewhere. */
    bool any = false;
    int front[12], nf = 0;
    for (int k = 0; k < 12; k++) {
        int face = k / 2, axis = face / 2;
        float outward = (face & 1) ? -1.0f : 1.0f;
        if (outward * d.v[axis] <= 0.0f) front[nf++] = k;
    }
    for (int i = 0; i < nf; i++) {
        int k = front[i];
        fm_vec3_t tri[3] = { box_corner(he, box_tris[k][0]), box_corner(he, box_tris[k][1]),
                             box_corner(he, box_tris[k][2]) };
        coll_prim_hit_t h;
        if (coll_prim_tri_sweep_ex(seg, r, &d, tri, any ? hit->t : t_max, false, &h) && (!any || h.t < hit->t)) {
            *hit = h;
            any = true;
        }
    }
    if (!any) return false;
    float rin = r - tol;
    if (hit->t > 0.0f && prim_goes_deeper(r, hit->normal, d, rin, t_max - hit->t)) return true;
    for (int i = 0; i < nf; i++) {
        int k = front[i];
        fm_vec3_t tri[3] = { box_corner(he, box_tris[k][0]), box_corner(he, box_tris[k][1]),
                             box_corner(he, box_tris[k][2]) };
        coll_prim_hit_t h;
        if (coll_prim_tri_sweep_ex(seg, rin, &d, tri, t_max, false, &h)) return true;
    }
    return false;
}

/* ---------------------------------------------------------------- cylinder distance */

/** Closest point of the solid cylinder (local Y axis) to local point p. */
static fm_vec3_t cyl_closest_pt(fm_vec3_t p, float R, float hh)
{
    float rho2 = p.x * p.x + p.z * p.z;
    float k = rho2 > R * R ? R / sqrtf(rho2) : 1.0f;
    return v3(p.x * k, f_max(-hh, f_min(hh, p.y)), p.z * k);
}

/**
 * Squared distance of local segment a..b to the solid cylinder, with closest points.
 * The squared distance along a segment to a convex set is convex with derivative
 * 2 (p - c(p)) . s, so bisection on the sign of that derivative finds the minimum; the
 * sign is computed accurately even where the distance itself is flat.
 */
static float seg_cyl_closest(fm_vec3_t a, fm_vec3_t b, float R, float hh, fm_vec3_t *ps, fm_vec3_t *pc)
{
    fm_vec3_t s = v3_sub(b, a);
    float u = 0.0f;
    if (v3_len2(s) > 1e-14f) {
        fm_vec3_t p0 = a, p1 = b;
        float g0 = v3_dot(v3_sub(p0, cyl_closest_pt(p0, R, hh)), s);
        float g1 = v3_dot(v3_sub(p1, cyl_closest_pt(p1, R, hh)), s);
        if (g0 >= 0.0f) u = 0.0f;
        else if (g1 <= 0.0f) u = 1.0f;
        else {
            float lo = 0.0f, hi = 1.0f;
            for (int it = 0; it < 26; it++) {
                float mid = 0.5f * (lo + hi);
                fm_vec3_t p = v3_madd(a, s, mid);
                float g = v3_dot(v3_sub(p, cyl_closest_pt(p, R, hh)), s);
                if (g < 0.0f) lo = mid;
                else if (g > 0.0f) hi = mid;
                else { lo = hi = mid; break; }
            }
            u = 0.5f * (lo + hi);
        }
    }
    *ps = v3_madd(a, s, u);
    *pc = cyl_closest_pt(*ps, R, hh);
    return v3_len2(v3_sub(*ps, *pc));
}

/** Closest points of a world segment and the cylinder body, results in world frame. */
static float seg_cyl_closest_world(const body_frame_t *f, fm_vec3_t a, fm_vec3_t b, fm_vec3_t *pc, fm_vec3_t *n)
{
    fm_vec3_t la = q_rot_inv(&f->q, v3_sub(a, f->pos)), lb = q_rot_inv(&f->q, v3_sub(b, f->pos)), ps;
    float d2 = seg_cyl_closest(la, lb, f->he.x, f->he.y, &ps, pc);
    /* the direction in the body frame: differences of world points lose it for tiny gaps */
    *n = q_rot(&f->q, v3_unit_or(v3_sub(ps, *pc), v3(0.0f, 0.0f, 0.0f)));
    *pc = v3_add(f->pos, q_rot(&f->q, *pc));
    return d2;
}

/* ---------------------------------------------------------------- libccd (cylinder) */

#define PRIM_CCD_MAX_SUPPORT 400

typedef struct {
    const body_frame_t *f;
    int calls;
    bool capped;
} ccd_body_t;

typedef struct {
    fm_vec3_t a, b;
    float r;
    fm_vec3_t sweep;   /* the capsule swept over [0, sweep] */
} ccd_capsule_t;

static fm_vec3_t from_ccd(const ccd_vec3_t *v) { return v3(v->v[0], v->v[1], v->v[2]); }
static void to_ccd(ccd_vec3_t *out, fm_vec3_t v) { out->v[0] = v.x; out->v[1] = v.y; out->v[2] = v.z; }

static void support_body(const void *obj, const ccd_vec3_t *dir, ccd_vec3_t *out)
{
    ccd_body_t *b = (ccd_body_t *)(uintptr_t)obj;
    fm_vec3_t dw = from_ccd(dir);
    if (++b->calls > PRIM_CCD_MAX_SUPPORT) {
        /* Hard cap on libccd's uncapped loops: a point far behind the search direction
         * makes every MPR phase stop with "no intersection". */
        b->capped = true;
        to_ccd(out, v3_scale(v3_unit_or(dw, v3(0.0f, 1.0f, 0.0f)), -1.0e6f));
        return;
    }
    const body_frame_t *f = b->f;
    fm_vec3_t dl = q_rot_inv(&f->q, dw), p;
    if (f->shape == COLL_SHAPE_CYLINDER) {
        float l = sqrtf(dl.x * dl.x + dl.z * dl.z);
        p = l > 1e-12f ? v3(f->he.x * dl.x / l, 0.0f, f->he.x * dl.z / l) : v3(0.0f, 0.0f, 0.0f);
        p.y = dl.y >= 0.0f ? f->he.y : -f->he.y;
    } else { /* box */
        p = v3(dl.x >= 0.0f ? f->he.x : -f->he.x, dl.y >= 0.0f ? f->he.y : -f->he.y,
                    dl.z >= 0.0f ? f->he.z : -f->he.z);
    }
    to_ccd(out, v3_add(f->pos, q_rot(&f->q, p)));
}

static void center_body(const void *obj, ccd_vec3_t *out)
{
    const ccd_body_t *b = obj;
    to_ccd(out, b->f->pos);
}

static void support_capsule(const void *obj, const ccd_vec3_t *dir, ccd_vec3_t *out)
{
    const ccd_capsule_t *c = obj;
    fm_vec3_t dw = from_ccd(dir);
    fm_vec3_t p = v3_dot(dw, c->a) >= v3_dot(dw, c->b) ? c->a : c->b;
    p = v3_madd(p, v3_unit_or(dw, v3(0.0f, 0.0f, 0.0f)), c->r);
    if (v3_dot(dw, c->sweep) > 0.0f) p = v3_add(p, c->sweep);
    to_ccd(out, p);
}

static void center_capsule(const void *obj, ccd_vec3_t *out)
{
    const ccd_capsule_t *c = obj;
    to_ccd(out, v3_madd(v3_scale(v3_add(c->a, c->b), 0.5f), c->sweep, 0.5f));
}

static void ccd_setup(ccd_t *ccd)
{
    /* CCD_INIT without first_dir: ccdFirstDirDefault lives in libccd's GJK/EPA file (ccd.c),
     * which the console build leaves out; MPR starts from the centres and never reads it. */
    *ccd = (ccd_t){ .epa_tolerance = CCD_REAL(0.0001), .dist_tolerance = CCD_REAL(1E-6) };
    ccd->support1 = support_body;
    ccd->support2 = support_capsule;
    ccd->center1 = center_body;
    ccd->center2 = center_capsule;
    ccd->max_iterations = 64;
    ccd->mpr_tolerance = 1e-6f;
}

static bool ccd_intersect(const ccd_t *ccd, ccd_body_t *b, const ccd_capsule_t *c)
{
    b->calls = 0;
    int res = ccdMPRIntersect(b, c, ccd);
    return res && !b->capped;
}

/** Penetration (depth, normal body -> capsule); false when separated. */
static bool ccd_penetration(const ccd_t *ccd, ccd_body_t *b, const ccd_capsule_t *c, float *depth,
                            fm_vec3_t *n, fm_vec3_t *pos)
{
    ccd_real_t dep;
    ccd_vec3_t dir, p;
    b->calls = 0;
    if (ccdMPRPenetration(b, c, ccd, &dep, &dir, &p) != 0 || b->capped) return false;
    *depth = dep;
    *n = v3_unit_or(from_ccd(&dir), v3(0.0f, 0.0f, 0.0f));
    *pos = from_ccd(&p);
    return f_finite(*depth) && v3_len2(*n) > 0.5f;
}

/** Fallback push-out direction when MPR reports a touch without direction. */
static fm_vec3_t centre_dir(const body_frame_t *f, const fm_vec3_t seg[2])
{
    return v3_unit_or(v3_sub(v3_scale(v3_add(seg[0], seg[1]), 0.5f), f->pos), v3(0.0f, 1.0f, 0.0f));
}

static bool ccd_overlap(const body_frame_t *f, const fm_vec3_t seg[2], float r, float tol, coll_prim_hit_t *hit)
{
    /* Segment outside the solid: exact distance and direction from the closest points. */
    fm_vec3_t pc, nn;
    float d2 = seg_cyl_closest_world(f, seg[0], seg[1], &pc, &nn);
    if (d2 > 1e-10f) {
        float rin = r - tol;
        if (!(d2 < rin * rin)) return false;
        float dist = sqrtf(d2);
        hit->t = 0.0f;
        hit->depth = r - dist;
        hit->normal = v3_len2(nn) > 0.5f ? nn : centre_dir(f, seg);
        hit->point = pc;
        return true;
    }
    /* Segment inside or through the solid: MPR penetration along the centre line. */
    ccd_t ccd;
    ccd_setup(&ccd);
    ccd_body_t b = { f, 0, false };
    ccd_capsule_t c = { seg[0], seg[1], r, v3(0.0f, 0.0f, 0.0f) };
    float depth;
    fm_vec3_t n, p;
    if (!ccd_intersect(&ccd, &b, &c)) return false;
    if (!ccd_penetration(&ccd, &b, &c, &depth, &n, &p)) return false;
    if (!(depth > tol)) return false;
    hit->t = 0.0f;
    hit->depth = depth;
    hit->normal = n;
    hit->point = p;
    return true;
}

#ifdef COLL_METHOD_HOOKS
static bool g_force_mpr;
void coll_set_body_sweep_mpr(bool force) { g_force_mpr = force; }
#else
#define g_force_mpr false /* the library proper: MPR only where Newton does not settle */
#endif

/** MPR time of impact (the fallback): bisection on the body against the capsule swept
 *  over [0, t], a convex shape that grows with t, so the test is monotone. */
static bool ccd_sweep_mpr(const body_frame_t *f, const fm_vec3_t seg[2], float r, fm_vec3_t d, float t_max,
                          float tol, float *t_hit)
{
    float dl = sqrtf(v3_len2(d)) * t_max;
    ccd_t ccd;
    ccd_setup(&ccd);
    ccd_body_t b = { f, 0, false };
    /* the motion must take the capsule deeper than the tolerance somewhere */
    ccd_capsule_t c = { seg[0], seg[1], r - tol, v3_scale(d, t_max) };
    if (!ccd_intersect(&ccd, &b, &c)) return false;
    c.r = r;
    float lo = 0.0f, hi = t_max;
    c.sweep = v3(0.0f, 0.0f, 0.0f);
    if (ccd_intersect(&ccd, &b, &c)) {
        *t_hit = 0.0f;
        return true;
    }
    /* to 2e-5 m along the motion (the normal comes from exact closest points) */
    for (int it = 0; it < 40 && (hi - lo) * dl > 2e-5f * t_max; it++) {
        float mid = 0.5f * (lo + hi);
        c.sweep = v3_scale(d, mid);
        if (ccd_intersect(&ccd, &b, &c)) hi = mid; else lo = mid;
    }
    *t_hit = lo;
    return true;
}

/** Distance of the moving capsule's segment at time t to the cylinder, normal, point. */
static float cyl_dist_at(const body_frame_t *f, const fm_vec3_t seg[2], fm_vec3_t d, float t,
                         fm_vec3_t *n, fm_vec3_t *p)
{
    float d2 = seg_cyl_closest_world(f, v3_madd(seg[0], d, t), v3_madd(seg[1], d, t), p, n);
    if (!(v3_len2(*n) > 0.5f)) *n = centre_dir(f, seg);
    return sqrtf(d2);
}

/**
 * First t in [t0, t_max] where the distance reaches `target`, by Newton steps on the
 * exact distance f(t) (convex in t, derivative n . d): from the left of the root the
 * tangent of a convex function stays below it, so every step lands at or before the root.
 * Returns 1 (hit, t/n/p set), 0 (no hit), -1 (not converged: use the MPR fallback).
 */
static int cyl_newton(const body_frame_t *f, const fm_vec3_t seg[2], fm_vec3_t d, float target, float t0,
                      float t_max, float *t_out, fm_vec3_t *n, fm_vec3_t *p)
{
    float t = t0, dl = sqrtf(v3_len2(d));
    const float eps = 2e-7f * (1.0f + target);
    for (int it = 0; it < 24; it++) {
        float dist = cyl_dist_at(f, seg, d, t, n, p);
        float gap = dist - target;
        if (gap <= eps && gap >= -eps) { *t_out = t; return 1; }
        float slope = -v3_dot(*n, d);
        if (!(slope > 0.0f)) return gap > 0.0f ? 0 : -1; /* at its minimum: it only grows from here */
        /* A rounded slope can overshoot a long step: shorten long steps a little, and a
         * step that did land inside (gap < 0) steps back onto the left of the root. */
        float step = gap / slope;
        if (gap > 1e3f * eps) step *= 0.9998f;
        if (t + step > t_max) return 0;      /* f >= its tangent > target up to t_max */
        t += step;
        if (t < t0) return -1;
        if (step * dl < 1e-7f && step * dl > -1e-7f) { *t_out = t; cyl_dist_at(f, seg, d, t, n, p); return 1; }
    }
    return -1;
}

static bool ccd_sweep(const body_frame_t *f, const fm_vec3_t seg[2], float r, fm_vec3_t d, float t_max,
                      float tol, coll_prim_hit_t *hit)
{
    if (ccd_overlap(f, seg, r, tol, hit)) return true;
    if (!(v3_len2(d) * t_max * t_max > 1e-18f)) return false;
    float rin = r - tol, t = 0.0f;
    fm_vec3_t n, p;
    float dist = cyl_dist_at(f, seg, d, 0.0f, &n, &p);
    if (dist > r) {
        int res = g_force_mpr ? -1 : cyl_newton(f, seg, d, r, 0.0f, t_max, &t, &n, &p);
        if (res == 0) return false;
        if (res < 0) {
            if (!ccd_sweep_mpr(f, seg, r, d, t_max, tol, &t)) return false;
            cyl_dist_at(f, seg, d, t, &n, &p);
        }
        dist = r;
    }
    /* the motion must take the capsule deeper than the tolerance */
    if (!prim_goes_deeper(dist, n, d, rin, t_max - t)) {
        float t2;
        fm_vec3_t n2, p2;
        int res = g_force_mpr ? -1 : cyl_newton(f, seg, d, rin, t, t_max, &t2, &n2, &p2);
        if (res == 0) return false;
        if (res < 0 && !ccd_sweep_mpr(f, seg, r, d, t_max, tol, &t2)) return false;
    }
    hit->t = t;
    hit->depth = 0.0f;
    hit->normal = n;
    hit->point = p;
    return true;
}

/* ---------------------------------------------------------------- capsule vs body */

bool coll_capsule_body_sweep(const fm_vec3_t seg[2], float r, const fm_vec3_t *disp,
                             const coll_body_t *body, const fm_vec3_t *body_pos_rel,
                             float t_max, coll_prim_hit_t *hit)
{
    body_frame_t f;
    if (!hit || !disp || !seg_ok(seg, r) || !prim_sane3(*disp) || !(t_max >= 0.0f) || !prim_sane(t_max) ||
        !prim_sane3(v3_scale(*disp, t_max)))
        return false;
    if (!body_setup(body, body_pos_rel, &f)) return false;
    const float tol = f_min(COLL_PRIM_TOUCH_TOL, 0.25f * r);
    switch (f.shape) {
    case COLL_SHAPE_SPHERE:
    case COLL_SHAPE_CAPSULE: {
        /* Cheap exact reject first: the segments farther apart at the start than the two
         * radii plus the whole motion cannot meet (the general sweep below costs ~5k). */
        fm_vec3_t ax[3], cp, cq;
        float reach = r + f.he.x + sqrtf(v3_dot(*disp, *disp)) * t_max;
        if (round_axis_dist2(&f, seg, ax, &cp, &cq) > reach * reach * 1.0001f + 1e-8f) return false;
        if (!coll_capsule_triangle_sweep(seg, r + f.he.x, disp, ax, t_max, hit)) return false;
        hit->point = v3_madd(hit->point, hit->normal, f.he.x);
        return true;
    }
    case COLL_SHAPE_BOX: {
        fm_vec3_t ls[2] = { q_rot_inv(&f.q, v3_sub(seg[0], f.pos)), q_rot_inv(&f.q, v3_sub(seg[1], f.pos)) };
        fm_vec3_t ld = q_rot_inv(&f.q, *disp);
        if (!box_sweep_local(ls, r, ld, f.he, t_max, tol, hit)) return false;
        hit->normal = q_rot(&f.q, hit->normal);
        hit->point = v3_add(f.pos, q_rot(&f.q, hit->point));
        return true;
    }
    case COLL_SHAPE_CYLINDER:
    default:
        return ccd_sweep(&f, seg, r, *disp, t_max, tol, hit);
    }
}

bool coll_capsule_body_overlap(const fm_vec3_t seg[2], float r, const coll_body_t *body,
                               const fm_vec3_t *body_pos_rel, coll_prim_hit_t *hit)
{
    body_frame_t f;
    if (!hit || !seg_ok(seg, r)) return false;
    if (!body_setup(body, body_pos_rel, &f)) return false;
    const float tol = f_min(COLL_PRIM_TOUCH_TOL, 0.25f * r);
    switch (f.shape) {
    case COLL_SHAPE_SPHERE:
    case COLL_SHAPE_CAPSULE: {
        /* Round shapes against the capsule: the closest points of the two axes are the
         * whole answer (what the general triangle path would compute, without its setup). */
        fm_vec3_t ax[3], cp, cq;
        float reach = r + f.he.x;
        float d2 = round_axis_dist2(&f, seg, ax, &cp, &cq);
        float rin = reach - f_min(COLL_PRIM_TOUCH_TOL, 0.25f * reach);
        if (!(d2 < rin * rin)) return false;
        float d = sqrtf(d2);
        if (!(d > 1e-6f)) { /* the axes cross: the general path picks a careful push-out */
            if (!coll_capsule_triangle_overlap(seg, reach, ax, hit)) return false;
            hit->point = v3_madd(hit->point, hit->normal, f.he.x);
            return true;
        }
        fm_vec3_t n = v3_scale(v3_sub(cp, cq), 1.0f / d);
        hit->t = 0.0f;
        hit->depth = reach - d;
        hit->normal = n;
        hit->point = v3_madd(cq, n, f.he.x);
        return true;
    }
    case COLL_SHAPE_BOX: {
        fm_vec3_t ls[2] = { q_rot_inv(&f.q, v3_sub(seg[0], f.pos)), q_rot_inv(&f.q, v3_sub(seg[1], f.pos)) };
        if (!box_overlap_local(ls, r, f.he, tol, hit)) return false;
        hit->normal = q_rot(&f.q, hit->normal);
        hit->point = v3_add(f.pos, q_rot(&f.q, hit->point));
        return true;
    }
    case COLL_SHAPE_CYLINDER:
    default:
        return ccd_overlap(&f, seg, r, tol, hit);
    }
}
