/// \file test_2_3_2_exercises.cpp Exercise 2.3.2-3 (exercises/exercises.txt): the counts of points in convex position, and the fan of a parabola.
#include <doctest/doctest.h>

#include <algorithm>

#include "stats.h"
#include "support.h"

namespace {

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

}  // namespace

TEST_CASE("2.3.2 exercise 2.3.2-3 points in convex position have n n_vf = 3n - 6 and n n_ve = 4n - 6") {
  for (int n : {3, 4, 5, 10, 57, 300}) {
    CAPTURE(n);
    const dt::MeshCounts c = parabolaCounts(n);
    CHECK(c.n == n);
    CHECK(c.nh == n);  // every point on the hull
    CHECK(c.sumVF == 3L * n - 6);  // n_vf = 3 - 6/n
    CHECK(c.sumVE == 4L * n - 6);  // n_ve = 4 - 6/n
  }
}

TEST_CASE("2.3.2 exercise 2.3.2-3 on a parabola one vertex belongs to all n - 2 triangles") {
  for (int n : {3, 4, 5, 10, 57, 300}) {
    CAPTURE(n);
    const dt::MeshCounts c = parabolaCounts(n);
    CHECK(c.nf == n - 2);
    CHECK(*std::max_element(c.vf.begin(), c.vf.end()) == n - 2);
  }
}
