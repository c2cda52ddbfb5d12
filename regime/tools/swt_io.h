/* swt_io.h - output and input helpers of the regime tools.
 *
 * swt_outset: a set of output files that appear together or not at all.
 * Every file is first written to a temporary name in its own folder
 * (".tmp-<name>") and renamed only by swt_outset_commit(); swt_outset_abort()
 * removes the temporaries and, when the set created the output folder, the
 * folder itself, so a failed run never leaves half an output behind.
 *
 * swt_parse_*: strict parsing of option values (whole string consumed, finite,
 * in range); errors are one line naming the option and the value.
 */
#ifndef SWT_IO_H
#define SWT_IO_H

#include <stddef.h>
#include <stdio.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef struct swt_outset swt_outset;

/* A set of outputs in folder dir (created, with parents, when missing), or,
 * with dir NULL, of files given by their own paths. NULL + err on failure. */
swt_outset *swt_outset_alloc(const char *dir, char *err, size_t errlen);
/* Register output `name` (a file name inside dir, or a path when dir is NULL)
 * and return its temporary path (valid until the set is freed), or NULL. */
const char *swt_outset_add(swt_outset *o, const char *name, char *err, size_t errlen);
/* swt_outset_add() and fopen(tmp, "w"): the stream is closed by commit/abort. */
FILE *swt_outset_open(swt_outset *o, const char *name, char *err, size_t errlen);
/* Final path of a registered name (dir/name). */
const char *swt_outset_final(const swt_outset *o, const char *name);
/* Close every stream (checking write errors) and rename every temporary to
 * its final name. On failure the set is aborted and -1 returned. */
int swt_outset_commit(swt_outset *o, char *err, size_t errlen);
/* Remove every temporary (and the folder when this set created it). */
void swt_outset_abort(swt_outset *o);
/* Free; aborts first when neither commit nor abort was called. */
void swt_outset_free(swt_outset *o);

/* Parse a real number in [lo, hi]. 0, or -1 with "OPT: 'TEXT' is ..." in err. */
int swt_parse_double(const char *opt, const char *text, double lo, double hi,
                     double *out, char *err, size_t errlen);
/* Parse an integer in [lo, hi]. */
int swt_parse_int(const char *opt, const char *text, long lo, long hi, long *out,
                  char *err, size_t errlen);
/* Parse a comma-separated list of reals in [lo, hi] into a new array (free()
 * it); *n receives the count (>= 1). */
int swt_parse_list(const char *opt, const char *text, double lo, double hi,
                   double **out, int *n, char *err, size_t errlen);

/* Run "gnuplot SCRIPT" in the folder DIR (NULL: the current one) and wait.
 * 0, or -1 with a message (gnuplot missing, failed, killed). Its stderr is
 * passed through. */
int swt_run_gnuplot(const char *dir, const char *script, char *err, size_t errlen);
/* A gnuplot script PNG.gp beside the PNG it draws (a temporary of its own,
 * never renamed): swt_gnuplot_open() creates it and writes the lines that
 * select pngcairo (or png when cairo is missing) with the given size and set
 * the output to `png` (a temporary path); the caller writes the plot commands
 * to g->f; swt_gnuplot_finish() closes it, runs gnuplot and removes it.
 * Both return 0, or -1 with a message.
 * No user text reaches the script: gnuplot runs in the folder of the PNG and
 * the script names every file by its own name there (swt_gp_name: the part
 * after the last '/', the output set's fixed names), so a folder name with
 * quotes or gnuplot commands in it is only ever a path given to chdir. */
typedef struct {
    FILE *f;
    char path[4200];
    char dir[4200];
} swt_gnuplot;
/* The file name of `path` for a gnuplot script: the part after the last '/'. */
const char *swt_gp_name(const char *path);
int swt_gnuplot_open(swt_gnuplot *g, const char *png, int width, int height,
                     char *err, size_t errlen);
int swt_gnuplot_finish(swt_gnuplot *g, char *err, size_t errlen);

/* Monotonic wall clock [s]. */
double swt_now(void);
/* CPU time of the calling thread [s]. */
double swt_thread_cpu(void);

#ifdef __cplusplus
}
#endif
#endif
