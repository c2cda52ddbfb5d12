/* swe_opts.c - the command line of tutorials/wedge/Allrun (swe_opts.h). The checks
 * come in the order Allrun has always made them: each option as it is met, then the
 * cross-checks, then the variant's block, then -parallel against the processors. */
#include "swe_opts.h"
#include "swe_run.h"

#include <libgen.h>
#include <regex.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

static int fail(int code, char *err, size_t nerr, const char *fmt, ...) __attribute__((format(printf, 4, 5)));
static int fail(int code, char *err, size_t nerr, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(err, nerr, fmt, ap);
    va_end(ap);
    return code;
}

/* 1 when S matches the extended regular expression RE (anchored by RE itself) */
static int matches(const char *re, const char *s)
{
    regex_t r;
    if (regcomp(&r, re, REG_EXTENDED | REG_NOSUB))
        return 0;
    const int ok = !regexec(&r, s, 0, NULL, 0);
    regfree(&r);
    return ok;
}

static const char *number_re = "^[-+]?([0-9]+[.]?[0-9]*|[.][0-9]+)([eE][-+]?[0-9]+)?$";

static void copy(char *dst, size_t n, const char *src)
{
    snprintf(dst, n, "%s", src);
}

int swe_opts_variant(const char *path, const char *block, const char *key, char *out, size_t n)
{
    FILE *f = fopen(path, "r");
    if (!f)
        return -1;
    char *line = NULL;
    size_t cap = 0;
    int inb = 0, rc = 1;
    out[0] = '\0';
    while (getline(&line, &cap, f) >= 0) {
        line[strcspn(line, "\n")] = '\0';
        char *c = strstr(line, "//");
        if (c)
            *c = '\0';
        const char *f1 = line + strspn(line, " \t");
        const size_t l1 = strcspn(f1, " \t");
        if (!l1)
            continue;
        if (l1 == strlen(block) && !strncmp(f1, block, l1)) {
            inb = 1;
            continue;
        }
        if (!inb)
            continue;
        if (l1 == 1 && *f1 == '}')
            break;
        if (l1 != strlen(key) || strncmp(f1, key, l1))
            continue;
        /* the key and the blanks after it removed (the line kept whole without a blank),
           then a last ';' with only blanks after it */
        const char *v = line, *after = f1 + l1;
        if (strspn(after, " \t"))
            v = after + strspn(after, " \t");
        size_t len = strlen(v), t = len;
        while (t && (v[t - 1] == ' ' || v[t - 1] == '\t'))
            t--;
        if (t && v[t - 1] == ';')
            len = t - 1;
        size_t k = 0;
        for (size_t i = 0; i < len && k + 1 < n; i++)
            if (v[i] != '"')
                out[k++] = v[i];
        out[k] = '\0';
        rc = k ? 0 : 1;
        break;
    }
    free(line);
    fclose(f);
    return rc;
}

int swe_opts_entry(const char *path, const char *key, char *out, size_t n)
{
    FILE *f = fopen(path, "r");
    if (!f)
        return -1;
    char re[256], *line = NULL;
    size_t cap = 0;
    regex_t r;
    regmatch_t m[2];
    snprintf(re, sizeof re, "^[[:space:]]*%s[[:space:]]+(.*);[[:space:]]*$", key);
    int rc = regcomp(&r, re, REG_EXTENDED) ? -1 : 1;
    out[0] = '\0';
    while (rc == 1 && getline(&line, &cap, f) >= 0) {
        line[strcspn(line, "\n")] = '\0';
        char *c = strstr(line, "//");
        if (c)
            *c = '\0';
        if (!regexec(&r, line, 2, m, 0)) {
            snprintf(out, n, "%.*s", (int)(m[1].rm_eo - m[1].rm_so), line + m[1].rm_so);
            rc = 0;
        }
    }
    if (rc != -1)
        regfree(&r);
    free(line);
    fclose(f);
    return rc;
}

/* the first field after KEY as the first field of a line, up to a ';' (an awk reading) */
static void first_field_entry(const char *path, const char *key, char *out, size_t n)
{
    FILE *f = fopen(path, "r");
    char *line = NULL, *save = NULL;
    size_t cap = 0;
    out[0] = '\0';
    while (f && getline(&line, &cap, f) >= 0) {
        char *f1 = strtok_r(line, " \t\n", &save), *f2 = f1 ? strtok_r(NULL, " \t\n", &save) : NULL;
        if (f1 && !strcmp(f1, key)) {
            snprintf(out, n, "%.*s", f2 ? (int)strcspn(f2, ";") : 0, f2 ? f2 : "");
            break;
        }
    }
    free(line);
    if (f)
        fclose(f);
}

void swe_opts_quote(FILE *out, const char *value)
{
    fputc('\'', out);
    for (const char *p = value; *p; p++)
        if (*p == '\'')
            fputs("'\\''", out);
        else
            fputc(*p, out);
    fputc('\'', out);
}

int swe_opts_list(const char *opt, const char *text, int num, char *out, size_t n, FILE *notes, char *err,
                  size_t nerr)
{
    if (!*text)
        return fail(2, err, nerr, "%s: an empty list", opt);
    char *buf = strdup(text);
    size_t cap = 1;
    for (const char *p = text; *p; p++)
        cap += *p == ',';
    char **item = calloc(cap, sizeof *item);
    double *val = calloc(cap, sizeof *val);
    if (!buf || !item || !val) {
        free(buf), free(item), free(val);
        return fail(1, err, nerr, "%s: out of memory", opt);
    }
    size_t m = 0;
    int rc = 0;
    for (char *p = buf;; p++) {
        char *e = strchr(p, ',');
        if (e)
            *e = '\0';
        item[m] = p;
        if (!*p) {
            rc = fail(2, err, nerr, "%s: an empty item in '%s'", opt, text);
            break;
        }
        if (num && !matches(number_re, p)) {
            rc = fail(2, err, nerr, "%s: '%s' in '%s' is not a number", opt, p, text);
            break;
        }
        val[m] = num ? strtod(p, NULL) : 0;
        for (size_t j = 0; j < m && !rc; j++) {
            char a[64], b[64];
            if (num) {
                snprintf(a, sizeof a, "%.17g", val[j]);
                snprintf(b, sizeof b, "%.17g", val[m]);
            }
            if (num ? !strcmp(a, b) : !strcmp(item[j], p))
                rc = fail(2, err, nerr, "%s: '%s' is given twice in '%s'", opt, p, text);
        }
        m++;
        if (rc || !e)
            break;
        p = e;
    }
    if (!rc && num) { /* ascending, equal values keeping their order */
        int sorted = 1;
        for (size_t i = 1; i < m; i++)
            if (val[i] < val[i - 1])
                sorted = 0;
        for (size_t i = 1; i < m && !sorted; i++) {
            char *x = item[i];
            const double xv = val[i];
            size_t j = i;
            for (; j > 0 && val[j - 1] > xv; j--)
                item[j] = item[j - 1], val[j] = val[j - 1];
            item[j] = x, val[j] = xv;
        }
        if (!sorted && notes)
            fprintf(notes, "Allrun: note: %s: '%s' taken in ascending order\n", opt, text);
    }
    if (!rc) {
        size_t k = 0;
        out[0] = '\0';
        for (size_t i = 0; i < m; i++)
            k += (size_t)snprintf(out + (k < n ? k : n), k < n ? n - k : 0, "%s%s", i ? "," : "", item[i]);
        if (k >= n)
            rc = fail(2, err, nerr, "%s: the list '%s' is too long", opt, text);
    }
    free(buf), free(item), free(val);
    return rc;
}

int swe_opts_spray_entry(const char *file, const char *kind, const char *key, const char *value, char *out, size_t n,
                         char *err, size_t nerr)
{
    if (!file)
        file = "constant/sprayProperties";
    const char *num = "[+]?([0-9]+[.]?[0-9]*|[.][0-9]+)([eE][+-]?[0-9]+)?";
    char re[256];
    int ok;
    if (!strcmp(kind, "num")) {
        snprintf(re, sizeof re, "^%s$", num);
        copy(out, n, value);
        ok = matches(re, value) && strtod(value, NULL) > 0;
    } else { /* the parentheses removed, the words joined by one blank */
        size_t k = 0;
        for (const char *p = value; *p && k + 1 < n; p++)
            if (!strchr("()", *p) && (!strchr(" \t\n", *p) || (k && out[k - 1] != ' ')))
                out[k++] = strchr(" \t\n", *p) ? ' ' : *p;
        while (k && out[k - 1] == ' ')
            k--;
        out[k] = '\0';
        if (!strcmp(kind, "list2")) {
            snprintf(re, sizeof re, "^%s %s$", num, num);
            const char *second = strchr(out, ' ');
            ok = matches(re, out) && strtod(out, NULL) > 0 && strtod(second, NULL) > strtod(out, NULL);
        } else {
            ok = matches("^[1-9][0-9]{0,6}( [1-9][0-9]{0,6})*$", out);
            for (char *c = out; ok && *c; c++)
                *c = *c == ' ' ? ',' : *c;
        }
    }
    if (ok)
        return 0;
    const char *v = *out ? out : "<missing>";
    if (!strcmp(kind, "num"))
        return fail(2, err, nerr, "%s: '%s' must be a positive number, got '%s'", file, key, v);
    if (!strcmp(kind, "list2"))
        return fail(2, err, nerr,
                    "%s: '%s' must be two positive numbers, the first the smaller, got '%s'",
                    file, key, v);
    return fail(2, err, nerr, "%s: '%s' must be a list of whole numbers from 1, got '%s'", file,
                key, v);
}

/* the directory DIR (relative) seen from the logical folder BASE as `cd DIR && pwd`
   shows it: "." and ".." taken by name, else (no such folder) the physical path */
static int logical_dir(const char *base, const char *dir, char *out, size_t n)
{
    char *path = malloc(strlen(base) + strlen(dir) + 2);
    if (!path)
        return 1;
    sprintf(path, "%s/%s", base, dir);
    size_t k = 0;
    out[0] = '\0';
    for (char *save = NULL, *c = strtok_r(path, "/", &save); c; c = strtok_r(NULL, "/", &save)) {
        if (!strcmp(c, "."))
            continue;
        if (!strcmp(c, "..")) {
            while (k && out[k - 1] != '/')
                k--;
            if (k)
                k--;
            out[k] = '\0';
            continue;
        }
        if (k + strlen(c) + 2 > n) {
            free(path);
            return 1;
        }
        k += (size_t)sprintf(out + k, "/%s", c);
    }
    free(path);
    if (!k)
        copy(out, n, "/");
    struct stat st;
    if (stat(out, &st) || !S_ISDIR(st.st_mode)) {
        char *r = realpath(dir, NULL);
        if (!r)
            return 1;
        copy(out, n, r);
        free(r);
    }
    return 0;
}

static int add_arg(swe_allrun *o, const char *a, size_t len)
{
    char **args = realloc(o->args, (size_t)(o->nargs + 1) * sizeof *args);
    if (!args)
        return 1;
    o->args = args;
    if (!(o->args[o->nargs] = strndup(a, len)))
        return 1;
    o->nargs++;
    return 0;
}

/* log.Allrun.args, one option a line, as the options of the run */
static int read_resume_args(swe_allrun *o, const char *case_dir, char *err, size_t nerr)
{
    struct stat st;
    if (stat("log.Allrun.args", &st) || !S_ISREG(st.st_mode))
        return fail(2, err, nerr,
                    "-resume: no run to resume in %s (log.Allrun.args is missing: a run writes it when it starts)",
                    case_dir);
    FILE *f = fopen("log.Allrun.args", "r");
    if (!f)
        return fail(1, err, nerr, "-resume: cannot read %s/log.Allrun.args", case_dir);
    char *line = NULL;
    size_t cap = 0;
    ssize_t len;
    int rc = 0;
    while (!rc && (len = getline(&line, &cap, f)) >= 0)
        rc = add_arg(o, line, (size_t)len - (len && line[len - 1] == '\n'));
    free(line);
    fclose(f);
    return rc ? fail(1, err, nerr, "-resume: out of memory") : 0;
}

static const char *flags[] = {"-feedback", "-rebound", "-rough", "-wake-source", "-full", "-halfstep",
                              "-refine-wake", "-compare", "-split", "-oversubscribe", NULL};

static int *flag_var(swe_allrun *o, const char *a)
{
    int *vars[] = {&o->feedback, &o->rebound, &o->rough, &o->wake_source, &o->full, &o->halfstep,
                   &o->refine_wake, &o->compare, &o->split, &o->oversubscribe};
    for (int i = 0; flags[i]; i++)
        if (!strcmp(a, flags[i]))
            return vars[i];
    return NULL;
}

/* the options one by one, each refused as it is met */
static int parse_loop(swe_allrun *o, int n, char *const *a, const char *case_dir, FILE *notes, int *replay_given,
                      int *checkpoint_given, char *err, size_t nerr)
{
    static const char *levels[] = {"-3", "-2", "-1", "0", "1", "2", "3", NULL};
    for (int i = 0; i < n; i++) {
        const char *v = i + 1 < n ? a[i + 1] : "";
        int *flag = flag_var(o, a[i]);
        if (!strcmp(a[i], "-h") || !strcmp(a[i], "--help")) {
            o->help = 1;
            return 0;
        } else if (flag) {
            *flag = 1;
        } else if (!strcmp(a[i], "-steady")) {
            copy(o->route, sizeof o->route, "steady");
        } else if (!strcmp(a[i], "-replay")) {
            o->replay = *replay_given = 1;
        } else if (!strcmp(a[i], "-coupled")) {
            o->replay = 0;
        } else if (!strcmp(a[i], "-rear-layers") || !strcmp(a[i], "-no-rear-layers")) {
            o->rear_layers = a[i][1] == 'r';
        } else if (!strcmp(a[i], "-estimate")) {
            o->estimate = 1;
        } else if (!strcmp(a[i], "-ladder")) {
            struct stat st;
            o->ladder_given = 1;
            if (!*v)
                return fail(2, err, nerr, "-ladder needs a file (a ladder.csv of post/wedge-ladder) or none");
            if (strcmp(v, "none") && (stat(v, &st) || !S_ISREG(st.st_mode) || access(v, R_OK)))
                return fail(2, err, nerr, "-ladder %s: not a readable file", v);
            if (!strcmp(v, "none") || v[0] == '/') {
                copy(o->ladder, sizeof o->ladder, v);
            } else { /* Allrun works in the case folder: the path as seen from there */
                char *d = strdup(v), *b = strdup(v), dir[SWE_OPTS_TEXT / 2];
                const int bad = !d || !b || logical_dir(case_dir, dirname(d), dir, sizeof dir);
                if (!bad)
                    snprintf(o->ladder, sizeof o->ladder, "%s/%s", dir, basename(b));
                free(d), free(b);
                if (bad)
                    return fail(2, err, nerr, "-ladder %s: not a readable file", v);
            }
            i++;
        } else if (!strcmp(a[i], "-checkpoint")) {
            *checkpoint_given = 1;
            const double m = strtod(v, NULL);
            if (strcmp(v, "off") &&
                !(matches("^[0-9]*[.]?[0-9]+([eE][-+]?[0-9]+)?$", v) && m > 0 && m <= 1e6))
                return fail(2, err, nerr,
                            "-checkpoint needs a positive number of minutes (at most 1e6) or off, got '%s'", v);
            copy(o->checkpoint, sizeof o->checkpoint, v);
            i++;
        } else if (!strcmp(a[i], "-resume")) {
            return fail(2, err, nerr, "-resume is the only option of its command line (the run goes on with its own)");
        } else if (!strcmp(a[i], "-level")) {
            int k = 0;
            while (levels[k] && strcmp(levels[k], v))
                k++;
            if (!levels[k])
                return fail(2, err, nerr, "-level needs a whole number from -3 to 3, got '%s'", v);
            copy(o->mesh_level, sizeof o->mesh_level, v);
            i++;
        } else if (!strcmp(a[i], "-parcels")) {
            if (!matches("^[1-9][0-9]?$", v))
                return fail(2, err, nerr, "-parcels needs a whole factor from 1 to 99, got '%s'", v);
            copy(o->parcels, sizeof o->parcels, v);
            i++;
        } else if (!strcmp(a[i], "-parallel")) { /* digits only, at most 6 (no overflow) */
            if (!matches("^[1-9][0-9]{0,5}$", v))
                return fail(2, err, nerr,
                            "-parallel needs a whole number of processes from 1 (without leading zeros), got '%s'", v);
            copy(o->nproc_run, sizeof o->nproc_run, v);
            i++;
        } else if (!strcmp(a[i], "-fine") || !strcmp(a[i], "-test")) {
            if (strcmp(o->level, "coarse") && strcmp(o->level, a[i] + 1))
                return fail(2, err, nerr, "%s with -%s: give one mesh level (-fine or -test)", a[i], o->level);
            copy(o->level, sizeof o->level, a[i] + 1);
        } else if (!strcmp(a[i], "-gate")) {
            if (!matches("^(off|tangential|shear|regime)$", v))
                return fail(2, err, nerr, "-gate must be off, tangential, shear or regime, got '%s'", v);
            copy(o->gate, sizeof o->gate, v);
            i++;
        } else if (!strcmp(a[i], "-dispersion")) {
            const int rc = swe_opts_list("-dispersion", v, 0, o->dispersions, sizeof o->dispersions, notes, err, nerr);
            if (rc)
                return rc;
            const char *t = "(nearwall|nearwall-utau|nearwall-k|crw|stochastic|gradient|none)";
            char re[256];
            snprintf(re, sizeof re, "^%s(,%s)*$", t, t);
            if (!matches(re, o->dispersions))
                return fail(2, err, nerr,
                            "-dispersion needs a comma-separated list of nearwall, nearwall-utau, nearwall-k, crw, "
                            "stochastic, gradient, none; got '%s'",
                            v);
            i++;
        } else if (!strcmp(a[i], "-sizes")) {
            o->sizes_given = 1;
            copy(o->sizes, sizeof o->sizes, v);
            if (strcmp(v, "none")) {
                const int rc = swe_opts_list("-sizes", v, 1, o->sizes, sizeof o->sizes, notes, err, nerr);
                if (rc)
                    return rc;
                char *s = strdup(o->sizes), *save = NULL;
                int ok = s != NULL;
                for (char *c = s ? strtok_r(s, ",", &save) : NULL; c && ok; c = strtok_r(NULL, ",", &save))
                    ok = matches("^[0-9]+$", c) && strtod(c, NULL) >= 1 && strtod(c, NULL) <= 1000;
                free(s);
                if (!ok)
                    return fail(2, err, nerr,
                                "-sizes needs whole diameters in um (1..1000), comma-separated, or none, got '%s'", v);
            }
            i++;
        } else {
            return fail(2, err, nerr, "unknown option '%s' (see --help)", a[i]);
        }
    }
    return 0;
}

static int variant(const swe_allrun *o, const char *key, int optional, char *out, size_t n, char *err, size_t nerr)
{
    if (swe_opts_variant("constant/variants", o->level, key, out, n) && !optional)
        return fail(2, err, nerr, "constant/variants: no %s for the variant %s", key, o->level);
    return 0;
}

/* the route's options: those of the transient route refused on the steady one, -rear-layers's
 * default, the -dispersion list split into the main treatment and the others */
static int route_options(swe_allrun *o, int replay_given, int checkpoint_given, char *err, size_t nerr)
{
    const int transient = !strcmp(o->route, "transient");
    if (o->sizes_given && strcmp(o->sizes, "none") && !transient)
        return fail(2, err, nerr, "-sizes needs the transient route (not -steady)");
    if (o->wake_source && !strcmp(o->sizes, "none"))
        return fail(2, err, nerr, "-wake-source releases the size classes in the wake: not with -sizes none");
    if (!strcmp(o->sizes, "none"))
        o->sizes[0] = '\0';
    /* the options of the transient route only, in the order they have always been checked */
    const int given[] = {o->feedback, o->rebound, o->rough, replay_given, o->wake_source,
                         o->full,     o->halfstep, o->resume, checkpoint_given};
    const char *name[] = {"feedback", "rebound", "rough", "replay", "wake-source", "full", "halfstep", "resume",
                          "checkpoint"};
    for (int i = 0; i < 9 && !transient; i++)
        if (given[i] && !strcmp(name[i], "resume"))
            return fail(2, err, nerr, "-resume: the steady route is not resumed (a few minutes: run it again)");
        else if (given[i])
            return fail(2, err, nerr, "-%s needs the transient route (not -steady)", name[i]);
    if (!transient)
        o->replay = 0;
    if (o->rear_layers == 1 && !transient)
        return fail(2, err, nerr,
                    "-rear-layers needs the transient route (simpleFoam does not converge on the resolved rear face; "
                    "the steady route keeps its wall function there)");
    if (o->rear_layers < 0)
        o->rear_layers = transient;
    const size_t first = strcspn(o->dispersions, ",");
    snprintf(o->disp_main, sizeof o->disp_main, "%.*s", (int)first, o->dispersions);
    copy(o->disp_extra, sizeof o->disp_extra, o->dispersions[first] ? o->dispersions + first + 1 : "");
    for (char *c = o->disp_extra; *c; c++)
        if (*c == ',')
            *c = ' ';
    if (*o->disp_extra && !transient)
        return fail(2, err, nerr, "several -dispersion treatments need the transient route (not -steady)");
    return 0;
}

/* -parallel N against the machine's processors (nproc) and the mesh of the level (with -level
 * and -refine-wake) against -parallel N */
static int parallel_and_mesh(swe_allrun *o, long ncpu, char *err, size_t nerr)
{
    /* -parallel N: at most nproc (-oversubscribe: 4 x) */
    const long np = strtol(o->nproc_run, NULL, 10), np_max = o->oversubscribe ? 4 * ncpu : ncpu;
    if (np > np_max && !o->oversubscribe)
        return fail(2, err, nerr,
                    "-parallel %ld: this machine has %ld processors (nproc); accepted: 1 to %ld (up to %ld with "
                    "-oversubscribe)",
                    np, ncpu, np_max, 4 * ncpu);
    if (np > np_max)
        return fail(2, err, nerr, "-parallel %ld: accepted with -oversubscribe: 1 to %ld (4 x the %ld processors of nproc)",
                    np, np_max, ncpu);
    if (o->oversubscribe && np <= 1)
        return fail(2, err, nerr, "-oversubscribe needs -parallel N with N > 1");
    o->mpi_oversubscribe = np > ncpu;
    /* the mesh of the level, -level and -refine-wake; -parallel N at most its cells along y */
    swe_mesh m;
    static const char *keys[] = {"nxUp", "nxBody", "nxDown", "nBody", "nOut"};
    if (swe_mesh_parse(o->mesh, &m, err, nerr))
        return 2;
    for (int i = 0; i < 5; i++)
        if (swe_mesh_get(&m, keys[i]) < 0)
            return fail(2, err, nerr, "the mesh '%s' has no %s", o->mesh, keys[i]);
    const int lv = atoi(o->mesh_level);
    if (lv || o->refine_wake) {
        swe_mesh_scale(&m, lv, o->refine_wake);
        swe_mesh_format(&m, o->mesh, sizeof o->mesh);
    }
    o->ny = swe_mesh_ny(&m);
    snprintf(o->level_scale, sizeof o->level_scale, "%.12g", swe_level_scale(lv));
    if (np > o->ny)
        return fail(2, err, nerr,
                    "-parallel %ld: the %s mesh has %ld cells along y and every process needs a slab of at least one: "
                    "accepted 1 to %ld",
                    np, o->level, o->ny, o->ny);
    return 0;
}

/* the regime map's slide length and v_t list (vtlist: comma-separated) */
static int regime_map(swe_allrun *o, char *err, size_t nerr)
{
    char vt[1024];
    swe_opts_entry("constant/gates/regime", "slideLength", o->slide, sizeof o->slide);
    swe_opts_entry("constant/gates/regime", "vtTable", vt, sizeof vt);
    size_t k = 0;
    for (const char *p = vt; *p && k + 1 < sizeof o->vtlist; p++)
        if (!strchr("()", *p) && (!strchr(" \t", *p) || (k && o->vtlist[k - 1] != ',')))
            o->vtlist[k++] = strchr(" \t", *p) ? ',' : *p;
    while (k && o->vtlist[k - 1] == ',')
        k--;
    o->vtlist[k] = '\0';
    if (!*o->slide || !*o->vtlist)
        return fail(2, err, nerr, "constant/gates/regime: slideLength and vtTable are required");
    return 0;
}

int swe_opts_parse(int nargs, char *const *argv, const char *case_dir, long ncpu, swe_allrun *o, FILE *notes,
                   char *err, size_t nerr)
{
    memset(o, 0, sizeof *o);
    copy(o->nproc_run, sizeof o->nproc_run, "1");
    copy(o->mesh_level, sizeof o->mesh_level, "0");
    copy(o->level, sizeof o->level, "coarse");
    copy(o->route, sizeof o->route, "transient");
    copy(o->gate, sizeof o->gate, "off");
    copy(o->checkpoint, sizeof o->checkpoint, "30");
    copy(o->dispersions, sizeof o->dispersions, "nearwall");
    o->replay = 1;
    o->rear_layers = -1; /* 1 on the transient route, 0 on the steady one, unless given */
    int rc = 0;
    if (nargs >= 1 && !strcmp(argv[0], "-resume")) {
        if (nargs != 1)
            return fail(2, err, nerr,
                        "-resume takes no other option: the run goes on with its own (log.Allrun.args)");
        if ((rc = read_resume_args(o, case_dir, err, nerr)))
            return rc;
        o->resume = 1;
    } else {
        for (int i = 0; i < nargs && !rc; i++)
            rc = add_arg(o, argv[i], strlen(argv[i]));
        if (rc)
            return fail(1, err, nerr, "out of memory");
    }
    int replay_given = 0, checkpoint_given = 0;
    if ((rc = parse_loop(o, o->nargs, o->args, case_dir, notes, &replay_given, &checkpoint_given, err, nerr)) ||
        o->help)
        return rc;
    /* the options as -resume will read them: -ladder's file as the absolute path found above */
    for (int i = 0; i + 1 < o->nargs; i++)
        if (!strcmp(o->args[i], "-ladder")) {
            char *l = strdup(o->ladder);
            if (!l)
                return fail(1, err, nerr, "out of memory");
            free(o->args[i + 1]);
            o->args[i + 1] = l;
        }
    if ((rc = route_options(o, replay_given, checkpoint_given, err, nerr)))
        return rc;
    /* the variant's block: the mesh, the parcel factors, -rough's grid, the optional times */
    if ((rc = variant(o, "mesh", 0, o->mesh, sizeof o->mesh, err, nerr)) ||
        (rc = variant(o, "parcelFactor", 0, o->parcel_factor, sizeof o->parcel_factor, err, nerr)) ||
        (rc = variant(o, "classFactor", 0, o->class_factor, sizeof o->class_factor, err, nerr)) ||
        (rc = variant(o, "steadyFactor", 0, o->steady_factor, sizeof o->steady_factor, err, nerr)))
        return rc;
    /* -parcels K: the size classes' parcels K times (the variant's classFactor x K) */
    if (o->parcels[0] && strcmp(o->parcels, "1")) {
        const double cf = strtod(o->class_factor, NULL) * strtod(o->parcels, NULL);
        if (o->route[0] == 's')
            return fail(2, err, nerr, "-parcels multiplies the size classes of the transient route (not -steady)");
        snprintf(o->class_factor, sizeof o->class_factor, "%.10g", cf);
    }
    if ((rc = parallel_and_mesh(o, ncpu, err, nerr)))
        return rc;
    /* the default ladder: the one measured on the run's mesh family, when the case holds it */
    struct stat st;
    const char *def = o->rear_layers ? "constant/ladder-rear-layers.csv" : "constant/ladder.csv";
    if (!o->ladder_given)
        copy(o->ladder, sizeof o->ladder, stat(def, &st) ? "none" : def);
    /* -rough's grid (refused here, before anything is written), the variant's own times */
    if (o->rough && (rc = variant(o, strcmp(o->gate, "regime") ? "roughGrid" : "roughGridRegime", 0, o->rough_grid,
                                  sizeof o->rough_grid, err, nerr)))
        return rc;
    variant(o, "spinUpTime", 1, o->spin, sizeof o->spin, err, nerr);
    variant(o, "fillTime", 1, o->fill, sizeof o->fill, err, nerr);
    variant(o, "samplingTime", 1, o->sample, sizeof o->sample, err, nerr);
    variant(o, "replayStart", 1, o->replay_start, sizeof o->replay_start, err, nerr);
    variant(o, "replayPeriod", 1, o->replay_period, sizeof o->replay_period, err, nerr);
    /* the regime map's slide length and v_t list; the step the replay interval is checked against */
    if ((rc = regime_map(o, err, nerr)))
        return rc;
    if (o->halfstep)
        copy(o->max_delta_t, sizeof o->max_delta_t, "5e-4");
    else
        first_field_entry("system/controlDict.transient", "maxDeltaT", o->max_delta_t, sizeof o->max_delta_t);
    return 0;
}

static void assign(FILE *out, const char *name, const char *value)
{
    fprintf(out, "%s=", name);
    swe_opts_quote(out, value);
    fputc('\n', out);
}

void swe_opts_write(FILE *out, const swe_allrun *o)
{
    fprintf(out, "help=%d\n", o->help);
    if (o->help)
        return;
    fputs("args_given=(", out);
    for (int i = 0; i < o->nargs; i++) {
        fputs(i ? " " : "", out);
        swe_opts_quote(out, o->args[i]);
    }
    fputs(")\n", out);
    const struct {
        const char *name;
        int v;
    } ints[] = {{"resume", o->resume},           {"oversubscribe", o->oversubscribe}, {"compare", o->compare},
                {"split", o->split},             {"sizes_given", o->sizes_given},     {"feedback", o->feedback},
                {"rebound", o->rebound},         {"rough", o->rough},                 {"replay", o->replay},
                {"wake_source", o->wake_source}, {"full", o->full},                   {"halfstep", o->halfstep},
                {"refine_wake", o->refine_wake}, {"estimate_only", o->estimate},      {"rear_layers", o->rear_layers}};
    for (size_t i = 0; i < sizeof ints / sizeof *ints; i++)
        fprintf(out, "%s=%d\n", ints[i].name, ints[i].v);
    const struct {
        const char *name, *v;
    } texts[] = {{"nproc_run", o->nproc_run},
                 {"mesh_level", o->mesh_level},
                 {"level", o->level},
                 {"route", o->route},
                 {"gate", o->gate},
                 {"checkpoint_min", o->checkpoint},
                 {"sizes", o->sizes},
                 {"dispersions", o->dispersions},
                 {"disp_main", o->disp_main},
                 {"disp_extra", o->disp_extra},
                 {"ladder_file", o->ladder},
                 {"mesh", o->mesh},
                 {"level_scale", o->level_scale},
                 {"ppn_factor", o->parcel_factor},
                 {"class_factor", o->class_factor},
                 {"steady_factor", o->steady_factor},
                 {"rough_grid", o->rough_grid},
                 {"variant_spinUpTime", o->spin},
                 {"variant_fillTime", o->fill},
                 {"variant_samplingTime", o->sample},
                 {"variant_replayStart", o->replay_start},
                 {"variant_replayPeriod", o->replay_period},
                 {"slide", o->slide},
                 {"vtlist", o->vtlist}};
    for (size_t i = 0; i < sizeof texts / sizeof *texts; i++)
        assign(out, texts[i].name, texts[i].v);
    fprintf(out, "ny=%ld\nmpi_opts=(%s)\n", o->ny, o->mpi_oversubscribe ? "--oversubscribe" : "");
    /* the estimate's arguments that come from the options and the case's settings */
    fputs("est=(--mesh ", out);
    swe_opts_quote(out, o->mesh);
    fprintf(out, " --nozzle-array constant/nozzleArray --np %s%s", o->nproc_run, o->compare ? " --compare" : "");
    if (!strcmp(o->route, "steady")) {
        fputs(" --route steady --ppn-factor ", out);
        swe_opts_quote(out, o->steady_factor);
        fputs(")\n", out);
        return;
    }
    if (o->replay) {
        fputs(" --replay --max-delta-t ", out);
        swe_opts_quote(out, o->max_delta_t);
    }
    const int flag[] = {o->feedback, o->rough, o->rebound, o->split, o->full, o->halfstep, o->rear_layers, o->wake_source};
    const char *name[] = {"feedback", "rough", "rebound", "split", "full", "halfstep", "rear-layers", "wake-source"};
    for (int i = 0; i < 8; i++)
        if (flag[i])
            fprintf(out, " --%s", name[i]);
    const char *v[][2] = {{"--ppn-factor", o->parcel_factor}, {"--class-factor", o->class_factor},
                          {"--dispersion", o->dispersions},   {"--level-scale", o->level_scale}};
    for (int i = 0; i < 4; i++) {
        fprintf(out, " %s ", v[i][0]);
        swe_opts_quote(out, v[i][1]);
    }
    fputs(")\n", out);
}

void swe_opts_free(swe_allrun *o)
{
    for (int i = 0; i < o->nargs; i++)
        free(o->args[i]);
    free(o->args);
    o->args = NULL;
    o->nargs = 0;
}
