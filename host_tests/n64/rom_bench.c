/*
 * Console instruction counts of the benchmark scenarios (make bench-n64): bench/bench_main.c
 * unchanged (its main renamed bench_main), run once per scenario as `bench_run cost exact
 * SCENARIO ASSETS CELL` would be, with the markers of bench/bench_hooks.c reading COP0 Count
 * (the emulator runs with CountPerOp = 1: one count per executed instruction). Prints one
 * line per scenario: "BENCH scenario cell window-count window-count ...", raw (the marker
 * overhead, the minimum of the empty windows, is subtracted by bench/n64_console.py).
 */
#include <stdio.h>
#include "rom.h"

int bench_main(int argc, char **argv);
void rom_bench_mark(int end);

#define MAX_WINDOWS 512
static uint32_t t0, windows[MAX_WINDOWS];
static int nwindows;

void rom_bench_mark(int end)
{
    uint32_t now = rom_count();
    if (!end) { t0 = now; return; }
    if (nwindows < MAX_WINDOWS) windows[nwindows++] = now - t0;
}

int main(void)
{
    /* as bench/run.sh: as baked (cell label 0), and baked with a 1 m grid cell request
     * (label 1; the same collbake options) */
    static const struct { const char *scn, *label, *dir; } runs[] = {
        {"empty", "0", "build/assets"},
        {"walk", "0", "build/assets"},      {"walk", "1", "assets_c1"},
        {"stairs", "0", "build/assets"},    {"stairs", "1", "assets_c1"},
        {"vcorner", "0", "build/assets"},   {"vcorner", "1", "assets_c1"},
        {"platform", "0", "build/assets"},  {"platform", "1", "assets_c1"},
        {"crowd32", "0", "build/assets"},   {"crowd32", "1", "assets_c1"},
        {"stairs_real", "0", "build/assets"}, {"crack", "0", "build/assets"},
        {"crowd32_col", "0", "build/assets"},
    };
    int bad = 0;
    for (unsigned i = 0; i < sizeof runs / sizeof runs[0]; i++) {
        char *argv[] = {"bench_run", "cost", "exact", (char *)runs[i].scn, (char *)runs[i].dir, "0", NULL};
        nwindows = 0;
        int rc = bench_main(6, argv);
        if (rc != 0) { printf("BENCH-ERROR %s %s: bench_main returned %d\n", runs[i].scn, runs[i].label, rc); bad++; }
        printf("BENCH %s %s", runs[i].scn, runs[i].label);
        for (int k = 0; k < nwindows; k++) printf(" %lu", (unsigned long)windows[k]);
        printf("\n");
    }
    return bad;
}
