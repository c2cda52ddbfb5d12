#!/usr/bin/env bash
# etc/setup.sh - make a Debian 12 machine ready to build and run SnowWall.
#
# Usage: etc/setup.sh [--help] [--no-openfoam]
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
#
# Exit status: 0 ready, 1 a step failed (the message names it).
set -euo pipefail

top=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
want_of=1
for a in "$@"; do
    case "$a" in
        -h|--help) sed -n '2,18p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
        --no-openfoam) want_of=0 ;;
        *) echo "setup.sh: unknown option '$a' (see --help)" >&2; exit 1 ;;
    esac
done

say() { printf 'setup: %s\n' "$*"; }
die() { printf 'setup: error: %s\n' "$*" >&2; exit 1; }

c_pkgs=(build-essential cmake pkg-config libgsl-dev libcmocka-dev gnuplot-nox
        libpng-dev libjpeg-dev)
of_pkgs=(openfoam openfoam-examples openmpi-bin libopenmpi-dev dpkg-dev)
# Code_Saturne 6.0 (tests/codesaturne): the solver, its headers, its Python
# scripts and user templates; gfortran builds a case's Fortran user file
cs_pkgs=(code-saturne-bin code-saturne-include code-saturne-data gfortran)
pkgs=("${c_pkgs[@]}")
[ "$want_of" = 1 ] && pkgs+=("${of_pkgs[@]}" "${cs_pkgs[@]}")

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
if [ -f "$stamp" ] && [ -d "$ofdir/src/lagrangian/intermediate/lnInclude" ] \
   && [ -d "$ofdir/src/lagrangian/spray/lnInclude" ] \
   && [ -x "$ofdir/platforms/tools/linux64Gcc/wmkdepend" ] && [ -f "$ofdir/$pimple/pEqn.H" ] \
   && [ -f "$ofdir/bin/tools/RunFunctions" ]; then
    say "OpenFOAM v1912 sources ready in ${ofdir#$top/}"
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
