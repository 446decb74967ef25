# Animation of Figure 2.5's insertions: frame 00 is DT_0; then, for each point p_i, the cavity
# C(DT_{i-1}, p_i) (shaded orange, in DT_{i-1}) and the ball B(DT_{i-1}, p_i) (shaded green, in
# DT_i). PNG frames fig2_5_anim_NN.png, and the animated GIF fig2_5_anim.gif written by gnuplot's
# own gif terminal (libgd; no other program needed), which holds the last frame a little longer.
# Data (sec2_2_bowyer_watson): fig2_5_anim_NN_{tri,fill,p}.dat, fig2_5_anim_{titles,count}.dat,
# fig2_5_super.dat, fig2_5_points.dat.
if (!exists("datadir")) datadir = "."
if (!exists("outdir")) outdir = "."
set size ratio -1
set style textbox opaque noborder
unset key
unset border
unset tics
stats datadir."/fig2_5_anim_count.dat" using 1 nooutput
nframes = int(STATS_max)
stats datadir."/fig2_5_super.dat" using 1 nooutput
x0 = STATS_min; x1 = STATS_max
stats datadir."/fig2_5_super.dat" using 2 nooutput
y0 = STATS_min; y1 = STATS_max
m = 0.09 * (x1 - x0)
set xrange [x0-m:x1+m]
set yrange [y0-m:y1+m]
# Pass 0 writes one PNG per frame; pass 1 writes the same frames into one animated GIF (the last
# one three more times, so the finished triangulation stays on screen before the loop restarts).
do for [pass=0:1] {
  if (pass == 1) {
    set terminal gif animate delay 90 loop 0 size 700,720 enhanced font "DejaVuSans,12"
    set output outdir."/fig2_5_anim.gif"
  }
  do for [g=0:nframes-1+3*pass] {
  f = (g < nframes) ? g : nframes - 1
  if (pass == 0) {
    set terminal pngcairo size 700,720 enhanced font "Sans,14"
    set output outdir.sprintf("/fig2_5_anim_%02d.png", f)
  }
  set title system(sprintf("sed -n '%dp' '%s/fig2_5_anim_titles.dat'", f + 1, datadir))
  stem = datadir.sprintf("/fig2_5_anim_%02d", f)
  fillc = (f % 2 == 1) ? "#f6c88f" : "#b7e1b5"
  npoints = (f + 1) / 2
  plot (f == 0 ? stem."_tri.dat" : stem."_fill.dat") using 1:2 with filledcurves closed fc rgb (f == 0 ? "white" : fillc) fs solid 1.0, \
       stem."_tri.dat" with lines lw 1.5 lc rgb "#303030", \
       datadir."/fig2_5_super.dat" using 1:($2 > 0.5 ? $2 + 0.5 * m : $2 - 0.5 * m):3 with labels boxed font ",13" tc rgb "#2050c0", \
       datadir."/fig2_5_points.dat" using 1:2 with points pt 6 ps 1.1 lc rgb "#909090", \
       datadir."/fig2_5_points.dat" using 1:($0 < npoints ? $2 : NaN) with points pt 7 ps 1.1 lc rgb "#303030", \
       (f == 0 ? datadir."/fig2_5_super.dat" : stem."_p.dat") using 1:(f == 0 ? NaN : $2) with points pt 7 ps 1.8 lc rgb "#d02020", \
       (f == 0 ? datadir."/fig2_5_super.dat" : stem."_p.dat") using 1:(f == 0 ? NaN : $2):3 with labels boxed offset 1.8,0.9 font ",15" tc rgb "#d02020"
  }
  set output
}
