/* test_swi.c - cmocka tests of the photo comparison (tools/snowphoto/swi_*). */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "swi_synth.h"
#include <jpeglib.h>   /* after stdio.h (swi_synth.h): the many-scans JPEG */

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
        assert_int_equal(swi_homography_apply(Href, src[i][0], src[i][1], &dst[i][0], &dst[i][1]), 0);
    double H[9];
    char err[256];
    assert_int_equal(swi_homography_solve(src, dst, H, err, sizeof err), 0);
    for (int k = 0; k < 9; k++)
        assert_true(fabs(H[k] - Href[k]) < 1e-9 * (1 + fabs(Href[k])));
    for (double x = -20; x <= 120; x += 17)
        for (double y = -10; y <= 90; y += 13) {
            double a, b, c, d;
            swi_homography_apply(Href, x, y, &a, &b);
            swi_homography_apply(H, x, y, &c, &d);
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
    assert_int_not_equal(swi_homography_solve(src, collinear, H, err, sizeof err), 0);
    assert_non_null(strstr(err, "collinear"));
    double nanpts[4][2] = {{0, 0}, {1, 0}, {1, NAN}, {0, 1}};
    assert_int_not_equal(swi_homography_solve(src, nanpts, H, err, sizeof err), 0);
    assert_non_null(strstr(err, "not finite"));
}

static void test_metrics_counts(void **state)
{
    (void)state;
    swi_metrics m = {.tp = 30, .fp = 10, .fn = 20, .tn = 40};
    swi_metrics_from_counts(&m);
    assert_true(fabs(m.iou - 0.5) < 1e-12);
    assert_true(fabs(m.dice - 2.0 / 3) < 1e-12);
    assert_true(fabs(m.precision - 0.75) < 1e-12);
    assert_true(fabs(m.recall - 0.6) < 1e-12);
    assert_true(fabs(m.photoSnowFraction - 0.5) < 1e-12);
    swi_metrics e = {.tn = 5};
    swi_metrics_from_counts(&e);
    assert_true(e.iou == 1 && e.dice == 1 && e.precision == 1 && e.recall == 1);
}

/* run the whole comparison on a synthetic photo file (PNG or JPEG) */
static void compare_file(const char *photo_name, int jpeg, double ulo, double uhi,
                         double iou, double dice, double prec, double rec, double tol)
{
    char photo_path[512], csv_path[512], err[512];
    path_in_tmp(photo_path, sizeof photo_path, photo_name);
    path_in_tmp(csv_path, sizeof csv_path, "sim.csv");
    swi_image *img = synth_photo(0.5, 0.5);
    assert_non_null(img);
    int rc = jpeg ? swi_image_write_jpeg(photo_path, img, 95, err, sizeof err)
                  : swi_image_write_png(photo_path, img, err, sizeof err);
    assert_int_equal(rc, 0);
    swi_image_free(img);
    assert_int_equal(synth_csv(csv_path, 8, ulo, uhi, 0.5), 0);

    swi_image *photo = NULL;
    assert_int_equal(swi_image_read(photo_path, &photo, err, sizeof err), 0);
    assert_int_equal(photo->width, 640);
    assert_int_equal(photo->height, 480);
    swi_simmap *sim = NULL;
    assert_int_equal(swi_simmap_read(csv_path, &sim, err, sizeof err), 0);
    assert_int_equal(sim->ny, 8);
    assert_int_equal(sim->nz, 8);
    assert_true(fabs(sim->y0 + 0.06) < 1e-9 && fabs(sim->z1 - 0.06) < 1e-9);

    swi_config c;
    swi_config_defaults(&c);
    memcpy(c.corners, synth_corners, sizeof c.corners);
    c.res = 160;
    swi_metrics m;
    swi_image *side = NULL;
    assert_int_equal(swi_compare_run(&c, photo, sim, &m, &side, err, sizeof err), 0);
    print_message("%s u in [%g,%g): IoU %.4f Dice %.4f precision %.4f recall %.4f\n", photo_name,
                  ulo, uhi, m.iou, m.dice, m.precision, m.recall);
    assert_true(fabs(m.iou - iou) < tol);
    assert_true(fabs(m.dice - dice) < tol);
    assert_true(fabs(m.precision - prec) < tol);
    assert_true(fabs(m.recall - rec) < tol);
    assert_true(fabs(m.simThresholdUsed - 0.2) < 1e-12);   /* 10 % of the 2.0 maximum */
    assert_non_null(side);
    assert_int_equal(side->width, 3 * 160 + 16);
    swi_image_free(side);
    swi_image_free(photo);
    swi_simmap_free(sim);
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
    swi_image *photo = synth_photo(0.5, 0.5);
    char csv_path[512], err[512] = "";
    path_in_tmp(csv_path, sizeof csv_path, "sim2.csv");
    assert_int_equal(synth_csv(csv_path, 4, 0, 1, 1), 0);
    swi_simmap *sim = NULL;
    assert_int_equal(swi_simmap_read(csv_path, &sim, err, sizeof err), 0);
    swi_config c;
    swi_config_defaults(&c);
    memcpy(c.corners, synth_corners, sizeof c.corners);
    swi_metrics m;
    c.corners[2][0] = 700;   /* outside the 640 px wide photo */
    assert_int_equal(swi_compare_run(&c, photo, sim, &m, NULL, err, sizeof err), 2);
    assert_non_null(strstr(err, "corner 3"));
    memcpy(c.corners, synth_corners, sizeof c.corners);
    c.photoThreshold = 1.5;
    assert_int_equal(swi_compare_run(&c, photo, sim, &m, NULL, err, sizeof err), 2);
    c.photoThreshold = 0.5;
    c.corners[1][0] = 100; c.corners[1][1] = 80;   /* two corners coincide */
    assert_int_not_equal(swi_compare_run(&c, photo, sim, &m, NULL, err, sizeof err), 0);
    swi_simmap_free(sim);
    swi_image_free(photo);
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
    swi_simmap *m = NULL;
    path_in_tmp(p, sizeof p, "bad.csv");
    write_text(p, "y,z,d\n0,0,1\n1,0,1\n0,1,1\n");   /* 3 faces: not a grid */
    assert_int_equal(swi_simmap_read(p, &m, err, sizeof err), 2);
    write_text(p, "y,z,d\n0,0,1\n1,0,nan\n0,1,1\n1,1,1\n");
    assert_int_equal(swi_simmap_read(p, &m, err, sizeof err), 2);
    assert_non_null(strstr(err, ":3:"));
    write_text(p, "y,z,d\n0,0,1\n1,0,-1\n0,1,1\n1,1,1\n");
    assert_int_equal(swi_simmap_read(p, &m, err, sizeof err), 2);
    write_text(p, "y,z,d\n0,0,1\n1;0;1\n");
    assert_int_equal(swi_simmap_read(p, &m, err, sizeof err), 2);
    assert_non_null(strstr(err, "expected"));
    write_text(p, "y,z,d\n0,0,1\n1,0,1\n3,0,1\n0,1,1\n1,1,1\n3,1,1\n");   /* uneven */
    assert_int_equal(swi_simmap_read(p, &m, err, sizeof err), 2);
    assert_non_null(strstr(err, "evenly"));
    assert_null(m);
    unlink(p);
    path_in_tmp(p, sizeof p, "missing.csv");
    assert_int_equal(swi_simmap_read(p, &m, err, sizeof err), 2);
    swi_image *img = NULL;
    path_in_tmp(p, sizeof p, "notimage.png");
    write_text(p, "hello, not an image\n");
    assert_int_equal(swi_image_read(p, &img, err, sizeof err), 2);
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
    swi_simmap *m = NULL;
    assert_int_equal(swi_simmap_read(p, &m, err, sizeof err), 0);
    swi_region_stats s;
    assert_int_equal(swi_regions(m, 0.1, 0.1, 0.3, &s, err, sizeof err), 0);
    assert_int_equal(s.holds[SWI_REGION_EDGES], 1);
    assert_true(fabs(s.covered[SWI_REGION_EDGES] - 1) < 1e-12);
    assert_int_equal(s.holds[SWI_REGION_LEFT], 0);
    assert_int_equal(s.holds[SWI_REGION_RIGHT], 0);
    assert_int_equal(s.holds[SWI_REGION_CENTRE], 0);
    assert_int_equal(s.nfaces[SWI_REGION_EDGES], 400 - 16 * 16);
    /* unit face spacing: region mass = number of faces x value */
    assert_true(fabs(s.mass[SWI_REGION_EDGES] - 144) < 1e-9);
    assert_true(fabs(s.mass[SWI_REGION_LEFT]) < 1e-12);
    /* left side only: faces iy 2..6 (u 0.125 .. 0.325) */
    for (int i = 0; i < 400; i++) {
        int iy = i % 20;
        m->val[i] = (iy >= 2 && iy <= 6) ? 1.0 : 0.0;
    }
    assert_int_equal(swi_regions(m, 0.1, 0.1, 0.3, &s, err, sizeof err), 0);
    assert_int_equal(s.holds[SWI_REGION_LEFT], 1);
    assert_int_equal(s.holds[SWI_REGION_RIGHT], 0);
    assert_int_equal(s.holds[SWI_REGION_CENTRE], 0);
    assert_true(fabs(s.mass[SWI_REGION_LEFT] - 5 * 16) < 1e-9);     /* iy 2..6, iz 2..17 */
    assert_true(fabs(s.mass[SWI_REGION_EDGES] - 5 * 4) < 1e-9);     /* iy 2..6 in the band rows */
    assert_int_equal(swi_regions(m, 0.1, 0.5, 0.3, &s, err, sizeof err), 2);
    swi_simmap_free(m);
    unlink(p);
}

static double now_s(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

/* the size limits, at their edges */
static void test_image_size_check(void **state)
{
    (void)state;
    char err[512] = "";
    assert_int_equal(swi_image_check_size("a", "PNG", 10000, 10000, err, sizeof err), 0);
    assert_int_equal(swi_image_check_size("a", "PNG", 30000, 3333, err, sizeof err), 0);
    assert_int_equal(swi_image_check_size("a", "PNG", 1, 30000, err, sizeof err), 0);
    assert_int_equal(swi_image_check_size("a", "PNG", 30001, 1, err, sizeof err), 2);
    assert_int_equal(swi_image_check_size("a", "PNG", 1, 30001, err, sizeof err), 2);
    assert_int_equal(swi_image_check_size("a", "PNG", 10001, 10000, err, sizeof err), 2);
    assert_int_equal(swi_image_check_size("a", "PNG", 0, 5, err, sizeof err), 2);
    assert_int_equal(swi_image_check_size("x.jpg", "JPEG", 4294967295UL, 4294967295UL, err,
                                          sizeof err), 2);
    assert_non_null(strstr(err, "x.jpg: JPEG header claims 4294967295 x 4294967295 pixels"));
    assert_null(swi_image_alloc(30001, 1));
    assert_null(swi_image_alloc(10001, 10000));
}

/* read a file both ways (path and bytes in memory); both must agree */
static int read_both(const char *path, swi_image **img, char *err, size_t errlen)
{
    int rc = swi_image_read(path, img, err, errlen);
    size_t n = 0;
    unsigned char *b = synth_slurp(path, &n);
    assert_non_null(b);
    swi_image *m = NULL;
    char err2[512] = "";
    int rc2 = swi_image_read_mem(b, n, path, &m, err2, sizeof err2);
    free(b);
    assert_int_equal(rc, rc2);
    if (rc) {
        assert_null(*img);
        assert_null(m);
        assert_string_equal(err, err2);
    } else {
        assert_int_equal(m->width, (*img)->width);
        assert_int_equal(m->height, (*img)->height);
        assert_memory_equal(m->rgb, (*img)->rgb, (size_t)m->width * (size_t)m->height * 3u);
    }
    swi_image_free(m);
    return rc;
}

/* a small file claiming a huge size is refused from its header, at once */
static void test_image_huge_header(void **state)
{
    (void)state;
    char p[512], err[512] = "";
    swi_image *img = NULL;
    path_in_tmp(p, sizeof p, "huge.jpg");
    assert_int_equal(synth_jpeg_claiming(p, 96, 96, 60000, 60000), 0);
    double t0 = now_s();
    assert_int_equal(read_both(p, &img, err, sizeof err), 2);
    print_message("%s (%.3f s)\n", err, now_s() - t0);
    assert_true(now_s() - t0 < 1);
    assert_non_null(strstr(err, "huge.jpg: JPEG header claims 60000 x 60000 pixels"));
    unlink(p);
    path_in_tmp(p, sizeof p, "huge.png");
    assert_int_equal(synth_png_claiming(p, 20000, 20000), 0);
    assert_int_equal(read_both(p, &img, err, sizeof err), 2);
    assert_non_null(strstr(err, "huge.png: PNG header claims 20000 x 20000 pixels"));
    assert_int_equal(synth_png_claiming(p, 1, 30001), 0);
    assert_int_equal(read_both(p, &img, err, sizeof err), 2);
    assert_non_null(strstr(err, "1 x 30001"));
    unlink(p);
    /* within the limits but with the data of a 96 x 96 / 1 x 1 image: the decoder's
     * complaint (a libjpeg warning, a libpng error) ends it */
    path_in_tmp(p, sizeof p, "big.jpg");
    assert_int_equal(synth_jpeg_claiming(p, 96, 96, 29000, 3400), 0);
    assert_int_equal(read_both(p, &img, err, sizeof err), 2);
    print_message("%s\n", err);
    assert_non_null(strstr(err, "JPEG decoding failed"));
    unlink(p);
    path_in_tmp(p, sizeof p, "big.png");
    assert_int_equal(synth_png_claiming(p, 10000, 10000), 0);
    assert_int_equal(read_both(p, &img, err, sizeof err), 2);
    assert_non_null(strstr(err, "PNG decoding failed"));
    /* the patched 1 x 1 file itself still reads */
    assert_int_equal(synth_png_claiming(p, 1, 1), 0);
    assert_int_equal(read_both(p, &img, err, sizeof err), 0);
    swi_image_free(img);
    unlink(p);
}

/* a truncated JPEG is refused, named (libjpeg alone decodes it: a grey rest and a
 * warning on stderr) */
static void test_image_truncated(void **state)
{
    (void)state;
    char p[512], q[512], err[512] = "";
    swi_image *img = synth_photo(0.5, 0.5), *back = NULL;
    path_in_tmp(p, sizeof p, "full.jpg");
    path_in_tmp(q, sizeof q, "half.jpg");
    assert_int_equal(swi_image_write_jpeg(p, img, 95, err, sizeof err), 0);
    assert_int_equal(read_both(p, &back, err, sizeof err), 0);
    swi_image_free(back);
    assert_int_equal(synth_truncate(p, q, 0.5), 0);
    assert_int_equal(read_both(q, &back, err, sizeof err), 2);
    print_message("%s\n", err);
    assert_non_null(strstr(err, "half.jpg: JPEG decoding failed (Premature end of JPEG file)"));
    /* corrupt entropy-coded data (bytes overwritten in the middle): a warning -> error */
    size_t n = 0;
    unsigned char *b = synth_slurp(p, &n);
    assert_non_null(b);
    for (size_t i = n / 2; i < n / 2 + 64; i++)
        b[i] = (unsigned char)(i * 37);
    assert_int_equal(swi_image_read_mem(b, n, "corrupt.jpg", &back, err, sizeof err), 2);
    print_message("%s\n", err);
    assert_non_null(strstr(err, "corrupt.jpg: JPEG decoding failed"));
    free(b);
    unlink(p);
    unlink(q);
    path_in_tmp(p, sizeof p, "full.png");
    path_in_tmp(q, sizeof q, "half.png");
    assert_int_equal(swi_image_write_png(p, img, err, sizeof err), 0);
    assert_int_equal(synth_truncate(p, q, 0.5), 0);
    assert_int_equal(read_both(q, &back, err, sizeof err), 2);
    print_message("%s\n", err);
    assert_non_null(strstr(err, "half.png: PNG decoding failed"));
    assert_non_null(strstr(err, "truncated"));
    assert_int_equal(synth_truncate(p, q, 0.9), 0);
    assert_int_equal(read_both(q, &back, err, sizeof err), 2);
    /* cut inside the signature / empty */
    assert_int_equal(synth_truncate(p, q, 0.0), 0);
    assert_int_equal(read_both(q, &back, err, sizeof err), 2);
    assert_non_null(strstr(err, "half.png: empty file"));
    assert_int_equal(synth_truncate(p, q, 0.002), 0);   /* 5 bytes of the signature */
    assert_int_equal(read_both(q, &back, err, sizeof err), 2);
    assert_non_null(strstr(err, "neither PNG nor JPEG"));
    assert_int_equal(swi_image_read_mem(NULL, 0, NULL, &back, err, sizeof err), 2);
    assert_non_null(strstr(err, "(memory)"));
    swi_image_free(img);
    unlink(p);
    unlink(q);
}

/* A 3-component progressive JPEG with 2090 scans (every AC coefficient of every
 * component alone, then refined bit by bit): more than SWI_JPEG_MAX_SCANS. */
static void write_many_scans_jpeg(const char *path)
{
    enum { AL = 10 };
    static jpeg_scan_info scans[11 + 3 * 63 * 11];
    int k = 0;
    for (int al = AL; al >= 0; al--, k++) {    /* DC, interleaved, then refinements */
        scans[k].comps_in_scan = 3;
        for (int c = 0; c < 3; c++) scans[k].component_index[c] = c;
        scans[k].Ss = scans[k].Se = 0;
        scans[k].Ah = al == AL ? 0 : al + 1;
        scans[k].Al = al;
    }
    for (int c = 0; c < 3; c++)
        for (int s = 1; s < 64; s++)
            for (int al = AL; al >= 0; al--, k++) {
                scans[k].comps_in_scan = 1;
                scans[k].component_index[0] = c;
                scans[k].Ss = scans[k].Se = s;
                scans[k].Ah = al == AL ? 0 : al + 1;
                scans[k].Al = al;
            }
    FILE *f = fopen(path, "wb");
    assert_non_null(f);
    struct jpeg_compress_struct ci;
    struct jpeg_error_mgr je;
    ci.err = jpeg_std_error(&je);
    jpeg_create_compress(&ci);
    jpeg_stdio_dest(&ci, f);
    ci.image_width = ci.image_height = 16;
    ci.input_components = 3;
    ci.in_color_space = JCS_RGB;
    jpeg_set_defaults(&ci);
    ci.scan_info = scans;
    ci.num_scans = k;
    jpeg_start_compress(&ci, TRUE);
    swi_image *img = synth_noise(16, 16);
    assert_non_null(img);
    while (ci.next_scanline < ci.image_height) {
        JSAMPROW row = img->rgb + (size_t)ci.next_scanline * 48u;
        jpeg_write_scanlines(&ci, &row, 1);
    }
    jpeg_finish_compress(&ci);
    jpeg_destroy_compress(&ci);
    fclose(f);
    swi_image_free(img);
}

static void test_image_many_scans(void **state)
{
    (void)state;
    char p[512], err[512] = "";
    path_in_tmp(p, sizeof p, "scans.jpg");
    write_many_scans_jpeg(p);
    swi_image *img = NULL;
    assert_int_equal(read_both(p, &img, err, sizeof err), 2);
    print_message("%s\n", err);
    assert_non_null(strstr(err, "more than 1000 scans"));
    unlink(p);
}

/* corner sets: the face accepted; bow-tie, concave, mirrored, collinear and
 * sub-pixel ones refused, named */
static void test_corners(void **state)
{
    (void)state;
    char err[512] = "";
    assert_int_equal(swi_corners_check(synth_corners, 640, 480, err, sizeof err), 0);
    struct { double c[4][2]; const char *text; } bad[] = {
        {{{100, 80}, {540, 60}, {300, 150}, {60, 400}}, "concave at corner 3 (bottom-right"},
        {{{100, 80}, {540, 60}, {580, 420}, {200, 100}}, "concave at corner 4 (bottom-left"},
        {{{100, 80}, {540, 60}, {60, 400}, {580, 420}}, "side from corner 2 to 3 crosses the side from corner 4 to 1 (a bow-tie)"},
        {{{100, 80}, {580, 420}, {540, 60}, {60, 400}}, "side from corner 1 to 2 crosses the side from corner 3 to 4 (a bow-tie)"},
        {{{100, 80}, {60, 400}, {580, 420}, {540, 60}}, "counter-clockwise"},
        {{{100, 80}, {100.5, 80}, {100.5, 80.5}, {100, 80.5}}, "covers 0.25 px^2 and is 0.5 px wide"},
        {{{100, 80}, {540, 60}, {540, 65}, {100, 85}}, "px wide"},           /* 2200 px^2 but 5 px wide */
        {{{100, 80}, {105, 80}, {105, 85}, {100, 85}}, "covers 25 px^2"},    /* 5 x 5 px */
        {{{100, 80}, {100, 80}, {580, 420}, {60, 400}}, "on one line or coincide"},
        {{{100, 80}, {300, 80}, {500, 80}, {60, 400}}, "corners 1, 2, 3 (top-left, top-right, bottom-right) lie on one line"},
        {{{100, 80}, {540, 60}, {580, 420}, {60, 500}}, "corner 4 (bottom-left, 60,500) lies outside the 640x480"},
        {{{100, 80}, {540, NAN}, {580, 420}, {60, 400}}, "corner 2 (top-right, 540,nan) is not a finite point"},
    };
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        err[0] = '\0';
        assert_int_equal(swi_corners_check((const double(*)[2])bad[i].c, 640, 480, err, sizeof err), 2);
        print_message("%s\n", err);
        assert_non_null(strstr(err, bad[i].text));
    }
    /* the limits themselves: a 10 x 10 square passes, 9.9 x 20 does not */
    const double sq[4][2] = {{0, 0}, {10, 0}, {10, 10}, {0, 10}};
    assert_int_equal(swi_corners_check(sq, 640, 480, err, sizeof err), 0);
    const double thin[4][2] = {{0, 0}, {20, 0}, {20, 9.9}, {0, 9.9}};
    assert_int_equal(swi_corners_check(thin, 640, 480, err, sizeof err), 2);
    /* the comparison runs the same check first */
    swi_image *photo = synth_photo(0.5, 0.5);
    char csv[512];
    path_in_tmp(csv, sizeof csv, "c.csv");
    assert_int_equal(synth_csv(csv, 4, 0, 1, 1), 0);
    swi_simmap *sim = NULL;
    assert_int_equal(swi_simmap_read(csv, &sim, err, sizeof err), 0);
    swi_config c;
    swi_config_defaults(&c);
    memcpy(c.corners, bad[2].c, sizeof c.corners);
    swi_metrics m;
    assert_int_equal(swi_compare_run(&c, photo, sim, &m, NULL, err, sizeof err), 2);
    assert_non_null(strstr(err, "bow-tie"));
    swi_simmap_free(sim);
    swi_image_free(photo);
    unlink(csv);
}

static void test_md_cell(void **state)
{
    (void)state;
    char out[128];
    const char *in = "a|b\nc`d\\e<f\tg";
    size_t n = swi_md_cell(in, out, sizeof out);
    assert_string_equal(out, "a\\|b c\\`d\\\\e\\<f g");
    assert_int_equal(n, strlen(out));
    assert_int_equal(swi_md_cell(in, NULL, 0), n);
    assert_int_equal(swi_md_cell(in, out, 4), n);   /* cut, always terminated */
    assert_string_equal(out, "a\\|");
    assert_int_equal(swi_md_cell("tangential 0.5 m/s", out, sizeof out), 18);
    assert_string_equal(out, "tangential 0.5 m/s");
    assert_int_equal(swi_md_cell("", out, sizeof out), 0);
    assert_string_equal(out, "");
}

/* the CSV parser from memory = from a file; hostile text */
static void test_simmap_mem(void **state)
{
    (void)state;
    char p[512], err[512] = "";
    path_in_tmp(p, sizeof p, "mem.csv");
    assert_int_equal(synth_csv(p, 8, 0, 0.75, 0.5), 0);
    size_t n = 0;
    unsigned char *b = synth_slurp(p, &n);
    assert_non_null(b);
    swi_simmap *a = NULL, *m = NULL;
    assert_int_equal(swi_simmap_read(p, &a, err, sizeof err), 0);
    assert_int_equal(swi_simmap_read_mem((const char *)b, n, "mem", &m, err, sizeof err), 0);
    assert_int_equal(a->ny, m->ny);
    assert_int_equal(a->nz, m->nz);
    assert_memory_equal(a->val, m->val, 64 * sizeof *a->val);
    swi_simmap_free(a);
    swi_simmap_free(m);
    /* without the last newline, and cut in the middle of the last number */
    assert_int_equal(swi_simmap_read_mem((const char *)b, n - 1, "mem", &m, err, sizeof err), 0);
    swi_simmap_free(m);
    assert_int_equal(swi_simmap_read_mem((const char *)b, n - 3, "mem", &m, err, sizeof err), 0);
    swi_simmap_free(m);    /* "0.01" cut to "0." still parses: the grid is whole */
    assert_int_equal(swi_simmap_read_mem((const char *)b, n / 2, "mem", &m, err, sizeof err), 2);
    assert_null(m);
    free(b);
    unlink(p);
    assert_int_equal(swi_simmap_read_mem(NULL, 0, NULL, &m, err, sizeof err), 2);
    assert_non_null(strstr(err, "(memory): empty"));
    /* binary garbage is shown as '?', in at most 60 characters, on one line */
    const char garbage[] = "y,z,d\n\x1b[31mred\x7f\xff\xfe,1,2\n";
    assert_int_equal(swi_simmap_read_mem(garbage, sizeof garbage - 1, "g", &m, err, sizeof err), 2);
    print_message("%s\n", err);
    assert_non_null(strstr(err, "g:2: expected 'y,z,value', got '?[31mred???,1,2'"));
    char longbad[300];
    memset(longbad, 'x', sizeof longbad);
    memcpy(longbad, "h\n", 2);
    assert_int_equal(swi_simmap_read_mem(longbad, sizeof longbad, "l", &m, err, sizeof err), 2);
    assert_non_null(strstr(err, "xxx...'"));
    assert_null(strchr(err, '\n'));
    /* a NUL byte, an over-long line */
    const char nul[] = "y,z,d\n0,0,1\0\n1,0,1\n0,1,1\n1,1,1\n";
    assert_int_equal(swi_simmap_read_mem(nul, sizeof nul - 1, "nul", &m, err, sizeof err), 2);
    assert_non_null(strstr(err, "nul:2: NUL byte"));
    char *big = malloc(5000);
    assert_non_null(big);
    memset(big, ' ', 5000);
    memcpy(big, "y,z,d\n0,0,1", 11);
    assert_int_equal(swi_simmap_read_mem(big, 5000, "long", &m, err, sizeof err), 2);
    assert_non_null(strstr(err, "long:2: line longer than 1023 characters"));
    free(big);
    /* more faces than SWI_SIMMAP_MAX_FACES: refused while reading */
    size_t cap = 16 * (size_t)(SWI_SIMMAP_MAX_FACES + 2), len = 0;
    char *many = malloc(cap);
    assert_non_null(many);
    len += (size_t)snprintf(many, cap, "y,z,d\n");
    for (int i = 0; i <= SWI_SIMMAP_MAX_FACES; i++)
        len += (size_t)snprintf(many + len, cap - len, "%d,%d,1\n", i % 1000, i / 1000);
    assert_int_equal(swi_simmap_read_mem(many, len, "many", &m, err, sizeof err), 2);
    assert_non_null(strstr(err, "many:1000002: more than 1000000 faces"));
    free(many);
}

int main(void)
{
    snprintf(tmpdir, sizeof tmpdir, "/tmp/test_swi.XXXXXX");
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
        cmocka_unit_test(test_image_size_check),
        cmocka_unit_test(test_image_huge_header),
        cmocka_unit_test(test_image_truncated),
        cmocka_unit_test(test_image_many_scans),
        cmocka_unit_test(test_corners),
        cmocka_unit_test(test_md_cell),
        cmocka_unit_test(test_simmap_mem),
    };
    int rc = cmocka_run_group_tests(tests, NULL, NULL);
    rmdir(tmpdir);
    return rc;
}
