#!/usr/bin/env bash
# Checks the console archive: every object is big-endian MIPS-III (VR4300) and the only
# undefined symbols outside the archive are on a short libc allow-list.
set -eu
lib=$1; nm=$2; readelf=$3; extra=${4:-}  # extra: archive (libccd) whose symbols count as defined
allow='^(memcpy|memset|memmove|memcmp|sqrtf|fabsf|floorf|ceilf|sinf|cosf|acosf|atan2f|tanf|fmodf)$'
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
(cd "$tmp" && ar x "$(realpath "$OLDPWD/$lib")" 2>/dev/null || ar x "$lib")
bad=0
for o in "$tmp"/*.o; do
    hdr=$($readelf -h "$o")
    echo "$hdr" | grep -q "big endian" || { echo "n64-check: $(basename "$o") is not big-endian"; bad=1; }
    echo "$hdr" | grep -q "MIPS R4000\|MIPS" || { echo "n64-check: $(basename "$o") is not MIPS"; bad=1; }
    echo "$hdr" | grep -qi "mips3" || { echo "n64-check: $(basename "$o") is not MIPS-III: $(echo "$hdr" | grep Flags)"; bad=1; }
done
defined=$($nm -g --defined-only "$lib" $extra 2>/dev/null | awk 'NF==3{print $3}' | sort -u)
undef=$($nm -u "$lib" 2>/dev/null | awk 'NF>=2{print $2}' | sort -u)
for s in $undef; do
    echo "$defined" | grep -qx "$s" && continue
    echo "$s" | grep -Eq "$allow" && continue
    echo "n64-check: $lib references '$s', which is not on the libc allow-list"; bad=1
done
[ $bad = 0 ] && echo "n64-check: $lib ok (big-endian MIPS-III, libc use: $(echo "$undef" | grep -E "$allow" | tr '\n' ' '))"
exit $bad
