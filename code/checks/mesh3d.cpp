#include "mesh3d.h"

#include <algorithm>
#include <stdexcept>

namespace dt {

std::vector<Tet> kuhnTetrahedra(int k) {
  if (k < 1) throw std::invalid_argument("kuhnTetrahedra: k must be at least 1");
  auto id = [k](const int c[3]) { return (c[0] * (k + 1) + c[1]) * (k + 1) + c[2]; };
  std::vector<Tet> tets;
  for (int i = 0; i < k; ++i)
    for (int j = 0; j < k; ++j)
      for (int l = 0; l < k; ++l) {
        Tri axes = {0, 1, 2};
        do {  // one tetrahedron per order of the three steps
          int c[3] = {i, j, l};
          Tet t;
          t[0] = id(c);
          for (int s = 0; s < 3; ++s) {
            ++c[axes[std::size_t(s)]];
            t[std::size_t(s + 1)] = id(c);
          }
          tets.push_back(t);
        } while (std::next_permutation(axes.begin(), axes.end()));
      }
  return tets;
}

std::map<Tri, int> tetsPerFacet(const std::vector<Tet>& tets) {
  std::map<Tri, int> out;
  for (Tet t : tets) {
    std::sort(t.begin(), t.end());
    for (int skip = 0; skip < 4; ++skip) {
      Tri f;
      for (int q = 0, m = 0; q < 4; ++q)
        if (q != skip) f[std::size_t(m++)] = t[std::size_t(q)];
      ++out[f];
    }
  }
  return out;
}

std::map<std::pair<int, int>, EdgeRing> edgeRings(const std::vector<Tet>& tets) {
  // Around edge ab each tetrahedron abcd has two facets through ab, named by c and d; two
  // tetrahedra are consecutive around ab iff they share one of these names.
  std::map<std::pair<int, int>, std::vector<std::pair<int, std::array<int, 2>>>> around;
  for (int q = 0; q < int(tets.size()); ++q) {
    const Tet& t = tets[std::size_t(q)];
    for (int a = 0; a < 4; ++a)
      for (int b = a + 1; b < 4; ++b) {
        std::array<int, 2> other;
        for (int r = 0, m = 0; r < 4; ++r)
          if (r != a && r != b) other[std::size_t(m++)] = t[std::size_t(r)];
        around[std::minmax(t[std::size_t(a)], t[std::size_t(b)])].push_back({q, other});
      }
  }
  std::map<std::pair<int, int>, EdgeRing> out;
  for (const auto& [edge, list] : around) {
    std::map<int, std::vector<std::size_t>> byFacet;  // facet name -> positions in list
    for (std::size_t p = 0; p < list.size(); ++p)
      for (int c : list[p].second) byFacet[c].push_back(p);
    std::size_t start = 0;
    int ends = 0, startFrom = -1;
    for (const auto& [c, ps] : byFacet) {
      if (ps.size() > 2)
        throw std::logic_error("edgeRings: a facet through an edge has more than two tetrahedra");
      if (ps.size() == 1) {
        if (ends++ == 0) start = ps[0], startFrom = c;  // a path starts at an end
      }
    }
    if (ends != 0 && ends != 2)
      throw std::logic_error("edgeRings: the tetrahedra around an edge are not one fan");
    EdgeRing ring;
    ring.closed = ends == 0;
    std::vector<bool> used(list.size(), false);
    std::size_t cur = start;
    int from = startFrom;  // the facet we came through (a path's end: the open one)
    while (true) {
      used[cur] = true;
      ring.tets.push_back(list[cur].first);
      const auto& names = list[cur].second;
      const int next = names[0] == from ? names[1] : names[0];
      std::size_t nextPos = cur;
      for (std::size_t p : byFacet[next])
        if (p != cur) nextPos = p;
      if (nextPos == cur || used[nextPos]) break;  // a path's end, or the cycle closed
      from = next;
      cur = nextPos;
    }
    if (ring.tets.size() != list.size())
      throw std::logic_error("edgeRings: the tetrahedra around an edge are not one fan");
    out[edge] = ring;
  }
  return out;
}

}  // namespace dt
