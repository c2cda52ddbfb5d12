/* sbd_body.c - the square-back Ahmed body's surface: parameters and the
 * triangulation (see sbd_body.h for the geometry). */
#include "sbd_body.h"
#include "swo_err.h"

#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#define SBD_MAX_VERTS 20000000u   /* a guard against absurd resolutions */

void sbd_params_default(sbd_params *p)
{
    /* Ahmed, Ramm & Faltin (1984): 1044 x 389 x 288 mm, 50 mm clearance,
     * front radius 100 mm, stilts of 30 mm diameter; the stilts' positions
     * (202 and 672 mm behind the nose, 163.5 mm either side of the centre
     * line) as in the drawing's reconstructions (doc/reference/ahmed.md) */
    *p = (sbd_params){
        .length = 1.044, .width = 0.389, .height = 0.288, .clearance = 0.050,
        .radius = 0.100, .stilt_radius = 0.015, .stilt_x1 = 0.202, .stilt_x2 = 0.672,
        .stilt_y = 0.1635, .stilt_below = 0.010, .stilt_into = 0.010,
        .sensor_width = 0.050, .sensor_height = 0.040, .sensor_y = 0.0, .sensor_z = 0.266,
        .cell = 0.010, .arc_steps = 16, .stilt_sides = 32,
    };
}

static const struct { const char *key; size_t off; int is_int; } sbd_keys[] = {
#define K(f) { #f, offsetof(sbd_params, f), 0 }
    K(length), K(width), K(height), K(clearance), K(radius), K(stilt_radius),
    K(stilt_x1), K(stilt_x2), K(stilt_y), K(stilt_below), K(stilt_into),
    K(sensor_width), K(sensor_height), K(sensor_y), K(sensor_z), K(cell),
#undef K
    { "arc_steps", offsetof(sbd_params, arc_steps), 1 },
    { "stilt_sides", offsetof(sbd_params, stilt_sides), 1 },
};

const char *sbd_params_keys(void)
{
    return "length width height clearance radius stilt_radius stilt_x1 stilt_x2 stilt_y "
           "stilt_below stilt_into sensor_width sensor_height sensor_y sensor_z cell "
           "arc_steps stilt_sides";
}

int sbd_params_set(sbd_params *p, const char *kv, char *err, size_t errlen)
{
    const char *eq = strchr(kv, '=');
    if (!eq || eq == kv)
        return swo_fail(-1, err, errlen, "'%s' is not key=value", kv);
    size_t klen = (size_t)(eq - kv);
    const char *val = eq + 1;
    for (size_t i = 0; i < sizeof sbd_keys / sizeof sbd_keys[0]; i++) {
        if (strlen(sbd_keys[i].key) != klen || strncmp(sbd_keys[i].key, kv, klen))
            continue;
        char *end;
        errno = 0;
        if (sbd_keys[i].is_int) {
            long n = strtol(val, &end, 10);
            if (end == val || *end || errno || n < 1 || n > 100000)
                return swo_fail(-1, err, errlen, "%.*s: '%s' is not a whole number from 1 to 100000",
                                (int)klen, kv, val);
            *(int *)((char *)p + sbd_keys[i].off) = (int)n;
        } else {
            double d = strtod(val, &end);
            if (end == val || *end || errno || !isfinite(d) || strpbrk(val, "xX"))
                return swo_fail(-1, err, errlen, "%.*s: '%s' is not a finite decimal number",
                                (int)klen, kv, val);
            *(double *)((char *)p + sbd_keys[i].off) = d;
        }
        return 0;
    }
    return swo_fail(-1, err, errlen, "unknown key '%.*s' (keys: %s)", (int)klen, kv, sbd_params_keys());
}

int sbd_params_check(const sbd_params *p, char *err, size_t errlen)
{
    const double len[] = { p->length, p->width, p->height, p->clearance, p->radius,
                           p->stilt_radius, p->sensor_width, p->sensor_height, p->cell };
    const char *name[] = { "length", "width", "height", "clearance", "radius",
                           "stilt_radius", "sensor_width", "sensor_height", "cell" };
    for (size_t i = 0; i < sizeof len / sizeof len[0]; i++)
        if (!(len[i] > 0 && len[i] <= 1e3))
            return swo_fail(-1, err, errlen, "%s must be in (0, 1000] m, got %g", name[i], len[i]);
    if (!(2 * p->radius < p->width && 2 * p->radius < p->height && p->radius < p->length))
        return swo_fail(-1, err, errlen, "radius %g m does not fit: it must be below half the width, "
                        "half the height and the length", p->radius);
    if (!(p->stilt_below >= 0 && p->stilt_into > 0 && p->stilt_into < p->height - p->radius))
        return swo_fail(-1, err, errlen, "stilt_below must be >= 0 and stilt_into in (0, height - radius)");
    for (int k = 0; k < 2; k++) {
        double x = k ? p->stilt_x2 : p->stilt_x1;
        if (!(x - p->stilt_radius > p->radius && x + p->stilt_radius < p->length))
            return swo_fail(-1, err, errlen, "stilt_x%d %g m: a stilt must stand under the flat "
                            "underside (between radius and length)", k + 1, x);
    }
    if (!(p->stilt_y - p->stilt_radius > 0 && p->stilt_y + p->stilt_radius < p->width / 2))
        return swo_fail(-1, err, errlen, "stilt_y %g m: the stilts must stand under the body, "
                        "clear of the centreline", p->stilt_y);
    if (fabs(p->stilt_x1 - p->stilt_x2) < 2 * p->stilt_radius)
        return swo_fail(-1, err, errlen, "the stilts overlap (stilt_x1 and stilt_x2 closer than a diameter)");
    double y0 = p->sensor_y - p->sensor_width / 2, y1 = p->sensor_y + p->sensor_width / 2;
    double z0 = p->sensor_z - p->sensor_height / 2, z1 = p->sensor_z + p->sensor_height / 2;
    if (!(y0 > -p->width / 2 && y1 < p->width / 2 && z0 > p->clearance && z1 < p->clearance + p->height))
        return swo_fail(-1, err, errlen, "the sensor (%g x %g m at y %g, z %g) must lie inside the rear face",
                        p->sensor_width, p->sensor_height, p->sensor_y, p->sensor_z);
    if (p->arc_steps < 2 || p->arc_steps > 1000 || p->stilt_sides < 6 || p->stilt_sides > 10000)
        return swo_fail(-1, err, errlen, "arc_steps must be 2..1000 and stilt_sides 6..10000");
    double n = (p->width / p->cell + 8) * (p->height / p->cell + 8) * 2
             + 2 * (p->width + p->height) / p->cell * (p->length / p->cell + p->arc_steps);
    if (!(n < SBD_MAX_VERTS))
        return swo_fail(-1, err, errlen, "cell %g m is too small for this body (about %.3g vertices; "
                        "at most %u)", p->cell, n, SBD_MAX_VERTS);
    return 0;
}

double sbd_body_volume_exact(const sbd_params *p)
{
    double W = p->width, H = p->height, L = p->length, R = p->radius;
    double a = W / 2 - R, c = H - 2 * R;
    /* the front's cross-section (2a + 2r)(c + 2r) integrated over [0, R]:
     * int r dx = pi R^2 / 4, int r^2 dx = 2 R^3 / 3 */
    double front = 2 * a * c * R + (4 * a + 2 * c) * M_PI * R * R / 4 + 4 * (2 * R * R * R / 3);
    return W * H * (L - R) + front;
}

const char *sbd_region_name(int region)
{
    static const char *names[SBD_NREGION] = { "nose", "top", "bottom", "sides", "rear", "sensor", "stilts" };
    return region >= 0 && region < SBD_NREGION ? names[region] : "?";
}

/* ------------------------------------------------------------------ building */

typedef struct {
    sbd_surface *s;
    size_t cap_v, cap_t;
    int failed;
} sbd_builder;

static size_t add_v(sbd_builder *b, double x, double y, double z)
{
    sbd_surface *s = b->s;
    if (s->nv == b->cap_v) {
        size_t n = b->cap_v ? 2 * b->cap_v : 1024;
        void *v = realloc(s->v, n * sizeof *s->v);
        if (!v) { b->failed = 1; return 0; }
        s->v = v;
        b->cap_v = n;
    }
    s->v[s->nv][0] = x; s->v[s->nv][1] = y; s->v[s->nv][2] = z;
    return s->nv++;
}

static void add_t(sbd_builder *b, size_t i, size_t j, size_t k, int region)
{
    sbd_surface *s = b->s;
    if (b->failed) return;
    if (s->nt == b->cap_t) {
        size_t n = b->cap_t ? 2 * b->cap_t : 2048;
        void *t = realloc(s->t, n * sizeof *s->t);
        if (!t) { b->failed = 1; return; }
        s->t = t;
        void *r = realloc(s->region, n * sizeof *s->region);
        if (!r) { b->failed = 1; return; }
        s->region = r;
        b->cap_t = n;
    }
    s->t[s->nt][0] = i; s->t[s->nt][1] = j; s->t[s->nt][2] = k;
    s->region[s->nt] = region;
    s->nt++;
}

/* a quad a-b-c-d, counter-clockwise seen from outside */
static void add_q(sbd_builder *b, size_t a, size_t c1, size_t c2, size_t d, int region)
{
    add_t(b, a, c1, c2, region);
    add_t(b, a, c2, d, region);
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* the coordinates in [-1, 1] of the lines across one side of a station: about
 * 2/step uniform segments, plus the sensor's edges s0 < s1; points closer than
 * a third of a step to an edge are dropped (no slivers) */
static double *grid_1d(double step, double s0, double s1, size_t *n_out)
{
    size_t nseg = (size_t)ceil(2 / step);
    if (nseg < 2) nseg = 2;
    double *u = malloc((nseg + 3) * sizeof *u);
    if (!u) return NULL;
    double h = 2.0 / (double)nseg, tol = h / 3;
    size_t n = 0;
    for (size_t i = 0; i <= nseg; i++) {
        double x = -1 + h * (double)i;
        if (i == nseg) x = 1;
        int end = i == 0 || i == nseg;
        if (!end && (fabs(x - s0) < tol || fabs(x - s1) < tol))
            continue;
        u[n++] = x;
    }
    u[n++] = s0;
    u[n++] = s1;
    qsort(u, n, sizeof *u, cmp_double);
    *n_out = n;
    return u;
}

/* the body's shell: stations along x, each a rectangle traced through the
 * same (u, v) lines; the nose cap at x = 0 and the rear cap at x = L */
static void build_body(sbd_builder *b, const sbd_params *p, const double *u, size_t nu1,
                       const double *v, size_t nv1)
{
    double W = p->width, H = p->height, L = p->length, R = p->radius, h = p->clearance;
    double a = W / 2 - R, c2 = H / 2 - R, zmid = h + H / 2;
    size_t nu = nu1 - 1, nv = nv1 - 1, M = 2 * nu + 2 * nv;
    size_t nstraight = (size_t)ceil((L - R) / p->cell);
    if (nstraight < 1) nstraight = 1;
    size_t K = (size_t)p->arc_steps, nst = K + 1 + nstraight;
    size_t *first = malloc(nst * sizeof *first);   /* first loop vertex of each station */
    size_t *g = malloc(nu1 * nv1 * sizeof *g);      /* a cap's grid of vertex indices */
    if (!first || !g) { b->failed = 1; free(first); free(g); return; }

    for (size_t s = 0; s < nst; s++) {
        double x, r;
        if (s <= K) {
            double th = (M_PI / 2) * (double)s / (double)K;
            x = s == K ? R : R * (1 - cos(th));
            r = s == K ? R : R * sin(th);
        } else {
            x = s == nst - 1 ? L : R + (L - R) * (double)(s - K) / (double)nstraight;
            r = R;
        }
        double hw = a + r, hh = c2 + r;
        first[s] = b->s->nv;
        /* the loop: bottom (u up), right side (v up), top (u down), left (v down) */
        for (size_t i = 0; i < nu; i++) add_v(b, x, u[i] * hw, zmid - hh);
        for (size_t j = 0; j < nv; j++) add_v(b, x, hw, zmid + v[j] * hh);
        for (size_t i = nu; i > 0; i--) add_v(b, x, u[i] * hw, zmid + hh);
        for (size_t j = nv; j > 0; j--) add_v(b, x, -hw, zmid + v[j] * hh);
    }
    /* the lateral quads between stations: the loop runs counter-clockwise in
     * (y, z), so (s, i) (s, i+1) (s+1, i+1) (s+1, i) faces outwards */
    for (size_t s = 0; s + 1 < nst; s++)
        for (size_t i = 0; i < M; i++) {
            int reg = SBD_NOSE;
            if (s >= K)
                reg = i < nu ? SBD_BOTTOM : i < nu + nv ? SBD_SIDES : i < 2 * nu + nv ? SBD_TOP : SBD_SIDES;
            size_t i1 = (i + 1) % M;
            add_q(b, first[s] + i, first[s] + i1, first[s + 1] + i1, first[s + 1] + i, reg);
        }
    /* the caps: a grid whose border is the end station's loop */
    double y0 = p->sensor_y - p->sensor_width / 2, y1 = p->sensor_y + p->sensor_width / 2;
    double z0 = p->sensor_z - p->sensor_height / 2, z1 = p->sensor_z + p->sensor_height / 2;
    for (int rear = 0; rear <= 1; rear++) {
        size_t s = rear ? nst - 1 : 0;
        double x = rear ? L : 0, hw = rear ? W / 2 : a, hh = rear ? H / 2 : c2;
        for (size_t j = 0; j <= nv; j++)
            for (size_t i = 0; i <= nu; i++) {
                size_t pos;
                if (j == 0) pos = i;
                else if (i == nu) pos = nu + j;
                else if (j == nv) pos = nu + nv + (nu - i);
                else if (i == 0) pos = 2 * nu + nv + (nv - j);
                else { g[j * nu1 + i] = add_v(b, x, u[i] * hw, zmid + v[j] * hh); continue; }
                g[j * nu1 + i] = first[s] + pos % M;
            }
        for (size_t j = 0; j < nv; j++)
            for (size_t i = 0; i < nu; i++) {
                size_t q00 = g[j * nu1 + i], q10 = g[j * nu1 + i + 1];
                size_t q11 = g[(j + 1) * nu1 + i + 1], q01 = g[(j + 1) * nu1 + i];
                if (!rear) { add_q(b, q00, q01, q11, q10, SBD_NOSE); continue; }
                double yc = (u[i] + u[i + 1]) / 2 * hw, zc = zmid + (v[j] + v[j + 1]) / 2 * hh;
                int reg = yc > y0 && yc < y1 && zc > z0 && zc < z1 ? SBD_SENSOR : SBD_REAR;
                add_q(b, q00, q10, q11, q01, reg);
            }
    }
    free(first);
    free(g);
}

/* a stilt: a closed polygonal cylinder from below the ground into the body */
static void build_stilt(sbd_builder *b, const sbd_params *p, double xc, double yc)
{
    size_t n = (size_t)p->stilt_sides;
    double zb = -p->stilt_below, zt = p->clearance + p->stilt_into, r = p->stilt_radius;
    size_t cb = add_v(b, xc, yc, zb), ct = add_v(b, xc, yc, zt), f = b->s->nv;
    for (size_t k = 0; k < n; k++) {
        double t = 2 * M_PI * (double)k / (double)n;
        add_v(b, xc + r * cos(t), yc + r * sin(t), zb);
        add_v(b, xc + r * cos(t), yc + r * sin(t), zt);
    }
    for (size_t k = 0; k < n; k++) {
        size_t k1 = (k + 1) % n;
        size_t b0 = f + 2 * k, t0 = b0 + 1, b1 = f + 2 * k1, t1 = b1 + 1;
        add_q(b, b0, b1, t1, t0, SBD_STILTS);   /* side: counter-clockwise in (x, y) */
        add_t(b, cb, b1, b0, SBD_STILTS);       /* bottom faces -z */
        add_t(b, ct, t0, t1, SBD_STILTS);       /* top faces +z */
    }
}

int sbd_build(const sbd_params *p, sbd_surface **out, char *err, size_t errlen)
{
    *out = NULL;
    if (sbd_params_check(p, err, errlen))
        return -1;
    sbd_surface *s = calloc(1, sizeof *s);
    if (!s)
        return swo_fail(-1, err, errlen, "out of memory");
    sbd_builder b = { .s = s };
    size_t nu1, nv1;
    double *u = grid_1d(p->cell / (p->width / 2), (p->sensor_y - p->sensor_width / 2) / (p->width / 2),
                        (p->sensor_y + p->sensor_width / 2) / (p->width / 2), &nu1);
    double zmid = p->clearance + p->height / 2;
    double *v = grid_1d(p->cell / (p->height / 2), (p->sensor_z - p->sensor_height / 2 - zmid) / (p->height / 2),
                        (p->sensor_z + p->sensor_height / 2 - zmid) / (p->height / 2), &nv1);
    if (!u || !v) b.failed = 1;
    if (!b.failed) build_body(&b, p, u, nu1, v, nv1);
    free(u);
    free(v);
    for (int k = 0; k < 4 && !b.failed; k++)
        build_stilt(&b, p, k < 2 ? p->stilt_x1 : p->stilt_x2, k % 2 ? p->stilt_y : -p->stilt_y);
    if (b.failed) {
        sbd_free(s);
        return swo_fail(-1, err, errlen, "out of memory building the surface");
    }
    *out = s;
    return 0;
}

void sbd_free(sbd_surface *s)
{
    if (!s) return;
    free(s->v);
    free(s->t);
    free(s->region);
    free(s);
}
