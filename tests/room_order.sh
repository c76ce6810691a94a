#!/usr/bin/env bash
# The rooms of the code (include/mpm_otm/<room>, source/<room>) include only
# the rooms before them in this order (doc/manual.md, "How the code is
# organised"), so that the graph of includes between rooms has no cycle.
# Prints every include that breaks the order and fails if there is one.
# Usage: tests/room_order.sh SOURCE_DIRECTORY
set -euo pipefail
root=${1:?the source directory}
order=(base grid material_points materials problems shape_functions
  grid_system boundary_conditions algorithms io simulator)
declare -A rank
for i in "${!order[@]}"; do rank[${order[$i]}]=$i; done
status=0
for room_dir in "$root"/include/mpm_otm/* "$root"/source/*/; do
  room_dir=${room_dir%/}
  room=$(basename "$room_dir")
  [ -n "${rank[$room]+x}" ] || { echo "unknown room: $room_dir"; status=1; continue; }
  while IFS=: read -r file line; do
    used=$(echo "$line" | sed 's|.*#include <mpm_otm/\([a-z_]*\)/.*|\1|')
    [ -n "${rank[$used]+x}" ] || { echo "$file: unknown room $used"; status=1; continue; }
    if [ "${rank[$used]}" -gt "${rank[$room]}" ]; then
      echo "$file: room $room includes $used, which comes after it"
      status=1
    fi
  done < <(grep -H "#include <mpm_otm/" "$room_dir"/* || true)
done
[ $status -eq 0 ] && echo "every room includes only the rooms before it"
exit $status
