// Exercise 2.3.6-1 (book/sec2_3_6.md): where 2.2.1's flips alone are stuck.
#include <stdexcept>

#include "exercises.h"

namespace dt {

//! [stuckRecoveryExample]
StuckRecovery stuckRecoveryExample() {
  // BEGIN SOLUTION 2.3.6-1
  // A flat triangle u v y: its circumcircle has radius about 1/(8 d) = 12.5 and swallows the
  // super vertices of a square twice as wide as the box, so DT(S0 ∪ S) joins y to two super
  // vertices s1, s2 across the hull edge u v: the triangles (u, s1, y), (s1, s2, y),
  // (v, s2, y) of the page. Each edge from y to a super vertex has a super vertex opposite,
  // which 2.2.1's rule never flips.
  const double d = 0.01;
  return StuckRecovery{{0, 0, 1, 0, 0.5, -d}, 2.0};
  // END SOLUTION 2.3.6-1
}
//! [stuckRecoveryExample]

}  // namespace dt
