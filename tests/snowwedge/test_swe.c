/* test_swe.c - the wedge's statistics (tools/snowwedge) on synthetic data with
 * known answers: the log-normal spray's distribution function and classes,
 * the mass medians of the spray and of a composed deposit, the regions of the
 * rear face and their effective sample sizes, the composition of classes with
 * its propagated error, the face's blocks and the grid chosen from their error,
 * the test of two halves, and the spectral peak of an unevenly sampled signal;
 * bad inputs give a named error, never an exit. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <string.h>
#include <cmocka.h>

#include <gsl/gsl_cdf.h>

#include "swe_blocks.h"
#include "swe_signal.h"
#include "swe_spray.h"
#include "swe_stats.h"

#define ASSERT_NEAR(x, ref, tol) assert_true(fabs((x) - (ref)) <= (tol))

static swe_spray spray(void)
{
    swe_spray s;
    swe_spray_default(&s);
    return s;
}

/* F(mvd x freeze) = 1/2, F(mvd x freeze x sigma_g) = Phi(1) */
static void distribution(void **st)
{
    (void)st;
    const swe_spray s = spray();
    ASSERT_NEAR(swe_spray_cdf(&s, 20 * 1.03), 0.5, 1e-15);
    ASSERT_NEAR(swe_spray_cdf(&s, 20 * 1.03 * 1.8), 0.8413447460685429, 1e-14);
    ASSERT_NEAR(swe_spray_cdf(&s, 20 * 1.03 / 1.8), 1 - 0.8413447460685429, 1e-14);
    /* the density integrates to 1 over the whole line (in m, x 1e-6) */
    double sum = 0;
    const double lo = 1e-8, hi = 1e-2;
    const int n = 200000;
    for (int i = 0; i < n; i++) {
        const double a = lo * pow(hi / lo, (double)i / n), b = lo * pow(hi / lo, (i + 1.0) / n);
        sum += 0.5 * (swe_spray_density(&s, a) + swe_spray_density(&s, b)) * (b - a) * 1e6;
    }
    ASSERT_NEAR(sum, 1.0, 1e-6);
}

/* classes: shares sum to 1; two classes placed symmetrically (in log d) about
   the median over a symmetric range share the mass equally; one class holds it
   all with the range's ends as its edges */
static void classes(void **st)
{
    (void)st;
    swe_spray s = spray();
    const double d5[5] = {5, 10, 20, 40, 80};
    double w[5], e0[5], e1[5];
    assert_int_equal(swe_spray_classes(&s, d5, 5, w, e0, e1, NULL, 0), 0);
    double tot = 0;
    for (int i = 0; i < 5; i++)
        tot += w[i];
    ASSERT_NEAR(tot, 1, 1e-14);
    ASSERT_NEAR(e0[0], 2 * 1.03, 1e-14);
    ASSERT_NEAR(e1[4], 150 * 1.03, 1e-12);
    ASSERT_NEAR(e1[1], sqrt(200.0), 1e-12);
    ASSERT_NEAR(e0[2], sqrt(200.0), 1e-12);
    /* the middle class: Phi between its edges over the truncated total */
    const double z = log(1.8);
    const double F = gsl_cdf_ugaussian_P((log(sqrt(800.0) / 1.03) - log(20)) / z) -
                     gsl_cdf_ugaussian_P((log(sqrt(200.0) / 1.03) - log(20)) / z);
    const double T = gsl_cdf_ugaussian_P((log(150.0) - log(20)) / z) -
                     gsl_cdf_ugaussian_P((log(2.0) - log(20)) / z);
    ASSERT_NEAR(w[2], F / T, 1e-14);

    s.mvd = 10;
    s.freeze = 1;
    s.dmin = 1;
    s.dmax = 100;
    const double d2[2] = {10 / 3.0, 30};
    assert_int_equal(swe_spray_classes(&s, d2, 2, w, e0, e1, NULL, 0), 0);
    ASSERT_NEAR(w[0], 0.5, 1e-14);
    ASSERT_NEAR(w[1], 0.5, 1e-14);
    const double d1[1] = {7};
    assert_int_equal(swe_spray_classes(&s, d1, 1, w, e0, e1, NULL, 0), 0);
    ASSERT_NEAR(w[0], 1, 1e-15);
    ASSERT_NEAR(e0[0], 1, 0);
    ASSERT_NEAR(e1[0], 100, 0);
}

/* medians: a range symmetric about the median keeps it; an asymmetric one
   moves it to Phi^-1((Phi(zlo) + Phi(zhi)) / 2); a deposit with the same
   capture everywhere has the spray's median, one captured by a single class
   the median of that class's mass */
static void medians(void **st)
{
    (void)st;
    swe_spray s = spray();
    s.dmin = 20 / 4.0;
    s.dmax = 20 * 4.0;
    double x;
    char err[128];
    assert_int_equal(swe_spray_median(&s, &x, err, sizeof err), 0);
    ASSERT_NEAR(x, 20 * 1.03, 1e-9);
    s = spray();
    assert_int_equal(swe_spray_median(&s, &x, err, sizeof err), 0);
    const double ls = log(1.8), zl = log(2 / 20.0) / ls, zh = log(150 / 20.0) / ls;
    const double zm =
        gsl_cdf_ugaussian_Pinv(0.5 * (gsl_cdf_ugaussian_P(zl) + gsl_cdf_ugaussian_P(zh)));
    ASSERT_NEAR(x, 20 * 1.03 * exp(zm * ls), 1e-9);

    const double d[5] = {5, 10, 20, 40, 80};
    double w[5], e0[5], e1[5], c[5] = {3, 3, 3, 3, 3};
    assert_int_equal(swe_spray_classes(&s, d, 5, w, e0, e1, NULL, 0), 0);
    double xd;
    assert_int_equal(swe_deposit_median(&s, e0, e1, w, c, 5, &xd, err, sizeof err), 0);
    ASSERT_NEAR(xd, x, 1e-9);
    const double c1[5] = {0, 0, 0, 2, 0};
    assert_int_equal(swe_deposit_median(&s, e0, e1, w, c1, 5, &xd, err, sizeof err), 0);
    const double Fm = 0.5 * (swe_spray_cdf(&s, e0[3]) + swe_spray_cdf(&s, e1[3]));
    ASSERT_NEAR(xd, 20 * 1.03 * exp(gsl_cdf_ugaussian_Pinv(Fm) * ls), 1e-9);
    const double c0[5] = {0};
    assert_int_equal(swe_deposit_median(&s, e0, e1, w, c0, 5, &xd, err, sizeof err), SWE_EINVAL);
    assert_true(strlen(err) > 0);
}

/* the regions of a unit face and the effective sample size of records from
   shared origins: origin A's two copies (1 + 1 kg) and origin B (2 kg) make
   n_eff = 4^2 / (2^2 + 2^2) = 2 */
static void rear_regions(void **st)
{
    (void)st;
    const double o[4] = {0, 1, 0, 1};
    assert_int_equal(swe_region_of(o, 0.05, 0.5), SWE_EDGES);
    assert_int_equal(swe_region_of(o, 0.5, 0.95), SWE_EDGES);
    assert_int_equal(swe_region_of(o, 0.2, 0.5), SWE_LEFT);
    assert_int_equal(swe_region_of(o, 0.8, 0.5), SWE_RIGHT);
    assert_int_equal(swe_region_of(o, 0.5, 0.5), SWE_CENTRE);
    assert_int_equal(swe_region_of(o, 0.5, 0.8), -1);
    double a = 0;
    for (int r = 0; r < SWE_FACE; r++)
        a += swe_region_area(r);
    ASSERT_NEAR(a, 0.88, 1e-15); /* the rest: between centre and edges */

    const swe_record rec[4] = {
        {0.2, 0.5, 1, 0, 7}, {0.25, 0.4, 1, 0, 7}, {0.3, 0.6, 2, 1, 7}, {0.5, 0.5, 6, 0, 8}};
    swe_region_stats s[SWE_NREGION];
    assert_int_equal(swe_rear_stats(rec, 4, o, s, NULL, 0), 0);
    assert_int_equal(s[SWE_LEFT].n, 3);
    assert_int_equal(s[SWE_LEFT].origins, 2);
    ASSERT_NEAR(s[SWE_LEFT].mass, 4, 1e-15);
    ASSERT_NEAR(s[SWE_LEFT].neff, 2, 1e-15);
    assert_int_equal(s[SWE_CENTRE].n, 1);
    ASSERT_NEAR(s[SWE_CENTRE].neff, 1, 1e-15);
    assert_int_equal(s[SWE_FACE].n, 4);
    assert_int_equal(s[SWE_FACE].origins, 3);
    ASSERT_NEAR(s[SWE_FACE].neff, 100.0 / (4 + 4 + 36), 1e-14);
    assert_int_equal(s[SWE_RIGHT].n, 0);
    ASSERT_NEAR(s[SWE_RIGHT].neff, 0, 0);
    /* equal independent masses: n_eff is the count */
    swe_record many[50];
    for (int i = 0; i < 50; i++)
        many[i] = (swe_record){0.8, 0.5, 0.3, 0, i};
    assert_int_equal(swe_rear_stats(many, 50, o, s, NULL, 0), 0);
    ASSERT_NEAR(s[SWE_RIGHT].neff, 50, 1e-12);
    const double bad[4] = {1, 1, 0, 1};
    char err[128];
    assert_int_equal(swe_rear_stats(rec, 4, bad, s, err, sizeof err), SWE_EINVAL);
    assert_true(strlen(err) > 0);
}

/* composition: sums and variances of two classes, a class without n_eff adds
   no variance; standing out beyond 2 standard errors; the halves' z */
static void compose(void **st)
{
    (void)st;
    swe_class c[2] = {{0.25, {1, 2, 3, 4, 10}, {4, 4, 4, 4, 4}},
                      {0.75, {2, 0, 1, 4, 8}, {9, 0, 1, 16, 36}}};
    double S[SWE_NREGION], V[SWE_NREGION];
    swe_compose(c, 2, 1, S, V);
    ASSERT_NEAR(S[SWE_LEFT], 0.25 + 1.5, 1e-15);
    ASSERT_NEAR(V[SWE_LEFT], 0.0625 / 4 + 2.25 / 9, 1e-15);
    ASSERT_NEAR(S[SWE_RIGHT], 0.5, 1e-15);
    ASSERT_NEAR(V[SWE_RIGHT], 0.25 / 4, 1e-15);
    ASSERT_NEAR(S[SWE_FACE], 2.5 + 6, 1e-15);
    swe_compose(c, 2, 2, S, V);
    ASSERT_NEAR(S[SWE_FACE], 17, 1e-14);
    ASSERT_NEAR(V[SWE_FACE], 25.0 / 4 + 144.0 / 36, 1e-13);

    /* face 10: the left side expects 2 */
    assert_int_equal(swe_stands_out(2.5, 0.05, 10, SWE_LEFT), 1);
    assert_int_equal(swe_stands_out(2.5, 0.0625, 10, SWE_LEFT), 0); /* exactly 2 se: not beyond */
    assert_int_equal(swe_stands_out(1.0, 0.01, 10, SWE_LEFT), -1);
    assert_int_equal(swe_stands_out(1.0, 0.01, 10, SWE_FACE), 0);
    assert_int_equal(swe_stands_out(0, 0, 0, SWE_LEFT), 0);

    double p;
    ASSERT_NEAR(swe_ztest(1, 0.5, 3, 0.5, &p), 2, 1e-15);
    ASSERT_NEAR(p, 0.04550026389635842, 1e-12);
    ASSERT_NEAR(swe_ztest(3, 0, 3, 0, &p), 0, 0);
    ASSERT_NEAR(p, 1, 1e-15);
}

/* a sine of 37 Hz on uneven steps (the solver's adaptive step): its peak
   within a step of the grid (1 / (4 W)), its rms A / sqrt(2) */
static void spectral_peak(void **st)
{
    (void)st;
    enum { N = 2000 };
    static double t[N], x[N];
    double tt = 0.4;
    for (int i = 0; i < N; i++) {
        tt += 2e-4 * (1 + 0.3 * sin(0.37 * i));
        t[i] = tt;
        x[i] = 0.7 + 0.2 * sin(2 * M_PI * 37 * tt + 0.3);
    }
    const double a = 0.4, b = t[N - 1];
    double f;
    char err[128];
    assert_int_equal(swe_peak_frequency(t, x, N, a, b, 300, &f, err, sizeof err), 0);
    ASSERT_NEAR(f, 37, 0.25 / (b - a) + 1e-9);
    ASSERT_NEAR(swe_rms(x, N), 0.2 / sqrt(2), 1e-2);
    const double q[4] = {1, 2, 3, 4};
    ASSERT_NEAR(swe_mean(q, 4), 2.5, 1e-15);
    ASSERT_NEAR(swe_rms(q, 4), sqrt(1.25), 1e-15);
    /* a second, stronger line wins */
    for (int i = 0; i < N; i++)
        x[i] += 0.5 * sin(2 * M_PI * 111 * t[i]);
    assert_int_equal(swe_peak_frequency(t, x, N, a, b, 300, &f, err, sizeof err), 0);
    ASSERT_NEAR(f, 111, 0.25 / (b - a) + 1e-9);
    assert_int_equal(swe_peak_frequency(t, x, 2, a, b, 300, &f, err, sizeof err), SWE_EINVAL);
    assert_int_equal(swe_peak_frequency(t, x, N, b, a, 300, &f, err, sizeof err), SWE_EINVAL);
    assert_true(strlen(err) > 0);
}

/* the time for a target error at the 1/sqrt(time) law: 40 s at 20 % -> 160 s
   for 10 %; 1000 s at 2.5 % -> 62.5 s; nothing for a zero error or target */
static void time_for_error(void **st)
{
    (void)st;
    ASSERT_NEAR(swe_time_for_error(40, 20, 10), 160, 1e-12);
    ASSERT_NEAR(swe_time_for_error(1000, 2.5, 10), 62.5, 1e-12);
    ASSERT_NEAR(swe_time_for_error(1000, 0, 10), 0, 0);
    ASSERT_NEAR(swe_time_for_error(1000, 5, 0), 0, 0);
}

/* bad settings: a named error, the outputs untouched */
static void bad_inputs(void **st)
{
    (void)st;
    char err[128];
    swe_spray s = spray();
    s.sigma_g = 1;
    assert_int_equal(swe_spray_check(&s, err, sizeof err), SWE_EINVAL);
    assert_non_null(strstr(err, "sigma_g"));
    s = spray();
    s.dmax = 1;
    assert_int_equal(swe_spray_check(&s, err, sizeof err), SWE_EINVAL);
    assert_non_null(strstr(err, "range"));
    s = spray();
    s.mvd = 0;
    double x;
    assert_int_equal(swe_spray_median(&s, &x, err, sizeof err), SWE_EINVAL);
    assert_non_null(strstr(err, "mvd"));
    s = spray();
    const double d[2] = {20, 10};
    double w[2], e0[2], e1[2];
    assert_int_equal(swe_spray_classes(&s, d, 2, w, e0, e1, err, sizeof err), SWE_EINVAL);
    assert_int_equal(swe_spray_classes(&s, d, 0, w, e0, e1, err, sizeof err), SWE_EINVAL);
}

/* the face's blocks: known answers, origins shared, two classes, mass kept,
   the grid from the error, refusals */
static void blocks(void **st)
{
    (void)st;
    const double o[4] = {0, 1, 0, 1};
    char err[256];
    swe_block b[64];
    /* one record per quadrant, mass 1, scale 2: each block 2 x 1 / 0.25, error 1 */
    const swe_record q[4] = {{0.25, 0.75, 1, 0, 1}, {0.75, 0.75, 1, 0, 2},
                             {0.25, 0.25, 1, 0, 3}, {0.75, 0.25, 1, 0, 4}};
    swe_block_class c = {q, 4, 2};
    assert_int_equal(swe_blocks(&c, 1, o, 2, b, err, sizeof err), 0);
    for (int i = 0; i < 4; i++) {
        ASSERT_NEAR(b[i].deposit, 8, 1e-12);
        ASSERT_NEAR(b[i].rel, 1, 1e-12);
        assert_int_equal(b[i].records, 1);
    }
    /* block 0 is the top left seen from behind: y 0 .. 0.5, z 0.5 .. 1 */
    ASSERT_NEAR(b[0].y1, 0.5, 1e-15);
    ASSERT_NEAR(b[0].z0, 0.5, 1e-15);
    ASSERT_NEAR(b[3].y0, 0.5, 1e-15);
    ASSERT_NEAR(b[3].z1, 0.5, 1e-15);
    /* two records of one origin in a block: n_eff 1; of two origins: 2 */
    const swe_record same[2] = {{0.1, 0.9, 1, 3, 7}, {0.2, 0.8, 1, 3, 7}};
    const swe_record two[2] = {{0.1, 0.9, 1, 3, 7}, {0.2, 0.8, 1, 3, 8}};
    c = (swe_block_class){same, 2, 1};
    assert_int_equal(swe_blocks(&c, 1, o, 2, b, err, sizeof err), 0);
    ASSERT_NEAR(b[0].rel, 1, 1e-12);
    assert_int_equal(b[1].records, 0);
    ASSERT_NEAR(b[1].rel, 0, 0);
    c = (swe_block_class){two, 2, 1};
    assert_int_equal(swe_blocks(&c, 1, o, 2, b, err, sizeof err), 0);
    ASSERT_NEAR(b[0].rel, 1 / sqrt(2), 1e-12);
    /* two classes: the deposits add, so do the variances D_kb^2 / n_eff_kb */
    const swe_block_class cc[2] = {{two, 2, 1}, {q, 1, 3}};
    assert_int_equal(swe_blocks(cc, 2, o, 2, b, err, sizeof err), 0);
    ASSERT_NEAR(b[0].deposit, 2 / 0.25 + 3 / 0.25, 1e-12);
    ASSERT_NEAR(b[0].var, (8.0 * 8) / 2 + 12.0 * 12, 1e-9);
    /* the mass is kept at every grid, records on and beyond the outline included */
    swe_record r[300];
    for (int i = 0; i < 300; i++)
        r[i] = (swe_record){fmod(0.37 * i, 1.3) - 0.15, fmod(0.61 * i, 1.2) - 0.1,
                            1 + (i % 7), i % 5, i / 3};
    const swe_block_class rc = {r, 300, 0.5};
    double m = 0;
    for (int i = 0; i < 300; i++)
        m += 0.5 * r[i].mass;
    for (int nb = 1; nb <= 8; nb++) {
        assert_int_equal(swe_blocks(&rc, 1, o, nb, b, err, sizeof err), 0);
        double s = 0;
        long n = 0;
        for (int i = 0; i < nb * nb; i++) {
            s += b[i].deposit / (nb * nb);
            n += b[i].records;
        }
        ASSERT_NEAR(s, m, 1e-9 * m);
        assert_int_equal(n, 300);
    }
    /* the grid: a 24 x 24 lattice of single-origin records of one mass; every
       block non-empty, the rms error is nb / 24 exactly: 7 at a target of 0.3 */
    static swe_record lat[576];
    for (int i = 0; i < 576; i++)
        lat[i] = (swe_record){(i % 24 + 0.5) / 24, (i / 24 + 0.5) / 24, 1, 0, i};
    const swe_block_class lc = {lat, 576, 1};
    int nb;
    double rms;
    assert_int_equal(swe_blocks_grid(&lc, 1, o, 24, 0.3, &nb, &rms, err, sizeof err), 0);
    assert_int_equal(nb, 7);
    ASSERT_NEAR(rms, 7.0 / 24, 1e-12);
    assert_int_equal(swe_blocks_grid(&lc, 1, o, 24, 1.0 / 24, &nb, &rms, err, sizeof err), 0);
    assert_int_equal(nb, 1);
    assert_int_equal(swe_blocks_grid(&lc, 1, o, 4, 0.3, &nb, &rms, err, sizeof err), 0);
    assert_int_equal(nb, 4);
    /* no record: one block, no error to give */
    const swe_block_class none = {NULL, 0, 1};
    assert_int_equal(swe_blocks_grid(&none, 1, o, 24, 0.3, &nb, &rms, err, sizeof err), 0);
    assert_int_equal(nb, 1);
    assert_true(isinf(rms));
    /* refusals, named */
    const double flat[4] = {0, 1, 1, 1};
    assert_int_equal(swe_blocks(&lc, 1, flat, 2, b, err, sizeof err), SWE_EINVAL);
    assert_non_null(strstr(err, "outline"));
    assert_int_equal(swe_blocks(&lc, 1, o, 0, b, err, sizeof err), SWE_EINVAL);
    const swe_block_class neg = {lat, 576, -1}, nan_s = {lat, 576, NAN};
    assert_int_equal(swe_blocks(&neg, 1, o, 2, b, err, sizeof err), SWE_EINVAL);
    assert_non_null(strstr(err, "scale"));
    assert_int_equal(swe_blocks(&nan_s, 1, o, 2, b, err, sizeof err), SWE_EINVAL);
    assert_int_equal(swe_blocks_grid(&lc, 1, o, 0, 0.3, &nb, &rms, err, sizeof err), SWE_EINVAL);
    assert_int_equal(swe_blocks_grid(&lc, 1, o, 24, 0, &nb, &rms, err, sizeof err), SWE_EINVAL);
    assert_non_null(strstr(err, "target"));
    assert_int_equal(swe_blocks_grid(&lc, 1, o, 24, NAN, &nb, &rms, err, sizeof err), SWE_EINVAL);
}

/* Welch's spectrum: a sine of 28 Hz and amplitude 2 plus one of 8 Hz and
   amplitude 1 on uneven steps: the variance 2.5 kept within 3 %, the peak at
   28 Hz and the lowest peak holding 10 % at 8 Hz within one bin; refusals */
static void spectrum(void **st)
{
    (void)st;
    enum { N = 6000 };
    static double t[N], x[N];
    double tt = 0;
    for (int i = 0; i < N; i++) {
        t[i] = tt;
        x[i] = 2 * sin(2 * M_PI * 28 * tt) + sin(2 * M_PI * 8 * tt + 0.3) + 5;
        tt += 1e-4 * (1 + 0.5 * sin(0.37 * i)); /* uneven, 0.5e-4 .. 1.5e-4 s */
    }
    swe_spectrum s;
    char err[256];
    assert_int_equal(swe_spectrum_welch(t, x, N, 0, t[N - 1], 1, 0, &s, err, sizeof err), 0);
    assert_true(s.dt > 0.9e-4 && s.dt < 1.1e-4);
    ASSERT_NEAR(s.var, 2.5, 0.03 * 2.5 * 1.5);
    double fp, fl, below;
    swe_spectrum_peaks(&s, 0.1, &fp, &fl, &below);
    ASSERT_NEAR(fp, 28, s.df);
    ASSERT_NEAR(fl, 8, s.df);
    ASSERT_NEAR(below, 0.2, 0.05); /* the 8 Hz sine: 0.5 of 2.5 */
    swe_spectrum_free(&s);
    /* three segments: a coarser resolution, the same variance */
    assert_int_equal(swe_spectrum_welch(t, x, N, 0, t[N - 1], 3, 0, &s, err, sizeof err), 0);
    assert_int_equal(s.nseg, 3);
    ASSERT_NEAR(s.var, 2.5, 0.1 * 2.5);
    swe_spectrum_free(&s);
    /* refusals, named */
    assert_int_equal(swe_spectrum_welch(t, x, N, 1, 0.5, 1, 0, &s, err, sizeof err), SWE_EINVAL);
    assert_non_null(strstr(err, "window"));
    assert_int_equal(swe_spectrum_welch(t, x, N, 0, 2e-4, 1, 0, &s, err, sizeof err), SWE_EINVAL);
    assert_non_null(strstr(err, "fewer than 8"));
    assert_int_equal(swe_spectrum_welch(t, x, N, 0, t[N - 1], 0, 0, &s, err, sizeof err),
                     SWE_EINVAL);
    assert_int_equal(swe_spectrum_welch(t, x, 20, 0, 1, 5, 0, &s, err, sizeof err), SWE_EINVAL);
    assert_non_null(strstr(err, "segment"));
    x[7] = NAN;
    assert_int_equal(swe_spectrum_welch(t, x, N, 0, t[N - 1], 1, 0, &s, err, sizeof err),
                     SWE_EINVAL);
    assert_non_null(strstr(err, "sample 8"));
    x[7] = 0;
    t[9] = t[8];
    assert_int_equal(swe_spectrum_welch(t, x, N, 0, t[N - 1], 1, 0, &s, err, sizeof err),
                     SWE_EINVAL);
    assert_non_null(strstr(err, "do not increase"));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(distribution), cmocka_unit_test(classes),
        cmocka_unit_test(medians),      cmocka_unit_test(rear_regions),
        cmocka_unit_test(compose),      cmocka_unit_test(blocks),
        cmocka_unit_test(spectral_peak), cmocka_unit_test(spectrum),
        cmocka_unit_test(time_for_error), cmocka_unit_test(bad_inputs),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
