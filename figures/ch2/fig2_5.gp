# Figure 2.5: a set of 9 points and the two super-triangles p_{-1} p_{-2} p_{-3} and
# p_{-2} p_{-1} p_{-4} that contain them all (DT_0), then the triangulation after the insertion
# of 1, 2, 3, 4 and all 9 points. Inserted points are filled, the others hollow; the point
# inserted last has a red ring.
# Data (sec2_2_bowyer_watson): fig2_5_{0,1,2,3,4,9}.dat (edges, each once), fig2_5_points.dat
# and fig2_5_super.dat (x y label giflabel: the markers), fig2_5_labels_{0,1,2,3,4,9}.dat (x y
# label lx ly super: each panel's labels, placed beside their points with that panel's edges),
# fig2_5_view.gp (P1..P6: each panel's box and view, from the program's layout).
load system("dirname '".ARG0."'")."/style.gp"
load datadir."/fig2_5_view.gp"
array K[6] = [0, 1, 2, 3, 4, 9]
do for [term in "png svg"] {
  eval fig_open(term, "fig2_5")
  set output (term eq "png" ? outdir."/fig2_5.png" : outdir."/fig2_5.svg")
  eval layout(3, 2)
  do for [i=1:6] {
    k = K[i]
    eval panel(i, k == 0 ? "DT_".M."0}" : sprintf("%d point%s inserted", k, k == 1 ? "" : "s"))
    eval value(sprintf("P%d", i))
    # The inserted points (filled) only where there are some: a plot must draw something.
    # The point inserted last ringed in the new point's colour (a shape too, not a colour alone).
    inserted = (k == 0) ? "" : sprintf(", datadir.'/fig2_5_points.dat' every ::0::%d using 1:2 with points pt 7 ps (1.3*PS) lc rgb C_POINT", k - 1) . \
                               sprintf(", datadir.'/fig2_5_points.dat' every ::%d::%d using 1:2 with points pt 6 ps (2.4*PS) lw 2 lc rgb C_NEW", k - 1, k - 1)
    eval "plot datadir.sprintf('/fig2_5_%d.dat', k) with lines lw 1.5 lc rgb C_TRI, " . \
         "datadir.'/fig2_5_super.dat' using 1:2 with points pt 5 ps (1.3*PS) lc rgb C_SUPER, " . \
         "datadir.sprintf('/fig2_5_labels_%d.dat', k) using 4:($6 == 1 ? $5 : NaN):3 with labels tc rgb C_SUPER font ',' . sprintf('%.1f', 0.85 * FS), " . \
         "datadir.'/fig2_5_points.dat' using 1:2 with points pt 6 ps (1.3*PS) lc rgb C_PENDING, " . \
         "datadir.sprintf('/fig2_5_labels_%d.dat', k) using 4:($6 == 0 ? $5 : NaN):3 with labels tc rgb C_TRI font ',' . sprintf('%.1f', 0.85 * FS)" . inserted
  }
  unset multiplot
}
