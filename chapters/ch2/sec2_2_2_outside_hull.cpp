// Section 2.2.2 (TODO in the notes): inserting a point outside the current convex hull.
//
// Writes into --out (default build/output/ch2):
//   fig_outside_hull.{png,svg}  before: the hull edges the new point sees and the Delaunay
//                               cavity (ghost faces of the visible edges + finite faces);
//                               after: the new triangles; third panel: a point on the line of
//                               a hull edge (that edge is not seen: no flat triangle)
//   table_outside_hull.*        how often a point falls outside the current hull, and what
//                               its insertion costs, by family and insertion order
#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>

#include "check.h"
#include "common.h"
#include "generators.h"
#include "hilbert.h"
#include "hull.h"
#include "figure_data.h"
#include "predicates.h"
#include "triangulate.h"

namespace {

using dt::XY;

std::string polygon(int& id, const dt::Face* f, const char* color) {
  std::ostringstream s;
  s.precision(17);
  s << "set object " << ++id << " polygon from ";
  for (int i = 0; i <= 3; ++i) s << (i ? " to " : "") << f->V[i % 3]->x << "," << f->V[i % 3]->y;
  s << " fc rgb \"" << color << "\" fs solid 1.0 noborder behind\n";
  return s.str();
}

std::string segment(const dt::Vertex* a, const dt::Vertex* b, const char* color, double lw) {
  std::ostringstream s;
  s.precision(17);
  s << "set arrow from " << a->x << "," << a->y << " to " << b->x << "," << b->y
    << " nohead lc rgb \"" << color << "\" lw " << lw << " front\n";
  return s.str();
}

// One panel pair: DT of `base`, then q inserted. Writes <stem>_{before,after}.{gp,dat}.
// `line` (x0 y0 x1 y1, or empty): a line the caption names, through (x0, y0) and (x1, y1),
// drawn dotted across both panels' view (the style's construction lines).
void panels(const ch::Options& o, const std::string& stem, int row, const XY& base, double qx, double qy,
            const std::string& note, const std::vector<double>& line = {}) {
  dt::Triangulation T;
  std::vector<dt::Vertex*> S;
  for (std::size_t i = 0; i < base.size() / 2; ++i)
    S.push_back(T.addVertex(base[2 * i], base[2 * i + 1], long(i)));
  dt::delaunayTrglHull(T, S, dt::StartRule::LastCavity);
  dt::Vertex* q = T.addVertex(qx, qy, long(S.size()));
  // Before: the visible hull edges and the finite faces of the cavity (the style's conflict and
  // cavity colours).
  const auto vis = dt::visibleHullEdges(T, q);
  std::string obj, lineObj;
  int id = 0;
  std::size_t cavityFinite = 0;
  for (const dt::Face* f : T.finiteFaces())
    if (f->inCircle(q)) obj += polygon(id, f, "#f0a830"), ++cavityFinite;
  for (const auto& e : vis) obj += segment(e.a, e.b, "#c51b7d", 4);
  for (const auto& e : vis) {  // the ghost faces in conflict: the rays from the edge ends away
    obj += "set arrow from " + ch::fmt("%.17g,%.17g", e.a->x, e.a->y) + " to " +
           ch::fmt("%.17g,%.17g", q->x, q->y) + " nohead lc rgb \"#c51b7d\" lw 1.5 dt 2 front\n";
    obj += "set arrow from " + ch::fmt("%.17g,%.17g", e.b->x, e.b->y) + " to " +
           ch::fmt("%.17g,%.17g", q->x, q->y) + " nohead lc rgb \"#c51b7d\" lw 1.5 dt 2 front\n";
  }
  auto plural = [](std::size_t k, const char* w) {
    return std::to_string(k) + " " + w + (k == 1 ? "" : "s");
  };
  obj += "ftitle = \"" + note + plural(vis.size(), "visible edge") + ", " + plural(cavityFinite, "triangle") +
         " in " + ch::mathText("\\mathscr{C}") + "\"\n";
  // The row's two panels, laid out in pixels (VIEW), share one view: the after mesh contains q.
  double x0 = q->x, x1 = q->x, y0 = q->y, y1 = q->y;
  for (const dt::Vertex* v : S) x0 = std::min(x0, v->x), x1 = std::max(x1, v->x), y0 = std::min(y0, v->y), y1 = std::max(y1, v->y);
  const double m = 0.06 * std::max(x1 - x0, y1 - y0);
  const ch::FigureSize fs = ch::figureSize("fig_outside_hull");
  const double lw = std::max(1.5, fs.em / 18);
  const ch::Panel pBefore = ch::cellPanel(fs, 2, 2, 2 * row, x0 - m, x1 + m, y0 - m, y1 + m),
                  pAfter = ch::cellPanel(fs, 2, 2, 2 * row + 1, x0 - m, x1 + m, y0 - m, y1 + m);
  // The label of q keeps one place in both panels: placed once, clear of what either draws.
  ch::LabelPlacer placer(pBefore, fs.em);
  const std::vector<ch::Seg> beforeSegs = ch::faceSegs(T.finiteFaces());
  placer.segments(beforeSegs, 1.2 * lw);
  for (const auto& e : vis) {
    placer.segment(e.a->x, e.a->y, e.b->x, e.b->y, 4 * lw);
    placer.segment(e.a->x, e.a->y, q->x, q->y, 1.5 * lw);
    placer.segment(e.b->x, e.b->y, q->x, q->y, 1.5 * lw);
  }
  for (const dt::Vertex* v : S) placer.marker(v->x, v->y, ch::pointRadius(fs, 0.8));
  placer.marker(q->x, q->y, ch::pointRadius(fs, 1.6));
  ch::Seg across{};
  if (line.size() == 4 && ch::clipLine(line[0], line[1], line[2] - line[0], line[3] - line[1], x0 - m, x1 + m, y0 - m, y1 + m, across)) {
    lineObj = "set arrow from " + ch::fmt("%.17g,%.17g", across.x0, across.y0) + " to " +
              ch::fmt("%.17g,%.17g", across.x1, across.y1) + " nohead lc rgb \"#8c8c8c\" lw 1.5 dt 3 back\n";
    obj += lineObj;
    placer.segment(across.x0, across.y0, across.x1, across.y1, 1.5 * lw);
  }
  obj += "VIEW = \"" + pBefore.gnuplot() + "\"\n";
  ch::writeOut(o, stem + "_before.gp", obj);
  ch::writeOut(o, stem + "_before.dat", ch::gnuplotSegs(beforeSegs));
  // After: insertVertex (the Delaunay kernel with ghost faces), new triangles in blue.
  dt::InsertionStats st;
  dt::InsertionScratch scratch;
  dt::insertVertex(T, dt::anyGhost(T), q, st, scratch);
  const dt::CheckReport r = dt::checkTriangulation(T);
  if (!r.ok) throw std::logic_error("outside-hull figure: " + r.error);
  obj = lineObj;
  id = 0;
  std::size_t fresh = 0;
  for (const dt::Face* f : T.finiteFaces())
    if (f->V[0] == q || f->V[1] == q || f->V[2] == q) obj += polygon(id, f, "#e5f5d5"), ++fresh;
  obj += "ftitle = \"after: " + plural(fresh, "new triangle") + "\"\n";
  const std::vector<ch::Seg> afterSegs = ch::faceSegs(T.finiteFaces());
  placer.segments(afterSegs, 1.2 * lw);
  // Beside p, on its side of every edge of both panels (and of the lines to the visible edges).
  std::vector<ch::Seg> sides = afterSegs;
  sides.insert(sides.end(), beforeSegs.begin(), beforeSegs.end());
  const auto [lx, ly] = placer.placeAttached(q->x, q->y, ch::mathText("p"), sides);
  ch::writeOut(o, stem + "_label.dat", ch::fmt("%.17g %.17g\n", lx, ly));
  obj += "VIEW = \"" + pAfter.gnuplot() + "\"\n";
  ch::writeOut(o, stem + "_after.gp", obj);
  ch::writeOut(o, stem + "_after.dat", ch::gnuplotSegs(afterSegs));
  std::ostringstream pts;
  for (const dt::Vertex* v : S) pts << v->x << " " << v->y << "\n";
  ch::writeOut(o, stem + "_points.dat", pts.str());
  ch::writeOut(o, stem + "_q.dat", ch::fmt("%.17g %.17g\n", q->x, q->y));
  std::cout << stem << ": " << vis.size() << " visible edges, " << cavityFinite
            << " finite cavity faces, " << fresh << " new triangles, DT checked exactly\n";
}

void figure(const ch::Options& o) {
  XY base = dt::uniformDiskPoints(14, 222, 40);
  // Integer coordinates, so that the point on a supporting line below is exactly on it.
  for (double& c : base) c = std::round(c);
  dt::Triangulation T;
  std::vector<dt::Vertex*> S;
  for (std::size_t i = 0; i < base.size() / 2; ++i)
    S.push_back(T.addVertex(base[2 * i], base[2 * i + 1], long(i)));
  dt::delaunayTrglHull(T, S, dt::StartRule::LastCavity);
  const auto H = dt::hullEdges(T);
  // The longest hull edge.
  std::size_t best = 0;
  double len = 0;
  for (std::size_t i = 0; i < H.size(); ++i) {
    const double l = std::hypot(H[i].b->x - H[i].a->x, H[i].b->y - H[i].a->y);
    if (l > len) len = l, best = i;
  }
  const auto& e = H[best];
  // Just outside the middle of the longest hull edge: a few finite faces join the cavity.
  const double mx = 0.5 * (e.a->x + e.b->x), my = 0.5 * (e.a->y + e.b->y);
  panels(o, "outhull", 0, base, mx + 0.12 * (e.b->y - e.a->y), my - 0.12 * (e.b->x - e.a->x), "");
  // Half-integers: q = b + (b - a) / 2 is computed exactly, so it is exactly on the line.
  const double qx = e.b->x + 0.5 * (e.b->x - e.a->x), qy = e.b->y + 0.5 * (e.b->y - e.a->y);
  dt::Vertex q(qx, qy);
  std::cout << "supporting-line point: orient = " << dt::orientationTest(e.a, e.b, &q)
            << " (0: exactly on the line of the hull edge)\n";
  panels(o, "outline", 1, base, qx, qy, "on a hull line: ", {e.a->x, e.a->y, e.b->x, e.b->y});
  ch::runGnuplot(o, "fig_outside_hull.gp");
}

void table(const ch::Options& o, ch::Values& v) {
  double visibleMax = 0;
  const std::size_t n = o.maxN ? std::size_t(o.maxN) : (o.quick ? 5000 : 50000);
  ch::Table t;
  t.caption = "Insertions outside the current hull (2.2.2), n = " + std::to_string(n) +
              " points: share of such insertions, hull edges seen, cavity sizes";
  t.header = {"family", "order", "outside the hull", "mean visible edges (outside)",
              "mean cavity, outside (ghosts incl.)", "mean cavity, all", "DT(S) exact"};
  for (const std::string fam : {"uniform square", "uniform disk", "circle"})
    for (const std::string order : {"random", "Hilbert", "lexicographic"}) {
      const std::size_t m = fam == "circle" ? std::min<std::size_t>(n, 3000) : n;
      const XY p = fam == "uniform square" ? dt::uniformPoints(m, 7)
                   : fam == "uniform disk" ? dt::uniformDiskPoints(m, 7)
                                           : dt::randomCirclePoints(m, 7);
      std::vector<std::size_t> idx(m);
      for (std::size_t i = 0; i < m; ++i) idx[i] = i;
      if (order == "Hilbert") idx = dt::hilbertOrder(p);
      if (order == "lexicographic")
        std::sort(idx.begin(), idx.end(), [&](std::size_t a, std::size_t b) {
          return p[2 * a] < p[2 * b] || (p[2 * a] == p[2 * b] && p[2 * a + 1] < p[2 * b + 1]);
        });
      dt::Triangulation T;
      std::vector<dt::Vertex*> S;
      for (std::size_t i : idx) S.push_back(T.addVertex(p[2 * i], p[2 * i + 1], long(i)));
      dt::delaunayTrglHull(T, {S[0], S[1], S[2]}, dt::StartRule::LastCavity);
      dt::InsertionStats st;
      dt::InsertionScratch scratch;
      std::uint64_t outside = 0, visible = 0, cavOut = 0, inserted = 0;
      dt::Face* last = dt::anyGhost(T);
      for (std::size_t i = 3; i < S.size(); ++i) {
        // Outside iff some ghost face is in conflict; count its visible edges by walking the
        // ghost ring (O(n_h) per point: fine for these sizes; the kernel itself never does it).
        const auto vis = dt::visibleHullEdges(T, S[i]);
        const std::uint64_t before = st.cavityFaces;
        dt::Face* b = dt::insertVertex(T, last, S[i], st, scratch);
        if (b) last = b, ++inserted;
        if (!vis.empty()) ++outside, visible += vis.size(), cavOut += st.cavityFaces - before;
      }
      const dt::CheckReport r = dt::checkTriangulation(T);
      const double share = 100.0 * double(outside) / double(inserted);
      if (outside) visibleMax = std::max(visibleMax, double(visible) / double(outside));
      if (fam != "circle") {
        std::string key = fam + "_" + order;
        for (char& c : key) c = c == ' ' ? '_' : c;
        v.num("s222.outside_" + key, share, "%.1f%%");
      }
      t.add({fam, order, ch::fmt("%.2f%%", 100.0 * double(outside) / double(inserted)),
             ch::fmt("%.2f", outside ? double(visible) / double(outside) : 0.0),
             ch::fmt("%.2f", outside ? double(cavOut) / double(outside) : 0.0),
             ch::fmt("%.2f", st.meanCavity()), r.ok && r.nVertices == m ? "yes" : "NO"});
    }
  t.emit(o, "table_outside_hull");
  v.num("s222.visible_max", visibleMax, "%.2f");
}

}  // namespace

int main(int argc, char** argv) {
  const ch::Program p{"sec2_2_2_outside_hull", "Section 2.2.2: inserting a point outside the hull.",
                      100, 10000000, {"fig_outside_hull"}, {}};
  return ch::runMain(argc, argv, p, [](const ch::Options& o) {
    ch::Values v(o, "sec2_2_2_outside_hull");
    figure(o);
    if (o.everything()) table(o, v);
    v.write();
  });
}
