# Chapter 1 figures: force against length per family, energy of a uniformly stretched sheet, the spring mesh.
# Called as: gnuplot -e "data='DIR'; plots='DIR'" plot.gp
set terminal pngcairo size 900,600 enhanced font "Sans,12"
set grid
set key top right

# K, d and the grid size are read back from the data, so the titles stay true for any --K, --spacing, --grid.
stats data.'/force_extension.dat' index 0 using 2 nooutput
d = STATS_max
stats data.'/force_extension.dat' index 0 using 5 nooutput
K = STATS_max / d
stats data.'/springs.dat' index 0 using 1:2 nooutput
M = int(STATS_max_x / d + 0.5) + 1
N = int(STATS_max_y / d + 0.5) + 1

set output plots.'/ch01_force_extension.png'
set title sprintf("Force of one spring of each family, K (L_0 - l), K = %g N/m", K)
set xlabel "spring length l [m]"
set ylabel "force on p along u = (x_p - x_q)/l [N]"
set xzeroaxis lt -1 lw 1
set label 1 "force > 0: compressed (l < L_0), pushes p and q apart" at graph 0.97, graph 0.94 right
set label 2 "force < 0: stretched (l > L_0), pulls them together" at graph 0.97, graph 0.88 right
set key bottom left
plot data.'/force_extension.dat' index 0 using 3:5 with lines lw 2 lc rgb "#1f77b4" \
       title sprintf("structural, L_0 = d = %g m", d), \
     ''                          index 1 using 3:5 with lines lw 2 lc rgb "#2ca02c" \
       title sprintf("shear, L_0 = d √2 = %.3g m", d * sqrt(2)), \
     ''                          index 2 using 3:5 with lines lw 2 lc rgb "#ff7f0e" \
       title sprintf("flexion, L_0 = 2d = %g m", 2 * d)
unset label 1
unset label 2
unset xzeroaxis

set output plots.'/ch01_stretch_energy.png'
set title sprintf("Spring energy of the %d x %d sheet stretched uniformly by s (K = %g N/m, d = %g m)", M, N, K, d)
set xlabel "stretch factor s (every spring s L_0 long)"
set ylabel "spring energy [J]"
set key top center
plot data.'/stretch_energy.dat' using 1:2 with lines lw 2 lc rgb "#1f77b4" title "structural", \
     '' using 1:3 with lines lw 2 lc rgb "#2ca02c" title "shear", \
     '' using 1:4 with lines lw 2 lc rgb "#ff7f0e" title "flexion", \
     '' using 1:5 with lines lw 3 lc rgb "black" title "total (model)", \
     '' every 5 using 1:6 with points pt 6 ps 1.5 lc rgb "red" title "closed form ½ K (s-1)^2 Σ L_0^2"

# The mesh: a corner of the cloth, large enough to show every kind of spring, with its particles as dots.
set output plots.'/ch01_springs_mesh.png'
set terminal pngcairo size 1500,560 enhanced font "Sans,12"
corner = 7
set multiplot layout 1,3 title sprintf("The three spring families: the corner 0 ≤ i, j ≤ %d of the %d x %d cloth (d = %g m)", corner, M, N, d)
unset key
unset grid
set size ratio -1
set xrange [-0.4 * d : (corner + 0.4) * d]
set yrange [-0.4 * d : (corner + 0.4) * d]
set xlabel "x [m]"
set ylabel "y [m]"
set title "structural: (i,j)-(i+1,j), (i,j)-(i,j+1)"
plot data.'/springs.dat' index 0 with lines lw 2 lc rgb "#1f77b4", \
     ''                  index 0 with points pt 7 ps 0.8 lc rgb "black"
set title "shear: both diagonals of every cell"
plot data.'/springs.dat' index 1 with lines lw 2 lc rgb "#2ca02c", \
     ''                  index 0 with points pt 7 ps 0.8 lc rgb "black"
set title "flexion: (i,j)-(i+2,j), (i,j)-(i,j+2), drawn as arcs"
plot data.'/springs.dat' index 2 with lines lw 2 lc rgb "#ff7f0e", \
     ''                  index 0 with points pt 7 ps 0.8 lc rgb "black"
unset multiplot
