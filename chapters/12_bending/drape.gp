# Chapter 12's drape figure: the curtain's RMS curvature over time, and its middle column seen from the side at
# 0.5 s and 2 s, with and without bending. Called as: gnuplot -e "data='DIR'; plots='DIR'" drape.gp
set terminal pngcairo size 1100,500 enhanced font "Sans,11"
set output plots.'/ch12_drape.png'
set multiplot layout 1,2
set grid
titles = "'no bending' 'flexion springs (Ch. 10)' 'quadratic, B = 5e-6' 'hinge, B = 6.1e-5' 'quadratic, B = 3.9e-2'"
colors = "#7f7f7f #d62728 #9467bd #1f77b4 #2ca02c"
set title "RMS curvature of the curtain"
set xlabel "t [s]"
set ylabel "kappa_{rms} [1/m]"
set key top right font ",9"
plot for [k=1:5] data.'/drape_curvature.dat' u 1:(column(k+1)) w l lw 2 lc rgb word(colors, k) t word(titles, k)
set title "Middle column from the side: 0.5 s (dashed) and 2 s"
set xlabel "y [m]"
set ylabel "z [m]"
set size ratio -1
unset key
unset xlabel
unset ylabel
unset zlabel
plot for [k=0:4] data.'/drape_profile.dat' index 2*k u 1:2 w lp pt 7 ps 0.4 dt 2 lc rgb word(colors, k+1), \
     for [k=0:4] data.'/drape_profile.dat' index 2*k+1 u 1:2 w lp pt 7 ps 0.5 lw 2 lc rgb word(colors, k+1)
unset multiplot

# The sheet on the sphere of Chapter 11 at rest, without and with the hinge energy: its final.dat at t = 20 s from
# the two runs committed in data/sphere_drape/ (the commands in its provenance.txt), the sphere as a wire frame.
set terminal pngcairo size 1200,560 enhanced font "Sans,11"
set output plots.'/ch12_sphere.png'
set multiplot layout 1,2
set view 62, 28, 1.7
set view equal xyz
set xyplane at 0
unset border
unset tics
unset grid
unset key
unset xlabel
unset ylabel
unset zlabel
set size noratio
set parametric
set isosamples 13, 9
set urange [0:2*pi]
set vrange [-pi/2:pi/2]
R = 0.3; cx = 0.475; cy = 0.475; cz = 0.3
set xrange [-0.05:1.0]
set yrange [-0.05:1.0]
set zrange [0:0.65]
files = "data/sphere_drape/springs/final.dat data/sphere_drape/hinge/final.dat"
do for [k=1:2] {
  F = word(files, k)
  set title word("'the springs of Chapter 11 alone' 'with the hinge energy, B = 6.87e-5 N m (heavy, row 4)'", k)
  splot cx + R*cos(u)*cos(v), cy + R*sin(u)*cos(v), cz + R*sin(v) w l lc rgb "#cccccc", \
        for [i=0:19] F every ::(20*i)::(20*i+19) u 3:4:5 w l lw 1.5 lc rgb "#1f77b4", \
        for [j=0:19] F every 20::j u 3:4:5 w l lw 1.5 lc rgb "#1f77b4"
}
unset multiplot
