/* Build-pipeline smoke test: the library links, libccd is single precision, guard counts. */
#include "unity.h"
#include "alloc_guard.h"
#include "coll/common.h"
#include <ccd/ccd.h>
#include <stdlib.h>
#include <string.h>

void setUp(void) {}
void tearDown(void) {}

static void test_strerror_names_every_code(void)
{
    for (int e = COLL_OK; e <= COLL_ERR_NOT_FOUND; e++)
        TEST_ASSERT_NOT_EQUAL(0, strcmp(coll_strerror((coll_err_t)e), "unknown error"));
    TEST_ASSERT_EQUAL_STRING("unknown error", coll_strerror((coll_err_t)999));
}

static void test_libccd_is_single_precision(void)
{
    TEST_ASSERT_EQUAL(sizeof(float), sizeof(ccd_real_t));
}

static void test_alloc_guard_counts_heap_calls(void)
{
    alloc_guard_begin();
    void *volatile p = malloc(16);
    free(p);
    TEST_ASSERT_EQUAL_UINT(1, alloc_guard_end());
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_strerror_names_every_code);
    RUN_TEST(test_libccd_is_single_precision);
    RUN_TEST(test_alloc_guard_counts_heap_calls);
    return UNITY_END();
}
