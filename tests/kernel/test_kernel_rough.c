/* test_kernel_rough.c - the rough wall (wall lattice) against closed
 * forms and its own limits: one asperity hit head-on is a sphere-sphere impact
 * with R* = R r/(R + r) (elastic JKR sticking velocity V_s within 0.5 %), a
 * huge asperity is the flat wall (v_crit within 0.5 %), the lattice geometry
 * and its random variant, reproducible stick fractions that converge as
 * 1/sqrt(N), and no NaN or runaway on extreme inputs; the adaptive step
 * against the fixed one it replaced. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>

#include "swp_contact.h"
#include "swp_jkr.h"
#include "swr_collide.h"
#include "swr_wall.h"
#include "swt_vcrit.h"
#include "kernel_test.h"

#define REL(x, ref) (fabs((x) - (ref)) / fabs(ref))

/* Head-on on top of one asperity, elastic JKR: the sphere sticks iff its
 * kinetic energy is below the separation energy U_c of the particle-asperity
 * contact, i.e. below Thornton & Ning's V_s of a sphere of R* and the
 * particle's mass (the wall's V_s formula with rho scaled by (R/R*)^3). */
static void one_asperity_vs(void **state)
{
    (void)state;
    const double radii[] = { 0.5e-6, 1e-6, 5e-6 };
    const double ds[] = { 10e-6, 50e-6 };
    for (size_t a = 0; a < 3; a++) {
        char kr[64], ks[64];
        snprintf(kr, sizeof kr, "asperity_r=%g", radii[a]);
        snprintf(ks, sizeof ks, "asperity_spacing=%g", 3.0 * radii[a]);
        /* cor elastic everywhere; and asperity_yield elastic: the
         * default plastic law on the particle, elastic asperity contacts, and
         * on whole spheres (asperity_shape sphere: the same top) */
        const char *kv[] = { "wall=lattice", kr, ks, "cor=elastic", NULL };
        const char *kvy[] = { "wall=lattice", kr, ks, "asperity_yield=elastic", "asperity_shape=sphere", NULL };
        swr_params p = test_params(kv);
        swr_model *m = test_model(kv), *my = test_model(kvy);
        const double Es = swp_effective_modulus(p.E, p.nu, p.E_wall, p.nu_wall);
        for (size_t k = 0; k < 2; k++) {
            const double R = 0.5 * ds[k], Rs = R * radii[a] / (R + radii[a]);
            const double rho_eff = p.rho * pow(R / Rs, 3.0);
            const double vs = swp_sticking_velocity_tn(p.gamma, rho_eff, Es, Rs);
            double vc;
            assert_int_equal(swr_vcrit_normal(m, ds[k], 1e-4, 1e2, 1e-5, &vc), 0);
            const double e = REL(vc, vs);
            double vy;
            assert_int_equal(swr_vcrit_normal(my, ds[k], 1e-4, 1e2, 1e-5, &vy), 0);
            printf("  r %g um, d %g um: v_crit %.6g, V_s(R*) %.6g, rel %.2e; elastic asperity "
                   "sphere %.6g, rel %.2e\n", radii[a] * 1e6, ds[k] * 1e6, vc, vs, e, vy, REL(vy, vs));
            assert_true(e < 5e-3);
            assert_true(REL(vy, vs) < 5e-3);
        }
        swr_model_free(m);
        swr_model_free(my);
    }
}

/* A huge asperity hit on its top is the flat wall (default contact: JKR with
 * Thornton's plastic COR dashpot, the stepped integrator in 3-D). */
static void huge_asperity_is_flat(void **state)
{
    (void)state;
    const char *flat[] = { NULL };
    const char *big[] = { "wall=lattice", "asperity_r=0.1", "asperity_spacing=0.3", NULL };
    swr_model *mf = test_model(flat), *mb = test_model(big);
    const double ds[] = { 10e-6, 30e-6, 100e-6 };
    for (size_t k = 0; k < 3; k++) {
        double vf, vb;
        assert_int_equal(swr_vcrit_normal(mf, ds[k], 1e-3, 1e2, 1e-5, &vf), 0);
        assert_int_equal(swr_vcrit_normal(mb, ds[k], 1e-3, 1e2, 1e-5, &vb), 0);
        printf("  d %g um: flat %.6g, r = 0.1 m %.6g, rel %.2e\n", ds[k] * 1e6, vf, vb, REL(vb, vf));
        assert_true(REL(vb, vf) < 5e-3);
        /* and a bounce's COR */
        swr_impact in = { ds[k], 2.0 * vf, 0.0, 0.0, 0.0, 0.0 };
        swr_result rf, rb;
        assert_int_equal(swr_collide(mf, &in, &rf, NULL), SWR_OK);
        assert_int_equal(swr_collide(mb, &in, &rb, NULL), SWR_OK);
        assert_false(rf.contact_kept);
        assert_false(rb.contact_kept);
        assert_true(fabs(rb.e_n - rf.e_n) < 5e-3);
        assert_true(rb.energy_err < 1e-3);
    }
    swr_model_free(mf);
    swr_model_free(mb);
}

/* Lattice nodes, spacing, the random offsets within their bounds and fixed
 * by the seed, and the index ranges covering a box. */
static void lattice_geometry(void **state)
{
    (void)state;
    const char *sq[] = { "wall=lattice", "asperity_r=1e-6", "asperity_spacing=2e-6", NULL };
    const char *hx[] = { "wall=lattice", "lattice=hex", "asperity_spacing=2e-6", NULL };
    const char *rn[] = { "wall=lattice", "asperity_spacing=2e-6", "asperity_jitter=0.3",
                         "asperity_dz=0.5e-6", "wall_seed=7", NULL };
    const char *rn2[] = { "wall=lattice", "asperity_spacing=2e-6", "asperity_jitter=0.3",
                          "asperity_dz=0.5e-6", "wall_seed=8", NULL };
    swr_wall w, h, r, r2;
    swr_params p;
    p = test_params(sq); swr_wall_init(&w, &p);
    p = test_params(hx); swr_wall_init(&h, &p);
    p = test_params(rn); swr_wall_init(&r, &p);
    p = test_params(rn2); swr_wall_init(&r2, &p);
    double c[3], c2[3];
    swr_wall_asperity(&w, 3, -2, c);
    assert_true(fabs(c[0] - 6e-6) < 1e-18 && fabs(c[1] + 4e-6) < 1e-18 && c[2] == 0.0);
    /* hexagonal: every neighbour of a node at the spacing */
    swr_wall_asperity(&h, 0, 0, c);
    const int nb[6][2] = { { 1, 0 }, { -1, 0 }, { 0, 1 }, { -1, 1 }, { 0, -1 }, { -1, -1 } };
    for (int k = 0; k < 6; k++) {
        swr_wall_asperity(&h, nb[k][0], nb[k][1], c2);
        assert_true(fabs(hypot(c2[0] - c[0], c2[1] - c[1]) - 2e-6) < 1e-15);
    }
    /* random: bounded offsets, the same for the same seed, different otherwise */
    int differ = 0;
    for (int i = -20; i <= 20; i++)
        for (int j = -20; j <= 20; j++) {
            swr_wall_asperity(&r, i, j, c);
            assert_true(fabs(c[0] - i * 2e-6) <= 0.3 * 2e-6 + 1e-18);
            assert_true(fabs(c[1] - j * 2e-6) <= 0.3 * 2e-6 + 1e-18);
            assert_true(c[2] <= 0.0 && c[2] >= -0.5e-6);
            swr_wall_asperity(&r, i, j, c2);
            assert_memory_equal(c, c2, sizeof c);
            swr_wall_asperity(&r2, i, j, c2);
            differ += c[0] != c2[0];
        }
    assert_true(differ > 1600);
    /* the index ranges hold every node in a box */
    const swr_wall *ws[] = { &w, &h, &r };
    for (int q = 0; q < 3; q++) {
        const double xlo = -3.3e-6, xhi = 5.1e-6, ylo = 0.7e-6, yhi = 9.9e-6;
        int j0, j1, inside = 0, found = 0;
        for (int i = -30; i <= 30; i++)
            for (int j = -30; j <= 30; j++) {
                swr_wall_asperity(ws[q], i, j, c);
                inside += c[0] >= xlo && c[0] <= xhi && c[1] >= ylo && c[1] <= yhi;
            }
        swr_wall_rows(ws[q], ylo, yhi, &j0, &j1);
        for (int j = j0; j <= j1; j++) {
            int i0, i1;
            swr_wall_row_range(ws[q], j, xlo, xhi, &i0, &i1);
            for (int i = i0; i <= i1; i++) {
                swr_wall_asperity(ws[q], i, j, c);
                found += c[0] >= xlo && c[0] <= xhi && c[1] >= ylo && c[1] <= yhi;
            }
        }
        assert_int_equal(found, inside);
        assert_true(inside > 5);
    }
}

/* A stick fraction is a fixed number for a seed and the binomial error of
 * N points shrinks as 1/sqrt(N): over 24 seeds the spread of the fraction
 * at N = 8, 32, 128 matches sqrt(p (1 - p) / N) with p from all the points. */
static void probability_seed_and_convergence(void **state)
{
    (void)state;
    const char *kv[] = { "wall=lattice", NULL };
    swr_model *m = test_model(kv);
    swt_vcrit_opts o;
    swt_vcrit_opts_default(&o);
    const double d = 50e-6, vn = 0.5;   /* a cell with p between 0.1 and 0.9 */
    swt_fraction f1, f2;
    char msg[200] = "";
    o.points = 32;
    o.seed = 5;
    assert_int_equal(swt_stick_fraction(m, d, vn, &o, &f1, NULL, msg, sizeof msg), 0);
    assert_int_equal(swt_stick_fraction(m, d, vn, &o, &f2, NULL, msg, sizeof msg), 0);
    assert_int_equal(f1.sticks, f2.sticks);
    assert_int_equal(f1.steps, f2.steps);
    const int ns[] = { 8, 32, 128 };
    const int nseed = 24;
    double sd[3], pall = 0.0;
    long tot = 0, st = 0;
    double frac[3][24];
    for (int k = 0; k < 3; k++)
        for (int s = 0; s < nseed; s++) {
            o.points = ns[k];
            o.seed = 100 + 1000 * k + s;
            assert_int_equal(swt_stick_fraction(m, d, vn, &o, &f1, NULL, msg, sizeof msg), 0);
            frac[k][s] = (double)f1.sticks / f1.points;
            st += f1.sticks;
            tot += f1.points;
        }
    pall = (double)st / tot;
    printf("  p(d 50 um, v_n 0.5 m/s) = %.4f over %ld points\n", pall, tot);
    assert_true(pall > 0.1 && pall < 0.9);
    for (int k = 0; k < 3; k++) {
        double mean = 0.0, var = 0.0;
        for (int s = 0; s < nseed; s++)
            mean += frac[k][s] / nseed;
        for (int s = 0; s < nseed; s++)
            var += (frac[k][s] - mean) * (frac[k][s] - mean) / (nseed - 1);
        sd[k] = sqrt(var);
        const double expect = sqrt(pall * (1.0 - pall) / ns[k]);
        printf("  N %3d: spread %.4f, binomial %.4f, ratio %.2f\n", ns[k], sd[k], expect,
               sd[k] / expect);
        /* 24 samples: the sample sd is within a factor 1.6 of the truth at > 99 % */
        assert_true(sd[k] / expect > 1.0 / 1.6 && sd[k] / expect < 1.6);
    }
    /* 1/sqrt(N): 16 times the points, a quarter of the spread */
    assert_true(sd[0] / sd[2] > 2.0 && sd[0] / sd[2] < 8.0);
    swr_model_free(m);
}

/* Extreme inputs: no NaN, no result outside its range, never past the step
 * bound, for sizes, speeds, asperity sizes and laws across their ranges. */
static void extreme_inputs(void **state)
{
    (void)state;
    srand48(11);
    const char *walls[][7] = {
        { "wall=lattice", NULL },
        { "wall=lattice", "lattice=hex", "asperity_r=1e-8", "asperity_spacing=5e-8", NULL },
        { "wall=lattice", "asperity_r=1e-3", "asperity_spacing=2e-3", "asperity_jitter=0.5",
          "asperity_dz=5e-4", NULL },
        { "wall=lattice", "asperity_spacing=1e-5", "adhesion=none", "cor=0.5", NULL },
        { "wall=lattice", "gamma=10", "E=1e8", "mu=2", "dashpot=both", NULL },
        { "wall=lattice", "cor=elastic", "gamma=0.01", "asperity_dz=0.9e-6", "asperity_jitter=0.2", NULL },
    };
    long n = 0, bound = 0;
    for (size_t w = 0; w < sizeof walls / sizeof walls[0]; w++) {
        swr_model *m = test_model(walls[w]);
        double lx, ly;
        swr_model_sample_area(m, &lx, &ly);
        assert_true(lx > 0.0 && ly > 0.0);
        const swr_params *pp = swr_model_params(m);
        const double dmax = fmin(SWR_D_MAX, SWR_ROUGH_D_OVER_R_MAX * pp->asperity_r);
        /* beyond d / r = SWR_ROUGH_D_OVER_R_MAX: a named error */
        if (dmax < SWR_D_MAX) {
            swr_impact big = { dmax * 1.01, 1.0, 0.0, 0.0, 0.0, 0.0 };
            swr_result r;
            assert_int_equal(swr_collide(m, &big, &r, NULL), SWR_EINVAL);
            assert_non_null(strstr(r.msg, "asperity radii"));
        }
        for (int k = 0; k < 40; k++) {
            swr_impact in = { SWR_D_MIN * pow(dmax / SWR_D_MIN, drand48()), 1e-3 * pow(1e6, drand48()),
                              drand48() < 0.5 ? 0.0 : 1e-3 * pow(1e5, drand48()), 0.0,
                              lx * drand48(), ly * drand48() };
            swr_result r;
            const swr_status st = swr_collide(m, &in, &r, NULL);
            assert_true(st == SWR_OK || st == SWR_STEP_BOUND);
            /* a bounce leaves with at most the impact energy (on a rough wall
             * tangential speed may turn into normal: e_n > 1 is possible) */
            const double et = isfinite(r.e_t) ? r.e_t : 0.0;
            const double e_out = r.e_n * r.e_n * in.vn * in.vn + et * et * in.vt * in.vt;
            if (!(isfinite(r.e_n) && r.e_n >= 0.0
                  && e_out <= (in.vn * in.vn + in.vt * in.vt) * (1.0 + 1e-2)))
                fail_msg("wall %zu: d %g vn %g vt %g x %g y %g: e_n %g e_t %g", w, in.d, in.vn,
                         in.vt, in.x, in.y, r.e_n, et);
            assert_true(isfinite(r.t_contact) && r.t_contact >= 0.0);
            assert_true(isfinite(r.energy_err) && isfinite(r.delta_max));
            assert_true(r.steps <= r.max_steps);
            assert_true(r.contacts >= 1);
            n++;
            bound += st == SWR_STEP_BOUND;
        }
        swr_model_free(m);
    }
    printf("  %ld impacts, %ld on a bound\n", n, bound);
    /* grazing flights across many cells of a sparse lattice (flown in chunks) */
    const char *sparse[] = { "wall=lattice", "asperity_r=0.2e-6", "asperity_spacing=20e-6", NULL };
    swr_model *m = test_model(sparse);
    for (int k = 0; k < 8; k++) {
        swr_impact in = { 2e-6, 1e-3, 50.0, 0.0, 3e-6 * k, 1.7e-6 * k };
        swr_result r;
        const swr_status st = swr_collide(m, &in, &r, NULL);
        assert_true(st == SWR_OK || st == SWR_STEP_BOUND);
        assert_true(r.contacts >= 1 && isfinite(r.e_n) && isfinite(r.t_contact));
    }
    swr_model_free(m);
}

/* Settings: every rough-wall key is checked and named; thornton-ning is refused. */
static void rough_params(void **state)
{
    (void)state;
    swr_params p;
    char err[256];
    swr_params_default(&p);
    assert_int_equal(swr_params_set_kv(&p, "wall=bumpy", err, sizeof err), -1);
    assert_non_null(strstr(err, "wall"));
    assert_int_equal(swr_params_set_kv(&p, "lattice=triangle", err, sizeof err), -1);
    assert_int_equal(swr_params_set_kv(&p, "asperity_r=-1e-6", err, sizeof err), -1);
    assert_non_null(strstr(err, "asperity_r"));
    assert_int_equal(swr_params_set_kv(&p, "asperity_jitter=0.7", err, sizeof err), -1);
    assert_int_equal(swr_params_set_kv(&p, "wall_seed=1.5", err, sizeof err), -1);
    assert_non_null(strstr(err, "integer"));
    assert_int_equal(swr_params_set_kv(&p, "rough_hold=nan", err, sizeof err), -1);
    assert_int_equal(swr_params_set_kv(&p, "wall=lattice", err, sizeof err), 0);
    /* overlapping asperities (the contact search of one impact grows without
     * bound, hours for one impact): spacing below 2 r is refused on a lattice,
     * naming both; touching (s = 2 r) is accepted;
     * on a flat wall the asperity keys are not used */
    assert_int_equal(swr_params_set_kv(&p, "asperity_spacing=1.5e-6", err, sizeof err), 0);
    assert_int_equal(swr_params_validate(&p, err, sizeof err), -1);
    assert_non_null(strstr(err, "asperity_spacing: 1.5e-06 m is below 2 asperity_r = 2e-06 m"));
    assert_null(swr_model_alloc(&p, err, sizeof err));
    assert_int_equal(swr_params_set_kv(&p, "asperity_r=0.75e-6", err, sizeof err), 0);
    assert_int_equal(swr_params_validate(&p, err, sizeof err), 0);
    assert_int_equal(swr_params_set_kv(&p, "lattice=hex", err, sizeof err), 0);
    assert_int_equal(swr_params_set_kv(&p, "asperity_spacing=1e-9", err, sizeof err), 0);
    assert_int_equal(swr_params_validate(&p, err, sizeof err), -1);
    assert_int_equal(swr_params_set_kv(&p, "wall=flat", err, sizeof err), 0);
    assert_int_equal(swr_params_validate(&p, err, sizeof err), 0);
    swr_params_default(&p);
    assert_int_equal(swr_params_set_kv(&p, "wall=lattice", err, sizeof err), 0);
    assert_int_equal(swr_params_set_kv(&p, "cor=thornton-ning", err, sizeof err), 0);
    assert_null(swr_model_alloc(&p, err, sizeof err));
    assert_non_null(strstr(err, "thornton-ning"));
    /* a flat wall prints no wall keys; a lattice prints them all */
    swr_params_default(&p);
    char buf[4096];
    FILE *f = fmemopen(buf, sizeof buf, "w");
    swr_params_print(&p, "", f);
    fclose(f);
    assert_null(strstr(buf, "asperity"));
    assert_int_equal(swr_params_set_kv(&p, "wall=lattice", err, sizeof err), 0);
    f = fmemopen(buf, sizeof buf, "w");
    swr_params_print(&p, "", f);
    fclose(f);
    assert_non_null(strstr(buf, "wall lattice"));
    assert_non_null(strstr(buf, "asperity_spacing"));
    assert_non_null(strstr(buf, "rough_hold"));
    assert_non_null(strstr(buf, "rough_step adaptive"));
    assert_non_null(strstr(buf, "asperity_shape hemisphere"));
    assert_non_null(strstr(buf, "asperity_yield contact"));
    /* asperity_shape, asperity_yield: the names or a named error; a whole
     * sphere may sink by up to its diameter, a hemisphere by its radius */
    assert_int_equal(swr_params_set_kv(&p, "asperity_shape=cube", err, sizeof err), -1);
    assert_non_null(strstr(err, "asperity_shape: 'cube'"));
    assert_int_equal(swr_params_set_kv(&p, "asperity_yield=soft", err, sizeof err), -1);
    assert_non_null(strstr(err, "asperity_yield: 'soft'"));
    assert_int_equal(swr_params_set_kv(&p, "asperity_dz=1.5e-6", err, sizeof err), 0);
    assert_int_equal(swr_params_validate(&p, err, sizeof err), -1);
    assert_non_null(strstr(err, "asperity_dz"));
    assert_int_equal(swr_params_set_kv(&p, "asperity_shape=sphere", err, sizeof err), 0);
    assert_int_equal(swr_params_validate(&p, err, sizeof err), 0);
    assert_int_equal(swr_params_set_kv(&p, "asperity_dz=0", err, sizeof err), 0);
    {
        swr_wall w;
        swr_wall_init(&w, &p);
        double c[3];
        swr_wall_asperity(&w, 0, 0, c);
        assert_true(swr_wall_top(&w) == 2.0 * p.asperity_r);
        assert_true(c[2] == p.asperity_r);
    }
    /* rough_step: adaptive | fixed, anything else named */
    assert_int_equal(swr_params_set_kv(&p, "rough_step=fixed", err, sizeof err), 0);
    assert_int_equal(p.rough_step, SWR_ROUGH_STEP_FIXED);
    assert_int_equal(swr_params_set_kv(&p, "rough_step=fast", err, sizeof err), -1);
    assert_non_null(strstr(err, "rough_step: 'fast'"));
}

/* The adaptive step against the fixed one it replaced (rough_step
 * fixed): over a grid of diameters and speeds around the interface of the
 * default lattice, at the same impact points, the stick counts differ by at
 * most 2 of 32 in any cell (the binomial sigma at p = 0.5 is 2.8 points) and in
 * at most 1 % of all impacts, and the steps are at least 3 times fewer; on a
 * sparse lattice (spacing 8 um), where 10 um spheres roll on the base plane
 * for tens of contact times before they stick or leave, the counts differ by
 * at most 2 of 32 too (the held phase's longer step, SWR_ROUGH_HELD). */
static void adaptive_step_vs_fixed(void **state)
{
    (void)state;
    const char *ka[] = { "wall=lattice", NULL };
    const char *kf[] = { "wall=lattice", "rough_step=fixed", NULL };
    swr_model *ma = test_model(ka), *mf = test_model(kf);
    swt_vcrit_opts o;
    swt_vcrit_opts_default(&o);
    o.points = 32;
    long flips = 0, n = 0, steps_a = 0, steps_f = 0;
    int worst = 0;
    for (int i = 0; i < 5; i++) {
        const double d = 10e-6 + 22.5e-6 * i;
        for (int j = 0; j < 6; j++) {
            const double vn = 0.1 * pow(50.0, j / 5.0);
            swt_fraction fa, ff;
            char msg[200] = "";
            assert_int_equal(swt_stick_fraction(ma, d, vn, &o, &fa, NULL, msg, sizeof msg), 0);
            assert_int_equal(swt_stick_fraction(mf, d, vn, &o, &ff, NULL, msg, sizeof msg), 0);
            const int dc = abs(fa.sticks - ff.sticks);
            if (dc > worst)
                worst = dc;
            flips += dc;
            n += o.points;
            steps_a += fa.steps;
            steps_f += ff.steps;
        }
    }
    const char *sa[] = { "wall=lattice", "asperity_spacing=8e-6", NULL };
    const char *sf[] = { "wall=lattice", "asperity_spacing=8e-6", "rough_step=fixed", NULL };
    swr_model *msa = test_model(sa), *msf = test_model(sf);
    swt_fraction fa, ff;
    char msg[200] = "";
    assert_int_equal(swt_stick_fraction(msa, 10e-6, 9.5, &o, &fa, NULL, msg, sizeof msg), 0);
    assert_int_equal(swt_stick_fraction(msf, 10e-6, 9.5, &o, &ff, NULL, msg, sizeof msg), 0);
    printf("  %ld impacts: stick count differs by %ld in all (worst cell %d of 32); "
           "steps %ld adaptive, %ld fixed (x%.1f); sparse lattice, 10 um at 9.5 m/s: %d and %d "
           "of 32 stick, %ld and %ld steps\n", n, flips, worst, steps_a, steps_f,
           (double)steps_f / steps_a, fa.sticks, ff.sticks, fa.steps, ff.steps);
    assert_true(worst <= 2);
    assert_true(flips * 100 <= n);
    assert_true(steps_f >= 3 * steps_a);
    assert_true(abs(fa.sticks - ff.sticks) <= 2);
    assert_true(fa.sticks > 0 && fa.sticks < 32);
    swr_model_free(ma);
    swr_model_free(mf);
    swr_model_free(msa);
    swr_model_free(msf);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(rough_params),
        cmocka_unit_test(lattice_geometry),
        cmocka_unit_test(one_asperity_vs),
        cmocka_unit_test(huge_asperity_is_flat),
        cmocka_unit_test(probability_seed_and_convergence),
        cmocka_unit_test(extreme_inputs),
        cmocka_unit_test(adaptive_step_vs_fixed),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
