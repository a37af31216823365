# Chapter 12's drape figure: the curtain's RMS curvature over time and its hem at the end, with and without
# bending. Called as: gnuplot -e "data='DIR'; plots='DIR'" drape.gp
set terminal pngcairo size 1100,480 enhanced font "Sans,11"
set output plots.'/ch12_drape.png'
set multiplot layout 1,2
set grid
set key top right font ",9"
titles = "'no bending' 'flexion springs (Ch. 10)' 'hinge, B = 5e-6' 'hinge, B = 6.1e-5' 'quadratic, B = 6.1e-5'"
colors = "#7f7f7f #d62728 #1f77b4 #2ca02c #9467bd"
set title "RMS curvature of the sheet"
set xlabel "t [s]"
set ylabel "kappa_{rms} [1/m]"
plot for [k=1:5] data.'/drape_curvature.dat' u 1:(column(k+1)) w l lw 2 lc rgb word(colors, k) t word(titles, k)
set title "The hem at t = 3 s, seen from below"
set xlabel "x along the hem [m]"
set ylabel "y out of the curtain's plane [m]"
unset key
plot for [k=0:4] data.'/drape_hem.dat' index k u 1:2 w lp pt 7 ps 0.6 lw 2 lc rgb word(colors, k+1)
unset multiplot
