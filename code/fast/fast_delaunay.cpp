#include "fast_delaunay.h"

#include <algorithm>
#include <chrono>
#include <stdexcept>

#include "fast_core.h"
#include "hilbert.h"
#include "predicates.h"

namespace dt {

namespace {

using fast::Inserter;
using fast::MarkClaim;
using fast::PlainAccess;

// One thread: the core with plain memory access and marks (fast_core.h).
template <class Pred, bool kMap, bool kCentroid>
void run(std::vector<double>& P, std::vector<int>& orig, FastResult& res, Pred pred,
         const FastOptions& opt, fast::RawMemory memA) {
  const int n = int(orig.size());
  const fast::FirstTriangle f = fast::firstTriangle(P, n);
  fast::Store S(P.data(), n, fast::slotsFor(std::size_t(n)), 1, std::move(memA));
  if (f.ccw)
    S.init(0, f.i1, f.i2);
  else
    S.init(0, f.i2, f.i1);
  MarkClaim claim(S);
  Inserter<Pred, PlainAccess, MarkClaim, kMap, kCentroid> K(S, claim, pred, res.stats);
  K.ringStart = !opt.ladderLastCavityStart;
  res.stats.insertions = 3;
  std::vector<std::pair<int, int>> dups;  // (point, vertex it duplicates), insertion numbers
  const std::size_t every = std::max<std::size_t>(1, opt.progressEvery);
  std::size_t nextReport = opt.progress ? every : std::size_t(-1);
  res.stats.x86_64_v3 = fast::useV3(opt);
  fast::inBuild(res.stats.x86_64_v3, [&] {
    for (int i = 1; i < n; ++i) {
      if (__builtin_expect(std::size_t(i) == nextReport, 0)) {
        opt.progress(std::size_t(i), std::size_t(n), res.stats);
        nextReport += every;
      }
      if (i == f.i1 || i == f.i2) continue;
      int d = -1;
      if (K.insert(i, d) == decltype(K)::Duplicate) dups.emplace_back(i, d);
    }
  });
  // Only the vertices of the triangles are kept: they become the output.
  claim.freeMarks();
  S.freeAdjacency();
  fast::finish(S.V, std::size_t(S.count.load()), n, P, orig, dups, opt.insertionNumbering, 1,
               res);
}

}  // namespace

std::vector<std::uint64_t> fastHilbertKeys(const std::vector<double>& xy, int depth) {
  if (depth == 0) depth = hilbertAutoDepth(xy.size() / 2);
  if (depth < 1 || depth > 31) throw std::invalid_argument("fastHilbertKeys: depth out of 1..31");
  return hilbertKeysFast(xy, depth);
}

//! [fastDelaunay]
FastResult fastDelaunay(const std::vector<double>& xy, const FastOptions& opt) {
  fast::checkInput(xy, "fastDelaunay");
  if ((opt.ladderMapAdjacency && !opt.ladderCentroidWalk) ||
      (opt.ladderCentroidWalk && !opt.ladderLastCavityStart) ||
      (opt.ladderLastCavityStart && !opt.ladderCallPredicates))
    throw std::invalid_argument("fastDelaunay: the ladder switches are cumulative");
  const std::size_t n = xy.size() / 2;
  FastResult res;
  const auto t0 = std::chrono::steady_clock::now();
  fast::RawMemory memA;  // the adjacency array's memory, which the default order's sort borrows
  std::vector<int> orig;  // orig[i]: input number of the i-th point inserted
  orig.reserve(n);
  adviseHugePages(orig.data(), n * sizeof(int));
  if (opt.order == FastOrder::Input) {
    for (std::size_t i = 0; i < n; ++i) orig.push_back(int(i));
  } else if (opt.order == FastOrder::RadixBrio) {  // hilbert.h: one sort for the whole library
    memA = fast::adjacencyMemory(fast::slotsFor(n), n);
    const std::size_t* o =
        brioCoinOrderInto(xy, opt.seed, std::max(1, std::min(opt.rounds, 32)), memA.get());
    orig.assign(o, o + n);
  } else {
    const std::vector<std::size_t> o =
        opt.order == FastOrder::Brio ? brioOrder(xy, opt.seed) : hilbertOrder(xy);
    orig.assign(o.begin(), o.end());
  }
  if (!memA) memA = fast::adjacencyMemory(fast::slotsFor(n), n);
  std::vector<double> P = fast::pointsInOrder(xy, orig, 1);
  const auto t1 = std::chrono::steady_clock::now();
  res.stats.sortSeconds = std::chrono::duration<double>(t1 - t0).count();
  if (opt.ladderCallPredicates) {
    const PredicateCounters before = predicateCounters();
    const fast::CalledPredicates pred;
    if (opt.ladderMapAdjacency)
      run<fast::CalledPredicates, true, true>(P, orig, res, pred, opt, std::move(memA));
    else if (opt.ladderCentroidWalk)
      run<fast::CalledPredicates, false, true>(P, orig, res, pred, opt, std::move(memA));
    else
      run<fast::CalledPredicates, false, false>(P, orig, res, pred, opt, std::move(memA));
    res.stats.orient = predicateCounters().orient - before.orient;
    res.stats.incircle = predicateCounters().incircle - before.incircle;
  } else {
    run<fast::InlinePredicates, false, false>(P, orig, res, fast::InlinePredicates{&res.stats}, opt,
                                              std::move(memA));
  }
  res.stats.insertSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t1).count();
  return res;
}
//! [fastDelaunay]

}  // namespace dt
