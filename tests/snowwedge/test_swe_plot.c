/* test_swe_plot.c - the gnuplot script of rear-face maps side by side
 * (tools/snowwedge swe_plot.h) on synthetic input with known answers: titles
 * wrapped as `fold -s -w W` wraps them (word boundaries, a word longer than
 * the width cut at it, tabs to multiples of 8, a literal backslash-n or a
 * newline starting a line, blanks at line ends removed), the figure's size
 * (460 px a panel, 18 px a title line beyond two), the whole script of one and
 * of two panels, titles and file names quoted so that they cannot end their
 * string or run a command, and the largest deposit of the maps. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>

#include "swe_plot.h"

/* wrap TEXT at W and compare with the lines WANT (joined by '\n') */
static void wraps(const char *text, int w, const char *want, int want_lines)
{
    int n = -1;
    char *got = swe_plot_wrap(text, w, &n);
    assert_non_null(got);
    assert_string_equal(got, want);
    assert_int_equal(n, want_lines);
    free(got);
}

static void wrapping(void **st)
{
    (void)st;
    wraps("", 10, "", 1);
    wraps("short", 10, "short", 1);
    /* a break after the last blank within the width; the blank not kept */
    wraps("aaa bbb ccc", 7, "aaa\nbbb ccc", 2); /* "aaa bbb" fits, its blank does not */
    wraps("aaa bbb ccc", 6, "aaa\nbbb\nccc", 3);
    /* exactly the width stays one line */
    wraps("abcdefghij", 10, "abcdefghij", 1);
    /* a word longer than the width: cut at the width */
    wraps("abcdefghijkl", 5, "abcde\nfghij\nkl", 3);
    wraps("ab abcdefghijkl", 5, "ab\nabcde\nfghij\nkl", 4);
    /* a literal backslash-n and a newline start a line; a trailing one an empty line */
    wraps("one\\ntwo", 10, "one\ntwo", 2);
    wraps("one\ntwo\\n", 10, "one\ntwo\n", 3);
    wraps("\\n\\n", 10, "\n\n", 3);
    /* a backslash before the backslash-n stays (the second one starts the line) */
    wraps("a\\\\nb", 10, "a\\\nb", 2);
    /* blanks at a line's end removed, inside kept */
    wraps("a  b   ", 10, "a  b", 1);
    wraps("aaaa    bbbb", 6, "aaaa\n  bbbb", 2);
    /* a tab takes the columns to the next multiple of 8 */
    wraps("ab\tcd", 9, "ab\t\ncd", 2); /* a tab at a line end stays */
    wraps("ab\tcd efgh", 12, "ab\tcd\nefgh", 2);
    /* the compose title of one panel, 72 characters wide (580 px) */
    wraps("Rear face seen from behind - composed from the size classes\\nlog-normal by mass, MVD 20 um, "
          "sigma_g 1.8, droplets 2-150 um, ice x 1.03: snow after 30 min, rear total 1.2e-05 kg",
          72,
          "Rear face seen from behind - composed from the size classes\n"
          "log-normal by mass, MVD 20 um, sigma_g 1.8, droplets 2-150 um, ice x\n"
          "1.03: snow after 30 min, rear total 1.2e-05 kg", 3);
}

static void sizes(void **st)
{
    (void)st;
    int w, h;
    swe_plot_size(1, 2, &w, &h);
    assert_int_equal(w, 580);
    assert_int_equal(h, 560);
    swe_plot_size(3, 1, &w, &h);
    assert_int_equal(w, 1500);
    assert_int_equal(h, 560);
    /* 18 px for each line beyond two */
    swe_plot_size(4, 3, &w, &h);
    assert_int_equal(w, 1960);
    assert_int_equal(h, 578);
    swe_plot_size(2, 6, &w, &h);
    assert_int_equal(h, 632);
}

/* the script of p into PNG as text (the caller frees) */
static char *script(const swe_plot_panels *p, const char *png, int want_rc)
{
    char *t = NULL, err[256] = "";
    size_t len = 0;
    FILE *f = open_memstream(&t, &len);
    assert_non_null(f);
    const int rc = swe_plot_script(f, p, png, err, sizeof err);
    fclose(f);
    assert_int_equal(rc, want_rc);
    if (rc)
        assert_string_equal(err, "a file name holds a newline");
    return t;
}

static const char *tail =
    "set size ratio -1\n"
    "set xrange [-0.06-0.005:0.06+0.005]; set yrange [-0.0475-0.005:0.0725+0.005]\n"
    "set cbrange [0:0.0256778]\n"
    "set cblabel 'deposit [kg/m^2]'\n"
    "set palette defined (0 '#f7fbff', 0.15 '#c6dbef', 0.4 '#6baed6', 0.7 '#2171b5', 1 '#08306b')\n"
    "set xlabel 'y [m] (right = +y)'; set ylabel 'z [m]'\n"
    "set datafile separator ','\n"
    "set object 1 rectangle from -0.06,-0.0475 to 0.06,0.0725 front fillstyle empty border lc "
    "rgb 'black' lw 2\n";

static void one_panel(void **st)
{
    (void)st;
    const char *maps[] = {"r/rear_deposit.csv"}, *titles[] = {"snow after 30 min\\nrear total 1 kg"};
    swe_plot_panels p = {"Rear face", 1, maps, titles, 0.02567784, {-0.06, 0.06, -0.0475, 0.0725}};
    char *t = script(&p, "r/.x.png.abc", 0), want[4096];
    /* one panel: its title below the figure's, three lines in all: 18 px more */
    snprintf(want, sizeof want,
             "set terminal pngcairo size 580,578 font 'DejaVu Sans,11'\n"
             "set output 'r/.x.png.abc'\n"
             "set title \"Rear face\\nsnow after 30 min\\nrear total 1 kg\"\n%s"
             "plot 'r/rear_deposit.csv' every ::1 using 1:2:3 with image notitle\n", tail);
    assert_string_equal(t, want);
    free(t);
    /* nothing positive: the scale 0 .. 1 */
    p.vmax = 0;
    t = script(&p, "x.png", 0);
    assert_non_null(strstr(t, "set cbrange [0:1]\n"));
    free(t);
}

static void panels(void **st)
{
    (void)st;
    const char *maps[] = {"a.csv", "b.csv"},
                *titles[] = {"first half 0.1 .. 0.15 s (x2) with a title that is longer than "
                             "fifty-eight characters", "second"};
    swe_plot_panels p = {"Rear face", 2, maps, titles, 0.02567784, {-0.06, 0.06, -0.0475, 0.0725}};
    char *t = script(&p, "o.png", 0), want[4096];
    /* two panels: 1040 px wide, the figure title's line plus one for the panels' */
    snprintf(want, sizeof want,
             "set terminal pngcairo size 1040,560 font 'DejaVu Sans,11'\n"
             "set output 'o.png'\n"
             "set multiplot layout 1,2 title \"Rear face\"\n%s"
             "set title \"first half 0.1 .. 0.15 s (x2) with a title that is longer\\nthan "
             "fifty-eight characters\"\n"
             "plot 'a.csv' every ::1 using 1:2:3 with image notitle\n"
             "set title \"second\"\n"
             "plot 'b.csv' every ::1 using 1:2:3 with image notitle\n"
             "unset multiplot\n", tail);
    assert_string_equal(t, want);
    free(t);
    /* a figure title of three lines and the panels' line: 2 lines beyond two */
    p.title = "one\\ntwo\\nthree";
    t = script(&p, "o.png", 0);
    assert_non_null(strstr(t, "size 1040,596 "));
    free(t);
}

static void quoting(void **st)
{
    (void)st;
    const char *maps[] = {"it's.csv", "<rm x", "-"},
                *titles[] = {"a\"; system(\"rm x\"); print \"", "b `rm x` c\\", "+"};
    swe_plot_panels p = {"T \"q\"", 3, maps, titles, 1, {0, 1, 0, 1}};
    char *t = script(&p, "o'.png", 0);
    /* double quotes and backslashes escaped, a backquote as its octal escape */
    assert_non_null(strstr(t, "title \"T \\\"q\\\"\"\n"));
    assert_non_null(strstr(t, "set title \"a\\\"; system(\\\"rm x\\\"); print \\\"\"\n"));
    assert_non_null(strstr(t, "set title \"b \\140rm x\\140 c\\\\\"\n"));
    assert_null(strchr(t, '`'));
    /* a single quote doubled; a pipe or standard input read as a file */
    assert_non_null(strstr(t, "set output 'o''.png'\n"));
    assert_non_null(strstr(t, "plot 'it''s.csv' every"));
    assert_non_null(strstr(t, "plot './<rm x' every"));
    assert_non_null(strstr(t, "plot './-' every"));
    free(t);
    /* a newline in a file name is refused */
    maps[0] = "a\nset output 'x'";
    free(script(&p, "o.png", -1));
    maps[0] = "a.csv";
    free(script(&p, "o\n.png", -1));
}

static void map_max(void **st)
{
    (void)st;
    char dir[] = "/tmp/test_swe_plot.XXXXXX", a[64], b[64], err[128];
    assert_non_null(mkdtemp(dir));
    snprintf(a, sizeof a, "%s/a.csv", dir);
    snprintf(b, sizeof b, "%s/b.csv", dir);
    FILE *f = fopen(a, "w");
    fputs("y,z,deposit_kg_m2\n0,0,0.5\n0,1,x\n1,0,2.5\n", f);
    fclose(f);
    f = fopen(b, "w");
    fputs("99,99,99\n0,0,1.5\n", f); /* the header line is not a value */
    fclose(f);
    const char *maps[] = {a, b};
    double m = -1;
    assert_int_equal(swe_plot_map_max(maps, 2, &m, err, sizeof err), 0);
    assert_true(m == 2.5);
    /* nothing positive: 0 */
    f = fopen(b, "w");
    fputs("h\n0,0,-1\n", f);
    fclose(f);
    assert_int_equal(swe_plot_map_max(maps + 1, 1, &m, err, sizeof err), 0);
    assert_true(m == 0);
    remove(a);
    remove(b);
    /* an unreadable map named */
    assert_int_equal(swe_plot_map_max(maps, 1, &m, err, sizeof err), -1);
    assert_string_equal(err, a);
    remove(dir);
}

/* the blocks' picture: two panels 1200 px wide, the grey limit twice the
   target, the errors written in the blocks up to 8 x 8, names quoted */
static char *blocks_script(const swe_plot_blocks *p, const char *png, int want_rc)
{
    char *t = NULL, err[256] = "";
    size_t len = 0;
    FILE *f = open_memstream(&t, &len);
    assert_non_null(f);
    const int rc = swe_plot_blocks_script(f, p, png, err, sizeof err);
    fclose(f);
    assert_int_equal(rc, want_rc);
    if (rc)
        assert_string_equal(err, "a file name holds a newline");
    return t;
}

static void blocks(void **st)
{
    (void)st;
    swe_plot_blocks p = {"Rear \"face\"", "b's.csv", 3, 0.3, 0.288, 0.0435, {-0.06, 0.06, -0.06, 0.06}};
    char *t = blocks_script(&p, "o.png", 0);
    assert_non_null(strstr(t, "set terminal pngcairo size 1200,560 "));
    assert_non_null(strstr(t, "set multiplot layout 1,2 title \"Rear \\\"face\\\"\"\n"));
    assert_non_null(strstr(t, "deposit per block, 3 x 3: the finest grid"));
    assert_non_null(strstr(t, "is <= 30 %: 29 %"));
    assert_non_null(strstr(t, "grey: error > 60 % or no parcel"));
    assert_non_null(strstr(t, "($7 > 0 && $6 <= 0.6) ?"));
    assert_non_null(strstr(t, "($7 == 0 || $6 > 0.6) ?"));
    assert_non_null(strstr(t, "set cbrange [0:0.0435]"));
    assert_non_null(strstr(t, "plot 'b''s.csv' every ::1"));
    assert_non_null(strstr(t, "with labels notitle"));
    free(t);
    /* no grid holds the target: said so */
    p.nb = 1, p.rms = 0.32;
    t = blocks_script(&p, "o.png", 0);
    assert_non_null(strstr(t, "deposit per block, 1 x 1: no grid holds an error\\n<= 30 %; the whole face's is 32 %"));
    free(t);
    p.rms = 0.288;
    /* finer than 8 x 8: no numbers in the blocks (they would not fit) */
    p.nb = 9;
    t = blocks_script(&p, "o.png", 0);
    assert_null(strstr(t, "with labels"));
    free(t);
    p.csv = "a\nb.csv";
    free(blocks_script(&p, "o.png", -1));
    p.csv = "b.csv";
    free(blocks_script(&p, "o\n.png", -1));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(wrapping), cmocka_unit_test(sizes),   cmocka_unit_test(one_panel),
        cmocka_unit_test(panels),   cmocka_unit_test(quoting), cmocka_unit_test(map_max),
        cmocka_unit_test(blocks),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
