/* swg_table.h - the resolution-ladder table of snowgci: a CSV file with a
 * header naming the columns quantity, level, h or cells, value, se (any order,
 * more columns ignored), one row per quantity and level (doc/convergence.md). */
#ifndef SWG_TABLE_H
#define SWG_TABLE_H

#include <stddef.h>
#include <stdio.h>

typedef struct {
    char *label;  /* the level's name */
    double size;  /* h, or the cell count when the table has a cells column */
    double value; /* the quantity on this level */
    double se;    /* its standard error */
    int line;     /* the line it came from */
} swg_row;

typedef struct {
    char *name;
    swg_row *rows;
    size_t n, cap;
} swg_quantity;

typedef struct {
    swg_quantity *q;
    size_t n, cap;
    int has_cells; /* the size column is cells (else h) */
} swg_table;

/* Read the table from f (fname names it in messages). Refuses, with a one-line
 * message naming the file, the line and the value: a missing or duplicate column,
 * both h and cells, a row with another number of fields, an empty name, a value
 * that is not a finite decimal number, h <= 0 or cells < 1, a negative standard
 * error, |value| or se above 1e100, a level named twice in a quantity, no rows.
 * Returns 0, or 1 with err set (the table freed). */
int swg_table_read(FILE *f, const char *fname, swg_table *t, char *err, size_t errlen);
void swg_table_free(swg_table *t);

#endif
