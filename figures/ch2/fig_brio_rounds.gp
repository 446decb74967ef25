# BRIO (2.3.5): 4000 uniform points in BRIO order. Each panel shows one of the last three
# rounds, joined in its own Hilbert order, over the points of the earlier rounds (grey).
# Data (sec2_3_5_hilbert): fig_brio_rounds.dat, one gnuplot block (index) per round.
load system("dirname '".ARG0."'")."/style.gp"
info = system('cat -- "${DT_DATADIR:-.}/fig_brio_rounds.info"')
R = int(word(substr(info, strstrt(info, "=") + 1, strlen(info)), 1))
sizes = system('sed -n 2p -- "${DT_DATADIR:-.}/fig_brio_rounds.info"')
do for [term in "png svg"] {
  eval fig_open(term, "fig_brio_rounds")
  set output (term eq "png" ? outdir."/fig_brio_rounds.png" : outdir."/fig_brio_rounds.svg")
  set border
  set tics out nomirror
  set xtics nomirror; set ytics nomirror
  set xrange [0:1]
  set yrange [0:1]
  set xtics 0, 0.5, 1 nomirror offset 0, (term eq "svg" ? 0.4 : 0)  # the svg terminal sets tick labels lower than pngcairo
  set ytics 0, 0.5, 1 nomirror
  eval layout(1, 3)
  # Each square as large as its cell allows (at gnuplot's margins they were 3 cm wide
  # on a 15-cm canvas): the cell's width less the tick labels, its height less title and tics.
  set tmargin at screen 1 - 2.3 * EM / FH
  set bmargin at screen 3.0 * EM / FH
  do for [r = R-3:R-1] {
    k = r - R + 3
    set lmargin at screen (k + 0.0) / 3 + 3.4 * EM / FW
    set rmargin at screen (k + 1.0) / 3 - 0.6 * EM / FW
    eval panel(r - R + 4, sprintf("round %d of %d: %s points", r + 1, R, word(sizes, r + 1)))
    plot for [q = 0:r-1] datadir."/fig_brio_rounds.dat" index q using 1:2 with points pt 7 ps (0.2*PS) lc rgb C_PENDING, \
         datadir."/fig_brio_rounds.dat" index r using 1:2 with linespoints lw 1 pt 7 ps (0.25*PS) lc rgb word(C_SERIES, 1)
  }
  unset multiplot
}
