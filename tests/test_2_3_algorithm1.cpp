/// \file test_2_3_algorithm1.cpp Claims of the introduction of section 2.3 about Algorithm 1: it tests every triangle at every insertion.
#include <doctest/doctest.h>

#include "bowyer_watson.h"
#include "support.h"

TEST_CASE("2.3 Algorithm 1 tests every triangle: 2i of them at iteration i and n(n+1) in all") {
  for (std::size_t n : {10u, 100u, 1000u}) {
    const dt::BowyerWatsonResult bw = dt::bowyerWatson(dt::uniformPoints(n, 25));
    // DT_{i-1} has 2 + 2(i-1) = 2i triangles (each insertion adds |C|+2 and removes |C|).
    CHECK(bw.incircleTests == n * (n + 1));
    CHECK(bw.tri.size() == 2 + 2 * n);
  }
}
