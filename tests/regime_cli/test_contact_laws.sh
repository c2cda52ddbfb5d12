#!/usr/bin/env bash
# validation/contact-laws.sh: the contact laws side by side (doc/kernel.md)
# through the tool: outputs, the physics relations between the laws
# and the error paths (nothing left behind).
. "$(dirname "$0")/common.sh"
CL=$SW_TOP/validation/contact-laws.sh
export SNOWREGIME=$SR
"$CL" --help | grep -q "thornton-ning" || fail "--help does not describe the laws"
"$CL" --out "$WORK/cl" >"$WORK/cl.log" 2>&1 || { cat "$WORK/cl.log"; fail "contact-laws.sh exit $?"; }
for f in vcrit.csv vcrit.md e_v.csv contact-laws.png; do
    [ -s "$WORK/cl/$f" ] || fail "missing $f"
done
[ "$(ls -A "$WORK" | grep -c '^\.contact-laws')" -eq 0 ] || fail "temporary folder left behind"
# rows of the table: d = 10, 20, 50, 100 um; columns as in the header
col() { awk -F'|' -v name="$1" -v d="$2" 'NR == 1 { for (i = 1; i <= NF; i++) { h = $i; gsub(/ /, "", h); if (h == name) c = i } }
        NR > 2 { x = $2; gsub(/ /, "", x); if (x == d) { v = $c; gsub(/ /, "", v); print v } }' "$WORK/cl/vcrit.md"; }
th=$(col thornton 10); bo=$(col both 10); el=$(col elastic 100); tn30=$(col tn-30MPa 100); tn1=$(col tn-1MPa 10); es=$(col estimate 10)
[ "$th" = "7.89" ] || fail "thornton v_crit at 10 um: '$th' (baseline 7.89 m/s)"
fcmp "$(awk -v a="$bo" -v b="$th" 'BEGIN { print a / b }')" "<=" 1.05 || fail "both vs thornton: $bo vs $th"
fcmp "$(awk -v a="$bo" -v b="$th" 'BEGIN { print a / b }')" ">=" 1.0 || fail "both below thornton: $bo vs $th"
[ "$tn30" = "$el" ] || fail "thornton-ning at 30 MPa should be elastic at 100 um: $tn30 vs $el"
fcmp "$tn1" ">" 100 || fail "thornton-ning at 1 MPa, 10 um: $tn1"
[ "$es" = "3.56" ] || fail "closed-form estimate at 10 um: '$es' (3.56 m/s)"
# e(v): 57 speeds, every value in [0, 1]
[ "$(grep -vc '^v_m_s' "$WORK/cl/e_v.csv")" -eq 57 ] || fail "e_v.csv rows"
awk -F, 'NR > 1 { for (i = 2; i <= NF; i++) if (!($i >= 0 && $i <= 1)) exit 1 }' "$WORK/cl/e_v.csv" || fail "e_n outside [0, 1]"
# errors: no --out, an unknown option, a bad setting: exit 2, no folder
"$CL" >/dev/null 2>&1; [ $? -eq 2 ] || fail "no --out: exit not 2"
"$CL" --out "$WORK/x" --bogus >/dev/null 2>&1; [ $? -eq 2 ] || fail "unknown option: exit not 2"
"$CL" --out "$WORK/bad" --set gamma=-1 >"$WORK/bad.log" 2>&1; rc=$?
[ $rc -eq 2 ] || fail "bad setting: exit $rc"
grep -q "gamma" "$WORK/bad.log" || fail "bad setting: message does not name gamma: $(cat "$WORK/bad.log")"
[ ! -e "$WORK/bad" ] || fail "bad setting left $WORK/bad"
[ "$(ls -A "$WORK" | grep -c '^\.contact-laws')" -eq 0 ] || fail "temporary folder left after a failure"
finish
