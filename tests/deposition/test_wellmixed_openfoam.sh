#!/usr/bin/env bash
# test_wellmixed_openfoam.sh - the tracer-limit check, short: the channel's flow
# on the wall-function mesh (validation/deposition.sh, a few parcels only for its
# flow, about 10 s), then validation/wellmixed.sh on it with the mean flow alone,
# snowNearWall's walk with its default scale and with u* from the k at the
# parcel alone, and OpenFOAM's stochasticDispersionRAS, 4000 tracers each over
# 10 outer Lagrangian times (about 1 min). Checks: the walk's two scales keep
# every y+ band within 10 % of uniform or three binomial standard errors (the
# walk whose drift took u* as fixed, with k a step per cell, piled tracers up
# 6-37 times in such bands), the mean flow alone too, the stochastic model
# fails at least one band (the check can fail), a --zone's rows, the table and
# plot written, a release denser next to the walls (--wall-release: the band y+ 0-1,
# judged; the same on 2 processes), the refusals of bad options (exit 2, nothing written) and of
# bad wellMixedCheck entries (a FatalIOError naming the key).
# The tracking: the ribbed channel's wall-function mesh (validation/rib.sh, its
# flow, about 15 s), the mean flow alone with 4000 tracers over 3 outer
# Lagrangian times, the parcels' velocity interpolated cellPoint (OpenFOAM's:
# tracers pile up at its walls, 11 times the uniform share within y+ 1) and
# faceFlux (from the face fluxes: every band within 10 % or three standard
# errors). Skipped (77) without
# OpenFOAM, the project's solver and wrapper, bin/snowdeposit or gnuplot.
# shellcheck source=openfoam_test.sh
. "$(dirname "$0")/openfoam_test.sh"
[ -x "$top/bin/snowdeposit" ] || { echo "bin/snowdeposit missing: skipped"; exit 77; }

"$top/validation/deposition.sh" --out "$tmp/dep" --mesh wf --models none --tau-plus 10 --parcels 10 --t-run 100 > "$tmp/log.dep" 2>&1
check "the channel's flow (deposition.sh) exits 0" "[ $? -eq 0 ]"
case_dir="$tmp/dep/wf/case"
"$top/validation/wellmixed.sh" --case "$case_dir" --walls "(walls)" --dt 5.4e-5 --out "$tmp/wm" \
    --models none,crw,crw-k,stochastic --parcels 4000 --zone "core:0,0.005,0:0.0127,0.0077,0.0127" > "$tmp/log" 2>&1
rc=$?
cat "$tmp/log"
check "wellmixed.sh exits 0" "[ $rc -eq 0 ]"
csv="$tmp/wm/wellmixed.csv"
check "wellmixed.csv, .md, .png written" "[ -s '$csv' ] && [ -s '$tmp/wm/wellmixed.md' ] && [ -s '$tmp/wm/wellmixed.png' ]"
for m in none crw crw-k; do
    check "$m: five bands" "[ \"\$(awk -F, -v m=$m '\$1 == m && \$2 == \"all\"' '$csv' | wc -l)\" -eq 5 ]"
    # the rows with volume (a zone's bands beyond its walls are empty)
    # within 10 % or three binomial standard errors (two, the check's own verdict,
    # fails one band in twenty by chance alone: too often for a suite of 15 bands)
    check "$m: every band within 10 % or 3 standard errors" \
        "! awk -F, -v m=$m '\$1 == m && \$6 > 0 && (\$9 - 1 > 0.1 || 1 - \$9 > 0.1) && (\$9 - 1 > 3 * \$10 || 1 - \$9 > 3 * \$10)' '$csv' | grep -q ."
    check "$m: bands from y+ 5 on within 10 %" \
        "! awk -F, -v m=$m '\$1 == m && \$6 > 0 && \$4 >= 5 && (\$9 < 0.9 || \$9 > 1.1)' '$csv' | grep -q ."
done
check "the zone 'core' has its rows, the walk's well mixed there" \
    "[ \"\$(awk -F, '\$1 == \"crw\" && \$2 == \"core\"' '$csv' | wc -l)\" -eq 6 ] && awk -F, '\$1 == \"crw\" && \$2 == \"core\" && \$3 == \"whole\" { exit !(\$9 > 0.9 && \$9 < 1.1) }' '$csv'"
check "stochasticDispersionRAS fails a band (the check can fail)" "awk -F, '\$1 == \"stochastic\" && \$12 == \"FAIL\"' '$csv' | grep -q ."
# a release denser next to the walls (--wall-release 20:1: the wall cells 20 times the
# parcels, the others 20 times as heavy): the mean flow keeps the weighted concentration
# uniform, and the thin band y+ 0-1 (0.3 % of the volume, "few" with 1000 plain
# parcels: +-0.56) is judged with an error under 0.2
"$top/validation/wellmixed.sh" --case "$case_dir" --walls "(walls)" --dt 5.4e-5 --out "$tmp/wr" \
    --models none --parcels 1000 --tl-multiple 2 --wall-release 20:1 > "$tmp/log.wr" 2>&1
check "--wall-release 20:1 exits 0, the check weighs the parcels" \
    "[ $? -eq 0 ] && grep -q 'weighted by nParticle' \$(ls -d '$tmp'/wr/case/postProcessing/lagrangian/t_none/wellMixed/*/wellMixed.dat | sort -V | tail -1)"
check "--wall-release: every band within 10 % or 3 standard errors, y+ 0-1 judged with se < 0.2" \
    "awk -F, '\$1 == \"none\" && \$2 == \"all\" { n++; d = \$9 - 1; if (d < 0) d = -d; if (!(d <= 0.1 || d <= 3 * \$10)) bad++; if (\$4 == 0 && !(\$10 < 0.2 && \$12 == \"ok\")) bad++ } END { exit !(n == 5 && !bad) }' '$tmp/wr/wellmixed.csv'"
# the same cloud function on 2 processes (decomposePar + mpirun): its summary reduced on
# every processor (a reduce after the master's own return once waited for ever), the
# same parcels counted
wr_case="$tmp/wr/case"
printf 'FoamFile { version 2.0; format ascii; class dictionary; object decomposeParDict; }\nnumberOfSubdomains 2;\nmethod simple;\ncoeffs { n (1 2 1); }\n' \
    > "$wr_case/system/decomposeParDict"
(cd "$wr_case" && rm -rf postProcessing && decomposePar -force > log.decomposePar 2>&1 &&
    timeout 300 mpirun -np 2 --oversubscribe pimpleUncoupledKinematicParcelFoam -parallel -frozen -clouds "(t_none)" \
    > log.parallel 2>&1)
check "--wall-release on 2 processes: the run ends, the summary as in serial" \
    "[ $? -eq 0 ] && grep -q '^End' '$wr_case/log.parallel' && [ \"\$(grep -o 'mean parcels [0-9]*' '$wr_case/log.parallel' | tail -1)\" = \"\$(grep -o 'mean parcels [0-9]*' '$wr_case/log.particles' | tail -1)\" ]"
# refusals: exit 2, nothing written
check "faceFlux took the velocity of every cell from the six fluxes (a channel of cuboids)" "grep -q 'faceFlux: \([0-9]*\) of \1 cells are parallelepipeds' '$tmp/wm/case/log.particles'"
for bad in "--walls walls" "--walls (nonesuch)" "--walls (left)" "--dt 0" "--dt abc" "--parcels 0" "--tl-multiple 1" "--models none,bogus" "--zone x:1,2:3,4,5" "--d 1" \
    "--interpolation cell" "--inlet nonesuch" "--inlet left" "--inlet" "--wall-release 1" "--wall-release 5:0" \
    "--wall-release 5:x" "--wall-release"; do
    # shellcheck disable=SC2086
    "$top/validation/wellmixed.sh" --case "$case_dir" --walls "(walls)" --dt 5.4e-5 --out "$tmp/bad" $bad > "$tmp/log.bad" 2>&1
    rc=$?
    check "refused: $bad (exit 2, nothing written; $(head -1 "$tmp/log.bad"))" "[ $rc -eq 2 ] && [ ! -e '$tmp/bad' ]"
done
# the cloud function's own refusals: a FatalIOError naming the key and value
wm_case="$tmp/wm/case"
props="$wm_case/constant/t_crwProperties"
cp "$props" "$tmp/props.orig"
bad_dict() {   # replacement of the wellMixed entry, expected message
    sed "s|wellMixed { type wellMixedCheck;[^}]*}|wellMixed { type wellMixedCheck; $1 }|" "$tmp/props.orig" > "$props"
    (cd "$wm_case" && timeout 120 pimpleUncoupledKinematicParcelFoam -frozen -clouds "(t_crw)" > "$tmp/log.dict" 2>&1)
    local rc=$?
    check "wellMixedCheck refuses $1 (exit $rc)" "[ $rc -ne 0 ] && [ $rc -ne 124 ] && grep -q 'FOAM FATAL' '$tmp/log.dict' && grep -qF -- \"$2\" '$tmp/log.dict'"
}
bad_dict "patches (walls); bands (0 5 1);" "bands"
bad_dict "patches (walls); bands (1 5);" "must start at 0"
bad_dict "patches (walls); zones (nonesuch);" "no cell zone 'nonesuch'"
bad_dict "patches (walls); samplesPerCell 0;" "samplesPerCell 0 is outside"
bad_dict "patches (walls); samplesPerCell -3;" "samplesPerCell -3 is outside"
bad_dict "patches (walls); totalSamples 1e12;" "totalSamples 1e+12 is outside"
bad_dict "patches (walls); Cmu nan;" "wellMixed.Cmu"
bad_dict "patches (walls); Cmu 2;" "Cmu = 2"
bad_dict "patches (walls); band (0 1);" "unknown key 'band'"
bad_dict "patches (wal);" "'wal' matches no patch"
bad_dict "patches (left);" "is a cyclic patch, not a wall"
bad_dict "bands (0 1);" "patches"
bad_dict "patches (walls); startTime;" "startTime"
cp "$tmp/props.orig" "$props"
"$top/validation/wellmixed.sh" --case "$tmp/nonesuch" --walls "(walls)" --dt 5.4e-5 --out "$tmp/bad" > "$tmp/log.bad" 2>&1
check "refused: a case without a mesh" "[ $? -eq 2 ] && [ ! -e '$tmp/bad' ] && grep -q nonesuch '$tmp/log.bad'"

# the tracking on the ribbed channel's wall-function mesh: cellPoint fails, faceFlux holds
"$top/validation/rib.sh" --out "$tmp/rib" --mesh wf --models none --tau-plus 10 --parcels 10 --t-run 1000 > "$tmp/log.rib" 2>&1
check "the ribbed channel's flow (rib.sh) exits 0" "[ $? -eq 0 ]"
for interp in cellPoint faceFlux; do
    "$top/validation/wellmixed.sh" --case "$tmp/rib/wf/case" --dt 6.5e-5 --parcels 4000 --tl-multiple 3 --models none \
        --walls "(top floorUp ribFront ribTop ribBack floor_0 floor_1 floor_2 floor_3 floor_4 floor_5)" \
        --interpolation $interp --out "$tmp/rib-$interp" > "$tmp/log.rib-$interp" 2>&1
    rc=$?
    grep '| none | all |' "$tmp/rib-$interp/wellmixed.md"
    check "rib, $interp: wellmixed.sh exits 0" "[ $rc -eq 0 ]"
done
rcsv="$tmp/rib-cellPoint/wellmixed.csv"
check "rib, cellPoint: the mean flow piles tracers up within y+ 1 (over 3 times uniform)" \
    "awk -F, '\$1 == \"none\" && \$2 == \"all\" && \$4 == 0 { exit !(\$9 > 3) }' '$rcsv'"
rcsv="$tmp/rib-faceFlux/wellmixed.csv"
check "rib, faceFlux: every band within 10 % or 3 standard errors" \
    "[ \"\$(awk -F, '\$1 == \"none\" && \$2 == \"all\"' '$rcsv' | wc -l)\" -eq 5 ] && ! awk -F, '\$1 == \"none\" && \$6 > 0 && (\$9 - 1 > 0.1 || 1 - \$9 > 0.1) && (\$9 - 1 > 3 * \$10 || 1 - \$9 > 3 * \$10)' '$rcsv' | grep -q ."
[ "$fails" -eq 0 ] && { echo PASS; exit 0; } || { echo "$fails failure(s)"; exit 1; }
