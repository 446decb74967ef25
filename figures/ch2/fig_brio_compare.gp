# BRIO against Hilbert-only and random order (2.3.5): mean cavity size, mean walk length and
# time per point against n, on four inputs. Colour: input; line type: order.
# Data (sec2_3_5_hilbert): brio_compare.dat (input n order nsearch ncavity t us_per_point).
if (!exists("datadir")) datadir = "."
if (!exists("outdir")) outdir = "."
f = datadir."/brio_compare.dat"
names = "uniform clustered parabola jittered-grid"
orders = "random Hilbert BRIO"
colors = "#1f77b4 #d62728 #2ca02c #9467bd"
set logscale x
set format x "10^{%T}"
set grid lc rgb "#d0d0d0"
set xlabel "n"
do for [term in "png svg"] {
  if (term eq "png") {
    set terminal pngcairo size 1600,560 enhanced font "Sans,12"
    set output outdir."/fig_brio_compare.png"
  } else {
    set terminal svg size 1600,560 enhanced font "Sans,12" background rgb "white"
    set output outdir."/fig_brio_compare.svg"
  }
  set multiplot layout 1,3
  do for [col in "5 4 7"] {
    c = col + 0
    set title (c == 5 ? "N_{cavity}: mean cavity size" : (c == 4 ? "N_{search}: mean walk length" : "time per point (µs), ordering included"))
    set logscale y
    if (c == 5) { set key top left font ",10" spacing 1.0 } else { unset key }
    plot for [k = 0:7] f using ($1 == int(k/2) && $3 == k%2 + 1 ? $2 : NaN):c \
           with linespoints lw 2 dt 1+k%2 pt (k%2 == 0 ? 7 : 5) ps 0.9 \
           lc rgb word(colors, int(k/2) + 1) title word(names, int(k/2) + 1)." ".word(orders, k%2 + 2), \
         for [i = 0:3] f using ($1 == i && $3 == 0 ? $2 : NaN):c with points pt 9 ps 1.6 lc rgb word(colors, i + 1) \
           title (i == 0 ? "random order (triangles)" : "")
  }
  unset multiplot
}
