/* swe_plot.c - the gnuplot script of rear-face deposit maps side by side
 * (swe_plot.h). */
#include "swe_plot.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* a growing string */
typedef struct {
    char *s;
    size_t len, cap;
    int bad;
} buf;

static void put(buf *b, const char *s, size_t n)
{
    if (b->bad)
        return;
    if (b->len + n + 1 > b->cap) {
        size_t cap = b->cap ? 2 * b->cap : 256;
        while (cap < b->len + n + 1)
            cap *= 2;
        char *t = realloc(b->s, cap);
        if (!t) {
            b->bad = 1;
            return;
        }
        b->s = t, b->cap = cap;
    }
    memcpy(b->s + b->len, s, n);
    b->len += n;
    b->s[b->len] = '\0';
}

/* a line of the wrapped text: without its trailing blanks (spaces only) */
static void emit(buf *b, const char *s, size_t n, int *nlines)
{
    while (n && s[n - 1] == ' ')
        n--;
    if (*nlines)
        put(b, "\n", 1);
    put(b, s, n);
    ++*nlines;
}

/* the column after character c (fold's rule: a backspace steps back, a carriage
   return to 0, a tab to the next multiple of 8, anything else one byte on) */
static size_t column_after(size_t col, char c)
{
    if (c == '\b')
        return col ? col - 1 : 0;
    if (c == '\r')
        return 0;
    if (c == '\t')
        return col + 8 - col % 8;
    return col + 1;
}

/* one input line (no newline in it) folded at width w, breaking after the last
   blank that keeps a line within w, else at w; a character wider than the
   width stands alone */
static void fold_line(buf *b, const char *s, size_t len, size_t w, int *nlines)
{
    char *line = malloc(len + 1);
    if (!line) {
        b->bad = 1;
        return;
    }
    size_t off = 0, col = 0;
    for (size_t i = 0; i < len; i++) {
        const char c = s[i];
        for (;;) {
            col = column_after(col, c);
            if (col <= w)
                break;
            size_t end = off;
            int blank = 0;
            while (end && !blank) {
                --end;
                blank = line[end] == ' ' || line[end] == '\t';
            }
            if (blank) {
                end++;
                emit(b, line, end, nlines);
                memmove(line, line + end, off - end);
                off -= end;
                col = 0;
                for (size_t k = 0; k < off; k++)
                    col = column_after(col, line[k]);
                continue;
            }
            if (off == 0)
                break;
            emit(b, line, off, nlines);
            off = col = 0;
        }
        line[off++] = c;
    }
    emit(b, line, off, nlines);
    free(line);
}

char *swe_plot_wrap(const char *text, int width, int *nlines)
{
    buf b = {0};
    *nlines = 0;
    const size_t w = width > 0 ? (size_t)width : 1;
    const char *p = text;
    for (;;) {
        /* the line up to a literal backslash-n or a newline */
        size_t n = 0;
        while (p[n] && p[n] != '\n' && !(p[n] == '\\' && p[n + 1] == 'n'))
            n++;
        fold_line(&b, p, n, w, nlines);
        if (!p[n])
            break;
        p += n + (p[n] == '\n' ? 1 : 2);
    }
    if (b.bad || !b.s) {
        free(b.s);
        return NULL;
    }
    return b.s;
}

void swe_plot_size(int n, int title_lines, int *width, int *height)
{
    *width = 120 + 460 * n;
    *height = 560 + 18 * (title_lines > 2 ? title_lines - 2 : 0);
}

/* the wrapped lines as one gnuplot double-quoted string: "\n" between lines,
   a backslash and a double quote escaped, a backquote (gnuplot's command
   substitution, done inside double quotes) written as its octal escape */
static void put_dq(buf *b, const char *lines)
{
    put(b, "\"", 1);
    for (const char *c = lines; *c; c++) {
        if (*c == '\n')
            put(b, "\\n", 2);
        else if (*c == '\\' || *c == '"') {
            put(b, "\\", 1);
            put(b, c, 1);
        } else if (*c == '`')
            put(b, "\\140", 4);
        else
            put(b, c, 1);
    }
    put(b, "\"", 1);
}

/* a file name as a gnuplot single-quoted string (a quote doubled; a name
   gnuplot would take for a pipe '<...', standard input '-', the pseudo-files
   '+' and '++' or a data block '$...' read as ./NAME); -1 for a newline */
static int put_sq(buf *b, const char *path)
{
    if (strchr(path, '\n'))
        return -1;
    put(b, "'", 1);
    if (path[0] == '<' || path[0] == '$' || !strcmp(path, "-") || !strcmp(path, "+") ||
        !strcmp(path, "++"))
        put(b, "./", 2);
    for (const char *c = path; *c; c++)
        put(b, *c == '\'' ? "''" : c, *c == '\'' ? 2 : 1);
    put(b, "'", 1);
    return 0;
}

static void putf(buf *b, const char *fmt, double v)
{
    char t[64];
    const int n = snprintf(t, sizeof t, fmt, v);
    put(b, t, (size_t)n);
}

#define PUT(b, s) put(b, s, strlen(s))

int swe_plot_script(FILE *out, const swe_plot_panels *p, const char *png, char *err,
                    size_t errlen)
{
    if (p->n < 1) {
        snprintf(err, errlen, "no map to plot");
        return -1;
    }
    const int n = p->n;
    int width, height, lines, k;
    swe_plot_size(n, 0, &width, &height);
    char *title, **pt = calloc((size_t)n, sizeof *pt);
    if (!pt) {
        snprintf(err, errlen, "out of memory");
        return -1;
    }
    int bad = 0, newline = 0;
    if (n > 1) {
        title = swe_plot_wrap(p->title, (width - 40) * 2 / 15, &lines);
        lines += 1; /* the panels' titles */
        for (int i = 0; i < n; i++)
            bad |= !(pt[i] = swe_plot_wrap(p->titles[i], 58, &k));
    } else {
        const size_t len = strlen(p->title) + strlen(p->titles[0]) + 3;
        char *both = malloc(len);
        if (both)
            snprintf(both, len, "%s\\n%s", p->title, p->titles[0]);
        title = both ? swe_plot_wrap(both, (width - 40) * 2 / 15, &lines) : NULL;
        free(both);
    }
    bad |= !title;
    swe_plot_size(n, lines, &width, &height);
    const double *o = p->outline;
    buf b = {0};
    char t[128];
    snprintf(t, sizeof t, "set terminal pngcairo size %d,%d font 'DejaVu Sans,11'\nset output ",
             width, height);
    PUT(&b, t);
    newline |= put_sq(&b, png) < 0;
    if (n > 1) {
        snprintf(t, sizeof t, "\nset multiplot layout 1,%d title ", n);
        PUT(&b, t);
    } else {
        PUT(&b, "\nset title ");
    }
    if (title)
        put_dq(&b, title);
    PUT(&b, "\nset size ratio -1\nset xrange [");
    putf(&b, "%.6g", o[0]), PUT(&b, "-0.005:"), putf(&b, "%.6g", o[1]);
    PUT(&b, "+0.005]; set yrange [");
    putf(&b, "%.6g", o[2]), PUT(&b, "-0.005:"), putf(&b, "%.6g", o[3]);
    PUT(&b, "+0.005]\nset cbrange [0:");
    putf(&b, "%.6g", p->vmax > 0 ? p->vmax : 1);
    PUT(&b, "]\nset cblabel 'deposit [kg/m^2]'\n"
            "set palette defined (0 '#f7fbff', 0.15 '#c6dbef', 0.4 '#6baed6', 0.7 '#2171b5', "
            "1 '#08306b')\nset xlabel 'y [m] (right = +y)'; set ylabel 'z [m]'\n"
            "set datafile separator ','\nset object 1 rectangle from ");
    putf(&b, "%.6g", o[0]), PUT(&b, ","), putf(&b, "%.6g", o[2]), PUT(&b, " to ");
    putf(&b, "%.6g", o[1]), PUT(&b, ","), putf(&b, "%.6g", o[3]);
    PUT(&b, " front fillstyle empty border lc rgb 'black' lw 2\n");
    for (int i = 0; i < n; i++) {
        if (n > 1 && pt[i]) {
            PUT(&b, "set title ");
            put_dq(&b, pt[i]);
            PUT(&b, "\n");
        }
        PUT(&b, "plot ");
        newline |= put_sq(&b, p->maps[i]) < 0;
        PUT(&b, " every ::1 using 1:2:3 with image notitle\n");
    }
    if (n > 1)
        PUT(&b, "unset multiplot\n");
    for (int i = 0; i < n; i++)
        free(pt[i]);
    free(pt);
    free(title);
    int rc = 0;
    if (bad || b.bad || newline) {
        snprintf(err, errlen, newline ? "a file name holds a newline" : "out of memory");
        rc = -1;
    } else if (fwrite(b.s, 1, b.len, out) != b.len) {
        snprintf(err, errlen, "cannot write the script");
        rc = -1;
    }
    free(b.s);
    return rc;
}

int swe_plot_map_max(const char *const *maps, int n, double *vmax, char *err, size_t errlen)
{
    double m = 0;
    for (int k = 0; k < n; k++) {
        FILE *f = fopen(maps[k], "r");
        if (!f) {
            snprintf(err, errlen, "%s", maps[k]);
            return -1;
        }
        char line[512];
        double y, z, v;
        for (int ln = 0; fgets(line, sizeof line, f); ln++)
            if (ln && sscanf(line, "%lf,%lf,%lf", &y, &z, &v) == 3 && v > m)
                m = v;
        fclose(f);
    }
    *vmax = m;
    return 0;
}

int swe_plot_blocks_script(FILE *out, const swe_plot_blocks *p, const char *png, char *err,
                           size_t errlen)
{
    int width, height, lines;
    swe_plot_size(2, 0, &width, &height);
    char *title = swe_plot_wrap(p->title, (width - 40) * 2 / 15, &lines);
    swe_plot_size(2, lines + 1, &width, &height);
    width += 160; /* room for the two colour scales' labels */
    const double *o = p->outline, lim = 2 * p->target;
    buf b = {0};
    char t[512];
    int newline = 0;
    snprintf(t, sizeof t, "set terminal pngcairo size %d,%d font 'DejaVu Sans,11'\nset output ",
             width, height);
    PUT(&b, t);
    newline |= put_sq(&b, png) < 0;
    PUT(&b, "\nset multiplot layout 1,2 title ");
    if (title)
        put_dq(&b, title);
    PUT(&b, "\nset size ratio -1\nset xrange [");
    putf(&b, "%.6g", o[0]), PUT(&b, "-0.005:"), putf(&b, "%.6g", o[1]);
    PUT(&b, "+0.005]; set yrange [");
    putf(&b, "%.6g", o[2]), PUT(&b, "-0.005:"), putf(&b, "%.6g", o[3]);
    PUT(&b, "+0.005]\nset xlabel 'y [m] (right = +y)'; set ylabel 'z [m]'\n"
            "set datafile separator ','\nset object 1 rectangle from ");
    putf(&b, "%.6g", o[0]), PUT(&b, ","), putf(&b, "%.6g", o[2]), PUT(&b, " to ");
    putf(&b, "%.6g", o[1]), PUT(&b, ","), putf(&b, "%.6g", o[3]);
    PUT(&b, " front fillstyle empty border lc rgb 'black' lw 2\n");
    if (p->rms <= p->target)
        snprintf(t, sizeof t,
                 "set lmargin at screen 0.07; set rmargin at screen 0.37\n"
                 "set title \"deposit per block, %d x %d: the finest grid whose typical\\n"
                 "block's error (deposit-weighted rms) is <= %.0f %%: %.0f %%\\n"
                 "grey: error > %.0f %% or no parcel, no value shown\"\n",
                 p->nb, p->nb, 100 * p->target, 100 * p->rms, 100 * lim);
    else
        snprintf(t, sizeof t,
                 "set lmargin at screen 0.07; set rmargin at screen 0.37\n"
                 "set title \"deposit per block, %d x %d: no grid holds an error\\n"
                 "<= %.0f %%; the whole face's is %.0f %%\\n"
                 "grey: error > %.0f %% or no parcel, no value shown\"\n",
                 p->nb, p->nb, 100 * p->target, 100 * p->rms, 100 * lim);
    PUT(&b, t);
    PUT(&b, "set cbrange [0:");
    putf(&b, "%.6g", p->vmax > 0 ? p->vmax : 1);
    PUT(&b, "]\nset cblabel 'deposit [kg/m^2]'\n"
            "set palette defined (0 '#f7fbff', 0.15 '#c6dbef', 0.4 '#6baed6', 0.7 '#2171b5', "
            "1 '#08306b')\nplot ");
    newline |= put_sq(&b, p->csv) < 0;
    snprintf(t, sizeof t,
             " every ::1 using (($7 > 0 && $6 <= %.6g) ? ($1+$2)/2 : NaN):(($3+$4)/2):(($2-$1)/2):"
             "(($4-$3)/2):5 with boxxyerror fs solid 1.0 noborder lc palette notitle, \\\n"
             "     '' every ::1 using (($7 == 0 || $6 > %.6g) ? ($1+$2)/2 : NaN):(($3+$4)/2):"
             "(($2-$1)/2):(($4-$3)/2) with boxxyerror fs solid 1.0 noborder lc rgb '#c8c8c8' "
             "notitle\n",
             lim, lim);
    PUT(&b, t);
    PUT(&b, "set lmargin at screen 0.57; set rmargin at screen 0.87\n"
            "set title \"relative error of each block (1 sigma) [%]\\n"
            "from the parcels' independent origins\"\n"
            "set cbrange [0:100]; set cblabel 'relative error [%]'\n"
            "set palette defined (0 '#ffffff', 0.3 '#fdd49e', 0.6 '#fc8d59', 1 '#b30000')\nplot ");
    newline |= put_sq(&b, p->csv) < 0;
    PUT(&b, " every ::1 using (($7 > 0) ? ($1+$2)/2 : NaN):(($3+$4)/2):(($2-$1)/2):"
            "(($4-$3)/2):(100*$6 < 100 ? 100*$6 : 100) with boxxyerror fs solid 1.0 noborder "
            "lc palette notitle, \\\n     '' every ::1 using (($7 == 0) ? ($1+$2)/2 : NaN):"
            "(($3+$4)/2):(($2-$1)/2):(($4-$3)/2) with boxxyerror fs solid 1.0 noborder "
            "lc rgb '#c8c8c8' notitle");
    if (p->nb <= 8) {
        PUT(&b, ", \\\n     '' every ::1 using (($1+$2)/2):(($3+$4)/2):($7 > 0 ? "
                "sprintf('%.0f %%', 100*$6) : 'none') with labels notitle");
    }
    PUT(&b, "\nunset multiplot\n");
    free(title);
    int rc = 0;
    if (!title || b.bad || newline) {
        snprintf(err, errlen, newline ? "a file name holds a newline" : "out of memory");
        rc = -1;
    } else if (fwrite(b.s, 1, b.len, out) != b.len) {
        snprintf(err, errlen, "cannot write the script");
        rc = -1;
    }
    free(b.s);
    return rc;
}
