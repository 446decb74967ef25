# BRIO (2.3.5): 4000 uniform points in BRIO order. Each panel shows one of the last three
# rounds, joined in its own Hilbert order and coloured by rank in it, as Figure 2.12 does (from
# the first, dark, to the last, yellow; one colour bar at the right), with the points of the
# earlier rounds (grey) on top.
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
  set palette defined (0 C_RANK_FIRST, 0.5 C_RANK_MID, 1 C_RANK_LAST)
  set cbrange [0:1]
  set cbtics ("first" 0, "last" 1) scale 0
  # The three cells share the canvas less 5.5 em at the right, where the colour bar stands.
  wcell = (1 - 5.5 * EM / FW) / 3
  set colorbox vertical user origin screen (1 - 4.6 * EM / FW), screen 0.3 size screen (0.7 * EM / FW), screen 0.4
  unset colorbox
  eval layout(1, 3)
  # Each square as large as its cell allows (at gnuplot's margins they were 3 cm wide
  # on a 15-cm canvas): the cell's width less the tick labels, its height less title and tics.
  set tmargin at screen 1 - 2.3 * EM / FH
  set bmargin at screen 3.0 * EM / FH
  do for [r = R-3:R-1] {
    k = r - R + 3
    set lmargin at screen k * wcell + 3.4 * EM / FW
    set rmargin at screen (k + 1) * wcell - 0.6 * EM / FW
    if (k == 2) { set colorbox } else { unset colorbox }
    eval panel(r - R + 4, sprintf("round %d of %d: %s points", r + 1, R, word(sizes, r + 1)))
    # $0: a point's rank in its round (the line within the block).
    m = word(sizes, r + 1) - 1.0
    plot datadir."/fig_brio_rounds.dat" index r using 1:2:($0 / m) with lines lw 1 lc palette notitle, \
         for [q = 0:r-1] datadir."/fig_brio_rounds.dat" index q using 1:2 with points pt 7 ps (0.3*PS) lc rgb C_PENDING notitle
  }
  unset multiplot
}
