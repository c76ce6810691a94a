#!/usr/bin/env bash
# Cost of OTM-P1, BSMPM, the unified approach (P1 and quadratic B-splines),
# MPM-maxent and OTM-maxent relative to MPM-P1 on B1b (prm/B1b-bar-fixed-ends*.prm) at 32
# and 512 nodes, next to the journal's Table 1. Each method's time loop (16000 steps at 32 nodes, 1000
# at 512, dt = 1e-5; output only at the first and last step) is timed from
# the run's own wall-time lines; the methods are run in turn, REPEATS times, and the fastest time of
# each is kept, so that all ratios come from one side-by-side session.
# Usage: scripts/benchmark_methods.sh [path to mpm-otm] [repeats]
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
exe=$(realpath "${1:-$root/build-release/mpm-otm}")
repeats=${2:-5}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"

# loop_time PRM NODES EXTRA: seconds of the time loop
loop_time() {
  steps=$((512000 / $2))
  cp "$root/prm/$1" run.prm
  printf 'subsection Time\n set End time = %s\nend\nsubsection Mesh\n set Subdivisions = %s\nend\nsubsection Output\n set Interval = 0\n set Format = none\n set Write particle CSV = false\nend\n%s\n' \
    "$(awk "BEGIN{print $steps * 1e-5}")" "$(($2 - 1))" "$3" >> run.prm
  "$exe" --overwrite run.prm > log
  t0=$(grep '^step  *0 ' log | sed 's/.*wall time = \([0-9.]*\) s.*/\1/')
  t1=$(grep "^step  *$steps " log | sed 's/.*wall time = \([0-9.]*\) s.*/\1/')
  awk "BEGIN{print $t1 - $t0}"
}

methods=("MPM-P1|B1b-bar-fixed-ends.prm|"
         "MPM-P1 consistent|B1b-bar-fixed-ends.prm|set Mass matrix = consistent"
         "OTM-P1|B1b-bar-fixed-ends-otm.prm|"
         "Unified P1|B1b-bar-fixed-ends-otm.prm|set Method = Unified"
         "BSMPM p=2|B1b-bar-fixed-ends-bsmpm.prm|"
         "BSMPM p=2 lumped|B1b-bar-fixed-ends-bsmpm.prm|set Mass matrix = lumped"
         "Unified p=2|B1b-bar-fixed-ends-unified.prm|"
         "MPM-maxent|B1b-bar-fixed-ends-mpm-maxent.prm|"
         "MPM-maxent lumped|B1b-bar-fixed-ends-mpm-maxent.prm|set Mass matrix = lumped"
         "OTM-maxent|B1b-bar-fixed-ends-otm-maxent.prm|")
declare -A best
for nodes in 32 512; do
  for ((r = 0; r < repeats; ++r)); do
    for entry in "${methods[@]}"; do
      IFS='|' read -r name prm extra <<< "$entry"
      t=$(loop_time "$prm" "$nodes" "$extra")
      key="$name@$nodes"
      if [ -z "${best[$key]:-}" ] || awk "BEGIN{exit !($t < ${best[$key]})}"; then
        best[$key]=$t
      fi
    done
  done
done

echo "| method | 32 nodes: loop time (s) | ratio | journal | 512 nodes: loop time (s) | ratio | journal |"
echo "|---|---|---|---|---|---|---|"
declare -A journal=(["MPM-P1@32"]="1" ["MPM-P1@512"]="1" ["OTM-P1@32"]="1.48" ["OTM-P1@512"]="1.19"
                    ["Unified P1@32"]="-" ["Unified P1@512"]="-" ["MPM-P1 consistent@32"]="-" ["MPM-P1 consistent@512"]="-"
                    ["BSMPM p=2@32"]="1.32" ["BSMPM p=2@512"]="1.04" ["BSMPM p=2 lumped@32"]="1.32" ["BSMPM p=2 lumped@512"]="1.04"
                    ["Unified p=2@32"]="1.78" ["Unified p=2@512"]="1.12"
                    ["MPM-maxent@32"]="0.98" ["MPM-maxent@512"]="2.31" ["MPM-maxent lumped@32"]="0.98" ["MPM-maxent lumped@512"]="2.31"
                    ["OTM-maxent@32"]="1.55" ["OTM-maxent@512"]="2.50")
for entry in "${methods[@]}"; do
  IFS='|' read -r name _ _ <<< "$entry"
  row="| $name"
  for nodes in 32 512; do
    t=${best["$name@$nodes"]}
    ratio=$(awk "BEGIN{printf \"%.2f\", $t / ${best["MPM-P1@$nodes"]}}")
    row="$row | $t | $ratio | ${journal["$name@$nodes"]}"
  done
  echo "$row |"
done
