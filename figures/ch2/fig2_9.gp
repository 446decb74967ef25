# Figure 2.9: a triangulation with n = 12, n_h = 9; each vertex labelled with its number of
# adjacent triangles n_vf. Data: fig2_9_tri.dat (triangles as closed polylines),
# fig2_9_vertices.dat (x y n_vf n_ve on_hull), fig2_9_title.txt (the averages).
# Hull vertices are yellow, inner vertices green.
if (!exists("datadir")) datadir = "."
if (!exists("outdir")) outdir = "."
title = system("cat '".datadir."/fig2_9_title.txt'")
set size ratio -1
unset key
unset border
unset tics
set title title font ",13"
set offsets 0.15, 0.15, 0.15, 0.15
set style fill solid 1.0 border lc rgb "black"
do for [term in "png svg"] {
  if (term eq "png") {
    set terminal pngcairo size 900,720 enhanced font "Sans,12"
    set output outdir."/fig2_9.png"
  } else {
    set terminal svg size 900,720 enhanced font "Sans,12" background rgb "white"
    set output outdir."/fig2_9.svg"
  }
  plot datadir."/fig2_9_tri.dat" with lines lw 1.5 lc rgb "#4060a0", \
       datadir."/fig2_9_vertices.dat" using 1:2:(0.075):($5 > 0 ? 0xf0d070 : 0x9fd49f) \
         with circles lc rgb variable fs solid 1.0 border lc rgb "black", \
       datadir."/fig2_9_vertices.dat" using 1:2:(sprintf("%d", $3)) with labels font ",13"
}
