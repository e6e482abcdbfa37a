#include "alloc_guard.h"
#include <stdlib.h>

void *__real_malloc(size_t size);
void *__real_calloc(size_t n, size_t size);
void *__real_realloc(void *p, size_t size);
void __real_free(void *p);

static size_t g_allocs;

void alloc_guard_begin(void) { g_allocs = 0; }
size_t alloc_guard_end(void) { return g_allocs; }

void *__wrap_malloc(size_t size) { g_allocs++; return __real_malloc(size); }
void *__wrap_calloc(size_t n, size_t size) { g_allocs++; return __real_calloc(n, size); }
void *__wrap_realloc(void *p, size_t size) { g_allocs++; return __real_realloc(p, size); }
void __wrap_free(void *p) { __real_free(p); }
