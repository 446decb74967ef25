# Section 2.2.2: a point p outside the current hull, before (cavity) and after (new triangles).
# Data from sec2_2_2_outside_hull: out{hull,line}_{before,after}.{gp,dat} (VIEW: the panel's box
# and view from the program's layout; before and after share a scale), *_points.dat, *_q.dat,
# *_label.dat (where the placer put the label of p: one place in both panels of a row).
# (a)-(b): a point seeing hull edges; (c)-(d): a point on the line of a hull edge.
load system("dirname '".ARG0."'")."/style.gp"
do for [t in "png svg"] {
  eval fig_open(t, "fig_outside_hull")
  set output (t eq "png" ? outdir.'/fig_outside_hull.png' : outdir.'/fig_outside_hull.svg')
  eval layout(2, 2)
  k = 0
  do for [s in "outhull outline"] {
    do for [w in "before after"] {
      k = k + 1
      load datadir.'/'.s.'_'.w.'.gp'
      eval panel(k, ftitle)
      eval VIEW
      plot datadir.'/'.s.'_'.w.'.dat' with lines lc rgb C_TRI lw 1.2, \
           datadir.'/'.s.'_points.dat' with points pt 7 ps (0.8*PS) lc rgb C_POINT, \
           datadir.'/'.s.'_q.dat' with points pt 7 ps (1.6*PS) lc rgb C_NEW, \
           datadir.'/'.s.'_label.dat' using 1:2:(M."𝑝}") with labels tc rgb C_NEW
      unset object; unset arrow
    }
  }
  unset multiplot
}
