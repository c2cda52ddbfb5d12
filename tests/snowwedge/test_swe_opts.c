/* test_swe_opts.c - the command line of tutorials/wedge/Allrun (tools/snowwedge/swe_opts.c)
 * on a temporary case folder with a known constant/variants: the defaults of each
 * route, every refusal's text and code, the order of the checks (an option refused
 * as it is met before a cross-check; the transient-only options in their order),
 * the list rule (empty items, a value twice, a numeric list put in ascending order
 * with a note), -ladder made absolute as `cd DIR && pwd` shows it, -resume reading
 * log.Allrun.args, the variant's block, and the quoting of the assignments. */
#include <limits.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include <cmocka.h>

#include "swe_opts.h"
#include "swe_run.h"

static char dir[PATH_MAX], old[PATH_MAX];

static const char *variants = "FoamFile { object variants; }\n"
                              "// test: a comment naming mesh\n"
                              "test\n{\n"
                              "    mesh            \"nxUp 8; nxBody 12; nxDown 16; nBody 12; nOut 7;\";   // quoted\n"
                              "    parcelFactor    0.25;\n"
                              "    classFactor     0.125;     // the machinery only\n"
                              "    steadyFactor    0.05;\n"
                              "    spinUpTime      0.05;\n"
                              "    empty           ;\n"
                              "}\n"
                              "coarse\n{\n"
                              "    mesh   \"nxUp 12; nxBody 22; nxDown 28; nBody 20; nOut 11;\";\n"
                              "    parcelFactor 1;\n    classFactor 1;\n    steadyFactor 1;\n"
                              "    roughGrid \"--points 32\";\n"
                              "}\n"
                              "fine\n{\n    mesh \"nxUp 16;\";\n}\n";

static void write_file(const char *path, const char *text)
{
    FILE *f = fopen(path, "w");
    assert_non_null(f);
    fputs(text, f);
    fclose(f);
}

static int setup(void **state)
{
    (void)state;
    assert_non_null(getcwd(old, sizeof old));
    snprintf(dir, sizeof dir, "/tmp/test_swe_opts.XXXXXX");
    assert_non_null(mkdtemp(dir));
    assert_int_equal(chdir(dir), 0);
    assert_int_equal(mkdir("constant", 0755), 0);
    assert_int_equal(mkdir("sub", 0755), 0);
    assert_int_equal(mkdir("system", 0755), 0);
    assert_int_equal(mkdir("constant/gates", 0755), 0);
    write_file("constant/variants", variants);
    write_file("constant/gates/regime", "tangentialGate\n{\n    // slideLength 3;\n    slideLength 1e-4;   // [m]\n"
                                        "    vtTable     ( 0 0.05\t0.1 );   // [m/s]\n}\n");
    write_file("system/controlDict.transient", "deltaT 1e-4;\nmaxDeltaT       1e-3; // max\n");
    write_file("sub/ladder.csv", "quantity\n");
    return 0;
}

static int teardown(void **state)
{
    (void)state;
    unlink("constant/variants");
    unlink("sub/ladder.csv");
    unlink("log.Allrun.args");
    unlink("constant/gates/regime");
    unlink("system/controlDict.transient");
    rmdir("constant/gates");
    rmdir("system");
    rmdir("constant");
    rmdir("sub");
    assert_int_equal(chdir(old), 0);
    rmdir(dir);
    return 0;
}

/* parse the words of ARGS (blank-separated; "" for none) on NCPU processors */
static int parse(const char *args, long ncpu, swe_allrun *o, char *err, size_t nerr)
{
    char buf[512], *words[32];
    int n = 0;
    snprintf(buf, sizeof buf, "%s", args);
    for (char *save = NULL, *w = strtok_r(buf, " ", &save); w; w = strtok_r(NULL, " ", &save))
        words[n++] = w;
    err[0] = '\0';
    return swe_opts_parse(n, words, dir, ncpu, o, NULL, err, nerr);
}

/* ARGS refused with code CODE and exactly the message WANT */
static void refused(const char *args, long ncpu, int code, const char *want)
{
    swe_allrun o;
    char err[1024];
    const int rc = parse(args, ncpu, &o, err, sizeof err);
    swe_opts_free(&o);
    if (rc != code || strcmp(err, want))
        fail_msg("'%s': %d '%s', want %d '%s'", args, rc, err, code, want);
}

static void test_variant(void **state)
{
    (void)state;
    char v[128];
    assert_int_equal(swe_opts_variant("constant/variants", "test", "mesh", v, sizeof v), 0);
    assert_string_equal(v, "nxUp 8; nxBody 12; nxDown 16; nBody 12; nOut 7;");
    assert_int_equal(swe_opts_variant("constant/variants", "test", "classFactor", v, sizeof v), 0);
    assert_string_equal(v, "0.125");
    assert_int_equal(swe_opts_variant("constant/variants", "test", "empty", v, sizeof v), 1);
    assert_int_equal(swe_opts_variant("constant/variants", "test", "roughGrid", v, sizeof v), 1);
    assert_int_equal(swe_opts_variant("constant/variants", "coarse", "roughGrid", v, sizeof v), 0);
    assert_string_equal(v, "--points 32");
    /* the block ends at its '}': fine's mesh is not coarse's parcelFactor */
    assert_int_equal(swe_opts_variant("constant/variants", "fine", "parcelFactor", v, sizeof v), 1);
    assert_int_equal(swe_opts_variant("constant/no-such", "test", "mesh", v, sizeof v), -1);
}

static void test_entry(void **state)
{
    (void)state;
    char v[128];
    assert_int_equal(swe_opts_entry("constant/gates/regime", "slideLength", v, sizeof v), 0);
    assert_string_equal(v, "1e-4"); /* the commented-out line skipped */
    assert_int_equal(swe_opts_entry("constant/gates/regime", "vtTable", v, sizeof v), 0);
    assert_string_equal(v, "( 0 0.05\t0.1 )");
    assert_int_equal(swe_opts_entry("constant/gates/regime", "vt", v, sizeof v), 1);
    assert_int_equal(swe_opts_entry("constant/no-such", "vt", v, sizeof v), -1);
}

static void test_quote(void **state)
{
    (void)state;
    char *buf = NULL;
    size_t len = 0;
    FILE *f = open_memstream(&buf, &len);
    swe_opts_quote(f, "a'b $(x) \"c\"");
    fclose(f);
    assert_string_equal(buf, "'a'\\''b $(x) \"c\"'");
    free(buf);
}

static void test_list(void **state)
{
    (void)state;
    char out[64], err[256], *notes = NULL;
    size_t len = 0;
    FILE *f = open_memstream(&notes, &len);
    assert_int_equal(swe_opts_list("-sizes", "20,5,10", 1, out, sizeof out, f, err, sizeof err), 0);
    fclose(f);
    assert_string_equal(out, "5,10,20");
    assert_string_equal(notes, "Allrun: note: -sizes: '20,5,10' taken in ascending order\n");
    free(notes);
    assert_int_equal(swe_opts_list("-sizes", "5,10,05", 1, out, sizeof out, NULL, err, sizeof err), 2);
    assert_string_equal(err, "-sizes: '05' is given twice in '5,10,05'");
    assert_int_equal(swe_opts_list("-sizes", "5,,10", 1, out, sizeof out, NULL, err, sizeof err), 2);
    assert_string_equal(err, "-sizes: an empty item in '5,,10'");
    assert_int_equal(swe_opts_list("-sizes", "", 1, out, sizeof out, NULL, err, sizeof err), 2);
    assert_string_equal(err, "-sizes: an empty list");
    assert_int_equal(swe_opts_list("-sizes", "5,x", 1, out, sizeof out, NULL, err, sizeof err), 2);
    assert_string_equal(err, "-sizes: 'x' in '5,x' is not a number");
    /* names keep their order; "05" and "5" are two names */
    assert_int_equal(swe_opts_list("-d", "crw,05,5", 0, out, sizeof out, NULL, err, sizeof err), 0);
    assert_string_equal(out, "crw,05,5");
    assert_int_equal(swe_opts_list("-d", "crw,none,crw", 0, out, sizeof out, NULL, err, sizeof err), 2);
    assert_string_equal(err, "-d: 'crw' is given twice in 'crw,none,crw'");
}

static void spray(const char *kind, const char *value, int code, const char *want)
{
    char out[256], err[512];
    const int rc = swe_opts_spray_entry(NULL, kind, "k/e", value, out, sizeof out, err, sizeof err);
    if (rc != code || strcmp(rc ? err : out, want))
        fail_msg("%s '%s': %d '%s', want %d '%s'", kind, value, rc, rc ? err : out, code, want);
}

static void test_spray_entry(void **state)
{
    (void)state;
    spray("num", "2.5e-3", 0, "2.5e-3");
    spray("num", "+.5", 0, "+.5");
    spray("num", "0", 2, "constant/sprayProperties: 'k/e' must be a positive number, got '0'");
    spray("num", "(1)", 2, "constant/sprayProperties: 'k/e' must be a positive number, got '(1)'");
    spray("num", "", 2, "constant/sprayProperties: 'k/e' must be a positive number, got '<missing>'");
    spray("list2", "(10  40)", 0, "10 40");
    spray("list2", "(40 10)", 2,
          "constant/sprayProperties: 'k/e' must be two positive numbers, the first the smaller, got '40 10'");
    spray("list2", "( 1 2 3 )", 2,
          "constant/sprayProperties: 'k/e' must be two positive numbers, the first the smaller, got '1 2 3'");
    spray("intlist", "(5 10\n 20)", 0, "5,10,20");
    spray("intlist", "(5 010)", 2, "constant/sprayProperties: 'k/e' must be a list of whole numbers from 1, got '5 010'");
    spray("intlist", "(12345678)", 2,
          "constant/sprayProperties: 'k/e' must be a list of whole numbers from 1, got '12345678'");
    spray("intlist", "()", 2, "constant/sprayProperties: 'k/e' must be a list of whole numbers from 1, got '<missing>'");
}

/* the last step of a solver log (swe_run.c, read by snowwedge progress --watch) */
static void test_last_time(void **state)
{
    (void)state;
    char t[64];
    write_file("log.t", "Time = 0.01\nCourant\nTime = 0.025\nExecutionTime = 1 s\n");
    assert_int_equal(swe_last_time("log.t", t, sizeof t), 0);
    assert_string_equal(t, "0.025");
    /* the step being written (no newline yet) counts; " Time = " (indented) does not */
    write_file("log.t", "Time = 0.01\n Time = 9\nTime = 0.02");
    assert_int_equal(swe_last_time("log.t", t, sizeof t), 0);
    assert_string_equal(t, "0.02");
    /* the last step 200 000 bytes before the end: found across the blocks */
    FILE *f = fopen("log.t", "w");
    assert_non_null(f);
    fputs("Time = 0.5\nTime = 0.75\n", f);
    for (int i = 0; i < 10000; i++)
        fputs("Courant Number mean: 0\n", f);
    fclose(f);
    assert_int_equal(swe_last_time("log.t", t, sizeof t), 0);
    assert_string_equal(t, "0.75");
    write_file("log.t", "no step yet\n");
    assert_int_equal(swe_last_time("log.t", t, sizeof t), 0);
    assert_string_equal(t, "");
    unlink("log.t");
    assert_int_equal(swe_last_time("log.t", t, sizeof t), 1);
}

static void test_defaults(void **state)
{
    (void)state;
    swe_allrun o;
    char err[256];
    assert_int_equal(parse("", 2, &o, err, sizeof err), 0);
    assert_string_equal(o.level, "coarse");
    assert_string_equal(o.route, "transient");
    assert_int_equal(o.rear_layers, 1);
    assert_int_equal(o.replay, 1);
    assert_string_equal(o.mesh, "nxUp 12; nxBody 22; nxDown 28; nBody 20; nOut 11;");
    assert_int_equal(o.ny, 42);
    assert_string_equal(o.level_scale, "1");
    assert_string_equal(o.ladder, "none"); /* the case holds no ladder */
    assert_string_equal(o.disp_main, "nearwall");
    assert_string_equal(o.disp_extra, "");
    assert_string_equal(o.spin, ""); /* the coarse block has no times */
    assert_string_equal(o.slide, "1e-4");
    assert_string_equal(o.vtlist, "0,0.05,0.1");
    assert_string_equal(o.max_delta_t, "1e-3");
    swe_opts_free(&o);
    assert_int_equal(parse("-steady -test -gate shear", 2, &o, err, sizeof err), 0);
    assert_int_equal(o.rear_layers, 0);
    assert_int_equal(o.replay, 0);
    assert_string_equal(o.parcel_factor, "0.25");
    assert_string_equal(o.spin, "0.05");
    assert_string_equal(o.ladder, "none");
    swe_opts_free(&o);
    write_file("constant/ladder.csv", "quantity\n");
    assert_int_equal(parse("-test -level 1 -no-rear-layers", 2, &o, err, sizeof err), 0);
    assert_string_equal(o.ladder, "constant/ladder.csv");
    assert_string_equal(o.mesh, "nxUp 11; nxBody 17; nxDown 23; nBody 17; nOut 10;"); /* x sqrt(2), half up */
    assert_string_equal(o.level_scale, "0.707106781187");
    unlink("constant/ladder.csv");
    swe_opts_free(&o);
    assert_int_equal(parse("-dispersion crw,nearwall,none -sizes 20,5 -parallel 2 -oversubscribe", 1, &o, err,
                           sizeof err),
                     0);
    assert_string_equal(o.disp_main, "crw");
    assert_string_equal(o.disp_extra, "nearwall none");
    assert_string_equal(o.sizes, "5,20");
    assert_int_equal(o.mpi_oversubscribe, 1);
    swe_opts_free(&o);
    assert_int_equal(parse("-halfstep", 2, &o, err, sizeof err), 0);
    assert_string_equal(o.max_delta_t, "5e-4");
    swe_opts_free(&o);
    assert_int_equal(parse("-sizes none -test --help -gate on", 2, &o, err, sizeof err), 0);
    assert_int_equal(o.help, 1); /* help stops the reading: -gate on not seen */
    swe_opts_free(&o);
}

static void test_refusals(void **state)
{
    (void)state;
    refused("-gate on --help", 2, 2, "-gate must be off, tangential, shear or regime, got 'on'");
    refused("-parallel 007", 2, 2, "-parallel needs a whole number of processes from 1 (without leading zeros), got '007'");
    refused("-parallel 1234567", 2, 2,
            "-parallel needs a whole number of processes from 1 (without leading zeros), got '1234567'");
    refused("-parallel", 2, 2, "-parallel needs a whole number of processes from 1 (without leading zeros), got ''");
    refused("-parallel 3", 2, 2, "-parallel 3: this machine has 2 processors (nproc); accepted: 1 to 2 (up to 8 with -oversubscribe)");
    refused("-parallel 9 -oversubscribe", 2, 2, "-parallel 9: accepted with -oversubscribe: 1 to 8 (4 x the 2 processors of nproc)");
    refused("-oversubscribe", 2, 2, "-oversubscribe needs -parallel N with N > 1");
    refused("-fine -test", 2, 2, "-test with -fine: give one mesh level (-fine or -test)");
    refused("-level 4", 2, 2, "-level needs a whole number from -3 to 3, got '4'");
    refused("-level +1", 2, 2, "-level needs a whole number from -3 to 3, got '+1'");
    refused("-checkpoint 5.", 2, 2, "-checkpoint needs a positive number of minutes (at most 1e6) or off, got '5.'");
    refused("-checkpoint 1.1e6", 2, 2, "-checkpoint needs a positive number of minutes (at most 1e6) or off, got '1.1e6'");
    refused("-sizes 5.5", 2, 2, "-sizes needs whole diameters in um (1..1000), comma-separated, or none, got '5.5'");
    refused("-sizes 1001,5", 2, 2, "-sizes needs whole diameters in um (1..1000), comma-separated, or none, got '1001,5'");
    refused("-dispersion nearwall,nearwall-tau", 2, 2,
            "-dispersion needs a comma-separated list of nearwall, nearwall-utau, nearwall-k, crw, stochastic, "
            "gradient, none; got 'nearwall,nearwall-tau'");
    refused("-parallell 2", 2, 2, "unknown option '-parallell' (see --help)");
    refused("-test -resume", 2, 2, "-resume is the only option of its command line (the run goes on with its own)");
    refused("-resume -test", 2, 2, "-resume takes no other option: the run goes on with its own (log.Allrun.args)");
    refused("-ladder", 2, 2, "-ladder needs a file (a ladder.csv of post/wedge-ladder) or none");
    refused("-ladder sub", 2, 2, "-ladder sub: not a readable file");
    /* the cross-checks after the whole line, in their order */
    refused("-steady -sizes 5 -feedback", 2, 2, "-sizes needs the transient route (not -steady)");
    refused("-wake-source -sizes none", 2, 2, "-wake-source releases the size classes in the wake: not with -sizes none");
    refused("-steady -checkpoint 5 -halfstep -replay -rough", 2, 2, "-rough needs the transient route (not -steady)");
    refused("-steady -checkpoint 5 -halfstep", 2, 2, "-halfstep needs the transient route (not -steady)");
    refused("-steady -rear-layers", 2, 2,
            "-rear-layers needs the transient route (simpleFoam does not converge on the resolved rear face; the "
            "steady route keeps its wall function there)");
    refused("-steady -dispersion crw,none", 2, 2, "several -dispersion treatments need the transient route (not -steady)");
    /* the variant's block after the options, -parallel after it */
    refused("-fine -parallel 99", 2, 2, "constant/variants: no parcelFactor for the variant fine");
    refused("-test -rough", 2, 2, "constant/variants: no roughGrid for the variant test");
    write_file("constant/gates/regime", "slideLength 1e-4;\n");
    refused("-test", 2, 2, "constant/gates/regime: slideLength and vtTable are required");
    write_file("constant/gates/regime", "slideLength 1e-4;\nvtTable (0 1);\n");
    /* the mesh's cells along y after -parallel against the processors */
    refused("-test -parallel 27 -oversubscribe", 8, 2,
            "-parallel 27: the test mesh has 26 cells along y and every process needs a slab of at least one: "
            "accepted 1 to 26");
}

static void test_ladder_and_resume(void **state)
{
    (void)state;
    swe_allrun o;
    char err[512], want[PATH_MAX + 128];
    /* relative: from the case folder by name ("." and ".." taken as written) */
    assert_int_equal(parse("-ladder ./sub/../sub/ladder.csv -test -ladder sub/ladder.csv", 2, &o, err, sizeof err), 0);
    snprintf(want, sizeof want, "%s/sub/ladder.csv", dir);
    assert_string_equal(o.ladder, want);
    assert_int_equal(o.nargs, 5);
    assert_string_equal(o.args[1], want); /* every -ladder's file: the one in effect */
    assert_string_equal(o.args[4], want);
    swe_opts_free(&o);
    snprintf(want, sizeof want,
             "-resume: no run to resume in %s (log.Allrun.args is missing: a run writes it when it starts)", dir);
    refused("-resume", 2, 2, want);
    write_file("log.Allrun.args", "-steady\n-test\n");
    refused("-resume", 2, 2, "-resume: the steady route is not resumed (a few minutes: run it again)");
    write_file("log.Allrun.args", "-test\n-gate\nshear\n");
    assert_int_equal(parse("-resume", 2, &o, err, sizeof err), 0);
    assert_int_equal(o.resume, 1);
    assert_string_equal(o.gate, "shear");
    assert_int_equal(o.nargs, 3);
    swe_opts_free(&o);
    write_file("log.Allrun.args", "");
    assert_int_equal(parse("-resume", 2, &o, err, sizeof err), 0);
    assert_int_equal(o.nargs, 0);
    swe_opts_free(&o);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_variant), cmocka_unit_test(test_entry),  cmocka_unit_test(test_quote),     cmocka_unit_test(test_list), cmocka_unit_test(test_spray_entry), cmocka_unit_test(test_last_time),
        cmocka_unit_test(test_defaults), cmocka_unit_test(test_refusals), cmocka_unit_test(test_ladder_and_resume),
    };
    return cmocka_run_group_tests(tests, setup, teardown);
}
