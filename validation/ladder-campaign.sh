#!/usr/bin/env bash
# ladder-campaign.sh - the wedge's resolution ladder as one campaign that survives the
# end of a sitting: every rung in its own copy of tutorials/wedge, started, resumed or
# skipped, one after the other, then gathered by post/wedge-ladder.
#
# Usage: validation/ladder-campaign.sh [--help] --dir DIR [--levels LIST] [--parcels K]
#                                      [--parallel N] [--status]
#
#   --dir DIR       the campaign's folder (created): DIR/level<N>/ per rung, DIR/ladder/
#                   the gathered ladder once every rung is done
#   --levels LIST   the rungs, comma-separated whole numbers -3..3 (default -1,0,1,2)
#   --parcels K     Allrun -parcels K for every rung (default 1): the size classes'
#                   parcels K times, a rung's sampling error 1/sqrt(K) times
#   --parallel N    Allrun -parallel N for every rung (default 1)
#   --status        print each rung's state and stop
#
# Per rung, in the order of LIST: a folder without a run is made (the case's files as
# git tracks them) and `Allrun -level N -parcels K -parallel N` started; a run whose
# log ends with Allrun's "done" is skipped; any other (interrupted, killed, the machine
# switched off) goes on with `Allrun -resume`, with the options it was started with.
# Allrun's output is appended to DIR/level<N>/run.log. A rung that fails stops the
# campaign (its message and exit status); run the same command again to go on. When
# every rung is done, post/wedge-ladder gathers them into DIR/ladder/ (ladder.csv,
# ladder.md, total_error.*), which constant/ladder-rear-layers.csv is made from.
# A second campaign in the same folder while one runs is refused by the rungs' own
# lock (etc/caselock.sh). Exit 0 when every rung is done and gathered, 2 on bad usage,
# else the failing step's status.
set -euo pipefail
usage() { sed -n '2,/^set -euo/p' "$0" | sed '$d; s/^# \{0,1\}//'; }
die() { echo "ladder-campaign: $1" >&2; exit "${2:-2}"; }
top=$(cd "$(dirname "$0")/.." && pwd)
dir= levels=-1,0,1,2 parcels=1 np=1 status=0
while [ $# -gt 0 ]; do
    case "$1" in
        -h|--help) usage; exit 0 ;;
        --dir) [ -n "${2:-}" ] || die "--dir needs a folder"; dir=$2; shift ;;
        --levels) [[ ${2:-} =~ ^-?[0-3](,-?[0-3])*$ ]] || die "--levels needs whole numbers -3..3, comma-separated, got '${2:-}'"; levels=$2; shift ;;
        --parcels) [[ ${2:-} =~ ^[1-9][0-9]?$ ]] || die "--parcels needs a whole factor 1..99, got '${2:-}'"; parcels=$2; shift ;;
        --parallel) [[ ${2:-} =~ ^[1-9][0-9]{0,5}$ ]] || die "--parallel needs a whole number of processes, got '${2:-}'"; np=$2; shift ;;
        --status) status=1 ;;
        *) die "unknown option '$1' (see --help)" ;;
    esac
    shift
done
[ -n "$dir" ] || die "--dir DIR is required (see --help)"
[ ! -e "$dir" ] || [ -d "$dir" ] || die "--dir: '$dir' exists and is not a folder"
state() {  # state FOLDER: new, done, or interrupted
    if [ ! -f "$1/log.Allrun.args" ]; then echo new
    elif [ -f "$1/run.log" ] && tail -n 1 "$1/run.log" | grep -q ': done (transient route)'; then echo done
    else echo interrupted; fi
}
IFS=, read -r -a lv <<< "$levels"
for n in "${lv[@]}"; do
    d=$dir/level$n
    echo "ladder-campaign: level $n: $(state "$d") ($d)"
done
[ "$status" = 0 ] || exit 0
mkdir -p "$dir"
for n in "${lv[@]}"; do
    d=$dir/level$n
    case "$(state "$d")" in
        done) continue ;;
        new)
            mkdir -p "$d"
            (cd "$top/tutorials/wedge" && git ls-files . | tar cf - -T -) | tar xf - -C "$d"
            echo "ladder-campaign: level $n: Allrun -level $n -parcels $parcels -parallel $np"
            (cd "$d" && SNOWWALL_TOP=$top ./Allrun -level "$n" -parcels "$parcels" -parallel "$np" >> run.log 2>&1) ||
                { rc=$?; tail -n 3 "$d/run.log" >&2; die "level $n failed (exit $rc): $d/run.log" "$rc"; } ;;
        interrupted)
            echo "ladder-campaign: level $n: Allrun -resume"
            (cd "$d" && SNOWWALL_TOP=$top ./Allrun -resume >> run.log 2>&1) ||
                { rc=$?; tail -n 3 "$d/run.log" >&2; die "level $n failed (exit $rc): $d/run.log" "$rc"; } ;;
    esac
done
runs=(); for n in "${lv[@]}"; do runs+=(--run "$dir/level$n"); done
SNOWWALL_TOP=$top "$top/tutorials/wedge/post/wedge-ladder" "${runs[@]}" --out "$dir/ladder"
echo "ladder-campaign: every rung done: $dir/ladder/"
