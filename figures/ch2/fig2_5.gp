# Figure 2.5: a set of 9 points and the two super-triangles p_{-1} p_{-2} p_{-3} and
# p_{-2} p_{-1} p_{-4} that contain them all (DT_0), then the triangulation after the insertion
# of 1, 2, 3, 4 and all 9 points. Inserted points are filled, the others hollow.
# Data (sec2_2_bowyer_watson): fig2_5_{0,1,2,3,4,9}.dat (edges, each once), fig2_5_points.dat
# and fig2_5_super.dat (x y label, then the label place in each panel).
load system("dirname '".ARG0."'")."/style.gp"
stats datadir."/fig2_5_super.dat" using 1:2 nooutput
m = 0.08 * (STATS_max_x - STATS_min_x)
set xrange [STATS_min_x-m:STATS_max_x+m]
set yrange [STATS_min_y-m:STATS_max_y+m]
array K[6] = [0, 1, 2, 3, 4, 9]
do for [term in "png svg"] {
  eval fig_open(term, "fig2_5")
  set output (term eq "png" ? outdir."/fig2_5.png" : outdir."/fig2_5.svg")
  eval layout(2, 3)
  do for [i=1:6] {
    k = K[i]
    eval panel(i, k == 0 ? "DT_0" : sprintf("%d point%s inserted", k, k == 1 ? "" : "s"))
    plot datadir.sprintf("/fig2_5_%d.dat", k) with lines lw 1.5 lc rgb C_TRI, \
         datadir."/fig2_5_super.dat" using 1:2 with points pt 5 ps (1.2*PS) lc rgb C_SUPER, \
         datadir."/fig2_5_super.dat" using (column(2 + 2 * i)):(column(3 + 2 * i)):3 with labels tc rgb C_SUPER, \
         datadir."/fig2_5_points.dat" using 1:2 with points pt 6 ps (1.2*PS) lc rgb "#808080", \
         datadir."/fig2_5_points.dat" using 1:($0 < k ? $2 : NaN) with points pt 7 ps (1.2*PS) lc rgb C_POINT, \
         datadir."/fig2_5_points.dat" using (column(2 + 2 * i)):(column(3 + 2 * i)):3 with labels tc rgb C_TRI
  }
  unset multiplot
}
