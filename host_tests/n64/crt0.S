/* Start-up of the test ROM, linked first at 0x80000400: COP0 Status (CU0|CU1|FR for the o64
 * ABI, BEV clear), FCR31 = FS (flush denormals, as libdragon sets), exception vectors at
 * 0x80000000/080/100/180 jumping to rom_exception (prints Cause/EPC/BadVAddr/FCR31), stack
 * at the top of RDRAM, .bss cleared, then rom_main. setjmp/longjmp for Unity are here too. */
    .set noreorder
    .set noat
    .section .text.start, "ax"
    .globl _start
_start:
    lui   $8, 0x3400            /* CU1 | CU0 | FR */
    mtc0  $8, $12               /* Status */
    nop
    mtc0  $0, $13               /* Cause */
    lui   $8, 0x0100            /* FS */
    ctc1  $8, $31
    move  $28, $0
    la    $29, __stack_top
    la    $8, __bss_start
    la    $9, __bss_end
1:  beq   $8, $9, 2f
    nop
    sw    $0, 0($8)
    b     1b
    addiu $8, $8, 4
2:  /* exception vectors: copy the 4-instruction jump (uncached, KSEG1) */
    la    $8, vector_jump
    lw    $10, 0($8)
    lw    $11, 4($8)
    lw    $12, 8($8)
    lw    $13, 12($8)
    lui   $9, 0xA000
    li    $14, 4
3:  sw    $10, 0($9)
    sw    $11, 4($9)
    sw    $12, 8($9)
    sw    $13, 12($9)
    addiu $14, $14, -1
    bnez  $14, 3b
    addiu $9, $9, 0x80
    jal   rom_main
    nop
4:  b     4b
    nop

vector_jump:
    la    $26, exception_entry  /* lui + addiu: 2 instructions */
    jr    $26
    nop

exception_entry:
    la    $29, __exc_stack_top
    jal   rom_exception
    nop
5:  b     5b
    nop

/* int setjmp(jmp_buf): ra, sp, s8, s0-s7 (64-bit in o64), $f20-$f31 */
    .globl setjmp
setjmp:
    sd    $31, 0($4)
    sd    $29, 8($4)
    sd    $30, 16($4)
    sd    $16, 24($4)
    sd    $17, 32($4)
    sd    $18, 40($4)
    sd    $19, 48($4)
    sd    $20, 56($4)
    sd    $21, 64($4)
    sd    $22, 72($4)
    sd    $23, 80($4)
    sdc1  $f20, 88($4)
    sdc1  $f21, 96($4)
    sdc1  $f22, 104($4)
    sdc1  $f23, 112($4)
    sdc1  $f24, 120($4)
    sdc1  $f25, 128($4)
    sdc1  $f26, 136($4)
    sdc1  $f27, 144($4)
    sdc1  $f28, 152($4)
    sdc1  $f29, 160($4)
    sdc1  $f30, 168($4)
    sdc1  $f31, 176($4)
    jr    $31
    move  $2, $0

/* void longjmp(jmp_buf, int) */
    .globl longjmp
longjmp:
    ld    $31, 0($4)
    ld    $29, 8($4)
    ld    $30, 16($4)
    ld    $16, 24($4)
    ld    $17, 32($4)
    ld    $18, 40($4)
    ld    $19, 48($4)
    ld    $20, 56($4)
    ld    $21, 64($4)
    ld    $22, 72($4)
    ld    $23, 80($4)
    ldc1  $f20, 88($4)
    ldc1  $f21, 96($4)
    ldc1  $f22, 104($4)
    ldc1  $f23, 112($4)
    ldc1  $f24, 120($4)
    ldc1  $f25, 128($4)
    ldc1  $f26, 136($4)
    ldc1  $f27, 144($4)
    ldc1  $f28, 152($4)
    ldc1  $f29, 160($4)
    ldc1  $f30, 168($4)
    ldc1  $f31, 176($4)
    bnez  $5, 6f
    move  $2, $5
    li    $2, 1
6:  jr    $31
    nop
