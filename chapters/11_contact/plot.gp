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
# The key beside the graph: inside, the standing strip runs through any corner. Its markers are drawn larger than
# the particles' so that their colours can be read.
set key at graph 1.05, 1 left top Left reverse
set xtics 0.1
plot for [k = 0:30:10] data.'/fold_frames.dat' index k using 4:5 with points pt 7 ps 0.25 lt (k / 10 + 1) notitle, \
     for [k = 0:30:10] keyentry with points pt 7 ps 1 lt (k / 10 + 1) title sprintf("t = %.2f s", k / 30.0)
set size noratio

# ---- one animation per scene: the cloth and what it touches, at every kept frame ----
# The obstacles are drawn from <scene>_geometry.txt, the lines run.txt records for the same scene (incline_angle =
# deg; ground_z = z; sphere = cx cy cz r), so that the figures show the geometry the run used, not a copy of it.
reset
unset key
unset colorbox
set view 62, 32, 1.15
set view equal xyz  # one scale on every axis: the sphere looks round and the incline keeps its angle
set xyplane relative 0
set border 4095 lc rgb "#a0a0a0"
set xlabel "x [m]"
set ylabel "y [m]" offset 2, -0.5
set zlabel "z [m]" rotate by 90
set tics textcolor rgb "#606060"
# The cloth red, the obstacles in muted greys. With hidden3d each surface's underside takes the next linetype: the
# cloth's blue where the view shows it, the sphere's the same as its outside.
set linetype 11 lc rgb "#c0392b"
underside_colour = "#1f618d"
set linetype 12 lc rgb underside_colour
set linetype 13 lc rgb "#7f98ad"
set linetype 14 lc rgb "#7f98ad"
plane_colour = "#d9d4c7"
# A GIF has 256 colours; pm3d's palette would take most of them and the plane would come out in the nearest grey.
set palette maxcolors 8
# The sphere's mesh: 24 meridians by 12 parallels keep its outline round at the animation's size; 48 by 24
# looks the same there and costs the script 15 % more time.
sphere_meridians = 24
sphere_parallels = 12
margin = 0.05

scenes = "incline sphere fold"
do for [s = 1:3] {
  scene = word(scenes, s)
  file = data.'/'.scene.'_frames.dat'
  geometry = data.'/'.scene.'_geometry.txt'
  set autoscale x; set autoscale y; set autoscale z  # stats keeps to the ranges set, so clear the last scene's first
  # The geometry file's key = value lines; a scene without an obstacle leaves its variable NaN or "".
  ground_z = NaN; incline_angle = NaN; sphere = ""
  set datafile separator "="
  stats geometry using (key = word(strcol(1), 1), \
                        key eq "ground_z" ? (ground_z = real(strcol(2))) : \
                        key eq "incline_angle" ? (incline_angle = real(strcol(2))) : \
                        key eq "sphere" ? (sphere = strcol(2)) : 0, 0) nooutput
  set datafile separator whitespace
  # The cloth's extent over all frames; stats of one column keeps to the x range, so no range is set before the last.
  stats file using 3 nooutput
  x0 = STATS_min; x1 = STATS_max; frames = STATS_blocks
  stats file using 4 nooutput
  y0 = STATS_min; y1 = STATS_max
  stats file using 5 nooutput
  z0 = STATS_min; z1 = STATS_max
  stats file using 1 nooutput  # the grid's rows i and columns j
  M = STATS_max + 1
  stats file using 2 nooutput
  N = STATS_max + 1
  title = scene eq "incline" ? sprintf("A %d x %d sheet sliding down the %g-degree incline", M, N, incline_angle) : \
          scene eq "sphere" ? sprintf("A %d x %d sheet dropped onto the sphere", M, N) : \
          sprintf("A %d x %d strip folding on the ground", M, N)
  y0 = y0 - margin; y1 = y1 + margin
  # The plane under the cloth, a rectangle as wide as the cloth's path and a margin, drawn behind everything: the
  # view looks down on its upper side, where the cloth is.
  if (incline_angle == incline_angle) {
    # The plane through the origin with normal (sin, 0, cos), downhill along +x (scenes.cpp): from the cloth's
    # highest to its lowest point along the slope s = x / cos.
    c = cos(incline_angle * pi / 180); t = sin(incline_angle * pi / 180)
    s0 = x0 / c - margin; s1 = x1 / c + margin
    set object 2 polygon from s0 * c, y0, -s0 * t to s1 * c, y0, -s1 * t to s1 * c, y1, -s1 * t \
      to s0 * c, y1, -s0 * t to s0 * c, y0, -s0 * t
    x0 = s0 * c; x1 = s1 * c; z0 = -s1 * t; z1 = z1 + margin
  } else {
    x0 = x0 - margin; x1 = x1 + margin
    set object 2 polygon from x0, y0, ground_z to x1, y0, ground_z to x1, y1, ground_z to x0, y1, ground_z \
      to x0, y0, ground_z
    z0 = ground_z; z1 = z1 + margin
  }
  set object 2 behind fillcolor rgb plane_colour fillstyle solid 1 border lc rgb "#a09a8a"
  # Over the sphere, a square of the cloth's underside colour on the ground, drawn before the plane covers it: the
  # first frame does not show the underside, and an animation written with `optimize` (below) has only the colours
  # of its first frame.
  if (strlen(sphere) > 0) {
    set object 1 polygon from x0 + margin, y0 + margin, ground_z to x0 + 2 * margin, y0 + margin, ground_z \
      to x0 + 2 * margin, y0 + 2 * margin, ground_z to x0 + margin, y0 + margin, ground_z
    set object 1 behind fillcolor rgb underside_colour fillstyle solid 1 noborder
  } else {
    unset object 1
  }
  # The sphere's mesh, once per scene: longitude u, latitude v.
  set print $sphere
  if (strlen(sphere) > 0) {
    cx = word(sphere, 1) + 0; cy = word(sphere, 2) + 0; cz = word(sphere, 3) + 0; r = word(sphere, 4) + 0
    do for [i = 0:sphere_meridians] {
      do for [j = 0:sphere_parallels] {
        u = 2 * pi * i / sphere_meridians; v = pi * j / sphere_parallels - pi / 2
        print sprintf("%g %g %g", cx + r * cos(v) * cos(u), cy + r * cos(v) * sin(u), cz + r * sin(v))
      }
      print ""
    }
    z1 = (cz + r + margin > z1 ? cz + r + margin : z1)
  }
  unset print
  # With one scale on every axis the picture's size follows the x and y ranges: both as long as the longest
  # extent, so that a tall scene (the strip standing) fits too.
  L = x1 - x0 > y1 - y0 ? x1 - x0 : y1 - y0
  L = z1 - z0 > L ? z1 - z0 : L
  set xrange [(x0 + x1 - L) / 2:(x0 + x1 + L) / 2]
  set yrange [(y0 + y1 - L) / 2:(y0 + y1 + L) / 2]
  set zrange [z0:z1]
  tic = L < 0.6 ? 0.1 : 0.2
  set xtics tic offset 0, -0.4; set ytics tic offset 0.6, 0; set ztics tic

  # Over the plane the cloth is a shaded surface, its quadrangles painted far to near. Over the sphere that order
  # fails: it sorts whole quadrangles by their mean depth, and a sheet 5 mm above a sphere of 8 cm quadrangles
  # sorts wrongly wherever they overlap. There both are wireframes with hidden lines removed exactly (hidden3d).
  if (strlen(sphere) > 0) {
    unset pm3d
    set hidden3d front offset 1
  } else {
    unset hidden3d
    set pm3d depthorder lighting primary 0.5 specular 0
  }
  # With `optimize` a frame is stored as its change from the one before, a third to a half of the size; but gnuplot
  # gives each frame the colours it draws, in the order it draws them, and the file keeps the first frame's, so a
  # colour that first appears later shows as another. On the incline and over the sphere (with the underside's
  # square above) every frame draws only the first frame's colours, and the frames come out pixel for pixel as
  # without it. The folding strip's lit shades change from frame to frame: its frames are stored whole.
  if (scene eq "fold") {
    set terminal gif animate delay 8 loop 0 size 480,420 font "Sans,9"
  } else {
    set terminal gif animate optimize delay 8 loop 0 size 480,420 font "Sans,9"
  }
  set output plots.'/ch11_'.scene.'.gif'
  do for [k = 0:frames - 1] {
    set title sprintf("%s: frame %d of %d", title, k, frames - 1)
    if (strlen(sphere) > 0) {
      splot $sphere using 1:2:3 with lines lt 13, file index k using 3:4:5 with lines lt 11
    } else {
      splot file index k using 3:4:5 with pm3d fillcolor linetype 11
    }
  }
  set output

  # The sheet at rest on the sphere, as a still, seen from lower down to show more of the sphere under it.
  if (strlen(sphere) > 0) {
    set view 72, 35
    set terminal pngcairo size 900,640 enhanced font "Sans,11"
    set output plots.'/ch11_drape.png'
    set title sprintf("The %d x %d sheet at rest on the sphere (r = %g m), its last frame", M, N, r)
    splot $sphere using 1:2:3 with lines lt 13 lw 0.8, file index (frames - 1) using 3:4:5 with lines lt 11 lw 1.2
    set output
    set view 62, 32, 1.15
  }
}
