#!/usr/bin/env bash
# G5 by strength reduction (doc/benchmarks.md, "G5: the factor of safety by
# strength reduction"): prm/G5-slope-strength-reduction.prm on 1 m, 0.5 m
# and 0.25 m cells (or the sizes given), each an analysis with
# Analysis = strength reduction (bisection from [1, 2] to 0.02, a trial
# fails beyond 1 m of displacement or still moving at 15 s).
# Writes
#   doc/data/G5-strength-reduction-trials.dat  every trial: cell size,
#     trial, factor, outcome, at rest, end time, largest displacement;
#   doc/data/G5-factor-of-safety.dat  per cell size: the factor of safety,
#     the bracket, the number of trials, the difference from Bishop's;
#   doc/data/G5-mechanism.dat  the plastic strain of the last failing trial
#     on the finest cells, at the points' initial positions;
# and draws doc/figures/G5-strength-reduction.png (gnuplot-nox) beside
# Bishop's simplified method (doc/data/G5-bishop.txt, bishop_slope.py).
#
# Usage: doc/scripts/g5_strength_reduction.sh [path to mpm-otm] [cell sizes]
# (default: build-release/mpm-otm, made by ./scripts/setup.sh run; 1 0.5
# 0.25, which take about 1, 5 and 10 minutes with a release build)
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
exe=${1:-$root/build-release/mpm-otm}
exe=$(cd "$(dirname "$exe")" && pwd)/$(basename "$exe")
shift || true
sizes=${*:-1 0.5 0.25}
data=$root/doc/data
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"

bishop=$(awk '/c = 10 kPa/ { for (i = 1; i <= NF; ++i) if ($i == "F") { gsub(";", "", $(i + 2)); print $(i + 2) } }' "$data/G5-bishop.txt")
echo "# cells trial factor outcome at_rest end_time largest_displacement (m, s, m)" > "$data/G5-strength-reduction-trials.dat"
echo "# cells factor_of_safety stands_at fails_at trials difference_from_Bishop_${bishop}_percent" > "$data/G5-factor-of-safety.dat"
for h in $sizes; do
  nx=$(awk "BEGIN{print int(45 / $h + 0.5)}")
  ny=$(awk "BEGIN{print int(16 / $h + 0.5)}")
  cp "$root/prm/G5-slope-strength-reduction.prm" run.prm
  printf 'subsection Mesh\n set Subdivisions = %s, %s\nend\nsubsection Output\n set Directory = run-%s\n set Format = none\n set Write particle CSV = true\n set Time interval = 15\n set Overwrite = true\nend\n' \
    "$nx" "$ny" "$h" >> run.prm
  echo "G5 strength reduction on $h m cells ($nx x $ny)"
  "$exe" run.prm > "run-$h.log" 2>&1 || { tail -5 "run-$h.log" >&2; exit 1; }
  grep "^Strength reduction" "run-$h.log" | grep -v "output in" >&2
  awk -F, -v h="$h" 'NR > 1 { print h, $1, $2, $3, $4, $5, $6 }' \
    "run-$h/strength-reduction.csv" >> "$data/G5-strength-reduction-trials.dat"
  awk -v h="$h" -v b="$bishop" '
    $1 == h { n++; if ($4 == "stands" && (s == "" || $3 > s)) s = $3
              if ($4 == "fails" && (f == "" || $3 < f)) f = $3 }
    END { F = (s + f) / 2; printf "%s %.4f %s %s %d %.1f\n", h, F, s, f, n, 100 * (F / b - 1) }' \
    "$data/G5-strength-reduction-trials.dat" >> "$data/G5-factor-of-safety.dat"
  mechanism=$(awk '/failure mechanism/ { sub(/.*</, ""); sub(/>.*/, ""); print }' "run-$h/factor-of-safety.txt")
  last=$(ls "$mechanism"/particles-*.csv | sort | tail -n 1)
  awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) column[$i] = i; next }
           { printf "%.4g %.4g %.3g\n", $column["X"], $column["Y"], $column["plastic_strain"] }' \
    "$last" > "$data/G5-mechanism.dat"
done
cat "$data/G5-factor-of-safety.dat"

read -r xc yc rc < <(awk '/c = 10 kPa/ { gsub(",", ""); for (i = 1; i <= NF; ++i) if ($i == "centre") print $(i + 1), $(i + 2), $(i + 4) }' "$data/G5-bishop.txt")
finest=$(echo "$sizes" | tr ' ' '\n' | sort -g | head -n 1)
gnuplot <<GP
set terminal pngcairo size 1200,900 font ",11" noenhanced
set output "$root/doc/figures/G5-strength-reduction.png"
set multiplot
set origin 0, 0.5
set size 0.5, 0.5
set title "trials: largest displacement at the end"
set xlabel "strength reduction factor F"
set ylabel "largest displacement (m)"
set logscale y
set yrange [0.01:20]
set xrange [0.95:2.05]
set key top left
set arrow 1 from $bishop, 0.01 to $bishop, 20 nohead dt 2 lc rgb "black"
set label 1 "Bishop $bishop" at $bishop + 0.02, 8
set arrow 2 from 0.95, 1 to 2.05, 1 nohead dt 3 lc rgb "gray40"
set label 2 "fails above 1 m" at 1.02, 1.3
plot for [h in "$sizes"] \
  "< awk '\$1 == \"".h."\"' $data/G5-strength-reduction-trials.dat | sort -g -k3" \
  using 3:7 with linespoints pt 7 title h." m cells"
unset logscale y
unset arrow
unset label
set origin 0.5, 0.5
set title "factor of safety against Bishop's simplified method"
set xlabel "cell size (m)"
set ylabel "F"
set xrange [0:1.1]
set yrange [1.3:1.9]
set key bottom right
plot "$data/G5-factor-of-safety.dat" using 1:2:3:4 with yerrorbars pt 7 title "strength reduction (bracket)", \
     $bishop with lines lw 2 lc rgb "black" title "Bishop", \
     1.05 * $bishop with lines dt 2 lc rgb "gray40" title "+5 %", \
     1.10 * $bishop with lines dt 3 lc rgb "gray40" title "+10 %"
set origin 0, 0
set title "plastic strain of the last failing trial ($finest m cells), initial positions"
set xlabel "x (m)"
set ylabel "y (m)"
set size ratio -1 1, 0.5
set xrange [0:45]
set yrange [0:16]
set cbrange [0:1]
set cblabel "equivalent plastic strain"
set key top right
xc = $xc; yc = $yc; rc = $rc
plot "$data/G5-mechanism.dat" using 1:2:3 with points pt 5 ps 0.25 palette notitle, \
     [xc - rc:xc + rc] (yc - sqrt(rc**2 - (x - xc)**2) < (x < 15 ? 15 : x < 30 ? 15 - (x - 15) / 1.5 : 5) ? yc - sqrt(rc**2 - (x - xc)**2) : 1/0) \
       with lines lw 2 lc rgb "black" title "Bishop's critical circle"
unset multiplot
GP
echo "wrote $data/G5-strength-reduction-trials.dat, G5-factor-of-safety.dat, G5-mechanism.dat and doc/figures/G5-strength-reduction.png"
