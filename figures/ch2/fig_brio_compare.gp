# BRIO against Hilbert-only and random order (2.3.5): (a) mean cavity size,
# (b) mean walk length and (c) time per point against n (log axes: the series span decades),
# for Hilbert (dashed line, hollow marker) and BRIO (solid line, filled marker) order; (d)
# random order, in its own panel (it is only run at the small sizes). Colour and marker shape:
# the input. Each series is drawn a little left (Hilbert) or right (BRIO) of its n, the inputs
# a step apart, so that no marker hides another. A series whose work per point grew like n
# (N_search + N_cavity > 200) is not run at the next size: its last point is circled. One
# legend for all four panels, under them.
# Data (sec2_3_5_hilbert): brio_compare.dat (input n order nsearch ncavity t us_per_point),
# brio_compare_stops.dat (the last row of each stopped series).
load system("dirname '".ARG0."'")."/style.gp"
f = datadir."/brio_compare.dat"
g = datadir."/brio_compare_stops.dat"
names = "uniform clustered parabola jittered-grid circle"
marks = "7 5 9 13 11"
stats f using 1 nooutput
ninputs = int(STATS_max) + 1
stats f using 2 nooutput
nlo = STATS_min; nhi = STATS_max
xlo = nlo / 2.2; xhi = nhi * 2.2
# A series' offset along x (a factor): Hilbert 0.07 decade left of n, BRIO 0.07 right, random
# order at n; the inputs 0.025 decade apart within each order.
xoff(inp, ord) = 10 ** ((ord == 1 ? -0.07 : (ord == 2 ? 0.07 : 0)) + 0.025 * (inp - (ninputs - 1) / 2.0))
# The stopped series of random order (r = 1) or of Hilbert and BRIO (r = 0); a circle around
# each one's last point, only where some series stopped (a plot must draw something).
# (The file reaches the shell as "$DT_DATADIR/...": expanded, never read as code.)
nstops(r) = (system(sprintf("awk -- '$1 != \"NaN\" && ($3 == 0) == %d' \"${DT_DATADIR:-.}/brio_compare_stops.dat\" | wc -l", r)) + 0)
nstopsR = nstops(1); nstopsHB = nstops(0)
stopped(c, r) = ((r ? nstopsR : nstopsHB) > 0) ? sprintf(", g using ((%d ? $3 == 0 : $3 > 0) ? $2 * xoff($1, $3) : NaN):%d with points pt 6 ps (3.2*PS) lw 1.5 lc rgb 'black' notitle", r, c) : ""
# Hilbert's markers hollow (gnuplot's hollow shape is the filled one's number less one).
series(c, order, dash) = sprintf("for [i = 0:%d] f using ($1 == i && $3 == %d ? $2 * xoff($1, $3) : NaN):%d with linespoints lw 2 dt %d pt (int(word(marks, i + 1)) - %d) ps (1.1*PS) lc rgb word(C_SERIES, i + 1) notitle", ninputs - 1, order, c, dash, order == 1 ? 1 : 0)
# The top and bottom of row r's plots, in screen units from the em: 2.6 em under the top of
# the row's cell (its panel titles), and over its bottom 2.4 em in the top row (the tick labels
# 10^k) and 4.4 em in the bottom row, which also has the x label n, shared by the columns (under
# the top row it met the titles of the bottom row). The label n is centred 0.6 em over the bottom of
# the canvas, a label at a fixed place: as an xlabel each terminal put it elsewhere. Left to
# gnuplot, the svg terminal, which takes a line for taller than its text, made its panels a
# fifth shorter than the PNG's, and (d)'s legend spread over the y axis.
# The bottom row leaves 3 em more under it for the legend, two lines across the canvas.
rows(r) = sprintf("set tmargin at screen %.4f; set bmargin at screen %.4f; ", 1 - (r - 1) / 2.0 - 2.6 * EM / FH, (r == 1 ? 0.5 + 2.4 * EM / FH : 7.8 * EM / FH)) . \
  (r == 1 ? "unset label 101" : sprintf("set label 101 \"%s\" at graph 0.5, screen %.4f center", M."𝑛}", 3.6 * EM / FH))
do for [term in "png svg"] {
  eval fig_open(term, "fig_brio_compare")
  set output (term eq "png" ? outdir."/fig_brio_compare.png" : outdir."/fig_brio_compare.svg")
  set size noratio
  set border 3
  set tics out nomirror
  set xtics nomirror; set ytics nomirror
  set logscale x
  set format x "10^{%T}"
  set grid lc rgb C_GRID lw 1
  set xrange [xlo:xhi]
  eval layout(2, 2)
  eval rows(1)
  eval panel(1, M."𝑁_{cavity}}".", log scale")
  set logscale y
  set yrange [*:*]
  set ytics autofreq
  eval "plot " . series(5, 1, 2) . ", " . series(5, 2, 1) . stopped(5, 0)
  eval panel(2, M."𝑁_{search}}"." (log scale)")
  eval "plot " . series(4, 1, 2) . ", " . series(4, 2, 1) . stopped(4, 0)
  eval rows(2)
  eval panel(3, "time per point (µs, log scale)")
  eval "plot " . series(7, 1, 2) . ", " . series(7, 2, 1) . stopped(7, 0)
  eval panel(4, "random order: ".M."𝑁_{search}}"." (log scale)")
  set logscale y
  set yrange [*:*]
  set ytics autofreq
  # The legend, under the panels: one entry per input (colour and shape), then the two orders
  # (line and fill, in black).
  set key at screen 0.5, screen (1.5 * EM / FH) center center vertical maxrows 2 samplen 2.5 spacing 1.0 width 1 Left reverse
  eval "plot " . series(4, 0, 1) . stopped(4, 1) . \
       ", for [i = 0:ninputs - 1] NaN with linespoints lw 2 pt int(word(marks, i + 1)) ps (1.1*PS) lc rgb word(C_SERIES, i + 1) title word(names, i + 1)" . \
       ", NaN with linespoints lw 2 dt 2 pt 6 ps (1.1*PS) lc rgb 'black' title 'Hilbert (hollow)'" . \
       ", NaN with linespoints lw 2 dt 1 pt 7 ps (1.1*PS) lc rgb 'black' title 'BRIO (filled)'"
  unset multiplot
}
