#!/usr/bin/env bash
# test_lammps_rough.sh (ctest lammps_rough): the rough-wall cross-check against
# LAMMPS (validation/lammps-rough.sh) on its --quick subset: 4 impact
# points x 3 angles, Hertz (2 speeds) with a constant COR and elastic JKR, every impact
# within the tolerances of doc/kernel.md (--check); its outputs and error paths.
# Skipped (77) when LAMMPS is not installed (etc/setup.sh --lammps).
. "$(dirname "$0")/common.sh"
LR=$SW_TOP/validation/lammps-rough.sh
export SNOWLAMMPS=$SW_BUILD/tools/snowlammps/snowlammps
[ -x "$SNOWLAMMPS" ] || { echo "SKIP: $SNOWLAMMPS not built"; exit 77; }
# snowlammps itself (no LAMMPS needed): the help's sections, strict options (exit 2,
# the option and the value named), nothing made on bad input
SL=$SNOWLAMMPS
h=$("$SL" --help) || fail "snowlammps --help: exit $?"
for sec in NAME SYNOPSIS DESCRIPTION OPTIONS OUTPUT EXIT.STATUS EXAMPLES; do
    echo "$h" | grep -q "^$sec" || fail "snowlammps --help: no section $sec"
done
slerr() {   # slerr WORD ARGS...: exit 2 and WORD in the message
    local w=$1; shift
    "$SL" "$@" >/dev/null 2>"$WORK/sle"; local rc=$?
    [ $rc -eq 2 ] && grep -q -- "$w" "$WORK/sle" || fail "snowlammps $*: exit $rc, $(cat "$WORK/sle")"
}
slerr "--out" --grid 2
slerr "--frob" --out "$WORK/y" --frob
slerr "2x" --out "$WORK/y" --grid 2x
slerr "21" --out "$WORK/y" --grid 21
slerr "nan" --out "$WORK/y" --d nan
slerr "1e-3" --out "$WORK/y" --d 1e-3
slerr "--angles" --out "$WORK/y" --angles 0,,30
slerr "85" --out "$WORK/y" --angles 0,85
slerr "0" --out "$WORK/y" --speeds-jkr 0.3,0
slerr "soft" --out "$WORK/y" --cases hertz,soft
slerr "--tol-v" --out "$WORK/y" --tol-v -1
slerr "--cor" --out "$WORK/y" --cor
[ ! -e "$WORK/y" ] || fail "snowlammps made its output folder on bad input"
"$SL" --out "$WORK/y" --lmp /nonexistent/lmp --grid 1 --angles 0 --cases hertz >/dev/null 2>"$WORK/sle"
[ $? -eq 1 ] && grep -q "nonexistent" "$WORK/sle" || fail "snowlammps with a missing lmp: not exit 1 naming it"
[ ! -e "$WORK/y" ] || fail "snowlammps left its work folder or the output folder it made: $(ls -A "$WORK/y")"
# the comma-list rule: a value or a case twice, an empty item refused; a list out
# of order taken in ascending order with a note (here before lmp is found missing)
slerr "gives the value 2 twice" --out "$WORK/y" --speeds-hertz 2,0.5,2
slerr "names 'hertz' twice" --out "$WORK/y" --cases hertz,jkr,hertz
slerr "'0,' has an empty item" --out "$WORK/y" --angles 0,
"$SL" --out "$WORK/y" --lmp /nonexistent/lmp --speeds-hertz 2,0.5 >/dev/null 2>"$WORK/sle"
grep -qx "snowlammps: note: --speeds-hertz: '2,0.5' taken in ascending order" "$WORK/sle" || fail "no ascending note: $(cat "$WORK/sle")"
# the output folder: a foreign one refused before any work unless --force; a link refused
mkdir -p "$WORK/fo" && echo mine >"$WORK/fo/notes.txt"
slerr "is not empty and not a SnowWall output folder (holds 'notes.txt'); give --force" --out "$WORK/fo"
"$SL" --out "$WORK/fo" --force --lmp /nonexistent/lmp >/dev/null 2>"$WORK/sle"
[ $? -eq 1 ] && grep -q "note: --force" "$WORK/sle" && [ "$(ls -A "$WORK/fo")" = notes.txt ] || fail "snowlammps --force into a foreign folder: $(cat "$WORK/sle"); $(ls -A "$WORK/fo")"
ln -s "$WORK/fo" "$WORK/folink"
slerr "is a symbolic link" --out "$WORK/folink"
# (a failure of the checks above is reported, not hidden by the skip)
command -v "${LMP:-lmp}" >/dev/null 2>&1 || { [ "$FAILS" -eq 0 ] || finish; echo "SKIP: LAMMPS (lmp) not installed: etc/setup.sh --lammps"; exit 77; }
"$LR" --help | grep -q "jkr-elastic" || fail "--help does not describe the cases"
"$LR" --out "$WORK/q" --quick --check >"$WORK/q.log" 2>&1 || { cat "$WORK/q.log"; fail "lammps-rough.sh --quick --check exit $?"; }
for f in summary.md impacts.csv report.txt times.txt; do
    [ -s "$WORK/q/$f" ] || fail "missing $f"
done
[ "$(ls -A "$WORK" | grep -c '^\.lammps-rough')" -eq 0 ] || fail "temporary folder left behind"
[ ! -e "$WORK/q/.work" ] || fail "work folder left in the output"
# 4 points x 3 angles x (2 hertz speeds + 1 jkr-elastic speed) = 36 impacts, all within the tolerances
[ "$(grep -vc '^case,' "$WORK/q/impacts.csv")" -eq 36 ] || fail "impacts.csv rows"
grep -q "impacts outside the tolerances: 0 of 36" "$WORK/q/summary.md" || fail "impacts outside the tolerances"
# the calibrated COR on the flat plane is the target in both codes (0.7 within 1e-3)
awk -F'|' '/COR on the flat base plane/ { v = $3 + 0; if (v < 0.699 || v > 0.701) bad = 1; n++ }
           END { exit !(n == 4 && !bad) }' "$WORK/q/summary.md" || fail "flat-plane COR not 0.7 in both codes"
# errors: exit 2 with the bad input named, nothing left behind
"$LR" >/dev/null 2>&1; [ $? -eq 2 ] || fail "no --out: exit not 2"
"$LR" --out "$WORK/x" --bogus 2>"$WORK/e1"; [ $? -eq 2 ] && grep -q -- "--bogus" "$WORK/e1" || fail "unknown option"
"$LR" --out "$WORK/x" --speeds-hertz 1,-2 2>"$WORK/e2"; [ $? -eq 2 ] && grep -q -- "-2" "$WORK/e2" || fail "bad speed"
"$LR" --out "$WORK/x" --cases hertz,soft 2>"$WORK/e3"; [ $? -eq 2 ] && grep -q "soft" "$WORK/e3" || fail "bad case"
"$LR" --out "$WORK/x" --grid 2 --grid 2x 2>"$WORK/e4"; [ $? -eq 2 ] && grep -q "2x" "$WORK/e4" || fail "bad grid"
[ ! -e "$WORK/x" ] || fail "output folder made on bad input"
LMP=/nonexistent/lmp "$LR" --out "$WORK/x" --quick >/dev/null 2>&1; [ $? -eq 77 ] || fail "absent lmp: exit not 77"
finish
