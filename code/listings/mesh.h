// The face-based data structure of section 2.3.3: Listings 2.1 (Vertex), 2.2 (Edge) and
// 2.3 (Face), corrected, and the Triangulation that owns them.
#pragma once

#include <cstddef>
#include <cstdint>
#include <deque>
#include <functional>
#include <vector>

namespace dt {

//! [Vertex]
/// A point of the triangulation (Listing 2.1). `id` is the point's number in the input
/// (0-based); the super-triangle corners p_{-1}..p_{-4} of 2.2.1 have ids -1..-4, and the
/// vertex at infinity used for insertions outside the hull (2.2.2) has `infinite` set.
struct Vertex {
  double x, y, z;
  long id = 0;
  bool infinite = false;
  // Listing 2.1 printed the parameter list garbled ("double }X\mathrm{"); z defaults to 0 in 2D.
  Vertex(double X, double Y, double Z = 0, long ID = 0) : x(X), y(Y), z(Z), id(ID) {}
};
//! [Vertex]

//! [Edge]
/// An edge (Listing 2.2): unoriented for comparison, but it remembers the orientation it was
/// created with, because the Delaunay ball (Listing 2.7) needs it.
struct Edge {
  Vertex *vmin, *vmax;  // sorted: equality and order ignore orientation
  Vertex* V[2];         // as created: V[0] -> V[1]
  // Listing 2.2 lacked the constructor's opening brace and wrote "vl" for v1.
  Edge(Vertex* v1, Vertex* v2) : V{v1, v2} {
    // Listing 2.2 compared unrelated pointers with < and std::min, which C++ leaves
    // unspecified; std::less gives the total order the map needs.
    const bool swapped = std::less<Vertex*>()(v2, v1);
    vmin = swapped ? v2 : v1;
    vmax = swapped ? v1 : v2;
  }
  bool operator<(const Edge& other) const {
    std::less<Vertex*> lt;
    if (lt(vmin, other.vmin)) return true;
    if (lt(other.vmin, vmin)) return false;
    return lt(vmax, other.vmax);
  }
  bool operator==(const Edge& other) const {
    return vmin == other.vmin && vmax == other.vmax;
  }
};
//! [Edge]

//! [Face]
/// A triangle (Listing 2.3): three vertices in counter-clockwise order and three neighbours;
/// F[k] is across the edge V[k] V[(k+1)%3] (nullptr on the boundary of the domain).
/// A "ghost" face has one vertex at infinity: it stands for the half-plane outside one hull
/// edge (2.2.2).
struct Face {  // Listing 2.3 missed this opening brace
  Face* F[3];
  Vertex* V[3];
  bool deleted;
  Face(Vertex* v0, Vertex* v1, Vertex* v2) {
    V[0] = v0;
    V[1] = v1;
    V[2] = v2;
    F[0] = F[1] = F[2] = nullptr;
    deleted = false;
  }
  Edge getEdge(int k) const { return Edge(V[k], V[(k + 1) % 3]); }
  /// True iff c is strictly inside the circumcircle (exact). For a ghost face (a, b, inf):
  /// iff c is strictly left of a->b, or on the open segment ab. Listing 2.3 declared it
  /// without a definition.
  bool inCircle(const Vertex* c) const;
  /// Index (0..2) of the vertex at infinity, or -1 for a finite face.
  int infiniteIndex() const {
    return V[0]->infinite ? 0 : (V[1]->infinite ? 1 : (V[2]->infinite ? 2 : -1));
  }
  bool isGhost() const { return infiniteIndex() >= 0; }
  /// The centroid (Listing 2.3 declared it without a definition). Finite faces only.
  Vertex centroid() const;
};
//! [Face]

/// Index of the edge of f shared with neighbour g (f->F[k] == g), or -1.
inline int neighbourIndex(const Face* f, const Face* g) {
  for (int k = 0; k < 3; ++k)
    if (f->F[k] == g) return k;
  return -1;
}

/// Sign of the orientation of three vertices (exact; robust predicate of 2.3.1).
int orientationTest(const Vertex* a, const Vertex* b, const Vertex* c);

/// The triangulation: it owns its vertices and faces (std::deque keeps addresses stable while
/// it grows; everything is freed with it). Faces are never freed one by one: the kernel
/// reuses the slots of cavity faces, as Listing 2.7 does.
class Triangulation {
 public:
  Triangulation();
  Triangulation(const Triangulation&) = delete;
  Triangulation& operator=(const Triangulation&) = delete;

  Vertex* addVertex(double x, double y, long id);
  Face* addFace(Vertex* a, Vertex* b, Vertex* c);
  Vertex* infiniteVertex() { return &infinite_; }

  std::deque<Vertex>& vertices() { return vertices_; }
  const std::deque<Vertex>& vertices() const { return vertices_; }
  std::deque<Face>& faces() { return faces_; }
  const std::deque<Face>& faces() const { return faces_; }

  /// Finite, live faces (the triangles a user sees, super-triangle faces included).
  std::vector<const Face*> finiteFaces() const;
  std::size_t numFiniteFaces() const;

 private:
  std::deque<Vertex> vertices_;
  std::deque<Face> faces_;
  Vertex infinite_;
};

}  // namespace dt
