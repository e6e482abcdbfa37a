/**
 * @file mesh.c
 * @brief Collision meshes: allocation-free builder (triangles + uniform grid spatial hash
 *        in one caller-owned block), hostile-input-safe loader of baked big-endian blobs,
 *        and the blob writer used by the bake tool. Layout: mesh_format.h.
 */
#include "vec3.h"
#include "mesh_format.h"
#include <math.h>
#include <string.h>

/* Plain comparisons (libm's fminf/fmaxf are not on the console's libc allow-list). */

/* Hard caps of the grid, which coll_mesh_build_size() budgets for: the builder grows the
 * cell size until the grid fits (a single cell always does). */
#define GRID_MAX_CELLS(n) (2u * (uint64_t)(n) + 64u)
#define GRID_MAX_REFS(n)  (8u * (uint64_t)(n) + 64u)
/* Softer targets for an automatically chosen cell size (smaller blobs). */
#define GRID_AUTO_CELLS(n) ((uint64_t)(n) / 2u + 64u)
/* Hashed grids (cells finer than a dense grid of the budget allows): entries, a power of two. */
#define GRID_AUTO_BUCKETS(n) ((uint64_t)(n) / 4u + 64u)
#define GRID_AUTO_REFS(n)  (3u * (uint64_t)(n) + 64u)
#define QMAX 65535.0f
/* Float meshes of fewer input triangles always get the sub-cell codes (a bigger one where
 * they keep it within 24 bytes a triangle). */
#define CODES_ALWAYS 512u
/* ... where they pay: a ref's triangle covers at most this many of its cell's 16 quarters
 * (X times Z) on average. */
#define CODES_MAX_COVER 6u

/* ------------------------------------------------------------------ byte order ---- */

static bool host_is_le(void)
{
    const union { uint32_t u; uint8_t b[4]; } probe = { 1u };
    return probe.b[0] == 1u;
}

static uint32_t bswap32(uint32_t v)
{
    return (v >> 24) | ((v >> 8) & 0xFF00u) | ((v << 8) & 0xFF0000u) | (v << 24);
}

static uint16_t bswap16(uint16_t v) { return (uint16_t)((v >> 8) | (v << 8)); }

static uint32_t rd32(const uint8_t *p, bool swap)
{
    uint32_t v;
    memcpy(&v, p, 4);
    return swap ? bswap32(v) : v;
}

static uint16_t rd16(const uint8_t *p, bool swap)
{
    uint16_t v;
    memcpy(&v, p, 2);
    return swap ? bswap16(v) : v;
}

static float u2f(uint32_t u)
{
    float f;
    memcpy(&f, &u, 4);
    return f;
}

static void wr32be(uint8_t *p, uint32_t v)
{
    p[0] = (uint8_t)(v >> 24); p[1] = (uint8_t)(v >> 16); p[2] = (uint8_t)(v >> 8); p[3] = (uint8_t)v;
}

static void wr16be(uint8_t *p, uint16_t v)
{
    p[0] = (uint8_t)(v >> 8); p[1] = (uint8_t)v;
}

/* ------------------------------------------------------------------ checksum ------- */

#define FNV_BASIS 2166136261u
#define FNV_PRIME 16777619u

static uint32_t mix(uint32_t h, uint32_t v) { return (h ^ v) * FNV_PRIME; }

/* Sections of a mesh as (offset, element size, count). */
typedef struct { uint64_t off, count; uint32_t esize; } section_t;

#define NSECT 6
enum { SECT_VERTS, SECT_TRIS, SECT_TBASE, SECT_CELLS, SECT_REFS, SECT_CODES };

static void sections_of(uint32_t flags, const coll_mesh_layout_t *l, uint64_t nverts, uint64_t ntris,
                        uint64_t ncells, uint64_t nrefs, section_t s[NSECT])
{
    s[0].off = l->off_verts; s[0].esize = (flags & COLL_MESHF_QUANT) ? 2u : 4u; s[0].count = nverts * 3u;
    s[1].off = l->off_tris;
    s[1].esize = (flags & (COLL_MESHF_IDX16 | COLL_MESHF_IDXBLK)) ? 2u : 4u;
    s[1].count = ntris * 3u;
    s[2].off = l->off_tbase; s[2].esize = 4u; s[2].count = l->ntbase;
    s[3].off = l->off_cells; s[3].esize = 4u; s[3].count = ncells + 1u;
    s[4].off = l->off_refs;  s[4].esize = (flags & COLL_MESHF_REF16) ? 2u : 4u; s[4].count = nrefs;
    s[5].off = l->off_codes; s[5].esize = 1u; s[5].count = (flags & COLL_MESHF_RCODE) ? nrefs : 0u;
}

/* Header words from `version` on, checksum word excluded; then all section values. */
static uint32_t checksum_of(const uint8_t *b, bool swap, const section_t s[NSECT])
{
    uint32_t h = FNV_BASIS;
    for (uint32_t w = 1; w < sizeof(struct coll_mesh_s) / 4u; w++)
        if (w != offsetof(struct coll_mesh_s, checksum) / 4u) h = mix(h, rd32(b + 4u * w, swap));
    for (int i = 0; i < NSECT; i++) {
        const uint8_t *p = b + s[i].off;
        if (s[i].esize == 1u) {
            for (uint64_t k = 0; k < s[i].count; k++) h = mix(h, p[k]);
        } else if (s[i].esize == 2u) {
            for (uint64_t k = 0; k < s[i].count; k++) h = mix(h, rd16(p + 2u * k, swap));
        } else {
            for (uint64_t k = 0; k < s[i].count; k++) h = mix(h, rd32(p + 4u * k, swap));
        }
    }
    return h;
}

static uint64_t ncells_of(const coll_mesh_t *m) { return coll_mesh_cell_count(m); }

static coll_mesh_layout_t layout_of_mesh(const coll_mesh_t *m)
{
    return coll_mesh_layout_of(m->flags, m->nverts, m->ntris, ncells_of(m), m->nrefs);
}

static uint32_t checksum_native(const coll_mesh_t *m)
{
    coll_mesh_layout_t l = layout_of_mesh(m);
    section_t s[NSECT];
    sections_of(m->flags, &l, m->nverts, m->ntris, ncells_of(m), m->nrefs, s);
    return checksum_of((const uint8_t *)m, false, s);
}

/* ------------------------------------------------------------------ accessors ------ */

static fm_vec3_t vertex_of(const coll_mesh_t *m, uint32_t v)
{
    const uint8_t *base = (const uint8_t *)m + m->off_verts;
    fm_vec3_t p;
    if (m->flags & COLL_MESHF_QUANT) {
        const uint16_t *q = (const uint16_t *)(const void *)base + 3u * v;
        for (int a = 0; a < 3; a++) p.v[a] = m->qorigin[a] + (float)q[a] * m->qscale[a];
    } else {
        const float *f = (const float *)(const void *)base + 3u * v;
        p.x = f[0]; p.y = f[1]; p.z = f[2];
    }
    return p;
}

static void tri_indices(const coll_mesh_t *m, uint32_t i, uint32_t idx[3])
{
    const uint8_t *base = (const uint8_t *)m + m->off_tris;
    if (m->flags & COLL_MESHF_IDX16) {
        const uint16_t *t = (const uint16_t *)(const void *)base + 3u * i;
        idx[0] = t[0]; idx[1] = t[1]; idx[2] = t[2];
    } else if (m->flags & COLL_MESHF_IDXBLK) {
        const uint16_t *t = (const uint16_t *)(const void *)base + 3u * i;
        uint32_t b = coll_mesh_tri_bases(m)[i >> COLL_MESH_TRI_BLOCK_SHIFT];
        idx[0] = b + t[0]; idx[1] = b + t[1]; idx[2] = b + t[2];
    } else {
        const uint32_t *t = (const uint32_t *)(const void *)base + 3u * i;
        idx[0] = t[0]; idx[1] = t[1]; idx[2] = t[2];
    }
}

void coll_mesh_tri_local(const coll_mesh_t *m, uint32_t i, fm_vec3_t out[3])
{
    uint32_t idx[3];
    tri_indices(m, i, idx);
    out[0] = vertex_of(m, idx[0]);
    out[1] = vertex_of(m, idx[1]);
    out[2] = vertex_of(m, idx[2]);
}

size_t coll_mesh_size(const coll_mesh_t *mesh) { return mesh ? mesh->total_size : 0u; }

uint32_t coll_mesh_triangle_count(const coll_mesh_t *mesh) { return mesh ? mesh->ntris : 0u; }

void coll_mesh_triangle(const coll_mesh_t *mesh, uint32_t i, fm_vec3_t out[3])
{
    if (!out) return;
    if (!mesh || i >= mesh->ntris) {
        memset(out, 0, 3 * sizeof(fm_vec3_t));
        return;
    }
    coll_mesh_tri_local(mesh, i, out);
}

void coll_mesh_bounds(const coll_mesh_t *mesh, fm_vec3_t *min, fm_vec3_t *max)
{
    for (int a = 0; a < 3; a++) {
        if (min) min->v[a] = mesh ? mesh->bmin[a] : 0.0f;
        if (max) max->v[a] = mesh ? mesh->bmax[a] : 0.0f;
    }
}

/* ------------------------------------------------------------------ build ---------- */

static bool vfinite(const float *p) { return isfinite(p[0]) && isfinite(p[1]) && isfinite(p[2]); }

/* Non-degenerate: the sine of the smallest corner angle is not vanishingly small. */
static bool tri_has_area(const fm_vec3_t t[3])
{
    fm_vec3_t e1, e2, n;
    fm_vec3_sub(&e1, &t[1], &t[0]);
    fm_vec3_sub(&e2, &t[2], &t[0]);
    fm_vec3_cross(&n, &e1, &e2);
    float n2 = fm_vec3_len2(&n);
    if (!(n2 > 1e-30f) || !isfinite(n2)) return false;
    return n2 > 1e-12f * fm_vec3_len2(&e1) * fm_vec3_len2(&e2);
}

/* Input triangle passes index and finiteness checks. */
static bool input_tri_ok(const float *verts, uint32_t nverts, const uint32_t *ix)
{
    if (ix[0] >= nverts || ix[1] >= nverts || ix[2] >= nverts) return false;
    if (ix[0] == ix[1] || ix[1] == ix[2] || ix[0] == ix[2]) return false;
    return vfinite(verts + 3u * ix[0]) && vfinite(verts + 3u * ix[1]) && vfinite(verts + 3u * ix[2]);
}

/* Input triangle t is stored: its indices pass, and its stored (possibly quantized)
 * vertices span an area. The builder keeps exactly these, compacted in input order. */
static bool tri_kept(const coll_mesh_t *m, const float *verts, uint32_t nverts, const uint32_t *indices, uint32_t t)
{
    const uint32_t *ix = indices + 3u * t;
    if (!input_tri_ok(verts, nverts, ix)) return false;
    fm_vec3_t tri[3] = { vertex_of(m, ix[0]), vertex_of(m, ix[1]), vertex_of(m, ix[2]) };
    return tri_has_area(tri);
}

/* Block-based 16-bit indices for a mesh of more than 65535 vertices: each block of
 * COLL_MESH_TRI_BLOCK kept triangles gets its smallest vertex index as base (into tbase);
 * false when a block reaches over more than 65535 vertices above it. */
static bool block_bases(const coll_mesh_t *m, const float *verts, uint32_t nverts, const uint32_t *indices,
                        uint32_t ntris, uint32_t *tbase)
{
    uint32_t lo = UINT32_MAX, hi = 0, n = 0;
    for (uint32_t t = 0; t <= ntris; t++) {
        if (t < ntris && !tri_kept(m, verts, nverts, indices, t)) continue;
        if (n > 0 && (t == ntris || (n & (COLL_MESH_TRI_BLOCK - 1u)) == 0u)) { /* a block ends */
            if (hi - lo > 65535u) return false;
            tbase[(n - 1u) >> COLL_MESH_TRI_BLOCK_SHIFT] = lo;
            lo = UINT32_MAX;
            hi = 0;
        }
        if (t == ntris) break;
        for (int k = 0; k < 3; k++) {
            uint32_t v = indices[3u * t + k];
            if (v < lo) lo = v;
            if (v > hi) hi = v;
        }
        n++;
    }
    return true;
}

/* Separating-axis test of a triangle against a box (center c, half sizes h). */
static bool axis_separates(const fm_vec3_t *a, const fm_vec3_t v[3], const float h[3])
{
    float p0 = fm_vec3_dot(a, &v[0]), p1 = fm_vec3_dot(a, &v[1]), p2 = fm_vec3_dot(a, &v[2]);
    float lo = f_min(p0, f_min(p1, p2)), hi = f_max(p0, f_max(p1, p2));
    float r = h[0] * fabsf(a->x) + h[1] * fabsf(a->y) + h[2] * fabsf(a->z);
    return lo > r || hi < -r;
}

static bool tri_box_overlap(const fm_vec3_t tri[3], const float c[3], const float h[3])
{
    fm_vec3_t v[3], e[3];
    for (int i = 0; i < 3; i++)
        for (int a = 0; a < 3; a++) v[i].v[a] = tri[i].v[a] - c[a];
    for (int a = 0; a < 3; a++) {
        float lo = f_min(v[0].v[a], f_min(v[1].v[a], v[2].v[a]));
        float hi = f_max(v[0].v[a], f_max(v[1].v[a], v[2].v[a]));
        if (lo > h[a] || hi < -h[a]) return false;
    }
    fm_vec3_sub(&e[0], &v[1], &v[0]);
    fm_vec3_sub(&e[1], &v[2], &v[1]);
    fm_vec3_sub(&e[2], &v[0], &v[2]);
    fm_vec3_t n;
    fm_vec3_cross(&n, &e[0], &e[1]);
    if (axis_separates(&n, v, h)) return false;
    for (int i = 0; i < 3; i++) {
        for (int a = 0; a < 3; a++) {
            fm_vec3_t unit = {{0.0f, 0.0f, 0.0f}}, ax;
            unit.v[a] = 1.0f;
            fm_vec3_cross(&ax, &e[i], &unit);
            if (axis_separates(&ax, v, h)) return false;
        }
    }
    return true;
}

typedef struct {
    float origin[3];
    float cell;
    float margin;
    uint32_t dims[3];
    uint32_t nbuckets; /* 0: dense grid; else hashed (power of two) */
} grid_t;

/* Grid counts are converted as (float)(int32_t) (see coll_mesh_cell_coord). */
/* Calls visit for every cell triangle tri (conservatively) intersects; stops and returns
 * false as soon as visit does. The same predicate serves counting and filling. */
typedef bool (*cell_visit_fn)(void *ctx, uint32_t cell);

static bool for_each_cell_of_tri(const grid_t *g, const fm_vec3_t tri[3], cell_visit_fn visit, void *ctx)
{
    uint32_t lo[3], hi[3];
    float inv = 1.0f / g->cell;
    for (int a = 0; a < 3; a++) {
        float mn = f_min(tri[0].v[a], f_min(tri[1].v[a], tri[2].v[a])) - g->margin;
        float mx = f_max(tri[0].v[a], f_max(tri[1].v[a], tri[2].v[a])) + g->margin;
        lo[a] = coll_mesh_cell_coord(mn, g->origin[a], inv, g->dims[a]);
        hi[a] = coll_mesh_cell_coord(mx, g->origin[a], inv, g->dims[a]);
    }
    bool single = lo[0] == hi[0] && lo[1] == hi[1] && lo[2] == hi[2];
    /* Hashed grid: a triangle is listed once per entry even when several of its cells
     * share it (the first DEDUP entries it reaches are remembered; beyond that a repeat
     * is only redundant, never wrong). Every pass visits in the same order. */
#define DEDUP 32
    uint32_t done[DEDUP];
    uint32_t ndone = 0;
    float h[3] = { 0.5f * g->cell + g->margin, 0.5f * g->cell + g->margin, 0.5f * g->cell + g->margin };
    for (uint32_t z = lo[2]; z <= hi[2]; z++) {
        for (uint32_t y = lo[1]; y <= hi[1]; y++) {
            for (uint32_t x = lo[0]; x <= hi[0]; x++) {
                if (!single) {
                    float c[3] = { g->origin[0] + ((float)(int32_t)x + 0.5f) * g->cell,
                                   g->origin[1] + ((float)(int32_t)y + 0.5f) * g->cell,
                                   g->origin[2] + ((float)(int32_t)z + 0.5f) * g->cell };
                    if (!tri_box_overlap(tri, c, h)) continue;
                }
                uint32_t e;
                if (g->nbuckets) {
                    e = coll_mesh_hash_cell(x, y, z, g->nbuckets);
                    bool rep = false;
                    for (uint32_t i = 0; i < ndone && !rep; i++) rep = done[i] == e;
                    if (rep) continue;
                    if (ndone < DEDUP) done[ndone++] = e;
                } else {
                    e = x + g->dims[0] * (y + g->dims[1] * z);
                }
                if (!visit(ctx, e)) return false;
            }
        }
    }
    return true;
}

typedef struct { uint64_t count, limit; } count_ctx_t;

static bool count_visit(void *ctx, uint32_t cell)
{
    (void)cell;
    count_ctx_t *c = ctx;
    return ++c->count <= c->limit;
}

/* The sub-cell code (COLL_MESHF_RCODE) of a triangle whose box grown by the grid margin is
 * lo..hi, listed in entry cell of a dense grid; *cover += the quarters it covers (X times
 * Z). */
static uint32_t code_of(const grid_t *g, uint32_t cell, const float lo[3], const float hi[3], uint64_t *cover)
{
    uint32_t x = cell % g->dims[0], z = cell / g->dims[0] / g->dims[1];
    float cx = g->origin[0] + (float)(int32_t)x * g->cell, cz = g->origin[2] + (float)(int32_t)z * g->cell;
    float inv4 = 4.0f / g->cell;
    uint32_t ax = coll_mesh_quarter(lo[0], cx, inv4), bx = coll_mesh_quarter(hi[0], cx, inv4);
    uint32_t az = coll_mesh_quarter(lo[2], cz, inv4), bz = coll_mesh_quarter(hi[2], cz, inv4);
    *cover += (uint64_t)(bx - ax + 1u) * (bz - az + 1u);
    return coll_mesh_quarter_bits(ax, bx) | coll_mesh_quarter_bits(az, bz) << 4;
}

/* The triangle's box grown by the grid margin (what its codes describe). */
static void code_box(const grid_t *g, const fm_vec3_t tri[3], float lo[3], float hi[3])
{
    for (int a = 0; a < 3; a++) {
        lo[a] = f_min(tri[0].v[a], f_min(tri[1].v[a], tri[2].v[a])) - g->margin;
        hi[a] = f_max(tri[0].v[a], f_max(tri[1].v[a], tri[2].v[a])) + g->margin;
    }
}

typedef struct {
    uint32_t *cells;
    const grid_t *g; /* a dense grid whose codes' cover is summed, or NULL */
    float lo[3], hi[3];
    uint64_t cover;
} hist_ctx_t;

static bool hist_visit(void *ctx, uint32_t cell)
{
    hist_ctx_t *h = ctx;
    h->cells[cell]++;
    if (h->g) (void)code_of(h->g, cell, h->lo, h->hi, &h->cover);
    return true;
}

typedef struct {
    uint32_t *cells;
    uint8_t *refs;
    bool ref16;
    uint32_t tri;
    /* the sub-cell codes (COLL_MESHF_RCODE), or NULL; the grid, and the triangle's box
     * grown by the grid margin on X and Z */
    uint8_t *codes;
    const grid_t *g;
    float lo[3], hi[3];
    uint64_t cover;
} fill_ctx_t;

static bool fill_visit(void *ctx, uint32_t cell)
{
    fill_ctx_t *f = ctx;
    uint32_t k = --f->cells[cell];
    if (f->ref16) ((uint16_t *)(void *)f->refs)[k] = (uint16_t)f->tri;
    else ((uint32_t *)(void *)f->refs)[k] = f->tri;
    if (f->codes) f->codes[k] = (uint8_t)code_of(f->g, cell, f->lo, f->hi, &f->cover);
    return true;
}

static uint32_t mesh_flags_for(uint32_t nverts, uint32_t ntris, bool quant)
{
    uint32_t flags = quant ? COLL_MESHF_QUANT : 0u;
    if (nverts <= 65535u) flags |= COLL_MESHF_IDX16;
    if (ntris <= 65535u) flags |= COLL_MESHF_REF16;
    return flags;
}

size_t coll_mesh_build_size(uint32_t nverts, uint32_t ntris, const coll_mesh_build_opts_t *opts)
{
    bool quant = opts && (opts->flags & COLL_MESH_QUANTIZE);
    uint32_t flags = mesh_flags_for(nverts, ntris, quant);
    /* (a small float mesh: room for the sub-cell codes too; a bigger one has them only
     * within 24 bytes a triangle, less than this bound without them: see coll_mesh_build) */
    if (!quant && ntris < CODES_ALWAYS) flags |= COLL_MESHF_RCODE;
    coll_mesh_layout_t l = coll_mesh_layout_of(flags, nverts, ntris, GRID_MAX_CELLS(ntris), GRID_MAX_REFS(ntris));
    if (l.total > 0xFFFFFFF8u || l.total > (uint64_t)SIZE_MAX) return 0;
    return (size_t)l.total;
}

/* Chooses the cell size: from the triangle sizes (or opts), grown until the grid fits. */
static void choose_grid(const coll_mesh_t *m, float want_cell, float mean_extent, grid_t *g)
{
    float ext[3], maxabs = 0.0f, maxext = 0.0f;
    for (int a = 0; a < 3; a++) {
        ext[a] = m->bmax[a] - m->bmin[a];
        maxext = f_max(maxext, ext[a]);
        maxabs = f_max(maxabs, f_max(fabsf(m->bmin[a]), fabsf(m->bmax[a])));
        g->origin[a] = m->bmin[a];
    }
    bool automatic = !(want_cell > 0.0f);
    /* Automatic: start at half the mean triangle size but no finer than character scale
     * (1 m: a query box is about that wide, finer cells only add cell visits), then grow
     * in steps of 1.25 until the grid fits the memory budget. */
    float cell = automatic ? f_max(0.5f * mean_extent, 1.0f) : want_cell;
    if (!(cell >= maxext * (1.0f / 4096.0f))) cell = maxext * (1.0f / 4096.0f);
    if (!(cell > 1e-6f)) cell = 1e-6f;
    uint64_t max_cells = automatic ? GRID_AUTO_CELLS(m->ntris) : GRID_MAX_CELLS(m->ntris);
    uint64_t max_refs = automatic ? GRID_AUTO_REFS(m->ntris) : GRID_MAX_REFS(m->ntris);
    for (;;) {
        bool fits = true;
        uint64_t ncells = 1;
        for (int a = 0; a < 3; a++) {
            float d = ceilf(ext[a] / cell);
            if (d < 1.0f) d = 1.0f;
            if (d > 1048576.0f) { fits = false; d = 1048576.0f; }
            g->dims[a] = (uint32_t)d;
            ncells *= g->dims[a];
        }
        /* Finer than a dense grid of the budget: hash the cells into a power-of-two
         * number of entries (memory where the triangles are, not per cell). */
        g->nbuckets = 0;
        if (ncells > max_cells) {
            uint64_t want = automatic ? GRID_AUTO_BUCKETS(m->ntris) : max_cells, nb = 64;
            while (nb * 2u <= want) nb *= 2u;
            g->nbuckets = (uint32_t)nb;
            ncells = nb;
        }
        g->cell = cell;
        g->margin = cell * 1e-3f + maxabs * 2e-6f;
        bool single = g->dims[0] == 1u && g->dims[1] == 1u && g->dims[2] == 1u;
        /* Automatic: the grid (cell array + refs) also stays within a byte budget per
         * triangle, so the finer start costs no more memory than the old coarse default. */
        uint64_t refs_cap = max_refs;
        /* (quantized: a small constant, so a small level also stays under 14 B a triangle) */
        const uint64_t budget = (m->flags & COLL_MESHF_QUANT) ? (uint64_t)m->ntris * 9u / 2u + 128u
                                                              : (uint64_t)m->ntris * 19u / 2u + 1024u;
        const unsigned rshift = (m->flags & COLL_MESHF_REF16) ? 1u : 2u; /* ref bytes 2 or 4 (no 64-bit divide) */
        if (automatic) {
            uint64_t left = budget > 4u * (ncells + 1u) ? budget - 4u * (ncells + 1u) : 0u;
            if ((left >> rshift) < refs_cap) refs_cap = left >> rshift;
            if (refs_cap < m->ntris && !single) fits = false;
        }
        /* Hashed: the cells are no longer bounded by the budget, so bound the build work
         * (cells tested per triangle box) by a multiple of the refs allowed. */
        if (fits && g->nbuckets) {
            uint64_t work = 0, limit = 16u * refs_cap + 4096u;
            float inv = 1.0f / cell;
            for (uint32_t t = 0; t < m->ntris && work <= limit; t++) {
                fm_vec3_t tri[3];
                coll_mesh_tri_local(m, t, tri);
                uint64_t n = 1;
                for (int a = 0; a < 3; a++) {
                    float mn = f_min(tri[0].v[a], f_min(tri[1].v[a], tri[2].v[a])) - g->margin;
                    float mx = f_max(tri[0].v[a], f_max(tri[1].v[a], tri[2].v[a])) + g->margin;
                    n *= 1u + coll_mesh_cell_coord(mx, g->origin[a], inv, g->dims[a]) - coll_mesh_cell_coord(mn, g->origin[a], inv, g->dims[a]);
                }
                work += n;
            }
            if (work > limit) fits = false;
        }
        if (fits) {
            if (single) return;
            count_ctx_t cc = { 0, refs_cap };
            bool ok = true;
            for (uint32_t t = 0; t < m->ntris && ok; t++) {
                fm_vec3_t tri[3];
                coll_mesh_tri_local(m, t, tri);
                ok = for_each_cell_of_tri(g, tri, count_visit, &cc);
            }
            if (ok) {
                /* Hashed and automatic: as many buckets as the byte budget has room for
                 * beside the refs (up to one a ref): fewer cells share a bucket's list, so a
                 * query meets fewer triangles of other cells (real maps: -12 % per step). */
                uint64_t refs_bytes = cc.count << rshift, cap = GRID_MAX_CELLS(m->ntris);
                while (automatic && g->nbuckets && (uint64_t)g->nbuckets * 2u <= cc.count &&
                       (uint64_t)g->nbuckets * 2u <= cap && 4u * ((uint64_t)g->nbuckets * 2u + 1u) + refs_bytes <= budget)
                    g->nbuckets *= 2u;
                return;
            }
        }
        if (single) return; /* cannot happen: one cell holds ntris <= max_refs refs */
        cell *= automatic ? 1.25f : 1.5f; /* automatic: finer steps land nearer the budget */
        if (cell >= maxext) cell = f_max(maxext, 1e-6f) * 1.0001f;
    }
}

coll_err_t coll_mesh_build(void *buf, size_t buf_size, const float *verts, uint32_t nverts,
                           const uint32_t *indices, uint32_t ntris,
                           const coll_mesh_build_opts_t *opts, const coll_mesh_t **out)
{
    if (out) *out = NULL;
    if (!buf || !out || (nverts && !verts) || (ntris && !indices)) return COLL_ERR_INVALID_ARG;
    if (opts && ((opts->flags & ~(uint32_t)COLL_MESH_QUANTIZE) || isnan(opts->cell_size) ||
                 isinf(opts->cell_size)))
        return COLL_ERR_INVALID_ARG;
    if ((uintptr_t)buf & 7u) return COLL_ERR_ALIGNMENT;
    if (buf_size < sizeof(struct coll_mesh_s)) return COLL_ERR_BUFFER_TOO_SMALL;

    bool quant = opts && (opts->flags & COLL_MESH_QUANTIZE);
    uint32_t flags = mesh_flags_for(nverts, ntris, quant);
    coll_mesh_t *m = buf;
    memset(m, 0, sizeof *m);
    m->flags = flags;
    m->version = COLL_MESH_VERSION;
    m->nverts = nverts;
    coll_mesh_layout_t l = coll_mesh_layout_of(flags, nverts, 0, 0, 0);
    m->off_verts = (uint32_t)l.off_verts;
    m->off_tris = (uint32_t)l.off_tris;
    if (l.off_tris > buf_size) return COLL_ERR_BUFFER_TOO_SMALL;
    uint8_t *base = buf;

    /* Vertices: floats as given (non-finite ones, never referenced, become 0), or
     * quantized over the bounds of the usable input triangles. */
    if (quant) {
        float lo[3] = { INFINITY, INFINITY, INFINITY }, hi[3] = { -INFINITY, -INFINITY, -INFINITY };
        for (uint32_t t = 0; t < ntris; t++) {
            const uint32_t *ix = indices + 3u * t;
            if (!input_tri_ok(verts, nverts, ix)) continue;
            fm_vec3_t tri[3];
            for (int k = 0; k < 3; k++) memcpy(&tri[k], verts + 3u * ix[k], 12);
            if (!tri_has_area(tri)) continue;
            for (int k = 0; k < 3; k++)
                for (int a = 0; a < 3; a++) {
                    lo[a] = f_min(lo[a], tri[k].v[a]);
                    hi[a] = f_max(hi[a], tri[k].v[a]);
                }
        }
        for (int a = 0; a < 3; a++) {
            if (!(lo[a] <= hi[a])) lo[a] = hi[a] = 0.0f;
            m->qorigin[a] = lo[a];
            m->qscale[a] = (hi[a] - lo[a]) / QMAX;
        }
        uint16_t *q = (uint16_t *)(void *)(base + m->off_verts);
        for (uint32_t v = 0; v < nverts; v++) {
            for (int a = 0; a < 3; a++) {
                float x = verts[3u * v + a];
                float f = m->qscale[a] > 0.0f ? (x - m->qorigin[a]) / m->qscale[a] + 0.5f : 0.0f;
                if (!(f > 0.0f)) f = 0.0f;
                if (f > QMAX) f = QMAX;
                q[3u * v + a] = (uint16_t)f;
            }
        }
    } else {
        float *f = (float *)(void *)(base + m->off_verts);
        for (uint32_t v = 0; v < nverts; v++) {
            bool ok = vfinite(verts + 3u * v);
            for (int a = 0; a < 3; a++) f[3u * v + a] = ok ? verts[3u * v + a] : 0.0f;
        }
    }
    memset(base + l.off_verts + (uint64_t)nverts * (quant ? 6u : 12u), 0,
           (size_t)(l.off_tris - l.off_verts - (uint64_t)nverts * (quant ? 6u : 12u)));

    /* More than 65535 vertices: 16-bit indices from a base per block of triangles when
     * every block's triangles lie within 65535 vertices of it (meshes as modelled and
     * exported do: neighbouring triangles share nearby vertices), else 32-bit ones. */
    uint32_t nt_kept = 0;
    const uint32_t *tbase = NULL;
    if (!(flags & COLL_MESHF_IDX16)) {
        for (uint32_t t = 0; t < ntris; t++) nt_kept += tri_kept(m, verts, nverts, indices, t);
        /* the bases go where that layout puts them, inside the 32-bit one's indices (which
         * overwrite them when a block does not fit) */
        coll_mesh_layout_t lb = coll_mesh_layout_of(flags | COLL_MESHF_IDXBLK, nverts, nt_kept, 0, 0);
        if (lb.off_cells > buf_size) return COLL_ERR_BUFFER_TOO_SMALL;
        uint32_t *tb = (uint32_t *)(void *)(base + lb.off_tbase);
        if (nt_kept > 0u && block_bases(m, verts, nverts, indices, ntris, tb)) {
            flags |= COLL_MESHF_IDXBLK;
            m->flags = flags;
            tbase = tb;
        }
    }

    /* Triangles: usable ones compacted in input order; bounds and mean size from the
     * stored (possibly quantized) vertices. */
    uint32_t nt = 0;
    float lo[3] = { INFINITY, INFINITY, INFINITY }, hi[3] = { -INFINITY, -INFINITY, -INFINITY };
    float extent_sum = 0.0f;
    size_t stride = (flags & (COLL_MESHF_IDX16 | COLL_MESHF_IDXBLK)) ? 6u : 12u;
    for (uint32_t t = 0; t < ntris; t++) {
        const uint32_t *ix = indices + 3u * t;
        if (!input_tri_ok(verts, nverts, ix)) continue;
        fm_vec3_t tri[3] = { vertex_of(m, ix[0]), vertex_of(m, ix[1]), vertex_of(m, ix[2]) };
        if (!tri_has_area(tri)) continue;
        if (l.off_tris + (uint64_t)(nt + 1u) * stride > buf_size) return COLL_ERR_BUFFER_TOO_SMALL;
        uint8_t *dst = base + l.off_tris + (size_t)nt * stride;
        if (flags & COLL_MESHF_IDX16) {
            uint16_t *d = (uint16_t *)(void *)dst;
            d[0] = (uint16_t)ix[0]; d[1] = (uint16_t)ix[1]; d[2] = (uint16_t)ix[2];
        } else if (tbase) {
            uint32_t bbase = tbase[nt >> COLL_MESH_TRI_BLOCK_SHIFT];
            uint16_t *d = (uint16_t *)(void *)dst;
            d[0] = (uint16_t)(ix[0] - bbase); d[1] = (uint16_t)(ix[1] - bbase); d[2] = (uint16_t)(ix[2] - bbase);
        } else {
            uint32_t *d = (uint32_t *)(void *)dst;
            d[0] = ix[0]; d[1] = ix[1]; d[2] = ix[2];
        }
        float e = 0.0f;
        for (int a = 0; a < 3; a++) {
            float mn = f_min(tri[0].v[a], f_min(tri[1].v[a], tri[2].v[a]));
            float mx = f_max(tri[0].v[a], f_max(tri[1].v[a], tri[2].v[a]));
            lo[a] = f_min(lo[a], mn);
            hi[a] = f_max(hi[a], mx);
            e = f_max(e, mx - mn);
        }
        extent_sum += e;
        nt++;
    }
    if (nt == 0)
        for (int a = 0; a < 3; a++) lo[a] = hi[a] = 0.0f;
    m->ntris = nt;
    if (nt <= 65535u) m->flags |= COLL_MESHF_REF16;
    flags = m->flags;
    for (int a = 0; a < 3; a++) { m->bmin[a] = lo[a]; m->bmax[a] = hi[a]; }

    /* Grid. */
    grid_t g;
    choose_grid(m, opts ? opts->cell_size : 0.0f, nt ? extent_sum / (float)(int32_t)nt : 1.0f, &g);
    uint64_t ncells = (uint64_t)g.dims[0] * g.dims[1] * g.dims[2];
    if (g.nbuckets) {
        ncells = g.nbuckets;
        m->flags |= COLL_MESHF_HASH;
        m->nbuckets = g.nbuckets;
        flags = m->flags;
    }
    l = coll_mesh_layout_of(flags, nverts, nt, ncells, 0);
    if (l.off_refs > buf_size) return COLL_ERR_BUFFER_TOO_SMALL;
    uint64_t tris_end = l.off_tris + (uint64_t)nt * stride, tbase_end = l.off_tbase + l.ntbase * 4u;
    memset(base + tris_end, 0, (size_t)(l.off_tbase - tris_end));
    memset(base + tbase_end, 0, (size_t)(l.off_cells - tbase_end));
    uint32_t *cells = (uint32_t *)(void *)(base + l.off_cells);
    memset(cells, 0, (size_t)(l.off_refs - l.off_cells));
    bool codes = !quant && !g.nbuckets; /* may have the codes: their cover summed */
    hist_ctx_t hc = { cells, codes ? &g : NULL, {0}, {0}, 0u };
    for (uint32_t t = 0; t < nt; t++) {
        fm_vec3_t tri[3];
        coll_mesh_tri_local(m, t, tri);
        if (codes) code_box(&g, tri, hc.lo, hc.hi);
        for_each_cell_of_tri(&g, tri, hist_visit, &hc);
    }
    uint32_t run = 0;
    for (uint64_t c = 0; c < ncells; c++) { run += cells[c]; cells[c] = run; }
    cells[ncells] = run;
    /* The sub-cell codes (COLL_MESHF_RCODE): a float mesh's dense grid, where the blob
     * stays within 24 bytes a triangle with them (a small mesh, of fewer than CODES_ALWAYS
     * input triangles, always). Not the buffer's size: coll_mesh_build_size() has room
     * (24 bytes a triangle is below its bound for a mesh without them). And only where
     * they pay: where a ref's triangle covers few of its cell's 16 quarters. A query
     * rejects an entry from its code at about a quarter of the cost of the float test of
     * its vertices, but only those whose quarters its box misses; triangles as large as
     * their cells (a few big faces in coarse cells: over CODES_MAX_COVER quarters a ref on
     * average) leave too few (measured on the bench courses: the sample level as baked
     * covers 4.9 quarters a ref, Jolt's terrain 3.4; the crack course's 6.4 and the real
     * stairs' 6.9 made those courses 0.3-1 % dearer with the codes). */
    if (codes && hc.cover <= CODES_MAX_COVER * (uint64_t)run) {
        coll_mesh_layout_t lc = coll_mesh_layout_of(flags | COLL_MESHF_RCODE, nverts, nt, ncells, run);
        if (ntris < CODES_ALWAYS || lc.total < 24u * (uint64_t)nt) {
            flags |= COLL_MESHF_RCODE;
            m->flags = flags;
        }
    }
    l = coll_mesh_layout_of(flags, nverts, nt, ncells, run);
    if (l.total > buf_size || l.total > 0xFFFFFFF8u) return COLL_ERR_BUFFER_TOO_SMALL;
    fill_ctx_t fc = { cells, base + l.off_refs, (flags & COLL_MESHF_REF16) != 0, 0,
                      (flags & COLL_MESHF_RCODE) ? base + l.off_codes : NULL, &g, {0}, {0}, 0u };
    for (uint32_t t = nt; t-- > 0;) {
        fm_vec3_t tri[3];
        fc.tri = t;
        coll_mesh_tri_local(m, t, tri);
        if (fc.codes) code_box(&g, tri, fc.lo, fc.hi);
        for_each_cell_of_tri(&g, tri, fill_visit, &fc);
    }
    uint64_t refs_end = l.off_refs + (uint64_t)run * ((flags & COLL_MESHF_REF16) ? 2u : 4u);
    memset(base + refs_end, 0, (size_t)(l.off_codes - refs_end));
    uint64_t codes_end = l.off_codes + ((flags & COLL_MESHF_RCODE) ? run : 0u);
    memset(base + codes_end, 0, (size_t)(l.total - codes_end));

    m->nrefs = run;
    for (int a = 0; a < 3; a++) { m->grid_origin[a] = g.origin[a]; m->dims[a] = g.dims[a]; }
    m->cell_size = g.cell;
    m->grid_margin = g.margin;
    m->off_cells = (uint32_t)l.off_cells;
    m->off_refs = (uint32_t)l.off_refs;
    m->total_size = (uint32_t)l.total;
    m->checksum = checksum_native(m);
    m->magic = COLL_MESH_MAGIC_NATIVE;
    *out = m;
    return COLL_OK;
}

/* ------------------------------------------------------------------ load ----------- */

static bool hdr_float_ok(float f) { return isfinite(f); }

/* Validates the blob read with or without byte swapping; touches nothing. */
static coll_err_t validate(const uint8_t *b, size_t size, bool swap)
{
    struct coll_mesh_s h;
    for (uint32_t w = 0; w < sizeof h / 4u; w++) {
        uint32_t v = rd32(b + 4u * w, swap);
        memcpy((uint8_t *)&h + 4u * w, &v, 4);
    }
    if (h.version < COLL_MESH_VERSION_MIN || h.version > COLL_MESH_VERSION) return COLL_ERR_VERSION;
    if (h.total_size > size) return COLL_ERR_TRUNCATED;
    if (h.total_size < sizeof h || (h.total_size & 7u)) return COLL_ERR_CORRUPT;
    if (h.flags & ~(uint32_t)COLL_MESHF_ALL) return COLL_ERR_CORRUPT;
    bool hashed = (h.flags & COLL_MESHF_HASH) != 0u;
    if (hashed ? (h.nbuckets == 0u || (h.nbuckets & (h.nbuckets - 1u)) != 0u) : h.nbuckets != 0u)
        return COLL_ERR_CORRUPT;
    uint64_t limit = h.total_size;
    if (h.nverts > limit || h.ntris > limit || h.nrefs > limit) return COLL_ERR_CORRUPT;
    uint64_t ncells = 1;
    for (int a = 0; a < 3; a++) {
        if (h.dims[a] == 0u || h.dims[a] > 1048576u) return COLL_ERR_CORRUPT;
        ncells *= h.dims[a];
        if (!hashed && ncells > limit) return COLL_ERR_CORRUPT;
    }
    if (hashed) ncells = h.nbuckets;
    if (ncells > limit) return COLL_ERR_CORRUPT;
    for (int a = 0; a < 3; a++) {
        if (!hdr_float_ok(h.bmin[a]) || !hdr_float_ok(h.bmax[a]) || !hdr_float_ok(h.grid_origin[a]) ||
            !hdr_float_ok(h.qorigin[a]) || !hdr_float_ok(h.qscale[a]))
            return COLL_ERR_CORRUPT;
        if (!(h.bmin[a] <= h.bmax[a]) || h.qscale[a] < 0.0f) return COLL_ERR_CORRUPT;
    }
    if (!hdr_float_ok(h.cell_size) || !(h.cell_size > 0.0f)) return COLL_ERR_CORRUPT;
    if (!hdr_float_ok(h.grid_margin) || !(h.grid_margin >= 0.0f) || !(h.grid_margin < h.cell_size) || h.reserved != 0u)
        return COLL_ERR_CORRUPT; /* finite first: no ordered compare of a NaN (the console emulator traps) */
    if ((h.flags & COLL_MESHF_IDX16) && h.nverts > 65536u) return COLL_ERR_CORRUPT;
    /* block-based indices: version 4 only, and never together with plain 16-bit ones */
    if ((h.flags & COLL_MESHF_IDXBLK) && (h.version < 4u || (h.flags & COLL_MESHF_IDX16))) return COLL_ERR_CORRUPT;
    if ((h.flags & COLL_MESHF_REF16) && h.ntris > 65536u) return COLL_ERR_CORRUPT;
    /* sub-cell codes: version 5 only, and a dense grid's */
    if ((h.flags & COLL_MESHF_RCODE) && (h.version < 5u || hashed)) return COLL_ERR_CORRUPT;
    coll_mesh_layout_t l = coll_mesh_layout_of(h.flags, h.nverts, h.ntris, ncells, h.nrefs);
    if (l.off_verts != h.off_verts || l.off_tris != h.off_tris || l.off_cells != h.off_cells ||
        l.off_refs != h.off_refs || l.total != h.total_size)
        return COLL_ERR_CORRUPT;

    section_t s[NSECT];
    sections_of(h.flags, &l, h.nverts, h.ntris, ncells, h.nrefs, s);
    if (checksum_of(b, swap, s) != h.checksum) return COLL_ERR_CORRUPT;

    /* Contents. */
    if (!(h.flags & COLL_MESHF_QUANT)) {
        for (uint64_t k = 0; k < s[0].count; k++)
            if (!isfinite(u2f(rd32(b + s[0].off + 4u * k, swap)))) return COLL_ERR_CORRUPT;
    }
    const section_t *st = &s[SECT_TRIS], *sb = &s[SECT_TBASE];
    for (uint64_t k = 0; k < st->count; k++) {
        uint64_t v = st->esize == 2u ? rd16(b + st->off + 2u * k, swap) : rd32(b + st->off + 4u * k, swap);
        if (h.flags & COLL_MESHF_IDXBLK) v += rd32(b + sb->off + 4u * ((k / 3u) >> COLL_MESH_TRI_BLOCK_SHIFT), swap);
        if (v >= h.nverts) return COLL_ERR_CORRUPT;
    }
    uint32_t prev = 0;
    for (uint64_t k = 0; k <= ncells; k++) {
        uint32_t v = rd32(b + s[SECT_CELLS].off + 4u * k, swap);
        if ((k == 0 && v != 0u) || v < prev || v > h.nrefs) return COLL_ERR_CORRUPT;
        prev = v;
    }
    if (prev != h.nrefs) return COLL_ERR_CORRUPT;
    const section_t *sr = &s[SECT_REFS];
    for (uint64_t k = 0; k < sr->count; k++) {
        uint32_t v = sr->esize == 2u ? rd16(b + sr->off + 2u * k, swap) : rd32(b + sr->off + 4u * k, swap);
        if (v >= h.ntris) return COLL_ERR_CORRUPT;
    }
    /* each code's nibbles are a run of one to four quarters (what the builder writes) */
    const section_t *sc = &s[SECT_CODES];
    for (uint64_t k = 0; k < sc->count; k++) {
        uint32_t c = b[sc->off + k];
        for (int n = 0; n < 2; n++) {
            uint32_t q = (c >> (4 * n)) & 15u, low = q & (0u - q); /* lowest bit set */
            if (q == 0u || ((q + low) & q) != 0u) return COLL_ERR_CORRUPT;
        }
    }
    return COLL_OK;
}

static void swap_in_place(uint8_t *b)
{
    uint32_t *w = (uint32_t *)(void *)b;
    for (uint32_t i = 0; i < sizeof(struct coll_mesh_s) / 4u; i++) w[i] = bswap32(w[i]);
    const coll_mesh_t *m = (const coll_mesh_t *)(void *)b;
    coll_mesh_layout_t l = layout_of_mesh(m);
    section_t s[NSECT];
    sections_of(m->flags, &l, m->nverts, m->ntris, ncells_of(m), m->nrefs, s);
    for (int i = 0; i < NSECT; i++) {
        if (s[i].esize == 1u) continue; /* bytes */
        if (s[i].esize == 2u) {
            uint16_t *p = (uint16_t *)(void *)(b + s[i].off);
            for (uint64_t k = 0; k < s[i].count; k++) p[k] = bswap16(p[k]);
        } else {
            uint32_t *p = (uint32_t *)(void *)(b + s[i].off);
            for (uint64_t k = 0; k < s[i].count; k++) p[k] = bswap32(p[k]);
        }
    }
}

coll_err_t coll_mesh_load(void *blob, size_t size, const coll_mesh_t **out)
{
    if (out) *out = NULL;
    if (!blob || !out) return COLL_ERR_INVALID_ARG;
    if ((uintptr_t)blob & 7u) return COLL_ERR_ALIGNMENT;
    if (size < 4u) return COLL_ERR_TRUNCATED;
    uint8_t *b = blob;
    bool le = host_is_le();
    bool native;
    if (rd32(b, false) == COLL_MESH_MAGIC_NATIVE) native = true;
    else if (rd32(b, le) == COLL_MESH_MAGIC_BLOB) native = false;
    else return COLL_ERR_BAD_MAGIC;
    /* another version first: an older (shorter-headed) blob says so, not "truncated" */
    if (size >= 8u) {
        uint32_t v = rd32(b + 4, !native && le);
        if (v < COLL_MESH_VERSION_MIN || v > COLL_MESH_VERSION) return COLL_ERR_VERSION;
    }
    if (size < sizeof(struct coll_mesh_s)) return COLL_ERR_TRUNCATED;
    bool swap = !native && le;
    coll_err_t err = validate(b, size, swap);
    if (err != COLL_OK) return err;
    if (swap) swap_in_place(b);
    ((coll_mesh_t *)blob)->magic = COLL_MESH_MAGIC_NATIVE;
    *out = blob;
    return COLL_OK;
}

/* ------------------------------------------------------------------ write ---------- */

coll_err_t coll_mesh_write_blob(const coll_mesh_t *m, void *out, size_t out_size, size_t *written)
{
    if (written) *written = 0;
    if (!m || m->magic != COLL_MESH_MAGIC_NATIVE) return COLL_ERR_INVALID_ARG;
    if (written) *written = m->total_size;
    if (!out) return COLL_ERR_INVALID_ARG;
    if (out_size < m->total_size) return COLL_ERR_BUFFER_TOO_SMALL;
    uint8_t *o = out;
    const uint8_t *b = (const uint8_t *)m;
    memset(o, 0, m->total_size);
    for (uint32_t w = 0; w < sizeof(struct coll_mesh_s) / 4u; w++) wr32be(o + 4u * w, rd32(b + 4u * w, false));
    wr32be(o, COLL_MESH_MAGIC_BLOB);
    coll_mesh_layout_t l = layout_of_mesh(m);
    section_t s[NSECT];
    sections_of(m->flags, &l, m->nverts, m->ntris, ncells_of(m), m->nrefs, s);
    for (int i = 0; i < NSECT; i++) {
        for (uint64_t k = 0; k < s[i].count; k++) {
            if (s[i].esize == 1u) o[s[i].off + k] = b[s[i].off + k];
            else if (s[i].esize == 2u) wr16be(o + s[i].off + 2u * k, rd16(b + s[i].off + 2u * k, false));
            else wr32be(o + s[i].off + 4u * k, rd32(b + s[i].off + 4u * k, false));
        }
    }
    return COLL_OK;
}
