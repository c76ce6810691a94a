#!/usr/bin/env bash
# Cost of locating the material points on a grid read from a Gmsh file
# against the box grid with the same cells, on one core: a 4 m x 1 m
# rectangle of NX x NY quadrilaterals (default 320 x 80, 2 x 2 points per
# cell, 102,400 points), linear MPM (USL, lumped mass), 100 steps of 1e-4 s.
# Two motions: the bar's first mode (points stay in their cells) and a block
# [0.2, 3.4] x [0.1, 0.7] that translates at (20, 2) m/s (a point crosses a
# cell every 6 steps). Three grids: the box, the same grid as a Mesh file
# and a Mesh file whose inner vertices are shifted by up to 0.15 of a cell
# (cells that are no parallelograms, as Gmsh draws them).
# Prints a Markdown table of the timer section "move grid, locate particles"
# and of the whole time loop (seconds, each the least of REPEAT runs).
# Usage: scripts/benchmark_location.sh [path to mpm-otm] [NX NY] [REPEAT]
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
exe=$(realpath "${1:-$root/build-release/mpm-otm}")
nx=${2:-320}
ny=${3:-80}
repeat=${4:-3}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"

# write_mesh FILE SHIFT: the rectangle in Gmsh's format 2.2, boundary lines
# tagged 1 (bottom), 2 (left), 3 (right), 4 (top), the cells 10.
write_mesh() {
  awk -v nx="$nx" -v ny="$ny" -v shift="$2" 'BEGIN {
    hx = 4 / nx; hy = 1 / ny
    print "$MeshFormat\n2.2 0 8\n$EndMeshFormat"
    print "$PhysicalNames\n5\n1 1 \"bottom\"\n1 2 \"left\"\n1 3 \"right\"\n1 4 \"top\"\n2 10 \"domain\"\n$EndPhysicalNames"
    print "$Nodes"; print (nx + 1) * (ny + 1)
    for (j = 0; j <= ny; ++j)
      for (i = 0; i <= nx; ++i) {
        x = i * hx; y = j * hy
        if (i > 0 && i < nx && j > 0 && j < ny) {
          x += shift * hx * sin(2.1 * i + 1.3 * j)
          y += shift * hy * cos(1.7 * i + 2.9 * j)
        }
        printf "%d %.15g %.15g 0\n", j * (nx + 1) + i + 1, x, y
      }
    print "$EndNodes"; print "$Elements"; print 2 * (nx + ny) + nx * ny
    n = 0
    for (i = 0; i < nx; ++i) printf "%d 1 2 1 1 %d %d\n", ++n, i + 1, i + 2
    for (j = 0; j < ny; ++j) printf "%d 1 2 2 2 %d %d\n", ++n, j * (nx + 1) + 1, (j + 1) * (nx + 1) + 1
    for (j = 0; j < ny; ++j) printf "%d 1 2 3 3 %d %d\n", ++n, j * (nx + 1) + nx + 1, (j + 1) * (nx + 1) + nx + 1
    for (i = 0; i < nx; ++i) printf "%d 1 2 4 4 %d %d\n", ++n, ny * (nx + 1) + i + 1, ny * (nx + 1) + i + 2
    for (j = 0; j < ny; ++j)
      for (i = 0; i < nx; ++i) {
        a = j * (nx + 1) + i + 1
        printf "%d 3 2 10 10 %d %d %d %d\n", ++n, a, a + 1, a + nx + 2, a + nx + 1
      }
    print "$EndElements"
  }' > "$1"
}
write_mesh regular.msh 0
write_mesh shifted.msh 0.15

# run GRID MOTION: prints "locating_s time_loop_s" (least of the repeats).
run() {
  {
    printf 'set Dimension = 2\nset Problem = custom\nset Method = MPM\n'
    printf 'set Update scheme = USL\nset Shape functions = linear\n'
    printf 'set Mass matrix = lumped\nset Bodies = bar\n'
    printf 'subsection Time\n set End time = 1e-2\n set Time step = 1e-4\nend\n'
    if [ "$1" = box ]; then
      printf 'subsection Mesh\n set Lower corner = 0, 0\n set Upper corner = 4, 1\n'
      printf ' set Subdivisions = %s, %s\nend\n' "$nx" "$ny"
    else
      printf 'subsection Mesh\n set Mesh file = %s.msh\nend\n' "$1"
    fi
    printf 'subsection Particles\n set Particles per cell = 2\nend\n'
    printf 'subsection Material\n set Model = linear elastic\n'
    printf " set Young's modulus = 100\n set Poisson's ratio = 0\n set Density = 1\nend\n"
    if [ "$2" = mode ]; then
      printf 'subsection Body bar\n set Shape = box\n set Lower corner = 0, 0\n'
      printf ' set Upper corner = 4, 1\n set Initial velocity = 0.1 * sin(pi * x / 4); 0\nend\n'
    else
      printf 'subsection Body bar\n set Shape = box\n set Lower corner = 0.2, 0.1\n'
      printf ' set Upper corner = 3.4, 0.7\n set Initial velocity = 20; 2\nend\n'
    fi
    printf 'subsection Output\n set Directory = out\n set Interval = 0\n set Format = none\nend\n'
  } > run.prm
  best_locate=1e9
  best_loop=1e9
  for _ in $(seq "$repeat"); do
    "$exe" --overwrite run.prm > log
    locate=$(grep 'move grid, locate particles' log | awk -F'|' '{gsub(/s| /, "", $4); print $4}')
    t0=$(grep '^step  *0 ' log | sed 's/.*wall time = \([0-9.]*\) s.*/\1/')
    t1=$(grep '^step  *100 ' log | sed 's/.*wall time = \([0-9.]*\) s.*/\1/')
    best_locate=$(awk -v a="$best_locate" -v b="$locate" 'BEGIN{print (b < a ? b : a)}')
    best_loop=$(awk -v a="$best_loop" -v b="$t1" -v c="$t0" 'BEGIN{print (b - c < a ? b - c : a)}')
  done
  echo "$best_locate $best_loop"
}

echo "| motion | grid | locating (s) | time loop (s) | locating / box's |"
echo "|---|---|---|---|---|"
for motion in mode translation; do
  box_locate=
  for grid in box regular shifted; do
    read -r locate loop < <(run "$grid" "$motion")
    [ -z "$box_locate" ] && box_locate=$locate
    awk -v m="$motion" -v g="$grid" -v l="$locate" -v t="$loop" -v b="$box_locate" \
      'BEGIN { printf "| %s | %s | %.3f | %.3f | %.2f |\n", m, g, l, t, l / b }'
  done
done
