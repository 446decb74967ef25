# Section 2.2.1 / 2.3.6: DT(S) recovered from DT(S0 ∪ S) by flips, frame by frame, on a
# Figure-2.6-like configuration. Data from sec2_3_6_flips: rec_frames.gp (frame count, view),
# rec_frame_K.{gp,dat} (conv(S) shaded, flipped edge dashed red, new edge blue), rec_points.dat.
set encoding utf8
load datadir.'/rec_frames.gp'
cols = (nframes <= 4) ? nframes : ((nframes <= 6) ? 3 : 4)
rows = (nframes + cols - 1) / cols
do for [t in "png svg"] {
  if (t eq "png") {
    set terminal pngcairo size 420*cols, 440*rows font "Sans,11"
    set output outdir.'/fig_recovery_frames.png'
  } else {
    set terminal svg size 420*cols, 440*rows font "Sans,11"
    set output outdir.'/fig_recovery_frames.svg'
  }
  set multiplot layout rows, cols
  unset key; unset border; unset xtics; unset ytics
  set size ratio -1
  set xrange [xlo:xhi]; set yrange [ylo:yhi]
  do for [k = 0:nframes-1] {
    load sprintf('%s/rec_frame_%d.gp', datadir, k)
    plot sprintf('%s/rec_frame_%d.dat', datadir, k) with lines lc rgb "#555555" lw 1, \
         datadir.'/rec_points.dat' with points pt 7 ps 0.8 lc rgb "black"
    unset object; unset label; unset arrow
  }
  unset multiplot
}
