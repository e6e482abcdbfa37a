/*
 * ROMs that must fail, so the console run cannot pass by accident (tools/test_run_n64.sh):
 * built once per case with -DSELFTEST_<case>.
 *   exception  a load from an unmapped address (TLB miss): ROM-EXCEPTION, status=exception
 *   reserved   an instruction the VR4300 lacks (MIPS32r2 seb): the emulator's reserved opcode
 *   hang       never reaches the end marker: the runner's timeout
 *   status     main returns 1: ROM-END status=1
 *   ok         main returns 0 (the runner must accept it)
 */
#include <stdint.h>
#include <stdio.h>

int main(void)
{
    printf("selftest\n");
#if defined(SELFTEST_exception)
    volatile uint32_t *p = (volatile uint32_t *)(uintptr_t)0x00001000u;
    return (int)*p;
#elif defined(SELFTEST_reserved)
    int r = 1;
    __asm__ volatile(".set push\n.set mips32r2\nseb %0, %0\n.set pop" : "+r"(r));
    return r - 1;
#elif defined(SELFTEST_hang)
    for (volatile int i = 0;; i++) {}
#elif defined(SELFTEST_status)
    return 1;
#else
    return 0;
#endif
}
