# The fixed grid against the adaptive Hilbert order (2.3.5, issue 19): (a) mean walk length and
# (b) time per point against n, for uniform points plus one point at (1e12, 1e12).
# Data (sec2_3_5_hilbert): fig_outlier_walk.dat, index 0 fixed grid, index 1 adaptive
# (n order nsearch ncavity t).
load system("dirname '".ARG0."'")."/style.gp"
f = datadir."/fig_outlier_walk.dat"
stats f using 1 nooutput
do for [term in "png svg"] {
  eval fig_open(term, "fig_outlier_walk")
  set output (term eq "png" ? outdir."/fig_outlier_walk.png" : outdir."/fig_outlier_walk.svg")
  set size noratio
  set border
  set tics out nomirror
  set xtics nomirror; set ytics nomirror
  set logscale xy
  set format x "10^{%T}"
  set grid lc rgb C_GRID lw 1
  set xlabel M."𝑛}"." (uniform points + one outlier)"  # the longer label ran past the right edge of the PNG
  set xrange [STATS_min / 1.5:STATS_max * 1.5]
  eval layout(1, 2)
  eval panel(1, M."𝑁_{search}}".": mean walk length")
  set key inside right center Left reverse samplen 2 spacing 1.1  # between the curves: at the top left it lay on them
  plot f index 0 using 1:3 with linespoints lw 2 pt 7 ps (1.2*PS) lc rgb word(C_SERIES, 2) title "fixed grid", \
       f index 1 using 1:3 with linespoints lw 2 pt 5 ps (1.2*PS) lc rgb word(C_SERIES, 1) title "adaptive", \
       f index 0 using 1:(0.5 * sqrt($1)) with lines dt 2 lc rgb C_CONSTRUCT title "0.5 √".M."𝑛}"
  eval panel(2, "time per point (µs), ordering included")
  unset key
  plot f index 0 using 1:(1e6 * $5 / $1) with linespoints lw 2 pt 7 ps (1.2*PS) lc rgb word(C_SERIES, 2), \
       f index 1 using 1:(1e6 * $5 / $1) with linespoints lw 2 pt 5 ps (1.2*PS) lc rgb word(C_SERIES, 1)
  unset multiplot
}
