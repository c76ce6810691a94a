#!/usr/bin/env bash
# Stages with closed forms: prm/staged-column.prm, a soil column whose top
# layer is excavated (stage excavation) and then backfilled with a lighter
# material (stage backfill), each stage run to rest. Exact (one-dimensional
# compression, M = E (1 - nu) / ((1 + nu)(1 - 2 nu)), displacements from the
# stage's start): the excavation's heave u_y(Y) = q1 Y / M, q1 = 40 kPa; the
# backfill's settlement u_y(Y) = -q2 Y / M, q2 = 30 kPa, of the base and
# -q2 4 m / M of the fill; sigma_yy = -rho g (4 m - Y) - (0 or q2) in the
# base.
# Writes doc/data/staged-column-excavation.dat and
# doc/data/staged-column-backfill.dat (per point: Y, u_y, the exact u_y,
# sigma_yy, the exact sigma_yy; at the last step of each stage, from
# stages.csv), doc/data/staged-column-stages.csv (the run's stages.csv) and
# draws doc/figures/staged-column.png (gnuplot-nox).
#
# Usage: doc/scripts/staged_column.sh [path to mpm-otm]
# (default: build-release/mpm-otm, made by ./scripts/setup.sh run)
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
exe=${1:-$root/build-release/mpm-otm}
exe=$(cd "$(dirname "$exe")" && pwd)/$(basename "$exe")
data=$root/doc/data
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"

cp "$root/prm/staged-column.prm" run.prm
printf 'subsection Output\n set Directory = out\n set Format = none\n set Overwrite = true\nend\n' >> run.prm
"$exe" run.prm > run.log 2>&1
grep -E "^Stage|^Quasi-static" run.log
cp out/stages.csv "$data/staged-column-stages.csv"

E=10e6 nu=0.3 rho=2000 g=10
for stage in excavation backfill; do
  step=$(awk -F, -v name=$stage '$3 == name { print $1 }' out/stages.csv)
  file=$(printf 'out/particles-%05d.csv' "$step")
  if [ $stage = excavation ]; then q=-40e3; else q=30e3; fi
  awk -F, -v q=$q -v E=$E -v nu=$nu -v rho=$rho -v g=$g '
    NR == 1 { for (i = 1; i <= NF; ++i) column[$i] = i; next }
    {
      M = E * (1 - nu) / ((1 + nu) * (1 - 2 * nu))
      Y = $column["Y"]
      base = (Y < 4)
      exact_u = base ? -q * Y / M : -q * 4 / M
      exact_s = base ? -rho * g * (4 - Y) - (q > 0 ? q : 0) : 0
      printf "%.6g %.6g %.6g %.6g %.6g %d\n", Y, $column["uy"], exact_u,
             $column["syy"], exact_s, base
    }' "$file" | sort -g > "$data/staged-column-$stage.dat"
  awk -v q=$q -v E=$E -v nu=$nu -v stage=$stage '
    { M = E * (1 - nu) / ((1 + nu) * (1 - 2 * nu)); scale = (q < 0 ? -q : q) * 4 / M
      e = ($2 - $3) / scale; if (e < 0) e = -e
      if ($6 == 1 && e > base) base = e
      if ($6 == 0 && e > fill) fill = e }
    END { printf "%s: largest displacement error %.2f %% of q H / M in the base", stage, 100 * base
          if (fill > 0) printf ", %.2f %% in the fill", 100 * fill
          printf "\n" }' "$data/staged-column-$stage.dat"
done

gnuplot <<GP
set terminal pngcairo size 1000,420 font ",11" noenhanced
set output "$root/doc/figures/staged-column.png"
set multiplot layout 1,2
set xlabel "height Y at the stage's start (m)"
set ylabel "u_y (mm)"
set key top left
set title "excavation: heave of the base"
plot "$data/staged-column-excavation.dat" using 1:(1000*\$2) with points pt 7 ps 0.6 title "material points", \
     "" using 1:(1000*\$3) with lines lw 2 title "exact q1 Y / M"
set title "backfill: settlement of base and fill"
set key top right
plot "$data/staged-column-backfill.dat" using 1:(1000*\$2) with points pt 7 ps 0.6 title "material points", \
     "" using 1:(1000*\$3) with lines lw 2 title "exact: -q2 Y / M, then -q2 4 m / M"
unset multiplot
GP
echo "wrote $data/staged-column-*.dat, $data/staged-column-stages.csv and doc/figures/staged-column.png"
