/* sbd_main.c - snowbody: the square-back Ahmed body as an STL surface for
 * snappyHexMesh, and the checks of that surface. */
#include "sbd_body.h"
#include "sbd_cmd.h"
#include "sbd_stl.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

static const char *usage =
"NAME\n"
"    snowbody - the square-back Ahmed body as a closed STL surface\n"
"\n"
"SYNOPSIS\n"
"    snowbody stl --out FILE [--force] [--set KEY=VALUE]...\n"
"    snowbody check [--set KEY=VALUE]...\n"
"    snowbody snow-post --case DIR --fill T --sample T --build-up S --out DIR ...\n"
"    snowbody --help\n"
"\n"
"DESCRIPTION\n"
"    stl writes the body of Ahmed, Ramm & Faltin (1984) with a 0 degree rear\n"
"    slant (the square back) as an ASCII STL in metres, one solid per region:\n"
"    nose (the rounded front, x < radius), top, bottom, sides, rear (the rear face\n"
"    less the sensor), sensor (a rectangle on the rear face), stilts. x runs from\n"
"    the nose (0) to the rear face (length), y to the car's left (0 on the centre\n"
"    line), z up from the ground (0). The body is one closed shell; each of the four\n"
"    stilts is its own closed shell reaching stilt_below under the ground and\n"
"    stilt_into into the body (snappyHexMesh cuts them with the ground and keeps\n"
"    the union).\n"
"\n"
"    snow-post reads a snow run on the body (tutorials/ahmed/snow) and writes the\n"
"    deposit per patch, the sensor's deposit against time, the rear-face map and\n"
"    the error table; its options: snowbody snow-post --help.\n"
"\n"
"    check builds the same surface and prints 'key = value' lines: vertices,\n"
"    triangles, open_edges and nonmanifold_edges (0 and 0 for a closed surface),\n"
"    body_volume and its closed form body_volume_exact with their relative\n"
"    difference (the front's arcs are polygons of arc_steps segments), the frontal\n"
"    area (width x height) and the area of each region.\n"
"\n"
"OPTIONS\n"
"    --out FILE        the STL (stl); written whole or not at all (a temporary in\n"
"                      its folder, renamed at the end)\n"
"    --force           replace FILE when it exists (a regular file only)\n"
"    --set KEY=VALUE   a dimension in metres or a resolution; keys and defaults:\n"
"                        length 1.044  width 0.389  height 0.288  clearance 0.05\n"
"                        radius 0.1 (the four front edges)\n"
"                        stilt_radius 0.015  stilt_x1 0.202  stilt_x2 0.672 (axes from\n"
"                        the nose)  stilt_y 0.1635 (from the centre line)\n"
"                        stilt_below 0.01  stilt_into 0.01\n"
"                        sensor_width 0.05  sensor_height 0.04  sensor_y 0\n"
"                        sensor_z 0.266 (centre above the ground)\n"
"                        cell 0.01 (edge length on the flat faces)\n"
"                        arc_steps 16 (segments of a front quarter arc)\n"
"                        stilt_sides 32\n"
"    -h, --help        this text\n"
"\n"
"EXIT STATUS\n"
"    0 success, 2 usage or input error (one line on standard error), 1 other\n"
"    failure (memory, writing).\n"
"\n"
"EXAMPLE\n"
"    snowbody stl --out constant/triSurface/ahmed.stl --set sensor_z=0.25\n";

static int finish_stdout(int rc)
{
    if (fflush(stdout) || ferror(stdout)) {
        fprintf(stderr, "snowbody: writing standard output failed\n");
        return 1;
    }
    return rc;
}

static int write_stl(const sbd_surface *s, const char *path, int force)
{
    struct stat st;
    if (lstat(path, &st) == 0) {
        if (!S_ISREG(st.st_mode)) {
            fprintf(stderr, "snowbody: --out %s exists and is not a regular file\n", path);
            return 2;
        }
        if (!force) {
            fprintf(stderr, "snowbody: --out %s exists (give --force to replace it)\n", path);
            return 2;
        }
    }
    size_t n = strlen(path) + 32;
    char *tmp = malloc(n);
    if (!tmp) { fprintf(stderr, "snowbody: out of memory\n"); return 1; }
    snprintf(tmp, n, "%s.tmp%ld", path, (long)getpid());
    FILE *f = fopen(tmp, "w");
    if (!f) {
        fprintf(stderr, "snowbody: --out %s: cannot write (%s)\n", path, strerror(errno));
        free(tmp);
        return 2;
    }
    char err[256];
    int rc = sbd_stl_write(s, f, err, sizeof err);
    if (fclose(f) && rc == 0) { rc = -1; snprintf(err, sizeof err, "closing the STL failed"); }
    if (rc == 0 && rename(tmp, path)) { rc = -1; snprintf(err, sizeof err, "rename: %s", strerror(errno)); }
    if (rc) {
        remove(tmp);
        fprintf(stderr, "snowbody: --out %s: %s\n", path, err);
        free(tmp);
        return 1;
    }
    free(tmp);
    return 0;
}

static int print_check(const sbd_params *p, const sbd_surface *s)
{
    sbd_measure m;
    char err[256];
    if (sbd_measure_surface(s, &m, err, sizeof err)) {
        fprintf(stderr, "snowbody: %s\n", err);
        return 1;
    }
    double ve = sbd_body_volume_exact(p);
    printf("vertices = %zu\ntriangles = %zu\nopen_edges = %zu\nnonmanifold_edges = %zu\n",
           s->nv, s->nt, m.open_edges, m.nonmanifold);
    printf("body_volume_m3 = %.9g\nbody_volume_exact_m3 = %.9g\nbody_volume_rel_diff = %.3e\n",
           m.body_volume, ve, (m.body_volume - ve) / ve);
    printf("volume_all_shells_m3 = %.9g\nfrontal_area_m2 = %.9g\nwidth_x_height_m2 = %.9g\n",
           m.volume, m.frontal_area, p->width * p->height);
    for (int r = 0; r < SBD_NREGION; r++)
        printf("area_%s_m2 = %.9g\n", sbd_region_name(r), m.area[r]);
    return finish_stdout(m.open_edges || m.nonmanifold ? 1 : 0);
}

int main(int argc, char **argv)
{
    if (argc < 2) {
        fprintf(stderr, "snowbody: missing command (stl, check or snow-post); see snowbody --help\n");
        return 2;
    }
    if (!strcmp(argv[1], "-h") || !strcmp(argv[1], "--help")) {
        fputs(usage, stdout);
        return finish_stdout(0);
    }
    if (!strcmp(argv[1], "snow-post"))
        return sbd_cmd_snow_post(argc, argv);
    int is_stl = !strcmp(argv[1], "stl"), is_check = !strcmp(argv[1], "check");
    if (!is_stl && !is_check) {
        fprintf(stderr, "snowbody: unknown command '%s' (stl, check or snow-post); see snowbody --help\n", argv[1]);
        return 2;
    }
    sbd_params p;
    sbd_params_default(&p);
    const char *out = NULL;
    int force = 0;
    char err[512];
    for (int i = 2; i < argc; i++) {
        const char *o = argv[i];
        if (!strcmp(o, "-h") || !strcmp(o, "--help")) { fputs(usage, stdout); return finish_stdout(0); }
        if (!strcmp(o, "--force") && is_stl) { force = 1; continue; }
        if (i + 1 >= argc || (strcmp(o, "--set") && !(is_stl && !strcmp(o, "--out")))) {
            fprintf(stderr, "snowbody: option '%s' unknown or missing its value; see snowbody --help\n", o);
            return 2;
        }
        const char *a = argv[++i];
        if (!strcmp(o, "--out")) out = a;
        else if (sbd_params_set(&p, a, err, sizeof err)) {
            fprintf(stderr, "snowbody: --set %s\n", err);
            return 2;
        }
    }
    if (is_stl && !out) {
        fprintf(stderr, "snowbody: stl needs --out FILE\n");
        return 2;
    }
    if (sbd_params_check(&p, err, sizeof err)) {
        fprintf(stderr, "snowbody: %s\n", err);
        return 2;
    }
    sbd_surface *s;
    if (sbd_build(&p, &s, err, sizeof err)) {
        fprintf(stderr, "snowbody: %s\n", err);
        return 1;
    }
    int rc = is_stl ? write_stl(s, out, force) : print_check(&p, s);
    sbd_free(s);
    return rc;
}
