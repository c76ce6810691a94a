#!/bin/sh
# mpirun killed with SIGKILL cannot pass the signal on; its ranks must die
# with it instead of running on and writing output. A run on two ranks is
# killed (its mpirun) after its first output; a tenth of a second later no
# rank may be left (they die with it: 0.01 s here; before, Open MPI's own
# clean-up took 0.2 s and more) and statistics.csv may not grow any more.
# Usage: killed_mpirun.sh <mpm-otm> <parameter file>
exe=$1
prm=$2
directory=output-resume
. "$(dirname "$0")/start_run.sh"

rm -rf $directory
start_run 2 log
[ -f $directory/grid.pvd ] || { echo "the run wrote no output:"; cat log; exit 1; }
kill -9 $run
wait $run 2> /dev/null
sleep 0.1
left=$(pgrep -f "^$exe $prm" | wc -l)
rows=$(wc -l < $directory/statistics.csv)
sleep 2
if [ "$left" -ne 0 ]; then
  echo "$left rank(s) still running 0.1 s after mpirun was killed"
  pkill -9 -f "^$exe $prm"
  exit 1
fi
[ "$(wc -l < $directory/statistics.csv)" -eq "$rows" ] ||
  { echo "statistics.csv grew after mpirun was killed"; exit 1; }
echo "mpirun killed: no rank left after 0.1 s, no row written after"
