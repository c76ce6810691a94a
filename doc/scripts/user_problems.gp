# Figures of the G1-G4 sections of doc/benchmarks.md from doc/data/G*.dat
# (run from doc/; doc/scripts/reproduce_user_problems.sh writes the data).
set terminal pngcairo size 800,560 font ",11"
set grid
set key top right

set output "figures/G1-cantilever.png"
set title "G1: tip deflection of the cantilever, gravity switched on at t = 0, undamped"
set xlabel "t (s)"
set ylabel "tip deflection -u_y (m)"
set key bottom right
plot "data/G1-tip-linear-8.dat" using 1:(-$2) with lines lw 2 title "mpm-otm, linear MPM, 8 cells across h", \
     "data/G1-tip-B-spline-8.dat" using 1:(-$2) with lines lw 2 dt 2 title "mpm-otm, quadratic B-splines, 8 cells", \
     1.0080e-2 with lines lc rgb "black" dt 3 title "static deflection, Timoshenko 1.008e-2", \
     1.0080e-2 * (1 - cos(2 * pi * x / 0.1624)) with lines lc rgb "gray" title "Timoshenko: 1.008e-2 (1 - cos(2 pi t / 0.1624))"

set output "figures/G2-friction-block.png"
set title "G2: block on a rough plane, centre of mass"
set xlabel "t (s)"
set ylabel "x_{centre}(t) - x_{centre}(0) (m)"
set key top left
g = 9.81
a(theta, mu) = (g * (sin(theta * pi / 180) - mu * cos(theta * pi / 180)) > 0) ? g * (sin(theta * pi / 180) - mu * cos(theta * pi / 180)) : 0
plot "data/G2-centre-30-0.3.dat" using 1:2 with points pt 7 title "mpm-otm, theta = 30, mu = 0.3", \
     a(30, 0.3) * x**2 / 2 with lines lc rgb "black" title "rigid block, a = 2.356", \
     "data/G2-centre-30-0.dat" using 1:2 with points pt 5 title "mpm-otm, theta = 30, mu = 0", \
     a(30, 0) * x**2 / 2 with lines lc rgb "black" dt 2 title "rigid block, a = g/2", \
     "data/G2-centre-10-0.3.dat" using 1:2 with points pt 9 title "mpm-otm, theta = 10, mu = 0.3 (at rest)"

set output "figures/G3-load-displacement.png"
set title "G3: smooth strip footing on a Tresca soil (half model), 2 x 2 points per cell"
set xlabel "settlement (m)"
set ylabel "load per unit length (kN/m)"
set key bottom right
set yrange [0:36]
plot "data/G3-load-linear-none-40.dat" using 1:($2 / 1e3) with lines lw 1 lc rgb "#e41a1c" dt 2 title "linear, no remedy, 8 cells per half-width", \
     "data/G3-load-linear-F-bar-40.dat" using 1:($2 / 1e3) with lines lw 2 lc rgb "#e41a1c" title "linear, F-bar, 8 cells", \
     "data/G3-load-linear-F-bar-80.dat" using 1:($2 / 1e3) with lines lw 2 lc rgb "#ff7f00" title "linear, F-bar, 16 cells", \
     "data/G3-load-bspline-none-40.dat" using 1:($2 / 1e3) with lines lw 1 lc rgb "#377eb8" dt 2 title "B-splines p = 2, no remedy, 8 cells", \
     "data/G3-load-bspline-F-bar-40.dat" using 1:($2 / 1e3) with lines lw 2 lc rgb "#377eb8" title "B-splines p = 2, F-bar, 8 cells", \
     "data/G3-load-bspline-F-bar-80.dat" using 1:($2 / 1e3) with lines lw 2 lc rgb "#4daf4a" title "B-splines p = 2, F-bar, 16 cells", \
     25.708 with lines lc rgb "black" dt 3 lw 2 title "Prandtl (2 + pi) c B / 2 = 25.71 kN/m"
set autoscale

set output "figures/G3-plastic-strain.png"
set terminal pngcairo size 800,860 font ",11"
set xlabel "x (m)"
set ylabel "y (m)"
set size ratio -1
set xrange [0:2.5]
set yrange [1.2:2.6]
set cblabel "equivalent plastic strain"
set cbrange [0:0.2]
set palette rgbformulae 33,13,10
unset key
set multiplot layout 2,1 title "G3: equivalent plastic strain at a settlement of 0.1, linear functions, 8 cells per half-width"
set title "no remedy (locked)"
plot "data/G3-plastic-strain-linear-none.dat" using 1:2:3 with points pt 5 ps 0.35 palette
set title "F-bar"
plot "data/G3-plastic-strain-linear-F-bar.dat" using 1:2:3 with points pt 5 ps 0.35 palette
unset multiplot
set terminal pngcairo size 800,560 font ",11"
unset size
set autoscale
unset cbrange

set output "figures/G4-deposits.png"
set terminal pngcairo size 760,800 font ",11"
set ytics 0.1
set xlabel "x (m)"
set ylabel "y (m)"
set xrange [0:1.2]
set yrange [0:0.42]
set cbrange [0:2]
set cblabel "equivalent plastic strain"
set key top right
# One panel per aspect ratio a = H0 / L0 (L0 = 0.2): the deposit coloured
# by the equivalent plastic strain and the initial column.
set multiplot layout 3,1 title "G4: final deposits of the columns (L_0 = 0.2), colour: equivalent plastic strain"
do for [case in "0.5 1 2"] {
  height = 0.2 * case
  set title "a = ".case
  set arrow 1 from 0, height to 0.2, height nohead dt 2 lc rgb "black" front
  set arrow 2 from 0.2, height to 0.2, 0 nohead dt 2 lc rgb "black" front
  plot "data/G4-deposit-".case.".dat" using 1:2:3 with points pt 5 ps 0.2 palette notitle, \
       NaN with lines dt 2 lc rgb "black" title "initial column"
}
unset multiplot
unset arrow
unset cblabel
set ytics autofreq
set autoscale
unset cbrange

set output "figures/G4-failure-surface.png"
set terminal pngcairo size 700,560 font ",11"
set title "G4: speed at t = 0.05 s (a = 1, 40 cells across L_0) and the Rankine surface"
set xlabel "x (m)"
set ylabel "y (m)"
set size ratio -1
set xrange [0:0.3]
set yrange [0:0.22]
set cblabel "speed (m/s)"
plot "data/G4-failure-speed.dat" using 1:2:3 with points pt 5 ps 0.3 palette notitle, \
     [0.0845:0.2] (0.2 - x) * tan(60 * pi / 180) with lines lw 2 lc rgb "black" title "45 + phi/2 = 60 deg from the toe"
unset cblabel
set size noratio
set autoscale

# G5: the slope sweep. Bishop's critical circle (phi = 30 deg held) from
# data/G5-bishop.txt, written by bishop_slope.py.
circle = system("awk '/critical cohesion/ { gsub(\",\", \"\"); for (i = 1; i <= NF; ++i) if ($i == \"centre\") print $(i + 1), $(i + 2), $(i + 4) }' data/G5-bishop.txt")
xc = word(circle, 1) + 0
yc = word(circle, 2) + 0
rc = word(circle, 3) + 0
c_bishop = system("awk '/critical cohesion/ { for (i = 1; i <= NF; ++i) if ($i == \"cohesion\") print $(i + 1) }' data/G5-bishop.txt") + 0

set output "figures/G5-slope-sweep.png"
set terminal pngcairo size 760,520 font ",11"
set title "G5: largest displacement at the end of each run of the sweep"
set xlabel "cohesion c (Pa), phi = 30 deg"
set ylabel "largest displacement (m)"
set logscale y
set xrange [0:3000]
set yrange [0.05:20]
set key top right
set arrow 1 from c_bishop, 0.05 to c_bishop, 20 nohead dt 2 lc rgb "black"
set label 1 "Bishop" at c_bishop + 40, 10
set arrow 2 from 0, 1 to 3000, 1 nohead dt 3 lc rgb "gray40"
set label 2 "slides above 1 m" at 2000, 1.25
plot for [h in "1 0.5 0.25"] \
       "< awk '$1 == ".h." && $2 == \"F-bar\"' data/G5-runs.dat | sort -g -k3" using 3:6 with linespoints pt 7 title "F-bar, ".h." m cells", \
     for [h in "1 0.5 0.25"] \
       "< awk '$1 == ".h." && $2 == \"none\"' data/G5-runs.dat | sort -g -k3" using 3:6 with linespoints pt 6 dt 2 title "none, ".h." m cells"
unset logscale y
unset arrow
unset label
set autoscale

set output "figures/G5-shear-band.png"
set terminal pngcairo size 900,420 font ",11"
set title "G5: equivalent plastic strain of the slide nearest the critical cohesion (0.25 m cells, F-bar), at the initial positions"
set xlabel "x (m)"
set ylabel "y (m)"
set size ratio -1
set xrange [0:45]
set yrange [0:16]
set cbrange [0:1]
set cblabel "equivalent plastic strain"
set key bottom left opaque
plot "data/G5-plastic-strain.dat" using 1:2:3 with points pt 5 ps 0.25 palette notitle, \
     [xc - rc:xc + rc] (yc - sqrt(rc**2 - (x - xc)**2) < (x < 15 ? 15 : x < 30 ? 15 - (x - 15) / 1.5 : 5) ? yc - sqrt(rc**2 - (x - xc)**2) : 1/0) \
       with lines lw 2 lc rgb "black" title "Bishop's critical circle, c = 862 Pa"
unset cblabel
unset cbrange
set size noratio
set autoscale

# The biaxial test with strain softening (prm/biaxial-softening.prm).
set output "figures/biaxial-load.png"
set terminal pngcairo size 760,520 font ",11"
set title "Biaxial test, softening Mohr-Coulomb: platen load (mean over 0.05 s)"
set xlabel "platen displacement (m)"
set ylabel "load (kN/m)"
set xrange [0:0.06]
set yrange [0:80]
set key top right font ",9"
peak = 2 * 20 * cos(pi / 6) / (1 - sin(pi / 6))
residual = 2 * 5 * cos(5 * pi / 180) / (1 - sin(5 * pi / 180))
plot "data/biaxial-load-0.05-B-spline-nodal-average-F-bar.dat" using 1:($2 / 1e3) with lines lw 2 title "B-splines, nodal average, 0.05 m cells", \
     "data/biaxial-load-0.1-B-spline-nodal-average-F-bar.dat" using 1:($2 / 1e3) with lines lw 2 title "B-splines, nodal average, 0.1 m cells", \
     "data/biaxial-load-0.05-B-spline-none-F-bar.dat" using 1:($2 / 1e3) with lines dt 2 title "B-splines, local, 0.05 m cells", \
     "data/biaxial-load-0.05-linear-nodal-average-F-bar.dat" using 1:($2 / 1e3) with lines lw 1 title "linear, nodal average, 0.05 m cells", \
     "data/biaxial-load-0.05-linear-none-F-bar.dat" using 1:($2 / 1e3) with lines dt 2 title "linear, local, 0.05 m cells", \
     "data/biaxial-load-0.05-linear-none-none.dat" using 1:($2 / 1e3) with lines dt 4 title "linear, local, no locking remedy", \
     peak with lines dt 3 lc rgb "black" title "peak 2 c cos(phi) / (1 - sin(phi))", \
     residual with lines dt 4 lc rgb "gray30" title "residual 2 c_r cos(phi_r) / (1 - sin(phi_r))"
set output "figures/biaxial-load-late.png"
set title "Biaxial test: platen load after the peak (mean over 0.05 s)"
set xrange [0.02:0.06]
set yrange [8:16]
plot "data/biaxial-load-0.05-B-spline-nodal-average-F-bar.dat" using 1:($2 / 1e3) with lines lw 2 title "B-splines, nodal average, 0.05 m cells", \
     "data/biaxial-load-0.1-B-spline-nodal-average-F-bar.dat" using 1:($2 / 1e3) with lines lw 2 title "B-splines, nodal average, 0.1 m cells", \
     "data/biaxial-load-0.05-B-spline-none-F-bar.dat" using 1:($2 / 1e3) with lines dt 2 title "B-splines, local, 0.05 m cells", \
     "data/biaxial-load-0.05-linear-nodal-average-F-bar.dat" using 1:($2 / 1e3) with lines lw 1 title "linear, nodal average, 0.05 m cells", \
     "data/biaxial-load-0.05-linear-none-F-bar.dat" using 1:($2 / 1e3) with lines dt 2 title "linear, local, 0.05 m cells", \
     "data/biaxial-load-0.05-linear-none-none.dat" using 1:($2 / 1e3) with lines dt 4 title "linear, local, no locking remedy", \
     peak with lines dt 3 lc rgb "black" title "peak 2 c cos(phi) / (1 - sin(phi))", \
     residual with lines dt 4 lc rgb "gray30" title "residual 2 c_r cos(phi_r) / (1 - sin(phi_r))"
set autoscale

set output "figures/biaxial-shear-band.png"
set terminal pngcairo size 560,760 font ",11"
set title "Biaxial test: plastic strain at the end (B-splines,\nnodal average, 0.05 m cells), at the initial positions"
set xlabel "x (m)"
set ylabel "y (m)"
set size ratio -1
set xrange [0:1]
set yrange [0:2]
set cbrange [0:0.5]
set cblabel "equivalent plastic strain"
set key bottom right opaque
stats "< awk '$3 > 0.05 && $2 > 0.1 && $2 < 1.9' data/biaxial-plastic-strain-B-spline.dat" using 1:2 nooutput
xm = STATS_mean_x
ym = STATS_mean_y
direction = STATS_slope > 0 ? 1 : -1
plot "data/biaxial-plastic-strain-B-spline.dat" using 1:2:3 with points pt 5 ps 0.4 palette notitle, \
     ym + direction * tan(45 * pi / 180) * (x - xm) with lines lw 2 dt 2 lc rgb "black" title "Roscoe 45 deg", \
     ym + direction * tan(60 * pi / 180) * (x - xm) with lines lw 2 dt 3 lc rgb "black" title "Coulomb 60 deg"
unset cblabel
unset cbrange
set size noratio
set autoscale
