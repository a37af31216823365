# Chapter 2 figures: energy of the report's cloth under explicit and symplectic Euler for the report's three
# (K, D), and explicit Euler's energy growth on a single spring against the prediction (1 + (h omega)^2)^n.
# Called as: gnuplot -e "data='DIR'; plots='DIR'" plot.gp   (DIR from ch02_explicit_euler --report-runs)
set terminal pngcairo size 1400,560 enhanced font "Sans,12"
# E0, the single spring's initial energy, before any range is set (stats obeys the axis ranges)
stats data.'/single_spring.dat' every ::0::0 using 2 nooutput
E0 = STATS_min
set grid
set logscale y
set format y "10^{%T}"
set xlabel "time t [s]"
set ylabel "total energy E [J]"
set xrange [0:2]
set yrange [1e4:1e12]
set key top left

set output plots.'/ch02_energy.png'
set multiplot layout 1,2 title "Total energy of the 20 x 20 cloth, h = 0.01 s (a curve that stops: the run diverged)"
set title "explicit Euler"
plot data.'/explicit_euler_K50_D0/energy.dat'   using 1:5 with lines lw 2 lc rgb "#1f77b4" title "K = 50, D = 0", \
     data.'/explicit_euler_K200_D0/energy.dat'  using 1:5 with lines lw 2 lc rgb "#d62728" title "K = 200, D = 0", \
     data.'/explicit_euler_K200_D20/energy.dat' using 1:5 with lines lw 2 lc rgb "#2ca02c" title "K = 200, D = 20", \
     79200 with lines dt 2 lc rgb "black" title "E(0) = 79200 J"
set title "symplectic Euler"
plot data.'/symplectic_euler_K50_D0/energy.dat'   using 1:5 with lines lw 2 lc rgb "#1f77b4" title "K = 50, D = 0", \
     data.'/symplectic_euler_K200_D0/energy.dat'  using 1:5 with lines lw 2 lc rgb "#d62728" title "K = 200, D = 0", \
     data.'/symplectic_euler_K200_D20/energy.dat' using 1:5 with lines lw 2 lc rgb "#2ca02c" title "K = 200, D = 20", \
     79200 with lines dt 2 lc rgb "black" title "E(0) = 79200 J"
unset multiplot

set terminal pngcairo size 900,600 enhanced font "Sans,12"
set output plots.'/ch02_single_spring.png'
set title "One undamped spring, K = 200 N/m, m = 1 kg, h = 0.01 s (h {/Symbol w} = 0.1414)"
set ylabel "energy relative to the start, E / E_0"
set format y "%g"
set yrange [0.5:100]
set key top left
plot data.'/single_spring.dat' using 1:($3/E0) with lines lw 4 lc rgb "#bbbbbb" title "prediction (1 + (h {/Symbol w})^2)^n", \
     '' every 8 using 1:($2/E0) with points pt 6 ps 1.3 lc rgb "#d62728" title "explicit Euler, measured", \
     '' using 1:($4/E0) with lines lw 2 lc rgb "#1f77b4" title "symplectic Euler, measured"
