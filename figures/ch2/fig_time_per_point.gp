# Time per point of the fast kernel against n (bench_parallel). Reads time_per_point.dat and,
# when a run with --max-n >= 10^7 left it, time_per_point_large.dat from datadir; writes
# fig_time_per_point.{png,svg} into outdir. The cache markers: time_per_point_view.gp (the
# chart's x range nlo to nhi, the number of markers ncaches), time_per_point_cache_lines.dat
# (one vertical line per marker, y2 from 0 to 1) and time_per_point_caches.dat (n, label, its
# height in y2, its centre), all written by bench_parallel; y2 is the graph's height, 0 to 1.16.
load system("dirname '".ARG0."'")."/style.gp"
small = datadir.'/time_per_point.dat'
large = datadir.'/time_per_point_large.dat'
load datadir.'/time_per_point_view.gp'
cacheLines = datadir.'/time_per_point_cache_lines.dat'
cacheLabels = datadir.'/time_per_point_caches.dat'
haveLarge = strlen(system('ls -- "${DT_DATADIR:-.}/time_per_point_large.dat" 2>/dev/null')) > 0
curves = "plot small using 1:2 with linespoints lw 2 pt 7 lc rgb word(C_SERIES, 1) title 'total', " . \
  "small using 1:4 with linespoints lw 1.5 pt 5 lc rgb word(C_SERIES, 5) title 'the sort', " . \
  "small using 1:5 with linespoints lw 1.5 pt 9 lc rgb word(C_SERIES, 3) title 'the rest'"
extra = ", large using 1:2 with points pt 7 ps 1.6 lc rgb word(C_SERIES, 1) title 'total (a --max-n run)', " . \
  "large using 1:4 with points pt 5 ps 1.4 lc rgb word(C_SERIES, 5) notitle, " . \
  "large using 1:5 with points pt 9 ps 1.4 lc rgb word(C_SERIES, 3) notitle"
markers = ", cacheLines using 1:2 axes x1y2 with lines lw 1.5 dt 2 lc rgb C_CONSTRUCT notitle, " . \
  "cacheLabels using 4:3:2 axes x1y2 with labels center notitle"
plot_cmd = (haveLarge ? curves . extra : curves) . (ncaches > 0 ? markers : "")
do for [t in "png svg"] {
  eval fig_open(t, "fig_time_per_point")
  set output (t eq "png" ? outdir.'/fig_time_per_point.png' : outdir.'/fig_time_per_point.svg')
  set size noratio
  set border 3
  set tics out nomirror
  set xtics nomirror; set ytics nomirror
  set logscale x
  set format x "10^{%T}"
  set xlabel "points n (uniform random)" offset 0, 0.4
  set ylabel "nanoseconds per point (CPU)"
  set xrange [nlo:nhi]
  set yrange [0:*]
  # The key is below the chart, so that the cache markers never meet it; above the curves a
  # band for the markers' labels (y2 1.04 and 1.10, of 1.16): the curves end at 0.83 of the
  # height (1 / 1.2), the lines at 0.86.
  set offsets 0, 0, graph 0.20, 0
  set y2range [0:1.16]
  unset y2tics
  set grid xtics ytics lc rgb "#c4c4c4" lw 1
  unset x2tics; unset y2tics
  set xtics nomirror; set ytics nomirror
  set key outside below center horizontal Left reverse samplen 1.5 spacing 1.0 width 1
  eval(plot_cmd)
}
