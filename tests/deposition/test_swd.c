/* test_swd.c - the near-wall dispersion model (wallmodel/core/swd.h), its
 * wall-layer formulas (regime/physics/swp_nearwall.h) and the 1-D channel
 * (tools/snowdeposit/swc_channel.h). */
#include <math.h>
#include <stdint.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include <cmocka.h>

#include "swc_channel.h"
#include "swd.h"
#include "swp_nearwall.h"

#define ASSERT_REL(x, ref, tol) assert_true(fabs((x) - (ref)) <= (tol) * fabs(ref))

/* The formulas against numbers worked out by hand from the published fits,
 * and the near-wall limits u' ~ y, v' ~ y^2. */
static void wall_layer_values(void **s)
{
    (void)s;
    /* v'+ = 0.005 y^2 / (1 + 0.002923 y^2.128) */
    ASSERT_REL(swp_vrms_plus(10.0), 0.5 / (1.0 + 0.002923 * pow(10.0, 2.128)), 1e-14);
    ASSERT_REL(swp_vrms_plus(1e-3) / 1e-6, 0.005, 1e-4);
    ASSERT_REL(swp_urms_plus(1e-3) / 1e-3, 0.4, 1e-4);
    ASSERT_REL(swp_wrms_plus(1e-3) / 1e-3, 0.19, 1e-3);
    /* peak of u' near y+ 15 at about 2.5-2.8 (channel DNS) */
    double umax = 0, ymax = 0;
    for (double y = 1; y < 100; y += 0.25)
        if (swp_urms_plus(y) > umax) {
            umax = swp_urms_plus(y);
            ymax = y;
        }
    assert_true(ymax > 10 && ymax < 25 && umax > 2.3 && umax < 2.9);
    /* T_L+: 10 in the sublayer, continuous at y+ = 5 within 0.05, held past 200 */
    assert_true(swp_tl_plus(2.0) == 10.0);
    assert_true(fabs(swp_tl_plus(5.0) - 10.0) < 0.05);
    assert_true(swp_tl_plus(300.0) == swp_tl_plus(200.0));
    /* Reichardt: u+ = y+ in the sublayer, the log law far out */
    ASSERT_REL(swp_uplus(0.1), 0.1, 2e-3);
    ASSERT_REL(swp_uplus(1000.0), log(1000.0) / 0.41 + 5.0, 0.03);
    /* derivatives against central differences */
    for (double y = 0.5; y < 300; y *= 1.7) {
        const double h = 1e-5 * y;
        ASSERT_REL(swp_dvrms_plus(y), (swp_vrms_plus(y + h) - swp_vrms_plus(y - h)) / (2 * h), 1e-6);
        ASSERT_REL(swp_duplus(y), (swp_uplus(y + h) - swp_uplus(y - h)) / (2 * h), 1e-6);
    }
    /* bad input: NaN, never a number */
    assert_true(isnan(swp_vrms_plus(-1.0)) && isnan(swp_tl_plus(NAN)) && isnan(swp_uplus(INFINITY)));
}

static void relaxation_and_law(void **s)
{
    (void)s;
    /* Stokes: 920 kg/m3, 10 um, air mu 1.8e-5: 2.84e-4 s */
    ASSERT_REL(swp_tau_p(920, 1e-5, 1.8e-5, 0), 920 * 1e-10 / (18 * 1.8e-5), 1e-14);
    ASSERT_REL(swp_tau_p(920, 1e-5, 1.8e-5, 1.0), 920 * 1e-10 / (18 * 1.8e-5) / 1.15, 1e-12);
    const double tp = swp_tau_plus(920, 1e-5, 1.8e-5, 1.5e-5, 0.7);
    ASSERT_REL(swp_d_of_tau_plus(tp, 920, 1.8e-5, 1.5e-5, 0.7), 1e-5, 1e-12);
    ASSERT_REL(swp_wood_vplus(1.0, 0), 4.5e-4, 1e-14);
    assert_true(swp_wood_vplus(100.0, 0) == 0.13);
    ASSERT_REL(swp_wood_vplus(0.0, 1e6), 0.057e-4, 1e-12);
    /* Brownian diffusivity of a 1 um sphere in air at 293 K: about 2.7e-11 m2/s */
    const double D = swp_brownian_diffusivity(1e-6, 293.15, 1.81e-5, 0.066e-6);
    assert_true(D > 2.5e-11 && D < 2.9e-11);
    assert_true(isnan(swp_tau_p(-1, 1e-5, 1.8e-5, 0)) && isnan(swp_wood_vplus(NAN, 0)));
}

static void settings(void **s)
{
    (void)s;
    swd_model *m = swd_alloc();
    assert_non_null(m);
    assert_true(swd_ready(m));
    assert_int_equal(swd_set(m, "layerYPlus", 80), SWD_OK);
    assert_false(swd_ready(m));
    assert_int_equal(swd_commit(m), SWD_OK);
    /* unknown key, NaN, out of range: refused, named, model unchanged */
    assert_int_equal(swd_set(m, "layerYplus", 50), SWD_EINVAL);
    assert_non_null(strstr(swd_errmsg(m), "layerYplus"));
    assert_int_equal(swd_set(m, "CT", NAN), SWD_EINVAL);
    assert_non_null(strstr(swd_errmsg(m), "CT"));
    assert_int_equal(swd_set(m, "CT", 0.0), SWD_EINVAL);
    assert_true(swd_get(m, "CT") == 0.3 && swd_get(m, "layerYPlus") == 80);
    /* blend below the layer: refused at commit */
    assert_int_equal(swd_set(m, "blendYPlus", 60), SWD_OK);
    assert_int_equal(swd_commit(m), SWD_EINVAL);
    assert_non_null(strstr(swd_errmsg(m), "blendYPlus"));
    assert_false(swd_ready(m));
    swd_local at = { .y = 1e-4, .u_tau = 0.5, .nu = 1.5e-5, .k = 0.1, .eps = 1.0 };
    double w[3] = { 0, 0, 0 }, xi[3] = { 0, 0, 0 };
    assert_int_equal(swd_advance(m, &at, 1e-4, 1e-4, w, xi, NULL, NULL), SWD_ENOTREADY);
    assert_int_equal(swd_set(m, "blendYPlus", 120), SWD_OK);
    assert_int_equal(swd_commit(m), SWD_OK);
    for (size_t k = 0; swd_key(k); k++)
        assert_false(isnan(swd_get(m, swd_key(k))));
    swd_free(m);
}

/* The statistics: the wall layer in wall units, the bulk from k, the blend,
 * and no NaN anywhere on an extreme grid. */
static void statistics(void **s)
{
    (void)s;
    swd_model *m = swd_alloc();
    const double nu = 1.5e-5, ut = 0.5;
    swd_stats st;
    swd_local at = { .y = 10 * nu / ut, .u_tau = ut, .nu = nu };   /* y+ = 10, no k */
    assert_int_equal(swd_stats_at(m, &at, &st), SWD_OK);
    ASSERT_REL(st.yplus, 10.0, 1e-12);
    ASSERT_REL(st.sigma[1], ut * swp_vrms_plus(10.0), 1e-12);
    ASSERT_REL(st.tl, swp_tl_plus(10.0) * nu / (ut * ut), 1e-12);
    ASSERT_REL(st.dsigma[1], swp_dvrms_plus(10.0) * ut * ut / nu, 1e-12);
    assert_true(st.dsigma[0] == 0.0 && st.dsigma[2] == 0.0);   /* u_tau's layer: only y varies */
    assert_true(st.layer == 1.0);
    /* bulk: isotropic sqrt(2k/3), T_L = 0.3 k/eps */
    at.y = 1.0;
    at.k = 0.6;
    at.eps = 2.0;
    assert_int_equal(swd_stats_at(m, &at, &st), SWD_OK);
    for (int i = 0; i < 3; i++)
        ASSERT_REL(st.sigma[i], sqrt(0.4), 1e-12);
    ASSERT_REL(st.tl, 0.3 * 0.6 / 2.0, 1e-12);
    assert_true(st.layer == 0.0 && st.dsigma[1] == 0.0);   /* k uniform: no drift */
    /* no wall */
    at.y = -1;
    assert_int_equal(swd_stats_at(m, &at, &st), SWD_OK);
    assert_true(st.yplus == -1.0 && st.layer == 0.0);
    /* the k-based velocity scale where the wall shear vanishes */
    at.y = 1e-4;
    at.u_tau = 0.0;
    at.k = 0.25;
    assert_int_equal(swd_stats_at(m, &at, &st), SWD_OK);
    ASSERT_REL(st.ustar, pow(0.09, 0.25) * 0.5, 1e-12);
    /* the scale alone: u_tau, or Cmu^(1/4) k^(1/2), whichever is smaller */
    at.u_tau = 0.3;
    assert_int_equal(swd_set_scale(m, SWD_USTAR_SHEAR), SWD_OK);
    assert_int_equal(swd_stats_at(m, &at, &st), SWD_ENOTREADY);
    assert_int_equal(swd_commit(m), SWD_OK);
    assert_int_equal(swd_stats_at(m, &at, &st), SWD_OK);
    ASSERT_REL(st.ustar, 0.3, 1e-12);
    ASSERT_REL(st.yplus, 1e-4 * 0.3 / nu, 1e-12);
    assert_int_equal(swd_set_scale(m, SWD_USTAR_TURBULENCE), SWD_OK);
    assert_int_equal(swd_commit(m), SWD_OK);
    at.u_tau = 2.0;
    assert_int_equal(swd_stats_at(m, &at, &st), SWD_OK);
    ASSERT_REL(st.ustar, pow(0.09, 0.25) * 0.5, 1e-12);
    /* no k and the turbulence scale: no wall layer, no NaN */
    at.k = 0.0;
    assert_int_equal(swd_stats_at(m, &at, &st), SWD_OK);
    assert_true(st.ustar == 0.0 && st.layer == 0.0 && st.sigma[1] == 0.0);
    /* names both ways, another value refused and the model unchanged */
    assert_int_equal(swd_scale_of("wallShear"), SWD_USTAR_SHEAR);
    assert_int_equal(swd_scale_of("turbulence"), SWD_USTAR_TURBULENCE);
    assert_int_equal(swd_scale_of("max"), SWD_USTAR_MAX);
    assert_int_equal(swd_scale_of("Max"), -1);
    assert_int_equal(swd_scale_of(NULL), -1);
    assert_string_equal(swd_scale_name(3), "wallCell");
    assert_null(swd_scale_name(4));
    assert_int_equal(swd_set_scale(m, -1), SWD_EINVAL);
    assert_non_null(strstr(swd_errmsg(m), "-1"));
    assert_int_equal(swd_get_scale(m), SWD_USTAR_TURBULENCE);
    char buf[400];
    swd_describe(m, buf, sizeof buf);
    assert_non_null(strstr(buf, "(not u_tau)"));
    assert_int_equal(swd_set_scale(m, SWD_USTAR_MAX), SWD_OK);
    assert_int_equal(swd_commit(m), SWD_OK);
    swd_describe(m, buf, sizeof buf);
    assert_non_null(strstr(buf, "max(u_tau, 0.09^(1/4)"));
    /* the blend is continuous at both ends */
    at.u_tau = ut;
    at.k = 3.33 * ut * ut;
    at.eps = ut * ut * ut / (0.41 * 125 * nu / ut);
    double prev = -1;
    for (double yp = 99.0; yp <= 151.0; yp += 0.5) {
        at.y = yp * nu / ut;
        assert_int_equal(swd_stats_at(m, &at, &st), SWD_OK);
        if (prev > 0)
            assert_true(fabs(st.sigma[1] - prev) < 0.02 * prev);
        prev = st.sigma[1];
    }
    /* bad input */
    at.nu = 0;
    assert_int_equal(swd_stats_at(m, &at, &st), SWD_EINVAL);
    at.nu = nu;
    at.y = NAN;
    assert_int_equal(swd_stats_at(m, &at, &st), SWD_EINVAL);
    /* an extreme grid: every input finite gives finite outputs */
    const double ys[] = { 0, 1e-300, 1e-9, 1e-3, 1.0, 1e6 };
    const double uts[] = { 0, 1e-300, 1e-20, 1e-3, 1.0, 1e3 };
    const double ks[] = { 0, 1e-300, 1e-6, 1.0, 1e6 };
    for (size_t a = 0; a < 6; a++)
        for (size_t b = 0; b < 6; b++)
            for (size_t c = 0; c < 5; c++)
                for (size_t e = 0; e < 5; e++) {
                    swd_local x = { .y = ys[a], .u_tau = uts[b], .nu = 1e-5, .k = ks[c], .eps = ks[e] };
                    double w[3] = { 1, -2, 3 }, xi[3] = { 0.5, -0.5, 1.0 }, kick[3];
                    assert_int_equal(swd_advance(m, &x, 1e-4, 1e-5, w, xi, kick, &st), SWD_OK);
                    for (int i = 0; i < 3; i++)
                        assert_true(isfinite(w[i]) && isfinite(kick[i]) && isfinite(st.sigma[i]));
                }
    swd_free(m);
}

/* The hosts' wall frame: en into the fluid, es along the wall's part of the
 * flow, ez = es x en, orthonormal; a flow normal to the wall or none still
 * gives a frame; the contact speed is u* u+(d/2 in wall units). */
static void wall_frame(void **s)
{
    (void)s;
    const double n[3] = { 0, 0, -1 }, u[3] = { 3, 4, 7 };
    double es[3], en[3], ez[3];
    swd_wall_frame(n, u, es, en, ez);
    assert_true(en[0] == 0 && en[1] == 0 && en[2] == 1);
    ASSERT_REL(es[0], 0.6, 1e-15);
    ASSERT_REL(es[1], 0.8, 1e-15);
    assert_true(es[2] == 0);
    /* ez = es x en = (0.8, -0.6, 0) */
    ASSERT_REL(ez[0], 0.8, 1e-15);
    ASSERT_REL(ez[1], -0.6, 1e-15);
    const double normal[3] = { 0, 0, 5 }, none[3] = { 0, 0, 0 };
    for (int c = 0; c < 2; c++) {
        swd_wall_frame(n, c ? none : normal, es, en, ez);
        double ss = 0, sn = 0, zz = 0;
        for (int k = 0; k < 3; k++) {
            ss += es[k] * es[k];
            sn += es[k] * en[k];
            zz += ez[k] * ez[k];
        }
        ASSERT_REL(ss, 1.0, 1e-15);
        ASSERT_REL(zz, 1.0, 1e-15);
        assert_true(fabs(sn) < 1e-15);
    }
    swd_stats st;
    st.ustar = 0.5;
    ASSERT_REL(swd_contact_speed(&st, 1.5e-5, 2e-5), 0.5 * swp_uplus(0.5 * 2e-5 * 0.5 / 1.5e-5), 1e-15);
}

/* One step against its closed form: w <- a w + sqrt(1 - a^2) xi (+ drift) and
 * the kick sigma w (1 - exp(-dt/tau_p)) with the new w. */
static void one_step(void **s)
{
    (void)s;
    swd_model *m = swd_alloc();
    const double nu = 1.5e-5, ut = 0.5, dt = 2e-5, tp = 1e-4;
    swd_local at = { .y = 8 * nu / ut, .u_tau = ut, .nu = nu };
    swd_stats st;
    swd_stats_at(m, &at, &st);
    double w[3] = { 0.3, -0.7, 1.1 }, w0[3] = { 0.3, -0.7, 1.1 }, xi[3] = { 0.2, 0.4, -0.6 }, kick[3];
    assert_int_equal(swd_advance(m, &at, dt, tp, w, xi, kick, NULL), SWD_OK);
    const double a = exp(-dt / st.tl);
    for (int i = 0; i < 3; i++) {
        const double want = a * w0[i] + sqrt(1 - a * a) * xi[i] + (1 - a) * st.tl * st.dsigma[i];
        ASSERT_REL(w[i], want, 1e-12);
        /* sigma at the coming step's midpoint (k uniform here: y alone moves) */
        swd_local mid = at;
        mid.y = at.y + 0.5 * st.sigma[1] * w[1] * dt;
        swd_stats sm;
        swd_stats_at(m, &mid, &sm);
        ASSERT_REL(kick[i], sm.sigma[i] * w[i] * (1 - exp(-dt / tp)), 1e-12);
    }
    /* a bad step leaves w alone */
    double keep[3] = { w[0], w[1], w[2] };
    assert_int_equal(swd_advance(m, &at, -1, tp, w, xi, kick, NULL), SWD_EINVAL);
    assert_int_equal(swd_advance(m, &at, dt, 0, w, xi, kick, NULL), SWD_EINVAL);
    assert_true(!memcmp(w, keep, sizeof w));
    swd_free(m);
}

/* write text into a fresh temporary file; its path in buf */
static void temp_file(char *buf, size_t n, const char *text)
{
    snprintf(buf, n, "/tmp/test_swd_XXXXXX");
    const int fd = mkstemp(buf);
    assert_true(fd >= 0);
    FILE *f = fdopen(fd, "w");
    assert_non_null(f);
    fputs(text, f);
    assert_int_equal(fclose(f), 0);
}

#define CLOSURE_HEAD "// a comment\n/* and\n another */\ndepositionClosure\n{\n    version 1; law wood;\n" \
                     "    sublayerYPlus 10;\n    layerYPlus 100; blendYPlus 150; CT 0.3; Cmu 0.09;\n"

/* A load error: SWD_EINVAL, the message holds want, the closure as it was. */
static void load_refused(swd_model *m, const char *text, const char *want)
{
    char path[64];
    temp_file(path, sizeof path, text);
    const int was = swd_closure_on(m);
    assert_int_equal(swd_load_closure(m, path), SWD_EINVAL);
    if (!strstr(swd_errmsg(m), want) || !strstr(swd_errmsg(m), path))
        fail_msg("message '%s' lacks '%s' or the path", swd_errmsg(m), want);
    assert_int_equal(swd_closure_on(m), was);
    unlink(path);
}

/* The closure's file as snowdeposit calibrate writes it, read by the core for
 * hosts without a dictionary reader; every malformed variant refused with the
 * file, line and key. */
static void closure_file(void **s)
{
    (void)s;
    swd_model *m = swd_alloc();
    char path[64];
    temp_file(path, sizeof path,
              CLOSURE_HEAD "    tauPlus ( 0.1 1 10 );\n    vPlusSublayer ( 1e-6 1e-4 0 );\n"
                           "    vPlusLaw ( 1 2 3 );\n}\n");
    assert_int_equal(swd_load_closure(m, path), SWD_OK);
    assert_false(swd_ready(m));
    assert_int_equal(swd_commit(m), SWD_OK);
    assert_true(swd_closure_on(m));
    ASSERT_REL(swd_closure_vs(m, 1.0), 1e-4, 1e-12);
    ASSERT_REL(swd_closure_vs(m, sqrt(0.1)), 1e-5, 1e-9);   /* ln-ln between positive nodes */
    unlink(path);
    load_refused(m, "depositionClosure { sublayerYPlus 10; }", "missing key 'tauPlus'");
    load_refused(m, CLOSURE_HEAD "tauPlus ( 0.1 1 ); vPlusSublayer ( 1e-6 1e-4 0 ); }",
                 "tauPlus has 2 values, vPlusSublayer 3");
    load_refused(m, CLOSURE_HEAD "tauPlus ( 0.1 nan 10 ); vPlusSublayer ( 1e-6 1e-4 0 ); }",
                 "'nan' is not a finite number");
    load_refused(m, CLOSURE_HEAD "tauPlus ( 0.1 1 10 ) vPlusSublayer ( 1e-6 1e-4 0 ); }",
                 "key 'tauPlus': no ';'");
    load_refused(m, CLOSURE_HEAD "tauPlus ( 0.1 1 10 ); vPlusSublayer ( 1e-6 1e-4 0 );",
                 "no closing '}'");
    load_refused(m, CLOSURE_HEAD "tauPlus ( 0.1 1 10 ; vPlusSublayer ( 1e-6 1e-4 0 ); }",
                 "key 'tauPlus': ';' inside the list");
    load_refused(m, "closure { }", "missing sub-dictionary 'depositionClosure");
    load_refused(m, CLOSURE_HEAD "tauPlus ( 0.1 1 1000000000000000000000000000000000000000000000000000000000000000000 ); "
                    "vPlusSublayer ( 1e-6 1e-4 0 ); }",
                 "a value longer than 63 characters");
    load_refused(m, "depositionClosure { sublayerYPlus 100000000000000000000000000000000000000000000000000000000000000001; }",
                 "a value longer than 63 characters");
    load_refused(m, CLOSURE_HEAD "tauPlus ( 1 0.1 10 ); vPlusSublayer ( 1e-6 1e-4 0 ); }",
                 "tauPlus[1]");
    /* calibrated with another walk: refused, naming the setting */
    load_refused(m, "depositionClosure { sublayerYPlus 10; layerYPlus 80; blendYPlus 150; CT 0.3; "
                    "Cmu 0.09; tauPlus ( 0.1 1 ); vPlusSublayer ( 0 0 ); }",
                 "calibrated with layerYPlus 80, the model uses 100");
    load_refused(m, "depositionClosure { sublayerYPlus 10; tauPlus ( 0.1 1 ); vPlusSublayer ( 0 0 ); }",
                 "missing key 'layerYPlus'");
    assert_int_equal(swd_load_closure(m, "/nonexistent/deposition.coeffs"), SWD_EINVAL);
    assert_non_null(strstr(swd_errmsg(m), "cannot open"));
    assert_int_equal(swd_load_closure(m, NULL), SWD_EINVAL);
    /* the shipped calibration loads */
    assert_int_equal(swd_load_closure(m, SW_SHIPPED_CLOSURE), SWD_OK);
    assert_int_equal(swd_commit(m), SWD_OK);
    assert_true(swd_closure_vs(m, 1.0) > 0);
    swd_free(m);
}

static void closure_table(void **s)
{
    (void)s;
    swd_model *m = swd_alloc();
    assert_false(swd_closure_on(m));
    const double t[] = { 0.1, 1, 10 }, v[] = { 1e-6, 1e-4, 0 };
    /* errors: unsorted, negative, NaN, too few, sublayer above the layer */
    const double bad_t[] = { 1, 0.1, 10 }, bad_v[] = { 1e-6, -1, 0 }, nan_v[] = { NAN, 0, 0 };
    assert_int_equal(swd_set_closure(m, 10, bad_t, v, 3), SWD_EINVAL);
    assert_non_null(strstr(swd_errmsg(m), "tauPlus[1]"));
    assert_int_equal(swd_set_closure(m, 10, t, bad_v, 3), SWD_EINVAL);
    assert_int_equal(swd_set_closure(m, 10, t, nan_v, 3), SWD_EINVAL);
    assert_int_equal(swd_set_closure(m, 10, t, v, 1), SWD_EINVAL);
    assert_int_equal(swd_set_closure(m, 500, t, v, 3), SWD_EINVAL);
    assert_false(swd_closure_on(m));
    assert_int_equal(swd_set_closure(m, 10, t, v, 3), SWD_OK);
    assert_int_equal(swd_commit(m), SWD_OK);
    assert_true(swd_closure_on(m));
    /* nodes, log-log between positive nodes, linear to a zero node, held outside */
    ASSERT_REL(swd_closure_vs(m, 1.0), 1e-4, 1e-12);
    ASSERT_REL(swd_closure_vs(m, sqrt(0.1)), 1e-5, 1e-9);
    ASSERT_REL(swd_closure_vs(m, sqrt(10.0)), 0.5e-4, 1e-9);
    assert_true(swd_closure_vs(m, 0.01) == 1e-6 && swd_closure_vs(m, 100) == 0.0);
    /* the rate inside the sublayer only */
    const double nu = 1.5e-5, ut = 0.5, tp = 1.0 * nu / (ut * ut);   /* tau+ = 1 */
    swd_local at = { .y = 5 * nu / ut, .u_tau = ut, .nu = nu };
    swd_stats st;
    swd_stats_at(m, &at, &st);
    ASSERT_REL(swd_deposit_rate(m, &st, nu, tp), 1e-4 * ut * ut / (10 * nu), 1e-9);
    at.y = 12 * nu / ut;
    swd_stats_at(m, &at, &st);
    assert_true(swd_deposit_rate(m, &st, nu, tp) == 0.0);
    /* layerYPlus below the sublayer: refused at commit */
    assert_int_equal(swd_set(m, "layerYPlus", 8), SWD_OK);
    assert_int_equal(swd_commit(m), SWD_EINVAL);
    swd_closure_off(m);
    assert_int_equal(swd_commit(m), SWD_OK);
    swd_free(m);
}

/* sigma_i at x = x0 + h e_j of a place whose k varies linearly (gradient g in
 * the wall frame) and whose wall distance is y0 + x_1 */

static double sigma_at(const swd_model *m, const swd_local *at0, int i, int j, double h)
{
    swd_local x = *at0;
    x.k = at0->k + h * at0->grad_k[j];
    if (j == 1)
        x.y = at0->y + h;
    swd_stats st;
    assert_int_equal(swd_stats_at(m, &x, &st), SWD_OK);
    return st.sigma[i];
}

/* The drift is the derivative of the same sigma that sets the noise: the
 * model's d sigma_i / d x_i against central differences of sigma_i, in the
 * sublayer, the buffer and log layer, the blend and the bulk, for every
 * velocity scale (where u* follows the k at the particle, its change counts). */
static void drift_is_the_gradient(void **s)
{
    (void)s;
    swd_model *m = swd_alloc();
    const double nu = 1.5e-5, ut = 0.3;
    const double yps[] = { 0.5, 3.0, 20.0, 90.0, 120.0, 140.0, 400.0 };
    for (int sc = SWD_USTAR_MAX; sc <= SWD_USTAR_WALLCELL; sc++) {
        assert_int_equal(swd_set_scale(m, sc), SWD_OK);
        assert_int_equal(swd_commit(m), SWD_OK);
        for (size_t a = 0; a < sizeof yps / sizeof *yps; a++) {
            /* k with u_k = 0.45 > u_tau (the k scale wins in max), rising
               away from the wall and varying along it */
            swd_local at = { .y = yps[a] * nu / 0.45, .u_tau = ut, .nu = nu, .k = 0.45 * 0.45 / 0.3,
                             .eps = 5.0, .grad_k = { 40.0, 300.0, -25.0 }, .k_wall = 0.5 };
            swd_stats st;
            assert_int_equal(swd_stats_at(m, &at, &st), SWD_OK);
            for (int i = 0; i < 3; i++) {
                const double h = 1e-4 * at.y;
                const double fd = (sigma_at(m, &at, i, i, h) - sigma_at(m, &at, i, i, -h)) / (2 * h);
                const double scale_ = fabs(fd) + 1e-3 * st.sigma[i] / at.y;
                if (fabs(st.dsigma[i] - fd) > 1e-5 * scale_)
                    fail_msg("scale %s y+ %g component %d: d sigma/dx %.9g, central difference %.9g",
                             swd_scale_name(sc), st.yplus, i, st.dsigma[i], fd);
            }
        }
    }
    swd_free(m);
}

static uint64_t splitmix(uint64_t *x)
{
    uint64_t z = (*x += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
}

/* 1-D tracers between a reflecting wall (y = 0) and a mirror (y = H) in
 * wall-bounded turbulence whose k rises linearly away from the wall, with u*
 * from the k at the particle (the scale where the old walk piled tracers up
 * next to the wall): the time-averaged share of the tracers in each y+ band
 * over the band's share of the height. `grad` 0 gives the walk no gradient
 * of k (the walk before the drift took u*'s change into account). */
static void tracer_shares(const swd_model *m, int grad, double ratio[4])
{
    const double H = 400.0, nu = 1.0, k0 = 0.3 / 0.3, k1 = 1.2 / 0.3;   /* u_k^2 = 0.3 k */
    const double dkdy = (k1 - k0) / H;
    const double edges[5] = { 0.0, 5.0, 30.0, 100.0, 1e300 };
    /* the band edges in y: y+ = y u*(y) / nu is monotonic */
    double ye[5] = { 0.0, 0.0, 0.0, 0.0, H };
    for (int b = 1; b < 4; b++) {
        double lo = 0, hi = H;
        for (int it = 0; it < 100; it++) {
            const double mid = 0.5 * (lo + hi);
            const double yp = mid * sqrt(0.3 * (k0 + dkdy * mid)) / nu;
            if (yp < edges[b])
                lo = mid;
            else
                hi = mid;
        }
        ye[b] = 0.5 * (lo + hi);
    }
    enum { N = 3000 };
    static double y[N], w[N][3];
    uint64_t st = 12345;
    for (int i = 0; i < N; i++) {
        y[i] = H * (i + 0.5) / N;
        for (int c = 0; c < 3; c++)
            w[i][c] = 0.0;
    }
    double occ[4] = { 0 }, tot = 0.0;
    const double t_end = 6000.0, t_warm = 1000.0;
    for (int i = 0; i < N; i++) {
        double t = 0.0;
        while (t < t_end) {
            swd_local at = { .y = y[i], .u_tau = 0.0, .nu = nu, .k = k0 + dkdy * y[i] };
            at.eps = pow(0.3 * at.k, 1.5) / (0.41 * fmax(y[i], 1.0));
            at.grad_k[1] = grad ? dkdy : 0.0;
            swd_stats s;
            swd_stats_at(m, &at, &s);
            const double dt = fmin(0.5 * s.tl, 8.0);   /* up to 2.4 t+ at the wall */
            double xi[3];
            for (int c = 0; c < 3; c++) {
                /* Box-Muller from splitmix64: deterministic, no GSL needed */
                const double u1 = (splitmix(&st) >> 11 | 1) / 9007199254740992.0;
                const double u2 = (splitmix(&st) >> 11) / 9007199254740992.0;
                xi[c] = sqrt(-2.0 * log(u1)) * cos(2.0 * M_PI * u2);
            }
            double kick[3];
            swd_advance(m, &at, dt, 1e-9, w[i], xi, kick, &s);
            if (t >= t_warm) {
                int b = 0;
                while (b < 3 && y[i] >= ye[b + 1])
                    b++;
                occ[b] += dt;
                tot += dt;
            }
            y[i] += kick[1] * dt;   /* a tracer: the fluctuation's velocity */
            if (y[i] < 0.0) {   /* the wall reflects the tracer and the fluid velocity it sees */
                y[i] = -y[i];
                w[i][1] = fabs(w[i][1]);
            }
            if (y[i] > H) {
                y[i] = 2.0 * H - y[i];
                w[i][1] = -fabs(w[i][1]);
            }
            t += dt;
        }
    }
    for (int b = 0; b < 4; b++)
        ratio[b] = (occ[b] / tot) / ((ye[b + 1] - ye[b]) / H);
}

/* Thomson's well-mixed condition in the wall layer: tracers released
 * uniformly stay uniform in every y+ band (0-5, 5-30, 30-100, beyond) within
 * 10 %, where u* changes with the particle's place; without the gradient of k
 * (the walk whose drift took u* as fixed) they pile up at the wall. */
static void well_mixed_1d(void **s)
{
    (void)s;
    swd_model *m = swd_alloc();
    assert_int_equal(swd_set_scale(m, SWD_USTAR_TURBULENCE), SWD_OK);
    assert_int_equal(swd_commit(m), SWD_OK);
    double r[4], r0[4];
    tracer_shares(m, 1, r);
    tracer_shares(m, 0, r0);
    for (int b = 0; b < 4; b++)
        if (fabs(r[b] - 1.0) > 0.1)
            fail_msg("band %d: share %.3f of uniform (without the gradient: %.3f)", b, r[b], r0[b]);
    printf("shares %.3f %.3f %.3f %.3f; without %.3f %.3f %.3f %.3f\n", r[0], r[1], r[2], r[3], r0[0], r0[1], r0[2], r0[3]);
    if (!(r0[0] > 1.3))
        fail_msg("without the gradient of k the wall band holds %.3f of uniform: the check cannot fail", r0[0]);
    swd_free(m);
}

/* The 1-D channel: tracers stay well mixed (no spurious drift to the wall), the
 * CRW's inertial deposition at tau+ = 10 is near the measurements (Wood's
 * 0.045), and its diffusion-impaction deposition at tau+ = 1 is far below
 * (the known failure of a Gaussian CRW, which the closure repairs). */
static void channel(void **s)
{
    (void)s;
    swd_model *m = swd_alloc();
    swc_params p;
    swc_params_default(&p);
    p.n = 400;
    p.t_run = 6000;
    p.t_warm = 1000;
    swc_result r;
    char err[256];
    p.tau_plus = 0.01;
    assert_int_equal(swc_run(m, &p, &r, err, sizeof err), 0);
    assert_true(r.c_sub > 0.8 && r.c_sub < 1.5);
    assert_true(r.vplus < 1e-4);
    p.tau_plus = 10;
    assert_int_equal(swc_run(m, &p, &r, err, sizeof err), 0);
    assert_true(r.vplus > 0.045 / 2 && r.vplus < 0.045 * 2);
    assert_true(r.vplus_se < 0.2 * r.vplus);
    p.tau_plus = 1;
    assert_int_equal(swc_run(m, &p, &r, err, sizeof err), 0);
    assert_true(r.vplus < 4.5e-4 / 5);
    /* bad parameters are named */
    p.tau_plus = -1;
    assert_int_equal(swc_run(m, &p, &r, err, sizeof err), -1);
    assert_non_null(strstr(err, "tau+"));
    swd_free(m);
}

/* Gravity towards the wall: a walk that keeps tracers well mixed keeps
 * settling tracers uniform too (the normalized Langevin equation's stationary
 * density is uniform for any drift velocity added to the fluid's, doc/
 * deposition.md), so the deposition of tracer-like particles is settling and
 * no more: V+ = g+ tau+ (the turbulent part is ~1e-8 at tau+ 0.01), and the
 * concentration next to the wall is the mean. */
static void settling_adds(void **s)
{
    (void)s;
    swd_model *m = swd_alloc();
    assert_int_equal(swd_commit(m), SWD_OK);
    swc_params p;
    swc_params_default(&p);
    p.n = 4000;
    p.t_run = 6000;
    p.t_warm = 1000;
    p.tau_plus = 0.01;
    p.g_plus = 1.0;    /* settling V+ 0.01 */
    p.y_sub = 1.0;
    swc_result r;
    char err[256];
    assert_int_equal(swc_run(m, &p, &r, err, sizeof err), 0);
    const double vs = p.g_plus * p.tau_plus;
    printf("settling: V+ %.4g +- %.2g over g+ tau+ %.4g: %.3f; c(y+ < 1) %.3f\n", r.vplus,
           r.vplus_se, vs, r.vplus / vs, r.c_sub);
    if (fabs(r.vplus / vs - 1.0) > 0.15)
        fail_msg("tracer-like particles under gravity deposit %.3f of settling", r.vplus / vs);
    assert_true(r.vplus_se < 0.1 * vs);
    if (fabs(r.c_sub - 1.0) > 0.2)
        fail_msg("under gravity the band y+ < 1 holds %.3f of the mean", r.c_sub);
    /* g+ out of range is named */
    p.g_plus = 2.0;
    assert_int_equal(swc_run(m, &p, &r, err, sizeof err), -1);
    assert_non_null(strstr(err, "g+"));
    p.g_plus = NAN;
    assert_int_equal(swc_run(m, &p, &r, err, sizeof err), -1);
    swd_free(m);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(wall_layer_values), cmocka_unit_test(relaxation_and_law),
        cmocka_unit_test(settings),          cmocka_unit_test(statistics),
        cmocka_unit_test(one_step),          cmocka_unit_test(closure_table),
        cmocka_unit_test(closure_file),      cmocka_unit_test(wall_frame),
        cmocka_unit_test(channel),           cmocka_unit_test(drift_is_the_gradient),
        cmocka_unit_test(well_mixed_1d),     cmocka_unit_test(settling_adds),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
