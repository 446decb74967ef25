// Section 2.1: the Delaunay kernel DT_{n+1} = DT_n - C + B (eq. 2.1).
//
// Regenerates Figure 2.1 (DT_n of 15 points; the cavity of p_{n+1} with its circumcircles),
// Figure 2.2 (a star-shaped polygon, its kernel by half-plane intersection, sight lines from a
// kernel point), Figure 2.3 (the proof of Proposition 2.1.1: the chain of cavity triangles met
// by the segment from a cavity triangle to p_{n+1}, and one step of the argument), Figure 2.4
// (the Delaunay ball and an outside triangle sigma_i sigma_{i+1} p_j with its circle), and
// table_kernel_checks: Proposition 2.1.1 and Property 2.1.1 checked exactly at every insertion.
//
//   sec2_1_kernel [--out DIR] [--quick] [--max-n N] [--no-plot]
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <map>
#include <memory>
#include <random>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include "check.h"
#include "common.h"
#include "generators.h"
#include "figure_data.h"
#include "predicates.h"
#include "star.h"
#include "triangulate.h"

namespace {

using dt::XY;

std::string num(double v) { return ch::fmt("%.10g", v); }

struct Circle {
  double x, y, r;
};
// Circumcircle in floating point: for drawing only (decisions use the exact predicates).
Circle circumcircle(const dt::Vertex* a, const dt::Vertex* b, const dt::Vertex* c) {
  const double bx = b->x - a->x, by = b->y - a->y, cx = c->x - a->x, cy = c->y - a->y;
  const double d = 2 * (bx * cy - by * cx);
  const double ux = (cy * (bx * bx + by * by) - by * (cx * cx + cy * cy)) / d;
  const double uy = (bx * (cx * cx + cy * cy) - cx * (bx * bx + by * by)) / d;
  return {a->x + ux, a->y + uy, std::hypot(ux, uy)};
}

std::string circleLine(const Circle& c) { return num(c.x) + " " + num(c.y) + " " + num(c.r) + "\n"; }

std::string triangleBlock(const dt::Face* f) {
  std::string s;
  for (int k = 0; k <= 3; ++k) s += num(f->V[k % 3]->x) + " " + num(f->V[k % 3]->y) + "\n";
  return s + "\n\n";  // two blank lines: one gnuplot "index" per triangle
}

// The boundary of a cavity, counter-clockwise, as a vertex cycle (Proposition 2.1.1 makes it
// one simple polygon; checkCavity has verified it before this is called).
std::vector<const dt::Vertex*> boundaryCycle(const std::vector<dt::Face*>& C) {
  std::map<std::pair<const dt::Vertex*, const dt::Vertex*>, int> dir;
  for (const dt::Face* f : C)
    for (int k = 0; k < 3; ++k) dir[{f->V[k], f->V[(k + 1) % 3]}] = 1;
  std::map<const dt::Vertex*, const dt::Vertex*> next;
  for (const auto& [e, one] : dir)
    if (!dir.count({e.second, e.first})) next[e.first] = e.second;
  std::vector<const dt::Vertex*> cyc;
  const dt::Vertex* v = next.begin()->first;
  do {
    cyc.push_back(v);
    v = next[v];
  } while (v != cyc.front() && cyc.size() <= next.size());
  return cyc;
}

bool contains(const std::vector<dt::Face*>& C, const dt::Face* f) {
  return std::find(C.begin(), C.end(), f) != C.end();
}

// The proof's chain: the faces met by the segment from q, a vertex of `from`, to p, found by a
// straight walk with exact orientation tests. Empty if the segment does not enter `from`
// through its interior, passes through a vertex, or leaves the cavity (Proposition 2.1.1
// forbids it).
std::vector<dt::Face*> chainTo(dt::Face* from, const dt::Vertex* q, const dt::Vertex* p,
                               const std::vector<dt::Face*>& C) {
  std::vector<dt::Face*> chain = {from};
  dt::Face* f = from;
  for (int step = 0; step < 200; ++step) {
    bool inside = true;
    for (int k = 0; k < 3; ++k) inside = inside && dt::orientationTest(f->V[k], f->V[(k + 1) % 3], p) >= 0;
    if (inside) return chain;
    int next = -1;
    for (int k = 0; k < 3 && next < 0; ++k) {
      const dt::Vertex *a = f->V[k], *b = f->V[(k + 1) % 3];
      if (a == q || b == q) continue;
      const int oa = dt::orientationTest(q, p, a), ob = dt::orientationTest(q, p, b);
      if (oa == 0 || ob == 0) return {};
      if (dt::orientationTest(a, b, p) < 0 && oa != ob) next = k;
    }
    if (next < 0 || f->F[next] == nullptr || !contains(C, f->F[next])) return {};
    f = f->F[next];
    chain.push_back(f);
  }
  return {};
}

const dt::Vertex* apexOf(const dt::Face* f, const dt::Face* g) {  // the vertex of f not in g
  for (const dt::Vertex* v : f->V)
    if (std::find(std::begin(g->V), std::end(g->V), v) == std::end(g->V)) return v;
  return nullptr;
}

// The names of the notes' proof (Figure 2.3) for a chain of four triangles
// p2p3p4 -> p2p4p5 -> p2p5p1 -> p1p5p6: vertices p1..p6 (index 0 unused), or empty if the chain
// does not have that shape (the walk turns around p2 for the third triangle, then around p5).
std::vector<const dt::Vertex*> notesNames(const std::vector<dt::Face*>& ch) {
  if (ch.size() != 4) return {};
  std::vector<const dt::Vertex*> v(7, nullptr);
  v[3] = apexOf(ch[0], ch[1]);
  v[4] = apexOf(ch[1], ch[2]);
  v[5] = apexOf(ch[1], ch[0]);
  v[2] = apexOf(ch[2], ch[3]);
  v[1] = apexOf(ch[2], ch[1]);
  v[6] = apexOf(ch[3], ch[2]);
  // p2 must be in the first two triangles (p2p3p4, p2p4p5), p5 in the last one.
  auto has = [](const dt::Face* f, const dt::Vertex* x) {
    return std::find(std::begin(f->V), std::end(f->V), x) != std::end(f->V);
  };
  if (!has(ch[0], v[2]) || !has(ch[1], v[2]) || !has(ch[0], v[4]) || !has(ch[3], v[5])) return {};
  return v;
}

// The step of a chain whose two circles differ most (centre distance over radius), so that
// Figure 2.3's right panel shows two distinct circles. Returns {index, spread}.
std::pair<std::size_t, double> widestStep(const std::vector<dt::Face*>& chain) {
  std::pair<std::size_t, double> best = {0, -1};
  for (std::size_t i = 0; i + 1 < chain.size(); ++i) {
    const Circle a = circumcircle(chain[i]->V[0], chain[i]->V[1], chain[i]->V[2]);
    const Circle b = circumcircle(chain[i + 1]->V[0], chain[i + 1]->V[1], chain[i + 1]->V[2]);
    const double spread = std::hypot(a.x - b.x, a.y - b.y) / std::max(a.r, b.r);
    if (spread > best.second) best = {i, spread};
  }
  return best;
}

// ---- Figure 2.2: a star-shaped polygon and its kernel -------------------------------------

// Figure 2.2's layout for the kernel point x and ker(Σ)'s label in the corner kerCorner: its files (if o is given) and its score, 100 for
// each label that no clear spot keeps beside its point (then placed by place(), unattached) and
// 1 for each label more than 1.5 em from its point.
int figure22Layout(const std::vector<dt::Point2>& P, const std::vector<dt::Point2>& K, const dt::Point2& x,
                   int kerCorner, const ch::Options* o) {
  int score = 0;
  std::string poly, ker, sight, lines, labels;
  // The view: the polygon with room for the labels, laid out in pixels (fig2_2_view.gp) so that
  // the labels are placed clear of everything drawn; the edge lines are clipped to it here.
  const ch::FigureSize fs = ch::figureSize("fig2_2");
  double vx0 = 1e300, vx1 = -1e300, vy0 = 1e300, vy1 = -1e300;  // the polygon, with room for labels
  for (const auto& q : P) vx0 = std::min(vx0, q.x), vx1 = std::max(vx1, q.x), vy0 = std::min(vy0, q.y), vy1 = std::max(vy1, q.y);
  const double vm = 0.14 * std::max(vx1 - vx0, vy1 - vy0);
  const ch::Panel pv = ch::fitPanel(fs.W, fs.H, 0, 0, fs.W, fs.H, vx0 - vm, vx1 + vm, vy0 - vm, vy1 + vm, 0.2 * fs.em);
  const double X0 = pv.x0, X1 = pv.x1, Y0 = pv.y0, Y1 = pv.y1, lw = std::max(1.5, fs.em / 18);
  ch::LabelPlacer placer(pv, fs.em);
  for (std::size_t i = 0; i <= P.size(); ++i)
    poly += num(P[i % P.size()].x) + " " + num(P[i % P.size()].y) + "\n";
  for (std::size_t i = 0; i <= K.size(); ++i) {
    ker += num(K[i % K.size()].x) + " " + num(K[i % K.size()].y) + "\n";
    if (i > 0) placer.segment(K[i - 1].x, K[i - 1].y, K[i % K.size()].x, K[i % K.size()].y, 2 * lw);
  }
  for (std::size_t j = 0; j < P.size(); ++j) {
    const dt::Point2 a = P[j], b = P[(j + 1) % P.size()];
    placer.segment(a.x, a.y, b.x, b.y, 2.5 * lw);
    placer.segment(x.x, x.y, a.x, a.y, 1.2 * lw);
    placer.marker(a.x, a.y, ch::pointRadius(fs, 0.9));
    sight += num(x.x) + " " + num(x.y) + "\n" + num(P[j].x) + " " + num(P[j].y) + "\n\n";
    // The line of each edge, the border of its half-plane: from the edge to the kernel (the
    // part of the line where it bounds the intersection), a little beyond both, clipped to
    // the view; not across the whole view, where the lines cluttered the corners' labels.
    const double ex = b.x - a.x, ey = b.y - a.y, e2 = ex * ex + ey * ey, pad = 0.12 / std::sqrt(e2);
    double t0 = 0, t1 = 1;
    for (const auto& q : K) {
      const double t = ((q.x - a.x) * ex + (q.y - a.y) * ey) / e2;
      t0 = std::min(t0, t), t1 = std::max(t1, t);
    }
    t0 -= pad, t1 += pad;
    ch::Seg l{a.x + t0 * ex, a.y + t0 * ey, a.x + t1 * ex, a.y + t1 * ey};
    if (ch::clipLine(l.x0, l.y0, l.x1 - l.x0, l.y1 - l.y0, std::max(X0, std::min(l.x0, l.x1)), std::min(X1, std::max(l.x0, l.x1)),
                     std::max(Y0, std::min(l.y0, l.y1)), std::min(Y1, std::max(l.y0, l.y1)), l)) {
      lines += num(l.x0) + " " + num(l.y0) + "\n" + num(l.x1) + " " + num(l.y1) + "\n\n";
      placer.segment(l.x0, l.y0, l.x1, l.y1, 1.2 * lw);
    }
  }
  placer.marker(x.x, x.y, ch::pointRadius(fs, 1.5));
  // ker(Σ): in a free corner of the view (kerCorner: 0 lower left, 1 lower right, 2 upper left,
  // 3 upper right), with an arrow to a kernel point near the kernel's corner on that side (the
  // sight lines fill the kernel's middle). The arrow is an obstacle.
  const double sx = (kerCorner & 1) ? -1 : 1, sy = (kerCorner & 2) ? -1 : 1;
  std::size_t low = 0;
  for (std::size_t i = 0; i < K.size(); ++i)
    if (sx * K[i].x + sy * K[i].y < sx * K[low].x + sy * K[low].y) low = i;
  double kx = 0, ky = 0;
  for (const auto& q : K) kx += q.x / double(K.size()), ky += q.y / double(K.size());
  const double ax = 0.5 * (kx + K[low].x), ay = 0.5 * (ky + K[low].y);
  const std::string kerName = "ker(" + ch::mathText("\\Sigma") + ")";
  // Its place: the clearest in that quarter of the view (left-aligned text).
  const double kerW = ch::textWidthEm(kerName) * fs.em;  // px
  auto kerBox = [&](double x, double y) {
    return ch::PxBox{pv.px(x) - 3, pv.py(y) - 0.5 * fs.em - 3, pv.px(x) + kerW + 3, pv.py(y) + 0.65 * fs.em + 3};
  };
  double tx = 0, ty = 0, bestC = -1e300;
  for (int i = 0; i <= 20; ++i)
    for (int j = 0; j <= 20; ++j) {
      const double fx = 0.02 + 0.3 * i / 20, fy = 0.04 + 0.3 * j / 20;
      const double x = sx > 0 ? X0 + fx * (X1 - X0) : X1 - fx * (X1 - X0) - kerW / pv.scale(),
                   y = sy > 0 ? Y0 + fy * (Y1 - Y0) : Y1 - fy * (Y1 - Y0);
      const double c = std::min(placer.clearance(kerBox(x, y)), 12.0) - 0.001 * (i + j);
      if (c > bestC) bestC = c, tx = x, ty = y;
    }
  placer.box(kerBox(tx, ty));
  // The arrow's tail: beside the text's end nearer the kernel, a little above (below) it.
  const double tailx = sx > 0 ? tx + (kerW + 0.3 * fs.em) / pv.scale() : tx - 0.3 * fs.em / pv.scale(),
               taily = ty + sy * (sy > 0 ? 0.3 : 0.7) * fs.em / pv.scale();
  placer.segment(tailx, taily, ax, ay, 1.5 * lw);
  // Corner labels, then x's, then ker(Σ)'s (its place is fixed: it only has to be clear).
  // Each label attached to its point: no edge or sight line between them.
  std::vector<ch::Seg> drawn;
  for (std::size_t j = 0; j < P.size(); ++j) {
    const dt::Point2 a = P[j], b = P[(j + 1) % P.size()];
    drawn.push_back({a.x, a.y, b.x, b.y});
    drawn.push_back({x.x, x.y, a.x, a.y});
  }
  for (std::size_t j = 0; j < P.size(); ++j) {
    const std::string name = ch::mathText("\\sigma_{" + std::to_string(j + 1) + "}");
    // Prefer the direction away from x: outside the polygon, where the corner is alone.
    const double away = std::atan2(P[j].y - x.y, P[j].x - x.x) * 180 / M_PI;
    // Attached where a clear spot is; else the nearest clear spot (a label never on a line).
    ch::LabelPlacer trial = placer;
    auto [lx, ly] = trial.placeAttached(P[j].x, P[j].y, name, drawn, away, 4);
    if (trial.lastClearance() >= 1) {
      placer = trial;
      score += std::hypot(lx - P[j].x, ly - P[j].y) * pv.scale() > 1.5 * fs.em;
    } else {
      std::tie(lx, ly) = placer.place(P[j].x, P[j].y, name, away);
      score += 100;
    }
    labels += num(lx) + " " + num(ly) + " " + ch::quoted(name) + "\n";
  }
  {
    // x's label in the widest angle between two of its sight lines.
    std::vector<double> ang;
    for (const auto& q : P) ang.push_back(std::atan2(q.y - x.y, q.x - x.x));
    std::sort(ang.begin(), ang.end());
    double gapMid = 0, gapWidth = -1;
    for (std::size_t j = 0; j < ang.size(); ++j) {
      const double a0 = ang[j], a1 = j + 1 < ang.size() ? ang[j + 1] : ang[0] + 2 * M_PI;
      if (a1 - a0 > gapWidth) gapWidth = a1 - a0, gapMid = 0.5 * (a0 + a1);
    }
    const std::string name = ch::mathText("x");
    // (its sight lines fan out from it: the label may sit across one, clear of it)
    std::vector<ch::Seg> sides;
    for (std::size_t j = 0; j < P.size(); ++j) sides.push_back({P[j].x, P[j].y, P[(j + 1) % P.size()].x, P[(j + 1) % P.size()].y});
    ch::LabelPlacer trial = placer;
    auto [lx, ly] = trial.placeAttached(x.x, x.y, name, sides, gapMid * 180 / M_PI, 3, 2.5);
    if (trial.lastClearance() >= 1) {
      placer = trial;
      score += std::hypot(lx - x.x, ly - x.y) * pv.scale() > 1.5 * fs.em;
    } else {
      std::tie(lx, ly) = placer.place(x.x, x.y, name, gapMid * 180 / M_PI);
      score += 100;
    }
    if (o) ch::writeOut(*o, "fig2_2_xlabel.dat", num(lx) + " " + num(ly) + " " + ch::quoted(name) + "\n");
  }
  if (o) ch::writeOut(*o, "fig2_2_view.gp", ch::fmt("X0 = %.10g; X1 = %.10g; Y0 = %.10g; Y1 = %.10g\n", X0, X1, Y0, Y1) +
                                       "VIEW = \"" + pv.gnuplot() + "\"\n" +
                                       ch::fmt("AX = %.10g; AY = %.10g; TX = %.10g; TY = %.10g; TAILX = %.10g; TAILY = %.10g\n", ax, ay, tx, ty, tailx, taily) +
                                       "KER = \"" + kerName + "\"\n");
  if (o) ch::writeOut(*o, "fig2_2_polygon.dat", poly);
  if (o) ch::writeOut(*o, "fig2_2_kernel.dat", ker);
  if (o) ch::writeOut(*o, "fig2_2_sight.dat", sight);
  if (o) ch::writeOut(*o, "fig2_2_lines.dat", lines);
  if (o) ch::writeOut(*o, "fig2_2_labels.dat", labels);
  if (o) ch::writeOut(*o, "fig2_2_x.dat", num(x.x) + " " + num(x.y) + "\n");
  return score;
}

void figure22(const ch::Options& o) {
  // An irregular seven-pointed star (counter-clockwise), fixed corners.
  const double outer[7] = {1.00, 0.86, 1.10, 0.95, 0.80, 1.05, 0.90};
  const double inner[7] = {0.46, 0.52, 0.40, 0.55, 0.48, 0.43, 0.50};
  std::vector<dt::Point2> P;
  for (int k = 0; k < 7; ++k) {
    const double a = 2 * M_PI * k / 7 + 0.2, b = a + M_PI / 7 + 0.06 * std::sin(3.0 * k);
    P.push_back({outer[k] * std::cos(a), outer[k] * std::sin(a)});
    P.push_back({inner[k] * std::cos(b) + 0.05, inner[k] * std::sin(b) - 0.03});
  }
  const std::vector<dt::Point2> K = dt::polygonKernel(P);
  dt::Point2 x = {0, 0};
  for (const auto& q : K) x.x += q.x / double(K.size()), x.y += q.y / double(K.size());
  // x: a kernel point off the centre, so that the sight lines fan, chosen by score
  // (figure22Layout): every label beside its point and clear, as near as that allows; among
  // the centroid moved 0.15 to 0.6 of the way to each corner of the kernel (in order; the first
  // best wins).
  // ker(Σ)'s label goes in one of the view's corners, also by score.
  const dt::Point2 c = x;
  int best = 1 << 30, kerCorner = 0;
  for (int corner = 0; corner < 4; ++corner)
    for (const double t : {0.3, 0.15, 0.45, 0.6})
      for (const dt::Point2& q : K) {
        const dt::Point2 cand = {c.x + t * (q.x - c.x), c.y + t * (q.y - c.y)};
        if (!dt::inOpenKernel(P, cand)) continue;
        const int score = figure22Layout(P, K, cand, corner, nullptr);
        if (score < best) best = score, x = cand, kerCorner = corner;
      }
  std::size_t seen = 0;
  for (std::size_t j = 0; j < P.size(); ++j) seen += dt::seesCorner(P, x, j);
  std::cout << "Figure 2.2: polygon of " << P.size() << " corners, kernel of " << K.size()
            << " corners; the kernel point sees " << seen << "/" << P.size()
            << " corners (exact test); in the open kernel: " << dt::inOpenKernel(P, x) << "\n";
  std::cout << "Figure 2.2: the kernel point x chosen by score: " << best << " (100 per label not attached, 1 per label beyond 1.5 em)\n";
  figure22Layout(P, K, x, kerCorner, &o);
  ch::runGnuplot(o, "fig2_2.gp");
}

// ---- Figures 2.1, 2.3, 2.4: one point set, one new point ----------------------------------

// The example the three figures share: DT_n of 15 points, the new point p_{n+1} (not yet
// inserted), its cavity C and the cavity's boundary sigma (counter-clockwise).
struct KernelExample {
  std::unique_ptr<dt::Triangulation> T;
  std::vector<dt::Vertex*> S;
  dt::Vertex* p = nullptr;
  std::vector<dt::Face*> C;
  std::vector<const dt::Vertex*> sigma;
  std::vector<ch::Seg> dtnSegs;  // DT_n's edges, each once
};

// Panel k (0 or 1) of Figure 2.1: the points of S with a margin of 2 percent.
ch::Panel figure21Panel(const std::vector<dt::Vertex*>& S, int k) {
  double bx0 = 1e300, bx1 = -1e300, by0 = 1e300, by1 = -1e300;
  for (const dt::Vertex* v : S)
    bx0 = std::min(bx0, v->x), bx1 = std::max(bx1, v->x), by0 = std::min(by0, v->y), by1 = std::max(by1, v->y);
  const double m = 0.02 * (bx1 - bx0);
  return ch::cellPanel(ch::figureSize("fig2_1"), 1, 2, k, bx0 - m, bx1 + m, by0 - m, by1 + m);
}

// DT_n of the jittered grid of seed `seed`: 15 points, a 4 x 4 grid without one corner,
// jittered, so that DT_n has triangles of reasonable shapes.
void jitteredGrid(unsigned seed, KernelExample& ex) {
  XY pts;
  std::mt19937_64 jr(seed);
  std::uniform_real_distribution<double> j(-0.11, 0.11);
  for (int a = 0; a < 4; ++a)
    for (int b = 0; b < 4; ++b)
      if (a + b < 6) pts.push_back(0.12 + 0.25 * a + j(jr)), pts.push_back(0.12 + 0.25 * b + j(jr));
  ex.T = std::make_unique<dt::Triangulation>();
  ex.S.clear();
  for (std::size_t i = 0; i < pts.size() / 2; ++i) ex.S.push_back(ex.T->addVertex(pts[2 * i], pts[2 * i + 1], long(i + 1)));
  dt::delaunayTrglHull(*ex.T, ex.S, dt::StartRule::LastCavity);
  const dt::PlainMesh m = dt::extractMesh(*ex.T, false);
  ex.dtnSegs = ch::triangleSegs(m.xy, m.tri);
}

// The smallest angle of a triangle, degrees.
double minAngleDeg(const dt::Face* f) {
  double m = 180;
  for (int k = 0; k < 3; ++k) {
    const dt::Vertex *a = f->V[k], *b = f->V[(k + 1) % 3], *c = f->V[(k + 2) % 3];
    const double u = std::atan2(std::fabs((b->x - a->x) * (c->y - a->y) - (b->y - a->y) * (c->x - a->x)),
                                (b->x - a->x) * (c->x - a->x) + (b->y - a->y) * (c->y - a->y));
    m = std::min(m, u * 180 / M_PI);
  }
  return m;
}

// The example, chosen by score (deterministic): the jitter seeds 2201..2300, and for each 3000
// random candidates for p_{n+1} inside the hull and four in each triangle. What it must show, as numbers:
// - Figure 2.3: a proof chain (the cavity triangles met by the segment from a cavity vertex p3
//   to p_{n+1}) of the notes' shape p2p3p4 -> p2p4p5 -> p2p5p1 -> p1p5p6 (100), with the circles
//   C_I of p2p3p4 and C_J of p2p4p5 well apart: centres a quarter radius apart or more (40),
//   and 16 x their spread (at most 8);
// - Figure 2.1's focus rule: p_{n+1} at least 3.5 marker radii (px, as drawn) from every edge
//   of DT_n (50), more room counted up to 6 radii;
// - no cavity triangle with an angle under 15 degrees (30): a triangle drawn to be seen is
//   no sliver; every circle of Figure 2.1 (b) inside its view (20);
// - a cavity of about 6 triangles (minus the difference).
KernelExample kernelExample() {
  KernelExample ex;
  const double rp = ch::pointRadius(ch::figureSize("fig2_1"), 1.6);  // p_{n+1}'s marker, px
  double bestX = 0, bestY = 0, bestScore = -1e9, bestMargin = 0;
  unsigned bestSeed = 0;
  for (unsigned seed = 2201; seed < 2301; ++seed) {
    jitteredGrid(seed, ex);
    const ch::Panel pa = figure21Panel(ex.S, 0);
    // The candidates: 3000 random points, then each triangle's incentre and three points a
    // quarter of the way from it to the corners (where a point has the most room).
    std::vector<std::pair<double, double>> cand;
    std::mt19937_64 rng(2102);
    std::uniform_real_distribution<double> u(0.15, 0.85);
    for (int c = 0; c < 3000; ++c) cand.push_back({u(rng), u(rng)});
    for (const dt::Face& f : ex.T->faces()) {
      if (f.isGhost()) continue;
      double w[3], sw = 0, ix = 0, iy = 0;
      for (int k = 0; k < 3; ++k) {
        const dt::Vertex *b = f.V[(k + 1) % 3], *c = f.V[(k + 2) % 3];
        sw += w[k] = std::hypot(b->x - c->x, b->y - c->y);
      }
      for (int k = 0; k < 3; ++k) ix += w[k] * f.V[k]->x / sw, iy += w[k] * f.V[k]->y / sw;
      cand.push_back({ix, iy});
      for (int k = 0; k < 3; ++k) cand.push_back({ix + 0.25 * (f.V[k]->x - ix), iy + 0.25 * (f.V[k]->y - iy)});
    }
    for (const auto& [cx, cy] : cand) {
      dt::Vertex p(cx, cy);
      std::vector<dt::Face*> C = dt::conflictFaces(*ex.T, &p);
      bool ghost = C.empty();
      for (const dt::Face* f : C) ghost = ghost || f->isGhost();
      if (ghost || C.size() > 8) continue;
      double margin = 1e300;  // px
      for (const ch::Seg& s : ex.dtnSegs) margin = std::min(margin, ch::segDistance(s, p.x, p.y) * pa.scale());
      double angle = 180;  // the cavity's smallest angle, degrees
      bool inView = true;  // every circle of Figure 2.1 (b) inside the view
      for (const dt::Face* f : C) {
        angle = std::min(angle, minAngleDeg(f));
        const Circle c = circumcircle(f->V[0], f->V[1], f->V[2]);
        inView = inView && c.x - c.r > pa.x0 && c.x + c.r < pa.x1 && c.y - c.r > pa.y0 && c.y + c.r < pa.y1;
      }
      const double room = (margin >= 3.2 * rp ? 50.0 : 0.0) + std::min(margin / rp, 6.0) + (angle >= 15 ? 30.0 : 0.0) +
                          (inView ? 20.0 : 0.0);
      if (room + 152 < bestScore) continue;  // the chain's terms add at most 152: no need to walk
      for (dt::Face* f : C)
        for (const dt::Vertex* a : f->V) {
          const std::vector<dt::Face*> ch = chainTo(f, a, &p, C);
          const double spread = ch.size() >= 2 ? std::min(widestStep({ch[0], ch[1]}).second, 0.5) : 0;
          const double score = (notesNames(ch).empty() ? 0.0 : 100.0) + room + (spread >= 0.25 ? 40.0 : 0.0) +
                               double(ch.size()) - std::fabs(double(C.size()) - 6) + 16 * spread;
          if (score > bestScore) bestScore = score, bestX = p.x, bestY = p.y, bestSeed = seed, bestMargin = margin;
        }
    }
  }
  jitteredGrid(bestSeed, ex);
  std::cout << "Figures 2.1-2.4: jitter seed " << bestSeed << ", score " << bestScore << "; p_{n+1} is "
            << ch::fmt("%.1f", bestMargin / rp) << " marker radii from every edge of DT_n (the focus rule: 3)\n";
  if (bestMargin < 3 * rp) std::cout << "Figures 2.1-2.4: no candidate keeps p_{n+1} 3 marker radii from the edges\n";
  ex.p = ex.T->addVertex(bestX, bestY, long(ex.S.size() + 1));
  ex.C = dt::conflictFaces(*ex.T, ex.p);
  const dt::CavityReport rep = dt::checkCavity({ex.C.begin(), ex.C.end()}, ex.p);
  std::cout << "Figures 2.1, 2.3, 2.4: n = " << ex.S.size() << ", p_{n+1} = (" << bestX << ", " << bestY
            << "), |C| = " << rep.faces << ", |bnd| = " << rep.boundaryEdges
            << ", Proposition 2.1.1 and Property 2.1.1 hold: " << (rep.ok ? "yes" : rep.error) << "\n";
  ex.sigma = boundaryCycle(ex.C);
  return ex;
}

// Figure 2.1: DT_n and p_{n+1}; the cavity with its circumcircles.
void figure21(const ch::Options& o, const KernelExample& ex) {
  const std::vector<dt::Vertex*>& S = ex.S;
  const dt::Vertex* p = ex.p;
  const std::vector<const dt::Vertex*>& sigma = ex.sigma;
  std::string ptsText, circles, cavity;
  for (const dt::Vertex* v : S) ptsText += num(v->x) + " " + num(v->y) + "\n";
  for (const dt::Face* f : ex.C) circles += circleLine(circumcircle(f->V[0], f->V[1], f->V[2]));
  for (std::size_t i = 0; i <= sigma.size(); ++i)
    cavity += num(sigma[i % sigma.size()]->x) + " " + num(sigma[i % sigma.size()]->y) + "\n";
  {
    // Both panels show one view, laid out here in pixels (fig2_1_view.gp), so the label of
    // p_{n+1} is placed once, clear of everything either panel draws: the edges, the cavity's
    // boundary and circles, the points; attached to p_{n+1} (no edge between them).
    const ch::FigureSize fs = ch::figureSize("fig2_1");
    const ch::Panel pa = figure21Panel(S, 0), pb = figure21Panel(S, 1);
    const double lw = std::max(1.5, fs.em / 18);
    // The label of (a), attached to p_{n+1} (no edge between them); (b), where the cavity's
    // circles crowd p_{n+1}, names it in its title and draws it in the same red, unlabelled.
    const std::string name = ch::mathText("p_{n+1}");
    ch::LabelPlacer placer(pa, fs.em);
    placer.segments(ex.dtnSegs, 1.5 * lw);
    for (const dt::Vertex* v : S) placer.marker(v->x, v->y, ch::pointRadius(fs, 1.0));
    placer.marker(p->x, p->y, ch::pointRadius(fs, 1.6));
    const auto [lx, ly] = placer.placeAttached(p->x, p->y, name, ex.dtnSegs, NAN, 3, 1.5);
    ch::writeOut(o, "fig2_1_p.dat", num(p->x) + " " + num(p->y) + " " + num(lx) + " " + num(ly) + " " + ch::quoted(name) + "\n");
    ch::writeOut(o, "fig2_1_view.gp", "P1 = \"" + pa.gnuplot() + "\"\nP2 = \"" + pb.gnuplot() + "\"\n");
  }
  ch::writeOut(o, "fig2_1_dtn.dat", ch::gnuplotSegs(ex.dtnSegs));
  ch::writeOut(o, "fig2_1_points.dat", ptsText);
  ch::writeOut(o, "fig2_1_cavity.dat", cavity);
  ch::writeOut(o, "fig2_1_circles.dat", circles);
  ch::runGnuplot(o, "fig2_1.gp");
}

// Figure 2.3: the proof of Proposition 2.1.1 in the notes' names.
void figure23(const ch::Options& o, const KernelExample& ex) {
  const std::vector<dt::Vertex*>& S = ex.S;
  const dt::Vertex* p = ex.p;
  const std::vector<dt::Face*>& C = ex.C;
  const std::vector<const dt::Vertex*>& sigma = ex.sigma;
  const std::vector<ch::Seg>& dtnSegs = ex.dtnSegs;
  // Figure 2.3, in the notes' names: the chain p2p3p4 -> p2p4p5 -> p2p5p1 -> p1p5p6 met by the
  // segment p3 p_{n+1}, and its first step: C_I (circle of p2p3p4) beyond p2p4 lies in C_J
  // (circle of p2p4p5).
  std::vector<dt::Face*> chain;
  const dt::Vertex* apex = nullptr;
  for (dt::Face* f : C)
    for (const dt::Vertex* a : f->V) {
      std::vector<dt::Face*> ch = chainTo(f, a, p, C);
      const bool named = !notesNames(ch).empty(), best = !notesNames(chain).empty();
      if ((named && !best) || (named == best && ch.size() > chain.size())) chain = ch, apex = a;
    }
  if (chain.size() < 2) throw std::runtime_error("Figure 2.3: no chain of two cavity triangles");
  const std::vector<const dt::Vertex*> names = notesNames(chain);
  if (names.size() != 7)  // the seeds are fixed: this only fails if the search above changes
    throw std::runtime_error("Figure 2.3: no chain of the notes' shape p2p3p4 -> p2p4p5 -> p2p5p1 -> p1p5p6");
  std::string chainText, nameText;
  for (const dt::Face* f : chain) chainText += triangleBlock(f);
  if (chainText.size() >= 2) chainText.resize(chainText.size() - 2);  // no empty last index
  // The view of (a): the cavity with a margin; label sizes follow it (650 px, em 28 px).
  double cx0 = 1e300, cx1 = -1e300, cy0 = 1e300, cy1 = -1e300;
  for (const dt::Vertex* v : sigma)
    cx0 = std::min(cx0, v->x), cx1 = std::max(cx1, v->x), cy0 = std::min(cy0, v->y), cy1 = std::max(cy1, v->y);
  const double cm = 0.12 * std::max(cx1 - cx0, cy1 - cy0);
  cx0 -= cm, cx1 += cm, cy0 -= cm, cy1 += cm;
  // Both panels are laid out here in pixels (fig2_3_view.gp: PA, PB), so that every label is
  // placed clear of everything its panel draws.
  const ch::FigureSize fs = ch::figureSize("fig2_3");
  const double lw = std::max(1.5, fs.em / 18);
  const ch::Panel pa = ch::cellPanel(fs, 1, 2, 0, cx0, cx1, cy0, cy1);
  ch::LabelPlacer placerA(pa, fs.em);
  placerA.segments(dtnSegs, 1.2 * lw);
  for (std::size_t i = 0; i < sigma.size(); ++i)
    placerA.segment(sigma[i]->x, sigma[i]->y, sigma[(i + 1) % sigma.size()]->x, sigma[(i + 1) % sigma.size()]->y, 3 * lw);
  placerA.segment(apex->x, apex->y, p->x, p->y, 2.5 * lw);
  for (const dt::Vertex* v : S) placerA.marker(v->x, v->y, ch::pointRadius(fs, 1.0));
  placerA.marker(p->x, p->y, ch::pointRadius(fs, 1.5));
  const auto [plx, ply] = placerA.place(p->x, p->y, ch::mathText("p_{n+1}"));
  for (std::size_t i = 1; i < names.size(); ++i) {
    const std::string name = ch::mathText("p_" + std::to_string(i));
    const auto [lx, ly] = placerA.place(names[i]->x, names[i]->y, name);
    nameText += num(lx) + " " + num(ly) + " " + ch::quoted(name) + "\n";
  }
  std::cout << "Figure 2.3: the segment from a cavity vertex to p_{n+1} crosses " << chain.size()
            << " cavity triangles; in the notes' shape p2p3p4 -> p2p4p5 -> p2p5p1 -> p1p5p6: "
            << (names.empty() ? "no" : "yes") << "\n";
  const dt::Face *d1 = chain[0], *d2 = chain[1];
  const Circle c1 = circumcircle(d1->V[0], d1->V[1], d1->V[2]);
  const Circle c2 = circumcircle(d2->V[0], d2->V[1], d2->V[2]);
  const int k = dt::neighbourIndex(d1, d2);
  const dt::Vertex *a = d1->V[k], *b = d1->V[(k + 1) % 3];
  // The step panel's view: both circles, with a margin; the line p2p4 is clipped to it.
  const double m = 0.06 * (std::max(c1.x + c1.r, c2.x + c2.r) - std::min(c1.x - c1.r, c2.x - c2.r));
  const double zx0 = std::min(c1.x - c1.r, c2.x - c2.r) - m, zx1 = std::max(c1.x + c1.r, c2.x + c2.r) + m;
  const double zy0 = std::min(c1.y - c1.r, c2.y - c2.r) - m, zy1 = std::max(c1.y + c1.r, c2.y + c2.r) + m;
  const ch::Panel pb = ch::cellPanel(fs, 1, 2, 1, zx0, zx1, zy0, zy1);
  ch::Seg line;
  ch::clipLine(a->x, a->y, b->x - a->x, b->y - a->y, pb.x0, pb.x1, pb.y0, pb.y1, line);
  std::string stepLabels;
  {
    ch::LabelPlacer placerB(pb, fs.em);
    placerB.segment(line.x0, line.y0, line.x1, line.y1, 1.5 * lw);
    placerB.segment(apex->x, apex->y, p->x, p->y, 2 * lw);
    for (const dt::Face* f : {d1, d2})
      for (int e = 0; e < 3; ++e) placerB.segment(f->V[e]->x, f->V[e]->y, f->V[(e + 1) % 3]->x, f->V[(e + 1) % 3]->y, 4 * lw);
    placerB.circle(c1.x, c1.y, c1.r, 2 * lw);
    placerB.circle(c2.x, c2.y, c2.r, 2 * lw);
    for (const dt::Face* f : {d1, d2})
      for (const dt::Vertex* v : f->V) placerB.marker(v->x, v->y, ch::pointRadius(fs, 1.0));
    placerB.marker(p->x, p->y, ch::pointRadius(fs, 1.5));
    for (std::size_t i = 2; i < 6; ++i) {  // p1 and p6 are not in the first step
      const std::string name = ch::mathText("p_" + std::to_string(i));
      const auto [lx, ly] = placerB.place(names[i]->x, names[i]->y, name);
      stepLabels += num(lx) + " " + num(ly) + " " + ch::quoted(name) + "\n";
    }
    const std::string pname = ch::mathText("p_{n+1}");
    const auto [zx, zy] = placerB.place(p->x, p->y, pname);
    stepLabels += num(zx) + " " + num(zy) + " " + ch::quoted(pname) + "\n";
    // A circle's label: beside its own circle, on the outside, where it is clearest; the
    // circle's point nearest the label must not be near the other circle.
    auto circleLabel = [&](const Circle& c, const Circle& other, const std::string& name) {
      double best = -1e300, bx = 0, by = 0;
      for (int t = 0; t < 72; ++t) {
        const double a = 2 * M_PI * t / 72, qx = c.x + c.r * std::cos(a), qy = c.y + c.r * std::sin(a);
        if (std::fabs(std::hypot(qx - other.x, qy - other.y) - other.r) < 0.25 * c.r) continue;
        const auto [lx, ly] = std::pair{qx, qy};
        // (the box as the placer's: 0.47 em above the anchor, 0.85 em below with a subscript)
        const double hw = 0.5 * ch::textWidthEm(name) * fs.em + 2, up = 0.5 * fs.em + 2, down = 0.9 * fs.em + 2;
        const double cx = pb.px(lx) + (hw + 0.4 * fs.em) * std::cos(a), cy = pb.py(ly) - (0.7 * fs.em + 0.4 * fs.em) * std::sin(a);
        const double cl = placerB.clearance({cx - hw, cy - up, cx + hw, cy + down});
        // The label nearer its own circle than the other one.
        const double ux = pb.x0 + (cx - pb.left) / pb.scale(), uy = pb.y1 - (cy - pb.top) / pb.scale();
        if (std::fabs(std::hypot(ux - c.x, uy - c.y) - c.r) >= std::fabs(std::hypot(ux - other.x, uy - other.y) - other.r)) continue;
        if (cl > best) best = cl, bx = cx, by = cy;
      }
      const double hw = 0.5 * ch::textWidthEm(name) * fs.em + 2, up = 0.5 * fs.em + 2, down = 0.9 * fs.em + 2;
      placerB.box({bx - hw, by - up, bx + hw, by + down});
      const double dx = pb.x0 + (bx - pb.left) / pb.scale(), dy = pb.y1 - (by - pb.top) / pb.scale();
      return num(dx) + " " + num(dy) + " " + ch::quoted(name) + "\n";
    };
    stepLabels = circleLabel(c1, c2, ch::mathText("C_I")) + circleLabel(c2, c1, ch::mathText("C_J")) + stepLabels;
  }
  std::cout << "Figure 2.3: circle centres of the first step " << std::hypot(c1.x - c2.x, c1.y - c2.y) / std::max(c1.r, c2.r)
            << " radii apart\n";
  // The cap of C_I beyond p2p4: d1 = (a, b, c) is counter-clockwise on its circle, so the arc
  // from a to b counter-clockwise (without c) is the one right of a->b, on p's side.
  std::string capText;
  const double ta = std::atan2(a->y - c1.y, a->x - c1.x);
  double tb = std::atan2(b->y - c1.y, b->x - c1.x);
  while (tb <= ta) tb += 2 * M_PI;
  for (int s = 0; s <= 200; ++s) {
    const double t = ta + (tb - ta) * s / 200;
    capText += num(c1.x + c1.r * std::cos(t)) + " " + num(c1.y + c1.r * std::sin(t)) + "\n";
  }
  capText += num(a->x) + " " + num(a->y) + "\n";
  ch::writeOut(o, "fig2_3_chain.dat", chainText);
  ch::writeOut(o, "fig2_3_names.dat", nameText);
  ch::writeOut(o, "fig2_3_segment.dat", num(apex->x) + " " + num(apex->y) + "\n" + num(p->x) + " " +
                                           num(p->y) + "\n");
  ch::writeOut(o, "fig2_3_plabel.dat", num(plx) + " " + num(ply) + " " + ch::quoted(ch::mathText("p_{n+1}")) + "\n");
  ch::writeOut(o, "fig2_3_circles.dat", circleLine(c1) + circleLine(c2));
  ch::writeOut(o, "fig2_3_edge.dat", num(a->x) + " " + num(a->y) + "\n" + num(b->x) + " " + num(b->y) +
                                        "\n\n\n" + ch::gnuplotSegs({line}));
  ch::writeOut(o, "fig2_3_cap.dat", capText);
  ch::writeOut(o, "fig2_3_steptri.dat", triangleBlock(d1) + triangleBlock(d2));
  ch::writeOut(o, "fig2_3_steplabels.dat", stepLabels);
  ch::writeOut(o, "fig2_3_view.gp", "PA = \"" + pa.gnuplot() + "\"\nPB = \"" + pb.gnuplot() + "\"\n");
  ch::runGnuplot(o, "fig2_3.gp");
}

// Figure 2.4: the Delaunay ball, an outside triangle and a new one with their circles. Inserts
// p_{n+1} into the example's triangulation (so it comes last).
void figure24(const ch::Options& o, KernelExample& ex) {
  dt::Triangulation& T = *ex.T;
  const std::vector<dt::Vertex*>& S = ex.S;
  dt::Vertex* p = ex.p;
  const std::vector<dt::Face*>& C = ex.C;
  const std::vector<const dt::Vertex*>& sigma = ex.sigma;
  // Figure 2.4: insert p, then pick the boundary edge sigma_i sigma_{i+1} whose outside triangle
  // and new triangle have the smallest circles (so both fit in the picture).
  std::map<std::pair<const dt::Vertex*, const dt::Vertex*>, const dt::Face*> outsideOf;
  for (const dt::Face* f : C)
    for (int k = 0; k < 3; ++k)
      if (f->F[k] && !contains(C, f->F[k]) && !f->F[k]->isGhost())
        outsideOf[{f->V[k], f->V[(k + 1) % 3]}] = f->F[k];
  dt::InsertionStats st;
  dt::InsertionScratch scratch;
  dt::insertVertex(T, C[0], p, st, scratch);
  const dt::CheckReport after = dt::checkTriangulation(T);
  std::cout << "Figure 2.4: the ball has " << (st.cavityFaces + 2) << " triangles for |C| = "
            << st.cavityFaces << "; DT_{n+1} is Delaunay (exact check): " << (after.ok ? "yes" : after.error) << "\n";
  std::size_t best = 0;
  double bestR = 1e300;
  for (std::size_t i = 0; i < sigma.size(); ++i) {
    auto it = outsideOf.find({sigma[i], sigma[(i + 1) % sigma.size()]});
    if (it == outsideOf.end()) continue;
    const dt::Face* t = it->second;
    const double r = std::max(circumcircle(t->V[0], t->V[1], t->V[2]).r,
                              circumcircle(sigma[i], sigma[(i + 1) % sigma.size()], p).r);
    if (r < bestR) bestR = r, best = i;
  }
  const dt::Vertex *si = sigma[best], *si1 = sigma[(best + 1) % sigma.size()];
  const dt::Face* out = outsideOf.at({si, si1});
  const dt::Vertex* pj = nullptr;
  for (const dt::Vertex* v : out->V)
    if (v != si && v != si1) pj = v;
  const dt::PlainMesh afterMesh = dt::extractMesh(T, false);
  const std::vector<ch::Seg> afterSegs = ch::triangleSegs(afterMesh.xy, afterMesh.tri);
  const Circle cOut = circumcircle(si, si1, pj), cNew = circumcircle(si, si1, p);
  // The view: the points and both circles, with a margin.
  double vx0 = std::min(cOut.x - cOut.r, cNew.x - cNew.r), vx1 = std::max(cOut.x + cOut.r, cNew.x + cNew.r);
  double vy0 = std::min(cOut.y - cOut.r, cNew.y - cNew.r), vy1 = std::max(cOut.y + cOut.r, cNew.y + cNew.r);
  for (std::size_t i = 0; i < afterMesh.xy.size(); i += 2) {
    vx0 = std::min(vx0, afterMesh.xy[i]), vx1 = std::max(vx1, afterMesh.xy[i]);
    vy0 = std::min(vy0, afterMesh.xy[i + 1]), vy1 = std::max(vy1, afterMesh.xy[i + 1]);
  }
  // The view, laid out in pixels (fig2_4_view.gp) so that the labels are placed clear of every
  // edge, circle, point and other label.
  const ch::FigureSize fs4 = ch::figureSize("fig2_4");
  const double lw4 = std::max(1.5, fs4.em / 18);
  const ch::Panel pv = ch::fitPanel(fs4.W, fs4.H, 0, 0, fs4.W, fs4.H, vx0, vx1, vy0, vy1, 0.4 * fs4.em);
  ch::LabelPlacer placer(pv, fs4.em);
  placer.segments(afterSegs, 1.5 * lw4);
  for (std::size_t i = 0; i < sigma.size(); ++i)
    placer.segment(sigma[i]->x, sigma[i]->y, sigma[(i + 1) % sigma.size()]->x, sigma[(i + 1) % sigma.size()]->y, 3 * lw4);
  for (const dt::Vertex* v : {si, si1, pj}) {
    const dt::Vertex* w = v == si ? si1 : v == si1 ? pj : si;
    placer.segment(v->x, v->y, w->x, w->y, 3 * lw4);
  }
  placer.circle(cOut.x, cOut.y, cOut.r, 2 * lw4);
  placer.circle(cNew.x, cNew.y, cNew.r, 2 * lw4);
  for (const dt::Vertex* v : S) placer.marker(v->x, v->y, ch::pointRadius(fs4, 1.0));
  placer.marker(p->x, p->y, ch::pointRadius(fs4, 1.6));
  std::string labels4, special;
  auto label = [&](const dt::Vertex* v, const std::string& tex) {
    const std::string name = ch::mathText(tex);
    const auto [lx, ly] = placer.placeAttached(v->x, v->y, name, afterSegs, NAN, 2);
    labels4 += num(lx) + " " + num(ly) + " " + ch::quoted(name) + "\n";
  };
  label(p, "p_{n+1}");
  label(si, "\\sigma_i");
  label(si1, "\\sigma_{i+1}");
  label(pj, "p_j");
  {
    // The ball's name, at the centroid of its largest triangle (or as near as is clear).
    double bestA = -1, gx = 0, gy = 0;
    for (std::size_t i = 0; i < sigma.size(); ++i) {
      const dt::Vertex *a = sigma[i], *b = sigma[(i + 1) % sigma.size()];
      const double area = std::fabs((a->x - p->x) * (b->y - p->y) - (a->y - p->y) * (b->x - p->x));
      if (area > bestA) bestA = area, gx = (a->x + b->x + p->x) / 3, gy = (a->y + b->y + p->y) / 3;
    }
    const std::string name = ch::mathText("\\mathscr{B}");
    const auto [lx, ly] = placer.place(gx, gy, name, NAN, 0.6 * fs4.em);  // well apart from p_{n+1}
    labels4 += num(lx) + " " + num(ly) + " " + ch::quoted(name) + "\n";
  }
  for (const dt::Vertex* v : {si, si1, pj, si}) special += num(v->x) + " " + num(v->y) + "\n";
  // sigma_{i+1} sigma_i p_j is the counter-clockwise order of the outside triangle.
  const bool pOut = dt::incircle(si1->x, si1->y, si->x, si->y, pj->x, pj->y, p->x, p->y) <= 0;
  const bool pjOut = dt::incircle(si->x, si->y, si1->x, si1->y, p->x, p->y, pj->x, pj->y) <= 0;
  std::cout << "Figure 2.4: p_{n+1} outside the circle of σ_i σ_{i+1} p_j: " << pOut
            << "; p_j outside the circle of σ_i σ_{i+1} p_{n+1}: " << pjOut << "\n";
  ch::writeOut(o, "fig2_4_dt.dat", ch::gnuplotSegs(afterSegs));
  ch::writeOut(o, "fig2_4_labels.dat", labels4);
  ch::writeOut(o, "fig2_4_outside.dat", special);
  ch::writeOut(o, "fig2_4_newtri.dat", num(si->x) + " " + num(si->y) + "\n" + num(si1->x) + " " + num(si1->y) + "\n" +
                                          num(p->x) + " " + num(p->y) + "\n" + num(si->x) + " " + num(si->y) + "\n");
  ch::writeOut(o, "fig2_4_circles.dat", circleLine(cOut) + circleLine(cNew));
  ch::writeOut(o, "fig2_4_view.gp", "VIEW = \"" + pv.gnuplot() + "\"\n");
  ch::runGnuplot(o, "fig2_4.gp");
}

// ---- table_kernel_checks: Proposition 2.1.1 and Property 2.1.1 at every insertion ----------

void kernelChecks(const ch::Options& o) {
  const std::size_t n = o.maxN > 0 ? std::size_t(o.maxN) : (o.quick ? 1000 : 5000);
  struct Input {
    std::string name;
    XY p;
  };
  std::vector<Input> inputs;
  inputs.push_back({"uniform random", dt::uniformPoints(n, 2111)});
  const int side = int(std::sqrt(double(n)));
  XY grid = dt::gridPoints(side, side);
  dt::shufflePoints(grid, 2112);  // a random insertion order of a grid
  inputs.push_back({"grid " + std::to_string(side) + "x" + std::to_string(side) + ", shuffled", grid});
  // stride 7919 (prime): the points in a scattered order
  inputs.push_back({"circle (rounded cos, sin)", dt::circlePoints(std::min<std::size_t>(n, 2000), 1, 7919)});
  ch::Table tab;
  tab.caption = "Proposition 2.1.1 and Property 2.1.1, checked exactly (checkCavity) at every "
                "insertion into the two super-triangles; the cavity is computed by testing every "
                "triangle";
  tab.header = {"input", "insertions", "mean cavity size", "max cavity size",
                "mean boundary edges", "all checks pass", "DT(S ∪ S0) Delaunay"};
  for (const Input& in : inputs) {
    const std::size_t m = in.p.size() / 2;
    double x0 = in.p[0], x1 = x0, y0 = in.p[1], y1 = y0;
    for (std::size_t i = 0; i < m; ++i) {
      x0 = std::min(x0, in.p[2 * i]), x1 = std::max(x1, in.p[2 * i]);
      y0 = std::min(y0, in.p[2 * i + 1]), y1 = std::max(y1, in.p[2 * i + 1]);
    }
    dt::Triangulation T;
    dt::initSuperTriangles(T, x0, y0, x1, y1);
    dt::InsertionStats st;
    dt::InsertionScratch scratch;
    dt::Face* start = &T.faces().front();
    std::size_t bad = 0, maxC = 0, sumB = 0, sumC = 0;
    ch::Progress prog("checking " + in.name, m);
    for (std::size_t i = 0; i < m; ++i) {
      dt::Vertex* v = T.addVertex(in.p[2 * i], in.p[2 * i + 1], long(i));
      const std::vector<dt::Face*> C = dt::conflictFaces(T, v);
      const dt::CavityReport r = dt::checkCavity({C.begin(), C.end()}, v);
      bad += !r.ok;
      maxC = std::max(maxC, C.size());
      sumB += r.boundaryEdges;
      sumC += C.size();
      dt::Face* b = dt::insertVertex(T, start, v, st, scratch);
      if (b) start = b;
      prog.update(i + 1);
    }
    const bool ok = dt::checkTriangulation(T).ok;
    tab.add({in.name, std::to_string(m), ch::fmt("%.3f", double(sumC) / double(m)),
             std::to_string(maxC), ch::fmt("%.3f", double(sumB) / double(m)),
             bad == 0 ? "yes" : ch::fmt("no (%zu failures)", bad), ok ? "yes" : "no"});
  }
  tab.emit(o, "table_kernel_checks");
}

}  // namespace

int main(int argc, char** argv) {
  const ch::Program p{"sec2_1_kernel", "Section 2.1: Figures 2.1-2.4 and the kernel checks.", 100,
                      10000000, {"fig2_1", "fig2_2", "fig2_3", "fig2_4"}, {}};
  return ch::runMain(argc, argv, p, [](const ch::Options& o) {
    if (o.wants("fig2_2")) figure22(o);
    if (o.wants("fig2_1") || o.wants("fig2_3") || o.wants("fig2_4")) {
      KernelExample ex = kernelExample();
      if (o.wants("fig2_1")) figure21(o, ex);
      if (o.wants("fig2_3")) figure23(o, ex);
      if (o.wants("fig2_4")) figure24(o, ex);
    }
    if (o.everything()) kernelChecks(o);
  });
}
