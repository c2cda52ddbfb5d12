#!/usr/bin/env bash
# test_wedge_case.sh - tutorials/wedge end to end on its coarsest variant
# (Allrun -test -compare, about 1-2 min on 2 cores) in a temporary copy:
#  * mass conservation for every gate setting (off, tangential, shear):
#      deposit field integral (surfaceFieldValue areaIntegrate over the wedge faces)
#      = logged deposited total (snowWall.dat of the wall model), relative to the
#        injected mass, within 1e-5;
#      logged total = injected - escaped (parcels through inlet/outlet, from
#        patchPostProcessing) - airborne (cloud mass at the end), within 1e-3;
#      injected = sprayRate x buildUpTime (30 min) within 1e-6;
#      rear-face map (raw per-face values x face area) = rear integral within 1e-4
#      (plus 1e-9 kg absolute);
#  * the rear-face PNG, the per-patch table and the 3-panel gate PNG are written;
#  * the shear gate computed the wall shear stress, the other settings did not;
#  * Allclean restores the case (no file left that the repository does not hold).
# With WEDGE_MODE=parallel (test_wedge_parallel.sh): Allrun -test -parallel 2, the
# gates-off run only, and the same checks for it plus the decomposition.
# Skipped (77) without OpenFOAM, bin/snowregime or libsnowWallInteraction.so.
set -u
mode=${WEDGE_MODE:-serial}
if [ "$mode" = parallel ]; then
    args=(-test -parallel 2); gates=off
else
    args=(-test -compare); gates="off tangential shear"
fi
top=${SW_TOP:?SW_TOP not set}
. "$top/etc/openfoam-env.sh" 2>/dev/null
command -v simpleFoam >/dev/null && command -v icoUncoupledKinematicParcelFoam >/dev/null ||
    { echo "OpenFOAM not found: skipped"; exit 77; }
[ -x "$top/bin/snowregime" ] && [ -x "$top/bin/snowphoto" ] || { echo "bin/snowregime or bin/snowphoto missing (./Allwmake): skipped"; exit 77; }
[ -f "$FOAM_USER_LIBBIN/libsnowWallInteraction.so" ] || { echo "libsnowWallInteraction.so missing: skipped"; exit 77; }
command -v gnuplot >/dev/null || { echo "gnuplot missing: skipped"; exit 77; }

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
# copy the case's source files only (tracked or not ignored), not a previous run's output
mkdir -p "$tmp/wedge"
if git -C "$top" rev-parse >/dev/null 2>&1; then
    (cd "$top/tutorials/wedge" && git ls-files -co --exclude-standard . | sort) > "$tmp/tracked"
else
    (cd "$top/tutorials/wedge" && ./Allclean >/dev/null && find . -type f | sed 's|^\./||' | sort) > "$tmp/tracked"
fi
(cd "$top/tutorials/wedge" && tar cf - -T "$tmp/tracked") | (cd "$tmp/wedge" && tar xf -)
fails=0
check() { if eval "$2"; then echo "ok   $1"; else echo "FAIL $1"; fails=$((fails+1)); fi; }
absle() { awk -v a="$1" -v t="$2" 'BEGIN{if (a<0) a=-a; exit !(a<=t)}'; }
val() { awk -v k="$1" '$1==k {print $3}' "$2"; }

start=$(date +%s)
SNOWWALL_TOP="$top" "$tmp/wedge/Allrun" "${args[@]}" > "$tmp/allrun.log" 2>&1
rc=$?
echo "Allrun ${args[*]}: exit $rc in $(( $(date +%s) - start )) s"
[ $rc = 0 ] || { tail -40 "$tmp/allrun.log"; exit 1; }
r="$tmp/wedge/results"

rate=$(. "$top/etc/openfoam-env.sh"; foamDictionary -entry sprayRate -value "$tmp/wedge/constant/sprayProperties")
tb=$(. "$top/etc/openfoam-env.sh"; foamDictionary -entry buildUpTime -value "$tmp/wedge/constant/sprayProperties")
for g in $gates; do
    mb="$r/$g/mass_balance.txt"
    check "$g: mass balance written" "[ -s '$mb' ]" || continue
    sed 's/^/     /' "$mb"
    inj=$(val injected "$mb"); esc=$(val escaped "$mb"); air=$(val airborne "$mb")
    logd=$(val deposited_logged "$mb"); fld=$(val deposited_field "$mb")
    check "$g: injected = sprayRate x buildUpTime" "absle \$(awk -v i=$inj -v r=$rate -v t=$tb 'BEGIN{print (i-r*t)/(r*t)}') 1e-6"
    check "$g: something deposited" "awk -v d=$logd 'BEGIN{exit !(d>0)}'"
    check "$g: field integral = logged total (1e-5 of injected)" "absle \$(awk -v a=$fld -v b=$logd -v i=$inj 'BEGIN{print (a-b)/i}') 1e-5"
    check "$g: logged = injected - escaped - airborne (1e-3)" "absle \$(awk -v l=$logd -v i=$inj -v e=$esc -v a=$air 'BEGIN{print (l-(i-e-a))/i}') 1e-3"
    rear_int=$(awk -F, '$1=="rear"{print $3}' "$r/$g/deposit_per_patch.csv")
    rear_area=$(awk -F, '$1=="rear"{print $2}' "$r/$g/deposit_per_patch.csv")
    map_int=$(awk -F, -v A="$rear_area" 'NR>1{s+=$3; n++} END{printf "%.10g", s*A/n}' "$r/$g/rear_deposit.csv")
    check "$g: rear map x face area = rear integral ($map_int vs $rear_int)" "absle \$(awk -v a=$map_int -v b=$rear_int 'BEGIN{print a-b}') \$(awk -v b=$rear_int 'BEGIN{print 1e-4*b+1e-9}')"
    check "$g: rear-face PNG" "[ \"\$(head -c 4 '$r/$g/rear_deposit.png' | tail -c 3)\" = PNG ]"
    check "$g: per-patch table lists the 6 wedge patches" "[ \$(grep -c -E '^\| (rear|nose|top|bottom|sideYneg|sideYpos) \|' '$r/$g/deposit_per_patch.md') = 6 ]"
done
check "main rear-face PNG and table" "[ -s '$r/rear_deposit.png' ] && [ -s '$r/deposit_per_patch.md' ]"
check "ParaView files" "[ -f '$tmp/wedge/case.foam' ] && ls '$tmp/wedge/VTK' >/dev/null 2>&1"
check "gates off computed no wallShearStress" "! ls '$tmp/wedge/'[0-9]*/wallShearStress >/dev/null 2>&1 && ! grep -q wallShearStress '$tmp/wedge/log.icoUncoupledKinematicParcelFoam'"
if [ "$mode" = parallel ]; then
    check "decomposed into 2 (simpleFoam and particles)" "grep -q 'Processor 1' '$tmp/wedge/log.decomposePar' && grep -q 'nProcs : 2' '$tmp/wedge/log.icoUncoupledKinematicParcelFoam'"
    check "reconstructed deposit field" "ls '$tmp/wedge/'0.*/kinematicCloud:snowDeposit >/dev/null 2>&1"
else
    check "gate comparison PNG" "[ \"\$(head -c 4 '$r/gates_compare.png' | tail -c 3)\" = PNG ]"
    check "regions table has 3 gate rows" "[ \$(grep -c -E '^\| (off|tangential|shear) \|' '$r/regions.md') = 3 ]"
    check "shear gate computed wallShearStress" "ls '$tmp/wedge/gates/shear/'*/wallShearStress >/dev/null 2>&1"
fi
"$tmp/wedge/Allclean"
(cd "$tmp/wedge" && find . -type f | sed 's|^\./||' | sort > "$tmp/after")
check "Allclean restores the case" "diff '$tmp/tracked' '$tmp/after'"

[ "$fails" = 0 ] || { echo "$fails check(s) failed"; exit 1; }
echo "all checks passed"
