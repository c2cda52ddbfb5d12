#!/usr/bin/env bash
# wellmixed.sh - the tracer-limit check of the dispersion treatments on any
# case: tracers released uniformly in its frozen flow must stay uniform
#
# Usage: validation/wellmixed.sh --case DIR --walls PATCHES --dt S --out DIR
#            [--time T] [--models LIST] [--parcels N] [--tl-multiple M]
#            [--zone NAME:X0,Y0,Z0:X1,Y1,Z1]... [--d D] [--inlet PATCH]
#            [--interpolation faceFlux|cellPoint] [--wall-release K[:L]]
#            [--force] [--help]
#
# Thomson's well-mixed condition (doc/deposition.md): in any turbulence,
# tracers released well mixed stay well mixed. The check takes the case's mesh
# and its converged flow at time T (default: its first time folder holding
# U, k and omega or epsilon), and rides, in that flow frozen
# (pimpleUncoupledKinematicParcelFoam -frozen), one cloud of near-tracer ice
# spheres (diameter --d, default 0.2 um: tau+ well below 0.01 at wall shear
# velocities under 1 m/s; no gravity) per treatment, released uniformly over
# the whole mesh (cellZoneInjection at a number density that gives --parcels);
# the walls of --walls and every other wall reflect them (localInteraction
# rebound, e = 1, no friction), and so do symmetry planes; other patches let
# them out.
# An open domain (a wind tunnel) loses its tracers through the outlet: with
# --inlet PATCH, tracers also enter through that patch at the rate that keeps
# the release's concentration, n Q (n the parcels per volume, Q the patch's
# volume inflow from the flow's phi), randomly over its faces by area (a
# uniform inflow), from the start to the end; plain patches without net flux
# (slip tunnel walls) then reflect the tracers, as walls do. The cloud function
# wellMixedCheck of each cloud measures the parcels' time-averaged share of
# each y+ band (0-1, 1-5, 5-30, 30-100, beyond; y to the nearest face of
# --walls, u* = max(u_tau, Cmu^(1/4) k^(1/2)) of that face's cell) and of each
# --zone (a box of cells, corners in metres) against the share of the volume
# there, from the end of the first outer Lagrangian time to the end of
# --tl-multiple of them (default 10; the outer Lagrangian time 0.3 k/eps, its
# 90th percentile over the cells: the core flow's, not the wall cells').
#
# --wall-release K[:L]: the cells within L layers of the --walls (default 2;
# the wall cells and L - 1 layers of their point neighbours) get K times the
# parcels, each of weight 1 (nParticle), the rest of the mesh (and the inflow)
# the plain release at weight K: the weighted concentration starts uniform, and the
# thin wall bands (y+ 0-1, 1-5), which a plain release leaves with fewer than
# 5 expected parcels on a fine mesh, are judged. wellMixedCheck counts every
# parcel with its weight (its error the weighted one). K in (1, 1000], L in
# 1..20; the parcels then number up to K times more in those cells (the
# estimate before the run takes their cell share as an upper bound of their
# volume share). It pays while the light parcels stay near the walls (the mean
# flow alone, short windows); once the walk has mixed them, and in a through-flow
# (they leave before the window opens), the same parcels released uniformly do
# better (doc/reference/wellMixedCheck.md).
#
# Treatments (--models, comma-separated; default none,crw): none (the mean
# flow alone: the tracking itself must keep tracers uniform), crw
# (snowNearWall's walk, closure off: tracers must not deposit), crw-utau,
# crw-k, crw-wallcell (its wall layer's velocity scale from the wall shear, the
# k at the parcel alone, the k of the wall face's cell), stochastic
# (OpenFOAM's stochasticDispersionRAS, for comparison).
#
# --interpolation: the parcels' velocity interpolation of every cloud,
# faceFlux (default: the velocity rebuilt from the flow's face fluxes in every
# hexahedron, doc/deposition.md, "The tracking next to a wall"; it needs the
# flow's phi in the time folder) or cellPoint (OpenFOAM's).
#
# Writes into DIR, only when the run succeeds: wellmixed.csv (per treatment,
# region and band: volume share, parcel share, ratio, binomial and batch
# standard errors, verdict), wellmixed.md (the table and the verdicts),
# wellmixed.png (ratio against band per treatment with two binomial standard
# errors), and the case (case/, logs included). DIR: the scripts' folder
# rule (etc/outdir.sh): missing or empty or an earlier SnowWall output folder;
# another is refused (exit 2) unless --force; nothing in it is deleted.
# Exit status: 0 done (whatever the verdicts), 1 a run failed, 2 usage error.
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
here="$top/validation/deposition"
case_in= walls= out= time= dt= models=none,crw parcels=2000 mult=10 d=2e-7 force=0 interp=faceFlux inlet=
wr= wr_k= wr_l=2
zones=()
die2() { echo "wellmixed.sh: $*" >&2; exit 2; }
while [ $# -gt 0 ]; do
    case "$1" in
        -h|--help) awk 'NR > 1 && !/^#/ { exit } NR > 1 { sub(/^# ?/, ""); print }' "$0"; exit 0 ;;
        --case) [ -n "${2:-}" ] || die2 "--case needs a case folder"; case_in=$2; shift ;;
        --walls) [ -n "${2:-}" ] || die2 "--walls needs a patch list, e.g. \"(walls)\""; walls=$2; shift ;;
        --out) [ -n "${2:-}" ] || die2 "--out needs a folder"; out=$2; shift ;;
        --time) [ -n "${2:-}" ] || die2 "--time needs a time folder name"; time=$2; shift ;;
        --dt) [ -n "${2:-}" ] || die2 "--dt needs a time step in seconds"; dt=$2; shift ;;
        --models) [ -n "${2:-}" ] || die2 "--models needs a list"; models=$2; shift ;;
        --parcels) [ -n "${2:-}" ] || die2 "--parcels needs a number"; parcels=$2; shift ;;
        --tl-multiple) [ -n "${2:-}" ] || die2 "--tl-multiple needs a number"; mult=$2; shift ;;
        --zone) [ -n "${2:-}" ] || die2 "--zone needs NAME:X0,Y0,Z0:X1,Y1,Z1"; zones+=("$2"); shift ;;
        --d) [ -n "${2:-}" ] || die2 "--d needs a diameter in metres"; d=$2; shift ;;
        --inlet) [ -n "${2:-}" ] || die2 "--inlet needs a patch name"; inlet=$2; shift ;;
        --interpolation) [ -n "${2:-}" ] || die2 "--interpolation needs faceFlux or cellPoint"; interp=$2; shift ;;
        --wall-release) [ -n "${2:-}" ] || die2 "--wall-release needs K or K:L"; wr=$2; shift ;;
        --force) force=1 ;;
        *) die2 "unknown option '$1' (see --help)" ;;
    esac
    shift
done
[ -n "$case_in" ] || die2 "--case DIR is required (see --help)"
[ -n "$walls" ] || die2 "--walls PATCHES is required, e.g. --walls \"(walls)\""
[ -n "$dt" ] || die2 "--dt S is required (about 2 nu/u_tau^2 of the walls)"
[ -n "$out" ] || die2 "--out DIR is required"
[ -f "$case_in/constant/polyMesh/owner" ] && [ -f "$case_in/constant/polyMesh/boundary" ] \
    || die2 "--case: '$case_in' has no uncompressed mesh (constant/polyMesh/owner and boundary)"
[[ "$walls" =~ ^\(\ *[A-Za-z_][A-Za-z0-9_.:-]*(\ +[A-Za-z_][A-Za-z0-9_.:-]*)*\ *\)$ ]] \
    || die2 "--walls: '$walls' is not a list of patch names in parentheses, e.g. \"(walls)\""
walls_names=${walls#(}; walls_names=${walls_names%)}
num='^[0-9]*\.?[0-9]+([eE][-+]?[0-9]+)?$'
[[ "$dt" =~ $num ]] && awk -v x="$dt" 'BEGIN { exit !(x > 0 && x < 1) }' || die2 "--dt: '$dt' is not a step in (0, 1) s"
[[ "$parcels" =~ ^[1-9][0-9]{0,6}$ ]] || die2 "--parcels: '$parcels' is not a whole number in 1..9999999"
[[ "$mult" =~ $num ]] && awk -v x="$mult" 'BEGIN { exit !(x >= 2 && x <= 1000) }' || die2 "--tl-multiple: '$mult' is not a number in [2, 1000]"
[[ "$d" =~ $num ]] && awk -v x="$d" 'BEGIN { exit !(x > 0 && x < 1e-3) }' || die2 "--d: '$d' is not a diameter in (0, 1e-3) m"
zre='^[A-Za-z][A-Za-z0-9_]*:(-?[0-9.eE+-]+,){2}-?[0-9.eE+-]+:(-?[0-9.eE+-]+,){2}-?[0-9.eE+-]+$'
for z in "${zones[@]}"; do [[ "$z" =~ $zre ]] || die2 "--zone: '$z' is not NAME:X0,Y0,Z0:X1,Y1,Z1"; done
if [ -n "$wr" ]; then
    wr_k=${wr%%:*}
    [ "$wr_k" = "$wr" ] || wr_l=${wr#*:}
    [[ "$wr_k" =~ $num ]] && awk -v x="$wr_k" 'BEGIN { exit !(x > 1 && x <= 1000) }' \
        || die2 "--wall-release: K '$wr_k' (of '$wr') is not a factor in (1, 1000]"
    [[ "$wr_l" =~ ^[1-9][0-9]?$ ]] && [ "$wr_l" -le 20 ] \
        || die2 "--wall-release: L '$wr_l' (of '$wr') is not a number of cell layers in 1..20"
fi
# shellcheck source=../etc/outdir.sh
. "$top/etc/outdir.sh"
# shellcheck source=deposition/common.sh
. "$here/common.sh"
dep_interpolation wellmixed.sh "$interp" || exit 2
outdir_list models wellmixed.sh --models "$models" name
IFS=, read -r -a modelList <<< "$models"
dep_models wellmixed.sh "none crw crw-utau crw-k crw-wallcell stochastic" "${modelList[@]}" || exit 2
dep_require wellmixed.sh "$top" checkMesh topoSet foamDictionary || exit 1
# the flow's time
if [ -z "$time" ]; then
    for t in $(cd "$case_in" && ls -d [0-9]* 2>/dev/null | sort -g); do
        if [ -f "$case_in/$t/U" ] && [ -f "$case_in/$t/k" ] && { [ -f "$case_in/$t/omega" ] || [ -f "$case_in/$t/epsilon" ]; }; then
            time=$t; break
        fi
    done
    [ -n "$time" ] || die2 "--case: no time folder of '$case_in' holds U, k and omega or epsilon"
fi
[ -f "$case_in/$time/U" ] && [ -f "$case_in/$time/k" ] || die2 "--time: '$case_in/$time' has no U and k"
[ "$interp" = cellPoint ] || [ -f "$case_in/$time/phi" ] || die2 "--interpolation $interp: '$case_in/$time' has no phi (the flow's face fluxes)"
# the patch types of the mesh: every wall reflects, every plain patch lets out;
# constraint and coupled patches are left to the tracking
read -r -a wallPatches <<< "$(awk '/^[ \t]*[A-Za-z_][A-Za-z0-9_.:-]*[ \t]*$/ { n = $1 } /^[ \t]*type[ \t]+wall;/ { printf "%s ", n }' "$case_in/constant/polyMesh/boundary")"
read -r -a openPatches <<< "$(awk '/^[ \t]*[A-Za-z_][A-Za-z0-9_.:-]*[ \t]*$/ { n = $1 } /^[ \t]*type[ \t]+patch;/ { printf "%s ", n }' "$case_in/constant/polyMesh/boundary")"
read -r -a mirrorPatches <<< "$(awk '/^[ \t]*[A-Za-z_][A-Za-z0-9_.:-]*[ \t]*$/ { n = $1 } /^[ \t]*type[ \t]+(symmetryPlane|symmetry);/ { printf "%s ", n }' "$case_in/constant/polyMesh/boundary")"
[ "${#wallPatches[@]}" -ge 1 ] || { echo "wellmixed.sh: the mesh has no wall patch" >&2; exit 2; }
if [ -n "$inlet" ]; then
    case " ${openPatches[*]} " in *" $inlet "*) ;;
        *) echo "wellmixed.sh: --inlet: '$inlet' is not a plain patch of the mesh (plain patches: ${openPatches[*]:-none})" >&2; exit 2 ;; esac
    [ -f "$case_in/$time/phi" ] || die2 "--inlet $inlet: '$case_in/$time' has no phi (the inflow is taken from it)"
fi
for w in ${walls_names}; do
    case " ${wallPatches[*]} " in *" $w "*) ;;
        *) echo "wellmixed.sh: --walls: '$w' is not a wall patch of the mesh (walls: ${wallPatches[*]})" >&2; exit 2 ;; esac
done
outdir_begin wellmixed.sh "$out" "$force"
# shellcheck source=../etc/openfoam-env.sh
. "$top/etc/openfoam-env.sh" >/dev/null
t_start=$(date +%s)

c="$tmp/case"
mkdir -p "$c/constant" "$c/system" "$c/0"
cp -r "$case_in/constant/polyMesh" "$c/constant/"
for f in transportProperties turbulenceProperties; do cp "$case_in/constant/$f" "$c/constant/"; done
# the air's density for the parcels' drag (a steady incompressible case may not give one;
# the tracers follow the flow either way)
grep -q '^[[:space:]]*rhoInf' "$c/constant/transportProperties" || echo "rhoInf          1.2;" >> "$c/constant/transportProperties"
[ ! -d "$case_in/constant/polyMesh/sets" ] || rm -rf "$c/constant/polyMesh/sets"
for f in U p k omega epsilon nut phi; do [ ! -f "$case_in/$time/$f" ] || cp "$case_in/$time/$f" "$c/0/"; done
# p only for the solver's set-up (the flow is frozen): from 0/ or 0.orig/ when the time has none
for d0 in 0 0.orig; do [ -f "$c/0/p" ] || [ ! -f "$case_in/$d0/p" ] || cp "$case_in/$d0/p" "$c/0/"; done
cp "$case_in/system/fvSolution" "$c/system/"
[ ! -f "$case_in/system/decomposeParDict" ] || cp "$case_in/system/decomposeParDict" "$c/system/"
echo "FoamFile { version 2.0; format ascii; class uniformDimensionedVectorField; object g; }
dimensions [0 1 -2 0 0 0 0];
value (0 0 0);" > "$c/constant/g"
dep_particle_schemes "$c"
dep_control "$c" topoSet 1 1 1
# the flow's fields in ascii (the case may write binary): read below, and by the solver alike
(cd "$c" && foamFormatConvert -time 0 > log.foamFormatConvert 2>&1) \
    || { dep_show_fail wellmixed.sh "foamFormatConvert of the flow's fields" "$c/log.foamFormatConvert"; exit 1; }

# --inlet: the volume flux through every plain patch (postProcess, the flow's phi):
# the inlet's inflow Q; the patches without net flux reflect
reflectPatches=()
if [ -n "$inlet" ]; then
    escapes=() qs=()
    q_in=
    for p in "${openPatches[@]}"; do
        q=$(cd "$c" && postProcess -time 0 -func "patchIntegrate(name=$p,operation=sum,phi)" 2>&1 |
            awk '/of phi =/ { print $NF }' | tail -1)
        [ -n "$q" ] || { echo "wellmixed.sh: the flux through patch $p could not be summed (postProcess)" >&2; exit 1; }
        [ "$p" != "$inlet" ] || q_in=$(awk -v q="$q" 'BEGIN { printf "%.10g", -q }')
        qs+=("$p $q")
    done
    awk -v q="$q_in" 'BEGIN { exit !(q > 0) }' ||
        { echo "wellmixed.sh: --inlet $inlet: no inflow through it (its inflow, minus the sum of phi, is ${q_in:-?} m3/s)" >&2; exit 2; }
    for pq in "${qs[@]}"; do
        read -r p q <<< "$pq"
        if [ "$p" != "$inlet" ] && awk -v q="$q" -v qi="$q_in" 'BEGIN { exit !((q < 0 ? -q : q) <= 1e-6 * qi) }'; then
            reflectPatches+=("$p")
        else
            escapes+=("$p")
        fi
    done
    openPatches=("${escapes[@]}")
fi

# the whole mesh as one cell zone (the release), and the --zone boxes
{
    echo "FoamFile { version 2.0; format ascii; class dictionary; object topoSetDict; }"
    echo "actions ("
    echo "  { name allSet; type cellSet; action new; source boxToCell; sourceInfo { box (-1e30 -1e30 -1e30) (1e30 1e30 1e30); } }"
    echo "  { name all; type cellZoneSet; action new; source setToCellZone; sourceInfo { set allSet; } }"
    if [ -n "$wr" ]; then
        # the wall cells of --walls, grown by point neighbours to L layers; the rest
        echo "  { name wallReleaseF; type faceSet; action new; source patchToFace; sourceInfo { patches $walls; } }"
        echo "  { name wallRelease; type cellSet; action new; source faceToCell; sourceInfo { set wallReleaseF; option owner; } }"
        for ((i = 1; i < wr_l; i++)); do
            echo "  { name wallReleaseP; type pointSet; action new; source cellToPoint; sourceInfo { set wallRelease; option all; } }"
            echo "  { name wallRelease; type cellSet; action add; source pointToCell; sourceInfo { set wallReleaseP; option any; } }"
        done
        echo "  { name wallReleaseZ; type cellZoneSet; action new; source setToCellZone; sourceInfo { set wallRelease; } }"
        echo "  { name coreRelease; type cellSet; action new; source cellToCell; sourceInfo { set allSet; } }"
        echo "  { name coreRelease; type cellSet; action subtract; source cellToCell; sourceInfo { set wallRelease; } }"
        echo "  { name coreReleaseZ; type cellZoneSet; action new; source setToCellZone; sourceInfo { set coreRelease; } }"
    fi
    zl=
    for z in "${zones[@]}"; do
        IFS=: read -r zn a b <<< "$z"
        echo "  { name ${zn}Set; type cellSet; action new; source boxToCell; sourceInfo { box (${a//,/ }) (${b//,/ }); } }"
        echo "  { name $zn; type cellZoneSet; action new; source setToCellZone; sourceInfo { set ${zn}Set; } }"
        zl="$zl $zn"
    done
    echo ");"
} > "$c/system/topoSetDict"
(cd "$c" && topoSet > log.topoSet 2>&1 && checkMesh -constant > log.checkMesh 2>&1) \
    || { dep_show_fail wellmixed.sh "topoSet / checkMesh" "$c/log.topoSet"; exit 1; }
for z in "${zones[@]}"; do
    zn=${z%%:*}
    n=$(awk -v z="${zn}Set" '$0 ~ "cellSet " z { for (i = 1; i <= NF; i++) if ($i == "size") print $(i + 1) }' "$c/log.topoSet" | tail -1)
    [ "${n:-0}" -gt 0 ] 2>/dev/null || { echo "wellmixed.sh: --zone $zn: the box holds no cell" >&2; exit 2; }
done
vol=$(awk '/Total volume/ { for (i = 1; i < NF; i++) if ($i == "volume" && $(i + 1) == "=") { v = $(i + 2); sub(/\.$/, "", v); print v } }' "$c/log.checkMesh" | tail -1)
[ -n "$vol" ] || { echo "wellmixed.sh: checkMesh gave no volume ($c/log.checkMesh)" >&2; exit 1; }

# the outer Lagrangian time: 0.3 k/eps, its 90th percentile over the cells
field_values() {   # file
    foamDictionary -entry internalField -value "$1" 2>/dev/null | tr -s ' ()\n' '\n' | awk '
        /^uniform$/ { u = 1; next } /^nonuniform$|^List<scalar>$/ { next }
        u && /^[-0-9.eE+]+$/ { print; exit }
        /^[-0-9.eE+]+$/ { if (!n++) next; print }'
}
ncells=$(awk '/^ *cells:/ { print $2 }' "$c/log.checkMesh" | head -1)
unreadable() { echo "wellmixed.sh: the values of $1 cannot be read (foamDictionary; a field of the case's time $time)" >&2; exit 1; }
if [ -f "$c/0/epsilon" ]; then field_values "$c/0/epsilon" > "$tmp/eps.txt" || unreadable epsilon
else
    field_values "$c/0/k" > "$tmp/k.txt" || unreadable k
    field_values "$c/0/omega" > "$tmp/omega.txt" || unreadable omega
    paste "$tmp/k.txt" "$tmp/omega.txt" | awk '{ print 0.09 * $1 * $2 }' > "$tmp/eps.txt"
fi
field_values "$c/0/k" > "$tmp/k.txt" || unreadable k
tl=$(paste "$tmp/k.txt" "$tmp/eps.txt" | awk '$2 > 0 { print 0.3 * $1 / $2 }' | sort -g \
    | awk '{ v[NR] = $1 } END { i = int(0.9 * NR + 0.5); if (i < 1) i = 1; if (NR) printf "%.6g", v[i] }')
[ -n "$tl" ] || { echo "wellmixed.sh: no cell with k and epsilon > 0 in the flow" >&2; exit 1; }
tend=$(awk -v t="$tl" -v m="$mult" 'BEGIN { printf "%.6g", m * t }')
nsteps=$(awk -v a="$tend" -v b="$dt" 'BEGIN { printf "%d", a / b + 0.999 }')
[ "$nsteps" -le 200000 ] || { echo "wellmixed.sh: $nsteps steps of $dt s for $mult outer Lagrangian times of $tl s: more than 200 000 (raise --dt or lower --tl-multiple)" >&2; exit 2; }
tend=$(awk -v n="$nsteps" -v b="$dt" 'BEGIN { printf "%.10g", n * b }')
nd=$(awk -v n="$parcels" -v v="$vol" 'BEGIN { printf "%.10g", n / v }')
nparc=$parcels
if [ -n "$wr" ]; then
    nwr=$(awk '$0 ~ "cellSet wallRelease" { for (i = 1; i <= NF; i++) if ($i == "size") print $(i + 1) }' "$c/log.topoSet" | tail -1)
    [ "${nwr:-0}" -gt 0 ] 2>/dev/null || { echo "wellmixed.sh: --wall-release: no cell next to the walls $walls (topoSet: $c/log.topoSet)" >&2; exit 1; }
    # an upper bound: the wall cells' share of the cells for their share of the volume
    nparc=$(awk -v n="$parcels" -v k="$wr_k" -v w="$nwr" -v c="${ncells:-1}" 'BEGIN { printf "%d", n * (1 + (k - 1) * w / c) + 0.5 }')
    echo "wellmixed.sh: --wall-release $wr_k:$wr_l: $nwr of ${ncells:-?} cells within $wr_l layers of the walls get $wr_k times the parcels, the others weigh $wr_k (at most $nparc parcels a cloud)"
fi
dep_estimate wellmixed.sh "$nparc" "${#modelList[@]}" "$nsteps steps of $dt s ($mult x the outer Lagrangian time $tl s)" \
    "$(awk -v p="$nparc" -v n="${#modelList[@]}" -v c="${ncells:-0}" 'BEGIN { print p * n * 2000 + c * 3000 + 2e8 }')" \
    "$(awk -v p="$nparc" -v n="${#modelList[@]}" -v s="$nsteps" 'BEGIN { print p * n * s * 5e-6 / 60 }')" "lower --parcels" || exit 2
# (5 us a parcel step: measured on the channel, 7.4 million parcel steps in 34 s)

# the release: uniform, or (--wall-release) K times as dense next to the walls, the other
# parcels (and those entering) K times as heavy (OpenFOAM's injection drops a parcel of
# nParticle below 1, so the light ones weigh 1)
w_core=1
release_in() {   # name zone number-density nParticle
    echo "        $1
        {
            type            cellZoneInjection;
            cellZone        $2;
            numberDensity   $3;
            SOI             0;
            parcelBasisType fixed;
            nParticle       $4;
            massTotal       1;
            U0              (0 0 0);
            sizeDistribution { type fixedValue; fixedValueDistribution { value $d; } }
        }"
}
if [ -z "$wr" ]; then
    release=$(release_in uniform all "$nd" 1)
else
    w_core=$wr_k
    release="$(release_in core coreReleaseZ "$nd" "$w_core")
$(release_in wallLayers wallReleaseZ "$(awk -v n="$nd" -v k="$wr_k" 'BEGIN { printf "%.10g", n * k }')" 1)"
fi
inflow=
if [ -n "$inlet" ]; then
    rate=$(awk -v n="$nd" -v q="$q_in" 'BEGIN { printf "%.10g", n * q }')
    awk -v r="$rate" -v t="$dt" 'BEGIN { exit !(r * t >= 1) }' ||
        { echo "wellmixed.sh: --inlet $inlet: $rate tracers/s enter, under one a step of $dt s (raise --parcels)" >&2; exit 2; }
    inflow="
        inflow
        {
            type            patchInjection;
            patch           $inlet;
            SOI             0;
            duration        $tend;
            parcelsPerSecond $rate;
            flowRateProfile constant 1;
            parcelBasisType fixed;
            nParticle       $w_core;
            massTotal       1;
            U0              (0 0 0);
            sizeDistribution { type fixedValue; fixedValueDistribution { value $d; } }
        }"
    echo "wellmixed.sh: --inlet $inlet: inflow $q_in m3/s, $rate tracers/s; reflecting: ${wallPatches[*]} ${reflectPatches[*]}; out: ${openPatches[*]}"
fi
: > "$c/clouds.txt"
for m in "${modelList[@]}"; do
    name="t_${m//-/_}"
    funcs=
    case "$m" in
        none) disp=none ;;
        stochastic) disp=stochasticDispersionRAS ;;
        crw|crw-utau|crw-k|crw-wallcell)
            disp=none
            scale=max
            [ "$m" != crw-utau ] || scale=wallShear
            [ "$m" != crw-k ] || scale=turbulence
            [ "$m" != crw-wallcell ] || scale=wallCell
            funcs="nearWall { type snowNearWall; patches $walls; closure off; velocityScale $scale; }" ;;
    esac
    {
        echo "FoamFile { version 2.0; format ascii; class dictionary; object ${name}Properties; }"
        dep_cloud_solution
        cat <<EOF2
constantProperties { rho0 920; }
subModels
{
    particleForces { sphereDrag; }
    injectionModels
    {
$release$inflow
    }
    dispersionModel $disp;
    patchInteractionModel localInteraction;
    localInteractionCoeffs
    {
        patches
        (
$(for p in "${wallPatches[@]}" "${reflectPatches[@]}" "${mirrorPatches[@]}"; do echo "            $p { type rebound; e 1; mu 0; }"; done)
$(for p in "${openPatches[@]}"; do echo "            $p { type escape; }"; done)
        );
    }
    surfaceFilmModel none;
    stochasticCollisionModel none;
    collisionModel  none;
}
cloudFunctions
{
    $funcs
    wellMixed { type wellMixedCheck; patches $walls; startTime $tl; zones ($zl); }
}
EOF2
    } > "$c/constant/${name}Properties"
    echo "$name $m" >> "$c/clouds.txt"
done
dep_control "$c" pimpleUncoupledKinematicParcelFoam "$tend" "$dt" "$nsteps"
echo "wellmixed.sh: ${#modelList[@]} clouds of about $parcels tracers (d $d m), $nsteps steps of $dt s, window $tl .. $tend s"
dep_run_particles "$c" || { dep_show_fail wellmixed.sh "the tracer run" "$c/log.particles"; exit 1; }

# the tables of every cloud
csv="$tmp/wellmixed.csv"
echo "model,region,band,yplus_lo,yplus_hi,volume_share,volume_share_se,parcel_share,ratio,se_binomial,se_batch,verdict" > "$csv"
while read -r name m; do
    f=$(ls -d "$c"/postProcessing/lagrangian/"$name"/wellMixed/*/wellMixed.dat 2>/dev/null | sort -V | tail -1)
    [ -n "$f" ] || { echo "wellmixed.sh: cloud $name wrote no wellMixed.dat" >&2; exit 1; }
    awk -v m="$m" '!/^#/ && NF == 11 { printf "%s", m; for (i = 1; i <= NF; i++) printf ",%s", $i; print "" }' "$f" >> "$csv"
done < "$c/clouds.txt"
"$here/wellmixed-report" --force --title "tracer-limit check: $case_in" --out "$tmp" "$csv" || { echo "wellmixed.sh: the report failed" >&2; exit 1; }
echo "wellmixed.sh: done in $(( $(date +%s) - t_start )) s"
cat "$tmp/wellmixed.md"
outdir_commit
