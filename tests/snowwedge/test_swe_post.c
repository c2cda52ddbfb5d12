/* test_swe_post.c - the per-run post-processing of the wedge (tools/snowwedge
 * swe_post.h) on synthetic files with known answers: the readers of
 * surfaceFieldValue.dat, snowWall.dat, reasons.dat, raw surface files,
 * Lagrangian records and the solver log; the halves of the window with their
 * Poisson error, the Stokes number of the wake and the fill of the wake
 * (stationary and censored); missing inputs give a named error. */
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

#include "swe_post.h"

#define ASSERT_NEAR(x, ref, tol) assert_true(fabs((x) - (ref)) <= (tol))

static char dir[64];

static const char *put(const char *name, const char *text)
{
    static char path[8][256];
    static int k;
    char *p = path[k++ % 8];
    snprintf(p, 256, "%s/%s", dir, name);
    FILE *f = fopen(p, "w");
    assert_non_null(f);
    fputs(text, f);
    fclose(f);
    return p;
}

static int setup(void **st)
{
    (void)st;
    snprintf(dir, sizeof dir, "/tmp/test_swe_post.XXXXXX");
    return mkdtemp(dir) ? 0 : -1;
}

static int teardown(void **st)
{
    (void)st;
    char cmd[128];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", dir);
    return system(cmd);
}

/* awk's "%s" of a number: integers as they are, others to 6 digits */
static void rounding(void **st)
{
    (void)st;
    assert_true(swe_post_awk_str(12) == 12);
    assert_true(swe_post_awk_str(1.23456789e-5) == 1.23457e-5);
    assert_true(swe_post_round(0.123456789012, 10) == 0.123456789);
    assert_true(swe_post_same_time(0.4 + 1e-10, 0.4));
    assert_false(swe_post_same_time(0.41, 0.4));
}

/* the column of the header, at a time or the last row; missing ones named */
static void field_table(void **st)
{
    (void)st;
    const char *p = put("sfv.dat", "# Region type : patch rear\n# Area          : 1.44000000e-02\n"
                                   "# Time        \tareaIntegrate(c:snowDeposit)\tother\n"
                                   "0.2\t1.5\t9\n0.4\t2.123456789012\t9\n0.6\t4\t9\n");
    double v, a;
    char err[256];
    assert_int_equal(swe_post_field_at(p, "areaIntegrate(c:snowDeposit)", "0.4", &v, err, sizeof err), 0);
    assert_true(v == 2.123456789);
    assert_int_equal(swe_post_field_at(p, "areaIntegrate(c:snowDeposit)", "last", &v, err, sizeof err), 0);
    assert_true(v == 4);
    assert_int_equal(swe_post_area(p, &a), 0);
    assert_true(a == 0.0144);
    assert_int_equal(swe_post_field_at(p, "areaIntegrate(c:snowDeposit)", "0.5", &v, err, sizeof err), 2);
    assert_non_null(strstr(err, "has no row at time 0.5"));
    assert_int_equal(swe_post_field_at(p, "x", "last", &v, err, sizeof err), 2);
    assert_non_null(strstr(err, "has no column x"));
    assert_int_equal(swe_post_field_at("/no/such", "x", "last", &v, err, sizeof err), 1);
}

/* the wall model's counts: the row nearest the time, the mass to 6 digits */
static void wall_counts(void **st)
{
    (void)st;
    const char *p = put("snowWall.dat",
        "# time rear:impacts rear:sticks rear:bounces rear:ripoffs rear:depositedMass[kg]\n"
        "0.1 1 1 0 0 1.23456789e-5\n0.2 5 3 2 0 2e-5\n0.3 9 6 3 0 3e-5\n");
    double c[5];
    char err[64];
    assert_int_equal(swe_post_counts_at(p, "rear", "0.21", c, err, sizeof err), 0);
    assert_true(c[0] == 5 && c[1] == 3 && c[2] == 2 && c[3] == 0 && c[4] == 2e-5);
    assert_int_equal(swe_post_counts_at(p, "rear", "0", c, err, sizeof err), 0);
    assert_true(c[4] == 1.23457e-5);
    assert_int_equal(swe_post_counts_at(p, "rear", "last", c, err, sizeof err), 0);
    assert_true(c[0] == 9);
    assert_int_equal(swe_post_counts_at(p, "nose", "last", c, err, sizeof err), 0);
    assert_true(c[0] == 0 && c[4] == 0); /* a patch without columns reads 0 */
}

/* the time folder holding a file; reasons.dat's line of a patch */
static void folders_and_reasons(void **st)
{
    (void)st;
    char sub[128], name[64];
    snprintf(sub, sizeof sub, "%s/sw", dir);
    mkdir(sub, 0755);
    const char *t[3] = {"0.2", "0.4", "1"};
    for (int k = 0; k < 3; k++) {
        snprintf(name, sizeof name, "sw/%s", t[k]);
        char d[256];
        snprintf(d, sizeof d, "%s/%s", dir, name);
        mkdir(d, 0755);
        if (k < 2) {
            snprintf(name, sizeof name, "sw/%s/reasons.dat", t[k]);
            put(name, "# patch type impacts stuck criterion tangential shear probability\n"
                      "rear snow 10 4 3 2 1 0 0\n");
        }
    }
    assert_int_equal(swe_post_time_dir(sub, "reasons.dat", "0.40000000001", name, sizeof name), 0);
    assert_string_equal(name, "0.4");
    assert_int_equal(swe_post_time_dir(sub, "reasons.dat", "last", name, sizeof name), 0);
    assert_string_equal(name, "0.4"); /* 1 holds no reasons.dat */
    assert_int_equal(swe_post_time_dir(sub, "reasons.dat", "0.3", name, sizeof name), 0);
    assert_string_equal(name, "");
    long r[5];
    char err[256], p[512];
    snprintf(p, sizeof p, "%s/0.2/reasons.dat", sub);
    assert_int_equal(swe_post_reasons(p, "rear", r, err, sizeof err), 0);
    assert_true(r[0] == 4 && r[1] == 3 && r[2] == 2 && r[3] == 1 && r[4] == 0);
    assert_int_equal(swe_post_reasons(p, "nose", r, err, sizeof err), 2);
    assert_non_null(strstr(err, "has no line for patch nose"));
}

/* raw faces; the cloud's report in the log; the mass of Lagrangian records */
static void raw_log_records(void **st)
{
    (void)st;
    swe_post_raw r;
    char err[256];
    const char *p = put("a.raw", "# x y z v\n0 -1 2 3\n0 1 2 5\nbad line\n");
    assert_int_equal(swe_post_raw_read(p, &r, err, sizeof err), 0);
    assert_int_equal(r.n, 2);
    assert_true(r.y[1] == 1 && r.z[1] == 2 && r.v[1] == 5);
    swe_post_raw_free(&r);
    p = put("log", "Evolving c\nparcelSplitting c: 3 parcels split\nCloud: c\n"
                   "    Current mass in system = 1\n  - mass introduced = 1\n"
                   "  - parcels added = 2\nCloud: c\n    Current mass in system = 0.5\n"
                   "  - mass introduced = 2\n  - mass introduced = 4\n  - parcels added = 3\n"
                   "  - parcels added = 4\nCloud: d\n  - mass introduced = 100\n");
    swe_post_log l;
    assert_int_equal(swe_post_log_read(p, "c", &l, err, sizeof err), 0);
    assert_true(l.injected == 6 && l.parcels == 7 && l.airborne == 0.5 && l.split);
    assert_int_equal(swe_post_log_read(p, "d", &l, err, sizeof err), 0);
    assert_true(l.injected == 100 && !l.split);
    /* nParticle 2, rho 3, d such that pi d^3 / 6 = 1: 6 kg; a second file adds 6 */
    const double d = cbrt(6 / SWE_POST_PI);
    char text[256];
    snprintf(text, sizeof text, "# Time currentProc (a b) nParticle d rho\n0.1 0 (1 2) 2 %.17g 3\n", d);
    const char *f[2] = {put("e1.post", text), put("e2.post", text)};
    double m;
    assert_int_equal(swe_post_post_mass(f, 2, &m, err, sizeof err), 0);
    ASSERT_NEAR(m, 12, 1e-12);
}

/* the halves: deposits, their difference about the mean, the Poisson error */
static void halves(void **st)
{
    (void)st;
    const double c0[5] = {10, 4, 6, 0, 1}, ch[5] = {20, 8, 12, 0, 2}, c1[5] = {30, 20, 10, 0, 4};
    swe_post_halves_t h;
    swe_post_halves(c0, ch, c1, &h);
    assert_true(h.impacts == 20 && h.sticks == 16 && h.window == 3);
    assert_true(h.half1 == 2 && h.half2 == 4);
    ASSERT_NEAR(swe_post_halves_diff(&h), -200.0 / 3, 1e-12);
    ASSERT_NEAR(swe_post_poisson(16), 25, 1e-12);
    assert_true(isinf(swe_post_poisson(0)));
    const double z[5] = {0};
    swe_post_halves(z, z, z, &h);
    assert_true(isnan(swe_post_halves_diff(&h)));
}

/* St = rho d^2 U / (18 mu H), 10 um ice in the wedge's wake */
static void stokes(void **st)
{
    (void)st;
    ASSERT_NEAR(swe_post_stokes(10), 0.05046742049788973, 1e-15);
    ASSERT_NEAR(swe_post_stokes(20) / swe_post_stokes(10), 4, 1e-12);
}

/* the wake full from the start: every fill 1; ages cut off by the spray's
   start: the deposit rate de-censored */
static void fill(void **st)
{
    (void)st;
    enum { N = 100 };
    swe_post_rec r[N + 1];
    for (int i = 0; i < N; i++)
        r[i] = (swe_post_rec){1 + (i + 0.5) / N, 0.0105, 1};
    r[N] = (swe_post_rec){0.5, 0.0105, 1}; /* before the window: not counted */
    swe_post_fill_t s;
    assert_int_equal(swe_post_fill(r, N + 1, 0, 1, 2, 0.95, &s), 0);
    assert_int_equal(s.n, N);
    ASSERT_NEAR(s.mass, N, 1e-12);
    ASSERT_NEAR(s.fill, 1, 1e-12);
    ASSERT_NEAR(s.fill1, 1, 1e-12);
    ASSERT_NEAR(s.fill2, 1, 1e-12);
    ASSERT_NEAR(s.a50, 0.011, 1e-15);
    ASSERT_NEAR(s.aF, 0.011, 1e-15);
    ASSERT_NEAR(s.amax, 0.0105, 0);
    /* spray on at 0.9, age 0.5005 (bin 500): seen only after 1.4005 s, rate
       M / (2 - 1.4005); all in the second half */
    for (int i = 0; i < 10; i++)
        r[i] = (swe_post_rec){1.55 + 0.04 * i, 0.5005, 1};
    assert_int_equal(swe_post_fill(r, 10, 0.9, 1, 2, 0.95, &s), 0);
    ASSERT_NEAR(s.fill, 2 - 1.4005, 1e-12);
    ASSERT_NEAR(s.fill1, 0, 0);
    ASSERT_NEAR(s.fill2, 2 * (2 - 1.4005), 1e-12);
    ASSERT_NEAR(s.aF, 0.501, 1e-15);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(rounding),   cmocka_unit_test(field_table),
        cmocka_unit_test(wall_counts), cmocka_unit_test(folders_and_reasons),
        cmocka_unit_test(raw_log_records), cmocka_unit_test(halves),
        cmocka_unit_test(stokes),     cmocka_unit_test(fill),
    };
    return cmocka_run_group_tests(tests, setup, teardown);
}
