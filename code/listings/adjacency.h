// Listing 2.4: connecting the triangles of a cavity (section 2.3.4).
#pragma once

#include <cstdint>
#include <vector>

#include "mesh.h"

namespace dt {

/// Sets F[k] of every pair of faces in `cavity` that share an edge (Listing 2.4, 2.3.4).
/// O(N log N) for N faces: one std::map search and insert or erase per edge. An edge seen
/// once is left as it was (it borders a face outside the list). Throws std::logic_error if
/// two faces walk an edge in the same direction. A list that is not a manifold in another way
/// is not detected: the map forgets an edge once two faces are linked across it (as Listing
/// 2.4 does), so a third face on that edge is taken for one on the boundary and keeps its link
/// (exercise 2.3.4-1's computeAdjacenciesSorted rejects it).
void computeAdjacencies(std::vector<Face*>& cavity);

/// The work of one computeAdjacencies call on its std::map, counted by the map itself: the
/// measure of 2.3.4's "one search/insert on a std::map per triangle" and of its O(N log N).
struct AdjacencyCounts {
  std::uint64_t searches = 0;     ///< map.find calls (one per edge of every face)
  std::uint64_t inserts = 0;      ///< map.insert calls (an edge seen for the first time)
  std::uint64_t erases = 0;       ///< map.erase calls (an edge met from its second face)
  std::uint64_t comparisons = 0;  ///< key comparisons made by all of them
  std::uint64_t largest = 0;      ///< the most edges the map held at once
};

/// The same, adding the map's operations to `counts`.
void computeAdjacencies(std::vector<Face*>& cavity, AdjacencyCounts& counts);

/// The same, adding to `comparisons` the number of edge comparisons its std::map made (the
/// measure of the O(N log N) claim of 2.3.4; the tests count them).
void computeAdjacencies(std::vector<Face*>& cavity, std::uint64_t& comparisons);

}  // namespace dt
