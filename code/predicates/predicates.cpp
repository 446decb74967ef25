#include "predicates.h"

#include "predicates_inline.h"

namespace dt {

namespace {
PredicateCounters g_counters;
thread_local int g_lastStage = 0;
}  // namespace

PredicateCounters& predicateCounters() { return g_counters; }
int lastPredicateStage() { return g_lastStage; }

// ---------------------------------------------------------------------------------------------
// Robust predicates: the core of predicates_inline.h (filter with a proved bound, the
// small-multiple, wide and extended-exponent stages, GMP), plus the counters and the last
// stage for the chapter programs.
int orient2d(double ax, double ay, double bx, double by, double cx, double cy) {
  int stage = pred::kFilter;
  const int s = pred::orient2d(ax, ay, bx, by, cx, cy, stage);
  g_lastStage = stage;
  g_counters.orient.add(stage);
  return s;
}

int incircle(double ax, double ay, double bx, double by, double cx, double cy, double dx,
             double dy) {
  int stage = pred::kFilter;
  const int s = pred::incircle(ax, ay, bx, by, cx, cy, dx, dy, stage);
  g_lastStage = stage;
  g_counters.incircle.add(stage);
  return s;
}

}  // namespace dt
