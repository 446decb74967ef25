# Table 2.1 as a graph: N_search (faces visited by lineSearch per insertion) against n, this
# library and the notes, with the sqrt(n) slope through our first point (table2_1_sqrt.dat).
if (!exists("datadir")) datadir = "."
if (!exists("outdir")) outdir = "."
set logscale xy
set xlabel "n (random points, random order)"
set ylabel "N_{search}"
set key top left
set grid
set xrange [500:2e6]
set format x "10^{%T}"
set yrange [10:1000]
do for [term in "png svg"] {
  if (term eq "png") {
    set terminal pngcairo size 800,560 enhanced font "Sans,12"
    set output outdir."/fig_table2_1_search.png"
  } else {
    set terminal svg size 800,560 enhanced font "Sans,12" background rgb "white"
    set output outdir."/fig_table2_1_search.svg"
  }
  plot datadir."/table2_1.dat" using 1:2 with linespoints pt 7 ps 1.3 lw 2 title "this library", \
       datadir."/table2_1.dat" using 1:5 with linespoints pt 6 ps 1.3 lw 2 dt 2 title "notes' Table 2.1", \
       datadir."/table2_1_sqrt.dat" using 1:2 with lines lw 1.5 lc rgb "gray" title "slope 1/2 (N {/Symbol \265} n^{1/2})"
}
