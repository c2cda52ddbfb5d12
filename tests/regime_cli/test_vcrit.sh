#!/usr/bin/env bash
# snowregime vcrit: the output contract, tolerance, physics direction and the
# elastic JKR closed form of Thornton & Ning through the whole tool.
. "$(dirname "$0")/common.sh"
dl="1e-05,2.5e-05,5e-05,0.0001"
"$SR" vcrit --d "$dl" >"$WORK/v.txt" 2>"$WORK/v.err"; rc=$?
[ $rc -eq 0 ] || { cat "$WORK/v.err"; fail "vcrit exit $rc"; }
# contract: non-comment lines are exactly <d>TAB<v>, one per diameter, same order
grep -v '^#' "$WORK/v.txt" >"$WORK/data.txt"
[ "$(wc -l <"$WORK/data.txt")" -eq 4 ] || fail "expected 4 data lines, got $(wc -l <"$WORK/data.txt")"
num='[-+]?[0-9]+(\.[0-9]*)?([eE][-+]?[0-9]+)?'
grep -Evq "^${num}	${num}\$" "$WORK/data.txt" && fail "a data line is not <d>TAB<v>: $(grep -Ev "^${num}	${num}\$" "$WORK/data.txt" | head -1)"
[ "$(cut -f1 "$WORK/data.txt" | awk '{ printf "%s%g", (NR > 1 ? "," : ""), $1 }')" = "1e-05,2.5e-05,5e-05,0.0001" ] \
    || fail "diameters not echoed in order (SI): $(cut -f1 "$WORK/data.txt" | tr '\n' ' ')"
# larger particles stick only at lower speeds
awk -F'\t' 'NR > 1 && !($2 < prev) { exit 1 } { prev = $2 }' "$WORK/data.txt" || fail "v_crit not decreasing with d"
# the tolerance: 1e-3 and 1e-6 runs agree within 1e-3 (bracket of 1e-3 -> error <= 5e-4)
"$SR" vcrit --d 3e-05 --tol 1e-6 | grep -v '^#' | cut -f2 >"$WORK/fine"
"$SR" vcrit --d 3e-05 --tol 1e-3 | grep -v '^#' | cut -f2 >"$WORK/coarse"
fcmp "$(awk -v a="$(cat "$WORK/fine")" -v b="$(cat "$WORK/coarse")" 'BEGIN { x = a / b - 1; print (x < 0 ? -x : x) }')" "<=" 6e-4 \
    || fail "tol 1e-3 vs 1e-6: $(cat "$WORK/coarse") vs $(cat "$WORK/fine")"
# elastic JKR: v_crit of the tool within 0.5 % of Thornton-Ning V_s (printed in the comments)
"$SR" vcrit --d 2e-05,8e-05 --set cor=elastic --tol 1e-4 >"$WORK/el.txt" || fail "elastic vcrit exit $?"
while IFS=$'\t' read -r d v; do
    vs=$(grep "^# d $(awk -v d="$d" 'BEGIN { printf "%g", d }'):" "$WORK/el.txt" | sed -n 's/.*Thornton-Ning V_s \([0-9.e+-]*\).*/\1/p')
    [ -n "$vs" ] || { fail "no Thornton-Ning V_s comment for d $d"; continue; }
    fcmp "$(awk -v a="$v" -v b="$vs" 'BEGIN { x = a / b - 1; print (x < 0 ? -x : x) }')" "<=" 0.005 \
        || fail "elastic d $d: v_crit $v vs V_s $vs"
done < <(grep -v '^#' "$WORK/el.txt")
# nothing to bracket: range below v_crit -> nan, comment, exit 1
"$SR" vcrit --d 1e-05 --vmin 1e-4 --vmax 2e-4 >"$WORK/all.txt" 2>/dev/null; rc=$?
[ $rc -eq 1 ] || fail "sticks-everywhere range: exit $rc, want 1"
grep -q "^1e-05	nan$" "$WORK/all.txt" || fail "sticks-everywhere: data line should be nan"
grep -q "sticks over the whole range" "$WORK/all.txt" || fail "sticks-everywhere not reported"
"$SR" vcrit --d 1e-04 --vmin 20 --vmax 40 >"$WORK/none.txt" 2>/dev/null; rc=$?
[ $rc -eq 1 ] || fail "bounces-everywhere range: exit $rc, want 1"
grep -q "bounces over the whole range" "$WORK/none.txt" || fail "bounces-everywhere not reported"
# settings: a config file acts like --set, and --set given later overrides it
printf '# test config\ngamma = 0.5\ncor thornton\n' >"$WORK/g.cfg"
a=$("$SR" vcrit --d 3e-05 --config "$WORK/g.cfg" | grep -v '^#')
b=$("$SR" vcrit --d 3e-05 --set gamma=0.5 | grep -v '^#')
c=$("$SR" vcrit --d 3e-05 --config "$WORK/g.cfg" --set gamma=0.2 | grep -v '^#')
d0=$("$SR" vcrit --d 3e-05 | grep -v '^#')
[ "$a" = "$b" ] || fail "config gamma 0.5 ($a) != --set gamma=0.5 ($b)"
[ "$c" = "$d0" ] || fail "--set after --config should win ($c vs $d0)"
[ "$a" != "$d0" ] || fail "gamma 0.5 should change v_crit"
"$SR" vcrit --d 3e-05 --config "$WORK/g.cfg" | grep -q '^# setting gamma 0.5' || fail "settings not echoed as comments"
ok "vcrit checks done"
finish
