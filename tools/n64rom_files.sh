#!/usr/bin/env bash
# Writes the assembly of the files embedded in the test ROM (rom_files[] in
# host_tests/n64/rom.h): n64rom_files.sh NOTE FILE... > files.S. Names are kept as given
# (paths from the repository root, where the host suites open them); a FILE given as DIR/
# embeds an empty directory entry (so opendir finds a directory with nothing embedded), one
# given as NAME=PATH embeds PATH under NAME.
# NOTE (rom_note) is printed by the ROM when it starts.
set -eu
note=$1; shift
echo '    .section .rodata'
echo '    .balign 4'
printf '    .globl rom_note\nrom_note: .asciz "%s"\n' "$note"
echo '    .balign 4'
echo '    .globl rom_nfiles'
echo "rom_nfiles: .word $#"
echo '    .globl rom_files'
echo 'rom_files:'
i=0
for f in "$@"; do echo "    .word name$i, data$i, data${i}_end - data$i"; i=$((i + 1)); done
i=0
for f in "$@"; do
    name=${f%%=*}; path=${f#*=}
    echo "name$i: .asciz \"$name\""
    if [ "${f%/}" != "$f" ]; then echo "data$i:"; else echo "data$i: .incbin \"$path\""; fi
    echo "data${i}_end: .byte 0"
    echo '    .balign 4'
    i=$((i + 1))
done
