// Solutions of the classroom exercises that need code of their own (exercises/exercises.txt,
// book/solutions.md). The other exercises' solutions live next to the code they extend.
#pragma once

#include <cstddef>
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

}  // namespace dt
