#!/usr/bin/env bash
# test_ladder_campaign.sh - validation/ladder-campaign.sh without running a rung: the
# state of each rung (new, interrupted, done) as --status reads it, and its refusals.
. "$(dirname "$0")/common.sh"
C="$top/validation/ladder-campaign.sh"
d="$tmp/camp"
mkdir -p "$d/level-1" "$d/level0"
echo "-level" > "$d/level-1/log.Allrun.args"
printf 'Allrun [9 s]: x\nAllrun [10 s]: done (transient route). Results in x\n' > "$d/level-1/run.log"
echo "-level" > "$d/level0/log.Allrun.args"
printf 'Allrun [9 s]: solver at t = 0.1 of 0.8 s\n' > "$d/level0/run.log"
"$C" --dir "$d" --levels -1,0,1 --status > "$tmp/o" 2> "$tmp/e"
check "status: exit 0, three lines" "[ \$? = 0 ] && [ \$(wc -l < '$tmp/o') = 3 ]"
check "status: level -1 done, level 0 interrupted, level 1 new" \
    "grep -q '^ladder-campaign: level -1: done ' '$tmp/o' && grep -q '^ladder-campaign: level 0: interrupted ' '$tmp/o' && grep -q '^ladder-campaign: level 1: new ' '$tmp/o'"
check "status: nothing made" "[ ! -e '$d/level1' ]"
bad() {  # bad TEXT ARGS...: exit 2 naming it, nothing made
    local want=$1; shift
    "$C" "$@" > /dev/null 2> "$tmp/e"; local rc=$?
    check "refused: $want" "[ $rc = 2 ] && grep -qF -- \"$want\" '$tmp/e'"
}
bad "--dir DIR is required" --levels 0
bad "--levels needs whole numbers -3..3, comma-separated, got '4'" --dir "$d" --levels 4
bad "--levels needs whole numbers -3..3, comma-separated, got '0,,1'" --dir "$d" --levels 0,,1
bad "--parcels needs a whole factor 1..99, got '0'" --dir "$d" --parcels 0
bad "--parallel needs a whole number of processes, got 'x'" --dir "$d" --parallel x
bad "unknown option '--bogus'" --dir "$d" --bogus
touch "$tmp/file"
bad "--dir: '$tmp/file' exists and is not a folder" --dir "$tmp/file"
finish
