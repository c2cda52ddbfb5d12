#!/usr/bin/env bash
# snowregime map --vt 0,...: the combined regime.coeffs with the d_crit(v_n, v_t)
# table, read back by the wall-model core and checked against the
# kernel at random off-grid points (oblique_check).
. "$(dirname "$0")/common.sh"
OC=$SW_BUILD/tests/regime_cli/oblique_check
"$SR" map --out "$WORK/ob" --vt 0,0.25,0.5,1,2,4,8 --max-slide 100e-6 --nd 20 --nv 30 --no-plot \
    >"$WORK/ob.log" 2>&1 || { cat "$WORK/ob.log"; fail "map --vt exit $?"; }
f=$WORK/ob/regime.coeffs
[ -s "$f" ] || fail "no combined regime.coeffs"
for k in obliqueSlide obliqueVt obliqueVn obliqueDCrit; do grep -q "^ *$k " "$f" || fail "regime.coeffs lacks $k"; done
for v in 0 0.25; do [ -s "$WORK/ob/regime-vt$v.coeffs" ] || fail "per-v_t file regime-vt$v.coeffs missing"; done
# (v_t 8 m/s: every grid point bounces, no fit, no per-v_t file; the table still has the row)
# the v_t = 0 row agrees with the normal fit within its residual (+ the bisection tolerance)
dev=$(sed -n 's/.*v_t = 0 row vs the fit: max \([0-9.e+-]*\);.*/\1/p' "$WORK/ob.log")
maxres=$(awk '$1 == "maxResidual" { sub(";", "", $2); print $2 }' "$f")
[ -n "$dev" ] && [ -n "$maxres" ] || fail "no v_t = 0 deviation ($dev) or maxResidual ($maxres)"
fcmp "$dev" "<=" "$(awk -v r="$maxres" 'BEGIN { print r + 1e-3 }')" || fail "v_t = 0 row vs fit: $dev > maxResidual $maxres + 1e-3"
# 200 random off-grid (v_n, v_t): the wall model's d_crit within 2 % of the kernel's
"$OC" "$f" 200 11 >"$WORK/oc.txt" || fail "oblique_check exit $?"
cat "$WORK/oc.txt"
err=$(sed -n 's/.*relative error of d_crit: max \([0-9.e+-]*\),.*/\1/p' "$WORK/oc.txt")
n=$(sed -n 's/^points \([0-9]*\) of.*/\1/p' "$WORK/oc.txt")
[ "${n:-0}" -ge 200 ] || fail "only ${n:-0} points compared"
fcmp "${err:-1}" "<" 0.02 || fail "interpolation error $err >= 2 %"
# a tangential speed reduces d_crit: the table falls along v_t at fixed v_n
awk '/obliqueDCrit/ { on = 1 } on { gsub(/[();]/, " "); for (i = 1; i <= NF; i++) if ($i ~ /^[0-9]/) v[n++] = $i }
     on && /;/ { exit } END { nv = n / 7; if (!(v[nv * 6] < v[0])) exit 1 }' "$f" || fail "d_crit does not fall from v_t 0 to 8 m/s"
# a list not starting at 0: per-v_t maps only, with a note
"$SR" map --out "$WORK/ob2" --vt 0.5,1 --max-slide 100e-6 --nd 12 --nv 12 --no-plot --vmin 0.3 --vmax 10 \
    >"$WORK/ob2.log" 2>&1 || fail "map --vt 0.5,1 exit $?"
grep -q "does not start with 0" "$WORK/ob2.log" || fail "no note for a list without 0"
[ ! -e "$WORK/ob2/regime.coeffs" ] || fail "combined file written for a list without 0"
finish
