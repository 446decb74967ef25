// Exercise 2.2.2-1 (book/sec2_2_2.md): where the points that see exactly one hull edge lie.
#include <gmp.h>

#include <stdexcept>

#include "exercises.h"
#include "predicates.h"

namespace dt {

// BEGIN SOLUTION 2.2.2-1 (remove)
namespace {

// The exact sign of the cross product (b - a) x (d - c): the differences of doubles are not
// doubles, so the products are formed in rationals.
int crossSign(Point2 a, Point2 b, Point2 c, Point2 d) {
  mpq_t v[8], l, r;
  const double in[8] = {b.x, a.x, d.y, c.y, b.y, a.y, d.x, c.x};
  for (int k = 0; k < 8; ++k) {
    mpq_init(v[k]);
    mpq_set_d(v[k], in[k]);
  }
  mpq_inits(l, r, nullptr);
  mpq_sub(v[0], v[0], v[1]);  // bx - ax
  mpq_sub(v[2], v[2], v[3]);  // dy - cy
  mpq_sub(v[4], v[4], v[5]);  // by - ay
  mpq_sub(v[6], v[6], v[7]);  // dx - cx
  mpq_mul(l, v[0], v[2]);
  mpq_mul(r, v[4], v[6]);
  const int s = mpq_cmp(l, r);
  for (int k = 0; k < 8; ++k) mpq_clear(v[k]);
  mpq_clears(l, r, nullptr);
  return (s > 0) - (s < 0);
}

}  // namespace
// END SOLUTION 2.2.2-1

//! [oneEdgeRegionBounded]
bool oneEdgeRegionBounded(const std::vector<Point2>& poly, std::size_t i) {
  const std::size_t m = poly.size();
  if (m < 3) throw std::invalid_argument("oneEdgeRegionBounded: fewer than 3 corners");
  if (i >= m) throw std::invalid_argument("oneEdgeRegionBounded: no edge with that index");
  const Point2 a = poly[(i + m - 1) % m], b = poly[i], c = poly[(i + 1) % m],
               d = poly[(i + 2) % m];
  if (orient2d(a.x, a.y, b.x, b.y, c.x, c.y) <= 0 || orient2d(b.x, b.y, c.x, c.y, d.x, d.y) <= 0)
    throw std::invalid_argument("oneEdgeRegionBounded: a corner of the edge is not strictly convex");
  // BEGIN SOLUTION 2.2.2-1
  // The region is the open half-plane beyond bc cut by the closed inner half-planes of ab and
  // cd. Its directions to infinity t satisfy (c - b) x t < 0, (b - a) x t >= 0 and
  // (d - c) x t >= 0; there is one (t = b - a) exactly when the lines of ab and cd do not meet
  // beyond bc, that is when cd does not turn left from ab: (b - a) x (d - c) <= 0.
  return crossSign(a, b, c, d) > 0;
  // END SOLUTION 2.2.2-1
}
//! [oneEdgeRegionBounded]

}  // namespace dt
