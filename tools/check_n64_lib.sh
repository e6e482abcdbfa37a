#!/usr/bin/env bash
# Checks the console archives before a libdragon game links them:
#   check_n64_lib.sh [--libdragon-fmath] TOOLPREFIX ARCHIVE...
# TOOLPREFIX is the binutils prefix (mips-linux-gnu- or $N64_INST/bin/mips64-elf-).
# Every object must be
#   - 32-bit big-endian MIPS, ISA MIPS III (the VR4300), o64 ABI (libdragon's; GNU ld
#     refuses to mix o32 and o64 objects);
#   - free of double-precision arithmetic and conversions (add.d, mul.d, cvt.d.w, cvt.s.d,
#     c.lt.d, ...): the library is single precision. ldc1/sdc1 and dmtc1/dmfc1 are moves,
#     not arithmetic, and o64 code may use them to save and restore FP registers;
#   - (libcoll's) without calls to fabsf or sqrtf: src/coll/coll_libm.h makes them the
#     builtins, which -ffreestanding otherwise turns into libc calls.
# Across the archives together:
#   - undefined symbols are on a short libc/libm allow-list (with --libdragon-fmath also
#     libdragon's own fm_ functions, which then come from libdragon);
#   - defined external symbols carry the archive's own prefixes: coll_ and char_body_ for
#     libcoll (its internals too: coll_cb_, coll_prim_); ccd, __ccd for libccd. Nothing in libdragon's fm_
#     namespace, nothing that could clash with the game or libdragon.
set -eu
ldfm=0
if [ "${1:-}" = --libdragon-fmath ]; then ldfm=1; shift; fi
[ $# -ge 2 ] || { echo "usage: $0 [--libdragon-fmath] TOOLPREFIX ARCHIVE..." >&2; exit 2; }
tp=$1; shift
nm=${tp}nm; readelf=${tp}readelf; objdump=${tp}objdump
allow='^(memcpy|memmove|memset|sqrtf|fabsf|ceilf|sinf|cosf|acosf|fminf)$'
[ $ldfm = 1 ] && allow="${allow%)\$}|fm_[a-z0-9_]+)\$"
prefixes_for() {   # allowed prefixes of defined external symbols, by archive
    case "$(basename "$1")" in
        libccd*) echo '^(ccd|__ccd)' ;;
        *)       echo '^(coll_|char_body_)' ;;
    esac
}
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
bad=0
fail() { echo "n64-check: $*"; bad=1; }
n=0
for lib in "$@"; do
    [ -f "$lib" ] || { fail "$lib: no such archive"; continue; }
    n=$((n + 1)); d="$tmp/$n"; mkdir -p "$d"
    abs=$(cd "$(dirname "$lib")" && pwd)/$(basename "$lib")
    (cd "$d" && ${tp}ar x "$abs")
    for o in "$d"/*.o; do
        [ -f "$o" ] || { fail "$lib: no objects"; break; }
        name="$(basename "$lib")($(basename "$o"))"
        hdr=$($readelf -h "$o")
        flags=$(echo "$hdr" | sed -n 's/^ *Flags: *//p')
        echo "$hdr" | grep -q "Class: *ELF32" || fail "$name is not ELF32"
        echo "$hdr" | grep -q "big endian" || fail "$name is not big-endian"
        echo "$hdr" | grep -q "Machine: *MIPS" || fail "$name is not MIPS"
        echo "$flags" | grep -qw "mips3" || fail "$name is not MIPS III (VR4300): flags $flags"
        echo "$flags" | grep -qw "o64" || fail "$name is not the o64 ABI libdragon uses: flags $flags"
        dbl=$($objdump -d "$o" | awk -F'\t' '
            /^[0-9a-f]+ <.*>:$/ { fn = $0; sub(/^[0-9a-f]+ /, "", fn); sub(/:$/, "", fn) }
            NF >= 3 { m = $3; sub(/ .*/, "", m)
                      if (m ~ /^[a-z0-9]+(\.[a-z0-9]+)*\.d$/ || m ~ /\.d\./) print fn " " m }' | sort -u)
        [ -z "$dbl" ] || fail "$name has double-precision instructions: $(echo "$dbl" | head -n 8 | tr '\n' ';')"
        # the library's own code inlines fabsf and sqrtf (src/coll/coll_libm.h): under
        # -ffreestanding a file that reaches them another way calls the libc per use
        case "$(basename "$lib")" in libccd*) ;; *)
            calls=$($nm -u "$o" | awk '$2 == "fabsf" || $2 == "sqrtf" {print $2}' | tr '\n' ' ')
            [ -z "$calls" ] || fail "$name calls libm's $calls(not inlined: include coll_libm.h first)" ;;
        esac
    done
    pre=$(prefixes_for "$lib")
    for s in $($nm -g --defined-only "$lib" | awk 'NF==3{print $3}' | sort -u); do
        echo "$s" | grep -Eq "$pre" || fail "$lib defines '$s', outside its own prefixes ($pre)"
    done
done
defined=$($nm -g --defined-only "$@" 2>/dev/null | awk 'NF==3{print $3}' | sort -u)
undef=$($nm -u "$@" 2>/dev/null | awk 'NF>=2{print $2}' | sort -u)
used=""
for s in $undef; do
    echo "$defined" | grep -qxF "$s" && continue
    if echo "$s" | grep -Eq "$allow"; then used="$used $s"; continue; fi
    fail "the archives reference '$s', which is not on the allow-list $allow"
done
if [ $bad = 0 ]; then
    echo "n64-check: $* ok (o64, MIPS III, single precision only, own prefixes only; uses:$used)"
fi
exit $bad
