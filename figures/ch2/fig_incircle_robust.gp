# New figure (2.3.1): the robust incircle test: (a) whole map with the zoom window marked, (b) a zoom on the corner where the exact zero (i = j = 0) is the only cell on the circle.
# a(1/2,-47/2), b(49/2,-47/2), c(49/2,1/2) lie counter-clockwise on the circle through
# d0(1/2,1/2), tangent there to the diagonal; d(1/2 + i eps, 1/2 + j eps), eps = 2^-53.
# Exactly: inside (+1) below the diagonal, outside (-1) on and above it, 0 only at i = j = 0.
# Data (sec2_3_1_predicates): map_incircle_robust_abcd.dat.
load system("dirname '".ARG0."'")."/style.gp"
Z1 = 15.5  # the zoom window: 0 <= i, j < 16
do for [term in "png svg"] {
  eval fig_open(term, "fig_incircle_robust")
  set output (term eq "png" ? outdir."/fig_incircle_robust.png" : outdir."/fig_incircle_robust.svg")
  set border
  set tics
  set xlabel map_xlabel("𝑑")
  eval layout(1, 2)
  eval sign_bar
  unset colorbox
  set lmargin at screen 0.12  # room for the y label's superscript at the left edge
  set rmargin at screen 0.46
  set ylabel map_ylabel("𝑑") offset 1,0
  set xrange [-0.5:255.5]
  set yrange [-0.5:255.5]
  set xtics 0,64,256 out nomirror
  set ytics 0,64,256 out nomirror
  set object 1 rect from -0.5, -0.5 to Z1, Z1 front fs empty border lc rgb "black" lw 2.5
  eval panel(1, "robust ".M."𝒞(𝑎,𝑏,𝑐,𝑑)}")
  plot datadir."/map_incircle_robust_abcd.dat" matrix with image notitle
  unset object 1
  set lmargin at screen 0.55
  set rmargin at screen 0.89
  unset ylabel
  set colorbox vertical user origin screen 0.915, screen 0.3 size screen 0.018, screen 0.45
  set xrange [-0.5:Z1]
  set yrange [-0.5:Z1]
  set xtics 0,4,16 out nomirror
  set ytics 0,4,16 out nomirror
  eval panel(2, "zoom: 0 ≤ ".M."𝑖}, ".M."𝑗} < 16")
  plot datadir."/map_incircle_robust_abcd.dat" matrix with image notitle
  unset multiplot
  unset output
}
