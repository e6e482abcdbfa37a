/**
 * @file coll_libm.h
 * @brief <math.h>, with fabsf and sqrtf as the compiler's own instructions. Included by
 *        the library's private headers and sources in place of <math.h>, before anything
 *        (fm_math.h's inline vector lengths) calls them.
 *
 * The console archive and the bench ROM are built with -ffreestanding, which implies
 * -fno-builtin: there GCC calls fabsf and sqrtf (a jump, the libc's body, the argument
 * and result moves, and the caller's temporaries saved around every call) where the hosted
 * builds (x86, the qemu MIPS build, a libdragon game's n64.mk flags) inline them: the
 * sign bit cleared in a general register (-mabs=legacy), and sqrt.s with -fno-math-errno.
 * The same instructions the libc's own fabsf and sqrtf run (the bench ROM's rom_libc.c is
 * __builtin_fabsf and __builtin_sqrtf), so every result is the same bit for bit; only the
 * calls go. Measured (2026-12-06, perf26): the emulated console's vcorner worst step
 * 40,437 -> see docs/BENCHMARKS.md.
 */
#ifndef COLL_LIBM_H
#define COLL_LIBM_H

#include <math.h>

#if defined(__GNUC__)
#undef fabsf
#define fabsf(x) __builtin_fabsf(x)
#undef sqrtf
#define sqrtf(x) __builtin_sqrtf(x)
#endif

#endif /* COLL_LIBM_H */
