// Shared helpers of the test suite: point generators with fixed seeds, and a one-call
// "triangulate and check exactly".
#pragma once

#include <cmath>
#include <random>
#include <vector>

#include "check.h"
#include "triangulate.h"

namespace dttest {

using XY = std::vector<double>;  // x0 y0 x1 y1 ...

inline XY uniformPoints(std::size_t n, unsigned seed, double lo = 0, double hi = 1) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(lo, hi);
  XY p;
  for (std::size_t i = 0; i < n; ++i) {
    p.push_back(u(rng));
    p.push_back(u(rng));
  }
  return p;
}

inline XY gridPoints(int nx, int ny, double step = 1, double x0 = 0, double y0 = 0) {
  XY p;
  for (int i = 0; i < nx; ++i)
    for (int j = 0; j < ny; ++j) {
      p.push_back(x0 + i * step);
      p.push_back(y0 + j * step);
    }
  return p;
}

// Points on a circle; with `exact` the points are the integer solutions of x^2 + y^2 = r^2
// for r = 5^k products (exactly cocircular), otherwise rounded cos/sin (nearly cocircular).
inline XY circlePoints(std::size_t n, double r = 1) {
  XY p;
  for (std::size_t i = 0; i < n; ++i) {
    const double t = 2 * M_PI * double(i) / double(n);
    p.push_back(r * std::cos(t));
    p.push_back(r * std::sin(t));
  }
  return p;
}

inline void shuffle(XY& p, unsigned seed) {
  std::mt19937_64 rng(seed);
  const std::size_t n = p.size() / 2;
  for (std::size_t i = n; i > 1; --i) {
    std::uniform_int_distribution<std::size_t> d(0, i - 1);
    const std::size_t j = d(rng);
    std::swap(p[2 * (i - 1)], p[2 * j]);
    std::swap(p[2 * (i - 1) + 1], p[2 * j + 1]);
  }
}

// DT(S) with the hull method, extracted and checked exactly. Returns the report.
inline dt::CheckReport triangulateAndCheck(const XY& p, dt::InsertionStats* st = nullptr,
                                           dt::StartRule rule = dt::StartRule::LastCavity) {
  dt::Triangulation T;
  std::vector<dt::Vertex*> S;
  for (std::size_t i = 0; i < p.size() / 2; ++i) S.push_back(T.addVertex(p[2 * i], p[2 * i + 1], long(i)));
  dt::delaunayTrglHull(T, S, rule, st);
  const dt::CheckReport full = dt::checkTriangulation(T);
  if (!full.ok) return full;
  const dt::PlainMesh m = dt::extractMesh(T, true);
  return dt::checkDelaunay(m.xy, m.tri);
}

}  // namespace dttest
