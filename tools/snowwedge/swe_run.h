/* swe_run.h - the numbers tutorials/wedge/Allrun computes or formats: the cost
 * estimate of a run's options, the mesh of a rung of the resolution ladder, the
 * coneInjection dictionaries of the nozzles, the manual decomposition into slabs
 * along y, the rung's record (results/level.txt), the rear face's y+ summary,
 * the joining of the logs and tables of a resumed run, and the total-error
 * table against a resolution ladder (results/total_error.md). Defined in
 * swe_run.c (the set-up and the rung's record), swe_resume.c (a resumed run)
 * and swe_total.c (the total error). Every function returns 0 or a non-zero
 * code with a one-line message in err; none exits. */
#ifndef SWE_RUN_H
#define SWE_RUN_H

#include <stddef.h>
#include <stdio.h>

/* ---- the mesh of the variant (system/meshSize: "KEY N; KEY N; ...") ---------------- */
#define SWE_MESH_MAX 16
typedef struct {
    int n;
    char key[SWE_MESH_MAX][32];
    long val[SWE_MESH_MAX];
} swe_mesh;

int swe_mesh_parse(const char *text, swe_mesh *m, char *err, size_t nerr);
long swe_mesh_get(const swe_mesh *m, const char *key); /* -1: absent */
/* every count x sqrt(2)^level rounded half up (at least 1); with refine_wake
   nxDown and nBody x 1.25 rounded (after the level) */
void swe_mesh_scale(swe_mesh *m, int level, int refine_wake);
/* "nxUp 20; nxBody 8; ..." (the keys in their order, one blank after each ';') */
void swe_mesh_format(const swe_mesh *m, char *out, size_t n);
/* the block mesh's cells (3 x 3 x 3 blocks less the body) and cells along y */
double swe_mesh_cells(const swe_mesh *m);
long swe_mesh_ny(const swe_mesh *m);
/* the step scale of a level, sqrt(2)^-level (even: 2^(-level/2) exactly) */
double swe_level_scale(int level);

/* ---- the case's spray and size classes (constant/sprayProperties) -------------------- */
/* 2 with err unless mvd in [0.1, 1000] um, sigma_g in (1, 10], freeze in [0.5, 2] and
   the range within [0.1, 10000] um (the texts as the dictionary gives them, for err) */
int swe_check_spray(const char *mvd, const char *sigma_g, const char *freeze, const char *range_lo,
                    const char *range_hi, char *err, size_t nerr);
/* 2 with err unless as many parcel counts as sizes, every size at most 1000 um and
   each once (the lists as comma-separated text) */
int swe_check_classes(const char *sizes, const char *parcels, char *err, size_t nerr);

/* ---- the cost estimate ------------------------------------------------------------- */
typedef struct {
    int steady;                     /* the steady route: cells, parcels, memory, disk only */
    double cells0, nbody;           /* the block mesh's cells, nBody */
    int nozzles;
    double ppn, ppn_factor;         /* the spray's parcels per nozzle and the variant's factor */
    const double *class_ppn;        /* per class, parcels per nozzle (before class_factor) */
    int nclasses;
    double class_factor;
    int compare, feedback, rough, rebound, split, full, halfstep, rear_layers, replay;
    int ndisp;                      /* dispersion treatments (the main one included) */
    int nwake;                      /* wake-source classes */
    double spin, fill, sample;      /* s */
    double replay_start, replay_period, replay_interval; /* the interval already level-scaled */
    int np;                         /* processes */
    double avail, free_disk;        /* bytes; < 0: unknown */
} swe_estimate_in;

typedef struct {
    double cells, steps, flow_steps, parcels, class_parcels;
    int clouds;
    double mem_flow, lib, mem_parcels, disk_fields, disk_parcels;
    double t_flow, t_parcels;       /* s */
    int streamed;                   /* the library above 80 % of avail: streamed from disk */
} swe_estimate_out;

/* the model (doc/reference/wedge-Allrun.md, "The estimate"); returns 0 */
int swe_estimate(const swe_estimate_in *in, swe_estimate_out *out);
/* the one line "Allrun: estimate: ..." */
void swe_estimate_print(FILE *f, const swe_estimate_in *in, const swe_estimate_out *out);
/* 2: the flow and library exceed the memory, or the fields the disk (msg: the
   refusal, one line); 0 otherwise */
int swe_estimate_refuse(const swe_estimate_in *in, const swe_estimate_out *out, char *msg, size_t n);

/* ---- the transient route's times ------------------------------------------------------
 * The inputs as the case gives them (text, copied where a file shows them); the
 * outputs as text with the precision Allrun's dictionaries and logs have always had. */
typedef struct {
    const char *spin, *fill, *sample, *class_factor, *rate, *build_up;
    const char *replay_start, *replay_period, *replay_interval; /* NULL: no replay */
    const char *level_scale, *checkpoint_min;                   /* "off": no checkpoint */
    int level, full, halfstep;
} swe_times_in;

typedef struct {
    char class_factor[32], sample[32];           /* -full: 4 x the rate, twice the window */
    char t0[32], th[32], t1[32], write[32];       /* the window, its middle, the writes */
    char soi[32], mass_total[32], duration[32];   /* constant/sprayDerived */
    char replay_interval[32];                     /* level-scaled: a whole fraction of the period */
    char step_scale[32], max_delta_t[32], delta_t[32], checkpoint_s[32];
    char sampled[32], library_end[32];
} swe_times_out;

/* 2 with err: spinUpTime + fillTime not a whole multiple of half the window, or the
   replay period not a whole multiple (at least 2) of its interval, or the library
   ending after the run */
int swe_times(const swe_times_in *in, swe_times_out *out, char *err, size_t nerr);

/* ---- the progress line while the solver runs ---------------------------------------------
 * "Allrun [A s]: solver at t = T of TE s (P %), E s elapsed, ...": the time left at
 * the rate of the current phase since its first reading (time ts, es seconds ago);
 * in the flow phase of a replayed run (t_flow >= 0) the time left to t_flow only */
void swe_progress_line(char *s, size_t n, double t, double t_end, double t_flow, int replay_phase,
                       double ts, long elapsed, long phase_elapsed, long allrun);
/* the time of a solver log's last step: the third field of its last line beginning
   "Time = " (out "" when there is none yet); 0, or 1 when LOG cannot be read */
int swe_last_time(const char *path, char *out, size_t n);

/* ---- the nozzles' coneInjection dictionaries ------------------------------------------ */
/* the points "x y z" of a nozzleArray file (// comments and parentheses removed;
   lines of three numbers, their text kept); returns the count, -1 unreadable */
int swe_nozzle_points(const char *path, char (**pts)[128], char *err, size_t nerr);
/* the 9 wake-source points: x 0.36, y, z = -0.04, 0, 0.04 m + 0.1 mm */
int swe_wake_points(char (**pts)[128]);
/* one coneInjection per point: soi, mass_total, duration as in sprayDerived;
   size_um <= 0: the spray's table (#include "sprayDistribution"); speed: the
   nozzles' Umag as written (NULL: the wedge's tunnel speed, 19.444 m/s) */
void swe_nozzles_write(FILE *f, char (*pts)[128], int np, long parcels, const char *soi,
                       double mass_total, const char *duration, double size_um, int wake, const char *speed);

/* ---- the decomposition into slabs along y --------------------------------------------- */
/* proc[i] of cell i: the cells up to the first layer of centres downstream of
   x_nozzle first, then by y; cut into nproc equal counts. x, y are the centres
   as printed to 6 significant digits. Returns 0, or 2 (no cell downstream) */
int swe_decompose(const double *x, const double *y, size_t nc, int nproc, double x_nozzle,
                  int *proc, char *err, size_t nerr);

/* ---- the rung's record (results/level.txt) from the solver's log ---------------------- */
typedef struct {
    const char *level, *variant, *refine_wake, *halfstep, *full, *step_scale, *cells;
    const char *max_delta_t, *replay_interval, *gate, *mvd, *rear_layers, *rear_yplus;
    const char *window0, *window1;  /* the sampling window, as given */
    double t0, t1;                  /* the same as numbers */
} swe_level_in;
/* 2 with err: no 'Wall time' line with a flow entry, or no step in the window */
int swe_level_write(FILE *log, const swe_level_in *in, FILE *out, char *err, size_t nerr);

/* the rear patch's first-cell y+ of yPlus.dat tables: least minimum, mean of the
   averages, largest maximum; returns the rows read */
int swe_yplus_rear(FILE *const *tables, int n, double *mn, double *mean, double *mx);

/* ---- a resumed run's logs and tables -------------------------------------------------- */
/* the parts of a solver log as one run's: every part up to the start of the next
   that has a step (its first time less its deltaT), the 'Wall time' entries of a
   later part offset by the earlier parts' last values at their cut */
int swe_join_logs(FILE *const *parts, int n, FILE *out, char *err, size_t nerr);
/* a function object's table: BASE's header and rows up to t, then NEW's rows */
int swe_join_table(FILE *base, FILE *add, double t, FILE *out);

/* the latest time folder after 0 written whole in case_dir (nproc 1) or in each of its
   processor0..N-1: uniform/time and the flow fields U p k omega nut non-empty. t is
   "" when there is none; 2 with err when a processor folder is missing */
int swe_resume_time(const char *case_dir, int nproc, char *t, size_t n, char *err, size_t nerr);

/* the tables a restart at time t began: for every folder NAME of dir (postProcessing,
   but its lagrangian records) holding NAME/t, the files of NAME/t that its first
   time folder holds too. SWE_TABLES_LIST prints "FIRST NEW" lines to out,
   SWE_TABLES_REMOVE removes each NEW, SWE_TABLES_JOIN joins NEW into FIRST
   (swe_join_table), removes it and then every empty NAME/t */
enum { SWE_TABLES_LIST, SWE_TABLES_REMOVE, SWE_TABLES_JOIN };
int swe_restart_tables(const char *dir, const char *t, int mode, FILE *out, char *err, size_t nerr);
/* -resume in the case folder (the working directory): the solver SOLVER started again
   from time t (system/controlDict's startFrom and startTime lines set, the interrupted
   log.SOLVER kept as log.SOLVER.partK, K the first free, the tables an earlier resume
   from t began removed from postProcessing, t appended to log.Allrun.resumes); and the
   run's parts joined (log.SOLVER.part1.. and log.SOLVER as one log, the tables of
   postProcessing of every time of log.Allrun.resumes). msg: the line Allrun logs */
int swe_resume_start(const char *solver, const char *t, char *msg, size_t nmsg, char *err, size_t nerr);
int swe_resume_join(const char *solver, char *msg, size_t nmsg, char *err, size_t nerr);

/* ---- the total error against a resolution ladder (results/total_error.md) -------------- */
/* why the run is not on the ladder (settings "KEY VALUE" against the ladder's
   '# setting' lines, the level and its cells against its rows); "" if it is */
int swe_ladder_why(FILE *ladder, const char *const *settings, int nset, const char *level,
                   const char *cells, char *why, size_t n);
/* the '# note' lines of a ladder as a markdown section (nothing when none) */
void swe_ladder_notes(FILE *ladder, FILE *out);
/* the table from snowladder's total_error.csv (rows of the run NAME) */
int swe_total_error_table(FILE *csv, const char *run, const char *mvd, const char *ladder,
                          const char *level, const char *cells, FILE *out);

#endif
