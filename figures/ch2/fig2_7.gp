# Figure 2.7: the naive orientation test on b(12,12), c(24,24), a(1/2 + i eps, 1/2 + j eps),
# eps = 2^-53, 0 <= i, j < 256. Left O(a,b,c) (pivot c), right O(c,b,a) (pivot a).
# Green -1, yellow 0, red +1. Also fig2_7_errors: where each map differs from the exact sign.
# Data (sec2_3_1_predicates): map_orient_naive_{abc,cba}.dat, err_orient_naive_{abc,cba}.dat
# (n x n matrices, row j, column i).
if (!exists("datadir")) datadir = "."
if (!exists("outdir")) outdir = "."
set size ratio -1
set xrange [-0.5:255.5]
set yrange [-0.5:255.5]
set xtics 0,64,256 out nomirror
set ytics 0,64,256 out nomirror
set xlabel "i   (x_a = 1/2 + i 2^{-53})"
set ylabel "j   (y_a = 1/2 + j 2^{-53})"
unset colorbox
set key outside bottom center horizontal samplen 1
set style fill solid 1.0 noborder
do for [fig in "fig2_7 fig2_7_errors"] {
do for [term in "png svg"] {
  if (term eq "png") {
    set terminal pngcairo size 1300,720 enhanced font "Sans,14"
    set output outdir."/".fig.".png"
  } else {
    set terminal svg size 1300,720 enhanced font "Sans,14" background rgb "white"
    set output outdir."/".fig.".svg"
  }
  set multiplot layout 1,2
  if (fig eq "fig2_7") {
    set palette defined (-1 "#1a9641", 0 "#ffd700", 1 "#d7191c")
    set cbrange [-1:1]
    set title "naive O(a,b,c) = sign((x_a-x_c)(y_b-y_c) - (y_a-y_c)(x_b-x_c))"
    plot datadir."/map_orient_naive_abc.dat" matrix with image notitle, \
         NaN with boxes lc rgb "#1a9641" title "-1", NaN with boxes lc rgb "#ffd700" title "0", \
         NaN with boxes lc rgb "#d7191c" title "+1"
    set title "naive O(c,b,a) (pivot a)"
    plot datadir."/map_orient_naive_cba.dat" matrix with image notitle, \
         NaN with boxes lc rgb "#1a9641" title "-1", NaN with boxes lc rgb "#ffd700" title "0", \
         NaN with boxes lc rgb "#d7191c" title "+1"
  } else {
    set palette defined (0 "white", 1 "#ff9900", 2 "black", 3 "#2060ff")
    set cbrange [0:3]
    set title "naive O(a,b,c): cells with a wrong sign"
    plot datadir."/err_orient_naive_abc.dat" matrix with image notitle, \
         NaN with boxes lc rgb "#ff9900" title "wrong zero", NaN with boxes lc rgb "black" title "flipped sign"
    set title "naive O(c,b,a): cells with a wrong sign"
    plot datadir."/err_orient_naive_cba.dat" matrix with image notitle, \
         NaN with boxes lc rgb "#ff9900" title "wrong zero", NaN with boxes lc rgb "black" title "flipped sign"
  }
  unset multiplot
  unset output
}
}
