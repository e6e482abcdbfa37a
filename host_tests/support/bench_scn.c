/* Benchmark / stability support: geometry builders, double-precision reference, scenarios.
 * See bench_scn.h. Test-side code: doubles are fine here. */
#include "bench_scn.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

/* ================================================================== geometry */

void bench_geo_init(bench_geo_t *g, float *v, uint32_t cap_v, uint32_t *idx, uint32_t cap_t)
{
    memset(g, 0, sizeof(*g));
    g->v = v; g->idx = idx; g->cap_v = cap_v; g->cap_t = cap_t;
}

uint32_t bench_geo_vert(bench_geo_t *g, double x, double y, double z)
{
    if (g->nv >= g->cap_v) { g->overflow = true; return 0; }
    g->v[3 * g->nv + 0] = (float)x;
    g->v[3 * g->nv + 1] = (float)y;
    g->v[3 * g->nv + 2] = (float)z;
    return g->nv++;
}

void bench_geo_tri(bench_geo_t *g, uint32_t a, uint32_t b, uint32_t c)
{
    if (g->nt >= g->cap_t || g->overflow) { g->overflow = true; return; }
    g->idx[3 * g->nt + 0] = a;
    g->idx[3 * g->nt + 1] = b;
    g->idx[3 * g->nt + 2] = c;
    g->nt++;
}

void bench_geo_quad(bench_geo_t *g, fm_vec3_t a, fm_vec3_t b, fm_vec3_t c, fm_vec3_t d)
{
    uint32_t ia = bench_geo_vert(g, a.x, a.y, a.z), ib = bench_geo_vert(g, b.x, b.y, b.z);
    uint32_t ic = bench_geo_vert(g, c.x, c.y, c.z), id = bench_geo_vert(g, d.x, d.y, d.z);
    bench_geo_tri(g, ia, ib, ic);
    bench_geo_tri(g, ia, ic, id);
}

static fm_vec3_t v3(double x, double y, double z)
{
    fm_vec3_t r = {{(float)x, (float)y, (float)z}};
    return r;
}

void bench_geo_box(bench_geo_t *g, fm_vec3_t mn, fm_vec3_t mx)
{
    uint32_t i[8];
    for (int k = 0; k < 8; k++)
        i[k] = bench_geo_vert(g, (k & 1) ? mx.x : mn.x, (k & 2) ? mx.y : mn.y, (k & 4) ? mx.z : mn.z);
    static const uint8_t f[6][4] = {
        {0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5} };
    for (int k = 0; k < 6; k++) {
        bench_geo_tri(g, i[f[k][0]], i[f[k][1]], i[f[k][2]]);
        bench_geo_tri(g, i[f[k][0]], i[f[k][2]], i[f[k][3]]);
    }
}

void bench_geo_grid(bench_geo_t *g, double x0, double z0, double x1, double z1, double y,
                    uint32_t n, uint32_t m)
{
    uint32_t base = g->nv;
    for (uint32_t j = 0; j <= m; j++)
        for (uint32_t i = 0; i <= n; i++)
            bench_geo_vert(g, x0 + (x1 - x0) * i / n, y, z0 + (z1 - z0) * j / m);
    for (uint32_t j = 0; j < m; j++)
        for (uint32_t i = 0; i < n; i++) {
            uint32_t a = base + j * (n + 1) + i, b = a + 1, c = a + n + 1, d = c + 1;
            if ((i + j) & 1) { bench_geo_tri(g, a, b, d); bench_geo_tri(g, a, d, c); }
            else             { bench_geo_tri(g, a, b, c); bench_geo_tri(g, b, d, c); }
        }
}

void bench_geo_wall(bench_geo_t *g, double x0, double z0, double x1, double z1, double y0, double y1)
{
    bench_geo_quad(g, v3(x0, y0, z0), v3(x1, y0, z1), v3(x1, y1, z1), v3(x0, y1, z0));
}

void bench_geo_offset(bench_geo_t *g, double dx, double dy, double dz)
{
    for (uint32_t i = 0; i < g->nv; i++) {
        g->v[3 * i + 0] = (float)(g->v[3 * i + 0] + dx);
        g->v[3 * i + 1] = (float)(g->v[3 * i + 1] + dy);
        g->v[3 * i + 2] = (float)(g->v[3 * i + 2] + dz);
    }
}

/* ====================================================== double reference */

typedef bench_d3_t d3;
static d3 dv(double x, double y, double z) { d3 r = {x, y, z}; return r; }
static d3 dadd(d3 a, d3 b) { return dv(a.x + b.x, a.y + b.y, a.z + b.z); }
static d3 dsub(d3 a, d3 b) { return dv(a.x - b.x, a.y - b.y, a.z - b.z); }
static d3 dmul(d3 a, double s) { return dv(a.x * s, a.y * s, a.z * s); }
static double ddot(d3 a, d3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static d3 dcross(d3 a, d3 b) { return dv(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x); }
static double dlen(d3 a) { return sqrt(ddot(a, a)); }
static d3 dof(fm_vec3_t v) { return dv(v.x, v.y, v.z); }
static double clamp01(double x) { return x < 0 ? 0 : (x > 1 ? 1 : x); }

/* Ericson, Real-Time Collision Detection 5.1.5 */
static d3 closest_pt_tri(d3 p, d3 a, d3 b, d3 c)
{
    d3 ab = dsub(b, a), ac = dsub(c, a), ap = dsub(p, a);
    double d1 = ddot(ab, ap), d2 = ddot(ac, ap);
    if (d1 <= 0 && d2 <= 0) return a;
    d3 bp = dsub(p, b);
    double d3_ = ddot(ab, bp), d4 = ddot(ac, bp);
    if (d3_ >= 0 && d4 <= d3_) return b;
    double vc = d1 * d4 - d3_ * d2;
    if (vc <= 0 && d1 >= 0 && d3_ <= 0) { double v = d1 / (d1 - d3_); return dadd(a, dmul(ab, v)); }
    d3 cp = dsub(p, c);
    double d5 = ddot(ab, cp), d6 = ddot(ac, cp);
    if (d6 >= 0 && d5 <= d6) return c;
    double vb = d5 * d2 - d1 * d6;
    if (vb <= 0 && d2 >= 0 && d6 <= 0) { double w = d2 / (d2 - d6); return dadd(a, dmul(ac, w)); }
    double va = d3_ * d6 - d5 * d4;
    if (va <= 0 && (d4 - d3_) >= 0 && (d5 - d6) >= 0) {
        double w = (d4 - d3_) / ((d4 - d3_) + (d5 - d6));
        return dadd(b, dmul(dsub(c, b), w));
    }
    double den = va + vb + vc;
    if (!(fabs(den) > 0)) return a;
    double v = vb / den, w = vc / den;
    return dadd(a, dadd(dmul(ab, v), dmul(ac, w)));
}

/* Ericson 5.1.9: closest points of segments p1q1 and p2q2; returns squared distance. */
static double closest_seg_seg(d3 p1, d3 q1, d3 p2, d3 q2, d3 *c1, d3 *c2)
{
    d3 d1 = dsub(q1, p1), d2 = dsub(q2, p2), r = dsub(p1, p2);
    double a = ddot(d1, d1), e = ddot(d2, d2), f = ddot(d2, r);
    double s, t;
    const double eps = 1e-300;
    if (a <= eps && e <= eps) { *c1 = p1; *c2 = p2; return ddot(r, r); }
    if (a <= eps) { s = 0; t = clamp01(f / e); }
    else {
        double c = ddot(d1, r);
        if (e <= eps) { t = 0; s = clamp01(-c / a); }
        else {
            double b = ddot(d1, d2), den = a * e - b * b;
            s = den > 0 ? clamp01((b * f - c * e) / den) : 0;
            t = (b * s + f) / e;
            if (t < 0) { t = 0; s = clamp01(-c / a); }
            else if (t > 1) { t = 1; s = clamp01((b - c) / a); }
        }
    }
    *c1 = dadd(p1, dmul(d1, s));
    *c2 = dadd(p2, dmul(d2, t));
    d3 w = dsub(*c1, *c2);
    return ddot(w, w);
}

double bench_ref_seg_tri_dist(d3 p0, d3 p1, const d3 t[3], d3 *ps, d3 *pt)
{
    d3 n = dcross(dsub(t[1], t[0]), dsub(t[2], t[0]));
    double nn = ddot(n, n);
    if (nn > 1e-40) {
        double s0 = ddot(n, dsub(p0, t[0])), s1 = ddot(n, dsub(p1, t[0]));
        if (((s0 <= 0 && s1 >= 0) || (s0 >= 0 && s1 <= 0)) && s0 != s1) {
            double s = s0 / (s0 - s1);
            d3 q = dadd(p0, dmul(dsub(p1, p0), s));
            double e0 = ddot(n, dcross(dsub(t[1], t[0]), dsub(q, t[0])));
            double e1 = ddot(n, dcross(dsub(t[2], t[1]), dsub(q, t[1])));
            double e2 = ddot(n, dcross(dsub(t[0], t[2]), dsub(q, t[2])));
            if (e0 >= 0 && e1 >= 0 && e2 >= 0) {
                if (ps) *ps = q;
                if (pt) *pt = q;
                return 0.0;
            }
        }
    }
    d3 bs = p0, bt = closest_pt_tri(p0, t[0], t[1], t[2]);
    double best = ddot(dsub(bs, bt), dsub(bs, bt));
    d3 q = closest_pt_tri(p1, t[0], t[1], t[2]);
    double d = ddot(dsub(p1, q), dsub(p1, q));
    if (d < best) { best = d; bs = p1; bt = q; }
    for (int e = 0; e < 3; e++) {
        d3 c1, c2;
        d = closest_seg_seg(p0, p1, t[e], t[(e + 1) % 3], &c1, &c2);
        if (d < best) { best = d; bs = c1; bt = c2; }
    }
    if (ps) *ps = bs;
    if (pt) *pt = bt;
    return sqrt(best);
}

/* Conservative advancement on the exact double distance. Returns 1 hit, 0 none. */
static int ref_sweep_d(d3 p0, d3 p1, double r, d3 D, const d3 T[3], double t_max,
                       double *t_out, double *depth, d3 *normal, d3 *point)
{
    d3 ps, pt;
    double d = bench_ref_seg_tri_dist(p0, p1, T, &ps, &pt);
    if (d < r) {
        d3 n = dsub(ps, pt);
        double l = dlen(n);
        if (l > 1e-12) n = dmul(n, 1.0 / l);
        else {
            n = dcross(dsub(T[1], T[0]), dsub(T[2], T[0]));
            l = dlen(n);
            n = l > 0 ? dmul(n, 1.0 / l) : dv(0, 1, 0);
            if (ddot(n, dsub(dmul(dadd(p0, p1), 0.5), T[0])) < 0) n = dmul(n, -1.0);
        }
        *t_out = 0; *depth = r - d; *normal = n; *point = pt;
        return 1;
    }
    double L = dlen(D);
    if (!(L > 1e-12)) return 0;
    double t = 0;
    for (int it = 0; it < 400000; it++) {
        d3 o = dmul(D, t);
        d = bench_ref_seg_tri_dist(dadd(p0, o), dadd(p1, o), T, &ps, &pt) - r;
        if (d <= 1e-7) {
            d3 n = dsub(ps, pt);
            double l = dlen(n);
            n = l > 0 ? dmul(n, 1.0 / l) : dmul(D, -1.0 / L);
            if (ddot(n, D) < -1e-9 * L) {
                *t_out = t; *depth = 0; *normal = n; *point = pt;
                return 1;
            }
            t += fmax(d / L, 1e-6);   /* touching but not approaching: creep on */
        } else {
            t += d / L;
        }
        if (t > t_max) return 0;
    }
    return 0;
}

bool bench_ref_tri_sweep(void *ctx, const fm_vec3_t seg[2], float r, const fm_vec3_t *disp,
                         const fm_vec3_t tri[3], float t_max, coll_prim_hit_t *hit)
{
    (void)ctx;
    d3 T[3] = {dof(tri[0]), dof(tri[1]), dof(tri[2])};
    double t, depth;
    d3 n, p;
    if (!ref_sweep_d(dof(seg[0]), dof(seg[1]), r, dof(*disp), T, t_max, &t, &depth, &n, &p))
        return false;
    hit->t = (float)t;
    if (hit->t > t_max) hit->t = t_max;
    hit->depth = (float)depth;
    hit->normal = v3(n.x, n.y, n.z);
    hit->point = v3(p.x, p.y, p.z);
    return true;
}

static d3 xf_point(const coll_transform_t *xf, d3 p)
{
    if (!xf) return p;
    p = dv(p.x * xf->scale.x, p.y * xf->scale.y, p.z * xf->scale.z);
    d3 q = dv(xf->rot.x, xf->rot.y, xf->rot.z);
    double w = xf->rot.w;
    d3 t = dmul(dcross(q, p), 2.0);
    p = dadd(dadd(p, dmul(t, w)), dcross(q, t));
    return dadd(p, dof(xf->pos));
}

static bool xf_is_identity(const coll_transform_t *xf)
{
    return !xf || (xf->pos.x == 0 && xf->pos.y == 0 && xf->pos.z == 0 && xf->rot.x == 0 && xf->rot.y == 0 &&
                   xf->rot.z == 0 && xf->rot.w == 1 && xf->scale.x == 1 && xf->scale.y == 1 && xf->scale.z == 1);
}

static void part_tri(const bench_ref_part_t *pt, uint32_t i, d3 T[3])
{
    const bench_geo_t *g = pt->geo;
    bool id = xf_is_identity(pt->xf);
    for (int k = 0; k < 3; k++) {
        const float *v = &g->v[3 * g->idx[3 * i + k]];
        T[k] = id ? dv(v[0], v[1], v[2]) : xf_point(pt->xf, dv(v[0], v[1], v[2]));
    }
}

double bench_ref_penetration(const bench_ref_part_t *parts, int nparts, d3 p0, d3 p1, double r)
{
    double pen = 0;
    d3 mn = dv(fmin(p0.x, p1.x) - r, fmin(p0.y, p1.y) - r, fmin(p0.z, p1.z) - r);
    d3 mx = dv(fmax(p0.x, p1.x) + r, fmax(p0.y, p1.y) + r, fmax(p0.z, p1.z) + r);
    for (int k = 0; k < nparts; k++)
        for (uint32_t i = 0; i < parts[k].geo->nt; i++) {
            d3 T[3];
            part_tri(&parts[k], i, T);
            if (fmax(T[0].x, fmax(T[1].x, T[2].x)) < mn.x || fmin(T[0].x, fmin(T[1].x, T[2].x)) > mx.x ||
                fmax(T[0].y, fmax(T[1].y, T[2].y)) < mn.y || fmin(T[0].y, fmin(T[1].y, T[2].y)) > mx.y ||
                fmax(T[0].z, fmax(T[1].z, T[2].z)) < mn.z || fmin(T[0].z, fmin(T[1].z, T[2].z)) > mx.z)
                continue;
            /* zero-area triangles are dropped by the mesh build: skip them here too */
            if (dlen(dcross(dsub(T[1], T[0]), dsub(T[2], T[0]))) <= 0) continue;
            double d = bench_ref_seg_tri_dist(p0, p1, T, NULL, NULL);
            if (r - d > pen) pen = r - d;
        }
    return pen;
}

double bench_ref_sweep_t(const bench_ref_part_t *parts, int nparts, d3 c, d3 axis, double r,
                         double hh, d3 disp)
{
    d3 p0 = dsub(c, dmul(axis, hh)), p1 = dadd(c, dmul(axis, hh));
    double best = 2.0;
    d3 e = dv(fabs(axis.x) * hh + r, fabs(axis.y) * hh + r, fabs(axis.z) * hh + r);
    d3 mn = dv(fmin(c.x, c.x + disp.x) - e.x, fmin(c.y, c.y + disp.y) - e.y, fmin(c.z, c.z + disp.z) - e.z);
    d3 mx = dv(fmax(c.x, c.x + disp.x) + e.x, fmax(c.y, c.y + disp.y) + e.y, fmax(c.z, c.z + disp.z) + e.z);
    for (int k = 0; k < nparts; k++)
        for (uint32_t i = 0; i < parts[k].geo->nt; i++) {
            d3 T[3];
            part_tri(&parts[k], i, T);
            if (fmax(T[0].x, fmax(T[1].x, T[2].x)) < mn.x || fmin(T[0].x, fmin(T[1].x, T[2].x)) > mx.x ||
                fmax(T[0].y, fmax(T[1].y, T[2].y)) < mn.y || fmin(T[0].y, fmin(T[1].y, T[2].y)) > mx.y ||
                fmax(T[0].z, fmax(T[1].z, T[2].z)) < mn.z || fmin(T[0].z, fmin(T[1].z, T[2].z)) > mx.z)
                continue;
            if (dlen(dcross(dsub(T[1], T[0]), dsub(T[2], T[0]))) <= 0) continue;
            double t, depth;
            d3 n, p;
            if (ref_sweep_d(p0, p1, r, disp, T, best < 1.0 ? best : 1.0, &t, &depth, &n, &p) && t < best)
                best = t;
        }
    return best <= 1.0 ? best : -1.0;
}

/* ================================================================== levels */

bool bench_level_build(bench_level_t *lv, void *buf, size_t buf_size, float cell_size, uint32_t flags)
{
    if (lv->geo.overflow) return false;
    coll_mesh_build_opts_t o = {cell_size, flags};
    if (coll_mesh_build_size(lv->geo.nv, lv->geo.nt, &o) > buf_size) return false;
    if (coll_mesh_build(buf, buf_size, lv->geo.v, lv->geo.nv, lv->geo.idx, lv->geo.nt, &o, &lv->mesh) != COLL_OK)
        return false;
    coll_transform_t id = COLL_TRANSFORM_IDENTITY;
    memset(&lv->inst, 0, sizeof(lv->inst));
    lv->inst.mesh = lv->mesh;
    lv->inst.xf = id;
    lv->inst.write_mask = 0x01;
    lv->inst.id = 1;
    coll_scene_init(&lv->scene);
    if (coll_scene_add_mesh(&lv->scene, &lv->inst) != COLL_OK) return false;
    lv->part.geo = &lv->geo;
    lv->part.xf = &lv->inst.xf;
    return true;
}

void bench_body_sweep_capsule(const char_body_t *b, d3 *p0, d3 *p1, double *r)
{
    const char_body_settings_t *s = char_body_get_settings(b);
    fm_vec3_t f = char_body_foot_pos(b);
    d3 up = dof(s->up), foot = dof(f);
    double lo = (double)s->step_height + s->radius, hi = (double)s->height - s->radius;
    if (hi < lo) hi = lo;
    *p0 = dadd(foot, dmul(up, lo));
    *p1 = dadd(foot, dmul(up, hi));
    *r = s->radius;
}

/* ================================================================ scenarios */

/* Scratch layout inside the caller's buffer: vertex and index arrays, then the mesh. */
#define SCN_MAXV 24000u
#define SCN_MAXT 24000u

typedef struct {
    bench_level_t lv;
    void *mesh_buf;
    size_t mesh_size;
    char_body_t body;
    fm_vec3_t pos;
    double pen;         /* max penetration seen */
    bool always_floor;  /* on floor every frame since tracking began */
    bool finite;
} scn_t;

static bool scn_begin(scn_t *s, void *buf, size_t buf_size)
{
    memset(s, 0, sizeof(*s));
    size_t geo_bytes = SCN_MAXV * 12u + SCN_MAXT * 12u;
    if (buf_size < geo_bytes + 4096) return false;
    uint8_t *p = (uint8_t *)buf;
    bench_geo_init(&s->lv.geo, (float *)p, SCN_MAXV, (uint32_t *)(p + SCN_MAXV * 12u), SCN_MAXT);
    s->mesh_buf = p + ((geo_bytes + 7u) & ~(size_t)7u);
    s->mesh_size = buf_size - ((geo_bytes + 7u) & ~(size_t)7u);
    s->finite = true;
    return true;
}

static bool scn_build(scn_t *s)
{
    return bench_level_build(&s->lv, s->mesh_buf, s->mesh_size, 0.0f, 0);
}

static void scn_body(scn_t *s, fm_vec3_t foot, float r, float h, float step, float snap)
{
    s->pos = foot;
    char_body_init(&s->body, &s->pos);
    char_body_settings_t st = CHAR_BODY_SETTINGS_DEFAULT;
    st.radius = r; st.height = h; st.step_height = step; st.floor_snap_distance = snap;
    st.center_offset = v3(0, h * 0.5, 0);
    char_body_configure(&s->body, &st);
    char_body_teleport(&s->body, foot, true);
    s->always_floor = true;
}

static double body_pen(scn_t *s)
{
    d3 p0, p1;
    double r;
    bench_body_sweep_capsule(&s->body, &p0, &p1, &r);
    return bench_ref_penetration(&s->lv.part, 1, p0, p1, r);
}

static void scn_step(scn_t *s, fm_vec3_t in, float dt)
{
    s->body.input_velocity = in;
    char_body_move_and_slide_in(&s->body, &s->lv.scene, dt);
    double p = body_pen(s);
    if (p > s->pen) s->pen = p;
    if (!char_body_is_on_floor(&s->body)) s->always_floor = false;
    if (!isfinite(s->pos.x) || !isfinite(s->pos.y) || !isfinite(s->pos.z)) s->finite = false;
}

static bench_result_t res(const char *name, const char *what, const char *unit, double limit)
{
    bench_result_t r;
    memset(&r, 0, sizeof(r));
    r.name = name; r.what = what; r.unit = unit; r.limit = limit; r.pass = true;
    return r;
}

static void fail(bench_result_t *r, const char *why)
{
    if (r->pass) snprintf(r->note, sizeof(r->note), "%s", why);
    r->pass = false;
}

/* Common checks: finite state and a penetration bound. */
static void common_checks(bench_result_t *r, const scn_t *s, double pen_limit)
{
    r->pen = s->pen;
    if (!s->finite) fail(r, "non-finite position");
    if (s->pen > pen_limit) {
        char b[64];
        snprintf(b, sizeof(b), "penetration %.4g m > %.3g", s->pen, pen_limit);
        fail(r, b);
    }
}

static double hdist(fm_vec3_t a, double x, double z)
{
    return sqrt((a.x - x) * (a.x - x) + (a.z - z) * (a.z - z));
}

static double deg2rad(double d) { return d * 3.14159265358979323846 / 180.0; }

/* ---- V-corner crease: walls meeting at angle deg, walking into it slightly off-axis. */
static bench_result_t scn_vcorner(int deg, const char *name, void *buf, size_t n)
{
    bench_result_t r = res(name, "final distance from the crease rest point; jitter over the last 1 s",
                           "m", 0.05);
    scn_t s;
    if (!scn_begin(&s, buf, n)) { fail(&r, "scratch"); return r; }
    double h = deg2rad(deg) * 0.5;
    bench_geo_grid(&s.lv.geo, -20, -20, 20, 20, 0, 4, 4);
    bench_geo_wall(&s.lv.geo, 0, 0, 15 * sin(h), 15 * cos(h), -1, 4);
    bench_geo_wall(&s.lv.geo, 0, 0, -15 * sin(h), 15 * cos(h), -1, 4);
    if (!scn_build(&s)) { fail(&r, "build"); return r; }
    double zrest = 0.5 / sin(h);
    scn_body(&s, v3(0, 0, zrest + 4.0), 0.5f, 2.0f, 0.25f, 0.30f);
    fm_vec3_t in = v3(5 * sin(deg2rad(10)), 0, -5 * cos(deg2rad(10)));
    const float dt = 1.0f / 30.0f;
    double jitter = 0;
    for (int f = 0; f < 150; f++) {
        fm_vec3_t before = s.pos;
        scn_step(&s, in, dt);
        if (f >= 120) {
            double d = fm_vec3_distance(&before, &s.pos);
            if (d > jitter) jitter = d;
        }
    }
    common_checks(&r, &s, 1e-3);
    r.err = hdist(s.pos, 0, zrest);
    if (r.err > r.limit) fail(&r, "did not settle in the crease");
    if (jitter > 1e-3) { char b[64]; snprintf(b, sizeof(b), "jitter %.3g m/frame", jitter); fail(&r, b); }
    if (!char_body_is_on_floor(&s.body)) fail(&r, "left the floor");
    return r;
}

/* ---- grazing slides over coplanar seams: floor, or along a tessellated wall */
static bench_result_t scn_seams(bool wall, void *buf, size_t n)
{
    bench_result_t r = res(wall ? "seams_wall" : "seams_floor",
                           wall ? "worst speed loss along a tessellated wall (fraction); bump"
                                : "worst vertical bump (m) walking across a tessellated floor",
                           wall ? "frac" : "m", wall ? 0.01 : 1e-3);
    scn_t s;
    if (!scn_begin(&s, buf, n)) { fail(&r, "scratch"); return r; }
    bench_geo_grid(&s.lv.geo, -10, -10, 40, 40, 0, 100, 100);   /* 0.5 m cells, 20k tris */
    if (wall) {
        /* wall plane x = 3, tessellated 0.5 m x 0.5 m, both diagonals alternating */
        for (int j = 0; j < 8; j++)
            for (int i = 0; i < 80; i++) {
                double z0 = -10 + 0.5 * i, y0 = -0.5 + 0.5 * j;
                uint32_t a = bench_geo_vert(&s.lv.geo, 3, y0, z0), b = bench_geo_vert(&s.lv.geo, 3, y0, z0 + 0.5);
                uint32_t c = bench_geo_vert(&s.lv.geo, 3, y0 + 0.5, z0 + 0.5), d = bench_geo_vert(&s.lv.geo, 3, y0 + 0.5, z0);
                if ((i + j) & 1) { bench_geo_tri(&s.lv.geo, a, b, c); bench_geo_tri(&s.lv.geo, a, c, d); }
                else { bench_geo_tri(&s.lv.geo, a, b, d); bench_geo_tri(&s.lv.geo, b, c, d); }
            }
    }
    if (!scn_build(&s)) { fail(&r, "build"); return r; }
    const float dt = 1.0f / 30.0f;
    double bump = 0, loss = 0;
    if (!wall) {
        scn_body(&s, v3(0.13, 0, 0.07), 0.5f, 2.0f, 0.25f, 0.30f);
        fm_vec3_t in = v3(6.0 * 0.9376, 0, 6.0 * 0.3477);          /* ~20 deg to the seams */
        for (int f = 0; f < 90; f++) {
            fm_vec3_t before = s.pos;
            scn_step(&s, in, dt);
            if (fabs(s.pos.y) > bump) bump = fabs(s.pos.y);
            if (f > 0) {
                double sp = hdist(s.pos, before.x, before.z) / dt;
                if (1.0 - sp / 6.0 > loss) loss = 1.0 - sp / 6.0;
            }
        }
        r.err = bump;
        if (loss > 0.01) { char b[64]; snprintf(b, sizeof(b), "speed loss %.3g", loss); fail(&r, b); }
    } else {
        /* start touching-distance 2 cm off the wall, push into it at 30 deg */
        scn_body(&s, v3(3 - 0.52, 0, -8), 0.5f, 2.0f, 0.25f, 0.30f);
        fm_vec3_t in = v3(2.5, 0, 5.0);
        for (int f = 0; f < 90; f++) {
            fm_vec3_t before = s.pos;
            scn_step(&s, in, dt);
            if (fabs(s.pos.y) > bump) bump = fabs(s.pos.y);
            if (f > 2) {
                double sp = (s.pos.z - before.z) / dt;
                if (1.0 - sp / 5.0 > loss) loss = 1.0 - sp / 5.0;
            }
        }
        r.err = loss;
        if (bump > 1e-3) { char b[64]; snprintf(b, sizeof(b), "bump %.3g m", bump); fail(&r, b); }
    }
    common_checks(&r, &s, 1e-3);
    if (r.err > r.limit) fail(&r, wall ? "speed lost along the wall" : "bump over a seam");
    if (!s.always_floor) fail(&r, "left the floor");
    return r;
}

/* ---- 1 cm thin wall at 55 m/s, or a 1 cm floor slab hit falling at 55 m/s */
static bench_result_t scn_thin(bool fall, void *buf, size_t n)
{
    bench_result_t r = res(fall ? "thin_floor_fall55" : "thin_wall_55",
                           fall ? "how far the foot ends below the slab top (m)"
                                : "how far the capsule front ends past the wall's near face (m)",
                           "m", 1e-3);
    scn_t s;
    if (!scn_begin(&s, buf, n)) { fail(&r, "scratch"); return r; }
    const float dt = 1.0f / 30.0f;
    /* four start phases, a quarter of a frame's travel apart: a method that tests only
     * some points along the motion tunnels in at least one of them */
    if (!fall) {
        bench_geo_grid(&s.lv.geo, -20, -20, 120, 20, 0, 2, 2);
        bench_geo_box(&s.lv.geo, v3(10.0, -0.5, -10), v3(10.01, 4, 10));
        if (!scn_build(&s)) { fail(&r, "build"); return r; }
        double worst = 0;
        for (int ph = 0; ph < 4; ph++) {
            scn_body(&s, v3(55.0 / 30.0 * 0.25 * ph, 0, 0.0), 0.5f, 2.0f, 0.25f, 0.30f);
            for (int f = 0; f < 30; f++) {
                scn_step(&s, v3(55, 0, 0), dt);
                double past = s.pos.x + 0.5 - 10.0;
                if (past > worst) worst = past;
            }
            if (s.pos.x > 10.005) fail(&r, "tunnelled through the wall");
        }
        r.err = worst;
    } else {
        bench_geo_box(&s.lv.geo, v3(-10, -0.01, -10), v3(10, 0, 10));
        if (!scn_build(&s)) { fail(&r, "build"); return r; }
        double worst = 0;
        for (int ph = 0; ph < 4; ph++) {
            scn_body(&s, v3(0.21, 60 + 55.0 / 30.0 * 0.25 * ph, 0.13), 0.5f, 2.0f, 0.25f, 0.30f);
            char_body_set_velocity(&s.body, v3(0, -55, 0));
            for (int f = 0; f < 60; f++) scn_step(&s, v3(0, 0, 0), dt);
            if (-s.pos.y > worst) worst = -s.pos.y;
            if (s.pos.y < -0.005) fail(&r, "fell through the slab");
            if (!char_body_is_on_floor(&s.body)) fail(&r, "not on the floor after landing");
        }
        r.err = worst;
    }
    common_checks(&r, &s, 1e-3);
    if (r.err > r.limit && r.pass) fail(&r, "overshoot");
    return r;
}

/* ---- tiny (0.02) and huge (10) capsules walking into a wall */
static bench_result_t scn_size(bool huge, void *buf, size_t n)
{
    float rad = huge ? 10.0f : 0.02f;
    bench_result_t r = res(huge ? "huge_r10" : "tiny_r0.02",
                           "distance of the rest point from wall - r (m); limit 2 % of r + 1.5 mm of skin",
                           "m", 0.02 * rad + 1.5e-3);
    scn_t s;
    if (!scn_begin(&s, buf, n)) { fail(&r, "scratch"); return r; }
    double wall_x = huge ? 40.0 : 0.5;
    bench_geo_grid(&s.lv.geo, -wall_x * 3, -wall_x * 3, wall_x * 3, wall_x * 3, 0, 6, 6);
    bench_geo_wall(&s.lv.geo, wall_x, -wall_x * 2, wall_x, wall_x * 2, -1, huge ? 60 : 1);
    if (!scn_build(&s)) { fail(&r, "build"); return r; }
    if (huge) scn_body(&s, v3(0, 0, 0.3), 10.0f, 40.0f, 0.25f, 0.30f);
    else      scn_body(&s, v3(0, 0, 0.003), 0.02f, 0.08f, 0.01f, 0.02f);
    float speed = huge ? 12.0f : 0.3f;
    const float dt = 1.0f / 30.0f;
    for (int f = 0; f < 120; f++) scn_step(&s, v3(speed, 0, 0), dt);
    r.err = fabs(s.pos.x - (wall_x - rad));
    common_checks(&r, &s, 0.01 * rad);
    if (r.err > r.limit) fail(&r, "rest point off");
    if (!s.always_floor) fail(&r, "left the floor");
    return r;
}

/* ---- the test course: floor, 5 stairs, a landing and a wall. Returns final foot. */
static bool course_build(scn_t *s, double ox, double oz)
{
    bench_geo_grid(&s->lv.geo, -5, -5, 30, 5, 0, 14, 4);
    for (int k = 0; k < 5; k++) {   /* stairs: rise 0.2, run 0.4, starting x = 4 */
        double x0 = 4 + 0.4 * k;
        bench_geo_box(&s->lv.geo, v3(x0, 0, -3), v3(30, 0.2 * (k + 1), 3));
    }
    bench_geo_wall(&s->lv.geo, 12, -5, 12, 5, -1, 5);
    bench_geo_offset(&s->lv.geo, ox, 0, oz);
    return scn_build(s);
}

static fm_vec3_t course_run(scn_t *s, double ox, double oz, float dt, float total, bool *ok)
{
    scn_body(s, v3(ox, 0, oz + 0.11), 0.5f, 2.0f, 0.25f, 0.30f);
    int frames = (int)(total / dt + 0.5f);
    for (int f = 0; f < frames; f++) scn_step(s, v3(4, 0, 0), dt);
    *ok = true;
    fm_vec3_t p = s->pos;
    p.x = (float)(p.x - ox);
    p.z = (float)(p.z - oz);
    return p;
}

/* expected rest: on the top step (y = 1.0), against the wall at x = 12 - r */
static double course_err(fm_vec3_t p)
{
    return sqrt((p.x - 11.5) * (p.x - 11.5) + (p.y - 1.0) * (p.y - 1.0) + (p.z - 0.11) * (p.z - 0.11));
}

static bench_result_t scn_far(void *buf, size_t n)
{
    bench_result_t r = res("far_5km", "stairs + wall course 5 km from the origin: final position error (m)",
                           "m", 0.01);
    scn_t s;
    if (!scn_begin(&s, buf, n)) { fail(&r, "scratch"); return r; }
    if (!course_build(&s, 5000, 5000)) { fail(&r, "build"); return r; }
    bool ok;
    fm_vec3_t p = course_run(&s, 5000, 5000, 1.0f / 30.0f, 8.0f, &ok);
    r.err = course_err(p);
    common_checks(&r, &s, 2e-3);
    if (r.err > r.limit) fail(&r, "final position off (stairs or wall)");
    return r;
}

static bench_result_t scn_dt(int hz, const char *name, void *buf, size_t n)
{
    bench_result_t r = res(name, "stairs + wall course: final position error (m)", "m", 0.01);
    scn_t s;
    if (!scn_begin(&s, buf, n)) { fail(&r, "scratch"); return r; }
    if (!course_build(&s, 0, 0)) { fail(&r, "build"); return r; }
    bool ok;
    fm_vec3_t p = course_run(&s, 0, 0, 1.0f / (float)hz, 8.0f, &ok);
    r.err = course_err(p);
    common_checks(&r, &s, 1e-3);
    if (r.err > r.limit) fail(&r, "final position off (stairs or wall)");
    return r;
}

/* ---- sliver and near-degenerate triangles tiling a floor */
static bench_result_t scn_sliver(void *buf, size_t n)
{
    bench_result_t r = res("sliver_tris", "worst vertical bump (m) over 1e-5 m slivers and long needles", "m", 1e-3);
    scn_t s;
    if (!scn_begin(&s, buf, n)) { fail(&r, "scratch"); return r; }
    bench_geo_t *g = &s.lv.geo;
    /* 1 m quads, each as abm, mbc, amc (width 1e-5 m), acd */
    for (int j = -4; j < 4; j++)
        for (int i = -4; i < 24; i++) {
            uint32_t a = bench_geo_vert(g, i, 0, j), b = bench_geo_vert(g, i + 1, 0, j);
            uint32_t c = bench_geo_vert(g, i + 1, 0, j + 1), d = bench_geo_vert(g, i, 0, j + 1);
            uint32_t m = bench_geo_vert(g, i + 0.5 + 0.7e-5, 0, j + 0.5 - 0.7e-5);
            bench_geo_tri(g, a, b, m); bench_geo_tri(g, m, b, c);
            bench_geo_tri(g, a, m, c); bench_geo_tri(g, a, c, d);
        }
    /* needles: a fan from (24,0,-4) to 200 points along z = 4 (aspect ~ 300) */
    uint32_t apex = bench_geo_vert(g, 24, 0, -4), prev = bench_geo_vert(g, 24, 0, 4);
    for (int k = 1; k <= 200; k++) {
        uint32_t q = bench_geo_vert(g, 24 + 0.1 * k, 0, 4);
        bench_geo_tri(g, apex, prev, q);
        prev = q;
    }
    bench_geo_tri(g, apex, prev, bench_geo_vert(g, 44, 0, -4));
    if (!scn_build(&s)) { fail(&r, "build"); return r; }
    scn_body(&s, v3(-3.3, 0, -0.2), 0.5f, 2.0f, 0.25f, 0.30f);
    const float dt = 1.0f / 30.0f;
    double bump = 0;
    for (int f = 0; f < 240; f++) {
        scn_step(&s, v3(5.0, 0, 0.3), dt);
        if (fabs(s.pos.y) > bump) bump = fabs(s.pos.y);
    }
    r.err = bump;
    common_checks(&r, &s, 1e-3);
    if (r.err > r.limit) fail(&r, "bump / fell");
    if (!s.always_floor) fail(&r, "left the floor");
    if (s.pos.x < 35) fail(&r, "did not get across");
    return r;
}

/* ---- exactly touching starts: against a wall (slide along, then leave), on a floor */
static bench_result_t scn_touch(bool wall, void *buf, size_t n)
{
    bench_result_t r = res(wall ? "touching_wall" : "touching_floor",
                           wall ? "speed loss sliding from an exact wall contact (fraction)"
                                : "drift (m) standing still from an exact floor contact",
                           wall ? "frac" : "m", wall ? 0.01 : 1e-4);
    scn_t s;
    if (!scn_begin(&s, buf, n)) { fail(&r, "scratch"); return r; }
    bench_geo_grid(&s.lv.geo, -10, -10, 10, 30, 0, 2, 4);
    bench_geo_wall(&s.lv.geo, 2, -10, 2, 30, -1, 4);
    if (!scn_build(&s)) { fail(&r, "build"); return r; }
    const float dt = 1.0f / 30.0f;
    if (wall) {
        scn_body(&s, v3(1.5, 0, 0), 0.5f, 2.0f, 0.25f, 0.30f);
        double z0 = s.pos.z;
        for (int f = 0; f < 30; f++) scn_step(&s, v3(1, 0, 5), dt);
        double sp = (s.pos.z - z0) / (30 * dt);
        r.err = 1.0 - sp / 5.0;
        if (r.err < 0) r.err = 0;
        double x0 = s.pos.x;
        for (int f = 0; f < 10; f++) scn_step(&s, v3(-3, 0, 0), dt);
        if (x0 - s.pos.x < 0.9) fail(&r, "could not move away from the wall");
    } else {
        scn_body(&s, v3(0.3, 0, 0.3), 0.5f, 2.0f, 0.25f, 0.30f);
        for (int f = 0; f < 60; f++) scn_step(&s, v3(0, 0, 0), dt);
        r.err = fabs(s.pos.y) + hdist(s.pos, 0.3, 0.3);
    }
    common_checks(&r, &s, 1e-3);
    if (r.err > r.limit) fail(&r, wall ? "lost speed along the wall" : "drifted");
    if (!s.always_floor) fail(&r, "left the floor");
    return r;
}

/* ---- rotating platform at 360 deg/s: a 4 m disc, body standing 2 m off the axis */
static bench_result_t scn_platform(void *buf, size_t n)
{
    bench_result_t r = res("platform_360", "distance from where the platform point carried it (m)", "m", 0.05);
    scn_t s;
    if (!scn_begin(&s, buf, n)) { fail(&r, "scratch"); return r; }
    bench_geo_t *g = &s.lv.geo;
    uint32_t c = bench_geo_vert(g, 0, 0, 0), first = 0, prev = 0;
    for (int k = 0; k <= 32; k++) {
        double a = 2 * 3.14159265358979323846 * k / 32;
        uint32_t q = bench_geo_vert(g, 4 * cos(a), 0, 4 * sin(a));
        if (k == 0) first = q; else bench_geo_tri(g, c, q, prev);
        prev = q;
    }
    (void)first;
    if (!scn_build(&s)) { fail(&r, "build"); return r; }
    scn_body(&s, v3(2, 0, 0), 0.5f, 2.0f, 0.25f, 0.30f);
    const float dt = 1.0f / 30.0f;
    const int frames = 60;
    fm_vec3_t axis = v3(0, 1, 0);
    scn_step(&s, v3(0, 0, 0), dt);   /* stand on it first: carrying starts once grounded */
    for (int f = 1; f <= frames; f++) {
        fm_quat_from_axis_angle(&s.lv.inst.xf.rot, &axis, (float)(2 * 3.14159265358979323846 * f * dt));
        scn_step(&s, v3(0, 0, 0), dt);
    }
    fm_vec3_t local = v3(2, 0, 0), expect;
    fm_quat_rotate_vec3(&expect, &s.lv.inst.xf.rot, &local);
    r.err = fm_vec3_distance(&expect, &s.pos);
    common_checks(&r, &s, 2e-3);
    if (r.err > r.limit) fail(&r, "not carried with the platform");
    if (!s.always_floor) fail(&r, "lost the platform");
    return r;
}

/* ---- table */
typedef enum { K_VC, K_SEAMF, K_SEAMW, K_THINW, K_THINF, K_TINY, K_HUGE, K_FAR, K_DT, K_SLIVER,
               K_TOUCHW, K_TOUCHF, K_PLAT } kind_t;
static const struct { kind_t k; int p; const char *name; } g_scn[] = {
    {K_VC, 15, "vcorner_15"}, {K_VC, 30, "vcorner_30"}, {K_VC, 60, "vcorner_60"},
    {K_VC, 90, "vcorner_90"}, {K_VC, 120, "vcorner_120"},
    {K_SEAMF, 0, "seams_floor"}, {K_SEAMW, 0, "seams_wall"},
    {K_THINW, 0, "thin_wall_55"}, {K_THINF, 0, "thin_floor_fall55"},
    {K_TINY, 0, "tiny_r0.02"}, {K_HUGE, 0, "huge_r10"}, {K_FAR, 0, "far_5km"},
    {K_DT, 240, "dt_1/240"}, {K_DT, 60, "dt_1/60"}, {K_DT, 30, "dt_1/30"}, {K_DT, 15, "dt_1/15"},
    {K_DT, 5, "dt_1/5"},
    {K_SLIVER, 0, "sliver_tris"}, {K_TOUCHW, 0, "touching_wall"}, {K_TOUCHF, 0, "touching_floor"},
    {K_PLAT, 0, "platform_360"},
};

int bench_scn_count(void) { return (int)(sizeof(g_scn) / sizeof(g_scn[0])); }

bench_result_t bench_scn_run(int i, bool reduced, void *buf, size_t n)
{
    (void)reduced;
    switch (g_scn[i].k) {
    case K_VC: return scn_vcorner(g_scn[i].p, g_scn[i].name, buf, n);
    case K_SEAMF: return scn_seams(false, buf, n);
    case K_SEAMW: return scn_seams(true, buf, n);
    case K_THINW: return scn_thin(false, buf, n);
    case K_THINF: return scn_thin(true, buf, n);
    case K_TINY: return scn_size(false, buf, n);
    case K_HUGE: return scn_size(true, buf, n);
    case K_FAR: return scn_far(buf, n);
    case K_DT: return scn_dt(g_scn[i].p, g_scn[i].name, buf, n);
    case K_SLIVER: return scn_sliver(buf, n);
    case K_TOUCHW: return scn_touch(true, buf, n);
    case K_TOUCHF: return scn_touch(false, buf, n);
    case K_PLAT: return scn_platform(buf, n);
    }
    bench_result_t r = res("?", "?", "", 0);
    fail(&r, "unknown scenario");
    return r;
}
