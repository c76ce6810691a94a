#!/bin/sh
# SIGTERM (what a batch scheduler sends before it kills a job at its time
# limit) ends a run after a complete step: the run exits non-zero naming
# the signal and the step, particles.pvd ends with that step's output,
# which is complete, and statistics.csv ends with its row. Serial and on
# two MPI ranks (mpirun forwards the signal to the ranks).
# Usage: sigterm_writes_last_output.sh <mpm-otm> <parameter file>
exe=$1
prm=$2
directory=output-sigterm

for ranks in 1 2; do
  rm -rf $directory log
  if [ $ranks -eq 1 ]; then
    "$exe" "$prm" > log 2>&1 &
  else
    mpirun -np 2 --oversubscribe "$exe" "$prm" > log 2>&1 &
  fi
  run=$!
  # Wait for the first output, then let the run go on for a second.
  waited=0
  until [ -f $directory/grid.pvd ] || [ $waited -ge 600 ]; do
    sleep 0.1
    waited=$((waited + 1))
  done
  sleep 1
  kill -TERM $run
  wait $run
  status=$?
  echo "$ranks rank(s): exit status $status"
  cat log | tr '\n' ' ' | grep -o 'Stopped by SIGTERM[^<]*'
  [ $status -ne 0 ] || { echo "expected a non-zero exit status"; exit 1; }
  step=$(tr '\n' ' ' < log | grep -o 'Stopped by SIGTERM after time step [0-9]*' | grep -o '[0-9]*$')
  [ -n "$step" ] || { echo "no 'Stopped by SIGTERM after time step N' in:"; cat log; exit 1; }
  last=$(grep -o 'file="[^"]*"' $directory/particles.pvd | tail -n 1 | cut -d'"' -f2)
  expected=particles_$(printf '%05d' "$step").pvtu
  [ "$last" = "$expected" ] ||
    { echo "particles.pvd ends with $last, not $expected"; exit 1; }
  tail -c 12 "$directory/$last" | grep -q '</VTKFile>' ||
    { echo "$last is incomplete"; exit 1; }
  [ "$(tail -n 1 $directory/statistics.csv | cut -d, -f1)" = "$step" ] ||
    { echo "statistics.csv does not end with step $step"; exit 1; }
done
echo "both runs stopped after a complete step with its output"
