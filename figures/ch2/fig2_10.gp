# Figure 2.10: (a) the Delaunay cavity of a new point p in the mesh; (b) the remeshed ball, the
# neighbours outside the cavity and the adjacencies set by computeAdjacencies (double arrows):
# between new faces (green), and between new faces and the neighbours (blue).
# Data (sec2_3_4_algorithms): fig2_10_{before,after}.dat (edges, each once), fig2_10_cavity.dat,
# fig2_10_ball.dat, fig2_10_outer.dat (triangles), fig2_10_links_{new,outer}.dat (x y dx dy),
# fig2_10_point.dat, fig2_10_label.dat (where the placer put the label of p: one place in both
# panels), fig2_10_view.gp (PA, PB: the panels' boxes and view, from the program's layout;
# T_*: the legend's words in the notes' notation).
load system("dirname '".ARG0."'")."/style.gp"
load datadir."/fig2_10_view.gp"
do for [term in "png svg"] {
  eval fig_open(term, "fig2_10")
  set output (term eq "png" ? outdir."/fig2_10.png" : outdir."/fig2_10.svg")

  # Each panel's legend at a fixed place in the band below it (the program leaves 4.5 em): an
  # "outside" key lands at different heights in the png and svg terminals.
  key_at(x) = sprintf("set key at screen %.4f, screen %.4f center top vertical maxrows 2 samplen 1.5 width -1", x, 4.3 * EM / FH)
  eval layout(1, 2)
  eval panel(1, "the cavity of ".M."𝑝}")
  eval PA
  eval key_at(0.25)
  plot datadir."/fig2_10_cavity.dat" with filledcurves closed fc rgb C_CAVITY fs solid 1.0 title "cavity ".T_CAVITY, \
       datadir."/fig2_10_before.dat" with lines lw 1.2 lc rgb C_TRI notitle, \
       datadir."/fig2_10_point.dat" with points pt 7 ps (1.6*PS) lc rgb C_NEW notitle, \
       datadir."/fig2_10_label.dat" using 1:2:(M."𝑝}") with labels tc rgb C_NEW notitle
  eval panel(2, "the ball and its adjacencies")
  eval PB
  eval key_at(0.72)  # left of the cell's middle: the two columns are wider than (a)'s one
  plot datadir."/fig2_10_outer.dat" with filledcurves closed fc rgb C_NEIGH fs solid 1.0 title "neighbours", \
       datadir."/fig2_10_ball.dat" with filledcurves closed fc rgb C_BALL fs solid 1.0 title "ball ".T_BALL, \
       datadir."/fig2_10_after.dat" with lines lw 1.2 lc rgb C_TRI notitle, \
       datadir."/fig2_10_links_new.dat" using 1:2:3:4 with vectors head filled size screen 0.007,25 lw 2 lc rgb C_BALL_EDGE title T_NEWNEW, \
       datadir."/fig2_10_links_outer.dat" using 1:2:3:4 with vectors head filled size screen 0.007,25 lw 2 lc rgb C_NEIGH_EDGE title T_NEWOUT, \
       datadir."/fig2_10_point.dat" with points pt 7 ps (1.6*PS) lc rgb C_NEW notitle, \
       datadir."/fig2_10_label.dat" using 1:2:(M."𝑝}") with labels tc rgb C_NEW notitle
  unset multiplot
}
