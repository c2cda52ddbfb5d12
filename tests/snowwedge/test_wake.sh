#!/usr/bin/env bash
# test_wake.sh - validation/wake.sh on a synthetic run with known answers: Cd 0.4 with
# a sine of 8 Hz and amplitude 0.02, Cs a sine of 32 Hz, Cp_b -0.35 with the drag's
# sine; over 0.1 .. 0.6 s: St of the 32 Hz peak (32 x 0.12 / 19.444 = 0.197), the
# means, the slowest mode 8 Hz; the spread of library means: 0 for windows of one
# period (0.125 s), 0.02 x 2 / pi for half periods from a zero crossing; bad usage and
# a missing table.
. "$(dirname "$0")/common.sh"
W="$top/validation/wake.sh"
r="$tmp/run"
mkdir -p "$r/postProcessing/forceCoeffs/0" "$r/postProcessing/basePressure/0" "$r/postProcessing/inletPressure/0"
awk -v F="$r/postProcessing/forceCoeffs/0/coefficient.dat" -v B="$r/postProcessing/basePressure/0/surfaceFieldValue.dat" \
    -v I="$r/postProcessing/inletPressure/0/surfaceFieldValue.dat" 'BEGIN { pi = atan2(0, -1); q = 0.5 * 19.444^2
    print "# Time Cd Cs Cl" > F; print "# Time areaAverage(p)" > B; print "# Time areaAverage(p)" > I
    for (i = 1; i <= 6000; i++) { t = i * 1e-4; s = sin(2 * pi * 8 * t)
        printf "%.6g %.10g %.10g 0\n", t, 0.4 + 0.02 * s, 0.03 * sin(2 * pi * 32 * t) > F
        printf "%.6g %.10g\n", t, (-0.35 + 0.02 * s) * q + 3 > B; printf "%.6g 3\n", t > I } }'
"$W" --library 0.125 "$r" > "$tmp/o" 2> "$tmp/e"
check "wake: exit 0, a header and one row" "[ \$? = 0 ] && [ \$(wc -l < '$tmp/o') = 3 ]"
row=$(tail -1 "$tmp/o")
check "wake: the record 0.1 .. 0.6, St 0.197 of the 32 Hz peak, Cd 0.4, Cp_b -0.35 ($row)" \
    "echo '$row' | grep -q '^| run | 0.1 .. 0.6 | [0-9.]* | 0.197 +- 0.0[0-9]* | 0.4000 | -0.3500 | 8.0 (0.049) | 8.0 (0.049) | 0.0000, 0.0000 (4 windows) |$'"
"$W" --library 0.0625 --from 0.125 --to 0.5 "$r" | tail -1 > "$tmp/o2"
check "wake: half-period windows from a zero crossing, the spread 0.02 x 2 / pi = 0.0127" "grep -q '| 0.0127, 0.0127 (6 windows) |\$' '$tmp/o2'"
"$W" --library 0.5 "$r" | tail -1 > "$tmp/o3"
check "wake: one window, no spread" "grep -q '| - (fewer than 2 windows) |$' '$tmp/o3'"
"$W" --bogus "$r" > /dev/null 2> "$tmp/e"; rc=$?
check "wake: an unknown option, exit 2, named" "[ $rc = 2 ] && grep -q \"unknown option '--bogus'\" '$tmp/e'"
"$W" --library x "$r" > /dev/null 2> "$tmp/e"; rc=$?
check "wake: --library x, exit 2" "[ $rc = 2 ] && grep -q \"library needs a positive number, got 'x'\" '$tmp/e'"
rm "$r/postProcessing/inletPressure/0/surfaceFieldValue.dat"
"$W" "$r" > "$tmp/o" 2> "$tmp/e"; rc=$?
check "wake: a missing table, exit 1, named, nothing printed" "[ $rc = 1 ] && grep -q 'inletPressure/0/surfaceFieldValue.dat missing' '$tmp/e' && [ ! -s '$tmp/o' ]"
finish
