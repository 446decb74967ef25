# Figure 2.3: the Delaunay cavity is star-shaped (the proof of Proposition 2.1.1, in the notes'
# names). (a) The segment from p3 to p_{n+1} crosses the triangles p2p3p4, p2p4p5, p2p5p1 and
# p1p5p6 (shaded darker), all in the cavity; p1p5p6 contains p_{n+1}.
# (b) The first step: p_{n+1} is in C_I (circle of p2p3p4, dashed) and beyond the line p2p4 (dotted);
# the part of C_I beyond p2p4 (shaded) lies inside C_J (circle of p2p4p5), so C_J contains
# p_{n+1} too and p2p4p5 is in the cavity. Both circles are circumcircles (dark blue, dashed);
# C_J has a dash-dot pattern to tell them apart.
# Data (sec2_1_kernel): fig2_1_dtn.dat, fig2_1_cavity.dat, fig2_3_chain.dat (one index per
# triangle), fig2_3_names.dat, fig2_3_segment.dat (p3, p_{n+1}), fig2_3_plabel.dat,
# fig2_3_circles.dat (C_I, C_J: x y r), fig2_3_edge.dat (index 0: p2p4; index 1: its line,
# clipped to the view of (b)), fig2_3_cap.dat, fig2_3_steptri.dat, fig2_3_steplabels.dat,
# fig2_3_view.gp (PA, PB: each panel's box and view, from the program's layout).
load system("dirname '".ARG0."'")."/style.gp"
load datadir."/fig2_3_view.gp"
stats datadir."/fig2_3_chain.dat" nooutput
nchain = STATS_blocks
do for [term in "png svg"] {
  eval fig_open(term, "fig2_3")
  set output (term eq "png" ? outdir."/fig2_3.png" : outdir."/fig2_3.svg")
  eval layout(1, 2)
  eval panel(1, "the segment ".M."𝑝_3 𝑝_{𝑛+1}}")
  eval PA
  plot datadir."/fig2_1_cavity.dat" with filledcurves closed fc rgb C_CAVITY fs transparent solid 0.45, \
       for [i=0:nchain-1] datadir."/fig2_3_chain.dat" index i with filledcurves closed fc rgb C_CAVITY fs solid 1.0, \
       datadir."/fig2_1_dtn.dat" with lines lw 1.2 lc rgb C_TRI, \
       datadir."/fig2_1_cavity.dat" with lines lw 3 lc rgb C_CAVITY_EDGE, \
       datadir."/fig2_3_segment.dat" with lines lw 2.5 lc rgb C_NEW, \
       datadir."/fig2_1_points.dat" with points pt 7 ps (1.0*PS) lc rgb C_POINT, \
       datadir."/fig2_3_segment.dat" every ::1::1 with points pt 7 ps (1.5*PS) lc rgb C_NEW, \
       datadir."/fig2_3_plabel.dat" using 1:2:3 with labels tc rgb C_NEW, \
       datadir."/fig2_3_names.dat" using 1:2:3 with labels tc rgb C_TRI
  eval panel(2, "one step: ".M."𝐶_𝐼} beyond ".M."𝑝_2𝑝_4} lies in ".M."𝐶_𝐽}")
  eval PB
  plot datadir."/fig2_3_cap.dat" with filledcurves closed fc rgb C_CAP fs solid 1.0, \
       datadir."/fig2_3_steptri.dat" with lines lw 2 lc rgb C_TRI, \
       datadir."/fig2_3_edge.dat" index 1 with lines lw 1.5 dt 3 lc rgb C_CONSTRUCT, \
       datadir."/fig2_3_edge.dat" index 0 with lines lw 4 lc rgb C_CAVITY_EDGE, \
       datadir."/fig2_3_segment.dat" with lines lw 2 lc rgb C_NEW, \
       datadir."/fig2_3_circles.dat" every ::0::0 using 1:2:3 with circles lw 2 dt 2 lc rgb C_CIRCLE fs empty, \
       datadir."/fig2_3_circles.dat" every ::1::1 using 1:2:3 with circles lw 2 dt (10,5,1,5) lc rgb C_CIRCLE fs empty, \
       datadir."/fig2_3_steplabels.dat" every ::0::1 using 1:2:3 with labels tc rgb C_CIRCLE, \
       datadir."/fig2_3_steplabels.dat" every ::2 using 1:2:3 with labels tc rgb C_TRI, \
       datadir."/fig2_3_steptri.dat" with points pt 7 ps (1.0*PS) lc rgb C_POINT, \
       datadir."/fig2_3_segment.dat" every ::1::1 with points pt 7 ps (1.5*PS) lc rgb C_NEW
  unset multiplot
}
