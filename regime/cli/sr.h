/* sr.h - shared pieces of the snowregime command-line program. */
#ifndef SR_H
#define SR_H

#include <stdio.h>

#include "swr_collide.h"
#include "swr_params.h"
#include "swt_fit.h"
#include "swt_io.h"
#include "swt_map.h"
#include "swt_progress.h"
#include "swt_vcrit.h"

#define SR_EXIT_FAIL 1   /* computation or output failure */
#define SR_EXIT_USAGE 2  /* bad option, setting or input */

/* Command-line cursor: argv[i] is the word being looked at. */
typedef struct {
    int argc;
    char **argv;
    int i;
    const char *cmd;     /* subcommand name, for messages */
    char err[400];
    const char *rough_only; /* the first rough-wall-only option given (--points, --seed,
                               --level), checked against the wall by sr_rough_only_check */
} sr_args;

/* Settings common to every subcommand: --config FILE, --set key=value. */
typedef struct {
    const char *config;
    const char *sets[256];
    int nsets;
    int threads;
} sr_settings;

/* 1 when argv[i] is option `name` ("--name VALUE" or "--name=VALUE"); *val gets
 * the value (NULL and a message in a->err when it is missing). */
int sr_opt(sr_args *a, const char *name, const char **val);
/* 1 when argv[i] is the flag `name`. */
int sr_flag(sr_args *a, const char *name);
/* Handles --config/--set/--threads at argv[i]: 1 taken, 0 not, -1 error (a->err). */
int sr_settings_opt(sr_args *a, sr_settings *s);
/* --points N, --seed S, --level P (rough walls) into o: 1 taken, 0 not, -1 error. */
/* 0 when the model's wall is rough or no rough-only option was given; else -1 with
 * a message naming the option (a flat wall would ignore it without a word). */
int sr_rough_only_check(const sr_args *a, const swr_model *m, char *err, size_t errlen);
int sr_rough_opt(sr_args *a, swt_vcrit_opts *o);
/* defaults + config + sets + validate; -1 with message on error */
int sr_settings_apply(const sr_settings *s, swr_params *p, char *err, size_t errlen);
/* Usage error: prints "snowregime CMD: MSG" and returns SR_EXIT_USAGE. */
int sr_usage_error(const char *cmd, const char *msg);
int sr_fail(const char *cmd, const char *msg);
/* The output set of `--out DIR` (swo_out.h: the output-folder contract; force:
 * --force, which also lets a long run go, see sr_help.c), or of files by their
 * own paths when dir is NULL. Prints "snowregime CMD: note: ..." when it writes
 * into a foreign folder by force. NULL with the message printed and *rc the
 * exit status (SR_EXIT_USAGE when refused, SR_EXIT_FAIL otherwise). */
swo_set *sr_out_open(const char *cmd, const char *dir, int force, int *rc);
/* An output failure of set o with message msg printed: its exit status. */
int sr_out_fail(const char *cmd, const swo_set *o, const char *msg);
/* A comma list of numbers (swo_list_numbers: no empty item, no value twice,
 * taken in ascending order with a note on stderr): 0, or -1 with a->err. */
int sr_list(sr_args *a, const char *opt, const char *text, double lo, double hi, double **out,
            int *n);
/* Prints the help text of a subcommand (to stdout). */
void sr_help(const char *cmd);

/* Automatic normal-speed range of a map: [v_crit(dmax) / 1.5, 1.5 v_crit(dmin)].
 * The impacts of its searches are counted into pg (NULL: none). */
int sr_auto_vrange(const swr_model *m, swt_grid *g, int set_min, int set_max,
                   const swt_vcrit_opts *o, swt_progress *pg, char *err, size_t errlen);
/* Impacts of the automatic range's searches, for an estimate (each: a scan
 * and a bisection, o->points impacts an evaluation on a rough wall). */
double sr_auto_vrange_work(const swr_model *m, int set_min, int set_max, const swt_vcrit_opts *o);
/* The estimate of a run of `work` impacts (a pilot on grid g with o): printed
 * to stderr when at least a few seconds, and refused (-1, message in err)
 * when more than SR_LONG_RUN_S unless force. Returns 0 and *pg, the progress
 * report of the run (swt_progress_free it; NULL is fine). */
#define SR_LONG_RUN_S 3600.0
/* Impacts of v_crit searches for nd diameters (snowregime vcrit). */
double sr_vcrit_work(const swr_model *m, int nd, const swt_vcrit_opts *o);
int sr_estimate(const char *cmd, const swr_model *m, const swt_grid *g, const swt_vcrit_opts *o,
                double work, int threads, int force, swt_progress_mode mode, swt_progress **pg,
                char *err, size_t errlen);

/* "normal contact kept" / "full stick" / "full stick, at rest within S m" */
const char *sr_outcome_text(const swt_vcrit_opts *o, char *buf, size_t n);

int sr_cmd_collide(int argc, char **argv);
int sr_cmd_vcrit(int argc, char **argv);
int sr_cmd_map(int argc, char **argv);
int sr_cmd_sensitivity(int argc, char **argv);
int sr_cmd_convergence(int argc, char **argv);

#endif
