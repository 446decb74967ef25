// The counting fact behind 2.3.3's remark that the face-based structure "can be extended in
// 3D": in a tetrahedral mesh every facet has one or two tetrahedra (a fixed-size record), while
// the tetrahedra around an edge form a cycle of varying length (an edge-based record must hold
// that cycle). A small mesh and the incidences that decide it; no 3D triangulation is built.
#pragma once

#include <array>
#include <map>
#include <utility>
#include <vector>

#include "tri.h"

namespace dt {

/// A tetrahedron by its four vertex numbers.
using Tet = std::array<int, 4>;

/// The Kuhn (Freudenthal) subdivision of a k x k x k grid of unit cubes: each cube cut into 6
/// tetrahedra along its main diagonal, one per order in which the path from its lowest to its
/// highest corner steps along x, y, z. Vertex (i, j, l) is numbered (i (k+1) + j) (k+1) + l.
/// Neighbouring cubes cut their shared square along the same diagonal, so the mesh is conforming.
std::vector<Tet> kuhnTetrahedra(int k);

/// The tetrahedra on each facet (a sorted vertex triple): 1 on the boundary, 2 inside.
std::map<Tri, int> tetsPerFacet(const std::vector<Tet>& tets);

/// The tetrahedra around one edge, in order: consecutive ones share a facet through the edge.
struct EdgeRing {
  std::vector<int> tets;  ///< indices into the mesh's list, in the order around the edge
  bool closed = false;    ///< a cycle (an interior edge) or a path (a boundary edge)
};

/// The ring of every edge (a sorted vertex pair). Throws std::logic_error if the tetrahedra
/// around an edge are not one cycle or one path (a facet with three tetrahedra, or two separate
/// fans: not a manifold).
std::map<std::pair<int, int>, EdgeRing> edgeRings(const std::vector<Tet>& tets);

}  // namespace dt
