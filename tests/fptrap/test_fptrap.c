/* test_fptrap.c - the floating-point traps of the C tests are on:
 * sw_fptrap.c, linked into every C test, enabled invalid, divide by zero and
 * overflow before main(); a quiet NaN or an infinity used as a value (the
 * sentinels of the code) and isnan/isinf do not trap. */
#define _GNU_SOURCE 1 /* fegetexcept */
#include <fenv.h>
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

static void traps_on(void **state)
{
    (void)state;
    const char *e = getenv("SW_FPTRAP");
    if (e && strcmp(e, "0") == 0)
        skip();
    const int want = FE_INVALID | FE_DIVBYZERO | FE_OVERFLOW;
    assert_int_equal(fegetexcept() & want, want);
}

static void sentinels_do_not_trap(void **state)
{
    (void)state;
    volatile double nan = NAN, inf = INFINITY, big = 1e308;
    assert_true(isnan(nan) && isinf(inf) && !isfinite(nan) && isfinite(big));
    assert_true(nan != nan); /* == and != are quiet comparisons */
    volatile double s = nan + 1.0; /* arithmetic on a quiet NaN raises nothing */
    assert_true(isnan(s));
    assert_true(fmin(inf, big) == big);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(traps_on),
        cmocka_unit_test(sentinels_do_not_trap),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
