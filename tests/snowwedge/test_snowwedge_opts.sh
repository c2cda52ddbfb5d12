#!/usr/bin/env bash
# test_snowwedge_opts.sh - the snowwedge commands behind tutorials/wedge/Allrun's command
# line and plumbing, in a temporary case folder: allrun-options (the assignments Allrun
# evaluates; values that hold quotes or $(...) come back as the very text and run
# nothing; every refusal one line "Allrun: ...", exit 2, nothing on stdout), spray-entry
# (an entry of constant/sprayProperties checked), progress --watch (the progress line of
# a log's last step while a process runs) and resume-start / resume-join (a resumed
# run's controlDict, log parts and resume record).
# shellcheck source=common.sh
. "$(dirname "$0")/common.sh"
c="$tmp/case"
mkdir -p "$c/constant" "$c/system"
printf 'test\n{\n    mesh "nxUp 8; nxBody 12; nxDown 16; nBody 12; nOut 7;";\n    parcelFactor 0.25;\n    classFactor 0.125;\n    steadyFactor 0.05;\n}\n' \
    > "$c/constant/variants"
sed 's/^test/coarse/' "$c/constant/variants" >> "$c/constant/variants"
mkdir -p "$c/constant/gates"
printf 'slideLength 1e-4;\nvtTable (0 0.5 1);\n' > "$c/constant/gates/regime"
printf 'maxDeltaT 1e-3;\n' > "$c/system/controlDict.transient"
opts() { (cd "$c" && "$S" allrun-options --nproc 2 --case "$c" -- "$@"); }

opts -test -gate shear > "$tmp/o"
check "allrun-options: the settings as assignments (the variant's mesh, the default ladder, mpi_opts, the estimate's arguments)" \
    "grep -qx \"est=(--mesh 'nxUp 8; nxBody 12; nxDown 16; nBody 12; nOut 7;' --nozzle-array constant/nozzleArray --np 1 --replay --max-delta-t '1e-3' --rear-layers --ppn-factor '0.25' --class-factor '0.125' --dispersion 'nearwall' --level-scale '1')\" '$tmp/o' && grep -qx \"vtlist='0,0.5,1'\" '$tmp/o' && grep -qx \"mesh='nxUp 8; nxBody 12; nxDown 16; nBody 12; nOut 7;'\" '$tmp/o' && grep -qx \"gate='shear'\" '$tmp/o' && grep -qx 'rear_layers=1' '$tmp/o' && grep -qx \"ladder_file='none'\" '$tmp/o' && grep -qx 'mpi_opts=()' '$tmp/o' && grep -qx \"args_given=('-test' '-gate' 'shear')\" '$tmp/o'"
# hostile values: a file name with $(...), quotes and backquotes given to -ladder (made
# absolute) and read back by -resume: evaluated, the assignments give the very text back
# and run nothing; a refusal names the value as it is
hostile=('$(touch pwned)' "'; touch pwned; '" 'a"b`touch pwned`\')
for h in "${hostile[@]}"; do
    opts -test -gate "$h" > "$tmp/o" 2> "$tmp/e"; rc=$?
    check "allrun-options -gate '$h': exit 2, the value named as it is" \
        "[ $rc = 2 ] && [ ! -s '$tmp/o' ] && [ \"\$(cat '$tmp/e')\" = \"Allrun: -gate must be off, tangential, shear or regime, got '\$h'\" ]"
    touch "$c/$h"
    printf '%s\n' -test -ladder "$h" > "$c/log.Allrun.args"
    (cd "$c" && "$S" allrun-options --case "$c" -- -resume) > "$tmp/o"
    (cd "$c" && eval "$(cat "$tmp/o")" && printf '%s\n' "$ladder_file" "${args_given[2]}" "$resume") > "$tmp/v"
    check "allrun-options -resume with -ladder '$h': evaluated, the absolute path back as text, nothing run" \
        "[ \"\$(sed -n 1p '$tmp/v')\" = \"$c/\$h\" ] && [ \"\$(sed -n 2p '$tmp/v')\" = \"$c/\$h\" ] && [ \"\$(sed -n 3p '$tmp/v')\" = 1 ] && [ ! -e '$c/pwned' ]"
    rm -f "$c/$h" "$c/log.Allrun.args"
done
printf '%s\n' -test -ladder none > "$c/log.Allrun.args"
(cd "$c" && "$S" allrun-options --case "$c" -- -resume) > "$tmp/o"
check "allrun-options -resume: the options of log.Allrun.args" \
    "grep -qx 'resume=1' '$tmp/o' && grep -qx \"args_given=('-test' '-ladder' 'none')\" '$tmp/o'"
rm -f "$c/log.Allrun.args"

refused() {  # refused MESSAGE ARGS...: exit 2, the one line, nothing on stdout
    local want=$1; shift
    opts "$@" > "$tmp/o" 2> "$tmp/e"; local rc=$?
    check "allrun-options $*: exit 2, '$want'" \
        "[ $rc = 2 ] && [ ! -s '$tmp/o' ] && [ \"\$(cat '$tmp/e')\" = \"Allrun: \$want\" ]"
}
# -parcels K: the classes' factor K times (-test's 0.125 x 4), the spray's not; refusals
opts -test -parcels 4 > "$tmp/o"
check "allrun-options -test -parcels 4: class_factor 0.5, parcel_factor as the variant's" \
    "grep -qx \"class_factor='0.5'\" '$tmp/o' && grep -q -- \"--class-factor '0.5'\" '$tmp/o' && [ \"\$(opts -test | grep '^parcel_factor=')\" = \"\$(grep '^parcel_factor=' '$tmp/o')\" ]"
refused "-parcels needs a whole factor from 1 to 99, got '0'" -parcels 0
refused "-parcels needs a whole factor from 1 to 99, got '100'" -parcels 100
refused "-parcels needs a whole factor from 1 to 99, got ''" -parcels
refused "-parcels multiplies the size classes of the transient route (not -steady)" -steady -parcels 2
refused "-resume: no run to resume in $c (log.Allrun.args is missing: a run writes it when it starts)" -resume
refused "-resume takes no other option: the run goes on with its own (log.Allrun.args)" -resume -test
refused "-parallel 3: this machine has 2 processors (nproc); accepted: 1 to 2 (up to 8 with -oversubscribe)" -parallel 3
refused "-checkpoint needs a positive number of minutes (at most 1e6) or off, got '0'" -checkpoint 0
refused "-feedback needs the transient route (not -steady)" -steady -feedback
refused "-sizes: '20' is given twice in '20,5,20'" -sizes 20,5,20
refused "constant/variants: no mesh for the variant fine" -fine
opts -sizes 20,5,10 > "$tmp/o" 2> "$tmp/e"
check "allrun-options -sizes 20,5,10: in ascending order with a note" \
    "grep -qx \"sizes='5,10,20'\" '$tmp/o' && grep -qx \"Allrun: note: -sizes: '20,5,10' taken in ascending order\" '$tmp/e'"
opts -test --help -gate on > "$tmp/o"
check "allrun-options --help among the options: help=1 only" "[ \"\$(cat '$tmp/o')\" = help=1 ]"
"$S" allrun-options --nproc 0 -- -test > /dev/null 2> "$tmp/e"
check "allrun-options --nproc 0: exit 2 naming --nproc" "[ $? = 2 ] && grep -q -- '--nproc' '$tmp/e'"

# spray-entry
check "spray-entry list2: parentheses and blanks away" \
    "[ \"\$('$S' spray-entry --kind list2 --key spray/range -- '( 2  150 )')\" = '2 150' ]"
check "spray-entry intlist: comma-separated" \
    "[ \"\$('$S' spray-entry --kind intlist --key classes/sizes -- '( 5 10 20 )')\" = 5,10,20 ]"
"$S" spray-entry --kind num --key spray/mvd -- '' > "$tmp/o" 2> "$tmp/e"
check "spray-entry num of a missing entry: exit 2, named <missing>" \
    "[ $? = 2 ] && grep -qxF \"snowwedge: constant/sprayProperties: 'spray/mvd' must be a positive number, got '<missing>'\" '$tmp/e'"
"$S" spray-entry --kind words --key k -- 1 > /dev/null 2> "$tmp/e"
check "spray-entry --kind words: exit 2" "[ $? = 2 ] && grep -q -- '--kind' '$tmp/e'"

# progress --watch: a log whose last step is t = 0.05 of 0.2 s, while a process runs
printf 'Time = 0.01\nCourant\nTime = 0.05\nExecutionTime = 3 s\n' > "$tmp/log"
sleep 3 & pid=$!
"$S" progress --watch "$tmp/log" --end 0.2 --pid "$pid" --allrun-start "$(date +%s)" --interval 0.5 > "$tmp/o"
check "progress --watch: the line of the last step while the process runs, then it stops" \
    "[ \$(wc -l < '$tmp/o') -ge 3 ] && grep -q '^Allrun \\[[0-9]* s\\]: solver at t = 0.05 of 0.2 s (25 %), [0-9]* s elapsed, time left not yet estimated' '$tmp/o'"

# resume-start / resume-join: two parts of a log, the record of the resume
r="$tmp/run"; mkdir -p "$r/system"
printf 'application x;\nstartFrom       latestTime;\nstartTime       0;\nendTime 1;\n' > "$r/system/controlDict"
printf 'deltaT = 0.1\nTime = 0.1\nWall time [s], largest: flow 1\ndeltaT = 0.1\nTime = 0.2\nWall time [s], largest: flow 2\n' > "$r/log.S"
(cd "$r" && "$S" resume-start --time 0.1 --solver S) > "$tmp/o"
check "resume-start: startFrom and startTime set, the log kept as part 1, the resume recorded" \
    "grep -qx 'startTime       0.1;' '$r/system/controlDict' && grep -qx 'startFrom       startTime;' '$r/system/controlDict' && grep -qx 'endTime 1;' '$r/system/controlDict' && [ -f '$r/log.S.part1' ] && [ ! -e '$r/log.S' ] && [ \"\$(cat '$r/log.Allrun.resumes')\" = 0.1 ] && grep -qx 'resume: S from time 0.1 (the last time folder written whole), resume 1' '$tmp/o'"
printf 'deltaT = 0.1\nTime = 0.2\nWall time [s], largest: flow 0.5\n' > "$r/log.S"
(cd "$r" && "$S" resume-join --solver S) > "$tmp/o"
check "resume-join: the two parts as one log" \
    "[ -f '$r/log.S' ] && [ -f '$r/log.S.part2' ] && [ \$(grep -c '^Time = ' '$r/log.S') = 2 ] && grep -qx 'resume: the logs of 2 parts joined into log.S; the tables of postProcessing/ joined' '$tmp/o'"
printf 'application x;\n' > "$r/system/controlDict"
(cd "$r" && "$S" resume-start --time 0.1 --solver S) > /dev/null 2> "$tmp/e"
check "resume-start without a startTime line: exit 1 named" \
    "[ $? = 1 ] && grep -qxF 'snowwedge: -resume: could not set startTime 0.1 in system/controlDict' '$tmp/e'"
finish
