# Chapter 12 figures: the cantilever strip's rest shapes against the heavy elastica, and the tip deflection's
# convergence with the spacing. Called as: gnuplot -e "data='DIR'; plots='DIR'" plot.gp
set terminal pngcairo size 1000,650 enhanced font "Sans,12"

# 1. Shapes at lambda = 1, 8, 40 (index 4k: elastica, 4k+1 hinge, 4k+2 quadratic, 4k+3 flexion springs).
set output plots.'/ch12_shapes.png'
set title "Cantilever strips at rest, L/20, against the heavy elastica (lambda = (L/c)^3)"
set xlabel "x / L"
set ylabel "z / L"
set size ratio -1
set xrange [0:1.05]
set yrange [-1:0.05]
set grid
set key outside right top font ",10"
F = data.'/shapes.dat'
# The labels go before the one plot command: a replot would write a second page that viewers do not show.
set label 1 "lambda = 1" at 0.80, -0.07
set label 2 "lambda = 8" at 0.66, -0.40
set label 3 "lambda = 40" at 0.04, -0.75
# Each flexion strip's tip, by its lambda.
set label 4 "1" at 0.57, -0.73 tc rgb "#d62728" font ",10"
set label 5 "8" at 0.53, -0.77 tc rgb "#d62728" font ",10"
set label 6 "40" at 0.425, -0.82 tc rgb "#d62728" font ",10"
plot for [k=0:2] F index 4*k u 1:2 w l lw 2 lc rgb "#333333" t (k == 0 ? "elastica" : ""), \
     for [k=0:2] F index 4*k+1 u 1:2 w p pt 7 ps 0.8 lc rgb "#1f77b4" t (k == 0 ? "hinge" : ""), \
     for [k=0:2] F index 4*k+2 u 1:2 w p pt 6 ps 1.2 lc rgb "#2ca02c" t (k == 0 ? "quadratic" : ""), \
     for [k=0:2] F index 4*k+3 u 1:2 w lp pt 4 ps 0.8 dt 2 lc rgb "#d62728" t (k == 0 ? "flexion springs" : "")
unset label
set size noratio

# 2. Convergence at lambda = 8.
set output plots.'/ch12_convergence.png'
set title "Tip deflection against the heavy elastica, lambda = 8, as the spacing halves"
set xlabel "spacing d / L"
set ylabel "|relative error of the tip deflection|"
set logscale xy
set format x "10^{%L}"
set format y "10^{%L}"
set autoscale
set key inside right bottom font ",11" box opaque
G = data.'/convergence.dat'
plot G u 2:3 w lp pt 7 lw 2 lc rgb "#1f77b4" t "hinge", \
     G u 2:5 w lp pt 6 lw 2 lc rgb "#2ca02c" t "quadratic", \
     G u 2:7 w lp pt 4 lw 2 lc rgb "#d62728" t "flexion springs (K from B at 20 /m)", \
     G u 2:(0.25*($2*20)**2*0.002) w l dt 2 lc rgb "#888888" t "slope 2"

# 3. The standard's reading on the four fabrics: each strip at the overhang where its tip chord reaches 41.5 degrees
# (points), its elastica at the same lambda (line), and the standard's 41.5 degree line through the clamp.
set output plots.'/ch12_fabrics.png'
set title "Four fabrics at the overhang of the 41.5 degree reading: hinge strips at L/20 against the heavy elastica"
set xlabel "x [cm]"
set ylabel "z [cm]"
unset logscale
set format x "%g"
set format y "%g"
set size ratio -1
set xrange [0:5.5]
set yrange [-4.5:0.3]
set key inside left bottom font ",10" box opaque
H = data.'/fabrics.dat'
colors = "#1f77b4 #2ca02c #ff7f0e #d62728"
plot -tan(41.5*pi/180)*x w l dt 2 lc rgb "#888888" t "41.5 degrees below the clamp", \
     NaN w l lw 2 lc rgb "#333333" t "heavy elastica (line)", \
     for [k=0:3] H index 2*k u 1:2 w l lw 2 lc rgb word(colors, k+1) notitle, \
     for [k=0:3] H index 2*k+1 u 1:2 w p pt 7 ps 0.9 lc rgb word(colors, k+1) t columnheader(1)
