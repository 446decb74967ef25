#include "fast_delaunay.h"

#include "fast_core.h"

namespace dt {

//! [fastDelaunay]
FastResult fastDelaunay(const std::vector<double>& xy, const FastOptions& opt) {
  return fast::oneThread<fast::InlinePredicates>(xy, opt, {fast::hasV3(), true});
}
//! [fastDelaunay]

}  // namespace dt
