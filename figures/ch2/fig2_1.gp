# Figure 2.1: the Delaunay triangulation DT_n of 15 points (left) and the Delaunay cavity
# C(DT_n, p_{n+1}) (right): the triangles whose circumcircles contain p_{n+1}, shaded, with
# those circles dashed. Data (sec2_1_kernel): fig2_1_dtn.dat (triangles), fig2_1_points.dat,
# fig2_1_p.dat (p_{n+1}), fig2_1_cavity.dat (cavity boundary), fig2_1_circles.dat (x y r).
if (!exists("datadir")) datadir = "."
if (!exists("outdir")) outdir = "."
set size ratio -1
unset key
unset border
unset tics
set xrange [-0.08:1.08]
set yrange [-0.08:1.08]
do for [term in "png svg"] {
  if (term eq "png") {
    set terminal pngcairo size 1300,680 enhanced font "Sans,14"
    set output outdir."/fig2_1.png"
  } else {
    set terminal svg size 1300,680 enhanced font "Sans,14" background rgb "white"
    set output outdir."/fig2_1.svg"
  }
  set multiplot layout 1,2
  set title "DT_n: the Delaunay triangulation of n = 15 points"
  plot datadir."/fig2_1_dtn.dat" with lines lw 1.5 lc rgb "#303030", \
       datadir."/fig2_1_points.dat" with points pt 7 ps 0.9 lc rgb "black", \
       datadir."/fig2_1_p.dat" with points pt 7 ps 1.4 lc rgb "#d02020", \
       datadir."/fig2_1_p.dat" using 1:2:("p_{n+1}") with labels offset 2.2,0.9 tc rgb "#d02020" font ",16"
  set title "the cavity C(DT_n, p_{n+1}) and its circumcircles"
  plot datadir."/fig2_1_cavity.dat" with filledcurves closed fc rgb "#f6c88f" fs solid 1.0, \
       datadir."/fig2_1_dtn.dat" with lines lw 1.5 lc rgb "#303030", \
       datadir."/fig2_1_cavity.dat" with lines lw 3 lc rgb "#b05a00", \
       datadir."/fig2_1_circles.dat" using 1:2:3 with circles lw 1.5 dt 2 lc rgb "#2050c0" fs empty, \
       datadir."/fig2_1_points.dat" with points pt 7 ps 0.9 lc rgb "black", \
       datadir."/fig2_1_p.dat" with points pt 7 ps 1.4 lc rgb "#d02020", \
       datadir."/fig2_1_p.dat" using 1:2:("p_{n+1}") with labels offset 2.2,0.9 tc rgb "#d02020" font ",16"
  unset multiplot
}
