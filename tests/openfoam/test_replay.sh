#!/usr/bin/env bash
# test_replay.sh - the set-up checks of pimpleUncoupledKinematicParcelFoam -replay
# (flowReplay.H) on the box mesh with a laminar PIMPLE flow (U, p), before any step:
#  - a library that fits: the one-line estimate "Replay: N snapshots x M cells x K
#    values = X GB" with N x M x K x 8 bytes = X, then the library taken and played back;
#  - phi listed in fields played back (the solved fluxes, to 1e-6), not listed rebuilt
#    from U;
#  - a fixed deltaT longer than interval, and adjustTimeStep with maxDeltaT unset or
#    longer than interval: FatalIOErrors naming replay, interval and the numbers, with
#    no time step run; maxDeltaT equal to interval accepted;
#  - a misspelt key and a memoryFraction outside (0, 1]: named FatalIOErrors;
#  - resuming a run whose library is stored (store yes): stopped after and inside
#    the library (U, p and phi stored), started again from its last write, the same flow to 1e-9 as a run
#    never stopped; a late start without store, and a stored snapshot missing, refused;
#    a FIFO, a link or a file in the library's place refused before any step;
#  - -checkpoint: every step written when it is due, the flow unchanged; 0, -1,
#    nan and 1e999 refused; -speedScale's bad factors and its use without -frozen
#    refused;
#  - memory: a mesh whose library (100 000 snapshots of U and p) is about twice the
#    machine's MemAvailable: refused with the estimate before the first step, in seconds;
#    stored (store yes), streamed from disk instead;
#  - streaming (stream yes): the played-back flow the in-memory one to the last bit, also
#    resumed; stream yes without store and an unknown stream value refused.
# About 20 s.
set -euo pipefail
# shellcheck source=common.sh
. "$(dirname "$0")/common.sh"
solver="$top/platforms/bin/pimpleUncoupledKinematicParcelFoam"
[ -x "$solver" ] || { echo "SKIP: $solver not built (run ./Allwmake)"; exit 77; }

# make_case DIR CELLS: the box with a laminar PIMPLE flow and an empty snow cloud
make_case() {
    cp -r "$top/tests/openfoam/box" "$1"
    cp "$fixture" "$1/constant/regime.coeffs"
    (
        cd "$1"
        sed -i "s/(4 4 4) simpleGrading/($2 $2 $2) simpleGrading/" system/blockMeshDict
        cat > 0/U <<'EOT'
FoamFile { version 2.0; format ascii; class volVectorField; object U; }
dimensions [0 1 -1 0 0 0 0];
internalField uniform (0.2 0 0);
boundaryField
{
    wall  { type noSlip; }
    top   { type fixedValue; value uniform (0.2 0 0); }
    sides { type fixedValue; value uniform (0.2 0 0); }
}
EOT
        cat > 0/p <<'EOT'
FoamFile { version 2.0; format ascii; class volScalarField; object p; }
dimensions [0 2 -2 0 0 0 0];
internalField uniform 0;
boundaryField { ".*" { type zeroGradient; } }
EOT
        cat > system/fvSchemes <<'EOT'
FoamFile { version 2.0; format ascii; class dictionary; object fvSchemes; }
ddtSchemes { default Euler; }
gradSchemes { default Gauss linear; }
divSchemes { default none; div(phi,U) Gauss linear; div((nuEff*dev2(T(grad(U))))) Gauss linear; }
laplacianSchemes { default Gauss linear corrected; }
interpolationSchemes { default linear; }
snGradSchemes { default corrected; }
EOT
        cat > system/fvSolution <<'EOT'
FoamFile { version 2.0; format ascii; class dictionary; object fvSolution; }
solvers
{
    "(p|pFinal)" { solver PCG; preconditioner DIC; tolerance 1e-8; relTol 0; }
    "(U|UFinal)" { solver PBiCGStab; preconditioner DILU; tolerance 1e-8; relTol 0; }
}
PIMPLE { nOuterCorrectors 1; nCorrectors 2; nNonOrthogonalCorrectors 0; pRefCell 0; pRefValue 0; }
EOT
        snow_cloud "" "$(
            echo "        #include \"regime.coeffs\""
            echo "        patches ( wall { type snow; } \"(top|sides)\" { type escape; } );")"
        foamDictionary -entry application -set pimpleUncoupledKinematicParcelFoam system/controlDict > /dev/null
        foamDictionary -entry functions -set '{}' system/controlDict > /dev/null
        foamDictionary -entry endTime -set 0.04 system/controlDict > /dev/null
        foamDictionary -entry writeInterval -set 0.04 system/controlDict > /dev/null
        run log.blockMesh blockMesh
    )
}
# set_replay DIR START PERIOD INTERVAL: the replay dictionary of system/controlDict
set_replay() {
    foamDictionary -entry replay -set "{ start $2; period $3; interval $4; fields (U p); }" \
        "$1/system/controlDict" > /dev/null
}
# expect_refusal DIR PATTERN: a FatalIOError with PATTERN, before the first time step
expect_refusal() {
    local t0=$SECONDS rc=0
    (cd "$1" && "$solver" -replay > log.run 2>&1) || rc=$?
    if [ "$rc" != 1 ] || ! grep -q "FOAM FATAL IO ERROR" "$1/log.run"; then
        tail -20 "$1/log.run" >&2
        fail "$1: exit $rc without a FatalIOError, expected one with '$2'"
    fi
    grep -qF -- "$2" "$1/log.run" || { tail -20 "$1/log.run" >&2; fail "$1: no '$2' in the error"; }
    ! grep -q '^Time = ' "$1/log.run" || fail "$1: time steps were run before the refusal"
    [ $((SECONDS - t0)) -le 60 ] || fail "$1: the refusal took $((SECONDS - t0)) s"
}

# 1. a library that fits: the estimate, then taken and played back
c="$tmp/ok"
make_case "$c" 4
set_replay "$c" 0 0.02 0.005
(cd "$c" && run log.run "$solver" -replay)
line=$(grep '^Replay: [0-9]* snapshots x' "$c/log.run") || fail "ok: no estimate line"
echo "$line"
echo "$line" | awk '{ n = $2; m = $5; k = $8; x = $11
    exit !(n == 4 && m == 64 && k == 4 && x > 0.99 * n * m * k * 8 / 1e9 && x < 1.01 * n * m * k * 8 / 1e9) }' ||
    fail "ok: the estimate is not 4 snapshots x 64 cells x 4 values x 8 bytes: $line"
echo "$line" | grep -q 'GB available' || fail "ok: no available memory in: $line"
grep -q 'Replay: library complete, 4 snapshots' "$c/log.run" || fail "ok: the library was not completed"
grep -q 'the flow is played back' "$c/log.run" || fail "ok: the flow was not played back"

# 1b. phi: listed in fields, it is played back with them (at 0.025 s, one interval into
# the playback, the flux is snapshot 1's, the solved flux of 0.005 s, to 1e-6): the
# fluxes keep continuity, as the parcels' faceFlux interpolation needs; not listed, it
# is rebuilt from U (fvc::flux) and differs from the solved flux
phi_ascii() {  # phi_ascii DIR TIME: the internal face fluxes of TIME, one a line
    awk '/^internalField/ { f = 1; next } f && /^\(/ { g = 1; next } g && /^\)/ { exit } g { print }' "$1/$2/phi"
}
for fl in "U p phi" "U p"; do
    c="$tmp/phi${fl// /}"
    make_case "$c" 4
    foamDictionary -entry replay -set "{ start 0; period 0.02; interval 0.005; fields ($fl); }" \
        "$c/system/controlDict" > /dev/null
    foamDictionary -entry writePrecision -set 17 "$c/system/controlDict" > /dev/null
    foamDictionary -entry writeInterval -set 0.005 "$c/system/controlDict" > /dev/null
    foamDictionary -entry endTime -set 0.025 "$c/system/controlDict" > /dev/null
    (cd "$c" && run log.run "$solver" -replay)
    rel=$(paste <(phi_ascii "$c" 0.005) <(phi_ascii "$c" 0.025) | awk '
        { d = $1 - $2; if (d < 0) d = -d; a = $1 < 0 ? -$1 : $1; if (d > m) m = d; if (a > s) s = a; n++ }
        END { if (n != 144 || s == 0) print "bad", n; else printf "%.3g\n", m / s }')
    echo "replay fields ($fl): phi at 0.025 s against the solved phi of 0.005 s, largest difference $rel of the largest flux"
    case "$fl" in
        *phi) awk -v r="$rel" 'BEGIN { exit !(r + 0 == r && r <= 1e-6) }' || fail "phi listed: not played back ($rel)" ;;
        *) awk -v r="$rel" 'BEGIN { exit !(r + 0 == r && r > 1e-6) }' || fail "phi not listed: not rebuilt from U ($rel)" ;;
    esac
done

# 2. the time step against interval
c="$tmp/fixed"
make_case "$c" 4
set_replay "$c" 0 0.02 0.001          # deltaT 0.005 fixed
expect_refusal "$c" "fixed time step deltaT 0.005 s (adjustTimeStep off) is longer than 'interval' 0.001"
grep -q "replay" "$c/log.run" || fail "fixed: the error does not name replay"

c="$tmp/adjust"
make_case "$c" 4
set_replay "$c" 0 0.02 0.001
foamDictionary -entry adjustTimeStep -set yes "$c/system/controlDict" > /dev/null
foamDictionary -entry maxCo -set 0.5 "$c/system/controlDict" > /dev/null
expect_refusal "$c" "adjustTimeStep with maxDeltaT unlimited (not set) longer than 'interval' 0.001"
foamDictionary -entry maxDeltaT -set 0.002 "$c/system/controlDict" > /dev/null
expect_refusal "$c" "maxDeltaT 0.002 s longer than 'interval' 0.001"
# maxDeltaT equal to interval: accepted (the wedge's default, 1e-3 and 1e-3)
foamDictionary -entry maxDeltaT -set 0.001 "$c/system/controlDict" > /dev/null
foamDictionary -entry endTime -set 0.003 "$c/system/controlDict" > /dev/null
set_replay "$c" 0 0.002 0.001
(cd "$c" && run log.run "$solver" -replay)
grep -q '^Replay: 2 snapshots x 64 cells' "$c/log.run" || fail "adjust: maxDeltaT = interval not accepted"

# a misspelt key is named, not ignored; memoryFraction outside (0, 1] refused
c="$tmp/typo"
make_case "$c" 4
foamDictionary -entry replay -set "{ start 0; period 0.02; interval 0.005; fields (U p); memoryFracton 0.5; }" \
    "$c/system/controlDict" > /dev/null
expect_refusal "$c" "replay: unknown key 'memoryFracton'"
for v in 0 -1 1e300; do
    foamDictionary -entry replay -set "{ start 0; period 0.02; interval 0.005; fields (U p); memoryFraction $v; }" \
        "$c/system/controlDict" > /dev/null
    expect_refusal "$c" "replay: 'memoryFraction' must be in (0, 1]"
done

# 4. resuming (store yes): a run stopped at T and started again from its last written
# time (startFrom latestTime) ends with the flow of a run that was never stopped, to
# 1e-9: stopped after the library (0.03 s: every snapshot read back) and inside it
# (0.01 s: three read back, the fourth taken after the restart). The box's writes
# are ascii with 17 digits, so the restart time's fields are exact (the library is
# binary whatever the case's format).
# Refused before the first step: a late start without store, and a stored library
# with a snapshot missing.
resume_case() {  # resume_case DIR END: a stored library 0 .. 0.02 s, writes every 0.01 s to END
    make_case "$1" 4
    foamDictionary -entry replay -set "{ start 0; period 0.02; interval 0.005; fields (U p phi); store yes; }" \
        "$1/system/controlDict" > /dev/null
    foamDictionary -entry writePrecision -set 17 "$1/system/controlDict" > /dev/null
    foamDictionary -entry writeInterval -set 0.01 "$1/system/controlDict" > /dev/null
    foamDictionary -entry endTime -set "$2" "$1/system/controlDict" > /dev/null
}
u_ascii() {  # u_ascii DIR TIME: the internal U of TIME, one component a line
    awk '/^internalField/ { f = 1; next } f && /^\(/ && NF == 3 { gsub(/[()]/, ""); print $1; print $2; print $3 } f && /^\)/ { exit }' "$1/$2/U"
}
c="$tmp/whole"
resume_case "$c" 0.06
(cd "$c" && run log.run "$solver" -replay)
[ "$(wc -l < "$c/replayLibrary/times")" = 4 ] || fail "whole: replayLibrary/times does not list 4 snapshots"
[ -f "$c/replayLibrary/3/U" ] && [ -f "$c/replayLibrary/3/p" ] && [ -f "$c/replayLibrary/3/phi" ] ||
    fail "whole: snapshot 3 not written (U, p, phi)"
grep -q 'format *binary' "$c/replayLibrary/0/U" || fail "whole: snapshot 0 not binary"
u_ascii "$c" 0.06 > "$tmp/u.whole"
[ "$(wc -l < "$tmp/u.whole")" = 192 ] || fail "whole: U at 0.06 s has $(wc -l < "$tmp/u.whole") values, want 64 x 3"
for stop in 0.03 0.01; do
    c="$tmp/stop$stop"
    resume_case "$c" "$stop"
    (cd "$c" && run log.run1 "$solver" -replay)
    foamDictionary -entry endTime -set 0.06 "$c/system/controlDict" > /dev/null
    (cd "$c" && run log.run2 "$solver" -replay)
    # the library completed by the first run (stopped after it) or the second
    want=4 done=1; [ "$stop" = 0.03 ] || want=3 done=2
    grep -q "^Replay: resumed at $stop s: $want of 4 snapshots read back" "$c/log.run2" ||
        { tail -20 "$c/log.run2" >&2; fail "stop $stop: not resumed with $want snapshots read back"; }
    grep -q 'Replay: library complete, 4 snapshots' "$c/log.run$done" || fail "stop $stop: the library was not completed in run $done"
    head -1 <(grep '^Time = ' "$c/log.run2") | grep -q "^Time = $(awk -v s="$stop" 'BEGIN { print s + 0.005 }')\$" ||
        fail "stop $stop: the second run does not start after $stop s"
    u_ascii "$c" 0.06 > "$tmp/u.stop"
    paste "$tmp/u.whole" "$tmp/u.stop" | awk '{ d = $1 - $2; if (d < 0) d = -d; if (d > m) m = d; n++ }
        END { printf "resume at %s s: %d values, largest |U - U_whole| %.3g\n", s, n, m; exit !(n == 192 && m <= 1e-9) }' s="$stop" ||
        fail "stop $stop: U at 0.06 s is not the uninterrupted run's"
done
# streaming (stream yes): the snapshots read back from disk when played, two in memory:
# U at 0.06 s the in-memory run's to the last bit, also resumed after the library
c="$tmp/stream"
resume_case "$c" 0.06
foamDictionary -entry replay -set "{ start 0; period 0.02; interval 0.005; fields (U p phi); store yes; stream yes; }" \
    "$c/system/controlDict" > /dev/null
(cd "$c" && run log.run "$solver" -replay)
grep -q '^Replay: the library is streamed: every snapshot is kept on disk only' "$c/log.run" || fail "stream: not announced"
u_ascii "$c" 0.06 > "$tmp/u.stream"
cmp -s "$tmp/u.whole" "$tmp/u.stream" || fail "stream: U at 0.06 s is not the in-memory run's to the last bit"
rm -rf "$c"/0.0[3-6]*
(cd "$c" && run log.run2 "$solver" -replay)
grep -q '^Replay: resumed at 0.02 s: 4 of 4 snapshots read back' "$c/log.run2" || { tail -5 "$c/log.run2" >&2; fail "stream: not resumed"; }
u_ascii "$c" 0.06 > "$tmp/u.stream2"
cmp -s "$tmp/u.whole" "$tmp/u.stream2" || fail "stream: resumed, U at 0.06 s is not the in-memory run's"
echo "stream: U at 0.06 s the in-memory run's to the last bit, also resumed at 0.02 s"
for v in "stream yes;" "stream maybe; store yes;"; do
    foamDictionary -entry replay -set "{ start 0; period 0.02; interval 0.005; fields (U p); $v }" \
        "$c/system/controlDict" > /dev/null
    case "$v" in *maybe*) want="replay: 'stream' must be auto, yes or no, got 'maybe'" ;; *) want="'stream yes' reads the snapshots back from disk: it needs 'store yes'" ;; esac
    rm -rf "$c"/0.0*; expect_refusal "$c" "$want"
done
# refusals: a late start without store; a snapshot missing from the stored library
c="$tmp/stop0.03"
foamDictionary -entry replay -set "{ start 0; period 0.02; interval 0.005; fields (U p); }" \
    "$c/system/controlDict" > /dev/null
foamDictionary -entry endTime -set 0.08 "$c/system/controlDict" > /dev/null
expect_refusal "$c" "or resume a run whose library was stored: store yes"
foamDictionary -entry replay -set "{ start 0; period 0.02; interval 0.005; fields (U p); store yes; }" \
    "$c/system/controlDict" > /dev/null
sed -i '$d' "$c/replayLibrary/times"
expect_refusal "$c" "but 3 are there"
grep -q "the 4 snapshots taken by then are read back from" "$c/log.run" || fail "missing snapshot: the error does not say what was due"

# store yes never writes over what is not the library's: a FIFO at replayLibrary/times,
# a link at a snapshot's field, a file where the folder goes: refused before any step,
# the thing left as it was; a foreign file beside the library kept
c="$tmp/targets"
resume_case "$c" 0.02
notlib() {  # notlib WHAT PATTERN: the solver refuses before its first step, naming it
    local rc=0
    (cd "$c" && "$solver" -replay > log.run 2>&1) || rc=$?
    [ "$rc" = 1 ] && grep -q "$2" "$c/log.run" && ! grep -q '^Time = ' "$c/log.run" ||
        { tail -5 "$c/log.run" >&2; fail "targets, $1: exit $rc, not refused before the first step"; }
}
mkdir -p "$c/replayLibrary"; mkfifo "$c/replayLibrary/times"
notlib "a FIFO at times" "replayLibrary/times\" exists and is not a regular file"
[ -p "$c/replayLibrary/times" ] || fail "targets: the FIFO was replaced"
rm -rf "$c/replayLibrary"; mkdir -p "$c/replayLibrary/2"; ln -s /dev/null "$c/replayLibrary/2/U"
notlib "a link at snapshot 2's U" "replayLibrary/2/U\" exists and is not a regular file"
[ -L "$c/replayLibrary/2/U" ] || fail "targets: the link was replaced"
rm -rf "$c/replayLibrary"; echo theirs > "$c/replayLibrary"
notlib "a file where the folder goes" "replayLibrary\" exists and is not a folder"
[ "$(cat "$c/replayLibrary")" = theirs ] || fail "targets: the file was replaced"
rm -f "$c/replayLibrary"; mkdir "$c/replayLibrary"; echo theirs > "$c/replayLibrary/notes.txt"
(cd "$c" && run log.run "$solver" -replay)
[ "$(cat "$c/replayLibrary/notes.txt")" = theirs ] && [ -s "$c/replayLibrary/3/U" ] || fail "targets: a foreign file beside the library"
echo "store: a FIFO, a link and a file in the library's place refused, a foreign file beside it kept"

# 5. -checkpoint S: every step whose wall clock since the last write reaches S is also
# written (here S = 1e-9 s: every step), the steps unchanged: the same U at the end
# as the run without checkpoints; S not a positive number refused
c="$tmp/checkpoint"
resume_case "$c" 0.06
(cd "$c" && run log.run "$solver" -replay -checkpoint 1e-9)
n=$(cd "$c" && ls -d 0.0* | wc -l)
[ "$n" = 12 ] || fail "checkpoint: $n time folders after 0, want the 12 steps of 0.005 s to 0.06 s"
grep -q '^Checkpoint: a write whenever [0-9.e-]* s of wall clock' "$c/log.run" || fail "checkpoint: not announced"
u_ascii "$c" 0.06 > "$tmp/u.ckpt"
cmp -s "$tmp/u.whole" "$tmp/u.ckpt" || fail "checkpoint: U at 0.06 s is not the run's without checkpoints"
for v in 0 -1 nan inf abc 5s 1e999; do
    (cd "$c" && "$solver" -replay -checkpoint "$v" > log.bad 2>&1) && fail "checkpoint $v: accepted"
    grep -q -- "-checkpoint: a positive number of seconds of wall clock, got $v" "$c/log.bad" ||
        { tail -5 "$c/log.bad" >&2; fail "checkpoint $v: no named error"; }
done
echo "checkpoint: every step written, U at 0.06 s unchanged; 0, -1, nan, inf, abc, 5s, 1e999 refused"
# -speedScale (with -frozen only): a factor in [0.001, 1000]; 1e999 refused by name, not
# by the overflow trap
for v in 0 -1 nan 1e999 2000 abc; do
    (cd "$c" && "$solver" -frozen -speedScale "$v" > log.bad 2>&1) && fail "speedScale $v: accepted"
    grep -q -- "-speedScale: a factor from 0.001 to 1000, got $v" "$c/log.bad" ||
        { tail -5 "$c/log.bad" >&2; fail "speedScale $v: no named error"; }
done
(cd "$c" && "$solver" -speedScale 0.5 > log.bad 2>&1) && fail "speedScale without -frozen: accepted"
grep -q -- "-speedScale scales the held flow: give -frozen too" "$c/log.bad" || fail "speedScale without -frozen: no named error"
echo "speedScale: 0, -1, nan, 1e999, 2000, abc and no -frozen refused"

# 3. memory: 100 000 snapshots of U and p (32 bytes a cell) on a mesh whose library is
# about twice MemAvailable: refused at once, with the estimate
avail=$(awk '$1 == "MemAvailable:" { print $2 * 1024 }' /proc/meminfo)
[ -n "$avail" ] || { echo "SKIP (part): /proc/meminfo has no MemAvailable"; exit 0; }
n=$(awk -v a="$avail" 'BEGIN { n = int((2 * a / (1e5 * 32)) ^ (1 / 3)) + 1; print (n < 4) ? 4 : n }')
c="$tmp/memory"
make_case "$c" "$n"
set_replay "$c" 0 100 0.001           # 100 000 snapshots
foamDictionary -entry deltaT -set 0.001 "$c/system/controlDict" > /dev/null
expect_refusal "$c" "replay: the library of 'period' 100 s / 'interval' 0.001 s = 100000 snapshots"
grep -q "GB available (MemAvailable of /proc/meminfo)" "$c/log.run" || fail "memory: the error does not give the available memory"
grep '^Replay: 100000 snapshots' "$c/log.run" || fail "memory: no estimate line before the refusal"
# the same library stored (stream auto): streamed from disk instead of refused
foamDictionary -entry replay -set "{ start 0; period 100; interval 0.001; fields (U p); store yes; }" \
    "$c/system/controlDict" > /dev/null
foamDictionary -entry endTime -set 0.003 "$c/system/controlDict" > /dev/null
(cd "$c" && run log.run "$solver" -replay)
grep -q '^Replay: the library is streamed: .*: the library does not fit in memory' "$c/log.run" || fail "memory, store yes: not streamed"
[ -s "$c/replayLibrary/3/U" ] || fail "memory, store yes: the snapshots not on disk"
echo "memory, store yes: streamed from disk"
echo "PASS: replay set-up checks (estimate, time step, keys, memory at $n^3 cells)"
