#!/usr/bin/env bash
# Run the benchmarks of doc/benchmarks.md with the parameter files in prm/,
# collect the numbers in doc/data/*.dat and draw doc/figures/*.png with
# gnuplot (Debian package gnuplot-nox).
#
# Usage: doc/scripts/reproduce_benchmarks.sh [path to mpm-otm]
# (default: build-release/mpm-otm, made by ./scripts/setup.sh run; the
# program max-ent-functions-1d of the same build directory draws Fig. 4)
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
  printf '%s\nsubsection Output\n set Directory = run\n set Format = none\nend\n' "$2" >> run.prm
  rm -rf run
  "$exe" run.prm > /dev/null
}
# Last value of a column of run/statistics.csv.
last() { tail -1 run/statistics.csv | cut -d, -f"$1"; }

# Time series of the tracked points of a run: for each particles-*.csv of
# ./run, the time (step * $2) and the mean displacement and velocity of the
# points within $4 (default 0.05) of the middle X = $3 of a 1D/2D bar
# ($1 = middle) or of the top row of a column ($1 = top).
track() {
  for file in run/particles-*.csv; do
    step=$(basename "$file" .csv | sed 's/particles-0*//')
    awk -F, -v mode="$1" -v t="$(awk "BEGIN{print ${step:-0} * $2}")" -v middle="${3:-0}" -v half_width="${4:-0.05}" '
      NR == 1 { for (i = 1; i <= NF; i++) col[$i] = i
                up = ("Y" in col) ? "Y" : "X"; u = ("uy" in col && mode == "top") ? "uy" : "ux"
                v = ("vy" in col && mode == "top") ? "vy" : "vx" }
      NR > 1 && mode == "middle" && ($(col["X"]) - middle)^2 < half_width^2 { su += $(col[u]); sv += $(col[v]); n++ }
      NR > 1 && mode == "top" { y = $(col[up]); if (y > top + 1e-9) { top = y; su = 0; sv = 0; n = 0 }
                                if (y > top - 1e-9) { su += $(col[u]); sv += $(col[v]); n++ } }
      END { printf "%.6g %.8e %.8e\n", t, su / n, sv / n }' "$file"
  done | sort -g
}

echo "Journal Fig. 4: 1D max-ent functions, 11 nodes, d_max = 2"
"$(dirname "$exe")/max-ent-functions-1d" 11 2 400 > "$data/max-ent-functions-1d.dat"

echo "B1b: RMS displacement error at T = 1e-3 (P1, quadratic B-splines, max-ent)"
for entry in mpm-p1:B1b-bar-fixed-ends.prm otm-p1:B1b-bar-fixed-ends-otm.prm \
             bsmpm-p2:B1b-bar-fixed-ends-bsmpm.prm unified-p2:B1b-bar-fixed-ends-unified.prm \
             mpm-maxent:B1b-bar-fixed-ends-mpm-maxent.prm otm-maxent:B1b-bar-fixed-ends-otm-maxent.prm; do
  name=${entry%%:*}
  prm=${entry#*:}
  {
    echo "# nodes  rms_displacement_error  (prm/$prm)"
    for nodes in 8 16 32 64 128 256 512; do
      run $prm "subsection Mesh
 set Subdivisions = $((nodes - 1))
end
subsection Output
 set Write particle CSV = false
end"
      echo "$nodes $(last 6)"
    done
  } > "$data/B1b-$name.dat"
done

echo "B1b: stress profiles at T with 32 nodes (journal Fig. 5)"
for prm in B1b-bar-fixed-ends.prm B1b-bar-fixed-ends-otm.prm B1b-bar-fixed-ends-unified.prm; do
  run $prm "subsection Output
 set Interval = 0
 set Write particle CSV = true
end"
  awk -F, 'NR > 1 { printf "%.8f %.8e\n", $2, $6 }' run/particles-00100.csv | sort -g > "$prm.dat"
done
{
  echo "# X  sigma_exact  sigma_MPM_P1  sigma_OTM_P1  sigma_unified_p2  (32 nodes, T = 1e-3)"
  paste -d' ' B1b-bar-fixed-ends.prm.dat <(cut -d' ' -f2 B1b-bar-fixed-ends-otm.prm.dat) \
    <(cut -d' ' -f2 B1b-bar-fixed-ends-unified.prm.dat) |
    awk '{ pi = 3.14159265358979; c = sqrt(4e3)
           printf "%s %.8e %s %s %s\n", $1, 0.6 * sqrt(4e3) * sin(pi * c * 1e-3) * cos(pi * $1), $2, $3, $4 }'
} > "$data/B1b-stress-profile.dat"

echo "B1a: RMS stress error of MPM and OTM over the first 20 steps"
run B1a-bar-fixed-ends-conference.prm "set Method = MPM
set Update scheme = USL"
cut -d, -f1,8 run/statistics.csv | tail -n +2 > mpm.csv
run B1a-bar-fixed-ends-conference.prm "set Method = OTM"
cut -d, -f8 run/statistics.csv | tail -n +2 > otm.csv
{
  echo "# step  stress_rms_error_MPM  stress_rms_error_OTM  (prm/B1a-bar-fixed-ends-conference.prm)"
  paste -d, mpm.csv otm.csv | tr ',' ' '
} > "$data/B1a-stress-error.dat"

echo "B2: profiles at T = 0.4 and convergence at T = 0.1"
for method in mpm otm bsmpm unified mpm-maxent otm-maxent; do
  run B2-traction-bar-$method.prm ""
  {
    echo "# X  u  u_exact  sigma  sigma_exact  (prm/B2-traction-bar-$method.prm, T = 0.4)"
    awk -F, 'NR > 1 { pi = 3.14159265358979; t = 0.4; X = $2
        s1 = t + X; s2 = t - X
        f1 = (s1 >= 1 && s1 < 3) ? sin(pi * s1) : 0; f2 = (s2 >= 1 && s2 < 3) ? sin(pi * s2) : 0
        g1 = (s1 >= 1 && s1 < 3) ? -(1 + cos(pi * s1)) / pi : 0; g2 = (s2 >= 1 && s2 < 3) ? -(1 + cos(pi * s2)) / pi : 0
        printf "%.8f %.8e %.8e %.8e %.8e\n", X, $4, (g1 - g2) / 100, $6, f1 + f2 }' \
      run/particles-04000.csv | sort -g
  } > "$data/B2-profile-$method.dat"
done
short="subsection Time
 set End time = 0.1
end
subsection Particles
 set Particles per cell = 12
end
subsection Output
 set Write particle CSV = false
end"
{
  echo "# material_nodes  rms_displacement_error: MPM-P1  OTM-P1  BSMPM  unified  MPM-maxent  OTM-maxent  MPM-maxent_consistent_mass  (T = 0.1, 12 points per cell)"
  for nodes in 5 9 17 33 65 129 257; do
    fixed_grid="subsection Mesh
 set Subdivisions = $((5 * (nodes - 1) / 4))
end"
    material_grid="subsection Mesh
 set Subdivisions = $((nodes - 1))
end"
    run B2-traction-bar-convergence.prm "$fixed_grid
subsection Output
 set Write particle CSV = false
end"
    mpm=$(last 6)
    run B2-traction-bar-otm.prm "$short
$material_grid"
    otm=$(last 6)
    run B2-traction-bar-convergence.prm "$fixed_grid
set Shape functions = B-spline
set B-spline degree = 2
set Mass matrix = consistent
subsection Output
 set Write particle CSV = false
end"
    bsmpm=$(last 6)
    run B2-traction-bar-unified.prm "$short
$material_grid"
    unified=$(last 6)
    run B2-traction-bar-mpm-maxent.prm "$short
$fixed_grid
subsection Mesh
 set Upper corner = 1.25
end"
    mpm_maxent=$(last 6)
    run B2-traction-bar-mpm-maxent.prm "$short
$fixed_grid
subsection Mesh
 set Upper corner = 1.25
end
set Mass matrix = consistent"
    mpm_maxent_consistent=$(last 6)
    run B2-traction-bar-otm-maxent.prm "$short
$material_grid"
    echo "$nodes $mpm $otm $bsmpm $unified $mpm_maxent $(last 6) $mpm_maxent_consistent"
  done
} > "$data/B2-convergence.dat"

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

echo "B5: PS-MPM L2 displacement error at t = 0.02, and its dependence on the point layout on fine grids"
published=(3.70985e-04 3.13639e-05 3.56528e-06 4.90397e-07 1.76596e-07 -)
{
  echo "# n_x  h_x  L2_error  thesis_Table_4.3  (prm/B5-bar-2d-small-powell-sabin.prm)"
  i=0
  for nx in 2 3 5 9 17 33; do
    run B5-bar-2d-small-powell-sabin.prm "subsection Mesh
 set Subdivisions = $((nx - 1)), 1
end"
    echo "$nx $(awk "BEGIN{print 25/($nx-1)}") $(last 7) ${published[$i]}"
    i=$((i + 1))
  done
} > "$data/B5-powell-sabin.dat"
{
  echo "# n_x  points_per_block_x  points_per_block_y  points_per_triangle  L2_error  (prm/B5-bar-2d-small-powell-sabin.prm;"
  echo "# thesis Table 4.3 at n_x = 17: 56 points per triangle 1.76596e-07, 90 points per triangle 1.14682e-07)"
  for layout in "17 16 14" "17 14 16" "17 18 20" "17 20 18" "17 32 28" "33 16 14" "33 32 28"; do
    read -r nx px py <<< "$layout"
    run B5-bar-2d-small-powell-sabin.prm "subsection Mesh
 set Subdivisions = $((nx - 1)), 1
end
subsection Particles
 set Particles per cell = $px, $py
end"
    echo "$nx $px $py $((px * py / 4)) $(last 7)"
  done
} > "$data/B5-powell-sabin-layout.dat"

echo "B5 small deformation over three periods: middle of the bar, Lagrange and Powell-Sabin MPM"
run B5-bar-2d-small-history.prm ""
track middle 1e-3 12.5 0.16 > lagrange.dat
run B5-bar-2d-small-history-powell-sabin.prm ""
track middle 1e-3 12.5 0.16 > powell-sabin.dat
{
  echo "# time  u_exact  v_exact  u_MPM  v_MPM  u_PS_MPM  v_PS_MPM  (points within 0.16 of the middle X = 12.5, exact at X = 12.5, 1.3e-4 of it from theirs; prm/B5-bar-2d-small-history.prm, prm/B5-bar-2d-small-history-powell-sabin.prm)"
  paste -d' ' lagrange.dat <(cut -d' ' -f2,3 powell-sabin.dat) |
    awk '{ w = 3.14159265358979 * 10 / 25; print $1, 0.1 / w * sin(w * $1), 0.1 * cos(w * $1), $2, $3, $4, $5 }'
} > "$data/B5-history.dat"

echo "B6: top displacement of the soil column (Lagrange and Powell-Sabin MPM)"
# The top row of points of ./run against the exact series (BENCHMARKS.md B6).
top_against_exact() {
  echo "# time  top_displacement  exact  top_velocity  exact  (prm/$1)"
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
}
run B6-soil-column-small.prm ""
top_against_exact B6-soil-column-small.prm > "$data/B6-top.dat"
run B6-soil-column-small-powell-sabin.prm ""
top_against_exact B6-soil-column-small-powell-sabin.prm > "$data/B6-top-powell-sabin.dat"
run B6-soil-column-small-powell-sabin.prm "subsection Mesh
 set Subdivisions = 2, 16
end"
top_against_exact "B6-soil-column-small-powell-sabin.prm on 2 x 16 blocks" > "$data/B6-top-powell-sabin-2x16.dat"

echo "B5 and B6, large deformation: Lagrange MPM against the 1D OTM reference"
run B5-bar-large-reference-1d.prm ""
track middle 1e-3 12.5 > reference.dat
run B5-bar-2d-large.prm ""
track middle 1e-3 12.5 > mpm.dat
# Powell-Sabin: 10 points per block of width 3.125 in x; the nearest to the
# middle are 0.156 from it, where u differs from the middle's by 2e-4.
run B5-bar-2d-large-powell-sabin.prm ""
track middle 1e-3 12.5 0.16 > powell-sabin.dat
run B5-bar-2d-large-powell-sabin-unified.prm ""
track middle 1e-3 12.5 0.16 > unified.dat
{
  echo "# time  u_reference  v_reference  u_MPM  v_MPM  u_PS_MPM  v_PS_MPM  (middle of the bar; prm/B5-bar-large-reference-1d.prm, prm/B5-bar-2d-large.prm, prm/B5-bar-2d-large-powell-sabin.prm, then u_unified_PS v_unified_PS: prm/B5-bar-2d-large-powell-sabin-unified.prm)"
  paste -d' ' reference.dat <(cut -d' ' -f2,3 mpm.dat) <(cut -d' ' -f2,3 powell-sabin.dat) <(cut -d' ' -f2,3 unified.dat)
} > "$data/B5-large.dat"
run B6-soil-column-large-reference-1d.prm ""
track top 2e-5 > reference.dat
run B6-soil-column-2d-large.prm ""
track top 1e-4 > mpm.dat
run B6-soil-column-2d-large-powell-sabin.prm ""
track top 1e-4 > powell-sabin.dat
run B6-soil-column-2d-large-powell-sabin-unified.prm ""
track top 1e-4 > unified.dat
{
  echo "# time  u_reference  v_reference  u_MPM  v_MPM  u_PS_MPM  v_PS_MPM  (top of the column; prm/B6-soil-column-large-reference-1d.prm, prm/B6-soil-column-2d-large.prm, prm/B6-soil-column-2d-large-powell-sabin.prm, then u_unified_PS v_unified_PS: prm/B6-soil-column-2d-large-powell-sabin-unified.prm)"
  paste -d' ' reference.dat <(cut -d' ' -f2,3 mpm.dat) <(cut -d' ' -f2,3 powell-sabin.dat) <(cut -d' ' -f2,3 unified.dat)
} > "$data/B6-large.dat"

echo "B6, large deformation, thesis Chapter 5: Powell-Sabin MPM with nearly empty cells"
prm=B6-soil-column-large-powell-sabin-remedies.prm
for remedy in "partially-lumped:" "lumped:set Mass matrix = lumped" \
              "deactivated:set Mass matrix = consistent
set Deactivation threshold = 1e-2" "deactivated-1e-3:set Mass matrix = consistent
set Deactivation threshold = 1e-3"; do
  run $prm "${remedy#*:}"
  track top 1e-4 > "${remedy%%:*}.dat"
done
# The unified approach: the grid is the column and moves with it.
run B6-soil-column-large-powell-sabin-unified.prm ""
track top 1e-4 > unified.dat
{
  echo "# time  u_reference  v_reference  then u, v of the top for: partially lumped, lumped, deactivation below 1e-2, below 1e-3  (prm/$prm), unified approach with the consistent matrix (prm/B6-soil-column-large-powell-sabin-unified.prm)"
  paste -d' ' reference.dat <(cut -d' ' -f2,3 partially-lumped.dat) <(cut -d' ' -f2,3 lumped.dat) \
    <(cut -d' ' -f2,3 deactivated.dat) <(cut -d' ' -f2,3 deactivated-1e-3.dat) <(cut -d' ' -f2,3 unified.dat)
} > "$data/B6-remedies.dat"
# The same remedies on 2 x 16 (+1) blocks.
prm_2x16=B6-soil-column-large-powell-sabin-remedies-2x16.prm
for remedy in "partially-lumped:" "lumped:set Mass matrix = lumped"; do
  run $prm_2x16 "${remedy#*:}"
  track top 1e-4 > "${remedy%%:*}-2x16.dat"
done
{
  echo "# time  u_reference  v_reference  then u, v of the top for: partially lumped, lumped  (prm/$prm_2x16)"
  paste -d' ' reference.dat <(cut -d' ' -f2,3 partially-lumped-2x16.dat) <(cut -d' ' -f2,3 lumped-2x16.dat)
} > "$data/B6-remedies-2x16.dat"
# Largest deviations from the reference, relative to its largest value, of
# the displacement and velocity pairs (columns 4, 5; 6, 7; ...) of a data
# file whose columns 2 and 3 are the reference.
largest_deviations() {
  awk 'function abs(x) { return x < 0 ? -x : x }
       !/^#/ { if (abs($2) > umax) umax = abs($2)
               if (abs($3) > vmax) vmax = abs($3)
               for (i = 4; i < NF; i += 2) {
                 if (abs($i - $2) > eu[i]) eu[i] = abs($i - $2)
                 if (abs($(i + 1) - $3) > ev[i]) ev[i] = abs($(i + 1) - $3) }
               n = NF }
       END { for (i = 4; i < n; i += 2) printf "%s %.1f%% / %.1f%%", (i > 4 ? "," : ""), 100 * eu[i] / umax, 100 * ev[i] / vmax; print "" }' "$1"
}
{
  echo "# largest displacement / velocity deviation of the top from the 1D reference, relative to its largest value"
  echo "1 x 8 (+1) blocks, partially lumped, lumped, deactivation below 1e-2, below 1e-3, and the unified approach (1 x 8 blocks, consistent):$(largest_deviations "$data/B6-remedies.dat")"
  echo "2 x 16 (+1) blocks, partially lumped, lumped:$(largest_deviations "$data/B6-remedies-2x16.dat")"
} > "$data/B6-remedies-deviations.txt"
# The consistent mass matrix: the run stops; keep where, on 1 x 8 (+1) and
# on 2 x 16 (+1) blocks.
{
  for entry in "1 x 8 (+1):$prm" "2 x 16 (+1):$prm_2x16"; do
    run "${entry#*:}" "set Mass matrix = consistent" 2> consistent.txt || true
    echo "${entry%%:*} blocks: $(tr -s ' \n' ' ' < consistent.txt | grep -o 'Stopped in time step [0-9]* (t = [0-9.e-]* to [0-9.e-]*)')"
  done
} > "$data/B6-remedies-consistent.txt"

echo "B3: sigma11 along X2 = 0.0664 at T = 3.5e-3"
: > "$data/B3-errors.dat"
for method in otm bsmpm unified mpm-maxent otm-maxent; do
  run B3-plate-manufactured-$method.prm "subsection Output
 set Interval = 0
end"
  awk -F, 'NR > 1 && ($3 - 0.06640625)^2 < 1e-18 { printf "%.8f %.8e\n", $2, $10 }' \
    run/particles-00035.csv | sort -g > $method.dat
  echo "$method $(last 6) $(last 8)" >> "$data/B3-errors.dat"
done
# MPM-maxent with the lumped mass instead of the prm file's consistent one.
run B3-plate-manufactured-mpm-maxent.prm "set Mass matrix = lumped
subsection Output
 set Interval = 0
end"
awk -F, 'NR > 1 && ($3 - 0.06640625)^2 < 1e-18 { printf "%.8f %.8e\n", $2, $10 }' \
  run/particles-00035.csv | sort -g > mpm-maxent-lumped.dat
echo "mpm-maxent-lumped $(last 6) $(last 8)" >> "$data/B3-errors.dat"
run B3-plate-manufactured.prm "subsection Output
 set Interval = 0
end"
echo "mpm $(last 6) $(last 8)" >> "$data/B3-errors.dat"
sed -i '1i # method  rms_displacement_error  rms_stress_error  (T = 3.5e-3, prm/B3-plate-manufactured*.prm)' "$data/B3-errors.dat"
{
  echo "# X1  sigma11_MPM_P1  sigma11_exact  sigma11_OTM_P1  sigma11_BSMPM  sigma11_unified  sigma11_MPM_maxent  sigma11_OTM_maxent  sigma11_MPM_maxent_lumped  (prm/B3-plate-manufactured*.prm)"
  awk -F, 'NR > 1 && ($3 - 0.06640625)^2 < 1e-18 {
      pi = 3.14159265358979; E = 1e7; nu = 0.3; rho = 1000; A = 0.005; t = 3.5e-3
      lambda = E * nu / ((1 + nu) * (1 - 2 * nu)); mu = E / (2 * (1 + nu)); c = sqrt(E / rho)
      F1 = 1 + 2 * pi * A * cos(2 * pi * $2) * sin(c * pi * t)
      F2 = 1 + 2 * pi * A * cos(2 * pi * $3) * sin(c * pi * t + pi)
      J = F1 * F2
      printf "%.8f %.8e %.8e\n", $2, $10, (lambda * log(J) + mu * (F1 * F1 - 1)) / J }' \
    run/particles-00035.csv | sort -g |
    paste -d' ' - <(cut -d' ' -f2 otm.dat) <(cut -d' ' -f2 bsmpm.dat) <(cut -d' ' -f2 unified.dat) \
      <(cut -d' ' -f2 mpm-maxent.dat) <(cut -d' ' -f2 otm-maxent.dat) \
      <(cut -d' ' -f2 mpm-maxent-lumped.dat)
} > "$data/B3-sigma11.dat"

echo "B4: L2 projection onto Powell-Sabin splines and P1, structured and perturbed grids"
# No time stepping: a program of its own (doc/scripts/b4_projection.cc),
# built next to mpm-otm (target b4-projection).
b4=$(dirname "$exe")/b4-projection
[ -x "$b4" ] || cmake --build "$(dirname "$exe")" --target b4-projection > /dev/null
"$b4" > "$data/B4-projection.dat"

echo "Plots"
cd "$root/doc"
gnuplot scripts/benchmarks.gp
echo "Done: doc/data/*.dat and doc/figures/*.png"
