# New figure (2.3.1): the naive incircle test, in two argument orders that are an even permutation of each other (so exactly the same map).
# a(1/2,-47/2), b(49/2,-47/2), c(49/2,1/2) lie counter-clockwise on the circle through
# d0(1/2,1/2), tangent there to the diagonal; d(1/2 + i eps, 1/2 + j eps), eps = 2^-53.
# Exactly: inside (+1) below the diagonal, outside (-1) on and above it, 0 only at i = j = 0.
# Data (sec2_3_1_predicates): map_incircle_naive_abcd.dat, map_incircle_naive_dcba.dat.
if (!exists("datadir")) datadir = "."
if (!exists("outdir")) outdir = "."
set size ratio -1
set xlabel "i   (x_d = 1/2 + i 2^{-53})"
set ylabel "j   (y_d = 1/2 + j 2^{-53})"
unset colorbox
set palette defined (-1 "#1a9641", 0 "#ffd700", 1 "#d7191c")
set cbrange [-1:1]
set key outside bottom center horizontal samplen 1
set style fill solid 1.0 noborder
do for [term in "png svg"] {
  if (term eq "png") {
    set terminal pngcairo size 1300,720 enhanced font "Sans,14"
    set output outdir."/fig_incircle_naive.png"
  } else {
    set terminal svg size 1300,720 enhanced font "Sans,14" background rgb "white"
    set output outdir."/fig_incircle_naive.svg"
  }
  set multiplot layout 1,2
  set xrange [-0.5:255.5]
  set yrange [-0.5:255.5]
  set xtics 0,64,256 out nomirror
  set ytics 0,64,256 out nomirror
  set title "naive InC(a,b,c,d) (pivot d)"
  plot datadir."/map_incircle_naive_abcd.dat" matrix with image notitle, \
       NaN with boxes lc rgb "#1a9641" title "-1 (outside)", NaN with boxes lc rgb "#ffd700" title "0", \
       NaN with boxes lc rgb "#d7191c" title "+1 (inside)"
  if (0) {
    set xrange [-0.5:15.5]
    set yrange [-0.5:15.5]
    set xtics 0,4,16 out nomirror
    set ytics 0,4,16 out nomirror
  }
  set title "naive InC(d,c,b,a) (pivot a)"
  plot datadir."/map_incircle_naive_dcba.dat" matrix with image notitle, \
       NaN with boxes lc rgb "#1a9641" title "-1 (outside)", NaN with boxes lc rgb "#ffd700" title "0", \
       NaN with boxes lc rgb "#d7191c" title "+1 (inside)"
  unset multiplot
  unset output
}
