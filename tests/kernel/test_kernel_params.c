/* test_kernel_params.c - swr_params: defaults, strict parsing, ranges,
 * config files, print/load round trip, model allocation. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include <cmocka.h>

#include "swp_contact.h"
#include "swp_time.h"
#include "swr_collide.h"
#include "swr_params.h"

static void defaults(void **s)
{
    (void)s;
    swr_params p;
    swr_params_default(&p);
    char err[256] = "";
    assert_int_equal(swr_params_validate(&p, err, sizeof err), 0);
    assert_true(p.rho == 920.0 && p.E == 9.8e9 && p.nu == 0.31 && p.sigma_y == 1.0e6);
    assert_true(p.E_wall == 2.0e9 && p.nu_wall == 0.35 && p.gamma == 0.2 && p.mu == 0.05);
    assert_int_equal(p.cor, SWR_COR_THORNTON);
    assert_int_equal(p.cor_pair, SWR_PAIR_WALL);
    assert_int_equal(p.adhesion, SWR_ADHESION_JKR);
    assert_true(p.accuracy == 60.0);
}

/* The message names the key and the value. */
static void expect_reject(swr_params *p, const char *key, const char *value)
{
    char err[256] = "";
    const swr_params before = *p;
    assert_int_equal(swr_params_set(p, key, value, err, sizeof err), -1);
    assert_non_null(strstr(err, key));
    assert_non_null(strstr(err, value));
    assert_memory_equal(&before, p, sizeof before); /* untouched */
}

static void set_and_reject(void **s)
{
    (void)s;
    swr_params p;
    swr_params_default(&p);
    char err[256];
    assert_int_equal(swr_params_set(&p, "gamma", "0.5", err, sizeof err), 0);
    assert_true(p.gamma == 0.5);
    assert_int_equal(swr_params_set(&p, "cor", "elastic", err, sizeof err), 0);
    assert_int_equal(p.cor, SWR_COR_ELASTIC);
    assert_int_equal(swr_params_set(&p, "cor", "0.35", err, sizeof err), 0);
    assert_int_equal(p.cor, SWR_COR_CONSTANT);
    assert_true(p.cor_value == 0.35);
    assert_int_equal(swr_params_set(&p, "cor", "thornton-asymptote", err, sizeof err), 0);
    assert_int_equal(p.cor, SWR_COR_THORNTON_ASYMPTOTE);
    assert_int_equal(swr_params_set(&p, "cor", "thornton-ning", err, sizeof err), 0);
    assert_int_equal(p.cor, SWR_COR_THORNTON_NING);
    assert_int_equal(p.dashpot, SWR_DASHPOT_LOADING);
    assert_int_equal(swr_params_set(&p, "dashpot", "both", err, sizeof err), 0);
    assert_int_equal(p.dashpot, SWR_DASHPOT_BOTH);
    assert_int_equal(swr_params_set(&p, "cor_pair", "particle", err, sizeof err), 0);
    assert_int_equal(p.cor_pair, SWR_PAIR_PARTICLE);
    assert_int_equal(swr_params_set(&p, "adhesion", "none", err, sizeof err), 0);
    assert_int_equal(p.adhesion, SWR_ADHESION_NONE);
    /* the extreme grid is accepted */
    const char *ok[][2] = { { "E", "0.1e9" }, { "E", "100e9" }, { "gamma", "0.01" },
                            { "gamma", "10" }, { "cor", "0.01" }, { "cor", "1" } };
    for (size_t i = 0; i < sizeof ok / sizeof ok[0]; i++)
        assert_int_equal(swr_params_set(&p, ok[i][0], ok[i][1], err, sizeof err), 0);

    expect_reject(&p, "gamma", "nan");
    expect_reject(&p, "gamma", "inf");
    expect_reject(&p, "gamma", "-0.1");
    expect_reject(&p, "E", "1e300");
    expect_reject(&p, "E", "9.8e9x");
    expect_reject(&p, "nu", "0.6");
    expect_reject(&p, "rho", "");
    expect_reject(&p, "cor", "1.5");
    expect_reject(&p, "cor", "0");
    expect_reject(&p, "cor", "plastic");
    expect_reject(&p, "cor_pair", "floor");
    expect_reject(&p, "adhesion", "dmt");
    expect_reject(&p, "dashpot", "unloading");
    expect_reject(&p, "cor", "thornton-ninga");
    expect_reject(&p, "accuracy", "2");
    expect_reject(&p, "colour", "blue");
}

static void key_value(void **s)
{
    (void)s;
    swr_params p;
    swr_params_default(&p);
    char err[256];
    assert_int_equal(swr_params_set_kv(&p, "gamma=1.0", err, sizeof err), 0);
    assert_true(p.gamma == 1.0);
    assert_int_equal(swr_params_set_kv(&p, " mu = 0.3 ", err, sizeof err), 0);
    assert_true(p.mu == 0.3);
    assert_int_equal(swr_params_set_kv(&p, "gamma", err, sizeof err), -1);
    assert_int_equal(swr_params_set_kv(&p, "=3", err, sizeof err), -1);
    assert_int_equal(swr_params_set_kv(&p, "E=abc", err, sizeof err), -1);
    assert_non_null(strstr(err, "E"));
    assert_non_null(strstr(err, "abc"));
}

static char *write_tmp(const char *text)
{
    static char path[64];
    snprintf(path, sizeof path, "/tmp/swr_params_XXXXXX");
    const int fd = mkstemp(path);
    assert_true(fd >= 0);
    FILE *f = fdopen(fd, "w");
    fputs(text, f);
    fclose(f);
    return path;
}

static void config_file(void **s)
{
    (void)s;
    swr_params p;
    swr_params_default(&p);
    char err[256];
    char *path = write_tmp("# comment\n\ngamma 0.4\nE = 8.9e9   # trailing comment\ncor thornton-asymptote\n");
    assert_int_equal(swr_params_load(&p, path, err, sizeof err), 0);
    assert_true(p.gamma == 0.4 && p.E == 8.9e9 && p.cor == SWR_COR_THORNTON_ASYMPTOTE);
    unlink(path);

    path = write_tmp("gamma 0.4\nsigma_y nan\n");
    assert_int_equal(swr_params_load(&p, path, err, sizeof err), -1);
    char want[96];
    snprintf(want, sizeof want, "%s:2:", path);
    assert_non_null(strstr(err, want));
    assert_non_null(strstr(err, "sigma_y"));
    unlink(path);

    path = write_tmp("gamma\n");
    assert_int_equal(swr_params_load(&p, path, err, sizeof err), -1);
    assert_non_null(strstr(err, ":1:"));
    unlink(path);

    assert_int_equal(swr_params_load(&p, "/nonexistent/swr.cfg", err, sizeof err), -1);
    assert_non_null(strstr(err, "/nonexistent/swr.cfg"));
}

/* swr_params_print writes a file swr_params_load reads back to the same set. */
static void print_round_trip(void **s)
{
    (void)s;
    swr_params p, q;
    swr_params_default(&p);
    char err[256];
    assert_int_equal(swr_params_set(&p, "cor", "0.123456789", err, sizeof err), 0);
    assert_int_equal(swr_params_set(&p, "gamma", "0.37", err, sizeof err), 0);
    assert_int_equal(swr_params_set(&p, "adhesion", "none", err, sizeof err), 0);
    assert_int_equal(swr_params_set(&p, "cor_pair", "particle", err, sizeof err), 0);
    assert_int_equal(swr_params_set(&p, "dashpot", "both", err, sizeof err), 0);
    char path[] = "/tmp/swr_print_XXXXXX";
    const int fd = mkstemp(path);
    FILE *f = fdopen(fd, "w");
    swr_params_print(&p, "", f);
    fclose(f);
    swr_params_default(&q);
    assert_int_equal(swr_params_load(&q, path, err, sizeof err), 0);
    unlink(path);
    assert_true(q.cor == p.cor && q.cor_value == p.cor_value && q.gamma == p.gamma);
    assert_true(q.adhesion == p.adhesion && q.cor_pair == p.cor_pair && q.dashpot == p.dashpot);
    assert_true(q.E == p.E && q.rho == p.rho && q.xi_crit == p.xi_crit && q.z0 == p.z0);
}

static void model_alloc(void **s)
{
    (void)s;
    swr_params p;
    swr_params_default(&p);
    char err[256] = "";
    swr_model *m = swr_model_alloc(&p, err, sizeof err);
    assert_non_null(m);
    assert_true(swr_model_params(m)->gamma == 0.2);
    int ok = 0;
    /* doc/physics-brief.md section 3: lambda about 9.6-41.3 for 10-100 um (z0 0.3 nm) */
    const double l10 = swr_model_tabor(m, 10e-6, &ok);
    assert_true(ok && l10 > 5.0 && l10 < 40.0);
    swr_model_free(m);
    p.gamma = NAN;
    assert_null(swr_model_alloc(&p, err, sizeof err));
    assert_non_null(strstr(err, "gamma"));
    /* bad impacts */
    swr_params_default(&p);
    m = swr_model_alloc(&p, err, sizeof err);
    swr_result r;
    const swr_impact bad[] = { { NAN, 1.0, 0.0, 0.0, 0.0, 0.0 }, { 50e-6, 0.0, 0.0, 0.0, 0.0, 0.0 },
                               { 50e-6, -1.0, 0.0, 0.0, 0.0, 0.0 }, { 50e-6, 1.0, -1.0, 0.0, 0.0, 0.0 },
                               { 50e-6, INFINITY, 0.0, 0.0, 0.0, 0.0 }, { 50e-6, 1.0, 0.0, NAN, 0.0, 0.0 },
                               { 1.0, 1.0, 0.0, 0.0, 0.0, 0.0 }, { 50e-6, 1.0, 0.0, 0.0, NAN, 0.0 },
                               { 50e-6, 1.0, 0.0, 0.0, 0.0, 2.0 } };
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        assert_int_equal(swr_collide(m, &bad[i], &r, NULL), SWR_EINVAL);
        assert_int_equal(r.status, SWR_EINVAL);
        assert_true(r.msg[0] != '\0');
    }
    swr_model_free(m);
}

/* Tiny impact speeds: the scaled units stay finite for
 * every accepted v_n. With adhesion an impact slower than the elastic sticking
 * speed sticks (it used to bounce below 1e-85 m/s); without adhesion it
 * rebounds with the COR and the Hertz contact time; below SWR_V_MIN the kernel
 * refuses with the accepted range. */
static void tiny_speeds(void **s)
{
    (void)s;
    swr_params p;
    char err[256];
    const double ds[] = { SWR_D_MIN, 50e-6, SWR_D_MAX };
    const double vs[] = { 1e-300, 1e-90, SWR_V_MIN, 1e-9 };
    for (int law = 0; law < 3; law++) {
        swr_params_default(&p);
        if (law == 1) assert_int_equal(swr_params_set_kv(&p, "adhesion=none", err, sizeof err), 0);
        if (law == 2) {
            assert_int_equal(swr_params_set_kv(&p, "adhesion=none", err, sizeof err), 0);
            assert_int_equal(swr_params_set_kv(&p, "cor=0.5", err, sizeof err), 0);
        }
        swr_model *m = swr_model_alloc(&p, err, sizeof err);
        assert_non_null(m);
        for (size_t i = 0; i < 3; i++)
            for (size_t k = 0; k < 4; k++) {
                if (law > 0 && vs[k] < SWR_V_MIN) continue; /* Hertz: refused, below */
                swr_impact in = { ds[i], vs[k], 0.0, 0.0, 0.0, 0.0 };
                swr_result r;
                assert_int_equal(swr_collide(m, &in, &r, NULL), SWR_OK);
                assert_true(isfinite(r.e_n) && isfinite(r.t_contact) && isfinite(r.delta_max));
                assert_true(isfinite(r.energy_err) && r.energy_err < 1e-3);
                if (law == 0) {
                    assert_true(r.stick);
                } else {
                    const double mass = p.rho * M_PI * ds[i] * ds[i] * ds[i] / 6.0;
                    const double Es = swp_effective_modulus(p.E, p.nu, p.E_wall, p.nu_wall);
                    const double tc = swp_hertz_contact_time(mass, 0.5 * ds[i], Es, vs[k]);
                    assert_false(r.contact_kept);
                    /* thornton: below the yield velocity the rebound is elastic */
                    assert_true(fabs(r.e_n - (law == 1 ? 1.0 : 0.5)) < 5e-3);
                    if (law == 1) assert_true(fabs(r.t_contact / tc - 1.0) < 1e-2);
                }
            }
        swr_impact below = { 50e-6, 0.5 * SWR_V_MIN, 0.0, 0.0, 0.0, 0.0 };
        swr_result r;
        if (law > 0) {
            assert_int_equal(swr_collide(m, &below, &r, NULL), SWR_EINVAL);
            assert_non_null(strstr(r.msg, "vn"));
            assert_non_null(strstr(r.msg, "without adhesion"));
        } else {
            assert_int_equal(swr_collide(m, &below, &r, NULL), SWR_OK);
            assert_true(r.stick);
        }
        swr_model_free(m);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(defaults),
        cmocka_unit_test(set_and_reject),
        cmocka_unit_test(key_value),
        cmocka_unit_test(config_file),
        cmocka_unit_test(print_round_trip),
        cmocka_unit_test(model_alloc),
        cmocka_unit_test(tiny_speeds),
    };
    return cmocka_run_group_tests_name("kernel_params", tests, NULL, NULL);
}
