# Chapter 10's peer comparison: error at T = 0.5 s against CPU time for the programs written with Boost.Odeint and
# SUNDIALS and for the book's methods, on the stiff fabric. Called as: gnuplot -e "data='DIR'; plots='DIR'" peers.gp
set terminal pngcairo size 1000,650 enhanced font "Sans,12"
set output plots.'/ch10_peers.png'
set title "Fabric 20 x 20, K = 1e5 N/m: the peers and the book's methods, error at T = 0.5 s against CPU time"
set logscale xy
set format x "10^{%L}"
set format y "10^{%L}"
set xlabel "CPU time to T [s]"
set ylabel "largest position error at T [m]"
set grid
set key inside right top font ",11" box opaque
set yrange [1e-10:1]
set arrow 1 from graph 0, first 1e-2 to graph 1, first 1e-2 nohead dt 2 lc rgb "#888888"
set arrow 2 from graph 0, first 1e-3 to graph 1, first 1e-3 nohead dt 2 lc rgb "#888888"
set label 1 "1 cm" at graph 0.01, first 1.5e-2
set label 2 "1 mm" at graph 0.01, first 1.5e-3
F = data.'/peers.dat'
# Columns: side program setting steps cpu_seconds error_at_T; failed runs have error NaN and are left out.
plot F u 5:(strcol(1) eq "odeint" ? $6 : 1/0) w p pt 5 ps 1.6 lc rgb "#1f77b4" t "Boost.Odeint (RK4, Dormand-Prince)", \
     F u 5:(strcol(1) eq "SUNDIALS" ? $6 : 1/0) w p pt 9 ps 1.8 lc rgb "#ff7f0e" t "SUNDIALS (CVODE BDF, ARKODE backward Euler)", \
     F u 5:(strcol(1) eq "book" ? $6 : 1/0) w p pt 7 ps 1.6 lc rgb "#2ca02c" t "the book's methods"
