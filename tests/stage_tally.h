// Which stage of the predicate core (code/predicates/predicates_inline.h) decided each call: a tally that
// the exactness tests print and check, so that an agreement with the oracle says something
// about every stage, not just the filter. It reads the one record of stages
// (code/predicates/predicate_stages.h): the enum in run order, its names, kStageCount. A stage number
// outside the enum is counted apart, and the tests fail on it.
#pragma once

#include <cstdint>
#include <sstream>
#include <string>
#include <vector>

#include "predicate_stages.h"

namespace dtoracle {

constexpr int kStages = dt::pred::kStageCount;

inline std::string stageName(int s) {
  return s >= 0 && s < kStages ? dt::pred::kStageNames[s] : "stage " + std::to_string(s);
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
