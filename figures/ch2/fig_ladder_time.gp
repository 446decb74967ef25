# The optimisation ladder (opt_ladder): time of each step, from the corrected listings to the
# fast kernel, on the same points. Reads ladder.dat from datadir; writes fig_ladder_time.{png,svg}.
if (!exists("datadir")) datadir = "."
if (!exists("outdir")) outdir = "."
set style data histograms
set style fill solid 0.8 border -1
set boxwidth 0.7
set ylabel "CPU time (s), sorting included"
set xlabel "step (each adds one change to the previous one)"
set title "From the corrected listings to the fast kernel"
set yrange [0:*]
set offsets 0, 0, graph 0.15, 0
set grid ytics
unset key
set xtics rotate by -30 left
plot_cmd = "plot datadir.'/ladder.dat' using 3:xtic(2) linecolor rgb '#4a7ab5', '' using 0:3:(sprintf('%.2f s\\n×%.1f', $3, $4)) with labels offset 0,1.6 font ',10'"
set terminal pngcairo size 900,520 font "DejaVu Sans,11"
set output outdir.'/fig_ladder_time.png'
eval(plot_cmd)
set terminal svg size 900,520 font "DejaVu Sans,11"
set output outdir.'/fig_ladder_time.svg'
eval(plot_cmd)
