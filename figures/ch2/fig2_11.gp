# Figure 2.11: the curves H1 and H2, with the local frames of Listing 2.8: each quadrant's
# centre x0 (black dot), red half-side r (red arrow) and blue half-side b (blue arrow); each
# cell labelled with its Hilbert coordinates (in H_2 without parentheses, to fit).
# Data (sec2_3_5_hilbert): fig2_11_h{1,2}.dat (cell centres in curve order, with their
# Hilbert coordinates), fig2_11_frames{1,2}.dat (x0 y0 xRed yRed xBlue yBlue).
load system("dirname '".ARG0."'")."/style.gp"
do for [term in "png svg"] {
  eval fig_open(term, "fig2_11")
  set output (term eq "png" ? outdir."/fig2_11.png" : outdir."/fig2_11.svg")
  set border
  set tics out nomirror
  set xrange [-0.05:1.05]
  set yrange [-0.05:1.05]
  set grid back lt 1 lc rgb "#c8c8c8" lw 1
  set style arrow 1 head filled size 0.035,20 lw 3 lc rgb C_NEW
  set style arrow 2 head filled size 0.035,20 lw 3 lc rgb C_NEIGH_EDGE
  eval layout(1, 2)
  do for [k=1:2] {
    eval panel(k, k == 1 ? "H_1 and the root frame" : "H_2 and the frames of level 1")
    if (k == 1) { set xtics 0, 0.5, 1; set ytics 0, 0.5, 1 } else { set xtics 0, 0.25, 1; set ytics 0, 0.25, 1 }
    f = datadir.sprintf("/fig2_11_frames%d.dat", k)
    c = datadir.sprintf("/fig2_11_h%d.dat", k)
    plot c using 1:2 with linespoints lw 2.5 lc rgb "black" pt 7 ps (0.8*PS), \
         f using 1:2:3:4 with vectors arrowstyle 1, \
         f using 1:2:5:6 with vectors arrowstyle 2, \
         f using ($1+$3*0.6+$5*0.14):($2+$4*0.6+$6*0.14):("r") with labels tc rgb C_NEW, \
         f using ($1+$5*0.6+$3*0.14):($2+$6*0.6+$4*0.14):("b") with labels tc rgb C_NEIGH_EDGE, \
         f using ($1-0.035):($2-0.035):("x_0") with labels, \
         c using ($1+(k == 1 ? 0.1 : 0.07)):($2-(k == 1 ? 0.08 : 0.068)):(k == 1 ? strcol(3) : substr(strcol(3), 2, strlen(strcol(3)) - 1)) with labels tc rgb "#505050"
  }
  unset multiplot
}
