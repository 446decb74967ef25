# Figure 2.8: the robust orientation test (floating-point filter with a proven error bound, exact
# fallback) on the grid of Figure 2.7: (a) the whole 256 x 256 map of O(a,b,c), with the zoom
# window marked; (b) the zoom on 32 x 32 cells around the diagonal, where only the diagonal
# (i = j, a on the line bc) is 0. Colour bar: -1 blue, 0 yellow, +1 red.
# Data (sec2_3_1_predicates): map_orient_robust_abc.dat.
load system("dirname '".ARG0."'")."/style.gp"
Z0 = 111.5; Z1 = 143.5  # the zoom window
do for [term in "png svg"] {
  eval fig_open(term, "fig2_8")
  set output (term eq "png" ? outdir."/fig2_8.png" : outdir."/fig2_8.svg")
  set border
  set tics
  set xlabel map_xlabel("𝑎")
  eval layout(1, 2)
  eval sign_bar
  unset colorbox
  set lmargin at screen 0.12  # room for the y label's superscript at the left edge
  set rmargin at screen 0.46
  set ylabel map_ylabel("𝑎") offset 1,0
  set xrange [-0.5:255.5]
  set yrange [-0.5:255.5]
  set xtics 0,64,256 out nomirror
  set ytics 0,64,256 out nomirror
  set object 1 rect from Z0, Z0 to Z1, Z1 front fs empty border lc rgb "black" lw 2.5
  eval panel(1, "robust ".M."𝒪(𝑎,𝑏,𝑐)}")
  plot datadir."/map_orient_robust_abc.dat" matrix with image notitle
  unset object 1
  set lmargin at screen 0.55
  set rmargin at screen 0.89
  unset ylabel
  set colorbox vertical user origin screen 0.915, screen 0.3 size screen 0.018, screen 0.45
  set xrange [Z0:Z1]
  set yrange [Z0:Z1]
  set xtics 112,8,144 out nomirror
  set ytics 112,8,144 out nomirror
  eval panel(2, "zoom: 112 ≤ ".M."𝑖}, ".M."𝑗} < 144")
  plot datadir."/map_orient_robust_abc.dat" matrix with image notitle
  unset multiplot
  unset output
}
