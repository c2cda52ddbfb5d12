/* test_swp.c - closed forms of regime/physics against independent numbers. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <cmocka.h>

#include "swp_contact.h"
#include "swp_cor.h"

#define ASSERT_REL(x, ref, tol) assert_true(fabs((x) - (ref)) <= (tol) * fabs(ref))

/* Baseline ice on ABS (doc/physics-brief.md section 2). */
static const double E1 = 9.8e9, NU1 = 0.31, E2 = 2.0e9, NU2 = 0.35, GAM = 0.2, RHO = 920.0;

static void effective_modulus(void **s)
{
    (void)s;
    ASSERT_REL(swp_effective_modulus(E1, NU1, E2, NU2), 1.8829e9, 1e-3);
    ASSERT_REL(swp_effective_radius(25e-6, INFINITY), 25e-6, 1e-15);
    ASSERT_REL(swp_effective_radius(2.0, 2.0), 1.0, 1e-15);
}

/* F(a0) = 0, F at its minimum (load control) = -1.5 pi Gamma R,
 * delta(a_f) = delta_c and F is the minimum of F(a) at d F/d a = 0. */
static void jkr_closed_forms(void **s)
{
    (void)s;
    const double Es = swp_effective_modulus(E1, NU1, E2, NU2), R = 25e-6;
    const double a0 = swp_jkr_a0(GAM, Es, R);
    assert_true(fabs(swp_jkr_force(a0, GAM, Es, R)) < 1e-12 * swp_jkr_pulloff_force(GAM, R));
    /* minimum of F(a) by golden section, independent of the closed form */
    double lo = 0.0, hi = a0;
    for (int i = 0; i < 200; i++) {
        double m1 = hi - 0.618034 * (hi - lo), m2 = lo + 0.618034 * (hi - lo);
        if (swp_jkr_force(m1, GAM, Es, R) < swp_jkr_force(m2, GAM, Es, R)) hi = m2; else lo = m1;
    }
    ASSERT_REL(-swp_jkr_force(0.5 * (lo + hi), GAM, Es, R), swp_jkr_pulloff_force(GAM, R), 1e-9);
    const double af = swp_jkr_af(GAM, Es, R);
    ASSERT_REL(swp_jkr_delta(af, GAM, Es, R), swp_jkr_delta_c(GAM, Es, R), 1e-12);
    /* d delta / d a = 0 at a_f: minimum overlap reachable on the JKR curve */
    const double h = af * 1e-4;
    assert_true(swp_jkr_delta(af + h, GAM, Es, R) > swp_jkr_delta(af, GAM, Es, R));
    assert_true(swp_jkr_delta(af - h, GAM, Es, R) > swp_jkr_delta(af, GAM, Es, R));
}

/* Thornton (1997): e = 1 at V_i = V_y, tends to 1.185 (V_y/V_i)^(1/4), and the
 * wall asymptote is the same law with the wall yield velocity. */
static void thornton_cor(void **s)
{
    (void)s;
    ASSERT_REL(swp_cor_thornton(1.0), 1.0, 1e-15);
    assert_true(fabs(swp_cor_thornton(0.999999) - 1.0) < 1e-3);
    const double x = 1e-8;
    ASSERT_REL(swp_cor_thornton(x), 1.185 * pow(x, 0.25), 2e-3);
    const double Es = swp_effective_modulus(E1, NU1, E2, NU2), py = swp_limiting_pressure(1e6);
    const double vy = swp_yield_velocity_wall(py, Es, RHO), vi = 3.0;
    ASSERT_REL(swp_cor_thornton_wall_asymptote(py, Es, RHO, vi),
               swp_cor_thornton_pp_asymptote(vy / vi), 2e-3);
    assert_true(swp_cor_thornton(2.0) == 1.0);
    assert_true(isnan(swp_cor_thornton(NAN)));
    ASSERT_REL(swp_cor_combine(0.8, 1.0), 0.8, 1e-15);
    assert_true(swp_cor_combine(0.1, 0.1) == 0.0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(effective_modulus),
        cmocka_unit_test(jkr_closed_forms),
        cmocka_unit_test(thornton_cor),
    };
    return cmocka_run_group_tests_name("physics", tests, NULL, NULL);
}
