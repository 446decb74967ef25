// Geometric predicates of section 2.3.1: orientation and incircle.
//
// Four families, from fastest to safest, so that section 2.3.1 can show each one at work (the
// robust one here, the exact one in predicates_exact.h, the others in predicates_demo.h):
//   - naive:    the formula of the notes evaluated in double precision (wrong near degeneracy);
//   - notes:    the notes' static filter (1e-15, 1e-11) with a 200-bit MPFR fallback;
//   - exact:    the exact sign, computed with GMP integers (the oracle);
//   - robust:   a floating-point evaluation behind a provably safe error bound, falling back
//               to the exact sign. This is the one the kernel uses.
//
// Conventions. orient2d(a,b,c) > 0 iff a, b, c turn counter-clockwise; the value computed is the
// notes' (xa-xc)(yb-yc) - (ya-yc)(xb-xc), pivoting on c. incircle(a,b,c,d) > 0 iff d lies
// strictly inside the circle through a, b, c when a, b, c are counter-clockwise (the sign flips
// for a clockwise triangle); it pivots on d.
#pragma once

#include <cstdint>

#include "predicate_stages.h"
#include "predicates_demo.h"
#include "predicates_exact.h"

namespace dt {

/// Counters of the robust predicates' calls, by the stage that decided them; the chapter
/// programs read them (share of exact fallbacks, share of time spent in the orientation test).
/// Not thread-safe: one triangulation at a time.
struct PredicateCounters {
  pred::StageCounts orient;    ///< calls of orient2d (robust)
  pred::StageCounts incircle;  ///< calls of incircle (robust)
  void reset() { *this = PredicateCounters{}; }
};
PredicateCounters& predicateCounters();

/// Robust orientation (2.3.1): double evaluation + safe error bound, exact fallback (the core
/// is dt::pred::orient2d in predicates_inline.h; this adds the counters).
/// The sign is exact for every input of finite doubles.
int orient2d(double ax, double ay, double bx, double by, double cx, double cy);
/// Robust incircle (2.3.1): double evaluation + safe error bound, exact fallback.
int incircle(double ax, double ay, double bx, double by, double cx, double cy, double dx,
             double dy);

/// Stage that decided the last robust call on this thread (for tests and the 2.3.1 program): a
/// dt::pred::Stage (predicate_stages.h; predicates_inline.h defines and proves the stages).
int lastPredicateStage();

}  // namespace dt
