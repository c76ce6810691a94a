#!/usr/bin/env bash
# G10 (BENCHMARKS.md): the absorbing (Lysmer-Kuhlemeyer) base of
# prm/G10-absorbing-boundary.prm. A half-sine velocity pulse on the top of
# an elastic column (1 m x 10 m) travels down at normal incidence; runs:
#  - P wave (top moving down, sides slipping), base absorbing, with linear
#    functions (MPM and the unified approach), quadratic B-splines and
#    max-ent; base fixed (full reflection);
#  - the reference: the same column twice as deep (20 m, base fixed), whose
#    base the pulse has not left by the End time;
#  - S wave (top moving along x, sides held vertically), base absorbing,
#    on the file's cells and on cells half as large; base fixed.
# For each: the work the top supplied against rho c V^2 t_p / 2, the
# energy left in the column at the End time (what the base reflected)
# over the supplied work, and the points' mean displacement against the
# pulse's 2 V t_p / pi. The P runs also give the history of the energy in
# the column and the vertical displacement of the point at
# (0.4375, 5.0625), 4.94 m below the top (in the reference the point at
# the same depth).
# Writes doc/data/G10-absorbing.dat (table), G10-absorbing-energy.dat
# (energy in the column over the work supplied so far: P absorbing, P
# fixed, S absorbing),
# G10-absorbing-point.dat and draws doc/figures/G10-absorbing.png
# (gnuplot-nox).
#
# Usage: doc/scripts/g10_absorbing.sh [path to mpm-otm]
# (default: build-release/mpm-otm, made by ./scripts/setup.sh run)
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
exe=${1:-$root/build-release/mpm-otm}
exe=$(cd "$(dirname "$exe")" && pwd)/$(basename "$exe")
data=$root/doc/data
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"

rho=2000 V=0.01 tp=0.05 cp=82.0413 cs=43.8529

# Run the file with extra lines $2 into directory $1.
run() {
  cp "$root/prm/G10-absorbing-boundary.prm" "$1.prm"
  printf '%s\nsubsection Output\n set Directory = %s\n set Format = none\n set Overwrite = true\nend\n' "$2" "$1" >> "$1.prm"
  "$exe" "$1.prm" > "$1.log" 2>&1
}

shear='subsection Time
 set End time = 0.35
end
subsection Boundary top
 set Velocity components = x
 set Velocity = t < 0.05 ? 0.01 * sin(pi * t / 0.05) : 0; 0
end
subsection Boundary left
 set Type = velocity
 set Velocity components = y
end
subsection Boundary right
 set Type = velocity
 set Velocity components = y
end'
fixed='subsection Boundary base
 set Type = fixed
end'
csv='subsection Output
 set Write particle CSV = true
end'

run p-linear "$csv"
run p-unified "set Method = Unified
set Update scheme = USL"
run p-bspline "set Shape functions = B-spline"
run p-maxent "set Shape functions = max-ent"
run p-fixed "$fixed
$csv"
run p-reference "$fixed
$csv
subsection Mesh
 set Upper corner = 1, 20
 set Subdivisions = 4, 80
end"
run s-linear "$shear"
run s-fine "$shear
subsection Mesh
 set Subdivisions = 8, 80
end"
run s-fixed "$shear
$fixed"

# The table row of run $1 (label $2, wave speed $3, displacement
# component $4 of the particle CSV: 6 ux, 7 uy), from its statistics and
# its points at the end (the last particle CSV, or a run writing one).
row() {
  local dir=$1 label=$2 c=$3
  awk -F, -v label="$label" -v rho=$rho -v V=$V -v tp=$tp -v c="$c" '
    NR == 1 { for (i = 1; i <= NF; i++) { if ($i == "kinetic_energy") k = i;
              if ($i == "strain_energy") s = i; if ($i == "supplied_work") w = i }
              next }
    { e = $k + $s; work = $w }
    END { incident = rho * c * V * V * tp / 2;
          printf "%-28s %10.5f %10.5f %+8.2f%% %10.3e\n", label, work,
                 incident, 100 * (work / incident - 1), e / work }' \
    "$dir/statistics.csv"
}

{
  echo "# G10: absorbing base, pulse at normal incidence (doc/scripts/g10_absorbing.sh)"
  echo "# case  supplied_work(J/m)  rho_c_V^2_tp/2  difference  energy_left/supplied"
  row p-linear "P_linear_MPM_absorbing" $cp
  row p-unified "P_linear_Unified_absorbing" $cp
  row p-bspline "P_B-spline_p2_absorbing" $cp
  row p-maxent "P_max-ent_absorbing" $cp
  row p-fixed "P_linear_base_fixed" $cp
  row s-linear "S_linear_absorbing" $cs
  row s-fine "S_linear_8x80_absorbing" $cs
  row s-fixed "S_linear_base_fixed" $cs
} > "$data/G10-absorbing.dat"
cat "$data/G10-absorbing.dat"

# Energy in the column over the work supplied so far, per time: one block
# per run (gnuplot's index 0, 1, 2).
energy() {
  awk -F, -v label="$2" 'NR == 1 { for (i = 1; i <= NF; i++) {
             if ($i == "kinetic_energy") k = i; if ($i == "strain_energy") s = i;
             if ($i == "supplied_work") w = i }
             print "# " label ": time  E/W"; next }
           { printf "%g %.6g\n", $2, ($w > 0 ? ($k + $s) / $w : 0) }' "$1/statistics.csv"
}
{
  energy p-linear "P wave, absorbing base"; printf '\n\n'
  energy p-fixed "P wave, fixed base"; printf '\n\n'
  energy s-linear "S wave, absorbing base"
} > "$data/G10-absorbing-energy.dat"

# The monitored point's vertical displacement (mm) over time: X = 0.4375,
# Y = 5.0625 (absorbing, fixed), Y = 15.0625 (reference).
point() {
  local dir=$1 Y=$2
  for file in "$dir"/particles-*.csv; do
    step=${file##*-}; step=${step%.csv}
    awk -F, -v Y="$Y" -v t="$((10#$step))" 'NR > 1 && ($2 - 0.4375)^2 < 1e-12 && ($3 - Y)^2 < 1e-12 { printf "%g %.6g\n", t * 1e-3, 1e3 * $7 }' "$file"
  done
}
point p-linear 5.0625 > a.dat
point p-fixed 5.0625 > f.dat
point p-reference 15.0625 > r.dat
{
  echo "# time  uy_absorbing(mm)  uy_base_fixed(mm)  uy_reference_20m(mm); pulse: -2 V t_p / pi = -0.3183 mm"
  paste -d' ' a.dat f.dat r.dat | awk '{ print $1, $2, $4, $6 }'
} > "$data/G10-absorbing-point.dat"
awk 'NR > 1 { if ($4 < m) m = $4; if ($2 < a) a = $2 } END {
       printf "largest downward displacement: absorbing %.4f mm, reference %.4f mm (%+.2f %%)\n", a, m, 100 * (a / m - 1) }' \
  "$data/G10-absorbing-point.dat"

gnuplot <<GP
set terminal pngcairo size 1100,420 font ",10"
set output "$root/doc/figures/G10-absorbing.png"
set multiplot layout 1,2
set xlabel "t (s)"
set ylabel "energy in the column / work supplied"
set key bottom left
set yrange [0:1.1]
plot "$data/G10-absorbing-energy.dat" index 0 u 1:2 w l lw 2 t "P wave, absorbing base", \
     "" index 1 u 1:2 w l lw 2 dt 2 t "P wave, fixed base", \
     "" index 2 u 1:2 w l lw 2 t "S wave, absorbing base"
set ylabel "u_y at 4.94 m below the top (mm)"
set key top right
set yrange [*:*]
plot "$data/G10-absorbing-point.dat" u 1:2 w l lw 2 t "absorbing base", \
     "" u 1:4 w p pt 6 ps 0.6 t "reference, 20 m deep", \
     "" u 1:3 w l lw 1 dt 2 t "fixed base", \
     -0.3183 w l lw 1 lc rgb "black" dt 3 t "-2 V t_p / pi"
unset multiplot
GP
echo "wrote doc/figures/G10-absorbing.png"
