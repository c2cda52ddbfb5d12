/* swe_cli.c - the snowwedge command's option parser and helpers (swe_cli.h). */
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

const char *swe_cli_prog = "snowwedge";

void swe_cli_die(int code, const char *fmt, ...)
{
    va_list ap;
    fprintf(stderr, "%s: ", swe_cli_prog);
    va_start(ap, fmt);
    vfprintf(stderr, fmt, ap);
    va_end(ap);
    fputc('\n', stderr);
    exit(code);
}

double swe_cli_number(const char *opt, const char *s)
{
    char *end;
    errno = 0;
    const double v = strtod(s, &end);
    if (end == s || *end || errno || !isfinite(v))
        swe_cli_die(2, "%s: '%s' is not a number", opt, s);
    return v;
}

FILE *swe_cli_open(const char *path)
{
    FILE *f = fopen(path, "r");
    if (!f)
        swe_cli_die(1, "cannot read %s", path);
    return f;
}

void swe_cli_parse(int argc, char **argv, swe_options *o)
{
    swe_spray_default(&o->spray);
    o->sg_s = "1.8";
    o->range_s = "2,150";
    o->freeze_s = "1.03";
    o->files = calloc((size_t)argc + 1, sizeof *o->files);
    if (!o->files)
        swe_cli_die(1, "out of memory");
    for (int i = 2; i < argc; i++) {
        const char *a = argv[i];
        if (!strcmp(a, "-h") || !strcmp(a, "--help")) {
            fputs(swe_cli_usage, stdout);
            exit(0);
        }
        if (a[0] == '-' && a[1] == '-') {
            if (i + 1 >= argc || !argv[i + 1][0])
                swe_cli_die(2, "%s needs a value (see --help)", a);
            const char *v = argv[++i];
            if (!strcmp(a, "--mvd")) {
                o->spray.mvd = swe_cli_number(a, v);
                o->mvd_s = v;
                o->has_spray = 1;
            } else if (!strcmp(a, "--sigma-g")) {
                o->spray.sigma_g = swe_cli_number(a, v);
                o->sg_s = v;
            } else if (!strcmp(a, "--freeze")) {
                o->spray.freeze = swe_cli_number(a, v);
                o->freeze_s = v;
            } else if (!strcmp(a, "--range")) {
                char *c = strchr(v, ',');
                if (!c || strchr(c + 1, ','))
                    swe_cli_die(2, "--range: '%s' is not MIN,MAX", v);
                char buf[64];
                snprintf(buf, sizeof buf, "%.*s", (int)(c - v), v);
                o->spray.dmin = swe_cli_number(a, buf);
                o->spray.dmax = swe_cli_number(a, c + 1);
                o->range_s = v;
            } else if (!strcmp(a, "--masses"))
                o->masses = v;
            else if (!strcmp(a, "--classes"))
                o->classes = v;
            else if (!strcmp(a, "--weights"))
                o->weights = v;
            else if (!strcmp(a, "--table"))
                o->table = v;
            else if (!strcmp(a, "--desc"))
                o->desc = v;
            else if (!strcmp(a, "--label"))
                o->label = v;
            else if (!strcmp(a, "--from"))
                o->from = v;
            else if (!strcmp(a, "--to"))
                o->to = v;
            else if (!strcmp(a, "--outline"))
                o->outline = v;
            else if (!strcmp(a, "--kind"))
                o->kind = v;
            else if (!strcmp(a, "--window"))
                o->window = v;
            else if (!strcmp(a, "--target"))
                o->target = v;
            else if (!strcmp(a, "--segments"))
                o->segments = v;
            else if (!strcmp(a, "--psd"))
                o->psd = v;
            else
                swe_cli_die(2, "%s: unknown option '%s' (see --help)", argv[1], a);
        } else
            o->files[o->nfiles++] = a;
    }
    if (o->has_spray) {
        char err[256];
        if (swe_spray_check(&o->spray, err, sizeof err))
            swe_cli_die(2, "%s", err);
    }
}

void swe_cli_need(const char *what, const char *v, const char *cmd)
{
    if (!v)
        swe_cli_die(2, "%s: %s is required (see --help)", cmd, what);
}


int swe_cli_read_weights(const char *path, char (*d)[32], double *w, double *e0, double *e1, int max)
{
    FILE *f = swe_cli_open(path);
    int n = 0;
    char line[512];
    while (fgets(line, sizeof line, f)) {
        if (n >= max)
            swe_cli_die(2, "%s: more than %d classes", path, max);
        char e0s[64], e1s[64];
        if (sscanf(line, "%31s %lf %63s %63s", d[n], &w[n], e0s, e1s) != 4)
            swe_cli_die(2, "%s: line %d is not \"D w e0 e1\"", path, n + 1);
        e0[n] = strtod(e0s, NULL);
        e1[n] = strtod(e1s, NULL);
        n++;
    }
    fclose(f);
    return n;
}


void swe_cli_strip_parens(char *s)
{
    for (; *s; s++)
        if (*s == '(' || *s == ')')
            *s = ' ';
}
