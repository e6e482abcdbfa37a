/* Soak harness: the independent double-precision brute-force checker.
 * It never calls the library's queries: it works on the generator's own triangle data
 * (world-space doubles for static pieces, re-transformed in double for moving ones) and
 * on the collider bodies' shape parameters. */
#include "soak_sim.h"
#include <math.h>
#include <string.h>

static double dot3(const double a[3], const double b[3]) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
static void sub3(double o[3], const double a[3], const double b[3]) { o[0] = a[0] - b[0]; o[1] = a[1] - b[1]; o[2] = a[2] - b[2]; }
static void cross3(double o[3], const double a[3], const double b[3])
{
    double t[3] = {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
    memcpy(o, t, sizeof t);
}
static double dist3(const double a[3], const double b[3])
{
    double d[3]; sub3(d, a, b); return sqrt(dot3(d, d));
}
static double clamp01(double x) { return x < 0 ? 0 : (x > 1 ? 1 : x); }

/* Closest point on triangle abc to p (Ericson, Real-Time Collision Detection 5.1.5). */
static void closest_pt_tri(double out[3], const double p[3], const double a[3], const double b[3], const double c[3])
{
    double ab[3], ac[3], ap[3], bp[3], cp[3];
    sub3(ab, b, a); sub3(ac, c, a); sub3(ap, p, a);
    double d1 = dot3(ab, ap), d2 = dot3(ac, ap);
    if (d1 <= 0 && d2 <= 0) { memcpy(out, a, 3 * sizeof(double)); return; }
    sub3(bp, p, b);
    double d3 = dot3(ab, bp), d4 = dot3(ac, bp);
    if (d3 >= 0 && d4 <= d3) { memcpy(out, b, 3 * sizeof(double)); return; }
    double vc = d1 * d4 - d3 * d2;
    if (vc <= 0 && d1 >= 0 && d3 <= 0) {
        double v = d1 / (d1 - d3);
        for (int k = 0; k < 3; k++) out[k] = a[k] + v * ab[k];
        return;
    }
    sub3(cp, p, c);
    double d5 = dot3(ab, cp), d6 = dot3(ac, cp);
    if (d6 >= 0 && d5 <= d6) { memcpy(out, c, 3 * sizeof(double)); return; }
    double vb = d5 * d2 - d1 * d6;
    if (vb <= 0 && d2 >= 0 && d6 <= 0) {
        double w = d2 / (d2 - d6);
        for (int k = 0; k < 3; k++) out[k] = a[k] + w * ac[k];
        return;
    }
    double va = d3 * d6 - d5 * d4;
    if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {
        double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
        for (int k = 0; k < 3; k++) out[k] = b[k] + w * (c[k] - b[k]);
        return;
    }
    double denom = 1.0 / (va + vb + vc);
    double v = vb * denom, w = vc * denom;
    for (int k = 0; k < 3; k++) out[k] = a[k] + ab[k] * v + ac[k] * w;
}

double soak_seg_seg_dist(const double p1[3], const double q1[3], const double p2[3], const double q2[3])
{
    double d1[3], d2[3], r[3];
    sub3(d1, q1, p1); sub3(d2, q2, p2); sub3(r, p1, p2);
    double a = dot3(d1, d1), e = dot3(d2, d2), f = dot3(d2, r);
    double s, t;
    const double eps = 1e-18;
    if (a <= eps && e <= eps) return dist3(p1, p2);
    if (a <= eps) { s = 0; t = clamp01(f / e); }
    else {
        double c = dot3(d1, r);
        if (e <= eps) { t = 0; s = clamp01(-c / a); }
        else {
            double b = dot3(d1, d2), denom = a * e - b * b;
            s = denom > 0 ? clamp01((b * f - c * e) / denom) : 0;
            t = (b * s + f) / e;
            if (t < 0) { t = 0; s = clamp01(-c / a); }
            else if (t > 1) { t = 1; s = clamp01((b - c) / a); }
        }
    }
    double c1[3], c2[3];
    for (int k = 0; k < 3; k++) { c1[k] = p1[k] + d1[k] * s; c2[k] = p2[k] + d2[k] * t; }
    return dist3(c1, c2);
}

double soak_seg_tri_dist(const double p0[3], const double p1[3], const double *v0, const double *v1,
                         const double *v2)
{
    const double *v[3] = {v0, v1, v2};
    double e1[3], e2[3], n[3];
    sub3(e1, v[1], v[0]); sub3(e2, v[2], v[0]);
    cross3(n, e1, e2);
    double nn = dot3(n, n);
    if (nn > 0) {
        double a0[3], a1[3];
        sub3(a0, p0, v[0]); sub3(a1, p1, v[0]);
        double s0 = dot3(n, a0), s1 = dot3(n, a1);
        if ((s0 <= 0 && s1 >= 0) || (s0 >= 0 && s1 <= 0)) {
            if (s0 != s1) {
                double t = s0 / (s0 - s1), x[3], c[3];
                for (int k = 0; k < 3; k++) x[k] = p0[k] + (p1[k] - p0[k]) * t;
                closest_pt_tri(c, x, v[0], v[1], v[2]);
                if (dist3(c, x) <= 1e-12) return 0.0;
            }
        }
    }
    double best, d, c[3];
    closest_pt_tri(c, p0, v[0], v[1], v[2]); best = dist3(c, p0);
    closest_pt_tri(c, p1, v[0], v[1], v[2]); d = dist3(c, p1); if (d < best) best = d;
    for (int k = 0; k < 3; k++) {
        d = soak_seg_seg_dist(p0, p1, v[k], v[(k + 1) % 3]);
        if (d < best) best = d;
    }
    return best;
}

/* Distance from point to segment. */
static double pt_seg_dist(const double p[3], const double a[3], const double b[3])
{
    double ab[3], ap[3];
    sub3(ab, b, a); sub3(ap, p, a);
    double l = dot3(ab, ab), t = l > 0 ? clamp01(dot3(ap, ab) / l) : 0;
    double c[3] = {a[0] + ab[0] * t, a[1] + ab[1] * t, a[2] + ab[2] * t};
    return dist3(c, p);
}

void soak_body_capsules(const char_body_t *b, soak_capsule_t *full, soak_capsule_t *sweep)
{
    soak_capsules_at(&b->settings, *b->owner_pos, full, sweep);
}

static bool tri_seen(uint8_t mask, const char_body_settings_t *s)
{
    return (s->coll_types & COLL_TYPE_MESH) && (mask & s->read_mask);
}

/* Penetration the seed accepts on a walkable triangle: the probe stands the foot POINT on
 * it, and the sweep capsule's bottom ball (centre r + step above the foot) then reaches
 * r - (r + step) cos(slope) into a slope. The seed asks users to pick radius/step so this
 * is <= 0 ("the maximum angle must not collide with the sweep capsule"); the generator
 * mostly does, and when it does not, this much is tolerated on walkable triangles only. */
static double walkable_allowance(const soak_wtri_t *w, const char_body_settings_t *s, const double mid[3])
{
    double e1[3], e2[3], n[3], d[3];
    sub3(e1, w->v[1], w->v[0]); sub3(e2, w->v[2], w->v[0]);
    cross3(n, e1, e2);
    double l = sqrt(dot3(n, n));
    if (!(l > 0)) return 0;
    sub3(d, mid, w->v[0]);
    if (dot3(n, d) < 0) l = -l;
    double up[3] = {s->up.x, s->up.y, s->up.z};
    double cs = dot3(n, up) / l;
    if (cs < cos((double)s->floor_max_angle) - 1e-4) return 0;
    double a = (double)s->radius - ((double)s->radius + s->step_height) * cs;
    return a > 0 ? a : 0;
}

/* One pass over the seen static triangles near cap: the largest penetration beyond the
 * walkable allowance (its triangle and raw depth), and the deepest raw penetration. */
static double static_pen_scan(const soak_level_t *lvl, const char_body_settings_t *s, const soak_capsule_t *cap,
                              int32_t *tri_out, double *raw_out, double *deepest_out)
{
    double best = 0, raw = 0, deepest = 0;
    int32_t bt = -1;
    double mid[3], half = dist3(cap->a, cap->b) * 0.5;
    for (int k = 0; k < 3; k++) mid[k] = (cap->a[k] + cap->b[k]) * 0.5;
    for (uint32_t i = 0; i < lvl->nwtris; i++) {
        const soak_wtri_t *w = &lvl->wtris[i];
        if (!tri_seen(w->mask, s)) continue;
        if (dist3(mid, w->c) > half + cap->r + w->rad) continue;
        double d = soak_seg_tri_dist(cap->a, cap->b, w->v[0], w->v[1], w->v[2]);
        double pen = cap->r - d;
        if (pen <= 0) continue;
        if (pen > deepest) deepest = pen;
        double ex = pen - walkable_allowance(w, s, mid);
        if (ex > best) { best = ex; bt = (int32_t)i; raw = pen; }
    }
    if (tri_out) *tri_out = bt;
    if (raw_out) *raw_out = raw;
    if (deepest_out) *deepest_out = deepest;
    return best;
}

double soak_check_static_pen(const soak_level_t *lvl, const char_body_settings_t *s,
                             const soak_capsule_t *cap, int32_t *tri_out, double *raw_out)
{
    return static_pen_scan(lvl, s, cap, tri_out, raw_out, NULL);
}

/* The overlap the body's recover pushes out of at a step's start: the deepest raw
 * penetration (r - distance) of cap into a seen static triangle, the walkable allowance
 * not taken off (the recover does not know the seed's rule: a sweep capsule 0.8 mm into
 * a walkable slope that the allowance tolerates is pushed 1.3 mm out along its normal,
 * soak s25 l6), or into a seen static collider body (sphere, box, capsule: the recover
 * pushes out of every contact, a body's too; an airborne body 0.56 mm into a static
 * capsule body was pushed 1.06 mm out, soak s58 l109), at most SOAK_PEN_TOL (deeper,
 * beyond the allowance, the step is exempt; within it, no more push-out is tolerated than
 * for a real overlap). Moving bodies are not counted: within 0.5 m they exempt the step. */
double soak_check_pushout_depth(const soak_level_t *lvl, const char_body_settings_t *s, const soak_capsule_t *cap)
{
    double deepest;
    static_pen_scan(lvl, s, cap, NULL, NULL, &deepest);
    double body = soak_check_body_pen(lvl, s, cap);
    if (body > deepest) deepest = body;
    return deepest < SOAK_PEN_TOL ? deepest : SOAK_PEN_TOL;
}

/* Signed crossings of the ray from p along dir with the seen triangles of closed pieces:
 * +1 leaving through a front face (by winding: the outside of its solid), -1 entering. The
 * sum is the number of closed solids (boxes of a staircase overlap: each counts) around p. */
static int closed_winding(const soak_level_t *lvl, const char_body_settings_t *s, const double p[3], const double dir[3])
{
    int wn = 0;
    for (uint32_t i = 0; i < lvl->nwtris; i++) {
        const soak_wtri_t *w = &lvl->wtris[i];
        if (!w->closed || !tri_seen(w->mask, s)) continue;
        double e1[3], e2[3], h[3], q[3], t0[3];
        sub3(e1, w->v[1], w->v[0]); sub3(e2, w->v[2], w->v[0]);
        cross3(h, dir, e2);
        double det = dot3(e1, h);
        if (fabs(det) < 1e-14) continue;
        sub3(t0, p, w->v[0]);
        double u = dot3(t0, h) / det;
        if (u < 0 || u > 1) continue;
        cross3(q, t0, e1);
        double v = dot3(dir, q) / det;
        if (v < 0 || u + v > 1) continue;
        if (dot3(e2, q) / det <= 0) continue;
        double n[3];
        cross3(n, e1, e2);
        const bool out = dot3(n, dir) > 0; /* through its front face */
        wn += out == (w->closed != 2) ? 1 : -1; /* (2: its back face is the outside) */
    }
    return wn;
}

bool soak_check_inside_closed(const soak_level_t *lvl, const char_body_settings_t *s, const double p[3])
{
    /* two rays in directions no generated edge or face lies along: both must agree (a ray
     * through an edge shared by two triangles counts it twice or not at all). Both go up:
     * a solid standing on the room floor may have no bottom face (a V valley's wedges, the
     * floor closes them: soak s31 l310), and a ray down would leave it through the floor
     * uncounted. */
    static const double d1[3] = {0.3713906763541037, 0.8121168928170934, 0.4501390297069412};
    static const double d2[3] = {-0.5773502691896258, 0.6172133998483676, 0.5345224838248488};
    return closed_winding(lvl, s, p, d1) > 0 && closed_winding(lvl, s, p, d2) > 0;
}

/* double transform of a point by an instance transform */
static void xf_point(double out[3], const coll_transform_t *xf, const double lp[3])
{
    double q[4] = {xf->rot.x, xf->rot.y, xf->rot.z, xf->rot.w};
    double v[3] = {lp[0] * xf->scale.x, lp[1] * xf->scale.y, lp[2] * xf->scale.z};
    double u[3] = {q[0], q[1], q[2]}, t[3], t2[3];
    cross3(t, u, v);
    for (int k = 0; k < 3; k++) t[k] *= 2.0;
    cross3(t2, u, t);
    for (int k = 0; k < 3; k++) out[k] = v[k] + q[3] * t[k] + t2[k] + (double)xf->pos.v[k];
}
/* inverse rigid transform (bodies ignore scale) */
static void xf_inv_rigid(double out[3], const coll_transform_t *xf, const double wp[3])
{
    double v[3] = {wp[0] - xf->pos.x, wp[1] - xf->pos.y, wp[2] - xf->pos.z};
    double u[3] = {-(double)xf->rot.x, -(double)xf->rot.y, -(double)xf->rot.z}, w = xf->rot.w, t[3], t2[3];
    cross3(t, u, v);
    for (int k = 0; k < 3; k++) t[k] *= 2.0;
    cross3(t2, u, t);
    for (int k = 0; k < 3; k++) out[k] = v[k] + w * t[k] + t2[k];
}

static double body_dist(const soak_lbody_t *lb, const soak_capsule_t *cap)
{
    const coll_body_t *b = &lb->body;
    double a[3], bb[3];
    xf_inv_rigid(a, &b->xf, cap->a);
    xf_inv_rigid(bb, &b->xf, cap->b);
    double hx = b->half_extents.x, hy = b->half_extents.y, hz = b->half_extents.z;
    switch (b->shape) {
    case COLL_SHAPE_SPHERE: {
        double o[3] = {0, 0, 0};
        return pt_seg_dist(o, a, bb) - hx;
    }
    case COLL_SHAPE_CAPSULE:
    case COLL_SHAPE_CYLINDER: { /* a cylinder lies inside its capsule: a lower bound */
        double p[3] = {0, -hy, 0}, q[3] = {0, hy, 0};
        return soak_seg_seg_dist(a, bb, p, q) - hx;
    }
    case COLL_SHAPE_BOX: {
        for (int e = 0; e < 2; e++) {
            const double *pt = e ? bb : a;
            if (fabs(pt[0]) <= hx && fabs(pt[1]) <= hy && fabs(pt[2]) <= hz) return 0;
        }
        double best = 1e300;
        for (int ax = 0; ax < 3; ax++)
            for (int sgn = -1; sgn <= 1; sgn += 2) {
                double h[3] = {hx, hy, hz}, v[4][3];
                int u = (ax + 1) % 3, w = (ax + 2) % 3;
                for (int k = 0; k < 4; k++) {
                    v[k][ax] = sgn * h[ax];
                    v[k][u] = ((k == 1 || k == 2) ? 1 : -1) * h[u];
                    v[k][w] = ((k >= 2) ? 1 : -1) * h[w];
                }
                double t1[3][3], t2[3][3];
                memcpy(t1[0], v[0], sizeof v[0]); memcpy(t1[1], v[1], sizeof v[0]); memcpy(t1[2], v[2], sizeof v[0]);
                memcpy(t2[0], v[0], sizeof v[0]); memcpy(t2[1], v[2], sizeof v[0]); memcpy(t2[2], v[3], sizeof v[0]);
                double d = soak_seg_tri_dist(a, bb, t1[0], t1[1], t1[2]);
                if (d < best) best = d;
                d = soak_seg_tri_dist(a, bb, t2[0], t2[1], t2[2]);
                if (d < best) best = d;
            }
        return best;
    }
    }
    return 1e300;
}

double soak_check_body_pen(const soak_level_t *lvl, const char_body_settings_t *s, const soak_capsule_t *cap)
{
    double best = 0;
    if (!(s->coll_types & COLL_TYPE_BODY)) return 0;
    for (uint32_t i = 0; i < lvl->nbodies; i++) {
        const soak_lbody_t *lb = &lvl->bodies[i];
        if (lb->moving || lb->body.shape == COLL_SHAPE_CYLINDER || !(lb->body.write_mask & s->read_mask)) continue;
        double d = body_dist(lb, cap);
        if (d < 0) d = 0;
        if (cap->r - d > best) best = cap->r - d;
    }
    return best;
}

/* Nearest of the level's static and moving triangles seen by s to a shape within `half` of
 * `mid` (the bound that skips far triangles), by dist(triangle, ctx). */
typedef double (*tri_dist_fn)(const double *t0, const double *t1, const double *t2, const void *ctx);
/* nearest_tri for what lies within `limit`: triangles farther are skipped (the result is
 * `limit` when none is nearer) */
static double nearest_tri_within(const soak_level_t *lvl, const char_body_settings_t *s, const double mid[3],
                                 double half, double limit, tri_dist_fn dist, const void *ctx)
{
    double best = limit;
    for (uint32_t i = 0; i < lvl->nwtris; i++) {
        const soak_wtri_t *w = &lvl->wtris[i];
        if (!tri_seen(w->mask, s)) continue;
        if (dist3(mid, w->c) - half - w->rad > best) continue;
        double d = dist(w->v[0], w->v[1], w->v[2], ctx);
        if (d < best) best = d;
    }
    for (uint32_t i = 0; i < lvl->npieces; i++) {
        const soak_piece_t *p = &lvl->pieces[i];
        if (!p->moving || !tri_seen(p->inst.write_mask, s)) continue;
        double pc[3] = {p->inst.xf.pos.x, p->inst.xf.pos.y, p->inst.xf.pos.z};
        double sc = fabs(p->inst.xf.scale.x);
        if (fabs(p->inst.xf.scale.y) > sc) sc = fabs(p->inst.xf.scale.y);
        if (fabs(p->inst.xf.scale.z) > sc) sc = fabs(p->inst.xf.scale.z);
        if (dist3(mid, pc) - half - p->bound_radius * sc * 1.001 > best) continue;
        for (uint32_t t = 0; t < p->ntris; t++) {
            double v[3][3];
            for (int j = 0; j < 3; j++) {
                const float *lv = lvl->verts + (size_t)(p->first_vert + lvl->idx[(p->first_tri + t) * 3 + (uint32_t)j]) * 3;
                double l3[3] = {lv[0], lv[1], lv[2]};
                xf_point(v[j], &p->inst.xf, l3);
            }
            double d = dist(v[0], v[1], v[2], ctx);
            if (d < best) best = d;
        }
    }
    return best;
}

static double nearest_tri(const soak_level_t *lvl, const char_body_settings_t *s, const double mid[3], double half,
                          tri_dist_fn dist, const void *ctx)
{
    return nearest_tri_within(lvl, s, mid, half, 1e300, dist, ctx);
}

static double seg_dist_cb(const double *t0, const double *t1, const double *t2, const void *ctx)
{
    const soak_capsule_t *cap = ctx;
    return soak_seg_tri_dist(cap->a, cap->b, t0, t1, t2);
}

double soak_check_nearest(const soak_level_t *lvl, const char_body_settings_t *s, const soak_capsule_t *cap)
{
    double mid[3], half = dist3(cap->a, cap->b) * 0.5;
    for (int k = 0; k < 3; k++) mid[k] = (cap->a[k] + cap->b[k]) * 0.5;
    double best = nearest_tri(lvl, s, mid, half, seg_dist_cb, cap); /* segment distance */
    if (s->coll_types & COLL_TYPE_BODY) {
        for (uint32_t i = 0; i < lvl->nbodies; i++) {
            const soak_lbody_t *lb = &lvl->bodies[i];
            if (!(lb->body.write_mask & s->read_mask)) continue;
            double d = body_dist(lb, cap);
            if (d < 0) d = 0;
            if (d < best) best = d;
        }
    }
    return best - cap->r;
}

/* ------------------------------------------------------------------ behaviour oracles */

void soak_capsules_at(const char_body_settings_t *s, fm_vec3_t o, soak_capsule_t *full, soak_capsule_t *sweep)
{
    double c[3] = {(double)o.x + s->center_offset.x, (double)o.y + s->center_offset.y,
                   (double)o.z + s->center_offset.z};
    double up[3] = {s->up.x, s->up.y, s->up.z};
    double h = (double)s->height * 0.5 - s->radius;
    if (h < 0) h = 0;
    double step = s->step_height;
    for (int k = 0; k < 3; k++) {
        full->a[k] = c[k] - up[k] * h;
        full->b[k] = c[k] + up[k] * h;
        sweep->a[k] = c[k] - up[k] * (h - step);
        sweep->b[k] = full->b[k];
    }
    full->r = sweep->r = s->radius;
}

/* Unit normal of w oriented along up (n.up >= 0); false for a degenerate triangle. */
static bool tri_normal_up(const soak_wtri_t *w, const double up[3], double n[3])
{
    double e1[3], e2[3];
    sub3(e1, w->v[1], w->v[0]); sub3(e2, w->v[2], w->v[0]);
    cross3(n, e1, e2);
    double l = sqrt(dot3(n, n));
    if (!(l > 0)) return false;
    if (dot3(n, up) < 0) l = -l;
    for (int k = 0; k < 3; k++) n[k] /= l;
    return true;
}

/* Walkable (collision is double-sided: either face) and the seed's slope allowance of the
 * sweep capsule's bottom ball, as a height along up (0 on flat floors or when the seed's
 * rule holds). */
/* The cosine tolerance of tri_walkable: a face within 1e-4 of the floor angle's cosine is
 * walkable for the checker, either way of it, since the body's float may judge it either
 * way. soak_check_footing_steep turns it round (-1e-4) for a body that judged the face
 * it stands on steep: a face in that band is then steep for the footing too. */
static double walk_cos_tol = 1e-4;
/* For a body claiming a walkable floor (the footing verdict, foot85), the band below
 * the floor angle's cosine is the reach of the body's float on this face, not 1e-4: its
 * face normal is a float cross product of two edges, off by a few float steps of
 * |e1||e2| / |e1 x e2| (large on a sliver), then rotated and dotted with up. A face steeper
 * than that is steep for the body too, and a foot in it is the step zone beside a wall, not
 * under a floor (soak s140 l405: a wall 56.9744 degrees off up for a floor angle of
 * 56.9731, cosines 2.0e-5 apart; the body stood on the room floor with its step zone
 * 23.6 mm into the wall). Within the reach the face is walkable as before, either way. */
static bool walk_float_reach = false;

static double face_float_reach(const soak_wtri_t *w)
{
    double e1[3], e2[3], n[3];
    sub3(e1, w->v[1], w->v[0]); sub3(e2, w->v[2], w->v[0]);
    cross3(n, e1, e2);
    const double l = sqrt(dot3(n, n));
    return 32.0 * ldexp(1.0, -24) * sqrt(dot3(e1, e1) * dot3(e2, e2)) / l; /* 32 float steps */
}

static bool tri_walkable(const soak_wtri_t *w, const char_body_settings_t *s, const double up[3], double n[3],
                         double *allow_up)
{
    if (!tri_normal_up(w, up, n)) return false;
    double cs = dot3(n, up), tol = walk_cos_tol;
    if (walk_float_reach && tol > 0) {
        const double reach = face_float_reach(w);
        if (reach < tol) tol = reach;
    }
    if (cs < cos((double)s->floor_max_angle) - tol) return false;
    double a = (double)s->radius - ((double)s->radius + s->step_height) * cs;
    *allow_up = a > 0 ? a / cs : 0;
    return true;
}

/* The face tri_walkable found walkable (the one facing up) is the inside of a closed
 * solid (its winding faces away from up: the front face is an underside, the back face
 * looks into the solid). No body stands on it: a foot above it would be inside the solid.
 * Under a tilted up the side of a tile leans over the crack beside it by less than the
 * floor angle, seen from inside (soak s4 l20: up 48 degrees off vertical, a tile side
 * 43.4 degrees off up from inside): the foot in the crack is under the tile's overhang,
 * not under a floor. A piece not known closed (a single quad, a triangle soup, a map)
 * counts either face as before. */
static bool inside_face(const soak_wtri_t *w, const double up[3])
{
    if (!w->closed) return false;
    double e1[3], e2[3], n[3];
    sub3(e1, w->v[1], w->v[0]); sub3(e2, w->v[2], w->v[0]);
    cross3(n, e1, e2);
    return w->closed == 2 ? dot3(n, up) > 0 : dot3(n, up) < 0; /* (2: its back face is the outside) */
}

static void foot_point(const char_body_settings_t *s, fm_vec3_t owner, double up[3], double f[3], double *r)
{
    soak_capsule_t full, sweep;
    soak_capsules_at(s, owner, &full, &sweep);
    up[0] = s->up.x; up[1] = s->up.y; up[2] = s->up.z;
    for (int k = 0; k < 3; k++) f[k] = full.a[k] - up[k] * full.r;
    *r = full.r;
}

static double pt_tri_dist(const double p[3], const soak_wtri_t *w)
{
    double c[3];
    closest_pt_tri(c, p, w->v[0], w->v[1], w->v[2]);
    return dist3(c, p);
}

/* How far the ball (centre bc, radius r) must be raised along up to clear triangle w:
 * 0 when it does not overlap it, -1 when no raise up to top clears it (bisection, 40
 * steps, in [0, top]). */
static double raise_to_clear(const double bc[3], const double up[3], double r, const soak_wtri_t *w, double top)
{
    double lo = 0, hi = top, p[3];
    if (pt_tri_dist(bc, w) >= r) return 0;
    for (int k = 0; k < 3; k++) p[k] = bc[k] + up[k] * hi;
    if (pt_tri_dist(p, w) < r) return -1;
    for (int it = 0; it < 40; it++) {
        double mid = 0.5 * (lo + hi);
        for (int k = 0; k < 3; k++) p[k] = bc[k] + up[k] * mid;
        if (pt_tri_dist(p, w) >= r) hi = mid; else lo = mid;
    }
    return hi;
}

int32_t soak_footing_tri = -1; /* the triangle of the last soak_check_footing result (diagnosis) */
int32_t soak_footing_tri2 = -1; /* the other triangle of its crack pair, or -1: under the foot */
int soak_footing_ncontacts = 0; /* contacts around the foot of the crack case, 0: under the foot */
double soak_footing_widest = 0; /* their widest angular gap across up, rad */

/* Footing, case 2: the triangles of the first n contacts in ord (ctri) all lie on one
 * side of a line across up beside the foot: the directions from the ball centre bc to
 * their vertices, across up, leave a gap wider than 180 degrees (e1, e2: a basis across
 * up). That is a ledge (the straight border of a tile field beside the foot), which the
 * ball rolls off away from the line, not a crack. A foot a hair beside such a border sees
 * the contacts along it nearly 180 degrees apart, within SOAK_CRACK_OPEN of surrounding
 * it (soak seed 2 level 282: 1 mm); the edges of a crack, a slot or a hole have vertices
 * on both sides of the foot. */
static bool contacts_on_one_ledge(const soak_level_t *lvl, const double e1[3], const double e2[3],
                                  const double bc[3], const int32_t *ctri, const int *ord, int n)
{
    enum { MAXV = 3 * 64 }; /* every contact (MAXC): 9 around s3 l369 */
    double a[MAXV];
    int na = 0;
    if (n < 1 || 3 * n > MAXV) return false;
    for (int i = 0; i < n; i++) {
        const soak_wtri_t *w = &lvl->wtris[ctri[ord[i]]];
        for (int v = 0; v < 3; v++) {
            double d[3];
            sub3(d, w->v[v], bc);
            double x = dot3(d, e1), y = dot3(d, e2);
            if (x * x + y * y < 1e-12) return false; /* a vertex right under the foot */
            double t = atan2(y, x);
            int j = na++;
            while (j > 0 && a[j - 1] > t) { a[j] = a[j - 1]; j--; }
            a[j] = t;
        }
    }
    double widest = a[0] + 2 * M_PI - a[na - 1];
    for (int i = 1; i < na; i++)
        if (a[i] - a[i - 1] > widest) widest = a[i] - a[i - 1];
    return widest > M_PI + SOAK_LEDGE_GAP;
}

/* Footing, case 2: the contact c (the point of walkable triangle w, plane normal n, closest
 * to the ball's centre bc) is no closest point of the face w is part of: another seen
 * triangle in w's plane contains c and has a point closer to bc (strictly; a triangle is
 * convex, so the distance falls from c into it: c is no local minimum of the face's
 * distance). A face split into triangles touches the ball where the face is closest, not
 * at a diagonal's end: a tile's top as two triangles, the foot 8 mm beside its edge, the
 * second triangle's closest point was the tile's corner 0.12 m across, and with a slope's
 * corner on the other side it completed a surround the tile's edge alone does not make
 * (soak s16 l147: 43 mm). Identical copies (a duplicated piece) are no closer: kept. */
static bool coplanar_closer(const soak_level_t *lvl, const char_body_settings_t *s, const double up[3],
                            const soak_wtri_t *w, const double n[3], const double c[3], const double bc[3], double r)
{
    const double dc = dist3(c, bc), off = dot3(n, w->v[0]);
    for (uint32_t j = 0; j < lvl->nwtris; j++) {
        const soak_wtri_t *o = &lvl->wtris[j];
        if (o == w || !tri_seen(o->mask, s) || dist3(bc, o->c) > o->rad + r) continue;
        double on[3], allow;
        if (!tri_walkable(o, s, up, on, &allow) || inside_face(o, up)) continue;
        if (!(fabs(dot3(n, on)) > 1 - 1e-9) || !(fabs(dot3(n, o->v[0]) - off) < 1e-6)) continue;
        if (!(pt_tri_dist(c, o) < 1e-9)) continue;
        double q[3];
        closest_pt_tri(q, bc, o->v[0], o->v[1], o->v[2]);
        if (dist3(q, bc) < dc - 1e-9) return true;
    }
    return false;
}

/* Footing of a body grounded on a steep surface: a face the body judged steep (its slope
 * within the float's reach of the floor angle, so the checker's tolerance counted it
 * walkable) is steep here too, and the foot resting with its step zone in it (the sweep
 * capsule on the face) is no footing failure: soak s17 l209, a face 29.810 degrees off up
 * for a floor angle of 29.8 (cosines 8.9e-5 apart), the foot 34.5 mm inside it. A face
 * clearly walkable (beyond the band) is judged as for any grounded body. */
double soak_check_footing_steep(const soak_level_t *lvl, const char_body_settings_t *s, fm_vec3_t owner)
{
    walk_cos_tol = -1e-4;
    double ex = soak_check_footing(lvl, s, owner);
    walk_cos_tol = 1e-4;
    return ex;
}

/* The runtime's positions are floats: where the foot ends within a few float steps of a
 * walkable tread's edge, which side of the edge it is on is the rounding's choice, and the
 * body's float rays see the edge where the rounding puts it. Staircase boxes yawed 138
 * degrees at 20 m from the origin (a float step 1.9 um): the foot ended 0.88 um past tread
 * 2's front edge in double, the body's foot ray missed that tread and stood it on tread 1,
 * 180.76 mm under tread 2; a frame later it stepped up (soak s99 l223). The verdict is the
 * best one over the foot moved across up by 8 float steps of the owner's largest coordinate
 * (2^-20 of it; 15-30 um in a 48 m room), in 8 directions: a foot 1 mm past an edge is
 * judged as before. Only a failing verdict is searched. */
static double footing_rounded(const soak_level_t *lvl, const char_body_settings_t *s, fm_vec3_t owner, bool steep);

double soak_check_footing_rounded(const soak_level_t *lvl, const char_body_settings_t *s, fm_vec3_t owner, bool steep)
{
    walk_float_reach = !steep; /* (see walk_float_reach) */
    const double ex = footing_rounded(lvl, s, owner, steep);
    walk_float_reach = false;
    return ex;
}

static double footing_rounded(const soak_level_t *lvl, const char_body_settings_t *s, fm_vec3_t owner, bool steep)
{
    const double ex = steep ? soak_check_footing_steep(lvl, s, owner) : soak_check_footing(lvl, s, owner);
    if (!(ex > SOAK_FOOT_TOL)) return ex;
    const int32_t tri = soak_footing_tri, tri2 = soak_footing_tri2;
    const int nct = soak_footing_ncontacts;
    double up[3] = {s->up.x, s->up.y, s->up.z}, a[3], b[3];
    const double ul = sqrt(dot3(up, up));
    for (int k = 0; k < 3; k++) up[k] /= ul;
    /* a: any unit vector across up; b = up x a */
    const double ref[3] = {fabs(up[0]) < 0.9 ? 1.0 : 0.0, fabs(up[0]) < 0.9 ? 0.0 : 1.0, 0.0};
    cross3(b, up, ref);
    const double bl = sqrt(dot3(b, b));
    for (int k = 0; k < 3; k++) b[k] /= bl;
    cross3(a, b, up);
    double m = fabs((double)owner.x);
    if (fabs((double)owner.y) > m) m = fabs((double)owner.y);
    if (fabs((double)owner.z) > m) m = fabs((double)owner.z);
    if (m < 1.0) m = 1.0;
    const double eps = ldexp(m, -20);
    double best = ex;
    for (int i = 0; i < 8 && best > SOAK_FOOT_TOL; i++) {
        const double ang = i * 0.78539816339744831, ca = cos(ang), sa = sin(ang);
        fm_vec3_t o = owner;
        o.x = (float)((double)owner.x + eps * (ca * a[0] + sa * b[0]));
        o.y = (float)((double)owner.y + eps * (ca * a[1] + sa * b[1]));
        o.z = (float)((double)owner.z + eps * (ca * a[2] + sa * b[2]));
        const double e = steep ? soak_check_footing_steep(lvl, s, o) : soak_check_footing(lvl, s, o);
        if (e < best) best = e;
    }
    if (best > SOAK_FOOT_TOL) { /* failing: the diagnosis is the one at the foot itself */
        soak_footing_tri = tri;
        soak_footing_tri2 = tri2;
        soak_footing_ncontacts = nct;
    }
    return best;
}

double soak_check_footing(const soak_level_t *lvl, const char_body_settings_t *s, fm_vec3_t owner)
{
    soak_footing_tri = soak_footing_tri2 = -1;
    soak_footing_ncontacts = 0;
    double up[3], f[3], r;
    foot_point(s, owner, up, f, &r);
    const double step = s->step_height, below = (double)s->floor_snap_distance + 2 * r;
    /* 1. the surface directly under the foot: the highest walkable triangle the line along
     *    up through the foot crosses, from snap + 2r below to step_height + 1 mm above
     *    (higher than the step zone it would be inside the sweep capsule: penetration) */
    bool found = false;
    double z1 = -1e300, ex1 = 0;
    int32_t under = -1; /* the triangle of z1: the surface under the foot */
    /* planes of the walkable triangles the foot stands on or over (crossed by that line
     * at most SOAK_FOOT_TOL above the foot, or below it), each once: case 2 below does
     * not take them for a side of a gap */
    enum { MAXON = 32 };
    double onn[MAXON][3], ond[MAXON];
    int non = 0;
    for (uint32_t i = 0; i < lvl->nwtris; i++) {
        const soak_wtri_t *w = &lvl->wtris[i];
        if (!tri_seen(w->mask, s)) continue;
        if (dist3(f, w->c) > w->rad + below + step + r) continue;
        double n[3], allow;
        if (!tri_walkable(w, s, up, n, &allow) || inside_face(w, up)) continue;
        double d[3];
        sub3(d, w->v[0], f);
        double t = dot3(n, d) / dot3(n, up);
        if (!(t >= -below && t <= step + SOAK_FOOT_TOL)) continue;
        double x[3] = {f[0] + up[0] * t, f[1] + up[1] * t, f[2] + up[2] * t};
        if (pt_tri_dist(x, w) > 1e-9) continue;
        if (!found || t > z1) { z1 = t; under = (int32_t)i; }
        /* at it or above it (t <= SOAK_FOOT_TOL): the foot is over this floor, not over a
         * gap, however high it is held above it (the sweep capsule's bottom ball resting on
         * a slope too steep for the capsule's bottom, r / cos > r + step: s3 l15, l146; the
         * ball held in a wedge over it: s3 l124) */
        bool dup = false;
        for (int k = 0; k < non && !dup; k++)
            dup = dot3(n, onn[k]) > 1 - 1e-9 && fabs(dot3(n, w->v[0]) - ond[k]) < 1e-6;
        if (t <= SOAK_FOOT_TOL && !dup && non < MAXON) {
            for (int k = 0; k < 3; k++) onn[non][k] = n[k];
            ond[non++] = dot3(n, w->v[0]);
        }
        if (!found || t - allow > ex1) { ex1 = t - allow; if (ex1 > 0) soak_footing_tri = (int32_t)i; }
        found = true;
    }
    /* 2. a crack, slot or hole narrower than the capsule: walkable triangles around the
     *    foot (their closest points to the bottom ball centre, in directions across up,
     *    surround it: see below) that the bottom ball overlaps. Resting on both edges the
     *    foot sags r - sqrt(r^2 - (g/2)^2) below them over a gap g, and no more: for each
     *    such triangle the excess is how far the ball must be raised along up to clear it
     *    (the sag is thereby allowed exactly); a pair fails by the smaller of its two
     *    excesses. One-sided overlaps (a ledge or tread edge in the step zone
     *    beside the foot) are legitimate and not counted. Nor is the plane the foot stands
     *    on (case 1 found it at the foot): the foot is on it, not over a gap beside it.
     *    On one slope of a V valley, its foot point just past the slot's edge, the ball
     *    overlaps that slope by the seed's slope rule (r / cos - r along up: the foot, not
     *    the ball, stands on it) and the other slope by less; paired, the two failed a
     *    body standing on the surface under its foot (seed 1 levels 8, 22, 26). */
    double bc[3] = {f[0] + up[0] * r, f[1] + up[1] * r, f[2] + up[2] * r};
    /* The surface under the foot holds the ball up to where the ball raised along up
     * clears it (on a slope the full ball overlaps it by the seed's slope rule, r / cos - r
     * along up). When that raise clears every walkable contact too, the surface under the
     * foot out-holds them all: the ball raised onto it rests on it alone, lower than it
     * the contacts hold nothing, and none is a side of a gap (oa_dm5: a flat floor's edge
     * and a 30 degree slope beside the foot, both in the step zone, the foot on a 30
     * degree slope across them; paired, they failed it as a crack by 4.1 and 25.9 mm). Not
     * when one contact needs more (a crack in a ramp whose floor is the ramp's plane
     * lowered: the uphill side holds the ball above that floor; out-holding only the
     * contacts it clears would leave the uphill side alone, one-sided, and pass a foot
     * sunk into the crack). Only where the foot is on or above that surface (case 1 fails
     * it otherwise); on a flat floor the ball touches it at most (hold 0), and nothing is
     * out-held. The surface is every triangle of that plane the ball overlaps, not only
     * the one the line through the foot crosses: which triangle of a planar quad the foot
     * is over is no matter of the surface (soak s17 l182: the foot on a 38 degree slope
     * near its bottom edge, in the quad's triangle that the ball overlaps least (a raise
     * of 0.181 m clears it), the other one touching the ball 0.6 m uphill (0.268 m); the
     * far slope of a V valley beside it needs 0.230 m: out-held by the slope, a crack
     * between that far slope and another near slope under the foot's slope by the first
     * triangle alone (166 mm); with the quad's other diagonal, 0). */
    const double top = step + r + 0.01;
    double hold = 0, held = 0; /* held: the largest raise a contact needs (top: none clears it) */
    bool tangent = false; /* the ball raised by hold rests on the surface under the foot (below) */
    if (under >= 0 && z1 <= SOAK_FOOT_TOL) {
        double un[3], unused;
        hold = raise_to_clear(bc, up, r, &lvl->wtris[under], top);
        if (hold < 0) hold = 0;
        const bool plane = tri_walkable(&lvl->wtris[under], s, up, un, &unused);
        const double ud = plane ? dot3(un, lvl->wtris[under].v[0]) : 0;
        for (uint32_t i = 0; i < lvl->nwtris && plane; i++) {
            const soak_wtri_t *w = &lvl->wtris[i];
            if ((int32_t)i == under || !tri_seen(w->mask, s) || dist3(bc, w->c) > w->rad + r) continue;
            double n[3], allow;
            if (!tri_walkable(w, s, up, n, &allow) || inside_face(w, up)) continue;
            if (!(dot3(n, un) > 1 - 1e-9 && fabs(dot3(n, w->v[0]) - ud) < 1e-6)) continue;
            double h = raise_to_clear(bc, up, r, w, top);
            if (h > hold) hold = h;
        }
        /* The ball raised by hold rests on that surface itself, touching it at one point T,
         * when hold is the raise its whole plane needs (T lies on the surface's triangles),
         * and nothing is in its way there when no triangle crosses the segment from T to that
         * ball's centre (the floor of a crack in a ramp, the ramp's plane lowered, runs on
         * under the ramp, where T lies: it holds nothing there). Then, below, when the
         * contacts that raise does not clear are one ledge beside the foot (or none), the
         * surface out-holds them all: the ball rests on it beside that ledge, as on a flat
         * floor. Under an up 15 degrees off a tile field's normal, the foot on a tile lower
         * than its neighbours, 6 mm from one's edge: raised onto the tile by the slope rule
         * (34.4 mm) the ball clears every neighbour but one, which it overlaps by 5.6 mm;
         * counted from the foot, three neighbours surrounded the ball and failed the body by
         * 11.09 mm (soak s37 l330). Contacts left on both sides are judged from the foot as
         * before: in a hole between tiles 0.15 m high under an 11 degree up, the ball raised
         * onto the floor clears one side (12 of 19 mm) but still overlaps two tiles 142
         * degrees apart by 0.12-0.15 m; that body sank into the hole (soak s6 l429, 12.05
         * mm, on the body before its fix). */
        if (plane && hold > 0) {
            const double cs = dot3(un, up), dn = dot3(un, bc) - ud;
            if (cs > 0 && hold >= (r - dn) / cs - 1e-7) {
                double cc[3], tp[3];
                for (int k = 0; k < 3; k++) {
                    cc[k] = bc[k] + up[k] * hold;
                    tp[k] = cc[k] - un[k] * (r - 1e-6);
                }
                bool open = true;
                for (uint32_t i = 0; i < lvl->nwtris && open; i++) {
                    const soak_wtri_t *w = &lvl->wtris[i];
                    if (!tri_seen(w->mask, s) || dist3(cc, w->c) > w->rad + r) continue;
                    open = soak_seg_tri_dist(tp, cc, w->v[0], w->v[1], w->v[2]) > 1e-7;
                }
                tangent = open;
            }
        }
    }
    /* The points of the floor the foot stands on (its triangles in case 1's planes) closest
     * to the ball's centre, where the ball overlaps it: a walkable contact whose closest
     * point is one of them touches the ball exactly where that floor does, at the edge it
     * shares with it (a box's top edge, the box's side below it walkable under a tilted up:
     * a convex ridge). It is the floor under the foot, not a side of a gap (soak s10 l402:
     * the foot on a stair's tread 4 cm inside the staircase's side, up tilted 45 degrees
     * over that side; the tread's edge, through the side face, made the surround with the
     * next two steps' corners in the step zone: 8.25 mm). A face across a concave crease
     * from that floor touches the ball elsewhere than the floor does: it still counts. */
    enum { MAXF = 16 };
    double fpt[MAXF][3];
    int nf = 0;
    for (uint32_t i = 0; i < lvl->nwtris && non > 0 && nf < MAXF; i++) {
        const soak_wtri_t *w = &lvl->wtris[i];
        if (!tri_seen(w->mask, s) || dist3(bc, w->c) > w->rad + r) continue;
        double n[3], allow;
        if (!tri_walkable(w, s, up, n, &allow) || inside_face(w, up)) continue;
        bool stood_on = false;
        for (int k = 0; k < non && !stood_on; k++)
            stood_on = dot3(n, onn[k]) > 1 - 1e-9 && fabs(dot3(n, w->v[0]) - ond[k]) < 1e-6;
        if (!stood_on) continue;
        closest_pt_tri(fpt[nf], bc, w->v[0], w->v[1], w->v[2]);
        if (dist3(fpt[nf], bc) < r) nf++;
    }
    enum { MAXC = 64 };
    double cu[MAXC][3], cex[MAXC], chi[MAXC];
    int32_t ctri[MAXC];
    int nc = 0;
    for (uint32_t i = 0; i < lvl->nwtris && nc < MAXC; i++) {
        const soak_wtri_t *w = &lvl->wtris[i];
        if (!tri_seen(w->mask, s)) continue;
        if (dist3(bc, w->c) > w->rad + r) continue;
        double n[3], allow;
        if (!tri_walkable(w, s, up, n, &allow) || inside_face(w, up)) continue;
        bool stood_on = false;
        for (int k = 0; k < non && !stood_on; k++)
            stood_on = dot3(n, onn[k]) > 1 - 1e-9 && fabs(dot3(n, w->v[0]) - ond[k]) < 1e-6;
        if (stood_on) continue;
        double c[3], d[3];
        closest_pt_tri(c, bc, w->v[0], w->v[1], w->v[2]);
        if (dist3(c, bc) >= r) continue;
        bool floors = false; /* touches the ball where the floor under the foot does (above) */
        for (int k = 0; k < nf && !floors; k++) floors = dist3(c, fpt[k]) < 1e-9;
        if (floors) continue;
        if (coplanar_closer(lvl, s, up, w, n, c, bc, r)) continue;
        sub3(d, bc, w->v[0]);
        if (dot3(n, d) <= 0) continue; /* ball centre below its plane: not resting on it */
        sub3(d, c, bc);
        double du = dot3(d, up), dh[3] = {d[0] - up[0] * du, d[1] - up[1] * du, d[2] - up[2] * du};
        double l = sqrt(dot3(dh, dh));
        if (l < 1e-6) continue; /* right under the ball centre: case 1's business */
        double hi = raise_to_clear(bc, up, r, w, top);
        if (hi < 0) { held = top; continue; } /* not cleared by any raise in range */
        if (hi > held) held = hi;
        for (int k = 0; k < 3; k++) cu[nc][k] = dh[k] / l;
        cex[nc] = hi - allow;
        chi[nc] = hi;
        ctri[nc] = (int32_t)i;
        nc++;
    }
    double worst = ex1 > 0 ? ex1 : 0;
    if (held <= hold) nc = 0; /* all out-held by the surface under the foot */
    double e1[3] = {1, 0, 0}, e2[3];
    if (fabs(up[0]) > 0.9) { e1[0] = 0; e1[1] = 1; }
    double eu = dot3(e1, up);
    for (int k = 0; k < 3; k++) e1[k] -= up[k] * eu;
    double el = sqrt(dot3(e1, e1));
    for (int k = 0; k < 3; k++) e1[k] /= el;
    cross3(e2, up, e1);
    if (tangent && nc > 0) {
        /* the contacts the ball resting on the surface under the foot still overlaps: one
         * ledge beside it (their triangles on one side of a line beside the foot) or none,
         * and that surface out-holds the others; otherwise all are judged from the foot */
        int left[MAXC], nl = 0;
        for (int i = 0; i < nc; i++)
            if (chi[i] > hold) left[nl++] = i;
        if (nl == 0 || contacts_on_one_ledge(lvl, e1, e2, bc, ctri, left, nl)) nc = 0;
    }
    /* The contacts hold the ball (a crack, a slot, a hole) only where they surround the
     * foot across up: no half-plane of directions is free of them (no angular gap between
     * them wider than 180 degrees, SOAK_CRACK_OPEN of rounding allowed), so the ball
     * raised onto them cannot roll off sideways. Two contacts do so when opposite (the
     * parallel edges of a groove, a crack, a slot), three or more around it (a hole
     * between tiles). Two contacts 120-130 degrees apart (block or tile corners beside an
     * open floor) do not: the ball rolls off between them onto the floor, as the body's
     * roll test finds, and standing on that floor with the step zone overlapping both is
     * the seed's ledge rule (seed 1 levels 5, 21, 47, 49, 66, 69: the oracle counted every
     * pair more than 120 degrees apart); nor do several tiles along one kerb line beside
     * the foot (their directions span less than 180 degrees). The excess is that of the
     * contacts still surrounding the foot when the ball is raised: taken in order of
     * excess, the excess of the one that completes the surround. */
    int ord[MAXC];
    for (int i = 0; i < nc; i++) {
        int k = i;
        while (k > 0 && cex[ord[k - 1]] < cex[i]) { ord[k] = ord[k - 1]; k--; }
        ord[k] = i;
    }
    double ang[MAXC];
    for (int k = 0; k < nc; k++) {
        double a = atan2(dot3(cu[ord[k]], e2), dot3(cu[ord[k]], e1));
        int j = k; /* insertion into the sorted angles of the first k contacts */
        while (j > 0 && ang[j - 1] > a) { ang[j] = ang[j - 1]; j--; }
        ang[j] = a;
        if (k == 0) continue;
        double widest = ang[0] + 2 * M_PI - ang[k];
        for (int i = 1; i <= k; i++)
            if (ang[i] - ang[i - 1] > widest) widest = ang[i] - ang[i - 1];
        if (widest > M_PI + SOAK_CRACK_OPEN) continue;
        if (widest > M_PI - SOAK_CRACK_OPEN && contacts_on_one_ledge(lvl, e1, e2, bc, ctri, ord, k + 1)) continue;
        if (cex[ord[k]] > worst) {
            worst = cex[ord[k]];
            soak_footing_tri = ctri[ord[k]];
            soak_footing_tri2 = ctri[ord[0]];
            soak_footing_ncontacts = k + 1;
            soak_footing_widest = widest;
        }
        break;
    }
    return worst;
}

/* Distance between triangle t and the parallelogram q0, q1, q1 + D, q0 + D (two triangles):
 * the shortest of an edge of one to the other (0 where they cross). */
static double tri_quad_dist(const double *t0, const double *t1, const double *t2, double q[4][3])
{
    const double *tv[3] = {t0, t1, t2};
    double best = 1e300, d;
    for (int e = 0; e < 3; e++) {
        d = soak_seg_tri_dist(tv[e], tv[(e + 1) % 3], q[0], q[1], q[2]);
        if (d < best) best = d;
        d = soak_seg_tri_dist(tv[e], tv[(e + 1) % 3], q[0], q[2], q[3]);
        if (d < best) best = d;
    }
    for (int e = 0; e < 4; e++) {
        d = soak_seg_tri_dist(q[e], q[(e + 1) % 4], t0, t1, t2);
        if (d < best) best = d;
    }
    return best;
}

static double quad_dist_cb(const double *t0, const double *t1, const double *t2, const void *ctx)
{
    return tri_quad_dist(t0, t1, t2, (double (*)[3])ctx);
}

/* Nearest static or moving triangle to the capsule cap swept along D (m, minus the radius):
 * the swept capsule is the parallelogram of its segment along D grown by the radius. The
 * samples along the way alone (every half radius) miss what pokes in between two of them:
 * a thin wall's end the capsule grazes (soak s18 l426: a 26.5 m/s step of 2.67 m in 8
 * samples 0.33 m apart, a wall's vertical end edge 14 mm from the nearest two and touched
 * between them; the body, max_slides 1, stopped there at 79 %). */
static double swept_nearest(const soak_level_t *lvl, const char_body_settings_t *s, const soak_capsule_t *cap,
                            const double D[3])
{
    double q[4][3], mid[3];
    for (int k = 0; k < 3; k++) {
        q[0][k] = cap->a[k]; q[1][k] = cap->b[k];
        q[2][k] = cap->b[k] + D[k]; q[3][k] = cap->a[k] + D[k];
        mid[k] = (cap->a[k] + cap->b[k] + D[k]) * 0.5;
    }
    double half = 0.5 * (dist3(cap->a, cap->b) + sqrt(dot3(D, D)));
    return nearest_tri(lvl, s, mid, half, quad_dist_cb, q) - cap->r;
}

/* A riser in the way: the part of a triangle higher than the step zone reaches (more than
 * step_height + 9 mm over the foot: the body climbs a riser up to step_height + 1 cm,
 * CB_MARGIN, docs/ARCHITECTURE.md; higher it meets a wall), within 1 mm of the full capsule
 * swept along the way at its own height, where the way goes towards it (not touched at the
 * start, or nearer somewhere along the way than at the start: a kerb the way runs along or
 * leaves is no obstacle). The raised capsule of the free test misses the top edge of a low riser under
 * the ball: 10 mm higher it clears an edge whose contact normal is 11 degrees off up by 9.8
 * mm (soak s23 l338: a step-0 body's ball resting on the edge of a tile 14.6 mm higher,
 * 0.16 m ahead; walking into it the body slid along it as along a wall, 39 %). */
typedef struct {
    double q[4][3];   /* the swept segment (parallelogram) */
    double f[3], up[3], top; /* the foot and the height along up above it that is a riser */
    double r;
    double len;           /* |D| */
} riser_ctx_t;

static double riser_dist_cb(const double *t0, const double *t1, const double *t2, const void *ctx)
{
    const riser_ctx_t *c = ctx;
    const double *tv[3] = {t0, t1, t2};
    double poly[4][3], h[3], d[3];
    int np = 0;
    for (int k = 0; k < 3; k++) { sub3(d, tv[k], c->f); h[k] = dot3(d, c->up) - c->top; }
    /* clip the triangle to the half-space above the riser height */
    for (int k = 0; k < 3; k++) {
        int j = (k + 1) % 3;
        if (h[k] > 0) memcpy(poly[np++], tv[k], sizeof poly[0]);
        if ((h[k] > 0) != (h[j] > 0)) {
            double u = h[k] / (h[k] - h[j]);
            for (int m = 0; m < 3; m++) poly[np][m] = tv[k][m] + u * (tv[j][m] - tv[k][m]);
            np++;
        }
    }
    if (np < 3) return 1e300;
    /* towards it: met along the way, or touched at the start and nearer somewhere along it
     * (the way's distance to it is below the start's) */
    double d0 = 1e300, best = 1e300;
    for (int k = 1; k + 1 < np; k++) {
        double x = soak_seg_tri_dist(c->q[0], c->q[1], poly[0], poly[k], poly[k + 1]);
        if (x < d0) d0 = x;
    }
    if (d0 - c->len > c->r + 1e-3) return 1e300; /* out of the way's reach */
    double q[4][3];
    memcpy(q, c->q, sizeof q);
    for (int k = 1; k + 1 < np; k++) {
        double x = tri_quad_dist(poly[0], poly[k], poly[k + 1], q);
        if (x < best) best = x;
    }
    if (d0 <= c->r + 1e-3 && !(best < d0 - 1e-9)) return 1e300;
    return best;
}

static bool riser_in_way(const soak_level_t *lvl, const char_body_settings_t *s, fm_vec3_t owner, const double D[3])
{
    riser_ctx_t c;
    soak_capsule_t full, sweep;
    soak_capsules_at(s, owner, &full, &sweep);
    foot_point(s, owner, c.up, c.f, &c.r);
    c.top = (double)s->step_height + 0.009;
    double mid[3];
    for (int k = 0; k < 3; k++) {
        c.q[0][k] = full.a[k]; c.q[1][k] = full.b[k];
        c.q[2][k] = full.b[k] + D[k]; c.q[3][k] = full.a[k] + D[k];
        mid[k] = (full.a[k] + full.b[k] + D[k]) * 0.5;
    }
    double half = 0.5 * (dist3(full.a, full.b) + sqrt(dot3(D, D)));
    c.len = sqrt(dot3(D, D));
    /* only what lies within r + 1 mm of the way is of interest (the bounding-sphere cull) */
    return nearest_tri_within(lvl, s, mid, half, c.r + 2e-3, riser_dist_cb, &c) - c.r <= 1e-3;
}

bool soak_check_free_flat(const soak_level_t *lvl, const char_body_settings_t *s, fm_vec3_t owner, fm_vec3_t disp)
{
    const double h0 = 0.01, below = 0.002;
    double len = sqrt((double)disp.x * disp.x + (double)disp.y * disp.y + (double)disp.z * disp.z);
    double r = s->radius;
    int n = (int)ceil(len / (0.5 * r)) + 1;
    if (n > 64 || !(len > 0)) return false;
    for (int k = 0; k <= n; k++) {
        double t = (double)k / n;
        fm_vec3_t p, q;
        for (int j = 0; j < 3; j++) {
            double base = (double)owner.v[j] + (double)disp.v[j] * t;
            p.v[j] = (float)(base + s->up.v[j] * h0);
            q.v[j] = (float)(base - s->up.v[j] * below);
        }
        soak_capsule_t full, sweep;
        /* raised by 1 cm: nothing (floor included) within 9 mm: no wall, bump or slope */
        soak_capsules_at(s, p, &full, &sweep);
        if (soak_check_nearest(lvl, s, &full) < h0 - 1e-3) return false;
        /* lowered by 2 mm: the floor is there (no hole, crack wider than a hair, or drop) */
        soak_capsules_at(s, q, &full, &sweep);
        if (!(soak_check_nearest(lvl, s, &full) < 0)) return false;
        /* and it is a static walkable triangle right under the foot point */
        double up[3], f[3], rr;
        foot_point(s, q, up, f, &rr);
        bool under = false;
        for (uint32_t i = 0; i < lvl->nwtris && !under; i++) {
            const soak_wtri_t *w = &lvl->wtris[i];
            if (!tri_seen(w->mask, s) || dist3(f, w->c) > w->rad + 0.01) continue;
            double nn[3], allow;
            if (!tri_walkable(w, s, up, nn, &allow)) continue;
            double d[3];
            sub3(d, w->v[0], f);
            double tt = dot3(nn, d) / dot3(nn, up);
            /* the floor holding the foot: within the 2 mm the lowered capsule went, not
             * farther below (the lowered capsule met something else: a 19 mm edge the
             * ball of a step-0 body rests on, 3 mm over the floor under the foot, which
             * the raised capsule clears by 10.8 mm, its contact normal 11 degrees off up;
             * walking into it is climbing it, soak s17 l7: 58 %) */
            if (!(tt >= -1e-6 && tt <= 0.005)) continue;
            double x[3] = {f[0] + up[0] * tt, f[1] + up[1] * tt, f[2] + up[2] * tt};
            /* tilted no more than the progress oracle's share allows: walking follows a
             * walkable slope, covering cos(tilt) of the input across up (a ramp's crest
             * 0.7 mm ahead is more than 9 mm from the raised capsule: dm6ish, 27 degrees) */
            if (pt_tri_dist(x, w) <= 1e-9 && dot3(nn, up) >= SOAK_PROGRESS_MIN) under = true;
        }
        if (!under) return false;
    }
    /* and between the samples: the raised capsule swept along the whole way (only where
     * the samples found it free: the soak runs this on every walking step) */
    fm_vec3_t p0;
    for (int j = 0; j < 3; j++) p0.v[j] = (float)((double)owner.v[j] + s->up.v[j] * h0);
    soak_capsule_t full, sweep;
    soak_capsules_at(s, p0, &full, &sweep);
    double D[3] = {disp.x, disp.y, disp.z};
    if (!(swept_nearest(lvl, s, &full, D) >= h0 - 1e-3)) return false;
    /* and no riser above the step zone in the way, which the raised capsule can clear */
    return !riser_in_way(lvl, s, owner, D);
}

bool soak_check_touches_walkable(const soak_level_t *lvl, const char_body_settings_t *s, fm_vec3_t owner)
{
    soak_capsule_t full, sweep;
    soak_capsules_at(s, owner, &full, &sweep);
    double up[3] = {s->up.x, s->up.y, s->up.z}, r = full.r;
    for (uint32_t i = 0; i < lvl->nwtris; i++) {
        const soak_wtri_t *w = &lvl->wtris[i];
        if (!tri_seen(w->mask, s)) continue;
        if (dist3(full.a, w->c) > w->rad + r + 0.01) continue;
        double n[3], allow;
        if (!tri_walkable(w, s, up, n, &allow)) continue;
        double c[3], d[3];
        closest_pt_tri(c, full.a, w->v[0], w->v[1], w->v[2]);
        sub3(d, full.a, c);
        double dl = dist3(c, full.a);
        if (!(dot3(d, up) > 1e-6 && dl <= r + 1e-3)) continue;
        /* Resting on it: the contact normal (from the contact to the ball's centre) is
         * itself walkable. A face's is its own normal; at a floor's edge that the ball
         * touches with its side (a ramp's side beside it, soak s3 l96: 90 degrees off up;
         * the lower edge of an overhang's underside, s3 l46: 63 degrees) it is as steep
         * as a wall, and the ball rests on nothing there. */
        if (dl > 1e-9 && dot3(d, up) < (cos((double)s->floor_max_angle) - 1e-4) * dl) continue;
        return true;
    }
    return false;
}

/* Room to stand near the body at owner, within one straight move: a walkable static
 * triangle (either face, not the inside of a closed solid) crossed by a line along up
 * through a point within 5 r of the foot across up (columns r / 2 apart), between snap +
 * 2 r below the foot and step_height + 2 r above it, where a body standing with its foot on
 * it (1 cm over it) passes the state checks (its sweep capsule at most SOAK_PEN_TOL inside
 * any static triangle beyond the slope allowance) and the footing oracle, and the sweep
 * capsule swept straight there from owner comes no more than SOAK_PEN_TOL into anything.
 * The body's own stand search looks 0.5 r .. 4 r away across up in eight directions,
 * lifting by at most r + step: this looks wider and finer. Brute force; asked only where
 * a footing and a support verdict would both fail (soak_sim_check), never on an ordinary
 * step. */
bool soak_check_room_to_stand(const soak_level_t *lvl, const char_body_settings_t *s, fm_vec3_t owner)
{
    double up[3], f[3], r;
    foot_point(s, owner, up, f, &r);
    double ax[3] = {1, 0, 0};
    if (fabs(up[0]) > 0.9) { ax[0] = 0; ax[2] = 1; }
    double e1[3], e2[3], a = dot3(ax, up);
    for (int k = 0; k < 3; k++) e1[k] = ax[k] - up[k] * a;
    double l = sqrt(dot3(e1, e1));
    for (int k = 0; k < 3; k++) e1[k] /= l;
    cross3(e2, up, e1);
    soak_capsule_t full0, sweep0;
    soak_capsules_at(s, owner, &full0, &sweep0);
    const double below = (double)s->floor_snap_distance + 2 * r, above = (double)s->step_height + 2 * r;
    const double span = 5 * r, pitch = 0.5 * r;
    const int n = 10;
    for (int i = -n; i <= n; i++)
        for (int j = -n; j <= n; j++) {
            double u = i * pitch, v = j * pitch;
            if (u * u + v * v > span * span * (1 + 1e-9)) continue;
            double p[3];
            for (int k = 0; k < 3; k++) p[k] = f[k] + e1[k] * u + e2[k] * v;
            for (uint32_t t = 0; t < lvl->nwtris; t++) {
                const soak_wtri_t *w = &lvl->wtris[t];
                if (!tri_seen(w->mask, s)) continue;
                double dc[3];
                sub3(dc, w->c, p);
                double hu = dot3(dc, up), hx[3];
                for (int k = 0; k < 3; k++) hx[k] = dc[k] - up[k] * hu;
                if (sqrt(dot3(hx, hx)) > w->rad || hu < -below - w->rad || hu > above + w->rad) continue;
                double nn[3], allow;
                if (!tri_walkable(w, s, up, nn, &allow) || inside_face(w, up)) continue;
                double d[3];
                sub3(d, w->v[0], p);
                double h = dot3(nn, d) / dot3(nn, up);
                if (!(h >= -below && h <= above)) continue;
                double x[3] = {p[0] + up[0] * h, p[1] + up[1] * h, p[2] + up[2] * h};
                if (pt_tri_dist(x, w) > 1e-9) continue;
                /* the body standing there: owner moved as the foot is, 1 cm over x */
                double D[3];
                for (int k = 0; k < 3; k++) D[k] = x[k] + up[k] * 0.01 - f[k];
                fm_vec3_t o = {{(float)(owner.x + D[0]), (float)(owner.y + D[1]), (float)(owner.z + D[2])}};
                soak_capsule_t full, sweep;
                soak_capsules_at(s, o, &full, &sweep);
                if (soak_check_static_pen(lvl, s, &sweep, NULL, NULL) > SOAK_PEN_TOL) continue;
                if (soak_check_footing(lvl, s, o) > SOAK_FOOT_TOL) continue;
                if (swept_nearest(lvl, s, &sweep0, D) < -SOAK_PEN_TOL) continue;
                return true;
            }
        }
    return false;
}
