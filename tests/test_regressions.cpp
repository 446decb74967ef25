/// \file test_regressions.cpp Inputs on which the fuzz harnesses (tests/fuzz) once found a failure, replayed through the same checks, plus a direct test of each fix.
#include <doctest/doctest.h>

#include <cfloat>
#include <cmath>

#include "fuzz/fuzz_checks.h"
#include "support.h"

namespace {

std::string replayTriangulate(const std::vector<std::uint8_t>& bytes) {
  return dtfuzz::checkPointSet(dtfuzz::decodePoints(bytes.data(), bytes.size()));
}

}  // namespace

TEST_CASE("regressions fuzz 1: triangles near 1e308 made the walk's centroid overflow") {
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

TEST_CASE("regressions fuzz 2: a subnormal difference vanished in the small-multiple exact stage") {
  // fuzz_triangulate, mode 0 (raw doubles): (0, 0), (0, 8.0869e-320) and (1.3568e-312,
  // 1.0385e34). The orientation's differences 8e-320 and 1e34 were taken as multiples of
  // h = 2^89 because 8e-320 / 2^89 underflows to 0, so orient2d returned 0 instead of -1 and
  // the recovery of DT(S) by flips (2.3.6) met an edge "in conflict but not flippable".
  // Fixed in smallMultiples (predicates_inline.h): a nonzero difference that scales to 0 is
  // not a multiple of h.
  const std::vector<std::uint8_t> crash = {
      0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,
      0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,
      0x00, 0xf0, 0x3f, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,
      0x00, 0x00, 0x00, 0x00, 0x00, 0xf0, 0x3f, 0x00, 0x00, 0x00, 0x00, 0x00,
      0x00, 0xf0, 0x33, 0x00, 0xf0, 0x3f, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,
      0xe0, 0x3f, 0x00, 0x00, 0x47, 0x00, 0x00, 0x00, 0x00, 0xe0, 0x3f};
  CHECK(replayTriangulate(crash) == "");
  const double tiny = 8.0868664911295234e-320, x = 1.3567511245393893e-312, y = 1.038522630442973e34;
  CHECK(dt::orient2dExact(0, tiny, x, y, 0, 0) == -1);
  CHECK(dt::orient2d(0, tiny, x, y, 0, 0) == -1);
  CHECK(dt::orient2d(x, y, 0, tiny, 0, 0) == 1);
}

TEST_CASE("regressions oracle 1: a lattice rectangle near 2^255 overflowed incircle's semi-static filter") {
  // Found by the independent oracle (tests/oracle.h, 2.3.1 exactness tests): the four corners
  // of a rectangle, exactly cocircular. M (the largest difference) is about 2^256, M^4 is still
  // finite, but a lift times a minor overflowed to -infinity, and -det > 134u M^4 held: the
  // filter answered -1. Fixed by requiring M < 2^254 in that filter (predicates_inline.h).
  const double v[8] = {0x1.8p+249, -0x1.2b8p+255, 0x1.a8p+255, -0x1.2b8p+255,
                       0x1.8p+249, 0x1.69p+254,   0x1.a8p+255, 0x1.69p+254};
  CHECK(dt::incircle(v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7]) == 0);
  CHECK(dt::incircleExact(v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7]) == 0);
  // The same rectangle at every scale up to overflow: never a wrong sign.
  for (int e = 200; e <= 766; ++e) {
    CAPTURE(e);
    double w[8];
    for (int i = 0; i < 8; ++i) w[i] = std::ldexp(v[i], e - 255);
    CHECK(dt::incircle(w[0], w[1], w[2], w[3], w[4], w[5], w[6], w[7]) == 0);
  }
}

TEST_CASE("regressions mutant parser-short-line: a .node line with too few fields is refused") {
  // scripts/mutants.sh showed no test gave the parser a short point line: a parser that
  // accepted one (reading fields that are not there) survived. Here it must name the line.
  const std::string in = dttest::tmpPath("short_line.node");
  dttest::writeText(in, "3 2 0 0\n0 0 0\n1 1\n2 0 1\n");
  const dttest::CliResult r = dttest::runCli("'" + in + "' -o '" + dttest::tmpPath("short_line_out") + "'");
  CHECK(r.status != 0);
  CHECK(r.err.find("short_line.node") != std::string::npos);
  CHECK(r.err.find(":3") != std::string::npos);
  CHECK(r.err.find("field") != std::string::npos);
}
