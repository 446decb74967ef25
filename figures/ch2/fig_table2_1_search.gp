# Table 2.1 as a graph: N_search (faces visited by lineSearch per insertion) against n, this
# library (table2_1.dat) and the notes' four values (table2_1_notes.dat, the notes' data), with
# the sqrt(n) slope through our first point over the notes' sizes (table2_1_sqrt.dat).
load system("dirname '".ARG0."'")."/style.gp"
do for [term in "png svg"] {
  eval fig_open(term, "fig_table2_1_search")
  set output (term eq "png" ? outdir."/fig_table2_1_search.png" : outdir."/fig_table2_1_search.svg")
  set size noratio
  set border
  set tics out nomirror
  set xtics nomirror; set ytics nomirror
  set logscale xy
  set xlabel M."𝑛}"." (random points, random order; log scale)"
  set ylabel M."𝑁_{search}}"." (log scale)"
  # The legend at the top left, over the data: the y axis reaches 4000, so the data (at most
  # the notes' 503) stay under the legend's three rows.
  set key top left Left reverse samplen 2.5 spacing 1.1 width 1
  set grid lc rgb C_GRID lw 1
  # Frame: the notes' sizes with a margin, N_search from a little under the first value to a
  # little over the last.
  set xrange [600:1.7e6]
  set format x "10^{%T}"
  set yrange [10:4000]
  plot datadir."/table2_1_sqrt.dat" using 1:2 with lines lw 1.5 dt 3 lc rgb C_CONSTRUCT title "slope 1/2 (".M."𝑁 ∝ √𝑛})", \
       datadir."/table2_1_notes.dat" using 1:2 with linespoints pt 6 ps (1.3*PS) lw 2 dt 2 lc rgb word(C_SERIES, 2) title "notes' Table 2.1", \
       datadir."/table2_1.dat" using 1:2 with linespoints pt 7 ps (1.3*PS) lw 2 lc rgb word(C_SERIES, 1) title "this library"
}
