#!/usr/bin/env bash
# bench/faceflux.sh - benchmark of the parcels' velocity interpolation: faceFlux
# (the velocity rebuilt from the face fluxes) against OpenFOAM's cellPoint
# (prints figures).
#
# Usage: bench/faceflux.sh [--reps N] [--parcels N] [--help]
#
# The channel's flow on its wall-function mesh (validation/deposition.sh, about
# 10 s), then, N times for each interpolation (default 3, alternating), the
# tracer run of validation/wellmixed.sh with the mean flow alone (--parcels
# tracers, default 20000, over 3 outer Lagrangian times): the solver's
# ExecutionTime over the parcel steps (parcels x steps), in microseconds per
# parcel step, the median of the N runs and the ratio of the medians.
# Not a test: nothing is asserted. Needs ./Allwmake and OpenFOAM (etc/setup.sh).
# Exit 2 on bad arguments, 1 when a run fails.
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
reps=3 parcels=20000
while [ $# -gt 0 ]; do
    case "$1" in
        -h|--help) sed -n '2,15p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
        --reps) [ -n "${2:-}" ] || { echo "bench/faceflux.sh: --reps needs a number" >&2; exit 2; }; reps=$2; shift ;;
        --parcels) [ -n "${2:-}" ] || { echo "bench/faceflux.sh: --parcels needs a number" >&2; exit 2; }; parcels=$2; shift ;;
        *) echo "bench/faceflux.sh: unknown option '$1' (see --help)" >&2; exit 2 ;;
    esac
    shift
done
[[ "$reps" =~ ^[1-9][0-9]?$ ]] || { echo "bench/faceflux.sh: --reps: '$reps' is not a whole number in 1..99" >&2; exit 2; }
[[ "$parcels" =~ ^[1-9][0-9]{2,6}$ ]] || { echo "bench/faceflux.sh: --parcels: '$parcels' is not a whole number in 100..9999999" >&2; exit 2; }
tmp=$(mktemp -d "${TMPDIR:-/tmp}/faceflux-bench.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
echo "# bench/faceflux.sh on $(uname -n), $(nproc) cores, $(date -u +%Y-%m-%dT%H:%MZ), $reps repetitions, $parcels tracers"
"$top/validation/deposition.sh" --out "$tmp/flow" --mesh wf --models none --tau-plus 10 --parcels 10 --t-run 100 \
    > "$tmp/flow.log" 2>&1 || { tail -5 "$tmp/flow.log" >&2; echo "bench/faceflux.sh: the channel's flow failed" >&2; exit 1; }
for r in $(seq "$reps"); do
    for interp in cellPoint faceFlux; do
        out="$tmp/$interp.$r"
        "$top/validation/wellmixed.sh" --case "$tmp/flow/wf/case" --walls "(walls)" --dt 5.4e-5 --models none \
            --parcels "$parcels" --tl-multiple 3 --interpolation "$interp" --out "$out" > "$out.log" 2>&1 ||
            { tail -5 "$out.log" >&2; echo "bench/faceflux.sh: the $interp run failed" >&2; exit 1; }
        awk -v i="$interp" '
            /^Time = / { steps++ }
            /Current number of parcels/ { n = $NF; sum += n }
            /^ExecutionTime/ { t = $3 }
            END { if (sum > 0) printf "%s %.6g %.0f\n", i, t / sum * 1e6, sum }' "$out/case/log.particles"
    done
done > "$tmp/runs.txt"
awk '{ v[$1, ++n[$1]] = $2; ps[$1] = $3 }
    function median(k,   m, i, j, t, a) {
        m = n[k]; for (i = 1; i <= m; i++) a[i] = v[k, i]
        for (i = 1; i <= m; i++) for (j = i + 1; j <= m; j++) if (a[j] < a[i]) { t = a[i]; a[i] = a[j]; a[j] = t }
        return (m % 2) ? a[(m + 1) / 2] : (a[m / 2] + a[m / 2 + 1]) / 2 }
    END {
        for (k in n) { med[k] = median(k); printf "%-10s %.3f us per parcel step (median of %d runs of %.3g parcel steps)\n", k, med[k], n[k], ps[k] }
        if (med["cellPoint"] > 0) printf "faceFlux / cellPoint: %.3f\n", med["faceFlux"] / med["cellPoint"] }' "$tmp/runs.txt"
