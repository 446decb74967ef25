# Figure 2.7: the naive orientation test on b(12,12), c(24,24), a(1/2 + i eps, 1/2 + j eps),
# eps = 2^-53, 0 <= i, j < 256. (a) O(a,b,c) (pivot c), (b) O(c,b,a) (pivot a).
# Blue -1, yellow 0, red +1 (style.gp's sign colours; colour bar with the three values).
# Also fig2_7_errors: where each map differs from the exact sign; and fig2_7_deuteranopia: the
# figure as a deuteranope sees it (the sign colours simulated by sec2_3_1_predicates, in
# sign_colours_deuteranopia.gp).
# Data (sec2_3_1_predicates): map_orient_naive_{abc,cba}.dat, err_orient_naive_{abc,cba}.dat
# (n x n matrices, row j, column i).
load system("dirname '".ARG0."'")."/style.gp"
load datadir."/sign_colours_deuteranopia.gp"
O_ABC = M."𝒪(𝑎,𝑏,𝑐)}"
O_CBA = M."𝒪(𝑐,𝑏,𝑎)}"
do for [fig in "fig2_7 fig2_7_errors fig2_7_deuteranopia"] {
do for [term in "png svg"] {
  eval fig_open(term, fig)
  set border
  set tics
  set xrange [-0.5:255.5]
  set yrange [-0.5:255.5]
  set xtics 0,64,256 out nomirror
  set ytics 0,64,256 out nomirror
  set xlabel map_xlabel("𝑎")
  if (fig eq "fig2_7") {
    set output (term eq "png" ? outdir."/fig2_7.png" : outdir."/fig2_7.svg")
  }
  if (fig eq "fig2_7_errors") {
    set output (term eq "png" ? outdir."/fig2_7_errors.png" : outdir."/fig2_7_errors.svg")
  }
  if (fig eq "fig2_7_deuteranopia") {
    set output (term eq "png" ? outdir."/fig2_7_deuteranopia.png" : outdir."/fig2_7_deuteranopia.svg")
  }
  eval layout(1, 2)
  # Two maps of one size, the colour bar right of (b); (b) shares (a)'s y label.
  L1 = 0.12; R1 = L1 + (fig eq "fig2_7_errors" ? 0.31 : 0.34)
  L2 = R1 + 0.09; R2 = L2 + R1 - L1
  set lmargin at screen L1
  set rmargin at screen R1
  set ylabel map_ylabel("𝑎") offset 1,0
  if (fig ne "fig2_7_errors") {
    if (fig eq "fig2_7") { eval sign_bar } else { eval sign_bar_of(D_MINUS, D_ZERO, D_PLUS) }
    seen = (fig eq "fig2_7" ? "" : ", deuteranopia")
    unset colorbox
    eval panel(1, "naive ".O_ABC.seen)
    plot datadir."/map_orient_naive_abc.dat" matrix with image notitle
    set lmargin at screen L2
    set rmargin at screen R2
    unset ylabel
    set colorbox vertical user origin screen R2 + 0.025, screen 0.3 size screen 0.018, screen 0.45
    eval panel(2, "naive ".O_CBA.seen)
    plot datadir."/map_orient_naive_cba.dat" matrix with image notitle
  } else {
    set palette defined (-0.5 "white", 0.5 "white", 0.5 C_ZERO, 1.5 C_ZERO, 1.5 "black", 2.5 "black", 2.5 C_ERR_SIGN, 3.5 C_ERR_SIGN)
    set cbrange [-0.5:3.5]
    set cbtics ("right" 0, "0, not ±1" 1, "flipped" 2, "±1, not 0" 3) scale 0
    unset colorbox
    eval panel(1, "errors of naive ".O_ABC)
    plot datadir."/err_orient_naive_abc.dat" matrix with image notitle
    set lmargin at screen L2
    set rmargin at screen R2
    unset ylabel
    set colorbox vertical user origin screen R2 + 0.025, screen 0.3 size screen 0.018, screen 0.45
    eval panel(2, "errors of naive ".O_CBA)
    plot datadir."/err_orient_naive_cba.dat" matrix with image notitle
  }
  unset multiplot
  unset output
  set cbtics auto
}
}
