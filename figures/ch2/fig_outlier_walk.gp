# The fixed grid against the adaptive Hilbert order (2.3.5, issue 19): (a) mean walk length and
# (b) time per point against n, for uniform points plus one point at (1e12, 1e12); log axes.
# Data (sec2_3_5_hilbert): fig_outlier_walk.dat, index 0 fixed grid, index 1 adaptive
# (n order nsearch ncavity t). The dashed line 0.5 sqrt(n) is a function, drawn over the whole
# frame (also when a --quick run has one n). In (b), where the two times can coincide, the
# fixed grid is drawn 0.04 decade left of its n and the adaptive order 0.04 decade right.
load system("dirname '".ARG0."'")."/style.gp"
f = datadir."/fig_outlier_walk.dat"
stats f using 1 nooutput
nlo = STATS_min; nhi = STATS_max
# (a)'s frame: from under the lowest walk to over both the highest walk and 0.5 sqrt(n), with
# the top left (where the legend sits) left free: a decade over the highest value.
stats f using 3 nooutput
wlo = STATS_min; whi = (STATS_max > 0.5 * sqrt(nhi * 1.5) ? STATS_max : 0.5 * sqrt(nhi * 1.5))
stats f using (1e6 * $5 / $1) nooutput
tlo = STATS_min; thi = STATS_max
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
  set xlabel M."𝑛}"." (log scale)"
  set xrange [nlo / 1.5:nhi * 1.5]
  eval layout(1, 2)
  eval panel(1, M."𝑁_{search}}".": mean walk length (log)")
  set yrange [wlo / 2:whi * 10]
  set key inside top left Left reverse samplen 2 spacing 1.1 width 1
  set samples 50
  plot f index 0 using 1:3 with linespoints lw 2 pt 7 ps (1.2*PS) lc rgb word(C_SERIES, 2) title "fixed grid", \
       f index 1 using 1:3 with linespoints lw 2 pt 5 ps (1.2*PS) lc rgb word(C_SERIES, 1) title "adaptive", \
       0.5 * sqrt(x) with lines lw 1.5 dt 2 lc rgb C_CONSTRUCT title "0.5 √".M."𝑛}"
  eval panel(2, "time per point, ordering included (µs, log)")
  unset key
  set yrange [10 ** floor(log10(tlo)):10 ** ceil(log10(thi))]  # whole decades: two labelled ticks at least
  plot f index 0 using ($1 * 10 ** -0.04):(1e6 * $5 / $1) with linespoints lw 2 pt 7 ps (1.2*PS) lc rgb word(C_SERIES, 2), \
       f index 1 using ($1 * 10 ** 0.04):(1e6 * $5 / $1) with linespoints lw 2 pt 5 ps (1.2*PS) lc rgb word(C_SERIES, 1)
  unset multiplot
}
