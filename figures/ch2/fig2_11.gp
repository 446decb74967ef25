# Figure 2.11: the curves ℋ_1 and ℋ_2, with the local frames of Listing 2.8: each quadrant's
# centre x0 (black dot), red half-side r (red arrow) and blue half-side b (blue arrow); each
# cell labelled with its Hilbert coordinates (k0, k1) beside its centre.
# Data (sec2_3_5_hilbert): fig2_11_h{1,2}.dat (cell centres in curve order, with their
# Hilbert coordinates and where their labels go), fig2_11_frames{1,2}.dat (x0 y0 xRed yRed xBlue yBlue).
load system("dirname '".ARG0."'")."/style.gp"
do for [term in "png svg"] {
  eval fig_open(term, "fig2_11")
  set output (term eq "png" ? outdir."/fig2_11.png" : outdir."/fig2_11.svg")
  set border
  set tics out nomirror
  set xtics nomirror; set ytics nomirror
  set xrange [-0.07:1.07]  # room for the labels beside the curve at x = 1/8 and 7/8
  set yrange [-0.05:1.05]
  set grid back lt 1 lc rgb C_GRID lw 1

  eval layout(1, 2)
  do for [k=1:2] {
    eval panel(k, k == 1 ? M."ℋ_1} and the root frame" : M."ℋ_2} and the frames of level 1")
    if (k == 1) { set xtics 0, 0.5, 1 nomirror; set ytics 0, 0.5, 1 nomirror } else { set xtics 0, 0.25, 1 nomirror; set ytics 0, 0.25, 1 nomirror }
    f = datadir.sprintf("/fig2_11_frames%d.dat", k)
    c = datadir.sprintf("/fig2_11_h%d.dat", k)
    # The arrows end short of the quadrant's side (0.7), so that no two heads meet. The labels
    # r, b and x0 sit on the side of each arrow away from the other one, 0.3 along it; a cell's
    # coordinates (k0, k1) sit where the program put them (columns 4, 5), off the curve.
    plot c using 1:2 with linespoints lw 2.5 lc rgb "black" pt 7 ps (0.8*PS), \
         f using 1:2:($3*0.7):($4*0.7) with vectors head filled size 0.035,20 lw 3 lc rgb C_NEW, \
         f using 1:2:($5*0.7):($6*0.7) with vectors head filled size 0.035,20 lw 3 lc rgb C_NEIGH_EDGE, \
         f using 1:2 with points pt 7 ps (1.2*PS) lc rgb "black", \
         f using ($1+$3*0.3-$5*(k == 1 ? 0.16 : 0.22)):($2+$4*0.3-$6*(k == 1 ? 0.16 : 0.22)):(M."𝑟}") with labels tc rgb C_NEW, \
         f using ($1+$5*0.3-$3*(k == 1 ? 0.16 : 0.22)):($2+$6*0.3-$4*(k == 1 ? 0.16 : 0.22)):(M."𝑏}") with labels tc rgb C_NEIGH_EDGE, \
         f using ($1-($3+$5)*(k == 1 ? 0.16 : 0.25)):($2-($4+$6)*(k == 1 ? 0.16 : 0.25)):(M."𝑥_0}") with labels, \
         c using 4:5:3 with labels tc rgb C_MUTED font sprintf(",%.1f", 0.85 * FS)
  }
  unset multiplot
}
