# Figure 2.11: the curves H1 and H2, with the local frames of Listing 2.8: each quadrant's
# centre x0 (black dot), red half-side r (red arrow) and blue half-side b (blue arrow).
# Data (sec2_3_5_hilbert): fig2_11_h{1,2}.dat (cell centres in curve order, with their
# Hilbert coordinates), fig2_11_frames{1,2}.dat (x0 y0 xRed yRed xBlue yBlue).
if (!exists("datadir")) datadir = "."
if (!exists("outdir")) outdir = "."
set size ratio -1
unset key
set xrange [-0.05:1.05]
set yrange [-0.05:1.12]
set xtics 0, 0.25, 1
set ytics 0, 0.25, 1
set grid back lt 1 lc rgb "#b8b8b8" lw 1
set style arrow 1 head filled size 0.035,20 lw 3 lc rgb "#d02020"
set style arrow 2 head filled size 0.035,20 lw 3 lc rgb "#2040d0"
do for [term in "png svg"] {
  if (term eq "png") {
    set terminal pngcairo size 1300,680 enhanced font "Sans,13"
    set output outdir."/fig2_11.png"
  } else {
    set terminal svg size 1300,680 enhanced font "Sans,13" background rgb "white"
    set output outdir."/fig2_11.svg"
  }
  set multiplot layout 1,2
  do for [k=1:2] {
    set title sprintf("H_%d: %s", k, k == 1 ? "the root frame and the order (0)..(3)" : "the four frames of level 1 and the order (q_0,q_1)")
    if (k == 1) { set xtics 0, 0.5, 1; set ytics 0, 0.5, 1 } else { set xtics 0, 0.25, 1; set ytics 0, 0.25, 1 }
    f = datadir.sprintf("/fig2_11_frames%d.dat", k)
    c = datadir.sprintf("/fig2_11_h%d.dat", k)
    plot c using 1:2 with linespoints lw 2.5 lc rgb "black" pt 7 ps 0.8, \
         f using 1:2:3:4 with vectors arrowstyle 1, \
         f using 1:2:5:6 with vectors arrowstyle 2, \
         f using ($1+$3*0.6+$5*0.12):($2+$4*0.6+$6*0.12):("r") with labels font ",15" tc rgb "#d02020", \
         f using ($1+$5*0.6+$3*0.12):($2+$6*0.6+$4*0.12):("b") with labels font ",15" tc rgb "#2040d0", \
         f using ($1-0.03):($2-0.03):("x_0") with labels font ",13", \
         c using ($1+(k == 1 ? 0.09 : 0.055)):($2-(k == 1 ? 0.07 : 0.045)):3 with labels font (k == 1 ? ",15" : ",11") tc rgb "#404040"
  }
  unset multiplot
}
