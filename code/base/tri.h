// The triangle of the index-based kernels and of every plain mesh: three vertex numbers,
// counter-clockwise. Named once here, so that every header that passes triangles around says
// the same thing.
#pragma once

#include <array>

namespace dt {

/// A triangle as three vertex indices, counter-clockwise.
using Tri = std::array<int, 3>;

}  // namespace dt
