// The error every triangulator of the library throws on input that has no triangulation: the
// listings, the fast kernel and the entry point share it, so it lives below all of them.
// (Errors of one room stay in that room: InputError in io.h, OutputRefused in output_files.h,
// UnsupportedInput in delaunay.h, ThreadStartError in parallel_for.h.)
#pragma once

#include <stdexcept>

namespace dt {

/// Input that has no Delaunay triangulation (fewer than three distinct points, or all points
/// collinear), or that the chosen method cannot represent.
struct DegenerateInput : std::runtime_error {
  using std::runtime_error::runtime_error;
};

}  // namespace dt
