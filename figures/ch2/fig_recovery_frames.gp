# Section 2.2.1 / 2.3.6: DT(S) recovered from DT(S0 ∪ S) by flips, frame by frame, on a
# Figure-2.6-like configuration. Data from sec2_3_6_flips: rec_frames.gp (frame count, view),
# rec_frame_K.{gp,dat} (conv(S) uncovered pink, covered pale blue, the flipped edge dashed, the
# new edge green, every vertex labelled, the frame's title ftitle), rec_points.dat.
load system("dirname '".ARG0."'")."/style.gp"
load datadir.'/rec_frames.gp'
cols = (nframes <= 4) ? nframes : ((nframes <= 6) ? 3 : 4)
rows = (nframes + cols - 1) / cols
do for [t in "png svg"] {
  eval fig_open(t, "fig_recovery_frames")
  set output (t eq "png" ? outdir.'/fig_recovery_frames.png' : outdir.'/fig_recovery_frames.svg')
  set xrange [xlo:xhi]; set yrange [ylo:yhi]
  eval layout(rows, cols)
  do for [k = 0:nframes-1] {
    load sprintf('%s/rec_frame_%d.gp', datadir, k)
    eval panel(k + 1, ftitle)
    plot sprintf('%s/rec_frame_%d.dat', datadir, k) with lines lc rgb C_TRI lw 1, \
         datadir.'/rec_points.dat' with points pt 7 ps (0.8*PS) lc rgb C_POINT
    unset object; unset arrow
    unset label
  }
  unset multiplot
}
