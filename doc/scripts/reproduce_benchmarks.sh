#!/usr/bin/env bash
# Run the benchmarks of doc/benchmarks.md with the parameter files in prm/,
# collect the numbers in doc/data/*.dat and draw doc/figures/*.png with
# gnuplot (Debian package gnuplot-nox).
#
# Usage: doc/scripts/reproduce_benchmarks.sh [path to mpm-otm]
# (default: build-release/mpm-otm, made by ./scripts/setup.sh run)
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
exe=${1:-$root/build-release/mpm-otm}
exe=$(cd "$(dirname "$exe")" && pwd)/$(basename "$exe")
data=$root/doc/data
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"

# Run prm/$1 with extra lines $2 appended; output in ./run.
run() {
  cp "$root/prm/$1" run.prm
  printf '%s\nsubsection Output\n set Directory = run\n set Write VTU = false\nend\n' "$2" >> run.prm
  rm -rf run
  "$exe" run.prm > /dev/null
}
# Last value of a column of run/statistics.csv.
last() { tail -1 run/statistics.csv | cut -d, -f"$1"; }

echo "B1b: MPM-P1 RMS displacement error at T = 1e-3"
{
  echo "# nodes  rms_displacement_error  (prm/B1b-bar-fixed-ends.prm)"
  for nodes in 8 16 32 64 128 256 512; do
    run B1b-bar-fixed-ends.prm "subsection Mesh
 set Subdivisions = $((nodes - 1))
end
subsection Output
 set Write particle CSV = false
end"
    echo "$nodes $(last 6)"
  done
} > "$data/B1b-mpm-p1.dat"

echo "B5: Lagrange MPM L2 displacement error at t = 0.02"
published=(1.80956e-04 4.44076e-05 1.07531e-05 2.68352e-06)
{
  echo "# n_x  h_x  L2_error  thesis_Table_4.2  (prm/B5-bar-2d-small.prm)"
  i=0
  for nx in 5 9 17 33; do
    run B5-bar-2d-small.prm "subsection Mesh
 set Subdivisions = $((nx - 1)), 1
end"
    echo "$nx $(awk "BEGIN{print 25/($nx-1)}") $(last 7) ${published[$i]}"
    i=$((i + 1))
  done
} > "$data/B5-lagrange.dat"

echo "B6: top displacement of the soil column"
run B6-soil-column-small.prm ""
{
  echo "# time  top_displacement  exact  top_velocity  exact  (prm/B6-soil-column-small.prm)"
  for file in run/particles-*.csv; do
    step=$(basename "$file" .csv | sed 's/particles-0*//')
    awk -F, -v step="${step:-0}" 'NR > 1 { if ($3 > top + 1e-9) { top = $3; u = 0; v = 0; n = 0 }
        if ($3 > top - 1e-9) { u += $7; v += $9; n++ } }
      END {
        t = step * 1e-4; H = 25; c = sqrt(5e4); g = -9.81; pi = 3.14159265358979; ue = 0; ve = 0
        for (k = 1; k <= 400; k++) { m = 2 * k - 1; kk = m * pi / (2 * H); a = 16 * H * H / (m * m * m * pi * pi * pi)
          ue += a * (1 - cos(c * kk * t)) * sin(kk * top); ve += a * c * kk * sin(c * kk * t) * sin(kk * top) }
        printf "%.6g %.8e %.8e %.8e %.8e\n", t, u / n, g / (c * c) * ue, v / n, g / (c * c) * ve }' "$file"
  done | sort -g
} > "$data/B6-top.dat"

echo "B3: sigma11 along X2 = 0.0664 at T = 3.5e-3"
run B3-plate-manufactured.prm "subsection Output
 set Interval = 0
end"
{
  echo "# X1  sigma11_MPM_P1  sigma11_exact  (prm/B3-plate-manufactured.prm)"
  awk -F, 'NR > 1 && ($3 - 0.06640625)^2 < 1e-18 {
      pi = 3.14159265358979; E = 1e7; nu = 0.3; rho = 1000; A = 0.005; t = 3.5e-3
      lambda = E * nu / ((1 + nu) * (1 - 2 * nu)); mu = E / (2 * (1 + nu)); c = sqrt(E / rho)
      F1 = 1 + 2 * pi * A * cos(2 * pi * $2) * sin(c * pi * t)
      F2 = 1 + 2 * pi * A * cos(2 * pi * $3) * sin(c * pi * t + pi)
      J = F1 * F2
      printf "%.8f %.8e %.8e\n", $2, $10, (lambda * log(J) + mu * (F1 * F1 - 1)) / J }' \
    run/particles-00035.csv | sort -g
} > "$data/B3-sigma11.dat"

echo "Plots"
cd "$root/doc"
gnuplot scripts/benchmarks.gp
echo "Done: doc/data/*.dat and doc/figures/*.png"
