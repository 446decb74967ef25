/// \file test_errata.cpp Regression tests for errors of the printed listings that the other test files do not pin (linked from the errata page).
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>

#include "cavity.h"
#include "hilbert.h"
#include "predicates.h"
#include "search.h"
#include "support.h"

using namespace dt;
using dt::XY;

namespace {

// One step of Listing 2.6 exactly as printed: the neighbour across the first edge that the
// segment centroid -> v crosses strictly (both products < 0), or -1 if there is none, in which
// case the printed `while (1)` loop runs again on the same face, forever.
int printedLineSearchStep(const Face& f, const Vertex& v) {
  const Vertex c = f.centroid();
  for (int k = 0; k < 3; ++k) {
    const Edge e = f.getEdge(k);
    if (orientationTest(&c, &v, e.vmin) * orientationTest(&c, &v, e.vmax) < 0 &&
        orientationTest(e.vmin, e.vmax, &c) * orientationTest(e.vmin, e.vmax, &v) < 0)
      return k;
  }
  return -1;
}

}  // namespace

TEST_CASE("errata Listing 2.6: the printed walk has no exit when its line passes through a vertex") {
  // Face (0,0) (3,0) (0,3): centroid (1,1), computed exactly. The line from (1,1) to v = (7,-2)
  // runs through the vertex (3,0); v is outside the circumcircle (centre (1.5,1.5), r^2 = 4.5).
  Triangulation T;
  Vertex* a = T.addVertex(0, 0, 0);
  Vertex* b = T.addVertex(3, 0, 1);
  Vertex* c = T.addVertex(0, 3, 2);
  Vertex* v = T.addVertex(7, -2, 3);
  delaunayTrglHull(T, {a, b, c}, StartRule::FirstFace);
  Face* f = &T.faces().front();
  REQUIRE_FALSE(f->isGhost());
  REQUIRE_FALSE(f->inCircle(v));
  CHECK(orientationTest(a, b, c) > 0);
  const Vertex cen = f->centroid();
  CHECK(orientationTest(&cen, v, b) == 0);  // the line goes through the vertex (3,0)
  CHECK(printedLineSearchStep(*f, *v) == -1);  // the printed loop would spin on f
  // The corrected walk leaves f and finds a face in conflict with v (here a ghost face).
  SearchInfo info;
  info.maxSteps = T.faces().size() + 1;
  Face* seed = lineSearch(f, v, &info);
  REQUIRE(seed != nullptr);
  CHECK(seed->inCircle(v));
  CHECK(info.steps == 2);
  InsertionStats st;
  InsertionScratch scratch;
  CHECK(insertVertex(T, f, v, st, scratch) != nullptr);
  const CheckReport r = checkTriangulation(T);
  CHECK_MESSAGE(r.ok, r.error);
}

TEST_CASE("errata Listing 2.7: faces across the cavity boundary are not left marked deleted") {
  // Listing 2.5 marks the faces of otherSide as deleted; the printed Listing 2.7 never clears
  // the mark, so a later cavity stops at them. After every insertion no face may stay marked.
  XY p = dt::uniformPoints(2000, 23);
  Triangulation T;
  std::vector<Vertex*> S;
  for (std::size_t i = 0; i < p.size() / 2; ++i) S.push_back(T.addVertex(p[2 * i], p[2 * i + 1], long(i)));
  initSuperTriangles(T, 0, 0, 1, 1);
  InsertionStats st;
  InsertionScratch scratch;
  Face* last = &T.faces().front();
  std::size_t marked = 0, otherSideSeen = 0;
  for (Vertex* s : S) {
    last = insertVertex(T, last, s, st, scratch);
    REQUIRE(last != nullptr);
    otherSideSeen += scratch.otherSide.size();
    for (const Face& g : T.faces()) marked += g.deleted ? 1 : 0;
  }
  CHECK(otherSideSeen > 0);  // the situation did arise
  CHECK(marked == 0);
  const CheckReport r = checkTriangulation(T);
  CHECK_MESSAGE(r.ok, r.error);
}

TEST_CASE("errata Listing 2.7: every face of every Delaunay ball is counter-clockwise") {
  // The printed Edge keeps only (vmin, vmax) sorted by address, which loses the orientation of
  // the boundary edge; a ball built from it has about half its faces clockwise.
  XY p = dt::gridPoints(15, 15);
  dt::shufflePoints(p, 9);
  Triangulation T;
  std::vector<Vertex*> S;
  for (std::size_t i = 0; i < p.size() / 2; ++i) S.push_back(T.addVertex(p[2 * i], p[2 * i + 1], long(i)));
  initSuperTriangles(T, 0, 0, 14, 14);
  InsertionStats st;
  InsertionScratch scratch;
  Face* last = &T.faces().front();
  std::size_t clockwise = 0, built = 0;
  for (Vertex* s : S) {
    last = insertVertex(T, last, s, st, scratch);
    REQUIRE(last != nullptr);
    for (std::size_t i = 0; i < scratch.bnd.size(); ++i) {
      const Edge& e = scratch.bnd[i];
      ++built;
      if (orientationTest(e.V[0], e.V[1], s) <= 0) ++clockwise;
    }
  }
  CHECK(built == st.cavityFaces + 2 * st.insertions);  // |ball| = |C| + 2 at every insertion
  CHECK(clockwise == 0);
  std::size_t sortedWouldBeClockwise = 0;
  for (const Face* f : T.finiteFaces())
    for (int k = 0; k < 3; ++k) {
      const Edge e = f->getEdge(k);
      if (orientationTest(e.vmin, e.vmax, f->V[(k + 2) % 3]) < 0) ++sortedWouldBeClockwise;
    }
  // Rebuilding each face from its edges in the printed (vmin, vmax) order would reverse many.
  CHECK(sortedWouldBeClockwise > T.numFiniteFaces() / 2);
  CHECK(checkTriangulation(T).ok);
}

TEST_CASE("errata 2.3.5: a depth-d Hilbert coordinate has d digits k_0..k_{d-1} and not d+1") {
  // The notes write (k_0, k_1, ..., k_d); Listing 2.8 fills bits[0..d-1] only.
  int bits[9];
  std::fill(bits, bits + 9, -7);
  HilbertCoord(0.3, 0.8, 0.5, 0.5, 0.5, 0, 0, 0.5, 8, bits);
  for (int i = 0; i < 8; ++i) {
    CHECK(bits[i] >= 0);
    CHECK(bits[i] <= 3);
  }
  CHECK(bits[8] == -7);
}

TEST_CASE("errata 2.3.1: O(c b a) is -O(a b c) and not the same value") {
  // The notes say the two maps "should be the same"; swapping two points is an odd
  // permutation of the determinant's rows. Exact signs on the notes' own example.
  const double eps = std::ldexp(1.0, -53);
  int opposite = 0, cells = 0;
  for (int i = 0; i < 64; ++i)
    for (int j = 0; j < 64; ++j) {
      const double ax = 0.5 + i * eps, ay = 0.5 + j * eps;
      const int abc = orient2dExact(ax, ay, 12, 12, 24, 24);
      const int cba = orient2dExact(24, 24, 12, 12, ax, ay);
      ++cells;
      if (abc == -cba) ++opposite;
    }
  CHECK(opposite == cells);
  CHECK(orient2dExact(0.5 + eps, 0.5, 12, 12, 24, 24) != 0);  // off the diagonal: nonzero
}
