# The optimisation ladder (opt_ladder): time of each step, from the corrected listings to the
# fast kernel, on the same points (each time the median of the runs, log scale). Reads ladder.dat from datadir; writes fig_ladder_time.{png,svg}.
load system("dirname '".ARG0."'")."/style.gp"
do for [t in "png svg"] {
  eval fig_open(t, "fig_ladder_time")
  set output (t eq "png" ? outdir.'/fig_ladder_time.png' : outdir.'/fig_ladder_time.svg')
  set size noratio
  set border 3
  set tics out nomirror
  set xtics nomirror; set ytics nomirror
  set style data histograms
  set style fill solid 0.85 border -1
  set boxwidth 0.7
  set ylabel "CPU time (s)"  # the caption says the sort is included: the longer label ran past the canvas
  set xlabel "step (each adds one change)"  # longer, it ran past the canvas at 8 cm
  # Log scale: the times span about a decade, and on a linear axis every bar after the first
  # two looked alike (tests/test_figures_rules.cpp: a series over a decade gets a log axis).
  set logscale y
  stats datadir.'/ladder.dat' using 3 nooutput
  set yrange [STATS_min / 2:STATS_max * 4]
  set format y "%g"
  set grid ytics lc rgb C_GRID lw 1
  set xtics rotate by -45 left nomirror  # at -30 the names of neighbouring bars met
  set ytics nomirror
  set rmargin 6
  plot datadir.'/ladder.dat' using 3:xtic(2) linecolor rgb word(C_SERIES, 1), \
       '' using 0:3:(sprintf("×%.1f", $4)) with labels rotate by 90 left offset 0,0.5  # upright, they overlapped (a bar is 2 em wide)
}
