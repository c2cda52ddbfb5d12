#!/usr/bin/env bash
# test_wedge_compose.sh - post/wedge-compose on a synthetic per-class table with a
# known answer (no OpenFOAM): three classes (5, 10, 20 um) on a 2 x 2 rear map,
# class masses 1:2:1. Checks the composed map (sum_k w_k m_k per face), the
# composed region masses and their propagated errors (se^2 = sum (w_k M_k)^2 /
# n_eff_k), the class captures, the log-normal weights (sum to 1, the mass median
# class, the interpolated mass medians), the halves of the window composed and
# compared, the blocks of the composed map from the classes' records (and the older
# results without them), the bad inputs (exit 2, no output), and that a failed run
# leaves nothing.
set -u
top=${SW_TOP:?SW_TOP not set}
C="$top/tutorials/wedge/post/wedge-compose"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fails=0
check() { if eval "$2"; then echo "ok   $1"; else echo "FAIL $1"; fails=$((fails+1)); fi; }
near() { awk -v a="$1" -v b="$2" -v t="${3:-1e-6}" 'BEGIN { d = a - b; if (d < 0) d = -d; s = (b < 0 ? -b : b); exit !(d <= t * (s > 1e-30 ? s : 1)) }'; }

# class k: map values, injected mass, rear deposit, region (mass, n_eff) x 5
mk() {  # mk UM V1 V2 V3 V4 INJ DEP  LM LN RM RN CM CN EM EN WM WN
    local d="$tmp/res/d$1um"; mkdir -p "$d"
    printf 'y,z,deposit_kg_m2\n-1,-1,%s\n1,-1,%s\n-1,1,%s\n1,1,%s\n' "$2" "$3" "$4" "$5" > "$d/rear_deposit.csv"
    printf 'gate = off\ninjected = %s\n' "$6" > "$d/mass_balance.txt"
    printf 'patch,area_m2,deposit_kg,mean_kg_m2,impacts,sticks,bounces,ripoffs,logged_kg\nrear,1,%s,0,0,0,0,0,0\n' "$7" > "$d/deposit_per_patch.csv"
    cell() { if [ "$1" = 0 ]; then echo "0"; else echo "3 impacts, 3 origins, $1 kg, n_eff $2, +- 0 %"; fi; }
    printf '| period | left side | right side | centre | edges | whole face |\n|---|---|---|---|---|---|\n| window 0.15 .. 0.45 s | %s | %s | %s | %s | %s |\n' \
        "$(cell "$8" "$9")" "$(cell "${10}" "${11}")" "$(cell "${12}" "${13}")" "$(cell "${14}" "${15}")" "$(cell "${16}" "${17}")" > "$d/rear_statistics.md"
}
mk 5  4 0 2 2   2.0 0.4   0.1 4   0.2 16  0 0     0.1 25  0.4 100
mk 10 1 1 1 1   2.0 0.2   0.05 1  0.05 4  0.05 9  0.05 16 0.2 36
mk 20 0 0 0 8   2.0 0.1   0 0     0.1 1   0 0     0 0     0.1 4
printf '# class masses\n5,1\n10,2\n20,1\n' > "$tmp/masses.csv"
"$C" --results "$tmp/res" --out "$tmp/out" --masses "$tmp/masses.csv" > "$tmp/log" 2>&1
check "composition with --masses exits 0" "[ $? -eq 0 ]"
# the map: w = 0.25, 0.5, 0.25
want=(1.5 0.5 1.0 3.0)
got=($(awk -F, 'NR > 1 { print $3 }' "$tmp/out/rear_deposit.csv"))
for i in 0 1 2 3; do check "map face $i = ${want[$i]} (${got[$i]:-none})" "near '${got[$i]:-x}' '${want[$i]}'"; done
# regions: left 0.25*0.1 + 0.5*0.05 = 0.05, se^2 = (0.025^2)/4 + (0.025^2)/1
row() { awk -F'|' -v r="$1" '$2 ~ r { print $3, $4 }' "$tmp/out/regions.md"; }
read -r lm lerr <<< "$(row "left side")"
check "left side mass 0.05 ($lm)" "near '$lm' 0.05 1e-3"
lwant=$(awk 'BEGIN { printf "%.1f", 100 * sqrt(0.025^2 / 4 + 0.025^2 / 1) / 0.05 }')
check "left side error $lwant % (${lerr})" "[ '${lerr% %}' = '$lwant' ]"
read -r wm werr <<< "$(row "whole face")"
check "whole face 0.25*0.4 + 0.5*0.2 + 0.25*0.1 = 0.225 ($wm)" "near '$wm' 0.225 1e-3"
wwant=$(awk 'BEGIN { printf "%.1f", 100 * sqrt(0.1^2/100 + 0.1^2/36 + 0.025^2/4) / 0.225 }')
check "whole face error $wwant % (${werr})" "[ '${werr% %}' = '$wwant' ]"
read -r cm cerr <<< "$(row "centre")"
check "centre 0.5*0.05 = 0.025, error = 1/sqrt(9)" "near '$cm' 0.025 1e-3 && [ '${cerr% %}' = '33.3' ]"
# class captures: 1e6 dep / inj
check "capture of 5 um = 2e5 ppm" "grep -q '^| 5 | - | 0.25 | 2e+05 |' '$tmp/out/classes.md'"
check "rear deposit's median class is 10 um" "grep -q 'rear-face deposit 10 um' '$tmp/out/classes.md'"
# a log-normal spray: weights sum to 1; a very fine spray puts its median in the 5 um class
"$C" --results "$tmp/res" --out "$tmp/out2" --mvd 20 --sigma-g 1.8 > /dev/null 2>&1
check "log-normal MVD 20: exit 0" "[ $? -eq 0 ]"
check "log-normal MVD 20: weights sum to 1" "awk -F'|' '\$2 ~ /^ [0-9]/ { s += \$4 } END { exit !(s > 0.9999 && s < 1.0001) }' '$tmp/out2/classes.md'"
check "log-normal MVD 20: median class 20 um" "grep -q 'the spray 20 um' '$tmp/out2/classes.md'"
# interpolated: the spray's own median is 20 x 1.03 = 20.6 um (the truncation at 2 and
# 150 um moves it by less than 0.05 um); the deposit's lies inside its median class,
# 14.1 .. 154.5 um, and below the spray's (the finer classes capture more here)
mm=$(sed -n 's/.*(interpolated.*): the spray \([0-9.]*\) um, the rear-face deposit \([0-9.]*\) um\./\1 \2/p' "$tmp/out2/classes.md")
check "log-normal MVD 20: interpolated medians, spray 20.6 um, deposit in 14.1 .. 20.6 um ($mm)" \
    "echo '$mm' | awk '{ exit !(\$1 == 20.6 && \$2 > 14.1 && \$2 < 20.6) }'"
"$C" --results "$tmp/res" --out "$tmp/out3" --mvd 3 > /dev/null 2>&1
check "log-normal MVD 3: median class 5 um" "grep -q 'the spray 5 um' '$tmp/out3/classes.md'"
check "no halves rows: no halves table" "! grep -q 'halves of the sampling window' '$tmp/out/regions.md'"
# the halves: each class's statistics with a first and a second half (whole face
# 0.1 kg, n_eff 100 in every class; weights 1:2:1): composed x2 = 2 (0.25 + 0.5 +
# 0.25) 0.1 = 0.2 kg, error sqrt(sum (2 w_k 0.1)^2 / 100) = 0.0122 (6.1 %); equal
# halves agree (difference 0), a second half 3 times the first disagrees by
# 0.4 / sqrt(0.0122^2 + 0.0367^2) = 10.3 standard errors
halves() {  # halves DIR M1 M2: whole-face rows of the halves with masses M1, M2, n_eff 100
    local f
    for f in "$1"/d*um/rear_statistics.md; do
        printf '| first half 0.15 .. 0.3 s | 0 | 0 | 0 | 0 | 3 impacts, 3 origins, %s kg, n_eff 100, +- 10 %% |\n| second half 0.3 .. 0.45 s | 0 | 0 | 0 | 0 | 3 impacts, 3 origins, %s kg, n_eff 100, +- 10 %% |\n' "$2" "$3" >> "$f"
    done
}
cp -r "$tmp/res" "$tmp/resA"; halves "$tmp/resA" 0.1 0.1
"$C" --results "$tmp/resA" --out "$tmp/outA" --masses "$tmp/masses.csv" > /dev/null 2>&1
check "equal halves: agree, whole face 0.2 kg +- 6.1 % each (x2)" \
    "grep -q '^Halves: agree' '$tmp/outA/regions.md' && grep -q '^| whole face | 0.2 | 6.1 % | 0.2 | 6.1 % | +0.0 |' '$tmp/outA/regions.md'"
cp -r "$tmp/res" "$tmp/resB"; halves "$tmp/resB" 0.1 0.3
"$C" --results "$tmp/resB" --out "$tmp/outB" --masses "$tmp/masses.csv" > /dev/null 2>&1
check "second half 3x the first: disagree by +10.3 standard errors" \
    "grep -q '^Halves: \*\*disagree\*\* (1 of 1 regions' '$tmp/outB/regions.md' && grep -q '^| whole face | 0.2 | 6.1 % | 0.6 | 6.1 % | +10.3 |' '$tmp/outB/regions.md'"
# the blocks: without rear_records.csv (an older run) the per-face picture, said; with 16
# records per class on a 4 x 4 lattice (one origin each, mass 1) the face's error is
# sqrt(sum (w_k dep_k)^2 / 16) / 0.225 = 16.0 % and 2 x 2 blocks would have 31.9 %: one
# block of 0.225 kg / 16 m^2
check "no records: the per-face picture, said" "grep -q 'no rear_records.csv in every class' '$tmp/log' && [ ! -e '$tmp/out/rear_blocks.csv' ]"
cp -r "$tmp/res" "$tmp/resR"
for d in "$tmp"/resR/d*um; do
    { echo '# records'; echo 'y,z,mass_kg,origProc,origId'
      for i in $(seq 0 15); do echo "$(( i % 4 - 2 )).5,$(( i / 4 - 2 )).5,1,0,$i"; done; } > "$d/rear_records.csv"
done
"$C" --results "$tmp/resR" --out "$tmp/outR" --masses "$tmp/masses.csv" > "$tmp/logR" 2>&1
check "records: exit 0, one block of 16 %" "[ $? -eq 0 ] && grep -q '^blocks: 1 x 1 of 4 x 4 m, the finest of 1 .. 24 whose deposit-weighted rms error is <= 30 %: 16 %' '$tmp/logR'"
check "records: rear_blocks.csv holds the face's 0.225 kg on 16 m^2" \
    "awk -F, 'NR == 3 { exit !(\$1 == -2 && \$2 == 2 && \$5 == 0.0140625 && \$6 > 0.1595 && \$6 < 0.1597 && \$7 == 48) }' '$tmp/outR/rear_blocks.csv'"
command -v gnuplot > /dev/null || echo "skip records: the picture (no gnuplot)"
command -v gnuplot > /dev/null && check "records: the picture of the blocks" "[ \"\$(head -c 4 '$tmp/outR/rear_deposit.png' | tail -c 3)\" = PNG ]"
# fewer records: not even the whole face holds 30 %, said so
cp -r "$tmp/resR" "$tmp/resF"
for d in "$tmp"/resF/d*um; do sed -i '/,[4-9]$/d; /,1[0-5]$/d' "$d/rear_records.csv"; done
"$C" --results "$tmp/resF" --out "$tmp/outF" --masses "$tmp/masses.csv" > "$tmp/logF" 2>&1
check "4 records a class: one block, no grid within 30 %, said" "grep -q '^blocks: 1 x 1 of 4 x 4 m: no grid holds an error <= 30 %, the whole face.s is 32 %' '$tmp/logF' && grep -q '^# .*: no grid of 1 .. 24 holds' '$tmp/outF/rear_blocks.csv'"
# a class with a rear deposit and no record of it: exit 2, named, nothing written
cp -r "$tmp/resR" "$tmp/resE"; printf 'y,z,mass_kg,origProc,origId\n' > "$tmp/resE/d10um/rear_records.csv"
"$C" --results "$tmp/resE" --out "$tmp/outE" --masses "$tmp/masses.csv" > /dev/null 2> "$tmp/err"
check "a deposit without records: exit 2, named, nothing written" \
    "[ $? -eq 2 ] && grep -q 'd10um: a rear deposit of 0.2 kg but no record of it in rear_records.csv' '$tmp/err' && [ ! -e '$tmp/outE' ]"
printf 'y,z,mass_kg,origProc,origId\n0,0,nan,0,1\n' > "$tmp/resE/d10um/rear_records.csv"
"$C" --results "$tmp/resE" --out "$tmp/outE" --masses "$tmp/masses.csv" > /dev/null 2> "$tmp/err"
check "a record of mass nan: exit 2, file and line named" \
    "[ $? -eq 2 ] && grep -q 'd10um/rear_records.csv line 2: not y,z,mass_kg' '$tmp/err' && [ ! -e '$tmp/outE' ]"
printf 'y,z,mass_kg,origProc,origId\n0,0,1e-9,inf,1\n' > "$tmp/resE/d10um/rear_records.csv"
"$C" --results "$tmp/resE" --out "$tmp/outE" --masses "$tmp/masses.csv" > /dev/null 2> "$tmp/err"
check "a record of origin inf: exit 2, file and line named" \
    "[ $? -eq 2 ] && grep -q 'd10um/rear_records.csv line 2: not y,z,mass_kg' '$tmp/err' && [ ! -e '$tmp/outE' ]"
# bad inputs: exit 2, one line, nothing written
bad() {  # bad TEXT args...
    local want=$1; shift
    "$C" "$@" > /dev/null 2> "$tmp/err"; local rc=$?
    check "refused ($want): exit 2" "[ $rc -eq 2 ] && grep -qF -- '$want' '$tmp/err'"
}
bad "--mvd" --results "$tmp/res" --out "$tmp/bad" --mvd -3
bad "--sigma-g" --results "$tmp/res" --out "$tmp/bad" --mvd 20 --sigma-g 1
bad "--range" --results "$tmp/res" --out "$tmp/bad" --mvd 20 --range 150,2
bad "exclude" --results "$tmp/res" --out "$tmp/bad" --mvd 20 --masses "$tmp/masses.csv"
bad "--sampled" --results "$tmp/res" --out "$tmp/bad" --mvd 20 --sampled 0
bad "--out needs" --results "$tmp/res" --mvd 20 --out
printf '7,1\n' > "$tmp/m7.csv"
bad "line 1" --results "$tmp/res" --out "$tmp/bad" --masses "$tmp/m7.csv"
check "nothing written by the refusals" "[ ! -e '$tmp/bad' ] && [ -z \"\$(ls -A '$tmp' | grep '^\\.wedge-compose')\" ]"
rm "$tmp/res/d20um/rear_statistics.md"
"$C" --results "$tmp/res" --out "$tmp/bad" --mvd 20 > /dev/null 2>&1
check "a missing result: exit 1, nothing written" "[ $? -eq 1 ] && [ ! -e '$tmp/bad' ]"
[ "$fails" -eq 0 ] && { echo PASS; exit 0; } || { echo "$fails failure(s)"; exit 1; }
