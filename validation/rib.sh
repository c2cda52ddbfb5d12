#!/usr/bin/env bash
# rib.sh - deposition in a separated flow: a channel with ribs on its floor,
# every dispersion treatment, the deposition per wall zone behind the rib
#
# Usage: validation/rib.sh --out DIR [--force] [--mesh resolved|wf|both]
#            [--tau-plus LIST] [--models LIST] [--parcels N] [--t-run T]
#            [--gravity none|floor] [--coeffs FILE] [--short]
#            [--interpolation faceFlux|cellPoint] [--help]
#
# A channel of height 10 H (H = 5 mm) with square ribs of height H on its
# floor every 20 H and a smooth top wall, periodic along the flow, two-
# dimensional (one cell across, empty sides), air at 20 C, the bulk velocity
# 6 m/s (Re 20 000 on the channel's height) held by a mean pressure gradient;
# steady RANS (kOmegaSST, simpleFoam, 4000 iterations; the flow table gives
# the pressure gradient's change over the last 500 as its convergence), then
# frozen. Behind each rib the flow separates and reattaches a few rib heights
# downstream: the wall shear goes to zero and changes sign, the case where the
# near-wall treatment leaves the channel it was calibrated in. The smooth top
# wall of the same channel is the reference.
#
# For every tau+ of the list and every treatment one cloud of ice spheres
# (920 kg/m3) released uniformly over the channel; every wall contact is a
# deposit (localInteraction escape). The clouds ride the frozen flow together
# (pimpleUncoupledKinematicParcelFoam -frozen), steps of 2 t+, a warm-up of
# 2000 t+ then the window of --t-run t+; t+ and tau+ in the units of the top
# wall, t+ = t u_top^2/nu, tau+ = tau_p u_top^2/nu, u_top from its mean wall
# shear. Per wall zone Z (area A_Z) the deposition velocity
#   V+_Z = (D_Z + E_Z) Vol / (A_Z u_top Int N dt)
# over the window, D_Z the parcels that left through Z by tracking, E_Z the
# expected number that the sublayer closure of snowNearWall brought there
# (0 for the other treatments), Vol the channel's volume, N the parcels in
# it; standard error V+_Z/sqrt(D_Z + E_Z) (that of one deposit when none).
# Zones: top (the smooth wall), floorUp (the 5 H of floor before the rib),
# ribFront, ribTop, ribBack, and the floor after the rib in bands of x/H from
# its back face 0-2, 2-4, 4-6, 6-9, 9-12, 12-14 (floor_0 ... floor_5).
#
# Treatments (--models, comma-separated): stochastic
# (stochasticDispersionRAS), gradient (gradientDispersionRAS), none, nearwall
# (snowNearWall with the closure of --coeffs), nearwall-utau and nearwall-k
# (its velocity scale from the wall shear / the turbulence alone), crw
# (snowNearWall without the closure); default stochastic,none,nearwall.
# Meshes (--mesh): resolved (the first cell at y+ about 1 on every wall,
# 19 280 cells), wf (uniform cells of H/2, first cell centre at y+ 25-40,
# wall functions, 796 cells: the class of the wedge's mesh), both (default:
# side by side, one process each).
# --gravity: none (default: the walls vertical, turbulence alone carries the
# particles across) or floor (gravity towards the floor, as in wind-tunnel
# measurements on horizontal floors; with snowNearWall it shows an open
# defect of the walk, doc/deposition.md); --tau-plus: default 0.3,1,3,10,30
# (each in [0.01, 1000], no value twice); --parcels per cloud (default 3000);
# --t-run (default 20000, rounded up to whole warm-up lengths); --coeffs: the
# closure (default etc/deposition.coeffs); --short: the test (wf mesh, tau+
# 10, none and nearwall, 1500 parcels, window 4000).
#
# --interpolation: the parcels' velocity interpolation, faceFlux (default:
# rebuilt from the flow's face fluxes in every hexahedron, so that the mean
# flow keeps tracers uniform, doc/deposition.md) or cellPoint (OpenFOAM's:
# it gathers tracer-like parcels at walls on wall-function meshes).
#
# Writes into DIR, only when the run succeeds: zones.csv (per mesh,
# treatment, tau+ and zone: the counts, V+, its error, V+ over the top wall's),
# wakes.csv and rib.md (the tables; the near wake 0-4 H against the far wake
# 9-14 H, the whole ribbed wall against the top wall), rib.png (V+ of the floor
# over the top wall's against x/H per tau+, the reattachment marked; near wake,
# far wake and top wall against tau+ with Wood's correlation), flow.md (u_top,
# the ribbed wall's u* from the momentum balance, the reattachment length, the
# convergence, the run times), <mesh>/wall.csv (the zones' mean wall shear and
# y+, the reattachment), deposition.coeffs and the cases (<mesh>/case).
# The rules of --out are those of every SnowWall script (etc/outdir.sh): DIR
# missing is created; an empty folder or an earlier SnowWall output folder
# gets the files beside what it holds; any other existing DIR is refused
# (exit 2) unless --force; nothing in DIR is ever deleted. Before any work
# one line estimates the parcels, memory and time; a memory estimate above
# what the machine has available is refused.
# Exit status: 0 done, 1 a run failed, 2 usage error.
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
here="$top/validation/deposition"
out=
meshes=both
taus=0.3,1,3,10,30
models=stochastic,none,nearwall
parcels=3000
trun=20000
twarm=2000
gravity=none
coeffs=
interp=faceFlux
force=0
zones=0,2,4,6,9,12,14
die2() { echo "rib.sh: $*" >&2; exit 2; }
# shellcheck source=deposition/common.sh
. "$here/common.sh"
while [ $# -gt 0 ]; do
    case "$1" in
        -h|--help) awk 'NR > 1 && !/^#/ { exit } NR > 1 { sub(/^# ?/, ""); print }' "$0"; exit 0 ;;
        --mesh) [ -n "${2:-}" ] || die2 "--mesh needs resolved, wf or both"; meshes=$2; shift ;;
        --tau-plus) [ -n "${2:-}" ] || die2 "--tau-plus needs a list"; taus=$2; shift ;;
        --t-run) [ -n "${2:-}" ] || die2 "--t-run needs a number"; trun=$2; shift ;;
        --gravity) [ -n "${2:-}" ] || die2 "--gravity needs none or floor"; gravity=$2; shift ;;
        --short) meshes=wf; taus=10; models=none,nearwall; parcels=1500; trun=4000; twarm=1000 ;;
        *) dep_option rib.sh "$1" "${2:-}" || exit 2; [ "$DEP_NARGS" = 1 ] || shift ;;
    esac
    shift
done
[ -n "$out" ] || die2 "--out DIR is required (see --help)"
case "$meshes" in resolved|wf) ;; both) meshes="resolved wf" ;; *) die2 "--mesh: '$meshes' is not resolved, wf or both" ;; esac
case "$gravity" in none|floor) ;; *) die2 "--gravity: '$gravity' is not none or floor" ;; esac
[[ "$parcels" =~ ^[1-9][0-9]{0,5}$ ]] || die2 "--parcels: '$parcels' is not a whole number in 1..999999"
[[ "$trun" =~ ^[1-9][0-9]{0,6}$ ]] || die2 "--t-run: '$trun' is not a whole number of wall units in 1..9999999"
# shellcheck source=../etc/outdir.sh
. "$top/etc/outdir.sh"
dep_interpolation rib.sh "$interp" || exit 2
outdir_list taus rib.sh --tau-plus "$taus" num
outdir_list models rib.sh --models "$models" name
IFS=, read -r -a tauList <<< "$taus"
dep_numbers rib.sh --tau-plus 0.01 1000 "${tauList[@]}" || exit 2
IFS=, read -r -a modelList <<< "$models"
dep_models rib.sh "stochastic gradient none nearwall nearwall-utau nearwall-k crw" "${modelList[@]}" || exit 2
[ -n "$coeffs" ] || coeffs="$top/etc/deposition.coeffs"
dep_require rib.sh "$top" simpleFoam blockMesh topoSet createPatch postProcess || exit 1
dep_check_coeffs rib.sh "$top" "$coeffs" || exit $?
# what the options multiply, before any work, scaled from the measured default
# run (2026-11-28, one process per mesh, 1908 s: the resolved flow 258 s and
# 3.3 us per parcel and step, the wf flow 4 s and 1.7 us): about 4 kB a cell
# and 1 kB a parcel
nsteps_est=$(awk -v w="$twarm" -v r="$trun" 'BEGIN { nw = int(w / 2 + 0.5); printf "%d", nw * (1 + int((r / 2 + nw - 1) / nw)) }')
read -r est_p est_mem est_min < <(awk -v meshes="$meshes" -v nm="${#modelList[@]}" -v ns="${#tauList[@]}" -v np="$parcels" \
    -v st="$nsteps_est" 'BEGIN {
        n = split(meshes, m, " "); p = nm * ns * np; tmax = 0; mem = 0
        for (i = 1; i <= n; i++) {
            c = m[i] == "wf" ? 796 : 19280
            tf = m[i] == "wf" ? 5 : 260
            tp = (m[i] == "wf" ? 1.7e-6 : 3.3e-6) * p * st
            if (tf + tp > tmax) tmax = tf + tp
            mem += c * 4e3 + p * 1e3
        }
        printf "%d %.6g %.6g\n", p, mem, tmax / 60
    }')
dep_estimate rib.sh "$est_p" $((${#modelList[@]} * ${#tauList[@]})) "$nsteps_est steps" "$est_mem" "$est_min" \
    "fewer --parcels, --models or --tau-plus" || exit 2
outdir_begin rib.sh "$out" "$force"
# shellcheck source=../etc/openfoam-env.sh
. "$top/etc/openfoam-env.sh" >/dev/null
t_start=$(date +%s)
cp "$coeffs" "$tmp/deposition.coeffs"
coeffs="$tmp/deposition.coeffs"

# the channel: rib height H, period 20 H, height 10 H, span H
h=0.005
ubar=6
nu=1.5e-5
mu=1.8e-5   # nu * rhoInf (1.2)
rhop=920
walls="top floorUp ribFront ribTop ribBack"
nz=$(awk -F, '{ print NF - 1 }' <<< "$zones")
for ((i = 0; i < nz; i++)); do walls="$walls floor_$i"; done

write_cloud() {   # case name d model
    dep_write_cloud "$1" "$2" "$3" "$4" "$rhop" "($ubar 0 0)" uniform "$walls" "($walls)"
}

# parcels released uniformly over the fluid (not in the rib; 1e-6 H off the
# walls), in the mid-plane of the two-dimensional mesh
write_positions() {   # case n seed
    awk -v n="$2" -v s="$3" -v h="$h" 'BEGIN {
        srand(s); e = 1e-6 * h
        print "FoamFile { version 2.0; format ascii; class vectorField; object positions; }"
        print n; print "("
        for (i = 0; i < n; ) {
            x = -5 * h + e + (20 * h - 2 * e) * rand(); y = e + (10 * h - 2 * e) * rand()
            if (x > -e && x < h + e && y < h + e) continue
            printf "(%.10g %.10g %.10g)\n", x, y, 0.5 * h; i++
        }
        print ")"
    }' > "$1/constant/positions"
}

run_mesh() {
    local mesh=$1
    c="$tmp/$mesh/case"
    mkdir -p "$c"
    cp -r "$here/rib/system" "$here/rib/constant" "$here/rib/0.orig" "$c/"
    if [ "$mesh" = resolved ]; then kwall=fixedValue; nutwall=nutLowReWallFunction
    else kwall=kqRWallFunction; nutwall=nutkWallFunction; fi
    cat > "$c/constant/ribParameters" <<EOF
Ubar    $ubar;
kWall   $kwall;
nutWall $nutwall;
EOF
    [ "$gravity" = floor ] && g="0 -9.81 0" || g="0 0 0"
    cat > "$c/constant/g" <<EOF
FoamFile { version 2.0; format ascii; class uniformDimensionedVectorField; object g; }
dimensions      [0 1 -2 0 0 0 0];
value           ($g);
EOF
    "$here/rib-mesh" --case "$c" --h "$h" --mesh "$mesh" --zones "$zones"
    dep_flow rib.sh "$c" "$mesh" 4000 topoSet "createPatch -overwrite" || return 1
    tflow=$DEP_TFLOW last=$DEP_LAST
    cells=$(awk '/nCells:/ { print $2 }' "$c/log.blockMesh")
    # the mean pressure gradient at the end and its change over the last 500
    # iterations (the flow's convergence: the periodic channel's outer flow
    # settles slowly, about halving the change every 500 iterations)
    read -r gradp gdrift < <(awk '/^Time = / { it = $3 } /Pressure gradient source/ { for (i = 1; i <= NF; i++) if ($i == "gradient") g[it] = $(i + 2); last = it }
        END { printf "%s %.2g\n", g[last], (last - 500 in g) ? (g[last] - g[last - 500]) / g[last] : 1 }' "$c/log.simpleFoam")
    # the wall shear per zone and the reattachment length
    (cd "$c" && simpleFoam -postProcess -latestTime -funcs '(wallShearStress yPlus)' > log.wall 2>&1) \
        || { dep_show_fail rib.sh "$mesh: wallShearStress" "$c/log.wall"; return 1; }
    "$here/rib-wall" --case "$c" --time "$last" --h "$h" > "$tmp/wall_$mesh.csv" \
        || { echo "rib.sh: $mesh: reading the wall shear failed" >&2; return 1; }
    utop=$(awk -F, '$1 == "top" { printf "%.6g", sqrt($4 < 0 ? -$4 : $4) }' "$tmp/wall_$mesh.csv")
    [ -n "$utop" ] || { echo "rib.sh: $mesh: no wall shear of the top wall" >&2; return 1; }
    # the ribbed wall's u*: the momentum balance of a period less the top wall's share
    urib=$(awk -v g="$gradp" -v h="$h" -v u="$utop" 'BEGIN { f = g * (200 * h * h - h * h) / (20 * h) - u * u; printf "%.4g", (f > 0 ? sqrt(f) : 0) }')
    xr=$(awk -F, '$1 == "reattachment" { print $2 }' "$tmp/wall_$mesh.csv")
    (cd "$c" && rm -rf 0 && mv "$last" 0 && rm -rf 0/uniform 0/wallShearStress 0/yPlus)

    tnu=$(awk -v u="$utop" -v nu="$nu" 'BEGIN { printf "%.10g", nu / (u * u) }')
    dt=$(awk -v t="$tnu" 'BEGIN { printf "%.6g", 2 * t }')
    # whole warm-up lengths: the closure's counts are written at their ends
    nsteps=$(awk -v w="$twarm" -v r="$trun" 'BEGIN { nw = int(w / 2 + 0.5); printf "%d", nw * (1 + int((r / 2 + nw - 1) / nw)) }')
    tend=$(awk -v n="$nsteps" -v b="$dt" 'BEGIN { printf "%.10g", n * b }')
    nwarm=$(awk -v w="$twarm" 'BEGIN { printf "%d", w / 2 + 0.5 }')
    write_positions "$c" "$parcels" 7
    cp "$coeffs" "$c/constant/deposition.coeffs"
    : > "$c/clouds.txt"
    nclouds=0
    for m in "${modelList[@]}"; do
        for i in "${!tauList[@]}"; do
            t=${tauList[$i]}
            d=$(awk -v t="$t" -v u="$utop" -v nu="$nu" -v mu="$mu" -v r="$rhop" 'BEGIN { printf "%.6g", sqrt(18 * mu * t * nu / (r * u * u)) }')
            name="c_${m}_$i"
            write_cloud "$c" "$name" "$d" "$m" || return 1
            echo "$name $m $t $d" >> "$c/clouds.txt"
            nclouds=$((nclouds + 1))
        done
    done
    dep_control "$c" pimpleUncoupledKinematicParcelFoam "$tend" "$dt" "$nwarm"
    dep_particle_schemes "$c"
    echo "rib.sh: $mesh mesh: u_top $utop m/s, ribbed wall u* $urib m/s, reattachment $xr H; $nclouds clouds of $parcels parcels, $nsteps steps of 2 t+"
    t0=$(date +%s)
    dep_run_particles "$c" "$nwarm" || { dep_show_fail rib.sh "$mesh: the particle run" "$c/log.particles"; return 1; }
    tpart=$(( $(date +%s) - t0 ))
    "$here/rib-deposit" --case "$c" --mesh "$mesh" --h "$h" --utop "$utop" --dt "$dt" --nwarm "$nwarm" \
        > "$tmp/rows_$mesh.csv" \
        || { echo "rib.sh: $mesh: reading the particle run failed" >&2; return 1; }
    awk -v m="$mesh" -v cells="$cells" -v u="$utop" -v ur="$urib" -v xr="$xr" -v g="$gradp" -v gd="$gdrift" -v tf="$tflow" -v tp="$tpart" \
        -v ns="$nsteps" -v nc="$nclouds" -v w="$tmp/wall_$mesh.csv" 'BEGIN {
        while ((getline l < w) > 0) { split(l, a, ","); if (a[1] == "top") yt = a[5]; if (a[1] == "floor_5") yf = a[5] }
        printf "| %s | %d | %.4g (%s) | %.3g | %.3g | %s | %.3g | %.3g | %d | %d | %d steps x %d clouds |\n", \
            m, cells, g, gd, u, ur, xr, yt, yf, tf, tp, ns, nc
    }' > "$tmp/flow_$mesh.md"
}

{
    echo "# The ribbed channel's flow (validation/rib.sh)"
    echo
    echo "Rib height H = $h m, period 20 H, channel height 10 H, bulk velocity $ubar m/s"
    echo "(Re $(awk -v u="$ubar" -v h="$h" -v nu="$nu" 'BEGIN { printf "%.0f", u * 10 * h / nu }') on the height), gravity: $gravity."
    echo "u_top from the top wall's mean shear; the ribbed wall's u* from the momentum balance of a"
    echo "period (pressure gradient times the fluid's area, less the top wall's shear); the"
    echo "reattachment length from the rib's back face to where the floor's shear turns positive."
    echo
    echo "| mesh | cells | dp/dx [m/s2] (its relative change over the last 500 of 4000 SIMPLE iterations) | u_top [m/s] | ribbed wall u* [m/s] | reattachment [H] | top y+ | floor y+ (12-14 H) | flow run [s] | particle run [s] | parcel steps |"
    echo "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
} > "$tmp/flow.md"
pids=()
for mesh in $meshes; do
    run_mesh "$mesh" &
    pids+=($!)
done
failed=0
for pid in "${pids[@]}"; do wait "$pid" || failed=1; done
[ "$failed" = 0 ] || { echo "rib.sh: a mesh failed (above)" >&2; exit 1; }
t_total=$(( $(date +%s) - t_start ))
echo "mesh,model,tau_plus,d_m,zone,x0_h,x1_h,area_m2,tracked,closure_expected,vplus,vplus_se,ratio_top" > "$tmp/zones.csv"
for mesh in $meshes; do
    cat "$tmp/rows_$mesh.csv" >> "$tmp/zones.csv"
    cat "$tmp/flow_$mesh.md" >> "$tmp/flow.md"
    mv "$tmp/wall_$mesh.csv" "$tmp/$mesh/wall.csv"
    rm -f "$tmp/rows_$mesh.csv" "$tmp/flow_$mesh.md"
done
echo >> "$tmp/flow.md"
echo "Whole run: $t_total s (the meshes side by side, one process each)." >> "$tmp/flow.md"
"$here/rib-report" --dir "$tmp" || { echo "rib.sh: the report failed" >&2; exit 1; }
echo "rib.sh: done in $t_total s"
cat "$tmp/rib.md"
outdir_commit
