# Chapter 8 figures from ch08_adaptive_step --experiments: the hard case, the pairs' response to a jump, and the
# estimates against the true local errors. Called as gnuplot -e "data='DIR'; plots='DIR'" plot.gp
set terminal pngcairo size 900,700 enhanced font 'Sans,11'
set grid
pairs = "heun_euler bs32 rkf45 cash_karp dopri5 tsit5"

# h(t) and the rejected attempts beside the shortest spring (dopri5, PI controller, first block).
set output plots.'/ch08_hard_case.png'
set multiplot layout 2,1
set logscale y
set format y '10^{%L}'
set xrange [0:1]
set ylabel 'step h [s]'
set title 'dopri5 on the 20 x 20 cloth, K = 50, D = 0, rtol = atol = 1e-6, PI controller' noenhanced
set key bottom left
plot data.'/hard_case.dat' index 0 using 2:($5 == 1 ? $3 : 1/0) with linespoints pt 7 ps 0.4 lc rgb '#1f77b4' title 'accepted', \
     '' index 0 using 2:($5 == 0 ? $3 : 1/0) with points pt 2 ps 1.2 lw 2 lc rgb '#d62728' title 'rejected'
set ylabel 'shortest spring l / L_0'
set xlabel 't [s]'
unset title
plot data.'/hard_case.dat' index 0 using 2:6 with lines lc rgb '#7f7f7f' title 'at each attempt', \
     '' index 0 using 2:($5 == 0 ? $6 : 1/0) with points pt 2 ps 1.2 lw 2 lc rgb '#d62728' title 'where a step was rejected'
unset multiplot
unset logscale
unset format
unset xlabel
set autoscale

# What each pair's stages make of a jump in the acceleration at t0 + theta h.
set output plots.'/ch08_jump_response.png'
set terminal pngcairo size 1000,620 enhanced font 'Sans,10'
unset ylabel
set multiplot layout 2,3 title 'A jump J in the acceleration at t_0 + {/Symbol q} h: velocity error of the step and its estimate, per unit J h (each panel its own scale)'
set xrange [0:1]
# Each pair's own vertical range: a common one either cuts the largest errors off or flattens the smallest. A
# margin above and below keeps a curve at its extreme off the frame and clear of the key.
set autoscale y
set offsets 0, 0, graph 0.25, graph 0.05
set key top right font ',8'
do for [i=1:6] {
  set title word(pairs, i) noenhanced
  set xlabel '{/Symbol q}'
  plot data.'/jump_response.dat' using 1:(column(2*i)) with lines lw 2 lc rgb '#d62728' title 'true error', \
       '' using 1:(column(2*i+1)) with lines lw 2 lc rgb '#1f77b4' title 'estimate'
}
unset multiplot
set autoscale
set offsets 0, 0, 0, 0
unset xrange
unset yrange

# The estimate against the true local error of every accepted step on the cloth.
set terminal pngcairo size 1000,620 enhanced font 'Sans,10'
set output plots.'/ch08_estimate_check.png'
set multiplot layout 2,3 title 'Accepted steps on the cloth at rtol = atol = 1e-5: true local error against the estimate (both in tolerances)'
set logscale xy
set format x '10^{%L}'
set format y '10^{%L}'
set xrange [1e-4:10]
set yrange [1e-4:1e4]
unset key
do for [i=1:6] {
  set title word(pairs, i) noenhanced
  set xlabel 'estimate'
  set ylabel 'true error'
  plot data.'/estimate_check.dat' index (i-1) using 4:5 with points pt 7 ps 0.5 lc rgb '#1f77b4', \
       x with lines lc rgb '#7f7f7f', 10 with lines dt 2 lc rgb '#d62728'
}
unset multiplot
