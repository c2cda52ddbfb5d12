/* swe_ladder.h - the wedge's runs against each other: a run's rung of the
 * resolution ladder (results/level.txt, the Strouhal number's resolution
 * error, the rows of the collector's table ladder.csv and their check), the
 * change between two resolutions with its standard error and z, and the
 * numbers of the error plots (awk's way of writing a number, the ranges).
 *
 * Every function takes const inputs, returns 0 or an SWE_E* code (swe_spray.h)
 * with a one-line message in err when err is given, and never exits. */
#ifndef SWE_LADDER_H
#define SWE_LADDER_H

#include <stddef.h>

/* the reference of the Strouhal number St = f H / U: the wedge's height H
   [m] and the tunnel's speed U [m/s] */
#define SWE_LADDER_H_M 0.12
#define SWE_LADDER_U_MS 19.444

/* the Strouhal number's error from the spectrum's resolution over the window
   [w0, w1] s: the peak is known to +- 1/(2W) in frequency (W = w1 - w0), a
   uniform error of standard deviation 1/(W sqrt(12)), times H / U */
double swe_ladder_st_error(double w0, double w1);

/* the scale of a kinematic pressure difference to a pressure coefficient:
   1 / (0.5 U^2) */
double swe_ladder_cp_scale(void);

/* ---- results/level.txt: "KEY VALUE..." lines --------------------------------- */

/* the value of KEY in the text of level.txt (its first line "KEY ..."; the
   fields after KEY joined by one blank) into out; SWE_EINVAL when absent */
int swe_ladder_key(const char *text, const char *key, char *out, size_t outlen);

/* ---- ladder.csv: the collector's table --------------------------------------- */

/* the header of the collector's table */
#define SWE_LADDER_HEADER "quantity,run,design,level,cells,step,value,se,t_flow,t_clouds"

/* is line (no newline) a row of the table: ten comma-separated fields, the
   level (4th) a whole number with an optional minus, the cells (5th) a whole
   number? 1 yes, 0 no */
int swe_ladder_row_ok(const char *line);

/* the field k (0-based) of a comma-separated line into out ("" beyond the last) */
void swe_ladder_field(const char *line, char sep, int k, char *out, size_t outlen);

/* ---- two resolutions of one quantity ---------------------------------------- */

typedef enum {
    SWE_CHANGE_NONE = 0, /* no deposit in either run (both <= 0) */
    SWE_CHANGE_ONE,      /* deposit in one run only, or no error to weigh it */
    SWE_CHANGE_AGREES,   /* |z| <= 2 */
    SWE_CHANGE_DIFFERS   /* |z| > 2 */
} swe_change_kind;

typedef struct {
    swe_change_kind kind;
    double change;    /* R / B - 1 */
    double se_change; /* its standard error, first order:
                         (R / B) sqrt((se_B / B)^2 + (se_R / R)^2), the second
                         term only for R > 0 */
    double z;         /* (R - B) / sqrt(se_B^2 + se_R^2) */
    double bound;     /* for agrees: |change| + 2 se_change, the largest change
                         the two runs allow at 2 standard errors */
} swe_change;

/* the change from the base b (standard error sb) to the refined r (sr) */
void swe_ladder_change(double b, double sb, double r, double sr, swe_change *out);

/* ---- numbers as awk writes them ---------------------------------------------- */

/* v written as awk converts a number to text: an integral value as a whole
   number, any other with "%.6g" */
void swe_ladder_awknum(double v, char *out, size_t outlen);

/* the ranges of a log-log error plot: x0 x1 y0 y1 from the points (x[i], y[i])
   and the targets (horizontal lines): x from half the least to twice the
   largest, y from the least / 1.5 to the largest x 1.5 (a least value <= 0
   taken as 1e-3); SWE_EINVAL without a point */
int swe_ladder_plot_range(const double *x, const double *y, size_t n, const double *targets,
                          size_t nt, double range[4], char *err, size_t errlen);

#endif
