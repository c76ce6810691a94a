# Sourced by g5_strength_reduction.sh and g5_staged.sh: a strength reduction
# of a G5 parameter file on several cell sizes, and the gnuplot lines that
# draw a failure mechanism beside Bishop's critical circle.
# Needs: $exe (mpm-otm), $root (the repository), $data (doc/data), the
# current directory a scratch directory.

# strength_reduction_runs PRM TRIALS FACTORS MECHANISM SIZES...
# Runs prm/PRM on each cell size (the 45 m x 16 m grid of G5) and writes
# every trial to TRIALS (cell size, trial, factor, outcome, at rest, end
# time, largest displacement), per size the factor of safety, bracket,
# number of trials and difference from Bishop's to FACTORS, and the plastic
# strain of the last failing trial on the last size to MECHANISM (initial
# positions).
strength_reduction_runs() {
  local prm=$1 trials=$2 factors=$3 mechanism=$4
  shift 4
  bishop=$(awk '/c = 10 kPa/ { for (i = 1; i <= NF; ++i) if ($i == "F") { gsub(";", "", $(i + 2)); print $(i + 2) } }' "$data/G5-bishop.txt")
  echo "# cells trial factor outcome at_rest end_time largest_displacement (m, s, m)" > "$trials"
  echo "# cells factor_of_safety stands_at fails_at trials difference_from_Bishop_${bishop}_percent" > "$factors"
  local h nx ny last
  for h in "$@"; do
    nx=$(awk "BEGIN{print int(45 / $h + 0.5)}")
    ny=$(awk "BEGIN{print int(16 / $h + 0.5)}")
    cp "$root/prm/$prm" run.prm
    printf 'subsection Mesh\n set Subdivisions = %s, %s\nend\nsubsection Output\n set Directory = run-%s\n set Format = none\n set Write particle CSV = true\n set Time interval = 1000\n set Overwrite = true\nend\n' \
      "$nx" "$ny" "$h" >> run.prm
    echo "$prm: strength reduction on $h m cells ($nx x $ny)"
    "$exe" run.prm > "run-$h.log" 2>&1 || { tail -5 "run-$h.log" >&2; exit 1; }
    grep "^Strength reduction" "run-$h.log" | grep -v "output in" >&2
    awk -F, -v h="$h" 'NR > 1 { print h, $1, $2, $3, $4, $5, $6 }' \
      "run-$h/strength-reduction.csv" >> "$trials"
    awk -v h="$h" -v b="$bishop" '
      $1 == h { n++; if ($4 == "stands" && (s == "" || $3 > s)) s = $3
                if ($4 == "fails" && (f == "" || $3 < f)) f = $3 }
      END { F = (s + f) / 2; printf "%s %.4f %s %s %d %.1f\n", h, F, s, f, n, 100 * (F / b - 1) }' \
      "$trials" >> "$factors"
    last=$(awk '/failure mechanism/ { sub(/.*</, ""); sub(/>.*/, ""); print }' "run-$h/factor-of-safety.txt")
    last=$(ls "$last"/particles-*.csv | sort | tail -n 1)
    awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) column[$i] = i; next }
             { printf "%.4g %.4g %.3g\n", $column["X"], $column["Y"], $column["plastic_strain"] }' \
      "$last" > "$mechanism"
  done
}

# mechanism_plot MECHANISM: the gnuplot lines of a plot of the plastic
# strain in MECHANISM (x, y, strain) over G5's slope, with Bishop's critical
# circle for c = 10 kPa (doc/data/G5-bishop.txt).
mechanism_plot() {
  local xc yc rc
  read -r xc yc rc < <(awk '/c = 10 kPa/ { gsub(",", ""); for (i = 1; i <= NF; ++i) if ($i == "centre") print $(i + 1), $(i + 2), $(i + 4) }' "$data/G5-bishop.txt")
  cat <<GP
set xlabel "x (m)"
set ylabel "y (m)"
set size ratio -1 1, 0.5
set xrange [0:45]
set yrange [0:16]
set cbrange [0:1]
set cblabel "equivalent plastic strain"
set key top right
xc = $xc; yc = $yc; rc = $rc
plot "$1" using 1:2:3 with points pt 5 ps 0.25 palette notitle, \\
     [xc - rc:xc + rc] (yc - sqrt(rc**2 - (x - xc)**2) < (x < 15 ? 15 : x < 30 ? 15 - (x - 15) / 1.5 : 5) ? yc - sqrt(rc**2 - (x - xc)**2) : 1/0) \\
       with lines lw 2 lc rgb "black" title "Bishop's critical circle"
GP
}
