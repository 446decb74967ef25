#include "robustness.h"

#include <algorithm>
#include <cstdlib>
#include <stdexcept>
#include <utility>

#include "predicates.h"

namespace dt {

SignMap orientMap(OrientFn f, OrientOrder order, int n, double eps) {
  using C = Figure27;
  SignMap m;
  m.n = n;
  m.s.resize(static_cast<std::size_t>(n) * n);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const double ax = C::x0 + i * eps, ay = C::y0 + j * eps;  // exact: i eps is a multiple of ulp
      int v = 0;
      switch (order) {
        case OrientOrder::ABC: v = f(ax, ay, C::bx, C::by, C::cx, C::cy); break;
        case OrientOrder::CBA: v = f(C::cx, C::cy, C::bx, C::by, ax, ay); break;
        case OrientOrder::BCA: v = f(C::bx, C::by, C::cx, C::cy, ax, ay); break;
      }
      m.s[static_cast<std::size_t>(j) * n + i] = static_cast<signed char>(v);
    }
  return m;
}

SignMap incircleMap(IncircleFn f, IncircleOrder order, int n, double eps) {
  using C = IncircleConfig;
  SignMap m;
  m.n = n;
  m.s.resize(static_cast<std::size_t>(n) * n);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const double dx = C::x0 + i * eps, dy = C::y0 + j * eps;
      const int v = order == IncircleOrder::ABCD
                        ? f(C::ax, C::ay, C::bx, C::by, C::cx, C::cy, dx, dy)
                        : f(dx, dy, C::cx, C::cy, C::bx, C::by, C::ax, C::ay);
      m.s[static_cast<std::size_t>(j) * n + i] = static_cast<signed char>(v);
    }
  return m;
}

MapErrors compareMaps(const SignMap& got, const SignMap& exact) {
  MapErrors e;
  for (int j = 0; j < got.n; ++j)
    for (int i = 0; i < got.n; ++i) {
      ++e.cells;
      const int g = got.at(i, j), x = exact.at(i, j);
      if (g == x) continue;
      ++e.wrong;
      if (g == 0)
        ++e.wrongZeros;
      else if (x == 0)
        ++e.spurious;
      else
        ++e.flipped;
      if (std::abs(i - j) > e.farthest) {
        e.farthest = std::abs(i - j);
        e.fi = i;
        e.fj = j;
      }
    }
  return e;
}

long agreeingCells(const SignMap& a, const SignMap& b, int factor) {
  long k = 0;
  for (std::size_t c = 0; c < a.s.size(); ++c) k += a.s[c] == factor * b.s[c];
  return k;
}

// Products pi^s conj(pi)^(2e-s) of the Gaussian primes pi = 2+i, 3+2i, 4+i dividing r.
std::vector<std::pair<double, double>> cocircularIntegerPoints() {
  using I = long long;  // |x|, |y| <= r < 2^51 and the factors are below 5: products < 2^54
  struct G {
    I x, y;
  };
  auto mul = [](G a, G b) { return G{a.x * b.x - a.y * b.y, a.x * b.y + a.y * b.x}; };
  const std::pair<G, int> factors[] = {{{2, 1}, 12}, {{3, 2}, 4}, {{4, 1}, 2}};
  std::vector<G> pts = {{1, 0}};
  for (const auto& [g, e] : factors) {
    std::vector<G> next;
    const G c{g.x, -g.y};
    for (const G& z : pts)
      for (int s = 0; s <= 2 * e; ++s) {
        G w = z;
        for (int k = 0; k < s; ++k) w = mul(w, g);
        for (int k = 0; k < 2 * e - s; ++k) w = mul(w, c);
        next.push_back(w);
      }
    pts = next;
  }
  std::vector<std::pair<double, double>> out;
  for (const G& z : pts) out.emplace_back(double(z.x), double(z.y));  // < 2^53: exact
  return out;
}

//! [orient2dNaiveCanonical]
int orient2dNaiveCanonical(double ax, double ay, double bx, double by, double cx, double cy) {
  // BEGIN SOLUTION 2.3.1-1
  struct P {
    double x, y;
    bool operator<(const P& o) const { return x < o.x || (x == o.x && y < o.y); }
  };
  P p[3] = {{ax, ay}, {bx, by}, {cx, cy}};
  int parity = 1;  // each swap of two points negates the orientation
  if (p[1] < p[0]) std::swap(p[0], p[1]), parity = -parity;
  if (p[2] < p[1]) std::swap(p[1], p[2]), parity = -parity;
  if (p[1] < p[0]) std::swap(p[0], p[1]), parity = -parity;
  return parity * orient2dNaive(p[0].x, p[0].y, p[1].x, p[1].y, p[2].x, p[2].y);
  // END SOLUTION 2.3.1-1
}
//! [orient2dNaiveCanonical]

bool segmentsCrossNotes(double px, double py, double qx, double qy, double rx, double ry,
                        double sx, double sy) {
  return orient2d(px, py, qx, qy, rx, ry) * orient2d(px, py, qx, qy, sx, sy) < 0 &&
         orient2d(rx, ry, sx, sy, px, py) * orient2d(rx, ry, sx, sy, qx, qy) < 0;
}

//! [segmentsIntersect]
// BEGIN SOLUTION 2.3.1-3 (remove)
namespace {
// For r on the line pq: is r within the bounding box of p and q? Comparisons are exact.
bool onSegment(double px, double py, double qx, double qy, double rx, double ry) {
  return std::min(px, qx) <= rx && rx <= std::max(px, qx) && std::min(py, qy) <= ry &&
         ry <= std::max(py, qy);
}
}  // namespace
// END SOLUTION 2.3.1-3

bool segmentsIntersect(double px, double py, double qx, double qy, double rx, double ry,
                       double sx, double sy) {
  // BEGIN SOLUTION 2.3.1-3
  const int o1 = orient2d(px, py, qx, qy, rx, ry), o2 = orient2d(px, py, qx, qy, sx, sy);
  const int o3 = orient2d(rx, ry, sx, sy, px, py), o4 = orient2d(rx, ry, sx, sy, qx, qy);
  if (o1 * o2 < 0 && o3 * o4 < 0) return true;  // proper crossing: the notes' case
  // Otherwise they meet only at an endpoint lying on the other segment: on its line (exact
  // zero) and in its bounding box. This also covers a segment of length zero (p = q): then
  // every orientation with p, q is 0, and the box test alone says whether r is p.
  if (o1 == 0 && onSegment(px, py, qx, qy, rx, ry)) return true;
  if (o2 == 0 && onSegment(px, py, qx, qy, sx, sy)) return true;
  if (o3 == 0 && onSegment(rx, ry, sx, sy, px, py)) return true;
  if (o4 == 0 && onSegment(rx, ry, sx, sy, qx, qy)) return true;
  return false;
  // END SOLUTION 2.3.1-3
}
//! [segmentsIntersect]

}  // namespace dt
