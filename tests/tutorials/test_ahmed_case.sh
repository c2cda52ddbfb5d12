#!/usr/bin/env bash
# test_ahmed_case.sh - tutorials/ahmed end to end on its test level (Allrun
# -test, in a temporary copy; about 10 s on an idle machine): the surface written by
# snowbody is closed; the mesh passes checkMesh and has the body's patches with
# the sensor as its own wall patch on the rear face; snappyHexMesh added wall
# layers (the layer mesh has more cells than the snapped one, and the body's
# patches hold more than one of the two wanted layers on average); the drag
# coefficient and the base pressure are finite and plausible for this coarse
# mesh (0.15 < Cd < 1, the stilts add drag, the rear face under suction); the
# option refusals exit 2; Allclean restores the case. Skipped (77) without
# OpenFOAM's meshing tools and simpleFoam, or bin/snowbody.
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
for bad in "-bogus" "-iterations 5" "-iterations x" "-parallel 0" "-test -fine"; do
    # shellcheck disable=SC2086
    SNOWWALL_TOP="$top" "$c/Allrun" $bad > "$tmp/refuse.log" 2>&1
    rc=$?
    check "Allrun $bad refused (exit $rc)" [ "$rc" = 2 ]
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
check "a second run is refused until Allclean" bash -c "SNOWWALL_TOP='$top' '$c/Allrun' -test > /dev/null 2>&1; [ \$? = 1 ]"
"$c/Allclean"
(cd "$c" && find . -type f | sed 's|^\./||' | sort) > "$tmp/after"
check "Allclean restores the case" diff "$tmp/tracked" "$tmp/after"
[ "$fails" = 0 ] || { echo "$fails check(s) failed"; exit 1; }
echo "all checks passed"
