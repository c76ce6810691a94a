# Sourced by the doc scripts that follow the cantilever's tip (G1).
# tip_history X DT: the mean uy of the points of the last point column of
# the cantilever (X > $1) for every particles-*.csv of ./run, one line
# "time uy" per file, time = step * $2.
tip_history() {
  for file in run/particles-*.csv; do
    step=$(basename "$file" .csv | sed 's/particles-0*//')
    awk -F, -v t="$(awk "BEGIN{print ${step:-0} * $2}")" -v x="$1" \
      'NR > 1 && $2 > x { s += $7; n++ } END { printf "%.6g %.8e\n", t, s / n }' "$file"
  done | sort -g
}
