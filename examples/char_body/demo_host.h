/**
 * @file demo_host.h
 * @brief PC-side helpers of the char_body example shared by the headless demo, the SDL2
 *        preview and the replay test: load the baked levels and the replay scripts.
 */
#ifndef CHAR_BODY_EXAMPLE_DEMO_HOST_H
#define CHAR_BODY_EXAMPLE_DEMO_HOST_H

#include "game.h"
#include "game_replay.h"

/** Baked meshes used in place (the blobs stay allocated while the meshes are in use). */
typedef struct {
    void *blobs[6];
    const coll_mesh_t *course;
    const coll_mesh_t *platforms[4]; ///< GAME_PLAT_* order
    const coll_mesh_t *planet;
} demo_assets_t;

/** Loads DIR/test_course.coll, DIR/platform_{translate,rotate,scale,lift}.coll and
 *  DIR/planet.coll. Prints what failed to stderr and returns false. */
bool demo_assets_load(demo_assets_t *a, const char *dir);
void demo_assets_free(demo_assets_t *a);

/** Reads and parses a replay script; prints the failing line on error. */
bool demo_replay_load(replay_t *r, const char *path);

/** One-line status: time, position, floor state, floor id, current command. */
void demo_status_line(char *buf, int size, const game_t *g, const replay_t *r);

#endif
