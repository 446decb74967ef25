/// \file test_2_3_2_adjacencies.cpp Claims of sections 2.3.2-2.3.3: Euler's counts, eqs. (2.2)-(2.3), Figure 2.9, pointer counts, the vertex star, and computeAdjacencies.
#include <doctest/doctest.h>

#include <algorithm>
#include <map>
#include <set>
#include <stdexcept>

#include "adjacency.h"
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

TEST_CASE("2.3.2 n_f = 2(n-1) - n_h and n_e = 3(n-1) - n_h, exactly, degenerate inputs included") {
  for (const auto& [name, p] : inputs()) {
    CAPTURE(name);
    const Built b = build(p);
    const dt::MeshCounts& c = b.counts;
    CHECK(c.n == long(b.report.nVertices));
    CHECK(c.nh == long(b.report.nHull));
    CHECK(c.ne == long(b.report.nEdges));
    CHECK(c.nf == c.eulerNF());
    CHECK(c.ne == c.eulerNE());
  }
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

TEST_CASE("2.3.2 Figure 2.9: n = 12, n_h = 9, n_vf = 39/12 = 3.25") {
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
  CHECK(c.meanVF() > 5.98);
  CHECK(c.meanVF() < 6);
  CHECK(c.meanVE() > 5.98);
  CHECK(c.meanVE() < 6);
}

TEST_CASE("Exercise 2.3.2.1: counts of a grid's Delaunay triangulation in closed form") {
  for (auto [nx, ny] : {std::pair<long, long>{2, 2}, {2, 9}, {5, 3}, {17, 11}}) {
    CAPTURE(nx);
    CAPTURE(ny);
    dt::XY g = dt::gridPoints(int(nx), int(ny), 0.5, -3, 7);
    dt::shufflePoints(g, unsigned(nx * ny));
    const dt::MeshCounts c = build(g).counts;
    const std::array<long, 4> f = dt::gridCounts(nx, ny);
    CHECK(c.n == f[0]);
    CHECK(c.nh == f[1]);
    CHECK(c.nf == f[2]);
    CHECK(c.ne == f[3]);
  }
  CHECK_THROWS_AS(dt::gridCounts(1, 5), std::invalid_argument);
}

TEST_CASE("Exercise 2.3.2.2: every triangulation has a vertex with at most 5 edges") {
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

TEST_CASE("2.3.3 pointer counts: full 42n, bidirectional 30n, vertices only 9n, winged-edge 33n, face-based 15n") {
  const std::vector<dt::PointerCount> a = dt::pointerCounts(1e6, 0, false);
  REQUIRE(a.size() == 5);
  const double notes[5] = {42, 30, 9, 33, 15};
  for (int i = 0; i < 5; ++i) {
    CAPTURE(a[std::size_t(i)].name);
    CHECK(a[std::size_t(i)].perVertex == notes[i]);
  }
  // With the exact counts of a mesh with n vertices and n_h on the hull, each N_p/n approaches
  // the notes' value from below as n grows (n_h = 4 sqrt(n), a grid-like hull).
  for (double n : {1e2, 1e4, 1e6}) {
    const std::vector<dt::PointerCount> e = dt::pointerCounts(n, 4 * std::sqrt(n), true);
    for (int i = 0; i < 5; ++i) {
      CHECK(e[std::size_t(i)].perVertex < notes[i]);
      CHECK(e[std::size_t(i)].perVertex > notes[i] * (1 - 5 / std::sqrt(n)));
    }
  }
  // "With 8 bytes pointers, ... n = 10^6 is 120 Mb": 15 pointers of 8 bytes per vertex.
  CHECK(a[4].perVertex * 8 * 1e6 == 120e6);
}

TEST_CASE("Exercise 2.3.3.1: a half-edge structure needs 36n pointers") {
  CHECK(dt::halfEdgePointers(1e6, 0, false) == 36);
  CHECK(dt::halfEdgePointers(1000, 30, true) < 36);
}

TEST_CASE("Exercise 2.3.3.2: vertexStar lists exactly the triangles of a vertex") {
  // With ghost faces (closed stars) and with super-triangles (open stars at the corners).
  for (int method = 0; method < 2; ++method) {
    CAPTURE(method);
    dt::Triangulation T;
    std::vector<dt::Vertex*> S;
    dt::XY p = dt::gridPoints(6, 5);
    const dt::XY r = dt::uniformPoints(40, 3, 0, 5);
    p.insert(p.end(), r.begin(), r.end());
    for (std::size_t i = 0; i < p.size() / 2; ++i) S.push_back(T.addVertex(p[2 * i], p[2 * i + 1], long(i)));
    if (method == 0) {
      dt::delaunayTrglHull(T, S, dt::StartRule::LastCavity);
    } else {
      dt::initSuperTriangles(T, 0, 0, 5, 5);
      dt::delaunayTrgl(T, S, dt::StartRule::LastCavity);
    }
    REQUIRE(dt::checkTriangulation(T).ok);
    std::map<const dt::Vertex*, std::set<const dt::Face*>> truth;
    std::map<const dt::Vertex*, dt::Face*> anyFace;
    for (dt::Face& f : T.faces())
      if (!f.deleted && !f.isGhost())
        for (const dt::Vertex* v : f.V) {
          truth[v].insert(&f);
          anyFace[v] = &f;
        }
    for (const auto& [v, faces] : truth) {
      const std::vector<dt::Face*> star = dt::vertexStar(anyFace[v], v);
      CHECK(std::set<const dt::Face*>(star.begin(), star.end()) == faces);
      CHECK(star.size() == faces.size());
      for (std::size_t i = 0; i + 1 < star.size(); ++i)  // consecutive faces share an edge
        CHECK(dt::neighbourIndex(star[i], star[i + 1]) >= 0);
    }
    dt::Face* f = anyFace.begin()->second;
    const dt::Vertex stranger(100, 100);
    CHECK_THROWS_AS(dt::vertexStar(f, &stranger), std::logic_error);
  }
}

TEST_CASE("2.3.4 Listing 2.4: computeAdjacencies pairs every interior edge exactly once") {
  for (unsigned seed : {1u, 2u, 3u}) {
    dt::Triangulation T;
    std::vector<dt::Vertex*> S;
    dt::XY p = seed == 3 ? dt::gridPoints(12, 9) : dt::uniformPoints(500, seed);
    for (std::size_t i = 0; i < p.size() / 2; ++i) S.push_back(T.addVertex(p[2 * i], p[2 * i + 1], long(i)));
    dt::initSuperTriangles(T, 0, 0, 12, 12);
    dt::delaunayTrgl(T, S, dt::StartRule::LastCavity);
    REQUIRE(dt::checkTriangulation(T).ok);
    // Remember the links, forget them, rebuild them from scratch with each method.
    std::vector<dt::Face*> all;
    std::map<dt::Face*, std::array<dt::Face*, 3>> before;
    for (dt::Face& f : T.faces()) {
      all.push_back(&f);
      before[&f] = {f.F[0], f.F[1], f.F[2]};
    }
    for (int method = 0; method < 2; ++method) {
      CAPTURE(method);
      for (dt::Face* f : all) f->F[0] = f->F[1] = f->F[2] = nullptr;
      if (method == 0)
        dt::computeAdjacencies(all);
      else
        dt::computeAdjacenciesSorted(all);
      std::size_t links = 0, boundary = 0;
      for (dt::Face* f : all)
        for (int k = 0; k < 3; ++k) {
          CHECK(f->F[k] == before[f][std::size_t(k)]);
          if (f->F[k] == nullptr) {
            ++boundary;
            continue;
          }
          ++links;
          const int j = dt::neighbourIndex(f->F[k], f);
          REQUIRE(j >= 0);
          CHECK(f->F[k]->V[j] == f->V[(k + 1) % 3]);  // across the same edge, opposite way
        }
      // The super-square: 4 boundary edges; every other edge linked from both sides.
      const dt::MeshCounts c = dt::meshCounts(T.vertices().size(), dt::extractMesh(T, false).tri);
      CHECK(boundary == 4);
      CHECK(links == 2 * std::size_t(c.ne - 4));
    }
  }
}

TEST_CASE("2.3.4 Listing 2.4 rejects an edge used twice with the same orientation") {
  dt::Triangulation T;
  dt::Vertex* a = T.addVertex(0, 0, 0);
  dt::Vertex* b = T.addVertex(1, 0, 1);
  dt::Vertex* c = T.addVertex(0, 1, 2);
  dt::Vertex* d = T.addVertex(0, -1, 3);
  std::vector<dt::Face*> faces = {T.addFace(a, b, c), T.addFace(a, b, d)};
  std::vector<dt::Face*> copy = faces;
  CHECK_THROWS_AS(dt::computeAdjacencies(faces), std::logic_error);
  CHECK_THROWS_AS(dt::computeAdjacenciesSorted(copy), std::logic_error);
}
