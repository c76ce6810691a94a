#!/usr/bin/env bash
# Run the benchmarks G1-G5 of doc/benchmarks.md (BENCHMARKS.md "Beyond the
# seeds") and the biaxial test with strain softening with the parameter
# files in prm/, collect the numbers in doc/data/G*.dat and biaxial-*.dat
# and draw the figures in doc/figures/ with gnuplot (Debian package
# gnuplot-nox; doc/scripts/user_problems.gp).
#
# Usage: doc/scripts/reproduce_user_problems.sh [path to mpm-otm]
#   [G1 G2 G3 G4 G5 biaxial]
# (default: build-release/mpm-otm, made by ./scripts/setup.sh run; all of
# them; G5 needs python3-numpy for Bishop's method)
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
exe=${1:-$root/build-release/mpm-otm}
exe=$(cd "$(dirname "$exe")" && pwd)/$(basename "$exe")
shift || true
benchmarks=${*:-G1 G2 G3 G4 G5 biaxial}
data=$root/doc/data
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"

# Run prm/$1 with extra lines $2 appended; output in ./run.
run() {
  cp "$root/prm/$1" run.prm
  printf '%s\nsubsection Output\n set Directory = run\n set Format = none\nend\n' "$2" >> run.prm
  rm -rf run
  "$exe" run.prm > run.log 2>&1 || { tail -5 run.log >&2; return 1; }
}

# tip_history X DT: the tip of the cantilever over time (tip_history.sh).
. "$root/doc/scripts/tip_history.sh"

for benchmark in $benchmarks; do
  case $benchmark in
    G1)
      echo "G1: cantilever under its own weight, static deflection and period"
      {
        echo "# family cells_across_h static_tip_deflection period (prm/G1-cantilever-*.prm)"
        for family in linear B-spline; do
          for cells in 4 8; do
            nx=$((12 * cells)); ny=$((4 * cells))
            dt=$(awk "BEGIN{print 2.5e-5 * 8 / $cells}")
            grid="set Shape functions = $family
set B-spline degree = 2
subsection Mesh
 set Subdivisions = $nx, $ny
end
subsection Time
 set Time step = $dt
end"
            if [ "$family" = linear ]; then
              # At rest with the prm file's local damping: the last tip.
              run G1-cantilever-static.prm "$grid
subsection Output
 set Interval = $(awk "BEGIN{print int(0.05 / $dt + 0.5)}")
end"
              static=$(tip_history 0.99 "$dt" | tail -1 | cut -d' ' -f2)
            else
              # Quadratic B-splines creep to rest slowly under local
              # damping; undamped, gravity ramped up over two periods, the
              # mean tip over the period after the ramp.
              run G1-cantilever-static.prm "$grid
subsection Damping
 set Local damping coefficient = 0
end
subsection Gravity
 set Ramp time = 0.33
end
subsection Time
 set End time = 0.494
end
subsection Output
 set Interval = $(awk "BEGIN{print int(1e-3 / $dt + 0.5)}")
end"
              static=$(tip_history 0.99 "$dt" | awk '$1 >= 0.33 - 1e-9 { s += $2; n++ } END { printf "%.8e", s / n }')
            fi
            run G1-cantilever-vibration.prm "$grid
subsection Output
 set Interval = $(awk "BEGIN{print int(1e-3 / $dt + 0.5)}")
end"
            tip_history 0.99 "$dt" > "$data/G1-tip-$family-$cells.dat"
            # The period: mean time between the up-crossings of the mean.
            period=$(awk '{ t[NR] = $1; u[NR] = $2; s += $2 } END {
                       m = s / NR; n = 0
                       for (i = 2; i <= NR; i++)
                         if (u[i - 1] < m && u[i] >= m) {
                           c = t[i - 1] + (m - u[i - 1]) / (u[i] - u[i - 1]) * (t[i] - t[i - 1])
                           if (n > 0) { sum += c - last; k++ }
                           last = c; n++ }
                       printf "%.6g", sum / k }' "$data/G1-tip-$family-$cells.dat")
            echo "$family $cells $static $period"
          done
        done
      } | tee "$data/G1-cantilever.dat"
      ;;
    G2)
      echo "G2: block sliding on a rough plane, centre of mass at t = 0.5"
      {
        echo "# theta_deg mu x_centre(0.5) x_rigid(0.5) normal_reaction m_g_cos_theta y_centre(0.5) (prm/G2-friction-block.prm)"
        for case in "30 0.3" "30 0" "10 0.3"; do
          set -- $case
          gx=$(awk "BEGIN{print 9.81 * sin($1 * atan2(0, -1) / 180)}")
          gy=$(awk "BEGIN{print -9.81 * cos($1 * atan2(0, -1) / 180)}")
          run G2-friction-block.prm "subsection Gravity
 set Vector = $gx, $gy
end
subsection Boundary floor
 set Friction coefficient = $2
end
subsection Output
 set Interval = 50
end"
          for file in run/particles-*.csv; do
            step=$(basename "$file" .csv | sed 's/particles-0*//')
            awk -F, -v t="$(awk "BEGIN{print ${step:-0} * 2e-4}")" \
              'NR > 1 { s += $14 * $6; r += $14 * $7; m += $14 } END { printf "%.4g %.8e %.4e\n", t, s / m, r / m }' "$file"
          done | sort -g > "$data/G2-centre-$1-$2.dat"
          x=$(tail -1 "$data/G2-centre-$1-$2.dat" | cut -d' ' -f2)
          y=$(tail -1 "$data/G2-centre-$1-$2.dat" | cut -d' ' -f3)
          exact=$(awk "BEGIN{a = $gx + $2 * $gy; if (a < 0) a = 0; print a * 0.125}")
          normal=$(awk -F, 'NR > 2 { s += $8; n++ } END { print s / n }' run/statistics.csv)
          echo "$1 $2 $x $exact $normal $(awk "BEGIN{print -20 * $gy}") $y"
        done
      } | tee "$data/G2-friction-block.dat"
      ;;
    G3)
      echo "G3: Prandtl footing, load against settlement, linear functions and"
      echo "quadratic B-splines, with and without the volumetric locking remedy"
      {
        echo "# family remedy cells_per_half_width mean_load_0.03-0.1 (N/m) excess_over_Prandtl_25708 (%) mean_in_cell_spread_of_p/c (plastic zone)"
        for family in linear bspline; do
          prm=G3-prandtl-footing.prm
          rows=0.5
          if [ $family = bspline ]; then
            prm=G3-prandtl-footing-bspline.prm
            rows=1
          fi
          for remedy in none F-bar; do
            for n in 20 40 80; do
              h=$(awk "BEGIN{print 2.5 / $n}")
              dt=$(awk "BEGIN{print 4e-4 * 40 / $n}")
              run $prm "set Volumetric locking remedy = $remedy
subsection Mesh
 set Subdivisions = $n, $((6 * n / 5))
end
subsection Time
 set Time step = $dt
 set End time = 1.05
end
subsection Boundary footing
 set Box lower corner = 0, $(awk "BEGIN{print 2.5 - $rows * $h + 1e-6}")
 set Box upper corner = 0.5001, $(awk "BEGIN{print 2.5 + $rows * $h - 1e-6}")
end
subsection Output
 set Interval = $(awk "BEGIN{print int(0.01 / $dt + 0.5)}")
 set Write particle CSV = true
end"
              {
                echo "# settlement load_per_unit_length (half model, N/m; $family, $remedy, $n x $((6 * n / 5)) cells)"
                awk -F, 'NR > 1 { print -$9, -$7 }' run/statistics.csv
              } > "$data/G3-load-$family-$remedy-$n.dat"
              plateau=$(awk 'NR > 1 && $1 > 0.03 && $1 <= 0.1 { s += $2; n++ } END { print s / n }' \
                "$data/G3-load-$family-$remedy-$n.dat")
              last=$(ls run/particles-*.csv | tail -1)
              spread=$(awk -F, -v h="$h" -f "$root/doc/scripts/cell_spread.awk" "$last")
              echo "$family $remedy $((n / 5)) $plateau $(awk "BEGIN{printf \"%.1f\", 100 * ($plateau / 25708 - 1)}") $spread"
              if [ "$n" = 40 ]; then
                awk -F, 'NR > 1 { printf "%.4g %.4g %.3g\n", $4, $5, $17 }' "$last" \
                  > "$data/G3-plastic-strain-$family-$remedy.dat"
              fi
            done
          done
        done
      } | tee "$data/G3-limit-load.dat"
      ;;
    G4)
      echo "G4: granular column collapse, a = 0.5, 1, 2 (20 cells across L0),"
      echo "without a volumetric locking remedy and with F-bar (the default)"
      {
        echo "# remedy a H0 front toe H_inf (L_front-L0)/L0 (L_toe-L0)/L0 Lube Balmforth-Kerswell (prm/G4-column-collapse.prm)"
        for remedy in none F-bar; do
          for a in 0.5 1 2; do
            H0=$(awk "BEGIN{print 0.2 * $a}")
            run G4-column-collapse.prm "set Volumetric locking remedy = $remedy
subsection Body column
 set Upper corner = 0.2, $H0
end
subsection Output
 set Interval = 500
end"
            last=$(ls run/particles-*.csv | tail -1)
            deposit="$data/G4-deposit-$a.dat"
            [ $remedy = none ] && deposit="$work/deposit.dat"
            awk -F, 'NR > 1 { printf "%.4g %.4g %.3g\n", $4, $5, $17 }' "$last" > "$deposit"
            # The front: the furthest point; the toe: the furthest x where
            # the deposit is at least one cell (0.01) thick, in columns of
            # 0.01.
            awk -v a="$a" -v H0="$H0" -v remedy="$remedy" '{ b = int($1 / 0.01); if ($2 > top[b]) top[b] = $2; if ($1 > front) front = $1; if ($2 > h) h = $2 }
              END { for (b in top) if (top[b] >= 0.01 && (b + 1) * 0.01 > toe) toe = (b + 1) * 0.01
                    lube = (a < 2.3) ? 1.2 * a : 1.9 * a ^ (2 / 3)
                    printf "%s %s %s %.4f %.4f %.4f %.3f %.3f %.3f %.3f\n", remedy, a, H0, front, toe, h + 0.0025, (front - 0.2) / 0.2, (toe - 0.2) / 0.2, lube, a ^ 0.9 }' "$deposit"
          done
        done
      } | tee "$data/G4-run-out.dat"
      {
        echo "# psi cells_across_L0 failure_surface_angle_deg at 50 % 20 % 10 % of the row's largest speed, direction_of_motion_deg of the points faster than 30 % of the largest speed (a = 1, t = 0.05 s; Coulomb/Rankine 45 + phi/2 = 60, Arthur 45 + (phi + psi)/4, Roscoe 45 + psi/2)"
        for psi in 0 30; do
          for cells in 20 40 80; do
            dt=$(awk "BEGIN{print 1e-4 * 20 / $cells}")
            if ! run G4-column-collapse.prm "subsection Mesh
 set Upper corner = 0.3, 0.24
 set Subdivisions = $((3 * cells / 2)), $((6 * cells / 5))
end
subsection Material
 subsection Drucker-Prager
  set Dilatancy angle = $psi
 end
end
subsection Time
 set End time = 0.05
 set Time step = $dt
end
subsection Output
 set Interval = $(awk "BEGIN{print int(0.05 / $dt + 0.5)}")
end"; then
              echo "$psi $cells unstable: $(grep -o 'Stopped in time step [0-9]* (t = [0-9.e-]*' run.log)"
              continue
            fi
            last=$(ls run/particles-*.csv | tail -1)
            angles=""
            for fraction in 0.5 0.2 0.1; do
              angles="$angles $(awk -v L0=0.2 -v H0=0.2 -v cell="$(awk "BEGIN{print 0.2 / $cells}")" -v fraction=$fraction -f "$root/doc/scripts/failure_surface.awk" "$last" | cut -d' ' -f2)"
            done
            angles="$angles $(awk -v L0=0.2 -v H0=0.2 -v cell="$(awk "BEGIN{print 0.2 / $cells}")" -v fraction=0.3 -f "$root/doc/scripts/motion_direction.awk" "$last" | cut -d' ' -f2)"
            echo "$psi $cells$angles"
            if [ "$psi" = 0 ] && [ "$cells" = 40 ]; then
              awk -F, 'NR > 1 { printf "%.4g %.4g %.3g\n", $4, $5, sqrt($8 * $8 + $9 * $9) }' "$last" > "$data/G4-failure-speed.dat"
            fi
          done
        done
      } | tee "$data/G4-failure-angle.dat"
      ;;
    G5)
      echo "G5: slope, critical cohesion with phi = 30 deg held, against Bishop"
      /usr/bin/python3 "$root/doc/scripts/bishop_slope.py" factor 10e3 30 |
        sed 's/^/Bishop, c = 10 kPa: /' | tee "$data/G5-bishop.txt"
      /usr/bin/python3 "$root/doc/scripts/bishop_slope.py" critical-cohesion 30 |
        sed 's/^/Bishop, phi = 30 deg: /' | tee -a "$data/G5-bishop.txt"
      # slope H REMEDY C: run the slope on cells of size H with cohesion C;
      # prints "slides" or "stands", "rest" or "moving" at the end, and the
      # largest displacement. A slope stands when it has come to rest
      # (Quasi-static end) with no point displaced by more than 1 m (a tenth
      # of its height); a failing slope runs out by metres and may come to
      # rest at the toe.
      slope() {
        run G5-slope.prm "set Volumetric locking remedy = $2
subsection Mesh
 set Subdivisions = $(awk "BEGIN{print int(45 / $1 + 0.5)}"), $(awk "BEGIN{print int(16 / $1 + 0.5)}")
end
subsection Material
 subsection Mohr-Coulomb
  set Cohesion = $3
 end
end
subsection Output
 set Time interval = 15
 set Write particle CSV = true
end"
        local last state displacement verdict
        last=$(ls run/particles-*.csv | tail -1)
        state=moving
        grep -q "at rest at t" run.log && state=rest
        displacement=$(awk -F, 'NR > 1 { u = sqrt($6 * $6 + $7 * $7); if (u > m) m = u } END { printf "%.3f", m }' "$last")
        verdict=slides
        if [ $state = rest ] && awk "BEGIN{exit !($displacement < 1)}"; then verdict=stands; fi
        echo "cells $1 m, $2, c = $3 Pa: $verdict ($state, largest displacement $displacement m)" >&2
        echo "$1 $2 $3 $verdict $state $displacement" >> "$data/G5-runs.dat"
        echo "$verdict $state $displacement"
      }
      echo "# cells remedy cohesion verdict state_at_end largest_displacement (m, Pa; every run of the sweep)" > "$data/G5-runs.dat"
      {
        echo "# cells remedy c=0_verdict c=0_state c=0_largest_displacement critical_cohesion_low critical_cohesion_high (Pa; the slope slides at low, stands at high)"
        for h in 1 0.5 0.25; do
          for remedy in none F-bar; do
            read -r verdict0 state0 u0 < <(slope $h $remedy 0)
            low=0
            high=3000
            for _ in 1 2 3 4 5 6; do
              c=$(awk "BEGIN{print ($low + $high) / 2}")
              read -r verdict state u < <(slope $h $remedy "$c")
              if [ "$verdict" = stands ]; then high=$c; else low=$c; fi
              if [ "$h" = 0.25 ] && [ $remedy = F-bar ] && [ "$verdict" = slides ]; then
                # Plastic strain of the slide nearest the critical cohesion
                # at the points' initial positions, beside Bishop's circle.
                awk -F, 'NR > 1 { printf "%.4g %.4g %.3g\n", $2, $3, $17 }' \
                  "$(ls run/particles-*.csv | tail -1)" > "$data/G5-plastic-strain.dat"
              fi
            done
            echo "$h $remedy $verdict0 $state0 $u0 $low $high"
          done
        done
      } | tee "$data/G5-critical-cohesion.dat"
      # The band against Bishop's critical circle, column by column (0.25 m
      # of initial x) between the crest's edge and the toe: the height of
      # the largest plastic strain, and of the lowest point with more than
      # 0.1 (the base of the slide), above the circle.
      read -r xc yc rc < <(awk '/critical cohesion/ { gsub(",", ""); for (i = 1; i <= NF; ++i) if ($i == "centre") print $(i + 1), $(i + 2), $(i + 4) }' "$data/G5-bishop.txt")
      awk -v xc="$xc" -v yc="$yc" -v r="$rc" '
        { b = int($1 / 0.25)
          if (!(b in m) || $3 > m[b]) { m[b] = $3; ym[b] = $2; x[b] = $1 }
          if ($3 > 0.1 && (!(b in yl) || $2 < yl[b])) yl[b] = $2 }
        END {
          for (b in m) {
            if (x[b] < 16 || x[b] > 29 || !(b in yl)) continue
            y = yc - sqrt(r * r - (x[b] - xc) ^ 2)
            d = ym[b] - y; e = yl[b] - y; n++
            s += d; a += (d < 0 ? -d : d); if (d * d > dm * dm) dm = d; if (d * d <= 0.25) k++
            t += e; if (e * e > em * em) em = e }
          printf "largest plastic strain: mean %.2f m above the circle, mean |offset| %.2f m, largest %.2f m, %d of %d columns within 0.5 m (two cells)\n", s / n, a / n, dm, k, n
          printf "base of the slide (plastic strain > 0.1): mean %.2f m above the circle, largest %.2f m\n", t / n, em }' \
        "$data/G5-plastic-strain.dat" | tee "$data/G5-band-offset.txt"
      ;;
    biaxial)
      echo "Biaxial test with strain softening: peak, residual, shear band"
      {
        echo "# cells family regularisation remedy peak_load late_load(platen displacement 0.045-0.06 m) band_points band_angle slip (kN/m, deg, m; exact peak 69.28, residual 10.91)"
        # family, regularisation, locking remedy; the platen's box reaches
        # a cell (B-splines: their control points) or half a cell (linear:
        # the vertices) above and below the specimen's top.
        for setting in "B-spline nodal-average F-bar" "B-spline none F-bar" \
                       "linear nodal-average F-bar" "linear none F-bar" "linear none none"; do
          read -r family regularisation remedy <<< "$setting"
          for h in 0.1 0.05; do
            nx=$(awk "BEGIN { print 1.6 / $h }"); ny=$(awk "BEGIN { print 2.2 / $h }")
            reach=$h
            [ "$family" = linear ] && reach=$(awk "BEGIN { print 0.5 * $h }")
            name=$h-$family-$regularisation-$remedy
            run biaxial-softening.prm "set Shape functions = $family
set Softening regularisation = ${regularisation/-/ }
set Volumetric locking remedy = $remedy
subsection Mesh
 set Subdivisions = $nx, $ny
end
subsection Boundary platen
 set Box lower corner = -0.3, $(awk "BEGIN { print 2 - $reach }")
 set Box upper corner = 1.3, $(awk "BEGIN { print 2 + $reach }")
end
subsection Time
 set End time = 12
end
subsection Output
 set Time interval = 0.05
 set Write particle CSV = true
end"
            # Platen displacement and load (the mean over each 0.05 s).
            awk -F, 'NR > 1 { printf "%.5f %.1f\n", -$9, -$7 }' run/statistics.csv \
              > "$data/biaxial-load-$name.dat"
            last=$(ls run/particles-*.csv | tail -1)
            if [ "$h" = 0.05 ] && [ "$regularisation" = nodal-average ]; then
              awk -F, 'NR > 1 { printf "%.4g %.4g %.3g\n", $2, $3, $17 }' "$last" \
                > "$data/biaxial-plastic-strain-$family.dat"
            fi
            peak=$(awk '$2 > m { m = $2 } END { printf "%.2f", m / 1e3 }' "$data/biaxial-load-$name.dat")
            late=$(awk '$1 > 0.045 { s += $2; n++ } END { printf "%.2f", s / n / 1e3 }' "$data/biaxial-load-$name.dat")
            band=$(awk -F, 'NR > 1 && $17 > 0.05 && $3 > 0.1 && $3 < 1.9 {
                n++; sx += $2; sy += $3; sxx += $2 * $2; sxy += $2 * $3 }
              NR > 1 && $3 > 1.9 { t += $6; nt++ } NR > 1 && $3 < 0.1 { b += $6; nb++ }
              END { s = (n * sxy - sx * sy) / (n * sxx - sx * sx); d = t / nt - b / nb
                printf "%d %.1f %.3f", n, atan2(s < 0 ? -s : s, 1) * 45 / atan2(1, 1), d < 0 ? -d : d }' "$last")
            echo "$h $family $regularisation $remedy $peak $late $band"
          done
        done
      } | tee "$data/biaxial-summary.dat"
      ;;
  esac
done

if command -v gnuplot > /dev/null; then
  (cd "$root/doc" && gnuplot scripts/user_problems.gp)
else
  echo "gnuplot not found: figures not drawn (apt-get install gnuplot-nox)"
fi
