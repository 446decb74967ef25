// Counting a triangulation (sections 2.3.2-2.3.4): vertex degrees and Euler's counts, the
// pointer counts of the data structures of 2.3.3, the vertex star of the face-based structure,
// and a second way of connecting faces. Solutions of the exercises of those sections.
#pragma once

#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include "mesh.h"
#include "tri.h"

namespace dt {

//! [MeshCounts]
/// The counts of section 2.3.2 measured on a list of triangles: n, n_h, n_f, n_e, and for each
/// vertex its number of adjacent triangles (vf) and edges (ve). Vertices that no triangle uses
/// are not counted. n_h is the number of vertices on boundary edges (edges with one triangle).
struct MeshCounts {
  long n = 0, nh = 0, nf = 0, ne = 0;
  std::vector<int> vf, ve;  ///< per point index (0 for unused points)
  long sumVF = 0, sumVE = 0;
  double meanVF() const { return n ? double(sumVF) / double(n) : 0; }  ///< measured n_vf
  double meanVE() const { return n ? double(sumVE) / double(n) : 0; }  ///< measured n_ve
  long eulerNF() const { return 2 * (n - 1) - nh; }                    ///< 2(n-1) - n_h
  long eulerNE() const { return 3 * (n - 1) - nh; }                    ///< 3(n-1) - n_h
  double eq22() const { return 6.0 - double(3 * nh + 6) / double(n); }  ///< eq. (2.2)
  double eq23() const { return 6.0 - double(2 * nh + 6) / double(n); }  ///< eq. (2.3)
};
//! [MeshCounts]

/// Counts of the triangles `tri` on `np` points (indices 0..np-1). Edges are found by sorting
/// the 3 n_f directed edges, O(n_f log n_f); no geometry is used.
MeshCounts meshCounts(std::size_t np, const std::vector<Tri>& tri);

/// Exercise 2.3.2-1: the counts {n, n_h, n_f, n_e} of the Delaunay triangulation of an
/// nx x ny grid (nx, ny >= 2), in closed form (book/solutions.md derives it).
std::array<long, 4> gridCounts(long nx, long ny);

/// Exercise 2.3.2-2: the index of a vertex with at most 5 edges, or -1 if every used vertex
/// has 6 edges or more.
int lowDegreeVertex(const MeshCounts& c);

//! [pointerCounts]
/// The data structures of section 2.3.3 and their pointer counts N_p, one pointer per
/// explicit entity plus one per stored adjacency. `exact` uses n_f, n_e, n_vf, n_ve of a
/// triangulation with n vertices and n_h on the hull; otherwise the notes' asymptotic values
/// n_e = 3n, n_f = 2n, n_ve = n_vf = 6, n_ef = 2.
struct PointerCount {
  std::string name;
  double perVertex;  ///< N_p / n
};
std::vector<PointerCount> pointerCounts(double n, double nh, bool exact);
//! [pointerCounts]

/// Exercise 2.3.3-1: N_p of a half-edge structure (not in the notes), counted as
/// pointerCounts counts the other structures (`exact` likewise).
double halfEdgePointers(double n, double nh, bool exact);

//! [vertexStar]
/// Exercise 2.3.3-2: the star of v in the face-based structure, starting from one face f of v.
/// Returns the finite faces of v counter-clockwise,
/// consecutive ones sharing an edge; around a hull vertex the fan starts at the hull (after the
/// ghost faces, or at an F == nullptr that the turn then completes clockwise).
/// Throws std::logic_error if v is not a vertex of f, or if the turn exceeds `maxFaces` faces
/// (a corrupted mesh), instead of spinning forever.
std::vector<Face*> vertexStar(Face* f, const Vertex* v, std::size_t maxFaces = 1u << 30);
//! [vertexStar]

/// Exercise 2.3.4-1: computeAdjacencies without std::map, O(N log N), with its contract: sets
/// F[k] of every pair of faces of the list that share an edge (F[k] is the face across the edge
/// V[k] V[k+1]); a link across an edge that only one face of the list has is left as it was (it
/// borders a face outside the list). Throws std::logic_error if an edge is shared by more than
/// two faces or two faces walk it in the same direction.
void computeAdjacenciesSorted(std::vector<Face*>& faces);

/// Exercise 2.3.4-2 (backward analysis of N_cavity): for T = DT(S0 u S) built on the
/// super-triangles, returns {the mean over the real vertices v (id >= 0) of the size of the
/// cavity v would have if it were the last point inserted, computed from T alone without
/// removing or inserting a point; D, the number of triangle corners at the four super-vertices}.
std::array<double, 2> backwardCavityMean(const Triangulation& T);

}  // namespace dt
