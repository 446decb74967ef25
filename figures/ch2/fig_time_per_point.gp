# Time per point of the fast kernel against n (bench_parallel). Reads time_per_point.dat and,
# when a run with --max-n >= 10^7 left it, time_per_point_large.dat from datadir; writes
# fig_time_per_point.{png,svg} into outdir.
if (!exists("datadir")) datadir = "."
if (!exists("outdir")) outdir = "."
small = datadir.'/time_per_point.dat'
large = datadir.'/time_per_point_large.dat'
haveLarge = strlen(system("ls '".large."' 2>/dev/null")) > 0
set logscale x
set format x "10^{%T}"
set xlabel "points n (uniform random)"
set ylabel "nanoseconds per point"
set yrange [0:*]
set grid
set key center right
set xrange [500:*]
set offsets 0, graph 0.06, graph 0.05, 0
set title "Fast kernel, one thread: cost per point (sorting included)"
if (haveLarge) {
  plot_cmd = "plot small using 1:2 with linespoints lw 2 pt 7 lc rgb '#4a7ab5' title 'CPU time, total', " . \
    "small using 1:4 with linespoints lw 1.5 pt 5 lc rgb '#d08a2c' title 'of which the sort (BRIO, Hilbert)', " . \
    "small using 1:5 with linespoints lw 1.5 pt 9 lc rgb '#3c9b5c' title 'the rest (insertions, output)', " . \
    "large using 1:2 with points pt 7 ps 1.6 lc rgb '#4a7ab5' title 'total, --max-n run', " . \
    "large using 1:4 with points pt 5 ps 1.4 lc rgb '#d08a2c' notitle, " . \
    "large using 1:5 with points pt 9 ps 1.4 lc rgb '#3c9b5c' notitle"
} else {
  plot_cmd = "plot small using 1:2 with linespoints lw 2 pt 7 lc rgb '#4a7ab5' title 'CPU time, total', " . \
    "small using 1:4 with linespoints lw 1.5 pt 5 lc rgb '#d08a2c' title 'of which the sort (BRIO, Hilbert)', " . \
    "small using 1:5 with linespoints lw 1.5 pt 9 lc rgb '#3c9b5c' title 'the rest (insertions, output)'"
}
set terminal pngcairo size 900,520 font "DejaVu Sans,11"
set output outdir.'/fig_time_per_point.png'
eval(plot_cmd)
set terminal svg size 900,520 font "DejaVu Sans,11"
set output outdir.'/fig_time_per_point.svg'
eval(plot_cmd)
