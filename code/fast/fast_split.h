// The parallel kernel's default design (fast_parallel.h, ParallelClaim::Parts): divide and merge.
// Each thread triangulates the points of one slab of x alone, with the one-thread core
// (fast_core.h: plain access, private marks, no atomics); one thread then merges the parts along
// the seams. Internal header: included by fast_parallel.cpp and the tests.
#pragma once

#include <vector>

#include "fast_parallel.h"

namespace dt {
namespace fast {

/// Whether the closed circumdisk of the triangle a b c lies strictly inside the open slab
/// lo < x < hi (lo may be -infinity, hi +infinity). Computed in floating point at the triangle's
/// own scale (a power of two, so extreme coordinates neither overflow nor underflow) with a
/// margin far above the rounding error; false whenever it cannot be sure (a sliver, a value
/// that is not finite). A "true" is therefore always right; a "false" may be too cautious.
bool diskInSlab(const double* a, const double* b, const double* c, double lo, double hi);

/// What splitAndMerge did, for ParallelStats.
struct SplitReport {
  bool merged = false;        ///< false: a part could not be triangulated alone, or the seam
                              ///< check failed; the caller then runs the sequential kernel
  std::size_t border = 0;     ///< points re-triangulated along the seams (the set B)
  double partsSeconds = 0;    ///< wall time of the parts (all threads)
  double busySeconds = 0;     ///< the threads' time in their parts, summed
  double mergeSeconds = 0;    ///< one thread: B, its triangulation and the flood
  double finishSeconds = 0;   ///< the output (fast::finish)
};

/// DT(S) of xy with `threads` parts (threads >= 2, the default insertion order; the input is
/// checked by the caller). Sets rep.merged to false and returns an empty result when it could
/// not merge (see SplitReport); otherwise a Delaunay triangulation of the points, the same
/// triangles as fastDelaunay when DT(S) is unique. Why the merge is right: book/parallel.md.
FastResult splitAndMerge(const std::vector<double>& xy, int threads, const FastOptions& opt,
                         bool v3, SplitReport& rep);

}  // namespace fast
}  // namespace dt
