/* swi_main.c - snowphoto: compare a photo of the wedge's rear face with the
 * simulated deposit map; list which rear-face regions hold snow. */
#include "swi_compare.h"
#include "swi_image.h"
#include "swo_out.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

/* accepted --parcel-mass [kg] */
#define SWI_PARCEL_MASS_MIN 1e-20
#define SWI_PARCEL_MASS_MAX 1e3

static const char *usage =
"NAME\n"
"    snowphoto - compare a photo of the wedge's rear face with the simulated snow map\n"
"\n"
"SYNOPSIS\n"
"    snowphoto compare --photo FILE --corners X1,Y1,X2,Y2,X3,Y3,X4,Y4 --sim CSV\n"
"                      [--photo-threshold L] [--sim-threshold KG_M2 | --sim-rel-threshold F]\n"
"                      [--res N] [--out PNG]\n"
"    snowphoto regions --sim CSV [--sim-threshold KG_M2 | --sim-rel-threshold F]\n"
"                      [--band B] [--hold F] [--label TEXT] [--parcel-mass KG]\n"
"    snowphoto --help\n"
"\n"
"DESCRIPTION\n"
"    compare rectifies the photo (PNG or JPEG, detected from the file's contents) to\n"
"    the rear face: the four corners are the pixel positions (x right, y down, origin\n"
"    at the image's top-left corner) of the face's top-left, top-right, bottom-right\n"
"    and bottom-left corners as seen from behind. A homography (8x8 linear system,\n"
"    GSL LU) maps face coordinates (u right, v down, both 0..1) to pixels. Snow in the\n"
"    photo is every point whose luminance (Rec. 601, 0 = black, 1 = white) is >= L:\n"
"    bright snow on a darker face; choose L between the face's and the snow's\n"
"    brightness. Snow in the simulation is every face whose deposit is >= the\n"
"    simulation threshold. Both masks are sampled on an N x N grid of the face and\n"
"    compared with the photo as the truth:\n"
"        precision = TP/(TP+FP)  recall = TP/(TP+FN)  IoU = TP/(TP+FP+FN)\n"
"        Dice = 2TP/(2TP+FP+FN)  (an empty denominator counts as 1)\n"
"    The result goes to standard output as 'key = value' lines.\n"
"\n"
"    regions reports, for the four regions of the rear face used to describe the\n"
"    wind-tunnel photos, the mean deposit, the fraction of faces >= the threshold\n"
"    and whether the region holds snow (fraction >= F of --hold). Regions (face\n"
"    coordinates): edges = the border band of width B; left side u in [B, 0.35);\n"
"    right side u in (0.65, 1-B]; centre u in [0.35, 0.65] x v in [0.3, 0.7]; the\n"
"    sides span v in [B, 1-B]. One markdown table row: per region whether it\n"
"    holds snow (bold), the covered fraction and the mean deposit; with\n"
"    --parcel-mass also the number of parcels deposited in the region (its mass\n"
"    = sum of deposit x face area, divided by the mass of one parcel) and the\n"
"    Poisson relative error 1/sqrt(N) of that count ('inf' for none).\n"
"\n"
"    CSV is the rear-face map written by tutorials/wedge/post/wedge-post\n"
"    (results/<gate>/rear_deposit.csv): a header line, then 'y,z,deposit_kg_m2' per\n"
"    face; y grows to the viewer's right, z upwards; the faces form a regular grid.\n"
"\n"
"OPTIONS\n"
"    --photo FILE            photo of the rear face, PNG or JPEG, at most 30000 px\n"
"                            a side and 100 MP (checked from the header before\n"
"                            decoding); a corrupt or truncated file is an error,\n"
"                            a libjpeg warning too\n"
"    --corners LIST          8 numbers: x,y of top-left, top-right, bottom-right,\n"
"                            bottom-left (pixels); each inside the image; they must\n"
"                            make a convex quadrilateral running clockwise on the\n"
"                            image (no bow-tie, no reflex corner, not mirrored), at\n"
"                            least 10 px wide in every direction and 100 px^2\n"
"    --sim CSV               simulated rear-face map (at most 1000000 faces)\n"
"    --photo-threshold L     luminance threshold in [0, 1] (default 0.5)\n"
"    --sim-threshold T       deposit threshold [kg/m2], >= 0\n"
"    --sim-rel-threshold F   threshold as a fraction of the map's maximum, in (0, 1]\n"
"                            (default 0.1; used unless --sim-threshold is given)\n"
"    --res N                 comparison grid N x N, 2..4000 (default 200)\n"
"    --out PNG               side-by-side image: rectified photo | simulated map\n"
"                            (white -> dark blue = 0 -> max) | overlay (white both,\n"
"                            red simulation only, blue photo only, grey neither)\n""                            PNG appears whole or not at all (a temporary in its\n"
"                            folder, renamed at the end; a full disk is exit 1).\n"
"                            Checked before any work: its folder must exist and\n"
"                            be writable, and PNG is replaced only when absent or\n"
"                            a regular file (a folder, device, FIFO, socket or\n"
"                            symbolic link there: exit 2, left as it is)\n"
"    --band B                edge band width for regions, in (0, 0.3) (default 0.1)\n"
"    --hold F                covered fraction for 'holds snow', in (0, 1] (default 0.3)\n"
"    --label TEXT            first column of the regions rows (default: the CSV path);\n"
"                            '|', '\\', '`' and '<' are backslash-escaped, newlines\n"
"                            and other control characters become spaces\n"
"    --parcel-mass KG        mass of one parcel [kg], 1e-20 .. 1000 (a parcelBasisType mass\n"
"                            spray: every parcel carries the same mass); adds\n"
"                            parcel counts and Poisson errors per region\n"
"    -h, --help              this text\n"
"\n"
"EXIT STATUS\n"
"    0 success, 2 usage or input error (one line on standard error naming the\n"
"    option or input and the value), 1 other failure (memory, writing the\n"
"    output). Interrupted by SIGINT, SIGTERM or SIGHUP, snowphoto leaves no file:\n"
"    the temporary of --out is removed and the run ends by the signal.\n"
"\n"
"EXAMPLE\n"
"    snowphoto compare --photo rear.jpg --corners 412,188,1630,204,1611,1402,398,1380 \\\n"
"        --sim tutorials/wedge/results/tangential/rear_deposit.csv \\\n"
"        --photo-threshold 0.6 --out compare.png\n";

static int parse_double(const char *opt, const char *s, double *out)
{
    char *end;
    errno = 0;
    double v = strtod(s, &end);
    /* decimal only: strtod also takes hexadecimal (0x1p-30) */
    if (end == s || *end != '\0' || errno || !isfinite(v) || strpbrk(s, "xX")) {
        fprintf(stderr, "snowphoto: %s: '%s' is not a finite decimal number\n", opt, s);
        return 2;
    }
    *out = v;
    return 0;
}

static int parse_corners(const char *s, double c[4][2])
{
    const char *p = s;
    if (strpbrk(s, "xX")) {
        fprintf(stderr, "snowphoto: --corners: '%s' is not 8 comma-separated finite decimal numbers\n", s);
        return 2;
    }
    for (int k = 0; k < 8; k++) {
        char *end;
        errno = 0;
        double v = strtod(p, &end);
        if (end == p || errno || !isfinite(v) || (k < 7 && *end != ',') || (k == 7 && *end != '\0')) {
            fprintf(stderr, "snowphoto: --corners: '%s' is not 8 comma-separated finite numbers\n", s);
            return 2;
        }
        c[k / 2][k % 2] = v;
        p = end + 1;
    }
    return 0;
}

/* --out PNG checked before any work: its folder takes files and PNG is absent
 * or a regular file (common/swo_out.h; a device or FIFO there is refused and
 * left as it is). 0, or the exit status with the message printed. */
static int check_out(const char *path)
{
    char err[600];
    swo_set *set = NULL;
    const swo_spec spec = { "snowphoto", "--out", NULL, 0, 0 };
    int rc = swo_alloc(&spec, &set, err, sizeof err);
    if (rc == SWO_OK)
        rc = swo_check(set, path, err, sizeof err);
    if (rc != SWO_OK)
        fprintf(stderr, "snowphoto: --out: %s\n", err);
    swo_free(set);
    return rc;
}

/* The results go to standard output: a failed write (a full disk, a closed pipe
 * reader) is a failure, not a silent exit 0. */
static int finish_stdout(int rc)
{
    if ((fflush(stdout) != 0 || ferror(stdout)) && rc == 0) {
        fprintf(stderr, "snowphoto: writing the results to standard output failed (%s)\n",
                strerror(errno));
        return 1;
    }
    return rc;
}

/* a command's options */
typedef struct {
    const char *cmd;           /* compare or regions */
    int is_compare, is_regions;
    swi_config cfg;
    const char *photo_path, *sim_path, *out_path, *label;
    const char *corners_arg;
    int have_corners;
    double band, hold, parcel_mass;
} photo_opts;

/* the command's options after argv[1] into o (its defaults set by the caller): 0, -1 when the
 * help was printed, or the exit status of a usage error with its message printed */
static int parse_options(int argc, char **argv, photo_opts *o)
{
    const char *cmd = o->cmd;
    const int is_compare = o->is_compare, is_regions = o->is_regions;
    for (int i = 2; i < argc; i++) {
        const char *opt = argv[i];
        if (!strcmp(opt, "-h") || !strcmp(opt, "--help")) {
            fputs(usage, stdout);
            return -1;
        }
        if (i + 1 >= argc) {
            fprintf(stderr, "snowphoto: option '%s' unknown or missing its value; see snowphoto --help\n", opt);
            return 2;
        }
        const char *a = argv[++i];
        double d;
        if (!strcmp(opt, "--photo") && is_compare) o->photo_path = a;
        else if (!strcmp(opt, "--sim")) o->sim_path = a;
        else if (!strcmp(opt, "--out") && is_compare) o->out_path = a;
        else if (!strcmp(opt, "--label") && is_regions) o->label = a;
        else if (!strcmp(opt, "--corners") && is_compare) {
            if (parse_corners(a, o->cfg.corners)) return 2;
            o->have_corners = 1;
            o->corners_arg = a;
        } else if (!strcmp(opt, "--photo-threshold") && is_compare) {
            if (parse_double(opt, a, &d)) return 2;
            if (d < 0 || d > 1) {
                fprintf(stderr, "snowphoto: --photo-threshold %s outside [0, 1]\n", a);
                return 2;
            }
            o->cfg.photoThreshold = d;
        } else if (!strcmp(opt, "--sim-threshold")) {
            if (parse_double(opt, a, &d)) return 2;
            if (d < 0) {
                fprintf(stderr, "snowphoto: --sim-threshold %s is negative\n", a);
                return 2;
            }
            o->cfg.simThreshold = d;
        } else if (!strcmp(opt, "--sim-rel-threshold")) {
            if (parse_double(opt, a, &d)) return 2;
            if (!(d > 0 && d <= 1)) {
                fprintf(stderr, "snowphoto: --sim-rel-threshold %s outside (0, 1]\n", a);
                return 2;
            }
            o->cfg.simRelThreshold = d;
        } else if (!strcmp(opt, "--res") && is_compare) {
            if (parse_double(opt, a, &d)) return 2;
            if (d != floor(d) || d < 2 || d > 4000) {
                fprintf(stderr, "snowphoto: --res %s is not an integer in 2..4000\n", a);
                return 2;
            }
            o->cfg.res = (int)d;
        } else if (!strcmp(opt, "--band") && is_regions) {
            if (parse_double(opt, a, &d)) return 2;
            if (!(d > 0 && d < 0.3)) {
                fprintf(stderr, "snowphoto: --band %s outside (0, 0.3)\n", a);
                return 2;
            }
            o->band = d;
        } else if (!strcmp(opt, "--hold") && is_regions) {
            if (parse_double(opt, a, &d)) return 2;
            if (!(d > 0 && d <= 1)) {
                fprintf(stderr, "snowphoto: --hold %s outside (0, 1]\n", a);
                return 2;
            }
            o->hold = d;
        } else if (!strcmp(opt, "--parcel-mass") && is_regions) {
            if (parse_double(opt, a, &d)) return 2;
            /* from one 0.1 um ice sphere (4.8e-19 kg) to a tonne: outside it the
             * parcel counts mass / parcel mass are not counts of anything
             * (1e-300 and 1e300 are refused) */
            if (!(d >= SWI_PARCEL_MASS_MIN && d <= SWI_PARCEL_MASS_MAX)) {
                fprintf(stderr, "snowphoto: --parcel-mass %s is outside [%g, %g] kg\n", a,
                        SWI_PARCEL_MASS_MIN, SWI_PARCEL_MASS_MAX);
                return 2;
            }
            o->parcel_mass = d;
        } else {
            fprintf(stderr, "snowphoto %s: unknown option '%s'; see snowphoto --help\n", cmd, opt);
            return 2;
        }
    }
    return 0;
}

/* snowphoto regions: one table row, the map's regions holding snow or not; the exit status */
static int run_regions(const photo_opts *o, const swi_simmap *sim)
{
    const swi_config cfg = o->cfg;
    const char *sim_path = o->sim_path, *label = o->label;
    const double parcel_mass = o->parcel_mass;
    char err[1024] = "";
    double thr = cfg.simThreshold >= 0 ? cfg.simThreshold : cfg.simRelThreshold * sim->vmax;
    swi_region_stats st;
    int rc = swi_regions(sim, thr, o->band, o->hold, &st, err, sizeof err);
    if (rc) {
        fprintf(stderr, "snowphoto: %s: %s\n", sim_path, err);
        return rc;
    }
    /* the label (or path) as a table cell: a '|' or newline in it cannot break the table */
    const char *text = label ? label : sim_path;
    size_t need = swi_md_cell(text, NULL, 0) + 1;
    char *cell = malloc(need);
    if (!cell) {
        fprintf(stderr, "snowphoto: out of memory\n");
        return 1;
    }
    swi_md_cell(text, cell, need);
    printf("| %s |", cell);
    free(cell);
    for (int r = 0; r < SWI_NREGIONS; r++) {
        printf(" %s (%.0f %%, %.3g kg/m2", st.holds[r] ? "**snow**" : "no", 100 * st.covered[r], st.mean[r]);
        if (parcel_mass > 0) {
            double n = st.mass[r] / parcel_mass;
            if (n >= 0.5)
                printf(", %.0f parcels +- %.1f %%", n, 100 / sqrt(n));
            else
                printf(", 0 parcels +- inf");
        }
        printf(") |");
    }
    printf(" %.3g |\n", thr);
    return finish_stdout(0);
}

/* snowphoto compare: the photo against the map, the metrics printed, the side-by-side
 * picture written (--out); the exit status */
static int run_compare(const photo_opts *o, const swi_simmap *sim)
{
    const swi_config cfg = o->cfg;
    const char *photo_path = o->photo_path, *sim_path = o->sim_path, *out_path = o->out_path;
    char err[1024] = "";
    swi_image *photo = NULL;
    int rc = swi_image_read(photo_path, &photo, err, sizeof err);
    if (rc) {
        fprintf(stderr, "snowphoto: --photo %s\n", err);
        return rc;
    }
    rc = swi_corners_check(cfg.corners, photo->width, photo->height, err, sizeof err);
    if (rc) {
        fprintf(stderr, "snowphoto: --corners %s: %s\n", o->corners_arg, err);
        swi_image_free(photo);
        return rc;
    }
    swi_metrics m;
    swi_image *side = NULL;
    rc = swi_compare_run(&cfg, photo, sim, &m, out_path ? &side : NULL, err, sizeof err);
    if (rc) {
        fprintf(stderr, "snowphoto: %s: %s\n", photo_path, err);
    } else {
        if (out_path) {
            rc = swi_image_write_png(out_path, side, err, sizeof err);
            if (rc) fprintf(stderr, "snowphoto: --out: %s\n", err);
        }
        if (!rc) {
            printf("photo = %s\nsim = %s\n", photo_path, sim_path);
            printf("photo_threshold = %g\nsim_threshold_kg_m2 = %.6g\nres = %d\n", cfg.photoThreshold,
                   m.simThresholdUsed, cfg.res);
            printf("photo_snow_fraction = %.4f\nsim_snow_fraction = %.4f\n", m.photoSnowFraction,
                   m.simSnowFraction);
            printf("tp = %ld\nfp = %ld\nfn = %ld\ntn = %ld\n", m.tp, m.fp, m.fn, m.tn);
            printf("iou = %.4f\ndice = %.4f\nprecision = %.4f\nrecall = %.4f\n", m.iou, m.dice,
                   m.precision, m.recall);
            if (out_path) printf("side_by_side = %s\n", out_path);
        }
    }
    swi_image_free(side);
    swi_image_free(photo);
    return finish_stdout(rc);
}

int main(int argc, char **argv)
{
    if (argc < 2) {
        fprintf(stderr, "snowphoto: missing command (compare or regions); see snowphoto --help\n");
        return 2;
    }
    if (!strcmp(argv[1], "-h") || !strcmp(argv[1], "--help")) {
        fputs(usage, stdout);
        return finish_stdout(0);
    }
    const char *cmd = argv[1];
    int is_compare = !strcmp(cmd, "compare"), is_regions = !strcmp(cmd, "regions");
    if (!is_compare && !is_regions) {
        fprintf(stderr, "snowphoto: unknown command '%s' (compare or regions); see snowphoto --help\n", cmd);
        return 2;
    }
    photo_opts o = {.cmd = cmd, .is_compare = is_compare, .is_regions = is_regions, .band = 0.1, .hold = 0.3,
                    .parcel_mass = 0};
    swi_config_defaults(&o.cfg);
    const int prc = parse_options(argc, argv, &o);
    if (prc < 0)
        return finish_stdout(0);
    if (prc)
        return prc;
    if (!o.sim_path) {
        fprintf(stderr, "snowphoto %s: --sim CSV is required\n", cmd);
        return 2;
    }
    if (is_compare && (!o.photo_path || !o.have_corners)) {
        fprintf(stderr, "snowphoto compare: --photo and --corners are required\n");
        return 2;
    }
    if (o.out_path) {
        const int c = check_out(o.out_path);
        if (c)
            return c;
    }
    swo_signals_on();   /* interrupted, the run leaves no temporary of --out behind */
    char err[1024] = "";
    swi_simmap *sim = NULL;
    int rc = swi_simmap_read(o.sim_path, &sim, err, sizeof err);
    if (rc) {
        fprintf(stderr, "snowphoto: --sim %s\n", err);
        return rc;
    }
    rc = is_regions ? run_regions(&o, sim) : run_compare(&o, sim);
    swi_simmap_free(sim);
    return rc;
}
