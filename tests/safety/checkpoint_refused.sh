#!/bin/sh
# mpm-otm --resume checks a checkpoint before it decodes anything or removes
# any output: every file against the size and CRC-32 that shared.bin
# records (and shared.bin against its own), and the run's identity, its
# parameters and grid, against the parameters.prm of the resumed run. Each
# damaged or foreign checkpoint and each changed parameter is refused with a
# message that names the file or the entry, and the output of the run is
# left as it was. A longer end time is accepted. Serial, and on two MPI
# ranks for some cases.
# Usage: checkpoint_refused.sh <mpm-otm> <parameter file> <Gmsh file>
exe=$1
prm=$2
mesh=$3
directory=output-checkpoint
fail() {
  echo "$1"
  [ -f log ] && cat log
  exit 1
}

# A finished run whose newest checkpoint is the one after step 100, so that
# a resume would remove the output of steps 150 and 200.
fresh_run() {
  rm -rf $directory log
  $launch "$exe" "$1" > log 2>&1 || fail "the run failed:"
  rm -rf $directory/checkpoint-00150
  [ -f $directory/checkpoint-00100/shared.bin ] || fail "no checkpoint 100"
  (cd $directory && ls && cat statistics.csv particles-*.csv) > before
}

# Resume and require a non-zero exit, a message matching $1 and the output
# unchanged.
refused() {
  $launch "$exe" --resume $directory > log 2>&1 &&
    fail "$case: the resume was accepted:"
  tr '\n' ' ' < log | grep -E -q "$1" ||
    fail "$case: the message does not match <$1>:"
  (cd $directory && ls && cat statistics.csv particles-*.csv) > after
  cmp -s before after || fail "$case: the output was changed"
  echo "$case: refused as expected"
}

# Overwrite COUNT bytes of FILE at OFFSET with random bytes that differ.
damage() {
  size=$(stat -c %s "$1")
  offset=$(( $2 < size ? $2 : size / 2 ))
  for k in $(seq 0 $(( $3 - 1 ))); do
    old=$(od -An -tu1 -j $((offset + k)) -N1 "$1" | tr -d ' ')
    new=$(( (old + 1 + k) % 256 ))
    printf "$(printf '\\%03o' $new)" |
      dd of="$1" bs=1 seek=$((offset + k)) conv=notrunc 2>/dev/null
  done
}
checkpoint=$directory/checkpoint-00100
for ranks in 1 2; do
  launch=""
  [ $ranks -eq 1 ] || launch="mpirun -np $ranks --oversubscribe"
  last=$((ranks - 1))
  points=$checkpoint/points-000$last.bin

  case="$ranks rank(s), 8 bytes of a point changed"
  fresh_run "$prm"
  damage $points 200 8
  refused "Cannot resume from <$checkpoint>: <$points> does not match the size and checksum that $checkpoint/shared.bin records for it.*remove <$checkpoint>"

  case="$ranks rank(s), a changed Young's modulus"
  fresh_run "$prm"
  sed -i "s/Young's modulus *= 4e3/Young's modulus = 5e3/" \
    $directory/parameters.prm
  refused "it was written by a run with other parameters than the parameters.prm of the resumed run: Material/Young's modulus = <5e3> [(]the run that wrote it: <4e3>[)]"
  [ $ranks -eq 1 ] || continue

  case="random bytes in points-0000.bin"
  fresh_run "$prm"
  head -c "$(stat -c %s $points)" /dev/urandom > $points
  refused "<$points> does not match the size and checksum"

  case="a truncated state-0000.bin"
  fresh_run "$prm"
  truncate -s 10 $checkpoint/state-0000.bin
  refused "<$checkpoint/state-0000.bin> does not match the size and checksum"

  case="one byte of shared.bin changed"
  fresh_run "$prm"
  damage $checkpoint/shared.bin 100 1
  refused "<$checkpoint/shared.bin> does not match its checksum"

  case="a point file of another checkpoint of the run"
  fresh_run "$prm"
  cp $directory/checkpoint-00050/points-0000.bin $points
  refused "<$points> does not match the size and checksum"

  case="the checkpoint of another run"
  sed "s/Young's modulus = 4e3/Young's modulus = 6e3/; s/Directory = output-checkpoint/Directory = output-other/" \
    "$prm" > other.prm
  rm -rf output-other && "$exe" other.prm > log 2>&1 || fail "the other run failed:"
  fresh_run "$prm"
  rm -rf $checkpoint && cp -r output-other/checkpoint-00100 $checkpoint
  refused "Material/Young's modulus = <4e3> [(]the run that wrote it: <6e3>[)]"

  case="a shorter end time"
  fresh_run "$prm"
  sed -i "s/End time *= 0.2/End time = 0.05/" $directory/parameters.prm
  refused "Time/End time = 0.05 is not after the checkpoint's time 0.1"

  case="a changed mesh file"
  cp "$mesh" mesh.msh
  sed "s|set Subdivisions = 20, 5|set Mesh file = $(pwd)/mesh.msh|; s/Upper corner = 3, 0.8/Upper corner = 3, 0.6/; s/Boundary ids = 2/Boundary ids = 1/" "$prm" > mesh.prm
  fresh_run mesh.prm
  # Move the first node of the mesh by a thousandth.
  awk 'found == 1 && NF == 4 { $2 = $2 + 0.001; found = 2 } /^\$Nodes/ { found = 1 } { print }' "$mesh" > mesh.msh
  cmp -s "$mesh" mesh.msh && fail "the mesh file was not changed"
  refused "it was written on another grid than the resumed run's"
done

# A longer end time is accepted: the run continues to it.
fresh_run "$prm"
sed -i "s/End time *= 0.2/End time = 0.3/" $directory/parameters.prm
"$exe" --resume $directory > log 2>&1 || fail "the resume with a longer end time failed:"
[ "$(tail -n 1 $directory/statistics.csv | cut -d, -f1)" = "300" ] ||
  fail "the resumed run did not continue to step 300"
echo "a longer end time: accepted, run to step 300"

# A staged run: the End time of its last stage may be extended, that of an
# earlier stage may not change.
sed "s/^ *set End time = 0.2$//; s/^set Bodies = block$/set Bodies = block\nset Stages = first, second/" "$prm" > staged.prm
printf 'subsection Stage first\n  set End time = 0.1\nend\nsubsection Stage second\n  set End time = 0.2\nend\n' >> staged.prm
case="a staged run, an earlier stage's End time changed"
fresh_run staged.prm
sed -i "s/End time *= 0.1 /End time = 0.12 /" $directory/parameters.prm
refused "Stage first/End time = <0.12> [(]the run that wrote it: <0.1>[)]"
case="a staged run, the last stage's End time before the stage before"
fresh_run staged.prm
sed -i "s/End time *= 0.2 /End time = 0.05 /" $directory/parameters.prm
refused "Stage second/End time = 0.05 must be after the end of the stage before [(]0.1 s"
fresh_run staged.prm
sed -i "s/End time *= 0.2 /End time = 0.3 /" $directory/parameters.prm
"$exe" --resume $directory > log 2>&1 || fail "the staged resume with a longer last stage failed:"
[ "$(tail -n 1 $directory/statistics.csv | cut -d, -f1)" = "300" ] ||
  fail "the resumed staged run did not continue to step 300"
[ "$(tail -n 1 $directory/stages.csv | cut -d, -f1,3,6)" = "300,second,0.3" ] ||
  fail "stages.csv does not end with stage second at step 300, t = 0.3"
echo "a staged run: the last stage's End time extended, run to step 300"
