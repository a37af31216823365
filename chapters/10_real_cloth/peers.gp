# Chapter 10's peer comparison: error at T = 0.5 s against CPU time for the programs written with Boost.Odeint and
# SUNDIALS and for the book's methods, on the stiff fabric. Called as: gnuplot -e "data='DIR'; plots='DIR'" peers.gp
set terminal pngcairo size 1000,800 enhanced font "Sans,12"
set output plots.'/ch10_peers.png'
set title "Fabric 20 x 20, K = 1e5 N/m: the peers and the book's methods, error at T = 0.5 s against CPU time"
set logscale xy
set format x "10^{%L}"
set format y "10^{%L}"
set xlabel "CPU time to T [s]" offset 0,0.6
set ylabel "largest position error at T [m]"
set grid
# The key below the plot, in columns, so that it covers no point: one symbol per program, filled for the book's
# force routine and open for the plain loop.
set key outside below center maxrows 5 font ",11" box spacing 1.1 height 0.5
set yrange [1e-10:1]
set arrow 1 from graph 0, first 1e-2 to graph 1, first 1e-2 nohead dt 2 lc rgb "#888888"
set arrow 2 from graph 0, first 1e-3 to graph 1, first 1e-3 nohead dt 2 lc rgb "#888888"
set label 1 "1 cm" at graph 0.01, first 1.5e-2
set label 2 "1 mm" at graph 0.01, first 1.5e-3
F = data.'/peers.dat'
# Columns: side program setting steps cpu_seconds error_at_T; failed runs have error NaN and are left out.
is(a, b) = strstrt(strcol(2), a) > 0 && strstrt(strcol(2), b) > 0
plot F u 5:(is("odeint RK4", "plain") ? $6 : 1/0) w p pt 4 ps 1.6 lc rgb "#1f77b4" t "odeint RK4, plain loop", \
     F u 5:(is("odeint RK4", "book's") ? $6 : 1/0) w p pt 5 ps 1.6 lc rgb "#1f77b4" t "odeint RK4, book's forces", \
     F u 5:(is("Dormand", "plain") ? $6 : 1/0) w lp pt 6 ps 1.6 dt 3 lc rgb "#17becf" t "odeint Dormand-Prince, plain loop", \
     F u 5:(is("Dormand", "book's") ? $6 : 1/0) w lp pt 7 ps 1.6 dt 3 lc rgb "#17becf" t "odeint Dormand-Prince, book's forces", \
     F u 5:(is("CVODE", "plain") ? $6 : 1/0) w lp pt 8 ps 1.8 dt 2 lc rgb "#ff7f0e" t "CVODE BDF, plain loop", \
     F u 5:(is("CVODE", "book's") ? $6 : 1/0) w lp pt 9 ps 1.8 dt 2 lc rgb "#ff7f0e" t "CVODE BDF, book's forces", \
     F u 5:(is("ARKODE backward", "plain") ? $6 : 1/0) w lp pt 10 ps 1.8 dt 4 lc rgb "#d62728" t "ARKODE backward Euler, plain loop", \
     F u 5:(is("ARKODE backward", "book's") ? $6 : 1/0) w lp pt 11 ps 1.8 dt 4 lc rgb "#d62728" t "ARKODE backward Euler, book's forces", \
     F u 5:(is("ARKODE linearly", "") ? $6 : 1/0) w lp pt 13 ps 1.8 dt 5 lc rgb "#9467bd" t "ARKODE linearly implicit Euler", \
     F u 5:(is("book: ", "symplectic_euler") ? $6 : 1/0) w p pt 3 ps 2 lw 2 lc rgb "#2ca02c" t "book: symplectic\\_euler", \
     F u 5:(is("book: ", "rk4") ? $6 : 1/0) w p pt 2 ps 2 lw 2 lc rgb "#2ca02c" t "book: rk4", \
     F u 5:(is("book: ", "implicit_euler") ? $6 : 1/0) w lp pt 1 ps 2 lw 2 lc rgb "#006400" t "book: implicit\\_euler/one/cg"
