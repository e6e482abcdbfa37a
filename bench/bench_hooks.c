/* Measured-call wrappers and trace markers. See bench_hooks.h. */
#include "bench_hooks.h"

/* The asm keeps the compiler from treating the markers as pure (and removing the calls).
 * The console test ROM (mk/n64bench.mk) builds this file with BENCH_MARK_HOOK naming a
 * function that reads COP0 Count at each marker. */
#ifdef BENCH_MARK_HOOK
void BENCH_MARK_HOOK(int end);
#define BENCH_MARK(end) BENCH_MARK_HOOK(end)
#else
#define BENCH_MARK(end) __asm__ volatile("" ::: "memory")
#endif
__attribute__((noinline)) void bench_mark_begin(void) { BENCH_MARK(0); }
__attribute__((noinline)) void bench_mark_end(void) { BENCH_MARK(1); }

__attribute__((noinline)) void bench_step(char_body_t *b, const coll_scene_t *s, float dt)
{
    bench_mark_begin();
    char_body_move_and_slide_in(b, s, dt);
    bench_mark_end();
}

__attribute__((noinline)) void bench_frame(char_body_t *b, int n, const coll_scene_t *s, float dt)
{
    bench_mark_begin();
    for (int i = 0; i < n; i++) char_body_move_and_slide_in(&b[i], s, dt);
    bench_mark_end();
}

__attribute__((noinline)) bool bench_ray(const coll_scene_t *s, fm_vec3_t o, fm_vec3_t d, float max_dist,
                                         coll_ray_hit_t *hit)
{
    bench_mark_begin();
    bool r = coll_raycast(s, o, d, max_dist, 0xFF, COLL_TYPE_ALL, hit);
    bench_mark_end();
    return r;
}

__attribute__((noinline)) void bench_empty(void)
{
    bench_mark_begin();
    bench_mark_end();
}
