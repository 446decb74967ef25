/// \file test_regressions.cpp Inputs on which the fuzz harnesses (tests/fuzz) once found a failure, replayed through the same checks, plus a direct test of each fix.
#include <doctest/doctest.h>

#include <cfloat>
#include <cmath>

#include "fuzz/fuzz_checks.h"

namespace {

std::string replayTriangulate(const std::vector<std::uint8_t>& bytes) {
  return dtfuzz::checkPointSet(dtfuzz::decodePoints(bytes.data(), bytes.size()));
}

}  // namespace

TEST_CASE("fuzz regression 1: triangles near 1e308 made the walk's centroid overflow") {
  // fuzz_triangulate, mode 2 (small integers times 2^1022): the centroid of Listing 2.6's walk
  // summed three coordinates of about 2^1023 to infinity, and the exact orientation test then
  // received a non-finite point (GMP aborts on it). Fixed in Face::centroid (mesh.cpp).
  const std::vector<std::uint8_t> crash = {0x02, 0x30, 0x08, 0x00, 0x00, 0x01, 0x00, 0x00, 0x01,
                                           0x01, 0x01, 0x02, 0x03, 0xff, 0xfe, 0x05, 0x05};
  const dtfuzz::XY p = dtfuzz::decodePoints(crash.data(), crash.size());
  REQUIRE(p.size() == 12);  // 6 finite points; (5, 5) 2^1022 overflows and is dropped
  CHECK(std::fabs(p[6]) == std::ldexp(1.0, 1022));
  CHECK(replayTriangulate(crash) == "");
  // The fix itself: the centroid of a face with coordinates near DBL_MAX is finite and inside.
  dt::Vertex a(DBL_MAX, DBL_MAX), b(-DBL_MAX, DBL_MAX), c(DBL_MAX, -DBL_MAX);
  const dt::Face f(&a, &b, &c);
  const dt::Vertex g = f.centroid();
  CHECK(std::isfinite(g.x));
  CHECK(std::isfinite(g.y));
  CHECK(dt::orientationTest(&a, &b, &g) > 0);
  CHECK(dt::orientationTest(&b, &c, &g) > 0);
  CHECK(dt::orientationTest(&c, &a, &g) > 0);
}
