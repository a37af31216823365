# Chapter 9 figures: energy of the undamped cloth under every implicit method; observed orders on (200, 20);
# work against precision on the stiff cloth (5000, 20).
# Called as: gnuplot -e "data='DIR'; plots='DIR'" plot.gp   (DIR from ch09_implicit_runge_kutta --report-runs)
set terminal pngcairo size 900,600 enhanced font "Sans,12"
set grid

set output plots.'/ch09_energy.png'
set title "Undamped 20 x 20 cloth (K = 50, D = 0), h = 0.01 s"
set xlabel "time t [s]"
set ylabel "total energy E [J]"
set key bottom left
plot data.'/energy_implicit_euler/energy.dat'    using 1:5 with lines lw 2 lc rgb "#d62728" title "implicit Euler", \
     data.'/energy_bdf2/energy.dat'              using 1:5 with lines lw 2 lc rgb "#ff7f0e" title "BDF2", \
     data.'/energy_sdirk2/energy.dat'            using 1:5 with lines lw 2 lc rgb "#2ca02c" title "SDIRK2", \
     data.'/energy_trbdf2/energy.dat'            using 1:5 with lines lw 2 dt 2 lc rgb "#8c564b" title "TR-BDF2", \
     data.'/energy_sdirk3/energy.dat'            using 1:5 with lines lw 2 lc rgb "#9467bd" title "SDIRK3", \
     data.'/energy_trapezoid/energy.dat'         using 1:5 with lines lw 2 lc rgb "#17becf" title "trapezoid", \
     data.'/energy_esdirk32/energy.dat'          using 1:5 with lines lw 2 dt 4 lc rgb "#e377c2" title "ESDIRK3(2)4L[2]SA", \
     data.'/energy_esdirk43/energy.dat'          using 1:5 with lines lw 2 dt 5 lc rgb "#7f7f7f" title "ESDIRK4(3)6L[2]SA", \
     data.'/energy_implicit_midpoint/energy.dat' using 1:5 with lines lw 2 dt 3 lc rgb "#1f77b4" title "implicit midpoint"

set output plots.'/ch09_orders.png'
set title "Error at T = 0.4 s on (K, D) = (200, 20) against RK4 at h = 2×10^{-5}"
set xlabel "step h [s]"
set ylabel "max |x - x_{ref}| [m]"
set logscale xy
set format x "10^{%T}"
set format y "10^{%T}"
set key bottom right
# orders.dat: one index per method (0..8, the registry's order); work_precision.dat: implicit Euler, SDIRK2,
# SDIRK3, BDF2 with full Newton (0..3), then the same with modified Newton (4..7).
plot data.'/orders.dat' index 0 using 3:4 with linespoints lw 2 pt 7 lc rgb "#d62728" title "implicit Euler", \
     data.'/orders.dat' index 1 using 3:4 with linespoints lw 2 pt 5 lc rgb "#1f77b4" title "implicit midpoint", \
     data.'/orders.dat' index 2 using 3:4 with linespoints lw 2 pt 4 lc rgb "#17becf" title "trapezoid", \
     data.'/orders.dat' index 3 using 3:4 with linespoints lw 2 pt 9 lc rgb "#2ca02c" title "SDIRK2", \
     data.'/orders.dat' index 4 using 3:4 with linespoints lw 2 pt 11 lc rgb "#9467bd" title "SDIRK3", \
     data.'/orders.dat' index 5 using 3:4 with linespoints lw 2 pt 13 lc rgb "#8c564b" title "TR-BDF2", \
     data.'/orders.dat' index 6 using 3:4 with linespoints lw 2 pt 12 lc rgb "#e377c2" title "ESDIRK3(2)4L[2]SA", \
     data.'/orders.dat' index 7 using 3:4 with linespoints lw 2 pt 14 lc rgb "#7f7f7f" title "ESDIRK4(3)6L[2]SA", \
     data.'/orders.dat' index 8 using 3:4 with linespoints lw 2 pt 3 lc rgb "#ff7f0e" title "BDF2"

set output plots.'/ch09_work_precision.png'
set title "Stiff cloth (K, D) = (5000, 20), T = 0.4 s: full Newton (solid), modified (dashed)"
set xlabel "max |x - x_{ref}| [m]"
set ylabel "processor time [s]"
set key top right
plot data.'/work_precision.dat' index 0 using 4:5 with linespoints lw 2 pt 7 lc rgb "#d62728" title "implicit Euler", \
     data.'/work_precision.dat' index 1 using 4:5 with linespoints lw 2 pt 9 lc rgb "#2ca02c" title "SDIRK2", \
     data.'/work_precision.dat' index 2 using 4:5 with linespoints lw 2 pt 11 lc rgb "#9467bd" title "SDIRK3", \
     data.'/work_precision.dat' index 3 using 4:5 with linespoints lw 2 pt 3 lc rgb "#ff7f0e" title "BDF2", \
     data.'/work_precision.dat' index 4 using 4:5 with linespoints lw 2 dt 2 pt 6 lc rgb "#d62728" notitle, \
     data.'/work_precision.dat' index 5 using 4:5 with linespoints lw 2 dt 2 pt 8 lc rgb "#2ca02c" notitle, \
     data.'/work_precision.dat' index 6 using 4:5 with linespoints lw 2 dt 2 pt 10 lc rgb "#9467bd" notitle, \
     data.'/work_precision.dat' index 7 using 4:5 with linespoints lw 2 dt 2 pt 2 lc rgb "#ff7f0e" notitle
