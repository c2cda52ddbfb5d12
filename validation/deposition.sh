#!/usr/bin/env bash
# deposition.sh - turbulent deposition in a channel: the CFD chain against the
# measured deposition velocities (doc/deposition.md)
#
# Usage: validation/deposition.sh --out DIR [--force] [--mesh resolved|wf|both]
#            [--tau-plus LIST] [--models LIST] [--parcels N] [--t-run T]
#            [--coeffs FILE | --calibrate] [--short] [--re-tau R]
#            [--interpolation faceFlux|cellPoint] [--help]
#
# A fully developed channel flow between two walls, periodic along the flow
# and across it, at the Reynolds number of Liu & Agarwal's pipe at Re = 10 000
# (Re_tau about 314, air at 20 C), held by a mean pressure gradient; the flow
# is a steady RANS (kOmegaSST, simpleFoam), then frozen. In it, for every
# tau+ of the list and every dispersion treatment, one cloud of ice spheres
# (920 kg/m3, the density of Liu & Agarwal's olive oil) released uniformly
# over the channel; every wall contact is a deposit (localInteraction escape).
# The clouds ride the frozen flow together (pimpleUncoupledKinematicParcelFoam
# -frozen); the deposition velocity of each is
#   V+ = (D + E) h / (u_tau Int N dt)     over the window after the warm-up,
# D the parcels that left through the walls by tracking, E the expected
# number that the sublayer closure of snowNearWall brought there (its
# probabilities summed; 0 for the other treatments), N the parcels in the
# channel, h its half height; standard error V+/sqrt(D + E) (Poisson). Beside
# it V+_core = V+ / c_core, on the concentration outside the wall layer
# (y+ > 30), c_core that concentration over the mean over the window (the
# cloud function wellMixedCheck): particles of tau+ 10-30 gather in the
# viscous sublayer and hover there, where they count in the mean but carry
# almost none of the flow, and a sampling probe or a pipe's mixed outflow, the
# measurements' reference, does not see them (doc/deposition.md).
#
# Treatments (--models, comma-separated): stochastic (stochasticDispersionRAS),
# gradient (gradientDispersionRAS), none (no dispersion), nearwall
# (snowNearWall: the C core's continuous random walk with the sublayer
# closure of --coeffs), crw (snowNearWall without the closure).
# Meshes (--mesh): resolved (first cell y+ about 0.5, 60 cells per half
# height, graded), wf (a wall-function mesh: 10 uniform cells, first cell
# centre y+ about 30, as on the wedge), both (default).
#
# --re-tau: the friction Reynolds number u_tau h / nu the flow is set up for
# (default 314, Liu & Agarwal's pipe; 100 .. 2000): the bulk velocity is
# 13.3 m/s x (R/314)^(8/7) (Blasius: u_tau ~ U^(7/8)), the wall-function mesh
# has 2 round(R/62) cells across (at least 4; its first cell centre at y+
# about 30), the resolved mesh is the same (its first cell at y+ 0.26 R/314);
# flow.md gives the Re_tau and y+ reached. V+ and tau+ are in wall units, so
# Wood's correlation is the reference at every R.
# --interpolation: the parcels' velocity interpolation, faceFlux (default:
# rebuilt from the flow's face fluxes in every hexahedron, so that the mean
# flow keeps tracers uniform, doc/deposition.md) or cellPoint (OpenFOAM's:
# it gathers tracer-like parcels at walls on wall-function meshes).
#
# Writes into DIR, only when the run succeeds: vplus.csv and vplus.md (V+ and
# V+_core per mesh, treatment and tau+, with the counts, the errors, c_core and
# Wood's correlation),
# vplus.png (V+ against tau+ with the correlations of the measurements),
# flow.md (u_tau, Re_tau, y+ of the first cell, the run times),
# deposition.coeffs (the closure used) and the cases (<mesh>/case, logs
# included). DIR missing: created (its parent must exist). DIR an empty folder
# or an earlier SnowWall output folder (it holds .snowwall-output): the files
# are written into it, what else it holds stays. Any other existing DIR is
# refused (exit 2) unless --force: then the files are written into it (regular
# files of the same names replaced), nothing deleted, no .snowwall-output
# added. Nothing is ever deleted from DIR.
# --tau-plus: default 0.3,1,3,10,30 (each in [0.01, 1000], no empty item, no
# value twice; used in ascending order, with a note when given otherwise);
# --models: no empty item, no name twice; --parcels per cloud (default 2000);
# --t-run: the window in wall units t+ = t u_tau^2/nu (default 20000, after a
# warm-up of 2000); --coeffs: the closure (default etc/deposition.coeffs, the
# shipped calibration); --calibrate: calibrate it anew first (bin/snowdeposit
# calibrate, about 4 min; into DIR/deposition.coeffs); --short: the test (wf
# mesh, tau+ 1,10, nearwall only, 1000 parcels, window 8000).
# Exit status: 0 done, 1 a run failed, 2 usage error.
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
here="$top/validation/deposition"
out=
meshes=both
taus=0.3,1,3,10,30
models=stochastic,gradient,none,nearwall
parcels=2000
trun=20000
twarm=2000
coeffs=
interp=faceFlux
retau_set=314
calibrate=0
force=0
die2() { echo "deposition.sh: $*" >&2; exit 2; }
# shellcheck source=deposition/common.sh
. "$here/common.sh"
while [ $# -gt 0 ]; do
    case "$1" in
        -h|--help) awk 'NR > 1 && !/^#/ { exit } NR > 1 { sub(/^# ?/, ""); print }' "$0"; exit 0 ;;
        --mesh) [ -n "${2:-}" ] || die2 "--mesh needs resolved, wf or both"; meshes=$2; shift ;;
        --tau-plus) [ -n "${2:-}" ] || die2 "--tau-plus needs a list"; taus=$2; shift ;;
        --t-run) [ -n "${2:-}" ] || die2 "--t-run needs a number"; trun=$2; shift ;;
        --re-tau) [ -n "${2:-}" ] || die2 "--re-tau needs a friction Reynolds number"; retau_set=$2; shift ;;
        --calibrate) calibrate=1 ;;
        --short) meshes=wf; taus=1,10; models=nearwall; parcels=1000; trun=8000; twarm=1000 ;;
        *) dep_option deposition.sh "$1" "${2:-}" || exit 2; [ "$DEP_NARGS" = 1 ] || shift ;;
    esac
    shift
done
[ -n "$out" ] || die2 "--out DIR is required (see --help)"
case "$meshes" in resolved|wf) ;; both) meshes="resolved wf" ;; *) die2 "--mesh: '$meshes' is not resolved, wf or both" ;; esac
[[ "$parcels" =~ ^[1-9][0-9]{0,5}$ ]] || die2 "--parcels: '$parcels' is not a whole number in 1..999999"
[[ "$trun" =~ ^[1-9][0-9]{0,6}$ ]] || die2 "--t-run: '$trun' is not a whole number of wall units in 1..9999999"
# shellcheck source=../etc/outdir.sh
. "$top/etc/outdir.sh"
dep_interpolation deposition.sh "$interp" || exit 2
outdir_list taus deposition.sh --tau-plus "$taus" num
outdir_list models deposition.sh --models "$models" name
IFS=, read -r -a tauList <<< "$taus"
dep_numbers deposition.sh --tau-plus 0.01 1000 "${tauList[@]}" || exit 2
IFS=, read -r -a modelList <<< "$models"
dep_models deposition.sh "stochastic gradient none nearwall crw" "${modelList[@]}" || exit 2
[[ "$retau_set" =~ ^[0-9]+(\.[0-9]+)?$ ]] && awk -v r="$retau_set" 'BEGIN { exit !(r >= 100 && r <= 2000) }' ||
    die2 "--re-tau: '$retau_set' is not a number in [100, 2000]"
[ -z "$coeffs" ] || [ "$calibrate" = 0 ] || die2 "--coeffs and --calibrate exclude each other"
[ -n "$coeffs" ] || coeffs="$top/etc/deposition.coeffs"
dep_require deposition.sh "$top" simpleFoam blockMesh || exit 1
[ -x "$top/bin/snowdeposit" ] || { echo "deposition.sh: bin/snowdeposit missing: run ./Allwmake" >&2; exit 1; }
[ "$calibrate" = 1 ] || dep_check_coeffs deposition.sh "$top" "$coeffs" || exit $?
outdir_begin deposition.sh "$out" "$force"
# shellcheck source=../etc/openfoam-env.sh
. "$top/etc/openfoam-env.sh" >/dev/null
t_start=$(date +%s)

# the channel: half height h (Liu & Agarwal's pipe radius), bulk velocity for
# Re_tau about --re-tau (314: 13.3 m/s) with nu = 1.5e-5 m2/s
h=0.00635
ubar=$(awk -v r="$retau_set" 'BEGIN { printf "%.4g", 13.3 * (r / 314) ^ (8 / 7) }')
nu=1.5e-5
rhop=920
mu=1.8e-5   # nu * rhoInf (1.2)

if [ "$calibrate" = 1 ]; then
    echo "deposition.sh: calibrating the sublayer closure (snowdeposit calibrate)"
    "$top/bin/snowdeposit" calibrate --out "$tmp/deposition.coeffs" > "$tmp/calibrate.txt"
    coeffs="$tmp/deposition.coeffs"
else
    cp "$coeffs" "$tmp/deposition.coeffs"
    coeffs="$tmp/deposition.coeffs"
fi

# blockMeshDict of a mesh: 2 x NY x 2 cells, y graded symmetrically to the walls
write_mesh() {   # case ny grading
    cat > "$1/system/blockMeshDict" <<EOF
FoamFile { version 2.0; format ascii; class dictionary; object blockMeshDict; }
// validation/deposition: channel 0 < y < 2h, h = $h m, periodic in x and z
convertToMeters $h;
vertices ((0 0 0) (2 0 0) (2 2 0) (0 2 0) (0 0 2) (2 0 2) (2 2 2) (0 2 2));
blocks (hex (0 1 2 3 4 5 6 7) (2 $2 2) simpleGrading (1 ((0.5 0.5 $3) (0.5 0.5 $(awk -v g="$3" 'BEGIN { printf "%.10g", 1/g }'))) 1));
boundary
(
    walls { type wall; faces ((0 1 5 4) (3 7 6 2)); }
    left  { type cyclic; neighbourPatch right; faces ((0 4 7 3)); }
    right { type cyclic; neighbourPatch left;  faces ((1 2 6 5)); }
    front { type cyclic; neighbourPatch back;  faces ((0 3 2 1)); }
    back  { type cyclic; neighbourPatch front; faces ((4 5 6 7)); }
);
EOF
}

# cloud properties: one tau+ and treatment, with the concentration outside the
# wall layer (y+ > 30) over the window (wellMixedCheck "core": channel-vplus)
write_cloud() {   # case name d model window_start_s
    DEP_EXTRA_FUNCS="core { type wellMixedCheck; patches (walls); bands (0 30); startTime $5; totalSamples 200000; }" \
        dep_write_cloud "$1" "$2" "$3" "$4" "$rhop" "($ubar 0 0)" uniform walls "(walls)"
}

# parcels released uniformly over the channel (away from the walls by 1e-6 h)
write_positions() {   # case n seed
    awk -v n="$2" -v s="$3" -v h="$h" 'BEGIN {
        srand(s)
        print "FoamFile { version 2.0; format ascii; class vectorField; object positions; }"
        print n; print "("
        for (i = 0; i < n; i++) {
            y = h * (1e-6 + (2 - 2e-6) * rand())
            printf "(%.10g %.10g %.10g)\n", 2 * h * rand(), y, 2 * h * rand()
        }
        print ")"
    }' > "$1/constant/positions"
}

rows="$tmp/rows.csv"
echo "mesh,model,tau_plus,d_m,parcels,deposits_tracked,closure_drawn,closure_expected,int_N_dt_s,vplus,vplus_se,wood,c_core,vplus_core,vplus_core_se" > "$rows"
flowmd="$tmp/flow.md"
{
    echo "# The channel flow (validation/deposition.sh)"
    echo
    echo "| mesh | cells across | first cell y+ (centre) | u_tau [m/s] | Re_tau | bulk U [m/s] | flow run [s] | particle run [s] | parcel steps |"
    echo "|---|---:|---:|---:|---:|---:|---:|---:|---:|"
} > "$flowmd"

# one mesh: flow, particles, V+ rows into $tmp/rows_<mesh>.csv and the flow
# table's row into $tmp/flow_<mesh>.md
run_mesh() {
    local mesh=$1
    c="$tmp/$mesh/case"
    mkdir -p "$c"
    cp -r "$here/channel/system" "$here/channel/constant" "$here/channel/0.orig" "$c/"
    if [ "$mesh" = resolved ]; then
        ny=120; grading=38; kwall=fixedValue; nutwall=nutLowReWallFunction
    else
        ny=$(awk -v r="$retau_set" 'BEGIN { n = 2 * int(r / 62 + 0.5); print (n < 4 ? 4 : n) }')
        grading=1; kwall=kqRWallFunction; nutwall=nutkWallFunction
    fi
    cat > "$c/constant/channelParameters" <<EOF
Ubar    $ubar;
kWall   $kwall;
nutWall $nutwall;
EOF
    write_mesh "$c" "$ny" "$grading"
    dep_flow deposition.sh "$c" "$mesh" 4000 || exit 1
    tflow=$DEP_TFLOW last=$DEP_LAST
    # u_tau from the mean pressure gradient: u_tau^2 = h dp/dx (kinematic)
    gradp=$(awk '/Pressure gradient source/ { for (i = 1; i <= NF; i++) if ($i == "gradient") g = $(i + 2) } END { print g }' "$c/log.simpleFoam")
    utau=$(awk -v g="$gradp" -v h="$h" 'BEGIN { printf "%.6g", sqrt(g * h) }')
    retau=$(awk -v u="$utau" -v h="$h" -v nu="$nu" 'BEGIN { printf "%.4g", u * h / nu }')
    (cd "$c" && simpleFoam -postProcess -func yPlus -time "$last" > log.yPlus 2>&1) || true
    yplus=$(awk '/y\+ : min/ { for (i = 1; i <= NF; i++) if ($i == "average") a = $(i + 2) } END { print a }' "$c/log.yPlus")
    # the converged flow becomes time 0 for the particles
    (cd "$c" && rm -rf 0 && mv "$last" 0 && rm -rf 0/uniform)

    # the clouds
    tnu=$(awk -v u="$utau" -v nu="$nu" 'BEGIN { printf "%.10g", nu / (u * u) }')
    dt=$(awk -v t="$tnu" 'BEGIN { printf "%.6g", 2 * t }')
    tend=$(awk -v t="$tnu" -v w="$twarm" -v r="$trun" 'BEGIN { printf "%.6g", (w + r) * t }')
    nsteps=$(awk -v a="$tend" -v b="$dt" 'BEGIN { printf "%d", a / b + 0.5 }')
    tend=$(awk -v n="$nsteps" -v b="$dt" 'BEGIN { printf "%.10g", n * b }')
    nwarm=$(awk -v w="$twarm" 'BEGIN { printf "%d", w / 2 + 0.5 }')
    write_positions "$c" "$parcels" 7
    cp "$coeffs" "$c/constant/deposition.coeffs"
    clouds=()
    for m in "${modelList[@]}"; do
        for i in "${!tauList[@]}"; do
            t=${tauList[$i]}
            d=$(awk -v t="$t" -v u="$utau" -v nu="$nu" -v mu="$mu" -v r="$rhop" 'BEGIN { printf "%.6g", sqrt(18 * mu * t * nu / (r * u * u)) }')
            name="c_${m}_$i"
            write_cloud "$c" "$name" "$d" "$m" "$(awk -v n="$nwarm" -v s="$dt" 'BEGIN { printf "%.10g", n * s }')"
            clouds+=("$name")
            echo "$name $m $t $d" >> "$c/clouds.txt"
        done
    done
    # the particle run: steps of 2 t+, written at the end of the warm-up and the end
    dep_control "$c" pimpleUncoupledKinematicParcelFoam "$tend" "$dt" "$nwarm"
    dep_particle_schemes "$c"
    echo "deposition.sh: $mesh mesh: u_tau $utau m/s, Re_tau $retau; ${#clouds[@]} clouds of $parcels parcels, $nsteps steps of 2 t+"
    t0=$(date +%s)
    dep_run_particles "$c" || { dep_show_fail deposition.sh "$mesh: the particle run" "$c/log.particles"; exit 1; }
    tpart=$(( $(date +%s) - t0 ))

    # per cloud: V+ from the parcels left at every step and the closure's counts
    "$here/channel-vplus" --case "$c" --mesh "$mesh" --h "$h" --utau "$utau" --dt "$dt" \
        --nwarm "$nwarm" --parcels "$parcels" | sort -t, -k2,2 -k3,3g > "$tmp/rows_$mesh.csv" \
        || { echo "deposition.sh: $mesh: reading the particle run failed" >&2; exit 1; }
    steps=$(awk '/^Time = /' "$c/log.particles" | wc -l)
    echo "| $mesh | $ny | $yplus | $utau | $retau | $ubar | $tflow | $tpart | $steps time steps x ${#clouds[@]} clouds |" > "$tmp/flow_$mesh.md"
}
# the meshes side by side, one process each (the machine's 2 cores)
pids=()
for mesh in $meshes; do
    run_mesh "$mesh" &
    pids+=($!)
done
failed=0
for pid in "${pids[@]}"; do wait "$pid" || failed=1; done
[ "$failed" = 0 ] || { echo "deposition.sh: a mesh failed (above)" >&2; exit 1; }
t_total=$(( $(date +%s) - t_start ))
for mesh in $meshes; do
    cat "$tmp/rows_$mesh.csv" >> "$rows"
    cat "$tmp/flow_$mesh.md" >> "$flowmd"
    rm -f "$tmp/rows_$mesh.csv" "$tmp/flow_$mesh.md"
done
echo >> "$flowmd"
echo "Whole run: $t_total s (the meshes side by side, one process each)." >> "$flowmd"
mv "$rows" "$tmp/vplus.csv"
"$here/deposition-report" --force --out "$tmp" "$tmp/vplus.csv" || { echo "deposition.sh: the report failed" >&2; exit 1; }
echo "deposition.sh: done in $t_total s"
cat "$tmp/vplus.md"
outdir_commit
