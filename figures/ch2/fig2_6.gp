# Figure 2.6: (a) the final triangulation DT(S0 ∪ S) of 10 points in super-triangles 1.5 times
# their box, with the convex hull Ω(S) shaded (salmon where only triangles with a super-vertex
# cover it), p_k, p_j, p_l named and the circle of p_k p_j p_l (dashed), which contains the
# super-vertex p_{-1}; (b) the triangles without super-vertices leave part of Ω(S)
# uncovered (salmon): the triangle p_k p_j p_l of DT(S) (dashed) is missing, and the edge from
# p_j to p_{-1} (red) crosses p_k p_l.
# Data (sec2_2_bowyer_watson): fig2_6_all.dat, fig2_6_kept.dat (triangles, for the fill),
# fig2_6_kept_edges.dat, fig2_6_hull.dat, fig2_6_points.dat, fig2_6_missing.dat,
# fig2_6_circle.dat, fig2_6_labels.dat (b), fig2_6_labels_a.dat (a), fig2_6_super.dat (x y name lx ly in_circle),
# fig2_6_exit.dat (where a crossing edge leaves view (b)), fig2_6_crossing.dat, fig2_6_view.gp.
load system("dirname '".ARG0."'")."/style.gp"
load datadir."/fig2_6_view.gp"
do for [term in "png svg"] {
  eval fig_open(term, "fig2_6")
  set output (term eq "png" ? outdir."/fig2_6.png" : outdir."/fig2_6.svg")
  eval layout(1, 2)
  eval panel(1, "DT(".M."𝑆_0} ∪ ".M."𝑆}) and Ω(".M."𝑆})")
  eval PA
  plot datadir."/fig2_6_hull.dat" with filledcurves closed fc rgb C_UNCOVERED fs solid 1.0, \
       datadir."/fig2_6_kept.dat" with filledcurves closed fc rgb C_HULL fs solid 1.0, \
       datadir."/fig2_6_all.dat" with lines lw 1.2 lc rgb C_TRI, \
       datadir."/fig2_6_crossing.dat" with lines lw 3 lc rgb C_CONFLICT, \
       datadir."/fig2_6_circle.dat" using 1:2:3 with circles lw 2 dt 2 lc rgb C_CIRCLE fs empty, \
       datadir."/fig2_6_points.dat" with points pt 7 ps (0.8*PS) lc rgb C_POINT, \
       datadir."/fig2_6_super.dat" using 1:2 with points pt 5 ps (1.3*PS) lc rgb C_SUPER, \
       datadir."/fig2_6_super.dat" using 4:5:3 with labels tc rgb C_SUPER, \
       datadir."/fig2_6_labels_a.dat" using 1:2:3 with labels tc rgb C_TRI
  eval panel(2, "DT(".M."𝑆}) ⊄ DT(".M."𝑆_0} ∪ ".M."𝑆})")
  eval PB
  plot datadir."/fig2_6_hull.dat" with filledcurves closed fc rgb C_UNCOVERED fs solid 1.0, \
       datadir."/fig2_6_kept.dat" with filledcurves closed fc rgb C_HULL fs solid 1.0, \
       datadir."/fig2_6_kept_edges.dat" with lines lw 1.5 lc rgb C_TRI, \
       datadir."/fig2_6_crossing.dat" with lines lw 3 lc rgb C_CONFLICT, \
       datadir."/fig2_6_missing.dat" with lines lw 2.5 dt 2 lc rgb C_CIRCLE, \
       datadir."/fig2_6_points.dat" with points pt 7 ps (1.0*PS) lc rgb C_POINT, \
       datadir."/fig2_6_labels.dat" using 1:2:3 with labels tc rgb C_TRI, \
       datadir."/fig2_6_exit.dat" using 3:4:5 with labels tc rgb C_CONFLICT
  unset multiplot
}
