/* swt_io.c - strict option parsing, gnuplot runner (the outputs: swo_out.c). */
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
        swo_signal_child(pid);   /* stopped and reaped first when a signal ends the run */
    if (rc != 0) {
        snprintf(err, errlen, "cannot run gnuplot: %s (install gnuplot-nox, or use --no-plot)",
                 strerror(rc));
        return -1;
    }
    int st;
    while (waitpid(pid, &st, 0) < 0) {
        if (errno != EINTR) {
            swo_signal_child(0);
            snprintf(err, errlen, "waiting for gnuplot: %s", strerror(errno));
            return -1;
        }
    }
    swo_signal_child(0);
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
    swo_signal_scratch(g->path);
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
    swo_signal_scratch(NULL);
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
