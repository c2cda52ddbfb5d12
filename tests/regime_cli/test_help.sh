#!/usr/bin/env bash
# --help on the program and every subcommand: man-page sections, exit 0.
. "$(dirname "$0")/common.sh"
for c in "" collide vcrit map sensitivity convergence; do
    out=$("$SR" ${c:+$c} --help 2>&1); rc=$?
    [ $rc -eq 0 ] || fail "snowregime $c --help: exit $rc"
    secs="NAME SYNOPSIS DESCRIPTION EXIT.STATUS EXAMPLES"
    [ -n "$c" ] && secs="$secs OPTIONS OUTPUT"
    for s in $secs; do
        echo "$out" | grep -q "^$s" || fail "snowregime $c --help: no section $s"
    done
    [ -n "$c" ] && { echo "$out" | grep -q "snowregime $c" || fail "snowregime $c --help does not name the command"; }
done
"$SR" help map | grep -q "^SYNOPSIS" || fail "snowregime help map"
"$SR" >/dev/null 2>&1; [ $? -eq 2 ] || fail "snowregime without a command should exit 2"
"$SR" frobnicate >/dev/null 2>&1; [ $? -eq 2 ] || fail "unknown command should exit 2"
ok "help texts checked"
finish
