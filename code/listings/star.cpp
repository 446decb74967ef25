#include "star.h"

#include <algorithm>
#include <cstdint>
#include <stdexcept>
#include <unordered_map>

#include "predicates.h"
#include "robustness.h"

namespace dt {

namespace {

int orient(Point2 a, Point2 b, Point2 c) { return orient2d(a.x, a.y, b.x, b.y, c.x, c.y); }

// c is on the closed segment ab, given that a, b, c are collinear (comparisons only: exact).
bool onClosedSegment(Point2 a, Point2 b, Point2 c) {
  return std::min(a.x, b.x) <= c.x && c.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= c.y &&
         c.y <= std::max(a.y, b.y);
}

// Collinear a, b, c with b != a, c != a: b and c lie on the same side of a on their line.
bool sameSideOnLine(Point2 a, Point2 b, Point2 c) {
  if (b.x != a.x) return (b.x > a.x) == (c.x > a.x);
  return (b.y > a.y) == (c.y > a.y);
}

}  // namespace

// The closed-segment test is exercise 2.3.1-3 (robustness.cpp); delegating keeps its answer out of
// this file's source view and gives the star code one implementation to trust.
bool segmentsIntersect(Point2 a, Point2 b, Point2 c, Point2 d) {
  return segmentsIntersect(a.x, a.y, b.x, b.y, c.x, c.y, d.x, d.y);
}

//! [polygonKernelImpl]
std::vector<Point2> polygonKernel(const std::vector<Point2>& poly) {
  // BEGIN SOLUTION 2.1-1
  if (poly.size() < 3) return {};
  double x0 = poly[0].x, x1 = x0, y0 = poly[0].y, y1 = y0;
  for (const Point2& q : poly) {
    x0 = std::min(x0, q.x), x1 = std::max(x1, q.x);
    y0 = std::min(y0, q.y), y1 = std::max(y1, q.y);
  }
  // ker(Σ) ⊂ Σ ⊂ its bounding box: start from the box and keep, for every oriented edge ab,
  // the part left of the line ab (Sutherland-Hodgman clipping of a convex polygon).
  std::vector<Point2> K = {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}, next;
  const std::size_t m = poly.size();
  for (std::size_t i = 0; i < m && !K.empty(); ++i) {
    const Point2 a = poly[i], b = poly[(i + 1) % m];
    auto value = [&](Point2 q) { return (b.x - a.x) * (q.y - a.y) - (b.y - a.y) * (q.x - a.x); };
    next.clear();
    for (std::size_t k = 0; k < K.size(); ++k) {
      const Point2 u = K[k], v = K[(k + 1) % K.size()];
      const int su = orient(a, b, u), sv = orient(a, b, v);
      if (su >= 0) next.push_back(u);
      if (su * sv < 0) {  // uv crosses the line: add the (rounded) crossing point
        const double du = value(u), dv = value(v), t = du / (du - dv);
        next.push_back({u.x + t * (v.x - u.x), u.y + t * (v.y - u.y)});
      }
    }
    K.clear();
    for (const Point2& q : next)  // drop repeated corners
      if (K.empty() || q.x != K.back().x || q.y != K.back().y) K.push_back(q);
    while (K.size() > 1 && K.front().x == K.back().x && K.front().y == K.back().y) K.pop_back();
    if (K.size() < 3) K.clear();
  }
  // A kernel without interior (a segment or a point) is reported as empty.
  bool hasArea = false;
  for (std::size_t k = 1; k + 1 < K.size() && !hasArea; ++k)
    hasArea = orient(K[0], K[k], K[k + 1]) > 0;
  if (!hasArea) K.clear();
  return K;
  // END SOLUTION 2.1-1
}
//! [polygonKernelImpl]

bool inOpenKernel(const std::vector<Point2>& poly, Point2 x) {
  // BEGIN SOLUTION 2.1-1
  for (std::size_t i = 0; i < poly.size(); ++i)
    if (orient(poly[i], poly[(i + 1) % poly.size()], x) <= 0) return false;
  return !poly.empty();
  // END SOLUTION 2.1-1
}

bool insidePolygon(const std::vector<Point2>& poly, Point2 x) {
  bool in = false;
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const Point2 a = poly[i], b = poly[(i + 1) % poly.size()];
    const int o = orient(a, b, x);
    if (o == 0 && onClosedSegment(a, b, x)) return false;  // on the boundary
    // Crossing number of the ray from x towards +x, half-open in y so that a vertex on the
    // ray counts once; the crossing is right of x iff x is left of the upward edge.
    if ((a.y > x.y) != (b.y > x.y) && ((b.y > a.y) ? o > 0 : o < 0)) in = !in;
  }
  return in;
}

bool seesCorner(const std::vector<Point2>& poly, Point2 x, std::size_t j) {
  if (!insidePolygon(poly, x)) return false;
  const std::size_t m = poly.size();
  const Point2 s = poly[j];
  for (std::size_t i = 0; i < m; ++i) {
    const std::size_t i1 = (i + 1) % m;
    if (i == j || i1 == j) {
      // An edge at σ_j meets the open segment x σ_j only by running along it.
      const Point2 o = poly[i == j ? i1 : i];
      if (orient(x, s, o) == 0 && sameSideOnLine(s, x, o)) return false;
    } else if (segmentsIntersect(x, s, poly[i], poly[i1])) {
      return false;  // σ_j is on no other edge of a simple polygon, so this meets the open part
    }
  }
  return true;
}

//! [checkCavityImpl]
CavityReport checkCavity(const std::vector<const Face*>& C, const Vertex* p) {
  // BEGIN SOLUTION 2.1-2
  CavityReport r;
  auto fail = [&r](const std::string& why) {
    r.ok = false;
    if (r.error.empty()) r.error = why;
    return r;
  };
  r.faces = C.size();
  if (C.empty()) return fail("the cavity is empty");
  // Directed edges a->b of the faces, keyed by their vertex pointers.
  struct Key {
    const Vertex *a, *b;
    bool operator==(const Key& o) const { return a == o.a && b == o.b; }
  };
  struct Hash {
    std::size_t operator()(const Key& k) const {
      return std::hash<const void*>()(k.a) * 31 + std::hash<const void*>()(k.b);
    }
  };
  std::unordered_map<Key, std::size_t, Hash> owner;  // directed edge -> face index
  for (std::size_t i = 0; i < C.size(); ++i) {
    const Face* f = C[i];
    if (f->isGhost()) return fail("a cavity face has a vertex at infinity");
    if (orientationTest(f->V[0], f->V[1], f->V[2]) <= 0)
      return fail("a cavity face is not counter-clockwise");
    if (!f->inCircle(p)) fail("p is not strictly inside the circle of a cavity face");
    for (int k = 0; k < 3; ++k)
      if (!owner.emplace(Key{f->V[k], f->V[(k + 1) % 3]}, i).second)
        return fail("two cavity faces share an edge with the same orientation");
  }
  // Edge-connected components (breadth-first, through edges seen in both directions).
  std::vector<char> seen(C.size(), 0);
  std::vector<std::size_t> queue;
  for (std::size_t s = 0; s < C.size(); ++s) {
    if (seen[s]) continue;
    ++r.components;
    seen[s] = 1;
    queue.assign(1, s);
    while (!queue.empty()) {
      const Face* f = C[queue.back()];
      queue.pop_back();
      for (int k = 0; k < 3; ++k) {
        auto it = owner.find(Key{f->V[(k + 1) % 3], f->V[k]});
        if (it != owner.end() && !seen[it->second]) {
          seen[it->second] = 1;
          queue.push_back(it->second);
        }
      }
    }
  }
  // Boundary: the directed edges whose reverse is not an edge of C.
  std::unordered_map<const Vertex*, const Vertex*> next;
  for (const auto& [k, i] : owner) {
    if (owner.count(Key{k.b, k.a})) continue;
    ++r.boundaryEdges;
    if (!next.emplace(k.a, k.b).second) return fail("two boundary edges leave the same vertex");
    if (orientationTest(k.a, k.b, p) <= 0)
      fail("p is not strictly left of a boundary edge: the cavity is not star-shaped with p "
           "in its kernel");
    // Winding number of the boundary around p: the upward edges crossing the ray from p
    // towards +x (half-open in y). p is strictly left of every edge, so an upward edge
    // crossing p's horizontal line does so right of p, and a downward one left of p.
    if (k.a->y <= p->y && p->y < k.b->y) ++r.winding;
  }
  // Property 2.1.1: every vertex of the cavity lies on its boundary.
  for (const Face* f : C)
    for (const Vertex* v : f->V)
      if (!next.count(v)) ++r.innerVertices;
  if (r.components != 1) fail("the cavity is not edge-connected");
  // One cycle through distinct vertices: following `next` from any vertex returns to it
  // after visiting every boundary edge.
  const Vertex* start = next.begin()->first;
  const Vertex* v = start;
  std::size_t steps = 0;
  do {
    auto it = next.find(v);
    if (it == next.end()) return fail("the boundary is not closed");
    v = it->second;
    ++steps;
  } while (v != start && steps <= next.size());
  if (steps != next.size()) fail("the boundary is not a single cycle");
  if (r.winding != 1) fail("the boundary does not wind once around p");
  if (r.innerVertices != 0) fail("a vertex lies inside the cavity (Property 2.1.1)");
  if (r.boundaryEdges != r.faces + 2) fail("|bnd| != |C| + 2");
  return r;
  // END SOLUTION 2.1-2
}
//! [checkCavityImpl]

std::vector<Face*> conflictFaces(Triangulation& T, const Vertex* p) {
  std::vector<Face*> out;
  for (Face& f : T.faces())
    if (!f.deleted && f.inCircle(p)) out.push_back(&f);
  return out;
}

}  // namespace dt
