// Going further: a fast exact Bowyer-Watson kernel, for inputs of millions of points, where the
// listings' pointer-linked faces and std::map cost most of the time. Same algorithm and same result
// class as delaunayTrglHull (2.2.2, Listing 2.7): the exact DT(S), ghost faces for insertions
// outside the hull, duplicates merged. What changes is only how it is stored and evaluated:
// index-based triangles in contiguous arrays, no std::map, explicit stacks, inlined filtered
// predicates, a Hilbert order, and a walk that starts from the last cavity.
#pragma once

#include <vector>

#include "fast_types.h"

namespace dt {

/// DT(S) of the points xy = x0 y0 x1 y1 ..., exact for every input of finite doubles (the same
/// triangulation class as delaunayTrglHull; checkDelaunay validates it). Of several equal points
/// the smallest-numbered one is kept. Throws DegenerateInput (errors.h) if there are fewer
/// than three distinct points or all points are collinear, std::invalid_argument on non-finite
/// coordinates or more than 2^28 points.
FastResult fastDelaunay(const std::vector<double>& xy, const FastOptions& opt = {});

}  // namespace dt
