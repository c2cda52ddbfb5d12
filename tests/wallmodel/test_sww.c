/* test_sww.c - the wall-interaction core (wallmodel/core, sww_) and the shear
 * detachment closed forms (regime/physics/swp_detach) against independent numbers. */
#include <math.h>
#include <pthread.h>
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
#include "swp_contact.h"
#include "swp_cor.h"
#include "swp_detach.h"

#define SWW_TEST_MAX 4096   /* SWW_MAX_TABLE: values per list */
#define ASSERT_REL(x, ref, tol) assert_true(fabs((x) - (ref)) <= (tol) * fabs(ref))

static const char *const FIXTURE = SWW_FIXTURES "/regime.coeffs";
/* the fixture's fit: ln d = C0 + C1 x + C2 x^2 + C3 x^3, x = ln v */
static const double C0 = -10.414313, C1 = -1.3, C2 = -0.02, C3 = -0.005;
static const double VNMIN = 0.2, VNMAX = 6.0, SLO = -1.2, SHI = -1.4, VY = 1.44e-4;

static double fit(double v)
{
    const double x = log(v);
    return exp(C0 + C1 * x + C2 * x * x + C3 * x * x * x);
}

static char tmpdir[64];

static int setup(void **s)
{
    (void)s;
    strcpy(tmpdir, "/tmp/sww-test-XXXXXX");
    return mkdtemp(tmpdir) ? 0 : -1;
}

static int teardown(void **s)
{
    (void)s;
    char cmd[128];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", tmpdir);
    return system(cmd) == 0 ? 0 : -1;
}

static sww_model *load_fixture(void)
{
    sww_model *m = sww_alloc();
    assert_non_null(m);
    const int rc = sww_regime_load(m, FIXTURE);
    if (rc)
        fprintf(stderr, "%s\n", sww_errmsg(m));
    assert_int_equal(rc, SWW_OK);
    return m;
}

static sww_outcome decide(const sww_model *m, double d, double vn, double vt, double tau, double u)
{
    sww_impact in = { .d = d, .vn = vn, .vt = vt, .tau_w = tau, .u = u };
    sww_outcome out;
    assert_int_equal(sww_decide(m, &in, &out), SWW_OK);
    return out;
}

/* ------------------------------------------------------------- criterion */

static void fixture_loads(void **s)
{
    (void)s;
    sww_model *m = load_fixture();
    assert_true(sww_ready(m));
    assert_string_equal(sww_label(m), "test fixture: dry snow on ABS");
    assert_true(sww_vn_min(m) == VNMIN && sww_vn_max(m) == VNMAX);
    for (double v = VNMIN; v <= VNMAX; v *= 1.37)
        ASSERT_REL(sww_dcrit(m, v), fit(v), 1e-12);
    ASSERT_REL(sww_dcrit(m, 1.0), 3e-5, 1e-6);
    assert_false(sww_tangential_on(m));
    assert_false(sww_shear_on(m));
    char buf[512];
    sww_describe(m, buf, sizeof buf);
    assert_non_null(strstr(buf, "tangential gate off; shear gate off"));
    sww_free(m);
}

static void criterion_stick_bounce(void **s)
{
    (void)s;
    sww_model *m = load_fixture();
    const double vns[] = { 0.05, 0.2, 0.7, 1.0, 3.3, 6.0, 20.0 };
    for (size_t i = 0; i < sizeof vns / sizeof *vns; i++) {
        const double v = vns[i], dc = sww_dcrit(m, v);
        sww_outcome o = decide(m, dc * 0.999, v, 5.0, 0.0, 0.3);
        assert_int_equal(o.fate, SWW_STICK);
        assert_int_equal(o.reason, SWW_BY_CRITERION);
        assert_true(o.e_n == 1.0 && o.e_t == 1.0 && o.p_stick == 1.0);
        o = decide(m, dc, v, 0.0, 0.0, 0.0); /* d == d_crit: sticks (bounce if d > d_crit) */
        assert_int_equal(o.fate, SWW_STICK);
        o = decide(m, dc * 1.001, v, 0.0, 0.0, 0.999);
        assert_int_equal(o.fate, SWW_BOUNCE);
        assert_int_equal(o.reason, SWW_BY_CRITERION);
        assert_true(o.p_stick == 0.0);
        /* rebound factors: Thornton with the file's yield velocity, e_t default 1 */
        ASSERT_REL(o.e_n, swp_cor_thornton(VY / v), 1e-14);
        assert_true(o.e_n > 0.0 && o.e_n < 1.0);
        assert_true(o.e_t == 1.0);
        ASSERT_REL(o.d_crit, dc, 0.0);
    }
    /* constant rebound and tangential factor */
    assert_int_equal(sww_regime_number(m, "reboundNormal", 0.3), SWW_OK);
    assert_false(sww_ready(m)); /* changed: must be committed again */
    sww_impact in = { .d = 1e-4, .vn = 2.0, .u = 0.5 };
    sww_outcome o;
    assert_int_equal(sww_decide(m, &in, &o), SWW_ENOTREADY);
    assert_int_equal(sww_regime_commit(m, "code"), SWW_OK);
    assert_int_equal(sww_set_rebound_tangential(m, 0.8), SWW_OK);
    o = decide(m, 1e-4, 2.0, 1.0, 0.0, 0.5);
    assert_int_equal(o.fate, SWW_BOUNCE);
    assert_true(o.e_n == 0.3 && o.e_t == 0.8);
    assert_int_equal(sww_set_rebound_tangential(m, 1.5), SWW_EINVAL);
    assert_non_null(strstr(sww_errmsg(m), "1.5"));
    sww_free(m);
}

/* d_crit is never the polynomial outside [vnMin, vnMax]: power law anchored at the end. */
static void range_handling(void **s)
{
    (void)s;
    sww_model *m = load_fixture();
    const double dlo = fit(VNMIN), dhi = fit(VNMAX);
    const double lows[] = { 0.19999, 0.1, 1e-3, 1e-9 };
    for (size_t i = 0; i < 4; i++)
        ASSERT_REL(sww_dcrit(m, lows[i]), dlo * pow(lows[i] / VNMIN, SLO), 1e-12);
    const double highs[] = { 6.0001, 10.0, 100.0, 1e6 };
    for (size_t i = 0; i < 4; i++) {
        ASSERT_REL(sww_dcrit(m, highs[i]), dhi * pow(highs[i] / VNMAX, SHI), 1e-12);
        /* the cubic itself would turn elsewhere: it is not used out here */
    }
    assert_true(fit(1e6) != sww_dcrit(m, 1e6));
    /* continuous at both ends */
    ASSERT_REL(sww_dcrit(m, VNMIN * (1 - 1e-12)), sww_dcrit(m, VNMIN), 1e-9);
    ASSERT_REL(sww_dcrit(m, VNMAX * (1 + 1e-12)), sww_dcrit(m, VNMAX), 1e-9);
    /* extreme inputs: no NaN, physically sensible limits */
    assert_true(isinf(sww_dcrit(m, 0.0)));
    assert_true(isinf(sww_dcrit(m, 1e-320)) || sww_dcrit(m, 1e-320) > 1.0);
    assert_true(sww_dcrit(m, 1e300) >= 0.0);
    assert_true(isnan(sww_dcrit(m, NAN)));
    sww_outcome o = decide(m, 1e-3, 0.0, 0.0, 0.0, 0.1); /* v_n = 0: no bounce */
    assert_int_equal(o.fate, SWW_STICK);
    assert_int_equal(o.range, -1);
    assert_int_equal(decide(m, 1e-5, VNMIN, 0.0, 0.0, 0.1).range, 0);
    assert_int_equal(decide(m, 1e-5, VNMAX, 0.0, 0.0, 0.1).range, 0);
    assert_int_equal(decide(m, 1e-5, VNMAX * 1.0001, 0.0, 0.0, 0.1).range, 1);
    assert_int_equal(decide(m, 1e-5, VNMIN * 0.9999, 0.0, 0.0, 0.1).range, -1);
    o = decide(m, 1e-6, 1e300, 0.0, 0.0, 0.1);
    assert_int_equal(o.fate, SWW_BOUNCE);
    assert_false(isnan(o.e_n));
    sww_free(m);
}

static void table_and_linear_from_code(void **s)
{
    (void)s;
    sww_model *m = sww_alloc();
    const double vn[] = { 0.1, 1.0, 10.0 }, dc[] = { 1e-4, 1e-5, 4e-6 };
    assert_int_equal(sww_regime_word(m, "representation", "table"), SWW_OK);
    assert_int_equal(sww_regime_list(m, "vn", vn, 3), SWW_OK);
    assert_int_equal(sww_regime_list(m, "dCrit", dc, 3), SWW_OK);
    assert_int_equal(sww_regime_number(m, "vnMin", 0.1), SWW_OK);
    assert_int_equal(sww_regime_number(m, "vnMax", 10.0), SWW_OK);
    assert_int_equal(sww_regime_number(m, "slopeLow", -1.0), SWW_OK);
    assert_int_equal(sww_regime_number(m, "slopeHigh", 0.0), SWW_OK);
    /* an unknown key from code is refused too, and names itself */
    assert_int_equal(sww_regime_number(m, "bogus", 1.0), SWW_EINVAL);
    assert_non_null(strstr(sww_errmsg(m), "'bogus' is not a regime key"));
    assert_int_equal(sww_regime_list(m, "bogus", vn, 3), SWW_EINVAL);
    assert_int_equal(sww_regime_word(m, "bogus", "x"), SWW_EINVAL);
    assert_int_equal(sww_regime_commit(m, "code"), SWW_OK);
    /* linear in ln-ln: geometric means at the log midpoints */
    ASSERT_REL(sww_dcrit(m, sqrt(0.1 * 1.0)), sqrt(1e-4 * 1e-5), 1e-12);
    ASSERT_REL(sww_dcrit(m, sqrt(10.0)), sqrt(1e-5 * 4e-6), 1e-12);
    ASSERT_REL(sww_dcrit(m, 1.0), 1e-5, 1e-12);
    ASSERT_REL(sww_dcrit(m, 0.01), 1e-4 * pow(0.1, -1.0), 1e-12);
    ASSERT_REL(sww_dcrit(m, 1000.0), 4e-6, 1e-12); /* flat slope */
    /* no yieldVelocity, no reboundNormal: elastic rebound */
    assert_true(sww_rebound_normal(m, 3.0) == 1.0);

    /* linear basis: d_crit = 5e-5 - 4e-6 v on [1, 10] */
    sww_regime_clear(m);
    const double c[] = { 5e-5, -4e-6 };
    assert_int_equal(sww_regime_word(m, "representation", "polynomial"), SWW_OK);
    assert_int_equal(sww_regime_word(m, "basis", "linear"), SWW_OK);
    assert_int_equal(sww_regime_list(m, "coeffs", c, 2), SWW_OK);
    assert_int_equal(sww_regime_number(m, "degree", 1), SWW_OK);
    assert_int_equal(sww_regime_number(m, "vnMin", 1.0), SWW_OK);
    assert_int_equal(sww_regime_number(m, "vnMax", 10.0), SWW_OK);
    assert_int_equal(sww_regime_number(m, "slopeLow", -1.0), SWW_OK);
    assert_int_equal(sww_regime_number(m, "slopeHigh", -2.0), SWW_OK);
    assert_int_equal(sww_regime_number(m, "reboundNormal", 0.5), SWW_OK);
    assert_int_equal(sww_regime_commit(m, "code"), SWW_OK);
    ASSERT_REL(sww_dcrit(m, 5.0), 3e-5, 1e-12);
    ASSERT_REL(sww_dcrit(m, 20.0), 1e-5 * 0.25, 1e-12);
    /* the linear polynomial would go negative at 12.5 m/s; the power law does not */
    assert_true(sww_dcrit(m, 13.0) > 0.0);
    sww_free(m);
}

/* ------------------------------------------------------------- gates */

static void tangential_gate(void **s)
{
    (void)s;
    sww_model *m = load_fixture();
    const double d = 1e-5, v = 1.0; /* well below d_crit = 30 um: a stick candidate */
    assert_true(isinf(sww_vt_max(m, d)));
    assert_int_equal(decide(m, d, v, 1e3, 0.0, 0.5).fate, SWW_STICK); /* off: any v_t sticks */
    assert_int_equal(sww_set_tangential_gate(m, 2.0, 5e-5, 0.0), SWW_OK);
    assert_int_equal(decide(m, d, v, 2.0, 0.0, 0.5).fate, SWW_STICK);
    sww_outcome o = decide(m, d, v, 2.0001, 0.0, 0.5);
    assert_int_equal(o.fate, SWW_BOUNCE);
    assert_int_equal(o.reason, SWW_BY_TANGENTIAL);
    ASSERT_REL(o.e_n, swp_cor_thornton(VY / v), 1e-14);
    /* a bouncing particle stays a bounce by the criterion */
    o = decide(m, 1e-4, v, 100.0, 0.0, 0.5);
    assert_int_equal(o.reason, SWW_BY_CRITERION);
    /* power law vtMax(d) = 2 (d / 50 um)^-0.5 */
    assert_int_equal(sww_set_tangential_gate(m, 2.0, 5e-5, -0.5), SWW_OK);
    ASSERT_REL(sww_vt_max(m, 1.25e-5), 4.0, 1e-14);
    assert_int_equal(decide(m, 1.25e-5, v, 3.99, 0.0, 0.5).fate, SWW_STICK);
    assert_int_equal(decide(m, 1.25e-5, v, 4.01, 0.0, 0.5).fate, SWW_BOUNCE);
    sww_set_tangential_off(m);
    assert_int_equal(decide(m, 1.25e-5, v, 400.0, 0.0, 0.5).fate, SWW_STICK);
    assert_int_equal(sww_set_tangential_gate(m, NAN, 5e-5, 0), SWW_EINVAL);
    assert_non_null(strstr(sww_errmsg(m), "vtMax nan"));
    assert_int_equal(sww_set_tangential_gate(m, 1.0, -5e-5, 0), SWW_EINVAL);
    assert_non_null(strstr(sww_errmsg(m), "dRef -5e-05"));
    assert_int_equal(sww_set_tangential_gate(m, 1.0, 5e-5, INFINITY), SWW_EINVAL);
    assert_false(sww_tangential_on(m));
    sww_free(m);
}

/* Independent critical shear stress: moments / forces written out here. */
static double tau_indep(double G, double Es, double R, double mu, double k)
{
    const double Fc = k * 1.5 * M_PI * G * R;
    const double a0 = cbrt(9.0 * M_PI * G * R * R / (2.0 * Es));
    /* per unit tau: drag 1.7009*3 pi mu d (R/mu) = 1.7009*6 pi R^2; torque 0.944*4 pi R^3 */
    const double drag1 = 1.7009 * 3.0 * M_PI * (2.0 * R) * R;
    const double torque1 = 0.944 * 4.0 * M_PI * R * R * R;
    const double roll = Fc * a0 / (drag1 * R + torque1);
    const double slide = mu * Fc / drag1;
    return mu > 0 && slide < roll ? slide : roll;
}

/* Build-up feedback (a face covered by snow): bare -> blended -> covered. The covered
 * regime is the fixture with ln d_crit lowered by ln 2 (d_crit(1 m/s) 15 um
 * instead of 30 um) and a constant rebound 0.3. */
static int same_outcome(const sww_outcome *a, const sww_outcome *b)
{
    return a->fate == b->fate && a->reason == b->reason && a->d_crit == b->d_crit
        && a->p_stick == b->p_stick && a->e_n == b->e_n && a->e_t == b->e_t
        && a->range == b->range;
}

static void buildup_blend(void **s)
{
    (void)s;
    sww_model *bare = load_fixture(), *cov = load_fixture();
    const double c[] = { C0 - log(2.0), C1, C2, C3 };
    assert_int_equal(sww_regime_list(cov, "coeffs", c, 4), SWW_OK);
    assert_int_equal(sww_regime_number(cov, "reboundNormal", 0.3), SWW_OK);
    assert_int_equal(sww_regime_commit(cov, "covered"), SWW_OK);
    ASSERT_REL(sww_dcrit(cov, 1.0), 0.5 * sww_dcrit(bare, 1.0), 1e-12);
    const double d = 2e-5, v = 1.0; /* sticks on the bare wall, bounces on snow */
    sww_impact in = { .d = d, .vn = v, .vt = 0.0, .tau_w = 0.0, .u = 0.999 };
    sww_outcome o, ref;
    /* bare: w = 0 is sww_decide of the bare regime exactly, for any u */
    assert_int_equal(sww_decide_blend(bare, cov, 0.0, &in, &o), SWW_OK);
    assert_int_equal(sww_decide(bare, &in, &ref), SWW_OK);
    assert_true(same_outcome(&o, &ref));
    assert_int_equal(o.fate, SWW_STICK);
    /* covered: w = 1 is the covered regime */
    in.u = 0.0;
    assert_int_equal(sww_decide_blend(bare, cov, 1.0, &in, &o), SWW_OK);
    assert_int_equal(sww_decide(cov, &in, &ref), SWW_OK);
    assert_true(same_outcome(&o, &ref));
    assert_int_equal(o.fate, SWW_BOUNCE);
    ASSERT_REL(o.e_n, 0.3, 1e-15);
    /* blended, w = 0.3: p_stick = 0.7 */
    in.u = 0.69;
    assert_int_equal(sww_decide_blend(bare, cov, 0.3, &in, &o), SWW_OK);
    assert_int_equal(o.fate, SWW_STICK);
    ASSERT_REL(o.p_stick, 0.7, 1e-15);
    ASSERT_REL(o.d_crit, 0.7 * sww_dcrit(bare, v) + 0.3 * sww_dcrit(cov, v), 1e-14);
    in.u = 0.71;
    assert_int_equal(sww_decide_blend(bare, cov, 0.3, &in, &o), SWW_OK);
    assert_int_equal(o.fate, SWW_BOUNCE);
    ASSERT_REL(o.e_n, 0.3, 1e-15);               /* the regime that bounced */
    /* the fraction of sticks over many u is 1 - w */
    for (double w = 0.0; w <= 1.0; w += 0.125) {
        long n = 0;
        for (int k = 0; k < 1000; k++) {
            in.u = (k + 0.5) / 1000.0;
            assert_int_equal(sww_decide_blend(bare, cov, w, &in, &o), SWW_OK);
            n += o.fate == SWW_STICK;
        }
        assert_int_equal(n, (long)lround(1000.0 * (1.0 - w)));
    }
    /* both agree: no blend effect */
    in.d = 5e-6;
    in.u = 0.999;
    assert_int_equal(sww_decide_blend(bare, cov, 0.5, &in, &o), SWW_OK);
    assert_int_equal(o.fate, SWW_STICK);
    /* no covered regime: the bare one */
    assert_int_equal(sww_decide_blend(bare, NULL, 0.5, &in, &o), SWW_OK);
    /* bad input */
    assert_int_equal(sww_decide_blend(bare, cov, -0.1, &in, &o), SWW_EINVAL);
    assert_int_equal(sww_decide_blend(bare, cov, 1.5, &in, &o), SWW_EINVAL);
    assert_int_equal(sww_decide_blend(bare, cov, NAN, &in, &o), SWW_EINVAL);
    in.u = 1.0;
    assert_int_equal(sww_decide_blend(bare, cov, 0.5, &in, &o), SWW_EINVAL);
    /* the covered fraction and the monolayer */
    ASSERT_REL(sww_monolayer_mass(920.0, 33e-6), M_PI / (2.0 * sqrt(3.0)) * 2.0 / 3.0 * 920.0 * 33e-6, 1e-15);
    ASSERT_REL(sww_monolayer_mass(920.0, 33e-6), 0.018357, 1e-4);
    assert_true(isnan(sww_monolayer_mass(-1.0, 1e-5)) && isnan(sww_monolayer_mass(920.0, INFINITY)));
    assert_true(sww_cover_fraction(0.0, 0.02) == 0.0 && sww_cover_fraction(-1.0, 0.02) == 0.0);
    ASSERT_REL(sww_cover_fraction(0.005, 0.02), 0.25, 1e-15);
    assert_true(sww_cover_fraction(0.02, 0.02) == 1.0 && sww_cover_fraction(1e9, 0.02) == 1.0);
    assert_true(isnan(sww_cover_fraction(NAN, 0.02)) && isnan(sww_cover_fraction(0.01, 0.0)));
    /* NaN or zero inputs give a NaN result without forming one by arithmetic
     * (the floating-point traps stay quiet); a tiny covering mass saturates instead of overflowing; an
     * overflowing monolayer is INFINITY */
    assert_true(isnan(sww_monolayer_mass(NAN, 1e-5)) && isnan(sww_monolayer_mass(920.0, 0.0)));
    assert_true(isnan(sww_cover_fraction(0.01, NAN)));
    assert_true(sww_cover_fraction(1.0, 1e-320) == 1.0 && sww_cover_fraction(1e300, 1e-300) == 1.0);
    assert_true(isinf(sww_monolayer_mass(1e300, 1e300)));
    sww_free(bare);
    sww_free(cov);
}

/* The oblique table (d_crit over v_n and v_t) from code: the fixture's normal interface with
 * a table D = min(d_crit(v_n), d_t(v_t)), d_t = 20 um (v_t / 0.5)^(-2/3). */
static double dtan(double vt) { return 2e-5 * pow(vt / 0.5, -2.0 / 3.0); }

static void set_oblique(sww_model *m, const double *vt, size_t nvt)
{
    const double vn[] = { 0.05, 0.2, 1.0, 6.0, 20.0 };
    double d[5 * 8];
    for (size_t i = 0; i < nvt; i++)
        for (size_t j = 0; j < 5; j++) {
            const double dn = sww_dcrit(m, vn[j]);
            d[i * 5 + j] = i == 0 ? dn : fmin(dn, dtan(vt[i]));
        }
    assert_int_equal(sww_regime_list(m, "obliqueVt", vt, nvt), SWW_OK);
    assert_int_equal(sww_regime_list(m, "obliqueVn", vn, 5), SWW_OK);
    assert_int_equal(sww_regime_list(m, "obliqueDCrit", d, nvt * 5), SWW_OK);
    assert_int_equal(sww_regime_number(m, "obliqueSlide", 1e-4), SWW_OK);
    assert_int_equal(sww_regime_commit(m, "code"), SWW_OK);
}

static void oblique_gate(void **s)
{
    (void)s;
    sww_model *m = load_fixture();
    /* without a table the regime gate cannot be set; d_crit(v_n, v_t) = d_crit(v_n) */
    assert_int_equal(sww_set_tangential_regime(m), SWW_EMISSING);
    assert_non_null(strstr(sww_errmsg(m), "oblique table"));
    assert_true(sww_dcrit_oblique(m, 1.0, 5.0) == sww_dcrit(m, 1.0));
    assert_false(sww_oblique_table(m, NULL, NULL));
    assert_int_equal(sww_check_oblique_slide(m, 1e-4), SWW_EMISSING);
    assert_non_null(strstr(sww_errmsg(m), "has no oblique table"));
    {
        /* a table without obliqueSlide: the slide length cannot be checked, an
         * error rather than a NaN that a caller with traps on would compare */
        sww_model *t = load_fixture();
        const double tvt[] = { 0.0, 1.0 }, tvn[] = { 0.1, 1.0 }, td[] = { 1e-4, 3e-5, 5e-5, 2e-5 };
        assert_int_equal(sww_regime_list(t, "obliqueVt", tvt, 2), SWW_OK);
        assert_int_equal(sww_regime_list(t, "obliqueVn", tvn, 2), SWW_OK);
        assert_int_equal(sww_regime_list(t, "obliqueDCrit", td, 4), SWW_OK);
        assert_int_equal(sww_regime_commit(t, "code"), SWW_OK);
        assert_true(isnan(sww_oblique_slide(t)));
        assert_int_equal(sww_check_oblique_slide(t, 1e-4), SWW_EMISSING);
        assert_non_null(strstr(sww_errmsg(t), "oblique table has no obliqueSlide"));
        sww_free(t);
    }
    const double vt[] = { 0.0, 0.5, 1.0, 2.0 };
    set_oblique(m, vt, 4);
    size_t nvt, nvn;
    assert_true(sww_oblique_table(m, &nvt, &nvn) && nvt == 4 && nvn == 5);
    /* a case's slide length against the table's obliqueSlide (1e-4) */
    assert_int_equal(sww_check_oblique_slide(m, 1e-4), SWW_OK);
    assert_int_equal(sww_check_oblique_slide(m, 1e-4 * (1.0 + 1e-12)), SWW_OK);
    assert_int_equal(sww_check_oblique_slide(m, 2e-4), SWW_EINVAL);
    assert_non_null(strstr(sww_errmsg(m), "slideLength 0.0002 m differs from the regime table's obliqueSlide 0.0001 m"));
    assert_int_equal(sww_check_oblique_slide(m, -1.0), SWW_EINVAL);
    assert_int_equal(sww_check_oblique_slide(m, NAN), SWW_EINVAL);
    assert_non_null(strstr(sww_errmsg(m), "slideLength nan must be a finite length >= 0 m"));
    assert_int_equal(sww_check_oblique_slide(m, INFINITY), SWW_EINVAL);
    assert_int_equal(sww_set_tangential_regime(m), SWW_OK);
    assert_int_equal(sww_tangential_on(m), 2);
    /* v_t = 0 and v_t -> 0: the normal interface exactly */
    for (double v = 0.01; v < 100.0; v *= 1.7) {
        assert_true(sww_dcrit_oblique(m, v, 0.0) == sww_dcrit(m, v));
        assert_true(sww_dcrit_oblique(m, v, 1e-9) == sww_dcrit(m, v));
    }
    /* where the tangential limit binds (v_n 0.2: d_crit 100+ um), the power law
     * d_t is exact inside, below and beyond the v_t nodes (linear in ln-ln) */
    const double vts[] = { 0.5, 0.7, 1.0, 1.5, 0.1, 0.02, 3.0, 40.0 };
    for (size_t k = 0; k < sizeof vts / sizeof *vts; k++)
        ASSERT_REL(sww_dcrit_oblique(m, 0.2, vts[k]), dtan(vts[k]), 1e-12);
    /* off the v_n nodes too (D_t does not depend on v_n here) */
    ASSERT_REL(sww_dcrit_oblique(m, 0.37, 0.8), fmin(sww_dcrit(m, 0.37), dtan(0.8)), 1e-12);
    /* where the normal limit binds the kink is exact: min of the two */
    ASSERT_REL(sww_dcrit_oblique(m, 3.0, 0.7), fmin(sww_dcrit(m, 3.0), dtan(0.7)), 1e-12);
    /* outside the v_n span: the tangential limit of the end column */
    ASSERT_REL(sww_dcrit_oblique(m, 0.001, 1.0), dtan(1.0), 1e-12);
    ASSERT_REL(sww_dcrit_oblique(m, 500.0, 1.0), fmin(sww_dcrit(m, 500.0), dtan(1.0)), 1e-12);
    /* monotone in v_t, never NaN, limits */
    srand48(7);
    for (int k = 0; k < 20000; k++) {
        const double vn = exp(-8.0 + 16.0 * drand48()), v1 = exp(-12.0 + 20.0 * drand48());
        const double a = sww_dcrit_oblique(m, vn, v1), b = sww_dcrit_oblique(m, vn, 1.3 * v1);
        assert_true(a > 0.0 && b > 0.0 && isfinite(a) && b <= a);
    }
    assert_true(sww_dcrit_oblique(m, 1.0, INFINITY) == 0.0);
    assert_true(isnan(sww_dcrit_oblique(m, NAN, 1.0)) && isnan(sww_dcrit_oblique(m, 1.0, NAN)));
    assert_true(isinf(sww_dcrit_oblique(m, 0.0, 1.0)));
    /* the decision: between d_t and d_crit(v_n) a stick candidate bounces by
     * the tangential gate; below d_t it sticks */
    const double d = 0.5 * (dtan(1.0) + sww_dcrit(m, 0.5));
    assert_true(d > dtan(1.0) && d < sww_dcrit(m, 0.5));
    sww_outcome o = decide(m, d, 0.5, 1.0, 0.0, 0.5);
    assert_int_equal(o.fate, SWW_BOUNCE);
    assert_int_equal(o.reason, SWW_BY_TANGENTIAL);
    assert_int_equal(decide(m, d, 0.5, 0.0, 0.0, 0.5).fate, SWW_STICK);
    assert_int_equal(decide(m, 0.9 * dtan(1.0), 0.5, 1.0, 0.0, 0.5).fate, SWW_STICK);
    char buf[600];
    sww_describe(m, buf, sizeof buf);
    assert_non_null(strstr(buf, "regime table 4 x 5"));
    /* loading a regime without a table while the gate is on: an error naming
     * the missing table; a failed load changes nothing (the model loaded
     * before is kept): the gate, the table and the decisions stay */
    assert_int_equal(sww_regime_load(m, FIXTURE), SWW_EMISSING);
    assert_non_null(strstr(sww_errmsg(m), "needs the oblique table"));
    assert_int_equal(sww_tangential_on(m), 2);
    assert_true(sww_ready(m));
    assert_int_equal(decide(m, d, 0.5, 1.0, 0.0, 0.5).reason, SWW_BY_TANGENTIAL);
    assert_int_equal(sww_regime_load(m, "/no/such/regime.coeffs"), SWW_EIO);
    assert_true(sww_ready(m));
    assert_int_equal(decide(m, d, 0.5, 0.0, 0.0, 0.5).fate, SWW_STICK);
    /* after a failed load, a successful one leaves no stale message */
    sww_set_tangential_off(m);
    assert_int_equal(sww_regime_load(m, FIXTURE), SWW_OK);
    assert_string_equal(sww_errmsg(m), "");
    sww_free(m);

    /* two v_t values: flat below the only non-zero node (documented) */
    m = load_fixture();
    const double vt2[] = { 0.0, 1.0 };
    set_oblique(m, vt2, 2);
    ASSERT_REL(sww_dcrit_oblique(m, 0.2, 0.1), dtan(1.0), 1e-12);
    ASSERT_REL(sww_dcrit_oblique(m, 0.2, 10.0), dtan(1.0), 1e-12);
    sww_free(m);

    /* errors, each naming the key and value */
    m = load_fixture();
    const double vbad[] = { 0.1, 0.5 }, vdec[] = { 0.0, 0.5, 0.4 }, vn3[] = { 0.1, 1.0, 10.0 };
    assert_int_equal(sww_regime_list(m, "obliqueVt", vbad, 2), SWW_EINVAL);
    assert_non_null(strstr(sww_errmsg(m), "must be 0"));
    assert_int_equal(sww_regime_list(m, "obliqueVt", vdec, 3), SWW_EINVAL);
    assert_non_null(strstr(sww_errmsg(m), "strictly increasing"));
    const double dneg[] = { 1e-5, -1e-5, 1e-5, 1e-5, 1e-5, 1e-5 };
    assert_int_equal(sww_regime_list(m, "obliqueDCrit", dneg, 6), SWW_EINVAL);
    assert_non_null(strstr(sww_errmsg(m), "-1e-05"));
    assert_int_equal(sww_regime_number(m, "obliqueVt", 1.0), SWW_EINVAL);
    const double vt3[] = { 0.0, 0.5, 1.0 };
    assert_int_equal(sww_regime_list(m, "obliqueVt", vt3, 3), SWW_OK);
    assert_int_equal(sww_regime_commit(m, "code"), SWW_EMISSING);
    assert_non_null(strstr(sww_errmsg(m), "obliqueVn"));
    assert_int_equal(sww_regime_list(m, "obliqueVn", vn3, 3), SWW_OK);
    const double d8[] = { 1e-5, 1e-5, 1e-5, 1e-5, 1e-5, 1e-5, 1e-5, 1e-5 };
    assert_int_equal(sww_regime_list(m, "obliqueDCrit", d8, 8), SWW_OK);
    assert_int_equal(sww_regime_commit(m, "code"), SWW_EINVAL);
    assert_non_null(strstr(sww_errmsg(m), "8 values"));
    const double drise[] = { 1e-5, 1e-5, 1e-5, 2e-5, 1e-5, 1e-5, 1e-5, 1e-5, 1e-5 };
    assert_int_equal(sww_regime_list(m, "obliqueDCrit", drise, 9), SWW_OK);
    assert_int_equal(sww_regime_commit(m, "code"), SWW_EINVAL);
    assert_non_null(strstr(sww_errmsg(m), "must not increase with v_t"));
    sww_free(m);
}

/* ------------------------------------------------------------- rough wall */

/* A rough wall's stick-probability table on the fixture's interface: diameters
 * 5, 20, 80 um, speeds 0.5, 1, 4 m/s; p rows by diameter. */
static const double PD[] = { 5e-6, 2e-5, 8e-5 }, PV[] = { 0.5, 1.0, 4.0 };
static const double PP[] = { 0.95, 0.90, 0.60,    /* d 5 um  */
                             0.80, 0.55, 0.20,    /* d 20 um */
                             0.40, 0.10, 0.00 };  /* d 80 um */

static const char *PTABLE =
    "    probabilityD      (5e-6 2e-5 8e-5);\n"
    "    probabilityVn     (0.5 1 4);\n"
    "    probabilityStick  (0.95 0.90 0.60 0.80 0.55 0.20 0.40 0.10 0.00);\n"
    "    probabilityPoints 64;\n";

/* the fixture file with the table inside regime { } */
static sww_model *load_rough(void)
{
    FILE *f = fopen(FIXTURE, "r");
    assert_non_null(f);
    static char text[8192];
    const size_t n = fread(text, 1, sizeof text - 1, f);
    fclose(f);
    text[n] = '\0';
    char *close = strrchr(text, '}');
    assert_non_null(close);
    char out[10000];
    snprintf(out, sizeof out, "%.*s%s}\n", (int)(close - text), text, PTABLE);
    char path[256];
    snprintf(path, sizeof path, "%s/rough.coeffs", tmpdir);
    f = fopen(path, "w");
    assert_non_null(f);
    fputs(out, f);
    fclose(f);
    sww_model *m = sww_alloc();
    const int rc = sww_regime_load(m, path);
    if (rc)
        fprintf(stderr, "%s\n", sww_errmsg(m));
    assert_int_equal(rc, SWW_OK);
    return m;
}

/* bilinear in (ln d, ln v_n), written out independently: weights of the four
 * corners of the cell (i, j) */
static double p_expected(double d, double v)
{
    size_t i = 0, j = 0;
    while (i < 1 && d > PD[i + 1])
        i++;
    while (j < 1 && v > PV[j + 1])
        j++;
    const double a = log(d / PD[i]) / log(PD[i + 1] / PD[i]);
    const double b = log(v / PV[j]) / log(PV[j + 1] / PV[j]);
    return PP[i * 3 + j] * (1 - a) * (1 - b) + PP[i * 3 + j + 1] * (1 - a) * b
         + PP[(i + 1) * 3 + j] * a * (1 - b) + PP[(i + 1) * 3 + j + 1] * a * b;
}

static void probability_table(void **s)
{
    (void)s;
    sww_model *m = load_rough(), *sharp = load_fixture();
    size_t nd = 9, nv = 9;
    assert_true(sww_probability_table(m, &nd, &nv) && nd == 3 && nv == 3);
    assert_false(sww_probability_table(sharp, &nd, &nv));
    assert_true(nd == 0 && nv == 0);
    assert_false(sww_probability_table(sharp, NULL, NULL));
    /* the interface is unchanged: d_crit is the p = 0.5 contour's fit */
    for (double v = 0.01; v < 100.0; v *= 1.9)
        assert_true(sww_dcrit(m, v) == sww_dcrit(sharp, v));
    /* exactly the table at the nodes (corners and edges included) */
    for (size_t i = 0; i < 3; i++)
        for (size_t j = 0; j < 3; j++) {
            const sww_outcome o = decide(m, PD[i], PV[j], 0.0, 0.0, 0.0);
            assert_true(o.p_stick == PP[i * 3 + j]);
            assert_int_equal(o.fate, PP[i * 3 + j] > 0.0 ? SWW_STICK : SWW_BOUNCE);
        }
    /* bilinear in (ln d, ln v_n) in between */
    srand48(11);
    double pmin = 1.0, pmax = 0.0;
    for (int k = 0; k < 2000; k++) {
        const double d = PD[0] * pow(PD[2] / PD[0], drand48());
        const double v = PV[0] * pow(PV[2] / PV[0], drand48());
        const double p = decide(m, d, v, 0.0, 0.0, 0.5).p_stick;
        assert_true(fabs(p - p_expected(d, v)) <= 1e-12);
        pmin = fmin(pmin, p);
        pmax = fmax(pmax, p);
    }
    assert_true(pmin < 0.1 && pmax > 0.9);
    /* the centre of a cell: the mean of its corners */
    assert_true(fabs(decide(m, sqrt(PD[0] * PD[1]), sqrt(PV[1] * PV[2]), 0, 0, 0.5).p_stick
                     - 0.25 * (0.90 + 0.60 + 0.55 + 0.20)) <= 1e-12);
    /* outside the span: the interface's sharp decision (d_crit(1 m/s) = 30 um) */
    const double outside[][2] = { { 4.9e-6, 1.0 }, { 1e-6, 3.0 }, { 8.1e-5, 1.0 }, { 2e-4, 0.6 },
                                  { 2e-5, 0.49 }, { 2e-5, 0.1 }, { 2e-5, 4.01 }, { 2e-5, 30.0 },
                                  { 1e-3, 0.0 }, { 1e-7, 50.0 }, { 1e-3, 1e-3 } };
    for (size_t k = 0; k < sizeof outside / sizeof *outside; k++) {
        const double d = outside[k][0], v = outside[k][1];
        const sww_outcome o = decide(m, d, v, 0.0, 0.0, 0.5), r = decide(sharp, d, v, 0.0, 0.0, 0.5);
        assert_true(o.p_stick == (d <= sww_dcrit(sharp, v) ? 1.0 : 0.0));
        assert_true(same_outcome(&o, &r));
    }
    /* the random number decides: u < p sticks, u >= p bounces by the criterion */
    const double d = 1.3e-5, v = 2.2, p = p_expected(d, v);
    assert_true(p > 0.3 && p < 0.7);
    assert_int_equal(decide(m, d, v, 0, 0, nextafter(p, 0.0)).fate, SWW_STICK);
    sww_outcome o = decide(m, d, v, 0, 0, p);
    assert_int_equal(o.fate, SWW_BOUNCE);
    assert_int_equal(o.reason, SWW_BY_CRITERION);
    ASSERT_REL(o.e_n, swp_cor_thornton(VY / v), 1e-14);
    assert_true(o.e_t == 1.0);
    /* the stick fraction over 20000 uniform u is p within 4 binomial sigma */
    const int n = 20000;
    long sticks = 0;
    srand48(2026);
    for (int k = 0; k < n; k++)
        sticks += decide(m, d, v, 0, 0, drand48()).fate == SWW_STICK;
    const double sigma = sqrt(n * p * (1 - p));
    if (fabs(sticks - n * p) > 4 * sigma)
        fail_msg("%ld sticks of %d, expected %.1f +- 4 x %.1f", sticks, n, n * p, sigma);
    /* the gates still act on a stick candidate of the table: d = 20 um at
     * v_n 4 m/s sticks with p 0.2 although d > d_crit(4) = 4.2 um */
    assert_true(sww_dcrit(m, 4.0) < 2e-5);
    assert_int_equal(decide(m, 2e-5, 4.0, 0.3, 0, 0.1).fate, SWW_STICK);
    assert_int_equal(sww_set_tangential_gate(m, 0.2, 5e-5, 0.0), SWW_OK);
    o = decide(m, 2e-5, 4.0, 0.3, 0, 0.1);
    assert_int_equal(o.fate, SWW_BOUNCE);
    assert_int_equal(o.reason, SWW_BY_TANGENTIAL);
    assert_true(o.p_stick == 0.2);
    sww_set_tangential_off(m);
    assert_int_equal(sww_set_shear_gate_constant(m, 1.0), SWW_OK);
    assert_int_equal(decide(m, 2e-5, 4.0, 0.0, 1.0, 0.1).fate, SWW_RIPOFF);
    assert_int_equal(decide(m, 2e-5, 4.0, 0.0, 1.0, 0.3).fate, SWW_BOUNCE);
    sww_set_shear_off(m);
    /* the log line says so; a map without the table says nothing new */
    char buf[800];
    sww_describe(m, buf, sizeof buf);
    assert_non_null(strstr(buf, "stick probability table 3 x 3 (d 5e-06..8e-05 m, v_n 0.5..4 m/s"));
    sww_describe(sharp, buf, sizeof buf);
    assert_null(strstr(buf, "probability"));
    /* from code: the same model as the file */
    sww_model *c = load_fixture();
    assert_int_equal(sww_regime_list(c, "probabilityD", PD, 3), SWW_OK);
    assert_int_equal(sww_regime_list(c, "probabilityVn", PV, 3), SWW_OK);
    assert_int_equal(sww_regime_list(c, "probabilityStick", PP, 9), SWW_OK);
    assert_false(sww_probability_table(c, NULL, NULL));  /* not before the commit */
    assert_int_equal(sww_regime_commit(c, "code"), SWW_OK);
    for (int k = 0; k < 2000; k++) {
        const double dd = exp(log(1e-6) + log(200.0) * drand48()), vv = exp(-3.0 + 6.0 * drand48());
        const double u = drand48();
        const sww_outcome a = decide(c, dd, vv, 0, 0, u), b = decide(m, dd, vv, 0, 0, u);
        assert_true(same_outcome(&a, &b));
    }
    /* a new regime without the table: back to the sharp map */
    sww_regime_clear(c);
    assert_int_equal(sww_regime_load(c, FIXTURE), SWW_OK);
    assert_false(sww_probability_table(c, NULL, NULL));
    assert_true(decide(c, 2e-5, 4.0, 0, 0, 0.1).fate == SWW_BOUNCE);
    sww_free(c);
    sww_free(m);
    sww_free(sharp);
}

/* A rough wall's table over v_t too (snowregime map --set wall=lattice
 * --vt 0,...): layers v_t = 0 (the table above), 1 m/s (half
 * of it) and 3 m/s (none sticks). Read at the impact's v_t with the regime
 * gate on (exact at the nodes, linear between layers, the last layer beyond
 * them), at v_t = 0 with the gate off; a bounce that v_t = 0 would have stuck
 * is a tangential one. */
static void probability_table_vt(void **s)
{
    (void)s;
    static const double VT[] = { 0.0, 1.0, 3.0 };
    double P3[3 * 3 * 3];
    for (size_t i = 0; i < 3; i++)
        for (size_t k = 0; k < 3; k++)
            for (size_t j = 0; j < 3; j++)
                P3[(i * 3 + k) * 3 + j] = k == 0 ? PP[i * 3 + j] : k == 1 ? 0.5 * PP[i * 3 + j] : 0.0;
    sww_model *m = load_fixture(), *flat2 = load_rough();
    assert_int_equal(sww_regime_list(m, "probabilityD", PD, 3), SWW_OK);
    assert_int_equal(sww_regime_list(m, "probabilityVn", PV, 3), SWW_OK);
    assert_int_equal(sww_regime_list(m, "probabilityVt", VT, 3), SWW_OK);
    assert_int_equal(sww_regime_list(m, "probabilityStick", P3, 27), SWW_OK);
    assert_int_equal(sww_regime_commit(m, "code"), SWW_OK);
    double vmax = 0.0;
    assert_int_equal(sww_probability_vt(m, &vmax), 3);
    assert_true(vmax == 3.0);
    assert_int_equal(sww_probability_vt(flat2, NULL), 0);
    /* gate off: the v_t = 0 layer whatever v_t, as the table without v_t */
    srand48(5);
    for (int k = 0; k < 500; k++) {
        const double d = PD[0] * pow(PD[2] / PD[0], drand48()), v = PV[0] * pow(PV[2] / PV[0], drand48());
        const double vt = 5.0 * drand48(), u = drand48();
        const sww_outcome a = decide(m, d, v, vt, 0, u), b = decide(flat2, d, v, vt, 0, u);
        assert_true(same_outcome(&a, &b));
    }
    /* regime gate on: the layers at their nodes, linear between, the last beyond */
    assert_int_equal(sww_set_tangential_regime(m), SWW_OK);
    for (size_t i = 0; i < 3; i++)
        for (size_t j = 0; j < 3; j++)
            for (size_t k = 0; k < 3; k++)
                assert_true(decide(m, PD[i], PV[j], VT[k], 0, 0.5).p_stick == P3[(i * 3 + k) * 3 + j]);
    for (int k = 0; k < 500; k++) {
        const double d = PD[0] * pow(PD[2] / PD[0], drand48()), v = PV[0] * pow(PV[2] / PV[0], drand48());
        const double vt = 4.0 * drand48(), p0 = p_expected(d, v);
        const double want = vt <= 1.0 ? p0 * (1.0 - 0.5 * vt) : vt <= 3.0 ? 0.5 * p0 * (1.0 - (vt - 1.0) / 2.0) : 0.0;
        assert_true(fabs(decide(m, d, v, vt, 0, 0.5).p_stick - want) <= 1e-12);
    }
    /* u between p(v_t) and p(0): a tangential bounce; above p(0): the criterion's */
    const double d = 1.3e-5, v = 2.2, p0 = p_expected(d, v);
    sww_outcome o = decide(m, d, v, 1.0, 0, 0.75 * p0);
    assert_int_equal(o.fate, SWW_BOUNCE);
    assert_int_equal(o.reason, SWW_BY_TANGENTIAL);
    assert_int_equal(o.by_draw, 0);
    o = decide(m, d, v, 1.0, 0, 0.25 * p0);
    assert_int_equal(o.fate, SWW_STICK);
    o = decide(m, d, v, 1.0, 0, nextafter(p0, 1.0));
    assert_int_equal(o.reason, SWW_BY_CRITERION);
    assert_int_equal(o.by_draw, 1);
    char buf[800];
    sww_describe(m, buf, sizeof buf);
    assert_non_null(strstr(buf, "stick probability table 3 x 3 x 3 (d 5e-06..8e-05 m, v_t 0..3 m/s"));
    assert_non_null(strstr(buf, "tangential gate on: the rough wall's stick probability over v_t 0..3"));
    /* a sharp regime without any v_t table refuses the regime gate */
    sww_model *sharp = load_fixture();
    assert_int_equal(sww_set_tangential_regime(sharp), SWW_EMISSING);
    assert_non_null(strstr(sww_errmsg(sharp), "probabilityVt"));
    /* bad tables: named */
    sww_model *b = load_fixture();
    static const double VT1[] = { 0.5, 1.0 }, VT2[] = { 0.0, 2.0, 1.0 };
    assert_int_equal(sww_regime_list(b, "probabilityVt", VT1, 2), SWW_EINVAL);
    assert_non_null(strstr(sww_errmsg(b), "starts at v_t = 0"));
    assert_int_equal(sww_regime_list(b, "probabilityVt", VT2, 3), SWW_EINVAL);
    assert_non_null(strstr(sww_errmsg(b), "strictly increasing"));
    assert_int_equal(sww_regime_list(b, "probabilityVt", VT, 3), SWW_OK);
    assert_int_equal(sww_regime_commit(b, "code"), SWW_EMISSING);
    assert_non_null(strstr(sww_errmsg(b), "'probabilityVt' without"));
    sww_regime_clear(b);
    assert_int_equal(sww_regime_load(b, FIXTURE), SWW_OK);
    assert_int_equal(sww_regime_list(b, "probabilityD", PD, 3), SWW_OK);
    assert_int_equal(sww_regime_list(b, "probabilityVn", PV, 3), SWW_OK);
    assert_int_equal(sww_regime_list(b, "probabilityVt", VT, 3), SWW_OK);
    assert_int_equal(sww_regime_list(b, "probabilityStick", PP, 9), SWW_OK);
    assert_int_equal(sww_regime_commit(b, "code"), SWW_EINVAL);
    assert_non_null(strstr(sww_errmsg(b), "3 x 3 x 3 = 27"));
    sww_free(b);
    sww_free(sharp);
    sww_free(m);
    sww_free(flat2);
}

/* Bilinear in (ln d, ln v_n) over any axes, by a linear scan (independent
 * of the core's direct indexing on uniform axes and its bisection). */
static double p_ref(const double *D, size_t nd, const double *V, size_t nv, const double *P,
                    double d, double v)
{
    size_t i = 0, j = 0;
    while (i + 2 < nd && d > D[i + 1])
        i++;
    while (j + 2 < nv && v > V[j + 1])
        j++;
    const double a = log(d / D[i]) / log(D[i + 1] / D[i]);
    const double b = log(v / V[j]) / log(V[j + 1] / V[j]);
    return P[i * nv + j] * (1 - a) * (1 - b) + P[i * nv + j + 1] * (1 - a) * b
         + P[(i + 1) * nv + j] * a * (1 - b) + P[(i + 1) * nv + j + 1] * a * b;
}

/* The cell search on each kind of axis: uniform in ln (snowregime's speeds),
 * uniform in the value (snowregime's diameters), irregular, and uniform in ln
 * to within the core's 1e-9 of a cell (nodes moved by +-5e-10 of a cell: the
 * direct index lands next to the right cell near a node). */
static void probability_axes(void **s)
{
    (void)s;
    enum { ND = 46, NV = 50 };
    double D[4][ND], V[4][NV], P[ND * NV];
    for (int i = 0; i < ND; i++) {
        D[0][i] = 1e-5 * pow(10.0, i / (ND - 1.0));
        D[1][i] = 1e-5 + 9e-5 * i / (ND - 1.0);
        D[2][i] = 1e-5 * pow(10.0, pow(i / (ND - 1.0), 1.7));
        D[3][i] = D[0][i] * (i > 0 && i < ND - 1 ? exp((i % 2 ? 5e-10 : -5e-10) * log(10.0) / (ND - 1)) : 1.0);
    }
    for (int j = 0; j < NV; j++) {
        V[0][j] = 0.1 * pow(100.0, j / (NV - 1.0));
        V[1][j] = 0.1 + 9.9 * j / (NV - 1.0);
        V[2][j] = 0.1 * pow(100.0, pow(j / (NV - 1.0), 0.6));
        V[3][j] = V[0][j] * (j > 0 && j < NV - 1 ? exp((j % 2 ? -5e-10 : 5e-10) * log(100.0) / (NV - 1)) : 1.0);
    }
    for (int i = 0; i < ND; i++)   /* steep in both directions: 0, 0.5, 1 */
        for (int j = 0; j < NV; j++)
            P[i * NV + j] = ((i + 2 * j) % 3) / 2.0;
    srand48(5);
    for (int a = 0; a < 4; a++)
        for (int b = 0; b < 4; b++) {
            sww_model *m = load_fixture();
            assert_int_equal(sww_regime_list(m, "probabilityD", D[a], ND), SWW_OK);
            assert_int_equal(sww_regime_list(m, "probabilityVn", V[b], NV), SWW_OK);
            assert_int_equal(sww_regime_list(m, "probabilityStick", P, ND * NV), SWW_OK);
            assert_int_equal(sww_regime_commit(m, "code"), SWW_OK);
            for (int i = 0; i < ND; i++)
                for (int j = 0; j < NV; j += 7)
                    assert_true(decide(m, D[a][i], V[b][j], 0, 0, 0.5).p_stick == P[i * NV + j]);
            for (int k = 0; k < 5000; k++) {
                /* random points, and points next to a node (rounding) */
                double d = D[a][0] * pow(D[a][ND - 1] / D[a][0], drand48());
                double v = V[b][0] * pow(V[b][NV - 1] / V[b][0], drand48());
                if (k % 2) {
                    const double e = 1e-11 * (k % 4 == 1 ? -1.0 : 1.0);
                    d = D[a][(k / 2) % ND] * (1.0 + e);
                    v = V[b][(k / 3) % NV] * (1.0 - e);
                    if (d < D[a][0] || d > D[a][ND - 1] || v < V[b][0] || v > V[b][NV - 1])
                        continue;
                }
                const double p = decide(m, d, v, 0, 0, 0.5).p_stick;
                if (!(fabs(p - p_ref(D[a], ND, V[b], NV, P, d, v)) <= 1e-12))
                    fail_msg("axes %d/%d: d %.17g v %.17g: p %.17g, expected %.17g", a, b, d, v,
                             p, p_ref(D[a], ND, V[b], NV, P, d, v));
            }
            sww_free(m);
        }
}

/* The blend with probabilities: the bare wall is rough (table), the covered
 * regime the sharp fixture; p = (1 - w) p_bare + w p_covered. */
static void blend_probabilities(void **s)
{
    (void)s;
    sww_model *bare = load_rough(), *cov = load_fixture();
    assert_int_equal(sww_regime_number(cov, "reboundNormal", 0.3), SWW_OK);
    assert_int_equal(sww_regime_commit(cov, "covered"), SWW_OK);
    const double d = 1.3e-5, v = 2.2, pb = decide(bare, d, v, 0, 0, 0).p_stick;
    assert_true(fabs(pb - p_expected(d, v)) <= 1e-12 && pb > 0.3 && pb < 0.7);
    assert_true(d > sww_dcrit(cov, v));   /* the covered wall bounces it: p_covered 0 */
    sww_impact in = { .d = d, .vn = v, .u = 0.0 };
    sww_outcome o;
    for (double w = 0.0; w <= 1.0; w += 0.125) {
        const double p = (1.0 - w) * pb;
        long n = 0, want = 0;
        for (int k = 0; k < 1000; k++) {
            in.u = (k + 0.5) / 1000.0;
            assert_int_equal(sww_decide_blend(bare, cov, w, &in, &o), SWW_OK);
            assert_true(fabs(o.p_stick - p) <= 1e-15);
            n += o.fate == SWW_STICK;
            want += in.u < p;
            if (o.fate != SWW_STICK && w > 0.0)
                ASSERT_REL(o.e_n, 0.3, 1e-15);    /* the covered regime's bounce */
        }
        assert_int_equal(n, want);
    }
    /* both regimes between 0 and 1: the covered one a second rough wall with a
     * constant rebound; a particle that does not stick bounces by the
     * criterion with the rebound of the regime less likely to stick */
    sww_model *cov2 = load_rough();
    assert_int_equal(sww_regime_number(cov2, "reboundNormal", 0.3), SWW_OK);
    const double Pc[] = { 1, 1, 1, 1, 1, 1, 1, 1, 1 };
    assert_int_equal(sww_regime_list(cov2, "probabilityStick", Pc, 9), SWW_OK);
    assert_int_equal(sww_regime_commit(cov2, "covered 2"), SWW_OK);
    const double w = 0.25, p = (1.0 - w) * pb + w * 1.0;
    in.u = nextafter(p, 0.0);
    assert_int_equal(sww_decide_blend(bare, cov2, w, &in, &o), SWW_OK);
    assert_int_equal(o.fate, SWW_STICK);
    assert_true(fabs(o.p_stick - p) <= 1e-15);
    in.u = p;
    assert_int_equal(sww_decide_blend(bare, cov2, w, &in, &o), SWW_OK);
    assert_int_equal(o.fate, SWW_BOUNCE);
    assert_int_equal(o.reason, SWW_BY_CRITERION);
    ASSERT_REL(o.e_n, swp_cor_thornton(VY / v), 1e-14);  /* the bare, rough wall's */
    /* swapped: the bare wall sticks surely, the covered one with pb */
    assert_int_equal(sww_decide_blend(cov2, bare, 0.75, &in, &o), SWW_OK);
    assert_int_equal(o.fate, SWW_BOUNCE);
    ASSERT_REL(o.e_n, swp_cor_thornton(VY / v), 1e-14);
    /* a gate that stops the covered regime's stick gives it p = 0 */
    assert_int_equal(sww_set_tangential_gate(cov2, 0.1, 5e-5, 0.0), SWW_OK);
    in.vt = 0.5;
    in.u = 0.0;
    assert_int_equal(sww_decide_blend(bare, cov2, w, &in, &o), SWW_OK);
    assert_true(fabs(o.p_stick - 0.75 * pb) <= 1e-15);
    in.u = 0.75 * pb;
    assert_int_equal(sww_decide_blend(bare, cov2, w, &in, &o), SWW_OK);
    assert_int_equal(o.fate, SWW_BOUNCE);
    assert_int_equal(o.reason, SWW_BY_TANGENTIAL);        /* the covered regime's gate */
    ASSERT_REL(o.e_n, 0.3, 1e-15);
    sww_free(cov2);
    sww_free(bare);
    sww_free(cov);
}

static void detach_physics(void **s)
{
    (void)s;
    const double G = 0.2, Es = 1.88e9, R = 25e-6;
    ASSERT_REL(swp_tau_detach(G, Es, R, 0.05, 1.0), tau_indep(G, Es, R, 0.05, 1.0), 1e-12);
    /* smooth JKR: order 10 Pa for 50 um (doc/physics-brief.md section 8): ~33.7 Pa, rolling */
    const double t50 = swp_tau_detach(G, Es, R, 0.05, 1.0);
    assert_true(t50 > 10.0 && t50 < 100.0);
    assert_true(swp_tau_roll(G, Es, R, 1.0) < swp_tau_slide(G, R, 0.05, 1.0));
    ASSERT_REL(t50, 33.7, 0.01);
    /* at the threshold the moments balance */
    ASSERT_REL(swp_shear_moment(t50, R),
               swp_jkr_pulloff_force(G, R) * swp_jkr_a0(G, Es, R), 1e-12);
    /* a tiny friction coefficient makes sliding the weaker mode */
    ASSERT_REL(swp_tau_detach(G, Es, R, 1e-3, 1.0), swp_tau_slide(G, R, 1e-3, 1.0), 1e-12);
    ASSERT_REL(swp_shear_drag(swp_tau_slide(G, R, 1e-3, 1.0), R),
               1e-3 * swp_jkr_pulloff_force(G, R), 1e-12);
    /* roughness scales linearly; smaller particles resist larger stresses (~R^-4/3) */
    ASSERT_REL(swp_tau_detach(G, Es, R, 0.05, 0.1), 0.1 * t50, 1e-12);
    ASSERT_REL(swp_tau_roll(G, Es, R / 8.0, 1.0), swp_tau_roll(G, Es, R, 1.0) * 16.0, 1e-12);
    /* mu <= 0: sliding ignored */
    ASSERT_REL(swp_tau_detach(G, Es, R, 0.0, 1.0), swp_tau_roll(G, Es, R, 1.0), 1e-15);
}

static void shear_gate(void **s)
{
    (void)s;
    sww_model *m = load_fixture();
    const double d = 2e-5, v = 1.0; /* stick candidate */
    /* off: tau_w is not even read (NaN accepted) */
    assert_true(isinf(sww_tau_crit(m, d)));
    assert_int_equal(decide(m, d, v, 0.0, NAN, 0.5).fate, SWW_STICK);
    assert_int_equal(sww_set_shear_gate_constant(m, 1.5), SWW_OK);
    assert_int_equal(decide(m, d, v, 0.0, 1.49, 0.5).fate, SWW_STICK);
    sww_outcome o = decide(m, d, v, 0.5, 1.5, 0.5);
    assert_int_equal(o.fate, SWW_RIPOFF);
    assert_int_equal(o.reason, SWW_BY_SHEAR);
    ASSERT_REL(o.e_n, swp_cor_thornton(VY / v), 1e-14);
    /* a bounce is a bounce whatever the shear */
    assert_int_equal(decide(m, 1e-4, v, 0.0, 1e6, 0.5).fate, SWW_BOUNCE);
    /* shear on: a bad tau_w is an input error */
    sww_impact in = { .d = d, .vn = v, .tau_w = NAN, .u = 0.5 };
    assert_int_equal(sww_decide(m, &in, &o), SWW_EINVAL);
    in.tau_w = -1.0;
    assert_int_equal(sww_decide(m, &in, &o), SWW_EINVAL);
    /* ... at every impact, not only at a stick candidate: a bounce
     * (d above d_crit) with a bad tau_w is refused too */
    sww_impact big = { .d = 1e-4, .vn = v, .tau_w = NAN, .u = 0.5 };
    assert_int_equal(sww_decide(m, &big, &o), SWW_EINVAL);
    big.tau_w = INFINITY;
    assert_int_equal(sww_decide(m, &big, &o), SWW_EINVAL);
    /* adhesion: tau_c(d) from the regime's gamma, Estar, mu */
    assert_int_equal(sww_set_shear_gate_adhesion(m, 0.1), SWW_OK);
    const double tc = tau_indep(0.2, 1.88e9, d / 2, 0.05, 0.1);
    ASSERT_REL(sww_tau_crit(m, d), tc, 1e-12);
    assert_int_equal(decide(m, d, v, 0.0, tc * 0.999, 0.5).fate, SWW_STICK);
    assert_int_equal(decide(m, d, v, 0.0, tc * 1.001, 0.5).fate, SWW_RIPOFF);
    /* no number for a diameter that is not one, and a stick candidate
     * whose tau_c is not a number is an input error, not a gate that never fires */
    const double bad_d[] = { 0.0, -1.0, INFINITY, -INFINITY, NAN };
    for (size_t k = 0; k < 5; k++) {
        assert_true(isnan(sww_tau_crit(m, bad_d[k])));
        assert_true(isnan(sww_vt_max(m, bad_d[k])));
    }
    in.d = 1e-300;
    in.vn = v;
    in.tau_w = 1.0;
    if (isnan(sww_tau_crit(m, in.d)))
        assert_int_equal(sww_decide(m, &in, &o), SWW_EINVAL);
    /* tangential gate is checked first: a bounce, not a rip-off */
    assert_int_equal(sww_set_tangential_gate(m, 0.1, 5e-5, 0.0), SWW_OK);
    assert_int_equal(decide(m, d, v, 0.2, tc * 2, 0.5).fate, SWW_BOUNCE);
    sww_set_shear_off(m);
    assert_false(sww_shear_on(m));
    assert_int_equal(sww_set_shear_gate_adhesion(m, 0.0), SWW_EINVAL);
    assert_non_null(strstr(sww_errmsg(m), "roughnessFactor 0"));
    /* the message is the last call's: a call that succeeds leaves none */
    assert_int_equal(sww_set_rebound_tangential(m, 0.5), SWW_OK);
    assert_string_equal(sww_errmsg(m), "");
    assert_int_equal(sww_set_shear_gate_adhesion(m, 0.0), SWW_EINVAL);
    assert_int_equal(sww_set_shear_gate_constant(m, -1.0), SWW_EINVAL);
    assert_non_null(strstr(sww_errmsg(m), "tauCrit -1"));
    sww_free(m);

    /* adhesion without gamma in the map */
    m = sww_alloc();
    const double c[] = { -10.0, -1.0 };
    sww_regime_word(m, "representation", "polynomial");
    sww_regime_list(m, "coeffs", c, 2);
    sww_regime_number(m, "vnMin", 0.1);
    sww_regime_number(m, "vnMax", 1.0);
    sww_regime_number(m, "slopeLow", -1.0);
    sww_regime_number(m, "slopeHigh", -1.0);
    assert_int_equal(sww_regime_commit(m, "code"), SWW_OK);
    assert_int_equal(sww_set_shear_gate_adhesion(m, 1.0), SWW_EMISSING);
    assert_non_null(strstr(sww_errmsg(m), "'gamma'"));
    sww_free(m);
}

/* The caller's random number: any u in [0,1) gives the sharp map's answer. */
static void probability_hook_and_bad_impacts(void **s)
{
    (void)s;
    sww_model *m = load_fixture();
    const double dc = sww_dcrit(m, 2.0);
    for (double u = 0.0; u < 1.0; u += 0.0625) {
        assert_int_equal(decide(m, dc * 0.99, 2.0, 0, 0, u).fate, SWW_STICK);
        assert_int_equal(decide(m, dc * 1.01, 2.0, 0, 0, u).fate, SWW_BOUNCE);
    }
    const sww_impact bad[] = {
        { .d = 0.0, .vn = 1.0 }, { .d = -1e-5, .vn = 1.0 }, { .d = NAN, .vn = 1.0 },
        { .d = INFINITY, .vn = 1.0 }, { .d = 1e-5, .vn = -1.0 }, { .d = 1e-5, .vn = NAN },
        { .d = 1e-5, .vn = 1.0, .vt = -1.0 }, { .d = 1e-5, .vn = 1.0, .vt = NAN },
        { .d = 1e-5, .vn = 1.0, .u = 1.0 }, { .d = 1e-5, .vn = 1.0, .u = -0.1 },
        { .d = 1e-5, .vn = 1.0, .u = NAN }, { .d = 1e-5, .vn = INFINITY },
    };
    for (size_t i = 0; i < sizeof bad / sizeof *bad; i++) {
        sww_outcome o;
        assert_int_equal(sww_decide(m, &bad[i], &o), SWW_EINVAL);
    }
    sww_free(m);
    sww_model *e = sww_alloc();
    sww_outcome o;
    sww_impact ok = { .d = 1e-5, .vn = 1.0, .u = 0.5 };
    assert_int_equal(sww_decide(e, &ok, &o), SWW_ENOTREADY);
    assert_true(isnan(sww_dcrit(e, 1.0)));
    sww_free(e);
}

/* Setting the numbers from code gives the same model as the file. */
static void code_equals_file(void **s)
{
    (void)s;
    sww_model *f = load_fixture(), *c = sww_alloc();
    const double co[] = { C0, C1, C2, C3 };
    sww_regime_word(c, "representation", "polynomial");
    sww_regime_list(c, "coeffs", co, 4);
    sww_regime_number(c, "vnMin", VNMIN);
    sww_regime_number(c, "vnMax", VNMAX);
    sww_regime_number(c, "slopeLow", SLO);
    sww_regime_number(c, "slopeHigh", SHI);
    sww_regime_number(c, "yieldVelocity", VY);
    assert_int_equal(sww_regime_commit(c, "code"), SWW_OK);
    for (double v = 1e-3; v < 1e3; v *= 1.9)
        ASSERT_REL(sww_dcrit(c, v), sww_dcrit(f, v), 1e-13);
    assert_true(sww_rebound_normal(c, 2.0) == sww_rebound_normal(f, 2.0));
    sww_free(f);
    sww_free(c);
}

/* Many threads deciding with one model give the serial answers. */
typedef struct { const sww_model *m; int offset; long mismatches; } job;
static int serial_fate[4096];

static void *worker(void *arg)
{
    job *j = arg;
    for (int rep = 0; rep < 50; rep++)
        for (int i = 0; i < 4096; i++) {
            const int k = (i + j->offset) % 4096;
            sww_impact in = { .d = 1e-6 * (1 + k % 97), .vn = 0.01 * (1 + k / 8), .vt = 0.001 * k,
                              .tau_w = 0.1 * (k % 13), .u = (k % 10) / 10.0 };
            sww_outcome o;
            if (sww_decide(j->m, &in, &o) != SWW_OK || (int)o.fate != serial_fate[k])
                j->mismatches++;
        }
    return NULL;
}

static void threads_agree(sww_model *m);

static void thread_safe(void **s)
{
    (void)s;
    threads_agree(load_fixture());
    threads_agree(load_rough());
}

static void threads_agree(sww_model *m)
{
    assert_int_equal(sww_set_tangential_gate(m, 2.0, 5e-5, -0.3), SWW_OK);
    assert_int_equal(sww_set_shear_gate_adhesion(m, 0.01), SWW_OK);
    int counts[3] = { 0, 0, 0 };
    for (int k = 0; k < 4096; k++) {
        sww_impact in = { .d = 1e-6 * (1 + k % 97), .vn = 0.01 * (1 + k / 8), .vt = 0.001 * k,
                          .tau_w = 0.1 * (k % 13), .u = (k % 10) / 10.0 };
        sww_outcome o;
        assert_int_equal(sww_decide(m, &in, &o), SWW_OK);
        serial_fate[k] = o.fate;
        counts[o.fate]++;
    }
    assert_true(counts[0] > 0 && counts[1] > 0 && counts[2] > 0); /* all three fates occur */
    pthread_t t[4];
    job jobs[4];
    for (int i = 0; i < 4; i++) {
        jobs[i] = (job){ m, i * 1000, 0 };
        assert_int_equal(pthread_create(&t[i], NULL, worker, &jobs[i]), 0);
    }
    for (int i = 0; i < 4; i++) {
        pthread_join(t[i], NULL);
        assert_int_equal(jobs[i].mismatches, 0);
    }
    sww_free(m);
}

/* ------------------------------------------------------------- loader errors */

static const char *GOOD =
    "regime\n{\n"
    "    representation polynomial;\n"
    "    basis log;\n"
    "    degree 1;\n"
    "    coeffs (-10.0 -1.0);\n"
    "    vnMin 0.2;\n"
    "    vnMax 6.0;\n"
    "    slopeLow -1.2;\n"
    "    slopeHigh -1.4;\n"
    "}\n";

/* Replace the first line containing `what` (a key) with `with` ("" deletes it). */
static char *edit(const char *base, const char *what, const char *with)
{
    static char out[4096];
    const char *p = strstr(base, what);
    assert_non_null(p);
    const char *ls = p;
    while (ls > base && ls[-1] != '\n')
        ls--;
    const char *le = strchr(p, '\n');
    snprintf(out, sizeof out, "%.*s%s%s", (int)(ls - base), base, with, le);
    return out;
}

static int load_text(const char *text, char *path, sww_model **mp)
{
    static int n;
    snprintf(path, 256, "%s/case%d.coeffs", tmpdir, n++);
    FILE *f = fopen(path, "w");
    assert_non_null(f);
    fputs(text, f);
    fclose(f);
    *mp = sww_alloc();
    return sww_regime_load(*mp, path);
}

typedef struct {
    const char *key, *with;   /* edit of GOOD (key NULL: `with` is the whole text) */
    int rc;
    const char *msg1, *msg2;  /* must appear in the message (besides the path) */
} bad_case;

static void loader_errors(void **s)
{
    (void)s;
    const bad_case cases[] = {
        { "representation", "", SWW_EMISSING, "missing key 'representation'", NULL },
        { "coeffs", "", SWW_EMISSING, "missing key 'coeffs'", NULL },
        { "vnMin", "", SWW_EMISSING, "missing key 'vnMin'", NULL },
        { "vnMax", "", SWW_EMISSING, "missing key 'vnMax'", NULL },
        { "slopeLow", "", SWW_EMISSING, "missing key 'slopeLow'", NULL },
        { "slopeHigh", "", SWW_EMISSING, "missing key 'slopeHigh'", NULL },
        { "vnMin", "vnMin nan;", SWW_EINVAL, "key 'vnMin'", "not a finite number" },
        { "vnMax", "vnMax inf;", SWW_EINVAL, "key 'vnMax'", "not a finite number" },
        { "coeffs", "coeffs (-10 nan);", SWW_EINVAL, "key 'coeffs'", "entry 1" },
        { "coeffs", "coeffs (-10 abc);", SWW_EINVAL, "key 'coeffs'", "'abc'" },
        { "vnMin", "vnMin 0.2x;", SWW_EINVAL, "key 'vnMin'", "'0.2x' is not a number" },
        /* the other representation's keys: refused, not dropped */
        { "vnMax", "vnMax 6.0; vn (0.2 6); dCrit (1e-5 2e-5);", SWW_EINVAL, "key 'vn'",
          "not used with representation polynomial" },
        /* hexadecimal: strtod would take it, OpenFOAM's reader does not: refused */
        { "vnMax", "vnMax 0x6;", SWW_EINVAL, "key 'vnMax'", "'0x6' is not a number" },
        { "coeffs", "coeffs (0x1p3 -1.3 -0.02 -0.005);", SWW_EINVAL, "key 'coeffs'", "'0x1p3' (entry 0) is not a number" },
        { "vnMin", "vnMin 7;", SWW_EINVAL, "key 'vnMin'", "7 is not below vnMax 6" },
        { "vnMin", "vnMin 6;", SWW_EINVAL, "key 'vnMin'", "6 is not below vnMax 6" },
        { "vnMin", "vnMin -1;", SWW_EINVAL, "key 'vnMin'", "-1 must be > 0" },
        { "degree", "degree 3;", SWW_EINVAL, "key 'degree'", "value 3 does not match the 2" },
        { "coeffs", "coeffs (-10.0 1.0);", SWW_EINVAL, "key 'coeffs'", "increases" },
        { "slopeLow", "slopeLow 0.5;", SWW_EINVAL, "key 'slopeLow'", "0.5" },
        { "slopeHigh", "slopeHigh 2;", SWW_EINVAL, "key 'slopeHigh'", "value 2" },
        { "representation", "representation spline;", SWW_EINVAL, "key 'representation'", "'spline'" },
        { "basis", "basis log10;", SWW_EINVAL, "key 'basis'", "'log10'" },
        { "vnMax", "vnMax (1 2);", SWW_EINVAL, "key 'vnMax'", "expects one number" },
        { "coeffs", "coeffs -10;", SWW_EINVAL, "key 'coeffs'", "expects a list" },
        { "vnMax", "vnMax 6.0", SWW_EPARSE, "key 'vnMax'", "expected ';'" },
        { "vnMax", "vnMax 6.0; vnMax 7;", SWW_EPARSE, "key 'vnMax' appears twice", NULL },
        { "vnMax", "vnMax 6.0; /* open", SWW_EPARSE, "unterminated /* comment", NULL },
        { "vnMax", "vnMax \"6.0;", SWW_EPARSE, "unterminated string", NULL },
        { "vnMax", "#include \"x\"", SWW_EPARSE, "'#include'", NULL },
        { "vnMax", "vnMax 6.0; yieldVelocity -1;", SWW_EINVAL, "key 'yieldVelocity'", "-1" },
        { "vnMax", "vnMax 6.0; reboundNormal 1.2;", SWW_EINVAL, "key 'reboundNormal'", "1.2" },
        { "vnMax", "vnMax 6.0; gamma 0;", SWW_EINVAL, "key 'gamma'", "0 must be > 0" },
        { "vnMax", "vnMax 6.0; version 2;", SWW_EINVAL, "key 'version'", "2" },
        /* unknown keys are errors naming file, line and key: a misspelt
         * yieldVelocity would otherwise leave every bounce elastic */
        { "vnMax", "vnMax 6.0;\n yieldVelocty 1.4e-4;", SWW_EINVAL, "key 'yieldVelocty' is not a regime key", ":" },
        { "vnMax", "vnMax 6.0; futureList (1 2);", SWW_EINVAL, "key 'futureList' is not a regime key", NULL },
        { "vnMax", "vnMax 6.0; colour blue;", SWW_EINVAL, "key 'colour' is not a regime key", NULL },
        { "vnMax", "vnMax 6.0; extra { a 1; }", SWW_EINVAL, "key 'extra': a sub-dictionary is not a regime key", NULL },
        { "vnMax", "vnMax 6.0; dMin 1e-4; dMax 1e-5;", SWW_EINVAL, "keys 'dMin', 'dMax'", "must be below" },
        /* a consistency error of the commit names the lines that set the keys */
        { "vnMax", "vnMax 6.0;\n dMin 1e-4;\n dMax 1e-5;", SWW_EINVAL, "must be below 1e-05 (dMin line ",
          ", dMax line " },
        { NULL, "other { a 1; }\n", SWW_EMISSING, "missing sub-dictionary 'regime", NULL },
        { NULL, "regime { vnMin 1; ", SWW_EPARSE, "'regime'", "not closed" },
        { NULL, "regime { vnMin 1; } }", SWW_EPARSE, "found '}'", NULL },
        { NULL, "", SWW_EMISSING, "missing sub-dictionary", NULL },
        /* table representation */
        { NULL, "regime { representation table; vn (0.1 1 10); vnMin 0.2; vnMax 6; slopeLow -1; "
                "slopeHigh -1; }", SWW_EMISSING, "missing key 'dCrit'", NULL },
        { NULL, "regime { representation table; dCrit (1e-4 1e-5 1e-6); vnMin 0.2; vnMax 6; "
                "slopeLow -1; slopeHigh -1; }", SWW_EMISSING, "missing key 'vn'", NULL },
        { NULL, "regime { representation table; vn (0.1 1 1); dCrit (1e-4 1e-5 1e-6); vnMin 0.2; "
                "vnMax 6; slopeLow -1; slopeHigh -1; }", SWW_EINVAL, "key 'vn'", "strictly increasing" },
        { NULL, "regime { representation table; vn (0.1 1 10); dCrit (1e-4 0 1e-6); vnMin 0.2; "
                "vnMax 6; slopeLow -1; slopeHigh -1; }", SWW_EINVAL, "key 'dCrit'", "value 0" },
        { NULL, "regime { representation table; vn (0.1 1 10); dCrit (1e-4 1e-5); vnMin 0.2; "
                "vnMax 6; slopeLow -1; slopeHigh -1; }", SWW_EINVAL, "key 'dCrit'", "2 values" },
        { NULL, "regime { representation table; vn (0.1 1 10); dCrit (1e-4 1e-5 2e-5); vnMin 0.2; "
                "vnMax 6; slopeLow -1; slopeHigh -1; }", SWW_EINVAL, "key 'dCrit'", "increases" },
        { NULL, "regime { representation table; vn (0.3 1 10); dCrit (1e-4 1e-5 1e-6); vnMin 0.2; "
                "vnMax 6; slopeLow -1; slopeHigh -1; }", SWW_EINVAL, "key 'vn'", "does not cover" },
        { NULL, "regime { representation polynomial; basis linear; coeffs (1e-5 -1e-5); "
                "vnMin 0.2; vnMax 6; slopeLow -1; slopeHigh -1; }", SWW_EINVAL, "key 'coeffs'",
                "not a finite positive diameter" },
        /* the stick-probability table (rough wall) */
        { "vnMax", "vnMax 6.0; probabilityVn (0.1 10); probabilityStick (0.3 0.3 0.3 0.3);",
          SWW_EMISSING, "missing 'probabilityD'", NULL },
        { "vnMax", "vnMax 6.0; probabilityD (1e-6 1e-4); probabilityStick (0.3 0.3 0.3 0.3);",
          SWW_EMISSING, "missing 'probabilityVn'", NULL },
        { "vnMax", "vnMax 6.0; probabilityD (1e-6 1e-4); probabilityVn (0.1 10);",
          SWW_EMISSING, "missing 'probabilityStick'", NULL },
        { "vnMax", "vnMax 6.0; probabilityD (1e-6 1e-4); probabilityVn (0.1 1 10); "
          "probabilityStick (0.3 0.3 0.3 0.3 0.3);", SWW_EINVAL, "key 'probabilityStick'",
          "5 values, but probabilityD x probabilityVn = 2 x 3 = 6" },
        { "vnMax", "vnMax 6.0; probabilityD (1e-6 1e-4); probabilityVn (0.1 10); "
          "probabilityStick (0.3 1.5 0.3 0.3);", SWW_EINVAL, "key 'probabilityStick'",
          "value 1.5 (entry 1) is not a probability in [0, 1]" },
        { "vnMax", "vnMax 6.0; probabilityD (1e-6 1e-4); probabilityVn (0.1 10); "
          "probabilityStick (0.3 0.3 -0.01 0.3);", SWW_EINVAL, "key 'probabilityStick'",
          "value -0.01 (entry 2)" },
        { "vnMax", "vnMax 6.0; probabilityD (1e-6 1e-4); probabilityVn (0.1 10); "
          "probabilityStick (0.3 0.3 0.3 nan);", SWW_EINVAL, "key 'probabilityStick'",
          "value nan (entry 3) is not a finite number" },
        { "vnMax", "vnMax 6.0; probabilityD (1e-6 1e-4 1e-4); probabilityVn (0.1 10); "
          "probabilityStick (0.3 0.3 0.3 0.3 0.3 0.3);", SWW_EINVAL, "key 'probabilityD'",
          "value 0.0001 (entry 2) is not larger than 0.0001" },
        { "vnMax", "vnMax 6.0; probabilityD (1e-6 1e-4); probabilityVn (10 0.1); "
          "probabilityStick (0.3 0.3 0.3 0.3);", SWW_EINVAL, "key 'probabilityVn'",
          "value 0.1 (entry 1) is not larger than 10" },
        { "vnMax", "vnMax 6.0; probabilityD (0 1e-4); probabilityVn (0.1 10); "
          "probabilityStick (0.3 0.3 0.3 0.3);", SWW_EINVAL, "key 'probabilityD'",
          "value 0 (entry 0) must be > 0" },
        { "vnMax", "vnMax 6.0; probabilityD (1e-6 1e-4); probabilityVn (0.1 inf); "
          "probabilityStick (0.3 0.3 0.3 0.3);", SWW_EINVAL, "key 'probabilityVn'",
          "value inf (entry 1) is not a finite number" },
        { "vnMax", "vnMax 6.0; probabilityD (1e-6 1e-4); probabilityVn (0.1); "
          "probabilityStick (0.3 0.3);", SWW_EINVAL, "key 'probabilityVn'", "1 values, expected 2" },
        { "vnMax", "vnMax 6.0; probabilityD (1e-6 1e-4); probabilityVn (0.1 10); "
          "probabilityStick 0.3;", SWW_EINVAL, "key 'probabilityStick'", "expects a list" },
        { "vnMax", "vnMax 6.0; probabilityD (1e-6 1e-4); probabilityVn (0.1 10); "
          "probabilityStick (0.3 0.3 0.3 0.3); probabilityPoints 0;", SWW_EINVAL,
          "key 'probabilityPoints'", "value 0 is not a whole number >= 1" },
        { "vnMax", "vnMax 6.0; probabilityPoints 2.5;", SWW_EINVAL, "key 'probabilityPoints'",
          "value 2.5" },
        { "vnMax", "vnMax 6.0; probabilityPoints (64);", SWW_EINVAL, "key 'probabilityPoints'",
          "expects one number" },
    };
    char path[256];
    for (size_t i = 0; i < sizeof cases / sizeof *cases; i++) {
        const bad_case *c = &cases[i];
        sww_model *m;
        const int rc = load_text(c->key ? edit(GOOD, c->key, c->with) : c->with, path, &m);
        const char *msg = sww_errmsg(m);
        if (rc != c->rc || !strstr(msg, path) || !strstr(msg, c->msg1)
            || (c->msg2 && !strstr(msg, c->msg2)) || strchr(msg, '\n'))
            fail_msg("case %zu: rc %d (want %d), message: %s", i, rc, c->rc, msg);
        assert_false(sww_ready(m));
        sww_free(m);
    }
    /* a table of more than 4096 values per list: the file and from code */
    static char big[60000];
    static double many[SWW_TEST_MAX + 1];
    size_t len = (size_t)snprintf(big, sizeof big, "regime { representation polynomial; coeffs "
                                  "(-10 -1); vnMin 0.2; vnMax 6; slopeLow -1; slopeHigh -1;\n"
                                  "probabilityD (1e-6 1e-4); probabilityVn (");
    for (int i = 0; i <= SWW_TEST_MAX; i++) {
        many[i] = 0.1 + 1e-3 * i;
        len += (size_t)snprintf(big + len, sizeof big - len, "%.6g ", many[i]);
    }
    snprintf(big + len, sizeof big - len, ");\nprobabilityStick (0.3 0.3 0.3 0.3); }\n");
    sww_model *m;
    assert_int_equal(load_text(big, path, &m), SWW_EPARSE);
    assert_non_null(strstr(sww_errmsg(m), "key 'probabilityVn': more than 4096 values"));
    assert_non_null(strstr(sww_errmsg(m), path));
    assert_int_equal(sww_regime_list(m, "probabilityVn", many, SWW_TEST_MAX + 1), SWW_EINVAL);
    assert_non_null(strstr(sww_errmsg(m), "key 'probabilityVn': 4097 values, expected 2 to 4096"));
    assert_int_equal(sww_regime_list(m, "probabilityVn", many, SWW_TEST_MAX), SWW_OK);
    sww_free(m);
    /* the good text loads, with a line number in a later parse error */
    assert_int_equal(load_text(GOOD, path, &m), SWW_OK);
    sww_free(m);
    assert_int_equal(load_text(edit(GOOD, "vnMax", "vnMax 6.0 ;;"), path, &m), SWW_EPARSE);
    assert_non_null(strstr(sww_errmsg(m), ":8:"));
    sww_free(m);
    m = sww_alloc();
    assert_int_equal(sww_regime_load(m, "/nonexistent/regime.coeffs"), SWW_EIO);
    assert_non_null(strstr(sww_errmsg(m), "/nonexistent/regime.coeffs: cannot open"));
    /* not a regular file: refused at once (a FIFO would wait for a writer) */
    char fifo[] = "/tmp/sww-fifo-XXXXXX";
    const int fd = mkstemp(fifo);
    assert_true(fd >= 0);
    close(fd);
    unlink(fifo);
    assert_int_equal(mkfifo(fifo, 0600), 0);
    assert_int_equal(sww_regime_load(m, fifo), SWW_EIO);
    assert_non_null(strstr(sww_errmsg(m), "not a regular file"));
    unlink(fifo);
    assert_int_equal(sww_regime_load(m, "/tmp"), SWW_EIO);
    assert_non_null(strstr(sww_errmsg(m), "/tmp: not a regular file"));
    sww_free(m);
}


/* the counter-based draw: fixed by its key, uniform, uncorrelated */
static void uniform_hash(void **s)
{
    (void)s;
    assert_true(sww_uniform_hash(1234567, 0, 17, 40, 0) == sww_uniform_hash(1234567, 0, 17, 40, 0));
    assert_true(sww_uniform_hash(1234567, 0, 17, 40, 0) != sww_uniform_hash(1234568, 0, 17, 40, 0));
    assert_true(sww_uniform_hash(1, 0, 17, 40, 0) != sww_uniform_hash(1, 0, 17, 40, 1));
    assert_true(sww_uniform_hash(1, 0, 17, 40, 0) != sww_uniform_hash(1, 1, 17, 40, 0));
    /* 2e5 keys as a run walks them (parcel ids, steps, counts): in [0, 1), mean and
     * 16-bin chi-square within their 4-sigma / 0.1 % bounds, neighbours uncorrelated */
    const int n = 200000, nb = 16;
    long bins[16] = { 0 };
    double sum = 0.0, sxy = 0.0, prev = 0.5;
    for (int i = 0; i < n; i++) {
        const double u = sww_uniform_hash(1234567, i % 3, i / 3 % 1000, i / 3000, i % 2);
        assert_true(u >= 0.0 && u < 1.0);
        sum += u;
        sxy += (u - 0.5) * (prev - 0.5);
        prev = u;
        bins[(int)(u * nb)]++;
    }
    assert_true(fabs(sum / n - 0.5) <= 4.0 * sqrt(1.0 / 12.0 / n));
    double chi2 = 0.0;
    for (int b = 0; b < nb; b++)
        chi2 += (bins[b] - n / (double)nb) * (bins[b] - n / (double)nb) / (n / (double)nb);
    assert_true(chi2 < 37.7);                       /* 15 degrees of freedom, p = 0.001 */
    assert_true(fabs(sxy / n) <= 4.0 / 12.0 / sqrt((double)n));   /* lag-1 covariance */
    /* extreme keys: still in [0, 1) */
    assert_true(sww_uniform_hash(~0ULL, -1, -1, -1, -1) < 1.0);
    assert_true(sww_uniform_hash(0, 0, 0, 0, 0) >= 0.0);
}

/* ------------------------------------------------------------- counts by reason */

static void outcome_classes(void **s)
{
    (void)s;
    sww_model *m = load_fixture(), *r = load_rough();
    /* sharp map: stuck / criterion, never the draw, whatever u */
    for (double u = 0.0; u < 1.0; u += 0.249) {
        sww_outcome o = decide(m, 1e-5, 1.0, 0.0, 0.0, u);
        assert_int_equal(sww_outcome_class(&o), SWW_CLASS_STUCK);
        assert_false(o.by_draw);
        o = decide(m, 5e-5, 1.0, 0.0, 0.0, u);
        assert_int_equal(sww_outcome_class(&o), SWW_CLASS_CRITERION);
        assert_false(o.by_draw);
    }
    /* the gates */
    assert_int_equal(sww_set_tangential_gate(m, 0.5, 5e-5, 0.0), SWW_OK);
    sww_outcome o = decide(m, 1e-5, 1.0, 2.0, 0.0, 0.5);
    assert_int_equal(sww_outcome_class(&o), SWW_CLASS_TANGENTIAL);
    sww_set_tangential_off(m);
    assert_int_equal(sww_set_shear_gate_constant(m, 0.5), SWW_OK);
    o = decide(m, 1e-5, 1.0, 0.0, 1.0, 0.5);
    assert_int_equal(sww_outcome_class(&o), SWW_CLASS_SHEAR);
    /* a rough wall's table: u >= p > 0 is the draw; p = 0 the criterion */
    const double d = 1.3e-5, v = 2.2, p = p_expected(d, v);
    o = decide(r, d, v, 0, 0, p);
    assert_true(o.by_draw && o.fate == SWW_BOUNCE && o.reason == SWW_BY_CRITERION);
    assert_int_equal(sww_outcome_class(&o), SWW_CLASS_PROBABILITY);
    o = decide(r, d, v, 0, 0, nextafter(p, 0.0));
    assert_int_equal(sww_outcome_class(&o), SWW_CLASS_STUCK);
    o = decide(r, 8e-5, 4.0, 0, 0, 0.0);                  /* p = 0 at that node */
    assert_int_equal(sww_outcome_class(&o), SWW_CLASS_CRITERION);
    /* a stick candidate by the draw that a gate stops counts for the gate */
    assert_int_equal(sww_set_tangential_gate(r, 0.5, 5e-5, 0.0), SWW_OK);
    o = decide(r, d, v, 2.0, 0, 0.0);
    assert_int_equal(sww_outcome_class(&o), SWW_CLASS_TANGENTIAL);
    sww_set_tangential_off(r);
    /* the blend: p in (0, 1) decided by u */
    sww_impact in = { .d = 5e-5, .vn = 1.0, .vt = 0.0, .tau_w = 0.0, .u = 0.6 };
    sww_set_shear_off(m);
    assert_int_equal(sww_decide_blend(m, r, 0.5, &in, &o), SWW_OK);
    if (o.fate != SWW_STICK)
        assert_int_equal(sww_outcome_class(&o), o.p_stick > 0 ? SWW_CLASS_PROBABILITY
                                                               : SWW_CLASS_CRITERION);
    in.u = 0.0;
    assert_int_equal(sww_decide_blend(m, r, 0.5, &in, &o), SWW_OK);
    assert_int_equal(sww_outcome_class(&o), o.p_stick > 0 ? SWW_CLASS_STUCK : SWW_CLASS_CRITERION);
    for (int c = 0; c < SWW_NCLASS; c++)
        assert_string_not_equal(sww_class_name((sww_class)c), "?");
    assert_string_equal(sww_class_name(SWW_CLASS_PROBABILITY), "probability");
    sww_free(m);
    sww_free(r);
}

/* ------------------------------------------------------------- rebound tables */

/* The kernel's rebound as tables: d 20, 80 um (rows), v_n 0.5, 4 m/s (columns),
 * with v_t layers 0, 1, 4 m/s for the 3-D case. */
static const double RD[] = { 2e-5, 8e-5 }, RV[] = { 0.5, 4.0 };   /* v_t layers 0, 1, 4 m/s */
static const double REN[] = { 0.10, 0.05, 0.20, 0.08,    /* v_t 0 */
                              0.09, 0.04, 0.18, 0.07,    /* v_t 1 */
                              0.05, 0.02, 0.10, 0.04 };  /* v_t 4 */
static const double RET[] = { 0.70, 0.80, 0.60, 0.75,    /* v_t 0: not used */
                              0.60, 0.70, 0.50, 0.65,
                              0.80, 0.90, 0.85, 0.95 };

static const char *RTABLE2 =
    "    reboundD   (2e-5 8e-5);\n"
    "    reboundVn  (0.5 4);\n"
    "    reboundEn  (0.10 0.05 0.20 0.08);\n";
static const char *RTABLE3 =
    "    reboundD   (2e-5 8e-5);\n"
    "    reboundVn  (0.5 4);\n"
    "    reboundVt  (0 1 4);\n"
    "    reboundEn  (0.10 0.05 0.20 0.08 0.09 0.04 0.18 0.07 0.05 0.02 0.10 0.04);\n"
    "    reboundEt  (0.70 0.80 0.60 0.75 0.60 0.70 0.50 0.65 0.80 0.90 0.85 0.95);\n";

/* The fixture with `extra` inside regime { }: the load's return code. */
static int load_fixture_with(const char *extra, sww_model **mp, char *path)
{
    FILE *f = fopen(FIXTURE, "r");
    assert_non_null(f);
    static char text[8192];
    const size_t n = fread(text, 1, sizeof text - 1, f);
    fclose(f);
    text[n] = '\0';
    char *close = strrchr(text, '}');
    assert_non_null(close);
    static char out[16384];
    snprintf(out, sizeof out, "%.*s%s}\n", (int)(close - text), text, extra);
    return load_text(out, path, mp);
}

/* bilinear in (ln d, ln v_n) on layer k, written out: clamped to the nodes */
static double rb_expected(const double *T, int k, double d, double v)
{
    double a = log(d / RD[0]) / log(RD[1] / RD[0]), b = log(v / RV[0]) / log(RV[1] / RV[0]);
    a = a < 0 ? 0 : (a > 1 ? 1 : a);
    b = b < 0 ? 0 : (b > 1 ? 1 : b);
    const double *L = T + 4 * k;
    return L[0] * (1 - a) * (1 - b) + L[1] * (1 - a) * b + L[2] * a * (1 - b) + L[3] * a * b;
}

static void rebound_tables(void **s)
{
    (void)s;
    char path[256];
    sww_model *m, *old = load_fixture();
    assert_int_equal(load_fixture_with(RTABLE2, &m, path), SWW_OK);
    size_t nd = 9, nv = 9, nt = 9;
    assert_true(sww_rebound_table(m, &nd, &nv, &nt) && nd == 2 && nv == 2 && nt == 1);
    assert_true(sww_rebound_uses_table(m));
    /* an old file: no table, the classic rebound exactly as before */
    assert_false(sww_rebound_table(old, &nd, &nv, &nt));
    assert_true(nd == 0 && nv == 0 && nt == 0);
    assert_false(sww_rebound_uses_table(old));
    double en, et;
    for (double v = 0.05; v < 30; v *= 1.7) {
        sww_rebound(old, 5e-5, v, 1.0, &en, &et);
        assert_true(en == sww_rebound_normal(old, v) && et == 1.0);
        const sww_outcome o = decide(old, 5e-5, v, 1.0, 0, 0.5);
        if (o.fate == SWW_BOUNCE)
            assert_true(o.e_n == sww_rebound_normal(old, v) && o.e_t == 1.0);
    }
    char buf[512];
    sww_describe(old, buf, sizeof buf);
    assert_non_null(strstr(buf, "e_n Thornton(V_y 0.000144 m/s), e_t 1;"));
    sww_describe(m, buf, sizeof buf);
    assert_non_null(strstr(buf, "e_n kernel table 2 x 2 (d 2e-05..8e-05 m, v_n 0.5..4 m/s), e_t 1;"));
    /* the nodes exactly, bilinear in (ln d, ln v_n) between them, clamped in d, below v_n */
    for (int i = 0; i < 2; i++)
        for (int j = 0; j < 2; j++) {
            sww_rebound(m, RD[i], RV[j], 0.0, &en, &et);
            assert_true(en == REN[2 * i + j] && et == 1.0);
        }
    const double ds[] = { 1e-7, 2e-5, 3.3e-5, 5e-5, 7.9e-5, 8e-5, 1e-3 };
    const double vs[] = { 0.0, 1e-320, 0.1, 0.5, 0.77, 2.0, 3.99, 4.0 };
    for (size_t i = 0; i < sizeof ds / sizeof *ds; i++)
        for (size_t j = 0; j < sizeof vs / sizeof *vs; j++) {
            sww_rebound(m, ds[i], vs[j], 0.3, &en, &et);
            assert_true(fabs(en - rb_expected(REN, 0, ds[i], vs[j] > 0 ? vs[j] : 1e-300)) <= 1e-12);
        }
    /* above the last v_n node: Thornton's e_p carries it on (the fixture has yieldVelocity) */
    for (double v = 4.5; v < 1e4; v *= 3.1) {
        sww_rebound(m, 5e-5, v, 0.0, &en, &et);
        const double ref = rb_expected(REN, 0, 5e-5, 4.0) * swp_cor_thornton(VY / v)
                         / swp_cor_thornton(VY / 4.0);
        ASSERT_REL(en, ref, 1e-12);
    }
    /* sww_decide's bounce and rip-off leave with these factors */
    const sww_outcome ob = decide(m, 5e-5, 2.0, 0.7, 0, 0.5);
    assert_int_equal(ob.fate, SWW_BOUNCE);
    sww_rebound(m, 5e-5, 2.0, 0.7, &en, &et);
    assert_true(ob.e_n == en && ob.e_t == et && fabs(en - rb_expected(REN, 0, 5e-5, 2.0)) <= 1e-12);
    assert_int_equal(sww_set_shear_gate_constant(m, 0.5), SWW_OK);
    const sww_outcome orip = decide(m, 5e-6, 1.0, 0.0, 1.0, 0.5);
    assert_int_equal(orip.fate, SWW_RIPOFF);
    assert_true(fabs(orip.e_n - rb_expected(REN, 0, 5e-6, 1.0)) <= 1e-12);
    sww_set_shear_off(m);
    /* reboundTangential stays the e_t of a table without reboundEt */
    assert_int_equal(sww_set_rebound_tangential(m, 0.4), SWW_OK);
    sww_rebound(m, 5e-5, 2.0, 0.7, &en, &et);
    assert_true(et == 0.4);
    /* the classic rebound as an option; the table required where there is none */
    assert_int_equal(sww_set_rebound_model(m, SWW_REBOUND_CLASSIC), SWW_OK);
    sww_rebound(m, 5e-5, 2.0, 0.7, &en, &et);
    assert_true(en == sww_rebound_normal(m, 2.0) && et == 0.4);
    assert_false(sww_rebound_uses_table(m));
    assert_int_equal(sww_set_rebound_model(m, SWW_REBOUND_TABLE), SWW_OK);
    assert_true(sww_rebound_uses_table(m));
    assert_int_equal(sww_set_rebound_model(old, SWW_REBOUND_TABLE), SWW_EMISSING);
    assert_non_null(strstr(sww_errmsg(old), "no rebound table"));
    assert_int_equal(sww_set_rebound_model(old, 7), SWW_EINVAL);
    /* a model set to `table` refuses a regime without the table at its commit */
    assert_int_equal(sww_regime_load(m, FIXTURE), SWW_EMISSING);
    assert_non_null(strstr(sww_errmsg(m), "rebound 'table' needs the kernel's rebound table"));
    sww_free(m);

    /* 3-D: layers by v_t */
    assert_int_equal(load_fixture_with(RTABLE3, &m, path), SWW_OK);
    assert_true(sww_rebound_table(m, &nd, &nv, &nt) && nd == 2 && nv == 2 && nt == 3);
    sww_describe(m, buf, sizeof buf);
    assert_non_null(strstr(buf, "e_n, e_t kernel table 3 x 2 x 2 (v_t 0..4 m/s"));
    assert_null(strstr(buf, "e_t 1;"));
    const double d = 3.3e-5, v = 1.3;
    sww_rebound(m, d, v, 0.0, &en, &et);
    assert_true(fabs(en - rb_expected(REN, 0, d, v)) <= 1e-12);
    assert_true(fabs(et - rb_expected(RET, 1, d, v)) <= 1e-12);  /* v_t = 0: layer 1 (no use) */
    sww_rebound(m, d, v, 0.25, &en, &et);                         /* linear in v_t below node 1 */
    assert_true(fabs(en - (0.75 * rb_expected(REN, 0, d, v) + 0.25 * rb_expected(REN, 1, d, v))) <= 1e-12);
    assert_true(fabs(et - rb_expected(RET, 1, d, v)) <= 1e-12);
    sww_rebound(m, d, v, 2.0, &en, &et);                          /* linear in ln v_t: w = 1/2 */
    assert_true(fabs(en - 0.5 * (rb_expected(REN, 1, d, v) + rb_expected(REN, 2, d, v))) <= 1e-12);
    assert_true(fabs(et - 0.5 * (rb_expected(RET, 1, d, v) + rb_expected(RET, 2, d, v))) <= 1e-12);
    sww_rebound(m, d, v, 40.0, &en, &et);                         /* clamped beyond the last */
    assert_true(fabs(en - rb_expected(REN, 2, d, v)) <= 1e-12);
    assert_true(fabs(et - rb_expected(RET, 2, d, v)) <= 1e-12);
    /* never NaN, always in [0, 1]; NaN only for bad input */
    srand48(23);
    for (int k = 0; k < 20000; k++) {
        const double dd = exp(-700.0 + 1400.0 * drand48()), vv = k % 7 ? exp(-745.0 + 1450.0 * drand48()) : 0.0;
        const double tt = k % 5 ? exp(-745.0 + 1450.0 * drand48()) : 0.0;
        sww_rebound(m, dd, vv, tt, &en, &et);
        assert_true(en >= 0.0 && en <= 1.0 && et >= 0.0 && et <= 1.0);
    }
    sww_rebound(m, NAN, 1.0, 0.0, &en, &et);
    assert_true(isnan(en) && isnan(et));
    sww_rebound(m, 1e-5, -1.0, 0.0, &en, &et);
    assert_true(isnan(en));
    sww_rebound(m, 1e-5, 1.0, INFINITY, &en, &et);
    assert_true(isnan(en));
    sww_free(m);
    sww_free(old);

    /* malformed tables: a named error, the model not ready */
    static const struct { const char *text; int rc; const char *msg; } bad[] = {
        { "    reboundD (2e-5 8e-5);\n    reboundVn (0.5 4);\n", SWW_EMISSING, "missing 'reboundEn'" },
        { "    reboundVn (0.5 4);\n    reboundEn (0.1 0.1 0.1 0.1);\n", SWW_EMISSING, "missing 'reboundD'" },
        { "    reboundD (2e-5 8e-5);\n    reboundVn (0.5 4);\n    reboundEn (0.1 0.1 0.1);\n",
          SWW_EINVAL, "key 'reboundEn': 3 values, but (no reboundVt) 1 x reboundD x reboundVn = 1 x 2 x 2 = 4" },
        { "    reboundD (2e-5 8e-5);\n    reboundVn (0.5 4);\n    reboundEn (0.1 0.1 1.3 0.1);\n",
          SWW_EINVAL, "key 'reboundEn': value 1.3 (entry 2) is not a rebound factor in [0, 1]" },
        { "    reboundD (8e-5 2e-5);\n    reboundVn (0.5 4);\n    reboundEn (0.1 0.1 0.1 0.1);\n",
          SWW_EINVAL, "key 'reboundD': value 2e-05 (entry 1) is not larger than 8e-05" },
        { "    reboundD (2e-5 8e-5);\n    reboundVn (0 4);\n    reboundEn (0.1 0.1 0.1 0.1);\n",
          SWW_EINVAL, "key 'reboundVn': value 0 (entry 0) must be > 0" },
        { "    reboundD (2e-5 8e-5);\n    reboundVn (0.5 4);\n    reboundEn (0.1 0.1 0.1 0.1);\n"
          "    reboundEt (0.1 0.1 0.1 0.1);\n", SWW_EMISSING, "key 'reboundEt' needs 'reboundVt'" },
        { "    reboundD (2e-5 8e-5);\n    reboundVn (0.5 4);\n    reboundVt (0 1);\n"
          "    reboundEn (0.1 0.1 0.1 0.1 0.1 0.1 0.1 0.1);\n", SWW_EMISSING, "missing 'reboundEt'" },
        { "    reboundD (2e-5 8e-5);\n    reboundVn (0.5 4);\n    reboundVt (0.5 1);\n", SWW_EINVAL,
          "key 'reboundVt': the first value is 0.5, it must be 0" },
        { "    reboundD (2e-5 8e-5);\n    reboundVn (0.5 4);\n    reboundVt (0 1);\n"
          "    reboundEn (0.1 0.1 0.1 0.1 0.1 0.1 0.1 0.1);\n    reboundEt (0.1 0.1 0.1 0.1);\n",
          SWW_EINVAL, "key 'reboundEt': 4 values, but reboundVt x reboundD x reboundVn = 2 x 2 x 2 = 8" },
        { "    reboundD (2e-5 8e-5);\n    reboundVn (0.5 4);\n    reboundEn (0.1 0.1 nan 0.1);\n",
          SWW_EINVAL, "key 'reboundEn'" },
        { "    reboundEn 0.1;\n", SWW_EINVAL, "key 'reboundEn': expects a list" },
        { "    reboundEx (0.1 0.2);\n", SWW_EINVAL, "key 'reboundEx' is not a regime key" },
    };
    for (size_t k = 0; k < sizeof bad / sizeof *bad; k++) {
        const int rc = load_fixture_with(bad[k].text, &m, path);
        if (rc != bad[k].rc || !strstr(sww_errmsg(m), bad[k].msg) || !strstr(sww_errmsg(m), path))
            fprintf(stderr, "case %zu: rc %d: %s\n", k, rc, sww_errmsg(m));
        assert_int_equal(rc, bad[k].rc);
        assert_non_null(strstr(sww_errmsg(m), bad[k].msg));
        assert_non_null(strstr(sww_errmsg(m), path));
        assert_null(strchr(sww_errmsg(m), '\n'));
        assert_false(sww_ready(m));
        sww_free(m);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(fixture_loads),
        cmocka_unit_test(criterion_stick_bounce),
        cmocka_unit_test(range_handling),
        cmocka_unit_test(table_and_linear_from_code),
        cmocka_unit_test(tangential_gate),
        cmocka_unit_test(oblique_gate),
        cmocka_unit_test(buildup_blend),
        cmocka_unit_test(probability_table),
        cmocka_unit_test(probability_table_vt),
        cmocka_unit_test(probability_axes),
        cmocka_unit_test(blend_probabilities),
        cmocka_unit_test(detach_physics),
        cmocka_unit_test(shear_gate),
        cmocka_unit_test(probability_hook_and_bad_impacts),
        cmocka_unit_test(code_equals_file),
        cmocka_unit_test(thread_safe),
        cmocka_unit_test(loader_errors),
        cmocka_unit_test(rebound_tables),
        cmocka_unit_test(outcome_classes),
        cmocka_unit_test(uniform_hash),
    };
    return cmocka_run_group_tests_name("wallmodel", tests, setup, teardown);
}
