# etc/openfoam-env.sh - source this to build against and run Debian's OpenFOAM v1912.
# Sets the WM_* / FOAM_* variables matching Debian's own build (debian/rules),
# points FOAM_SRC and WM_DIR at the source cache made by etc/setup.sh and
# FOAM_USER_LIBBIN at SnowWall's git-ignored platforms/ folder.
_sw_top=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
export SNOWWALL_DIR="$_sw_top"
export WM_PROJECT=OpenFOAM WM_PROJECT_VERSION=v1912 WM_ARCH=linux64 \
       WM_COMPILER=Gcc WM_COMPILER_TYPE=system WM_COMPILE_OPTION=Opt \
       WM_PRECISION_OPTION=DP WM_LABEL_SIZE=32 WM_LABEL_OPTION=Int32 \
       WM_OPTIONS=linux64GccDPInt32Opt WM_MPLIB=SYSTEMOPENMPI WM_OSTYPE=POSIX \
       WM_ARCH_OPTION=64 WM_COMPILER_LIB_ARCH=64 WM_NCOMPPROCS=2
# WM_PROJECT_DIR is the unpacked source tree (wmake puts its helpers under it);
# its etc/ is a link to Debian's /usr/share/openfoam/etc, which the solvers read.
export WM_PROJECT_DIR="$_sw_top/.cache/openfoam/openfoam-OpenFOAM-v1912.200626"
export FOAM_SRC="$WM_PROJECT_DIR/src" WM_DIR="$WM_PROJECT_DIR/wmake"
export FOAM_LIBBIN=/usr/lib
export FOAM_USER_LIBBIN="$_sw_top/platforms/lib" FOAM_USER_APPBIN="$_sw_top/platforms/bin"
export FOAM_APPBIN=/usr/bin FOAM_ETC=/usr/share/openfoam/etc
export MPI_ARCH_PATH=/usr/lib/x86_64-linux-gnu/openmpi
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
case ":$PATH:" in *":$WM_DIR:"*) ;; *) export PATH="$WM_DIR:$PATH" ;; esac
case ":$PATH:" in *":$FOAM_USER_APPBIN:"*) ;; *) export PATH="$FOAM_USER_APPBIN:$PATH" ;; esac
case ":${LD_LIBRARY_PATH:-}:" in *":$FOAM_USER_LIBBIN:"*) ;;
    *) export LD_LIBRARY_PATH="$FOAM_USER_LIBBIN${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}" ;; esac
unset _sw_top
