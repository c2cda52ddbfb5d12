/* swt_io.h - input and plotting helpers of the regime tools.
 *
 * The outputs themselves are written by the common output writer (swo_out.h:
 * atomic output sets, the output-folder contract, comma lists).
 *
 * swt_parse_*: strict parsing of option values (whole string consumed, finite,
 * in range); errors are one line naming the option and the value.
 */
#ifndef SWT_IO_H
#define SWT_IO_H

#include <stddef.h>
#include <stdio.h>

#include "swo_out.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Parse a real number in [lo, hi]. 0, or -1 with "OPT: 'TEXT' is ..." in err. */
int swt_parse_double(const char *opt, const char *text, double lo, double hi,
                     double *out, char *err, size_t errlen);
/* Parse an integer in [lo, hi]. */
int swt_parse_int(const char *opt, const char *text, long lo, long hi, long *out,
                  char *err, size_t errlen);
/* Comma lists: swo_list_numbers() (swo_out.h). */

/* Run "gnuplot SCRIPT" in the folder DIR (NULL: the current one) and wait.
 * 0, or -1 with a message (gnuplot missing, failed, killed). Its stderr is
 * passed through. */
int swt_run_gnuplot(const char *dir, const char *script, char *err, size_t errlen);
/* A gnuplot script PNG.gp beside the PNG it draws (a temporary of its own,
 * never renamed): swt_gnuplot_open() creates it and writes the lines that
 * select pngcairo (or png when cairo is missing) with the given size and set
 * the output to `png` (a temporary path of an output set, swo_add); the caller writes the plot commands
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
