// Star-shaped polygons and the Delaunay cavity (sections 2.1.1 and 2.1.2): the kernel of a
// polygon by half-plane intersection, exact visibility, and an exact check of Proposition 2.1.1
// and Property 2.1.1 on a cavity.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "mesh.h"

namespace dt {

/// A point of the plane (for polygons that are not part of a triangulation).
struct Point2 {
  double x, y;
};

//! [polygonKernel]
/// ker(Σ) of a counter-clockwise simple polygon Σ (2.1.1): the intersection of the closed
/// half-planes to the left of its oriented edges, computed by clipping the bounding box with
/// each half-plane in turn (O(m^2) for m corners). Returns the corners of the convex kernel,
/// counter-clockwise, or an empty vector if the kernel is empty or has no interior. The
/// clipping decisions are exact; the new corners are rounded intersections, good for drawing.
std::vector<Point2> polygonKernel(const std::vector<Point2>& poly);
//! [polygonKernel]

/// Exact: x is strictly left of every oriented edge of the counter-clockwise polygon, i.e. in
/// the interior of the intersection of the half-planes.
bool inOpenKernel(const std::vector<Point2>& poly, Point2 x);

/// Exact: x lies in the interior of the simple polygon (not on its boundary).
bool insidePolygon(const std::vector<Point2>& poly, Point2 x);

/// Exact visibility (the notes' definition of ker, 2.1.1): x is inside the polygon and the
/// open segment from x to corner j meets no edge of the polygon.
bool seesCorner(const std::vector<Point2>& poly, Point2 x, std::size_t j);

/// Exact: the closed segments ab and cd have a common point.
bool segmentsIntersect(Point2 a, Point2 b, Point2 c, Point2 d);

/// What checkCavity found about a set of faces and a point p.
struct CavityReport {
  bool ok = true;
  std::string error;              ///< first violated property, in words
  std::size_t faces = 0;          ///< |C|
  std::size_t boundaryEdges = 0;  ///< |bnd|: edges of exactly one face of C
  std::size_t components = 0;     ///< edge-connected components of C
  std::size_t innerVertices = 0;  ///< vertices of C not on its boundary (Property 2.1.1: 0)
  long winding = 0;               ///< winding number of the boundary around p
};

//! [checkCavity]
/// Checks exactly that the finite faces C form what Proposition 2.1.1 and Property 2.1.1
/// promise for the point p: C is non-empty; p is strictly inside every circumcircle; C is
/// edge-connected; its boundary edges form one closed cycle through distinct vertices; p is
/// strictly left of every boundary edge and the boundary winds once around p (so the union of
/// C is a polygon, star-shaped, with p in the interior of its kernel); no vertex of C is off
/// the boundary; and |bnd| = |C| + 2.
CavityReport checkCavity(const std::vector<const Face*>& C, const Vertex* p);
//! [checkCavity]

/// The cavity by definition (2.1.2): every live face of T whose open circumdisk contains p,
/// found by testing every face (no search, no connectivity assumed).
std::vector<Face*> conflictFaces(Triangulation& T, const Vertex* p);

}  // namespace dt
