#include "check.h"

#include <algorithm>
#include <cstdint>

#include "predicates.h"
#include "predicates_inline.h"

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
                          const std::vector<Tri>& tri,
                          const std::vector<char>* mustUse) {
  CheckReport r;
  const int np = static_cast<int>(xy.size() / 2);
  r.nFaces = tri.size();
  if (tri.empty()) return fail(r, "no triangle");
  auto X = [&](int i) { return xy[2 * i]; };
  auto Y = [&](int i) { return xy[2 * i + 1]; };
  std::vector<char> used(np, 0);
  // Filtered predicates inlined (predicates_inline.h): GMP only where the filter and the
  // small-multiple stage cannot decide.
  auto orient = [&](int a, int b, int c) {
    int stage = pred::kFilter;
    return pred::orient2d(X(a), Y(a), X(b), Y(b), X(c), Y(c), stage);
  };
  if (tri.size() > (std::size_t(1) << 30)) return fail(r, "more than 2^30 triangles");
  for (std::size_t t = 0; t < tri.size(); ++t) {
    const auto& T = tri[t];
    for (int k = 0; k < 3; ++k)
      if (T[k] < 0 || T[k] >= np) return fail(r, "triangle " + std::to_string(t) + ": bad index");
    if (T[0] == T[1] || T[1] == T[2] || T[0] == T[2])
      return fail(r, "triangle " + std::to_string(t) + ": repeated vertex");
    if (orient(T[0], T[1], T[2]) <= 0)
      return fail(r, "triangle " + std::to_string(t) + " is not counter-clockwise: " +
                         pt(xy, T[0]) + " " + pt(xy, T[1]) + " " + pt(xy, T[2]));
    for (int k = 0; k < 3; ++k) used[T[k]] = 1;
  }
  // Every edge of every triangle, grouped by its smaller vertex with a counting sort (linear
  // time, 4 bytes per half-edge): the (at most two) triangles of an edge land in the same small
  // group, where a short sort by the other vertex puts them side by side.
  std::vector<std::uint32_t> start(std::size_t(np) + 1, 0);
  auto lo = [&](std::uint32_t h) {
    const auto& T = tri[h / 3];
    return std::min(T[h % 3], T[(h % 3 + 1) % 3]);
  };
  auto hi = [&](std::uint32_t h) {
    const auto& T = tri[h / 3];
    return std::max(T[h % 3], T[(h % 3 + 1) % 3]);
  };
  const std::uint32_t nHalf = std::uint32_t(3 * tri.size());
  for (std::uint32_t h = 0; h < nHalf; ++h) ++start[std::size_t(lo(h)) + 1];
  for (int v = 0; v < np; ++v) start[std::size_t(v) + 1] += start[std::size_t(v)];
  std::vector<std::uint32_t> he(nHalf);
  {
    std::vector<std::uint32_t> fillPos(start.begin(), start.end() - 1);
    for (std::uint32_t h = 0; h < nHalf; ++h) he[fillPos[std::size_t(lo(h))]++] = h;
  }
  // Interior edges: locally Delaunay. Boundary edges: successor map.
  std::vector<int> next(std::size_t(np), -1);  // boundary: a -> b for boundary edge a->b
  std::size_t nBoundary = 0, nInterior2 = 0;
  // The groups in vertex order: the memory reads are as coherent as the numbering (the command
  // line numbers the points in the fast kernel's spatially sorted insertion order).
  std::string failure;
  std::vector<std::uint64_t> keys;  // one group: (other vertex, half-edge), sorted
  auto group = [&](int v) {
    keys.clear();
    for (std::uint32_t e = start[std::size_t(v)]; e < start[std::size_t(v) + 1]; ++e)
      keys.push_back((std::uint64_t(std::uint32_t(hi(he[e]))) << 32) | he[e]);
    std::sort(keys.begin(), keys.end());
    const auto gb = keys.begin(), ge = keys.end();
    for (auto i = gb; i != ge;) {
      auto j = i + 1;
      while (j != ge && (*j >> 32) == (*i >> 32)) ++j;
      const std::uint32_t h0 = std::uint32_t(*i), h1 = std::uint32_t(*(i + 1 == ge ? i : i + 1));
      const auto& T = tri[h0 / 3];
      const int a = T[h0 % 3], b = T[(h0 % 3 + 1) % 3];
      if (j - i == 1) {
        if (next[std::size_t(a)] >= 0) {
          failure = "boundary is not a simple polygon at " + pt(xy, a);
          return false;
        }
        next[std::size_t(a)] = b;
        ++nBoundary;
      } else {
        const auto& U = tri[h1 / 3];
        const int ku = int(h1 % 3);
        if (j - i > 2 || U[ku] == a) {
          failure = "edge " + pt(xy, a) + " -> " + pt(xy, b) +
                    " belongs to two triangles with the same orientation";
          return false;
        }
        nInterior2 += 2;
        const int d = U[(ku + 2) % 3];  // vertex of U opposite edge b->a
        int stage = pred::kFilter;
        if (pred::incircle(X(T[0]), Y(T[0]), X(T[1]), Y(T[1]), X(T[2]), Y(T[2]), X(d), Y(d),
                           stage) > 0) {
          failure = "edge " + pt(xy, a) + " - " + pt(xy, b) + " is not locally Delaunay: " +
                    pt(xy, d) + " is inside the circle of its neighbour";
          return false;
        }
      }
      i = j;
    }
    return true;
  };
  for (int v = 0; v < np; ++v)
    if (!group(v)) return fail(r, failure);
  // The boundary: one closed cycle, turning left or going straight at every vertex, and going
  // round once (the x-direction of its edges changes sign exactly twice).
  if (nBoundary == 0) return fail(r, "no boundary");
  int start0 = 0;
  while (next[std::size_t(start0)] < 0) ++start0;
  int prev = -1, cur = start0, steps = 0, xChanges = 0, lastDx = 0;
  std::vector<int> cycle;
  do {
    cycle.push_back(cur);
    if (next[std::size_t(cur)] < 0) return fail(r, "boundary is open at " + pt(xy, cur));
    prev = cur;
    cur = next[std::size_t(cur)];
    const int dx = (X(cur) > X(prev)) - (X(cur) < X(prev));
    if (dx != 0) {
      if (lastDx != 0 && dx != lastDx) ++xChanges;
      lastDx = dx;
    }
    if (++steps > int(nBoundary)) return fail(r, "boundary does not close");
  } while (cur != start0);
  if (std::size_t(steps) != nBoundary)
    return fail(r, "boundary has more than one component (a hole or a second piece)");
  // close the x-direction count around the cycle
  {
    int firstDx = 0;
    for (std::size_t i = 0; i < cycle.size() && firstDx == 0; ++i) {
      const int a = cycle[i], b = next[std::size_t(a)];
      firstDx = (X(b) > X(a)) - (X(b) < X(a));
    }
    if (firstDx != 0 && lastDx != 0 && firstDx != lastDx) ++xChanges;
  }
  const std::size_t m = cycle.size();
  for (std::size_t i = 0; i < m; ++i) {
    const int u = cycle[(i + m - 1) % m], v = cycle[i], w = cycle[(i + 1) % m];
    if (orient(u, v, w) < 0)
      return fail(r, "boundary is not convex at " + pt(xy, v));
  }
  if (xChanges > 2) return fail(r, "boundary winds more than once");
  r.nHull = m;
  r.nVertices = std::size_t(std::count(used.begin(), used.end(), 1));
  r.nEdges = nInterior2 / 2 + nBoundary;
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
