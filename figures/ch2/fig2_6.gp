# Figure 2.6: the final triangulation DT(S0 ∪ S) of 10 points in super-triangles 1.5 times their
# box (left), with the convex hull Ω(S) shaded: deleting the triangles that touch a super-vertex
# leaves part of Ω(S) uncovered (right), so DT(S) is not contained in DT(S0 ∪ S). The triangle
# p_k p_j p_l of DT(S) (dashed) is missing: its circumcircle contains the super-vertex p_{-1},
# and the edges from super-vertices that cross p_k p_l are drawn in red.
# Data (sec2_2_bowyer_watson): fig2_6_all.dat, fig2_6_kept.dat, fig2_6_hull.dat,
# fig2_6_points.dat, fig2_6_missing.dat, fig2_6_circle.dat, fig2_6_labels.dat,
# fig2_6_super.dat, fig2_6_crossing.dat.
if (!exists("datadir")) datadir = "."
if (!exists("outdir")) outdir = "."
set size ratio -1
set style textbox opaque noborder
unset key
unset border
unset tics
stats datadir."/fig2_6_all.dat" using 1 nooutput
x0 = STATS_min; x1 = STATS_max
stats datadir."/fig2_6_all.dat" using 2 nooutput
y0 = STATS_min; y1 = STATS_max
m = 0.08 * (x1 - x0)
stats datadir."/fig2_6_hull.dat" using 1 nooutput
hx0 = STATS_min; hx1 = STATS_max
stats datadir."/fig2_6_hull.dat" using 2 nooutput
hy0 = STATS_min; hy1 = STATS_max
hm = 0.08 * (hx1 - hx0)
do for [term in "png svg"] {
  if (term eq "png") {
    set terminal pngcairo size 1400,720 enhanced font "Sans,14"
    set output outdir."/fig2_6.png"
  } else {
    set terminal svg size 1400,720 enhanced font "Sans,14" background rgb "white"
    set output outdir."/fig2_6.svg"
  }
  set multiplot layout 1,2
  set title "DT(S_0 ∪ S), with the convex hull Ω(S) shaded"
  set xrange [x0-m:x1+m]
  set yrange [y0-m:y1+m]
  plot datadir."/fig2_6_hull.dat" with filledcurves closed fc rgb "#b7d7f0" fs solid 1.0, \
       datadir."/fig2_6_all.dat" with lines lw 1.2 lc rgb "#404040", \
       datadir."/fig2_6_crossing.dat" with lines lw 3 lc rgb "#d02020", \
       datadir."/fig2_6_circle.dat" using 1:2:3 with circles lw 2 dt 2 lc rgb "#2050c0" fs empty, \
       datadir."/fig2_6_points.dat" with points pt 7 ps 0.8 lc rgb "black", \
       datadir."/fig2_6_super.dat" using 1:2 with points pt 5 ps 1.3 lc rgb "#d02020", \
       datadir."/fig2_6_super.dat" using 1:($2 > 0.5 * (y0 + y1) ? $2 + 0.5 * m : $2 - 0.5 * m):3 with labels boxed font ",16" tc rgb "#d02020"
  set title "the triangles without super-vertices do not cover Ω(S)"
  set xrange [hx0-hm:hx1+hm]
  set yrange [hy0-hm:hy1+hm]
  plot datadir."/fig2_6_hull.dat" with filledcurves closed fc rgb "#b7d7f0" fs solid 1.0, \
       datadir."/fig2_6_kept.dat" with filledcurves closed fc rgb "white" fs solid 1.0, \
       datadir."/fig2_6_kept.dat" with lines lw 1.5 lc rgb "#303030", \
       datadir."/fig2_6_hull.dat" with lines lw 1 lc rgb "#2050c0", \
       datadir."/fig2_6_crossing.dat" with lines lw 3 lc rgb "#d02020", \
       datadir."/fig2_6_missing.dat" with lines lw 2.5 dt 2 lc rgb "#2050c0", \
       datadir."/fig2_6_points.dat" with points pt 7 ps 1.0 lc rgb "black", \
       datadir."/fig2_6_labels.dat" using 1:2:3 with labels boxed offset 1.4,0.9 font ",16" tc rgb "#2050c0"
  unset multiplot
}
