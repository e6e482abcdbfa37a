#!/usr/bin/env bash
# Jolt CharacterVirtual scene (docs/JOLT-SCENE.md): instructions per character update,
# counted by callgrind (never time), against Jolt's figures from issue 14.
#   bench/jolt_run.sh BIN OUT      BIN: build/bench/bin/jolt_scene, OUT: build/bench
# Writes OUT/jolt_scene.md (and prints it); callgrind files and logs in OUT/jolt/.
# Two runs at a time (the machine has 2 cores), under nice.
set -euo pipefail
bin=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
out=$(mkdir -p "$2" && cd "$2" && pwd)
dir=$out/jolt
mkdir -p "$dir"
JOBS=${BENCH_JOBS:-2}

# Jolt's figures (issue 14: SSE4.2 build, x86 instructions per CharacterVirtual update,
# callgrind) and the targets (a fifth of them).
JOLT_60=33100
JOLT_300=61300

CELLS="0 2"          # 0: the builder's automatic cell; 2: an explicit 2 m cell
STEPS="60 300"

job() {   # run "$@" in the background, at most $JOBS at a time
    while [ "$(jobs -rp | wc -l)" -ge "$JOBS" ]; do wait -n; done
    "$@" &
}

run() {   # cell steps
    local name="c$1_s$2"
    (cd "$dir" && nice valgrind --tool=callgrind --toggle-collect=jolt_step_all \
        --callgrind-out-file="$dir/$name.out" "$bin" "$2" "$1" > "$dir/$name.txt" 2> "$dir/$name.err") ||
        { echo "bench-jolt: run $name failed (see $dir/$name.err)" >&2; return 1; }
}

echo "bench-jolt: callgrind runs (cells: $CELLS; steps: $STEPS)" >&2
for c in $CELLS; do for s in $STEPS; do job run "$c" "$s"; done; done
fail=0
for p in $(jobs -rp); do wait "$p" || fail=1; done
[ $fail = 0 ] || exit 1

val() { awk -F= -v k="$2" '$1 == k { print $2; exit }' "$dir/$1.txt"; }
total() { awk '/^totals:/ { print $2; exit }' "$dir/$1.out"; }
# Inclusive count of function $2 within the measured region of run $1 (0 when never called).
# callgrind_annotate lists a function once per source file its code came from (inlined
# header code separately, relative paths) and once in total (absolute path): the larger of
# the total and the sum of the pieces.
incl() {
    callgrind_annotate --inclusive=yes --threshold=100 "$dir/$1.out" 2>/dev/null |
        awk -v f="$2" '/^ *[0-9,]+ +\( *[0-9.]+%\) +[^ ]+:/ {
            n = $1; gsub(",", "", n)
            r = $0; sub(/^[^)]*\) +/, "", r); sub(/ .*$/, "", r)
            fn = r; sub(/^.*:/, "", fn); if (fn != f) next
            if (r ~ /^\//) { if (n + 0 > a) a = n + 0 } else s += n
        } END { printf "%d\n", (a > s ? a : s) }'
}
# Calls of function $2 within the measured region of run $1 (callgrind's calls= lines;
# names are compressed as "cfn=(id) name" the first time, "cfn=(id)" after).
calls() {
    awk -v f="$2" '
        /^c?fn=\(/ { id = $1; sub(/^c?fn=/, "", id); if (NF > 1) { nm = $0; sub(/^[^ ]* /, "", nm); name[id] = nm }
                     if ($0 ~ /^cfn=/) cur = name[id]; next }
        /^calls=/ { if (cur == f) { c = $1; sub(/^calls=/, "", c); n += c } }
        END { printf "%d\n", n }' "$dir/$1.out"
}
k() { awk -v n="$1" -v d="$2" 'BEGIN { printf "%.1fk", n / d / 1000 }'; }
cellname() { if [ "$1" = 0 ]; then echo "automatic ($(val "c$1_s60" cell) m)"; else echo "$1 m ($(val "c$1_s60" cell) m built)"; fi; }

md=$out/jolt_scene.md
{
    echo "### Jolt CharacterVirtual scene: x86-64 instructions per character update"
    echo
    echo "100 characters, dt 1/60, callgrind \`--toggle-collect=jolt_step_all\` (the per-step"
    echo "character loop: target logic + \`char_body_move_and_slide_in\`); per update = that"
    echo "loop's Ir / (steps x 100). Jolt: issue 14's figures (SSE4.2 build, callgrind)."
    echo
    echo "| grid cell | steps | ours per update | Jolt per update | ours / Jolt | target (1/5 Jolt) | met |"
    echo "|---|---|---|---|---|---|---|"
    for c in $CELLS; do for s in $STEPS; do
        n="c${c}_s$s"; t=$(total "$n"); u=$((s * 100))
        j=$([ "$s" = 60 ] && echo $JOLT_60 || echo $JOLT_300)
        awk -v t="$t" -v u="$u" -v j="$j" -v cn="$(cellname "$c")" -v s="$s" 'BEGIN {
            o = t / u; tg = j / 5;
            printf "| %s | %d | %.1fk | %.1fk | %.2fx | <= %.1fk | %s |\n", cn, s, o / 1000, j / 1000, o / j, tg / 1000,
                   (o <= tg ? "yes" : sprintf("no (%.1fx over)", o / tg)) }'
    done; done
    echo
    echo "Accuracy (independent double-precision check after every step, measured steps plus a"
    echo "2 s settle with no input; sweep capsule = the full capsule shortened from the bottom by"
    echo "step_height, the capsule the library keeps out of geometry):"
    echo
    echo "| grid cell | steps | max penetration, sweep capsule | closest approach | steps > 1 mm | on floor at the end | at rest at the end: grounded | after the settle: at rest / grounded | query overflows |"
    echo "|---|---|---|---|---|---|---|---|---|"
    for c in $CELLS; do for s in $STEPS; do
        n="c${c}_s$s"
        printf "| %s | %d | %s mm | %s mm | %s | %s / 100 | %s / %s | %s / %s | %s |\n" "$(cellname "$c")" "$s" \
            "$(val "$n" max_pen_sweep_mm)" "$(val "$n" min_clearance_sweep_mm)" "$(val "$n" pen_samples_over_1mm)" \
            "$(val "$n" end_on_floor)" "$(val "$n" end_at_rest_grounded)" "$(val "$n" end_at_rest)" \
            "$(val "$n" settled_at_rest)" "$(val "$n" settled_at_rest_grounded)" "$(val "$n" overflows)"
    done; done
    echo
    echo "What the bodies met (body-steps of the measured steps; the first ~50 steps are the drop"
    echo "from the start height onto the terrain):"
    echo
    echo "| grid cell | steps | body-steps | airborne | within 5 cm of the stairs or wall | hit a wall | stepped up/down | lowest foot |"
    echo "|---|---|---|---|---|---|---|---|"
    for c in $CELLS; do for s in $STEPS; do
        n="c${c}_s$s"
        printf "| %s | %d | %s | %s | %s | %s | %s | %s m |\n" "$(cellname "$c")" "$s" "$(val "$n" samples)" \
            "$(val "$n" airborne_samples)" "$(val "$n" near_stairs_wall_samples)" "$(val "$n" hit_wall_samples)" \
            "$(val "$n" stepped_samples)" "$(val "$n" min_foot_y)"
    done; done
    echo
    echo "Profile split (callgrind inclusive counts within the measured loop, instructions per"
    echo "update). coll_gather_begin: the step's one grid walk; coll_gather_*: the step's queries"
    echo "on the gathered triangles (inclusive of the scene queries they fall back to);"
    echo "coll_capsule_sweep / coll_raycast: the scene queries alone (fallbacks: a query reaching"
    echo "outside the gathered box, mostly the crack rule's roll sweep). The char body phase"
    echo "columns (cb_*) include the queries they make:"
    echo
    echo "| grid cell | steps | total | move_and_slide | coll_gather_begin | coll_gather_capsule_sweep | coll_gather_raycast | coll_gather_capsule_overlaps | coll_capsule_sweep | coll_raycast | coll_cb_slide | coll_cb_probe_floor | coll_cb_recover |"
    echo "|---|---|---|---|---|---|---|---|---|---|---|---|---|"
    for c in $CELLS; do for s in $STEPS; do
        n="c${c}_s$s"; u=$((s * 100))
        row="| $(cellname "$c") | $s | $(k "$(total "$n")" $u)"
        for f in char_body_move_and_slide_in coll_gather_begin coll_gather_capsule_sweep coll_gather_raycast coll_gather_capsule_overlaps coll_capsule_sweep coll_raycast coll_cb_slide coll_cb_probe_floor coll_cb_recover; do
            row="$row | $(k "$(incl "$n" "$f")" $u)"
        done
        echo "$row |"
    done; done
    echo
    echo "Calls per body step (queries on the gathered triangles, the scene sweeps they fell back"
    echo "to, and the exact primitives: capsule-triangle sweeps, ray-triangle tests). callgrind"
    echo "counts calls outside the toggled function too, so these are over the measured steps and"
    echo "the unmeasured settle after them (settle_steps more steps of 100 bodies, at rest):"
    echo
    echo "| grid cell | steps (+ settle) | coll_gather_capsule_sweep | coll_gather_capsule_sweep_above | coll_gather_raycast | coll_gather_capsule_overlaps_m | capsule_sweep_above | coll_tri_sweep_prep | coll_ray_triangle_sheared |"
    echo "|---|---|---|---|---|---|---|---|---|"
    for c in $CELLS; do for s in $STEPS; do
        n="c${c}_s$s"; st=$(val "$n" settle_steps); u=$(((s + st) * 100))
        row="| $(cellname "$c") | $s (+ $st)"
        for f in coll_gather_capsule_sweep coll_gather_capsule_sweep_above coll_gather_raycast coll_gather_capsule_overlaps_m capsule_sweep_above coll_tri_sweep_prep coll_ray_triangle_sheared; do
            row="$row | $(awk -v n="$(calls "$n" "$f")" -v u=$u 'BEGIN { printf "%.2f", n / u }')"
        done
        echo "$row |"
    done; done
} > "$md"
cat "$md"

# The same figures as CSV, for the targets table of docs/BENCHMARKS.md (bench/tables.py).
{
    echo "cell,cell_eff,steps,per_update,jolt,max_pen_sweep_mm,pen_samples_over_1mm,settled_at_rest,settled_at_rest_grounded,gathers,gather_overflows,gather_misses,dedup_overflows"
    for c in $CELLS; do for s in $STEPS; do
        n="c${c}_s$s"; t=$(total "$n"); u=$((s * 100))
        j=$([ "$s" = 60 ] && echo $JOLT_60 || echo $JOLT_300)
        echo "$c,$(val "$n" cell),$s,$((t / u)),$j,$(val "$n" max_pen_sweep_mm),$(val "$n" pen_samples_over_1mm),$(val "$n" settled_at_rest),$(val "$n" settled_at_rest_grounded),$(val "$n" gathers),$(val "$n" gather_overflows),$(val "$n" gather_misses),$(val "$n" dedup_overflows)"
    done; done
} > "$out/jolt.csv"
