#!/bin/sh
# A run stopped by SIGTERM writes a checkpoint of its last step; mpm-otm
# --resume continues it to the end, and its last particle CSV equals, every
# digit, that of the same run left uninterrupted; so does statistics.csv,
# the averaged floor reactions included, but for the row of the step the
# signal added. Serial and on two MPI
# ranks. The signal is sent right after the first output, so that the run
# cannot have finished before it arrives.
# Usage: sigterm_then_resume.sh <mpm-otm> <parameter file>
exe=$1
prm=$2
directory=output-resume
. "$(dirname "$0")/start_run.sh"
last_csv=particles-10000.csv

for ranks in 1 2; do
  launch=""
  [ $ranks -eq 1 ] || launch="mpirun -np $ranks --oversubscribe"
  rm -rf $directory reference-$ranks.csv log
  $launch "$exe" "$prm" > log 2>&1 ||
    { echo "the uninterrupted run failed:"; cat log; exit 1; }
  cp $directory/$last_csv reference-$ranks.csv
  cp $directory/statistics.csv reference-statistics-$ranks.csv
  rm -rf $directory

  start_run $ranks log
  kill -TERM $run
  wait $run
  step=$(tr '\n' ' ' < log | grep -o 'Stopped by SIGTERM after time step [0-9]*' | grep -o '[0-9]*$')
  [ -n "$step" ] || { echo "no 'Stopped by SIGTERM after time step N' in:"; cat log; exit 1; }
  [ -f $directory/checkpoint-$(printf '%05d' "$step")/shared.bin ] ||
    { echo "no checkpoint of step $step"; ls $directory; exit 1; }
  tr '\n' ' ' < log | grep -q "mpm-otm --resume $directory" ||
    { echo "the message does not say how to resume:"; cat log; exit 1; }
  echo "$ranks rank(s): stopped after step $step with a checkpoint"

  $launch "$exe" --resume $directory > log 2>&1 ||
    { echo "the resumed run failed:"; cat log; exit 1; }
  grep -q "resumed from <$directory/checkpoint-$(printf '%05d' "$step")>" log ||
    { echo "the resumed run does not name its checkpoint:"; cat log; exit 1; }
  cmp $directory/$last_csv reference-$ranks.csv ||
    { echo "the resumed run ends otherwise than the uninterrupted one"; exit 1; }
  [ "$(tail -n 1 $directory/statistics.csv | cut -d, -f1)" = "10000" ] ||
    { echo "statistics.csv does not end with step 10000"; exit 1; }
  [ "$(cut -d, -f1 $directory/statistics.csv | sort | uniq -d)" = "" ] ||
    { echo "statistics.csv lists a step twice"; exit 1; }
  if [ $((step % 2500)) -ne 0 ]; then
    grep -v "^$step," $directory/statistics.csv > statistics-without-signal.csv
  else
    cp $directory/statistics.csv statistics-without-signal.csv
  fi
  cmp statistics-without-signal.csv reference-statistics-$ranks.csv ||
    { echo "statistics.csv differs from the uninterrupted run's:";
      diff statistics-without-signal.csv reference-statistics-$ranks.csv;
      exit 1; }
  echo "$ranks rank(s): resumed run identical to the uninterrupted one"
done
