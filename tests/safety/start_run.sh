# Shared by the safety tests (sourced): start_run RANKS LOG starts mpm-otm
# ($exe on $prm) in the background on RANKS ranks with its output in LOG,
# sets run to its process id (mpirun's for two ranks) and waits until the
# first output of $directory is complete (grid.pvd is written after
# particles.pvd), for at most 60 s.
start_run() {
  if [ "$1" -eq 1 ]; then
    "$exe" "$prm" > "$2" 2>&1 &
  else
    mpirun -np "$1" --oversubscribe "$exe" "$prm" > "$2" 2>&1 &
  fi
  run=$!
  waited=0
  until [ -f "$directory/grid.pvd" ] || [ $waited -ge 600 ]; do
    sleep 0.1
    waited=$((waited + 1))
  done
}
