/* Soak harness: PRNG, deterministic trig, the random level generator (versions 1 and 2)
 * and loaded (baked, real) levels with their spawn points.
 * Generation is done in double with +-*÷ and sqrt only (no libm trig), so a seed gives
 * bit-identical levels on every IEEE platform (x86-64, big-endian MIPS under qemu). */
#include "soak_sim.h"

coll_query_stats_t soak_query_stats;
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* ------------------------------------------------------------------ PRNG */
uint64_t soak_mix64(uint64_t z)
{
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

void soak_rng_seed(soak_rng_t *r, uint64_t seed) { r->s = seed; }

uint64_t soak_rng_next(soak_rng_t *r)
{
    r->s += 0x9E3779B97F4A7C15ull;
    return soak_mix64(r->s);
}

double soak_rng_unit(soak_rng_t *r) { return (double)(soak_rng_next(r) >> 11) * (1.0 / 9007199254740992.0); }
double soak_rng_range(soak_rng_t *r, double a, double b) { return a + (b - a) * soak_rng_unit(r); }
uint32_t soak_rng_below(soak_rng_t *r, uint32_t n) { return n ? (uint32_t)((soak_rng_next(r) >> 32) % n) : 0; }
bool soak_rng_chance(soak_rng_t *r, double p) { return soak_rng_unit(r) < p; }

/* ------------------------------------------------------------------ trig */
#define SOAK_PI 3.14159265358979323846

/* Taylor series on |r| <= pi/4: error < 1e-16, and only exact IEEE operations. */
static double sin_poly(double r)
{
    double r2 = r * r, term = r, sum = r;
    for (int k = 1; k <= 9; k++) {
        term = -term * r2 / (double)((2 * k) * (2 * k + 1));
        sum += term;
    }
    return sum;
}
static double cos_poly(double r)
{
    double r2 = r * r, term = 1.0, sum = 1.0;
    for (int k = 1; k <= 9; k++) {
        term = -term * r2 / (double)((2 * k - 1) * (2 * k));
        sum += term;
    }
    return sum;
}
static void sincos_det(double x, double *s, double *c)
{
    double q = floor(x * (2.0 / SOAK_PI) + 0.5);
    double r = x - q * (SOAK_PI / 2.0);
    double sr = sin_poly(r), cr = cos_poly(r);
    long long qi = (long long)fmod(q, 4.0);
    if (qi < 0) qi += 4;
    switch (qi) {
    case 0: *s = sr; *c = cr; break;
    case 1: *s = cr; *c = -sr; break;
    case 2: *s = -sr; *c = -cr; break;
    default: *s = -cr; *c = sr; break;
    }
}
double soak_sin(double x) { double s, c; sincos_det(x, &s, &c); return s; }
double soak_cos(double x) { double s, c; sincos_det(x, &s, &c); return c; }

/* ------------------------------------------------------------------ small double helpers */
typedef struct { double x, y, z; } dv3;
typedef struct { double x, y, z, w; } dq;

static dv3 v3(double x, double y, double z) { dv3 r = {x, y, z}; return r; }
static dv3 v_add(dv3 a, dv3 b) { return v3(a.x + b.x, a.y + b.y, a.z + b.z); }
static dv3 v_sub(dv3 a, dv3 b) { return v3(a.x - b.x, a.y - b.y, a.z - b.z); }
static dv3 v_scale(dv3 a, double s) { return v3(a.x * s, a.y * s, a.z * s); }
static dv3 v_cross(dv3 a, dv3 b) { return v3(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x); }
static double v_len(dv3 a) { return sqrt(a.x * a.x + a.y * a.y + a.z * a.z); }

/* Random vector, components drawn in x, y, z order. (C leaves the evaluation order of
 * function arguments unspecified, and GCC on x86-64 and MIPS really differ: never draw
 * random numbers in two arguments of one call.) */
static dv3 rv3(soak_rng_t *r, double lx, double hx, double ly, double hy, double lz, double hz)
{
    dv3 v;
    v.x = soak_rng_range(r, lx, hx);
    v.y = soak_rng_range(r, ly, hy);
    v.z = soak_rng_range(r, lz, hz);
    return v;
}

static dq q_axis_angle(dv3 axis, double ang)
{
    double l = v_len(axis);
    double s = soak_sin(ang * 0.5), c = soak_cos(ang * 0.5);
    dq q = {axis.x / l * s, axis.y / l * s, axis.z / l * s, c};
    return q;
}
static dq q_mul(dq a, dq b)
{
    dq r = {a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y,
            a.w * b.y - a.x * b.z + a.y * b.w + a.z * b.x,
            a.w * b.z + a.x * b.y - a.y * b.x + a.z * b.w,
            a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z};
    return r;
}
static dq q_norm(dq q)
{
    double l = sqrt(q.x * q.x + q.y * q.y + q.z * q.z + q.w * q.w);
    dq r = {q.x / l, q.y / l, q.z / l, q.w / l};
    return r;
}
static dv3 q_rot(dq q, dv3 v)
{
    dv3 u = v3(q.x, q.y, q.z);
    dv3 t = v_scale(v_cross(u, v), 2.0);
    return v_add(v_add(v, v_scale(t, q.w)), v_cross(u, t));
}
static dv3 rand_unit(soak_rng_t *r)
{
    for (;;) {
        dv3 v = rv3(r, -1, 1, -1, 1, -1, 1);
        double l = v_len(v);
        if (l > 0.1 && l <= 1.0) return v_scale(v, 1.0 / l);
    }
}

/* ------------------------------------------------------------------ builder */
enum { K_ROOM, K_BOX, K_RAMP, K_STAIRS, K_WALL, K_VCORNER, K_SOUP, K_SLAB, K_OVERLAP, K_PLATFORM,
       /* generator version 2 (issue 12: real-world geometry) */
       K_CRACK, K_VSLOT, K_TILES, K_OVERHANG, K_STAIRS2 };

typedef struct {
    soak_level_t *l;
    soak_piece_t *p;
    int err;
    /* generator 2: the character this level's soak run uses (soak_settings_random from the
     * same level seed, as soak_main draws it), so cracks, slots and risers are sized
     * against its radius, step height and floor angle */
    double radius, step, max_angle_deg;
} bld_t;

static uint32_t b_vert(bld_t *b, dv3 v)
{
    soak_level_t *l = b->l;
    if (l->nverts >= SOAK_MAX_VERTS) { b->err = -2; return 0; }
    l->verts[l->nverts * 3 + 0] = (float)v.x;
    l->verts[l->nverts * 3 + 1] = (float)v.y;
    l->verts[l->nverts * 3 + 2] = (float)v.z;
    b->p->nverts++;
    return l->nverts++ - b->p->first_vert;
}
static void b_tri(bld_t *b, uint32_t i0, uint32_t i1, uint32_t i2)
{
    soak_level_t *l = b->l;
    if (l->ntris >= SOAK_MAX_TRIS) { b->err = -3; return; }
    l->idx[l->ntris * 3 + 0] = i0;
    l->idx[l->ntris * 3 + 1] = i1;
    l->idx[l->ntris * 3 + 2] = i2;
    l->ntris++;
    b->p->ntris++;
}
static void b_quad(bld_t *b, dv3 a, dv3 c1, dv3 c2, dv3 d)
{
    uint32_t i0 = b_vert(b, a), i1 = b_vert(b, c1), i2 = b_vert(b, c2), i3 = b_vert(b, d);
    b_tri(b, i0, i1, i2);
    b_tri(b, i0, i2, i3);
}
/* Axis-aligned (in piece space) box between lo and hi: 8 shared vertices, 12 triangles. */
static void b_box(bld_t *b, dv3 lo, dv3 hi)
{
    uint32_t i[8];
    for (int k = 0; k < 8; k++)
        i[k] = b_vert(b, v3((k & 1) ? hi.x : lo.x, (k & 2) ? hi.y : lo.y, (k & 4) ? hi.z : lo.z));
    static const uint8_t f[12][3] = {
        {0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6}, {0, 1, 5}, {0, 5, 4},
        {2, 6, 7}, {2, 7, 3}, {0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}};
    for (int k = 0; k < 12; k++) b_tri(b, i[f[k][0]], i[f[k][1]], i[f[k][2]]);
}
/* Flat grid of n x n quads at height y covering [-h, h]^2. */
static void b_grid(bld_t *b, double h, double y, int n, bool flip)
{
    uint32_t base = b_vert(b, v3(-h, y, -h));
    for (int k = 1; k < (n + 1) * (n + 1); k++) {
        int ix = k % (n + 1), iz = k / (n + 1);
        b_vert(b, v3(-h + 2 * h * ix / n, y, -h + 2 * h * iz / n));
    }
    for (int iz = 0; iz < n; iz++)
        for (int ix = 0; ix < n; ix++) {
            uint32_t a = base + (uint32_t)(iz * (n + 1) + ix);
            if (flip) { b_tri(b, a, a + 1, a + (uint32_t)n + 2); b_tri(b, a, a + (uint32_t)n + 2, a + (uint32_t)n + 1); }
            else      { b_tri(b, a, a + (uint32_t)n + 2, a + 1); b_tri(b, a, a + (uint32_t)n + 1, a + (uint32_t)n + 2); }
        }
}

static soak_piece_t *new_piece(soak_level_t *l, int kind)
{
    if (l->npieces >= SOAK_MAX_PIECES) return NULL;
    soak_piece_t *p = &l->pieces[l->npieces++];
    memset(p, 0, sizeof *p);
    p->first_vert = l->nverts;
    p->first_tri = l->ntris;
    p->kind = kind;
    p->base_rot[3] = 1.0f;
    p->inst.xf.rot.w = 1.0f;
    p->inst.xf.scale.x = p->inst.xf.scale.y = p->inst.xf.scale.z = 1.0f;
    p->inst.write_mask = 0x01;
    p->inst.id = (uint16_t)l->npieces; /* 1-based */
    return p;
}

static void gen_geometry(bld_t *b, soak_rng_t *r, int kind)
{
    switch (kind) {
    case K_BOX: {
        dv3 h = rv3(r, 0.1, 3, 0.1, 2.5, 0.1, 3);
        b_box(b, v3(-h.x, 0, -h.z), v3(h.x, 2 * h.y, h.z));
        break;
    }
    case K_SLAB: {
        dv3 h = rv3(r, 0.5, 4, 0.02, 0.4, 0.5, 4);
        b_box(b, v3(-h.x, -h.y, -h.z), h);
        break;
    }
    case K_RAMP: {
        double len = soak_rng_range(r, 1, 8), w = soak_rng_range(r, 0.8, 4);
        double ang = soak_rng_range(r, 5, 80) * (SOAK_PI / 180.0);
        double hgt = len * soak_sin(ang) / soak_cos(ang);
        if (hgt > 10) { hgt = 10; }
        dv3 a = v3(0, 0, -w / 2), c = v3(0, 0, w / 2), d = v3(len, 0, -w / 2), e = v3(len, 0, w / 2);
        dv3 f = v3(len, hgt, -w / 2), g = v3(len, hgt, w / 2);
        b_quad(b, a, c, g, f);              /* slope */
        b_quad(b, d, f, g, e);              /* back */
        b_quad(b, a, d, e, c);              /* bottom */
        uint32_t i0 = b_vert(b, a), i1 = b_vert(b, d), i2 = b_vert(b, f);
        b_tri(b, i0, i1, i2);
        i0 = b_vert(b, c); i1 = b_vert(b, g); i2 = b_vert(b, e);
        b_tri(b, i0, i1, i2);
        break;
    }
    case K_STAIRS: {
        int n = 2 + (int)soak_rng_below(r, 10);
        double tread = soak_rng_range(r, 0.2, 1.2), w = soak_rng_range(r, 0.8, 4), y = 0;
        double len = tread * n;
        for (int k = 0; k < n; k++) {
            y += soak_rng_range(r, 0.02, 0.7);
            b_box(b, v3(k * tread, 0, -w / 2), v3(len, y, w / 2));
        }
        break;
    }
    case K_WALL: {
        double w = soak_rng_range(r, 1, 8), h = soak_rng_range(r, 0.3, 6);
        if (soak_rng_chance(r, 0.5)) {
            b_quad(b, v3(-w / 2, 0, 0), v3(w / 2, 0, 0), v3(w / 2, h, 0), v3(-w / 2, h, 0));
        } else {
            double t = soak_rng_range(r, 0.003, 0.05);
            b_box(b, v3(-w / 2, 0, -t / 2), v3(w / 2, h, t / 2));
        }
        break;
    }
    case K_VCORNER: {
        double ang = soak_rng_range(r, 12, 170) * (SOAK_PI / 180.0);
        double l1 = soak_rng_range(r, 1.5, 6), l2 = soak_rng_range(r, 1.5, 6), h = soak_rng_range(r, 0.5, 6);
        dv3 d2 = v3(soak_cos(ang), 0, soak_sin(ang));
        b_quad(b, v3(0, 0, 0), v3(l1, 0, 0), v3(l1, h, 0), v3(0, h, 0));
        b_quad(b, v3(0, 0, 0), v3(0, h, 0), v_add(v3(0, h, 0), v_scale(d2, l2)), v_scale(d2, l2));
        if (soak_rng_chance(r, 0.5)) { /* close it with a floor wedge: a crease on the ground */
            uint32_t i0 = b_vert(b, v3(0, 0, 0)), i1 = b_vert(b, v3(l1, 0, 0)), i2 = b_vert(b, v_scale(d2, l2));
            b_tri(b, i0, i1, i2);
        }
        break;
    }
    /* ---- generator version 2 ---- */
    case K_CRACK: {
        /* two floor pieces (boxes, tops at hgt) with a crack between them, 0.5 cm .. 1.5 m
         * wide (skewed towards narrow: 1.5 x radius for radii 0.1 .. 1), sometimes with a
         * 1-20 mm height mismatch */
        double hgt = soak_rng_range(r, 0.03, 0.5), u = soak_rng_unit(r);
        double g = 0.005 + (1.5 * b->radius - 0.005) * u * u * u; /* 0.5 cm .. 1.5 r, mostly narrow */
        double l1 = soak_rng_range(r, 1, 5), l2 = soak_rng_range(r, 1, 5), w = soak_rng_range(r, 1.5, 6);
        double dh = soak_rng_chance(r, 0.3) ? soak_rng_range(r, 0.001, 0.02) : 0.0;
        if (soak_rng_chance(r, 0.5)) dh = -dh;
        b_box(b, v3(-g / 2 - l1, 0, -w / 2), v3(-g / 2, hgt, w / 2));
        b_box(b, v3(g / 2, 0, -w / 2), v3(g / 2 + l2, hgt + dh, w / 2));
        break;
    }
    case K_VSLOT: {
        /* a V valley: two walkable 35-44 degree slopes facing each other whose bottom
         * edges leave a 10-15 cm slot, y0 deep down to the room floor */
        /* walkable for this level's character: at most its floor angle - 1 degree */
        double amax = b->max_angle_deg - 1.0 < 44.0 ? b->max_angle_deg - 1.0 : 44.0;
        double amin = amax < 35.0 ? amax - 9.0 : 35.0;
        double a1 = soak_rng_range(r, amin, amax) * (SOAK_PI / 180.0), a2 = soak_rng_range(r, amin, amax) * (SOAK_PI / 180.0);
        double slot = soak_rng_range(r, 0.10, 0.15), y0 = soak_rng_range(r, 0.1, 0.6);
        double run = soak_rng_range(r, 1, 4), w = soak_rng_range(r, 1.5, 6);
        for (int side = 0; side < 2; side++) {
            double a = side ? a2 : a1, sg = side ? 1.0 : -1.0, x0 = sg * slot / 2, x1 = sg * (slot / 2 + run);
            double top = y0 + run * soak_sin(a) / soak_cos(a);
            dv3 p0 = v3(x0, y0, -w / 2), p1 = v3(x0, y0, w / 2), p2 = v3(x1, top, w / 2), p3 = v3(x1, top, -w / 2);
            dv3 q0 = v3(x0, 0, -w / 2), q1 = v3(x0, 0, w / 2), q2 = v3(x1, 0, w / 2), q3 = v3(x1, 0, -w / 2);
            b_quad(b, p0, p1, p2, p3);      /* slope */
            b_quad(b, q0, q1, p1, p0);      /* slot wall */
            b_quad(b, q3, q2, p2, p3);      /* back */
            b_quad(b, q0, p0, p3, q3);      /* ends */
            b_quad(b, q1, q2, p2, p1);
        }
        break;
    }
    case K_TILES: {
        /* modular floor tiles: nx x nz thin boxes with 0-2 cm gaps and 1-20 mm height
         * mismatches */
        int nx = 2 + (int)soak_rng_below(r, 5), nz = 2 + (int)soak_rng_below(r, 5);
        double ts = soak_rng_range(r, 0.5, 2), th = soak_rng_range(r, 0.02, 0.3);
        double gap = soak_rng_chance(r, 0.3) ? 0.0 : soak_rng_range(r, 0.002, 0.02);
        for (int iz = 0; iz < nz; iz++)
            for (int ix = 0; ix < nx; ix++) {
                double dh = soak_rng_chance(r, 0.5) ? soak_rng_range(r, 0.001, 0.02) : 0.0;
                if (soak_rng_chance(r, 0.5)) dh = -dh;
                double x0 = ix * (ts + gap), z0 = iz * (ts + gap);
                b_box(b, v3(x0, 0, z0), v3(x0 + ts, th + dh, z0 + ts));
            }
        break;
    }
    case K_OVERHANG: {
        if (soak_rng_chance(r, 0.5)) {
            /* a low ledge: a slab on a wall, its underside hc above the floor */
            double hc = soak_rng_range(r, 0.3, 2.5), t = soak_rng_range(r, 0.05, 0.4);
            double d = soak_rng_range(r, 0.5, 3), w = soak_rng_range(r, 1.5, 6);
            b_box(b, v3(-0.3, 0, -w / 2), v3(0, hc + t, w / 2));
            b_box(b, v3(0, hc, -w / 2), v3(d, hc + t, w / 2));
        } else {
            /* a single-sided ramp: one quad from the floor up at 8-40 degrees, nothing
             * under it: its low edge and the floor form an acute wedge */
            double ang = soak_rng_range(r, 8, 40) * (SOAK_PI / 180.0), len = soak_rng_range(r, 1, 5);
            double w = soak_rng_range(r, 1, 5), y0 = soak_rng_chance(r, 0.5) ? 0.0 : soak_rng_range(r, 0.001, 0.05);
            double hgt = y0 + len * soak_sin(ang);
            double run = len * soak_cos(ang);
            b_quad(b, v3(0, y0, -w / 2), v3(0, y0, w / 2), v3(run, hgt, w / 2), v3(run, hgt, -w / 2));
        }
        break;
    }
    case K_STAIRS2: {
        /* a regular staircase: treads 0.25-0.45 m, equal risers of 30-100 % of the step
         * height (5-35 cm when the step is under 2 cm) */
        int n = 3 + (int)soak_rng_below(r, 10);
        double tread = soak_rng_range(r, 0.25, 0.45);
        double rise = b->step >= 0.02 ? soak_rng_range(r, 0.3, 1.0) * b->step : soak_rng_range(r, 0.05, 0.35);
        double w = soak_rng_range(r, 1, 4), len = tread * n;
        for (int k = 0; k < n; k++) b_box(b, v3(k * tread, 0, -w / 2), v3(len, (k + 1) * rise, w / 2));
        break;
    }
    case K_SOUP: {
        int n = 5 + (int)soak_rng_below(r, 36);
        double ext = soak_rng_range(r, 1, 4);
        for (int k = 0; k < n; k++) {
            dv3 p[3];
            for (int tries = 0; tries < 50; tries++) {
                for (int j = 0; j < 3; j++)
                    p[j] = rv3(r, -ext, ext, 0, 2 * ext, -ext, ext);
                dv3 c = v_cross(v_sub(p[1], p[0]), v_sub(p[2], p[0]));
                double la = v_len(v_sub(p[1], p[0])), lb = v_len(v_sub(p[2], p[0])), lc = v_len(v_sub(p[2], p[1]));
                double mx = la > lb ? (la > lc ? la : lc) : (lb > lc ? lb : lc);
                /* no slivers: area relative to the longest edge must be sizeable */
                if (v_len(c) > 0.02 && v_len(c) / (mx * mx) > 0.05) break;
            }
            uint32_t i0 = b_vert(b, p[0]), i1 = b_vert(b, p[1]), i2 = b_vert(b, p[2]);
            b_tri(b, i0, i1, i2);
        }
        break;
    }
    default:
        break;
    }
}

static void set_xf(soak_piece_t *p, dv3 pos, dq rot, dv3 scale)
{
    p->inst.xf.pos.x = (float)pos.x; p->inst.xf.pos.y = (float)pos.y; p->inst.xf.pos.z = (float)pos.z;
    p->inst.xf.rot.x = (float)rot.x; p->inst.xf.rot.y = (float)rot.y;
    p->inst.xf.rot.z = (float)rot.z; p->inst.xf.rot.w = (float)rot.w;
    p->inst.xf.scale.x = (float)scale.x; p->inst.xf.scale.y = (float)scale.y; p->inst.xf.scale.z = (float)scale.z;
}

static dq fq(const fm_quat_t *q) { dq r = {q->x, q->y, q->z, q->w}; return r; }

static int build_mesh(soak_level_t *l, soak_piece_t *p)
{
    size_t need = coll_mesh_build_size(p->nverts, p->ntris, NULL);
    size_t off = (l->pool_used + 15u) & ~(size_t)15u;
    if (need == 0 || off + need > SOAK_POOL_BYTES) return -4;
    const coll_mesh_t *m = NULL;
    coll_err_t e = coll_mesh_build(l->pool + off, need, l->verts + (size_t)p->first_vert * 3, p->nverts,
                                   l->idx + (size_t)p->first_tri * 3, p->ntris, NULL, &m);
    if (e != COLL_OK || !m) return -5;
    l->pool_used = off + need;
    p->inst.mesh = m;
    double rad = 0;
    for (uint32_t k = 0; k < p->nverts; k++) {
        const float *v = l->verts + (size_t)(p->first_vert + k) * 3;
        double d = sqrt((double)v[0] * v[0] + (double)v[1] * v[1] + (double)v[2] * v[2]);
        if (d > rad) rad = d;
    }
    p->bound_radius = rad;
    return 0;
}

/* A world triangle's bounding sphere: centroid and the farthest corner from it. */
static void wtri_bound(soak_wtri_t *w)
{
    double c[3], rad = 0;
    for (int k = 0; k < 3; k++) c[k] = (w->v[0][k] + w->v[1][k] + w->v[2][k]) / 3.0;
    for (int j = 0; j < 3; j++) {
        double d = sqrt((w->v[j][0] - c[0]) * (w->v[j][0] - c[0]) + (w->v[j][1] - c[1]) * (w->v[j][1] - c[1]) +
                        (w->v[j][2] - c[2]) * (w->v[j][2] - c[2]));
        if (d > rad) rad = d;
    }
    memcpy(w->c, c, sizeof c);
    w->rad = rad;
}

#define SOAK_FLIP_MAX_TRIS 32

/* Local position of vertex j of the piece's triangle t. */
static const float *tri_vert(const soak_level_t *l, const soak_piece_t *p, uint32_t t, int j)
{
    return l->verts + (size_t)(p->first_vert + l->idx[(p->first_tri + t) * 3 + (uint32_t)j]) * 3;
}
static bool same_pos(const float *a, const float *b) { return a[0] == b[0] && a[1] == b[1] && a[2] == b[2]; }

/* A piece of at most SOAK_FLIP_MAX_TRIS triangles whose every edge (by position) is shared
 * by exactly one other of its triangles, which can be wound consistently: true, with
 * flip[t] set for the triangles to turn over so that all face out (positive volume).
 * A piece standing upright on the room floor (on_floor: its local y = 0 is the floor's
 * plane) may leave edges in that plane open, the floor closing the solid, and may be
 * several such shells, each wound out by its own volume: a V valley's two wedges (slope,
 * slot wall, back and ends, no bottom face: soak s31 l310). The volume is taken about the
 * local origin, which lies in the floor's plane, so the missing bottom adds nothing. */
static bool orient_by_position(const soak_level_t *l, const soak_piece_t *p, bool on_floor, bool *flip, bool *by_floor)
{
    *by_floor = false;
    const uint32_t n = p->ntris;
    if (n < 4 || n > SOAK_FLIP_MAX_TRIS) return false;
    int nb[SOAK_FLIP_MAX_TRIS][3];
    bool same[SOAK_FLIP_MAX_TRIS][3]; /* the neighbour has the edge in the same direction */
    for (uint32_t t = 0; t < n; t++)
        for (int j = 0; j < 3; j++) {
            const float *a = tri_vert(l, p, t, j), *b = tri_vert(l, p, t, (j + 1) % 3);
            int found = 0;
            for (uint32_t u = 0; u < n; u++) {
                if (u == t) continue;
                for (int k = 0; k < 3; k++) {
                    const float *c = tri_vert(l, p, u, k), *d = tri_vert(l, p, u, (k + 1) % 3);
                    bool fw = same_pos(a, c) && same_pos(b, d), bw = same_pos(a, d) && same_pos(b, c);
                    if (fw || bw) { found++; nb[t][j] = (int)u; same[t][j] = fw; }
                }
            }
            if (found == 0 && on_floor && a[1] == 0.0f && b[1] == 0.0f) {
                nb[t][j] = -1; /* closed by the floor */
                same[t][j] = false;
                *by_floor = true;
            }
            else if (found != 1) return false;
        }
    /* flood the orientation from a triangle of each shell (one shell unless on_floor) */
    int state[SOAK_FLIP_MAX_TRIS], shell[SOAK_FLIP_MAX_TRIS], stack[SOAK_FLIP_MAX_TRIS], sp = 0, nshell = 0;
    for (uint32_t t = 0; t < n; t++) state[t] = -1;
    for (uint32_t t0 = 0; t0 < n; t0++) {
        if (state[t0] >= 0) continue;
        if (nshell > 0 && !on_floor) return false; /* more than one shell */
        state[t0] = 0;
        shell[t0] = nshell;
        stack[sp++] = (int)t0;
        while (sp > 0) {
            int t = stack[--sp];
            for (int j = 0; j < 3; j++) {
                int u = nb[t][j];
                if (u < 0) continue; /* an edge on the floor: no neighbour, no orientation to pass on */
                int want = state[t] ^ (same[t][j] ? 1 : 0);
                if (state[u] < 0) { state[u] = want; shell[u] = nshell; stack[sp++] = u; }
                else if (state[u] != want) return false; /* not orientable */
            }
        }
        nshell++;
    }
    double vol[SOAK_FLIP_MAX_TRIS] = {0};
    for (uint32_t t = 0; t < n; t++) {
        const float *a = tri_vert(l, p, t, 0), *b = tri_vert(l, p, t, 1), *c = tri_vert(l, p, t, 2);
        double v = (double)a[0] * ((double)b[1] * c[2] - (double)b[2] * c[1]) -
                   (double)a[1] * ((double)b[0] * c[2] - (double)b[2] * c[0]) +
                   (double)a[2] * ((double)b[0] * c[1] - (double)b[1] * c[0]);
        vol[shell[t]] += state[t] ? -v : v;
    }
    for (int k = 0; k < nshell; k++)
        if (!(fabs(vol[k]) > 1e-9)) return false;
    for (uint32_t t = 0; t < n; t++) flip[t] = (state[t] != 0) != (vol[shell[t]] < 0);
    if (nshell > 1) *by_floor = true;
    return true;
}

/* World-space double copy of a static piece's triangles (the checker's data). */
static void world_tris(soak_level_t *l, const soak_piece_t *p)
{
    dq q = fq(&p->inst.xf.rot);
    dv3 pos = v3(p->inst.xf.pos.x, p->inst.xf.pos.y, p->inst.xf.pos.z);
    dv3 sc = v3(p->inst.xf.scale.x, p->inst.xf.scale.y, p->inst.xf.scale.z);
    /* closed: every directed edge (a, b) of the piece met exactly once as (b, a) and once
     * as itself (shared vertices: boxes, tile fields); quads of their own vertices are not */
    const uint32_t *ix = l->idx + (size_t)p->first_tri * 3;
    bool closed = p->ntris > 0;
    for (uint32_t t = 0; t < p->ntris && closed; t++)
        for (int j = 0; j < 3 && closed; j++) {
            uint32_t a = ix[t * 3 + (uint32_t)j], b = ix[t * 3 + (uint32_t)(j + 1) % 3];
            int same = 0, rev = 0;
            for (uint32_t u = 0; u < p->ntris; u++)
                for (int k = 0; k < 3; k++) {
                    uint32_t c = ix[u * 3 + (uint32_t)k], d = ix[u * 3 + (uint32_t)(k + 1) % 3];
                    same += c == a && d == b;
                    rev += c == b && d == a;
                }
            closed = same == 1 && rev == 1;
        }
    /* Not closed by its indices: a solid built of quads with vertices of their own and its
     * sides wound the other way (the ramp: soak s9 l185) is still closed when every edge,
     * by position, is shared by exactly two of its triangles: the checker's copy is then
     * wound consistently, outwards (flip[t]: its second and third vertices swapped). */
    bool flip[SOAK_FLIP_MAX_TRIS] = {false};
    /* standing upright on the room floor (the real-world shapes: unscaled, a yaw only) */
    const bool on_floor = pos.y == 0.0 && q.x == 0.0 && q.z == 0.0 && sc.x == 1.0 && sc.y == 1.0 && sc.z == 1.0;
    bool by_floor = false;
    if (!closed) closed = orient_by_position(l, p, on_floor, flip, &by_floor);
    /* a mirroring scale turns the winding inside out */
    if (sc.x * sc.y * sc.z < 0) closed = false;
    for (uint32_t t = 0; t < p->ntris && l->nwtris < SOAK_MAX_TRIS; t++) {
        soak_wtri_t *w = &l->wtris[l->nwtris++];
        for (int jj = 0; jj < 3; jj++) {
            /* (closed by the floor: the vertex order kept, the winding in `closed`, 2 for a
             * triangle whose back face is the outside; the soak's teleport targets are picked
             * on these triangles, and the runs stay those of before) */
            const int j = closed && !by_floor && t < SOAK_FLIP_MAX_TRIS && flip[t] && jj > 0 ? 3 - jj : jj;
            const float *v = l->verts + (size_t)(p->first_vert + l->idx[(p->first_tri + t) * 3 + (uint32_t)j]) * 3;
            dv3 lv = v3((double)v[0] * sc.x, (double)v[1] * sc.y, (double)v[2] * sc.z);
            dv3 wv = v_add(pos, q_rot(q, lv));
            w->v[jj][0] = wv.x; w->v[jj][1] = wv.y; w->v[jj][2] = wv.z;
        }
        wtri_bound(w);
        w->mask = p->inst.write_mask;
        w->closed = (uint8_t)(!closed ? 0 : by_floor && t < SOAK_FLIP_MAX_TRIS && flip[t] ? 2 : 1);
    }
}

int soak_level_generate(soak_level_t *l, uint64_t seed) { return soak_level_generate_v(l, seed, SOAK_GEN_V1); }

int soak_level_generate_v(soak_level_t *l, uint64_t seed, int gen)
{
    soak_rng_t r;
    if (gen < SOAK_GEN_V1 || gen > SOAK_GEN_CURRENT) return -8;
    soak_rng_seed(&r, soak_mix64(seed ^ 0x5EEDF00Dull));
    l->seed = seed;
    l->gen = gen;
    l->loaded = false;
    l->file[0] = 0;
    l->wtris = l->wtris_store;
    l->npieces = l->nbodies = l->nverts = l->ntris = l->nwtris = 0;
    l->pool_used = 0;
    coll_scene_init(&l->scene);
    coll_scene_set_stats(&l->scene, &soak_query_stats);
    bld_t b = {l, NULL, 0, 0.5, 0.25, 45.0};
    if (gen >= 2) {
        soak_rng_t sr;
        soak_rng_seed(&sr, soak_mix64(seed ^ 0x5E77ull)); /* soak_main's settings stream */
        char_body_settings_t hint;
        fm_vec3_t unused;
        soak_settings_random(&sr, &hint, &unused);
        b.radius = hint.radius;
        b.step = hint.step_height;
        b.max_angle_deg = (double)hint.floor_max_angle * (180.0 / SOAK_PI);
    }
    const double H = SOAK_ROOM_HALF, Y = SOAK_ROOM_HEIGHT;

    /* The room: floor grid (the lowest floor), four walls and a ceiling. Closed, so the
     * body can never legitimately leave it whatever its up vector. */
    b.p = new_piece(l, K_ROOM);
    b_grid(&b, H, 0.0, 6, false);
    b_grid(&b, H, Y, 2, true);
    b_quad(&b, v3(-H, 0, -H), v3(H, 0, -H), v3(H, Y, -H), v3(-H, Y, -H));
    b_quad(&b, v3(-H, 0, H), v3(-H, Y, H), v3(H, Y, H), v3(H, 0, H));
    b_quad(&b, v3(-H, 0, -H), v3(-H, Y, -H), v3(-H, Y, H), v3(-H, 0, H));
    b_quad(&b, v3(H, 0, -H), v3(H, 0, H), v3(H, Y, H), v3(H, Y, -H));
    if (b.err || build_mesh(l, b.p)) return -1;

    /* Static clutter */
    int nstatic = 8 + (int)soak_rng_below(&r, 22);
    for (int i = 0; i < nstatic; i++) {
        static const int kinds[] = {K_BOX, K_BOX, K_RAMP, K_RAMP, K_STAIRS, K_STAIRS, K_WALL,
                                    K_VCORNER, K_VCORNER, K_SOUP, K_SLAB, K_OVERLAP};
        /* version 2: half of the pieces are the real-world shapes of issue 12 */
        static const int kinds2[] = {K_BOX, K_RAMP, K_STAIRS, K_WALL, K_VCORNER, K_SOUP, K_SLAB, K_OVERLAP,
                                     K_CRACK, K_CRACK, K_VSLOT, K_VSLOT, K_TILES, K_TILES, K_OVERHANG,
                                     K_OVERHANG, K_STAIRS2, K_STAIRS2};
        int kind = gen >= 2 ? kinds2[soak_rng_below(&r, (uint32_t)(sizeof kinds2 / sizeof kinds2[0]))]
                            : kinds[soak_rng_below(&r, (uint32_t)(sizeof kinds / sizeof kinds[0]))];
        soak_piece_t *prev = l->npieces > 1 ? &l->pieces[l->npieces - 1] : NULL;
        if (kind == K_OVERLAP && (!prev || prev->kind == K_ROOM)) kind = K_BOX;
        b.p = new_piece(l, kind);
        if (!b.p) break;
        dv3 pos = rv3(&r, -H + 2, H - 2, 0, 0, -H + 2, H - 2);
        dq rot = q_axis_angle(v3(0, 1, 0), soak_rng_range(&r, 0, 2 * SOAK_PI));
        dv3 sc = v3(1, 1, 1);
        if (kind == K_OVERLAP) {
            /* same geometry as the previous piece: exactly coplanar, or a hair off */
            uint32_t fv = l->nverts;
            for (uint32_t k = 0; k < prev->nverts * 3; k++) {
                if (l->nverts >= SOAK_MAX_VERTS) { b.err = -2; break; }
                l->verts[fv * 3 + k] = l->verts[prev->first_vert * 3 + k];
                if (k % 3 == 2) l->nverts++;
            }
            b.p->nverts = prev->nverts;
            for (uint32_t k = 0; k < prev->ntris * 3 && l->ntris < SOAK_MAX_TRIS; k++) {
                l->idx[l->ntris * 3 + (k % 3)] = l->idx[prev->first_tri * 3 + k];
                if (k % 3 == 2) { l->ntris++; b.p->ntris++; }
            }
            pos = v3(prev->inst.xf.pos.x, prev->inst.xf.pos.y, prev->inst.xf.pos.z);
            rot = fq(&prev->inst.xf.rot);
            sc = v3(prev->inst.xf.scale.x, prev->inst.xf.scale.y, prev->inst.xf.scale.z);
            uint32_t mode = soak_rng_below(&r, 3);
            if (mode == 1) pos = v_add(pos, rv3(&r, -0.01, 0.01, 0, 0.002, -0.01, 0.01));
            if (mode == 2) rot = q_mul(rot, q_axis_angle(v3(0, 1, 0), soak_rng_range(&r, 0.1, 1.5)));
        } else if (kind >= K_CRACK) {
            /* real-world shapes stand on the room floor, upright, unscaled (a random yaw) */
            gen_geometry(&b, &r, kind);
        } else {
            gen_geometry(&b, &r, kind);
            if (kind == K_SLAB || kind == K_SOUP || soak_rng_chance(&r, 0.15))
                pos.y = soak_rng_range(&r, 0.05, kind == K_SLAB ? 8.0 : 5.0);
            if (soak_rng_chance(&r, 0.15)) {
                dv3 ax = rand_unit(&r);
                rot = q_mul(rot, q_axis_angle(ax, soak_rng_range(&r, 0, SOAK_PI)));
            }
            if (soak_rng_chance(&r, 0.25))
                sc = rv3(&r, 0.5, 2, 0.5, 2, 0.5, 2);
            if (soak_rng_chance(&r, 0.08)) b.p->inst.write_mask = 0x02; /* another layer */
        }
        set_xf(b.p, pos, q_norm(rot), sc);
        if (b.err || build_mesh(l, b.p)) return -1;
    }
    for (uint32_t i = 0; i < l->npieces; i++) world_tris(l, &l->pieces[i]);

    /* Moving platforms (not in the static checker set) */
    int nmoving = (int)soak_rng_below(&r, 5);
    for (int i = 0; i < nmoving; i++) {
        int kind = soak_rng_chance(&r, 0.7) ? K_SLAB : (soak_rng_chance(&r, 0.5) ? K_RAMP : K_BOX);
        b.p = new_piece(l, kind);
        if (!b.p) break;
        gen_geometry(&b, &r, kind);
        soak_piece_t *p = b.p;
        p->moving = true;
        p->kind = K_PLATFORM;
        dv3 pos = rv3(&r, -H + 4, H - 4, 0.2, 8, -H + 4, H - 4);
        dq rot = q_axis_angle(v3(0, 1, 0), soak_rng_range(&r, 0, 2 * SOAK_PI));
        p->base_pos[0] = (float)pos.x; p->base_pos[1] = (float)pos.y; p->base_pos[2] = (float)pos.z;
        p->base_rot[0] = (float)rot.x; p->base_rot[1] = (float)rot.y; p->base_rot[2] = (float)rot.z; p->base_rot[3] = (float)rot.w;
        dv3 md = soak_rng_chance(&r, 0.3) ? v3(0, 1, 0) : rand_unit(&r);
        p->move_dir[0] = (float)md.x; p->move_dir[1] = (float)md.y; p->move_dir[2] = (float)md.z;
        p->move_amp = soak_rng_chance(&r, 0.8) ? soak_rng_range(&r, 0.3, 4) : 0;
        p->move_omega = soak_rng_range(&r, 0.2, 2.5);
        p->move_phase = soak_rng_range(&r, 0, 2 * SOAK_PI);
        dv3 ra = soak_rng_chance(&r, 0.7) ? v3(0, 1, 0) : rand_unit(&r);
        p->rot_axis[0] = (float)ra.x; p->rot_axis[1] = (float)ra.y; p->rot_axis[2] = (float)ra.z;
        p->rot_omega = soak_rng_chance(&r, 0.5) ? soak_rng_range(&r, -1.5, 1.5) : 0;
        p->scale_amp = soak_rng_chance(&r, 0.3) ? soak_rng_range(&r, 0.05, 0.45) : 0;
        p->scale_omega = soak_rng_range(&r, 0.2, 2);
        set_xf(p, pos, rot, v3(1, 1, 1));
        if (b.err || build_mesh(l, p)) return -1;
    }

    /* Collider bodies */
    int nb = (int)soak_rng_below(&r, SOAK_MAX_BODIES - 1);
    for (int i = 0; i < nb; i++) {
        soak_lbody_t *lb = &l->bodies[l->nbodies++];
        memset(lb, 0, sizeof *lb);
        coll_body_t *bd = &lb->body;
        bd->shape = (coll_shape_t)soak_rng_below(&r, 4);
        bd->half_extents.x = (float)soak_rng_range(&r, 0.2, 2);
        bd->half_extents.y = (float)soak_rng_range(&r, 0.2, 2);
        bd->half_extents.z = (float)soak_rng_range(&r, 0.2, 2);
        dv3 pos = rv3(&r, -H + 3, H - 3, 0, 6, -H + 3, H - 3);
        dv3 ax = soak_rng_chance(&r, 0.7) ? v3(0, 1, 0) : rand_unit(&r);
        dq rot = q_axis_angle(ax, soak_rng_range(&r, 0, 2 * SOAK_PI));
        bd->xf.pos.x = (float)pos.x; bd->xf.pos.y = (float)pos.y; bd->xf.pos.z = (float)pos.z;
        bd->xf.rot.x = (float)rot.x; bd->xf.rot.y = (float)rot.y; bd->xf.rot.z = (float)rot.z; bd->xf.rot.w = (float)rot.w;
        bd->xf.scale.x = bd->xf.scale.y = bd->xf.scale.z = 1.0f;
        bd->write_mask = 0x01;
        bd->id = (uint16_t)(100 + i);
        lb->base_pos[0] = bd->xf.pos.x; lb->base_pos[1] = bd->xf.pos.y; lb->base_pos[2] = bd->xf.pos.z;
        if (soak_rng_chance(&r, 0.25)) {
            dv3 md = rand_unit(&r);
            lb->moving = true;
            lb->move_dir[0] = (float)md.x; lb->move_dir[1] = (float)md.y; lb->move_dir[2] = (float)md.z;
            lb->move_amp = soak_rng_range(&r, 0.3, 3);
            lb->move_omega = soak_rng_range(&r, 0.2, 2);
        }
    }

    for (uint32_t i = 0; i < l->npieces; i++)
        if (coll_scene_add_mesh(&l->scene, &l->pieces[i].inst) != COLL_OK) return -6;
    for (uint32_t i = 0; i < l->nbodies; i++)
        if (coll_scene_add_body(&l->scene, &l->bodies[i].body) != COLL_OK) return -7;
    soak_level_animate(l, 0.0);
    return 0;
}

void soak_level_animate(soak_level_t *l, double t)
{
    for (uint32_t i = 0; i < l->npieces; i++) {
        soak_piece_t *p = &l->pieces[i];
        if (!p->moving) continue;
        double s = soak_sin(p->move_omega * t + p->move_phase) * p->move_amp;
        dv3 pos = v3(p->base_pos[0] + p->move_dir[0] * s, p->base_pos[1] + p->move_dir[1] * s,
                     p->base_pos[2] + p->move_dir[2] * s);
        dq base = {p->base_rot[0], p->base_rot[1], p->base_rot[2], p->base_rot[3]};
        dq rot = q_norm(q_mul(base, q_axis_angle(v3(p->rot_axis[0], p->rot_axis[1], p->rot_axis[2]), p->rot_omega * t)));
        double sc = 1.0 + p->scale_amp * soak_sin(p->scale_omega * t);
        set_xf(p, pos, rot, v3(sc, sc, sc));
    }
    for (uint32_t i = 0; i < l->nbodies; i++) {
        soak_lbody_t *lb = &l->bodies[i];
        if (!lb->moving) continue;
        double s = soak_sin(lb->move_omega * t) * lb->move_amp;
        lb->body.xf.pos.x = (float)(lb->base_pos[0] + lb->move_dir[0] * s);
        lb->body.xf.pos.y = (float)(lb->base_pos[1] + lb->move_dir[1] * s);
        lb->body.xf.pos.z = (float)(lb->base_pos[2] + lb->move_dir[2] * s);
    }
}

static uint64_t fnv_u32(uint64_t h, uint32_t v)
{
    for (int k = 0; k < 4; k++) { h ^= (v >> (8 * k)) & 0xFFu; h *= 0x100000001B3ull; }
    return h;
}
static uint64_t fnv_f(uint64_t h, float f) { uint32_t u; memcpy(&u, &f, 4); return fnv_u32(h, u); }

uint64_t soak_level_hash(const soak_level_t *l)
{
    uint64_t h = 0xCBF29CE484222325ull;
    h = fnv_u32(h, l->npieces); h = fnv_u32(h, l->nbodies);
    for (uint32_t i = 0; i < l->nverts * 3; i++) h = fnv_f(h, l->verts[i]);
    for (uint32_t i = 0; i < l->ntris * 3; i++) h = fnv_u32(h, l->idx[i]);
    for (uint32_t i = 0; i < l->npieces; i++) {
        const soak_piece_t *p = &l->pieces[i];
        for (int k = 0; k < 3; k++) h = fnv_f(h, p->inst.xf.pos.v[k]);
        for (int k = 0; k < 4; k++) h = fnv_f(h, p->inst.xf.rot.v[k]);
        for (int k = 0; k < 3; k++) h = fnv_f(h, p->inst.xf.scale.v[k]);
        h = fnv_u32(h, p->inst.write_mask);
        h = fnv_u32(h, p->moving);
    }
    for (uint32_t i = 0; i < l->nbodies; i++) {
        const coll_body_t *b = &l->bodies[i].body;
        h = fnv_u32(h, (uint32_t)b->shape);
        for (int k = 0; k < 3; k++) h = fnv_f(h, b->half_extents.v[k]);
        for (int k = 0; k < 3; k++) h = fnv_f(h, b->xf.pos.v[k]);
        for (int k = 0; k < 4; k++) h = fnv_f(h, b->xf.rot.v[k]);
    }
    return h;
}

/* ------------------------------------------------------------------ settings */
void soak_settings_random(soak_rng_t *r, char_body_settings_t *s, fm_vec3_t *start)
{
    *s = CHAR_BODY_SETTINGS_DEFAULT;
    double rad = soak_rng_range(r, 0.1, 1.0);
    double height = soak_rng_range(r, 2 * rad, 4.0);
    if (height < 2 * rad) height = 2 * rad;
    double inner = height / 2 - rad;
    double ang = soak_rng_range(r, 20, 70) * (SOAK_PI / 180.0);
    /* The seed's rule: the sweep capsule must clear walkable slopes when the foot stands on
     * them, i.e. step >= r (1 / cos(angle) - 1). Most levels keep it (strict checks); the
     * rest break it on purpose (the checker then tolerates exactly that much on slopes). */
    double lo = rad * (1.0 / soak_cos(ang) - 1.0);
    double step;
    if (soak_rng_chance(r, 0.75) && lo <= inner)
        {
        double u1 = soak_rng_unit(r);
        double u2 = soak_rng_unit(r);
        step = lo + (inner - lo) * u1 * u2;
    }
    else
        step = soak_rng_chance(r, 0.1) ? 0.0 : soak_rng_range(r, 0, inner);
    double snap = step + (soak_rng_chance(r, 0.2) ? 0.0 : soak_rng_range(r, 0, 0.5));
    s->radius = (float)rad;
    s->height = (float)height;
    s->step_height = (float)step;
    s->floor_snap_distance = (float)snap;
    s->floor_max_angle = (float)ang;
    s->max_slides = (uint8_t)(1 + soak_rng_below(r, 8));
    s->gravity = (float)soak_rng_range(r, 5, 60);
    s->max_fall_speed = (float)soak_rng_range(r, 10, 80);
    s->follow_floor = !soak_rng_chance(r, 0.2);
    s->coll_types = soak_rng_chance(r, 0.3) ? COLL_TYPE_ALL : COLL_TYPE_MESH;
    s->read_mask = soak_rng_chance(r, 0.7) ? 0x01 : (soak_rng_chance(r, 0.5) ? 0x03 : 0xFF);
    if (soak_rng_chance(r, 0.5)) { /* capsule bottom at the owner origin */
        s->center_offset.x = 0.0f; s->center_offset.y = (float)(height / 2); s->center_offset.z = 0.0f;
    }
    /* start: capsule wholly inside the room (it may be inside clutter) */
    double m = height / 2 + 0.1;
    start->x = (float)(soak_rng_range(r, -SOAK_ROOM_HALF + m, SOAK_ROOM_HALF - m) - s->center_offset.x);
    start->y = (float)(soak_rng_range(r, m, 10) - s->center_offset.y);
    start->z = (float)(soak_rng_range(r, -SOAK_ROOM_HALF + m, SOAK_ROOM_HALF - m) - s->center_offset.z);
}

/* ------------------------------------------------------------------ loaded (real) levels */

static uint32_t le32(const unsigned char *p)
{
    return (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 | (uint32_t)p[3] << 24;
}

static unsigned char *read_all(const char *path, size_t *n)
{
    FILE *f = fopen(path, "rb");
    if (!f) return NULL;
    size_t cap = 1 << 16, len = 0;
    unsigned char *buf = NULL;
    if (posix_memalign((void **)&buf, 16, cap) != 0) { fclose(f); return NULL; }
    for (;;) {
        if (len == cap) {
            unsigned char *nb = NULL;
            if (posix_memalign((void **)&nb, 16, cap * 2) != 0) { free(buf); fclose(f); return NULL; }
            memcpy(nb, buf, len);
            free(buf);
            buf = nb;
            cap *= 2;
        }
        size_t got = fread(buf + len, 1, cap - len, f);
        len += got;
        if (got == 0) break;
    }
    int bad = ferror(f);
    fclose(f);
    if (bad) { free(buf); return NULL; }
    *n = len;
    return buf;
}

int soak_level_load(soak_level_t *l, const char *blob_path, const char *raw_path, char *err, size_t errlen)
{
    static unsigned char *blob;      /* kept for the life of the program (the mesh lives in it) */
    static soak_wtri_t *tris;
    size_t nb = 0, nr = 0;
    free(blob); blob = NULL;
    free(tris); tris = NULL;
    l->loaded = false;
    blob = read_all(blob_path, &nb);
    if (!blob) { snprintf(err, errlen, "ERROR: %s: cannot read", blob_path); return -1; }
    const coll_mesh_t *m = NULL;
    coll_err_t e = coll_mesh_load(blob, nb, &m);
    if (e != COLL_OK) { snprintf(err, errlen, "ERROR: %s: does not load: %s", blob_path, coll_strerror(e)); return -2; }
    unsigned char *raw = read_all(raw_path, &nr);
    if (!raw) { snprintf(err, errlen, "ERROR: %s: cannot read (collbake --dump-raw)", raw_path); return -3; }
    if (nr < 16 || memcmp(raw, "CRAW", 4) != 0 || le32(raw + 4) != 1) {
        free(raw); snprintf(err, errlen, "ERROR: %s: not a CRAW v1 file", raw_path); return -4;
    }
    uint32_t nv = le32(raw + 8), nt = le32(raw + 12);
    if (nv > 0x10000000u || nt > 0x10000000u || nr != 16 + (size_t)nv * 12 + (size_t)nt * 12) {
        free(raw); snprintf(err, errlen, "ERROR: %s: truncated or bad counts", raw_path); return -5;
    }
    tris = malloc((size_t)(nt ? nt : 1) * sizeof *tris);
    if (!tris) { free(raw); snprintf(err, errlen, "ERROR: out of memory"); return -6; }
    for (int k = 0; k < 3; k++) { l->lo[k] = 1e300; l->hi[k] = -1e300; }
    for (uint32_t t = 0; t < nt; t++) {
        soak_wtri_t *w = &tris[t];
        for (int j = 0; j < 3; j++) {
            uint32_t vi = le32(raw + 16 + (size_t)nv * 12 + ((size_t)t * 3 + (size_t)j) * 4);
            if (vi >= nv) { free(raw); snprintf(err, errlen, "ERROR: %s: bad index", raw_path); return -7; }
            for (int k = 0; k < 3; k++) {
                uint32_t u = le32(raw + 16 + ((size_t)vi * 3 + (size_t)k) * 4);
                float f;
                memcpy(&f, &u, 4);
                w->v[j][k] = f;
                if (f < l->lo[k]) l->lo[k] = f;
                if (f > l->hi[k]) l->hi[k] = f;
            }
        }
        wtri_bound(w);
        w->mask = 0x01;
        w->closed = 0; /* a map's solids are not known: every face counts either way */
    }
    free(raw);
    l->npieces = l->nbodies = l->nverts = l->ntris = 0;
    l->pool_used = 0;
    l->gen = 0;
    coll_scene_init(&l->scene);
    coll_scene_set_stats(&l->scene, &soak_query_stats);
    soak_piece_t *p = new_piece(l, K_ROOM);
    p->inst.mesh = m;
    p->bound_radius = 0;
    l->wtris = tris;
    l->nwtris = nt;
    if (coll_scene_add_mesh(&l->scene, &p->inst) != COLL_OK) { snprintf(err, errlen, "ERROR: scene full"); return -8; }
    snprintf(l->file, sizeof l->file, "%s", blob_path);
    l->loaded = true;
    return 0;
}

/* Candidate floor points of a loaded level: on upward-facing triangles of at least
 * 0.25 m^2, under a roof (some triangle straight above: a ceiling or the sky's brushes, so
 * not on the top of the map's outer shell). Found once per level (a fixed sequence). */
#define SPAWN_CANDIDATES 512
static struct { char file[256]; uint32_t n; double p[SPAWN_CANDIDATES][3]; } g_spawn;

static bool roofed(const soak_level_t *l, const double x[3])
{
    for (uint32_t i = 0; i < l->nwtris; i++) {
        const soak_wtri_t *t = &l->wtris[i];
        if (t->v[0][1] <= x[1] || t->v[1][1] <= x[1] || t->v[2][1] <= x[1]) continue;
        double ax = t->v[0][0] - x[0], az = t->v[0][2] - x[2], bx = t->v[1][0] - x[0], bz = t->v[1][2] - x[2];
        double cx = t->v[2][0] - x[0], cz = t->v[2][2] - x[2];
        double d1 = ax * bz - az * bx, d2 = bx * cz - bz * cx, d3 = cx * az - cz * ax;
        if ((d1 > 0 && d2 > 0 && d3 > 0) || (d1 < 0 && d2 < 0 && d3 < 0)) return true;
    }
    return false;
}

static void spawn_candidates(const soak_level_t *l)
{
    if (g_spawn.n && strcmp(g_spawn.file, l->file) == 0) return;
    snprintf(g_spawn.file, sizeof g_spawn.file, "%s", l->file);
    g_spawn.n = 0;
    soak_rng_t r;
    soak_rng_seed(&r, 0x5BA3ull);
    for (int tries = 0; tries < 20000 && g_spawn.n < SPAWN_CANDIDATES && l->nwtris > 0; tries++) {
        const soak_wtri_t *w = &l->wtris[soak_rng_below(&r, l->nwtris)];
        dv3 a = v3(w->v[0][0], w->v[0][1], w->v[0][2]);
        dv3 e1 = v_sub(v3(w->v[1][0], w->v[1][1], w->v[1][2]), a), e2 = v_sub(v3(w->v[2][0], w->v[2][1], w->v[2][2]), a);
        dv3 n = v_cross(e1, e2);
        double area2 = v_len(n);
        if (!(area2 > 0.5) || n.y < 0.9 * area2) continue; /* >= 0.25 m^2, facing up (+Y) */
        double u = soak_rng_unit(&r), v = soak_rng_unit(&r);
        if (u + v > 1) { u = 1 - u; v = 1 - v; }
        dv3 c = v_add(a, v_add(v_scale(e1, u), v_scale(e2, v)));
        double x[3] = {c.x, c.y + 0.05, c.z};
        if (!roofed(l, x)) continue;
        memcpy(g_spawn.p[g_spawn.n++], x, sizeof x);
    }
}

fm_vec3_t soak_level_spawn(soak_rng_t *r, const soak_level_t *l, const char_body_settings_t *s)
{
    fm_vec3_t o = {{0.0f, 0.0f, 0.0f}};
    spawn_candidates(l);
    double h = 0.5 * (double)s->height;
    for (int tries = 0; tries < 200 && g_spawn.n > 0; tries++) {
        const double *c = g_spawn.p[soak_rng_below(r, g_spawn.n)];
        for (int k = 0; k < 3; k++) o.v[k] = (float)((k == 1 ? c[1] + h : c[k]) - s->center_offset.v[k]);
        soak_capsule_t full, sweep;
        soak_capsules_at(s, o, &full, &sweep);
        if (soak_check_nearest(l, s, &full) > 0.01) return o; /* room for the capsule */
    }
    return o;
}
