#!/usr/bin/env bash
# Cost per material-point step of MPM-maxent and OTM-maxent (d_max = 2,
# consistent mass) against MPM-P1 (lumped and consistent mass) on B1b
# (prm/B1b-bar-fixed-ends*.prm) from 512 to 8192 nodes, 12 points per cell,
# 200 steps with dt = 1e-5 * 512 / nodes (the same Courant number on every
# grid). With the neighbour search the cost per point-step should not grow
# with the number of nodes. The time loop is timed from the run's own
# wall-time lines; each run is repeated REPEATS times in turn and the
# fastest kept. Prints a Markdown table of nanoseconds per point-step.
# Usage: scripts/benchmark_max_ent_scaling.sh [path to mpm-otm] [repeats]
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
exe=$(realpath "${1:-$root/build-release/mpm-otm}")
repeats=${2:-3}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
steps=200

# ns_per_point_step PRM NODES EXTRA
ns_per_point_step() {
  cp "$root/prm/$1" run.prm
  printf 'subsection Time\n set Time step = %s\n set End time = %s\nend\nsubsection Mesh\n set Subdivisions = %s\nend\nsubsection Output\n set Interval = 0\n set Format = none\n set Write particle CSV = false\nend\n%s\n' \
    "$(awk "BEGIN{print 1e-5 * 512 / $2}")" "$(awk "BEGIN{print $steps * 1e-5 * 512 / $2}")" "$(($2 - 1))" "$3" >> run.prm
  "$exe" --overwrite run.prm > log
  points=$(grep -o '[0-9]* material points' log | cut -d' ' -f1)
  t0=$(grep '^step  *0 ' log | sed 's/.*wall time = \([0-9.]*\) s.*/\1/')
  t1=$(grep "^step  *$steps " log | sed 's/.*wall time = \([0-9.]*\) s.*/\1/')
  awk "BEGIN{printf \"%.0f\", ($t1 - $t0) * 1e9 / ($points * $steps)}"
}

methods=("MPM-P1 lumped|B1b-bar-fixed-ends.prm|"
         "MPM-P1 consistent|B1b-bar-fixed-ends.prm|set Mass matrix = consistent"
         "MPM-maxent|B1b-bar-fixed-ends-mpm-maxent.prm|"
         "MPM-maxent lumped|B1b-bar-fixed-ends-mpm-maxent.prm|set Mass matrix = lumped"
         "OTM-maxent|B1b-bar-fixed-ends-otm-maxent.prm|")
sizes=(512 2048 8192)
declare -A best
for ((r = 0; r < repeats; ++r)); do
  for nodes in "${sizes[@]}"; do
    for entry in "${methods[@]}"; do
      IFS='|' read -r name prm extra <<< "$entry"
      t=$(ns_per_point_step "$prm" "$nodes" "$extra")
      key="$name@$nodes"
      if [ -z "${best[$key]:-}" ] || [ "$t" -lt "${best[$key]}" ]; then
        best[$key]=$t
      fi
    done
  done
done

echo "| method | $(printf '%s nodes | ' "${sizes[@]}")"
echo "|---|$(printf -- '---|%.0s' "${sizes[@]}")"
for entry in "${methods[@]}"; do
  IFS='|' read -r name _ _ <<< "$entry"
  row="| $name"
  for nodes in "${sizes[@]}"; do
    row="$row | ${best["$name@$nodes"]}"
  done
  echo "$row |"
done
