# The worst case of 2.3.4: points on y = x^2, x = -n..-1, inserted in increasing x. The size of
# the cavity of the i-th point: with ghost faces every previous triangle is in it.
if (!exists("datadir")) datadir = "."
if (!exists("outdir")) outdir = "."
set xlabel "point i of (x, x^2), x = -n..-1, inserted in increasing x"
set ylabel "faces in the Delaunay cavity of point i"
set key right center
set grid
set logscale y
do for [term in "png svg"] {
  if (term eq "png") {
    set terminal pngcairo size 800,560 enhanced font "Sans,12"
    set output outdir."/fig_parabola_cavity.png"
  } else {
    set terminal svg size 800,560 enhanced font "Sans,12" background rgb "white"
    set output outdir."/fig_parabola_cavity.svg"
  }
  plot datadir."/parabola_cavity.dat" using 1:3 with lines lw 2 title "DT(S) with ghost faces", \
       datadir."/parabola_cavity.dat" using 1:2 with lines lw 2 title "super-triangles (Listing 2.7)"
}
