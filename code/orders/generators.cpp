/// \file generators.cpp
/// Point families with fixed seeds (see generators.h).
#include "generators.h"

#include "mesh.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>
#include <utility>

namespace dt {

XY uniformPoints(std::size_t n, std::uint64_t seed, double lo, double hi) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(lo, hi);
  XY p(2 * n);
  for (double& v : p) v = u(rng);
  return p;
}

XY uniformDiskPoints(std::size_t n, std::uint64_t seed, double R) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0, 1);
  XY p;
  p.reserve(2 * n);
  for (std::size_t i = 0; i < n; ++i) {
    const double r = std::sqrt(u(rng)), t = 2 * M_PI * u(rng);
    p.push_back(R * r * std::cos(t));
    p.push_back(R * r * std::sin(t));
  }
  return p;
}

XY randomCirclePoints(std::size_t n, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0, 1);
  XY p;
  p.reserve(2 * n);
  for (std::size_t i = 0; i < n; ++i) {
    const double t = 2 * M_PI * u(rng);
    p.push_back(std::cos(t));
    p.push_back(std::sin(t));
  }
  return p;
}

XY gaussianClusters(std::size_t n, std::uint64_t seed, int clusters) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<double> cx(clusters), cy(clusters), s(clusters);
  for (int b = 0; b < clusters; ++b) {
    cx[b] = 0.1 + 0.8 * u(rng);
    cy[b] = 0.1 + 0.8 * u(rng);
    s[b] = 0.001 * std::pow(50.0, u(rng));
  }
  std::normal_distribution<double> g(0, 1);
  XY p(2 * n);
  for (std::size_t i = 0; i < n; ++i) {
    const int b = int(u(rng) * clusters) % clusters;
    p[2 * i] = cx[b] + s[b] * g(rng);
    p[2 * i + 1] = cy[b] + s[b] * g(rng);
  }
  return p;
}

XY gridPoints(int nx, int ny, double step, double x0, double y0) {
  XY p;
  p.reserve(2 * std::size_t(std::max(nx, 0)) * std::size_t(std::max(ny, 0)));
  for (int i = 0; i < nx; ++i)
    for (int j = 0; j < ny; ++j) {
      p.push_back(x0 + i * step);
      p.push_back(y0 + j * step);
    }
  return p;
}

XY rotatedGridPoints(int nx, int ny) {
  XY p;
  for (int i = 0; i < nx; ++i)
    for (int j = 0; j < ny; ++j) {
      p.push_back(3.0 * i - 4.0 * j);
      p.push_back(4.0 * i + 3.0 * j);
    }
  return p;
}

XY jitteredGridPoints(std::size_t n, std::uint64_t seed, double jitter) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-jitter, jitter);
  const std::size_t m = std::size_t(std::ceil(std::sqrt(double(n))));
  XY p;
  p.reserve(2 * n);
  for (std::size_t k = 0; k < n; ++k) {
    p.push_back((double(k % m) + u(rng)) / double(m));
    p.push_back((double(k / m) + u(rng)) / double(m));
  }
  // The order comes from std::shuffle on the same generator (the published tables use it).
  std::vector<std::size_t> perm(n);
  std::iota(perm.begin(), perm.end(), std::size_t{0});
  std::shuffle(perm.begin(), perm.end(), rng);
  XY q(2 * n);
  for (std::size_t k = 0; k < n; ++k) {
    q[2 * k] = p[2 * perm[k]];
    q[2 * k + 1] = p[2 * perm[k] + 1];
  }
  return q;
}

XY circlePoints(std::size_t n, double r, std::size_t stride) {
  XY p;
  p.reserve(2 * n);
  for (std::size_t i = 0; i < n; ++i) {
    const double t = 2 * M_PI * double((i * stride) % n) / double(n);
    p.push_back(r * std::cos(t));
    p.push_back(r * std::sin(t));
  }
  return p;
}

XY parabolaPoints(std::size_t n, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1, 1);
  XY p(2 * n);
  for (std::size_t i = 0; i < n; ++i) {
    const double x = u(rng);
    p[2 * i] = x;
    p[2 * i + 1] = x * x;
  }
  return p;
}

XY outlierPoints(std::size_t n, std::uint64_t seed, double far) {
  if (n == 0) return {};
  XY p = uniformPoints(n - 1, seed);
  const std::size_t at = std::size_t(std::mt19937_64(seed + 1)() % n);
  p.insert(p.begin() + std::ptrdiff_t(2 * at), {far, far});
  return p;
}

XY clusterBesideUniform(std::size_t n, std::uint64_t seed, double width) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0, 1);
  const std::size_t inCluster = n / 10;
  XY p;
  p.reserve(2 * n);
  for (std::size_t i = 0; i < n; ++i) {
    if (i < inCluster) {
      p.push_back(0.3 + width * (u(rng) - 0.5));
      p.push_back(0.7 + width * (u(rng) - 0.5));
    } else {
      p.push_back(u(rng));
      p.push_back(u(rng));
    }
  }
  shufflePoints(p, seed + 1);
  return p;
}

XY logRadiusPoints(std::size_t n, std::uint64_t seed, double rmin, double rmax) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0, 1);
  const double l0 = std::log(rmin), l1 = std::log(rmax);
  XY p;
  p.reserve(2 * n);
  for (std::size_t i = 0; i < n; ++i) {
    const double r = std::exp(l0 + (l1 - l0) * u(rng)), t = 2 * M_PI * u(rng);
    p.push_back(r * std::cos(t));
    p.push_back(r * std::sin(t));
  }
  return p;
}

XY exponentSpreadPoints(std::size_t n, std::uint64_t seed, int kmin, int kmax) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0, 1);
  std::uniform_int_distribution<int> k(kmin, kmax);
  XY p(2 * n);
  for (double& v : p) {
    const int e = k(rng);
    const double x = std::ldexp(0.5 + u(rng), e);
    v = rng() & 1 ? x : -x;
  }
  return p;
}

void shufflePoints(XY& p, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  for (std::size_t i = p.size() / 2; i > 1; --i) {
    const std::size_t j = std::uniform_int_distribution<std::size_t>(0, i - 1)(rng);
    std::swap(p[2 * (i - 1)], p[2 * j]);
    std::swap(p[2 * (i - 1) + 1], p[2 * j + 1]);
  }
}

std::vector<Vertex*> addVertices(Triangulation& T, const XY& p) {
  std::vector<Vertex*> S;
  S.reserve(p.size() / 2);
  for (std::size_t i = 0; i < p.size() / 2; ++i)
    S.push_back(T.addVertex(p[2 * i], p[2 * i + 1], long(i)));
  return S;
}

}  // namespace dt
