#!/usr/bin/env bash
# test_wedge_options.sh - tutorials/wedge/Allrun refuses bad options with exit 2 and
# one message naming the option, the value and the accepted range, before it writes
# anything (once, -parallel 999 decomposed the case into some 18 000 files
# before mpirun refused); so do the post-processing scripts (post/wedge-*) for a
# missing option value or a malformed --window. Runs in a temporary copy of the case's
# source files; the option refusals need bin/snowwedge (allrun-options), not OpenFOAM
# (they come first). With OpenFOAM and the build also Allrun's one-line estimate (-estimate) and
# its refusals of a replay interval below maxDeltaT and of a replay library above the
# available memory. About 1 s, with the estimate checks about 30 s.
set -u
top=${SW_TOP:?SW_TOP not set}
export SNOWWALL_TOP="$top"   # Allrun and the post/ scripts run from a copy of the case
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }
w="$tmp/wedge"
mkdir -p "$w"
if git -C "$top" rev-parse >/dev/null 2>&1; then
    (cd "$top/tutorials/wedge" && git ls-files -co --exclude-standard . | tar cf - -T -) | (cd "$w" && tar xf -)
else
    (cd "$top/tutorials/wedge" && tar cf - --exclude=results .) | (cd "$w" && tar xf -)
fi
[ -x "$w/Allrun" ] || fail "no Allrun in the copy"
listing() { (cd "$w" && find . | sort); }
listing > "$tmp/before"
ncpu=$(nproc 2>/dev/null || echo 1)

refused() {  # refused PATTERN ARGS...: exit 2, PATTERN in the message, nothing written
    local want=$1; shift
    SNOWWALL_TOP="$top" "$w/Allrun" "$@" > "$tmp/out" 2> "$tmp/err"; local rc=$?
    [ "$rc" = 2 ] || fail "Allrun $*: exit $rc, want 2 ($(cat "$tmp/err"))"
    grep -qF -- "$want" "$tmp/err" || fail "Allrun $*: the message does not say '$want': $(cat "$tmp/err")"
    listing | diff -q "$tmp/before" - > /dev/null || fail "Allrun $*: wrote or removed files: $(listing | diff "$tmp/before" - | head -5)"
    echo "ok   Allrun $*: $(head -1 "$tmp/err")"
}
# -checkpoint: minutes, a positive number or off
for v in 0 -5 abc 1e7 ''; do refused "-checkpoint needs a positive number of minutes (at most 1e6) or off, got '$v'" -checkpoint "$v"; done
refused "-checkpoint needs the transient route (not -steady)" -steady -checkpoint 5
# -resume: only alone, and only where a run wrote its options; not the steady route
refused "-resume: no run to resume in" -resume
refused "-resume takes no other option" -resume -test
refused "-resume is the only option of its command line" -test -resume
printf '%s\n' -steady -test > "$w/log.Allrun.args"; listing > "$tmp/before"
refused "-resume: the steady route is not resumed" -resume
rm -f "$w/log.Allrun.args"; listing > "$tmp/before"
refused "-parallel 999: this machine has $ncpu processors (nproc); accepted: 1 to $ncpu (up to $((4 * ncpu)) with -oversubscribe)" -parallel 999
refused "-parallel $((ncpu + 1)): this machine has $ncpu processors" -test -parallel $((ncpu + 1))
refused "-parallel $((4 * ncpu + 1)): accepted with -oversubscribe: 1 to $((4 * ncpu))" -parallel $((4 * ncpu + 1)) -oversubscribe
refused "-parallel needs a whole number of processes from 1 (without leading zeros), got '0'" -parallel 0
refused "got '007'" -parallel 007
refused "got '99999999999999999999'" -parallel 99999999999999999999
refused "got '-2'" -parallel -2
refused "got ''" -parallel
refused "-rebound needs the transient route" -steady -rebound
refused "-replay needs the transient route" -steady -replay
refused "-wake-source needs the transient route" -steady -wake-source
refused "-wake-source releases the size classes in the wake: not with -sizes none" -wake-source -sizes none
refused "Allrun: -sizes: 'nothing' in 'nothing' is not a number" -sizes nothing
refused "-sizes needs whole diameters in um (1..1000), comma-separated, or none, got '5.5'" -sizes 5.5
refused "-oversubscribe needs -parallel N with N > 1" -oversubscribe
refused "-gate must be off, tangential, shear or regime, got 'on'" -gate on
refused "-ladder needs a file (a ladder.csv of post/wedge-ladder) or none" -ladder
refused "-ladder $tmp/no-such.csv: not a readable file" -ladder "$tmp/no-such.csv"
refused "-ladder $tmp: not a readable file" -ladder "$tmp"
# a malformed ladder is refused before the run, not after it
printf '# a comment\nquantity,run,level,cells,value,se,t_flow,t_clouds\n' > "$tmp/l1.csv"
refused "-ladder $tmp/l1.csv: line 2: not the header of post/wedge-ladder" -ladder "$tmp/l1.csv"
printf 'quantity,run,design,level,cells,step,value,se,t_flow,t_clouds\nCd,a,default,0,100,1e-3,0.4,0.01,1\n' > "$tmp/l2.csv"
refused "-ladder $tmp/l2.csv: line 2: not a row of ten fields" -ladder "$tmp/l2.csv"
printf 'quantity,run,design,level,cells,step,value,se,t_flow,t_clouds\nCd,a,default,zero,100,1e-3,0.4,0.01,1,1\n' > "$tmp/l3.csv"
refused "-ladder $tmp/l3.csv: line 2: not a row of ten fields with a whole level" -ladder "$tmp/l3.csv"
printf '# only comments\nquantity,run,design,level,cells,step,value,se,t_flow,t_clouds\n' > "$tmp/l4.csv"
refused "-ladder $tmp/l4.csv: no row" -ladder "$tmp/l4.csv"
# list options (etc/outdir.sh's outdir_list): an empty item or a name twice refused,
# named with the text; an unsorted -sizes taken in ascending order with a note (seen
# before a later refusal)
refused "Allrun: -sizes: an empty item in '5,,10'" -sizes 5,,10
refused "Allrun: -sizes: an empty item in '5,10,'" -sizes 5,10,
refused "Allrun: -sizes: an empty item in ',5'" -sizes ,5
refused "Allrun: -sizes: an empty list" -sizes ''
refused "Allrun: -dispersion: an empty item in 'nearwall,,crw'" -dispersion nearwall,,crw
refused "Allrun: -dispersion: an empty item in 'crw,'" -dispersion crw,
refused "Allrun: -dispersion: 'crw' is given twice in 'crw,nearwall,crw'" -dispersion crw,nearwall,crw
refused "Allrun: -dispersion needs a comma-separated list of nearwall, nearwall-utau, nearwall-k, crw, stochastic, gradient, none; got 'nearwall,nearwall-tau'" -dispersion nearwall,nearwall-tau
refused "Allrun: -sizes: '20' is given twice in '20,5,20'" -sizes 20,5,20
refused "-sizes needs the transient route" -steady -sizes 20,5,10
grep -qxF "Allrun: note: -sizes: '20,5,10' taken in ascending order" "$tmp/err" ||
    fail "Allrun -sizes 20,5,10: no note of the ascending order: $(cat "$tmp/err")"
[ "$(grep -c . "$tmp/err")" = 2 ] || fail "Allrun -sizes 20,5,10: more than the note and the refusal: $(cat "$tmp/err")"
refused "-sizes needs the transient route" -steady -sizes 5,10,20
! grep -q "note:" "$tmp/err" || fail "Allrun -sizes 5,10,20: a note for a sorted list: $(cat "$tmp/err")"
refused "unknown option '-parallell'" -parallell 2
# found by a hostile sweep: two mesh levels or a diameter twice were taken without a word
refused "-test with -fine: give one mesh level (-fine or -test)" -fine -test
refused "-sizes: '05' is given twice in '5,10,05'" -sizes 5,10,05
# the post-processing scripts: a missing option value or a malformed --window is a
# usage error, exit 2, named (once '--gate' alone exited 1 from the shell's own
# ${2:?}, and '--window 1e-,2,3' passed as 1,2,3)
post_refused() {  # post_refused PATTERN SCRIPT ARGS...
    local want=$1 script=$2; shift 2
    "$w/post/$script" "$@" > "$tmp/out" 2> "$tmp/err"; local rc=$?
    [ "$rc" = 2 ] || fail "$script $*: exit $rc, want 2 ($(cat "$tmp/err"))"
    grep -qF -- "$want" "$tmp/err" || fail "$script $*: the message does not say '$want': $(cat "$tmp/err")"
    listing | diff -q "$tmp/before" - > /dev/null || fail "$script $*: wrote or removed files in the case"
    [ ! -e "$tmp/post-out" ] || fail "$script $*: created its --out folder"
    echo "ok   $script $*: $(head -1 "$tmp/err")"
}
post_refused "wedge-post: --gate needs a name" wedge-post --case "$w" --out "$tmp/post-out" --gate
post_refused "wedge-post: --window '1e-,2,3' is not T0,TH,T1" wedge-post --case "$w" --out "$tmp/post-out" --window 1e-,2,3
post_refused "wedge-post: --window '0,2,1' is not T0,TH,T1 with 0 <= T0 < TH < T1" wedge-post --case "$w" --out "$tmp/post-out" --window 0,2,1
# a post-processing run that fails on its input leaves --out as it was: not
# created when it did not exist, untouched when it did
"$w/post/wedge-post" --case "$w" --out "$tmp/post-out/deep" > "$tmp/out" 2> "$tmp/err"; rc=$?
[ "$rc" = 1 ] || fail "wedge-post on a case without results: exit $rc, want 1"
grep -q "wedge-post: missing" "$tmp/err" || fail "wedge-post without results: $(cat "$tmp/err")"
[ ! -e "$tmp/post-out" ] || fail "a failed wedge-post left the folders it created: $(find "$tmp/post-out" | head -3)"
mkdir -p "$tmp/kept" && echo old > "$tmp/kept/rear_deposit.csv"
"$w/post/wedge-post" --case "$w" --out "$tmp/kept" > /dev/null 2>&1 && fail "wedge-post without results succeeded"
[ "$(ls -A "$tmp/kept")" = rear_deposit.csv ] && [ "$(cat "$tmp/kept/rear_deposit.csv")" = old ] \
    || fail "a failed wedge-post changed an existing --out: $(ls -A "$tmp/kept")"
echo "ok   wedge-post failing on its input leaves --out as it was"
post_refused "wedge-capture: --gate needs a name" wedge-capture --results "$tmp/post-out" --gate
post_refused "wedge-variant: --log needs a file" wedge-variant --variant rough --log
post_refused "wedge-compare: --rel needs a number" wedge-compare --rel
post_refused "wedge-panels: --title needs a text" wedge-panels --title
# a results folder without the results: exit 1 with a message (found by a hostile sweep:
# an empty 'ls | sort' under pipefail ended wedge-capture and -compose with exit 2 and
# wedge-dispersion with exit 1, without a word)
post_missing() {  # post_missing PATTERN SCRIPT ARGS...
    local want=$1 script=$2; shift 2
    "$w/post/$script" "$@" > "$tmp/out" 2> "$tmp/err"; local rc=$?
    [ "$rc" = 1 ] || fail "$script $*: exit $rc, want 1 ($(cat "$tmp/err"))"
    grep -qF -- "$want" "$tmp/err" || fail "$script $*: the message does not say '$want': $(cat "$tmp/err")"
    echo "ok   $script $*: $(head -1 "$tmp/err")"
}
mkdir -p "$tmp/noresults"
post_missing "wedge-capture: no $tmp/noresults/d<N>um results" wedge-capture --results "$tmp/noresults"
post_missing "wedge-compose: no $tmp/noresults/d<N>um results" wedge-compose --results "$tmp/noresults" --out "$tmp/compose-out" --mvd 30
post_missing "wedge-dispersion: no main deposit_per_patch.csv in $tmp/noresults" wedge-dispersion --results "$tmp/noresults" --main nearwall --others crw
[ ! -e "$tmp/compose-out" ] || fail "wedge-compose without results created --out"
# mpirun is asked before anything is written: a (fake) mpirun that cannot start the
# processes stops Allrun with its message
if [ "$ncpu" -ge 2 ]; then
    mkdir -p "$tmp/fakebin"
    printf '#!/bin/sh\necho "There are not enough slots available in the system"\nexit 1\n' > "$tmp/fakebin/mpirun"
    chmod +x "$tmp/fakebin/mpirun"
    PATH="$tmp/fakebin:$PATH" refused "-parallel 2: mpirun cannot start 2 processes here" -parallel 2
    grep -q "not enough slots" "$tmp/err" || fail "mpirun's own message not passed on: $(cat "$tmp/err")"
fi
# the estimate of the chosen options (needs OpenFOAM and the build: Allrun checks
# them first): one line before anything is written; -estimate stops there; a
# replayInterval shorter than maxDeltaT and a replay library above the available
# memory are refused (exit 2) before anything is written
if [ -x /usr/bin/simpleFoam ] && [ -x "$top/bin/snowregime" ] && [ -x "$top/bin/snowphoto" ] &&
   [ -f "$top/platforms/lib/libsnowWallInteraction.so" ]; then
    estimate() {  # estimate ARGS...: exit 0, one estimate line, nothing written
        "$w/Allrun" -estimate "$@" > "$tmp/out" 2> "$tmp/err" || fail "Allrun -estimate $*: exit $? ($(cat "$tmp/err"))"
        [ "$(grep -c '^Allrun: estimate: ' "$tmp/out")" = 1 ] || fail "Allrun -estimate $*: not one estimate line: $(cat "$tmp/out")"
        listing | diff -q "$tmp/before" - > /dev/null || fail "Allrun -estimate $*: wrote or removed files"
        echo "ok   Allrun -estimate $*: $(cut -c1-110 "$tmp/out")..."
    }
    estimate
    # the coarse mesh's 100 568 cells with five splits of the 20 x 20 cells on the
    # rear face (the default -rear-layers): 102 568 (checkMesh's count, doc/wedge.md);
    # the spray and the five classes
    grep -q '^Allrun: estimate: 102568 cells, 6 clouds, ' "$tmp/out" || fail "Allrun -estimate: $(cat "$tmp/out")"
    flow1=$(sed 's/.*(flow \([0-9.e+-]*\),.*/\1/' "$tmp/out")
    steps=$(sed 's/.*about \([0-9]*\) time steps.*/\1/' "$tmp/out")
    estimate -halfstep
    steps2=$(sed 's/.*about \([0-9]*\) time steps.*/\1/' "$tmp/out")
    [ "$steps2" = $((2 * steps)) ] || fail "Allrun -estimate -halfstep: $steps2 steps, want 2 x $steps"
    # -refine-wake: 138 671 cells (25 x 25 on the rear face) + 5 x 625
    estimate -refine-wake
    grep -q '^Allrun: estimate: 141796 cells' "$tmp/out" || fail "Allrun -estimate -refine-wake: $(cat "$tmp/out")"
    # the rear face on its wall function: the block mesh's 100 568 cells, the flow
    # 1/1.64 as long (the cells' ratio aside)
    estimate -no-rear-layers
    grep -q '^Allrun: estimate: 100568 cells' "$tmp/out" || fail "Allrun -estimate -no-rear-layers: $(cat "$tmp/out")"
    flow0=$(sed 's/.*(flow \([0-9.e+-]*\),.*/\1/' "$tmp/out")
    awk -v a="$flow1" -v b="$flow0" 'BEGIN { r = a / b / (102568 / 100568); exit !(r > 1.5 && r < 1.8) }' ||
        fail "Allrun -estimate: the flow $flow1 min with the rear layers, $flow0 min without (want about 1.64 x per cell)"
    estimate -rear-layers
    grep -q '^Allrun: estimate: 102568 cells' "$tmp/out" || fail "Allrun -estimate -rear-layers: $(cat "$tmp/out")"
    refused "-rear-layers needs the transient route" -steady -rear-layers
    # a ladder whose numbers snowladder refuses (nan, one level only): refused before the run
    { echo 'quantity,run,design,level,cells,step,value,se,t_flow,t_clouds'
      echo 'Cd,a,default,0,100,1e-3,nan,0.01,1,1'; echo 'Cd,b,default,1,200,1e-3,0.4,0.01,1,1'; } > "$tmp/l5.csv"
    refused "-ladder $tmp/l5.csv: snowladder cannot judge against it" -estimate -ladder "$tmp/l5.csv"
    grep -q "value 'nan' is not a finite decimal number" "$tmp/err" || fail "the nan ladder: $(cat "$tmp/err")"
    { echo 'quantity,run,design,level,cells,step,value,se,t_flow,t_clouds'; echo 'Cd,a,default,0,100,1e-3,0.4,0.01,1,1'; } > "$tmp/l6.csv"
    refused "-ladder $tmp/l6.csv: snowladder cannot judge against it" -estimate -ladder "$tmp/l6.csv"
    grep -q "has 1 level (need at least 2)" "$tmp/err" || fail "the one-level ladder: $(cat "$tmp/err")"
    estimate -ladder none
    estimate -checkpoint 0.5
    # the steady route: its own line (the block mesh, no rear layers; one run per gate with -compare)
    estimate -steady
    grep -q '^Allrun: estimate: 100568 cells, 1 cloud(s), 100000 parcels injected each (steady route' "$tmp/out" || fail "Allrun -estimate -steady: $(cat "$tmp/out")"
    estimate -steady -compare
    grep -q ' 4 cloud(s), ' "$tmp/out" || fail "Allrun -estimate -steady -compare: $(cat "$tmp/out")"
    estimate -checkpoint off
    # the wall layer's velocity scales as further treatments: per treatment one cloud
    # of the spray and one per class (6 + 2 x 6 clouds)
    estimate -dispersion nearwall,nearwall-utau,nearwall-k
    grep -q '^Allrun: estimate: 102568 cells, 18 clouds, ' "$tmp/out" || fail "Allrun -estimate -dispersion nearwall,nearwall-utau,nearwall-k: $(cat "$tmp/out")"
    # -resume where a run wrote its options (here none: the default) but no mesh:
    # refused before anything is written
    : > "$w/log.Allrun.args"; listing > "$tmp/before"
    refused "-resume: the run's mesh (constant/polyMesh, log.checkMesh) is gone: nothing to resume" -resume
    rm -f "$w/log.Allrun.args"; listing > "$tmp/before"
    estimate -test -sizes 10,5,20 -compare -rebound    # 1 + 3 + 1 + 3 clouds
    grep -q ' 8 clouds, ' "$tmp/out" || fail "Allrun -estimate -test -sizes 10,5,20 -compare -rebound: $(cat "$tmp/out")"
    sp="$w/constant/sprayProperties"
    cp "$sp" "$tmp/sprayProperties"
    sed -i 's/^\( *replayInterval *\)[^;]*;/\11e-6;/' "$sp"
    refused "replayInterval 1e-06 s is shorter than the run's maxDeltaT 1e-3 s" -test
    cp "$tmp/sprayProperties" "$sp"
    sed -i 's/^\( *replayInterval *\)[^;]*;/\15e-4;/' "$sp"
    estimate -halfstep                     # 5e-4 = the -halfstep maxDeltaT: accepted
    refused "replayInterval 0.0005 s is shorter than the run's maxDeltaT 1e-3 s" -estimate
    cp "$tmp/sprayProperties" "$sp"
    sed -i 's/^\( *replayPeriod *\)[^;]*;/\1100;/' "$sp"     # 100 000 snapshots of 102 568 cells
    # too large for the memory: streamed from disk, and refused for the disk it needs
    refused "the fields written and the stored flow library need about" -estimate
    grep -q "903 GB, more than the .* GB free in the case folder" "$tmp/err" || fail "the disk refusal: $(cat "$tmp/err")"
    cp "$tmp/sprayProperties" "$sp"
    # one run at a time (etc/caselock.sh): while another process holds the folder's lock
    # (flock on Allrun, as a running Allrun does, with its Allrun.owner), Allrun, -resume and
    # Allclean are refused naming it, nothing written or removed, and -estimate still answers;
    # once the holder has ended, the lock is free: Allclean passes and removes the owner file
    printf 'pid 4242\nhost h\nstarted 2026-12-07 10:00:00 +0000\noptions -test\n' > "$w/Allrun.owner"
    listing > "$tmp/before"
    (cd "$w" && exec flock -o Allrun sleep 30) & holder=$!
    for ((k = 0; k < 50; k++)); do (cd "$w" && ! flock -n Allrun true) && break; sleep 0.1; done
    export SNOWWALL_LOCK_WAIT=0
    refused "another run is writing this folder ($w): pid 4242 on h, started 2026-12-07 10:00:00 +0000, options: -test" -test
    echo "-test" > "$w/log.Allrun.args"; listing > "$tmp/before"
    refused "another run is writing this folder ($w): pid 4242" -resume
    rm -f "$w/log.Allrun.args"; listing > "$tmp/before"
    estimate
    (cd "$w" && ./Allclean) > "$tmp/out" 2> "$tmp/err" && fail "Allclean while the folder is locked: exit 0"
    grep -qF "a run is writing this folder ($w): pid 4242" "$tmp/err" || fail "Allclean while locked: $(cat "$tmp/err")"
    listing | diff -q "$tmp/before" - > /dev/null || fail "Allclean while locked removed files"
    echo "ok   Allclean while the folder is locked: $(head -1 "$tmp/err")"
    kill "$holder" 2>/dev/null; wait "$holder" 2>/dev/null
    (cd "$w" && ./Allclean) || fail "Allclean after the holder ended: exit $?"
    [ ! -e "$w/Allrun.owner" ] || fail "Allclean left Allrun.owner"
    echo "ok   the holder ended: the lock free again, Allclean removes Allrun.owner"
    # Allrun.owner never written through a FIFO (or a link): refused, and Allclean leaves it
    mkfifo "$w/Allrun.owner"; listing > "$tmp/before"
    refused "Allrun.owner is not a file a run wrote (a link, folder, FIFO or device)" -test
    (cd "$w" && ./Allclean) || fail "Allclean with a FIFO Allrun.owner: exit $?"
    [ -p "$w/Allrun.owner" ] || fail "Allclean removed a FIFO it did not write"
    rm -f "$w/Allrun.owner"
    echo "ok   a FIFO named Allrun.owner: Allrun refuses, Allclean leaves it"
    unset SNOWWALL_LOCK_WAIT
else
    echo "skip the estimate checks: OpenFOAM or the build missing"
fi
echo "PASS"
