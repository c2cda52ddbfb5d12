/* test_sbd.c - the Ahmed body's surface: closed and outward, its volume,
 * frontal area and region areas against the closed forms, the volume's error
 * falling as the square of the front's arc segment, the parameter refusals
 * and the STL's solids. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <cmocka.h>

#include "sbd_body.h"
#include "sbd_stl.h"

#include <gsl/gsl_integration.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* the body's volume written out independently: the straight part W H (L - R)
 * plus the rounded front, whose cross-section at depth x is the rectangle
 * (W - 2R + 2r)(H - 2R + 2r) with r = sqrt(R^2 - (R - x)^2), integrated here
 * numerically over x in [0, R] (GSL's adaptive Gauss-Kronrod, QAG) */
static double front_section(double x, void *vp)
{
    const sbd_params *p = vp;
    double R = p->radius, s = R - x, r = sqrt(fmax(R * R - s * s, 0));
    return (p->width - 2 * R + 2 * r) * (p->height - 2 * R + 2 * r);
}

static double volume_reference(const sbd_params *p)
{
    gsl_integration_workspace *w = gsl_integration_workspace_alloc(1000);
    assert_non_null(w);
    gsl_function f = { .function = front_section, .params = (void *)p };
    double front, abserr;
    assert_int_equal(gsl_integration_qag(&f, 0, p->radius, 0, 1e-12, 1000, GSL_INTEG_GAUSS61, w,
                                         &front, &abserr), 0);
    gsl_integration_workspace_free(w);
    return p->width * p->height * (p->length - p->radius) + front;
}

static sbd_surface *build(const sbd_params *p)
{
    sbd_surface *s = NULL;
    char err[256] = "";
    int rc = sbd_build(p, &s, err, sizeof err);
    if (rc) fprintf(stderr, "%s\n", err);
    assert_int_equal(rc, 0);
    assert_non_null(s);
    return s;
}

static void measure(const sbd_surface *s, sbd_measure *m)
{
    char err[256];
    assert_int_equal(sbd_measure_surface(s, m, err, sizeof err), 0);
}

static void test_closed_and_measures(void **state)
{
    (void)state;
    sbd_params p;
    sbd_params_default(&p);
    sbd_surface *s = build(&p);
    sbd_measure m;
    measure(s, &m);
    assert_int_equal(m.open_edges, 0);
    assert_int_equal(m.nonmanifold, 0);
    double vref = volume_reference(&p);
    assert_true(fabs(sbd_body_volume_exact(&p) - vref) < 1e-9 * vref);
    /* outward (positive) and within the polygon's error of the exact front */
    assert_true(m.body_volume > 0);
    assert_true(fabs(m.body_volume - vref) / vref < 2e-4);
    /* the published frontal area: 0.389 x 0.288 = 0.112 m^2 */
    assert_true(fabs(m.frontal_area - 0.389 * 0.288) < 1e-12);
    assert_true(fabs(m.area[SBD_SENSOR] - p.sensor_width * p.sensor_height) < 1e-12);
    assert_true(fabs(m.area[SBD_REAR] + m.area[SBD_SENSOR] - p.width * p.height) < 1e-12);
    assert_true(fabs(m.area[SBD_TOP] - (p.length - p.radius) * p.width) < 1e-12);
    assert_true(fabs(m.area[SBD_SIDES] - 2 * (p.length - p.radius) * p.height) < 1e-12);
    /* four stilts: polygons of n sides, from below the ground into the body */
    double n = p.stilt_sides, hs = p.stilt_below + p.clearance + p.stilt_into;
    double vstilt = 4 * (n / 2) * p.stilt_radius * p.stilt_radius * sin(2 * M_PI / n) * hs;
    assert_true(fabs(m.volume - m.body_volume - vstilt) < 1e-12);
    sbd_free(s);
}

/* the polygon of the front converges to the closed form at second order */
static void test_volume_converges(void **state)
{
    (void)state;
    sbd_params p;
    sbd_params_default(&p);
    double vref = volume_reference(&p), e[3];
    for (int k = 0; k < 3; k++) {
        p.arc_steps = 8 << k;
        sbd_surface *s = build(&p);
        sbd_measure m;
        measure(s, &m);
        assert_int_equal(m.open_edges, 0);
        e[k] = fabs(m.body_volume - vref);
        sbd_free(s);
    }
    assert_true(e[0] / e[1] > 3.5 && e[0] / e[1] < 4.5);
    assert_true(e[1] / e[2] > 3.5 && e[1] / e[2] < 4.5);
}

/* other shapes stay closed: a square box (radius tiny), an off-centre
 * sensor, a coarse surface */
static void test_variants_closed(void **state)
{
    (void)state;
    const char *sets[][3] = {
        { "radius=0.001", "arc_steps=2", NULL },
        { "sensor_y=0.1", "sensor_z=0.1", "sensor_width=0.02" },
        { "cell=0.2", "stilt_sides=6", NULL },
    };
    for (size_t i = 0; i < sizeof sets / sizeof sets[0]; i++) {
        sbd_params p;
        sbd_params_default(&p);
        char err[256];
        for (int k = 0; k < 3 && sets[i][k]; k++)
            assert_int_equal(sbd_params_set(&p, sets[i][k], err, sizeof err), 0);
        sbd_surface *s = build(&p);
        sbd_measure m;
        measure(s, &m);
        assert_int_equal(m.open_edges, 0);
        assert_int_equal(m.nonmanifold, 0);
        assert_true(m.body_volume > 0);
        assert_true(fabs(m.area[SBD_SENSOR] - p.sensor_width * p.sensor_height) < 1e-12);
        sbd_free(s);
    }
}

static void test_refusals(void **state)
{
    (void)state;
    const char *bad[] = { "radius=0.2", "sensor_z=0.02", "sensor_width=0.5", "stilt_x1=0.05",
                          "stilt_y=0.2", "cell=0", "cell=1e-7", "arc_steps=1", "length=-1" };
    char err[256];
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        sbd_params p;
        sbd_params_default(&p);
        assert_int_equal(sbd_params_set(&p, bad[i], err, sizeof err), 0);
        err[0] = '\0';
        assert_int_equal(sbd_params_check(&p, err, sizeof err), -1);
        assert_true(strlen(err) > 10);
        sbd_surface dummy, *s = &dummy;   /* sbd_build must reset it to NULL */
        assert_int_equal(sbd_build(&p, &s, err, sizeof err), -1);
        assert_null(s);
    }
    sbd_params p;
    sbd_params_default(&p);
    assert_int_equal(sbd_params_set(&p, "foo=1", err, sizeof err), -1);
    assert_non_null(strstr(err, "foo"));
    assert_int_equal(sbd_params_set(&p, "radius=abc", err, sizeof err), -1);
    assert_int_equal(sbd_params_set(&p, "radius=0x1p-3", err, sizeof err), -1);
    assert_int_equal(sbd_params_set(&p, "radius", err, sizeof err), -1);
    assert_int_equal(sbd_params_set(&p, "arc_steps=2.5", err, sizeof err), -1);
}

/* the STL: seven solids named by region, one facet per triangle */
static void test_stl(void **state)
{
    (void)state;
    sbd_params p;
    sbd_params_default(&p);
    p.cell = 0.05;
    sbd_surface *s = build(&p);
    FILE *f = tmpfile();
    assert_non_null(f);
    char err[256];
    assert_int_equal(sbd_stl_write(s, f, err, sizeof err), 0);
    rewind(f);
    char line[256];
    size_t facets = 0, solids = 0;
    int seen[SBD_NREGION] = { 0 };
    while (fgets(line, sizeof line, f)) {
        if (!strncmp(line, "  facet normal", 14)) facets++;
        if (!strncmp(line, "solid ", 6)) {
            solids++;
            line[strcspn(line, "\n")] = '\0';
            for (int r = 0; r < SBD_NREGION; r++)
                if (!strcmp(line + 6, sbd_region_name(r))) seen[r] = 1;
        }
    }
    fclose(f);
    assert_int_equal(facets, s->nt);
    assert_int_equal(solids, SBD_NREGION);
    for (int r = 0; r < SBD_NREGION; r++) assert_int_equal(seen[r], 1);
    sbd_free(s);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_closed_and_measures),
        cmocka_unit_test(test_volume_converges),
        cmocka_unit_test(test_variants_closed),
        cmocka_unit_test(test_refusals),
        cmocka_unit_test(test_stl),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
