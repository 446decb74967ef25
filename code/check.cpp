#include "check.h"

#include <algorithm>
#include <cstdint>
#include <unordered_map>

#include "predicates.h"

namespace dt {

namespace {

CheckReport fail(CheckReport r, const std::string& why) {
  r.ok = false;
  r.error = why;
  return r;
}

std::string pt(const std::vector<double>& xy, int i) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "#%d (%.17g, %.17g)", i, xy[2 * i], xy[2 * i + 1]);
  return buf;
}

}  // namespace

CheckReport checkDelaunay(const std::vector<double>& xy,
                          const std::vector<std::array<int, 3>>& tri,
                          const std::vector<char>* mustUse) {
  CheckReport r;
  const int np = static_cast<int>(xy.size() / 2);
  r.nFaces = tri.size();
  if (tri.empty()) return fail(r, "no triangle");
  auto X = [&](int i) { return xy[2 * i]; };
  auto Y = [&](int i) { return xy[2 * i + 1]; };
  std::vector<char> used(np, 0);
  // Every edge of every triangle, keyed by its unordered vertex pair and sorted, so that the
  // (at most two) triangles of an edge sit side by side. A sort, rather than a hash map, keeps
  // the check of 10^6 points to a fraction of a second.
  struct HalfEdge {
    std::uint64_t key;  // (min vertex, max vertex)
    std::uint32_t t;    // triangle
    std::uint8_t k;     // local index of the edge's first vertex: edge T[k] -> T[k+1]
  };
  std::vector<HalfEdge> he;
  he.reserve(tri.size() * 3);
  auto key = [](int a, int b) {
    return (std::uint64_t(std::uint32_t(std::min(a, b))) << 32) | std::uint32_t(std::max(a, b));
  };
  for (std::size_t t = 0; t < tri.size(); ++t) {
    const auto& T = tri[t];
    for (int k = 0; k < 3; ++k)
      if (T[k] < 0 || T[k] >= np) return fail(r, "triangle " + std::to_string(t) + ": bad index");
    if (T[0] == T[1] || T[1] == T[2] || T[0] == T[2])
      return fail(r, "triangle " + std::to_string(t) + ": repeated vertex");
    if (orient2d(X(T[0]), Y(T[0]), X(T[1]), Y(T[1]), X(T[2]), Y(T[2])) <= 0)
      return fail(r, "triangle " + std::to_string(t) + " is not counter-clockwise: " +
                         pt(xy, T[0]) + " " + pt(xy, T[1]) + " " + pt(xy, T[2]));
    for (int k = 0; k < 3; ++k) {
      used[T[k]] = 1;
      he.push_back({key(T[k], T[(k + 1) % 3]), std::uint32_t(t), std::uint8_t(k)});
    }
  }
  std::sort(he.begin(), he.end(), [](const HalfEdge& p, const HalfEdge& q) {
    return p.key < q.key || (p.key == q.key && p.t < q.t);
  });
  // Interior edges: locally Delaunay. Boundary edges: successor map.
  std::unordered_map<int, int> next;  // boundary: a -> b for boundary edge a->b
  std::size_t nInterior2 = 0;
  for (std::size_t i = 0; i < he.size();) {
    std::size_t j = i + 1;
    while (j < he.size() && he[j].key == he[i].key) ++j;
    const auto& T = tri[he[i].t];
    const int a = T[he[i].k], b = T[(he[i].k + 1) % 3];
    if (j - i == 1) {
      if (!next.emplace(a, b).second)
        return fail(r, "boundary is not a simple polygon at " + pt(xy, a));
    } else {
      const auto& U = tri[he[i + 1].t];
      if (j - i > 2 || U[he[i + 1].k] == a)
        return fail(r, "edge " + pt(xy, a) + " -> " + pt(xy, b) +
                           " belongs to two triangles with the same orientation");
      nInterior2 += 2;
      const int d = U[(he[i + 1].k + 2) % 3];  // vertex of U opposite edge b->a
      if (incircle(X(T[0]), Y(T[0]), X(T[1]), Y(T[1]), X(T[2]), Y(T[2]), X(d), Y(d)) > 0)
        return fail(r, "edge " + pt(xy, a) + " - " + pt(xy, b) + " is not locally Delaunay: " +
                           pt(xy, d) + " is inside the circle of its neighbour");
    }
    i = j;
  }
  // The boundary: one closed cycle, turning left or going straight at every vertex, and going
  // round once (the x-direction of its edges changes sign exactly twice).
  if (next.empty()) return fail(r, "no boundary");
  const int start = next.begin()->first;
  int prev = -1, cur = start, steps = 0, xChanges = 0, lastDx = 0;
  std::vector<int> cycle;
  do {
    cycle.push_back(cur);
    auto it = next.find(cur);
    if (it == next.end()) return fail(r, "boundary is open at " + pt(xy, cur));
    prev = cur;
    cur = it->second;
    const int dx = (X(cur) > X(prev)) - (X(cur) < X(prev));
    if (dx != 0) {
      if (lastDx != 0 && dx != lastDx) ++xChanges;
      lastDx = dx;
    }
    if (++steps > int(next.size())) return fail(r, "boundary does not close");
  } while (cur != start);
  if (std::size_t(steps) != next.size())
    return fail(r, "boundary has more than one component (a hole or a second piece)");
  // close the x-direction count around the cycle
  {
    int firstDx = 0;
    for (std::size_t i = 0; i < cycle.size() && firstDx == 0; ++i) {
      const int a = cycle[i], b = next[a];
      firstDx = (X(b) > X(a)) - (X(b) < X(a));
    }
    if (firstDx != 0 && lastDx != 0 && firstDx != lastDx) ++xChanges;
  }
  const std::size_t m = cycle.size();
  for (std::size_t i = 0; i < m; ++i) {
    const int u = cycle[(i + m - 1) % m], v = cycle[i], w = cycle[(i + 1) % m];
    if (orient2d(X(u), Y(u), X(v), Y(v), X(w), Y(w)) < 0)
      return fail(r, "boundary is not convex at " + pt(xy, v));
  }
  if (xChanges > 2) return fail(r, "boundary winds more than once");
  r.nHull = m;
  r.nVertices = std::size_t(std::count(used.begin(), used.end(), 1));
  r.nEdges = nInterior2 / 2 + next.size();
  const long n = long(r.nVertices), nh = long(r.nHull);
  if (long(r.nFaces) != 2 * (n - 1) - nh)
    return fail(r, "n_f = " + std::to_string(r.nFaces) + " but 2(n-1)-n_h = " +
                       std::to_string(2 * (n - 1) - nh));
  if (long(r.nEdges) != 3 * (n - 1) - nh)
    return fail(r, "n_e = " + std::to_string(r.nEdges) + " but 3(n-1)-n_h = " +
                       std::to_string(3 * (n - 1) - nh));
  if (mustUse != nullptr)
    for (int i = 0; i < np && i < int(mustUse->size()); ++i)
      if ((*mustUse)[i] && !used[i]) return fail(r, "point " + pt(xy, i) + " is not a vertex");
  return r;
}

CheckReport checkTriangulation(const Triangulation& T) {
  CheckReport r;
  for (const Face& f : T.faces()) {
    if (f.deleted) return fail(r, "a face is still marked deleted");
    for (int k = 0; k < 3; ++k) {
      const Face* g = f.F[k];
      if (g == nullptr) continue;
      const int j = neighbourIndex(g, &f);
      if (j < 0) return fail(r, "adjacency is not symmetric");
      if (g->V[j] != f.V[(k + 1) % 3] || g->V[(j + 1) % 3] != f.V[k])
        return fail(r, "neighbours do not share the edge they are linked across");
    }
  }
  const PlainMesh m = extractMesh(T, false);
  return checkDelaunay(m.xy, m.tri);
}

}  // namespace dt
