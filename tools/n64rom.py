#!/usr/bin/env python3
"""Assembles a test ROM for emulators: n64rom.py BOOT.bin PROGRAM.bin OUT.z64 [TITLE]

Layout: 0x40-byte header (0x80371240, entry 0x80000400), the boot stub at 0x40..0xFFF
(its last word, 0xFFC, holds the program length the stub DMAs), the program from 0x1000.
The header CRC words are the 6102 checksum of 0x1000..0x100FFF (emulators do not check
them; real hardware would also need CIC boot code). Big-endian (.z64)."""
import struct
import sys

boot = open(sys.argv[1], 'rb').read()
prog = open(sys.argv[2], 'rb').read()
title = (sys.argv[4] if len(sys.argv) > 4 else 'CHARBODY64 TEST').encode()[:20].ljust(20, b' ')
if len(boot) > 0xFFC - 0x40:
    sys.exit('n64rom: boot stub too large: %d bytes' % len(boot))
prog += b'\0' * (-len(prog) % 16)
rom = bytearray(0x1000) + prog
rom += b'\0' * max(0, 0x101000 - len(rom))          # at least 1 MiB of program area
rom += b'\0' * (-len(rom) % 0x100000)              # whole MiBs


def crc6102(data):
    m = 0xFFFFFFFF
    seed = 0xF8CA4DDC
    t1 = t2 = t3 = t4 = t5 = t6 = seed
    for i in range(0x1000, 0x101000, 4):
        d = struct.unpack_from('>I', data, i)[0]
        if (t6 + d) & m < t6:
            t4 = (t4 + 1) & m
        t6 = (t6 + d) & m
        t3 ^= d
        r = ((d << (d & 0x1F)) | (d >> ((32 - (d & 0x1F)) & 0x1F))) & m if d & 0x1F else d
        t5 = (t5 + r) & m
        t2 = t2 ^ r if t2 > d else t2 ^ (t6 ^ d)
        t1 = (t1 + (t5 ^ d)) & m
    return (t6 ^ t4 ^ t3) & m, (t5 ^ t2 ^ t1) & m


struct.pack_into('>IIII', rom, 0, 0x80371240, 0x0000000F, 0x80000400, 0x0000144C)
rom[0x20:0x34] = title
rom[0x3B:0x40] = b'N' + b'CB' + b'E' + b'\0'
rom[0x40:0x40 + len(boot)] = boot
struct.pack_into('>I', rom, 0xFFC, len(prog))
struct.pack_into('>II', rom, 0x10, *crc6102(rom))
open(sys.argv[3], 'wb').write(rom)
