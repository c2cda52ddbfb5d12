/* test_swe_ladder.c - the runs against each other (tools/snowwedge, swe_ladder.h)
 * on synthetic data with known answers: the Strouhal number's resolution error
 * of a window, the pressure coefficient's scale, the keys of level.txt, the
 * check of the collector's rows, the change between two resolutions with its
 * standard error, z and verdict, numbers written as awk writes them, and the
 * ranges of the error plot. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <string.h>
#include <cmocka.h>

#include "swe_ladder.h"
#include "swe_spray.h"

#define ASSERT_NEAR(x, ref, tol) assert_true(fabs((x) - (ref)) <= (tol))

/* the peak of a window W is known to +- 1/(2W): a uniform error of standard
   deviation 1/(W sqrt(12)) in frequency, H/U of it in St; twice the window,
   half the error */
static void strouhal_error(void **st)
{
    (void)st;
    ASSERT_NEAR(swe_ladder_st_error(0.4, 0.8), 0.12 / 19.444 / (0.4 * sqrt(12)), 1e-17);
    ASSERT_NEAR(swe_ladder_st_error(0.4, 0.8), 0.00445395, 5e-9);
    ASSERT_NEAR(swe_ladder_st_error(0, 0.8), swe_ladder_st_error(0.4, 0.8) / 2, 1e-17);
    /* Cp = p / (0.5 U^2): 0.5 x 19.444^2 = 189.034568 */
    ASSERT_NEAR(1 / swe_ladder_cp_scale(), 189.034568, 1e-9);
}

static void level_keys(void **st)
{
    (void)st;
    const char *t = "# written by Allrun\nlevel -1\n  window 0.4   0.8\nwindowx 3\nmvd 20\ngate";
    char v[64];
    assert_int_equal(swe_ladder_key(t, "window", v, sizeof v), 0);
    assert_string_equal(v, "0.4 0.8"); /* the fields joined by one blank */
    assert_int_equal(swe_ladder_key(t, "level", v, sizeof v), 0);
    assert_string_equal(v, "-1");
    assert_int_equal(swe_ladder_key(t, "windowx", v, sizeof v), 0);
    assert_string_equal(v, "3");
    assert_int_equal(swe_ladder_key(t, "gate", v, sizeof v), 0); /* a key without value */
    assert_string_equal(v, "");
    assert_int_equal(swe_ladder_key(t, "cells", v, sizeof v), SWE_EINVAL);
    assert_int_equal(swe_ladder_key(t, "win", v, sizeof v), SWE_EINVAL); /* whole words only */
}

static void rows(void **st)
{
    (void)st;
    assert_true(swe_ladder_row_ok("Cd,L-1,default,-1,37444,0.0004,0.37,0.01,142.7,138.2"));
    assert_true(swe_ladder_row_ok("St,L1,full,1,1000,0.0004,0.12,0.004,1,2"));
    assert_false(swe_ladder_row_ok("Cd,L-1,default,-1,37444,0.0004,0.37,0.01,142.7"));  /* 9 */
    assert_false(swe_ladder_row_ok("Cd,L-1,default,-1,37444,0.0004,0.37,0.01,142.7,1,2")); /* 11 */
    assert_false(swe_ladder_row_ok("Cd,L-1,default,x,37444,0.0004,0.37,0.01,142.7,138.2"));
    assert_false(swe_ladder_row_ok("Cd,L-1,default,-1,-37444,0.0004,0.37,0.01,142.7,138.2"));
    assert_false(swe_ladder_row_ok("Cd,L-1,default,1.5,37444,0.0004,0.37,0.01,142.7,138.2"));
    assert_false(swe_ladder_row_ok("Cd,L-1,default,,37444,0.0004,0.37,0.01,142.7,138.2"));
    char f[32];
    swe_ladder_field("a,,c", ',', 1, f, sizeof f);
    assert_string_equal(f, "");
    swe_ladder_field("a,,c", ',', 2, f, sizeof f);
    assert_string_equal(f, "c");
    swe_ladder_field("a,,c", ',', 3, f, sizeof f);
    assert_string_equal(f, "");
}

/* B = 100 +- 3, R = 110 +- 4: z = 10 / 5 = 2 (agrees, at the edge), change 10 %
   with se 1.1 sqrt(0.03^2 + (4/110)^2); R = 115: z 3, differs */
static void change(void **st)
{
    (void)st;
    swe_change c;
    swe_ladder_change(100, 3, 110, 4, &c);
    assert_int_equal(c.kind, SWE_CHANGE_AGREES);
    ASSERT_NEAR(c.z, 2, 1e-14);
    ASSERT_NEAR(c.change, 0.1, 1e-14);
    const double se = 1.1 * sqrt(0.03 * 0.03 + (4 / 110.0) * (4 / 110.0));
    ASSERT_NEAR(c.se_change, se, 1e-14);
    ASSERT_NEAR(c.bound, 0.1 + 2 * se, 1e-14);
    swe_ladder_change(100, 3, 85, 4, &c);
    assert_int_equal(c.kind, SWE_CHANGE_DIFFERS);
    ASSERT_NEAR(c.z, -3, 1e-14);
    swe_ladder_change(0, 0, 0, 0, &c);
    assert_int_equal(c.kind, SWE_CHANGE_NONE);
    swe_ladder_change(0, 0, 5, 1, &c); /* snow in the refined run only */
    assert_int_equal(c.kind, SWE_CHANGE_ONE);
    swe_ladder_change(5, 0, 5, 0, &c); /* no error to weigh the change with */
    assert_int_equal(c.kind, SWE_CHANGE_ONE);
    swe_ladder_change(10, 1, 0, 0, &c); /* the refined run bare: change -100 % */
    assert_int_equal(c.kind, SWE_CHANGE_DIFFERS);
    ASSERT_NEAR(c.change, -1, 1e-15);
    ASSERT_NEAR(c.se_change, 0, 1e-15);
}

static void awk_numbers(void **st)
{
    (void)st;
    char b[64];
    swe_ladder_awknum(3, b, sizeof b);
    assert_string_equal(b, "3");
    swe_ladder_awknum(-40, b, sizeof b);
    assert_string_equal(b, "-40");
    swe_ladder_awknum(2.5, b, sizeof b);
    assert_string_equal(b, "2.5");
    swe_ladder_awknum(1 / 3.0, b, sizeof b);
    assert_string_equal(b, "0.333333");
    swe_ladder_awknum(1.23456789e-5, b, sizeof b);
    assert_string_equal(b, "1.23457e-05");
    swe_ladder_awknum(123456789.5, b, sizeof b);
    assert_string_equal(b, "1.23457e+08");
}

/* points (10, 5) and (1000, 50), targets 10 and 30 %: x 5 .. 2000, y 5/1.5 ..
   75; a target below every point widens the range; a time of 0 becomes 1e-3 */
static void plot_range(void **st)
{
    (void)st;
    const double x[2] = {10, 1000}, y[2] = {5, 50}, t[2] = {10, 30}, t2[1] = {1};
    double r[4];
    assert_int_equal(swe_ladder_plot_range(x, y, 2, t, 2, r, NULL, 0), 0);
    ASSERT_NEAR(r[0], 5, 1e-15);
    ASSERT_NEAR(r[1], 2000, 1e-12);
    ASSERT_NEAR(r[2], 5 / 1.5, 1e-15);
    ASSERT_NEAR(r[3], 75, 1e-13);
    assert_int_equal(swe_ladder_plot_range(x, y, 2, t2, 1, r, NULL, 0), 0);
    ASSERT_NEAR(r[2], 1 / 1.5, 1e-15);
    ASSERT_NEAR(r[3], 75, 1e-13);
    const double x0[2] = {0, 100};
    assert_int_equal(swe_ladder_plot_range(x0, y, 2, t, 2, r, NULL, 0), 0);
    ASSERT_NEAR(r[0], 5e-4, 1e-18);
    char err[128];
    assert_int_equal(swe_ladder_plot_range(x, y, 0, t, 2, r, err, sizeof err), SWE_EINVAL);
    assert_non_null(strstr(err, "no point"));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(strouhal_error), cmocka_unit_test(level_keys),
        cmocka_unit_test(rows),           cmocka_unit_test(change),
        cmocka_unit_test(awk_numbers),    cmocka_unit_test(plot_range),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
