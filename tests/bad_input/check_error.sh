#!/bin/sh
# Run mpm-otm on a bad parameter file and require a non-zero exit and an
# error message matching a regular expression.
# Usage: check_error.sh <mpm-otm> <parameter file> <regex> [file that must exist afterwards]
# --overwrite: the tests rerun into the same directories. LAUNCHER (e.g.
# "mpirun -np 2"), if set, runs the executable.
output=$($LAUNCHER "$1" --overwrite "$2" 2>&1)
status=$?
if [ $status -eq 0 ]; then
  echo "expected a non-zero exit status, got 0"; echo "$output"; exit 1
fi
if ! printf '%s\n' "$output" | tr '\n' ' ' | grep -E -q "$3"; then
  echo "the message does not match <$3>:"; echo "$output"; exit 1
fi
if [ -n "$4" ] && [ ! -f "$4" ]; then
  echo "expected <$4> to be kept after the failure"; exit 1
fi
echo "exit status $status, message as expected"
