# Chapter 4 figures: implicit Euler's energy with full Newton and with one iteration for the report's three
# (K, D); the residuals of one stiff step; Newton iterations per step with the symmetric and the definite matrix.
# Called as: gnuplot -e "data='DIR'; plots='DIR'" plot.gp   (DIR from ch04_implicit_euler --report-runs)
set terminal pngcairo size 900,600 enhanced font "Sans,12"
set grid

set output plots.'/ch04_energy.png'
set title "Implicit Euler on the 20 x 20 cloth, h = 0.01 s: full Newton (lines) and one iteration (points)"
set xlabel "time t [s]"
set ylabel "total energy E [J]"
set xrange [0:2]
set key bottom left
plot data.'/full_K50_D0/energy.dat'   using 1:5 with lines lw 2 lc rgb "#1f77b4" title "K = 50, D = 0", \
     data.'/one_K50_D0/energy.dat'    every 10 using 1:5 with points pt 6 lc rgb "#1f77b4" notitle, \
     data.'/full_K200_D0/energy.dat'  using 1:5 with lines lw 2 lc rgb "#d62728" title "K = 200, D = 0", \
     data.'/one_K200_D0/energy.dat'   every 10 using 1:5 with points pt 6 lc rgb "#d62728" notitle, \
     data.'/full_K200_D20/energy.dat' using 1:5 with lines lw 2 lc rgb "#2ca02c" title "K = 200, D = 20", \
     data.'/one_K200_D20/energy.dat'  every 10 using 1:5 with points pt 6 lc rgb "#2ca02c" notitle, \
     79200 with lines dt 2 lc rgb "black" title "E(0) = 79200 J"

# The lowest residual reached, and the time of the definite matrix's failed step, as the run measured them.
set datafile missing "?"  # residuals.dat's ratio at k = 0, which is undefined
stats data.'/residuals.dat' using 2 nooutput
floor = STATS_min
stats data.'/iterations_definite.dat' using 1 nooutput
t_stall = STATS_max

set output plots.'/ch04_residuals.png'
set title "Newton on one stiff step: report scene, K = 10^5 N/m, D = 0, h = 0.01 s, exact Jacobian, LU"
set xlabel "Newton iteration k"
set ylabel "residual |r_k|_{/Symbol \245} [N s]"
set logscale y
set format y "10^{%T}"
set xrange [0:12]
set yrange [1e-14:1e4]
set key top right
plot data.'/residuals.dat' using 1:2 with linespoints lw 2 pt 7 lc rgb "#1f77b4" title "|r_k|", \
     floor with lines dt 2 lc rgb "gray" title sprintf("lowest residual reached, %.2g", floor)

set output plots.'/ch04_iterations.png'
set title "Newton iterations per step, K = 50, D = 0, h = 0.01 s, LDL^T, tolerance 10^{-8}"
set xlabel "time t [s]"
set ylabel "Newton iterations in the step"
unset logscale y
set format y "%g"
set xrange [0:2]
set yrange [0:26]
set key top left
plot data.'/iterations_symmetric.dat' using 1:2 with steps lw 2 lc rgb "#1f77b4" title "symmetric (exact Hessian)", \
     data.'/iterations_definite.dat'  using 1:2 with steps lw 2 lc rgb "#d62728" title sprintf("definite (Choi and Ko): stalls at t = %.2f s", t_stall), \
     20 with lines dt 2 lc rgb "black" title "--newton-max-iter 20"
