/// \file test_2_3_algorithm1.cpp Claims of the introduction of section 2.3 (and of 2.3.1) about Algorithm 1: it tests every triangle at every insertion, precomputed circumcircles leave it quadratic, a naive circle test produces invalid meshes, and random perturbation rescues it only above some size.
#include <doctest/doctest.h>

#include <cmath>
#include <random>
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
    const dt::BowyerWatsonResult exact = dt::bowyerWatson(p);
    const dt::CheckReport good = dt::checkDelaunay(exact.xy, exact.tri);
    CHECK_MESSAGE(good.ok, good.error);
    const dt::BowyerWatsonResult naive = dt::bowyerWatson(p, 10.0, dt::CircleTest::Naive);
    const dt::CheckReport bad = dt::checkDelaunay(naive.xy, naive.tri);
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
    // The library's Algorithm 1 (code/listings/bowyer_watson.cpp), with the exact test and with
    // stored circles; the predicate core's counter sees the exact test's calls, not the stored.
    const std::uint64_t before = dt::predicateCounters().incircle.calls();
    const dt::BowyerWatsonResult exact = dt::bowyerWatson(p);
    const std::uint64_t exactCalls = dt::predicateCounters().incircle.calls() - before;
    const dt::BowyerWatsonResult pre = dt::bowyerWatson(p, 10.0, dt::CircleTest::Stored);
    CHECK(dt::predicateCounters().incircle.calls() - before == exactCalls);
    CHECK(dt::checkDelaunay(pre.xy, pre.tri).ok);  // random points: the rounded circles decide right
    CHECK(dt::canonicalTriangles(pre.ids, pre.tri) == dt::canonicalTriangles(exact.ids, exact.tri));
    // Every triangle of DT_{k-1} still tested at step k: 2 + 2(k-1) of them, n(n+1) in all,
    // whatever a single test costs.
    const std::uint64_t preTests = pre.incircleTests;
    CHECK(exactCalls == n * (n + 1));
    CHECK(preTests == n * (n + 1));
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
    const dt::BowyerWatsonResult r = dt::bowyerWatson(p, 10.0, dt::CircleTest::Naive);
    return dt::checkDelaunay(r.xy, r.tri).ok;
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
