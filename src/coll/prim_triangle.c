/**
 * @file prim_triangle.c
 * @brief Ray and capsule against one triangle: watertight ray test, exact capsule sweep
 *        (time of impact) and static overlap with minimum-translation push-out.
 *
 * The sweep works in configuration space: the capsule (segment S, radius r) moving by d
 * touches triangle T at the first t where dist(S + t d, T) = r, i.e. where the point t*d
 * enters K = T (+) -S (+) ball(r). K is convex; its boundary is covered by pieces that are
 * each a subset of K, so the earliest entry over all pieces is the exact entry into K:
 *  - the triangle's two offset faces, for the segment's endpoints (ray vs offset face),
 *  - the triangle edges' cylinders, for the segment's endpoints (ray vs cylinder side),
 *  - the capsule (S, r) for each triangle vertex moving by -d (ray vs capsule),
 *  - the offset parallelogram faces edge x S (edge-edge interior contacts).
 * Each piece's normal at the entry point is K's normal there (K is C1), so the contact
 * normal is exact too.
 *
 * Touch tolerance (COLL_PRIM_TOUCH_TOL): a capsule whose distance to the triangle is at
 * least r - tol is touching, not overlapping. A sweep only reports a hit when the motion
 * within [0, t_max] brings the capsule deeper than tol into the triangle; it then reports
 * the first time the distance reaches r (clamped at 0). So sliding exactly along a
 * surface, or touching and moving away, never blocks, while a real approach is blocked
 * at the exact touching time.
 */
#include "prim_util.h"

/* ---------------------------------------------------------------- elementary ray tests */

/* The elementary tests run a dozen times per exact sweep: the sweep takes them inline
 * (PRIM_INLINE *_in versions; on the console's o32 calls every by-value vector argument
 * went through the stack and the integer registers), the exported names wrap them. */
#if defined(__GNUC__)
#define PRIM_INLINE static inline __attribute__((always_inline))
#else
#define PRIM_INLINE static inline
#endif

/* Where the line m + d s (m: the origin relative to a centre point, or across an axis)
 * first reaches distance r: ROUND_INSIDE when it starts within r, ROUND_MISS when it never
 * gets there or only after s_max, else ROUND_ENTERS at *s. */
enum { ROUND_MISS, ROUND_INSIDE, ROUND_ENTERS };
PRIM_INLINE int round_entry(fm_vec3_t m, fm_vec3_t d, float r, float s_max, float *s)
{
    float cc = v3_dot(m, m) - r * r;
    if (cc <= 0.0f) return ROUND_INSIDE;
    float b = v3_dot(m, d);
    if (b >= 0.0f) return ROUND_MISS;
    /* The entry comes after cc / (-2b) (the root's denominator is below -2b): past s_max
     * with a margin far above the rounding of *s, so a miss either way (bit-identical). */
    if (cc > -2.002f * b * s_max) return ROUND_MISS;
    float a = v3_dot(d, d);
    /* b^2 - a*cc cancels badly for a far origin: use a*(r^2 - dmin^2), dmin from the
     * closest point of the line to the centre. */
    fm_vec3_t w = v3_madd(m, d, -b / a);
    float disc = a * (r * r - v3_dot(w, w));
    if (!(disc >= 0.0f)) return ROUND_MISS;
    *s = cc / (-b + sqrtf(disc)); /* smaller root without cancellation */
    return *s <= s_max ? ROUND_ENTERS : ROUND_MISS;
}

/* Outward normal at m + d s, or away from the motion when that point is the centre. */
PRIM_INLINE fm_vec3_t round_normal(fm_vec3_t m, fm_vec3_t d, float s)
{
    return v3_unit_or_against(v3_madd(m, d, s), d);
}

PRIM_INLINE bool ray_sphere_in(fm_vec3_t o, fm_vec3_t d, fm_vec3_t c, float r, float s_max, prim_ray_t *out)
{
    fm_vec3_t m = v3_sub(o, c);
    float s = 0.0f;
    int e = round_entry(m, d, r, s_max, &s);
    if (e == ROUND_MISS) return false;
    out->s = s;
    out->n = round_normal(m, d, s);
    return true;
}

PRIM_INLINE bool ray_cylinder_side_in(fm_vec3_t o, fm_vec3_t d, fm_vec3_t c0, fm_vec3_t c1, float r, float s_max,
                                      prim_ray_t *out)
{
    fm_vec3_t ax = v3_sub(c1, c0);
    float ss = v3_dot(ax, ax);
    if (!(ss > 1e-20f)) return false;
    fm_vec3_t m = v3_sub(o, c0);
    float md = v3_dot(m, ax), dd = v3_dot(d, ax);
    fm_vec3_t mp = v3_madd(m, ax, -md / ss);   /* components perpendicular to the axis */
    fm_vec3_t dp = v3_madd(d, ax, -dd / ss);
    float s = 0.0f;
    int e = round_entry(mp, dp, r, s_max, &s);
    if (e == ROUND_MISS) return false;
    float axial = md + s * dd;
    if (axial < 0.0f || axial > ss) return false; /* past an end: the end spheres cover it */
    out->s = s;
    out->n = round_normal(mp, dp, s);
    return true;
}

PRIM_INLINE bool ray_capsule_in(fm_vec3_t o, fm_vec3_t d, fm_vec3_t c0, fm_vec3_t c1, float r, float s_max,
                                prim_ray_t *out)
{
    prim_ray_t h = { 0.0f, { { 0.0f, 0.0f, 0.0f } } }; /* (set by every test that returns true) */
    bool any = false;
    if (ray_cylinder_side_in(o, d, c0, c1, r, s_max, &h)) { *out = h; s_max = h.s; any = true; }
    if (ray_sphere_in(o, d, c0, r, s_max, &h) && (!any || h.s < out->s)) { *out = h; s_max = h.s; any = true; }
    if (ray_sphere_in(o, d, c1, r, s_max, &h) && (!any || h.s < out->s)) { *out = h; any = true; }
    return any;
}

bool coll_prim_ray_sphere(fm_vec3_t o, fm_vec3_t d, fm_vec3_t c, float r, float s_max, prim_ray_t *out)
{
    return ray_sphere_in(o, d, c, r, s_max, out);
}

bool coll_prim_ray_cylinder_side(fm_vec3_t o, fm_vec3_t d, fm_vec3_t c0, fm_vec3_t c1, float r, float s_max,
                                 prim_ray_t *out)
{
    return ray_cylinder_side_in(o, d, c0, c1, r, s_max, out);
}

bool coll_prim_ray_capsule(fm_vec3_t o, fm_vec3_t d, fm_vec3_t c0, fm_vec3_t c1, float r, float s_max,
                           prim_ray_t *out)
{
    /* the same three tests as ray_capsule_in, through the out-of-line ones (code size) */
    prim_ray_t h = { 0.0f, { { 0.0f, 0.0f, 0.0f } } };
    bool any = false;
    if (coll_prim_ray_cylinder_side(o, d, c0, c1, r, s_max, &h)) { *out = h; s_max = h.s; any = true; }
    if (coll_prim_ray_sphere(o, d, c0, r, s_max, &h) && (!any || h.s < out->s)) { *out = h; s_max = h.s; any = true; }
    if (coll_prim_ray_sphere(o, d, c1, r, s_max, &h) && (!any || h.s < out->s)) { *out = h; any = true; }
    return any;
}

PRIM_INLINE float closest_seg_seg_in(fm_vec3_t p0, fm_vec3_t p1, fm_vec3_t q0, fm_vec3_t q1,
                                     float *u_out, float *v_out, fm_vec3_t *cp, fm_vec3_t *cq)
{
    const float eps = 1e-20f;
    fm_vec3_t d1 = v3_sub(p1, p0), d2 = v3_sub(q1, q0), w = v3_sub(p0, q0);
    float a = v3_dot(d1, d1), e = v3_dot(d2, d2), f = v3_dot(d2, w);
    float s, t;
    if (a <= eps && e <= eps) {
        s = 0.0f; t = 0.0f;
    } else if (a <= eps) {
        s = 0.0f; t = f_clamp01(f / e);
    } else {
        float c = v3_dot(d1, w);
        if (e <= eps) {
            t = 0.0f; s = f_clamp01(-c / a);
        } else {
            float b = v3_dot(d1, d2);
            float denom = v3_len2(v3_cross(d1, d2)); /* = a e - b^2 without cancellation */
            s = denom > 1e-12f * a * e ? f_clamp01((b * f - c * e) / denom) : 0.0f;
            t = (b * s + f) / e;
            if (t < 0.0f) { t = 0.0f; s = f_clamp01(-c / a); }
            else if (t > 1.0f) { t = 1.0f; s = f_clamp01((b - c) / a); }
        }
    }
    fm_vec3_t x = v3_madd(p0, d1, s), y = v3_madd(q0, d2, t);
    if (u_out) *u_out = s;
    if (v_out) *v_out = t;
    if (cp) *cp = x;
    if (cq) *cq = y;
    return v3_len2(v3_sub(x, y));
}

/* closest_seg_seg_in(p0, p1, q, q, ...)'s point of p0..p1 (the same expressions for a
 * point q: bit-identical), without the general case's code. */
PRIM_INLINE fm_vec3_t closest_on_seg(fm_vec3_t p0, fm_vec3_t p1, fm_vec3_t q)
{
    const float eps = 1e-20f;
    fm_vec3_t d1 = v3_sub(p1, p0), w = v3_sub(p0, q);
    float a = v3_dot(d1, d1);
    float s = a <= eps ? 0.0f : f_clamp01(-v3_dot(d1, w) / a);
    return v3_madd(p0, d1, s);
}

float coll_prim_closest_seg_seg(fm_vec3_t p0, fm_vec3_t p1, fm_vec3_t q0, fm_vec3_t q1,
                                float *u_out, float *v_out, fm_vec3_t *cp, fm_vec3_t *cq)
{
    return closest_seg_seg_in(p0, p1, q0, q1, u_out, v_out, cp, cq);
}

/* ---------------------------------------------------------------- triangle helpers */

/* a*b - c*d with both products error-free (Veltkamp split, no FMA needed): the cross
 * product of two nearly parallel edges (a flat sliver) would otherwise lose its direction. */
static float split_hi(float a)
{
    volatile float t = 4097.0f * a; /* volatile: keep the split exact under any contraction */
    return t - (t - a);
}

static float prod_err(float a, float b, float p)
{
    float ah = split_hi(a), al = a - ah, bh = split_hi(b), bl = b - bh;
    return ((ah * bh - p) + ah * bl + al * bh) + al * bl;
}

static float diff_of_products(float a, float b, float c, float d)
{
    float p1 = a * b, p2 = c * d;
    return (p1 - p2) + (prod_err(a, b, p1) - prod_err(c, d, p2));
}

static fm_vec3_t cross_accurate(fm_vec3_t a, fm_vec3_t b)
{
    return v3(diff_of_products(a.y, b.z, a.z, b.y), diff_of_products(a.z, b.x, a.x, b.z),
                   diff_of_products(a.x, b.y, a.y, b.x));
}

typedef struct {
    fm_vec3_t v[3];
    fm_vec3_t e[3];    /* v[i+1] - v[i] */
    fm_vec3_t nraw;    /* (v1 - v0) x (v2 - v0) */
    fm_vec3_t n;       /* unit normal when has_face */
    bool has_face;
    uint8_t apex;      /* tri_setup: the vertex the two shortest edges share (kept in a prep) */
} tri_t;

/* Vertices, edges and the raw normal of a triangle (tri_setup without the unit normal);
 * *apex: the vertex shared by the two shortest edges, *nn: |nraw|^2, *lmax: the longest
 * edge squared. */
/* The raw normal from the edges e[i] = v[i+1] - v[i]: the two shortest crossed (for a
 * needle that keeps the rounding error small); *apex: the vertex they share; *lmax: the
 * longest edge squared. */
PRIM_INLINE fm_vec3_t raw_normal(const fm_vec3_t e[3], int *apex, float *lmax)
{
    float l0 = v3_len2(e[0]), l1 = v3_len2(e[1]), l2 = v3_len2(e[2]);
    int ia, ib;
    if (l0 >= l1 && l0 >= l2)      { ia = 1; ib = 2; *apex = 2; }
    else if (l1 >= l0 && l1 >= l2) { ia = 2; ib = 0; *apex = 0; }
    else                           { ia = 0; ib = 1; *apex = 1; }
    fm_vec3_t nraw = v3_cross(e[ia], e[ib]);
    float nn = v3_len2(nraw);
    /* Flat sliver (the short edges nearly parallel): redo the products exactly. */
    if (nn < 1e-4f * v3_len2(e[ia]) * v3_len2(e[ib]))
        nraw = cross_accurate(e[ia], e[ib]);
    *lmax = f_max(l0, f_max(l1, l2));
    return nraw;
}

static inline void tri_setup_raw(tri_t *t, const fm_vec3_t tri[3], int *apex, float *nn_out, float *lmax)
{
    for (int i = 0; i < 3; i++) t->v[i] = tri[i];
    for (int i = 0; i < 3; i++) t->e[i] = v3_sub(t->v[(i + 1) % 3], t->v[i]);
    t->nraw = raw_normal(t->e, apex, lmax);
    *nn_out = v3_len2(t->nraw);
}

/* Whether a triangle with raw normal nraw (nn: |nraw|^2, lmax: its longest edge squared)
 * has a face (not a needle or a point), and its unit normal *n then (else zero): one rule
 * for tri_setup and the ray's prep. */
PRIM_INLINE bool face_normal(fm_vec3_t nraw, float nn, float lmax, fm_vec3_t *n)
{
    bool has_face = nn > 1e-14f * lmax * lmax && nn > 1e-30f && f_finite(nn);
    *n = has_face ? v3_scale(nraw, 1.0f / sqrtf(nn)) : v3(0.0f, 0.0f, 0.0f);
    return has_face;
}

static void tri_setup(tri_t *t, const fm_vec3_t tri[3])
{
    int apex;
    float nn, lmax;
    tri_setup_raw(t, tri, &apex, &nn, &lmax);
    t->apex = (uint8_t)apex;
    t->has_face = face_normal(t->nraw, nn, lmax, &t->n);
}

/* tri_setup through a triangle's prep (prim.h): made from it when it is ready, else made
 * and kept in it (p NULL: tri_setup). The same expressions either way: bit-identical. */
static inline void tri_setup_keep(tri_t *t, const fm_vec3_t tri[3], coll_tri_prep_t *p)
{
    if (!p) {
        tri_setup(t, tri);
        return;
    }
    if (p->ready) {
        for (int i = 0; i < 3; i++) t->v[i] = tri[i];
        for (int i = 0; i < 3; i++) t->e[i] = v3_sub(t->v[(i + 1) % 3], t->v[i]);
        t->nraw = p->nraw;
        t->n = p->n;
        t->has_face = p->has_face;
        return;
    }
    tri_setup(t, tri);
    p->nraw = t->nraw;
    p->n = t->n;
    p->has_face = t->has_face;
    p->apex = t->apex;
    p->ready = true;
}

/* a and b the same floats, bit for bit (-0 and 0 apart): the same input to any expression */
static inline bool v3_same_bits(fm_vec3_t a, fm_vec3_t b)
{
    union { float f; uint32_t u; } ax = { a.x }, ay = { a.y }, az = { a.z }, bx = { b.x }, by = { b.y }, bz = { b.z };
    return ((ax.u ^ bx.u) | (ay.u ^ by.u) | (az.u ^ bz.u)) == 0u;
}

/** Point q (on or near the plane) inside the closed triangle. */
static bool tri_contains(const tri_t *t, const fm_vec3_t *pq)
{
    const fm_vec3_t q = *pq;
    for (int i = 0; i < 3; i++)
        if (v3_dot(v3_cross(t->e[i], v3_sub(q, t->v[i])), t->nraw) < 0.0f) return false;
    return true;
}

/** Squared distance of segment a..b to the triangle with closest points. */
/* hab: the heights of a and b over the face (the expressions below), when the caller has
 * them already; NULL: computed here. */
static float seg_tri_closest_ex(const tri_t *t, const fm_vec3_t *pa, const fm_vec3_t *pb, const float *hab,
                                fm_vec3_t *ps, fm_vec3_t *pt, int *edge, float *eu, float *ev)
{
    const fm_vec3_t a = *pa, b = *pb;
    const bool point = a.x == b.x && a.y == b.y && a.z == b.z; /* a sphere's centre */
    float best = 3.0e38f;
    *edge = -1;
    if (t->has_face) {
        float ha = hab ? hab[0] : v3_dot(t->n, v3_sub(a, t->v[0]));
        float hb = hab ? hab[1] : v3_dot(t->n, v3_sub(b, t->v[0]));
        if ((ha <= 0.0f && hb >= 0.0f) || (ha >= 0.0f && hb <= 0.0f)) {
            float den = ha - hb;
            fm_vec3_t x = den != 0.0f ? v3_madd(a, v3_sub(b, a), ha / den) : a;
            x = v3_madd(x, t->n, -v3_dot(t->n, v3_sub(x, t->v[0])));
            if (tri_contains(t, &x)) { *ps = x; *pt = x; return 0.0f; }
        }
        fm_vec3_t q = v3_madd(a, t->n, -ha);
        bool ina = tri_contains(t, &q);
        if (ina) { best = ha * ha; *ps = a; *pt = q; }
        if (point) {
            if (ina) return best; /* a point over the face: nothing is closer */
        } else {
            q = v3_madd(b, t->n, -hb);
            bool inb = tri_contains(t, &q);
            if (inb && hb * hb < best) { best = hb * hb; *ps = b; *pt = q; }
            /* Both ends over the face (and on one side of it): so is the whole segment, and
             * its distance, the height, is least at an end; no edge is closer. */
            if (ina && inb) return best;
        }
    }
    if (point) {
        /* A point (a sphere's centre): the closest point of each edge by projection, far
         * cheaper than the segment-segment closest pair it would otherwise reduce to. */
        for (int i = 0; i < 3; i++) {
            float ee = v3_len2(t->e[i]);
            float v = ee > 0.0f ? f_clamp01(v3_dot(v3_sub(a, t->v[i]), t->e[i]) / ee) : 0.0f;
            fm_vec3_t cq = v3_madd(t->v[i], t->e[i], v);
            float d2 = v3_len2(v3_sub(a, cq));
            if (d2 < best) { best = d2; *ps = a; *pt = cq; *edge = i; *eu = 0.0f; *ev = v; }
        }
        return best;
    }
    for (int i = 0; i < 3; i++) {
        fm_vec3_t cp, cq;
        float u, v;
        float d2 = closest_seg_seg_in(a, b, t->v[i], t->v[(i + 1) % 3], &u, &v, &cp, &cq);
        if (d2 < best) { best = d2; *ps = cp; *pt = cq; *edge = i; *eu = u; *ev = v; }
    }
    return best;
}

static float seg_tri_closest(const tri_t *t, const fm_vec3_t *a, const fm_vec3_t *b, fm_vec3_t *ps, fm_vec3_t *pt)
{
    int edge;
    float u, v;
    return seg_tri_closest_ex(t, a, b, NULL, ps, pt, &edge, &u, &v);
}

/**
 * Contact normal (triangle -> segment) from the closest pair of segment a..b and the
 * triangle. For a pair interior to both the segment and an edge, the direction is that of
 * the two lines' cross product: rounding moves such a pair along the lines (the position
 * there is ill-conditioned), which tilts ps - pt but not the cross product.
 */
static fm_vec3_t pair_normal(const tri_t *t, fm_vec3_t a, fm_vec3_t b, fm_vec3_t ps, fm_vec3_t pt,
                             int edge, float u, float v, fm_vec3_t fallback)
{
    fm_vec3_t diff = v3_sub(ps, pt);
    fm_vec3_t n = v3_unit_or(diff, fallback);
    if (edge < 0 || !(u > 1e-4f && u < 1.0f - 1e-4f) || !(v > 1e-4f && v < 1.0f - 1e-4f)) return n;
    fm_vec3_t s = v3_sub(b, a), e = t->e[edge];
    fm_vec3_t m = v3_cross(s, e);
    float mm = v3_len2(m);
    if (!(mm > 1e-4f * v3_len2(s) * v3_len2(e))) return n;  /* near-parallel: the difference is better */
    m = v3_scale(m, 1.0f / sqrtf(mm));
    if (v3_dot(m, diff) < 0.0f) m = v3_neg(m);
    return v3_dot(m, n) > 0.9999f ? m : n;
}

float coll_prim_seg_tri_closest(const fm_vec3_t tri[3], fm_vec3_t a, fm_vec3_t b, fm_vec3_t *ps, fm_vec3_t *pt)
{
    tri_t t;
    tri_setup(&t, tri);
    return seg_tri_closest(&t, &a, &b, ps, pt);
}

/** Overlap result from the closest points at distance sqrt(d2) < r. */
static void overlap_result(const tri_t *t, fm_vec3_t a, fm_vec3_t b, float r, float d2,
                           fm_vec3_t ps, fm_vec3_t pt, coll_prim_hit_t *hit)
{
    float dist = sqrtf(d2);
    hit->t = 0.0f;
    hit->point = pt;
    if (dist > 1e-6f) {
        hit->normal = v3_unit_or(v3_sub(ps, pt), t->has_face ? t->n : v3(0.0f, 1.0f, 0.0f));
        hit->depth = r - dist;
        return;
    }
    if (!t->has_face) {
        /* A segment-like "triangle" (used for capsule and sphere bodies) crossing the
         * capsule's segment: push out perpendicular to both, away from the collider. */
        fm_vec3_t e = t->e[0];
        if (v3_len2(t->e[1]) > v3_len2(e)) e = t->e[1];
        if (v3_len2(t->e[2]) > v3_len2(e)) e = t->e[2];
        fm_vec3_t s = v3_sub(b, a);
        fm_vec3_t away = v3_sub(v3_scale(v3_add(a, b), 0.5f),
                                v3_scale(v3_add(v3_add(t->v[0], t->v[1]), t->v[2]), 1.0f / 3.0f));
        fm_vec3_t n = v3_cross(e, s);
        if (!(v3_len2(n) > 1e-12f * v3_len2(e) * v3_len2(s))) {
            /* parallel or point-like: the part of `away` perpendicular to the longer one */
            fm_vec3_t ax = v3_len2(s) > v3_len2(e) ? s : e;
            float l2 = v3_len2(ax);
            n = l2 > 1e-20f ? v3_madd(away, ax, -v3_dot(away, ax) / l2) : away;
            if (!(v3_len2(n) > 1e-20f)) { /* any perpendicular of ax */
                n = fabsf(ax.x) < 0.6f * sqrtf(l2) ? v3_cross(ax, v3(1.0f, 0.0f, 0.0f))
                                                   : v3_cross(ax, v3(0.0f, 1.0f, 0.0f));
            }
        }
        if (v3_dot(n, away) < 0.0f) n = v3_neg(n);
        hit->normal = v3_unit_or(n, v3(0.0f, 1.0f, 0.0f));
        hit->depth = r - dist;
        return;
    }
    /* The segment touches or crosses the face: push along the face normal to the side of
     * the segment's centre, far enough that the endpoint behind the plane clears it by r. */
    float ha = v3_dot(t->n, v3_sub(a, t->v[0]));
    float hb = v3_dot(t->n, v3_sub(b, t->v[0]));
    float hc = ha + hb;
    float sig = hc > 0.0f ? 1.0f : (hc < 0.0f ? -1.0f : (ha >= hb ? 1.0f : -1.0f));
    if (ha == hb) sig = 1.0f;
    hit->normal = v3_scale(t->n, sig);
    hit->depth = r - f_min(sig * ha, sig * hb);
}

/* ---------------------------------------------------------------- sweep */

typedef struct {
    tri_t tri;
    fm_vec3_t a, b, s, d;
    float ss;
    float mag;      /* coordinate magnitude (L1) of the segment, the motion and the triangle; < 0 until
                     * an axis test first needs it (sweep_mag) */
    float t_max;    /* the sweep's t_max (for sweep_mag) */
    float h[2], dn; /* has_face: heights of a and b over the face, and d along its normal */
    bool sphere;    /* inner segment (nearly) zero: only endpoint a is used */
} sweep_ctx_t;

typedef struct {
    float t;
    fm_vec3_t n, p;
    bool hit;
} feat_hit_t;

static void take(feat_hit_t *best, float t, fm_vec3_t n, fm_vec3_t p)
{
    if (!best->hit || t < best->t) { best->hit = true; best->t = t; best->n = n; best->p = p; }
}

/**
 * Time tt in [0, t_max] at which a point at signed distance h from a plane, moving at dn
 * along its normal, comes within r of it from its own side (sig: that side), when that
 * is earlier than the best hit so far; false when it moves away or arrives too late.
 */
static inline bool plane_approach(float h, float dn, float r, float t_max, const feat_hit_t *best,
                                  float *tt, float *sig)
{
    *sig = 1.0f;
    if (h < 0.0f) { *sig = -1.0f; h = -h; dn = -dn; }
    if (dn >= 0.0f) return false;
    float t = (h - r) / -dn;
    if (t < 0.0f) t = 0.0f;
    if (!(t <= t_max) || (best->hit && t >= best->t)) return false;
    *tt = t;
    return true;
}

/** Endpoint p moving by d against the offset face on its side. */
static void face_test(const sweep_ctx_t *c, fm_vec3_t p, float h, float r, float t_max, feat_hit_t *best)
{
    const tri_t *t = &c->tri;
    float dn = c->dn;
    float tt, sig;
    if (!plane_approach(h, dn, r, t_max, best, &tt, &sig)) return;
    fm_vec3_t q = v3_madd(v3_madd(p, c->d, tt), t->n, -(h + tt * dn)); /* onto the plane */
    if (!tri_contains(t, &q)) return;
    take(best, tt, v3_scale(t->n, sig), q);
}

/** Interior of the inner segment against the interior of triangle edge i. */
static void edge_edge_test(const sweep_ctx_t *c, int i, float r, float t_max, feat_hit_t *best)
{
    fm_vec3_t e = c->tri.e[i], e0 = c->tri.v[i];
    fm_vec3_t m = v3_cross(c->s, e);
    float mm = v3_dot(m, m);
    if (!(mm > 1e-10f * c->ss * v3_dot(e, e)) || !(mm > 1e-30f)) return; /* parallel: cylinders cover it */
    fm_vec3_t mu = v3_scale(m, 1.0f / sqrtf(mm));
    float h = v3_dot(mu, v3_sub(c->a, e0));
    float dn = v3_dot(mu, c->d);
    float tt, sig;
    if (!plane_approach(h, dn, r, t_max, best, &tt, &sig)) return;
    fm_vec3_t w = v3_sub(e0, v3_madd(c->a, c->d, tt));
    float u = v3_dot(v3_cross(w, e), m) / mm;
    float v = v3_dot(v3_cross(w, c->s), m) / mm;
    if (u < 0.0f || u > 1.0f || v < 0.0f || v > 1.0f) return;
    /* Nearly parallel lines leave mu (and so tt) poorly conditioned: never accept a time
     * at which the two segments are still clearly apart (the cylinders cover the rest). */
    fm_vec3_t at = v3_madd(c->a, c->d, tt);
    float sd2 = closest_seg_seg_in(at, v3_add(at, c->s), e0, c->tri.v[(i + 1) % 3], NULL, NULL, NULL, NULL);
    float rr = r + 1e-5f * (1.0f + r);
    if (sd2 > rr * rr) return;
    take(best, tt, v3_scale(mu, sig), v3_madd(e0, e, v));
}

/**
 * Separating-axis cull along u (any direction; not normalised): true when the capsule's
 * inner segment, swept by d over [0, t_max], stays farther than rc from the triangle along u
 * (the four swept segment ends against the three vertices), with a relative allowance for
 * the rounding of the projections and of the feature tests it stands in for. The distance
 * of convex sets is at least their separation along any axis, so a true answer means no
 * contact within rc over the whole motion. Squared compare: no sqrt, no division.
 */
PRIM_INLINE bool sweep_separated_k(sweep_ctx_t *c, const fm_vec3_t *pu, float rc, float t_max, float slack);
static bool sweep_separated(sweep_ctx_t *c, const fm_vec3_t *u, float rc, float t_max)
{
    return sweep_separated_k(c, u, rc, t_max, 1e-5f);
}

static inline float v3_abs_sum(fm_vec3_t v) { return fabsf(v.x) + fabsf(v.y) + fabsf(v.z); }

/* The coordinates' magnitude, made when an axis test first separates (most candidates
 * that reach the feature sweep never get that far: their setup skips it). Summed in this
 * order: the culls' allowances, hence the results, depend on its rounding. */
static float sweep_mag(sweep_ctx_t *c)
{
    if (c->mag >= 0.0f) return c->mag;
    float m = v3_abs_sum(c->a);
    m += v3_abs_sum(c->b);
    m += v3_abs_sum(c->d) * c->t_max;
    m += v3_abs_sum(c->tri.v[0]);
    m += v3_abs_sum(c->tri.v[1]);
    m += v3_abs_sum(c->tri.v[2]);
    c->mag = m;
    return m;
}

/* The segment's and the triangle's extents along the axis u: the segment's lower end at the
 * start (seg0), the motion's part towards the triangle (move, <= 0), the triangle's upper
 * end (tri); false for an axis too short or not finite. */
typedef struct { float uu, seg0, move, tri; } axis_span_t;
PRIM_INLINE bool axis_span(const sweep_ctx_t *c, fm_vec3_t u, float t_max, axis_span_t *s)
{
    s->uu = v3_len2(u);
    if (!(s->uu > V3_TINY_LEN2) || !f_finite(s->uu)) return false;
    const tri_t *t = &c->tri;
    float sa = v3_dot(u, c->a), sb = v3_dot(u, c->b), sd = v3_dot(u, c->d) * t_max;
    float t0 = v3_dot(u, t->v[0]), t1 = v3_dot(u, t->v[1]), t2 = v3_dot(u, t->v[2]);
    s->seg0 = f_min(sa, sb);
    s->move = f_min(sd, 0.0f);
    s->tri = f_max(t0, f_max(t1, t2));
    return true;
}

PRIM_INLINE bool sweep_separated_k(sweep_ctx_t *c, const fm_vec3_t *pu, float rc, float t_max, float slack)
{
    const fm_vec3_t u = *pu;
    axis_span_t s;
    if (!axis_span(c, u, t_max, &s)) return false;
    float sep = s.seg0 + s.move - s.tri;
    if (!(sep > 0.0f)) return false;
    float u1 = fabsf(u.x) + fabsf(u.y) + fabsf(u.z);
    sep -= slack * u1 * sweep_mag(c);
    float rr = rc * 1.0001f + 1e-7f;
    return sep > 0.0f && sep * sep > rr * rr * s.uu;
}

/* sweep_separated_k along the boundary axis, which also tells (*clear) whether the start
 * alone (t = 0: the motion's term left out) is separated along u by more than r (allowance
 * 1e-5 of the coordinates' magnitude, sweep_separated's): then the segment's distance to the
 * triangle at the start is more than r (a distance is at least the separation along any
 * axis), so there is neither an overlap nor a contact at t = 0, and the start's closest pair
 * would serve only the cull along its own direction. */
PRIM_INLINE bool sweep_separated_start(sweep_ctx_t *c, const fm_vec3_t *pu, float rc, float t_max, float slack,
                                       float r, bool *clear)
{
    const fm_vec3_t u = *pu;
    *clear = false;
    axis_span_t s;
    if (!axis_span(c, u, t_max, &s)) return false;
    float sep0 = s.seg0 - s.tri;
    if (!(sep0 > 0.0f)) return false;
    float u1 = fabsf(u.x) + fabsf(u.y) + fabsf(u.z);
    float mg = sweep_mag(c);
    float sep = s.seg0 + s.move - s.tri; /* (sweep_separated_k's, term for term) */
    if (sep > 0.0f) {
        sep -= slack * u1 * mg;
        float rr = rc * 1.0001f + 1e-7f;
        if (sep > 0.0f && sep * sep > rr * rr * s.uu) return true;
    }
    sep0 -= 1e-5f * u1 * mg;
    float r0 = r * 1.0001f + 1e-6f;
    *clear = sep0 > 0.0f && sep0 * sep0 > r0 * r0 * s.uu;
    return false;
}

/* sweep_separated_k (rc, slack), telling apart a miss by the allowance alone: 1 separated,
 * 2 separated without the allowance but not with it, 0 not even without it. */
PRIM_INLINE int sweep_separated_why(sweep_ctx_t *c, const fm_vec3_t *pu, float rc, float t_max, float slack)
{
    const fm_vec3_t u = *pu;
    axis_span_t s;
    if (!axis_span(c, u, t_max, &s)) return 0;
    float sep = s.seg0 + s.move - s.tri;
    if (!(sep > 0.0f)) return 0;
    float u1 = fabsf(u.x) + fabsf(u.y) + fabsf(u.z);
    float rr = rc * 1.0001f + 1e-7f;
    float sepa = sep - slack * u1 * sweep_mag(c);
    if (sepa > 0.0f && sepa * sepa > rr * rr * s.uu) return 1;
    return sep * sep > rr * rr * s.uu ? 2 : 0;
}

/* |u . w| summed term by term: what the rounding of u . w (and of w's own subtraction)
 * scales with. */
static inline float v3_abs_dot(fm_vec3_t u, fm_vec3_t w)
{
    return fabsf(u.x * w.x) + fabsf(u.y * w.y) + fabsf(u.z * w.z);
}

/* sweep_separated_k along u with every point measured from o (a point of the triangle near
 * the capsule: a closest pair's point on it, on edge's interior at ev when edge >= 0), so
 * that the allowance is the rounding of those local projections (1e-6 of their terms, each
 * a subtraction and a dot product: a few float epsilons) instead of 1e-6 of the
 * coordinates' magnitude: on a long triangle whose far vertices lie along an edge the axis
 * is perpendicular to, their terms are near zero. Any axis is a valid test; this one is
 * the cull's, not a different answer. */
static bool sweep_separated_at(const sweep_ctx_t *c, const fm_vec3_t *pu, float rc, float t_max, const fm_vec3_t *po,
                               int edge, float ev)
{
    fm_vec3_t u = *pu;
    const fm_vec3_t o = *po;
    /* o on edge's interior (closest pair): the pair's direction is perpendicular to the
     * edge but for the rounding of the point on it, which tilts it towards the edge's far
     * vertex (1e-6 over a 40 m edge: more than the tolerance); the part perpendicular to the
     * edge is an axis as good */
    if (edge >= 0 && ev > 0.0f && ev < 1.0f) {
        fm_vec3_t e = c->tri.e[edge];
        u = v3_madd(u, e, -v3_dot(u, e) / v3_len2(e));
    }
    float uu = v3_len2(u);
    if (!(uu > V3_TINY_LEN2) || !f_finite(uu)) return false;
    const tri_t *t = &c->tri;
    fm_vec3_t wa = v3_sub(c->a, o), wb = v3_sub(c->b, o), wd = v3_scale(c->d, t_max);
    fm_vec3_t w0 = v3_sub(t->v[0], o), w1 = v3_sub(t->v[1], o), w2 = v3_sub(t->v[2], o);
    float sa = v3_dot(u, wa), sb = v3_dot(u, wb), sd = v3_dot(u, wd);
    float t0 = v3_dot(u, w0), t1 = v3_dot(u, w1), t2 = v3_dot(u, w2);
    float sep = f_min(sa, sb) + f_min(sd, 0.0f) - f_max(t0, f_max(t1, t2));
    if (!(sep > 0.0f)) return false;
    float err = f_max(v3_abs_dot(u, wa), v3_abs_dot(u, wb)) + v3_abs_dot(u, wd) +
                f_max(v3_abs_dot(u, w0), f_max(v3_abs_dot(u, w1), v3_abs_dot(u, w2)));
    sep -= 1e-6f * err;
    float rr = rc * 1.0001f + 1e-7f;
    return sep > 0.0f && sep * sep > rr * rr * uu;
}

/** Earliest entry of t*d into K(r) over [0, t_max]; any = stop at the first piece found. */
static bool sweep_features(const sweep_ctx_t *c, float r, float t_max, bool any, feat_hit_t *best)
{
    const tri_t *t = &c->tri;
    int nend = c->sphere ? 1 : 2;
    fm_vec3_t ends[2] = { c->a, c->b };
    best->hit = false;
    prim_ray_t h = { 0.0f, { { 0.0f, 0.0f, 0.0f } } }; /* (set by every test that returns true) */
    for (int k = 0; k < nend; k++) {
        if (t->has_face) {
            face_test(c, ends[k], c->h[k], r, t_max, best);
            if (any && best->hit) return true;
        }
        for (int i = 0; i < 3; i++) {
            float lim = best->hit ? best->t : t_max;
            if (ray_cylinder_side_in(ends[k], c->d, t->v[i], t->v[(i + 1) % 3], r, lim, &h)) {
                take(best, h.s, h.n, v3_madd(v3_madd(ends[k], c->d, h.s), h.n, -r));
                if (any) return true;
            }
        }
    }
    fm_vec3_t nd = v3_neg(c->d);
    for (int i = 0; i < 3; i++) {
        float lim = best->hit ? best->t : t_max;
        bool got = c->sphere ? ray_sphere_in(t->v[i], nd, c->a, r, lim, &h)
                             : ray_capsule_in(t->v[i], nd, c->a, c->b, r, lim, &h);
        if (got) {
            take(best, h.s, v3_neg(h.n), t->v[i]);
            if (any) return true;
        }
    }
    if (!c->sphere) {
        for (int i = 0; i < 3; i++) {
            edge_edge_test(c, i, r, t_max, best);
            if (any && best->hit) return true;
        }
    }
    return best->hit;
}

/* tri_sweep's plane cull at rin, for confirm: the swept capsule, at heights lo..hi over the
 * face's plane over the whole motion, that stays farther than the touch tolerance from it (a
 * ball or capsule resting against a wall, moved along it or away: the crack rule's drop
 * beside a wall the slide stopped at, in a V corner) never goes deeper than the tolerance
 * into the triangle, which is no hit. The allowance is 1e-6 of the heights' terms (the unit
 * normal times the ends' offsets from the first vertex, and the motion), far above their
 * rounding (a few float epsilons of those terms). Before the axes and the closest pair,
 * which find the same. Out of line: rarely called (its caller tests a necessary condition). */
#if defined(__GNUC__)
__attribute__((noinline))
#endif
static bool plane_rin_separated(const sweep_ctx_t *c, float lo, float hi, float r, float t_max, bool moving)
{
    float rc = (r - f_min(COLL_PRIM_TOUCH_TOL, 0.25f * r)) * 1.0001f + 1e-7f; /* tri_sweep's rin */
    if (!(lo > rc || hi < -rc)) return false;
    float err = v3_abs_sum(v3_sub(c->a, c->tri.v[0])) + v3_abs_sum(v3_sub(c->b, c->tri.v[0])) +
                (moving ? v3_abs_sum(c->d) * t_max : 0.0f);
    return f_max(lo, -hi) - 1e-6f * err > rc;
}

/* confirm: count a contact only when the motion goes deeper than the touch tolerance;
 * held (NULL: none): a contact after t = 0 that comes no sooner than t_max is none (the
 * caller holds one at t_max already; its refinement and confirmation would be wasted), and
 * *held, the held contact's normal (or zero), is tried as a separating axis before the
 * closest pairs. */
static bool tri_sweep(const fm_vec3_t seg[2], float r, const fm_vec3_t *disp, const fm_vec3_t tri[3],
                      coll_tri_prep_t *prep, float t_max, bool confirm, const fm_vec3_t *held,
                      coll_prim_hit_t *hit)
{
    const bool before = held != NULL;
    if (!seg || !disp || !tri || !hit) return false;
    /* (prim_sane and prim_sane3 on all of them, one branch: prim_room_ok) */
    if (!(r >= 0.0f) || !(t_max >= 0.0f)) return false;
    if (!prim_room_ok(prim_room_bits(r) | prim_room_bits(t_max) | prim_room3(seg[0]) | prim_room3(seg[1]) |
                      prim_room3(*disp)))
        return false;
    /* a ready prep's triangle passed this check when it was filled (the same vertex values) */
    if (!(prep && prep->ready) && !prim_room_ok(prim_room3(tri[0]) | prim_room3(tri[1]) | prim_room3(tri[2])))
        return false;
    if (!prim_room_ok(prim_room3(v3_scale(*disp, t_max)))) return false;

    sweep_ctx_t c;
    tri_setup_keep(&c.tri, tri, prep);
    c.a = seg[0]; c.b = seg[1]; c.d = *disp;
    c.s = v3_sub(c.b, c.a);
    c.ss = v3_dot(c.s, c.s);
    c.sphere = !(c.ss > 1e-14f);
    if (c.sphere) { c.a = v3_madd(c.a, c.s, 0.5f); c.b = c.a; c.s = v3(0.0f, 0.0f, 0.0f); c.ss = 0.0f; }
    bool moving = v3_dot(c.d, c.d) * t_max * t_max > 1e-24f;

    /* Cull: both endpoints beyond the same offset plane over the whole motion. */
    bool far = false;
    if (c.tri.has_face) {
        float ha = c.h[0] = v3_dot(c.tri.n, v3_sub(c.a, c.tri.v[0]));
        float hb = c.h[1] = v3_dot(c.tri.n, v3_sub(c.b, c.tri.v[0]));
        c.dn = v3_dot(c.tri.n, c.d);
        float dd = moving ? c.dn * t_max : 0.0f;
        float lo = f_min(f_min(ha, hb), f_min(ha + dd, hb + dd));
        float hi = f_max(f_max(ha, hb), f_max(ha + dd, hb + dd));
        if (lo > r || hi < -r) return false;
        /* With confirm, the same cull at rin (plane_rin_separated; first its necessary
         * condition, rin being at least r less COLL_PRIM_TOUCH_TOL) */
        if (confirm && (lo > r - COLL_PRIM_TOUCH_TOL || hi < COLL_PRIM_TOUCH_TOL - r) &&
            plane_rin_separated(&c, lo, hi, r, t_max, moving))
            return false;
        /* Far: the start beyond the offset plane, with room for the closest pair's rounding
         * (its distance is at least the height). Then there is neither an overlap nor a
         * contact at t = 0, and the start's closest pair would serve only the cull on its
         * direction: the boundary axis below stands in for it. */
        float rf = r * 1.0001f + 1e-6f;
        far = moving && (f_min(ha, hb) > rf || f_max(ha, hb) < -rf);
    }

    const float tol = f_min(COLL_PRIM_TOUCH_TOL, 0.25f * r);
    float rin = r - tol;
    c.mag = -1.0f; /* (sweep_mag) */
    c.t_max = t_max;
    /* Separating-axis culls: the swept capsule stays clear of the triangle along an axis
     * (most candidates near stairs and corners that the plane cull keeps: the capsule
     * beside a riser or a tread's edge). With confirm, a contact that never goes deeper
     * than the touch tolerance is no hit, so clearing rin suffices, and the allowance is
     * the confirm test's own (1e-6, the question it answers after the features: does the
     * motion get within rin?): a capsule resting against or sliding along a wall then stops
     * here instead of after the feature sweep and the refinement. Any axis is a valid test,
     * so each cull is conservative whatever the axis; the axes differ in what they catch.
     *
     * First the boundary axis: from the nearest point of the triangle's boundary to the
     * end nearer the plane (for a point beside the face that is its closest pair; over the
     * face the pair's direction is the normal, which the plane cull has tried; for a
     * segment it is near the pair's). A point-segment projection per edge and one test,
     * against the start's closest pair (about 550 x86, more for a segment): on a far start
     * it replaces the pair; on a near one a segment tries it first (a sphere's closest pair
     * is cheap: the point path). Measured against the closest pair's cull alone (x86):
     * stairs_real -5.7 %, stairs -3.2 %, crack -0.6 %, Jolt -1.7 %, V-corner +2.4 % (walls the
     * capsule touches, where the pair is computed after all). */
    fm_vec3_t sep;
    if (moving && c.tri.has_face && (far || !c.sphere)) {
        fm_vec3_t p = fabsf(c.h[0]) <= fabsf(c.h[1]) ? c.a : c.b;
        float bestl = 3.0e38f;
        sep = v3(0.0f, 0.0f, 0.0f);
        for (int i = 0; i < 3; i++) {
            fm_vec3_t w = v3_sub(p, c.tri.v[i]);
            float ee = v3_len2(c.tri.e[i]);
            if (!(ee > 0.0f)) continue;
            fm_vec3_t u = v3_madd(w, c.tri.e[i], -f_clamp01(v3_dot(w, c.tri.e[i]) / ee));
            float l = v3_len2(u);
            if (l < bestl) { bestl = l; sep = u; }
        }
        bool clear;
        if (confirm ? sweep_separated_start(&c, &sep, rin, t_max, 1e-6f, r, &clear)
                    : sweep_separated_start(&c, &sep, r, t_max, 1e-5f, r, &clear))
            return false;
        /* the start clear along it: as far (no start pair; the features find any contact),
         * where the coordinates are small (the end cull's `small` below); in large ones (a
         * crack's 100 m floor) the pair's axis measured from its point on the triangle
         * culls candidates that would otherwise reach the features */
        far = far || (clear && 1e-6f * sweep_mag(&c) < r - (rin * 1.0001f + 1e-7f));
    }
    /* Then, with a hit held, its normal (held): the held contact's neighbour across their
     * shared edge (a stair's nosing: the tread and the riser, or a quad's two triangles)
     * meets the capsule only at t_max, where the capsule touches the edge, and lies behind
     * the edge along that normal, so the swept capsule stays clear of rin along it by about
     * the touch tolerance: dropped before the start's closest pair and the end's (2-3.5k
     * console instructions on stairs_real's nosings). A cull like the others (any axis is a
     * valid one, with the confirm culls' allowance); only where the coordinates are small
     * enough for that allowance to leave the tolerance room (the end cull's `small` below:
     * in a crack's 100 m floor it never separates and would only cost). */
    if (held && confirm && moving && 1e-6f * sweep_mag(&c) < r - (rin * 1.0001f + 1e-7f) &&
        sweep_separated_k(&c, held, rin, t_max, 1e-6f))
        return false;
    fm_vec3_t ps = { { 0.0f, 0.0f, 0.0f } }, pt = ps;
    float d2 = 0.0f;
    if (!far) {
        int edge0;
        float eu0, ev0;
        d2 = seg_tri_closest_ex(&c.tri, &c.a, &c.b, c.tri.has_face ? c.h : NULL, &ps, &pt, &edge0, &eu0, &ev0);
        if (d2 < rin * rin) {
            overlap_result(&c.tri, c.a, c.b, r, d2, ps, pt, hit);
            return true;
        }
        if (!moving) return false;
        /* then the closest pair's direction at the start; with confirm, where only the
         * allowance (1e-6 of the coordinates' magnitude) kept it from separating, again
         * measured from the pair's point on the triangle (sweep_separated_at: a ball rolled
         * along a crack's edge in a 100 m floor stays clear of it by 1e-4) */
        sep = v3_sub(ps, pt);
        if (confirm) {
            int why = sweep_separated_why(&c, &sep, rin, t_max, 1e-6f);
            if (why == 1 || (why == 2 && sweep_separated_at(&c, &sep, rin, t_max, &pt, edge0, ev0))) return false;
        } else if (sweep_separated(&c, &sep, r, t_max)) {
            return false;
        }
    }

    feat_hit_t best;
    /* the closest pair at the end of the motion (the confirmation's), when the end cull
     * below made it */
    bool end_known = false;
    float d2e = 0.0f;
    fm_vec3_t es = ps, et = ps;
    if (!far && d2 <= r * r) {
        best.hit = true;
        best.t = 0.0f;
        best.n = v3_unit_or(v3_sub(ps, pt), c.tri.has_face ? c.tri.n : v3(0.0f, 1.0f, 0.0f));
        best.p = pt;
    } else {
        /* The end cull: with a hit held at t_max (before), a candidate that reaches the
         * capsule only at t_max (the held contact's neighbour across their shared edge: a
         * nosing, a crack's edge) is no better, but the start's axes above cannot tell (its
         * contact direction is the end's) and the feature sweep finds its contact at t_max, or
         * a rounding earlier, where the confirmation then runs the features again to find it
         * never goes deeper (3-6k console instructions each). The end's closest pair is the
         * confirmation's own last axis: the swept capsule clear of rin along it, with the
         * confirm culls' allowance (1e-6), never goes deeper than the touch tolerance, which
         * is no hit however the features would find it. Where the coordinates are small, with
         * the confirm culls' own test (its allowance 1e-6 of their magnitude); where that
         * allowance leaves the tolerance no room (a crack's edge in a 100 m floor: magnitude
         * 87-162), the same axis measured from the end's point on the triangle and made
         * perpendicular to the edge it lies on, its allowance the rounding of those local
         * terms (sweep_separated_at). Only once a hit is held (a first contact pays the end's
         * pair for nothing: measured, it cost more than it saved). */
        if (confirm && before) {
            bool small = 1e-6f * sweep_mag(&c) < r - (rin * 1.0001f + 1e-7f);
            fm_vec3_t off = v3_scale(c.d, t_max);
            fm_vec3_t ea = v3_add(c.a, off), eb = v3_add(c.b, off);
            int eedge;
            float eeu, eev;
            d2e = seg_tri_closest_ex(&c.tri, &ea, &eb, NULL, &es, &et, &eedge, &eeu, &eev);
            end_known = true;
            if (!(d2e < rin * rin)) {
                fm_vec3_t sep2 = v3_sub(es, et);
                if (small ? sweep_separated_k(&c, &sep2, rin, t_max, 1e-6f)
                          : sweep_separated_at(&c, &sep2, rin, t_max, &et, eedge, eev))
                    return false;
            }
        }
        if (!sweep_features(&c, r, t_max, false, &best)) return false;
    }
    if (before && best.t > 0.0f && !(best.t < t_max)) return false;

    hit->t = best.t;
    hit->depth = 0.0f;
    hit->normal = best.n;
    hit->point = best.p;
    if (far && !(best.t > 0.0f)) d2 = seg_tri_closest(&c.tri, &c.a, &c.b, &ps, &pt); /* (rounding only) */
    float hd = sqrtf(d2);
    if (best.t > 0.0f) {
        /* The pieces meet tangentially, so which one won is decided by rounding near a
         * junction; the closest points at the contact time give the normal smoothly. */
        fm_vec3_t off = v3_scale(c.d, best.t);
        fm_vec3_t ha = v3_add(c.a, off), hb = v3_add(c.b, off);
        int edge;
        float eu, ev;
        float d2h = seg_tri_closest_ex(&c.tri, &ha, &hb, NULL, &ps, &pt, &edge, &eu, &ev);
        /* Near a flat minimum rounding can pick a candidate pair slightly off the true one
         * (e.g. a vertex instead of a point just past it on the next edge); alternating
         * projections (segment point nearest the triangle point, and back) settle it. */
        /* (a sphere's centre is a point: its closest pair is exact already) */
        bool interior = c.sphere || (edge >= 0 && eu > 1e-4f && eu < 1.0f - 1e-4f && ev > 1e-4f && ev < 1.0f - 1e-4f);
        /* A round that gives back its own triangle point (bit for bit) leaves the next one
         * the same input, so the same answer: the pair has settled and the loop stops (the
         * capsule's end on a stair's nosing: both rounds found the same pair, ~460 console
         * instructions each). */
        for (int it = 0; it < 2 && !interior && d2h > 0.25f * r * r; it++) {
            fm_vec3_t qt, dummy;
            fm_vec3_t qs = closest_on_seg(ha, hb, pt);
            float q2 = seg_tri_closest(&c.tri, &qs, &qs, &dummy, &qt);
            if (!(q2 <= d2h)) break;
            bool settled = v3_same_bits(qt, pt);
            d2h = q2; ps = qs; pt = qt;
            edge = -1;
            if (settled) break;
        }
        hd = r;
        if (d2h > 0.25f * r * r) {
            hit->normal = pair_normal(&c.tri, ha, hb, ps, pt, edge, eu, ev, best.n);
            hit->point = pt;
            hd = sqrtf(d2h);
        }
    }
    /* Count the contact only when the motion goes deeper than the touch tolerance: first
     * the cheap sufficient test from the contact, then the exact one. */
    if (confirm && !prim_goes_deeper(hd, hit->normal, c.d, rin, t_max - best.t)) {
        if (sweep_separated_k(&c, &hit->normal, rin, t_max, 1e-6f)) return false;
        if (!end_known) {
            fm_vec3_t off = v3_scale(c.d, t_max);
            fm_vec3_t ea = v3_add(c.a, off), eb = v3_add(c.b, off);
            d2e = seg_tri_closest(&c.tri, &ea, &eb, &es, &et);
        }
        if (!(d2e < rin * rin)) {
            /* clear of rin along the closest pair's direction at the end: never deeper
             * (known not when that test ran before the features) */
            fm_vec3_t sep2 = v3_sub(es, et);
            if (!end_known && sweep_separated(&c, &sep2, rin, t_max)) return false;
            feat_hit_t conf;
            if (!sweep_features(&c, rin, t_max, true, &conf)) return false;
        }
    }
    return true;
}

bool coll_prim_tri_sweep_ex(const fm_vec3_t seg[2], float r, const fm_vec3_t *disp, const fm_vec3_t tri[3],
                            float t_max, bool confirm, coll_prim_hit_t *hit)
{
    return tri_sweep(seg, r, disp, tri, NULL, t_max, confirm, NULL, hit);
}

bool coll_prim_tri_sweep_prep(const fm_vec3_t seg[2], float r, const fm_vec3_t *disp, const fm_vec3_t tri[3],
                              coll_tri_prep_t *p, float t_max, const fm_vec3_t *held, coll_prim_hit_t *hit)
{
    return tri_sweep(seg, r, disp, tri, p, t_max, true, held, hit);
}

bool coll_capsule_triangle_sweep(const fm_vec3_t seg[2], float r, const fm_vec3_t *disp,
                                 const fm_vec3_t tri[3], float t_max, coll_prim_hit_t *hit)
{
    return tri_sweep(seg, r, disp, tri, NULL, t_max, true, NULL, hit);
}

static bool tri_overlap(const fm_vec3_t seg[2], float r, const fm_vec3_t tri[3], coll_tri_prep_t *prep,
                        coll_prim_hit_t *hit, bool *clear, coll_tri_axis_t *axis)
{
    if (!seg || !tri || !hit) return false;
    if (!(r >= 0.0f) || !prim_room_ok(prim_room_bits(r) | prim_room3(seg[0]) | prim_room3(seg[1]))) return false;
    if (!(prep && prep->ready) && !prim_room_ok(prim_room3(tri[0]) | prim_room3(tri[1]) | prim_room3(tri[2])))
        return false;
    tri_t t;
    tri_setup_keep(&t, tri, prep);
    float rin = r - f_min(COLL_PRIM_TOUCH_TOL, 0.25f * r);
    /* Cull on the sweep's boundary axis (tri_sweep): from the nearest point of the
     * triangle's boundary to the end nearer the plane; the segment clear of the triangle by
     * more than rin along it (sweep_separated's allowance) has no overlap. The query's plane
     * cull has dropped most candidates beyond the plane; this one drops the neighbours
     * beside the capsule before their closest pair (about 600 x86). Measured (x86):
     * stairs_real -2.0 %, stairs -0.3 %, V-corner +1.1 % (walls the capsule touches). */
    if (t.has_face) {
        float hab[2] = { v3_dot(t.n, v3_sub(seg[0], t.v[0])), v3_dot(t.n, v3_sub(seg[1], t.v[0])) };
        /* The face's plane at rin (tri_sweep's plane_rin_separated, without motion): a
         * segment farther than rin from the plane, on one side of it (a capsule resting
         * against a wall within the touch tolerance: the recovery's look in a V corner), is
         * farther from the triangle: no overlap, without the closest pair. The allowance is
         * 1e-6 of the heights' terms, far above their rounding. */
        {
            float lo = f_min(hab[0], hab[1]), hi = f_max(hab[0], hab[1]);
            float rc = rin * 1.0001f + 1e-7f;
            if ((lo > rc || hi < -rc) &&
                f_max(lo, -hi) - 1e-6f * (v3_abs_sum(v3_sub(seg[0], t.v[0])) + v3_abs_sum(v3_sub(seg[1], t.v[0]))) > rc) {
                if (clear) *clear = true;
                return false;
            }
        }
        fm_vec3_t p = fabsf(hab[0]) <= fabsf(hab[1]) ? seg[0] : seg[1];
        float bestl = 3.0e38f;
        fm_vec3_t u = v3(0.0f, 0.0f, 0.0f);
        for (int i = 0; i < 3; i++) {
            fm_vec3_t w = v3_sub(p, t.v[i]);
            float ee = v3_len2(t.e[i]);
            if (!(ee > 0.0f)) continue;
            fm_vec3_t ui = v3_madd(w, t.e[i], -f_clamp01(v3_dot(w, t.e[i]) / ee));
            float l = v3_len2(ui);
            if (l < bestl) { bestl = l; u = ui; }
        }
        float uu = v3_len2(u);
        if (uu > V3_TINY_LEN2 && f_finite(uu)) {
            float seg0 = f_min(v3_dot(u, seg[0]), v3_dot(u, seg[1]));
            float top = f_max(v3_dot(u, t.v[0]), f_max(v3_dot(u, t.v[1]), v3_dot(u, t.v[2])));
            float sep = seg0 - top;
            /* (the axis tri_sweep's boundary cull would take for this segment and triangle,
             * and its extents: the same p, edges and expressions as axis_span's) */
            if (axis) {
                axis->u = u;
                axis->seg0 = seg0;
                axis->top = top;
            }
            float mag = v3_abs_sum(seg[0]) + v3_abs_sum(seg[1]) + v3_abs_sum(t.v[0]) + v3_abs_sum(t.v[1]) + v3_abs_sum(t.v[2]);
            sep -= 1e-5f * v3_abs_sum(u) * mag;
            float rr = rin * 1.0001f + 1e-7f;
            if (sep > 0.0f && sep * sep > rr * rr * uu) {
                /* clear of rin by the allowance (1e-5 of the coordinates' magnitude), far
                 * more than the closest pair's rounding: tri_sweep's pair at t_max = 0 is no
                 * overlap either */
                if (clear) *clear = true;
                return false;
            }
        }
    }
    fm_vec3_t ps, pt;
    float d2 = seg_tri_closest(&t, &seg[0], &seg[1], &ps, &pt);
    if (!(d2 < rin * rin)) {
        /* (tri_sweep with t_max = 0 computes this very pair: the same expressions on the
         * same values, its heights over the face included, and stops on it) */
        if (clear) *clear = true;
        return false;
    }
    overlap_result(&t, seg[0], seg[1], r, d2, ps, pt, hit);
    return true;
}

bool coll_capsule_triangle_overlap(const fm_vec3_t seg[2], float r, const fm_vec3_t tri[3],
                                   coll_prim_hit_t *hit)
{
    return tri_overlap(seg, r, tri, NULL, hit, NULL, NULL);
}

bool coll_capsule_triangle_overlap_prep(const fm_vec3_t seg[2], float r, const fm_vec3_t tri[3],
                                        coll_tri_prep_t *p, coll_prim_hit_t *hit)
{
    return tri_overlap(seg, r, tri, p, hit, NULL, NULL);
}

bool coll_capsule_triangle_overlap_clear(const fm_vec3_t seg[2], float r, const fm_vec3_t tri[3],
                                         coll_tri_prep_t *p, coll_prim_hit_t *hit, bool *clear,
                                         coll_tri_axis_t *axis)
{
    *clear = false;
    if (axis) axis->u = v3(0.0f, 0.0f, 0.0f);
    return tri_overlap(seg, r, tri, p, hit, clear, axis);
}

bool coll_tri_sweep_axis_culls(const fm_vec3_t seg[2], float r, const fm_vec3_t *disp, const fm_vec3_t tri[3],
                               float t_max, const coll_tri_axis_t *axis)
{
    /* tri_sweep's state as its boundary cull reads it: the segment's ends (not a sphere's
     * midpoint: only a segment reaches that cull without a far start), the motion, the
     * triangle's vertices (the prep's setup keeps tri's values) and the magnitude not yet
     * made */
    if (!(r >= 0.0f) || !(t_max >= 0.0f)) return false;
    sweep_ctx_t c;
    c.a = seg[0];
    c.b = seg[1];
    c.d = *disp;
    for (int i = 0; i < 3; i++) c.tri.v[i] = tri[i];
    c.s = v3_sub(c.b, c.a);
    c.ss = v3_dot(c.s, c.s);
    if (!(c.ss > 1e-14f)) return false; /* a sphere: that cull runs only on a far start */
    if (!(v3_dot(c.d, c.d) * t_max * t_max > 1e-24f)) return false; /* not moving: no such cull */
    c.mag = -1.0f;
    c.t_max = t_max;
    const float tol = f_min(COLL_PRIM_TOUCH_TOL, 0.25f * r);
    float rin = r - tol;
    bool clear;
    return sweep_separated_start(&c, &axis->u, rin, t_max, 1e-6f, r, &clear);
}

/* ---------------------------------------------------------------- ray */

/* The ray's shear (coll_ray_triangle below): the axis of d's largest component becomes
 * +z; false for a direction out of range or with no length. (Woop et al. swap x and y when
 * d points down that axis, to keep the winding for back-face culling; a two-sided test
 * does not need it: the swap negates U, V and W exactly, since a rounded difference is the
 * negated rounded difference the other way round, and the inside test and det == 0 do not
 * see the sign. Nothing else uses them.) */
bool coll_ray_shear(const fm_vec3_t *d, coll_ray_shear_t *sh)
{
    if (!prim_room_ok(prim_room3(*d))) return false;
    int kz = 0;
    float ax = fabsf(d->x), ay = fabsf(d->y), az = fabsf(d->z);
    if (ay > ax && ay >= az) kz = 1;
    else if (az > ax && az > ay) kz = 2;
    int kx = (kz + 1) % 3, ky = (kx + 1) % 3;
    float dz = d->v[kz];
    if (dz == 0.0f) return false; /* zero direction */
    sh->kz = (uint8_t)kz;
    sh->sx = d->v[kx] / dz;
    sh->sy = d->v[ky] / dz;
    return true;
}

/* The watertight edge test of the translated vertices A, B, C in the shear kx, ky, kz
 * (constants where it is inlined: no indexed loads): true when the ray passes through the
 * closed triangle (not edge-on). */
PRIM_INLINE bool ray_edges(const fm_vec3_t *A, const fm_vec3_t *B, const fm_vec3_t *C, float sx, float sy,
                           const int kx, const int ky, const int kz)
{
    float Ax = A->v[kx] - sx * A->v[kz], Ay = A->v[ky] - sy * A->v[kz];
    float Bx = B->v[kx] - sx * B->v[kz], By = B->v[ky] - sy * B->v[kz];
    float Cx = C->v[kx] - sx * C->v[kz], Cy = C->v[ky] - sy * C->v[kz];
    float U = Cx * By - Cy * Bx;
    float V = Ax * Cy - Ay * Cx;
    float W = Bx * Ay - By * Ax;
    if ((U < 0.0f || V < 0.0f || W < 0.0f) && (U > 0.0f || V > 0.0f || W > 0.0f)) return false;
    float det = U + V + W;
    return det != 0.0f && f_finite(det);
}

/* d passed coll_ray_shear (sane, sheared into sh). */
PRIM_INLINE bool ray_triangle_sheared_in(const fm_vec3_t *o, const fm_vec3_t *d, const coll_ray_shear_t *sh,
                                         const fm_vec3_t tri[3], float s_max, coll_tri_prep_t *p,
                                         coll_prim_hit_t *hit)
{
    if (!(s_max >= 0.0f)) return false;
    const float sx = sh->sx, sy = sh->sy;
    fm_vec3_t A = v3_sub(tri[0], *o), B = v3_sub(tri[1], *o), C = v3_sub(tri[2], *o);
    bool in;
    switch (sh->kz) {
    case 0: in = ray_edges(&A, &B, &C, sx, sy, 1, 2, 0); break;
    case 1: in = ray_edges(&A, &B, &C, sx, sy, 2, 0, 1); break;
    default: in = ray_edges(&A, &B, &C, sx, sy, 0, 1, 2); break;
    }
    if (!in) return false;
    /* The inputs' range, after the edge test (a miss returns false either way; values out
     * of range or not finite only make float results there, no fault). A ready prep's
     * triangle passed it when it was filled (the same vertex values). */
    uint32_t room = prim_room3(*o);
    if (!(p && p->ready)) room |= prim_room3(tri[0]) | prim_room3(tri[1]) | prim_room3(tri[2]);
    if (!prim_room_ok(room)) return false;
    /* The distance from the plane through the vertex shared by the two shortest edges:
     * better conditioned than the sheared-z interpolation for slivers. The raw normal
     * (tri_setup_raw's expressions: bit-identical), from the prep when it is ready. */
    fm_vec3_t nraw;
    int apex;
    float nn = 0.0f, lmax = 0.0f;
    if (p && p->ready) {
        nraw = p->nraw;
        apex = p->apex;
    } else {
        fm_vec3_t e[3];
        for (int i = 0; i < 3; i++) e[i] = v3_sub(tri[(i + 1) % 3], tri[i]);
        nraw = raw_normal(e, &apex, &lmax);
        nn = v3_len2(nraw);
    }
    float dn = v3_dot(nraw, *d);
    if (dn == 0.0f) return false;
    float s = v3_dot(nraw, v3_sub(tri[apex], *o)) / dn;
    if (!(s >= 0.0f) || !(s <= s_max) || !f_finite(s)) return false;

    fm_vec3_t n;
    if (p && !p->ready) {
        /* a hit: its unit normal is tri_setup's when the triangle has a face; kept */
        p->nraw = nraw;
        p->apex = (uint8_t)apex;
        p->has_face = face_normal(nraw, nn, lmax, &p->n);
        p->ready = true;
    }
    /* (has_face: |nraw|^2 > 1e-30 and finite, so v3_unit_or_against's own expression) */
    if (p && p->has_face) n = p->n;
    else n = v3_unit_or_against(nraw, *d);
    if (v3_dot(n, *d) > 0.0f) n = v3_neg(n);
    hit->t = s;
    hit->depth = 0.0f;
    hit->normal = n;
    hit->point = v3_madd(*o, *d, s);
    return true;
}

/*
 * Watertight ray/triangle (Woop, Benthin, Wald 2013): the ray is sheared to +z and the
 * three edge functions are evaluated on the translated vertices. A shared edge is
 * evaluated from the same two vertices in both triangles, giving exactly negated values,
 * so a ray through the edge cannot slip between them.
 */
bool coll_ray_triangle(const fm_vec3_t *o, const fm_vec3_t *d, const fm_vec3_t tri[3],
                       float s_max, coll_prim_hit_t *hit)
{
    if (!o || !d || !tri || !hit) return false;
    coll_ray_shear_t sh;
    if (!coll_ray_shear(d, &sh)) return false;
    return ray_triangle_sheared_in(o, d, &sh, tri, s_max, NULL, hit);
}

bool coll_ray_triangle_sheared(const fm_vec3_t *o, const fm_vec3_t *d, const coll_ray_shear_t *sh,
                               const fm_vec3_t tri[3], float s_max, coll_tri_prep_t *p, coll_prim_hit_t *hit)
{
    return ray_triangle_sheared_in(o, d, sh, tri, s_max, p, hit);
}
