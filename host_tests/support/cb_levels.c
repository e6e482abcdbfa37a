/* Procedural test geometry for the character-body suites (see cb_levels.h). */
#include "cb_levels.h"
#include <math.h>
#include <stdio.h>
#include <string.h>

/* The console test ROM (mk/n64rom.mk) builds this with smaller limits: 8 MiB of RAM. */
#ifndef CB_GEO_MAX_V
#define CB_GEO_MAX_V 65536
#endif
#ifndef CB_GEO_MAX_T
#define CB_GEO_MAX_T 32768
#endif
#ifndef CB_ARENA_BYTES
#define CB_ARENA_BYTES (8u << 20)
#endif

static float geo_v[CB_GEO_MAX_V * 3];
static uint32_t geo_i[CB_GEO_MAX_T * 3];
static uint32_t geo_nv, geo_nt;
static bool geo_overflow;
static uint64_t arena_store[CB_ARENA_BYTES / 8];
static size_t arena_used;

cb_world_t cb_world;

void cb_geo_begin(void) { geo_nv = geo_nt = 0; geo_overflow = false; }

static uint32_t vert(fm_vec3_t p)
{
    if (geo_nv >= CB_GEO_MAX_V) return 0;
    geo_v[geo_nv * 3 + 0] = p.x;
    geo_v[geo_nv * 3 + 1] = p.y;
    geo_v[geo_nv * 3 + 2] = p.z;
    return geo_nv++;
}

void cb_geo_tri(fm_vec3_t a, fm_vec3_t b, fm_vec3_t c)
{
    if (geo_nt >= CB_GEO_MAX_T || geo_nv + 3 > CB_GEO_MAX_V) { geo_overflow = true; return; }
    uint32_t ia = vert(a), ib = vert(b), ic = vert(c);
    geo_i[geo_nt * 3 + 0] = ia;
    geo_i[geo_nt * 3 + 1] = ib;
    geo_i[geo_nt * 3 + 2] = ic;
    geo_nt++;
}

void cb_geo_quad(fm_vec3_t a, fm_vec3_t b, fm_vec3_t c, fm_vec3_t d)
{
    cb_geo_tri(a, b, c);
    cb_geo_tri(a, c, d);
}

void cb_geo_box(fm_vec3_t center, fm_vec3_t half, float yaw)
{
    fm_vec3_t p[8];
    float cy = cosf(yaw), sy = sinf(yaw);
    for (int i = 0; i < 8; i++) {
        float x = (i & 1) ? half.x : -half.x, y = (i & 2) ? half.y : -half.y, z = (i & 4) ? half.z : -half.z;
        p[i] = cb_vec(center.x + cy * x + sy * z, center.y + y, center.z - sy * x + cy * z);
    }
    cb_geo_quad(p[0], p[1], p[3], p[2]); /* -z */
    cb_geo_quad(p[4], p[6], p[7], p[5]); /* +z */
    cb_geo_quad(p[0], p[2], p[6], p[4]); /* -x */
    cb_geo_quad(p[1], p[5], p[7], p[3]); /* +x */
    cb_geo_quad(p[0], p[4], p[5], p[1]); /* -y */
    cb_geo_quad(p[2], p[3], p[7], p[6]); /* +y */
}

void cb_geo_profile(const float *xs, const float *ys, int n, float z0, float z1)
{
    for (int i = 0; i + 1 < n; i++)
        cb_geo_quad(cb_vec(xs[i], ys[i], z0), cb_vec(xs[i], ys[i], z1), cb_vec(xs[i + 1], ys[i + 1], z1),
                    cb_vec(xs[i + 1], ys[i + 1], z0));
}

void cb_geo_stairs(float tread, float riser, int steps, float z0, float z1)
{
    float xs[2 * CB_GEO_MAX_STAIRS + 2], ys[2 * CB_GEO_MAX_STAIRS + 2];
    if (steps > CB_GEO_MAX_STAIRS) steps = CB_GEO_MAX_STAIRS;
    int n = 0;
    xs[n] = -30.0f; ys[n++] = 0.0f;
    for (int k = 0; k < steps; k++) {
        xs[n] = (float)k * tread; ys[n++] = (float)k * riser;
        xs[n] = (float)k * tread; ys[n++] = (float)(k + 1) * riser;
    }
    xs[n] = 30.0f; ys[n++] = (float)steps * riser;
    cb_geo_profile(xs, ys, n, z0, z1);
}

void cb_geo_grid(float half, int n, float height)
{
    float cell = 2.0f * half / (float)n;
    for (int i = 0; i < n; i++)
        for (int j = 0; j < n; j++) {
            float x0 = -half + cell * (float)i, z0 = -half + cell * (float)j;
            cb_geo_quad(cb_vec(x0, height, z0), cb_vec(x0, height, z0 + cell), cb_vec(x0 + cell, height, z0 + cell),
                        cb_vec(x0 + cell, height, z0));
        }
}

void cb_geo_sphere(fm_vec3_t c, float r, int slices, int stacks)
{
    for (int i = 0; i < stacks; i++) {
        float t0 = 3.14159265f * (float)i / (float)stacks, t1 = 3.14159265f * (float)(i + 1) / (float)stacks;
        for (int j = 0; j < slices; j++) {
            float p0 = 6.2831853f * (float)j / (float)slices, p1 = 6.2831853f * (float)(j + 1) / (float)slices;
#define SPH(t, p) cb_vec(c.x + r * sinf(t) * cosf(p), c.y + r * cosf(t), c.z + r * sinf(t) * sinf(p))
            fm_vec3_t a = SPH(t0, p0), b = SPH(t0, p1), d = SPH(t1, p0), e = SPH(t1, p1);
#undef SPH
            if (i > 0) cb_geo_tri(a, b, e);
            if (i + 1 < stacks) cb_geo_tri(a, e, d);
        }
    }
}

const coll_mesh_t *cb_geo_end(void)
{
    if (geo_overflow) return NULL;
    size_t need = coll_mesh_build_size(geo_nv, geo_nt, NULL);
    need = (need + 7u) & ~(size_t)7u;
    if (need == 0 || arena_used + need > sizeof arena_store) return NULL;
    const coll_mesh_t *m = NULL;
    if (coll_mesh_build((uint8_t *)arena_store + arena_used, need, geo_v, geo_nv, geo_i, geo_nt, NULL, &m) != COLL_OK)
        return NULL;
    arena_used += need;
    return m;
}

void cb_world_reset(void)
{
    memset(&cb_world, 0, sizeof cb_world);
    coll_scene_init(&cb_world.scene);
    arena_used = 0;
    cb_geo_begin();
}

coll_mesh_instance_t *cb_world_add_mesh(const coll_mesh_t *mesh, coll_transform_t xf, uint16_t id)
{
    if (!mesh || cb_world.ninst >= 16) return NULL;
    coll_mesh_instance_t *in = &cb_world.inst[cb_world.ninst++];
    in->mesh = mesh;
    in->xf = xf;
    in->write_mask = 0x01;
    in->id = id;
    if (coll_scene_add_mesh(&cb_world.scene, in) != COLL_OK) return NULL;
    return in;
}

coll_mesh_instance_t *cb_world_add_geo(uint16_t id)
{
    coll_transform_t xf = COLL_TRANSFORM_IDENTITY;
    const coll_mesh_t *m = cb_geo_end();
    cb_geo_begin();
    return cb_world_add_mesh(m, xf, id);
}

coll_body_t *cb_world_add_box_body(fm_vec3_t pos, fm_vec3_t half, uint16_t id)
{
    if (cb_world.nbodies >= 4) return NULL;
    coll_body_t *b = &cb_world.bodies[cb_world.nbodies++];
    coll_transform_t xf = COLL_TRANSFORM_IDENTITY;
    b->shape = COLL_SHAPE_BOX;
    b->half_extents = half;
    b->xf = xf;
    b->xf.pos = pos;
    b->write_mask = 0x01;
    b->id = id;
    if (coll_scene_add_body(&cb_world.scene, b) != COLL_OK) return NULL;
    return b;
}

void cb_level_floor(float half)
{
    cb_geo_box(cb_vec(0.0f, -0.5f, 0.0f), cb_vec(half, 0.5f, half), 0.0f);
}

char_body_settings_t cb_foot_settings(void)
{
    char_body_settings_t s = CHAR_BODY_SETTINGS_DEFAULT;
    s.center_offset = cb_vec(0.0f, 0.5f * s.height, 0.0f);
    return s;
}

void cb_body_init(char_body_t *body, fm_vec3_t *pos, fm_vec3_t start)
{
    *pos = start;
    char_body_init(body, pos);
    char_body_settings_t s = cb_foot_settings();
    char_body_configure(body, &s);
}

bool cb_body_finite(const char_body_t *body)
{
    fm_vec3_t p = char_body_foot_pos(body), v = char_body_get_velocity(body);
    return isfinite(p.x) && isfinite(p.y) && isfinite(p.z) && isfinite(v.x) && isfinite(v.y) && isfinite(v.z);
}

void cb_report(const char *what, double value, const char *unit)
{
    printf("MEASURED %s = %.6g %s\n", what, value, unit);
}
