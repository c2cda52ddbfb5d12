/* swe_cmd_flow.c - snowwedge forces, probes, errortime: the flow's time series
 * over the window (swe_signal.h) and the error against run time. */
#include "swe_cli.h"

#include "swe_signal.h"
#include "swe_spray.h"
#include "swe_stats.h"

#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* ---- time series of the flow ------------------------------------------------------ */
static void window_of(const swe_options *o, const char *cmd, double *a, double *b)
{
    swe_cli_need("--window", o->window, cmd);
    const char *c = strchr(o->window, ',');
    char buf[64];
    if (!c || (size_t)(c - o->window) >= sizeof buf)
        swe_cli_die(2, "--window: '%s' is not T0,T1", o->window);
    snprintf(buf, sizeof buf, "%.*s", (int)(c - o->window), o->window);
    *a = swe_cli_number("--window", buf);
    *b = swe_cli_number("--window", c + 1);
    if (!(*b > *a))
        swe_cli_die(2, "--window: '%s' is not T0,T1 with T0 < T1", o->window);
}

int swe_cmd_forces(const swe_options *o)
{
    double a, b;
    window_of(o, "forces", &a, &b);
    if (o->nfiles != 1)
        swe_cli_die(2, "forces: give one coefficient.dat (see --help)");
    FILE *f = swe_cli_open(o->files[0]);
    size_t cap = 4096, n = 0;
    double *t = malloc(cap * sizeof *t), *cd = malloc(cap * sizeof *cd),
           *cs = malloc(cap * sizeof *cs), *cl = malloc(cap * sizeof *cl);
    static char line[1 << 14];
    while (t && cd && cs && cl && fgets(line, sizeof line, f)) {
        if (line[0] == '#')
            continue;
        double v[4];
        if (sscanf(line, "%lf %lf %lf %lf", &v[0], &v[1], &v[2], &v[3]) != 4)
            continue;
        if (!(v[0] > a + 1e-12 && v[0] <= b + 1e-12))
            continue;
        if (n == cap) {
            cap *= 2;
            t = realloc(t, cap * sizeof *t);
            cd = realloc(cd, cap * sizeof *cd);
            cs = realloc(cs, cap * sizeof *cs);
            cl = realloc(cl, cap * sizeof *cl);
            if (!t || !cd || !cs || !cl)
                break;
        }
        t[n] = v[0];
        cd[n] = v[1];
        cs[n] = v[2];
        cl[n] = v[3];
        n++;
    }
    fclose(f);
    if (!t || !cd || !cs || !cl)
        swe_cli_die(1, "out of memory");
    if (n >= 10) { /* fewer samples: no line, as the window holds no spectrum */
        double fs, fl;
        char err[256];
        if (swe_peak_frequency(t, cs, n, a, b, 300, &fs, err, sizeof err) ||
            swe_peak_frequency(t, cl, n, a, b, 300, &fl, err, sizeof err))
            swe_cli_die(2, "forces: %s", err);
        printf("Forces on the wedge (reference: rear face 0.0144 m2, 19.444 m/s): mean Cd %.3f; "
               "side force Cs rms %.3g, dominant frequency %.1f Hz (Strouhal number f H/U = %.3f, "
               "H = 0.12 m); lift Cl rms %.3g, dominant frequency %.1f Hz (St %.3f).\n",
               swe_mean(cd, n), swe_rms(cs, n), fs, fs * 0.12 / 19.444, swe_rms(cl, n), fl,
               fl * 0.12 / 19.444);
    }
    free(t);
    free(cd);
    free(cs);
    free(cl);
    return 0;
}

/* one column of a table whose last "# Time ..." line names its columns */
static size_t read_column(const char *path, const char *col, double **tp, double **xp)
{
    FILE *f = swe_cli_open(path);
    static char line[1 << 16];
    int c = -1;
    size_t n = 0, cap = 4096;
    double *t = malloc(cap * sizeof *t), *x = malloc(cap * sizeof *x);
    if (!t || !x)
        swe_cli_die(1, "out of memory");
    for (long ln = 1; fgets(line, sizeof line, f); ln++) {
        if (line[0] == '#') {
            char *save = NULL, *w = strtok_r(line + 1, " \t\r\n", &save);
            if (!w || strcmp(w, "Time"))
                continue;
            c = -1;
            for (int k = 1; (w = strtok_r(NULL, " \t\r\n", &save)); k++)
                if (!strcmp(w, col))
                    c = k;
            if (c < 0)
                swe_cli_die(2, "%s: the header has no column '%s'", path, col);
            continue;
        }
        if (c < 0)
            continue;
        char *save = NULL, *w = strtok_r(line, " \t\r\n", &save);
        if (!w)
            continue;
        double v[2];
        v[0] = swe_cli_number(path, w);
        for (int k = 1; k <= c; k++)
            if (!(w = strtok_r(NULL, " \t\r\n", &save)))
                swe_cli_die(2, "%s line %ld: no column %d (%s)", path, ln, c + 1, col);
        v[1] = swe_cli_number(path, w);
        if (n == cap) {
            cap *= 2;
            double *g = realloc(t, cap * sizeof *t), *h = g ? realloc(x, cap * sizeof *x) : NULL;
            if (!g || !h)
                swe_cli_die(1, "out of memory");
            t = g, x = h;
        }
        t[n] = v[0], x[n++] = v[1];
    }
    fclose(f);
    if (c < 0)
        swe_cli_die(2, "%s: no '# Time ...' header naming '%s'", path, col);
    *tp = t, *xp = x;
    return n;
}

int swe_cmd_spectrum(const swe_options *o)
{
    double a, b;
    window_of(o, "spectrum", &a, &b);
    if (o->nfiles < 2 || o->nfiles % 2)
        swe_cli_die(2, "spectrum: give FILE COLUMN pairs (see --help)");
    int k = 1;
    if (o->segments) {
        const double v = swe_cli_number("--segments", o->segments);
        if (!(v >= 1 && v <= 1000 && v == floor(v)))
            swe_cli_die(2, "--segments: '%s' is not a whole number 1 .. 1000", o->segments);
        k = (int)v;
    }
    const int ns = o->nfiles / 2;
    swe_spectrum *s = calloc((size_t)ns, sizeof *s);
    if (!s)
        swe_cli_die(1, "out of memory");
    double dt = 0;
    for (int i = 0; i < ns; i++) {
        double *t, *x;
        const char *path = o->files[2 * i], *col = o->files[2 * i + 1];
        const size_t n = read_column(path, col, &t, &x);
        char err[256];
        if (swe_spectrum_welch(t, x, n, a, b, k, dt, &s[i], err, sizeof err))
            swe_cli_die(2, "spectrum: %s %s: %s", path, col, err);
        dt = s[i].dt; /* every signal on the first one's step */
        double fp, fl, below;
        swe_spectrum_peaks(&s[i], 0.1, &fp, &fl, &below);
        printf("%s %s: rms %.4g; %d segment(s) of %.4g s, df %.3g Hz; peak %.1f Hz (St %.3f); "
               "lowest peak with 10 %% of the variance %.1f Hz (St %.3f); below %.1f Hz %.0f %% "
               "of the variance\n",
               path, col, sqrt(s[i].var), s[i].nseg, (double)s[i].seglen * s[i].dt, s[i].df, fp,
               fp * 0.12 / 19.444, fl, fl * 0.12 / 19.444, fp / 2, 100 * below);
        free(t);
        free(x);
    }
    if (o->psd) {
        FILE *f = fopen(o->psd, "w");
        if (!f)
            swe_cli_die(1, "cannot write %s: %s", o->psd, strerror(errno));
        fprintf(f, "f_Hz,St");
        for (int i = 0; i < ns; i++)
            fprintf(f, ",%s", o->files[2 * i + 1]);
        fputc('\n', f);
        size_t nf = s[0].nf;
        for (int i = 1; i < ns; i++)
            nf = s[i].nf < nf ? s[i].nf : nf;
        for (size_t j = 0; j < nf; j++) {
            fprintf(f, "%.6g,%.6g", (double)j * s[0].df, (double)j * s[0].df * 0.12 / 19.444);
            for (int i = 0; i < ns; i++)
                fprintf(f, ",%.6g", s[i].psd[j]);
            fputc('\n', f);
        }
        if (fclose(f))
            swe_cli_die(1, "cannot write %s: %s", o->psd, strerror(errno));
    }
    for (int i = 0; i < ns; i++)
        swe_spectrum_free(&s[i]);
    free(s);
    return 0;
}

int swe_forces_solved(const char *path, double a, double b, double period)
{
    double *t = NULL, *x[3];
    static const char *col[3] = {"Cd", "Cs", "Cl"};
    size_t n = 0;
    for (int k = 0; k < 3; k++) {
        double *tk;
        n = read_column(path, col[k], &tk, &x[k]);
        if (k)
            free(tk);
        else
            t = tk;
    }
    swe_spectrum s[3];
    char err[256];
    int bad = 0;
    for (int k = 0; k < 3 && !bad; k++)
        bad = swe_spectrum_welch(t, x[k], n, a, b, 1, k ? s[0].dt : 0, &s[k], err, sizeof err) != 0;
    double mcd = 0;
    size_t m = 0;
    for (size_t i = 0; i < n; i++)
        if (t[i] > a + 1e-12 && t[i] <= b + 1e-12)
            mcd += x[0][i], m++;
    free(t);
    for (int k = 0; k < 3; k++)
        free(x[k]);
    if (bad) {
        printf("The solved flow of the library %g .. %g s holds no spectrum (%s).\n", a, b, err);
        return 0;
    }
    double fp[3], fl[3], below[3];
    for (int k = 0; k < 3; k++)
        swe_spectrum_peaks(&s[k], 0.1, &fp[k], &fl[k], &below[k]);
    const double sc = 0.12 / 19.444, e = s[1].df / 2;
    printf("The window's flow is the library %g .. %g s played back with period %g s, so its "
           "spectrum holds only multiples of %.3g Hz. Over the solved flow of the library "
           "(Welch, resolution %.3g Hz): mean Cd %.3f; side force Cs rms %.3g, peak %.1f +- %.1f "
           "Hz (Strouhal number of the solved flow = %.3f, +- %.3f); lift Cl rms %.3g, peak %.1f Hz "
           "(St %.3f); the library holds %.2g shedding periods (of the side force's peak); the "
           "slowest mode with 10 %% of Cd's variance %.1f Hz (St %.3f): the library holds %.2g of "
           "its periods%s.\n",
           a, b, period, 1 / period, s[1].df, m ? mcd / (double)m : 0, sqrt(s[1].var), fp[1], e,
           fp[1] * sc, e * sc, sqrt(s[2].var), fp[2], fp[2] * sc, (b - a) * fp[1], fl[0],
           fl[0] * sc, (b - a) * fl[0],
           fl[0] < 1.5 * s[0].df ? " (the lowest frequency the library resolves: a slower mode "
                                   "cannot be told from it)"
                                 : "");
    for (int k = 0; k < 3; k++)
        swe_spectrum_free(&s[k]);
    return 0;
}

int swe_cmd_probes(const swe_options *o)
{
    double a, b;
    window_of(o, "probes", &a, &b);
    if (o->nfiles != 1)
        swe_cli_die(2, "probes: give one probes file of U (see --help)");
    FILE *f = swe_cli_open(o->files[0]);
    enum { MAXP = 64 };
    char loc[MAXP][128];
    double s[MAXP] = {0}, q[MAXP] = {0};
    int np = 0;
    long n = 0;
    static char line[1 << 14];
    while (fgets(line, sizeof line, f)) {
        if (!strncmp(line, "# Probe ", 8)) {
            char *p = line + 8;
            while (*p >= '0' && *p <= '9')
                p++;
            if (*p == ' ')
                p++;
            p[strcspn(p, "\r\n")] = 0;
            if (strlen(p) >= sizeof loc[0])
                swe_cli_die(2, "%s: a probe location longer than %zu characters", o->files[0],
                    sizeof loc[0] - 1);
            if (np < MAXP)
                memcpy(loc[np++], p, strlen(p) + 1);
            continue;
        }
        if (line[0] == '#')
            continue;
        swe_cli_strip_parens(line);
        char *save = NULL, *tok = strtok_r(line, " \t\r\n", &save);
        if (!tok)
            continue;
        const double t = strtod(tok, NULL);
        if (!(t > a + 1e-12 && t <= b + 1e-12))
            continue;
        n++;
        for (int k = 0; k < np; k++) {
            tok = strtok_r(NULL, " \t\r\n", &save);
            const double u = tok ? strtod(tok, NULL) : 0;
            s[k] += u;
            q[k] += u * u;
            strtok_r(NULL, " \t\r\n", &save);
            strtok_r(NULL, " \t\r\n", &save);
        }
    }
    fclose(f);
    if (!n)
        return 0;
    printf("Axial air velocity Ux in the near wake (mean / rms of the fluctuation):");
    for (int k = 0; k < np; k++) {
        const double m = s[k] / (double)n;
        printf(" at %s %.2f / %.2f m/s;", loc[k], m, sqrt(q[k] / (double)n - m * m));
    }
    printf("\n");
    return 0;
}

/* ---- error against run time ------------------------------------------------------ */
int swe_cmd_errortime(const swe_options *o)
{
    const double target = o->target ? swe_cli_number("--target", o->target) : 10;
    if (!(target > 0))
        swe_cli_die(2, "--target: '%s' is not a positive error in %%", o->target);
    if (o->nfiles != 1)
        swe_cli_die(2, "errortime: give one POINTS file (see --help)");
    FILE *f = swe_cli_open(o->files[0]);
    char line[4096];
    for (int ln = 1; fgets(line, sizeof line, f); ln++) {
        line[strcspn(line, "\r\n")] = 0;
        char *fld[4], *save = NULL;
        int k = 0;
        for (char *t = strtok_r(line, "\t", &save); t && k < 4; t = strtok_r(NULL, "\t", &save))
            fld[k++] = t;
        if (k != 4)
            swe_cli_die(2, "%s line %d is not \"design run wall_s error\" (tab-separated)", o->files[0], ln);
        const double t = swe_cli_number(o->files[0], fld[2]), e = swe_cli_number(o->files[0], fld[3]);
        printf("| %s | %s | %.0f | %.1f | %.3g |\n", fld[0], fld[1], t, e,
               swe_time_for_error(t, e, target));
    }
    fclose(f);
    return 0;
}

