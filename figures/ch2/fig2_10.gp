# Figure 2.10: (a) the Delaunay cavity of a new point p in the mesh; (b) the remeshed ball, the
# neighbours outside the cavity and the adjacencies set by computeAdjacencies (double arrows):
# between new faces (green), and between new faces and the neighbours (blue).
# Data (sec2_3_4_algorithms): fig2_10_{before,after}.dat (edges, each once), fig2_10_cavity.dat,
# fig2_10_ball.dat, fig2_10_outer.dat (triangles), fig2_10_links_{new,outer}.dat (x y dx dy),
# fig2_10_point.dat.
load system("dirname '".ARG0."'")."/style.gp"
stats datadir."/fig2_10_after.dat" using 1:2 nooutput
m = 0.04 * (STATS_max_x - STATS_min_x)
do for [term in "png svg"] {
  eval fig_open(term, "fig2_10")
  set output (term eq "png" ? outdir."/fig2_10.png" : outdir."/fig2_10.svg")

  set key outside bottom center horizontal maxrows 2 samplen 2 width 1
  set bmargin 5  # the same in both panels, so that both keys fit and the panels keep one size
  set xrange [STATS_min_x - m:STATS_max_x + m]
  set yrange [STATS_min_y - m:STATS_max_y + m]
  eval layout(1, 2)
  eval panel(1, "the cavity of ".M."𝑝}")
  plot datadir."/fig2_10_cavity.dat" with filledcurves closed fc rgb C_CAVITY fs solid 1.0 title "cavity", \
       datadir."/fig2_10_before.dat" with lines lw 1.2 lc rgb C_TRI notitle, \
       datadir."/fig2_10_point.dat" with points pt 7 ps (1.6*PS) lc rgb C_NEW notitle, \
       datadir."/fig2_10_point.dat" using 1:2:(M."𝑝}") with labels offset 0.9,0.9 tc rgb C_NEW notitle
  eval panel(2, "the ball and its adjacencies")
  plot datadir."/fig2_10_outer.dat" with filledcurves closed fc rgb C_NEIGH fs solid 1.0 title "neighbours", \
       datadir."/fig2_10_ball.dat" with filledcurves closed fc rgb C_BALL fs solid 1.0 title "ball", \
       datadir."/fig2_10_after.dat" with lines lw 1.2 lc rgb C_TRI notitle, \
       datadir."/fig2_10_links_new.dat" using 1:2:3:4 with vectors head filled size screen 0.007,25 lw 2 lc rgb C_BALL_EDGE title "new - new", \
       datadir."/fig2_10_links_outer.dat" using 1:2:3:4 with vectors head filled size screen 0.007,25 lw 2 lc rgb C_NEIGH_EDGE title "new - neighbour", \
       datadir."/fig2_10_point.dat" with points pt 7 ps (1.6*PS) lc rgb C_NEW notitle, \
       datadir."/fig2_10_point.dat" using 1:2:(M."𝑝}") with labels offset 0.9,0.9 tc rgb C_NEW notitle
  unset multiplot
}
