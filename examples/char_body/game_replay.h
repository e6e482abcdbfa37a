/**
 * @file game_replay.h
 * @brief Scripted input for the char_body example: a small autopilot that plays a text
 *        script of timed commands by steering towards waypoints (not raw sticks), so the
 *        replay survives small physics changes. Platform-independent, no allocation.
 *
 * Script, one command per line, '#' starts a comment:
 *   walk_to X Z [SPEED]          steer to (X, Z) (ground plane) at SPEED m/s (run speed)
 *   push X Z S [SPEED]           steer towards (X, Z) for S seconds, arriving or not
 *   jump [HOLD]                  press jump, hold it HOLD s (0.5); next command starts at once
 *   coyote_jump X Z [DELAY]      run towards (X, Z); DELAY s (0.07) after leaving the floor, jump
 *   land_jump [H]                in the air, press jump once falling with the ground H m (0.4)
 *                                below the feet: the game buffers it and jumps on landing
 *   wait S                       stand still S seconds
 *   board N [DX DZ]              walk onto platform N (at local offset DX, DZ) until on it
 *   ride N S [DX DZ]             board N, then stand still on it for S seconds
 *   wait_phase N FROM TO         stand still until platform N's cycle phase (0..1) is in [FROM, TO)
 *   gravity planet|normal        press the gravity toggle if the mode differs
 *   planet_lap [SPEED]           walk one great circle round the planet (current heading)
 *   drop                         press the drop button (through the one-way platform stood on)
 *   mark NAME                    record a named moment (the test and the status lines use it)
 */
#ifndef CHAR_BODY_EXAMPLE_GAME_REPLAY_H
#define CHAR_BODY_EXAMPLE_GAME_REPLAY_H

#include "game.h"

#ifdef __cplusplus
extern "C" {
#endif

#define REPLAY_MAX_COMMANDS 160
#define REPLAY_MAX_MARKS 48
#define REPLAY_NAME_LEN 24

typedef enum {
    REPLAY_WALK_TO = 0, REPLAY_JUMP, REPLAY_COYOTE_JUMP, REPLAY_WAIT, REPLAY_BOARD, REPLAY_RIDE,
    REPLAY_WAIT_PHASE, REPLAY_GRAVITY, REPLAY_PLANET_LAP, REPLAY_MARK, REPLAY_PUSH, REPLAY_LAND_JUMP,
    REPLAY_DROP,
} replay_op_t;

typedef struct {
    replay_op_t op;
    float a[5];                 ///< numeric arguments in script order
    char name[REPLAY_NAME_LEN]; ///< mark name / word argument
    uint16_t line;              ///< script line, for messages
} replay_cmd_t;

/** A recorded `mark`. */
typedef struct {
    char name[REPLAY_NAME_LEN];
    float time;
    fm_vec3_t pos;
    int state;          ///< game_body_state(): CHAR_BODY_AIRBORNE, _ON_FLOOR, _ON_STEEP
    int32_t floor_id;
} replay_mark_t;

typedef struct {
    replay_cmd_t cmds[REPLAY_MAX_COMMANDS];
    uint16_t count;
    uint16_t pc;          ///< current command
    float cmd_time;       ///< seconds in the current command
    float jump_hold;      ///< seconds the jump button stays held
    float sub_time;       ///< per-command scratch timer
    int sub_state;        ///< per-command phase
    fm_vec3_t lap_axis;   ///< planet lap: great-circle normal
    fm_vec3_t lap_prev;   ///< planet lap: last radial direction
    float lap_angle;      ///< planet lap: radians walked
    float stuck_time;     ///< seconds steering hard without moving (blocked)
    float detour_time;    ///< seconds left of a sidestep round an obstacle
    float detour_sign;    ///< side of the next sidestep (+1 / -1, alternating)
    uint32_t detours;     ///< sidesteps taken
    bool gravity_press;   ///< toggle held this frame
    uint32_t timeouts;    ///< commands abandoned after their time limit
    uint16_t timeout_line;///< script line of the first timeout
    uint32_t laps;        ///< planet laps completed
    uint16_t mark_count;
    replay_mark_t marks[REPLAY_MAX_MARKS];
    int error_line;       ///< parse error line, 0 when none
} replay_t;

/** Parses a script (not NUL-terminated: len bytes). Returns false on a syntax error
 *  (error_line says where). */
bool replay_parse(replay_t *r, const char *text, uint32_t len);
/** Input for this frame; advances commands. */
void replay_input(replay_t *r, const game_t *g, game_input_t *in, float dt);
/** True once every command has finished. */
bool replay_done(const replay_t *r);
/** Name of the current command (for status lines). */
const char *replay_op_name(replay_op_t op);
/** The mark with this name, or NULL. */
const replay_mark_t *replay_find_mark(const replay_t *r, const char *name);

#ifdef __cplusplus
}
#endif
#endif
