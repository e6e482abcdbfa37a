/* Benchmark sweep methods: libccd bisection and discrete sub-stepping. See bench_methods.h. */
#include "bench_methods.h"

#include <ccd/ccd.h>
#include <ccd/vec3.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bench_scn.h"

/* ---------------------------------------------------------------- libccd */

typedef struct {
    fm_vec3_t a, b;   /* segment */
    float r;
    fm_vec3_t d;      /* displacement */
    float t0, t1;     /* time interval swept */
} ccd_capsule_t;

typedef struct {
    fm_vec3_t v[3];
} ccd_tri_t;

static void capsule_support(const void *obj, const ccd_vec3_t *dir, ccd_vec3_t *out)
{
    const ccd_capsule_t *c = (const ccd_capsule_t *)obj;
    float dx = dir->v[0], dy = dir->v[1], dz = dir->v[2];
    float da = dx * c->a.x + dy * c->a.y + dz * c->a.z;
    float db = dx * c->b.x + dy * c->b.y + dz * c->b.z;
    const fm_vec3_t *p = da >= db ? &c->a : &c->b;
    float l = sqrtf(dx * dx + dy * dy + dz * dz);
    float s = l > 0.0f ? c->r / l : 0.0f;
    float dd = dx * c->d.x + dy * c->d.y + dz * c->d.z;
    float t = dd > 0.0f ? c->t1 : c->t0;
    out->v[0] = p->x + dx * s + c->d.x * t;
    out->v[1] = p->y + dy * s + c->d.y * t;
    out->v[2] = p->z + dz * s + c->d.z * t;
}

static void capsule_center(const void *obj, ccd_vec3_t *out)
{
    const ccd_capsule_t *c = (const ccd_capsule_t *)obj;
    float t = 0.5f * (c->t0 + c->t1);
    out->v[0] = 0.5f * (c->a.x + c->b.x) + c->d.x * t;
    out->v[1] = 0.5f * (c->a.y + c->b.y) + c->d.y * t;
    out->v[2] = 0.5f * (c->a.z + c->b.z) + c->d.z * t;
}

static void tri_support(const void *obj, const ccd_vec3_t *dir, ccd_vec3_t *out)
{
    const ccd_tri_t *t = (const ccd_tri_t *)obj;
    int best = 0;
    float bd = -INFINITY;
    for (int i = 0; i < 3; i++) {
        float d = dir->v[0] * t->v[i].x + dir->v[1] * t->v[i].y + dir->v[2] * t->v[i].z;
        if (d > bd) { bd = d; best = i; }
    }
    out->v[0] = t->v[best].x; out->v[1] = t->v[best].y; out->v[2] = t->v[best].z;
}

static void tri_center(const void *obj, ccd_vec3_t *out)
{
    const ccd_tri_t *t = (const ccd_tri_t *)obj;
    out->v[0] = (t->v[0].x + t->v[1].x + t->v[2].x) * (1.0f / 3.0f);
    out->v[1] = (t->v[0].y + t->v[1].y + t->v[2].y) * (1.0f / 3.0f);
    out->v[2] = (t->v[0].z + t->v[1].z + t->v[2].z) * (1.0f / 3.0f);
}

static int ccd_hits(const bench_ccd_ctx_t *cx, const ccd_t *ccd, ccd_capsule_t *cap, const ccd_tri_t *tri,
                    float t0, float t1)
{
    cap->t0 = t0; cap->t1 = t1;
    return cx->use_mpr ? ccdMPRIntersect(cap, tri, ccd) : ccdGJKIntersect(cap, tri, ccd);
}

/* Normal and point at a (slightly) overlapping pose from MPR penetration; falls back to the
 * triangle's face normal towards the capsule. */
static void ccd_contact(const ccd_t *ccd, ccd_capsule_t *cap, const ccd_tri_t *tri, float t,
                        coll_prim_hit_t *hit, float *depth_out)
{
    cap->t0 = cap->t1 = t;
    ccd_real_t depth = 0;
    ccd_vec3_t dir, pos;
    fm_vec3_t e1, e2, n;
    fm_vec3_sub(&e1, &tri->v[1], &tri->v[0]);
    fm_vec3_sub(&e2, &tri->v[2], &tri->v[0]);
    fm_vec3_cross(&n, &e1, &e2);
    fm_vec3_norm(&n, &n);
    if (ccdMPRPenetration(cap, tri, ccd, &depth, &dir, &pos) == 0 && isfinite(dir.v[0])) {
        /* dir points out of the Minkowski difference capsule - triangle: the capsule
         * leaves by moving along -dir. */
        hit->normal.x = -dir.v[0]; hit->normal.y = -dir.v[1]; hit->normal.z = -dir.v[2];
        hit->point.x = pos.v[0]; hit->point.y = pos.v[1]; hit->point.z = pos.v[2];
    } else {
        ccd_vec3_t c;
        capsule_center(cap, &c);
        float s = (c.v[0] - tri->v[0].x) * n.x + (c.v[1] - tri->v[0].y) * n.y + (c.v[2] - tri->v[0].z) * n.z;
        if (s < 0.0f) fm_vec3_negate(&n, &n);
        hit->normal = n;
        tri_center(tri, &c);
        hit->point.x = c.v[0]; hit->point.y = c.v[1]; hit->point.z = c.v[2];
    }
    if (depth_out) *depth_out = (float)depth;
}

bool bench_ccd_tri_sweep(void *ctx, const fm_vec3_t seg[2], float r, const fm_vec3_t *disp,
                         const fm_vec3_t tri[3], float t_max, coll_prim_hit_t *hit)
{
    const bench_ccd_ctx_t *cx = (const bench_ccd_ctx_t *)ctx;
    ccd_t ccd;
    CCD_INIT(&ccd);
    ccd.support1 = capsule_support;
    ccd.support2 = tri_support;
    ccd.center1 = capsule_center;
    ccd.center2 = tri_center;
    ccd.max_iterations = cx->ccd_max_iter;
    ccd.mpr_tolerance = 1e-5f;
    ccd_capsule_t cap = {seg[0], seg[1], r, *disp, 0.0f, 0.0f};
    ccd_tri_t t3 = {{tri[0], tri[1], tri[2]}};

    if (!ccd_hits(cx, &ccd, &cap, &t3, 0.0f, t_max)) return false;
    if (ccd_hits(cx, &ccd, &cap, &t3, 0.0f, 0.0f)) {
        float depth;
        ccd_contact(&ccd, &cap, &t3, 0.0f, hit, &depth);
        hit->t = 0.0f;
        hit->depth = depth > 0.0f ? depth : 0.0f;
        if (!(hit->depth > 0.0f)) {
            /* touching at t = 0: only a hit when the motion goes into the triangle */
            if (fm_vec3_dot(&hit->normal, disp) >= 0.0f) return false;
        }
        return true;
    }
    float len = fm_vec3_len(disp);
    float lo = 0.0f, hi = t_max;
    for (int i = 0; i < cx->iters && (hi - lo) * len > cx->tol; i++) {
        float mid = 0.5f * (lo + hi);
        if (ccd_hits(cx, &ccd, &cap, &t3, lo, mid)) hi = mid;
        else lo = mid;
    }
    ccd_contact(&ccd, &cap, &t3, hi, hit, NULL);
    if (fm_vec3_dot(&hit->normal, disp) >= 0.0f) return false; /* grazing, moving away */
    hit->t = lo;
    hit->depth = 0.0f;
    return true;
}

/* ------------------------------------------------------------- discrete */

bool bench_disc_tri_sweep(void *ctx, const fm_vec3_t seg[2], float r, const fm_vec3_t *disp,
                          const fm_vec3_t tri[3], float t_max, coll_prim_hit_t *hit)
{
    const bench_disc_ctx_t *cx = (const bench_disc_ctx_t *)ctx;
    int n = cx->n < 1 ? 1 : cx->n;
    float prev = 0.0f;
    for (int i = 0; i <= n; i++) {
        float t = (float)i / (float)n;
        if (i > 0 && prev >= t_max) break;       /* could not beat the best hit so far */
        fm_vec3_t s[2], o;
        fm_vec3_scale(&o, disp, t);
        fm_vec3_add(&s[0], &seg[0], &o);
        fm_vec3_add(&s[1], &seg[1], &o);
        coll_prim_hit_t h;
        if (coll_capsule_triangle_overlap(s, r, tri, &h)) {
            if (i > 0 && fm_vec3_dot(&h.normal, disp) >= 0.0f) { prev = t; continue; }
            *hit = h;
            hit->t = i == 0 ? 0.0f : prev;
            hit->depth = i == 0 ? h.depth : 0.0f;
            /* the contact point found at the overlapping step, carried back to t = prev */
            if (i > 0) { fm_vec3_scale(&o, disp, prev - t); fm_vec3_add(&hit->point, &h.point, &o); }
            return true;
        }
        prev = t;
    }
    return false;
}

/* ------------------------------------------------------------- by name */

static bench_ccd_ctx_t g_ccd;
static bench_disc_ctx_t g_disc;

bool bench_method_install(const char *spec)
{
    if (strcmp(spec, "exact") == 0) { coll_set_tri_sweep_method(NULL, NULL); return true; }
    if (strcmp(spec, "ref") == 0) { coll_set_tri_sweep_method(bench_ref_tri_sweep, NULL); return true; }
    if (strncmp(spec, "ccd-gjk:", 8) == 0 || strncmp(spec, "ccd-mpr:", 8) == 0) {
        g_ccd.use_mpr = spec[4] == 'm';
        g_ccd.iters = 16;
        g_ccd.tol = 1e-4f;
        g_ccd.ccd_max_iter = 100;
        const char *p = spec + 8;
        g_ccd.iters = atoi(p);
        p = strchr(p, ':');
        if (p) g_ccd.tol = strtof(p + 1, NULL);
        if (g_ccd.iters < 0) return false;
        coll_set_tri_sweep_method(bench_ccd_tri_sweep, &g_ccd);
        return true;
    }
    if (strncmp(spec, "disc:", 5) == 0) {
        g_disc.n = atoi(spec + 5);
        if (g_disc.n < 1) return false;
        coll_set_tri_sweep_method(bench_disc_tri_sweep, &g_disc);
        return true;
    }
    return false;
}
