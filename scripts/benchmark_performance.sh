#!/usr/bin/env bash
# Speed and memory of linear MPM (prm/performance-bar-2d.prm: 2D bar,
# quadrilaterals, USL, lumped mass, 2 x 2 points per cell, 100 steps) at about
# 1e4, 1e5 and 1e6 material points, on one core. Prints a Markdown table:
# particle-steps per second of the time loop (from the run's own wall-time
# lines, so set-up and output are excluded), peak resident memory
# (/usr/bin/time -v), and memory per point beyond that of a run with one
# cell (libraries, MPI).
# Usage: scripts/benchmark_performance.sh [path to mpm-otm] [parameter lines]
# The optional parameter lines are appended to the file, e.g.
# 'set Shape functions = B-spline' for quadratic B-splines.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
exe=$(realpath "${1:-$root/build-release/mpm-otm}")
extra=${2:-}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"

# run NX NY: prints "points seconds_of_time_loop peak_kB"
run() {
  cp "$root/prm/performance-bar-2d.prm" run.prm
  printf 'subsection Mesh\n set Subdivisions = %s, %s\nend\n%s\n' "$1" "$2" "$extra" >> run.prm
  /usr/bin/time -v "$exe" --overwrite run.prm > log 2> time.log
  points=$(grep -o '[0-9]* material points' log | cut -d' ' -f1)
  t0=$(grep '^step  *0 ' log | sed 's/.*wall time = \([0-9.]*\) s.*/\1/')
  t1=$(grep '^step  *100 ' log | sed 's/.*wall time = \([0-9.]*\) s.*/\1/')
  kb=$(grep 'Maximum resident' time.log | awk '{print $NF}')
  echo "$points $(awk "BEGIN{print $t1 - $t0}") $kb"
}

read -r _ _ base_kb < <(run 1 1)
echo "| material points | cells | particle-steps/s | peak memory (MB) | bytes per point (total) | bytes per point (beyond a 1-cell run) |"
echo "|---|---|---|---|---|---|"
for size in "100 25" "316 79" "1000 250"; do
  read -r nx ny <<< "$size"
  read -r points seconds kb < <(run "$nx" "$ny")
  awk -v p="$points" -v s="$seconds" -v kb="$kb" -v base="$base_kb" -v cells=$((nx * ny)) \
    'BEGIN { printf "| %d | %d | %.2e | %.0f | %.0f | %.0f |\n", p, cells, p * 100 / s, kb / 1024, kb * 1024 / p, (kb - base) * 1024 / p }'
done
echo
echo "(1-cell run: $((base_kb / 1024)) MB)"
