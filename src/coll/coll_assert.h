/**
 * @file coll_assert.h
 * @brief Debug checks of the caller's contract (a game bug, not bad data: bad data gets an
 *        error code). On in hosted builds without NDEBUG (the PC build a game is tested
 *        in), off in freestanding builds (the console archive: libcoll has no libc
 *        assert), forced either way with -DCOLL_DEBUG_ASSERTS=1 or 0 (libdragon supplies
 *        assert() to a console build that turns them on).
 */
#ifndef COLL_ASSERT_H
#define COLL_ASSERT_H

#ifndef COLL_DEBUG_ASSERTS
#if !defined(NDEBUG) && __STDC_HOSTED__
#define COLL_DEBUG_ASSERTS 1
#else
#define COLL_DEBUG_ASSERTS 0
#endif
#endif

#if COLL_DEBUG_ASSERTS
#include <assert.h>
#define COLL_DEBUG_ASSERT(cond, msg) assert((cond) && (msg))
#else
#define COLL_DEBUG_ASSERT(cond, msg) ((void)0)
#endif

#endif
