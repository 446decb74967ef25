/// \file test_parallel.cpp Tests of the parallel kernel (code/fast/fast_parallel.h, the going-further page on both cores): the exact DT(S), the sequential kernel's triangulation in general position, a Delaunay triangulation on degenerate input.
#include <doctest/doctest.h>
#include <sched.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <map>
#include <set>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "check.h"
#include "degenerate.h"
#include "fast_delaunay.h"
#include "fast_parallel.h"
#include "fast_split.h"
#include "generators.h"
#include "hilbert.h"
#include "predicates.h"
#include "support.h"
#include "triangulate.h"

namespace {

using Tris = std::vector<std::array<int, 3>>;

Tris canonical(Tris t) {
  for (auto& f : t) std::rotate(f.begin(), std::min_element(f.begin(), f.end()), f.end());
  std::sort(t.begin(), t.end());
  return t;
}

constexpr dt::ParallelMode kAlways = dt::ParallelMode::Always;

// Runs the concurrent rounds (whatever the cost model would choose), validates the result
// exactly (every point not reported as a duplicate must be a vertex), and returns it.
dt::FastResult parallelChecked(const dttest::XY& p, int threads, int minPiece,
                               dt::ParallelStats* ps = nullptr,
                               dt::ParallelClaim claim = dt::ParallelClaim::Slabs) {
  dt::FastResult r = dt::fastDelaunayParallel(p, threads, {}, ps, minPiece, claim, kAlways);
  std::vector<char> must(p.size() / 2, 1);
  for (const auto& d : r.duplicates) must[std::size_t(d.first)] = 0;
  const dt::CheckReport c = dt::checkDelaunay(p, r.tri, &must);
  INFO(c.error);
  CHECK(c.ok);
  return r;
}

}  // namespace

TEST_CASE("parallel the same triangulation as the sequential kernel in general position") {
  // Small pieces and more threads than cores make the threads meet (and defer) often. The three
  // designs: parts merged along their seams (the default; it never defers), and the shared
  // triangulation's slabs and locks.
  for (dt::ParallelClaim claim :
       {dt::ParallelClaim::Parts, dt::ParallelClaim::Slabs, dt::ParallelClaim::Locks}) {
    std::uint64_t deferred = 0, concurrent = 0;
    for (std::size_t n : {3000u, 40000u, 200000u}) {
      const dttest::XY p = dttest::uniformPoints(n, 7 + n);
      const Tris seq = canonical(dt::fastDelaunay(p).tri);
      for (int threads : {2, 3, 8})
        for (int minPiece : {4, 2048}) {
          CAPTURE(n);
          CAPTURE(threads);
          CAPTURE(minPiece);
          CAPTURE(int(claim));
          dt::ParallelStats ps;
          const dt::FastResult r = parallelChecked(p, threads, minPiece, &ps, claim);
          CHECK(ps.threadsUsed == threads);
          CHECK(ps.reason == dt::ParallelReason::Concurrent);
          CHECK(r.stats.insertions == n);
          CHECK(canonical(r.tri) == seq);
          deferred += ps.deferred;
          concurrent += ps.parallelPoints;
        }
    }
    CHECK(concurrent > 0);
    // The slabs defer the insertions whose cavity leaves the thread's slab: with pieces of 4
    // points and 8 threads many do, but far from all (a claim that refused everything would
    // still give the right triangles, one thread doing all the work).
    CHECK(deferred < concurrent / 4);
    if (claim == dt::ParallelClaim::Parts) CHECK(deferred == 0);
    MESSAGE((claim == dt::ParallelClaim::Parts ? "parts"
             : claim == dt::ParallelClaim::Slabs ? "slabs" : "locks")
            << ": insertions deferred " << deferred << " of " << concurrent);
  }
}

TEST_CASE("parallel a Delaunay triangulation on every degenerate family") {
  // Several Delaunay triangulations exist: the result must be one of them (checked exactly),
  // with the sequential kernel's number of triangles and the same merged duplicates.
  for (const dtdeg::Family& f : dtdeg::families()) {
    CAPTURE(f.name);
    const dt::FastResult seq = dt::fastDelaunay(f.points);
    for (int threads : {2, 4})
      for (dt::ParallelClaim claim : {dt::ParallelClaim::Slabs, dt::ParallelClaim::Locks}) {
        const dt::FastResult r = parallelChecked(f.points, threads, 8, nullptr, claim);
        CHECK(r.tri.size() == seq.tri.size());
        CHECK(r.duplicates == seq.duplicates);
      }
  }
}

namespace {

// Whether DT(S) is unique, from one Delaunay triangulation of S: no edge between two triangles
// has the fourth point on the circle (exact incircle). Then every Delaunay triangulation of S
// is this one.
bool uniqueDelaunay(const dttest::XY& p, const Tris& tri) {
  std::map<std::pair<int, int>, int> apex;  // directed edge a -> b: the third vertex of its triangle
  for (const auto& t : tri)
    for (int k = 0; k < 3; ++k) apex[{t[k], t[(k + 1) % 3]}] = t[(k + 2) % 3];
  auto at = [&](int v, int c) { return p[2 * std::size_t(v) + std::size_t(c)]; };
  for (const auto& t : tri)
    for (int k = 0; k < 3; ++k) {
      const auto other = apex.find({t[(k + 1) % 3], t[k]});
      if (other == apex.end()) continue;
      const int d = other->second;
      if (dt::incircle(at(t[0], 0), at(t[0], 1), at(t[1], 0), at(t[1], 1), at(t[2], 0),
                       at(t[2], 1), at(d, 0), at(d, 1)) == 0)
        return false;
    }
  return true;
}

}  // namespace

TEST_CASE("parallel the parts and their seam give DT(S) on every degenerate family") {
  // Each family at 2, 3 and 8 threads, the parts forced (mode Always): the result is validated
  // exactly, has the sequential kernel's triangles where DT(S) is unique, else its number of
  // triangles, and the same merged duplicates. Where a slab's points are collinear or the seam
  // cannot be merged, the sequential kernel runs and the reason says so.
  int merged = 0, fallbacks = 0, uniqueSets = 0;
  for (const dtdeg::Family& f : dtdeg::families()) {
    CAPTURE(f.name);
    const dt::FastResult seq = dt::fastDelaunay(f.points);
    const bool unique = uniqueDelaunay(f.points, seq.tri);
    uniqueSets += unique;
    for (int threads : {2, 3, 8}) {
      CAPTURE(threads);
      dt::ParallelStats ps;
      const dt::FastResult r = parallelChecked(f.points, threads, 8, &ps, dt::ParallelClaim::Parts);
      CHECK(r.tri.size() == seq.tri.size());
      CHECK(r.duplicates == seq.duplicates);
      if (unique) CHECK(canonical(r.tri) == canonical(seq.tri));
      if (ps.reason == dt::ParallelReason::Concurrent) {
        ++merged;
        CHECK(ps.threadsUsed == threads);
        CHECK(ps.borderPoints > 0);
      } else {
        ++fallbacks;
        CHECK(ps.reason == dt::ParallelReason::SeamNotMerged);
        CHECK(ps.threadsUsed == 1);
      }
    }
  }
  MESSAGE("parts merged " << merged << " times, fell back " << fallbacks << " times; "
                          << uniqueSets << " families with a unique DT(S)");
  // The merge itself ran on most of them (cocircular grids included), not only the fallback.
  CHECK(merged >= 2 * fallbacks);
  CHECK(uniqueSets >= 3);
}

TEST_CASE("parallel a disk is inside a slab only when it is") {
  // Circles with exact centres and radii: the integer points (3, 4), (5, 0), (-4, -3) of the
  // circle of radius 5 about the origin, scaled by powers of two (exact) and moved.
  for (int e : {-1000, -600, -100, 0, 100, 600, 900}) {
    for (double cx : {0.0, 7.0, -1e6}) {
      CAPTURE(e);
      CAPTURE(cx);
      const double s = std::ldexp(1.0, e), c = cx * s;
      const double a[2] = {c + 3 * s, 4 * s}, b[2] = {c + 5 * s, 0}, d[2] = {c - 4 * s, -3 * s};
      const double left = c - 5 * s, right = c + 5 * s;  // the disk's extent in x
      // Well inside: true. Touching either side, or cut: false.
      CHECK(dt::fast::diskInSlab(a, b, d, left - 1e-6 * s, right + 1e-6 * s));
      CHECK(dt::fast::diskInSlab(a, b, d, -HUGE_VAL, right + 1e-6 * s));
      CHECK(dt::fast::diskInSlab(a, b, d, left - 1e-6 * s, HUGE_VAL));
      CHECK_FALSE(dt::fast::diskInSlab(a, b, d, left, right + 1e-6 * s));
      CHECK_FALSE(dt::fast::diskInSlab(a, b, d, left - 1e-6 * s, right));
      CHECK_FALSE(dt::fast::diskInSlab(a, b, d, left - 1e-6 * s, c));
      CHECK_FALSE(dt::fast::diskInSlab(a, b, d, c, HUGE_VAL));
      // The vertices in the other order (clockwise): the same disk.
      CHECK(dt::fast::diskInSlab(a, d, b, left - 1e-6 * s, right + 1e-6 * s));
      CHECK_FALSE(dt::fast::diskInSlab(a, d, b, left - 1e-6 * s, right));
    }
  }
  // A sliver (its centre moves far with a rounding) and a value that is not finite: not judged.
  const double p[2] = {0, 0}, q[2] = {1, 1e-9}, r[2] = {2, 0}, inf[2] = {HUGE_VAL, 0};
  CHECK_FALSE(dt::fast::diskInSlab(p, q, r, -HUGE_VAL, 1e300));
  CHECK_FALSE(dt::fast::diskInSlab(p, q, inf, -1e300, 1e300));
}

TEST_CASE("parallel the sort with several threads gives the sequential order") {
  // The parallel kernel's sort must be the sequential one, point for point: random, clustered
  // (long refined runs, which the pieces must not cut), outliers, and every degenerate family
  // (equal keys, equal points, flat boxes). Odd thread counts give uneven pieces and three
  // runs to merge. The same in memory the kernels lend (brioCoinOrderInto): the order there,
  // and nothing written past the bytes brioCoinScratchBytes promises.
  std::vector<std::pair<std::string, dttest::XY>> inputs = {
      {"uniform", dttest::uniformPoints(100000, 3)},
      {"clusters", dt::gaussianClusters(60000, 5, 3)},
      {"cluster beside uniform", dt::clusterBesideUniform(30000, 9)},
      {"outliers", dt::outlierPoints(20000, 11)},
      {"exponent spread", dt::exponentSpreadPoints(5000, 13)},
      {"tiny", dttest::uniformPoints(3, 1)}};
  for (const dtdeg::Family& f : dtdeg::families()) inputs.emplace_back(f.name, f.points);
  for (const auto& in : inputs)
    for (bool adaptive : {true, false})
      for (int rounds : {8, 1}) {
        CAPTURE(in.first);
        CAPTURE(adaptive);
        CAPTURE(rounds);
        const std::vector<std::size_t> seq = dt::brioCoinOrder(in.second, 1, rounds, adaptive);
        for (int threads : {2, 3, 4}) {
          CAPTURE(threads);
          CHECK(dt::brioCoinOrder(in.second, 1, rounds, adaptive, threads) == seq);
        }
        for (int threads : {1, 2}) {
          CAPTURE(threads);
          const std::size_t n = seq.size(), bytes = dt::brioCoinScratchBytes(n), guard = 64;
          std::vector<std::uint64_t> lent((bytes + guard) / 8 + 1, 0x5a5a5a5a5a5a5a5aULL);
          const std::size_t* o =
              dt::brioCoinOrderInto(in.second, 1, rounds, lent.data(), adaptive, threads);
          CHECK(std::vector<std::size_t>(o, o + n) == seq);
          const unsigned char* end = reinterpret_cast<const unsigned char*>(lent.data()) + bytes;
          CHECK(std::count(end, end + guard, 0x5a) == long(guard));
        }
      }
}

TEST_CASE("parallel rejects what the sequential kernel rejects") {
  const dttest::XY collinear = {0, 0, 1, 1, 2, 2, 3, 3};
  CHECK_THROWS_AS(dt::fastDelaunayParallel(collinear, 2), dt::DegenerateInput);
  CHECK_THROWS_AS(dt::fastDelaunayParallel({0, 0, 0, 0, 1, 1}, 2), dt::DegenerateInput);
  CHECK_THROWS_AS(dt::fastDelaunayParallel({0, 0, 1, 0, 0, NAN}, 2), std::invalid_argument);
  CHECK_THROWS_AS(dt::fastDelaunayParallel({0, 0, 1, 0, 0}, 2), std::invalid_argument);
  dt::FastOptions o;
  o.order = dt::InsertionOrder::Hilbert;
  CHECK_THROWS_AS(dt::fastDelaunayParallel(dttest::uniformPoints(100, 1), 2, o),
                  std::invalid_argument);
}

TEST_CASE("parallel the command line gives the same triangles with one and two threads") {
  const dttest::XY p = dttest::uniformPoints(30000, 99);
  const std::string in = dttest::tmpPath("parallel_in.node");
  dttest::writeText(in, dttest::nodeText(p));
  Tris got[2];
  for (int k = 0; k < 2; ++k) {
    const std::string out = dttest::tmpPath("parallel_out_" + std::to_string(k + 1));
    const dttest::CliResult r =
        dttest::runCli("'" + in + "' -o '" + out + "' --threads " + std::to_string(k + 1));
    INFO(r.err);
    REQUIRE(r.status == 0);
    got[k] = canonical(dttest::readEle(out + ".ele", 1));
  }
  CHECK(!got[0].empty());
  CHECK(got[0] == got[1]);
  CHECK(got[0] == canonical(dt::fastDelaunay(p).tri));
  const dttest::CliResult bad = dttest::runCli("'" + in + "' -o x --threads 0");
  CHECK(bad.status == 2);
  CHECK(bad.err.find("--threads") != std::string::npos);
}

TEST_CASE("parallel numbers the output in insertion order and reports progress on request") {
  dttest::XY p = dttest::uniformPoints(60000, 5);
  p.insert(p.end(), {p[10], p[11], p[20], p[21]});  // two duplicates
  const dt::FastResult plain =
      dt::fastDelaunayParallel(p, 2, {}, nullptr, 64, dt::ParallelClaim::Slabs, kAlways);
  dt::FastOptions o;
  o.insertionNumbering = true;
  o.progressEvery = 1000;
  std::size_t calls = 0, last = 0;
  bool increasing = true;
  o.progress = [&](std::size_t done, std::size_t total, const dt::FastStats&) {
    increasing = increasing && done >= last && done <= total && total == p.size() / 2;
    last = done;
    ++calls;
  };
  const dt::FastResult r =
      dt::fastDelaunayParallel(p, 2, o, nullptr, 64, dt::ParallelClaim::Slabs, kAlways);
  REQUIRE(r.inserted.size() == p.size() / 2);
  REQUIRE(r.points.size() == p.size());
  for (std::size_t i = 0; i < r.inserted.size(); ++i) {
    CHECK(r.points[2 * i] == p[2 * std::size_t(r.inserted[i])]);
    CHECK(r.points[2 * i + 1] == p[2 * std::size_t(r.inserted[i]) + 1]);
  }
  Tris mapped = r.tri;
  for (auto& t : mapped)
    for (int& v : t) v = r.inserted[std::size_t(v)];
  CHECK(canonical(mapped) == canonical(plain.tri));
  CHECK(r.duplicates == plain.duplicates);
  CHECK(r.duplicates.size() == 2);
  CHECK(calls > 10);
  CHECK(increasing);
}

TEST_CASE("parallel the shared core alone gives the sequential triangulation and its time adds up") {
  // fastDelaunaySharedCoreAlone: the parallel machinery (relaxed access, claims, rounds,
  // deferred insertions) with one thread, which bench_parallel's budget compares with the
  // sequential kernel. Same triangles; with the whole plane as its slab, one thread still defers
  // the cavities that touch the hull (a slab never takes a ghost), but nothing else.
  const dttest::XY p = dttest::uniformPoints(100000, 31);
  const Tris seq = canonical(dt::fastDelaunay(p).tri);
  for (dt::ParallelClaim claim : {dt::ParallelClaim::Slabs, dt::ParallelClaim::Locks}) {
    CAPTURE(int(claim));
    dt::ParallelStats ps;
    const dt::FastResult r = dt::fastDelaunaySharedCoreAlone(p, {}, &ps, claim);
    CHECK(canonical(r.tri) == seq);
    CHECK(ps.threadsUsed == 1);
    CHECK(ps.parallelPoints > 90000);
    if (claim == dt::ParallelClaim::Locks) CHECK(ps.deferred == 0);
    CHECK(ps.deferred < ps.parallelPoints / 100);
    // The parts of the budget: each measured, none larger than the whole, and one thread is
    // busy in its pieces for no longer than the rounds last.
    CHECK(ps.concurrentSeconds > 0);
    CHECK(ps.finishSeconds > 0);
    CHECK(ps.busySeconds <= ps.concurrentSeconds);
    CHECK(ps.busySeconds > ps.concurrentSeconds / 2);
    CHECK(ps.loneSeconds + ps.concurrentSeconds + ps.finishSeconds <= r.stats.insertSeconds);
  }
  // Two threads: the busy time is summed over both, so it may exceed the rounds' wall time,
  // but not twice it.
  dt::ParallelStats ps;
  const dt::FastResult r =
      dt::fastDelaunayParallel(p, 2, {}, &ps, 2048, dt::ParallelClaim::Slabs, kAlways);
  CHECK(canonical(r.tri) == seq);
  CHECK(ps.parallelPoints > 0);
  CHECK(ps.busySeconds <= 2 * ps.concurrentSeconds);
  CHECK(ps.loneSeconds + ps.concurrentSeconds + ps.finishSeconds <= r.stats.insertSeconds);
}

namespace {

// The cost model's decision for p with `threads` threads asked for, and the result validated
// exactly and checked against the sequential kernel's triangles, triangle by triangle: when the
// model ran one thread (that kernel itself, cocircular points or not), and whatever it chose
// when DT(S) is unique (`unique`: p in general position).
dt::ParallelStats decided(const dttest::XY& p, bool unique, int threads = 2) {
  dt::ParallelStats ps;
  const dt::FastResult r = dt::fastDelaunayParallel(p, threads, {}, &ps);
  const dt::CheckReport c = dt::checkDelaunay(p, r.tri);
  INFO(c.error);
  CHECK(c.ok);
  if (unique || ps.threadsUsed == 1) {
    const dt::FastResult seq = dt::fastDelaunay(p);
    CHECK(canonical(r.tri) == canonical(seq.tri));
    CHECK(r.duplicates == seq.duplicates);
  }
  CHECK(ps.threadsRequested == threads);
  return ps;
}

// What the model says when it sees the input (the machine has a second core).
dt::ParallelReason onTwoCores(dt::ParallelReason r) {
  return dt::defaultThreadCount() >= 2 ? r : dt::ParallelReason::OneCore;
}

}  // namespace

TEST_CASE("parallel the cost model runs one thread below its size and says why") {
  const std::size_t least = 2 * dt::ParallelModel::minPointsPerThread;
  const dt::ParallelStats small = decided(dttest::uniformPoints(30000, 4), true);
  CHECK(small.threadsUsed == 1);
  CHECK(small.reason == onTwoCores(dt::ParallelReason::TooFewPoints));
  CHECK(small.parallelPoints == 0);
  const dt::ParallelStats justBelow = decided(dttest::uniformPoints(least - 1, 5), true);
  CHECK(justBelow.threadsUsed == 1);
  CHECK(justBelow.reason == onTwoCores(dt::ParallelReason::TooFewPoints));
  // One thread asked for: the sequential kernel, and that reason.
  dt::ParallelStats one;
  dt::fastDelaunayParallel(dttest::uniformPoints(1000, 6), 1, {}, &one);
  CHECK(one.threadsUsed == 1);
  CHECK(one.reason == dt::ParallelReason::OneRequested);
}

TEST_CASE("parallel the cost model runs one thread on tiny input and on a small circle") {
  // However many threads are asked for: the sequential kernel, its triangles (decided compares
  // them one by one, on the circle and the grid too, where only the same kernel with the same
  // order gives the same ones), no concurrent round, and the reason.
  std::vector<dttest::XY> sets;
  for (std::size_t n : {3u, 4u, 17u, 500u}) sets.push_back(dttest::uniformPoints(n, 40 + n));
  sets.push_back(dt::circlePoints(64));
  sets.push_back(dt::gridPoints(9, 9));  // cocircular squares: DT(S) is not unique
  sets.push_back({0, 0, 1, 0, 0, 1, 1, 0, 0, 0});  // duplicates merged as by the sequential kernel
  for (const dttest::XY& p : sets)
    for (int threads : {2, 8, dt::defaultThreadCount()}) {
      CAPTURE(p.size() / 2);
      CAPTURE(threads);
      const dt::ParallelStats ps = decided(p, false, threads);
      CHECK(ps.threadsUsed == 1);
      CHECK(ps.reason == (threads > 1 ? onTwoCores(dt::ParallelReason::TooFewPoints)
                                      : dt::ParallelReason::OneRequested));
      CHECK(ps.parallelPoints == 0);
      CHECK(ps.parallelRounds == 0);
    }
}

TEST_CASE("parallel the cost model shares uniform points from its size on") {
  const std::size_t least = 2 * dt::ParallelModel::minPointsPerThread;
  const dt::ParallelStats ps = decided(dttest::uniformPoints(least, 8), true);
  const bool two = dt::defaultThreadCount() >= 2;
  CHECK(ps.threadsUsed == (two ? 2 : 1));
  CHECK(ps.reason == onTwoCores(dt::ParallelReason::Concurrent));
  if (two) {
    CHECK(ps.parallelPoints > least / 2);  // the large rounds went to the threads
    CHECK(ps.forecast.ratio > 0);
    CHECK(ps.forecast.ratio <= dt::ParallelModel::maxCutShareRatio);
  }
}

TEST_CASE("parallel the cost model runs one thread where the slabs cannot split") {
  const std::size_t n = 2 * dt::ParallelModel::minPointsPerThread + 1000;
  // Every point of a circle is on the hull, whose ghosts no slab may take; points with a tiny
  // spread in x put every triangle across the cut. Both are above the model's size.
  const dt::ParallelStats circle = decided(dt::circlePoints(n), false);
  CHECK(circle.threadsUsed == 1);
  CHECK(circle.reason == onTwoCores(dt::ParallelReason::SlabsDoNotSplit));
  dttest::XY thin = dttest::uniformPoints(n, 9);
  for (std::size_t i = 0; i < thin.size(); i += 2) thin[i] = 1 + thin[i] * 1e-9;
  const dt::ParallelStats flat = decided(thin, false);
  CHECK(flat.threadsUsed == 1);
  CHECK(flat.reason == onTwoCores(dt::ParallelReason::SlabsDoNotSplit));
  if (dt::defaultThreadCount() >= 2) {
    CHECK(circle.forecast.cutShare == 1.0);
    CHECK(flat.forecast.ratio > dt::ParallelModel::maxCutShareRatio);
  }
}

TEST_CASE("parallel the split forecast tells uniform points from a circle and an exponent spread") {
  // The forecast alone (no size gate): uniform points give about the reference share, the
  // points of a circle are all on the hull, an exponent spread crowds the cut.
  const dt::SplitForecast u = dt::forecastSplit(dttest::uniformPoints(100000, 10), 2);
  CHECK(u.uniformCutShare > 0);
  CHECK(u.uniformCutShare < 0.2);
  CHECK(u.ratio > 0.5);
  CHECK(u.ratio < 1.5);
  CHECK(dt::forecastSplit(dt::circlePoints(5000), 2).cutShare == 1.0);
  CHECK(dt::forecastSplit(dt::exponentSpreadPoints(20000, 11), 2).ratio >
        dt::ParallelModel::maxCutShareRatio);
  // Three slabs cut more than two.
  CHECK(dt::forecastSplit(dttest::uniformPoints(100000, 10), 3).uniformCutShare > u.uniformCutShare);
  // The share itself, counted another way on a set smaller than the sample (so the sample is
  // the set): vertices of triangles with vertices on both sides of the median x, or on a hull
  // edge (an edge of one triangle only).
  const dttest::XY q = dttest::uniformPoints(1500, 13);
  const std::vector<dt::Tri> tri = dt::fastDelaunay(q).tri;
  std::vector<double> xs;
  for (std::size_t i = 0; i < q.size(); i += 2) xs.push_back(q[i]);
  std::nth_element(xs.begin(), xs.begin() + 750, xs.end());
  const double cut = xs[750];
  std::map<std::pair<int, int>, int> edgeUses;
  std::set<int> cutVertices;
  for (const dt::Tri& t : tri) {
    int right = 0;
    for (int v : t) right += q[2 * std::size_t(v)] >= cut;
    if (right == 1 || right == 2) cutVertices.insert(t.begin(), t.end());
    for (int k = 0; k < 3; ++k) ++edgeUses[std::minmax(t[k], t[(k + 1) % 3])];
  }
  for (const auto& e : edgeUses)
    if (e.second == 1) cutVertices.insert({e.first.first, e.first.second});
  CHECK(dt::forecastSplit(q, 2).cutShare == doctest::Approx(double(cutVertices.size()) / 1500));
  // A collinear sample has no triangulation: it cannot be split.
  CHECK(dt::forecastSplit({0, 0, 1, 1, 2, 2, 3, 3}, 2).cutShare == 1.0);
}

TEST_CASE("parallel the command line prints the threads used and why") {
  const dttest::XY p = dttest::uniformPoints(20000, 12);
  const std::string in = dttest::tmpPath("parallel_stats_in.node");
  dttest::writeText(in, dttest::nodeText(p));
  const std::string out = dttest::tmpPath("parallel_stats_out");
  for (const char* t : {"2", "auto"}) {
    const dttest::CliResult r = dttest::runCli("'" + in + "' -o '" + out + "' --stats --threads " + t);
    INFO(r.err);
    REQUIRE(r.status == 0);
    CHECK(r.out.find("\nthreads_used: 1\n") != std::string::npos);
    CHECK(r.out.find(std::string("\nthreads_reason: ") +
                     dt::parallelReasonName(onTwoCores(dt::ParallelReason::TooFewPoints)) + "\n") !=
          std::string::npos);
  }
  const dttest::CliResult one = dttest::runCli("'" + in + "' -o '" + out + "' --stats");
  CHECK(one.out.find("\nthreads_reason: one_thread_requested\n") != std::string::npos);
  const dttest::CliResult listings =
      dttest::runCli("'" + in + "' -o '" + out + "' --stats --threads 2 --kernel listings");
  CHECK(listings.out.find("\nthreads_reason: sequential_order_or_kernel\n") != std::string::npos);
  // The threads asked for, as parsed: 'auto' is the machine's hardware threads, and no count
  // exceeds the CPUs this process may run on (the command line caps it, with a note).
  cpu_set_t cpus;
  REQUIRE(::sched_getaffinity(0, sizeof cpus, &cpus) == 0);
  const int usable = CPU_COUNT(&cpus);
  for (const auto& [arg, want] : {std::pair<std::string, int>{"2", 2}, {"auto", dt::defaultThreadCount()},
                                  {"1", 1}, {"0007", 7}}) {
    CAPTURE(arg);
    const dttest::CliResult r =
        dttest::runCli("'" + in + "' -o '" + out + "' --stats --threads " + arg);
    REQUIRE(r.status == 0);
    CHECK(r.out.find("\nthreads_requested: " + std::to_string(std::min(want, usable)) + "\n") !=
          std::string::npos);
  }
  // Bad values: refused before anything is read or written, naming the value.
  for (const char* v : {"automatic", "0", "-1", "1025", "", "2.5", "auto ", "+2", "99999"}) {
    CAPTURE(v);
    std::remove((out + "_bad.ele").c_str());
    const dttest::CliResult bad =
        dttest::runCli("'" + in + "' -o '" + out + "_bad' --threads '" + v + "'");
    CHECK(bad.status == 2);
    CHECK(bad.err.find("--threads must be 'auto' or an integer from 1 to 1024, not '" +
                       std::string(v) + "'") != std::string::npos);
    CHECK(!dttest::fileExists(out + "_bad.ele"));
  }
}
