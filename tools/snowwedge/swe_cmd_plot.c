/* swe_cmd_plot.c - snowwedge panels, compare and blocks: the rear-face maps
 * side by side on one colour scale (the script from swe_plot.h, drawn by
 * gnuplot on the PATH), the gate comparison of tutorials/wedge (post/wedge-panels
 * and post/wedge-compare are their wrappers) and the composed rear face on the
 * blocks its statistics hold (swe_blocks.h; post/wedge-compose). Every output file is written to a
 * temporary in its folder and renamed into place (common/swo_out.h) only when
 * the final name is absent or a regular file. --name NAME, first, sets the
 * prefix of the messages. */
#include "swe_blocks.h"
#include "swe_cli.h"
#include "swe_plot.h"
#include "swe_post.h"
#include "swo_out.h"

#include <errno.h>
#include <libgen.h>
#include <math.h>
#include <signal.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

static const char *prog = "snowwedge";
static swo_set *live; /* the output being written, removed when the command dies */

static void die(int code, const char *fmt, ...) __attribute__((noreturn, format(printf, 2, 3)));
static void die(int code, const char *fmt, ...)
{
    swo_free(live);
    va_list ap;
    fprintf(stderr, "%s: ", prog);
    va_start(ap, fmt);
    vfprintf(stderr, fmt, ap);
    va_end(ap);
    fputc('\n', stderr);
    exit(code);
}

static const char *panels_help =
    "%s - rear-face deposit maps side by side on one colour scale (PNG, gnuplot).\n"
    "\n"
    "Usage: %s --out PNG --title TEXT CSV TITLE [CSV TITLE ...]\n"
    "\n"
    "  --out PNG     the picture; an existing PNG is replaced only when it is a regular file\n"
    "  --title TEXT  the figure's title (a literal \"\\n\" starts a new line)\n"
    "  CSV TITLE     a rear-face map of post/wedge-post (y,z,deposit_kg_m2) and its panel's title\n"
    "Faces seen from behind, the colour scale from 0 to the largest value of all maps, titles\n"
    "wrapped to the width they have (doc/reference/wedge-post.md).\n"
    "Exit status 0 on success, 2 on bad usage, 1 when a map is missing or empty or gnuplot fails.\n";

static const char *compare_help =
    "%s - the gate comparison of tutorials/wedge (after Allrun -compare), from\n"
    "DIR/<gate>/rear_deposit.csv and deposit_per_patch.csv of the gate settings off,\n"
    "tangential, shear, regime: DIR/gates_compare.png (the rear faces on one colour scale),\n"
    "DIR/gates_per_patch.md (snowwedge gates) and DIR/regions.md (snowphoto regions with\n"
    "one threshold: F x the largest rear-face deposit of the four settings).\n"
    "\n"
    "Usage: %s --results DIR [--snowphoto EXE] [--rel F]\n"
    "\n"
    "  --snowphoto EXE  default the snowphoto beside snowwedge (bin/snowphoto of this repository)\n"
    "  --rel F          the threshold's share of the largest deposit, (0, 1] (default 0.1)\n";

/* the option's value: present and not empty, else a usage error */
static const char *value(int argc, char **argv, int i, const char *what)
{
    if (i + 1 >= argc || !argv[i + 1][0])
        die(2, "%s needs %s (see --help)", argv[i], what);
    return argv[i + 1];
}

/* a final name that exists and is not a regular file (a symbolic link neither) */
static int not_regular(const char *path)
{
    struct stat st;
    return lstat(path, &st) == 0 && !S_ISREG(st.st_mode);
}

/* ---- one output file ----------------------------------------------------------------- */
/* its temporary in its folder (the set is `live` until published) */
static const char *out_begin(const char *path)
{
    char err[1024];
    if (not_regular(path))
        die(2, "'%s' exists and is not a regular file: not replaced", path);
    const swo_spec spec = {prog, "--out", NULL, 0, 0};
    if (swo_alloc(&spec, &live, err, sizeof err) != SWO_OK)
        die(2, "%s", err);
    const char *tmp = swo_add(live, path, err, sizeof err);
    if (!tmp)
        die(swo_code(live), "%s", err);
    return tmp;
}

/* the temporary (mode 644) renamed to PATH: refused (exit 2, the temporary
   removed) when PATH is there and not a regular file */
static void out_publish(const char *tmp, const char *path)
{
    char err[1024];
    if (chmod(tmp, 0644))
        die(1, "cannot write '%s': %s", path, strerror(errno));
    if (not_regular(path))
        die(2, "'%s' exists and is not a regular file: not replaced", path);
    if (swo_commit(live, err, sizeof err) != SWO_OK)
        die(swo_code(live), "%s", err);
    swo_free(live);
    live = NULL;
}

/* a file's text on standard output */
static void show(const char *path)
{
    FILE *f = swe_cli_open(path);
    char b[4096];
    size_t n;
    while ((n = fread(b, 1, sizeof b, f)))
        fwrite(b, 1, n, stdout);
    fclose(f);
}

/* ---- panels ----------------------------------------------------------------------------- */
/* the records of a file as awk counts them (0 when unreadable) */
static long records(const char *path)
{
    FILE *f = fopen(path, "r");
    if (!f)
        return 0;
    long n = 0;
    int c, last = '\n';
    while ((c = getc(f)) != EOF)
        n += (last = c) == '\n';
    fclose(f);
    return n + (last != '\n');
}

/* the script run by gnuplot: 0 when it exited 0 */
static int gnuplot(const char *script, size_t len)
{
    int fd[2];
    fflush(NULL);
    if (pipe(fd))
        return -1;
    const pid_t pid = fork();
    if (pid < 0)
        return -1;
    if (pid == 0) {
        dup2(fd[0], 0);
        close(fd[0]);
        close(fd[1]);
        execlp("gnuplot", "gnuplot", (char *)NULL);
        fprintf(stderr, "%s: gnuplot: %s\n", prog, strerror(errno));
        _exit(127);
    }
    swo_signal_child(pid);
    close(fd[0]);
    void (*was)(int) = signal(SIGPIPE, SIG_IGN); /* gnuplot gone: a write error, not a signal */
    size_t done = 0;
    while (done < len) {
        const ssize_t w = write(fd[1], script + done, len - done);
        if (w < 0 && errno == EINTR)
            continue;
        if (w <= 0)
            break;
        done += (size_t)w;
    }
    close(fd[1]);
    signal(SIGPIPE, was);
    int st;
    while (waitpid(pid, &st, 0) < 0 && errno == EINTR)
        ;
    swo_signal_child(0);
    return done == len && WIFEXITED(st) && WEXITSTATUS(st) == 0 ? 0 : -1;
}

/* the gnuplot script a writer left in the memory stream s (rc the writer's
 * status, err its message): closed (len is final only then), run and freed;
 * a failure exits as the commands always did */
static void run_script(FILE *s, char **script, const size_t *len, int rc, const char *err)
{
    if (fclose(s) || rc) {
        free(*script);
        die(rc ? 2 : 1, "%s", rc ? err : "out of memory");
    }
    const int grc = gnuplot(*script, *len);
    free(*script);
    if (grc)
        die(1, "gnuplot failed");
}

/* OUT must be absent or a regular file (not a symbolic link) in a folder that exists */
static void file_check(const char *path)
{
    char *d = strdup(path);
    if (!d)
        die(1, "out of memory");
    const char *dir = dirname(d);
    struct stat st;
    if (stat(dir, &st) || !S_ISDIR(st.st_mode))
        die(2, "--out: folder '%s' does not exist", dir);
    free(d);
    if (lstat(path, &st) == 0 && S_ISLNK(st.st_mode))
        die(2, "--out: '%s' is a symbolic link: give the file itself", path);
    if (not_regular(path))
        die(2, "--out: '%s' exists and is not a regular file", path);
}

/* the picture of the figure p (p->vmax and p->outline from its maps) into OUT */
static void draw(swe_plot_panels *p, const char *out)
{
    file_check(out);
    for (int i = 0; i < p->n; i++)
        if (records(p->maps[i]) <= 1)
            die(1, "map '%s' missing or empty", p->maps[i]);
    char err[1024];
    if (swe_plot_map_max(p->maps, p->n, &p->vmax, err, sizeof err))
        swe_cli_die(1, "cannot read %s", err);
    swe_cli_outline(p->maps[0], p->outline);
    const char *tmp = out_begin(out);
    char *script = NULL;
    size_t len = 0;
    FILE *s = open_memstream(&script, &len);
    if (!s)
        die(1, "out of memory");
    run_script(s, &script, &len, swe_plot_script(s, p, tmp, err, sizeof err), err);
    out_publish(tmp, out);
}

static int panels(int argc, char **argv, int first)
{
    const char *out = NULL, *title = "";
    const char **maps = calloc((size_t)argc, sizeof *maps),
               **titles = calloc((size_t)argc, sizeof *titles);
    if (!maps || !titles)
        die(1, "out of memory");
    int n = 0;
    for (int i = first; i < argc; i++) {
        const char *a = argv[i];
        if (!strcmp(a, "-h") || !strcmp(a, "--help")) {
            printf(panels_help, prog, prog);
            exit(0);
        } else if (!strcmp(a, "--out")) {
            out = value(argc, argv, i++, "a file");
        } else if (!strcmp(a, "--title")) {
            title = value(argc, argv, i++, "a text");
        } else if (!strncmp(a, "--", 2)) {
            die(2, "unknown option '%s' (see --help)", a);
        } else {
            if (i + 1 >= argc)
                die(2, "map '%s' has no title", a);
            maps[n] = a, titles[n++] = argv[++i];
        }
    }
    if (!out || n < 1)
        die(2, "--out and at least one CSV TITLE pair are required");
    swe_plot_panels p = {title, n, maps, titles, 0, {0}};
    draw(&p, out);
    free(maps);
    free(titles);
    return 0;
}

/* ---- compare ---------------------------------------------------------------------------- */
static const char *const gates[4] = {"off", "tangential", "shear", "regime"};
static const char *const names[4] = {"gates off (normal criterion)", "+ tangential gate",
                                     "+ tangential + shear gate",
                                     "+ regime gate d_{crit}(v_n, v_t)"};

/* awk's test r > 0 && r <= 1 of the text r: numerically when it is a number,
   else as strings */
static int rel_ok(const char *r)
{
    char *end;
    const double v = strtod(r, &end);
    while (*end == ' ' || *end == '\t' || *end == '\n')
        end++;
    if (end != r && !*end)
        return v > 0 && v <= 1;
    return strcmp(r, "0") > 0 && strcmp(r, "1") <= 0;
}

/* a file's text (NULL when unreadable; the caller frees) */
static char *slurp(const char *path)
{
    FILE *f = fopen(path, "r");
    if (!f)
        return NULL;
    char *t = NULL;
    size_t len = 0;
    FILE *m = open_memstream(&t, &len);
    int c;
    while (m && (c = getc(f)) != EOF)
        putc(c, m);
    fclose(f);
    if (!m || fclose(m)) {
        free(t);
        return NULL;
    }
    return t;
}

/* the third fields of the "rear" rows of deposit_per_patch.csv, one a line ("?"
   when none) */
static void rear_total(const char *path, char *out, size_t len)
{
    char *t = slurp(path), *save = NULL;
    out[0] = '\0';
    size_t k = 0;
    for (char *l = t ? strtok_r(t, "\n", &save) : NULL; l; l = strtok_r(NULL, "\n", &save)) {
        if (strncmp(l, "rear,", 5) && strcmp(l, "rear"))
            continue;
        const char *f = strchr(l, ',') ? strchr(strchr(l, ',') + 1, ',') : NULL;
        const size_t fl = f ? strcspn(f + 1, ",") : 0;
        k += (size_t)snprintf(out + k, k < len ? len - k : 0, "%s%.*s", k ? "\n" : "", (int)fl,
                              f ? f + 1 : "");
    }
    free(t);
    while (k && k < len && out[k - 1] == '\n')
        out[--k] = '\0';
    if (!out[0])
        snprintf(out, len, "?");
}

/* the parcel mass of mass_balance.txt when no parcel was split (else "") */
static void parcel_mass(const char *path, char *out, size_t len)
{
    char *t = slurp(path), *save = NULL, m[256] = "", s[256] = "";
    for (char *l = t ? strtok_r(t, "\n", &save) : NULL; l; l = strtok_r(NULL, "\n", &save)) {
        char f1[256], f3[256] = "";
        if (sscanf(l, "%255s %*s %255s", f1, f3) >= 1 &&
            (!strcmp(f1, "parcel_mass") || !strcmp(f1, "split")))
            snprintf(f1[0] == 'p' ? m : s, sizeof m, "%s", f3);
    }
    free(t);
    snprintf(out, len, "%s", strcmp(s, "no") ? "" : m);
}

/* a child writing into the open file f: snowwedge gates (exe NULL) or snowphoto
   regions; its exit status */
static int child(FILE *f, const char *exe, char **args)
{
    fflush(NULL);
    const pid_t pid = fork();
    if (pid < 0)
        return -1;
    if (pid == 0) {
        if (dup2(fileno(f), 1) < 0)
            _exit(1);
        if (!exe) {
            const int rc = swe_cmd_post(4, args);
            fflush(stdout);
            _exit(rc);
        }
        execv(exe, args);
        fprintf(stderr, "%s: %s: %s\n", prog, exe, strerror(errno));
        _exit(127);
    }
    swo_signal_child(pid);
    int st;
    while (waitpid(pid, &st, 0) < 0 && errno == EINTR)
        ;
    swo_signal_child(0);
    return WIFEXITED(st) ? WEXITSTATUS(st) : -1;
}

/* an output of the comparison, RES/NAME, as a stream on its temporary *tmp */
static FILE *table(const char *res, const char *name, char *path, size_t len, const char **tmp)
{
    char err[1024];
    snprintf(path, len, "%s/%s", res, name);
    *tmp = out_begin(path);
    FILE *f = swo_open(live, path, err, sizeof err);
    if (!f)
        die(swo_code(live), "%s", err);
    return f;
}

static int compare(int argc, char **argv, int first)
{
    char here[4096] = "";
    const ssize_t hl = readlink("/proc/self/exe", here, sizeof here - 16);
    if (hl > 0) /* default: the snowphoto beside this snowwedge */
        snprintf(strrchr(here, '/') ? strrchr(here, '/') + 1 : here, 16, "snowphoto");
    const char *res = NULL, *exe = hl > 0 ? here : "snowphoto", *rel = "0.1";
    for (int i = first; i < argc; i++) {
        const char *a = argv[i];
        if (!strcmp(a, "-h") || !strcmp(a, "--help")) {
            printf(compare_help, prog, prog);
            exit(0);
        } else if (!strcmp(a, "--results")) {
            res = value(argc, argv, i++, "a folder");
        } else if (!strcmp(a, "--snowphoto")) {
            exe = value(argc, argv, i++, "a program");
        } else if (!strcmp(a, "--rel")) {
            rel = value(argc, argv, i++, "a number");
        } else {
            die(2, "unknown option '%s' (see --help)", a);
        }
    }
    if (!res)
        die(2, "--results is required");
    if (!rel_ok(rel))
        die(2, "--rel '%s' outside (0, 1]", rel);
    if (access(exe, X_OK))
        die(1, "%s not found (run ./Allwmake)", exe);
    char path[4][2][4096];
    struct stat st;
    for (int g = 0; g < 4; g++)
        for (int k = 0; k < 2; k++) {
            snprintf(path[g][k], sizeof path[g][k], "%s/%s/%s", res, gates[g],
                     k ? "deposit_per_patch.csv" : "rear_deposit.csv");
            if (stat(path[g][k], &st) || !S_ISREG(st.st_mode))
                die(1, "missing %s (run Allrun -compare)", path[g][k]);
        }
    /* one colour scale and one threshold for all four */
    char *end;
    errno = 0;
    const double r = strtod(rel, &end);
    if (end == rel || *end || errno || !isfinite(r)) {
        fprintf(stderr, "snowwedge: --rel: '%s' is not a number\n", rel);
        return 1;
    }
    const char *maps[4] = {path[0][0], path[1][0], path[2][0], path[3][0]}, *titles[4];
    char err[1024], vmax[64], thr[64], tt[4][8192], out[4096];
    double m;
    if (swe_plot_map_max(maps, 4, &m, err, sizeof err))
        swe_cli_die(1, "cannot read %s", err);
    snprintf(vmax, sizeof vmax, "%.6g", m);
    snprintf(thr, sizeof thr, "%.6g", r * swe_post_round(m, 6));
    for (int g = 0; g < 4; g++) {
        char total[4096];
        rear_total(path[g][1], total, sizeof total);
        snprintf(tt[g], sizeof tt[g], "%s\\nrear face total %s kg", names[g], total);
        titles[g] = tt[g];
    }
    swe_plot_panels p = {"Rear face seen from behind: snow deposit after 30 min [kg/m^2] (one "
                         "colour scale)", 4, maps, titles, 0, {0}};
    snprintf(out, sizeof out, "%s/gates_compare.png", res);
    const char *me = prog;
    prog = "wedge-panels"; /* the picture's messages as the panels' own */
    draw(&p, out);
    prog = me;
    printf("%s: %s\n", prog, out);

    char *args[16] = {"snowwedge", "gates", "--results", (char *)res, NULL};
    const char *tmp;
    FILE *f = table(res, "gates_per_patch.md", out, sizeof out, &tmp);
    if (child(f, NULL, args)) {
        swo_free(live);
        return 1;
    }
    out_publish(tmp, out);
    show(out);

    f = table(res, "regions.md", out, sizeof out, &tmp);
    fputs("| gate setting | left side | right side | centre | edges | threshold [kg/m2] |\n"
          "|---|---|---|---|---|---:|\n", f);
    for (int g = 0; g < 4; g++) {
        /* parcel counts only where every parcel carries the same mass (no splitting) */
        char mb[4096], pm[256];
        snprintf(mb, sizeof mb, "%s/%s/mass_balance.txt", res, gates[g]);
        parcel_mass(mb, pm, sizeof pm);
        char *a[16] = {(char *)exe, "regions", "--sim", path[g][0], "--sim-threshold", thr,
                       "--label", (char *)gates[g], pm[0] ? "--parcel-mass" : NULL, pm, NULL};
        child(f, exe, a); /* a failed region row is left out, as it always was */
    }
    fprintf(f, "\nEach cell: whether the region holds snow (>= 30 %% of its faces at or above the\n"
               "threshold), that fraction, the region's mean deposit and the parcels deposited\n"
               "there with their Poisson error. Threshold = %s x the\n"
               "largest rear-face deposit of the four settings (%s kg/m2). Regions in face\n"
               "coordinates seen from behind (snowphoto --help): edges = border band 0.1 wide;\n"
               "left/right side = u < 0.35 / u > 0.65 inside it; centre = 0.35..0.65 x 0.3..0.7.\n",
            rel, vmax);
    out_publish(tmp, out);
    show(out);
    return 0;
}

/* ---- blocks ----------------------------------------------------------------------------- */
static const char *blocks_help =
    "%s - the composed rear face on blocks as coarse as its sampling error needs.\n"
    "\n"
    "Usage: %s --weights FILE [--target E] [--finest N] --csv OUT.csv\n"
    "       [--out PNG --title TEXT] CLASS_DIR...\n"
    "\n"
    "  --weights FILE  the classes' weights (snowwedge weights: \"D w e0 e1\" per class)\n"
    "  --target E      the deposit-weighted rms relative error the grid may have, a fraction\n"
    "                  in (0, 1] (default 0.3)\n"
    "  --finest N      the finest grid tried, N x N blocks, 1 .. 256 (default 24)\n"
    "  --csv OUT.csv   per block y0,y1,z0,z1,deposit_kg_m2,rel_error,records after a '#' line\n"
    "  --out PNG       the picture (gnuplot): the deposit per block, blocks whose error exceeds\n"
    "                  2 E or without a parcel grey; each block's relative error\n"
    "  --title TEXT    the picture's title (a literal \"\\n\" starts a new line)\n"
    "  CLASS_DIR       a class's results, .../d<D>um: rear_records.csv (snowwedge rear-records),\n"
    "                  deposit_per_patch.csv (its rear deposit [kg]), rear_deposit.csv (the\n"
    "                  face's outline, the first class's)\n"
    "The grid is the finest n in 1 .. N whose blocks' deposit-weighted rms relative error is\n"
    "at most E (1 when none is); a block's error comes from the parcels' independent origins\n"
    "(tools/snowwedge/swe_blocks.h). Prints one line: the grid, its error, the blocks' range.\n"
    "Exit status 0 on success, 2 on bad usage or input, 1 when a file is unreadable or gnuplot\n"
    "fails; nothing is written then.\n";

/* a class's rear deposit [kg]: deposit_per_patch.csv's row "rear", third column */
static double rear_deposit_kg(const char *dir)
{
    char path[4096];
    snprintf(path, sizeof path, "%s/deposit_per_patch.csv", dir);
    FILE *f = swe_cli_open(path);
    char line[4096];
    double v = NAN;
    while (fgets(line, sizeof line, f))
        if (!strncmp(line, "rear,", 5)) {
            char *c = strchr(line + 5, ',');
            if (c) {
                char *e;
                v = strtod(c + 1, &e);
                if (e == c + 1 || (*e != ',' && *e != '\n' && *e))
                    v = NAN;
            }
            break;
        }
    fclose(f);
    if (!(v >= 0 && isfinite(v)))
        die(2, "%s: no rear row with a deposit_kg >= 0", path);
    return v;
}

/* a class's records (rear_records.csv) */
static swe_record *read_class_records(const char *dir, size_t *count, double *mass)
{
    char path[4096];
    snprintf(path, sizeof path, "%s/rear_records.csv", dir);
    FILE *f = swe_cli_open(path);
    size_t cap = 256, n = 0;
    swe_record *r = malloc(cap * sizeof *r);
    if (!r)
        die(1, "out of memory");
    char line[1024];
    *mass = 0;
    int header = 0;
    for (int ln = 1; fgets(line, sizeof line, f); ln++) {
        if (line[0] == '#' || line[0] == '\n')
            continue;
        if (!header) {
            if (strncmp(line, "y,z,mass_kg,origProc,origId", 27))
                die(2, "%s line %d: not the header y,z,mass_kg,origProc,origId", path, ln);
            header = 1;
            continue;
        }
        double y, z, m, p, id;
        int used = 0;
        if (sscanf(line, "%lf,%lf,%lf,%lf,%lf%n", &y, &z, &m, &p, &id, &used) != 5 ||
            (line[used] && line[used] != '\n') || !isfinite(y) || !isfinite(z) || !isfinite(m) ||
            !(m >= 0) || !isfinite(p) || !isfinite(id) || p != floor(p) || id != floor(id))
            die(2, "%s line %d: not y,z,mass_kg,origProc,origId (finite numbers, mass >= 0, "
                   "whole origins)", path, ln);
        if (n == cap) {
            cap *= 2;
            swe_record *g = realloc(r, cap * sizeof *r);
            if (!g)
                die(1, "out of memory");
            r = g;
        }
        r[n++] = (swe_record){y, z, m, (long)p, (long)id};
        *mass += m;
    }
    fclose(f);
    if (!header)
        die(2, "%s: no header y,z,mass_kg,origProc,origId", path);
    *count = n;
    return r;
}

/* the class's diameter from its folder's name d<D>um (NULL when it is none) */
static const char *class_of(const char *dir, char d[32])
{
    size_t len = strlen(dir);
    while (len > 1 && dir[len - 1] == '/')
        len--;
    size_t b = len;
    while (b > 0 && dir[b - 1] != '/')
        b--;
    const size_t k = len - b;
    if (k < 4 || k > 30 || dir[b] != 'd' || strncmp(dir + len - 2, "um", 2))
        return NULL;
    for (size_t i = b + 1; i < len - 2; i++)
        if (dir[i] < '0' || dir[i] > '9')
            return NULL;
    snprintf(d, 32, "%.*s", (int)(k - 3), dir + b + 1);
    return d;
}

/* blocks' command line */
typedef struct {
    const char *weights, *csv, *png, *title;
    double target;
    int finest;
    const char **dirs; /* the CLASS_DIRs, nd of them */
    int nd;
} blocks_opts;

/* blocks' options read and checked (exits on --help and on bad usage) */
static void blocks_parse(int argc, char **argv, int first, blocks_opts *o)
{
    o->dirs = calloc((size_t)argc, sizeof *o->dirs);
    if (!o->dirs)
        die(1, "out of memory");
    for (int i = first; i < argc; i++) {
        const char *a = argv[i];
        if (!strcmp(a, "-h") || !strcmp(a, "--help")) {
            printf(blocks_help, prog, prog);
            exit(0);
        } else if (!strcmp(a, "--weights")) {
            o->weights = value(argc, argv, i++, "a file");
        } else if (!strcmp(a, "--csv")) {
            o->csv = value(argc, argv, i++, "a file");
        } else if (!strcmp(a, "--out")) {
            o->png = value(argc, argv, i++, "a file");
        } else if (!strcmp(a, "--title")) {
            o->title = value(argc, argv, i++, "a text");
        } else if (!strcmp(a, "--target")) {
            const char *v = value(argc, argv, i++, "a fraction");
            o->target = swe_cli_number("--target", v);
            if (!(o->target > 0 && o->target <= 1))
                die(2, "--target: '%s' is not in (0, 1]", v);
        } else if (!strcmp(a, "--finest")) {
            const char *v = value(argc, argv, i++, "a number of blocks");
            const double f = swe_cli_number("--finest", v);
            if (!(f >= 1 && f <= 256 && f == floor(f)))
                die(2, "--finest: '%s' is not a whole number 1 .. 256", v);
            o->finest = (int)f;
        } else if (!strncmp(a, "--", 2)) {
            die(2, "unknown option '%s' (see --help)", a);
        } else {
            o->dirs[o->nd++] = a;
        }
    }
    if (!o->weights || !o->csv || o->nd < 1)
        die(2, "--weights, --csv and at least one CLASS_DIR are required (see --help)");
    if (o->png && !o->title)
        die(2, "--out needs --title (see --help)");
    file_check(o->csv);
    if (o->png)
        file_check(o->png);
    if (o->png && !strcmp(o->png, o->csv))
        die(2, "--out and --csv are the same file '%s'", o->csv);
}

/* every class's rear records, each weighted by its class's weight x rear deposit / the records'
 * mass; the composed face's deposit [kg] in *face_kg (exits on bad input) */
static swe_block_class *blocks_classes(const blocks_opts *o, double *face_kg)
{
    enum { MAXC = 256 };
    static char wd[MAXC][32];
    static double ww[MAXC], we0[MAXC], we1[MAXC];
    const int nw = swe_cli_read_weights(o->weights, wd, ww, we0, we1, MAXC);
    swe_block_class *cl = calloc((size_t)o->nd, sizeof *cl);
    if (!cl)
        die(1, "out of memory");
    double face = 0;
    for (int k = 0; k < o->nd; k++) {
        char d[32];
        if (!class_of(o->dirs[k], d))
            die(2, "'%s' is no class folder .../d<D>um", o->dirs[k]);
        double w = NAN;
        for (int i = 0; i < nw; i++)
            if (!strcmp(wd[i], d))
                w = ww[i];
        if (isnan(w))
            die(2, "'%s': class %s um has no weight in %s", o->dirs[k], d, o->weights);
        double mass;
        size_t n;
        swe_record *r = read_class_records(o->dirs[k], &n, &mass);
        const double dep = rear_deposit_kg(o->dirs[k]);
        if (dep > 0 && !(mass > 0))
            die(2, "%s: a rear deposit of %g kg but no record of it in rear_records.csv", o->dirs[k],
                dep);
        cl[k] = (swe_block_class){r, n, mass > 0 ? w * dep / mass : 0};
        face += w * dep;
    }
    *face_kg = face;
    return cl;
}

/* the blocks' table into tcsv, the output set's temporary of --csv: the '#' line with the grid
 * and its error, a row per block (exits on a write error) */
static void blocks_write_csv(const blocks_opts *o, const char *tcsv, const swe_block *b, int nb, double rms,
                             double face)
{
    const char *csv = o->csv;
    const int finest = o->finest;
    const double target = o->target;
    FILE *f = fopen(tcsv, "w");
    if (!f)
        die(1, "cannot write '%s': %s", csv, strerror(errno));
    if (rms <= target)
        fprintf(f, "# the composed rear deposit on %d x %d blocks: the finest grid of 1 .. %d whose "
                   "deposit-weighted rms relative error is at most %.3g (it is %.3g); the face %.6g kg\n",
                nb, nb, finest, target, rms, face);
    else
        fprintf(f, "# the composed rear deposit on %d x %d blocks: no grid of 1 .. %d holds a "
                   "deposit-weighted rms relative error of at most %.3g (the whole face's is %.3g); "
                   "the face %.6g kg\n",
                nb, nb, finest, target, rms, face);
    fprintf(f, "y0,y1,z0,z1,deposit_kg_m2,rel_error,records\n");
    for (int i = 0; i < nb * nb; i++)
        fprintf(f, "%.6g,%.6g,%.6g,%.6g,%.6g,%.4g,%ld\n", b[i].y0, b[i].y1, b[i].z0, b[i].z1,
                b[i].deposit, b[i].rel, b[i].records);
    if (fclose(f))
        die(1, "cannot write '%s': %s", csv, strerror(errno));
    if (chmod(tcsv, 0644))
        die(1, "cannot write '%s': %s", csv, strerror(errno));
}

/* the picture of the blocks (--out) from the table tcsv, added to the output set (exits when
 * gnuplot or a write fails) */
static void blocks_picture(const blocks_opts *o, const char *tcsv, int nb, double rms, double vmax,
                           const double ol[4])
{
    const char *png = o->png;
    char err[1024];
    const char *tpng = swo_add(live, png, err, sizeof err);
    if (!tpng)
        die(swo_code(live), "%s", err);
    const swe_plot_blocks p = {o->title, tcsv, nb, o->target, rms, vmax, {ol[0], ol[1], ol[2], ol[3]}};
    char *script = NULL;
    size_t len = 0;
    FILE *s = open_memstream(&script, &len);
    if (!s)
        die(1, "out of memory");
    run_script(s, &script, &len, swe_plot_blocks_script(s, &p, tpng, err, sizeof err), err);
    if (chmod(tpng, 0644))
        die(1, "cannot write '%s': %s", png, strerror(errno));
}

static int blocks(int argc, char **argv, int first)
{
    blocks_opts o = {NULL, NULL, NULL, NULL, 0.3, 24, NULL, 0};
    blocks_parse(argc, argv, first, &o);
    const double target = o.target;
    const int finest = o.finest, nd = o.nd;
    double face;
    swe_block_class *cl = blocks_classes(&o, &face);
    char path[4096], err[1024];
    snprintf(path, sizeof path, "%s/rear_deposit.csv", o.dirs[0]);
    double ol[4];
    swe_cli_outline(path, ol);
    int nb;
    double rms;
    if (swe_blocks_grid(cl, (size_t)nd, ol, finest, target, &nb, &rms, err, sizeof err))
        die(2, "%s", err);
    swe_block *b = malloc((size_t)nb * nb * sizeof *b);
    if (!b)
        die(1, "out of memory");
    if (swe_blocks(cl, (size_t)nd, ol, nb, b, err, sizeof err))
        die(2, "%s", err);
    double lo = INFINITY, hi = 0, vmax = 0;
    int grey = 0;
    for (int i = 0; i < nb * nb; i++) {
        if (b[i].records == 0 || b[i].rel > 2 * target) {
            grey++;
            continue;
        }
        lo = b[i].rel < lo ? b[i].rel : lo;
        hi = b[i].rel > hi ? b[i].rel : hi;
        vmax = b[i].deposit > vmax ? b[i].deposit : vmax;
    }
    /* the files: one set, written whole or not at all */
    const swo_spec spec = {prog, "--csv", NULL, 0, 0};
    if (swo_alloc(&spec, &live, err, sizeof err) != SWO_OK)
        die(2, "%s", err);
    const char *tcsv = swo_add(live, o.csv, err, sizeof err);
    if (!tcsv)
        die(swo_code(live), "%s", err);
    blocks_write_csv(&o, tcsv, b, nb, rms, face);
    if (o.png)
        blocks_picture(&o, tcsv, nb, rms, vmax, ol);
    if (swo_commit(live, err, sizeof err) != SWO_OK)
        die(swo_code(live), "%s", err);
    swo_free(live);
    live = NULL;
    if (rms <= target)
        printf("blocks: %d x %d of %.3g x %.3g m, the finest of 1 .. %d whose deposit-weighted rms "
               "error is <= %.0f %%: %.0f %%; ",
               nb, nb, (ol[1] - ol[0]) / nb, (ol[3] - ol[2]) / nb, finest, 100 * target, 100 * rms);
    else
        printf("blocks: %d x %d of %.3g x %.3g m: no grid holds an error <= %.0f %%, the whole "
               "face's is %.0f %%; ",
               nb, nb, (ol[1] - ol[0]) / nb, (ol[3] - ol[2]) / nb, 100 * target, 100 * rms);
    if (grey < nb * nb)
        printf("block errors %.0f .. %.0f %%", 100 * lo, 100 * hi);
    printf("%s%d block(s) grey (error > %.0f %% or no parcel); face %.4g kg\n",
           grey < nb * nb ? "; " : "", grey, 200 * target, face);
    for (int k = 0; k < nd; k++)
        free((void *)cl[k].rec);
    free(cl);
    free(b);
    free(o.dirs);
    return 0;
}

int swe_cmd_plot(int argc, char **argv)
{
    const int is_panels = !strcmp(argv[1], "panels"), is_blocks = !strcmp(argv[1], "blocks");
    if (!is_panels && !is_blocks && strcmp(argv[1], "compare"))
        return -1;
    prog = is_panels ? "snowwedge panels" : is_blocks ? "snowwedge blocks" : "snowwedge compare";
    int first = 2;
    if (argc > 3 && !strcmp(argv[2], "--name") && argv[3][0])
        prog = argv[3], first = 4;
    swo_signals_on(); /* interrupted, no temporary is left behind */
    if (is_blocks)
        return blocks(argc, argv, first);
    return is_panels ? panels(argc, argv, first) : compare(argc, argv, first);
}
