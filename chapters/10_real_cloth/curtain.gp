# Chapter 10's figures of cloth that moves: the free edge's mean height against time for the reference and the
# methods, the error over every frame against CPU time beside the size of the motion, and implicit Euler's damping
# of a rigid rotation. Called as: gnuplot -e "data='DIR'; plots='DIR'" curtain.gp
set terminal pngcairo size 1400,620 enhanced font "Sans,11"

# 1. The free edge's mean height: the reference at every frame, and each method at its own frames.
set output plots.'/ch10_curtain_edge.png'
set multiplot layout 1,2 title "The free edge's mean height (20 x 20, K = 1e5 N/m): reference and methods"
set xlabel "t [s]"
set ylabel "mean height of the free edge [m]"
set grid
set key bottom right font ",9" box opaque
do for [scene in "curtain swing"] {
  E = data.'/curtain_edge_'.scene.'.dat'
  set title (scene eq "curtain" ? "the curtain, released flat" : "the curtain thrown down at 4 rad/s")
  if (scene eq "curtain") { set key bottom left } else { set key top left }
  plot E index "reference" u 1:2 w l lw 4 lc rgb "black" t "reference (dopri5)", \
       E index "rk4 " u 1:2 w l lw 2 dt 2 lc rgb "#1f77b4" t "RK4 at its stable step", \
       E index "implicit_euler/one/cg h = 1/30" u 1:2 w lp pt 7 ps 0.6 lc rgb "#d62728" t "implicit Euler, 1 iteration, h = 1/30", \
       E index "implicit_euler/one/cg h = 1/60" u 1:2 w lp pt 5 ps 0.5 lc rgb "#ff7f0e" t "implicit Euler, 1 iteration, h = 1/60", \
       E index "implicit_euler/one/cg h = 1/120" u 1:2 w l lw 2 lc rgb "#9467bd" t "implicit Euler, 1 iteration, h = 1/120", \
       E index "local_global h = 1/60" u 1:2 w lp pt 4 ps 0.6 lc rgb "#e377c2" t "local/global, 10 iterations, h = 1/60"
}
unset multiplot

# 2. Error over every frame against CPU time, beside the motion (the error of a cloth that never moves).
set output plots.'/ch10_curtain_cost.png'
set terminal pngcairo size 1800,620 enhanced font "Sans,11"
set multiplot layout 1,3 title "Largest position error over every frame against CPU time; above the grey line a run is no better than standing still"
set logscale xy
set format x "10^{%L}"
set format y "10^{%L}"
set xlabel "CPU time [s]"
set ylabel "largest position error over the frames [m]"
set yrange [1e-9:10]
set key center right font ",9" box opaque
M = data.'/curtain_motion.dat'
do for [scene in "curtain swing corners"] {
  F = data.'/curtain_'.scene.'.dat'
  stats M u (strcol(1) eq scene ? $4 : NaN) nooutput
  motion = STATS_max
  set title (scene eq "curtain" ? "the curtain, released flat" : scene eq "swing" ? "the curtain thrown down at 4 rad/s" : "the sheet hung by its four corners")
  set arrow 1 from graph 0, first motion to graph 1, first motion nohead lw 3 lc rgb "#aaaaaa"
  set arrow 2 from graph 0, first 1e-2 to graph 1, first 1e-2 nohead dt 2 lc rgb "#888888"
  set arrow 3 from graph 0, first 1e-3 to graph 1, first 1e-3 nohead dt 2 lc rgb "#888888"
  ok(m) = (strcol(1) eq m && strcol(10) eq "ok")
  okp(prefix) = (strstrt(strcol(1), prefix) == 1 && strcol(10) eq "ok")
  plot F u (ok("symplectic_euler") ? $4 : 1/0):6 w p pt 7 ps 1.5 lc rgb "#2ca02c" t "symplectic Euler", \
       F u (ok("rk4") ? $4 : 1/0):6 w p pt 5 ps 1.5 lc rgb "#1f77b4" t "RK4", \
       F u (ok("implicit_euler/one/cg") ? $4 : 1/0):6 w lp pt 9 ps 1.3 lc rgb "#ff7f0e" t "implicit Euler, 1 iteration (1/30, 1/60, 1/120)", \
       F u (ok("implicit_euler/cg") ? $4 : 1/0):6 w lp pt 11 ps 1.3 lc rgb "#d62728" t "implicit Euler, Newton", \
       F u (ok("local_global") ? $4 : 1/0):6 w lp pt 13 ps 1.3 lc rgb "#e377c2" t "local/global, 10 iterations", \
       F u (okp("xpbd/") ? $4 : 1/0):6 w lp pt 15 ps 1.3 lc rgb "#8c564b" t "XPBD, 10 iterations (4, 16, 64 substeps a frame)", \
       F u (okp("small_steps/") ? $4 : 1/0):6 w lp pt 6 ps 1.3 lc rgb "#17becf" t "small steps (64, 256, 512 substeps a frame)"
}
unset multiplot
unset arrow 1
unset arrow 2
unset arrow 3

# 3. A rigid rotation under implicit Euler: the measured rate against the stiff-limit recurrence.
set output plots.'/ch10_rotation.png'
set terminal pngcairo size 1000,620 enhanced font "Sans,11"
unset logscale
set format x "%g"
set format y "%g"
set yrange [0:1.05]
set xlabel "t [s]"
set ylabel "angular rate w(t) / w0"
set title "Two particles turning at w0 = 10 rad/s on stiff springs (K/m = 1e6 s^{-2}): implicit Euler, measured (points) and predicted (lines)"
set key bottom left font ",10" box opaque
R = data.'/rotation.dat'
plot R index "rk4" u 1:($2/10) w l lw 3 lc rgb "black" t "RK4 at h = 1e-4 s", \
     for [h in "1/30 1/60 1/120"] R index "implicit_euler/exact h = ".h u 1:($3/10) w l lw 2 lc rgb (h eq "1/30" ? "#d62728" : h eq "1/60" ? "#ff7f0e" : "#9467bd") t "predicted, h = ".h, \
     for [h in "1/30 1/60 1/120"] R index "implicit_euler/exact h = ".h u 1:($2/10) w p pt 7 ps 0.6 lc rgb (h eq "1/30" ? "#d62728" : h eq "1/60" ? "#ff7f0e" : "#9467bd") t "implicit Euler, Newton, h = ".h
