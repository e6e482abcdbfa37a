/* setjmp for the test ROM (host_tests/n64/crt0.S): replaces the C library's header. */
#ifndef ROM_SETJMP_H
#define ROM_SETJMP_H
typedef long long jmp_buf[24];
int setjmp(jmp_buf env);
void longjmp(jmp_buf env, int val) __attribute__((noreturn));
#endif
