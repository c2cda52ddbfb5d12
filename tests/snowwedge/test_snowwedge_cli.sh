#!/usr/bin/env bash
# test_snowwedge_cli.sh - the snowwedge command (tools/snowwedge) on synthetic
# files with known answers: class weights of a log-normal spray placed
# symmetrically about its median, the composed map, the rear-face records'
# regions and effective sample size, the spectral peak of a sine in a
# forceCoeffs table, the probes' mean and rms; bad inputs exit 2 with one line
# naming the input.
# shellcheck source=common.sh
. "$(dirname "$0")/common.sh"

"$S" --help > "$tmp/help"; check "--help exits 0 with the synopsis" "[ $? -eq 0 ] && grep -q '^SYNOPSIS' '$tmp/help'"
# MVD 10 um, no freezing, droplets 2.5 .. 40 um: classes 5 and 20 um split at 10 um, half the mass each
"$S" weights --mvd 10 --freeze 1 --range 2.5,40 --classes 5,20 > "$tmp/w"
check "weights: 5 um 0.5 of 2.5 .. 10 um" "grep -qx '5 0.5 2.5 10' '$tmp/w'"
check "weights: 20 um 0.5 of 10 .. 40 um" "grep -qx '20 0.5 10 40' '$tmp/w'"
printf '# masses\n5,1\n\n20,3\n' > "$tmp/m.csv"
"$S" weights --masses "$tmp/m.csv" --classes 5,20 > "$tmp/wm"
check "weights --masses: 0.25, 0.75" "[ \"\$(cat '$tmp/wm')\" = \"\$(printf '5 0.25 nan nan\n20 0.75 nan nan')\" ]"
# the map: 0.25 x d5 + 0.75 x d20, the first map's order
mkdir -p "$tmp/d5um" "$tmp/d20um"
printf 'y,z,deposit_kg_m2\n-1,-1,4\n1,-1,0\n-1,1,8\n1,1,1\n' > "$tmp/d5um/m.csv"
printf 'y,z,deposit_kg_m2\n-1,-1,0\n1,-1,4\n-1,1,8\n1,1,3\n' > "$tmp/d20um/m.csv"
"$S" map --weights "$tmp/wm" "$tmp/d5um/m.csv" "$tmp/d20um/m.csv" > "$tmp/map"
check "map: 1, 3, 8, 2.5" "[ \"\$(tr '\n' ' ' < '$tmp/map')\" = '-1,-1,1 1,-1,3 -1,1,8 1,1,2.5 ' ]"
check "outline of a 2 x 2 map: the centres +- half a face" "[ \"\$('$S' outline '$tmp/d5um/m.csv')\" = '-2 2 -2 2' ]"
# records on the face -2..2 (u = (y + 2) / 4, v = (2 - z) / 4): origin 0:7 twice (1 + 1 kg) and
# 1:7 (2 kg) on the left side: n_eff = 4^2 / (2^2 + 2^2) = 2; one at the centre; one outside the window
d=$(awk 'BEGIN { printf "%.12g", (6 / 3.141592653589793) ^ (1 / 3) }')   # nParticle 1, rho 1: mass 1 kg
{
    echo '# Time (position0 position1 position2) origProc origId nParticle d rho'
    echo "0.5 (0.3 -1 0) 0 7 1 $d 1"
    echo "0.6 (0.3 -0.9 0.2) 0 7 1 $d 1"
    echo "0.7 (0.3 -0.8 -0.2) 1 7 2 $d 1"
    echo "0.7 (0.3 0 0) 0 8 1 $d 1"
    echo "0.9 (0.3 0 0) 0 9 1 $d 1"
} > "$tmp/rear.post"
"$S" rear-stats --label w --from 0.4 --to 0.8 --outline "$tmp/d5um/m.csv" --kind sticks "$tmp/rear.post" > "$tmp/row"
check "rear-stats: left side 3 records, 2 origins, 4 kg, n_eff 2" "grep -qF '| w | 3 sticks, 2 origins, 4 kg, n_eff 2.0, +- 71 % | 0 | 1 sticks, 1 origins, 1 kg, n_eff 1.0, +- 100 % | 0 | 4 sticks, 3 origins, 5 kg, n_eff 2.8, +- 60 % |' '$tmp/row'"
# a side force of 25 Hz on uneven steps over 0.2 .. 1 s
awk 'BEGIN { print "# Time Cd Cs Cl"; t = 0.1; for (i = 0; i < 4000; i++) { t += 2.5e-4 * (1 + 0.4 * sin(i)); if (t > 1) break
             printf "%.9g 0.5 %.9g %.9g\n", t, 0.3 * sin(2 * 3.141592653589793 * 25 * t), 0.1 * sin(2 * 3.141592653589793 * 62.5 * t) } }' > "$tmp/coef.dat"
"$S" forces --window 0.2,1 "$tmp/coef.dat" > "$tmp/f"
check "forces: mean Cd 0.5, Cs at 25.0 Hz (St 0.154), Cl at 62.5 Hz (on the grid 2/W + k/(4W))" "grep -q 'mean Cd 0.500; side force Cs rms 0.21[12], dominant frequency 25.0 Hz (Strouhal number f H/U = 0.154' '$tmp/f' && grep -q 'lift Cl rms 0.070[0-9]*, dominant frequency 62.5 Hz' '$tmp/f'"
printf '# Probe 0 (0.36 0 0)\n# Probe 1 (0.45 0 0)\n#  Probe 0 1\n#  Time\n' > "$tmp/U"
for t in 0.1 0.3 0.5 0.7; do echo "$t (1 0 0) (2 0 0)"; done >> "$tmp/U"
echo "0.9 (3 0 0) (2 0 0)" >> "$tmp/U"
"$S" probes --window 0.2,1 "$tmp/U" > "$tmp/p"
check "probes: 1.5 / 0.87 and 2 / 0" "grep -qF 'at (0.36 0 0) 1.50 / 0.87 m/s; at (0.45 0 0) 2.00 / 0.00 m/s;' '$tmp/p'"
# error against run time: 40 s at 20 % -> 160 s for 10 %, 1000 s at 2.5 % -> 62.5 s (5 % target: 250 s)
printf 'spray\tdefault\t40\t20\nclasses\t-full\t1000\t2.5\n' > "$tmp/pts"
"$S" errortime "$tmp/pts" > "$tmp/et"
check "errortime: 160 s and 62.5 s for 10 %" "[ \"\$(cat '$tmp/et')\" = \"\$(printf '| spray | default | 40 | 20.0 | 160 |\n| classes | -full | 1000 | 2.5 | 62.5 |')\" ]"
check "errortime --target 5: 250 s" "'$S' errortime --target 5 '$tmp/pts' | grep -qxF '| classes | -full | 1000 | 2.5 | 250 |'"
# refusals: exit 2, one line naming the input
bad() {  # bad TEXT args...
    local want=$1; shift
    "$S" "$@" > "$tmp/out" 2> "$tmp/err"; local rc=$?
    check "refused ($want): exit 2, one line" "[ $rc -eq 2 ] && [ \$(wc -l < '$tmp/err') -eq 1 ] && grep -qF -- '$want' '$tmp/err' && [ ! -s '$tmp/out' ]"
}
bad "unknown command" frobnicate
bad "sigma_g" weights --mvd 20 --sigma-g 1 --classes 5
bad "--mvd" weights --mvd abc --classes 5
bad "increasing" weights --mvd 20 --classes 20,5
bad "--masses line 2" weights --masses <(printf '5,1\n7,1\n') --classes 5,20
bad "--window" forces --window 1,0.2 "$tmp/coef.dat"
bad "unknown option" map --frob x
bad "--target" errortime --target 0 "$tmp/pts"
bad "tab-separated" errortime <(printf 'a b c d\n')
"$S" forces --window 0.2,1 "$tmp/nonexistent" > /dev/null 2> "$tmp/err"
check "an unreadable file: exit 1" "[ $? -eq 1 ] && grep -q 'cannot read' '$tmp/err'"
finish
