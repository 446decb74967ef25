// Figure data helpers of the chapter programs (the figure style, book/figure_style.md):
// where to put a label so that no drawn segment crosses it, construction lines clipped to the
// view, and triangulations written with each edge once.
#pragma once

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <stdexcept>
#include <utility>
#include <vector>

namespace ch {

/// A drawn segment, in data coordinates.
struct Seg {
  double x0, y0, x1, y1;
};

double segDistance(const Seg& s, double x, double y);

/// The centre of the label of the point (x, y): among 24 directions, about `r` (or 2.2 r) away, the one
/// whose text box (half width `hw`, half height `hh`, in data units) stays farthest from every
/// segment of `segs` and every point of `avoid` (x, y pairs). Ties go to the upper right.
std::pair<double, double> labelSpot(double x, double y, double r, double hw, double hh,
                                    const std::vector<Seg>& segs,
                                    const std::vector<double>& avoid = {});

/// The edges of triangles (vertex coordinates x, y per vertex; index triples), each edge once.
std::vector<Seg> triangleSegs(const std::vector<double>& xy,
                              const std::vector<std::array<int, 3>>& tri);

/// The edges of faces (anything with vertex pointers V[0..2] that have x and y, e.g. dt::Face),
/// each edge once.
template <class Faces>
std::vector<Seg> faceSegs(const Faces& F) {
  std::map<std::pair<const void*, const void*>, bool> seen;
  std::vector<Seg> segs;
  for (const auto* f : F)
    for (int k = 0; k < 3; ++k) {
      const auto *a = f->V[k], *b = f->V[(k + 1) % 3];
      const void *pa = a, *pb = b;
      if (seen.emplace(std::minmax(pa, pb), true).second) segs.push_back({a->x, a->y, b->x, b->y});
    }
  return segs;
}

/// Segments as gnuplot data, one block per segment. A triangulation drawn from this has every
/// edge drawn once: with closed triangles an inner edge is drawn twice and, antialiased, looks
/// darker than a hull edge.
std::string gnuplotSegs(const std::vector<Seg>& segs);

/// A circle as a closed polyline (gnuplot data, one block): gnuplot's "with circles" drops a
/// circle whose centre is outside the view, a polyline is clipped like any line.
std::string circlePolyline(double cx, double cy, double r, int n = 240);

/// A circle as a dashed polyline for gnuplot: `dashes` pieces, each drawn over `on` of its
/// period (blank lines between them), so that every terminal draws it dashed (gnuplot's gif
/// terminal draws a dash type solid).
std::string dashedCirclePolyline(double cx, double cy, double r, int dashes = 48, double on = 0.6);

/// gnuplotSegs(triangleSegs(xy, tri)): a triangulation with each edge once.
std::string gnuplotEdges(const std::vector<double>& xy,
                         const std::vector<std::array<int, 3>>& tri);

/// The part of the line through (ax, ay) with direction (dx, dy) inside the box
/// [x0, x1] x [y0, y1] (Liang-Barsky). A construction line is drawn as this segment, so that
/// gnuplot never has to clip a segment whose ends are both outside the view (it drops those).
/// Returns false if the line misses the box.
bool clipLine(double ax, double ay, double dx, double dy, double x0, double x1, double y0,
              double y1, Seg& out);

// ---- the notes' notation -------------------------------------------------------------------

/// Appends the UTF-8 encoding of `cp` to `out`.
void appendUtf8(std::string& out, char32_t cp);

/// The math font of the figures (Debian's fonts-dejavu-extra): it has the Unicode mathematical
/// alphanumerics (italic 𝑝, script 𝒞), which DejaVu Sans lacks.
inline const char* kMathFont = "DejaVu Math TeX Gyre";

/// A formula in the notes' notation as gnuplot enhanced text for the PNG and SVG terminals:
/// `tex` is a small TeX subset, e.g. "p_{n+1}", "\\sigma_{i+1}", "\\mathscr{C}(\\mathrm{DT}_n, p)",
/// "\\Sigma". Latin letters become mathematical italic (U+1D434...; h is U+210E), \\mathrm{...}
/// stays upright, a minus sign is U+2212, and the whole is set in the math font, so the figure
/// shows the notes' italic p with a real subscript and script 𝒞, ℬ. Unknown commands throw.
std::string mathText(const std::string& tex);

/// The same formula for gnuplot's gif terminal (libgd): libgd reads only 1- to 3-byte UTF-8,
/// so the mathematical alphanumerics are out; letters are set in DejaVu Serif Italic (the
/// design of the math font's italics), the rest in the math font. Script capitals outside the
/// Basic Multilingual Plane (𝒞) cannot be shown: the caller words those.
std::string mathTextGif(const std::string& tex);

/// A string as one gnuplot data column: in double quotes (it may hold spaces).
inline std::string quoted(const std::string& s) { return "\"" + s + "\""; }

// ---- panels with a known scale, and a label placer that sees everything drawn ---------------

/// One panel of a figure: its plot box on the canvas in pixels (y down from the top) and the
/// data view it shows, with equal scales on both axes. The chapter program lays the panels out
/// itself (fitPanel) and writes gnuplot() into the figure's view file, so that it knows where
/// every label lands in pixels, and a panel's box hugs its content (no blank bands).
struct Panel {
  double left = 0, top = 0, w = 1, h = 1;  // plot box, px
  double W = 1, H = 1;                     // canvas, px
  double x0 = 0, x1 = 1, y0 = 0, y1 = 1;   // data view
  double scale() const { return w / (x1 - x0); }  // px per data unit
  double px(double x) const { return left + (x - x0) * scale(); }
  double py(double y) const { return top + (y1 - y) * scale(); }
  /// gnuplot commands that give this panel its box and view (margins at screen, no ratio).
  std::string gnuplot() const;
};

/// The panel that shows the data box [bx0, bx1] x [by0, by1] as large as it fits into the cell
/// (cellLeft, cellTop, cellW, cellH px of a W x H canvas), equal scales, centred, `pad` px inside
/// the cell on every side; the view grows in one direction to fill the box.
Panel fitPanel(double W, double H, double cellLeft, double cellTop, double cellW, double cellH, double bx0,
               double bx1, double by0, double by1, double pad);


/// A figure's size and text em in pixels, as figures/ch2/style.gp gives them (its FIGSIZES and
/// FIG8CM tables; fig_em there): the chapter programs lay their panels out in these pixels.
struct FigureSize {
  double W = 0, H = 0, em = 0;
};

FigureSize figureSize(const std::string& name, const std::string& styleGp = std::string(DT_SOURCE_DIR) + "/figures/ch2/style.gp");

/// The panels of a figure laid out as rows x cols equal cells, each with a title band of
/// 2 em at its top (where style.gp's panel() writes "(a) ..."), each showing its data box as
/// large as it fits (fitPanel, 0.4 em inside the cell).
Panel cellPanel(const FigureSize& fs, int rows, int cols, int k, double bx0, double bx1, double by0, double by1,
                double bottomEm = 0);

/// The radius in px of a point drawn with "ps (k*PS)" (style.gp's fig_points: 0.2146 em).
inline double pointRadius(const FigureSize& fs, double k) { return k * 0.2146 * fs.em; }

/// A label's box in pixels (y down).
struct PxBox {
  double x0, y0, x1, y1;
};

/// The width in em of gnuplot enhanced text as DejaVu sets it, a little generous: sub- and
/// superscripts at 0.8, braces and font switches not counted. Only the placer uses it; the
/// figure test measures the real boxes from the font files.
double textWidthEm(const std::string& s);

/// Places labels beside their points so that no label touches anything drawn: edges,
/// circles, arrows, point markers, other labels, the panel's edges. Works in pixels of one
/// Panel. Add every obstacle first, then place the labels (each placed label becomes an
/// obstacle). A label keeps one place across panels and frames when it is placed once with
/// the obstacles of all of them (add the edges of every panel, then place).
class LabelPlacer {
 public:
  LabelPlacer(const Panel& p, double emPx) : p_(p), em_(emPx) {}
  /// A drawn segment (data units) of the given line width in px.
  void segment(double ax, double ay, double bx, double by, double widthPx = 2) {
    segs_.push_back({p_.px(ax), p_.py(ay), p_.px(bx), p_.py(by), 0.5 * widthPx});
  }
  void segments(const std::vector<Seg>& s, double widthPx = 2) {
    for (const Seg& g : s) segment(g.x0, g.y0, g.x1, g.y1, widthPx);
  }
  /// A circle (centre and radius in data units) as 96 segments.
  void circle(double cx, double cy, double r, double widthPx = 2);
  /// A point marker of radius `radiusPx`.
  void marker(double x, double y, double radiusPx) { discs_.push_back({p_.px(x), p_.py(y), radiusPx}); }
  /// A box already taken (a title, a legend), in px.
  void box(const PxBox& b) { boxes_.push_back(b); }
  /// The next placeAttached() tries this anchor (data units) first, e.g. the label's place in
  /// the frame before, and keeps it if it keeps every rule and is clear (no jump).
  void preferAt(double lx, double ly) { preferAt_ = {lx, ly}, hasPreferAt_ = true; }
  /// Two labels on one line (sharing more than half their height) must keep `px` more than
  /// the gap between them, so that they do not read as one run of text ("p8 p2"). 0: off.
  void sameLineExtra(double px) { sameLine_ = px; }

  /// The place (data units, the centre of the text) for the label `text` of the point (x, y):
  /// the candidate nearest the point, among 32 directions on rings of growing distance, whose
  /// box keeps `gap` px from every obstacle and stays inside the panel; if none is clear, the
  /// one with the largest clearance. `preferDeg` (an angle, or NaN) is tried first on each
  /// ring. The label's box becomes an obstacle.
  std::pair<double, double> place(double x, double y, const std::string& text, double preferDeg = NAN, double gap = 4);

  /// Like place(), but the label stays attached to its point as a textbook editor requires:
  /// its anchor and its box are nearer to its own point than to any other marker,
  /// its anchor and its box's centre at most `maxEm` em from the point, and the line from the
  /// point to the anchor crosses none of `edges` (data units: the triangulation drawn, so that
  /// no edge separates a label from its point). Among the candidates that keep these rules, the
  /// nearest one clear of every obstacle by `gap` px, else the clearest; `preferDeg` is tried
  /// first; `angleDeg`, if given, receives the direction chosen (to prefer it in the next panel
  /// or frame). If no candidate within maxEm is clear, one up to 2 maxEm away that is; failing
  /// that the clearest within maxEm; only if no candidate keeps the rules does it fall back to
  /// place().
  std::pair<double, double> placeAttached(double x, double y, const std::string& text, const std::vector<Seg>& edges,
                                          double preferDeg = NAN, double gap = 5, double maxEm = 1.5,
                                          double* angleDeg = nullptr);

  /// The clearance of the last label placed from everything else (px; negative if it
  /// touches something): whether place() or placeAttached() found a clear spot.
  double lastClearance() const { return boxes_.empty() ? 1e300 : clearance(boxes_.back(), true); }

  /// The least distance in px from the box to any obstacle or the panel's edge (negative
  /// inside one).
  double clearance(const PxBox& b, bool skipLast = false) const;

 private:
  static double boxPoint(const PxBox& b, double x, double y);
  // Whether the segment from the point (x, y) to (u, v) crosses the segment e (px), not
  // counting a touch within 1.5 px of the point (the point's own edges start there).
  static bool crosses(double x, double y, double u, double v, const std::array<double, 4>& e);
  static double boxSeg(const PxBox& b, const std::array<double, 5>& s);
  Panel p_;
  double em_;
  std::vector<std::array<double, 5>> segs_;  // x0 y0 x1 y1 half-width, px
  std::vector<std::array<double, 3>> discs_;
  std::vector<PxBox> boxes_;
  bool farther_ = false;  // placeAttached is looking beyond its maxEm
  double sameLine_ = 0;   // sameLineExtra
  std::pair<double, double> preferAt_{0, 0};
  bool hasPreferAt_ = false;
};

}  // namespace ch
