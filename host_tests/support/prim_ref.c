/* Double-precision reference geometry for the primitive tests (see prim_ref.h). */
#include "prim_ref.h"
#include <math.h>
#include <stddef.h>

prim_ref_v3 prim_ref_v(double x, double y, double z) { prim_ref_v3 v = { x, y, z }; return v; }
prim_ref_v3 prim_ref_add(prim_ref_v3 a, prim_ref_v3 b) { return prim_ref_v(a.x + b.x, a.y + b.y, a.z + b.z); }
prim_ref_v3 prim_ref_sub(prim_ref_v3 a, prim_ref_v3 b) { return prim_ref_v(a.x - b.x, a.y - b.y, a.z - b.z); }
prim_ref_v3 prim_ref_scale(prim_ref_v3 a, double s) { return prim_ref_v(a.x * s, a.y * s, a.z * s); }
double prim_ref_dot(prim_ref_v3 a, prim_ref_v3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
prim_ref_v3 prim_ref_cross(prim_ref_v3 a, prim_ref_v3 b)
{
    return prim_ref_v(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}
double prim_ref_len(prim_ref_v3 a) { return sqrt(prim_ref_dot(a, a)); }

static double clamp01(double x) { return x < 0 ? 0 : (x > 1 ? 1 : x); }

double prim_ref_seg_seg(prim_ref_v3 p0, prim_ref_v3 p1, prim_ref_v3 q0, prim_ref_v3 q1,
                        prim_ref_v3 *cp, prim_ref_v3 *cq)
{
    prim_ref_v3 d1 = prim_ref_sub(p1, p0), d2 = prim_ref_sub(q1, q0), r = prim_ref_sub(p0, q0);
    double a = prim_ref_dot(d1, d1), e = prim_ref_dot(d2, d2), f = prim_ref_dot(d2, r);
    double s, t;
    if (a <= 1e-300 && e <= 1e-300) { s = t = 0; }
    else if (a <= 1e-300) { s = 0; t = clamp01(f / e); }
    else {
        double c = prim_ref_dot(d1, r);
        if (e <= 1e-300) { t = 0; s = clamp01(-c / a); }
        else {
            double b = prim_ref_dot(d1, d2);
            prim_ref_v3 cr = prim_ref_cross(d1, d2);
            double den = prim_ref_dot(cr, cr);
            s = den > 1e-28 * a * e ? clamp01((b * f - c * e) / den) : 0;
            t = (b * s + f) / e;
            if (t < 0) { t = 0; s = clamp01(-c / a); }
            else if (t > 1) { t = 1; s = clamp01((b - c) / a); }
        }
    }
    /* near-parallel segments: polish the pair by alternating projections */
    for (int it = 0; it < 4; it++) {
        prim_ref_v3 y = prim_ref_add(q0, prim_ref_scale(d2, t));
        if (a > 1e-300) s = clamp01(prim_ref_dot(prim_ref_sub(y, p0), d1) / a);
        prim_ref_v3 x = prim_ref_add(p0, prim_ref_scale(d1, s));
        if (e > 1e-300) t = clamp01(prim_ref_dot(prim_ref_sub(x, q0), d2) / e);
    }
    prim_ref_v3 x = prim_ref_add(p0, prim_ref_scale(d1, s)), y = prim_ref_add(q0, prim_ref_scale(d2, t));
    if (cp) *cp = x;
    if (cq) *cq = y;
    return prim_ref_len(prim_ref_sub(x, y));
}

prim_ref_v3 prim_ref_closest_pt_tri(prim_ref_v3 p, const prim_ref_v3 tri[3])
{
    prim_ref_v3 a = tri[0], b = tri[1], c = tri[2];
    prim_ref_v3 n = prim_ref_cross(prim_ref_sub(b, a), prim_ref_sub(c, a));
    double nn = prim_ref_dot(n, n);
    prim_ref_v3 best = a;
    double bd = 1e300;
    if (nn > 0) {
        prim_ref_v3 q = prim_ref_sub(p, prim_ref_scale(n, prim_ref_dot(n, prim_ref_sub(p, a)) / nn));
        bool in = true;
        for (int i = 0; i < 3; i++) {
            prim_ref_v3 e = prim_ref_sub(tri[(i + 1) % 3], tri[i]);
            if (prim_ref_dot(prim_ref_cross(e, prim_ref_sub(q, tri[i])), n) < 0) in = false;
        }
        if (in) return q;
    }
    for (int i = 0; i < 3; i++) {
        prim_ref_v3 cq;
        double d = prim_ref_seg_seg(p, p, tri[i], tri[(i + 1) % 3], NULL, &cq);
        if (d < bd) { bd = d; best = cq; }
    }
    return best;
}

double prim_ref_seg_tri(prim_ref_v3 a, prim_ref_v3 b, const prim_ref_v3 tri[3],
                        prim_ref_v3 *ps, prim_ref_v3 *pt)
{
    prim_ref_v3 n = prim_ref_cross(prim_ref_sub(tri[1], tri[0]), prim_ref_sub(tri[2], tri[0]));
    double nn = prim_ref_dot(n, n);
    if (nn > 0) {
        double ha = prim_ref_dot(n, prim_ref_sub(a, tri[0])), hb = prim_ref_dot(n, prim_ref_sub(b, tri[0]));
        if ((ha <= 0 && hb >= 0) || (ha >= 0 && hb <= 0)) {
            prim_ref_v3 x = (ha != hb) ? prim_ref_add(a, prim_ref_scale(prim_ref_sub(b, a), ha / (ha - hb))) : a;
            bool in = true;
            for (int i = 0; i < 3; i++) {
                prim_ref_v3 e = prim_ref_sub(tri[(i + 1) % 3], tri[i]);
                if (prim_ref_dot(prim_ref_cross(e, prim_ref_sub(x, tri[i])), n) < 0) in = false;
            }
            if (in) { if (ps) *ps = x; if (pt) *pt = x; return 0; }
        }
    }
    double best = 1e300;
    prim_ref_v3 bs = a, bt = tri[0];
    prim_ref_v3 ends[2] = { a, b };
    for (int k = 0; k < 2; k++) {
        prim_ref_v3 q = prim_ref_closest_pt_tri(ends[k], tri);
        double d = prim_ref_len(prim_ref_sub(ends[k], q));
        if (d < best) { best = d; bs = ends[k]; bt = q; }
    }
    for (int i = 0; i < 3; i++) {
        prim_ref_v3 cp, cq;
        double d = prim_ref_seg_seg(a, b, tri[i], tri[(i + 1) % 3], &cp, &cq);
        if (d < best) { best = d; bs = cp; bt = cq; }
    }
    if (ps) *ps = bs;
    if (pt) *pt = bt;
    return best;
}

double prim_ref_captri_fn(void *vctx, double t, prim_ref_v3 *normal)
{
    prim_ref_captri_t *c = vctx;
    prim_ref_v3 off = prim_ref_scale(c->d, t), ps, pt;
    double d = prim_ref_seg_tri(prim_ref_add(c->a, off), prim_ref_add(c->b, off), c->tri, &ps, &pt);
    if (normal) *normal = d > 0 ? prim_ref_scale(prim_ref_sub(ps, pt), 1.0 / d) : prim_ref_v(0, 0, 0);
    return d;
}

void prim_ref_sweep(prim_ref_fn f, void *ctx, double r, double t_max, prim_ref_sweep_t *out)
{
    out->f0 = f(ctx, 0, NULL);
    double lo = 0, hi = t_max;
    const double g = 0.6180339887498949;
    double x1 = hi - g * (hi - lo), x2 = lo + g * (hi - lo);
    double f1 = f(ctx, x1, NULL), f2 = f(ctx, x2, NULL);
    for (int it = 0; it < 75; it++) {
        if (f1 <= f2) { hi = x2; x2 = x1; f2 = f1; x1 = hi - g * (hi - lo); f1 = f(ctx, x1, NULL); }
        else { lo = x1; x1 = x2; f1 = f2; x2 = lo + g * (hi - lo); f2 = f(ctx, x2, NULL); }
    }
    out->tmin = 0.5 * (lo + hi);
    out->fmin = f(ctx, out->tmin, NULL);
    double fe = f(ctx, t_max, NULL);
    if (out->f0 <= out->fmin) { out->fmin = out->f0; out->tmin = 0; }
    if (fe < out->fmin) { out->fmin = fe; out->tmin = t_max; }
    out->n = prim_ref_v(0, 0, 0);
    if (out->f0 <= r) { out->t_first = 0; f(ctx, 0, &out->n); return; }
    if (out->fmin > r) { out->t_first = -1; return; }
    lo = 0; hi = out->tmin;
    for (int it = 0; it < 200 && hi - lo > 1e-13 * (1 + t_max); it++) {
        double m = 0.5 * (lo + hi);
        if (f(ctx, m, NULL) > r) lo = m; else hi = m;
    }
    out->t_first = hi;
    f(ctx, hi, &out->n);
}

uint32_t prim_ref_rng_u32(prim_ref_rng_t *g)
{
    g->s ^= g->s << 13; g->s ^= g->s >> 7; g->s ^= g->s << 17;
    return (uint32_t)(g->s >> 32);
}

double prim_ref_rng_range(prim_ref_rng_t *g, double a, double b)
{
    return a + (b - a) * (prim_ref_rng_u32(g) / 4294967296.0);
}

prim_ref_v3 prim_ref_rng_unit(prim_ref_rng_t *g)
{
    for (;;) {
        prim_ref_v3 v = prim_ref_v(prim_ref_rng_range(g, -1, 1), prim_ref_rng_range(g, -1, 1),
                                   prim_ref_rng_range(g, -1, 1));
        double l = prim_ref_len(v);
        if (l > 0.1 && l <= 1) return prim_ref_scale(v, 1 / l);
    }
}
