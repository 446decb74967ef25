// The one core of the robust predicates (2.3.1): a floating-point filter with a proved error
// bound, exact stages in machine arithmetic, then exact GMP integers (predicates_exact.h, the
// one thing beneath this file). Inline, so that the fast kernel (fast_core.h) calls it without a
// function call; predicates.cpp wraps it with the library's counters. The error-bound
// derivations live here and only here.
//
// A new stage touches two files: predicate_stages.h (its enumerator, in run order, and its name)
// and this one (the stage itself, called from orient2dSlow / incircleSlow). Every record of
// stages (StageCounts: the library's counters, the fast kernel's, the tests' tallies) is an
// array indexed by Stage, so nothing else changes. Its test goes to tests/test_predicate_core.cpp.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <utility>

#include "predicate_stages.h"
#include "predicates_exact.h"

namespace dt {
namespace pred {

constexpr double kU = 0x1p-53;  // unit roundoff of binary64, round to nearest

// ---------------------------------------------------------------------------------------------
// The small-multiple stage, between the filter and GMP, for the degenerate tests that grids and
// other "round" data produce in bulk (the filter cannot decide a zero).
//
// Claim. Let every difference d_i of a predicate be computed exactly, and be an integer multiple
// of a power of two h with |d_i| < 2^B h (B = 12 for incircle, 25 for orient2d), with
// 2^-260 <= h <= 2^200. Then the filter's floating-point value `det` IS the determinant.
// Proof. Every intermediate of degree k is an integer multiple of h^k. Its magnitude, for
// incircle (M = max |d_i| < 2^12 h): products |d_i d_j| < 2^24 h^2; lifts (sum of two squares) and
// minors (difference of two products) < 2^25 h^2; lift x minor < 2^50 h^4; the partial sums of
// three such < 3 2^50 h^4 < 2^52 h^4. For orient2d (M < 2^25 h): products < 2^50 h^2, their
// difference < 2^51 h^2. An integer N times 2^E with |N| < 2^53 and E >= -1074 is a double (a
// subnormal if small), and h^4 >= 2^-1040, h^4 2^53 <= 2^853 < 2^1024: no operation rounds,
// underflows or overflows, so each computed value equals the exact one. []
// Exactness of a difference d = fl(a - b) is checked with Knuth's two-sum: its rounding error,
// computed without error, is zero. (On overflow d is infinite, the check gives NaN != 0: no.)
inline bool exactDifference(double a, double b, double d) {
  const double bb = d - a;
  return (a - (d - bb)) - (b + bb) == 0;
}

/// Are all d[0..N) integer multiples of one power of two h in [2^-260, 2^200] with
/// |d_i| < 2^bits h? (h = 2^(e - bits), where 2^(e-1) <= max |d_i| < 2^e.)
template <int N>
inline bool smallMultiples(const double (&d)[N], int bits) {
  double m = 0;
  for (double v : d) m = std::max(m, std::fabs(v));
  if (!(m > 0)) return false;
  int e = 0;
  std::frexp(m, &e);  // m < 2^e
  if (e - bits < -260 || e - bits > 200) return false;
  const double inv = std::ldexp(1.0, bits - e);  // 1/h, exact
  for (double v : d) {
    // Exact unless it underflows: a nonzero v far below h (h > 1, v subnormal) can scale to 0,
    // which would pass for the integer 0 and make the "exact" value lose v (found by fuzzing:
    // orient2d((0, 8e-320), (1.4e-312, 1e34), (0, 0)) returned 0). Reject it.
    const double q = v * inv;
    if (q != double(std::int64_t(q)) || (q == 0 && v != 0)) return false;
  }
  return true;
}

// The wide stage, for what the small-multiple stage leaves: the differences exact and integer
// multiples of one power of two h with |d_i| < 2^62 h (points on a circle: rounded coordinates
// whose differences are exact but have up to about 40 significant bits). Then q_i = d_i / h are
// integers below 2^62 (int64), their products are below 2^124 (int128), lifts and minors below
// 2^125, and lift x minor below 2^250: the determinant is evaluated exactly with 128- and
// 256-bit integers, far cheaper than GMP. Any power of two h will do (d_i 2^(62-e) is exact
// whatever e), so there is no range to guard.
__extension__ typedef __int128 Int128;
__extension__ typedef unsigned __int128 UInt128;

/// q[i] = d[i] / h as integers, h = 2^(e-62) with 2^(e-1) <= max |d_i| < 2^e; false if some
/// d[i] is not an integer multiple of h (or all are zero).
template <int N>
inline bool wideMultiples(const double (&d)[N], std::int64_t (&q)[N]) {
  double m = 0;
  for (double v : d) m = std::max(m, std::fabs(v));
  if (!(m > 0)) return false;
  int e = 0;
  std::frexp(m, &e);
  for (int i = 0; i < N; ++i) {
    // Exact when d[i] is a multiple of h (then |x| < 2^62 is an integer); otherwise x is not
    // an integer, or a nonzero d[i] far below h underflowed to 0: both rejected.
    const double x = std::ldexp(d[i], 62 - e);
    if (x != std::floor(x) || (x == 0 && d[i] != 0)) return false;
    q[i] = std::int64_t(x);
  }
  return true;
}

/// An unsigned 256-bit integer (hi, lo), enough for the sums of lift x minor products.
struct UInt256 {
  UInt128 hi = 0, lo = 0;
  void add(const UInt256& o) {
    lo += o.lo;
    hi += o.hi + (lo < o.lo);  // carry
  }
  bool operator<(const UInt256& o) const { return hi != o.hi ? hi < o.hi : lo < o.lo; }
};

/// a b for a, b < 2^127, from four 64 x 64-bit products.
inline UInt256 mul256(UInt128 a, UInt128 b) {
  const std::uint64_t a0 = std::uint64_t(a), a1 = std::uint64_t(a >> 64);
  const std::uint64_t b0 = std::uint64_t(b), b1 = std::uint64_t(b >> 64);
  const UInt128 p00 = UInt128(a0) * b0, p01 = UInt128(a0) * b1;
  const UInt128 p10 = UInt128(a1) * b0, p11 = UInt128(a1) * b1;
  const UInt128 mid = (p00 >> 64) + std::uint64_t(p01) + std::uint64_t(p10);  // < 3 2^64
  UInt256 r;
  r.lo = (mid << 64) | std::uint64_t(p00);
  r.hi = p11 + (p01 >> 64) + (p10 >> 64) + (mid >> 64);
  return r;
}

/// Sign of lift_a minor_a + lift_b minor_b + lift_c minor_c, lifts >= 0, all below 2^126:
/// the positive and the negative terms summed apart (each sum < 2^252), then compared.
inline int signOfLiftedSum(const Int128 (&lift)[3], const Int128 (&minor)[3]) {
  UInt256 pos, neg;
  for (int i = 0; i < 3; ++i) {
    if (minor[i] == 0 || lift[i] == 0) continue;
    const UInt256 t = mul256(UInt128(lift[i]), UInt128(minor[i] > 0 ? minor[i] : -minor[i]));
    (minor[i] > 0 ? pos : neg).add(t);
  }
  return (neg < pos) - (pos < neg);
}

// ---------------------------------------------------------------------------------------------
// The extended-exponent stage, for what the filters leave only because of overflow or underflow:
// coordinates whose exponents spread over the whole double range (2^-1074 beside 2^1023), where
// products overflow or vanish, differences are inexact (so the integer stages cannot start), and
// GMP would work on integers of some 2100 bits (8400 in incircle's products).
//
//! [extendedExponent]
// An Xf is m 2^e with m a double, 1/2 <= |m| < 1 or m = 0, and e an int: the exponent has its own
// integer, so nothing the predicates compute (exponents within +-4400) can overflow or underflow.
// Claim. Each operation below returns (exact result)(1 + d) with |d| <= u = 2^-53:
//  - product: m1 m2 has magnitude in [1/4, 1), far from the subnormals: one rounding to nearest;
//    renormalising (a power of two) is exact.
//  - sum, exponents e1 >= e2, gap g = e1 - e2: if g <= 60, m2 2^-g (|.| >= 2^-61) is exact (a
//    power of two times a double, far from the subnormals; so a fused multiply-add would give
//    the same sum), and the exact sum of m1 and it, a multiple of 2^-113, is either 0 or far
//    above the subnormals: one rounding to nearest. If g > 60 the result is x1 itself:
//    |x2| < 2^e2 <= 2^(e1-61) <= 2^-60 |x1|, so |d| = |x2| / |x1 + x2| <= 1 / (2^60 - 1) < u.
//  - the constants 5u and 12u are powers of two times small integers: xf() holds them exactly.
// So the Xf evaluation obeys the rounding model on which the two filters' error bounds below
// are proved (every operation exact times (1 + d), |d| <= u), without their two caveats: there is
// no underflow and no overflow. The same expressions and the same bounds (5u detsum, 12u
// permanent), evaluated in Xf, therefore decide the sign whenever |det| exceeds the bound, for
// every input of finite doubles. Exact zeros and near-degenerate inputs still go to GMP.
struct Xf {
  double m;
  int e;
};

/// m 2^e normalised (m finite): the exponent field of m moves into e, bit by bit (no frexp call).
inline Xf xfNorm(double m, int e) {
  std::uint64_t b;
  std::memcpy(&b, &m, sizeof b);
  int be = int((b >> 52) & 0x7ff);
  if (be == 0) {  // zero or subnormal (only the inputs can be)
    if (m == 0) return {0.0, 0};
    m *= 0x1p64;
    e -= 64;
    std::memcpy(&b, &m, sizeof b);
    be = int((b >> 52) & 0x7ff);
  }
  b = (b & ~(std::uint64_t{0x7ff} << 52)) | (std::uint64_t{1022} << 52);  // |m| in [1/2, 1)
  std::memcpy(&m, &b, sizeof m);
  return {m, e + be - 1022};
}
inline Xf xf(double v) { return xfNorm(v, 0); }
inline Xf operator*(Xf a, Xf b) { return xfNorm(a.m * b.m, a.e + b.e); }
inline Xf operator+(Xf a, Xf b) {
  if (a.m == 0) return b;
  if (b.m == 0) return a;
  if (a.e < b.e) std::swap(a, b);
  const int g = a.e - b.e;
  if (g > 60) return a;
  std::uint64_t pb = std::uint64_t(1023 - g) << 52;  // 2^-g, a normal double
  double p;
  std::memcpy(&p, &pb, sizeof p);
  return xfNorm(a.m + b.m * p, a.e);
}
inline Xf operator-(Xf a) { return {-a.m, a.e}; }
inline Xf operator-(Xf a, Xf b) { return a + (-b); }
inline Xf xfAbs(Xf a) { return {std::fabs(a.m), a.e}; }
/// |a| > b for b >= 0 (both normalised: compare exponents, then mantissas).
inline bool xfAbsAbove(Xf a, Xf b) {
  if (a.m == 0) return false;
  if (b.m == 0) return true;
  return a.e != b.e ? a.e > b.e : std::fabs(a.m) > b.m;
}
//! [extendedExponent]

/// The orientation filter in Xf: the sign if |det| > 5u detsum, else 2 (undecided).
inline int orient2dExtendedPivot(double ax, double ay, double bx, double by, double cx,
                                 double cy) {
  const Xf l = (xf(ax) - xf(cx)) * (xf(by) - xf(cy));
  const Xf r = (xf(ay) - xf(cy)) * (xf(bx) - xf(cx));
  const Xf det = l - r;
  const Xf bound = xf(5 * kU) * (xfAbs(l) + xfAbs(r));
  return xfAbsAbove(det, bound) ? (det.m > 0 ? 1 : -1) : 2;
}

/// The incircle filter (permanent bound) in Xf, pivot d: the sign if |det| > 12u permanent,
/// else 2.
inline int incircleExtendedPivot(double ax, double ay, double bx, double by, double cx,
                                 double cy, double dx, double dy) {
  const Xf adx = xf(ax) - xf(dx), ady = xf(ay) - xf(dy);
  const Xf bdx = xf(bx) - xf(dx), bdy = xf(by) - xf(dy);
  const Xf cdx = xf(cx) - xf(dx), cdy = xf(cy) - xf(dy);
  const Xf bdxcdy = bdx * cdy, cdxbdy = cdx * bdy;
  const Xf cdxady = cdx * ady, adxcdy = adx * cdy;
  const Xf adxbdy = adx * bdy, bdxady = bdx * ady;
  const Xf alift = adx * adx + ady * ady;
  const Xf blift = bdx * bdx + bdy * bdy;
  const Xf clift = cdx * cdx + cdy * cdy;
  const Xf det = alift * (bdxcdy - cdxbdy) + blift * (cdxady - adxcdy) +
                 clift * (adxbdy - bdxady);
  const Xf permanent = (xfAbs(bdxcdy) + xfAbs(cdxbdy)) * alift +
                       (xfAbs(cdxady) + xfAbs(adxcdy)) * blift +
                       (xfAbs(adxbdy) + xfAbs(bdxady)) * clift;
  const Xf bound = xf(12 * kU) * permanent;
  return xfAbsAbove(det, bound) ? (det.m > 0 ? 1 : -1) : 2;
}

// The pivot. A difference of two points of very different sizes rounds to the larger one and
// loses the smaller; taking the differences to the smallest point keeps the small points'
// differences among themselves accurate, which is what a tiny minor beside a huge lift needs.
// The determinants are the same: orient2d is invariant under cyclic shifts of its points, and
// the 4 x 4 incircle determinant (rows x, y, x^2 + y^2, 1) changes sign under a cyclic shift of
// its four rows, an odd permutation.
inline double xfSize(double x, double y) { return std::max(std::fabs(x), std::fabs(y)); }

/// orient2dExtendedPivot with the smallest point as pivot.
inline int orient2dExtended(double ax, double ay, double bx, double by, double cx, double cy) {
  const double a = xfSize(ax, ay), b = xfSize(bx, by), c = xfSize(cx, cy);
  if (a < b && a < c) return orient2dExtendedPivot(bx, by, cx, cy, ax, ay);
  if (b < c) return orient2dExtendedPivot(cx, cy, ax, ay, bx, by);
  return orient2dExtendedPivot(ax, ay, bx, by, cx, cy);
}

/// incircleExtendedPivot with the smallest point as pivot.
inline int incircleExtended(double ax, double ay, double bx, double by, double cx, double cy,
                            double dx, double dy) {
  const double a = xfSize(ax, ay), b = xfSize(bx, by), c = xfSize(cx, cy), d = xfSize(dx, dy);
  const double m = std::min(std::min(a, b), std::min(c, d));
  int s;
  if (m == d) return incircleExtendedPivot(ax, ay, bx, by, cx, cy, dx, dy);
  if (m == a) return (s = incircleExtendedPivot(bx, by, cx, cy, dx, dy, ax, ay)) == 2 ? 2 : -s;
  if (m == b) return incircleExtendedPivot(cx, cy, dx, dy, ax, ay, bx, by);
  return (s = incircleExtendedPivot(dx, dy, ax, ay, bx, by, cx, cy)) == 2 ? 2 : -s;
}

// ---------------------------------------------------------------------------------------------
// Error bound for orient2d (u = 2^-53, round to nearest, no FMA: -ffp-contract=off).
// Write each rounded operation as an exact one times (1 + d), |d| <= u. The computed value is
//   fl( fl(fl(ax-cx) fl(by-cy)) - fl(fl(ay-cy) fl(bx-cx)) ),
// so each of the two exact products L = (ax-cx)(by-cy), R = (ay-cy)(bx-cx) reaches the result
// multiplied by at most four factors (1+d): two differences, one product, one subtraction.
// Hence |computed - (L - R)| <= g4 (|L| + |R|), g4 = 4u/(1-4u). The computed
// detsum = fl(|fl(L)| + |fl(R)|) satisfies |L| + |R| <= detsum (1+u)/(1-g3) < detsum (1 + 5u).
// So the error is below 4u(1 + 9u) detsum, which 5u detsum exceeds; computing 5u detsum itself
// rounds by a relative u at most, still above. Two caveats the textbook bound ignores:
//  - underflow: a product below 2^-1022 has an absolute (not relative) error of up to 2^-1075.
//    Requiring detsum >= 2^-960 makes the margin (5u - 4u(1+9u)) detsum > 2^-1014 dwarf it;
//    smaller inputs go to the exact stages.
//  - overflow: any infinity or NaN makes the comparison false, so the exact stages decide.
// The notes' rule |O| > 1e-15 max(...)^2 is not of this form: it ignores the cancellation in
// the differences (it uses the coordinates, not |L| + |R|) and the sign of the coordinates.

/// The stages after the filter (out of line: rarely reached, and it keeps the callers small).
__attribute__((noinline)) inline int orient2dSlow(double ax, double ay, double bx, double by,
                                                  double cx, double cy, int& stage) {
  const double acx = ax - cx, bcy = by - cy, acy = ay - cy, bcx = bx - cx;
  const double d[4] = {acx, bcy, acy, bcx};
  // Both integer stages need the differences exact: test that once.
  const bool exact = exactDifference(ax, cx, acx) && exactDifference(by, cy, bcy) &&
                     exactDifference(ay, cy, acy) && exactDifference(bx, cx, bcx);
  if (exact && smallMultiples(d, 25)) {
    const double det = acx * bcy - acy * bcx;  // exact, by the claim above
    stage = kSmallInt;
    return (det > 0) - (det < 0);
  }
  std::int64_t q[4];
  if (exact && wideMultiples(d, q)) {
    const Int128 l = Int128(q[0]) * q[1], r = Int128(q[2]) * q[3];  // each below 2^124
    stage = kWide;
    return (l > r) - (l < r);
  }
  const int x = orient2dExtended(ax, ay, bx, by, cx, cy);
  if (x != 2) {
    stage = kExtended;
    return x;
  }
  stage = kExact;
  return orient2dExact(ax, ay, bx, by, cx, cy);
}

//! [orient2d]
/// Robust orientation: the filter, then orient2dSlow. `stage` receives the stage that decided.
__attribute__((always_inline)) inline int orient2d(double ax, double ay, double bx, double by,
                                                   double cx, double cy, int& stage) {
  const double detleft = (ax - cx) * (by - cy);
  const double detright = (ay - cy) * (bx - cx);
  const double det = detleft - detright;
  const double detsum = std::fabs(detleft) + std::fabs(detright);
  const double bound = 5 * kU * detsum;
  if ((det > bound || -det > bound) && detsum >= 0x1p-960) {
    stage = kFilter;
    return det > 0 ? 1 : -1;
  }
  return orient2dSlow(ax, ay, bx, by, cx, cy, stage);
}
//! [orient2d]

// Error bound for incircle, in the same style. The determinant is
//   alift (bdx cdy - cdx bdy) + blift (cdx ady - adx cdy) + clift (adx bdy - bdx ady)
// with differences to d. Expanded, it is a sum of 24 monomials of degree 4; in floating point
// each reaches the result through at most 11 rounded operations: 2 differences and 1 product
// and 1 sum in the lift (4), 2 differences and 1 product and 1 subtraction in the minor (4),
// the product lift x minor (1), and the two final additions (2). So the error is at most
// g11 P, where P is the sum of the absolute values of the monomials: the "permanent",
// computed below as alift (|bdx cdy| + |cdx bdy|) + ... P is taken on the exact differences,
// so each of its monomials also reaches the computed permanent through 11 roundings (the same
// 2 + 2 differences, 1 square, 1 lift sum, 1 product, 1 sum of absolute values, 1 product by
// the lift, 2 final sums): P <= permanent / (1-u)^11 < permanent (1 + 12u). The error is thus
// below g11 (1 + 12u) permanent < 11u (1 + 24u) permanent, and the computed 12u permanent,
// at least 12u (1-u) permanent, exceeds it.
// Underflow: if every nonzero difference is at least 2^-511 in magnitude, no
// degree-2 product underflows; a degree-4 product may, with an absolute error of at most
// 2^-1075, which the margin u permanent covers once permanent >= 2^-900. Otherwise, and on
// overflow (infinity or NaN), the exact stages decide.
// The semi-static bound tried first. Let M = max of the six computed |differences|. The exact
// differences are at most M / (1-u) < M (1 + 2u), and each of the three terms of P is a lift
// (at most 2 M^2) times a sum of two products (at most 2 M^2): P < 12 M^4 (1 + 2u)^4. The
// error is then below g11 12 (1 + 9u) M^4 < 133u M^4, and the computed 134u ((M M) (M M)),
// at least 134u (1-u)^4 M^4, exceeds it by more than u M^4. Underflow: with M >= 2^-200,
// u M^4 >= 2^-853; the at most 15 products that may underflow (absolute error 2^-1075 each,
// later multiplied by at most 2 M^2 (1 + 4u)) add far less than that. Overflow gives an
// infinity or NaN, and the comparisons fail. It is looser than the permanent (12 M^4 >= P),
// so the tests it leaves go on to the permanent's bound.

inline bool notTiny(double v) { return v == 0 || std::fabs(v) >= 0x1p-511; }

//! [incircleSlow]
__attribute__((noinline)) inline int incircleSlow(double ax, double ay, double bx, double by,
                                                  double cx, double cy, double dx, double dy,
                                                  int& stage) {
  const double adx = ax - dx, ady = ay - dy;
  const double bdx = bx - dx, bdy = by - dy;
  const double cdx = cx - dx, cdy = cy - dy;
  const double diff[6] = {adx, ady, bdx, bdy, cdx, cdy};
  // Both integer stages need the differences exact: test that once.
  const bool exact = exactDifference(ax, dx, adx) && exactDifference(ay, dy, ady) &&
                     exactDifference(bx, dx, bdx) && exactDifference(by, dy, bdy) &&
                     exactDifference(cx, dx, cdx) && exactDifference(cy, dy, cdy);
  if (exact && smallMultiples(diff, 12)) {
    // The filter's expression, in the filter's order: exact, by the claim above.
    const double alift = adx * adx + ady * ady;
    const double blift = bdx * bdx + bdy * bdy;
    const double clift = cdx * cdx + cdy * cdy;
    const double det = alift * (bdx * cdy - cdx * bdy) + blift * (cdx * ady - adx * cdy) +
                       clift * (adx * bdy - bdx * ady);
    stage = kSmallInt;
    return (det > 0) - (det < 0);
  }
  std::int64_t q[6];
  if (exact && wideMultiples(diff, q)) {
    auto sq = [](std::int64_t x) { return Int128(x) * x; };
    auto cross = [](std::int64_t x1, std::int64_t y1, std::int64_t x2, std::int64_t y2) {
      return Int128(x1) * y2 - Int128(x2) * y1;
    };
    const Int128 lift[3] = {sq(q[0]) + sq(q[1]), sq(q[2]) + sq(q[3]), sq(q[4]) + sq(q[5])};
    const Int128 minor[3] = {cross(q[2], q[3], q[4], q[5]), cross(q[4], q[5], q[0], q[1]),
                             cross(q[0], q[1], q[2], q[3])};
    stage = kWide;
    return signOfLiftedSum(lift, minor);
  }
  const int x = incircleExtended(ax, ay, bx, by, cx, cy, dx, dy);
  if (x != 2) {
    stage = kExtended;
    return x;
  }
  stage = kExact;
  return incircleExact(ax, ay, bx, by, cx, cy, dx, dy);
}

//! [incircleSlow]

//! [incircle]
/// Robust incircle: the filter, then incircleSlow. `stage` receives the stage that decided.
__attribute__((always_inline)) inline int incircle(double ax, double ay, double bx, double by,
                                                   double cx, double cy, double dx, double dy,
                                                   int& stage) {
  const double adx = ax - dx, ady = ay - dy;
  const double bdx = bx - dx, bdy = by - dy;
  const double cdx = cx - dx, cdy = cy - dy;
  const double bdxcdy = bdx * cdy, cdxbdy = cdx * bdy;
  const double cdxady = cdx * ady, adxcdy = adx * cdy;
  const double adxbdy = adx * bdy, bdxady = bdx * ady;
  const double alift = adx * adx + ady * ady;
  const double blift = bdx * bdx + bdy * bdy;
  const double clift = cdx * cdx + cdy * cdy;
  const double det = alift * (bdxcdy - cdxbdy) + blift * (cdxady - adxcdy) +
                     clift * (adxbdy - bdxady);
  // A cheaper, semi-static bound first (derived above): most tests need no permanent.
  const double M = std::max(std::max(std::max(std::fabs(adx), std::fabs(ady)),
                                     std::max(std::fabs(bdx), std::fabs(bdy))),
                            std::max(std::fabs(cdx), std::fabs(cdy)));
  // M < 2^254 keeps every intermediate (at most 12 M^4) finite: M^4 alone may be finite while
  // a lift times a minor (up to 4 M^4) overflows to an infinity that passes the comparison
  // (found by the independent oracle of tests/oracle.h on a lattice rectangle near 2^255).
  if (M >= 0x1p-200 && M < 0x1p254) {
    const double boundM = 134 * kU * ((M * M) * (M * M));
    if (det > boundM || -det > boundM) {
      stage = kFilter;
      return det > 0 ? 1 : -1;
    }
  }
  const double permanent = (std::fabs(bdxcdy) + std::fabs(cdxbdy)) * alift +
                           (std::fabs(cdxady) + std::fabs(adxcdy)) * blift +
                           (std::fabs(adxbdy) + std::fabs(bdxady)) * clift;
  const double bound = 12 * kU * permanent;
  if ((det > bound || -det > bound) && permanent >= 0x1p-900) {
    // The underflow guard: every difference zero or at least 2^-511. The smallest magnitude
    // decides it at once in the usual case (no zero difference).
    const double m = std::min(std::min(std::min(std::fabs(adx), std::fabs(ady)),
                                       std::min(std::fabs(bdx), std::fabs(bdy))),
                              std::min(std::fabs(cdx), std::fabs(cdy)));
    if (m >= 0x1p-511 || (notTiny(adx) && notTiny(ady) && notTiny(bdx) && notTiny(bdy) &&
                          notTiny(cdx) && notTiny(cdy))) {
      stage = kFilter;
      return det > 0 ? 1 : -1;
    }
  }
  return incircleSlow(ax, ay, bx, by, cx, cy, dx, dy, stage);
}
//! [incircle]

// ---------------------------------------------------------------------------------------------
// The ghost face's conflict rule (2.2.2). A ghost (a, b, inf) stands for the outer side of the
// hull edge a b; its "circumcircle" is the limit of circles through a and b whose centre goes to
// infinity on that side: the open half-plane left of a->b, plus the open segment ab itself (a
// point there is also strictly inside the finite neighbour's circle). Face::inCircle (mesh.cpp)
// and the fast kernels (fast_core.h) both decide it here.

/// p on the open segment ab, given a, b, p collinear (comparisons only, hence exact).
inline bool onOpenSegment(double ax, double ay, double bx, double by, double px, double py) {
  if (ax != bx) return (ax < px && px < bx) || (bx < px && px < ax);
  return (ay < py && py < by) || (by < py && py < ay);
}

/// Is p in conflict with the ghost (a, b, inf)? orientABP is the sign of orient2d(a, b, p),
/// computed by the caller with its own (counted or inlined) predicate.
inline bool ghostConflict(int orientABP, double ax, double ay, double bx, double by, double px,
                          double py) {
  return orientABP > 0 || (orientABP == 0 && onOpenSegment(ax, ay, bx, by, px, py));
}

}  // namespace pred
}  // namespace dt
