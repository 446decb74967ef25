/// \file test_2_3_3_data_structure.cpp Claims of section 2.3.3 (choice of a data structure): the pointer counts of the five structures and the memory of the face-based one, the half-edge count, and the vertex star.
#include <doctest/doctest.h>

#include <cmath>
#include <map>
#include <set>
#include <stdexcept>

#include "adjacency.h"
#include "stats.h"
#include "support.h"

TEST_CASE("2.3.3 pointer counts: full 42n and bidirectional 30n and vertices-only 9n and winged-edge 33n and face-based 15n") {
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

TEST_CASE("2.3.3 exercise 1: a half-edge structure needs 36n pointers") {
  CHECK(dt::halfEdgePointers(1e6, 0, false) == 36);
  CHECK(dt::halfEdgePointers(1000, 30, true) < 36);
}

TEST_CASE("2.3.3 exercise 2: vertexStar lists exactly the triangles of a vertex") {
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
