/// \file test_2_3_5_exercises.cpp Exercises of section 2.3.5 (exercises/exercises.txt): the four frames of Listing 2.8, the bottom row of H_k, points on a circle, the first BRIO rounds, and the Hilbert index without branches. The tests of the prove and measure exercises state their answers: they sit in solution regions that a released workspace does not have.
#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <set>
#include <vector>

#include "exercises.h"
#include "hilbert.h"
#include "support.h"

namespace {

// BEGIN SOLUTION 2.3.5-1 (remove)
// The frame of a quadrant relative to the root (red = +x, blue = +y), as the signs of its
// halved vectors: (red.x, red.y, blue.x, blue.y), each in {-1, 0, 1}.
std::array<int, 4> shape(const dt::HilbertFrame& f) {
  auto s = [](double v) { return (v > 0) - (v < 0); };
  return {s(f.xRed), s(f.yRed), s(f.xBlue), s(f.yBlue)};
}

void collectFrames(const dt::HilbertFrame& f, int depth, std::set<std::array<int, 4>>& seen,
                   bool& lengthsOk, double half) {
  seen.insert(shape(f));
  lengthsOk = lengthsOk && std::fabs(f.xRed) + std::fabs(f.yRed) == half &&
              std::fabs(f.xBlue) + std::fabs(f.yBlue) == half;
  if (depth == 0) return;
  for (int q = 0; q < 4; ++q) collectFrames(dt::hilbertChild(f, q), depth - 1, seen, lengthsOk, half / 2);
}
// END SOLUTION 2.3.5-1

// BEGIN SOLUTION 2.3.5-3 (remove)
// Table 2.2's setting (super-triangles, walk from the last cavity), checked exactly; N_cavity.
double meanCavity(const dt::XY& p, const std::vector<std::size_t>& order) {
  double xmin = p[0], xmax = p[0], ymin = p[1], ymax = p[1];
  for (std::size_t i = 0; i < p.size(); i += 2) {
    xmin = std::min(xmin, p[i]); xmax = std::max(xmax, p[i]);
    ymin = std::min(ymin, p[i + 1]); ymax = std::max(ymax, p[i + 1]);
  }
  dt::Triangulation T;
  dt::initSuperTriangles(T, xmin, ymin, xmax, ymax);
  std::vector<dt::Vertex*> S;
  for (std::size_t k : order) S.push_back(T.addVertex(p[2 * k], p[2 * k + 1], long(k)));
  dt::InsertionStats st;
  dt::delaunayTrgl(T, S, dt::StartRule::LastCavity, &st);
  REQUIRE(dt::checkTriangulation(T).ok);
  return st.meanCavity();
}
// END SOLUTION 2.3.5-3

}  // namespace

// BEGIN SOLUTION 2.3.5-1 (remove)
TEST_CASE("2.3.5 exercise 2.3.5-1 every quadrant frame is the root frame swapped or negated or both") {
  const dt::HilbertFrame root{0.5, 0.5, 0.5, 0, 0, 0.5};
  std::set<std::array<int, 4>> seen;
  bool lengthsOk = true;
  collectFrames(root, 6, seen, lengthsOk, 0.5);  // 5461 quadrants
  const std::set<std::array<int, 4>> four = {
      {1, 0, 0, 1}, {0, 1, 1, 0}, {-1, 0, 0, -1}, {0, -1, -1, 0}};
  CHECK(seen == four);
  CHECK(lengthsOk);  // each vector is axis-parallel with the quadrant's half-size
}
// END SOLUTION 2.3.5-1

// BEGIN SOLUTION 2.3.5-2 (remove)
TEST_CASE("2.3.5 exercise 2.3.5-2 the bottom row of H_k is visited from left to right") {
  for (int k = 1; k <= 10; ++k) {
    CAPTURE(k);
    const std::uint32_t side = 1u << k;
    bool increasing = true;
    for (std::uint32_t i = 0; i + 1 < side; ++i)
      increasing = increasing && dt::hilbertIndex(i, 0, k) < dt::hilbertIndex(i + 1, 0, k);
    CHECK(increasing);
    // And it is the curve's first cell and last cell.
    CHECK(dt::hilbertIndex(0, 0, k) == 0);
    CHECK(dt::hilbertIndex(side - 1, 0, k) == (std::uint64_t(1) << (2 * k)) - 1);
  }
}
// END SOLUTION 2.3.5-2

// BEGIN SOLUTION 2.3.5-3 (remove)
TEST_CASE("2.3.5 exercise 2.3.5-3 N_cavity of points on a circle in Hilbert order and BRIO") {
  // Measured spread (sec2_3_5_hilbert, table_brio, circle rows; seeds 1-3, n = 10^3..1.6 10^4):
  // Hilbert 3.3-3.9, BRIO 2.9-3.2. On a parabola Hilbert order gives 50 at 10^3, 136 at 4000.
  double hilbert[2] = {0, 0};
  const std::size_t sizes[2] = {1000, 4000};
  for (int s = 0; s < 2; ++s)
    for (std::uint64_t seed : {1, 2, 3}) {
      const dt::XY p = dt::randomCirclePoints(sizes[s], seed);
      const double h = meanCavity(p, dt::hilbertOrder(p));
      const double b = meanCavity(p, dt::brioOrder(p, seed));
      CAPTURE(sizes[s]);
      CAPTURE(seed);
      CHECK(h < 4.5);
      CHECK(b < 3.6);
      hilbert[s] += h / 3;
    }
  MESSAGE("circle, Hilbert order: N_cavity " << hilbert[0] << " at n = 1000, " << hilbert[1]
                                             << " at n = 4000");
  CHECK(hilbert[1] < 1.25 * hilbert[0]);  // no growth with n (the parabola's grows 2.7 times)
}
// END SOLUTION 2.3.5-3

// BEGIN SOLUTION 2.3.5-4 (remove)
TEST_CASE("2.3.5 exercise 2.3.5-4 the first two BRIO rounds have the same size up to one point") {
  for (std::size_t n = 65; n <= 20000; n += 7) {
    CAPTURE(n);
    const std::vector<std::size_t> r = dt::brioRoundSizes(n);
    REQUIRE(r.size() >= 2);
    // Round 0 is what is left when the last halving makes round 1: floor and ceiling of a half.
    const long d01 = long(r[1]) - long(r[0]);
    CHECK((d01 == 0 || d01 == 1));
    CHECK(r[0] <= 64);
    // Every later round is as large as all earlier ones together, up to one point.
    long before = long(r[0] + r[1]);
    for (std::size_t k = 2; k < r.size(); ++k) {
      const long d = long(r[k]) - before;
      CHECK((d == 0 || d == 1));
      before += long(r[k]);
    }
  }
  CHECK(dt::brioRoundSizes(64).size() == 1);  // small sets are one round
}
// END SOLUTION 2.3.5-4

TEST_CASE("2.3.5 exercise 2.3.5-5 the branch-free Hilbert index agrees with hilbertIndex on every cell up to depth 8") {
  for (int depth = 1; depth <= 8; ++depth) {
    const std::uint32_t side = 1u << depth;
    std::size_t wrong = 0;
    for (std::uint32_t i = 0; i < side; ++i)
      for (std::uint32_t j = 0; j < side; ++j) {
        const std::uint64_t want = dt::hilbertIndex(i, j, depth);
        const std::uint64_t got = dt::hilbertIndexBranchFree(i, j, depth);
        if (got != want && wrong++ == 0)  // the first wrong cell names the input
          FAIL_CHECK("depth " << depth << " cell (i, j) = (" << i << ", " << j << "): got " << got
                              << ", the curve visits it at " << want);
      }
    CHECK_MESSAGE(wrong == 0, "depth " << depth << ": " << wrong << " of " << side * side << " cells wrong");
  }
}

TEST_CASE("2.3.5 exercise 2.3.5-5 the branch-free Hilbert index is exact at depth 31") {
  // Depth 31 keys use 62 bits: a wrong shift or a 32-bit intermediate shows here.
  std::uint64_t s = 0x9e3779b97f4a7c15ULL;
  auto next = [&s] {
    s ^= s << 13, s ^= s >> 7, s ^= s << 17;
    return std::uint32_t(s & 0x7fffffffu);
  };
  std::vector<std::array<std::uint32_t, 2>> cells = {{0, 0}, {0x7fffffffu, 0}, {0, 0x7fffffffu},
                                                     {0x7fffffffu, 0x7fffffffu}, {1u << 30, 1u << 30}};
  for (int k = 0; k < 20000; ++k) cells.push_back({next(), next()});
  for (int depth : {16, 31})
    for (const auto& c : cells) {
      const std::uint32_t mask = depth == 31 ? 0x7fffffffu : (1u << depth) - 1;
      const std::uint32_t i = c[0] & mask, j = c[1] & mask;
      const std::uint64_t want = dt::hilbertIndex(i, j, depth), got = dt::hilbertIndexBranchFree(i, j, depth);
      if (got != want) {
        FAIL_CHECK("depth " << depth << " cell (i, j) = (" << i << ", " << j << "): got " << got
                            << ", the curve visits it at " << want);
        break;
      }
    }
  CHECK(dt::hilbertIndexBranchFree(0x7fffffffu, 0, 31) == (std::uint64_t(1) << 62) - 1);
}
