/* swi_compare.h - compare a photo of the wedge's rear face with the simulated
 * deposit map.
 *
 * Face coordinates: u in [0, 1] from the viewer's left to right edge (seen from
 * behind, = +y of the case), v in [0, 1] from the top edge down (-z).
 * The photo is rectified with the homography (u, v) -> pixel given by the face's
 * four corners (top-left, top-right, bottom-right, bottom-left in the photo).
 * Snow in the photo: luminance >= photoThreshold (bright snow on a darker face).
 * Snow in the simulation: deposit >= simThreshold [kg/m2] (or, when simThreshold
 * < 0, >= simRelThreshold * the map's maximum).
 * Both are compared on a res x res grid of the face; the photo is taken as truth:
 *   precision = TP/(TP+FP), recall = TP/(TP+FN), IoU = TP/(TP+FP+FN),
 *   Dice = 2TP/(2TP+FP+FN); an empty denominator gives 1 (both masks empty).
 */
#ifndef SWI_COMPARE_H
#define SWI_COMPARE_H
#include <stddef.h>
#include "swi_image.h"

/* Simulated map on a regular grid of face centres. */
typedef struct swi_simmap {
    int ny, nz;             /* faces along y (left -> right) and z (bottom -> top) */
    double y0, y1, z0, z1;  /* the face extent [m] (outline, from centres and spacing) */
    double *val;            /* ny*nz values [kg/m2], index iy + ny*iz, iz = 0 at the bottom */
    double vmax;
} swi_simmap;

/* At most this many faces in a map (a 1000 x 1000 grid; the wedge's is 20 x 20). */
#define SWI_SIMMAP_MAX_FACES 1000000

/* Read the CSV written by tutorials/wedge/post/wedge-post: a header line, then
 * "y,z,value" per face (blank lines and '#' comments skipped); the centres must
 * form a full regular grid of at least 2 x 2 faces, every value finite and >= 0.
 * Bad input: code 2 and one line "PATH[:LINE]: what" in err (a bad line is shown
 * in at most 60 characters, bytes other than printable ASCII as '?'); lines of
 * more than 1023 characters, NUL bytes and more than SWI_SIMMAP_MAX_FACES faces
 * are refused. *out is NULL unless 0 is returned. */
int swi_simmap_read(const char *path, swi_simmap **out, char *err, size_t errlen);
/* The same parser on text in memory (data[0..n), not modified, need not end in
 * '\0'; name is used in messages, NULL gives "(memory)"): the entry point for
 * fuzzing. */
int swi_simmap_read_mem(const char *data, size_t n, const char *name, swi_simmap **out,
                        char *err, size_t errlen);
void swi_simmap_free(swi_simmap *m);
/* Value at face coordinates (u, v) (nearest face). */
double swi_simmap_at(const swi_simmap *m, double u, double v);

typedef struct swi_config {
    double corners[4][2];   /* pixel (x, y): top-left, top-right, bottom-right, bottom-left */
    double photoThreshold;  /* luminance in [0, 1], default 0.5 */
    double simThreshold;    /* kg/m2; < 0: use simRelThreshold (default -1) */
    double simRelThreshold; /* fraction of the map's maximum, default 0.1 */
    int res;                /* comparison grid res x res, default 200 */
} swi_config;

void swi_config_defaults(swi_config *c);

/* The face in the photo must be big enough to compare: */
#define SWI_CORNERS_MIN_WIDTH 10.0   /* px, the quadrilateral's smallest width */
#define SWI_CORNERS_MIN_AREA 100.0   /* px^2 */

/* Check the four corners (top-left, top-right, bottom-right, bottom-left, in
 * pixels, y down) in a width x height photo: every corner finite and inside the
 * photo; no three on one line; a convex quadrilateral (no bow-tie, no reflex
 * corner) running clockwise on the image (counter-clockwise = a mirrored face);
 * at least SWI_CORNERS_MIN_WIDTH wide in every direction and SWI_CORNERS_MIN_AREA
 * in area. 0, or 2 with a message naming the corner(s) in err. swi_compare_run
 * calls it first. */
int swi_corners_check(const double corners[4][2], int width, int height, char *err,
                      size_t errlen);

typedef struct swi_metrics {
    long tp, fp, fn, tn;
    double iou, dice, precision, recall;
    double photoSnowFraction, simSnowFraction;  /* of the face area */
    double simThresholdUsed;                    /* kg/m2 */
} swi_metrics;

/* Rectify, segment, compare. When side is non-NULL, *side receives a new image:
 * rectified photo | simulated map | overlay (white TP, red FP = simulated only,
 * blue FN = photo only), each res x res. */
int swi_compare_run(const swi_config *c, const swi_image *photo, const swi_simmap *sim,
                    swi_metrics *m, swi_image **side, char *err, size_t errlen);

/* Metrics from counts (exposed for tests). */
void swi_metrics_from_counts(swi_metrics *m);

/* Regions of the rear face (face coordinates, edge band width `band` = 0.1):
 * edges: the border band; left side: u in [band, 0.35), right side: u in (0.65, 1-band];
 * centre: u in [0.35, 0.65] x v in [0.3, 0.7]; the sides span v in [band, 1-band].
 * For each region: mean deposit, deposited mass (sum of value x face area, the
 * faces of the regular grid spanning the outline) and the fraction of its faces
 * at or above the threshold; it "holds snow" when that fraction >= holdFraction. */
enum { SWI_REGION_LEFT, SWI_REGION_RIGHT, SWI_REGION_CENTRE, SWI_REGION_EDGES, SWI_NREGIONS };
typedef struct swi_region_stats {
    int nfaces[SWI_NREGIONS];
    double mean[SWI_NREGIONS];      /* kg/m2 */
    double mass[SWI_NREGIONS];      /* kg: sum of value x face area */
    double covered[SWI_NREGIONS];   /* fraction of faces >= threshold */
    int holds[SWI_NREGIONS];
} swi_region_stats;
const char *swi_region_name(int r);
int swi_regions(const swi_simmap *sim, double threshold, double band, double holdFraction,
                swi_region_stats *s, char *err, size_t errlen);

/* text as the content of a markdown table cell: '|', '\\', '`' and '<' are
 * backslash-escaped (no column break, code span or HTML), control characters
 * (newline, CR, tab, ...) become spaces (the row stays one line). Writes at most
 * outlen bytes with the '\0' and returns the length of the whole result (as
 * snprintf: the output was cut when the return is >= outlen). */
size_t swi_md_cell(const char *text, char *out, size_t outlen);

#endif
