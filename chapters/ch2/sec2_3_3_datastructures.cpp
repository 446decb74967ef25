// Section 2.3.3, "Choice of a datastructure": the notes' pointer counts (full 42n, bidirectional
// 30n, vertices only 9n, winged-edge 33n, face-based 15n) recomputed from the counting formulas,
// asymptotically and exactly, and the real footprint of this library's face-based structure for
// 10^6 points (sizeof, resident memory), beside the notes' "120 Mb".
//
//   sec2_3_3_datastructures [--out DIR] [--quick] [--max-n N]
//
// --max-n sets the number of points of the footprint measurement (default 10^6, --quick 10^5).
#include <sys/resource.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <random>

#include "check.h"
#include "common.h"
#include "generators.h"
#include "stats.h"
#include "triangulate.h"

namespace {

// Resident memory of this process now (bytes), from /proc/self/statm.
double residentBytes() {
  std::ifstream in("/proc/self/statm");
  double pages = 0, resident = 0;
  in >> pages >> resident;
  return resident * double(sysconf(_SC_PAGESIZE));
}

// Peak resident memory of this process so far (bytes); Linux reports ru_maxrss in kB.
double peakResidentBytes() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return double(u.ru_maxrss) * 1024.0;
}

void pointerTable(const ch::Options& o) {
  ch::Table t;
  t.caption = "Pointers N_p / n of the data structures of section 2.3.3: the notes' asymptotic "
              "counts (n_e = 3n, n_f = 2n, n_ve = n_vf = 6, n_ef = 2) and the exact counts for "
              "n random points (n_h measured) and an n-point grid";
  // Exact counts need n_h: a real random triangulation and a grid.
  struct Case {
    std::string name;
    double n, nh;
  };
  std::vector<Case> cases;
  {
    dt::Triangulation T;
    dt::delaunayTrglHull(T, dt::addVertices(T, dt::uniformPoints(1000, 233)), dt::StartRule::LastCavity);
    const dt::CheckReport r = dt::checkTriangulation(T);
    if (!r.ok) throw std::runtime_error("pointer table: " + r.error);
    cases.push_back({"1000 random points", double(r.nVertices), double(r.nHull)});
  }
  const std::array<long, 4> g = dt::gridCounts(10, 10);
  cases.push_back({"10x10 grid", double(g[0]), double(g[1])});
  const std::array<long, 4> g2 = dt::gridCounts(1000, 1000);
  cases.push_back({"1000x1000 grid", double(g2[0]), double(g2[1])});
  t.header = {"data structure", "notes (n >> n_h)"};
  for (const Case& c : cases)
    t.header.push_back(ch::fmt("exact, %s (n = %.0f, n_h = %.0f)", c.name.c_str(), c.n, c.nh));
  const std::vector<dt::PointerCount> asym = dt::pointerCounts(1, 0, false);
  std::vector<std::vector<dt::PointerCount>> exact;
  for (const Case& c : cases) exact.push_back(dt::pointerCounts(c.n, c.nh, true));
  for (std::size_t i = 0; i < asym.size(); ++i) {
    std::vector<std::string> row = {asym[i].name, ch::fmt("%gn", asym[i].perVertex)};
    for (const auto& e : exact) row.push_back(ch::fmt("%.3fn", e[i].perVertex));
    t.add(row);
  }
  t.emit(o, "table_datastructures_pointers");
  // The answers of exercises 2.3.3-1 and 2.3.3-2, each its own table: only the teacher's
  // edition of the book shows them (in the solution blocks of book/sec2_3_3.md).
  const auto answer = [&](const std::string& name, const std::string& row, double asymptotic,
                          auto exactFor) {
    ch::Table a;
    a.caption = "Pointers N_p / n: " + row;
    a.header = t.header;
    std::vector<std::string> r = {row, ch::fmt("%gn", asymptotic)};
    for (std::size_t k = 0; k < cases.size(); ++k) r.push_back(ch::fmt("%.3fn", exactFor(k)));
    a.add(r);
    a.emit(o, name);
  };
  answer("table_datastructures_halfedge", "half-edge (exercise 2.3.3-1)", dt::halfEdgePointers(1, 0, false),
         [&](std::size_t k) { return dt::halfEdgePointers(cases[k].n, cases[k].nh, true); });
  answer("table_datastructures_vertexstar", "face-based + one Face* per vertex (exercise 2.3.3-2)",
         asym[4].perVertex + 1, [&](std::size_t k) { return exact[k][4].perVertex + 1; });
}

void footprint(const ch::Options& o) {
  const long n = o.maxN > 0 ? o.maxN : (o.quick ? 100000 : 1000000);
  // Random points, inserted in a snake order of 1000 x 1000 cells (so that the walk from the
  // previous ball is short and the run takes seconds); memory does not depend on the order.
  // Drawn straight into pairs (not through dt::uniformPoints): a second copy of the input would
  // count in the peak memory measured below.
  std::mt19937_64 rng(o.seed(333));
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<std::array<double, 2>> pts(static_cast<std::size_t>(n));
  for (auto& p : pts) {
    p[0] = u(rng);
    p[1] = u(rng);
  }
  const double cells = std::ceil(std::sqrt(double(n)));
  auto key = [cells](const std::array<double, 2>& p) {
    const double row = std::floor(p[1] * cells);
    const double col = std::floor(p[0] * cells);
    return row * cells + (std::fmod(row, 2) == 0 ? col : cells - 1 - col);
  };
  std::sort(pts.begin(), pts.end(), [&](const auto& a, const auto& b) { return key(a) < key(b); });
  const double rss0 = residentBytes();
  dt::InsertionStats st;
  std::size_t nv = 0, nf = 0;
  double rss1 = 0, peak = 0;
  {
    dt::Triangulation T;
    std::vector<dt::Vertex*> S;
    S.reserve(pts.size());
    for (std::size_t i = 0; i < pts.size(); ++i) S.push_back(T.addVertex(pts[i][0], pts[i][1], long(i)));
    dt::initSuperTriangles(T, 0, 0, 1, 1);
    dt::delaunayTrgl(T, S, dt::StartRule::LastCavity, &st);
    S.clear();
    S.shrink_to_fit();  // only the triangulation itself stays resident
    rss1 = residentBytes();
    peak = peakResidentBytes();  // before the check, which needs memory of its own
    nv = T.vertices().size();
    nf = T.faces().size();
    const dt::CheckReport r = dt::checkTriangulation(T);
    if (!r.ok) throw std::runtime_error("footprint: " + r.error);
  }
  const double structBytes = double(nv * sizeof(dt::Vertex) + nf * sizeof(dt::Face));
  const double MB = 1e6;
  ch::Table t;
  t.caption = ch::fmt("Footprint of this library's face-based structure (Face: 3 Vertex*, 3 Face*, "
                      "a flag; Vertex: x, y, z, id, a flag) for n = %ld random points, beside the "
                      "notes' 15 pointers of 8 bytes per vertex",
                      n);
  t.header = {"quantity", "this library", "notes"};
  t.add({"sizeof(Vertex*) = sizeof(Face*)", ch::fmt("%zu bytes", sizeof(dt::Face*)), "8 bytes"});
  t.add({"sizeof(Vertex)", ch::fmt("%zu bytes", sizeof(dt::Vertex)), "1 pointer (coordinates not counted)"});
  t.add({"sizeof(Face)", ch::fmt("%zu bytes", sizeof(dt::Face)), "7 pointers = 56 bytes"});
  t.add({"vertices (4 super-vertices included)", std::to_string(nv), ch::fmt("%ld", n)});
  t.add({"faces n_f (2n + 2 with the super-triangles)", std::to_string(nf), ch::fmt("about 2n = %ld", 2 * n)});
  t.add({"bytes per vertex: sizeof sums", ch::fmt("%.1f", structBytes / double(n)), "15 x 8 = 120"});
  t.add({"structure: vertices x sizeof(Vertex) + faces x sizeof(Face)",
         ch::fmt("%.1f MB", structBytes / MB), ch::fmt("%.0f MB", 120.0 * double(n) / MB)});
  t.add({"resident memory added by the triangulation (/proc/self/statm)",
         ch::fmt("%.1f MB", (rss1 - rss0) / MB), "-"});
  t.add({"peak resident memory of the program after the insertions (getrusage; the input points and the insertion buffers included)", ch::fmt("%.1f MB", peak / MB), "-"});
  t.emit(o, "table_datastructures_footprint");
  std::cout << ch::fmt("n = %ld: %zu faces, N_search = %.2f (snake order, walk from the last ball)\n",
                       n, nf, st.meanSearch());
}

}  // namespace

int main(int argc, char** argv) {
  const ch::Program p{"sec2_3_3_datastructures",
                      "Section 2.3.3: pointer counts and the memory footprint (no figure).", 1000,
                      10000000, {}, {}};
  return ch::runMain(argc, argv, p, [](const ch::Options& o) {
    pointerTable(o);
    footprint(o);
  });
}
