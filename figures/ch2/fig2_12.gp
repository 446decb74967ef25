# Figure 2.12: Hilbert sort of 1000 and 10000 random points; consecutive points are joined,
# coloured by their rank in the order (colour bar: from the first, dark, to the last, yellow).
# Data (sec2_3_5_hilbert): fig2_12_1000.dat, fig2_12_10000.dat (x y rank).
load system("dirname '".ARG0."'")."/style.gp"
do for [term in "png svg"] {
  eval fig_open(term, "fig2_12")
  set output (term eq "png" ? outdir."/fig2_12.png" : outdir."/fig2_12.svg")
  set border
  set tics out nomirror
  set xtics nomirror; set ytics nomirror
  set xrange [0:1]
  set yrange [0:1]
  set xtics 0, 0.5, 1 nomirror
  set ytics 0, 0.5, 1 nomirror
  set palette defined (0 C_RANK_FIRST, 0.5 C_RANK_MID, 1 C_RANK_LAST)
  set cbrange [0:1]
  set cbtics ("first" 0, "last" 1) scale 0
  set colorbox vertical user origin screen 0.905, screen 0.25 size screen 0.016, screen 0.5
  eval layout(1, 2)
  do for [n in "1000 10000"] {
    set lmargin at screen (n eq "1000" ? 0.08 : 0.50)
    set rmargin at screen (n eq "1000" ? 0.43 : 0.86)
    eval panel(n eq "1000" ? 1 : 2, n." points")
    if (n eq "1000") { unset colorbox } else { set colorbox }
    plot datadir."/fig2_12_".n.".dat" using 1:2:($3 / (n + 0.0)) with lines lw (n eq "1000" ? 1.5 : 1) lc palette notitle
  }
  unset multiplot
}
