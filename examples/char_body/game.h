/**
 * @file game.h
 * @brief The char_body example's game logic: a player controller on char_body_t, an
 *        orbiting camera, moving platforms and the two sample levels.
 *
 * Platform-independent C11 (math only, no allocation, no I/O): the same files build for
 * the PC (headless replay, SDL2 preview, tests) and the console (libdragon front-end).
 * A front-end loads the baked level meshes, fills a game_input_t each frame (from a
 * joypad, the keyboard or the replay autopilot) and calls game_step().
 */
#ifndef CHAR_BODY_EXAMPLE_GAME_H
#define CHAR_BODY_EXAMPLE_GAME_H

#include "coll/char_body.h"
#include "coll/scene.h"

#ifdef __cplusplus
extern "C" {
#endif

#define GAME_MAX_PLATFORMS 4
#define GAME_MAX_NPCS 3

/** One frame of player intent. Sticks in [-1, 1]; buttons are "held" states. */
typedef struct {
    float stick_x;        ///< move: +1 = right of the camera
    float stick_y;        ///< move: +1 = away from the camera
    float cam_x;          ///< camera yaw rate: +1 = orbit to the right
    float cam_y;          ///< camera pitch rate: +1 = look down more steeply
    bool jump;            ///< jump button held
    bool toggle_gravity;  ///< gravity toggle button held (acts on the press)
    bool drop;            ///< drop through the one-way platform stood on (acts on the press)
} game_input_t;

/** A non-player body walking back and forth between two points (feet positions); the
 *  player bumps into it (each has its own collider, char_body_set_collider). */
typedef struct {
    fm_vec3_t a, b;       ///< patrol ends, feet positions
    float speed;          ///< m/s; 0 stands still at a
} game_npc_t;

/** How a moving platform moves. All motions are sinusoidal about the platform's base. */
typedef enum {
    GAME_PLATFORM_TRANSLATE = 0, ///< back and forth along `axis` by `amount` meters
    GAME_PLATFORM_ROTATE,        ///< about the vertical axis, `amount` = rad/s (constant spin)
    GAME_PLATFORM_SCALE,         ///< x and z scale 1 + `amount` sin(2 pi t / period)
    GAME_PLATFORM_LIFT,          ///< up by 0 .. `amount` meters: (1 - cos) / 2
} game_platform_kind_t;

/** A moving platform: description plus the mesh instance the game moves every frame. */
typedef struct {
    game_platform_kind_t kind;
    fm_vec3_t base_pos;     ///< world position of the mesh origin at phase 0
    fm_vec3_t base_scale;   ///< mesh scale at phase 0
    fm_vec3_t axis;         ///< translate direction (unit), TRANSLATE only
    float amount;           ///< meters, rad/s or scale factor, see the kind
    float period;           ///< seconds per back-and-forth cycle
    const coll_mesh_t *mesh;   ///< the platform's own mesh (local origin at its top centre)
    coll_mesh_instance_t inst; ///< registered in the game's scene; game_init fills it
} game_platform_t;

/** What a level needs: meshes come from the front-end (baked blobs loaded in place). */
typedef struct {
    const coll_mesh_t *level;         ///< static level geometry
    fm_vec3_t spawn;                  ///< player origin (capsule centre) at start and respawn
    float spawn_yaw;                  ///< initial camera yaw, radians (0 looks along -Z)
    float kill_height;                ///< respawn below this height (normal gravity)
    bool has_planet;                  ///< planet gravity available
    fm_vec3_t planet_center;
    float kill_distance;              ///< planet: respawn farther than this from the centre
    uint8_t platform_count;
    game_platform_t platforms[GAME_MAX_PLATFORMS]; ///< inst.mesh/xf are filled by game_init
    const coll_mesh_t *one_way_mesh;  ///< a one-way platform (COLL_INSTANCE_ONE_WAY), or NULL
    fm_vec3_t one_way_pos;            ///< its mesh origin (top centre)
    uint8_t npc_count;
    game_npc_t npcs[GAME_MAX_NPCS];
} game_level_t;

/** Tuning of the controller. GAME_TUNING_DEFAULT gives the values the replays assume. */
typedef struct {
    float run_speed;        ///< m/s at full stick (7)
    float ground_accel;     ///< m/s^2 towards the stick's velocity on the floor (40)
    float air_accel;        ///< m/s^2 in the air (14)
    float jump_speed;       ///< m/s along up (11: about 2 m high with gravity 30)
    float jump_cut;         ///< upward speed kept when jump is released early (0.45)
    float coyote_time;      ///< seconds after leaving a floor a jump still works (0.15)
    float jump_buffer;      ///< seconds a jump press is remembered before landing (0.15)
    float steep_min_factor; ///< speed factor reached on a steep surface (0.35)
    float steep_rate;       ///< factor change per second towards the target (2.5)
    float gravity_blend;    ///< seconds to turn up to the new gravity after a toggle (0.35)
    float cam_yaw_rate;     ///< rad/s at full camera stick (2.5)
    float cam_pitch_rate;   ///< rad/s (1.5)
} game_tuning_t;

#define GAME_TUNING_DEFAULT ((game_tuning_t){ \
    .run_speed = 7.0f, .ground_accel = 40.0f, .air_accel = 14.0f, .jump_speed = 11.0f, \
    .jump_cut = 0.45f, .coyote_time = 0.15f, .jump_buffer = 0.15f, .steep_min_factor = 0.35f, \
    .steep_rate = 2.5f, .gravity_blend = 0.35f, .cam_yaw_rate = 2.5f, .cam_pitch_rate = 1.5f })

/** Event counters and measurements the front-ends print and the tests check. */
typedef struct {
    uint32_t frames;
    uint32_t jumps;           ///< jumps started
    uint32_t coyote_jumps;    ///< jumps started while airborne, inside the coyote window
    uint32_t buffered_jumps;  ///< jumps started on landing from a buffered press
    uint32_t jump_cuts;       ///< early releases that cut the upward speed
    uint32_t respawns;        ///< fell out of the level
    uint32_t gravity_toggles;
    float ride_distance[GAME_MAX_PLATFORMS]; ///< meters platform i carried the player (own walking excluded)
    float ride_time[GAME_MAX_PLATFORMS];     ///< seconds stood on platform i
    float steep_time;         ///< seconds on steep surfaces
    float min_speed_factor;   ///< lowest steep-surface speed factor seen
    uint32_t platform_jump_landings; ///< jumps off a moving platform that landed on it again
    uint32_t npc_bumps;       ///< frames the player touched a non-player body
    uint32_t camera_steps;    ///< stair steps the camera smoothed (step events)
    uint32_t one_way_landings; ///< landings on the one-way platform
    uint32_t drops;           ///< drops through the one-way platform
} game_stats_t;

/** A non-player body's state. */
typedef struct {
    char_body_t body;
    fm_vec3_t pos;            ///< origin = capsule centre
    coll_gather_cache_t gather_cache; ///< the body's gather cache (char_body_set_gather_cache)
    coll_body_t collider;     ///< registered in the game's scene
    bool to_b;                ///< walking towards b
} game_npc_state_t;

/** The whole game state; plain data, no pointers to outside except the level meshes. */
typedef struct {
    game_level_t level;
    game_tuning_t tuning;
    coll_scene_t scene;
    coll_mesh_instance_t level_inst;
    char_body_t body;
    fm_vec3_t pos;           ///< player origin = capsule centre (body's owner position)
    coll_gather_cache_t gather_cache; ///< the player's gather cache (char_body_set_gather_cache)
    fm_vec3_t up;            ///< current up (blended after a gravity toggle)
    fm_vec3_t cam_fwd;       ///< camera forward across up (unit, perpendicular to up)
    float cam_pitch;         ///< camera elevation above the player's horizon, radians
    float cam_dist;          ///< camera distance, meters
    fm_vec3_t move_vel;      ///< smoothed horizontal velocity (input_velocity)
    fm_vec3_t facing;        ///< player facing, unit, across up
    float speed_factor;      ///< steep-surface slowdown, 1 on normal ground
    float coyote_timer;      ///< time left to jump after leaving the floor
    float jump_buffer_timer; ///< time left on a buffered jump press
    bool jump_held_prev;
    bool toggle_held_prev;
    bool jumping;            ///< rising from a jump, jump still held (variable height)
    bool planet_gravity;     ///< gravity mode
    fm_vec3_t blend_from;    ///< up when the gravity toggle happened
    float blend_t;           ///< 0..1 progress of the up blend (1 = done)
    float time;              ///< seconds simulated
    fm_vec3_t prev_pos;
    int32_t prev_floor_id;
    coll_body_t collider;    ///< the player's own collider (the non-player bodies bump into it)
    coll_mesh_instance_t one_way_inst;
    game_npc_state_t npcs[GAME_MAX_NPCS];
    float cam_step;          ///< camera height offset absorbing stair steps, decays to 0
    int32_t jump_floor_id;   ///< floor id when the last jump started (-1: none)
    bool drop_held_prev;
    game_stats_t stats;
} game_t;

/** Fixed step the example runs at. */
#define GAME_DT (1.0f / 60.0f)

/** Platform ids start here; the level mesh has id GAME_LEVEL_ID. */
#define GAME_LEVEL_ID 1
#define GAME_PLATFORM_ID0 10
#define GAME_ONE_WAY_ID 20
#define GAME_PLAYER_COLLIDER_ID 30
#define GAME_NPC_ID0 31

/** Sets up the scene, the body and the platforms. The game keeps pointers into itself:
 *  do not copy a game_t after init. */
void game_init(game_t *g, const game_level_t *level);
/** One fixed step: platforms, input, body, respawn, camera. */
void game_step(game_t *g, const game_input_t *in, float dt);
/** Moves the platforms to their pose at time t (called by game_step). */
void game_update_platforms(game_t *g, float t);

/** Camera eye and the point it looks at, world space. */
void game_camera(const game_t *g, fm_vec3_t *eye, fm_vec3_t *target, fm_vec3_t *cam_up);
/** Camera-relative unit vectors on the player's ground plane. */
void game_move_basis(const game_t *g, fm_vec3_t *fwd, fm_vec3_t *right);

/** The player's ground state (the animation state and the debug colours: white airborne,
 *  green on the floor, orange on a steep surface), straight from char_body_ground_state(). */
char_body_ground_state_t game_body_state(const game_t *g);

/** Platform order of the course (platform N in the replay scripts). */
enum { GAME_PLAT_TRANSLATE = 0, GAME_PLAT_ROTATE, GAME_PLAT_SCALE, GAME_PLAT_LIFT };

/** The test course (assets/levels/test_course.gltf): stairs, ramps, V-corners, steep
 *  slopes, ledges, and the four moving platforms (meshes in GAME_PLAT_* order). */
void game_level_course(game_level_t *out, const coll_mesh_t *level, const coll_mesh_t *const platforms[4]);
/** The planet (assets/levels/planet.gltf): radius 20 m round the origin. */
void game_level_planet(game_level_t *out, const coll_mesh_t *level);

/* ---- small vector helpers shared by the example's files ---- */
fm_vec3_t game_v3(float x, float y, float z);
fm_vec3_t game_v3_add(fm_vec3_t a, fm_vec3_t b);
fm_vec3_t game_v3_sub(fm_vec3_t a, fm_vec3_t b);
fm_vec3_t game_v3_scale(fm_vec3_t a, float s);
float game_v3_dot(fm_vec3_t a, fm_vec3_t b);
fm_vec3_t game_v3_cross(fm_vec3_t a, fm_vec3_t b);
float game_v3_len(fm_vec3_t a);
fm_vec3_t game_v3_norm(fm_vec3_t a);
/** A point of a mesh instance's local space in world space (scale, rotate, translate). */
fm_vec3_t game_instance_point(const coll_mesh_instance_t *inst, fm_vec3_t local);
/** a with its component along unit n removed. */
fm_vec3_t game_v3_reject(fm_vec3_t a, fm_vec3_t n);
/** Rotates v by the shortest arc that takes unit a onto unit b. */
fm_vec3_t game_v3_transport(fm_vec3_t v, fm_vec3_t a, fm_vec3_t b);
float game_clampf(float x, float lo, float hi);
/** Spherical interpolation between unit vectors. */
fm_vec3_t game_v3_slerp(fm_vec3_t a, fm_vec3_t b, float t);

#ifdef __cplusplus
}
#endif
#endif
