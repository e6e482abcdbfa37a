/**
 * @file bsp.c
 * @brief Quake III Arena BSP (IBSP version 46) reader for collbake: the collision-relevant
 *        surfaces of the world model as triangles.
 *
 * Layout (all little-endian): "IBSP", int32 version 46, 17 lumps {int32 offset, int32 length}.
 * Used lumps: 1 shaders (name[64], int32 surfaceFlags, int32 contentFlags), 7 models
 * (float mins[3], maxs[3], int32 firstSurface, numSurfaces, firstBrush, numBrushes),
 * 10 drawverts (44 bytes: float xyz[3], st[2], lightmap[2], normal[3], uint8 color[4]),
 * 11 drawindexes (int32), 13 surfaces (104 bytes: int32 shaderNum, fogNum, surfaceType,
 * firstVert, numVerts, firstIndex, numIndexes, lightmapNum, lightmapX, lightmapY,
 * lightmapWidth, lightmapHeight, float lightmapOrigin[3], lightmapVecs[3][3], int32
 * patchWidth, patchHeight at bytes 96 and 100).
 *
 * Surface types: 1 planar and 3 triangle soup: triangles from drawindexes (relative to
 * firstVert); 2 patch: a patchWidth x patchHeight grid of control points (odd sizes),
 * made of 3x3 biquadratic Bezier pieces, each tessellated at a fixed level; 4 flare and
 * anything else: no geometry.
 *
 * Collision: only surfaces whose shader has CONTENTS_SOLID (0x1) and not SURF_NONSOLID
 * (0x4000) are taken (water, fog, lava, slime and decals are not solid; SURF_NODRAW
 * surfaces are normally not in the surface lump at all). Quake's invisible clip brushes
 * (CONTENTS_PLAYERCLIP) have no surfaces and are therefore missing: brushes are not read.
 *
 * Triangles are wound counter-clockwise seen from the side their vertex normals point to.
 *
 * Every length, count and index is validated before use; an error returns a message
 * (the caller prints it as "ERROR: <file>: ...").
 */
#include "bsp.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#define BSP_LUMPS 17
#define LUMP_SHADERS 1
#define LUMP_MODELS 7
#define LUMP_VERTS 10
#define LUMP_INDEXES 11
#define LUMP_SURFACES 13

#define SHADER_SIZE 72
#define MODEL_SIZE 40
#define VERT_SIZE 44
#define SURFACE_SIZE 104

#define CONTENTS_SOLID 0x1u
#define SURF_NONSOLID 0x4000u

#define MST_PLANAR 1
#define MST_PATCH 2
#define MST_TRIANGLE_SOUP 3

#define PATCH_LEVEL 4        /* each 3x3 Bezier piece becomes 4 x 4 quads */
#define PATCH_MAX_SIDE 1025  /* control points per side (Quake's MAX_PATCH_SIZE is 32) */

static char g_err[256];

static const char *fail(const char *fmt, long a, long b)
{
    snprintf(g_err, sizeof g_err, fmt, a, b);
    return g_err;
}

static uint32_t rd32(const unsigned char *p)
{
    return (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 | (uint32_t)p[3] << 24;
}
static int32_t rdi(const unsigned char *p) { uint32_t u = rd32(p); int32_t i; memcpy(&i, &u, 4); return i; }
static float rdf(const unsigned char *p) { uint32_t u = rd32(p); float f; memcpy(&f, &u, 4); return f; }

typedef struct {
    const unsigned char *p;
    uint32_t n;   /* records */
} lump_t;

typedef struct {
    lump_t shaders, models, verts, indexes, surfaces;
    double unit;
    bsp_tri_fn fn;
    void *user;
    bsp_stats_t *st;
} ctx_t;

/* Quake (x, y, z), Z up -> (x, z, -y) * unit, Y up (a rotation: winding is kept). */
static int vert(const ctx_t *c, uint32_t i, double out[3])
{
    const unsigned char *v = c->verts.p + (size_t)i * VERT_SIZE;
    double x = rdf(v), y = rdf(v + 4), z = rdf(v + 8);
    if (!isfinite(x) || !isfinite(y) || !isfinite(z)) return -1;
    out[0] = x * c->unit;
    out[1] = z * c->unit;
    out[2] = -y * c->unit;
    return 0;
}

/* The drawvert's normal, converted like the position (zero when absent or not finite). */
static void vnormal(const ctx_t *c, uint32_t i, double out[3])
{
    const unsigned char *v = c->verts.p + (size_t)i * VERT_SIZE + 28;
    double x = rdf(v), y = rdf(v + 4), z = rdf(v + 8);
    if (!isfinite(x) || !isfinite(y) || !isfinite(z)) x = y = z = 0;
    out[0] = x; out[1] = z; out[2] = -y;
}

/* Emits a triangle wound counter-clockwise seen from its front (the side its vertex
 * normals point to: the open side of a wall or floor), as glTF and OBJ have it, whatever
 * the map's winding: the facing matters to tools (the soak's spawn points), and the
 * runtime is double-sided anyway. n: the summed vertex normals (zero: kept as is). */
static void emit(const ctx_t *c, const double a[3], const double b[3], const double d[3], const double n[3])
{
    double t[9], e1[3], e2[3], x[3];
    for (int k = 0; k < 3; k++) { e1[k] = b[k] - a[k]; e2[k] = d[k] - a[k]; }
    x[0] = e1[1] * e2[2] - e1[2] * e2[1];
    x[1] = e1[2] * e2[0] - e1[0] * e2[2];
    x[2] = e1[0] * e2[1] - e1[1] * e2[0];
    int flip = n && x[0] * n[0] + x[1] * n[1] + x[2] * n[2] < 0;
    memcpy(t, a, 3 * sizeof(double));
    memcpy(t + 3, flip ? d : b, 3 * sizeof(double));
    memcpy(t + 6, flip ? b : d, 3 * sizeof(double));
    c->fn(c->user, t);
    c->st->triangles++;
}

static const char *do_indexed(const ctx_t *c, long s, uint32_t fv, uint32_t nv, uint32_t fi, uint32_t ni)
{
    if (ni % 3) return fail("surface %ld: %ld indexes, not a multiple of 3", s, (long)ni);
    for (uint32_t k = 0; k < ni; k += 3) {
        double p[3][3], n[3] = {0, 0, 0}, vn[3];
        for (int j = 0; j < 3; j++) {
            int32_t ix = rdi(c->indexes.p + ((size_t)fi + k + (uint32_t)j) * 4);
            if (ix < 0 || (uint32_t)ix >= nv) return fail("surface %ld: index %ld outside its vertices", s, (long)ix);
            if (vert(c, fv + (uint32_t)ix, p[j]) != 0) return fail("surface %ld: non-finite vertex %ld", s, (long)ix);
            vnormal(c, fv + (uint32_t)ix, vn);
            for (int a = 0; a < 3; a++) n[a] += vn[a];
        }
        emit(c, p[0], p[1], p[2], n);
    }
    return NULL;
}

static void bez(double cp[3][3][3], double u, double v, double out[3])
{
    double bu[3] = {(1 - u) * (1 - u), 2 * u * (1 - u), u * u};
    double bv[3] = {(1 - v) * (1 - v), 2 * v * (1 - v), v * v};
    for (int k = 0; k < 3; k++) {
        double s = 0;
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++) s += bv[i] * bu[j] * cp[i][j][k];
        out[k] = s;
    }
}

static const char *do_patch(const ctx_t *c, long s, uint32_t fv, uint32_t nv, int32_t w, int32_t h)
{
    if (w < 3 || h < 3 || w > PATCH_MAX_SIDE || h > PATCH_MAX_SIDE || !(w & 1) || !(h & 1)) {
        snprintf(g_err, sizeof g_err, "surface %ld: patch size %ld x %ld (each side must be odd, 3..%d)", s, (long)w,
                 (long)h, PATCH_MAX_SIDE);
        return g_err;
    }
    if ((uint32_t)w * (uint32_t)h != nv) return fail("surface %ld: patch has %ld vertices, not width x height", s, (long)nv);
    for (int32_t py = 0; py + 2 < h; py += 2)
        for (int32_t px = 0; px + 2 < w; px += 2) {
            double cp[3][3][3], cn[3][3][3];
            for (int i = 0; i < 3; i++)
                for (int j = 0; j < 3; j++) {
                    if (vert(c, fv + (uint32_t)((py + i) * w + px + j), cp[i][j]) != 0)
                        return fail("surface %ld: non-finite patch control point", s, 0);
                    vnormal(c, fv + (uint32_t)((py + i) * w + px + j), cn[i][j]);
                }
            double g[PATCH_LEVEL + 1][PATCH_LEVEL + 1][3], gn[PATCH_LEVEL + 1][PATCH_LEVEL + 1][3];
            for (int i = 0; i <= PATCH_LEVEL; i++)
                for (int j = 0; j <= PATCH_LEVEL; j++) {
                    bez(cp, (double)j / PATCH_LEVEL, (double)i / PATCH_LEVEL, g[i][j]);
                    bez(cn, (double)j / PATCH_LEVEL, (double)i / PATCH_LEVEL, gn[i][j]);
                }
            for (int i = 0; i < PATCH_LEVEL; i++)
                for (int j = 0; j < PATCH_LEVEL; j++) {
                    double n1[3], n2[3];
                    for (int a = 0; a < 3; a++) {
                        n1[a] = gn[i][j][a] + gn[i + 1][j][a] + gn[i + 1][j + 1][a];
                        n2[a] = gn[i][j][a] + gn[i + 1][j + 1][a] + gn[i][j + 1][a];
                    }
                    emit(c, g[i][j], g[i + 1][j], g[i + 1][j + 1], n1);
                    emit(c, g[i][j], g[i + 1][j + 1], g[i][j + 1], n2);
                }
        }
    return NULL;
}

static const char *lump(const unsigned char *d, size_t n, int k, uint32_t rec, const char *name, lump_t *out)
{
    int32_t off = rdi(d + 8 + 8 * k), len = rdi(d + 12 + 8 * k);
    if (off < 0 || len < 0 || (size_t)off > n || (size_t)len > n - (size_t)off) {
        snprintf(g_err, sizeof g_err, "lump %d (%s) at %ld, %ld bytes, outside the %zu-byte file (truncated?)", k, name,
                 (long)off, (long)len, n);
        return g_err;
    }
    if ((uint32_t)len % rec) {
        snprintf(g_err, sizeof g_err, "lump %d (%s): %ld bytes, not a multiple of %u", k, name, (long)len, (unsigned)rec);
        return g_err;
    }
    out->p = d + off;
    out->n = (uint32_t)len / rec;
    return NULL;
}

int bsp_is_bsp(const unsigned char *d, size_t n) { return n >= 4 && memcmp(d, "IBSP", 4) == 0; }

const char *bsp_read(const unsigned char *d, size_t n, double unit, int all_models, bsp_tri_fn fn, void *user,
                     bsp_stats_t *st)
{
    memset(st, 0, sizeof *st);
    if (n < 8 + 8 * BSP_LUMPS) return fail("%ld bytes: too short for a BSP header", (long)n, 0);
    if (!bsp_is_bsp(d, n)) return fail("not a Quake III BSP (no IBSP magic)", 0, 0);
    int32_t version = rdi(d + 4);
    if (version != 46) return fail("IBSP version %ld, only 46 (Quake III Arena) is read", (long)version, 0);
    if (!(unit > 0) || !isfinite(unit)) return fail("bad unit", 0, 0);
    ctx_t c;
    memset(&c, 0, sizeof c);
    c.unit = unit; c.fn = fn; c.user = user; c.st = st;
    const char *e;
    if ((e = lump(d, n, LUMP_SHADERS, SHADER_SIZE, "shaders", &c.shaders)) ||
        (e = lump(d, n, LUMP_MODELS, MODEL_SIZE, "models", &c.models)) ||
        (e = lump(d, n, LUMP_VERTS, VERT_SIZE, "drawverts", &c.verts)) ||
        (e = lump(d, n, LUMP_INDEXES, 4, "drawindexes", &c.indexes)) ||
        (e = lump(d, n, LUMP_SURFACES, SURFACE_SIZE, "surfaces", &c.surfaces)))
        return e;
    uint32_t first = 0, count = c.surfaces.n;
    if (!all_models) {
        if (c.models.n == 0) return fail("no models (the world is model 0)", 0, 0);
        int32_t f = rdi(c.models.p + 24), k = rdi(c.models.p + 28);
        if (f < 0 || k < 0 || (uint32_t)f > c.surfaces.n || (uint32_t)k > c.surfaces.n - (uint32_t)f)
            return fail("world model surfaces %ld (+%ld) outside the surface lump", (long)f, (long)k);
        first = (uint32_t)f; count = (uint32_t)k;
    }
    st->surfaces = count;
    for (uint32_t s = first; s < first + count; s++) {
        const unsigned char *f = c.surfaces.p + (size_t)s * SURFACE_SIZE;
        int32_t shader = rdi(f), type = rdi(f + 8), fv = rdi(f + 12), nv = rdi(f + 16), fi = rdi(f + 20),
                ni = rdi(f + 24), pw = rdi(f + 96), ph = rdi(f + 100);
        if (shader < 0 || (uint32_t)shader >= c.shaders.n)
            return fail("surface %ld: shader %ld outside the shader lump", (long)s, (long)shader);
        const unsigned char *sh = c.shaders.p + (size_t)shader * SHADER_SIZE;
        uint32_t sflags = rd32(sh + 64), contents = rd32(sh + 68);
        if (type != MST_PLANAR && type != MST_PATCH && type != MST_TRIANGLE_SOUP) { st->other++; continue; }
        if (!(contents & CONTENTS_SOLID) || (sflags & SURF_NONSOLID)) { st->nonsolid++; continue; }
        if (fv < 0 || nv < 0 || (uint32_t)fv > c.verts.n || (uint32_t)nv > c.verts.n - (uint32_t)fv)
            return fail("surface %ld: vertices outside the drawvert lump", (long)s, 0);
        const char *err;
        if (type == MST_PATCH) {
            st->patches++;
            err = do_patch(&c, (long)s, (uint32_t)fv, (uint32_t)nv, pw, ph);
        } else {
            if (fi < 0 || ni < 0 || (uint32_t)fi > c.indexes.n || (uint32_t)ni > c.indexes.n - (uint32_t)fi)
                return fail("surface %ld: indexes outside the drawindex lump", (long)s, 0);
            if (type == MST_PLANAR) st->planar++; else st->soups++;
            err = do_indexed(&c, (long)s, (uint32_t)fv, (uint32_t)nv, (uint32_t)fi, (uint32_t)ni);
        }
        if (err) return err;
    }
    return NULL;
}
