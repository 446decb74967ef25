# Figure 2.4: the Delaunay ball ℬ(DT_n, p_{n+1}): the fan of triangles σ_i σ_{i+1} p_{n+1}
# that fills the cavity (shaded green), an outside triangle σ_i σ_{i+1} p_j (blue) with its
# circumcircle (dashed), which does not contain p_{n+1}, and the circumcircle of the new
# triangle σ_i σ_{i+1} p_{n+1} (dash-dotted), which does not contain p_j.
# Data (sec2_1_kernel): fig2_4_dt.dat (DT_{n+1}, each edge once), fig2_1_cavity.dat,
# fig2_4_labels.dat (x y label: p_{n+1}, σ_i, σ_{i+1}, p_j, ℬ), fig2_4_outside.dat,
# fig2_4_newtri.dat, fig2_4_circles.dat (x y r), fig2_1_p.dat, fig2_1_points.dat,
# fig2_4_view.gp (the view, from the program's layout, which placed the labels).
load system("dirname '".ARG0."'")."/style.gp"
load datadir."/fig2_4_view.gp"
do for [term in "png svg"] {
  eval fig_open(term, "fig2_4")
  set output (term eq "png" ? outdir."/fig2_4.png" : outdir."/fig2_4.svg")
  eval VIEW
  plot datadir."/fig2_1_cavity.dat" with filledcurves closed fc rgb C_BALL fs solid 1.0, \
       datadir."/fig2_4_outside.dat" with filledcurves closed fc rgb C_NEIGH fs solid 1.0, \
       datadir."/fig2_4_newtri.dat" with filledcurves closed fc rgb C_BALL_EDGE fs transparent solid 0.25, \
       datadir."/fig2_4_dt.dat" with lines lw 1.5 lc rgb C_TRI, \
       datadir."/fig2_1_cavity.dat" with lines lw 3 lc rgb C_BALL_EDGE, \
       datadir."/fig2_4_outside.dat" with lines lw 3 lc rgb C_NEIGH_EDGE, \
       datadir."/fig2_4_circles.dat" every ::0::0 using 1:2:3 with circles lw 2 dt 2 lc rgb C_CIRCLE fs empty, \
       datadir."/fig2_4_circles.dat" every ::1::1 using 1:2:3 with circles lw 2 dt (10,5,1,5) lc rgb C_CIRCLE fs empty, \
       datadir."/fig2_1_points.dat" with points pt 7 ps (1.0*PS) lc rgb C_POINT, \
       datadir."/fig2_1_p.dat" using 1:2 with points pt 7 ps (1.6*PS) lc rgb C_NEW, \
       datadir."/fig2_4_labels.dat" every ::0::0 using 1:2:3 with labels tc rgb C_NEW, \
       datadir."/fig2_4_labels.dat" every ::1::2 using 1:2:3 with labels tc rgb C_BALL_EDGE, \
       datadir."/fig2_4_labels.dat" every ::3::3 using 1:2:3 with labels tc rgb C_NEIGH_EDGE, \
       datadir."/fig2_4_labels.dat" every ::4::4 using 1:2:3 with labels tc rgb C_BALL_EDGE
}
