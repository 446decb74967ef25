// Figure data helpers of the chapter programs (the figure style, book/figure_style.md):
// where to put a label so that no drawn segment crosses it, construction lines clipped to the
// view, and triangulations written with each edge once.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace ch {

/// A drawn segment, in data coordinates.
struct Seg {
  double x0, y0, x1, y1;
};

inline double segDistance(const Seg& s, double x, double y) {
  const double dx = s.x1 - s.x0, dy = s.y1 - s.y0, l2 = dx * dx + dy * dy;
  double t = l2 > 0 ? ((x - s.x0) * dx + (y - s.y0) * dy) / l2 : 0;
  t = std::clamp(t, 0.0, 1.0);
  return std::hypot(x - s.x0 - t * dx, y - s.y0 - t * dy);
}

/// The centre of the label of the point (x, y): among 24 directions, about `r` (or 2.2 r) away, the one
/// whose text box (half width `hw`, half height `hh`, in data units) stays farthest from every
/// segment of `segs` and every point of `avoid` (x, y pairs). Ties go to the upper right.
inline std::pair<double, double> labelSpot(double x, double y, double r, double hw, double hh,
                                           const std::vector<Seg>& segs,
                                           const std::vector<double>& avoid = {}) {
  std::pair<double, double> best = {x + r, y + r};
  double bestScore = -1;
  for (int ring = 0; ring < 2; ++ring)  // near the point first; farther if the near ring is crowded
    for (int k = 0; k < 24; ++k) {
      const double a = M_PI / 4 + 2 * M_PI * k / 24, rr = ring ? 2.2 * r : r;
      // The box's centre on an ellipse, so that its near side is about rr from the point: a
      // wide label needs more room sideways than up or down.
      const double cx = x + (rr + hw) * std::cos(a), cy = y + (rr + hh) * std::sin(a);
      double score = 1e300;
      for (double fx : {-1.0, 0.0, 1.0})
        for (double fy : {-1.0, 0.0, 1.0}) {
          const double px = cx + fx * hw, py = cy + fy * hh;
          for (const Seg& s : segs) score = std::min(score, segDistance(s, px, py));
          for (std::size_t i = 0; i + 1 < avoid.size(); i += 2)
            score = std::min(score, std::hypot(px - avoid[i], py - avoid[i + 1]));
        }
      if (ring) score = std::min(score, 0.5 * r);  // a far label only wins if no near one is clear
      if (score > bestScore + 1e-12) bestScore = score, best = {cx, cy};
    }
  return best;
}

/// The edges of triangles (vertex coordinates x, y per vertex; index triples), each edge once.
inline std::vector<Seg> triangleSegs(const std::vector<double>& xy,
                                     const std::vector<std::array<int, 3>>& tri) {
  std::map<std::pair<int, int>, bool> seen;
  std::vector<Seg> s;
  for (const auto& t : tri)
    for (int k = 0; k < 3; ++k) {
      const int a = t[k], b = t[(k + 1) % 3];
      if (!seen.emplace(std::minmax(a, b), true).second) continue;
      s.push_back({xy[2 * a], xy[2 * a + 1], xy[2 * b], xy[2 * b + 1]});
    }
  return s;
}

/// The edges of faces (anything with vertex pointers V[0..2] that have x and y, e.g. dt::Face),
/// each edge once.
template <class Faces>
std::vector<Seg> faceSegs(const Faces& F) {
  std::map<std::pair<const void*, const void*>, bool> seen;
  std::vector<Seg> segs;
  for (const auto* f : F)
    for (int k = 0; k < 3; ++k) {
      const auto *a = f->V[k], *b = f->V[(k + 1) % 3];
      const void *pa = a, *pb = b;
      if (seen.emplace(std::minmax(pa, pb), true).second) segs.push_back({a->x, a->y, b->x, b->y});
    }
  return segs;
}

/// Segments as gnuplot data, one block per segment. A triangulation drawn from this has every
/// edge drawn once: with closed triangles an inner edge is drawn twice and, antialiased, looks
/// darker than a hull edge.
inline std::string gnuplotSegs(const std::vector<Seg>& segs) {
  std::string out;
  char buf[128];
  for (const Seg& s : segs) {
    std::snprintf(buf, sizeof buf, "%.10g %.10g\n%.10g %.10g\n\n", s.x0, s.y0, s.x1, s.y1);
    out += buf;
  }
  return out;
}

/// A circle as a closed polyline (gnuplot data, one block): gnuplot's "with circles" drops a
/// circle whose centre is outside the view, a polyline is clipped like any line.
inline std::string circlePolyline(double cx, double cy, double r, int n = 240) {
  std::string out;
  char buf[96];
  for (int i = 0; i <= n; ++i) {
    const double t = 2 * M_PI * i / n;
    std::snprintf(buf, sizeof buf, "%.10g %.10g\n", cx + r * std::cos(t), cy + r * std::sin(t));
    out += buf;
  }
  return out + "\n";
}

/// gnuplotSegs(triangleSegs(xy, tri)): a triangulation with each edge once.
inline std::string gnuplotEdges(const std::vector<double>& xy,
                                const std::vector<std::array<int, 3>>& tri) {
  return gnuplotSegs(triangleSegs(xy, tri));
}

/// The part of the line through (ax, ay) with direction (dx, dy) inside the box
/// [x0, x1] x [y0, y1] (Liang-Barsky). A construction line is drawn as this segment, so that
/// gnuplot never has to clip a segment whose ends are both outside the view (it drops those).
/// Returns false if the line misses the box.
inline bool clipLine(double ax, double ay, double dx, double dy, double x0, double x1, double y0,
                     double y1, Seg& out) {
  double t0 = -1e300, t1 = 1e300;
  const double p[4] = {-dx, dx, -dy, dy}, q[4] = {ax - x0, x1 - ax, ay - y0, y1 - ay};
  for (int i = 0; i < 4; ++i) {
    if (p[i] == 0) {
      if (q[i] < 0) return false;
      continue;
    }
    const double t = q[i] / p[i];
    if (p[i] < 0) t0 = std::max(t0, t);
    else t1 = std::min(t1, t);
  }
  if (t0 > t1) return false;
  out = {ax + t0 * dx, ay + t0 * dy, ax + t1 * dx, ay + t1 * dy};
  return true;
}

}  // namespace ch
