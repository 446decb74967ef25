# Section 2.2.2: a point outside the current hull. Data from sec2_2_2_outside_hull:
# out{hull,line}_{before,after}.{gp,dat}, *_points.dat, *_q.dat.
# Top: a point seeing several hull edges. Bottom: a point on the line of a hull edge.
set encoding utf8
do for [t in "png svg"] {
  if (t eq "png") {
    set terminal pngcairo size 1300,1150 font "Sans,11"
    set output outdir.'/fig_outside_hull.png'
  } else {
    set terminal svg size 1300,1150 font "Sans,11"
    set output outdir.'/fig_outside_hull.svg'
  }
  set multiplot layout 2,2
  unset key; unset border; unset xtics; unset ytics
  set size ratio -1
  set offsets graph 0.05, graph 0.05, graph 0.05, graph 0.05
  do for [s in "outhull outline"] {
    do for [w in "before after"] {
      load datadir.'/'.s.'_'.w.'.gp'
      plot datadir.'/'.s.'_'.w.'.dat' with lines lc rgb "#777777" lw 1, \
           datadir.'/'.s.'_points.dat' with points pt 7 ps 0.7 lc rgb "black", \
           datadir.'/'.s.'_q.dat' with points pt 7 ps 1.6 lc rgb "#c0392b", \
           datadir.'/'.s.'_q.dat' using 1:2:("p") with labels offset 1.2,0.6 font ",13"
      unset object; unset label; unset arrow
    }
  }
  unset multiplot
}
