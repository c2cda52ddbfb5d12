/* swe_post.c - the per-run post-processing of the wedge: readers of the
 * run's OpenFOAM tables and the numbers made from them (swe_post.h). */
#include "swe_post.h"
#include "swo_err.h"

#include <dirent.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#define fail swo_fail  /* common/swo_err.h */

double swe_post_round(double v, int digits)
{
    char buf[64];
    snprintf(buf, sizeof buf, "%.*g", digits, v);
    return strtod(buf, NULL);
}

double swe_post_awk_str(double v)
{
    if (isfinite(v) && fabs(v) < 1e15 && v == (double)(long long)v)
        return v;
    return swe_post_round(v, 6);
}

int swe_post_same_time(double a, double t)
{
    return fabs(a - t) <= 1e-9 + 1e-6 * t;
}

/* the blank-separated fields of a line (modified in place) */
static int fields(char *line, char **f, int max)
{
    int n = 0;
    for (char *t = strtok(line, " \t\r\n"); t && n < max; t = strtok(NULL, " \t\r\n"))
        f[n++] = t;
    return n;
}

enum { MAXF = 512, LINE = 16384 };

int swe_post_field_at(const char *path, const char *col, const char *ts, double *v, char *err,
                      size_t nerr)
{
    const int last = !strcmp(ts, "last");
    const double t = last ? 0 : strtod(ts, NULL);
    FILE *fp = fopen(path, "r");
    if (!fp)
        return fail(1, err, nerr, "cannot read %s", path);
    static char line[LINE];
    char *f[MAXF];
    int c = -1, ok = 0;
    while (fgets(line, sizeof line, fp)) {
        if (!strncmp(line, "# Time", 6)) {
            const int n = fields(line + 2, f, MAXF);
            for (int i = 0; i < n; i++)
                if (!strcmp(f[i], col))
                    c = i;
            continue;
        }
        if (line[0] == '#')
            continue;
        const int n = fields(line, f, MAXF);
        if (n > 1 && c >= 0 && (last || swe_post_same_time(strtod(f[0], NULL), t))) {
            *v = c < n ? strtod(f[c], NULL) : 0;
            ok = 1;
        }
    }
    fclose(fp);
    if (c < 0)
        return fail(2, err, nerr, "%s has no column %s", path, col);
    if (!ok)
        return fail(2, err, nerr, "%s has no row at time %s", path, ts);
    *v = swe_post_round(*v, 10);
    return 0;
}

int swe_post_area(const char *path, double *area)
{
    FILE *fp = fopen(path, "r");
    if (!fp)
        return 1;
    static char line[LINE];
    char *f[8];
    *area = 0;
    while (fgets(line, sizeof line, fp))
        if (!strncmp(line, "# Area", 6) && fields(line, f, 8) >= 4)
            *area = strtod(f[3], NULL);
    fclose(fp);
    return 0;
}

int swe_post_counts_at(const char *path, const char *patch, const char *ts, double c[5],
                       char *err, size_t nerr)
{
    const int last = !strcmp(ts, "last");
    const double t = last ? 0 : strtod(ts, NULL);
    static const char *what[5] = {"impacts", "sticks", "bounces", "ripoffs", "depositedMass[kg]"};
    FILE *fp = fopen(path, "r");
    if (!fp)
        return fail(1, err, nerr, "cannot read %s", path);
    static char line[LINE], best[LINE];
    char *f[MAXF];
    int col[5] = {-1, -1, -1, -1, -1}, have = 0;
    double bestd = 0;
    while (fgets(line, sizeof line, fp)) {
        if (line[0] == '#') {
            const int n = fields(line, f, MAXF);
            for (int k = 0; k < 5; k++) {
                char name[256];
                snprintf(name, sizeof name, "%s:%s", patch, what[k]);
                for (int i = 1; i < n; i++)
                    if (!strcmp(f[i], name))
                        col[k] = i - 1;
            }
            continue;
        }
        char copy[LINE];
        memcpy(copy, line, sizeof copy);
        if (fields(copy, f, MAXF) < 2)
            continue;
        const double d = fabs(strtod(f[0], NULL) - t);
        if (last || !have || d < bestd) {
            memcpy(best, line, sizeof best);
            bestd = d;
            have = 1;
        }
    }
    fclose(fp);
    const int n = have ? fields(best, f, MAXF) : 0;
    for (int k = 0; k < 5; k++)
        c[k] = (col[k] >= 0 && col[k] < n) ? swe_post_awk_str(strtod(f[col[k]], NULL)) : 0;
    return 0;
}

int swe_post_time_dir(const char *parent, const char *file, const char *ts, char *dir,
                      size_t ndir)
{
    const int last = !strcmp(ts, "last");
    const double t = last ? 0 : strtod(ts, NULL);
    dir[0] = 0;
    DIR *d = opendir(parent);
    if (!d)
        return 0;
    double bestv = -HUGE_VAL;
    char bestname[256] = "";
    for (struct dirent *e; (e = readdir(d));) {
        if (e->d_name[0] == '.')
            continue;
        char p[4096];
        struct stat st;
        snprintf(p, sizeof p, "%s/%s/%s", parent, e->d_name, file);
        if (stat(p, &st) || !S_ISREG(st.st_mode))
            continue;
        const double v = strtod(e->d_name, NULL);
        /* the latest, or the one at t (of two, the later name in glob order) */
        if (last ? v > bestv
                 : swe_post_same_time(v, t) && (!bestname[0] || strcmp(e->d_name, bestname) > 0)) {
            bestv = v;
            snprintf(bestname, sizeof bestname, "%s", e->d_name);
        }
    }
    closedir(d);
    snprintf(dir, ndir, "%s", bestname);
    return 0;
}

int swe_post_reasons(const char *path, const char *patch, long r[5], char *err, size_t nerr)
{
    FILE *fp = fopen(path, "r");
    if (!fp)
        return fail(1, err, nerr, "cannot read %s", path);
    static char line[LINE];
    char *f[MAXF];
    int ok = 0;
    while (fgets(line, sizeof line, fp)) {
        if (line[0] == '#')
            continue;
        const int n = fields(line, f, MAXF);
        if (n >= 1 && !strcmp(f[0], patch)) {
            for (int k = 0; k < 5; k++)
                r[k] = 3 + k < n ? (long)strtod(f[3 + k], NULL) : 0;
            ok = 1;
        }
    }
    fclose(fp);
    return ok ? 0 : fail(2, err, nerr, "%s has no line for patch %s", path, patch);
}

int swe_post_raw_read(const char *path, swe_post_raw *r, char *err, size_t nerr)
{
    memset(r, 0, sizeof *r);
    FILE *fp = fopen(path, "r");
    if (!fp)
        return fail(1, err, nerr, "cannot read %s", path);
    static char line[LINE];
    char *f[8];
    size_t cap = 0;
    while (fgets(line, sizeof line, fp)) {
        if (line[0] == '#' || fields(line, f, 8) != 4)
            continue;
        if (r->n == cap) {
            cap = cap ? 2 * cap : 1024;
            double *y = realloc(r->y, cap * sizeof *y), *z = realloc(r->z, cap * sizeof *z),
                   *v = realloc(r->v, cap * sizeof *v);
            r->y = y ? y : r->y;
            r->z = z ? z : r->z;
            r->v = v ? v : r->v;
            if (!y || !z || !v) {
                fclose(fp);
                swe_post_raw_free(r);
                return fail(1, err, nerr, "out of memory reading %s", path);
            }
        }
        r->y[r->n] = strtod(f[1], NULL);
        r->z[r->n] = strtod(f[2], NULL);
        r->v[r->n] = strtod(f[3], NULL);
        r->n++;
    }
    fclose(fp);
    return 0;
}

void swe_post_raw_free(swe_post_raw *r)
{
    free(r->y);
    free(r->z);
    free(r->v);
    memset(r, 0, sizeof *r);
}

static double last_number(char *line)
{
    char *f[MAXF];
    const int n = fields(line, f, MAXF);
    return n ? strtod(f[n - 1], NULL) : 0;
}

int swe_post_log_read(const char *path, const char *cloud, swe_post_log *l, char *err, size_t nerr)
{
    memset(l, 0, sizeof *l);
    FILE *fp = fopen(path, "r");
    if (!fp)
        return fail(1, err, nerr, "cannot read %s", path);
    static char line[LINE];
    char cur[256] = "", ev[256] = "";
    double inj = 0, np = 0;
    while (fgets(line, sizeof line, fp)) {
        char name[256];
        if (!strncmp(line, "Cloud: ", 7) && sscanf(line + 7, "%255s", name) == 1) {
            snprintf(cur, sizeof cur, "%s", name);
            if (!strcmp(cur, cloud))
                inj = np = 0;
            continue;
        }
        if (!strncmp(line, "Evolving ", 9) && sscanf(line + 9, "%255s", name) == 1)
            snprintf(ev, sizeof ev, "%s", name);
        else if (!strcmp(ev, cloud)) {
            const char *p = strstr(line, "parcelSplitting ");
            if (p && strstr(p + 16, "parcels split"))
                l->split = 1;
        }
        if (strcmp(cur, cloud))
            continue;
        if (strstr(line, "mass introduced"))
            inj += last_number(line);
        else if (strstr(line, "parcels added"))
            np += last_number(line);
        else if (strstr(line, "Current mass in system"))
            l->airborne = last_number(line);
    }
    fclose(fp);
    l->injected = swe_post_round(inj, 10);
    l->airborne = swe_post_round(l->airborne, 10);
    l->parcels = (long)np;
    return 0;
}

int swe_post_post_mass(const char *const *files, int nfiles, double *mass, char *err, size_t nerr)
{
    static char line[LINE];
    char *f[MAXF];
    int cn = -1, cd = -1, cr = -1;
    double m = 0;
    for (int k = 0; k < nfiles; k++) {
        FILE *fp = fopen(files[k], "r");
        if (!fp)
            return fail(1, err, nerr, "cannot read %s", files[k]);
        while (fgets(line, sizeof line, fp)) {
            const int n = fields(line, f, MAXF);
            if (line[0] == '#') {
                for (int i = 1; i < n; i++) {
                    cn = strcmp(f[i], "nParticle") ? cn : i - 1;
                    cd = strcmp(f[i], "d") ? cd : i - 1;
                    cr = strcmp(f[i], "rho") ? cr : i - 1;
                }
            } else if (n > 3 && cn >= 0 && cd >= 0 && cr >= 0) {
                const double vn = cn < n ? strtod(f[cn], NULL) : 0,
                             vd = cd < n ? strtod(f[cd], NULL) : 0,
                             vr = cr < n ? strtod(f[cr], NULL) : 0;
                m += vn * vr * SWE_POST_PI / 6 * pow(vd, 3);
            }
        }
        fclose(fp);
    }
    *mass = m;
    return 0;
}

void swe_post_halves(const double c0[5], const double ch[5], const double c1[5],
                     swe_post_halves_t *h)
{
    h->impacts = c1[0] - c0[0];
    h->sticks = c1[1] - c0[1];
    h->half1 = 2 * (ch[4] - c0[4]);
    h->half2 = 2 * (c1[4] - ch[4]);
    h->window = c1[4] - c0[4];
}

double swe_post_halves_diff(const swe_post_halves_t *h)
{
    if (!(h->half1 + h->half2 > 0))
        return NAN;
    return 100 * (h->half1 - h->half2) / ((h->half1 + h->half2) / 2);
}

double swe_post_poisson(double sticks)
{
    return sticks > 0 ? 100 / sqrt(sticks) : INFINITY;
}

double swe_post_stokes(double d_um)
{
    const double tau = SWE_POST_RHO_ICE * pow(d_um * 1e-6, 2) / (18 * SWE_POST_MU_AIR);
    return tau * SWE_POST_SPEED / SWE_POST_HEIGHT;
}

/* a / b; over 0 (no stationary rate seen) inf, or -nan for 0 / 0, as awk prints them */
static double ratio(double a, double b)
{
    if (b != 0)
        return a / b;
    return a > 0 ? INFINITY : a < 0 ? -INFINITY : -NAN;
}

/* the integral of the de-censored age density over the bins, window ta .. tb */
static double fill_rate(const double *mb, const char *has, long nb, double soi, double ta,
                        double tb)
{
    double s = 0;
    for (long k = 0; k < nb; k++) {
        if (!has[k])
            continue;
        double lo = soi + (k + 0.5) * 1e-3;
        lo = lo < ta ? ta : lo;
        if (tb - lo > 1e-9)
            s += mb[k] / (tb - lo);
    }
    return s;
}

int swe_post_fill(const swe_post_rec *r, size_t n, double soi, double t0, double t1, double F,
                  swe_post_fill_t *out)
{
    memset(out, 0, sizeof *out);
    const double th = (t0 + t1) / 2;
    long bmax = 0;
    double mh1 = 0, mh2 = 0;
    for (size_t i = 0; i < n; i++)
        if (r[i].t > t0 + 1e-12 && r[i].t <= t1 + 1e-12) {
            const long b = (long)(r[i].age / 1e-3);
            bmax = b > bmax ? b : bmax;
        }
    double *mb = calloc((size_t)bmax + 1, sizeof *mb);
    char *has = calloc((size_t)bmax + 1, 1);
    if (!mb || !has) {
        free(mb);
        free(has);
        return 1;
    }
    for (size_t i = 0; i < n; i++) {
        if (!(r[i].t > t0 + 1e-12 && r[i].t <= t1 + 1e-12))
            continue;
        const double m = r[i].mass, a = r[i].age;
        out->n++;
        out->mass += m;
        if (r[i].t <= th)
            mh1 += m;
        else
            mh2 += m;
        out->amax = a > out->amax ? a : out->amax;
        const long b = (long)(a / 1e-3);
        if (b >= 0) {
            mb[b] += m;
            has[b] = 1;
        }
    }
    const double rinf = fill_rate(mb, has, bmax + 1, soi, t0, t1);
    double c = 0;
    out->a50 = out->aF = -1;
    for (long k = 0; k <= bmax; k++) {
        if (!has[k])
            continue;
        double lo = soi + (k + 0.5) * 1e-3;
        lo = lo < t0 ? t0 : lo;
        if (t1 - lo > 1e-9)
            c += mb[k] / (t1 - lo);
        if (out->a50 < 0 && c >= 0.5 * rinf)
            out->a50 = (k + 1) * 1e-3;
        if (out->aF < 0 && c >= F * rinf)
            out->aF = (k + 1) * 1e-3;
    }
    out->fill = ratio(out->mass, rinf * (t1 - t0));
    out->fill1 = ratio(mh1, rinf * (th - t0));
    out->fill2 = ratio(mh2, rinf * (t1 - th));
    free(mb);
    free(has);
    return 0;
}
