/* Boot stub of the test ROM (ROM 0x40..0xFFF). The emulator's PIF boot copies it to SP DMEM
 * (0xA4000040) and jumps there. It DMAs the program (ROM 0x1000.., its length in the last
 * word of the boot area, patched in by tools/n64rom.py) to RDRAM 0x80000400, stores the
 * memory size where libultra/libdragon look for it (0x80000318) and jumps to the entry.
 * For emulators only: real hardware also needs RDRAM set up and CIC-matching boot code. */
    .set noreorder
    .set noat
    .section .text
    .globl boot_stub
boot_stub:
    lui   $8, 0xA460            /* PI registers */
1:  lw    $9, 0x10($8)          /* PI_STATUS: wait while DMA or IO busy */
    andi  $9, $9, 3
    bnez  $9, 1b
    nop
    li    $9, 0x00000400        /* RDRAM destination (physical) */
    sw    $9, 0x00($8)          /* PI_DRAM_ADDR */
    li    $9, 0x10001000        /* cartridge source */
    sw    $9, 0x04($8)          /* PI_CART_ADDR */
    lui   $10, 0xA400
    lw    $9, 0x0FFC($10)       /* program length (ROM 0xFFC, now in DMEM) */
    addiu $9, $9, -1
    sw    $9, 0x0C($8)          /* PI_WR_LEN: starts cartridge -> RDRAM */
2:  lw    $9, 0x10($8)
    andi  $9, $9, 3
    bnez  $9, 2b
    nop
    li    $9, 2
    sw    $9, 0x10($8)          /* clear the PI interrupt */
    lui   $9, 0xA000
    li    $10, 0x00800000       /* 8 MiB (expansion pak) */
    sw    $10, 0x318($9)
    lui   $9, 0x8000
    ori   $9, $9, 0x0400
    jr    $9
    nop
