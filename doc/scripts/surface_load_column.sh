#!/usr/bin/env bash
# A load on a body's surface (Surface loads): prm/surface-load-column.prm,
# an elastic column 4 m high under a pressure q = 10 kPa on its top, damped
# to rest. Exact (one-dimensional compression): u_y(Y) = -q Y / M of the
# point that starts at height Y, sigma_yy = -q, sigma_xx = nu / (1 - nu)
# sigma_yy, M = E (1 - nu) / ((1 + nu)(1 - 2 nu)).
# Writes doc/data/surface-load-column.dat (per point: Y, u_y, the exact
# u_y, sigma_yy / q, sigma_xx / q) and draws
# doc/figures/surface-load-column.png (gnuplot-nox).
#
# Usage: doc/scripts/surface_load_column.sh [path to mpm-otm]
# (default: build-release/mpm-otm, made by ./scripts/setup.sh run)
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
exe=${1:-$root/build-release/mpm-otm}
exe=$(cd "$(dirname "$exe")" && pwd)/$(basename "$exe")
data=$root/doc/data
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"

cp "$root/prm/surface-load-column.prm" run.prm
printf 'subsection Output\n set Directory = out\n set Format = none\n set Overwrite = true\n set Time interval = 1\nend\n' >> run.prm
"$exe" run.prm > run.log 2>&1
last=$(ls out/particles-*.csv | sort | tail -n 1)

q=10e3 E=10e6 nu=0.3
awk -F, -v q=$q -v E=$E -v nu=$nu '
  NR == 1 { for (i = 1; i <= NF; ++i) column[$i] = i; next }
  {
    M = E * (1 - nu) / ((1 + nu) * (1 - 2 * nu))
    Y = $column["Y"]
    printf "%.6g %.6g %.6g %.6g %.6g\n", Y, $column["uy"], -q * Y / M,
           $column["syy"] / q, $column["sxx"] / q
  }' "$last" | sort -g > "$data/surface-load-column.dat"

gnuplot <<GP
set terminal pngcairo size 1000,420 font ",11" noenhanced
set output "$root/doc/figures/surface-load-column.png"
set multiplot layout 1,2
set xlabel "initial height Y (m)"
set ylabel "settlement -uy (mm)"
set key top left
plot "$data/surface-load-column.dat" using 1:(-1000*\$2) with points pt 7 ps 0.6 title "material points", \
     "" using 1:(-1000*\$3) with lines lw 2 title "exact q Y / M"
set ylabel "stress / q"
set key center right
set yrange [-1.1:0]
plot "$data/surface-load-column.dat" using 1:4 with points pt 7 ps 0.6 title "sigma_yy", \
     "" using 1:5 with points pt 6 ps 0.6 title "sigma_xx", \
     -1 with lines lw 2 title "exact sigma_yy", \
     -0.3/0.7 with lines lw 2 dt 2 title "exact sigma_xx"
unset multiplot
GP
echo "wrote $data/surface-load-column.dat and doc/figures/surface-load-column.png"
