#!/usr/bin/env bash
# stock-rebuilt.sh - one of Debian's stock Lagrangian tutorials that Debian's build of its
# solver cannot run, with snowWallInteraction on its walls, on the solver rebuilt by
# etc/setup.sh --stock-solvers (doc/wallmodel.md, "Stock solvers rebuilt")
#
# Usage: validation/stock-rebuilt.sh --out DIR --case NAME --end T [--stock] [--solver S] [--help]
#
#   --case NAME  injectionChannel (MPPICFoam), cyclone (MPPICFoam) or verticalChannel
#                (reactingParcelFoam), copied from the openfoam-examples package
#   --end T      endTime T [s], one write at T
#   --stock      keep the case's own patch interaction model (no snow lines)
#   --solver S   the solver to run (default: the case's solver found on PATH after
#                etc/openfoam-env.sh, i.e. platforms/bin's rebuilt one when there;
#                /usr/bin/MPPICFoam runs Debian's build)
#
# The case is made as its Allrun makes it (blockMesh; snappyHexMesh for cyclone, run
# serial; potentialFoam for verticalChannel), changed only as the tests change the stock
# cases (tests/openfoam/stock.sh): the documented lines of doc/wallmodel.md with the
# fixture regime (walls a snow patch, every other patch OpenFOAM's own), endTime,
# writePrecision 12 and a patchPostProcessing record of every hit on `walls`. It runs in
# DIR (created; kept) and prints the steps, the largest Courant number, the execution and
# wall times, the parcels, the impacts / sticks / bounces / rip-offs and wall hits on
# `walls` and the cloud's mass balance.
# Exit status: 0 the run ended, 1 it failed (its exit status and the log's tail are
# printed), 2 usage error.
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
out='' name='' end='' stock=0 solver=''
usage() { echo "stock-rebuilt.sh: $1 (see --help)" >&2; exit 2; }
while [ $# -gt 0 ]; do
    case "$1" in
        -h|--help) awk 'NR > 1 && !/^#/ { exit } NR > 1 { sub(/^# ?/, ""); print }' "$0"; exit 0 ;;
        --out) [ -n "${2:-}" ] || usage "--out needs a folder"; out=$2; shift ;;
        --case) [ -n "${2:-}" ] || usage "--case needs a name"; name=$2; shift ;;
        --end) [ -n "${2:-}" ] || usage "--end needs a time"; end=$2; shift ;;
        --solver) [ -n "${2:-}" ] || usage "--solver needs a program"; solver=$2; shift ;;
        --stock) stock=1 ;;
        *) usage "unknown option '$1'" ;;
    esac
    shift
done
[ -n "$out" ] || usage "--out DIR is required"
[ -n "$end" ] || usage "--end T is required"
awk -v t="$end" 'BEGIN { exit !(t + 0 > 0) }' || usage "--end '$end' is not a positive time"
case "$name" in
    injectionChannel|cyclone) tut=lagrangian/MPPICFoam/$name cloud=kinematicCloud app=MPPICFoam ;;
    verticalChannel) tut=lagrangian/reactingParcelFoam/$name cloud=reactingCloud1 app=reactingParcelFoam ;;
    '') usage "--case NAME is required (injectionChannel, cyclone, verticalChannel)" ;;
    *) usage "unknown case '$name' (injectionChannel, cyclone, verticalChannel)" ;;
esac
[ ! -e "$out" ] && [ ! -L "$out" ] || usage "$out exists: give a new folder"

export SW_TOP="$top"
# the tests' helpers (stock_copy, shorten, dropin, count_hits, hits, snow_counts, balance);
# common.sh makes a temp folder this script does not use
# shellcheck source=../tests/openfoam/common.sh
. "$top/tests/openfoam/common.sh"
# shellcheck source=../tests/openfoam/stock.sh
. "$top/tests/openfoam/stock.sh"
trap - EXIT
rm -rf "$tmp"
: "${solver:=$(command -v "$app" || true)}"
[ -n "$solver" ] && [ -x "$solver" ] || { echo "stock-rebuilt.sh: no $app to run" >&2; exit 1; }

mkdir -p "$(dirname "$out")"
stock_copy "$tut" "$out"
case "$name" in
    injectionChannel) (cd "$out" && run log.blockMesh blockMesh) ;;
    cyclone) cp "$examples/resources/geometry/cyclone.stl.gz" "$out/constant/triSurface/"
             (cd "$out" && run log.blockMesh blockMesh && run log.snappyHexMesh snappyHexMesh -overwrite) ;;
    verticalChannel) (cd "$out" && run log.blockMesh blockMesh && cp -r 0.orig 0 \
                      && run log.potentialFoam potentialFoam) ;;
esac
shorten "$out" "$end"
props="$out/constant/${cloud}Properties"
count_hits "$props" "(walls)"
if [ "$stock" = 0 ]; then
    dropin "$out" "${cloud}Properties" 'walls { type snow; }' '".*" { type none; }'
fi

echo "stock-rebuilt.sh: $name to $end s with $solver ($([ "$stock" = 1 ] && echo "its own patch interaction model" || echo "snowWallInteraction on walls")) in $out"
rc=0
t0=$(date +%s.%N)
(cd "$out" && "$solver" > log.run 2>&1) || rc=$?
t1=$(date +%s.%N)
log="$out/log.run"
echo "steps: $(grep -c '^Time = ' "$log" || true) (last $(grep '^Time = ' "$log" | tail -n 1 | cut -d' ' -f3))"
echo "largest Courant number: $(awk '/^Courant Number/ { if ($NF > m) m = $NF } END { print m + 0 }' "$log")"
echo "time: $(grep '^ExecutionTime' "$log" | tail -n 1), wall $(awk -v a="$t0" -v b="$t1" 'BEGIN { printf "%.0f", b - a }') s"
if [ "$rc" != 0 ]; then
    tail -n 15 "$log"
    echo "stock-rebuilt.sh: $solver ended with exit status $rc" >&2
    exit 1
fi
echo "parcels at the end: $(grep 'Current number of parcels' "$log" | tail -n 1 | awk '{ print $NF }')"
if [ "$stock" = 0 ]; then
    echo "walls: impacts sticks bounces ripoffs $(snow_counts "$log" walls)"
    grep "snowWall: patch walls: impacts" "$log" | tail -n 1 | sed 's/^ *//'
fi
echo "walls: hits recorded $(hits "$out" "$cloud" walls)"
echo "mass balance (injected airborne escaped deposited transferred relErr) [kg]: $(balance "$log" "$cloud")"
