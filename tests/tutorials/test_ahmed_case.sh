#!/usr/bin/env bash
# test_ahmed_case.sh - tutorials/ahmed end to end on its test level (Allrun
# -test, in a temporary copy; about 40 s on an idle machine): the surface written by
# snowbody is closed; the mesh passes checkMesh and has the body's patches with
# the sensor as its own wall patch on the rear face; snappyHexMesh added wall
# layers (the layer mesh has more cells than the snapped one, and the body's
# patches hold more than one of the two wanted layers on average); the drag
# coefficient and the base pressure are finite and plausible for this coarse
# mesh (0.15 < Cd < 1, the stilts add drag, the rear face under suction); the
# option refusals exit 2. The snow: the frozen flow scaled to the snow's speed
# (the solver's log), every body
# patch's deposit table and stick records (snow-post refuses records that do
# not add up to the deposit field), snow on the rear face and the nose, the
# results (snow.md's tables, the CSVs' rows, the two pictures as PNG), the run
# against the ladder refused for the test level, and -snow-only again on the
# same flow with another parcel count. Allclean restores the case. Skipped (77)
# without OpenFOAM's meshing tools and simpleFoam, or bin/snowbody.
set -u
top=${SW_TOP:?SW_TOP not set}
. "$top/etc/openfoam-env.sh" 2>/dev/null
for exe in blockMesh surfaceFeatureExtract snappyHexMesh checkMesh simpleFoam; do
    command -v "$exe" >/dev/null || { echo "$exe not found: skipped"; exit 77; }
done
[ -x "$top/bin/snowbody" ] || { echo "bin/snowbody missing (./Allwmake): skipped"; exit 77; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fails=0
check() {  # check DESCRIPTION COMMAND...: one line per check
    local what=$1; shift
    if "$@"; then echo "ok: $what"; else echo "FAIL: $what"; fails=$((fails + 1)); fi
}
(cd "$top/tutorials/ahmed" && git ls-files -co --exclude-standard . 2>/dev/null | sort) > "$tmp/tracked"
[ -s "$tmp/tracked" ] || (cd "$top/tutorials/ahmed" && find . -type f | sed 's|^\./||' | sort) > "$tmp/tracked"
c=$tmp/ahmed
mkdir -p "$c"
(cd "$top/tutorials/ahmed" && tar cf - -T "$tmp/tracked") | (cd "$c" && tar xf -)

# refusals first (no OpenFOAM work): exit 2, one line naming the option
for bad in "-bogus" "-iterations 5" "-iterations x" "-parallel 0" "-test -fine" "-parcels 0" "-parcels 1.5" \
           "-no-snow -snow-only" "-no-snow -parcels 3" "-snow-only -iterations 20" "-snow-only -test"; do
    # shellcheck disable=SC2086
    SNOWWALL_TOP="$top" "$c/Allrun" $bad > "$tmp/refuse.log" 2>&1
    rc=$?
    check "Allrun $bad refused (exit $rc)" [ "$rc" = 2 ]
done
# a bad constant/snowProperties is refused before any work, naming the entry
sp=$c/constant/snowProperties
cp "$sp" "$tmp/snowProperties"
for edit in 's/^sprayRate .*/sprayRate -1;/:sprayRate' 's/^speed .*/speed nan;/:speed' \
            's/^parcelsPerNozzle .*/parcelsPerNozzle 1e999;/:out of range' 's/^fillTime .*/fillTime 0.4;/:whole multiple'; do
    sed -i "${edit%%:*}" "$sp"
    SNOWWALL_TOP="$top" "$c/Allrun" -test > "$tmp/refuse.log" 2>&1
    rc=$?
    check "constant/snowProperties '${edit%%:*}' refused (exit $rc): $(head -c 120 "$tmp/refuse.log")" \
        bash -c "[ $rc = 2 ] && grep -q '${edit#*:}' '$tmp/refuse.log'"
    cp "$tmp/snowProperties" "$sp"
done
check "Allrun --help" bash -c "SNOWWALL_TOP='$top' '$c/Allrun' --help | grep -q '^Usage: tutorials/ahmed/Allrun'"
check "nothing written by the refusals" bash -c "[ \$(cd '$c' && find . -type f | wc -l) = \$(wc -l < '$tmp/tracked') ]"

t0=$(date +%s)
SNOWWALL_TOP="$top" "$c/Allrun" -test > "$tmp/allrun.log" 2>&1
rc=$?
echo "Allrun -test: exit $rc in $(( $(date +%s) - t0 )) s"
if [ "$rc" != 0 ]; then cat "$tmp/allrun.log"; echo "FAIL: Allrun -test"; exit 1; fi
f=$c/results/flow.txt
val() { awk -F' = ' -v k="$1" '$1 == k { print $2 }' "$f" | awk '{ print $1 }'; }
check "the surface is closed" bash -c "'$top/bin/snowbody' check --set cell=0.02 | grep -q '^open_edges = 0$'"
check "checkMesh: Mesh OK" grep -q '^Mesh OK' "$c/log.checkMesh"
b=$c/constant/polyMesh/boundary
sensor=$(awk '/^ *ahmed_sensor$/ { s = 1 } s && /type/ { t = $2 } s && /nFaces/ { n = $2 + 0; print t, n; exit }' "$b")
check "the sensor is its own wall patch with faces ($sensor)" bash -c "[ '${sensor%% *}' = 'wall;' ] && [ '${sensor##* }' -gt 0 ]"
for p in nose top bottom sides rear stilts; do
    check "patch ahmed_$p" grep -q "^ *ahmed_$p\$" "$b"
done
snapped=$(awk '/^Snapped mesh : cells:/ { sub("cells:", "", $4); print $4 }' "$c/log.snappyHexMesh")
layered=$(awk '/^Layer mesh : cells:/ { sub("cells:", "", $4); print $4 }' "$c/log.snappyHexMesh")
check "layers added: $snapped snapped cells -> $layered" bash -c "[ -n '$snapped' ] && [ -n '$layered' ] && [ '$layered' -gt '$snapped' ]"
lb=$(val layers_body_mean)
check "mean layers on the body $lb of 2 (> 1)" awk -v x="$lb" 'BEGIN { exit !(x > 1 && x <= 2) }'
ls=$(val layers_sensor)
check "layers on the sensor $ls (> 1)" awk -v x="$ls" 'BEGIN { exit !(x > 1) }'
cd_=$(val cd_body) cda=$(val cd_with_stilts) cpb=$(val cp_base) cps=$(val cp_sensor) it=$(val iterations)
check "60 iterations ($it)" [ "$it" = 60 ]
check "Cd $cd_ finite, in (0.15, 1)" awk -v x="$cd_" 'BEGIN { exit !(x == x + 0 && x > 0.15 && x < 1) }'
check "the stilts add drag ($cda > $cd_)" awk -v a="$cda" -v b="$cd_" 'BEGIN { exit !(a > b && a < b + 0.3) }'
check "the rear face under suction (Cp $cpb in (-1, 0))" awk -v x="$cpb" 'BEGIN { exit !(x > -1 && x < 0) }'
check "the sensor's Cp $cps in (-1, 0.2)" awk -v x="$cps" 'BEGIN { exit !(x > -1 && x < 0.2) }'
sh=$(val pressure_drag_share)
check "pressure drag share $sh in (0.5, 1)" awk -v x="$sh" 'BEGIN { exit !(x > 0.5 && x < 1) }'
check "results/flow.md states the published Cd" grep -q '| published Cd, square back (Ahmed, Ramm & Faltin 1984, as quoted: not yet checked against the paper) | 0.25 |' "$c/results/flow.md"
# the snow
sr=$c/results/snow
sl=$c/snow/log.snow
check "the snow run's flow scaled to 19.444 m/s" grep -q '^Frozen flow: U, phi x 0.32406' "$sl"
check "the snow's cost estimated before the run (1050 parcels)" grep -q 'snow: estimate: 1050 parcels, at most .* GB of memory' "$tmp/allrun.log"
check "k by the square of the scale" grep -q '^Frozen flow: k x 0.10501' "$sl"
check "omega and nut by the scale" bash -c "grep -q '^Frozen flow: omega x 0.32406' '$sl' && grep -q '^Frozen flow: nut x 0.32406' '$sl'"
check "every body patch has a deposit table" bash -c "[ \$(ls -d '$c'/snow/postProcessing/deposit_ahmed_* | wc -l) = 7 ]"
check "the stick records of the rear face" bash -c "ls '$c'/snow/postProcessing/lagrangian/kinematicCloud/snowWallSticks/*/ahmed_rear.post > /dev/null"
for f in snow.md summary.txt deposit.csv sensor.csv rear_map.csv rear_deposit.png sensor.png .snowwall-output; do
    check "results/snow/$f" test -s "$sr/$f"
done
for f in rear_deposit.png sensor.png; do
    check "$f is a PNG" bash -c "head -c 8 '$sr/$f' | od -An -c | grep -q 'P   N   G'"
done
sv() { awk -F' = ' -v k="$1" '$1 == k { print $2 }' "$sr/summary.txt"; }
rk=$(sv rear_kg_m2) rs=$(sv rear_sticks) nose=$(awk -F, '$1 == "ahmed_nose" { print $5 }' "$sr/deposit.csv")
check "snow on the rear face ($rk kg/m2, $rs sticks)" awk -v x="$rk" -v n="$rs" 'BEGIN { exit !(x > 0 && n > 0) }'
check "snow on the nose ($nose kg)" awk -v x="$nose" 'BEGIN { exit !(x > 0) }'
check "deposit.csv: 7 patches and the rear face" bash -c "[ \$(grep -c '^ahmed_' '$sr/deposit.csv') = 7 ] && grep -q '^rear_face,' '$sr/deposit.csv'"
check "sensor.csv: 31 rows from 0 to 30 minutes" bash -c "[ \$(tail -n +2 '$sr/sensor.csv' | wc -l) = 31 ] && tail -1 '$sr/sensor.csv' | grep -q '^30,'"
check "rear_map.csv: 16 x 12 bins" bash -c "[ \$(tail -n +2 '$sr/rear_map.csv' | wc -l) = 192 ]"
check "the test level is not on the ladder: sampling error only" grep -q "The level 'test' is not on the resolution ladder" "$sr/snow.md"
check "snow.md: the error against run time of the ladder" grep -q '^### The error against run time' "$sr/snow.md"
SNOWWALL_TOP="$top" "$c/Allrun" -test -snow-only -parcels 5 > "$tmp/again.log" 2>&1
rc=$?
check "Allrun -test -snow-only -parcels 5 on the same flow (exit $rc)" [ "$rc" = 0 ]
check "the second snow run with 5 parcels per nozzle" grep -q '5 parcels per nozzle x 42 nozzles' "$sr/snow.md"
mkdir -p "$c/snow2" && touch "$c/snow2/mine"
check "a snow/ Allrun did not write is refused" bash -c "cd '$c' && rm -rf snow && mv snow2 snow && SNOWWALL_TOP='$top' ./Allrun -test -snow-only > /dev/null 2>&1; [ \$? = 1 ] && [ -f snow/mine ]"
rm -rf "$c/snow"
check "a second run is refused until Allclean" bash -c "SNOWWALL_TOP='$top' '$c/Allrun' -test > /dev/null 2>&1; [ \$? = 1 ]"
"$c/Allclean"
(cd "$c" && find . -type f | sed 's|^\./||' | sort) > "$tmp/after"
check "Allclean restores the case" diff "$tmp/tracked" "$tmp/after"
[ "$fails" = 0 ] || { echo "$fails check(s) failed"; exit 1; }
echo "all checks passed"
