#!/usr/bin/env bash
# Bakes every .gltf/.glb/.obj of Debian's assimp-testmodels with collbake (an ASan+UBSan
# build) and records how each went, for host_tests/test_bake_roundtrip.c to judge:
#   baked    exit 0, blob written (the test loads it)
#   refused  exit 1 with an "ERROR: <file>: ..." line and no sanitizer report
#   crash    anything else: a signal, a sanitizer report, a timeout, no ERROR line
# Usage: bake_testmodels.sh COLLBAKE MODELS_DIR OUT_DIR
# Always exits 0 once the results file is written: the test turns crashes into failures.
set -u
bake=$1; models=$2; out=$3
rm -rf "$out"; mkdir -p "$out"
results="$out/results.tsv"; tmp="$results.tmp"
: > "$tmp"
export ASAN_OPTIONS=${ASAN_OPTIONS:-abort_on_error=0:detect_leaks=1}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
n=0; baked=0; refused=0; crashed=0
if [ ! -d "$models" ]; then
    echo "bake_testmodels: $models not found (install assimp-testmodels)" >&2
fi
while IFS= read -r -d '' f; do
    n=$((n + 1))
    blob="$out/$n.coll"
    log="$out/$n.log"
    timeout 120 "$bake" "$f" -o "$blob" > "$log" 2>&1
    rc=$?
    msg=$(grep -m1 -E '^ERROR: ' "$log" | tr '\t' ' ')
    if grep -qE 'Sanitizer|runtime error:' "$log"; then
        status=crash; msg=$(grep -m1 -E 'Sanitizer|runtime error:' "$log" | tr '\t' ' ')
    elif [ $rc = 0 ] && [ -s "$blob" ]; then
        status=baked; msg=$(grep -m1 -E '^  triangles' "$log" | sed 's/^ *//')
    elif [ $rc = 1 ] && [ -n "$msg" ] && [ ! -e "$blob" ]; then
        status=refused
    else
        status=crash; msg="exit $rc: $(tail -n 1 "$log" | tr '\t' ' ')"
    fi
    case $status in baked) baked=$((baked + 1));; refused) refused=$((refused + 1));; *) crashed=$((crashed + 1));; esac
    [ $status = baked ] || rm -f "$blob"
    printf '%s\t%d\t%s\t%s\t%s\n' "$status" "$rc" "$([ $status = baked ] && echo "$n.coll" || echo -)" "$f" "$msg" >> "$tmp"
done < <(find "$models" -type f \( -iname '*.gltf' -o -iname '*.glb' -o -iname '*.obj' \) -print0 2>/dev/null | sort -z)
# Inputs collbake must refuse with a clear message (the test checks they were "refused").
syn="$out/synthetic"; mkdir -p "$syn"
printf 'not a model\n' > "$syn/garbage.obj"
printf 'v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\n' > "$syn/degenerate.obj"
printf 'v 0 0 0\nv 1e7 0 0\nv 0 0 1e7\nf 1 2 3\n' > "$syn/too_large.obj"
printf 'v 0 0 0\nv 1 0 0\nv 0 0 1\nf 1 2 3\n' > "$syn/tri.obj"
printf '{"asset":{"version":"2.0"},"scenes":[{"nodes":[]}],"scene":0}\n' > "$syn/empty.gltf"
check_refused() {  # name, args...
    local name=$1; shift
    n=$((n + 1))
    local log="$out/$n.log" blob="$out/$n.coll"
    timeout 120 "$bake" "$@" -o "$blob" > "$log" 2>&1
    local rc=$? status msg
    msg=$(grep -m1 -E '^ERROR: ' "$log" | tr '\t' ' ')
    if grep -qE 'Sanitizer|runtime error:' "$log"; then status=crash
    elif [ $rc = 1 ] && [ -n "$msg" ] && [ ! -e "$blob" ]; then status=refused
    elif [ $rc = 0 ]; then status=baked
    else status=crash; msg="exit $rc: $(tail -n 1 "$log")"
    fi
    case $status in refused) refused=$((refused + 1));; baked) baked=$((baked + 1));; *) crashed=$((crashed + 1));; esac
    rm -f "$blob"
    printf '%s\t%d\t-\tmust-refuse:%s\t%s\n' "$status" "$rc" "$name" "$msg" >> "$tmp"
}
# Welding: two triangles sharing an edge whose copies differ by 20-30 um must share 2 vertices
# (4 in total; the pair at x = 1 straddles a weld-grid cell boundary); at --weld 0 they stay 6.
printf 'v 0 0 0\nv 0.99999 0 0\nv 0 0 1\nv 1.00002 0 0\nv 0 0.00002 1\nv 1 0 1\nf 1 2 3\nf 4 6 5\n' > "$syn/weld.obj"
check_welds() {  # name, expected vertex count, args...
    local name=$1 want=$2; shift 2
    n=$((n + 1))
    local log="$out/$n.log" blob="$out/$n.coll" status msg
    timeout 120 "$bake" "$@" -o "$blob" > "$log" 2>&1
    local rc=$?
    msg=$(grep -m1 -E '^  welding' "$log" | sed 's/^ *//')
    if grep -qE 'Sanitizer|runtime error:' "$log" || [ $rc != 0 ]; then status=crash; msg="exit $rc: $(tail -n 1 "$log")"
    elif echo "$msg" | grep -q -- "-> $want vertices"; then status=baked
    else status=wrong; fi
    case $status in baked) baked=$((baked + 1));; *) crashed=$((crashed + 1));; esac
    printf '%s\t%d\t%s\tmust-weld:%s\t%s\n' "$status" "$rc" "$([ $status = baked ] && echo "$n.coll" || echo -)" "$name" "$msg" >> "$tmp"
}
check_welds weld-default 4 "$syn/weld.obj"
check_welds weld-exact-only 6 --weld 0 "$syn/weld.obj"
check_refused missing-file "$syn/no_such_file.gltf"
check_refused unreadable "$syn/garbage.obj"
check_refused degenerate-only "$syn/degenerate.obj"
check_refused too-large "$syn/too_large.obj"
check_refused no-meshes "$syn/empty.gltf"
check_refused only-matches-nothing --only 'nothing_*' "$syn/tri.obj"
check_refused bad-scale --scale -1 "$syn/tri.obj"
mv "$tmp" "$results"
echo "assimp-testmodels (+7 must-refuse, +2 must-weld inputs): $n runs: $baked baked, $refused refused with a message, $crashed crashed"
grep -E '^crash' "$results" | cut -f4,5 | sed 's/^/  CRASH: /'
exit 0
