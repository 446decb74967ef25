# The worst case of 2.3.4: points on y = x^2, x = -n..-1, inserted in increasing x. The size of
# the cavity of the i-th point: with ghost faces every previous triangle is in it.
load system("dirname '".ARG0."'")."/style.gp"
stats datadir."/parabola_cavity.dat" using 1 nooutput
# The x tic step: the smallest of 1, 2, 5 x 10^k with at most 4 steps up to the last point.
xstep = 10**floor(log10(STATS_max / 4.0))
xstep = (STATS_max / xstep <= 4 ? xstep : STATS_max / (2 * xstep) <= 4 ? 2 * xstep : STATS_max / (5 * xstep) <= 4 ? 5 * xstep : 10 * xstep)
do for [term in "png svg"] {
  eval fig_open(term, "fig_parabola_cavity")
  set output (term eq "png" ? outdir."/fig_parabola_cavity.png" : outdir."/fig_parabola_cavity.svg")
  set size noratio
  set border
  set tics out nomirror
  set xtics nomirror; set ytics nomirror
  # At 8 cm the text is large for the plot: a short x label, at most 5 x tics, the legend in
  # the empty band between the two curves (a longer label ran past the canvas, the tics into
  # each other).
  set xlabel "point ".M."𝑖}"." (inserted in increasing ".M."𝑥}".")"
  set ylabel "faces in the cavity of point ".M."𝑖}"
  set xtics xstep
  set key at graph 0.09, graph 0.47 left center Left reverse samplen 1.5 spacing 1.1
  set grid lc rgb C_GRID lw 1
  set logscale y
  plot datadir."/parabola_cavity.dat" using 1:3 with lines lw 2.5 lc rgb word(C_SERIES, 1) title "DT(".M."𝑆}".") with ghost faces", \
       datadir."/parabola_cavity.dat" using 1:2 with lines lw 2.5 lc rgb word(C_SERIES, 2) title "super-triangles"
}
