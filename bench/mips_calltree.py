#!/usr/bin/env python3
"""The call tree of one measured step of a scenario, from qemu's exec trace of the
VR4300-compiled bench (inclusive and self instructions per call path).

    make bench-mips-profile SCN=stairs_real        (writes build/benchprof/trace.txt)
    mips_calltree.py BINARY TRACE STEP [DEPTH] [SPLIT,FUNCTIONS]

STEP counts the measured calls from 0 (bench_mark_begin .. bench_mark_end, as
bench/mipscount.c and bench/mips_profile.py count them). A call is the entry of a function's
first instruction from another function; a return is the first instruction back in a
function on the stack (tail calls and code shared between functions can misplace a few
instructions). Calls of one function under one parent are summed into one line ("xN") except
for the functions in SPLIT (default sweep_tri, overlap_tri, coll_ray_triangle_sheared), each
of whose calls gets a line of its own (#0, #1, ... in call order): which candidate triangle
test cost what."""
import bisect, collections, re, subprocess, sys

binary, trace, step = sys.argv[1], sys.argv[2], int(sys.argv[3])
maxd = int(sys.argv[4]) if len(sys.argv) > 4 else 8
split = set((sys.argv[5] if len(sys.argv) > 5 else "sweep_tri,overlap_tri,coll_ray_triangle_sheared").split(","))
nm = subprocess.run(["mips-linux-gnu-nm", "-n", "--defined-only", binary], capture_output=True, text=True, check=True)
syms = [(int(a, 16), n) for a, t, n in (l.split() for l in nm.stdout.splitlines() if len(l.split()) == 3)
        if t in "tTwW"]
addrs = [a for a, _ in syms]
starts = set(addrs)
name_at = {n: a for a, n in syms}
beg, end = name_at["bench_mark_begin"], name_at["bench_mark_end"]
pc_re = re.compile(r"\[[0-9a-f]+/([0-9a-f]+)/")


def node():
    return {"n": 0, "self": 0, "calls": 0, "ch": collections.OrderedDict()}


def child(par, fn):
    key = f"{fn}#{sum(1 for k in par['ch'] if k.split('#')[0] == fn)}" if fn in split else fn
    nd = par["ch"].get(key)
    if nd is None:
        nd = par["ch"][key] = node()
    nd["calls"] += 1
    return nd


root = node()
k, on, found = -1, False, False
stack = []
with open(trace) as f:
    for line in f:
        m = pc_re.search(line)
        if not m:
            continue
        pc = int(m.group(1), 16)
        if pc == beg:
            k += 1
            on = k == step
            stack = [("", root)]
            continue
        if pc == end:
            if on:
                found = True
                break
            continue
        if not on:
            continue
        fn = syms[bisect.bisect_right(addrs, pc) - 1][1]
        if fn != stack[-1][0]:
            back = next((i for i in range(len(stack) - 1, 0, -1) if stack[i][0] == fn), None)
            if pc in starts or back is None:
                stack.append((fn, child(stack[-1][1], fn)))
            else:
                del stack[back + 1:]
        for _, nd in stack:
            nd["n"] += 1
        stack[-1][1]["self"] += 1
if not found:
    sys.exit(f"mips_calltree: no measured call {step} in the trace")


def show(name, nd, d):
    if d > maxd:
        return
    print(f"{'  ' * d}{name} {nd['n']:,} (x{nd['calls']}, self {nd['self']:,})")
    for c, ch in nd["ch"].items():
        show(c, ch, d + 1)


print(f"measured call {step}: {root['n']:,} instructions")
for c, ch in root["ch"].items():
    show(c, ch, 0)
