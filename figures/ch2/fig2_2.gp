# Figure 2.2: a star-shaped polygon Σ and its kernel ker(Σ), computed by intersecting the
# half-planes left of its oriented edges (edge lines dotted, clipped to the view by the
# program), with a point x of the kernel and its sight lines to every corner σ_j.
# Data (sec2_1_kernel): fig2_2_polygon.dat, fig2_2_kernel.dat, fig2_2_sight.dat,
# fig2_2_lines.dat, fig2_2_labels.dat (x y label), fig2_2_x.dat, fig2_2_xlabel.dat,
# fig2_2_view.gp (the view, the place of ker(Σ) and its arrow, all from the program's layout).
load system("dirname '".ARG0."'")."/style.gp"
load datadir."/fig2_2_view.gp"
do for [term in "png svg"] {
  eval fig_open(term, "fig2_2")
  set output (term eq "png" ? outdir."/fig2_2.png" : outdir."/fig2_2.svg")
  eval VIEW
  set arrow 1 from TAILX, TAILY to AX, AY lw 1.5 lc rgb C_KERNEL_EDGE front
  set label 1 KER at TX, TY left tc rgb C_KERNEL_EDGE front
  plot datadir."/fig2_2_polygon.dat" with filledcurves closed fc rgb C_HULL fs solid 1.0, \
       datadir."/fig2_2_lines.dat" with lines lw 1.2 dt 3 lc rgb C_CONSTRUCT, \
       datadir."/fig2_2_kernel.dat" with filledcurves closed fc rgb C_KERNEL fs solid 1.0, \
       datadir."/fig2_2_kernel.dat" with lines lw 2 lc rgb C_KERNEL_EDGE, \
       datadir."/fig2_2_sight.dat" with lines lw 1.2 lc rgb C_SIGHT, \
       datadir."/fig2_2_polygon.dat" with lines lw 2.5 lc rgb C_TRI, \
       datadir."/fig2_2_polygon.dat" with points pt 7 ps (0.9*PS) lc rgb C_POINT, \
       datadir."/fig2_2_labels.dat" using 1:2:3 with labels tc rgb C_TRI, \
       datadir."/fig2_2_x.dat" with points pt 7 ps (1.5*PS) lc rgb C_NEW, \
       datadir."/fig2_2_xlabel.dat" using 1:2:3 with labels tc rgb C_NEW
}
