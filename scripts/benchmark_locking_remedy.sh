#!/usr/bin/env bash
# Cost of the volumetric locking remedy: the time loop of G3
# (prm/G3-prandtl-footing.prm and -bspline.prm, 40 x 48 cells, 7680 points,
# 750 steps to t = 0.3 s, no field output) with Volumetric locking remedy =
# none and F-bar, run alternately so that both see the same machine, three
# times each. Prints a Markdown table: the time-loop wall time of every run
# (from the run's own wall-time lines) and the ratio F-bar / none of the
# medians.
# Usage: scripts/benchmark_locking_remedy.sh [path to mpm-otm]
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
exe=$(realpath "${1:-$root/build-release/mpm-otm}")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"

# run PRM REMEDY: prints the seconds of the time loop
run() {
  cp "$root/prm/$1" run.prm
  printf 'set Volumetric locking remedy = %s\nsubsection Time\n set End time = 0.3\nend\nsubsection Output\n set Directory = run\n set Format = none\n set Interval = 100000\nend\n' "$2" >> run.prm
  "$exe" --overwrite run.prm > log
  t0=$(grep '^step  *0 ' log | sed 's/.*wall time = \([0-9.]*\) s.*/\1/')
  t1=$(grep '^step  *750 ' log | sed 's/.*wall time = \([0-9.]*\) s.*/\1/')
  awk "BEGIN{print $t1 - $t0}"
}

median() { printf '%s\n' "$@" | sort -g | sed -n 2p; }

echo "| functions | none (s) | F-bar (s) | F-bar / none (medians) |"
echo "|---|---|---|---|"
for prm in G3-prandtl-footing.prm G3-prandtl-footing-bspline.prm; do
  none=()
  f_bar=()
  for repeat in 1 2 3; do
    none+=("$(run $prm none)")
    f_bar+=("$(run $prm F-bar)")
  done
  family=linear
  [ "$prm" = G3-prandtl-footing-bspline.prm ] && family="B-splines p = 2"
  echo "| $family | ${none[*]} | ${f_bar[*]} | $(awk "BEGIN{printf \"%.3f\", $(median "${f_bar[@]}") / $(median "${none[@]}")}") |"
done
