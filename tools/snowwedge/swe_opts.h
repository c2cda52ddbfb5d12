/* swe_opts.h - the command line of tutorials/wedge/Allrun: its options read and
 * checked (every refusal one line, the texts Allrun has always printed), the
 * cross-checks between them (the transient route's options, -rear-layers, the
 * dispersion treatments, -parallel against the processors), the variant's block
 * of constant/variants, and the result written as shell assignments whose values
 * are quoted so that no value can run as code. Defined in swe_opts.c; every
 * function returns 0 or a non-zero code (1 an unreadable file, 2 a refused
 * option) with a one-line message in err; none exits. */
#ifndef SWE_OPTS_H
#define SWE_OPTS_H

#include <stddef.h>
#include <stdio.h>

/* the value of KEY in the block BLOCK of a variants file (comments after // removed,
   the trailing ';' and the double quotes removed): 0 and out, 1 when absent or empty,
   -1 when the file cannot be read */
int swe_opts_variant(const char *path, const char *block, const char *key, char *out, size_t n);

/* the value of KEY in a file of "KEY VALUE;" lines (comments after // removed): the
   first line that is KEY, blanks, VALUE up to its last ';', blanks. 0 and out, 1 when
   absent, -1 when the file cannot be read */
int swe_opts_entry(const char *path, const char *key, char *out, size_t n);

/* VALUE as one shell word between single quotes (a ' as '\'') */
void swe_opts_quote(FILE *out, const char *value);

/* the comma-separated list TEXT of option OPT (num: numbers, put in ascending order;
   otherwise names, in their order) checked: no empty list or item, no item twice.
   0 and the list in out (a note on notes when it was reordered), or 2 and err */
int swe_opts_list(const char *opt, const char *text, int num, char *out, size_t n, FILE *notes, char *err,
                  size_t nerr);

/* an entry of constant/sprayProperties as foamDictionary -value printed it, checked:
   KIND "num" a positive number (as written); "list2" two positive numbers, the first
   the smaller, and "intlist" whole numbers from 1 (at most 7 digits), both with the
   parentheses removed and the blanks collapsed (intlist then comma-separated).
   0 and the value in out, or 2 and err naming KEY and the value */
int swe_opts_spray_entry(const char *file, const char *kind, const char *key, const char *value, char *out, size_t n,
                         char *err, size_t nerr);

#define SWE_OPTS_TEXT 4096
typedef struct {
    int help;                    /* --help met: nothing else set */
    int resume;                  /* -resume: the options read from log.Allrun.args */
    int nargs;                   /* the options as -resume will read them (-ladder's file absolute) */
    char **args;
    char nproc_run[8], mesh_level[4], level[8], route[10], gate[12], checkpoint[64];
    char parcels[4];             /* -parcels K: the size classes' parcels x K (1 .. 99) */
    int oversubscribe, compare, split, feedback, rebound, rough, replay, wake_source, full, halfstep;
    int refine_wake, estimate, rear_layers, sizes_given, ladder_given, mpi_oversubscribe;
    char sizes[SWE_OPTS_TEXT], dispersions[SWE_OPTS_TEXT], disp_main[64], disp_extra[SWE_OPTS_TEXT];
    char ladder[SWE_OPTS_TEXT];
    /* the variant's block of constant/variants ("" when absent: the optional times) */
    long ny;                     /* the mesh's cells along y */
    char level_scale[32];        /* the step scale of -level, sqrt(2)^-N */
    char mesh[256], parcel_factor[64], class_factor[64], steady_factor[64], rough_grid[256];
    char spin[64], fill[64], sample[64], replay_start[64], replay_period[64];
    /* constant/gates/regime's slideLength and vtTable (comma-separated); the transient
       route's maxDeltaT (system/controlDict.transient, -halfstep 5e-4) */
    char slide[64], vtlist[1024], max_delta_t[64];
} swe_allrun;

/* ARGV (NARGS words) as Allrun's options, in the case folder CASE_DIR (its
   log.Allrun.args when the only option is -resume, constant/variants; a relative
   -ladder path made absolute from CASE_DIR as `cd DIR && pwd` does) on a machine
   of NCPU processors; notes (a reordered -sizes) on notes. Free with
   swe_opts_free also after an error. */
int swe_opts_parse(int nargs, char *const *argv, const char *case_dir, long ncpu, swe_allrun *o, FILE *notes,
                   char *err, size_t nerr);
/* the assignments Allrun evaluates (one a line; args_given, mpi_opts and est, the
   estimate's arguments that come from the options, as arrays) */
void swe_opts_write(FILE *out, const swe_allrun *o);
void swe_opts_free(swe_allrun *o);

/* the commands snowwedge allrun-options and spray-entry (swe_cmd_opts.c): their exit status */
int swe_cmd_opts(int argc, char **argv);
int swe_cmd_spray_entry(int argc, char **argv);

#endif
