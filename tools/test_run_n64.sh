#!/usr/bin/env bash
# Negative test of the console run (tools/run_n64.sh): ROMs that must fail for the right
# reason, and one that must pass (host_tests/n64/rom_selftest.c). Prints a Unity-style
# summary line so tools/run_tests.sh counts it with the suites.
#   test_run_n64.sh [ROM_DIR]     (default build/n64rom)
set -u
top=$(cd "$(dirname "$0")/.." && pwd)
dir=${1:-$top/build/n64rom}
n=0; bad=0
check() {   # case expect-exit(0/1) pattern
    n=$((n + 1))
    out=$(N64_TIMEOUT=${N64_SELFTEST_TIMEOUT:-15} bash "$top/tools/run_n64.sh" "$dir/selftest_$1.z64" 2>&1)
    rc=$?
    if { [ "$2" = 0 ] && [ $rc != 0 ]; } || { [ "$2" != 0 ] && [ $rc = 0 ]; } || ! echo "$out" | grep -q "$3"; then
        echo "tools/test_run_n64.sh:$n:selftest_$1:FAIL: exit $rc, expected $2 and '$3':"
        echo "$out" | tail -n 5
        bad=$((bad + 1))
    else
        echo "tools/test_run_n64.sh:$n:selftest_$1:PASS ($(echo "$out" | tail -n 1))"
    fi
}
check ok 0 "status 0"
check status 1 "status 1"
check exception 1 "ROM-EXCEPTION code=2"
check reserved 1 "reserved opcode"
check hang 1 "timeout after"
echo "$n Tests $bad Failures 0 Ignored"
[ $bad = 0 ]
