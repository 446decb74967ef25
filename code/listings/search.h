// Listing 2.6: the walk that finds a seed of the Delaunay cavity (section 2.3.4).
#pragma once

#include <cstdint>
#include <vector>

#include "mesh.h"

namespace dt {

/// What lineSearch saw, besides the face it returns.
struct SearchInfo {
  std::uint64_t steps = 0;     ///< faces visited (tested with inCircle): N_search of Table 2.1
  Vertex* duplicate = nullptr; ///< set if v coincides with this vertex of the triangulation
  bool outside = false;        ///< set if v lies outside the triangulated domain
  /// Safety cap on the faces visited (the caller passes the number of faces: a visibility
  /// walk on a Delaunay triangulation never visits a face twice). Exceeding it throws.
  std::uint64_t maxSteps = ~std::uint64_t{0};
  /// If set, every face visited is appended, in walk order (the live figure of 2.5 draws it).
  std::vector<const Face*>* trace = nullptr;
};

/// Walks from face f towards v and returns the first face whose circumcircle strictly
/// contains v: a seed for delaunayCavity (Listing 2.6). At each face the walk follows the
/// line from the face's centroid to v, as the notes do, through an edge that v lies strictly
/// beyond; on a Delaunay triangulation such a "visibility" walk always terminates
/// (Edelsbrunner's acyclicity theorem). Returns nullptr if v duplicates a vertex
/// (info->duplicate) or lies outside a domain without ghost faces (info->outside).
Face* lineSearch(Face* f, Vertex* v, SearchInfo* info = nullptr);

}  // namespace dt
