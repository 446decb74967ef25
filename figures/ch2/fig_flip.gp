# Section 2.3.6 / 2.3.3: an edge flip, (a) before and (b) after. Data from sec2_3_6_flips:
# flip_{before,after}_tri.dat (triangles), flip_{before,after}.gp (shaded faces, edge, labels).
# The two faces of the flip in the cavity's colour before and the ball's after, the four
# adjacent faces in the neighbours' colour. Labels: each vertex's number of triangles. In (a) the
# circle through a, b, c (flip_circle.dat: x y r), dashed: it holds d, so a b must flip. Every
# vertex has a marker (flip_{before,after}_points.dat).
load system("dirname '".ARG0."'")."/style.gp"
do for [t in "png svg"] {
  eval fig_open(t, "fig_flip")
  set output (t eq "png" ? outdir.'/fig_flip.png' : outdir.'/fig_flip.svg')
  eval layout(1, 2)
  eval panel(1, "before: edge ".M."𝑎𝑏}")
  load datadir.'/flip_before.gp'
  eval VIEW
  plot datadir.'/flip_before_tri.dat' with lines lc rgb C_TRI lw 1.2, \
       datadir.'/flip_circle.dat' using 1:2:3 with circles lw 1.5 dt 2 lc rgb C_CIRCLE fs empty, \
       datadir.'/flip_before_points.dat' with points pt 7 ps (1.0*PS) lc rgb C_POINT
  unset object; unset arrow
  unset label
  eval panel(2, "after: edge ".M."𝑐𝑑} (change)")
  load datadir.'/flip_after.gp'
  eval VIEW
  plot datadir.'/flip_after_tri.dat' with lines lc rgb C_TRI lw 1.2, \
       datadir.'/flip_after_points.dat' with points pt 7 ps (1.0*PS) lc rgb C_POINT
  unset object; unset label; unset arrow
  unset multiplot
}
