#!/usr/bin/env python3
"""Console instruction counts from the emulated console beside the qemu trace figures.

Usage: n64_console.py RUN_LOG QEMU_CONSOLE_CSV BENCHMARKS_MD

RUN_LOG is the output of the bench ROM (host_tests/n64/rom_bench.c under mupen64plus with
Core[CountPerOp]=1): lines "BENCH scenario cell w1 w2 ...", the COP0 Count difference of
each measured window. The marker overhead (the smallest "empty" window) is subtracted, as
bench/run.sh does for the qemu trace. The qemu figures come from QEMU_CONSOLE_CSV (written
by make bench's qemu pass) when it exists, else from the committed console-cost table in
BENCHMARKS_MD. The table replaces the section between the make bench-n64 markers of
BENCHMARKS_MD (appended after the make bench section when the markers are missing)."""
import csv, os, re, sys

log, qcsv, doc = sys.argv[1], sys.argv[2], sys.argv[3]
runs = {}
for line in open(log):
    f = line.split()
    if len(f) >= 3 and f[0] == "BENCH":
        runs[(f[1], f[2])] = [int(x) for x in f[3:]]
if ("empty", "0") not in runs or not runs[("empty", "0")]:
    sys.exit("n64_console: no empty-window run in " + log)
overhead = min(runs[("empty", "0")])

qemu, source = {}, None
if os.path.exists(qcsv):
    for r in csv.DictReader(open(qcsv)):
        qemu[(r["scenario"], r["cell"])] = (float(r["mips_mean"]), float(r["mips_max"]), r["cell_eff"])
    source = "this run of make bench (%s)" % qcsv
else:
    text = open(doc).read()
    sect = text.split("### Console cost", 1)[-1].split("<!--", 1)[0]
    names = {"32 bodies, one frame (per frame)": "crowd32",
             "32 bodies with own colliders, one frame (per frame)": "crowd32_col"}
    for m in re.finditer(r"^\| ([^|]+) \| (as baked|rebaked), ([0-9.]+) m \| [0-9,]+ \| ([0-9,]+) \| ([0-9,]+) \|", sect, re.M):
        scn = names.get(m.group(1).strip(), m.group(1).strip())
        cell = "0" if m.group(2) == "as baked" else "1"
        qemu[(scn, cell)] = (float(m.group(4).replace(",", "")), float(m.group(5).replace(",", "")), m.group(3))
    source = "the committed qemu table above (make bench not run in this tree)"

out = []
P = out.append
P("### Console cost on the emulated console (COP0 Count, mupen64plus)\n")
P("Instructions per call counted by the console itself: the bench ROM (o64, `-mno-abicalls "
  "-G0`, the archives `make n64` builds) under mupen64plus %s with `Core[CountPerOp]=1`, so COP0 "
  "Count advances once per executed instruction. Marker overhead (%d) subtracted. qemu figures from %s; "
  "the qemu build is o32 with PIC calls through the GOT, so it runs a few more instructions per "
  "call.\n" % ("2.5.9 (cached interpreter)", overhead, source))
P("| scenario | grid cell | console instr / call (mean) | console max | qemu mean | qemu max | console vs qemu, mean | max |")
P("|---|---|---:|---:|---:|---:|---:|---:|")
order = ["walk", "stairs", "vcorner", "platform", "crowd32", "stairs_real", "crack", "crowd32_col"]
for scn in order:
    for cell in ("0", "1"):
        w = runs.get((scn, cell))
        if not w:
            continue
        v = [x - overhead for x in w]
        mean, mx = sum(v) / len(v), max(v)
        q = qemu.get((scn, cell))
        label = {"crowd32": "32 bodies, one frame (per frame)",
                 "crowd32_col": "32 bodies with own colliders, one frame (per frame)"}.get(scn, scn)
        c = ("as baked" if cell == "0" else "rebaked") + (", %s m" % q[2] if q else "")
        if q:
            P("| %s | %s | %s | %s | %s | %s | %+.1f %% | %+.1f %% |" % (
                label, c, f"{mean:,.0f}", f"{mx:,}", f"{q[0]:,.0f}", f"{q[1]:,.0f}",
                100 * (mean - q[0]) / q[0], 100 * (mx - q[1]) / q[1]))
        else:
            P("| %s | %s | %s | %s | - | - | - | - |" % (label, c, f"{mean:,.0f}", f"{mx:,}"))
P("")
table = "\n".join(out)

begin, end = "<!-- BEGIN GENERATED (make bench-n64) -->", "<!-- END GENERATED (make bench-n64) -->"
text = open(doc).read()
if begin in text and end in text:
    pre, rest = text.split(begin, 1)
    _, post = rest.split(end, 1)
    text = pre + begin + "\n" + table + end + post
else:
    main_end = "<!-- END GENERATED -->"
    pre, post = text.split(main_end, 1) if main_end in text else (text, "")
    text = pre + (main_end + "\n\n" if main_end in text else "") + begin + "\n" + table + end + "\n" + post
open(doc, "w").write(text)
print(table)
print("bench-n64: docs/BENCHMARKS.md console table updated")
