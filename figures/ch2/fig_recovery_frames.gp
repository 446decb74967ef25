# Section 2.2.1 / 2.3.6: DT(S) recovered from DT(S0 ∪ S) by flips, frame by frame, on a
# Figure-2.6-like configuration. Data from sec2_3_6_flips: rec_frames.gp (frame count, grid),
# rec_frame_K.{gp,dat} (conv(S) uncovered pink, covered pale blue, the flipped edge dashed in
# the conflict colour, the new edge green, the labels (one place per vertex in every frame),
# the frame's title ftitle, VIEW: its box and view from the program's layout), rec_points.dat,
# rec_super.dat (the super-vertices: purple squares, as in Figures 2.5 and 2.6).
load system("dirname '".ARG0."'")."/style.gp"
load datadir.'/rec_frames.gp'
do for [t in "png svg"] {
  eval fig_open(t, "fig_recovery_frames")
  set output (t eq "png" ? outdir.'/fig_recovery_frames.png' : outdir.'/fig_recovery_frames.svg')
  eval layout(rows, cols)
  do for [k = 0:nframes-1] {
    load sprintf('%s/rec_frame_%d.gp', datadir, k)
    eval panel(k + 1, ftitle)
    eval VIEW
    plot sprintf('%s/rec_frame_%d.dat', datadir, k) with lines lc rgb C_TRI lw 1, \
         datadir.'/rec_points.dat' with points pt 7 ps (0.9*PS) lc rgb C_POINT, \
         datadir.'/rec_super.dat' with points pt 5 ps (1.3*PS) lc rgb C_SUPER
    unset object; unset arrow
    unset label
  }
  unset multiplot
}
