#!/usr/bin/env bash
# etc/setup.sh - make a Debian 12 machine ready to build and run SnowWall.
#
# Usage: etc/setup.sh [--help] [--no-openfoam] [--stock-solvers NAME[,NAME...]] [--lammps]
#
# Installs (as root, with apt-get) the Debian packages SnowWall needs (among
# them Code_Saturne 6.0 and gfortran, for the Code_Saturne binding's test), then
# fetches the Debian *source* package of OpenFOAM v1912 and unpacks only
# src/, wmake/, META-INFO, bin/tools (RunFunctions, for the stock tutorials'
# Allrun scripts) and the pimpleFoam solver folder (whose flow equations
# the project's solver includes) into the git-ignored cache .cache/openfoam,
# builds wmake's helpers and the lnInclude folders a Lagrangian model needs.
# Every step is skipped when its result is already there, so a second run
# does no downloads and returns in well under 5 s.
#
# --no-openfoam   install only what the C parts need (compiler, cmake, GSL,
#                 cmocka, gnuplot); skip OpenFOAM and its headers, and Code_Saturne.
# --stock-solvers NAME[,NAME...]
#                 opt-in, not part of the default set-up (minutes of compiling):
#                 also rebuild these stock v1912 solvers, which Debian's build of
#                 them breaks, from the source package with the fix, into
#                 platforms/bin (FOAM_USER_APPBIN, first on PATH after sourcing
#                 etc/openfoam-env.sh). Accepted names: MPPICFoam, reactingParcelFoam;
#                 both are built with -D__restrict__= (their fvc::reconstruct
#                 breaks the __restrict__ promise of OpenFOAM's loop macros, which
#                 GCC 12 relies on: wrong on non-Cartesian cells; doc/wallmodel.md,
#                 "Stock solvers rebuilt"). Skipped when already built with the same fix;
#                 the first build takes about 1-2 min a solver on 2 cores.
# --lammps        opt-in, not part of the default set-up: also install Debian's
#                 LAMMPS (package lammps, the `lmp` binary, 29 Sep 2021 on Debian 12)
#                 for the rough-wall cross-check validation/lammps-rough.sh and its
#                 test lammps_rough (skipped without it). Skipped when installed;
#                 goes with --no-openfoam too.
#
# Exit status: 0 ready, 1 a step failed or a bad option (the message names it).
set -euo pipefail

top=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
want_of=1
stock=()              # --stock-solvers: the stock solvers to rebuild with the fix
want_lammps=0         # --lammps: Debian's LAMMPS for validation/lammps-rough.sh
stock_known=(MPPICFoam reactingParcelFoam)
stock_list() {        # stock_list LIST: check each name of the comma list, add it once
    local n k ok names
    [ -n "$1" ] || { echo "setup.sh: --stock-solvers needs a list of solver names (accepted: ${stock_known[*]})" >&2; exit 1; }
    IFS=, read -r -a names <<< "$1"
    for n in "${names[@]}"; do
        ok=0
        for k in "${stock_known[@]}"; do [ "$n" = "$k" ] && ok=1; done
        [ "$ok" = 1 ] || { echo "setup.sh: --stock-solvers: unknown solver '$n' (accepted: ${stock_known[*]})" >&2; exit 1; }
        case " ${stock[*]:-} " in *" $n "*) ;; *) stock+=("$n") ;; esac
    done
}
while [ $# -gt 0 ]; do
    case "$1" in
        -h|--help) awk 'NR > 1 && !/^#/ { exit } NR > 1 { sub(/^# ?/, ""); print }' "$0"; exit 0 ;;
        --no-openfoam) want_of=0 ;;
        --stock-solvers) [ $# -ge 2 ] || stock_list ""; stock_list "$2"; shift ;;
        --stock-solvers=*) stock_list "${1#--stock-solvers=}" ;;
        --lammps) want_lammps=1 ;;
        *) echo "setup.sh: unknown option '$1' (see --help)" >&2; exit 1 ;;
    esac
    shift
done
if [ "$want_of" = 0 ] && [ ${#stock[@]} -gt 0 ]; then
    echo "setup.sh: --stock-solvers needs OpenFOAM: it cannot go with --no-openfoam" >&2; exit 1
fi

say() { printf 'setup: %s\n' "$*"; }
die() { printf 'setup: error: %s\n' "$*" >&2; exit 1; }

c_pkgs=(build-essential cmake pkg-config libgsl-dev libcmocka-dev gnuplot-nox universal-ctags
        libpng-dev libjpeg-dev)
of_pkgs=(openfoam openfoam-examples openmpi-bin libopenmpi-dev dpkg-dev)
# Code_Saturne 6.0 (tests/codesaturne): the solver, its headers, its Python
# scripts and user templates; gfortran builds a case's Fortran user file
cs_pkgs=(code-saturne-bin code-saturne-include code-saturne-data gfortran)
# LAMMPS (opt-in --lammps): the rough-wall cross-check (validation/lammps-rough.sh)
lammps_pkgs=(lammps)
pkgs=("${c_pkgs[@]}")
[ "$want_of" = 1 ] && pkgs+=("${of_pkgs[@]}" "${cs_pkgs[@]}")
[ "$want_lammps" = 1 ] && pkgs+=("${lammps_pkgs[@]}")

missing=()
for p in "${pkgs[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" \
        || missing+=("$p")
done
SUDO=
[ "$(id -u)" = 0 ] || SUDO=sudo
if [ ${#missing[@]} -gt 0 ]; then
    say "installing Debian packages: ${missing[*]}"
    export DEBIAN_FRONTEND=noninteractive
    $SUDO apt-get update -qq || die "apt-get update failed"
    $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null \
        || die "apt-get install ${missing[*]} failed"
else
    say "Debian packages present"
fi
[ "$want_of" = 1 ] || { say "ready (C parts only)"; exit 0; }

# --- OpenFOAM v1912 headers and wmake from the Debian source package ---
cache="$top/.cache/openfoam"
ofdir="$cache/openfoam-OpenFOAM-v1912.200626"
stamp="$cache/.ready"
pimple=applications/solvers/incompressible/pimpleFoam

# --- opt-in (--stock-solvers): stock solvers rebuilt from the source package with the fix ---
# stock_spec NAME sets s_dir (the solver's folder in the source tree), s_unpack (folders
# of the orig tarball it needs), s_lninc (folders under src/ whose lnInclude it needs),
# s_applninc (the same for folders beside the solver) and s_flags (the fix: extra
# compiler flags, through wmake's FOAM_EXTRA_CXXFLAGS)
stock_spec() {
    s_lninc=(); s_applninc=()
    case "$1" in
        MPPICFoam)
            # fvc::reconstruct's inv(tmp) & tmp reuses its input's storage while the
            # loop macros declare it __restrict__: GCC 12 overwrites the input before
            # reading it on skewed cells (doc/wallmodel.md)
            s_dir=applications/solvers/lagrangian/DPMFoam/MPPICFoam
            s_unpack=(applications/solvers/lagrangian/DPMFoam)
            s_lninc=(TurbulenceModels/phaseIncompressible)
            s_applninc=(applications/solvers/lagrangian/DPMFoam/DPMTurbulenceModels)
            s_flags="-D__restrict__=" ;;
        reactingParcelFoam)
            # the same fvc::reconstruct, in its momentum predictor (UEqn.H): wrong on
            # 1050 of verticalChannel's cells, whose step 2 then stops in
            # heRhoThermo::correct (doc/wallmodel.md)
            s_dir=applications/solvers/lagrangian/reactingParcelFoam
            s_unpack=(applications/solvers/lagrangian/reactingParcelFoam
                      applications/solvers/combustion/reactingFoam)
            s_lninc=(sampling thermophysicalModels/chemistryModel ODE combustionModels)
            s_flags="-D__restrict__=" ;;
    esac
}

# stock_build: build each solver of --stock-solvers into platforms/bin, unless the one
# there was built with the same fix (its stamp platforms/bin/.NAME.stock holds the flags)
stock_build() {
    [ ${#stock[@]} -gt 0 ] || return 0
    # shellcheck source=openfoam-env.sh
    . "$top/etc/openfoam-env.sh"
    local n d l exe mark log
    [ -n "${orig:-}" ] || orig=$(ls "$cache"/openfoam_1912.200626.orig.tar.* 2>/dev/null | head -n1 || true)
    local todo=() get=()
    for n in "${stock[@]}"; do
        stock_spec "$n"
        exe="$FOAM_USER_APPBIN/$n" mark="$FOAM_USER_APPBIN/.$n.stock"
        if [ -x "$exe" ] && [ -f "$mark" ] && [ "$(cat "$mark")" = "$s_flags" ]; then
            say "stock $n already built with '$s_flags' in ${exe#$top/}"
            continue
        fi
        todo+=("$n")
        for d in "${s_unpack[@]}"; do
            [ -d "$ofdir/$d" ] || get+=("openfoam-OpenFOAM-v1912.200626/$d")
        done
    done
    [ ${#todo[@]} -gt 0 ] || return 0
    if [ ${#get[@]} -gt 0 ]; then
        # one pass over the tarball (about 10 s each)
        say "unpacking ${get[*]#openfoam-OpenFOAM-v1912.200626/} from ${orig##*/}"
        [ -n "$orig" ] || die "no openfoam_1912.200626.orig.tar.* in $cache (run etc/setup.sh without --stock-solvers first?)"
        tar -xf "$orig" -C "$cache" "${get[@]}" || die "unpacking ${get[*]} from $orig failed"
    fi
    for n in "${todo[@]}"; do
        stock_spec "$n"
        exe="$FOAM_USER_APPBIN/$n" mark="$FOAM_USER_APPBIN/.$n.stock"
        for l in "${s_lninc[@]}"; do
            [ -d "$FOAM_SRC/$l" ] || continue   # a -I folder of Make/options that v1912 lacks
            (cd "$FOAM_SRC" && wmakeLnInclude -u "$l" >/dev/null 2>&1) || die "wmakeLnInclude $l failed"
        done
        for l in "${s_applninc[@]}"; do
            (cd "$WM_PROJECT_DIR" && wmakeLnInclude -u "$l" >/dev/null 2>&1) || die "wmakeLnInclude $l failed"
        done
        # objects of an earlier build with other flags would be reused: remove them
        rm -rf "$WM_PROJECT_DIR/build/$WM_OPTIONS/$s_dir" "$mark"
        mkdir -p "$FOAM_USER_APPBIN"
        log="$cache/log.stock-$n"
        say "building stock $n with '$s_flags' into ${FOAM_USER_APPBIN#$top/} (1-2 min; log ${log#$top/})"
        (cd "$ofdir/$s_dir" && FOAM_APPBIN="$FOAM_USER_APPBIN" \
            FOAM_SOLVERS="$ofdir/applications/solvers" FOAM_EXTRA_CXXFLAGS="$s_flags" \
            wmake) > "$log" 2>&1 || { tail -20 "$log" >&2; die "building stock $n failed (log $log)"; }
        [ -x "$exe" ] || die "building stock $n left no $exe (log $log)"
        printf '%s\n' "$s_flags" > "$mark"
        say "built ${exe#$top/}"
    done
}
if [ -f "$stamp" ] && [ -d "$ofdir/src/lagrangian/intermediate/lnInclude" ] \
   && [ -d "$ofdir/src/lagrangian/spray/lnInclude" ] \
   && [ -x "$ofdir/platforms/tools/linux64Gcc/wmkdepend" ] && [ -f "$ofdir/$pimple/pEqn.H" ] \
   && [ -f "$ofdir/bin/tools/RunFunctions" ]; then
    say "OpenFOAM v1912 sources ready in ${ofdir#$top/}"
    stock_build
    exit 0
fi
mkdir -p "$cache"
orig=$(ls "$cache"/openfoam_1912.200626.orig.tar.* 2>/dev/null | head -n1 || true)
if [ -z "$orig" ]; then
    if ! grep -rqs '^Types:.*deb-src' /etc/apt/sources.list.d/ /etc/apt/sources.list 2>/dev/null \
       && ! grep -qs '^deb-src' /etc/apt/sources.list; then
        say "adding a deb-src entry for bookworm main"
        $SUDO tee /etc/apt/sources.list.d/snowwall-src.sources >/dev/null <<'SRC'
Types: deb-src
URIs: http://deb.debian.org/debian
Suites: bookworm
Components: main
Signed-By: /usr/share/keyrings/debian-archive-keyring.gpg
SRC
        $SUDO apt-get update -qq || die "apt-get update (deb-src) failed"
    fi
    say "downloading the openfoam source package (about 45 MB)"
    (cd "$cache" && apt-get source --download-only -qq openfoam=1912.200626-1 >/dev/null 2>&1 \
        || apt-get source --download-only -qq openfoam >/dev/null) \
        || die "apt-get source --download-only openfoam failed"
    orig=$(ls "$cache"/openfoam_1912.200626.orig.tar.* 2>/dev/null | head -n1 || true)
    [ -n "$orig" ] || die "no openfoam_1912.200626.orig.tar.* in $cache after download"
fi
if [ ! -d "$ofdir/src" ] || [ ! -f "$ofdir/$pimple/pEqn.H" ]; then
    say "unpacking src/ wmake/ META-INFO $pimple/ from ${orig##*/}"
    tar -xf "$orig" -C "$cache" \
        openfoam-OpenFOAM-v1912.200626/src openfoam-OpenFOAM-v1912.200626/wmake \
        openfoam-OpenFOAM-v1912.200626/META-INFO \
        "openfoam-OpenFOAM-v1912.200626/$pimple" || die "unpacking $orig failed"
fi
# bin/tools: RunFunctions and CleanFunctions, which a stock tutorial's Allrun
# sources from $WM_PROJECT_DIR (without them: "runApplication: command not found")
if [ ! -f "$ofdir/bin/tools/RunFunctions" ]; then
    say "unpacking bin/tools (RunFunctions for the stock tutorials' Allrun) from ${orig##*/}"
    tar -xf "$orig" -C "$cache" openfoam-OpenFOAM-v1912.200626/bin/tools \
        || die "unpacking bin/tools from $orig failed"
fi
[ -e "$ofdir/etc" ] || ln -s /usr/share/openfoam/etc "$ofdir/etc"
# shellcheck source=openfoam-env.sh
. "$top/etc/openfoam-env.sh"
say "building wmake helpers"
(cd "$WM_DIR/src" && ./Allmake >/dev/null 2>&1) || die "building wmake helpers failed"
say "making lnInclude folders"
for l in OpenFOAM OSspecific/POSIX finiteVolume meshTools lagrangian/basic \
         lagrangian/intermediate lagrangian/distributionModels lagrangian/turbulence \
         regionModels/regionModel regionModels/surfaceFilmModels \
         TurbulenceModels/turbulenceModels TurbulenceModels/incompressible \
         TurbulenceModels/compressible transportModels transportModels/compressible \
         transportModels/incompressible thermophysicalModels/basic \
         thermophysicalModels/specie thermophysicalModels/reactionThermo \
         thermophysicalModels/SLGThermo thermophysicalModels/thermophysicalProperties \
         thermophysicalModels/radiation dynamicMesh dynamicFvMesh fileFormats surfMesh \
         functionObjects/forces functionObjects/field lagrangian/spray; do
    [ -d "$FOAM_SRC/$l" ] || continue
    (cd "$FOAM_SRC" && wmakeLnInclude -u "$l" >/dev/null 2>&1) || die "wmakeLnInclude $l failed"
done
touch "$stamp"
say "ready: OpenFOAM v1912 headers and wmake in ${ofdir#$top/}"
stock_build
