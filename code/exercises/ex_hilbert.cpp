// Exercise 2.3.5-5 (book/sec2_3_5.md): the Hilbert index of Listing 2.8 without branches.
#include <stdexcept>

#include "exercises.h"

namespace dt {

//! [hilbertIndexBranchFree]
std::uint64_t hilbertIndexBranchFree(std::uint32_t i, std::uint32_t j, int depth) {
  // BEGIN SOLUTION 2.3.5-5
  // The frame (red, blue) is the root's, possibly swapped (sw) and possibly negated (ng). In
  // that frame the cell's bits (bx, by) say on which side of red and blue it lies; the side
  // bits give the quadrant (0 -- , 1 -+ , 2 ++ , 3 +-), and quadrants 0 and 3 swap the frame,
  // 3 also negates it.
  std::uint64_t key = 0;
  std::uint32_t sw = 0, ng = 0;
  for (int s = depth - 1; s >= 0; --s) {
    const std::uint32_t bx = (i >> s) & 1u, by = (j >> s) & 1u;
    const std::uint32_t d = sw & (bx ^ by);
    const std::uint32_t red = (bx ^ d) ^ ng, blue = (by ^ d) ^ ng;  // 1: the + side
    key = key << 2 | std::uint64_t(red << 1 | (red ^ blue));
    sw ^= blue ^ 1u;          // quadrants 0 and 3 (blue side -) swap
    ng ^= red & (blue ^ 1u);  // quadrant 3 also negates
  }
  return key;
  // END SOLUTION 2.3.5-5
}
//! [hilbertIndexBranchFree]

}  // namespace dt
