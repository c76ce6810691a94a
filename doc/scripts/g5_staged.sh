#!/usr/bin/env bash
# G5 in stages (doc/benchmarks.md, "G5 in stages"): prm/G5-slope-staged.prm,
# the slope built in two lifts (the slope to 13 m from K0, then the top 2 m
# placed on it), then its factor of safety by strength reduction in the
# last stage, on 1 m and 0.5 m cells (or the sizes given).
# Writes
#   doc/data/G5-staged-trials.dat  every trial: cell size, trial, factor,
#     outcome, at rest, end time, largest displacement in the last stage;
#   doc/data/G5-staged-factor-of-safety.dat  per cell size: the factor of
#     safety, the bracket, the number of trials, the difference from
#     Bishop's and the single-stage factor on the same cells
#     (doc/data/G5-factor-of-safety.dat);
#   doc/data/G5-staged-mechanism.dat  the plastic strain of the last failing
#     trial on the finest cells, at the points' positions at the start of
#     the last stage;
# and draws doc/figures/G5-staged.png (gnuplot-nox).
#
# Usage: doc/scripts/g5_staged.sh [path to mpm-otm] [cell sizes]
# (default: build-release/mpm-otm, made by ./scripts/setup.sh run; 1 0.5,
# which take about 1 and 3 minutes with a release build)
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
exe=${1:-$root/build-release/mpm-otm}
exe=$(cd "$(dirname "$exe")" && pwd)/$(basename "$exe")
shift || true
sizes=${*:-1 0.5}
data=$root/doc/data
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"

. "$root/doc/scripts/strength_reduction_runs.sh"
# shellcheck disable=SC2086
strength_reduction_runs G5-slope-staged.prm "$data/G5-staged-trials.dat" \
  "$data/G5-staged-factor-of-safety.dat" "$data/G5-staged-mechanism.dat" $sizes
# The single-stage factor on the same cells beside each.
awk 'NR == FNR { if ($1 !~ /^#/) single[$1] = $2; next }
     /^#/ { print $0, "single_stage_factor"; next }
     { print $0, ($1 in single ? single[$1] : "nan") }' \
  "$data/G5-factor-of-safety.dat" "$data/G5-staged-factor-of-safety.dat" > factors.tmp
mv factors.tmp "$data/G5-staged-factor-of-safety.dat"
cat "$data/G5-staged-factor-of-safety.dat"

finest=$(echo "$sizes" | tr ' ' '\n' | sort -g | head -n 1)
gnuplot <<GP
set terminal pngcairo size 1200,900 font ",11" noenhanced
set output "$root/doc/figures/G5-staged.png"
set multiplot
set origin 0, 0.5
set size 1, 0.5
set title "trials in stages (filled) and in one stage (open): largest displacement"
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
  "< awk '\$1 == \"".h."\"' $data/G5-staged-trials.dat | sort -g -k3" \
  using 3:7 with linespoints pt 7 title h." m cells, stages", \
     for [h in "$sizes"] \
  "< awk '\$1 == \"".h."\"' $data/G5-strength-reduction-trials.dat | sort -g -k3" \
  using 3:7 with linespoints pt 6 dt 2 title h." m cells, one stage"
unset logscale y
unset arrow
unset label
set origin 0, 0
set title "plastic strain of the last failing trial in stages ($finest m cells)"
$(mechanism_plot "$data/G5-staged-mechanism.dat")
unset multiplot
GP
echo "wrote $data/G5-staged-trials.dat, G5-staged-factor-of-safety.dat, G5-staged-mechanism.dat and doc/figures/G5-staged.png"
