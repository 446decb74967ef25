/// \file test_2_3_1_predicates.cpp Section 2.3.1: the robust predicates equal the exact oracle on millions of near-degenerate inputs, the maps of Figures 2.7-2.8 have the printed properties, and every counterexample to the notes' filters and to 200-bit MPFR is pinned.
#include <doctest/doctest.h>
#include <gmp.h>

#include <cmath>
#include <random>

#include "predicates.h"
#include "robustness.h"

using namespace dt;

namespace {

// An oracle independent of predicates.cpp: GMP rationals (mpq_set_d is exact for finite doubles).
struct Q {
  mpq_t v;
  Q() { mpq_init(v); }
  explicit Q(double d) { mpq_init(v), mpq_set_d(v, d); }
  ~Q() { mpq_clear(v); }
  Q(const Q&) = delete;
  Q& operator=(const Q&) = delete;
};
void sub(Q& r, const Q& a, const Q& b) { mpq_sub(r.v, a.v, b.v); }
void mul(Q& r, const Q& a, const Q& b) { mpq_mul(r.v, a.v, b.v); }

int orientQ(double ax, double ay, double bx, double by, double cx, double cy) {
  Q A(ax), B(ay), C(bx), D(by), E(cx), F(cy), t1, t2, t3, t4;
  sub(t1, A, E), sub(t2, D, F), mul(t3, t1, t2);
  sub(t1, B, F), sub(t2, C, E), mul(t4, t1, t2);
  sub(t1, t3, t4);
  return mpq_sgn(t1.v);
}

// Expansion along d's row of the 4x4 determinant |x y x^2+y^2 1|, independent of the 3x3 form.
int incircleQ(const double* p) {
  Q x[4], y[4], w[4], t, u, det, m;
  for (int i = 0; i < 4; ++i) {
    mpq_set_d(x[i].v, p[2 * i]), mpq_set_d(y[i].v, p[2 * i + 1]);
    mul(t, x[i], x[i]), mul(u, y[i], y[i]), mpq_add(w[i].v, t.v, u.v);
  }
  // det = sum over i of (-1)^i * |x y w| of the other three rows, times the column of ones.
  for (int i = 0; i < 4; ++i) {
    int r[3], k = 0;
    for (int j = 0; j < 4; ++j)
      if (j != i) r[k++] = j;
    Q a, b, c;
    mul(t, y[r[1]], w[r[2]]), mul(u, y[r[2]], w[r[1]]), sub(a, t, u), mul(a, a, x[r[0]]);
    mul(t, x[r[1]], w[r[2]]), mul(u, x[r[2]], w[r[1]]), sub(b, t, u), mul(b, b, y[r[0]]);
    mul(t, x[r[1]], y[r[2]]), mul(u, x[r[2]], y[r[1]]), sub(c, t, u), mul(c, c, w[r[0]]);
    sub(m, a, b), mpq_add(m.v, m.v, c.v);
    // |x y w 1| = -M0 + M1 - M2 + M3 where Mi is the minor without row i (expansion on the ones)
    if (i % 2 == 0)
      mpq_sub(det.v, det.v, m.v);
    else
      mpq_add(det.v, det.v, m.v);
  }
  return mpq_sgn(det.v);  // subtracting row d from the others gives the 3x3 form of incircle()
}

double scaled(std::mt19937_64& g, int emax) {
  std::uniform_real_distribution<double> u(-1, 1);
  std::uniform_int_distribution<int> e(-emax, emax);
  return std::ldexp(u(g), e(g));
}

double nudge(double x, int k) {
  for (; k > 0; --k) x = std::nextafter(x, HUGE_VAL);
  for (; k < 0; ++k) x = std::nextafter(x, -HUGE_VAL);
  return x;
}

}  // namespace

TEST_CASE("2.3.1 robust orient2d equals the exact oracle on 1.2 million near-collinear inputs") {
  std::mt19937_64 g(2301);
  std::uniform_int_distribution<int> fam(0, 3), k(-3, 3), e(-500, 500), small(-4, 4);
  std::uniform_real_distribution<double> t(-2, 3);
  long wrong = 0, filtered = 0, exact = 0;
  const long N = 1200000;
  for (long it = 0; it < N; ++it) {
    double a[2], b[2], c[2];
    switch (fam(g)) {
      case 0:  // one scale, mixed signs
        for (int q = 0; q < 2; ++q) a[q] = scaled(g, 2), b[q] = scaled(g, 2);
        break;
      case 1:  // each point at its own scale: wide exponent ranges
        a[0] = scaled(g, 0), a[1] = scaled(g, 0);
        b[0] = std::ldexp(scaled(g, 0), e(g)), b[1] = std::ldexp(scaled(g, 0), e(g));
        break;
      case 2:  // tiny and huge, near underflow and overflow of the products
        for (int q = 0; q < 2; ++q) a[q] = std::ldexp(scaled(g, 4), e(g) > 0 ? 500 : -520),
                                    b[q] = a[q] * (1 + t(g));
        break;
      default:  // exactly collinear small integers, some nudged by one ulp
        a[0] = small(g), a[1] = small(g), b[0] = small(g), b[1] = small(g);
        break;
    }
    const double s = t(g);
    c[0] = nudge(a[0] + s * (b[0] - a[0]), k(g) / 2);
    c[1] = nudge(a[1] + s * (b[1] - a[1]), k(g) / 2);
    if (!(std::isfinite(c[0]) && std::isfinite(c[1]))) continue;
    const int r = orient2d(a[0], a[1], b[0], b[1], c[0], c[1]);
    (lastPredicateStage() == 0 ? filtered : exact)++;
    wrong += r != orient2dExact(a[0], a[1], b[0], b[1], c[0], c[1]);
  }
  CHECK(wrong == 0);
  // Both stages were exercised, so the agreement says something about each.
  CHECK(filtered > N / 10);
  CHECK(exact > N / 10);
}

TEST_CASE("2.3.1 robust incircle equals the exact oracle on 1 million near-cocircular inputs") {
  std::mt19937_64 g(2302);
  std::uniform_int_distribution<int> fam(0, 2), k(-2, 2), e(-250, 250), ex(150, 260), mm(1, 1 << 20);
  std::uniform_real_distribution<double> ang(0, 2 * M_PI);
  const auto P = cocircularIntegerPoints();
  std::uniform_int_distribution<std::size_t> pick(0, P.size() - 1);
  long wrong = 0, filtered = 0, exact = 0;
  const long N = 1000000;
  for (long it = 0; it < N; ++it) {
    double v[8];
    switch (fam(g)) {
      case 0: {  // rounded cos/sin on a circle of random centre and radius, scales 2^-250..2^250
        const double s = std::ldexp(1.0, e(g)), cx = scaled(g, 1) * s, cy = scaled(g, 1) * s;
        const double r = s * (0.25 + std::fabs(scaled(g, 0)));
        for (int p = 0; p < 4; ++p) {
          // every other time d is moved off the circle by about 2^-30 r: a decidable case
          const double rp = (p == 3 && it % 2) ? r * (1 + std::ldexp(scaled(g, 0), -30)) : r;
          const double a = ang(g);
          v[2 * p] = nudge(cx + rp * std::cos(a), k(g));
          v[2 * p + 1] = nudge(cy + rp * std::sin(a), k(g));
        }
        break;
      }
      case 1: {  // exactly cocircular 51-bit integers, scaled by a power of two, one nudged
        const double s = std::ldexp(1.0, e(g));
        for (int p = 0; p < 4; ++p) {
          const auto& q = P[pick(g)];
          v[2 * p] = q.first * s, v[2 * p + 1] = q.second * s;
        }
        const int q = int(pick(g) % 8);
        v[q] = nudge(v[q], k(g));
        break;
      }
      default: {  // a zero coordinate of a cocircular quadruple made tiny: 250-bit differences
        const double base[8] = {3, 4, -5, 0, 0, 5, 4, -3};
        for (int q = 0; q < 8; ++q) v[q] = base[q];
        v[(mm(g) & 1) ? 3 : 4] = ((mm(g) & 1) ? -1 : 1) * std::ldexp(double(mm(g)), -ex(g));
        break;
      }
    }
    const int r = incircle(v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7]);
    (lastPredicateStage() == 0 ? filtered : exact)++;
    wrong += r != incircleExact(v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7]);
  }
  CHECK(wrong == 0);
  CHECK(filtered > N / 10);
  CHECK(exact > N / 10);
}

TEST_CASE("2.3.1 the exact oracle agrees with an independent rational evaluation from 1e-300 to 1e300") {
  std::mt19937_64 g(2303);
  std::uniform_int_distribution<int> e(-1000, 1000);
  long wrong = 0;
  for (int it = 0; it < 40000; ++it) {
    double v[8];
    for (double& x : v) x = std::ldexp(scaled(g, 0), e(g) % (it % 2 ? 1000 : 30));
    if (it % 3 == 0) v[4] = v[0], v[5] = v[1] + (v[3] - v[1]);  // some exact degeneracies
    wrong += orient2dExact(v[0], v[1], v[2], v[3], v[4], v[5]) != orientQ(v[0], v[1], v[2], v[3], v[4], v[5]);
    if (it % 4 == 0)
      wrong += incircleExact(v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7]) != incircleQ(v);
  }
  const auto P = cocircularIntegerPoints();
  const double q[8] = {P[1].first, P[1].second, P[40].first, P[40].second,
                       P[500].first, P[500].second, P[900].first, P[900].second};
  CHECK(incircleQ(q) == 0);
  CHECK(incircleExact(q[0], q[1], q[2], q[3], q[4], q[5], q[6], q[7]) == 0);
  CHECK(wrong == 0);
}

TEST_CASE("2.3.1 Figure 2.7: the grid holds 256 consecutive doubles 1/2 + i 2^-53 (not rounded away)") {
  for (int i = 0; i < Figure27::n; ++i) {
    const double x = Figure27::x0 + i * Figure27::eps;
    CHECK(x - 0.5 == std::ldexp(double(i), -53));
    if (i > 0) CHECK(x == std::nextafter(Figure27::x0 + (i - 1) * Figure27::eps, 1.0));
  }
}

TEST_CASE("2.3.1 Figure 2.7: the naive maps are wrong near the diagonal 'even at 20 ulps' from it") {
  const SignMap exABC = orientMap(orient2dExact, OrientOrder::ABC);
  const SignMap exCBA = orientMap(orient2dExact, OrientOrder::CBA);
  const MapErrors l = compareMaps(orientMap(orient2dNaive, OrientOrder::ABC), exABC);
  const MapErrors r = compareMaps(orientMap(orient2dNaive, OrientOrder::CBA), exCBA);
  // Deterministic (IEEE binary64, round to nearest, no contraction): the counts the book prints.
  CHECK(l.wrong == 11492);
  CHECK(l.wrongZeros == 11492);  // pivot c: both products in one binade, rounding only merges
  CHECK(l.flipped == 0);
  CHECK(l.farthest == 63);
  CHECK(r.wrong == 11972);
  CHECK(r.flipped == 672);  // pivot a: rounded differences can flip the sign
  CHECK(r.farthest == 78);
  CHECK(l.farthest > 20);  // the notes' "20 times the significand precision" is an understatement
  CHECK(l.spurious == 0);
  CHECK(r.spurious == 0);
}

TEST_CASE("2.3.1 O(c b a) = -O(a b c) exactly (the notes say 'the same') and naive breaks it while O(b c a) does not") {
  const SignMap eABC = orientMap(orient2dExact, OrientOrder::ABC);
  const SignMap eCBA = orientMap(orient2dExact, OrientOrder::CBA);
  const SignMap eBCA = orientMap(orient2dExact, OrientOrder::BCA);
  const SignMap nABC = orientMap(orient2dNaive, OrientOrder::ABC);
  const SignMap nCBA = orientMap(orient2dNaive, OrientOrder::CBA);
  const SignMap nBCA = orientMap(orient2dNaive, OrientOrder::BCA);
  const long cells = 65536;
  CHECK(agreeingCells(eCBA, eABC, -1) == cells);
  CHECK(agreeingCells(eCBA, eABC, +1) == 256);  // only the diagonal, where both are 0
  CHECK(agreeingCells(eBCA, eABC, +1) == cells);
  CHECK(agreeingCells(nCBA, nABC, -1) == 53532);
  CHECK(agreeingCells(nCBA, nBCA, -1) == cells);  // same pivot a: negated bit for bit
  for (int j = 0; j < 256; j += 5)
    for (int i = 0; i < 256; i += 3) {
      const double ax = 0.5 + i * Figure27::eps, ay = 0.5 + j * Figure27::eps;
      CHECK(orient2dNaiveValue(24, 24, 12, 12, ax, ay) == -orient2dNaiveValue(12, 12, 24, 24, ax, ay));
    }
}

TEST_CASE("2.3.1 Figure 2.8: the robust maps are exact; 0 exactly on the diagonal") {
  for (OrientOrder o : {OrientOrder::ABC, OrientOrder::CBA, OrientOrder::BCA}) {
    const SignMap m = orientMap(orient2d, o);
    CHECK(compareMaps(m, orientMap(orient2dExact, o)).wrong == 0);
    for (int j = 0; j < m.n; ++j)
      for (int i = 0; i < m.n; ++i) CHECK_MESSAGE((m.at(i, j) == 0) == (i == j), i << "," << j);
  }
}

TEST_CASE("2.3.1 incircle maps: naive wrong and robust exact with only the corner cell on the circle") {
  const SignMap e1 = incircleMap(incircleExact, IncircleOrder::ABCD);
  const SignMap e2 = incircleMap(incircleExact, IncircleOrder::DCBA);
  CHECK(agreeingCells(e1, e2, 1) == 65536);  // an even permutation: the same exact map
  const MapErrors n1 = compareMaps(incircleMap(incircleNaive, IncircleOrder::ABCD), e1);
  const MapErrors n2 = compareMaps(incircleMap(incircleNaive, IncircleOrder::DCBA), e2);
  CHECK(n1.wrong == 17205);
  CHECK(n1.flipped == 7684);
  CHECK(n2.wrong == 14367);
  CHECK(n2.flipped == 4892);
  CHECK(compareMaps(incircleMap(incircle, IncircleOrder::ABCD), e1).wrong == 0);
  CHECK(compareMaps(incircleMap(incircle, IncircleOrder::DCBA), e2).wrong == 0);
  // Exactly: inside iff 24 (j - i) + (i^2 + j^2) eps < 0.
  for (int j = 0; j < e1.n; ++j)
    for (int i = 0; i < e1.n; ++i) {
      const int want = (i == 0 && j == 0) ? 0 : (j < i ? 1 : -1);
      if (e1.at(i, j) != want) FAIL_CHECK(i << "," << j);
    }
}

TEST_CASE("2.3.1 the notes' orientation filter (1e-15) lets wrong signs through: pinned cases") {
  // As printed, max(x_a, ..., y_c) is signed: Figure 2.7 turned by a half-turn has max = -1/2.
  const double eps = Figure27::eps;
  const double ax = -(0.5 + 55 * eps), ay = -(0.5 + 41 * eps);
  CHECK(orient2dExact(-24, -24, -12, -12, ax, ay) == 1);
  CHECK(orient2dNotes(-24, -24, -12, -12, ax, ay) == -1);
  CHECK(orient2dNotesAbs(-24, -24, -12, -12, ax, ay) == 1);
  CHECK(orient2d(-24, -24, -12, -12, ax, ay) == 1);
  // Even with max |coordinate|, 1e-15 max^2 is below the worst error (about 24u max^2).
  const double p[6] = {0x1.0000000000008p+0, 0x1.000000000000ep+0, 0x1.0000000000016p+0,
                       0x1.000000000001cp+0, -0x1.ffffffffffffep-1, -0x1.ffffffffffffep-1};
  CHECK(orient2dExact(p[0], p[1], p[2], p[3], p[4], p[5]) == -1);
  CHECK(orient2dNotesAbs(p[0], p[1], p[2], p[3], p[4], p[5]) == 1);
  CHECK(std::fabs(orient2dNaiveValue(p[0], p[1], p[2], p[3], p[4], p[5])) > 1e-15);
  CHECK(orient2d(p[0], p[1], p[2], p[3], p[4], p[5]) == -1);
  CHECK(lastPredicateStage() == 1);  // the safe bound sends it to the exact stage
}

TEST_CASE("2.3.1 the notes' incircle filter (1e-11) lets wrong signs through: signed max and underflow") {
  using C = IncircleConfig;
  const double eps = C::eps;
  // Turned by -90 degrees, (x, y) -> (y, -x): every coordinate but one is <= 0, signed max 1/2.
  {
    const double dx = C::x0 + 144 * eps, dy = C::y0 + 81 * eps;
    const double v[8] = {C::ay, -C::ax, C::by, -C::bx, C::cy, -C::cx, dy, -dx};
    CHECK(incircleExact(v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7]) == 1);
    CHECK(incircleNotes(v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7]) == -1);
    CHECK(incircle(v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7]) == 1);
  }
  // Scaled by 2^-273: the products are subnormal and the threshold 1e-11 max^4 underflows to 0.
  {
    const double s = 0x1p-273, dx = (C::x0 + 255 * eps) * s, dy = C::y0 * s;
    const double v[8] = {C::ax * s, C::ay * s, C::bx * s, C::by * s, C::cx * s, C::cy * s, dx, dy};
    CHECK(incircleExact(v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7]) == 1);
    CHECK(incircleNotesAbs(v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7]) == -1);
    CHECK(incircle(v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7]) == 1);
  }
}

TEST_CASE("2.3.1 200-bit MPFR is not exact: pinned counterexamples and enough bits fix them") {
  // orient2d, wrong zero: 1 - 2^-600 rounds to 1.
  CHECK(orient2dExact(1, 1, 2, 2, 0x1p-600, 0) == -1);
  CHECK(orient2dMPFR200(1, 1, 2, 2, 0x1p-600, 0) == 0);
  CHECK(orient2dNotes(1, 1, 2, 2, 0x1p-600, 0) == 0);
  CHECK(orient2d(1, 1, 2, 2, 0x1p-600, 0) == -1);
  CHECK(orient2dMPFR(exactBitsOrient2d(1, 1, 2, 2, 0x1p-600, 0), 1, 1, 2, 2, 0x1p-600, 0) == -1);
  // orient2d, flipped sign.
  const double c0 = -0x1.a87dep-196, c1 = -0x1.93e94p-196;
  CHECK(orient2dExact(1, 1, 2, 2, c0, c1) == 1);
  CHECK(orient2dMPFR200(1, 1, 2, 2, c0, c1) == -1);
  CHECK(orient2d(1, 1, 2, 2, c0, c1) == 1);
  CHECK(orient2dMPFR(exactBitsOrient2d(1, 1, 2, 2, c0, c1), 1, 1, 2, 2, c0, c1) == 1);
  // incircle, exactly cocircular 51-bit integers: MPFR-200 says "not on the circle".
  const double q[8] = {-0x1.d5c4532c089cp+46,  -0x1.c9412a59424fp+50, -0x1.c7be1bb5b0b64p+50,
                       -0x1.7ad5b19c0308p+47,  -0x1.117aa79ef20f8p+49, 0x1.b5511f085e72p+50,
                       0x1.2f1a7b32911fcp+50,  0x1.579dbc83a81cp+50};
  CHECK(incircleExact(q[0], q[1], q[2], q[3], q[4], q[5], q[6], q[7]) == 0);
  CHECK(incircleMPFR200(q[0], q[1], q[2], q[3], q[4], q[5], q[6], q[7]) == -1);
  CHECK(incircle(q[0], q[1], q[2], q[3], q[4], q[5], q[6], q[7]) == 0);
  CHECK(incircleMPFR(exactBitsIncircle(q[0], q[1], q[2], q[3], q[4], q[5], q[6], q[7]), q[0], q[1],
                     q[2], q[3], q[4], q[5], q[6], q[7]) == 0);
  // incircle, flipped sign: one zero coordinate of (3,4), (-5,0), (0,5), (4,-3) made tiny.
  const double w[8] = {3, 4, -5, 0, 0x1.6a2p-196, 5, 4, -3};
  CHECK(incircleExact(w[0], w[1], w[2], w[3], w[4], w[5], w[6], w[7]) == 1);
  CHECK(incircleMPFR200(w[0], w[1], w[2], w[3], w[4], w[5], w[6], w[7]) == -1);
  CHECK(incircle(w[0], w[1], w[2], w[3], w[4], w[5], w[6], w[7]) == 1);
}

TEST_CASE("2.3.1 exercise 2: exactBits bits make MPFR exact on wide random inputs") {
  std::mt19937_64 g(2304);
  std::uniform_int_distribution<int> e(-300, 300);
  long wrong = 0;
  for (int it = 0; it < 3000; ++it) {
    double v[8];
    for (double& x : v) x = std::ldexp(scaled(g, 0), e(g));
    v[4] = v[0] + 0.5 * (v[2] - v[0]), v[5] = v[1] + 0.5 * (v[3] - v[1]);  // near-collinear
    wrong += orient2dMPFR(exactBitsOrient2d(v[0], v[1], v[2], v[3], v[4], v[5]), v[0], v[1], v[2],
                          v[3], v[4], v[5]) != orient2dExact(v[0], v[1], v[2], v[3], v[4], v[5]);
    wrong += incircleMPFR(exactBitsIncircle(v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7]), v[0],
                          v[1], v[2], v[3], v[4], v[5], v[6], v[7]) !=
             incircleExact(v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7]);
  }
  CHECK(wrong == 0);
  CHECK(exactBitsOrient2d(1.5, 1.25, 1.75, 1.125, 1.0, 1.875) == 109);  // one binade: 2*53 + 3
  CHECK(exactBitsIncircle(1.5, 1.25, 1.75, 1.125, 1.0, 1.875, 1.5, 1.5) == 220);  // > 200
}

TEST_CASE("2.3.1 exercise 1: sorting the points makes the naive test consistent but not correct") {
  const SignMap ex = orientMap(orient2dExact, OrientOrder::ABC);
  const SignMap abc = orientMap(orient2dNaiveCanonical, OrientOrder::ABC);
  const SignMap cba = orientMap(orient2dNaiveCanonical, OrientOrder::CBA);
  const SignMap bca = orientMap(orient2dNaiveCanonical, OrientOrder::BCA);
  CHECK(agreeingCells(cba, abc, -1) == 65536);
  CHECK(agreeingCells(bca, abc, 1) == 65536);
  CHECK(compareMaps(abc, ex).wrong > 0);
}

TEST_CASE("2.3.1 exercise 3: segment intersection with proper crossings (the notes) and touching cases") {
  // proper crossing: both agree
  CHECK(segmentsCrossNotes(0, 0, 2, 2, 0, 2, 2, 0));
  CHECK(segmentsIntersect(0, 0, 2, 2, 0, 2, 2, 0));
  // T-junction, shared endpoint, collinear overlap: the notes' test says no
  CHECK_FALSE(segmentsCrossNotes(0, 0, 2, 0, 1, 0, 1, 5));
  CHECK(segmentsIntersect(0, 0, 2, 0, 1, 0, 1, 5));
  CHECK(segmentsIntersect(0, 0, 1, 1, 1, 1, 2, 0));
  CHECK(segmentsIntersect(0, 0, 3, 3, 1, 1, 5, 5));
  CHECK_FALSE(segmentsIntersect(0, 0, 1, 1, 2, 2, 3, 3));  // collinear, disjoint
  CHECK_FALSE(segmentsIntersect(0, 0, 1, 0, 0, 1, 1, 1));  // parallel
  // zero-length segments
  CHECK(segmentsIntersect(1, 1, 1, 1, 0, 0, 2, 2));
  CHECK_FALSE(segmentsIntersect(1, 1, 1, 1, 0, 0, 2, 2.5));
  CHECK(segmentsIntersect(1, 1, 1, 1, 1, 1, 1, 1));
  CHECK_FALSE(segmentsIntersect(1, 1, 1, 1, 1, 2, 1, 2));
  // near-degenerate: the endpoint 1/2 + 2^-53 beside the line through (12,12), (24,24)
  const double e = 0x1p-53;
  CHECK_FALSE(segmentsIntersect(0.5 + e, 0.5, 0.5 + e, 0.5, 12, 12, 24, 24));
  CHECK(segmentsIntersect(0.5 + e, 0.5 + e, 0.5 + e, 0.5 + e, 0.25, 0.25, 24, 24));
}
