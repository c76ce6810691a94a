#!/usr/bin/env bash
# Cost of Powell-Sabin MPM (PS-MPM) against Lagrange (linear) MPM on B5, in
# one side-by-side session (Release build, one core):
#
# 1. Per material-point step on the B5 bar (prm/B5-bar-2d-small*.prm: MUSL,
#    consistent mass, hypo-elastic, 16 x 14 points per block = 56 per
#    triangle, dt = 1e-5, 2000 steps to t = 0.02) for the same number of
#    functions: PS has three per vertex, so a PS grid of n x m blocks is set
#    against a linear grid of 3n x m blocks (about three times the vertices;
#    three times the points too, the cost is per point-step). The time loop
#    is timed from the run's own wall-time lines; the "shape functions" row
#    of its timing table gives the evaluation's share.
# 2. Set-up of the shape functions (PS: refinement, control triangles,
#    ordinates; linear: the FE_SimplexP(1) numbering) from the run's line
#    "set-up of the shape functions: wall time = ... s", for about 1e3, 1e4
#    and 1e5 vertices (the bar with square blocks, 2 x 2 points per block,
#    lumped mass - too few points for a consistent one - and one step).
#
# Each run is repeated REPEATS times in turn and the fastest kept. Prints two
# Markdown tables.
# Usage: scripts/benchmark_powell_sabin.sh [path to mpm-otm] [repeats]
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
exe=${1:-$root/build-release/mpm-otm}
exe=$(cd "$(dirname "$exe")" && pwd)/$(basename "$exe")
repeats=${2:-3}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"

# run PRM NX NY EXTRA: runs prm/PRM on NX x NY blocks with EXTRA appended.
run() {
  cp "$root/prm/$1" run.prm
  printf 'subsection Mesh\n set Subdivisions = %s, %s\nend\nsubsection Output\n set Directory = run\n set Interval = 0\n set Format = none\n set Write particle CSV = false\nend\n%s\n' \
    "$2" "$3" "$4" >> run.prm
  rm -rf run
  "$exe" run.prm > log 2>&1 || { echo "failed: prm/$1 on $2 x $3 blocks:" >&2; tail -5 log >&2; exit 1; }
}

# step_cost PRM NX NY: "functions points ns_per_point_step
# shape_function_ns_per_point_step" of the 2000-step B5 run.
step_cost() {
  run "$1" "$2" "$3" ""
  functions=$(grep -o '[0-9]* shape functions' log | cut -d' ' -f1)
  points=$(grep -o '[0-9]* material points' log | cut -d' ' -f1)
  t0=$(grep '^step  *0 ' log | sed 's/.*wall time = \([0-9.]*\) s.*/\1/')
  t1=$(grep '^step  *2000 ' log | sed 's/.*wall time = \([0-9.]*\) s.*/\1/')
  shape=$(grep '^| shape functions' log | awk -F'|' '{print $4}' | sed 's/s *$//')
  awk -v f="$functions" -v p="$points" -v t0="$t0" -v t1="$t1" -v s="$shape" \
    'BEGIN { printf "%d %d %.1f %.1f\n", f, p, (t1 - t0) * 1e9 / (p * 2000), s * 1e9 / (p * 2000) }'
}

# setup_time PRM NX NY: "functions seconds" of the shape functions' set-up.
setup_time() {
  run "$1" "$2" "$3" "set Mass matrix = lumped
subsection Particles
 set Particles per cell = 2
end
subsection Time
 set End time = 1e-5
end"
  functions=$(grep -o '[0-9]* shape functions' log | cut -d' ' -f1)
  seconds=$(grep '^set-up of the shape functions' log | sed 's/.*wall time = \([0-9.]*\) s.*/\1/')
  echo "$functions $seconds"
}

# keep_min KEY VALUE...: best[KEY] = the run with the smallest third field
# (step costs) or second field (set-up times) so far.
declare -A best
keep() {
  local key=$1 field=$2
  shift 2
  local value="$*"
  local new old
  new=$(echo "$value" | cut -d' ' -f"$field")
  if [ -n "${best[$key]:-}" ]; then
    old=$(echo "${best[$key]}" | cut -d' ' -f"$field")
    awk "BEGIN{exit !($new < $old)}" || return 0
  fi
  best[$key]=$value
}

ps=B5-bar-2d-small-powell-sabin.prm
linear=B5-bar-2d-small.prm
step_sizes=("16 1" "64 4")
# Square blocks on the 25 x 2 bar: 2 nx ny + nx + ny + 1 vertices.
setup_sizes=("80 6" "250 20" "790 63")
for ((r = 0; r < repeats; ++r)); do
  for size in "${step_sizes[@]}"; do
    read -r nx ny <<< "$size"
    keep "ps@$size" 3 "$(step_cost $ps "$nx" "$ny")"
    keep "linear@$size" 3 "$(step_cost $linear $((3 * nx)) "$ny")"
  done
  for size in "${setup_sizes[@]}"; do
    read -r nx ny <<< "$size"
    keep "ps-setup@$size" 2 "$(setup_time $ps "$nx" "$ny")"
    keep "linear-setup@$size" 2 "$(setup_time $linear "$nx" "$ny")"
  done
done

echo "| blocks (PS / linear) | PS functions | linear functions | PS ns per point-step | linear ns per point-step | ratio | PS shape functions (ns) | linear shape functions (ns) |"
echo "|---|---|---|---|---|---|---|---|"
for size in "${step_sizes[@]}"; do
  read -r nx ny <<< "$size"
  read -r f_ps _ t_ps s_ps <<< "${best["ps@$size"]}"
  read -r f_lin _ t_lin s_lin <<< "${best["linear@$size"]}"
  awk -v a="$nx x $ny / $((3 * nx)) x $ny" -v fp="$f_ps" -v fl="$f_lin" -v tp="$t_ps" -v tl="$t_lin" -v sp="$s_ps" -v sl="$s_lin" \
    'BEGIN { printf "| %s | %d | %d | %.0f | %.0f | %.2f | %.0f | %.0f |\n", a, fp, fl, tp, tl, tp / tl, sp, sl }'
done
echo
echo "| blocks | vertices | PS set-up (s) | PS set-up per vertex (us) | linear set-up (s) | linear set-up per vertex (us) |"
echo "|---|---|---|---|---|---|"
for size in "${setup_sizes[@]}"; do
  read -r nx ny <<< "$size"
  read -r f_ps t_ps <<< "${best["ps-setup@$size"]}"
  read -r _ t_lin <<< "${best["linear-setup@$size"]}"
  awk -v a="$nx x $ny" -v v=$((f_ps / 3)) -v tp="$t_ps" -v tl="$t_lin" \
    'BEGIN { printf "| %s | %d | %.3f | %.2f | %.3f | %.2f |\n", a, v, tp, tp * 1e6 / v, tl, tl * 1e6 / v }'
done
