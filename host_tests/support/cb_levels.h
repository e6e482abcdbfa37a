/**
 * @file cb_levels.h
 * @brief Procedural test geometry for the character-body suites: floors, walls, V-corners,
 *        ramps, stairs, ledges, ceilings, thin walls and sphere planets, built with
 *        coll_mesh_build() into static buffers, plus one static scene to put them in.
 */
#ifndef CB_LEVELS_H
#define CB_LEVELS_H

#include "coll/char_body.h"
#include "coll/mesh.h"
#include "coll/scene.h"

/* ---- geometry accumulation (one static buffer, cleared by cb_geo_begin) ---- */
void cb_geo_begin(void);
void cb_geo_tri(fm_vec3_t a, fm_vec3_t b, fm_vec3_t c);
/** Quad a-b-c-d as two triangles. */
void cb_geo_quad(fm_vec3_t a, fm_vec3_t b, fm_vec3_t c, fm_vec3_t d);
/** Axis-aligned box, then rotated by yaw (radians, about +Y through the box centre). */
void cb_geo_box(fm_vec3_t center, fm_vec3_t half, float yaw);
/** A profile polyline in the X-Y plane (xs[i], ys[i]) extruded from z0 to z1. */
void cb_geo_profile(const float *xs, const float *ys, int n, float z0, float z1);
/** A staircase profile extruded from z0 to z1: flat ground from x = -30, `steps` (at most
 *  CB_GEO_MAX_STAIRS) risers rising along +x from x = 0, a landing to x = 30. */
#define CB_GEO_MAX_STAIRS 16
void cb_geo_stairs(float tread, float riser, int steps, float z0, float z1);
/** Flat grid of (n x n) cells, each two triangles, on y = height, x and z in [-half, half]. */
void cb_geo_grid(float half, int n, float height);
/** Latitude-longitude sphere (outward faces). */
void cb_geo_sphere(fm_vec3_t center, float radius, int slices, int stacks);
/** Builds what was accumulated into the static arena. */
const coll_mesh_t *cb_geo_end(void);

/* ---- the one scene the suites use ---- */
typedef struct {
    coll_scene_t scene;
    coll_mesh_instance_t inst[16];
    coll_body_t bodies[4];
    int ninst, nbodies;
} cb_world_t;
extern cb_world_t cb_world;

/** Empties the scene and the mesh arena. */
void cb_world_reset(void);
/** Adds a mesh instance at xf (write_mask 0x01); returns it (the test may move it). */
coll_mesh_instance_t *cb_world_add_mesh(const coll_mesh_t *mesh, coll_transform_t xf, uint16_t id);
/** Adds the accumulated geometry as a static instance at the origin. */
coll_mesh_instance_t *cb_world_add_geo(uint16_t id);
coll_body_t *cb_world_add_box_body(fm_vec3_t pos, fm_vec3_t half, uint16_t id);

/* ---- ready-made levels ---- */
/** Flat floor: a 1 m thick slab, top at y = 0, x and z in [-half, half]. */
void cb_level_floor(float half);

/* ---- helpers ---- */
static inline fm_vec3_t cb_vec(float x, float y, float z) { fm_vec3_t v = {{x, y, z}}; return v; }
/** Default settings with center_offset (0, height / 2, 0): the owner position is the foot. */
char_body_settings_t cb_foot_settings(void);
/** Inits body on *pos with cb_foot_settings(). */
void cb_body_init(char_body_t *body, fm_vec3_t *pos, fm_vec3_t start);
/** Prints a measured figure as "MEASURED what = value unit" (the suites' result lines). */
void cb_report(const char *what, double value, const char *unit);
/** True when position and velocity are finite. */
bool cb_body_finite(const char_body_t *body);

/** One step on cb_world with the allocation guard (needs unity.h and alloc_guard.h). */
#define CB_STEP(body, dt) ASSERT_NO_ALLOC(char_body_move_and_slide_in((body), &cb_world.scene, (dt)))

#endif
