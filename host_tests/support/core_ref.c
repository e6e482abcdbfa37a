/** @file core_ref.c @brief Double-precision references for test_scene_query. */
#include "core_ref.h"
#include "coll/mesh.h"
#include <math.h>
#include <stddef.h>

core_d3 core_d3_of(fm_vec3_t v) { core_d3 r = { v.x, v.y, v.z }; return r; }
core_d3 core_d3_add(core_d3 a, core_d3 b) { core_d3 r = { a.x + b.x, a.y + b.y, a.z + b.z }; return r; }
core_d3 core_d3_sub(core_d3 a, core_d3 b) { core_d3 r = { a.x - b.x, a.y - b.y, a.z - b.z }; return r; }
core_d3 core_d3_scale(core_d3 a, double s) { core_d3 r = { a.x * s, a.y * s, a.z * s }; return r; }
double core_d3_dot(core_d3 a, core_d3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
core_d3 core_d3_cross(core_d3 a, core_d3 b)
{
    core_d3 r = { a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x };
    return r;
}
double core_d3_len(core_d3 a) { return sqrt(core_d3_dot(a, a)); }

static void quat_d(const coll_transform_t *xf, double q[4])
{
    double n = sqrt((double)xf->rot.x * xf->rot.x + (double)xf->rot.y * xf->rot.y +
                    (double)xf->rot.z * xf->rot.z + (double)xf->rot.w * xf->rot.w);
    q[0] = xf->rot.x / n; q[1] = xf->rot.y / n; q[2] = xf->rot.z / n; q[3] = xf->rot.w / n;
}

static core_d3 rot(const double q[4], core_d3 v)
{
    core_d3 u = { q[0], q[1], q[2] };
    core_d3 t = core_d3_scale(core_d3_cross(u, v), 2.0);
    return core_d3_add(core_d3_add(v, core_d3_scale(t, q[3])), core_d3_cross(u, t));
}

core_d3 core_xf_rotate(const coll_transform_t *xf, core_d3 v)
{
    double q[4];
    quat_d(xf, q);
    return rot(q, v);
}

core_d3 core_xf_unrotate(const coll_transform_t *xf, core_d3 v)
{
    double q[4];
    quat_d(xf, q);
    q[0] = -q[0]; q[1] = -q[1]; q[2] = -q[2];
    return rot(q, v);
}

core_d3 core_xf_point(const coll_transform_t *xf, core_d3 p)
{
    core_d3 s = { p.x * xf->scale.x, p.y * xf->scale.y, p.z * xf->scale.z };
    return core_d3_add(core_xf_rotate(xf, s), core_d3_of(xf->pos));
}

void core_world_tri(const coll_mesh_instance_t *inst, uint32_t t, core_d3 out[3])
{
    fm_vec3_t v[3];
    coll_mesh_triangle(inst->mesh, t, v);
    for (int k = 0; k < 3; k++) out[k] = core_xf_point(&inst->xf, core_d3_of(v[k]));
}

bool core_ray_tri(core_d3 o, core_d3 d, const core_d3 tri[3], double s_max, double slack, double *s,
                  double *min_bary, core_d3 *n)
{
    core_d3 e1 = core_d3_sub(tri[1], tri[0]), e2 = core_d3_sub(tri[2], tri[0]);
    core_d3 nn = core_d3_cross(e1, e2);
    double den = -core_d3_dot(d, nn);
    if (fabs(den) < 1e-300) return false;
    core_d3 ao = core_d3_sub(o, tri[0]);
    double t = core_d3_dot(ao, nn) / den;
    if (t < 0 || t > s_max) return false;
    core_d3 p = core_d3_add(o, core_d3_scale(d, t));
    double nn2 = core_d3_dot(nn, nn);
    double b[3];
    for (int i = 0; i < 3; i++) {
        core_d3 a = tri[(i + 1) % 3], c = tri[(i + 2) % 3];
        b[i] = core_d3_dot(core_d3_cross(core_d3_sub(a, p), core_d3_sub(c, p)), nn) / nn2;
    }
    double mb = fmin(b[0], fmin(b[1], b[2]));
    if (mb < -slack) return false;
    *s = t;
    *min_bary = mb;
    double l = sqrt(nn2);
    nn = core_d3_scale(nn, 1.0 / l);
    if (core_d3_dot(nn, d) > 0) nn = core_d3_scale(nn, -1.0);
    *n = nn;
    return true;
}

/* Ray vs sphere/cylinder-side/slab pieces in the body's local frame. */
static bool ray_sphere(core_d3 o, core_d3 d, core_d3 c, double r, double *s, core_d3 *n)
{
    core_d3 m = core_d3_sub(o, c);
    double a = core_d3_dot(d, d), b = core_d3_dot(m, d), cc = core_d3_dot(m, m) - r * r;
    double disc = b * b - a * cc;
    if (disc < 0) return false;
    double t = (-b - sqrt(disc)) / a;
    if (t < 0) return false;
    *s = t;
    *n = core_d3_scale(core_d3_sub(core_d3_add(o, core_d3_scale(d, t)), c), 1.0 / r);
    return true;
}

/* Infinite cylinder around local Y, radius r, only |y| <= h accepted. */
static bool ray_cyl_side(core_d3 o, core_d3 d, double r, double h, double *s, core_d3 *n)
{
    double a = d.x * d.x + d.z * d.z, b = o.x * d.x + o.z * d.z, c = o.x * o.x + o.z * o.z - r * r;
    if (a < 1e-300) return false;
    double disc = b * b - a * c;
    if (disc < 0) return false;
    double t = (-b - sqrt(disc)) / a;
    if (t < 0) return false;
    double y = o.y + d.y * t;
    if (fabs(y) > h) return false;
    core_d3 p = core_d3_add(o, core_d3_scale(d, t));
    core_d3 nn = { p.x / r, 0, p.z / r };
    *s = t;
    *n = nn;
    return true;
}

static void take(bool hit, double s, core_d3 n, bool *have, double *best, core_d3 *bn)
{
    if (hit && (!*have || s < *best)) { *have = true; *best = s; *bn = n; }
}

bool core_ray_body(core_d3 o, core_d3 d, const coll_body_t *b, double s_max, double *s, core_d3 *n)
{
    core_d3 lo = core_xf_unrotate(&b->xf, core_d3_sub(o, core_d3_of(b->xf.pos)));
    core_d3 ld = core_xf_unrotate(&b->xf, d);
    double hx = b->half_extents.x, hy = b->half_extents.y, hz = b->half_extents.z;
    bool have = false;
    double best = 0, t = 0;
    core_d3 bn = { 0, 0, 0 }, nn;
    switch (b->shape) {
    case COLL_SHAPE_SPHERE: {
        core_d3 c = { 0, 0, 0 };
        { bool ok_ = ray_sphere(lo, ld, c, hx, &t, &nn); take(ok_, t, nn, &have, &best, &bn); }
        break;
    }
    case COLL_SHAPE_CAPSULE: {
        core_d3 c0 = { 0, -hy, 0 }, c1 = { 0, hy, 0 };
        { bool ok_ = ray_cyl_side(lo, ld, hx, hy, &t, &nn); take(ok_, t, nn, &have, &best, &bn); }
        { bool ok_ = ray_sphere(lo, ld, c0, hx, &t, &nn); take(ok_, t, nn, &have, &best, &bn); }
        { bool ok_ = ray_sphere(lo, ld, c1, hx, &t, &nn); take(ok_, t, nn, &have, &best, &bn); }
        break;
    }
    case COLL_SHAPE_CYLINDER: {
        { bool ok_ = ray_cyl_side(lo, ld, hx, hy, &t, &nn); take(ok_, t, nn, &have, &best, &bn); }
        for (int sgn = -1; sgn <= 1; sgn += 2) {
            if (fabs(ld.y) < 1e-300) continue;
            t = (sgn * hy - lo.y) / ld.y;
            if (t < 0) continue;
            core_d3 p = core_d3_add(lo, core_d3_scale(ld, t));
            if (p.x * p.x + p.z * p.z > hx * hx) continue;
            core_d3 cn = { 0, (double)sgn, 0 };
            take(true, t, cn, &have, &best, &bn);
        }
        break;
    }
    case COLL_SHAPE_BOX: {
        double h[3] = { hx, hy, hz }, ov[3] = { lo.x, lo.y, lo.z }, dv[3] = { ld.x, ld.y, ld.z };
        double t0 = 0, t1 = 1e300;
        int ax = -1;
        double sg = 0;
        for (int a = 0; a < 3; a++) {
            if (fabs(dv[a]) < 1e-300) {
                if (fabs(ov[a]) > h[a]) return false;
                continue;
            }
            double ta = (-h[a] - ov[a]) / dv[a], tb = (h[a] - ov[a]) / dv[a];
            double sa = -1;
            if (ta > tb) { double x = ta; ta = tb; tb = x; sa = 1; }
            if (ta > t0) { t0 = ta; ax = a; sg = sa; }
            if (tb < t1) t1 = tb;
            if (t0 > t1) return false;
        }
        if (ax < 0) return false;
        core_d3 cn = { ax == 0 ? sg : 0, ax == 1 ? sg : 0, ax == 2 ? sg : 0 };
        take(true, t0, cn, &have, &best, &bn);
        break;
    }
    }
    if (!have || best > s_max) return false;
    *s = best;
    *n = core_xf_rotate(&b->xf, bn);
    return true;
}

static double clamp01(double x) { return x < 0 ? 0 : (x > 1 ? 1 : x); }

double core_seg_seg(core_d3 p0, core_d3 p1, core_d3 q0, core_d3 q1, core_d3 *cp, core_d3 *cq)
{
    core_d3 d1 = core_d3_sub(p1, p0), d2 = core_d3_sub(q1, q0), r = core_d3_sub(p0, q0);
    double a = core_d3_dot(d1, d1), e = core_d3_dot(d2, d2), f = core_d3_dot(d2, r);
    double s, t;
    if (a <= 1e-300 && e <= 1e-300) {
        s = t = 0;
    } else if (a <= 1e-300) {
        s = 0;
        t = clamp01(f / e);
    } else {
        double c = core_d3_dot(d1, r);
        if (e <= 1e-300) {
            t = 0;
            s = clamp01(-c / a);
        } else {
            double b = core_d3_dot(d1, d2), den = a * e - b * b;
            s = den > 1e-300 * a * e ? clamp01((b * f - c * e) / den) : 0;
            t = (b * s + f) / e;
            if (t < 0) { t = 0; s = clamp01(-c / a); }
            else if (t > 1) { t = 1; s = clamp01((b - c) / a); }
        }
    }
    core_d3 x = core_d3_add(p0, core_d3_scale(d1, s)), y = core_d3_add(q0, core_d3_scale(d2, t));
    if (cp) *cp = x;
    if (cq) *cq = y;
    return core_d3_len(core_d3_sub(x, y));
}

/* Ericson's closest point on triangle. */
static core_d3 closest_pt_tri(core_d3 p, core_d3 a, core_d3 b, core_d3 c)
{
    core_d3 ab = core_d3_sub(b, a), ac = core_d3_sub(c, a), ap = core_d3_sub(p, a);
    double d1 = core_d3_dot(ab, ap), d2 = core_d3_dot(ac, ap);
    if (d1 <= 0 && d2 <= 0) return a;
    core_d3 bp = core_d3_sub(p, b);
    double d3 = core_d3_dot(ab, bp), d4 = core_d3_dot(ac, bp);
    if (d3 >= 0 && d4 <= d3) return b;
    double vc = d1 * d4 - d3 * d2;
    if (vc <= 0 && d1 >= 0 && d3 <= 0) return core_d3_add(a, core_d3_scale(ab, d1 / (d1 - d3)));
    core_d3 cp = core_d3_sub(p, c);
    double d5 = core_d3_dot(ab, cp), d6 = core_d3_dot(ac, cp);
    if (d6 >= 0 && d5 <= d6) return c;
    double vb = d5 * d2 - d1 * d6;
    if (vb <= 0 && d2 >= 0 && d6 <= 0) return core_d3_add(a, core_d3_scale(ac, d2 / (d2 - d6)));
    double va = d3 * d6 - d5 * d4;
    if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0)
        return core_d3_add(b, core_d3_scale(core_d3_sub(c, b), (d4 - d3) / ((d4 - d3) + (d5 - d6))));
    double den = 1.0 / (va + vb + vc);
    return core_d3_add(a, core_d3_add(core_d3_scale(ab, vb * den), core_d3_scale(ac, vc * den)));
}

double core_seg_tri(core_d3 p0, core_d3 p1, const core_d3 tri[3], core_d3 *cp, core_d3 *ct)
{
    double best = 1e300;
    core_d3 bp = p0, bt = tri[0];
    /* segment crossing the triangle */
    core_d3 d = core_d3_sub(p1, p0);
    double s, mb;
    core_d3 n;
    if (core_ray_tri(p0, d, tri, 1.0, 0.0, &s, &mb, &n)) {
        core_d3 x = core_d3_add(p0, core_d3_scale(d, s));
        if (cp) *cp = x;
        if (ct) *ct = x;
        return 0.0;
    }
    for (int e = 0; e < 2; e++) {
        core_d3 p = e ? p1 : p0;
        core_d3 q = closest_pt_tri(p, tri[0], tri[1], tri[2]);
        double l = core_d3_len(core_d3_sub(p, q));
        if (l < best) { best = l; bp = p; bt = q; }
    }
    for (int i = 0; i < 3; i++) {
        core_d3 x, y;
        double l = core_seg_seg(p0, p1, tri[i], tri[(i + 1) % 3], &x, &y);
        if (l < best) { best = l; bp = x; bt = y; }
    }
    if (cp) *cp = bp;
    if (ct) *ct = bt;
    return best;
}

double core_seg_body_core(core_d3 p0, core_d3 p1, const coll_body_t *b, double *body_r, core_d3 *cp,
                          core_d3 *cb)
{
    core_d3 c = core_d3_of(b->xf.pos);
    double hy = b->shape == COLL_SHAPE_CAPSULE ? b->half_extents.y : 0.0;
    core_d3 ax = { 0, hy, 0 };
    ax = core_xf_rotate(&b->xf, ax);
    *body_r = b->half_extents.x;
    return core_seg_seg(p0, p1, core_d3_sub(c, ax), core_d3_add(c, ax), cp, cb);
}

void core_sweep_analyse(core_dist_fn f, void *ctx, double reach, core_sweep_ref_t *out)
{
    out->f0 = f(ctx, 0.0);
    out->t_touch = 0.0;
    if (out->f0 <= 0.0) {
        out->fmin = out->f0; /* f is convex: the min may be lower, but t_touch = 0 anyway */
        double a = 0, b = 1;
        for (int i = 0; i < 56; i++) {
            double m1 = a + (b - a) * 0.381966, m2 = b - (b - a) * 0.381966;
            if (f(ctx, m1) < f(ctx, m2)) b = m2; else a = m1;
        }
        out->fmin = fmin(out->f0, f(ctx, 0.5 * (a + b)));
        return;
    }
    if (out->f0 - reach > 1e-3) { out->fmin = out->f0 - reach; return; } /* cannot reach */
    double a = 0, b = 1;
    for (int i = 0; i < 56; i++) {
        double m1 = a + (b - a) * 0.381966, m2 = b - (b - a) * 0.381966;
        if (f(ctx, m1) < f(ctx, m2)) b = m2; else a = m1;
    }
    double tm = 0.5 * (a + b);
    out->fmin = fmin(f(ctx, tm), f(ctx, 1.0));
    if (f(ctx, 1.0) < f(ctx, tm)) tm = 1.0;
    if (out->fmin > 0) return;
    double lo = 0, hi = tm;
    for (int i = 0; i < 56; i++) {
        double m = 0.5 * (lo + hi);
        if (f(ctx, m) > 0) lo = m; else hi = m;
    }
    out->t_touch = hi;
}
