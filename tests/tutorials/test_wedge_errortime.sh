#!/usr/bin/env bash
# test_wedge_errortime.sh - post/wedge-errortime on synthetic cost tables (no
# OpenFOAM; gnuplot needed for the plot): the table's rows and the time each design
# needs for 10 % at its rate (t (e / 10)^2), the designs of two runs, a region on
# which no design put snow (said in the table, the plot holds the target only,
# exit 0: a coarse mesh's bare edges are a result, not an error), and the refusals
# (exit 2: no --out, an unknown region, a CSV without its label, a folder at --out).
set -u
top=${SW_TOP:?SW_TOP not set}
E="$top/tutorials/wedge/post/wedge-errortime"
command -v gnuplot >/dev/null || { echo "gnuplot missing: skipped"; exit 77; }
tmp=$(mktemp -d)
trap '[ -n "${KEEP:-}" ] || rm -rf "$tmp"' EXIT
fails=0
check() { if eval "$2"; then echo "ok   $1"; else echo "FAIL $1"; fails=$((fails+1)); fi; }

{ echo 'design,wall_s,face,left,right,centre,edges'
  echo 'flow,250,,,,,'
  echo 'spray,40,20,30,30,40,'
  echo 'classes,160,5,8,9,12,'; } > "$tmp/a.csv"
{ echo 'design,wall_s,face,left,right,centre,edges'
  echo 'classes,1000,2.5,4,4,6,50'; } > "$tmp/b.csv"
SNOWWALL_TOP=$top "$E" --out "$tmp/face.png" --region face "$tmp/a.csv" default "$tmp/b.csv" -full > "$tmp/face.md" 2> "$tmp/err"
check "two runs, region face: exit 0, PNG written" "[ $? = 0 ] && [ -s '$tmp/face.png' ]"
check "the flow row is no design; three points" "[ \$(grep -c '^| [a-z]* | ' '$tmp/face.md') = 4 ]"   # header + 3
check "spray, 40 s at 20 %: 160 s for 10 %" "grep -qx '| spray | default | 40 | 20.0 | 160 |' '$tmp/face.md'"
check "classes of -full, 1000 s at 2.5 %: 62.5 s for 10 %" "grep -qx '| classes | -full | 1000 | 2.5 | 62.5 |' '$tmp/face.md'"
# the default region (edges): only -full's classes put snow there
SNOWWALL_TOP=$top "$E" --out "$tmp/edges.png" "$tmp/a.csv" default "$tmp/b.csv" -full > "$tmp/edges.md"
check "edges (default region): the one design with snow there" "[ \$(grep -c '^| classes | -full | 1000 | 50.0 | 2.5e+04 |' '$tmp/edges.md') = 1 ] && [ \$(grep -c '^| ' '$tmp/edges.md') = 2 ]"
# no design with snow on the region
SNOWWALL_TOP=$top "$E" --out "$tmp/bare.png" "$tmp/a.csv" default > "$tmp/bare.md" 2> "$tmp/err"
check "edges bare in every design: exit 0, said in the table, PNG written" \
    "[ $? = 0 ] && grep -q '^No design of the tables put snow on the edges region' '$tmp/bare.md' && [ -s '$tmp/bare.png' ]"
# refusals
refused() {  # refused PATTERN ARGS...
    local want=$1; shift
    SNOWWALL_TOP=$top "$E" "$@" > /dev/null 2> "$tmp/err"; local rc=$?
    check "refused ($*): exit 2, '$want'" "[ $rc = 2 ] && grep -qF -- '$want' '$tmp/err'"
}
refused "--out PNG is required" "$tmp/a.csv" default
refused "is not face, left, right, centre or edges" --out "$tmp/x.png" --region middle "$tmp/a.csv" default
refused "has no label" --out "$tmp/x.png" "$tmp/a.csv"
mkdir "$tmp/dir.png"
refused "wedge-errortime" --out "$tmp/dir.png" "$tmp/a.csv" default
check "the folder at --out left alone" "[ -d '$tmp/dir.png' ]"
[ "$fails" = 0 ] && echo PASS || { echo "$fails check(s) failed"; exit 1; }
