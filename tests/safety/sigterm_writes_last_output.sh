#!/bin/sh
# SIGTERM (what a batch scheduler sends before it kills a job at its time
# limit) ends a run after a complete step: the run exits with status 143
# (128 + SIGTERM; under mpirun non-zero) naming the signal and the step,
# particles.pvd ends with that step's output, which is complete, and
# statistics.csv ends with its row. Serial and on two MPI ranks (mpirun
# forwards the signal to the ranks).
# Usage: sigterm_writes_last_output.sh <mpm-otm> <parameter file>
exe=$1
prm=$2
directory=output-sigterm
. "$(dirname "$0")/start_run.sh"

for ranks in 1 2; do
  rm -rf $directory log
  # After the first output, let the run go on for a second.
  start_run $ranks log
  sleep 1
  kill -TERM $run
  wait $run
  status=$?
  echo "$ranks rank(s): exit status $status"
  cat log | tr '\n' ' ' | grep -o 'Stopped by SIGTERM[^<]*'
  # mpirun, which received the signal itself, gives a status of its own.
  if [ $ranks -eq 1 ]; then
    [ $status -eq 143 ] ||
      { echo "expected exit status 143 (128 + SIGTERM, as a shell reports it)"; exit 1; }
  else
    [ $status -ne 0 ] || { echo "expected a non-zero exit status"; exit 1; }
  fi
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
