/* The bare-metal test ROM's own interfaces (host_tests/n64). */
#ifndef ROM_H
#define ROM_H
#include <stdint.h>

/** A file embedded in the ROM (tools/n64rom_files.sh writes the table). */
typedef struct { const char *name; const char *data; uint32_t size; } rom_file_entry_t;
extern const rom_file_entry_t rom_files[];
extern const uint32_t rom_nfiles;
extern const char rom_note[]; ///< what the build left out, printed at start

void rom_isv_putc(char c);   ///< IS-Viewer output, flushed per line
void rom_isv_flush(void);
/** Prints the end marker with the exit status and stops (never returns). */
void rom_finish(int status) __attribute__((noreturn));
/** COP0 Count: instructions x CountPerOp since reset (wraps at 2^32). */
static inline uint32_t rom_count(void)
{
    uint32_t c;
    __asm__ volatile("mfc0 %0, $9" : "=r"(c));
    return c;
}
#endif
