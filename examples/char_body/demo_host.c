/**
 * @file demo_host.c
 * @brief Asset and script loading for the PC front-ends of the char_body example.
 */
#include "demo_host.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Whole file into an 8-byte-aligned heap block (coll_mesh_load uses it in place). */
static void *read_file(const char *path, size_t *size)
{
    FILE *f = fopen(path, "rb");
    if (!f) return NULL;
    void *buf = NULL;
    long n = -1;
    if (fseek(f, 0, SEEK_END) == 0) n = ftell(f);
    if (n >= 0 && fseek(f, 0, SEEK_SET) == 0) {
        buf = malloc((size_t)n + 8u); /* malloc is at least 8-byte aligned */
        if (buf && fread(buf, 1, (size_t)n, f) != (size_t)n) {
            free(buf);
            buf = NULL;
        }
    }
    fclose(f);
    if (buf) {
        ((char *)buf)[n] = 0;
        *size = (size_t)n;
    }
    return buf;
}

static bool load_mesh(demo_assets_t *a, int slot, const char *dir, const char *name, const coll_mesh_t **out)
{
    char path[512];
    snprintf(path, sizeof path, "%s/%s.coll", dir, name);
    size_t size = 0;
    a->blobs[slot] = read_file(path, &size);
    if (!a->blobs[slot]) {
        fprintf(stderr, "ERROR: %s: cannot read (run `make assets` first)\n", path);
        return false;
    }
    coll_err_t err = coll_mesh_load(a->blobs[slot], size, out);
    if (err != COLL_OK) {
        fprintf(stderr, "ERROR: %s: %s\n", path, coll_strerror(err));
        return false;
    }
    return true;
}

bool demo_assets_load(demo_assets_t *a, const char *dir)
{
    memset(a, 0, sizeof *a);
    static const char *const plat_names[4] = {
        "platform_translate", "platform_rotate", "platform_scale", "platform_lift",
    };
    bool ok = load_mesh(a, 0, dir, "test_course", &a->course);
    for (int i = 0; i < 4; i++) ok = load_mesh(a, 1 + i, dir, plat_names[i], &a->platforms[i]) && ok;
    ok = load_mesh(a, 5, dir, "planet", &a->planet) && ok;
    if (!ok) demo_assets_free(a);
    return ok;
}

void demo_assets_free(demo_assets_t *a)
{
    for (int i = 0; i < 6; i++) free(a->blobs[i]);
    memset(a, 0, sizeof *a);
}

bool demo_replay_load(replay_t *r, const char *path)
{
    size_t size = 0;
    char *text = read_file(path, &size);
    if (!text) {
        fprintf(stderr, "ERROR: %s: cannot read\n", path);
        return false;
    }
    bool ok = replay_parse(r, text, (uint32_t)size);
    if (!ok) fprintf(stderr, "ERROR: %s:%d: bad command\n", path, r->error_line);
    free(text);
    return ok;
}

void demo_status_line(char *buf, int size, const game_t *g, const replay_t *r)
{
    static const char *const state[3] = {[CHAR_BODY_AIRBORNE] = "air  ", [CHAR_BODY_ON_FLOOR] = "floor",
                                         [CHAR_BODY_ON_STEEP] = "steep"};
    const char *cmd = r && !replay_done(r) ? replay_op_name(r->cmds[r->pc].op) : "-";
    int line = r && !replay_done(r) ? r->cmds[r->pc].line : 0;
    snprintf(buf, (size_t)size, "t=%6.2f pos=(%7.2f %6.2f %7.2f) %s floor_id=%3d %s gravity=%s cmd=%s:%d",
             (double)g->time, (double)g->pos.x, (double)g->pos.y, (double)g->pos.z, state[game_body_state(g)],
             (int)char_body_floor_id(&g->body), g->speed_factor < 0.999f ? "slowed" : "      ",
             g->planet_gravity ? "planet" : "normal", cmd, line);
}
