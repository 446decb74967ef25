/// \file test_2_3_3_data_structure.cpp Claims of section 2.3.3 (choice of a data structure): the pointer counts of the five structures and the memory of the face-based one, the half-edge count, and the vertex star.
#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <malloc.h>
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
  // With Euler's exact counts (n_f = 2(n-1) - n_h, n_e = 3(n-1) - n_h) each count is the
  // notes' value minus (a + b n_h) / n, worked out by hand from the records: full 42n - 41 -
  // 18 n_h, bidirectional 30n - 29 - 12 n_h, vertices only 9n - 8 - 4 n_h, winged edge 33n - 31
  // - 11 n_h, face-based 15n - 14 - 7 n_h. Checked exactly on real meshes (n and n_h of a
  // Delaunay triangulation) and on a grid-like hull.
  const double a0[5] = {41, 29, 8, 31, 14}, b0[5] = {18, 12, 4, 11, 7};
  std::vector<std::pair<double, double>> cases = {{1e2, 40}, {1e4, 400}, {1e6, 4000}};
  for (std::size_t m : {100u, 1000u}) {
    dt::Triangulation T;
    dt::delaunayTrglHull(T, dt::addVertices(T, dt::uniformPoints(m, 29)), dt::StartRule::LastCavity);
    const dt::PlainMesh mesh = dt::extractMesh(T, true);
    const dt::MeshCounts c = dt::meshCounts(mesh.xy.size() / 2, mesh.tri);
    cases.push_back({double(c.n), double(c.nh)});
  }
  for (const auto& [n, nh] : cases) {
    CAPTURE(n);
    CAPTURE(nh);
    const std::vector<dt::PointerCount> e = dt::pointerCounts(n, nh, true);
    for (int i = 0; i < 5; ++i) {
      CAPTURE(e[std::size_t(i)].name);
      CHECK(e[std::size_t(i)].perVertex == doctest::Approx(notes[i] - (a0[i] + b0[i] * nh) / n).epsilon(1e-13));
    }
  }
  // "With 8 bytes pointers, ... n = 10^6 is 120 Mb": 15 pointers of 8 bytes per vertex.
  CHECK(a[4].perVertex * 8 * 1e6 == 120e6);
}

TEST_CASE("2.3.3 exercise 1: halfEdgePointers counts the pointers of a half-edge structure") {
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

TEST_CASE("2.3.3 in 3D a tetrahedron has at most one neighbour per facet but an edge has a varying number of tetrahedra around it") {
  // Why the face-based structure extends directly to 3D and an edge-based one only with a
  // variable-size cycle per edge (the errata qualifies the notes' "the edge-based ones cannot").
  // No 3D code is under test here: this is the counting fact the book cites, on a mesh built
  // here.
  // Face-based: each simplex stores its vertices and one neighbour across each facet; that is a
  // fixed-size record in any dimension iff every facet has at most 2 simplices (a manifold).
  // Edge-based (winged edge: 2 faces, 4 wing edges, 2 vertices per edge): fixed-size iff every
  // edge has a fixed number of faces around it, true in 2D (1 or 2), false in 3D, where the
  // number of tetrahedra around an edge varies. Counted on the Freudenthal (Kuhn) subdivision
  // of a 4 x 4 x 4 grid of cubes, 6 tetrahedra per cube, and on a 2D Delaunay triangulation.
  const int k = 4;
  auto id = [&](int i, int j, int l) { return (i * (k + 1) + j) * (k + 1) + l; };
  std::vector<std::array<int, 4>> tets;
  std::array<int, 3> perm = {0, 1, 2};
  for (int i = 0; i < k; ++i)
    for (int j = 0; j < k; ++j)
      for (int l = 0; l < k; ++l) {
        std::sort(perm.begin(), perm.end());
        do {  // the path (i,j,l) -> ... -> (i+1,j+1,l+1), one axis at a time
          int c[3] = {i, j, l};
          std::array<int, 4> t;
          t[0] = id(c[0], c[1], c[2]);
          for (int s = 0; s < 3; ++s) {
            ++c[perm[std::size_t(s)]];
            t[std::size_t(s + 1)] = id(c[0], c[1], c[2]);
          }
          tets.push_back(t);
        } while (std::next_permutation(perm.begin(), perm.end()));
      }
  REQUIRE(tets.size() == std::size_t(6 * k * k * k));
  std::map<std::array<int, 3>, int> perFacet;
  std::map<std::pair<int, int>, int> perEdge;
  for (auto t : tets) {
    std::sort(t.begin(), t.end());
    for (int skip = 0; skip < 4; ++skip) {
      std::array<int, 3> f;
      int m = 0;
      for (int q = 0; q < 4; ++q)
        if (q != skip) f[std::size_t(m++)] = t[std::size_t(q)];
      ++perFacet[f];
    }
    for (int a = 0; a < 4; ++a)
      for (int b = a + 1; b < 4; ++b) ++perEdge[{t[std::size_t(a)], t[std::size_t(b)]}];
  }
  std::set<int> facetCounts, edgeCounts;
  for (const auto& [f, n] : perFacet) facetCounts.insert(n);
  for (const auto& [e, n] : perEdge) edgeCounts.insert(n);
  CHECK(facetCounts == std::set<int>{1, 2});  // 4 vertices + 4 neighbours per tetrahedron
  MESSAGE("tetrahedra around an edge: from " << *edgeCounts.begin() << " to " << *edgeCounts.rbegin());
  CHECK(edgeCounts.size() >= 3);              // no fixed-size edge record
  CHECK(*edgeCounts.rbegin() >= 6);
  // 2D: every edge of a triangulation has 1 or 2 triangles, so a fixed 8-pointer record works.
  dt::Triangulation T;
  dt::delaunayTrglHull(T, dt::addVertices(T, dt::uniformPoints(500, 33)), dt::StartRule::LastCavity);
  std::map<std::pair<const dt::Vertex*, const dt::Vertex*>, int> perEdge2;
  for (const dt::Face* f : T.finiteFaces())
    for (int q = 0; q < 3; ++q) ++perEdge2[std::minmax(f->V[q], f->V[(q + 1) % 3])];
  std::set<int> edgeCounts2;
  for (const auto& [e, n] : perEdge2) edgeCounts2.insert(n);
  CHECK(edgeCounts2 == std::set<int>{1, 2});
}

TEST_CASE("2.3.3 the real footprint of the face-based structure at 10^6 points is above the notes' 120 MB") {
  // "With 8 bytes pointers, the memory footprint of a mesh with n = 10^6 is 120 Mb": 15 pointers
  // per vertex, coordinates not counted. This library stores 2n - 2 faces (the finite ones and
  // the ghosts, Euler's count with the hull closed), no deleted slot left after the insertions
  // (each cavity face is reused), so its structure takes n sizeof(Vertex) + (2n - 2) sizeof(Face)
  // bytes: checked on 3 10^4 random points (Euler's count holds at any n), then evaluated at 10^6.
  const std::size_t n = 30000;
  const auto pts = dt::uniformPoints(n, 34);
  // What the heap really holds for the mesh: the allocator's bytes in use after the
  // triangulation (its temporaries freed) minus before (the points are allocated already).
  // glibc's count; a sanitizer's allocator does not update it, so only the Release build
  // compares it.
  auto heapInUse = [] {  // small blocks, and the large ones glibc maps on their own
    const struct mallinfo2 m = mallinfo2();
    return double(m.uordblks) + double(m.hblkhd);
  };
  const double heapBefore = heapInUse();
  dt::Triangulation T;
  dt::delaunayTrglHull(T, dt::addVertices(T, pts), dt::StartRule::LastCavity);
  const double heapBytes = heapInUse() - heapBefore;
  REQUIRE(dt::checkTriangulation(T).ok);
  std::size_t live = 0;
  for (const dt::Face& f : T.faces()) live += !f.deleted;
  CHECK(live == 2 * n - 2);
  CHECK(T.faces().size() == 2 * n - 2);
  CHECK(T.vertices().size() == n);
  const double perPoint = double(sizeof(dt::Vertex)) + 2 * double(sizeof(dt::Face));
  const double bytes = 1e6 * double(sizeof(dt::Vertex)) + (2e6 - 2) * double(sizeof(dt::Face));
  MESSAGE("sizeof(Vertex) = " << sizeof(dt::Vertex) << ", sizeof(Face) = " << sizeof(dt::Face)
                              << ": " << bytes / 1e6 << " MB at 10^6 points (the notes: 120 MB); heap "
                              << heapBytes / double(n) << " bytes per point at n = " << n);
  // A face is at least its 6 pointers (48 bytes) and a vertex its two coordinates (16 bytes):
  // the notes' 15 pointers (7 per face, 1 per vertex) leave the coordinates out.
  CHECK(sizeof(dt::Face) >= 6 * sizeof(void*));
  CHECK(sizeof(dt::Vertex) >= 2 * sizeof(double));
#if !defined(__SANITIZE_ADDRESS__)
  // The records are the whole footprint: the deques keep them in 512-byte blocks (9 faces or
  // 12 vertices, each block with the allocator's header), which adds up to 10 %, and no other
  // structure (an edge map, a list of deleted faces, a copy of the points) stays behind.
  CHECK(heapBytes >= perPoint * double(n));
  CHECK(heapBytes <= 1.10 * perPoint * double(n));
  CHECK(heapBytes / double(n) * 1e6 > 120e6);  // the real footprint at 10^6, from the heap
#endif
  CHECK(bytes > 120e6);
}
