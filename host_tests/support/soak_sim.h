/**
 * @file soak_sim.h
 * @brief Soak / property / determinism harness shared by the soak program
 *        (host_tests/soak/soak_main.c) and the Unity suites test_replays and test_determinism.
 *
 * Pieces:
 *  - soak_rng_*      splitmix64 PRNG (never rand()): identical streams on every platform.
 *  - soak_level_*    random level from a seed: enclosure, boxes, ramps, stairs, thin walls,
 *                    V-corners, triangle soups, overlapping/coplanar copies, moving mesh
 *                    platforms (translate/rotate/scale) and collider bodies, all built with
 *                    coll_mesh_build into the level's own static pool (no malloc).
 *                    Generation uses double arithmetic and our own sin/cos only, so a seed
 *                    gives bit-identical levels on x86-64 and big-endian MIPS.
 *  - soak_play_*     random per-frame play (inputs, jumps, teleports, up changes, dt, NaN).
 *  - soak_check_*    independent double-precision brute-force property checker, and the
 *                    geometry of the behaviour oracles (footing, free flat floor, support).
 *  - soak_sim_*      runs a body on a level frame by frame and classifies property failures
 *                    (state checks, then the behaviour oracles: soak_sim_check_motion).
 *  - soak_replay_*   text replay files (hex floats) with per-architecture expected states.
 *
 * Every non-static symbol starts with soak_ (this file's objects are linked into every
 * test binary).
 */
#ifndef SOAK_SIM_H
#define SOAK_SIM_H

#include <stdint.h>
#include <stdio.h>
#include <stdbool.h>
#include "coll/char_body.h"

/* ------------------------------------------------------------------ PRNG */
typedef struct { uint64_t s; } soak_rng_t;
void     soak_rng_seed(soak_rng_t *r, uint64_t seed);
uint64_t soak_rng_next(soak_rng_t *r);
double   soak_rng_unit(soak_rng_t *r);                 ///< [0, 1)
double   soak_rng_range(soak_rng_t *r, double a, double b);
uint32_t soak_rng_below(soak_rng_t *r, uint32_t n);    ///< [0, n)
bool     soak_rng_chance(soak_rng_t *r, double p);
/** splitmix64 finalizer, used to derive independent sub-seeds. */
uint64_t soak_mix64(uint64_t x);

/** Deterministic double sine/cosine (no libm: same bits on every IEEE platform). */
double soak_sin(double x);
double soak_cos(double x);

/* ------------------------------------------------------------------ level */
#define SOAK_MAX_PIECES   40      ///< mesh instances per level (scene holds 64)
#define SOAK_MAX_BODIES   10
#define SOAK_MAX_VERTS    12000
#define SOAK_MAX_TRIS     8000
#define SOAK_POOL_BYTES   (1u << 20)

/** Room interior (the enclosure): x,z in [-HALF, HALF], y in [0, HEIGHT]. */
#define SOAK_ROOM_HALF    24.0
#define SOAK_ROOM_HEIGHT  24.0

typedef struct {
    uint32_t first_vert, nverts, first_tri, ntris; ///< ranges in the level arrays (local coords)
    coll_mesh_instance_t inst;
    bool moving;
    /* motion (moving pieces): xf(t) from the base transform */
    float base_pos[3];
    float base_rot[4];
    float move_dir[3];
    double move_amp, move_omega, move_phase;
    float rot_axis[3];
    double rot_omega;
    double scale_amp, scale_omega;
    double bound_radius;          ///< local bounding-sphere radius (around local origin)
    int kind;                     ///< generator kind (for stats)
} soak_piece_t;

typedef struct {
    coll_body_t body;
    bool moving;
    float base_pos[3];
    float move_dir[3];
    double move_amp, move_omega;
} soak_lbody_t;

/** Static triangle in world space, double precision (checker data). */
typedef struct {
    double v[3][3];
    double c[3];      ///< bounding-sphere centre
    double rad;       ///< bounding-sphere radius
    uint8_t mask;     ///< write mask of its piece
    uint8_t closed;   ///< its piece is closed and consistently wound (every directed edge met
                      ///< once reversed): its front face (by winding) is the outside of a solid;
                      ///< 2: closed, its back face is the outside (a solid closed by the room
                      ///< floor, kept in the generator's vertex order: the soak's teleport
                      ///< targets are picked on these triangles)
} soak_wtri_t;

/** Generator versions. 1: the original generator (replays without a `gen` line);
 *  2: adds the real-world shapes of issue 12 (cracks, V-valley slots, modular tiles with
 *  gaps and height mismatches, overhangs and acute wedges, regular staircases). */
#define SOAK_GEN_V1      1
#define SOAK_GEN_CURRENT 2

typedef struct {
    uint64_t seed;
    int gen;                            ///< generator version (SOAK_GEN_*), 0 for a loaded level
    uint32_t npieces, nbodies, nverts, ntris, nwtris;
    soak_piece_t pieces[SOAK_MAX_PIECES];
    soak_lbody_t bodies[SOAK_MAX_BODIES];
    float verts[SOAK_MAX_VERTS * 3];
    uint32_t idx[SOAK_MAX_TRIS * 3];
    soak_wtri_t *wtris;                 ///< static pieces only, world space (wtris_store or a loaded level's)
    soak_wtri_t wtris_store[SOAK_MAX_TRIS];
    /* A loaded (real) level instead of the generated room: bounds of its triangles; the
     * room checks (escape) are replaced by "left the level's bounds" (reported). */
    bool loaded;
    double lo[3], hi[3];
    char file[256];                     ///< loaded level: its blob path
    coll_scene_t scene;
    size_t pool_used;
    _Alignas(16) unsigned char pool[SOAK_POOL_BYTES];
} soak_level_t;

/** Generates and builds the level for seed with generator version 1 (the original one;
 *  0 on success, else a negative code). */
int  soak_level_generate(soak_level_t *lvl, uint64_t seed);
/** The same with an explicit generator version (SOAK_GEN_V1 .. SOAK_GEN_CURRENT). */
int  soak_level_generate_v(soak_level_t *lvl, uint64_t seed, int gen);
/** Loads a baked level: blob (collbake .coll, for the library) and raw (collbake --dump-raw,
 *  the checker's independent copy of the same triangles). The blob and the raw triangles
 *  are malloc'd (host tool only). 0 on success, else a negative code with a message. */
int  soak_level_load(soak_level_t *lvl, const char *blob_path, const char *raw_path, char *err, size_t errlen);
/** What the queries of every soak scene did (coll_scene_set_stats): character steps that
 *  gathered, their overflows and the queries that ran on the scene instead (issue 14's
 *  "overflow fallbacks rare enough to be noise" on real levels). */
extern coll_query_stats_t soak_query_stats;
/** Sets the transforms of moving pieces and bodies for time t (seconds). */
void soak_level_animate(soak_level_t *lvl, double t);
/** FNV-1a hash of the generated geometry, transforms and body data (cross-platform). */
uint64_t soak_level_hash(const soak_level_t *lvl);

/** Random character settings within the documented ranges, plus a start position. */
void soak_settings_random(soak_rng_t *r, char_body_settings_t *s, fm_vec3_t *start);

/* ------------------------------------------------------------------ play */
enum {
    SOAK_OP_JUMP = 1,      ///< velocity += up * jump
    SOAK_OP_TELEPORT = 2,  ///< teleport(tele, tele_reset)
    SOAK_OP_UP = 4,        ///< set_up(up)
    SOAK_OP_VEL = 8,       ///< set_velocity(vel)
};

typedef struct {
    float dt;
    fm_vec3_t input;
    uint8_t ops;
    uint8_t tele_reset;
    float jump;
    fm_vec3_t tele;
    fm_vec3_t up;
    fm_vec3_t vel;
} soak_frame_t;

typedef struct {
    soak_rng_t rng;
    fm_vec3_t input;
    float base_dt;
    uint32_t hold;        ///< frames left before the input changes
    bool gentle;          ///< real levels: walking and jumping only (0.5-8 m/s, dt 1/60 or 1/30,
                          ///< jumps, respawns at spawn points; no NaN, no up changes)
} soak_play_t;

void soak_play_init(soak_play_t *p, uint64_t seed);
/** Spawn point of a loaded level: above a random upward-facing triangle (capsule centre
 *  height/2 + 5 cm above it), as an owner position. */
fm_vec3_t soak_level_spawn(soak_rng_t *r, const soak_level_t *lvl, const char_body_settings_t *s);
/** Next frame's play; owner is the body's current origin (teleports and up changes keep
 *  the whole capsule inside the room so it can always get out without leaving it). */
void soak_play_next(soak_play_t *p, const soak_level_t *lvl, const char_body_settings_t *s,
                    fm_vec3_t owner, soak_frame_t *f);

/* ------------------------------------------------------------------ checker */
/** Closest distance between segment [p0,p1] and triangle (double). */
double soak_seg_tri_dist(const double p0[3], const double p1[3], const double *v0, const double *v1,
                         const double *v2);
/** Closest distance between two segments. */
double soak_seg_seg_dist(const double p0[3], const double p1[3], const double q0[3], const double q1[3]);

/** World capsule: segment a..b, radius r. */
typedef struct { double a[3], b[3], r; } soak_capsule_t;

/** Full capsule and sweep capsule (shortened from the bottom by step_height) of a body. */
void soak_body_capsules(const char_body_t *b, soak_capsule_t *full, soak_capsule_t *sweep);

/** Deepest penetration (r - distance) of cap into a seen static triangle beyond what the
 *  seed accepts (walkable slopes when radius/step/angle break the seed's rule); 0 when none.
 *  tri_out: index in lvl->wtris; raw_out: the raw depth of that triangle. */
double soak_check_static_pen(const soak_level_t *lvl, const char_body_settings_t *s,
                             const soak_capsule_t *cap, int32_t *tri_out, double *raw_out);
/** The start overlap the body's recover pushes out of: the deepest raw penetration of cap
 *  into a seen static triangle (the walkable allowance not taken off), at most SOAK_PEN_TOL. */
double soak_check_pushout_depth(const soak_level_t *lvl, const char_body_settings_t *s, const soak_capsule_t *cap);
/** True when p lies inside a closed static solid (a piece whose every edge is shared
 *  once reversed: boxes, tile fields, stair blocks), by the signed crossings of two rays
 *  with its seen triangles. A capsule whose centre is inside one and that overlaps none of
 *  its faces is wholly in it: in geometry, though no face is within its radius. */
bool soak_check_inside_closed(const soak_level_t *lvl, const char_body_settings_t *s, const double p[3]);
/** Deepest penetration of cap into a seen static collider body (sphere, capsule, box; exact
 *  in double; cylinders are skipped); 0 when none. Reported, not a failure. */
double soak_check_body_pen(const soak_level_t *lvl, const char_body_settings_t *s, const soak_capsule_t *cap);
/** Smallest distance from the capsule surface to any seen geometry (static, moving, bodies). */
double soak_check_nearest(const soak_level_t *lvl, const char_body_settings_t *s,
                          const soak_capsule_t *cap);

/* ------------------------------------------------------------------ simulation */
enum {
    SOAK_FAIL_NONE = 0,
    SOAK_FAIL_NONFINITE,    ///< position or velocity not finite
    SOAK_FAIL_PENETRATION,  ///< sweep capsule > 1 mm into a static triangle, no excuse
    SOAK_FAIL_ESCAPE,       ///< capsule centre left the room (below the lowest floor etc.)
    SOAK_FAIL_FLOOR,        ///< is_on_floor with no surface within snap reach
    SOAK_FAIL_STATE,        ///< inconsistent state (steep without floor, floor id, normal)
    /* behaviour oracles (checks version 2; docs/RELIABILITY.md) */
    SOAK_FAIL_DIRECTION,    ///< walking: the step moved against the input by more than 1 mm
    SOAK_FAIL_PROGRESS,     ///< walking over verified free flat floor: < 90 % of the input distance
    SOAK_FAIL_FOOTING,      ///< grounded foot > 1 mm below the walkable surface under it
    SOAK_FAIL_SUPPORT,      ///< at rest 30 frames touching walkable geometry, not grounded
    SOAK_FAIL_VELOCITY,     ///< reported velocity differs from displacement / dt
    SOAK_FAIL_COUNT
};
const char *soak_fail_name(int kind);

#define SOAK_PEN_TOL     1e-3   ///< allowed penetration, m
#define SOAK_FLOOR_TOL   1e-2   ///< slack of the is_on_floor reach check, m
#define SOAK_RECOVER_FRAMES 120 ///< excused penetration longer than this counts as "stuck"

/** Checker versions. 1: the state checks only (replays without a `checks` line);
 *  2: plus the behaviour oracles direction, progress, footing, support, velocity. */
#define SOAK_CHECKS_V1      1
#define SOAK_CHECKS_CURRENT 2

#define SOAK_ORACLES_ALL  ((1u << SOAK_FAIL_DIRECTION) | (1u << SOAK_FAIL_PROGRESS) | (1u << SOAK_FAIL_FOOTING) | \
                           (1u << SOAK_FAIL_SUPPORT) | (1u << SOAK_FAIL_VELOCITY))
#define SOAK_DIR_TOL      1e-3  ///< direction: largest displacement against the input, m
#define SOAK_PROGRESS_MIN 0.90  ///< progress: share of the input distance covered on free flat floor
#define SOAK_FOOT_TOL     1e-3  ///< footing: foot below the surface under it, m
#define SOAK_CRACK_OPEN   (0.5 * M_PI / 180.0) ///< footing: contacts around the foot leaving no gap wider than 180 degrees + this hold the ball (parallel edges, not a kerb beside the foot)
#define SOAK_LEDGE_GAP    1e-9  ///< footing: contacts whose triangles' vertices leave a gap wider than 180 degrees + this (rad, rounding) around the foot are a ledge beside it, not a crack
#define SOAK_REST_FRAMES  30    ///< support: frames at rest before the body must be grounded
#define SOAK_REST_MOVE    1e-4  ///< support: "at rest" = at most this displacement per frame, m
#define SOAK_VEL_TOL_POS  1e-3  ///< velocity: tolerance, as a displacement over dt (m)
#define SOAK_VEL_TOL_REL  0.02  ///< velocity: or this share of the speed, whichever is larger
#define SOAK_BODY_MAX_DT  0.1f  ///< the body clamps dt to this (CB_MAX_DT)
#define SOAK_BODY_MAX_SPEED 200.0 ///< the body clamps speeds to this (CB_MAX_SPEED)
typedef struct {
    uint64_t frames, hard[SOAK_FAIL_COUNT];
    uint64_t soft_pen_frames;     ///< penetrating frames excused by teleport/up change/movers
    uint64_t wedged_frames;       ///< frames excused as still in the game's overlap: wedged with no room, or in a static collider body (soak_sim_check)
    uint64_t inside_frames;       ///< oracle failures withheld: the step started or ended wholly
                                  ///< inside a closed solid
    uint64_t stuck_events;        ///< excused penetration lasting > SOAK_RECOVER_FRAMES
    uint64_t excused_escapes;     ///< left the room while recovering from an excused overlap
    uint64_t on_floor_frames, steep_frames;
    uint64_t body_pen_frames;     ///< sweep capsule > 1 cm into a static collider body (reported)
    double max_body_pen;
    double max_soft_pen, max_hard_pen;
    /* behaviour oracles: how often each applied (frames checked) */
    uint64_t oracle_frames[SOAK_FAIL_COUNT];
    uint64_t left_level;          ///< loaded levels: left the level's bounds (fell out; reported)
} soak_stats_t;

/** One step's motion as the behaviour oracles see it (soak_sim_step fills it; the tests
 *  build bad ones by hand). Positions are owner positions. */
typedef struct {
    fm_vec3_t pos0, pos1;         ///< before / after the step
    fm_vec3_t vel1;               ///< reported velocity after the step
    fm_vec3_t input;              ///< input_velocity of the step
    float dt;                     ///< the step's dt (valid)
    bool grounded0, steep0;       ///< floor state before the step
    bool excuse;                  ///< teleport, up change, mover near or carried this frame
    bool pen0;                    ///< started overlapping (penetrating or in an excused state)
    double pen_depth;             ///< the start overlap the recover pushes out of (soak_check_pushout_depth), m (under SOAK_PEN_TOL
                                  ///< the body's recover still pushes it out: not motion)
    bool launched;                ///< the velocity along up before the step rose: a jump, not a walk
} soak_motion_t;

typedef struct {
    soak_level_t *lvl;
    char_body_t body;
    fm_vec3_t owner;
    coll_gather_cache_t gather_cache; ///< the body's, when SOAK_GATHER_CACHE=1 in the environment
    double time;
    uint32_t frame;
    bool excused;
    bool escaped;                 ///< left the room after an excused overlap: checks end
    uint32_t excused_frames;
    uint32_t last_teleport, last_up, last_mover; ///< frame numbers of the last excuse events (+1)
    int checks;                   ///< SOAK_CHECKS_* (soak_sim_begin: current)
    uint32_t oracles;             ///< enabled behaviour oracles: bit (1 << SOAK_FAIL_*) (default all)
    uint32_t rest_frames;         ///< support oracle: consecutive frames at rest
    int last_fail;
    double last_pen, last_raw;
    double pen_before;          ///< checker penetration before the last step (diagnosis)
    fm_vec3_t pos_before, vel_before;
    int32_t last_tri;
    char msg[256];
    soak_stats_t st;
} soak_sim_t;

/** Starts a run on an already generated level (animated to t = 0). */
void soak_sim_begin(soak_sim_t *sim, soak_level_t *lvl, const char_body_settings_t *s,
                    fm_vec3_t start);
/** Runs one frame and checks it; returns SOAK_FAIL_* (msg describes a failure). */
int  soak_sim_step(soak_sim_t *sim, const soak_frame_t *f, bool check);
/** The property checks of one frame on the body's current state (soak_sim_step calls it
 *  after the step). excuse: the frame teleported, changed up or had a mover near;
 *  stepped: the step ran (valid dt), so the floor state is fresh. */
int  soak_sim_check(soak_sim_t *sim, bool excuse, bool stepped);
/** The behaviour oracles (checks version 2) on one step's motion and the body's current
 *  state (the state after the step). Returns SOAK_FAIL_* (msg describes a failure). */
int  soak_sim_check_motion(soak_sim_t *sim, const soak_motion_t *m);
/** Footing: how far (m) the foot is below the walkable surface under it beyond the
 *  tolerated sag (0 when not below); the oracle fails above SOAK_FOOT_TOL. */
double soak_check_footing(const soak_level_t *lvl, const char_body_settings_t *s, fm_vec3_t owner);
/** soak_check_footing for a body grounded on a steep surface: faces within the checker's
 *  cosine tolerance of the floor angle (1e-4) count as steep, as the body judged them. */
double soak_check_footing_steep(const soak_level_t *lvl, const char_body_settings_t *s, fm_vec3_t owner);
/** The footing oracle's verdict: soak_check_footing (or _steep), the best of it over the
 *  foot moved across up by float rounding (8 float steps of the owner's largest
 *  coordinate: 2^-20 of it, at least 2^-20 m) in 8 directions. A float foot within
 *  rounding of a tread's edge is on either side of it as the rounding goes (s99 l223). */
double soak_check_footing_rounded(const soak_level_t *lvl, const char_body_settings_t *s, fm_vec3_t owner, bool steep);
extern int32_t soak_footing_tri; ///< triangle (lvl->wtris index) behind the last footing result, -1: none
extern int32_t soak_footing_tri2; ///< the other triangle of its crack pair (case 2), -1: the surface under the foot
extern int soak_footing_ncontacts; ///< contacts around the foot of that crack, 0: the surface under the foot
extern double soak_footing_widest; ///< their widest angular gap across up, rad
/** Progress: whether the checker verifies free, flat, walkable space for the capsule from
 *  owner along disp (across up). */
bool soak_check_free_flat(const soak_level_t *lvl, const char_body_settings_t *s, fm_vec3_t owner, fm_vec3_t disp);
/** Support: whether the full capsule touches (within 1 mm) walkable geometry below its
 *  bottom ball centre, resting on it: the contact normal is within the walkable angle
 *  (not a floor's edge touched with the ball's side). */
bool soak_check_touches_walkable(const soak_level_t *lvl, const char_body_settings_t *s, fm_vec3_t owner);
/** Whether the full capsule could stand somewhere near the body at owner: on a walkable
 *  static triangle within 5 r of the foot across up, snap + 2 r below to step + 2 r above
 *  it, clear of everything (the excuse for a body the game wedged, soak_sim_check). */
bool soak_check_room_to_stand(const soak_level_t *lvl, const char_body_settings_t *s, fm_vec3_t owner);
/** Full and sweep capsules of settings s at owner position owner. */
void soak_capsules_at(const char_body_settings_t *s, fm_vec3_t owner, soak_capsule_t *full, soak_capsule_t *sweep);
/** Prints the body state, the deepest triangle and the library's own overlap view (diagnosis). */
void soak_sim_explain(const soak_sim_t *sim, FILE *out);

/* ------------------------------------------------------------------ replay */
#define SOAK_MAX_EXPECT 4
typedef struct {
    char arch[24];
    char lib[24];                   ///< library source fingerprint the state was stored with
    fm_vec3_t pos, vel;
    int on_floor;
} soak_expect_t;

typedef struct {
    uint64_t level_seed;
    char_body_settings_t settings;
    fm_vec3_t start;
    double t0;                      ///< level time at the start (moving pieces), s
    bool has_vel0, start_clear;     ///< start velocity given; start known to be overlap-free
    fm_vec3_t vel0;
    uint32_t nframes, cap;
    soak_frame_t *frames;           ///< caller-owned, cap entries
    int fail_kind;                  ///< failure recorded when written (informational)
    uint32_t fail_frame;
    int gen;                        ///< generator version (`gen` line; 1 when absent)
    int checks;                     ///< checker version (`checks` line; 1 when absent)
    uint32_t oracles;               ///< `oracles` line: enabled oracle bits (0 / absent: all)
    char level_file[256];           ///< `levelfile` line: a loaded level (.coll; its .raw beside it)
    uint32_t nexpect;
    soak_expect_t expect[SOAK_MAX_EXPECT];
    char note[160];
} soak_replay_t;

/** This build's architecture tag ("x86_64", "mips", ...). */
const char *soak_arch(void);
/** Fingerprint (cksum) of the library sources this harness was built with (mk/soak.mk). */
const char *soak_lib_version(void);

int  soak_replay_write(const char *path, const soak_replay_t *rp);
/** 0 on success; negative on parse error (line number in *err_line). */
int  soak_replay_read(const char *path, soak_replay_t *rp, int *err_line);

/** Result of replaying a file. */
typedef struct {
    int fails;                      ///< hard property failures
    int first_fail_kind;
    uint32_t first_fail_frame;
    char first_msg[256];
    fm_vec3_t pos, vel;
    int on_floor;
    soak_stats_t st;
} soak_replay_result_t;

/** Replays rp on lvl (regenerated from rp->level_seed), checking every frame. */
int soak_replay_run(const soak_replay_t *rp, soak_level_t *lvl, soak_replay_result_t *res);
/** Like soak_replay_run, printing a diagnosis of the first failure to out (may be NULL). */
int soak_replay_run_explain(const soak_replay_t *rp, soak_level_t *lvl, soak_replay_result_t *res, FILE *out);

/** Expected state for this architecture, or NULL. */
const soak_expect_t *soak_replay_expect_for(const soak_replay_t *rp, const char *arch);

#endif
