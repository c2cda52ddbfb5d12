#!/usr/bin/env bash
# test_snowwedge_post.sh - snowwedge's per-run post-processing commands (the
# tables of tutorials/wedge/post) on a synthetic case with known answers: the
# deposit per patch over a window with its counts by reason (and a refusal when
# they do not add up), the mass balance, the halves of the window with their
# Poisson error, a rear-face map as a difference of two raw files, the capture
# table with the Stokes number, the cost table, the gate and variant tables,
# the dispersion table; missing inputs exit 1 with one line naming them.
# shellcheck source=common.sh
. "$(dirname "$0")/common.sh"

# ---- a case: cloud c, six patches, writes at 0.2, 0.4, 0.6 -----------------------------
c="$tmp/case"
patches="rear nose top bottom sideYneg sideYpos"
for p in $patches; do
    mkdir -p "$c/postProcessing/deposit_$p/0"
    # area 0.5 m2; deposit 1, 2, 4 kg at the three writes (rear: 10x)
    k=1; [ "$p" = rear ] && k=10
    printf '# Area          : 5.0e-01\n# Time\tareaIntegrate(c:snowDeposit)\n0.2\t%s\n0.4\t%s\n0.6\t%s\n' \
        "$k" $((2 * k)) $((4 * k)) > "$c/postProcessing/deposit_$p/0/surfaceFieldValue.dat"
done
mkdir -p "$c/postProcessing/c:snowWall/0" "$c/postProcessing/c:snowWall/0.2" "$c/postProcessing/c:snowWall/0.6"
{
    printf '# time'
    for p in $patches; do printf ' %s:impacts %s:sticks %s:bounces %s:ripoffs %s:depositedMass[kg]' $p $p $p $p $p; done
    printf '\n'
    # at 0.2: 10 impacts, 4 sticks, 6 bounces, 1 kg; 0.4: 30, 12, 18, 2; 0.6: 110, 40, 70, 4
    for row in "0.2 10 4 6 0 1" "0.4 30 12 18 0 2" "0.6 110 40 70 0 4"; do
        set -- $row; printf '%s' "$1"; shift
        for p in $patches; do printf ' %s %s %s %s %s' "$@"; done; printf '\n'
    done
} > "$c/postProcessing/c:snowWall/0/snowWall.dat"
for t in 0.2 0.6; do
    { echo "# patch type impacts stuck criterion tangential shear probability escaped"
      for p in $patches; do
          if [ $t = 0.2 ]; then echo "$p snow 10 4 5 1 0 0 0"; else echo "$p snow 110 40 60 5 0 5 0"; fi
      done; } > "$c/postProcessing/c:snowWall/$t/reasons.dat"
done
{ echo "Evolving c"; echo "Cloud: c"; echo "    Current mass in system = 0.5"
  echo "  - mass introduced = 100"; echo "  - parcels added = 50"
  echo "Courant Number mean: 0.1 max: 0.5"; echo "deltaT = 0.01"; echo "Time = 0.3"
  echo "Courant Number mean: 0.3 max: 0.9"; echo "deltaT = 0.03"; echo "Time = 0.5"; } > "$c/log"
mkdir -p "$c/postProcessing/lagrangian/c/escaped/0"
d=$(awk 'BEGIN { printf "%.17g", (6 / 3.14159265358979) ^ (1 / 3) }')   # pi d^3 / 6 = 1
printf '# Time currentProc nParticle d rho\n0.3 0 2 %s 3\n' "$d" > "$c/postProcessing/lagrangian/c/escaped/0/outlet.post"

(cd "$c" && "$S" patch-table --cloud c --gate off --what "the window" --window 0.2,0.6 --csv "$tmp/pp.csv") > "$tmp/pp.md"
check "patch-table: rear over 0.2 .. 0.6: 30 kg, 60 kg/m2, 100 impacts, by reason 36,55,4,0,5" \
    "grep -qx 'rear,0.5,30,60,100,36,64,0,3,36,55,4,0,5' '$tmp/pp.csv'"
check "patch-table: the markdown total 30 + 5 x 3 kg" "grep -q '^| \*\*all wedge faces\*\* | | \*\*45\*\* |' '$tmp/pp.md'"
(cd "$c" && "$S" patch-table --cloud c --csv "$tmp/pl.csv") > /dev/null
check "patch-table: the totals at the last write" "grep -qx 'nose,0.5,4,8,110,40,70,0,4,40,60,5,0,5' '$tmp/pl.csv'"
sed -i 's/^rear snow 110 40 60/rear snow 110 41 60/' "$c/postProcessing/c:snowWall/0.6/reasons.dat"
(cd "$c" && "$S" patch-table --name wedge-post --cloud c --csv "$tmp/bad.csv") > /dev/null 2> "$tmp/err"; rc=$?
check "patch-table: counts by reason that do not add up: exit 1, named" \
    "[ $rc = 1 ] && grep -q '^wedge-post: patch rear: the counts by reason (stuck 41' '$tmp/err'"
sed -i 's/^rear snow 110 41 60/rear snow 110 40 60/' "$c/postProcessing/c:snowWall/0.6/reasons.dat"
check "patch-table: the failed table's CSV not written, no temporary left" \
    "[ ! -e '$tmp/bad.csv' ] && [ -z \"\$(ls -A '$tmp' | grep '^\.tmp-')\" ]"
# its CSV never over a folder or a device
mkdir "$tmp/csvdir"
(cd "$c" && "$S" patch-table --cloud c --csv "$tmp/csvdir") > /dev/null 2> "$tmp/err"; rc=$?
check "patch-table: --csv a folder: refused (2), the folder left" \
    "[ $rc = 2 ] && grep -q \"cannot write '$tmp/csvdir': it exists and is a folder\" '$tmp/err' && [ -d '$tmp/csvdir' ]"
(cd "$c" && "$S" patch-table --cloud c --csv /dev/null) > /dev/null 2> "$tmp/err"; rc=$?
check "patch-table: --csv /dev/null: refused (2)" "[ $rc = 2 ] && grep -q 'character device' '$tmp/err'"

(cd "$c" && "$S" balance --cloud c --gate off --log log) > "$tmp/mb"
check "balance: injected 100, escaped 2 x 3 x 1 = 6 kg, airborne 0.5" \
    "grep -qx 'injected = 100' '$tmp/mb' && grep -qx 'escaped = 6' '$tmp/mb' && grep -qx 'airborne = 0.5' '$tmp/mb'"
check "balance: logged 6 x 4 kg, field 40 + 5 x 4 kg, parcel mass 2 kg" \
    "grep -qx 'deposited_logged = 24' '$tmp/mb' && grep -qx 'deposited_field = 60' '$tmp/mb' && grep -qx 'parcel_mass = 2' '$tmp/mb'"
check "balance: err_field_vs_logged = (60 - 24) / 100" "grep -qx 'err_field_vs_logged = 3.600e-01' '$tmp/mb'"

printf '| period | left |\n| window 0.2 .. 0.6 s | x |\n' > "$tmp/rs.md"
(cd "$c" && "$S" convergence --cloud c --gate off --window 0.2,0.4,0.6 --log log --file "$tmp/rs.md") > "$tmp/conv"
# halves of the nose: 2 (2 - 1) = 2 and 2 (4 - 2) = 4 kg, they differ by -2 / 3 = -67 %; 36 sticks: 1/6
check "convergence: the halves x2, their difference, the Poisson error of 36 sticks" \
    "grep -qx '| nose | 100 | 36 | 3 | 2 | 4 | -67 % | 16.7 % |' '$tmp/conv'"
check "convergence: the parcel mass 100 / 50 kg and the time steps in the window" \
    "grep -q 'Parcel mass 2 kg (mean of the 50 injected)' '$tmp/conv' && grep -qx 'Time steps in the window: 2, mean deltaT 0.02 s, mean Courant number 0.2 (cell mean), largest 0.9.' '$tmp/conv'"

# a played-back flow (the log's "Replay:" line): the spectrum of the solved library too;
# Cs a sine of 30 Hz, Cd one of 10 Hz over 0.1 .. 0.3 s (resolution 5 Hz)
mkdir -p "$c/postProcessing/forceCoeffs/0"
awk 'BEGIN { pi = atan2(0, -1); print "# Time Cd Cs Cl"
    for (i = 1; i <= 6000; i++) { t = i * 1e-4
        printf "%.6g %.8g %.8g %.8g\n", t, 0.4 + 0.01 * sin(2 * pi * 10 * t), 0.02 * sin(2 * pi * 30 * t), 0.01 * sin(2 * pi * 60 * t) } }' \
    > "$c/postProcessing/forceCoeffs/0/coefficient.dat"
{ echo 'Replay: snapshots every 0.001 s from 0.1 s over 0.2 s (200 snapshots of 6(U p k omega nut phi)); the flow is solved until 0.3 s, then played back periodically'; cat "$c/log"; } > "$c/log.replay"
(cd "$c" && "$S" convergence --cloud c --window 0.2,0.4,0.6 --log log.replay --file "$tmp/rs.md") > "$tmp/convr"
check "convergence, replay: the solved library's spectrum, St 0.185 +- 0.015, Cd's mode 10 Hz" \
    "grep -q 'library 0.1 .. 0.3 s played back with period 0.2 s, so its spectrum holds only multiples of 5 Hz' '$tmp/convr' && grep -q 'peak 30.0 +- 2.5 Hz (Strouhal number of the solved flow = 0.185, +- 0.015); lift Cl rms 0.00707, peak 60.0 Hz' '$tmp/convr' && grep -q \"the library holds 6 shedding periods (of the side force's peak); the slowest mode with 10 % of Cd's variance 10.0 Hz (St 0.062): the library holds 2 of its periods.\" '$tmp/convr'"
(cd "$c" && "$S" convergence --cloud c --gate off --window 0.2,0.4,0.6 --log log --file "$tmp/rs.md") > "$tmp/convn"
check "convergence, no replay: the forces' line, no line of the library" "grep -q '^Forces on the wedge' '$tmp/convn' && ! grep -q 'solved flow of the library' '$tmp/convn'"
rm -r "$c/postProcessing/forceCoeffs"
# parcelSplitting split the cloud's parcels: no Poisson error of equal-mass parcels
sed 's/^Evolving c$/Evolving c\nparcelSplitting c: 2 parcels split/' "$c/log" > "$c/log.split"
(cd "$c" && "$S" convergence --cloud c --window 0.2,0.4,0.6 --log log.split --file "$tmp/rs.md") > "$tmp/convs"
check "convergence: split parcels: n/a" "grep -qx '| nose | 100 | 36 | 3 | 2 | 4 | -67 % | n/a (split) |' '$tmp/convs'"
check "balance: split = yes" "(cd '$c' && '$S' balance --cloud c --log log.split) | grep -qx 'split = yes'"
# the y+ line of the latest yPlus table (the patches in the order of the table, the
# last row of each, the later time folder) and, with --threshold, the regions' head
mkdir -p "$c/postProcessing/yPlus/0" "$c/postProcessing/yPlus/0.35" "$c/postProcessing/yPlus/0.4"
printf '# Time patch min max average\n0.1 rear 1 2 3\n' > "$c/postProcessing/yPlus/0/yPlus.dat"
printf '# Time patch min max average\n0.1 rear 1 2 3\n' > "$c/postProcessing/yPlus/0.35/yPlus.dat"
printf '# Time\tpatch\tmin\tmax\taverage\n0.5\tnose\t0.5\t2.22222\t1\n0.5\trear\t0.1234\t9.87654\t3\n0.6\tnose\t0.25\t3\t1.5\nbad line\n' \
    > "$c/postProcessing/yPlus/0.4/yPlus.dat"
(cd "$c" && "$S" convergence --cloud c --window 0.2,0.4,0.6 --log log --file "$tmp/rs.md" --threshold 1.5e-3) > "$tmp/convy"
check "convergence: y+ of the latest table, per patch its last row, %.3g" \
    "grep -qx 'y+ of the first cells at t = 0.6 s (min / max / mean): nose 0.25 / 3 / 1.5; rear 0.123 / 9.88 / 3;' '$tmp/convy'"
check "convergence --threshold: the regions' head after the y+ line" \
    "[ \"\$(sed -n '/^y+ of/,\$p' '$tmp/convy' | sed -n 3p)\" = '## Rear-face regions' ] && grep -q '^Threshold 1.5e-3 kg/m2 (10 % of the window' '$tmp/convy' && [ \"\$(tail -1 '$tmp/convy')\" = '|---|---|---|---|---|---:|' ]"
check "convergence: no yPlus table, no y+ line; no --threshold, no regions' head" "! grep -q 'y+\|Rear-face regions' '$tmp/conv'"
rm -rf "$c/postProcessing/yPlus"

# a rear-face map: 2 x (B - A), rows of constant z, y increasing
printf '# x y z v\n0 1 0 1\n0 -1 0 1\n0 1 -1 2\n' > "$tmp/a.raw"
printf '# x y z v\n0 1 0 4\n0 -1 0 2\n0 1 -1 2\n' > "$tmp/b.raw"
"$S" rear-map --minus "$tmp/a.raw" --factor 2 "$tmp/b.raw" > "$tmp/map"
check "rear-map: 2 x (B - A) sorted by z then y" "[ \"\$(tr '\n' ' ' < '$tmp/map')\" = 'y,z,deposit_kg_m2 1,-1,0 -1,0,2 1,0,6 ' ]"
check "map-max: the largest value and 0.1 x it" "[ \"\$('$S' map-max --rel 0.1 '$tmp/map')\" = '6 0.6' ]"
printf '# x y z v\n0 1 0 4\n' > "$tmp/c.raw"
"$S" rear-map --name wedge-post --minus "$tmp/a.raw" "$tmp/c.raw" > /dev/null 2> "$tmp/err"; rc=$?
check "rear-map: maps of different faces: exit 1, named" "[ $rc = 1 ] && grep -q 'wedge-post: rear-face maps .*a.raw and .*c.raw differ' '$tmp/err'"

# the capture table: 10 um, St = 920 (1e-5)^2 / (18 1.641e-5) x 19.444 / 0.12 = 0.0505
r="$tmp/res"
mkdir -p "$r/d10um" "$r/d5um"
cp "$tmp/pp.csv" "$r/d10um/deposit_per_patch.csv"; cp "$tmp/mb" "$r/d10um/mass_balance.txt"
"$S" capture --results "$r" --sampled 0.5 --name wedge-capture > "$tmp/cap" 2> "$tmp/err"; rc=$?
check "capture: a diameter without results: exit 1, named" "[ $rc = 1 ] && grep -qx 'wedge-capture: missing results in $r/d5um' '$tmp/err'"
rm -r "$r/d5um"
"$S" capture --results "$r" --sampled 0.5 --gate off > "$tmp/cap"
check "capture: Stokes number, impacts, rear share 1e6 x 30 / (100 x 0.5)" \
    "grep -qx '| 10 | 0.0505 | 50 | 100 | 100 | 100 | 200 | 100 | 6e+05 |' '$tmp/cap'"

# the cost table: wall times of the solver log, errors of the window row and the classes
mkdir -p "$r/g" "$r/compose/mvd20"
cp "$tmp/mb" "$r/g/mass_balance.txt"
printf '| period | l | r | c | e | f |\n| window 0.2 .. 0.6 s | 1 +- 10 %% | 2 +- 20 %% | - | 4 +- 40 %% | 5 +- 5.5 %% |\n' > "$r/g/rear_statistics.md"
printf '| region | x | err |\n| left side | 1 | 3 %% |\n| whole face | 1 | - |\n## halves\n| edges | 1 | 9 %% |\n' > "$r/compose/mvd20/regions.md"
echo 'Wall time [s], largest of the processes: flow 100, kinematicCloud 20, kinematicCloud_d5um 1.5, kinematicCloud_d10um 2, kinematicCloud_x 7' > "$tmp/wlog"
"$S" cost --results "$r" --log "$tmp/wlog" --gate g --mvd 20 > "$tmp/cost"
check "cost: flow, plain and stratified rows" \
    "[ \"\$(tr '\n' ' ' < '$tmp/cost')\" = 'design,wall_s,face,left,right,centre,edges flow,100,,,,, plain,20,5.5,10,20,,40 stratified,3.5,,3,,, ' ]"
sed -i 's/^split = no/split = yes/' "$r/g/mass_balance.txt"
check "cost: a split main cloud is the splitting design" "'$S' cost --results '$r' --log '$tmp/wlog' --gate g --mvd 20 | grep -q '^splitting,20,5.5,'"

# gates, variant and dispersion tables: the same per-patch table twice
for g in off tangential shear regime rough; do mkdir -p "$r/$g"; cp "$tmp/pp.csv" "$r/$g/deposit_per_patch.csv"; done
"$S" gates --results "$r" > "$tmp/gates"
check "gates: deposit, sticks / impacts and the counts by reason per gate setting" \
    "grep -qx '| rear | 30 | 36 / 100 | 30 | 36 / 100 | 30 | 36 / 100 | 30 | 36 / 100 |' '$tmp/gates' && grep -qx '| rear | 36 / 55 / 4 / 0 / 5 | 36 / 55 / 4 / 0 / 5 | 36 / 55 / 4 / 0 / 5 | 36 / 55 / 4 / 0 / 5 |' '$tmp/gates'"
sed -i 's/^rear,0.5,30,/rear,0.5,45,/' "$r/rough/deposit_per_patch.csv"
"$S" variant --variant rough --results "$r" --gate off > "$tmp/var"
check "variant: the rear deposit 30 -> 45 kg: +50 %" "grep -qx '| rear | 30 | 36 / 100 | 45 | 36 / 100 | +50.0 % |' '$tmp/var'"
"$S" variant --variant soft --results "$r" --gate off > /dev/null 2>&1; rc=$?
check "variant: an unknown variant: exit 2" "[ $rc = 2 ]"
mkdir -p "$r/dispersion/crw"; cp "$r/rough/deposit_per_patch.csv" "$r/dispersion/crw/"
"$S" dispersion --results "$r" --main nw --others crw > "$tmp/disp"
check "dispersion: the main table (the first result folder holding one) against crw" "grep -qx '| rear | 30 | 36 / 100 | 45 | 36 / 100 |' '$tmp/disp'"
"$S" dispersion --name wedge-dispersion --results "$r" --main nw --others "crw nosuch" > /dev/null 2> "$tmp/err"; rc=$?
check "dispersion: a missing treatment: exit 1, named" "[ $rc = 1 ] && grep -qx 'wedge-dispersion: missing $r/dispersion/nosuch/deposit_per_patch.csv' '$tmp/err'"

(cd "$c" && "$S" deposit --cloud c --patch rear --window 0.2,0.6) > "$tmp/dep"
check "deposit: the rear face over the window, 3 digits" "[ \"\$(cat '$tmp/dep')\" = 30 ]"
(cd "$c" && "$S" deposit --name wedge-post --cloud d --patch rear) > /dev/null 2> "$tmp/err"; rc=$?
check "deposit: a cloud without a column: exit 1, named" "[ $rc = 1 ] && grep -q '^wedge-post: postProcessing/deposit_rear/0/surfaceFieldValue.dat has no column areaIntegrate(d:snowDeposit)' '$tmp/err'"
check "time-dir: the folder holding a file at a time" "[ \"\$('$S' time-dir --file reasons.dat --time 0.6 '$c/postProcessing/c:snowWall')\" = 0.6 ]"
"$S" capture --bogus 1 > /dev/null 2>&1; rc=$?
check "an unknown option: exit 2" "[ $rc = 2 ]"

# the fill's window reversed and its level out of (0, 1): refused naming them
"$S" fill --soi 0 --window 1,0 /dev/null > /dev/null 2> "$tmp/err"
check "fill --window 1,0: exit 2, T1 after T0" "[ $? -eq 2 ] && grep -q 'T1 must be after T0' '$tmp/err'"
"$S" fill --soi 0 --window 0,1 --level 2 /dev/null > /dev/null 2> "$tmp/err"
check "fill --level 2: exit 2 naming --level" "[ $? -eq 2 ] && grep -q -- '--level' '$tmp/err'"
finish
