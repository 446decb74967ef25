#include "bowyer_watson.h"

#include <algorithm>
#include <map>
#include <stdexcept>
#include <string>
#include <utility>

#include "predicates.h"
#include "triangulate.h"

namespace dt {

//! [delaunayKernelStep]
KernelStep delaunayKernelStep(const std::vector<double>& xy, std::vector<Tri>& tri, int ip,
                              std::uint64_t* incircleTests, const InsideTest& inside) {
  // BEGIN SOLUTION 2.2-1
  const double px = xy[2 * ip], py = xy[2 * ip + 1];
  auto X = [&](int i) { return xy[2 * i]; };
  auto Y = [&](int i) { return xy[2 * i + 1]; };
  std::vector<Tri> cavity;
  // Algorithm 1 removed tau_j from DT_{i-1} inside "for j = 1 to size(DT_{i-1})": removing
  // shifts the next triangle into slot j, which the loop then skips. Compact in place instead.
  std::size_t kept = 0;
  for (std::size_t j = 0; j < tri.size(); ++j) {
    const Tri t = tri[j];
    if (incircleTests) ++*incircleTests;  // one real call per triangle tested
    // "Contains" is the open disk, decided exactly: a point on the circle (cocircular input)
    // leaves the triangle in place, and the cavity stays star-shaped (Proposition 2.1.1).
    if (inside ? inside(t, ip) : incircle(X(t[0]), Y(t[0]), X(t[1]), Y(t[1]), X(t[2]), Y(t[2]), px, py) > 0)
      cavity.push_back(t);
    else
      tri[kept++] = t;
  }
  tri.resize(kept);
  // Algorithm 1 indented the loop over the cavity inside the loop over DT_{i-1}: the ball must
  // be built once, after the whole cavity is known.
  // Its "e_jk is not shared by any other triangle of C" compared each edge with every other
  // triangle (O(|C|^2)); an edge a->b is shared iff b->a is also a cavity edge: sort and search.
  std::vector<std::pair<int, int>> edges;
  edges.reserve(3 * cavity.size());
  for (const Tri& t : cavity)
    for (int k = 0; k < 3; ++k) edges.emplace_back(t[k], t[(k + 1) % 3]);
  std::sort(edges.begin(), edges.end());
  KernelStep step;
  step.cavity = cavity.size();
  for (const auto& [a, b] : edges)
    if (!std::binary_search(edges.begin(), edges.end(), std::make_pair(b, a))) {
      // Algorithm 1 said "add a new triangle e_jk, p_i" without an orientation; keeping the
      // edge's direction in its cavity triangle makes (a, b, p) counter-clockwise.
      tri.push_back({a, b, ip});
      ++step.ball;
    }
  return step;
  // END SOLUTION 2.2-1
}
//! [delaunayKernelStep]

//! [bowyerWatson]
BowyerWatsonResult bowyerWatson(const std::vector<double>& xy, double factor, CircleTest test) {
  // BEGIN SOLUTION 2.2-1
  BowyerWatsonResult r;
  const std::size_t n = xy.size() / 2;
  if (n == 0) throw std::invalid_argument("bowyerWatson: no points");
  double x0 = xy[0], x1 = xy[0], y0 = xy[1], y1 = xy[1];
  for (std::size_t i = 0; i < n; ++i) {
    x0 = std::min(x0, xy[2 * i]), x1 = std::max(x1, xy[2 * i]);
    y0 = std::min(y0, xy[2 * i + 1]), y1 = std::max(y1, xy[2 * i + 1]);
  }
  // DT_0: the same super-vertices p_{-1}..p_{-4} and triangles as initSuperTriangles.
  Triangulation T0;
  initSuperTriangles(T0, x0, y0, x1, y1, factor);
  for (const Vertex& v : T0.vertices()) {
    r.xy.push_back(v.x);
    r.xy.push_back(v.y);
    r.ids.push_back(v.id);
  }
  r.tri = {{0, 1, 2}, {1, 0, 3}};  // p_{-1} p_{-2} p_{-3} and p_{-2} p_{-1} p_{-4}
  for (std::size_t i = 0; i < n; ++i) {
    r.xy.push_back(xy[2 * i]);
    r.xy.push_back(xy[2 * i + 1]);
    r.ids.push_back(long(i));
  }
  // Section 2.3's tests. Stored: a triangle's circle in floating point, computed the first time
  // the triangle is tested and kept (a triangle, once made, never changes).
  auto X = [&r](int i) { return r.xy[2 * i]; };
  auto Y = [&r](int i) { return r.xy[2 * i + 1]; };
  std::map<Tri, std::array<double, 3>> circle;  // centre x, centre y, squared radius
  InsideTest inside;                            // none: the exact incircle
  if (test == CircleTest::Naive)
    inside = [&](const Tri& t, int ip) {
      return incircleNaive(X(t[0]), Y(t[0]), X(t[1]), Y(t[1]), X(t[2]), Y(t[2]), X(ip), Y(ip)) > 0;
    };
  if (test == CircleTest::Stored)
    inside = [&](const Tri& t, int ip) {
      auto c = circle.find(t);
      if (c == circle.end()) {
        const double ax = X(t[0]), ay = Y(t[0]), bx = X(t[1]) - ax, by = Y(t[1]) - ay;
        const double dx = X(t[2]) - ax, dy = Y(t[2]) - ay, den = 2 * (bx * dy - by * dx);
        const double ux = (dy * (bx * bx + by * by) - by * (dx * dx + dy * dy)) / den;
        const double uy = (bx * (dx * dx + dy * dy) - dx * (bx * bx + by * by)) / den;
        c = circle.emplace(t, std::array<double, 3>{ax + ux, ay + uy, ux * ux + uy * uy}).first;
      }
      const double ex = X(ip) - c->second[0], ey = Y(ip) - c->second[1];
      return ex * ex + ey * ey < c->second[2];
    };
  for (std::size_t i = 0; i < n; ++i) {
    const int ip = int(4 + i);
    const KernelStep s = delaunayKernelStep(r.xy, r.tri, ip, &r.incircleTests, inside);
    // Only an inexact test can pass this bound: its cavities need not be disks, a ball fanned
    // from one that is not overlaps what was kept, and the list only grows. N points have at
    // most 2N - 5 triangles.
    if (r.tri.size() > r.ids.size() * 2) break;
    if (s.cavity == 0) {
      // Algorithm 1 does not say: an empty cavity means the point is on a vertex (a point
      // inside a triangle or on an edge is strictly inside its circle) or outside DT_0. An
      // inexact test may also miss every circle: the point is then left out.
      bool dup = false;
      for (int v = 0; v < ip && !dup; ++v) dup = X(v) == X(ip) && Y(v) == Y(ip);
      if (!dup && test != CircleTest::Exact) continue;
      if (!dup) throw std::out_of_range("bowyerWatson: point " + std::to_string(i) +
                                        " lies outside the super-triangles");
      ++r.duplicates;
      continue;
    }
    r.cavityFaces += s.cavity;
  }
  return r;
  // END SOLUTION 2.2-1
}
//! [bowyerWatson]

std::vector<std::array<long, 3>> canonicalTriangles(const std::vector<long>& ids,
                                                    const std::vector<Tri>& tri) {
  std::vector<std::array<long, 3>> out;
  out.reserve(tri.size());
  for (const Tri& t : tri) {
    std::array<long, 3> a = {ids[t[0]], ids[t[1]], ids[t[2]]};
    while (a[0] > a[1] || a[0] > a[2]) std::rotate(a.begin(), a.begin() + 1, a.end());
    out.push_back(a);
  }
  std::sort(out.begin(), out.end());
  return out;
}

std::vector<std::array<long, 2>> hullEdgesNotCovered(const std::vector<double>& xy,
                                                     const std::vector<long>& ids,
                                                     const std::vector<Tri>& tri) {
  // BEGIN SOLUTION 2.2-3
  auto X = [&](int i) { return xy[2 * i]; };
  auto Y = [&](int i) { return xy[2 * i + 1]; };
  std::vector<int> pts;
  for (std::size_t i = 0; i < ids.size(); ++i)
    if (ids[i] >= 0) pts.push_back(int(i));
  std::sort(pts.begin(), pts.end(), [&](int a, int b) {
    return X(a) < X(b) || (X(a) == X(b) && Y(a) < Y(b));
  });
  pts.erase(std::unique(pts.begin(), pts.end(),
                        [&](int a, int b) { return X(a) == X(b) && Y(a) == Y(b); }),
            pts.end());
  // Andrew's monotone chain with exact orientation; popping only on a right turn keeps the
  // collinear points of the hull, so that every hull edge is an edge of DT(S).
  std::vector<int> hull;
  for (int pass = 0; pass < 2; ++pass) {
    const std::size_t base = hull.size();
    for (std::size_t k = 0; k < pts.size(); ++k) {
      const int p = pass == 0 ? pts[k] : pts[pts.size() - 1 - k];
      while (hull.size() >= base + 2 &&
             orient2d(X(hull[hull.size() - 2]), Y(hull[hull.size() - 2]), X(hull.back()),
                      Y(hull.back()), X(p), Y(p)) < 0)
        hull.pop_back();
      hull.push_back(p);
    }
    hull.pop_back();  // the last point of one chain is the first of the other
  }
  std::vector<std::pair<int, int>> kept;  // directed edges of triangles free of super-vertices
  for (const Tri& t : tri) {
    if (ids[t[0]] < 0 || ids[t[1]] < 0 || ids[t[2]] < 0) continue;
    for (int k = 0; k < 3; ++k) kept.emplace_back(t[k], t[(k + 1) % 3]);
  }
  std::sort(kept.begin(), kept.end());
  std::vector<std::array<long, 2>> missing;
  for (std::size_t k = 0; k < hull.size(); ++k) {
    const int a = hull[k], b = hull[(k + 1) % hull.size()];  // counter-clockwise: a -> b
    if (!std::binary_search(kept.begin(), kept.end(), std::make_pair(a, b)))
      missing.push_back({ids[a], ids[b]});
  }
  return missing;
  // END SOLUTION 2.2-3
}

std::vector<Tri> bruteForceDelaunay(const std::vector<double>& xy) {
  const int n = int(xy.size() / 2);
  auto X = [&](int i) { return xy[2 * i]; };
  auto Y = [&](int i) { return xy[2 * i + 1]; };
  std::vector<Tri> out;
  for (int a = 0; a < n; ++a)
    for (int b = a + 1; b < n; ++b)
      for (int c = b + 1; c < n; ++c) {
        const int o = orient2d(X(a), Y(a), X(b), Y(b), X(c), Y(c));
        if (o == 0) continue;
        const Tri t = o > 0 ? Tri{a, b, c} : Tri{a, c, b};
        bool empty = true;
        for (int d = 0; d < n && empty; ++d)
          if (d != a && d != b && d != c)
            empty = incircle(X(t[0]), Y(t[0]), X(t[1]), Y(t[1]), X(t[2]), Y(t[2]), X(d), Y(d)) <= 0;
        if (empty) out.push_back(t);
      }
  return out;
}

}  // namespace dt
