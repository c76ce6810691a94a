#!/usr/bin/env bash
# The rules of "Particle velocity" (FLIP, PIC, blend 0.99, APIC; manual,
# 'Particle velocity') on three problems, with Update scheme = USL and MUSL:
#  - B1b, the vibrating bar with fixed ends (prm/B1b-bar-fixed-ends.prm,
#    linear, lumped mass; prm/B1b-bar-fixed-ends-bsmpm.prm, quadratic
#    B-splines, with its consistent mass, where APIC stops with a message,
#    and lumped): the
#    total energy after 10 periods of the first mode (T = 2 L / c =
#    0.031623 s) against its start, and the RMS displacement error then;
#  - G1, the cantilever switched on under gravity (prm/G1-cantilever-
#    vibration.prm, linear and quadratic B-splines, lumped mass, on the
#    4-cells-across-h grid of the test, dt = 4e-5 s
#    below USL's stable step, 0.8 s, about 5 periods), also with the file's MUSL FLIP: the period (mean time between
#    up-crossings of the tip's mean) against Timoshenko's 0.1624 s and the
#    decay, the tip's swing (max - min) in the last period over that in the
#    first;
#  - the spinning disk (prm/spinning-disk.prm, linear and quadratic
#    B-splines, 1000 steps): the angular momentum and the kinetic energy at
#    the end against the start.
# Writes doc/data/particle-velocity-*.dat and draws
# doc/figures/particle-velocity-disk.png and particle-velocity-G1.png
# (gnuplot-nox).
#
# Usage: doc/scripts/particle_velocity_rules.sh [path to mpm-otm]
# (default: build-release/mpm-otm, made by ./scripts/setup.sh run)
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
exe=${1:-$root/build-release/mpm-otm}
exe=$(cd "$(dirname "$exe")" && pwd)/$(basename "$exe")
data=$root/doc/data
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
rules="FLIP PIC blend APIC"

# Run prm/$1 with extra lines $2 appended; output in ./run. Prints nothing
# and returns 0 if the run ended, or prints "stopped at step N" if it
# stopped with an error.
run() {
  cp "$root/prm/$1" run.prm
  printf '%s\nsubsection Output\n set Directory = run\n set Format = none\n set Overwrite = true\nend\n' "$2" >> run.prm
  rm -rf run
  if ! "$exe" run.prm > run.log 2>&1; then
    grep -o 'Stopped in time step [0-9]*' run.log | sed 's/Stopped in time step/stopped at step/' || echo "failed"
  fi
}

# Column $1 (by name) of the last row of run/statistics.csv.
last_value() {
  awk -F, -v name="$1" 'NR == 1 { for (i = 1; i <= NF; i++) if ($i == name) c = i; next }
                        { v = $c } END { printf "%.15g", v }' run/statistics.csv
}

# Column $1 of the first row.
first_value() {
  awk -F, -v name="$1" 'NR == 1 { for (i = 1; i <= NF; i++) if ($i == name) c = i; next }
                        NR == 2 { printf "%.15g", $c }' run/statistics.csv
}

echo "B1b: total energy after 10 periods"
{
  echo "# family-mass scheme rule E(10T)/E(0) (prm/B1b-bar-fixed-ends*.prm)"
  for family in linear-lumped B-spline-consistent B-spline-lumped; do
    prm=B1b-bar-fixed-ends.prm
    mass=lumped
    case $family in
      B-spline-consistent) prm=B1b-bar-fixed-ends-bsmpm.prm; mass=consistent ;;
      B-spline-lumped) prm=B1b-bar-fixed-ends-bsmpm.prm ;;
    esac
    for scheme in USL MUSL; do
    for rule in $rules; do
      stopped=$(run "$prm" "set Particle velocity = $rule
set Update scheme = $scheme
set Mass matrix = $mass
subsection Time
 set End time = 0.31623
end
subsection Output
 set Interval = 0
 set Write particle CSV = false
end")
      if [ -n "$stopped" ]; then
        echo "$family $scheme $rule $stopped"
      else
        echo "$family $scheme $rule $(awk "BEGIN { printf \"%.6f\", $(last_value total_energy) / $(first_value total_energy) }")"
      fi
    done
    done
  done
} | tee "$data/particle-velocity-B1b.dat"

# tip_history X DT: the tip of the cantilever over time (tip_history.sh).
. "$root/doc/scripts/tip_history.sh"

echo "G1: period and decay of the cantilever's tip"
{
  echo "# family scheme rule period(s) swing_last/swing_first (Timoshenko 0.1624 s; prm/G1-cantilever-vibration.prm, 48 x 16 cells, lumped mass)"
  for family in linear B-spline; do
  for scheme in MUSL USL; do
  for rule in $rules; do
    stopped=$(run G1-cantilever-vibration.prm "set Update scheme = $scheme
set Particle velocity = $rule
set Shape functions = $family
set B-spline degree = 2
subsection Mesh
 set Subdivisions = 48, 16
end
subsection Time
 set Time step = 4e-5
 set End time = 0.8
end
subsection Output
 set Interval = 25
 set Write particle CSV = true
end")
    if [ -n "$stopped" ]; then
      echo "$family $scheme $rule $stopped"
      continue
    fi
    tip_history 0.99 4e-5 > tip.dat
    cp tip.dat "$data/particle-velocity-G1-tip-$family-$scheme-$rule.dat"
    awk -v label="$family $scheme $rule" '{ t[NR] = $1; u[NR] = $2; s += $2 } END {
      m = s / NR; n = 0
      for (i = 2; i <= NR; i++)
        if (u[i - 1] < m && u[i] >= m) {
          c[n++] = t[i - 1] + (m - u[i - 1]) / (u[i] - u[i - 1]) * (t[i] - t[i - 1]) }
      if (n < 3) { printf "%s no oscillation (overdamped)\n", label; exit }
      period = (c[n - 1] - c[0]) / (n - 1)
      # The swing in the first and in the last whole period.
      lo1 = 1e30; hi1 = -1e30; lo2 = 1e30; hi2 = -1e30
      for (i = 1; i <= NR; i++) {
        if (t[i] >= c[0] && t[i] <= c[1]) { lo1 = (u[i] < lo1) ? u[i] : lo1; hi1 = (u[i] > hi1) ? u[i] : hi1 }
        if (t[i] >= c[n - 2] && t[i] <= c[n - 1]) { lo2 = (u[i] < lo2) ? u[i] : lo2; hi2 = (u[i] > hi2) ? u[i] : hi2 }
      }
      printf "%s %.4f %.3f\n", label, period, (hi2 - lo2) / (hi1 - lo1) }' tip.dat
  done
  done
  done
} | tee "$data/particle-velocity-G1.dat"

echo "Spinning disk: angular momentum and kinetic energy after 1000 steps"
{
  echo "# family scheme rule L(1000)/L(0) - 1 E_kin(1000)/E_kin(0) (prm/spinning-disk.prm)"
  for family in linear B-spline; do
    for scheme in USL MUSL; do
    for rule in $rules; do
      stopped=$(run spinning-disk.prm "set Shape functions = $family
set B-spline degree = 2
set Update scheme = $scheme
set Particle velocity = $rule")
      if [ -n "$stopped" ]; then
        echo "$family $scheme $rule $stopped"
      else
        awk -F, 'NR == 2 { L0 = $NF; E0 = $3 } NR > 1 { print $2, $NF / L0, $3 / E0 }' \
          run/statistics.csv > "$data/particle-velocity-disk-$family-$scheme-$rule.dat"
        echo "$family $scheme $rule $(awk "BEGIN { printf \"%.3e %.4f\", $(last_value angular_momentum) / $(first_value angular_momentum) - 1, $(last_value kinetic_energy) / $(first_value kinetic_energy) }")"
      fi
    done
    done
  done
} | tee "$data/particle-velocity-disk.dat"

cd "$root/doc"
gnuplot <<'EOF'
set terminal pngcairo size 900,420 font ",11"
set output "figures/particle-velocity-disk.png"
set multiplot layout 1,2 title "Spinning elastic disk (prm/spinning-disk.prm), linear functions, 4 cells per radius (USL blend stopped in step 290)"
set grid
set xlabel "t (s)"
set ylabel "angular momentum / start"
set key bottom left
set yrange [0:1.05]
files = "FLIP PIC blend APIC"
plot for [r in files] "data/particle-velocity-disk-linear-USL-".r.".dat" using 1:2 with lines lw 2 title "linear, USL, ".r, \
     for [r in files] "data/particle-velocity-disk-linear-MUSL-".r.".dat" using 1:2 with lines lw 1 dt 2 title "linear, MUSL, ".r
set ylabel "kinetic energy / start"
plot for [r in files] "data/particle-velocity-disk-linear-USL-".r.".dat" using 1:3 with lines lw 2 title "linear, USL, ".r, \
     for [r in files] "data/particle-velocity-disk-linear-MUSL-".r.".dat" using 1:3 with lines lw 1 dt 2 title "linear, MUSL, ".r
unset multiplot

set terminal pngcairo size 800,480 font ",11"
set output "figures/particle-velocity-G1.png"
set title "G1: tip of the cantilever, quadratic B-splines, MUSL, lumped mass, 4 cells across h"
set xlabel "t (s)"
set ylabel "tip deflection -u_y (m)"
set key top center horizontal
set yrange [0:0.028]
plot for [r in files] "data/particle-velocity-G1-tip-B-spline-MUSL-".r.".dat" using 1:(-$2) with lines lw 2 title r, \
     1.0080e-2 * (1 - cos(2 * pi * x / 0.1624)) with lines lc rgb "gray" title "Timoshenko"
EOF
echo "wrote doc/figures/particle-velocity-disk.png and particle-velocity-G1.png"
