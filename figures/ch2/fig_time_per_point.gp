# Time per point of the fast kernel against n (bench_parallel). Reads time_per_point.dat and,
# when a run with --max-n >= 10^7 left it, time_per_point_large.dat from datadir; writes
# fig_time_per_point.{png,svg} into outdir.
load system("dirname '".ARG0."'")."/style.gp"
small = datadir.'/time_per_point.dat'
large = datadir.'/time_per_point_large.dat'
haveLarge = strlen(system('ls -- "${DT_DATADIR:-.}/time_per_point_large.dat" 2>/dev/null')) > 0
curves = "plot small using 1:2 with linespoints lw 2 pt 7 lc rgb word(C_SERIES, 1) title 'total (sort included)', " . \
  "small using 1:4 with linespoints lw 1.5 pt 5 lc rgb word(C_SERIES, 5) title 'the sort (BRIO, Hilbert)', " . \
  "small using 1:5 with linespoints lw 1.5 pt 9 lc rgb word(C_SERIES, 3) title 'the rest (insertions, output)'"
extra = ", large using 1:2 with points pt 7 ps 1.6 lc rgb word(C_SERIES, 1) title 'total, from a --max-n run', " . \
  "large using 1:4 with points pt 5 ps 1.4 lc rgb word(C_SERIES, 5) notitle, " . \
  "large using 1:5 with points pt 9 ps 1.4 lc rgb word(C_SERIES, 3) notitle"
plot_cmd = haveLarge ? curves . extra : curves
do for [t in "png svg"] {
  eval fig_open(t, "fig_time_per_point")
  set output (t eq "png" ? outdir.'/fig_time_per_point.png' : outdir.'/fig_time_per_point.svg')
  set size noratio
  set border 3
  set tics out nomirror
  set xtics nomirror; set ytics nomirror
  set logscale x
  set format x "10^{%T}"
  set xlabel "points n (uniform random)"
  set ylabel "nanoseconds per point (CPU)"
  set xrange [500:*]
  set yrange [0:*]
  # Headroom above the curves for the key (top left): with measured times the curves go anywhere.
  set offsets 0, graph 0.06, graph 0.40, 0
  set grid xtics ytics lc rgb "#c4c4c4" lw 1
  unset x2tics; unset y2tics
  set xtics nomirror; set ytics nomirror
  set key inside top left Left reverse samplen 1.5 spacing 1.0
  eval(plot_cmd)
}
