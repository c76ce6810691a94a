#!/bin/sh
# Output directory protection (issue 16): a second run into the directory
# of a first one must stop with a message naming the directory and leave
# the first run's files as they were; with --overwrite it must run, remove
# the first run's step files and checkpoints (here a stray
# particles-99999.csv and checkpoint-00007) and keep
# files that are not output.
# Usage: check_overwrite.sh <mpm-otm> <parameter file>
exe=$1
prm=$2
dir=output-output_directory_in_use
rm -rf $dir
"$exe" "$prm" > /dev/null 2>&1 || { echo "the first run failed"; exit 1; }
touch $dir/particles-99999.csv $dir/notes.txt
mkdir $dir/checkpoint-00007 && touch $dir/checkpoint-00007/shared.bin
before=$(cksum < $dir/statistics.csv)
if output=$("$exe" "$prm" 2>&1); then
  echo "the second run into the same directory did not stop"; exit 1
fi
if ! printf '%s\n' "$output" | tr '\n' ' ' | grep -E -q "Output/Directory: <$dir> holds the output of another run \(statistics.csv, parameters.prm, particles.pvd, grid.pvd\).*--overwrite"; then
  echo "unexpected message:"; echo "$output"; exit 1
fi
if [ "$(cksum < $dir/statistics.csv)" != "$before" ] || [ ! -e $dir/particles-99999.csv ]; then
  echo "the stopped run changed the first run's output"; exit 1
fi
"$exe" --overwrite "$prm" > /dev/null 2>&1 || { echo "the run with --overwrite failed"; exit 1; }
[ ! -e $dir/particles-99999.csv ] || { echo "--overwrite left the first run's step file"; exit 1; }
[ ! -e $dir/checkpoint-00007 ] || { echo "--overwrite left the first run's checkpoint"; exit 1; }
[ -e $dir/notes.txt ] || { echo "--overwrite removed a file that is not output"; exit 1; }
[ -e $dir/particles-00002.csv ] || { echo "the run with --overwrite wrote no output"; exit 1; }
echo "protected, and replaced with --overwrite"
