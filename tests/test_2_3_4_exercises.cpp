/// \file test_2_3_4_exercises.cpp Exercise 2.3.4-1 (exercises/exercises.txt): computeAdjacenciesSorted restores a triangulation's links, rejects an edge two faces walk the same way and an edge of three faces, and leaves the links across unmatched edges alone. Each failure names the face and the edge. The library's computeAdjacencies does what its header says of a third face on an edge.
#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <sstream>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <vector>

#include "adjacency.h"
#include "stats.h"
#include "support.h"

namespace {

// "face 12 (vertices 4 9 -1), edge 1 (9 -> -1)": a face by its index in the list and its
// vertices' ids (super vertices are negative).
std::string faceName(const std::vector<dt::Face*>& faces, const dt::Face* f, int k = -1) {
  std::ostringstream s;
  std::size_t idx = 0;
  while (idx < faces.size() && faces[idx] != f) ++idx;
  if (f == nullptr) return "nullptr";
  if (idx == faces.size()) s << "a face outside the list";
  else s << "face " << idx;
  s << " (vertices " << f->V[0]->id << " " << f->V[1]->id << " " << f->V[2]->id << ")";
  if (k >= 0) s << ", edge " << k << " (" << f->V[k]->id << " -> " << f->V[(k + 1) % 3]->id << ")";
  return s.str();
}

// DT(S0 u S) of n uniform points on the super-triangles, checked exactly.
void kernelMesh(dt::Triangulation& T, int n, unsigned seed) {
  const dt::XY p = dt::uniformPoints(std::size_t(n), seed);
  std::vector<dt::Vertex*> S;
  for (std::size_t i = 0; i < p.size() / 2; ++i) S.push_back(T.addVertex(p[2 * i], p[2 * i + 1], long(i)));
  dt::initSuperTriangles(T, 0, 0, 1, 1);
  dt::delaunayTrgl(T, S, dt::StartRule::LastCavity);
  REQUIRE(dt::checkTriangulation(T).ok);
}

}  // namespace

TEST_CASE("2.3.4 exercise 2.3.4-1 the links of a 3000-point triangulation are restored") {
  dt::Triangulation T;
  kernelMesh(T, 3000, dttest::variant(12));
  std::vector<dt::Face*> all;
  for (dt::Face& f : T.faces()) all.push_back(&f);
  std::vector<std::array<dt::Face*, 3>> links;
  for (dt::Face* f : all) links.push_back({f->F[0], f->F[1], f->F[2]});
  for (dt::Face* f : all) f->F[0] = f->F[1] = f->F[2] = nullptr;
  dt::computeAdjacenciesSorted(all);
  std::size_t wrong = 0;
  for (std::size_t i = 0; i < all.size(); ++i)
    for (int k = 0; k < 3; ++k)
      if (all[i]->F[k] != links[i][std::size_t(k)] && wrong++ == 0)
        FAIL_CHECK(faceName(all, all[i], k) << ": linked to " << faceName(all, all[i]->F[k])
                                            << ", expected " << faceName(all, links[i][std::size_t(k)]));
  CHECK_MESSAGE(wrong == 0, wrong << " of " << 3 * all.size() << " links wrong");
  CHECK(dt::checkTriangulation(T).ok);
}

TEST_CASE("2.3.4 exercise 2.3.4-1 an edge two faces use in the same direction is rejected") {
  // Two faces that walk their shared edge a -> b both: not an oriented mesh.
  dt::Triangulation T;
  dt::Vertex* a = T.addVertex(0, 0, 0);
  dt::Vertex* b = T.addVertex(1, 0, 1);
  dt::Vertex* c = T.addVertex(0, 1, 2);
  dt::Vertex* d = T.addVertex(0, -1, 3);
  // The same two triangles oriented as a mesh: linked, no exception.
  std::vector<dt::Face*> good = {T.addFace(a, b, c), T.addFace(b, a, d)};
  CHECK_NOTHROW(dt::computeAdjacenciesSorted(good));
  CHECK_MESSAGE(good[0]->F[0] == good[1], "faces (0 1 2) and (1 0 3) share the edge 0 - 1");
  CHECK_MESSAGE(good[1]->F[0] == good[0], "faces (1 0 3) and (0 1 2) share the edge 1 - 0");
  std::vector<dt::Face*> pair = {T.addFace(a, b, c), T.addFace(a, b, d)};
  INFO("faces (0 1 2) and (0 1 3) both walk the edge 0 -> 1");
  CHECK_THROWS_AS(dt::computeAdjacenciesSorted(pair), std::logic_error);

  // A real mesh where one face is turned over (two of its vertices exchanged): each of its
  // edges now runs the same way as in its neighbour.
  dt::Triangulation M;
  kernelMesh(M, 200, dttest::variant(5));
  std::vector<dt::Face*> all;
  for (dt::Face& f : M.faces()) all.push_back(&f);
  for (std::size_t pick : {std::size_t(0), all.size() / 2, all.size() - 1}) {
    std::vector<dt::Face*> faces = all;
    dt::Face* f = faces[pick];
    std::swap(f->V[1], f->V[2]);
    INFO(faceName(faces, f) << " turned over in a 200-point triangulation");
    CHECK_THROWS_AS(dt::computeAdjacenciesSorted(faces), std::logic_error);
    std::swap(f->V[1], f->V[2]);
  }
}

TEST_CASE("2.3.4 exercise 2.3.4-1 a link across an unmatched edge is left as it was") {
  // The faces around one vertex (its ball), as the kernel relinks a cavity: the links across
  // the ball's boundary point to faces outside the list and must stay.
  dt::Triangulation T;
  kernelMesh(T, 400, 7);
  std::vector<dt::Face*> all;
  for (dt::Face& f : T.faces()) all.push_back(&f);
  for (long vid : {0L, 57L, 399L}) {
    std::vector<dt::Face*> ball;
    for (dt::Face* f : all)
      if (f->V[0]->id == vid || f->V[1]->id == vid || f->V[2]->id == vid) ball.push_back(f);
    REQUIRE(ball.size() >= 3);
    std::unordered_map<const dt::Face*, std::array<dt::Face*, 3>> before;
    for (dt::Face* f : ball) before[f] = {f->F[0], f->F[1], f->F[2]};
    // Forget the links inside the ball only.
    auto inBall = [&](const dt::Face* g) { return before.count(g) != 0; };
    for (dt::Face* f : ball)
      for (int k = 0; k < 3; ++k)
        if (inBall(f->F[k])) f->F[k] = nullptr;
    dt::computeAdjacenciesSorted(ball);
    for (dt::Face* f : ball)
      for (int k = 0; k < 3; ++k) {
        dt::Face* want = before[f][std::size_t(k)];
        if (f->F[k] == want) continue;
        const std::string where = inBall(want) ? "inside the ball" : "on the ball's boundary";
        FAIL_CHECK("the ball of vertex " << vid << ": " << faceName(ball, f, k) << " (" << where
                                         << ") linked to " << faceName(ball, f->F[k]) << ", expected "
                                         << faceName(ball, want));
      }
  }
}

namespace {

// Five vertices around the edge 0 - 1: 2 above it, 3 and 4 below (ids 0..4).
std::array<dt::Vertex*, 5> aroundOneEdge(dt::Triangulation& T) {
  return {T.addVertex(0, 0, 0), T.addVertex(1, 0, 1), T.addVertex(0, 1, 2), T.addVertex(0, -1, 3),
          T.addVertex(1, -1, 4)};
}

}  // namespace

TEST_CASE("2.3.4 exercise 2.3.4-1 an edge of three faces is rejected") {
  // Three faces on the edge 0 - 1, one walking it 0 -> 1 and two 1 -> 0: each pair could be
  // linked, but no manifold has three faces on one edge.
  dt::Triangulation T;
  const auto v = aroundOneEdge(T);
  for (int order = 0; order < 3; ++order) {
    std::vector<dt::Face*> three = {T.addFace(v[0], v[1], v[2]), T.addFace(v[1], v[0], v[3]), T.addFace(v[1], v[0], v[4])};
    std::rotate(three.begin(), three.begin() + order, three.end());
    INFO("faces (0 1 2), (1 0 3) and (1 0 4), the list starting at the " << order << "-th");
    CHECK_THROWS_AS(dt::computeAdjacenciesSorted(three), std::logic_error);
  }
  // Without the third face the list is a mesh: linked, no exception.
  std::vector<dt::Face*> two = {T.addFace(v[0], v[1], v[2]), T.addFace(v[1], v[0], v[4])};
  CHECK_NOTHROW(dt::computeAdjacenciesSorted(two));
  CHECK_MESSAGE(two[0]->F[0] == two[1], "faces (0 1 2) and (1 0 4) share the edge 0 - 1");
}

TEST_CASE("2.3.4 computeAdjacencies takes a third face on a linked edge for a boundary face as its header says") {
  // The header promises no error here: the map forgets the edge once two faces are linked.
  dt::Triangulation T;
  const auto v = aroundOneEdge(T);
  std::vector<dt::Face*> three = {T.addFace(v[0], v[1], v[2]), T.addFace(v[1], v[0], v[3]), T.addFace(v[0], v[1], v[4])};
  three[2]->F[0] = three[2];  // a marker: a link the call must leave as it was
  CHECK_NOTHROW(dt::computeAdjacencies(three));
  CHECK(three[0]->F[0] == three[1]);
  CHECK(three[1]->F[0] == three[0]);
  CHECK(three[2]->F[0] == three[2]);
}
