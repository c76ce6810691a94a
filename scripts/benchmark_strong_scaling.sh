#!/usr/bin/env bash
# Strong scaling on this machine: the 2D bar of prm/performance-bar-2d.prm
# (USL, lumped mass, 100 steps) with about 1e6 material points, on 1 and 2
# MPI ranks, for linear functions on quadrilaterals (p4est) and on
# triangles (a fully distributed grid partitioned by METIS), quadratic
# B-splines, max-ent functions (d_max = 2) and Powell-Sabin splines. Runs
# alternate between 1 and 2 ranks, REPEAT times each (the
# machine is shared: compare runs of one series only). Prints a Markdown
# table with the seconds of the time loop (from the run's own wall-time
# lines, so set-up and output are excluded) and the speed-up. A third column
# times two independent 1-rank runs of the same problem side by side (the
# slower of the two): what the machine gives two processes that share
# nothing but its memory system and caches. 2 x (1 rank) / (side by side)
# is then the speed-up 2 ranks could reach without any communication.
# Usage: scripts/benchmark_strong_scaling.sh [path to mpm-otm] [REPEAT] [ROWS]
# (ROWS: a grep pattern that selects rows by label, e.g. 'max-ent').
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
exe=$(realpath "${1:-$root/build-release/mpm-otm}")
repeat=${2:-2}
rows=${3:-.}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1

# launch RANKS NX NY EXTRA DIRECTORY [MPIRUN OPTIONS]: runs in DIRECTORY,
# log in DIRECTORY/log
launch() {
  mkdir -p "$5"
  cp "$root/prm/performance-bar-2d.prm" "$5/run.prm"
  printf 'subsection Mesh\n set Subdivisions = %s, %s\nend\n%b\n' "$2" "$3" "$4" >> "$5/run.prm"
  (cd "$5" && mpirun ${6:-} -np "$1" "$exe" --overwrite run.prm < /dev/null > log 2>&1)
}
# seconds DIRECTORY: the time loop's seconds of the run in DIRECTORY
seconds() {
  t0=$(grep '^step  *0 ' "$1/log" | sed 's/.*wall time = \([0-9.]*\) s.*/\1/')
  t1=$(grep '^step  *100 ' "$1/log" | sed 's/.*wall time = \([0-9.]*\) s.*/\1/')
  awk "BEGIN{print $t1 - $t0}"
}
# run RANKS NX NY EXTRA: prints "points seconds_of_time_loop"
run() {
  launch "$@" single
  echo "$(grep -o '[0-9]* material points' single/log | head -1 | cut -d' ' -f1) $(seconds single)"
}
# side_by_side NX NY EXTRA: two 1-rank runs at once; prints the slower time
# (not bound to a core: two separate mpiruns would both bind to core 0)
side_by_side() {
  launch 1 "$1" "$2" "$3" first "--bind-to none" &
  launch 1 "$1" "$2" "$3" second "--bind-to none" &
  wait
  awk -v a="$(seconds first)" -v b="$(seconds second)" 'BEGIN { print (a > b ? a : b) }'
}

echo "| functions and grid | material points | 1 rank (s) | 2 ranks (s) | two 1-rank runs side by side (s) | speed-up | speed-up without communication |"
echo "|---|---|---|---|---|---|---|"
while IFS='|' read -r label nx ny extra; do
  echo "$label" | grep -q -- "$rows" || continue
  one="" two="" pair=""
  for _ in $(seq "$repeat"); do
    read -r points seconds < <(run 1 "$nx" "$ny" "$extra")
    one="$one $seconds"
    read -r points seconds < <(run 2 "$nx" "$ny" "$extra")
    two="$two $seconds"
    pair="$pair $(side_by_side "$nx" "$ny" "$extra")"
  done
  awk -v label="$label" -v p="$points" -v one="$one" -v two="$two" -v pair="$pair" 'BEGIN {
    n = split(one, a, " "); split(two, b, " "); split(pair, c, " ")
    best1 = a[1]; best2 = b[1]; bestc = c[1]; s1 = a[1]; s2 = b[1]; sc = c[1]
    for (i = 2; i <= n; ++i) {
      if (a[i] < best1) best1 = a[i]; if (b[i] < best2) best2 = b[i]; if (c[i] < bestc) bestc = c[i]
      s1 = s1 ", " a[i]; s2 = s2 ", " b[i]; sc = sc ", " c[i]
    }
    printf "| %s | %d | %s | %s | %s | %.2f | %.2f |\n", label, p, s1, s2, sc, best1 / best2, 2 * best1 / bestc
  }'
done <<'EOF'
linear, quadrilaterals|1000|250|
linear, triangles|1000|250|subsection Mesh\n set Cell type = simplex\nend
quadratic B-splines, quadrilaterals|1000|250|set Shape functions = B-spline
max-ent, quadrilaterals|1000|250|set Shape functions = max-ent
Powell-Sabin, triangles|1000|250|subsection Mesh\n set Cell type = simplex\nend\nset Shape functions = Powell-Sabin
EOF
echo
echo "(speed-up: best 1-rank time over best 2-rank time; without communication: 2 x best 1-rank time over the best side-by-side time)"
