/// \file test_2_1_exercises.cpp Exercise 2.1-1 (exercises/exercises.txt): the kernel of a polygon by clipping. Every edge must cut the kernel, the one from the last corner back to the first included (each polygon is tried from every starting corner), the kernel's area must be that of the points left of every edge, and a kernel without interior is empty. Each failure names the polygon and its starting corner.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "star.h"

namespace {

struct Named {
  std::string name;
  std::vector<dt::Point2> poly;  // counter-clockwise
};

// Star-shaped polygons with a kernel that has an interior.
std::vector<Named> starShaped() {
  std::vector<Named> v;
  Named star{"star with 7 spikes", {}};
  for (int k = 0; k < 14; ++k) {
    const double a = 2 * M_PI * k / 14, r = k % 2 ? 1.0 : 0.45 + 0.05 * (k % 3);
    star.poly.push_back({r * std::cos(a) + 0.1, r * std::sin(a)});
  }
  v.push_back(star);
  v.push_back({"L-shape", {{0, 0}, {3, 0}, {3, 1}, {1, 1}, {1, 3}, {0, 3}}});
  v.push_back({"chevron", {{0, 0}, {4, 0}, {4, 4}, {2, 2}, {0, 4}}});
  v.push_back({"notched square", {{0, 0}, {2, 0}, {2, 0.8}, {1.6, 1}, {2, 1.2}, {2, 2}, {0, 2}}});
  return v;
}

std::vector<dt::Point2> rotated(const std::vector<dt::Point2>& p, std::size_t r) {
  std::vector<dt::Point2> q(p.begin() + long(r), p.end());
  q.insert(q.end(), p.begin(), p.begin() + long(r));
  return q;
}

// The reference: the notes' definition of the kernel (2.1.1), exact: x sees every corner
// (seesCorner: inside the polygon, each open segment to a corner free of edges). On these
// polygons it is the open kernel (test_2_1_kernel.cpp samples the same grids).
bool seesEveryCorner(const std::vector<dt::Point2>& p, dt::Point2 x) {
  for (std::size_t k = 0; k < p.size(); ++k)
    if (!dt::seesCorner(p, x, k)) return false;
  return true;
}

double area(const std::vector<dt::Point2>& K) {
  double s = 0;
  for (std::size_t i = 0; i < K.size(); ++i) {
    const dt::Point2 a = K[i], b = K[(i + 1) % K.size()];
    s += a.x * b.y - a.y * b.x;
  }
  return s / 2;
}

struct Box {
  double x0, y0, x1, y1;
};
Box box(const std::vector<dt::Point2>& p) {
  Box b{p[0].x, p[0].y, p[0].x, p[0].y};
  for (const auto& q : p) {
    b.x0 = std::min(b.x0, q.x), b.x1 = std::max(b.x1, q.x);
    b.y0 = std::min(b.y0, q.y), b.y1 = std::max(b.y1, q.y);
  }
  return b;
}

}  // namespace

TEST_CASE("2.1 exercise 2.1-1 every corner of the kernel is on the inner side of every edge") {
  for (const Named& n : starShaped())
    for (std::size_t r = 0; r < n.poly.size(); ++r) {
      const std::vector<dt::Point2> P = rotated(n.poly, r);
      INFO("polygon '" << n.name << "' starting at corner " << r << " of " << P.size());
      const std::vector<dt::Point2> K = dt::polygonKernel(P);
      REQUIRE_MESSAGE(K.size() >= 3, "the kernel has an interior, but " << K.size() << " corners came back");
      const Box b = box(P);
      const double tol = 1e-9 * std::max(b.x1 - b.x0, b.y1 - b.y0);
      for (std::size_t i = 0; i < P.size(); ++i) {
        const dt::Point2 a = P[i], c = P[(i + 1) % P.size()];
        const double len = std::hypot(c.x - a.x, c.y - a.y);
        for (const dt::Point2& q : K) {
          const double dist = ((c.x - a.x) * (q.y - a.y) - (c.y - a.y) * (q.x - a.x)) / len;
          if (dist < -tol)
            FAIL("kernel corner (" << q.x << ", " << q.y << ") is " << -dist << " right of edge " << i
                                   << " (" << a.x << ", " << a.y << ") -> (" << c.x << ", " << c.y << ")");
        }
      }
    }
}

TEST_CASE("2.1 exercise 2.1-1 the area of the kernel is the share of sample points in the open kernel") {
  for (const Named& n : starShaped()) {
    // The share of cell centres of an m x m grid that see every corner: the kernel's area.
    const Box b = box(n.poly);
    const int m = 150;
    int inside = 0;
    for (int i = 0; i < m; ++i)
      for (int j = 0; j < m; ++j)
        inside += seesEveryCorner(n.poly, {b.x0 + (b.x1 - b.x0) * (i + 0.5) / m, b.y0 + (b.y1 - b.y0) * (j + 0.5) / m});
    const double boxArea = (b.x1 - b.x0) * (b.y1 - b.y0);
    const double sampled = boxArea * inside / (double(m) * m);
    for (std::size_t r = 0; r < n.poly.size(); ++r) {
      const std::vector<dt::Point2> P = rotated(n.poly, r);
      INFO("polygon '" << n.name << "' starting at corner " << r << " of " << P.size());
      const std::vector<dt::Point2> K = dt::polygonKernel(P);
      CHECK_MESSAGE(std::fabs(area(K) - sampled) < 0.02 * boxArea,
                    "kernel area " << area(K) << ", the points that see every corner cover about " << sampled);
    }
  }
}

TEST_CASE("2.1 exercise 2.1-1 a kernel without interior is reported empty") {
  // Two blocks joined along y = 0: the edge (0,0) -> (1,0) wants y >= 0, the edge (4,0) -> (3,0)
  // wants y <= 0, so the kernel is the segment from (1,0) to (3,0).
  const Named flat{"two blocks whose kernel is a segment",
                   {{0, 0}, {1, 0}, {1, -1}, {4, -1}, {4, 0}, {3, 0}, {3, 1}, {0, 1}}};
  for (std::size_t r = 0; r < flat.poly.size(); ++r) {
      const std::vector<dt::Point2> P = rotated(flat.poly, r);
      INFO("polygon '" << flat.name << "' starting at corner " << r << " of " << P.size());
      const std::vector<dt::Point2> K = dt::polygonKernel(P);
      CHECK_MESSAGE(K.empty(), K.size() << " corners came back, the first (" << (K.empty() ? 0 : K[0].x)
                                        << ", " << (K.empty() ? 0 : K[0].y) << ")");
      CHECK_FALSE(dt::inOpenKernel(P, {2, 0}));
  }
}

TEST_CASE("2.1 exercise 2.1-1 the open kernel test is exact on the lines of the edges") {
  // Grid points of the bounding box fall exactly on edge lines and their extensions, where a
  // rounded line equation errs; the reference is the notes' definition (every corner seen).
  std::vector<Named> polys = starShaped();
  polys.push_back({"comb (empty kernel)", {{0, 0}, {4, 0}, {4, 3}, {3, 3}, {3, 1}, {1, 1}, {1, 3}, {0, 3}}});
  polys.push_back({"unit square", {{0, 0}, {1, 0}, {1, 1}, {0, 1}}});
  for (const Named& n : polys) {
    const Box b = box(n.poly);
    std::size_t wrong = 0;
    for (int i = 0; i <= 60; ++i)
      for (int j = 0; j <= 60; ++j) {
        const dt::Point2 x = {b.x0 + (b.x1 - b.x0) * i / 60, b.y0 + (b.y1 - b.y0) * j / 60};
        const bool want = seesEveryCorner(n.poly, x), got = dt::inOpenKernel(n.poly, x);
        if (got != want && wrong++ == 0)
          FAIL_CHECK("polygon '" << n.name << "', point (" << x.x << ", " << x.y << "): inOpenKernel says "
                                 << std::string(got ? "inside" : "outside") << ", the point is "
                                 << std::string(want ? "strictly inside the kernel (it sees every corner)" : "not (a corner it does not see)"));
      }
    CHECK_MESSAGE(wrong == 0, "polygon '" << n.name << "': " << wrong << " of 3721 sample points wrong");
  }
  const std::vector<dt::Point2> comb = polys[polys.size() - 2].poly;
  CHECK_MESSAGE(dt::polygonKernel(comb).empty(), "polygon 'comb (empty kernel)'");
  CHECK_MESSAGE(dt::polygonKernel(polys.back().poly).size() == 4, "polygon 'unit square' is its own kernel");
}
