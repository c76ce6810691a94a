#!/usr/bin/env bash
# Cost of the constitutive models on the 2D performance bar
# (prm/performance-bar-2d.prm: linear MPM, USL, lumped mass, 2 x 2 points
# per cell, 320 x 80 cells = 102400 points, 100 steps) on one core:
# nanoseconds per particle-step of the time loop (from the run's wall-time
# lines) for the hypo-elastic model and each elasto-plastic model, run
# interleaved (hypo-elastic, von Mises, Drucker-Prager, Mohr-Coulomb, then
# again) $2 times (default 3), and the ratio of each median to the
# hypo-elastic median. The plastic models are set up so that most points
# return in most steps: von Mises with a yield stress of 0.01 Pa (the bar's
# stresses reach about 1 Pa), Drucker-Prager and Mohr-Coulomb cohesionless
# (phi = 30 deg): every point in tension returns to the apex.
# Usage: scripts/benchmark_materials.sh [path to mpm-otm] [repetitions]
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
exe=${1:-$root/build-release/mpm-otm}
exe=$(cd "$(dirname "$exe")" && pwd)/$(basename "$exe")
repetitions=${2:-3}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"

# run MODEL [lines]: prints nanoseconds per particle-step of the time loop
run() {
  cp "$root/prm/performance-bar-2d.prm" run.prm
  printf 'subsection Material\n set Model = %s\n%s\nend\n' "$1" "${2:-}" >> run.prm
  "$exe" --overwrite run.prm > log
  points=$(grep -o '[0-9]* material points' log | cut -d' ' -f1)
  t0=$(grep '^step  *0 ' log | sed 's/.*wall time = \([0-9.]*\) s.*/\1/')
  t1=$(grep '^step  *100 ' log | sed 's/.*wall time = \([0-9.]*\) s.*/\1/')
  awk "BEGIN{printf \"%.1f\", ($t1 - $t0) * 1e9 / ($points * 100)}"
}

models=("hypo-elastic" "von Mises" "Drucker-Prager" "Mohr-Coulomb")
extras=("" " subsection von Mises
  set Yield stress = 0.01
 end" "" "")
declare -A times
for ((r = 0; r < repetitions; ++r)); do
  for i in "${!models[@]}"; do
    times[$i]="${times[$i]:-} $(run "${models[$i]}" "${extras[$i]}")"
  done
done
median() { tr ' ' '\n' | grep -v '^$' | sort -g | awk '{v[NR] = $1} END {print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2}'; }
base=$(echo "${times[0]}" | median)
echo "| model | ns per particle-step (runs) | median | ratio to hypo-elastic |"
echo "|---|---|---|---|"
for i in "${!models[@]}"; do
  m=$(echo "${times[$i]}" | median)
  echo "| ${models[$i]} |${times[$i]} | $m | $(awk "BEGIN{printf \"%.2f\", $m / $base}") |"
done
