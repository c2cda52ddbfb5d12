/* swe_resume.c - a resumed wedge run: its solver logs and function-object
 * tables joined into those of one run, the time it restarts from (swe_run.h). */
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

/* ---- a resumed run ---------------------------------------------------------------------- */
#define SWE_JOIN_MAXC 256
typedef struct {
    char name[SWE_JOIN_MAXC][64];
    double v[SWE_JOIN_MAXC];
    int n;
} wall_set;

static double *wall_slot(wall_set *w, const char *name)
{
    for (int i = 0; i < w->n; i++)
        if (!strcmp(w->name[i], name))
            return &w->v[i];
    if (w->n == SWE_JOIN_MAXC)
        return NULL;
    snprintf(w->name[w->n], sizeof w->name[0], "%s", name);
    w->v[w->n] = 0;
    return &w->v[w->n++];
}

int swe_join_logs(FILE *const *parts, int n, FILE *out, char *err, size_t nerr)
{
    static char line[1 << 16];
    char tok[128];
    double *start = calloc((size_t)n + 1, sizeof *start);
    int *has = calloc((size_t)n + 1, sizeof *has);
    wall_set *off = calloc(1, sizeof *off), *last = calloc(1, sizeof *last);
    if (!start || !has || !off || !last) {
        free(start), free(has), free(off), free(last);
        return fail(err, nerr, 1, "out of memory");
    }
    /* first: each part's start, its first step's time less the deltaT before it */
    for (int i = 0; i < n; i++) {
        double dt = 0;
        while (fgets(line, sizeof line, parts[i])) {
            if (!strncmp(line, "deltaT = ", 9))
                dt = num(field(line, 3, tok, sizeof tok));
            else if (!strncmp(line, "Time = ", 7) && !has[i]) {
                start[i] = num(field(line, 3, tok, sizeof tok)) - dt;
                has[i] = 1;
            }
        }
        rewind(parts[i]);
    }
    for (int i = 0; i < n; i++) {
        int cut_has = 0;
        double cut = 0;
        for (int j = i + 1; j < n && !cut_has; j++)
            if (has[j]) {
                cut = start[j];
                cut_has = 1;
            }
        for (int c = 0; c < last->n; c++) {
            double *o = wall_slot(off, last->name[c]);
            if (o)
                *o += last->v[c];
        }
        last->n = 0;
        while (fgets(line, sizeof line, parts[i])) {
            if (!strncmp(line, "Time = ", 7) && cut_has &&
                num(field(line, 3, tok, sizeof tok)) > cut + 1e-9 * fabs(cut) + 1e-12)
                break;
            if (strncmp(line, "Wall time [s]", 13)) {
                fputs(line, out);
                if (!strchr(line, '\n'))
                    fputc('\n', out);
                continue;
            }
            chomp(line);
            char *colon = strchr(line, ':');
            if (!colon) { /* no entries: the line as it is */
                fprintf(out, "%s\n", line);
                continue;
            }
            fprintf(out, "%.*s", (int)(colon - line + 1), line);
            char *p = colon + 1;
            while (*p == ' ')
                p++;
            for (int k = 0; *p; k++) {
                char *e = strchr(p, ',');
                if (e)
                    *e = 0;
                char name[64], val[128];
                field(p, 1, name, sizeof name);
                field(p, 2, val, sizeof val);
                double *l = wall_slot(last, name), *o = wall_slot(off, name);
                if (l)
                    *l = num(val);
                fprintf(out, "%s%s %.10g", k ? ", " : " ", name, num(val) + (o ? *o : 0));
                if (!e)
                    break;
                p = e + 1;
                while (*p == ' ')
                    p++;
            }
            fputc('\n', out);
        }
    }
    free(start), free(has), free(off), free(last);
    return 0;
}

int swe_join_table(FILE *base, FILE *add, double t, FILE *out)
{
    static char line[1 << 16];
    char tok[128];
    while (fgets(line, sizeof line, base))
        if (line[0] == '#' || num(field(line, 1, tok, sizeof tok)) <= t + 1e-9 * t + 1e-12)
            fputs(line, out);
    while (fgets(line, sizeof line, add))
        if (line[0] != '#')
            fputs(line, out);
    return 0;
}

/* a time folder's name: a digit, then digits, '.', 'e', '+', '-' */
static int is_time_name(const char *s)
{
    if (*s < '0' || *s > '9')
        return 0;
    for (; *s; s++)
        if (!strchr("0123456789.e+-", *s))
            return 0;
    return 1;
}

typedef struct {
    char name[256];
    double v;
} tname;

static int tname_desc(const void *a, const void *b)
{
    const tname *x = a, *y = b;
    return x->v < y->v ? 1 : x->v > y->v ? -1 : -strcmp(x->name, y->name);
}

/* the time folders (names) of dir, latest first; returns their count, -1 unreadable */
static int time_names(const char *dir, tname **out)
{
    DIR *d = opendir(dir);
    if (!d)
        return -1;
    int n = 0, cap = 0;
    tname *t = NULL;
    for (struct dirent *e; (e = readdir(d));) {
        if (!is_time_name(e->d_name) || strlen(e->d_name) >= sizeof t->name)
            continue;
        if (n == cap) {
            cap = cap ? 2 * cap : 16;
            tname *u = realloc(t, (size_t)cap * sizeof *t);
            if (!u)
                break;
            t = u;
        }
        snprintf(t[n].name, sizeof t[n].name, "%s", e->d_name);
        t[n].v = strtod(e->d_name, NULL);
        n++;
    }
    closedir(d);
    if (n)
        qsort(t, (size_t)n, sizeof *t, tname_desc);
    *out = t;
    return n;
}

static int nonempty_file(const char *path)
{
    struct stat st;
    return !stat(path, &st) && st.st_size > 0;
}

int swe_resume_time(const char *case_dir, int nproc, char *t, size_t n, char *err, size_t nerr)
{
    char root[4096], path[8192];
    t[0] = 0;
    for (int r = 0; nproc > 1 && r < nproc; r++) {
        struct stat st;
        snprintf(root, sizeof root, "%s/processor%d", case_dir, r);
        if (stat(root, &st) || !S_ISDIR(st.st_mode))
            return fail(err, nerr, 2, "-resume: processor%d is missing (the run was on %d processes; nothing "
                        "to resume)", r, nproc);
    }
    if (nproc > 1)
        snprintf(root, sizeof root, "%s/processor0", case_dir);
    else
        snprintf(root, sizeof root, "%s", case_dir);
    tname *tn = NULL;
    const int k = time_names(root, &tn);
    const char *fields[] = {"uniform/time", "U", "p", "k", "omega", "nut"};
    for (int i = 0; i < k && !t[0]; i++) {
        if (!(tn[i].v > 0))
            continue;
        int ok = 1;
        for (int r = 0; ok && r < (nproc > 1 ? nproc : 1); r++)
            for (size_t f = 0; ok && f < sizeof fields / sizeof *fields; f++) {
                if (nproc > 1)
                    snprintf(path, sizeof path, "%s/processor%d/%s/%s", case_dir, r, tn[i].name, fields[f]);
                else
                    snprintf(path, sizeof path, "%s/%s/%s", case_dir, tn[i].name, fields[f]);
                ok = nonempty_file(path);
            }
        if (ok)
            snprintf(t, n, "%s", tn[i].name);
    }
    free(tn);
    return 0;
}

static int name_cmp(const struct dirent **a, const struct dirent **b)
{
    return strcmp((*a)->d_name, (*b)->d_name);
}

int swe_restart_tables(const char *dir, const char *t, int mode, FILE *out, char *err, size_t nerr)
{
    struct dirent **sub = NULL;
    const int ns = scandir(dir, &sub, NULL, name_cmp);
    int rc = 0;
    char tdir[4096], first[8192], add[8192], tmp[8300];
    for (int i = 0; i < ns; i++) {
        const char *name = sub[i]->d_name;
        struct stat st;
        snprintf(tdir, sizeof tdir, "%s/%s/%s", dir, name, t);
        if (!rc && name[0] != '.' && strcmp(name, "lagrangian") && !stat(tdir, &st) && S_ISDIR(st.st_mode)) {
            char named[4096];
            snprintf(named, sizeof named, "%s/%s", dir, name);
            tname *tn = NULL;
            const int k = time_names(named, &tn);
            const char *base = k > 0 ? tn[k - 1].name : NULL; /* the first (lowest) time */
            struct dirent **files = NULL;
            const int nf = base && strcmp(base, t) ? scandir(tdir, &files, NULL, name_cmp) : 0;
            for (int j = 0; j < nf; j++) {
                snprintf(add, sizeof add, "%s/%s", tdir, files[j]->d_name);
                snprintf(first, sizeof first, "%s/%s/%s", named, base, files[j]->d_name);
                struct stat sa, sb;
                if (!rc && !stat(add, &sa) && S_ISREG(sa.st_mode) && !stat(first, &sb) && S_ISREG(sb.st_mode)) {
                    if (mode == SWE_TABLES_LIST)
                        fprintf(out, "%s %s\n", first, add);
                    else if (mode == SWE_TABLES_REMOVE)
                        remove(add);
                    else {
                        snprintf(tmp, sizeof tmp, "%s.joined", add);
                        FILE *a = fopen(first, "r"), *b = fopen(add, "r"), *o = fopen(tmp, "w");
                        int ok = a && b && o && !swe_join_table(a, b, strtod(t, NULL), o);
                        if (a)
                            fclose(a);
                        if (b)
                            fclose(b);
                        if (o && fclose(o))
                            ok = 0;
                        if (!ok || rename(tmp, first) || remove(add))
                            rc = fail(err, nerr, 1, "could not join %s", add);
                    }
                }
                free(files[j]);
            }
            free(files);
            free(tn);
        }
        free(sub[i]);
    }
    free(sub);
    if (mode == SWE_TABLES_JOIN && !rc) {
        DIR *d = opendir(dir);
        for (struct dirent *e; d && (e = readdir(d));) {
            snprintf(tdir, sizeof tdir, "%s/%s/%s", dir, e->d_name, t);
            if (e->d_name[0] != '.')
                rmdir(tdir); /* only when empty */
        }
        if (d)
            closedir(d);
    }
    return rc;
}

/* the first K with no log.SOLVER.partK */
static int first_free_part(const char *solver)
{
    char p[4096];
    struct stat st;
    int k = 1;
    for (;; k++) {
        snprintf(p, sizeof p, "log.%s.part%d", solver, k);
        if (stat(p, &st))
            return k;
    }
}

int swe_resume_start(const char *solver, const char *t, char *msg, size_t nmsg, char *err, size_t nerr)
{
    const char *cd = "system/controlDict", *tmp = "system/controlDict.resume";
    FILE *in = fopen(cd, "r"), *out = in ? fopen(tmp, "w") : NULL;
    char *line = NULL;
    size_t cap = 0;
    int set = 0;
    while (out && getline(&line, &cap, in) >= 0)
        if (!strncmp(line, "startFrom ", 10))
            fputs("startFrom       startTime;\n", out);
        else if (!strncmp(line, "startTime ", 10) && ++set)
            fprintf(out, "startTime       %s;\n", t);
        else
            fputs(line, out);
    free(line);
    if (in)
        fclose(in);
    struct stat st;
    if (!out || fclose(out) || stat(cd, &st) || chmod(tmp, st.st_mode) || rename(tmp, cd) || !set) {
        remove(tmp);
        return fail(err, nerr, 1, "-resume: could not set startTime %s in system/controlDict", t);
    }
    char log[4096], part[4096];
    snprintf(log, sizeof log, "log.%s", solver);
    snprintf(part, sizeof part, "log.%s.part%d", solver, first_free_part(solver));
    if (!stat(log, &st) && rename(log, part))
        return fail(err, nerr, 1, "-resume: could not move %s to %s", log, part);
    char e[8400];
    if (swe_restart_tables("postProcessing", t, SWE_TABLES_REMOVE, stdout, e, sizeof e))
        return fail(err, nerr, 1, "-resume: %s", e);
    FILE *r = fopen("log.Allrun.resumes", "a+");
    if (!r || fprintf(r, "%s\n", t) < 0 || fseek(r, 0, SEEK_SET)) {
        if (r)
            fclose(r);
        return fail(err, nerr, 1, "-resume: could not write log.Allrun.resumes");
    }
    int n = 0;
    for (int c; (c = fgetc(r)) != EOF;)
        n += c == '\n';
    fclose(r);
    snprintf(msg, nmsg, "resume: %s from time %s (the last time folder written whole), resume %d", solver, t, n);
    return 0;
}

int swe_resume_join(const char *solver, char *msg, size_t nmsg, char *err, size_t nerr)
{
    const int n = first_free_part(solver);
    char log[4096], joined[4110], names[8192] = "";
    snprintf(log, sizeof log, "log.%s", solver);
    snprintf(joined, sizeof joined, "%s.joined", log);
    FILE **parts = calloc((size_t)n, sizeof *parts);
    if (!parts)
        return fail(err, nerr, 1, "out of memory");
    char p[4096];
    snprintf(p, sizeof p, "log.%s.part%d", solver, n);
    int rc = rename(log, p) ? fail(err, nerr, 1, "-resume: could not move %s to %s", log, p) : 0;
    size_t used = 0;
    for (int k = 1; k <= n && !rc; k++) {
        snprintf(p, sizeof p, "log.%s.part%d", solver, k);
        used += (size_t)snprintf(names + used, used < sizeof names ? sizeof names - used : 0, "%s%s", k > 1 ? " " : "", p);
        if (!(parts[k - 1] = fopen(p, "r")))
            rc = fail(err, nerr, 1, "-resume: could not join the solver logs (cannot read %s)", p);
    }
    FILE *out = rc ? NULL : fopen(joined, "w");
    char e[512];
    if (!rc) {
        int bad = !out || swe_join_logs(parts, n, out, e, sizeof e);
        if ((out && fclose(out)) || bad || rename(joined, log))
            rc = fail(err, nerr, 1, "-resume: could not join the solver logs %s", names);
    }
    for (int k = 0; k < n; k++)
        if (parts[k])
            fclose(parts[k]);
    free(parts);
    FILE *r = rc ? NULL : fopen("log.Allrun.resumes", "r");
    if (!rc && !r)
        rc = fail(err, nerr, 1, "-resume: cannot read log.Allrun.resumes");
    char t[256], te[8400];
    while (!rc && fgets(t, sizeof t, r)) {
        char *a = t + strspn(t, " \t");
        a[strcspn(a, " \t\n")] = '\0';
        if (swe_restart_tables("postProcessing", a, SWE_TABLES_JOIN, stdout, te, sizeof te))
            rc = fail(err, nerr, 1, "-resume: %s", te);
    }
    if (r)
        fclose(r);
    if (!rc)
        snprintf(msg, nmsg, "resume: the logs of %d parts joined into %s; the tables of postProcessing/ joined", n, log);
    return rc;
}
