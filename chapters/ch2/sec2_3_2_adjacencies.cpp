// Section 2.3.2, "More on adjacencies": Figure 2.9 (a triangulation with n = 12, n_h = 9, each
// vertex labelled with its number of triangles) and a table of the counts n, n_h, n_f, n_e,
// n_vf, n_ve measured on random, grid, convex-position and cocircular inputs, beside Euler's
// n_f = 2(n-1) - n_h, n_e = 3(n-1) - n_h and eqs. (2.2)-(2.3).
//
//   sec2_3_2_adjacencies [--out DIR] [--quick] [--max-n N] [--no-plot]
#include <algorithm>
#include <cmath>

#include "check.h"
#include "common.h"
#include "figure_data.h"
#include "generators.h"
#include "stats.h"
#include "triangulate.h"

namespace {

struct Result {
  dt::PlainMesh mesh;
  dt::MeshCounts counts;
};

// DT(S) of the points (ghost faces, no super-triangles), checked exactly.
Result triangulate(const std::vector<double>& xy) {
  dt::Triangulation T;
  std::vector<dt::Vertex*> S;
  for (std::size_t i = 0; i < xy.size() / 2; ++i)
    S.push_back(T.addVertex(xy[2 * i], xy[2 * i + 1], long(i)));
  dt::delaunayTrglHull(T, S, dt::StartRule::LastCavity);
  Result r;
  r.mesh = dt::extractMesh(T, true);
  const dt::CheckReport rep = dt::checkDelaunay(r.mesh.xy, r.mesh.tri);
  if (!rep.ok) throw std::runtime_error("invalid triangulation: " + rep.error);
  r.counts = dt::meshCounts(r.mesh.xy.size() / 2, r.mesh.tri);
  return r;
}

// Figure 2.9: nine points on a slightly irregular ellipse (all on the hull) and three inside.
void figure29(const ch::Options& o) {
  const std::vector<double> xy = {1.285,  0.149,  0.843,  0.735,  0.033,  1.020,  -0.803, 0.774,
                                  -1.287, 0.200,  -1.119, -0.469, -0.474, -0.931, 0.423,  -0.967,
                                  1.098,  -0.516, -0.45,  0.15,   0.35,   0.3,    0.05,   -0.4};
  const Result r = triangulate(xy);
  const dt::MeshCounts& c = r.counts;
  if (c.n != 12 || c.nh != 9 || c.sumVF != 39)
    throw std::runtime_error("Figure 2.9: expected n = 12, n_h = 9, 39 corners");
  // Each vertex is a disc with its count inside: the edges stop at the discs, so that no edge
  // runs under a count (fig2_9_disc.gp: the radius, in data units).
  const double R = 0.085;
  std::vector<ch::Seg> edges = ch::triangleSegs(r.mesh.xy, r.mesh.tri);
  for (ch::Seg& e : edges) {
    const double len = std::hypot(e.x1 - e.x0, e.y1 - e.y0), ux = (e.x1 - e.x0) / len, uy = (e.y1 - e.y0) / len;
    e = {e.x0 + R * ux, e.y0 + R * uy, e.x1 - R * ux, e.y1 - R * uy};
  }
  ch::writeOut(o, "fig2_9_tri.dat", ch::gnuplotSegs(edges));
  ch::writeOut(o, "fig2_9_disc.gp", ch::fmt("R = %.17g\n", R));
  std::string labels = "# x y n_vf(vertex) n_ve(vertex) on_hull\n";
  // A boundary vertex has one edge more than triangles (its fan is open); inner ones as many.
  for (std::size_t v = 0; v < c.vf.size(); ++v)
    labels += ch::fmt("%.17g %.17g %d %d %d\n", r.mesh.xy[2 * v], r.mesh.xy[2 * v + 1], c.vf[v],
                      c.ve[v], int(c.vf[v] < c.ve[v]));
  ch::writeOut(o, "fig2_9_vertices.dat", labels);
  // The notes' symbols in the math font (figures/ch2/notation.txt): italic n, n_h, n_vf.
  ch::writeOut(o, "fig2_9_title.txt",
               ch::mathText("n") + ch::fmt(" = %ld, ", c.n) + ch::mathText("n_h") + ch::fmt(" = %ld: mean ", c.nh) +
                   ch::mathText("n_{vf}") +
                   ch::fmt(" = %ld/%ld = %.2f;  eq. (2.2): 6 \342\210\222 (3 \303\227 %ld + 6)/%ld = %.2f", c.sumVF, c.n,
                           c.meanVF(), c.nh, c.n, c.eq22()));
  std::cout << "Figure 2.9: n = " << c.n << ", n_h = " << c.nh << ", sum of n_vf = " << c.sumVF
            << ", average n_vf = " << ch::fmt("%.4g", c.meanVF())
            << ", eq. (2.2) = " << ch::fmt("%.4g", c.eq22())
            << "; average n_ve = " << ch::fmt("%.4g", c.meanVE())
            << ", eq. (2.3) = " << ch::fmt("%.4g", c.eq23()) << "\n";
  ch::runGnuplot(o, "fig2_9.gp");
}

void countsTable(const ch::Options& o) {
  struct Input {
    std::string name;
    std::vector<double> xy;
  };
  const long maxN = o.maxN > 0 ? o.maxN : (o.quick ? 10000 : 100000);
  std::vector<Input> inputs;
  for (long n : {100L, 10000L, 100000L})
    if (n <= maxN) inputs.push_back({"uniform random", dt::uniformPoints(std::size_t(n), o.seed(232u + unsigned(n)))});
  for (long k : {10L, 100L, 300L})
    if (k * k <= maxN) {
      std::vector<double> g = dt::gridPoints(int(k), int(k));
      dt::shufflePoints(g, 7u);
      inputs.push_back({ch::fmt("grid %ldx%ld", k, k), g});
    }
  for (long n : {100L, 2000L})
    if (n <= maxN) {
      // convex position: (i, i^2) are exact doubles, every point a hull vertex
      std::vector<double> c;
      for (long i = 0; i < n; ++i) {
        c.push_back(double(i));
        c.push_back(double(i) * double(i));
      }
      dt::shufflePoints(c, 11u);
      inputs.push_back({"convex position (parabola)", c});
    }
  {
    // 1000 points rounded onto the unit circle: nearly cocircular, a hard case for the
    // predicates; the measured n_h says whether rounding left them all in convex position.
    std::vector<double> c = dt::circlePoints(std::size_t(std::min(1000L, maxN)));
    dt::shufflePoints(c, 13u);
    inputs.push_back({"circle (rounded)", c});
  }
  ch::Table t;
  // Two tables of the same runs (one would be wider than the book's page).
  t.caption = "Counts of section 2.3.2 measured on Delaunay triangulations (exactly checked), "
              "beside Euler's relations";
  t.header = {"input", "n", "n_h", "n_f", "2(n-1)-n_h", "n_e", "3(n-1)-n_h"};
  ch::Table m;
  m.caption = "The same triangulations: mean numbers of triangles (n_vf) and edges (n_ve) at a "
              "vertex, beside eqs. (2.2)-(2.3)";
  m.header = {"input", "n", "n_vf measured", "eq. (2.2)", "n_ve measured", "eq. (2.3)",
              "min..max n_vf"};
  ch::Progress prog("2.3.2 counts", inputs.size());
  std::size_t done = 0;
  for (const Input& in : inputs) {
    const Result r = triangulate(in.xy);
    const dt::MeshCounts& c = r.counts;
    int lo = 1 << 30, hi = 0;
    for (int d : c.vf)
      if (d > 0) {
        lo = std::min(lo, d);
        hi = std::max(hi, d);
      }
    t.add({in.name, std::to_string(c.n), std::to_string(c.nh), std::to_string(c.nf),
           std::to_string(c.eulerNF()), std::to_string(c.ne), std::to_string(c.eulerNE())});
    m.add({in.name, std::to_string(c.n), ch::fmt("%.6f", c.meanVF()), ch::fmt("%.6f", c.eq22()),
           ch::fmt("%.6f", c.meanVE()), ch::fmt("%.6f", c.eq23()), ch::fmt("%d..%d", lo, hi)});
    if (c.nf != c.eulerNF() || c.ne != c.eulerNE() || c.sumVF != 3 * c.nf || c.sumVE != 2 * c.ne)
      throw std::runtime_error(in.name + ": a count of section 2.3.2 does not hold");
    prog.update(++done);
  }
  t.emit(o, "table_adjacency_counts");
  m.emit(o, "table_adjacency_means");
  // The student's edition of the book shows both tables without the rows of points in convex
  // position (n_h = n: the parabola, and the circle too), which answer exercise 2.3.2-3. The
  // two tables have the same rows in the same order.
  for (std::size_t k = t.rows.size(); k-- > 0;)
    if (t.rows[k][1] == t.rows[k][2]) {
      t.rows.erase(t.rows.begin() + long(k));
      m.rows.erase(m.rows.begin() + long(k));
    }
  t.emit(o, "table_adjacency_counts_student");
  m.emit(o, "table_adjacency_means_student");
}

}  // namespace

int main(int argc, char** argv) {
  const ch::Program p{"sec2_3_2_adjacencies", "Section 2.3.2: adjacencies and Euler counts (Figure 2.9).",
                      100, 10000000, {"fig2_9"}, {}};
  return ch::runMain(argc, argv, p, [](const ch::Options& o) {
    figure29(o);
    if (o.everything()) countsTable(o);
  });
}
