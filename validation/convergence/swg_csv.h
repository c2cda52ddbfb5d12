/* swg_csv.h - the plain CSV fields of the ladder tables (snowgci, snowladder):
 * a line split at commas into trimmed fields (no quoting: a name holds no
 * comma), strict decimal numbers. */
#ifndef SWG_CSV_H
#define SWG_CSV_H

#define SWG_CSV_MAX_COLS 64

/* s without leading and trailing white space (s is changed in place). */
char *swg_csv_trim(char *s);
/* Split s in place at commas into at most SWG_CSV_MAX_COLS trimmed fields in
 * f; the count, or -1 when there are more. */
int swg_csv_split(char *s, char **f);
/* A finite decimal number filling all of s (no hexadecimal, nan or inf):
 * 1 with *v set, else 0. */
int swg_csv_number(const char *s, double *v);
/* A copy of s (malloc), or NULL. */
char *swg_csv_dup(const char *s);

#endif
