#!/usr/bin/env bash
# wallmodel_overhead.sh - tracking-time overhead of snowWallInteraction against the
# built-in localInteraction on a case with many wall impacts.
#
# Usage: bench/wallmodel/wallmodel_overhead.sh [--help] [--runs N] [--parcels N] [--steps N]
#                                              [--buildup] [--table]
#
# The case (made in a temp folder): a 0.1 m cube, 4x4x4 cells, walls at y = 0 and
# y = 0.1; N parcels (default 20000) of 100 um ice fly force-free at 10 m/s normal
# to the walls and bounce between them elastically: about 10 impacts per parcel in
# the default 100 steps of 1 ms. Both models see the same trajectories: localInteraction
# with rebound e 1 mu 0, snowWallInteraction with bench/wallmodel/regime.coeffs
# (d_crit(10 m/s) = 1.3 um, so every impact is a bounce, reboundNormal 1), i.e. the
# whole decision (d_crit power law, gates off) at every impact.
# Runs icoUncoupledKinematicParcelFoam N times per model (default 5), alternating,
# and prints the median ExecutionTime (CPU s) of each, the impacts per run and the
# overhead ratio. Needs ./Allwmake (platforms/lib/libsnowWallInteraction.so).
# Then runs sww_bench (build/release/bench/wallmodel, from ./Allwmake): the cost of
# one sww_decide call and its share of the run time in this case.
# --buildup: snowWallInteraction with the build-up feedback on (buildUp with the
# same regime as the covered one, coverMass 1 kg/m2): every impact also reads its
# face's deposit and the covered fraction (all bounce here, so w stays 0).
# --table: the regime carries a rough wall's stick-probability table (46 x 50, as
# snowregime map --set wall=lattice writes it) spanning every impact of the case
# (d 10-200 um, v_n 1-20 m/s) with p = 0: every decision interpolates the table
# (and still bounces, so the trajectories stay those of localInteraction).
# Exit 2 on bad arguments; 77 when OpenFOAM or the library is missing.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
top=$(cd "$here/../.." && pwd)
runs=5 parcels=20000 steps=100 buildup= table=0
usage() { sed -n '2,27p' "$0" | sed 's/^# \{0,1\}//'; }
while [ $# -gt 0 ]; do
    case "$1" in
        -h|--help) usage; exit 0 ;;
        --buildup) buildup='buildUp { #include "regime.coeffs" coverMass 1; }' ;;
        --table) table=1 ;;
        --runs|--parcels|--steps)
            [ $# -ge 2 ] && [[ "$2" =~ ^[1-9][0-9]*$ ]] \
                || { echo "wallmodel_overhead: $1 needs a positive integer, got '${2:-}'" >&2; exit 2; }
            case "$1" in --runs) runs=$2 ;; --parcels) parcels=$2 ;; --steps) steps=$2 ;; esac
            shift ;;
        *) echo "wallmodel_overhead: unknown option '$1' (see --help)" >&2; exit 2 ;;
    esac
    shift
done
[ -x /usr/bin/icoUncoupledKinematicParcelFoam ] || { echo "wallmodel_overhead: OpenFOAM not installed" >&2; exit 77; }
[ -f "$top/platforms/lib/libsnowWallInteraction.so" ] \
    || { echo "wallmodel_overhead: platforms/lib/libsnowWallInteraction.so missing: run ./Allwmake" >&2; exit 77; }
. "$top/etc/openfoam-env.sh"
tmp=$(mktemp -d /tmp/sw-bench-XXXXXX)
trap 'rm -rf "$tmp"' EXIT

# the case: from the test box (mesh, schemes), both horizontal walls are walls
base="$tmp/base"
cp -r "$top/tests/openfoam/box" "$base"
cp "$here/regime.coeffs" "$base/constant/regime.coeffs"
if [ "$table" = 1 ]; then
    # the probability table inside regime { }: before its closing brace
    awk 'BEGIN { nd = 46; nv = 50 }
         /^}/ && !done {
             printf "    probabilityD      (";
             for (i = 0; i < nd; i++) printf "%s%.6g", (i ? " " : ""), 1e-5 + 1.9e-4 * i / (nd - 1);
             printf ");\n    probabilityVn     (";
             for (j = 0; j < nv; j++) printf "%s%.6g", (j ? " " : ""), exp(log(20) * j / (nv - 1));
             printf ");\n    probabilityStick  (";
             for (k = 0; k < nd * nv; k++) printf "%s0", (k ? " " : "");
             printf ");\n    probabilityPoints 64;\n"; done = 1 }
         { print }' "$here/regime.coeffs" > "$base/constant/regime.coeffs"
fi
sed -i 's/top    { type patch;/top    { type wall; /' "$base/system/blockMeshDict"
sed -i 's/top   { type fixedValue; value uniform (0.2 0 0); }/top   { type fixedValue; value uniform (0 0 0); }/' "$base/0/U"
sed -i 's/^(0[.0-9e-]* 0 0)$/(0 0 0)/' "$base/0/U"
foamDictionary -entry functions -remove "$base/system/controlDict" > /dev/null
foamDictionary -entry endTime -set "$(awk -v n="$steps" 'BEGIN { print n * 0.001 }')" "$base/system/controlDict" > /dev/null
foamDictionary -entry deltaT -set 0.001 "$base/system/controlDict" > /dev/null
foamDictionary -entry writeControl -set timeStep "$base/system/controlDict" > /dev/null
foamDictionary -entry writeInterval -set 100000 "$base/system/controlDict" > /dev/null
awk -v n="$parcels" 'BEGIN {
    print "FoamFile { version 2.0; format ascii; class vectorField; object positions; }"
    print n; print "("
    srand(12345)
    for (i = 0; i < n; i++) printf "(%.6f %.6f %.6f)\n", 0.002 + 0.096 * rand(), 0.002 + 0.096 * rand(), 0.002 + 0.096 * rand()
    print ")" }' > "$base/constant/positions"
cloud="$base/constant/kinematicCloudProperties"
cat > "$cloud" <<EOC
FoamFile { version 2.0; format ascii; class dictionary; object kinematicCloudProperties; }
solution
{
    active true; coupled false; transient yes; cellValueSourceCorrection off; maxCo 0.3;
    interpolationSchemes { rho cell; U cellPoint; mu cell; }
    integrationSchemes { U Euler; }
}
constantProperties { rho0 920; youngsModulus 9.8e9; poissonsRatio 0.31; }
subModels
{
    particleForces {}
    injectionModels
    {
        all
        {
            type manualInjection; massTotal 0; parcelBasisType fixed; nParticle 1; SOI 0;
            positionsFile "positions"; U0 (0 10 0);
            sizeDistribution { type fixedValue; fixedValueDistribution { value 1e-4; } }
        }
    }
    dispersionModel none;
    surfaceFilmModel none;
    stochasticCollisionModel none;
    collisionModel none;
    PIM_LINE
    localInteractionCoeffs
    {
        patches ( "(wall|top)" { type rebound; e 1; mu 0; } sides { type escape; } );
    }
    snowWallInteractionCoeffs
    {
        #include "regime.coeffs"
        patches ( "(wall|top)" { type snow; } sides { type escape; } );
        $buildup
    }
}
cloudFunctions {}
EOC
(cd "$base" && blockMesh > log.blockMesh 2>&1) || { tail "$base/log.blockMesh" >&2; exit 1; }

one_run() { # MODEL -> prints "cpu impacts"
    local c="$tmp/run-$1"
    rm -rf "$c"; cp -r "$base" "$c"
    sed -i "s/PIM_LINE/patchInteractionModel $1;/" "$c/constant/kinematicCloudProperties"
    (cd "$c" && icoUncoupledKinematicParcelFoam > log 2>&1) || { tail -20 "$c/log" >&2; exit 1; }
    local cpu imp
    cpu=$(grep '^ExecutionTime' "$c/log" | tail -1 | awk '{ print $3 }')
    if [ "$1" = snowWallInteraction ]; then
        imp=$(awk '/snowWall: patch/ { gsub(",", ""); s += $5 } /^ExecutionTime/ { last = s; s = 0 } END { print last }' "$c/log")
    else
        imp=-
    fi
    echo "$cpu $imp"
}
median() { sort -g | awk '{ a[NR] = $1 } END { print (NR % 2) ? a[(NR + 1) / 2] : (a[NR / 2] + a[NR / 2 + 1]) / 2 }'; }

echo "wallmodel_overhead: $parcels parcels, $steps steps of 1 ms, $runs runs per model${buildup:+, build-up feedback on}$([ "$table" = 1 ] && echo ", stick-probability table (every impact inside)")"
: > "$tmp/local" ; : > "$tmp/snow"
for i in $(seq "$runs"); do
    read -r tl _ < <(one_run localInteraction)
    read -r ts imp < <(one_run snowWallInteraction)
    echo "  run $i: localInteraction $tl s, snowWallInteraction $ts s ($imp impacts)"
    echo "$tl" >> "$tmp/local"; echo "$ts" >> "$tmp/snow"
done
ml=$(median < "$tmp/local"); ms=$(median < "$tmp/snow")
echo "median ExecutionTime: localInteraction $ml s, snowWallInteraction $ms s"
echo "impacts per run: $imp ($(awk -v i="$imp" -v t="$ms" 'BEGIN { printf "%.3g", i / t }') per CPU second)"
awk -v a="$ml" -v b="$ms" 'BEGIN { printf "overhead: ratio %.4f (%+.2f %%), target <= 3 %%\n", b / a, 100 * (b / a - 1) }'

# the cost of the decision itself (C core), and what it amounts to in this case
sb="$top/build/release/bench/wallmodel/sww_bench"
if [ -x "$sb" ]; then
    out=$("$sb" "$here/regime.coeffs")
    echo "$out"
    ns=$(echo "$out" | awk '/^gates off/ { print $3 }')
    awk -v n="$ns" -v i="$imp" -v t="$ml" 'BEGIN {
        printf "decision cost in this case: %d impacts x %.1f ns = %.4f s = %.2f %% of the localInteraction run\n", i, n, i * n * 1e-9, 100 * i * n * 1e-9 / t }'
else
    echo "(build/release/bench/wallmodel/sww_bench not built: ./Allwmake)"
fi
