/// \file test_2_2_2_exercises.cpp Exercises of section 2.2.2 (exercises/exercises.txt): the region of points that see exactly one hull edge, and the lexicographically largest vertex.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>

#include "exercises.h"
#include "hull.h"
#include "predicates.h"
#include "support.h"

namespace {

using dt::Point2;

// How many edges of the counter-clockwise polygon P the point p sees (strictly beyond the
// edge's line), and whether edge i is among them.
int seenEdges(const std::vector<Point2>& P, Point2 p, std::size_t i, bool& seesI) {
  int count = 0;
  seesI = false;
  for (std::size_t k = 0; k < P.size(); ++k) {
    const Point2 a = P[k], b = P[(k + 1) % P.size()];
    if (dt::orient2d(a.x, a.y, b.x, b.y, p.x, p.y) < 0) {
      ++count;
      seesI = seesI || k == i;
    }
  }
  return count;
}

// Brute force: is there a point far away (R times the polygon's size from edge i's midpoint, in
// one of `samples` directions) that sees edge i and no other? For an unbounded region whose
// directions to infinity span a wide enough angle, yes; for a bounded one, no.
bool farPointSeesOnly(const std::vector<Point2>& P, std::size_t i, int samples) {
  const Point2 a = P[i], b = P[(i + 1) % P.size()];
  const Point2 mid{(a.x + b.x) / 2, (a.y + b.y) / 2};
  const double R = 1e6;
  for (int k = 0; k < samples; ++k) {
    const double t = 2 * M_PI * k / samples;
    const Point2 p{mid.x + R * std::cos(t), mid.y + R * std::sin(t)};
    bool seesI = false;
    if (seenEdges(P, p, i, seesI) == 1 && seesI) return true;
  }
  return false;
}

std::vector<Point2> regular(int k, double phase) {
  std::vector<Point2> P;
  for (int j = 0; j < k; ++j)
    P.push_back({std::cos(phase + 2 * M_PI * j / k), std::sin(phase + 2 * M_PI * j / k)});
  return P;
}

// The smallest angle that decides the brute force's resolution: the turns at the edge's two
// corners, and how far the two neighbouring edges are from parallel.
double margin(const std::vector<Point2>& P, std::size_t i) {
  const std::size_t m = P.size();
  auto dir = [&](std::size_t k) {
    const Point2 a = P[k % m], b = P[(k + 1) % m];
    return std::atan2(b.y - a.y, b.x - a.x);
  };
  auto turn = [](double from, double to) {
    double d = to - from;
    while (d <= -M_PI) d += 2 * M_PI;
    while (d > M_PI) d -= 2 * M_PI;
    return d;
  };
  const double u = dir(i + m - 1), w = dir(i), v = dir(i + 1);
  return std::min({std::fabs(turn(u, w)), std::fabs(turn(w, v)),
                   std::fabs(std::fabs(turn(u, v)) - M_PI)});
}

}  // namespace

TEST_CASE("2.2.2 exercise 2.2.2-1 oneEdgeRegionBounded on squares and triangles and regular polygons") {
  const std::vector<Point2> square = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  for (std::size_t i = 0; i < 4; ++i) CHECK_FALSE(dt::oneEdgeRegionBounded(square, i));
  const std::vector<Point2> triangle = {{0, 0}, {10, 0}, {5, 0.01}};
  for (std::size_t i = 0; i < 3; ++i) CHECK_FALSE(dt::oneEdgeRegionBounded(triangle, i));
  // A trapezoid: the long base's neighbours diverge below it, the short top's meet above it,
  // and each slanted side has two parallel neighbours.
  const std::vector<Point2> trapezoid = {{0, 0}, {4, 0}, {3, 1}, {1, 1}};
  CHECK_FALSE(dt::oneEdgeRegionBounded(trapezoid, 0));
  CHECK_FALSE(dt::oneEdgeRegionBounded(trapezoid, 1));
  CHECK(dt::oneEdgeRegionBounded(trapezoid, 2));
  CHECK_FALSE(dt::oneEdgeRegionBounded(trapezoid, 3));
  for (int k = 5; k <= 9; ++k) {
    CAPTURE(k);
    const std::vector<Point2> P = regular(k, 0.3);
    for (std::size_t i = 0; i < P.size(); ++i) CHECK(dt::oneEdgeRegionBounded(P, i));
  }
  CHECK_THROWS_AS(dt::oneEdgeRegionBounded({{0, 0}, {1, 0}}, 0), std::invalid_argument);
  CHECK_THROWS_AS(dt::oneEdgeRegionBounded(square, 4), std::invalid_argument);
  // (1, 0) is a straight corner, not a strict one.
  CHECK_THROWS_AS(dt::oneEdgeRegionBounded({{0, 0}, {1, 0}, {2, 0}, {1, 1}}, 0),
                  std::invalid_argument);
}

TEST_CASE("2.2.2 exercise 2.2.2-1 the answer agrees with far sample points on random convex polygons") {
  std::mt19937_64 rng(dttest::variant(2022));
  std::uniform_real_distribution<double> angle(0, 2 * M_PI);
  int bounded = 0, unbounded = 0, skipped = 0;
  for (int trial = 0; trial < 60; ++trial) {
    // Corners on a circle at sorted random angles: a strictly convex counter-clockwise polygon.
    const int m = 3 + trial % 6;
    std::vector<double> t(m);
    for (double& x : t) x = angle(rng);
    std::sort(t.begin(), t.end());
    std::vector<Point2> P;
    for (double x : t) P.push_back({std::cos(x), std::sin(x)});
    for (std::size_t i = 0; i < P.size(); ++i) {
      // The sampling resolves angles down to about 2 pi / 20000; thinner cases are left out.
      if (margin(P, i) < 0.01) { ++skipped; continue; }
      CAPTURE(trial);
      CAPTURE(i);
      const bool b = dt::oneEdgeRegionBounded(P, i);
      CHECK(b == !farPointSeesOnly(P, i, 20000));
      ++(b ? bounded : unbounded);
    }
  }
  MESSAGE("one-edge regions: " << bounded << " bounded, " << unbounded << " unbounded, "
                               << skipped << " too thin to sample");
  CHECK(bounded >= 20);
  CHECK(unbounded >= 20);
}

// The test of a prove exercise states the claim and the idea: not in a released workspace.
// BEGIN SOLUTION 2.2.2-2 (remove)
TEST_CASE("2.2.2 exercise 2.2.2-2 a point lexicographically larger than every vertex sees an edge at the largest vertex") {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(0, 1);
  int cases = 0;
  for (int trial = 0; trial < 40; ++trial) {
    // Random points, and grids whose hulls keep straight corners as vertices.
    const dt::XY p = trial % 2 ? dt::uniformPoints(30 + trial, 100 + trial)
                               : dt::gridPoints(2 + trial % 5, 3 + trial % 4);
    dt::Triangulation T;
    dt::delaunayTrglHull(T, dt::addVertices(T, p), dt::StartRule::LastCavity);
    const std::vector<dt::Vertex*> hull = dt::convexHull(T);
    const dt::Vertex* top = *std::max_element(hull.begin(), hull.end(), [](auto* a, auto* b) {
      return a->x < b->x || (a->x == b->x && a->y < b->y);
    });
    dt::Triangulation Q;  // holds the query points only
    for (int k = 0; k < 20; ++k) {
      // Same abscissa and above, or to the right at any height.
      const double x = k % 4 == 0 ? top->x : top->x + (0.01 + u(rng)) * (k % 3 == 0 ? 1e-9 : 2);
      const double y = k % 4 == 0 ? top->y + u(rng) + 1e-12 : -3 + 6 * u(rng);
      const dt::Vertex* q = Q.addVertex(x, y, k);
      const auto seen = dt::visibleHullEdges(T, q);
      CAPTURE(trial);
      CAPTURE(x);
      CAPTURE(y);
      const bool atTop = std::any_of(seen.begin(), seen.end(), [&](const dt::HullEdge& e) {
        return e.a == top || e.b == top;
      });
      CHECK(atTop);
      ++cases;
    }
  }
  CHECK(cases == 800);
}
// END SOLUTION 2.2.2-2
