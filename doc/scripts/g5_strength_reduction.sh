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

. "$root/doc/scripts/strength_reduction_runs.sh"
# shellcheck disable=SC2086
strength_reduction_runs G5-slope-strength-reduction.prm \
  "$data/G5-strength-reduction-trials.dat" "$data/G5-factor-of-safety.dat" \
  "$data/G5-mechanism.dat" $sizes
cat "$data/G5-factor-of-safety.dat"

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
$(mechanism_plot "$data/G5-mechanism.dat")
unset multiplot
GP
echo "wrote $data/G5-strength-reduction-trials.dat, G5-factor-of-safety.dat, G5-mechanism.dat and doc/figures/G5-strength-reduction.png"
