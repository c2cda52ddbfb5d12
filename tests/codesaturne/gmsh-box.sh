#!/usr/bin/env bash
# gmsh-box.sh - write a box of hexahedra as a Gmsh 2.2 ASCII mesh (for Code_Saturne).
#
# Usage: gmsh-box.sh [--help] NX NY NZ LX LY LZ OUT.msh
#
# The box [0, LX] x [0, LY] x [0, LZ] split into NX x NY x NZ equal hexahedra
# (type 5), and its boundary quadrangles (type 3) with the physical tags
# 1 y = 0, 2 y = LY, 3 the four other sides. Nodes are numbered x fastest,
# then y, then z; cells likewise. Written to OUT.msh.tmp, then renamed.
# Exit status: 0 written, 2 a bad argument (the message names it).
set -euo pipefail
if [ "${1:-}" = -h ] || [ "${1:-}" = --help ]; then
    sed -n '2,10p' "$0" | sed 's/^# \{0,1\}//'; exit 0
fi
[ $# = 7 ] || { echo "gmsh-box.sh: expected 7 arguments, got $# (see --help)" >&2; exit 2; }
for i in 1 2 3; do
    [[ ${!i} =~ ^[1-9][0-9]{0,3}$ ]] || { echo "gmsh-box.sh: N$i '${!i}' is not a whole number in [1, 9999]" >&2; exit 2; }
done
for i in 4 5 6; do
    awk -v v="${!i}" 'BEGIN { exit !(v ~ /^[0-9.eE+-]+$/ && v + 0 > 0 && v + 0 < 1e6) }' \
        || { echo "gmsh-box.sh: length L$((i - 3)) '${!i}' is not a number in (0, 1e6)" >&2; exit 2; }
done
out=$7
awk -v nx="$1" -v ny="$2" -v nz="$3" -v lx="$4" -v ly="$5" -v lz="$6" '
function node(i, j, k) { return 1 + i + (nx + 1) * (j + (ny + 1) * k) }
function quad(tag, a, b, c, d) { ne++; q = q sprintf("%d 3 2 %d %d %d %d %d %d\n", ne, tag, tag, a, b, c, d) }
BEGIN {
    printf "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n%d\n", (nx + 1) * (ny + 1) * (nz + 1)
    for (k = 0; k <= nz; k++) for (j = 0; j <= ny; j++) for (i = 0; i <= nx; i++)
        printf "%d %.17g %.17g %.17g\n", node(i, j, k), lx * i / nx, ly * j / ny, lz * k / nz
    printf "$EndNodes\n"
    ne = 0; q = ""
    # boundary quadrangles, numbered so that the normal points out of the box
    for (k = 0; k < nz; k++) for (i = 0; i < nx; i++) {
        quad(1, node(i, 0, k), node(i + 1, 0, k), node(i + 1, 0, k + 1), node(i, 0, k + 1))
        quad(2, node(i, ny, k), node(i, ny, k + 1), node(i + 1, ny, k + 1), node(i + 1, ny, k))
    }
    for (k = 0; k < nz; k++) for (j = 0; j < ny; j++) {
        quad(3, node(0, j, k), node(0, j, k + 1), node(0, j + 1, k + 1), node(0, j + 1, k))
        quad(3, node(nx, j, k), node(nx, j + 1, k), node(nx, j + 1, k + 1), node(nx, j, k + 1))
    }
    for (j = 0; j < ny; j++) for (i = 0; i < nx; i++) {
        quad(3, node(i, j, 0), node(i, j + 1, 0), node(i + 1, j + 1, 0), node(i + 1, j, 0))
        quad(3, node(i, j, nz), node(i + 1, j, nz), node(i + 1, j + 1, nz), node(i, j + 1, nz))
    }
    nq = ne
    printf "$Elements\n%d\n%s", nq + nx * ny * nz, q
    for (k = 0; k < nz; k++) for (j = 0; j < ny; j++) for (i = 0; i < nx; i++) {
        ne++
        printf "%d 5 2 4 4 %d %d %d %d %d %d %d %d\n", ne,
            node(i, j, k), node(i + 1, j, k), node(i + 1, j + 1, k), node(i, j + 1, k),
            node(i, j, k + 1), node(i + 1, j, k + 1), node(i + 1, j + 1, k + 1), node(i, j + 1, k + 1)
    }
    printf "$EndElements\n"
}' > "$out.tmp"
mv "$out.tmp" "$out"
