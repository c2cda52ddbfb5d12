/* swe_cmd_opts.c - snowwedge allrun-options: tutorials/wedge/Allrun's command line
 * checked (swe_opts.h) and written as the shell assignments Allrun evaluates; and
 * snowwedge spray-entry: one entry of constant/sprayProperties (or --file) checked. */
#include "swe_cli.h"
#include "swe_opts.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int swe_cmd_opts(int argc, char **argv)
{
    const char *case_dir = ".", *nproc = "1";
    int i = 2;
    for (; i < argc && strcmp(argv[i], "--"); i++) {
        if (!strcmp(argv[i], "-h") || !strcmp(argv[i], "--help")) {
            fputs(swe_cli_usage, stdout);
            return 0;
        } else if (i + 1 < argc && !strcmp(argv[i], "--nproc")) {
            nproc = argv[++i];
        } else if (i + 1 < argc && !strcmp(argv[i], "--case")) {
            case_dir = argv[++i];
        } else {
            swe_cli_die(2, "allrun-options: unknown option or missing value '%s' (see --help)", argv[i]);
        }
    }
    char *end;
    const long ncpu = strtol(nproc, &end, 10);
    if (*end || end == nproc || ncpu < 1 || ncpu > 1000000)
        swe_cli_die(2, "allrun-options: --nproc needs a whole number from 1, got '%s'", nproc);
    if (i >= argc)
        swe_cli_die(2, "allrun-options: give Allrun's options after -- (see --help)");
    swe_allrun o;
    char err[8192];
    const int rc = swe_opts_parse(argc - i - 1, argv + i + 1, case_dir, ncpu, &o, stderr, err, sizeof err);
    if (rc)
        fprintf(stderr, "Allrun: %s\n", err);
    else
        swe_opts_write(stdout, &o);
    swe_opts_free(&o);
    return rc;
}

int swe_cmd_spray_entry(int argc, char **argv)
{
    const char *kind = NULL, *key = NULL, *file = NULL;
    int i = 2;
    for (; i < argc && strcmp(argv[i], "--"); i++) {
        if (!strcmp(argv[i], "-h") || !strcmp(argv[i], "--help")) {
            fputs(swe_cli_usage, stdout);
            return 0;
        } else if (i + 1 < argc && !strcmp(argv[i], "--kind")) {
            kind = argv[++i];
        } else if (i + 1 < argc && !strcmp(argv[i], "--key")) {
            key = argv[++i];
        } else if (i + 1 < argc && !strcmp(argv[i], "--file")) {
            file = argv[++i];
        } else {
            swe_cli_die(2, "spray-entry: unknown option or missing value '%s' (see --help)", argv[i]);
        }
    }
    if (!kind || (strcmp(kind, "num") && strcmp(kind, "list2") && strcmp(kind, "intlist")))
        swe_cli_die(2, "spray-entry: --kind needs num, list2 or intlist, got '%s'", kind ? kind : "");
    if (!key || i + 2 != argc)
        swe_cli_die(2, "spray-entry: give --key KEY and the value after -- (see --help)");
    char out[SWE_OPTS_TEXT], err[SWE_OPTS_TEXT + 256];
    if (swe_opts_spray_entry(file, kind, key, argv[i + 1], out, sizeof out, err, sizeof err))
        swe_cli_die(2, "%s", err);
    puts(out);
    return 0;
}
