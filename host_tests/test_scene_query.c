/* Scene queries against a double-precision brute-force reference (every triangle of every
 * instance, every body): random raycasts and capsule sweeps over random meshes (long thin
 * triangles, dense clusters, far from the origin) under random transforms; plus masks,
 * type filters, registry errors, remove-then-query, ids, overflow fallback, zero
 * allocations, precision 5 km out, moving platforms. */
/* The method hooks (prim.h): this suite links libcoll_hooks.a ahead of libcoll.a. */
#define COLL_METHOD_HOOKS 1
#include "unity.h"
#include "alloc_guard.h"
#include "core_gen.h"
#include "core_ref.h"
#include "coll/scene.h"
#include "mesh_format.h"
#include "gather.h"
#include "prim.h"
#include "gather.h"
#include "grid_walk.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

void setUp(void) {}
void tearDown(void) {}

#ifdef __mips__
#define N_WORLDS 15
#else
#define N_WORLDS 100
#endif
#define QUERIES_PER_WORLD 100

#define MAXV 10000
#define MAXT 10000
static float g_verts[3 * MAXV];
static uint32_t g_idx[3 * MAXT];
static uint64_t g_meshbuf[3][(1u << 19) / 8];

/* Grids built by build_mesh() of each kind (the randomized agreement must cover both). */
static uint32_t g_hashed_built, g_dense_built;

static const coll_mesh_t *build_mesh(int slot, uint32_t nv, uint32_t nt, const coll_mesh_build_opts_t *o)
{
    const coll_mesh_t *m = NULL;
    size_t need = coll_mesh_build_size(nv, nt, o);
    TEST_ASSERT_TRUE(need <= sizeof g_meshbuf[0]);
    TEST_ASSERT_EQUAL_INT(COLL_OK, coll_mesh_build(g_meshbuf[slot], need, g_verts, nv, g_idx, nt, o, &m));
    if (m->flags & COLL_MESHF_HASH) g_hashed_built++;
    else g_dense_built++;
    return m;
}

/* ------------------------------------------------------------------ random worlds --- */

typedef struct {
    coll_scene_t scene;
    coll_mesh_instance_t inst[3];
    coll_body_t body[4];
    double lo[3], hi[3]; /* world region of interest */
} world_t;

static world_t g_w;

static void random_quat(core_rng_t *r, fm_quat_t *q)
{
    double x, y, z, w, n;
    do {
        x = core_rng_range(r, -1, 1); y = core_rng_range(r, -1, 1);
        z = core_rng_range(r, -1, 1); w = core_rng_range(r, -1, 1);
        n = x * x + y * y + z * z + w * w;
    } while (n < 0.05 || n > 1);
    n = sqrt(n);
    q->x = (float)(x / n); q->y = (float)(y / n); q->z = (float)(z / n); q->w = (float)(w / n);
}

/* Random soup: ordinary, long thin and clustered triangles around a local offset. */
static const coll_mesh_t *random_mesh(core_rng_t *r, int slot, double off[3], bool quant)
{
    uint32_t nt = 20 + core_rng_u32(r) % 300, nv = 0;
    for (uint32_t t = 0; t < nt; t++) {
        int kind = (int)(core_rng_u32(r) % 4);
        double c[3], e1[3], e2[3];
        double spread = kind == 2 ? 0.5 : 10.0; /* kind 2: dense cluster */
        for (int a = 0; a < 3; a++) {
            c[a] = off[a] + (kind == 2 ? core_rng_range(r, 2, 3) : core_rng_range(r, -spread, spread));
            e1[a] = core_rng_range(r, -1, 1);
            e2[a] = core_rng_range(r, -1, 1);
        }
        double s1 = kind == 1 ? core_rng_range(r, 4, 12) : (kind == 2 ? 0.2 : core_rng_range(r, 0.3, 3));
        double s2 = kind == 1 ? core_rng_range(r, 0.005, 0.05) : s1 * core_rng_range(r, 0.3, 1);
        if (kind == 3) { e1[1] *= 0.05; e2[1] *= 0.05; } /* floor-ish */
        for (int a = 0; a < 3; a++) {
            g_verts[3 * nv + a] = (float)c[a];
            g_verts[3 * (nv + 1) + a] = (float)(c[a] + e1[a] * s1);
            g_verts[3 * (nv + 2) + a] = (float)(c[a] + e2[a] * s2);
        }
        g_idx[3 * t] = nv; g_idx[3 * t + 1] = nv + 1; g_idx[3 * t + 2] = nv + 2;
        nv += 3;
    }
    coll_mesh_build_opts_t o = { 0.0f, quant ? COLL_MESH_QUANTIZE : 0u };
    if (core_rng_u32(r) % 4 == 0) o.cell_size = (float)core_rng_range(r, 0.5, 4);
    return build_mesh(slot, nv, nt, &o);
}

static void random_xf(core_rng_t *r, coll_transform_t *xf, double base[3])
{
    for (int a = 0; a < 3; a++) xf->pos.v[a] = (float)(base[a] + core_rng_range(r, -8, 8));
    int rk = (int)(core_rng_u32(r) % 3);
    if (rk == 0) { xf->rot.x = xf->rot.y = xf->rot.z = 0; xf->rot.w = 1; }
    else random_quat(r, &xf->rot);
    int sk = (int)(core_rng_u32(r) % 4);
    double u = core_rng_range(r, 0.5, 2.0);
    for (int a = 0; a < 3; a++) {
        double s = sk == 0 ? 1.0 : sk == 1 ? u : core_rng_range(r, 0.3, 3.0);
        if (sk == 3 && a == 1 && core_rng_u32(r) % 2) s = -s; /* mirrored */
        xf->scale.v[a] = (float)s;
    }
}

static bool g_bodies_supported;
/* Float rounding allowance of the world (meters): the scene maps the query into each
 * instance's local space in single precision, so mesh-local coordinates far from the
 * mesh's own origin under rotation and scale carry an error of a few ulp(local) x scale
 * (the rotated pivot); world coordinates add ulp(world). */
static double g_float_err;

static void random_world(core_rng_t *r, bool with_bodies)
{
    memset(&g_w, 0, sizeof g_w);
    coll_scene_init(&g_w.scene);
    double base[3] = { 0, 0, 0 }, moff[3] = { 0, 0, 0 };
    int far = (int)(core_rng_u32(r) % 3); /* 0: near origin, 1: instances at +-2 km, 2: mesh-local at 2 km */
    for (int a = 0; a < 3; a++) {
        double f = (core_rng_u32(r) % 2 ? 1 : -1) * core_rng_range(r, 1500, 2000);
        if (far == 1) base[a] = f;
        if (far == 2) moff[a] = f;
    }
    const coll_mesh_t *m0 = random_mesh(r, 0, moff, core_rng_u32(r) % 3 == 0);
    const coll_mesh_t *m1 = random_mesh(r, 1, moff, false);
    int ninst = 1 + (int)(core_rng_u32(r) % 3);
    for (int i = 0; i < ninst; i++) {
        coll_mesh_instance_t *in = &g_w.inst[i];
        in->mesh = i == 1 ? m1 : m0;
        double b[3];
        for (int a = 0; a < 3; a++) b[a] = base[a];
        random_xf(r, &in->xf, b);
        static const uint8_t masks[] = { 1, 1, 3, 5 };
        in->write_mask = masks[core_rng_u32(r) % 4];
        in->id = (uint16_t)(100 + i);
        TEST_ASSERT_EQUAL_INT(COLL_OK, coll_scene_add_mesh(&g_w.scene, in));
    }
    g_float_err = 0;
    for (int i = 0; i < ninst; i++) {
        fm_vec3_t lo, hi;
        coll_mesh_bounds(g_w.inst[i].mesh, &lo, &hi);
        double la = 0, smax = 0, smin = 1e300;
        for (int a = 0; a < 3; a++) {
            la = fmax(la, fmax(fabs(lo.v[a]), fabs(hi.v[a])));
            smax = fmax(smax, fabs(g_w.inst[i].xf.scale.v[a]));
            smin = fmin(smin, fabs(g_w.inst[i].xf.scale.v[a]));
        }
        bool simple = g_w.inst[i].xf.rot.w == 1.0f && smax == 1.0 && smin == 1.0;
        g_float_err = fmax(g_float_err, simple ? 3e-7 * la : 4e-7 * la * smax);
    }
    /* region: world AABB of all instance triangles */
    for (int a = 0; a < 3; a++) { g_w.lo[a] = 1e300; g_w.hi[a] = -1e300; }
    for (int i = 0; i < ninst; i++)
        for (uint32_t t = 0; t < coll_mesh_triangle_count(g_w.inst[i].mesh); t++) {
            core_d3 w[3];
            core_world_tri(&g_w.inst[i], t, w);
            for (int k = 0; k < 3; k++) {
                double v[3] = { w[k].x, w[k].y, w[k].z };
                for (int a = 0; a < 3; a++) { g_w.lo[a] = fmin(g_w.lo[a], v[a]); g_w.hi[a] = fmax(g_w.hi[a], v[a]); }
            }
        }
    if (with_bodies && g_bodies_supported) {
        int nb = (int)(core_rng_u32(r) % 5);
        for (int i = 0; i < nb; i++) {
            coll_body_t *b = &g_w.body[i];
            b->shape = (coll_shape_t)(core_rng_u32(r) % 4);
            b->half_extents.x = (float)core_rng_range(r, 0.2, 2);
            b->half_extents.y = (float)core_rng_range(r, 0.1, 2);
            b->half_extents.z = b->shape == COLL_SHAPE_BOX ? (float)core_rng_range(r, 0.2, 2) : 0.0f;
            for (int a = 0; a < 3; a++) b->xf.pos.v[a] = (float)core_rng_range(r, g_w.lo[a], g_w.hi[a]);
            random_quat(r, &b->xf.rot);
            b->xf.scale.x = b->xf.scale.y = b->xf.scale.z = 1;
            /* boxes and cylinders only on layer 2: the sweep reference (segment distances)
             * covers spheres and capsules; sweeps read layers 1 and 4 */
            bool round = b->shape == COLL_SHAPE_SPHERE || b->shape == COLL_SHAPE_CAPSULE;
            b->write_mask = round ? (core_rng_u32(r) % 2 ? 1 : 3) : 2;
            b->id = (uint16_t)(200 + i);
            TEST_ASSERT_EQUAL_INT(COLL_OK, coll_scene_add_body(&g_w.scene, b));
        }
    }
}

static core_d3 random_point_in_region(core_rng_t *r, double grow)
{
    core_d3 p;
    p.x = core_rng_range(r, g_w.lo[0] - grow, g_w.hi[0] + grow);
    p.y = core_rng_range(r, g_w.lo[1] - grow, g_w.hi[1] + grow);
    p.z = core_rng_range(r, g_w.lo[2] - grow, g_w.hi[2] + grow);
    return p;
}

/* A point on a random triangle of the scene (to aim queries at). */
static core_d3 random_surface_point(core_rng_t *r)
{
    int n = g_w.scene.mesh_count;
    const coll_mesh_instance_t *in = g_w.scene.meshes[core_rng_u32(r) % (uint32_t)n];
    uint32_t nt = coll_mesh_triangle_count(in->mesh);
    core_d3 w[3];
    core_world_tri(in, core_rng_u32(r) % nt, w);
    double a = core_rng_range(r, 0, 1), b = core_rng_range(r, 0, 1);
    if (a + b > 1) { a = 1 - a; b = 1 - b; }
    return core_d3_add(w[0], core_d3_add(core_d3_scale(core_d3_sub(w[1], w[0]), a),
                                         core_d3_scale(core_d3_sub(w[2], w[0]), b)));
}

static fm_vec3_t to_f(core_d3 d)
{
    fm_vec3_t v = {{ (float)d.x, (float)d.y, (float)d.z }};
    return v;
}

/* ------------------------------------------------------------------ ray reference --- */

typedef struct {
    bool certain_hit, possible_hit;
    double s_certain, s_possible; /* bounds widened by the conditioning */
    double s_certain_exact;       /* the reference nearest certain hit itself */
} ray_ref_t;

/* meters: a ray grazing an edge (or ending at max distance) within this is either way:
 * 0.2 mm plus float rounding along the ray (the scene runs in float, relative to the query
 * origin, so its error grows with the distance travelled). */
#define AMBIG_AT(s) (1e-4 * fmax(1.0, (s)) + g_float_err)
#define AMBIG AMBIG_AT(smax)

/* Signed distance of the ray's hit point from the triangle's boundary (meters). */
/* *amb: how far the hit may move along the ray or across an edge when the triangle is
 * displaced by AMBIG_AT(s) (the float error of the query-relative placement): grows as
 * 1/cos of the incidence angle, so grazing hits are judged with their true conditioning. */
static double g_amb;
static bool ray_tri_ref(core_d3 o, core_d3 d, const core_d3 w[3], double smax, double *s, double *edge_dist,
                        core_d3 *n)
{
    double mb;
    if (!core_ray_tri(o, d, w, smax * 1.01 + 1.0, 1e9, s, &mb, n)) return false;
    g_amb = AMBIG_AT(*s) / fmax(fabs(core_d3_dot(*n, d)), 1e-9);
    core_d3 p = core_d3_add(o, core_d3_scale(d, *s));
    core_d3 nn = core_d3_cross(core_d3_sub(w[1], w[0]), core_d3_sub(w[2], w[0]));
    double ed = 1e300;
    for (int i = 0; i < 3; i++) {
        core_d3 a = w[i], b = w[(i + 1) % 3];
        core_d3 e = core_d3_sub(b, a);
        /* inward distance from edge line within the plane */
        double sd = core_d3_dot(core_d3_cross(e, core_d3_sub(p, a)), nn) / (core_d3_len(e) * core_d3_len(nn));
        ed = fmin(ed, sd);
    }
    *edge_dist = ed;
    return true;
}

static void ray_reference(core_d3 o, core_d3 d, double smax, uint8_t mask, uint8_t types, ray_ref_t *rr)
{
    memset(rr, 0, sizeof *rr);
    rr->s_certain = rr->s_possible = rr->s_certain_exact = 1e300;
    const coll_scene_t *sc = &g_w.scene;
    if (types & COLL_TYPE_MESH)
        for (int i = 0; i < sc->mesh_count; i++) {
            const coll_mesh_instance_t *in = sc->meshes[i];
            if (!(in->write_mask & mask)) continue;
            for (uint32_t t = 0; t < coll_mesh_triangle_count(in->mesh); t++) {
                core_d3 w[3], n;
                double s, ed;
                core_world_tri(in, t, w);
                if (!ray_tri_ref(o, d, w, smax, &s, &ed, &n) || ed < -g_amb || s - g_amb > smax) continue;
                rr->possible_hit = true;
                rr->s_possible = fmin(rr->s_possible, s - g_amb);
                if (ed > g_amb && s + g_amb < smax - AMBIG) {
                    rr->certain_hit = true;
                    rr->s_certain = fmin(rr->s_certain, s + g_amb);
                    rr->s_certain_exact = fmin(rr->s_certain_exact, s);
                }
            }
        }
    if (types & COLL_TYPE_BODY)
        for (int i = 0; i < sc->body_count; i++) {
            const coll_body_t *b = sc->bodies[i];
            if (!(b->write_mask & mask)) continue;
            double s;
            core_d3 n;
            if (!core_ray_body(o, d, b, smax + AMBIG, &s, &n)) continue;
            rr->possible_hit = true;
            rr->s_possible = fmin(rr->s_possible, s);
            if (s < smax - AMBIG) {
                rr->certain_hit = true;
                rr->s_certain = fmin(rr->s_certain, s);
                rr->s_certain_exact = fmin(rr->s_certain_exact, s);
            }
        }
}

/* The reference distance and normal of the collider the scene reported. */
static bool ray_ref_for_reported(core_d3 o, core_d3 d, double smax, const coll_ray_hit_t *h, double *s, core_d3 *n,
                                 double *ed)
{
    *ed = 1e300;
    if (h->type == COLL_TYPE_MESH) {
        core_d3 w[3];
        core_world_tri(h->instance, (uint32_t)h->triangle, w);
        return ray_tri_ref(o, d, w, smax, s, ed, n);
    }
    return core_ray_body(o, d, h->body, smax + AMBIG, s, n);
}

static bool inside_any_body(core_d3 p, double margin)
{
    for (int i = 0; i < g_w.scene.body_count; i++) {
        const coll_body_t *b = g_w.scene.bodies[i];
        double rr;
        double dd = core_seg_body_core(p, p, b, &rr, NULL, NULL);
        if (dd < rr + margin) return true;
    }
    return false;
}

static void test_random_raycasts_match_reference(void)
{
    core_rng_t r;
    core_rng_seed(&r, 1234);
    int n = 0, hits = 0, strict = 0, certain = 0;
    double worst = 0, worst_n = 0;
    for (int wi = 0; wi < N_WORLDS; wi++) {
        random_world(&r, true);
        for (int q = 0; q < QUERIES_PER_WORLD; q++) {
            core_d3 o = random_point_in_region(&r, 5.0);
            if (inside_any_body(o, 0.01)) continue;
            core_d3 target = core_rng_u32(&r) % 4 ? random_surface_point(&r) : random_point_in_region(&r, 5.0);
            core_d3 d = core_d3_sub(target, o);
            double len = core_d3_len(d);
            if (len < 1e-3) continue;
            d = core_d3_scale(d, 1.0 / len);
            fm_vec3_t of = to_f(o), df = to_f(d);
            o = core_d3_of(of); /* reference uses exactly the float query */
            d = core_d3_of(df);
            double smax = core_rng_u32(&r) % 4 ? len * core_rng_range(&r, 0.5, 3.0) : 1e4;
            float smaxf = (float)smax;
            smax = smaxf;
            coll_ray_hit_t h;
            bool got;
            static const uint8_t rmasks[] = { 0xFF, 0xFF, 0xFF, 1, 2, 4 };
            static const uint8_t rtypes[] = { COLL_TYPE_ALL, COLL_TYPE_ALL, COLL_TYPE_ALL, COLL_TYPE_MESH, COLL_TYPE_BODY };
            uint8_t mask = rmasks[core_rng_u32(&r) % 6], types = rtypes[core_rng_u32(&r) % 5];
            ASSERT_NO_ALLOC(got = coll_raycast(&g_w.scene, of, df, smaxf, mask, types, &h));
            ray_ref_t rr;
            ray_reference(o, d, smax, mask, types, &rr);
            double tol = 1e-4 * fmax(1.0, fmin(smax, 1e3));
            char msg[200];
            snprintf(msg, sizeof msg, "world %d query %d: got %d (%.6f) certain %d (%.6f) possible %d (%.6f)", wi, q,
                     got, got ? h.distance : -1.0, rr.certain_hit, rr.s_certain, rr.possible_hit, rr.s_possible);
            n++;
            if (getenv("CORE_DEBUG") && (got != rr.certain_hit || (got && fabs(h.distance - rr.s_certain) > tol))) {
                printf("DEBUG %s\n", msg);
                for (int i = 0; i < g_w.scene.mesh_count; i++) {
                    const coll_mesh_instance_t *in = g_w.scene.meshes[i];
                    for (uint32_t t = 0; t < coll_mesh_triangle_count(in->mesh); t++) {
                        core_d3 w[3], nn; double s2, ed;
                        core_world_tri(in, t, w);
                        if (ray_tri_ref(o, d, w, smax, &s2, &ed, &nn) && ed > -AMBIG && s2 < (got ? h.distance + 1 : smax))
                            printf("  inst %d tri %u s %.6f ed %.3g\n", i, t, s2, ed);
                    }
                    const coll_mesh_t *mm = in->mesh;
                    printf("  inst %d: pos %g %g %g rot %g %g %g %g scale %g %g %g cell %g dims %u %u %u bmin %g %g %g\n", i,
                           in->xf.pos.x, in->xf.pos.y, in->xf.pos.z, in->xf.rot.x, in->xf.rot.y, in->xf.rot.z, in->xf.rot.w,
                           in->xf.scale.x, in->xf.scale.y, in->xf.scale.z, mm->cell_size, mm->dims[0], mm->dims[1], mm->dims[2],
                           mm->bmin[0], mm->bmin[1], mm->bmin[2]);
                }
                if (got && h.instance) {
                    core_d3 w[3], nn; double s2 = -1, mb = -1;
                    core_world_tri(h.instance, (uint32_t)h.triangle, w);
                    bool hh2 = core_ray_tri(o, d, w, 1e9, 1e9, &s2, &mb, &nn);
                    printf("  scene: tri %d ref hit %d s %.6f minbary %.3g; o %.9g %.9g %.9g d %.9g %.9g %.9g\n", h.triangle, hh2, s2, mb,
                           o.x, o.y, o.z, d.x, d.y, d.z);
                    for (int k = 0; k < 3; k++) printf("   w%d %.9g %.9g %.9g\n", k, w[k].x, w[k].y, w[k].z);
                }
            }
            if (!got) {
                TEST_ASSERT_FALSE_MESSAGE(rr.certain_hit, msg);
                continue;
            }
            hits++;
            TEST_ASSERT_TRUE_MESSAGE(rr.possible_hit, msg);
            TEST_ASSERT_TRUE_MESSAGE(h.distance >= rr.s_possible - tol, msg);
            TEST_ASSERT_TRUE_MESSAGE(!rr.certain_hit || h.distance <= rr.s_certain + tol, msg);
            /* the reported collider really is there, at that distance, with that normal */
            double s_rep, ed;
            core_d3 n_rep;
            TEST_ASSERT_TRUE((h.type & types) != 0);
            TEST_ASSERT_TRUE(((h.instance ? h.instance->write_mask : h.body->write_mask) & mask) != 0);
            TEST_ASSERT_TRUE_MESSAGE(ray_ref_for_reported(o, d, smax, &h, &s_rep, &n_rep, &ed), msg);
            double amb_rep = h.type == COLL_TYPE_MESH ? g_amb : AMBIG;
            TEST_ASSERT_TRUE_MESSAGE(fabs(s_rep - h.distance) <= tol + amb_rep, msg);
            double dn = core_d3_len(core_d3_sub(core_d3_of(h.normal), n_rep));
            if (ed > amb_rep && amb_rep < 100 * AMBIG_AT(s_rep)) {
                TEST_ASSERT_TRUE_MESSAGE(dn <= 1e-3, msg);
                worst_n = fmax(worst_n, dn);
            }
            TEST_ASSERT_EQUAL_UINT16(h.type == COLL_TYPE_MESH ? h.instance->id : h.body->id, h.id);
            core_d3 p_ref = core_d3_add(o, core_d3_scale(d, h.distance));
            TEST_ASSERT_TRUE_MESSAGE(core_d3_len(core_d3_sub(p_ref, core_d3_of(h.point))) <= tol + AMBIG_AT(h.distance) +
                                     3e-7 * core_d3_len(o), msg);
            if (rr.certain_hit) {
                certain++;
                double e = fabs(h.distance - rr.s_certain_exact);
                if (getenv("CORE_DEBUG") && e > tol)
                    printf("RAYDIFF %s: e %.4g amb_rep %.4g ed %.4g type %d\n", msg, e, amb_rep, ed, h.type);
                worst = fmax(worst, e / fmax(1.0, smax));
                if (e <= tol) strict++;
            }
        }
    }
    printf("raycasts: %d queries, %d hits, %d with an unambiguous nearest of which %d within 1e-4*len of it; "
           "worst |ds|/len %.3g, worst normal err %.3g\n", n, hits, certain, strict, worst, worst_n);
    TEST_ASSERT_TRUE(n >= N_WORLDS * QUERIES_PER_WORLD * 9 / 10);
}

/* ------------------------------------------------------------------ sweep reference - */

typedef struct {
    core_d3 s0, s1, disp;
    double r;
    const core_d3 *tri;
    const coll_body_t *body;
} sweep_ctx_t;

static double sweep_f(void *vctx, double t)
{
    sweep_ctx_t *c = vctx;
    core_d3 a = core_d3_add(c->s0, core_d3_scale(c->disp, t)), b = core_d3_add(c->s1, core_d3_scale(c->disp, t));
    if (c->tri) return core_seg_tri(a, b, c->tri, NULL, NULL) - c->r;
    double br;
    double d = core_seg_body_core(a, b, c->body, &br, NULL, NULL);
    return d - c->r - br;
}

typedef struct {
    bool ambiguous_start;   /* something starts within the touch band: skip the sample */
    bool overlap;           /* certain initial overlap */
    double depth_max;
    bool certain_hit;       /* some collider is penetrated deeper than the band during the move */
    double t_certain;       /* earliest first-touch time among those */
} sweep_ref_t;

#define TOUCH 1e-4 /* COLL_PRIM_TOUCH_TOL */

/* Colliders within reach of the query (all of them pass through here: brute force with an
 * exact distance prefilter). */
typedef struct { core_d3 w[3]; const coll_body_t *body; } cand_t;
static cand_t g_cand[MAXT * 3 + 8];
static int g_ncand;
static sweep_ctx_t g_sctx;

static void set_cand(int i)
{
    g_sctx.tri = g_cand[i].body ? NULL : g_cand[i].w;
    g_sctx.body = g_cand[i].body;
}

/* band: the touch tolerance plus the position tolerance of the comparison */
static void sweep_reference(core_d3 c, core_d3 axis, double r, double hh, core_d3 disp, uint8_t mask, uint8_t types,
                            double band, sweep_ref_t *sr)
{
    memset(sr, 0, sizeof *sr);
    sr->t_certain = 1e300;
    g_sctx.s0 = core_d3_sub(c, core_d3_scale(axis, hh));
    g_sctx.s1 = core_d3_add(c, core_d3_scale(axis, hh));
    g_sctx.disp = disp;
    g_sctx.r = r;
    g_ncand = 0;
    const coll_scene_t *sc = &g_w.scene;
    if (types & COLL_TYPE_MESH)
        for (int i = 0; i < sc->mesh_count; i++) {
            const coll_mesh_instance_t *in = sc->meshes[i];
            if (!(in->write_mask & mask)) continue;
            for (uint32_t t = 0; t < coll_mesh_triangle_count(in->mesh); t++) {
                cand_t *k = &g_cand[g_ncand];
                core_world_tri(in, t, k->w);
                /* exact prefilter: a triangle the capsule touches at some t is within hh + r of
                 * the centre's path */
                if (core_seg_tri(c, core_d3_add(c, disp), k->w, NULL, NULL) > hh + r + 1e-3) continue;
                k->body = NULL;
                g_ncand++;
            }
        }
    if (types & COLL_TYPE_BODY)
        for (int i = 0; i < sc->body_count; i++) {
            const coll_body_t *b = sc->bodies[i];
            if (!(b->write_mask & mask)) continue;
            g_cand[g_ncand].body = b;
            g_ncand++;
        }
    for (int i = 0; i < g_ncand; i++) {
        set_cand(i);
        core_sweep_ref_t a;
        core_sweep_analyse(sweep_f, &g_sctx, core_d3_len(disp), &a);
        if (fabs(a.f0) <= band) { sr->ambiguous_start = true; continue; }
        if (a.f0 < 0) {
            sr->overlap = true;
            sr->depth_max = fmax(sr->depth_max, -a.f0);
        }
        if (a.fmin < -band) {
            sr->certain_hit = true;
            sr->t_certain = fmin(sr->t_certain, a.t_touch);
        }
    }
}

/* Smallest f over [0, t] over all candidates (convex per candidate: golden section). */
static double min_f_before(double t)
{
    double best = 1e300;
    for (int i = 0; i < g_ncand; i++) {
        set_cand(i);
        double a = 0, b = t;
        for (int k = 0; k < 50; k++) {
            double m1 = a + (b - a) * 0.381966, m2 = b - (b - a) * 0.381966;
            if (sweep_f(&g_sctx, m1) < sweep_f(&g_sctx, m2)) b = m2; else a = m1;
        }
        best = fmin(best, fmin(sweep_f(&g_sctx, 0.5 * (a + b)), fmin(sweep_f(&g_sctx, 0), sweep_f(&g_sctx, t))));
    }
    return best;
}

static double reported_f(core_d3 c, core_d3 axis, double r, double hh, core_d3 disp, const coll_sweep_hit_t *h,
                         double t, core_d3 *normal)
{
    sweep_ctx_t ctx;
    core_d3 w[3];
    ctx.s0 = core_d3_sub(c, core_d3_scale(axis, hh));
    ctx.s1 = core_d3_add(c, core_d3_scale(axis, hh));
    ctx.disp = disp;
    ctx.r = r;
    ctx.tri = NULL;
    ctx.body = h->body;
    if (h->type == COLL_TYPE_MESH) {
        core_world_tri(h->instance, (uint32_t)h->triangle, w);
        ctx.tri = w;
    }
    core_d3 a = core_d3_add(ctx.s0, core_d3_scale(disp, t)), b = core_d3_add(ctx.s1, core_d3_scale(disp, t));
    core_d3 cp, cq;
    double d;
    if (ctx.tri) {
        d = core_seg_tri(a, b, w, &cp, &cq);
    } else {
        double br;
        d = core_seg_body_core(a, b, h->body, &br, &cp, &cq);
        d -= br;
    }
    core_d3 nn = core_d3_sub(cp, cq);
    double l = core_d3_len(nn);
    *normal = l > 1e-9 ? core_d3_scale(nn, 1.0 / l) : nn;
    return d - r;
}

static void test_random_capsule_sweeps_match_reference(void)
{
    core_rng_t r;
    core_rng_seed(&r, 777);
    int n = 0, hits = 0, overlaps = 0, strict = 0, skipped = 0;
    double worst = 0, worst_n = 0;
    for (int wi = 0; wi < N_WORLDS; wi++) {
        random_world(&r, true);
        for (int q = 0; q < QUERIES_PER_WORLD; q++) {
            core_d3 c = random_point_in_region(&r, 3.0);
            core_d3 axis = { core_rng_range(&r, -0.3, 0.3), 1, core_rng_range(&r, -0.3, 0.3) };
            if (core_rng_u32(&r) % 3 == 0) axis = (core_d3){ core_rng_range(&r, -1, 1), core_rng_range(&r, -1, 1), core_rng_range(&r, -1, 1) };
            double al = core_d3_len(axis);
            if (al < 0.1) continue;
            axis = core_d3_scale(axis, 1.0 / al);
            double rad = core_rng_range(&r, 0.05, 1.0), hh = core_rng_u32(&r) % 5 ? core_rng_range(&r, 0, 1.5) : 0;
            core_d3 target = core_rng_u32(&r) % 4 ? random_surface_point(&r) : random_point_in_region(&r, 3.0);
            core_d3 disp = core_d3_scale(core_d3_sub(target, c), core_rng_range(&r, 0.2, 2.0));
            /* character-scale sweeps (the exact triangle sweep is specified for those; very
             * long ones are covered by the raycasts) */
            double dl = core_d3_len(disp);
            if (dl > 40.0) {
                c = core_d3_sub(target, core_d3_scale(disp, 20.0 / dl));
                disp = core_d3_scale(disp, 40.0 / dl);
            }
            fm_vec3_t cf = to_f(c), af = to_f(axis), df = to_f(disp);
            float rf = (float)rad, hf = (float)hh;
            c = core_d3_of(cf); axis = core_d3_of(af); disp = core_d3_of(df); rad = rf; hh = hf;
            double L = core_d3_len(disp);
            double tol = 1e-4 * fmax(1.0, L);
            double band = TOUCH + tol + g_float_err + 3e-7 * (core_d3_len(c) + L); /* + float rounding */
            sweep_ref_t sr;
            static const uint8_t smasks[] = { 1, 1, 1, 4, 5 };
            static const uint8_t stypes[] = { COLL_TYPE_ALL, COLL_TYPE_ALL, COLL_TYPE_ALL, COLL_TYPE_MESH, COLL_TYPE_BODY };
            uint8_t mask = smasks[core_rng_u32(&r) % 5], types = stypes[core_rng_u32(&r) % 5];
            sweep_reference(c, axis, rad, hh, disp, mask, types, band, &sr);
            if (sr.ambiguous_start) { skipped++; continue; }
            coll_sweep_hit_t h;
            bool got;
            ASSERT_NO_ALLOC(got = coll_capsule_sweep(&g_w.scene, cf, af, rf, hf, df, mask, types, &h));
            if (got) {
                TEST_ASSERT_TRUE((h.type & types) != 0);
                TEST_ASSERT_TRUE(((h.instance ? h.instance->write_mask : h.body->write_mask) & mask) != 0);
            }
            n++;
            char msg[240];
            snprintf(msg, sizeof msg, "world %d query %d: got %d t=%.7f depth=%.6f | overlap %d depth %.6f certain %d "
                     "%.7f (L=%.3f)", wi, q, got, got ? h.t : -1.0, got ? h.depth : -1.0, sr.overlap,
                     sr.depth_max, sr.certain_hit, sr.t_certain, L);
            if (!got) {
                TEST_ASSERT_FALSE_MESSAGE(sr.certain_hit, msg);
                continue;
            }
            hits++;
            TEST_ASSERT_EQUAL_UINT16(h.type == COLL_TYPE_MESH ? h.instance->id : h.body->id, h.id);
            core_d3 nref;
            if (sr.overlap) {
                overlaps++;
                TEST_ASSERT_EQUAL_FLOAT_MESSAGE(0.0f, h.t, msg);
                /* depth of the deepest (distance-based; crossing segments have larger MTV depth) */
                if (sr.depth_max < rad - 1e-3) {
                    TEST_ASSERT_TRUE_MESSAGE(fabs(h.depth - sr.depth_max) <= band, msg);
                    double fr = reported_f(c, axis, rad, hh, disp, &h, 0.0, &nref);
                    TEST_ASSERT_TRUE_MESSAGE(fabs(-fr - h.depth) <= band, msg);
                    double d0 = rad + fr; /* core-to-triangle distance: the normal's lever */
                    if (d0 > 1e-3) {
                        double dn = core_d3_len(core_d3_sub(core_d3_of(h.normal), nref));
                        TEST_ASSERT_TRUE_MESSAGE(dn <= 1e-3 + (g_float_err + 3e-7 * core_d3_len(c)) / d0, msg);
                        worst_n = fmax(worst_n, dn);
                    }
                }
                continue;
            }
            TEST_ASSERT_FALSE_MESSAGE(h.t == 0.0f && h.depth > 0.0f, msg);
            /* Exactness in position space: the reported collider touches at t (within the
             * tolerance), and nothing was penetrated beyond the touch band on the way. */
            double fr = reported_f(c, axis, rad, hh, disp, &h, h.t, &nref);
            core_sweep_ref_t a1;
            {
                /* the reference normal at the reported collider's own exact touching time */
                sweep_ctx_t one = g_sctx;
                core_d3 w[3];
                one.body = h.body;
                one.tri = NULL;
                if (h.instance) {
                    core_world_tri(h.instance, (uint32_t)h.triangle, w);
                    one.tri = w;
                }
                core_sweep_analyse(sweep_f, &one, L, &a1);
                if (a1.fmin <= 0) (void)reported_f(c, axis, rad, hh, disp, &h, a1.t_touch, &nref);
            }
            if (getenv("CORE_DEBUG") && fabs(fr) > band) {
                printf("SWEEP %s: fr %.3g band %.3g minf %.3g\n", msg, fr, band, min_f_before(h.t));
                printf("  c %.9g %.9g %.9g axis %.9g %.9g %.9g r %.9g hh %.9g disp %.9g %.9g %.9g\n", c.x, c.y, c.z, axis.x, axis.y, axis.z, rad, hh, disp.x, disp.y, disp.z);
                if (h.instance) {
                    core_d3 w[3];
                    core_world_tri(h.instance, (uint32_t)h.triangle, w);
                    for (int k = 0; k < 3; k++) printf("   w%d %.9g %.9g %.9g\n", k, w[k].x, w[k].y, w[k].z);
                    /* direct prim call in the triangle's frame */
                    fm_vec3_t seg[2], tri[3], dd = to_f(disp);
                    seg[0] = to_f(core_d3_sub(core_d3_sub(c, core_d3_scale(axis, hh)), w[0]));
                    seg[1] = to_f(core_d3_sub(core_d3_add(c, core_d3_scale(axis, hh)), w[0]));
                    for (int k = 0; k < 3; k++) tri[k] = to_f(core_d3_sub(w[k], w[0]));
                    coll_prim_hit_t ph;
                    bool g = coll_capsule_triangle_sweep(seg, (float)rad, &dd, tri, 1.0f, &ph);
                    printf("  direct prim: %d t %.7f\n", g, g ? ph.t : -1.0);
                }
            }
            TEST_ASSERT_TRUE_MESSAGE(fabs(fr) <= band, msg);
            TEST_ASSERT_TRUE_MESSAGE(min_f_before(h.t) >= -band, msg);
            double dn = core_d3_len(core_d3_sub(core_d3_of(h.normal), nref));
            if (getenv("CORE_DEBUG") && dn > 1e-3 && a1.fmin < -band) {
                printf("NORMAL %s: dn %.3g scene %.6f %.6f %.6f ref %.6f %.6f %.6f\n", msg, dn, h.normal.x, h.normal.y, h.normal.z, nref.x, nref.y, nref.z);
                printf("  c %.9g %.9g %.9g axis %.9g %.9g %.9g r %.9g hh %.9g disp %.9g %.9g %.9g\n", c.x, c.y, c.z, axis.x, axis.y, axis.z, rad, hh, disp.x, disp.y, disp.z);
                if (h.instance) {
                    core_d3 w[3];
                    core_world_tri(h.instance, (uint32_t)h.triangle, w);
                    for (int k = 0; k < 3; k++) printf("   w%d %.9g %.9g %.9g\n", k, w[k].x, w[k].y, w[k].z);
                }
            }
            /* 1e-3, plus what float placement kilometres from the origin allows at an edge
             * or vertex contact (position error / radius) */
            /* at an edge or vertex contact the normal turns by (position offset) / radius: allow
             * for the (tolerated) offset between the scene's and the exact contact */
            double ntol = 1e-3 + (fabs(h.t - a1.t_touch) * L + g_float_err + 3e-7 * (core_d3_len(c) + L)) / rad;
            if (a1.fmin < -band) { /* a grazing touch has no well-conditioned contact normal */
                TEST_ASSERT_TRUE_MESSAGE(dn <= ntol, msg);
                worst_n = fmax(worst_n, dn);
            }
            if (sr.certain_hit) {
                double e = fabs(h.t - sr.t_certain) * L;
                worst = fmax(worst, e / fmax(1.0, L));
                if (e <= tol) strict++;
            }
        }
    }
    printf("capsule sweeps: %d queries (%d skipped: started within the touch band), %d hits (%d initial overlaps), "
           "%d within tol of the certain earliest; worst |dt|*L/max(1,L) %.3g, worst normal err %.3g\n",
           n, skipped, hits, overlaps, strict, worst, worst_n);
    TEST_ASSERT_TRUE(n >= N_WORLDS * QUERIES_PER_WORLD * 9 / 10);
}

/* ------------------------------------------------------------------ deterministic --- */

static const coll_mesh_t *floor_mesh(int slot, float half, float y)
{
    float v[] = { -half, y, -half, half, y, -half, half, y, half, -half, y, half };
    uint32_t idx[] = { 0, 2, 1, 0, 3, 2 };
    memcpy(g_verts, v, sizeof v);
    memcpy(g_idx, idx, sizeof idx);
    return build_mesh(slot, 4, 2, NULL);
}

static void place(coll_mesh_instance_t *in, const coll_mesh_t *m, float x, float y, float z, uint8_t mask, uint16_t id)
{
    coll_transform_t idt = COLL_TRANSFORM_IDENTITY;
    memset(in, 0, sizeof *in);
    in->mesh = m;
    in->xf = idt;
    in->xf.pos.x = x; in->xf.pos.y = y; in->xf.pos.z = z;
    in->write_mask = mask;
    in->id = id;
}

/* A scene counting its queries in st, with m placed once at the origin (layer 1). */
static void scene_of_one_mesh(coll_scene_t *s, coll_query_stats_t *st, coll_mesh_instance_t *a, const coll_mesh_t *m)
{
    coll_scene_init(s);
    memset(st, 0, sizeof *st);
    coll_scene_set_stats(s, st);
    place(a, m, 0, 0, 0, 1, 1);
    coll_scene_add_mesh(s, a);
}

static const fm_vec3_t DOWN = {{ 0, -1, 0 }}, UP = {{ 0, 1, 0 }};

static void test_masks_types_ids_and_remove(void)
{
    coll_scene_t s;
    coll_scene_init(&s);
    const coll_mesh_t *m = floor_mesh(0, 5, 0);
    coll_mesh_instance_t a, b;
    place(&a, m, 0, 0, 0, 0x01, 11);
    place(&b, m, 0, 2, 0, 0x02, 22);
    ASSERT_NO_ALLOC(TEST_ASSERT_EQUAL_INT(COLL_OK, coll_scene_add_mesh(&s, &a)));
    TEST_ASSERT_EQUAL_INT(COLL_OK, coll_scene_add_mesh(&s, &b));
    fm_vec3_t o = {{ 0.3f, 10, 0.2f }};
    coll_ray_hit_t h;
    TEST_ASSERT_TRUE(coll_raycast(&s, o, DOWN, 100, 0xFF, COLL_TYPE_ALL, &h));
    TEST_ASSERT_EQUAL_UINT16(22, h.id);
    TEST_ASSERT_EQUAL_PTR(&b, h.instance);
    TEST_ASSERT_NULL(h.body);
    TEST_ASSERT_EQUAL_UINT8(COLL_TYPE_MESH, h.type);
    TEST_ASSERT_FLOAT_WITHIN(1e-5f, 8.0f, h.distance);
    TEST_ASSERT_FLOAT_WITHIN(1e-5f, 1.0f, h.normal.y);
    TEST_ASSERT_FLOAT_WITHIN(1e-5f, 2.0f, h.point.y);
    TEST_ASSERT_TRUE(h.triangle == 0 || h.triangle == 1);
    /* read mask 1 sees only a */
    TEST_ASSERT_TRUE(coll_raycast(&s, o, DOWN, 100, 0x01, COLL_TYPE_ALL, &h));
    TEST_ASSERT_EQUAL_UINT16(11, h.id);
    /* type filter */
    TEST_ASSERT_FALSE(coll_raycast(&s, o, DOWN, 100, 0xFF, COLL_TYPE_BODY, &h));
    TEST_ASSERT_FALSE(coll_raycast(&s, o, DOWN, 100, 0x04, COLL_TYPE_ALL, &h));
    /* max distance */
    TEST_ASSERT_FALSE(coll_raycast(&s, o, DOWN, 7.9f, 0xFF, COLL_TYPE_ALL, &h));
    /* sweeps and overlaps follow the same masks */
    coll_sweep_hit_t sh;
    fm_vec3_t c = {{ 0, 4, 0 }}, disp = {{ 0, -10, 0 }};
    TEST_ASSERT_TRUE(coll_capsule_sweep(&s, c, UP, 0.5f, 0.5f, disp, 0xFF, COLL_TYPE_ALL, &sh));
    TEST_ASSERT_EQUAL_UINT16(22, sh.id);
    TEST_ASSERT_FLOAT_WITHIN(1e-4f, 0.1f, sh.t); /* bottom at 3, floor b at 2: 1 m of 10 */
    TEST_ASSERT_TRUE(coll_capsule_sweep(&s, c, UP, 0.5f, 0.5f, disp, 0x01, COLL_TYPE_ALL, &sh));
    TEST_ASSERT_EQUAL_UINT16(11, sh.id);
    TEST_ASSERT_FLOAT_WITHIN(1e-4f, 0.3f, sh.t);
    TEST_ASSERT_FALSE(coll_capsule_sweep(&s, c, UP, 0.5f, 0.5f, disp, 0xFF, COLL_TYPE_BODY, &sh));
    /* remove b, query again */
    ASSERT_NO_ALLOC(TEST_ASSERT_EQUAL_INT(COLL_OK, coll_scene_remove_mesh(&s, &b)));
    TEST_ASSERT_EQUAL_INT(COLL_ERR_NOT_FOUND, coll_scene_remove_mesh(&s, &b));
    TEST_ASSERT_TRUE(coll_raycast(&s, o, DOWN, 100, 0xFF, COLL_TYPE_ALL, &h));
    TEST_ASSERT_EQUAL_UINT16(11, h.id);
    TEST_ASSERT_TRUE(coll_capsule_sweep(&s, c, UP, 0.5f, 0.5f, disp, 0xFF, COLL_TYPE_ALL, &sh));
    TEST_ASSERT_EQUAL_UINT16(11, sh.id);
    /* nothing left */
    TEST_ASSERT_EQUAL_INT(COLL_OK, coll_scene_remove_mesh(&s, &a));
    TEST_ASSERT_FALSE(coll_raycast(&s, o, DOWN, 100, 0xFF, COLL_TYPE_ALL, &h));
}

static void test_registry_errors(void)
{
    static coll_scene_t s;
    static coll_mesh_instance_t in[COLL_SCENE_MAX_MESHES + 1];
    static coll_body_t bd[COLL_SCENE_MAX_BODIES + 1];
    coll_scene_init(&s);
    const coll_mesh_t *m = floor_mesh(0, 1, 0);
    for (int i = 0; i <= COLL_SCENE_MAX_MESHES; i++) place(&in[i], m, 0, 0, 0, 1, (uint16_t)i);
    for (int i = 0; i < COLL_SCENE_MAX_MESHES; i++) TEST_ASSERT_EQUAL_INT(COLL_OK, coll_scene_add_mesh(&s, &in[i]));
    TEST_ASSERT_EQUAL_INT(COLL_ERR_INVALID_ARG, coll_scene_add_mesh(&s, &in[3])); /* duplicate */
    TEST_ASSERT_EQUAL_INT(COLL_ERR_FULL, coll_scene_add_mesh(&s, &in[COLL_SCENE_MAX_MESHES]));
    TEST_ASSERT_EQUAL_UINT16(COLL_SCENE_MAX_MESHES, s.mesh_count);
    TEST_ASSERT_EQUAL_INT(COLL_OK, coll_scene_remove_mesh(&s, &in[5]));
    TEST_ASSERT_EQUAL_INT(COLL_OK, coll_scene_add_mesh(&s, &in[COLL_SCENE_MAX_MESHES]));
    TEST_ASSERT_EQUAL_INT(COLL_ERR_INVALID_ARG, coll_scene_add_mesh(NULL, &in[0]));
    coll_mesh_instance_t bad;
    place(&bad, m, 0, 0, 0, 1, 0);
    bad.xf.scale.y = 0;
    coll_scene_init(&s);
    TEST_ASSERT_EQUAL_INT(COLL_ERR_INVALID_ARG, coll_scene_add_mesh(&s, &bad));
    bad.xf.scale.y = 1;
    bad.xf.pos.x = NAN;
    TEST_ASSERT_EQUAL_INT(COLL_ERR_INVALID_ARG, coll_scene_add_mesh(&s, &bad));
    bad.xf.pos.x = 0;
    bad.mesh = NULL;
    TEST_ASSERT_EQUAL_INT(COLL_ERR_INVALID_ARG, coll_scene_add_mesh(&s, &bad));
    TEST_ASSERT_EQUAL_UINT16(0, s.mesh_count);
    for (int i = 0; i <= COLL_SCENE_MAX_BODIES; i++) {
        coll_transform_t idt = COLL_TRANSFORM_IDENTITY;
        memset(&bd[i], 0, sizeof bd[i]);
        bd[i].shape = COLL_SHAPE_SPHERE;
        bd[i].half_extents.x = 1;
        bd[i].xf = idt;
        bd[i].write_mask = 1;
    }
    for (int i = 0; i < COLL_SCENE_MAX_BODIES; i++) TEST_ASSERT_EQUAL_INT(COLL_OK, coll_scene_add_body(&s, &bd[i]));
    TEST_ASSERT_EQUAL_INT(COLL_ERR_INVALID_ARG, coll_scene_add_body(&s, &bd[0]));
    TEST_ASSERT_EQUAL_INT(COLL_ERR_FULL, coll_scene_add_body(&s, &bd[COLL_SCENE_MAX_BODIES]));
    TEST_ASSERT_EQUAL_INT(COLL_ERR_NOT_FOUND, coll_scene_remove_body(&s, &bd[COLL_SCENE_MAX_BODIES]));
    ASSERT_NO_ALLOC(TEST_ASSERT_EQUAL_INT(COLL_OK, coll_scene_remove_body(&s, &bd[0])));
    TEST_ASSERT_EQUAL_UINT16(COLL_SCENE_MAX_BODIES - 1, s.body_count);
    /* current scene */
    coll_scene_set_current(&s);
    TEST_ASSERT_EQUAL_PTR(&s, coll_scene_current());
    coll_scene_set_current(NULL);
    TEST_ASSERT_NULL(coll_scene_current());
}

static void test_invalid_queries_return_false(void)
{
    coll_scene_t s;
    coll_scene_init(&s);
    coll_mesh_instance_t a;
    place(&a, floor_mesh(0, 5, 0), 0, 0, 0, 1, 1);
    coll_scene_add_mesh(&s, &a);
    fm_vec3_t o = {{ 0, 1, 0 }}, nan3 = {{ NAN, 0, 0 }}, zero = {{ 0, 0, 0 }};
    coll_ray_hit_t h;
    TEST_ASSERT_TRUE(coll_raycast(&s, o, DOWN, 2, 0xFF, COLL_TYPE_ALL, &h));
    TEST_ASSERT_FALSE(coll_raycast(&s, nan3, DOWN, 2, 0xFF, COLL_TYPE_ALL, &h));
    TEST_ASSERT_FALSE(coll_raycast(&s, o, nan3, 2, 0xFF, COLL_TYPE_ALL, &h));
    TEST_ASSERT_FALSE(coll_raycast(&s, o, zero, 2, 0xFF, COLL_TYPE_ALL, &h));
    TEST_ASSERT_FALSE(coll_raycast(&s, o, DOWN, 0, 0xFF, COLL_TYPE_ALL, &h));
    TEST_ASSERT_FALSE(coll_raycast(&s, o, DOWN, INFINITY, 0xFF, COLL_TYPE_ALL, &h));
    coll_sweep_hit_t sh;
    TEST_ASSERT_FALSE(coll_capsule_sweep(&s, nan3, UP, 0.5f, 0.5f, DOWN, 0xFF, COLL_TYPE_ALL, &sh));
    TEST_ASSERT_FALSE(coll_capsule_sweep(&s, o, UP, -1, 0.5f, DOWN, 0xFF, COLL_TYPE_ALL, &sh));
    TEST_ASSERT_FALSE(coll_capsule_sweep(&s, o, UP, 0.5f, 0.5f, nan3, 0xFF, COLL_TYPE_ALL, &sh));
    /* an instance whose transform went bad after adding is skipped, not crashed on */
    a.xf.scale.x = 0;
    TEST_ASSERT_FALSE(coll_raycast(&s, o, DOWN, 2, 0xFF, COLL_TYPE_ALL, &h));
    a.xf.scale.x = NAN;
    TEST_ASSERT_FALSE(coll_capsule_sweep(&s, o, UP, 0.5f, 0.5f, DOWN, 0xFF, COLL_TYPE_ALL, &sh));
}

static void test_initial_overlap_deepest_and_overlaps_list(void)
{
    coll_scene_t s;
    coll_scene_init(&s);
    const coll_mesh_t *m = floor_mesh(0, 5, 0);
    coll_mesh_instance_t a, b;
    place(&a, m, 0, 0, 0, 1, 1);     /* floor at y = 0 */
    place(&b, m, 0, 0.3f, 0, 1, 2);  /* floor at y = 0.3 */
    coll_scene_add_mesh(&s, &a);
    coll_scene_add_mesh(&s, &b);
    fm_vec3_t c = {{ 0.1f, 0.9f, 0.2f }}, disp = {{ 1, 0, 0 }};
    /* capsule r 0.5, hh 0.2: bottom sphere centre at 0.7: floor b 0.4 away (depth 0.1),
     * floor a 0.7 away: no overlap... lower it */
    c.y = 0.6f; /* sphere centre 0.4: a depth 0.1, b depth 0.4 */
    coll_sweep_hit_t h;
    ASSERT_NO_ALLOC(TEST_ASSERT_TRUE(coll_capsule_sweep(&s, c, UP, 0.5f, 0.2f, disp, 0xFF, COLL_TYPE_ALL, &h)));
    TEST_ASSERT_EQUAL_FLOAT(0.0f, h.t);
    TEST_ASSERT_EQUAL_UINT16(2, h.id);
    TEST_ASSERT_FLOAT_WITHIN(1e-4f, 0.4f, h.depth);
    TEST_ASSERT_FLOAT_WITHIN(1e-4f, 1.0f, h.normal.y);
    coll_contact_t out[8];
    uint32_t n;
    ASSERT_NO_ALLOC(n = coll_capsule_overlaps(&s, c, UP, 0.5f, 0.2f, 0xFF, COLL_TYPE_ALL, out, 8));
    /* the sphere centre is over the shared diagonal of each floor's two triangles, or
     * not: count the triangles actually touched */
    TEST_ASSERT_EQUAL_UINT32(4, n);
    TEST_ASSERT_EQUAL_UINT16(2, out[0].id);
    for (uint32_t i = 1; i < n; i++) TEST_ASSERT_TRUE(out[i - 1].depth >= out[i].depth);
    TEST_ASSERT_FLOAT_WITHIN(1e-4f, 0.4f, out[0].depth);
    TEST_ASSERT_FLOAT_WITHIN(1e-4f, 0.1f, out[2].depth);
    /* the neighbour across the diagonal: 0.1/sqrt(2) sideways */
    TEST_ASSERT_FLOAT_WITHIN(1e-4f, 0.5f - sqrtf(0.16f + 0.005f), out[3].depth);
    TEST_ASSERT_EQUAL_UINT16(1, out[3].id);
    /* max_out smaller than the total: deepest kept, total still returned */
    coll_contact_t one;
    TEST_ASSERT_EQUAL_UINT32(n, coll_capsule_overlaps(&s, c, UP, 0.5f, 0.2f, 0xFF, COLL_TYPE_ALL, &one, 1));
    TEST_ASSERT_FLOAT_WITHIN(1e-4f, 0.4f, one.depth);
    TEST_ASSERT_EQUAL_UINT32(n, coll_capsule_overlaps(&s, c, UP, 0.5f, 0.2f, 0xFF, COLL_TYPE_ALL, NULL, 0));
    TEST_ASSERT_EQUAL_UINT32(0, coll_capsule_overlaps(&s, c, UP, 0.5f, 0.2f, 0x02, COLL_TYPE_ALL, out, 8));
}

/* Triangle (a, b, c) into g_verts / g_idx as the nt-th (its own three vertices). */
static void put_tri(uint32_t nt, fm_vec3_t a, fm_vec3_t b, fm_vec3_t c)
{
    const fm_vec3_t v[3] = { a, b, c };
    for (int k = 0; k < 3; k++) {
        for (int ax = 0; ax < 3; ax++) g_verts[3 * (3 * nt + (uint32_t)k) + (uint32_t)ax] = v[k].v[ax];
        g_idx[3 * nt + (uint32_t)k] = 3 * nt + (uint32_t)k;
    }
}

/* The ball's overlaps keeping distinct contacts answer like a single copy of each piece:
 * 24 coplanar copies of one triangle the ball sinks into (a level's duplicated brushes,
 * near copies of a slab), plus one shallower contact that matters (scene A: a wall on the
 * far side, the side of a hole the crack rule's surround test needs; scene B, the other
 * way round: the floor the ball rests on beside 24 copies of a wall its side is in, the
 * contact the support tests look for). Kept to the character body's 16, the deeper copies
 * dropped that contact (soak s47 l73). On the scene and on the gathered scene. */
static void test_ball_overlaps_keep_one_contact_per_copy(void)
{
    const fm_vec3_t F[3] = { {{ -2, 0, -2 }}, {{ -2, 0, 4 }}, {{ 4, 0, -2 }} };        /* y = 0, up +y */
    const fm_vec3_t W[3] = { {{ 0.4f, -2, -2 }}, {{ 0.4f, 4, -2 }}, {{ 0.4f, -2, 4 }} }; /* x = 0.4 */
    coll_mesh_build_opts_t o = { 0.5f, 0 };
    for (int scn = 0; scn < 2; scn++) {
        /* A: the ball (r 0.5) 0.1 into the floor's copies, 0.02 into the wall (at x 0.48);
         * B: 0.1 into the wall's copies, 0.01 into the floor (0.49 below the centre) */
        const fm_vec3_t *dup = scn == 0 ? F : W, *one = scn == 0 ? W : F;
        const fm_vec3_t shift = scn == 0 ? (fm_vec3_t){{ 0.08f, 0, 0 }} : (fm_vec3_t){{ 0, -0.49f, 0 }};
        const fm_vec3_t c = {{ 0, scn == 0 ? 0.4f : 0.0f, 0 }};
        uint32_t nt = 0;
        for (int i = 0; i < 24; i++, nt++) /* the copies, their vertices in turn (rounding differs) */
            put_tri(nt, dup[i % 3], dup[(i + 1) % 3], dup[(i + 2) % 3]);
        fm_vec3_t s0, s1, s2;
        fm_vec3_add(&s0, &one[0], &shift);
        fm_vec3_add(&s1, &one[1], &shift);
        fm_vec3_add(&s2, &one[2], &shift);
        put_tri(nt++, s0, s1, s2);
        const coll_mesh_t *m = build_mesh(scn, 3 * nt, nt, &o);
        coll_scene_t s;
        coll_query_stats_t st;
        coll_mesh_instance_t a;
        scene_of_one_mesh(&s, &st, &a, m);
        /* the premise: 25 contacts, and the deepest 16 are all copies */
        coll_contact_t ct[16];
        TEST_ASSERT_EQUAL_UINT32(25, coll_capsule_overlaps(&s, c, UP, 0.5f, 0.0f, 0xFF, COLL_TYPE_ALL, ct, 16));
        static coll_gather_t g;
        const fm_vec3_t lo = {{ -1, -1, -1 }}, hi = {{ 1, 1.5f, 1 }};
        coll_gather_begin(&g, &s, lo, hi, 0xFF, COLL_TYPE_MESH);
        TEST_ASSERT_TRUE(g.valid);
        for (int on_g = 0; on_g < 2; on_g++) {
            uint32_t gq = st.gather_queries, n;
            memset(ct, 0, sizeof ct);
            ASSERT_NO_ALLOC(n = on_g ? coll_gather_capsule_overlaps_distinct(&g, c, UP, 0.5f, 0.0f, ct, 16)
                                     : coll_capsule_overlaps_distinct(&s, c, UP, 0.5f, 0.0f, 0xFF, COLL_TYPE_ALL,
                                                                      ct, 16));
            TEST_ASSERT_EQUAL_UINT32(on_g ? gq + 1 : gq, st.gather_queries); /* answered where asked */
            TEST_ASSERT_EQUAL_UINT32(2, n);
            /* the copies' contact first (deeper), then the other piece's */
            const float want_n0 = scn == 0 ? ct[0].normal.y : -ct[0].normal.x;
            const float want_n1 = scn == 0 ? -ct[1].normal.x : ct[1].normal.y;
            TEST_ASSERT_FLOAT_WITHIN(1e-5f, 1.0f, want_n0);
            TEST_ASSERT_FLOAT_WITHIN(1e-4f, 0.1f, ct[0].depth);
            TEST_ASSERT_FLOAT_WITHIN(1e-5f, 1.0f, want_n1);
            TEST_ASSERT_FLOAT_WITHIN(1e-4f, scn == 0 ? 0.02f : 0.01f, ct[1].depth);
        }
    }
}

/* A capsule overlapping more distinct triangles than the dedup table holds: the query
 * falls back (counted) and still finds the deepest, and the overlap list has no
 * duplicates. */
static void test_dedup_overflow_falls_back_exactly(void)
{
    /* 40x40 quads of 5 cm under a 1 m sphere: ~ 1250 triangles in reach, many cells */
    uint32_t nv;
    uint32_t nt = core_grid_level(g_verts, &nv, g_idx, 40, 40, 0.05f, -1, 0, -1);
    for (uint32_t i = 0; i < nv; i++) g_verts[3 * i + 1] = 0;
    g_verts[3 * (20 * 41 + 20) + 1] = 0.05f; /* one bump: the deepest vertex */
    coll_mesh_build_opts_t o = { 0.1f, 0 };
    const coll_mesh_t *m = build_mesh(0, nv, nt, &o);
    coll_scene_t s;
    coll_query_stats_t st;
    coll_mesh_instance_t a;
    scene_of_one_mesh(&s, &st, &a, m);
    fm_vec3_t c = {{ 0, 0.8f, 0 }}, disp = {{ 0, -0.1f, 0 }};
    coll_sweep_hit_t h;
    uint32_t before = st.dedup_overflows;
    TEST_ASSERT_TRUE(coll_capsule_sweep(&s, c, UP, 1.0f, 0.0f, disp, 0xFF, COLL_TYPE_ALL, &h));
    TEST_ASSERT_TRUE(st.dedup_overflows > before);
    TEST_ASSERT_EQUAL_UINT32(1, st.queries);
    TEST_ASSERT_EQUAL_FLOAT(0.0f, h.t);
    TEST_ASSERT_FLOAT_WITHIN(1e-4f, 0.25f, h.depth); /* bump top at 0.05, sphere bottom at -0.2 */
    static coll_contact_t out[4000];
    uint32_t n = coll_capsule_overlaps(&s, c, UP, 1.0f, 0.0f, 0xFF, COLL_TYPE_ALL, out, 4000);
    /* reference count: triangles within 1 m of the centre, minus touching-band ones */
    uint32_t want = 0;
    for (uint32_t t = 0; t < nt; t++) {
        fm_vec3_t v[3];
        core_d3 w[3];
        coll_mesh_triangle(m, t, v);
        for (int k = 0; k < 3; k++) w[k] = core_d3_of(v[k]);
        core_d3 cd = core_d3_of(c);
        if (core_seg_tri(cd, cd, w, NULL, NULL) < 1.0 - 2e-4) want++;
    }
    TEST_ASSERT_TRUE(want > 500);
    TEST_ASSERT_EQUAL_UINT32(want, n);
    for (uint32_t i = 0; i < n; i++)
        for (uint32_t j = i + 1; j < n; j++) TEST_ASSERT_FALSE(out[i].triangle == out[j].triangle);
    TEST_ASSERT_FLOAT_WITHIN(1e-4f, 0.25f, out[0].depth);

    /* A ray skimming a dense floor (50 triangles per cell) visits far more triangles than
     * the table holds; it still returns the nearest hit. Diagonally: the ray's box (the
     * first test of every candidate, before the table) is then the square under its path,
     * so every triangle of the cells it crosses enters the table. */
    nt = core_grid_level(g_verts, &nv, g_idx, 60, 60, 0.02f, -0.6f, 0, -0.6f);
    for (uint32_t i = 0; i < nv; i++) g_verts[3 * i + 1] = 0;
    g_verts[1] = 0.3f; /* a raised far corner gives the bounds height, so the ray is inside them */
    m = build_mesh(1, nv, nt, &o);
    a.mesh = m;
    before = st.dedup_overflows;
    fm_vec3_t ro = {{ -0.59f, 0.002f, -0.587f }}, rd = {{ 1, -0.002f, 1 }};
    fm_vec3_norm(&rd, &rd);
    coll_ray_hit_t rh;
    TEST_ASSERT_TRUE(coll_raycast(&s, ro, rd, 10, 0xFF, COLL_TYPE_ALL, &rh));
    TEST_ASSERT_TRUE(st.dedup_overflows > before);
    double best = 1e300;
    for (uint32_t t = 0; t < nt; t++) {
        fm_vec3_t v[3];
        core_d3 w[3], nn;
        double sr, mb;
        coll_mesh_triangle(m, t, v);
        for (int k = 0; k < 3; k++) w[k] = core_d3_of(v[k]);
        if (core_ray_tri(core_d3_of(ro), core_d3_of(rd), w, 10, 0.0, &sr, &mb, &nn)) best = fmin(best, sr);
    }
    TEST_ASSERT_TRUE(best < 10);
    TEST_ASSERT_FLOAT_WITHIN(1e-4f, (float)best, rh.distance);
}

/* Two sweeps' hits the same bit for bit: distance, normal, point, triangle. */
static void assert_same_sweep_hit(const coll_sweep_hit_t *a, const coll_sweep_hit_t *b)
{
    TEST_ASSERT_EQUAL_MEMORY(&a->t, &b->t, sizeof a->t);
    TEST_ASSERT_EQUAL_MEMORY(&a->normal, &b->normal, sizeof a->normal);
    TEST_ASSERT_EQUAL_MEMORY(&a->point, &b->point, sizeof a->point);
    TEST_ASSERT_EQUAL_INT32(a->triangle, b->triangle);
}

/* A step's gathered sweep that reaches outside the gathered box (the crack rule's roll) is
 * answered from the gathered triangles when it meets one before it leaves the box (nothing
 * outside can be met sooner), and from the scene otherwise: the same hits as the scene's. */
static void test_gathered_sweep_leaving_the_box(void)
{
    /* walls (quads across x) at x = 0.8 and x = 3, and one at x = -3 */
    const float wx[3] = { 0.8f, 3.0f, -3.0f };
    uint32_t nv = 0, nt = 0;
    for (int w = 0; w < 3; w++) {
        for (int k = 0; k < 4; k++) {
            g_verts[3 * nv + 0] = wx[w];
            g_verts[3 * nv + 1] = (k & 1) ? 2.0f : -2.0f;
            g_verts[3 * nv + 2] = (k & 2) ? 2.0f : -2.0f;
            nv++;
        }
        uint32_t b = nv - 4;
        uint32_t q[6] = { b, b + 1, b + 3, b, b + 3, b + 2 };
        for (int k = 0; k < 6; k++) g_idx[3 * nt + k] = q[k];
        nt += 2;
    }
    coll_mesh_build_opts_t o = { 1.0f, 0 };
    const coll_mesh_t *m = build_mesh(0, nv, nt, &o);
    coll_scene_t s;
    coll_query_stats_t st;
    coll_mesh_instance_t a;
    scene_of_one_mesh(&s, &st, &a, m);
    static coll_gather_t g;
    coll_gather_begin(&g, &s, (fm_vec3_t){{ -1, -1, -1 }}, (fm_vec3_t){{ 1, 1, 1 }}, 0xFF, COLL_TYPE_ALL);
    TEST_ASSERT_EQUAL_UINT16(2, g.ntris);
    const fm_vec3_t c = {{ 0, 0, 0 }};
    coll_sweep_hit_t h, want;
    /* +x: the wall at 0.8 is met at t = 0.1375, inside the gathered box */
    fm_vec3_t d = {{ 4, 0, 0 }};
    uint32_t q0 = st.queries;
    TEST_ASSERT_TRUE(coll_gather_capsule_sweep(&g, c, UP, 0.25f, 0.0f, d, &h));
    TEST_ASSERT_EQUAL_UINT32(1, st.gather_queries);
    TEST_ASSERT_EQUAL_UINT32(0, st.gather_misses);
    TEST_ASSERT_EQUAL_UINT32(q0, st.queries);
    TEST_ASSERT_TRUE(coll_capsule_sweep(&s, c, UP, 0.25f, 0.0f, d, 0xFF, COLL_TYPE_ALL, &want));
    TEST_ASSERT_FLOAT_WITHIN(1e-6f, want.t, h.t);
    TEST_ASSERT_FLOAT_WITHIN(1e-6f, 0.1375f, h.t);
    TEST_ASSERT_EQUAL_INT32(want.triangle, h.triangle);
    /* the wall's triangles tested exactly keep their setup (gather.h), and the step's later
     * queries, using it, answer to the bit as the first did */
    TEST_ASSERT_TRUE(g.tris[0].prep.ready || g.tris[1].prep.ready);
    coll_sweep_hit_t again;
    TEST_ASSERT_TRUE(coll_gather_capsule_sweep(&g, c, UP, 0.25f, 0.0f, d, &again));
    assert_same_sweep_hit(&h, &again);
    st.gather_queries--; /* (the counts below are the first sweep's) */
    /* -x: nothing within the box; the wall at -3 lies beyond it: the scene answers */
    d = (fm_vec3_t){{ -4, 0, 0 }};
    TEST_ASSERT_TRUE(coll_gather_capsule_sweep(&g, c, UP, 0.25f, 0.0f, d, &h));
    TEST_ASSERT_EQUAL_UINT32(1, st.gather_misses);
    TEST_ASSERT_TRUE(coll_capsule_sweep(&s, c, UP, 0.25f, 0.0f, d, 0xFF, COLL_TYPE_ALL, &want));
    TEST_ASSERT_EQUAL_FLOAT(want.t, h.t);
    TEST_ASSERT_EQUAL_INT32(want.triangle, h.triangle);
    TEST_ASSERT_FLOAT_WITHIN(1e-6f, 2.75f / 4.0f, h.t);
    /* across the walls (along z), out of the box: no hit anywhere */
    d = (fm_vec3_t){{ 0, 0, 4 }};
    TEST_ASSERT_FALSE(coll_gather_capsule_sweep(&g, c, UP, 0.25f, 0.0f, d, &h));
    TEST_ASSERT_EQUAL_UINT32(2, st.gather_misses);
    /* a start outside the box: the scene */
    fm_vec3_t far = {{ 2.6f, 0, 0 }};
    d = (fm_vec3_t){{ 0.2f, 0, 0 }};
    TEST_ASSERT_TRUE(coll_gather_capsule_sweep(&g, far, UP, 0.25f, 0.0f, d, &h));
    TEST_ASSERT_EQUAL_UINT32(3, st.gather_misses);
    TEST_ASSERT_FLOAT_WITHIN(1e-5f, 0.75f, h.t);
}

/* A level 5 km from the origin: hits accurate to well under 1 mm. */
static void test_precision_far_from_origin(void)
{
    uint32_t nv;
    uint32_t nt = core_grid_level(g_verts, &nv, g_idx, 20, 20, 1.0f, 5000, 3000, -5000);
    const coll_mesh_t *m = build_mesh(0, nv, nt, NULL);
    coll_scene_t s;
    coll_scene_init(&s);
    coll_mesh_instance_t a;
    place(&a, m, 0, 0, 0, 1, 1);
    coll_scene_add_mesh(&s, &a);
    /* and a rotated, scaled instance of a small local mesh placed at 5 km */
    nt = core_grid_level(g_verts, &nv, g_idx, 10, 10, 1.0f, -5, 0, -5);
    const coll_mesh_t *m2 = build_mesh(1, nv, nt, NULL);
    coll_mesh_instance_t b;
    place(&b, m2, -5000, 2000, 5000, 1, 2);
    fm_vec3_t ax = {{ 0.3f, 0.9f, 0.1f }};
    fm_vec3_norm(&ax, &ax);
    fm_quat_from_axis_angle(&b.xf.rot, &ax, 0.7f);
    b.xf.scale.x = 1.5f; b.xf.scale.y = 0.7f; b.xf.scale.z = 2.0f;
    coll_scene_add_mesh(&s, &b);
    core_rng_t r;
    core_rng_seed(&r, 5);
    double worst = 0;
    for (int i = 0; i < 400; i++) {
        const coll_mesh_instance_t *in = i % 2 ? &b : &a;
        core_d3 p;
        g_w.scene = s; /* for random_surface_point */
        g_w.scene.mesh_count = 1;
        g_w.scene.meshes[0] = (coll_mesh_instance_t *)in;
        p = random_surface_point(&r);
        core_d3 dir = { core_rng_range(&r, -0.5, 0.5), -1, core_rng_range(&r, -0.5, 0.5) };
        dir = core_d3_scale(dir, 1.0 / core_d3_len(dir));
        core_d3 o = core_d3_sub(p, core_d3_scale(dir, 2.0));
        fm_vec3_t of = to_f(o), df = to_f(dir);
        coll_ray_hit_t h;
        TEST_ASSERT_TRUE(coll_raycast(&s, of, df, 10, 0xFF, COLL_TYPE_ALL, &h));
        /* reference for the reported triangle */
        core_d3 w[3], n;
        double sref, mb;
        core_world_tri(h.instance, (uint32_t)h.triangle, w);
        TEST_ASSERT_TRUE(core_ray_tri(core_d3_of(of), core_d3_of(df), w, 20, 1e-3, &sref, &mb, &n));
        worst = fmax(worst, fabs(sref - h.distance));
        TEST_ASSERT_TRUE(fabs(sref - h.distance) < 1e-3);
        /* capsule resting 1 cm above the surface point moving down 2 cm: hits at t ~ 0.5 */
        core_d3 up = core_d3_scale(n, 1.0);
        core_d3 cc = core_d3_add(p, core_d3_scale(up, 0.3 + 0.01));
        fm_vec3_t cf = to_f(cc), nf = to_f(n), dispf = to_f(core_d3_scale(up, -0.02));
        coll_sweep_hit_t sh;
        if (coll_capsule_sweep(&s, cf, nf, 0.3f, 0.0f, dispf, 0xFF, COLL_TYPE_ALL, &sh)) {
            core_d3 wn;
            double f = reported_f(core_d3_of(cf), core_d3_of(nf), 0.3, 0.0, core_d3_of(dispf), &sh, sh.t, &wn);
            worst = fmax(worst, fabs(f));
            TEST_ASSERT_TRUE(fabs(f) < 1e-3);
        }
    }
    printf("5 km from the origin: worst distance error %.3g m\n", worst);
}

/* The game moves / rotates / scales an instance without telling the scene. */
static void test_moving_platform_read_every_query(void)
{
    coll_scene_t s;
    coll_scene_init(&s);
    coll_mesh_instance_t a;
    place(&a, floor_mesh(0, 1, 0), 0, 0, 0, 1, 1);
    coll_scene_add_mesh(&s, &a);
    fm_vec3_t o = {{ 0.5f, 10, 0.5f }};
    coll_ray_hit_t h;
    TEST_ASSERT_TRUE(coll_raycast(&s, o, DOWN, 100, 0xFF, COLL_TYPE_ALL, &h));
    TEST_ASSERT_FLOAT_WITHIN(1e-5f, 10.0f, h.distance);
    a.xf.pos.y = 3;
    TEST_ASSERT_TRUE(coll_raycast(&s, o, DOWN, 100, 0xFF, COLL_TYPE_ALL, &h));
    TEST_ASSERT_FLOAT_WITHIN(1e-5f, 7.0f, h.distance);
    a.xf.pos.x = 5; /* moved away */
    TEST_ASSERT_FALSE(coll_raycast(&s, o, DOWN, 100, 0xFF, COLL_TYPE_ALL, &h));
    a.xf.scale.x = 10; /* scaled back under the ray */
    TEST_ASSERT_TRUE(coll_raycast(&s, o, DOWN, 100, 0xFF, COLL_TYPE_ALL, &h));
    fm_vec3_t zax = {{ 0, 0, 1 }};
    fm_quat_from_axis_angle(&a.xf.rot, &zax, FM_PI / 4); /* tilt 45 degrees about z */
    a.xf.pos.x = 0.5f;
    a.xf.scale.x = 1;
    TEST_ASSERT_TRUE(coll_raycast(&s, o, DOWN, 100, 0xFF, COLL_TYPE_ALL, &h));
    TEST_ASSERT_FLOAT_WITHIN(1e-4f, 7.0f, h.distance);
    TEST_ASSERT_FLOAT_WITHIN(1e-4f, 0.70710678f, h.normal.y);
}

/* A ray running exactly along cell boundaries (and along a triangle edge) of a grid with a
 * given cell size still finds the nearest triangle. */
static void test_ray_along_cell_boundary(void)
{
    uint32_t nv;
    uint32_t nt = core_grid_level(g_verts, &nv, g_idx, 16, 16, 1.0f, 0, 0, 0);
    for (uint32_t i = 0; i < nv; i++) g_verts[3 * i + 1] = 0;
    /* a wall at x = 9.5 crossing the boundary plane */
    float wall[] = { 9.5f, -1, 3, 9.5f, 3, 3, 9.5f, -1, 13 };
    memcpy(g_verts + 3 * nv, wall, sizeof wall);
    g_idx[3 * nt] = nv; g_idx[3 * nt + 1] = nv + 1; g_idx[3 * nt + 2] = nv + 2;
    coll_mesh_build_opts_t o = { 2.0f, 0 };
    const coll_mesh_t *m = build_mesh(0, nv + 3, nt + 1, &o);
    TEST_ASSERT_EQUAL_FLOAT(2.0f, m->cell_size);
    coll_scene_t s;
    coll_scene_init(&s);
    coll_mesh_instance_t a;
    place(&a, m, 0, 0, 0, 1, 1);
    coll_scene_add_mesh(&s, &a);
    /* along x at y = 0 (the floor plane, a cell boundary), z = 4 (a boundary, and an edge) */
    fm_vec3_t org = {{ 0.25f, 0.0f, 4.0f }}, dx = {{ 1, 0, 0 }};
    coll_ray_hit_t h;
    (void)coll_raycast(&s, org, dx, 30, 0xFF, COLL_TYPE_ALL, &h); /* coplanar with the floor: either way */
    fm_vec3_t org2 = {{ 0.25f, 2.0f, 4.0f }}; /* y = 2 and z = 4 are both cell boundaries */
    TEST_ASSERT_TRUE(coll_raycast(&s, org2, dx, 30, 0xFF, COLL_TYPE_ALL, &h));
    TEST_ASSERT_EQUAL_INT32((int32_t)nt, h.triangle);
    TEST_ASSERT_FLOAT_WITHIN(1e-5f, 9.25f, h.distance);
    TEST_ASSERT_FLOAT_WITHIN(1e-5f, -1.0f, h.normal.x);
    /* straight down along the line x = 4, z = 6 (two boundaries at once) onto the floor */
    fm_vec3_t org3 = {{ 4.0f, 7.0f, 6.0f }};
    TEST_ASSERT_TRUE(coll_raycast(&s, org3, DOWN, 30, 0xFF, COLL_TYPE_ALL, &h));
    TEST_ASSERT_FLOAT_WITHIN(1e-5f, 7.0f, h.distance);
    /* diagonal through a cell corner */
    fm_vec3_t org4 = {{ 0.0f, 8.0f, 0.0f }}, dd = {{ 1, -1, 1 }};
    fm_vec3_norm(&dd, &dd);
    TEST_ASSERT_TRUE(coll_raycast(&s, org4, dd, 30, 0xFF, COLL_TYPE_ALL, &h));
    TEST_ASSERT_FLOAT_WITHIN(1e-4f, 8.0f * sqrtf(3.0f), h.distance);
}

static void test_loaded_blob_queries_like_built(void)
{
    uint32_t nv;
    uint32_t nt = core_grid_level(g_verts, &nv, g_idx, 10, 10, 1.0f, 0, 0, 0);
    const coll_mesh_t *m = build_mesh(0, nv, nt, NULL);
    size_t w;
    TEST_ASSERT_EQUAL_INT(COLL_OK, coll_mesh_write_blob(m, g_meshbuf[1], sizeof g_meshbuf[1], &w));
    const coll_mesh_t *l;
    TEST_ASSERT_EQUAL_INT(COLL_OK, coll_mesh_load(g_meshbuf[1], w, &l));
    coll_scene_t s;
    coll_scene_init(&s);
    coll_mesh_instance_t a, b;
    place(&a, m, 0, 0, 0, 1, 1);
    place(&b, l, 0, 0, 0, 2, 2);
    coll_scene_add_mesh(&s, &a);
    coll_scene_add_mesh(&s, &b);
    core_rng_t r;
    core_rng_seed(&r, 9);
    for (int i = 0; i < 200; i++) {
        fm_vec3_t o = {{ (float)core_rng_range(&r, 0, 10), 5, (float)core_rng_range(&r, 0, 10) }};
        fm_vec3_t d = {{ (float)core_rng_range(&r, -1, 1), -1, (float)core_rng_range(&r, -1, 1) }};
        fm_vec3_norm(&d, &d);
        coll_ray_hit_t h1, h2;
        bool g1 = coll_raycast(&s, o, d, 20, 1, COLL_TYPE_ALL, &h1), g2 = coll_raycast(&s, o, d, 20, 2, COLL_TYPE_ALL, &h2);
        TEST_ASSERT_EQUAL(g1, g2);
        if (g1) {
            TEST_ASSERT_EQUAL_FLOAT(h1.distance, h2.distance);
            TEST_ASSERT_EQUAL_INT32(h1.triangle, h2.triangle);
        }
    }
}

/* The scene's triangle sweeps go through the installed method. */
static int g_method_calls;
static bool counting_method(void *ctx, const fm_vec3_t seg[2], float r, const fm_vec3_t *disp, const fm_vec3_t tri[3],
                            float t_max, coll_prim_hit_t *hit)
{
    (void)ctx;
    g_method_calls++;
    return coll_capsule_triangle_sweep(seg, r, disp, tri, t_max, hit);
}

static void test_sweep_uses_installed_method(void)
{
    coll_scene_t s;
    coll_scene_init(&s);
    coll_mesh_instance_t a;
    place(&a, floor_mesh(0, 5, 0), 0, 0, 0, 1, 1);
    coll_scene_add_mesh(&s, &a);
    fm_vec3_t c = {{ 0.2f, 2, 0.1f }}, disp = {{ 0, -3, 0 }};
    coll_sweep_hit_t h;
    g_method_calls = 0;
    coll_set_tri_sweep_method(counting_method, NULL);
    TEST_ASSERT_TRUE(coll_capsule_sweep(&s, c, UP, 0.5f, 0.5f, disp, 0xFF, COLL_TYPE_ALL, &h));
    coll_set_tri_sweep_method(NULL, NULL);
    TEST_ASSERT_TRUE(g_method_calls > 0);
    TEST_ASSERT_FLOAT_WITHIN(1e-4f, 1.0f / 3.0f, h.t); /* bottom at 1.0, floor at 0, 3 m travel */
}

/* The grid keeps the work per query small: character-sized sweeps over a 10k-triangle
 * level call the triangle sweep a handful of times, not 10,000 (counted, not timed). */
static void test_sweeps_test_few_triangles_on_a_big_level(void)
{
    uint32_t nv;
    uint32_t nt = core_grid_level(g_verts, &nv, g_idx, 100, 50, 1.5f, -75, 0, -37);
    TEST_ASSERT_EQUAL_UINT32(10000, nt);
    const coll_mesh_t *m = build_mesh(0, nv, nt, NULL);
    coll_scene_t s;
    coll_scene_init(&s);
    coll_mesh_instance_t a;
    place(&a, m, 0, 0, 0, 1, 1);
    coll_scene_add_mesh(&s, &a);
    core_rng_t r;
    core_rng_seed(&r, 3);
    coll_set_tri_sweep_method(counting_method, NULL);
    int total = 0, worst = 0, hits = 0;
    const int N = 1000;
    for (int i = 0; i < N; i++) {
        fm_vec3_t c = {{ (float)core_rng_range(&r, -70, 70), (float)core_rng_range(&r, 1.0, 1.6),
                         (float)core_rng_range(&r, -33, 33) }};
        fm_vec3_t d = {{ (float)core_rng_range(&r, -0.3, 0.3), (float)core_rng_range(&r, -0.6, 0.0),
                         (float)core_rng_range(&r, -0.3, 0.3) }};
        coll_sweep_hit_t h;
        g_method_calls = 0;
        hits += coll_capsule_sweep(&s, c, UP, 0.3f, 0.6f, d, 0xFF, COLL_TYPE_ALL, &h);
        total += g_method_calls;
        if (g_method_calls > worst) worst = g_method_calls;
    }
    coll_set_tri_sweep_method(NULL, NULL);
    printf("10k-triangle level, %d character sweeps (%d hits): %.1f triangle sweeps per query on average, "
           "%d at most\n", N, hits, (double)total / N, worst);
    TEST_ASSERT_TRUE(hits > N / 10);
    TEST_ASSERT_TRUE(total < 30 * N);
    TEST_ASSERT_TRUE(worst < 100);
}

static void probe_bodies(void)
{
    coll_body_t b;
    coll_transform_t idt = COLL_TRANSFORM_IDENTITY;
    memset(&b, 0, sizeof b);
    b.shape = COLL_SHAPE_SPHERE;
    b.half_extents.x = 1;
    b.xf = idt;
    fm_vec3_t o = {{ 0, 5, 0 }}, rel = {{ 0, -5, 0 }};
    coll_prim_hit_t ph;
    fm_vec3_t zero = {{ 0, 0, 0 }};
    g_bodies_supported = coll_ray_body(&zero, &DOWN, &b, &rel, 10, &ph);
    (void)o;
    if (!g_bodies_supported) printf("NOTE: collider-body primitives not implemented yet; random tests use meshes only\n");
}

/* Runs after the randomized agreement tests: both grid layouts (dense and hashed) were
 * among the meshes they compared against the double reference. */
/* The step gather (gather.h) against a reference built from the walk's own per-triangle
 * pieces (local_box, tri_rel_of, tri_abs, tri_box_reject): over random worlds (rotated,
 * scaled and mirrored instances, quantized meshes, dense and hashed grids, far from the
 * origin) and random boxes it keeps only triangles that pass the local and the
 * query-relative box tests, each once, with its placement, shape and box bit for bit, and
 * never leaves out one with a vertex inside both boxes. */
static void test_gather_keeps_the_triangles_meeting_its_box(void)
{
    core_rng_t r;
    core_rng_seed(&r, 4242);
    static coll_gather_t g;
    int checked = 0, kept = 0, n_inside = 0;
    for (int wi = 0; wi < N_WORLDS; wi++) {
        random_world(&r, false);
        for (int q = 0; q < 20; q++) {
            fm_vec3_t c = to_f(core_rng_u32(&r) % 2 ? random_surface_point(&r) : random_point_in_region(&r, 2.0));
            fm_vec3_t lo, hi;
            for (int a = 0; a < 3; a++) {
                double e = core_rng_range(&r, 0.05, 4.0);
                lo.v[a] = (float)(c.v[a] - e);
                hi.v[a] = (float)(c.v[a] + core_rng_range(&r, 0.05, 4.0));
            }
            uint8_t mask = core_rng_u32(&r) % 3 ? 0xFF : 2;
            ASSERT_NO_ALLOC(coll_gather_begin(&g, &g_w.scene, lo, hi, mask, COLL_TYPE_MESH));
            if (!g.valid) continue; /* overflowed: every query goes to the scene */
            checked++;
            /* a gather that shrank its box (gather_shrink) filtered its kept triangles by the
             * query-relative test only: they met the larger local box */
            bool shrunk = false;
            for (int a = 0; a < 3; a++) shrunk = shrunk || g.hi.v[a] != 0.5f * (hi.v[a] - lo.v[a]);
            for (uint16_t k = 0; k < g.ntris; k++)
                for (uint16_t j = (uint16_t)(k + 1); j < g.ntris; j++)
                    TEST_ASSERT_FALSE(g.tris[k].inst == g.tris[j].inst && g.tris[k].tri == g.tris[j].tri);
            for (uint16_t i = 0; i < g_w.scene.mesh_count; i++) {
                const coll_mesh_instance_t *in = g_w.scene.meshes[i];
                xf3_t x;
                memset(&x, 0, sizeof x);
                TEST_ASSERT_TRUE(xf_prepare(&in->xf, &x));
                fm_vec3_t o_l = to_local_point(&x, &in->xf, in->mesh, &g.origin), llo, lhi;
                local_box(in->mesh, &x, &o_l, &g.lo, &g.hi, &llo, &lhi);
                for (uint32_t t = 0; t < coll_mesh_triangle_count(in->mesh); t++) {
                    fm_vec3_t v[3], w0, shape[3], tri[3];
                    coll_mesh_triangle(in->mesh, t, v);
                    tri_rel_of(v, &x, &o_l, &w0, shape);
                    tri_abs(&w0, shape, tri);
                    int found = -1;
                    for (uint16_t k = 0; k < g.ntris; k++)
                        if (g.tris[k].inst == in && g.tris[k].tri == (int32_t)t) found = k;
                    /* the walk's two tests: the local box (with the grid margin), then the
                     * query-relative one (the cells list a triangle only where its surface
                     * meets them, so one passing both may still be left out, but not one
                     * with a vertex well inside both boxes) */
                    bool meets = (in->write_mask & mask) && (shrunk || !tri_box_reject(v, &llo, &lhi)) &&
                                 !tri_box_reject(tri, &g.lo, &g.hi);
                    bool inside = false;
                    for (int kk = 0; kk < 3; kk++) {
                        bool in_both = true;
                        for (int a = 0; a < 3; a++) {
                            double e = 1e-3 * (1.0 + fabs(v[kk].v[a]));
                            in_both = in_both && v[kk].v[a] > llo.v[a] + e && v[kk].v[a] < lhi.v[a] - e &&
                                      tri[kk].v[a] > g.lo.v[a] + 1e-3 && tri[kk].v[a] < g.hi.v[a] - 1e-3;
                        }
                        inside = inside || in_both;
                    }
                    if (found < 0) {
                        TEST_ASSERT_FALSE_MESSAGE(meets && inside, "a triangle inside the gathered box is missing");
                        continue;
                    }
                    TEST_ASSERT_TRUE_MESSAGE(meets, "a gathered triangle fails the box tests");
                    n_inside += inside;
                    kept++;
                    const coll_gather_tri_t *gt = &g.tris[found];
                    TEST_ASSERT_EQUAL_MEMORY(&w0, &gt->w0, sizeof w0);
                    TEST_ASSERT_EQUAL_MEMORY(&shape[1], &gt->e1, sizeof w0);
                    TEST_ASSERT_EQUAL_MEMORY(&shape[2], &gt->e2, sizeof w0);
                    for (int a = 0; a < 3; a++) {
                        float mn = f_min(tri[0].v[a], f_min(tri[1].v[a], tri[2].v[a]));
                        float mx = f_max(tri[0].v[a], f_max(tri[1].v[a], tri[2].v[a]));
                        TEST_ASSERT_EQUAL_MEMORY(&mn, &gt->lo.v[a], sizeof mn);
                        TEST_ASSERT_EQUAL_MEMORY(&mx, &gt->hi.v[a], sizeof mx);
                    }
                }
            }
        }
    }
    TEST_ASSERT_TRUE(checked > N_WORLDS * 10);
    TEST_ASSERT_TRUE(kept > checked);
    TEST_ASSERT_TRUE(n_inside > checked / 2);
}

/* A gather over more triangles than it keeps shrinks its box about the same centre (down
 * to half the asked size) instead of sending every query of the step to the scene: it
 * stays valid, keeps every triangle that meets the smaller box, and a query inside it
 * answers as the scene does. A box that would need less than half still overflows. */
static void test_gather_shrinks_its_box_on_dense_triangles(void)
{
    /* 40x40 quads of 5 cm: a 0.6 m box meets ~340 triangles, a 0.3 m one ~100 */
    uint32_t nv;
    uint32_t nt = core_grid_level(g_verts, &nv, g_idx, 40, 40, 0.05f, -1, 0, -1);
    for (uint32_t i = 0; i < nv; i++) g_verts[3 * i + 1] = 0;
    coll_mesh_build_opts_t o = { 0.25f, 0 };
    const coll_mesh_t *m = build_mesh(0, nv, nt, &o);
    coll_scene_t s;
    coll_query_stats_t st;
    coll_mesh_instance_t a;
    scene_of_one_mesh(&s, &st, &a, m);
    static coll_gather_t g;
    fm_vec3_t lo = {{ -0.31f, -0.3f, -0.29f }}, hi = {{ 0.29f, 0.3f, 0.31f }};
    ASSERT_NO_ALLOC(coll_gather_begin(&g, &s, lo, hi, 0xFF, COLL_TYPE_MESH));
    TEST_ASSERT_TRUE(g.valid);
    TEST_ASSERT_EQUAL_UINT32(0, st.gather_overflows);
    for (int ax = 0; ax < 3; ax++) {
        float asked = 0.5f * (hi.v[ax] - lo.v[ax]);
        TEST_ASSERT_TRUE(g.hi.v[ax] < asked && g.hi.v[ax] >= 0.5f * asked * 0.999f);
        TEST_ASSERT_EQUAL_FLOAT(-g.hi.v[ax], g.lo.v[ax]);
    }
    TEST_ASSERT_TRUE(g.ntris > 0 && g.ntris <= COLL_GATHER_MAX);
    uint32_t meeting = 0;
    for (uint32_t t = 0; t < nt; t++) {
        fm_vec3_t v[3];
        coll_mesh_triangle(m, t, v);
        bool meets = true;
        for (int ax = 0; ax < 3; ax++) {
            float r0 = v[0].v[ax] - g.origin.v[ax], r1 = v[1].v[ax] - g.origin.v[ax], r2 = v[2].v[ax] - g.origin.v[ax];
            float mn = f_min(r0, f_min(r1, r2)), mx = f_max(r0, f_max(r1, r2));
            meets = meets && !(mx < g.lo.v[ax] || mn > g.hi.v[ax]);
        }
        int found = 0;
        for (uint16_t k = 0; k < g.ntris; k++) found += g.tris[k].tri == (int32_t)t;
        TEST_ASSERT_TRUE(found <= 1);
        if (meets) TEST_ASSERT_EQUAL_INT_MESSAGE(1, found, "a triangle meeting the shrunk box is missing");
        meeting += meets;
    }
    TEST_ASSERT_TRUE(meeting > 0);
    /* a capsule inside the shrunk box: the gathered answer is the scene's */
    static coll_contact_t out_g[256], out_s[256];
    fm_vec3_t c = {{ 0.02f, 0.05f, -0.01f }};
    uint32_t ng = coll_gather_capsule_overlaps(&g, c, UP, 0.08f, 0.0f, out_g, 256);
    uint32_t ns = coll_capsule_overlaps(&s, c, UP, 0.08f, 0.0f, 0xFF, COLL_TYPE_ALL, out_s, 256);
    TEST_ASSERT_TRUE(ns > 0);
    TEST_ASSERT_EQUAL_UINT32(ns, ng);
    /* too dense even at half the size: every query to the scene, as before */
    fm_vec3_t lo2 = {{ -0.8f, -0.8f, -0.8f }}, hi2 = {{ 0.8f, 0.8f, 0.8f }};
    coll_gather_begin(&g, &s, lo2, hi2, 0xFF, COLL_TYPE_MESH);
    TEST_ASSERT_FALSE(g.valid);
    TEST_ASSERT_EQUAL_UINT32(1, st.gather_overflows);
}

/* A triangle listed in many of the gather's cells (long slivers over a fine grid: each in
 * ~16 cells, 60 of them, so that many share a hash of the gather's dedup) is kept once, and
 * every one inside the box is kept; over the whole box and over boxes that cut them. */
static void test_gather_keeps_a_triangle_of_many_cells_once(void)
{
    const uint32_t n = 60;
    for (uint32_t i = 0; i < n; i++) {
        float z = 0.03f * (float)i, y = 0.01f * (float)(i % 7);
        const float v[9] = { -2.0f, y, z, 2.0f, y + 0.02f, z + 0.5f, -2.0f, y, z + 0.04f };
        for (int k = 0; k < 9; k++) g_verts[9 * i + (uint32_t)k] = v[k];
        for (uint32_t k = 0; k < 3; k++) g_idx[3 * i + k] = 3 * i + k;
    }
    coll_mesh_build_opts_t o = { 0.25f, 0 };
    const coll_mesh_t *m = build_mesh(0, 3 * n, n, &o);
    coll_scene_t s;
    coll_query_stats_t st;
    coll_mesh_instance_t a;
    scene_of_one_mesh(&s, &st, &a, m);
    static coll_gather_t g;
    const float boxes[3][6] = { { -2.1f, -0.1f, -0.1f, 2.1f, 0.2f, 2.4f },
                                { -0.3f, -0.1f, 0.2f, 1.7f, 0.2f, 1.1f },
                                { 0.5f, 0.0f, 0.9f, 1.5f, 0.05f, 1.6f } };
    uint32_t kept = 0;
    for (int b = 0; b < 3; b++) {
        fm_vec3_t lo = {{ boxes[b][0], boxes[b][1], boxes[b][2] }}, hi = {{ boxes[b][3], boxes[b][4], boxes[b][5] }};
        ASSERT_NO_ALLOC(coll_gather_begin(&g, &s, lo, hi, 0xFF, COLL_TYPE_MESH));
        TEST_ASSERT_TRUE(g.valid);
        for (uint32_t t = 0; t < n; t++) {
            fm_vec3_t v[3];
            coll_mesh_triangle(m, t, v);
            /* (the cells list a triangle where its surface meets them: one whose box only
             * meets the gathered box may be left out, not one with a vertex inside it) */
            bool inside = b == 0;
            for (int kk = 0; kk < 3; kk++) {
                bool in = true;
                for (int ax = 0; ax < 3; ax++)
                    in = in && v[kk].v[ax] > lo.v[ax] + 1e-3f && v[kk].v[ax] < hi.v[ax] - 1e-3f;
                inside = inside || in;
            }
            int found = 0;
            for (uint16_t k = 0; k < g.ntris; k++) found += g.tris[k].tri == (int32_t)t;
            TEST_ASSERT_TRUE_MESSAGE(found <= 1, "a triangle gathered twice");
            if (inside) TEST_ASSERT_EQUAL_INT_MESSAGE(1, found, "a triangle inside the box is missing");
            kept += (uint32_t)found;
        }
    }
    TEST_ASSERT_TRUE(kept > n); /* the whole box kept all 60, the others some */
}

/* The triangles of an n x n grid of quads over the (n + 1)^2 vertices in g_verts (row by
 * row along x), two a quad split along the same diagonal, into g_idx: their count. */
static uint32_t grid_quad_indices(int n)
{
    uint32_t nt = 0;
    for (int z = 0; z < n; z++)
        for (int x = 0; x < n; x++) {
            uint32_t a = (uint32_t)(z * (n + 1) + x), b = a + 1, c = a + (uint32_t)(n + 1), d = c + 1;
            const uint32_t q[6] = { a, c, b, b, c, d };
            for (int k = 0; k < 6; k++) g_idx[3 * nt + (uint32_t)k] = q[k];
            nt += 2;
        }
    return nt;
}

/* The crack rule's first look drops the capsule's bottom ball to two skins over the floor
 * the foot ray found (char_body_floor.c, ball_reaches_floor): a sweep that stays above that
 * plane. coll_gather_capsule_sweep_above gives the same answer as the plain gathered sweep,
 * bit for bit, without the exact tests of the triangles lying under the plane (a rolling
 * terrain's neighbours of the floor triangle, which the plane cull keeps): fewer calls of
 * the triangle sweep, counted (Jolt's terrain scene: 19.2k -> 17.0k x86 per update). */
static void test_gathered_sweep_above_a_floor_plane(void)
{
    /* a rolling terrain of 0.5 m quads (Jolt's CharacterVirtual scene's, smaller) */
    const int N = 24;
    uint32_t nv = 0;
    for (int z = 0; z <= N; z++)
        for (int x = 0; x <= N; x++) {
            float fx = -6.0f + 0.5f * (float)x, fz = -6.0f + 0.5f * (float)z;
            g_verts[3 * nv] = fx;
            g_verts[3 * nv + 1] = 0.8f * sinf(0.9f * fx) * cosf(0.7f * fz);
            g_verts[3 * nv + 2] = fz;
            nv++;
        }
    const coll_mesh_t *m = build_mesh(0, nv, grid_quad_indices(N), NULL);
    coll_scene_t s;
    coll_query_stats_t st;
    coll_mesh_instance_t inst;
    scene_of_one_mesh(&s, &st, &inst, m);
    const float r = 0.3f, step = 0.4f, skin = 0.001f;
    core_rng_t rng;
    core_rng_seed(&rng, 1411);
    static coll_gather_t g;
    int plain_calls = 0, above_calls = 0, drops = 0, met = 0;
    for (int i = 0; i < 400; i++) {
        fm_vec3_t foot = {{ (float)core_rng_range(&rng, -4.5, 4.5), 3.0f, (float)core_rng_range(&rng, -4.5, 4.5) }};
        coll_ray_hit_t fl;
        TEST_ASSERT_TRUE(coll_raycast(&s, foot, (fm_vec3_t){{ 0, -1, 0 }}, 10.0f, 0xFF, COLL_TYPE_ALL, &fl));
        float nu = fl.normal.y;
        TEST_ASSERT_TRUE(nu > 0.5f);
        /* the body standing on it: the ball from the sweep capsule's bottom ball down to two
         * skins over the floor's plane (ball_reaches_floor's length) */
        fm_vec3_t b0 = {{ fl.point.x, fl.point.y + r + step, fl.point.z }};
        fm_vec3_t rel;
        fm_vec3_sub(&rel, &b0, &fl.point);
        float len = (fm_vec3_dot(&rel, &fl.normal) - r) / nu - 2.0f * skin;
        TEST_ASSERT_TRUE(len > 0.0f);
        fm_vec3_t lo = {{ b0.x - 1.0f, b0.y - 2.0f, b0.z - 1.0f }}, hi = {{ b0.x + 1.0f, b0.y + 1.0f, b0.z + 1.0f }};
        coll_gather_begin(&g, &s, lo, hi, 0xFF, COLL_TYPE_MESH);
        TEST_ASSERT_TRUE(g.valid);
        fm_vec3_t disp = {{ 0.0f, -len, 0.0f }};
        const coll_gather_above_t above = { fl.normal, fl.point, skin * nu, false };
        coll_sweep_hit_t h1, h2;
        coll_set_tri_sweep_method(counting_method, NULL);
        g_method_calls = 0;
        bool f1 = coll_gather_capsule_sweep(&g, b0, UP, r, 0.0f, disp, &h1);
        plain_calls += g_method_calls;
        g_method_calls = 0;
        bool f2;
        ASSERT_NO_ALLOC(f2 = coll_gather_capsule_sweep_above(&g, b0, UP, r, 0.0f, disp, &above, &h2));
        above_calls += g_method_calls;
        coll_set_tri_sweep_method(NULL, NULL);
        TEST_ASSERT_EQUAL(f1, f2);
        drops++;
        if (!f1) continue;
        met++;
        assert_same_sweep_hit(&h1, &h2);
    }
    printf("ball drops over a rolling terrain: %d (%d meet something), triangle sweeps %d -> %d with the floor "
           "plane\n", drops, met, plain_calls, above_calls);
    TEST_ASSERT_TRUE(met > 0 && met < drops); /* both kinds of drop (concave spots meet a neighbour) */
    TEST_ASSERT_TRUE(above_calls * 2 < plain_calls);
}

/* Appends to g_verts/g_idx a staircase strip across z -5 .. 5: flat at y 0 from x = x0, six
 * steps (treads 0.28 m, risers 0.18 m) from x = 0, flat at y 1.08 to x = x1 (a real
 * staircase's proportions: the bench's stairs_real). */
static void add_stair_strip(uint32_t *nv, uint32_t *nt, float x0, float x1)
{
    float xs[24], ys[24];
    int np = 0;
    xs[np] = x0; ys[np++] = 0.0f;
    for (int k = 0; k < 6; k++) {
        xs[np] = 0.28f * (float)k; ys[np++] = 0.18f * (float)k;
        xs[np] = 0.28f * (float)k; ys[np++] = 0.18f * (float)(k + 1);
    }
    xs[np] = x1; ys[np++] = 1.08f;
    const uint32_t base = *nv;
    for (int i = 0; i < np; i++)
        for (int e = 0; e < 2; e++) {
            g_verts[3 * *nv] = xs[i]; g_verts[3 * *nv + 1] = ys[i]; g_verts[3 * *nv + 2] = e ? 5.0f : -5.0f;
            (*nv)++;
        }
    for (uint32_t i = 0; i + 1 < (uint32_t)np; i++) {
        uint32_t a = base + 2 * i, b = a + 1, c = a + 3, d = a + 2;
        uint32_t q[6] = { a, b, c, a, c, d };
        for (int k = 0; k < 6; k++) g_idx[3 * *nt + (uint32_t)k] = q[k];
        *nt += 2;
    }
}

/* The crack rule's roll (char_body_floor.c, ball_held and roll_above): the ball resting on
 * an edge, lifted off its contact by a fifth of the skin, rolls down the contact's tangent
 * plane. It stays above that plane by its measured clearance, so the faces behind the edge
 * (a nosing's tread and riser, a crack's top and side) lie under it: the sweep that skips
 * them (coll_gather_above_t with all, on the gather and on the scene's walk when the roll
 * leaves the gathered box) answers as the plain sweeps do, bit for bit, with fewer exact
 * triangle tests (perf19: the bench's stairs step 42 48.1k -> 31.2k console instructions). A
 * staircase (treads 0.28, risers 0.18 m) and two slabs with a 0.4 m crack, near the origin and
 * 100 m from it; balls dropped onto the nosings and crack edges, rolled a radius to two. */
static void test_roll_above_its_contact_plane_matches_plain(void)
{
    uint32_t nv = 0, nt = 0;
    /* the staircase strip, z -5 .. 5, along +x from x = 0 */
    add_stair_strip(&nv, &nt, -5.0f, 5.0f);
    /* two slabs 1 m thick at z > 10.2 and z < 9.8, x -20 .. 20 (their tops and crack sides) */
    for (int sl = 0; sl < 2; sl++) {
        float zin = sl ? 10.2f : 9.8f, zout = sl ? 30.0f : -10.0f;
        float top[4][3] = { { -20, 0, zin }, { 20, 0, zin }, { 20, 0, zout }, { -20, 0, zout } };
        float side[4][3] = { { -20, -1, zin }, { 20, -1, zin }, { 20, 0, zin }, { -20, 0, zin } };
        for (int f = 0; f < 2; f++) {
            float (*v)[3] = f ? side : top;
            uint32_t b = nv;
            for (int k = 0; k < 4; k++) {
                for (int a = 0; a < 3; a++) g_verts[3 * nv + a] = v[k][a];
                nv++;
            }
            uint32_t q[6] = { b, b + 2, b + 1, b, b + 3, b + 2 };
            if (sl == 0) { q[1] = b + 1; q[2] = b + 2; q[4] = b + 2; q[5] = b + 3; }
            for (int k = 0; k < 6; k++) g_idx[3 * nt + k] = q[k];
            nt += 2;
        }
    }
    const coll_mesh_t *m = build_mesh(0, nv, nt, NULL);
    const float skin = 0.001f;
    core_rng_t rng;
    core_rng_seed(&rng, 1919);
    static coll_gather_t g;
    typedef struct {
        fm_vec3_t b1, way;
        float r;
        coll_gather_above_t above;
        bool found;
        coll_sweep_hit_t h;
    } scene_roll_t;
    static scene_roll_t sr[600];
    int rolls = 0, met = 0, outside = 0, plain_calls = 0, above_calls = 0;
    for (int off = 0; off < 2; off++) {
        const float ox = off ? 100.0f : 0.0f, oz = off ? -70.0f : 0.0f;
        coll_scene_t s;
        coll_query_stats_t st;
        coll_mesh_instance_t inst;
        coll_scene_init(&s);
        memset(&st, 0, sizeof st);
        coll_scene_set_stats(&s, &st);
        place(&inst, m, ox, 0.0f, oz, 0xFF, 1);
        coll_scene_add_mesh(&s, &inst);
        int nscene = 0;
        for (int i = 0; i < 600; i++) {
            const float r = (float)core_rng_range(&rng, 0.2, 0.6);
            /* over a nosing (x near 0.28 k) or over the crack (z near 10) */
            fm_vec3_t b0;
            if (i & 1) {
                int k = 1 + (int)core_rng_range(&rng, 0.0, 4.99);
                b0 = (fm_vec3_t){{ 0.28f * (float)k + (float)core_rng_range(&rng, -0.05, 0.3), 2.5f,
                                   (float)core_rng_range(&rng, -4.0, 4.0) }};
            } else {
                b0 = (fm_vec3_t){{ (float)core_rng_range(&rng, -15.0, 15.0), 1.5f,
                                   10.0f + (float)core_rng_range(&rng, -0.25, 0.25) }};
            }
            b0.x += ox;
            b0.z += oz;
            coll_sweep_hit_t h1;
            if (!coll_capsule_sweep(&s, b0, UP, r, 0.0f, (fm_vec3_t){{ 0, -3, 0 }}, 0xFF, COLL_TYPE_MESH, &h1) ||
                !(h1.t > 0.0f))
                continue;
            const fm_vec3_t n = h1.normal;
            if (!(n.y > 0.02f && n.y < 0.999f)) continue; /* rests on an edge, not a face */
            /* the rule's roll: from the contact lifted by a fifth of the skin, down the tangent */
            fm_vec3_t b1 = {{ b0.x + 0.2f * skin * n.x, b0.y - 3.0f * h1.t + 0.2f * skin * n.y,
                              b0.z + 0.2f * skin * n.z }};
            fm_vec3_t tan = {{ n.x * n.y, -1.0f + n.y * n.y, n.z * n.y }};
            float tl = sqrtf(fm_vec3_dot(&tan, &tan)), roll = r * (float)core_rng_range(&rng, 1.0, 2.0);
            fm_vec3_t way = {{ tan.x / tl * roll, tan.y / tl * roll, tan.z / tl * roll }};
            /* the plane and its margin as the rule makes them */
            fm_vec3_t rp;
            fm_vec3_sub(&rp, &b1, &h1.point);
            float hs = fm_vec3_dot(&rp, &n) - r, he = hs + fm_vec3_dot(&way, &n);
            float room = (hs < he ? hs : he) - 1e-6f * (r + fabsf(way.x) + fabsf(way.y) + fabsf(way.z));
            TEST_ASSERT_TRUE(room > 0.0f);
            const coll_gather_above_t above = { n, h1.point, 0.49f * room, true };
            /* a gathered box around the ball's start: the roll stays in it or leaves it */
            float gb = (float)core_rng_range(&rng, 1.2, 3.0) * r;
            fm_vec3_t lo = {{ b1.x - gb, b1.y - gb, b1.z - gb }}, hi = {{ b1.x + gb, b1.y + gb, b1.z + gb }};
            coll_gather_begin(&g, &s, lo, hi, 0xFF, COLL_TYPE_MESH);
            TEST_ASSERT_TRUE(g.valid);
            coll_sweep_hit_t hp, hg, ha;
            coll_set_tri_sweep_method(counting_method, NULL);
            g_method_calls = 0;
            bool fp = coll_capsule_sweep(&s, b1, UP, r, 0.0f, way, 0xFF, COLL_TYPE_MESH, &hp);
            bool fg = coll_gather_capsule_sweep(&g, b1, UP, r, 0.0f, way, &hg);
            plain_calls += g_method_calls;
            g_method_calls = 0;
            uint32_t miss0 = st.gather_misses;
            bool fa;
            ASSERT_NO_ALLOC(fa = coll_gather_capsule_sweep_above(&g, b1, UP, r, 0.0f, way, &above, &ha));
            outside += st.gather_misses > miss0;
            if (nscene < 600) sr[nscene++] = (scene_roll_t){ b1, way, r, above, fp, hp };
            above_calls += 2 * g_method_calls; /* (against the two plain sweeps) */
            coll_set_tri_sweep_method(NULL, NULL);
            rolls++;
            TEST_ASSERT_EQUAL(fg, fa);
            if (!fa) continue;
            met++;
            assert_same_sweep_hit(&hg, &ha);
        }
        /* and on the scene's walk alone (a gathered box away from the ball: the roll leaves it
         * at once), against the plain scene sweeps above */
        coll_gather_begin(&g, &s, (fm_vec3_t){{ ox - 60.0f, 0.0f, oz }}, (fm_vec3_t){{ ox - 59.0f, 1.0f, oz + 1.0f }},
                          0xFF, COLL_TYPE_MESH);
        for (int i = 0; i < nscene; i++) {
            coll_sweep_hit_t ha;
            const scene_roll_t *q = &sr[i];
            bool fa;
            ASSERT_NO_ALLOC(fa = coll_gather_capsule_sweep_above(&g, q->b1, UP, q->r, 0.0f, q->way, &q->above, &ha));
            TEST_ASSERT_EQUAL(q->found, fa);
            if (!fa) continue;
            TEST_ASSERT_EQUAL_MEMORY(&q->h.t, &ha.t, sizeof ha.t);
            TEST_ASSERT_EQUAL_MEMORY(&q->h.normal, &ha.normal, sizeof ha.normal);
            TEST_ASSERT_EQUAL_MEMORY(&q->h.point, &ha.point, sizeof ha.point);
            TEST_ASSERT_EQUAL_INT32(q->h.triangle, ha.triangle);
        }
    }
    printf("crack rule rolls along a contact's tangent plane: %d (%d meet something, %d leave the gathered box), "
           "triangle sweeps %d -> %d with the plane\n", rolls, met, outside, plain_calls, above_calls);
    TEST_ASSERT_TRUE(rolls > 300 && met > 0 && met < rolls && outside > 0 && outside < rolls);
    TEST_ASSERT_TRUE(above_calls * 4 < plain_calls * 3);
}

/* The recovery's overlap query remembers the gathered triangles it found clear of the
 * capsule (coll_gather_capsule_overlaps_m: closest pair no overlap, or a separating axis);
 * the slide's first sweep from the same place, once it holds a hit at t = 0, skips them
 * (coll_gather_capsule_sweep_m): their test over t_max = 0 would compute the same pair and
 * find nothing (perf16; the V-corner course, a capsule wedged into two walls, tested 4 wall
 * triangles twice a step). The same answer bit for bit as the plain gathered sweep and the
 * scene's, for capsules touching two walls of a V (each within 2e-4 r inside to 4e-3 r
 * outside of touching), swept into, along and away from them; fewer triangle sweeps. */
static void test_gathered_sweep_memo_matches_plain(void)
{
    /* two walls 3 m high meeting at x = z = 0 at 60 degrees (the bench's V-corner), a floor */
    const float ca = 0.8660254f, sa = 0.5f, L = 2.5f, H = 3.0f;
    const fm_vec3_t da = {{ -sa, 0.0f, -ca }}, db = {{ sa, 0.0f, -ca }}; /* along each wall, away from the corner */
    uint32_t nv = 0, nt = 0;
    const fm_vec3_t dirs[2] = { da, db };
    for (int w = 0; w < 2; w++) {
        float ex = dirs[w].x * L, ez = dirs[w].z * L;
        float v[4][3] = { { 0, 0, 0 }, { ex, 0, ez }, { ex, H, ez }, { 0, H, 0 } };
        for (int k = 0; k < 4; k++)
            for (int j = 0; j < 3; j++) g_verts[3 * (nv + (uint32_t)k) + (uint32_t)j] = v[k][j];
        uint32_t q[6] = { nv, nv + 1, nv + 2, nv, nv + 2, nv + 3 };
        if (w == 1) { q[1] = nv + 2; q[2] = nv + 1; q[4] = nv + 3; q[5] = nv + 2; }
        for (int k = 0; k < 6; k++) g_idx[3 * nt + (uint32_t)k] = q[k];
        nv += 4;
        nt += 2;
    }
    float fv[4][3] = { { -3, 0, 1 }, { 3, 0, 1 }, { 3, 0, -3 }, { -3, 0, -3 } };
    for (int k = 0; k < 4; k++)
        for (int j = 0; j < 3; j++) g_verts[3 * (nv + (uint32_t)k) + (uint32_t)j] = fv[k][j];
    uint32_t fq[6] = { nv, nv + 2, nv + 1, nv, nv + 3, nv + 2 };
    for (int k = 0; k < 6; k++) g_idx[3 * nt + (uint32_t)k] = fq[k];
    nv += 4;
    nt += 2;
    const coll_mesh_t *m = build_mesh(0, nv, nt, NULL);
    coll_scene_t s;
    coll_query_stats_t st;
    coll_mesh_instance_t inst;
    scene_of_one_mesh(&s, &st, &inst, m);
    /* the walls' inward normals (across up) */
    const fm_vec3_t na = {{ ca, 0.0f, -sa }}, nb = {{ -ca, 0.0f, -sa }};
    core_rng_t rng;
    core_rng_seed(&rng, 1616);
    static coll_gather_t g;
    const float r = 0.5f, ihh = 0.375f;
    int cases = 0, held0 = 0, calls_plain = 0, calls_memo = 0;
    for (int i = 0; i < 3000; i++) {
        /* distances to the two walls' planes */
        float dA = r * (float)core_rng_range(&rng, 0.9996, 1.001), dB = r * (float)core_rng_range(&rng, 0.9996, 1.001);
        if (core_rng_range(&rng, 0, 1) < 0.3) dB = r * (float)core_rng_range(&rng, 1.0, 1.3);
        /* the point at those distances: na.p = dA, nb.p = dB (p across up) */
        float det = na.x * nb.z - na.z * nb.x;
        float px = (dA * nb.z - dB * na.z) / det, pz = (na.x * dB - nb.x * dA) / det;
        fm_vec3_t c = {{ px, (float)core_rng_range(&rng, 0.9, 1.3), pz }};
        /* into the corner, along a wall, away, or anywhere, 0.02-0.3 m */
        int kind = i % 4;
        fm_vec3_t d;
        if (kind == 0) d = (fm_vec3_t){{ (float)core_rng_range(&rng, -0.2, 0.2), 0.0f, 1.0f }};
        else if (kind == 1) d = (i & 4) ? da : db;
        else if (kind == 2) d = (fm_vec3_t){{ (float)core_rng_range(&rng, -1, 1), 0.0f, -1.0f }};
        else d = (fm_vec3_t){{ (float)core_rng_range(&rng, -1, 1), (float)core_rng_range(&rng, -0.3, 0.3),
                               (float)core_rng_range(&rng, -1, 1) }};
        fm_vec3_scale(&d, &d, (float)core_rng_range(&rng, 0.02, 0.3) / fm_vec3_len(&d));
        fm_vec3_t lo = {{ c.x - 1.5f, c.y - 1.5f, c.z - 1.5f }}, hi = {{ c.x + 1.5f, c.y + 1.5f, c.z + 1.5f }};
        coll_gather_begin(&g, &s, lo, hi, 0xFF, COLL_TYPE_MESH);
        TEST_ASSERT_TRUE(g.valid);
        coll_contact_t ct[8];
        coll_gather_memo_t memo;
        memo.g = NULL;
        (void)coll_gather_capsule_overlaps_m(&g, c, UP, r, ihh, ct, 8, &memo);
        /* every third sweep from a place a little deeper into the walls than the overlap
         * query looked: the memo is not this capsule's */
        if (i % 3 == 2) {
            c.x -= 2e-4f * (na.x + nb.x);
            c.z -= 2e-4f * (na.z + nb.z);
        }
        coll_sweep_hit_t h0, h1, h2;
        bool f0 = coll_capsule_sweep(&s, c, UP, r, ihh, d, 0xFF, COLL_TYPE_MESH, &h0);
        bool f1 = coll_gather_capsule_sweep(&g, c, UP, r, ihh, d, &h1);
        bool f2;
        ASSERT_NO_ALLOC(f2 = coll_gather_capsule_sweep_m(&g, c, UP, r, ihh, d, NULL, &memo, &h2));
        TEST_ASSERT_EQUAL(f1, f2);
        TEST_ASSERT_EQUAL(f0, f2);
        cases++;
        if (f1) {
            assert_same_sweep_hit(&h1, &h2);
            TEST_ASSERT_EQUAL_MEMORY(&h1.depth, &h2.depth, sizeof h1.depth);
            TEST_ASSERT_EQUAL_INT32(h0.triangle, h2.triangle);
            TEST_ASSERT_EQUAL_FLOAT(h0.t, h2.t);
            if (h1.t == 0.0f) held0++;
        }
        /* the triangle sweeps made, plain and with the memo */
        coll_set_tri_sweep_method(counting_method, NULL);
        g_method_calls = 0;
        (void)coll_gather_capsule_sweep(&g, c, UP, r, ihh, d, &h1);
        calls_plain += g_method_calls;
        g_method_calls = 0;
        (void)coll_gather_capsule_sweep_m(&g, c, UP, r, ihh, d, NULL, &memo, &h2);
        calls_memo += g_method_calls;
        coll_set_tri_sweep_method(NULL, NULL);
    }
    printf("capsules in a V corner: %d sweeps (%d held at t = 0), triangle sweeps %d -> %d with the overlap's memo\n",
           cases, held0, calls_plain, calls_memo);
    TEST_ASSERT_TRUE(held0 > 100 && held0 < cases - 100);
    TEST_ASSERT_TRUE(calls_memo + 100 < calls_plain);
}

/* The stair step's down sweep (coll_gather_capsule_sweep_corner_m) takes the boundary axes
 * of the recovery's overlap at the step's start (the memo) from where the lift and the move
 * across left the capsule: a triangle that axis separates over the down sweep's motion is
 * not tested. On a staircase like stairs_real's (treads 0.28 m, risers 0.18 m, quads 10 m
 * wide split along their diagonals), capsules looked at over a tread near a nosing, lifted
 * by 0.05-0.3 m, moved across by up to 0.2 m and swept down by the lift and up to 0.1 m
 * more: the same answer bit for bit as the plain corner sweep and the scene's, fewer
 * triangle sweeps; a memo of another capsule (another inner half height) is not used. */
static void test_gathered_down_sweep_memo_matches_plain(void)
{
    uint32_t nv = 0, nt = 0;
    double xs[24], ys[24];
    int np = 0;
    xs[np] = -20; ys[np++] = 0;
    for (int k = 0; k < 10; k++) {
        xs[np] = 0.28 * k; ys[np++] = 0.18 * k;
        xs[np] = 0.28 * k; ys[np++] = 0.18 * (k + 1);
    }
    xs[np] = 20; ys[np++] = 1.8;
    for (int i = 0; i < np; i++)
        for (int e = 0; e < 2; e++) {
            g_verts[3 * nv + 0] = (float)xs[i];
            g_verts[3 * nv + 1] = (float)ys[i];
            g_verts[3 * nv + 2] = e ? 5.0f : -5.0f;
            nv++;
        }
    for (int i = 0; i + 1 < np; i++) {
        uint32_t a = 2u * (uint32_t)i, b = a + 1, c = a + 3, d = a + 2; /* as the bench's strip */
        uint32_t q[6] = { a, b, c, a, c, d };
        for (int k = 0; k < 6; k++) g_idx[3 * nt + (uint32_t)k] = q[k];
        nt += 2;
    }
    const coll_mesh_t *m = build_mesh(0, nv, nt, NULL);
    coll_scene_t s;
    coll_query_stats_t st;
    coll_mesh_instance_t inst;
    scene_of_one_mesh(&s, &st, &inst, m);
    core_rng_t rng;
    core_rng_seed(&rng, 3434);
    static coll_gather_t g;
    const float r = 0.5f, ihh = 0.375f;
    int cases = 0, hits = 0, calls_plain = 0, calls_memo = 0;
    for (int i = 0; i < 3000; i++) {
        int k = 1 + (int)core_rng_range(&rng, 0, 7.99);
        /* the bottom ball over tread k - 1, from 0.2 m behind the nosing of riser k to 0.1 m past it */
        float xn = 0.28f * (float)k, yt = 0.18f * (float)k;
        fm_vec3_t c0 = {{ xn + (float)core_rng_range(&rng, -0.2, 0.1), 0.0f, (float)core_rng_range(&rng, -0.3, 0.3) }};
        c0.y = yt + r + ihh + (float)core_rng_range(&rng, 0.0, 0.05);
        if (c0.x > xn) c0.y += 0.18f;
        float lift = (float)core_rng_range(&rng, 0.05, 0.3);
        fm_vec3_t c1 = {{ c0.x + (float)core_rng_range(&rng, 0.0, 0.2), c0.y + lift,
                          c0.z + (float)core_rng_range(&rng, -0.05, 0.05) }};
        fm_vec3_t d = {{ 0.0f, -(lift + (float)core_rng_range(&rng, 0.0, 0.1)), 0.0f }};
        fm_vec3_t lo = {{ c0.x - 1.5f, c0.y - 1.5f, c0.z - 1.5f }}, hi = {{ c1.x + 1.5f, c1.y + 1.5f, c1.z + 1.5f }};
        coll_gather_begin(&g, &s, lo, hi, 0xFF, COLL_TYPE_MESH);
        TEST_ASSERT_TRUE(g.valid);
        coll_contact_t ct[8];
        coll_gather_memo_t memo;
        memo.g = NULL;
        /* every fifth: the memo is of a capsule of another shape (not used) */
        (void)coll_gather_capsule_overlaps_m(&g, c0, UP, r, i % 5 == 4 ? ihh * 0.5f : ihh, ct, 8, &memo);
        coll_sweep_hit_t h0, h1, h2;
        bool f0 = coll_capsule_sweep(&s, c1, UP, r, ihh, d, 0xFF, COLL_TYPE_MESH, &h0);
        bool f1 = coll_gather_capsule_sweep_corner(&g, c1, UP, r, ihh, d, &h1);
        bool f2;
        ASSERT_NO_ALLOC(f2 = coll_gather_capsule_sweep_corner_m(&g, c1, UP, r, ihh, d, &memo, &h2));
        TEST_ASSERT_EQUAL(f1, f2);
        TEST_ASSERT_EQUAL(f0, f2);
        cases++;
        if (f1) {
            hits++;
            assert_same_sweep_hit(&h1, &h2);
            TEST_ASSERT_EQUAL_MEMORY(&h1.depth, &h2.depth, sizeof h1.depth);
            TEST_ASSERT_EQUAL_INT32(h0.triangle, h2.triangle);
            TEST_ASSERT_EQUAL_FLOAT(h0.t, h2.t);
        }
        coll_set_tri_sweep_method(counting_method, NULL);
        g_method_calls = 0;
        (void)coll_gather_capsule_sweep_corner(&g, c1, UP, r, ihh, d, &h1);
        int plain = g_method_calls;
        g_method_calls = 0;
        (void)coll_gather_capsule_sweep_corner_m(&g, c1, UP, r, ihh, d, &memo, &h2);
        coll_set_tri_sweep_method(NULL, NULL);
        if (i % 5 == 4) TEST_ASSERT_EQUAL_INT(plain, g_method_calls);
        calls_plain += plain;
        calls_memo += g_method_calls;
    }
    printf("down sweeps on stairs: %d (%d hits), triangle sweeps %d -> %d with the start's memo\n", cases, hits,
           calls_plain, calls_memo);
    TEST_ASSERT_TRUE(hits > 1000);
    TEST_ASSERT_TRUE(calls_memo + 500 < calls_plain);
}

/* The gathered ray, down a floor of quads (two triangles each, 0.5 m, tilted a little in
 * half the cases), through the vertices, along the shared edges and anywhere, with the
 * triangles' preps made or not by an earlier sweep: the hit of the plain loop over the
 * gathered triangles (coll_ray_triangle on each, in order, kept when nearer than the one
 * held) bit for bit. On an edge two triangles share the ray meets both at the same
 * distance: the first is the hit (the gathered ray no longer tests the second past its
 * edge test: a hit is taken only nearer). */
static void test_gathered_ray_down_shared_edges(void)
{
    const int n = 8;
    const float q = 0.5f;
    core_rng_t rng;
    core_rng_seed(&rng, 2222);
    static coll_gather_t g;
    int rays = 0, hits = 0, ties = 0;
    for (int tilt = 0; tilt < 2; tilt++) {
        uint32_t nv = 0;
        for (int z = 0; z <= n; z++)
            for (int x = 0; x <= n; x++) {
                float *v = &g_verts[3 * nv++];
                v[0] = (float)x * q;
                v[1] = tilt ? 0.03f * (float)x + 0.011f * (float)z : 0.0f;
                v[2] = (float)z * q;
            }
        const coll_mesh_t *m = build_mesh(0, nv, grid_quad_indices(n), NULL);
        coll_scene_t s;
        coll_query_stats_t st;
        coll_mesh_instance_t inst;
        scene_of_one_mesh(&s, &st, &inst, m);
        const fm_vec3_t down = {{ 0.0f, -1.0f, 0.0f }};
        for (int i = 0; i < 1500; i++) {
            int kind = i % 3;
            float x = (float)core_rng_range(&rng, 0.6, 3.4), z = (float)core_rng_range(&rng, 0.6, 3.4);
            if (kind == 0) { x = q * (float)(1 + i % 6); z = q * (float)(1 + (i / 6) % 6); } /* a vertex */
            else if (kind == 1) { if (i & 1) x = q * (float)(1 + i % 6); else z = q * (float)(1 + i % 6); } /* an edge */
            fm_vec3_t o = {{ x, 1.0f, z }};
            fm_vec3_t lo = {{ x - 0.8f, -0.5f, z - 0.8f }}, hi = {{ x + 0.8f, 1.6f, z + 0.8f }};
            coll_gather_begin(&g, &s, lo, hi, 0xFF, COLL_TYPE_MESH);
            TEST_ASSERT_TRUE(g.valid);
            if (i & 4) { /* the preps made by a sweep first */
                coll_sweep_hit_t sh;
                const fm_vec3_t d = {{ 0.0f, -0.6f, 0.0f }};
                (void)coll_gather_capsule_sweep(&g, o, UP, 0.3f, 0.2f, d, &sh);
            }
            /* the plain loop */
            fm_vec3_t rel;
            fm_vec3_sub(&rel, &o, &g.origin);
            bool have = false;
            float best = 1.4f; /* the ray inside the gathered box: answered from it */
            int32_t tri = -1, found = 0;
            fm_vec3_t nrm = {{ 0.0f, 0.0f, 0.0f }};
            for (uint16_t k = 0; k < g.ntris; k++) {
                const coll_gather_tri_t *gt = &g.tris[k];
                fm_vec3_t w0, shape[3], oo;
                fm_vec3_sub(&w0, &gt->w0, &rel);
                shape[0] = (fm_vec3_t){{ 0.0f, 0.0f, 0.0f }};
                shape[1] = gt->e1;
                shape[2] = gt->e2;
                fm_vec3_negate(&oo, &w0);
                coll_prim_hit_t ph;
                if (coll_ray_triangle(&oo, &down, shape, best, &ph)) {
                    found++;
                    if (!have || ph.t < best) { have = true; best = ph.t; tri = gt->tri; nrm = ph.normal; }
                }
            }
            coll_ray_hit_t h;
            bool got = coll_gather_raycast(&g, o, down, 1.4f, &h);
            TEST_ASSERT_EQUAL(have, got);
            rays++;
            if (got) {
                hits++;
                if (found > 1) ties++;
                TEST_ASSERT_EQUAL_MEMORY(&best, &h.distance, sizeof best);
                TEST_ASSERT_EQUAL_MEMORY(&nrm, &h.normal, sizeof nrm);
                TEST_ASSERT_EQUAL_INT32(tri, h.triangle);
            }
        }
        TEST_ASSERT_EQUAL_UINT32(0, (uint32_t)st.gather_misses); /* every query answered from the gather */
    }
    printf("gathered rays down a quad floor: %d rays, %d hits, %d on an edge two triangles share\n", rays, hits, ties);
    TEST_ASSERT_TRUE(ties > 500);
}

/* Capsule sweeps whose swept volume passes within 0.3 % of r of a tilted floor's plane, on
 * either side of touching: the scene's sweep (its plane cull before the exact test
 * included) finds a hit exactly when the exact triangle test does on some triangle. */
static void test_sweeps_grazing_a_plane_agree_with_the_exact_test(void)
{
    core_rng_t r;
    core_rng_seed(&r, 777);
    coll_scene_t s;
    coll_scene_init(&s);
    coll_mesh_instance_t a;
    place(&a, floor_mesh(0, 4, 0), 0, 0, 0, 1, 1);
    coll_scene_add_mesh(&s, &a);
    int hits = 0, n = 0;
    for (int q = 0; q < 4000; q++) {
        random_quat(&r, &a.xf.rot);
        if (q % 3 == 0) { a.xf.rot.x = a.xf.rot.z = 0; a.xf.rot.y = (float)core_rng_range(&r, -1, 1); a.xf.rot.w = 1; }
        fm_quat_norm(&a.xf.rot, &a.xf.rot);
        for (int k = 0; k < 3; k++) a.xf.pos.v[k] = (float)core_rng_range(&r, -3, 3);
        fm_vec3_t nrm, c0, l = {{ (float)core_rng_range(&r, -2, 2), 0, (float)core_rng_range(&r, -2, 2) }};
        fm_quat_rotate_vec3(&nrm, &a.xf.rot, &UP);
        fm_quat_rotate_vec3(&c0, &a.xf.rot, &l);
        fm_vec3_add(&c0, &c0, &a.xf.pos);
        float rad = (float)core_rng_range(&r, 0.1, 0.6), hh = (float)core_rng_range(&r, 0, 0.6);
        fm_vec3_t disp = {{ (float)core_rng_range(&r, -1, 1), (float)core_rng_range(&r, -1, 1),
                            (float)core_rng_range(&r, -1, 1) }};
        if (q % 2) { /* along the plane */
            float dn = fm_vec3_dot(&disp, &nrm);
            for (int k = 0; k < 3; k++) disp.v[k] -= dn * nrm.v[k];
        }
        double u = core_rng_range(&r, -0.003, 0.003);
        float side = q % 5 == 0 ? -1.0f : 1.0f; /* below the floor too (two-sided) */
        double nu = fabs(fm_vec3_dot(&nrm, &UP)), nd = side * fm_vec3_dot(&nrm, &disp);
        double dist = rad * (1.0 + u) + hh * nu - fmin(0.0, nd);
        fm_vec3_t c;
        for (int k = 0; k < 3; k++) c.v[k] = c0.v[k] + side * (float)dist * nrm.v[k];
        if (fabs(u) * rad < 3e-4) continue; /* within the touch tolerance: either way */
        n++;
        bool want = false;
        fm_vec3_t seg[2] = { {{ 0, -hh, 0 }}, {{ 0, hh, 0 }} };
        for (uint32_t t = 0; t < 2; t++) {
            core_d3 w[3];
            core_world_tri(&a, t, w);
            fm_vec3_t tri[3];
            for (int k = 0; k < 3; k++) tri[k] = to_f(core_d3_sub(w[k], core_d3_of(c)));
            coll_prim_hit_t ph;
            want = want || coll_capsule_triangle_sweep(seg, rad, &disp, tri, 1.0f, &ph);
        }
        coll_sweep_hit_t h;
        bool got = coll_capsule_sweep(&s, c, UP, rad, hh, disp, 0xFF, COLL_TYPE_MESH, &h);
        char msg[120];
        snprintf(msg, sizeof msg, "query %d: u %.5f side %.0f got %d want %d", q, u, side, got, want);
        TEST_ASSERT_EQUAL_INT_MESSAGE(want, got, msg);
        hits += got;
    }
    TEST_ASSERT_TRUE(n > 2000);
    TEST_ASSERT_TRUE(hits > n / 4 && hits < n - n / 4);
}

/* The gathered triangles of two gathers, bit for bit and in the same order. */
static void assert_same_gather(const coll_gather_t *a, const coll_gather_t *b)
{
    TEST_ASSERT_EQUAL_INT(a->valid, b->valid);
    if (!a->valid) return;
    TEST_ASSERT_EQUAL_MEMORY(&a->origin, &b->origin, sizeof a->origin);
    TEST_ASSERT_EQUAL_MEMORY(&a->lo, &b->lo, sizeof a->lo);
    TEST_ASSERT_EQUAL_MEMORY(&a->hi, &b->hi, sizeof a->hi);
    TEST_ASSERT_EQUAL_MEMORY(&a->scale, &b->scale, sizeof a->scale);
    TEST_ASSERT_EQUAL_UINT(a->ntris, b->ntris);
    for (uint16_t k = 0; k < a->ntris; k++) {
        const coll_gather_tri_t *x = &a->tris[k], *y = &b->tris[k];
        TEST_ASSERT_TRUE(x->inst == y->inst);
        TEST_ASSERT_EQUAL_INT(x->tri, y->tri);
        TEST_ASSERT_EQUAL_MEMORY(&x->w0, &y->w0, sizeof x->w0);
        TEST_ASSERT_EQUAL_MEMORY(&x->e1, &y->e1, sizeof x->e1);
        TEST_ASSERT_EQUAL_MEMORY(&x->e2, &y->e2, sizeof x->e2);
        TEST_ASSERT_EQUAL_MEMORY(&x->lo, &y->lo, sizeof x->lo);
        TEST_ASSERT_EQUAL_MEMORY(&x->hi, &y->hi, sizeof x->hi);
    }
}

/* A gather through a cache (coll_gather_begin_cached) is the fresh gather of the same box:
 * the same triangles in the same order with the same placement, shape and box bit for bit,
 * and the same query answers, over random walks of a body-sized box through random worlds
 * (rotated, scaled, quantized, dense and hashed grids, far from the origin), with teleports,
 * an instance transform changed every frame, meshes removed and added back, the read mask
 * changed, and refills that overflow the cache. No allocation on the way. */
static void test_gather_cache_equals_fresh_gather(void)
{
    core_rng_t r;
    core_rng_seed(&r, 1414);
    static coll_gather_t gc, gf;
    static coll_gather_cache_t cache;
    uint32_t steps = 0, hits = 0, fills = 0, overflows = 0, kept = 0, moved = 0, removed = 0, masks = 0;
    for (int wi = 0; wi < N_WORLDS; wi++) {
        random_world(&r, false);
        coll_gather_cache_reset(&cache);
        fm_vec3_t c = to_f(random_surface_point(&r));
        fm_vec3_t half = {{(float)core_rng_range(&r, 0.3, 1.0), (float)core_rng_range(&r, 0.6, 1.6),
                           (float)core_rng_range(&r, 0.3, 1.0)}};
        uint8_t mask = 0xFF;
        coll_mesh_instance_t *gone = NULL;
        coll_transform_t xf0 = g_w.inst[0].xf;
        for (int st = 0; st < 60; st++) {
            uint32_t ev = core_rng_u32(&r) % 40;
            if (ev == 0) c = to_f(random_surface_point(&r)); /* teleport */
            else if (ev == 1) c = to_f(random_point_in_region(&r, 2.0));
            else
                for (int a = 0; a < 3; a++) c.v[a] += (float)core_rng_range(&r, -0.25, 0.25);
            if (ev == 2) { mask = core_rng_u32(&r) % 2 ? 0xFF : 2; masks++; }
            if (ev == 3 && !gone && g_w.scene.mesh_count > 1) {
                gone = g_w.scene.meshes[core_rng_u32(&r) % g_w.scene.mesh_count];
                TEST_ASSERT_EQUAL_INT(COLL_OK, coll_scene_remove_mesh(&g_w.scene, gone));
                removed++;
            } else if (ev == 4 && gone) {
                TEST_ASSERT_EQUAL_INT(COLL_OK, coll_scene_add_mesh(&g_w.scene, gone));
                gone = NULL;
            }
            /* instance 0 moves (a platform the game writes every frame) in half the worlds */
            if (wi % 2) {
                float ph = 0.05f * (float)st;
                g_w.inst[0].xf.pos.x = xf0.pos.x + 0.3f * sinf(ph);
                g_w.inst[0].xf.pos.y = xf0.pos.y + 0.01f * (float)(st % 3);
                if (st % 7 == 3) {
                    fm_quat_t q = g_w.inst[0].xf.rot;
                    q.x += 0.01f;
                    g_w.inst[0].xf.rot = q;
                }
                moved++;
            }
            fm_vec3_t lo, hi, flo, fhi;
            float grow = (float)core_rng_range(&r, 0.0, 1.2);
            for (int a = 0; a < 3; a++) {
                lo.v[a] = c.v[a] - half.v[a];
                hi.v[a] = c.v[a] + half.v[a];
                float ahead = (float)core_rng_range(&r, -0.5, 0.5);
                flo.v[a] = lo.v[a] - grow + (ahead < 0.0f ? ahead : 0.0f);
                fhi.v[a] = hi.v[a] + grow + (ahead > 0.0f ? ahead : 0.0f);
            }
            ASSERT_NO_ALLOC(coll_gather_begin_cached(&gc, &cache, &g_w.scene, lo, hi, flo, fhi, mask, COLL_TYPE_MESH));
            coll_gather_begin(&gf, &g_w.scene, lo, hi, mask, COLL_TYPE_MESH);
            assert_same_gather(&gc, &gf);
            steps++;
            kept += gc.ntris;
            /* the same answers, bit for bit (the queries fill the triangles' prep as they go) */
            fm_vec3_t down = {{0.0f, -1.0f, 0.0f}}, axis = {{0.0f, 1.0f, 0.0f}};
            fm_vec3_t disp = {{(float)core_rng_range(&r, -0.3, 0.3), (float)core_rng_range(&r, -0.3, 0.1),
                               (float)core_rng_range(&r, -0.3, 0.3)}};
            float rad = 0.5f * f_min(half.x, half.z), ihh = 0.3f * half.y;
            coll_ray_hit_t rh[2];
            coll_sweep_hit_t sh[2];
            coll_contact_t ct[2][8];
            memset(rh, 0, sizeof rh);
            memset(sh, 0, sizeof sh);
            memset(ct, 0, sizeof ct);
            coll_gather_t *gg[2] = { &gc, &gf };
            bool rb[2], sb[2];
            uint32_t nc[2];
            for (int i = 0; i < 2; i++) {
                rb[i] = coll_gather_raycast(gg[i], c, down, 0.9f * half.y, &rh[i]);
                sb[i] = coll_gather_capsule_sweep(gg[i], c, axis, rad, ihh, disp, &sh[i]);
                nc[i] = coll_gather_capsule_overlaps(gg[i], c, axis, rad, ihh, ct[i], 8);
            }
            TEST_ASSERT_EQUAL_INT(rb[0], rb[1]);
            TEST_ASSERT_EQUAL_MEMORY(&rh[0], &rh[1], sizeof rh[0]);
            TEST_ASSERT_EQUAL_INT(sb[0], sb[1]);
            TEST_ASSERT_EQUAL_MEMORY(&sh[0], &sh[1], sizeof sh[0]);
            TEST_ASSERT_EQUAL_UINT(nc[0], nc[1]);
            TEST_ASSERT_EQUAL_MEMORY(ct[0], ct[1], sizeof ct[0]);
        }
        if (gone) TEST_ASSERT_EQUAL_INT(COLL_OK, coll_scene_add_mesh(&g_w.scene, gone));
        hits += cache.hits;
        fills += cache.fills;
        overflows += cache.overflows;
    }
    printf("gather cache: %u steps, %u hits, %u refills, %u overflows, %u kept triangles; %u moved, %u removed, "
           "%u mask changes\n",
           steps, hits, fills, overflows, kept, moved, removed, masks);
    TEST_ASSERT_TRUE(hits > steps / 4);
    TEST_ASSERT_TRUE(fills > (uint32_t)N_WORLDS);
    TEST_ASSERT_TRUE(overflows > 0u);
    TEST_ASSERT_TRUE(kept > steps);
    TEST_ASSERT_TRUE(removed > 0u && masks > 0u);
}

/* The sub-cell codes (COLL_MESHF_RCODE) change nothing but the work: every ref's code is
 * the quarters of its triangle's box grown by the grid margin in its cell (X bits 0-3, Z
 * bits 4-7), and a gather on a coded mesh is bit for bit the gather on the same mesh with
 * its codes ignored (a copy with the flag cleared): the same triangles in the same order,
 * placement, shape and box, over random worlds (rotated and scaled instances take the
 * generic walk, identity ones the coded 16-bit one; far from the origin; boxes from a
 * body's size to a few metres). It fails when the walk's quarters of its box are those of
 * the first cell in every cell (no superset in the cells after it), or without the margin
 * in the codes' boxes. */
static uint64_t g_twinbuf[2][(1u << 19) / 8];

static void check_codes(const coll_mesh_t *m, uint32_t *partial)
{
    const uint8_t *codes = coll_mesh_codes(m);
    TEST_ASSERT_NOT_NULL(codes);
    const uint32_t *cells = coll_mesh_cells(m);
    float inv4 = 4.0f / m->cell_size;
    for (uint32_t z = 0; z < m->dims[2]; z++)
        for (uint32_t y = 0; y < m->dims[1]; y++)
            for (uint32_t x = 0; x < m->dims[0]; x++) {
                uint32_t ci = coll_mesh_cell_index(m, x, y, z);
                float cx = m->grid_origin[0] + (float)(int32_t)x * m->cell_size;
                float cz = m->grid_origin[2] + (float)(int32_t)z * m->cell_size;
                for (uint32_t k = cells[ci]; k < cells[ci + 1]; k++) {
                    fm_vec3_t v[3];
                    coll_mesh_triangle(m, coll_mesh_ref(m, k), v);
                    float lo[3], hi[3];
                    for (int a = 0; a < 3; a++) {
                        lo[a] = f_min(v[0].v[a], f_min(v[1].v[a], v[2].v[a])) - m->grid_margin;
                        hi[a] = f_max(v[0].v[a], f_max(v[1].v[a], v[2].v[a])) + m->grid_margin;
                    }
                    TEST_ASSERT_EQUAL_UINT(coll_mesh_ref_code(lo[0], hi[0], lo[2], hi[2], cx, cz, inv4), codes[k]);
                    *partial += codes[k] != 0xFFu;
                }
            }
}

/* A float mesh on a dense grid (so it has codes): a floor-like field of triangles over a
 * 24 x 24 m area a few metres high, walls and small clutter among them, far from the origin
 * in its own frame when off is. */
static const coll_mesh_t *coded_mesh(core_rng_t *r, int slot, double off)
{
    uint32_t nt = 60 + core_rng_u32(r) % 400, nv = 0;
    for (uint32_t t = 0; t < nt; t++) {
        int kind = (int)(core_rng_u32(r) % 3);
        double c[3] = { off + core_rng_range(r, -12, 12), off + core_rng_range(r, 0, 3), off + core_rng_range(r, -12, 12) };
        double s = kind == 2 ? 0.1 : core_rng_range(r, 0.3, 3);
        for (int k = 0; k < 3; k++)
            for (int a = 0; a < 3; a++) {
                double e = k == 0 ? 0.0 : core_rng_range(r, -1, 1) * s;
                if (kind == 0 && a == 1) e *= 0.05; /* floor */
                if (kind == 1 && a == (k == 1 ? 0 : 2)) e *= 0.02; /* upright */
                g_verts[3 * (nv + (uint32_t)k) + a] = (float)(c[a] + e);
            }
        g_idx[3 * t] = nv; g_idx[3 * t + 1] = nv + 1; g_idx[3 * t + 2] = nv + 2;
        nv += 3;
    }
    coll_mesh_build_opts_t o = { core_rng_u32(r) % 3 ? (float)core_rng_range(r, 1.0, 6.0) : 0.0f, 0u };
    return build_mesh(slot, nv, nt, &o);
}

static void test_gather_codes_change_nothing(void)
{
    core_rng_t r;
    core_rng_seed(&r, 1717);
    static coll_gather_t g, h;
    static coll_scene_t twin;
    static coll_mesh_instance_t tinst[3];
    uint32_t coded = 0, partial = 0, compared = 0, kept = 0;
    for (int wi = 0; wi < N_WORLDS; wi++) {
        memset(&g_w, 0, sizeof g_w);
        coll_scene_init(&g_w.scene);
        coll_scene_init(&twin);
        double off = core_rng_u32(&r) % 3 == 0 ? core_rng_range(&r, 1500, 2000) : 0.0;
        const coll_mesh_t *ms[2] = { coded_mesh(&r, 0, off), coded_mesh(&r, 1, 0.0) };
        for (int i = 0; i < 2; i++) {
            if (!(ms[i]->flags & COLL_MESHF_RCODE)) {
                TEST_ASSERT_TRUE((ms[i]->flags & COLL_MESHF_HASH) != 0u);
                continue;
            }
            check_codes(ms[i], &partial);
            coded++;
        }
        int ninst = 1 + (int)(core_rng_u32(&r) % 3);
        for (int i = 0; i < ninst; i++) {
            coll_mesh_instance_t *in = &g_w.inst[i];
            int slot = i == 1 ? 1 : 0;
            in->mesh = ms[slot];
            double b[3] = { 0, 0, 0 };
            random_xf(&r, &in->xf, b);
            if (core_rng_u32(&r) % 2) { /* the common instance: no rotation, unit scale */
                in->xf.rot = (fm_quat_t){{ 0, 0, 0, 1 }};
                in->xf.scale = (fm_vec3_t){{ 1, 1, 1 }};
            }
            in->write_mask = i == 2 ? 2 : 1;
            in->id = (uint16_t)(100 + i);
            TEST_ASSERT_EQUAL_INT(COLL_OK, coll_scene_add_mesh(&g_w.scene, in));
            tinst[i] = *in;
            if (ms[slot]->flags & COLL_MESHF_RCODE) { /* the twin: the same bytes, the codes ignored */
                memcpy(g_twinbuf[slot], ms[slot], ms[slot]->total_size);
                uint32_t fl = ms[slot]->flags & ~(uint32_t)COLL_MESHF_RCODE;
                memcpy((uint8_t *)g_twinbuf[slot] + offsetof(struct coll_mesh_s, flags), &fl, sizeof fl);
                tinst[i].mesh = (const coll_mesh_t *)(const void *)g_twinbuf[slot];
            }
            TEST_ASSERT_EQUAL_INT(COLL_OK, coll_scene_add_mesh(&twin, &tinst[i]));
        }
        for (int a = 0; a < 3; a++) { g_w.lo[a] = 1e300; g_w.hi[a] = -1e300; }
        for (int i = 0; i < ninst; i++)
            for (uint32_t t = 0; t < coll_mesh_triangle_count(g_w.inst[i].mesh); t++) {
                core_d3 w[3];
                core_world_tri(&g_w.inst[i], t, w);
                for (int k = 0; k < 3; k++) {
                    double v[3] = { w[k].x, w[k].y, w[k].z };
                    for (int a = 0; a < 3; a++) { g_w.lo[a] = fmin(g_w.lo[a], v[a]); g_w.hi[a] = fmax(g_w.hi[a], v[a]); }
                }
            }
        for (int q = 0; q < 40; q++) {
            fm_vec3_t c = to_f(core_rng_u32(&r) % 2 ? random_surface_point(&r) : random_point_in_region(&r, 1.0));
            fm_vec3_t lo, hi;
            double big = core_rng_u32(&r) % 3 ? 0.8 : 3.0;
            for (int a = 0; a < 3; a++) {
                lo.v[a] = (float)(c.v[a] - core_rng_range(&r, 0.2, big));
                hi.v[a] = (float)(c.v[a] + core_rng_range(&r, 0.2, big));
            }
            uint8_t mask = core_rng_u32(&r) % 4 ? 0xFF : 2;
            ASSERT_NO_ALLOC(coll_gather_begin(&g, &g_w.scene, lo, hi, mask, COLL_TYPE_MESH));
            coll_gather_begin(&h, &twin, lo, hi, mask, COLL_TYPE_MESH);
            TEST_ASSERT_EQUAL_INT(h.valid, g.valid);
            if (!g.valid) continue;
            TEST_ASSERT_EQUAL_MEMORY(&h.lo, &g.lo, sizeof g.lo);
            TEST_ASSERT_EQUAL_MEMORY(&h.hi, &g.hi, sizeof g.hi);
            TEST_ASSERT_EQUAL_UINT(h.ntris, g.ntris);
            for (uint16_t k = 0; k < g.ntris; k++) {
                const coll_gather_tri_t *x = &g.tris[k], *y = &h.tris[k];
                TEST_ASSERT_EQUAL_INT(y->inst - tinst, x->inst - g_w.inst);
                TEST_ASSERT_EQUAL_INT(y->tri, x->tri);
                TEST_ASSERT_EQUAL_MEMORY(&y->w0, &x->w0, sizeof x->w0);
                TEST_ASSERT_EQUAL_MEMORY(&y->e1, &x->e1, sizeof x->e1);
                TEST_ASSERT_EQUAL_MEMORY(&y->e2, &x->e2, sizeof x->e2);
                TEST_ASSERT_EQUAL_MEMORY(&y->lo, &x->lo, sizeof x->lo);
                TEST_ASSERT_EQUAL_MEMORY(&y->hi, &x->hi, sizeof x->hi);
            }
            compared++;
            kept += g.ntris;
        }
    }
    printf("codes: %u coded meshes, %u partial codes, %u gathers compared, %u triangles\n", coded, partial, compared,
           kept);
    TEST_ASSERT_TRUE(coded > N_WORLDS / 2);
    TEST_ASSERT_TRUE(partial > 100u * coded);
    TEST_ASSERT_TRUE(compared > N_WORLDS * 30);
    TEST_ASSERT_TRUE(kept > compared);
}

static void test_grid_kinds_covered(void)
{
    printf("grids built: %u dense, %u hashed\n", g_dense_built, g_hashed_built);
    TEST_ASSERT_TRUE(g_dense_built > 0);
    TEST_ASSERT_TRUE(g_hashed_built > 0);
}

/* A staircase strip as a level mesh has it (treads 0.28 m, risers 0.18 m, each strip two
 * triangles across z -5 .. 5: the bench's stairs_real): capsules and balls placed diagonally
 * off a nosing (the edge between a riser and the tread above it), 0.98-1.3 r from it, swept
 * up, down, forward, back, diagonally or anywhere (perf20's test). The stair step's gathered
 * sweep (coll_gather_capsule_sweep_corner) skips a triangle flat along an axis whose box
 * passed the per-axis test but lies farther than r + eps from the swept axis's box
 * (gather_corner_clear); the plain gathered sweep has no such cull. The same answer bit for
 * bit (each on a gather of its own, so that neither reads preps the other made), far fewer
 * triangle sweeps, and the scene's answer to the rounding of its frame. */
static void test_gathered_sweep_box_corners_match_plain(void)
{
    uint32_t nv = 0, nt = 0;
    add_stair_strip(&nv, &nt, -4.0f, 4.0f);
    const coll_mesh_t *m = build_mesh(0, nv, nt, NULL);
    coll_scene_t s;
    coll_query_stats_t st;
    coll_mesh_instance_t inst;
    scene_of_one_mesh(&s, &st, &inst, m);
    core_rng_t rng;
    core_rng_seed(&rng, 2025);
    static coll_gather_t g0, g1;
    int cases = 0, hits = 0, calls_plain = 0, calls_corner = 0;
    for (int i = 0; i < 4000; i++) {
        const float r = (float)core_rng_range(&rng, 0.2, 0.6);
        const float ihh = (i % 3 == 0) ? 0.0f : (float)core_rng_range(&rng, 0.1, 0.5);
        /* a nosing (k = 1 .. 5: x 0.28 (k - 1), y 0.18 k) and a direction off it, above and
         * in front of the riser below it (or behind, over the tread) */
        int k = 1 + (int)core_rng_range(&rng, 0, 4.999);
        float nx = 0.28f * (float)(k - 1), ny = 0.18f * (float)k;
        float ang = (float)core_rng_range(&rng, 0.05, 3.09);
        float dist = r * (float)core_rng_range(&rng, 0.98, 1.3);
        /* the lower end of the axis at dist from the nosing */
        fm_vec3_t c = {{ nx - cosf(ang) * dist, ny + sinf(ang) * dist + ihh, (float)core_rng_range(&rng, -1, 1) }};
        int kind = i % 6;
        fm_vec3_t d;
        if (kind == 0) d = (fm_vec3_t){{ 0, 1, 0 }};
        else if (kind == 1) d = (fm_vec3_t){{ 0, -1, 0 }};
        else if (kind == 2) d = (fm_vec3_t){{ 1, 0, 0 }};
        else if (kind == 3) d = (fm_vec3_t){{ -1, 0, 0 }};
        else if (kind == 4) d = (fm_vec3_t){{ (float)core_rng_range(&rng, -1, 1), (float)core_rng_range(&rng, -1, 1), 0 }};
        else d = (fm_vec3_t){{ (float)core_rng_range(&rng, -1, 1), (float)core_rng_range(&rng, -1, 1),
                               (float)core_rng_range(&rng, -1, 1) }};
        if (!(fm_vec3_len(&d) > 1e-3f)) continue;
        fm_vec3_scale(&d, &d, (float)core_rng_range(&rng, 0.02, 0.3) / fm_vec3_len(&d));
        fm_vec3_t lo = {{ c.x - 1.5f, c.y - 1.5f, c.z - 1.5f }}, hi = {{ c.x + 1.5f, c.y + 1.5f, c.z + 1.5f }};
        coll_gather_begin(&g0, &s, lo, hi, 0xFF, COLL_TYPE_MESH);
        coll_gather_begin(&g1, &s, lo, hi, 0xFF, COLL_TYPE_MESH);
        TEST_ASSERT_TRUE(g0.valid && g1.valid);
        coll_sweep_hit_t h0, h1, hs;
        memset(&h0, 0, sizeof h0);
        memset(&h1, 0, sizeof h1);
        bool f0 = coll_gather_capsule_sweep(&g0, c, UP, r, ihh, d, &h0);
        bool f1;
        ASSERT_NO_ALLOC(f1 = coll_gather_capsule_sweep_corner(&g1, c, UP, r, ihh, d, &h1));
        TEST_ASSERT_EQUAL(f0, f1);
        cases++;
        if (f1) {
            hits++;
            TEST_ASSERT_EQUAL_MEMORY(&h0.t, &h1.t, sizeof h0.t);
            TEST_ASSERT_EQUAL_MEMORY(&h0.depth, &h1.depth, sizeof h0.depth);
            TEST_ASSERT_EQUAL_MEMORY(&h0.point, &h1.point, sizeof h0.point);
            TEST_ASSERT_EQUAL_MEMORY(&h0.normal, &h1.normal, sizeof h0.normal);
            TEST_ASSERT_EQUAL_INT32(h0.triangle, h1.triangle);
            /* the scene's sweep (no gather): the same to its frame's rounding */
            TEST_ASSERT_TRUE(coll_capsule_sweep(&s, c, UP, r, ihh, d, 0xFF, COLL_TYPE_MESH, &hs));
            TEST_ASSERT_FLOAT_WITHIN(1e-5f, hs.t, h1.t);
        }
        coll_set_tri_sweep_method(counting_method, NULL);
        coll_gather_begin(&g0, &s, lo, hi, 0xFF, COLL_TYPE_MESH);
        coll_gather_begin(&g1, &s, lo, hi, 0xFF, COLL_TYPE_MESH);
        g_method_calls = 0;
        (void)coll_gather_capsule_sweep(&g0, c, UP, r, ihh, d, &h0);
        calls_plain += g_method_calls;
        g_method_calls = 0;
        (void)coll_gather_capsule_sweep_corner(&g1, c, UP, r, ihh, d, &h1);
        calls_corner += g_method_calls;
        coll_set_tri_sweep_method(NULL, NULL);
    }
    printf("capsules off a stair's nosing: %d sweeps (%d hits), triangle sweeps gathered %d, with the corners %d\n",
           cases, hits, calls_plain, calls_corner);
    TEST_ASSERT_TRUE(cases > 3500);
    TEST_ASSERT_TRUE(hits > cases / 5 && hits < cases - cases / 5);
    TEST_ASSERT_TRUE(calls_corner + 500 < calls_plain);
}

int main(void)
{
    probe_bodies();
    UNITY_BEGIN();
    RUN_TEST(test_masks_types_ids_and_remove);
    RUN_TEST(test_registry_errors);
    RUN_TEST(test_invalid_queries_return_false);
    RUN_TEST(test_initial_overlap_deepest_and_overlaps_list);
    RUN_TEST(test_ball_overlaps_keep_one_contact_per_copy);
    RUN_TEST(test_dedup_overflow_falls_back_exactly);
    RUN_TEST(test_gather_shrinks_its_box_on_dense_triangles);
    RUN_TEST(test_gather_keeps_a_triangle_of_many_cells_once);
    RUN_TEST(test_gather_cache_equals_fresh_gather);
    RUN_TEST(test_precision_far_from_origin);
    RUN_TEST(test_moving_platform_read_every_query);
    RUN_TEST(test_ray_along_cell_boundary);
    RUN_TEST(test_loaded_blob_queries_like_built);
    RUN_TEST(test_sweep_uses_installed_method);
    RUN_TEST(test_sweeps_test_few_triangles_on_a_big_level);
    RUN_TEST(test_random_raycasts_match_reference);
    RUN_TEST(test_random_capsule_sweeps_match_reference);
    RUN_TEST(test_gather_keeps_the_triangles_meeting_its_box);
    RUN_TEST(test_sweeps_grazing_a_plane_agree_with_the_exact_test);
    RUN_TEST(test_gathered_sweep_above_a_floor_plane);
    RUN_TEST(test_roll_above_its_contact_plane_matches_plain);
    RUN_TEST(test_gather_codes_change_nothing);
    RUN_TEST(test_gathered_sweep_memo_matches_plain);
    RUN_TEST(test_gathered_down_sweep_memo_matches_plain);
    RUN_TEST(test_gathered_ray_down_shared_edges);
    RUN_TEST(test_grid_kinds_covered);
    RUN_TEST(test_gathered_sweep_leaving_the_box);
    RUN_TEST(test_gathered_sweep_box_corners_match_plain);
    return UNITY_END();
}
