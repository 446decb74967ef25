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
#include "mesh3d.h"
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
    const dt::XY r = dt::uniformPoints(40, dttest::variant(3), 0, 5);
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

TEST_CASE("2.3.3 in 3D a facet has 1 or 2 tetrahedra but the tetrahedra around an edge form a cycle of varying length") {
  // The notes: the face-based structure "can be extended in 3D", the edge-based ones cannot.
  // The errata corrects the second half: an edge-based record extends too, but around a 3D
  // edge it must hold a cycle of tetrahedra instead of two faces. Both halves on the library's
  // Kuhn mesh (code/checks/mesh3d.h) of a 4 x 4 x 4 grid of cubes: every facet has 1 or 2
  // tetrahedra (4 vertices + 4 neighbours per tetrahedron, a fixed record), every edge's
  // tetrahedra form one cycle (inside) or one path (on the boundary), of several lengths.
  const int k = 4;
  const std::vector<dt::Tet> tets = dt::kuhnTetrahedra(k);
  REQUIRE(tets.size() == std::size_t(6 * k * k * k));
  std::set<int> facetCounts;
  for (const auto& [f, n] : dt::tetsPerFacet(tets)) facetCounts.insert(n);
  CHECK(facetCounts == std::set<int>{1, 2});
  // An independent count of the tetrahedra on each edge, against the rings' lengths.
  std::map<std::pair<int, int>, std::size_t> perEdge;
  for (const dt::Tet& t : tets)
    for (int a = 0; a < 4; ++a)
      for (int b = a + 1; b < 4; ++b) ++perEdge[std::minmax(t[std::size_t(a)], t[std::size_t(b)])];
  const auto rings = dt::edgeRings(tets);
  REQUIRE(rings.size() == perEdge.size());
  // An edge lies on the cube's boundary iff both ends share a coordinate equal to 0 or k.
  auto onBoundary = [&](int u, int v) {
    const int cu[3] = {u / ((k + 1) * (k + 1)), u / (k + 1) % (k + 1), u % (k + 1)};
    const int cv[3] = {v / ((k + 1) * (k + 1)), v / (k + 1) % (k + 1), v % (k + 1)};
    for (int x = 0; x < 3; ++x)
      if (cu[x] == cv[x] && (cu[x] == 0 || cu[x] == k)) return true;
    return false;
  };
  std::set<std::size_t> cycleLengths;
  for (const auto& [e, ring] : rings) {
    CAPTURE(e.first);
    CAPTURE(e.second);
    REQUIRE(ring.tets.size() == perEdge[e]);
    // Consecutive tetrahedra share a facet through the edge (three common vertices).
    const std::size_t m = ring.tets.size();
    for (std::size_t i = 0; i + 1 < m + (ring.closed ? 1 : 0); ++i) {
      const dt::Tet& s = tets[std::size_t(ring.tets[i])];
      const dt::Tet& t = tets[std::size_t(ring.tets[(i + 1) % m])];
      int common = 0;
      for (int x : s) common += std::count(t.begin(), t.end(), x) > 0;
      CHECK(common == 3);
    }
    // A cycle exactly for an edge whose midpoint is inside the cube.
    const bool boundary = onBoundary(e.first, e.second);
    CHECK(ring.closed == !boundary);
    if (ring.closed) cycleLengths.insert(m);
  }
  MESSAGE("interior edges have cycles of " << *cycleLengths.begin() << " to " << *cycleLengths.rbegin() << " tetrahedra");
  CHECK(cycleLengths.size() >= 2);  // no fixed-size edge record
  CHECK(*cycleLengths.rbegin() >= 6);
  // A facet with three tetrahedra (not a manifold) is refused, not given a wrong ring.
  std::vector<dt::Tet> bad = {{0, 1, 2, 3}, {0, 1, 2, 4}, {0, 1, 2, 5}};
  CHECK_THROWS_WITH_AS(dt::edgeRings(bad), "edgeRings: a facet through an edge has more than two tetrahedra",
                       std::logic_error);
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
