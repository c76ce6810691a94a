#!/usr/bin/env bash
# Cost of the field output against the time steps between two outputs
# (issue 17: HDF5 output of 1e6 points in at most 10 % of the 100 steps
# between two outputs). prm/performance-bar-2d.prm at 1000 x 250 cells x
# 2 x 2 points = 1e6 points, 200 steps with output every 100 (steps 0, 100,
# 200), for Output/Format = none, vtu and hdf5, on NP ranks. Prints a
# Markdown table: the time-loop wall time of the 200 steps without output
# (Format = none, from the timer's sections other than output), and per
# format the seconds per output (TimerOutput section "output", divided by
# the 3 outputs) and that as a fraction of 100 steps.
# Usage: scripts/benchmark_output.sh [path to mpm-otm] [NP] [cells "NX, NY"]
#        [formats, default "vtu hdf5"]
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
exe=$(realpath "${1:-$root/build-release/mpm-otm}")
np=${2:-1}
cells=${3:-1000, 250}
formats=${4:-vtu hdf5}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"

# run FORMAT: prints "seconds_of_all_sections seconds_of_output"
run() {
  cp "$root/prm/performance-bar-2d.prm" run.prm
  printf 'subsection Mesh\n set Subdivisions = %s\nend\nsubsection Time\n set End time = 2e-2\nend\nsubsection Output\n set Directory = out-%s\n set Interval = 100\n set Format = %s\nend\n' "$cells" "$1" "$1" >> run.prm
  mpirun -np "$np" "$exe" --overwrite run.prm > log 2>&1
  awk -F'|' '/^\| (output|shape functions|particle to grid|solve|grid to particle|move grid)/ {
      gsub(/ /, "", $4); sub(/s$/, "", $4); total += $4; if ($2 ~ /output/) out = $4 }
    END { print total - out, out }' log
}

echo "| format | ranks | 100 steps (s) | one output (s) | output / 100 steps |"
echo "|---|---|---|---|---|"
read -r steps _ < <(run none)
for format in $formats; do
  read -r _ output < <(run "$format")
  awk -v f="$format" -v np="$np" -v s="$steps" -v o="$output" \
    'BEGIN { printf "| %s | %d | %.2f | %.2f | %.1f %% |\n", f, np, s / 2, o / 3, 100 * (o / 3) / (s / 2) }'
done
