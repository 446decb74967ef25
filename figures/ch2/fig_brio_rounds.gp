# BRIO (2.3.5): 4000 uniform points in BRIO order. Each panel shows one of the last three
# rounds, joined in its own Hilbert order, over the points of the earlier rounds (grey).
# Data (sec2_3_5_hilbert): fig_brio_rounds.dat, one gnuplot block (index) per round.
if (!exists("datadir")) datadir = "."
if (!exists("outdir")) outdir = "."
info = system("cat '".datadir."/fig_brio_rounds.info'")
R = int(word(substr(info, strstrt(info, "=") + 1, strlen(info)), 1))
sizes = system("sed -n 2p '".datadir."/fig_brio_rounds.info'")
set size ratio -1
unset key
set xrange [0:1]
set yrange [0:1]
set tics out nomirror
do for [term in "png svg"] {
  if (term eq "png") {
    set terminal pngcairo size 1500,560 enhanced font "Sans,12"
    set output outdir."/fig_brio_rounds.png"
  } else {
    set terminal svg size 1500,560 enhanced font "Sans,12" background rgb "white"
    set output outdir."/fig_brio_rounds.svg"
  }
  set multiplot layout 1,3
  do for [r = R-3:R-1] {
    set title sprintf("round %d of %d: %s points (earlier rounds in grey)", r + 1, R, word(sizes, r + 1))
    plot for [q = 0:r-1] datadir."/fig_brio_rounds.dat" index q using 1:2 with points pt 7 ps 0.35 lc rgb "#a0a0a0", \
         datadir."/fig_brio_rounds.dat" index r using 1:2 with linespoints lw 1 pt 7 ps 0.35 lc rgb "#c03060"
  }
  unset multiplot
}
