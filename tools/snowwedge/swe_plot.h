/* swe_plot.h - the picture of rear-face deposit maps side by side on one
 * colour scale: the gnuplot script (panel layout, figure size, titles wrapped
 * to the width they have, quoted so that no title or file name can end a
 * gnuplot string) for tutorials/wedge/post/wedge-panels and wedge-compare.
 *
 * Layout: n panels of 460 px in a row, the figure 120 + 460 n px wide and
 * 560 px high, 18 px more for each title line beyond two. Titles are wrapped
 * at word boundaries as fold -s -w W does (about 7.5 px a character at 11 pt):
 * the figure's title at W = (width - 40) 2 / 15 characters, a panel's at 58; a
 * literal backslash-n or a newline starts a new line. With one panel its title
 * is the figure title's last lines. The colour scale runs from 0 to the
 * largest deposit (0 .. 1 when nothing is positive); the axes span the first
 * map's outline with 5 mm to spare. Nothing here prints or exits. */
#ifndef SWE_PLOT_H
#define SWE_PLOT_H

#include <stddef.h>
#include <stdio.h>

/* the figure: its title and, per panel, a map (CSV y,z,deposit_kg_m2 with a
   header line) and its title */
typedef struct {
    const char *title;
    int n;                     /* panels, at least 1 */
    const char *const *maps;
    const char *const *titles;
    double vmax;               /* the largest deposit of all maps */
    double outline[4];         /* y0 y1 z0 z1 of the first map */
} swe_plot_panels;

/* TEXT wrapped at WIDTH characters as `fold -s -w WIDTH` wraps it after each
   literal "\n" became a newline, blanks at line ends removed: the lines joined
   by '\n' (malloc'd, the caller frees) and their count in *nlines; NULL when
   out of memory. */
char *swe_plot_wrap(const char *text, int width, int *nlines);

/* the figure's size in pixels for its title lines: width 120 + 460 n, height
   560 + 18 (lines - 2) when more than two lines (the title lines, plus one for
   the panels' titles when there are several panels) */
void swe_plot_size(int n, int title_lines, int *width, int *height);

/* the gnuplot script of the figure into PNG (pngcairo); 0, or -1 with a
   message in err (out of memory, no panel, or a newline in a file name) */
int swe_plot_script(FILE *out, const swe_plot_panels *p, const char *png, char *err,
                    size_t errlen);

/* the largest value (third column) of the rows after the header of the maps
   (0 when none is positive; rows that are not three numbers are skipped); 0,
   or -1 with the unreadable map's path in err */
int swe_plot_map_max(const char *const *maps, int n, double *vmax, char *err, size_t errlen);

/* the picture of the rear face's blocks (swe_blocks.h): two panels, the
   deposit per block on the colour scale 0 .. vmax (blocks without a record, or
   whose relative error exceeds twice the target, in grey: no value shown) and
   each block's relative error (1 sigma, per cent, on 0 .. 100 %), written in
   the block when nb <= 8; the figure as two panels of swe_plot_size. The
   blocks: a CSV with the columns y0,y1,z0,z1,deposit_kg_m2,rel_error,records
   after '#' lines and one header line. */
typedef struct {
    const char *title;  /* the figure's */
    const char *csv;    /* the blocks */
    int nb;             /* blocks across */
    double target;      /* the target error (a fraction) */
    double rms;         /* the deposit-weighted rms error */
    double vmax;        /* the largest block deposit */
    double outline[4];  /* y0 y1 z0 z1 */
} swe_plot_blocks;

/* the gnuplot script of the blocks' picture into PNG; 0, or -1 with a message
   in err (out of memory, a newline in a file name, a write error) */
int swe_plot_blocks_script(FILE *out, const swe_plot_blocks *p, const char *png, char *err,
                           size_t errlen);

#endif
