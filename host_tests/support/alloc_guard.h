/**
 * @file alloc_guard.h
 * @brief Counts heap calls made by the code under test. Every test binary is linked with
 *        -Wl,--wrap=malloc,calloc,realloc,free, so calls from our library and libccd land
 *        here; calls from inside libc itself (printf buffers) do not.
 */
#ifndef ALLOC_GUARD_H
#define ALLOC_GUARD_H
#include <stddef.h>

/** Starts counting from zero. */
void alloc_guard_begin(void);
/** Number of malloc/calloc/realloc calls since alloc_guard_begin(). */
size_t alloc_guard_end(void);

/** Asserts (Unity) that the statement makes no allocation. */
#define ASSERT_NO_ALLOC(stmt) do { alloc_guard_begin(); stmt; \
    TEST_ASSERT_EQUAL_UINT_MESSAGE(0u, (unsigned)alloc_guard_end(), "heap allocation in: " #stmt); } while (0)
#endif
