/// \file test_2_3_2_exercises.cpp Exercise 2.3.2-3 (exercises/exercises.txt): the counts of points in convex position, and the fan of a parabola.
#include <doctest/doctest.h>

#include <algorithm>

#include "stats.h"
#include "support.h"

namespace {

// BEGIN SOLUTION 2.3.2-3 (remove)
// DT(S) of the points (i, i^2), i = 0..n-1 (exact doubles, all in convex position), inserted in
// a shuffled order, checked exactly and counted.
dt::MeshCounts parabolaCounts(int n) {
  dt::XY p;
  for (int i = 0; i < n; ++i) {
    p.push_back(i);
    p.push_back(double(i) * i);
  }
  dttest::shuffle(p, unsigned(n));
  dt::Triangulation T;
  dt::delaunayTrglHull(T, dt::addVertices(T, p), dt::StartRule::LastCavity);
  REQUIRE(dt::checkTriangulation(T).ok);
  const dt::PlainMesh m = dt::extractMesh(T, true);
  REQUIRE(dt::checkDelaunay(m.xy, m.tri).ok);
  return dt::meshCounts(m.xy.size() / 2, m.tri);
}
// END SOLUTION 2.3.2-3

}  // namespace

// The tests state the answers: not in a released workspace.
// BEGIN SOLUTION 2.3.2-3 (remove)
TEST_CASE("2.3.2 exercise 2.3.2-3 the counts of points in convex position") {
  for (int n : {3, 4, 5, 10, 57, 300}) {
    CAPTURE(n);
    const dt::MeshCounts c = parabolaCounts(n);
    CHECK(c.n == n);
    CHECK(c.nh == n);  // every point on the hull
    CHECK(c.sumVF == 3L * n - 6);  // n_vf = 3 - 6/n
    CHECK(c.sumVE == 4L * n - 6);  // n_ve = 4 - 6/n
  }
}

TEST_CASE("2.3.2 exercise 2.3.2-3 the largest number of triangles at one vertex") {
  for (int n : {3, 4, 5, 10, 57, 300}) {
    CAPTURE(n);
    const dt::MeshCounts c = parabolaCounts(n);
    CHECK(c.nf == n - 2);
    CHECK(*std::max_element(c.vf.begin(), c.vf.end()) == n - 2);
  }
}
// END SOLUTION 2.3.2-3
