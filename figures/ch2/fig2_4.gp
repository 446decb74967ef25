# Figure 2.4: the Delaunay ball B(DT_n, p_{n+1}): the fan of triangles σ_i σ_{i+1} p_{n+1}
# that fills the cavity (shaded), and an outside triangle σ_i σ_{i+1} p_j (hatched) with its
# circle (solid), which does not contain p_{n+1}; the circle of σ_i σ_{i+1} p_{n+1} (dashed)
# does not contain p_j. Data (sec2_1_kernel): fig2_4_dt.dat (DT_{n+1}), fig2_1_cavity.dat,
# fig2_4_sigma.dat (labels), fig2_4_outside.dat, fig2_4_circles.dat (x y r), fig2_4_pj.dat,
# fig2_1_p.dat.
if (!exists("datadir")) datadir = "."
if (!exists("outdir")) outdir = "."
set size ratio -1
set style textbox opaque noborder
unset key
unset border
unset tics
set xrange [-0.08:1.08]
set yrange [-0.08:1.08]
do for [term in "png svg"] {
  if (term eq "png") {
    set terminal pngcairo size 800,800 enhanced font "Sans,14"
    set output outdir."/fig2_4.png"
  } else {
    set terminal svg size 800,800 enhanced font "Sans,14" background rgb "white"
    set output outdir."/fig2_4.svg"
  }
  set title "the ball: DT_{n+1} = DT_n - C + B"
  plot datadir."/fig2_1_cavity.dat" with filledcurves closed fc rgb "#f6c88f" fs solid 1.0, \
       datadir."/fig2_4_outside.dat" with filledcurves closed fc rgb "#9fc5e8" fs pattern 4, \
       datadir."/fig2_4_dt.dat" with lines lw 1.5 lc rgb "#303030", \
       datadir."/fig2_1_cavity.dat" with lines lw 3 lc rgb "#b05a00", \
       datadir."/fig2_4_outside.dat" with lines lw 3 lc rgb "#2050c0", \
       datadir."/fig2_4_circles.dat" every ::0::0 using 1:2:3 with circles lw 2 lc rgb "#2050c0" fs empty, \
       datadir."/fig2_4_circles.dat" every ::1::1 using 1:2:3 with circles lw 2 dt 2 lc rgb "#d02020" fs empty, \
       datadir."/fig2_4_sigma.dat" using 1:2:3 with labels boxed font ",16" tc rgb "#703000", \
       datadir."/fig2_4_pj.dat" using 1:2:("p_j") with labels boxed font ",16" tc rgb "#2050c0", \
       datadir."/fig2_1_p.dat" with points pt 7 ps 1.4 lc rgb "#d02020", \
       datadir."/fig2_1_p.dat" using 1:2:("p_{n+1}") with labels boxed offset 2.2,-0.9 tc rgb "#d02020" font ",16"
}
