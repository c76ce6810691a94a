# The point-to-point oscillation of the mean stress in G3's plastic zone,
# from a 2D particles-NNNNN.csv (awk -F, -v h=<cell size> -f cell_spread.awk):
# for every cell of size h that holds two or more points with an equivalent
# plastic strain above 0.01, the largest minus the smallest mean stress
# p = (sxx + syy + szz) / 3 of its points; printed: the mean of these
# spreads over the cells, divided by the cohesion c = 10 kPa.
NR > 1 && $17 > 0.01 {
  cell = int($4 / h) " " int($5 / h)
  p = ($10 + $11 + $15) / 3
  if (!(cell in low) || p < low[cell]) low[cell] = p
  if (!(cell in high) || p > high[cell]) high[cell] = p
  count[cell]++
}
END {
  for (cell in count)
    if (count[cell] > 1) { sum += high[cell] - low[cell]; n++ }
  printf "%.3f\n", (n > 0 ? sum / n / 10e3 : 0)
}
