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
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "check.h"
#include "common.h"
#include "generators.h"
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

// The proof's chain: the faces met by the segment from the centroid q of `from` to p, found by
// a straight walk with exact orientation tests. Empty if the segment passes through a vertex
// (then another configuration is chosen) or leaves the cavity (Proposition 2.1.1 forbids it).
std::vector<dt::Face*> chainTo(dt::Face* from, const dt::Vertex* p, const std::vector<dt::Face*>& C) {
  const dt::Vertex q = from->centroid();
  std::vector<dt::Face*> chain = {from};
  dt::Face* f = from;
  for (int step = 0; step < 200; ++step) {
    bool inside = true;
    for (int k = 0; k < 3; ++k) inside = inside && dt::orientationTest(f->V[k], f->V[(k + 1) % 3], p) >= 0;
    if (inside) return chain;
    int next = -1;
    for (int k = 0; k < 3 && next < 0; ++k) {
      const dt::Vertex *a = f->V[k], *b = f->V[(k + 1) % 3];
      const int oa = dt::orientationTest(&q, p, a), ob = dt::orientationTest(&q, p, b);
      if (oa == 0 || ob == 0) return {};
      if (dt::orientationTest(a, b, p) < 0 && oa != ob) next = k;
    }
    if (next < 0 || f->F[next] == nullptr || !contains(C, f->F[next])) return {};
    f = f->F[next];
    chain.push_back(f);
  }
  return {};
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
  x.x += 0.3 * (K[0].x - x.x);  // a kernel point off the centre, so the sight lines fan
  x.y += 0.3 * (K[0].y - x.y);
  std::size_t seen = 0;
  for (std::size_t j = 0; j < P.size(); ++j) seen += dt::seesCorner(P, x, j);
  std::cout << "Figure 2.2: polygon of " << P.size() << " corners, kernel of " << K.size()
            << " corners; the kernel point sees " << seen << "/" << P.size()
            << " corners (exact test); in the open kernel: " << dt::inOpenKernel(P, x) << "\n";
  std::string poly, ker, sight, lines, labels;
  for (std::size_t i = 0; i <= P.size(); ++i)
    poly += num(P[i % P.size()].x) + " " + num(P[i % P.size()].y) + "\n";
  for (std::size_t i = 0; i <= K.size(); ++i)
    ker += num(K[i % K.size()].x) + " " + num(K[i % K.size()].y) + "\n";
  for (std::size_t j = 0; j < P.size(); ++j) {
    sight += num(x.x) + " " + num(x.y) + "\n" + num(P[j].x) + " " + num(P[j].y) + "\n\n";
    // Corner labels, pushed outwards from the kernel point.
    const double dx = P[j].x - x.x, dy = P[j].y - x.y, d = std::hypot(dx, dy);
    labels += num(P[j].x + 0.1 * dx / d) + " " + num(P[j].y + 0.1 * dy / d) + " σ_{" +
              std::to_string(j + 1) + "}\n";
    // The line of each edge, long enough to cross the picture: its half-plane's border.
    const dt::Point2 a = P[j], b = P[(j + 1) % P.size()];
    const double ex = b.x - a.x, ey = b.y - a.y, e = std::hypot(ex, ey);
    lines += num(a.x - 3 * ex / e) + " " + num(a.y - 3 * ey / e) + "\n" + num(b.x + 3 * ex / e) +
             " " + num(b.y + 3 * ey / e) + "\n\n";
  }
  ch::writeOut(o, "fig2_2_polygon.dat", poly);
  ch::writeOut(o, "fig2_2_kernel.dat", ker);
  ch::writeOut(o, "fig2_2_sight.dat", sight);
  ch::writeOut(o, "fig2_2_lines.dat", lines);
  ch::writeOut(o, "fig2_2_labels.dat", labels);
  ch::writeOut(o, "fig2_2_x.dat", num(x.x) + " " + num(x.y) + "\n");
  ch::runGnuplot(o, "fig2_2.gp");
}

// ---- Figures 2.1, 2.3, 2.4: one point set, one new point ----------------------------------

void figures21to24(const ch::Options& o) {
  // 15 points: a 4 x 4 grid without one corner, jittered (fixed seed), so that DT_n has
  // triangles of reasonable shapes.
  const std::size_t n = 15;
  XY pts;
  {
    std::mt19937_64 jr(2101);
    std::uniform_real_distribution<double> j(-0.11, 0.11);
    for (int a = 0; a < 4; ++a)
      for (int b = 0; b < 4; ++b)
        if (a + b < 6) pts.push_back(0.12 + 0.25 * a + j(jr)), pts.push_back(0.12 + 0.25 * b + j(jr));
  }
  dt::Triangulation T;
  std::vector<dt::Vertex*> S;
  for (std::size_t i = 0; i < n; ++i) S.push_back(T.addVertex(pts[2 * i], pts[2 * i + 1], long(i + 1)));
  dt::delaunayTrglHull(T, S, dt::StartRule::LastCavity);
  // p_{n+1}: among 3000 random candidates inside the hull, the one whose proof chain is longest
  // (then whose cavity has 5 to 7 triangles), so that Figure 2.3 shows more than one step.
  std::mt19937_64 rng(2102);
  std::uniform_real_distribution<double> u(0.25, 0.75);
  double bestX = 0, bestY = 0, bestScore = -1e9;
  for (int c = 0; c < 3000; ++c) {
    dt::Vertex p(u(rng), u(rng));
    std::vector<dt::Face*> C = dt::conflictFaces(T, &p);
    bool ghost = C.empty();
    for (const dt::Face* f : C) ghost = ghost || f->isGhost();
    if (ghost || C.size() > 7) continue;
    std::vector<dt::Face*> longest;
    for (dt::Face* f : C) {
      std::vector<dt::Face*> ch = chainTo(f, &p, C);
      if (ch.size() > longest.size()) longest = ch;
    }
    const double spread = std::min(widestStep(longest).second, 0.5);
    const double score = 10.0 * double(longest.size()) - std::fabs(double(C.size()) - 6) + 16 * spread;
    if (score > bestScore) bestScore = score, bestX = p.x, bestY = p.y;
  }
  dt::Vertex* p = T.addVertex(bestX, bestY, long(n + 1));
  std::vector<dt::Face*> C = dt::conflictFaces(T, p);
  const dt::CavityReport rep = dt::checkCavity({C.begin(), C.end()}, p);
  std::cout << "Figures 2.1, 2.3, 2.4: n = " << n << ", p_{n+1} = (" << bestX << ", " << bestY
            << "), |C| = " << rep.faces << ", |bnd| = " << rep.boundaryEdges
            << ", Proposition 2.1.1 and Property 2.1.1 hold: " << (rep.ok ? "yes" : rep.error) << "\n";
  const dt::PlainMesh before = dt::extractMesh(T, false);
  const std::vector<const dt::Vertex*> sigma = boundaryCycle(C);

  // Figure 2.1.
  std::string ptsText, circles, cavity;
  for (const dt::Vertex* v : S) ptsText += num(v->x) + " " + num(v->y) + "\n";
  for (const dt::Face* f : C) circles += circleLine(circumcircle(f->V[0], f->V[1], f->V[2]));
  for (std::size_t i = 0; i <= sigma.size(); ++i)
    cavity += num(sigma[i % sigma.size()]->x) + " " + num(sigma[i % sigma.size()]->y) + "\n";
  ch::writeOut(o, "fig2_1_dtn.dat", dt::gnuplotTriangles(before.xy, before.tri));
  ch::writeOut(o, "fig2_1_points.dat", ptsText);
  ch::writeOut(o, "fig2_1_p.dat", num(p->x) + " " + num(p->y) + "\n");
  ch::writeOut(o, "fig2_1_cavity.dat", cavity);
  ch::writeOut(o, "fig2_1_circles.dat", circles);
  ch::runGnuplot(o, "fig2_1.gp");

  // Figure 2.3: the longest chain, and its first step Δ_1 -> Δ_2 across the edge e_1.
  std::vector<dt::Face*> chain;
  for (dt::Face* f : C) {
    std::vector<dt::Face*> ch = chainTo(f, p, C);
    if (ch.size() > chain.size()) chain = ch;
  }
  std::string chainText, chainLabels;
  for (std::size_t i = 0; i < chain.size(); ++i) {
    chainText += triangleBlock(chain[i]);
    const dt::Vertex g = chain[i]->centroid();
    chainLabels += num(g.x) + " " + num(g.y) + " Δ_{" + std::to_string(i + 1) + "}\n";
  }
  if (chainText.size() >= 2) chainText.resize(chainText.size() - 2);  // no empty last index
  const dt::Vertex q = chain[0]->centroid();
  std::cout << "Figure 2.3: the segment from Δ_1 to p_{n+1} crosses " << chain.size()
            << " cavity triangles\n";
  std::string stepText, capText, edgeText;
  std::string stepTri, stepLabels;
  if (chain.size() >= 2) {
    const std::size_t s = widestStep(chain).first;
    const dt::Face *d1 = chain[s], *d2 = chain[s + 1];
    const Circle c1 = circumcircle(d1->V[0], d1->V[1], d1->V[2]);
    const Circle c2 = circumcircle(d2->V[0], d2->V[1], d2->V[2]);
    stepText = circleLine(c1) + circleLine(c2);
    stepTri = triangleBlock(d1) + triangleBlock(d2);
    const dt::Vertex g1 = d1->centroid(), g2 = d2->centroid();
    const int k = dt::neighbourIndex(d1, d2);
    const dt::Vertex *a = d1->V[k], *b = d1->V[(k + 1) % 3];
    const double d = 0.72;  // circle labels at the upper left of C_i, upper right of C_{i+1}
    stepLabels = num(g1.x) + " " + num(g1.y) + " Δ_i\n" + num(g2.x) + " " + num(g2.y) +
                 " Δ_{i+1}\n" + num(c1.x - d * c1.r) + " " + num(c1.y + d * c1.r) + " C_i\n" +
                 num(c2.x + d * c2.r) + " " + num(c2.y + d * c2.r) + " C_{i+1}\n" +
                 num(0.5 * (a->x + b->x)) + " " + num(0.5 * (a->y + b->y)) + " e_i\n";
    std::cout << "Figure 2.3: step " << s + 1 << " -> " << s + 2 << ", circle centres "
              << std::hypot(c1.x - c2.x, c1.y - c2.y) / std::max(c1.r, c2.r)
              << " radii apart\n";
    edgeText = num(a->x) + " " + num(a->y) + "\n" + num(b->x) + " " + num(b->y) + "\n\n\n";
    const double ex = b->x - a->x, ey = b->y - a->y, e = std::hypot(ex, ey);
    const double L = 4 * std::max(c1.r, c2.r);
    edgeText += num(a->x - L * ex / e) + " " + num(a->y - L * ey / e) + "\n" +
                num(b->x + L * ex / e) + " " + num(b->y + L * ey / e) + "\n";
    // The cap of C_1 beyond e_1: Δ_1 = (a, b, c) is counter-clockwise on its circle, so the
    // arc from a to b counter-clockwise (without c) is the one right of a->b, on p's side.
    const double ta = std::atan2(a->y - c1.y, a->x - c1.x);
    double tb = std::atan2(b->y - c1.y, b->x - c1.x);
    while (tb <= ta) tb += 2 * M_PI;
    for (int s = 0; s <= 200; ++s) {
      const double t = ta + (tb - ta) * s / 200;
      capText += num(c1.x + c1.r * std::cos(t)) + " " + num(c1.y + c1.r * std::sin(t)) + "\n";
    }
    capText += num(a->x) + " " + num(a->y) + "\n";
  }
  ch::writeOut(o, "fig2_3_chain.dat", chainText);
  ch::writeOut(o, "fig2_3_labels.dat", chainLabels);
  ch::writeOut(o, "fig2_3_segment.dat", num(q.x) + " " + num(q.y) + "\n" + num(p->x) + " " + num(p->y) + "\n");
  ch::writeOut(o, "fig2_3_circles.dat", stepText);
  ch::writeOut(o, "fig2_3_edge.dat", edgeText);
  ch::writeOut(o, "fig2_3_cap.dat", capText);
  ch::writeOut(o, "fig2_3_steptri.dat", stepTri);
  ch::writeOut(o, "fig2_3_steplabels.dat", stepLabels);
  ch::runGnuplot(o, "fig2_3.gp");

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
  std::string sigmaText, special;
  for (std::size_t i = 0; i < sigma.size(); ++i) {
    // Labels sigma_1.. counted from sigma_i = the chosen edge's start, pushed away from p.
    const std::size_t j = (i + sigma.size() - best) % sigma.size();
    const double dx = sigma[i]->x - p->x, dy = sigma[i]->y - p->y, d = std::hypot(dx, dy);
    const std::string name = j == 0 ? "σ_i" : (j == 1 ? "σ_{i+1}" : "");
    sigmaText += num(sigma[i]->x + 0.05 * dx / d) + " " + num(sigma[i]->y + 0.05 * dy / d) +
                 " \"" + name + "\"\n";
  }
  for (const dt::Vertex* v : {si, si1, pj, si}) special += num(v->x) + " " + num(v->y) + "\n";
  // sigma_{i+1} sigma_i p_j is the counter-clockwise order of the outside triangle.
  const bool pOut = dt::incircle(si1->x, si1->y, si->x, si->y, pj->x, pj->y, p->x, p->y) <= 0;
  const bool pjOut = dt::incircle(si->x, si->y, si1->x, si1->y, p->x, p->y, pj->x, pj->y) <= 0;
  std::cout << "Figure 2.4: p_{n+1} outside the circle of σ_i σ_{i+1} p_j: " << pOut
            << "; p_j outside the circle of σ_i σ_{i+1} p_{n+1}: " << pjOut << "\n";
  ch::writeOut(o, "fig2_4_dt.dat", dt::gnuplotTriangles(afterMesh.xy, afterMesh.tri));
  ch::writeOut(o, "fig2_4_sigma.dat", sigmaText);
  ch::writeOut(o, "fig2_4_outside.dat", special);
  ch::writeOut(o, "fig2_4_circles.dat",
               circleLine(circumcircle(si, si1, pj)) + circleLine(circumcircle(si, si1, p)));
  {
    const dt::Vertex g = out->centroid();
    const double dx = pj->x - g.x, dy = pj->y - g.y, d = std::hypot(dx, dy);
    ch::writeOut(o, "fig2_4_pj.dat", num(pj->x + 0.045 * dx / d) + " " + num(pj->y + 0.045 * dy / d) + "\n");
  }
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
  return ch::runMain(argc, argv, "sec2_1_kernel", [](const ch::Options& o) {
    figure22(o);
    figures21to24(o);
    kernelChecks(o);
  });
}
