# Figure 2.1: the Delaunay triangulation DT_n of 15 points (a) and the Delaunay cavity
# 𝒞(DT_n, p_{n+1}) (b): the triangles whose circumcircles (dashed) contain p_{n+1}.
# Data (sec2_1_kernel): fig2_1_dtn.dat (edges, each once), fig2_1_points.dat, fig2_1_p.dat
# (p_{n+1}; columns 3-5: its label's place in (a) and text; (b), where the cavity's circles crowd it,
# names it in its title and draws it in the same red, unlabelled), fig2_1_cavity.dat (boundary),
# fig2_1_circles.dat, fig2_1_view.gp (P1, P2: each panel's box and view, from the
# program's layout, which placed the label; NC: the number of circles).
load system("dirname '".ARG0."'")."/style.gp"
load datadir."/fig2_1_view.gp"
do for [term in "png svg"] {
  eval fig_open(term, "fig2_1")
  set output (term eq "png" ? outdir."/fig2_1.png" : outdir."/fig2_1.svg")
  eval layout(1, 2)
  eval panel(1, "DT_".M."𝑛}")
  eval P1
  plot datadir."/fig2_1_dtn.dat" with lines lw 1.5 lc rgb C_TRI, \
       datadir."/fig2_1_points.dat" with points pt 7 ps (1.0*PS) lc rgb C_POINT, \
       datadir."/fig2_1_p.dat" using 1:2 with points pt 7 ps (1.6*PS) lc rgb C_NEW, \
       datadir."/fig2_1_p.dat" using 3:4:5 with labels tc rgb C_NEW
  eval panel(2, "the cavity ".M."𝒞(}DT".M."_𝑛, 𝑝_{𝑛+1})}")
  eval P2
  plot datadir."/fig2_1_cavity.dat" with filledcurves closed fc rgb C_CAVITY fs solid 1.0, \
       datadir."/fig2_1_circles.dat" using 1:2:3 with circles lw 1.5 dt 2 lc rgb C_CIRCLE fs empty, \
       datadir."/fig2_1_dtn.dat" with lines lw 1.5 lc rgb C_TRI, \
       datadir."/fig2_1_cavity.dat" with lines lw 3 lc rgb C_CAVITY_EDGE, \
       datadir."/fig2_1_points.dat" with points pt 7 ps (1.0*PS) lc rgb C_POINT, \
       datadir."/fig2_1_p.dat" using 1:2 with points pt 7 ps (1.6*PS) lc rgb C_NEW
  unset multiplot
}
