/* swi_synth.h - synthetic rear-face photos and simulated maps with a known overlap
 * (shared by the cmocka tests and the swi_testimg generator). */
#ifndef SWI_SYNTH_H
#define SWI_SYNTH_H
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "swi_compare.h"
#include "swi_homography.h"
#include "swi_image.h"

/* The face seen in perspective in a 640 x 480 photo. */
static const double synth_corners[4][2] = {{100, 80}, {540, 60}, {580, 420}, {60, 400}};

/* Photo: background luminance 0.15, face 0.3, snow 0.9 where u < su and v < sv. */
static inline swi_image *synth_photo(double su, double sv)
{
    const double unit[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    double Hinv[9];
    if (swi_homography_solve(synth_corners, unit, Hinv, NULL, 0))
        return NULL;
    swi_image *img = swi_image_alloc(640, 480);
    if (!img)
        return NULL;
    for (int y = 0; y < img->height; y++)
        for (int x = 0; x < img->width; x++) {
            double u, v, L = 0.15;
            if (!swi_homography_apply(Hinv, x + 0.5, y + 0.5, &u, &v) && u >= 0 && u <= 1 &&
                v >= 0 && v <= 1)
                L = (u < su && v < sv) ? 0.9 : 0.3;
            unsigned char g = (unsigned char)lround(L * 255);
            unsigned char *p = img->rgb + ((size_t)y * 640u + (size_t)x) * 3u;
            p[0] = g; p[1] = g; p[2] = g;
        }
    return img;
}

/* Simulated CSV: n x n faces over y, z in [-0.06, 0.06]; deposit 2.0 kg/m2 where
 * the face centre has u in [ulo, uhi) and v < sv (v = 0 at the top), else 0.01. */
static inline int synth_csv(const char *path, int n, double ulo, double uhi, double sv)
{
    FILE *f = fopen(path, "w");
    if (!f)
        return 1;
    fprintf(f, "y,z,deposit_kg_m2\n");
    double h = 0.12 / n;
    for (int iz = 0; iz < n; iz++)
        for (int iy = 0; iy < n; iy++) {
            double u = (iy + 0.5) / n, v = 1 - (iz + 0.5) / n;
            double val = (u >= ulo && u < uhi && v < sv) ? 2.0 : 0.01;
            fprintf(f, "%.9g,%.9g,%.9g\n", -0.06 + (iy + 0.5) * h, -0.06 + (iz + 0.5) * h, val);
        }
    return fclose(f) != 0;
}

/* ---- hostile images: valid small files whose header claims another size ---- */

static inline unsigned long synth_crc32(const unsigned char *p, size_t n)
{
    unsigned long c = 0xffffffffUL;
    for (size_t i = 0; i < n; i++) {
        c ^= p[i];
        for (int k = 0; k < 8; k++)
            c = (c >> 1) ^ (0xedb88320UL & (0UL - (c & 1)));
    }
    return c ^ 0xffffffffUL;
}

static inline unsigned char *synth_slurp(const char *path, size_t *n)
{
    FILE *f = fopen(path, "rb");
    if (!f)
        return NULL;
    unsigned char *b = malloc(1 << 20);
    *n = b ? fread(b, 1, 1 << 20, f) : 0;
    fclose(f);
    return b;
}

static inline int synth_spit(const char *path, const unsigned char *b, size_t n)
{
    FILE *f = fopen(path, "wb");
    if (!f)
        return 1;
    size_t w = fwrite(b, 1, n, f);
    return (fclose(f) != 0) | (w != n);
}

static inline void synth_be(unsigned char *p, unsigned long v, int bytes)
{
    for (int i = bytes - 1; i >= 0; i--, v >>= 8)
        p[i] = (unsigned char)(v & 0xff);
}

/* A w0 x h0 image of deterministic noise (compresses badly: a JPEG of 96 x 96 at
 * quality 95 is about 12 KB). */
static inline swi_image *synth_noise(int w0, int h0)
{
    swi_image *img = swi_image_alloc(w0, h0);
    unsigned long r = 12345;
    for (size_t i = 0; img && i < (size_t)w0 * (size_t)h0 * 3u; i++) {
        r = r * 1103515245UL + 12345UL;
        img->rgb[i] = (unsigned char)(r >> 16);
    }
    return img;
}

/* A real 1 x 1 PNG whose IHDR (CRC recomputed) claims w x h pixels. */
static inline int synth_png_claiming(const char *path, unsigned long w, unsigned long h)
{
    swi_image *img = synth_noise(1, 1);
    int rc = !img || swi_image_write_png(path, img, NULL, 0);
    swi_image_free(img);
    size_t n = 0;
    unsigned char *b = rc ? NULL : synth_slurp(path, &n);
    if (!b || n < 33 || memcmp(b + 12, "IHDR", 4) != 0) {
        free(b);
        return 1;
    }
    synth_be(b + 16, w, 4);
    synth_be(b + 20, h, 4);
    synth_be(b + 29, synth_crc32(b + 12, 17), 4);
    rc = synth_spit(path, b, n);
    free(b);
    return rc;
}

/* A real w0 x h0 noise JPEG whose frame header (SOF) claims w x h pixels (the
 * entropy-coded data then runs out long before the image does). */
static inline int synth_jpeg_claiming(const char *path, int w0, int h0, unsigned long w,
                                      unsigned long h)
{
    swi_image *img = synth_noise(w0, h0);
    int rc = !img || swi_image_write_jpeg(path, img, 95, NULL, 0);
    swi_image_free(img);
    size_t n = 0;
    unsigned char *b = rc ? NULL : synth_slurp(path, &n);
    rc = 1;
    for (size_t i = 2; b && i + 9 < n; i++)
        if (b[i] == 0xff && b[i + 1] >= 0xc0 && b[i + 1] <= 0xc2) {  /* SOF0..2 */
            synth_be(b + i + 5, h, 2);
            synth_be(b + i + 7, w, 2);
            rc = synth_spit(path, b, n);
            break;
        }
    free(b);
    return rc;
}

/* The first `fraction` of the file at path, written to out (a truncated file). */
static inline int synth_truncate(const char *path, const char *out, double fraction)
{
    size_t n = 0;
    unsigned char *b = synth_slurp(path, &n);
    int rc = !b || synth_spit(out, b, (size_t)((double)n * fraction));
    free(b);
    return rc;
}
#endif
