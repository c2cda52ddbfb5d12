#!/usr/bin/env bash
# snowregime on a rough wall: collide and vcrit with --set wall=lattice,
# the probability map with its contours and regime.coeffs (read back by the wall
# model, rough_check), thread invariance, and the errors of the rough options.
. "$(dirname "$0")/common.sh"
RC=$SW_BUILD/tests/regime_cli/rough_check
L="--set wall=lattice"
# one impact: the impact point and the contacts are reported
"$SR" collide --d 10e-6 --vn 2 $L --x 0.5e-6 --y 0.2e-6 >"$WORK/c.txt" || fail "collide exit $?"
grep -q "^contacts: [1-9]" "$WORK/c.txt" || fail "collide: no contacts line"
grep -q "^x: 5e-07" "$WORK/c.txt" || fail "collide: no impact point"
# head-on on an asperity's top, elastic: v_crit is V_s of R* = R r/(R + r)
"$SR" vcrit --d 20e-6 $L --set cor=elastic --points 1 --vmin 1e-3 --vmax 1 --tol 1e-4 >"$WORK/v1.txt" 2>&1 || fail "vcrit exit $?"
# points 1 draws one random point; the centre is checked in tests/kernel (test_kernel_rough)
grep -q "^# rough wall: v_crit is where the stick fraction over 1 impact points" "$WORK/v1.txt" || fail "vcrit: no rough-wall note"
# the p = 0.5 speed falls below the flat wall's
vf=$("$SR" vcrit --d 20e-6 | awk '!/^#/ { print $2 }')
vr=$("$SR" vcrit --d 20e-6 $L --points 16 | awk '!/^#/ { print $2 }')
fcmp "$vr" "<" "$vf" || fail "rough v_crit $vr not below flat $vf"
# the probability map, on 1 and 2 threads
for t in 1 2; do
    "$SR" map $L --nd 8 --nv 10 --points 12 --seed 3 --threads $t --out "$WORK/m$t" >"$WORK/m$t.log" 2>&1 \
        || { cat "$WORK/m$t.log"; fail "map --threads $t exit $?"; }
done
for f in map.csv contours.csv interface.csv regime.coeffs fit.txt; do
    [ -s "$WORK/m1/$f" ] || fail "map: no $f"
    [ "$f" = fit.txt ] || cmp -s "$WORK/m1/$f" "$WORK/m2/$f" || fail "map: $f differs between 1 and 2 threads"
done
[ -s "$WORK/m1/map.png" ] || fail "map: no map.png"
grep -q "^d_m,.*,p_stick,p_err,points" "$WORK/m1/map.csv" || fail "map.csv: no probability columns"
for lv in 0.1 0.5 0.9; do grep -q "^$lv," "$WORK/m1/contours.csv" || fail "contours.csv: no p = $lv contour"; done
grep -q "probabilityStick" "$WORK/m1/regime.coeffs" || fail "regime.coeffs: no probability table"
"$RC" "$WORK/m1/regime.coeffs" "$WORK/m1/map.csv" >"$WORK/rc.txt" || { cat "$WORK/rc.txt"; fail "rough_check"; }
cat "$WORK/rc.txt"
"$CHECK" "$WORK/m1/regime.coeffs" "$WORK/m1/interface.csv" >/dev/null || fail "coeffs_check on the p = 0.5 interface"
# another seed gives another sample (the same seed the same, above)
"$SR" map $L --nd 8 --nv 10 --points 12 --seed 4 --out "$WORK/m4" --no-plot >/dev/null 2>&1 || fail "map --seed 4"
cmp -s "$WORK/m1/map.csv" "$WORK/m4/map.csv" && fail "map: seeds 3 and 4 give the same map"
# a flat map has no probability columns or table
"$SR" map --nd 6 --nv 6 --out "$WORK/f" --no-plot >/dev/null 2>&1 || fail "flat map"
grep -q "probability" "$WORK/f/regime.coeffs" && fail "flat regime.coeffs has a probability table"
# errors: named, exit 2, nothing written
expect2() { local out=$1; shift; "$SR" "$@" >"$WORK/e.out" 2>"$WORK/e.err"; local rc=$?
    [ $rc -eq 2 ] || fail "$* : exit $rc (want 2)"; grep -q -- "$out" "$WORK/e.err" || { cat "$WORK/e.err"; fail "$* : message lacks '$out'"; }; }
# a rough map over v_t: the combined regime.coeffs holds p over
# (d, v_t, v_n); read back by the wall model with the regime gate at every
# node of each layer; a table beyond 4096 values is refused before any map
"$SR" map $L --points 8 --nd 6 --nv 8 --vmin 0.05 --vmax 5 --vt 0,1 --no-plot --out "$WORK/mvt" \
    >"$WORK/mvt.log" 2>&1 || { cat "$WORK/mvt.log"; fail "map --vt 0,1 on a lattice: exit $?"; }
grep -q "^    probabilityVt     (0 1);" "$WORK/mvt/regime.coeffs" || fail "map --vt 0,1: no probabilityVt"
for v in 0 1; do
    "$RC" "$WORK/mvt/regime.coeffs" "$WORK/mvt/map-vt$v.csv" "$v" >"$WORK/rcv.txt" \
        || { cat "$WORK/rcv.txt"; fail "rough_check of the v_t = $v layer"; }
done
expect2 "--nd x --nv x --vt: 46 x 50 x 2" map $L --vt 0,1 --out "$WORK/x1"
expect2 "--angle: not with a rough wall" map $L --angle 0,30 --out "$WORK/x2"
expect2 "4096" map $L --nd 100 --nv 100 --out "$WORK/x3"
expect2 "--level" map $L --level 0.3 --out "$WORK/x4"
expect2 "thornton-ning" map $L --set cor=thornton-ning --out "$WORK/x5"
expect2 "--points" vcrit --d 1e-5 $L --points 0
expect2 "asperity radii" collide --d 0.01 --vn 1 $L
expect2 "wall" collide --d 1e-5 --vn 1 --set wall=rough
# long runs say so: a map of hours is refused before any work, naming
# its estimate and --force; a vcrit of hours too; with --progress a map prints its
# estimate and the final line; a map of milliseconds without it prints neither
expect2 "--force" map $L --points 100000 --nd 60 --nv 60 --threads 1 --out "$WORK/x6"
grep -Eq "about [0-9.]+ (h|days) for [0-9.e+]+ impacts" "$WORK/e.err" || { cat "$WORK/e.err"; fail "map: the refusal gives no estimate"; }
# (100 diameters on 1 thread: hours on any machine, so refused whatever its speed)
dl=$(seq -s, 10 109 | sed 's/\([0-9]*\)/\1e-6/g')
expect2 "--force" vcrit --d "$dl" $L --points 100000 --vmin 1e-4 --vmax 1000 --tol 1e-12 --threads 1
"$SR" map $L --points 16 --nd 6 --nv 6 --vmin 0.1 --vmax 10 --no-plot --progress --out "$WORK/x7" \
    >/dev/null 2>"$WORK/p.err" || { cat "$WORK/p.err"; fail "map --progress: exit $?"; }
grep -q "^snowregime map: about .* for [0-9.e+]* impacts on 2 threads" "$WORK/p.err" \
    || { cat "$WORK/p.err"; fail "map: no estimate"; }
grep -q "^snowregime map: done, .* impacts in" "$WORK/p.err" || { cat "$WORK/p.err"; fail "map --progress: no final line"; }
"$SR" map $L --points 4 --nd 4 --nv 4 --vmin 0.1 --vmax 10 --no-plot --out "$WORK/x8" >/dev/null 2>"$WORK/q.err"
! grep -q "about\|impacts" "$WORK/q.err" || { cat "$WORK/q.err"; fail "a map of milliseconds printed an estimate"; }
for k in 1 2 3 4 5 6; do [ ! -e "$WORK/x$k" ] || fail "error left $WORK/x$k"; done
# validation/rough-wall.sh (the README's rough-wall table), quick
RW=$SW_TOP/validation/rough-wall.sh
SNOWREGIME=$SR "$RW" --out "$WORK/rw" --quick >"$WORK/rw.log" 2>&1 || { cat "$WORK/rw.log"; fail "rough-wall.sh --quick exit $?"; }
for f in vcrit.md geometry.md rough-map.png map/regime.coeffs times.txt; do [ -s "$WORK/rw/$f" ] || fail "rough-wall.sh: no $f"; done
[ "$(grep -c '^| square, r 1 um, s 2 um |' "$WORK/rw/vcrit.md")" = 3 ] || fail "rough-wall.sh: vcrit.md lacks the three p rows"
[ "$(grep -c '^| [0-9.]* | [0-9.]* |' "$WORK/rw/geometry.md")" = 8 ] || fail "rough-wall.sh: geometry.md lacks its 8 rows"
SNOWREGIME=$SR "$RW" --out "$WORK/rw2" --points 0 >/dev/null 2>&1; [ $? -eq 2 ] || fail "rough-wall.sh --points 0: not exit 2"
SNOWREGIME=$SR "$RW" --out "$WORK/rw3" --set wall=bumpy >/dev/null 2>&1; [ $? -eq 2 ] || fail "rough-wall.sh --set wall=bumpy: not exit 2"
ls -a "$WORK" | grep -q '^\.rough-wall' && fail "rough-wall.sh left a temporary folder"
[ ! -e "$WORK/rw2" ] && [ ! -e "$WORK/rw3" ] || fail "rough-wall.sh: a failed run left its folder"
finish
