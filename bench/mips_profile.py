#!/usr/bin/env python3
"""Where a scenario's console instructions go: per function (or per source line of one
function), per measured call, from qemu's exec trace of the VR4300-compiled bench.

    qemu-mips-static -singlestep -d nochain,exec -D TRACE bench_run_mips cost exact SCN ASSETS
    mips_profile.py BINARY TRACE [FUNCTION]

Counts only the instructions between bench_mark_begin and bench_mark_end (the measured
calls), like bench/mipscount.c; with FUNCTION, its instructions by source line (needs a
binary built with -g: make bench-mips-profile does that)."""
import bisect, collections, re, subprocess, sys

binary, trace = sys.argv[1], sys.argv[2]
fn = sys.argv[3] if len(sys.argv) > 3 else None
nm = subprocess.run(["mips-linux-gnu-nm", "-n", "--defined-only", binary], capture_output=True, text=True, check=True)
syms = [(int(a, 16), n) for a, t, n in (l.split() for l in nm.stdout.splitlines() if len(l.split()) == 3)
        if t in "tTwW"]
addrs = [a for a, _ in syms]
name_at = {n: a for a, n in syms}
beg, end = name_at["bench_mark_begin"], name_at["bench_mark_end"]
lo = hi = None
if fn:
    if fn not in name_at: sys.exit(f"mips_profile: no function {fn} in {binary}")
    lo = name_at[fn]
    hi = addrs[addrs.index(lo) + 1]
per_fn, per_pc = collections.Counter(), collections.Counter()
on, calls, total = False, 0, 0
pc_re = re.compile(r"\[[0-9a-f]+/([0-9a-f]+)/")
with open(trace) as f:
    for line in f:
        m = pc_re.search(line)
        if not m: continue
        pc = int(m.group(1), 16)
        if pc == beg: on = True; calls += 1; continue
        if pc == end: on = False; continue
        if not on: continue
        total += 1
        if fn:
            if lo <= pc < hi: per_pc[pc] += 1
        else:
            per_fn[syms[bisect.bisect_right(addrs, pc) - 1][1]] += 1
if not calls: sys.exit("mips_profile: no measured call in the trace")
print(f"{calls} measured calls, {total / calls:,.0f} instructions per call")
if fn:
    pcs = sorted(per_pc)
    lines = subprocess.run(["mips-linux-gnu-addr2line", "-e", binary] + [hex(p) for p in pcs],
                           capture_output=True, text=True).stdout.splitlines()
    by_line = collections.Counter()
    for p, l in zip(pcs, lines): by_line[l.rsplit("/", 1)[-1]] += per_pc[p]
    print(f"{fn}: {sum(per_pc.values()) / calls:,.0f} per call")
    for l, c in by_line.most_common(30): print(f"{c / calls:9,.0f}  {l}")
else:
    for n, c in per_fn.most_common(30): print(f"{c / calls:9,.0f}  {n}")
