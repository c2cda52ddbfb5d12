/* swe_cmd_wrap.c - the options of the scripts tutorials/wedge/post/wedge-*, parsed
 * and checked here with the scripts' own messages (prefix: the script's name; exit
 * 2 usage, 1 a missing input) and their --help. "snowwedge wedge-capture ARGS"
 * (wedge-cost, -dispersion, -fill, -resolution) then runs the one command the
 * script wraps; "snowwedge wedge-post ARGS" (wedge-compose, -ladder, -variant,
 * -errortime) prints the values as shell assignments for the script to eval (or,
 * for --help, the commands that print the help and exit 0). */
#include "swe_cli.h"
#include "swe_opts.h"

#include <ctype.h>
#include <glob.h>
#include <locale.h>
#include <sys/stat.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <fcntl.h>
#include <unistd.h>

enum { WRAP_MAX = 12, WRAP_ARGS = 256 };

/* one option: its name, the shell variable it sets, what a missing value
   "needs" (NULL: "a value"), its default; var NULL: a flag (sets "1") */
typedef struct {
    const char *opt, *var, *needs, *def;
} wrap_opt;

typedef struct {
    const char *script, *help;
    wrap_opt opt[WRAP_MAX];
    int pairs; /* positional CSV LABEL pairs (wedge-errortime) */
} wrap_spec;

/* the parsed values: one per option, the repeated --run, the positional words */
typedef struct {
    const wrap_spec *s;
    const char *val[WRAP_MAX];
    const char *list[WRAP_ARGS];
    int nlist;
} wrap_vals;

static const char *script = "snowwedge";

static void die(int code, const char *fmt, ...) __attribute__((noreturn, format(printf, 2, 3)));
static void die(int code, const char *fmt, ...)
{
    va_list ap;
    fprintf(stderr, "%s: ", script);
    va_start(ap, fmt);
    vfprintf(stderr, fmt, ap);
    va_end(ap);
    fputc('\n', stderr);
    exit(code);
}

static const char *get(const wrap_vals *v, const char *opt)
{
    for (int k = 0; k < WRAP_MAX && v->s->opt[k].opt; k++)
        if (!strcmp(v->s->opt[k].opt, opt))
            return v->val[k];
    return NULL;
}

static int given(const wrap_vals *v, const char *opt)
{
    const char *s = get(v, opt);
    return s && *s;
}

static void parse(const wrap_spec *s, int argc, char **argv, wrap_vals *v, int eval)
{
    v->s = s;
    for (int k = 0; k < WRAP_MAX && s->opt[k].opt; k++)
        v->val[k] = s->opt[k].def ? s->opt[k].def : "";
    for (int i = 2; i < argc; i++) {
        const char *a = argv[i];
        if (!strcmp(a, "-h") || !strcmp(a, "--help")) {
            printf(eval ? "cat <<'SWE_HELP'\n%sSWE_HELP\nexit 0\n" : "%s", s->help);
            exit(0);
        }
        int k = 0;
        while (k < WRAP_MAX && s->opt[k].opt && strcmp(s->opt[k].opt, a))
            k++;
        if (k < WRAP_MAX && s->opt[k].opt && !s->opt[k].var) {
            v->val[k] = "1";
            continue;
        }
        if (k == WRAP_MAX || !s->opt[k].opt) {
            if (s->pairs && strncmp(a, "--", 2)) {
                if (i + 1 >= argc)
                    die(2, "'%s' has no label (see --help)", a);
                if (v->nlist + 2 > WRAP_ARGS)
                    die(2, "more than %d CSV LABEL words", WRAP_ARGS);
                v->list[v->nlist++] = a;
                v->list[v->nlist++] = argv[++i];
                continue;
            }
            die(2, "unknown option '%s' (see --help)", a);
        }
        if (i + 1 >= argc || !argv[i + 1][0])
            die(2, "%s needs %s (see --help)", a, s->opt[k].needs ? s->opt[k].needs : "a value");
        v->val[k] = argv[++i];
        if (!strcmp(a, "--run")) {
            if (v->nlist >= WRAP_ARGS)
                die(2, "more than %d --run", WRAP_ARGS);
            v->list[v->nlist++] = v->val[k];
        }
    }
}

/* a whole decimal number as the scripts' patterns: digits with one optional point
   (at least one digit), an optional exponent; sign: "" none, "+" an optional + */
static int decimal(const char *s, const char *sign)
{
    if (*sign && *s == *sign)
        s++;
    int digits = 0, point = 0;
    for (; isdigit((unsigned char)*s) || (*s == '.' && !point); s++)
        *s == '.' ? (void)(point = 1) : (void)digits++;
    if (!digits)
        return 0;
    if (*s == 'e' || *s == 'E') {
        s++;
        if (*s == '+' || *s == '-')
            s++;
        if (!isdigit((unsigned char)*s))
            return 0;
        while (isdigit((unsigned char)*s))
            s++;
    }
    return !*s;
}

/* a time as wedge-fill's pattern: [0-9]*.?[0-9]+ (a point needs a digit after it) */
static int fill_time(const char *s)
{
    const char *p = strchr(s, '.');
    if (p && !isdigit((unsigned char)p[1]))
        return 0;
    return decimal(s, "");
}

/* a number in (lo, hi] (or (lo, hi) when open) */
static int in_range(const char *s, double lo, double hi, int open)
{
    const double x = strtod(s, NULL);
    return (decimal(s, "+") || (*s == '-' && decimal(s + 1, ""))) && x > lo && (open ? x < hi : x <= hi);
}

/* "A,B,..." split at commas into at most n fields; the count (n + 1: more) */
static int fields(const char *s, char f[][64], int n)
{
    int k = 0;
    for (const char *p = s;; k++) {
        const size_t len = strcspn(p, ",");
        if (k < n)
            snprintf(f[k], 64, "%.*s", (int)(len < 63 ? len : 63), p);
        if (!p[len])
            return k + 1;
        p += len + 1;
    }
}

/* WORD split as the shell's  IFS=, read -r F1 .. Fn-1 REST  does: the first n - 1
   fields into f, and whether REST is empty (the rest after the (n-1)-th comma is
   nothing or one comma) */
static int shell_read(const char *s, char f[][64], int n)
{
    const char *p = s;
    for (int k = 0; k < n - 1; k++) {
        const size_t len = strcspn(p, ",");
        snprintf(f[k], 64, "%.*s", (int)(len < 63 ? len : 63), p);
        p += len;
        if (*p)
            p++;
    }
    return !*p || !strcmp(p, ",");
}

/* a regular file that can be read */
static int readable_file(const char *path)
{
    struct stat st;
    return !stat(path, &st) && S_ISREG(st.st_mode) && !access(path, R_OK);
}

/* a comma-separated list of numbers (--mvd): no empty item, no number twice; put in
   ascending order (a note when it was not), into out */
static void num_list(const char *opt, const char *text, char *out, size_t n)
{
    char item[64][64];
    double x[64];
    const int k = fields(text, item, 64);
    if (k > 64)
        die(2, "%s: more than 64 items in '%s'", opt, text);
    for (int i = 0; i < k; i++) {
        if (!*item[i])
            die(2, "%s: an empty item in '%s'", opt, text);
        if (!decimal(item[i], "+") && !(item[i][0] == '-' && decimal(item[i] + 1, "")))
            die(2, "%s: '%s' in '%s' is not a number", opt, item[i], text);
        x[i] = strtod(item[i], NULL);
        for (int j = 0; j < i; j++)
            if (x[j] == x[i])
                die(2, "%s: '%s' is given twice in '%s'", opt, item[i], text);
    }
    int sorted = 1;
    for (int i = 1; i < k; i++) {
        if (x[i] >= x[i - 1])
            continue;
        sorted = 0;
        char t[64];
        double y = x[i];
        snprintf(t, sizeof t, "%s", item[i]);
        int j = i - 1;
        for (; j >= 0 && x[j] > y; j--) {
            x[j + 1] = x[j];
            memcpy(item[j + 1], item[j], sizeof item[0]);
        }
        x[j + 1] = y;
        memcpy(item[j + 1], t, sizeof t);
    }
    if (!sorted)
        fprintf(stderr, "%s: note: %s: '%s' taken in ascending order\n", script, opt, text);
    size_t len = 0;
    out[0] = 0;
    for (int i = 0; i < k && len < n; i++)
        len += (size_t)snprintf(out + len, n - len, "%s%s", i ? "," : "", item[i]);
}

/* one shell assignment NAME='VALUE' */
static void assign(const char *name, const char *value)
{
    printf("%s=", name);
    swe_opts_quote(stdout, value); /* single-quoted: no value runs as code */
    putchar('\n');
}

static void assign_all(const wrap_vals *v)
{
    for (int k = 0; k < WRAP_MAX && v->s->opt[k].opt; k++)
        assign(v->s->opt[k].var ? v->s->opt[k].var : "force", v->val[k][0] ? v->val[k] : "");
}

static void assign_list(const char *name, const wrap_vals *v)
{
    printf("%s=(", name);
    for (int i = 0; i < v->nlist; i++) {
        if (i)
            putchar(' ');
        swe_opts_quote(stdout, v->list[i]);
    }
    fputs(")\n", stdout);
}

/* ---- the scripts that wrap one command ---------------------------------------------- */

static const wrap_spec capture_spec = {
    "wedge-capture",
    "wedge-capture - wall impacts by particle diameter (after Allrun -sizes LIST): a markdown\n"
    "table of DIR/d<N>um/ (wedge-post's results per diameter) on standard output\n"
    "(doc/reference/wedge-post.md).\n"
    "\n"
    "Usage: post/wedge-capture --results DIR [--gate NAME] [--dispersion NAME] [--sampled F]\n"
    "\n"
    "  --results DIR      the folder of the d<N>um results\n"
    "  --gate NAME        the gate setting, for the title (default off)\n"
    "  --dispersion NAME  the dispersion treatment, for the title\n"
    "  --sampled F        the share of the injection in the sampling window (0, 1], default 1\n"
    "Exit status 0 on success, 2 on bad usage, 1 when a result is missing.\n",
    {{"--results", "res", "a folder", NULL},
     {"--gate", "gate", "a name", "off"},
     {"--dispersion", "disp", "a name", NULL},
     {"--sampled", "sampled", "a number", "1"}},
    0};

static int run_capture(const wrap_vals *v)
{
    if (!given(v, "--results"))
        die(2, "--results is required");
    const char *f = get(v, "--sampled");
    if (!in_range(f, 0, 1, 0))
        die(2, "--sampled '%s' outside (0, 1]", f);
    char *a[] = {"snowwedge", "capture", "--name", "wedge-capture", "--results",
                 (char *)get(v, "--results"), "--gate", (char *)get(v, "--gate"),
                 "--sampled", (char *)f, "--dispersion", (char *)get(v, "--dispersion"), NULL};
    return swe_cmd_post(given(v, "--dispersion") ? 12 : 10, a);
}

static const wrap_spec cost_spec = {
    "wedge-cost",
    "wedge-cost - the statistical error of the decided spray's rear-face deposit against the\n"
    "run time that bought it, per sampling design: CSV design,wall_s,face,left,right,centre,edges\n"
    "(errors in %; doc/reference/wedge-post.md).\n"
    "\n"
    "Usage: post/wedge-cost --results DIR --log SOLVERLOG --gate G --mvd UM\n"
    "\n"
    "  --results DIR   the run's results (DIR/G/rear_statistics.md, DIR/compose/mvdUM/)\n"
    "  --log SOLVERLOG the solver log (its 'Wall time [s]' line)\n"
    "  --gate G        the main cloud's gate setting\n"
    "  --mvd UM        the decided spray\n"
    "Exit status: 0 done, 1 a result missing, 2 usage.\n",
    {{"--results", "res", NULL, NULL},
     {"--log", "log", NULL, NULL},
     {"--gate", "gate", NULL, NULL},
     {"--mvd", "mvd", NULL, NULL}},
    0};

static int run_cost(const wrap_vals *v)
{
    const char *res = get(v, "--results"), *log = get(v, "--log"), *gate = get(v, "--gate");
    if (!*res || !*log || !*gate || !given(v, "--mvd"))
        die(2, "--results, --log, --gate and --mvd are required (see --help)");
    char path[4096];
    for (int k = 0; k < 3; k++) {
        snprintf(path, sizeof path, k == 1 ? "%s/%s/rear_statistics.md" : "%s/%s/mass_balance.txt", res, gate);
        if (access(k ? path : log, R_OK))
            die(1, "cannot read %s", k ? path : log);
    }
    FILE *f = fopen(log, "r");
    char line[4096];
    int wall = 0;
    while (f && !wall && fgets(line, sizeof line, f))
        wall = !strncmp(line, "Wall time [s]", 13);
    if (f)
        fclose(f);
    if (!wall)
        die(1, "%s has no 'Wall time [s]' line (an older solver?)", log);
    char *a[] = {"snowwedge", "cost", "--name", "wedge-cost", "--results", (char *)res, "--log", (char *)log,
                 "--gate", (char *)gate, "--mvd", (char *)get(v, "--mvd"), NULL};
    return swe_cmd_post(12, a);
}

static const wrap_spec dispersion_spec = {
    "wedge-dispersion",
    "wedge-dispersion - the dispersion treatments side by side (after Allrun -dispersion LIST):\n"
    "a markdown report on standard output, per treatment and wedge patch the deposit and\n"
    "sticks / impacts and, after Allrun -sizes, the rear share per diameter\n"
    "(doc/reference/wedge-post.md).\n"
    "\n"
    "Usage: post/wedge-dispersion --results DIR --main T --others \"T2 T3 ...\"\n"
    "\n"
    "  --results DIR  the run's results (DIR/<gate>/, DIR/dispersion/<T>/, DIR/capture*.md)\n"
    "  --main T       the main cloud's treatment\n"
    "  --others LIST  the further treatments, blank-separated\n"
    "Exit status 0 on success, 2 on bad usage, 1 when a result is missing.\n",
    {{"--results", "res", "a folder", NULL},
     {"--main", "main", "a treatment", NULL},
     {"--others", "others", "a list", NULL}},
    0};

static int run_dispersion(const wrap_vals *v)
{
    if (!given(v, "--results") || !given(v, "--main"))
        die(2, "--results and --main are required");
    char *a[] = {"snowwedge", "dispersion", "--name", "wedge-dispersion", "--results",
                 (char *)get(v, "--results"), "--main", (char *)get(v, "--main"),
                 "--others", (char *)get(v, "--others"), NULL};
    return swe_cmd_post(given(v, "--others") ? 10 : 8, a);
}

static const wrap_spec fill_spec = {
    "wedge-fill",
    "wedge-fill - how long the wake takes to fill with a cloud's snow, from the ages of its\n"
    "rear-face impact records (postProcessing/lagrangian/NAME/rearImpacts/*/rear.post): one\n"
    "markdown row on standard output (doc/reference/wedge-post.md)\n"
    "  | label | impacts | mass [kg] | a_0.5 [s] | a_F [s] | oldest [s] | fill of the\n"
    "    window | of its first half | of its second half |\n"
    "\n"
    "Usage: post/wedge-fill --case DIR --cloud NAME --soi T --window T0,T1 [--level F] [--label TEXT]\n"
    "\n"
    "  --case DIR      the run's case folder\n"
    "  --cloud NAME    the cloud\n"
    "  --soi T         the spray's start [s]\n"
    "  --window T0,T1  the sampling window (soi <= T0 < T1)\n"
    "  --level F       the share of a_F, in (0, 1) (default 0.95)\n"
    "  --label TEXT    the row's label (default NAME)\n"
    "Exit status: 0 done, 1 no records, 2 usage.\n",
    {{"--case", "case_dir", NULL, NULL},
     {"--cloud", "cloud", NULL, NULL},
     {"--soi", "soi", NULL, NULL},
     {"--window", "window", NULL, NULL},
     {"--level", "level", NULL, "0.95"},
     {"--label", "label", NULL, NULL}},
    0};

static int run_fill(const wrap_vals *v)
{
    const char *dir = get(v, "--case"), *cloud = get(v, "--cloud"), *soi = get(v, "--soi"),
               *win = get(v, "--window"), *level = get(v, "--level");
    if (!*dir)
        die(2, "--case DIR is required (see --help)");
    if (!*cloud)
        die(2, "--cloud NAME is required (see --help)");
    if (!fill_time(soi))
        die(2, "--soi: '%s' is not a time >= 0 (see --help)", soi);
    /* T0,T1 as the shell's read into T0, T1, REST: REST empty (one trailing comma) */
    char t[2][64], w[130];
    const int whole = shell_read(win, t, 3);
    const double s = strtod(soi, NULL), a = strtod(t[0], NULL), b = strtod(t[1], NULL);
    if (!whole || !fill_time(t[0]) || !fill_time(t[1]) || !(b > a && a >= s))
        die(2, "--window: '%s' is not T0,T1 with soi <= T0 < T1 (see --help)", win);
    if (!fill_time(level) || !in_range(level, 0, 1, 1))
        die(2, "--level: '%s' is not in (0, 1) (see --help)", level);
    char pattern[4096];
    snprintf(pattern, sizeof pattern, "%s/postProcessing/lagrangian/%s/rearImpacts/*/rear.post", dir, cloud);
    glob_t g;
    if (glob(pattern, 0, NULL, &g) || !g.gl_pathc)
        die(1, "no rear-face records %s", pattern);
    snprintf(w, sizeof w, "%s,%s", t[0], t[1]);
    char **a2 = calloc(g.gl_pathc + 13, sizeof *a2);
    if (!a2)
        die(1, "out of memory");
    const char *head[] = {"snowwedge", "fill", "--name", "wedge-fill", "--label", given(v, "--label") ? get(v, "--label") : cloud,
                          "--soi", soi, "--window", w, "--level", level};
    int k = 0;
    for (; k < 12; k++)
        a2[k] = (char *)head[k];
    for (size_t i = 0; i < g.gl_pathc; i++)
        a2[k++] = g.gl_pathv[i];
    const int rc = swe_cmd_post(k, a2);
    free(a2);
    globfree(&g);
    return rc;
}

static const wrap_spec resolution_spec = {
    "wedge-resolution",
    "wedge-resolution - the composed rear-face capture of two runs of tutorials/wedge side by\n"
    "side: does the resolution or the sampling limit the answer? Markdown on standard output\n"
    "(doc/reference/wedge-ladder.md).\n"
    "\n"
    "Usage: post/wedge-resolution --base DIR --refined DIR [--mvd LIST]\n"
    "                             [--base-label TEXT] [--refined-label TEXT]\n"
    "\n"
    "  --base DIR             the results folder of a run with size classes (compose/mvd*/)\n"
    "  --refined DIR          that of the other run (typically -refine-wake -halfstep)\n"
    "  --mvd LIST             the composed sprays, comma-separated (default: every one shared)\n"
    "  --base-label TEXT      the base run's name in the tables (default base)\n"
    "  --refined-label TEXT   the refined run's name (default refined)\n"
    "Exit status: 0 done, 1 a result missing or unreadable, 2 usage.\n",
    {{"--base", "base", NULL, NULL},
     {"--refined", "refined", NULL, NULL},
     {"--mvd", "mvds", NULL, NULL},
     {"--base-label", "lb", NULL, "base"},
     {"--refined-label", "lr", NULL, "refined"}},
    0};

static int run_resolution(const wrap_vals *v)
{
    if (!given(v, "--base") || !given(v, "--refined"))
        die(2, "--base and --refined are required (see --help)");
    const char *mvd = get(v, "--mvd");
    char list[1024];
    if (*mvd) {
        if (strspn(mvd, "0123456789.,\t\n ") < strlen(mvd))
            die(2, "--mvd needs diameters in um, comma-separated, got '%s' (see --help)", mvd);
        num_list("--mvd", mvd, list, sizeof list);
    }
    char *a[] = {"snowwedge", "resolution", "--base", (char *)get(v, "--base"), "--refined",
                 (char *)get(v, "--refined"), "--base-label", (char *)get(v, "--base-label"),
                 "--refined-label", (char *)get(v, "--refined-label"), "--mvd", list, NULL};
    return swe_ladder_main(*mvd ? 12 : 10, a);
}

/* ---- the scripts that orchestrate several steps: their options as assignments -------- */

static const wrap_spec post_spec = {
    "wedge-post",
    "wedge-post - post-process one snow cloud of a tutorials/wedge run: the rear-face map\n"
    "(CSV, PNG), the deposit per patch, the mass balance, the rear-face statistics and, with\n"
    "--window, the halves of the sampling window and convergence.md\n"
    "(doc/reference/wedge-post.md lists inputs and outputs).\n"
    "\n"
    "Usage: post/wedge-post --case DIR --out DIR [--force] [--cloud NAME] [--gate NAME]\n"
    "                       [--log FILE] [--window T0,TH,T1] [--snowphoto EXE]\n"
    "\n"
    "  --case DIR         the run's case folder (read only)\n"
    "  --out DIR          the output folder: created, or an empty or earlier SnowWall output folder\n"
    "  --force            write into any other existing --out folder (nothing deleted)\n"
    "  --cloud NAME       the cloud (default kinematicCloud; its field NAME:snowDeposit)\n"
    "  --gate NAME        the gate setting, for titles and tables (default off)\n"
    "  --log FILE         the solver log in DIR (default log.icoUncoupledKinematicParcelFoam)\n"
    "  --window T0,TH,T1  transient: the window [T0, T1] and its halves (else the last write)\n"
    "  --snowphoto EXE    for the region tables (default bin/snowphoto of this repository)\n"
    "Exit status 0 on success, 2 on bad usage, 1 when an input is missing.\n",
    {{"--case", "case_dir", "a folder", NULL},
     {"--out", "out", "a folder", NULL},
     {"--gate", "gate", "a name", "off"},
     {"--cloud", "cloud", "a name", "kinematicCloud"},
     {"--log", "solverlog", "a file", "log.icoUncoupledKinematicParcelFoam"},
     {"--window", "window", "T0,TH,T1", NULL},
     {"--snowphoto", "snowphoto", "a program", NULL},
     {"--force", NULL, NULL, "0"}},
    0};

static int run_post(const wrap_vals *v)
{
    const char *dir = get(v, "--case"), *win = get(v, "--window");
    if (!*dir || !given(v, "--out"))
        die(2, "--case and --out are required (see --help)");
    struct stat st;
    if (stat(dir, &st) || !S_ISDIR(st.st_mode))
        die(1, "case folder '%s' not found", dir);
    char t[3][64] = {"", "", ""};
    if (*win) {
        const int whole = shell_read(win, t, 4);
        const double a = strtod(t[0], NULL), b = strtod(t[1], NULL), c = strtod(t[2], NULL);
        if (!(whole && decimal(t[0], "+") && decimal(t[1], "+") && decimal(t[2], "+") &&
              a >= 0 && a < b && b < c))
            die(2, "--window '%s' is not T0,TH,T1 with 0 <= T0 < TH < T1", win);
    }
    assign_all(v);
    assign("w0", t[0]);
    assign("wh", t[1]);
    assign("w1", t[2]);
    return 0;
}

static const wrap_spec compose_spec = {
    "wedge-compose",
    "wedge-compose - the rear-face deposit of any spray, composed from the per-diameter\n"
    "clouds of Allrun -sizes without running again (doc/reference/wedge-ladder.md).\n"
    "\n"
    "Usage: post/wedge-compose --results DIR --out DIR [--force]\n"
    "           (--mvd UM [--sigma-g S] [--range MIN,MAX] [--freeze F] | --masses CSV)\n"
    "           [--sampled F] [--label TEXT]\n"
    "\n"
    "  --results DIR  Allrun -sizes' results: DIR/d<N>um/ of every simulated class\n"
    "  --mvd UM       the spray by mass: log-normal, median volume diameter UM\n"
    "  --sigma-g S    its geometric standard deviation (default 1.8)\n"
    "  --range A,B    truncated to droplets of A..B um (default 2,150)\n"
    "  --freeze F     ice diameter = F x droplet diameter (default 1.03)\n"
    "  --masses CSV   or the class masses directly: lines \"d_um,mass\" (normalized)\n"
    "  --sampled F    the share of each cloud's injection in the sampling window (default 1)\n"
    "  --label TEXT   the spray's description in the tables (default: from the options)\n"
    "  --out DIR      classes.md, regions.md, rear_deposit.csv (per face), rear_blocks.csv\n"
    "                 and rear_deposit.png (with gnuplot; the blocks the classes' records\n"
    "                 hold, each with its error: snowwedge blocks): created, or an empty\n"
    "                 or earlier SnowWall output folder\n"
    "  --force        write into any other existing --out folder (nothing deleted)\n"
    "Exit status: 0 done, 1 a result missing or unreadable, 2 usage.\n",
    {{"--results", "res", NULL, NULL},
     {"--out", "out", NULL, NULL},
     {"--mvd", "mvd", NULL, NULL},
     {"--sigma-g", "sg", NULL, "1.8"},
     {"--range", "range", NULL, "2,150"},
     {"--freeze", "freeze", NULL, "1.03"},
     {"--masses", "masses", NULL, NULL},
     {"--label", "label", NULL, NULL},
     {"--sampled", "sampled", NULL, "1"},
     {"--force", NULL, NULL, "0"}},
    0};

static int run_compose(const wrap_vals *v)
{
    const char *mvd = get(v, "--mvd"), *masses = get(v, "--masses");
    if (!given(v, "--results"))
        die(2, "--results DIR is required (see --help)");
    if (!given(v, "--out"))
        die(2, "--out DIR is required (see --help)");
    if (!*mvd && !*masses)
        die(2, "give the spray: --mvd UM or --masses CSV (see --help)");
    if (*mvd && *masses)
        die(2, "--mvd and --masses exclude each other (see --help)");
    if (*masses && access(masses, R_OK))
        die(2, "--masses: cannot read '%s' (see --help)", masses);
    char *a[] = {"snowwedge", "compose-check", "--sampled", (char *)get(v, "--sampled"),
                 "--mvd", (char *)mvd, "--sigma-g", (char *)get(v, "--sigma-g"),
                 "--range", (char *)get(v, "--range"), "--freeze", (char *)get(v, "--freeze"), NULL};
    if (swe_ladder_main(*mvd ? 12 : 4, a))
        exit(2);
    assign_all(v);
    return 0;
}

static const wrap_spec ladder_spec = {
    "wedge-ladder",
    "wedge-ladder - the resolution ladder of tutorials/wedge: the runs of Allrun -level N\n"
    "gathered into one table for snowladder total: the discretization error per quantity,\n"
    "the total error of every run against its run time, the cheapest run per target\n"
    "(the quantities, the rules of --with and the files: doc/reference/wedge-ladder.md).\n"
    "\n"
    "Usage: post/wedge-ladder --run DIR [--run DIR ...] [--with LADDER.csv] --out DIR\n"
    "           [--plot QUANTITY] [--targets LIST] [--snowladder PATH] [--force]\n"
    "       post/wedge-ladder --check LADDER.csv\n"
    "\n"
    "  --run DIR          a finished run's case folder of one mesh family, named by the folder\n"
    "  --with FILE        an earlier ladder.csv joined with the runs (then one --run will do)\n"
    "  --out DIR          ladder.md, total_error.csv, gci.csv, ladder.csv, total_error.png\n"
    "  --force            write into any existing --out folder\n"
    "  --plot Q           the quantity plotted (default face-mvdM of the decided spray)\n"
    "  --targets L        the target errors in percent (default 10,30)\n"
    "  --snowladder PATH  the program (default SnowWall's bin/snowladder)\n"
    "  --check FILE       only check a stored ladder's format: exit 0 silent, else 2\n"
    "Exit status: 0 done, 1 a result missing or unreadable, 2 usage.\n",
    {{"--run", "run", NULL, NULL},
     {"--out", "out", NULL, NULL},
     {"--plot", "plot", NULL, NULL},
     {"--targets", "targets", NULL, "10,30"},
     {"--snowladder", "ladder", NULL, NULL},
     {"--with", "with", NULL, NULL},
     {"--check", "check", NULL, NULL},
     {"--force", NULL, NULL, "0"}},
    0};

static int run_ladder(const wrap_vals *v)
{
    const char *check = get(v, "--check"), *with = get(v, "--with"), *targets = get(v, "--targets");
    if (*check) {
        if (v->nlist || given(v, "--out") || *with)
            die(2, "--check takes no other option (see --help)");
        if (!readable_file(check))
            die(2, "--check %s: not a readable file", check);
        char what[4200];
        snprintf(what, sizeof what, "--check %s", check);
        char *a[] = {"snowwedge", "ladder-stored", "--what", what, (char *)check, NULL};
        /* the stored rows not shown: standard output to /dev/null while it runs */
        fflush(stdout);
        const int keep = dup(1), null = open("/dev/null", O_WRONLY);
        if (keep < 0 || null < 0 || dup2(null, 1) < 0)
            die(1, "cannot write /dev/null");
        const int rc = swe_ladder_main(5, a);
        fflush(stdout);
        dup2(keep, 1);
        close(null);
        close(keep);
        if (!rc)
            puts("exit 0");
        return rc;
    }
    if (!given(v, "--out"))
        die(2, "--out DIR is required (see --help)");
    if (!*with && v->nlist < 2)
        die(2, "at least two --run DIR are needed (three for an observed order), or one and --with (see --help)");
    if (*with && v->nlist < 1)
        die(2, "--with needs at least one --run DIR (see --help)");
    if (*with && !readable_file(with))
        die(1, "--with %s: not a readable file", with);
    /* the targets: [0-9.]+ separated by single commas */
    int ok = *targets && *targets != ',' && targets[strlen(targets) - 1] != ',' && !strstr(targets, ",,") &&
             strspn(targets, "0123456789.,") == strlen(targets);
    if (!ok)
        die(2, "--targets: '%s' is not a comma-separated list of percentages (see --help)", targets);
    assign_all(v);
    assign_list("runs", v);
    return 0;
}

static const wrap_spec variant_spec = {
    "wedge-variant",
    "wedge-variant - a variant cloud of tutorials/wedge against the main one (after Allrun\n"
    "-feedback, -rough or -rebound): DIR/V.md, per patch the deposit and sticks / impacts of\n"
    "DIR/G/ and DIR/V/ and its change, then the rear-face regions of both (snowphoto regions,\n"
    "one threshold: F x the larger rear-face maximum; doc/reference/wedge-post.md).\n"
    "\n"
    "Usage: post/wedge-variant --variant feedback|rough|rebound --results DIR --gate G [--log FILE]\n"
    "                          [--snowphoto EXE] [--rel F]\n"
    "\n"
    "  --variant V      feedback, rough or rebound\n"
    "  --results DIR    the run's results (DIR/G/ the main cloud's, DIR/V/ the variant's)\n"
    "  --gate G         the main cloud's gate setting\n"
    "  --log FILE       the solver log (default log.pimpleUncoupledKinematicParcelFoam)\n"
    "  --snowphoto EXE  default bin/snowphoto of this repository\n"
    "  --rel F          the threshold's share of the larger maximum, (0, 1] (default 0.1)\n",
    {{"--variant", "var", "feedback, rough or rebound", NULL},
     {"--results", "res", "a folder", NULL},
     {"--gate", "gate", "a setting", NULL},
     {"--log", "logf", "a file", "log.pimpleUncoupledKinematicParcelFoam"},
     {"--snowphoto", "exe", "a program", NULL},
     {"--rel", "rel", "a number", "0.1"}},
    0};

static int run_variant(const wrap_vals *v)
{
    const char *var = get(v, "--variant"), *rel = get(v, "--rel");
    if (!given(v, "--results") || !given(v, "--gate"))
        die(2, "--results and --gate are required");
    static const char *const names[] = {"feedback", "rough", "rebound"},
                             *with[] = {"with feedback", "rough wall", "classic rebound"};
    int k = 0;
    while (k < 3 && strcmp(var, names[k]))
        k++;
    if (k == 3)
        die(2, "--variant must be feedback, rough or rebound, got '%s'", var);
    if (!in_range(rel, 0, 1, 0))
        die(2, "--rel '%s' outside (0, 1]", rel);
    assign_all(v);
    assign("with", with[k]);
    return 0;
}

static const wrap_spec errortime_spec = {
    "wedge-errortime",
    "wedge-errortime - the error against run time of the sampling designs, from the cost\n"
    "tables (post/wedge-cost) of one or more runs: on standard output a markdown table of\n"
    "every point and the time for 10 % at its rate, and a plot (doc/reference/wedge-ladder.md).\n"
    "\n"
    "Usage: post/wedge-errortime --out PNG [--region R] [--title TEXT] CSV LABEL [CSV LABEL ...]\n"
    "\n"
    "  CSV LABEL   a results/cost.csv of wedge-cost and the name of its run\n"
    "  --out PNG   the plot (an existing PNG replaced only when a regular file, else exit 2)\n"
    "  --region R  the error plotted: face, left, right, centre or edges (default edges)\n"
    "  --title T   the plot's title\n"
    "Exit status: 0 done, 1 input unreadable, 2 usage.\n",
    {{"--out", "out", NULL, NULL},
     {"--region", "region", NULL, "edges"},
     {"--title", "title", NULL, "Error of the rear-face deposit against run time"}},
    1};

static int run_errortime(const wrap_vals *v)
{
    const char *region = get(v, "--region");
    if (!given(v, "--out"))
        die(2, "--out PNG is required (see --help)");
    if (!v->nlist)
        die(2, "give at least one CSV LABEL (see --help)");
    if (strcmp(region, "face") && strcmp(region, "left") && strcmp(region, "right") &&
        strcmp(region, "centre") && strcmp(region, "edges"))
        die(2, "--region: '%s' is not face, left, right, centre or edges (see --help)", region);
    assign_all(v);
    assign_list("args", v);
    return 0;
}

int swe_cmd_wrap(int argc, char **argv)
{
    static const struct {
        const wrap_spec *spec;
        int (*run)(const wrap_vals *);
        int eval;
    } c[] = {{&capture_spec, run_capture, 0}, {&cost_spec, run_cost, 0},
             {&dispersion_spec, run_dispersion, 0}, {&fill_spec, run_fill, 0},
             {&resolution_spec, run_resolution, 0}, {&post_spec, run_post, 1},
             {&compose_spec, run_compose, 1}, {&ladder_spec, run_ladder, 1},
             {&variant_spec, run_variant, 1}, {&errortime_spec, run_errortime, 1}};
    for (size_t i = 0; i < sizeof c / sizeof *c; i++)
        if (!strcmp(argv[1], c[i].spec->script)) {
            script = swe_cli_prog = c[i].spec->script;
            static wrap_vals v;
            parse(c[i].spec, argc, argv, &v, c[i].eval);
            setlocale(LC_COLLATE, ""); /* file lists sorted as ls sorts them */
            return c[i].run(&v);
        }
    return -1;
}
