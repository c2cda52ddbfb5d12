#!/usr/bin/env bash
# test_wedge_resolution.sh - post/wedge-resolution on two synthetic runs with known
# answers (no OpenFOAM): the regions and class tables of post/wedge-compose for a
# base and a refined run. Checks the change, its standard error and z per row, the
# verdicts (differs beyond 2 sigma; agrees, with the bound |change| + 2 se; no
# deposit; deposit in one run only), the counts, the default --mvd (the sprays
# both runs hold) and the refusals (exit 2 usage, exit 1 a missing result).
set -u
top=${SW_TOP:?SW_TOP not set}
R="$top/tutorials/wedge/post/wedge-resolution"
tmp=$(mktemp -d)
trap '[ -n "${KEEP:-}" ] || rm -rf "$tmp"' EXIT
fails=0
check() { if eval "$2"; then echo "ok   $1"; else echo "FAIL $1"; fails=$((fails+1)); fi; }

# mk RUN MVD  LEFT E  RIGHT E  CENTRE E  EDGES E  FACE E : regions.md as wedge-compose
# writes it (the window table, then a halves table that must not be read)
mk() {
    local d="$tmp/$1/compose/mvd$2"; mkdir -p "$d"
    cell() { if [ "$2" = - ]; then echo "| $1 | - |"; else echo "| $1 | $2 % |"; fi; }
    {
        echo "# Rear-face regions for a spray: synthetic"
        echo
        echo "| region | deposit [kg] | +- | deposit per area over the face's | stands out |"
        echo "|---|---:|---:|---:|---|"
        echo "| left side $(cell "$3" "$4") 1 | no |"
        echo "| right side $(cell "$5" "$6") 1 | no |"
        echo "| centre $(cell "$7" "$8") 1 | no |"
        echo "| edges $(cell "$9" "${10}") 1 | no |"
        echo "| whole face $(cell "${11}" "${12}") 1 | - |"
        echo
        echo "## The halves of the sampling window (each x2)"
        echo
        echo "| region | first half [kg] | +- | second half [kg] | +- | difference / its standard error |"
        echo "|---|---:|---:|---:|---:|---:|"
        echo "| left side | 99 | 1 % | 99 | 1 % | +0.0 |"
    } > "$d/regions.md"
}
mkc() {  # mkc RUN MVD C5 E5 C10 E10: classes.md
    local d="$tmp/$1/compose/mvd$2"; mkdir -p "$d"
    {
        echo "| d [um] | class [um] | mass share w | rear capture [ppm] | +- | share of the rear deposit |"
        echo "|---:|---|---:|---:|---:|---:|"
        echo "| 5 | 2 - 7 | 0.5 | $3 | $4 % | 50 % |"
        echo "| 10 | 7 - 14 | 0.5 | $5 | $6 % | 50 % |"
        echo "| 80 | 56 - 154 | 0 | 0 | - | 0 % |"
    } > "$d/classes.md"
}
#         left      right      centre  edges      face
mk base 20  1 5     1 10       0 -     0 -        1 10
mk fine 20  2 5     1.1 10     0 -     0.5 20     1.3 10
mkc base 20 100 10 200 10
mkc fine 20 100 10 300 5
mk base 8   1 5     1 5        1 5     1 5        1 5      # only in the base: not compared by default
mkc base 8 100 10 200 10

"$R" --base "$tmp/base" --refined "$tmp/fine" --base-label coarse --refined-label wakefine > "$tmp/out" 2> "$tmp/err"
check "exit 0" "[ $? -eq 0 ] && [ ! -s '$tmp/err' ]"
row() { grep -F "| $1 |" "$tmp/out" | head -1; }
# left: 1 -> 2 (5 % each): change +100 %, se 2 sqrt(0.05^2 + 0.05^2) = 14.1 %, z = 1 / sqrt(0.05^2 + 0.1^2) = +8.9
check "left: +100 %, se 14.1 %, z +8.9, differs" "row 'left side' | grep -q '| +100.0 % | 14.1 % | +8.9 | differs |'"
# face: 1 -> 1.3 (10 % each): +30 %, se 1.3 sqrt(0.02) = 18.4 %, z = 0.3 / sqrt(0.01 + 0.0169) = +1.8, bound 30 + 36.8 = 67 %
check "face: +30 %, se 18.4 %, z +1.8, agrees within 67 %" "row 'whole face' | grep -q '| +30.0 % | 18.4 % | +1.8 | agrees (change within +-67 % at 2 sigma) |'"
check "right: +10 %, z +0.7" "row 'right side' | grep -q '| +10.0 % | .* | +0.7 | agrees'"
check "centre: no deposit in either run" "row centre | grep -q 'no deposit |'"
check "edges: deposit in one run only" "row edges | grep -q 'deposit in one run only |'"
check "4 rows with snow, 2 differ" "grep -q 'Rows with snow (regions and face): 4; differing by more than 2 standard errors: 2.' '$tmp/out'"
# classes: 5 um unchanged; 10 um 200 +- 10 % -> 300 +- 5 %: z = 100 / sqrt(400 + 225) = +4.0
check "class 5 um: +0 %, z +0.0" "row d5um | grep -q '| +0.0 % | .* | +0.0 | agrees'"
check "class 10 um: +50 %, z +4.0, differs" "row d10um | grep -q '| +50.0 % | .* | +4.0 | differs |'"
check "class 80 um: no deposit" "row d80um | grep -q 'no deposit |'"
check "by default the sprays both runs hold (MVD 20 only)" "grep -q 'Spray MVD 20 um' '$tmp/out' && ! grep -q 'Spray MVD 8 um' '$tmp/out'"
check "the halves table is not read" "! grep -q '| 99 ' '$tmp/out'"
check "labels in the header" "grep -q '| region | coarse | +- | wakefine |' '$tmp/out'"
# every table row has the header's 10 cells
check "every row has 10 cells" "awk -F'|' '/^\\|/ && NF != 11 { bad = 1 } END { exit bad }' '$tmp/out'"

# refusals
"$R" --base "$tmp/base" > /dev/null 2> "$tmp/err"
check "no --refined: exit 2" "[ $? -eq 2 ] && grep -q 'required' '$tmp/err'"
"$R" --base "$tmp/base" --refined "$tmp/fine" --mvd 8 > /dev/null 2> "$tmp/err"
check "--mvd 8 missing in the refined run: exit 1, names the file" "[ $? -eq 1 ] && grep -q 'fine/compose/mvd8/regions.md' '$tmp/err'"
"$R" --base "$tmp/base" --refined "$tmp/fine" --mvd x > /dev/null 2> "$tmp/err"
check "--mvd x: exit 2" "[ $? -eq 2 ] && grep -q \"got 'x'\" '$tmp/err'"
"$R" --base "$tmp/base" --refined "$tmp/none" > /dev/null 2> "$tmp/err"
check "a run without compose/: exit 1" "[ $? -eq 1 ] && grep -q 'none/compose missing' '$tmp/err'"
"$R" --help | grep -q 'Usage: post/wedge-resolution'
check "--help" "[ $? -eq 0 ]"
[ "$fails" -eq 0 ] && { echo PASS; exit 0; } || { echo "$fails failure(s)"; exit 1; }
