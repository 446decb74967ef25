# Figure 2.12: Hilbert sort of 1000 and 10000 random points; consecutive points are joined,
# coloured from the first (dark) to the last (yellow) point of the order.
# Data (sec2_3_5_hilbert): fig2_12_1000.dat, fig2_12_10000.dat (x y rank).
if (!exists("datadir")) datadir = "."
if (!exists("outdir")) outdir = "."
set size ratio -1
unset key
unset colorbox
set xrange [0:1]
set yrange [0:1]
set tics out nomirror
set palette defined (0 "#20206a", 0.5 "#c03060", 1 "#e0b000")
do for [term in "png svg"] {
  if (term eq "png") {
    set terminal pngcairo size 1400,720 enhanced font "Sans,13"
    set output outdir."/fig2_12.png"
  } else {
    set terminal svg size 1400,720 enhanced font "Sans,13" background rgb "white"
    set output outdir."/fig2_12.svg"
  }
  set multiplot layout 1,2
  do for [n in "1000 10000"] {
    set title sprintf("%s random points joined in Hilbert order", n)
    set cbrange [0:n+0]
    plot datadir."/fig2_12_".n.".dat" using 1:2:3 with lines lw (n eq "1000" ? 1.5 : 0.8) lc palette
  }
  unset multiplot
}
