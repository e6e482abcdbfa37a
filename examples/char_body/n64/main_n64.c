/**
 * @file main_n64.c
 * @brief Console front-end of the char_body example (libdragon): joypad input, the shared
 *        game logic, and a minimal software wireframe (graphics_draw_line) of the level
 *        near the player plus the char_body_debug_draw capsule.
 *
 *   stick move, C buttons camera, A jump, B gravity toggle, Z play/stop the replay,
 *   L / R test course / planet
 *
 * Levels come from the ROM filesystem (rom:/<name>.coll, baked on the PC, used in place).
 * Built by examples/char_body/n64/Makefile with libdragon's n64.mk; not built in CI.
 */
#ifndef COLL_USE_LIBDRAGON_FMATH
#define COLL_USE_LIBDRAGON_FMATH /* fm_vec3_t & co. from libdragon's fgeom.h (the Makefile sets it too) */
#endif
#include <libdragon.h>
#include <math.h>
#include <stdio.h>
#include "../game.h"
#include "../game_replay.h"

#define SCREEN_W 320
#define SCREEN_H 240
#define DRAW_RADIUS 24.0f /* meters: only level triangles this close are drawn */

static game_t game;
static replay_t replay;
static bool have_replay;
static const coll_mesh_t *course, *planet, *platforms[4];

static const coll_mesh_t *load_mesh(const char *path)
{
    int size = 0;
    void *blob = asset_load(path, &size); /* malloc'd: 8-byte aligned */
    const coll_mesh_t *mesh = NULL;
    coll_err_t err = coll_mesh_load(blob, (size_t)size, &mesh);
    assertf(err == COLL_OK, "%s: %s", path, coll_strerror(err));
    return mesh;
}

static void start_level(bool on_planet)
{
    game_level_t level;
    if (on_planet) game_level_planet(&level, planet);
    else game_level_course(&level, course, platforms);
    game_init(&game, &level);
    int size = 0;
    char *text = asset_load(on_planet ? "rom:/planet.txt" : "rom:/course.txt", &size);
    have_replay = text && replay_parse(&replay, text, (uint32_t)size);
    free(text);
}

/* ---- minimal perspective wireframe ---- */
typedef struct { fm_vec3_t eye, right, up, fwd; float focal; surface_t *fb; } view_t;

static bool project(const view_t *v, fm_vec3_t p, float *x, float *y, float *z)
{
    fm_vec3_t d = game_v3_sub(p, v->eye);
    *z = game_v3_dot(d, v->fwd);
    if (*z < 0.2f) return false;
    *x = SCREEN_W * 0.5f + game_v3_dot(d, v->right) / *z * v->focal;
    *y = SCREEN_H * 0.5f - game_v3_dot(d, v->up) / *z * v->focal;
    return true;
}

static void line3(const view_t *v, fm_vec3_t a, fm_vec3_t b, uint32_t color)
{
    float x0, y0, z0, x1, y1, z1;
    if (!project(v, a, &x0, &y0, &z0) || !project(v, b, &x1, &y1, &z1)) return;
    graphics_draw_line(v->fb, (int)x0, (int)y0, (int)x1, (int)y1, color);
}

static void dd_line(void *user, fm_vec3_t a, fm_vec3_t b, uint32_t rgba)
{
    line3(user, a, b, graphics_make_color(rgba >> 24, (rgba >> 16) & 0xFF, (rgba >> 8) & 0xFF, 0xFF));
}

static void draw_instance(const view_t *v, const coll_mesh_instance_t *inst, uint32_t color)
{
    uint32_t n = coll_mesh_triangle_count(inst->mesh);
    for (uint32_t i = 0; i < n; i++) {
        fm_vec3_t t[3];
        coll_mesh_triangle(inst->mesh, i, t);
        for (int k = 0; k < 3; k++) {
            t[k] = game_instance_point(inst, t[k]);
        }
        if (game_v3_len(game_v3_sub(t[0], game.pos)) > DRAW_RADIUS) continue;
        for (int k = 0; k < 3; k++) line3(v, t[k], t[(k + 1) % 3], color);
    }
}

int main(void)
{
    debug_init_isviewer();
    debug_init_usblog();
    display_init(RESOLUTION_320x240, DEPTH_16_BPP, 2, GAMMA_NONE, FILTERS_RESAMPLE);
    dfs_init(DFS_DEFAULT_LOCATION);
    joypad_init();

    course = load_mesh("rom:/test_course.coll");
    platforms[GAME_PLAT_TRANSLATE] = load_mesh("rom:/platform_translate.coll");
    platforms[GAME_PLAT_ROTATE] = load_mesh("rom:/platform_rotate.coll");
    platforms[GAME_PLAT_SCALE] = load_mesh("rom:/platform_scale.coll");
    platforms[GAME_PLAT_LIFT] = load_mesh("rom:/platform_lift.coll");
    planet = load_mesh("rom:/planet.coll");
    bool on_planet = false, playing = false;
    start_level(on_planet);

    for (;;) {
        joypad_poll();
        joypad_inputs_t pad = joypad_get_inputs(JOYPAD_PORT_1);
        joypad_buttons_t pressed = joypad_get_buttons_pressed(JOYPAD_PORT_1);
        if (pressed.l || pressed.r) { on_planet = pressed.r; start_level(on_planet); playing = false; }
        if (pressed.z) { if (!playing) start_level(on_planet); playing = !playing && have_replay; }

        game_input_t in = {
            .stick_x = (float)pad.stick_x / 85.0f, .stick_y = (float)pad.stick_y / 85.0f,
            .cam_x = (float)(pad.btn.c_right - pad.btn.c_left), .cam_y = (float)(pad.btn.c_up - pad.btn.c_down),
            .jump = pad.btn.a, .toggle_gravity = pad.btn.b,
        };
        if (playing && !replay_done(&replay)) replay_input(&replay, &game, &in, GAME_DT);
        game_step(&game, &in, GAME_DT);

        view_t v = { .fb = display_get(), .focal = (SCREEN_H * 0.5f) / tanf(0.5f * 1.05f) };
        fm_vec3_t target, up;
        game_camera(&game, &v.eye, &target, &up);
        v.fwd = game_v3_norm(game_v3_sub(target, v.eye));
        v.right = game_v3_norm(game_v3_cross(v.fwd, up));
        v.up = game_v3_cross(v.right, v.fwd);
        graphics_fill_screen(v.fb, graphics_make_color(16, 20, 24, 255));
        draw_instance(&v, &game.level_inst, graphics_make_color(110, 120, 140, 255));
        for (int i = 0; i < game.level.platform_count; i++)
            draw_instance(&v, &game.level.platforms[i].inst, graphics_make_color(70, 130, 220, 255));
        coll_debug_draw_t dd = { dd_line, &v };
        char_body_debug_draw(&game.body, &dd);
        char hud[96];
        snprintf(hud, sizeof hud, "t %.1f  %s  floor %d%s", (double)game.time,
                 (const char *[]){"air", "floor", "steep"}[game_body_state(&game)],
                 (int)char_body_floor_id(&game.body), playing ? "  REPLAY" : "");
        graphics_draw_text(v.fb, 12, 12, hud);
        display_show(v.fb);
    }
}
