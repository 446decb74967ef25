# BRIO against Hilbert-only and random order (2.3.5): (a) mean cavity size, (b) mean walk length
# and (c) time per point against n, on four inputs. Colour: input; line type: order; random
# order (triangles) only at the small sizes. A series whose work per point grew like n
# (N_search + N_cavity > 200) is not run at the next size: its last point is circled.
# Data (sec2_3_5_hilbert): brio_compare.dat (input n order nsearch ncavity t us_per_point),
# brio_compare_stops.dat (the last row of each stopped series).
load system("dirname '".ARG0."'")."/style.gp"
f = datadir."/brio_compare.dat"
g = datadir."/brio_compare_stops.dat"
names = "uniform clustered parabola jittered-grid"
orders = "random Hilbert BRIO"
stats f using 2 nooutput
do for [term in "png svg"] {
  eval fig_open(term, "fig_brio_compare")
  set output (term eq "png" ? outdir."/fig_brio_compare.png" : outdir."/fig_brio_compare.svg")
  set size noratio
  set border
  set tics out nomirror
  set logscale x
  set format x "10^{%T}"
  set grid lc rgb "#d8d8d8"
  set xlabel "n"
  set xrange [STATS_min / 1.5:STATS_max * 1.5]
  eval layout(1, 3)
  # One legend for the three panels, below them.
  set bmargin at screen 0.42
  set tmargin at screen 0.88
  do for [col in "5 4 7"] {
    c = col + 0
    set lmargin at screen (c == 5 ? 0.08 : (c == 4 ? 0.41 : 0.74))
    set rmargin at screen (c == 5 ? 0.30 : (c == 4 ? 0.63 : 0.96))
    eval panel(c == 5 ? 1 : (c == 4 ? 2 : 3), c == 5 ? "N_{cavity}" : (c == 4 ? "N_{search}" : "time per point (µs)"))
    set logscale y
    unset key
    plot for [k = 0:7] f using ($1 == int(k/2) && $3 == k%2 + 1 ? $2 : NaN):c \
           with linespoints lw 2 dt 1+k%2 pt (k%2 == 0 ? 7 : 5) ps (0.9*PS) \
           lc rgb word(C_SERIES, int(k/2) + 1) title word(names, int(k/2) + 1)." ".word(orders, k%2 + 2), \
         for [i = 0:3] f using ($1 == i && $3 == 0 ? $2 : NaN):c with points pt 9 ps (1.6*PS) lc rgb word(C_SERIES, i + 1) \
           title (i == 0 ? "random order (triangles)" : ""), \
         g using 2:c with points pt 6 ps (3.5*PS) lw 2 lc rgb "black" title "last size run (the next one would be quadratic)"
  }
  # The legend: a plot of its own below the panels, with no axes.
  unset logscale
  unset border
  unset tics
  unset xlabel
  unset grid
  unset label 100
  set lmargin at screen 0.02
  set rmargin at screen 0.98
  set bmargin at screen 0.01
  set tmargin at screen 0.25
  set xrange [0:1]
  set yrange [0:1]
  set key inside center center horizontal maxcols 3 samplen 2.5 width 1 spacing 1.1
  plot for [k = 0:7] NaN with linespoints lw 2 dt 1+k%2 pt (k%2 == 0 ? 7 : 5) ps (0.9*PS) \
         lc rgb word(C_SERIES, int(k/2) + 1) title word(names, int(k/2) + 1)." ".word(orders, k%2 + 2), \
       NaN with points pt 9 ps (1.6*PS) lc rgb "#606060" title "random order", \
       NaN with points pt 6 ps (3*PS) lw 2 lc rgb "black" title "last size run before quadratic"
  unset multiplot
}
