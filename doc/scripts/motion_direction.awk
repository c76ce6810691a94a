# Used by doc/scripts/reproduce_user_problems.sh (G4): the direction in
# which the collapsing wedge of a column moves, from one particles-NNNNN.csv
# (columns id,X,Y,x,y,ux,uy,vx,vy,...); -v L0=width -v H0=height -v cell=cell
# size [-v fraction=f, default 0.3]. Prints the number of points used and
# the angle in degrees below the horizontal.
# The points of the column (initially below H0 - 2 cells, now at x < L0)
# that move outwards faster than the fraction f of the largest speed; the
# mean of their directions of motion, atan(-vy / vx), weighted by their
# speeds. Material sliding on a band without dilatancy (psi = 0) moves
# parallel to it, so this is the band's angle from the horizontal.
BEGIN { FS = ","; if (fraction == "") fraction = 0.3 }
NR > 1 { n++; Y[n] = $3; x[n] = $4; vx[n] = $8; vy[n] = $9; S[n] = sqrt($8 * $8 + $9 * $9); if (S[n] > m) m = S[n] }
END {
  for (i = 1; i <= n; i++)
    if (S[i] > fraction * m && Y[i] < H0 - 2 * cell && x[i] < L0 && vx[i] > 0) {
      sum += atan2(-vy[i], vx[i]) * 180 / 3.14159265 * S[i]; weight += S[i]; k++ }
  printf "%d %.2f\n", k, sum / weight }
