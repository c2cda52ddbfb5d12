/* swe_cli.h - the snowwedge command's shared parts: its options, the
 * helpers that read numbers and files or end the command with a one-line
 * message (exit 1 an unreadable file, 2 usage or bad input), and one entry
 * per command (swe_cmd_*.c; usage and dispatch in swe_main.c). */
#ifndef SWE_CLI_H
#define SWE_CLI_H

#include "swe_spray.h"

#include <stdio.h>

/* the options of every command (NULL / 0: not given) */
typedef struct {
    swe_spray spray;
    int has_spray;
    const char *mvd_s, *sg_s, *range_s, *freeze_s; /* as given, for the header */
    const char *masses, *classes, *weights, *table, *desc, *label, *outline, *kind, *window;
    const char *from, *to, *target, *segments, *psd;
    const char **files;
    int nfiles;
} swe_options;


extern const char *swe_cli_usage;
/* the prefix of swe_cli_die's messages (default "snowwedge"; a script's name) */
extern const char *swe_cli_prog;

void swe_cli_die(int code, const char *fmt, ...) __attribute__((noreturn, format(printf, 2, 3)));
double swe_cli_number(const char *opt, const char *s);
FILE *swe_cli_open(const char *path);
void swe_cli_parse(int argc, char **argv, swe_options *o);
void swe_cli_need(const char *what, const char *v, const char *cmd);
/* the weights file of "snowwedge weights": classes d (as written), w, e0, e1 */
int swe_cli_read_weights(const char *path, char (*d)[32], double *w, double *e0, double *e1, int max);
/* the outline y0 y1 z0 z1 of a rear-face map, to 6 significant digits */
void swe_cli_outline(const char *path, double o[4]);

/* the parentheses of an OpenFOAM vector turned into blanks */
void swe_cli_strip_parens(char *s);

int swe_cmd_distribution(const swe_options *o);
int swe_cmd_weights(const swe_options *o);
int swe_cmd_classes(const swe_options *o);
int swe_cmd_regions(const swe_options *o);
int swe_cmd_map(const swe_options *o);
int swe_cmd_outline(const swe_options *o);
int swe_cmd_rear_stats(const swe_options *o);
int swe_cmd_rear_records(const swe_options *o);
int swe_cmd_forces(const swe_options *o);
int swe_cmd_spectrum(const swe_options *o);
/* the line of convergence.md on the solved flow of a replay library a .. b
   (period b - a): forceCoeffs' Cd mean, the spectra of Cd, Cs and Cl */
int swe_forces_solved(const char *path, double a, double b, double period);
int swe_cmd_probes(const swe_options *o);
int swe_cmd_errortime(const swe_options *o);
/* the commands of swe_cmd_ladder.c (ladder-*, resolution, errortime-points,
   compose-table), with their own options: the command's exit status, or -1
   when argv[1] is none of them */
int swe_ladder_main(int argc, char **argv);
/* the per-run post-processing commands (swe_cmd_post.c): their exit status,
   or -1 when argv[1] is none of them */
int swe_cmd_post(int argc, char **argv);

/* the options of the scripts tutorials/wedge/post/wedge-* (swe_cmd_wrap.c): the
   command's exit status, or -1 when argv[1] is none of the scripts */
int swe_cmd_wrap(int argc, char **argv);
/* the pictures (swe_cmd_plot.c: panels, compare), with their own options:
   the exit status, or -1 when argv[1] is none of them */
int swe_cmd_plot(int argc, char **argv);

/* tutorials/wedge/Allrun's commands (swe_cmd_run.c: spray-check, estimate, mesh, times, progress, nozzles,
   decompose, level, yplus, join-logs, join-table, resume-time, restart-tables,
   ladder-check, total-error),
   which parse their own options */
int swe_cmd_run_is(const char *cmd);
int swe_cmd_run(int argc, char **argv);

#endif
