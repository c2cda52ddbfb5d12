/* swe_main.c - snowwedge: the statistics of the wind-tunnel wedge's results
 * (tutorials/wedge/post): the spray's distribution and size classes, the
 * composition of the classes, the rear face's regions and their effective
 * sample sizes, and the force coefficients' mean, rms and spectral peak. */
#include "swe_cli.h"

#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

const char *swe_cli_usage =
"NAME\n"
"    snowwedge - the statistics of the wind-tunnel wedge (tutorials/wedge)\n"
"\n"
"SYNOPSIS\n"
"    snowwedge distribution SPRAY\n"
"    snowwedge weights (SPRAY | --masses CSV) --classes D1,D2,...\n"
"    snowwedge classes --weights FILE --table FILE --desc TEXT [SPRAY]\n"
"    snowwedge regions --weights FILE --table FILE --desc TEXT\n"
"    snowwedge map --weights FILE MAP.csv...\n"
"    snowwedge outline MAP.csv\n"
"    snowwedge rear-stats --label TEXT --from TA --to TB --outline MAP.csv\n"
"                         --kind sticks|impacts [RECORDS.post...]\n"
"    snowwedge forces --window T0,T1 COEFFICIENT.dat\n"
"    snowwedge probes --window T0,T1 PROBES_U\n"
"    snowwedge errortime [--target P] POINTS\n"
"    snowwedge spray-check --mvd UM --sigma-g S --freeze F --range MIN,MAX\n"
"                          [--sizes LIST --class-parcels LIST]\n"
"    snowwedge estimate --mesh MESH --nozzle-array FILE --ppn N --ppn-factor K\n"
"                       [--route steady] [--compare] [--np N] (transient:)\n"
"                       --class-factor K --spin T --fill T --sample T\n"
"                       [--sizes LIST --class-parcels LIST] [--dispersion LIST]\n"
"                       [--replay --replay-start T --replay-period T\n"
"                       --replay-interval T --max-delta-t T] [--level-scale S]\n"
"                       [--avail BYTES] [--free BYTES] [--feedback] [--rough]\n"
"                       [--rebound] [--split] [--full] [--halfstep]\n"
"                       [--rear-layers] [--wake-source]\n"
"    snowwedge mesh [--level N] [--refine-wake] MESH\n"
"    snowwedge times --spin T --fill T --sample T --class-factor K --rate R\n"
"                    --build-up T [--level N --level-scale S] [--full]\n"
"                    [--halfstep] [--checkpoint MIN|off] [--replay-start T\n"
"                    --replay-period T --replay-interval T]\n"
"    snowwedge progress --time T --end T [--flow-end T] [--phase flow|replay]\n"
"                       --phase-start T --elapsed S --phase-elapsed S --allrun S\n"
"    snowwedge nozzles (--array FILE | --wake) --derived FILE --parcels N\n"
"                      [--factor K] --size spray|UM\n"
"    snowwedge decompose --np N [--x-nozzle X] CX CY\n"
"    snowwedge level --log LOG --window T0,T1 --level N --variant V\n"
"                    --refine-wake B --halfstep B --full B --step-scale S\n"
"                    --cells N --max-delta-t T [--replay-interval T] --gate G\n"
"                    --mvd UM --rear-layers B [--rear-yplus TEXT]\n"
"    snowwedge yplus YPLUS.dat...\n"
"    snowwedge join-logs PART...\n"
"    snowwedge join-table --time T FIRST RESUMED\n"
"    snowwedge resume-time [--np N] [CASE]\n"
"    snowwedge restart-tables --time T [--remove | --join] POSTPROCESSING\n"
"    snowwedge ladder-check --ladder CSV --level N --cells N [KEY=VALUE...]\n"
"    snowwedge total-error --ladder CSV --mvd UM (--not-judged WHY |\n"
"                          --csv TOTAL_ERROR.csv --run NAME --level N --cells N)\n"
"    snowwedge --help\n"
"\n"
"    SPRAY is --mvd UM [--sigma-g S] [--range MIN,MAX] [--freeze F]: droplet\n"
"    mass log-normal with median volume diameter UM (0.1 .. 1000 um), geometric\n"
"    standard deviation S (1 < S <= 10, default 1.8), droplets MIN .. MAX um\n"
"    (default 2,150), ice diameter F x the droplet's (0.5 .. 2, default 1.03).\n"
"\n"
"DESCRIPTION\n"
"    distribution  the spray's mass density of the ice diameter as OpenFOAM's\n"
"             general distribution (constant/sprayDistribution): 121 diameters\n"
"             log-spaced over the frozen range, in m, density x 1e-6.\n"
"    weights  per class (ice diameters D1 < D2 < ... um) one line \"D w e0 e1\":\n"
"             its mass share w of the spray truncated to its range, and its edges\n"
"             (the geometric means of the neighbours, the range's ends outside).\n"
"             With --masses, lines \"d_um,mass\" (d_um one of the classes; #\n"
"             lines and blank lines skipped) normalized; e0, e1 then nan.\n"
"    classes  the markdown table of the classes of a composed spray (classes.md:\n"
"             edges, w, rear capture in ppm of the sprayed mass, its error\n"
"             1/sqrt(n_eff), share of the rear deposit) and the mass median\n"
"             diameters of the spray and of the rear deposit: the class holding\n"
"             it and, with SPRAY, interpolated (the log-normal within each class,\n"
"             the class's capture constant across it; bisection).\n"
"    regions  the markdown table of the composed rear-face regions (regions.md):\n"
"             deposit sum_k w_k M_k,r, its relative standard error\n"
"             (se^2 = sum (w_k M_k,r)^2 / n_eff_k,r), its mean per area over the\n"
"             face's, and whether it stands out by more than 2 standard errors;\n"
"             when every class has its halves, the halves of the window (x2)\n"
"             and their z = difference / its standard error (disagree: |z| > 2).\n"
"             --weights is the output of weights; --table one line per class:\n"
"             \"D injected deposit\" then mass and n_eff of left side, right side,\n"
"             centre, edges, whole face for the window, then (optional) the same\n"
"             ten for the first and the second half.\n"
"    map      the composed rear-face map: CSV y,z,deposit_kg_m2 summed over the\n"
"             maps (the class's diameter from the path .../d<D>um/FILE) with\n"
"             their weights, in the first map's order of faces.\n"
"    outline  \"y0 y1 z0 z1\" of a rear-face map: the face centres extended by\n"
"             half a face (6 significant digits).\n"
"    rear-stats  one markdown row \"| TEXT | left | right | centre | edges |\n"
"             whole face |\": per region the records with TA < Time <= TB\n"
"             (OpenFOAM .post files with the header # Time (position0 position1\n"
"             position2) origProc origId nParticle d rho), their independent\n"
"             origins, mass (nParticle rho pi d^3 / 6), effective sample size\n"
"             n_eff = (sum_a W_a)^2 / sum_a W_a^2 and error 1/sqrt(n_eff).\n"
"    forces   over T0 < t <= T1 of forceCoeffs' table: mean Cd, rms and\n"
"             dominant frequency of Cs and Cl (the largest peak of the transform\n"
"             on the uneven samples, 2/W .. 300 Hz in steps of 1/(4W)) and their\n"
"             Strouhal numbers f H / U (H 0.12 m, U 19.444 m/s); one line.\n"
"    probes   over T0 < t <= T1 of a probes table of U: mean and rms of Ux at\n"
"             every probe; one line.\n"
"    errortime  POINTS has one tab-separated line \"design run wall_s error\" per\n"
"             sampling design (error: relative, in %); prints a markdown row per\n"
"             line with the time that design needs for the target error P %\n"
"             (default 10) at its rate: wall_s (error / P)^2 (the error of n\n"
"             independent samples falls as 1/sqrt(n), the time grows as n).\n"
"    The commands below compute what tutorials/wedge/Allrun prints and writes\n"
"    (doc/reference/wedge-Allrun.md); MESH is \"nxUp N; nxBody N; nxDown N;\n"
"    nBody N; nOut N;\" (constant/variants).\n"
"    spray-check  exit 2 with one line unless the spray of constant/sprayProperties\n"
"             has mvd in [0.1, 1000] um, sigmaG in (1, 10], freeze in [0.5, 2] and a\n"
"             range within [0.1, 10000] um, and its classes (--sizes) at most 1000\n"
"             um each, once, with as many --class-parcels.\n"
"    estimate  the one line \"Allrun: estimate: ...\" of a run's cells, clouds,\n"
"             parcels, time steps, memory, disk and time, scaled from the default\n"
"             run measured (the model's constants: tools/snowwedge/swe_run.c);\n"
"             exit 2 with one line when the replay interval is shorter than\n"
"             maxDeltaT, or when the flow and its library exceed --avail bytes\n"
"             or the written fields --free bytes. --sizes gives the classes (the\n"
"             wake source's too), --class-parcels their parcels per nozzle\n"
"             (default: --ppn each).\n"
"    mesh     three lines: MESH with every count x sqrt(2)^N rounded half up (at\n"
"             least 1; with --refine-wake nxDown and nBody then x 1.25), the\n"
"             cells along y (nBody + 2 nOut) and the step scale sqrt(2)^-N.\n"
"    times    the transient route's times, \"KEY VALUE\" lines: with --full the\n"
"             class factor x 4 (fill + 2 window) / (fill + window) and the window\n"
"             doubled; the window t0 = spin + fill .. t1 and its middle, written\n"
"             every half window (exit 2 unless t0 is a whole multiple of it);\n"
"             the spray's SOI, massTotal R x T x (fill + window) / window and\n"
"             duration; the sampled share; with the replay its interval at the\n"
"             level (a whole fraction of the period; exit 2 unless the period\n"
"             is a whole multiple, at least 2, of the interval and the library\n"
"             ends by t1); the step scale, maxDeltaT (1e-3 s, 5e-4 s with\n"
"             --halfstep, x the scale, at most the interval), the first step\n"
"             1e-4 s x the scale, and the checkpoint in seconds.\n"
"    progress  Allrun's progress line: the solver's time of the end, the seconds\n"
"             elapsed and the time left at the rate of the phase since its first\n"
"             reading (--phase-start, --phase-elapsed seconds ago); in the flow\n"
"             phase of a replayed run the time left to --flow-end only.\n"
"    nozzles  one coneInjection per nozzle of the array (a line \"(x y z)\") or\n"
"             per wake-source point (9 points 0.06 m behind the rear face, 1 m/s\n"
"             into a downstream hemisphere), N x K parcels each (rounded; at\n"
"             least 1 for a diameter), SOI, duration and massTotal (shared) of\n"
"             FILE (constant/sprayDerived); --size spray: the spray's table.\n"
"    decompose  constant/cellDecomposition for N processes from the internal\n"
"             fields of the cell centres' x and y: the cells up to the first\n"
"             layer of centres downstream of X (default -0.45 m, the nozzles) to\n"
"             processor 0, then slabs along y of equal cell counts.\n"
"    level    results/level.txt from the solver's log: the steps, the steps and\n"
"             mean step in T0 < t <= T1, the last \"Wall time\" line's flow and\n"
"             the sum of its clouds; exit 2 when either is missing.\n"
"    yplus    \"min mean max\" of the rear patch's first-cell y+ over the rows of\n"
"             yPlus function-object tables (nothing when none).\n"
"    join-logs  the parts of an interrupted and resumed solver log as one run's:\n"
"             each part up to the start of the next (its first step's time less\n"
"             its deltaT), the \"Wall time\" entries of a part offset by the\n"
"             earlier parts' last values at their cut.\n"
"    join-table  a function object's table: FIRST's header and rows up to T,\n"
"             then RESUMED's rows.\n"
"    resume-time  the latest time folder after 0 that CASE (default .), or each\n"
"             of its processor0..N-1, holds whole (uniform/time, U, p, k, omega,\n"
"             nut non-empty); nothing when none; exit 2 when a processor folder\n"
"             is missing.\n"
"    restart-tables  the function-object tables a restart at T began: every\n"
"             file of NAME/T that NAME's first time folder also holds (NAME a\n"
"             folder of POSTPROCESSING but lagrangian), as \"FIRST NEW\" lines;\n"
"             --remove removes each NEW; --join joins it into FIRST (join-table)\n"
"             and removes it, then every empty NAME/T.\n"
"    ladder-check  why a run is not on a resolution ladder (post/wedge-ladder's\n"
"             ladder.csv): each KEY=VALUE against the ladder's \"# setting KEY\n"
"             VALUE\" line, the level and its cells against its rows; prints\n"
"             nothing when it is on it.\n"
"    total-error  results/total_error.md: the table of snowladder's\n"
"             total_error.csv for the run NAME (rear-face regions of the spray\n"
"             of MVD UM, classes, Cd, Cp_b, St: value, sampling, discretization,\n"
"             total error, reference), or the note that the run is not judged,\n"
"             then the ladder's \"# note\" lines.\n"
"\n"
"EXIT STATUS\n"
"    0 success; 1 an input file unreadable; 2 usage or bad input (one line\n"
"    naming the input and the value).\n";

int main(int argc, char **argv)
{
    if (argc < 2)
        swe_cli_die(2, "give a command (see --help)");
    if (!strcmp(argv[1], "-h") || !strcmp(argv[1], "--help")) {
        fputs(swe_cli_usage, stdout);
        return 0;
    }
    if (swe_cmd_run_is(argv[1])) /* Allrun's commands parse their own options */
        return swe_cmd_run(argc, argv);
    swe_options o = {0};
    swe_cli_parse(argc, argv, &o);
    int rc;
    if (!strcmp(argv[1], "distribution"))
        rc = swe_cmd_distribution(&o);
    else if (!strcmp(argv[1], "weights"))
        rc = swe_cmd_weights(&o);
    else if (!strcmp(argv[1], "classes"))
        rc = swe_cmd_classes(&o);
    else if (!strcmp(argv[1], "regions"))
        rc = swe_cmd_regions(&o);
    else if (!strcmp(argv[1], "map"))
        rc = swe_cmd_map(&o);
    else if (!strcmp(argv[1], "outline"))
        rc = swe_cmd_outline(&o);
    else if (!strcmp(argv[1], "rear-stats"))
        rc = swe_cmd_rear_stats(&o);
    else if (!strcmp(argv[1], "forces"))
        rc = swe_cmd_forces(&o);
    else if (!strcmp(argv[1], "probes"))
        rc = swe_cmd_probes(&o);
    else if (!strcmp(argv[1], "errortime"))
        rc = swe_cmd_errortime(&o);
    else
        swe_cli_die(2, "unknown command '%s' (see --help)", argv[1]);
    free(o.files);
    return rc;
}
