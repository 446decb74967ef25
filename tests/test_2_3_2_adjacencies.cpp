/// \file test_2_3_2_adjacencies.cpp Claims of section 2.3.2: Euler's counts, eqs. (2.2)-(2.3), Figure 2.9, and the section's exercises (grid counts, a vertex of degree at most 5).
#include <doctest/doctest.h>

#include <algorithm>
#include <map>
#include <random>
#include <set>
#include <stdexcept>

#include "adjacency.h"
#include "flip.h"
#include "stats.h"
#include "support.h"

namespace {

struct Built {
  dt::PlainMesh mesh;
  dt::CheckReport report;
  dt::MeshCounts counts;
};

// DT(S) with ghost faces, checked exactly, and counted by meshCounts (which shares no code with
// the checker: it sorts edges instead of hashing directed ones).
Built build(const dt::XY& p) {
  dt::Triangulation T;
  std::vector<dt::Vertex*> S;
  for (std::size_t i = 0; i < p.size() / 2; ++i) S.push_back(T.addVertex(p[2 * i], p[2 * i + 1], long(i)));
  dt::delaunayTrglHull(T, S, dt::StartRule::LastCavity);
  Built b;
  REQUIRE(dt::checkTriangulation(T).ok);
  b.mesh = dt::extractMesh(T, true);
  b.report = dt::checkDelaunay(b.mesh.xy, b.mesh.tri);
  REQUIRE_MESSAGE(b.report.ok, b.report.error);
  b.counts = dt::meshCounts(b.mesh.xy.size() / 2, b.mesh.tri);
  return b;
}

// The inputs of the tests: random, degenerate (grids, cocircular, collinear but one, duplicates)
// and badly scaled.
std::vector<std::pair<std::string, dt::XY>> inputs() {
  std::vector<std::pair<std::string, dt::XY>> v;
  for (unsigned s = 1; s <= 6; ++s) v.push_back({"uniform", dt::uniformPoints(50 * s * s, s)});
  for (int k : {2, 3, 7, 20}) {
    dt::XY g = dt::gridPoints(k, k + 1);
    dt::shufflePoints(g, unsigned(k));
    v.push_back({"grid", g});
  }
  v.push_back({"circle", dt::circlePoints(64)});
  dt::XY line;  // 30 collinear points and one off the line
  for (int i = 0; i < 30; ++i) {
    line.push_back(i);
    line.push_back(2.0 * i);
  }
  line.push_back(3);
  line.push_back(-1);
  v.push_back({"collinear + 1", line});
  dt::XY dup = dt::uniformPoints(200, 9);
  for (std::size_t i = 0; i < 100; ++i) dup.push_back(dup[i]);  // 50 points given twice
  v.push_back({"duplicates", dup});
  dt::XY tiny = dt::uniformPoints(300, 10, 0, 1e-200);
  v.push_back({"tiny", tiny});
  dt::XY huge = dt::uniformPoints(300, 11, -1e100, 1e100);
  v.push_back({"huge", huge});
  return v;
}

}  // namespace

TEST_CASE("2.3.2 n_f = 2(n-1) - n_h and n_e = 3(n-1) - n_h exactly with degenerate inputs included") {
  for (const auto& [name, p] : inputs()) {
    CAPTURE(name);
    const Built b = build(p);
    const dt::MeshCounts& c = b.counts;
    CHECK(c.n == long(b.report.nVertices));
    CHECK(c.nh == long(b.report.nHull));
    CHECK(c.ne == long(b.report.nEdges));
  }
  // checkDelaunay (inside build) already refuses a mesh whose counts break Euler, so the
  // counts above cannot disagree with Euler there. meshCounts alone: Euler holds for any
  // triangulation of the points, not only the Delaunay one (random flips), and fails for a
  // mesh that does not cover the hull of its vertices (a hole, two pieces).
  for (unsigned seed : {1u, 2u}) {
    dt::Triangulation T;
    dt::delaunayTrglHull(T, dt::addVertices(T, dt::uniformPoints(400, 40 + seed)), dt::StartRule::LastCavity);
    std::mt19937 g(seed);
    int flips = 0;
    for (int it = 0; it < 3000; ++it) {
      std::vector<dt::Face*> live;
      for (dt::Face& f : T.faces())
        if (!f.isGhost()) live.push_back(&f);
      flips += dt::flipEdge(live[g() % live.size()], int(g() % 3));
    }
    const dt::PlainMesh m = dt::extractMesh(T, true);
    CHECK(flips > 1000);
    CHECK_FALSE(dt::checkDelaunay(m.xy, m.tri).ok);  // no longer Delaunay
    const dt::MeshCounts c = dt::meshCounts(m.xy.size() / 2, m.tri);
    CHECK(c.nf == c.eulerNF());
    CHECK(c.ne == c.eulerNE());
  }
  // A square ring of 8 triangles (a hole in the middle) and two separate triangles.
  // Ring: outer square 0-3 = (0,0) (3,0) (3,3) (0,3), inner square 4-7 = (1,1) (2,1) (2,2) (1,2).
  const std::vector<std::array<int, 3>> ringTri = {{0, 1, 5}, {0, 5, 4}, {1, 2, 6}, {1, 6, 5},
                                                   {2, 3, 7}, {2, 7, 6}, {3, 0, 4}, {3, 4, 7}};
  const dt::MeshCounts r = dt::meshCounts(8, ringTri);
  CHECK(r.nf == 8);
  CHECK(r.nf != r.eulerNF());
  const dt::MeshCounts two = dt::meshCounts(6, {{0, 1, 2}, {3, 4, 5}});
  CHECK(two.nf != two.eulerNF());
}

TEST_CASE("2.3.2 eqs. (2.2)-(2.3): n n_vf = 3 n_f = 6n - 3n_h - 6 and n n_ve = 2 n_e = 6n - 2n_h - 6") {
  // Integer forms of the two equations: no rounding can hide an off-by-one.
  for (const auto& [name, p] : inputs()) {
    CAPTURE(name);
    const dt::MeshCounts c = build(p).counts;
    CHECK(c.sumVF == 3 * c.nf);
    CHECK(c.sumVF == 6 * c.n - 3 * c.nh - 6);
    CHECK(c.sumVE == 2 * c.ne);
    CHECK(c.sumVE == 6 * c.n - 2 * c.nh - 6);
    CHECK(c.meanVF() == doctest::Approx(c.eq22()).epsilon(1e-12));
    CHECK(c.meanVE() == doctest::Approx(c.eq23()).epsilon(1e-12));
  }
}

TEST_CASE("2.3.2 Figure 2.9: n = 12 and n_h = 9 give n_vf = 39/12 = 3.25") {
  // The points of Figure 2.9 (chapters/ch2/sec2_3_2_adjacencies.cpp).
  const dt::XY p = {1.285,  0.149,  0.843,  0.735,  0.033,  1.020,  -0.803, 0.774,
                        -1.287, 0.200,  -1.119, -0.469, -0.474, -0.931, 0.423,  -0.967,
                        1.098,  -0.516, -0.45,  0.15,   0.35,   0.3,    0.05,   -0.4};
  const dt::MeshCounts c = build(p).counts;
  CHECK(c.n == 12);
  CHECK(c.nh == 9);
  CHECK(c.nf == 13);
  CHECK(c.sumVF == 39);
  CHECK(c.meanVF() == 3.25);
  CHECK(c.eq22() == 3.25);
}

TEST_CASE("2.3.2 on random points n_vf and n_ve tend to 6 (n >> n_h)") {
  // E[n_h] grows like log n for uniform points, so 6 - n_vf = (3 n_h + 6)/n is below 0.02 at 10^4.
  const dt::MeshCounts c = build(dt::uniformPoints(10000, 77)).counts;
  CHECK(c.meanVF() > 5.98);  // book: s232.bound_mean_lo
  CHECK(c.meanVF() < 6);
  CHECK(c.meanVE() > 5.98);
  CHECK(c.meanVE() < 6);
}

TEST_CASE("2.3.2 exercise 1: counts of a grid's Delaunay triangulation in closed form") {
  for (auto [nx, ny] : {std::pair<long, long>{2, 2}, {2, 9}, {5, 3}, {17, 11}}) {
    CAPTURE(nx);
    CAPTURE(ny);
    dt::XY g = dt::gridPoints(int(nx), int(ny), 0.5, -3, 7);
    dt::shufflePoints(g, dttest::variant(unsigned(nx * ny)));
    const dt::MeshCounts c = build(g).counts;
    const std::array<long, 4> f = dt::gridCounts(nx, ny);
    CHECK(c.n == f[0]);
    CHECK(c.nh == f[1]);
    CHECK(c.nf == f[2]);
    CHECK(c.ne == f[3]);
  }
  CHECK_THROWS_AS(dt::gridCounts(1, 5), std::invalid_argument);
}

TEST_CASE("2.3.2 exercise 2: every triangulation has a vertex with at most 5 edges") {
  for (const auto& [name, p] : inputs()) {
    CAPTURE(name);
    const dt::MeshCounts c = build(p).counts;
    const int v = dt::lowDegreeVertex(c);
    REQUIRE(v >= 0);
    CHECK(c.ve[std::size_t(v)] <= 5);
  }
  dt::MeshCounts fake;  // the function can say "none": a hexagonal fan's centre alone
  fake.vf = {6};
  fake.ve = {6};
  CHECK(dt::lowDegreeVertex(fake) == -1);
}
