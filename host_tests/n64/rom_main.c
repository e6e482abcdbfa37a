/*
 * Test ROM runtime: IS-Viewer 64 output, the end marker, the exception report, and the
 * call of the linked program's main() (a host_tests suite, unchanged). The runner
 * (tools/run_n64.sh) needs the end marker "ROM-END status=0"; an exception prints
 * "ROM-EXCEPTION ..." and "ROM-END status=exception".
 */
#include <stdio.h>
#include <string.h>
#include "rom.h"

#define ISV_BUF ((volatile uint32_t *)0xB3FF0020u)
#define ISV_LEN ((volatile uint32_t *)0xB3FF0014u)

static char isv_line[512];
static uint32_t line_len;

void rom_isv_flush(void)
{
    if (!line_len) return;
    for (uint32_t i = 0; i < line_len; i += 4) {
        uint32_t w = 0;
        for (uint32_t k = 0; k < 4; k++)
            w = (w << 8) | (uint8_t)(i + k < line_len ? isv_line[i + k] : 0);
        ISV_BUF[i / 4] = w;
    }
    *ISV_LEN = line_len;
    line_len = 0;
}

void rom_isv_putc(char c)
{
    isv_line[line_len++] = c;
    if (c == '\n' || line_len == sizeof isv_line) rom_isv_flush();
}

static uint32_t count_start;

void rom_finish(int status)
{
    uint32_t counts = rom_count() - count_start;
    fflush(stdout);
    printf("\nROM-END status=%d count=%lu\n", status, (unsigned long)counts);
    fflush(stdout);
    for (;;) {}
}

int main(void);

void rom_main(void)
{
    count_start = rom_count();
    printf("ROM-START\n");
    if (rom_note[0]) printf("ROM: %s\n", rom_note);
    rom_finish(main());
}

static uint32_t cp0(int r)
{
    uint32_t v = 0;
    switch (r) {
    case 8: __asm__ volatile("mfc0 %0, $8" : "=r"(v)); break;
    case 12: __asm__ volatile("mfc0 %0, $12" : "=r"(v)); break;
    case 13: __asm__ volatile("mfc0 %0, $13" : "=r"(v)); break;
    case 14: __asm__ volatile("mfc0 %0, $14" : "=r"(v)); break;
    }
    return v;
}

void rom_exception(void)
{
    uint32_t fcr31;
    __asm__ volatile("cfc1 %0, $31" : "=r"(fcr31));
    uint32_t cause = cp0(13);
    line_len = 0;
    printf("\nROM-EXCEPTION code=%lu cause=%08lx epc=%08lx badvaddr=%08lx status=%08lx fcr31=%08lx\n",
           (unsigned long)((cause >> 2) & 31), (unsigned long)cause, (unsigned long)cp0(14),
           (unsigned long)cp0(8), (unsigned long)cp0(12), (unsigned long)fcr31);
    printf("ROM-END status=exception\n");
    fflush(stdout);
    for (;;) {}
}
