# Figure 2.2: a star-shaped polygon Σ and its kernel ker(Σ), computed by intersecting the
# half-planes left of its oriented edges (edge lines dotted, clipped to the view by the
# program), with a point x of the kernel and its sight lines to every corner σ_j.
# Data (sec2_1_kernel): fig2_2_polygon.dat, fig2_2_kernel.dat, fig2_2_sight.dat,
# fig2_2_lines.dat, fig2_2_labels.dat, fig2_2_x.dat, fig2_2_xlabel.dat, fig2_2_view.gp.
load system("dirname '".ARG0."'")."/style.gp"
load datadir."/fig2_2_view.gp"
set xrange [X0:X1]
set yrange [Y0:Y1]
# ker(Σ) is labelled below left, with an arrow to a point inside the kernel near its lowest
# corner (the sight lines fill the kernel's middle).
stats datadir."/fig2_2_kernel.dat" using 1:2 nooutput
kx = STATS_mean_x; ky = STATS_mean_y
stats datadir."/fig2_2_kernel.dat" using ($1 + $2) nooutput
i0 = STATS_index_min
stats datadir."/fig2_2_kernel.dat" every ::i0::i0 using 1 nooutput
lx = STATS_min
stats datadir."/fig2_2_kernel.dat" every ::i0::i0 using 2 nooutput
ly = STATS_min
set arrow 1 from X0 + 0.45, Y0 + 0.45 to 0.5 * (kx + lx), 0.5 * (ky + ly) lw 1.5 lc rgb C_CAVITY_EDGE front
set label 1 "ker(Σ)" at X0 + 0.2, Y0 + 0.38 tc rgb C_CAVITY_EDGE front
do for [term in "png svg"] {
  eval fig_open(term, "fig2_2")
  set output (term eq "png" ? outdir."/fig2_2.png" : outdir."/fig2_2.svg")
  plot datadir."/fig2_2_polygon.dat" with filledcurves closed fc rgb C_HULL fs solid 1.0, \
       datadir."/fig2_2_lines.dat" with lines lw 1.2 dt 3 lc rgb C_CONSTRUCT, \
       datadir."/fig2_2_kernel.dat" with filledcurves closed fc rgb C_CAVITY fs solid 1.0, \
       datadir."/fig2_2_kernel.dat" with lines lw 2 lc rgb C_CAVITY_EDGE, \
       datadir."/fig2_2_sight.dat" with lines lw 1.2 lc rgb C_BALL_EDGE, \
       datadir."/fig2_2_polygon.dat" with lines lw 2.5 lc rgb C_TRI, \
       datadir."/fig2_2_polygon.dat" with points pt 7 ps (0.9*PS) lc rgb C_POINT, \
       datadir."/fig2_2_labels.dat" using 1:2:3 with labels tc rgb C_TRI, \
       datadir."/fig2_2_x.dat" with points pt 7 ps (1.5*PS) lc rgb C_NEW, \
       datadir."/fig2_2_xlabel.dat" using 1:2:("x") with labels tc rgb C_NEW
}
