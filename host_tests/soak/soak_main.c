/* Soak program: random levels, random settings, random play, every frame checked by an
 * independent double-precision checker. On a failure it prints seed/level/frame and writes
 * a replay file that `make soak-replay REPLAY=path` (or `soak --replay path`) reproduces.
 *
 *   soak [--frames N] [--seed S] [--out DIR] [--max-replays N] [--level-frames N] [-v]
 *        [--save-passing N]   also write the first N levels that pass as baseline replays
 *        [--known DIR]        failures on levels of DIR's replays (open bugs) do not fail
 *        [--known-kinds FILE] nor failures of the kinds listed in FILE (open bug classes)
 *        [--gen N]            generator version (default: the current one, SOAK_GEN_CURRENT)
 *        [--oracles LIST]     behaviour oracles to run, comma-separated (direction, progress,
 *                             footing, support, velocity; default all)
 *        [--checks N]         checker version (1: state checks only; default: with the
 *                             behaviour oracles, SOAK_CHECKS_CURRENT)
 *   soak --level FILE.coll [--bodies N] [--frames N] [--seed S] ...
 *                        a baked level (its collbake --dump-raw FILE.raw beside it is the
 *                        checker's copy): N bodies, one after another, each with random
 *                        settings of a human-sized character, a spawn point and random
 *                        walking and jumping, frames/N frames each, under the same checks
 *        [--trace L]          print the body's state every frame of level (body) L
 *        [--shrink-min N]     a shrunk failing replay holds at least N frames (to see the
 *                             steps before the failing one)
 *   soak --replay FILE [--bless]     replay one file (bless: store this arch's final state)
 *   soak --replay-dir DIR            replay every *.replay in DIR
 *
 * Exit status: 0 when no hard property failure was seen, 1 otherwise, 2 on usage/IO errors.
 */
#define _FILE_OFFSET_BITS 64 /* 32-bit MIPS under qemu: readdir with 64-bit directory offsets */
#include "soak_sim.h"
#include <dirent.h>
#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>

#define MAX_LEVEL_FRAMES 4000

static soak_level_t g_level;
static soak_sim_t g_sim;
static soak_frame_t g_frames[MAX_LEVEL_FRAMES];

/* Body state before each frame, for shrinking a failing replay. */
typedef struct { fm_vec3_t owner, vel, up; double time; bool excused; } state_t;
static state_t g_state[MAX_LEVEL_FRAMES];

/* Shortest suffix of the level's frames (1, 2, 4, ... frames, starting from the recorded
 * state: position, velocity, up, level time) that still fails the same way. Fills rp
 * (frames point into g_frames); returns false when only the full replay reproduces. */
static int g_gen = SOAK_GEN_CURRENT, g_checks = SOAK_CHECKS_CURRENT;
static const char *g_level_file;
static uint32_t g_oracles = SOAK_ORACLES_ALL;
static uint32_t g_shrink_min = 1; /* --shrink-min N: a shrunk replay holds at least N frames */

/* --oracles direction,progress,...: the behaviour oracles to run (default all) */
static int parse_oracles(const char *v)
{
    uint32_t m = 0;
    char buf[256];
    snprintf(buf, sizeof buf, "%s", v);
    for (char *t = strtok(buf, ","); t; t = strtok(NULL, ",")) {
        int k = -1;
        for (int i = SOAK_FAIL_DIRECTION; i < SOAK_FAIL_COUNT; i++)
            if (!strcmp(t, soak_fail_name(i))) k = i;
        if (!strcmp(t, "all")) { m |= SOAK_ORACLES_ALL; continue; }
        if (k < 0) { fprintf(stderr, "ERROR: --oracles: unknown oracle '%s'\n", t); return -1; }
        m |= 1u << k;
    }
    g_oracles = m;
    return 0;
}

static void replay_header(soak_replay_t *rp, uint64_t lseed)
{
    rp->level_seed = lseed;
    rp->gen = g_gen;
    rp->checks = g_checks;
    rp->oracles = g_oracles;
    if (g_level_file) snprintf(rp->level_file, sizeof rp->level_file, "%s", g_level_file);
}

static bool shrink(uint64_t lseed, const char_body_settings_t *s, fm_vec3_t start, uint32_t fail_frame, int kind,
                   soak_replay_t *rp)
{
    for (uint32_t k = g_shrink_min ? g_shrink_min : 1; k <= fail_frame; k *= 2) {
        uint32_t first = fail_frame + 1 - k;
        const state_t *st = &g_state[first];
        if (st->excused) continue; /* the shrunk start must be overlap-free */
        memset(rp, 0, sizeof *rp);
        replay_header(rp, lseed);
        rp->settings = *s;
        rp->settings.up = st->up;
        rp->start = st->owner;
        rp->t0 = st->time;
        rp->vel0 = st->vel;
        rp->has_vel0 = true;
        rp->start_clear = true;
        rp->frames = &g_frames[first];
        rp->nframes = k;
        rp->cap = k;
        soak_replay_result_t res;
        if (soak_replay_run(rp, &g_level, &res) == 0 && res.fails > 0 && res.first_fail_kind == kind &&
            res.first_fail_frame == k - 1)
            return true;
    }
    memset(rp, 0, sizeof *rp);
    replay_header(rp, lseed);
    rp->settings = *s;
    rp->start = start;
    rp->frames = g_frames;
    rp->nframes = fail_frame + 1;
    return false;
}

/* Level seeds of the open-bug replays (--known DIR): failures there are reported as known. */
#define MAX_KNOWN 512
static uint64_t known_seeds[MAX_KNOWN];
static unsigned nknown;

static int load_known(const char *dir)
{
    static soak_frame_t scratch[1u << 13];
    DIR *d = opendir(dir);
    if (!d) return 0; /* no open bugs */
    struct dirent *de;
    char path[1024];
    while ((de = readdir(d)) != NULL && nknown < MAX_KNOWN) {
        size_t l = strlen(de->d_name);
        if (l < 8 || strcmp(de->d_name + l - 7, ".replay") != 0) continue;
        snprintf(path, sizeof path, "%s/%s", dir, de->d_name);
        soak_replay_t rp;
        rp.frames = scratch;
        rp.cap = sizeof scratch / sizeof scratch[0];
        int line = 0;
        if (soak_replay_read(path, &rp, &line) != 0) {
            fprintf(stderr, "ERROR: %s:%d: cannot parse replay\n", path, line);
            closedir(d);
            return -1;
        }
        known_seeds[nknown++] = rp.level_seed;
    }
    closedir(d);
    return 0;
}

/* Failure kinds with open bugs (--known-kinds FILE: one kind name per line, # comments). */
static bool known_kind[SOAK_FAIL_COUNT];

static int load_known_kinds(const char *path)
{
    FILE *f = fopen(path, "r");
    if (!f) return 0; /* no file: no kind is known */
    char line[128];
    while (fgets(line, sizeof line, f)) {
        char *p = line;
        while (*p == ' ' || *p == '\t') p++;
        size_t n = strcspn(p, " \t\r\n#");
        if (n == 0) continue;
        p[n] = 0;
        int k = -1;
        for (int i = 1; i < SOAK_FAIL_COUNT; i++)
            if (strcmp(p, soak_fail_name(i)) == 0) k = i;
        if (k < 0) { fprintf(stderr, "ERROR: %s: unknown failure kind '%s'\n", path, p); fclose(f); return -1; }
        known_kind[k] = true;
    }
    fclose(f);
    return 0;
}

static bool is_known(uint64_t lseed)
{
    for (unsigned i = 0; i < nknown; i++)
        if (known_seeds[i] == lseed) return true;
    return false;
}

static void usage(void)
{
    fprintf(stderr, "usage: soak [--frames N] [--seed S] [--out DIR] [--max-replays N] [--level-frames N]\n"
                    "            [--save-passing N] [--known DIR] [--known-kinds FILE] [-v]\n"
                    "       soak --replay FILE [--bless]\n"
                    "       soak --replay-dir DIR\n");
}

static void add_stats(soak_stats_t *a, const soak_stats_t *b)
{
    a->frames += b->frames;
    for (int k = 0; k < SOAK_FAIL_COUNT; k++) a->hard[k] += b->hard[k];
    a->soft_pen_frames += b->soft_pen_frames;
    a->wedged_frames += b->wedged_frames;
    a->inside_frames += b->inside_frames;
    a->stuck_events += b->stuck_events;
    a->excused_escapes += b->excused_escapes;
    a->body_pen_frames += b->body_pen_frames;
    if (b->max_body_pen > a->max_body_pen) a->max_body_pen = b->max_body_pen;
    a->on_floor_frames += b->on_floor_frames;
    for (int k = 0; k < SOAK_FAIL_COUNT; k++) a->oracle_frames[k] += b->oracle_frames[k];
    a->left_level += b->left_level;
    a->steep_frames += b->steep_frames;
    if (b->max_soft_pen > a->max_soft_pen) a->max_soft_pen = b->max_soft_pen;
    if (b->max_hard_pen > a->max_hard_pen) a->max_hard_pen = b->max_hard_pen;
}

static void print_stats(const char *what, const soak_stats_t *st, uint64_t levels, double secs)
{
    uint64_t hard = 0;
    for (int k = 1; k < SOAK_FAIL_COUNT; k++) hard += st->hard[k];
    printf("%s: %llu frames, %llu levels, %llu hard failures (", what, (unsigned long long)st->frames,
           (unsigned long long)levels, (unsigned long long)hard);
    for (int k = 1; k < SOAK_FAIL_COUNT; k++)
        printf("%s%s %llu", k > 1 ? ", " : "", soak_fail_name(k), (unsigned long long)st->hard[k]);
    printf(")\n%s: behaviour oracles applied on (frames):", what);
    for (int k = SOAK_FAIL_DIRECTION; k < SOAK_FAIL_COUNT; k++)
        printf(" %s %llu", soak_fail_name(k), (unsigned long long)st->oracle_frames[k]);
    if (st->left_level) printf("; fell out of the level's bounds: %llu", (unsigned long long)st->left_level);
    printf("; oracle failures withheld inside a closed solid: %llu\n", (unsigned long long)st->inside_frames);
    printf("%s: excused penetration frames %llu (teleport/up change/mover; max %.1f mm), stuck >%d frames: %llu, "
           "left the room while recovering: %llu, on floor %.1f%%, steep %.1f%%",
           what, (unsigned long long)st->soft_pen_frames, st->max_soft_pen * 1000.0, SOAK_RECOVER_FRAMES,
           (unsigned long long)st->stuck_events, (unsigned long long)st->excused_escapes, st->frames ? 100.0 * (double)st->on_floor_frames / (double)st->frames : 0.0,
           st->frames ? 100.0 * (double)st->steep_frames / (double)st->frames : 0.0);
    if (st->wedged_frames) printf(", still in the game's overlap (wedged, in a body) %llu", (unsigned long long)st->wedged_frames);
    if (secs > 0) printf(", %.0f frames/s", (double)st->frames / secs);
    printf("\n");
    printf("%s: reported only: frames with the sweep capsule > 1 cm inside a static collider body: %llu (max %.1f mm)\n",
           what, (unsigned long long)st->body_pen_frames, st->max_body_pen * 1000.0);
    const coll_query_stats_t *q = &soak_query_stats;
    printf("%s: queries: %lu steps gathered, %lu gather overflows (%.2f per 1000 steps), %lu dedup overflows, "
           "%lu queries outside the gathered box (run on the scene)\n", what, (unsigned long)q->gathers,
           (unsigned long)q->gather_overflows, q->gathers ? 1000.0 * (double)q->gather_overflows / (double)q->gathers : 0.0,
           (unsigned long)q->dedup_overflows, (unsigned long)q->gather_misses);
}

static int replay_one(const char *path, bool bless, bool verbose)
{
    static soak_frame_t frames[1u << 16];
    soak_replay_t rp;
    rp.frames = frames;
    rp.cap = sizeof frames / sizeof frames[0];
    int line = 0;
    int rc = soak_replay_read(path, &rp, &line);
    if (rc != 0) { fprintf(stderr, "ERROR: %s:%d: cannot parse replay (%d)\n", path, line, rc); return 2; }
    soak_replay_result_t res;
    if (soak_replay_run_explain(&rp, &g_level, &res, verbose ? stdout : NULL) != 0) {
        fprintf(stderr, "ERROR: %s: level 0x%016llx does not build\n", path, (unsigned long long)rp.level_seed);
        return 2;
    }
    int bad = 0;
    if (res.fails) {
        printf("%s: FAIL %d hard failure(s); first at frame %u: %s: %s\n", path, res.fails,
               (unsigned)res.first_fail_frame, soak_fail_name(res.first_fail_kind), res.first_msg);
        bad = 1;
    }
    const soak_expect_t *e = soak_replay_expect_for(&rp, soak_arch());
    if (e && strcmp(e->lib, soak_lib_version()) != 0) {
        printf("%s: stored %s state is from library %s, this is %s: not compared (make soak-bless)\n", path,
               soak_arch(), e->lib, soak_lib_version());
        e = NULL;
    }
    if (e) {
        bool same = memcmp(&e->pos, &res.pos, sizeof e->pos) == 0 && memcmp(&e->vel, &res.vel, sizeof e->vel) == 0 &&
                    e->on_floor == res.on_floor;
        if (!same) {
            printf("%s: FAIL final state differs from the stored %s state: pos %a %a %a (stored %a %a %a)\n", path,
                   soak_arch(), (double)res.pos.x, (double)res.pos.y, (double)res.pos.z, (double)e->pos.x,
                   (double)e->pos.y, (double)e->pos.z);
            bad = 1;
        }
    }
    if (!bad || verbose)
        printf("%s: %s, %u frames, final pos %a %a %a vel %a %a %a floor %d%s\n", path, bad ? "FAILED" : "ok",
               (unsigned)rp.nframes, (double)res.pos.x, (double)res.pos.y, (double)res.pos.z, (double)res.vel.x,
               (double)res.vel.y, (double)res.vel.z, res.on_floor, e ? " (matches stored state bitwise)" : "");
    if (bless) {
        if (res.fails) { fprintf(stderr, "ERROR: %s: not blessing a replay that fails\n", path); return 1; }
        soak_expect_t *slot = (soak_expect_t *)soak_replay_expect_for(&rp, soak_arch());
        if (!slot) {
            if (rp.nexpect >= SOAK_MAX_EXPECT) { fprintf(stderr, "ERROR: %s: too many expect lines\n", path); return 2; }
            slot = &rp.expect[rp.nexpect++];
            snprintf(slot->arch, sizeof slot->arch, "%s", soak_arch());
        }
        snprintf(slot->lib, sizeof slot->lib, "%s", soak_lib_version());
        slot->pos = res.pos;
        slot->vel = res.vel;
        slot->on_floor = res.on_floor;
        rp.fail_kind = 0;
        if (soak_replay_write(path, &rp) != 0) { fprintf(stderr, "ERROR: %s: cannot write\n", path); return 2; }
        printf("%s: stored the %s final state\n", path, soak_arch());
        return 0;
    }
    return bad;
}

static int replay_dir(const char *dir)
{
    DIR *d = opendir(dir);
    if (!d) { fprintf(stderr, "ERROR: %s: %s\n", dir, strerror(errno)); return 2; }
    struct dirent *de;
    int worst = 0, n = 0;
    char path[1024];
    while ((de = readdir(d)) != NULL) {
        size_t l = strlen(de->d_name);
        if (l < 8 || strcmp(de->d_name + l - 7, ".replay") != 0) continue;
        snprintf(path, sizeof path, "%s/%s", dir, de->d_name);
        int rc = replay_one(path, false, true);
        if (rc > worst) worst = rc;
        n++;
    }
    closedir(d);
    printf("%d replay(s) in %s\n", n, dir);
    return worst;
}

int main(int argc, char **argv)
{
    uint64_t frames = 100000, seed = 1;
    const char *out = "build/soak-failures", *replay = NULL, *rdir = NULL;
    unsigned max_replays = 20, level_frames = 0, save_passing = 0, saved = 0, bodies = 16;
    bool bless = false, verbose = false;
    long trace_level = -1; /* --trace L: print the body state of level (or body) L every frame */
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i];
        const char *v = i + 1 < argc ? argv[i + 1] : NULL;
        if (!strcmp(a, "--frames") && v) { frames = strtoull(v, NULL, 0); i++; }
        else if (!strcmp(a, "--seed") && v) { seed = strtoull(v, NULL, 0); i++; }
        else if (!strcmp(a, "--out") && v) { out = v; i++; }
        else if (!strcmp(a, "--max-replays") && v) { max_replays = (unsigned)strtoul(v, NULL, 0); i++; }
        else if (!strcmp(a, "--level-frames") && v) { level_frames = (unsigned)strtoul(v, NULL, 0); i++; }
        else if (!strcmp(a, "--replay") && v) { replay = v; i++; }
        else if (!strcmp(a, "--replay-dir") && v) { rdir = v; i++; }
        else if (!strcmp(a, "--known") && v) { if (load_known(v) != 0) return 2; i++; }
        else if (!strcmp(a, "--known-kinds") && v) { if (load_known_kinds(v) != 0) return 2; i++; }
        else if (!strcmp(a, "--save-passing") && v) { save_passing = (unsigned)strtoul(v, NULL, 0); i++; }
        else if (!strcmp(a, "--gen") && v) { g_gen = (int)strtol(v, NULL, 0); i++; }
        else if (!strcmp(a, "--checks") && v) { g_checks = (int)strtol(v, NULL, 0); i++; }
        else if (!strcmp(a, "--oracles") && v) { if (parse_oracles(v) != 0) return 2; i++; }
        else if (!strcmp(a, "--level") && v) { g_level_file = v; i++; }
        else if (!strcmp(a, "--bodies") && v) { bodies = (unsigned)strtoul(v, NULL, 0); i++; }
        else if (!strcmp(a, "--shrink-min") && v) { g_shrink_min = (uint32_t)strtoul(v, NULL, 0); i++; }
        else if (!strcmp(a, "--trace") && v) { trace_level = strtol(v, NULL, 0); i++; }
        else if (!strcmp(a, "--bless")) bless = true;
        else if (!strcmp(a, "-v")) verbose = true;
        else { usage(); return 2; }
    }
    if (replay) return replay_one(replay, bless, true);
    if (rdir) return replay_dir(rdir);
    if (g_gen < SOAK_GEN_V1 || g_gen > SOAK_GEN_CURRENT || g_checks < SOAK_CHECKS_V1 || g_checks > SOAK_CHECKS_CURRENT) {
        fprintf(stderr, "ERROR: --gen 1..%d, --checks 1..%d\n", SOAK_GEN_CURRENT, SOAK_CHECKS_CURRENT);
        return 2;
    }
    if (g_level_file) {
        char raw[1024], err[300];
        size_t n = strlen(g_level_file);
        if (n > 5 && strcmp(g_level_file + n - 5, ".coll") == 0) n -= 5;
        snprintf(raw, sizeof raw, "%.*s.raw", (int)n, g_level_file);
        if (soak_level_load(&g_level, g_level_file, raw, err, sizeof err) != 0) { fprintf(stderr, "%s\n", err); return 2; }
        if (bodies == 0) bodies = 1;
        if (!level_frames) level_frames = (unsigned)(frames / bodies < MAX_LEVEL_FRAMES ? frames / bodies : MAX_LEVEL_FRAMES);
        if (level_frames == 0) level_frames = 1;
        printf("soak: level %s: %u triangles, bounds (%.1f %.1f %.1f) .. (%.1f %.1f %.1f)\n", g_level_file,
               (unsigned)g_level.nwtris, g_level.lo[0], g_level.lo[1], g_level.lo[2], g_level.hi[0], g_level.hi[1],
               g_level.hi[2]);
    }
    if (level_frames > MAX_LEVEL_FRAMES) level_frames = MAX_LEVEL_FRAMES;

    printf("soak: seed %llu, %llu frames, arch %s, generator %d, checks %d\n", (unsigned long long)seed,
           (unsigned long long)frames, soak_arch(), g_gen, g_checks);
    fflush(stdout);
    soak_stats_t total;
    memset(&total, 0, sizeof total);
    uint64_t levels = 0, gen_errors = 0, failures = 0, known = 0, known_by_kind[SOAK_FAIL_COUNT] = {0};
    unsigned written = 0;
    clock_t t0 = clock();
    for (uint64_t li = 0; total.frames < frames; li++) {
        uint64_t lseed = soak_mix64(seed * 0x100000001B3ull + li);
        int grc = g_level_file ? 0 : soak_level_generate_v(&g_level, lseed, g_gen);
        if (grc != 0) {
            gen_errors++;
            fprintf(stderr, "ERROR: level 0x%016llx does not build (%d)\n", (unsigned long long)lseed, grc);
            if (gen_errors > 10) return 2;
            continue;
        }
        levels++;
        soak_rng_t r;
        soak_rng_seed(&r, soak_mix64(lseed ^ 0x5E77ull));
        char_body_settings_t s;
        fm_vec3_t start;
        soak_settings_random(&r, &s, &start);
        if (g_level_file) {
            /* a human-sized character, +Y up, on a spawn point */
            s = CHAR_BODY_SETTINGS_DEFAULT;
            s.radius = (float)soak_rng_range(&r, 0.3, 0.5);
            s.height = (float)soak_rng_range(&r, 1.6, 2.0);
            double inner = 0.5 * (double)s.height - s.radius, step = soak_rng_range(&r, 0.15, 0.45);
            s.step_height = (float)(step < inner ? step : inner);
            s.floor_snap_distance = s.step_height + (float)soak_rng_range(&r, 0.0, 0.2);
            s.floor_max_angle = (float)(soak_rng_range(&r, 40, 50) * 3.14159265358979323846 / 180.0);
            s.gravity = (float)soak_rng_range(&r, 20, 40);
            s.max_slides = (uint8_t)(2 + soak_rng_below(&r, 5));
            if (soak_rng_chance(&r, 0.5)) s.center_offset.y = 0.5f * s.height;
            start = soak_level_spawn(&r, &g_level, &s);
        }
        uint64_t n = level_frames ? level_frames : 500 + soak_rng_below(&r, MAX_LEVEL_FRAMES - 500);
        if (n > frames - total.frames) n = frames - total.frames;
        soak_play_t play;
        soak_play_init(&play, lseed);
        if (g_level_file) { play.gentle = true; play.base_dt = soak_rng_chance(&r, 0.5) ? 1.0f / 60 : 1.0f / 30; }
        soak_sim_begin(&g_sim, &g_level, &s, start);
        uint64_t level_known[SOAK_FAIL_COUNT] = {0};
        g_sim.checks = g_checks;
        g_sim.oracles = g_oracles;
        for (uint32_t i = 0; i < n; i++) {
            soak_play_next(&play, &g_level, &s, g_sim.owner, &g_frames[i]);
            g_state[i].owner = g_sim.owner;
            g_state[i].vel = char_body_get_velocity(&g_sim.body);
            g_state[i].up = g_sim.body.settings.up;
            g_state[i].time = g_sim.time;
            g_state[i].excused = g_sim.excused;
            int k = soak_sim_step(&g_sim, &g_frames[i], true);
            if (trace_level >= 0 && (uint64_t)trace_level == li)
                printf("  trace %u: pos %.4f %.4f %.4f vel %.3f %.3f %.3f floor %d id %d input %.2f %.2f dt %.4f\n", (unsigned)i,
                       (double)g_sim.owner.x, (double)g_sim.owner.y, (double)g_sim.owner.z, (double)g_sim.body.velocity.x,
                       (double)g_sim.body.velocity.y, (double)g_sim.body.velocity.z, char_body_is_on_floor(&g_sim.body),
                       (int)char_body_floor_id(&g_sim.body), (double)g_frames[i].input.x, (double)g_frames[i].input.z,
                       (double)g_frames[i].dt);
            if (k == SOAK_FAIL_NONE) {
                if (g_sim.escaped && g_level_file) { /* fell out of the level */
                    if (verbose)
                        printf("  body %llu fell out of the level at frame %u, from (%.2f %.2f %.2f), start (%.2f %.2f %.2f)\n",
                               (unsigned long long)li, (unsigned)i, (double)g_state[i].owner.x, (double)g_state[i].owner.y,
                               (double)g_state[i].owner.z, (double)start.x, (double)start.y, (double)start.z);
                    n = i + 1;
                    break;
                }
                continue;
            }
            if (is_known(lseed) || known_kind[k]) {
                known++;
                known_by_kind[k]++;
                if (!level_known[k]++)
                    printf("KNOWN (%s) seed %llu level %llu (level seed 0x%016llx) frame %u: %s: %s\n",
                           is_known(lseed) ? "open replay" : "open kind", (unsigned long long)seed,
                           (unsigned long long)li, (unsigned long long)lseed, (unsigned)i, soak_fail_name(k), g_sim.msg);
                /* a behaviour oracle's verdict leaves the state sound: keep running the
                 * level so that the other checks still cover it (only the first KNOWN line
                 * per kind and level is printed) */
                if (!is_known(lseed) && k >= SOAK_FAIL_DIRECTION) continue;
                break;
            }
            failures++;
            printf("FAIL seed %llu level %llu (level seed 0x%016llx) frame %u: %s: %s\n", (unsigned long long)seed,
                   (unsigned long long)li, (unsigned long long)lseed, (unsigned)i, soak_fail_name(k), g_sim.msg);
            if (written < max_replays) {
                char msg[sizeof g_sim.msg];
                memcpy(msg, g_sim.msg, sizeof msg);
                soak_replay_t rp;
                bool shrunk = shrink(lseed, &s, start, i, k, &rp);
                memcpy(g_sim.msg, msg, sizeof msg);
                rp.fail_kind = k;
                snprintf(rp.note, sizeof rp.note, "soak seed %llu level %llu frame %u%s: %s: %.80s",
                         (unsigned long long)seed, (unsigned long long)li, (unsigned)i,
                         shrunk ? " (shrunk to the last frames)" : "", soak_fail_name(k), g_sim.msg);
                rp.fail_frame = rp.nframes - 1;
                mkdir(out, 0777);
                char path[1024];
                snprintf(path, sizeof path, "%s/soak_s%llu_l%llu_%s.replay", out, (unsigned long long)seed,
                         (unsigned long long)li, soak_fail_name(k));
                if (soak_replay_write(path, &rp) == 0) {
                    written++;
                    printf("  replay: %s   (reproduce: make soak-replay REPLAY=%s)\n", path, path);
                } else {
                    fprintf(stderr, "ERROR: cannot write %s\n", path);
                }
            }
            break; /* one failure per level: the state after it is suspect */
        }
        if (saved < save_passing && g_sim.last_fail == SOAK_FAIL_NONE && n > 0) {
            /* a passing level as a baseline replay (bless it to store its final state) */
            soak_replay_t rp;
            memset(&rp, 0, sizeof rp);
            replay_header(&rp, lseed);
            rp.settings = s;
            rp.start = start;
            rp.nframes = (uint32_t)n;
            rp.frames = g_frames;
            snprintf(rp.note, sizeof rp.note, "baseline: soak seed %llu level %llu, %u frames without failure",
                     (unsigned long long)seed, (unsigned long long)li, (unsigned)n);
            mkdir(out, 0777);
            char path[1024];
            snprintf(path, sizeof path, "%s/base_s%llu_l%llu.replay", out, (unsigned long long)seed,
                     (unsigned long long)li);
            if (soak_replay_write(path, &rp) == 0) { saved++; printf("  saved passing level: %s\n", path); }
        }
        add_stats(&total, &g_sim.st);
        if (verbose && levels % 50 == 0) print_stats("progress", &total, levels, 0);
        fflush(stdout);
    }
    double secs = (double)(clock() - t0) / CLOCKS_PER_SEC;
    print_stats("soak", &total, levels, secs);
    if (known) {
        printf("soak: known (open) failures by kind, frames:");
        for (int k = 1; k < SOAK_FAIL_COUNT; k++)
            if (known_by_kind[k]) printf(" %s %llu", soak_fail_name(k), (unsigned long long)known_by_kind[k]);
        printf("\n");
    }
    printf("soak: %s (%llu new failing level(s), %llu known open, %u replay(s) written to %s)\n",
           failures ? "FAILED" : "PASSED", (unsigned long long)failures, (unsigned long long)known, written, out);
    return failures ? 1 : 0;
}
