/**
 * @file collbake.c
 * @brief Bakes a level (any format assimp reads: glTF 2.0, OBJ, ...) into the big-endian
 *        collision-mesh blob that coll_mesh_load() uses in place.
 *
 * Pipeline: import (assimp, triangulated) -> select nodes/meshes (--only) and apply node
 * transforms and --scale -> weld vertices (hash grid) -> drop collapsed, degenerate and
 * duplicate triangles -> compact vertices -> coll_mesh_build() (the runtime's own builder,
 * so there is one implementation of the layout) -> coll_mesh_write_blob() -> write the file,
 * read it back and coll_mesh_load() it as a final check -> print a summary.
 *
 * Host-only: uses malloc and stdio freely. Every failure prints "ERROR: <file>: ..." and
 * exits 1; it never writes a partial output file.
 */
#define _GNU_SOURCE
#include <assimp/cimport.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <errno.h>
#include <fnmatch.h>
#include <math.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "coll/mesh.h"
#include "mesh_format.h"
#include "bsp.h"

#define MAX_ONLY 32
#define BIG_TRI_CELLS 64     /* warn about triangles referenced by more cells than this */
#define SLIVER_ALTITUDE 1e-3 /* meters */
#define SLIVER_ASPECT 1000.0
#define COORD_WARN 1e4       /* beyond this, float spacing exceeds ~1 mm */
#define COORD_MAX 1e6        /* beyond this, refuse: float spacing ~6 cm */

typedef struct {
    const char *input, *output, *dump_raw, *report;
    const char *only[MAX_ONLY];
    int nonly;
    float cell_size, scale, weld, max_quant_error;
    double bsp_unit, min_kept;
    int quantize, verbose, bsp_all_models;
    int cell_choice; /* CELL_CHOICE_*: how the automatic cell is chosen */
} opts_t;

enum { CELL_CHOICE_RUNTIME, CELL_CHOICE_COST };

static const char *g_file = "collbake";

static void die(const char *fmt, ...)
{
    va_list ap;
    fflush(stdout);
    va_start(ap, fmt);
    fprintf(stderr, "ERROR: %s: ", g_file);
    vfprintf(stderr, fmt, ap);
    fputc('\n', stderr);
    va_end(ap);
    exit(1);
}

static void warn(const char *fmt, ...)
{
    va_list ap;
    fflush(stdout);
    va_start(ap, fmt);
    fprintf(stderr, "WARNING: %s: ", g_file);
    vfprintf(stderr, fmt, ap);
    fputc('\n', stderr);
    va_end(ap);
}

static void *xmalloc(size_t n)
{
    void *p = malloc(n ? n : 1);
    if (!p) die("out of memory (%zu bytes)", n);
    return p;
}

static void *xcalloc(size_t n, size_t s)
{
    void *p = calloc(n ? n : 1, s ? s : 1);
    if (!p) die("out of memory (%zu x %zu bytes)", n, s);
    return p;
}

/* Aligned so coll_mesh_build/coll_mesh_load accept it. */
static void *xalloc8(size_t n)
{
    void *p = NULL;
    if (posix_memalign(&p, 8, n ? n : 8) != 0) die("out of memory (%zu bytes)", n);
    return p;
}

static void usage(FILE *f)
{
    fprintf(f,
        "usage: collbake [options] INPUT -o OUTPUT.coll\n"
        "Bakes the triangles of a level (glTF 2.0 .gltf/.glb, .obj, or any format assimp reads)\n"
        "into a collision-mesh blob for coll_mesh_load(). Node transforms are applied.\n"
        "  -o FILE             output blob (big-endian, checksummed)\n"
        "  --cell-size M       grid cell edge in meters (default: automatic)\n"
        "  --cell-choice C     how the automatic cell is chosen: runtime (default: coll_mesh_build's own,\n"
        "                      for memory) or cost (that one or a candidate cell whose grid a character\n"
        "                      step is estimated to walk cheaper, within 10 %% more bytes)\n"
        "  --scale S           uniform scale after node transforms (0.01 for a centimeter level)\n"
        "  --only PATTERN      bake only meshes whose node, an ancestor node or the mesh itself has a\n"
        "                      name matching this fnmatch pattern, e.g. '*_coll' (repeatable; default all)\n"
        "  --weld TOL          merge vertices closer than TOL meters (default 0.0001; 0: exact only)\n"
        "  --quantize          16-bit vertices when the worst-case error stays below --max-quant-error\n"
        "  --max-quant-error M largest acceptable quantization error (default 0.005 m)\n"
        "  --bsp-unit M        Quake III .bsp input: metres per Quake unit (default 0.032); Quake's\n"
        "                      Z up becomes Y up\n"
        "  --bsp-all-models    .bsp: also the brush entities' surfaces (doors, platforms; default: world only)\n"
        "  --min-kept F        refuse the bake when fewer than F of the input triangles survive\n"
        "                      welding and the degenerate/duplicate filter (default 0.5; 0: never)\n"
        "  --dump-raw FILE     also write the welded triangles: little-endian \"CRAW\", u32 version 1,\n"
        "                      u32 nverts, u32 ntris, nverts*3 f32, ntris*3 u32\n"
        "  --report FILE       also write the summary as 'key value' lines\n"
        "  -v                  list every node and mesh taken or skipped\n"
        "  -h, --help          this text\n");
}

static float parse_float(const char *opt, const char *s, float lo)
{
    char *end = NULL;
    errno = 0;
    double d = s ? strtod(s, &end) : 0.0;
    if (!s || errno || end == s || *end || !isfinite(d) || d < lo)
        die("%s needs a number >= %g, got '%s'", opt, (double)lo, s ? s : "");
    return (float)d;
}

static void parse_args(int argc, char **argv, opts_t *o)
{
    memset(o, 0, sizeof *o);
    o->scale = 1.0f;
    o->weld = 1e-4f;
    o->max_quant_error = 0.005f;
    o->bsp_unit = 0.032;
    o->min_kept = 0.5;
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i];
        const char *next = i + 1 < argc ? argv[i + 1] : NULL;
        if (!strcmp(a, "-h") || !strcmp(a, "--help")) { usage(stdout); exit(0); }
        else if (!strcmp(a, "-v")) o->verbose = 1;
        else if (!strcmp(a, "--quantize")) o->quantize = 1;
        else if (!strcmp(a, "-o") && next) { o->output = next; i++; }
        else if (!strcmp(a, "--dump-raw") && next) { o->dump_raw = next; i++; }
        else if (!strcmp(a, "--report") && next) { o->report = next; i++; }
        else if (!strcmp(a, "--cell-size")) { o->cell_size = parse_float(a, next, 0.0f); i++; }
        else if (!strcmp(a, "--cell-choice") && next) {
            if (!strcmp(next, "cost")) o->cell_choice = CELL_CHOICE_COST;
            else if (!strcmp(next, "runtime")) o->cell_choice = CELL_CHOICE_RUNTIME;
            else die("--cell-choice is cost or runtime, got '%s'", next);
            i++;
        }
        else if (!strcmp(a, "--scale")) {
            o->scale = parse_float(a, next, 0.0f); i++;
            if (!(o->scale > 0.0f)) die("--scale must be > 0");
        }
        else if (!strcmp(a, "--weld")) { o->weld = parse_float(a, next, 0.0f); i++; }
        else if (!strcmp(a, "--bsp-unit")) {
            o->bsp_unit = parse_float(a, next, 0.0f); i++;
            if (!(o->bsp_unit > 0.0)) die("--bsp-unit must be > 0");
        }
        else if (!strcmp(a, "--bsp-all-models")) o->bsp_all_models = 1;
        else if (!strcmp(a, "--min-kept")) {
            o->min_kept = parse_float(a, next, 0.0f); i++;
            if (o->min_kept > 1.0) die("--min-kept is a share, 0..1");
        }
        else if (!strcmp(a, "--max-quant-error")) { o->max_quant_error = parse_float(a, next, 0.0f); i++; }
        else if (!strcmp(a, "--only") && next) {
            if (o->nonly == MAX_ONLY) die("more than %d --only patterns", MAX_ONLY);
            o->only[o->nonly++] = next; i++;
        }
        else if (a[0] == '-' && a[1]) { usage(stderr); die("unknown or incomplete option '%s'", a); }
        else if (!o->input) o->input = a;
        else { usage(stderr); die("more than one input ('%s' and '%s')", o->input, a); }
    }
    if (!o->input) { usage(stderr); die("no input file"); }
    g_file = o->input;
    if (!o->output) die("no output file (-o)");
}

/* ------------------------------------------------------------------ import -------- */

typedef struct {
    double *p;        /* 9 doubles per triangle, world space, scaled */
    size_t n, cap;    /* triangles */
    unsigned nodes, meshes_taken, meshes_skipped, nontri_faces, bad_faces, nonfinite;
    int is_bsp;
    bsp_stats_t bsp;
    double scale;     /* the BSP reader's triangles get --scale here */
} soup_t;

static void soup_push(soup_t *s, const double t[9])
{
    if (s->n == s->cap) {
        s->cap = s->cap ? 2 * s->cap : 1024;
        double *np = realloc(s->p, s->cap * 9 * sizeof(double));
        if (!np) die("out of memory (%zu triangles)", s->cap);
        s->p = np;
    }
    memcpy(s->p + 9 * s->n++, t, 9 * sizeof(double));
}

typedef struct { double m[3][4]; } xform_t; /* rows of an affine 3x4 */

static xform_t xf_mul(const xform_t *a, const xform_t *b)
{
    xform_t r;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 4; j++) {
            double v = a->m[i][0] * b->m[0][j] + a->m[i][1] * b->m[1][j] + a->m[i][2] * b->m[2][j];
            r.m[i][j] = v + (j == 3 ? a->m[i][3] : 0.0);
        }
    return r;
}

static int name_matches(const opts_t *o, const char *name)
{
    for (int i = 0; i < o->nonly; i++)
        if (name && fnmatch(o->only[i], name, 0) == 0) return 1;
    return 0;
}

static void walk(const struct aiScene *sc, const struct aiNode *nd, const xform_t *parent, int inherited,
                 const opts_t *o, soup_t *s, int depth)
{
    if (depth > 256) die("node hierarchy deeper than 256 levels");
    const struct aiMatrix4x4 *t = &nd->mTransformation;
    xform_t local = {{{t->a1, t->a2, t->a3, t->a4}, {t->b1, t->b2, t->b3, t->b4}, {t->c1, t->c2, t->c3, t->c4}}};
    xform_t world = xf_mul(parent, &local);
    const char *nname = nd->mName.data;
    int sel = inherited || o->nonly == 0 || name_matches(o, nname);
    s->nodes++;
    for (unsigned k = 0; k < nd->mNumMeshes; k++) {
        unsigned mi = nd->mMeshes[k];
        if (mi >= sc->mNumMeshes || !sc->mMeshes[mi]) { s->bad_faces++; continue; }
        const struct aiMesh *m = sc->mMeshes[mi];
        int take = sel || name_matches(o, m->mName.data);
        if (o->verbose)
            printf("  %-5s node '%s' mesh '%s': %u faces, %u vertices\n", take ? "take" : "skip", nname,
                   m->mName.data, m->mNumFaces, m->mNumVertices);
        if (!take) { s->meshes_skipped++; continue; }
        s->meshes_taken++;
        if (!m->mVertices) { s->nontri_faces += m->mNumFaces; continue; }
        for (unsigned f = 0; f < m->mNumFaces; f++) {
            const struct aiFace *face = &m->mFaces[f];
            if (face->mNumIndices != 3) { s->nontri_faces++; continue; }
            double tri[9];
            int ok = 1;
            for (int c = 0; c < 3 && ok; c++) {
                unsigned vi = face->mIndices[c];
                if (vi >= m->mNumVertices) { ok = 0; s->bad_faces++; break; }
                const struct aiVector3D *v = &m->mVertices[vi];
                for (int a = 0; a < 3; a++) {
                    double w = world.m[a][0] * v->x + world.m[a][1] * v->y + world.m[a][2] * v->z + world.m[a][3];
                    w *= o->scale;
                    if (!isfinite(w)) { ok = 0; s->nonfinite++; break; }
                    tri[3 * c + a] = w;
                }
            }
            if (ok) soup_push(s, tri);
        }
    }
    for (unsigned c = 0; c < nd->mNumChildren; c++)
        if (nd->mChildren && nd->mChildren[c]) walk(sc, nd->mChildren[c], &world, sel && o->nonly > 0, o, s, depth + 1);
}

static void bsp_tri(void *user, const double t[9])
{
    soup_t *s = user;
    double u[9];
    for (int k = 0; k < 9; k++) {
        u[k] = t[k] * s->scale;
        if (!isfinite(u[k])) { s->nonfinite++; return; }
    }
    soup_push(s, u);
}

/* A Quake III .bsp (IBSP magic): our own reader (assimp's leaves face indices unset). */
static int import_bsp(const opts_t *o, soup_t *s)
{
    FILE *f = fopen(o->input, "rb");
    if (!f) die("cannot open: %s", strerror(errno));
    unsigned char magic[4];
    size_t got = fread(magic, 1, 4, f);
    if (got < 4 || !bsp_is_bsp(magic, 4)) { fclose(f); return 0; }
    if (fseek(f, 0, SEEK_END) != 0) die("cannot seek: %s", strerror(errno));
    long len = ftell(f);
    if (len < 0 || len > 0x7FFFFFFFL) die("cannot size the file");
    rewind(f);
    unsigned char *d = xmalloc((size_t)len);
    if (fread(d, 1, (size_t)len, f) != (size_t)len) die("cannot read: %s", strerror(errno));
    fclose(f);
    memset(s, 0, sizeof *s);
    s->is_bsp = 1;
    s->scale = o->scale;
    const char *err = bsp_read(d, (size_t)len, o->bsp_unit, o->bsp_all_models, bsp_tri, s, &s->bsp);
    free(d);
    if (err) die("Quake III BSP: %s", err);
    if (s->n == 0)
        die("no triangles: the BSP has %u surfaces in the %s, none solid with geometry (%u non-solid, %u other)",
            s->bsp.surfaces, o->bsp_all_models ? "file" : "world model", s->bsp.nonsolid, s->bsp.other);
    return 1;
}

static void import(const opts_t *o, soup_t *s)
{
    if (import_bsp(o, s)) return;
    const struct aiScene *sc = aiImportFile(o->input, aiProcess_Triangulate | aiProcess_SortByPType);
    if (!sc) {
        const char *msg = aiGetErrorString();
        die("cannot read this file: %s", msg && *msg ? msg : "unknown format");
    }
    if (!sc->mRootNode) { aiReleaseImport(sc); die("no scene graph in the file"); }
    memset(s, 0, sizeof *s);
    xform_t ident = {{{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}}};
    walk(sc, sc->mRootNode, &ident, 0, o, s, 0);
    unsigned nmeshes = sc->mNumMeshes;
    aiReleaseImport(sc);
    if (s->n == 0) {
        if (s->meshes_taken == 0 && o->nonly > 0)
            die("no triangles: no node or mesh name matched --only (%u meshes, %u mesh instances skipped; "
                "-v lists the names)", nmeshes, s->meshes_skipped);
        if (nmeshes == 0) die("no triangles: the file holds no meshes");
        die("no triangles: %u meshes taken, none with a usable triangle (skipped: %u point/line faces, "
            "%u faces with bad indices, %u with non-finite vertices)", s->meshes_taken, s->nontri_faces,
            s->bad_faces, s->nonfinite);
    }
}

/* ------------------------------------------------------------------ weld ---------- */

typedef struct {
    float *v;          /* 3 floats per vertex */
    uint32_t nv;
    uint32_t *idx;     /* 3 per triangle */
    uint32_t nt;
    uint32_t in_tris, collapsed, degenerate, duplicate;
    uint32_t in_verts;
} welded_t;

static uint64_t hash3(int64_t x, int64_t y, int64_t z)
{
    uint64_t h = (uint64_t)x * 0x9E3779B97F4A7C15ull;
    h ^= (uint64_t)y * 0xC2B2AE3D27D4EB4Full + (h << 6) + (h >> 2);
    h ^= (uint64_t)z * 0x165667B19E3779F9ull + (h << 6) + (h >> 2);
    h ^= h >> 29;
    return h;
}

/* Same criterion as the runtime builder (tri_has_area in src/coll/mesh.c), in double. */
static int has_area(const float *a, const float *b, const float *c)
{
    double e1[3], e2[3], n[3];
    for (int k = 0; k < 3; k++) { e1[k] = (double)b[k] - a[k]; e2[k] = (double)c[k] - a[k]; }
    n[0] = e1[1] * e2[2] - e1[2] * e2[1];
    n[1] = e1[2] * e2[0] - e1[0] * e2[2];
    n[2] = e1[0] * e2[1] - e1[1] * e2[0];
    double n2 = n[0] * n[0] + n[1] * n[1] + n[2] * n[2];
    double l1 = e1[0] * e1[0] + e1[1] * e1[1] + e1[2] * e1[2];
    double l2 = e2[0] * e2[0] + e2[1] * e2[1] + e2[2] * e2[2];
    return n2 > 1e-30 && n2 > 1e-10 * l1 * l2; /* a little stricter than the runtime's 1e-12 */
}

static void weld(const soup_t *s, float tol, welded_t *w)
{
    size_t nin = s->n * 3;
    if (s->n > 0x3FFFFFFFu) die("level too large for the format: %zu triangles", s->n);
    memset(w, 0, sizeof *w);
    w->in_tris = (uint32_t)s->n;
    w->in_verts = (uint32_t)nin;
    float *verts = xmalloc(nin * 3 * sizeof(float));
    uint32_t *next = xmalloc(nin * sizeof(uint32_t));
    int64_t *cellkey = xmalloc(nin * 3 * sizeof(int64_t));
    size_t hsize = 1;
    while (hsize < 2 * nin) hsize <<= 1;
    uint32_t *head = xmalloc(hsize * sizeof(uint32_t));
    memset(head, 0xFF, hsize * sizeof(uint32_t));
    uint32_t *remap = xmalloc(nin * sizeof(uint32_t));
    double inv = tol > 0.0f ? 1.0 / tol : 0.0;
    double tol2 = (double)tol * tol;
    uint32_t nv = 0;

    for (size_t i = 0; i < nin; i++) {
        float p[3];
        for (int a = 0; a < 3; a++) p[a] = (float)s->p[3 * i + a];
        int64_t c[3];
        for (int a = 0; a < 3; a++) {
            if (tol > 0.0f) c[a] = (int64_t)floor((double)p[a] * inv);
            else { uint32_t u; memcpy(&u, &p[a], 4); c[a] = (p[a] == 0.0f) ? 0 : (int64_t)u; }
        }
        uint32_t found = UINT32_MAX;
        int r = tol > 0.0f ? 1 : 0;
        for (int dz = -r; dz <= r && found == UINT32_MAX; dz++)
            for (int dy = -r; dy <= r && found == UINT32_MAX; dy++)
                for (int dx = -r; dx <= r && found == UINT32_MAX; dx++) {
                    int64_t q[3] = { c[0] + dx, c[1] + dy, c[2] + dz };
                    for (uint32_t k = head[hash3(q[0], q[1], q[2]) & (hsize - 1)]; k != UINT32_MAX; k = next[k]) {
                        if (cellkey[3 * k] != q[0] || cellkey[3 * k + 1] != q[1] || cellkey[3 * k + 2] != q[2])
                            continue;
                        const float *v = verts + 3 * k;
                        double d2 = 0.0;
                        for (int a = 0; a < 3; a++) d2 += ((double)v[a] - p[a]) * ((double)v[a] - p[a]);
                        if (d2 <= tol2) { found = k; break; }
                    }
                }
        if (found == UINT32_MAX) {
            found = nv++;
            memcpy(verts + 3 * found, p, sizeof p);
            memcpy(cellkey + 3 * found, c, sizeof c);
            size_t h = hash3(c[0], c[1], c[2]) & (hsize - 1);
            next[found] = head[h];
            head[h] = found;
        }
        remap[i] = found;
    }
    free(head);
    free(next);
    free(cellkey);

    /* Triangles: drop collapsed, degenerate and duplicate (same three vertices) ones. */
    uint32_t *idx = xmalloc(s->n * 3 * sizeof(uint32_t));
    size_t tsize = 1;
    while (tsize < 2 * s->n) tsize <<= 1;
    uint32_t *tset = xmalloc(tsize * sizeof(uint32_t));
    memset(tset, 0xFF, tsize * sizeof(uint32_t));
    uint32_t nt = 0;
    for (size_t t = 0; t < s->n; t++) {
        uint32_t a = remap[3 * t], b = remap[3 * t + 1], c = remap[3 * t + 2];
        if (a == b || b == c || a == c) { w->collapsed++; continue; }
        if (!has_area(verts + 3 * a, verts + 3 * b, verts + 3 * c)) { w->degenerate++; continue; }
        uint32_t k[3] = { a, b, c }, tmp;
        if (k[0] > k[1]) { tmp = k[0]; k[0] = k[1]; k[1] = tmp; }
        if (k[1] > k[2]) { tmp = k[1]; k[1] = k[2]; k[2] = tmp; }
        if (k[0] > k[1]) { tmp = k[0]; k[0] = k[1]; k[1] = tmp; }
        size_t h = hash3(k[0], k[1], k[2]) & (tsize - 1);
        int dup = 0;
        for (; tset[h] != UINT32_MAX; h = (h + 1) & (tsize - 1)) {
            const uint32_t *o = idx + 3 * tset[h];
            uint32_t m[3] = { o[0], o[1], o[2] };
            if (m[0] > m[1]) { tmp = m[0]; m[0] = m[1]; m[1] = tmp; }
            if (m[1] > m[2]) { tmp = m[1]; m[1] = m[2]; m[2] = tmp; }
            if (m[0] > m[1]) { tmp = m[0]; m[0] = m[1]; m[1] = tmp; }
            if (m[0] == k[0] && m[1] == k[1] && m[2] == k[2]) { dup = 1; break; }
        }
        if (dup) { w->duplicate++; continue; }
        tset[h] = nt;
        idx[3 * nt] = a; idx[3 * nt + 1] = b; idx[3 * nt + 2] = c;
        nt++;
    }
    free(tset);
    free(remap);

    /* Compact: only referenced vertices, numbered in order of first use. */
    uint32_t *newid = xmalloc((nv ? nv : 1) * sizeof(uint32_t));
    memset(newid, 0xFF, (nv ? nv : 1) * sizeof(uint32_t));
    float *cv = xmalloc((size_t)(nv ? nv : 1) * 3 * sizeof(float));
    uint32_t ncv = 0;
    for (size_t k = 0; k < (size_t)nt * 3; k++) {
        uint32_t v = idx[k];
        if (newid[v] == UINT32_MAX) { newid[v] = ncv; memcpy(cv + 3 * ncv, verts + 3 * v, 12); ncv++; }
        idx[k] = newid[v];
    }
    free(newid);
    free(verts);
    w->v = cv;
    w->nv = ncv;
    w->idx = idx;
    w->nt = nt;
}

/* ------------------------------------------------------------------ analysis ------ */

typedef struct {
    uint32_t slivers, sliver_example;
    uint32_t nonmanifold;
    uint32_t nm_a, nm_b;
} shape_stats_t;

static void analyse_shape(const welded_t *w, shape_stats_t *st)
{
    memset(st, 0, sizeof *st);
    st->sliver_example = UINT32_MAX;
    for (uint32_t t = 0; t < w->nt; t++) {
        const float *p[3] = { w->v + 3 * w->idx[3 * t], w->v + 3 * w->idx[3 * t + 1], w->v + 3 * w->idx[3 * t + 2] };
        double e[3][3], len2[3];
        for (int k = 0; k < 3; k++) {
            for (int a = 0; a < 3; a++) e[k][a] = (double)p[(k + 1) % 3][a] - p[k][a];
            len2[k] = e[k][0] * e[k][0] + e[k][1] * e[k][1] + e[k][2] * e[k][2];
        }
        double n[3] = { e[0][1] * e[1][2] - e[0][2] * e[1][1], e[0][2] * e[1][0] - e[0][0] * e[1][2],
                        e[0][0] * e[1][1] - e[0][1] * e[1][0] };
        double area2 = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        double lmax = sqrt(fmax(len2[0], fmax(len2[1], len2[2])));
        double alt = lmax > 0.0 ? area2 / lmax : 0.0; /* smallest altitude */
        if (alt < SLIVER_ALTITUDE || lmax > SLIVER_ASPECT * alt) {
            if (!st->slivers) st->sliver_example = t;
            st->slivers++;
        }
    }
    /* Edges shared by more than two triangles: open-addressing map of sorted vertex pairs. */
    size_t esize = 1;
    while (esize < 6 * (size_t)w->nt) esize <<= 1;
    uint64_t *keys = xmalloc(esize * sizeof(uint64_t));
    uint32_t *count = xcalloc(esize, sizeof(uint32_t));
    memset(keys, 0xFF, esize * sizeof(uint64_t));
    for (uint32_t t = 0; t < w->nt; t++)
        for (int k = 0; k < 3; k++) {
            uint32_t a = w->idx[3 * t + k], b = w->idx[3 * t + (k + 1) % 3];
            if (a > b) { uint32_t tmp = a; a = b; b = tmp; }
            uint64_t key = ((uint64_t)a << 32) | b;
            size_t h = hash3(a, b, 7) & (esize - 1);
            while (keys[h] != UINT64_MAX && keys[h] != key) h = (h + 1) & (esize - 1);
            keys[h] = key;
            if (++count[h] == 3) {
                if (!st->nonmanifold) { st->nm_a = a; st->nm_b = b; }
                st->nonmanifold++;
            }
        }
    free(keys);
    free(count);
}

typedef struct {
    uint64_t ncells, nonempty;
    uint32_t max_per_cell;
    double mean_per_nonempty;
    uint32_t big_tris, max_cells_of_tri, biggest_tri;
} grid_stats_t;

static void analyse_grid(const coll_mesh_t *m, grid_stats_t *g)
{
    memset(g, 0, sizeof *g);
    g->ncells = coll_mesh_cell_count(m); /* hashed grids: the buckets */
    const uint32_t *cells = coll_mesh_cells(m);
    uint32_t *per_tri = xcalloc(m->ntris ? m->ntris : 1, sizeof(uint32_t));
    for (uint64_t c = 0; c < g->ncells; c++) {
        uint32_t n = cells[c + 1] - cells[c];
        if (n) g->nonempty++;
        if (n > g->max_per_cell) g->max_per_cell = n;
        for (uint32_t k = cells[c]; k < cells[c + 1]; k++) per_tri[coll_mesh_ref(m, k)]++;
    }
    g->mean_per_nonempty = g->nonempty ? (double)m->nrefs / (double)g->nonempty : 0.0;
    for (uint32_t t = 0; t < m->ntris; t++) {
        if (per_tri[t] > g->max_cells_of_tri) { g->max_cells_of_tri = per_tri[t]; g->biggest_tri = t; }
        if (per_tri[t] > BIG_TRI_CELLS) g->big_tris++;
    }
    free(per_tri);
}

/* ------------------------------------------------------------------ output -------- */

static void write_file(const char *path, const void *data, size_t n)
{
    size_t len = strlen(path);
    char *tmp = xmalloc(len + 16);
    snprintf(tmp, len + 16, "%s.tmp%ld", path, (long)getpid());
    FILE *f = fopen(tmp, "wb");
    if (!f) die("cannot create %s: %s", tmp, strerror(errno));
    size_t put = fwrite(data, 1, n, f);
    int bad = ferror(f);
    if (fclose(f) != 0 || put != n || bad) { remove(tmp); die("cannot write %s: %s", path, strerror(errno)); }
    if (rename(tmp, path) != 0) { remove(tmp); die("cannot create %s: %s", path, strerror(errno)); }
    free(tmp);
}

static void put_le32(uint8_t *p, uint32_t v)
{
    p[0] = (uint8_t)v; p[1] = (uint8_t)(v >> 8); p[2] = (uint8_t)(v >> 16); p[3] = (uint8_t)(v >> 24);
}

static void dump_raw(const char *path, const welded_t *w)
{
    size_t n = 16 + (size_t)w->nv * 12 + (size_t)w->nt * 12;
    uint8_t *b = xmalloc(n), *p = b;
    memcpy(p, "CRAW", 4);
    put_le32(p + 4, 1);
    put_le32(p + 8, w->nv);
    put_le32(p + 12, w->nt);
    p += 16;
    for (size_t k = 0; k < (size_t)w->nv * 3; k++, p += 4) { uint32_t u; memcpy(&u, &w->v[k], 4); put_le32(p, u); }
    for (size_t k = 0; k < (size_t)w->nt * 3; k++, p += 4) put_le32(p, w->idx[k]);
    write_file(path, b, n);
    free(b);
}

/* Builds with the runtime's own builder; returns the mesh (in a malloc'd aligned block). */
static const coll_mesh_t *build(const welded_t *w, float cell, int quant, void **block)
{
    coll_mesh_build_opts_t bo = { cell, quant ? (uint32_t)COLL_MESH_QUANTIZE : 0u };
    size_t need = coll_mesh_build_size(w->nv, w->nt, &bo);
    if (need == 0) die("level too large for the format (%u vertices, %u triangles exceed 4 GB blobs)", w->nv, w->nt);
    *block = xalloc8(need);
    const coll_mesh_t *m = NULL;
    coll_err_t err = coll_mesh_build(*block, need, w->v, w->nv, w->idx, w->nt, &bo, &m);
    if (err != COLL_OK) die("coll_mesh_build failed: %s", coll_strerror(err));
    return m;
}

/* ---- the automatic cell, by estimated query cost -------------------------------------
 * The runtime's automatic cell (coll_mesh_build, cell_size 0) is chosen for memory: the
 * finest cell whose grid fits a byte budget per triangle, hashed when a dense grid of that
 * cell has too many cells. On real maps (small detail triangles packed in a few spots) that
 * hashed fine grid walks more cell entries per query than a dense slightly coarser one. The
 * bake can afford to look: it builds a few candidate grids with the runtime's builder (so
 * the chosen grid is exactly the runtime's for that cell) and estimates what a character
 * step's gather walks in each: the cells and cell entries under a character-sized box
 * standing on the level's walkable triangles (COST_* below, area-weighted sample points),
 * weighted by what the walk pays per cell and per entry (x86, gather.c: about 12 and 9
 * instructions). The cheapest candidate within the memory cap wins; the runtime's own
 * choice is a candidate, so the estimate never picks a grid it rates worse. */
#define COST_SAMPLES 4096      /* sample points on walkable triangles (up to) */
#define COST_HALF_W 0.6f       /* the box: a 0.4 m radius capsule with a step's reach, */
#define COST_BELOW 0.6f        /* from the floor's snap reach below the foot */
#define COST_ABOVE 2.0f        /* to above the head (1.8 m) */
#define COST_PER_CELL 12.0
#define COST_PER_ENTRY 9.0
#define COST_MAX_GROWTH 1.10   /* a candidate may take up to 10 % more bytes than the runtime's choice */

typedef struct { float p[3]; } cost_pt_t;

/* Area-weighted points on the upward-facing triangles (normal within 60 degrees of +Y):
 * every triangle's share of COST_SAMPLES by its area, carried over (deterministic). */
static uint32_t cost_points(const welded_t *w, cost_pt_t *pts, uint32_t max)
{
    double total = 0.0;
    for (int pass = 0; pass < 2; pass++) {
        double acc = 0.0;
        uint32_t n = 0;
        for (uint32_t t = 0; t < w->nt; t++) {
            const float *a = &w->v[3 * w->idx[3 * t]], *b = &w->v[3 * w->idx[3 * t + 1]], *c = &w->v[3 * w->idx[3 * t + 2]];
            double e1[3], e2[3], cr[3];
            for (int k = 0; k < 3; k++) { e1[k] = (double)b[k] - a[k]; e2[k] = (double)c[k] - a[k]; }
            cr[0] = e1[1] * e2[2] - e1[2] * e2[1];
            cr[1] = e1[2] * e2[0] - e1[0] * e2[2];
            cr[2] = e1[0] * e2[1] - e1[1] * e2[0];
            double len = sqrt(cr[0] * cr[0] + cr[1] * cr[1] + cr[2] * cr[2]);
            if (!(len > 0.0) || cr[1] < 0.5 * len) continue;
            if (pass == 0) { total += len; continue; }
            acc += len * (double)max / total;
            /* points at fixed barycentric spots (the centroid first) */
            static const float bary[4][2] = { { 1.0f / 3, 1.0f / 3 }, { 0.6f, 0.2f }, { 0.2f, 0.6f }, { 0.2f, 0.2f } };
            for (int j = 0; acc >= 1.0 && n < max; j++, acc -= 1.0) {
                float u = bary[j & 3][0], v = bary[j & 3][1];
                for (int k = 0; k < 3; k++) pts[n].p[k] = a[k] + u * (b[k] - a[k]) + v * (c[k] - a[k]);
                n++;
            }
        }
        if (pass == 1) return n;
        if (!(total > 0.0)) return 0;
    }
    return 0;
}

/* Estimated walk cost of the sample boxes on mesh m (sum over the boxes). */
static double cost_of(const coll_mesh_t *m, const cost_pt_t *pts, uint32_t n)
{
    const uint32_t *cells = coll_mesh_cells(m);
    float inv = 1.0f / m->cell_size;
    double cost = 0.0;
    for (uint32_t i = 0; i < n; i++) {
        float lo[3] = { pts[i].p[0] - COST_HALF_W, pts[i].p[1] - COST_BELOW, pts[i].p[2] - COST_HALF_W };
        float hi[3] = { pts[i].p[0] + COST_HALF_W, pts[i].p[1] + COST_ABOVE, pts[i].p[2] + COST_HALF_W };
        uint32_t cl[3], ch[3];
        for (int a = 0; a < 3; a++) {
            cl[a] = coll_mesh_cell_coord(lo[a] - m->grid_margin, m->bmin[a], inv, m->dims[a]);
            ch[a] = coll_mesh_cell_coord(hi[a] + m->grid_margin, m->bmin[a], inv, m->dims[a]);
        }
        for (uint32_t z = cl[2]; z <= ch[2]; z++)
            for (uint32_t y = cl[1]; y <= ch[1]; y++)
                for (uint32_t x = cl[0]; x <= ch[0]; x++) {
                    uint32_t e = coll_mesh_cell_index(m, x, y, z);
                    cost += COST_PER_CELL + COST_PER_ENTRY * (double)(cells[e + 1] - cells[e]);
                }
    }
    return cost;
}

typedef struct { float cell; double cost, cost_runtime; uint32_t points; int tried; } cell_choice_t;

/* The automatic cell for this level and layout: the runtime's choice, or a cheaper
 * candidate (0.75 m .. 6 m in steps of 1.125: the estimate is sensitive to how the cells fall on the level, so a fine set of candidates, built as explicit cells) within the cap. */
static float choose_cell(const welded_t *w, int quant, cell_choice_t *cc)
{
    memset(cc, 0, sizeof *cc);
    cost_pt_t *pts = xmalloc(sizeof(cost_pt_t) * COST_SAMPLES);
    uint32_t n = cost_points(w, pts, COST_SAMPLES);
    coll_mesh_build_opts_t bo = { 0.0f, quant ? (uint32_t)COLL_MESH_QUANTIZE : 0u };
    size_t need = coll_mesh_build_size(w->nv, w->nt, &bo);
    void *block = need ? xalloc8(need) : NULL;
    const coll_mesh_t *m = NULL;
    float best = 0.0f;
    if (n && block && coll_mesh_build(block, need, w->v, w->nv, w->idx, w->nt, &bo, &m) == COLL_OK) {
        /* the cap: 10 % over the runtime's choice, and within 22 (float) or 13.5 (quantized)
         * bytes a triangle (the memory targets are 24 and 14) unless the runtime's is over */
        double cap = (double)m->total_size * COST_MAX_GROWTH, abs_cap = (quant ? 13.5 : 22.0) * (double)m->ntris;
        if (cap > abs_cap) cap = abs_cap > (double)m->total_size ? abs_cap : (double)m->total_size;
        cc->cost = cc->cost_runtime = cost_of(m, pts, n);
        cc->cell = m->cell_size;
        /* Only a hashed choice is replaced: that is where the estimate's gain was measured
         * (real maps: cells sharing buckets); between dense grids its differences are
         * within what the walk model misses (the per-ref codes of dense float grids, the
         * scene queries' cell walks), and a dense grid it rated cheaper measured dearer. */
        bool hashed = (m->flags & COLL_MESHF_HASH) != 0;
        for (float c = 0.75f; hashed && c <= 6.0f; c *= 1.125f) {
            bo.cell_size = c;
            if (coll_mesh_build(block, need, w->v, w->nv, w->idx, w->nt, &bo, &m) != COLL_OK) continue;
            cc->tried++;
            if ((double)m->total_size > cap || m->cell_size != c) continue;
            double k = cost_of(m, pts, n);
            if (k < cc->cost) { cc->cost = k; cc->cell = c; best = c; }
        }
    }
    cc->points = n;
    free(block);
    free(pts);
    return best; /* 0: the runtime's own choice */
}

/* Worst distance between a welded float vertex and its stored (quantized) value. */
static double quant_error(const coll_mesh_t *q, const welded_t *w)
{
    const uint16_t *qv = (const uint16_t *)(const void *)((const uint8_t *)q + q->off_verts);
    double worst = 0.0;
    for (uint32_t v = 0; v < w->nv; v++) {
        double d2 = 0.0;
        for (int a = 0; a < 3; a++) {
            double x = (double)(q->qorigin[a] + (float)qv[3 * v + a] * q->qscale[a]);
            d2 += (x - w->v[3 * v + a]) * (x - w->v[3 * v + a]);
        }
        if (d2 > worst) worst = d2;
    }
    return sqrt(worst);
}

static const char *base_name(const char *p)
{
    const char *s = strrchr(p, '/');
    return s ? s + 1 : p;
}

int main(int argc, char **argv)
{
    opts_t o;
    parse_args(argc, argv, &o);

    soup_t soup;
    import(&o, &soup);

    double lo[3] = { INFINITY, INFINITY, INFINITY }, hi[3] = { -INFINITY, -INFINITY, -INFINITY };
    for (size_t k = 0; k < soup.n * 3; k++)
        for (int a = 0; a < 3; a++) {
            lo[a] = fmin(lo[a], soup.p[3 * k + a]);
            hi[a] = fmax(hi[a], soup.p[3 * k + a]);
        }
    double maxabs = 0.0;
    for (int a = 0; a < 3; a++) maxabs = fmax(maxabs, fmax(fabs(lo[a]), fabs(hi[a])));
    if (maxabs > COORD_MAX)
        die("level too large for the format: coordinates reach %.3g m (limit %.0g m for float precision); "
            "is --scale right?", maxabs, COORD_MAX);

    if (o.weld > 0.0f && maxabs / o.weld > 1e15)
        die("--weld %g is too small for coordinates up to %.0f m (use --weld 0 to merge exact duplicates only)",
            (double)o.weld, maxabs);
    welded_t w;
    weld(&soup, o.weld, &w);
    free(soup.p);
    if (w.nt == 0)
        die("no triangles left: all %u were degenerate (%u collapsed by welding at %g m, %u zero-area)",
            w.in_tris, w.collapsed, (double)o.weld, w.degenerate);

    /* A bake that loses most of its input is an importer failure, not a level: assimp's
     * Quake III BSP importer, for one, leaves face indices unset and 4090 triangles collapse
     * into 1. Refuse it loudly rather than write a level with nothing in it. */
    if ((double)w.nt < o.min_kept * (double)w.in_tris)
        die("only %u of %u input triangles survive (%.1f %%; %u collapsed by welding at %g m, %u degenerate, "
            "%u duplicate): the importer or the options lost the level (at least %.0f %% must survive; "
            "--min-kept 0 bakes it anyway)", w.nt, w.in_tris, 100.0 * w.nt / (double)w.in_tris, w.collapsed,
            (double)o.weld, w.degenerate, w.duplicate, 100.0 * o.min_kept);

    void *fblock = NULL, *qblock = NULL;
    /* the automatic cell: the runtime's choice unless a cheaper one is estimated (choose_cell) */
    cell_choice_t fcc, qcc, *cc = NULL;
    float fcell = o.cell_size, qcell = o.cell_size;
    if (!(o.cell_size > 0.0f) && o.cell_choice == CELL_CHOICE_COST) {
        fcell = choose_cell(&w, 0, &fcc);
        if (o.quantize) qcell = choose_cell(&w, 1, &qcc);
    }
    const coll_mesh_t *fm = build(&w, fcell, 0, &fblock);
    const coll_mesh_t *m = fm;
    double qerr = 0.0;
    int quantized = 0;
    if (o.quantize) {
        const coll_mesh_t *qm = build(&w, qcell, 1, &qblock);
        qerr = quant_error(qm, &w);
        if (qerr > o.max_quant_error) {
            warn("quantization error %.4f m exceeds --max-quant-error %.4f m (level %.1f m across): "
                 "writing float vertices", qerr, (double)o.max_quant_error,
                 fmax(hi[0] - lo[0], fmax(hi[1] - lo[1], hi[2] - lo[2])));
        } else {
            m = qm;
            quantized = 1;
            if (!(o.cell_size > 0.0f) && o.cell_choice == CELL_CHOICE_COST) cc = &qcc;
            if (qm->ntris != fm->ntris)
                warn("%u triangles collapsed by quantization", fm->ntris - qm->ntris);
        }
    }
    if (!quantized && !(o.cell_size > 0.0f) && o.cell_choice == CELL_CHOICE_COST) cc = &fcc;
    if (fm->ntris != w.nt)
        warn("the runtime builder dropped %u more degenerate triangles", w.nt - fm->ntris);

    /* Blob, then the final check: read the file back and load it as the game will. */
    size_t size = coll_mesh_size(m), written = 0;
    uint8_t *blob = xmalloc(size);
    coll_err_t err = coll_mesh_write_blob(m, blob, size, &written);
    if (err != COLL_OK || written != size) die("coll_mesh_write_blob failed: %s", coll_strerror(err));
    write_file(o.output, blob, size);
    {
        FILE *f = fopen(o.output, "rb");
        if (!f) die("cannot reopen %s: %s", o.output, strerror(errno));
        void *back = xalloc8(size + 8);
        size_t got = fread(back, 1, size + 8, f);
        fclose(f);
        const coll_mesh_t *lm = NULL;
        err = got == size ? coll_mesh_load(back, got, &lm) : COLL_ERR_TRUNCATED;
        if (err != COLL_OK || coll_mesh_triangle_count(lm) != m->ntris) {
            remove(o.output);
            die("written blob %s does not load back: %s", o.output, coll_strerror(err));
        }
        free(back);
    }
    if (o.dump_raw) dump_raw(o.dump_raw, &w);

    shape_stats_t ss;
    analyse_shape(&w, &ss);
    grid_stats_t gs;
    analyse_grid(m, &gs);
    coll_mesh_layout_t l = coll_mesh_layout_of(m->flags, m->nverts, m->ntris, gs.ncells, m->nrefs);

    printf("collbake: %s -> %s\n", o.input, o.output);
    if (soup.is_bsp)
        printf("  input      Quake III BSP, %g m per unit: %u surfaces (%u planar, %u meshes, %u patches taken; "
               "%u non-solid, %u without geometry skipped); %u triangles\n", o.bsp_unit, soup.bsp.surfaces,
               soup.bsp.planar, soup.bsp.soups, soup.bsp.patches, soup.bsp.nonsolid, soup.bsp.other, w.in_tris);
    else {
    printf("  input      %u nodes, %u meshes baked, %u skipped", soup.nodes, soup.meshes_taken, soup.meshes_skipped);
    for (int i = 0; i < o.nonly; i++) printf("%s%s", i ? " " : " (--only ", o.only[i]);
    printf("%s; %u triangles", o.nonly ? ")" : "", w.in_tris);
    if (soup.nontri_faces) printf(", %u point/line faces ignored", soup.nontri_faces);
    if (soup.bad_faces || soup.nonfinite) printf(", %u bad indices, %u non-finite vertices dropped", soup.bad_faces, soup.nonfinite);
    printf("\n");
    }
    if (o.scale != 1.0f) printf("  scale      %g\n", (double)o.scale);
    printf("  welding    %u -> %u vertices (tolerance %g m)\n", w.in_verts, w.nv, (double)o.weld);
    printf("  triangles  %u in, %u out (%u collapsed by welding, %u degenerate, %u duplicate)\n",
           w.in_tris, m->ntris, w.collapsed, w.degenerate, w.duplicate);
    printf("  bounds     (%.3f, %.3f, %.3f) .. (%.3f, %.3f, %.3f), %.2f x %.2f x %.2f m\n",
           (double)m->bmin[0], (double)m->bmin[1], (double)m->bmin[2], (double)m->bmax[0], (double)m->bmax[1],
           (double)m->bmax[2], (double)(m->bmax[0] - m->bmin[0]), (double)(m->bmax[1] - m->bmin[1]),
           (double)(m->bmax[2] - m->bmin[2]));
    printf("  grid       cell %.3f m (%s), %u x %u x %u %s %llu %s, %llu non-empty\n", (double)m->cell_size,
           o.cell_size > 0.0f ? (m->cell_size == o.cell_size ? "--cell-size" : "grown from --cell-size to fit")
                              : cc ? "automatic, --cell-choice cost" : "automatic",
           m->dims[0], m->dims[1], m->dims[2], (m->flags & COLL_MESHF_HASH) ? "hashed into" : "=",
           (unsigned long long)gs.ncells, (m->flags & COLL_MESHF_HASH) ? "buckets" : "cells",
           (unsigned long long)gs.nonempty);
    if (cc)
        printf("  cell cost  %s: estimated %.0f x86 instructions of grid walk per character step (%u points on "
               "walkable triangles), the runtime's choice %.0f; %d candidates\n",
               cc->cell > 0.0f && cc->cost < cc->cost_runtime ? "a cheaper candidate" : "the runtime's choice",
               cc->points ? cc->cost / cc->points : 0.0, cc->points, cc->points ? cc->cost_runtime / cc->points : 0.0,
               cc->tried);
    printf("  per cell   max %u triangles, mean %.2f over non-empty cells; %u refs (%.2f cells per triangle)\n",
           gs.max_per_cell, gs.mean_per_nonempty, m->nrefs, m->ntris ? (double)m->nrefs / m->ntris : 0.0);
    printf("  size       %u bytes, %.1f bytes/triangle (header %u, vertices %llu, triangles %llu with %s indices, "
           "cells %llu, refs %llu)\n",
           m->total_size, m->ntris ? (double)m->total_size / m->ntris : 0.0, (unsigned)l.off_verts,
           (unsigned long long)(l.off_tris - l.off_verts), (unsigned long long)(l.off_cells - l.off_tris),
           (m->flags & COLL_MESHF_IDX16) ? "16-bit" : (m->flags & COLL_MESHF_IDXBLK) ? "16-bit block" : "32-bit",
           (unsigned long long)(l.off_refs - l.off_cells), (unsigned long long)(l.total - l.off_refs));
    if (o.quantize)
        printf("  quantized  %s: worst-case vertex error %.3g m (steps %.2g, %.2g, %.2g m)\n",
               quantized ? "yes" : "NO (float written)", qerr,
               (double)(quantized ? m->qscale[0] : 0.0f), (double)(quantized ? m->qscale[1] : 0.0f),
               (double)(quantized ? m->qscale[2] : 0.0f));

    if (maxabs > COORD_WARN)
        warn("coordinates reach %.0f m: float spacing there is %.1f mm; is --scale right?", maxabs,
             maxabs * 1.2e-7 * 1000.0);
    if (gs.big_tris) {
        fm_vec3_t t[3];
        coll_mesh_triangle(m, gs.biggest_tri, t);
        warn("%u triangles each span more than %d grid cells (largest: %u cells, triangle %u near "
             "(%.2f, %.2f, %.2f)); split big faces or raise --cell-size", gs.big_tris, BIG_TRI_CELLS,
             gs.max_cells_of_tri, gs.biggest_tri, (double)t[0].x, (double)t[0].y, (double)t[0].z);
    }
    if (ss.slivers) {
        const float *p = w.v + 3 * w.idx[3 * ss.sliver_example];
        warn("%u sliver triangles (an altitude under %.0f mm or longer than %.0fx it), e.g. near (%.3f, %.3f, %.3f)",
             ss.slivers, SLIVER_ALTITUDE * 1000.0, SLIVER_ASPECT, (double)p[0], (double)p[1], (double)p[2]);
    }
    if (ss.nonmanifold) {
        const float *a = w.v + 3 * ss.nm_a, *b = w.v + 3 * ss.nm_b;
        warn("%u non-manifold edges (shared by more than 2 triangles), e.g. (%.3f, %.3f, %.3f)-(%.3f, %.3f, %.3f)",
             ss.nonmanifold, (double)a[0], (double)a[1], (double)a[2], (double)b[0], (double)b[1], (double)b[2]);
    }
    if (w.degenerate || w.collapsed)
        printf("  note       %u degenerate triangles dropped (%u collapsed when welding at %g m)\n",
               w.degenerate + w.collapsed, w.collapsed, (double)o.weld);

    if (o.report) {
        char *txt = xmalloc(4096);
        int n = snprintf(txt, 4096,
            "input %s\ntriangles_in %u\ntriangles %u\nvertices %u\nbounds %.9g %.9g %.9g %.9g %.9g %.9g\n"
            "cell_size %.9g\ncell_size_requested %.9g\ncells %llu\nmax_per_cell %u\nbytes %u\nquantized %d\nquant_error %.9g\n"
            "slivers %u\nnonmanifold_edges %u\nbig_triangles %u\ncell_choice %s\ncell_walk_cost %.1f\ncell_walk_cost_runtime %.1f\n",
            base_name(o.input), w.in_tris, m->ntris, m->nverts, (double)m->bmin[0], (double)m->bmin[1],
            (double)m->bmin[2], (double)m->bmax[0], (double)m->bmax[1], (double)m->bmax[2], (double)m->cell_size,
            (double)o.cell_size, (unsigned long long)gs.ncells, gs.max_per_cell, m->total_size, quantized, qerr, ss.slivers,
            ss.nonmanifold, gs.big_tris, o.cell_size > 0.0f ? "explicit" : cc ? "cost" : "runtime",
            cc && cc->points ? cc->cost / cc->points : 0.0, cc && cc->points ? cc->cost_runtime / cc->points : 0.0);
        write_file(o.report, txt, (size_t)n);
        free(txt);
    }
    free(blob);
    free(fblock);
    free(qblock);
    free(w.v);
    free(w.idx);
    return 0;
}
