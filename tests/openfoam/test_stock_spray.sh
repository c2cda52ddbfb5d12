#!/usr/bin/env bash
# test_stock_spray.sh - sprayFoam (basicSprayCloud) on Debian's stock tutorial
# lagrangian/sprayFoam/aachenBomb, shortened (to 0.5 ms; the mesh coarsened from
# 41 x 41 x 100 to 5 x 5 x 10 cells for the test's time) and changed only by the
# documented lines of doc/wallmodel.md (stock.sh). The n-dodecane spray evaporates
# before it reaches a wall (the stock model records no wall hit either): the model
# loads, the run ends, every wall hit is an impact, the deposit field is written, and
# the mass balance injected = airborne + escaped + deposited + phase change closes to
# 1e-6.
set -euo pipefail
# shellcheck source=common.sh
. "$(dirname "$0")/common.sh"
# shellcheck source=stock.sh
. "$(dirname "$0")/stock.sh"
[ -x /usr/bin/sprayFoam ] || { echo "SKIP: sprayFoam not installed"; exit 77; }

stock_copy lagrangian/sprayFoam/aachenBomb "$tmp/stock"
sed -i 's/(41 41 100)/(5 5 10)/' "$tmp/stock/system/blockMeshDict"
grep -q '(5 5 10)' "$tmp/stock/system/blockMeshDict" || fail "aachenBomb: mesh size line not found"
(cd "$tmp/stock" && run log.blockMesh blockMesh)
shorten "$tmp/stock" 5e-4
cp -r "$tmp/stock" "$tmp/snow"
count_hits "$tmp/stock/constant/sprayCloudProperties" "(walls)"
(cd "$tmp/stock" && run log.run sprayFoam)

dropin "$tmp/snow" sprayCloudProperties 'walls { type snow; }' '".*" { type none; }'
count_hits "$tmp/snow/constant/sprayCloudProperties" "(walls)"
(cd "$tmp/snow" && run log.run sprayFoam)
grep -q "snowWallInteraction: regime 'test fixture" "$tmp/snow/log.run" || fail "model not selected"
sh=$(hits "$tmp/stock" sprayCloud walls); nh=$(hits "$tmp/snow" sprayCloud walls)
ni=$(snow_counts "$tmp/snow/log.run" walls | cut -d' ' -f1)
[ "$ni" = "$nh" ] || fail "walls: $ni impacts, $nh hits"
if [ "$sh" -gt 0 ] && [ "$nh" = 0 ]; then fail "the stock case hits walls ($sh), the snow case not"; fi
[ -f "$tmp/snow/0.0005/sprayCloud:snowDeposit" ] || fail "no deposit field"
grep -q "Current number of parcels *= [1-9]" "$tmp/snow/log.run" || fail "no parcel injected"
check_balance "$tmp/snow/log.run" sprayCloud
echo "aachenBomb: stock hits on walls $sh, snow impacts $ni = hits $nh"
echo PASS
