/// \file test_2_3_6_exercises.cpp Exercises of section 2.3.6 (exercises/exercises.txt): where 2.2.1's flips are stuck, and what a flip makes of the new edge.
#include <doctest/doctest.h>

#include <random>

#include "exercises.h"
#include "flip.h"
#include "predicates.h"
#include "support.h"

namespace {

// DT(S0 ∪ S) for the example, then the recovery by `rule`.
dt::FlipStats recover(dt::Triangulation& T, const dt::StuckRecovery& ex, dt::RecoveryRule rule) {
  double xmin = ex.xy[0], xmax = ex.xy[0], ymin = ex.xy[1], ymax = ex.xy[1];
  for (std::size_t i = 0; i < ex.xy.size(); i += 2) {
    xmin = std::min(xmin, ex.xy[i]); xmax = std::max(xmax, ex.xy[i]);
    ymin = std::min(ymin, ex.xy[i + 1]); ymax = std::max(ymax, ex.xy[i + 1]);
  }
  dt::initSuperTriangles(T, xmin, ymin, xmax, ymax, ex.factor);
  dt::delaunayTrgl(T, dt::addVertices(T, ex.xy), dt::StartRule::LastCavity);
  return dt::recoverDelaunay(T, rule);
}

}  // namespace

TEST_CASE("2.3.6 exercise 2.3.6-1 three points where the notes' flips are stuck and the completed rule is not") {
  const dt::StuckRecovery ex = dt::stuckRecoveryExample();
  REQUIRE(ex.xy.size() == 6);  // three points: with two super vertices, five in all
  const double* p = ex.xy.data();
  REQUIRE(dt::orient2d(p[0], p[1], p[2], p[3], p[4], p[5]) != 0);
  dt::Triangulation N;
  const dt::FlipStats notes = recover(N, ex, dt::RecoveryRule::NotesOnly);
  CHECK(notes.flips == 0);  // stuck: no edge qualifies for 2.2.1's rule
  // Without the super faces nothing of DT(S), a single triangle, is left.
  CHECK(dt::extractMesh(N, true).tri.empty());
  dt::Triangulation F;
  const dt::FlipStats full = recover(F, ex, dt::RecoveryRule::Full);
  CHECK(full.flips > 0);
  CHECK(dt::checkTriangulation(F).ok);
  const dt::PlainMesh m = dt::extractMesh(F, false);
  CHECK(m.tri.size() == 1);
  CHECK(dt::checkDelaunay(m.xy, m.tri).ok);
}

// The test of a prove exercise states the claim and the idea: not in a released workspace.
// BEGIN SOLUTION 2.3.6-2 (remove)
TEST_CASE("2.3.6 exercise 2.3.6-2 after a flip of a non-locally-Delaunay edge the new edge is locally Delaunay") {
  // Triangles (a, b, c) and (b, a, d) with d strictly inside the circle of (a, b, c): the flip
  // makes (c, a, d) and (d, b, c); then b is strictly outside the circle of (c, a, d) and a
  // strictly outside that of (d, b, c). Random and nearly cocircular quadruples.
  std::mt19937_64 rng(236);
  std::uniform_real_distribution<double> u(-1, 1);
  int flips = 0;
  for (int trial = 0; trial < 1000000 && flips < 20000; ++trial) {
    double q[8];
    for (double& x : q) x = u(rng);
    if (trial % 2) {  // four points within 1e-12 of the unit circle
      for (int k = 0; k < 4; ++k) {
        const double t = 3.2 * (u(rng) + 1);
        q[2 * k] = std::cos(t) + 1e-12 * u(rng);
        q[2 * k + 1] = std::sin(t) + 1e-12 * u(rng);
      }
    }
    const double *a = q, *b = q + 2, *c = q + 4, *d = q + 6;
    if (dt::orient2d(a[0], a[1], b[0], b[1], c[0], c[1]) <= 0) continue;  // (a, b, c) ccw
    if (dt::orient2d(b[0], b[1], a[0], a[1], d[0], d[1]) <= 0) continue;  // (b, a, d) ccw
    if (dt::incircle(a[0], a[1], b[0], b[1], c[0], c[1], d[0], d[1]) <= 0) continue;
    ++flips;
    CAPTURE(trial);
    // Flippable: both new triangles turn left (the page's argument).
    CHECK(dt::orient2d(c[0], c[1], a[0], a[1], d[0], d[1]) > 0);
    CHECK(dt::orient2d(d[0], d[1], b[0], b[1], c[0], c[1]) > 0);
    CHECK(dt::incircle(c[0], c[1], a[0], a[1], d[0], d[1], b[0], b[1]) < 0);
    CHECK(dt::incircle(d[0], d[1], b[0], b[1], c[0], c[1], a[0], a[1]) < 0);
  }
  MESSAGE(flips << " non-locally-Delaunay edges flipped");
  CHECK(flips >= 20000);
}
// END SOLUTION 2.3.6-2
