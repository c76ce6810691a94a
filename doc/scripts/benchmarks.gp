# Figures of doc/benchmarks.md from doc/data/*.dat (run from doc/).
set terminal pngcairo size 800,560 font ",11"
set grid
set key top right

set output "figures/B1b-convergence.png"
set title "B1b: RMS displacement error at T = 1e-3 (journal Fig. 6)"
set logscale xy
set xlabel "number of nodes"
set ylabel "RMS displacement error"
set format y "10^{%L}"
set key bottom left
plot "data/B1b-mpm-p1.dat" using 1:2 with linespoints lw 2 pt 7 title "mpm-otm, MPM-P1 (USL, lumped)", \
     "data/B1b-otm-p1.dat" using 1:2 with linespoints lw 2 pt 5 title "mpm-otm, OTM-P1 (consistent)", \
     "data/B1b-bsmpm-p2.dat" using 1:2 with linespoints lw 2 pt 9 title "mpm-otm, BSMPM p = 2 (consistent)", \
     "data/B1b-unified-p2.dat" using 1:2 with linespoints lw 2 pt 4 dt 2 title "mpm-otm, unified p = 2 (consistent)", \
     "data/B1b-mpm-maxent.dat" using 1:2 with linespoints lw 2 pt 11 title "mpm-otm, MPM-maxent d_{max} = 2 (consistent)", \
     "data/B1b-otm-maxent.dat" using 1:2 with linespoints lw 2 pt 13 dt 3 title "mpm-otm, OTM-maxent d_{max} = 2 (consistent)", \
     [8:512] 1.6e-4/x**2 with lines dt 2 lc rgb "gray" title "second order", \
     [8:64] 1.2e-4/x**3 with lines dt 3 lc rgb "black" title "third order"
set key top right

set output "figures/B2-convergence.png"
set title "B2: RMS displacement error at T = 0.1, 12 points per cell (journal Fig. 8)"
set xlabel "nodes in the material domain"
set key bottom left
plot "data/B2-convergence.dat" using 1:2 with linespoints lw 2 pt 7 title "mpm-otm, MPM-P1", \
     "data/B2-convergence.dat" using 1:3 with linespoints lw 2 pt 5 title "mpm-otm, OTM-P1", \
     "data/B2-convergence.dat" using 1:4 with linespoints lw 2 pt 9 title "mpm-otm, BSMPM p = 2", \
     "data/B2-convergence.dat" using 1:5 with linespoints lw 2 pt 4 title "mpm-otm, unified p = 2", \
     "data/B2-convergence.dat" using 1:6 with linespoints lw 2 pt 11 title "mpm-otm, MPM-maxent d_{max} = 2 (lumped)", \
     "data/B2-convergence.dat" using 1:8 with linespoints lw 2 pt 10 dt 3 title "mpm-otm, MPM-maxent d_{max} = 2 (consistent)", \
     "data/B2-convergence.dat" using 1:7 with linespoints lw 2 pt 13 title "mpm-otm, OTM-maxent d_{max} = 2", \
     [17:257] 5e-4/x**2 with lines dt 2 lc rgb "gray" title "second order"

set output "figures/B5-convergence.png"
set title "B5 small deformation: L2 displacement error at t = 0.02 (thesis Tables 4.2, 4.3)"
set xlabel "h_x"
set ylabel "L2 displacement error (thesis Eq. 4.4)"
set key top left
set yrange [5e-8:3e-2]
set datafile missing "-"
plot "data/B5-lagrange.dat" using 2:3 with linespoints lw 2 pt 7 title "mpm-otm, Lagrange MPM", \
     "data/B5-lagrange.dat" using 2:4 with points pt 6 ps 2 lc rgb "black" title "thesis Table 4.2", \
     "data/B5-powell-sabin.dat" using 2:3 with linespoints lw 2 pt 5 title "mpm-otm, PS-MPM (56 points per triangle)", \
     "data/B5-powell-sabin.dat" using 2:4 with points pt 4 ps 2 lc rgb "black" title "thesis Table 4.3", \
     [0.7:7] 4.6e-6*x**2 with lines dt 2 lc rgb "gray" title "second order", \
     [3:25] 1e-8*x**3 with lines dt 3 lw 1.5 lc rgb "black" title "third order"
set autoscale y

unset logscale
set format y "%g"
set output "figures/B1a-stress-error.png"
set title "B1a: RMS stress error over the first 20 steps (conference paper)"
set xlabel "time step"
set ylabel "RMS stress error (Pa)"
set key top left
plot "data/B1a-stress-error.dat" using 1:2 with linespoints lw 2 pt 7 title "mpm-otm, MPM-P1", \
     "data/B1a-stress-error.dat" using 1:3 with linespoints lw 2 pt 5 dt 2 title "mpm-otm, OTM-P1", \
     "-" using 1:2 with points pt 6 ps 2 lc rgb "black" title "published after 20 steps (MPM 3.8693, OTM 3.8684)"
20 3.8693
20 3.8684
e

set output "figures/B6-top-displacement.png"
set title "B6 small deformation: displacement of the top of the soil column (thesis Fig. 4.10)"
set xlabel "t (s)"
set ylabel "u_y (m)"
set key bottom right
plot "data/B6-top.dat" using 1:3 with lines lw 3 lc rgb "gray" title "exact (series)", \
     "data/B6-top.dat" using 1:2 with lines lw 1.5 lc rgb "blue" title "mpm-otm, Lagrange MPM 2 x 16 blocks", \
     "data/B6-top-powell-sabin.dat" using 1:2 with lines lw 1.5 dt 2 lc rgb "dark-green" title "mpm-otm, Powell-Sabin MPM 1 x 8 blocks"

set output "figures/B6-top-velocity.png"
set title "B6 small deformation: velocity of the top of the soil column (thesis Fig. 4.10)"
set ylabel "v_y (m/s)"
plot "data/B6-top.dat" using 1:5 with lines lw 3 lc rgb "gray" title "exact (series)", \
     "data/B6-top.dat" using 1:4 with lines lw 1.5 lc rgb "blue" title "mpm-otm, Lagrange MPM 2 x 16 blocks", \
     "data/B6-top-powell-sabin.dat" using 1:4 with lines lw 1.5 dt 2 lc rgb "dark-green" title "mpm-otm, Powell-Sabin MPM 1 x 8 blocks"

set output "figures/B2-stress.png"
set title "B2: stress at T = 0.4, 68 material nodes, 4 points per cell (journal Fig. 7)"
set xlabel "X (m)"
set ylabel "sigma (Pa)"
set key bottom left
plot "data/B2-profile-otm.dat" using 1:5 with lines lw 3 lc rgb "gray" title "exact", \
     "data/B2-profile-mpm.dat" using 1:4 with points pt 7 ps 0.5 lc rgb "red" title "mpm-otm, MPM-P1", \
     "data/B2-profile-otm.dat" using 1:4 with points pt 5 ps 0.5 lc rgb "blue" title "mpm-otm, OTM-P1", \
     "data/B2-profile-bsmpm.dat" using 1:4 with points pt 9 ps 0.6 lc rgb "dark-green" title "mpm-otm, BSMPM p = 2", \
     "data/B2-profile-unified.dat" using 1:4 with points pt 4 ps 0.6 lc rgb "black" title "mpm-otm, unified p = 2", \
     "data/B2-profile-mpm-maxent.dat" using 1:4 with points pt 11 ps 0.6 lc rgb "orange" title "mpm-otm, MPM-maxent d_{max} = 2", \
     "data/B2-profile-otm-maxent.dat" using 1:4 with points pt 13 ps 0.6 lc rgb "purple" title "mpm-otm, OTM-maxent d_{max} = 2"

set output "figures/B2-stress-free-end.png"
set title "B2: stress near the free end at T = 0.4, 68 material nodes (journal Fig. 7)"
set xrange [0.85:1.002]
set key bottom left
set arrow from 1. - 1. / 67., graph 0 to 1. - 1. / 67., graph 1 nohead dt 3 lc rgb "black"
set label "last cell {/Symbol \256}" at 1. - 1. / 67., graph 0.95 right offset -0.5, 0
plot "data/B2-profile-otm.dat" using 1:5 with lines lw 3 lc rgb "gray" title "exact", \
     "data/B2-profile-mpm.dat" using 1:4 with linespoints pt 7 ps 0.6 lc rgb "red" title "mpm-otm, MPM-P1", \
     "data/B2-profile-otm.dat" using 1:4 with linespoints pt 5 ps 0.6 lc rgb "blue" title "mpm-otm, OTM-P1", \
     "data/B2-profile-mpm-maxent.dat" using 1:4 with linespoints pt 11 ps 0.9 lc rgb "orange" title "mpm-otm, MPM-maxent d_{max} = 2", \
     "data/B2-profile-otm-maxent.dat" using 1:4 with linespoints pt 13 ps 0.9 lc rgb "purple" title "mpm-otm, OTM-maxent d_{max} = 2"
unset xrange
unset arrow
unset label

set output "figures/B2-displacement.png"
set title "B2: displacement at T = 0.4 (journal Fig. 7)"
set ylabel "u (m)"
plot "data/B2-profile-otm.dat" using 1:3 with lines lw 3 lc rgb "gray" title "exact", \
     "data/B2-profile-mpm.dat" using 1:2 with points pt 7 ps 0.5 lc rgb "red" title "mpm-otm, MPM-P1", \
     "data/B2-profile-otm.dat" using 1:2 with points pt 5 ps 0.5 lc rgb "blue" title "mpm-otm, OTM-P1", \
     "data/B2-profile-bsmpm.dat" using 1:2 with points pt 9 ps 0.6 lc rgb "dark-green" title "mpm-otm, BSMPM p = 2", \
     "data/B2-profile-unified.dat" using 1:2 with points pt 4 ps 0.6 lc rgb "black" title "mpm-otm, unified p = 2", \
     "data/B2-profile-mpm-maxent.dat" using 1:2 with points pt 11 ps 0.6 lc rgb "orange" title "mpm-otm, MPM-maxent d_{max} = 2", \
     "data/B2-profile-otm-maxent.dat" using 1:2 with points pt 13 ps 0.6 lc rgb "purple" title "mpm-otm, OTM-maxent d_{max} = 2"

set output "figures/B5-history.png"
set multiplot layout 2,1 title "B5 small deformation: middle of the bar (thesis Figs. 4.3 left and 4.5)"
set title ""
set xlabel "t (s)"
set ylabel "u_x (m)"
# Room below the curves for the key.
set xrange [0:15]
set yrange [-0.18:0.09]
set key bottom center horizontal maxrows 2
plot "data/B5-history.dat" using 1:2 with lines lw 3 lc rgb "gray" title "exact", \
     "data/B5-history.dat" using 1:4 with lines lw 1.5 lc rgb "red" title "mpm-otm, Lagrange MPM 12 x 1 blocks, 38 functions", \
     "data/B5-history.dat" using 1:6 with lines lw 1.5 dt 2 lc rgb "dark-green" title "mpm-otm, Powell-Sabin MPM 4 x 1 blocks, 42 functions"
set ylabel "v_x (m/s)"
set yrange [-0.19:0.12]
plot "data/B5-history.dat" using 1:3 with lines lw 3 lc rgb "gray" title "exact", \
     "data/B5-history.dat" using 1:5 with lines lw 1.5 lc rgb "red" title "mpm-otm, Lagrange MPM", \
     "data/B5-history.dat" using 1:7 with lines lw 1.5 dt 2 lc rgb "dark-green" title "mpm-otm, Powell-Sabin MPM"
unset multiplot
unset xrange
unset yrange
set key default

set output "figures/B5-large.png"
set multiplot layout 2,1 title "B5 large deformation: middle of the bar (thesis Figs. 4.7 and 4.8)"
set title ""
set xlabel "t (s)"
set ylabel "u_x (m)"
set key bottom left
plot "data/B5-large.dat" using 1:2 with lines lw 3 lc rgb "gray" title "1D OTM-P1 reference", \
     "data/B5-large.dat" using 1:4 with lines lw 1.5 lc rgb "red" title "mpm-otm, Lagrange MPM 16 x 1 blocks, 56 points per triangle", \
     "data/B5-large.dat" using 1:6 with lines lw 1.5 dt 2 lc rgb "dark-green" title "mpm-otm, Powell-Sabin MPM 8 x 1 blocks, 20 points per triangle", \
     "data/B5-large.dat" using 1:8 with lines lw 1.5 dt 3 lc rgb "black" title "mpm-otm, Powell-Sabin, unified approach, same grid"
set ylabel "v_x (m/s)"
plot "data/B5-large.dat" using 1:3 with lines lw 3 lc rgb "gray" title "1D OTM-P1 reference", \
     "data/B5-large.dat" using 1:5 with lines lw 1.5 lc rgb "red" title "mpm-otm, Lagrange MPM", \
     "data/B5-large.dat" using 1:7 with lines lw 1.5 dt 2 lc rgb "dark-green" title "mpm-otm, Powell-Sabin MPM", \
     "data/B5-large.dat" using 1:9 with lines lw 1.5 dt 3 lc rgb "black" title "mpm-otm, Powell-Sabin, unified approach"
unset multiplot

set output "figures/B6-large.png"
set multiplot layout 2,1 title "B6 large deformation: top of the soil column (thesis Fig. 4.13)"
set ylabel "u_y (m)"
plot "data/B6-large.dat" using 1:2 with lines lw 3 lc rgb "gray" title "1D OTM-P1 reference", \
     "data/B6-large.dat" using 1:4 with lines lw 1.5 lc rgb "red" title "mpm-otm, Lagrange MPM 1 x 4 blocks, 72 points per triangle", \
     "data/B6-large.dat" using 1:6 with lines lw 1.5 dt 2 lc rgb "dark-green" title "mpm-otm, Powell-Sabin MPM, same grid", \
     "data/B6-large.dat" using 1:8 with lines lw 1.5 dt 3 lc rgb "black" title "mpm-otm, Powell-Sabin, unified approach, same grid"
set ylabel "v_y (m/s)"
plot "data/B6-large.dat" using 1:3 with lines lw 3 lc rgb "gray" title "1D OTM-P1 reference", \
     "data/B6-large.dat" using 1:5 with lines lw 1.5 lc rgb "red" title "mpm-otm, Lagrange MPM", \
     "data/B6-large.dat" using 1:7 with lines lw 1.5 dt 2 lc rgb "dark-green" title "mpm-otm, Powell-Sabin MPM", \
     "data/B6-large.dat" using 1:9 with lines lw 1.5 dt 3 lc rgb "black" title "mpm-otm, Powell-Sabin, unified approach"
unset multiplot

set output "figures/B6-remedies.png"
set terminal pngcairo size 800,680 font ",11"
set multiplot title "B6 large deformation, Powell-Sabin MPM on 1 x 8 (+1 empty) blocks: mass-matrix remedies (thesis Ch. 5)\nand the unified approach on the moving 1 x 8 blocks, consistent mass"
# The key of both plots in a strip at the bottom, clear of the curves.
set key at screen 0.5, screen 0.045 center center horizontal maxrows 2 width -2
set size 1, 0.42
set origin 0, 0.52
set ylabel "u_y (m)"
plot "data/B6-remedies.dat" using 1:2 with lines lw 3 lc rgb "gray" title "1D OTM-P1 reference", \
     "data/B6-remedies.dat" using 1:4 with lines lw 1.5 lc rgb "dark-green" title "partially lumped", \
     "data/B6-remedies.dat" using 1:6 with lines lw 1.5 lc rgb "blue" title "lumped", \
     "data/B6-remedies.dat" using 1:8 with lines lw 1.5 lc rgb "red" title "consistent, deactivation below 1e-2", \
     "data/B6-remedies.dat" using 1:12 with lines lw 1.5 dt 2 lc rgb "black" title "unified, consistent"
set ylabel "v_y (m/s)"
set origin 0, 0.11
unset key
plot "data/B6-remedies.dat" using 1:3 with lines lw 3 lc rgb "gray", \
     "data/B6-remedies.dat" using 1:5 with lines lw 1.5 lc rgb "dark-green", \
     "data/B6-remedies.dat" using 1:7 with lines lw 1.5 lc rgb "blue", \
     "data/B6-remedies.dat" using 1:9 with lines lw 1.5 lc rgb "red", \
     "data/B6-remedies.dat" using 1:13 with lines lw 1.5 dt 2 lc rgb "black"
unset multiplot
set size 1, 1
set origin 0, 0
set key default
set terminal pngcairo size 800,560 font ",11"

set output "figures/B3-sigma11.png"
set title "B3: sigma_{11} along X_2 = 0.066 at T = 3.5e-3 (journal Fig. 9)"
set xlabel "X_1"
set ylabel "sigma_{11} (Pa)"
set key below center horizontal maxcols 3 Left reverse
plot "data/B3-sigma11.dat" using 1:3 with lines lw 3 lc rgb "gray" title "exact", \
     "data/B3-sigma11.dat" using 1:2 with points pt 7 ps 0.6 lc rgb "red" title "mpm-otm, MPM-P1", \
     "data/B3-sigma11.dat" using 1:4 with points pt 5 ps 0.6 lc rgb "blue" title "mpm-otm, OTM-P1", \
     "data/B3-sigma11.dat" using 1:5 with points pt 9 ps 0.6 lc rgb "dark-green" title "mpm-otm, BSMPM p = 2", \
     "data/B3-sigma11.dat" using 1:6 with points pt 4 ps 0.6 lc rgb "black" title "mpm-otm, unified p = 2", \
     "data/B3-sigma11.dat" using 1:7 with points pt 11 ps 0.6 lc rgb "orange" title "mpm-otm, MPM-maxent d_{max} = 3, consistent mass", \
     "data/B3-sigma11.dat" using 1:8 with points pt 13 ps 0.6 lc rgb "purple" title "mpm-otm, OTM-maxent d_{max} = 2"

set key inside noreverse Right vertical maxcols auto
set output "figures/B1b-stress-profile.png"
set title "B1b: stress at T = 1e-3 with 32 nodes (journal Fig. 5)"
set xlabel "X (m)"
set ylabel "sigma (Pa)"
set key top right
plot "data/B1b-stress-profile.dat" using 1:2 with lines lw 3 lc rgb "gray" title "exact", \
     "data/B1b-stress-profile.dat" using 1:3 with points pt 7 ps 0.5 lc rgb "red" title "mpm-otm, MPM-P1", \
     "data/B1b-stress-profile.dat" using 1:4 with points pt 5 ps 0.5 lc rgb "blue" title "mpm-otm, OTM-P1", \
     "data/B1b-stress-profile.dat" using 1:5 with points pt 4 ps 0.6 lc rgb "black" title "mpm-otm, unified p = 2"

set output "figures/max-ent-functions-1d.png"
set terminal pngcairo size 1000,760 font ",11"
set multiplot layout 2,2 title "1D cubic-spline priors and local max-ent functions, 11 nodes on [0, 1], d_{max} = 2 (journal Fig. 4)"
unset key
set xlabel "x"
set xrange [0:1]
set title "(a) cubic-spline priors w_i (Eq. 89)"
set ylabel "w_i"
plot for [i = 2:12] "data/max-ent-functions-1d.dat" using 1:i with lines lw 2
set title "(b) derivatives dw_i/dx"
set ylabel "dw_i/dx"
plot for [i = 13:23] "data/max-ent-functions-1d.dat" using 1:i with lines lw 2
set title "(c) max-ent functions phi_i (Eqs. 80-83)"
set ylabel "phi_i"
plot for [i = 24:34] "data/max-ent-functions-1d.dat" using 1:i with lines lw 2
set title "(d) derivatives dphi_i/dx"
set ylabel "dphi_i/dx"
plot for [i = 35:45] "data/max-ent-functions-1d.dat" using 1:i with lines lw 2
unset multiplot

set terminal pngcairo size 800,560 font ",11"
set output "figures/B3-sigma11-deviation.png"
set title "B3: sigma_{11} - exact along X_2 = 0.066 at T = 3.5e-3, in % of the largest exact stress"
set xlabel "X_1"
set ylabel "deviation (%)"
set xrange [0:1]
set yrange [-2:2]
set key below center horizontal maxcols 3 Left reverse
plot "data/B3-sigma11.dat" using 1:(100 * ($4 - $3) / 5.5488e5) with points pt 5 ps 0.5 lc rgb "blue" title "mpm-otm, OTM-P1 (to +-6 %)", \
     "data/B3-sigma11.dat" using 1:(100 * ($5 - $3) / 5.5488e5) with linespoints pt 9 ps 0.5 lc rgb "dark-green" title "mpm-otm, BSMPM p = 2", \
     "data/B3-sigma11.dat" using 1:(100 * ($6 - $3) / 5.5488e5) with linespoints pt 4 ps 0.5 lc rgb "black" title "mpm-otm, unified p = 2", \
     "data/B3-sigma11.dat" using 1:(100 * ($7 - $3) / 5.5488e5) with linespoints pt 11 ps 0.5 lc rgb "orange" title "mpm-otm, MPM-maxent d_{max} = 3, consistent mass", \
     "data/B3-sigma11.dat" using 1:(100 * ($9 - $3) / 5.5488e5) with linespoints pt 10 ps 0.5 lc rgb "brown" title "mpm-otm, MPM-maxent d_{max} = 3, lumped mass", \
     "data/B3-sigma11.dat" using 1:(100 * ($8 - $3) / 5.5488e5) with linespoints pt 13 ps 0.5 lc rgb "purple" title "mpm-otm, OTM-maxent d_{max} = 2"
unset yrange

set output "figures/B4-projection.png"
set title "B4: L2 projection of sin(pi x) sin(pi y) on n x n vertices (thesis Sect. 3.6)"
set logscale xy
set format y "10^{%L}"
set xrange [2:100]
set yrange [1e-7:1]
set xlabel "n (vertices per side, h = 1 / (n - 1))"
set ylabel "L2 error"
set key top right
plot "data/B4-projection.dat" using 1:4 with linespoints lw 2 pt 7 lc rgb "dark-green" title "mpm-otm, Powell-Sabin, structured", \
     "data/B4-projection.dat" using 1:9 with linespoints lw 2 pt 9 dt 2 lc rgb "dark-green" title "mpm-otm, Powell-Sabin, perturbed (0.2 h)", \
     "data/B4-projection.dat" using 1:7 with linespoints lw 2 pt 5 lc rgb "blue" title "mpm-otm, P1, structured", \
     "data/B4-projection.dat" using 1:11 with linespoints lw 2 pt 11 dt 2 lc rgb "blue" title "mpm-otm, P1, perturbed (0.2 h)", \
     "-" using 1:2 with points pt 6 ps 2 lc rgb "black" title "thesis Table 3.1 (Powell-Sabin)", \
     "-" using 1:2 with points pt 4 ps 2 lc rgb "black" title "BENCHMARKS.md B4 (P1, true L2)", \
     "-" using 1:2 with points pt 3 ps 1.5 lc rgb "gray" title "thesis Table 3.2 as printed (other f)", \
     [5:65] 0.03/(x-1)**3 with lines dt 3 lc rgb "black" title "third order", \
     [5:65] 0.8/(x-1)**2 with lines dt 2 lc rgb "gray" title "second order"
3 1.18575e-02
5 1.14331e-03
9 1.31622e-04
17 1.61689e-05
e
5 2.7726e-02
9 6.5955e-03
17 1.6180e-03
33 4.0235e-04
e
5 1.71200e-03
9 4.13089e-04
17 1.02202e-04
33 2.54938e-05
e
unset logscale
set format y "%g"
set autoscale xy
