#!/usr/bin/env bash
# test_stock_rebuilt.sh - the stock solvers rebuilt with -D__restrict__= by the opt-in
# `etc/setup.sh --stock-solvers MPPICFoam,reactingParcelFoam`, on the
# stock tutorials that Debian's own build of these solvers cannot run (doc/wallmodel.md,
# "Stock solvers rebuilt"). Skipped (77) unless platforms/bin holds MPPICFoam built by the
# opt-in, so it is not part of a default run; the verticalChannel part is skipped, with a
# notice, when reactingParcelFoam was not rebuilt.
# 1. the solver found on PATH (etc/openfoam-env.sh) is the rebuilt one;
# 2. MPPICFoam injectionChannel (672 cells on which Debian's build reconstructs wrongly)
#    with snowWallInteraction on `walls` (doc/wallmodel.md's lines), to 0.01 s (100 steps):
#    the run ends, the Courant number stays below 10 (Debian's build: 1e24 at step 3),
#    every wall hit is one impact, impacts, sticks and bounces > 0, the deposit field is
#    written, the mass balance closes to 1e-6;
# 3. reactingParcelFoam verticalChannel (1050 such cells; Debian's build stops in step 2
#    in heRhoThermo::correct) with snowWallInteraction on `walls`, started as its Allrun
#    does (potentialFoam), to 0.012 s (about 40 adaptive steps; parcels are injected from
#    0.01 s at 40 m/s and reach the walls within a step or two): the run ends, parcels are
#    in the cloud, every wall hit is one impact, impacts and bounces > 0 (the fixture
#    regime bounces these fast droplets), the mass balance (with evaporation) closes to 1e-6.
set -euo pipefail
# shellcheck source=common.sh
. "$(dirname "$0")/common.sh"
# shellcheck source=stock.sh
. "$(dirname "$0")/stock.sh"
bin="$top/platforms/bin"
rebuilt() { [ -x "$bin/$1" ] && grep -qx -- '-D__restrict__=' "$bin/.$1.stock" 2>/dev/null; }
rebuilt MPPICFoam || {
    echo "SKIP: $bin/MPPICFoam not rebuilt (opt-in: etc/setup.sh --stock-solvers MPPICFoam,reactingParcelFoam)"
    exit 77
}

# 1. PATH
[ "$(command -v MPPICFoam)" = "$bin/MPPICFoam" ] \
    || fail "MPPICFoam on PATH is $(command -v MPPICFoam), not $bin/MPPICFoam"

# 2. injectionChannel
c="$tmp/channel"
stock_copy lagrangian/MPPICFoam/injectionChannel "$c"
(cd "$c" && run log.blockMesh blockMesh)
shorten "$c" 0.01
count_hits "$c/constant/kinematicCloudProperties" "(walls)"
dropin "$c" kinematicCloudProperties 'walls { type snow; }' '".*" { type none; }'
(cd "$c" && run log.run MPPICFoam)
grep -q "snowWallInteraction: regime 'test fixture" "$c/log.run" || fail "injectionChannel: model not selected"
[ "$(grep -c '^Time = ' "$c/log.run")" = 100 ] || fail "injectionChannel: $(grep -c '^Time = ' "$c/log.run") steps, expected 100"
co=$(awk '/^Courant Number/ { if ($NF > m) m = $NF } END { print m + 0 }' "$c/log.run")
awk -v c="$co" 'BEGIN { exit !(c < 10) }' || fail "injectionChannel: Courant number up to $co"
read -r ni ns nb nr <<< "$(snow_counts "$c/log.run" walls)"
h=$(hits "$c" kinematicCloud walls)
[ "$ni" = "$h" ] || fail "injectionChannel: $ni impacts but $h wall hits"
[ "$ni" -gt 0 ] && [ "$ns" -gt 0 ] && [ "$nb" -gt 0 ] || fail "injectionChannel: impacts/sticks/bounces $ni/$ns/$nb"
[ -f "$c/0.01/kinematicCloud:snowDeposit" ] || fail "injectionChannel: no deposit field"
echo "injectionChannel to 0.01 s: max Courant $co; walls impacts/sticks/bounces/ripoffs $ni/$ns/$nb/$nr = wall hits $h"
check_balance "$c/log.run" kinematicCloud

# 3. verticalChannel
if ! rebuilt reactingParcelFoam; then
    echo "notice: $bin/reactingParcelFoam not rebuilt: verticalChannel not run"
    echo PASS
    exit 0
fi
[ "$(command -v reactingParcelFoam)" = "$bin/reactingParcelFoam" ] \
    || fail "reactingParcelFoam on PATH is $(command -v reactingParcelFoam), not $bin/reactingParcelFoam"
v="$tmp/vertical"
stock_copy lagrangian/reactingParcelFoam/verticalChannel "$v"
(cd "$v" && run log.blockMesh blockMesh && cp -r 0.orig 0 && run log.potentialFoam potentialFoam)
shorten "$v" 0.012
count_hits "$v/constant/reactingCloud1Properties" "(walls)"
dropin "$v" reactingCloud1Properties 'walls { type snow; }' '".*" { type none; }'
(cd "$v" && run log.run reactingParcelFoam)
grep -q "snowWallInteraction: regime 'test fixture" "$v/log.run" || fail "verticalChannel: model not selected"
np=$(grep "Current number of parcels" "$v/log.run" | tail -1 | awk '{print $NF}')
[ "${np:-0}" -gt 0 ] || fail "verticalChannel: no parcel in the cloud"
read -r ni ns nb nr <<< "$(snow_counts "$v/log.run" walls)"
h=$(hits "$v" reactingCloud1 walls)
[ "$ni" = "$h" ] || fail "verticalChannel: $ni impacts but $h wall hits"
[ "$ni" -gt 0 ] && [ "$nb" -gt 0 ] || fail "verticalChannel: impacts/sticks/bounces $ni/$ns/$nb"
echo "verticalChannel to 0.012 s: $(grep -c '^Time = ' "$v/log.run") steps, $np parcels; walls impacts/sticks/bounces/ripoffs $ni/$ns/$nb/$nr = wall hits $h"
check_balance "$v/log.run" reactingCloud1
echo PASS
