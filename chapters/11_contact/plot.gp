# Chapter 11's figures and animations from ch11_contact --report-runs: gnuplot -e "data='DIR'; plots='DIR'" plot.gp

# ---- the incline: the sheet's mean displacement down the slope against the closed form ----
set terminal pngcairo size 900,520 enhanced font "Sans,11"
set output plots.'/ch11_incline.png'
set title "A sheet released on an incline (symplectic Euler, h = 0.5 ms; mu_s = 0.3, mu_k = 0.2)"
set xlabel "t [s]"
set ylabel "mean displacement down the slope [m]"
set key top left
plot data.'/incline.dat' index 1 using 1:2 with points pt 7 ps 0.8 lc rgb "#c0392b" title "30 degrees (tan = 1.92 mu_s): simulated", \
     '' index 1 using 1:3 with lines lw 2 lc rgb "#2c3e50" title "g (sin - mu_k cos) t^2 / 2", \
     '' index 0 using 1:2 with points pt 5 ps 0.8 lc rgb "#2980b9" title "15.1 degrees (tan = 0.9 mu_s): simulated, at rest"

# ---- the drape: kinetic energy over its peak, every family ----
set output plots.'/ch11_sphere.png'
set title "A 10 x 10 sheet dropped onto a sphere: kinetic energy / its peak (D = 0.1 N s/m)"
set ylabel "kinetic energy / peak"
set logscale y
set format y "10^{%L}"
set yrange [1e-16:2]
set key bottom left font ",9"
names = "symplectic_euler rk4 implicit_euler_(one_iteration) implicit_euler_(Newton) sdirk2 local_global xpbd"
plot for [k = 0:6] data.'/sphere_energy.dat' index k using 1:2 with lines lw 2 title word(names, k + 1) noenhanced
unset logscale y
set format y "%g"
set yrange [*:*]

# ---- the fold: the strip seen from the side at four times (31 frames over T = 1 s) ----
set output plots.'/ch11_fold.png'
set title "A 30 x 100 strip folding onto itself (1 cm spacing and thickness), seen along x"
set xlabel "y [m]"
set ylabel "z [m]"
set size ratio -1
set key top right
set xtics 0.1
plot for [k = 0:30:10] data.'/fold_frames.dat' index k using 4:5 with points pt 7 ps 0.25 \
     title sprintf("t = %.2f s", k / 30.0)
set size noratio

# ---- one animation per scene: the mesh at every kept frame ----
reset
unset key
set view 62, 32
set xyplane at 0
set border 4095 lc rgb "#808080"
set xlabel "x [m]"
set ylabel "y [m]"
set zlabel "z [m]" rotate by 90
scenes = "incline sphere fold"
scene_frames = "51 51 31"  # the studies keep 50, 50 and 30 frames after the first
do for [s = 1:3] {
  scene = word(scenes, s)
  frames = word(scene_frames, s) + 0
  file = data.'/'.scene.'_frames.dat'
  set autoscale x  # stats keeps to the ranges set, so clear the last scene's first
  set autoscale y
  set autoscale z

  set terminal gif animate delay 8 loop 0 optimize size 480,420 font "Sans,9"
  set output plots.'/ch11_'.scene.'.gif'
  # Every column's extent first: stats of one column keeps to the x range, so no range is set before the last.
  stats file using 3 nooutput
  x0 = STATS_min; x1 = STATS_max
  stats file using 4 nooutput
  y0 = STATS_min; y1 = STATS_max
  stats file using 5 nooutput
  z0 = STATS_min; z1 = STATS_max
  set xrange [x0 - 0.05:x1 + 0.05]
  set yrange [y0 - 0.05:y1 + 0.05]
  set zrange [(z0 < 0 ? z0 - 0.05 : 0):z1 + 0.05]
  do for [k = 0:frames - 1] {
    set title sprintf("%s, frame %d of %d", scene, k, frames - 1)
    splot file index k using 3:4:5 with lines lc rgb "#2c3e50"
  }
  set output
}
