// Listing 2.7 and Algorithm 1: the incremental Bowyer-Watson triangulation (sections 2.2, 2.3.4),
// with the two initial triangulations: super-triangles (2.2.1) or a first triangle with ghost
// faces, so that points outside the current hull can be inserted (2.2.2).
#pragma once

#include <array>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "errors.h"
#include "mesh.h"
#include "tri.h"

namespace dt {

/// Where lineSearch starts for each new point (2.3.4).
enum class StartRule {
  FirstFace,  ///< the first face of the list, T[0], as Listing 2.7 does (Table 2.1)
  LastCavity  ///< a face of the previous ball: the rule the notes describe for Table 2.2
};

/// Counters for Tables 2.1 and 2.2.
struct InsertionStats {
  std::uint64_t insertions = 0;   ///< points inserted (duplicates excluded)
  std::uint64_t searchSteps = 0;  ///< faces visited by lineSearch, summed
  std::uint64_t cavityFaces = 0;  ///< faces of the Delaunay cavities, summed
  std::uint64_t duplicates = 0;   ///< points skipped because they coincide with a vertex
  double meanSearch() const { return insertions ? double(searchSteps) / insertions : 0; }
  double meanCavity() const { return insertions ? double(cavityFaces) / insertions : 0; }
};

/// Reusable buffers of one insertion (so that a triangulation of 10^6 points does not allocate
/// three vectors per point).
struct InsertionScratch {
  std::vector<Face*> cavity, otherSide;
  std::vector<Edge> bnd;
};

/// One step of Listing 2.7: inserts p into the Delaunay triangulation T, starting the walk at
/// `start`. Returns a face of the new ball (the next start under StartRule::LastCavity), or
/// nullptr if p duplicates a vertex (then p is not inserted, and stats.duplicates grows).
/// Throws std::out_of_range if p lies outside a domain without ghost faces.
Face* insertVertex(Triangulation& T, Face* start, Vertex* p, InsertionStats& stats,
                   InsertionScratch& scratch);

/// Algorithm 1's DT_0: two super-triangles p_{-1} p_{-2} p_{-3} and p_{-2} p_{-1} p_{-4} forming
/// a square centred on the box [xmin,xmax] x [ymin,ymax], `factor` times as wide (2.2.1).
/// Throws DegenerateInput if the corners are not finite or do not strictly enclose the box.
void initSuperTriangles(Triangulation& T, double xmin, double ymin, double xmax, double ymax,
                        double factor = 10.0);

/// Listing 2.7: inserts the points S into T one after the other (T already holds DT_0).
void delaunayTrgl(Triangulation& T, const std::vector<Vertex*>& S, StartRule rule,
                  InsertionStats* stats = nullptr);

/// DT(S) without super-triangles (2.2.2): starts from the first non-degenerate triangle of S
/// (in the given order), surrounded by three ghost faces, and inserts the other points; a
/// point outside the current hull conflicts with the ghost faces of the hull edges it sees.
/// Throws DegenerateInput if S has fewer than 3 distinct points or is collinear.
void delaunayTrglHull(Triangulation& T, const std::vector<Vertex*>& S, StartRule rule,
                      InsertionStats* stats = nullptr);

/// Plain copy of a triangulation: coordinates and counter-clockwise index triples.
struct PlainMesh {
  std::vector<double> xy;               ///< x0 y0 x1 y1 ...
  std::vector<long> ids;                ///< Vertex::id of each point
  std::vector<Tri> tri;  ///< finite faces
};

/// The finite faces of T, optionally without the faces touching a super-vertex (id < 0).
/// Vertices are renumbered 0..n-1 in the order of T.vertices(), only those used by a face.
PlainMesh extractMesh(const Triangulation& T, bool dropSuperFaces);

}  // namespace dt
