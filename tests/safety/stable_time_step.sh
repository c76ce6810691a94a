#!/bin/sh
# Every method, update scheme, mass matrix and family runs stably at 0.95
# of the stable time step the program prints: the vibrating bar (1D, and
# 2D with Powell-Sabin splines, linear functions and B-splines) with Time
# step = auto and Courant factor = 0.95 for 1000 steps, with an amplitude
# so small that the points do not move relative to the grid (so the stable
# step stays the one at the start). An unstable run gains energy by a
# fixed factor per step; Energy growth limit = 0.25 stops it with a
# non-zero exit. Before the estimate knew the nodal update, USL, OTM and
# the unified approach with a lumped mass matrix were unstable here (their
# limits are 0.74-0.81 of the estimate for M^-1 K).
# Usage: stable_time_step.sh <mpm-otm>
exe=$1
failed=0

# write_prm NAME END_TIME DIM METHOD FAMILY DEGREE SCHEME MASS
# (DIM = 1-free: a 1D bar fixed at x = 0 whose free end lies inside the
# grid, so that a partially lumped mass differs from the consistent one;
# otherwise the vibrating bar filling the grid)
write_prm() {
  cells="hypercube"
  if [ "$3" = "1-free" ]; then
    dimension=1
    mesh="set Lower corner = 0
  set Upper corner = 1.25
  set Subdivisions = 25"
    particles=4
    problem="set Problem = custom
subsection Custom problem
  set Material lower corner = 0
  set Material upper corner = 1
  set Initial velocity = 1e-6 * sin(pi * x / 2)
  set Fixed components = 0: x
end"
  else
    dimension=$3
    problem="set Problem = vibrating bar
subsection Vibrating bar
  set Initial velocity amplitude = 1e-6
end"
    if [ "$3" -eq 1 ]; then
      mesh="set Lower corner = 0
  set Upper corner = 1
  set Subdivisions = 20"
      particles=4
    elif [ "$5" = "Powell-Sabin" ]; then
      cells="simplex"
      mesh="set Lower corner = 0, 0
  set Upper corner = 25, 2
  set Subdivisions = 4, 1"
      particles="16, 14"
    else
      mesh="set Lower corner = 0, 0
  set Upper corner = 25, 2
  set Subdivisions = 8, 1"
      particles="4, 4"
    fi
  fi
  cat > $1.prm <<PRM
set Dimension = $dimension
$problem
set Method = $4
set Shape functions = $5
set B-spline degree = $6
set Update scheme = $7
set Mass matrix = $8
subsection Time
  set End time = $2
  set Time step = auto
  set Courant factor = 0.95
  set Energy growth limit = 0.25
end
subsection Mesh
  set Cell type = $cells
  $mesh
end
subsection Particles
  set Particles per cell = $particles
end
subsection Material
  set Young's modulus = 100
  set Poisson's ratio = 0
  set Density = 1
end
subsection Output
  set Directory = output-$1
  set Interval = 0
  set Format = none
end
PRM
}

# check DIM METHOD FAMILY DEGREE SCHEME MASS
check() {
  name="stable-$1d-$2-$3$4-$5-$6"
  name=$(echo "$name" | tr ' ' '_')
  write_prm $name 1e-12 "$@"
  dt=$("$exe" --overwrite $name.prm 2>&1 |
       grep -o "^time step [0-9.e+-]* s" | awk '{print $3}')
  if [ -z "$dt" ]; then
    echo "$name: no time step printed"; "$exe" --overwrite $name.prm
    failed=1; return
  fi
  write_prm $name "$(awk "BEGIN { print 1000 * $dt }")" "$@"
  if "$exe" --overwrite $name.prm > $name.log 2>&1; then
    echo "$name: stable for 1000 steps of $dt s"
  else
    echo "$name: UNSTABLE at 0.95 x the printed stable step ($dt s):"
    tail -n 3 $name.log
    failed=1
  fi
}

for mass in lumped consistent; do
  for scheme in USL MUSL; do
    for family in "linear 1" "B-spline 2" "B-spline 3" "max-ent 1"; do
      check 1 MPM $family $scheme $mass
    done
  done
  for family in "linear 1" "max-ent 1"; do
    check 1 OTM $family automatic $mass
  done
  for scheme in automatic MUSL; do
    for family in "linear 1" "B-spline 2" "max-ent 1"; do
      check 1 Unified $family $scheme $mass
    done
  done
  for scheme in USL MUSL; do
    for family in "linear 1" "B-spline 2" "Powell-Sabin 1"; do
      check 2 MPM $family $scheme $mass
    done
  done
  check 2 OTM linear 1 automatic $mass
done
# A partially lumped mass matrix: lumped rows at the bar's free end.
for scheme in USL MUSL; do
  for family in "linear 1" "B-spline 2"; do
    check 1-free MPM $family $scheme "partially lumped"
  done
done
exit $failed
