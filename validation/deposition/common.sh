# shellcheck shell=bash
# validation/deposition/common.sh - sourced by the deposition benchmarks
# (validation/deposition.sh, validation/bend.sh): the pieces of their OpenFOAM
# particle cases that are the same in both.
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
#   dep_cloud_solution
#       the solution { } entry of a cloud's properties (stdout)
#   dep_run_particles CASE
#       the clouds named in CASE/clouds.txt (first word of each line) carried
#       by the frozen flow together (pimpleUncoupledKinematicParcelFoam
#       -frozen), the log in CASE/log.particles; the solver's exit status

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

dep_cloud_solution() {
    cat <<'EOF2'
solution
{
    active          true;
    coupled         false;
    transient       yes;
    cellValueSourceCorrection off;
    maxCo           0.3;
    interpolationSchemes { rho cell; U cellPoint; mu cell; k cell; epsilon cell; }
    integrationSchemes { U analytical; }
}
EOF2
}

dep_run_particles() {   # case
    local names
    names=$(awk '{ print $1 }' "$1/clouds.txt" | tr '\n' ' ')
    (cd "$1" && pimpleUncoupledKinematicParcelFoam -frozen -clouds "(${names% })" > log.particles 2>&1)
}
