# Figure 2.2: a star-shaped polygon Σ and its kernel ker(Σ), computed by intersecting the
# half-planes left of its oriented edges (edge lines dotted), with a point x of the kernel and
# its sight lines to every corner σ_j. Data (sec2_1_kernel): fig2_2_polygon.dat,
# fig2_2_kernel.dat, fig2_2_sight.dat, fig2_2_lines.dat, fig2_2_labels.dat, fig2_2_x.dat.
if (!exists("datadir")) datadir = "."
if (!exists("outdir")) outdir = "."
set size ratio -1
unset key
unset border
unset tics
set xrange [-1.3:1.35]
set yrange [-1.3:1.3]
do for [term in "png svg"] {
  if (term eq "png") {
    set terminal pngcairo size 800,800 enhanced font "Sans,14"
    set output outdir."/fig2_2.png"
  } else {
    set terminal svg size 800,800 enhanced font "Sans,14" background rgb "white"
    set output outdir."/fig2_2.svg"
  }
  set title "a star-shaped polygon Σ, its kernel ker(Σ) (shaded) and a point x ∈ ker(Σ)"
  plot datadir."/fig2_2_polygon.dat" with filledcurves closed fc rgb "#e8eef8" fs solid 1.0, \
       datadir."/fig2_2_lines.dat" with lines lw 1 dt 3 lc rgb "#a0a0a0", \
       datadir."/fig2_2_kernel.dat" with filledcurves closed fc rgb "#f2a65a" fs solid 1.0, \
       datadir."/fig2_2_kernel.dat" with lines lw 2 lc rgb "#b05a00", \
       datadir."/fig2_2_sight.dat" with lines lw 1.2 lc rgb "#2e8b57", \
       datadir."/fig2_2_polygon.dat" with lines lw 2.5 lc rgb "#203060", \
       datadir."/fig2_2_polygon.dat" with points pt 7 ps 0.8 lc rgb "#203060", \
       datadir."/fig2_2_labels.dat" using 1:2:3 with labels font ",13" tc rgb "#203060", \
       datadir."/fig2_2_x.dat" with points pt 7 ps 1.4 lc rgb "#d02020", \
       datadir."/fig2_2_x.dat" using 1:2:("x") with labels offset -1.2,1.0 font ",16" tc rgb "#d02020", \
       datadir."/fig2_2_kernel.dat" every ::0::0 using (0.08):(-0.14):("ker(Σ)") with labels font ",15" tc rgb "#703000"
  unset multiplot
}
