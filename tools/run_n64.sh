#!/usr/bin/env bash
# Runs a test ROM in mupen64plus headless and prints what the ROM printed (IS-Viewer 64).
#   run_n64.sh ROM            (tools/run_tests.sh calls it as a suite's runner)
# Exit 0 only when the ROM printed its end marker "ROM-END status=0". An exception
# (ROM-EXCEPTION), a reserved opcode, an emulator that quits early, or no end marker within
# N64_TIMEOUT seconds of the emulator's own CPU time (default 900; a shared, loaded machine
# slows the wall clock, not the ROM's work) or 4 times that on the wall clock fail; the
# emulator this script started is then ended by its pid. N64_EMUMODE: 0 pure interpreter,
# 1 cached interpreter (default), 2 dynamic recompiler (faster, but it evaluates unordered
# FPU compares of NaN wrongly).
# N64_COUNT_PER_OP=1 makes COP0 Count an instruction count. The emulator's configuration
# and data stay under build/n64rom/emu (XDG_*_HOME, --configdir).
set -u
rom=$1
top=$(cd "$(dirname "$0")/.." && pwd)
emu=${MUPEN64PLUS:-$(command -v mupen64plus || echo /usr/games/mupen64plus)}
mode=${N64_EMUMODE:-1}
limit=${N64_TIMEOUT:-900}
home=${N64_EMU_HOME:-$top/build/n64rom/emu}
mkdir -p "$home/config" "$home/data" "$home/cache"
log=$(mktemp)
extra=()
[ -n "${N64_COUNT_PER_OP:-}" ] && extra+=(--set "Core[CountPerOp]=$N64_COUNT_PER_OP")
SDL_VIDEODRIVER=dummy SDL_AUDIODRIVER=dummy \
XDG_CONFIG_HOME="$home/config" XDG_DATA_HOME="$home/data" XDG_CACHE_HOME="$home/cache" \
    stdbuf -oL -eL "$emu" --nosaveoptions --nospeedlimit --noosd --configdir "$home/config" \
    --gfx dummy --audio dummy --input dummy --rsp dummy --emumode "$mode" "${extra[@]}" \
    "$rom" > "$log" 2>&1 &
pid=$!
stop() { kill "$pid" 2>/dev/null && sleep 0.2; kill -9 "$pid" 2>/dev/null; wait "$pid" 2>/dev/null; }
# whatever ends this script ends the emulator it started
trap 'stop; rm -f "$log"' EXIT
trap 'exit 124' TERM INT HUP
start=$SECONDS
why=""
tick=$(getconf CLK_TCK 2>/dev/null || echo 100)
# the emulator's user + system CPU seconds so far (fields 14 and 15 of /proc/PID/stat)
cpu_secs() { awk -v t="$tick" '{ sub(/^.*\) /, ""); print int(($12 + $13) / t) }' "/proc/$pid/stat" 2>/dev/null || echo 0; }
while :; do
    if grep -q "ROM-END" "$log"; then sleep 0.1; break; fi
    if grep -q "reserved opcode" "$log"; then why="reserved opcode"; break; fi
    if ! kill -0 "$pid" 2>/dev/null; then why="emulator exited without the end marker"; break; fi
    if [ "$(cpu_secs)" -ge "$limit" ]; then why="timeout after ${limit}s of CPU time"; break; fi
    if [ $((SECONDS - start)) -ge $((4 * limit)) ]; then why="timeout after $((4 * limit))s"; break; fi
    sleep 0.2
done
cpu=$(cpu_secs)
stop
secs=$((SECONDS - start))
# the ROM's output: the text after "IS64: " on each line the emulator printed
sed -n 's/^.*IS64: \{0,1\}//p' "$log"
grep -E "Core Error|reserved opcode" "$log" | grep -v "video device" | head -n 5
status=$(sed -n 's/^.*IS64: \{0,1\}ROM-END status=\([^ ]*\).*/\1/p' "$log" | tail -n 1)
echo "run_n64: $(basename "$rom"): ${why:-end marker, status ${status:-?}} (${secs}s, ${cpu}s CPU, emumode $mode)"
[ -z "$why" ] && [ "$status" = 0 ]
