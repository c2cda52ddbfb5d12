/* swt_io.c - atomic output sets, strict option parsing, gnuplot runner. */
#define _GNU_SOURCE   /* posix_spawn_file_actions_addchdir_np (glibc >= 2.29) */
#include "swt_io.h"

#include <errno.h>
#include <math.h>
#include <signal.h>
#include <spawn.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

extern char **environ;

typedef struct {
    char *name;    /* as registered */
    char *final;   /* final path */
    char *tmp;     /* temporary path in the same folder */
    FILE *fp;      /* open stream or NULL */
} swt_out;

struct swt_outset {
    char *dir;          /* NULL: names are paths */
    char *created;      /* top-most folder this set created (removed on abort) */
    swt_out *f;
    int n, cap;
    int done;           /* committed or aborted */
};

/* Interrupted runs leave nothing (SIGINT, SIGTERM, SIGHUP): the set being
 * written and the gnuplot script being run are known here, and the handler
 * removes their temporaries and the folders the set created with
 * async-signal-safe calls only (unlink, rmdir, character loops), then dies of
 * the same signal. */
static swt_outset *volatile g_active;
static char g_script[4200];
static volatile sig_atomic_t g_script_on;
static char g_dirbuf[4200];

static volatile pid_t g_child;   /* the gnuplot being waited for, or 0 */

static void on_signal(int sig)
{
    /* the plotting child first: stopped and reaped before the temporaries go,
     * else it writes its PNG after they were removed (issue 22) */
    const pid_t child = g_child;
    if (child > 0) {
        kill(child, SIGTERM);
        while (waitpid(child, NULL, 0) < 0 && errno == EINTR)
            ;
    }
    if (g_script_on)
        unlink(g_script);
    swt_outset *o = g_active;
    if (o && !o->done) {
        for (int i = 0; i < o->n; i++)
            if (o->f[i].tmp)
                unlink(o->f[i].tmp);
        if (o->created && o->dir) {
            size_t n = 0, nc = 0;
            while (o->dir[n] && n + 1 < sizeof g_dirbuf) {
                g_dirbuf[n] = o->dir[n];
                n++;
            }
            g_dirbuf[n] = '\0';
            while (o->created[nc])
                nc++;
            while (n >= nc && rmdir(g_dirbuf) == 0) {
                while (n > 0 && g_dirbuf[n - 1] != '/')
                    n--;
                if (n == 0)
                    break;
                g_dirbuf[--n] = '\0';
            }
        }
    }
    signal(sig, SIG_DFL);
    raise(sig);
}

static void watch_signals(swt_outset *o)
{
    static int installed;
    g_active = o;
    if (installed)
        return;
    installed = 1;
    const int sigs[] = { SIGINT, SIGTERM, SIGHUP };
    for (size_t k = 0; k < sizeof sigs / sizeof *sigs; k++) {
        struct sigaction sa;
        memset(&sa, 0, sizeof sa);
        sa.sa_handler = on_signal;
        sigemptyset(&sa.sa_mask);
        sigaction(sigs[k], &sa, NULL);
    }
}

static char *sdup(const char *s)
{
    size_t n = strlen(s) + 1;
    char *p = malloc(n);
    if (p) memcpy(p, s, n);
    return p;
}

/* mkdir -p; records the top-most folder created. */
static int mkdirs(const char *dir, char **created, char *err, size_t errlen)
{
    char *p = sdup(dir);
    if (!p) { snprintf(err, errlen, "out of memory"); return -1; }
    size_t len = strlen(p);
    while (len > 1 && p[len - 1] == '/') p[--len] = '\0';
    for (char *s = p + 1; ; s++) {
        int end = (*s == '\0');
        if (*s == '/' || end) {
            char c = *s;
            *s = '\0';
            struct stat st;
            if (stat(p, &st) != 0) {
                if (mkdir(p, 0777) != 0) {
                    snprintf(err, errlen, "cannot create folder '%s': %s", p, strerror(errno));
                    free(p);
                    return -1;
                }
                if (!*created) *created = sdup(p);
            } else if (!S_ISDIR(st.st_mode)) {
                snprintf(err, errlen, "'%s' exists and is not a folder", p);
                free(p);
                return -1;
            }
            *s = c;
            if (end) break;
        }
    }
    free(p);
    return 0;
}

swt_outset *swt_outset_alloc(const char *dir, char *err, size_t errlen)
{
    swt_outset *o = calloc(1, sizeof *o);
    if (!o) { snprintf(err, errlen, "out of memory"); return NULL; }
    if (dir) {
        if (!*dir) { snprintf(err, errlen, "empty output folder name"); free(o); return NULL; }
        o->dir = sdup(dir);
        if (!o->dir || mkdirs(dir, &o->created, err, errlen) != 0) {
            free(o->dir); free(o->created); free(o);
            return NULL;
        }
    }
    watch_signals(o);
    return o;
}

const char *swt_outset_add(swt_outset *o, const char *name, char *err, size_t errlen)
{
    for (int i = 0; i < o->n; i++)
        if (strcmp(o->f[i].name, name) == 0) return o->f[i].tmp;
    if (o->n == o->cap) {
        int cap = o->cap ? 2 * o->cap : 16;
        swt_out *f = realloc(o->f, (size_t)cap * sizeof *f);
        if (!f) { snprintf(err, errlen, "out of memory"); return NULL; }
        o->f = f; o->cap = cap;
    }
    size_t len = strlen(name) + (o->dir ? strlen(o->dir) : 0) + 16;
    swt_out *e = &o->f[o->n];
    e->name = sdup(name);
    e->final = malloc(len);
    e->tmp = malloc(len);
    e->fp = NULL;
    if (!e->name || !e->final || !e->tmp) {
        free(e->name); free(e->final); free(e->tmp);
        snprintf(err, errlen, "out of memory");
        return NULL;
    }
    if (o->dir) {
        snprintf(e->final, len, "%s/%s", o->dir, name);
        snprintf(e->tmp, len, "%s/.tmp-%s", o->dir, name);
    } else {
        const char *slash = strrchr(name, '/');
        snprintf(e->final, len, "%s", name);
        if (slash) snprintf(e->tmp, len, "%.*s.tmp-%s", (int)(slash - name + 1), name, slash + 1);
        else snprintf(e->tmp, len, ".tmp-%s", name);
    }
    /* the temporary is renamed over the final name: an existing folder, device,
     * FIFO or socket there would be replaced (as root, /dev/full became a file) */
    struct stat st;
    if (stat(e->final, &st) == 0 && !S_ISREG(st.st_mode)) {
        snprintf(err, errlen, "cannot write '%s': it exists and is not a regular file",
                 e->final);
        free(e->name); free(e->final); free(e->tmp);
        return NULL;
    }
    o->n++;
    return e->tmp;
}

FILE *swt_outset_open(swt_outset *o, const char *name, char *err, size_t errlen)
{
    const char *tmp = swt_outset_add(o, name, err, errlen);
    if (!tmp) return NULL;
    swt_out *e = NULL;
    for (int i = 0; i < o->n; i++)
        if (o->f[i].tmp == tmp) e = &o->f[i];
    if (e->fp) return e->fp;
    e->fp = fopen(tmp, "w");
    if (!e->fp) {
        snprintf(err, errlen, "cannot write '%s': %s", e->final, strerror(errno));
        return NULL;
    }
    return e->fp;
}

const char *swt_outset_final(const swt_outset *o, const char *name)
{
    for (int i = 0; i < o->n; i++)
        if (strcmp(o->f[i].name, name) == 0) return o->f[i].final;
    return NULL;
}

int swt_outset_commit(swt_outset *o, char *err, size_t errlen)
{
    for (int i = 0; i < o->n; i++) {
        swt_out *e = &o->f[i];
        if (e->fp) {
            int bad = ferror(e->fp);
            if (fclose(e->fp) != 0) bad = 1;
            e->fp = NULL;
            if (bad) {
                snprintf(err, errlen, "write error on '%s'", e->final);
                swt_outset_abort(o);
                return -1;
            }
        }
        struct stat st;
        if (stat(e->tmp, &st) != 0) {
            snprintf(err, errlen, "output '%s' was not produced", e->final);
            swt_outset_abort(o);
            return -1;
        }
    }
    for (int i = 0; i < o->n; i++) {
        if (rename(o->f[i].tmp, o->f[i].final) != 0) {
            snprintf(err, errlen, "cannot rename to '%s': %s", o->f[i].final, strerror(errno));
            swt_outset_abort(o);
            return -1;
        }
    }
    o->done = 1;
    return 0;
}

void swt_outset_abort(swt_outset *o)
{
    if (o->done) return;
    for (int i = 0; i < o->n; i++) {
        if (o->f[i].fp) { fclose(o->f[i].fp); o->f[i].fp = NULL; }
        unlink(o->f[i].tmp);
    }
    if (o->created && o->dir) {
        /* remove the folders this set created, innermost first */
        char *p = sdup(o->dir);
        while (p && strlen(p) >= strlen(o->created)) {
            if (rmdir(p) != 0) break;
            char *s = strrchr(p, '/');
            if (!s) break;
            *s = '\0';
        }
        free(p);
    }
    o->done = 1;
}

void swt_outset_free(swt_outset *o)
{
    if (!o) return;
    if (g_active == o) g_active = NULL;
    swt_outset_abort(o);
    for (int i = 0; i < o->n; i++) {
        free(o->f[i].name); free(o->f[i].final); free(o->f[i].tmp);
    }
    free(o->f); free(o->dir); free(o->created); free(o);
}

int swt_parse_double(const char *opt, const char *text, double lo, double hi,
                     double *out, char *err, size_t errlen)
{
    if (!text || !*text) {
        snprintf(err, errlen, "%s: missing value", opt);
        return -1;
    }
    /* decimal only: strtod also reads hexadecimal (0x10, 0x1p-14), which an
     * option value is not meant to be */
    if (strpbrk(text, "xX")) {
        snprintf(err, errlen, "%s: '%s' is not a decimal number", opt, text);
        return -1;
    }
    char *end;
    errno = 0;
    double v = strtod(text, &end);
    while (*end == ' ' || *end == '\t') end++;
    if (end == text || *end != '\0') {
        snprintf(err, errlen, "%s: '%s' is not a number", opt, text);
        return -1;
    }
    if (!isfinite(v)) {
        snprintf(err, errlen, "%s: '%s' is not a finite number", opt, text);
        return -1;
    }
    if (v < lo || v > hi) {
        if (lo > 0.0 && lo <= 1e-300 && v > 0.0)
            snprintf(err, errlen, "%s: '%s' is too small: the smallest accepted value is %g",
                     opt, text, lo);
        else if (lo > 0.0 && lo <= 1e-300)
            snprintf(err, errlen, "%s: '%s' is out of range (0, %g]", opt, text, hi);
        else
            snprintf(err, errlen, "%s: '%s' is out of range [%g, %g]", opt, text, lo, hi);
        return -1;
    }
    *out = v;
    return 0;
}

int swt_parse_int(const char *opt, const char *text, long lo, long hi, long *out,
                  char *err, size_t errlen)
{
    if (!text || !*text) {
        snprintf(err, errlen, "%s: missing value", opt);
        return -1;
    }
    char *end;
    errno = 0;
    long v = strtol(text, &end, 10);
    if (end == text || *end != '\0' || errno == ERANGE) {
        /* a number out of range (1e9, 99999999999999999999) is named so, not
         * "not an integer"; hexadecimal is not decimal */
        double x;
        char e2[8];
        if (!strpbrk(text, "xX") && swt_parse_double(opt, text, -HUGE_VAL, HUGE_VAL, &x, e2,
                                                    sizeof e2) == 0
            && x == floor(x) && (x < (double)lo || x > (double)hi))
            snprintf(err, errlen, "%s: '%s' is out of range [%ld, %ld]", opt, text, lo, hi);
        else
            snprintf(err, errlen, "%s: '%s' is not an integer", opt, text);
        return -1;
    }
    if (v < lo || v > hi) {
        snprintf(err, errlen, "%s: '%s' is out of range [%ld, %ld]", opt, text, lo, hi);
        return -1;
    }
    *out = v;
    return 0;
}

int swt_parse_list(const char *opt, const char *text, double lo, double hi,
                   double **out, int *n, char *err, size_t errlen)
{
    if (!text || !*text) {
        snprintf(err, errlen, "%s: missing value", opt);
        return -1;
    }
    int cap = 1;
    for (const char *s = text; *s; s++) cap += (*s == ',');
    double *v = malloc((size_t)cap * sizeof *v);
    char *buf = sdup(text);
    if (!v || !buf) { free(v); free(buf); snprintf(err, errlen, "out of memory"); return -1; }
    int k = 0;
    char *s = buf;
    for (;;) {
        char *comma = strchr(s, ',');
        if (comma) *comma = '\0';
        if (!*s) {
            snprintf(err, errlen, "%s: '%s' has an empty item", opt, text);
            free(v); free(buf);
            return -1;
        }
        if (swt_parse_double(opt, s, lo, hi, &v[k], err, errlen) != 0) {
            free(v); free(buf);
            return -1;
        }
        k++;
        if (!comma) break;
        s = comma + 1;
    }
    free(buf);
    *out = v;
    *n = k;
    return 0;
}

int swt_run_gnuplot(const char *dir, const char *script, char *err, size_t errlen)
{
    char *argv[] = { (char *)"gnuplot", (char *)script, NULL };
    pid_t pid;
    posix_spawn_file_actions_t fa;
    if (posix_spawn_file_actions_init(&fa) != 0) {
        snprintf(err, errlen, "cannot run gnuplot: out of memory");
        return -1;
    }
    if (dir && posix_spawn_file_actions_addchdir_np(&fa, dir) != 0) {
        posix_spawn_file_actions_destroy(&fa);
        snprintf(err, errlen, "cannot run gnuplot: out of memory");
        return -1;
    }
    int rc = posix_spawnp(&pid, "gnuplot", &fa, NULL, argv, environ);
    posix_spawn_file_actions_destroy(&fa);
    if (rc == 0)
        g_child = pid;
    if (rc != 0) {
        snprintf(err, errlen, "cannot run gnuplot: %s (install gnuplot-nox, or use --no-plot)",
                 strerror(rc));
        return -1;
    }
    int st;
    while (waitpid(pid, &st, 0) < 0) {
        if (errno != EINTR) {
            g_child = 0;
            snprintf(err, errlen, "waiting for gnuplot: %s", strerror(errno));
            return -1;
        }
    }
    g_child = 0;
    if (!WIFEXITED(st) || WEXITSTATUS(st) != 0) {
        snprintf(err, errlen, "gnuplot failed on '%s' (status %d)", script,
                 WIFEXITED(st) ? WEXITSTATUS(st) : -1);
        return -1;
    }
    return 0;
}

const char *swt_gp_name(const char *path)
{
    const char *slash = strrchr(path, '/');
    return slash ? slash + 1 : path;
}

int swt_gnuplot_open(swt_gnuplot *g, const char *png, int width, int height,
                     char *err, size_t errlen)
{
    snprintf(g->path, sizeof g->path, "%s.gp", png);
    g_script_on = 0;
    snprintf(g_script, sizeof g_script, "%s", g->path);
    g_script_on = 1;
    const char *name = swt_gp_name(png);
    if (name == png)
        snprintf(g->dir, sizeof g->dir, ".");
    else
        snprintf(g->dir, sizeof g->dir, "%.*s", (int)(name - png), png);
    g->f = fopen(g->path, "w");
    if (!g->f) {
        snprintf(err, errlen, "cannot write '%.300s'", g->path);
        return -1;
    }
    fprintf(g->f, "if (strstrt(GPVAL_TERMINALS, 'pngcairo') > 0) {\n"
                  "  set terminal pngcairo size %d,%d font 'Sans,10'\n"
                  "} else {\n"
                  "  set terminal png size %d,%d\n"
                  "}\n", width, height, width, height);
    fprintf(g->f, "set output '%s'\n", name);
    return 0;
}

int swt_gnuplot_finish(swt_gnuplot *g, char *err, size_t errlen)
{
    int rc = 0;
    if (fclose(g->f) != 0) {
        snprintf(err, errlen, "cannot write '%.300s'", g->path);
        rc = -1;
    }
    g->f = NULL;
    if (rc == 0)
        rc = swt_run_gnuplot(g->dir, swt_gp_name(g->path), err, errlen);
    remove(g->path);
    g_script_on = 0;
    return rc;
}

double swt_thread_cpu(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

double swt_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}
