# Chapter 9's comparison with SUNDIALS: processor time against the error reached on the stiff cloth (5000, 20),
# CVODE's BDF with KLU at a ladder of tolerances, the book's SDIRKs with modified Newton at a ladder of steps.
# Called as: gnuplot -e "data='DIR'; plots='DIR'" plot_sundials.gp   (DIR from ch09_sundials_benchmark --report-runs)
set terminal pngcairo size 900,600 enhanced font "Sans,12"
set grid
set output plots.'/ch09_sundials.png'
set title "Stiff cloth (K, D) = (5000, 20), T = 0.4 s: processor time against error"
set xlabel "max |x - x_{ref}| at T [m]"
set ylabel "processor time [s]"
set logscale xy
set format x "10^{%T}"
set key top right
plot data.'/stiff_runs.dat' index 0 using 1:2 with linespoints lw 2 pt 7 lc rgb "#444444" title "CVODE BDF + KLU", \
     data.'/stiff_runs.dat' index 1 using 1:2 with points pt 9 ps 1.6 lc rgb "#9467bd" title "SDIRK2 and SDIRK3, modified Newton"
