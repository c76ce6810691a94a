# Used by doc/scripts/reproduce_user_problems.sh (G4): the angle of the
# failure surface of a collapsing column from one particles-NNNNN.csv
# (columns id,X,Y,x,y,ux,uy,vx,vy,...); -v L0=width -v H0=height -v cell=cell
# size [-v fraction=f, default 0.5]. Prints the number of rows used and the
# angle in degrees.
# Failure surface at one instant: in every row of points (the same initial
# y), the x where the speed first rises through the fraction f of the row's
# largest speed (linear interpolation between neighbouring points; f = 0.5:
# the middle of the shear band, f = 0.1-0.2: the edge of the static region,
# where the experiments draw it); least-squares line through these (x, y)
# over the rows
# where the crossing lies inside the column (0 < x < L0) and below
# H0 - 2 cells; its angle from the horizontal in degrees.
BEGIN { FS = ","; if (fraction == "") fraction = 0.5 }
NR > 1 { r = sprintf("%.5f", $3); k = ++cnt[r]; X[r, k] = $2; S[r, k] = sqrt($8 * $8 + $9 * $9); if (S[r, k] > M[r]) M[r] = S[r, k] }
END {
  for (r in cnt) {
    n = cnt[r]
    # sort the row by X (insertion sort)
    for (i = 1; i <= n; i++) { xs[i] = X[r, i]; ss[i] = S[r, i] }
    for (i = 2; i <= n; i++) { a = xs[i]; b = ss[i]; j = i - 1; while (j > 0 && xs[j] > a) { xs[j + 1] = xs[j]; ss[j + 1] = ss[j]; j-- } xs[j + 1] = a; ss[j + 1] = b }
    h = fraction * M[r]; xc = -1
    for (i = 2; i <= n; i++) if (ss[i - 1] < h && ss[i] >= h) { xc = xs[i - 1] + (h - ss[i - 1]) / (ss[i] - ss[i - 1]) * (xs[i] - xs[i - 1]); break }
    if (xc > 0.5 * cell && xc < L0 - 0.5 * cell && r + 0 < H0 - 2 * cell) { m++; sx += xc; sy += r; sxx += xc * xc; sxy += xc * r }
  }
  slope = (m * sxy - sx * sy) / (m * sxx - sx * sx)
  printf "%d %.2f\n", m, atan2(-slope, 1) * 180 / 3.14159265 }
