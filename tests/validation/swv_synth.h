/* swv_synth.h - synthetic rear-face photos and simulated maps with a known overlap
 * (shared by the cmocka tests and the swv_testimg generator). */
#ifndef SWV_SYNTH_H
#define SWV_SYNTH_H
#include <math.h>
#include <stdio.h>
#include "swv_compare.h"
#include "swv_homography.h"
#include "swv_image.h"

/* The face seen in perspective in a 640 x 480 photo. */
static const double synth_corners[4][2] = {{100, 80}, {540, 60}, {580, 420}, {60, 400}};

/* Photo: background luminance 0.15, face 0.3, snow 0.9 where u < su and v < sv. */
static inline swv_image *synth_photo(double su, double sv)
{
    const double unit[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    double Hinv[9];
    if (swv_homography_solve(synth_corners, unit, Hinv, NULL, 0))
        return NULL;
    swv_image *img = swv_image_alloc(640, 480);
    if (!img)
        return NULL;
    for (int y = 0; y < img->height; y++)
        for (int x = 0; x < img->width; x++) {
            double u, v, L = 0.15;
            if (!swv_homography_apply(Hinv, x + 0.5, y + 0.5, &u, &v) && u >= 0 && u <= 1 &&
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
#endif
