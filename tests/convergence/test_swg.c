/* test_swg.c - the resolution ladder's discretization error
 * (validation/convergence/swg_gci.h): Celik et al. 2008's worked example,
 * synthetic ladders phi(h) = phi0 + C h^p with a known answer, every verdict,
 * the sampling error, the bounds of the order, and finite results (or a named
 * error) for hostile finite inputs, under the floating-point traps. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <string.h>
#include <cmocka.h>

#include "swg_gci.h"

#define ASSERT_NEAR(x, ref, tol) assert_true(fabs((x) - (ref)) <= (tol))
#define ASSERT_REL(x, ref, tol) assert_true(fabs((x) - (ref)) <= (tol) * fabs(ref))

static swg_settings S(void)
{
    swg_settings s;
    swg_settings_default(&s);
    return s;
}

static void ladder(swg_level l[3], const double h[3], double phi0, double C, double p,
                   double se)
{
    for (int i = 0; i < 3; i++) {
        l[i].h = h[i];
        l[i].value = phi0 + C * pow(h[i], p);
        l[i].se = se;
    }
}

/* Celik et al. 2008, Table 1: 2-D grids of N1, N2, N3 cells, h = (A/N)^(1/2).
 * The table's p and phi_ext21 to its printed digits: p 1.53, phi_ext21 6.1685
 * (column 1); p 0.75, phi_ext21 10.8801 (column 2); the oscillating column 3 with
 * p 1.51, phi_ext21 6.0269. e_a21, e_ext21 and GCI_fine21 to 0.05 % of the
 * values the paper's formulas give (1.50, 1.71, 2.17 %; 0.58, -, 1.07 %). */
static void celik_table1(void **st)
{
    (void)st;
    const swg_settings s = S();
    char err[256];
    double h[3];
    const double N1[3] = { 18000, 8000, 4500 }, N2[3] = { 18000, 4500, 980 };
    swg_level l[3];
    swg_result r;

    const double v1[3] = { 6.063, 5.972, 5.863 };
    for (int i = 0; i < 3; i++) {
        assert_int_equal(swg_cell_size(1.0, N1[i], 2, &h[i], err, sizeof err), 0);
        l[i] = (swg_level){ h[i], v1[i], 0.0 };
    }
    ASSERT_REL(h[1] / h[0], 1.5, 1e-12);
    assert_int_equal(swg_three_level(l, &s, &r, err, sizeof err), 0);
    assert_int_equal(r.verdict, SWG_MONOTONE);
    ASSERT_NEAR(r.r32, 1.333, 5e-4);
    ASSERT_NEAR(r.order.p, 1.53, 5e-3);
    ASSERT_NEAR(r.phi_ext21, 6.1685, 5e-5);
    ASSERT_NEAR(100 * r.e_a21, 1.5, 0.05);
    ASSERT_NEAR(100 * r.e_ext21, 1.7, 0.05);
    ASSERT_NEAR(100 * r.gci_fine21, 2.17, 0.05);
    assert_true(r.order.iterations > 0 && r.order.converged && r.order.residual < 1e-10);

    const double v2[3] = { 10.7880, 10.7250, 10.6050 };
    for (int i = 0; i < 3; i++) {
        assert_int_equal(swg_cell_size(1.0, N2[i], 2, &h[i], err, sizeof err), 0);
        l[i] = (swg_level){ h[i], v2[i], 0.0 };
    }
    assert_int_equal(swg_three_level(l, &s, &r, err, sizeof err), 0);
    assert_int_equal(r.verdict, SWG_MONOTONE);
    ASSERT_NEAR(r.order.p, 0.75, 5e-3);
    ASSERT_NEAR(r.phi_ext21, 10.8801, 5e-5);
    ASSERT_NEAR(100 * r.e_a21, 0.6, 0.05);
    ASSERT_NEAR(100 * r.gci_fine21, 1.07, 0.05);

    /* column 3 oscillates (R < 0): the verdict gives no order; the paper's
       order and extrapolation come from the same equation with s = -1 */
    const double v3[3] = { 6.0042, 5.9624, 6.0909 };
    for (int i = 0; i < 3; i++)
        l[i] = (swg_level){ h[i], v3[i], 0.0 };
    assert_int_equal(swg_three_level(l, &s, &r, err, sizeof err), 0);
    assert_int_equal(r.verdict, SWG_OSCILLATORY);
    assert_false(r.has_order);
    ASSERT_NEAR(r.spread, 6.0909 - 5.9624, 1e-12);
    swg_order_result o;
    assert_int_equal(swg_order(r.r21, r.r32, r.e21, r.e32, &s, &o, err, sizeof err), 0);
    ASSERT_NEAR(o.p, 1.51, 5e-3);
    const double ext = (pow(r.r21, o.p) * v3[0] - v3[1]) / (pow(r.r21, o.p) - 1);
    ASSERT_NEAR(ext, 6.0269, 5e-5);
    assert_true(o.residual < 1e-10);
}

/* phi(h) = phi0 + C h^p, p = 1, 1.5, 2, constant and non-constant ratios, C of
 * either sign: three exact levels give p and phi0 back */
static void synthetic_recovered(void **st)
{
    (void)st;
    const swg_settings s = S();
    char err[256];
    const double hs[4][3] = { { 0.1, 0.2, 0.4 },      /* r 2, 2 */
                              { 0.01, 0.0125, 0.015625 }, /* r 1.25, 1.25 */
                              { 0.1, 0.13, 0.25 },    /* r 1.3, 1.92 */
                              { 0.02, 0.05, 0.06 } }; /* r 2.5, 1.2 */
    const double ps[3] = { 1.0, 1.5, 2.0 }, Cs[2] = { 3.0, -0.7 };
    for (int k = 0; k < 4; k++)
        for (int j = 0; j < 3; j++)
            for (int c = 0; c < 2; c++) {
                swg_level l[3];
                swg_result r;
                ladder(l, hs[k], -2.5, Cs[c], ps[j], 0.0);
                assert_int_equal(swg_three_level(l, &s, &r, err, sizeof err), 0);
                assert_int_equal(r.verdict, SWG_MONOTONE);
                ASSERT_NEAR(r.order.p, ps[j], 1e-8);
                ASSERT_NEAR(r.phi_ext21, -2.5, 1e-9);
                /* the extrapolated relative error is the true one */
                ASSERT_REL(r.e_ext21, fabs((l[0].value + 2.5) / 2.5), 1e-6);
                /* the next-coarser extrapolation agrees, and the ladder is in the
                   asymptotic range */
                ASSERT_NEAR(r.phi_ext32, -2.5, 1e-9);
                ASSERT_NEAR(r.asymptotic, 1.0, 1e-6);
                assert_int_equal(r.order.bound, SWG_BOUND_NONE);
                assert_true(r.order.converged);
                if (k < 2)
                    assert_int_equal(r.order.iterations, 0); /* closed form */
                else
                    assert_true(r.order.iterations > 0 && r.order.iterations < 100);
                /* GCI = 1.25 e_a / (r21^p - 1) */
                ASSERT_REL(r.gci_fine21, 1.25 * r.e_a21 / (pow(r.r21, r.order.p) - 1), 1e-12);
                ASSERT_REL(r.gci_abs, 1.25 * fabs(r.e21) / (pow(r.r21, r.order.p) - 1), 1e-12);
            }
}

/* the four patterns of Celik's R = e21/e32 and the degenerate ones */
static void verdicts(void **st)
{
    (void)st;
    const swg_settings s = S();
    char err[256];
    const struct {
        double v[3];
        swg_verdict want;
    } cases[] = {
        { { 1.0, 1.1, 0.8 }, SWG_OSCILLATORY },      /* e21 +0.1, e32 -0.3 */
        { { 1.0, 1.3, 1.1 }, SWG_OSC_DIVERGENT },    /* e21 +0.3, e32 -0.2 */
        { { 1.0, 1.2, 1.3 }, SWG_DIVERGENT },        /* e21 0.2, e32 0.1 */
        { { 1.0, 1.2, 1.4 }, SWG_DIVERGENT },        /* R = 1: no convergence */
        { { 1.0, 1.2, 1.2 }, SWG_DIVERGENT },        /* e32 = 0 */
        { { 2.0, 2.0, 2.5 }, SWG_ZERO_FINE },        /* e21 = 0 */
        { { 2.0, 2.0, 2.0 }, SWG_UNCHANGED },        /* equal values */
        { { -0.5, -0.6, -0.8 }, SWG_MONOTONE },      /* negative values */
        { { 0.0, 0.1, 0.3 }, SWG_MONOTONE },         /* phi1 = 0 */
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        swg_level l[3];
        swg_result r;
        for (int j = 0; j < 3; j++)
            l[j] = (swg_level){ 0.1 * pow(2.0, j), cases[i].v[j], 0.0 };
        assert_int_equal(swg_three_level(l, &s, &r, err, sizeof err), 0);
        assert_int_equal(r.verdict, cases[i].want);
        assert_int_equal(r.pattern, cases[i].want);
        ASSERT_NEAR(r.spread, fmax(fmax(l[0].value, l[1].value), l[2].value)
                                  - fmin(fmin(l[0].value, l[1].value), l[2].value), 1e-15);
        if (cases[i].want != SWG_MONOTONE) {
            assert_false(r.has_order);
            assert_true(r.phi_ext21 == 0.0 && r.gci_fine21 == 0.0 && r.gci_abs == 0.0);
        } else {
            assert_true(r.has_order && r.gci_abs > 0.0);
        }
        /* a relative figure needs phi1 != 0 */
        if (l[0].value == 0.0) {
            assert_false(r.has_rel);
            assert_true(r.half_spread_rel == 0.0 && r.e_a21 == 0.0);
        }
    }
    /* the negative ladder: p 1 (differences 0.1, 0.2 on r 2) and phi_ext -0.4 */
    swg_level l[3] = { { 0.1, -0.5, 0 }, { 0.2, -0.6, 0 }, { 0.4, -0.8, 0 } };
    swg_result r;
    assert_int_equal(swg_three_level(l, &s, &r, err, sizeof err), 0);
    ASSERT_NEAR(r.order.p, 1.0, 1e-12);
    ASSERT_NEAR(r.phi_ext21, -0.4, 1e-12);
    ASSERT_NEAR(r.e_a21, 0.2, 1e-12);
}

/* differences inside their sampling errors give no order */
static void sampling(void **st)
{
    (void)st;
    const swg_settings s = S();
    char err[256];
    const double h[3] = { 0.1, 0.2, 0.4 };
    swg_level l[3];
    swg_result r;
    /* e21 = 0.1 (p 1, C 1); combined se sqrt(2) se; resolved iff 0.1 > 2 sqrt(2) se,
       se < 0.035355 */
    ladder(l, h, 1.0, 1.0, 1.0, 0.0354);
    assert_int_equal(swg_three_level(l, &s, &r, err, sizeof err), 0);
    assert_int_equal(r.verdict, SWG_UNRESOLVED);
    assert_int_equal(r.pattern, SWG_MONOTONE);
    assert_false(r.resolved21);
    assert_true(r.resolved32);
    assert_false(r.has_order);
    ASSERT_REL(r.z21, 0.1 / (sqrt(2.0) * 0.0354), 1e-9);
    ladder(l, h, 1.0, 1.0, 1.0, 0.0353);
    assert_int_equal(swg_three_level(l, &s, &r, err, sizeof err), 0);
    assert_int_equal(r.verdict, SWG_MONOTONE);
    assert_true(r.has_order && r.has_se_ext);
    /* the threshold is a setting */
    swg_settings s1 = s;
    s1.z = 1.0;
    ladder(l, h, 1.0, 1.0, 1.0, 0.0354);
    assert_int_equal(swg_three_level(l, &s1, &r, err, sizeof err), 0);
    assert_int_equal(r.verdict, SWG_MONOTONE);
    /* equal values with a sampling error: not resolved, not "unchanged" */
    for (int i = 0; i < 3; i++)
        l[i] = (swg_level){ h[i], 5.0, 0.01 };
    assert_int_equal(swg_three_level(l, &s, &r, err, sizeof err), 0);
    assert_int_equal(r.verdict, SWG_UNRESOLVED);
    assert_int_equal(r.pattern, SWG_UNCHANGED);
    /* an oscillation inside the noise is reported as unresolved */
    const double v[3] = { 1.0, 1.01, 0.99 };
    for (int i = 0; i < 3; i++)
        l[i] = (swg_level){ h[i], v[i], 0.02 };
    assert_int_equal(swg_three_level(l, &s, &r, err, sizeof err), 0);
    assert_int_equal(r.verdict, SWG_UNRESOLVED);
    assert_int_equal(r.pattern, SWG_OSCILLATORY);
}

/* the sampling error carried into p and phi_ext: against the derivatives of
 * the closed form with a constant ratio, p = ln(e32/e21)/ln r,
 * phi_ext = phi1 - e21/(r^p - 1) */
static void sampling_propagated(void **st)
{
    (void)st;
    const swg_settings s = S();
    char err[256];
    const double h[3] = { 0.1, 0.2, 0.4 }, se[3] = { 0.002, 0.003, 0.001 };
    swg_level l[3];
    ladder(l, h, 2.0, 5.0, 1.5, 0.0);
    for (int i = 0; i < 3; i++)
        l[i].se = se[i];
    swg_result r;
    assert_int_equal(swg_three_level(l, &s, &r, err, sizeof err), 0);
    assert_int_equal(r.verdict, SWG_MONOTONE);
    const double lr = log(2.0), e21 = r.e21, e32 = r.e32, p = r.order.p;
    const double dp[3] = { 1.0 / (lr * e21), (-1.0 / e32 - 1.0 / e21) / lr, 1.0 / (lr * e32) };
    double sp2 = 0.0, se2 = 0.0;
    const double d = pow(2.0, p) - 1.0;
    for (int i = 0; i < 3; i++) {
        /* phi_ext = phi1 - e21/d(p): d/dphi_i of it */
        const double de21 = i == 0 ? -1.0 : i == 1 ? 1.0 : 0.0;
        const double dd = pow(2.0, p) * lr * dp[i];
        const double dext = (i == 0 ? 1.0 : 0.0) - de21 / d + e21 * dd / (d * d);
        sp2 += dp[i] * dp[i] * se[i] * se[i];
        se2 += dext * dext * se[i] * se[i];
    }
    ASSERT_REL(r.se_p, sqrt(sp2), 1e-5);
    ASSERT_REL(r.se_phi_ext21, sqrt(se2), 1e-5);
    ASSERT_REL(r.u95_abs, hypot(r.gci_abs, 2 * se[0]), 1e-12);
}

/* the order is held at the bounds of its range, and says so */
static void order_bounds(void **st)
{
    (void)st;
    const swg_settings s = S();
    char err[256];
    swg_level l[3];
    swg_result r;
    const double h[3] = { 0.1, 0.2, 0.4 };
    ladder(l, h, 1.0, 1.0, 10.0, 0.0); /* p 10 > 8 */
    assert_int_equal(swg_three_level(l, &s, &r, err, sizeof err), 0);
    assert_int_equal(r.verdict, SWG_MONOTONE);
    assert_int_equal(r.order.bound, SWG_BOUND_HIGH);
    assert_true(r.order.p == 8.0);
    assert_true(r.order.residual > 1.0); /* the equation is not met at the bound */
    ladder(l, h, 1.0, 1.0, 0.2, 0.0); /* p 0.2 < 0.5 */
    assert_int_equal(swg_three_level(l, &s, &r, err, sizeof err), 0);
    assert_int_equal(r.order.bound, SWG_BOUND_LOW);
    assert_true(r.order.p == 0.5);
    /* non-constant ratio: values of one sign whose equation has no positive root
       (|e32/e21| = 2 below ln r32 / ln r21 = 11.5, Rn = 5.8): divergent, and the
       order alone is held at the lower bound */
    const swg_level m[3] = { { 1.0, 1.0, 0 }, { 1.1, 1.1, 0 }, { 3.3, 1.3, 0 } };
    assert_int_equal(swg_three_level(m, &s, &r, err, sizeof err), 0);
    assert_int_equal(r.verdict, SWG_DIVERGENT);
    ASSERT_REL(r.Rn, 0.5 * log(3.0) / log(1.1), 1e-12);
    swg_order_result o;
    assert_int_equal(swg_order(r.r21, r.r32, r.e21, r.e32, &s, &o, err, sizeof err), 0);
    assert_int_equal(o.bound, SWG_BOUND_LOW);
    assert_true(o.p == 0.5);
    /* the other way: r21 2.5, r32 1.2 and p 1 make |e21| > |e32| (R = 3 > 1), yet
       the ladder converges: Rn = 3 ln 1.2 / ln 2.5 = 0.6 */
    const double hw[3] = { 0.02, 0.05, 0.06 };
    ladder(l, hw, 1.0, 1.0, 1.0, 0.0);
    assert_int_equal(swg_three_level(l, &s, &r, err, sizeof err), 0);
    ASSERT_NEAR(r.R, 3.0, 1e-9);
    assert_int_equal(r.verdict, SWG_MONOTONE);
    ASSERT_NEAR(r.order.p, 1.0, 1e-9);
    /* a narrower range set by the user */
    swg_settings s2 = s;
    s2.p_min = 1.0;
    s2.p_max = 1.4;
    ladder(l, h, 1.0, 1.0, 1.5, 0.0);
    assert_int_equal(swg_three_level(l, &s2, &r, err, sizeof err), 0);
    assert_true(r.order.bound == SWG_BOUND_HIGH && r.order.p == 1.4);
    /* an iteration bound that stops Brent early is reported, not hidden */
    swg_settings s3 = s;
    s3.max_iter = 1;
    const double hn[3] = { 0.1, 0.13, 0.25 };
    ladder(l, hn, 1.0, 1.0, 1.5, 0.0);
    assert_int_equal(swg_three_level(l, &s3, &r, err, sizeof err), 0);
    assert_int_equal(r.order.iterations, 1);
    assert_false(r.order.converged);
    assert_true(r.order.width > 1e-6);
}

static void two_level(void **st)
{
    (void)st;
    const swg_settings s = S();
    char err[256];
    /* phi = 3 + 2 h^2 on h 0.1, 0.2: with the right assumed order phi_ext = 3 */
    const swg_level l[2] = { { 0.1, 3.02, 0.0 }, { 0.2, 3.08, 0.0 } };
    swg_result r;
    assert_int_equal(swg_two_level(l, 2.0, &s, &r, err, sizeof err), 0);
    assert_int_equal(r.verdict, SWG_TWO_LEVEL);
    assert_int_equal(r.nlevels, 2);
    ASSERT_NEAR(r.phi_ext21, 3.0, 1e-12);
    ASSERT_REL(r.gci_fine21, 3.0 * (0.06 / 3.02) / 3.0, 1e-12); /* Fs 3, r^p - 1 = 3 */
    /* the sampling error of phi_ext: (r^p se1)^2 + se2^2 over (r^p - 1)^2 */
    const swg_level m[2] = { { 0.1, 3.02, 0.001 }, { 0.2, 3.08, 0.002 } };
    assert_int_equal(swg_two_level(m, 2.0, &s, &r, err, sizeof err), 0);
    ASSERT_REL(r.se_phi_ext21, hypot(4 * 0.001, 0.002) / 3.0, 1e-12);
    /* inside the noise, and equal values */
    const swg_level n[2] = { { 0.1, 3.02, 0.03 }, { 0.2, 3.08, 0.03 } };
    assert_int_equal(swg_two_level(n, 2.0, &s, &r, err, sizeof err), 0);
    assert_int_equal(r.verdict, SWG_UNRESOLVED);
    assert_false(r.has_order);
    const swg_level q[2] = { { 0.1, 3.0, 0.0 }, { 0.2, 3.0, 0.0 } };
    assert_int_equal(swg_two_level(q, 2.0, &s, &r, err, sizeof err), 0);
    assert_int_equal(r.verdict, SWG_UNCHANGED);
    assert_int_equal(swg_two_level(l, 0.0, &s, &r, err, sizeof err), SWG_EINVAL);
    assert_non_null(strstr(err, "assumed order"));
}

/* named errors for inputs outside the documented ranges */
static void bad_inputs(void **st)
{
    (void)st;
    const swg_settings s = S();
    char err[256];
    swg_result r;
    const double h[3] = { 0.1, 0.2, 0.4 };
    swg_level l[3];
    const struct {
        int lvl;
        double h, v, se;
        const char *msg;
    } bad[] = {
        { 1, 0.1, NAN, 0, "level 2: value" },      { 0, 0.1, INFINITY, 0, "level 1: value" },
        { 2, 0.4, 1, -1, "level 3: standard error" }, { 0, 0.0, 1, 0, "level 1: h" },
        { 0, -0.1, 1, 0, "level 1: h" },            { 1, 0.1, 1, 0, "r21" },
        { 1, 0.5, 1, 0, "r32" },                   { 2, 0.2, 1, 0, "r32" },
        { 2, 1e6, 1, 0, "r32" },                   { 0, 0.1, 1e101, 0, "level 1: value" },
    };
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        ladder(l, h, 1.0, 1.0, 1.0, 0.0);
        l[bad[i].lvl] = (swg_level){ bad[i].h, bad[i].v, bad[i].se };
        err[0] = '\0';
        assert_int_equal(swg_three_level(l, &s, &r, err, sizeof err), SWG_EINVAL);
        assert_non_null(strstr(err, bad[i].msg));
    }
    swg_settings b = s;
    b.p_min = 0.0;
    ladder(l, h, 1.0, 1.0, 1.0, 0.0);
    assert_int_equal(swg_three_level(l, &b, &r, err, sizeof err), SWG_EINVAL);
    assert_non_null(strstr(err, "p_min"));
    b = s;
    b.p_max = NAN;
    assert_int_equal(swg_settings_check(&b, err, sizeof err), SWG_EINVAL);
    assert_non_null(strstr(err, "p_max"));
    b = s;
    b.fs3 = 0.5;
    assert_int_equal(swg_settings_check(&b, err, sizeof err), SWG_EINVAL);
    assert_int_equal(swg_settings_check(NULL, err, sizeof err), SWG_EINVAL);
    double x;
    assert_int_equal(swg_cell_size(1.0, 0.0, 3, &x, err, sizeof err), SWG_EINVAL);
    assert_non_null(strstr(err, "cell count"));
    assert_int_equal(swg_cell_size(-1.0, 10.0, 3, &x, err, sizeof err), SWG_EINVAL);
    assert_int_equal(swg_cell_size(1.0, 10.0, 4, &x, err, sizeof err), SWG_EINVAL);
    assert_int_equal(swg_cell_size(8.0, 1000.0, 3, &x, err, sizeof err), 0);
    ASSERT_REL(x, 0.2, 1e-12);
    swg_order_result o;
    assert_int_equal(swg_order(2.0, 2.0, 0.0, 1.0, &s, &o, err, sizeof err), SWG_EINVAL);
    assert_non_null(strstr(err, "non-zero"));
    /* no message buffer: still the code */
    assert_int_equal(swg_order(1.0, 2.0, 1.0, 1.0, &s, &o, NULL, 0), SWG_EINVAL);
    assert_string_equal(swg_verdict_name(SWG_UNRESOLVED), "not resolved by the statistics");
}

static int all_finite(const swg_result *r)
{
    const double x[] = { r->r21, r->r32, r->e21, r->e32, r->R, r->Rn, r->se21, r->se32, r->z21,
                         r->z32, r->order.p, r->order.width, r->order.residual, r->phi_ext21,
                         r->phi_ext32, r->gci_abs, r->gci32_abs, r->asymptotic, r->e_a21,
                         r->e_ext21, r->gci_fine21, r->se_p, r->se_phi_ext21, r->u95_abs,
                         r->phi_min, r->phi_max, r->spread, r->half_spread_rel };
    for (size_t i = 0; i < sizeof x / sizeof x[0]; i++)
        if (!isfinite(x[i]))
            return 0;
    return 1;
}

/* hostile finite inputs: every combination of extreme values, standard errors
 * and ratios gives finite results or a named error, with the traps on */
static void finite_sweep(void **st)
{
    (void)st;
    const swg_settings s = S();
    char err[256];
    const double vals[] = { 0.0, 1.0, -1.0, 1e-300, 1e100, -1e100, 1.0 + 4e-16, 2.5, 1e-200 };
    const double ses[] = { 0.0, 1e-300, 1.0, 1e100 };
    const double hs[3][3] = { { 1e-100, 1.01e-100, 1e-98 }, { 0.1, 0.2, 0.4 }, { 1, 100, 10000 } };
    const size_t nv = sizeof vals / sizeof vals[0];
    int ok = 0, errors = 0;
    for (size_t a = 0; a < nv; a++)
        for (size_t b = 0; b < nv; b++)
            for (size_t c = 0; c < nv; c++)
                for (size_t e = 0; e < 4; e++)
                    for (size_t k = 0; k < 3; k++) {
                        const swg_level l[3] = { { hs[k][0], vals[a], ses[e] },
                                                 { hs[k][1], vals[b], ses[e] },
                                                 { hs[k][2], vals[c], ses[e] } };
                        swg_result r;
                        err[0] = '\0';
                        const int rc = swg_three_level(l, &s, &r, err, sizeof err);
                        if (rc == 0) {
                            assert_true(all_finite(&r));
                            ok++;
                        } else {
                            assert_int_equal(rc, SWG_EINVAL);
                            assert_true(strlen(err) > 0);
                            errors++;
                        }
                        if (c == 0) {
                            const int rc2 = swg_two_level(l, 2.0, &s, &r, err, sizeof err);
                            assert_true(rc2 == 0 ? all_finite(&r) : rc2 == SWG_EINVAL);
                        }
                    }
    /* most combinations are valid ladders */
    assert_true(ok > 10 * errors);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(celik_table1),       cmocka_unit_test(synthetic_recovered),
        cmocka_unit_test(verdicts),           cmocka_unit_test(sampling),
        cmocka_unit_test(sampling_propagated), cmocka_unit_test(order_bounds),
        cmocka_unit_test(two_level),          cmocka_unit_test(bad_inputs),
        cmocka_unit_test(finite_sweep),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
