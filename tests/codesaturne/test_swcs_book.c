/* test_swcs_book.c - the host-neutral half of the host bindings
 * (wallmodel/CodeSaturne/swcs_book): zones, one impact in the wall's frame
 * through the C core, counts, deposit per face, the CSV files. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <sys/stat.h>
#include <signal.h>
#include <dirent.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include <cmocka.h>

#include "swcs_book.h"
#include "sww.h"

static const char *const FIXTURE = SWW_FIXTURES "/regime.coeffs";

static sww_model *fixture(void)
{
    sww_model *m = sww_alloc();
    assert_non_null(m);
    assert_int_equal(sww_regime_load(m, FIXTURE), SWW_OK);
    return m;
}

static void zones(void **s)
{
    (void)s;
    assert_null(swcs_book_alloc(0, 4));
    assert_null(swcs_book_alloc(3, 0));
    swcs_book *b = swcs_book_alloc(3, 4);
    assert_non_null(b);
    assert_int_equal(swcs_book_zone_type(b, 1), SWCS_NONE);
    assert_int_equal(swcs_book_set_zone(b, 1, "wall", "snow"), SWW_OK);
    assert_int_equal(swcs_book_set_zone(b, 2, "top", "escape"), SWW_OK);
    assert_int_equal(swcs_book_zone_type(b, 1), SWCS_SNOW);
    assert_int_equal(swcs_book_zone_type(b, 2), SWCS_ESCAPE);
    assert_int_equal(swcs_book_zone_type(b, 7), SWCS_NONE);
    assert_int_equal(swcs_book_set_zone(b, 1, "wall", "escape"), SWW_EINVAL);
    assert_string_equal(swcs_book_errmsg(b), "zone wall is given twice (first as snow, now as escape)");
    assert_int_equal(swcs_book_set_zone(b, 0, "inlet", "snowy"), SWW_EINVAL);
    assert_string_equal(swcs_book_errmsg(b), "zone inlet: type 'snowy' is not one of snow, escape, none");
    assert_int_equal(swcs_book_set_zone(b, 3, "x", "snow"), SWW_EINVAL);
    assert_string_equal(swcs_book_errmsg(b), "zone id 3 is outside [0, 3)");
    assert_int_equal(swcs_book_set_zone(b, 0, "", "snow"), SWW_EINVAL);
    char longname[100];
    memset(longname, 'a', sizeof longname - 1);
    longname[sizeof longname - 1] = '\0';
    assert_int_equal(swcs_book_set_zone(b, 0, longname, "snow"), SWW_EINVAL);
    swcs_book_free(b);
}

/* p1 / p2 / p6 of the box: a stick, a bounce (the core's e_n), the tangential gate */
static void impacts(void **s)
{
    (void)s;
    sww_model *m = fixture();
    assert_int_equal(sww_set_tangential_gate(m, 0.5, 5e-5, 0), SWW_OK);
    swcs_book *b = swcs_book_alloc(2, 4);
    assert_int_equal(swcs_book_set_zone(b, 0, "wall", "snow"), SWW_OK);
    assert_int_equal(swcs_book_set_zone(b, 1, "top", "escape"), SWW_OK);
    const double n[3] = {0, -1, 0};   /* out of the fluid at y = 0 */
    sww_outcome out;
    double un[3];
    const double u1[3] = {0, -1, 0};
    assert_int_equal(swcs_book_impact(b, m, 0, 2, 1e-5, 4.8e-13, u1, NULL, n, 0, 0.5, &out, un), SWW_OK);
    assert_int_equal(out.fate, SWW_STICK);
    assert_true(un[0] == 0 && un[1] == 0 && un[2] == 0);
    assert_true(swcs_book_deposit(b)[2] == 4.8e-13);
    /* 40 um at 1 m/s bounces: v_n' = e_n(1 m/s) v_n, tangential kept (e_t 1) */
    const double u2[3] = {0.3, -1, 0.1};
    assert_int_equal(swcs_book_impact(b, m, 0, 1, 4e-5, 1e-11, u2, NULL, n, 0, 0.5, &out, un), SWW_OK);
    assert_int_equal(out.fate, SWW_BOUNCE);
    /* the tangential gate stops this one: |v_t| 0.316 < 0.5, so it is the criterion */
    assert_int_equal(out.reason, SWW_BY_CRITERION);
    const double en = sww_rebound_normal(m, 1.0);
    assert_true(fabs(un[1] - en) <= 1e-15 && un[0] == 0.3 && un[2] == 0.1);
    assert_true(swcs_book_deposit(b)[1] == 0);
    /* p6: 10 um, v_n 1, v_t 0.8 > 0.5: bounces by the tangential gate */
    const double u6[3] = {0.8, -1, 0};
    assert_int_equal(swcs_book_impact(b, m, 0, 3, 1e-5, 1, u6, NULL, n, 0, 0.5, &out, un), SWW_OK);
    assert_int_equal(out.fate, SWW_BOUNCE);
    assert_int_equal(out.reason, SWW_BY_TANGENTIAL);
    /* a moving wall: the impact is decided in the wall's frame */
    /* (the wall moves into the fluid at 1 m/s, the particle towards it at 1 m/s:
       v_n 2 m/s; it leaves at the wall's velocity plus e_n(2) 2 m/s) */
    const double uw[3] = {0, 1, 0}, u7[3] = {0, -1, 0};
    assert_int_equal(swcs_book_impact(b, m, 0, 0, 4e-5, 1, u7, uw, n, 0, 0.5, &out, un), SWW_OK);
    assert_int_equal(out.fate, SWW_BOUNCE);
    assert_true(fabs(un[1] - (1 + 2 * sww_rebound_normal(m, 2.0))) <= 1e-15);
    const swcs_zone_counts *z = swcs_book_zone(b, 0);
    assert_int_equal(z->impacts, 4);
    assert_int_equal(z->sticks, 1);
    assert_int_equal(z->bounces, 3);
    assert_true(z->mass_deposited == 4.8e-13);
    /* errors: nothing booked */
    const double bad_n[3] = {0, -2, 0};
    assert_int_equal(swcs_book_impact(b, m, 0, 0, 1e-5, 1, u1, NULL, bad_n, 0, 0.5, &out, un), SWW_EINVAL);
    assert_non_null(strstr(swcs_book_errmsg(b), "is not a unit vector"));
    assert_int_equal(swcs_book_impact(b, m, 0, 4, 1e-5, 1, u1, NULL, n, 0, 0.5, &out, un), SWW_EINVAL);
    assert_string_equal(swcs_book_errmsg(b), "zone wall: impact on face 4, outside [0, 4)");
    assert_int_equal(swcs_book_impact(b, m, 0, 0, 1e-5, NAN, u1, NULL, n, 0, 0.5, &out, un), SWW_EINVAL);
    assert_int_equal(swcs_book_impact(b, m, 1, 0, 1e-5, 1, u1, NULL, n, 0, 0.5, &out, un), SWW_EINVAL);
    assert_string_equal(swcs_book_errmsg(b), "impact on zone id 1 (top), which is not a snow zone");
    assert_int_equal(swcs_book_impact(b, m, 0, 0, -1e-5, 1, u1, NULL, n, 0, 0.5, &out, un), SWW_EINVAL);
    assert_non_null(strstr(swcs_book_errmsg(b), "the core refused the impact d -1e-05 m"));
    assert_int_equal(swcs_book_zone(b, 0)->impacts, 4);
    /* escape */
    assert_int_equal(swcs_book_escape(b, 1, 2.5), SWW_OK);
    assert_int_equal(swcs_book_escape(b, 0, 2.5), SWW_EINVAL);
    assert_int_equal(swcs_book_zone(b, 1)->escapes, 1);
    swcs_book_free(b);
    sww_free(m);
}

static void unready_model(void **s)
{
    (void)s;
    sww_model *m = sww_alloc();
    swcs_book *b = swcs_book_alloc(1, 1);
    assert_int_equal(swcs_book_set_zone(b, 0, "wall", "snow"), SWW_OK);
    const double n[3] = {0, 0, 1}, u[3] = {0, 0, 1};
    sww_outcome out;
    double un[3];
    assert_int_equal(swcs_book_impact(b, m, 0, 0, 1e-5, 1, u, NULL, n, 0, 0.5, &out, un), SWW_ENOTREADY);
    assert_string_equal(swcs_book_errmsg(b), "zone wall: the regime map is not loaded");
    swcs_book_free(b);
    sww_free(m);
}

static void pack_summary_csv(void **s)
{
    (void)s;
    sww_model *m = fixture();
    swcs_book *b = swcs_book_alloc(3, 2);
    assert_int_equal(swcs_book_set_zone(b, 0, "wall", "snow"), SWW_OK);
    assert_int_equal(swcs_book_set_zone(b, 2, "out", "escape"), SWW_OK);
    const double n[3] = {1, 0, 0}, u[3] = {1, 0, 0};
    sww_outcome out;
    double un[3];
    assert_int_equal(swcs_book_impact(b, m, 0, 1, 1e-5, 0.25, u, NULL, n, 0, 0.5, &out, un), SWW_OK);
    assert_int_equal(swcs_book_escape(b, 2, 0.5), SWW_OK);
    /* a sum of two ranks' identical books */
    double v[3 * SWCS_PACK_PER_ZONE];
    swcs_book_pack(b, v);
    for (size_t i = 0; i < sizeof v / sizeof v[0]; ++i) v[i] *= 2;
    swcs_book_unpack(b, v);
    assert_int_equal(swcs_book_zone(b, 0)->impacts, 2);
    assert_int_equal(swcs_book_zone(b, 0)->sticks, 2);
    char buf[1024];
    const size_t len = swcs_book_summary(b, "SnowWall: ", buf, sizeof buf);
    assert_int_equal(len, strlen(buf));
    assert_string_equal(buf,
        "SnowWall: zone wall (snow): impacts 2, sticks 2, bounces 0, ripoffs 0, deposited mass 0.5 kg "
        "(0 impacts outside the fitted v_n range)\n"
        "SnowWall: zone out (escape): escapes 2, mass 1 kg\n");
    char small[20];
    assert_int_equal(swcs_book_summary(b, "", small, sizeof small), len - strlen("SnowWall: ") * 2);
    assert_int_equal(small[0], '\0');

    char dir[] = "/tmp/swcs-book-XXXXXX";
    assert_non_null(mkdtemp(dir));
    char path[256], line[256];
    snprintf(path, sizeof path, "%s/counts.csv", dir);
    assert_int_equal(swcs_book_write_counts(b, path, 0.1, 20), SWW_OK);
    FILE *f = fopen(path, "r");
    assert_non_null(f);
    assert_non_null(fgets(line, sizeof line, f));
    assert_string_equal(line, "time,step,zone,type,impacts,sticks,bounces,ripoffs,escapes,outside,"
                              "deposited_kg,escaped_kg\n");
    assert_non_null(fgets(line, sizeof line, f));
    assert_string_equal(line, "0.1,20,wall,snow,2,2,0,0,0,0,0.5,0\n");
    assert_non_null(fgets(line, sizeof line, f));
    assert_string_equal(line, "0.1,20,out,escape,0,0,0,0,2,0,0,1\n");
    fclose(f);
    /* no temporary left beside it: the folder holds counts.csv only */
    {
        DIR *d = opendir(dir);
        assert_non_null(d);
        int n = 0;
        for (struct dirent *e; (e = readdir(d)) != NULL;)
            if (strcmp(e->d_name, ".") && strcmp(e->d_name, ".."))
                n++, assert_string_equal(e->d_name, "counts.csv");
        closedir(d);
        assert_int_equal(n, 1);
    }
    snprintf(path, sizeof path, "%s/deposit.csv", dir);
    const double cog[6] = {0, 0, 0, 1, 2, 3}, area[2] = {0.5, 0.25};
    const int fz[2] = {1, 0};
    const long long num[2] = {10, 11};
    assert_int_equal(swcs_book_write_deposit(b, path, num, cog, area, fz), SWW_OK);
    f = fopen(path, "r");
    assert_non_null(fgets(line, sizeof line, f));
    assert_non_null(fgets(line, sizeof line, f));
    assert_string_equal(line, "11,wall,1,2,3,0.25,0.25,1\n");   /* face 0 is not in a snow zone */
    assert_null(fgets(line, sizeof line, f));
    fclose(f);
    remove(path);
    snprintf(path, sizeof path, "%s/counts.csv", dir);
    remove(path);
    /* an output folder that is not there: SWW_EIO naming the file */
    snprintf(path, sizeof path, "%s/no/such.csv", dir);
    assert_int_equal(swcs_book_write_counts(b, path, 0, 0), SWW_EIO);
    assert_non_null(strstr(swcs_book_errmsg(b), "cannot write '"));
    assert_non_null(strstr(swcs_book_errmsg(b), "/no/such.csv': folder"));
    assert_non_null(strstr(swcs_book_errmsg(b), "No such file or directory"));
    /* a FIFO at the output name: refused (SWW_EIO naming it), left a FIFO, no
     * temporary; the binding runs inside the host and installs no signal handler */
    snprintf(path, sizeof path, "%s/fifo.csv", dir);
    assert_int_equal(mkfifo(path, 0600), 0);
    assert_int_equal(swcs_book_write_counts(b, path, 0, 0), SWW_EIO);
    assert_non_null(strstr(swcs_book_errmsg(b), "fifo.csv': it exists and is a FIFO"));
    struct stat st;
    assert_int_equal(lstat(path, &st), 0);
    assert_true(S_ISFIFO(st.st_mode));
    remove(path);
    struct sigaction sa;
    assert_int_equal(sigaction(SIGINT, NULL, &sa), 0);
    assert_true(sa.sa_handler == SIG_DFL || sa.sa_handler == SIG_IGN);
    rmdir(dir);
    swcs_book_free(b);
    sww_free(m);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(zones),
        cmocka_unit_test(impacts),
        cmocka_unit_test(unready_model),
        cmocka_unit_test(pack_summary_csv),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
