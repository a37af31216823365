# Chapter 7 figures: stability regions from the tableaus, the cloth's spectrum h*lambda over them, and the
# measured against the predicted largest stable step h_max. Called as: gnuplot -e "data='DIR'; plots='DIR'" plot.gp
set terminal pngcairo size 900,800 enhanced font "Sans,12"
R = data.'/regions.dat'

# Contours |R(z)| = 1 of each method, into datablocks (index: 0 euler .. 5 rule38, 6 implicit, 7 symplectic).
set contour base
set cntrparam levels discrete 1.0
unset surface
set view map
set table $Ceuler
splot R index 0 using 1:2:3 with lines
set table $Cheun
splot R index 1 using 1:2:3 with lines
set table $Ckutta3
splot R index 3 using 1:2:3 with lines
set table $Crk4
splot R index 4 using 1:2:3 with lines
set table $Cimplicit
splot R index 6 using 1:2:3 with lines
set table $Csymplectic
splot R index 7 using 1:2:3 with lines
unset table
unset contour
set surface

set grid
set size ratio -1
set xlabel "Re z = Re(h {/Symbol l})"
set ylabel "Im z = Im(h {/Symbol l})"
set key outside bottom center horizontal maxrows 3

set output plots.'/ch07_regions.png'
set title "Stability regions |R(z)| <= 1, R computed from each Butcher tableau"
set xrange [-4:2.5]
set yrange [-3.5:3.5]
plot $Ceuler w l lw 2 lc rgb "#d62728" t "explicit Euler (inside)", \
     $Cheun w l lw 2 dt 5 lc rgb "#ff7f0e" t "Heun = midpoint (inside)", \
     $Ckutta3 w l lw 2 dt 6 lc rgb "#9467bd" t "Kutta's third order (inside)", \
     $Crk4 w l lw 2 dt 2 lc rgb "#1f77b4" t "RK4 = 3/8 rule (inside)", \
     $Cimplicit w l lw 2 dt 3 lc rgb "black" t "implicit Euler (stable OUTSIDE the circle)", \
     $Csymplectic w l lw 2 dt 4 lc rgb "#2ca02c" t "symplectic Euler, conjugate-pair modes (inside)"

set output plots.'/ch07_spectrum.png'
set terminal pngcairo size 1200,600 enhanced font "Sans,11"
set size noratio
set multiplot layout 1,3 title "h{/Symbol l} of the linearised cloth, h = 0.01 s, over the stability regions (K in N/m, D in N s/m)"
# One key for the three panels, below them; every panel keeps the same margins so that they line up.
set bmargin at screen 0.26
set tmargin at screen 0.88
# The region boundaries are drawn thin and half transparent, and the eigenvalues over them: undamped, every
# eigenvalue lies on the imaginary axis, which is also part of symplectic Euler's boundary. Sagged eigenvalues
# are small filled dots drawn over the rest-state ones, large open circles, so that both show where they coincide.
do for [c in "K50_D0 K200_D0 K200_D20"] {
  if (c eq "K200_D20") { set xrange [-3:0.3]; set yrange [-1.7:1.7] } else { set xrange [-0.12:0.12]; set yrange [-0.6:0.6] }
  if (c eq "K50_D0") { set key at screen 0.5, 0.09 center center horizontal maxrows 2 font ",10" box opaque width 2 } else { unset key }
  K = (c eq "K50_D0") ? "50" : "200"
  D = (c eq "K200_D20") ? "20" : "0"
  set title "K = ".K.", D = ".D
  plot $Ceuler w l lw 1.5 lc rgb "#60d62728" t "explicit Euler", \
       $Crk4 w l lw 1.5 dt 2 lc rgb "#601f77b4" t "RK4", \
       $Csymplectic w l lw 1.5 dt 4 lc rgb "#602ca02c" t "symplectic Euler", \
       $Cimplicit w l lw 1.5 dt 3 lc rgb "#60000000" t "implicit Euler boundary", \
       data.'/spectrum_rest_'.c.'.dat' u 1:2 w p pt 6 ps 1.3 lw 1.5 lc rgb "#444444" t "h{/Symbol l}, rest state", \
       data.'/spectrum_sagged_'.c.'.dat' u 1:2 w p pt 7 ps 0.6 lc rgb "#c51b7d" t "h{/Symbol l}, sagged equilibrium"
}
unset multiplot
set bmargin
set tmargin

set output plots.'/ch07_hmax.png'
set terminal pngcairo size 1200,760 enhanced font "Sans,11"
set size noratio
set logscale xy
set format x "10^{%L}"
set format y "10^{%L}"
set xrange [8:1.3e5]
set yrange [5e-5:0.4]
set xlabel "spring stiffness K [N/m]"
set ylabel "largest stable step h_{max} [s]"
set key outside bottom center horizontal maxrows 3 font ",10"
P = data.'/predicted_rest.dat'
S = data.'/predicted.dat'
M = data.'/measured.dat'
sel(m, d) = (strcol(3) eq m && $2 == d)
mid(lo, hi) = (lo > 0 && hi > 0) ? sqrt(lo * hi) : (lo > 0 ? lo : 1/0)
array meth[4] = ["explicit_euler", "symplectic_euler", "heun", "rk4"]
array label[4] = ["explicit Euler", "symplectic Euler", "Heun", "RK4"]
array col[4] = ["#d62728", "#2ca02c", "#ff7f0e", "#1f77b4"]
set multiplot layout 1,2 title "h_{max}: predicted (lines: rest state; squares: six largest sagged eigenvalues) and measured over 2 s (points, bracket)"
do for [Dv in "0 20"] {
  d = real(Dv)
  set title "D = ".Dv." N s/m"
  plot for [k=1:4] P u (sel(meth[k], d) ? $1 : 1/0):($4 > 0.01 * $5 ? $4 : 1/0) w l lw 2 lc rgb col[k] t label[k]." predicted (rest)", \
       for [k=1:4] S u (sel(meth[k], d) ? $1 : 1/0):($6 > 0.01 * $5 ? $6 : 1/0) w p pt 4 ps 1.3 lc rgb col[k] notitle, \
       for [k=1:3:2] P u (sel(meth[k], d) ? $1 : 1/0):5 w l dt 3 lw 2 lc rgb col[k] t label[k].": 2-s energy doubling (rest)", \
       for [k=1:4] M u (sel(meth[k], d) ? $1 : 1/0):(mid($4, $5)):($4 > 0 ? $4 : 1/0):($5 > 0 ? $5 : $4) w yerrorbars pt 7 ps 1.3 lc rgb col[k] t label[k]." measured"
}
unset multiplot

# Chapter 9's diagonally implicit methods (regions.dat index 8 on, computed on a wider grid): each is stable
# everywhere outside the closed curve (or right of the line) drawn, so the whole left half-plane is stable.
reset
set terminal pngcairo size 900,800 enhanced font "Sans,12"
set contour base
set cntrparam levels discrete 1.0
unset surface
set view map
set table $Cmidpoint
splot R index 8 using 1:2:3 with lines
set table $Csdirk2
splot R index 10 using 1:2:3 with lines
set table $Csdirk3
splot R index 11 using 1:2:3 with lines
set table $Ctrbdf2
splot R index 12 using 1:2:3 with lines
unset table
unset contour
set surface
set grid
set size ratio -1
set xlabel "Re z = Re(h {/Symbol l})"
set ylabel "Im z = Im(h {/Symbol l})"
set key outside bottom center horizontal maxrows 2
set output plots.'/ch07_regions_implicit.png'
set title "Implicit methods (Chapter 9): |R(z)| = 1 from each tableau; stable outside each curve"
set xrange [-4:10]
set yrange [-7:7]
plot $Cmidpoint w l lw 2 lc rgb "#1f77b4" t "implicit midpoint = trapezoid: Re z = 0", \
     $Csdirk2 w l lw 2 lc rgb "#2ca02c" t "SDIRK2", \
     $Csdirk3 w l lw 2 lc rgb "#9467bd" t "SDIRK3", \
     $Ctrbdf2 w l lw 2 dt 2 lc rgb "#8c564b" t "TR-BDF2"
