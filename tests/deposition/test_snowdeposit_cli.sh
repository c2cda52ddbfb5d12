#!/usr/bin/env bash
# snowdeposit: help, every bad input (exit 2, one line naming it, no file), a
# short calibration whose closure brings the channel's V+ to the law, and an
# interrupted calibration that leaves nothing.
set -u
: "${SW_TOP:?SW_TOP not set (run through ctest)}"
: "${SW_BUILD:?SW_BUILD not set (run through ctest)}"
SD=$SW_BUILD/tools/snowdeposit/snowdeposit
[ -x "$SD" ] || { echo "SKIP: $SD not built"; exit 77; }
WORK=$(mktemp -d "${TMPDIR:-/tmp}/snowdeposit.XXXXXX")
trap 'rm -rf "$WORK"' EXIT
FAILS=0
fail() { echo "FAIL: $*"; FAILS=$((FAILS + 1)); }
ok() { echo "ok: $*"; }

"$SD" --help | grep -q "^SYNOPSIS" && ok "--help" || fail "--help"
"$SD" channel --help | grep -q "calibrate" && ok "channel --help" || fail "channel --help"

check() {   # expected-text args...
    local want=$1; shift
    "$@" >/dev/null 2>"$WORK/err"; local rc=$?
    [ $rc -eq 2 ] || fail "'$*': exit $rc, want 2"
    [ "$(wc -l <"$WORK/err")" -eq 1 ] || fail "'$*': want one error line, got: $(cat "$WORK/err")"
    grep -qF -- "$want" "$WORK/err" || fail "'$*': message does not name '$want': $(cat "$WORK/err")"
}
check "frobnicate" "$SD" frobnicate
# check: a closure file read as the model reads it, before any work
"$SD" check "$SW_TOP/etc/deposition.coeffs" | grep -q "a sublayer closure for the default walk" \
    && ok "check: the shipped closure" || fail "check: the shipped closure"
printf 'depositionClosure { bogus 1; }\n' > "$WORK/bad.coeffs"
check "missing key 'sublayerYPlus'" "$SD" check "$WORK/bad.coeffs"
check "cannot open" "$SD" check "$WORK/none.coeffs"
check "check takes one FILE" "$SD" check
mkfifo "$WORK/check.fifo"
check "not a regular file" timeout 10 "$SD" check "$WORK/check.fifo"
check "not a regular file" "$SD" check "$WORK"
rm -f "$WORK/bad.coeffs" "$WORK/check.fifo"
check "--bogus" "$SD" channel --bogus 1
# the comma-list rule: an empty item or a value twice refused, naming the option and the text
check "--tau-plus: '1,,3' has an empty item" "$SD" channel --tau-plus 1,,3
check "--tau-plus: ',1' has an empty item" "$SD" channel --tau-plus ,1
check "--tau-plus: '1,' has an empty item" "$SD" channel --tau-plus 1,
check "--tau-plus: '1,3,1.0' gives the value 1 twice" "$SD" channel --tau-plus 1,3,1.0
check "nan" "$SD" channel --tau-plus nan
check "0x10" "$SD" channel --tau-plus 0x10
check "--tau-plus: '0' (in '0') is out of range (0, 10000]" "$SD" channel --tau-plus 0
check "--particles" "$SD" channel --particles 0
check "--particles" "$SD" channel --particles 2.5
check "--seed" "$SD" channel --seed -1
check "layerYplus" "$SD" channel --set layerYplus=50
check "CT" "$SD" channel --set CT=0
check "blendYPlus" "$SD" channel --set blendYPlus=50
check "--re-tau" "$SD" channel --re-tau 5
check "--sublayer" "$SD" channel --sublayer 500
check "--gravity" "$SD" channel --gravity -1
check "--gravity" "$SD" channel --gravity 2
check "--gravity" "$SD" channel --gravity nan
check "--c-below" "$SD" channel --c-below 0
check "--c-below: 400 is not below Re_tau 314" "$SD" channel --c-below 400
check "--law" "$SD" calibrate --out "$WORK/x" --law stokes
check "--scheme" "$SD" channel --scheme rk4
check "--out" "$SD" calibrate
check "--out" "$SD" channel --out "$WORK/y"
check "no/such" "$SD" calibrate --out "$WORK/no/such/file"
check "--t-run" "$SD" channel --t-run 1e300
# an option of the other command is refused, not dropped without a word (channel
# --law would run the default channel for minutes), and --set names its key
check "--law is an option of calibrate, not of channel" "$SD" channel --law wood
check "--closure is an option of channel, not of calibrate" "$SD" calibrate --out "$WORK/x" --closure wood
check "--set CT: 'nan' is not a finite decimal number" "$SD" channel --set CT=nan
# the work is estimated before it starts and refused over the limit (1e8 particles
# over t+ 1e9 would be a run of centuries)
check "at least 5e+16 particle steps" "$SD" channel --particles 1e8 --t-run 1e9 --tau-plus 1
check "--force" "$SD" calibrate --out "$WORK/x" --particles 1e6
# --particles 0: one "(see snowdeposit --help)", the range named
"$SD" channel --particles 0 >/dev/null 2>"$WORK/err"
[ "$(cat "$WORK/err")" = "snowdeposit: --particles: 0 is not an integer in [1, 100000000] (see snowdeposit --help)" ] \
    || fail "--particles 0: $(cat "$WORK/err")"
# calibrate --out FILE onto a folder, a FIFO, a link or a /dev/full-like node made
# here: refused before the work (exit 2, named), each left as it was
mkdir "$WORK/outdir"; mkfifo "$WORK/fifo"; echo keep >"$WORK/target"; ln -s "$WORK/target" "$WORK/link"
check "cannot write '$WORK/outdir': it exists and is a folder" "$SD" calibrate --out "$WORK/outdir"
check "cannot write '$WORK/fifo': it exists and is a FIFO" "$SD" calibrate --out "$WORK/fifo"
check "cannot write '$WORK/link': it exists and is a symbolic link" "$SD" calibrate --out "$WORK/link"
[ -d "$WORK/outdir" ] && [ -p "$WORK/fifo" ] && [ -L "$WORK/link" ] && [ "$(cat "$WORK/target")" = keep ] \
    || fail "a refused --out was changed"
if mknod "$WORK/full" c 1 7 2>/dev/null; then
    check "cannot write '$WORK/full': it exists and is a character device" "$SD" calibrate --out "$WORK/full"
    [ -c "$WORK/full" ] && ok "--out onto a device node: refused, still a device" || fail "--out replaced the device node"
    rm -f "$WORK/full"
fi
rmdir "$WORK/outdir"; rm -f "$WORK/fifo" "$WORK/link" "$WORK/target"
[ -z "$(ls -A "$WORK" | grep -v '^err$')" ] && ok "no file left by the errors" || fail "a file was left: $(ls -A "$WORK")"
# FILE in a read-only folder, as an unprivileged user (root's writes are not
# stopped by permissions): refused before the work, exit 2
mkdir "$WORK/ro" && chmod 555 "$WORK/ro" && chmod 755 "$WORK"
as_user=
if [ "$(id -u)" != 0 ]; then as_user=" "
elif command -v setpriv >/dev/null && setpriv --reuid=nobody --regid=nogroup --clear-groups true 2>/dev/null; then
    as_user="setpriv --reuid=nobody --regid=nogroup --clear-groups"
fi
if [ -n "$as_user" ]; then
    check "folder '$WORK/ro' is not writable" $as_user "$SD" calibrate --out "$WORK/ro/x.coeffs"
    [ -z "$(ls -A "$WORK/ro")" ] && ok "read-only folder: refused, nothing written" || fail "read-only folder: $(ls -A "$WORK/ro")"
else
    echo "skip: no unprivileged user for the read-only check"
fi
rmdir "$WORK/ro"
# a real full disk (a 16 KiB tmpfs filled up): the write error is found at
# flush/close, exit 1 naming FILE, the temporary removed (skipped where mounting
# is not permitted)
mkdir "$WORK/tiny"
if mount -t tmpfs -o size=16k tmpfs "$WORK/tiny" 2>/dev/null; then
    dd if=/dev/zero of="$WORK/tiny/fill" bs=1k count=64 2>/dev/null
    "$SD" calibrate --out "$WORK/tiny/full.coeffs" --tau-plus 1,3 --particles 10 --t-run 10 --t-warm 0 \
        >/dev/null 2>"$WORK/err"; rc=$?
    left=$(ls -A "$WORK/tiny" | grep -v '^fill')
    umount "$WORK/tiny"
    [ $rc -eq 1 ] && grep -qF "write error on '$WORK/tiny/full.coeffs': No space left on device" "$WORK/err" \
        && ok "full disk: exit 1, named" || fail "full disk: exit $rc, $(cat "$WORK/err")"
    [ -z "$left" ] && ok "full disk: no file, no temporary" || fail "full disk left: $left"
else
    echo "skip: mounting a tmpfs is not permitted here"
fi
rmdir "$WORK/tiny"
# a list out of order: taken in ascending order, with a one-line note
"$SD" channel --tau-plus 3,1 --particles 20 --t-run 20 --t-warm 0 >"$WORK/sorted.txt" 2>"$WORK/err" \
    || fail "channel --tau-plus 3,1: $(cat "$WORK/err")"
[ "$(cat "$WORK/err")" = "snowdeposit: note: --tau-plus: '3,1' taken in ascending order" ] || fail "no ascending note: $(cat "$WORK/err")"
[ "$(awk '!/^#/ && $1 + 0 > 0 { printf "%s ", $1 }' "$WORK/sorted.txt")" = "1 3 " ] || fail "tau+ rows not ascending: $(cat "$WORK/sorted.txt")"
rm -f "$WORK/sorted.txt"

# a short calibration: the file, its keys, and the closure at work
"$SD" calibrate --out "$WORK/dep.coeffs" --tau-plus 0.3,1,3,10 --particles 300 --t-run 4000 \
    --t-warm 500 >"$WORK/cal.txt" 2>"$WORK/err" || fail "calibrate: $(cat "$WORK/err")"
for k in tauPlus vPlusSublayer vPlusLaw vPlusCrw cSublayer sublayerYPlus layerYPlus; do
    grep -q "^ *$k " "$WORK/dep.coeffs" || fail "dep.coeffs has no $k"
done
ls -A "$WORK" | grep -q tmp && fail "calibrate left a temporary file" || ok "no temporary left"
"$SD" channel --closure wood --tau-plus 1,3,10 --particles 300 --t-run 4000 --t-warm 500 \
    >"$WORK/ch.txt" 2>"$WORK/err" || fail "channel --closure: $(cat "$WORK/err")"
cat "$WORK/ch.txt"
# V+ within a factor 2 of the law at tau+ 1, 3, 10 (the closure is calibrated
# on the same channel: this checks that it acts as designed, not the physics)
awk '!/^#/ && $1 + 0 > 0 { if (!($7 > 0.5 && $7 < 2)) { print "ratio " $7 " at tau+ " $1; bad = 1 } } END { exit bad }' \
    "$WORK/ch.txt" && ok "closure: V+ at the law within a factor 2" || fail "closure: V+ off the law"
# without the closure the CRW misses the diffusion-impaction deposition
"$SD" channel --tau-plus 1 --particles 300 --t-run 4000 --t-warm 500 >"$WORK/crw.txt" 2>&1
awk '!/^#/ && $1 == 1 { exit !($7 < 0.2) }' "$WORK/crw.txt" && ok "CRW alone far below the law at tau+ 1" \
    || fail "CRW alone at tau+ 1: $(cat "$WORK/crw.txt")"

# SIGTERM during calibrate: no file, no temporary
"$SD" calibrate --out "$WORK/killed.coeffs" --particles 20000 >/dev/null 2>&1 &
pid=$!
sleep 1
kill -TERM $pid; wait $pid; rc=$?
[ $rc -eq 143 ] || fail "SIGTERM: exit $rc, want 143"
ls -A "$WORK" | grep -q killed && fail "SIGTERM left $(ls -A "$WORK" | grep killed)" || ok "SIGTERM leaves nothing"

if [ "$FAILS" -eq 0 ]; then echo "PASS"; exit 0; else echo "$FAILS failure(s)"; exit 1; fi
