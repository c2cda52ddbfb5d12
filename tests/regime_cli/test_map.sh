#!/usr/bin/env bash
# snowregime map: every file, grid consistency with the fit, coeffs loaded by the
# wall model's reader, fit residuals, third axis.
. "$(dirname "$0")/common.sh"
out=$WORK/map
"$SR" map --out "$out" --nd 16 --nv 18 >"$WORK/log" 2>&1 || { cat "$WORK/log"; fail "map exit $?"; }
for f in map.csv interface.csv fit.txt regime.coeffs map.png; do
    [ -s "$out/$f" ] || fail "missing $f"
done
[ -z "$(ls -A "$out" | grep '^\.tmp-')" ] || fail "temporaries left: $(ls -A "$out")"
[ "$(head -c 4 "$out/map.png" | od -An -c | tr -d ' ')" = '211PNG' ] || fail "map.png is not a PNG"
# every grid point simulated
rows=$(grep -v '^#' "$out/map.csv" | tail -n +2 | wc -l)
[ "$rows" -eq $((16 * 18)) ] || fail "map.csv has $rows rows, want 288"
grep -q '^grid_points: 288$' "$out/fit.txt" || fail "fit.txt grid_points"
# stick and bounce both present, interface inside the range
nst=$(grep -v '^#' "$out/map.csv" | tail -n +2 | awk -F, '$3 == 1' | wc -l)
[ "$nst" -gt 20 ] && [ "$nst" -lt 268 ] || fail "sticking points $nst: interface not inside the grid"
# residuals small
rms=$(sed -n 's/^rms_rel_residual: //p' "$out/fit.txt"); mx=$(sed -n 's/^max_rel_residual: //p' "$out/fit.txt")
fcmp "$rms" "<" 0.02 || fail "rms residual $rms >= 2 %"
fcmp "$mx" "<" 0.05 || fail "max residual $mx >= 5 %"
npts=$(grep -v '^#' "$out/interface.csv" | tail -n +2 | wc -l)
[ "$npts" -ge 6 ] || fail "only $npts interface points"
# the wall model's reader loads regime.coeffs and agrees with the interface points
"$CHECK" "$out/regime.coeffs" "$out/interface.csv" || fail "coeffs_check"
# grid points well away from the fitted interface are classified as it says
awk -F, -v cf="$out/regime.coeffs" '
    BEGIN { while ((getline l < cf) > 0) {
              if (l ~ /^ *coeffs/) { gsub(/.*\(|\).*/, "", l); n = split(l, c, " ") }
              if (l ~ /^ *vnMin/) { split(l, a, /[ ;]+/); vmin = a[3] }
              if (l ~ /^ *vnMax/) { split(l, a, /[ ;]+/); vmax = a[3] } } }
    /^#/ || /^d_m/ { next }
    { v = $2; if (v < vmin || v > vmax) next
      x = log(v); y = 0; for (i = n; i >= 1; i--) y = y * x + c[i]; dc = exp(y)
      if ($1 < 0.85 * dc && $3 != 1) { print "point d " $1 " v " v " below d_crit " dc " bounces"; bad++ }
      if ($1 > 1.15 * dc && $3 != 0) { print "point d " $1 " v " v " above d_crit " dc " sticks"; bad++ }
      checked++ }
    END { print "checked " checked " grid points against the fit"; exit (bad > 0 || checked < 50) }' "$out/map.csv" \
    || fail "grid outcomes disagree with the fitted interface"
# threads split the rows only: 1 and 3 threads give the same map and interface
"$SR" map --out "$WORK/t1" --nd 9 --nv 11 --threads 1 --no-plot >/dev/null || fail "map --threads 1"
"$SR" map --out "$WORK/t3" --nd 9 --nv 11 --threads 3 --no-plot >/dev/null || fail "map --threads 3"
cmp -s "$WORK/t1/map.csv" "$WORK/t3/map.csv" || fail "map.csv differs between 1 and 3 threads"
cmp -s "$WORK/t1/interface.csv" "$WORK/t3/interface.csv" || fail "interface.csv differs between 1 and 3 threads"
# the fit degree is honoured and printed
grep -q '^degree: 3 ' "$out/fit.txt" || fail "degree 3 expected in fit.txt"
"$SR" map --out "$WORK/m2" --nd 12 --nv 14 --degree 2 --vlog 0 --no-plot >/dev/null || fail "map --degree 2 --vlog 0"
grep -q '^    degree          2;' "$WORK/m2/regime.coeffs" || fail "degree 2 not in regime.coeffs"
[ ! -e "$WORK/m2/map.png" ] || fail "--no-plot wrote a PNG"
# explicit range and a rerun into an existing folder replaces files atomically
"$SR" map --out "$out" --nd 10 --nv 20 --vmin 0.05 --vmax 5 --degree 2 --no-plot >/dev/null || fail "rerun into existing folder"
grep -q '^grid_points: 200$' "$out/fit.txt" || fail "rerun did not replace fit.txt"
# third axis: one map per tangential speed, full stick, at rest within 100 um
"$SR" map --out "$WORK/vt" --nd 10 --nv 12 --vt 0,0.5 --max-slide 1e-4 --no-plot >"$WORK/vt.log" 2>&1 || { cat "$WORK/vt.log"; fail "map --vt"; }
for s in -vt0 -vt0.5; do
    for f in map$s.csv interface$s.csv fit$s.txt; do [ -s "$WORK/vt/$f" ] || fail "missing $f"; done
    # a map of the series is written with its coeffs, or says why it has none
    [ -s "$WORK/vt/regime$s.coeffs" ] || grep -q '^no fit: ' "$WORK/vt/fit$s.txt" || fail "regime$s.coeffs missing without reason"
done
grep -q 'full stick.*vt 0.5' "$WORK/vt/map-vt0.5.csv" || fail "third axis should use full stick"
# a tangential speed can only reduce full sticking
n0=$(awk -F, '!/^#/ && !/^d_m/ && $3 == 1' "$WORK/vt/map-vt0.csv" | wc -l)
n5=$(awk -F, '!/^#/ && !/^d_m/ && $3 == 1' "$WORK/vt/map-vt0.5.csv" | wc -l)
[ "$n5" -lt "$n0" ] || fail "vt 0.5 with a bounded slide should stick less ($n5) than vt 0 ($n0)"
# without --max-slide the full stick of vt 0 is the normal outcome of the plain map
"$SR" map --out "$WORK/plain" --nd 10 --nv 12 --vmin "$(awk -F, '!/^#/ && !/^d_m/ { print $2; exit }' "$WORK/vt/map-vt0.csv")" \
    --vmax "$(awk -F, '!/^#/ && !/^d_m/ { v = $2 } END { print v }' "$WORK/vt/map-vt0.csv")" --no-plot >/dev/null || fail "plain map"
np=$(awk -F, '!/^#/ && !/^d_m/ && $3 == 1' "$WORK/plain/map.csv" | wc -l)
[ "$np" -ge "$n0" ] || fail "full stick at vt 0 ($n0) exceeds normal sticking ($np)"
ok "map checks done"
# a folder name never reaches gnuplot as text: quotes and a command
# in it, or a newline, still give the PNG and run nothing
(cd "$WORK" && "$SR" map --nd 6 --nv 6 --out "x'; system('touch PWNED'); print '" >/dev/null 2>&1) || fail "map into a folder with quotes: exit $?"
[ ! -e "$WORK/PWNED" ] && [ ! -e "$WORK/x'; system('touch PWNED'); print '/PWNED" ] || fail "a command in the --out name ran"
[ -s "$WORK/x'; system('touch PWNED'); print '/map.png" ] || fail "no map.png in a folder with quotes"
(cd "$WORK" && "$SR" map --nd 6 --nv 6 --out "nl
name" >/dev/null 2>&1) || fail "map into a folder with a newline: exit $?"
[ -s "$WORK/nl
name/map.png" ] || fail "no map.png in a folder with a newline"
[ "$(ls -a "$WORK" | grep -c '^\.tmp-')" = 0 ] || fail "temporary files left beside the folders"
finish
