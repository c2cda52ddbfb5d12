/* test_swt.c - unit tests of regime/tools that need no kernel run: the interface
 * fit (GSL) against known polynomials, the regime.coeffs writer read back by the
 * wall model's reader, atomic output sets, strict option parsing. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include <cmocka.h>

#include "sww.h"
#include "swt_fit.h"
#include "swt_io.h"
#include "swt_vcrit.h"

/* points of ln d = c0 + c1 x + c2 x^2 + c3 x^3, x = ln v */
static void make_points(swt_interface *it, int n, const double *c, int deg, double noise)
{
    it->n = n;
    it->vn = malloc((size_t)n * sizeof(double));
    it->dcrit = malloc((size_t)n * sizeof(double));
    for (int k = 0; k < n; k++) {
        double v = 0.5 * pow(20.0, (double)k / (n - 1)), x = log(v), y = 0.0;
        for (int i = deg; i >= 0; i--) y = y * x + c[i];
        it->vn[k] = v;
        it->dcrit[k] = exp(y) * (1.0 + noise * ((k % 2) ? 1.0 : -1.0));
    }
}

static void fit_recovers_polynomial(void **s)
{
    (void)s;
    const double c[4] = { -9.5, -0.9, -0.05, 0.004 };
    swt_interface it = { 0 };
    make_points(&it, 30, c, 3, 0.0);
    swt_fit f;
    char err[300];
    assert_int_equal(swt_fit_interface(&it, 3, &f, err, sizeof err), 0);
    assert_int_equal(f.degree, 3);
    for (int i = 0; i <= 3; i++) assert_true(fabs(f.c[i] - c[i]) < 1e-9);
    assert_true(f.rms < 1e-12 && f.maxres < 1e-12);
    assert_true(f.decreasing);
    assert_true(f.slope_lo < 0.0 && f.slope_hi < 0.0);
    swt_interface_free(&it);
}

static void fit_reports_residuals(void **s)
{
    (void)s;
    const double c[2] = { -10.0, -1.2 };
    swt_interface it = { 0 };
    make_points(&it, 20, c, 1, 0.01);   /* +-1 % alternating */
    swt_fit f;
    char err[300];
    assert_int_equal(swt_fit_interface(&it, 1, &f, err, sizeof err), 0);
    assert_true(fabs(f.maxres - 0.01) < 1.5e-3);
    assert_true(fabs(f.rms - 0.01) < 1.5e-3);
    assert_true(fabs(f.slope_lo + 1.2) < 0.05);
    swt_interface_free(&it);
}

static void fit_refuses_bad_input(void **s)
{
    (void)s;
    const double c[2] = { -10.0, -1.2 }, up[2] = { -10.0, 0.8 };
    swt_interface it = { 0 };
    swt_fit f;
    char err[300];
    make_points(&it, 3, c, 1, 0.0);
    assert_int_equal(swt_fit_interface(&it, 3, &f, err, sizeof err), -1);  /* 3 points, degree 3 */
    assert_non_null(strstr(err, "only 3 interface points"));
    assert_int_equal(swt_fit_interface(&it, 0, &f, err, sizeof err), -1);
    assert_non_null(strstr(err, "--degree"));
    swt_interface_free(&it);
    make_points(&it, 10, up, 1, 0.0);   /* increasing: no valid interface */
    assert_int_equal(swt_fit_interface(&it, 2, &f, err, sizeof err), -1);
    assert_non_null(strstr(err, "not decreasing"));
    swt_interface_free(&it);
}

/* a cubic that turns up inside the span: the fit lowers the degree and says so */
static void fit_lowers_degree_when_not_monotone(void **s)
{
    (void)s;
    const double c[4] = { -10.0, -1.0, 0.0, 0.1 };
    swt_interface it = { 0 };
    make_points(&it, 25, c, 3, 0.0);
    swt_fit f;
    char err[300];
    assert_int_equal(swt_fit_interface(&it, 3, &f, err, sizeof err), 0);
    assert_true(f.degree < 3);
    assert_true(f.decreasing);
    assert_non_null(strstr(f.note, "lowered"));
    swt_interface_free(&it);
}

static void coeffs_file_reads_back(void **s)
{
    (void)s;
    const double c[4] = { -9.5, -0.9, -0.05, 0.004 };
    swt_interface it = { 0 };
    make_points(&it, 30, c, 3, 0.0);
    swt_fit f;
    char err[300];
    assert_int_equal(swt_fit_interface(&it, 3, &f, err, sizeof err), 0);
    swr_params p;
    swr_params_default(&p);
    char path[] = "/tmp/test_swt_coeffs_XXXXXX";
    int fd = mkstemp(path);
    assert_true(fd >= 0);
    FILE *fp = fdopen(fd, "w");
    swt_coeffs_write(fp, &f, &p, 10e-6, 100e-6, "unit test");
    fclose(fp);
    sww_model *m = sww_alloc();
    int rc = sww_regime_load(m, path);
    if (rc != 0) fprintf(stderr, "%s\n", sww_errmsg(m));
    assert_int_equal(rc, 0);
    for (int k = 0; k < it.n; k++) assert_true(fabs(sww_dcrit(m, it.vn[k]) / it.dcrit[k] - 1.0) < 1e-9);
    assert_true(fabs(sww_vn_min(m) - it.vn[0]) < 1e-9 * it.vn[0]);
    assert_string_equal(sww_label(m), "unit test");
    sww_free(m);
    unlink(path);
    swt_interface_free(&it);
}

/* the output sets and the comma lists: tests/common/test_swo.c */

static void parse_is_strict(void **s)
{
    (void)s;
    double v;
    long n;
    char err[300];
    assert_int_equal(swt_parse_double("--x", "1.5e-3", 0, 1, &v, err, sizeof err), 0);
    assert_true(v == 1.5e-3);
    assert_int_equal(swt_parse_double("--x", "1.5abc", 0, 1, &v, err, sizeof err), -1);
    assert_non_null(strstr(err, "--x: '1.5abc'"));
    assert_int_equal(swt_parse_double("--x", "nan", 0, 1, &v, err, sizeof err), -1);
    assert_int_equal(swt_parse_double("--x", "inf", 0, 1e300, &v, err, sizeof err), -1);
    assert_int_equal(swt_parse_double("--x", "-1", 1e-300, 1, &v, err, sizeof err), -1);
    assert_non_null(strstr(err, "(0, 1]"));
    assert_int_equal(swt_parse_double("--x", "", 0, 1, &v, err, sizeof err), -1);
    assert_int_equal(swt_parse_int("--n", "12", 2, 20, &n, err, sizeof err), 0);
    assert_int_equal(n, 12);
    assert_int_equal(swt_parse_int("--n", "1.5", 2, 20, &n, err, sizeof err), -1);
    assert_int_equal(swt_parse_int("--n", "99999999999999999999", 2, 20, &n, err, sizeof err), -1);
}

/* synthetic outcomes: sticks on the union of intervals [lo_k, hi_k) */
typedef struct {
    int n;
    double lo[4], hi[4];
    long calls;
} bands;

static int band_sticks(void *p, double v, swt_vcrit_result *r)
{
    bands *b = p;
    b->calls++;
    r->collisions++;
    for (int k = 0; k < b->n; k++)
        if (v >= b->lo[k] && v < b->hi[k]) return 1;
    return 0;
}

static int fail_sticks(void *p, double v, swt_vcrit_result *r)
{
    (void)p; (void)v;
    snprintf(r->msg, sizeof r->msg, "kernel says no");
    return -1;
}

static void vcrit_search_bisects_to_tolerance(void **s)
{
    (void)s;
    const double tols[3] = { 1e-2, 1e-3, 1e-6 }, vstar[4] = { 0.00123, 0.4567, 3.21, 49.0 };
    for (int t = 0; t < 3; t++)
        for (int k = 0; k < 4; k++) {
            bands b = { 1, { 0.0 }, { vstar[k] }, 0 };
            swt_vcrit_opts o;
            swt_vcrit_opts_default(&o);
            o.rtol = tols[t];
            swt_vcrit_result r;
            assert_int_equal(swt_vcrit_search(band_sticks, &b, &o, &r), SWT_VCRIT_FOUND);
            assert_true(fabs(r.vcrit / vstar[k] - 1.0) <= 0.5 * tols[t] + 1e-12);
            assert_true(r.v_lo < vstar[k] && r.v_hi >= vstar[k]);
            assert_true(r.v_hi / r.v_lo <= 1.0 + tols[t]);
            assert_int_equal(r.changes, 1);
            assert_int_equal(r.collisions, b.calls);
            /* scan (~16) + bisection (log2(ln 2 / tol)) */
            assert_true(b.calls <= 17 + (long)ceil(log2(log(2.0) / tols[t])) + 1);
        }
}

static void vcrit_search_reports_ranges_and_nonmonotone(void **s)
{
    (void)s;
    swt_vcrit_opts o;
    swt_vcrit_opts_default(&o);
    swt_vcrit_result r;
    bands all = { 1, { 0.0 }, { 1e9 }, 0 }, none = { 0, { 0 }, { 0 }, 0 };
    assert_int_equal(swt_vcrit_search(band_sticks, &all, &o, &r), SWT_VCRIT_ALL_STICK);
    assert_true(r.vcrit == o.vmax && r.changes == 0);
    assert_int_equal(swt_vcrit_search(band_sticks, &none, &o, &r), SWT_VCRIT_NO_STICK);
    assert_true(r.vcrit == o.vmin && r.changes == 0);
    /* sticks below 0.2, bounces, sticks again in [2, 5): first change is v_crit */
    bands two = { 2, { 0.0, 2.0 }, { 0.2, 5.0 }, 0 };
    assert_int_equal(swt_vcrit_search(band_sticks, &two, &o, &r), SWT_VCRIT_FOUND);
    assert_true(fabs(r.vcrit / 0.2 - 1.0) <= 0.5 * o.rtol + 1e-12);
    assert_int_equal(r.changes, 3);
    assert_true(r.v_restick >= 2.0 && r.v_restick < 5.0);
    /* bounces at low speed, sticks in [0.5, 3): found, and the extra change is counted */
    bands mid = { 1, { 0.5 }, { 3.0 }, 0 };
    assert_int_equal(swt_vcrit_search(band_sticks, &mid, &o, &r), SWT_VCRIT_FOUND);
    assert_true(fabs(r.vcrit / 3.0 - 1.0) <= 0.5 * o.rtol + 1e-12);
    assert_int_equal(r.changes, 2);
    /* only bounce -> stick in range: no critical velocity, change reported */
    bands up = { 1, { 1.0 }, { 1e9 }, 0 };
    assert_int_equal(swt_vcrit_search(band_sticks, &up, &o, &r), SWT_VCRIT_NO_STICK);
    assert_int_equal(r.changes, 1);
    /* errors propagate with the message */
    assert_int_equal(swt_vcrit_search(fail_sticks, NULL, &o, &r), SWT_VCRIT_ERROR);
    assert_string_equal(r.msg, "kernel says no");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(vcrit_search_bisects_to_tolerance),
        cmocka_unit_test(vcrit_search_reports_ranges_and_nonmonotone),
        cmocka_unit_test(fit_recovers_polynomial),
        cmocka_unit_test(fit_reports_residuals),
        cmocka_unit_test(fit_refuses_bad_input),
        cmocka_unit_test(fit_lowers_degree_when_not_monotone),
        cmocka_unit_test(coeffs_file_reads_back),
        cmocka_unit_test(parse_is_strict),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
