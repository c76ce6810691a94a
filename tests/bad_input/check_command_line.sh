#!/bin/sh
# Run a command line of mpm-otm and require a non-zero exit and an error
# message matching a regular expression.
# Usage: check_command_line.sh <regex> <mpm-otm> [arguments...]
regex=$1
shift
output=$("$@" 2>&1)
status=$?
if [ $status -eq 0 ]; then
  echo "expected a non-zero exit status, got 0"; echo "$output"; exit 1
fi
if ! printf '%s\n' "$output" | tr '\n' ' ' | grep -E -q -e "$regex"; then
  echo "the message does not match <$regex>:"; echo "$output"; exit 1
fi
echo "exit status $status, message as expected"
