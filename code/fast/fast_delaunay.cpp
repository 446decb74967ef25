#include "fast_delaunay.h"

#include <stdexcept>

#include "fast_core.h"
#include "hilbert.h"

namespace dt {

std::vector<std::uint64_t> fastHilbertKeys(const std::vector<double>& xy, int depth) {
  if (depth == 0) depth = hilbertAutoDepth(xy.size() / 2);
  if (depth < 1 || depth > 31) throw std::invalid_argument("fastHilbertKeys: depth out of 1..31");
  return hilbertKeysFast(xy, depth);
}

//! [fastDelaunay]
FastResult fastDelaunay(const std::vector<double>& xy, const FastOptions& opt) {
  return fast::oneThread<fast::InlinePredicates>(xy, opt, {fast::hasV3(), true});
}
//! [fastDelaunay]

}  // namespace dt
