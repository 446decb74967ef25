// Exact validity checks (used by the tests, the chapter programs and the CLI).
#pragma once

#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include "tri.h"
#include "triangulate.h"

namespace dt {

/// Result of checkDelaunay: ok, or the first violation found, in words.
struct CheckReport {
  bool ok = true;
  std::string error;          ///< empty when ok
  std::size_t nVertices = 0;  ///< n: vertices used by the triangles
  std::size_t nHull = 0;      ///< n_h: vertices on the boundary (collinear ones included)
  std::size_t nFaces = 0;     ///< n_f
  std::size_t nEdges = 0;     ///< n_e
};

/// Checks, with exact predicates, that `tri` is the Delaunay triangulation of the points
/// it uses: every triangle counter-clockwise; every edge shared by at most two triangles with
/// opposite orientations; every interior edge locally Delaunay (the opposite vertex not strictly
/// inside the circumcircle); the boundary one simple closed convex polygon; Euler's counts
/// n_f = 2(n-1) - n_h and n_e = 3(n-1) - n_h (section 2.3.2). Together these make the triangles
/// tile the convex hull of their vertices and, by the Delaunay lemma, form a Delaunay
/// triangulation. If `mustUse` is given, every point i with mustUse[i] must be a vertex.
CheckReport checkDelaunay(const std::vector<double>& xy,
                          const std::vector<Tri>& tri,
                          const std::vector<char>* mustUse = nullptr);

/// checkDelaunay on the finite faces of a triangulation (super-triangle faces included).
/// Also checks that the face-to-face links F[k] are symmetric and match the shared edges.
CheckReport checkTriangulation(const Triangulation& T);

}  // namespace dt
