/// \file test_2_3_algorithm1.cpp Claims of the introduction of section 2.3 about Algorithm 1: it tests every triangle at every insertion.
#include <doctest/doctest.h>

#include "bowyer_watson.h"
#include "predicates.h"
#include "support.h"

TEST_CASE("2.3 Algorithm 1 tests every triangle: 2i of them at iteration i and n(n+1) in all") {
  for (std::size_t n : {10u, 100u, 1000u}) {
    CAPTURE(n);
    // Two instruments: Algorithm 1's own count of its incircle calls, and the predicate core's
    // counter of robust incircle calls (predicates.cpp), which Algorithm 1 cannot touch.
    const std::uint64_t before = dt::predicateCounters().incircle;
    const dt::BowyerWatsonResult bw = dt::bowyerWatson(dt::uniformPoints(n, 25));
    const std::uint64_t calls = dt::predicateCounters().incircle - before;
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
