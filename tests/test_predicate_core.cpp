/// \file test_predicate_core.cpp Tests of the one predicate core (code/predicates/predicates_inline.h): each stage (filter, small multiples, wide integers, extended exponent, GMP) is reached and agrees with the exact oracle.
#include <doctest/doctest.h>

#include <cmath>
#include <random>

#include "oracle.h"
#include "predicates.h"
#include "predicates_inline.h"

namespace {

struct Tally {
  long calls = 0, wrong = 0, stage[5] = {0, 0, 0, 0, 0};
};

// Both predicates of the core on one quadruple, against the independent rational oracle
// (tests/oracle.h: GMP rationals, the notes' determinants; no code shared with the core, whose
// own GMP stage would be compared with itself).
void check(const double v[8], Tally& o, Tally& c) {
  int s = -1;
  const int r = dt::pred::orient2d(v[0], v[1], v[2], v[3], v[4], v[5], s);
  ++o.calls;
  ++o.stage[s];
  o.wrong += r != dtoracle::orientQ(v[0], v[1], v[2], v[3], v[4], v[5]);
  const int q = dt::pred::incircle(v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7], s);
  ++c.calls;
  ++c.stage[s];
  c.wrong += q != dtoracle::incircleQ(v);
}

}  // namespace

TEST_CASE("predicate core decides grids at every scale (small multiples of 2^k) exactly in doubles") {
  // Points of a small grid (side 2^g) scaled by h = 2^s and shifted far from the origin: many
  // collinear and cocircular quadruples (the filter cannot decide a zero), differences exact.
  std::mt19937_64 rng(909);
  Tally o, c;
  for (int g : {3, 6, 11, 12, 13, 24, 25, 26}) {
    std::uniform_int_distribution<long> cell(0, (1L << g) - 1);
    for (int s : {-255, -100, -30, 0, 30, 150, 195}) {
      const double h = std::ldexp(1.0, s);
      for (double shift : {0.0, std::ldexp(1.0, 40), -std::ldexp(3.0, 26)}) {
        for (int it = 0; it < 400; ++it) {
          double v[8];
          for (double& x : v) x = (double(cell(rng)) + shift) * h;
          check(v, o, c);
        }
      }
    }
  }
  CHECK(o.wrong == 0);
  CHECK(c.wrong == 0);
  // The small-multiple stage does the bulk of the degenerate work on grids...
  CHECK(o.stage[dt::pred::kSmallInt] > 300);  // collinear triples: rarer than cocircular
  CHECK(c.stage[dt::pred::kSmallInt] > 1000);
  // ...but not all of it: beyond 2^12 h (incircle) and 2^25 h (orient2d) the wide stage decides.
  for (int s : {-255, 0, 195}) {
    const double h = std::ldexp(1.0, s), m = 4097 * h, p = (double(1 << 24) + 1) * h;
    int st = -1;
    CHECK(dt::pred::incircle(0, 0, m, 0, m, m, 0, m, st) == 0);  // a square: cocircular
    CHECK(st == dt::pred::kWide);
    CHECK(dt::pred::incircle(0, 0, m - h, 0, m - h, m - h, 0, m - h, st) == 0);  // side 4096 h
    CHECK(st == dt::pred::kSmallInt);
    CHECK(dt::pred::orient2d(0, 0, p, h, 2 * p, 2 * h, st) == 0);  // 2p > 2^25 h: h no longer fits
    CHECK(st == dt::pred::kWide);
    const double q = double(1 << 24) * h;  // differences 2q = 2^25 h, q, 2h, 4h: multiples of 2h
    CHECK(dt::pred::orient2d(0, 0, q, 2 * h, 2 * q, 4 * h, st) == 0);
    CHECK(st == dt::pred::kSmallInt);
  }
  CHECK(o.stage[dt::pred::kFilter] > o.calls / 2);
  CHECK(c.stage[dt::pred::kFilter] > c.calls / 4);
}

TEST_CASE("predicate core sends huge and tiny grids where h leaves [2^-260 .. 2^200] to the wide stage") {
  std::mt19937_64 rng(910);
  std::uniform_int_distribution<long> cell(0, 7);
  Tally o, c;
  for (int s : {-1070, -1000, -600, -270, 230, 500, 900}) {  // h = 2^(s-25) .. 2^(s-9)
    const double h = std::ldexp(1.0, s);
    for (int it = 0; it < 500; ++it) {
      double v[8];
      for (double& x : v) x = double(cell(rng)) * h;
      check(v, o, c);
    }
  }
  CHECK(o.wrong == 0);
  CHECK(c.wrong == 0);
  CHECK(o.stage[dt::pred::kSmallInt] == 0);
  CHECK(c.stage[dt::pred::kSmallInt] == 0);
  CHECK(o.stage[dt::pred::kWide] > 100);
  CHECK(c.stage[dt::pred::kWide] > 100);
}

TEST_CASE("predicate core wide stage holds 128- and 256-bit integers of up to 62-bit multiples") {
  std::mt19937_64 rng(912);
  Tally o, c;
  // Integers of up to 50 bits at random offsets: differences exact, of up to 51 bits, scaled
  // to up to 61 bits; lift x minor reaches 2^246, signs at random.
  std::uniform_int_distribution<std::int64_t> big(-(std::int64_t(1) << 49), std::int64_t(1) << 49);
  for (int it = 0; it < 20000; ++it) {
    double v[8];
    for (double& x : v) x = double(big(rng));
    if (it % 2) {  // a cocircular square of odd side: the positive and negative sums are equal
      const double m = double(big(rng) | 1), x0 = v[0], y0 = v[1];
      const double w[8] = {x0, y0, x0 + m, y0, x0 + m, y0 + m, x0, y0 + m};
      for (int k = 0; k < 8; ++k) v[k] = w[k];
    }
    check(v, o, c);
  }
  CHECK(o.wrong == 0);
  CHECK(c.wrong == 0);
  CHECK(c.stage[dt::pred::kWide] > 5000);  // the squares at least
  // Points on a circle, rounded (the bench's circle family): exact differences of 40-odd bits.
  for (int it = 0; it < 20000; ++it) {
    const double s = std::ldexp(1.0, int(rng() % 200) - 100), t0 = double(rng() % 100000);
    double v[8];
    for (int p = 0; p < 4; ++p) {
      const double t = 2 * M_PI * (t0 + double(rng() % 8)) / 100000;
      v[2 * p] = s * std::cos(t);
      v[2 * p + 1] = s * std::sin(t);
    }
    check(v, o, c);
  }
  CHECK(o.wrong == 0);
  CHECK(c.wrong == 0);
  CHECK(c.stage[dt::pred::kWide] > 10000);
  // The 256-bit product at its limits: (2^126 - 1)^2 and a carry out of the low half.
  const dt::pred::UInt128 a = (dt::pred::UInt128(1) << 126) - 1;
  const dt::pred::UInt256 sq = dt::pred::mul256(a, a);  // 2^252 - 2^127 + 1
  CHECK(sq.lo == (dt::pred::UInt128(1) << 127) + 1);  // -2^127 + 1 mod 2^128
  CHECK(sq.hi == (dt::pred::UInt128(1) << 124) - 1);
  dt::pred::UInt256 x;
  x.lo = ~dt::pred::UInt128(0);
  dt::pred::UInt256 one;
  one.lo = 1;
  x.add(one);
  CHECK(x.lo == 0);
  CHECK(x.hi == 1);
}

TEST_CASE("predicate core never takes a difference that rounds is never taken for exact") {
  // 2^60 - 1 rounds to 2^60, a multiple of a power of two: only the two-sum check stops it.
  const double big = std::ldexp(1.0, 60);
  int s = -1;
  // a = (2^60, 0), b = (2^60, 1), c = (1, 0): det = (2^60 - 1) * 1 - 0 * (2^60 - 1) > 0.
  const int r = dt::pred::orient2d(big, 0, big, 1, 1, 0, s);
  CHECK(r == dtoracle::orientQ(big, 0, big, 1, 1, 0));
  CHECK(r == 1);
  CHECK(s != dt::pred::kSmallInt);
  CHECK_FALSE(dt::pred::exactDifference(big, 1, big - 1));
  CHECK(dt::pred::exactDifference(big, big / 2, big - big / 2));
  const double ok[3] = {4095, -4094, 2};
  CHECK(dt::pred::smallMultiples(ok, 12));
  const double odd[3] = {4097, 2, 0};  // 4097 >= 2^12: h = 2 would not divide it
  CHECK_FALSE(dt::pred::smallMultiples(odd, 12));
  const double zero[2] = {0, 0};
  CHECK_FALSE(dt::pred::smallMultiples(zero, 12));
}

TEST_CASE("predicate core agrees with GMP on random near-degenerate inputs nudged by ulps") {
  std::mt19937_64 rng(911);
  std::uniform_real_distribution<double> u(-1, 1);
  std::uniform_int_distribution<int> k(-3, 3), sc(-200, 200);
  Tally o, c;
  auto nudge = [](double x, int n) {
    for (; n > 0; --n) x = std::nextafter(x, 1e308);
    for (; n < 0; ++n) x = std::nextafter(x, -1e308);
    return x;
  };
  for (int it = 0; it < 40000; ++it) {
    const double s = std::ldexp(1.0, sc(rng));
    const double cx = u(rng) * s, cy = u(rng) * s, r = (0.5 + std::fabs(u(rng))) * s;
    double v[8];
    // a, b and d on a circle, c on the segment ab: near-collinear a b c, near-cocircular a b c d.
    for (int p : {0, 1, 3}) {
      const double t = 3.2 * u(rng);
      v[2 * p] = nudge(cx + r * std::cos(t), k(rng));
      v[2 * p + 1] = nudge(cy + r * std::sin(t), k(rng));
    }
    const double t = u(rng);
    v[4] = nudge(v[0] + t * (v[2] - v[0]), k(rng));
    v[5] = nudge(v[1] + t * (v[3] - v[1]), k(rng));
    check(v, o, c);
    // and the quadruple with c moved onto the circle too
    const double w = 3.2 * u(rng);
    v[4] = nudge(cx + r * std::cos(w), k(rng));
    v[5] = nudge(cy + r * std::sin(w), k(rng));
    check(v, o, c);
  }
  CHECK(o.wrong == 0);
  CHECK(c.wrong == 0);
  CHECK(o.stage[dt::pred::kExact] > 100);  // inexact differences: only GMP can decide
  CHECK(c.stage[dt::pred::kExact] > 100);
  CHECK(o.stage[dt::pred::kFilter] > 1000);
  CHECK(c.stage[dt::pred::kFilter] > 1000);
}

TEST_CASE("predicate core dt::orient2d / dt::incircle report the small-multiple stage and count it") {
  dt::predicateCounters().reset();
  CHECK(dt::orient2d(0, 0, 1, 1, 2, 2) == 0);
  CHECK(dt::lastPredicateStage() == dt::pred::kSmallInt);
  CHECK(dt::incircle(0, 0, 1, 0, 1, 1, 0, 1) == 0);  // a square: cocircular
  CHECK(dt::lastPredicateStage() == dt::pred::kSmallInt);
  CHECK(dt::orient2d(0, 0, 1, 0, 0, 1) == 1);
  CHECK(dt::lastPredicateStage() == dt::pred::kFilter);
  const dt::PredicateCounters c = dt::predicateCounters();
  CHECK(c.orient.calls() == 2);
  CHECK(c.orient.beyondFilter() == 1);  // the filter failed once...
  CHECK(c.orient[dt::pred::kSmallInt] == 1);  // ...and the small-multiple stage decided
  CHECK(c.incircle[dt::pred::kSmallInt] == 1);
}

namespace {

// +-(1/2 + U[0, 1)) 2^k, k uniform in [kmin, kmax]: the exponent-spread family of bench_kernels.
double spread(std::mt19937_64& rng, int kmin = -1074, int kmax = 1023) {
  std::uniform_real_distribution<double> u(0, 1);
  std::uniform_int_distribution<int> k(kmin, kmax);
  const double x = std::ldexp(0.5 + u(rng), k(rng));
  return rng() & 1 ? x : -x;
}

double ulps(double x, int n) {
  for (; n > 0; --n) x = std::nextafter(x, 1e308);
  for (; n < 0; ++n) x = std::nextafter(x, -1e308);
  return x;
}

}  // namespace

TEST_CASE("predicate core exponents spread over the whole double range go to the extended-exponent stage and never get a wrong sign") {
  std::mt19937_64 rng(913);
  Tally o, c;
  for (int it = 0; it < 30000; ++it) {
    double v[8];
    for (double& x : v) x = spread(rng);
    check(v, o, c);
  }
  CHECK(o.wrong == 0);
  CHECK(c.wrong == 0);
  // Overflowing or vanishing products: the double filters fail on most of these, the
  // extended-exponent stage decides nearly all of what they leave.
  CHECK(o.stage[dt::pred::kExtended] > o.calls / 4);
  CHECK(c.stage[dt::pred::kExtended] > c.calls / 2);
  CHECK(o.stage[dt::pred::kExact] < o.calls / 100);
  CHECK(c.stage[dt::pred::kExact] < c.calls / 100);
}

TEST_CASE("predicate core exactly degenerate inputs at wildly different powers of two and their one-ulp neighbours agree with GMP") {
  // Points s_i (p, q) on a line through the origin, s_i = +-2^k_i with k_i spread over the
  // range (p, q small integers, so every coordinate is exact): any three are collinear and any
  // four "cocircular" (incircle of four collinear points is 0). Then each coordinate nudged by
  // one or two ulps, which leaves a tiny nonzero determinant that only the exact stages see.
  std::mt19937_64 rng(914);
  std::uniform_int_distribution<int> k(-1000, 1000), small(1, 15), nudge(-2, 2);
  Tally o, c;
  long zeros = 0;
  for (int it = 0; it < 6000; ++it) {
    const double p = small(rng), q = -small(rng);
    double v[8];
    for (int i = 0; i < 4; ++i) {
      const double si = std::ldexp(rng() & 1 ? 1.0 : -1.0, k(rng));
      v[2 * i] = si * p;
      v[2 * i + 1] = si * q;
    }
    int st = -1;
    zeros += dt::pred::orient2d(v[0], v[1], v[2], v[3], v[4], v[5], st) == 0;
    zeros += dt::pred::incircle(v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7], st) == 0;
    check(v, o, c);
    v[rng() % 8] = ulps(v[rng() % 8], nudge(rng));
    check(v, o, c);
  }
  CHECK(zeros == 2 * 6000);
  CHECK(o.wrong == 0);
  CHECK(c.wrong == 0);
  CHECK(o.stage[dt::pred::kExtended] > 100);  // a far point makes many nudged ones clear
  CHECK(c.stage[dt::pred::kExact] > 1000);    // exact zeros: GMP, as it must be
}

TEST_CASE("predicate core subnormal coordinates beside huge ones agree with GMP") {
  std::mt19937_64 rng(915);
  std::uniform_int_distribution<int> which(0, 3), sub(1, 1 << 20);
  Tally o, c;
  for (int it = 0; it < 20000; ++it) {
    double v[8];
    for (double& x : v) {
      switch (which(rng)) {
        case 0: x = sub(rng) * 0x1p-1074 * (rng() & 1 ? 1 : -1); break;  // subnormal
        case 1: x = 0; break;
        case 2: x = spread(rng, 900, 1023); break;
        default: x = spread(rng, -1074, -1000); break;
      }
    }
    check(v, o, c);
  }
  CHECK(o.wrong == 0);
  CHECK(c.wrong == 0);
  CHECK(o.stage[dt::pred::kExtended] > 1000);
  CHECK(c.stage[dt::pred::kExtended] > 1000);
  // The arithmetic itself: normalisation of subnormals, sums with a gap above 60.
  const dt::pred::Xf t = dt::pred::xf(0x1p-1074);
  CHECK(t.m == 0.5);
  CHECK(t.e == -1073);
  const dt::pred::Xf one = dt::pred::xf(1.0), s = one + dt::pred::xf(0x1p-61);
  CHECK(s.m == one.m);  // 1 + 2^-61 rounds to 1
  CHECK(s.e == one.e);
  const dt::pred::Xf d = dt::pred::xf(0x1p1000) - dt::pred::xf(0x1p1000);
  CHECK(d.m == 0);
}

TEST_CASE("predicate core dt::orient2d / dt::incircle count the extended-exponent stage") {
  dt::predicateCounters().reset();
  // (2^1000, 0), (0, 2^1000), (-2^1000, 3): products overflow; differences round (3 - 2^1000).
  CHECK(dt::orient2d(0x1p1000, 0, 0, 0x1p1000, -0x1p1000, 3) == 1);
  CHECK(dt::lastPredicateStage() == dt::pred::kExtended);
  CHECK(dt::incircle(0x1p1000, 0, 0, 0x1p1000, -0x1p1000, 3, 0x1p-1000, 0x1p-1070) == 1);
  CHECK(dt::lastPredicateStage() == dt::pred::kExtended);
  const dt::PredicateCounters k = dt::predicateCounters();
  CHECK(k.orient[dt::pred::kExtended] == 1);
  CHECK(k.incircle[dt::pred::kExtended] == 1);
  CHECK(k.orient.beyondFilter() == 1);  // the filter failed
  CHECK(k.orient[dt::pred::kSmallInt] == 0);
}
