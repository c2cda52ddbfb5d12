/* swe_total.c - a wedge run against its resolution ladder: the settings
 * check and results/total_error.md (swe_run.h). */
#include "swe_run.h"
#include "swe_run_text.h"
#include "swo_err.h"

#include <dirent.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#define fail(err, n, code, ...) swo_fail(code, err, n, __VA_ARGS__)  /* common/swo_err.h */

/* ---- the total error against a resolution ladder ------------------------------------------ */
/* two values equal as awk compares them: as numbers when both are, else as text */
static int awk_equal(const char *a, const char *b)
{
    char *ea, *eb;
    const double x = strtod(a, &ea), y = strtod(b, &eb);
    if (ea != a && eb != b && !*ea && !*eb)
        return x == y;
    return !strcmp(a, b);
}

/* the CSV fields of a line (split on ','), at most max; returns their count */
static int csv_split(char *line, char **f, int max)
{
    int k = 0;
    f[k++] = line;
    for (char *c = line; *c; c++)
        if (*c == ',') {
            *c = 0;
            if (k < max)
                f[k++] = c + 1;
        }
    return k;
}

int swe_ladder_why(FILE *ladder, const char *const *settings, int nset, const char *level,
                   const char *cells, char *why, size_t n)
{
    static char line[1 << 14];
    char tok[4][256];
    size_t l = 0;
    why[0] = 0;
    for (int s = 0; s < nset; s++) {
        const char *kv = settings[s], *v = strchr(kv, ' ');
        if (!v)
            continue;
        char key[256];
        snprintf(key, sizeof key, "%.*s", (int)(v - kv), kv);
        v++;
        rewind(ladder);
        while (fgets(line, sizeof line, ladder)) {
            if (strcmp(field(line, 1, tok[0], 256), "#") || strcmp(field(line, 2, tok[1], 256), "setting") ||
                strcmp(field(line, 3, tok[2], 256), key))
                continue;
            field(line, 4, tok[3], 256);
            if (tok[3][0] && strcmp(tok[3], v))
                l += (size_t)snprintf(why + l, l < n ? n - l : 0, "%s%s %s here, %s on the ladder",
                                      l ? "; " : "", key, v, tok[3]);
            break;
        }
    }
    rewind(ladder);
    char lc[256] = "";
    int found = 0;
    while (!found && fgets(line, sizeof line, ladder)) {
        chomp(line);
        if (line[0] == '#')
            continue;
        char *f[16] = {0};
        const int k = csv_split(line, f, 16);
        if (k >= 4 && awk_equal(f[3], level)) {
            snprintf(lc, sizeof lc, "%s", k >= 5 ? f[4] : "");
            found = 1;
        }
    }
    if (!found || !lc[0])
        l += (size_t)snprintf(why + l, l < n ? n - l : 0, "%slevel %s is not on the ladder", l ? "; " : "",
                              level);
    else if (strcmp(lc, cells))
        l += (size_t)snprintf(why + l, l < n ? n - l : 0,
                              "%slevel %s has %s cells on the ladder, %s here (another mesh: -test, "
                              "-fine, -refine-wake or -no-rear-layers)",
                              l ? "; " : "", level, lc, cells);
    return 0;
}

void swe_ladder_notes(FILE *ladder, FILE *out)
{
    static char line[1 << 14];
    char a[16], b[16];
    int n = 0;
    rewind(ladder);
    while (fgets(line, sizeof line, ladder)) {
        chomp(line);
        if (strcmp(field(line, 1, a, sizeof a), "#") || strcmp(field(line, 2, b, sizeof b), "note"))
            continue;
        if (!n++)
            fputs("\n## Notes of the ladder file (what its total leaves out, how to read it)\n\n", out);
        fprintf(out, "* %s\n", strncmp(line, "# note ", 7) ? line : line + 7);
    }
}

/* a relative error in %: one decimal below 9.95 %, none above */
static void pc(char *s, size_t n, double x)
{
    snprintf(s, n, x < 9.95 ? "%.1f %%" : "%.0f %%", x);
}

static int ends_with(const char *s, const char *suffix)
{
    const size_t a = strlen(s), b = strlen(suffix);
    return a >= b && !strcmp(s + a - b, suffix);
}

int swe_total_error_table(FILE *csv, const char *run, const char *mvd, const char *ladder,
                          const char *level, const char *cells, FILE *out)
{
    static char line[1 << 14];
    size_t cap[3] = {4096, 4096, 4096}, len[3] = {0, 0, 0};
    char *rows[3];
    for (int i = 0; i < 3; i++) {
        rows[i] = malloc(cap[i]);
        if (!rows[i])
            return 1;
        rows[i][0] = 0;
    }
    char suffix[128], facekey[128], face[256] = "", facekind[64] = "";
    snprintf(suffix, sizeof suffix, "-mvd%s", mvd);
    snprintf(facekey, sizeof facekey, "face-mvd%s", mvd);
    for (int nr = 1; fgets(line, sizeof line, csv); nr++) {
        if (nr == 1)
            continue;
        chomp(line);
        char *f[14] = {0};
        const int k = csv_split(line, f, 14);
        for (int i = k; i < 14; i++)
            f[i] = "";
        if (strcmp(f[1], run))
            continue;
        const char *q = f[0];
        char label[256];
        double scale = 1;
        int ord;
        if (ends_with(q, suffix)) {
            char r[128];
            snprintf(r, sizeof r, "%.*s", (int)(strlen(q) - strlen(suffix)), q);
            if (!strcmp(r, "face"))
                snprintf(label, sizeof label, "whole face [g / 30 min]");
            else if (!strcmp(r, "left") || !strcmp(r, "right"))
                snprintf(label, sizeof label, "%s side [g / 30 min]", r);
            else
                snprintf(label, sizeof label, "%s [g / 30 min]", r);
            scale = 1000;
            ord = 0;
        } else if (!strncmp(q, "capture-", 8)) {
            snprintf(label, sizeof label, "class %s [ppm]", q + 8);
            ord = 1;
        } else if (!strcmp(q, "Cd") || !strcmp(q, "Cp_b") || !strcmp(q, "St")) {
            snprintf(label, sizeof label, "%s", q);
            ord = 2;
        } else
            continue;
        const double ref = num(f[11]), a = ref < 0 ? -ref : ref;
        char s[32] = "-", d[32] = "-", t[32] = "-", row[1024];
        if (a > 0) {
            pc(s, sizeof s, 100 * num(f[7]) / a);
            pc(d, sizeof d, 100 * num(f[8]) / a);
        }
        if (f[10][0])
            pc(t, sizeof t, 100 * num(f[10]));
        const int l = snprintf(row, sizeof row, "| %s | %.4g | %s | %s | %s | %.4g | %s |\n", label,
                               num(f[6]) * scale, s, d, t, ref * scale, f[12]);
        if (len[ord] + (size_t)l + 1 > cap[ord]) {
            cap[ord] = 2 * (len[ord] + (size_t)l + 1);
            char *r = realloc(rows[ord], cap[ord]);
            if (!r)
                return 1;
            rows[ord] = r;
        }
        memcpy(rows[ord] + len[ord], row, (size_t)l + 1);
        len[ord] += (size_t)l;
        if (!strcmp(q, facekey) && a > 0) {
            char tt[32];
            pc(tt, sizeof tt, 100 * num(f[10]));
            snprintf(face, sizeof face, "%s (sampling %s, discretization %s)", tt, s, d);
            snprintf(facekind, sizeof facekind, "%s", f[12]);
        }
    }
    fprintf(out, "# Total error of the rear deposit\n\n");
    fprintf(out,
            "This run judged against the resolution ladder of %s: its level %s (%s cells) is on it, so "
            "its discretization error is the one of its level on the ladder: the distance of the value "
            "of the level from the reference, combined with the uncertainty of the reference itself "
            "(snowladder total: the Richardson extrapolation where the finest three levels converge "
            "monotonically beyond their sampling noise; else a bound, the larger of the distances to "
            "the finest value and to the extrapolation with the schemes' order 2, each with its last "
            "step as its uncertainty). The total "
            "error combines it with the sampling error of this run, sqrt(sampling^2 + "
            "discretization^2); all three relative to the reference. The whole judgement: "
            "results/ladder/ (ladder.md, total_error.csv, total_error.png).\n\n",
            ladder, level, cells);
    if (!face[0])
        fprintf(out, "Rear face, decided spray (MVD %s um): no relative total error (the reference is 0).\n\n",
                mvd);
    else
        fprintf(out, "Rear face, decided spray (MVD %s um): total error %s%s.\n\n", mvd, face,
                strcmp(facekind, "bound")
                    ? ""
                    : ", a bound: the ladder does not resolve its steps (they lie within the sampling "
                      "noise, or do not fall monotonically), so the error covers both readings, the "
                      "finest value and the extrapolation with the schemes' order");
    fprintf(out, "| quantity | this run | sampling | discretization | total | reference | reference from "
                 "|\n|---|---:|---:|---:|---:|---:|---|\n");
    for (int i = 0; i < 3; i++) {
        fputs(rows[i], out);
        free(rows[i]);
    }
    return 0;
}
