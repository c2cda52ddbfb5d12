/* test_swe_run.c - the numbers of tutorials/wedge/Allrun (tools/snowwedge/swe_run.c)
 * on inputs with known answers: the mesh of a ladder rung, the cost estimate of the
 * default coarse run and of the steady route (the very lines Allrun has printed),
 * the memory refusal, the nozzles' dictionaries, the slabs of the decomposition
 * (ties in y broken as sort(1) breaks them: by the whole line's bytes), the rung's
 * record from a solver log, the rear face's y+ summary, the joining of a resumed
 * run's logs (the cut, the wall-time offsets) and tables, and the total-error table. */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>

#include "swe_run.h"

#define ASSERT_NEAR(x, ref, tol) assert_true(fabs((x) - (ref)) <= (tol))

static const char *coarse = "nxUp 12; nxBody 22; nxDown 28; nBody 20; nOut 11;";

/* a stream over a string, and the text written to one */
static FILE *in_text(const char *s)
{
    FILE *f = fmemopen((void *)s, strlen(s), "r");
    assert_non_null(f);
    return f;
}

typedef struct {
    char *buf;
    size_t len;
    FILE *f;
} out_text;

static void out_open(out_text *o)
{
    o->buf = NULL;
    o->len = 0;
    o->f = open_memstream(&o->buf, &o->len);
    assert_non_null(o->f);
}

static char *out_close(out_text *o)
{
    fclose(o->f);
    return o->buf;
}

/* the coarse mesh: 100 568 cells, 42 along y; a rung up: every count x sqrt(2)
   rounded half up; -refine-wake: nxDown and nBody x 1.25 */
static void mesh(void **st)
{
    (void)st;
    swe_mesh m;
    char err[256], s[256];
    assert_int_equal(swe_mesh_parse(coarse, &m, err, sizeof err), 0);
    ASSERT_NEAR(swe_mesh_cells(&m), 100568, 0);
    assert_int_equal(swe_mesh_ny(&m), 42);
    swe_mesh_scale(&m, 1, 0);
    swe_mesh_format(&m, s, sizeof s);
    assert_string_equal(s, "nxUp 17; nxBody 31; nxDown 40; nBody 28; nOut 16;");
    assert_int_equal(swe_mesh_parse(coarse, &m, err, sizeof err), 0);
    swe_mesh_scale(&m, 0, 1);
    swe_mesh_format(&m, s, sizeof s);
    assert_string_equal(s, "nxUp 12; nxBody 22; nxDown 35; nBody 25; nOut 11;");
    ASSERT_NEAR(swe_mesh_cells(&m), 138671, 0);
    assert_int_equal(swe_mesh_parse(coarse, &m, err, sizeof err), 0);
    swe_mesh_scale(&m, -3, 0); /* x 2^-1.5: 12 -> 4.24 -> 4, ... */
    swe_mesh_format(&m, s, sizeof s);
    assert_string_equal(s, "nxUp 4; nxBody 8; nxDown 10; nBody 7; nOut 4;");
    ASSERT_NEAR(swe_level_scale(2), 0.5, 0);
    ASSERT_NEAR(swe_level_scale(-1), sqrt(2), 1e-15);
    assert_int_not_equal(swe_mesh_parse("nxUp twelve;", &m, err, sizeof err), 0);
    assert_non_null(strstr(err, "nxUp twelve"));
}

static const double class_ppn[5] = {100, 300, 345, 200, 100};

static swe_estimate_in coarse_default(void)
{
    swe_mesh m;
    swe_mesh_parse(coarse, &m, NULL, 0);
    swe_estimate_in in = {0};
    in.cells0 = swe_mesh_cells(&m);
    in.nbody = 20;
    in.nozzles = 25;
    in.ppn = 800;
    in.ppn_factor = 1;
    in.class_ppn = class_ppn;
    in.nclasses = 5;
    in.class_factor = 1;
    in.ndisp = 1;
    in.rear_layers = 1;
    in.replay = 1;
    in.spin = 0.1;
    in.fill = 0.3;
    in.sample = 0.4;
    in.replay_start = 0.1;
    in.replay_period = 0.1;
    in.replay_interval = 0.001;
    in.np = 1;
    in.avail = -1;
    in.free_disk = -1;
    return in;
}

/* the default coarse run: the line Allrun printed before the model moved to C */
static void estimate_default(void **st)
{
    (void)st;
    swe_estimate_in in = coarse_default();
    swe_estimate_out o;
    assert_int_equal(swe_estimate(&in, &o), 0);
    ASSERT_NEAR(o.cells, 102568, 0); /* + 5 x 20^2 rear-layer cells */
    assert_int_equal(o.clouds, 6);
    ASSERT_NEAR(o.parcels, 46125, 0); /* 25 x 800 + 25 x 1045 */
    ASSERT_NEAR(o.class_parcels, 26125, 0);
    ASSERT_NEAR(o.steps, 3200, 1e-9);     /* 0.8 s / 2.5e-4 s */
    ASSERT_NEAR(o.flow_steps, 800, 1e-9); /* the library complete at 0.2 s */
    out_text t;
    out_open(&t);
    swe_estimate_print(t.f, &in, &o);
    char *s = out_close(&t);
    assert_string_equal(
        s, "Allrun: estimate: 102568 cells, 6 clouds, 46125 parcels injected (26125 in split classes); "
           "about 3200 time steps (800 with the flow solved); memory 3.1 GB (flow 1.1 GB incl. a 0.9 "
           "GB replay library, parcels at most 2 GB), unknown available; disk 3.5 GB (fields and the "
           "stored flow library 0.97 GB, parcel records at most 2.6 GB), unknown free; time about 14 min "
           "on 1 process(es) (flow 8.3, particles 3.8 min, and about 2 min of set-up and "
           "post-processing; scaled from the default run measured on this machine)\n");
    free(s);
    char msg[512];
    in.avail = 2e9;
    in.free_disk = 1e12;
    assert_int_equal(swe_estimate_refuse(&in, &o, msg, sizeof msg), 0);
    in.avail = 0.5e9; /* the flow and library need 1.1 GB */
    assert_int_equal(swe_estimate_refuse(&in, &o, msg, sizeof msg), 2);
    assert_non_null(strstr(msg, "100 snapshots x 102568 cells"));
    assert_non_null(strstr(msg, "more than the 0.5 GB available"));
    in.avail = 2e9;
    in.free_disk = 0.5e9; /* the fields and library 0.97 GB */
    assert_int_equal(swe_estimate_refuse(&in, &o, msg, sizeof msg), 2);
    assert_non_null(strstr(msg, "more than the 0.5 GB free"));
    /* the flow, the library and the parcels above 80 % of 2 GB: the library streamed,
       two of its 100 snapshots in memory; with 0.1 GB even that refused */
    in = coarse_default();
    in.avail = 2e9;
    swe_estimate(&in, &o);
    assert_int_equal(o.streamed, 1);
    ASSERT_NEAR(o.mem_flow, 102568 * 2048 + 2 * o.lib / 100, 1);
    out_open(&t);
    swe_estimate_print(t.f, &in, &o);
    s = out_close(&t);
    assert_non_null(strstr(s, "incl. two snapshots of a 0.9 GB replay library streamed from disk: it does not fit,"));
    free(s);
    assert_int_equal(swe_estimate_refuse(&in, &o, msg, sizeof msg), 0);
    in.avail = 1e8;
    swe_estimate(&in, &o);
    assert_int_equal(swe_estimate_refuse(&in, &o, msg, sizeof msg), 2);
    assert_non_null(strstr(msg, "even with the library streamed"));
    in.avail = 100e9; /* room for all: in memory */
    swe_estimate(&in, &o);
    assert_int_equal(o.streamed, 0);
    /* -halfstep: twice the steps */
    in = coarse_default();
    in.halfstep = 1;
    swe_estimate(&in, &o);
    ASSERT_NEAR(o.steps, 6400, 1e-9);
}

static void estimate_steady(void **st)
{
    (void)st;
    swe_estimate_in in = coarse_default();
    in.steady = 1;
    in.ppn = 4000;
    in.compare = 1;
    swe_estimate_out o;
    swe_estimate(&in, &o);
    out_text t;
    out_open(&t);
    swe_estimate_print(t.f, &in, &o);
    char *s = out_close(&t);
    assert_non_null(strstr(s, "Allrun: estimate: 100568 cells, 4 cloud(s), 100000 parcels injected each (steady route"));
    free(s);
}

static void nozzles(void **st)
{
    (void)st;
    char(*p)[128] = NULL;
    assert_int_equal(swe_wake_points(&p), 9);
    assert_string_equal(p[0], "0.36 -0.0399 -0.0399");
    assert_string_equal(p[4], "0.36 0.0001 0.0001");
    out_text t;
    out_open(&t);
    swe_nozzles_write(t.f, p, 1, 3, "0.1", 0.5, "0.7", 20, 1, NULL);
    char *s = out_close(&t);
    assert_string_equal(s, "// generated by Allrun (write_nozzles): 1 nozzles, 3 parcels each\n"
                           "nozzle0\n{\n    type coneInjection;\n    SOI 0.1;\n    massTotal 0.5;\n"
                           "    parcelBasisType mass;\n    duration 0.7;\n    parcelsPerInjector 3;\n"
                           "    flowRateProfile constant 1;\n    Umag constant 1;\n"
                           "    thetaInner constant 0;\n    thetaOuter constant 90;\n"
                           "    positionAxis ( ((0.36 -0.0399 -0.0399) (1 0 0)) );\n"
                           "    sizeDistribution { type fixedValue; fixedValueDistribution { value 2e-05; } }\n}\n");
    free(s);
    free(p);
}

/* the nozzle side (x <= the first centre downstream of -0.45) first, then by y;
   equal y in the order of the lines "index x y flag" as bytes (10 before 2) */
static void decompose(void **st)
{
    (void)st;
    const double x[6] = {-0.5, -0.4, -0.4, 0.1, 0.1, 0.1}, y[6] = {0, 0.2, -0.2, 0.1, -0.1, 0.3};
    int p[10];
    char err[128];
    assert_int_equal(swe_decompose(x, y, 6, 2, -0.45, p, err, sizeof err), 0);
    const int two[6] = {0, 0, 0, 1, 1, 1};
    assert_memory_equal(p, two, sizeof two);
    assert_int_equal(swe_decompose(x, y, 6, 3, -0.45, p, err, sizeof err), 0);
    const int three[6] = {0, 1, 0, 2, 1, 2};
    assert_memory_equal(p, three, sizeof three);
    const double z[10] = {0};
    assert_int_equal(swe_decompose(z, z, 10, 2, -0.45, p, err, sizeof err), 0);
    const int ties[10] = {0, 0, 0, 0, 1, 1, 1, 1, 1, 0};
    assert_memory_equal(p, ties, sizeof ties);
    const double up[2] = {-1, -2};
    assert_int_not_equal(swe_decompose(up, up, 2, 2, -0.45, p, err, sizeof err), 0);
    assert_non_null(strstr(err, "downstream"));
}

static const char *part1 = "deltaT = 0.1\nTime = 0.1\nWall time [s], largest: flow 1, cloudA 0.5\n"
                           "deltaT = 0.1\nTime = 0.2\nWall time [s], largest: flow 2, cloudA 1\n"
                           "deltaT = 0.1\nTime = 0.3\nWall time [s], largest: flow 3, cloudA 1.5\n"
                           "deltaT = 0.1\nTime = 0.4\nWall time [s], largest: flow 4, cloudA 2\n";
static const char *part2 = "banner\ndeltaT = 0.1\nTime = 0.3\nWall time [s], largest: flow 1.25, cloudA 0.25\n"
                           "deltaT = 0.1\nTime = 0.4\nWall time [s], largest: flow 2.5, cloudA 0.5\n";

/* the run's record: 4 steps, 2 in the window 0.2 < t <= 0.4, the last wall times */
static void level(void **st)
{
    (void)st;
    FILE *log = in_text(part1);
    const swe_level_in in = {.level = "1", .variant = "test", .refine_wake = "0", .halfstep = "0",
                             .full = "0", .step_scale = "0.7", .cells = "99", .max_delta_t = "0.0007",
                             .replay_interval = "", .gate = "off", .mvd = "20", .rear_layers = "1",
                             .rear_yplus = "0.2 1 2", .window0 = "0.2", .window1 = "0.4", .t0 = 0.2, .t1 = 0.4};
    out_text t;
    out_open(&t);
    char err[128];
    assert_int_equal(swe_level_write(log, &in, t.f, err, sizeof err), 0);
    fclose(log);
    char *s = out_close(&t);
    assert_non_null(strstr(s, "\nreplay_interval -\ntime_steps 4\nwindow 0.2 0.4\nwindow_steps 2\nmean_delta_t 0.1\n"
                              "wall_flow_s 4\nwall_clouds_s 2\n"));
    assert_non_null(strstr(s, "rear_yplus 0.2 1 2\n"));
    free(s);
    log = in_text("Time = 0.1\n");
    out_open(&t);
    assert_int_not_equal(swe_level_write(log, &in, t.f, err, sizeof err), 0);
    fclose(log);
    free(out_close(&t));
}

static void yplus(void **st)
{
    (void)st;
    FILE *f[2] = {in_text("# Time\tpatch\tmin\tmax\taverage\n0.1\tnose\t9\t99\t50\n0.1\trear   \t0.5\t2\t1\n"),
                  in_text("0.2\t rear\t0.25\t1.5\t2\n")};
    double mn, mean, mx;
    assert_int_equal(swe_yplus_rear(f, 2, &mn, &mean, &mx), 2);
    ASSERT_NEAR(mn, 0.25, 0);
    ASSERT_NEAR(mean, 1.5, 0);
    ASSERT_NEAR(mx, 2, 0);
    fclose(f[0]), fclose(f[1]);
}

/* part 2 starts at 0.3 - 0.1 = 0.2: part 1's steps after 0.2 dropped; part 2's wall
   times offset by part 1's at its cut (flow 2, cloudA 1) */
static void join_logs(void **st)
{
    (void)st;
    FILE *p[2] = {in_text(part1), in_text(part2)};
    out_text t;
    out_open(&t);
    char err[128];
    assert_int_equal(swe_join_logs(p, 2, t.f, err, sizeof err), 0);
    fclose(p[0]), fclose(p[1]);
    char *s = out_close(&t);
    assert_string_equal(s, "deltaT = 0.1\nTime = 0.1\nWall time [s], largest: flow 1, cloudA 0.5\n"
                           "deltaT = 0.1\nTime = 0.2\nWall time [s], largest: flow 2, cloudA 1\n"
                           "deltaT = 0.1\n"
                           "banner\ndeltaT = 0.1\nTime = 0.3\nWall time [s], largest: flow 3.25, cloudA 1.25\n"
                           "deltaT = 0.1\nTime = 0.4\nWall time [s], largest: flow 4.5, cloudA 1.5\n");
    free(s);
}

static void join_table(void **st)
{
    (void)st;
    FILE *a = in_text("# Time Cd\n0.1 1\n0.2 2\n0.3 3\n"), *b = in_text("# Time Cd\n0.25 5\n0.3 6\n");
    out_text t;
    out_open(&t);
    swe_join_table(a, b, 0.2, t.f);
    fclose(a), fclose(b);
    char *s = out_close(&t);
    assert_string_equal(s, "# Time Cd\n0.1 1\n0.2 2\n0.25 5\n0.3 6\n");
    free(s);
}

static const char *ladder = "# setting variant coarse\n# setting gate off\n# note the fill is short\n"
                            "quantity,run,design,level,cells,step,value,se,t_flow,t_clouds\n"
                            "Cd,a,default,0,100,1e-3,0.4,0.01,1,1\nCd,b,default,1,200,1e-3,0.4,0.01,1,1\n";

static void ladder_why(void **st)
{
    (void)st;
    FILE *f = in_text(ladder);
    char why[512];
    const char *same[2] = {"variant coarse", "gate off"}, *other[2] = {"variant test", "gate off"};
    swe_ladder_why(f, same, 2, "1", "200", why, sizeof why);
    assert_string_equal(why, "");
    swe_ladder_why(f, other, 2, "1", "300", why, sizeof why);
    assert_string_equal(why, "variant test here, coarse on the ladder; level 1 has 200 cells on the ladder, 300 "
                             "here (another mesh: -test, -fine, -refine-wake or -no-rear-layers)");
    swe_ladder_why(f, same, 2, "-1", "300", why, sizeof why);
    assert_string_equal(why, "level -1 is not on the ladder");
    out_text t;
    out_open(&t);
    swe_ladder_notes(f, t.f);
    fclose(f);
    char *s = out_close(&t);
    assert_string_equal(s, "\n## Notes of the ladder file (what its total leaves out, how to read it)\n\n"
                           "* the fill is short\n");
    free(s);
}

/* rows of the run: the face (sampling 5 % of 2, discretization 12 %), a class, Cd
   (sampling 1.1 %, discretization 5.3 %: total 5.4 %, never below a component) */
static void total_error(void **st)
{
    (void)st;
    FILE *csv = in_text("quantity,run,design,level,cells,t_total_s,value,se,disc,total,rel_total,reference,reference_kind\n"
                        "Cd,r,default,0,9,1,0.4,0.004,0.02,x,0.0536656,0.38,extrapolated\n"
                        "face-mvd20,r,default,0,9,1,0.0021,0.0001,0.00024,x,0.13,0.002,finest\n"
                        "face-mvd20,other,default,0,9,1,1,1,1,x,1,1,finest\n"
                        "capture-5um,r,default,0,9,1,28,0,0,x,,0,finest\n");
    out_text t;
    out_open(&t);
    assert_int_equal(swe_total_error_table(csv, "r", "20", "L.csv", "0", "9", t.f), 0);
    fclose(csv);
    char *s = out_close(&t);
    assert_non_null(strstr(s, "Rear face, decided spray (MVD 20 um): total error 13 % (sampling 5.0 %, discretization 12 %).\n"));
    assert_non_null(strstr(s, "|---|---:|---:|---:|---:|---:|---|\n"
                              "| whole face [g / 30 min] | 2.1 | 5.0 % | 12 % | 13 % | 2 | finest |\n"
                              "| class 5um [ppm] | 28 | - | - | - | 0 | finest |\n"
                              "| Cd | 0.4 | 1.1 % | 5.3 % | 5.4 % | 0.38 | extrapolated |\n"));
    assert_null(strstr(s, ", a bound: the ladder"));
    free(s);
    /* a face judged against a ladder that does not resolve its steps: the headline
       says that its total is a bound over both readings */
    csv = in_text("quantity,run,design,level,cells,t_total_s,value,se,disc,total,rel_total,reference,reference_kind\n"
                  "face-mvd20,r,default,0,9,1,0.000304,4.26e-5,0.000102,x,0.70,0.000158,bound\n");
    out_open(&t);
    assert_int_equal(swe_total_error_table(csv, "r", "20", "L.csv", "0", "9", t.f), 0);
    fclose(csv);
    s = out_close(&t);
    assert_non_null(strstr(s, "Rear face, decided spray (MVD 20 um): total error 70 % (sampling 27 %, "
                              "discretization 65 %), a bound: the ladder does not resolve its steps"));
    assert_non_null(strstr(s, "| whole face [g / 30 min] | 0.304 | 27 % | 65 % | 70 % | 0.158 | bound |\n"));
    free(s);
}

/* the time left at the phase's rate: 0.04258 s of solver time in 200 s, 0.04742 s to go
   to the end of the solved flow: 223 s; in the replay phase to the end of the run */
static void progress(void **st)
{
    (void)st;
    char s[512];
    swe_progress_line(s, sizeof s, 0.05258, 0.2, 0.1, 0, 0.01, 251, 200, 300);
    assert_string_equal(s, "Allrun [300 s]: solver at t = 0.05258 of 0.2 s (26 %), 251 s elapsed, about 223 s "
                           "left of the solved flow (to t = 0.1 s; the replay after it is faster)");
    swe_progress_line(s, sizeof s, 0.15, 0.2, 0.1, 1, 0.1, 400, 50, 450);
    assert_string_equal(s, "Allrun [450 s]: solver at t = 0.15 of 0.2 s (75 %), 400 s elapsed, about 50 s left");
    swe_progress_line(s, sizeof s, 0.1, 0.2, -1, 0, 0.1, 30, 0, 60);
    assert_non_null(strstr(s, "time left not yet estimated"));
}

/* the spray's bounds and the classes' consistency, refused with the dictionary's texts */
static void spray_checks(void **st)
{
    (void)st;
    char err[512];
    assert_int_equal(swe_check_spray("20", "1.8", "1.03", "2", "150", err, sizeof err), 0);
    assert_int_equal(swe_check_spray("20", "1", "1.03", "2", "150", err, sizeof err), 2);
    assert_non_null(strstr(err, "got mvd 20, sigmaG 1, freeze 1.03, range (2 150)"));
    assert_int_equal(swe_check_spray("20", "1.8", "1.03", "0.05", "150", err, sizeof err), 2);
    assert_int_equal(swe_check_classes("5,10,20,40,80", "100,300,345,200,100", err, sizeof err), 0);
    assert_int_equal(swe_check_classes("5,10", "100", err, sizeof err), 2);
    assert_non_null(strstr(err, "got (5,10) and (100)"));
    assert_int_equal(swe_check_classes("5,1001", "1,1", err, sizeof err), 2);
    assert_int_equal(swe_check_classes("5,10,5", "1,1,1", err, sizeof err), 2);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(mesh),      cmocka_unit_test(estimate_default), cmocka_unit_test(estimate_steady),
        cmocka_unit_test(nozzles),   cmocka_unit_test(decompose),        cmocka_unit_test(level),
        cmocka_unit_test(yplus),     cmocka_unit_test(join_logs),        cmocka_unit_test(join_table),
        cmocka_unit_test(ladder_why), cmocka_unit_test(total_error),      cmocka_unit_test(progress),
        cmocka_unit_test(spray_checks),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
