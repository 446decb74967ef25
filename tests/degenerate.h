// Generators of degenerate point sets: the inputs on which naive predicates, walks
// and super-triangles break. Every generator is deterministic (fixed seeds). Used by
// test_degenerate.cpp, test_regressions.cpp and the fuzz harnesses' seed corpus.
#pragma once

#include <cmath>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "generators.h"

namespace dtdeg {

using XY = std::vector<double>;  // x0 y0 x1 y1 ...

inline void add(XY& p, double x, double y) {
  p.push_back(x);
  p.push_back(y);
}

/// The integer grid {0..nx-1} x {0..ny-1}: every unit square has 4 cocircular corners.
inline XY integerGrid(int nx, int ny) { return dt::gridPoints(nx, ny); }

/// The integer grid rotated exactly by the angle of cos = 3/5, sin = 4/5 (scaled by 5, so that
/// the coordinates stay integers): still exactly cocircular quadruples, but no edge is axis
/// parallel.
inline XY rotatedGridExact(int nx, int ny) { return dt::rotatedGridPoints(nx, ny); }

/// The unit grid rotated by `angle` in floating point: the rounded points are almost, but not
/// exactly, cocircular: the incircle signs are decided by the last bits.
inline XY rotatedGridRounded(int nx, int ny, double angle) {
  XY p;
  const double c = std::cos(angle), s = std::sin(angle);
  for (int i = 0; i < nx; ++i)
    for (int j = 0; j < ny; ++j) add(p, c * i - s * j, s * i + c * j);
  return p;
}

/// All integer points on the circle x^2 + y^2 = r^2: exactly cocircular. With r a product of
/// primes 1 mod 4 there are many (r = 5*13*17*29 gives 4 * 3^4 = 324 points).
inline XY cocircularIntegers(long r) {
  XY p;
  const long r2 = r * r;  // r < 2^26: r2 and x*x are exact in long and in double
  for (long x = -r; x <= r; ++x) {
    const long y2 = r2 - x * x;
    long y = std::lround(std::sqrt(double(y2)));
    while (y * y > y2) --y;
    while ((y + 1) * (y + 1) <= y2) ++y;
    if (y * y != y2) continue;
    add(p, double(x), double(y));
    if (y != 0) add(p, double(x), double(-y));
  }
  return p;
}

/// n points (r cos t, r sin t), rounded: nearly cocircular, plus the centre.
inline XY roundedCircle(int n, double r, bool centre) {
  XY p;
  for (int i = 0; i < n; ++i) {
    const double t = 2 * M_PI * i / n;
    add(p, r * std::cos(t), r * std::sin(t));
  }
  if (centre) add(p, 0, 0);
  return p;
}

/// Long collinear runs: `runs` horizontal lines of `perLine` points each, a diagonal line, and
/// points on the four sides of the bounding square (collinear hull vertices).
inline XY collinearRuns(int perLine, int runs) {
  XY p;
  for (int r = 0; r < runs; ++r)
    for (int i = 0; i < perLine; ++i) add(p, i * 0.5, r * 7.0);
  for (int i = 0; i < perLine; ++i) add(p, i * 0.25 + 0.125, i * 0.25 * 7.0 * (runs - 1) / (perLine * 0.5));
  const double w = (perLine - 1) * 0.5, h = (runs - 1) * 7.0;
  for (int i = 1; i < perLine; ++i) {
    add(p, -1, h * i / perLine);
    add(p, w + 1, h * i / perLine);
  }
  return p;
}

/// Collinear points, then one point off the line at the very end of the input: the first
/// triangle of the hull method only appears with the last point.
inline XY collinearThenOne(int n) {
  XY p;
  for (int i = 0; i < n; ++i) add(p, 3.0 * i, -2.0 * i);
  add(p, 1, 1);
  return p;
}

/// Uniform points, each repeated up to 3 times, and near-duplicates one and a few ulps away
/// in x, y or both.
inline XY duplicatesAndNear(int n, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0, 1);
  XY p;
  for (int i = 0; i < n; ++i) {
    const double x = u(rng), y = u(rng);
    add(p, x, y);
    const int k = int(rng() % 6);
    if (k == 0) add(p, x, y);
    if (k == 1) {
      add(p, x, y);
      add(p, x, y);
    }
    if (k == 2) add(p, std::nextafter(x, 2.0), y);
    if (k == 3) add(p, x, std::nextafter(std::nextafter(y, -1.0), -1.0));
    if (k == 4) add(p, std::nextafter(x, -1.0), std::nextafter(y, 2.0));
  }
  return p;
}

/// Clusters over 12 orders of magnitude: `perCluster` uniform points in squares of side
/// 10^-k, k = 0..12, all with a corner at the same point (1, 1) (so the tiny clusters sit
/// where the big ones are dense), and one cluster per scale placed far along the diagonal.
inline XY clusters12(int perCluster, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0, 1);
  XY p;
  for (int k = 0; k <= 12; ++k) {
    const double s = std::pow(10.0, -k);
    for (int i = 0; i < perCluster; ++i) add(p, 1 + s * u(rng), 1 + s * u(rng));
    for (int i = 0; i < perCluster / 4; ++i) add(p, 3 + k + s * u(rng), 3 + k + s * u(rng));
  }
  return p;
}

/// Uniform points scaled to `scale` (1e300, 1e-300): differences and products overflow or
/// underflow in double, so every filter must hand over to the exact stage.
inline XY scaledUniform(int n, double scale, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1, 1);
  XY p;
  for (int i = 0; i < n; ++i) add(p, scale * u(rng), scale * u(rng));
  return p;
}

/// An integer grid scaled to `scale`, cocircular quadruples at extreme exponents.
inline XY scaledGrid(int nx, int ny, double scale) {
  XY p = integerGrid(nx, ny);
  for (double& v : p) v *= scale;
  return p;
}

/// Points near 1e300 and near 1e-300 in one set: coordinates that differ by 600 orders of
/// magnitude inside the same predicate.
inline XY mixedExtremes(int n, unsigned seed) {
  XY p = scaledUniform(n, 1e300, seed);
  const XY q = scaledUniform(n, 1e-300, seed + 1);
  p.insert(p.end(), q.begin(), q.end());
  return p;
}

/// A huge input with few distinct points: `n` points drawn from the 7 points of a small
/// non-degenerate set (its centre among them, 4 of them cocircular).
inline XY fewDistinct(std::size_t n, unsigned seed) {
  const double base[7][2] = {{0, 0}, {1, 0}, {0, 1}, {1, 1}, {0.5, 0.5}, {2, 0.25}, {-1, 3}};
  std::mt19937_64 rng(seed);
  XY p;
  p.reserve(2 * n);
  for (std::size_t i = 0; i < n; ++i) {
    const auto& b = base[rng() % 7];
    add(p, b[0], b[1]);
  }
  return p;
}

/// Fisher-Yates with a fixed seed: the input order of each family is random but reproducible.
inline XY shuffled(XY p, unsigned seed) {
  dt::shufflePoints(p, seed);
  return p;
}

struct Family {
  std::string name;
  XY points;
};

/// Every family of the degenerate suite at a size where every variant, Algorithm 1 aside,
/// runs in a fraction of a second. `small` gives versions of about 100-300 points for the
/// O(n^2) Algorithm 1.
inline std::vector<Family> families(bool small = false) {
  const int g = small ? 12 : 40;
  std::vector<Family> f;
  f.push_back({"integer grid (sorted)", integerGrid(g, g)});
  f.push_back({"integer grid (shuffled)", shuffled(integerGrid(g, g), 1)});
  f.push_back({"grid rotated exactly (3/5, 4/5)", shuffled(rotatedGridExact(g, g), 2)});
  f.push_back({"grid rotated by 0.3 rad (rounded)", shuffled(rotatedGridRounded(g, g, 0.3), 3)});
  f.push_back({"cocircular integer points, r = 5*13*17*29",
               shuffled(cocircularIntegers(small ? 5 * 13 * 17 : 5 * 13 * 17 * 29), 4)});
  f.push_back({"rounded circle with centre", shuffled(roundedCircle(small ? 100 : 1000, 1, true), 5)});
  f.push_back({"collinear runs", shuffled(collinearRuns(small ? 20 : 100, small ? 3 : 8), 6)});
  f.push_back({"collinear, then one point off the line", collinearThenOne(small ? 100 : 1000)});
  f.push_back({"duplicates and near-duplicates", duplicatesAndNear(small ? 100 : 1000, 7)});
  f.push_back({"clusters over 12 orders of magnitude", shuffled(clusters12(small ? 8 : 80, 8), 8)});
  f.push_back({"uniform near 1e300", scaledUniform(small ? 150 : 1500, 1e300, 9)});
  f.push_back({"uniform near 1e-300", scaledUniform(small ? 150 : 1500, 1e-300, 10)});
  f.push_back({"integer grid times 1e300", shuffled(scaledGrid(g, g, 1e300), 11)});
  f.push_back({"integer grid times 1e-300", shuffled(scaledGrid(g, g, 1e-300), 12)});
  f.push_back({"1e300 and 1e-300 mixed", shuffled(mixedExtremes(small ? 80 : 700, 13), 13)});
  f.push_back({"few distinct points, many copies", fewDistinct(small ? 2000 : 20000, 14)});
  // For the adaptive Hilbert order (one crowded cell) and the extended-exponent stage. The
  // exponents stop at 2^1000 so that super-triangles (10x the box) still fit in doubles.
  const std::size_t m = small ? 150 : 1500;
  f.push_back({"uniform and one far outlier (1e12, 1e12)", dt::outlierPoints(m, 15, 1e12)});
  f.push_back({"cluster of width 1e-9 beside uniform points", dt::clusterBesideUniform(m, 16)});
  f.push_back({"radii log-uniform in [1e-6, 1e6]", dt::logRadiusPoints(m, 17)});
  f.push_back({"exponents spread over 2^-1070 .. 2^1000",
               dt::exponentSpreadPoints(m, 18, -1070, 1000)});
  return f;
}

}  // namespace dtdeg
