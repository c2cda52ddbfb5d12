#!/usr/bin/env bash
# contact-laws.sh - the kernel's normal contact laws side by side (doc/kernel.md)
#
# Usage: validation/contact-laws.sh --out DIR [--force] [--config FILE] [--set KEY=VALUE]... [--help]
#
# With bin/snowregime on the embedded defaults (dry snow on ABS), or on the
# settings given (--config/--set, as for snowregime), it measures for each law
#   elastic      cor elastic: elastic JKR, no plastic loss (v_crit = V_s)
#   estimate     the closed-form combination e_p(v) v = V_s (no kernel run)
#   thornton     cor thornton, dashpot while loading (the default)
#   both         cor thornton, dashpot while loading and unloading, calibrated
#                to the same non-adhesive COR
#   tn-1MPa ...  cor thornton-ning at sigma_y = 1, 3, 10, 30 MPa
# and writes into DIR, only when the run succeeds:
#   vcrit.csv    d [m] and v_crit [m/s] per law, 5-200 um (16 diameters)
#   vcrit.md     the same at 10, 20, 50, 100 um as a markdown table
#   e_v.csv      rebound COR e_n(v) at d = 50 um, v 1 mm/s - 50 m/s (0 = stick)
#   contact-laws.png  both, as plots (gnuplot)
# DIR missing: created (its parent must exist). DIR an empty folder or an
# earlier SnowWall output folder (it holds .snowwall-output): the files are
# written into it, what else it holds stays. Any other existing DIR is refused
# (exit 2) unless --force: then the files are written into it (regular files of
# the same names replaced), nothing deleted, no .snowwall-output added.
# Nothing is ever deleted from DIR.
# Speeds are searched in [1e-4, 1000] m/s; "> 1000" means sticks everywhere.
# The snowregime used is bin/snowregime, or $SNOWREGIME if set (the tests).
# Exit status: 0 done, 1 a run failed, 2 usage error or a rejected setting.
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
sr=${SNOWREGIME:-$top/bin/snowregime}
out=
force=0
sets=()
missing_value() { echo "contact-laws.sh: $1 (see --help)" >&2; exit 2; }   # a usage error: exit 2
while [ $# -gt 0 ]; do
    case "$1" in
        -h|--help) awk 'NR > 1 && !/^#/ { exit } NR > 1 { sub(/^# ?/, ""); print }' "$0"; exit 0 ;;
        --out) [ -n "${2:-}" ] || missing_value "--out needs a folder"; out=$2; shift ;;
        --force) force=1 ;;
        --config) [ -n "${2:-}" ] || missing_value "--config needs a file"; sets+=(--config "$2"); shift ;;
        --set) [ -n "${2:-}" ] || missing_value "--set needs KEY=VALUE"; sets+=(--set "$2"); shift ;;
        *) echo "contact-laws.sh: unknown option '$1' (see --help)" >&2; exit 2 ;;
    esac
    shift
done
[ -n "$out" ] || { echo "contact-laws.sh: --out DIR is required (see --help)" >&2; exit 2; }
[ -x "$sr" ] || { echo "contact-laws.sh: $sr missing: run ./Allwmake" >&2; exit 1; }
command -v gnuplot >/dev/null || { echo "contact-laws.sh: gnuplot missing (etc/setup.sh)" >&2; exit 1; }

# shellcheck source=../etc/outdir.sh
. "$top/etc/outdir.sh"
outdir_begin contact-laws.sh "$out" "$force"

laws=(elastic thornton both tn-1MPa tn-3MPa tn-10MPa tn-30MPa)
law_sets() {
    case "$1" in
        elastic) echo "--set cor=elastic" ;;
        thornton) echo "--set cor=thornton --set dashpot=loading" ;;
        both) echo "--set cor=thornton --set dashpot=both" ;;
        tn-*) local s=${1#tn-}; s=${s%MPa}; echo "--set cor=thornton-ning --set sigma_y=${s}e6" ;;
    esac
}
dlist=$(awk 'BEGIN { for (i = 0; i < 16; i++) printf "%s%.4g", (i ? "," : ""), 5e-6 * exp(log(40) * i / 15) }')
dtab=10e-6,20e-6,50e-6,100e-6

# settings as the kernel sees them (for the closed-form estimate)
"$sr" vcrit --d 1e-5 "${sets[@]}" --set cor=elastic >"$tmp/hdr" 2>/dev/null ||
    { echo "contact-laws.sh: snowregime rejects the settings:" >&2; "$sr" vcrit --d 1e-5 "${sets[@]}" >/dev/null; exit 2; }

vcrit_of() {   # law dlist -> file with "d v" lines ("nan" when sticks/bounces everywhere)
    # shellcheck disable=SC2046
    "$sr" vcrit --d "$2" --vmin 1e-4 --vmax 1000 "${sets[@]}" $(law_sets "$1") 2>/dev/null |
        awk '!/^#/ { print $1, $2 }' || true
}
for law in "${laws[@]}"; do
    vcrit_of "$law" "$dlist" >"$tmp/v_$law"
    vcrit_of "$law" "$dtab" >"$tmp/t_$law"
    [ -s "$tmp/v_$law" ] || { echo "contact-laws.sh: snowregime vcrit failed for $law" >&2; exit 1; }
done
# closed-form estimate: v with e_p(V_y/v) v = V_s (bisection in ln v)
estimate() {
    awk -v dl="$1" '
    $1 == "#" && $2 == "setting" { s[$3] = $4 }
    function ep(x,   e) { if (x >= 1) return 1
        e = sqrt(6 * sqrt(3) / 5) * sqrt(1 - x * x / 6) * (x / (x + 2 * sqrt(6 / 5 - x * x / 5)))^0.25
        return e > 1 ? 1 : e }
    END {
        es = 1 / ((1 - s["nu"]^2) / s["E"] + (1 - s["nu_wall"]^2) / s["E_wall"])
        py = 2.5 * s["sigma_y"]; vy = 1.56 * sqrt(py^5 / (es^4 * s["rho"]))
        n = split(dl, d, ",")
        for (i = 1; i <= n; i++) {
            R = d[i] / 2
            vs = 1.84 * (s["gamma"]^5 / (s["rho"]^3 * es^2 * R^5))^(1 / 6)
            lo = log(1e-6); hi = log(1e4)
            for (k = 0; k < 200; k++) { m = (lo + hi) / 2; v = exp(m)
                if (ep(vy / v) * v < vs) lo = m; else hi = m }
            printf "%.6g %.6g\n", d[i], exp((lo + hi) / 2)
        }
    }' "$tmp/hdr"
}
estimate "$dlist" >"$tmp/v_estimate"
estimate "$dtab" >"$tmp/t_estimate"
all=(elastic estimate thornton both tn-1MPa tn-3MPa tn-10MPa tn-30MPa)

# tables
{
    printf 'd_m'; for l in "${all[@]}"; do printf ',%s' "$l"; done; printf '\n'
    paste -d' ' $(for l in "${all[@]}"; do echo "$tmp/v_$l"; done) |
        awk '{ printf "%s", $1; for (i = 2; i <= NF; i += 2) printf ",%s", $i; printf "\n" }'
} >"$tmp/vcrit.csv"
{
    printf '| d [µm] |'; for l in "${all[@]}"; do printf ' %s |' "$l"; done; printf '\n|---|'
    for _ in "${all[@]}"; do printf -- '---:|'; done; printf '\n'
    paste -d' ' $(for l in "${all[@]}"; do echo "$tmp/t_$l"; done) |
        awk '{ printf "| %g |", $1 * 1e6
               for (i = 2; i <= NF; i += 2) printf " %s |", ($i == "nan" ? "> 1000" : sprintf("%.3g", $i))
               printf "\n" }'
} >"$tmp/vcrit.md"

# e_n(v) at 50 um
ev_laws=(elastic thornton both tn-1MPa tn-10MPa tn-30MPa)
{
    printf 'v_m_s'; for l in "${ev_laws[@]}"; do printf ',%s' "$l"; done; printf '\n'
    for v in $(awk 'BEGIN { for (i = 0; i <= 56; i++) printf "%.4g ", 1e-3 * 10^(i / 12) }'); do
        printf '%s' "$v"
        for l in "${ev_laws[@]}"; do
            # shellcheck disable=SC2046
            e=$("$sr" collide --d 50e-6 --vn "$v" "${sets[@]}" $(law_sets "$l") | awk '$1 == "e_n:" { print $2 }') ||
                { echo "contact-laws.sh: snowregime collide failed ($l, v $v)" >&2; exit 1; }
            printf ',%s' "$e"
        done
        printf '\n'
    done
} >"$tmp/e_v.csv"

# plot (fixed file names inside the temporary folder: no user text in the script)
(
    cd "$tmp"
    cat >plot.gp <<'EOF'
set terminal pngcairo size 1200,480 font ",10"
set output "contact-laws.png"
set datafile separator ","
set key autotitle columnhead noenhanced
colors = "#7b3294 #1b9e77 #2c7bb6 #e66101 #b2182b #fdae61 #4dac26 #000000"
set multiplot layout 1,2
set logscale xy
set grid
set title "critical sticking speed, dry snow on ABS"
set xlabel "d [um]"
set ylabel "v_{crit} [m/s]"
set xrange [4:250]
set yrange [1e-2:1e3]
set key top right font ",9"
plot for [i=2:9] "vcrit.csv" using ($1*1e6):(column(i) > 0 ? column(i) : 1/0) \
     with linespoints lw 2 pt 7 ps 0.5 lc rgb word(colors, i-1)
set title "rebound COR at d = 50 um (0: sticks)"
set xlabel "v_n [m/s]"
set ylabel "e_n"
unset logscale y
set xrange [1e-3:50]
set yrange [0:1.05]
set key top left font ",9"
idx = "1 3 4 5 7 8"
plot for [i=2:7] "e_v.csv" using 1:i with lines lw 2 lc rgb word(colors, int(word(idx, i-1)))
unset multiplot
EOF
    gnuplot plot.gp
    rm -f plot.gp
)
rm -f "$tmp"/v_* "$tmp"/t_* "$tmp/hdr"
outdir_commit
echo "contact-laws.sh: vcrit.csv, vcrit.md, e_v.csv, contact-laws.png in $out"
cat "$out/vcrit.md"
