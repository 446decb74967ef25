# Figure 2.1: the Delaunay triangulation DT_n of 15 points (a) and the Delaunay cavity
# C(DT_n, p_{n+1}) (b): the triangles whose circumcircles (dashed) contain p_{n+1}.
# Data (sec2_1_kernel): fig2_1_dtn.dat (triangles), fig2_1_points.dat, fig2_1_p.dat
# (p_{n+1}; columns 3-4: its label's place), fig2_1_cavity.dat (boundary), fig2_1_circles.dat.
load system("dirname '".ARG0."'")."/style.gp"
stats datadir."/fig2_1_points.dat" using 1:2 nooutput
m = 0.06 * (STATS_max_x - STATS_min_x)
set xrange [STATS_min_x - m:STATS_max_x + m]
set yrange [STATS_min_y - m:STATS_max_y + m]
do for [term in "png svg"] {
  eval fig_open(term, "fig2_1")
  set output (term eq "png" ? outdir."/fig2_1.png" : outdir."/fig2_1.svg")
  eval layout(1, 2)
  eval panel(1, "DT_n")
  plot datadir."/fig2_1_dtn.dat" with lines lw 1.5 lc rgb C_TRI, \
       datadir."/fig2_1_points.dat" with points pt 7 ps (1.0*PS) lc rgb C_POINT, \
       datadir."/fig2_1_p.dat" using 1:2 with points pt 7 ps (1.6*PS) lc rgb C_NEW, \
       datadir."/fig2_1_p.dat" using 3:4:("p_{n+1}") with labels tc rgb C_NEW
  eval panel(2, "the cavity C(DT_n, p_{n+1})")
  plot datadir."/fig2_1_cavity.dat" with filledcurves closed fc rgb C_CAVITY fs solid 1.0, \
       datadir."/fig2_1_circles.dat" using 1:2:3 with circles lw 1.5 dt 2 lc rgb C_CIRCLE fs empty, \
       datadir."/fig2_1_dtn.dat" with lines lw 1.5 lc rgb C_TRI, \
       datadir."/fig2_1_cavity.dat" with lines lw 3 lc rgb C_CAVITY_EDGE, \
       datadir."/fig2_1_points.dat" with points pt 7 ps (1.0*PS) lc rgb C_POINT, \
       datadir."/fig2_1_p.dat" using 1:2 with points pt 7 ps (1.6*PS) lc rgb C_NEW, \
       datadir."/fig2_1_p.dat" using 3:4:("p_{n+1}") with labels tc rgb C_NEW
  unset multiplot
}
