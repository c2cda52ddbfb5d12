#!/usr/bin/env bash
# snowregime sensitivity: files, and the direction of the two parameters that matter.
. "$(dirname "$0")/common.sh"
out=$WORK/sens
"$SR" sensitivity --out "$out" --nd 14 --nv 14 >"$WORK/log" 2>&1 || { cat "$WORK/log"; fail "sensitivity exit $?"; }
for f in sensitivity.csv sensitivity.md sensitivity-interfaces.csv sensitivity.png; do
    [ -s "$out/$f" ] || fail "missing $f"
done
[ -z "$(ls -A "$out" | grep '^\.tmp-')" ] || fail "temporaries left"
n() { awk -F, -v p="$1" -v v="$2" '$1 == p && ($2 + 0 == v + 0 || v == "") { print $3 }' "$out/sensitivity.csv"; }
base=$(n baseline ""); g01=$(n gamma 0.1); g1=$(n gamma 1); s05=$(n sigma_y 500000); s15=$(n sigma_y 1500000)
echo "sticking points: baseline $base, gamma 0.1 $g01, gamma 1 $g1, sigma_y 0.5e6 $s05, 1.5e6 $s15"
[ -n "$base" ] && [ -n "$g01" ] && [ -n "$g1" ] && [ -n "$s05" ] && [ -n "$s15" ] || fail "rows missing in sensitivity.csv"
[ "${g1:-0}" -gt "${base:-0}" ] || fail "gamma 1.0 should stick more than baseline"
[ "${g01:-0}" -lt "${base:-0}" ] || fail "gamma 0.1 should stick less than baseline"
[ "${s05:-0}" -gt "${base:-0}" ] || fail "sigma_y 0.5 MPa should stick more than baseline"
[ "${s15:-0}" -lt "${base:-0}" ] || fail "sigma_y 1.5 MPa should stick less than baseline"
[ "$(grep -c '^| ' "$out/sensitivity.md")" -eq 10 ] || fail "markdown table: want a header and 9 rows"
ok "sensitivity checks done"
finish
