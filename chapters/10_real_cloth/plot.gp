# Chapter 10 figures: error at T against CPU time for every method on the stiff fabric, the map of the cheapest
# method over resolution and stiffness, and the fabric falling. Called as: gnuplot -e "data='DIR'; plots='DIR'" plot.gp
set terminal pngcairo size 1000,700 enhanced font "Sans,12"

# 1. Cost against accuracy on the practitioner's fabric (20 x 20, K = 1e5, T = 0.5 s).
set output plots.'/ch10_cost_accuracy.png'
set title "Fabric 20 x 20, m = 6.25e-4 kg, K = 1e5 N/m, D = 0.01: error at T = 0.5 s against CPU time"
set logscale xy
set format x "10^{%L}"
set format y "10^{%L}"
set xlabel "CPU time to T [s]"
set ylabel "largest position error at T [m]"
set grid
set key inside left bottom font ",10" box opaque
set yrange [1e-9:10]
set arrow 1 from graph 0, first 1e-2 to graph 1, first 1e-2 nohead dt 2 lc rgb "#888888"
set arrow 2 from graph 0, first 1e-3 to graph 1, first 1e-3 nohead dt 2 lc rgb "#888888"
set label 1 "1 cm" at graph 0.01, first 1.5e-2
set label 2 "1 mm" at graph 0.01, first 1.5e-3
# The size of the motion: the rest state's distance from the reference at T. An error below it at a level above it
# (1 cm here) is met by standing still, so the line is drawn beside the levels.
stats data.'/displacement_T0.5.md' u 1 nooutput
motion = STATS_min
set arrow 3 from graph 0, first motion to graph 1, first motion nohead lw 2 lc rgb "#444444"
set label 3 sprintf("the motion: rest state %.3g m from the reference", motion) at graph 0.62, first 0.45 * motion
F = data.'/curves_practitioner_T0.5.dat'
plot F index 0 u 4:(strcol(11) eq "ok" ? $5 : 1/0) w lp pt 7 lw 2 lc rgb "#2ca02c" t "symplectic Euler", \
     F index 1 u 4:(strcol(11) eq "ok" ? $5 : 1/0) w lp pt 5 lw 2 lc rgb "#1f77b4" t "RK4", \
     F index 2 u 4:(strcol(11) eq "ok" ? $5 : 1/0) w lp pt 9 lw 2 lc rgb "#d62728" t "implicit Euler, Newton, direct", \
     F index 3 u 4:(strcol(11) eq "ok" ? $5 : 1/0) w lp pt 11 lw 2 lc rgb "#ff7f0e" t "implicit Euler, 1 iteration, direct", \
     F index 4 u 4:(strcol(11) eq "ok" ? $5 : 1/0) w lp pt 13 lw 2 lc rgb "#9467bd" t "implicit Euler, 1 iteration, CG", \
     F index 5 u 4:(strcol(11) eq "ok" ? $5 : 1/0) w lp pt 15 lw 2 lc rgb "#8c564b" t "implicit Euler, Newton, CG", \
     F index 6 u 4:(strcol(11) eq "ok" ? $5 : 1/0) w lp pt 4 lw 2 lc rgb "#e377c2" t "local/global, 10 iterations", \
     F index 7 u 4:(strcol(11) eq "ok" ? $5 : 1/0) w lp pt 6 lw 2 lc rgb "#17becf" t "local/global, 50 iterations"
unset arrow 1
unset arrow 2
unset arrow 3
unset label 1
unset label 2
unset label 3

# 2. The map: the cheapest method per (particles per side, K), at 1 cm and 1 mm, with its predicted CPU time; a
#    level the rest state already meets is marked "met by standing still" in grey, not as a winner.
set output plots.'/ch10_map.png'
set terminal pngcairo size 1400,620 enhanced font "Sans,11"
set multiplot layout 1,2 title "The four-corner sheet: cheapest method to reach the accuracy at T = 0.5 s\n(20 x 20 measured, larger grids predicted by the cost model; at the left, in grey, how far the sheet has moved by T)"
unset grid
set logscale xy
set format x "%g"
set format y "10^{%L}"
set xrange [7:240]
set yrange [3e2:3e6]
set xtics (20, 39, 77, 153)
set xlabel "particles per side (the same 0.95 m square)"
set ylabel "tensile spring stiffness K [N/m]"
unset key
W = data.'/map_winners.dat'
# Colour by method name.
color(s) = (s eq "symplectic_euler") ? 0x2ca02c : (s eq "rk4") ? 0x1f77b4 : (s eq "implicit_euler/one/cg") ? 0x9467bd : \
           (s eq "implicit_euler/one/exact") ? 0xff7f0e : (s eq "implicit_euler/exact") ? 0xd62728 : \
           (s eq "local_global") ? 0xe377c2 : (s eq "local_global/50it") ? 0x17becf : 0x8c564b
short(s) = (s eq "symplectic_euler") ? "sympl. Euler" : (s eq "rk4") ? "RK4" : (s eq "implicit_euler/one/cg") ? "IE 1 it. CG" : \
           (s eq "implicit_euler/one/exact") ? "IE 1 it. direct" : (s eq "implicit_euler/exact") ? "IE Newton direct" : \
           (s eq "local_global") ? "LG 10" : (s eq "local_global/50it") ? "LG 50" : "IE Newton CG"
do for [tol in "0.01 0.001"] {
  set title (tol eq "0.01" ? "largest position error 1 cm" : "largest position error 1 mm")
  # A level the rest state already meets (winner code -1) is nobody's win: marked in grey italics, not as a method.
  plot W u ($1 == real(tol) && $4 >= 0 ? $3 : 1/0):2:(sprintf("%s\n%.2g s", short(strcol(5)), $6)):(color(strcol(5))) \
         w labels font ",11:Bold" tc rgb variable, \
       W u ($1 == real(tol) && $4 < 0 ? $3 : 1/0):2:("met by\nstanding still") w labels font ",10:Italic" tc rgb 0x888888, \
       W u ($1 == real(tol) && $3 == 20 ? 10 : 1/0):2:(sprintf("moves\n%.2g m", $8)) w labels font ",10:Italic" tc rgb 0x888888
}
unset multiplot

# 3. The fabric (preset, 39 x 39) at t = 0, 0.1, ..., 0.5 s.
set output plots.'/ch10_fabric.png'
set terminal pngcairo size 1400,800 enhanced font "Sans,11"
unset logscale
set format x "%g"
set format y "%g"
set format z "%g"
set xtics auto
set xrange [0:0.95]
set yrange [0:0.95]
set zrange [-0.25:0.02]
set xlabel "x [m]"
set ylabel "y [m]"
unset zlabel
set view 62, 30
set hidden3d
set multiplot layout 2,3 title "The cotton preset (39 x 39, 0.25 kg/m^2, C = 2e4 N/m) hanging from its corners, RK4"
do for [k=0:5] {
  set title sprintf("t = %.1f s", 0.1 * k)
  splot data.'/fabric_frames.dat' index k u 3:4:5 w l lc rgb "#1f77b4" notitle
}
unset multiplot
