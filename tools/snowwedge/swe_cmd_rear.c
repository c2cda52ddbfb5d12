/* swe_cmd_rear.c - snowwedge outline, rear-stats and rear-records: the rear
 * face's outline, its records' regions and effective sample sizes
 * (swe_stats.h), and the records themselves (for the blocks of swe_blocks.h). */
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

/* the outline of a rear-face map, to 6 significant digits (as the panels and
   the region tables of earlier runs read it) */
void swe_cli_outline(const char *path, double o[4])
{
    FILE *f = swe_cli_open(path);
    char line[512];
    size_t cap = 1024, n = 0;
    double *y = malloc(cap * sizeof *y), *z = malloc(cap * sizeof *z);
    if (!y || !z)
        swe_cli_die(1, "out of memory");
    for (int ln = 0; fgets(line, sizeof line, f); ln++) {
        if (ln == 0)
            continue;
        if (n == cap) {
            cap *= 2;
            y = realloc(y, cap * sizeof *y);
            z = realloc(z, cap * sizeof *z);
            if (!y || !z)
                swe_cli_die(1, "out of memory");
        }
        if (sscanf(line, "%lf,%lf", &y[n], &z[n]) != 2)
            swe_cli_die(2, "%s line %d is not y,z,value", path, ln + 1);
        n++;
    }
    fclose(f);
    if (!n)
        swe_cli_die(2, "%s holds no face", path);
    double *a[2] = {y, z};
    for (int c = 0; c < 2; c++) {
        double lo = a[c][0], hi = a[c][0];
        for (size_t i = 0; i < n; i++) {
            lo = a[c][i] < lo ? a[c][i] : lo;
            hi = a[c][i] > hi ? a[c][i] : hi;
        }
        /* distinct values: sorted, counted */
        double *s = malloc(n * sizeof *s);
        if (!s)
            swe_cli_die(1, "out of memory");
        memcpy(s, a[c], n * sizeof *s);
        for (size_t i = 1; i < n; i++) /* insertion sort: maps are small and nearly sorted */
            for (size_t j = i; j > 0 && s[j - 1] > s[j]; j--) {
                const double t = s[j];
                s[j] = s[j - 1];
                s[j - 1] = t;
            }
        size_t nd = 1;
        for (size_t i = 1; i < n; i++)
            nd += (s[i] != s[i - 1]);
        free(s);
        const double h = (nd > 1) ? (hi - lo) / (double)(nd - 1) / 2 : 0.005;
        char buf[64];
        snprintf(buf, sizeof buf, "%.6g", lo - h);
        o[2 * c] = strtod(buf, NULL);
        snprintf(buf, sizeof buf, "%.6g", hi + h);
        o[2 * c + 1] = strtod(buf, NULL);
    }
    free(y);
    free(z);
}



int swe_cmd_outline(const swe_options *o)
{
    if (o->nfiles != 1)
        swe_cli_die(2, "outline: give one map (see --help)");
    double b[4];
    swe_cli_outline(o->files[0], b);
    printf("%.6g %.6g %.6g %.6g\n", b[0], b[1], b[2], b[3]);
    return 0;
}


/* ---- rear-face records ------------------------------------------------------------ */

/* the records of the files (postProcessing's rear.post of a cloud function:
   Time, position, origProc, origId, nParticle, d, rho) with ta < Time <= tb */
static swe_record *read_records(const char *const *files, int nfiles, double ta, double tb,
                                size_t *count)
{
    size_t cap = 4096, n = 0;
    swe_record *rec = malloc(cap * sizeof *rec);
    if (!rec)
        swe_cli_die(1, "out of memory");
    static char line[1 << 16];
    for (int fi = 0; fi < nfiles; fi++) {
        FILE *f = swe_cli_open(files[fi]);
        enum { T, Y, Z, P, I, N, D, R, NCOL };
        static const char *want[NCOL] = {"Time", "position1", "position2", "origProc",
                                         "origId", "nParticle", "d", "rho"};
        int col[NCOL], have = 0;
        for (int ln = 1; fgets(line, sizeof line, f); ln++) {
            swe_cli_strip_parens(line);
            char *tok[64];
            int nt = 0;
            char *save = NULL;
            for (char *t = strtok_r(line, " \t\r\n", &save); t && nt < 64;
                 t = strtok_r(NULL, " \t\r\n", &save))
                tok[nt++] = t;
            if (nt && tok[0][0] == '#') {
                if (!have) {
                    for (int k = 0; k < NCOL; k++) {
                        col[k] = -1;
                        for (int j = 1; j < nt; j++)
                            if (!strcmp(tok[j], want[k]))
                                col[k] = j - 1;
                        if (col[k] < 0)
                            swe_cli_die(2, "%s: the header has no column %s", files[fi], want[k]);
                    }
                    have = 1;
                }
                continue;
            }
            if (!nt)
                continue;
            if (!have)
                swe_cli_die(2, "%s line %d: a record before the header", files[fi], ln);
            double v[NCOL];
            for (int k = 0; k < NCOL; k++) {
                if (col[k] >= nt)
                    swe_cli_die(2, "%s line %d: %d columns, the header names more", files[fi], ln, nt);
                v[k] = swe_cli_number(files[fi], tok[col[k]]);
            }
            if (!(v[T] > ta + 1e-12 && v[T] <= tb + 1e-12))
                continue;
            if (n == cap) {
                cap *= 2;
                swe_record *g = realloc(rec, cap * sizeof *rec);
                if (!g)
                    swe_cli_die(1, "out of memory");
                rec = g;
            }
            rec[n++] = (swe_record){v[Y], v[Z], v[N] * v[R] * M_PI / 6 * v[D] * v[D] * v[D],
                                    (long)v[P], (long)v[I]};
        }
        fclose(f);
    }
    *count = n;
    return rec;
}

int swe_cmd_rear_records(const swe_options *o)
{
    swe_cli_need("--from", o->from, "rear-records");
    swe_cli_need("--to", o->to, "rear-records");
    if (!o->nfiles)
        swe_cli_die(2, "rear-records: give the records' files (see --help)");
    const double ta = swe_cli_number("--from", o->from), tb = swe_cli_number("--to", o->to);
    size_t n;
    swe_record *rec = read_records(o->files, o->nfiles, ta, tb, &n);
    printf("# the rear face's records with %s < Time <= %s s: position (y, z), mass "
           "nParticle rho pi d^3 / 6, origin\ny,z,mass_kg,origProc,origId\n", o->from, o->to);
    for (size_t i = 0; i < n; i++)
        printf("%.10g,%.10g,%.10g,%ld,%ld\n", rec[i].y, rec[i].z, rec[i].mass, rec[i].proc,
               rec[i].id);
    free(rec);
    return 0;
}

int swe_cmd_rear_stats(const swe_options *o)
{
    swe_cli_need("--label", o->label, "rear-stats");
    swe_cli_need("--from", o->from, "rear-stats");
    swe_cli_need("--to", o->to, "rear-stats");
    swe_cli_need("--outline", o->outline, "rear-stats");
    swe_cli_need("--kind", o->kind, "rear-stats");
    const double ta = swe_cli_number("--from", o->from), tb = swe_cli_number("--to", o->to);
    double ol[4];
    swe_cli_outline(o->outline, ol);
    size_t n;
    swe_record *rec = read_records(o->files, o->nfiles, ta, tb, &n);
    swe_region_stats st[SWE_NREGION];
    char err[256];
    if (swe_rear_stats(rec, n, ol, st, err, sizeof err))
        swe_cli_die(2, "rear-stats: %s", err);
    static const int order[SWE_NREGION] = {SWE_LEFT, SWE_RIGHT, SWE_CENTRE, SWE_EDGES, SWE_FACE};
    printf("| %s |", o->label);
    for (int i = 0; i < SWE_NREGION; i++) {
        const swe_region_stats *s = &st[order[i]];
        if (!s->n)
            printf(" 0 |");
        else
            printf(" %ld %s, %ld origins, %.3g kg, n_eff %.1f, +- %.0f %% |", s->n, o->kind,
                   s->origins, s->mass, s->neff, 100 / sqrt(s->neff));
    }
    printf("\n");
    free(rec);
    return 0;
}

