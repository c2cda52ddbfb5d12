/* swi_compare.c - simulated map input, rectification, segmentation, metrics, regions. */
#include "swi_compare.h"
#include "swi_error.h"
#include "swi_homography.h"

#include <errno.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>


void swi_simmap_free(swi_simmap *m)
{
    if (!m)
        return;
    free(m->val);
    free(m);
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* distinct values of sorted v[0..n) within tol; returns count, writes to u */
static int distinct(const double *v, int n, double tol, double *u)
{
    int k = 0;
    for (int i = 0; i < n; i++)
        if (k == 0 || v[i] - u[k - 1] > tol)
            u[k++] = v[i];
    return k;
}

static int find_index(const double *u, int n, double x, double tol)
{
    int lo = 0, hi = n - 1;
    while (lo <= hi) {
        int mid = (lo + hi) / 2;
        if (fabs(u[mid] - x) <= tol) return mid;
        if (u[mid] < x) lo = mid + 1; else hi = mid - 1;
    }
    return -1;
}

/* A line for a message: at most 60 characters, anything but printable ASCII as '?'. */
static void printable(char *dst, size_t len, const char *src)
{
    size_t i = 0;
    for (; src[i] && src[i] != '\n' && src[i] != '\r' && i + 4 < len && i < 60; i++)
        dst[i] = (src[i] >= 0x20 && src[i] < 0x7f) ? src[i] : '?';
    if (src[i] && src[i] != '\n' && src[i] != '\r' && i + 4 <= len) {
        memcpy(dst + i, "...", 3);
        i += 3;
    }
    dst[i] = '\0';
}

/* One line of f into buf (without its '\n'). Returns 0, or -1 at the end of the
 * file; *bad = 1 for a line longer than len - 1 characters (the rest is skipped),
 * 2 for a NUL byte in the line. */
static int read_line(FILE *f, char *buf, size_t len, int *bad)
{
    size_t k = 0;
    int c;
    *bad = 0;
    while ((c = getc_unlocked(f)) != EOF && c != '\n') {
        if (c == '\0')
            *bad = 2;
        else if (k + 1 < len)
            buf[k++] = (char)c;
        else if (!*bad)
            *bad = 1;
    }
    buf[k] = '\0';
    return (c == EOF && k == 0 && !*bad) ? -1 : 0;
}

/* The one CSV parser, on an open stream (path: the name in messages). */
static int simmap_read_stream(FILE *f, const char *path, swi_simmap **out, char *err, size_t errlen)
{
    size_t cap = 256, n = 0;
    double *y = malloc(cap * sizeof *y), *z = malloc(cap * sizeof *z), *v = malloc(cap * sizeof *v);
    char line[1024];
    long lineno = 0;
    int rc = 0;
    swi_simmap *m = NULL;
    double *uy = NULL, *uz = NULL, *sy = NULL, *sz = NULL;
    if (!y || !z || !v) { rc = swi_fail(err, errlen, 1, "%s: out of memory", path); goto done; }
    int bad;
    while (read_line(f, line, sizeof line, &bad) == 0) {
        lineno++;
        if (bad) {
            rc = bad == 1 ? swi_fail(err, errlen, 2, "%s:%ld: line longer than %d characters", path,
                                     lineno, (int)sizeof line - 1)
                          : swi_fail(err, errlen, 2, "%s:%ld: NUL byte in the line (not a text file?)",
                                     path, lineno);
            goto done;
        }
        if (lineno == 1 || line[0] == '#' || line[strspn(line, " \t\r\n")] == '\0')
            continue;   /* header, comments, blank lines */
        double a, b, c;
        char extra;
        if (sscanf(line, " %lf , %lf , %lf %c", &a, &b, &c, &extra) != 3) {
            char shown[80];
            printable(shown, sizeof shown, line);
            rc = swi_fail(err, errlen, 2, "%s:%ld: expected 'y,z,value', got '%s'", path, lineno,
                          shown);
            goto done;
        }
        if (!isfinite(a) || !isfinite(b) || !isfinite(c) || c < 0) {
            rc = swi_fail(err, errlen, 2, "%s:%ld: non-finite or negative value (y %g, z %g, value %g)",
                      path, lineno, a, b, c);
            goto done;
        }
        if (n == SWI_SIMMAP_MAX_FACES) {
            rc = swi_fail(err, errlen, 2, "%s:%ld: more than %d faces", path, lineno,
                          SWI_SIMMAP_MAX_FACES);
            goto done;
        }
        if (n == cap) {
            cap *= 2;
            double *ny = realloc(y, cap * sizeof *y); if (ny) y = ny;
            double *nz = realloc(z, cap * sizeof *z); if (nz) z = nz;
            double *nv = realloc(v, cap * sizeof *v); if (nv) v = nv;
            if (!ny || !nz || !nv) { rc = swi_fail(err, errlen, 1, "%s: out of memory", path); goto done; }
        }
        y[n] = a; z[n] = b; v[n] = c; n++;
    }
    if (ferror(f)) { rc = swi_fail(err, errlen, 2, "%s: read error (%s)", path, strerror(errno)); goto done; }
    if (n < 4) { rc = swi_fail(err, errlen, 2, "%s: %zu face values, need a grid of at least 2x2", path, n); goto done; }
    sy = malloc(n * sizeof *sy); sz = malloc(n * sizeof *sz);
    uy = malloc(n * sizeof *uy); uz = malloc(n * sizeof *uz);
    if (!sy || !sz || !uy || !uz) { rc = swi_fail(err, errlen, 1, "%s: out of memory", path); goto done; }
    memcpy(sy, y, n * sizeof *sy); memcpy(sz, z, n * sizeof *sz);
    qsort(sy, n, sizeof *sy, cmp_double); qsort(sz, n, sizeof *sz, cmp_double);
    double span = fmax(sy[n - 1] - sy[0], sz[n - 1] - sz[0]);
    double tol = 1e-6 * (span > 0 ? span : 1);
    int ny = distinct(sy, (int)n, tol, uy), nz = distinct(sz, (int)n, tol, uz);
    if (ny < 2 || nz < 2 || (size_t)ny * (size_t)nz != n) {
        rc = swi_fail(err, errlen, 2, "%s: %zu faces do not form a full regular grid (%d distinct y x %d distinct z)",
                  path, n, ny, nz);
        goto done;
    }
    double dy = (uy[ny - 1] - uy[0]) / (ny - 1), dz = (uz[nz - 1] - uz[0]) / (nz - 1);
    for (int i = 1; i < ny; i++)
        if (fabs(uy[i] - uy[i - 1] - dy) > 1e-3 * dy) {
            rc = swi_fail(err, errlen, 2, "%s: face centres are not evenly spaced in y (%g .. %g)", path, uy[i - 1], uy[i]);
            goto done;
        }
    for (int i = 1; i < nz; i++)
        if (fabs(uz[i] - uz[i - 1] - dz) > 1e-3 * dz) {
            rc = swi_fail(err, errlen, 2, "%s: face centres are not evenly spaced in z (%g .. %g)", path, uz[i - 1], uz[i]);
            goto done;
        }
    m = calloc(1, sizeof *m);
    if (!m || !(m->val = calloc(n, sizeof *m->val))) { rc = swi_fail(err, errlen, 1, "%s: out of memory", path); goto done; }
    m->ny = ny; m->nz = nz;
    m->y0 = uy[0] - dy / 2; m->y1 = uy[ny - 1] + dy / 2;
    m->z0 = uz[0] - dz / 2; m->z1 = uz[nz - 1] + dz / 2;
    char *seen = calloc(n, 1);
    if (!seen) { rc = swi_fail(err, errlen, 1, "%s: out of memory", path); goto done; }
    for (size_t i = 0; i < n; i++) {
        int iy = find_index(uy, ny, y[i], tol), iz = find_index(uz, nz, z[i], tol);
        size_t k = (size_t)iy + (size_t)ny * (size_t)iz;
        if (iy < 0 || iz < 0 || seen[k]) {
            free(seen);
            rc = swi_fail(err, errlen, 2, "%s: face (%g, %g) appears twice", path, y[i], z[i]);
            goto done;
        }
        seen[k] = 1;
        m->val[k] = v[i];
        if (v[i] > m->vmax) m->vmax = v[i];
    }
    free(seen);
    *out = m;
    m = NULL;
done:
    free(y); free(z); free(v); free(sy); free(sz); free(uy); free(uz);
    swi_simmap_free(m);
    return rc;
}

int swi_simmap_read(const char *path, swi_simmap **out, char *err, size_t errlen)
{
    *out = NULL;
    FILE *f = fopen(path, "r");
    if (!f)
        return swi_fail(err, errlen, 2, "%s: cannot open (%s)", path, strerror(errno));
    int rc = simmap_read_stream(f, path, out, err, errlen);
    fclose(f);
    return rc;
}

int swi_simmap_read_mem(const char *data, size_t n, const char *name, swi_simmap **out,
                        char *err, size_t errlen)
{
    *out = NULL;
    if (!name)
        name = "(memory)";
    if (!data || n == 0)
        return swi_fail(err, errlen, 2, "%s: empty, need a header and a grid of at least 2x2", name);
    /* read-only use of data: fmemopen's buffer is not const in its prototype */
    FILE *f = fmemopen((void *)(uintptr_t)data, n, "r");
    if (!f)
        return swi_fail(err, errlen, 1, "%s: fmemopen failed (%s)", name, strerror(errno));
    int rc = simmap_read_stream(f, name, out, err, errlen);
    fclose(f);
    return rc;
}

double swi_simmap_at(const swi_simmap *m, double u, double v)
{
    int iy = (int)floor(u * m->ny), iz = (int)floor((1 - v) * m->nz);
    if (iy < 0) iy = 0;
    if (iy >= m->ny) iy = m->ny - 1;
    if (iz < 0) iz = 0;
    if (iz >= m->nz) iz = m->nz - 1;
    return m->val[iy + m->ny * iz];
}

void swi_config_defaults(swi_config *c)
{
    memset(c, 0, sizeof *c);
    c->photoThreshold = 0.5;
    c->simThreshold = -1;
    c->simRelThreshold = 0.1;
    c->res = 200;
}

static const char *const corner_name[4] = {"top-left", "top-right", "bottom-right", "bottom-left"};

static double cross3(const double a[2], const double b[2], const double c[2])
{
    return (b[0] - a[0]) * (c[1] - b[1]) - (b[1] - a[1]) * (c[0] - b[0]);
}

int swi_corners_check(const double c[4][2], int width, int height, char *err, size_t errlen)
{
    for (int i = 0; i < 4; i++) {
        double x = c[i][0], y = c[i][1];
        if (!isfinite(x) || !isfinite(y))
            return swi_fail(err, errlen, 2, "corner %d (%s, %g,%g) is not a finite point", i + 1,
                            corner_name[i], x, y);
        if (x < 0 || y < 0 || x > width || y > height)
            return swi_fail(err, errlen, 2, "corner %d (%s, %g,%g) lies outside the %dx%d photo",
                            i + 1, corner_name[i], x, y, width, height);
    }
    /* turn at every corner: > 0 clockwise on the image (y down), the order
     * top-left, top-right, bottom-right, bottom-left seen from behind */
    double scale = 0, turn[4];
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++)
            scale = fmax(scale, hypot(c[i][0] - c[j][0], c[i][1] - c[j][1]));
    int pos = 0, neg = 0;
    for (int i = 0; i < 4; i++) {
        int a = (i + 3) % 4, b = (i + 1) % 4;
        turn[i] = cross3(c[a], c[i], c[b]);
        if (!(fabs(turn[i]) > 1e-12 * scale * scale))
            return swi_fail(err, errlen, 2,
                            "corners %d, %d, %d (%s, %s, %s) lie on one line or coincide: no "
                            "quadrilateral",
                            a + 1, i + 1, b + 1, corner_name[a], corner_name[i], corner_name[b]);
        if (turn[i] > 0) pos++; else neg++;
    }
    if (pos == 2) {
        /* two left and two right turns: two opposite sides cross */
        int k = (turn[0] > 0) == (turn[1] > 0) ? 1 : 0;   /* sides k..k+1 and k+2..k+3 */
        return swi_fail(err, errlen, 2,
                        "the side from corner %d to %d crosses the side from corner %d to %d (a "
                        "bow-tie): give top-left, top-right, bottom-right, bottom-left in this order",
                        k + 1, k + 2, k + 3, (k + 3) % 4 + 1);
    }
    if (pos == 1 || neg == 1) {
        int r = 0;
        for (int i = 0; i < 4; i++)
            if ((turn[i] > 0) == (pos == 1))
                r = i;
        return swi_fail(err, errlen, 2,
                        "the quadrilateral is concave at corner %d (%s, %g,%g): a face seen in "
                        "perspective is convex",
                        r + 1, corner_name[r], c[r][0], c[r][1]);
    }
    if (neg == 4)
        return swi_fail(err, errlen, 2,
                        "the corners run counter-clockwise on the image (a mirrored face): give "
                        "top-left, top-right, bottom-right, bottom-left as seen from behind");
    /* convex: the width is the smallest extent across a side's direction */
    double wmin = INFINITY, area = 0;
    for (int i = 0; i < 4; i++) {
        const int b = (i + 1) % 4;
        const double len = hypot(c[b][0] - c[i][0], c[b][1] - c[i][1]);
        double h = 0;
        for (int j = 0; j < 4; j++)
            h = fmax(h, fabs(cross3(c[i], c[b], c[j])) / len);
        wmin = fmin(wmin, h);
        area += c[i][0] * c[b][1] - c[b][0] * c[i][1];
    }
    area = fabs(area) / 2;
    if (wmin < SWI_CORNERS_MIN_WIDTH || area < SWI_CORNERS_MIN_AREA)
        return swi_fail(err, errlen, 2,
                        "the face covers %.3g px^2 and is %.3g px wide in the photo; at least %g "
                        "px^2 and %g px are needed",
                        area, wmin, SWI_CORNERS_MIN_AREA, SWI_CORNERS_MIN_WIDTH);
    return 0;
}

static double ratio1(long num, long den) { return den > 0 ? (double)num / (double)den : 1.0; }

void swi_metrics_from_counts(swi_metrics *m)
{
    m->precision = ratio1(m->tp, m->tp + m->fp);
    m->recall = ratio1(m->tp, m->tp + m->fn);
    m->iou = ratio1(m->tp, m->tp + m->fp + m->fn);
    m->dice = ratio1(2 * m->tp, 2 * m->tp + m->fp + m->fn);
    long all = m->tp + m->fp + m->fn + m->tn;
    m->photoSnowFraction = all > 0 ? (double)(m->tp + m->fn) / (double)all : 0;
    m->simSnowFraction = all > 0 ? (double)(m->tp + m->fp) / (double)all : 0;
}

static void put(swi_image *img, int x, int y, unsigned char r, unsigned char g, unsigned char b)
{
    unsigned char *p = img->rgb + ((size_t)y * (size_t)img->width + (size_t)x) * 3u;
    p[0] = r; p[1] = g; p[2] = b;
}

/* white -> blue colour map, t in [0, 1] */
static void cmap(double t, unsigned char *r, unsigned char *g, unsigned char *b)
{
    if (!(t > 0)) t = 0;
    if (t > 1) t = 1;
    *r = (unsigned char)lround(247 + t * (8 - 247));
    *g = (unsigned char)lround(251 + t * (48 - 251));
    *b = (unsigned char)lround(255 + t * (107 - 255));
}

int swi_compare_run(const swi_config *c, const swi_image *photo, const swi_simmap *sim,
                    swi_metrics *m, swi_image **side, char *err, size_t errlen)
{
    if (side) *side = NULL;
    memset(m, 0, sizeof *m);
    if (!(c->photoThreshold >= 0 && c->photoThreshold <= 1))
        return swi_fail(err, errlen, 2, "photo threshold %g outside [0, 1]", c->photoThreshold);
    if (c->simThreshold < 0 && !(c->simRelThreshold > 0 && c->simRelThreshold <= 1))
        return swi_fail(err, errlen, 2, "relative simulation threshold %g outside (0, 1]", c->simRelThreshold);
    if (!isfinite(c->simThreshold))
        return swi_fail(err, errlen, 2, "simulation threshold %g is not finite", c->simThreshold);
    if (c->res < 2 || c->res > 4000)
        return swi_fail(err, errlen, 2, "comparison resolution %d outside 2..4000", c->res);
    int rc = swi_corners_check(c->corners, photo->width, photo->height, err, errlen);
    if (rc)
        return rc;
    const double unit[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    double H[9];
    rc = swi_homography_solve(unit, c->corners, H, err, errlen);
    if (rc)
        return rc;
    double thr = c->simThreshold >= 0 ? c->simThreshold : c->simRelThreshold * sim->vmax;
    m->simThresholdUsed = thr;
    int R = c->res;
    swi_image *img = NULL;
    if (side) {
        img = swi_image_alloc(3 * R + 2 * 8, R);
        if (!img)
            return swi_fail(err, errlen, 1, "out of memory for the %dx%d side-by-side image", 3 * R + 16, R);
        memset(img->rgb, 255, (size_t)img->width * (size_t)img->height * 3u);
    }
    for (int j = 0; j < R; j++) {
        for (int i = 0; i < R; i++) {
            double u = (i + 0.5) / R, v = (j + 0.5) / R, px, py;
            if (swi_homography_apply(H, u, v, &px, &py)) {
                swi_image_free(img);
                return swi_fail(err, errlen, 2, "corners give a map that sends face point (%g, %g) to infinity", u, v);
            }
            double L = swi_image_luma(photo, px, py);
            int ps = L >= c->photoThreshold;
            double sv = swi_simmap_at(sim, u, v);
            int ss = sim->vmax > 0 ? sv >= thr : 0;
            if (ps && ss) m->tp++;
            else if (ss) m->fp++;
            else if (ps) m->fn++;
            else m->tn++;
            if (img) {
                unsigned char g = (unsigned char)lround(L * 255), r, gg, b;
                put(img, i, j, g, g, g);
                cmap(sim->vmax > 0 ? sv / sim->vmax : 0, &r, &gg, &b);
                if (ss) { /* thresholded: darker outline-free tint */ }
                put(img, R + 8 + i, j, r, gg, b);
                if (ps && ss) put(img, 2 * R + 16 + i, j, 255, 255, 255);
                else if (ss) put(img, 2 * R + 16 + i, j, 220, 40, 40);
                else if (ps) put(img, 2 * R + 16 + i, j, 40, 90, 220);
                else put(img, 2 * R + 16 + i, j, 60, 60, 60);
            }
        }
    }
    swi_metrics_from_counts(m);
    if (side) *side = img;
    return 0;
}

size_t swi_md_cell(const char *text, char *out, size_t outlen)
{
    size_t k = 0;
    for (const unsigned char *p = (const unsigned char *)text; *p; p++) {
        char buf[2];
        size_t m = 0;
        if (*p < 0x20 || *p == 0x7f)
            buf[m++] = ' ';                 /* newline, tab, ...: the row stays one line */
        else {
            if (*p == '|' || *p == '\\' || *p == '`' || *p == '<')
                buf[m++] = '\\';
            buf[m++] = (char)*p;
        }
        for (size_t i = 0; i < m; i++, k++)
            if (k + 1 < outlen)
                out[k] = buf[i];
    }
    if (outlen)
        out[k < outlen ? k : outlen - 1] = '\0';
    return k;
}

const char *swi_region_name(int r)
{
    static const char *names[SWI_NREGIONS] = {"left side", "right side", "centre", "edges"};
    return r >= 0 && r < SWI_NREGIONS ? names[r] : "?";
}

int swi_regions(const swi_simmap *sim, double threshold, double band, double holdFraction,
                swi_region_stats *s, char *err, size_t errlen)
{
    memset(s, 0, sizeof *s);
    if (!(threshold >= 0) || !isfinite(threshold))
        return swi_fail(err, errlen, 2, "region threshold %g must be >= 0", threshold);
    if (!(band > 0 && band < 0.3))
        return swi_fail(err, errlen, 2, "edge band %g outside (0, 0.3)", band);
    if (!(holdFraction > 0 && holdFraction <= 1))
        return swi_fail(err, errlen, 2, "hold fraction %g outside (0, 1]", holdFraction);
    int hit[SWI_NREGIONS] = {0};
    const double faceArea = (sim->y1 - sim->y0) / sim->ny * ((sim->z1 - sim->z0) / sim->nz);
    for (int iz = 0; iz < sim->nz; iz++) {
        for (int iy = 0; iy < sim->ny; iy++) {
            double u = (iy + 0.5) / sim->ny, v = 1 - (iz + 0.5) / sim->nz;
            double val = sim->val[iy + sim->ny * iz];
            int r;
            if (u < band || u > 1 - band || v < band || v > 1 - band) r = SWI_REGION_EDGES;
            else if (u < 0.35) r = SWI_REGION_LEFT;
            else if (u > 0.65) r = SWI_REGION_RIGHT;
            else if (v >= 0.3 && v <= 0.7) r = SWI_REGION_CENTRE;
            else continue;      /* above / below the centre: in no region */
            s->nfaces[r]++;
            s->mean[r] += val;
            s->mass[r] += val * faceArea;
            if (val >= threshold && val > 0) hit[r]++;
        }
    }
    for (int r = 0; r < SWI_NREGIONS; r++) {
        if (s->nfaces[r] == 0)
            return swi_fail(err, errlen, 2, "the %dx%d map has no face in region '%s' (too coarse)",
                        sim->ny, sim->nz, swi_region_name(r));
        s->mean[r] /= s->nfaces[r];
        s->covered[r] = (double)hit[r] / s->nfaces[r];
        s->holds[r] = s->covered[r] >= holdFraction;
    }
    return 0;
}
