#!/usr/bin/env bash
# The walk-through of the manual ("Step by step: from a Gmsh drawing to a
# factor of safety"): prm/example-layered-slope.prm, a slope of two layers
# drawn in Gmsh (prm/meshes/layered-slope.geo), by strength reduction.
# Writes doc/data/layered-slope-trials.dat (the trials),
# doc/data/layered-slope-mechanism.dat (the plastic strain of the last
# failing trial at the points' initial positions) and
# doc/data/layered-slope-bishop.txt (Bishop's simplified method,
# bishop_slope.py layered), and draws doc/figures/layered-slope.png
# (gnuplot-nox; python3-numpy for Bishop's method).
#
# Usage: doc/scripts/layered_slope.sh [path to mpm-otm]
# (default: build-release/mpm-otm, made by ./scripts/setup.sh run)
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
exe=${1:-$root/build-release/mpm-otm}
exe=$(cd "$(dirname "$exe")" && pwd)/$(basename "$exe")
data=$root/doc/data
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

/usr/bin/python3 "$root/doc/scripts/bishop_slope.py" layered 5e3 25 20e3 30 10 |
  tee "$data/layered-slope-bishop.txt"
# The mesh path of the parameter file is relative to the top of the
# repository.
cp "$root/prm/example-layered-slope.prm" "$work/run.prm"
printf 'subsection Output\n set Directory = %s/run\n set Format = none\n set Write particle CSV = true\n set Time interval = 15\nend\n' \
  "$work" >> "$work/run.prm"
(cd "$root" && "$exe" "$work/run.prm" > "$work/run.log" 2>&1) ||
  { tail -5 "$work/run.log" >&2; exit 1; }
grep "^Strength reduction" "$work/run.log" | grep -v "output in"
awk -F, 'NR > 1 { print $1, $2, $3, $4, $5, $6 }' "$work/run/strength-reduction.csv" |
  sed '1i # trial factor outcome at_rest end_time largest_displacement (s, m)' \
  > "$data/layered-slope-trials.dat"
mechanism=$(awk '/failure mechanism/ { sub(/.*</, ""); sub(/>.*/, ""); print }' "$work/run/factor-of-safety.txt")
last=$(ls "$mechanism"/particles-*.csv | sort | tail -n 1)
awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) column[$i] = i; next }
         { printf "%.4g %.4g %.3g\n", $column["X"], $column["Y"], $column["plastic_strain"] }' \
  "$last" > "$data/layered-slope-mechanism.dat"
factor=$(awk '/factor of safety/ { print $4 }' "$work/run/factor-of-safety.txt")

read -r bishop xc yc rc < <(awk '{ gsub("[,;]", ""); for (i = 1; i <= NF; ++i) { if ($i == "F") f = $(i + 2); if ($i == "centre") print f, $(i + 1), $(i + 2), $(i + 4) } }' "$data/layered-slope-bishop.txt")
gnuplot <<GP
set terminal pngcairo size 1100,460 font ",11" noenhanced
set output "$root/doc/figures/layered-slope.png"
set title "layered slope: plastic strain of the last failing trial (F = $factor by strength reduction; Bishop $bishop), initial positions"
set xlabel "x (m)"
set ylabel "y (m)"
set size ratio -1
set xrange [0:45]
set yrange [0:16]
set cbrange [0:1]
set cblabel "equivalent plastic strain"
set key top right
set arrow 1 from 0, 10 to 22.5, 10 nohead dt 2 lc rgb "gray40"
set label 1 "fill (y > 10): c = 5 kPa, phi = 25 deg" at 27, 13
set label 2 "foundation: c = 20 kPa, phi = 30 deg" at 27, 11.5
xc = $xc; yc = $yc; rc = $rc
plot "$data/layered-slope-mechanism.dat" using 1:2:3 with points pt 5 ps 0.3 palette notitle, \
     [xc - rc:xc + rc] (yc - sqrt(rc**2 - (x - xc)**2) < (x < 15 ? 15 : x < 30 ? 15 - (x - 15) / 1.5 : 5) ? yc - sqrt(rc**2 - (x - xc)**2) : 1/0) \
       with lines lw 2 lc rgb "black" title "Bishop's critical circle"
GP
echo "wrote $data/layered-slope-*.dat, layered-slope-bishop.txt and doc/figures/layered-slope.png"
