// An exact oracle for the predicates of section 2.3.1 that shares no code with the predicate
// core (code/predicates/predicates_inline.h, code/predicates/predicates.cpp): GMP rationals, the determinants as the
// notes write them. Every finite double is a rational, and mpq_set_d converts it exactly, so
// the sign below is the true sign for any input, subnormals and 2^1000 included.
//
// Also: the hard inputs the exactness tests draw from (exactly collinear and cocircular points
// on lattices and on x^2 + y^2 = r^2, scaled by powers of two from 2^-1074 to 2^960, the same
// moved by one or two ulps, mixed signs, exponent spreads, subnormals), so that every stage of
// the core has work to do.
#pragma once

#include <gmp.h>

#include <cmath>
#include <cstdint>
#include <random>
#include <utility>
#include <vector>

namespace dtoracle {

/// A GMP rational with RAII; Q(d) is exactly the double d.
struct Q {
  mpq_t v;
  Q() { mpq_init(v); }
  explicit Q(double d) { mpq_init(v), mpq_set_d(v, d); }
  ~Q() { mpq_clear(v); }
  Q(const Q&) = delete;
  Q& operator=(const Q&) = delete;
};
inline void sub(Q& r, const Q& a, const Q& b) { mpq_sub(r.v, a.v, b.v); }
inline void mul(Q& r, const Q& a, const Q& b) { mpq_mul(r.v, a.v, b.v); }

/// The notes' orientation, exactly: sign((xa - xc)(yb - yc) - (ya - yc)(xb - xc)).
inline int orientQ(double ax, double ay, double bx, double by, double cx, double cy) {
  Q A(ax), B(ay), C(bx), D(by), E(cx), F(cy), t1, t2, t3, t4;
  sub(t1, A, E), sub(t2, D, F), mul(t3, t1, t2);
  sub(t1, B, F), sub(t2, C, E), mul(t4, t1, t2);
  sub(t1, t3, t4);
  return mpq_sgn(t1.v);
}

/// Incircle as the 4x4 determinant |x y x^2+y^2 1| of a, b, c, d (p = xa ya xb yb xc yc xd yd),
/// expanded along the column of ones: a different formula from the core's 3x3 lifted form
/// pivoted on d. Positive iff d is inside the circle of a counter-clockwise a, b, c.
inline int incircleQ(const double* p) {
  Q x[4], y[4], w[4], t, u, det, m;
  for (int i = 0; i < 4; ++i) {
    mpq_set_d(x[i].v, p[2 * i]), mpq_set_d(y[i].v, p[2 * i + 1]);
    mul(t, x[i], x[i]), mul(u, y[i], y[i]), mpq_add(w[i].v, t.v, u.v);
  }
  for (int i = 0; i < 4; ++i) {
    int r[3], k = 0;
    for (int j = 0; j < 4; ++j)
      if (j != i) r[k++] = j;
    Q a, b, c;
    mul(t, y[r[1]], w[r[2]]), mul(u, y[r[2]], w[r[1]]), sub(a, t, u), mul(a, a, x[r[0]]);
    mul(t, x[r[1]], w[r[2]]), mul(u, x[r[2]], w[r[1]]), sub(b, t, u), mul(b, b, y[r[0]]);
    mul(t, x[r[1]], y[r[2]]), mul(u, x[r[2]], y[r[1]]), sub(c, t, u), mul(c, c, w[r[0]]);
    sub(m, a, b), mpq_add(m.v, m.v, c.v);
    // |x y w 1| = -M0 + M1 - M2 + M3, Mi the 3x3 minor without row i.
    if (i % 2 == 0)
      mpq_sub(det.v, det.v, m.v);
    else
      mpq_add(det.v, det.v, m.v);
  }
  return mpq_sgn(det.v);
}

// ---- hard inputs ----------------------------------------------------------------------------

inline double nudge(double x, int k) {
  for (; k > 0; --k) x = std::nextafter(x, HUGE_VAL);
  for (; k < 0; ++k) x = std::nextafter(x, -HUGE_VAL);
  return x;
}

/// All integer points of x^2 + y^2 = r^2 for r = 5 13 17 29 37 = 1185665 (a product of primes
/// 1 mod 4: 972 points, coordinates below 2^21).
inline const std::vector<std::pair<long, long>>& pythagoreanPoints() {
  static const std::vector<std::pair<long, long>> P = [] {
    std::vector<std::pair<long, long>> v;
    const long r = 5L * 13 * 17 * 29 * 37, r2 = r * r;
    for (long x = -r; x <= r; ++x) {
      const long y2 = r2 - x * x;
      long y = std::lround(std::sqrt(double(y2)));
      while (y * y > y2) --y;
      while ((y + 1) * (y + 1) <= y2) ++y;
      if (y * y != y2) continue;
      v.push_back({x, y});
      if (y != 0) v.push_back({x, -y});
    }
    return v;
  }();
  return P;
}

/// Random hard inputs, one family per call (family() says which, for the reports).
class HardInputs {
 public:
  explicit HardInputs(std::uint64_t seed) : g_(seed) {}
  int family() const { return family_; }
  static constexpr int kOrientFamilies = 9;
  static constexpr int kIncircleFamilies = 9;
  static const char* orientName(int f) {
    static const char* n[] = {"collinear lattice", "lattice moved 1-2 ulps", "rounded near-collinear",
                              "exponent spread 2^-1000..2^1000", "subnormal",
                              "near (1,1) and (-1,-1), ulps apart", "underflowing products",
                              "whole range 2^-1074..2^1023", "generic"};
    return n[f];
  }
  static const char* incircleName(int f) {
    static const char* n[] = {"Pythagorean r = 1185665", "Pythagorean moved 1-2 ulps",
                              "lattice rectangle", "rounded circle", "exponent spread",
                              "subnormal", "rounded circle, underflowing products",
                              "whole range 2^-1074..2^1023", "generic"};
    return n[f];
  }

  /// a b c as v[0..5].
  void orient(double* v) {
    family_ = pick(kOrientFamilies);
    switch (family_) {
      case 0:
      case 1:
      case 4: {
        // a + s dir, a + t dir: exactly collinear integers below 2^37, mixed signs.
        const int k = uni(1, 24);
        const long ax = luni(-(1L << k), 1L << k), ay = luni(-(1L << k), 1L << k);
        long dx = 0, dy = 0;
        while (dx == 0 && dy == 0) dx = uni(-60, 60), dy = uni(-60, 60);
        const long s = luni(-(1L << uni(0, 11)), 1L << 11), t = luni(-(1L << 11), 1L << uni(0, 11));
        const long w[6] = {ax, ay, ax + s * dx, ay + s * dy, ax + t * dx, ay + t * dy};
        const int e = family_ == 4 ? uni(-1074, -1040) : uni(0, 1) ? uni(-250, 170) : uni(-1000, 960);
        for (int i = 0; i < 6; ++i) v[i] = std::ldexp(double(w[i]), e);
        if (family_ != 0) {
          const int i = uni(0, 5);
          v[i] = nudge(v[i], uni(0, 1) ? uni(1, 2) : -uni(1, 2));
        }
        break;
      }
      case 2: {  // c = a + t (b - a) rounded, then moved by -1..1 ulp: one scale, mixed signs
        const int e = uni(-900, 900);
        for (int i = 0; i < 4; ++i) v[i] = std::ldexp(real(), e);
        const double t = 3 * real() + 0.5;
        v[4] = nudge(v[0] + t * (v[2] - v[0]), uni(-1, 1));
        v[5] = nudge(v[1] + t * (v[3] - v[1]), uni(-1, 1));
        break;
      }
      case 3: {  // each coordinate at its own scale, c on the line through a and b, rounded
        for (int i = 0; i < 4; ++i) v[i] = std::ldexp(real(), uni(-1000, 1000));
        const double t = 3 * real() + 0.5;
        v[4] = nudge(v[0] + t * (v[2] - v[0]), uni(-1, 1));
        v[5] = nudge(v[1] + t * (v[3] - v[1]), uni(-1, 1));
        break;
      }
      case 5: {  // a, b near (1, 1), c near (-1, -1), ulps apart: the largest rounding errors
        const double s = std::ldexp(1.0, uni(-20, 20));
        v[0] = (std::nextafter(1.0, 0.0) - uni(-40, 40) * 0x1p-53) * s;
        v[1] = (1 - uni(-40, 40) * 0x1p-53) * s;
        v[2] = v[0] + uni(-40, 40) * 0x1p-52 * s, v[3] = v[1] + uni(-40, 40) * 0x1p-52 * s;
        v[4] = (-1 + uni(0, 80) * 0x1p-53) * s, v[5] = (-1 + uni(0, 80) * 0x1p-53) * s;
        break;
      }
      case 6: {  // rounded near-collinear at 2^-560..2^-500: products near the subnormals
        const int e = uni(-560, -500);
        for (int i = 0; i < 4; ++i) v[i] = std::ldexp(real(), e);
        const double t = 3 * real() + 0.5;
        v[4] = nudge(v[0] + t * (v[2] - v[0]), uni(-2, 2));
        v[5] = nudge(v[1] + t * (v[3] - v[1]), uni(-2, 2));
        break;
      }
      case 7:  // every coordinate at its own exponent anywhere in the range (overflow, underflow)
        for (int i = 0; i < 6; ++i) v[i] = std::ldexp(real(), uni(-1074, 1023));
        break;
      default:
        for (int i = 0; i < 6; ++i) v[i] = std::ldexp(real(), uni(-2, 2));
    }
  }

  /// a b c d as v[0..7].
  void incircle(double* v) {
    family_ = pick(kIncircleFamilies);
    const auto& P = pythagoreanPoints();
    switch (family_) {
      case 0:
      case 1: {  // four distinct points of the circle, translated, scaled by 2^e
        std::size_t idx[4];
        for (int i = 0; i < 4; ++i) {
          bool fresh = false;
          while (!fresh) {
            idx[i] = std::size_t(luni(0, long(P.size()) - 1));
            fresh = true;
            for (int j = 0; j < i; ++j) fresh = fresh && idx[j] != idx[i];
          }
        }
        const long cx = luni(-(1L << 30), 1L << 30), cy = luni(-(1L << 30), 1L << 30);
        const int e = uni(-1000, 960);
        for (int i = 0; i < 4; ++i) {
          v[2 * i] = std::ldexp(double(P[idx[i]].first + cx), e);
          v[2 * i + 1] = std::ldexp(double(P[idx[i]].second + cy), e);
        }
        if (family_ == 1) {
          const int i = uni(0, 7);
          v[i] = nudge(v[i], uni(0, 1) ? uni(1, 2) : -uni(1, 2));
        }
        break;
      }
      case 2: {  // the corners of a lattice rectangle (cocircular), in random order, some moved
        const long x0 = uni(-1000, 1000), y0 = uni(-1000, 1000), w = uni(1, 1000), h = uni(1, 1000);
        long c[8] = {x0, y0, x0 + w, y0, x0 + w, y0 + h, x0, y0 + h};
        for (int i = 3; i > 0; --i) {
          const int j = uni(0, i);
          std::swap(c[2 * i], c[2 * j]), std::swap(c[2 * i + 1], c[2 * j + 1]);
        }
        const int e = uni(0, 1) ? uni(-250, 190) : uni(-1000, 1000);
        for (int i = 0; i < 8; ++i) v[i] = std::ldexp(double(c[i]), e);
        if (uni(0, 3) == 0) {
          const int i = uni(0, 7);
          v[i] = nudge(v[i], uni(0, 1) ? 1 : -1);
        }
        break;
      }
      case 3: {  // rounded cos/sin on a circle of random centre and radius, moved by 0-2 ulps
        const int e = uni(-250, 250);
        const double s = std::ldexp(1.0, e), ox = real() * s, oy = real() * s;
        const double r = s * (0.25 + std::fabs(real()));
        for (int i = 0; i < 4; ++i) {
          const double a = 6.283185307179586 * (0.5 + 0.5 * real());
          v[2 * i] = nudge(ox + r * std::cos(a), uni(-2, 2));
          v[2 * i + 1] = nudge(oy + r * std::sin(a), uni(-2, 2));
        }
        break;
      }
      case 4: {  // a cocircular quadruple with a zero coordinate made tiny: huge exponent spread
        const double base[8] = {3, 4, -5, 0, 0, 5, 4, -3};
        const int e = uni(-400, 400);
        for (int i = 0; i < 8; ++i) v[i] = std::ldexp(base[i], e);
        v[uni(0, 1) ? 3 : 4] = (uni(0, 1) ? -1 : 1) * std::ldexp(double(uni(1, 1 << 20)), e - uni(60, 600));
        break;
      }
      case 5: {  // multiples of the smallest subnormal: cocircular, some moved by an ulp
        const double base[8] = {3, 4, -5, 0, 0, 5, 4, -3};
        const double m = uni(1, 1 << 12);
        for (int i = 0; i < 8; ++i) v[i] = std::ldexp(base[i] * m, -1074);
        if (uni(0, 1)) {
          const int i = uni(0, 7);
          v[i] = nudge(v[i], uni(0, 1) ? 1 : -1);
        }
        break;
      }
      case 6: {  // rounded circle at 2^-290..2^-250: degree-4 products near the subnormals
        const double s = std::ldexp(1.0, uni(-290, -250)), ox = real() * s, oy = real() * s;
        const double r = s * (0.25 + std::fabs(real()));
        for (int i = 0; i < 4; ++i) {
          const double a = 6.283185307179586 * (0.5 + 0.5 * real());
          v[2 * i] = nudge(ox + r * std::cos(a), uni(-2, 2));
          v[2 * i + 1] = nudge(oy + r * std::sin(a), uni(-2, 2));
        }
        break;
      }
      case 7:  // every coordinate at its own exponent anywhere in the range (overflow, underflow)
        for (int i = 0; i < 8; ++i) v[i] = std::ldexp(real(), uni(-1074, 1023));
        break;
      default:
        for (int i = 0; i < 8; ++i) v[i] = std::ldexp(real(), uni(-2, 2));
    }
  }

 private:
  std::mt19937_64 g_;
  int family_ = 0;
  int uni(int a, int b) { return std::uniform_int_distribution<int>(a, b)(g_); }
  long luni(long a, long b) { return std::uniform_int_distribution<long>(a, b)(g_); }
  double real() { return std::uniform_real_distribution<double>(-1, 1)(g_); }
  // The generic family is drawn half as often as each hard one.
  int pick(int families) {
    const int f = uni(0, 2 * families - 2);
    return f / 2;
  }
};

}  // namespace dtoracle
