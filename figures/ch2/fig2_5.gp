# Figure 2.5: a set of 9 points and the two super-triangles p_{-1} p_{-2} p_{-3} and
# p_{-2} p_{-1} p_{-4} that contain them all (DT_0), then the triangulation after the insertion
# of 1, 2, 3, 4 and all 9 points. Inserted points are filled, the others hollow.
# Data (sec2_2_bowyer_watson): fig2_5_{0,1,2,3,4,9}.dat (triangles), fig2_5_points.dat and
# fig2_5_super.dat (x y label).
if (!exists("datadir")) datadir = "."
if (!exists("outdir")) outdir = "."
set size ratio -1
set style textbox opaque noborder
unset key
unset border
unset tics
stats datadir."/fig2_5_super.dat" using 1 nooutput
x0 = STATS_min; x1 = STATS_max
stats datadir."/fig2_5_super.dat" using 2 nooutput
y0 = STATS_min; y1 = STATS_max
m = 0.09 * (x1 - x0)
set xrange [x0-m:x1+m]
set yrange [y0-m:y1+m]
array K[6] = [0, 1, 2, 3, 4, 9]
do for [term in "png svg"] {
  if (term eq "png") {
    set terminal pngcairo size 1500,1020 enhanced font "Sans,13"
    set output outdir."/fig2_5.png"
  } else {
    set terminal svg size 1500,1020 enhanced font "Sans,13" background rgb "white"
    set output outdir."/fig2_5.svg"
  }
  set multiplot layout 2,3
  do for [i=1:6] {
    k = K[i]
    set title (k == 0 ? "DT_0: 9 points in two super-triangles" : sprintf("after %d insertion%s (%d triangles)", k, k == 1 ? "" : "s", 2 + 2 * k))
    plot datadir.sprintf("/fig2_5_%d.dat", k) with lines lw 1.5 lc rgb "#303030", \
         datadir."/fig2_5_super.dat" using 1:2 with points pt 5 ps 1.0 lc rgb "#2050c0", \
         datadir."/fig2_5_super.dat" using 1:($2 > 0.5 ? $2 + 0.5 * m : $2 - 0.5 * m):3 with labels boxed font ",13" tc rgb "#2050c0", \
         datadir."/fig2_5_points.dat" using 1:2 with points pt 6 ps 1.1 lc rgb "#909090", \
         datadir."/fig2_5_points.dat" using 1:($0 < k ? $2 : NaN) with points pt 7 ps 1.1 lc rgb "#d02020", \
         datadir."/fig2_5_points.dat" using 1:2:3 with labels offset 1.6,0.7 font ",12" tc rgb "#802020"
  }
  unset multiplot
}
