/**
 * @file preview_sdl.c
 * @brief Interactive SDL2 front-end of the char_body example (`make preview`): flat-shaded
 *        3D view of the baked level with a perspective camera orbiting the player, the
 *        capsule from char_body_debug_draw, keyboard and gamepad control.
 *
 *   keyboard  WASD move, arrows camera, space jump, G gravity toggle, P play/stop the
 *             replay, 1 / 2 test course / planet, Esc quit
 *   gamepad   left stick move, right stick camera, A jump, Y gravity toggle, Back replay
 *
 *   preview [--assets DIR] [--replays DIR] [--level course|planet] [--shot N --out FILE]
 *
 * --shot N plays N frames of the level's replay, saves the frame as a PNG and exits
 * (`make preview-shot` runs that under xvfb-run).
 */
#include "demo_host.h"
#include "demo_raster.h"
#include <SDL.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define WIN_W 960
#define WIN_H 720
#define NEAR_Z 0.1f

typedef struct {
    SDL_Renderer *ren;
    fm_vec3_t eye, right, upv, fwd;
    float focal;
} cam_t;

typedef struct { float x, y, z; } cpt_t; /* camera space: x right, y up, z forward */

static cpt_t to_cam(const cam_t *c, fm_vec3_t p)
{
    fm_vec3_t d = game_v3_sub(p, c->eye);
    return (cpt_t){ game_v3_dot(d, c->right), game_v3_dot(d, c->upv), game_v3_dot(d, c->fwd) };
}

static SDL_FPoint to_screen(const cam_t *c, cpt_t p)
{
    return (SDL_FPoint){ WIN_W * 0.5f + p.x / p.z * c->focal, WIN_H * 0.5f - p.y / p.z * c->focal };
}

static cpt_t cpt_lerp(cpt_t a, cpt_t b, float t)
{
    return (cpt_t){ a.x + (b.x - a.x) * t, a.y + (b.y - a.y) * t, a.z + (b.z - a.z) * t };
}

static void draw_line3(const cam_t *c, fm_vec3_t a, fm_vec3_t b, uint32_t rgba)
{
    cpt_t p = to_cam(c, a), q = to_cam(c, b);
    if (p.z < NEAR_Z && q.z < NEAR_Z) return;
    if (p.z < NEAR_Z) p = cpt_lerp(p, q, (NEAR_Z - p.z) / (q.z - p.z));
    if (q.z < NEAR_Z) q = cpt_lerp(q, p, (NEAR_Z - q.z) / (p.z - q.z));
    SDL_FPoint s = to_screen(c, p), e = to_screen(c, q);
    SDL_SetRenderDrawColor(c->ren, (Uint8)(rgba >> 24), (Uint8)(rgba >> 16), (Uint8)(rgba >> 8), (Uint8)rgba);
    SDL_RenderDrawLineF(c->ren, s.x, s.y, e.x, e.y);
}

static void dd_line(void *user, fm_vec3_t a, fm_vec3_t b, uint32_t rgba) { draw_line3(user, a, b, rgba); }

/* ---- level triangles: near-clipped, depth-sorted, flat-shaded ---- */

typedef struct { SDL_Vertex v[3]; float depth; } stri_t;
static stri_t *tris;
static int tri_cap;

static int cmp_far_first(const void *a, const void *b)
{
    float da = ((const stri_t *)a)->depth, db = ((const stri_t *)b)->depth;
    return (da < db) - (da > db);
}

static int emit(const cam_t *c, int n, const cpt_t *p, int np, SDL_Color col)
{
    for (int k = 1; k + 1 < np; k++) {
        if (n >= tri_cap) return n;
        stri_t *t = &tris[n++];
        const cpt_t *pk[3] = { &p[0], &p[k], &p[k + 1] };
        t->depth = 0.0f;
        for (int j = 0; j < 3; j++) {
            SDL_FPoint s = to_screen(c, *pk[j]);
            t->v[j] = (SDL_Vertex){ s, col, {0, 0} };
            t->depth += pk[j]->z;
        }
    }
    return n;
}

static int add_instance(const cam_t *c, int n, const coll_mesh_instance_t *inst, bool platform, bool planet)
{
    uint32_t count = coll_mesh_triangle_count(inst->mesh);
    fm_vec3_t light = game_v3_norm(game_v3(-0.4f, 1.0f, 0.3f));
    for (uint32_t i = 0; i < count; i++) {
        fm_vec3_t t[3];
        coll_mesh_triangle(inst->mesh, i, t);
        cpt_t in[3];
        for (int k = 0; k < 3; k++) {
            t[k] = game_instance_point(inst, t[k]);
            in[k] = to_cam(c, t[k]);
        }
        if (in[0].z < NEAR_Z && in[1].z < NEAR_Z && in[2].z < NEAR_Z) continue;
        fm_vec3_t nrm = game_v3_norm(game_v3_cross(game_v3_sub(t[1], t[0]), game_v3_sub(t[2], t[0])));
        /* Platforms and the planet are closed, outward-wound meshes: cull their back faces
         * (painter's sorting alone mixes a thin platform's top and bottom). */
        if ((platform || planet) && game_v3_dot(nrm, game_v3_sub(c->eye, t[0])) < 0.0f) continue;
        /* Clip against the near plane (Sutherland-Hodgman, one plane). */
        cpt_t out[4];
        int no = 0;
        for (int k = 0; k < 3; k++) {
            cpt_t a = in[k], b = in[(k + 1) % 3];
            if (a.z >= NEAR_Z) out[no++] = a;
            if ((a.z >= NEAR_Z) != (b.z >= NEAR_Z) && no < 4) out[no++] = cpt_lerp(a, b, (NEAR_Z - a.z) / (b.z - a.z));
        }
        float lit = 0.35f + 0.65f * fabsf(game_v3_dot(nrm, planet ? game_v3_norm(game_v3_add(t[0], light)) : light));
        float r = 95, g = 105, b = 120;
        if (!planet && fabsf(nrm.y) < 0.7071f && fabsf(nrm.y) > 0.05f) { r = 150; g = 105; b = 70; }
        if (platform) { r = 60; g = 110; b = 190; }
        SDL_Color col = { (Uint8)fminf(255.0f, r * lit * 1.4f), (Uint8)fminf(255.0f, g * lit * 1.4f),
                          (Uint8)fminf(255.0f, b * lit * 1.4f), 255 };
        n = emit(c, n, out, no, col);
    }
    return n;
}

static void draw_scene(cam_t *c, const game_t *g, bool show_help, const char *mode)
{
    SDL_SetRenderDrawColor(c->ren, 16, 20, 24, 255);
    SDL_RenderClear(c->ren);
    fm_vec3_t target, up;
    game_camera(g, &c->eye, &target, &up);
    c->fwd = game_v3_norm(game_v3_sub(target, c->eye));
    c->right = game_v3_norm(game_v3_cross(c->fwd, up));
    c->upv = game_v3_cross(c->right, c->fwd);
    c->focal = (WIN_H * 0.5f) / tanf(0.5f * 1.05f); /* 60 deg vertical field of view */

    /* Painter's order, level first, then the platforms over it: sorting a 3 x 3 m platform
     * against 4 x 4 m floor tiles by centroid depth would bury parts of it. */
    int nl = add_instance(c, 0, &g->level_inst, false, g->level.has_planet);
    qsort(tris, (size_t)nl, sizeof *tris, cmp_far_first);
    int n = nl;
    for (int i = 0; i < g->level.platform_count; i++)
        if (g->level.platforms[i].inst.mesh) n = add_instance(c, n, &g->level.platforms[i].inst, true, false);
    qsort(tris + nl, (size_t)(n - nl), sizeof *tris, cmp_far_first);
    for (int i = 0; i < n; i++) {
        SDL_RenderGeometry(c->ren, NULL, tris[i].v, 3, NULL, 0);
    }
    /* Light wireframe over the fills. */
    SDL_SetRenderDrawBlendMode(c->ren, SDL_BLENDMODE_BLEND);
    for (int i = 0; i < n; i++) {
        SDL_SetRenderDrawColor(c->ren, 220, 230, 240, 40);
        for (int k = 0; k < 3; k++)
            SDL_RenderDrawLineF(c->ren, tris[i].v[k].position.x, tris[i].v[k].position.y,
                                tris[i].v[(k + 1) % 3].position.x, tris[i].v[(k + 1) % 3].position.y);
    }
    SDL_SetRenderDrawBlendMode(c->ren, SDL_BLENDMODE_NONE);
    coll_debug_draw_t dd = { dd_line, c };
    char_body_debug_draw(&g->body, &dd);

    /* HUD: 5x7 font drawn as small rectangles. */
    static const char *const state[3] = {[CHAR_BODY_AIRBORNE] = "AIRBORNE", [CHAR_BODY_ON_FLOOR] = "ON FLOOR",
                                         [CHAR_BODY_ON_STEEP] = "STEEP"};
    char line[200];
    snprintf(line, sizeof line, "T %.1f  POS %.1f %.1f %.1f  %s  FLOOR ID %d  %s GRAVITY", (double)g->time,
             (double)g->pos.x, (double)g->pos.y, (double)g->pos.z, state[game_body_state(g)],
             (int)char_body_floor_id(&g->body), g->planet_gravity ? "PLANET" : "NORMAL");
    const char *lines[4] = { mode, line,
        show_help ? "WASD MOVE  ARROWS CAMERA  SPACE JUMP  G GRAVITY  P REPLAY  1 2 LEVEL  ESC" : "", "" };
    SDL_SetRenderDrawColor(c->ren, 235, 235, 200, 255);
    for (int l = 0; l < 3; l++) {
        int x = 10, y = 10 + l * 20;
        for (const char *s = lines[l]; *s; s++, x += 12) {
            const uint8_t *rows = img_font_glyph(*s);
            if (!rows) continue;
            for (int row = 0; row < 7; row++)
                for (int col = 0; col < 5; col++)
                    if (rows[row] & (0x10 >> col)) {
                        SDL_FRect rct = { (float)(x + col * 2), (float)(y + row * 2), 2.0f, 2.0f };
                        SDL_RenderFillRectF(c->ren, &rct);
                    }
        }
    }
}

/* ---- input ---- */

static float axis(SDL_GameController *pad, SDL_GameControllerAxis a)
{
    if (!pad) return 0.0f;
    float v = (float)SDL_GameControllerGetAxis(pad, a) / 32767.0f;
    return fabsf(v) < 0.2f ? 0.0f : v; /* dead zone */
}

static void read_input(SDL_GameController *pad, game_input_t *in)
{
    const Uint8 *k = SDL_GetKeyboardState(NULL);
    *in = (game_input_t){0};
    in->stick_x = (float)(k[SDL_SCANCODE_D] - k[SDL_SCANCODE_A]) + axis(pad, SDL_CONTROLLER_AXIS_LEFTX);
    in->stick_y = (float)(k[SDL_SCANCODE_W] - k[SDL_SCANCODE_S]) - axis(pad, SDL_CONTROLLER_AXIS_LEFTY);
    in->cam_x = (float)(k[SDL_SCANCODE_RIGHT] - k[SDL_SCANCODE_LEFT]) + axis(pad, SDL_CONTROLLER_AXIS_RIGHTX);
    in->cam_y = (float)(k[SDL_SCANCODE_UP] - k[SDL_SCANCODE_DOWN]) - axis(pad, SDL_CONTROLLER_AXIS_RIGHTY);
    in->jump = k[SDL_SCANCODE_SPACE] || (pad && SDL_GameControllerGetButton(pad, SDL_CONTROLLER_BUTTON_A));
    in->toggle_gravity = k[SDL_SCANCODE_G] || (pad && SDL_GameControllerGetButton(pad, SDL_CONTROLLER_BUTTON_Y));
}

/* ---- main ---- */

static game_t game;
static replay_t replay;

static bool start_level(const demo_assets_t *a, const char *replays, bool planet, bool *have_replay)
{
    game_level_t level;
    if (planet) game_level_planet(&level, a->planet);
    else game_level_course(&level, a->course, a->platforms);
    game_init(&game, &level);
    char path[512];
    snprintf(path, sizeof path, "%s/%s.txt", replays, planet ? "planet" : "course");
    *have_replay = demo_replay_load(&replay, path);
    return true;
}

int main(int argc, char **argv)
{
    const char *assets = "build/assets", *replays = "examples/char_body/replay", *out = "build/demo/preview.png";
    bool planet = false;
    long shot = -1;
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--assets") && i + 1 < argc) assets = argv[++i];
        else if (!strcmp(argv[i], "--replays") && i + 1 < argc) replays = argv[++i];
        else if (!strcmp(argv[i], "--out") && i + 1 < argc) out = argv[++i];
        else if (!strcmp(argv[i], "--shot") && i + 1 < argc) shot = strtol(argv[++i], NULL, 10);
        else if (!strcmp(argv[i], "--level") && i + 1 < argc) planet = !strcmp(argv[++i], "planet");
        else {
            fprintf(stderr, "usage: %s [--assets DIR] [--replays DIR] [--level course|planet] [--shot N --out FILE]\n", argv[0]);
            return 2;
        }
    }
    demo_assets_t a;
    if (!demo_assets_load(&a, assets)) return 1;
    tri_cap = 16384;
    tris = malloc((size_t)tri_cap * sizeof *tris);
    if (!tris) return 1;

    if (shot >= 0) SDL_SetHint(SDL_HINT_RENDER_DRIVER, "software"); /* Xvfb has no GPU */
    if (SDL_Init(SDL_INIT_VIDEO | SDL_INIT_GAMECONTROLLER) != 0) {
        fprintf(stderr, "ERROR: SDL_Init: %s\n", SDL_GetError());
        return 1;
    }
    SDL_Window *win = SDL_CreateWindow("charbody64 - char_body example", SDL_WINDOWPOS_CENTERED,
                                       SDL_WINDOWPOS_CENTERED, WIN_W, WIN_H, 0);
    SDL_Renderer *ren = win ? SDL_CreateRenderer(win, -1, shot >= 0 ? SDL_RENDERER_SOFTWARE : 0) : NULL;
    if (!ren) {
        fprintf(stderr, "ERROR: SDL window/renderer: %s\n", SDL_GetError());
        return 1;
    }
    SDL_GameController *pad = NULL;
    bool have_replay = false, playing = shot >= 0;
    start_level(&a, replays, planet, &have_replay);
    cam_t cam = { .ren = ren };
    int rc = 0;
    bool quit = false;
    Uint64 prev = SDL_GetPerformanceCounter();
    double acc = 0.0;
    long frame = 0;
    while (!quit) {
        SDL_Event e;
        while (SDL_PollEvent(&e)) {
            if (e.type == SDL_QUIT) quit = true;
            else if (e.type == SDL_CONTROLLERDEVICEADDED && !pad) pad = SDL_GameControllerOpen(e.cdevice.which);
            else if (e.type == SDL_CONTROLLERBUTTONDOWN && e.cbutton.button == SDL_CONTROLLER_BUTTON_BACK) playing = !playing && have_replay;
            else if (e.type == SDL_KEYDOWN && !e.key.repeat) {
                SDL_Keycode k = e.key.keysym.sym;
                if (k == SDLK_ESCAPE) quit = true;
                else if (k == SDLK_p) { if (!playing) start_level(&a, replays, planet, &have_replay); playing = !playing && have_replay; }
                else if (k == SDLK_1 || k == SDLK_2) { planet = k == SDLK_2; start_level(&a, replays, planet, &have_replay); playing = false; }
            }
        }
        /* Fixed 60 Hz steps; the shot mode runs as fast as it can. */
        Uint64 now = SDL_GetPerformanceCounter();
        acc += (double)(now - prev) / (double)SDL_GetPerformanceFrequency();
        prev = now;
        if (acc > 0.25) acc = 0.25;
        int steps = shot >= 0 ? 1 : 0;
        for (; shot < 0 && acc >= 1.0 / 60.0; acc -= 1.0 / 60.0) steps++;
        for (int s = 0; s < steps; s++) {
            game_input_t in;
            if (playing && !replay_done(&replay)) replay_input(&replay, &game, &in, GAME_DT);
            else read_input(pad, &in);
            game_step(&game, &in, GAME_DT);
            frame++;
        }
        if (shot >= 0 && frame < shot) continue; /* draw only the frame we keep */
        draw_scene(&cam, &game, shot < 0, playing ? "REPLAY (P TO STOP)" : "PLAYER CONTROL (P PLAYS THE REPLAY)");
        if (shot >= 0) {
            static uint8_t pixels[WIN_W * WIN_H * 3];
            if (SDL_RenderReadPixels(ren, NULL, SDL_PIXELFORMAT_RGB24, pixels, WIN_W * 3) != 0 ||
                !png_write_rgb(out, pixels, WIN_W, WIN_H, WIN_W * 3)) {
                fprintf(stderr, "ERROR: screenshot %s: %s\n", out, SDL_GetError());
                rc = 1;
            } else {
                char line[200];
                demo_status_line(line, sizeof line, &game, &replay);
                printf("preview: wrote %s after %ld frames; %s\n", out, frame, line);
            }
            break;
        }
        SDL_RenderPresent(ren);
    }
    if (pad) SDL_GameControllerClose(pad);
    SDL_DestroyRenderer(ren);
    SDL_DestroyWindow(win);
    SDL_Quit();
    free(tris);
    demo_assets_free(&a);
    return rc;
}
