/* sr_main.c - snowregime: stick/bounce regime maps of snow particles on a wall.
 * The subcommand dispatch. The commands live in sr_<command>.c, the option
 * helpers they share in sr_opts.c, the manual pages in sr_help.c: every file
 * calls into sr_opts.c / sr_help.c, none back into this one. */
#include <stdio.h>
#include <string.h>

#include "sr.h"

int main(int argc, char **argv)
{
    if (argc < 2) {
        fputs("usage: snowregime COMMAND [OPTIONS]   (snowregime --help for the manual)\n", stderr);
        return SR_EXIT_USAGE;
    }
    /* an interrupted run leaves no output: the temporaries of its output set,
     * the folders it created and a running gnuplot are cleaned up */
    swo_signals_on();
    const char *c = argv[1];
    if (strcmp(c, "--help") == 0 || strcmp(c, "-h") == 0 || strcmp(c, "help") == 0) {
        sr_help(argc > 2 ? argv[2] : NULL);
        return 0;
    }
    if (strcmp(c, "--version") == 0) {
        if (argc > 2) {   /* not dropped: 'snowregime --version map ...' runs nothing */
            fprintf(stderr, "snowregime: --version takes no arguments, got '%s'\n", argv[2]);
            return SR_EXIT_USAGE;
        }
        puts("snowregime (SnowWall) 0.1");
        return 0;
    }
    if (strcmp(c, "collide") == 0) return sr_cmd_collide(argc - 1, argv + 1);
    if (strcmp(c, "vcrit") == 0) return sr_cmd_vcrit(argc - 1, argv + 1);
    if (strcmp(c, "map") == 0) return sr_cmd_map(argc - 1, argv + 1);
    if (strcmp(c, "sensitivity") == 0) return sr_cmd_sensitivity(argc - 1, argv + 1);
    if (strcmp(c, "convergence") == 0) return sr_cmd_convergence(argc - 1, argv + 1);
    fprintf(stderr, "snowregime: unknown command '%s' (snowregime --help lists them)\n", c);
    return SR_EXIT_USAGE;
}
