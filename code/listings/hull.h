// Section 2.2.2 (a TODO in the notes): what if p_{n+1} lies outside the current convex hull?
//
// The Delaunay insertion itself is insertVertex on a triangulation with ghost faces (see
// delaunayTrglHull in triangulate.h and Face::inCircle's ghost rule): a ghost face (a, b, inf)
// is in conflict with p iff p sees its hull edge. This file adds what the section needs around
// it: the hull read off the ghost faces, the hull edges visible from a point, closing a
// triangulated disk with ghost faces, and the plain (non-Delaunay) insertion outside the hull
// that "wraps" the visible chain of the hull around the new point, which gives the sweep
// triangulation used as a starting point for Lawson's flips (2.3.6).
#pragma once

#include <cstdint>
#include <vector>

#include "mesh.h"

namespace dt {

/// A hull edge a -> b (the hull is counter-clockwise) and its ghost face.
struct HullEdge {
  Vertex* a;
  Vertex* b;
  Face* ghost;
};

//! [ghostNext]
/// For a ghost face g, the ghost of the next hull edge (counter-clockwise). In g = (.., inf, ..)
/// with inf at index i, the hull edge is V[i+2] -> V[i+1]; the ghost across (inf, V[i+1]) is
/// the next one, the ghost across (V[i+2], inf) the previous one.
inline Face* ghostNext(const Face* g) { return g->F[g->infiniteIndex()]; }
inline Face* ghostPrev(const Face* g) { return g->F[(g->infiniteIndex() + 2) % 3]; }
//! [ghostNext]

/// Some live ghost face of T, or nullptr (a triangulation made with super-triangles has none).
Face* anyGhost(const Triangulation& T);

/// The hull edges of T in counter-clockwise order, read from the ring of ghost faces. Points
/// of S on a hull edge's line between its ends are hull vertices too (DT(S) uses every point).
/// Empty if T has no ghost face.
std::vector<HullEdge> hullEdges(const Triangulation& T);

/// The hull vertices, counter-clockwise (the a's of hullEdges).
std::vector<Vertex*> convexHull(const Triangulation& T);

//! [visibleHullEdges]
/// The hull edges a -> b that q sees: q strictly to their right, orient(a, b, q) < 0, exactly.
/// They form one contiguous chain of the hull (empty iff q is in the closed hull); returned in
/// counter-clockwise order. A point on an edge's supporting line does not see that edge.
std::vector<HullEdge> visibleHullEdges(const Triangulation& T, const Vertex* q);
//! [visibleHullEdges]

/// Gives the triangulated disk `faces` (finite, counter-clockwise, links already set by
/// computeAdjacencies) a ghost face across each boundary edge, linked to each other around the
/// hull. The disk must be convex for the result to be a valid hull triangulation.
void attachGhosts(Triangulation& T, const std::vector<Face*>& faces);

/// Plain insertion of q outside the hull (no Delaunay criterion): every ghost face whose edge
/// q sees becomes the finite triangle joining that edge to q (its vertex at infinity is
/// replaced by q, its links stay valid), and two new ghost faces close the hull at the ends
/// of the chain. `hint` is a ghost face where the search for a visible edge starts (any ghost
/// works; one incident to the last hull vertex inserted makes the sweep linear). Returns a
/// ghost face incident to q. Throws std::invalid_argument if q sees no hull edge.
Face* insertOutsideHull(Triangulation& T, Vertex* q, Face* hint);

/// Counters of sweepTriangulation.
struct SweepStats {
  std::uint64_t duplicates = 0;  ///< points equal to an earlier one (skipped)
};

/// A triangulation of S that is not Delaunay in general: sort S by (x, y); fan the first point
/// off the line of the leading collinear run to that run; then each next point lies strictly
/// outside the current hull (it is lexicographically largest) and is joined to the hull edges
/// it sees (insertOutsideHull). T must be empty of faces. Throws DegenerateInput if S has
/// fewer than 3 distinct points or is collinear.
void sweepTriangulation(Triangulation& T, const std::vector<Vertex*>& S,
                        SweepStats* stats = nullptr);

}  // namespace dt
