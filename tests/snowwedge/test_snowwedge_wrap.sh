#!/usr/bin/env bash
# test_snowwedge_wrap.sh - the options of the scripts tutorials/wedge/post/wedge-*, parsed
# by snowwedge (swe_cmd_wrap.c): every refusal with its message (the script's name as
# prefix) and exit status, the defaults and the values printed as shell assignments
# (quotes kept through eval), --help; and the steps moved out of the scripts: the
# rear-face maps of a window (rear-maps), the head of a variant's regions table
# (convergence.md's y+ line and regions' head: test_snowwedge_post.sh).
# shellcheck source=common.sh
. "$(dirname "$0")/common.sh"

# refused CODE MESSAGE ARGS...: snowwedge ARGS exits CODE with exactly MESSAGE on stderr
refused() {
    local code=$1 msg=$2; shift 2
    (cd "$tmp/w" && "$S" "$@") > "$tmp/out" 2> "$tmp/err"; local rc=$?
    check "$* -> $code: $msg" "[ $rc = $code ] && [ \"\$(cat '$tmp/err')\" = \"\$msg\" ] && [ ! -s '$tmp/out' ]"
}
mkdir -p "$tmp/w/res/off" "$tmp/w/case"
: > "$tmp/w/empty"

# ---- wedge-capture ---------------------------------------------------------------------
refused 2 "wedge-capture: --results needs a folder (see --help)" wedge-capture --results
refused 2 "wedge-capture: --gate needs a name (see --help)" wedge-capture --results . --gate
refused 2 "wedge-capture: --sampled needs a number (see --help)" wedge-capture --sampled ''
refused 2 "wedge-capture: unknown option '--frob' (see --help)" wedge-capture --results . --frob
refused 2 "wedge-capture: unknown option 'x' (see --help)" wedge-capture x
refused 2 "wedge-capture: --results is required" wedge-capture
for f in 0 2 x 1e- -0.5; do
    refused 2 "wedge-capture: --sampled '$f' outside (0, 1]" wedge-capture --results . --sampled "$f"
done
refused 1 "wedge-capture: no no/such/d<N>um results (run Allrun -sizes LIST)" wedge-capture --results no/such

# ---- wedge-cost -------------------------------------------------------------------------
refused 2 "wedge-cost: --log needs a value (see --help)" wedge-cost --log
refused 2 "wedge-cost: unknown option 'x' (see --help)" wedge-cost x
refused 2 "wedge-cost: --results, --log, --gate and --mvd are required (see --help)" wedge-cost --results res --log l --gate off
refused 1 "wedge-cost: cannot read nolog" wedge-cost --results res --log nolog --gate off --mvd 20
refused 1 "wedge-cost: cannot read res/off/rear_statistics.md" wedge-cost --results res --log empty --gate off --mvd 20
: > "$tmp/w/res/off/rear_statistics.md"; : > "$tmp/w/res/off/mass_balance.txt"
refused 1 "wedge-cost: empty has no 'Wall time [s]' line (an older solver?)" wedge-cost --results res --log empty --gate off --mvd 20

# ---- wedge-dispersion -------------------------------------------------------------------
refused 2 "wedge-dispersion: --main needs a treatment (see --help)" wedge-dispersion --main
refused 2 "wedge-dispersion: --others needs a list (see --help)" wedge-dispersion --others ''
refused 2 "wedge-dispersion: --results and --main are required" wedge-dispersion --results . --others crw
refused 1 "wedge-dispersion: no main deposit_per_patch.csv in ." wedge-dispersion --results . --main nearwall

# ---- wedge-fill -------------------------------------------------------------------------
F=(wedge-fill --case case --cloud c --soi 1)
refused 2 "wedge-fill: --level needs a value (see --help)" wedge-fill --level
refused 2 "wedge-fill: --case DIR is required (see --help)" wedge-fill --cloud c
refused 2 "wedge-fill: --cloud NAME is required (see --help)" wedge-fill --case case
refused 2 "wedge-fill: --soi: '' is not a time >= 0 (see --help)" wedge-fill --case case --cloud c
for s in x -1 1. 1e-; do
    refused 2 "wedge-fill: --soi: '$s' is not a time >= 0 (see --help)" wedge-fill --case case --cloud c --soi "$s"
done
refused 2 "wedge-fill: --window: '' is not T0,T1 with soi <= T0 < T1 (see --help)" "${F[@]}"
for w in 2 2,1 0.5,2 1,2,3 1,2,3, a,2 1,1; do
    refused 2 "wedge-fill: --window: '$w' is not T0,T1 with soi <= T0 < T1 (see --help)" "${F[@]}" --window "$w"
done
for l in 0 1 x 1.5; do
    refused 2 "wedge-fill: --level: '$l' is not in (0, 1) (see --help)" "${F[@]}" --window 1,2 --level "$l"
done
refused 1 "wedge-fill: no rear-face records case/postProcessing/lagrangian/c/rearImpacts/*/rear.post" "${F[@]}" --window 1,2,
# the records of --case and --cloud: the same row as fill on the files
d="$tmp/w/case/postProcessing/lagrangian/c/rearImpacts"
mkdir -p "$d/0" "$d/1.5"
hdr='# Time currentProc origProc origId nParticle position0 position1 position2 U0 U1 U2 d rho age'
printf '%s\n1.2 0 0 1 10 0 0 0 0 0 0 1e-5 920 0.05\n1.7 0 0 2 10 0 0 0 0 0 0 1e-5 920 0.3\n' "$hdr" > "$d/0/rear.post"
printf '%s\n1.9 0 0 3 10 0 0 0 0 0 0 2e-5 920 0.6\n' "$hdr" > "$d/1.5/rear.post"
(cd "$tmp/w" && "$S" wedge-fill --case case --cloud c --soi 1 --window 1,2 --level .5) > "$tmp/fill1" 2>&1
(cd "$tmp/w" && "$S" fill --name wedge-fill --label c --soi 1 --window 1,2 --level .5 "$d/0/rear.post" "$d/1.5/rear.post") > "$tmp/fill2" 2>&1
check "wedge-fill: the row of fill on the cloud's records (label: the cloud)" "[ -s '$tmp/fill1' ] && cmp -s '$tmp/fill1' '$tmp/fill2' && grep -q '^| c |' '$tmp/fill1'"

# ---- wedge-resolution -------------------------------------------------------------------
refused 2 "wedge-resolution: --mvd needs a value (see --help)" wedge-resolution --mvd
refused 2 "wedge-resolution: --base and --refined are required (see --help)" wedge-resolution --base .
for m in x -5 1e3 '20;8'; do
    refused 2 "wedge-resolution: --mvd needs diameters in um, comma-separated, got '$m' (see --help)" wedge-resolution --base . --refined . --mvd "$m"
done
refused 2 "wedge-resolution: --mvd: an empty item in '1,,2'" wedge-resolution --base . --refined . --mvd 1,,2
refused 2 "wedge-resolution: --mvd: an empty item in '8,'" wedge-resolution --base . --refined . --mvd 8,
refused 2 "wedge-resolution: --mvd: '2.0' is given twice in '2,2.0'" wedge-resolution --base . --refined . --mvd 2,2.0
refused 2 "wedge-resolution: --mvd: '.' in '8,.' is not a number" wedge-resolution --base . --refined . --mvd 8,.
# an unsorted list: a note, then the runs' own check (no compose folder: exit 1)
(cd "$tmp/w" && "$S" wedge-resolution --base . --refined . --mvd 56,8,20) > /dev/null 2> "$tmp/err"; rc=$?
check "wedge-resolution: an unsorted --mvd noted in ascending order, then ./compose missing (exit 1)" \
    "[ $rc = 1 ] && [ \"\$(head -1 '$tmp/err')\" = \"wedge-resolution: note: --mvd: '56,8,20' taken in ascending order\" ] && grep -qx 'wedge-resolution: ./compose missing (a run with size classes: Allrun without -sizes none)' '$tmp/err'"

# ---- wedge-variant ----------------------------------------------------------------------
refused 2 "wedge-variant: --variant needs feedback, rough or rebound (see --help)" wedge-variant --variant
refused 2 "wedge-variant: --gate needs a setting (see --help)" wedge-variant --variant rough --results . --gate
refused 2 "wedge-variant: --log needs a file (see --help)" wedge-variant --variant rough --log
refused 2 "wedge-variant: --snowphoto needs a program (see --help)" wedge-variant --snowphoto ''
refused 2 "wedge-variant: --results and --gate are required" wedge-variant --variant rough --results .
refused 2 "wedge-variant: --variant must be feedback, rough or rebound, got 'foo'" wedge-variant --variant foo --results . --gate off
refused 2 "wedge-variant: --variant must be feedback, rough or rebound, got ''" wedge-variant --results . --gate off
refused 2 "wedge-variant: --rel '0' outside (0, 1]" wedge-variant --variant rough --results . --gate off --rel 0
refused 2 "wedge-variant: --rel '2' outside (0, 1]" wedge-variant --variant rebound --results . --gate off --rel 2

# ---- wedge-errortime --------------------------------------------------------------------
refused 2 "wedge-errortime: --title needs a value (see --help)" wedge-errortime --title
refused 2 "wedge-errortime: unknown option '--frob' (see --help)" wedge-errortime --frob
refused 2 "wedge-errortime: 'a.csv' has no label (see --help)" wedge-errortime --out o.png a.csv
refused 2 "wedge-errortime: --out PNG is required (see --help)" wedge-errortime a.csv A
refused 2 "wedge-errortime: give at least one CSV LABEL (see --help)" wedge-errortime --out o.png
refused 2 "wedge-errortime: --region: 'top' is not face, left, right, centre or edges (see --help)" wedge-errortime --out o.png --region top a.csv A

# ---- wedge-post -------------------------------------------------------------------------
refused 2 "wedge-post: --case needs a folder (see --help)" wedge-post --case
refused 2 "wedge-post: --window needs T0,TH,T1 (see --help)" wedge-post --case . --out o --window
refused 2 "wedge-post: --case and --out are required (see --help)" wedge-post --case .
refused 1 "wedge-post: case folder 'no/such' not found" wedge-post --case no/such --out o
refused 1 "wedge-post: case folder 'empty' not found" wedge-post --case empty --out o
for w in 1e-,2,3 0,2,1 0,1 nan,1,2 0,1,2,3 -1,1,2 0,0,1 ,1,2; do
    refused 2 "wedge-post: --window '$w' is not T0,TH,T1 with 0 <= T0 < TH < T1" wedge-post --case . --out o --window "$w"
done

# ---- wedge-compose ----------------------------------------------------------------------
refused 2 "wedge-compose: --range needs a value (see --help)" wedge-compose --range
refused 2 "wedge-compose: --results DIR is required (see --help)" wedge-compose --out o --mvd 30
refused 2 "wedge-compose: --out DIR is required (see --help)" wedge-compose --results . --mvd 30
refused 2 "wedge-compose: give the spray: --mvd UM or --masses CSV (see --help)" wedge-compose --results . --out o
refused 2 "wedge-compose: --mvd and --masses exclude each other (see --help)" wedge-compose --results . --out o --mvd 30 --masses empty
refused 2 "wedge-compose: --masses: cannot read 'no/such' (see --help)" wedge-compose --results . --out o --masses no/such
refused 2 "wedge-compose: --mvd: '0' is not a diameter in [0.1, 1000] um (see --help)" wedge-compose --results . --out o --mvd 0
refused 2 "wedge-compose: --sigma-g: '0.5' is not in (1, 10] (see --help)" wedge-compose --results . --out o --mvd 30 --sigma-g 0.5
refused 2 "wedge-compose: --range: '50,10' is not MIN,MAX with 0 < MIN < MAX <= 10000 um (see --help)" wedge-compose --results . --out o --mvd 30 --range 50,10
refused 2 "wedge-compose: --freeze: '3' is not in [0.5, 2] (see --help)" wedge-compose --results . --out o --mvd 30 --freeze 3
refused 2 "wedge-compose: --sampled: '0' is not in (0, 1] (see --help)" wedge-compose --results . --out o --masses empty --sampled 0

# ---- wedge-ladder -----------------------------------------------------------------------
refused 2 "wedge-ladder: --targets needs a value (see --help)" wedge-ladder --targets
refused 2 "wedge-ladder: unknown option 'x' (see --help)" wedge-ladder x
refused 2 "wedge-ladder: --check takes no other option (see --help)" wedge-ladder --check empty --run a
refused 2 "wedge-ladder: --check no/such: not a readable file" wedge-ladder --check no/such
refused 2 "wedge-ladder: --check res: not a readable file" wedge-ladder --check res
refused 2 "wedge-ladder: --out DIR is required (see --help)" wedge-ladder --run a --run b
refused 2 "wedge-ladder: at least two --run DIR are needed (three for an observed order), or one and --with (see --help)" wedge-ladder --out o --run a
refused 2 "wedge-ladder: --with needs at least one --run DIR (see --help)" wedge-ladder --out o --with empty
refused 1 "wedge-ladder: --with no/such: not a readable file" wedge-ladder --out o --run a --with no/such
for t in x 10,,30 ,10 10, 10:30; do
    refused 2 "wedge-ladder: --targets: '$t' is not a comma-separated list of percentages (see --help)" wedge-ladder --out o --run a --run b --targets "$t"
done
printf '# a comment\nquantity,run,design,level,cells,step,value,se,t_flow,t_clouds\nCd,a,d,0,100,1,1.1,0.01,1,1\n' > "$tmp/w/ok.csv"
(cd "$tmp/w" && "$S" wedge-ladder --check ok.csv) > "$tmp/out" 2> "$tmp/err"; rc=$?
check "wedge-ladder --check a good ladder: 'exit 0' for the script, nothing else" "[ $rc = 0 ] && [ \"\$(cat '$tmp/out')\" = 'exit 0' ] && [ ! -s '$tmp/err' ]"
printf 'quantity,run\n' > "$tmp/w/bad.csv"
(cd "$tmp/w" && "$S" wedge-ladder --check bad.csv) > "$tmp/out" 2> "$tmp/err"; rc=$?
check "wedge-ladder --check a bad ladder: exit 2, named as the script" "[ $rc = 2 ] && grep -q '^wedge-ladder: --check bad.csv: line 1: ' '$tmp/err' && [ ! -s '$tmp/out' ]"

# ---- the assignments: defaults, given values with quotes, lists ---------------------------
(cd "$tmp/w" && "$S" wedge-post --case . --out "o'1" --window 0,1,2, --force) > "$tmp/a" 2>&1
( eval "$(cat "$tmp/a")"
  [ "$case_dir" = . ] && [ "$out" = "o'1" ] && [ "$gate" = off ] && [ "$cloud" = kinematicCloud ] &&
  [ "$solverlog" = log.icoUncoupledKinematicParcelFoam ] && [ "$window" = 0,1,2, ] && [ -z "$snowphoto" ] &&
  [ "$force" = 1 ] && [ "$w0,$wh,$w1" = 0,1,2 ] ) && r=0 || r=1
check "wedge-post: the defaults, a quote in --out, the window's times (a trailing comma as the shell's read)" "[ $r = 0 ]"
(cd "$tmp/w" && "$S" wedge-ladder --run "a b" --run "c'd" --out o --targets 5) > "$tmp/a" 2>&1
( eval "$(cat "$tmp/a")"; [ "${#runs[@]}" = 2 ] && [ "${runs[0]}" = "a b" ] && [ "${runs[1]}" = "c'd" ] &&
  [ "$targets" = 5 ] && [ "$force" = 0 ] && [ -z "$ladder" ] ) && r=0 || r=1
check "wedge-ladder: the --run folders as an array, blanks and quotes kept" "[ $r = 0 ]"
(cd "$tmp/w" && "$S" wedge-errortime --out o.png x.csv "run 1" y.csv -z) > "$tmp/a" 2>&1
( eval "$(cat "$tmp/a")"; [ "${args[*]}" = "x.csv run 1 y.csv -z" ] && [ "${#args[@]}" = 4 ] && [ "$region" = edges ] &&
  [ "$title" = "Error of the rear-face deposit against run time" ] ) && r=0 || r=1
check "wedge-errortime: the CSV LABEL pairs, the default region and title" "[ $r = 0 ]"
(cd "$tmp/w" && "$S" wedge-variant --variant rebound --results . --gate off) > "$tmp/a" 2>&1
( eval "$(cat "$tmp/a")"; [ "$with" = "classic rebound" ] && [ "$rel" = 0.1 ] && [ "$logf" = log.pimpleUncoupledKinematicParcelFoam ] ) && r=0 || r=1
check "wedge-variant: the variant's name in the table, the defaults" "[ $r = 0 ]"
(cd "$tmp/w" && "$S" wedge-compose --results . --out o --mvd 20) > "$tmp/a" 2>&1
( eval "$(cat "$tmp/a")"; [ "$sg,$range,$freeze,$sampled,$force" = "1.8,2,150,1.03,1,0" ] && [ -z "$masses" ] ) && r=0 || r=1
check "wedge-compose: the spray's defaults" "[ $r = 0 ]"

# ---- --help: the script's usage, every option ---------------------------------------------
"$S" wedge-capture --help > "$tmp/h"; rc=$?
check "wedge-capture --help: exit 0, its usage" "[ $rc = 0 ] && grep -q '^Usage: post/wedge-capture --results DIR' '$tmp/h'"
for s in "capture --results --gate --dispersion --sampled" "cost --results --log --gate --mvd" \
         "dispersion --results --main --others" "fill --case --cloud --soi --window --level --label" \
         "resolution --base --refined --mvd --base-label --refined-label" \
         "post --case --out --force --cloud --gate --log --window --snowphoto" \
         "compose --results --out --force --mvd --sigma-g --range --freeze --masses --sampled --label" \
         "ladder --run --with --out --force --plot --targets --snowladder --check" \
         "variant --variant --results --gate --log --snowphoto --rel" "errortime --out --region --title"; do
    set -- $s
    "$S" "wedge-$1" --help > "$tmp/h"; rc=$?; n=$1; shift; miss=
    for o in "$@"; do grep -q -- "^  $o " "$tmp/h" || miss="$miss $o"; done
    check "wedge-$n --help: exit 0, one line for each option${miss:+ (missing:$miss)}" "[ $rc = 0 ] && [ -z '$miss' ]"
done
(bash -c "eval \"\$('$S' wedge-post --help)\"; echo after") > "$tmp/h"
check "wedge-post --help: printed through eval, then exit 0 (nothing after)" \
    "grep -q '^Usage: post/wedge-post --case DIR --out DIR' '$tmp/h' && ! grep -q '^after' '$tmp/h' && grep -q -- '--snowphoto EXE' '$tmp/h'"
for s in compose ladder variant errortime; do
    h=$(bash -c "eval \"\$('$S' wedge-$s --help)\"")
    check "wedge-$s --help through eval: its usage" "printf '%s' \"\$h\" | grep -q '^Usage: post/wedge-$s'"
done

# ---- rear-maps: the window's map and its halves x2, or the last write ----------------------
c="$tmp/case"
for t in 0.2 0.4 0.6; do
    mkdir -p "$c/postProcessing/deposit_rear/surface/$t"
done
printf '# x y z v\n0 1 0 1\n0 -1 0 1\n' > "$c/postProcessing/deposit_rear/surface/0.2/c:snowDeposit_patch_rear.raw"
printf '# x y z v\n0 1 0 2\n0 -1 0 4\n' > "$c/postProcessing/deposit_rear/surface/0.4/c:snowDeposit_patch_rear.raw"
printf '# x y z v\n0 1 0 7\n0 -1 0 5\n' > "$c/postProcessing/deposit_rear/surface/0.6/c:snowDeposit_patch_rear.raw"
mkdir -p "$tmp/maps" "$tmp/last"
(cd "$c" && "$S" rear-maps --name wedge-post --cloud c --dir "$tmp/maps" --window 0.2,0.4,0.6)
check "rear-maps: the window 0.2 .. 0.6 (B - A)" "[ \"\$(tr '\n' ' ' < '$tmp/maps/rear_deposit.csv')\" = 'y,z,deposit_kg_m2 -1,0,4 1,0,6 ' ]"
check "rear-maps: the first half x2" "[ \"\$(tr '\n' ' ' < '$tmp/maps/rear_deposit_half1.csv')\" = 'y,z,deposit_kg_m2 -1,0,6 1,0,2 ' ]"
check "rear-maps: the second half x2" "[ \"\$(tr '\n' ' ' < '$tmp/maps/rear_deposit_half2.csv')\" = 'y,z,deposit_kg_m2 -1,0,2 1,0,10 ' ]"
check "rear-maps: mode 644, no temporary file left" "[ \$(stat -c %a '$tmp/maps/rear_deposit.csv') = 644 ] && [ \$(ls -A '$tmp/maps' | wc -l) = 3 ]"
(cd "$c" && "$S" rear-maps --name wedge-post --cloud c --dir "$tmp/last")
check "rear-maps: without a window the last write" "[ \"\$(tr '\n' ' ' < '$tmp/last/rear_deposit.csv')\" = 'y,z,deposit_kg_m2 -1,0,5 1,0,7 ' ] && [ ! -e '$tmp/last/rear_deposit_half1.csv' ]"
(cd "$c" && "$S" rear-maps --name wedge-post --cloud c --dir "$tmp/last" --window 0.2,0.3,0.6) 2> "$tmp/err"; rc=$?
check "rear-maps: no map at a time: exit 1, named" "[ $rc = 1 ] && [ \"\$(cat '$tmp/err')\" = 'wedge-post: no rear-face map of c:snowDeposit at time 0.3 in postProcessing/deposit_rear/surface/' ]"
printf '# x y z v\n0 1 0 7\n' > "$c/postProcessing/deposit_rear/surface/0.6/c:snowDeposit_patch_rear.raw"
mkdir -p "$tmp/bad"
(cd "$c" && "$S" rear-maps --name wedge-post --cloud c --dir "$tmp/bad" --window 0.2,0.4,0.6) 2> "$tmp/err"; rc=$?
check "rear-maps: maps of different faces: exit 1, nothing left behind" "[ $rc = 1 ] && grep -q 'rear-face maps .* differ' '$tmp/err' && [ -z \"\$(ls -A '$tmp/bad')\" ]"
printf '# x y z v\n0 1 0 7\n0 -1 0 5\n' > "$c/postProcessing/deposit_rear/surface/0.6/c:snowDeposit_patch_rear.raw"
mkdir -p "$tmp/dirmap/rear_deposit.csv"
(cd "$c" && "$S" rear-maps --name wedge-post --cloud c --dir "$tmp/dirmap") 2> "$tmp/err"; rc=$?
check "rear-maps: a folder where the map goes: refused (2), left as it was" \
    "[ $rc = 2 ] && grep -q 'it exists and is a folder' '$tmp/err' && [ -d '$tmp/dirmap/rear_deposit.csv' ] && [ \"\$(ls -A '$tmp/dirmap')\" = rear_deposit.csv ]"

# ---- variant --part regions: the head of the regions table ---------------------------------
"$S" variant --variant rough --results . --gate off --part regions --rel 0.2 --threshold 0.004 > "$tmp/v"
check "variant --part regions: the threshold and its share" \
    "[ \"\$(head -1 '$tmp/v')\" = 'Rear-face regions (threshold 0.004 kg/m2 = 0.2 x the larger maximum):' ] && [ \$(wc -l < '$tmp/v') = 4 ]"
"$S" variant --variant rough --results . --gate off --part regions --threshold none > "$tmp/v"
check "variant --part regions --threshold none: no deposit in either" \
    "[ \"\$(head -1 '$tmp/v')\" = 'Rear-face regions (no deposit on the rear face in either cloud):' ]"

# ---- the scripts themselves: the wrappers run snowwedge with their arguments -----------------
P="$top/tutorials/wedge/post"
SNOWWALL_TOP="$top" "$P/wedge-capture" --results > /dev/null 2> "$tmp/err"; rc=$?
check "post/wedge-capture: snowwedge's refusal, exit 2" "[ $rc = 2 ] && [ \"\$(cat '$tmp/err')\" = 'wedge-capture: --results needs a folder (see --help)' ]"
SNOWWALL_TOP="$top" "$P/wedge-post" --case "$tmp/w" > /dev/null 2> "$tmp/err"; rc=$?
check "post/wedge-post: snowwedge's refusal through eval, exit 2" "[ $rc = 2 ] && [ \"\$(cat '$tmp/err')\" = 'wedge-post: --case and --out are required (see --help)' ]"
SNOWWALL_TOP="$tmp/none" "$P/wedge-fill" > /dev/null 2> "$tmp/err"; rc=$?
check "post/wedge-fill without snowwedge: exit 1, named" "[ $rc = 1 ] && grep -q '^wedge-fill: $tmp/none/bin/snowwedge not found (run ./Allwmake)' '$tmp/err'"
finish
