#include "stats.h"

#include <algorithm>
#include <cstdint>
#include <stdexcept>
#include <unordered_set>

namespace dt {

//! [meshCounts]
MeshCounts meshCounts(std::size_t np, const std::vector<Tri>& tri) {
  MeshCounts c;
  c.vf.assign(np, 0);
  c.ve.assign(np, 0);
  c.nf = long(tri.size());
  // Each edge as (min, max) once per triangle side; an edge listed once is on the boundary.
  std::vector<std::uint64_t> sides;
  sides.reserve(3 * tri.size());
  for (const auto& t : tri)
    for (int k = 0; k < 3; ++k) {
      ++c.vf[t[k]];
      const std::uint32_t a = std::uint32_t(t[k]), b = std::uint32_t(t[(k + 1) % 3]);
      sides.push_back((std::uint64_t(std::min(a, b)) << 32) | std::max(a, b));
    }
  std::sort(sides.begin(), sides.end());
  std::vector<char> onHull(np, 0);
  for (std::size_t i = 0; i < sides.size();) {
    std::size_t j = i + 1;
    while (j < sides.size() && sides[j] == sides[i]) ++j;
    const int a = int(sides[i] >> 32), b = int(sides[i] & 0xffffffffu);
    ++c.ne;
    ++c.ve[a];
    ++c.ve[b];
    if (j - i == 1) onHull[a] = onHull[b] = 1;
    i = j;
  }
  for (std::size_t v = 0; v < np; ++v) {
    if (c.vf[v] == 0) continue;
    ++c.n;
    c.nh += onHull[v];
    c.sumVF += c.vf[v];
    c.sumVE += c.ve[v];
  }
  return c;
}
//! [meshCounts]

//! [gridCounts]
std::array<long, 4> gridCounts(long nx, long ny) {
  // BEGIN SOLUTION 2.3.2-1
  if (nx < 2 || ny < 2) throw std::invalid_argument("gridCounts: need nx, ny >= 2");
  // Every square gets two triangles whichever diagonal it gets; Euler does the rest.
  const long n = nx * ny, nh = 2 * (nx + ny) - 4;
  return {n, nh, 2 * (nx - 1) * (ny - 1), 3 * n - 2 * nx - 2 * ny + 1};
  // END SOLUTION 2.3.2-1
}
//! [gridCounts]

//! [lowDegreeVertex]
int lowDegreeVertex(const MeshCounts& c) {
  // BEGIN SOLUTION 2.3.2-2
  for (std::size_t v = 0; v < c.ve.size(); ++v)
    if (c.vf[v] > 0 && c.ve[v] <= 5) return int(v);
  return -1;
  // END SOLUTION 2.3.2-2
}
//! [lowDegreeVertex]

//! [pointerCountsImpl]
std::vector<PointerCount> pointerCounts(double n, double nh, bool exact) {
  // Exact counts from Euler (2.3.2), or the notes' n >> n_h, n >> 1 values.
  const double nf = exact ? 2 * (n - 1) - nh : 2 * n;
  const double ne = exact ? 3 * (n - 1) - nh : 3 * n;
  const double nvf = exact ? 3 * nf / n : 6;  // each triangle has 3 corners
  const double nve = exact ? 2 * ne / n : 6;  // each edge has 2 ends
  const double nef = exact ? 3 * nf / ne : 2; // each triangle has 3 sides
  return {
      {"full", (n * (1 + nve + nvf) + ne * (2 + 1 + nef) + nf * (3 + 3 + 1)) / n},
      {"bidirectional", (n * (1 + nve) + ne * (2 + 1 + nef) + nf * (3 + 1)) / n},
      {"vertices only", (n + nf * (3 + 1)) / n},
      {"winged-edge", (n * (1 + 1) + ne * (1 + 8) + nf * (1 + 1)) / n},
      {"face-based", (n + nf * (1 + 6)) / n},
  };
}
//! [pointerCountsImpl]

//! [halfEdgePointers]
double halfEdgePointers(double n, double nh, bool exact) {
  // BEGIN SOLUTION 2.3.3-1
  const double nf = exact ? 2 * (n - 1) - nh : 2 * n;
  const double ne = exact ? 3 * (n - 1) - nh : 3 * n;
  return (2 * ne * (1 + 4) + n * (1 + 1) + nf * (1 + 1)) / n;
  // END SOLUTION 2.3.3-1
}
//! [halfEdgePointers]

//! [vertexStarImpl]
std::vector<Face*> vertexStar(Face* f, const Vertex* v, std::size_t maxFaces) {
  // BEGIN SOLUTION 2.3.3-2
  // A turn through F[] from face to face: time proportional to the degree of v.
  auto corner = [v](const Face* g) {
    for (int i = 0; i < 3; ++i)
      if (g->V[i] == v) return i;
    throw std::logic_error("vertexStar: the vertex is not a corner of the face");
  };
  std::vector<Face*> star;
  // Counter-clockwise around v: leave g through the edge V[i+2] -> V[i] (neighbour F[i+2]).
  Face* g = f;
  do {
    star.push_back(g);
    if (star.size() > maxFaces) throw std::logic_error("vertexStar: the turn does not close");
    g = g->F[(corner(g) + 2) % 3];
  } while (g != nullptr && g != f);
  if (g == f) {
    // Closed turn. Around a hull vertex it passes through ghost faces: start just after them,
    // so that the finite faces come out as one fan, consecutive ones sharing an edge.
    std::size_t k = 0;
    while (k < star.size() && !star[k]->isGhost()) ++k;
    if (k < star.size()) {
      while (star[k % star.size()]->isGhost()) ++k;
      std::rotate(star.begin(), star.begin() + long(k % star.size()), star.end());
      star.erase(std::remove_if(star.begin(), star.end(), [](Face* h) { return h->isGhost(); }),
                 star.end());
    }
    return star;
  }
  // Open star (a boundary vertex without ghost faces): turn clockwise from f, through F[i].
  std::vector<Face*> back;
  for (g = f->F[corner(f)]; g != nullptr; g = g->F[corner(g)]) {
    back.push_back(g);
    if (star.size() + back.size() > maxFaces)
      throw std::logic_error("vertexStar: the turn does not close");
  }
  star.insert(star.begin(), back.rbegin(), back.rend());
  return star;
  // END SOLUTION 2.3.3-2
}
//! [vertexStarImpl]

//! [computeAdjacenciesSorted]
void computeAdjacenciesSorted(std::vector<Face*>& faces) {
  // BEGIN SOLUTION 2.3.4-1
  struct Side {
    Vertex *lo, *hi;  // the edge, sorted
    std::size_t face;
    int k;  // F[k] of faces[face] is across it
    bool forward;  // lo -> hi is the face's orientation of the edge
  };
  std::vector<Side> sides;
  sides.reserve(3 * faces.size());
  std::less<Vertex*> lt;
  for (std::size_t i = 0; i < faces.size(); ++i)
    for (int k = 0; k < 3; ++k) {
      Vertex* a = faces[i]->V[k];
      Vertex* b = faces[i]->V[(k + 1) % 3];
      const bool fwd = lt(a, b);
      sides.push_back({fwd ? a : b, fwd ? b : a, i, k, fwd});
    }
  std::sort(sides.begin(), sides.end(), [&lt](const Side& s, const Side& t) {
    if (s.lo != t.lo) return lt(s.lo, t.lo);
    return lt(s.hi, t.hi);
  });
  for (std::size_t i = 0; i < sides.size();) {
    std::size_t j = i + 1;
    while (j < sides.size() && sides[j].lo == sides[i].lo && sides[j].hi == sides[i].hi) ++j;
    if (j - i > 2) throw std::logic_error("computeAdjacenciesSorted: edge of three faces");
    if (j - i == 2) {
      const Side& s = sides[i];
      const Side& t = sides[i + 1];
      if (s.forward == t.forward)
        throw std::logic_error("computeAdjacenciesSorted: edge used twice with one orientation");
      faces[s.face]->F[s.k] = faces[t.face];
      faces[t.face]->F[t.k] = faces[s.face];
    }
    i = j;
  }
  // END SOLUTION 2.3.4-1
}
//! [computeAdjacenciesSorted]

//! [backwardCavityMean]
std::array<double, 2> backwardCavityMean(const Triangulation& T) {
  // BEGIN SOLUTION 2.3.4-2
  double sum = 0, D = 0;
  std::unordered_set<const Vertex*> real;  // vertices of the mesh (skipped duplicates are not)
  for (const Face* f : T.finiteFaces())
    for (const Vertex* v : f->V) {
      (v->id < 0 ? D : sum) += 1;
      if (v->id >= 0) real.insert(v);
    }
  const double n = double(real.size());
  return {n > 0 ? (sum - 2 * n) / n : 0, D};
  // END SOLUTION 2.3.4-2
}
//! [backwardCavityMean]

}  // namespace dt
