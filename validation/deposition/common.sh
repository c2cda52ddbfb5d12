# shellcheck shell=bash
# validation/deposition/common.sh - sourced by the deposition benchmarks
# (validation/deposition.sh, bend.sh, rib.sh) and validation/wellmixed.sh: the
# pieces of their OpenFOAM cases that are the same in all.
#
#   dep_control CASE APP END_TIME DELTA_T WRITE_INTERVAL
#       CASE/system/controlDict: fixed steps, ascii, the wrapper's library
#   dep_particle_schemes CASE
#       CASE/system/fvSchemes of the particle run (the frozen flow's terms)
#   dep_dispersion TREATMENT PATCHES
#       sets DEP_DISP (the cloud's dispersionModel) and DEP_FUNCS (its
#       cloudFunctions entries) of a treatment: stochastic, gradient, none,
#       nearwall (snowNearWall with the closure of deposition.coeffs),
#       nearwall-utau / nearwall-k (the same with the wall layer's velocity
#       scale from the wall shear / the turbulence alone), crw (snowNearWall
#       without the closure); PATCHES the walls of snowNearWall, e.g. "(walls)"
#   dep_interpolation SCRIPT VALUE
#       DEP_UINTERP, the parcels' velocity interpolation of every cloud, set to
#       VALUE: faceFlux (the default: the velocity rebuilt from the flow's face
#       fluxes in every hexahedron, doc/deposition.md, "The tracking next to a
#       wall") or cellPoint (OpenFOAM's); another is refused (stderr, status 2)
#   dep_cloud_solution [UINTERP]
#       the solution { } entry of a cloud's properties (stdout); UINTERP the
#       parcels' velocity interpolation (default DEP_UINTERP)
#   dep_write_cloud CASE NAME D TREATMENT RHO U0 INJECTION ESCAPE WALLS
#       CASE/constant/NAMEProperties: ice spheres of diameter D and density RHO
#       released once at the points of constant/positions with velocity U0
#       ("(u v w)"), injector named INJECTION; drag and gravity; TREATMENT as
#       dep_dispersion with WALLS (e.g. "(walls)") for snowNearWall; every
#       patch of ESCAPE (space-separated) a localInteraction escape; the
#       cloudFunctions entries of DEP_EXTRA_FUNCS (default none) after the
#       treatment's
#   dep_numbers SCRIPT OPTION MIN MAX VALUES...
#       1 to 12 VALUES, each a number in [MIN, MAX]; otherwise one message
#       naming OPTION and the value (stderr, status 2)
#   dep_models SCRIPT ALLOWED VALUES...
#       every VALUE one of the space-separated ALLOWED (stderr, status 2)
#   dep_require SCRIPT TOP EXE...
#       the OpenFOAM tools EXE, the project's solver and wrapper under TOP and
#       gnuplot are there (stderr naming what is missing, status 1)
#   dep_check_coeffs SCRIPT TOP FILE
#       FILE read as the near-wall model reads a closure (bin/snowdeposit
#       check): its message on stderr and status 2 when it cannot be used,
#       status 1 when bin/snowdeposit is not built
#   dep_show_fail SCRIPT WHAT LOG
#       "SCRIPT: WHAT failed" and the end of LOG on stderr: from its fatal
#       error on, or its last lines (the work folder, and LOG with it, goes
#       with a failed run unless KEEP_TMP is set)
#   dep_estimate SCRIPT PARCELS CLOUDS STEPS MEMORY MINUTES HINT
#       the estimate line of what the options multiply (stdout) and, when the
#       MEMORY estimate [bytes] is above what the machine has available, its
#       refusal naming HINT (stderr, status 2)
#   dep_run_particles CASE [NWARM]
#       the clouds named in CASE/clouds.txt (first word of each line) carried
#       by the frozen flow together (pimpleUncoupledKinematicParcelFoam
#       -frozen), the log in CASE/log.particles; the solver's exit status.
#       With NWARM the log is filtered as it is written (a case with many
#       patches would write some 40 lines per cloud and step): the parcel
#       counts of every step, the patch fates at step NWARM and, after a line
#       "# the last step", at the last step; from a fatal error on, every line
#   dep_option SCRIPT OPTION [VALUE]
#       the options every benchmark takes, into the caller's variables: --out
#       DIR (out), --models LIST (models), --parcels N (parcels), --coeffs FILE
#       (coeffs), --interpolation NAME (interp), --force (force=1); sets
#       DEP_NARGS (the words it took: 2, or 1 for --force); a missing value or
#       any other option: one message naming it (stderr, status 2). Sourced
#       before the option loop, its `*)` branch.
#   dep_flow SCRIPT CASE MESH ITERATIONS [STEP...]
#       the steady flow of CASE: system/fvSchemes.flow as fvSchemes, ITERATIONS
#       steps of simpleFoam (dep_control), blockMesh, each STEP (a command of
#       the case, its log log.<first word>), 0.orig as 0, simpleFoam; sets
#       DEP_TFLOW (its wall time, s) and DEP_LAST (the converged time); on a
#       failure dep_show_fail of the newest log, status 1

dep_control() {   # case app endTime deltaT writeInterval
    cat > "$1/system/controlDict" <<EOF2
FoamFile { version 2.0; format ascii; class dictionary; object controlDict; }
application     $2;
startFrom       startTime;
startTime       0;
stopAt          endTime;
endTime         $3;
deltaT          $4;
writeControl    timeStep;
writeInterval   $5;
purgeWrite      0;
writeFormat     ascii;
writePrecision  10;
timeFormat      general;
timePrecision   10;
runTimeModifiable false;
adjustTimeStep  no;
libs            ("libsnowWallInteraction.so");
EOF2
}

dep_option() {   # script option [value]
    local s=$1 o=$2 v=${3:-} need=
    DEP_NARGS=2
    case "$o" in
        --out) need="a folder" ;;
        --models) need="a list" ;;
        --parcels) need="a number" ;;
        --coeffs) need="a file" ;;
        --interpolation) need="faceFlux or cellPoint" ;;
        --force) force=1; DEP_NARGS=1; return 0 ;;
        *) echo "$s: unknown option '$o' (see --help)" >&2; return 2 ;;
    esac
    [ -n "$v" ] || { echo "$s: $o needs $need" >&2; return 2; }
    case "$o" in
        --out) out=$v ;;
        --models) models=$v ;;
        --parcels) parcels=$v ;;
        --coeffs) coeffs=$v ;;
        --interpolation) interp=$v ;;
    esac
}

dep_flow() {   # script case mesh iterations [step...]
    local s=$1 c=$2 mesh=$3 it=$4 t0
    shift 4
    cp "$c/system/fvSchemes.flow" "$c/system/fvSchemes"
    dep_control "$c" simpleFoam "$it" 1 "$it"
    echo "$s: $mesh mesh: blockMesh, simpleFoam"
    t0=$(date +%s)
    (cd "$c" && blockMesh > log.blockMesh 2>&1 \
        && for step in "$@"; do $step > "log.${step%% *}" 2>&1 || exit 1; done \
        && rm -rf 0 && cp -r 0.orig 0 && simpleFoam > log.simpleFoam 2>&1) \
        || { dep_show_fail "$s" "$mesh: the flow" "$(ls -t "$c"/log.* | head -1)"; return 1; }
    DEP_TFLOW=$(( $(date +%s) - t0 ))
    DEP_LAST=$(cd "$c" && foamListTimes -latestTime 2>/dev/null | tail -1)
}

dep_particle_schemes() {   # case
    cat > "$1/system/fvSchemes" <<'EOF2'
FoamFile { version 2.0; format ascii; class dictionary; object fvSchemes; }
ddtSchemes      { default Euler; }
gradSchemes     { default Gauss linear; }
divSchemes      { default none; div(phi,U) Gauss linear; div(phi,k) Gauss linear; div(phi,omega) Gauss linear; div((nuEff*dev2(T(grad(U))))) Gauss linear; }
laplacianSchemes { default Gauss linear corrected; }
interpolationSchemes { default linear; }
snGradSchemes   { default corrected; }
wallDist        { method meshWave; }
EOF2
}

dep_dispersion() {   # treatment patches
    DEP_DISP=none
    DEP_FUNCS=
    local inc='#include "deposition.coeffs"' cl=on scale=max
    case "$1" in
        stochastic) DEP_DISP=stochasticDispersionRAS ;;
        gradient) DEP_DISP=gradientDispersionRAS ;;
        none) ;;
        nearwall|nearwall-utau|nearwall-k|crw)
            [ "$1" != crw ] || { inc=; cl=off; }
            [ "$1" != nearwall-utau ] || scale=wallShear
            [ "$1" != nearwall-k ] || scale=turbulence
            DEP_FUNCS="nearWall { type snowNearWall; patches $2; closure $cl; velocityScale $scale; $inc }"
            ;;
        *) echo "dep_dispersion: unknown treatment '$1'" >&2; return 2 ;;
    esac
}

DEP_UINTERP=faceFlux
dep_interpolation() {   # script value
    case "$2" in
        faceFlux|cellPoint) DEP_UINTERP=$2 ;;
        *) echo "$1: --interpolation: '$2' is not faceFlux or cellPoint" >&2; return 2 ;;
    esac
}

dep_cloud_solution() {
    cat <<EOF2
solution
{
    active          true;
    coupled         false;
    transient       yes;
    cellValueSourceCorrection off;
    maxCo           0.3;
    interpolationSchemes { rho cell; U ${1:-$DEP_UINTERP}; mu cell; k cell; epsilon cell; }
    integrationSchemes { U analytical; }
}
EOF2
}

dep_run_particles() {   # case [nwarm]
    local names
    names=$(awk '{ print $1 }' "$1/clouds.txt" | tr '\n' ' ')
    if [ -z "${2:-}" ]; then
        (cd "$1" && pimpleUncoupledKinematicParcelFoam -frozen -clouds "(${names% })" > log.particles 2>&1)
        return
    fi
    (cd "$1" && set -o pipefail && pimpleUncoupledKinematicParcelFoam -frozen -clouds "(${names% })" 2>&1 | awk -v nwarm="$2" '
        fatal { print; next }
        /FOAM FATAL|FOAM exiting|^--> / { fatal = 1; print; next }
        /^Time = / { step++; nb = 0; print; next }
        /^Cloud: / { print; buf[++nb] = $0; next }
        /Current number of parcels/ { print; next }
        /Parcel fate: patch |- escape / { if (step == nwarm) print; else buf[++nb] = $0; next }
        /^End|[Ee]rror|[Ww]arning/ { print }
        END { if (!fatal) { print "# the last step"; for (i = 1; i <= nb; i++) print buf[i] } }' > log.particles)
}

dep_write_cloud() {   # case name d treatment rho U0 injection escape walls
    local c=$1 name=$2 d=$3 model=$4 rho=$5 u0=$6 inj=$7 esc=$8 walls=$9 p
    dep_dispersion "$model" "$walls" || return 1
    {
        echo "FoamFile { version 2.0; format ascii; class dictionary; object ${name}Properties; }"
        dep_cloud_solution
        cat <<EOF2
constantProperties { rho0 $rho; }
subModels
{
    particleForces { sphereDrag; gravity; }
    injectionModels
    {
        $inj
        {
            type            manualInjection;
            massTotal       1;
            parcelBasisType fixed;
            nParticle       1;
            SOI             0;
            positionsFile   "positions";
            U0              $u0;
            sizeDistribution { type fixedValue; fixedValueDistribution { value $d; } }
        }
    }
    dispersionModel $DEP_DISP;
    patchInteractionModel localInteraction;
    localInteractionCoeffs
    {
        patches
        (
EOF2
        for p in $esc; do echo "            $p { type escape; }"; done
        cat <<EOF2
        );
    }
    surfaceFilmModel none;
    stochasticCollisionModel none;
    collisionModel  none;
}
cloudFunctions { $DEP_FUNCS ${DEP_EXTRA_FUNCS:-} }
EOF2
    } > "$c/constant/${name}Properties"
}

dep_estimate() {   # script parcels clouds steps memory minutes hint
    local avail
    avail=$(awk '/^MemAvailable:/ { print $2 * 1024 }' /proc/meminfo 2>/dev/null || true)
    awk -v s="$1" -v p="$2" -v nc="$3" -v st="$4" -v mem="$5" -v min="$6" -v hint="$7" -v avail="${avail:-0}" 'BEGIN {
        printf "%s: estimate: %d parcels in %d clouds per mesh, %s; memory about %.2g GB; about %.0f min\n", \
            s, p, nc, st, mem / 1e9, min + 0.5
        fflush()
        if (avail > 0 && mem > avail) {
            printf "%s: the estimated memory %.2g GB is more than the %.2g GB available: %s\n", \
                s, mem / 1e9, avail / 1e9, hint > "/dev/stderr"
            exit 2
        }
    }'
}

dep_numbers() {   # script option min max values...
    local s=$1 o=$2 min=$3 max=$4 v
    shift 4
    [ $# -ge 1 ] && [ $# -le 12 ] || { echo "$s: $o: 1 to 12 values" >&2; return 2; }
    for v in "$@"; do
        awk -v t="$v" -v lo="$min" -v m="$max" 'BEGIN { exit !(t ~ /^[0-9]*\.?[0-9]+([eE][-+]?[0-9]+)?$/ && t + 0 >= lo + 0 && t + 0 <= m + 0) }' \
            || { echo "$s: $o: '$v' is not a number in [$min, $max]" >&2; return 2; }
    done
}

dep_models() {   # script allowed values...
    local s=$1 allowed=$2 v
    shift 2
    for v in "$@"; do
        case " $allowed " in *" $v "*) ;;
            *) echo "$s: --models: '$v' is not one of: $allowed" >&2; return 2 ;; esac
    done
}

dep_require() {   # script top exe...
    local s=$1 top=$2 e
    shift 2
    for e in "$@"; do
        command -v "$e" >/dev/null || { echo "$s: $e not found (OpenFOAM: etc/setup.sh)" >&2; return 1; }
    done
    [ -x "$top/platforms/bin/pimpleUncoupledKinematicParcelFoam" ] && [ -f "$top/platforms/lib/libsnowWallInteraction.so" ] \
        || { echo "$s: the project's solver and wrapper are missing: run ./Allwmake" >&2; return 1; }
    command -v gnuplot >/dev/null || { echo "$s: gnuplot not found" >&2; return 1; }
}

dep_show_fail() {   # script what log
    echo "$1: $2 failed; its log ($3, kept with KEEP_TMP=1) ends:" >&2
    if grep -q 'FOAM FATAL' "$3" 2>/dev/null; then sed -n '/FOAM FATAL/,$p' "$3" | head -25 >&2
    else tail -15 "$3" >&2 2>/dev/null || true; fi
}

dep_check_coeffs() {   # script top file
    local msg
    [ -x "$2/bin/snowdeposit" ] || { echo "$1: bin/snowdeposit missing: run ./Allwmake" >&2; return 1; }
    msg=$("$2/bin/snowdeposit" check "$3" 2>&1 >/dev/null) \
        || { echo "$1: --coeffs: ${msg#snowdeposit: check: }" >&2; return 2; }
}
