// The stages of the robust predicates (predicates_inline.h) and the one record of which stage
// decided how many calls. Every counter of the library (predicateCounters(), FastStats) and of
// the tests is a StageCounts: an array indexed by Stage, so a new stage only adds an enumerator
// and a name here (and its code in predicates_inline.h).
#pragma once

#include <cstdint>

namespace dt {
namespace pred {

/// Which stage decided a robust predicate (the values of lastPredicateStage()), in the order
/// they run: each later stage is tried only when the earlier ones could not decide.
enum Stage : int {
  kFilter = 0,    ///< the floating-point filter
  kSmallInt = 1,  ///< the floating-point value itself, proved exact (small multiples of 2^k)
  kWide = 2,      ///< the same integers, up to 62 bits, evaluated in 128- and 256-bit integers
  kExtended = 3,  ///< the filter again, in floating point with a separate integer exponent
  kExact = 4,     ///< exact GMP integers (orient2dExact / incircleExact), always decides
  kStageCount = 5 ///< the number of stages
};

/// The stages' names, indexed by Stage (tables and test messages print them).
constexpr const char* kStageNames[kStageCount] = {"filter", "small multiples", "wide integers",
                                                  "extended exponent", "GMP"};

/// Calls of one predicate counted by the stage that decided them.
struct StageCounts {
  std::uint64_t n[kStageCount] = {};
  void add(int stage) { ++n[stage]; }
  std::uint64_t operator[](int stage) const { return n[stage]; }
  /// All calls counted.
  std::uint64_t calls() const {
    std::uint64_t s = 0;
    for (std::uint64_t v : n) s += v;
    return s;
  }
  /// The calls the filter could not decide (some exact stage did).
  std::uint64_t beyondFilter() const { return calls() - n[kFilter]; }
  StageCounts& operator+=(const StageCounts& o) {
    for (int s = 0; s < kStageCount; ++s) n[s] += o.n[s];
    return *this;
  }
  StageCounts operator-(const StageCounts& o) const {
    StageCounts r;
    for (int s = 0; s < kStageCount; ++s) r.n[s] = n[s] - o.n[s];
    return r;
  }
};

}  // namespace pred
}  // namespace dt
