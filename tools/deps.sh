#!/usr/bin/env bash
# Installs everything the build needs, idempotently:
#  - Debian binary packages listed in tools/deps-packages.txt,
#  - libccd and Unity sources from Debian *source* packages (libccd, cjson), unpacked
#    under build/deps/. The deb-src entry is derived from the machine's own apt sources.
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
deps="$top/build/deps"
mkdir -p "$deps"

SUDO=""
if [ "$(id -u)" != 0 ]; then SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive

apt_updated=0
apt_update() {
    if [ $apt_updated = 0 ]; then $SUDO apt-get update -q >/dev/null; apt_updated=1; fi
}

# ---- binary packages ----
want=$(sed -e 's/#.*//' -e '/^[[:space:]]*$/d' "$top/tools/deps-packages.txt" | awk '{print $1}')
missing=""
for p in $want; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing="$missing $p"
done
if [ -n "$missing" ]; then
    echo "deps: installing$missing"
    apt_update
    $SUDO apt-get install -y -q --no-install-recommends $missing >/dev/null
fi

# ---- source packages ----
have_src() { [ -f "$deps/libccd/src/ccd.c" ] && [ -f "$deps/unity/src/unity.c" ] && [ -f "$deps/unity/examples/unity_config.h" ]; }
if ! have_src; then
    # Derive deb-src entries from the existing apt configuration (no address is written
    # by hand): copy each deb822 file with Types: deb, or each one-line 'deb' entry.
    if ! grep -rqsE '^(Types:.*deb-src|deb-src )' /etc/apt/sources.list /etc/apt/sources.list.d/; then
        tmp=$(mktemp)
        for f in /etc/apt/sources.list.d/*.sources; do
            [ -f "$f" ] || continue
            sed -n '1,$p' "$f" | sed 's/^Types:[[:space:]]*deb[[:space:]]*$/Types: deb-src/' >> "$tmp"
            echo >> "$tmp"
        done
        if [ -s "$tmp" ]; then
            $SUDO cp "$tmp" /etc/apt/sources.list.d/charbody64-derived-src.sources
        fi
        if [ -f /etc/apt/sources.list ]; then
            grep -E '^deb ' /etc/apt/sources.list | sed 's/^deb /deb-src /' > "$tmp" || true
            [ -s "$tmp" ] && $SUDO cp "$tmp" /etc/apt/sources.list.d/charbody64-derived-src.list
        fi
        rm -f "$tmp"
        apt_updated=0
    fi
    apt_update
    mkdir -p "$deps/src"
    (cd "$deps/src" && apt-get source --download-only libccd cjson >/dev/null 2>&1) || {
        echo "deps: apt-get source failed (is a deb-src entry available?)" >&2; exit 1; }
    rm -rf "$deps/libccd" "$deps/unity"
    mkdir -p "$deps/libccd" "$deps/unity/src" "$deps/unity/examples"
    tar -xzf "$deps"/src/libccd_*.orig.tar.gz -C "$deps/libccd" --strip-components=1
    tar -xzf "$deps"/src/cjson_*.orig.tar.gz -C "$deps/src"
    cp "$deps"/src/cJSON-*/tests/unity/src/unity*.[ch] "$deps/unity/src/"
    # cJSON's copy of Unity includes ../examples/unity_config.h (it enables doubles).
    cp "$deps"/src/cJSON-*/tests/unity/examples/unity_config.h "$deps/unity/examples/"
    # libccd in single precision: the precision the console ships with.
    printf '#ifndef __CCD_CONFIG_H__\n#define __CCD_CONFIG_H__\n#define CCD_SINGLE\n#endif\n' \
        > "$deps/libccd/src/ccd/config.h"
fi
echo "deps: ok"
