# The figure style of the book (its page: book/figure_style.md). Every script of figures/ch2
# loads it first:   load dir."/style.gp"   (dir = the script's directory, see below).
#
# Sizes: every figure has one fixed size in pixels, in the table FIGSIZES; tests/test_figures.cpp
# reads the same table and checks every PNG against it. A new figure adds a line here.
# Fonts: the reference print width is 15 cm; the text em is W/50 px, which is 8.5 pt at
# 15 cm for any width W (15 cm = 425 pt, so W px -> 425 pt and W/50 px -> 8.5 pt).
# pngcairo renders 1 pt as 4/3 px (96 dpi) and svg 1 pt as 1 px, hence the two factors below.

if (!exists("datadir")) datadir = "."
if (!exists("outdir")) outdir = "."
# A path never goes into a command line: a script that hands a data file to a command names it
# through the environment, system('cat -- "${DT_DATADIR:-.}/x.txt"'), which the shell expands
# without reading it as code (chapters/common.h's runGnuplot sets DT_DATADIR to datadir; set
# it too when you run a script by hand with another datadir).
set encoding utf8

# ---- sizes (name width height) -----------------------------------------------------------
FIGSIZES = " fig2_1 1400 640" . \
           " fig2_2 1200 1200" . \
           " fig2_3 1400 800" . \
           " fig2_4 1200 1000" . \
           " fig2_5 1500 2200" . \
           " fig2_5_anim 1200 1260" . \
           " fig2_6 1400 860" . \
           " fig2_7 1400 800" . \
           " fig2_7_errors 1500 800" . \
           " fig2_7_deuteranopia 1400 800" . \
           " fig2_8 1400 800" . \
           " fig2_9 1200 1300" . \
           " fig2_10 1400 780" . \
           " fig2_11 1400 740" . \
           " fig2_12 1400 780" . \
           " fig_brio_compare 1500 900" . \
           " fig_brio_rounds 1500 560" . \
           " fig_flip 1400 760" . \
           " fig_incircle_naive 1400 800" . \
           " fig_incircle_robust 1400 800" . \
           " fig_ladder_time 1200 900" . \
           " fig_outlier_walk 1400 640" . \
           " fig_time_per_point 1200 860" . \
           " fig_outside_hull 1200 1440" . \
           " fig_parabola_cavity 1200 860" . \
           " fig_recovery_frames 1500 1560" . \
           " fig_table2_1_search 1200 860 "

# Figures printed at about 8 cm (one panel); the others are printed at 15 cm.
FIG8CM = " fig2_2 fig2_4 fig2_5_anim fig2_9 fig_ladder_time fig_parabola_cavity fig_table2_1_search fig_time_per_point "

fig_known(n) = strstrt(FIGSIZES, " ".n." ") > 0
fig_word(n, k) = int(word(FIGSIZES, words(substr(FIGSIZES, 1, strstrt(FIGSIZES, " ".n." "))) + k))
# A chapter program's --size WxH sets fig_size_w, fig_size_h: they win over the table.
figw(n) = exists("fig_size_w") ? int(fig_size_w) : fig_word(n, 2)
figh(n) = exists("fig_size_h") ? int(fig_size_h) : fig_word(n, 3)
fig_narrow(n) = strstrt(FIG8CM, " ".n." ") > 0
# The text em in pixels: 8.5 pt printed at 15 cm (425 pt: W/50) and 8.1 pt at 8 cm (227 pt: W/28).
fig_em(n) = figw(n) / (fig_narrow(n) ? 28.0 : 50.0)
# The font size in the terminal's own unit: svg 1 pt = 1 px, pngcairo 1 pt = 4/3 px (96 dpi).
fig_font(t, n) = (t eq "svg" ? fig_em(n) : 0.75 * fig_em(n))

# Points: scripts write "ps (1.5*PS)". PS makes a point of size 1 a disc of radius 0.2146 em
# (0.65 mm at 15 cm) on both terminals: pngcairo draws size 1 with a radius of 3.15 px whatever
# the font, the svg terminal with a radius of 0.375 x its font size.
fig_points(t, n) = (t eq "svg" ? 0.2146 / 0.375 : 0.2146 * fig_em(n) / 3.15)
# Line width 1 is em/18 px (1.6 px at 1400 px wide, 15 cm), and never under 1.5 px.
fig_lw(n) = (fig_em(n) / 18.0 > 1.5 ? fig_em(n) / 18.0 : 1.5)

# The command that opens figure `n` on terminal `t` ("png" or "svg"): a clean state
# (STYLE_RESET), white background, the style's size and font. The script then sets the output
# with the file name written out,
#   set output (term eq "png" ? outdir."/n.png" : outdir."/n.svg")
# so that chapters/common.h (gnuplotOutputs) knows which files it promises, and then its own
# settings. It sets FS (the font size) for scripts that need a label font relative to the
# text, e.g. font sprintf(",%g", 1.2 * FS), EM (the em in px) and FW, FH (the size in pixels).
fig_open(t, n) = (fig_known(n) ? "" : "print 'style.gp: figure ".n." has no size in FIGSIZES'; exit status 1;") . \
  STYLE_RESET . \
  sprintf("set terminal %s size %d,%d enhanced font 'Sans,%.1f' background rgb 'white' linewidth %.2f; ", \
          (t eq "svg" ? "svg" : "pngcairo"), figw(n), figh(n), fig_font(t, n), fig_lw(n)) . \
  sprintf("PS = %.3f; ", fig_points(t, n)) . \
  sprintf("FS = %.1f; EM = %.2f; FW = %d; FH = %d", fig_font(t, n), fig_em(n), figw(n), figh(n))

# The notes' notation: M."𝑝_{𝑛+1}}" sets a formula in the math font (fonts-dejavu-extra), which
# has the Unicode mathematical italics (𝑝, 𝑛), script capitals (𝒞, ℬ), σ and Σ. The chapter
# programs write their labels the same way (ch::mathText in chapters/figure_data.h).
M = "{/'DejaVu Math TeX Gyre' "

# ---- colours: one meaning each, in every figure -------------------------------------------
# This is the one table of colours: a figure script names a role (lc rgb C_CAVITY), never a
# colour (black and white, the ink and the paper, are no roles), and no two roles share a colour (tests/test_figures_rules.cpp checks both). The pairs
# a reader must tell apart (figures/ch2/meaning_pairs.txt) differ by a CIEDE2000 of at least 20
# under normal vision, protanopia, deuteranopia and tritanopia (Machado et al. 2009), or carry
# a second cue (a dash pattern, a marker shape) that the same test finds in the SVG.
C_TRI = "#3c3c3c"            # edges of the triangulation
C_POINT = "black"            # the points of S
C_NEW = "#e31a1c"            # the point being inserted (p_{n+1}, p)
C_CAVITY = "#f0a830"         # fill of the Delaunay cavity C
C_CAVITY_EDGE = "#c65a00"    # its boundary
C_BALL = "#e5f5d5"           # fill of the Delaunay ball B (the new triangles)
C_BALL_EDGE = "#004d40"      # its boundary / new edges
C_NEIGH = "#6aaed6"          # fill of the neighbours (outside triangles adjacent to C or B)
C_NEIGH_EDGE = "#2b63a8"     # their edges, links to them
C_CONFLICT = "#c51b7d"       # conflicts: wrong signs, crossing edges, removed edges
C_UNCOVERED = "#f4a582"      # the part of the convex hull that no triangle covers
C_HULL = "#dde6f0"           # a convex hull or polygon, shaded as background
C_CIRCLE = "#1a3f8f"         # circumcircles (dashed)
C_CAP = "#b9cdeb"            # the part of a circumcircle beyond an edge (Figure 2.3 (b)), shaded
C_SUPER = "#7b3294"          # super-vertices p_{-1}, p_{-2}, ...
C_CONSTRUCT = "#8c8c8c"      # construction lines (dotted)
C_KERNEL = "#fde49c"         # fill of a kernel ker(Σ) (Figure 2.2)
C_KERNEL_EDGE = "#9a7400"    # its boundary
C_SIGHT = "#5a5a5a"          # sight lines from a kernel point (thin, solid)
C_PENDING = "#808080"        # points not inserted yet (Figure 2.5), earlier rounds (BRIO)
C_MUTED = "#505050"          # secondary labels (Figure 2.11's cell numbers)
C_GRID = "#d0d0d0"           # grid lines of charts (behind the data)
C_HULL_VERTEX = "#f0c020"    # a vertex on the convex hull (Figure 2.9; inner vertices white)
# Sign maps (2.3.1): -1 blue, 0 yellow, +1 red. The notes' green and red are one colour to a
# red-green colour-blind reader; blue and red keep a CIEDE2000 of 44 or more for every reader.
C_MINUS = "#2166ac"
C_ZERO = "#ffd700"
C_PLUS = "#ca0020"
# Where a naive map is wrong (fig2_7_errors): right is white, a false 0 is C_ZERO, a flipped
# sign black, and a sign where the exact value is 0:
C_ERR_SIGN = "#4393c3"
# A sequential palette: the rank in an order (Figure 2.12), from the first to the last.
C_RANK_FIRST = "#20206a"
C_RANK_MID = "#c03060"
C_RANK_LAST = "#e0b000"
# Series of charts, in order (each series also has its own marker shape).
C_SERIES = "#1f77b4 #d62728 #2ca02c #9467bd #ff7f0e #8c564b"

# ---- geometry panels: equal aspect, no axes ------------------------------------------------
# (charts undo this with  set border; set tics; set size noratio)
# Every terminal pass starts from this clean state: fig_open runs it first, so that no setting
# of one pass (a legend panel's ranges, unset tics, ...) leaks into the next one. A script sets
# its own options after fig_open, inside the pass.
STYLE_RESET = "reset; set encoding utf8; set size ratio -1; unset key; unset border; unset tics; " . \
  "set style textbox transparent noborder; NROWS = 1; NCOLS = 1; "
eval STYLE_RESET

# Labels: no box over the geometry; a label sits beside its object, offset by about one
# character (offset 0.8,0.8 and the like), on the side away from the edges.
# Panel tags: each panel's title is "(a) short words"; the prose is in the caption. The titles
# of one row sit at one height (a screen label at the top of the panel's cell), whatever the
# aspect of each panel:   eval layout(rows, cols)  ...  eval panel(k, "words")  plot ...
NROWS = 1; NCOLS = 1
layout(r, c) = sprintf("NROWS = %d; NCOLS = %d; set multiplot layout %d,%d; set tmargin 2.5", r, c, r, c)
panel(k, text) = sprintf("unset title; set label 100 \"(%s) %s\" at screen %.4f, %.4f center front",   word("a b c d e f g h i j k l", k), text, ((k - 1) % NCOLS + 0.5) / NCOLS, 1 - (int((k - 1) / NCOLS) + 0.0) / NROWS - 1.0 * EM / FH)

# A sign map's colour bar: three boxes with the ticks -1, 0, +1 at their centres, in the colours
# m, z, p (sign_bar: the style's; fig2_7_deuteranopia passes them as a deuteranope sees them).
sign_bar_of(m, z, p) = "set palette defined (-1.5 '".m."', -0.5 '".m."', -0.5 '".z."', 0.5 '".z."', 0.5 '".p."', 1.5 '".p."'); set cbrange [-1.5:1.5]; set cbtics ('−1' -1, '0' 0, '+1' 1) scale 0; set colorbox"
sign_bar = sign_bar_of(C_MINUS, C_ZERO, C_PLUS)
# The axis labels of a map of cells (i, j): the point's coordinates (x_v, y_v) for the letter v
# of the moving point (a for the orientation maps, d for the incircle maps).
map_xlabel(v) = M."𝑖   (𝑥_{".v."} = 1/2 + 𝑖 2^{−53})}"
map_ylabel(v) = M."𝑗   (𝑦_{".v."} = 1/2 + 𝑗 2^{−53})}"
