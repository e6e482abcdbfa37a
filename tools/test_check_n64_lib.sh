#!/usr/bin/env bash
# Negative test of tools/check_n64_lib.sh, so the console check cannot silently pass:
#   test_check_n64_lib.sh CC TOOLPREFIX "ARCH FLAGS"
# builds tiny archives that each break one rule and expects the check to reject every one,
# and a clean one it must accept.
set -u
cc=$1; tp=$2; arch=$3
top=$(cd "$(dirname "$0")/.." && pwd)
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
base="$arch -G0 -mno-abicalls -fno-pic -ffreestanding -O2 -fno-math-errno"
mk() {   # mk NAME "EXTRA FLAGS" 'C SOURCE': archive $tmp/NAME/libcoll.a from one object
    mkdir -p "$tmp/$1"
    printf '%s\n' "$3" > "$tmp/$1/t.c"
    # shellcheck disable=SC2086
    $cc -std=gnu11 -w $base $2 -c "$tmp/$1/t.c" -o "$tmp/$1/t.o" && ${tp}ar rcs "$tmp/$1/libcoll.a" "$tmp/$1/t.o"
}
ok='#include <stdint.h>
float coll_ok(uint32_t n, float x) { return (float)(int32_t)n * x; }'
mk good "" "$ok"
mk double "" 'double coll_twice(double a, double b) { return a * b + 1.0; }'
mk u32cast "-mabi=32" '#include <stdint.h>
float coll_u32(uint32_t n) { return (float)n; }'
mk fmsym "" 'float fm_vec3_dot(const float *a, const float *b) { return a[0] * b[0]; }'
mk o32 "-mabi=32" "$ok"
mk malloc "" 'void *malloc(unsigned long); void *coll_alloc(void) { return malloc(4); }'
mk mips32 "-mabi=32 -march=mips32r2" "$ok"
mk prefix "" 'float cb_slide(float a) { return a * 2.0f; }'   # an internal without the library prefix
mk libmcall "" '#include <math.h>
float coll_len(float x, float y) { return sqrtf(fabsf(x) + y); }'   # libm calls, not the builtins

bad=0
run() { bash "$top/tools/check_n64_lib.sh" "$tp" "$tmp/$1/libcoll.a" > "$tmp/$1.log" 2>&1; }
if run good; then echo "check-test: clean archive accepted"; else
    echo "check-test: FAIL: the clean archive was rejected:"; cat "$tmp/good.log"; bad=1; fi
# case:reason the check must give (a rejection for another reason does not count)
for c in double:double-precision u32cast:double-precision fmsym:fm_vec3_dot o32:o64 malloc:malloc \
         mips32:"MIPS III" prefix:"outside its own prefixes" libmcall:"calls libm"; do
    t=${c%%:*}; why=${c#*:}
    if [ ! -f "$tmp/$t/libcoll.a" ]; then echo "check-test: FAIL: could not build case $t"; bad=1; continue; fi
    if run "$t"; then echo "check-test: FAIL: case $t passed the check"; bad=1
    elif ! grep -q "$why" "$tmp/$t.log"; then echo "check-test: FAIL: case $t rejected, but not for '$why':"; cat "$tmp/$t.log"; bad=1
    else echo "check-test: case $t rejected ($why)"; fi
done
exit $bad
