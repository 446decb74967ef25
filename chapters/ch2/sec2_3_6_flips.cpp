// Section 2.3.6 (TODO in the notes): the edge flip, and DT(S) recovered from DT(S0 ∪ S) by flips;
// also the flip claim of 2.3.3 (degrees change by -1, -1, +1, +1).
//
// Writes into --out (default build/output/ch2):
//   fig_flip.{png,svg}              an edge flip, before and after, with the four adjacent triangles
//   fig_recovery_frames.{png,svg}   the recovery on a Figure-2.6-like configuration, frame by frame
//   table_flip_degrees.*            degrees of the four vertices over many random flips (2.3.3)
//   table_recovery_methods.*        the two ways to DT(S) on the same inputs: time and flips
//   table_recovery_sizes.*          super-triangle size vs. naive removal, 2.2.1's flips, full rule
#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <memory>
#include <random>
#include <set>
#include <sstream>

#include "check.h"
#include "common.h"
#include "figure_data.h"
#include "flip.h"
#include "generators.h"
#include "hilbert.h"
#include "hull.h"
#include "predicates.h"
#include "triangulate.h"

namespace {

using dt::XY;

void bbox(const XY& p, double& x0, double& y0, double& x1, double& y1) {
  x0 = x1 = p[0], y0 = y1 = p[1];
  for (std::size_t i = 0; i < p.size() / 2; ++i) {
    x0 = std::min(x0, p[2 * i]), x1 = std::max(x1, p[2 * i]);
    y0 = std::min(y0, p[2 * i + 1]), y1 = std::max(y1, p[2 * i + 1]);
  }
}

void superDT(dt::Triangulation& T, const XY& p, double factor, dt::InsertionStats* st = nullptr) {
  double x0, y0, x1, y1;
  bbox(p, x0, y0, x1, y1);
  dt::initSuperTriangles(T, x0, y0, x1, y1, factor);
  dt::delaunayTrgl(T, dt::addVertices(T, p), dt::StartRule::LastCavity, st);
}

bool meshIsDT(const dt::Triangulation& T, std::size_t n) {
  const dt::PlainMesh m = dt::extractMesh(T, true);
  return m.ids.size() == n && dt::checkDelaunay(m.xy, m.tri).ok;
}

// gnuplot helpers: triangles as closed polylines, filled polygons and labels as "set object".
std::string triData(const std::vector<const dt::Face*>& F) { return ch::gnuplotSegs(ch::faceSegs(F)); }
std::string polygon(int& id, const std::vector<const dt::Vertex*>& P, const char* color) {
  std::ostringstream s;
  s.precision(17);
  s << "set object " << ++id << " polygon from ";
  for (std::size_t i = 0; i <= P.size(); ++i)
    s << (i ? " to " : "") << P[i % P.size()]->x << "," << P[i % P.size()]->y;
  s << " fc rgb \"" << color << "\" fs solid 1.0 noborder behind\n";
  return s.str();
}
std::string segment(const dt::Vertex* a, const dt::Vertex* b, const char* color, double lw,
                    const char* dash = "1") {
  std::ostringstream s;
  s.precision(17);
  s << "set arrow from " << a->x << "," << a->y << " to " << b->x << "," << b->y
    << " nohead lc rgb \"" << color << "\" lw " << lw << " dt " << dash << " front\n";
  return s.str();
}
std::map<const dt::Vertex*, int> degrees(const dt::Triangulation& T) {
  std::map<const dt::Vertex*, int> d;
  for (const dt::Face* f : T.finiteFaces())
    for (const dt::Vertex* v : f->V) ++d[v];
  return d;
}

// ---- Figure: one flip, before and after, with the four adjacent triangles --------------------
// The smallest angle of a triangle, degrees.
double minAngle(const dt::Vertex* const* V) {
  double m = 180;
  for (int i = 0; i < 3; ++i) {
    const dt::Vertex *a = V[i], *b = V[(i + 1) % 3], *c = V[(i + 2) % 3];
    m = std::min(m, std::fabs(std::atan2((b->x - a->x) * (c->y - a->y) - (b->y - a->y) * (c->x - a->x),
                                         (b->x - a->x) * (c->x - a->x) + (b->y - a->y) * (c->y - a->y))) * 180 / M_PI);
  }
  return m;
}
// The angle at v between u and w, degrees.
double angleAt(const dt::Vertex* v, const dt::Vertex* u, const dt::Vertex* w) {
  return std::fabs(std::atan2((u->x - v->x) * (w->y - v->y) - (u->y - v->y) * (w->x - v->x),
                              (u->x - v->x) * (w->x - v->x) + (u->y - v->y) * (w->y - v->y))) * 180 / M_PI;
}

void figureFlip(const ch::Options& o) {
  // A convex quadrilateral a d b c around the edge a b, four outer neighbours, and a ring.
  // What the figure must show, as numbers: a b clearly not locally Delaunay (the
  // angles at c and d sum to 215-245 degrees, far from the cocircular 180: the circle through
  // a, b, c holds d well inside), and the six triangles drawn (the flip's two, before and after,
  // and the four around them) with no angle under 12 degrees. c and d are searched on a grid
  // (600 configurations, deterministic, a few milliseconds); the best score wins.
  XY p = {0, 0, 4, 0.4, 2.2, 2.2, 1.8, -1.6,        // a b c d
          -1.6, 1.6, 5.2, 2.4, 0.2, -3.2, 5.0, -3.0,  // beyond c a, b c, a d, d b
          -3, -1, 6.8, -0.2, 1.5, 4, 2.5, -4.5};
  std::unique_ptr<dt::Triangulation> Tp;
  std::vector<dt::Vertex*> S;
  dt::Face* f = nullptr;
  int k = -1;
  // Triangulates p with the edge a b (if the Delaunay triangulation chose the other diagonal
  // c d, it is flipped first: the figure needs a valid triangulation, not a Delaunay one).
  auto build = [&]() {
    Tp = std::make_unique<dt::Triangulation>();
    S = dt::addVertices(*Tp, p);
    dt::delaunayTrglHull(*Tp, S, dt::StartRule::LastCavity);
    auto find = [&](const dt::Vertex* u, const dt::Vertex* v, int& idx) -> dt::Face* {
      for (dt::Face& g : Tp->faces())
        for (int i = 0; i < 3; ++i)
          if (!g.isGhost() && ((g.V[i] == u && g.V[(i + 1) % 3] == v) || (g.V[i] == v && g.V[(i + 1) % 3] == u))) {
            idx = i;
            return &g;
          }
      return nullptr;
    };
    f = find(S[0], S[1], k);
    if (f == nullptr) {
      dt::Face* h = find(S[2], S[3], k);
      if (h == nullptr || !dt::flipEdge(h, k)) return false;
      f = find(S[0], S[1], k);
    }
    return f != nullptr && dt::isFlippable(f, k);
  };
  // The score: -1000 per rule missed, then the smallest angle, less the distance of the
  // angle sum from 230.
  auto score = [&]() {
    const dt::Face* g = f->F[k];
    double smallest = std::min(minAngle(f->V), minAngle(g->V));
    for (const dt::Face* h : {static_cast<const dt::Face*>(f), g})
      for (int j = 0; j < 3; ++j)
        if (h->F[j] != f && h->F[j] != g && h->F[j] && !h->F[j]->isGhost()) smallest = std::min(smallest, minAngle(h->F[j]->V));
    // after the flip: the triangles c d a and c d b
    const dt::Vertex *a = S[0], *b = S[1], *c = S[2], *d = S[3];
    smallest = std::min({smallest, angleAt(a, c, d), angleAt(c, a, d), angleAt(d, a, c), angleAt(b, c, d), angleAt(c, b, d), angleAt(d, b, c)});
    const double sum = angleAt(c, a, b) + angleAt(d, a, b);
    return -1000.0 * ((smallest < 12) + (sum < 215 || sum > 245)) + smallest - std::fabs(sum - 230) / 5;
  };
  double best = -1e300;
  XY bestP = p;
  for (int i = 0; i < 600; ++i) {
    p[4] = 1.6 + 0.2 * (i % 5), p[5] = 1.0 + 0.2 * (i / 5 % 5), p[6] = 1.5 + 0.2 * (i / 25 % 4), p[7] = -0.8 - 0.2 * (i / 100);
    if (!build()) continue;
    const double sc = score();
    if (sc > best) best = sc, bestP = p;
  }
  p = bestP;
  if (!build()) throw std::logic_error("flip figure: no edge a b");
  const double sum = angleAt(S[2], S[0], S[1]) + angleAt(S[3], S[0], S[1]);
  std::cout << "flip figure: c = (" << p[4] << ", " << p[5] << "), d = (" << p[6] << ", " << p[7]
            << "), the angles at c and d sum to " << ch::fmt("%.0f", sum) << " degrees; score " << ch::fmt("%.1f", best)
            << (best < 0 ? " (a rule is missed: see the figure's rules above)" : "") << "\n";
  dt::Triangulation& T = *Tp;
  const char* names[] = {"a", "b", "c", "d"};
  auto draw = [&](const std::string& stem, const dt::Vertex* e0, const dt::Vertex* e1,
                  const std::map<const dt::Vertex*, int>& d0,
                  const std::map<const dt::Vertex*, int>& d1, bool after) {
    std::string obj;
    int id = 0;
    // The two faces of the flip, and the four faces around them.
    const dt::Face* g = f->F[k];
    for (const dt::Face* h : {static_cast<const dt::Face*>(f), g}) {
      // The style's colours: the two faces replaced (cavity), the two made (ball), neighbours.
      obj += polygon(id, {h->V[0], h->V[1], h->V[2]}, after ? "#e5f5d5" : "#f0a830");
      for (int j = 0; j < 3; ++j) {
        const dt::Face* n = h->F[j];
        if (n != nullptr && n != f && n != g && !n->isGhost())
          obj += polygon(id, {n->V[0], n->V[1], n->V[2]}, "#6aaed6");
      }
    }
    obj += segment(e0, e1, after ? "#004d40" : "#c51b7d", 3.5);
    // The panel, laid out in pixels (VIEW), and each label placed clear of every edge and
    // label of it.
    const ch::FigureSize fs = ch::figureSize("fig_flip");
    const double lw = std::max(1.5, fs.em / 18);
    const ch::Panel pv = ch::cellPanel(fs, 1, 2, after ? 1 : 0, -3.2, 7.0, -4.8, 4.3);
    // The labels at 0.85 em (7.2 pt at 15 cm): "b: 5 (−1)" is wide for the triangles around b.
    ch::LabelPlacer placer(pv, 0.85 * fs.em);
    placer.segments(ch::faceSegs(T.finiteFaces()), 1.2 * lw);
    // Before: the circle through a, b, c, which holds d (why a b must flip), dashed.
    const double ax = S[0]->x, ay = S[0]->y, bx = S[1]->x - ax, by = S[1]->y - ay, cx = S[2]->x - ax, cy = S[2]->y - ay;
    const double den = 2 * (bx * cy - by * cx);
    const double ux = (cy * (bx * bx + by * by) - by * (cx * cx + cy * cy)) / den, uy = (bx * (cx * cx + cy * cy) - cx * (bx * bx + by * by)) / den;
    if (!after) {
      placer.circle(ax + ux, ay + uy, std::hypot(ux, uy), 1.5 * lw);
      ch::writeOut(o, "flip_circle.dat", ch::fmt("%.10g %.10g %.10g\n", ax + ux, ay + uy, std::hypot(ux, uy)));
    }
    placer.segment(e0->x, e0->y, e1->x, e1->y, 3.5 * lw);
    std::set<const dt::Vertex*> corners;  // every vertex: a label stays nearer its own than any
    for (const dt::Face* h : T.finiteFaces())
      for (const dt::Vertex* v : h->V) corners.insert(v);
    for (const dt::Vertex* v : corners) placer.marker(v->x, v->y, 0.5 * lw);
    const std::vector<ch::Seg> edges = ch::faceSegs(T.finiteFaces());
    std::ostringstream lab;
    lab.precision(17);
    std::string rows;
    for (int i = 0; i < 4; ++i) {
      const dt::Vertex* v = S[std::size_t(i)];
      const int before = d0.at(v), now = d1.at(v);
      std::string t = ch::mathText(names[i]) + ": " + std::to_string(after ? now : before);
      if (after) t += std::string(" (") + (now > before ? "+" : "\u2212") + std::to_string(std::abs(now - before)) + ")";
      // Beside its vertex (nearer it than any other vertex, no edge between) within 3 em (the
      // label is 3 to 4 em wide), clear of every line; else the nearest clear spot.
      ch::LabelPlacer trial = placer;
      auto [x, y] = trial.placeAttached(v->x, v->y, t, edges, NAN, 4, 3.0);
      if (trial.lastClearance() >= 1)
        placer = trial;
      else
        std::tie(x, y) = placer.place(v->x, v->y, t);
      lab << "set label \"" << t << "\" at " << x << "," << y << " center front font sprintf(',%.1f', 0.85 * FS)\n";
      rows += ch::fmt("%.10g %.10g ", v->x, v->y) + ch::quoted(t) + ch::fmt(" %.10g %.10g\n", x, y);
    }
    ch::writeOut(o, stem + "_labels.dat", rows);  // x y label lx ly: what the label rules check
    obj += lab.str() + "VIEW = \"" + pv.gnuplot() + "\"\n";
    ch::writeOut(o, stem + ".gp", obj);
    ch::writeOut(o, stem + "_tri.dat", triData(T.finiteFaces()));
  };
  const auto d0 = degrees(T);
  draw("flip_before", S[0], S[1], d0, d0, false);
  if (!dt::flipEdge(f, k)) throw std::logic_error("flip figure: flip refused");
  const auto d1 = degrees(T);
  // after the flip f = (c, a, d): the new edge is c d
  draw("flip_after", S[2], S[3], d0, d1, true);
  std::cout << "flip figure: degrees a " << d0.at(S[0]) << "->" << d1.at(S[0]) << ", b "
            << d0.at(S[1]) << "->" << d1.at(S[1]) << ", c " << d0.at(S[2]) << "->"
            << d1.at(S[2]) << ", d " << d0.at(S[3]) << "->" << d1.at(S[3]) << "\n";
  ch::runGnuplot(o, "fig_flip.gp");
}

// ---- 2.3.3: degrees over many random flips ------------------------------------------------------
void tableDegrees(const ch::Options& o) {
  dt::Triangulation T;
  // Points and flipped edges come from one stream (so not from dt::uniformPoints).
  std::mt19937_64 rng(o.seed(233));
  std::uniform_real_distribution<double> u(0, 1);
  XY p;
  for (int i = 0; i < 2000; ++i) p.push_back(u(rng)), p.push_back(u(rng));
  dt::delaunayTrglHull(T, dt::addVertices(T, p), dt::StartRule::LastCavity);
  std::vector<dt::Face*> live;
  for (dt::Face& f : T.faces())
    if (!f.isGhost()) live.push_back(&f);
  // Degrees kept up to date by the claim itself would be circular: recount around the four
  // vertices by walking all faces is too slow, so count the faces around each of the 4 vertices
  // from a full degree map refreshed every flip (2000 points: cheap enough for 2000 flips).
  const int trials = o.quick ? 400 : 3000;
  long tried = 0, refused = 0, ok = 0, bad = 0;
  std::map<const dt::Vertex*, int> deg = degrees(T);
  for (int t = 0; t < trials; ++t) {
    dt::Face* f = live[rng() % live.size()];
    const int k = int(rng() % 3);
    ++tried;
    if (!dt::isFlippable(f, k)) {
      ++refused;
      continue;
    }
    const dt::Vertex* q[4] = {f->V[k], f->V[(k + 1) % 3], f->V[(k + 2) % 3],
                              f->F[k]->V[(dt::neighbourIndex(f->F[k], f) + 2) % 3]};
    dt::flipEdge(f, k);
    const auto now = degrees(T);
    int changed = 0;
    for (const auto& [v, d] : now) changed += (deg[v] != d);
    const bool good = now.at(q[0]) == deg[q[0]] - 1 && now.at(q[1]) == deg[q[1]] - 1 &&
                      now.at(q[2]) == deg[q[2]] + 1 && now.at(q[3]) == deg[q[3]] + 1 &&
                      changed == 4;
    (good ? ok : bad) += 1;
    deg = now;
  }
  ch::Table t;
  t.caption = "Table (2.3.3): random edge flips on DT of 2000 random points; degree = number of "
              "adjacent triangles";
  t.header = {"edges drawn", "not flippable (hull or reflex)", "flipped",
              "degrees -1,-1,+1,+1 and no other change", "other outcomes"};
  t.add({std::to_string(tried), std::to_string(refused), std::to_string(ok + bad),
         std::to_string(ok), std::to_string(bad)});
  t.emit(o, "table_flip_degrees");
}

// ---- Figure: recovery frames on a Figure-2.6-like configuration ----------------------------------

// How well a case shows the recovery, as an editor measures it (figureRecovery's search): the
// rules it breaks (the chosen case breaks none, or the log says which), then how much of conv(S)
// frame (a) leaves uncovered (the pink the caption promises: more is easier to see).
struct RecScore {
  int crowded = 0;       // pairs of markers less than 4 point radii apart
  int onEdge = 0;        // (frame, vertex) pairs with an edge not at the vertex nearer than 2 point radii
  int labels = 0;        // labels not clear of every line of every frame by 4 px within 1.5 em of their
                         // points, or less than 1.25 times nearer their points than any other vertex
  double uncovered = 0;  // px^2 of conv(S) that no triangle of S covers in frame (a): at least 3000
  int broken() const { return crowded + onEdge + labels + (uncovered < 3000); }
  bool better(const RecScore& o) const { return broken() != o.broken() ? broken() < o.broken() : uncovered > o.uncovered; }
  std::string text() const {
    return ch::fmt("%d markers crowded, %d vertices near an edge, %d labels not clear within 1.5 em, %.0f px^2 of the hull uncovered",
                   crowded, onEdge, labels, uncovered);
  }
};

// The recovery of DT(S) from DT(S0 ∪ S) on the points p (super-triangles `factor` times their
// box), frame by frame: its layout, its score, and (if o is given) its files.
// A case whose markers already break more than `bound` rules is not labelled (its score is then
// incomplete, and worse than `bound`).
RecScore recoveryFrames(const XY& p, double factor, const ch::Options* o, int bound = 1 << 30) {
  // Replay: frame 0 = DT(S0 ∪ S), then one frame per flip, then DT(S).
  std::vector<std::array<const dt::Vertex*, 4>> log;
  dt::Triangulation R;
  superDT(R, p, factor);
  dt::Triangulation Rlog;
  superDT(Rlog, p, factor);
  const dt::FlipStats st = dt::recoverDelaunay(Rlog, dt::RecoveryRule::Full, &log);
  auto byId = [&](long id) -> dt::Vertex* {
    for (dt::Vertex& v : R.vertices())
      if (v.id == id) return &v;
    throw std::logic_error("recovery figure: vertex not found");
  };
  // conv(S), shaded as in Figure 2.6's caption.
  dt::Triangulation H;
  dt::delaunayTrglHull(H, dt::addVertices(H, p), dt::StartRule::LastCavity);
  std::vector<const dt::Vertex*> hull;
  for (dt::Vertex* v : dt::convexHull(H)) hull.push_back(byId(v->id));
  // The frames' grid (as fig_recovery_frames.gp lays it out) and one view for all.
  const int nframes = int(log.size()) + 2;
  const int cols = 2, rows = (nframes + cols - 1) / cols;  // two frames a row: room for the labels
  double x0, y0, x1, y1;
  bbox(p, x0, y0, x1, y1);
  const double cx = 0.5 * (x0 + x1), cy = 0.5 * (y0 + y1);
  const double R2 = factor * 0.5 * std::max(x1 - x0, y1 - y0) * 1.3;  // room for the corners' labels
  const ch::FigureSize fs = ch::figureSize("fig_recovery_frames");
  const double lw = std::max(1.5, fs.em / 18);
  const ch::Panel p0 = ch::cellPanel(fs, rows, cols, 0, cx - R2, cx + R2, cy - R2, cy + R2);
  const double scale = p0.scale(), r = ch::pointRadius(fs, 0.9);
  RecScore score;
  struct Frame {
    std::string obj, dat;
    std::vector<const dt::Vertex*> named;
    std::vector<ch::Seg> segs;     // every line drawn: the triangles and the flip's two edges
    std::vector<double> widths;    // their widths, px
  };
  std::vector<Frame> frames;
  auto frame = [&](const std::string& title, const dt::Vertex* e0, const dt::Vertex* e1, const dt::Vertex* n0,
                   const dt::Vertex* n1, bool dropSuper) {
    Frame fr;
    int id = 0;
    // conv(S) in pink, the triangles of S in pale blue on top: pink shows what they miss
    // (the style's colours: uncovered hull, covered hull, the removed edge in the conflict
    // colour, the new one in the ball's).
    fr.obj += polygon(id, hull, "#f4a582");
    for (const dt::Face* f : R.finiteFaces())
      if (f->V[0]->id >= 0 && f->V[1]->id >= 0 && f->V[2]->id >= 0)
        fr.obj += polygon(id, {f->V[0], f->V[1], f->V[2]}, "#dde6f0");
    if (e0) fr.obj += segment(e0, e1, "#c51b7d", 2.5, "2"), fr.segs.push_back({e0->x, e0->y, e1->x, e1->y}), fr.widths.push_back(2.5 * lw);
    if (n0) fr.obj += segment(n0, n1, "#004d40", 3), fr.segs.push_back({n0->x, n0->y, n1->x, n1->y}), fr.widths.push_back(3 * lw);
    fr.obj += "ftitle = \"" + title + "\"\n";
    std::vector<const dt::Face*> F;
    for (const dt::Face* f : R.finiteFaces())
      if (!dropSuper || (f->V[0]->id >= 0 && f->V[1]->id >= 0 && f->V[2]->id >= 0)) F.push_back(f);
    for (const ch::Seg& e : ch::faceSegs(F)) fr.segs.push_back(e), fr.widths.push_back(1.5 * lw);
    // The score: no vertex on an edge that does not end at it.
    for (const dt::Vertex& v : R.vertices()) {
      if (dropSuper && v.id < 0) continue;
      for (const ch::Seg& e : fr.segs) {
        const bool at = (e.x0 == v.x && e.y0 == v.y) || (e.x1 == v.x && e.y1 == v.y);
        if (!at && ch::segDistance(e, v.x, v.y) * scale < 2 * r) {
          ++score.onEdge;
          break;
        }
      }
    }
    // The super-vertices (drawn in every frame) and the four vertices of the frame's flip (its
    // title names them) are labelled. (All the points would crowd a frame.)
    for (const dt::Vertex& v : R.vertices())
      if (v.id < 0 || &v == e0 || &v == e1 || &v == n0 || &v == n1) fr.named.push_back(&v);
    fr.dat = triData(F);
    frames.push_back(fr);
  };
  auto nm = [](const dt::Vertex* v) {
    return ch::mathText(v->id < 0 ? "p_{" + std::to_string(v->id) + "}" : "p_{" + std::to_string(v->id + 1) + "}");
  };
  // What frame (a) leaves of conv(S) uncovered, in px^2.
  auto area = [](const dt::Vertex* a, const dt::Vertex* b, const dt::Vertex* c) {
    return 0.5 * std::fabs((b->x - a->x) * (c->y - a->y) - (b->y - a->y) * (c->x - a->x));
  };
  for (std::size_t i = 1; i + 1 < hull.size(); ++i) score.uncovered += area(hull[0], hull[i], hull[i + 1]);
  for (const dt::Face* f : R.finiteFaces())
    if (f->V[0]->id >= 0 && f->V[1]->id >= 0 && f->V[2]->id >= 0) score.uncovered -= area(f->V[0], f->V[1], f->V[2]);
  score.uncovered *= scale * scale;
  frame("DT(" + ch::mathText("S_0") + " ∪ " + ch::mathText("S") + ")", nullptr, nullptr, nullptr, nullptr, false);
  for (const auto& e : log) {
    const dt::Vertex *a = byId(e[0]->id), *b = byId(e[1]->id);
    dt::Face* f = nullptr;
    int idx = -1;
    for (dt::Face& g : R.faces())
      for (int i = 0; i < 3 && !f; ++i)
        if (g.V[i] == a && g.V[(i + 1) % 3] == b) f = &g, idx = i;
    if (f == nullptr || !dt::flipEdge(f, idx)) throw std::logic_error("recovery replay failed");
    frame(nm(a) + nm(b) + " → " + nm(e[2]) + nm(e[3]), a, b, byId(e[2]->id), byId(e[3]->id), false);
  }
  frame("DT(" + ch::mathText("S") + ")", nullptr, nullptr, nullptr, nullptr, true);
  const int k = int(frames.size());
  std::vector<const dt::Vertex*> all;
  for (const dt::Vertex& v : R.vertices()) all.push_back(&v);
  for (std::size_t i = 0; i < all.size(); ++i)
    for (std::size_t j = i + 1; j < all.size(); ++j)
      score.crowded += std::hypot(all[i]->x - all[j]->x, all[i]->y - all[j]->y) * scale < 4 * r;
  if (score.crowded + score.onEdge + (score.uncovered < 3000) > bound) return score;
  // Labels, frame by frame: beside their points (placeAttached: on the point's side of every
  // line of the frame, within 1.5 em), the super-vertices first, each in the direction it had in
  // the frame before where that is clear.
  std::vector<std::map<const dt::Vertex*, std::pair<double, double>>> spot(frames.size());
  std::map<const dt::Vertex*, double> angle;
  for (std::size_t i = 0; i < frames.size(); ++i) {
    const Frame& fr = frames[i];
    ch::LabelPlacer placer(p0, fs.em);
    for (std::size_t j = 0; j < fr.segs.size(); ++j) placer.segment(fr.segs[j].x0, fr.segs[j].y0, fr.segs[j].x1, fr.segs[j].y1, fr.widths[j]);
    for (const dt::Vertex* v : all) placer.marker(v->x, v->y, ch::pointRadius(fs, v->id < 0 ? 1.3 : 0.9));
    std::vector<const dt::Vertex*> order = fr.named;
    std::stable_partition(order.begin(), order.end(), [](const dt::Vertex* v) { return v->id < 0; });
    for (const dt::Vertex* v : order) {
      double a = angle.count(v) ? angle[v] : NAN;
      const std::pair<double, double> at = spot[i][v] = placer.placeAttached(v->x, v->y, nm(v), fr.segs, a, 4, 1.5, &a);
      angle[v] = a;
      const double own = std::hypot(at.first - v->x, at.second - v->y);
      double other = 1e300;
      for (const dt::Vertex* w : all)
        if (w != v) other = std::min(other, std::hypot(at.first - w->x, at.second - w->y));
      score.labels += placer.lastClearance() < 4 - 1e-9 || own * scale > 1.5 * fs.em + 1e-6 || other < 1.25 * own;
    }
  }
  if (!o) return score;
  for (int i = 0; i < k; ++i) {
    std::ostringstream lab;
    lab.precision(17);
    for (const dt::Vertex* v : frames[std::size_t(i)].named)
      lab << "set label \"" << nm(v) << "\" at " << spot[std::size_t(i)][v].first << "," << spot[std::size_t(i)][v].second << " center front tc rgb "
          << (v->id < 0 ? "C_SUPER" : "C_TRI") << "\n";
    const ch::Panel pk = ch::cellPanel(fs, rows, cols, i, cx - R2, cx + R2, cy - R2, cy + R2);
    ch::writeOut(*o, "rec_frame_" + std::to_string(i) + ".gp", frames[std::size_t(i)].obj + lab.str() + "VIEW = \"" + pk.gnuplot() + "\"\n");
    ch::writeOut(*o, "rec_frame_" + std::to_string(i) + ".dat", frames[std::size_t(i)].dat);
  }
  std::ostringstream g;
  g << "nframes = " << k << "\nrows = " << rows << "; cols = " << cols << "\n";
  ch::writeOut(*o, "rec_frames.gp", g.str());
  // The markers, with their names (a third column gnuplot does not plot; the tests read it).
  std::ostringstream sup, pts;
  sup.precision(17), pts.precision(17);
  for (const dt::Vertex& v : R.vertices())
    if (v.id < 0) sup << v.x << " " << v.y << " " << ch::quoted(nm(&v)) << "\n";
  for (const dt::Vertex& v : R.vertices())
    if (v.id >= 0) pts << v.x << " " << v.y << " " << ch::quoted(nm(&v)) << "\n";
  ch::writeOut(*o, "rec_super.dat", sup.str());
  ch::writeOut(*o, "rec_points.dat", pts.str());
  std::cout << "recovery figure: super factor " << factor << ", " << st.flips << " flips (" << st.notesFlips
            << " of 2.2.1's kind, " << st.superOpposite << " with a super opposite vertex, " << st.superSuper
            << " super-super, " << st.realReal << " between points of S)\n";
  return score;
}

const int kRecN = 7;  // points in the recovery figure (nine crowded its frames' labels)
const int kRecTries = 30000;
void figureRecovery(const ch::Options& o) {
  // Seven points in a flat box (flat hull triangles, as in Figure 2.6) and super-triangles only
  // 1.25 times the box. The cases: seeds where the naive removal fails and the recovery takes two
  // flips, both of 2.2.1's kind (a super-real edge whose two opposite vertices are points of S:
  // the notes' rule; four frames, the figure's grid of 2 x 2, full); the figure draws the best
  // of them by score (RecScore) among kRecTries seeds from --seed (default 1) on.
  const double factor = 1.25;
  const std::uint64_t first = o.seed(1);
  XY best;
  RecScore bestScore;
  std::uint64_t seed = 0;
  for (std::uint64_t s = first; s < first + kRecTries; ++s) {
    std::mt19937_64 rng(s);
    std::uniform_real_distribution<double> ux(0, 10), uy(0, 4);
    XY q;
    for (int i = 0; i < kRecN; ++i) q.push_back(std::round(ux(rng) * 10) / 10), q.push_back(std::round(uy(rng) * 10) / 10);
    dt::Triangulation T;
    superDT(T, q, factor);
    if (meshIsDT(T, kRecN)) continue;  // naive removal works: not a Figure 2.6 case
    std::vector<std::array<const dt::Vertex*, 4>> lg;
    const dt::FlipStats fst = dt::recoverDelaunay(T, dt::RecoveryRule::Full, &lg);
    if (lg.size() != 2 || fst.notesFlips != 2) continue;
    const RecScore sc = recoveryFrames(q, factor, nullptr, best.empty() ? 1 << 30 : bestScore.broken());
    if (best.empty() || sc.better(bestScore)) best = q, bestScore = sc, seed = s;
  }
  if (best.empty()) throw std::logic_error("recovery figure: no configuration found");
  std::cout << "recovery figure: seed " << seed << ", the best of " << kRecTries << " seeds from " << first << ": " << bestScore.text() << "\n";
  if (bestScore.broken() > 0)
    std::cerr << "warning: recovery figure: its case breaks " << bestScore.broken()
              << " of the figure's rules (see the score above); it is drawn anyway: try another --seed\n";
  recoveryFrames(best, factor, &o);
  ch::runGnuplot(o, "fig_recovery_frames.gp");
}

// ---- Tables: the two ways to DT(S) ---------------------------------------------------------------
XY family(const std::string& name, std::size_t n, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0, 1);
  if (name == "uniform square") return dt::uniformPoints(n, seed);
  if (name == "grid") {
    const int m = int(std::sqrt(double(n)));
    return dt::gridPoints(m, m);
  }
  if (name == "circle") return dt::circlePoints(n);
  XY p;
  if (name == "bent line") {  // flat parabolic arc + a few points below it
    for (std::size_t i = 0; i < n; ++i) {
      const double t = u(rng);
      p.push_back(t), p.push_back(1e-4 * t * (1 - t));
    }
  } else {  // "huge circle arc": a short arc of a circle of radius 1e6, with inner points
    const double R = 1e6;
    for (std::size_t i = 0; i < n; ++i) {
      const double t = 1e-3 * (u(rng) - 0.5);
      p.push_back(R * std::sin(t)), p.push_back(R * std::cos(t) - R - (i % 4 == 0 ? u(rng) * 30 : 0));
    }
  }
  return p;
}

XY hilbertSorted(const XY& p) {
  const auto ord = dt::hilbertOrder(p);
  XY q;
  for (std::size_t i : ord) q.push_back(p[2 * i]), q.push_back(p[2 * i + 1]);
  return q;
}

// A list of names as prose: "a", "a and b", "a, b and c" ("none" if empty).
std::string listing(const std::vector<std::string>& v) {
  if (v.empty()) return "none";
  std::string s;
  for (std::size_t i = 0; i < v.size(); ++i)
    s += (i == 0 ? "" : (i + 1 == v.size() ? " and " : ", ")) + v[i];
  return s;
}

// How many of `sizes` sizes something held for, as prose.
std::string howMany(int k, int sizes) {
  if (k == sizes) return "for every size tried";
  if (k == 0) return "for no size tried";
  return ch::fmt("for %d of the %d sizes tried", k, sizes);
}

void tableMethods(const ch::Options& o, ch::Values& v) {
  const std::size_t maxN = o.maxN ? std::size_t(o.maxN) : (o.quick ? 20000 : 200000);
  const std::vector<std::string> fams = {"uniform square", "grid", "circle", "bent line",
                                         "huge circle arc"};
  ch::Table t;
  // Two tables of the same runs (one would be wider than the book's page): times, then flips
  // and correctness.
  t.caption = "Two ways to DT(S) on the same points (Hilbert order, walk from the last cavity): "
              "times as ratios to the hull method measured in the same run";
  t.header = {"family", "n", "hull method (s)", "super-triangles + recovery / hull",
              "of which recovery / hull", "Lawson from the sweep / hull"};
  ch::Table f;
  f.caption = "The same runs: flips, and which method gives DT(S) (super-triangles 10 times the "
              "box; n_h: hull vertices)";
  f.header = {"family", "n", "n_h", "recovery flips", "flips / n_h", "2.2.1-kind flips",
              "naive removal is DT(S)", "2.2.1's flips alone give DT(S)", "both exact",
              "Lawson flips / n"};
  std::vector<std::string> naiveFail, naiveOk, notesFail;
  bool allExact = true;
  double maxFlipsPerHull = 0;
  std::vector<std::size_t> sizes;
  for (std::size_t n = 1000; n <= maxN; n *= 10) sizes.push_back(n);
  ch::Progress prog("2.3.6 methods", fams.size() * sizes.size());
  std::uint64_t done = 0;
  for (const auto& fam : fams)
    for (std::size_t n : sizes) {
      // Points on a flat arc make every method quadratic (cavities and flips of size O(n)).
      if (fam == "bent line" && n > (o.quick ? 1000u : 3000u)) continue;
      const XY p = hilbertSorted(family(fam, n, 36));
      const std::size_t np = p.size() / 2;
      using clk = std::chrono::steady_clock;
      // Hull method (median of 3 runs for small n keeps the ratios steady).
      const int reps = n <= 10000 ? 3 : 1;
      std::vector<double> th, ts, tr, tl;
      std::size_t nh = 0;
      bool exact = true;
      dt::FlipStats fs, ls;
      for (int r = 0; r < reps; ++r) {
        dt::Triangulation H;
        auto t0 = clk::now();
        dt::delaunayTrglHull(H, dt::addVertices(H, p), dt::StartRule::LastCavity);
        th.push_back(ch::secondsSince(t0));
        dt::Triangulation T;
        t0 = clk::now();
        superDT(T, p, 10.0);
        const auto t1 = clk::now();
        fs = dt::recoverDelaunay(T);
        tr.push_back(ch::secondsSince(t1));
        ts.push_back(ch::secondsSince(t0));
        dt::Triangulation L;
        t0 = clk::now();
        dt::sweepTriangulation(L, dt::addVertices(L, p));
        ls = dt::lawsonFlip(L);
        tl.push_back(ch::secondsSince(t0));
        if (r == 0) {
          const auto cH = dt::checkTriangulation(H), cT = dt::checkTriangulation(T),
                     cL = dt::checkTriangulation(L);
          exact = cH.ok && cT.ok && cL.ok && cH.nVertices == np && cT.nVertices == np;
          nh = cH.nHull;
        }
      }
      auto med = [](std::vector<double> v) {
        std::sort(v.begin(), v.end());
        return v[v.size() / 2];
      };
      // The recovery's share comes from the run whose whole is the median: medians taken
      // apart let the part exceed the whole.
      std::vector<std::size_t> byWhole(ts.size());
      for (std::size_t k = 0; k < ts.size(); ++k) byWhole[k] = k;
      std::sort(byWhole.begin(), byWhole.end(), [&](std::size_t a, std::size_t b) { return ts[a] < ts[b]; });
      const std::size_t mid = byWhole[byWhole.size() / 2];
      const double h = med(th), s = ts[mid], rc = tr[mid], l = med(tl);
      dt::Triangulation N;
      superDT(N, p, 10.0);
      const bool naive = meshIsDT(N, np);
      dt::recoverDelaunay(N, dt::RecoveryRule::NotesOnly);
      const bool notes = meshIsDT(N, np);
      t.add({fam, std::to_string(np), ch::fmt("%.4f", h), ch::fmt("%.3f", s / h),
             ch::fmt("%.3f", rc / h), ch::fmt("%.2f", l / h)});
      f.add({fam, std::to_string(np), std::to_string(nh), std::to_string(fs.flips),
             ch::fmt("%.2f", double(fs.flips) / double(nh)), std::to_string(fs.notesFlips),
             naive ? "yes" : "no", notes ? "yes" : "no", exact ? "yes" : "NO",
             ch::fmt("%.2f", double(ls.flips) / double(np))});
      auto note = [&](std::vector<std::string>& list) {
        if (std::find(list.begin(), list.end(), fam) == list.end()) list.push_back(fam);
      };
      note(naive ? naiveOk : naiveFail);
      if (!notes) note(notesFail);
      allExact = allExact && exact;
      if (fam != "bent line") maxFlipsPerHull = std::max(maxFlipsPerHull, double(fs.flips) / double(nh));
      prog.update(++done);
    }
  t.emit(o, "table_recovery_methods");
  f.emit(o, "table_recovery_flips");
  // A family is listed as working only if no size failed.
  std::vector<std::string> ok;
  for (const std::string& fam : naiveOk)
    if (std::find(naiveFail.begin(), naiveFail.end(), fam) == naiveFail.end()) ok.push_back(fam);
  v.set("s236.methods_naive_fail", listing(naiveFail));
  v.set("s236.methods_naive_ok", listing(ok));
  v.set("s236.methods_notes_fail", listing(notesFail));
  v.verdict("s236.methods_full_exact", allExact, "exact on every input", "NOT exact on some input");
  v.num("s236.methods_flips_per_hull_max", maxFlipsPerHull, "%.2f");  // as in the table
}

void tableSizes(const ch::Options& o, ch::Values& v) {
  ch::Table t;
  t.caption = "Super-triangle size (factor x the bounding box) vs. what recovers DT(S); "
              "n = 2000 points per family";
  t.header = {"family", "factor", "naive removal is DT(S)", "2.2.1's flips alone",
              "full rule: flips", "of 2.2.1's kind", "super opposite", "super-super",
              "S-S", "full rule exact"};
  const std::vector<double> factors = {1.001, 1.1, 2.0, 10.0, 1e3, 1e6};
  int allExact = 0, rows = 0;
  for (const std::string fam : {"uniform square", "bent line", "huge circle arc", "circle"}) {
    int naiveFails = 0, notesFails = 0;
    for (double factor : factors) {
      const XY p = hilbertSorted(family(fam, 2000, 37));
      const std::size_t np = p.size() / 2;
      dt::Triangulation N;
      superDT(N, p, factor);
      const bool naive = meshIsDT(N, np);
      dt::recoverDelaunay(N, dt::RecoveryRule::NotesOnly);
      const bool notes = meshIsDT(N, np);
      dt::Triangulation T;
      superDT(T, p, factor);
      const dt::FlipStats fs = dt::recoverDelaunay(T);
      const auto c = dt::checkTriangulation(T);
      t.add({fam, ch::fmt("%g", factor), naive ? "yes" : "no", notes ? "yes" : "no",
             std::to_string(fs.flips), std::to_string(fs.notesFlips),
             std::to_string(fs.superOpposite), std::to_string(fs.superSuper),
             std::to_string(fs.realReal), c.ok && c.nVertices == np ? "yes" : "NO"});
      naiveFails += !naive;
      notesFails += !notes;
      allExact += c.ok && c.nVertices == np;
      ++rows;
    }
    std::string key = fam;
    for (char& ch : key) ch = ch == ' ' ? '_' : ch;
    v.set("s236.sizes_naive_fails_" + key, howMany(naiveFails, int(factors.size())));
    v.set("s236.sizes_notes_fails_" + key, howMany(notesFails, int(factors.size())));
  }
  const double big = factors.back();
  v.set("s236.sizes_factors", ch::fmt("%g", factors.front()) + " to " +
                                  (big >= 1000 ? ch::fmt("10^%.0f", std::log10(big)) : ch::fmt("%g", big)));
  v.verdict("s236.sizes_full_exact", allExact == rows, "exact for every size and family tried",
            "NOT exact on some rows (see the table)");
  t.emit(o, "table_recovery_sizes");
}

}  // namespace

int main(int argc, char** argv) {
  const ch::Program p{"sec2_3_6_flips", "Section 2.3.6: edge flips, DT(S) from DT(S0 u S).", 1000,
                      10000000, {"fig_flip", "fig_recovery_frames"}, {}};
  return ch::runMain(argc, argv, p, [](const ch::Options& o) {
    if (o.wants("fig_flip")) figureFlip(o);
    if (o.everything()) tableDegrees(o);
    if (o.wants("fig_recovery_frames")) figureRecovery(o);
    if (!o.everything()) return;
    ch::Values v(o, "sec2_3_6_flips");
    tableSizes(o, v);
    tableMethods(o, v);
    v.write();
  });
}
