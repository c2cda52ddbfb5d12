/* test_swd.c - the near-wall dispersion model (wallmodel/core/swd.h), its
 * wall-layer formulas (regime/physics/swp_nearwall.h) and the 1-D channel
 * (tools/snowdeposit/swc_channel.h). */
#include <math.h>
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
    swd_local at = { 1e-4, 0.5, 1.5e-5, 0.1, 1.0 };
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
    swd_local at = { 10 * nu / ut, ut, nu, 0.0, 0.0 };   /* y+ = 10, no k */
    assert_int_equal(swd_stats_at(m, &at, &st), SWD_OK);
    ASSERT_REL(st.yplus, 10.0, 1e-12);
    ASSERT_REL(st.sigma[1], ut * swp_vrms_plus(10.0), 1e-12);
    ASSERT_REL(st.tl, swp_tl_plus(10.0) * nu / (ut * ut), 1e-12);
    ASSERT_REL(st.dsigma_n, swp_dvrms_plus(10.0) * ut * ut / nu, 1e-12);
    assert_true(st.layer == 1.0);
    /* bulk: isotropic sqrt(2k/3), T_L = 0.3 k/eps */
    at.y = 1.0;
    at.k = 0.6;
    at.eps = 2.0;
    assert_int_equal(swd_stats_at(m, &at, &st), SWD_OK);
    for (int i = 0; i < 3; i++)
        ASSERT_REL(st.sigma[i], sqrt(0.4), 1e-12);
    ASSERT_REL(st.tl, 0.3 * 0.6 / 2.0, 1e-12);
    assert_true(st.layer == 0.0 && st.dsigma_n == 0.0);
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
    assert_null(swd_scale_name(3));
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
                    swd_local x = { ys[a], uts[b], 1e-5, ks[c], ks[e] };
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
 * the kick sigma w (1 - exp(-dt/tau_p)). */
static void one_step(void **s)
{
    (void)s;
    swd_model *m = swd_alloc();
    const double nu = 1.5e-5, ut = 0.5, dt = 2e-5, tp = 1e-4;
    swd_local at = { 8 * nu / ut, ut, nu, 0, 0 };
    swd_stats st;
    swd_stats_at(m, &at, &st);
    double w[3] = { 0.3, -0.7, 1.1 }, w0[3] = { 0.3, -0.7, 1.1 }, xi[3] = { 0.2, 0.4, -0.6 }, kick[3];
    assert_int_equal(swd_advance(m, &at, dt, tp, w, xi, kick, NULL), SWD_OK);
    const double a = exp(-dt / st.tl);
    for (int i = 0; i < 3; i++) {
        ASSERT_REL(kick[i], st.sigma[i] * w0[i] * (1 - exp(-dt / tp)), 1e-12);
        const double want = a * w0[i] + sqrt(1 - a * a) * xi[i] + (i == 1 ? (1 - a) * st.tl * st.dsigma_n : 0);
        ASSERT_REL(w[i], want, 1e-12);
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
    swd_local at = { 5 * nu / ut, ut, nu, 0, 0 };
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

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(wall_layer_values), cmocka_unit_test(relaxation_and_law),
        cmocka_unit_test(settings),          cmocka_unit_test(statistics),
        cmocka_unit_test(one_step),          cmocka_unit_test(closure_table),
        cmocka_unit_test(closure_file),      cmocka_unit_test(wall_frame),
        cmocka_unit_test(channel),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
