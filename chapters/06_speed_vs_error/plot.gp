# Chapter 6 figures: work-precision diagrams, sensitivity, near-zero springs, scaling, benchmarks.
# Called as gnuplot -e "data='DIR'; plots='DIR'" plot.gp
set terminal pngcairo size 900,620 enhanced font 'Sans,11'
set grid
set key outside right top
# The methods in the order of the data's blocks, and the names a reader reads in the legends.
array titles[10] = ["explicit Euler", "symplectic Euler", "Heun", "RK4", "3/8 rule", "implicit Euler, Newton, direct", \
                    "implicit Euler, Newton, CG", "implicit Euler, 1 iteration, direct", "implicit Euler, 1 iteration, CG", \
                    "dopri5, adaptive (Chapter 8)"]
# Colour, point type and dash pattern all differ, so that every line can be told apart in greyscale too:
# explicit methods solid with filled points, implicit ones dashed with open points.
set style line 1 lc rgb '#d62728' pt 5 dt 1
set style line 2 lc rgb '#ff7f0e' pt 7 dt 1
set style line 3 lc rgb '#bcbd22' pt 9 dt 1
set style line 4 lc rgb '#2ca02c' pt 11 dt 1
set style line 5 lc rgb '#17becf' pt 13 dt 1
set style line 6 lc rgb '#1f77b4' pt 4 dt 2
set style line 7 lc rgb '#9467bd' pt 6 dt 2
set style line 8 lc rgb '#1f77b4' pt 8 dt 4
set style line 9 lc rgb '#9467bd' pt 10 dt 4
set style line 10 lc rgb '#000000' pt 3 dt 1

do for [cfg in "K50_D0 K200_D20 K5000_D20"] {
  set output plots.'/ch06_wp_'.cfg.'.png'
  set logscale xy
  set format x '10^{%L}'
  set format y '10^{%L}'
  set xlabel 'thread CPU time of one run to T = 0.25 s [s] (fastest of 5)'
  set ylabel 'largest particle position error at T [m]'
  K = substr(cfg, 2, strstrt(cfg, '_') - 1)
  D = substr(cfg, strstrt(cfg, '_D') + 2, strlen(cfg))
  set title 'Work-precision, 20 x 20 cloth, K = '.K.' N/m, D = '.D.' N s/m, T = 0.25 s, h = T / 2^k' noenhanced
  # Ten curves: the key goes under the plot, where it hides none of them.
  set terminal pngcairo size 900,760 enhanced font 'Sans,11'
  set bmargin 9
  set key at screen 0.5, screen 0.015 center bottom horizontal maxrows 5 box font ',9' spacing 0.9 samplen 2.5
  plot for [i=1:10] data.'/wp_'.cfg.'.dat' index (i-1) using 4:5 with linespoints ls i lw 1.5 title titles[i] noenhanced
}
unset format
set key outside right top
set bmargin
set terminal pngcairo size 900,620 enhanced font 'Sans,11'

set output plots.'/ch06_sensitivity.png'
set logscale y
unset logscale x
set format y '10^{%L}'
set xlabel 't [s]'
set ylabel 'amplification of a 10^{-12} m perturbation'
set title 'Sensitivity: two RK4 runs 10^{-12} m apart (20x20, h = 5e-5 full, 5e-4 quick)' enhanced
plot data.'/sensitivity.dat' index 0 using 4:5 with lines lw 2 title 'K = 50, D = 0', \
     '' index 1 using 4:5 with lines lw 2 title 'K = 200, D = 20', \
     '' index 2 using 4:5 with lines lw 2 title 'K = 5000, D = 20', \
     1 with lines dt 2 lc 'black' notitle
unset format

set output plots.'/ch06_near_zero.png'
set logscale y
set format y '10^{%L}'
set xlabel 't [s]'
set ylabel 'shortest spring, l / L_0'
set title 'Shortest spring over the cloth, K = 50, D = 0, RK4 (20x20)' enhanced
plot data.'/near_zero.dat' using 1:2 with lines lw 2 title 'min over springs of l/L_0'
unset format

set output plots.'/ch06_order_loss.png'
set terminal pngcairo size 1300,560 enhanced font 'Sans,11'
set multiplot layout 1,2
set logscale y
set logscale y2
set format y '10^{%L}'
set format y2 '10^{%L}'
set ytics nomirror
set y2tics
set xlabel 't [s]'
set ylabel 'local error of one RK4 step, h = 10^{-3} s [m]'
set y2label 'shortest spring, l / L_0'
set key inside bottom left box opaque
set title 'Where RK4 makes its error, K = 50, D = 0' enhanced
plot data.'/local_error_h1000us.dat' using 1:2 with lines lw 1.5 lc rgb '#2ca02c' title 'local error estimate', \
     '' using 1:4 axes x1y2 with lines lw 1.5 lc rgb '#d62728' title 'shortest spring (right axis)'
unset y2tics
unset y2label
unset logscale y2
set ytics mirror
set logscale xy
set format x '10^{%L}'
set xlabel 'h [s]'
set ylabel '|x_h(T) - x_{h/2}(T)|, largest over particles [m]'
set key inside bottom right box opaque
set title 'Step halving: T = 0.25 s (solid), T = 1 s (dashed), K = 50, D = 0' enhanced
plot data.'/orders.dat' index 4 using 3:4 with linespoints ls 3 lw 1.5 title 'Heun, T = 0.25', \
     '' index 5 using 3:4 with linespoints ls 3 dt 2 lw 1.5 title 'Heun, T = 1', \
     '' index 6 using 3:4 with linespoints ls 4 lw 1.5 title 'RK4, T = 0.25', \
     '' index 7 using 3:4 with linespoints ls 4 dt 2 lw 1.5 title 'RK4, T = 1', \
     '' index 2 using 3:4 with linespoints ls 2 lw 1.5 title 'symplectic Euler, T = 0.25', \
     '' index 3 using 3:4 with linespoints ls 2 dt 2 lw 1.5 title 'symplectic Euler, T = 1'
unset multiplot
unset format
set terminal pngcairo size 900,620 enhanced font 'Sans,11'
set key outside right top

set output plots.'/ch06_scaling.png'
set key inside top left box opaque
set logscale xy
set format y '10^{%L}'
set xlabel 'springs'
set ylabel 'thread CPU time per step [s] (median)'
set title 'Cost per step against grid size, K = 50, D = 0 (explicit h = 1e-3, implicit h = 0.01)'
# No fitted exponents: the quick run measures too few sizes to fit one (the full sweep fits them
# over five sizes). Grey guide lines of slope 1 and 3/2 through each method's smallest grid show how linear
# and n^{3/2} growth would look.
# (One column at a time: two-column stats fits a line, and warns when it has only two points.)
stats data.'/scaling.dat' index 0 using 3 nooutput
x0 = STATS_min
stats data.'/scaling.dat' index 0 using 10 nooutput
y_explicit = STATS_min
stats data.'/scaling.dat' index 2 using 10 nooutput
y_direct = STATS_min
stats data.'/scaling.dat' index 3 using 10 nooutput
y_cg = STATS_min
plot data.'/scaling.dat' index 0 using 3:10 with linespoints ls 1 lw 1.5 title 'explicit Euler', \
     '' index 1 using 3:10 with linespoints ls 4 lw 1.5 title 'RK4', \
     '' index 2 using 3:10 with linespoints ls 6 lw 1.5 title 'implicit Euler, direct (block LDL^T)', \
     '' index 3 using 3:10 with linespoints ls 7 lw 1.5 title 'implicit Euler, CG', \
     y_explicit * (x / x0) with lines dt 3 lc rgb 'gray50' title 'slope 1', \
     y_cg * (x / x0) with lines dt 3 lc rgb 'gray50' notitle, \
     y_direct * (x / x0)**1.5 with lines dt 5 lc rgb 'gray30' title 'slope 3/2'
unset format

set output plots.'/ch06_benchmarks.png'
unset logscale
set logscale x
set format x '10^{%L}'
set style fill solid 0.6
stats data.'/benchmarks.dat' using 2 nooutput
set yrange [STATS_records - 0.4:-0.6]
set ytics nomirror noenhanced
unset key
set xlabel 'median thread CPU time [microseconds], 20x20 cloth, K = 50, D = 0, folded states'
set ylabel ''
set title 'Micro-benchmarks of the core (median thread CPU time)'
plot data.'/benchmarks.dat' using ($3*0.5):0:($3*0.5):(0.35):yticlabels(stringcolumn(1)) with boxxyerror lc rgb '#1f77b4' notitle
