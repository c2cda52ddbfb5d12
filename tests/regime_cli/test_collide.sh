#!/usr/bin/env bash
# snowregime collide: report fields, outcomes on both sides of v_crit, trajectory CSV and VTK.
. "$(dirname "$0")/common.sh"
vc=$("$SR" vcrit --d 4e-05 | grep -v '^#' | cut -f2)
slow=$(awk -v v="$vc" 'BEGIN { print 0.5 * v }'); fast=$(awk -v v="$vc" 'BEGIN { print 2 * v }')
"$SR" collide --d 4e-05 --vn "$slow" >"$WORK/slow.txt" || fail "collide slow: exit $?"
"$SR" collide --d 4e-05 --vn "$fast" >"$WORK/fast.txt" || fail "collide fast: exit $?"
for k in outcome contact_kept stick e_n e_t t_contact delta_max dt steps max_steps status energy_err tabor; do
    grep -q "^$k: " "$WORK/slow.txt" || fail "collide output has no '$k:'"
done
grep -q "^contact_kept: 1" "$WORK/slow.txt" || fail "0.5 v_crit should keep the contact"
grep -q "^outcome: bounce" "$WORK/fast.txt" || fail "2 v_crit should bounce"
en=$(sed -n 's/^e_n: //p' "$WORK/fast.txt")
fcmp "$en" ">" 0 && fcmp "$en" "<" 1 || fail "bounce e_n $en not in (0, 1)"
steps=$(sed -n 's/^steps: //p' "$WORK/fast.txt"); maxs=$(sed -n 's/^max_steps: //p' "$WORK/fast.txt")
[ "$steps" -gt 0 ] && [ "$steps" -le "$maxs" ] || fail "steps $steps not in (0, max_steps $maxs]"
# trajectory files
"$SR" collide --d 4e-05 --vn "$fast" --vt 0.3 --trace-csv "$WORK/t.csv" --trace-vtk "$WORK/t.vtk" >/dev/null \
    || fail "collide with traces: exit $?"
[ -s "$WORK/t.csv" ] && [ -s "$WORK/t.vtk" ] || fail "trace files missing"
ls -a "$WORK" | grep -q '^\.tmp-' && fail "temporary files left"
rows=$(grep -v '^#' "$WORK/t.csv" | tail -n +2 | wc -l)
[ "$rows" -ge 10 ] || fail "only $rows trajectory rows"
head -n 4 "$WORK/t.csv" | grep -q '^t_s,x_m,z_m,delta_m,vn_m_s,fn_N,a_m,vt_m_s,omega_rad_s$' || fail "CSV header"
head -1 "$WORK/t.vtk" | grep -q '^# vtk DataFile Version' || fail "VTK magic line"
npts=$(sed -n 's/^POINTS \([0-9]*\) double$/\1/p' "$WORK/t.vtk")
[ "$npts" = "$rows" ] || fail "VTK POINTS $npts != CSV rows $rows"
grep -q "^LINES 1 $((rows + 1))$" "$WORK/t.vtk" || fail "VTK polyline"
grep -q "^POINT_DATA $rows$" "$WORK/t.vtk" || fail "VTK point data count"
[ "$(grep -c '^SCALARS' "$WORK/t.vtk")" -eq 7 ] || fail "VTK: expected 7 point-data scalars"
# the VTK point data must match the CSV columns: time and overlap of the last row
last_csv=$(tail -1 "$WORK/t.csv" | cut -d, -f1)
last_vtk=$(awk '/^SCALARS time/ { on = 1; getline; next } on && /^SCALARS/ { exit } on { v = $1 } END { print v }' "$WORK/t.vtk")
fcmp "$(awk -v a="$last_csv" -v b="$last_vtk" 'BEGIN { x = a - b; print (x < 0 ? -x : x) }')" "<=" "$(awk -v a="$last_csv" 'BEGIN { print 1e-8 * (a < 0 ? -a : a) + 1e-30 }')" \
    || fail "VTK time $last_vtk != CSV time $last_csv"
# the centre moves along the wall while vt > 0
xlast=$(tail -1 "$WORK/t.csv" | cut -d, -f2)
fcmp "$xlast" ">" 0 || fail "centre x does not advance with vt > 0 ($xlast)"
# a NaN diameter and a bad trace path
"$SR" collide --d nan --vn 1 >/dev/null 2>"$WORK/e"; [ $? -eq 2 ] && grep -q -- "--d: 'nan'" "$WORK/e" || fail "NaN diameter"
# a trace into a missing folder: refused before the run (exit 2), the path named
"$SR" collide --d 4e-05 --vn 1 --trace-csv "$WORK/no/such/dir/t.csv" >/dev/null 2>"$WORK/e"; rc=$?
[ $rc -eq 2 ] && grep -qF "cannot write '$WORK/no/such/dir/t.csv'" "$WORK/e" || fail "trace into a missing folder: exit $rc, $(cat "$WORK/e")"
ok "collide checks done"
finish
