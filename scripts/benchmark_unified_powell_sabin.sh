#!/usr/bin/env bash
# Cost of the unified approach with Powell-Sabin splines against PS-MPM on
# B6 at large deformation (prm/B6-soil-column-2d-large-powell-sabin.prm:
# MUSL, consistent mass, hypo-elastic, 72 points per triangle), on 4 x 32
# blocks (36,864 points) for 500 steps of dt = 1e-4, in one side-by-side
# session (Release build, one core). The runs alternate, REPEAT times each.
# Prints a Markdown table: seconds of the time loop (from the run's own
# wall-time lines, so set-up and output are excluded), microseconds per
# point-step, and the seconds of the timer row "move grid, locate
# particles", which in the unified run holds the vertex motion, the rebuild
# of the splines on the moved grid and the location of the points.
# Usage: scripts/benchmark_unified_powell_sabin.sh [path to mpm-otm] [REPEAT]
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
exe=${1:-$root/build-release/mpm-otm}
exe=$(cd "$(dirname "$exe")" && pwd)/$(basename "$exe")
repeat=${2:-2}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"

# run METHOD: prints "points seconds_of_time_loop seconds_of_grid_motion"
run() {
  cp "$root/prm/B6-soil-column-2d-large-powell-sabin.prm" run.prm
  printf 'set Method = %s\nsubsection Mesh\n set Subdivisions = 4, 32\nend\nsubsection Time\n set End time = 0.05\nend\nsubsection Output\n set Directory = run\n set Format = none\n set Interval = 0\n set Write particle CSV = false\nend\n' "$1" >> run.prm
  "$exe" --overwrite run.prm > log 2>&1
  points=$(grep -o '[0-9]* material points' log | head -1 | cut -d' ' -f1)
  t0=$(grep '^step  *0 ' log | sed 's/.*wall time = \([0-9.]*\) s.*/\1/')
  t1=$(grep '^step  *500 ' log | sed 's/.*wall time = \([0-9.]*\) s.*/\1/')
  motion=$(grep 'move grid, locate particles' log | awk -F'|' '{print $4}' | tr -d ' s')
  echo "$points $(awk "BEGIN{print $t1 - $t0}") $motion"
}

echo "| method | material points | time loop (s) | per point-step (us) | move grid, locate particles (s) |"
echo "|---|---|---|---|---|"
best_mpm=1e9 best_unified=1e9
for _ in $(seq "$repeat"); do
  for method in MPM Unified; do
    read -r points seconds motion < <(run $method)
    echo "| $method | $points | $seconds | $(awk "BEGIN{printf \"%.2f\", 1e6 * $seconds / ($points * 500)}") | $motion |"
    if [ "$method" = MPM ]; then
      best_mpm=$(awk "BEGIN{print ($seconds < $best_mpm) ? $seconds : $best_mpm}")
    else
      best_unified=$(awk "BEGIN{print ($seconds < $best_unified) ? $seconds : $best_unified}")
    fi
  done
done
echo
echo "unified / PS-MPM (best times): $(awk "BEGIN{printf \"%.2f\", $best_unified / $best_mpm}")"
