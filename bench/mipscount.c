/*
 * mipscount: counts guest instructions between marker entries in a qemu exec trace.
 *
 * Run the program under qemu-mips-static -singlestep -d nochain,exec: every executed
 * translation block is then one guest instruction, logged as
 *   Trace 0: 0x7f... [00000000/004005e0/...] symbol
 * (the second field in brackets is the guest pc). This reads that log from stdin and, for
 * every window that starts at the entry of bench_mark_begin and ends at the entry of
 * bench_mark_end, prints the number of instructions executed in between, one per line.
 *
 *   mipscount BEGIN_ADDR END_ADDR < trace
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int main(int argc, char **argv)
{
    if (argc < 3) { fprintf(stderr, "usage: mipscount BEGIN_HEX END_HEX < trace\n"); return 2; }
    unsigned long begin = strtoul(argv[1], NULL, 16), end = strtoul(argv[2], NULL, 16);
    static char line[4096];
    long long n = 0, total = 0;
    int in = 0;
    while (fgets(line, sizeof(line), stdin)) {
        if (strncmp(line, "Trace ", 6) != 0) continue;
        char *p = strchr(line, '[');
        if (!p) continue;
        p = strchr(p, '/');
        if (!p) continue;
        unsigned long pc = strtoul(p + 1, NULL, 16);
        total++;
        if (pc == begin) { in = 1; n = 0; continue; }
        if (in && pc == end) { printf("%lld\n", n); in = 0; continue; }
        if (in) n++;
    }
    fprintf(stderr, "mipscount: %lld instructions traced\n", total);
    return 0;
}
