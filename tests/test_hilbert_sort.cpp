/// \file test_hilbert_sort.cpp The one Hilbert sort (code/hilbert.cpp): table keys and radix sort give the same orders as keys one level at a time and std::sort.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <utility>
#include <vector>

#include "hilbert.h"
#include "support.h"

namespace {

using XY = dttest::XY;

// The orders as 2.3.5 first defined them: keys of hilbertIndex, sorted by (key, index).
void sortByKeyRef(std::vector<std::size_t>& idx, std::size_t lo, std::size_t hi,
                  const std::vector<std::uint64_t>& keys) {
  std::vector<std::pair<std::uint64_t, std::size_t>> kv;
  for (std::size_t k = lo; k < hi; ++k) kv.emplace_back(keys[idx[k]], idx[k]);
  std::sort(kv.begin(), kv.end());
  for (std::size_t k = lo; k < hi; ++k) idx[k] = kv[k - lo].second;
}

std::vector<std::size_t> hilbertOrderRef(const XY& xy, int depth) {
  const std::vector<std::uint64_t> keys = dt::hilbertKeys(xy, depth);
  std::vector<std::size_t> idx(keys.size());
  std::iota(idx.begin(), idx.end(), std::size_t{0});
  sortByKeyRef(idx, 0, idx.size(), keys);
  return idx;
}

std::uint64_t splitmixRef(std::uint64_t& s) {
  std::uint64_t z = (s += 0x9e3779b97f4a7c15ULL);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

std::vector<std::size_t> brioOrderRef(const XY& xy, std::uint64_t seed, int depth) {
  const std::vector<std::uint64_t> keys = dt::hilbertKeys(xy, depth);
  const std::size_t n = keys.size();
  std::vector<std::size_t> idx(n);
  std::iota(idx.begin(), idx.end(), std::size_t{0});
  std::uint64_t state = seed;
  for (std::size_t i = n; i > 1; --i) std::swap(idx[i - 1], idx[std::size_t(splitmixRef(state) % i)]);
  std::size_t start = 0;
  for (std::size_t size : dt::brioRoundSizes(n)) {
    sortByKeyRef(idx, start, start + size, keys);
    start += size;
  }
  return idx;
}

// Random points, a grid (points on cell boundaries, exact ties at low depth) and duplicates.
XY mixedPoints(std::size_t n, unsigned seed) {
  XY p = dttest::uniformPoints(n, seed, -3, 5);
  const XY g = dttest::gridPoints(30, 30, 0.25, -2, -1);
  p.insert(p.end(), g.begin(), g.end());
  p.insert(p.end(), g.begin(), g.begin() + 200);  // 100 duplicated points
  return p;
}

}  // namespace

TEST_CASE("Hilbert sort (2.3.5) table keys equal the keys of hilbertIndex one level at a time") {
  for (int depth : {1, 2, 3, 4, 5, 7, 8, 13, 16, 18, 21, 31}) {
    const XY p = mixedPoints(3000, unsigned(depth));
    INFO("depth " << depth);
    CHECK(dt::hilbertKeysFast(p, depth) == dt::hilbertKeys(p, depth));
  }
  const XY p = dttest::uniformPoints(50000, 4);
  CHECK(dt::hilbertKeysFast(p) == dt::hilbertKeys(p, 0));
  CHECK(dt::hilbertKeysFast({1, 2, 1, 2}) == dt::hilbertKeys({1, 2, 1, 2}, 0));
}

TEST_CASE("Hilbert sort (2.3.5) by radix gives the order of std::sort on key then index") {
  // depth 31 packs 62 key bits: with the index they exceed 64 bits (the comparison-sort path).
  for (int depth : {0, 1, 3, 10, 20, 31}) {
    const XY p = mixedPoints(20000, 7 + unsigned(depth));
    INFO("depth " << depth);
    CHECK(dt::hilbertOrder(p, depth) == hilbertOrderRef(p, depth));
  }
  CHECK(dt::hilbertOrder({}).empty());
  CHECK(dt::hilbertOrder({2, 3}) == std::vector<std::size_t>{0});
}

TEST_CASE("Hilbert sort for BRIO in one sort gives the order of sorting each round by key then index") {
  for (int depth : {0, 2, 20, 31}) {
    const XY p = mixedPoints(20000, 17 + unsigned(depth));
    for (std::uint64_t seed : {1u, 5u}) {
      INFO("depth " << depth << " seed " << seed);
      CHECK(dt::brioOrder(p, seed, depth) == brioOrderRef(p, seed, depth));
    }
  }
}

TEST_CASE("Hilbert sort for BRIO by biased coins (the fast kernel's order) puts 3/4 of the points in the last round and each round in Hilbert order") {
  const std::size_t n = 40000;
  const XY p = mixedPoints(n - 1000, 31);
  const std::vector<std::size_t> o = dt::brioCoinOrder(p, 3);
  std::vector<std::size_t> s = o;
  std::sort(s.begin(), s.end());
  std::vector<std::size_t> id(n);
  std::iota(id.begin(), id.end(), std::size_t{0});
  REQUIRE(s == id);
  // Rounds are runs of increasing (key, index); a new round starts where that order drops.
  const std::vector<std::uint64_t> keys = dt::hilbertKeys(p, 0);
  std::vector<std::size_t> starts = {0};
  for (std::size_t k = 1; k < n; ++k)
    if (std::make_pair(keys[o[k]], o[k]) < std::make_pair(keys[o[k - 1]], o[k - 1])) starts.push_back(k);
  // 8 rounds, each one run; two consecutive runs merge when a round's last key happens to be
  // below the next round's first, which the first rounds (a few points each) may do.
  CHECK(starts.size() <= 8);
  CHECK(starts.size() >= 5);
  // The last round holds 3/4 of the points: binomial sd 0.0022, tolerance 0.01.
  CHECK(std::fabs(double(n - starts.back()) / double(n) - 0.75) < 0.01);
  CHECK(dt::brioCoinOrder(p, 3) == o);
  CHECK(dt::brioCoinOrder(p, 4) != o);
  CHECK(dt::brioCoinOrder(p, 3, 1) == dt::hilbertOrder(p));  // one round: the Hilbert sort
}
