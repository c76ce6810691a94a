#!/bin/sh
# A run killed with SIGKILL at a random moment must leave readable output:
# particles.pvd and grid.pvd complete, and every .pvtu they name complete
# with every .vtu piece it names complete (ARCHITECTURE.md, "Errors and
# safety"). Kills $3 serial runs and $3 runs on two MPI ranks (one rank is
# killed), each at a random moment after its first output.
# Usage: kill_during_output.sh <mpm-otm> <parameter file> <number of kills>
exe=$1
prm=$2
kills=${3:-4}
directory=output-kill
. "$(dirname "$0")/start_run.sh"

# complete FILE: FILE exists and ends with the closing tag of a VTK file.
complete() {
  [ -f "$1" ] && tail -c 12 "$1" | grep -q '</VTKFile>'
}

# check: every index in the output directory is complete, and so is
# everything it names.
check() {
  for series in particles grid; do
    pvd=$directory/$series.pvd
    complete "$pvd" || { echo "$pvd is missing or incomplete"; return 1; }
    for pvtu in $(grep -o 'file="[^"]*"' "$pvd" | cut -d'"' -f2); do
      complete "$directory/$pvtu" ||
        { echo "$pvd names $pvtu, which is missing or incomplete"; return 1; }
      for piece in $(grep -o 'Source="[^"]*"' "$directory/$pvtu" | cut -d'"' -f2); do
        complete "$directory/$piece" ||
          { echo "$pvtu names $piece, which is missing or incomplete"; return 1; }
      done
    done
  done
  echo "killed at step $(grep -c 'file=' "$directory/particles.pvd"): output complete"
}

for ranks in 1 2; do
  i=0
  while [ $i -lt "$kills" ]; do
    rm -rf $directory
    # After the first output, a random 0-2 s.
    start_run $ranks /dev/null
    sleep "$(awk "BEGIN{srand($$ + $i + 10 * $ranks); printf \"%.2f\", 2 * rand()}")"
    # One process of the run (for two ranks: the first rank found).
    victim=$(pgrep -f "^$exe $prm" | head -n 1)
    [ -n "$victim" ] && kill -9 "$victim"
    wait $run 2> /dev/null
    pkill -9 -f "^$exe $prm" 2> /dev/null
    echo "$ranks rank(s), kill $i:"
    check || exit 1
    i=$((i + 1))
  done
done
