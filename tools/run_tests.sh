#!/usr/bin/env bash
# Runs Unity test binaries and prints one summary line "N passed, N failed".
# Usage: run_tests.sh NAME "RUNNER" bin... [-- NAME "RUNNER" bin...]...
# A binary that crashes, times out or prints no Unity summary counts as one failure.
set -u
total_pass=0; total_fail=0; failed_list=()
timeout_s=${TEST_TIMEOUT:-1500}
while [ $# -gt 0 ]; do
    name=$1; runner=$2; shift 2
    echo "=== $name run ${runner:+(under $runner)}"
    while [ $# -gt 0 ] && [ "$1" != "--" ]; do
        bin=$1; shift
        log=$(mktemp)
        # shellcheck disable=SC2086
        timeout "$timeout_s" $runner "$bin" > "$log" 2>&1
        rc=$?
        summary=$(grep -E '^[0-9]+ Tests [0-9]+ Failures [0-9]+ Ignored' "$log" | tail -n 1)
        if [ -n "$summary" ]; then
            read -r t _ f _ i _ <<< "$summary"
            p=$((t - f - i))
            if [ "$rc" != 0 ] && [ "$f" = 0 ]; then f=1; fi
        else
            p=0; f=1
        fi
        total_pass=$((total_pass + p)); total_fail=$((total_fail + f))
        if [ "$f" != 0 ]; then
            failed_list+=("$name:$(basename "$bin")")
            echo "--- $(basename "$bin"): $p passed, $f failed (exit $rc)"
            grep -E ':FAIL|ERROR|Sanitizer|runtime error' "$log" | head -n 40
            [ -z "$summary" ] && tail -n 20 "$log"
        else
            echo "--- $(basename "$bin"): $p passed"
        fi
        rm -f "$log"
    done
    [ $# -gt 0 ] && shift
done
if [ ${#failed_list[@]} -gt 0 ]; then echo "failing suites: ${failed_list[*]}"; fi
echo "$total_pass passed, $total_fail failed"
[ "$total_fail" = 0 ]
