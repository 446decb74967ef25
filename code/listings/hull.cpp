#include "hull.h"

#include <algorithm>
#include <stdexcept>

#include "adjacency.h"
#include "triangulate.h"

namespace dt {

Face* anyGhost(const Triangulation& T) {
  for (const Face& f : T.faces())
    if (!f.deleted && f.isGhost()) return const_cast<Face*>(&f);
  return nullptr;
}

// The hull edge of ghost g, as the hull runs (counter-clockwise): V[i+2] -> V[i+1].
static HullEdge edgeOf(Face* g) {
  const int i = g->infiniteIndex();
  return HullEdge{g->V[(i + 2) % 3], g->V[(i + 1) % 3], g};
}

std::vector<HullEdge> hullEdges(const Triangulation& T) {
  std::vector<HullEdge> out;
  Face* g0 = anyGhost(T);
  if (g0 == nullptr) return out;
  // The ring has at most as many ghosts as T has faces: the bound turns a broken ring into
  // an error instead of an endless loop.
  const std::size_t cap = T.faces().size();
  Face* g = g0;
  do {
    out.push_back(edgeOf(g));
    g = ghostNext(g);
    if (g == nullptr || !g->isGhost() || out.size() > cap)
      throw std::logic_error("hullEdges: the ghost faces do not form a ring");
  } while (g != g0);
  return out;
}

std::vector<Vertex*> convexHull(const Triangulation& T) {
  std::vector<Vertex*> out;
  for (const HullEdge& e : hullEdges(T)) out.push_back(e.a);
  return out;
}

std::vector<HullEdge> visibleHullEdges(const Triangulation& T, const Vertex* q) {
  const std::vector<HullEdge> ring = hullEdges(T);
  const std::size_t m = ring.size();
  std::vector<char> sees(m);
  for (std::size_t i = 0; i < m; ++i) sees[i] = orientationTest(ring[i].a, ring[i].b, q) < 0;
  // Start after an edge q does not see, so the visible chain comes out in one piece.
  std::size_t s = 0;
  while (s < m && sees[s]) ++s;
  std::vector<HullEdge> out;
  if (s == m) return out;  // cannot happen for a convex hull; nothing sensible to return
  for (std::size_t k = 1; k <= m; ++k) {
    const std::size_t i = (s + k) % m;
    if (sees[i]) out.push_back(ring[i]);
  }
  return out;
}

void attachGhosts(Triangulation& T, const std::vector<Face*>& faces) {
  Vertex* inf = T.infiniteVertex();
  std::vector<Face*> ghosts;
  for (Face* f : faces)
    for (int k = 0; k < 3; ++k) {
      if (f->F[k] != nullptr) continue;
      // The ghost across boundary edge u -> v of f is (v, u, inf); its edge (v, u) is f's.
      Face* g = T.addFace(f->V[(k + 1) % 3], f->V[k], inf);
      g->F[0] = f;
      f->F[k] = g;
      ghosts.push_back(g);
    }
  // The ghost-to-ghost edges (v, inf) are each shared by exactly two ghosts around the hull.
  computeAdjacencies(ghosts);
}

//! [insertOutsideHull]
Face* insertOutsideHull(Triangulation& T, Vertex* q, Face* hint) {
  auto sees = [q](Face* g) {
    const HullEdge e = edgeOf(g);
    return orientationTest(e.a, e.b, q) < 0;
  };
  // Walk the ring from the hint to a visible edge (at most once round).
  const std::size_t cap = T.faces().size() + 1;
  std::size_t steps = 0;
  Face* g = hint;
  while (!sees(g)) {
    g = ghostNext(g);
    if (g == hint || ++steps > cap)
      throw std::invalid_argument("insertOutsideHull: the point sees no hull edge");
  }
  // Extend the visible chain both ways: first .. last, counter-clockwise.
  Face* first = g;
  Face* last = g;
  while (sees(ghostPrev(first)) && ghostPrev(first) != last) first = ghostPrev(first);
  while (sees(ghostNext(last)) && ghostNext(last) != first) last = ghostNext(last);
  Face* before = ghostPrev(first);
  Face* after = ghostNext(last);
  const HullEdge e0 = edgeOf(first), e1 = edgeOf(last);
  // The chain's ghosts become the triangles (hull edge, q): only the vertex at infinity changes,
  // so the links inside the chain and to the finite faces stay right.
  std::size_t chain = 0;
  for (Face* c = first;;) {
    Face* next = ghostNext(c);  // read while c is still a ghost
    c->V[c->infiniteIndex()] = q;
    if (c == last) break;
    if (++chain > cap) throw std::logic_error("insertOutsideHull: broken ghost ring");
    c = next;
  }
  // New hull edges e0.a -> q and q -> e1.b, with ghosts (q, e0.a, inf) and (e1.b, q, inf).
  Vertex* inf = T.infiniteVertex();
  Face* g0 = T.addFace(q, e0.a, inf);
  Face* g1 = T.addFace(e1.b, q, inf);
  std::vector<Face*> touched = {first, g0, g1, before};
  if (last != first) touched.push_back(last);
  if (after != before) touched.push_back(after);
  // Every stale link (across the old infinite edges of the chain's ends) is on an edge that
  // two faces of this list now share, so computeAdjacencies overwrites it.
  computeAdjacencies(touched);
  return g0;
}
//! [insertOutsideHull]

void sweepTriangulation(Triangulation& T, const std::vector<Vertex*>& S, SweepStats* stats) {
  SweepStats local;
  SweepStats& st = stats ? *stats : local;
  std::vector<Vertex*> P(S);
  std::sort(P.begin(), P.end(), [](const Vertex* u, const Vertex* v) {
    return u->x < v->x || (u->x == v->x && u->y < v->y);
  });
  std::vector<Vertex*> U;  // distinct points, lexicographic order
  for (Vertex* v : P) {
    if (!U.empty() && U.back()->x == v->x && U.back()->y == v->y) {
      ++st.duplicates;
      continue;
    }
    U.push_back(v);
  }
  if (U.size() < 3) throw DegenerateInput("fewer than 3 distinct points");
  // The leading collinear run U[0..m-1] and the first point U[m] off its line.
  std::size_t m = 2;
  while (m < U.size() && orientationTest(U[0], U[1], U[m]) == 0) ++m;
  if (m == U.size()) throw DegenerateInput("all points are collinear");
  std::vector<Face*> fan;
  for (std::size_t i = 0; i + 1 < m; ++i) {
    Vertex *a = U[i], *b = U[i + 1];
    if (orientationTest(a, b, U[m]) < 0) std::swap(a, b);
    fan.push_back(T.addFace(a, b, U[m]));
  }
  computeAdjacencies(fan);
  attachGhosts(T, fan);
  // A ghost incident to U[m], the lexicographically largest point so far.
  Face* hint = nullptr;
  for (Face& f : T.faces())
    if (f.isGhost() && (f.V[0] == U[m] || f.V[1] == U[m] || f.V[2] == U[m])) hint = &f;
  for (std::size_t i = m + 1; i < U.size(); ++i) {
    // The hull's lexicographically largest vertex is the previous point: q sees an edge at it.
    hint = insertOutsideHull(T, U[i], hint);
  }
}

}  // namespace dt
