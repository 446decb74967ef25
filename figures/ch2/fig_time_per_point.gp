# Time per point of the fast kernel against n (bench_parallel). Reads time_per_point.dat and,
# when a run with --max-n >= 10^7 left it, time_per_point_large.dat from datadir; writes
# fig_time_per_point.{png,svg} into outdir. The cache markers: time_per_point_view.gp (the
# chart's x range nlo to nhi, the number of markers ncaches, the top y2hi of y2, the plot's
# margins in screen units), time_per_point_cache_lines.dat (one vertical line per marker, y2
# from 0 to 1) and time_per_point_caches.dat (n, label, its height in y2, its centre), all
# written by bench_parallel, which places the labels in the pixels these margins give.
load system("dirname '".ARG0."'")."/style.gp"
small = datadir.'/time_per_point.dat'
large = datadir.'/time_per_point_large.dat'
load datadir.'/time_per_point_view.gp'
cacheLines = datadir.'/time_per_point_cache_lines.dat'
cacheLabels = datadir.'/time_per_point_caches.dat'
haveLarge = strlen(system('ls -- "${DT_DATADIR:-.}/time_per_point_large.dat" 2>/dev/null')) > 0
# Point sizes in the style's PS (without it the svg terminal drew the points five times larger
# than pngcairo).
curves = "plot small using 1:2 with linespoints lw 2 pt 7 ps (1.2*PS) lc rgb word(C_SERIES, 1) title 'total', " . \
  "small using 1:4 with linespoints lw 1.5 pt 5 ps (1.2*PS) lc rgb word(C_SERIES, 5) title 'the sort', " . \
  "small using 1:5 with linespoints lw 1.5 pt 9 ps (1.2*PS) lc rgb word(C_SERIES, 3) title 'the rest'"
extra = ", large using 1:2 with points pt 7 ps (1.6*PS) lc rgb word(C_SERIES, 1) title 'total (a --max-n run)', " . \
  "large using 1:4 with points pt 5 ps (1.4*PS) lc rgb word(C_SERIES, 5) notitle, " . \
  "large using 1:5 with points pt 9 ps (1.4*PS) lc rgb word(C_SERIES, 3) notitle"
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
  set xrange [nlo:nhi]
  set yrange [0:*]
  # The plot where bench_parallel placed the cache labels: margins at screen fractions, the same
  # pixels on both terminals. Above the curves a band for the markers' labels (y2 over 1, up to
  # y2hi): the curves end a little below the lines' top. Under the plot, from the bottom of the
  # canvas: the key (one row: below the chart, so that the cache markers never meet it), the x
  # label, the tick labels 10^k; left of it the y label. Each at a fixed place in em: as an
  # xlabel, a ylabel and a key below, each terminal put them elsewhere (the svg terminal's
  # estimate of a line is taller than its text), onto each other or past the canvas.
  set lmargin at screen marginL; set rmargin at screen marginR
  set bmargin at screen marginB; set tmargin at screen marginT
  set offsets 0, 0, graph (y2hi + 0.04 - 1), 0
  set y2range [0:y2hi]
  set label 101 "points ".M."𝑛}"." (uniform random)" at graph 0.5, screen 2.3 * EM / FH center
  set label 102 "CPU ns per point" at screen 1.0 * EM / FW, graph 0.5 center rotate by 90
  set grid xtics ytics lc rgb C_GRID lw 1
  unset x2tics; unset y2tics
  set xtics nomirror; set ytics nomirror
  set key at screen 0.5, screen 0.9 * EM / FH center center vertical maxrows 1 Left reverse samplen 1.5 width 1
  eval(plot_cmd)
}
