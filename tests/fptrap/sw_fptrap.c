/* sw_fptrap.c - floating-point traps for the C tests, as OpenFOAM sets them.
 *
 * Linked into every C test program (sw_add_ctest) and, in a build with
 * SNOWWALL_FPTRAP=ON (the sanitizer test build of ./Alltest), into the programs
 * the script tests run (snowregime, snowphoto, the check tools). Before main()
 * it enables the traps OpenFOAM sets (FOAM_SIGFPE): invalid operation, division
 * by zero and overflow raise SIGFPE, so a NaN formed by arithmetic, a NaN in an
 * ordered comparison, or an overflow fails the test instead of a user's run.
 * Underflow and inexact stay untrapped (as in OpenFOAM). SW_FPTRAP=0 in the
 * environment leaves them off (to compare a failing run without traps).
 * Quiet NaN and infinity constants (NAN, INFINITY) and isnan/isinf/isfinite do
 * not trap: code that uses them as sentinels must test them with those, never
 * with <, <=, >, >= (which raise FE_INVALID on a NaN). */
#define _GNU_SOURCE 1 /* feenableexcept: a glibc extension */
#include <fenv.h>
#include <stdlib.h>
#include <string.h>

__attribute__((constructor)) static void sw_fptrap_enable(void)
{
    const char *e = getenv("SW_FPTRAP");
    if (e && strcmp(e, "0") == 0)
        return;
    feenableexcept(FE_INVALID | FE_DIVBYZERO | FE_OVERFLOW);
}
