// Section 2.2: the Bowyer-Watson algorithm and its super-triangles.
//
// Regenerates Figure 2.5 (9 points, chosen by score, in the two super-triangles, then the
// triangulation after 1, 2, 3, 4 and all 9 insertions) with table_fig2_5 (its triangle counts), an animation of those
// insertions (fig2_5_anim_NN.png frames and fig2_5_anim.gif: the cavity, then the ball),
// Figure 2.6 (a configuration, found by a search over fixed seeds, where deleting the triangles
// of the super-triangles leaves part of the convex hull uncovered), and table_bowyer_watson
// (Algorithm 1, corrected, against Listing 2.7: same triangles, n(n+1) incircle tests, time),
// and table_fig2_6 (how often the hull is left uncovered, by super-triangle size).
//
//   sec2_2_bowyer_watson [--out DIR] [--quick] [--max-n N] [--no-plot] [--seed N]
// (--seed N: Figure 2.5's example is the best of a search from N; see figure25.)
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <map>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "bowyer_watson.h"
#include "check.h"
#include "common.h"
#include "figure_data.h"
#include "generators.h"
#include "predicates.h"
#include "star.h"
#include "triangulate.h"

namespace {

using dt::XY;
using Clock = std::chrono::steady_clock;

std::string num(double v) { return ch::fmt("%.10g", v); }

// The label of a point of Algorithm 1's numbering: p_{-1}..p_{-4}, p_1..p_n.
std::string pname(long id) { return id < 0 ? "p_{" + std::to_string(id) + "}" : "p_{" + std::to_string(id + 1) + "}"; }

// The boundary of a set of triangles that forms a disk, as a closed polyline (counter-clockwise).
std::string boundaryPolyline(const XY& xy, const std::vector<dt::Tri>& tris) {
  std::map<std::pair<int, int>, int> dir;
  for (const dt::Tri& t : tris)
    for (int k = 0; k < 3; ++k) dir[{t[k], t[(k + 1) % 3]}] = 1;
  std::map<int, int> next;
  for (const auto& [e, one] : dir)
    if (!dir.count({e.second, e.first})) next[e.first] = e.second;
  if (next.empty()) return "";
  std::string s;
  const int start = next.begin()->first;
  int v = start;
  std::size_t steps = 0;
  do {
    s += num(xy[2 * v]) + " " + num(xy[2 * v + 1]) + "\n";
    v = next[v];
  } while (v != start && ++steps <= next.size());
  return s + num(xy[2 * start]) + " " + num(xy[2 * start + 1]) + "\n";
}

struct CircleXY {
  double x, y, r;
};
CircleXY circumcircle(const XY& xy, int a, int b, int c) {
  const double ax = xy[2 * a], ay = xy[2 * a + 1];
  const double bx = xy[2 * b] - ax, by = xy[2 * b + 1] - ay, cx = xy[2 * c] - ax, cy = xy[2 * c + 1] - ay;
  const double d = 2 * (bx * cy - by * cx);
  const double ux = (cy * (bx * bx + by * by) - by * (cx * cx + cy * cy)) / d;
  const double uy = (bx * (cx * cx + cy * cy) - cx * (bx * bx + by * by)) / d;
  return {ax + ux, ay + uy, std::hypot(ux, uy)};
}

// ---- Figure 2.5 and its animation -----------------------------------------------------------

// Figure 2.5's example: 9 points in insertion order, the candidate (figure25Candidate) of the
// seed with the best score (Score25) among kFig25Tries seeds from --seed (default 25) on. For the
// book's seed that is seed 5005; figure25 checks that kFig25 is still what the search picks.
const XY kFig25 = {0.24, 0.95, 0.12, 0.08, 0.51, 0.69, 0.01, 0.86, 0.58, 0.15,
                   0.92, 0.38, 0.24, 0.55, 0.89, 0.77, 0.35, 0.31};
const double kFig25Factor = 1.5;  // super-square 1.5 times the box: small enough to see
const int kFig25Tries = 5000;

// How well a candidate shows what Figure 2.5 is about, as an editor measures it: the rules it
// breaks (the chosen one breaks none, or the log says which), then what makes it read better.
struct Score25 {
  int crowded = 0;         // pairs of points less than 4 marker radii apart
  int onEdge = 0;          // points not yet inserted less than 2 marker radii from an edge of DT_k (k = 0..9)
  int panelLabels = 0;     // labels of the six panels not clear of every line and label by 5 px within
                           // 1.5 em of their points, or less than 1.25 times nearer their points than any other
  int runs = 0;            // pairs of labels of a panel on one line less than 1 em apart (they read as one)
  int frameLabels = 0;     // labels of the animation's frames not clear within 1.5 em (circles pass near)
  double viewRatio = 0;    // the width of the animation's view (it holds every circle) over the square's
  double clear = 1e300;    // the least clearance of a panel label, px
  int broken() const { return crowded + onEdge + panelLabels + runs; }
  bool better(const Score25& o) const {
    if (broken() != o.broken()) return broken() < o.broken();
    if (frameLabels != o.frameLabels) return frameLabels < o.frameLabels;
    const double a = std::round(10 * viewRatio), b = std::round(10 * o.viewRatio);
    if (a != b) return a < b;
    return clear > o.clear;
  }
  std::string text() const {
    return ch::fmt("%d points crowded, %d near an edge, %d panel labels not clear within 1.5 em, %d pairs of labels in one run, "
                   "%d animation labels not clear, animation view %.2f squares wide, least label clearance %.1f px",
                   crowded, onEdge, panelLabels, runs, frameLabels, viewRatio, clear);
  }
};

// A candidate example: 9 points in the unit square on a grid of 0.01, each at least 0.2 from
// those before it (the first 9 of uniformPoints(400, seed) that are), in the order drawn; none
// if the 400 do not give 9.
XY figure25Candidate(std::uint64_t seed) {
  const XY pool = dt::uniformPoints(400, seed);
  XY out;
  for (std::size_t i = 0; i < pool.size() && out.size() < 18; i += 2) {
    const double x = std::round(100 * pool[i]) / 100, y = std::round(100 * pool[i + 1]) / 100;
    bool far = true;
    for (std::size_t j = 0; j < out.size(); j += 2) far = far && std::hypot(x - out[j], y - out[j + 1]) >= 0.2;
    if (far) out.push_back(x), out.push_back(y);
  }
  return out.size() == 18 ? out : XY{};
}

// What Figure 2.5's panels and the animation's frames share: the insertions
// (figure25Steps), the layout (figure25Panels, figure25Frames), the files they would write and
// the score.
struct Fig25 {
  XY points;  // the 9 points in insertion order
  dt::BowyerWatsonResult all;
  XY xy;
  std::vector<std::vector<ch::Seg>> shown;          // the edges of each panel
  std::vector<std::vector<ch::Seg>> allFrames;      // the edges of each frame
  std::vector<std::vector<CircleXY>> frameCircles;  // the circles of each frame
  std::vector<int> frameNew;                        // the point each frame inserts (-1: none)
  int frame = 0;                                    // the number of frames
  double x0 = 0, x1 = 0, y0 = 0, y1 = 0, m = 0;     // the points' box and the panels' margin
  ch::FigureSize fs, fa;                            // Figure 2.5's and the animation's sizes
  ch::Panel pa;                                     // the animation's view
  double animFont = 0, animPs = 0;
  std::vector<std::vector<double>> staticAngle;     // each label's direction in each panel, by k
  std::map<int, std::vector<std::pair<double, double>>> staticAt;  // each panel's labels, by k
  struct File {
    std::string name, text;
    bool logged;  // through ch::writeOut ("wrote ..."), else written quietly
  };
  std::vector<File> files;  // what the figure writes, once chosen
  ch::Table tab;            // table_fig2_5
  Score25 score;
  std::string name(std::size_t i) const { return ch::mathText(pname(all.ids[i])); }
  // A label row: x y name lx ly super.
  std::string row(std::size_t i, double lx, double ly) const {
    return num(xy[2 * i]) + " " + num(xy[2 * i + 1]) + " " + ch::quoted(name(i)) + " " + num(lx) + " " + num(ly) + " " +
           (all.ids[i] < 0 ? "1" : "0");
  }
  void out(const std::string& file, const std::string& text, bool logged = true) { files.push_back({file, text, logged}); }
};

// Figure 2.5's insertions: DT_0..DT_9 (fig2_5_K.dat for the panels), the animation's frames
// (fig2_5_anim_NN_*.dat: edges, cavity or ball, circles, the new point), its titles, and
// table_fig2_5.
void figure25Steps(Fig25& F) {
  // DT_0 and the points, numbered as Algorithm 1 does (super-vertices first).
  F.all = dt::bowyerWatson(F.points, kFig25Factor);
  const dt::BowyerWatsonResult& all = F.all;
  XY& xy = F.xy;
  xy = all.xy;
  std::vector<dt::Tri> tri = {{0, 1, 2}, {1, 0, 3}};
  ch::Table& tab = F.tab;
  tab.caption = "Figure 2.5: triangles of DT_k after k insertions into the two super-triangles "
                "(Algorithm 1); each insertion removes the cavity C and adds |C| + 2 triangles";
  tab.header = {"k", "cavity size", "ball size", "triangles"};
  tab.add({"0", "", "", std::to_string(tri.size())});
  F.out("fig2_5_0.dat", ch::gnuplotEdges(xy, tri));
  std::vector<std::vector<ch::Seg>>& shown = F.shown;
  shown = {ch::triangleSegs(xy, tri)};
  // Animation frames: 00 is DT_0; then for each point, the cavity (odd) and the ball (even).
  int& frame = F.frame;
  std::string titles;  // one line per frame: the PNG's title, a tab, the GIF's
  auto writeFrame = [&](const std::vector<dt::Tri>& mesh, const std::vector<dt::Tri>& fill, int ip,
                        const std::string& title) {
    const std::string stem = ch::fmt("fig2_5_anim_%02d", frame);
    F.out(stem + "_tri.dat", ch::gnuplotEdges(xy, mesh), false);
    F.out(stem + "_fill.dat", fill.empty() ? "" : boundaryPolyline(xy, fill), false);
    // The cavity's circumcircles, drawn on the cavity frames, dashed in the data (the GIF's
    // terminal draws every dash type solid); polylines, since most centres are outside the view.
    std::vector<CircleXY> cs;
    if (frame % 2 == 1)
      for (const dt::Tri& t : fill) cs.push_back(circumcircle(xy, t[0], t[1], t[2]));
    std::string circles;
    for (const CircleXY& c : cs) circles += ch::dashedCirclePolyline(c.x, c.y, c.r, std::max(24, int(60 * c.r)));
    F.out(stem + "_circles.dat", circles.empty() ? "NaN NaN\n" : circles, false);
    F.frameCircles.push_back(cs);
    F.frameNew.push_back(ip);
    F.out(stem + "_p.dat", ip < 0 ? "" : num(xy[2 * ip]) + " " + num(xy[2 * ip + 1]) + " " + pname(all.ids[ip]) + "\n", false);
    titles += title + "\n";
    F.allFrames.push_back(ch::triangleSegs(xy, mesh));
    ++frame;
  };
  writeFrame(tri, {}, -1, "DT_" + ch::mathText("0") + ": the two super-triangles\tDT_0: the two super-triangles");
  for (int k = 1; k <= 9; ++k) {
    const int ip = 3 + k;
    const std::vector<dt::Tri> before = tri;
    const dt::KernelStep s = dt::delaunayKernelStep(xy, tri, ip);
    std::vector<dt::Tri> ball(tri.end() - long(s.ball), tri.end());
    // The cavity: the triangles of DT_{k-1} that the library's step took away.
    const std::set<dt::Tri> kept(tri.begin(), tri.end() - long(s.ball));
    std::vector<dt::Tri> cavity;
    for (const dt::Tri& t : before)
      if (!kept.count(t)) cavity.push_back(t);
    if (cavity.size() != s.cavity) throw std::logic_error("figure 2.5: the step's cavity is not what it removed");
    // Titles: the PNG frames in the notes' notation; the GIF (libgd) cannot show 𝒞, so words.
    const std::string name = pname(all.ids[ip]);
    auto triangles = [](std::size_t n) { return std::to_string(n) + (n == 1 ? " triangle" : " triangles"); };
    writeFrame(before, cavity, ip, "inserting " + ch::mathText(name) + ": the cavity " + ch::mathText("\\mathscr{C}") + " (" +
                                       triangles(s.cavity) + ")\tinserting " + ch::mathTextGif(name) + ": the cavity (" +
                                       triangles(s.cavity) + ")");
    writeFrame(tri, ball, ip, "inserting " + ch::mathText(name) + ": the ball " + ch::mathText("\\mathscr{B}") + " (" +
                                  triangles(s.ball) + ")\tinserting " + ch::mathTextGif(name) + ": the ball (" + triangles(s.ball) + ")");
    tab.add({std::to_string(k), std::to_string(s.cavity), std::to_string(s.ball), std::to_string(tri.size())});
    if (k <= 4 || k == 9) {
      F.out(ch::fmt("fig2_5_%d.dat", k), ch::gnuplotEdges(xy, tri));
      shown.push_back(ch::triangleSegs(xy, tri));
    }
  }
  F.out("fig2_5_anim_titles.dat", titles);
  F.out("fig2_5_anim_count.dat", std::to_string(frame) + "\n");
}

// The box of a label in px as the placer sets it (anchor at its centre, 0.33 em above the baseline).
ch::PxBox labelBoxPx(const ch::Panel& p, double emPx, const std::string& text, double lx, double ly) {
  const double hw = 0.5 * ch::textWidthEm(text) * emPx, up = 0.47 * emPx,
               down = (text.find('_') != std::string::npos ? 0.85 : 0.6) * emPx;
  return {p.px(lx) - hw, p.py(ly) - up, p.px(lx) + hw, p.py(ly) + down};
}

// Points and labels. fig2_5_points.dat and fig2_5_super.dat: x y name giflabel (the markers).
// Each panel K of Figure 2.5 has its own labels (fig2_5_labels_K.dat: x y name lx ly super),
// placed with that panel's edges by placeAttached: beside its own point, on the point's side
// of every edge, within 1.5 em of the figure (1.5 / 0.85 of the labels' own em; one place for
// six panels was next to other points). The super-vertices' labels start outside the square,
// above or below their corner.
// A label keeps its direction from panel to panel where it can. Each animation frame has its
// labels too (fig2_5_anim_NN_labels.dat: x y name lx ly super giflabel), in the direction of
// the static panel that shows the same triangulation (at its very places on a frame without
// circles), clear of the frame's circles.
// The score's rules on points and panels are measured here.
// A candidate whose points already break more than `bound` rules is not laid out (false).
bool figure25Panels(Fig25& F, int bound = 1 << 30) {
  const XY& xy = F.xy;
  const std::vector<std::vector<CircleXY>>& frameCircles = F.frameCircles;
  double &x0 = F.x0, &x1 = F.x1, &y0 = F.y0, &y1 = F.y1;
  x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
  for (std::size_t i = 0; i < xy.size(); i += 2)
    x0 = std::min(x0, xy[i]), x1 = std::max(x1, xy[i]), y0 = std::min(y0, xy[i + 1]), y1 = std::max(y1, xy[i + 1]);
  // Room for the super-vertices' labels outside the square, above or below their corners: a
  // label's height, its gap and a marker, P px (m data units on a panel of m * w / (X + 2 m) px
  // per unit, X the square's width, w the panel's).
  const ch::FigureSize fs = F.fs = ch::figureSize("fig2_5"), fa = F.fa = ch::figureSize("fig2_5_anim");
  const double emL = 0.85 * fs.em, w = ch::cellPanel(fs, 3, 2, 0, 0, 1, 0, 1).w,
               P = 1.45 * emL + ch::pointRadius(fs, 1.3) + 2 * 5 + 2;
  const double m = F.m = P * (x1 - x0) / (w - 2 * P);
  // The animation's one view holds every circle of every frame (none cut by the canvas).
  double ax0 = x0 - m, ax1 = x1 + m, ay0 = y0 - m, ay1 = y1 + m;
  for (const auto& cs : frameCircles)
    for (const CircleXY& c : cs)
      ax0 = std::min(ax0, c.x - c.r), ax1 = std::max(ax1, c.x + c.r), ay0 = std::min(ay0, c.y - c.r), ay1 = std::max(ay1, c.y + c.r);
  F.score.viewRatio = std::max(ax1 - ax0, ay1 - ay0) / (x1 - x0);
  const double am = 0.01 * (ax1 - ax0);
  const ch::Panel pa = F.pa = ch::cellPanel(fa, 1, 1, 0, ax0 - am, ax1 + am, ay0 - am, ay1 + am, 2.5);
  const int panelOf[6] = {0, 1, 2, 3, 4, 9};
  const dt::BowyerWatsonResult& all = F.all;
  const std::size_t np = all.ids.size();
  auto name = [&](std::size_t i) { return F.name(i); };
  auto row = [&](std::size_t i, double lx, double ly) { return F.row(i, lx, ly); };
  const std::vector<std::vector<ch::Seg>>& shown = F.shown;
  // The points: apart, and off the edges of every DT_k that does not have them yet.
  {
    const double scale = ch::cellPanel(fs, 3, 2, 0, x0 - m, x1 + m, y0 - m, y1 + m).scale(), r = ch::pointRadius(fs, 1.3);
    for (std::size_t i = 0; i < np; ++i)
      for (std::size_t j = i + 1; j < np; ++j)
        F.score.crowded += std::hypot(xy[2 * i] - xy[2 * j], xy[2 * i + 1] - xy[2 * j + 1]) * scale < 4 * r;
    for (int k = 0; k <= 9; ++k)  // DT_k is frame 2k; points 4 + k on are not in it yet
      for (std::size_t i = 4 + std::size_t(k); i < np; ++i) {
        double d = 1e300;
        for (const ch::Seg& e : F.allFrames[std::size_t(2 * k)]) d = std::min(d, ch::segDistance(e, xy[2 * i], xy[2 * i + 1]));
        F.score.onEdge += d * scale < 2 * r;
      }
  }
  if (F.score.crowded + F.score.onEdge > bound) return false;
  // The labels of Figure 2.5 are set at 0.85 em (emL: 7.2 pt at 15 cm printed, 2 x 3 panels).
  std::vector<double> angle(np, NAN);
  for (std::size_t i = 0; i < 4; ++i) angle[i] = xy[2 * i + 1] > 0.5 * (y0 + y1) ? 90 : 270;
  std::vector<std::vector<double>>& staticAngle = F.staticAngle;
  staticAngle.assign(10, std::vector<double>(np, NAN));
  std::map<int, std::vector<std::pair<double, double>>>& staticAt = F.staticAt;
  std::string view;
  for (int k = 0; k < 6; ++k) {
    const ch::Panel pk = ch::cellPanel(fs, 3, 2, k, x0 - m, x1 + m, y0 - m, y1 + m);
    view += ch::fmt("P%d = \"", k + 1) + pk.gnuplot() + "\"\n";
    ch::LabelPlacer place(pk, emL);
    place.sameLineExtra(fs.em - 5);  // labels on one line at least 1 em apart (the gap is 5 px)
    place.segments(shown[k], 1.5 * std::max(1.5, fs.em / 18));
    for (std::size_t i = 0; i < np; ++i) place.marker(xy[2 * i], xy[2 * i + 1], ch::pointRadius(fs, 1.3));
    if (panelOf[k] > 0)  // the ring around the point inserted last (fig2_5.gp: ps 2.4, lw 2)
      place.marker(xy[2 * (3 + panelOf[k])], xy[2 * (3 + panelOf[k]) + 1], ch::pointRadius(fs, 2.4) + 2 * std::max(1.5, fs.em / 18));
    // The most crowded points first (most edges at them): their few clear wedges go to them.
    std::vector<std::size_t> order(np);
    std::vector<int> degree(np, 0);
    for (std::size_t i = 0; i < np; ++i) {
      order[i] = i;
      for (const ch::Seg& e : shown[k])
        degree[i] += (e.x0 == xy[2 * i] && e.y0 == xy[2 * i + 1]) || (e.x1 == xy[2 * i] && e.y1 == xy[2 * i + 1]);
    }
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return degree[a] > degree[b]; });
    std::vector<std::pair<double, double>> at(np);
    for (const std::size_t i : order) {
      at[i] = place.placeAttached(xy[2 * i], xy[2 * i + 1], name(i), shown[k], angle[i], 5, 1.5 / 0.85, &angle[i]);
      staticAngle[panelOf[k]][i] = angle[i];
      // The score: clear, within 1.5 em, and plainly nearer its own point than any other.
      const double c = place.lastClearance(), own = std::hypot(at[i].first - xy[2 * i], at[i].second - xy[2 * i + 1]);
      double other = 1e300;
      for (std::size_t j = 0; j < np; ++j)
        if (j != i) other = std::min(other, std::hypot(at[i].first - xy[2 * j], at[i].second - xy[2 * j + 1]));
      F.score.panelLabels += c < 5 - 1e-9 || own * pk.scale() > 1.5 * fs.em + 1e-6 || other < 1.25 * own;
      F.score.clear = std::min(F.score.clear, c);
    }
    for (std::size_t i = 0; i < np; ++i)
      for (std::size_t j = i + 1; j < np; ++j) {
        const ch::PxBox a = labelBoxPx(pk, emL, name(i), at[i].first, at[i].second),
                        b = labelBoxPx(pk, emL, name(j), at[j].first, at[j].second);
        const double overlapY = std::min(a.y1, b.y1) - std::max(a.y0, b.y0), gapX = std::max(a.x0 - b.x1, b.x0 - a.x1);
        F.score.runs += overlapY > 0.5 * std::min(a.y1 - a.y0, b.y1 - b.y0) && gapX < fs.em;
      }
    staticAt[panelOf[k]] = at;
    std::string labels;
    for (std::size_t i = 0; i < np; ++i) labels += row(i, at[i].first, at[i].second) + "\n";
    F.out(ch::fmt("fig2_5_labels_%d.dat", panelOf[k]), labels);
  }
  std::string pts, sup;
  for (std::size_t i = 0; i < np; ++i)
    (all.ids[i] < 0 ? sup : pts) += num(xy[2 * i]) + " " + num(xy[2 * i + 1]) + " " + ch::quoted(name(i)) + " " +
                                    ch::quoted(ch::mathTextGif(pname(all.ids[i]))) + "\n";
  F.out("fig2_5_points.dat", pts);
  F.out("fig2_5_super.dat", sup);
  // The animation's labels and markers are Figure 2.5's scaled to its view, so that a label
  // copied from a panel keeps the same room around it (fig2_5_anim.gp: ANIM_FONT of FS, ANIM_PS
  // of PS; the labels set smaller than Figure 2.5's where the view is smaller).
  const double ratio = pa.scale() / ch::cellPanel(fs, 3, 2, 0, x0 - m, x1 + m, y0 - m, y1 + m).scale();
  const double animFont = F.animFont = 0.85 * fs.em * ratio / fa.em, animPs = F.animPs = 1.3 * fs.em * ratio / fa.em;
  F.out("fig2_5_view.gp", view + "VIEWA = \"" + pa.gnuplot() + "\"\n" + ch::fmt("ANIM_FONT = %.4f; ANIM_PS = %.4f\n", animFont, animPs));
  return true;
}

// The animation's labels, frame by frame (see figure25Panels), and the score's count of those
// not clear within 1.5 em.
void figure25Frames(Fig25& F) {
  const XY& xy = F.xy;
  const dt::BowyerWatsonResult& all = F.all;
  const std::size_t np = all.ids.size();
  const ch::FigureSize& fa = F.fa;
  const ch::Panel& pa = F.pa;
  const int frame = F.frame;
  const double animFont = F.animFont, animPs = F.animPs;
  const auto& allFrames = F.allFrames;
  const auto& frameCircles = F.frameCircles;
  const auto& frameNew = F.frameNew;
  const auto& staticAngle = F.staticAngle;
  const auto& staticAt = F.staticAt;
  auto name = [&](std::size_t i) { return F.name(i); };
  auto row = [&](std::size_t i, double lx, double ly) { return F.row(i, lx, ly); };
  std::vector<double> fangle(np, NAN);
  std::vector<std::pair<double, double>> prevAt(np, {NAN, NAN});  // each label's place in the frame before
  for (int f = 0; f < frame; ++f) {
    // The triangulation a frame shows: DT_k on the ball frame 2k, DT_{k-1} on the cavity
    // frame 2k-1; the points inserted so far (and the one being inserted) are labelled.
    const int k = f == 0 ? 0 : f % 2 == 0 ? f / 2 : (f - 1) / 2;
    const std::size_t labelled = 4 + std::size_t((f + 1) / 2);
    ch::LabelPlacer place(pa, animFont * fa.em);
    place.segments(allFrames[f], 1.5 * std::max(1.5, fa.em / 18));
    for (const CircleXY& c : frameCircles[f]) place.circle(c.x, c.y, c.r, 1.5 * std::max(1.5, fa.em / 18));
    for (std::size_t i = 0; i < np; ++i) place.marker(xy[2 * i], xy[2 * i + 1], ch::pointRadius(fa, animPs));
    if (frameNew[f] >= 0) place.marker(xy[2 * frameNew[f]], xy[2 * frameNew[f] + 1], ch::pointRadius(fa, 1.4 * animPs));
    std::string labels;
    // A frame without circles that shows a panel's triangulation takes that panel's labels
    // (the two views have about the same label size per data unit); the others are placed,
    // in the panel's directions where they are clear.
    const bool same = staticAt.count(k) && frameCircles[f].empty();
    std::vector<std::size_t> order(labelled);  // the most crowded first: edges and circles near
    std::vector<int> degree(labelled, 0);
    for (std::size_t i = 0; i < labelled; ++i) {
      order[i] = i;
      for (const CircleXY& c : frameCircles[f])
        degree[i] += 2 * (std::fabs(std::hypot(xy[2 * i] - c.x, xy[2 * i + 1] - c.y) - c.r) * pa.scale() < 2 * fa.em);
      for (const ch::Seg& e : allFrames[f])
        degree[i] += (e.x0 == xy[2 * i] && e.y0 == xy[2 * i + 1]) || (e.x1 == xy[2 * i] && e.y1 == xy[2 * i + 1]);
    }
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return degree[a] > degree[b]; });
    std::vector<std::pair<double, double>> at(labelled);
    for (const std::size_t i : order) {
      const double prefer = staticAt.count(k) ? staticAngle[k][i] : fangle[i];
      if (same) {
        at[i] = staticAt.at(k)[i];
        fangle[i] = staticAngle[k][i];
        continue;
      }
      // No jump where none is needed: the static panel's place for this triangulation, else
      // the frame before's, if it is still clear.
      if (staticAt.count(k))
        place.preferAt(staticAt.at(k)[i].first, staticAt.at(k)[i].second);
      else if (!std::isnan(prevAt[i].first))
        place.preferAt(prevAt[i].first, prevAt[i].second);
      at[i] = place.placeAttached(xy[2 * i], xy[2 * i + 1], name(i), allFrames[f], prefer, 1.5, 1.5 / 0.85, &fangle[i]);
      F.score.frameLabels += place.lastClearance() < 1.5 - 1e-9 ||
                             std::hypot(at[i].first - xy[2 * i], at[i].second - xy[2 * i + 1]) * pa.scale() > 1.5 * animFont * fa.em / 0.85 + 1e-6;
    }
    for (std::size_t i = 0; i < labelled; ++i) {
      labels += row(i, at[i].first, at[i].second) + " " + ch::quoted(ch::mathTextGif(pname(all.ids[i]))) + "\n";
      prevAt[i] = at[i];
    }
    F.out(ch::fmt("fig2_5_anim_%02d_labels.dat", f), labels, false);
  }
}

void figure25(const ch::Options& o) {
  // The book's example is kFig25. A full run searches again from the book's seed and stops if
  // the search now picks other points (kFig25 is the search's result, kept in the source for the
  // live figure, which reads it when the build is configured); --quick draws kFig25 without the
  // search; --seed N draws the best candidate of a search from N. Every candidate is scored;
  // the frames (the costly part) only of those that may win.
  Fig25 best;
  std::uint64_t bestSeed = 0;
  if (o.quick && !o.seedOption) {
    best.points = kFig25;
    figure25Steps(best);
    figure25Panels(best);
    figure25Frames(best);
    std::cout << "Figure 2.5: the book's points (kFig25; --quick: not searched again): " << best.score.text() << "\n";
  } else {
    const std::uint64_t first = o.seed(25);
    bool have = false;
    for (std::uint64_t s = first; s < first + kFig25Tries; ++s) {
      if ((s - first) % 500 == 0) std::cerr << "Figure 2.5: scoring seeds " << s << ".." << s + 499 << "\n";
      Fig25 F;
      F.points = figure25Candidate(s);
      if (F.points.empty()) continue;
      figure25Steps(F);
      if (!figure25Panels(F, have ? best.score.broken() : 1 << 30)) continue;
      if (have && F.score.broken() > best.score.broken()) continue;
      figure25Frames(F);
      if (!have || F.score.better(best.score)) best = std::move(F), bestSeed = s, have = true;
    }
    if (!have) throw std::runtime_error(ch::fmt("Figure 2.5: no seed of %d from %llu gives 9 points 0.2 apart", kFig25Tries, (unsigned long long)first));
    std::cout << "Figure 2.5: seed " << bestSeed << ", the best of " << kFig25Tries << " seeds from " << first << ": "
              << best.score.text() << "\n";
    if (!o.seedOption && best.points != kFig25) {
      std::string xy;
      for (std::size_t i = 0; i < best.points.size(); ++i) xy += (i ? ", " : "") + ch::fmt("%.2f", best.points[i]);
      throw std::runtime_error("Figure 2.5: the search now picks other points than kFig25 (seed " + std::to_string(bestSeed) +
                               "): set kFig25 in chapters/ch2/sec2_2_bowyer_watson.cpp to {" + xy +
                               "} (the live figure reads it when the build is configured)");
    }
  }
  if (best.score.broken() > 0)
    std::cerr << "warning: Figure 2.5: its points break " << best.score.broken()
              << " of the figure's rules (see the score above); it is drawn anyway: try another --seed\n";
  for (const Fig25::File& f : best.files)
    if (f.logged)
      ch::writeOut(o, f.name, f.text);
    else
      dt::writeFileAtomic(o.out + "/" + f.name, f.text);
  std::cout << "wrote " << best.frame << " animation data sets " << o.out << "/fig2_5_anim_NN_*.dat\n";
  best.tab.emit(o, "table_fig2_5");
  ch::runGnuplot(o, "fig2_5.gp");
  ch::runGnuplot(o, "fig2_5_anim.gp");
}

// ---- Figure 2.6 ---------------------------------------------------------------------------

// What Figure 2.6 shows about one configuration: the first missing hull edge p_k p_l, the
// triangle p_k p_j p_l of DT(S) on it, and the edges of DT(S0 ∪ S) that cross p_k p_l.
struct Missing26 {
  int k = -1, j = -1, l = -1;                   // indices in the input points
  std::vector<std::pair<int, int>> crossing;    // edges crossing p_k p_l (indices in bw.xy)
  std::vector<int> superInCircle;               // super-vertices (0..3) inside circle(p_k p_j p_l)
  double radius = 0;
};

Missing26 analyse26(const XY& p, const dt::BowyerWatsonResult& bw, const std::array<long, 2>& edge) {
  Missing26 r;
  r.k = int(edge[0]), r.l = int(edge[1]);
  for (const dt::Tri& t : dt::bruteForceDelaunay(p))
    for (int c = 0; c < 3; ++c)
      if (t[c] == r.k && t[(c + 1) % 3] == r.l) r.j = t[(c + 2) % 3];
  if (r.j < 0) return r;
  for (int s = 0; s < 4; ++s)
    if (dt::incircle(p[2 * r.k], p[2 * r.k + 1], p[2 * r.l], p[2 * r.l + 1], p[2 * r.j], p[2 * r.j + 1],
                     bw.xy[2 * s], bw.xy[2 * s + 1]) > 0)
      r.superInCircle.push_back(s);
  r.radius = circumcircle(p, r.k, r.j, r.l).r;
  const int K = r.k + 4, L = r.l + 4;  // indices in bw.xy (super-vertices come first)
  auto P = [&](int i) { return dt::Point2{bw.xy[2 * i], bw.xy[2 * i + 1]}; };
  std::map<std::pair<int, int>, int> seen;
  for (const dt::Tri& t : bw.tri)
    for (int c = 0; c < 3; ++c) {
      const int a = std::min(t[c], t[(c + 1) % 3]), b = std::max(t[c], t[(c + 1) % 3]);
      if (a == K || a == L || b == K || b == L || !seen.emplace(std::make_pair(a, b), 1).second) continue;
      if (dt::segmentsIntersect(P(a), P(b), P(K), P(L))) r.crossing.push_back({a, b});
    }
  return r;
}

void figure26(const ch::Options& o) {
  // Search fixed seeds for 10 random points whose DT(S0 ∪ S) (super-square 1.5 times the box)
  // loses a hull edge of S when the super-triangles' faces are deleted. Show the first case
  // that looks like the notes' figure: one missing edge p_k p_l, crossed by the single edge
  // p_j p_{-1}, with a circumcircle of p_k p_j p_l small enough to draw.
  const double factor = 1.5;
  XY p;
  dt::BowyerWatsonResult bw;
  Missing26 mi;
  int found = 0, tried = 0, chosenSeed = -1;
  bool chosenLike = false;
  for (int seed = 1; seed <= 500; ++seed) {
    ++tried;
    const XY q = dt::uniformPoints(10, o.seed(2600 + seed));
    dt::BowyerWatsonResult r = dt::bowyerWatson(q, factor);
    const auto m = dt::hullEdgesNotCovered(r.xy, r.ids, r.tri);
    if (m.empty()) continue;
    ++found;
    if (chosenLike) continue;
    const Missing26 a = analyse26(q, r, m[0]);
    const double side = r.xy[2] - r.xy[0];  // p_{-2}.x - p_{-1}.x
    const bool like = m.size() == 1 && a.crossing.size() == 1 && a.crossing[0].first == 0 &&
                      a.crossing[0].second == a.j + 4 && a.radius < side;
    if (chosenSeed < 0 || like) p = q, bw = r, mi = a, chosenSeed = seed, chosenLike = like;
  }
  if (chosenSeed < 0) throw std::runtime_error("Figure 2.6: no configuration found");
  std::cout << "Figure 2.6: " << found << " of " << tried
            << " random 10-point sets (super-square 1.5 times the box) lose part of the hull; "
               "showing seed " << 2600 + chosenSeed << (chosenLike ? "" : " (not like the notes' figure)") << "\n";
  const int k = mi.k, j = mi.j, l = mi.l, K = k + 4, J = j + 4, L = l + 4;
  std::string crossing;
  for (const auto& [a, b] : mi.crossing)
    crossing += num(bw.xy[2 * a]) + " " + num(bw.xy[2 * a + 1]) + "\n" + num(bw.xy[2 * b]) + " " +
                num(bw.xy[2 * b + 1]) + "\n\n";
  std::cout << "Figure 2.6: hull edge " << pname(k) << " " << pname(l) << " is missing; " << pname(k) << " "
            << pname(j) << " " << pname(l) << " is in DT(S), its circle contains " << mi.superInCircle.size()
            << " super-vertices; " << mi.crossing.size() << " edge(s) of DT(S0 ∪ S) cross " << pname(k) << " "
            << pname(l) << "\n";
  std::vector<dt::Tri> kept;
  for (const dt::Tri& t : bw.tri)
    if (bw.ids[t[0]] >= 0 && bw.ids[t[1]] >= 0 && bw.ids[t[2]] >= 0) kept.push_back(t);
  const CircleXY c = circumcircle(p, k, j, l);
  // The views: (a) every point and the circle of p_k p_j p_l; (b) the hull of S. Labels are
  // placed off the edges of the panel they are in (em: 4.5% of the view).
  double ax0 = c.x - c.r, ax1 = c.x + c.r, ay0 = c.y - c.r, ay1 = c.y + c.r;
  for (std::size_t i = 0; i < bw.xy.size(); i += 2)
    ax0 = std::min(ax0, bw.xy[i]), ax1 = std::max(ax1, bw.xy[i]), ay0 = std::min(ay0, bw.xy[i + 1]), ay1 = std::max(ay1, bw.xy[i + 1]);
  double bx0 = p[0], bx1 = p[0], by0 = p[1], by1 = p[1];
  for (std::size_t i = 0; i < p.size(); i += 2)
    bx0 = std::min(bx0, p[i]), bx1 = std::max(bx1, p[i]), by0 = std::min(by0, p[i + 1]), by1 = std::max(by1, p[i + 1]);
  const double am = 0.1 * std::max(ax1 - ax0, ay1 - ay0), bm = 0.1 * std::max(bx1 - bx0, by1 - by0);  // room for labels
  ax0 -= am, ax1 += am, ay0 -= am, ay1 += am, bx0 -= bm, bx1 += bm, by0 -= bm, by1 += bm;
  // Both panels laid out in pixels (fig2_6_view.gp: PA, PB), each label placed clear of
  // everything its panel draws.
  const ch::FigureSize fs = ch::figureSize("fig2_6");
  const double lw = std::max(1.5, fs.em / 18);
  const ch::Panel pa = ch::cellPanel(fs, 1, 2, 0, ax0, ax1, ay0, ay1), pb = ch::cellPanel(fs, 1, 2, 1, bx0, bx1, by0, by1);
  const std::vector<ch::Seg> allSegs = ch::triangleSegs(bw.xy, bw.tri), keptSegs = ch::triangleSegs(bw.xy, kept);
  ch::LabelPlacer placeA(pa, fs.em), placeB(pb, fs.em);
  placeA.segments(allSegs, 1.2 * lw);
  placeA.circle(c.x, c.y, c.r, 2 * lw);
  placeB.segments(keptSegs, 1.5 * lw);
  for (const auto& [a, b] : mi.crossing) {
    placeA.segment(bw.xy[2 * a], bw.xy[2 * a + 1], bw.xy[2 * b], bw.xy[2 * b + 1], 3 * lw);
    placeB.segment(bw.xy[2 * a], bw.xy[2 * a + 1], bw.xy[2 * b], bw.xy[2 * b + 1], 3 * lw);
  }
  for (const auto& [u, v] : std::vector<std::pair<int, int>>{{k, l}, {k, j}, {j, l}}) placeB.segment(p[2 * u], p[2 * u + 1], p[2 * v], p[2 * v + 1], 2.5 * lw);
  for (std::size_t i = 0; i < p.size(); i += 2) {
    placeA.marker(p[i], p[i + 1], ch::pointRadius(fs, 0.8));
    placeB.marker(p[i], p[i + 1], ch::pointRadius(fs, 1.0));
  }
  for (int s = 0; s < 4; ++s) placeA.marker(bw.xy[2 * s], bw.xy[2 * s + 1], ch::pointRadius(fs, 1.3));
  // Each label beside its point: on its side of every edge of its panel, nearer it than any other
  // point (placeAttached); only if no such spot is clear, the nearest clear spot.
  std::vector<ch::Seg> edgesB = keptSegs;
  for (const auto& [u, v] : std::vector<std::pair<int, int>>{{k, l}, {k, j}, {j, l}}) edgesB.push_back({p[2 * u], p[2 * u + 1], p[2 * v], p[2 * v + 1]});
  auto attached = [](ch::LabelPlacer& placer, double x, double y, const std::string& text, const std::vector<ch::Seg>& edges) {
    ch::LabelPlacer trial = placer;
    const std::pair<double, double> at = trial.placeAttached(x, y, text, edges, NAN, 4);
    if (trial.lastClearance() >= 1) {
      placer = trial;
      return at;
    }
    return placer.place(x, y, text);
  };
  std::string labels, named;  // named: x y "name" of each labelled point of (b) (the tests read it)
  for (const auto& [idx, name] : std::vector<std::pair<int, std::string>>{{K, "p_k"}, {J, "p_j"}, {L, "p_l"}}) {
    const std::string text = ch::mathText(name);
    const auto [lx, ly] = attached(placeB, bw.xy[2 * idx], bw.xy[2 * idx + 1], text, edgesB);
    labels += num(lx) + " " + num(ly) + " " + ch::quoted(text) + "\n";
    named += num(bw.xy[2 * idx]) + " " + num(bw.xy[2 * idx + 1]) + " " + ch::quoted(text) + "\n";
  }
  // Super-vertex labels of (a); in (b), p_{-1} is named where its crossing edge leaves the view.
  std::string superLabel, exitLabel;
  for (int s = 0; s < 4; ++s) {
    const std::string text = ch::mathText(pname(bw.ids[s]));
    const auto [lx, ly] = attached(placeA, bw.xy[2 * s], bw.xy[2 * s + 1], text, allSegs);
    superLabel += num(bw.xy[2 * s]) + " " + num(bw.xy[2 * s + 1]) + " " + ch::quoted(text) + " " + num(lx) + " " + num(ly) + " " +
                  (std::count(mi.superInCircle.begin(), mi.superInCircle.end(), s) ? "1" : "0") + "\n";
  }
  // p_k, p_j, p_l named in (a) too, clear of the super-vertices' labels.
  std::string labelsA;
  for (const auto& [idx, name] : std::vector<std::pair<int, std::string>>{{K, "p_k"}, {J, "p_j"}, {L, "p_l"}}) {
    const std::string text = ch::mathText(name);
    const auto [lx, ly] = attached(placeA, bw.xy[2 * idx], bw.xy[2 * idx + 1], text, allSegs);
    labelsA += num(lx) + " " + num(ly) + " " + ch::quoted(text) + "\n";
  }
  for (const auto& [a, b] : mi.crossing) {
    const int sv = a < 4 ? a : b, other = a < 4 ? b : a;
    ch::Seg cl;
    if (!ch::clipLine(bw.xy[2 * other], bw.xy[2 * other + 1], bw.xy[2 * sv] - bw.xy[2 * other],
                      bw.xy[2 * sv + 1] - bw.xy[2 * other + 1], pb.x0, pb.x1, pb.y0, pb.y1, cl))
      continue;
    // cl runs along the line; its end towards the super-vertex is where the edge leaves the view.
    const double ex = cl.x1, ey = cl.y1;
    const std::string text = "to " + ch::mathText(pname(bw.ids[sv]));
    const auto [lx, ly] = placeB.place(ex, ey, text);
    exitLabel += num(ex) + " " + num(ey) + " " + num(lx) + " " + num(ly) + " " + ch::quoted(text) + "\n";
  }
  std::string pts;
  for (std::size_t i = 0; i < p.size() / 2; ++i) pts += num(p[2 * i]) + " " + num(p[2 * i + 1]) + "\n";
  ch::writeOut(o, "fig2_6_all.dat", ch::gnuplotSegs(allSegs));
  ch::writeOut(o, "fig2_6_kept.dat", dt::gnuplotTriangles(bw.xy, kept));
  ch::writeOut(o, "fig2_6_kept_edges.dat", ch::gnuplotSegs(keptSegs));
  ch::writeOut(o, "fig2_6_hull.dat", boundaryPolyline(p, dt::bruteForceDelaunay(p)));
  ch::writeOut(o, "fig2_6_points.dat", pts);
  ch::writeOut(o, "fig2_6_missing.dat", num(p[2 * k]) + " " + num(p[2 * k + 1]) + "\n" + num(p[2 * j]) + " " +
                                            num(p[2 * j + 1]) + "\n" + num(p[2 * l]) + " " + num(p[2 * l + 1]) + "\n" +
                                            num(p[2 * k]) + " " + num(p[2 * k + 1]) + "\n");
  ch::writeOut(o, "fig2_6_circle.dat", num(c.x) + " " + num(c.y) + " " + num(c.r) + "\n");
  ch::writeOut(o, "fig2_6_labels.dat", labels);
  ch::writeOut(o, "fig2_6_labels_a.dat", labelsA);
  ch::writeOut(o, "fig2_6_super.dat", superLabel);
  ch::writeOut(o, "fig2_6_named.dat", named);
  ch::writeOut(o, "fig2_6_exit.dat", exitLabel.empty() ? "NaN NaN NaN NaN x\n" : exitLabel);
  ch::writeOut(o, "fig2_6_crossing.dat", crossing);
  ch::writeOut(o, "fig2_6_view.gp", "PA = \"" + pa.gnuplot() + "\"\nPB = \"" + pb.gnuplot() + "\"\n");
  ch::runGnuplot(o, "fig2_6.gp");
  // How often it happens, for growing super-triangles (same 500 seeds).
  ch::Table tab;
  tab.caption = "Deleting the triangles that touch a super-vertex from DT(S0 ∪ S): how many of 500 "
                "random 10-point sets (uniform in the unit square) lose part of their convex hull, "
                "by the size of the super-square (a multiple of the points' bounding box)";
  tab.header = {"super-square / box", "sets tried", "hull not covered", "share"};
  for (double f : {1.5, 3.0, 10.0, 100.0, 1000.0}) {
    int lost = 0;
    for (int seed = 1; seed <= 500; ++seed) {
      const dt::BowyerWatsonResult r = dt::bowyerWatson(dt::uniformPoints(10, o.seed(2600 + seed)), f);
      lost += !dt::hullEdgesNotCovered(r.xy, r.ids, r.tri).empty();
    }
    tab.add({ch::fmt("%g", f), "500", std::to_string(lost), ch::fmt("%.1f%%", 100.0 * lost / 500)});
  }
  tab.emit(o, "table_fig2_6");
}

// ---- table_bowyer_watson ---------------------------------------------------------------------

void algorithm1Table(const ch::Options& o) {
  const std::size_t maxN = o.maxN > 0 ? std::size_t(o.maxN) : (o.quick ? 2000 : 16000);
  ch::Table tab;
  tab.caption = "Algorithm 1 (corrected, every triangle tested) against Listing 2.7 (delaunayTrgl, "
                "walk from the previous cavity), uniform random points, super-square 10 times the "
                "box; times are ratios to Listing 2.7 measured in the same run";
  tab.header = {"n", "incircle tests", "tests / n(n+1)", "Algorithm 1 / Listing 2.7 time",
                "same triangles", "Delaunay (exact)"};
  for (std::size_t n = 1000; n <= maxN; n *= 2) {
    const XY p = dt::uniformPoints(n, 2200 + n);
    // The machine may be shared: each time is the best of a few runs.
    auto t0 = Clock::now();
    dt::BowyerWatsonResult bw;
    double tBW = 1e300;
    for (int rep = 0; rep < (n <= 4000 ? 3 : 1); ++rep) {
      t0 = Clock::now();
      bw = dt::bowyerWatson(p);
      tBW = std::min(tBW, ch::secondsSince(t0));
    }
    double x0 = p[0], x1 = p[0], y0 = p[1], y1 = p[1];
    for (std::size_t i = 0; i < n; ++i) {
      x0 = std::min(x0, p[2 * i]), x1 = std::max(x1, p[2 * i]);
      y0 = std::min(y0, p[2 * i + 1]), y1 = std::max(y1, p[2 * i + 1]);
    }
    // Listing 2.7, timed several times (it is much faster) to get a stable baseline.
    double tL = 1e300;
    dt::PlainMesh m;
    for (int rep = 0; rep < 5; ++rep) {
      t0 = Clock::now();
      dt::Triangulation T;
      dt::initSuperTriangles(T, x0, y0, x1, y1);
      std::vector<dt::Vertex*> S;
      for (std::size_t i = 0; i < n; ++i) S.push_back(T.addVertex(p[2 * i], p[2 * i + 1], long(i)));
      dt::delaunayTrgl(T, S, dt::StartRule::LastCavity);
      tL = std::min(tL, ch::secondsSince(t0));
      if (rep == 0) m = dt::extractMesh(T, false);
    }
    const bool same = dt::canonicalTriangles(bw.ids, bw.tri) == dt::canonicalTriangles(m.ids, m.tri);
    const bool ok = dt::checkDelaunay(bw.xy, bw.tri).ok;
    tab.add({std::to_string(n), std::to_string(bw.incircleTests),
             ch::fmt("%.4f", double(bw.incircleTests) / (double(n) * double(n + 1))), ch::fmt("%.1f", tBW / tL),
             same ? "yes" : "no", ok ? "yes" : "no"});
    std::cerr << "n = " << n << " done\n";
  }
  tab.emit(o, "table_bowyer_watson");
}

}  // namespace

int main(int argc, char** argv) {
  const ch::Program p{"sec2_2_bowyer_watson",
                      "Section 2.2: Bowyer-Watson, super-triangles, Algorithm 1 (Figures 2.5, 2.6).",
                      1000, 1000000, {"fig2_5", "fig2_5_anim", "fig2_6"}, {}};
  return ch::runMain(argc, argv, p, [](const ch::Options& o) {
    if (o.wants("fig2_5") || o.wants("fig2_5_anim")) figure25(o);
    if (o.wants("fig2_6")) figure26(o);
    if (o.everything()) algorithm1Table(o);
  });
}
