# The fixed grid against the adaptive Hilbert order (2.3.5, issue 19): mean walk length and mean
# cavity size against n for uniform points plus one point at (1e12, 1e12).
# Data (sec2_3_5_hilbert): fig_outlier_walk.dat, index 0 fixed grid, index 1 adaptive
# (n order nsearch ncavity t).
if (!exists("datadir")) datadir = "."
if (!exists("outdir")) outdir = "."
f = datadir."/fig_outlier_walk.dat"
set logscale xy
set format x "10^{%T}"
set grid lc rgb "#d0d0d0"
set xlabel "n (uniform points in the unit square, plus the outlier)"
do for [term in "png svg"] {
  if (term eq "png") {
    set terminal pngcairo size 1100,560 enhanced font "Sans,12"
    set output outdir."/fig_outlier_walk.png"
  } else {
    set terminal svg size 1100,560 enhanced font "Sans,12" background rgb "white"
    set output outdir."/fig_outlier_walk.svg"
  }
  set multiplot layout 1,2
  set title "N_{search}: mean walk length"
  set key top left
  plot f index 0 using 1:3 with linespoints lw 2 pt 7 lc rgb "#d62728" title "fixed grid over the box", \
       f index 1 using 1:3 with linespoints lw 2 pt 5 lc rgb "#1f77b4" title "adaptive (cells refined)", \
       f index 0 using 1:(0.5 * sqrt($1)) with lines dt 2 lc rgb "#808080" title "0.5 sqrt(n)"
  set title "time per point (µs), ordering included"
  unset key
  plot f index 0 using 1:(1e6 * $5 / $1) with linespoints lw 2 pt 7 lc rgb "#d62728", \
       f index 1 using 1:(1e6 * $5 / $1) with linespoints lw 2 pt 5 lc rgb "#1f77b4"
  unset multiplot
}
