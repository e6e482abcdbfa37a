#!/usr/bin/env bash
# collbake's Quake III BSP reader and its loss rule, on files made by make_test_bsp.py:
#  - good.bsp bakes to the expected triangle count (35; 37 with --bsp-all-models), with Z up
#    turned into Y up and 0.032 m per unit (bounds from the report);
#  - every broken variant (truncations, bad version, lumps outside the file, bad indexes,
#    bad patches, NaN vertices, ...) is refused: exit 1, an "ERROR: <file>:" line, no output;
#  - randomly corrupted copies bake or are refused, never crash (ASan + UBSan build);
#  - a bake that keeps under half its input triangles is refused; --min-kept 0 bakes it;
#  - --cell-choice cost picks a cheaper-estimated cell than the runtime's on a level with a
#    dense cluster (within 10 % more bytes), keeps a dense runtime grid (floor.obj), the
#    default is the runtime's, --cell-size wins.
# Usage: test_bsp.sh COLLBAKE OUTDIR. Writes OUTDIR/results.tsv (ok|FAIL, name, detail),
# read by host_tests/test_bake_roundtrip.c; exits 1 when any line is FAIL.
set -u
bake=$1; out=$2
here=$(cd "$(dirname "$0")" && pwd)
rm -rf "$out"; mkdir -p "$out/in"
python3 "$here/make_test_bsp.py" "$out/in" || { echo "test_bsp: cannot generate the test files" >&2; exit 1; }
export ASAN_OPTIONS=${ASAN_OPTIONS:-abort_on_error=0:detect_leaks=1}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
res="$out/results.tsv"; : > "$res"
fails=0
put() { printf '%s\t%s\t%s\n' "$1" "$2" "$3" >> "$res"; [ "$1" = ok ] || fails=$((fails + 1)); }

# report value: key -> value
rv() { awk -v k="$2" '$1 == k { $1 = ""; sub(/^ /, ""); print; exit }' "$1"; }
near() { awk -v a="$1" -v b="$2" 'BEGIN { d = a - b; if (d < 0) d = -d; exit !(d < 1e-4) }'; }

# ---- the good file
f="$out/in/good.bsp"
if "$bake" "$f" -o "$out/good.coll" --report "$out/good.report" > "$out/good.log" 2>&1; then
    tin=$(rv "$out/good.report" triangles_in); tout=$(rv "$out/good.report" triangles)
    read -r x0 y0 z0 x1 y1 z1 <<< "$(rv "$out/good.report" bounds)"
    if [ "$tin" = 35 ] && [ "$tout" = 35 ] && near "$x0" 0 && near "$y0" 0 && near "$z0" -9.6 && near "$x1" 3.2 &&
       near "$y1" 2.048 && near "$z1" 0 && grep -q "35 triangles" "$out/good.log"; then
        put ok good "35 triangles, bounds $x0 $y0 $z0 .. $x1 $y1 $z1"
    else
        put FAIL good "triangles $tin in / $tout out (want 35), bounds $x0 $y0 $z0 .. $x1 $y1 $z1 (want 0 0 -9.6 .. 3.2 2.048 0)"
    fi
else
    put FAIL good "did not bake: $(grep -m1 ERROR "$out/good.log")"
fi
if "$bake" --bsp-all-models "$f" -o "$out/all.coll" --report "$out/all.report" > "$out/all.log" 2>&1 &&
   [ "$(rv "$out/all.report" triangles_in)" = 37 ]; then
    put ok all_models "37 triangles with the door"
else
    put FAIL all_models "$(rv "$out/all.report" triangles_in 2>/dev/null) triangles (want 37)"
fi
if "$bake" --bsp-unit 1 "$f" -o "$out/unit.coll" --report "$out/unit.report" > "$out/unit.log" 2>&1 &&
   read -r _ _ _ _ y1 _ <<< "$(rv "$out/unit.report" bounds)" && near "$y1" 64; then
    put ok bsp_unit "--bsp-unit 1 keeps Quake units (top at 64)"
else
    put FAIL bsp_unit "--bsp-unit 1: $(rv "$out/unit.report" bounds 2>/dev/null)"
fi

# ---- must be refused
for f in "$out"/in/bad_*.bsp; do
    name=$(basename "$f" .bsp)
    "$bake" "$f" -o "$out/$name.coll" > "$out/$name.log" 2>&1
    rc=$?
    msg=$(grep -m1 -E "^ERROR: " "$out/$name.log")
    if grep -qE 'Sanitizer|runtime error:' "$out/$name.log"; then
        put FAIL "$name" "sanitizer: $(grep -m1 -E 'Sanitizer|runtime error:' "$out/$name.log")"
    elif [ $rc = 1 ] && [[ $msg == "ERROR: $f:"* ]] && [ ! -e "$out/$name.coll" ]; then
        put ok "$name" "${msg#ERROR: $f: }"
    else
        put FAIL "$name" "exit $rc, '${msg}', output $( [ -e "$out/$name.coll" ] && echo written || echo none)"
    fi
done

# ---- random corruption: bakes (and the blob loads: collbake checks) or is refused
for f in "$out"/in/fuzz_*.bsp; do
    name=$(basename "$f" .bsp)
    timeout 60 "$bake" "$f" -o "$out/$name.coll" > "$out/$name.log" 2>&1
    rc=$?
    if grep -qE 'Sanitizer|runtime error:' "$out/$name.log"; then
        put FAIL "$name" "sanitizer: $(grep -m1 -E 'Sanitizer|runtime error:' "$out/$name.log")"
    elif [ $rc = 0 ] && [ -s "$out/$name.coll" ]; then
        put ok "$name" "baked"
    elif [ $rc = 1 ] && grep -q "^ERROR: $f:" "$out/$name.log" && [ ! -e "$out/$name.coll" ]; then
        put ok "$name" "refused: $(grep -m1 '^ERROR' "$out/$name.log" | cut -c1-120)"
    else
        put FAIL "$name" "exit $rc: $(tail -n 1 "$out/$name.log")"
    fi
done

# ---- the loss rule
f="$out/in/lossy.obj"
"$bake" "$f" -o "$out/lossy.coll" > "$out/lossy.log" 2>&1
rc=$?
if [ $rc = 1 ] && grep -q "^ERROR: $f: only 1 of 4 input triangles survive" "$out/lossy.log" && [ ! -e "$out/lossy.coll" ]; then
    put ok loss_rule "$(grep -m1 '^ERROR' "$out/lossy.log" | cut -c1-140)"
else
    put FAIL loss_rule "exit $rc: $(grep -m1 -E '^ERROR|triangles' "$out/lossy.log")"
fi
if "$bake" --min-kept 0 "$f" -o "$out/lossy0.coll" > "$out/lossy0.log" 2>&1 && [ -s "$out/lossy0.coll" ]; then
    put ok loss_rule_override "--min-kept 0 bakes it"
else
    put FAIL loss_rule_override "$(grep -m1 ERROR "$out/lossy0.log")"
fi

# ---- the automatic cell by estimated cost (--cell-choice cost, collbake.c choose_cell)
f="$out/in/cluster.obj"
if "$bake" "$f" -o "$out/cl_rt.coll" --report "$out/cl_rt.report" > "$out/cl_rt.log" 2>&1 &&
   "$bake" --cell-choice runtime "$f" -o "$out/cl_rt2.coll" > "$out/cl_rt2.log" 2>&1 &&
   "$bake" --cell-choice cost "$f" -o "$out/cl_cost.coll" --report "$out/cl_cost.report" > "$out/cl_cost.log" 2>&1 &&
   "$bake" --cell-choice cost --cell-size 4 "$f" -o "$out/cl_4.coll" --report "$out/cl_4.report" > "$out/cl_4.log" 2>&1; then
    rt_cell=$(rv "$out/cl_rt.report" cell_size); cost_cell=$(rv "$out/cl_cost.report" cell_size)
    rt_b=$(rv "$out/cl_rt.report" bytes); cost_b=$(rv "$out/cl_cost.report" bytes)
    k=$(rv "$out/cl_cost.report" cell_walk_cost); k0=$(rv "$out/cl_cost.report" cell_walk_cost_runtime)
    if cmp -s "$out/cl_rt.coll" "$out/cl_rt2.coll" && [ "$(rv "$out/cl_rt.report" cell_choice)" = runtime ] &&
       [ "$(rv "$out/cl_cost.report" cell_choice)" = cost ] && ! near "$rt_cell" "$cost_cell" &&
       awk -v k="$k" -v k0="$k0" -v b="$cost_b" -v b0="$rt_b" 'BEGIN { exit !(k > 0 && k < 0.9 * k0 && b <= 1.1 * b0) }' &&
       [ "$(rv "$out/cl_cost.report" triangles)" = "$(rv "$out/cl_rt.report" triangles)" ] &&
       grep -q "automatic, --cell-choice cost" "$out/cl_cost.log" &&
       near "$(rv "$out/cl_4.report" cell_size)" 4 && [ "$(rv "$out/cl_4.report" cell_choice)" = explicit ] &&
       "$bake" "$out/in/floor.obj" -o "$out/fl_rt.coll" > "$out/fl_rt.log" 2>&1 &&
       "$bake" --cell-choice cost "$out/in/floor.obj" -o "$out/fl_cost.coll" > "$out/fl_cost.log" 2>&1 &&
       grep -q "the runtime's choice:" "$out/fl_cost.log" && cmp -s "$out/fl_rt.coll" "$out/fl_cost.coll"; then
        put ok cell_choice "runtime cell $rt_cell ($rt_b bytes, walk $k0), cost: $cost_cell ($cost_b bytes, walk $k)"
    else
        put FAIL cell_choice "runtime cell $rt_cell ($rt_b bytes), cost: $cost_cell ($cost_b bytes, walk $k vs $k0)"
    fi
else
    put FAIL cell_choice "did not bake: $(cat "$out"/cl_*.log | grep -m1 ERROR)"
fi

n=$(wc -l < "$res")
echo "test_bsp: $((n - fails)) ok, $fails failed ($res)"
[ $fails = 0 ]
