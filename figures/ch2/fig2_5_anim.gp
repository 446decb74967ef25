# Animation of Figure 2.5's insertions: frame 00 is DT_0; then, for each point p_i, the cavity
# C(DT_{i-1}, p_i) (shaded, in DT_{i-1}, with the circumcircles that contain p_i) and the ball
# B(DT_{i-1}, p_i) (shaded, in DT_i). Every inserted point is labelled. PNG frames
# fig2_5_anim_NN.png, and the animated GIF fig2_5_anim.gif written by gnuplot's own gif terminal
# (libgd; no other program needed), which holds the last frame longer.
# The circles come dashed in their data (gnuplot's gif terminal draws a dash type solid), so
# they are drawn as plain lines; the GIF's key, whose sample is solid there, says "dashed" in words. Each frame's labels (fig2_5_anim_NN_labels.dat: x y label lx ly
# super giflabel) are placed by the program beside their points, clear of the frame's circles.
# The view holds every circle of every frame; labels and markers are Figure 2.5's scaled to it
# (fig2_5_view.gp: ANIM_FONT, ANIM_PS), so that a frame showing a panel's triangulation takes
# that panel's label places with the same room around them.
# Data (sec2_2_bowyer_watson): fig2_5_anim_NN_{tri,fill,p,circles,labels}.dat,
# fig2_5_anim_{titles,count}.dat, fig2_5_super.dat, fig2_5_points.dat.
load system("dirname '".ARG0."'")."/style.gp"
stats datadir."/fig2_5_anim_count.dat" using 1 nooutput
nframes = int(STATS_max)
load datadir."/fig2_5_view.gp"
# The frame's settings, run after each frame's reset: the view laid out by the program (which
# placed the labels in it), the legend below the picture.
ANIM = VIEWA . "; set key at screen 0.5, screen 0.01 center bottom horizontal samplen 1.5 width 1"
W = figw("fig2_5_anim"); H = figh("fig2_5_anim")
# Pass 0 writes one PNG per frame; pass 1 writes the same frames into one animated GIF (the last
# one three more times, so the finished triangulation stays on screen before the loop restarts).
do for [pass=0:1] {
  if (pass == 1) {
    # libgd's fonts are in points at 96 dpi like pngcairo's.
    eval sprintf("set terminal gif animate delay 90 loop 0 size %d,%d enhanced font 'DejaVuSans,%.1f' background rgb 'white' linewidth %.2f", W, H, fig_font("png", "fig2_5_anim"), fig_lw("fig2_5_anim"))
    set output outdir."/fig2_5_anim.gif"
  }
  do for [g=0:nframes-1+3*pass] {
  f = (g < nframes) ? g : nframes - 1
  if (pass == 0) {
    eval fig_open("png", "fig2_5_anim")
    set output outdir.sprintf("/fig2_5_anim_%02d.png", f)
  } else {
    eval STYLE_RESET
  }
  eval ANIM
  # The titles file: the PNG's title, a tab, the GIF's (libgd shows no 𝒞: words there).
  tline = system(sprintf('sed -n %dp -- "${DT_DATADIR:-.}/fig2_5_anim_titles.dat"', f + 1))
  tab = strstrt(tline, "\t")
  set label 100 (pass == 0 ? tline[1:tab - 1] : tline[tab + 1:]) at screen 0.5, screen 1 - 1.0 * fig_em("fig2_5_anim") / H center front
  stem = datadir.sprintf("/fig2_5_anim_%02d", f)
  # Cavity frames are odd, ball frames even (frame 0: DT_0). Each colour is its own plot
  # element, filtered by the frame's parity: gnuplot's gif terminal keeps the first colour an
  # element had through the whole animation.
  cav = (f % 2 == 1); bal = (f > 0 && f % 2 == 0)
  npoints = (f + 1) / 2
  plot (f == 0 ? datadir."/fig2_5_super.dat" : stem."_fill.dat") using 1:(cav ? $2 : NaN) with filledcurves closed fc rgb C_CAVITY fs solid 1.0 notitle, \
       (f == 0 ? datadir."/fig2_5_super.dat" : stem."_fill.dat") using 1:(bal ? $2 : NaN) with filledcurves closed fc rgb C_BALL fs solid 1.0 notitle, \
       stem."_circles.dat" using 1:2 with lines lw 1.5 lc rgb C_CIRCLE notitle, \
       stem."_tri.dat" with lines lw 1.5 lc rgb C_TRI notitle, \
       (f == 0 ? datadir."/fig2_5_super.dat" : stem."_fill.dat") using 1:(cav ? $2 : NaN) with lines lw 2.5 lc rgb C_CAVITY_EDGE notitle, \
       (f == 0 ? datadir."/fig2_5_super.dat" : stem."_fill.dat") using 1:(bal ? $2 : NaN) with lines lw 2.5 lc rgb C_BALL_EDGE notitle, \
       datadir."/fig2_5_super.dat" using 1:2 with points pt 5 ps (ANIM_PS*PS) lc rgb C_SUPER notitle, \
       stem."_labels.dat" using 4:($6 == 1 ? $5 : NaN):(pass == 0 ? strcol(3) : strcol(7)) with labels tc rgb C_SUPER font sprintf(',%.1f', ANIM_FONT * FS) notitle, \
       datadir."/fig2_5_points.dat" using 1:2 with points pt 6 ps (ANIM_PS*PS) lc rgb C_PENDING notitle, \
       datadir."/fig2_5_points.dat" using 1:($0 < npoints ? $2 : NaN) with points pt 7 ps (ANIM_PS*PS) lc rgb C_POINT notitle, \
       stem."_labels.dat" using 4:($6 == 0 ? $5 : NaN):(pass == 0 ? strcol(3) : strcol(7)) with labels tc rgb C_TRI font sprintf(',%.1f', ANIM_FONT * FS) notitle, \
       (f == 0 ? datadir."/fig2_5_super.dat" : stem."_p.dat") using 1:(f == 0 ? NaN : $2) with points pt 7 ps (1.4*ANIM_PS*PS) lc rgb C_NEW notitle, \
       NaN with boxes fs solid 1.0 fc rgb C_CAVITY title "cavity", \
       NaN with boxes fs solid 1.0 fc rgb C_BALL title "ball", \
       NaN with lines lw 1.5 dt 2 lc rgb C_CIRCLE title (pass == 0 ? "circumcircles" : "circumcircles (dashed)"), \
       NaN with points pt 7 ps (1.4*ANIM_PS*PS) lc rgb C_NEW title "new point"
  }
  set output
}
