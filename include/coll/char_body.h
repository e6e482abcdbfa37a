/**
 * @file coll/char_body.h
 * @brief Kinematic capsule character body: gravity along its own up vector, swept
 *        move-and-slide, creases, slopes, floor snapping, stairs, moving platforms.
 *
 * Each frame: set input_velocity, call char_body_move_and_slide(). The body adds gravity,
 * sweeps and slides, snaps to the floor and writes the resolved position back to the
 * owner's position. Allocation-free; the whole body is a plain struct (<= 256 bytes).
 *
 * What holds the body up, beyond the seed:
 * - Stairs: a riser of at most step_height is climbed at any update rate; where the
 *   shortened capsule's round bottom catches the nosing of a later riser first (treads
 *   shorter than about 0.45 m), the body steps over it (lift, move, come back down) and
 *   may ride that nosing until its foot is over the next tread. A taller riser blocks.
 * - Ledges and cracks: the foot is a point. Where the floor under the foot point is out of
 *   reach (none, or deeper than floor_snap_distance), the full capsule's bottom ball is
 *   dropped onto what is below it and rolled down its contact: when the roll meets the
 *   other side of a gap (a wedge) or a walkable floor within half a radius of descent, the
 *   body is supported and stands at the height of the lower contact -- a crack (a gap
 *   narrower than about 1.7 radii between floor pieces, a slot at the bottom of a valley or
 *   between a ledge and a wall). Where the roll finds nothing to hold it but the ball,
 *   lowered by half a radius, rests on three or more edges whose directions around it
 *   leave no gap of 180 degrees or more (the plane the foot is over not counted), it is in
 *   a hole between pieces and is held at its first contact. Otherwise it is a ledge and
 *   the body falls. Where the crack's edges have no room for the lift and either contact
 *   lies on the floor under the foot, that floor holds the body instead. Over a floor
 *   within reach the same ball holds the body above it where the gap is between surfaces
 *   at one level, or between surfaces on opposite sides of the foot at any levels (blocks
 *   of different heights): never on a stair's nosings, whose roll ends on the tread below.
 *   A side the dropped ball meets first there (a face too steep to stand on: a rock or a
 *   slab beside the tiles) is slid down past, and a face nearly along up that the foot
 *   point finds (a tile's side under a tilted up) does not stop the rule.
 * - Room to stand: a step that would leave the full capsule standing on a floor it has no
 *   room above (under a low ledge or an overhang) is not taken.
 * - char_body_get_velocity() is the velocity the body moved with (a stop by a wall, wedge
 *   or crack shows), not a fall speed accumulating while it rests; carry is not included.
 *   Across up it is the step's displacement / dt, sliding off an edge or a nosing included,
 *   and the push out of an overlap at the start of the step where it moves the body more
 *   than the skin (1 % of the radius, at most 1 mm: out of an overlap the game made, or
 *   along a crease); in the air (before and after the step) also a push along up of no
 *   more than a step of gravity (g dt^2: squeezed up a crease; the next step's gravity
 *   takes it back); not motion, so not in it: a push within the skin (a slide's own
 *   overshoot), any larger push along up, and on a walkable floor the snap and stair lift
 *   along up (there the velocity along up is 0). No motion across up is faster than the speed limit
 *   (200 m/s): a degenerate step (dt of a nanosecond) does not slide off a nosing or an
 *   edge, it waits for the next step.
 */
#ifndef COLL_CHAR_BODY_H
#define COLL_CHAR_BODY_H

#include "coll/common.h"
#include "coll/scene.h"

#ifdef __cplusplus
extern "C" {
#endif

/**
 * Character body settings: the seed's "Character-Body Component Settings" table, plus
 * additions; defaults in CHAR_BODY_SETTINGS_DEFAULT.
 *
 * Lengths are in the game's length unit, speeds in units/s, gravity in units/s^2. The
 * comments give the defaults in metres. A game in another unit sets units_per_meter (100
 * for centimetres, SM64-style; 1000 for millimetres) and scales every length, speed and
 * acceleration it gives the body by it: the body then moves the same course the same way,
 * scaled, because its internal tolerances (contact skin, touching distances, clamps such as
 * the 200 m/s speed limit) are metres times units_per_meter. It is one documented scale,
 * not guessed from the capsule: a big character in metres keeps metre tolerances.
 */
typedef struct {
    fm_vec3_t up;              ///< world up; gravity acts along -up. Normalized on configure.
    fm_vec3_t center_offset;   ///< owner origin -> capsule center, meters
    float gravity;             ///< m/s^2 along -up (30)
    float max_fall_speed;      ///< terminal speed along -up, m/s (55)
    float floor_max_angle;     ///< steepest walkable slope, radians (45 deg)
    float step_height;         ///< highest riser climbed, m (0.25); <= inner half height, <= snap
    float floor_snap_distance; ///< floor probe reach below the capsule, m (0.30); >= step
    float radius;              ///< capsule radius, m (0.5)
    float height;              ///< capsule total height incl. caps, m (2.0); >= 2 * radius
    uint8_t coll_types;        ///< COLL_TYPE_* seen (meshes)
    uint8_t max_slides;        ///< sweep-and-slide iterations per step, 1..8 (4)
    uint8_t read_mask;         ///< collision layers seen (0x01)
    bool follow_floor;         ///< carried by the mesh instance stood on (true)
    uint8_t leave_velocity;    ///< CHAR_BODY_LEAVE_*: the floor's velocity kept on leaving it (ADD)
    float units_per_meter;     ///< length units in a metre (1: metres; 100: centimetres); 1e-3..1e4,
                               ///< 0 or not finite: 1. Scales every internal length tolerance and limit.
} char_body_settings_t;

/** What the body keeps of the velocity of the floor it leaves (a jump, walking off an
 *  edge), as Godot's CharacterBody3D platform_on_leave. */
enum {
    CHAR_BODY_LEAVE_ADD = 0,        ///< keep all of it (default): jump off a lift, land on it
    CHAR_BODY_LEAVE_HORIZONTAL = 1, ///< keep only its part across up
    CHAR_BODY_LEAVE_DROP = 2,       ///< keep none of it
};

/** Where the body stands (char_body_ground_state()). */
typedef enum {
    CHAR_BODY_AIRBORNE = 0, ///< not touching a floor
    CHAR_BODY_ON_FLOOR,     ///< on a walkable floor
    CHAR_BODY_ON_STEEP,     ///< on a surface steeper than floor_max_angle (slides down it)
} char_body_ground_state_t;

/** What happened in the last step (char_body_events()): bits of char_body_events_t.flags. */
enum {
    CHAR_BODY_EVENT_LANDED      = 1u << 0, ///< airborne before, on a floor now (landing_speed)
    CHAR_BODY_EVENT_LEFT_FLOOR  = 1u << 1, ///< on a floor before, airborne now (a jump or a walk off)
    CHAR_BODY_EVENT_JUMPED      = 1u << 2, ///< left the floor moving up along up (with LEFT_FLOOR)
    CHAR_BODY_EVENT_STEPPED     = 1u << 3, ///< on a floor before and after, stepped up or down (step)
    CHAR_BODY_EVENT_HIT_CEILING = 1u << 4, ///< stopped by something above while moving up
    CHAR_BODY_EVENT_HIT_WALL    = 1u << 5, ///< slid along or stopped at a wall (wall_normal)
};

/** Events of the last step; all zero when nothing happened. */
typedef struct {
    uint8_t flags;         ///< CHAR_BODY_EVENT_* bits
    float landing_speed;   ///< LANDED: speed along -up at impact, m/s (>= 0)
    float step;            ///< STEPPED: height change along up, m (> 0 up a stair, < 0 down)
    fm_vec3_t wall_normal; ///< HIT_WALL: normal of the (last) wall hit, unit
} char_body_events_t;

/** The seed's defaults. */
#define CHAR_BODY_SETTINGS_DEFAULT ((char_body_settings_t){ \
    .up = {{0.0f, 1.0f, 0.0f}}, .center_offset = {{0.0f, 0.0f, 0.0f}}, \
    .gravity = 30.0f, .max_fall_speed = 55.0f, .floor_max_angle = 0.78539816f, \
    .step_height = 0.25f, .floor_snap_distance = 0.30f, .radius = 0.5f, .height = 2.0f, \
    .coll_types = COLL_TYPE_MESH, .max_slides = 4, .read_mask = 0x01, .follow_floor = true, \
    .units_per_meter = 1.0f })

/**
 * Optional per-body gather cache (char_body_set_gather_cache()). A step gathers the mesh
 * triangles around the body once (its box: the capsule grown by the step's reach). With a
 * cache, a refill keeps the mesh-local triangles of a larger box (the step's, swept six
 * steps ahead at the step's velocity, at most 1 m, and grown by 0.1 m; in units_per_meter)
 * and the following steps take theirs from it while the cache still covers them: the same
 * scene and mesh list, each instance seen then still on the same mesh, and the step's box,
 * taken into each instance's mesh space under its transform now, inside the mesh-space box
 * the cache walked there (so a moving or turning platform keeps its cached triangles until
 * the body leaves their box, and the game may write inst->xf any frame). Otherwise the
 * cache is refilled. The step sees exactly the triangles a fresh gather would, in the same
 * order, with bit-identical shapes (rebuilt from the cached mesh-local vertices by the
 * fresh gather's own expressions): the body moves bit for bit as without a cache. Scenes
 * with more than COLL_GATHER_CACHE_INSTANCES mesh instances, and refills meeting more than
 * COLL_GATHER_CACHE_TRIS triangles or 64 grid cells of an instance, take the uncached gather.
 * The game owns the memory (sizeof(coll_gather_cache_t): 5,176 B on the console, 5,280 B on
 * a 64-bit host); one cache serves one body. All fields are private.
 */
#ifndef COLL_GATHER_CACHE_TRIS
#define COLL_GATHER_CACHE_TRIS 64 ///< at most 64 (the library and the game must agree)
#endif
#ifndef COLL_GATHER_CACHE_INSTANCES
#define COLL_GATHER_CACHE_INSTANCES 8 ///< at most 255 (the library and the game must agree)
#endif

typedef struct {
    const coll_mesh_instance_t *inst;
    const coll_mesh_t *mesh;
    fm_vec3_t llo, lhi;    ///< the mesh-local box the fill walked
    uint32_t clo[3], chi[3]; ///< the grid cells it walked
    uint8_t walked;        ///< seen and valid at the fill: llo..lhi holds
    uint8_t first, count;  ///< its triangles: order[first .. first + count - 1]
} coll_gather_cache_inst_t;

typedef struct {
    fm_vec3_t v0, d1, d2;  ///< mesh-local first vertex (dequantized) and the other two less it
    fm_vec3_t blo, bhi;    ///< mesh-local box of the three vertices
    uint32_t tri;
    uint64_t cells;        ///< the walked cells whose list has it (bit per cell, x fastest)
} coll_gather_cache_tri_t;

typedef struct coll_gather_cache_s {
    const coll_scene_t *scene;
    uint8_t ninst, ntris;
    uint8_t valid;
    uint8_t backoff;       ///< misses left without a refill (after an overflow or unused refills)
    uint8_t since;         ///< hits since the last refill (saturating)
    uint8_t wasted;        ///< refills in a row that served no other step
    uint32_t hits, fills, overflows; ///< counters: steps taken from the cache, refills, overflows
    coll_gather_cache_inst_t inst[COLL_GATHER_CACHE_INSTANCES];
    uint8_t order[COLL_GATHER_CACHE_TRIS]; ///< tris[] by instance, then triangle index
    coll_gather_cache_tri_t tris[COLL_GATHER_CACHE_TRIS];
} coll_gather_cache_t;

/** A character body. Only input_velocity is meant to be written directly. */
typedef struct char_body_s {
    fm_vec3_t input_velocity;      ///< desired motion, m/s; only the part across up is used

    /* ---- state (read through the accessors) ---- */
    char_body_settings_t settings;
    fm_vec3_t *owner_pos;          ///< owner's origin, read each step and written back
    fm_vec3_t velocity;            ///< resolved velocity, m/s
    fm_vec3_t floor_normal;        ///< world normal of the floor stood on
    fm_vec3_t floor_local_point;   ///< foot contact in the floor instance's local space
    fm_vec3_t floor_world_point;   ///< the same contact in world space when it was recorded
    fm_vec3_t origin;              ///< the body's own origin when owner_pos is NULL; last good position
    float drop_time;               ///< s left falling through one-way platforms (private)
    const coll_mesh_instance_t *floor_instance; ///< mesh instance stood on (carry), or NULL
    float cos_floor_max_angle;     ///< cached cos(settings.floor_max_angle)
    float inner_half_height;       ///< cached height / 2 - radius
    float slide_speed;             ///< speed sliding down a steep floor, m/s (private)
    int32_t floor_id;              ///< id of the collider stood on, -1 when none
    uint8_t flags;                 ///< CB_FLAG_* (private)
    fm_vec3_t ground_velocity;     ///< velocity of the floor point stood on, m/s
    fm_vec3_t carry_velocity;      ///< last step's carry displacement / dt (private)
    fm_vec3_t air_velocity;        ///< floor velocity across up kept since leaving it (private)
    coll_body_t *collider;         ///< the body's own collider, kept in sync, or NULL
    char_body_events_t events;     ///< what happened in the last step
    coll_gather_cache_t *gather_cache; ///< the game's gather cache, or NULL (char_body_set_gather_cache)
} char_body_t;

/** Default settings, owner_pos attached (may be NULL: the body then keeps its own origin). */
void char_body_init(char_body_t *body, fm_vec3_t *owner_pos);
/** Applies settings, clamping them as the seed states, and refreshes cached values. */
void char_body_configure(char_body_t *body, const char_body_settings_t *settings);
const char_body_settings_t *char_body_get_settings(const char_body_t *body);
/** New up direction (normalized); zero or non-finite keeps the previous one. */
void char_body_set_up(char_body_t *body, fm_vec3_t up);
void char_body_set_center_offset(char_body_t *body, fm_vec3_t offset);

/**
 * One step on coll_scene_current(). dt <= 0 or not finite: no movement. With no current
 * scene (coll_scene_set_current() never called, or set to NULL) the body is left untouched;
 * that is a game bug, so debug builds (hosted, no NDEBUG; or -DCOLL_DEBUG_ASSERTS=1) assert.
 */
void char_body_move_and_slide(char_body_t *body, float dt);
/** One step on an explicit scene. */
void char_body_move_and_slide_in(char_body_t *body, const coll_scene_t *scene, float dt);

/** Standing on a walkable floor or a steep surface. */
bool char_body_is_on_floor(const char_body_t *body);
/** Standing on a surface steeper than floor_max_angle (is_on_floor is then true too). */
bool char_body_is_on_steep_surface(const char_body_t *body);
fm_vec3_t char_body_floor_normal(const char_body_t *body);
fm_vec3_t char_body_get_velocity(const char_body_t *body);
/** Sets the internal velocity (jumps: add up * jump_speed). Non-finite is ignored. */
void char_body_set_velocity(char_body_t *body, fm_vec3_t velocity);
/** Bottom point of the full capsule, world space. */
fm_vec3_t char_body_foot_pos(const char_body_t *body);
/** Id of the collider stood on, -1 when none. */
int32_t char_body_floor_id(const char_body_t *body);
/** Airborne, on a walkable floor, or on a steep surface. */
char_body_ground_state_t char_body_ground_state(const char_body_t *body);
/** Velocity of the floor point stood on (a moving, turning or scaling platform's motion at
 *  the foot), m/s; zero when airborne or on a static floor. */
fm_vec3_t char_body_ground_velocity(const char_body_t *body);
/** Events of the last step (landed, left the floor, stepped, hit a ceiling or a wall). */
const char_body_events_t *char_body_events(const char_body_t *body);

/**
 * Gives the body a collider of its own, so that other bodies (with COLL_TYPE_BODY in their
 * coll_types) collide with it: a capsule coll_body_t that the caller registers in the scene
 * (coll_scene_add_body) and owns. The body sets its shape to the full capsule and keeps it
 * at the body's position after every step and teleport; the body never collides with its
 * own collider (its write_mask is cleared while the body steps, then restored). NULL
 * detaches it. Bodies never push each other: each stops at or slides along the others.
 */
void char_body_set_collider(char_body_t *body, coll_body_t *collider);

/** Gives the body a gather cache (coll_gather_cache_t: owned by the game, one per body,
 *  about 5 KB), emptied here; NULL detaches it (the uncached gather, as without one).
 *  Steps then take their candidate triangles from it while the body stays in the box it
 *  was filled for and the scene is unchanged: the same triangles and answers, fewer grid
 *  walks (docs/BENCHMARKS.md, branch perf14). */
void char_body_set_gather_cache(char_body_t *body, coll_gather_cache_t *cache);

/** Drops through one-way platforms (COLL_INSTANCE_ONE_WAY): for as long as falling the
 *  body's height plus floor_snap_distance takes, they do not collide with it. */
void char_body_drop_through(char_body_t *body);

/** Moves the owner to owner_pos. reset_forces: zero velocity and clear the grounded state. */
void char_body_teleport(char_body_t *body, fm_vec3_t owner_pos, bool reset_forces);

/** Debug line callback target. Colours are 0xRRGGBBAA. */
typedef struct {
    void (*line)(void *user, fm_vec3_t a, fm_vec3_t b, uint32_t rgba);
    void *user;
} coll_debug_draw_t;

#define CHAR_BODY_COLOR_AIRBORNE  0xFFFFFFFFu ///< white
#define CHAR_BODY_COLOR_FLOOR     0x00FF00FFu ///< green
#define CHAR_BODY_COLOR_STEEP     0xFF8000FFu ///< orange
#define CHAR_BODY_COLOR_STEP_ZONE 0xFFFF00FFu ///< yellow
#define CHAR_BODY_COLOR_PROBE     0x0000FFFFu ///< blue
#define CHAR_BODY_COLOR_NORMAL    0x00FFFFFFu ///< cyan
#define CHAR_BODY_COLOR_FULL      0x404040FFu ///< dark grey

/** Draws the sweep capsule (state colour), full capsule, step zone, probe and contact normal. */
void char_body_debug_draw(const char_body_t *body, const coll_debug_draw_t *dd);

#ifdef __cplusplus
}
#endif
#endif
