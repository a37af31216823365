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
plot for [k=0:4] data.'/drape_profile.dat' index 2*k u 1:2 w lp pt 7 ps 0.4 dt 2 lc rgb word(colors, k+1), \
     for [k=0:4] data.'/drape_profile.dat' index 2*k+1 u 1:2 w lp pt 7 ps 0.5 lw 2 lc rgb word(colors, k+1)
unset multiplot
