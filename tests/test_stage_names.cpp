/// \file test_stage_names.cpp Stage accounting by name: for each stage of the robust predicates, one pinned input that only that stage decides, counted once under that stage's index and name and under no other, for orient2d and incircle apart.
#include <doctest/doctest.h>

#include <string>

#include "predicates.h"

namespace {

// Consecutive Fibonacci numbers: F58^2 - F57 F59 = 1, a determinant of 1 from 40-bit integers,
// below the filter's bound and beyond the small multiples: the wide-integer stage decides.
constexpr double F57 = 365435296162.0, F58 = 591286729879.0, F59 = 956722026041.0;

struct Pinned {
  int stage;
  const char* name;  // what the tables print for it
  double orient[6];
  double incircle[8];
};

const Pinned kPinned[] = {
    {dt::pred::kFilter, "filter", {0, 0, 1, 0, 0, 1}, {0, 0, 1, 0, 0, 1, 0.1, 0.1}},
    {dt::pred::kSmallInt, "small multiples", {0, 0, 1, 1, 2, 2}, {0, 0, 1, 0, 1, 1, 0, 1}},
    {dt::pred::kWide, "wide integers", {0, 0, F58, F59, F57, F58}, {0, 0, F58, F59, F57, F58, F58 + F57, F59 + F58}},
    {dt::pred::kExtended, "extended exponent", {0x1p1000, 0, 0, 0x1p1000, -0x1p1000, 3},
     {0x1p1000, 0, 0, 0x1p1000, -0x1p1000, 3, 0x1p-1000, 0x1p-1070}},
    {dt::pred::kExact, "GMP", {0.1, 0.3, 0.7, 0.9, 1e-17, 0.2}, {0.1, 0.1, 0.7, 0.1, 0.7, 0.7, 0.1, 0.7}},
};

}  // namespace

TEST_CASE("stage names the predicate stages are counted under their own name: one pinned input per stage for orient2d and incircle") {
  REQUIRE(sizeof(kPinned) / sizeof(kPinned[0]) == std::size_t(dt::pred::kStageCount));
  for (const Pinned& p : kPinned) {
    CAPTURE(p.name);
    CHECK(std::string(dt::pred::kStageNames[p.stage]) == p.name);
    dt::predicateCounters().reset();
    const double* o = p.orient;
    dt::orient2d(o[0], o[1], o[2], o[3], o[4], o[5]);
    CHECK(dt::lastPredicateStage() == p.stage);
    const double* c = p.incircle;
    dt::incircle(c[0], c[1], c[2], c[3], c[4], c[5], c[6], c[7]);
    CHECK(dt::lastPredicateStage() == p.stage);
    const dt::PredicateCounters k = dt::predicateCounters();
    for (int s = 0; s < dt::pred::kStageCount; ++s) {
      CAPTURE(dt::pred::kStageNames[s]);
      CHECK(k.orient[s] == (s == p.stage ? 1u : 0u));
      CHECK(k.incircle[s] == (s == p.stage ? 1u : 0u));
    }
  }
}
