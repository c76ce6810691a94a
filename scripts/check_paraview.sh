#!/usr/bin/env bash
# Check that ParaView opens the program's output: runs a 2D problem (the
# manufactured plate of prm/B3-plate-manufactured.prm) and a 3D one (a
# vibrating bar) on NP MPI ranks with Output/Format = vtu and hdf5, and
# opens particles.pvd / grid.pvd and particles.xdmf / grid.xdmf with
# ParaView's readers (scripts/open_in_paraview.py), which print the points,
# cells and field ranges of the first and last output.
# Needs pvpython: apt-get install paraview python3-paraview (not needed by
# the build or the tests).
# Usage: scripts/check_paraview.sh [path to mpm-otm] [NP, default 2]
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
exe=$(realpath "${1:-$root/build-release/mpm-otm}")
np=${2:-2}
command -v pvpython > /dev/null ||
  { echo "pvpython not found: apt-get install paraview python3-paraview"; exit 1; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"

cp "$root/prm/B3-plate-manufactured.prm" plate.prm
printf 'subsection Time\n set End time = 1e-3\nend\n' >> plate.prm
cat > bar.prm <<'PRM'
set Dimension = 3
set Problem = vibrating bar
subsection Time
  set End time = 0.02
  set Time step = 1e-4
end
subsection Mesh
  set Lower corner = 0, 0, 0
  set Upper corner = 25, 2, 2
  set Subdivisions = 8, 1, 1
end
subsection Material
  set Young's modulus = 100
  set Density = 1
end
subsection Vibrating bar
  set Initial velocity amplitude = 0.1
end
PRM

status=0
for case in plate bar; do
  for format in vtu hdf5; do
    cp $case.prm run.prm
    printf 'subsection Output\n set Directory = %s-%s\n set Format = %s\n set Interval = 5\nend\n' \
      "$case" "$format" "$format" >> run.prm
    mpirun -np "$np" "$exe" --overwrite run.prm < /dev/null > "$case-$format.log" 2>&1 ||
      { echo "$case, $format: the run failed"; tail -5 "$case-$format.log"; status=1; continue; }
    if [ "$format" = vtu ]; then files="particles.pvd grid.pvd"; else files="particles.xdmf grid.xdmf"; fi
    echo "== $case on $np ranks, Output/Format = $format"
    pvpython "$root/scripts/open_in_paraview.py" $(for f in $files; do echo "$case-$format/$f"; done) ||
      status=1
  done
done
exit $status
