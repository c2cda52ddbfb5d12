#!/usr/bin/env bash
# bend.sh - inertial deposition in a 90 degree pipe bend: the CFD chain and
# every dispersion treatment against Pui, Romay-Novas & Liu (1987)
#
# Usage: validation/bend.sh --out DIR [--force] [--mesh LIST]
#            [--stokes LIST] [--models LIST] [--parcels N] [--step F]
#            [--coeffs FILE] [--short]
#            [--interpolation faceFlux|cellPoint] [--help]
#
# A turbulent pipe flow (Re = 10 000 on the diameter, air at 20 C) through a
# 90 degree bend of curvature ratio R0 = R_bend/a = 5.6 (a the tube radius,
# 4.25 mm): a straight inlet of 5 diameters whose inflow is recycled from 3
# diameters downstream (a developed profile), the bend, 4 diameters of outlet.
# Steady RANS (kOmegaSST, simpleFoam), then frozen. In it, for every Stokes
# number of the list and every dispersion treatment, one cloud of ice spheres
# (920 kg/m3) released at once on the inlet plane, placed by the inlet's
# volume flux (a flux-weighted sample of the developed profile, uniform in
# angle) with the bulk velocity. Every wall contact is a deposit
# (localInteraction escape). The clouds ride the frozen flow together
# (pimpleUncoupledKinematicParcelFoam -frozen) until the parcels have left.
#
# Stk = rho_p d^2 U / (9 mu D) (the particle's Stokes time over the time the
# flow takes for a tube radius; no slip correction), U the bulk velocity;
# the bend's deposition efficiency
#   eta = (B + E) / N_in
# B the parcels that left through the bend's wall by tracking, E the expected
# number that the sublayer closure of snowNearWall brought there (its
# probabilities summed; 0 for the other treatments), N_in the parcels that
# entered the bend (released, less those deposited on the inlet pipe's wall,
# those that left through the inlet and those still in the inlet pipe at the
# end); standard error sqrt(eta (1 - eta) / N_in) (binomial); and eta_max,
# eta if every parcel still in the bend at the end had deposited there. Pui
# et al.'s turbulent fit (Re 6 000 and 10 000): eta = 1 - 10^(-0.963 Stk).
#
# Treatments (--models, comma-separated): stochastic
# (stochasticDispersionRAS), gradient (gradientDispersionRAS), none (no
# dispersion), nearwall (snowNearWall: the C core's continuous random walk
# with the sublayer closure of --coeffs), nearwall-utau and nearwall-k (the
# same with the wall layer's velocity scale u* from the wall shear alone or
# from the turbulence alone, velocityScale wallShear / turbulence), crw
# (snowNearWall without the closure). Meshes (--mesh, comma-separated):
# resolved (an O-grid of 8 x 8 + 4 x 8 x 20 cells a section, the ring graded
# to a first cell of y+ about 1; 30, 60, 20 cells along the inlet, bend and
# outlet), fine (the resolved mesh with 1.5 times the cells in every
# direction: 12 x 12 + 4 x 12 x 30, 45, 90, 30; about 3.4 times the cells),
# wf (a wall-function mesh, 4 x 4 + 4 x 4 x 4 cells a section, first cell
# centre at y+ about 20, as on the wedge); both (default) is resolved,wf. The meshes run side by side, one
# process each.
# --step F: the particles' time step as a fraction of the bulk's transit time
# of a tube radius (default 0.05; in (0, 0.5]).
#
# --interpolation: the parcels' velocity interpolation, faceFlux (default:
# rebuilt from the flow's face fluxes in every hexahedron, so that the mean
# flow keeps tracers uniform, doc/deposition.md) or cellPoint (OpenFOAM's:
# it gathers tracer-like parcels at walls on wall-function meshes).
#
# Writes into DIR, only when the run succeeds: efficiency.csv and
# efficiency.md (eta per mesh, treatment and Stk, with the counts, the error
# and Pui's fit), efficiency.png (eta against Stk with the fit), flow.md (the
# flow: friction factor of the inlet pipe against Blasius, u_tau, y+ of the
# first cell, Dean number, the run times), deposition.coeffs (the closure
# used) and the cases (<mesh>/case, logs included). The rules of --out are
# those of every SnowWall script (etc/outdir.sh): DIR missing is created; an
# empty folder or an earlier SnowWall output folder gets the files beside
# what it holds; any other existing DIR is refused (exit 2) unless --force;
# nothing in DIR is ever deleted.
# --stokes: default 0.01,0.03,0.1,0.3,1 (no empty item, no value twice, each
# in [0.001, 10]; used in ascending order); --models: default
# stochastic,none,crw,nearwall (no empty item, no name twice); --parcels per
# cloud (default 2000); --coeffs: the closure (default etc/deposition.coeffs);
# --short: the test (wf mesh, Stk 0.1 and 1, none and nearwall, 600 parcels).
# Parcels still in the pipe when the run ends (the slowest, near the wall)
# are counted and reported; the run ends after 8 flow-through times.
# Before any work one line estimates the parcels, memory and time of the
# options (scaled from the measured default run); a memory estimate above what
# the machine has available is refused (exit 2).
# Exit status: 0 done, 1 a run failed, 2 usage error.
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
here="$top/validation/deposition"
out=
meshes=both
stokes=0.01,0.03,0.1,0.3,1
models=stochastic,none,crw,nearwall
parcels=2000
coeffs=
interp=faceFlux
force=0
step=0.05
die2() { echo "bend.sh: $*" >&2; exit 2; }
# shellcheck source=deposition/common.sh
. "$here/common.sh"
while [ $# -gt 0 ]; do
    case "$1" in
        -h|--help) awk 'NR > 1 && !/^#/ { exit } NR > 1 { sub(/^# ?/, ""); print }' "$0"; exit 0 ;;
        --mesh) [ -n "${2:-}" ] || die2 "--mesh needs a list of resolved, fine, wf or both"; meshes=$2; shift ;;
        --step) [ -n "${2:-}" ] || die2 "--step needs a number"; step=$2; shift ;;
        --stokes) [ -n "${2:-}" ] || die2 "--stokes needs a list"; stokes=$2; shift ;;
        --short) meshes=wf; stokes=0.1,1; models=none,nearwall; parcels=600 ;;
        *) dep_option bend.sh "$1" "${2:-}" || exit 2; [ "$DEP_NARGS" = 1 ] || shift ;;
    esac
    shift
done
[ -n "$out" ] || die2 "--out DIR is required (see --help)"
[ "$meshes" = both ] && meshes=resolved,wf
[[ "$parcels" =~ ^[1-9][0-9]{0,5}$ ]] || die2 "--parcels: '$parcels' is not a whole number in 1..999999"
# shellcheck source=../etc/outdir.sh
. "$top/etc/outdir.sh"
dep_interpolation bend.sh "$interp" || exit 2
outdir_list stokes bend.sh --stokes "$stokes" num
outdir_list models bend.sh --models "$models" name
outdir_list meshes bend.sh --mesh "$meshes" name
IFS=, read -r -a meshList <<< "$meshes"
for m in "${meshList[@]}"; do
    case "$m" in resolved|fine|wf) ;; *) die2 "--mesh: '$m' is not resolved, fine or wf" ;; esac
done
awk -v t="$step" 'BEGIN { exit !(t ~ /^[0-9]*\.?[0-9]+([eE][-+]?[0-9]+)?$/ && t + 0 > 0 && t + 0 <= 0.5) }' \
    || die2 "--step: '$step' is not a number in (0, 0.5]"
IFS=, read -r -a stkList <<< "$stokes"
dep_numbers bend.sh --stokes 0.001 10 "${stkList[@]}" || exit 2
IFS=, read -r -a modelList <<< "$models"
dep_models bend.sh "stochastic gradient none nearwall nearwall-utau nearwall-k crw" "${modelList[@]}" || exit 2
[ -n "$coeffs" ] || coeffs="$top/etc/deposition.coeffs"
dep_require bend.sh "$top" simpleFoam blockMesh postProcess || exit 1
dep_check_coeffs bend.sh "$top" "$coeffs" || exit $?
# what the options multiply, before any work: parcels, memory and time, scaled
# from the measured default run (2026-11-28, one process per mesh: resolved flow
# 154 s and 20 x 2000 parcels 97 s; wf 5 s and 94 s; fine 3.4 times the
# resolved mesh's cells; about 4 kB a cell and 1 kB a parcel)
read -r est_p est_mem est_min < <(awk -v meshes="${meshList[*]}" -v nm="${#modelList[@]}" -v ns="${#stkList[@]}" \
    -v np="$parcels" -v st="$step" 'BEGIN {
        n = split(meshes, m, " "); p = nm * ns * np; tmax = 0; mem = 0
        for (i = 1; i <= n; i++) {
            c = m[i] == "wf" ? 4400 : m[i] == "fine" ? 261360 : 77440
            tf = m[i] == "wf" ? 5 : m[i] == "fine" ? 154 * 4.5 : 154
            tp = (m[i] == "wf" ? 94 : m[i] == "fine" ? 97 * 3.4 : 97) * (p / 40000) * (0.05 / st)
            if (tf + tp > tmax) tmax = tf + tp
            mem += c * 4e3 + p * 1e3
        }
        printf "%d %.6g %.6g\n", p, mem, tmax / 60
    }')
dep_estimate bend.sh "$est_p" $((${#modelList[@]} * ${#stkList[@]})) "${#meshList[@]} mesh(es) side by side" "$est_mem" "$est_min" \
    "fewer --parcels, --models, --stokes or meshes" || exit 2
outdir_begin bend.sh "$out" "$force"
# shellcheck source=../etc/openfoam-env.sh
. "$top/etc/openfoam-env.sh" >/dev/null
t_start=$(date +%s)
cp "$coeffs" "$tmp/deposition.coeffs"
coeffs="$tmp/deposition.coeffs"

# the pipe: radius a, diameter D, Re = U D / nu = 10 000, air at 20 C
a=0.00425
dia=0.0085
nu=1.5e-5
mu=1.8e-5   # nu * rhoInf (1.2)
ubar=$(awk -v d="$dia" -v nu="$nu" 'BEGIN { printf "%.6g", 1e4 * nu / d }')
rhop=920
r0=5.6
lin=$(awk -v d="$dia" 'BEGIN { printf "%.6g", 5 * d }')
lout=$(awk -v d="$dia" 'BEGIN { printf "%.6g", 4 * d }')
lbend=$(awk -v a="$a" -v r="$r0" 'BEGIN { printf "%.6g", r * a * atan2(1, 0) }')

# cloud properties: one Stokes number and treatment
write_cloud() {   # case name d model
    dep_write_cloud "$1" "$2" "$3" "$4" "$rhop" "($ubar 0 0)" inlet "inlet outlet wallIn bend wallOut" "(wallIn bend wallOut)"
}

# the release: N points on the inlet plane, the radius drawn from the inlet's
# volume flux (faces binned by radius, cumulative flux interpolated linearly
# in r^2 inside a bin), uniform in angle; inside the circle inscribed in the
# mesh's polygon of 4 NC wall faces (by 1e-4 of it), 1e-4 a downstream of the
# inlet
write_positions() {   # case n seed nc
    local c=$1
    (cd "$c" && postProcess -func writeCellCentres -latestTime > log.cellCentres 2>&1) \
        || { dep_show_fail bend.sh writeCellCentres "$c/log.cellCentres"; return 1; }
    local last
    last=$(cd "$c" && foamListTimes -latestTime 2>/dev/null | tail -1)
    awk -v n="$2" -v s="$3" -v a="$a" -v x0="-$lin" -v nc="$4" '
        # the inlet entries of a boundaryField: face centres (C) and fluxes (phi)
        FNR == 1 { file++; inl = 0; lst = 0; cnt = 0 }
        /^[ \t]*inlet[ \t]*$/ { inl = 1; next }
        inl && /^[ \t]*}/ { inl = 0; lst = 0 }
        inl && /value[ \t]+nonuniform/ { lst = 1; next }
        inl && lst == 1 && /^\(/ { lst = 2; next }
        inl && lst == 2 && /^\)/ { lst = 0; next }
        inl && lst == 2 {
            if (file == 1) { gsub(/[()]/, ""); y[cnt] = $2; z[cnt] = $3 }
            else flux[cnt] = -$1
            cnt++; nf = cnt
        }
        END {
            nb = 40
            for (i = 0; i < nf; i++) {
                r = sqrt(y[i] ^ 2 + z[i] ^ 2) / a; b = int(r * r * nb); if (b >= nb) b = nb - 1
                f[b] += flux[i]; tot += flux[i]
            }
            if (!(tot > 0)) { print "bend.sh: no inflow on the inlet patch" > "/dev/stderr"; exit 1 }
            cum[0] = 0
            for (b = 0; b < nb; b++) cum[b + 1] = cum[b] + f[b] / tot
            srand(s); pi = atan2(0, -1); rin = cos(pi / (4 * nc)) * (1 - 1e-4)
            print "FoamFile { version 2.0; format ascii; class vectorField; object positions; }"
            print n; print "("
            for (k = 0; k < n; k++) {
                u = rand(); b = 0
                while (b < nb - 1 && cum[b + 1] < u) b++
                w = (cum[b + 1] > cum[b]) ? (u - cum[b]) / (cum[b + 1] - cum[b]) : 0.5
                r = a * sqrt((b + w) / nb) * rin; t = 2 * pi * rand()
                printf "(%.10g %.10g %.10g)\n", x0 + 1e-4 * a, r * cos(t), r * sin(t)
            }
            print ")"
        }' "$c/$last/C" "$c/$last/phi" > "$c/constant/positions"
}

# one mesh: flow, particles, rows into $tmp/rows_<mesh>.csv, the flow table's
# row into $tmp/flow_<mesh>.md
run_mesh() {
    local mesh=$1
    c="$tmp/$mesh/case"
    mkdir -p "$c"
    cp -r "$here/bend/system" "$here/bend/constant" "$here/bend/0.orig" "$c/"
    case "$mesh" in
        resolved) nc=8; nr=20; grading=40; axial=30,60,20; kwall=fixedValue; nutwall=nutLowReWallFunction ;;
        fine) nc=12; nr=30; grading=40; axial=45,90,30; kwall=fixedValue; nutwall=nutLowReWallFunction ;;
        *) nc=4; nr=4; grading=1; axial=15,30,10; kwall=kqRWallFunction; nutwall=nutkWallFunction ;;
    esac
    cat > "$c/constant/bendParameters" <<EOF
Ubar    $ubar;
kWall   $kwall;
nutWall $nutwall;
EOF
    "$here/bend-mesh" --radius "$a" --bend-ratio "$r0" --inlet "$lin" --outlet "$lout" \
        --centre "$nc" --ring "$nr" --grading "$grading" --axial "$axial" > "$c/system/blockMeshDict"
    dep_flow bend.sh "$c" "$mesh" 3000 || return 1
    tflow=$DEP_TFLOW last=$DEP_LAST
    iters=$(awk '/^Time = / { n = $3 } END { print n }' "$c/log.simpleFoam")
    cells=$(awk '/nCells:/ { print $2 }' "$c/log.blockMesh")
    # the inlet pipe's mean wall shear (kinematic) and the first cell's y+
    (cd "$c" && simpleFoam -postProcess -latestTime -funcs '(wallShearStress yPlus)' > log.wall 2>&1) \
        || { dep_show_fail bend.sh "$mesh: wallShearStress" "$c/log.wall"; return 1; }
    (cd "$c" && postProcess -latestTime -func 'patchAverage(name=wallIn,wallShearStress)' > log.tauw 2>&1) \
        || { dep_show_fail bend.sh "$mesh: the wall shear average" "$c/log.tauw"; return 1; }
    tauw=$(awk '/areaAverage\(wallIn\) of wallShearStress/ { gsub(/[()]/, ""); print sqrt($(NF-2)^2 + $(NF-1)^2 + $NF^2) }' "$c/log.tauw" | tail -1)
    [ -n "$tauw" ] || { echo "bend.sh: $mesh: no wall shear in $c/log.tauw" >&2; return 1; }
    yplus=$(awk '/patch wallIn y\+ : min/ || (/y\+ : min/ && /wallIn/) { for (i = 1; i <= NF; i++) if ($i == "average") a = $(i + 2) } END { print a }' "$c/log.wall")
    # the converged flow becomes time 0 for the particles
    write_positions "$c" "$parcels" 7 "$nc" || return 1
    (cd "$c" && rm -rf 0 && mv "$last" 0 && rm -rf 0/uniform 0/C* 0/wallShearStress 0/yPlus)
    cp "$coeffs" "$c/constant/deposition.coeffs"

    # the clouds: steps of --step of the bulk's transit time of a tube radius;
    # 8 flow-through times of the pipe's length
    dt=$(awk -v a="$a" -v u="$ubar" -v f="$step" 'BEGIN { printf "%.6g", a / u * f }')
    len=$(awk -v l1="$lin" -v l2="$lbend" -v l3="$lout" 'BEGIN { printf "%.6g", l1 + l2 + l3 }')
    nsteps=$(awk -v l="$len" -v u="$ubar" -v dt="$dt" 'BEGIN { printf "%d", 8 * l / u / dt + 0.5 }')
    tend=$(awk -v n="$nsteps" -v b="$dt" 'BEGIN { printf "%.10g", n * b }')
    clouds=()
    : > "$c/clouds.txt"
    for m in "${modelList[@]}"; do
        for i in "${!stkList[@]}"; do
            s=${stkList[$i]}
            d=$(awk -v s="$s" -v mu="$mu" -v D="$dia" -v r="$rhop" -v u="$ubar" 'BEGIN { printf "%.6g", sqrt(9 * mu * D * s / (r * u)) }')
            name="c_${m}_$i"
            write_cloud "$c" "$name" "$d" "$m"
            clouds+=("$name")
            echo "$name $m $s $d" >> "$c/clouds.txt"
        done
    done
    dep_control "$c" pimpleUncoupledKinematicParcelFoam "$tend" "$dt" "$nsteps"
    dep_particle_schemes "$c"
    echo "bend.sh: $mesh mesh: ${#clouds[@]} clouds of $parcels parcels, $nsteps steps of $dt s"
    t0=$(date +%s)
    dep_run_particles "$c" || { dep_show_fail bend.sh "$mesh: the particle run" "$c/log.particles"; return 1; }
    tpart=$(( $(date +%s) - t0 ))

    "$here/bend-efficiency" --case "$c" --mesh "$mesh" --parcels "$parcels" \
        --bend-radius "$(awk -v a="$a" -v r="$r0" 'BEGIN { printf "%.10g", a * r }')" > "$tmp/rows_$mesh.csv" \
        || { echo "bend.sh: $mesh: reading the particle run failed" >&2; return 1; }
    awk -v m="$mesh" -v cells="$cells" -v it="$iters" -v t="$tauw" -v u="$ubar" -v yp="$yplus" \
        -v nu="$nu" -v d="$dia" -v tf="$tflow" -v tp="$tpart" -v ns="$nsteps" -v nc="${#clouds[@]}" 'BEGIN {
        f = 8 * t / (u * u); ut = sqrt(t)
        printf "| %s | %d | %d | %.4g | %.4g | %.3g | %.4g | %.3g | %d | %d | %d steps x %d clouds |\n", \
            m, cells, it, f, f / (0.3164 * 1e4 ^ -0.25), ut, ut * d / (2 * nu), yp, tf, tp, ns, nc
    }' > "$tmp/flow_$mesh.md"
}

rows="$tmp/efficiency.csv"
flowmd="$tmp/flow.md"
{
    echo "# The bend's flow (validation/bend.sh)"
    echo
    echo "Pipe diameter $dia m, bulk velocity $ubar m/s (Re 10 000), bend radius $r0 tube radii"
    echo "(Dean number Re/sqrt($r0) = $(awk -v r="$r0" 'BEGIN { printf "%.0f", 1e4 / sqrt(r) }')), inlet $lin m, bend $lbend m, outlet $lout m."
    echo "Friction factor f = 8 tau_w / (rho U^2) from the mean wall shear of the inlet pipe;"
    echo "Blasius: f = 0.3164 Re^-0.25 = $(awk 'BEGIN { printf "%.4f", 0.3164 * 1e4 ^ -0.25 }')."
    echo
    echo "| mesh | cells | SIMPLE iterations | f (inlet pipe) | f / Blasius | u_tau [m/s] | Re_tau | first cell y+ (inlet pipe, mean) | flow run [s] | particle run [s] | parcel steps |"
    echo "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
} > "$flowmd"
pids=()
for mesh in "${meshList[@]}"; do
    run_mesh "$mesh" &
    pids+=($!)
done
failed=0
for pid in "${pids[@]}"; do wait "$pid" || failed=1; done
[ "$failed" = 0 ] || { echo "bend.sh: a mesh failed (above)" >&2; exit 1; }
t_total=$(( $(date +%s) - t_start ))
echo "mesh,model,stokes,d_m,parcels,inlet_pipe_deposits,left_by_inlet,entered_bend,bend_tracked,bend_closure_drawn,bend_closure_expected,left_in_pipe,eta,eta_se,pui,in_inlet,in_bend,in_outlet,eta_max" > "$rows"
for mesh in "${meshList[@]}"; do
    cat "$tmp/rows_$mesh.csv" >> "$rows"
    cat "$tmp/flow_$mesh.md" >> "$flowmd"
    rm -f "$tmp/rows_$mesh.csv" "$tmp/flow_$mesh.md"
done
echo >> "$flowmd"
echo "Whole run: $t_total s (the meshes side by side, one process each)." >> "$flowmd"
"$here/bend-report" --dir "$tmp" || { echo "bend.sh: the report failed" >&2; exit 1; }
echo "bend.sh: done in $t_total s"
cat "$tmp/efficiency.md"
outdir_commit
