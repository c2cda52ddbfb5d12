/* sbd_snow.c - the snow on a body from the wall model's stick records: the
 * window's mass and its sampling error by origin, the halves, the map, and the
 * resolution ladder (sbd_snow.h). */
#include "sbd_snow.h"
#include "spo_origin.h"
#include "swg_ladder.h"

#include <errno.h>
#include <fenv.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int fail(char *err, size_t errlen, const char *fmt, ...)
{
    if (err && errlen) {
        va_list ap;
        va_start(ap, fmt);
        vsnprintf(err, errlen, fmt, ap);
        va_end(ap);
    }
    return -1;
}

/* a finite number filling the whole token; an overflowing one ("1e999") is
 * refused without raising the overflow exception (a host that traps it, as
 * OpenFOAM does, would die): strtod runs in non-stop mode */
int sbd_number(const char *tok, double *v)
{
    char *end = NULL;
    fenv_t env;
    feholdexcept(&env);
    errno = 0;
    *v = strtod(tok, &end);
    const int range = errno == ERANGE;
    feclearexcept(FE_ALL_EXCEPT);
    fesetenv(&env);
    return end != tok && *end == '\0' && !range && isfinite(*v);
}

/* ---- the stick records -------------------------------------------------------- */
enum { C_T, C_X, C_Y, C_Z, C_PROC, C_ID, C_NP, C_D, C_RHO, C_N };
static const char *const col_name[C_N] = {"Time", "position0", "position1", "position2", "origProc",
                                          "origId", "nParticle", "d", "rho"};

int sbd_sticks_read(sbd_sticks *st, const char *path, char *err, size_t errlen)
{
    FILE *f = fopen(path, "r");
    if (!f)
        return fail(err, errlen, "%s: cannot read (%s)", path, strerror(errno));
    char line[4096];
    int col[C_N], ncol = 0, have_header = 0;
    long lineno = 0;
    while (fgets(line, sizeof line, f)) {
        lineno++;
        if (!strchr(line, '\n') && !feof(f)) {
            fclose(f);
            return fail(err, errlen, "%s:%ld: a line longer than %zu characters", path, lineno, sizeof line - 2);
        }
        char *tok[64];
        int nt = 0;
        for (char *p = strtok(line, " \t\r\n()"); p && nt < 64; p = strtok(NULL, " \t\r\n()"))
            tok[nt++] = p;
        if (nt == 0)
            continue;
        if (tok[0][0] == '#') { /* the header names the columns; other comments are skipped */
            if (tok[0][1] == '\0') { /* "# Time ...": drop the lone '#' */
                memmove(tok, tok + 1, (size_t)--nt * sizeof *tok);
            } else {
                tok[0]++;
            }
            if (nt == 0 || strcmp(tok[0], "Time"))
                continue;
            for (int c = 0; c < C_N; c++)
                col[c] = -1;
            ncol = nt;
            for (int k = 0; k < nt; k++)
                for (int c = 0; c < C_N; c++)
                    if (!strcmp(tok[k], col_name[c]))
                        col[c] = k;
            for (int c = 0; c < C_N; c++)
                if (col[c] < 0) {
                    fclose(f);
                    return fail(err, errlen, "%s:%ld: the header names no column '%s'", path, lineno, col_name[c]);
                }
            have_header = 1;
            continue;
        }
        if (!have_header) {
            fclose(f);
            return fail(err, errlen, "%s:%ld: a record before the header line '# Time ...'", path, lineno);
        }
        if (nt != ncol) {
            fclose(f);
            return fail(err, errlen, "%s:%ld: %d values, the header names %d", path, lineno, nt, ncol);
        }
        double v[C_N];
        for (int c = 0; c < C_N; c++)
            if (!sbd_number(tok[col[c]], &v[c])) {
                fclose(f);
                return fail(err, errlen, "%s:%ld: %s '%s' is not a finite number", path, lineno, col_name[c],
                            tok[col[c]]);
            }
        if (v[C_NP] < 0 || v[C_D] < 0 || v[C_RHO] < 0) {
            fclose(f);
            return fail(err, errlen, "%s:%ld: a negative nParticle, d or rho", path, lineno);
        }
        if (st->n == st->cap) {
            size_t cap = st->cap ? 2 * st->cap : 1024;
            sbd_stick *s = realloc(st->s, cap * sizeof *s);
            if (!s) {
                fclose(f);
                return fail(err, errlen, "%s: out of memory at %zu sticks", path, st->n);
            }
            st->s = s;
            st->cap = cap;
        }
        sbd_stick *s = &st->s[st->n++];
        s->t = v[C_T];
        s->x[0] = v[C_X];
        s->x[1] = v[C_Y];
        s->x[2] = v[C_Z];
        s->proc = (long)v[C_PROC];
        s->id = (long)v[C_ID];
        s->mass = v[C_NP] * v[C_RHO] * M_PI * v[C_D] * v[C_D] * v[C_D] / 6;
    }
    int bad = ferror(f);
    fclose(f);
    if (bad)
        return fail(err, errlen, "%s: read error", path);
    if (!have_header)
        return fail(err, errlen, "%s: no header line '# Time (position0 position1 position2) origProc origId ...'",
                    path);
    return 0;
}

void sbd_sticks_free(sbd_sticks *st)
{
    if (!st)
        return;
    free(st->s);
    st->s = NULL;
    st->n = st->cap = 0;
}

/* ---- the window ------------------------------------------------------------------- */
/* the window is one bin, its halves the sub-bins of each origin's mass */
int sbd_window(const sbd_stick *s, size_t n, double t0, double t1, sbd_window_stat *out)
{
    if (!(t1 > t0) || !out)
        return -1;
    memset(out, 0, sizeof *out);
    spo_record *t = malloc((n ? n : 1) * sizeof *t);
    if (!t)
        return -1;
    const double tm = 0.5 * (t0 + t1);
    size_t m = 0;
    for (size_t i = 0; i < n; i++)
        if (s[i].t > t0 && s[i].t <= t1)
            t[m++] = (spo_record){0, s[i].t > tm, s[i].proc, s[i].id, s[i].mass};
    spo_bin w;
    const int rc = spo_origin_bins(t, m, 1, &w, NULL, 0);
    free(t);
    if (rc)
        return -1;
    out->sticks = m;
    out->origins = (size_t)w.origins;
    out->mass = w.mass;
    out->var = w.s2;
    for (int h = 0; h < 2; h++) {
        out->half[h] = w.sub_mass[h];
        out->half_var[h] = w.sub_s2[h];
    }
    return 0;
}

double sbd_halves_z(const sbd_window_stat *w)
{
    const double v = w->half_var[0] + w->half_var[1];
    return v > 0 ? (w->half[1] - w->half[0]) / sqrt(v) : 0;
}

int sbd_map(const sbd_stick *s, size_t n, double t0, double t1, int ia, int ib, double a0, double a1, int na,
            double b0, double b1, int nb, double *map, size_t *outside)
{
    if (ia < 0 || ia > 2 || ib < 0 || ib > 2 || ia == ib || !(a1 > a0) || !(b1 > b0) || na < 1 || nb < 1 ||
        !map)
        return -1;
    const double da = (a1 - a0) / na, db = (b1 - b0) / nb, area = da * db;
    size_t out = 0;
    for (int k = 0; k < na * nb; k++)
        map[k] = 0;
    for (size_t i = 0; i < n; i++) {
        if (!(s[i].t > t0 && s[i].t <= t1))
            continue;
        const double a = s[i].x[ia], b = s[i].x[ib];
        const double tol = 1e-9 * (fabs(a1 - a0) + fabs(b1 - b0));
        if (a < a0 - tol || a > a1 + tol || b < b0 - tol || b > b1 + tol) {
            out++;
            continue;
        }
        int ka = (int)floor((a - a0) / da), kb = (int)floor((b - b0) / db);
        ka = ka < 0 ? 0 : ka >= na ? na - 1 : ka;
        kb = kb < 0 ? 0 : kb >= nb ? nb - 1 : kb;
        map[kb * na + ka] += s[i].mass / area;
    }
    if (outside)
        *outside = out;
    return 0;
}

/* ---- the ladder ---------------------------------------------------------------------- */
int sbd_ladder_read(const char *path, sbd_ladder *l, char *err, size_t errlen)
{
    static const char *header = "level,cells,seconds,rear_kg_m2,rear_rel,sensor_kg_m2,sensor_rel";
    memset(l, 0, sizeof *l);
    FILE *f = fopen(path, "r");
    if (!f)
        return fail(err, errlen, "%s: cannot read (%s)", path, strerror(errno));
    char line[1024];
    long lineno = 0;
    int seen_header = 0;
    while (fgets(line, sizeof line, f)) {
        lineno++;
        line[strcspn(line, "\r\n")] = '\0';
        if (!line[0] || line[0] == '#')
            continue;
        if (!seen_header) {
            if (strcmp(line, header)) {
                fclose(f);
                return fail(err, errlen, "%s:%ld: the header must be '%s', got '%s'", path, lineno, header, line);
            }
            seen_header = 1;
            continue;
        }
        if (l->n == SBD_LADDER_MAX) {
            fclose(f);
            return fail(err, errlen, "%s:%ld: more than %d levels", path, lineno, SBD_LADDER_MAX);
        }
        char *fld[8];
        int nf = 0;
        for (char *p = line, *c; nf < 8; p = c + 1) {
            fld[nf++] = p;
            if (!(c = strchr(p, ',')))
                break;
            *c = '\0';
        }
        if (nf != 7) {
            fclose(f);
            return fail(err, errlen, "%s:%ld: %d fields, the header names 7", path, lineno, nf);
        }
        sbd_ladder_row *r = &l->row[l->n];
        double v[6];
        size_t ln = strlen(fld[0]);
        if (ln == 0 || ln >= sizeof r->level || strspn(fld[0], "abcdefghijklmnopqrstuvwxyz0123456789_-") != ln) {
            fclose(f);
            return fail(err, errlen, "%s:%ld: level '%s' is not a word of lower-case letters, digits, _ or -",
                        path, lineno, fld[0]);
        }
        for (int k = 0; k < 6; k++)
            if (!sbd_number(fld[k + 1], &v[k]) || !(v[k] > 0)) {
                fclose(f);
                return fail(err, errlen, "%s:%ld: field %d '%s' is not a positive finite number", path, lineno,
                            k + 2, fld[k + 1]);
            }
        if (v[0] != floor(v[0]) || v[0] > 2e9 || (l->n && v[0] <= l->row[l->n - 1].cells)) {
            fclose(f);
            return fail(err, errlen, "%s:%ld: cells '%s' must be a whole number above the previous level's", path,
                        lineno, fld[1]);
        }
        for (int k = 0; k < l->n; k++)
            if (!strcmp(l->row[k].level, fld[0])) {
                fclose(f);
                return fail(err, errlen, "%s:%ld: level '%s' given twice", path, lineno, fld[0]);
            }
        snprintf(r->level, sizeof r->level, "%s", fld[0]);
        r->cells = (long)v[0];
        r->seconds = v[1];
        r->value[0] = v[2];
        r->rel[0] = v[3];
        r->value[1] = v[4];
        r->rel[1] = v[5];
        l->n++;
    }
    fclose(f);
    if (!seen_header)
        return fail(err, errlen, "%s: no header line '%s'", path, header);
    if (l->n < 2)
        return fail(err, errlen, "%s: %d level(s); a ladder needs at least 2", path, l->n);
    return 0;
}

int sbd_ladder_find(const sbd_ladder *l, const char *level)
{
    for (int k = 0; k < l->n; k++)
        if (!strcmp(l->row[k].level, level))
            return k;
    return -1;
}

int sbd_ladder_disc(const sbd_ladder *l, int q, sbd_ladder_error *e, char *err, size_t errlen)
{
    if (!l || !e || q < 0 || q >= SBD_LADDER_Q || l->n < 2 || l->n > SBD_LADDER_MAX)
        return fail(err, errlen, "sbd_ladder_disc: a bad argument");
    /* the levels finest first: h = cells^(-1/3) */
    swg_level lv[SBD_LADDER_MAX];
    char m[256];
    for (int i = 0; i < l->n; i++) {
        const sbd_ladder_row *r = &l->row[l->n - 1 - i];
        if (swg_cell_size(1.0, (double)r->cells, 3, &lv[i].h, m, sizeof m))
            return fail(err, errlen, "level %s: %s", r->level, m);
        lv[i].value = r->value[q];
        lv[i].se = r->rel[q] * r->value[q];
    }
    swg_settings s;
    swg_settings_default(&s);
    swg_disc d;
    double disc[SBD_LADDER_MAX];
    if (swg_discretization(lv, (size_t)l->n, 2.0, &s, &d, disc, m, sizeof m))
        return fail(err, errlen, "the ladder's %s: %s", q ? "sensor" : "rear face", m);
    if (!(fabs(d.ref) > 0))
        return fail(err, errlen, "the ladder's %s: its reference is 0 (no relative error)", q ? "sensor" : "rear face");
    e->ref = d.ref;
    e->kind = swg_ref_kind_name(d.kind);
    for (int k = 0; k < l->n; k++) {
        e->disc[k] = disc[l->n - 1 - k] / fabs(d.ref);
        e->sampling[k] = l->row[k].rel[q] * l->row[k].value[q] / fabs(d.ref);
        e->total[k] = hypot(e->sampling[k], e->disc[k]);
    }
    return 0;
}
