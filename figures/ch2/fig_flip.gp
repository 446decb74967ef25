# Section 2.3.6 / 2.3.3: an edge flip, before and after. Data from sec2_3_6_flips:
# flip_{before,after}_tri.dat (triangles), flip_{before,after}.gp (shaded faces, edge, labels).
# Pink: the two triangles of the flip; blue: the four adjacent triangles. Labels: degrees.
set encoding utf8
do for [t in "png svg"] {
  if (t eq "png") {
    set terminal pngcairo size 1300,620 font "Sans,12"
    set output outdir.'/fig_flip.png'
  } else {
    set terminal svg size 1300,620 font "Sans,12"
    set output outdir.'/fig_flip.svg'
  }
  set multiplot layout 1,2
  unset key; unset border; unset xtics; unset ytics
  set size ratio -1
  set xrange [-3.5:7]; set yrange [-5:4.6]
  set title "before: edge ab (red); labels give each vertex's number of triangles" font ",13"
  load datadir.'/flip_before.gp'
  plot datadir.'/flip_before_tri.dat' with lines lc rgb "#555555" lw 1.2
  unset object; unset label; unset arrow
  set title "after: edge cd (blue); degrees change by −1, −1, +1, +1" font ",13"
  load datadir.'/flip_after.gp'
  plot datadir.'/flip_after_tri.dat' with lines lc rgb "#555555" lw 1.2
  unset object; unset label; unset arrow
  unset multiplot
}
