/* sr_mapplot.c - the gnuplot pictures of snowregime map (the stick/bounce
 * map with its interface and fit; the stick probability of a rough wall with
 * its contours) and of snowregime sensitivity (the interface per parameter). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "sr.h"

static void gp_fit_function(FILE *gp, const char *name, const swt_fit *F)
{
    fprintf(gp, "%s(x) = (x < %.10g || x > %.10g) ? 1/0 : 1e6*exp(", name, F->vnmin, F->vnmax);
    for (int i = 0; i <= F->degree; i++) fprintf(gp, "%s(%.17g)*log(x)**%d", i ? " + " : "", F->c[i], i);
    fprintf(gp, ")\n");
}

/* The axes of a map plot: v_n (log when the grid is) against d in um. */
static void gp_map_axes(FILE *f, const swt_map *mp)
{
    fprintf(f, "set datafile separator ','\nset key outside below horizontal\nset format x '%%g'\nset mxtics 10\n");
    if (mp->g.vlog) fprintf(f, "set logscale x\n");
    fprintf(f, "set xrange [%.10g:%.10g]\nset yrange [%.10g:%.10g]\n",
            mp->g.vmin / (mp->g.vlog ? 1.05 : 1.0), mp->g.vmax * 1.05,
            mp->g.dmin * 1e6 - 2, mp->g.dmax * 1e6 + 2);
    fprintf(f, "set xlabel 'normal impact speed v_n [m/s]'\nset ylabel 'particle diameter d [um]'\n");
}

int sr_map_plot(swo_set *os, const char *sfx, const sr_mapres *r, const char *title,
                char *err, size_t errlen)
{
    char name[128], gpname[128], csv[128], itf[128];
    snprintf(name, sizeof name, "map%s.png", sfx);
    snprintf(gpname, sizeof gpname, "map%s.gp", sfx);
    snprintf(csv, sizeof csv, "map%s.csv", sfx);
    snprintf(itf, sizeof itf, "interface%s.csv", sfx);
    const char *png = swo_add(os, name, err, errlen);
    const char *tcsv = swo_add(os, csv, err, errlen);
    const char *titf = swo_add(os, itf, err, errlen);
    if (!png || !tcsv || !titf) return -1;
    swt_gnuplot g;
    if (swt_gnuplot_open(&g, png, 800, 700, err, errlen) != 0) return -1;
    FILE *f = g.f;
    gp_map_axes(f, r->mp);
    fprintf(f, "set title \"%s\" noenhanced\nset samples 400\n", title);
    if (r->fit_ok) gp_fit_function(f, "dfit", &r->fit);
    fprintf(f, "plot '%s' skip 1 using 2:($3==1 ? $1*1e6 : 1/0) with points pt 5 ps 0.55 lc rgb '#3070d0' title 'stick', \\\n"
               "     '%s' skip 1 using 2:($3==0 ? $1*1e6 : 1/0) with points pt 5 ps 0.55 lc rgb '#e08070' title 'bounce', \\\n"
               "     '%s' skip 1 using 1:($2*1e6) with points pt 7 ps 0.8 lc rgb 'black' title 'interface points'",
            swt_gp_name(tcsv), swt_gp_name(tcsv), swt_gp_name(titf));
    if (r->fit_ok) fprintf(f, ", \\\n     dfit(x) with lines lw 2 lc rgb '#000000' title 'fit d_{crit}(v_n), degree %d'", r->fit.degree);
    fprintf(f, "\n");
    (void)gpname;
    return swt_gnuplot_finish(&g, err, errlen);
}

int sr_map_plot_rough(swo_set *os, const char *sfx, const sr_mapres *r, const char *title,
                      char *err, size_t errlen)
{
    char npng[64], ncsv[64], ncon[64];
    snprintf(npng, sizeof npng, "map%s.png", sfx);
    snprintf(ncsv, sizeof ncsv, "map%s.csv", sfx);
    snprintf(ncon, sizeof ncon, "contours%s.csv", sfx);
    const char *png = swo_add(os, npng, err, errlen);
    const char *tcsv = swo_add(os, ncsv, err, errlen);
    const char *tcon = swo_add(os, ncon, err, errlen);
    if (!png || !tcsv || !tcon) return -1;
    swt_gnuplot g;
    if (swt_gnuplot_open(&g, png, 820, 700, err, errlen) != 0) return -1;
    FILE *f = g.f;
    gp_map_axes(f, r->mp);
    fprintf(f, "set cblabel 'stick probability'\nset cbrange [0:1]\n"
               "set palette defined (0 '#e08070', 0.5 '#f4f0e8', 1 '#3070d0')\n");
    fprintf(f, "set title \"%s\" noenhanced\n", title);  /* title: no quotes or backslashes but its \\n */
    fprintf(f, "plot '%s' skip 1 using 2:($1*1e6):8 with points pt 5 ps 1.3 palette notitle, \\\n"
               "     '%s' skip 2 using ($1==0.1 ? $2 : 1/0):($3*1e6) with linespoints pt 7 ps 0.5 lw 2 lc rgb '#804000' title 'p = 0.1', \\\n"
               "     '%s' skip 2 using ($1==0.5 ? $2 : 1/0):($3*1e6) with linespoints pt 7 ps 0.5 lw 2 lc rgb 'black' title 'p = 0.5', \\\n"
               "     '%s' skip 2 using ($1==0.9 ? $2 : 1/0):($3*1e6) with linespoints pt 7 ps 0.5 lw 2 lc rgb '#004080' title 'p = 0.9'\n",
            swt_gp_name(tcsv), swt_gp_name(tcon), swt_gp_name(tcon), swt_gp_name(tcon));
    return swt_gnuplot_finish(&g, err, errlen);
}

/* The sensitivity plot png from the interfaces in tdata (sensitivity-
 * interfaces.csv: one gnuplot data block per map, the baseline first) over
 * the grid g: n maps, keys[k] = vals[k] (k = 0 the baseline). */
int sr_plot_sensitivity(const char *png, const char *tdata, const swt_grid *g, int n,
                        const char keys[][16], const double *vals, char *err, size_t errlen)
{
    swt_gnuplot gp;
    if (swt_gnuplot_open(&gp, png, 950, 650, err, errlen) != 0)
        return -1;
    FILE *f = gp.f;
    fprintf(f, "set datafile separator ','\nset key outside right top\nset format x '%%g'\nset mxtics 10\n");
    if (g->vlog) fprintf(f, "set logscale x\n");
    fprintf(f, "set xrange [%.10g:%.10g]\nset yrange [%.10g:%.10g]\n", g->vmin, g->vmax,
            g->dmin * 1e6, g->dmax * 1e6);
    fprintf(f, "set xlabel 'normal impact speed v_n [m/s]'\nset ylabel 'critical diameter d_{crit} [um]'\n");
    fprintf(f, "set title 'snowregime sensitivity: stick/bounce interface per parameter (below: stick)'\n");
    fprintf(f, "plot ");
    for (int k = 0; k < n; k++) {
        char lab[64];
        if (k == 0) snprintf(lab, sizeof lab, "baseline");
        else snprintf(lab, sizeof lab, "%s = %g", keys[k], vals[k]);
        fprintf(f, "%s'%s' index %d skip %d using 3:($4*1e6) with linespoints lw %d pt %d ps 0.6 title '%s'",
                k ? ", \\\n     " : "", swt_gp_name(tdata), k, k == 0 ? 1 : 0, k == 0 ? 3 : 1, k, lab);
    }
    fprintf(f, "\n");
    return swt_gnuplot_finish(&gp, err, errlen);
}
