# Figure 2.8: the robust orientation test (floating-point filter with a proven error bound, exact
# GMP fallback) on the grid of Figure 2.7: left the whole 256 x 256 map of O(a,b,c), right a zoom
# on 32 x 32 cells around the diagonal, where only the diagonal (i = j, a on line bc) is 0.
# Data (sec2_3_1_predicates): map_orient_robust_abc.dat.
if (!exists("datadir")) datadir = "."
if (!exists("outdir")) outdir = "."
set size ratio -1
set xlabel "i   (x_a = 1/2 + i 2^{-53})"
set ylabel "j   (y_a = 1/2 + j 2^{-53})"
unset colorbox
set palette defined (-1 "#1a9641", 0 "#ffd700", 1 "#d7191c")
set cbrange [-1:1]
set key outside bottom center horizontal samplen 1
set style fill solid 1.0 noborder
do for [term in "png svg"] {
  if (term eq "png") {
    set terminal pngcairo size 1300,720 enhanced font "Sans,14"
    set output outdir."/fig2_8.png"
  } else {
    set terminal svg size 1300,720 enhanced font "Sans,14" background rgb "white"
    set output outdir."/fig2_8.svg"
  }
  set multiplot layout 1,2
  set title "robust O(a,b,c)"
  set xrange [-0.5:255.5]
  set yrange [-0.5:255.5]
  set xtics 0,64,256 out nomirror
  set ytics 0,64,256 out nomirror
  plot datadir."/map_orient_robust_abc.dat" matrix with image notitle, \
       NaN with boxes lc rgb "#1a9641" title "-1", NaN with boxes lc rgb "#ffd700" title "0", \
       NaN with boxes lc rgb "#d7191c" title "+1"
  set title "zoom: 112 <= i, j < 144"
  set xrange [111.5:143.5]
  set yrange [111.5:143.5]
  set xtics 112,8,144 out nomirror
  set ytics 112,8,144 out nomirror
  plot datadir."/map_orient_robust_abc.dat" matrix with image notitle, \
       NaN with boxes lc rgb "#1a9641" title "-1", NaN with boxes lc rgb "#ffd700" title "0", \
       NaN with boxes lc rgb "#d7191c" title "+1"
  unset multiplot
  unset output
}
