// Solutions of the classroom exercises that need code of their own (exercises/exercises.txt,
// book/solutions.md). The other exercises' solutions live next to the code they extend.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "star.h"

namespace dt {

/// Exercise 2.2.2-1: the points outside a strictly convex counter-clockwise polygon that see
/// exactly its edge i (from poly[i] to poly[i+1]), that is lie strictly beyond that edge's line
/// and on or inside the lines of the other edges, form a convex region; returns true if that
/// region is bounded. Decided exactly. Throws std::invalid_argument if the polygon has fewer
/// than 3 corners, i is out of range, or a corner next to the edge is not strictly convex.
bool oneEdgeRegionBounded(const std::vector<Point2>& poly, std::size_t i);

/// Exercise 2.3.6-1: a point set S and a super-triangle factor (initSuperTriangles) for which
/// 2.2.1's flips (RecoveryRule::NotesOnly) are stuck: they make no flip and leave DT(S)
/// incomplete, while RecoveryRule::Full recovers it.
struct StuckRecovery {
  std::vector<double> xy;  ///< x0 y0 x1 y1 ...
  double factor;           ///< initSuperTriangles(T, box of xy, factor)
};
StuckRecovery stuckRecoveryExample();

/// Exercise 2.3.5-5: the Hilbert index of cell (i, j) of the 2^depth x 2^depth grid on H_depth,
/// the same number as hilbertIndex(i, j, depth) (Listing 2.8 started from red = +x, blue = +y;
/// 0 <= i, j < 2^depth, 1 <= depth <= 31), computed with integer operations only: a loop over
/// the levels and no branch (no if, switch, ?:, && or ||) and no call to the other Hilbert
/// functions.
std::uint64_t hilbertIndexBranchFree(std::uint32_t i, std::uint32_t j, int depth);

}  // namespace dt
