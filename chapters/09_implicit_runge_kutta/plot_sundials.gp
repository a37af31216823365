# Chapter 9's comparison with SUNDIALS: processor time against the error reached on the stiff cloth (5000, 20),
# CVODE's BDF and ARKODE's ESDIRKs with KLU at a ladder of tolerances, the book's embedded pairs at a ladder of
# tolerances and its SDIRKs at a ladder of steps; the lines join, for each error level, the time of each one's
# fastest run reaching it.
# Called as: gnuplot -e "data='DIR'; plots='DIR'" plot_sundials.gp   (DIR from ch09_sundials_benchmark --report-runs)
set terminal pngcairo size 900,600 enhanced font "Sans,12"
set grid
set output plots.'/ch09_sundials.png'
set title "Stiff cloth (K, D) = (5000, 20), T = 0.4 s: processor time against error"
set xlabel "max |x - x_{ref}| at T [m]"
set ylabel "processor time [s]"
set logscale xy
set format x "10^{%T}"
set key bottom left box opaque font ",11"
plot data.'/stiff_runs.dat' index 0 using 1:2 with points pt 6 ps 1.2 lc rgb "#444444" title "CVODE BDF + KLU", \
     data.'/stiff_runs.dat' index 3 using 1:2 with steps lw 2 lc rgb "#444444" title "CVODE, fastest reaching each level", \
     data.'/stiff_runs.dat' index 1 using 1:2 with points pt 4 ps 1.2 lc rgb "#2ca02c" title "ARKODE ESDIRK3(2)4L[2]SA and 4(3)6L[2]SA + KLU", \
     data.'/stiff_runs.dat' index 4 using 1:2 with steps lw 2 dt 2 lc rgb "#2ca02c" title "ARKODE, fastest reaching each level", \
     data.'/stiff_runs.dat' index 2 using 1:2 with points pt 9 ps 1.2 lc rgb "#9467bd" title "the book: ESDIRK pairs (and, full run, TR-BDF2, SDIRKs)", \
     data.'/stiff_runs.dat' index 5 using 1:2 with steps lw 2 lc rgb "#9467bd" title "the book, fastest reaching each level"
