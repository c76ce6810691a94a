# Figures of doc/benchmarks.md from doc/data/*.dat (run from doc/).
set terminal pngcairo size 800,560 font ",11"
set grid
set key top right

set output "figures/B1b-convergence.png"
set title "B1b: RMS displacement error at T = 1e-3 (journal Fig. 6, MPM-P1)"
set logscale xy
set xlabel "number of nodes"
set ylabel "RMS displacement error"
set format y "10^{%L}"
plot "data/B1b-mpm-p1.dat" using 1:2 with linespoints lw 2 pt 7 title "mpm-otm, MPM-P1 (USL, lumped)", \
     [8:128] 1e-3/x**2 with lines dt 2 lc rgb "gray" title "second order"

set output "figures/B5-convergence.png"
set title "B5 small deformation: L2 displacement error at t = 0.02 (thesis Table 4.2)"
set xlabel "h_x"
set ylabel "L2 displacement error (thesis Eq. 4.4)"
set key bottom right
plot "data/B5-lagrange.dat" using 2:3 with linespoints lw 2 pt 7 title "mpm-otm, Lagrange MPM", \
     "data/B5-lagrange.dat" using 2:4 with points pt 6 ps 2 lc rgb "black" title "thesis Table 4.2", \
     [0.7:7] 4.6e-6*x**2 with lines dt 2 lc rgb "gray" title "second order"

unset logscale
set format y "%g"
set output "figures/B6-top-displacement.png"
set title "B6 small deformation: displacement of the top of the soil column (thesis Fig. 4.10)"
set xlabel "t (s)"
set ylabel "u_y (m)"
set key bottom right
plot "data/B6-top.dat" using 1:3 with lines lw 3 lc rgb "gray" title "exact (series)", \
     "data/B6-top.dat" using 1:2 with lines lw 1.5 lc rgb "blue" title "mpm-otm, Lagrange MPM 2 x 16 blocks"

set output "figures/B6-top-velocity.png"
set title "B6 small deformation: velocity of the top of the soil column (thesis Fig. 4.10)"
set ylabel "v_y (m/s)"
plot "data/B6-top.dat" using 1:5 with lines lw 3 lc rgb "gray" title "exact (series)", \
     "data/B6-top.dat" using 1:4 with lines lw 1.5 lc rgb "blue" title "mpm-otm, Lagrange MPM 2 x 16 blocks"

set output "figures/B3-sigma11.png"
set title "B3: sigma_{11} along X_2 = 0.066 at T = 3.5e-3 (journal Fig. 9)"
set xlabel "X_1"
set ylabel "sigma_{11} (Pa)"
set key top right
plot "data/B3-sigma11.dat" using 1:3 with lines lw 3 lc rgb "gray" title "exact", \
     "data/B3-sigma11.dat" using 1:2 with points pt 7 ps 0.6 lc rgb "red" title "mpm-otm, MPM-P1"
