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

/* ---- map and sensitivity (sr_mapopt.c, sr_mapcompute.c, sr_mapout.c,
 * sr_mapplot.c) ---- */

/* Grid and map options shared by map and sensitivity. */
typedef struct {
    swt_grid g;
    int set_vmin, set_vmax;
    int degree, refine, plot;
    swt_vcrit_opts o;       /* outcome, tangential motion, tolerance */
    const char *out;
    int force;              /* --force: run even when estimated above SR_LONG_RUN_S, and
                               write into a non-empty folder that is not an output folder */
    swt_progress_mode progress; /* --progress: the progress line also off a terminal */
    swt_progress *pg;       /* the run's progress report (set by the command) */
} sr_mapopt;

/* Rough wall: the p = 0.1 and 0.9 contours beside the map's p = 0.5 interface. */
typedef struct {
    swt_interface lo, hi;   /* p = 0.1, p = 0.9 */
} sr_contours;

/* One computed map with its interface and fit. */
typedef struct {
    swt_map *mp;
    swt_interface it;
    sr_contours *contours;  /* rough wall only, else NULL */
    swt_fit fit;
    int fit_ok;
    char fit_err[300];
    double seconds_total;
} sr_mapres;

/* sr_mapopt.c: the defaults (46 x 50 grid, 10-100 um, automatic speeds,
 * degree 3, refined interface, plots). */
void sr_mapopt_default(sr_mapopt *m);
/* The grid and map options at argv[i]: 1 taken, 0 not mine, -1 error (a->err). */
int sr_mapopt_parse(sr_args *a, sr_mapopt *m);
/* --out given, the grid at most SR_MAX_CELLS cells, dmax > dmin, vmax > vmin:
 * 0, else -1 with a message. */
int sr_mapopt_check(sr_mapopt *m, char *err, size_t errlen);
/* Impacts of one map of mo on model m with options o (an estimate). */
double sr_map_work(const swr_model *m, const sr_mapopt *mo, const swt_vcrit_opts *o);
/* The grid of the pilot before the speed range is known. */
swt_grid sr_pilot_grid(const sr_mapopt *mo);

/* sr_mapcompute.c: one map of mo on model m with options o into r (its
 * interface, fit and on a rough wall its contours): 0, or -1 with a message;
 * sr_mapres_free r either way. */
int sr_map_compute(const swr_model *m, const sr_mapopt *mo, const swt_vcrit_opts *o, int threads,
                   sr_mapres *r, char *err, size_t errlen);
/* The contours p = 0.1 and 0.9 of r's rough-wall map into c. */
int sr_map_contours(const swr_model *m, const sr_mapres *r, const swt_vcrit_opts *o, int threads,
                    sr_contours *c, char *err, size_t errlen);
void sr_mapres_free(sr_mapres *r);

/* sr_mapout.c: one map's files into the set (names with suffix sfx: map.csv,
 * interface.csv, fit.txt, regime.coeffs when fitted, contours.csv on a rough
 * wall, the plot when plot); what: the map's description. */
int sr_map_write_files(swo_set *os, const char *sfx, const sr_mapres *r, const swr_params *p,
                       const char *what, int plot, int threads, char *err, size_t errlen);
/* Every file name of the maps (one per --vt / --angle value of axis, or one
 * map when axis is NULL) checked in the set before the work. */
int sr_map_check_names(swo_set *os, const double *axis, int naxis, int axis_angle, char *err,
                       size_t errlen);

/* sr_mapplot.c: the map plot (stick/bounce, interface, fit) and the rough
 * wall's (stick probability, contours) of one map into the set; the
 * sensitivity plot. 0, or -1 with a message. */
int sr_map_plot(swo_set *os, const char *sfx, const sr_mapres *r, const char *title, char *err,
                size_t errlen);
int sr_map_plot_rough(swo_set *os, const char *sfx, const sr_mapres *r, const char *title,
                      char *err, size_t errlen);
int sr_plot_sensitivity(const char *png, const char *tdata, const swt_grid *g, int n,
                        const char keys[][16], const double *vals, char *err, size_t errlen);

int sr_cmd_collide(int argc, char **argv);
int sr_cmd_vcrit(int argc, char **argv);
int sr_cmd_map(int argc, char **argv);
int sr_cmd_sensitivity(int argc, char **argv);
int sr_cmd_convergence(int argc, char **argv);

#endif
