/// \file test_2_3_algorithm1.cpp Claims of the introduction of section 2.3 (and of 2.3.1) about Algorithm 1: it tests every triangle at every insertion, precomputed circumcircles leave it quadratic, a naive circle test produces invalid meshes, and random perturbation rescues it only above some size.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <random>
#include <utility>
#include <vector>

#include "bowyer_watson.h"
#include "check.h"
#include "predicates.h"
#include "support.h"

TEST_CASE("2.3 Algorithm 1 tests every triangle: 2i of them at iteration i and n(n+1) in all") {
  for (std::size_t n : {10u, 100u, 1000u}) {
    CAPTURE(n);
    // Two instruments: Algorithm 1's own count of its incircle calls, and the predicate core's
    // counter of robust incircle calls (predicates.cpp), which Algorithm 1 cannot touch.
    const std::uint64_t before = dt::predicateCounters().incircle.calls();
    const dt::BowyerWatsonResult bw = dt::bowyerWatson(dt::uniformPoints(n, 25));
    const std::uint64_t calls = dt::predicateCounters().incircle.calls() - before;
    // DT_{i-1} has 2 + 2(i-1) = 2i triangles (each insertion adds |C|+2 and removes |C|).
    CHECK(bw.incircleTests == n * (n + 1));
    CHECK(calls == n * (n + 1));
    CHECK(bw.tri.size() == 2 + 2 * n);
  }
  // Per iteration: inserting the i-th point makes exactly 2i calls.
  const dt::XY p = dt::uniformPoints(30, 26);
  dt::BowyerWatsonResult prev = dt::bowyerWatson(dt::XY(p.begin(), p.begin() + 2));
  for (std::size_t i = 2; i <= 30; ++i) {
    const dt::BowyerWatsonResult bw = dt::bowyerWatson(dt::XY(p.begin(), p.begin() + long(2 * i)));
    CHECK(bw.incircleTests - prev.incircleTests == 2 * i);
    prev = bw;
  }
}

namespace {

// Algorithm 1 on a plain triangle list with the circle test as a parameter, so that the same
// loop runs with the exact, the naive and a precomputed-circumcircle test. DT_0 is the two
// super-triangles p-1 p-2 p-3 and p-2 p-1 p-4 of a square 10 times the points' box. Returns the
// triangles of DT(S u S0) over the points p-1..p-4 (indices 0..3) then S (4..), and counts the
// circle tests made.
struct Tri3 {
  int v[3];
  double cx, cy, r2;  // the circumcircle in floating point (only the precomputed test reads it)
};
using CircleTest = std::function<bool(const dt::XY&, const Tri3&, int)>;

std::vector<dt::Tri> algorithm1(const dt::XY& p, const CircleTest& inside, std::uint64_t& tests,
                                dt::XY& xy) {
  double lo = p[0], hi = p[0];
  for (double v : p) lo = std::min(lo, v), hi = std::max(hi, v);
  const double c = 0.5 * (lo + hi), R = 10 * (hi - lo + 1);
  xy = {c - R, c - R, c + R, c + R, c - R, c + R, c + R, c - R};
  xy.insert(xy.end(), p.begin(), p.end());
  auto make = [&xy](int a, int b, int d) {
    Tri3 t{{a, b, d}, 0, 0, 0};
    const double ax = xy[2 * a], ay = xy[2 * a + 1], bx = xy[2 * b] - ax, by = xy[2 * b + 1] - ay;
    const double dx = xy[2 * d] - ax, dy = xy[2 * d + 1] - ay, den = 2 * (bx * dy - by * dx);
    const double ux = (dy * (bx * bx + by * by) - by * (dx * dx + dy * dy)) / den;
    const double uy = (bx * (dx * dx + dy * dy) - dx * (bx * bx + by * by)) / den;
    t.cx = ax + ux, t.cy = ay + uy, t.r2 = ux * ux + uy * uy;
    return t;
  };
  std::vector<Tri3> tri = {make(0, 1, 2), make(1, 0, 3)};
  for (int ip = 4; ip < int(xy.size() / 2); ++ip) {
    std::vector<Tri3> kept, cavity;
    for (const Tri3& t : tri) {
      ++tests;
      (inside(xy, t, ip) ? cavity : kept).push_back(t);
    }
    std::vector<std::pair<int, int>> edges;
    for (const Tri3& t : cavity)
      for (int k = 0; k < 3; ++k) edges.emplace_back(t.v[k], t.v[(k + 1) % 3]);
    std::sort(edges.begin(), edges.end());
    for (const auto& [a, b] : edges)
      if (!std::binary_search(edges.begin(), edges.end(), std::make_pair(b, a)))
        kept.push_back(make(a, b, ip));
    tri = kept;
    // A triangulation of N points has at most 2N - 5 triangles: beyond that the cavities were
    // not disks and the list only grows; stop (the validator rejects what is returned).
    if (tri.size() > xy.size()) break;
  }
  std::vector<dt::Tri> out;
  for (const Tri3& t : tri) out.push_back({t.v[0], t.v[1], t.v[2]});
  return out;
}

const CircleTest kExact = [](const dt::XY& xy, const Tri3& t, int p) {
  auto X = [&](int i) { return xy[2 * i]; };
  auto Y = [&](int i) { return xy[2 * i + 1]; };
  return dt::incircle(X(t.v[0]), Y(t.v[0]), X(t.v[1]), Y(t.v[1]), X(t.v[2]), Y(t.v[2]), X(p), Y(p)) > 0;
};
const CircleTest kNaive = [](const dt::XY& xy, const Tri3& t, int p) {
  auto X = [&](int i) { return xy[2 * i]; };
  auto Y = [&](int i) { return xy[2 * i + 1]; };
  return dt::incircleNaive(X(t.v[0]), Y(t.v[0]), X(t.v[1]), Y(t.v[1]), X(t.v[2]), Y(t.v[2]), X(p), Y(p)) > 0;
};
const CircleTest kPrecomputed = [](const dt::XY& xy, const Tri3& t, int p) {
  const double dx = xy[2 * p] - t.cx, dy = xy[2 * p + 1] - t.cy;
  return dx * dx + dy * dy < t.r2;
};

// n points on the unit circle, rounded, and its centre: near-cocircular everywhere.
dt::XY roundedCircle(int n) {
  dt::XY p;
  for (int i = 0; i < n; ++i) p.insert(p.end(), {std::cos(2 * M_PI * i / n), std::sin(2 * M_PI * i / n)});
  p.insert(p.end(), {0.0, 0.0});
  return p;
}

}  // namespace

TEST_CASE("2.3.1 Algorithm 1 with the naive incircle test produces an invalid mesh that the validator catches") {
  // "Bowyer-Watson algorithm 1 that uses a non robust circle test can possibly produce invalid
  // meshes": the same loop, the same points, only the circle test differs.
  int invalid = 0;
  for (int n : {64, 100, 256, 360}) {
    CAPTURE(n);
    const dt::XY p = roundedCircle(n);
    std::uint64_t tests = 0;
    dt::XY xy;
    const auto exact = algorithm1(p, kExact, tests, xy);
    const dt::CheckReport good = dt::checkDelaunay(xy, exact);
    CHECK_MESSAGE(good.ok, good.error);
    const auto naive = algorithm1(p, kNaive, tests, xy);
    const dt::CheckReport bad = dt::checkDelaunay(xy, naive);
    MESSAGE(n << " points on a circle and its centre, naive incircle: "
              << (bad.ok ? std::string("valid") : bad.error));
    invalid += !bad.ok;
  }
  CHECK(invalid >= 2);
}

TEST_CASE("2.3 Algorithm 1 with precomputed circumcircles is still quadratic") {
  // "Centers of circumcircles could be computed in advance ... this approach remains quadratic":
  // a stored centre and radius make each test 5 operations instead of incircle's 29, but the
  // loop still tests every triangle: n(n+1) tests, 4 times as many for twice the points.
  std::uint64_t previous = 0;
  for (std::size_t n : {250u, 500u, 1000u}) {
    CAPTURE(n);
    const dt::XY p = dt::uniformPoints(n, 27);
    std::uint64_t exactTests = 0, preTests = 0;
    dt::XY xy;
    const auto exact = algorithm1(p, kExact, exactTests, xy);
    const auto pre = algorithm1(p, kPrecomputed, preTests, xy);
    CHECK(dt::checkDelaunay(xy, pre).ok);  // random points: the rounded circles decide right
    std::vector<long> ids(xy.size() / 2);
    for (std::size_t i = 0; i < ids.size(); ++i) ids[i] = long(i);
    CHECK(dt::canonicalTriangles(ids, pre) == dt::canonicalTriangles(ids, exact));
    // The library's Algorithm 1 (code/listings/bowyer_watson.cpp) counts its own incircle calls: the
    // same n(n+1), whatever a single test costs (2 + 2k triangles at step k, each tested).
    const dt::BowyerWatsonResult bw = dt::bowyerWatson(p);
    CHECK(bw.incircleTests == n * (n + 1));
    CHECK(preTests == bw.incircleTests);
    CHECK(exactTests == preTests);
    if (previous) CHECK(double(preTests) / double(previous) > 3.98);
    previous = preTests;
  }
}

TEST_CASE("2.3 random perturbation rescues the naive Algorithm 1 only above a size that depends on the input") {
  // "One solution is to randomly perturbate the position of the points ... the question is what
  // is the smallest perturbation": the rounded circle of the previous test, each coordinate moved
  // by a random relative amount delta. Tiny moves leave the naive test's errors decisive; large
  // ones make every quadruple far from cocircular and the naive run valid.
  const dt::XY base = roundedCircle(256);
  auto perturbed = [&](double delta, unsigned seed) {
    dt::XY p = base;
    std::mt19937_64 g(seed);
    std::uniform_real_distribution<double> u(-1, 1);
    for (double& v : p) v += delta * u(g);
    return p;
  };
  auto naiveValid = [](const dt::XY& p) {
    std::uint64_t tests = 0;
    dt::XY xy;
    const auto tri = algorithm1(p, kNaive, tests, xy);
    return dt::checkDelaunay(xy, tri).ok;
  };
  int smallOk = 0, largeOk = 0;
  for (unsigned seed = 1; seed <= 4; ++seed) {
    smallOk += naiveValid(perturbed(1e-15, seed));
    largeOk += naiveValid(perturbed(1e-3, seed));
  }
  MESSAGE("naive Algorithm 1 valid after a perturbation of 1e-15: " << smallOk << " of 4; of 1e-3: " << largeOk << " of 4");
  CHECK(smallOk < 4);
  CHECK(largeOk == 4);
}
