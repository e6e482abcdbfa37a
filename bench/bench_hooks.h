/**
 * @file bench_hooks.h
 * @brief Out-of-line wrappers around the measured calls. Instruction counters key on them:
 *        callgrind with --toggle-collect=bench_step (etc.), the qemu exec trace on the entry
 *        of bench_mark_begin / bench_mark_end. Kept in their own file so nothing inlines them.
 */
#ifndef BENCH_HOOKS_H
#define BENCH_HOOKS_H
#include "coll/char_body.h"
#include "coll/scene.h"

/** One char_body_move_and_slide_in, bracketed by the markers. */
void bench_step(char_body_t *b, const coll_scene_t *s, float dt);
/** n bodies, one frame (the crowd scenario): the whole frame is one measured window. */
void bench_frame(char_body_t *b, int n, const coll_scene_t *s, float dt);
/** One raycast, bracketed by the markers. */
bool bench_ray(const coll_scene_t *s, fm_vec3_t o, fm_vec3_t d, float max_dist, coll_ray_hit_t *hit);
/** Empty window: its count is the markers' own overhead, subtracted by the counter. */
void bench_empty(void);
void bench_mark_begin(void);
void bench_mark_end(void);
#endif
