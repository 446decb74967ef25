// Which stage of the predicate core (code/predicates_inline.h) decided each call: a tally that
// the exactness tests print and check, so that an agreement with the oracle says something
// about every stage, not just the filter.
//
// The stages are read generically: the tally covers 0 .. kStageCount-1, where kStageCount is
// the enumerator of that name at the end of dt::pred::Stage if the core defines it, else 4
// (kFilter, kExact, kSmallInt, kWide). A new stage registers by taking the next value and
// moving kStageCount after it; until it does, the tests fail on a stage number they do not know.
#pragma once

#include <cstdint>
#include <sstream>
#include <string>
#include <type_traits>
#include <vector>

#include "predicates_inline.h"

namespace dtoracle {

template <class E, class = void>
struct StageCount : std::integral_constant<int, 4> {};
template <class E>
struct StageCount<E, std::void_t<decltype(E::kStageCount)>>
    : std::integral_constant<int, int(E::kStageCount)> {};

constexpr int kStages = StageCount<dt::pred::Stage>::value;

inline std::string stageName(int s) {
  switch (s) {
    case dt::pred::kFilter: return "filter";
    case dt::pred::kExact: return "GMP";
    case dt::pred::kSmallInt: return "small multiples";
    case dt::pred::kWide: return "wide integers";
    case dt::pred::kExtended: return "extended exponent";
    default: return "stage " + std::to_string(s);
  }
}

struct StageTally {
  std::vector<std::uint64_t> n = std::vector<std::uint64_t>(kStages + 1, 0);  // last: unknown
  void add(int stage) { ++n[stage >= 0 && stage < kStages ? stage : kStages]; }
  std::uint64_t unknown() const { return n[kStages]; }
  std::string report() const {
    std::ostringstream o;
    for (int s = 0; s < kStages; ++s) o << (s ? ", " : "") << stageName(s) << " " << n[s];
    if (unknown()) o << ", unregistered stages " << unknown();
    return o.str();
  }
};

}  // namespace dtoracle
