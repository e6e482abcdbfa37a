/*
 * Tests the emulator cannot run (linked into the test ROMs, not the bench ROM).
 */
#include <string.h>
#include "unity.h"

/* ---------------------------------------------------------------- tests the emulator cannot run
 * mupen64plus's interpreters stop the whole emulation ("Invalid operation exception in C
 * opcode") when an ordered compare (c.lt.s, c.le.s, ...: C's <, <=, >, >=) sees a NaN,
 * where the VR4300 only sets the Invalid cause bit (its trap is disabled); its dynamic
 * recompiler instead evaluates unordered compares (c.ult.s, ...) wrongly for NaN. The tests
 * that feed NaN on purpose are reported as ignored on the console, with this reason; the
 * linker routes every RUN_TEST through here (--wrap=UnityDefaultTestRun). */
static const char *const emulator_skips[] = {
#include "rom_skips.h"
    NULL
};
void __real_UnityDefaultTestRun(UnityTestFunction func, const char *name, const int line);
void __wrap_UnityDefaultTestRun(UnityTestFunction func, const char *name, const int line);
static void skipped_on_emulator(void)
{
    TEST_IGNORE_MESSAGE("feeds NaN to ordered compares: mupen64plus stops on them (the VR4300 does not)");
}
void __wrap_UnityDefaultTestRun(UnityTestFunction func, const char *name, const int line)
{
    for (int i = 0; emulator_skips[i]; i++)
        if (strcmp(emulator_skips[i], name) == 0) func = skipped_on_emulator;
    __real_UnityDefaultTestRun(func, name, line);
}
