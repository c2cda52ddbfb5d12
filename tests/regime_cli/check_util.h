/* check_util.h - what the table-against-kernel checks (oblique_check,
 * rebound_check) share: a list read from a regime.coeffs, and the kernel model
 * of the embedded defaults plus KEY=VALUE arguments. Test tools only. */
#ifndef CHECK_UTIL_H
#define CHECK_UTIL_H

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "swr_collide.h"
#include "swr_params.h"

/* The list of key in FILE (NULL when absent); *n its length. */
static double *list_of(const char *path, const char *key, int *n)
{
    FILE *f = fopen(path, "r");
    if (!f)
        return NULL;
    char line[1 << 16];
    double *v = NULL;
    *n = 0;
    const size_t kl = strlen(key);
    while (fgets(line, sizeof line, f)) {
        char *p = line;
        while (*p == ' ')
            p++;
        if (strncmp(p, key, kl) != 0 || p[kl] != ' ' || !(p = strchr(p, '(')))
            continue;
        v = malloc(4096 * sizeof *v);
        for (char *t = strtok(p + 1, " );\n"); t && v && *n < 4096; t = strtok(NULL, " );\n"))
            v[(*n)++] = atof(t);
        break;
    }
    fclose(f);
    return v;
}

/* The kernel model of the embedded defaults plus argv[first..argc-1]
 * (KEY=VALUE), or NULL with a message prefixed by prog on stderr. */
static swr_model *kernel_of_args(const char *prog, int argc, char **argv, int first)
{
    swr_params p;
    swr_params_default(&p);
    char err[256];
    for (int i = first; i < argc; i++)
        if (swr_params_set_kv(&p, argv[i], err, sizeof err) != 0) {
            fprintf(stderr, "%s: %s\n", prog, err);
            return NULL;
        }
    swr_model *m = swr_model_alloc(&p, err, sizeof err);
    if (!m)
        fprintf(stderr, "%s: %s\n", prog, err);
    return m;
}

#endif
