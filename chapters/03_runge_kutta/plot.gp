# Chapter 3 figures: RK4 on the report's three (K, D) (energy and lowest point against time) and the observed
# order of every built-in tableau on the damped single spring.
# Called as: gnuplot -e "data='DIR'; plots='DIR'" plot.gp   (DIR from ch03_runge_kutta --report-runs --tableau rk4)
set terminal pngcairo size 900,600 enhanced font "Sans,12"
set grid
set xlabel "time t [s]"
set xrange [0:2]
set key bottom left

set output plots.'/ch03_energy.png'
set title "RK4 on the 20 x 20 cloth, h = 0.01 s: total energy"
set ylabel "total energy E [J]"
plot data.'/rk4_K50_D0/energy.dat'   using 1:5 with lines lw 2 lc rgb "#1f77b4" title "K = 50, D = 0", \
     data.'/rk4_K200_D0/energy.dat'  using 1:5 with lines lw 2 dt 2 lc rgb "#d62728" title "K = 200, D = 0", \
     data.'/rk4_K200_D20/energy.dat' using 1:5 with lines lw 2 dt 4 lc rgb "#2ca02c" title "K = 200, D = 20", \
     79200 with lines dt 3 lc rgb "black" title "E(0) = 79200 J"

set output plots.'/ch03_lowest_point.png'
set title "RK4 on the 20 x 20 cloth, h = 0.01 s: the lowest particle"
set ylabel "lowest z of the cloth [m]"
set key bottom right
plot data.'/rk4_K50_D0/lowest_point.dat'   using 1:2 with lines lw 2 lc rgb "#1f77b4" title "K = 50, D = 0", \
     data.'/rk4_K200_D0/lowest_point.dat'  using 1:2 with lines lw 2 dt 2 lc rgb "#d62728" title "K = 200, D = 0", \
     data.'/rk4_K200_D20/lowest_point.dat' using 1:2 with lines lw 2 dt 4 lc rgb "#2ca02c" title "K = 200, D = 20"

set output plots.'/ch03_order.png'
set title "Observed order on the damped single spring (K = 50, D = 2, m = 1), error at t = 1 s"
set xlabel "time step h [s]"
set ylabel "largest error in s and s'/{/Symbol w} [m]"
set logscale xy
set format x "10^{%T}"
set format y "10^{%T}"
set xrange [8e-5:0.06]
set yrange [1e-17:1e-1]
# The lower right corner is empty (no method is that accurate at large h): the key goes there.
set key bottom right box opaque font ",11" spacing 1.1
# Point types and dash patterns differ as well as colours, so the figure reads in greyscale.
plot data.'/order.dat' using 1:2 with linespoints lw 2 dt 1 pt 7 lc rgb "#1f77b4" title "explicit Euler", \
     '' using 1:3 with linespoints lw 2 dt 2 pt 5 lc rgb "#2ca02c" title "Heun", \
     '' using 1:4 with points pt 4 ps 2 lc rgb "#2ca02c" title "midpoint (same R(z) as Heun)", \
     '' using 1:5 with linespoints lw 2 dt 4 pt 9 lc rgb "#ff7f0e" title "Kutta's third order", \
     '' using 1:6 with linespoints lw 2 dt 1 pt 11 lc rgb "#d62728" title "RK4", \
     '' using 1:7 with points pt 6 ps 2 lc rgb "#d62728" title "3/8 rule (same R(z) as RK4)", \
     0.08*x with lines dt 3 lc rgb "gray" title "slopes 1, 2, 3, 4", \
     0.08*x**2 with lines dt 3 lc rgb "gray" notitle, \
     0.2*x**3 with lines dt 3 lc rgb "gray" notitle, \
     0.3*x**4 with lines dt 3 lc rgb "gray" notitle
