# Figure 2.3: the Delaunay cavity is star-shaped (the proof of Proposition 2.1.1).
# Left: the segment from a point q of a cavity triangle Δ_1 to p_{n+1} crosses the triangles
# Δ_1, ..., Δ_k, all in the cavity (shaded darker); Δ_k contains p_{n+1}.
# Right: one step. p_{n+1} is inside C_1 (circle of Δ_1) and beyond the edge e_1; the part of
# C_1 beyond e_1 (shaded) lies inside C_2 (circle of Δ_2), so C_2 contains p_{n+1} too.
# Data (sec2_1_kernel): fig2_1_dtn.dat, fig2_1_cavity.dat, fig2_3_chain.dat (one index per
# triangle), fig2_3_labels.dat, fig2_3_segment.dat (q, p), fig2_3_circles.dat (C_1, C_2: x y r),
# fig2_3_edge.dat (index 0: e_1; index 1: its line), fig2_3_cap.dat.
if (!exists("datadir")) datadir = "."
if (!exists("outdir")) outdir = "."
set size ratio -1
set style textbox opaque noborder
unset key
unset border
unset tics
stats datadir."/fig2_3_chain.dat" nooutput
nchain = STATS_blocks
stats datadir."/fig2_1_cavity.dat" using 1 nooutput
cx0 = STATS_min; cx1 = STATS_max
stats datadir."/fig2_1_cavity.dat" using 2 nooutput
cy0 = STATS_min; cy1 = STATS_max
m = 0.08 * (cx1 - cx0 > cy1 - cy0 ? cx1 - cx0 : cy1 - cy0)
stats datadir."/fig2_3_circles.dat" using ($1-$3) nooutput
zx0 = STATS_min
stats datadir."/fig2_3_circles.dat" using ($2-$3) nooutput
zy0 = STATS_min
stats datadir."/fig2_3_circles.dat" using ($1+$3) nooutput
zx1 = STATS_max
stats datadir."/fig2_3_circles.dat" using ($2+$3) nooutput
zy1 = STATS_max
zm = 0.05 * (zx1 - zx0)
do for [term in "png svg"] {
  if (term eq "png") {
    set terminal pngcairo size 1400,720 enhanced font "Sans,14"
    set output outdir."/fig2_3.png"
  } else {
    set terminal svg size 1400,720 enhanced font "Sans,14" background rgb "white"
    set output outdir."/fig2_3.svg"
  }
  set multiplot layout 1,2
  set title "the segment q p_{n+1} crosses Δ_1, ..., Δ_k: all in the cavity"
  set xrange [cx0-m:cx1+m]
  set yrange [cy0-m:cy1+m]
  plot datadir."/fig2_1_cavity.dat" with filledcurves closed fc rgb "#fbe3c4" fs solid 1.0, \
       for [i=0:nchain-1] datadir."/fig2_3_chain.dat" index i with filledcurves closed fc rgb "#f2a65a" fs solid 1.0, \
       datadir."/fig2_1_dtn.dat" with lines lw 1.2 lc rgb "#505050", \
       datadir."/fig2_1_cavity.dat" with lines lw 3 lc rgb "#b05a00", \
       datadir."/fig2_3_segment.dat" with lines lw 2.5 lc rgb "#d02020", \
       datadir."/fig2_3_segment.dat" with points pt 7 ps 1.3 lc rgb "#d02020", \
       datadir."/fig2_3_segment.dat" every ::0::0 using 1:2:("q") with labels boxed offset 0,-1.1 font ",16" tc rgb "#d02020", \
       datadir."/fig2_3_segment.dat" every ::1::1 using 1:2:("p_{n+1}") with labels boxed offset 0,-1.2 font ",16" tc rgb "#d02020", \
       datadir."/fig2_3_labels.dat" using 1:2:3 with labels offset -1.5,0 font ",15" tc rgb "#402000"
  set title "one step: the part of C_i beyond e_i lies inside C_{i+1}, so p_{n+1} ∈ C_{i+1}"
  set xrange [zx0-zm:zx1+zm]
  set yrange [zy0-zm:zy1+zm]
  plot datadir."/fig2_3_cap.dat" with filledcurves closed fc rgb "#f7c0c0" fs solid 1.0, \
       datadir."/fig2_3_steptri.dat" with lines lw 2 lc rgb "#404040", \
       datadir."/fig2_3_edge.dat" index 1 with lines lw 1 dt 2 lc rgb "#808080", \
       datadir."/fig2_3_edge.dat" index 0 with lines lw 4 lc rgb "#b05a00", \
       datadir."/fig2_3_circles.dat" every ::0::0 using 1:2:3 with circles lw 2 lc rgb "#2050c0" fs empty, \
       datadir."/fig2_3_circles.dat" every ::1::1 using 1:2:3 with circles lw 2 lc rgb "#2e8b57" fs empty, \
       datadir."/fig2_3_steplabels.dat" every ::0::1 using 1:2:3 with labels font ",16" tc rgb "#402000", \
       datadir."/fig2_3_steplabels.dat" every ::2::2 using 1:2:3 with labels offset -1.2,0.6 font ",16" tc rgb "#2050c0", \
       datadir."/fig2_3_steplabels.dat" every ::3::3 using 1:2:3 with labels offset 1.8,0.6 font ",16" tc rgb "#2e8b57", \
       datadir."/fig2_3_steplabels.dat" every ::4::4 using 1:2:3 with labels boxed offset 1.5,0 font ",16" tc rgb "#b05a00", \
       datadir."/fig2_3_segment.dat" every ::1::1 with points pt 7 ps 1.4 lc rgb "#d02020", \
       datadir."/fig2_3_segment.dat" every ::1::1 using 1:2:("p_{n+1}") with labels boxed offset 0,1.2 font ",16" tc rgb "#d02020"
  unset multiplot
}
