# Figure 2.10: left, the Delaunay cavity of a new point p (light pink) in the mesh; right, the
# remeshed ball (light pink), the neighbours outside the cavity (dark pink) and the adjacencies
# set by computeAdjacencies (red double arrows): between new faces, and to the neighbours.
if (!exists("datadir")) datadir = "."
if (!exists("outdir")) outdir = "."
unset key
unset border
unset tics
set size ratio -1
set style arrow 1 head filled size screen 0.008,20 lw 1.6 lc rgb "#c00000"
set style arrow 2 head filled size screen 0.008,20 lw 1.6 lc rgb "#7a1040"
do for [term in "png svg"] {
  if (term eq "png") {
    set terminal pngcairo size 1400,700 enhanced font "Sans,13"
    set output outdir."/fig2_10.png"
  } else {
    set terminal svg size 1400,700 enhanced font "Sans,13" background rgb "white"
    set output outdir."/fig2_10.svg"
  }
  set multiplot layout 1,2
  set title "the cavity C(DT_n, p) is removed"
  plot datadir."/fig2_10_cavity.dat" with filledcurves closed fc rgb "#f8c8d8" fs solid 1.0, \
       datadir."/fig2_10_before.dat" with lines lw 1 lc rgb "#4060a0", \
       datadir."/fig2_10_point.dat" with points pt 7 ps 1.6 lc rgb "#c00000"
  set title "the ball and its updated adjacencies"
  plot datadir."/fig2_10_outer.dat" with filledcurves closed fc rgb "#d87098" fs solid 1.0, \
       datadir."/fig2_10_ball.dat" with filledcurves closed fc rgb "#f8c8d8" fs solid 1.0, \
       datadir."/fig2_10_after.dat" with lines lw 1 lc rgb "#4060a0", \
       datadir."/fig2_10_links_new.dat" using 1:2:3:4 with vectors arrowstyle 1, \
       datadir."/fig2_10_links_outer.dat" using 1:2:3:4 with vectors arrowstyle 2, \
       datadir."/fig2_10_point.dat" with points pt 7 ps 1.6 lc rgb "#c00000"
  unset multiplot
}
