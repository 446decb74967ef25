# The worst case of 2.3.4: points on y = x^2, x = -n..-1, inserted in increasing x. The size of
# the cavity of the i-th point: with ghost faces every previous triangle is in it.
load system("dirname '".ARG0."'")."/style.gp"
do for [term in "png svg"] {
  eval fig_open(term, "fig_parabola_cavity")
  set output (term eq "png" ? outdir."/fig_parabola_cavity.png" : outdir."/fig_parabola_cavity.svg")
  set size noratio
  set border
  set tics out nomirror
  set xtics nomirror; set ytics nomirror
  set xlabel "point i of (x, x^2), x = -n..-1, inserted in increasing x"
  set ylabel "faces in the cavity of point i"
  set key top left
  set grid lc rgb "#d8d8d8" lw 1
  set logscale y
  plot datadir."/parabola_cavity.dat" using 1:3 with lines lw 2.5 lc rgb word(C_SERIES, 1) title "DT(S) with ghost faces", \
       datadir."/parabola_cavity.dat" using 1:2 with lines lw 2.5 lc rgb word(C_SERIES, 2) title "super-triangles (Listing 2.7)"
}
