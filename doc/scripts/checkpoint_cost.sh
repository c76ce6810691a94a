#!/usr/bin/env bash
# Cost of checkpoints (doc/performance.md, "Cost of checkpoints"): 500 steps
# of prm/performance-bar-2d.prm (102400 points) with a checkpoint every 100
# steps and without, interleaved; the time of the "checkpoint" row of the
# timing table, the size of one checkpoint, and the time to resume.
# Usage: doc/scripts/checkpoint_cost.sh [path to mpm-otm] [repetitions]
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
exe=$(realpath "${1:-$root/build-release/mpm-otm}")
repetitions=${2:-3}
work=$(mktemp -d)
cd "$work"
total() { grep "Total wallclock" "$1" | awk -F'|' '{print $3}' | tr -d ' s'; }
row() { grep "| $2 " "$1" | awk -F'|' '{print $4}' | tr -d ' s'; }
for interval in 100 0; do
  cp "$root/prm/performance-bar-2d.prm" run-$interval.prm
  printf 'subsection Time\n set End time = 0.05\nend\nsubsection Output\n set Directory = out-%s\n set Overwrite = true\nend\nsubsection Checkpoint\n set Interval = %s\nend\n' \
    "$interval" "$interval" >> run-$interval.prm
done
echo "| run | with checkpoints (total, of it writing 4) | without |"
echo "|---|---|---|"
for k in $(seq "$repetitions"); do
  "$exe" run-100.prm > with.log
  "$exe" run-0.prm > without.log
  echo "| $k | $(total with.log) s ($(row with.log checkpoint) s) | $(total without.log) s |"
done
echo
echo "size of one checkpoint: $(du -sh out-100/checkpoint-00400 | cut -f1)" \
  "($(du -sb out-100/checkpoint-00400 | cut -f1) bytes for 102400 points)"
start=$(date +%s.%N)
"$exe" --resume out-100 > resume.log
end=$(date +%s.%N)
echo "resume from step 400 and run 100 steps: $(echo "$end - $start" | bc) s" \
  "(the 100 steps alone: $(total resume.log) s)"
rm -rf "$work"
