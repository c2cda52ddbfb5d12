/* test_sbd_snow.c - the snow statistics of snowbody snow-post (sbd_snow.h):
 * the stick records read and refused, the window's mass, its halves and its
 * sampling variance grouped by origin (checked against the spread of many
 * simulated runs, where the per-stick variance is shown to fail), the map's
 * bins, and the resolution ladder read, refused and its mesh error. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <cmocka.h>

#include "sbd_snow.h"

#include <gsl/gsl_randist.h>
#include <gsl/gsl_rng.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

/* |a - b| <= tol in double precision (cmocka 1.1's float comparison rounds to float) */
#define assert_close(a, b, tol)                                                                  \
    do {                                                                                         \
        const double a_ = (a), b_ = (b);                                                         \
        if (!(fabs(a_ - b_) <= (tol)))                                                           \
            fail_msg("%s = %.17g, expected %.17g (tolerance %g)", #a, a_, b_, (double)(tol));     \
    } while (0)

static char *write_tmp(const char *text)
{
    static char path[64];
    snprintf(path, sizeof path, "/tmp/test_sbd_snow.XXXXXX");
    int fd = mkstemp(path);
    assert_true(fd >= 0);
    FILE *f = fdopen(fd, "w");
    assert_non_null(f);
    fputs(text, f);
    assert_int_equal(fclose(f), 0);
    return path;
}

static const char *hdr = "# Time (position0 position1 position2) origProc origId nParticle d rho\n";

static void records_read(void **state)
{
    (void)state;
    char text[1024];
    snprintf(text, sizeof text, "%s0.35 1.044 0.01 0.25 0 7 1000 2e-05 920\n\n0.4 1.044 0.02 0.26 1 7 10 1e-4 920\n",
             hdr);
    char *p = write_tmp(text);
    sbd_sticks st = {0};
    char err[512] = "";
    assert_int_equal(sbd_sticks_read(&st, p, err, sizeof err), 0);
    assert_int_equal(st.n, 2);
    assert_close(st.s[0].t, 0.35, 0);
    assert_close(st.s[0].x[1], 0.01, 0);
    assert_int_equal(st.s[1].proc, 1);
    assert_int_equal(st.s[1].id, 7);
    /* nParticle rho pi d^3 / 6 */
    assert_close(st.s[0].mass, 1000 * 920 * M_PI * 8e-15 / 6, 1e-25);
    assert_close(st.s[1].mass, 10 * 920 * M_PI * 1e-12 / 6, 1e-22);
    /* a second file appends; a header-only file adds nothing */
    assert_int_equal(sbd_sticks_read(&st, p, err, sizeof err), 0);
    assert_int_equal(st.n, 4);
    unlink(p);
    p = write_tmp(hdr);
    assert_int_equal(sbd_sticks_read(&st, p, err, sizeof err), 0);
    assert_int_equal(st.n, 4);
    unlink(p);
    sbd_sticks_free(&st);
    assert_null(st.s);
}

static void records_refused(void **state)
{
    (void)state;
    const char *bad[][2] = {
        {"0.35 1 2 3 0 7 1000 2e-05 920\n", "before the header"},
        {"# Time (position0 position1 position2) origProc nParticle d rho\n", "no column 'origId'"},
        {"#HDR#0.35 1 2 3 0 7 1000 2e-05\n", "8 values, the header names 9"},
        {"#HDR#0.35 1 2 nan 0 7 1000 2e-05 920\n", "position2 'nan' is not a finite number"},
        {"#HDR#0.35 1 2 3 0 7 1000 -2e-05 920\n", "a negative nParticle, d or rho"},
        {"#HDR#0.35 1 2 3 0 7 1e999 2e-05 920\n", "nParticle '1e999' is not a finite number"},
        {"", "no header line"},
    };
    for (size_t k = 0; k < sizeof bad / sizeof *bad; k++) {
        char text[1024] = "";
        const char *b = bad[k][0];
        if (!strncmp(b, "#HDR#", 5)) {
            snprintf(text, sizeof text, "%s%s", hdr, b + 5);
        } else {
            snprintf(text, sizeof text, "%s", b);
        }
        char *p = write_tmp(text);
        sbd_sticks st = {0};
        char err[512] = "";
        assert_int_equal(sbd_sticks_read(&st, p, err, sizeof err), -1);
        if (!strstr(err, bad[k][1]) || !strstr(err, p))
            fail_msg("case %zu: '%s' does not name the file and '%s'", k, err, bad[k][1]);
        unlink(p);
        sbd_sticks_free(&st);
    }
    sbd_sticks st = {0};
    char err[512] = "";
    assert_int_equal(sbd_sticks_read(&st, "/nonexistent/x.post", err, sizeof err), -1);
    assert_non_null(strstr(err, "/nonexistent/x.post"));
}

static sbd_stick stick(double t, long proc, long id, double mass)
{
    sbd_stick s = {.t = t, .proc = proc, .id = id, .mass = mass};
    return s;
}

static void window_by_origin(void **state)
{
    (void)state;
    /* origin (0,1): 1 + 2 kg in the first half, 3 kg in the second; (0,2): 4 kg in the
       second; (1,1): 5 kg outside the window (before), (1,2) 6 kg at t1 exactly (inside) */
    sbd_stick s[] = {stick(0.31, 0, 1, 1), stick(0.35, 0, 1, 2), stick(0.5, 0, 1, 3), stick(0.55, 0, 2, 4),
                     stick(0.3, 1, 1, 5), stick(0.6, 1, 2, 6)};
    sbd_window_stat w;
    assert_int_equal(sbd_window(s, 6, 0.3, 0.6, &w), 0);
    assert_int_equal(w.sticks, 5);
    assert_int_equal(w.origins, 3);
    assert_close(w.mass, 16, 1e-12);
    assert_close(w.var, 36 + 16 + 36, 1e-12);
    assert_close(w.half[0], 3, 1e-12);
    assert_close(w.half[1], 13, 1e-12);
    assert_close(w.half_var[0], 9, 1e-12);
    assert_close(w.half_var[1], 9 + 16 + 36, 1e-12);
    assert_close(sbd_halves_z(&w), 10 / sqrt(70), 1e-12);
    /* empty windows and bad arguments */
    assert_int_equal(sbd_window(s, 0, 0.3, 0.6, &w), 0);
    assert_int_equal(w.sticks, 0);
    assert_close(sbd_halves_z(&w), 0, 0);
    assert_int_equal(sbd_window(s, 6, 0.6, 0.6, &w), -1);
}

/* Many simulated runs: N injected parcels each reach the wall with probability
 * P; one that does is split into a Poisson number of copies (mean 20) that all
 * stick, sharing its mass. The grouped variance estimate averaged over the runs
 * must match the runs' spread of the mass (within 10 %, 2000 runs); a per-stick
 * estimate (the sum of the sticks' squared masses) must fall far short (the
 * copies are correlated), which is why the sticks are grouped. */
static void variance_against_simulation(void **state)
{
    (void)state;
    gsl_rng *r = gsl_rng_alloc(gsl_rng_mt19937);
    gsl_rng_set(r, 12345);
    const int runs = 2000, N = 4000;
    const double P = 0.01, m0 = 1e-6;
    double sum = 0, sum2 = 0, est = 0, naive = 0;
    sbd_stick *s = malloc(200000 * sizeof *s);
    assert_non_null(s);
    for (int k = 0; k < runs; k++) {
        size_t n = 0;
        for (long id = 0; id < N; id++) {
            if (gsl_rng_uniform(r) >= P)
                continue;
            unsigned c = 1 + gsl_ran_poisson(r, 19);
            double t = 0.3 + 0.3 * gsl_rng_uniform_pos(r);
            for (unsigned j = 0; j < c && n < 200000; j++)
                s[n++] = stick(t, 0, id, m0 / c);
        }
        sbd_window_stat w;
        assert_int_equal(sbd_window(s, n, 0.3, 0.6, &w), 0);
        sum += w.mass;
        sum2 += w.mass * w.mass;
        est += w.var;
        double nv = 0;
        for (size_t i = 0; i < n; i++)
            nv += s[i].mass * s[i].mass;
        naive += nv;
    }
    free(s);
    gsl_rng_free(r);
    const double mean = sum / runs, var = sum2 / runs - mean * mean;
    est /= runs;
    naive /= runs;
    assert_close(mean, N * P * m0, 0.02 * N * P * m0);
    if (fabs(est / var - 1) > 0.1)
        fail_msg("grouped variance %g against the runs' %g", est, var);
    if (naive / var > 0.2)
        fail_msg("the per-stick variance %g should fall far below the runs' %g", naive, var);
}

static void map_bins(void **state)
{
    (void)state;
    sbd_stick s[4] = {0};
    double pos[4][3] = {{1, 0.05, 0.1}, {1, 0.0, 0.0}, {1, 0.2, 0.2}, {1, 0.3, 0.1}};
    for (int k = 0; k < 4; k++) {
        s[k] = stick(0.5, 0, k, 2);
        memcpy(s[k].x, pos[k], sizeof pos[k]);
    }
    s[2].t = 0.1;   /* outside the window: not counted, not outside */
    double map[4];
    size_t out = 0;
    assert_int_equal(sbd_map(s, 4, 0.3, 0.6, 1, 2, 0, 0.2, 2, 0, 0.2, 2, map, &out), 0);
    assert_int_equal(out, 1);   /* y 0.3 */
    const double area = 0.1 * 0.1;
    assert_close(map[0], 2 / area, 1e-9);   /* (0, 0): the corner */
    assert_close(map[1], 0, 0);
    assert_close(map[2], 2 / area, 1e-9);   /* y 0.05, z 0.1: the edge of the upper row */
    assert_close(map[3], 0, 0);
    assert_int_equal(sbd_map(s, 4, 0.3, 0.6, 1, 1, 0, 0.2, 2, 0, 0.2, 2, map, &out), -1);
    assert_int_equal(sbd_map(s, 4, 0.3, 0.6, 1, 2, 0.2, 0.2, 2, 0, 0.2, 2, map, &out), -1);
}

static const char *lhdr = "level,cells,seconds,rear_kg_m2,rear_rel,sensor_kg_m2,sensor_rel\n";

static void ladder(void **state)
{
    (void)state;
    char text[1024];
    snprintf(text, sizeof text, "# measured\n%scoarse,100,60,2,0.1,4,0.2\nmedium,200,120,1.6,0.1,5,0.2\n"
                                "fine,400,300,1.5,0.05,5.5,0.1\n", lhdr);
    char *p = write_tmp(text);
    sbd_ladder l;
    char err[512] = "";
    assert_int_equal(sbd_ladder_read(p, &l, err, sizeof err), 0);
    unlink(p);
    assert_int_equal(l.n, 3);
    assert_int_equal(sbd_ladder_find(&l, "medium"), 1);
    assert_int_equal(sbd_ladder_find(&l, "test"), -1);
    /* the errors by the ladders' one rule (swg_discretization). The rear face 2, 1.6,
       1.5 (coarse to fine, se 0.2, 0.16, 0.075): its steps within the noise, so a bound
       over the finest value 1.5 (+- 0.1) and the extrapolation with order 2 over the
       ratio r = 2^(1/3), 1.5 - 0.1 / (r^2 - 1) (+- that step); the reference the
       smaller, every level's error the larger of the two readings' */
    sbd_ladder_error e;
    assert_int_equal(sbd_ladder_disc(&l, 0, &e, err, sizeof err), 0);
    assert_string_equal(e.kind, "bound");
    const double c = pow(2.0, 2.0 / 3.0) - 1.0, rb = 1.5 - 0.1 / c, ub = 0.1 / c;
    assert_close(e.ref, rb, 1e-12);
    assert_close(e.disc[2], fmax(0.1, hypot(1.5 - rb, ub)) / rb, 1e-12);
    assert_close(e.disc[1], fmax(hypot(0.1, 0.1), hypot(1.6 - rb, ub)) / rb, 1e-12);
    assert_close(e.disc[0], fmax(hypot(0.5, 0.1), hypot(2.0 - rb, ub)) / rb, 1e-12);
    for (int k = 0; k < 3; k++) {
        assert_close(e.sampling[k], l.row[k].rel[0] * l.row[k].value[0] / rb, 1e-12);
        /* the total is never below a component */
        assert_close(e.total[k], hypot(e.sampling[k], e.disc[k]), 1e-12);
        assert_true(e.total[k] >= e.disc[k] && e.total[k] >= e.sampling[k]);
    }
    /* a quantity of the wrong index is refused */
    assert_int_equal(sbd_ladder_disc(&l, 2, &e, err, sizeof err), -1);

    const char *bad[][2] = {
        {"level,cells\ncoarse,1\n", "the header must be"},
        {"#H#coarse,100,60,2,0.1,4,0.2\n", "at least 2"},
        {"#H#coarse,100,60,2,0.1,4,0.2\nfine,100,60,2,0.1,4,0.2\n", "above the previous"},
        {"#H#coarse,100,60,2,0.1,4,0.2\nfine,200,60,nan,0.1,4,0.2\n", "'nan' is not a positive"},
        {"#H#coarse,100,60,2,0.1,4,0.2\nfine,200,60,2,0.1,4\n", "6 fields"},
        {"#H#Coarse Level,100,60,2,0.1,4,0.2\nfine,200,60,2,0.1,4,0.2\n", "is not a word"},
        {"#H#coarse,100,60,2,0.1,4,0.2\ncoarse,200,60,2,0.1,4,0.2\n", "given twice"},
        {"#H#coarse,100,60,2,0.1,4,0.2\nfine,200,60,0,0.1,4,0.2\n", "is not a positive"},
    };
    for (size_t k = 0; k < sizeof bad / sizeof *bad; k++) {
        const char *b = bad[k][0];
        if (!strncmp(b, "#H#", 3))
            snprintf(text, sizeof text, "%s%s", lhdr, b + 3);
        else
            snprintf(text, sizeof text, "%s", b);
        p = write_tmp(text);
        assert_int_equal(sbd_ladder_read(p, &l, err, sizeof err), -1);
        if (!strstr(err, bad[k][1]) || !strstr(err, p))
            fail_msg("ladder case %zu: '%s' does not name the file and '%s'", k, err, bad[k][1]);
        unlink(p);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(records_read),
        cmocka_unit_test(records_refused),
        cmocka_unit_test(window_by_origin),
        cmocka_unit_test(variance_against_simulation),
        cmocka_unit_test(map_bins),
        cmocka_unit_test(ladder),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
