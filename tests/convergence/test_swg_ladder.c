/* test_swg_ladder.c - what a resolution ladder of runs needs besides the GCI
 * (validation/convergence/swg_ladder.h): the batch-means mean of a time series
 * (closed-form batches, a white-noise series against sigma / sqrt(n)), the
 * discretization error of every level on synthetic ladders phi0 + C h^p with a
 * known answer (monotone, more levels, two levels, oscillatory, unresolved),
 * the total error and the cheapest run under a target, and named errors. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>

#include <gsl/gsl_randist.h>
#include <gsl/gsl_rng.h>

#include "swg_ladder.h"

#define ASSERT_NEAR(x, ref, tol) assert_true(fabs((x) - (ref)) <= (tol))
#define ASSERT_REL(x, ref, tol) assert_true(fabs((x) - (ref)) <= (tol) * fabs(ref))

static swg_settings S(void)
{
    swg_settings s;
    swg_settings_default(&s);
    return s;
}

/* t = 1..16, x = t: four batches of four have the means 2.5, 6.5, 10.5, 14.5,
 * so the mean is 8.5 and se = sqrt(80/3) / 2; the window (t0, t1] excludes t0 */
static void series_closed_form(void **st)
{
    (void)st;
    double t[16], x[16];
    for (int i = 0; i < 16; i++)
        t[i] = x[i] = i + 1;
    swg_series_stat s;
    char err[256];
    assert_int_equal(swg_series_mean(t, x, 16, 0.0, 16.0, 4, &s, err, sizeof err), 0);
    ASSERT_NEAR(s.mean, 8.5, 1e-14);
    ASSERT_NEAR(s.se, sqrt(80.0 / 3.0) / 2.0, 1e-13);
    assert_int_equal(s.n, 16);
    assert_int_equal(s.nbatch, 4);
    /* (4, 12]: t = 5..12, batches 5-8 and 9-12: means 6.5, 10.5 -> se 2 */
    assert_int_equal(swg_series_mean(t, x, 16, 4.0, 12.0, 2, &s, err, sizeof err), 0);
    ASSERT_NEAR(s.mean, 8.5, 1e-14);
    ASSERT_NEAR(s.se, 2.0, 1e-13);
    ASSERT_NEAR(s.first, 5.0, 0);
    ASSERT_NEAR(s.last, 12.0, 0);
    /* a constant: se 0 */
    for (int i = 0; i < 16; i++)
        x[i] = -0.3;
    assert_int_equal(swg_series_mean(t, x, 16, 0.0, 16.0, 8, &s, err, sizeof err), 0);
    ASSERT_NEAR(s.mean, -0.3, 1e-15);
    ASSERT_NEAR(s.se, 0.0, 1e-15);
    /* uneven batches: 10 samples in 3 batches of 3, 3, 4 (t = 1..10) */
    for (int i = 0; i < 16; i++)
        x[i] = t[i];
    assert_int_equal(swg_series_mean(t, x, 16, 0.0, 10.0, 3, &s, err, sizeof err), 0);
    ASSERT_NEAR(s.mean, 5.5, 1e-14);
    const double b[3] = { 2.0, 5.0, 8.5 }, bm = (2.0 + 5.0 + 8.5) / 3;
    const double ss = (b[0] - bm) * (b[0] - bm) + (b[1] - bm) * (b[1] - bm) + (b[2] - bm) * (b[2] - bm);
    ASSERT_NEAR(s.se, sqrt(ss / 2 / 3), 1e-13);
}

/* white noise of standard deviation 2 around 0.4: the mean within 4 standard
 * errors and the batch-means se within 35 % of 2 / sqrt(n) (20 batches: the se
 * estimate scatters by about 1 / sqrt(2 x 19) = 16 %) */
static void series_white_noise(void **st)
{
    (void)st;
    const size_t n = 100000;
    double *t = malloc(n * sizeof *t), *x = malloc(n * sizeof *x);
    assert_non_null(t);
    assert_non_null(x);
    gsl_rng *r = gsl_rng_alloc(gsl_rng_mt19937);
    gsl_rng_set(r, 12345);
    for (size_t i = 0; i < n; i++) {
        t[i] = 1e-3 * (double)(i + 1);
        x[i] = 0.4 + gsl_ran_gaussian(r, 2.0);
    }
    gsl_rng_free(r);
    swg_series_stat s;
    char err[256];
    assert_int_equal(swg_series_mean(t, x, n, 0.0, 1e3, 20, &s, err, sizeof err), 0);
    const double se = 2.0 / sqrt((double)n);
    assert_true(fabs(s.mean - 0.4) < 4 * se);
    assert_true(s.se > 0.65 * se && s.se < 1.35 * se);
    free(t);
    free(x);
}

static void series_errors(void **st)
{
    (void)st;
    double t[8] = { 1, 2, 3, 4, 5, 6, 7, 8 }, x[8] = { 0 };
    swg_series_stat s;
    char err[256];
    assert_int_equal(swg_series_mean(t, x, 8, 2.0, 2.0, 2, &s, err, sizeof err), SWG_EINVAL);
    assert_non_null(strstr(err, "window"));
    assert_int_equal(swg_series_mean(t, x, 8, 0.0, 8.0, 1, &s, err, sizeof err), SWG_EINVAL);
    assert_non_null(strstr(err, "batches: 1"));
    assert_int_equal(swg_series_mean(t, x, 8, 0.0, 8.0, 5, &s, err, sizeof err), SWG_EINVAL);
    assert_non_null(strstr(err, "8 samples"));
    assert_int_equal(swg_series_mean(t, x, 8, 8.0, 9.0, 2, &s, err, sizeof err), SWG_EINVAL);
    assert_non_null(strstr(err, "0 samples"));
    t[4] = 4.0; /* not increasing */
    assert_int_equal(swg_series_mean(t, x, 8, 0.0, 8.0, 2, &s, err, sizeof err), SWG_EINVAL);
    assert_non_null(strstr(err, "sample 5"));
    t[4] = 5.0;
    x[2] = NAN;
    assert_int_equal(swg_series_mean(t, x, 8, 0.0, 8.0, 2, &s, err, sizeof err), SWG_EINVAL);
    assert_non_null(strstr(err, "sample 3"));
    x[2] = 2e100;
    assert_int_equal(swg_series_mean(t, x, 8, 0.0, 8.0, 2, &s, err, sizeof err), SWG_EINVAL);
}

static void levels(swg_level *l, size_t n, double h1, double r, double phi0, double C, double p,
                   double se)
{
    for (size_t i = 0; i < n; i++) {
        l[i].h = h1 * pow(r, (double)i);
        l[i].value = phi0 + C * pow(l[i].h, p);
        l[i].se = se;
    }
}

/* phi0 + C h^p, ratio sqrt(2): the reference is phi0 and every level's error
 * |C| h^p, for p 1, 2 and C of both signs, three and five levels */
static void discretization_monotone(void **st)
{
    (void)st;
    const swg_settings s = S();
    char err[256];
    const double ps[2] = { 1.0, 2.0 }, Cs[2] = { 0.7, -2.5 };
    for (int a = 0; a < 2; a++)
        for (int b = 0; b < 2; b++)
            for (size_t n = 3; n <= 5; n += 2) {
                swg_level l[5];
                double disc[5];
                swg_disc d;
                levels(l, n, 0.1, sqrt(2.0), 0.65, Cs[b], ps[a], 0.0);
                assert_int_equal(swg_discretization(l, n, 2.0, &s, &d, disc, err, sizeof err), 0);
                assert_int_equal(d.gci.verdict, SWG_MONOTONE);
                assert_int_equal(d.kind, SWG_REF_EXTRAPOLATED);
                ASSERT_NEAR(d.gci.order.p, ps[a], 1e-8);
                ASSERT_NEAR(d.ref, 0.65, 1e-10);
                /* the distance to phi_ext and the reference's own uncertainty
                   (Fs3 - 1) |phi1 - phi_ext| = 0.25 |C| h1^p, combined */
                const double u = 0.25 * fabs(Cs[b]) * pow(l[0].h, ps[a]);
                ASSERT_REL(d.ref_u, u, 1e-7);
                for (size_t i = 0; i < n; i++)
                    ASSERT_REL(disc[i], hypot(Cs[b] * pow(l[i].h, ps[a]), u), 1e-7);
            }
}

/* two levels: a resolved difference gives the two-level extrapolation with the
 * assumed order (exact for p = 2), an unresolved one the finest value */
static void discretization_two_levels(void **st)
{
    (void)st;
    const swg_settings s = S();
    char err[256];
    swg_level l[2];
    double disc[2];
    swg_disc d;
    levels(l, 2, 0.1, 2.0, 1.0, 3.0, 2.0, 0.001);
    assert_int_equal(swg_discretization(l, 2, 2.0, &s, &d, disc, err, sizeof err), 0);
    assert_int_equal(d.gci.verdict, SWG_TWO_LEVEL);
    assert_int_equal(d.kind, SWG_REF_EXTRAPOLATED);
    ASSERT_NEAR(d.ref, 1.0, 1e-12);
    /* two levels: the reference's uncertainty (Fs2 - 1) |phi1 - phi_ext| = 2 x 0.03 */
    ASSERT_REL(d.ref_u, 0.06, 1e-10);
    ASSERT_REL(disc[0], hypot(0.03, 0.06), 1e-10);
    ASSERT_REL(disc[1], hypot(0.12, 0.06), 1e-10);
    /* the same within the noise (se 1): the bound over the finest value 1.03 (u 0.09)
       and the extrapolation with order 2, 1.03 - 0.09 / 3 = 1.00 (u 0.03); the
       reference the smaller, 1.00, its se that of (4/3) phi1 - phi2 / 3 */
    l[0].se = l[1].se = 1.0;
    assert_int_equal(swg_discretization(l, 2, 2.0, &s, &d, disc, err, sizeof err), 0);
    assert_int_equal(d.gci.verdict, SWG_UNRESOLVED);
    assert_int_equal(d.kind, SWG_REF_BOUND);
    assert_string_equal(swg_ref_kind_name(d.kind), "bound");
    ASSERT_REL(d.ref_a, 1.03, 1e-12);
    ASSERT_REL(d.u_a, 0.09, 1e-10);
    ASSERT_REL(d.ref_b, 1.00, 1e-12);
    ASSERT_REL(d.u_b, 0.03, 1e-10);
    ASSERT_REL(d.ref, 1.00, 1e-12);
    ASSERT_REL(d.ref_u, 0.03, 1e-10);
    ASSERT_REL(d.ref_se, hypot(4.0 / 3.0, 1.0 / 3.0), 1e-12);
    ASSERT_REL(disc[0], 0.09, 1e-10);
    ASSERT_REL(disc[1], hypot(0.09, 0.09), 1e-10);
    /* an order outside (0, 20] is refused */
    assert_int_equal(swg_discretization(l, 2, 0.0, &s, &d, disc, err, sizeof err), SWG_EINVAL);
    assert_non_null(strstr(err, "order"));
    assert_int_equal(swg_discretization(l, 2, NAN, &s, &d, disc, err, sizeof err), SWG_EINVAL);
}

/* oscillation and a difference inside the noise: a bound over the finest value
 * (uncertain by its last change) and the extrapolation of the finest pair with
 * the formal order (uncertain by its step); every level's error the larger */
static void discretization_finest(void **st)
{
    (void)st;
    const swg_settings s = S();
    char err[256];
    swg_level l[4] = { { 1.0, 0.50, 0.0 }, { 1.5, 0.56, 0.0 }, { 2.25, 0.47, 0.0 },
                       { 3.375, 0.80, 0.0 } };
    double disc[4];
    swg_disc d;
    assert_int_equal(swg_discretization(l, 4, 2.0, &s, &d, disc, err, sizeof err), 0);
    assert_int_equal(d.gci.verdict, SWG_OSCILLATORY);
    assert_int_equal(d.kind, SWG_REF_BOUND);
    /* A: 0.50 +- 0.06; B: r 1.5, order 2: 0.50 - 0.06 / 1.25 = 0.452 +- 0.048; the
       reference 0.452 */
    ASSERT_NEAR(d.ref_a, 0.50, 0);
    ASSERT_NEAR(d.u_a, 0.06, 1e-15);
    ASSERT_NEAR(d.ref_b, 0.452, 1e-15);
    ASSERT_NEAR(d.u_b, 0.048, 1e-15);
    ASSERT_NEAR(d.ref, 0.452, 1e-15);
    /* every level's error the larger of the two readings': level 2 lands close to the
       finest value by chance and is not taken as accurate (A's 0.067 holds it), level 1
       and 3 are farther from B */
    ASSERT_NEAR(disc[0], hypot(0.048, 0.048), 1e-15);
    ASSERT_NEAR(disc[1], hypot(0.108, 0.048), 1e-15);
    ASSERT_NEAR(disc[2], hypot(0.03, 0.06), 1e-15);
    ASSERT_NEAR(disc[3], hypot(0.348, 0.048), 1e-15);
    /* monotone values, but e21 inside 2 combined standard errors */
    swg_level m[3];
    levels(m, 3, 0.1, 2.0, 1.0, 1.0, 2.0, 0.02);
    assert_int_equal(swg_discretization(m, 3, 2.0, &s, &d, disc, err, sizeof err), 0);
    assert_int_equal(d.gci.verdict, SWG_UNRESOLVED);
    assert_int_equal(d.kind, SWG_REF_BOUND);
    ASSERT_REL(disc[0], 0.03, 1e-10);
    ASSERT_REL(disc[2], hypot(0.16, 0.01), 1e-10);
}

/* The wedge's resolved ladder of the rear face (constant/ladder-rear-layers.csv,
 * 2026-11-27): 0.338, 0.249, 0.203 g over 37 444, 102 568, 296 416 cells, each step
 * within 1.5 combined standard errors. The finest-value rule took 0.203 g with its
 * last change as its uncertainty: level 0 at 32 %. The trend, if real, extrapolates
 * with order 2 to about 0.158 g: level 0 is then 58 % off. The bound covers both:
 * the reference 0.158 g, level 0's error the larger, 0.102 g (65 % of it). And on
 * random ladders whose steps are not resolved, no level's error is below either
 * reading's. */
static void discretization_unresolved_ladder(void **st)
{
    (void)st;
    const swg_settings s = S();
    char err[256];
    const double cells[3] = {296416, 102568, 37444};
    const double v[3] = {0.2028e-3, 0.2492e-3, 0.3382e-3}, se[3] = {3.042e-5, 3.66324e-5, 4.87008e-5};
    swg_level l[3];
    for (int i = 0; i < 3; i++) {
        assert_int_equal(swg_cell_size(1.0, cells[i], 3, &l[i].h, err, sizeof err), 0);
        l[i].value = v[i];
        l[i].se = se[i];
    }
    double disc[3];
    swg_disc d;
    assert_int_equal(swg_discretization(l, 3, 2.0, &s, &d, disc, err, sizeof err), 0);
    assert_int_equal(d.gci.verdict, SWG_UNRESOLVED);
    assert_int_equal(d.kind, SWG_REF_BOUND);
    const double c = pow(cells[0] / cells[1], 2.0 / 3.0) - 1.0;
    const double refb = v[0] - (v[1] - v[0]) / c;
    ASSERT_REL(d.ref, refb, 1e-12);
    assert_true(d.ref > 0.157e-3 && d.ref < 0.159e-3);
    const double finest_rule = hypot(v[1] - v[0], v[1] - v[0]);   /* the old rule, level 0 */
    ASSERT_REL(disc[1], hypot(v[1] - refb, (v[1] - v[0]) / c), 1e-12);
    assert_true(disc[1] > finest_rule);
    assert_true(disc[1] / d.ref > 0.64 && disc[1] / d.ref < 0.66);
    /* random ladders, each step inside the noise */
    unsigned x = 12345u;
    for (int k = 0; k < 2000; k++) {
        swg_level m[3];
        for (int i = 0; i < 3; i++) {
            x = x * 1103515245u + 12345u;
            m[i].h = (i ? m[i - 1].h : 1.0) * (1.2 + (x % 1000) / 1000.0);
            x = x * 1103515245u + 12345u;
            m[i].value = 1.0 + ((int)(x % 2001) - 1000) / 10000.0;
            m[i].se = 1.0;
        }
        if (swg_discretization(m, 3, 2.0, &s, &d, disc, err, sizeof err) != 0)
            fail_msg("%s", err);
        assert_int_equal(d.kind, SWG_REF_BOUND);
        const double cc = pow(m[1].h / m[0].h, 2.0) - 1.0, e = m[1].value - m[0].value;
        for (int i = 0; i < 3; i++) {
            assert_true(disc[i] >= hypot(m[i].value - m[0].value, e) * (1 - 1e-12));
            assert_true(disc[i] >= hypot(m[i].value - (m[0].value - e / cc), e / cc) * (1 - 1e-12));
        }
    }
}

static void discretization_errors(void **st)
{
    (void)st;
    const swg_settings s = S();
    char err[256];
    swg_level l[4];
    double disc[4];
    swg_disc d;
    levels(l, 4, 0.1, 2.0, 1.0, 1.0, 2.0, 0.0);
    assert_int_equal(swg_discretization(l, 1, 2.0, &s, &d, disc, err, sizeof err), SWG_EINVAL);
    assert_non_null(strstr(err, "1 given"));
    l[3].h = l[2].h; /* the fourth level not coarser */
    assert_int_equal(swg_discretization(l, 4, 2.0, &s, &d, disc, err, sizeof err), SWG_EINVAL);
    assert_non_null(strstr(err, "level 4"));
    l[3].h = 0.8;
    l[1].h = 0.05; /* the first three not finest first: libswgci's message */
    assert_int_equal(swg_discretization(l, 4, 2.0, &s, &d, disc, err, sizeof err), SWG_EINVAL);
}

/* total error: sqrt(se^2 + disc^2) over |reference| */
static void total_error(void **st)
{
    (void)st;
    char err[256];
    double t, r;
    int ok;
    assert_int_equal(swg_total_error(0.03, 0.04, -0.5, &t, &r, &ok, err, sizeof err), 0);
    ASSERT_NEAR(t, 0.05, 1e-16);
    ASSERT_NEAR(r, 0.1, 1e-15);
    assert_int_equal(ok, 1);
    assert_int_equal(swg_total_error(0.03, 0.04, 0.0, &t, &r, &ok, err, sizeof err), 0);
    assert_int_equal(ok, 0);
    ASSERT_NEAR(r, 0.0, 0);
    assert_int_equal(swg_total_error(1e100, 1e100, 1e-300, &t, &r, &ok, err, sizeof err), 0);
    assert_int_equal(ok, 0); /* the ratio would overflow */
    assert_int_equal(swg_total_error(-0.1, 0.04, 1.0, &t, &r, &ok, err, sizeof err), SWG_EINVAL);
    assert_non_null(strstr(err, "se -0.1"));
    assert_int_equal(swg_total_error(0.1, NAN, 1.0, &t, &r, &ok, err, sizeof err), SWG_EINVAL);
}

/* the cheapest run under a target, on a ladder of runs with known answers */
static void pick(void **st)
{
    (void)st;
    const double rel[6] = { 0.35, 0.25, 0.12, 0.08, 0.09, 0.02 };
    const double cost[6] = { 10, 40, 100, 400, 300, 300 };
    int ok[6] = { 1, 1, 1, 1, 1, 0 };
    size_t i = 99;
    assert_int_equal(swg_pick(rel, ok, cost, 6, 0.30, &i), 1);
    assert_int_equal(i, 1);
    assert_int_equal(swg_pick(rel, ok, cost, 6, 0.10, &i), 1);
    assert_int_equal(i, 4);
    assert_int_equal(swg_pick(rel, ok, cost, 6, 0.25, &i), 1);
    assert_int_equal(i, 1); /* exactly at the target counts */
    assert_int_equal(swg_pick(rel, ok, cost, 6, 0.05, &i), 0); /* run 5 has no relative error */
    ok[5] = 1; /* now the same cost as run 4 with the smaller error */
    assert_int_equal(swg_pick(rel, ok, cost, 6, 0.10, &i), 1);
    assert_int_equal(i, 5);
    assert_int_equal(swg_pick(rel, ok, cost, 6, 1.0, &i), 1);
    assert_int_equal(i, 0);
    const double bad[2] = { 1, -1 };
    assert_int_equal(swg_pick(rel, ok, bad, 2, 0.5, &i), -1);
    assert_int_equal(swg_pick(rel, ok, cost, 6, NAN, &i), -1);
    assert_int_equal(swg_pick(rel, ok, cost, 0, 0.5, &i), 0);
}

/* a ladder of runs end to end through the library: phi = 1 + 0.19 h^2 on three
 * levels of ratio sqrt(2) with two designs each (se 0.05 and 0.01):
 * every run's total error is sqrt(se^2 + (0.19 h^2)^2 + u^2), u = 0.25 x 0.19 h1^2
 * the reference's own uncertainty, the cheapest under 10 % the run the closed form
 * picks */
static void ladder_end_to_end(void **st)
{
    (void)st;
    const swg_settings s = S();
    char err[256];
    const double h[3] = { 0.5, 0.5 * sqrt(2.0), 1.0 };
    swg_level l[3];
    for (int i = 0; i < 3; i++)
        l[i] = (swg_level){ h[i], 1.0 + 0.19 * h[i] * h[i], 0.01 };
    double disc[3];
    swg_disc d;
    assert_int_equal(swg_discretization(l, 3, 2.0, &s, &d, disc, err, sizeof err), 0);
    assert_int_equal(d.gci.verdict, SWG_MONOTONE);
    ASSERT_NEAR(d.ref, 1.0, 1e-10);
    /* runs: level i, design k (0 default, 1 full); cost: flow 100 x 2.8^(2 - i),
       clouds 50 (default) or 280 (full) */
    double rel[6], cost[6];
    int ok[6];
    const double u = 0.25 * 0.19 * h[0] * h[0];
    for (int i = 0; i < 3; i++)
        for (int k = 0; k < 2; k++) {
            const double se = k ? 0.01 : 0.05;
            double t;
            assert_int_equal(swg_total_error(se, disc[i], d.ref, &t, &rel[2 * i + k], &ok[2 * i + k],
                                             err, sizeof err), 0);
            const double tot = sqrt(se * se + pow(0.19 * h[i] * h[i], 2) + u * u);
            ASSERT_REL(t, tot, 1e-8);
            cost[2 * i + k] = 100 * pow(2.8, 2 - i) + (k ? 280 : 50);
        }
    /* closed form: the cheapest run with sqrt(se^2 + (0.19 h^2)^2) <= 0.1 */
    size_t want = 99;
    for (int j = 0; j < 6; j++) {
        const double se = (j % 2) ? 0.01 : 0.05, hh = h[j / 2];
        if (sqrt(se * se + pow(0.19 * hh * hh, 2) + u * u) <= 0.1 && (want == 99 || cost[j] < cost[want]))
            want = (size_t)j;
    }
    size_t got;
    assert_int_equal(swg_pick(rel, ok, cost, 6, 0.10, &got), 1);
    assert_int_equal(got, want);
    assert_int_equal(want, 3); /* level 1 (h = 0.71), the full design: 9.55 % at 560 s, against
                                  level 0 default: 6.9 % at 834 s */
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(series_closed_form),
        cmocka_unit_test(series_white_noise),
        cmocka_unit_test(series_errors),
        cmocka_unit_test(discretization_monotone),
        cmocka_unit_test(discretization_two_levels),
        cmocka_unit_test(discretization_finest),
        cmocka_unit_test(discretization_unresolved_ladder),
        cmocka_unit_test(discretization_errors),
        cmocka_unit_test(total_error),
        cmocka_unit_test(pick),
        cmocka_unit_test(ladder_end_to_end),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
