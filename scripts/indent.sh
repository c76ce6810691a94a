#!/usr/bin/env bash
# Format every C++ file of include, source, tests and doc/scripts with the
# project's .clang-format (deal.II's style, clang-format 14). With --check,
# only report files that are not formatted.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
files=$(find include source tests doc/scripts -name '*.h' -o -name '*.cc')
if [ "${1:-}" = "--check" ]; then
  status=0
  for file in $files; do
    clang-format --dry-run -Werror "$file" > /dev/null 2>&1 || { echo "not formatted: $file"; status=1; }
  done
  exit $status
fi
clang-format -i $files
