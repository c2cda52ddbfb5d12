#!/usr/bin/env bash
# bench/nearwall.sh - benchmark of the near-wall walk (prints figures).
#
# Usage: bench/nearwall.sh [--reps N] [--build DIR] [--help]
#
# Runs swd_bench of the release build (./Allwmake: build/release; --build DIR:
# another CMake release build folder, e.g. one of an older commit, to compare):
# the nanoseconds per swd_advance call, the step every host makes per parcel and
# tracking step, at six places (the viscous sublayer and the bulk with k uniform
# and with a gradient of k, the buffer layer and the blend with a gradient),
# each the median of N repetitions (default 9) of 2 million calls, and their
# ratio to a whole OpenFOAM parcel step of 5 us (measured: validation/wellmixed.sh
# on the channel, 7.4 million parcel steps in 34 s).
# Not a test: nothing is asserted. Exit 2 on bad arguments, 1 without the build.
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
reps=9
build=$top/build/release
while [ $# -gt 0 ]; do
    case "$1" in
        -h|--help) sed -n '2,14p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
        --reps) [ -n "${2:-}" ] || { echo "bench/nearwall.sh: --reps needs a number" >&2; exit 2; }; reps=$2; shift ;;
        --build) [ -n "${2:-}" ] || { echo "bench/nearwall.sh: --build needs a folder" >&2; exit 2; }; build=$2; shift ;;
        *) echo "bench/nearwall.sh: unknown option '$1' (see --help)" >&2; exit 2 ;;
    esac
    shift
done
[[ "$reps" =~ ^[1-9][0-9]{0,2}$ ]] && [ "$reps" -le 1000 ] || { echo "bench/nearwall.sh: --reps: '$reps' is not a whole number in 1..1000" >&2; exit 2; }
bench=$build/bench/wallmodel/swd_bench
[ -x "$bench" ] || { echo "bench/nearwall.sh: $bench missing: run ./Allwmake first" >&2; exit 1; }
echo "# bench/nearwall.sh on $(uname -n), $(nproc) cores, $(date -u +%Y-%m-%dT%H:%MZ), $reps repetitions"
"$bench" "$reps" | awk '/^#/ { print; next } { ns = $(NF - 1); printf "%s   (%.1f %% of a 5 us parcel step)\n", $0, ns / 50 }'
