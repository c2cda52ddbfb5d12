/* test_swv.c - cmocka tests of the photo comparison (validation/swv_*). */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "swv_synth.h"

static char tmpdir[256];

static void path_in_tmp(char *buf, size_t len, const char *name)
{
    snprintf(buf, len, "%s/%s", tmpdir, name);
}

/* A known projective map is recovered from 4 points and reproduces other points. */
static void test_homography_known(void **state)
{
    (void)state;
    const double Href[9] = {1.3, 0.2, 10, -0.1, 0.9, 5, 1e-3, -2e-3, 1};
    double src[4][2] = {{0, 0}, {100, 0}, {100, 80}, {0, 80}}, dst[4][2];
    for (int i = 0; i < 4; i++)
        assert_int_equal(swv_homography_apply(Href, src[i][0], src[i][1], &dst[i][0], &dst[i][1]), 0);
    double H[9];
    char err[256];
    assert_int_equal(swv_homography_solve(src, dst, H, err, sizeof err), 0);
    for (int k = 0; k < 9; k++)
        assert_true(fabs(H[k] - Href[k]) < 1e-9 * (1 + fabs(Href[k])));
    for (double x = -20; x <= 120; x += 17)
        for (double y = -10; y <= 90; y += 13) {
            double a, b, c, d;
            swv_homography_apply(Href, x, y, &a, &b);
            swv_homography_apply(H, x, y, &c, &d);
            assert_true(fabs(a - c) < 1e-8 && fabs(b - d) < 1e-8);
        }
}

static void test_homography_degenerate(void **state)
{
    (void)state;
    double src[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    double collinear[4][2] = {{0, 0}, {1, 1}, {2, 2}, {0, 5}};
    double H[9];
    char err[256] = "";
    assert_int_not_equal(swv_homography_solve(src, collinear, H, err, sizeof err), 0);
    assert_non_null(strstr(err, "collinear"));
    double nanpts[4][2] = {{0, 0}, {1, 0}, {1, NAN}, {0, 1}};
    assert_int_not_equal(swv_homography_solve(src, nanpts, H, err, sizeof err), 0);
    assert_non_null(strstr(err, "not finite"));
}

static void test_metrics_counts(void **state)
{
    (void)state;
    swv_metrics m = {.tp = 30, .fp = 10, .fn = 20, .tn = 40};
    swv_metrics_from_counts(&m);
    assert_true(fabs(m.iou - 0.5) < 1e-12);
    assert_true(fabs(m.dice - 2.0 / 3) < 1e-12);
    assert_true(fabs(m.precision - 0.75) < 1e-12);
    assert_true(fabs(m.recall - 0.6) < 1e-12);
    assert_true(fabs(m.photoSnowFraction - 0.5) < 1e-12);
    swv_metrics e = {.tn = 5};
    swv_metrics_from_counts(&e);
    assert_true(e.iou == 1 && e.dice == 1 && e.precision == 1 && e.recall == 1);
}

/* run the whole comparison on a synthetic photo file (PNG or JPEG) */
static void compare_file(const char *photo_name, int jpeg, double ulo, double uhi,
                         double iou, double dice, double prec, double rec, double tol)
{
    char photo_path[512], csv_path[512], err[512];
    path_in_tmp(photo_path, sizeof photo_path, photo_name);
    path_in_tmp(csv_path, sizeof csv_path, "sim.csv");
    swv_image *img = synth_photo(0.5, 0.5);
    assert_non_null(img);
    int rc = jpeg ? swv_image_write_jpeg(photo_path, img, 95, err, sizeof err)
                  : swv_image_write_png(photo_path, img, err, sizeof err);
    assert_int_equal(rc, 0);
    swv_image_free(img);
    assert_int_equal(synth_csv(csv_path, 8, ulo, uhi, 0.5), 0);

    swv_image *photo = NULL;
    assert_int_equal(swv_image_read(photo_path, &photo, err, sizeof err), 0);
    assert_int_equal(photo->width, 640);
    assert_int_equal(photo->height, 480);
    swv_simmap *sim = NULL;
    assert_int_equal(swv_simmap_read(csv_path, &sim, err, sizeof err), 0);
    assert_int_equal(sim->ny, 8);
    assert_int_equal(sim->nz, 8);
    assert_true(fabs(sim->y0 + 0.06) < 1e-9 && fabs(sim->z1 - 0.06) < 1e-9);

    swv_config c;
    swv_config_defaults(&c);
    memcpy(c.corners, synth_corners, sizeof c.corners);
    c.res = 160;
    swv_metrics m;
    swv_image *side = NULL;
    assert_int_equal(swv_compare_run(&c, photo, sim, &m, &side, err, sizeof err), 0);
    print_message("%s u in [%g,%g): IoU %.4f Dice %.4f precision %.4f recall %.4f\n", photo_name,
                  ulo, uhi, m.iou, m.dice, m.precision, m.recall);
    assert_true(fabs(m.iou - iou) < tol);
    assert_true(fabs(m.dice - dice) < tol);
    assert_true(fabs(m.precision - prec) < tol);
    assert_true(fabs(m.recall - rec) < tol);
    assert_true(fabs(m.simThresholdUsed - 0.2) < 1e-12);   /* 10 % of the 2.0 maximum */
    assert_non_null(side);
    assert_int_equal(side->width, 3 * 160 + 16);
    swv_image_free(side);
    swv_image_free(photo);
    swv_simmap_free(sim);
    unlink(photo_path);
    unlink(csv_path);
}

/* photo: top-left quadrant; map: u < 0.75 top half -> TP 0.25, FP 0.125, FN 0 */
static void test_compare_png_overlap(void **state)
{
    (void)state;
    compare_file("photo.png", 0, 0.0, 0.75, 2.0 / 3, 0.8, 2.0 / 3, 1.0, 0.02);
}

/* map: u >= 0.25 top half -> TP 0.125, FP 0.25, FN 0.125: a mirrored map scores low */
static void test_compare_png_shifted(void **state)
{
    (void)state;
    compare_file("photo.png", 0, 0.25, 1.01, 0.25, 0.4, 1.0 / 3, 0.5, 0.02);
}

static void test_compare_jpeg(void **state)
{
    (void)state;
    compare_file("photo.jpg", 1, 0.0, 0.75, 2.0 / 3, 0.8, 2.0 / 3, 1.0, 0.03);
}

static void test_compare_bad_input(void **state)
{
    (void)state;
    swv_image *photo = synth_photo(0.5, 0.5);
    char csv_path[512], err[512] = "";
    path_in_tmp(csv_path, sizeof csv_path, "sim2.csv");
    assert_int_equal(synth_csv(csv_path, 4, 0, 1, 1), 0);
    swv_simmap *sim = NULL;
    assert_int_equal(swv_simmap_read(csv_path, &sim, err, sizeof err), 0);
    swv_config c;
    swv_config_defaults(&c);
    memcpy(c.corners, synth_corners, sizeof c.corners);
    swv_metrics m;
    c.corners[2][0] = 700;   /* outside the 640 px wide photo */
    assert_int_equal(swv_compare_run(&c, photo, sim, &m, NULL, err, sizeof err), 2);
    assert_non_null(strstr(err, "corner 3"));
    memcpy(c.corners, synth_corners, sizeof c.corners);
    c.photoThreshold = 1.5;
    assert_int_equal(swv_compare_run(&c, photo, sim, &m, NULL, err, sizeof err), 2);
    c.photoThreshold = 0.5;
    c.corners[1][0] = 100; c.corners[1][1] = 80;   /* two corners coincide */
    assert_int_not_equal(swv_compare_run(&c, photo, sim, &m, NULL, err, sizeof err), 0);
    swv_simmap_free(sim);
    swv_image_free(photo);
    unlink(csv_path);
}

static void write_text(const char *path, const char *text)
{
    FILE *f = fopen(path, "w");
    assert_non_null(f);
    fputs(text, f);
    fclose(f);
}

static void test_simmap_errors(void **state)
{
    (void)state;
    char p[512], err[512];
    swv_simmap *m = NULL;
    path_in_tmp(p, sizeof p, "bad.csv");
    write_text(p, "y,z,d\n0,0,1\n1,0,1\n0,1,1\n");   /* 3 faces: not a grid */
    assert_int_equal(swv_simmap_read(p, &m, err, sizeof err), 2);
    write_text(p, "y,z,d\n0,0,1\n1,0,nan\n0,1,1\n1,1,1\n");
    assert_int_equal(swv_simmap_read(p, &m, err, sizeof err), 2);
    assert_non_null(strstr(err, ":3:"));
    write_text(p, "y,z,d\n0,0,1\n1,0,-1\n0,1,1\n1,1,1\n");
    assert_int_equal(swv_simmap_read(p, &m, err, sizeof err), 2);
    write_text(p, "y,z,d\n0,0,1\n1;0;1\n");
    assert_int_equal(swv_simmap_read(p, &m, err, sizeof err), 2);
    assert_non_null(strstr(err, "expected"));
    write_text(p, "y,z,d\n0,0,1\n1,0,1\n3,0,1\n0,1,1\n1,1,1\n3,1,1\n");   /* uneven */
    assert_int_equal(swv_simmap_read(p, &m, err, sizeof err), 2);
    assert_non_null(strstr(err, "evenly"));
    assert_null(m);
    unlink(p);
    path_in_tmp(p, sizeof p, "missing.csv");
    assert_int_equal(swv_simmap_read(p, &m, err, sizeof err), 2);
    swv_image *img = NULL;
    path_in_tmp(p, sizeof p, "notimage.png");
    write_text(p, "hello, not an image\n");
    assert_int_equal(swv_image_read(p, &img, err, sizeof err), 2);
    assert_non_null(strstr(err, "neither PNG nor JPEG"));
    unlink(p);
}

/* regions on a 20 x 20 map: snow on the edge band only, then on both sides + centre */
static void test_regions(void **state)
{
    (void)state;
    char p[512], err[512];
    path_in_tmp(p, sizeof p, "regions.csv");
    FILE *f = fopen(p, "w");
    assert_non_null(f);
    fprintf(f, "y,z,d\n");
    for (int iz = 0; iz < 20; iz++)
        for (int iy = 0; iy < 20; iy++) {
            int edge = iy < 2 || iy > 17 || iz < 2 || iz > 17;
            fprintf(f, "%d,%d,%g\n", iy, iz, edge ? 1.0 : 0.0);
        }
    fclose(f);
    swv_simmap *m = NULL;
    assert_int_equal(swv_simmap_read(p, &m, err, sizeof err), 0);
    swv_region_stats s;
    assert_int_equal(swv_regions(m, 0.1, 0.1, 0.3, &s, err, sizeof err), 0);
    assert_int_equal(s.holds[SWV_REGION_EDGES], 1);
    assert_true(fabs(s.covered[SWV_REGION_EDGES] - 1) < 1e-12);
    assert_int_equal(s.holds[SWV_REGION_LEFT], 0);
    assert_int_equal(s.holds[SWV_REGION_RIGHT], 0);
    assert_int_equal(s.holds[SWV_REGION_CENTRE], 0);
    assert_int_equal(s.nfaces[SWV_REGION_EDGES], 400 - 16 * 16);
    /* unit face spacing: region mass = number of faces x value */
    assert_true(fabs(s.mass[SWV_REGION_EDGES] - 144) < 1e-9);
    assert_true(fabs(s.mass[SWV_REGION_LEFT]) < 1e-12);
    /* left side only: faces iy 2..6 (u 0.125 .. 0.325) */
    for (int i = 0; i < 400; i++) {
        int iy = i % 20;
        m->val[i] = (iy >= 2 && iy <= 6) ? 1.0 : 0.0;
    }
    assert_int_equal(swv_regions(m, 0.1, 0.1, 0.3, &s, err, sizeof err), 0);
    assert_int_equal(s.holds[SWV_REGION_LEFT], 1);
    assert_int_equal(s.holds[SWV_REGION_RIGHT], 0);
    assert_int_equal(s.holds[SWV_REGION_CENTRE], 0);
    assert_true(fabs(s.mass[SWV_REGION_LEFT] - 5 * 16) < 1e-9);     /* iy 2..6, iz 2..17 */
    assert_true(fabs(s.mass[SWV_REGION_EDGES] - 5 * 4) < 1e-9);     /* iy 2..6 in the band rows */
    assert_int_equal(swv_regions(m, 0.1, 0.5, 0.3, &s, err, sizeof err), 2);
    swv_simmap_free(m);
    unlink(p);
}

int main(void)
{
    snprintf(tmpdir, sizeof tmpdir, "/tmp/test_swv.XXXXXX");
    if (!mkdtemp(tmpdir))
        return 1;
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_homography_known),
        cmocka_unit_test(test_homography_degenerate),
        cmocka_unit_test(test_metrics_counts),
        cmocka_unit_test(test_compare_png_overlap),
        cmocka_unit_test(test_compare_png_shifted),
        cmocka_unit_test(test_compare_jpeg),
        cmocka_unit_test(test_compare_bad_input),
        cmocka_unit_test(test_simmap_errors),
        cmocka_unit_test(test_regions),
    };
    int rc = cmocka_run_group_tests(tests, NULL, NULL);
    rmdir(tmpdir);
    return rc;
}
