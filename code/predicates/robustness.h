// Section 2.3.1 as functions: the sign maps of Figures 2.7-2.8 and of the incircle test, their
// comparison with the exact oracle, and the solutions of the section's exercises. Shared by
// the chapter program sec2_3_1_predicates and by tests/test_2_3_1_predicates.cpp, so that the
// tests check the very maps the figures show.
#pragma once

#include <utility>
#include <vector>

namespace dt {

using OrientFn = int (*)(double, double, double, double, double, double);
using IncircleFn = int (*)(double, double, double, double, double, double, double, double);

/// Signs on an n x n grid of cells; cell (i, j) is the moving point (x0 + i eps, y0 + j eps).
struct SignMap {
  int n = 0;
  std::vector<signed char> s;  ///< row-major: s[j * n + i]
  int at(int i, int j) const { return s[static_cast<std::size_t>(j) * n + i]; }
};

/// The configuration of Figure 2.7 (after Kettner et al., "Classroom examples of robustness
/// problems"): b(12,12), c(24,24), a(1/2 + i eps, 1/2 + j eps), eps = 2^-53, 0 <= i, j < 256.
/// ulp(1/2) = 2^-53, so the 256 abscissas are 256 consecutive doubles, each exactly 1/2 + i eps.
struct Figure27 {
  static constexpr double bx = 12, by = 12, cx = 24, cy = 24;
  static constexpr double x0 = 0.5, y0 = 0.5, eps = 0x1p-53;
  static constexpr int n = 256;
};

/// Which argument order a map evaluates: O(a,b,c) (pivot c, as in the notes' formula),
/// O(c,b,a) (pivot a) or O(b,c,a) (pivot a).
enum class OrientOrder { ABC, CBA, BCA };

/// The map of Figure 2.7 / 2.8: f evaluated with the points in the given order.
SignMap orientMap(OrientFn f, OrientOrder order, int n = Figure27::n, double eps = Figure27::eps);

/// The incircle counterpart: a(1/2, -47/2), b(49/2, -47/2), c(49/2, 1/2) counter-clockwise on the
/// circle of centre (25/2, -23/2) through d0(1/2, 1/2), whose tangent at d0 is the diagonal;
/// d(1/2 + i eps, 1/2 + j eps). Exactly, d is inside iff 24 (j - i) + (i^2 + j^2) eps < 0: inside
/// below the diagonal, outside on and above it, on the circle only at i = j = 0.
struct IncircleConfig {
  static constexpr double ax = 0.5, ay = -23.5, bx = 24.5, by = -23.5, cx = 24.5, cy = 0.5;
  static constexpr double x0 = 0.5, y0 = 0.5, eps = 0x1p-53;
  static constexpr int n = 256;
};

/// InC(a,b,c,d) (pivot d, the moving point) or InC(d,c,b,a) (pivot a). The second order is an
/// even permutation of the first: exactly, the two maps are the same.
enum class IncircleOrder { ABCD, DCBA };

SignMap incircleMap(IncircleFn f, IncircleOrder order, int n = IncircleConfig::n,
                    double eps = IncircleConfig::eps);

/// How a map differs from the exact one. "Wrong zero": 0 where the exact sign is not 0;
/// "flipped": the opposite nonzero sign; "spurious": nonzero where the exact sign is 0.
struct MapErrors {
  long cells = 0, wrong = 0, wrongZeros = 0, flipped = 0, spurious = 0;
  int farthest = -1;     ///< max |i - j| over the wrong cells (-1: none)
  int fi = -1, fj = -1;  ///< one wrong cell at that distance
};
MapErrors compareMaps(const SignMap& got, const SignMap& exact);

/// Number of cells where a = factor * b (factor +1 or -1).
long agreeingCells(const SignMap& a, const SignMap& b, int factor);

/// Integer points on the circle x^2 + y^2 = r^2, r = 5^12 13^4 17^2 (about 2^50.8), all exactly
/// representable: any four are exactly cocircular, and the incircle terms outgrow 200-bit MPFR.
std::vector<std::pair<double, double>> cocircularIntegerPoints();

// ---- exercises of section 2.3.1 (the book states them; tests check the solutions) -------------

/// Exercise 2.3.1-1: a naive orientation (doubles, no filter) that is consistent under
/// permutations: f(a,b,c) = f(b,c,a) = -f(c,b,a) bit for bit.
int orient2dNaiveCanonical(double ax, double ay, double bx, double by, double cx, double cy);

/// Exercise 2.3.1-3: do the closed segments [p,q] and [r,s] share a point? Exact, for all doubles,
/// including touching endpoints, collinear overlaps and zero-length segments. The notes'
/// criterion O(p,q,r) O(p,q,s) < 0 and O(r,s,p) O(r,s,q) < 0 sees proper crossings only.
bool segmentsIntersect(double px, double py, double qx, double qy, double rx, double ry,
                       double sx, double sy);
/// The notes' criterion, with the robust orientation: true only for a proper crossing.
bool segmentsCrossNotes(double px, double py, double qx, double qy, double rx, double ry,
                        double sx, double sy);

}  // namespace dt
