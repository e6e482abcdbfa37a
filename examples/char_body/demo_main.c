/**
 * @file demo_main.c
 * @brief Headless front-end of the char_body example (`make demo`): plays the committed
 *        replays on the test course and on the planet, prints one status line per simulated
 *        second and draws top and side views with the trajectory and capsule snapshots.
 *
 *   demo [--assets DIR] [--replays DIR] [--out DIR] [--quiet] [--trace T0 T1]
 */
#include "demo_host.h"
#include "demo_raster.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#define BG 0x101418FFu

static float trace_from = 1e9f, trace_to = -1.0f; /* --trace T0 T1: every frame in [T0, T1] */

typedef struct { fm_vec3_t foot; int state; } sample_t;
typedef struct { fm_vec3_t a, b; uint32_t rgba; } line3_t;
typedef struct { fm_vec3_t p; char text[REPLAY_NAME_LEN]; } label_t;

/* Everything recorded during one run, drawn afterwards. */
typedef struct {
    sample_t *samples;
    int nsamples, cap_samples;
    line3_t *lines;
    int nlines, cap_lines;
    label_t labels[REPLAY_MAX_MARKS];
    int nlabels;
} record_t;

static void *grow(void *p, int *cap, size_t elem)
{
    *cap = *cap ? *cap * 2 : 1024;
    void *q = realloc(p, (size_t)*cap * elem);
    if (!q) { fprintf(stderr, "ERROR: out of memory\n"); exit(2); }
    return q;
}

static void rec_line(void *user, fm_vec3_t a, fm_vec3_t b, uint32_t rgba)
{
    record_t *rec = user;
    if (rec->nlines == rec->cap_lines) rec->lines = grow(rec->lines, &rec->cap_lines, sizeof(line3_t));
    rec->lines[rec->nlines++] = (line3_t){a, b, rgba};
}

/* ---- projection: world -> picture (u right, v down) ---- */
typedef struct {
    int u_axis, v_axis, depth_axis; /* world axes: top view x,z (depth -y); side x,y (depth z) */
    float v_sign;                   /* +1: world v grows downwards (top view z); -1: up (side y) */
    float depth_sign;               /* larger depth*sign is nearer the viewer, drawn last */
    float umin, vref, scale;
    int ox, oy;
    uint32_t fill_alpha;            /* triangle fill opacity, 0..255 */
} view_t;

static void project(const view_t *v, fm_vec3_t p, float *x, float *y)
{
    *x = (float)v->ox + (p.v[v->u_axis] - v->umin) * v->scale;
    *y = (float)v->oy + v->v_sign * (p.v[v->v_axis] - v->vref) * v->scale;
}

typedef struct { fm_vec3_t v[3]; float depth; uint32_t fill; } tri_t;

static int cmp_tri(const void *a, const void *b)
{
    float da = ((const tri_t *)a)->depth, db = ((const tri_t *)b)->depth;
    return (da > db) - (da < db);
}

static uint32_t shade(fm_vec3_t n, float h, bool platform, bool planet, const view_t *v)
{
    /* Light from the viewer's upper left; steep faces warm, walkable ones grey-blue. */
    fm_vec3_t light = game_v3_norm(v->depth_axis == 1 ? game_v3(-0.3f, 1.0f, -0.4f) : game_v3(-0.4f, 0.5f, 1.0f));
    float lit = 0.35f + 0.65f * fabsf(game_v3_dot(n, light));
    float r = 70, g = 78, b = 92;
    if (!planet && fabsf(n.y) < 0.7071f && fabsf(n.y) > 0.05f) { r = 120; g = 84; b = 60; } /* steeper than 45 deg */
    if (platform) { r = 50; g = 90; b = 150; }
    float k = lit * (1.0f + 0.06f * h);
    if (k > 1.6f) k = 1.6f;
    uint32_t R = (uint32_t)fminf(255.0f, r * k), G = (uint32_t)fminf(255.0f, g * k), B = (uint32_t)fminf(255.0f, b * k);
    return (R << 24) | (G << 16) | (B << 8) | v->fill_alpha;
}

static int add_mesh_tris(tri_t *out, int n, const coll_mesh_instance_t *inst, const view_t *v, bool platform,
                         bool planet, float ymin)
{
    uint32_t count = coll_mesh_triangle_count(inst->mesh);
    for (uint32_t i = 0; i < count; i++) {
        fm_vec3_t t[3];
        coll_mesh_triangle(inst->mesh, i, t);
        for (int k = 0; k < 3; k++) {
            out[n].v[k] = game_instance_point(inst, t[k]);
        }
        fm_vec3_t nrm = game_v3_norm(game_v3_cross(game_v3_sub(out[n].v[1], out[n].v[0]),
                                                   game_v3_sub(out[n].v[2], out[n].v[0])));
        float d = -1e30f, h = 0.0f;
        for (int k = 0; k < 3; k++) {
            d = fmaxf(d, out[n].v[k].v[v->depth_axis] * v->depth_sign);
            h += out[n].v[k].y / 3.0f;
        }
        out[n].depth = d;
        out[n].fill = shade(nrm, h - ymin, platform, planet, v);
        n++;
    }
    return n;
}

static void draw_view(img_t *im, const view_t *v, const game_t *g, const record_t *rec, bool labels)
{
    /* Level and platforms (at their pose at t = 0), painter's order along the view axis. */
    int total = (int)coll_mesh_triangle_count(g->level.level);
    for (int i = 0; i < g->level.platform_count; i++)
        if (g->level.platforms[i].inst.mesh) total += (int)coll_mesh_triangle_count(g->level.platforms[i].inst.mesh);
    tri_t *tris = malloc((size_t)total * sizeof *tris);
    if (!tris) return;
    fm_vec3_t lo, hi;
    coll_mesh_bounds(g->level.level, &lo, &hi);
    int n = add_mesh_tris(tris, 0, &g->level_inst, v, false, g->level.has_planet, lo.y);
    for (int i = 0; i < g->level.platform_count; i++)
        if (g->level.platforms[i].inst.mesh) {
            coll_mesh_instance_t at0 = g->level.platforms[i].inst;
            at0.xf.pos = g->level.platforms[i].base_pos;
            at0.xf.rot = (fm_quat_t){{0, 0, 0, 1}};
            at0.xf.scale = g->level.platforms[i].base_scale;
            n = add_mesh_tris(tris, n, &at0, v, true, false, lo.y);
        }
    qsort(tris, (size_t)n, sizeof *tris, cmp_tri);
    for (int i = 0; i < n; i++) {
        float x[3], y[3];
        for (int k = 0; k < 3; k++) project(v, tris[i].v[k], &x[k], &y[k]);
        img_tri(im, x[0], y[0], x[1], y[1], x[2], y[2], tris[i].fill);
        for (int k = 0; k < 3; k++)
            img_line(im, x[k], y[k], x[(k + 1) % 3], y[(k + 1) % 3], 0xC8D2DC30u, 1.0f);
    }
    free(tris);

    /* Trajectory of the feet, coloured by state. */
    static const uint32_t col[3] = {[CHAR_BODY_AIRBORNE] = CHAR_BODY_COLOR_AIRBORNE,
                                    [CHAR_BODY_ON_FLOOR] = CHAR_BODY_COLOR_FLOOR, [CHAR_BODY_ON_STEEP] = CHAR_BODY_COLOR_STEEP};
    for (int pass = 0; pass < 2; pass++) /* airborne (jumps, falls) on top, a little wider */
        for (int i = 1; i < rec->nsamples; i++) {
            int st = rec->samples[i].state;
            if ((st == CHAR_BODY_AIRBORNE) != (pass == 1)) continue;
            float x0, y0, x1, y1;
            project(v, rec->samples[i - 1].foot, &x0, &y0);
            project(v, rec->samples[i].foot, &x1, &y1);
            if (fabsf(x1 - x0) + fabsf(y1 - y0) > 200.0f) continue; /* respawn jump */
            img_line(im, x0, y0, x1, y1, col[st], st == CHAR_BODY_AIRBORNE ? 2.6f : 2.0f);
        }
    /* Capsule snapshots (char_body_debug_draw lines). */
    for (int i = 0; i < rec->nlines; i++) {
        float x0, y0, x1, y1;
        project(v, rec->lines[i].a, &x0, &y0);
        project(v, rec->lines[i].b, &x1, &y1);
        img_line(im, x0, y0, x1, y1, (rec->lines[i].rgba & 0xFFFFFF00u) | 0xE0u, 1.2f);
    }
    if (labels)
        for (int i = 0; i < rec->nlabels; i++) {
            float x, y;
            project(v, rec->labels[i].p, &x, &y);
            img_text(im, (int)x + 9, (int)y - 3, rec->labels[i].text, 0xFFE890FFu, 1);
        }
}

static void legend(img_t *im, int x, int y)
{
    static const struct { uint32_t c; const char *t; } items[] = {
        {CHAR_BODY_COLOR_FLOOR, "ON FLOOR"}, {CHAR_BODY_COLOR_STEEP, "STEEP"},
        {CHAR_BODY_COLOR_AIRBORNE, "AIRBORNE"}, {0x3C64A0FFu, "PLATFORM (T=0)"},
    };
    for (unsigned i = 0; i < sizeof items / sizeof items[0]; i++) {
        img_rect(im, x, y + 2, x + 14, y + 8, items[i].c);
        x = img_text(im, x + 20, y, items[i].t, 0xD0D0D0FFu, 1) + 14;
    }
}

static bool write_views(const game_t *g, const record_t *rec, const char *out_dir, const char *name,
                        float px_per_m_top, float px_per_m_side)
{
    fm_vec3_t lo, hi;
    coll_mesh_bounds(g->level.level, &lo, &hi);
    for (int i = 0; i < rec->nsamples; i++) {
        float y = rec->samples[i].foot.y + 2.2f;
        if (y > hi.y) hi.y = y;
    }
    const int margin = 16, title = 24;
    char path[512], text[160];
    bool ok = true;

    /* Top view: x right, z down (seen from +y). */
    view_t top = { .u_axis = 0, .v_axis = 2, .depth_axis = 1, .v_sign = 1.0f, .depth_sign = 1.0f,
                   .umin = lo.x, .vref = lo.z, .scale = px_per_m_top, .ox = margin, .oy = margin + title,
                   .fill_alpha = 0xFFu };
    img_t im;
    int w = (int)((hi.x - lo.x) * top.scale) + 2 * margin, h = (int)((hi.z - lo.z) * top.scale) + 2 * margin + title + 16;
    if (!img_init(&im, w, h, BG)) return false;
    draw_view(&im, &top, g, rec, true);
    snprintf(text, sizeof text, "%s - TOP VIEW (X RIGHT, Z DOWN), %.0f S", name, (double)g->time);
    img_text(&im, margin, 8, text, 0xFFFFFFFFu, 2);
    legend(&im, margin, h - 20);
    snprintf(path, sizeof path, "%s/%s_top.png", out_dir, name);
    ok = img_write_png(&im, path) && ok;
    printf("demo: wrote %s (%dx%d)\n", path, w, h);
    img_free(&im);

    /* Side view: x right, y up (seen from +z). A long level is cut into strips stacked
     * top to bottom so it keeps a readable scale. */
    int strips = hi.x - lo.x > 60.0f ? 2 : 1;
    float strip_len = (hi.x - lo.x) / (float)strips;
    int sw = (int)(strip_len * px_per_m_side) + 2 * margin, sh = (int)((hi.y - lo.y) * px_per_m_side) + 2 * margin;
    w = sw;
    h = title + strips * sh + 20;
    if (!img_init(&im, w, h, BG)) return false;
    for (int k = 0; k < strips; k++) {
        img_t strip;
        if (!img_init(&strip, sw, sh, BG)) { img_free(&im); return false; }
        view_t side = { .u_axis = 0, .v_axis = 1, .depth_axis = 2, .v_sign = -1.0f, .depth_sign = 1.0f,
                        .umin = lo.x + (float)k * strip_len, .vref = hi.y, .scale = px_per_m_side, .ox = margin,
                        .oy = margin, .fill_alpha = g->level.has_planet ? 0xFFu : 0x50u };
        draw_view(&strip, &side, g, rec, false);
        if (strips > 1) {
            snprintf(text, sizeof text, "X %.0f .. %.0f", (double)side.umin, (double)(side.umin + strip_len));
            img_text(&strip, margin, 2, text, 0xA0A8B0FFu, 1);
        }
        for (int y = 0; y < sh; y++)
            memcpy(&im.rgb[3 * (size_t)(title + k * sh + y) * (size_t)w], &strip.rgb[3 * (size_t)y * (size_t)sw],
                   3 * (size_t)sw);
        img_free(&strip);
    }
    snprintf(text, sizeof text, "%s - SIDE VIEW (X RIGHT, Y UP)", name);
    img_text(&im, margin, 8, text, 0xFFFFFFFFu, 2);
    legend(&im, margin, h - 20);
    snprintf(path, sizeof path, "%s/%s_side.png", out_dir, name);
    ok = img_write_png(&im, path) && ok;
    printf("demo: wrote %s (%dx%d)\n", path, w, h);
    img_free(&im);
    return ok;
}

/* Plays one replay on one level; returns the number of problems found. */
static int run(const game_level_t *level, const char *replay_path, const char *out_dir, const char *name,
               float top_scale, float side_scale, float snapshot_every, bool quiet)
{
    static game_t g;
    static replay_t r;
    if (!demo_replay_load(&r, replay_path)) return 1;
    game_init(&g, level);
    record_t rec = {0};
    coll_debug_draw_t dd = { rec_line, &rec };
    char line[200];
    printf("demo: %s: %s, %u commands\n", name, replay_path, (unsigned)r.count);
    uint16_t marks_seen = 0;
    const float max_time = 600.0f;
    while (!replay_done(&r) && g.time < max_time) {
        game_input_t in;
        replay_input(&r, &g, &in, GAME_DT);
        game_step(&g, &in, GAME_DT);
        if (rec.nsamples == rec.cap_samples) rec.samples = grow(rec.samples, &rec.cap_samples, sizeof(sample_t));
        rec.samples[rec.nsamples++] = (sample_t){ char_body_foot_pos(&g.body), game_body_state(&g) };
        while (marks_seen < r.mark_count) {
            const replay_mark_t *m = &r.marks[marks_seen++];
            char_body_debug_draw(&g.body, &dd);
            if (rec.nlabels < REPLAY_MAX_MARKS) {
                rec.labels[rec.nlabels].p = m->pos;
                snprintf(rec.labels[rec.nlabels].text, REPLAY_NAME_LEN, "%s", m->name);
                rec.nlabels++;
            }
            if (!quiet)
                printf("  mark %-14s t=%6.2f pos=(%7.2f %6.2f %7.2f) state=%d floor_id=%d\n", m->name,
                       (double)m->time, (double)m->pos.x, (double)m->pos.y, (double)m->pos.z, m->state,
                       (int)m->floor_id);
        }
        if (snapshot_every > 0.0f && g.stats.frames % (uint32_t)(snapshot_every * 60.0f + 0.5f) == 0)
            char_body_debug_draw(&g.body, &dd);
        if (!quiet && (g.stats.frames % 60 == 0 || (g.time >= trace_from && g.time <= trace_to))) {
            demo_status_line(line, sizeof line, &g, &r);
            printf("%s\n", line);
        }
    }
    int problems = 0;
    printf("demo: %s: %.1f s simulated, %u frames; jumps %u (coyote %u, buffered %u, cut %u), respawns %u, "
           "gravity toggles %u, laps %u, steep %.2f s (min speed factor %.2f), timeouts %u\n",
           name, (double)g.time, (unsigned)g.stats.frames, (unsigned)g.stats.jumps, (unsigned)g.stats.coyote_jumps,
           (unsigned)g.stats.buffered_jumps, (unsigned)g.stats.jump_cuts, (unsigned)g.stats.respawns,
           (unsigned)g.stats.gravity_toggles, (unsigned)r.laps, (double)g.stats.steep_time,
           (double)g.stats.min_speed_factor, (unsigned)r.timeouts);
    for (int i = 0; i < g.level.platform_count; i++)
        printf("demo: %s: platform %d ridden %.1f s, carried %.2f m\n", name, i, (double)g.stats.ride_time[i],
               (double)g.stats.ride_distance[i]);
    printf("demo: %s: jumps off a moving platform landed on it %u, one-way platform landings %u, drops %u, "
           "bumps into non-player bodies %u frames, stair steps smoothed by the camera %u\n",
           name, (unsigned)g.stats.platform_jump_landings, (unsigned)g.stats.one_way_landings, (unsigned)g.stats.drops,
           (unsigned)g.stats.npc_bumps, (unsigned)g.stats.camera_steps);
    if (!replay_done(&r)) { printf("demo: %s: replay did not finish\n", name); problems++; }
    if (r.timeouts) { printf("demo: %s: %u command(s) timed out (first at line %u)\n", name, (unsigned)r.timeouts, (unsigned)r.timeout_line); problems++; }
    if (g.stats.respawns) { printf("demo: %s: fell out of the level\n", name); problems++; }
    if (!write_views(&g, &rec, out_dir, name, top_scale, side_scale)) { printf("demo: %s: cannot write pictures\n", name); problems++; }
    free(rec.samples);
    free(rec.lines);
    return problems;
}

int main(int argc, char **argv)
{
    const char *assets = "build/assets", *replays = "examples/char_body/replay", *out = "build/demo";
    bool quiet = false;
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--assets") && i + 1 < argc) assets = argv[++i];
        else if (!strcmp(argv[i], "--replays") && i + 1 < argc) replays = argv[++i];
        else if (!strcmp(argv[i], "--out") && i + 1 < argc) out = argv[++i];
        else if (!strcmp(argv[i], "--quiet")) quiet = true;
        else if (!strcmp(argv[i], "--trace") && i + 2 < argc) { trace_from = strtof(argv[i + 1], NULL); trace_to = strtof(argv[i + 2], NULL); i += 2; }
        else {
            fprintf(stderr, "usage: %s [--assets DIR] [--replays DIR] [--out DIR] [--quiet] [--trace T0 T1]\n", argv[0]);
            return 2;
        }
    }
    mkdir(out, 0777); /* may exist already */
    demo_assets_t a;
    if (!demo_assets_load(&a, assets)) return 1;
    game_level_t level;
    char path[512];
    int problems = 0;

    game_level_course(&level, a.course, a.platforms);
    snprintf(path, sizeof path, "%s/course.txt", replays);
    problems += run(&level, path, out, "course", 12.0f, 24.0f, 0.0f, quiet);

    game_level_planet(&level, a.planet);
    snprintf(path, sizeof path, "%s/planet.txt", replays);
    problems += run(&level, path, out, "planet", 16.0f, 16.0f, 1.5f, quiet);

    demo_assets_free(&a);
    printf("demo: %s\n", problems ? "PROBLEMS (see above)" : "ok");
    return problems ? 1 : 0;
}
