# shellcheck shell=bash
# stock.sh - sourced (after common.sh) by the tests that run Debian's stock Lagrangian
# tutorials with snowWallInteraction (test_stock_*.sh).
#
# The cases are copied from the openfoam-examples package at test time and changed only
# by (a) the documented lines of doc/wallmodel.md (dropin), (b) shortening (endTime,
# writeInterval) and (c) instrumentation that does not touch the physics: writePrecision
# 12 (the mass balance is checked to 1e-6, the log's default 6 digits cannot show it) and
# a patchPostProcessing cloud function that records every hit on the wall patches.
examples=/usr/share/doc/openfoam-examples/examples

# stock_copy TUTORIAL DEST: copy a stock tutorial (skip, 77, when not installed)
stock_copy() {
    [ -d "$examples/$1" ] || { echo "SKIP: $examples/$1 not installed (openfoam-examples)"; exit 77; }
    cp -r "$examples/$1" "$2"
    find "$2" -name '*.gz' -exec gunzip {} +
}

# shorten CASE END [DELTAT]: endTime END, one write at the end, writePrecision 12
shorten() {
    local d="$1/system/controlDict" wc=runTime
    foamDictionary -entry endTime -set "$2" "$d" > /dev/null
    if [ -n "${3:-}" ]; then foamDictionary -entry deltaT -set "$3" "$d" > /dev/null; fi
    case "$(foamDictionary -entry adjustTimeStep -value "$d" 2>/dev/null || true)" in
        yes|on|true) wc=adjustableRunTime ;;
    esac
    foamDictionary -entry writeControl -set "$wc" "$d" > /dev/null
    foamDictionary -entry writeInterval -set "$2" "$d" > /dev/null
    foamDictionary -entry writePrecision -set 12 "$d" > /dev/null
}

# count_hits CLOUDFILE PATCHES: instrumentation, a patchPostProcessing cloud function
# that records every hit on PATCHES (a list "(a b)"), before any interaction model
count_hits() {
    foamDictionary -entry cloudFunctions -set \
        "{ wallHits { type patchPostProcessing; maxStoredParcels 100000000; patches $2; } }" \
        "$1" > /dev/null
}

# hits CASE CLOUD PATCH: the hits recorded on PATCH over the run (all write times)
hits() {
    local n=0 f
    for f in "$1"/postProcessing/lagrangian/"$2"/wallHits/*/"$3".post; do
        [ -f "$f" ] || continue
        n=$((n + $(grep -vc '^#' "$f" || true)))
    done
    echo "$n"
}

# dropin CASE CLOUDFILE ENTRY...: the documented lines (doc/wallmodel.md): libs in
# controlDict; the cloud's patchInteractionModel replaced by snowWallInteraction; its
# coefficients (#include "regime.coeffs" and the patches ENTRY...) added after it; the
# regime file copied into constant/
dropin() {
    local c=$1 props="$1/constant/$2"; shift 2
    cp "$fixture" "$c/constant/regime.coeffs"
    if ! grep -q 'libsnowWallInteraction.so' "$c/system/controlDict"; then
        sed -i 's/^application .*/&\nlibs ("libsnowWallInteraction.so");/' "$c/system/controlDict"
    fi
    grep -q '^libs ("libsnowWallInteraction.so");' "$c/system/controlDict" \
        || fail "$c: no 'application' line to add libs after"
    local entries="$*"
    sed -i "s/^\( *\)patchInteractionModel  *[A-Za-z]*;/\1patchInteractionModel snowWallInteraction;\n\1snowWallInteractionCoeffs\n\1{\n\1    #include \"regime.coeffs\"\n\1    patches ( $entries );\n\1}/" "$props"
    [ "$(grep -c 'patchInteractionModel snowWallInteraction;' "$props")" = 1 ] \
        || fail "$props: expected one patchInteractionModel line to replace"
}

# cloud_block LOG CLOUD: the last report of CLOUD in LOG (its "Cloud: CLOUD" line and
# the indented lines under it)
cloud_block() {
    awk -v c="Cloud: $2" '
        $0 == c { n = 0; on = 1; delete b; next }
        on && /^ / { b[++n] = $0; next }
        on { on = 0; for (i = 1; i <= n; i++) last[i] = b[i]; ln = n }
        END { if (on) { for (i = 1; i <= n; i++) last[i] = b[i]; ln = n }
              for (i = 1; i <= ln; i++) print last[i] }
    ' "$1"
}

# balance LOG CLOUD: "injected airborne escaped deposited transferred relErr" of the
# cloud's last report: injected = sum of "mass introduced"; airborne = "Current mass in
# system"; escaped = the cloud's "Parcel fate: system" escape; deposited = the snow
# patches' "deposited mass"; transferred = phase change + devolatilisation + surface
# reaction; relErr = |injected - (airborne + escaped + deposited + transferred)| / injected
balance() {
    cloud_block "$1" "$2" | awk '
        /mass introduced/ { inj += $NF }
        /Current mass in system/ { air = $NF }
        /Parcel fate: system/ { sys = 1; next }
        sys && /- escape/ { split($0, a, "="); split(a[2], b, ","); esc = b[2] + 0; sys = 0 }
        /snowWall: patch .*deposited mass/ { s = $0; sub(/.*deposited mass /, "", s); sub(/ kg.*/, "", s); dep += s }
        /Mass transfer (phase change|devolatilisation|surface reaction)/ { tr += $NF }
        END {
            if (inj <= 0) { print "0 0 0 0 0 1"; exit }
            e = inj - (air + esc + dep + tr); if (e < 0) e = -e
            printf "%.12g %.12g %.12g %.12g %.12g %.3g\n", inj, air, esc, dep, tr, e / inj
        }'
}

# check_balance LOG CLOUD: fail unless the balance closes to 1e-6; print it
check_balance() {
    local b; b=$(balance "$1" "$2")
    awk -v b="$b" 'BEGIN { split(b, a, " "); exit !(a[1] > 0 && a[6] <= 1e-6) }' \
        || fail "$1: mass balance of $2 does not close to 1e-6 (injected airborne escaped deposited transferred relErr: $b)"
    echo "$2 mass balance (injected airborne escaped deposited transferred relErr): $b"
}

# snow_counts LOG PATCH [CLOUD]: "impacts sticks bounces ripoffs" of PATCH in the last
# summary (of CLOUD's last report, when the log has several clouds)
snow_counts() {
    if [ -n "${3:-}" ]; then cloud_block "$1" "$3"; else cat "$1"; fi \
        | grep "snowWall: patch $2: impacts" | tail -n 1 \
        | sed 's/.*impacts \([0-9]*\), sticks \([0-9]*\), bounces \([0-9]*\), ripoffs \([0-9]*\).*/\1 \2 \3 \4/'
}

# escaped_parcels LOG CLOUD: the escaped parcels of the cloud's "Parcel fate: system" line
# in its last report
escaped_parcels() {
    cloud_block "$1" "$2" | awk '/Parcel fate: system/ { s = 1; next }
        s && /- escape/ { split($0, a, "="); split(a[2], b, ","); print b[1] + 0; exit }'
}

# patch_values FILE PATCH: the face values of PATCH's value entry, one per line ("uniform X"
# gives "uniform X"), whatever the list layout (one line or many)
patch_values() {
    foamDictionary -entry "boundaryField/$2/value" -value "$1" | tr '()' '  ' | awk '
        { for (i = 1; i <= NF; i++) t[++n] = $i }
        END {
            if (t[1] == "uniform") { print "uniform " t[2]; exit }
            # nonuniform List<scalar> N v1 ... vN
            for (i = 4; i <= n; i++) print t[i]
        }'
}

# same_patch_field FILE1 FILE2 PATCH [TOL]: the two fields agree on PATCH to TOL (relative,
# default 1e-9); a "uniform X" side stands for X on every face of the other side
same_patch_field() {
    awk -v tol="${4:-1e-9}" '
        function rel(a, b) { d = a - b; if (d < 0) d = -d; m = (a < 0 ? -a : a); return d <= tol * (m > 0 ? m : 1) }
        FNR == 1 { f++ }
        f == 1 { if ($1 == "uniform") u1 = $2; else a[++n1] = $1; next }
        { if ($1 == "uniform") u2 = $2; else b[++n2] = $1 }
        END {
            if (u1 != "" && u2 != "") exit !rel(u1, u2)
            if (u1 != "") { for (i = 1; i <= n2; i++) if (!rel(u1, b[i])) exit 1; exit !(n2 > 0) }
            if (u2 != "") { for (i = 1; i <= n1; i++) if (!rel(a[i], u2)) exit 1; exit !(n1 > 0) }
            if (n1 != n2) exit 1
            for (i = 1; i <= n1; i++) if (!rel(a[i], b[i])) exit 1
        }' <(patch_values "$1" "$3") <(patch_values "$2" "$3")
}

# run_np2 CASE SOLVER "N": decomposePar into 2 with the simple method, subdomains N (e.g.
# "(1 1 2)"; the stock decomposeParDicts ask for scotch, a dummy in Debian's build), mpirun
# -np 2, reconstructPar of the last time; logs log.decomposePar, log.run, log.reconstructPar
run_np2() {
    cat > "$1/system/decomposeParDict" <<EOD
FoamFile { version 2.0; format ascii; class dictionary; object decomposeParDict; }
numberOfSubdomains 2;
method simple;
simpleCoeffs { n $3; delta 0.001; }
EOD
    (cd "$1" && run log.decomposePar decomposePar \
        && run log.run mpirun -np 2 --oversubscribe "$2" -parallel \
        && run log.reconstructPar reconstructPar -latestTime)
}
