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
"    snowwedge ladder-level --name NAME RUN\n"
"    snowwedge ladder-rows --name NAME RUN\n"
"    snowwedge ladder-stored --what TEXT [--names \" A B \"] LADDER.csv\n"
"    snowwedge ladder-join --with LADDER.csv --family FAMILY --names \" A B \" RUNS.csv\n"
"    snowwedge ladder-plot --quantity Q --targets LIST --points FILE --png PNG\n"
"                          TOTAL_ERROR.csv\n"
"    snowwedge ladder-cheapest --quantity Q --targets LIST LADDER.md\n"
"    snowwedge resolution --base DIR --refined DIR [--mvd LIST] [--base-label A]\n"
"                         [--refined-label B]\n"
"    snowwedge errortime-points --region R CSV LABEL [CSV LABEL ...]\n"
"    snowwedge errortime-plot --region R --title TEXT --dir DIR POINTS\n"
"    snowwedge compose-check [--mvd UM --sigma-g S --range A,B --freeze F] --sampled F\n"
"    snowwedge compose-table --sampled F RESULTS D1 D2 ...\n"
"    per-run post-processing (tutorials/wedge/post/wedge-*; run in the case\n"
"    folder; every one takes --name NAME, the prefix of its messages):\n"
"    snowwedge rear-map [--minus RAW_A] [--factor K] RAW_B\n"
"    snowwedge patch-table --cloud C --csv FILE [--gate G] [--what TEXT] [--window T0,T1]\n"
"    snowwedge deposit --cloud C --patch P [--window T0,T1]\n"
"    snowwedge cloud-log --cloud C --log LOG\n"
"    snowwedge balance --cloud C --log LOG [--gate G]\n"
"    snowwedge rear-table --cloud C --file MAP.csv [--window T0,TH,T1]\n"
"    snowwedge convergence --cloud C --log LOG --window T0,TH,T1 --file STATS.md [--gate G]\n"
"    snowwedge time-dir --file NAME [--time T] PARENT\n"
"    snowwedge map-max [--rel F] [--exact] MAP.csv...\n"
"    snowwedge capture --results DIR [--sampled F] [--gate G] [--dispersion T]\n"
"    snowwedge fill --soi T --window T0,T1 [--level F] [--label TEXT] RECORDS.post...\n"
"    snowwedge cost --results DIR --log LOG --gate G --mvd UM\n"
"    snowwedge gates --results DIR\n"
"    snowwedge variant --variant feedback|rough|rebound --results DIR --gate G\n"
"                      [--log LOG] [--part notes]\n"
"    snowwedge dispersion --results DIR --main T [--others \"T2 T3 ...\"]\n"
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
"    ladder-level  a run of the resolution ladder (RUN/results/level.txt of\n"
"             Allrun -level): one tab-separated line: the window T0,T1, the scale\n"
"             1 / (0.5 U^2) of the base pressure, the row's columns\n"
"             NAME,design,level,cells,step and ,t_flow,t_clouds, the decided spray,\n"
"             the mesh family \"variant V;refine_wake R;halfstep H;rear_layers L;\n"
"             gate G;mvd M\" (a missing key: exit 1).\n"
"    ladder-rows  the run's rows of the collector's table (quantity,run,design,\n"
"             level,cells,step,value,se,t_flow,t_clouds): St of\n"
"             results/GATE/convergence.md with the spectrum's resolution error\n"
"             H / (U W sqrt(12)) for the window W; per composed spray\n"
"             (results/compose/mvdM/regions.md) left-, right-, centre-, edges-,\n"
"             face-mvdM; per class of the decided spray capture-Dum; se = value x\n"
"             relative error.\n"
"    ladder-stored  the rows of a stored ladder.csv: after '#' and blank lines\n"
"             its header, then rows of ten fields with a whole level and cell\n"
"             count, at least one, no run named in --names; else exit 2 with\n"
"             \"TEXT: line N: ...\".\n"
"    ladder-join  RUNS.csv joined with the stored rows of --with: its '# setting\n"
"             K V' lines must match FAMILY (exit 2); a quantity of the runs it\n"
"             lacks is left out with a note.\n"
"    ladder-plot  the relative total error of Q per run (total_error.csv of\n"
"             snowladder total) into --points as \"time error% run(design)\", and\n"
"             on standard output the gnuplot script of the log-log plot into PNG\n"
"             (ranges: half the least to twice the largest time, the least error\n"
"             / 1.5 to the largest x 1.5, targets included); no such Q: exit 2.\n"
"    ladder-cheapest  the cheapest run per target of Q from ladder.md's table\n"
"             \"## Discretization\": one line.\n"
"    resolution  Markdown: per composed spray (--mvd, default every one the two\n"
"             runs share) and region of DIR/compose/mvdM/regions.md, and per class\n"
"             of classes.md, B and R with their errors, the change R / B - 1, its\n"
"             error (R / B) sqrt((se_B / B)^2 + (se_R / R)^2), z = (R - B) /\n"
"             sqrt(se_B^2 + se_R^2) and the verdict: differs (|z| > 2) or agrees\n"
"             (the change within |R / B - 1| + 2 se at 2 sigma).\n"
"    errortime-points  the POINTS of errortime from cost tables of\n"
"             post/wedge-cost: every design but the flow with a positive wall\n"
"             time and an error of region R (face, left, right, centre, edges).\n"
"    errortime-plot  the points of each design into DIR/d_DESIGN and on standard\n"
"             output the gnuplot script into DIR/plot.png (the 1/sqrt(time) line\n"
"             through each point, the 10 % target).\n"
"    compose-check  the options of post/wedge-compose: plain numbers, MVD in\n"
"             [0.1, 1000], S in (1, 10], F in [0.5, 2], 0 < A < B <= 10000,\n"
"             sampled in (0, 1]; else exit 2 naming the first.\n"
"    compose-table  the --table of classes and regions: per class D of\n"
"             RESULTS/dDum \"D injected deposit\" (injected x sampled of\n"
"             mass_balance.txt, the rear of deposit_per_patch.csv), then mass and\n"
"             n_eff of the five regions of rear_statistics.md for the window and,\n"
"             when the class has both, its halves.\n"
"    The per-run post-processing (doc/reference/wedge-post.md; times as\n"
"    written, or last; deposits from postProcessing/deposit_<patch>/0/\n"
"    surfaceFieldValue.dat, counts from the wall model's <C>:snowWall/0/\n"
"    snowWall.dat (the row nearest a time) and <time>/reasons.dat):\n"
"    rear-map  CSV y,z,deposit_kg_m2 of K x (RAW_B - RAW_A) (raw surface files,\n"
"             the same faces), rows of constant z, y increasing.\n"
"    patch-table  deposit_per_patch.csv (to FILE) and .md (standard output):\n"
"             per wedge patch area, deposit, mean, counts and counts by reason\n"
"             over the window (or the totals at the last write); refused (1)\n"
"             when the counts by reason do not add up to the counts.\n"
"    deposit  a patch's deposit (over the window), 3 digits.\n"
"    cloud-log  \"parcels parcel_mass split\" of the cloud in the solver log.\n"
"    balance  mass_balance.txt: injected, escaped (the escaped records'\n"
"             nParticle rho pi d^3 / 6), airborne, deposited (logged and field),\n"
"             their relative errors, parcels, mean parcel mass, split.\n"
"    rear-table  rear_statistics.md: rear-stats rows of the stick records (else\n"
"             every impact) for the whole run or the window and its halves.\n"
"    convergence  convergence.md up to its y+ line: per patch the impacts and\n"
"             sticks of the window, the deposits of the window and of the\n"
"             halves x2, their difference about their mean and the Poisson\n"
"             error 100 / sqrt(sticks) (n/a with split parcels); STATS.md; the\n"
"             time steps, Courant numbers, forces and probes of the window.\n"
"    time-dir  the time folder of PARENT holding NAME at time T (default last).\n"
"    map-max  the largest value of the maps (0 when none is positive) and F x\n"
"             it (to 6 digits; --exact: F x the exact largest value).\n"
"    capture  the capture table of DIR/d<N>um: Stokes number of the wake\n"
"             St = rho d^2 U / (18 mu H) (rho 920 kg/m3, mu 1.641e-5 Pa s,\n"
"             U 19.444 m/s, H 0.12 m), parcels, impacts per face, rear share\n"
"             1e6 deposit / (injected F) [ppm].\n"
"    fill     the age of rear-face impacts of a spray on at T: the age density\n"
"             over the window de-censored (q(a) = M(a) / (T1 - max(T0, T + a)),\n"
"             1 ms bins), its rate r_inf, the ages a_0.5 and a_F (F default\n"
"             0.95) and the fill of the window and its halves; one row.\n"
"    cost     cost.csv: design,wall_s,face,left,right,centre,edges from the\n"
"             solver log's \"Wall time [s]\" line, the main cloud's window row\n"
"             and the composed classes' regions.\n"
"    gates, variant, dispersion  the per-patch tables side by side of the\n"
"             gate settings, of a variant against the main cloud (deposit\n"
"             change; feedback: covered faces from LOG) and of the dispersion\n"
"             treatments (with their capture tables).\n"
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
    /* the commands of the runs against each other (swe_cmd_ladder.c) parse
       their own options */
    const int lrc = swe_ladder_main(argc, argv);
    if (lrc >= 0)
        return lrc;
    /* the per-run post-processing commands parse their own options */
    const int post_rc = swe_cmd_post(argc, argv);
    if (post_rc >= 0)
        return post_rc;
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
