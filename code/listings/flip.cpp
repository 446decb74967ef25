#include "flip.h"

#include <algorithm>
#include <stdexcept>
#include <unordered_map>
#include <vector>

#include "hull.h"
#include "predicates.h"

namespace dt {

bool isFlippable(const Face* f, int k) {
  const Face* g = f->F[k];
  if (g == nullptr || f->isGhost() || g->isGhost()) return false;
  const int j = neighbourIndex(g, f);
  if (j < 0) return false;
  const Vertex* a = f->V[k];
  const Vertex* b = f->V[(k + 1) % 3];
  const Vertex* c = f->V[(k + 2) % 3];
  const Vertex* d = g->V[(j + 2) % 3];
  // The quadrilateral a d b c is strictly convex iff both new triangles turn left.
  return orientationTest(c, a, d) > 0 && orientationTest(d, b, c) > 0;
}

//! [flipEdge]
bool flipEdge(Face* f, int k) {
  if (!isFlippable(f, k)) return false;
  Face* g = f->F[k];
  const int j = neighbourIndex(g, f);
  Vertex* a = f->V[k];
  Vertex* b = f->V[(k + 1) % 3];
  Vertex* c = f->V[(k + 2) % 3];
  Vertex* d = g->V[(j + 2) % 3];
  Face* fbc = f->F[(k + 1) % 3];  // across b c
  Face* fca = f->F[(k + 2) % 3];  // across c a
  Face* gad = g->F[(j + 1) % 3];  // across a d
  Face* gdb = g->F[(j + 2) % 3];  // across d b
  // f = (c, a, d): edges c a, a d, d c.   g = (d, b, c): edges d b, b c, c d.
  f->V[0] = c, f->V[1] = a, f->V[2] = d;
  f->F[0] = fca, f->F[1] = gad, f->F[2] = g;
  g->V[0] = d, g->V[1] = b, g->V[2] = c;
  g->F[0] = gdb, g->F[1] = fbc, g->F[2] = f;
  // Two outer faces changed sides: a d now borders f (was g), b c now borders g (was f).
  if (gad != nullptr) gad->F[neighbourIndex(gad, g)] = f;
  if (fbc != nullptr) fbc->F[neighbourIndex(fbc, f)] = g;
  return true;
}
//! [flipEdge]

namespace {

// A stack entry: the directed edge a -> b of face f when it was pushed. A flip elsewhere may
// have moved the edge to another face (then the flip pushed it again) or removed it: an entry
// whose face no longer has a -> b is stale and skipped. Every edge that may have stopped being
// locally Delaunay (the four outer edges of a flipped quadrilateral) is pushed with its current
// face, so no edge is missed.
struct StackEdge {
  Face* f;
  Vertex* a;
  Vertex* b;
};

bool isSuper(const Vertex* v) { return v->id < 0 && !v->infinite; }

void pushEdges(std::vector<StackEdge>& st, Face* f) {
  for (int k = 0; k < 3; ++k) st.push_back({f, f->V[k], f->V[(k + 1) % 3]});
}

// Lawson's loop. `conflict(a,b,c,d) > 0`: flip edge a b of (a, b, c) | (b, a, d).
// `accept(a,b,c,d)`: the edge kind may be flipped at all. `onFlip` records the kind.
template <class Conflict, class Accept, class OnFlip>
void lawsonLoop(std::vector<StackEdge>& st, std::size_t nFaces, FlipStats& stats,
                Conflict conflict, Accept accept, OnFlip onFlip) {
  // Lawson flips at most O(n^2) times (each flip lowers the lifted surface); the cap only
  // turns a bug into an exception.
  const std::uint64_t cap = std::uint64_t(nFaces) * nFaces + 64;
  while (!st.empty()) {
    const StackEdge e = st.back();
    st.pop_back();
    Face* f = e.f;
    if (f->deleted) continue;
    int k = -1;
    for (int i = 0; i < 3 && k < 0; ++i)
      if (f->V[i] == e.a && f->V[(i + 1) % 3] == e.b) k = i;
    if (k < 0) continue;  // stale
    Face* g = f->F[k];
    if (g == nullptr || f->isGhost() || g->isGhost()) continue;  // hull or domain boundary
    Vertex* c = f->V[(k + 2) % 3];
    Vertex* d = g->V[(neighbourIndex(g, f) + 2) % 3];
    if (!accept(e.a, e.b, c, d)) continue;
    ++stats.tests;
    if (conflict(e.a, e.b, c, d) <= 0) continue;
    // A strict conflict implies a strictly convex quadrilateral (a reflex corner would lie
    // inside the triangle of the other three, below their lifted plane); checked anyway.
    if (!flipEdge(f, k))
      throw std::logic_error("Lawson: an edge in conflict is not flippable");
    onFlip(e.a, e.b, c, d);
    if (++stats.flips > cap) throw std::logic_error("Lawson: too many flips");
    // After the flip f = (c, a, d) and g = (d, b, c); their outer edges go back on the stack.
    st.push_back({f, c, e.a});
    st.push_back({f, e.a, d});
    st.push_back({g, d, e.b});
    st.push_back({g, e.b, c});
  }
}

}  // namespace

//! [lawsonFlip]
FlipStats lawsonFlip(Triangulation& T) {
  FlipStats stats;
  std::vector<StackEdge> st;
  for (Face& f : T.faces())
    if (!f.deleted && !f.isGhost()) pushEdges(st, &f);
  lawsonLoop(
      st, T.faces().size(), stats,
      [](Vertex* a, Vertex* b, Vertex* c, Vertex* d) {
        return incircle(a->x, a->y, b->x, b->y, c->x, c->y, d->x, d->y);
      },
      [](Vertex*, Vertex*, Vertex*, Vertex*) { return true; },
      [](Vertex*, Vertex*, Vertex*, Vertex*) {});
  return stats;
}
//! [lawsonFlip]

//! [superInCircle]
int superInCircle(const Vertex* a, const Vertex* b, const Vertex* c, const Vertex* d) {
  // "d below the plane of a, b, c" is Q = O(d,b,c) z_a + O(a,d,c) z_b + O(a,b,d) z_c
  // - O(a,b,c) z_d > 0 (O = orientation), which has the sign of incircle(a, b, c, d).
  // The coefficient of the highest super vertex's H decides; ties fall to the next one.
  const Vertex* q[4] = {a, b, c, d};
  int order[4], m = 0;
  for (int i = 0; i < 4; ++i)
    if (isSuper(q[i])) order[m++] = i;
  // p_{-1} is the farthest: larger id (closer to 0) first (insertion sort of at most 4).
  for (int i = 1; i < m; ++i)
    for (int j = i; j > 0 && q[order[j]]->id > q[order[j - 1]]->id; --j)
      std::swap(order[j], order[j - 1]);
  for (int t = 0; t < m; ++t) {
    int s = 0;
    switch (order[t]) {
      case 0: s = orientationTest(d, b, c); break;
      case 1: s = orientationTest(a, d, c); break;
      case 2: s = orientationTest(a, b, d); break;
      default: s = -orientationTest(a, b, c); break;
    }
    if (s != 0) return s;
  }
  return incircle(a->x, a->y, b->x, b->y, c->x, c->y, d->x, d->y);
}
//! [superInCircle]

void compactFaces(Triangulation& T) {
  std::deque<Face>& F = T.faces();
  std::unordered_map<const Face*, Face*> to;
  std::size_t w = 0;
  for (std::size_t i = 0; i < F.size(); ++i)
    if (!F[i].deleted) to[&F[i]] = &F[w++];
  w = 0;
  for (std::size_t i = 0; i < F.size(); ++i)
    if (!F[i].deleted) {
      if (i != w) F[w] = F[i];
      ++w;
    }
  while (F.size() > w) F.pop_back();
  for (Face& f : F)
    for (Face*& n : f.F)
      if (n != nullptr) {
        auto it = to.find(n);
        if (it == to.end()) throw std::logic_error("compactFaces: link to a deleted face");
        n = it->second;
      }
}

//! [recoverDelaunay]
FlipStats recoverDelaunay(Triangulation& T, RecoveryRule rule,
                          std::vector<std::array<const Vertex*, 4>>* log) {
  FlipStats stats;
  std::vector<StackEdge> st;
  for (Face& f : T.faces()) {
    if (f.deleted || f.isGhost()) continue;
    if (isSuper(f.V[0]) || isSuper(f.V[1]) || isSuper(f.V[2])) pushEdges(st, &f);
  }
  const bool notesOnly = rule == RecoveryRule::NotesOnly;
  lawsonLoop(
      st, T.faces().size(), stats,
      [](Vertex* a, Vertex* b, Vertex* c, Vertex* d) { return superInCircle(a, b, c, d); },
      [notesOnly](Vertex* a, Vertex* b, Vertex* c, Vertex* d) {
        // 2.2.1's rule: an edge p_{-i} p_j whose opposite vertices are both in S. For it,
        // superInCircle reduces to "p_{-i} p_j crosses p_k p_l" (one orientation test).
        return !notesOnly || (isSuper(a) != isSuper(b) && !isSuper(c) && !isSuper(d));
      },
      [&stats, log](Vertex* a, Vertex* b, Vertex* c, Vertex* d) {
        if (log != nullptr) log->push_back({a, b, c, d});
        const int sa = isSuper(a) + isSuper(b);
        if (sa == 2) ++stats.superSuper;
        else if (sa == 0) ++stats.realReal;
        else if (isSuper(c) || isSuper(d)) ++stats.superOpposite;
        else ++stats.notesFlips;
      });
  if (notesOnly) return stats;
  // Remove the faces touching a super vertex; the faces of S now tile conv(S) (see the book),
  // and their boundary edges get ghost faces.
  std::vector<Face*> border;
  for (Face& f : T.faces()) {
    if (f.deleted || f.isGhost()) continue;
    if (isSuper(f.V[0]) || isSuper(f.V[1]) || isSuper(f.V[2])) {
      f.deleted = true;
      ++stats.removedFaces;
    }
  }
  for (Face& f : T.faces()) {
    if (f.deleted) continue;
    bool onBorder = false;
    for (Face*& n : f.F)
      if (n != nullptr && n->deleted) n = nullptr, onBorder = true;
    if (onBorder) border.push_back(&f);
  }
  if (border.empty()) throw std::logic_error("recoverDelaunay: no face of S is left");
  attachGhosts(T, border);
  compactFaces(T);
  return stats;
}
//! [recoverDelaunay]

}  // namespace dt
