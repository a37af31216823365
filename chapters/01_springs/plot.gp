# Chapter 1 figures: force against extension per family, energy of a uniformly stretched sheet, the spring mesh.
# Called as: gnuplot -e "data='DIR'; plots='DIR'" plot.gp
set terminal pngcairo size 900,600 enhanced font "Sans,12"
set grid
set key top right

set output plots.'/ch01_force_extension.png'
set title "Force along the spring, K (L_0 - l), K = 50 N/m"
set xlabel "length l [m]"
set ylabel "force on p along u [N]"
plot data.'/force_extension.dat' index 0 using 3:5 with lines lw 2 lc rgb "#1f77b4" title "structural, L_0 = d", \
     ''                          index 1 using 3:5 with lines lw 2 lc rgb "#2ca02c" title "shear, L_0 = d sqrt 2", \
     ''                          index 2 using 3:5 with lines lw 2 lc rgb "#ff7f0e" title "flexion, L_0 = 2d"

set output plots.'/ch01_stretch_energy.png'
set title "Spring energy of the 20 x 20 sheet stretched uniformly by s (K = 50 N/m)"
set xlabel "stretch factor s"
set ylabel "spring energy [J]"
set key top center
plot data.'/stretch_energy.dat' using 1:2 with lines lw 2 lc rgb "#1f77b4" title "structural", \
     '' using 1:3 with lines lw 2 lc rgb "#2ca02c" title "shear", \
     '' using 1:4 with lines lw 2 lc rgb "#ff7f0e" title "flexion", \
     '' using 1:5 with lines lw 3 lc rgb "black" title "total (model)", \
     '' every 5 using 1:6 with points pt 6 ps 1.5 lc rgb "red" title "closed form 1/2 K (s-1)^2 sum L_0^2"

set output plots.'/ch01_springs_mesh.png'
set terminal pngcairo size 1500,520 enhanced font "Sans,12"
set multiplot layout 1,3 title "The three spring families of the 20 x 20 cloth"
unset key
set size ratio -1
set xlabel "x [m]"
set ylabel "y [m]"
set title "structural"
plot data.'/springs.dat' index 0 with lines lc rgb "#1f77b4"
set title "shear"
plot data.'/springs.dat' index 1 with lines lc rgb "#2ca02c"
set title "flexion"
plot data.'/springs.dat' index 2 with lines lc rgb "#ff7f0e"
unset multiplot
