// The last stage of the robust predicates (predicates_inline.h) and the oracle of the tests: the
// exact signs, with GMP integers, for every input of finite doubles. Beneath the predicate core:
// it includes nothing of the library.
#pragma once

namespace dt {

/// Exact sign of the orientation determinant for any finite doubles (GMP integers).
int orient2dExact(double ax, double ay, double bx, double by, double cx, double cy);
/// Exact sign of the incircle determinant for any finite doubles (GMP integers).
int incircleExact(double ax, double ay, double bx, double by, double cx, double cy, double dx,
                  double dy);

}  // namespace dt
