# Figure 2.9: a triangulation with n = 12, n_h = 9; each vertex labelled with its number of
# adjacent triangles n_vf. Hull vertices yellow, inner vertices white (legend below).
# Data: fig2_9_tri.dat (edges, each once, stopping at the discs), fig2_9_vertices.dat (x y n_vf
# n_ve on_hull), fig2_9_title.txt (the mean and eq. (2.2)), fig2_9_disc.gp (R: the discs' radius).
load system("dirname '".ARG0."'")."/style.gp"
load datadir."/fig2_9_disc.gp"
title = system('cat -- "${DT_DATADIR:-.}/fig2_9_title.txt"')
do for [term in "png svg"] {
  eval fig_open(term, "fig2_9")
  set output (term eq "png" ? outdir."/fig2_9.png" : outdir."/fig2_9.svg")
  set offsets 0.05, 0.05, 0.15, 0.15  # room for the end discs, no side band over 10 %
  set key outside bottom center horizontal samplen 1 width 2
  # Two lines (the count, then eq. (2.2)): one line is wider than the figure at its print size.
  cut = strstrt(title, ";")
  set title (cut > 0 ? title[1:cut] . "\n" . title[cut + 1:] : title)
  plot datadir."/fig2_9_tri.dat" with lines lw 1.5 lc rgb C_TRI notitle, \
       datadir."/fig2_9_vertices.dat" using 1:2:(R):($5 > 0 ? int("0x".C_HULL_VERTEX[2:]) : 0xffffff) \
         with circles lc rgb variable fs solid 1.0 border lc rgb "black" notitle, \
       datadir."/fig2_9_vertices.dat" using 1:2:(sprintf("%d", $3)) with labels notitle, \
       NaN with points pt 7 ps (3*PS) lc rgb C_HULL_VERTEX title "hull vertex", \
       NaN with points pt 6 ps (3*PS) lc rgb "black" title "inner vertex (label: ".M."𝑛_{𝑣𝑓}})"
}
