# Chapter 8's work-precision figure from ch08_work_precision: error at T against thread CPU time, the project's
# pairs (rms and max norms) and Boost.Odeint's controlled steppers. Called as gnuplot -e "data='DIR'; plots='DIR'".
set terminal pngcairo size 900,750 enhanced font 'Sans,11'
set output plots.'/ch08_work_precision.png'
set grid
set logscale xy
set format x '10^{%L}'
set format y '10^{%L}'
set key inside bottom left noenhanced font ',9'
set xlabel 'thread CPU time of one run to T = 1 s [s] (best of the timed runs)'
set ylabel 'largest particle position error at T [m]'
set title 'Work-precision, 20 x 20 cloth, K = 50, D = 0, T = 1 s: adaptive pairs and Boost.Odeint' noenhanced
f = data.'/work_precision.dat'
sel(s, m) = (strcol(1) eq s && strcol(2) eq m)
plot f using (sel('project_rms', 'dopri5') ? $6 : 1/0):4 with linespoints pt 7 lc rgb '#1f77b4' title 'dopri5, rms norm', \
     f using (sel('project_max', 'dopri5') ? $6 : 1/0):4 with linespoints pt 6 dt 2 lc rgb '#1f77b4' title 'dopri5, max norm', \
     f using (sel('project_rms', 'tsit5') ? $6 : 1/0):4 with linespoints pt 9 lc rgb '#2ca02c' title 'tsit5, rms', \
     f using (sel('project_rms', 'cash_karp') ? $6 : 1/0):4 with linespoints pt 5 lc rgb '#9467bd' title 'cash_karp, rms', \
     f using (sel('project_max', 'cash_karp') ? $6 : 1/0):4 with linespoints pt 4 dt 2 lc rgb '#9467bd' title 'cash_karp, max', \
     f using (sel('project_rms', 'rkf45') ? $6 : 1/0):4 with linespoints pt 11 lc rgb '#17becf' title 'rkf45, rms', \
     f using (sel('project_rms', 'bs32') ? $6 : 1/0):4 with linespoints pt 13 lc rgb '#bcbd22' title 'bs32, rms', \
     f using (sel('odeint_plain', 'dopri5') ? $6 : 1/0):4 with linespoints pt 7 lw 2 lc rgb '#d62728' title 'odeint dopri5, plain program', \
     f using (sel('odeint_plain', 'cash_karp54') ? $6 : 1/0):4 with linespoints pt 5 lw 2 lc rgb '#ff7f0e' title 'odeint cash_karp54, plain program', \
     f using (sel('odeint_project_forces', 'dopri5') ? $6 : 1/0):4 with linespoints pt 6 dt 2 lc rgb '#d62728' title 'odeint dopri5, project forces', \
     f using (sel('odeint_project_forces', 'cash_karp54') ? $6 : 1/0):4 with linespoints pt 4 dt 2 lc rgb '#ff7f0e' title 'odeint cash_karp54, project forces'
