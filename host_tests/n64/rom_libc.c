/*
 * The small C library of the bare-metal test ROM (no libdragon, no newlib): what the
 * library, Unity and the host test suites call, built for the VR4300 with the o64 ABI.
 *
 *  - output: stdout and stderr go to the IS-Viewer 64 buffer (cart 0x13FF0020, length at
 *    0x13FF0014), one line at a time; the emulator prints each as "IS64: <line>";
 *  - files: the files embedded by the build (rom_files[], the regression replays) can be
 *    opened for reading and listed with opendir/readdir; a file opened for writing lives
 *    in RAM until removed;
 *  - math: sqrt/fabs are the FPU instructions; floor, ceil and fmod are exact; sin, cos,
 *    exp, log, atan are series in double precision (errors of a few 1e-16), and the float
 *    versions round those, so they agree with a correctly rounded libm except in the rare
 *    case of a result within ~1e-16 of a rounding boundary;
 *  - malloc is a bump allocator over the RAM after .bss (the library never allocates; the
 *    allocation guard of the test suites still counts calls).
 * Test code only: it uses double precision freely; the library archives are checked
 * separately (tools/check_n64_lib.sh).
 */
#include <dirent.h>
#include <math.h>
#include <stdarg.h>
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "rom.h"

/* ------------------------------------------------------------------ memory and strings */
static int is_space(int c) { return c == ' ' || (c >= '\t' && c <= '\r'); }
static int to_lower(int c) { return c >= 'A' && c <= 'Z' ? c - 'A' + 'a' : c; }

void *memchr(const void *s, int c, size_t n)
{
    const unsigned char *p = s;
    for (; n; n--, p++)
        if (*p == (unsigned char)c) return (void *)p;
    return NULL;
}
void *memcpy(void *restrict d, const void *restrict s, size_t n)
{
    unsigned char *dp = d;
    const unsigned char *sp = s;
    if ((((uintptr_t)dp | (uintptr_t)sp) & 3) == 0) {
        for (; n >= 4; n -= 4, dp += 4, sp += 4) *(uint32_t *)(void *)dp = *(const uint32_t *)(const void *)sp;
    }
    while (n--) *dp++ = *sp++;
    return d;
}

void *memmove(void *d, const void *s, size_t n)
{
    unsigned char *dp = d;
    const unsigned char *sp = s;
    if (dp == sp || n == 0) return d;
    if (dp < sp || dp >= sp + n) return memcpy(d, s, n);
    while (n--) dp[n] = sp[n];
    return d;
}

void *memset(void *d, int c, size_t n)
{
    unsigned char *dp = d;
    if (((uintptr_t)dp & 3) == 0 && n >= 4) {
        uint32_t w = (unsigned char)c * 0x01010101u;
        for (; n >= 4; n -= 4, dp += 4) *(uint32_t *)(void *)dp = w;
    }
    while (n--) *dp++ = (unsigned char)c;
    return d;
}

int memcmp(const void *a, const void *b, size_t n)
{
    const unsigned char *p = a, *q = b;
    for (; n; n--, p++, q++)
        if (*p != *q) return *p < *q ? -1 : 1;
    return 0;
}

size_t strlen(const char *s) { const char *p = s; while (*p) p++; return (size_t)(p - s); }
int strcmp(const char *a, const char *b)
{
    while (*a && *a == *b) { a++; b++; }
    return (unsigned char)*a - (unsigned char)*b;
}
int strncmp(const char *a, const char *b, size_t n)
{
    for (; n; n--, a++, b++) {
        if (*a != *b) return (unsigned char)*a - (unsigned char)*b;
        if (!*a) return 0;
    }
    return 0;
}
char *strchr(const char *s, int c)
{
    for (;; s++) {
        if (*s == (char)c) return (char *)s;
        if (!*s) return NULL;
    }
}
char *strrchr(const char *s, int c)
{
    const char *r = NULL;
    for (;; s++) {
        if (*s == (char)c) r = s;
        if (!*s) return (char *)r;
    }
}
char *strcpy(char *d, const char *s) { char *r = d; while ((*d++ = *s++) != 0) {} return r; }
char *strncpy(char *d, const char *s, size_t n)
{
    size_t i = 0;
    for (; i < n && s[i]; i++) d[i] = s[i];
    for (; i < n; i++) d[i] = 0;
    return d;
}
char *strstr(const char *h, const char *n)
{
    size_t ln = strlen(n);
    for (; *h; h++)
        if (strncmp(h, n, ln) == 0) return (char *)h;
    return ln ? NULL : (char *)h;
}

/* ------------------------------------------------------------------ process */
/* atexit: a few handlers, run last-registered first by exit() (the soak's counters) */
static void (*g_atexit[4])(void);
static int g_natexit;
int atexit(void (*fn)(void))
{
    if (g_natexit >= (int)(sizeof g_atexit / sizeof g_atexit[0])) return -1;
    g_atexit[g_natexit++] = fn;
    return 0;
}
void exit(int code)
{
    while (g_natexit > 0) g_atexit[--g_natexit]();
    rom_finish(code);
    for (;;) {}
}
void abort(void)
{
    fputs("abort()\n", stderr);
    exit(134);
}
char *getenv(const char *name) { (void)name; return NULL; }
pid_t getpid(void) { return 64; }

/* bump allocator: [size][block...] from __heap_start to __heap_end */
extern char __heap_start[], __heap_end[];
static char *heap_top;
void *malloc(size_t n)
{
    if (!heap_top) heap_top = __heap_start;
    size_t need = (n + 15u) & ~(size_t)15u;
    if ((size_t)(__heap_end - heap_top) < need + 16u) return NULL;
    *(size_t *)(void *)heap_top = n;
    void *p = heap_top + 16;
    heap_top += need + 16;
    return p;
}
void free(void *p) { (void)p; }
int posix_memalign(void **out, size_t align, size_t n)
{
    char *p = malloc(n + align);
    if (!p) return 12; /* ENOMEM */
    *out = (void *)(((uintptr_t)p + align - 1) & ~(uintptr_t)(align - 1));
    return 0;
}

/* shell sort: small arrays in test code */
void qsort(void *base, size_t n, size_t sz, int (*cmp)(const void *, const void *))
{
    char *a = base, tmp[256];
    if (sz > sizeof tmp) return;
    for (size_t gap = n / 2; gap > 0; gap /= 2)
        for (size_t i = gap; i < n; i++)
            for (size_t j = i; j >= gap && cmp(a + (j - gap) * sz, a + j * sz) > 0; j -= gap) {
                memcpy(tmp, a + j * sz, sz);
                memcpy(a + j * sz, a + (j - gap) * sz, sz);
                memcpy(a + (j - gap) * sz, tmp, sz);
            }
}

void *calloc(size_t n, size_t s)
{
    if (s && n > (size_t)-1 / s) return NULL;
    void *p = malloc(n * s);
    if (p) memset(p, 0, n * s);
    return p;
}
void *realloc(void *p, size_t n)
{
    void *q = malloc(n);
    if (q && p) {
        size_t old = *(size_t *)(void *)((char *)p - 16);
        memcpy(q, p, old < n ? old : n);
    }
    return q;
}
/* the test suites link with --wrap=malloc,...: the real ones are these */
void *__real_malloc(size_t n);
void *__real_calloc(size_t n, size_t s);
void *__real_realloc(void *p, size_t n);
void __real_free(void *p);
void *__real_malloc(size_t n) { return malloc(n); }
void *__real_calloc(size_t n, size_t s) { return calloc(n, s); }
void *__real_realloc(void *p, size_t n) { return realloc(p, n); }
void __real_free(void *p) { free(p); }

/* ------------------------------------------------------------------ number parsing */
static int digit_val(int c)
{
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'z') return c - 'a' + 10;
    if (c >= 'A' && c <= 'Z') return c - 'A' + 10;
    return 99;
}

unsigned long long strtoull(const char *s, char **end, int base)
{
    const char *p = s;
    while (is_space((unsigned char)*p)) p++;
    bool neg = false;
    if (*p == '+' || *p == '-') neg = *p++ == '-';
    if ((base == 0 || base == 16) && p[0] == '0' && (p[1] == 'x' || p[1] == 'X') && digit_val(p[2]) < 16) {
        p += 2;
        base = 16;
    } else if (base == 0) {
        base = p[0] == '0' ? 8 : 10;
    }
    unsigned long long v = 0;
    const char *start = p;
    while (digit_val(*p) < base) v = v * (unsigned)base + (unsigned)digit_val(*p++);
    if (end) *end = (char *)(p == start ? s : p);
    return neg ? -v : v;
}
unsigned long strtoul(const char *s, char **end, int base) { return (unsigned long)strtoull(s, end, base); }
long long strtoll(const char *s, char **end, int base) { return (long long)strtoull(s, end, base); }
long strtol(const char *s, char **end, int base) { return (long)strtoull(s, end, base); }
int atoi(const char *s) { return (int)strtol(s, NULL, 10); }
long atol(const char *s) { return strtol(s, NULL, 10); }

static double pow10i(int e)
{
    double r = 1.0, b = 10.0;
    unsigned u = (unsigned)(e < 0 ? -e : e);
    for (; u; u >>= 1, b *= b)
        if (u & 1) r *= b;
    return e < 0 ? 1.0 / r : r;
}

static bool match_ci(const char *p, const char *w)
{
    for (; *w; p++, w++)
        if (to_lower((unsigned char)*p) != *w) return false;
    return true;
}

/* Hex floats exactly (up to 60 mantissa bits), nan/inf, decimals closely (not always
 * correctly rounded: the replay files and the test suites write hex). */
double strtod(const char *s, char **end)
{
    const char *p = s;
    while (is_space((unsigned char)*p)) p++;
    bool neg = false;
    if (*p == '+' || *p == '-') neg = *p++ == '-';
    double r;
    if (match_ci(p, "nan")) {
        p += 3;
        r = __builtin_nan("");
    } else if (match_ci(p, "inf")) {
        p += match_ci(p, "infinity") ? 8 : 3;
        r = __builtin_inf();
    } else if (p[0] == '0' && (p[1] == 'x' || p[1] == 'X')) {
        const char *q = p + 2;
        uint64_t m = 0;
        int shift = 0, nd = 0;
        bool dot = false;
        for (;; q++) {
            if (*q == '.' && !dot) { dot = true; continue; }
            int d = digit_val(*q);
            if (d >= 16) break;
            nd++;
            if (m >> 56) { if (!dot) shift += 4; continue; } /* beyond 60 bits: dropped */
            m = m * 16 + (unsigned)d;
            if (dot) shift -= 4;
        }
        if (!nd) { if (end) *end = (char *)s; return 0.0; }
        if (*q == 'p' || *q == 'P') {
            char *e2;
            long e = strtol(q + 1, &e2, 10);
            if (e2 != q + 1) { shift += (int)e; q = e2; }
        }
        r = ldexp((double)m, shift);
        p = q;
    } else {
        double m = 0.0;
        int e10 = 0, nd = 0;
        bool dot = false;
        for (;; p++) {
            if (*p == '.' && !dot) { dot = true; continue; }
            if (*p < '0' || *p > '9') break;
            nd++;
            if (m < 1e18) { m = m * 10 + (*p - '0'); if (dot) e10--; }
            else if (!dot) e10++;
        }
        if (!nd) { if (end) *end = (char *)s; return 0.0; }
        if (*p == 'e' || *p == 'E') {
            char *e2;
            long e = strtol(p + 1, &e2, 10);
            if (e2 != p + 1) { e10 += (int)e; p = e2; }
        }
        r = e10 < -300 ? m * pow10i(-300) * pow10i(e10 + 300) : m * pow10i(e10);
    }
    if (end) *end = (char *)p;
    return neg ? -r : r;
}
double atof(const char *s) { return strtod(s, NULL); }
float strtof(const char *s, char **end) { return (float)strtod(s, end); }

/* ------------------------------------------------------------------ math */
double fabs(double x) { return __builtin_fabs(x); }
float fabsf(float x) { return __builtin_fabsf(x); }
double sqrt(double x) { return __builtin_sqrt(x); }
float sqrtf(float x) { return __builtin_sqrtf(x); }
double fmin(double a, double b) { return a != a ? b : (b != b ? a : (a < b ? a : b)); }
double fmax(double a, double b) { return a != a ? b : (b != b ? a : (a > b ? a : b)); }
float fminf(float a, float b) { return a != a ? b : (b != b ? a : (a < b ? a : b)); }
float fmaxf(float a, float b) { return a != a ? b : (b != b ? a : (a > b ? a : b)); }

static const double TWO52 = 4503599627370496.0;
double floor(double x)
{
    if (x == 0 || !(fabs(x) < TWO52)) return x; /* zero, integral, inf or nan */
    double t = x >= 0 ? (x + TWO52) - TWO52 : (x - TWO52) + TWO52; /* nearest */
    if (t > x) t -= 1.0;
    return t == 0 && x < 0 ? -0.0 : t;
}
double ceil(double x) { return -floor(-x); }
double trunc(double x) { return x < 0 ? ceil(x) : floor(x); }
double round(double x) { return x < 0 ? -floor(-x + 0.5) : floor(x + 0.5); }
float floorf(float x) { return (float)floor(x); }
float ceilf(float x) { return (float)ceil(x); }
float truncf(float x) { return (float)trunc(x); }
float roundf(float x) { return (float)round(x); }

double ldexp(double x, int e)
{
    while (e > 1000) { x *= 0x1p1000; e -= 1000; }
    while (e < -1000) { x *= 0x1p-1000; e += 1000; }
    union { double d; uint64_t u; } s;
    if (e >= -1022) {
        s.u = (uint64_t)(e + 1023) << 52;
        return x * s.d;
    }
    s.u = (uint64_t)(e + 1022 + 1023) << 52; /* two steps: 2^-1022 * 2^(e+1022) */
    return x * s.d * 0x1p-1022;
}
float ldexpf(float x, int e) { return (float)ldexp(x, e); }
double scalbn(double x, int e) { return ldexp(x, e); }

double frexp(double x, int *e)
{
    union { double d; uint64_t u; } v = { x };
    int ex = (int)(v.u >> 52 & 0x7ff);
    if (ex == 0) {
        if (x == 0) { *e = 0; return x; }
        v.d = x * 0x1p64;
        ex = (int)(v.u >> 52 & 0x7ff) - 64;
    } else if (ex == 0x7ff) {
        *e = 0;
        return x;
    }
    *e = ex - 1022;
    v.u = (v.u & ~(0x7ffull << 52)) | (0x3feull << 52);
    return v.d;
}

/* Exact: each step subtracts y * 2^k with y * 2^k <= r < 2 y 2^k (Sterbenz). */
double fmod(double x, double y)
{
    if (x != x || y != y || __builtin_isinf(x) || y == 0) return __builtin_nan("");
    if (__builtin_isinf(y)) return x;
    double r = fabs(x), ay = fabs(y);
    while (r >= ay) {
        double t = ay;
        while (t <= r * 0.5) t *= 2.0;
        r -= t;
    }
    return x < 0 ? -r : r;
}
float fmodf(float x, float y) { return (float)fmod(x, y); }

static const double PIO2_1 = 1.57079632673412561417e+00;  /* first 33 bits of pi/2 */
static const double PIO2_2 = 6.07710050650619224932e-11;  /* next 33 bits */
static const double PIO2_3 = 2.02226624879595063154e-21;  /* the rest */
static const double INV_PIO2 = 6.36619772367581382433e-01;

/* x = k pi/2 + r, |r| <= ~pi/4 (accurate for |x| up to ~1e9) */
static double reduce(double x, int *k)
{
    double n = floor(x * INV_PIO2 + 0.5);
    *k = (int)(int64_t)n;
    return ((x - n * PIO2_1) - n * PIO2_2) - n * PIO2_3;
}
static double sin_poly(double r)
{
    double r2 = r * r, s = 0.0;
    for (int i = 23; i >= 3; i -= 2) s = (s + 1.0) * r2 / ((double)i * (double)(i - 1)) * -1.0;
    return r + r * s;
}
static double cos_poly(double r)
{
    double r2 = r * r, s = 0.0;
    for (int i = 22; i >= 2; i -= 2) s = (s + 1.0) * r2 / ((double)i * (double)(i - 1)) * -1.0;
    return 1.0 + s;
}
double sin(double x)
{
    if (x != x || __builtin_isinf(x)) return __builtin_nan("");
    if (fabs(x) < 0x1p-27) return x;
    int k;
    double r = reduce(x, &k);
    switch (k & 3) {
    case 0: return sin_poly(r);
    case 1: return cos_poly(r);
    case 2: return -sin_poly(r);
    default: return -cos_poly(r);
    }
}
double cos(double x)
{
    if (x != x || __builtin_isinf(x)) return __builtin_nan("");
    int k;
    double r = reduce(x, &k);
    switch (k & 3) {
    case 0: return cos_poly(r);
    case 1: return -sin_poly(r);
    case 2: return -cos_poly(r);
    default: return sin_poly(r);
    }
}
double tan(double x) { return sin(x) / cos(x); }
float sinf(float x) { return (float)sin(x); }
float cosf(float x) { return (float)cos(x); }
float tanf(float x) { return (float)tan(x); }
void sincosf(float x, float *s, float *c) { *s = sinf(x); *c = cosf(x); }

static const double LN2_HI = 6.93147180369123816490e-01, LN2_LO = 1.90821492927058770002e-10;
double exp(double x)
{
    if (x != x) return x;
    if (x > 709.8) return __builtin_inf();
    if (x < -745.2) return 0.0;
    double n = floor(x / (LN2_HI + LN2_LO) + 0.5);
    double r = (x - n * LN2_HI) - n * LN2_LO;
    double s = 1.0;
    for (int i = 17; i >= 1; i--) s = 1.0 + s * r / (double)i;
    return ldexp(s, (int)(int64_t)n);
}
double log(double x)
{
    if (x != x || x < 0) return __builtin_nan("");
    if (x == 0) return -__builtin_inf();
    if (__builtin_isinf(x)) return x;
    int e;
    double m = frexp(x, &e); /* [0.5, 1) */
    if (m < 0.70710678118654752440) { m *= 2.0; e--; }
    double f = (m - 1.0) / (m + 1.0), f2 = f * f, s = 0.0;
    for (int i = 41; i >= 3; i -= 2) s = (s + 1.0 / (double)i) * f2;
    return e * LN2_HI + (e * LN2_LO + 2.0 * f * (1.0 + s * 1.0));
}
double log10(double x) { return log(x) / 2.30258509299404568402; }
double pow(double x, double y)
{
    if (y == 0) return 1.0;
    if (x == 1) return 1.0;
    if (x != x || y != y) return __builtin_nan("");
    if (x == 0) return y > 0 ? 0.0 : __builtin_inf();
    if (x < 0) {
        double yi = floor(y);
        if (yi != y) return __builtin_nan("");
        double r = exp(y * log(-x));
        return fmod(yi, 2.0) != 0 ? -r : r;
    }
    return exp(y * log(x));
}
float powf(float x, float y) { return (float)pow(x, y); }
float expf(float x) { return (float)exp(x); }
float logf(float x) { return (float)log(x); }

static double atan_small(double t) /* |t| <= tan(pi/12) */
{
    double t2 = t * t, s = 0.0;
    for (int i = 41; i >= 3; i -= 2) s = (s + ((i / 2) % 2 ? -1.0 : 1.0) / (double)i) * t2;
    return t + t * s;
}
double atan(double x)
{
    if (x != x) return x;
    bool neg = x < 0, inv = false;
    double a = fabs(x), off = 0.0;
    if (a > 1.0) { a = 1.0 / a; inv = true; }
    if (a > 0.26794919243112270) { /* tan(pi/12): atan(a) = pi/6 + atan((a - c) / (1 + a c)) */
        const double c = 0.57735026918962576451; /* tan(pi/6) */
        a = (a - c) / (1.0 + a * c);
        off = 0.52359877559829887308;
    }
    double r = off + atan_small(a);
    if (inv) r = 1.57079632679489661923 - r;
    return neg ? -r : r;
}
double atan2(double y, double x)
{
    const double pi = 3.14159265358979323846;
    if (x != x || y != y) return x + y;
    if (x == 0) return y > 0 ? pi / 2 : (y < 0 ? -pi / 2 : (__builtin_signbit(x) ? (__builtin_signbit(y) ? -pi : pi) : y));
    double r = atan(y / x);
    if (x < 0) r += __builtin_signbit(y) ? -pi : pi;
    return r;
}
double asin(double x) { return atan2(x, sqrt((1.0 - x) * (1.0 + x))); }
double acos(double x) { return atan2(sqrt((1.0 - x) * (1.0 + x)), x); }
float atan2f(float y, float x) { return (float)atan2(y, x); }
float atanf(float x) { return (float)atan(x); }
float acosf(float x) { return (float)acos(x); }
float asinf(float x) { return (float)asin(x); }
double hypot(double a, double b) { return sqrt(a * a + b * b); }
double copysign(double a, double b) { return __builtin_copysign(a, b); }
float copysignf(float a, float b) { return __builtin_copysignf(a, b); }

/* ------------------------------------------------------------------ files */
typedef struct rom_file {
    char name[96];
    const char *rdata;  /* embedded, read-only */
    char *wdata;        /* RAM file */
    size_t size, cap, pos;
    int kind;           /* 0 free, 1 console, 2 read, 3 write */
    int err;
} rom_file_t;

#define RAM_FILES 4
#define RAM_FILE_BYTES (64u << 10)
#define OPEN_MAX_ROM 8
static char ram_store[RAM_FILES][RAM_FILE_BYTES];
static struct { char name[96]; size_t size; bool used; } ram_dir[RAM_FILES];
static rom_file_t open_files[OPEN_MAX_ROM];
static rom_file_t console_out = { .kind = 1 }, console_err = { .kind = 1 };
FILE *stdout = (FILE *)&console_out;
FILE *stderr = (FILE *)&console_err;
FILE *stdin = NULL;

static int ram_find(const char *path)
{
    for (int i = 0; i < RAM_FILES; i++)
        if (ram_dir[i].used && strcmp(ram_dir[i].name, path) == 0) return i;
    return -1;
}

FILE *fopen(const char *path, const char *mode)
{
    rom_file_t *f = NULL;
    for (int i = 0; i < OPEN_MAX_ROM && !f; i++)
        if (!open_files[i].kind) f = &open_files[i];
    if (!f || strlen(path) >= sizeof f->name) return NULL;
    memset(f, 0, sizeof *f);
    snprintf(f->name, sizeof f->name, "%s", path);
    if (mode[0] == 'r') {
        int r = ram_find(path);
        if (r >= 0) {
            f->rdata = ram_store[r];
            f->size = ram_dir[r].size;
        } else {
            uint32_t i = 0;
            for (; i < rom_nfiles; i++)
                if (strcmp(rom_files[i].name, path) == 0) break;
            if (i == rom_nfiles) return NULL;
            f->rdata = rom_files[i].data;
            f->size = rom_files[i].size;
        }
        f->kind = 2;
        return (FILE *)f;
    }
    if (mode[0] == 'w') {
        int r = ram_find(path);
        for (int i = 0; i < RAM_FILES && r < 0; i++)
            if (!ram_dir[i].used) r = i;
        if (r < 0) return NULL;
        ram_dir[r].used = true;
        ram_dir[r].size = 0;
        snprintf(ram_dir[r].name, sizeof ram_dir[r].name, "%s", path);
        f->wdata = ram_store[r];
        f->cap = RAM_FILE_BYTES;
        f->kind = 3;
        return (FILE *)f;
    }
    return NULL;
}

int fclose(FILE *fp)
{
    rom_file_t *f = (rom_file_t *)fp;
    if (!f || f->kind < 2) return 0;
    if (f->kind == 3) {
        int r = ram_find(f->name);
        if (r >= 0) ram_dir[r].size = f->size;
    }
    int err = f->err;
    f->kind = 0;
    return err ? EOF : 0;
}

int remove(const char *path)
{
    int r = ram_find(path);
    if (r < 0) return -1;
    ram_dir[r].used = false;
    return 0;
}

char *fgets(char *buf, int n, FILE *fp)
{
    rom_file_t *f = (rom_file_t *)fp;
    if (!f || f->kind != 2 || n <= 0 || f->pos >= f->size) return NULL;
    int i = 0;
    while (i < n - 1 && f->pos < f->size) {
        char c = f->rdata[f->pos++];
        buf[i++] = c;
        if (c == '\n') break;
    }
    buf[i] = 0;
    return buf;
}

size_t fread(void *p, size_t sz, size_t n, FILE *fp)
{
    rom_file_t *f = (rom_file_t *)fp;
    if (!f || f->kind != 2 || sz == 0) return 0;
    size_t avail = (f->size - f->pos) / sz, k = n < avail ? n : avail;
    memcpy(p, f->rdata + f->pos, k * sz);
    f->pos += k * sz;
    return k;
}

int fseek(FILE *fp, long off, int whence)
{
    rom_file_t *f = (rom_file_t *)fp;
    if (!f || f->kind != 2) return -1;
    long base = whence == SEEK_SET ? 0 : whence == SEEK_CUR ? (long)f->pos : (long)f->size;
    if (base + off < 0 || (size_t)(base + off) > f->size) return -1;
    f->pos = (size_t)(base + off);
    return 0;
}
long ftell(FILE *fp)
{
    rom_file_t *f = (rom_file_t *)fp;
    return f && f->kind == 2 ? (long)f->pos : f && f->kind == 3 ? (long)f->size : -1L;
}
void rewind(FILE *fp) { fseek(fp, 0, SEEK_SET); }

int ferror(FILE *fp) { return fp ? ((rom_file_t *)fp)->err : 1; }
int feof(FILE *fp) { rom_file_t *f = (rom_file_t *)fp; return f && f->kind == 2 && f->pos >= f->size; }
int fflush(FILE *fp) { (void)fp; rom_isv_flush(); return 0; }

static void file_put(rom_file_t *f, const char *s, size_t n)
{
    if (f->kind == 1) {
        for (size_t i = 0; i < n; i++) rom_isv_putc(s[i]);
    } else if (f->kind == 3) {
        if (f->size + n > f->cap) { f->err = 1; n = f->cap - f->size; }
        memcpy(f->wdata + f->size, s, n);
        f->size += n;
    } else {
        f->err = 1;
    }
}

size_t fwrite(const void *p, size_t sz, size_t n, FILE *fp)
{
    file_put((rom_file_t *)fp, p, sz * n);
    return n;
}
int fputc(int c, FILE *fp) { char ch = (char)c; file_put((rom_file_t *)fp, &ch, 1); return (unsigned char)c; }
int putc(int c, FILE *fp) { return fputc(c, fp); }
int putchar(int c) { return fputc(c, stdout); }
int fputs(const char *s, FILE *fp) { file_put((rom_file_t *)fp, s, strlen(s)); return 0; }
int puts(const char *s) { fputs(s, stdout); return fputc('\n', stdout); }

/* directories: the embedded files directly inside the directory. readdir64 is what a
 * suite built with _FILE_OFFSET_BITS=64 calls (test_replays does, for 32-bit hosts). */
struct rom_dirent64 {
    uint64_t d_ino;
    int64_t d_off;
    unsigned short d_reclen;
    unsigned char d_type;
    char d_name[256];
};
typedef struct { char dir[96]; uint32_t next; struct dirent ent; struct rom_dirent64 ent64; } rom_dir_t;
static rom_dir_t dir_slot;
static bool dir_busy;
DIR *opendir(const char *path)
{
    if (dir_busy) return NULL;
    size_t l = strlen(path);
    if (l + 2 > sizeof dir_slot.dir) return NULL;
    bool any = false;
    for (uint32_t i = 0; i < rom_nfiles && !any; i++)
        any = strncmp(rom_files[i].name, path, l) == 0 && rom_files[i].name[l] == '/';
    if (!any) return NULL;
    snprintf(dir_slot.dir, sizeof dir_slot.dir, "%s/", path);
    dir_slot.next = 0;
    dir_busy = true;
    return (DIR *)&dir_slot;
}
static const char *next_entry(rom_dir_t *r)
{
    size_t l = strlen(r->dir);
    while (r->next < rom_nfiles) {
        const char *n = rom_files[r->next++].name;
        if (strncmp(n, r->dir, l) == 0 && n[l] && !strchr(n + l, '/')) return n + l;
    }
    return NULL;
}
struct dirent *readdir(DIR *d)
{
    rom_dir_t *r = (rom_dir_t *)d;
    const char *n = next_entry(r);
    if (!n) return NULL;
    memset(&r->ent, 0, sizeof r->ent);
    snprintf(r->ent.d_name, sizeof r->ent.d_name, "%s", n);
    r->ent.d_type = DT_REG;
    return &r->ent;
}
struct rom_dirent64 *rom_readdir64(DIR *d) __asm__("readdir64");
struct rom_dirent64 *rom_readdir64(DIR *d)
{
    rom_dir_t *r = (rom_dir_t *)d;
    const char *n = next_entry(r);
    if (!n) return NULL;
    memset(&r->ent64, 0, sizeof r->ent64);
    snprintf(r->ent64.d_name, sizeof r->ent64.d_name, "%s", n);
    r->ent64.d_type = DT_REG;
    return &r->ent64;
}
int closedir(DIR *d) { (void)d; dir_busy = false; return 0; }

/* ------------------------------------------------------------------ formatted output */
typedef struct { char *buf; size_t cap, len; rom_file_t *f; } sink_t;

static void out_n(sink_t *o, const char *s, size_t n)
{
    if (o->f) file_put(o->f, s, n);
    else
        for (size_t i = 0; i < n; i++, o->len++)
            if (o->len + 1 < o->cap) o->buf[o->len] = s[i];
    if (o->f) o->len += n;
}
static void out_c(sink_t *o, char c, int n) { while (n-- > 0) out_n(o, &c, 1); }

static int fmt_uint(char *tmp, unsigned long long v, unsigned base, bool upper)
{
    const char *dig = upper ? "0123456789ABCDEF" : "0123456789abcdef";
    int n = 0;
    do { tmp[n++] = dig[v % base]; v /= base; } while (v);
    for (int i = 0; i < n / 2; i++) { char t = tmp[i]; tmp[i] = tmp[n - 1 - i]; tmp[n - 1 - i] = t; }
    return n;
}

/* %a like glibc: 0x1.hhhp+e, trailing zeros dropped; 0x0p+0 for zero */
static int fmt_hexfloat(char *tmp, double v, bool upper, int prec)
{
    union { double d; uint64_t u; } b = { v };
    int n = 0;
    uint64_t mant = b.u & ((1ull << 52) - 1);
    int ex = (int)(b.u >> 52 & 0x7ff);
    int lead = 1;
    if (ex == 0) {
        if (mant == 0) { lead = 0; ex = 0; }
        else { lead = 0; ex = -1022; }
    } else {
        ex -= 1023;
    }
    tmp[n++] = '0'; tmp[n++] = upper ? 'X' : 'x'; tmp[n++] = (char)('0' + lead);
    int nd = 13;
    if (prec < 0) {
        while (nd > 0 && ((mant >> (4 * (13 - nd))) & 15) == 0) nd--;
    } else {
        nd = prec < 13 ? prec : 13; /* truncation (the tests print full precision) */
    }
    if (nd > 0) tmp[n++] = '.';
    for (int i = 0; i < nd; i++) tmp[n++] = (upper ? "0123456789ABCDEF" : "0123456789abcdef")[(mant >> (48 - 4 * i)) & 15];
    tmp[n++] = upper ? 'P' : 'p';
    tmp[n++] = ex < 0 ? '-' : '+';
    n += fmt_uint(tmp + n, (unsigned long long)(ex < 0 ? -ex : ex), 10, false);
    return n;
}

/* %f / %e (%g picks one): digits by repeated scaling, good to ~15 significant digits */
static int fmt_fixed(char *tmp, double v, int prec)
{
    int n = 0;
    if (prec > 17) prec = 17;
    double r = 0.5 * pow10i(-prec);
    v += r;
    if (v >= 1e18) { /* out of range for the integer part: fall back to %e-like */
        n += snprintf(tmp, 64, "%e", v);
        return n;
    }
    unsigned long long ip = (unsigned long long)v;
    n += fmt_uint(tmp + n, ip, 10, false);
    double fr = v - (double)ip;
    if (prec > 0) tmp[n++] = '.';
    for (int i = 0; i < prec; i++) {
        fr *= 10.0;
        int d = (int)fr;
        if (d > 9) d = 9;
        tmp[n++] = (char)('0' + d);
        fr -= d;
    }
    return n;
}
static int fmt_exp(char *tmp, double v, int prec, bool upper)
{
    int e = 0;
    if (v != 0) {
        while (v >= 10.0) { v /= 10.0; e++; }
        while (v < 1.0) { v *= 10.0; e--; }
        double r = 0.5 * pow10i(-prec);
        if (v + r >= 10.0) { v /= 10.0; e++; }
    }
    int n = fmt_fixed(tmp, v, prec);
    tmp[n++] = upper ? 'E' : 'e';
    tmp[n++] = e < 0 ? '-' : '+';
    if (e < 0) e = -e;
    if (e < 10) tmp[n++] = '0';
    n += fmt_uint(tmp + n, (unsigned)e, 10, false);
    return n;
}

static int do_format(sink_t *o, const char *fmt, va_list ap)
{
    char tmp[400];
    for (const char *p = fmt; *p; p++) {
        if (*p != '%') { out_n(o, p, 1); continue; }
        p++;
        bool left = false, zero = false, plus = false, space = false, alt = false;
        for (;; p++) {
            if (*p == '-') left = true;
            else if (*p == '0') zero = true;
            else if (*p == '+') plus = true;
            else if (*p == ' ') space = true;
            else if (*p == '#') alt = true;
            else break;
        }
        int width = 0, prec = -1;
        if (*p == '*') { width = va_arg(ap, int); if (width < 0) { left = true; width = -width; } p++; }
        else while (*p >= '0' && *p <= '9') width = width * 10 + (*p++ - '0');
        if (*p == '.') {
            p++;
            prec = 0;
            if (*p == '*') { prec = va_arg(ap, int); p++; }
            else while (*p >= '0' && *p <= '9') prec = prec * 10 + (*p++ - '0');
        }
        int lng = 0; /* 0 int, 1 long, 2 long long, 3 size_t/ptrdiff, -1 short, -2 char */
        for (;; p++) {
            if (*p == 'l') lng = lng == 1 ? 2 : 1;
            else if (*p == 'h') lng = lng == -1 ? -2 : -1;
            else if (*p == 'z' || *p == 't') lng = 3;
            else if (*p == 'j' || *p == 'q') lng = 2;
            else if (*p == 'L') lng = 0;
            else break;
        }
        char c = *p;
        if (!c) break;
        const char *body = tmp;
        int n = 0;
        char sign = 0;
        const char *prefix = "";
        switch (c) {
        case 'd': case 'i': {
            long long v = lng == 2 ? va_arg(ap, long long) : lng == 1 ? va_arg(ap, long) :
                          lng == 3 ? (long long)va_arg(ap, ptrdiff_t) : va_arg(ap, int);
            if (lng == -1) v = (short)v;
            if (lng == -2) v = (signed char)v;
            unsigned long long u = v < 0 ? 0ull - (unsigned long long)v : (unsigned long long)v;
            if (v < 0) sign = '-'; else if (plus) sign = '+'; else if (space) sign = ' ';
            n = prec == 0 && u == 0 ? 0 : fmt_uint(tmp, u, 10, false);
            break;
        }
        case 'u': case 'x': case 'X': case 'o': {
            unsigned long long u = lng == 2 ? va_arg(ap, unsigned long long) : lng == 1 ? va_arg(ap, unsigned long) :
                                   lng == 3 ? (unsigned long long)va_arg(ap, size_t) : va_arg(ap, unsigned);
            if (lng == -1) u = (unsigned short)u;
            if (lng == -2) u = (unsigned char)u;
            unsigned base = c == 'u' ? 10 : c == 'o' ? 8 : 16;
            n = prec == 0 && u == 0 ? 0 : fmt_uint(tmp, u, base, c == 'X');
            if (alt && u && base == 16) prefix = c == 'X' ? "0X" : "0x";
            break;
        }
        case 'p': {
            uintptr_t u = (uintptr_t)va_arg(ap, void *);
            prefix = "0x";
            n = fmt_uint(tmp, u, 16, false);
            break;
        }
        case 'c': tmp[0] = (char)va_arg(ap, int); n = 1; prec = -1; break;
        case 's': {
            const char *s = va_arg(ap, const char *);
            if (!s) s = "(null)";
            size_t l = strlen(s);
            if (prec >= 0 && (size_t)prec < l) l = (size_t)prec;
            body = s;
            n = (int)l;
            prec = -1;
            break;
        }
        case 'f': case 'F': case 'e': case 'E': case 'g': case 'G': case 'a': case 'A': {
            double v = va_arg(ap, double);
            if (__builtin_signbit(v)) { sign = '-'; v = -v; } else if (plus) sign = '+'; else if (space) sign = ' ';
            if (v != v) { strcpy(tmp, c >= 'a' ? "nan" : "NAN"); n = 3; }
            else if (__builtin_isinf(v)) { strcpy(tmp, c >= 'a' ? "inf" : "INF"); n = 3; }
            else if (c == 'a' || c == 'A') n = fmt_hexfloat(tmp, v, c == 'A', prec);
            else if (c == 'f' || c == 'F') n = fmt_fixed(tmp, v, prec < 0 ? 6 : prec);
            else if (c == 'e' || c == 'E') n = fmt_exp(tmp, v, prec < 0 ? 6 : prec, c == 'E');
            else {
                int P = prec < 0 ? 6 : prec == 0 ? 1 : prec;
                int e = 0;
                double w = v;
                if (w != 0) { while (w >= 10.0) { w /= 10.0; e++; } while (w < 1.0) { w *= 10.0; e--; } }
                if (e < -4 || e >= P) n = fmt_exp(tmp, v, P - 1, c == 'G');
                else n = fmt_fixed(tmp, v, P - 1 - e);
                if (!alt && memchr(tmp, '.', (size_t)n)) { /* strip trailing zeros */
                    int epos = n;
                    for (int i = 0; i < n; i++) if (tmp[i] == 'e' || tmp[i] == 'E') { epos = i; break; }
                    int q = epos;
                    while (q > 0 && tmp[q - 1] == '0') q--;
                    if (q > 0 && tmp[q - 1] == '.') q--;
                    memmove(tmp + q, tmp + epos, (size_t)(n - epos));
                    n -= epos - q;
                }
            }
            prec = -1;
            zero = zero && !left;
            break;
        }
        case '%': tmp[0] = '%'; n = 1; prec = -1; break;
        case 'n': { int *np = va_arg(ap, int *); *np = (int)o->len; continue; }
        default: tmp[0] = '%'; tmp[1] = c; n = 2; prec = -1; break;
        }
        int digits_pad = prec > n ? prec - n : 0;
        int total = (sign ? 1 : 0) + (int)strlen(prefix) + digits_pad + n;
        int pad = width > total ? width - total : 0;
        if (!left && !(zero && prec < 0)) out_c(o, ' ', pad);
        if (sign) out_n(o, &sign, 1);
        out_n(o, prefix, strlen(prefix));
        if (!left && zero && prec < 0) out_c(o, '0', pad);
        out_c(o, '0', digits_pad);
        out_n(o, body, (size_t)n);
        if (left) out_c(o, ' ', pad);
    }
    return (int)o->len;
}

int vsnprintf(char *buf, size_t cap, const char *fmt, va_list ap)
{
    sink_t o = { buf, cap, 0, NULL };
    int n = do_format(&o, fmt, ap);
    if (cap) buf[o.len < cap ? o.len : cap - 1] = 0;
    return n;
}
int snprintf(char *buf, size_t cap, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    int n = vsnprintf(buf, cap, fmt, ap);
    va_end(ap);
    return n;
}
int sprintf(char *buf, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    int n = vsnprintf(buf, (size_t)-1 / 2, fmt, ap);
    va_end(ap);
    return n;
}
int vfprintf(FILE *fp, const char *fmt, va_list ap)
{
    sink_t o = { NULL, 0, 0, (rom_file_t *)fp };
    return do_format(&o, fmt, ap);
}
int fprintf(FILE *fp, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    int n = vfprintf(fp, fmt, ap);
    va_end(ap);
    return n;
}
int vprintf(const char *fmt, va_list ap) { return vfprintf(stdout, fmt, ap); }
int printf(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    int n = vfprintf(stdout, fmt, ap);
    va_end(ap);
    return n;
}
