# Chapter 5 figures: the report's Figures 2-7 as strain-coloured meshes, the overview grid, energy and sag against
# time, one animation per run, and the K x D sweep as heat maps.
# Called as: gnuplot -e "data='DIR'; plots='DIR'" plot.gp. Beside the meshes and series the program writes small
# tables that say which block of each mesh file to draw and what the labels say; they are read into arrays first.
stats data.'/parameters.dat' using (h = $1, t_end = $2, sweep_t_end_implicit = $3, nmethods = int($4), nconfigs = int($5), \
                                    ninstants = int($6), e_ref = $7, e_ref_is_e0 = int($8), 0) nooutput
# The energy the ratios are relative to: E(0), the launch's kinetic energy, or for a cloth dropped from rest
# (E(0) = 0) W L, the potential energy its weight loses in falling by its side.
ref_name = e_ref_is_e0 ? "E(0)" : "E_{ref}"
ref_label = e_ref_is_e0 ? sprintf("E(0) = %.3g kJ", e_ref / 1000) : sprintf("E_{ref} = W L = %.3g kJ (E(0) = 0)", e_ref / 1000)
nruns = nmethods * nconfigs
# runs.dat: run name "method" "status" mesh_blocks t_reached xmin xmax ymin ymax zmin zmax (run = m * nconfigs + c)
array run_name[nruns]; array run_method[nruns]; array run_status[nruns]; array run_blocks[nruns]
array run_t_reached[nruns]; array run_box[6 * nruns]  # xmin, xmax, ymin, ymax, zmin, zmax per run
do for [r = 1:nruns] {
  stats data.'/runs.dat' every ::r-1::r-1 using (name = strcol(2), method = strcol(3), status = strcol(4), \
    blocks = int($5), reached = $6, x0 = $7, x1 = $8, y0 = $9, y1 = $10, z0 = $11, z1 = $12, 0) nooutput
  run_name[r] = name; run_method[r] = method; run_status[r] = status; run_blocks[r] = blocks
  run_t_reached[r] = reached
  b = (r - 1) * 6
  run_box[b + 1] = x0; run_box[b + 2] = x1; run_box[b + 3] = y0; run_box[b + 4] = y1; run_box[b + 5] = z0
  run_box[b + 6] = z1
}
# instants.dat: run instant mesh_block "label", row k = (run - 1) * ninstants + instant
array instant_block[nruns * ninstants]; array instant_label[nruns * ninstants]
do for [k = 1:nruns * ninstants] {
  stats data.'/instants.dat' every ::k-1::k-1 using (block = int($3), label = strcol(4), 0) nooutput
  instant_block[k] = block; instant_label[k] = label
}
# cases.dat: case K D log_energy_axis sag_low
array cfg_K[nconfigs]; array cfg_D[nconfigs]; array cfg_logscale[nconfigs]; array cfg_sag_low[nconfigs]
do for [c = 1:nconfigs] {
  stats data.'/cases.dat' every ::c-1::c-1 using (K = $2, D = $3, logscale = int($4), low = $5, 0) nooutput
  cfg_K[c] = K; cfg_D[c] = D; cfg_logscale[c] = logscale; cfg_sag_low[c] = low
}
# figures.dat: figure run "caption"
stats data.'/figures.dat' using 1 nooutput
nfigures = STATS_records
array fig_number[nfigures]; array fig_run[nfigures]; array fig_caption[nfigures]
do for [f = 1:nfigures] {
  stats data.'/figures.dat' every ::f-1::f-1 using (number = int($1), run = int($2), caption = strcol(3), 0) nooutput
  fig_number[f] = number; fig_run[f] = run; fig_caption[f] = caption
}
run_index(m, c) = (m - 1) * nconfigs + c
mesh(r) = data.'/mesh_'.run_name[r].'.dat'
series(r) = data.'/series_'.run_name[r].'.dat'
method_color(m) = m == 1 ? "#d62728" : m == 2 ? "#9467bd" : m == 3 ? "#1f77b4" : "#2ca02c"

# Strain s = (l - L0)/L0 spans -1 (collapsed) to about 100 here, so the colour is asinh(s / 0.05): linear near 0,
# logarithmic beyond; the tics are labelled in strain itself.
sc(s) = asinh(s / 0.05)
set palette defined (sc(-1) "#08306b", sc(-0.1) "#4292c6", 0 "#a0a0a0", sc(0.1) "#fec44f", sc(1) "#ec7014", \
                     sc(10) "#cb181d", sc(100) "#3f007d")
set cbrange [sc(-1):sc(100)]
set cbtics ("-1" sc(-1), "-0.1" sc(-0.1), "0" 0, "0.1" sc(0.1), "1" sc(1), "10" sc(10), "100" sc(100))
set cblabel "strain (l - L_0)/L_0"

# Draws block b of run r's mesh; the spring colour is column 4. x and y share one scale; z, which spans up to
# 25 m under a 1.9 m sheet, gets its own (each title says so; read depths from the z tics).
set xyplane at 0
set view 62, 32
set view equal xy
set ticslevel 0
set xlabel "x [m]" offset 0,-0.5
set ylabel "y [m]" offset 0,-0.5
set zlabel "z [m]" rotate by 90 offset 1,0
set border 4095 lc rgb "#808080"
unset key
# x, y tics every 0.5 m while the run stays near its 1.9 m square, gnuplot's choice once it flies apart.
set_xy_tics(r) = (run_box[(r - 1) * 6 + 2] - run_box[(r - 1) * 6 + 1] > 5 || run_box[(r - 1) * 6 + 4] - run_box[(r - 1) * 6 + 3] > 5) ? \
  "set xtics autofreq; set ytics autofreq" : "set xtics 0.5; set ytics 0.5"

# ---- one sheet per report figure the page shows: the cloth at t = 0.05 T, 0.25 T, 0.5 T, T ----
# The page shows Figures 4, 6 and 7, the three that carry its argument (dampers as a second stability limit for
# explicit Euler and RK4, implicit Euler's smooth loss of energy); the overview shows every run at one instant.
shown_figure(n) = n == 4 || n == 6 || n == 7
set terminal pngcairo size 1300,1000 enhanced font "Sans,11"
do for [f = 1:nfigures] {
  if (!shown_figure(fig_number[f])) { continue }
  r = fig_run[f]
  eval set_xy_tics(r)
  set output sprintf("%s/ch05_figure%d.png", plots, fig_number[f])
  set multiplot layout 2,2 title sprintf("%s\n{/*0.85 %s, h = %g s: structural springs coloured by strain (%s)}\n{/*0.85 x and y drawn to scale, z to its own: read depths from its tics [m]}", \
      fig_caption[f], run_method[r], h, run_status[r]) font ",14"
  do for [i = 1:ninstants] {
    k = (r - 1) * ninstants + i
    set title instant_label[k]
    splot mesh(r) index instant_block[k] using 1:2:3:(sc($4)) with lines lw 1.5 lc palette
  }
  unset multiplot
}

# ---- overview: methods in rows, configurations in columns, the cloth at t = T/2 ----
set terminal pngcairo size 1500,1700 enhanced font "Sans,10"
set output plots.'/ch05_overview.png'
set multiplot layout nmethods, nconfigs title sprintf("All methods at t = %g s, h = %g s (rows: methods; columns: K [N/m], D [N s/m]); springs coloured by strain; x, y to scale, z to its own scale", t_end / 2, h) font ",14"
unset colorbox
do for [m = 1:nmethods] {
  do for [c = 1:nconfigs] {
    r = run_index(m, c)
    k = (r - 1) * ninstants + 3
    eval set_xy_tics(r)
    set title sprintf("{/:Bold %s, K = %g, D = %g}\n%s%s", run_method[r], cfg_K[c], cfg_D[c], run_status[r], \
                      run_t_reached[r] < t_end / 2 ? sprintf("\nshowing its last sane frame, t = %g s", run_t_reached[r]) : "")
    splot mesh(r) index instant_block[k] using 1:2:3:(sc($4)) with lines lw 1 lc palette
  }
}
unset multiplot
set colorbox

# ---- energy and sag against time, one panel per configuration, every method ----
reset  # settings only: the arrays read above stay
set terminal pngcairo size 1500,520 enhanced font "Sans,11"
set grid
set key top left
set output plots.'/ch05_energy.png'
set multiplot layout 1, nconfigs title sprintf("Total energy E(t) / %s, %s, h = %g s (a curve ends where its run diverged)", ref_name, ref_label, h) font ",13"
do for [c = 1:nconfigs] {
  set title sprintf("K = %g N/m, D = %g N s/m", cfg_K[c], cfg_D[c])
  if (cfg_logscale[c]) { set logscale y; set format y "10^{%T}"; set yrange [*:*] } else { unset logscale y; set format y "%g" }
  set xlabel "t [s]"
  set ylabel "E(t) / " . ref_name . (cfg_logscale[c] ? " (log scale)" : "")
  plot for [m = 1:nmethods] series(run_index(m, c)) using 1:3 with lines lw 2 lc rgb method_color(m) title run_method[run_index(m, c)]
}
unset multiplot

unset logscale y
set format y "%g"
set key bottom left Left reverse samplen 1.5
set output plots.'/ch05_sag.png'
set multiplot layout 1, nconfigs title sprintf("Lowest free particle of the cloth, min z, h = %g s (a curve leaving the frame is a run blowing up)", h) font ",13"
do for [c = 1:nconfigs] {
  set title sprintf("K = %g N/m, D = %g N s/m", cfg_K[c], cfg_D[c])
  set xlabel "t [s]"
  set ylabel "lowest z [m]"
  set yrange [1.4 * cfg_sag_low[c]:*]  # room below the curves for the key
  plot for [m = 1:nmethods] series(run_index(m, c)) using 1:4 with lines lw 2 lc rgb method_color(m) title run_method[run_index(m, c)]
}
unset multiplot
set yrange [*:*]

# ---- one small animation per run: the mesh every T/20, then the last sane frame of a diverged run ----
reset
sc(s) = asinh(s / 0.05)
set palette defined (sc(-1) "#08306b", sc(-0.1) "#4292c6", 0 "#a0a0a0", sc(0.1) "#fec44f", sc(1) "#ec7014", \
                     sc(10) "#cb181d", sc(100) "#3f007d")
set cbrange [sc(-1):sc(100)]
unset colorbox
unset key
set view 62, 32
set xyplane at 0
set border 4095 lc rgb "#808080"
# Small frames: no x, y tics (the sheets above carry them), z labelled so the fall reads in metres.
unset xtics
unset ytics
set ztics font ",8"
set zlabel "z [m]" rotate by 90 offset 2,0
# Animations of the damped, stiff configuration only, where the methods part ways; symplectic Euler's is left out
# (its failure is explicit Euler's, the page says why).
animated(r) = strstrt(run_name[r], "K200_D20") > 0 && strstrt(run_name[r], "symplectic") == 0
do for [r = 1:nmethods * nconfigs] {
  if (!animated(r)) { continue }
  set terminal gif animate delay 15 loop 0 optimize size 420,360 font "Sans,9"
  set output sprintf("%s/ch05_%s.gif", plots, run_name[r])
  b = (r - 1) * 6
  set xrange [run_box[b + 1]:run_box[b + 2]]
  set yrange [run_box[b + 3]:run_box[b + 4]]
  set zrange [run_box[b + 5]:run_box[b + 6]]
  last = run_blocks[r] - 1
  do for [k = 0:last] {
    t = (k == last) ? run_t_reached[r] : k * t_end / 20
    set title sprintf("%s, K = %g, D = %g, h = %g s\nt = %.2f s%s", run_method[r], cfg_K[(r - 1) % nconfigs + 1], \
      cfg_D[(r - 1) % nconfigs + 1], h, t, (k == last && run_t_reached[r] < t_end) ? ": ".run_status[r] : "")
    splot mesh(r) index k using 1:2:3:(sc($4)) with lines lc palette
  }
  set output
}

# ---- the sweep: one heat map per method over K x D ----
reset
sweep = data.'/sweep.dat'
Klabels = "10 25 50 100 200 500 1000"
Dlabels = "0 1 5 20"
set xtics () ; do for [i = 1:7] { set xtics add (word(Klabels, i) i - 1) }
set ytics () ; do for [i = 1:4] { set ytics add (word(Dlabels, i) i - 1) }
set xrange [-0.5:6.5]
set yrange [-0.5:3.5]
set xlabel "K [N/m]"
set ylabel "D [N s/m]"
set tics nomirror
unset key
array sweep_title[4] = ["explicit Euler", "symplectic Euler", "RK4", "implicit Euler"]
# Gain: log10 of max_{s <= t} (E(t) - E(s))/E_ref, floored at 1e-8 (a method that never added energy shows 0 there).
gain_colour(g) = log10(g > 1e-8 ? g : 1e-8)
# (The cell texts are written inline: gnuplot 5.4 mislabels `with labels` when the text comes from a user function.)
set palette defined (-8 "#f7fbff", -6 "#c6dbef", -4 "#6baed6", -2 "#fdae6b", 0 "#e6550d", 2 "#7f2704")

set terminal pngcairo size 1400,900 enhanced font "Sans,11"
set output plots.'/ch05_sweep_gain.png'
set multiplot layout 2,2 title sprintf("Energy gain max_{s <= t} (E(t) - E(s))/%s over the K x D sweep, h = %g s, T = %g s (implicit Euler: T = %g s)\n{/*0.8 The exact solution's energy never rises (constant for D = 0, falling for D > 0): any rise is the method's error. Grey: the run diverged or a step failed.}", ref_name, h, t_end, sweep_t_end_implicit) font ",12"
set cbrange [-8:2]
set cbtics ("≤1e-8" -8, "1e-6" -6, "1e-4" -4, "0.01" -2, "1" 0, "100" 2)
unset cblabel
do for [m = 0:3] {
  set title sweep_title[m + 1]
  plot sweep index m using 2:3:(column(6) == 0 ? gain_colour(column(8)) : NaN) with image, \
       '' index m using (column(6) != 0 ? column(2) : NaN):3:(0.5):(0.5) with boxxyerror fs solid 1.0 noborder lc rgb "#909090", \
       '' index m using 2:3:(column(6) != 0 ? sprintf("%s\n%.2f s", strcol(13), column(7)) : column(8) == 0 ? "0" : sprintf("%.1e", column(8))) with labels font ",9"
}
unset multiplot

set output plots.'/ch05_sweep_final.png'
set multiplot layout 2,2 title sprintf("Energy at the end relative to the start, (E(T) - E(0))/%s, h = %g s, T = %g s (implicit Euler: T = %g s)\n{/*0.8 Negative: energy lost (dampers, or the method's numerical damping); positive: energy gained. Grey: diverged or a step failed.}", ref_name, h, t_end, sweep_t_end_implicit) font ",12"
set palette defined (-1 "#08519c", -0.3 "#6baed6", 0 "#f7f7f7", 0.3 "#fc9272", 1 "#a50f15")
set cbrange [-1:1]
set cbtics ("≤ -1" -1, "-0.5" -0.5, "0" 0, "0.5" 0.5, "≥ 1" 1)
unset cblabel
do for [m = 0:3] {
  set title sweep_title[m + 1]
  plot sweep index m using 2:3:(column(6) == 0 ? (column(9) < -1 ? -1 : column(9) > 1 ? 1 : column(9)) : NaN) with image, \
       '' index m using (column(6) != 0 ? column(2) : NaN):3:(0.5):(0.5) with boxxyerror fs solid 1.0 noborder lc rgb "#909090", \
       '' index m using 2:3:(column(6) != 0 ? sprintf("%s\n%.2f s", strcol(13), column(7)) : abs(column(9)) < 0.01 ? sprintf("%.1e", column(9)) : abs(column(9)) >= 10 ? sprintf("%.3g", column(9)) : sprintf("%.2f", column(9))) with labels font ",9"
}
unset multiplot
