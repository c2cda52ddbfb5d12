# rear-outline.awk - the outline of a rear-face map (CSV of post/wedge-post:
# header, then y,z,value per face on a regular grid): the face centres extended
# by half a face. Prints "y0 y1 z0 z1". Used by wedge-panels and wedge-post.
# Usage: awk -F, -f rear-outline.awk MAP.csv
NR == 2 { a = b = $1; c = d = $2 }
NR > 1 { if ($1 < a) a = $1; if ($1 > b) b = $1; if ($2 < c) c = $2; if ($2 > d) d = $2; ys[$1] = 1; zs[$2] = 1 }
END {
    ny = 0; for (k in ys) ny++
    nz = 0; for (k in zs) nz++
    hy = (ny > 1) ? (b - a) / (ny - 1) / 2 : 0.005
    hz = (nz > 1) ? (d - c) / (nz - 1) / 2 : 0.005
    print a - hy, b + hy, c - hz, d + hz
}
