#include "fast_parallel.h"

#include <algorithm>
#include <chrono>
#include <memory>
#include <stdexcept>

#include "fast_core.h"
#include "hilbert.h"

namespace dt {

namespace {

// Several threads: the core with relaxed atomic access and try-locks (fast_core.h), on one
// shared Store. Every entry of V and A is read and written with relaxed atomic accesses, so a
// walk may read a triangle that another thread is rewriting without a data race; what the walk
// finds is only a hint, checked under a lock.
using Inserter = fast::Inserter<fast::InlinePredicates, fast::RelaxedAccess, fast::LockClaim>;

// One thread's state, on cache lines of its own: two threads' counters never share a line.
struct alignas(64) Worker {
  FastStats stats;
  std::vector<std::pair<int, int>> dups;  // (point, vertex it duplicates), insertion numbers
  std::vector<int> deferred;
};

// Inserts points [from, to) of the insertion order (skipping i1, i2) with one inserter; a Busy
// point goes to the deferred list, or is an error when the inserter must be alone. tick(i), if
// given, is called before point i when i - from is a multiple of `every` (the progress report).
template <class Tick>
void insertRange(Inserter& in, Worker& w, int from, int to, int i1, int i2, bool alone,
                 std::size_t every, Tick tick) {
  std::size_t next = every;
  for (int i = from; i < to; ++i) {
    if (__builtin_expect(std::size_t(i - from) == next, 0)) {
      tick(i);
      next += every;
    }
    if (i == i1 || i == i2) continue;
    int d = -1;
    const Inserter::Outcome o = in.insert(i, d);
    if (o == Inserter::Duplicate) {
      w.dups.emplace_back(i, d);
    } else if (o == Inserter::Busy) {
      if (alone) throw std::logic_error("fastDelaunayParallel: a lone insertion met a lock");
      w.deferred.push_back(i);
    }
  }
}

}  // namespace

int defaultThreadCount() { return std::max(1, int(std::thread::hardware_concurrency())); }

//! [fastDelaunayParallel]
FastResult fastDelaunayParallel(const std::vector<double>& xy, int threads, const FastOptions& opt,
                                ParallelStats* pstats, int minPiece) {
  ParallelStats ps;
  if (threads <= 1) {
    if (pstats) *pstats = ps;
    return fastDelaunay(xy, opt);
  }
  threads = std::min(threads, fast::kMaxThreads);
  ps.threads = threads;
  if (opt.order != FastOrder::RadixBrio || opt.ladderCallPredicates)
    throw std::invalid_argument(
        "fastDelaunayParallel: more than one thread needs the default order and predicates");
  fast::checkInput(xy, "fastDelaunayParallel");
  const std::size_t n = xy.size() / 2;
  FastResult res;
  const auto t0 = std::chrono::steady_clock::now();
  const int rounds = std::max(1, std::min(opt.rounds, 32));
  std::vector<int> orig;
  {
    const std::vector<std::size_t> o = brioCoinOrder(xy, opt.seed, rounds, true, threads);
    orig.assign(o.begin(), o.end());
  }
  std::vector<double> P = fast::pointsInOrder(xy, orig, threads);
  // Where each round starts in the order (the rounds are consecutive, first round first).
  std::vector<std::vector<int>> roundSize(std::size_t(threads), std::vector<int>(rounds, 0));
  fast::parallelFor(threads, n, [&](int k, std::size_t lo, std::size_t hi) {
    for (std::size_t i = lo; i < hi; ++i)
      ++roundSize[std::size_t(k)][std::size_t(brioCoinRound(i, opt.seed, rounds))];
  });
  std::vector<int> roundStart(std::size_t(rounds) + 1, 0);
  for (int r = 0; r < rounds; ++r) {
    roundStart[r + 1] = roundStart[r];
    for (const std::vector<int>& c : roundSize) roundStart[r + 1] += c[std::size_t(r)];
  }
  res.stats.sortSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

  const int N = int(n);
  const fast::FirstTriangle f = fast::firstTriangle(P, N);
  const int i1 = f.i1, i2 = f.i2;
  // Room for the 2n + 2 triangles and each thread's last, partly used block of slots.
  const std::size_t slots = 2 * n + 2 + std::size_t(threads) * fast::LockClaim::kBlock;
  fast::Store S(P.data(), N, slots);
  if (f.ccw)
    S.init(0, i1, i2);
  else
    S.init(0, i2, i1);
  fast::Locks L(slots, 4);
  std::vector<Worker> W(static_cast<std::size_t>(threads));
  std::vector<std::unique_ptr<fast::LockClaim>> claims;
  std::vector<std::unique_ptr<Inserter>> ins;
  for (int k = 0; k < threads; ++k) {
    claims.emplace_back(new fast::LockClaim(S, L, k + 1));
    ins.emplace_back(new Inserter(S, *claims.back(), fast::InlinePredicates{&W[k].stats}, W[k].stats));
  }
  res.stats.insertions = 3;

  // A round goes to the threads when each gets at least minPiece points; before that (and for
  // the points the first triangle skipped), one thread inserts.
  int seqEnd = i2 + 1;
  int r0 = 0;
  while (r0 < rounds && (roundStart[r0 + 1] <= seqEnd ||
                         roundStart[r0 + 1] - roundStart[r0] < std::max(1, minPiece) * threads))
    ++r0;
  seqEnd = std::max(seqEnd, roundStart[r0]);
  // Progress (FastOptions::progress) is reported by the calling thread only, so the callback
  // needs no locking: during a concurrent round, from its own piece (the pieces advance at about
  // the same rate), with its own counters scaled by the number of threads.
  const std::size_t every =
      opt.progress ? std::max<std::size_t>(1, opt.progressEvery) : std::size_t(-1);
  auto report = [&](std::size_t done, int scale) {
    FastStats s = W[0].stats;
    s.walkSteps *= std::uint64_t(scale);
    s.cavityFaces *= std::uint64_t(scale);
    s.insertions = std::min<std::uint64_t>(done, s.insertions * std::uint64_t(scale));
    opt.progress(std::min(done, n), n, s);
  };
  insertRange(*ins[0], W[0], 1, seqEnd, i1, i2, true, every,
              [&](int i) { report(std::size_t(i), 1); });
  const auto tp = std::chrono::steady_clock::now();
  for (int r = r0; r < rounds; ++r) {
    const int from = std::max(seqEnd, roundStart[r]), to = roundStart[r + 1];
    if (from >= to) continue;
    ++ps.parallelRounds;
    ps.parallelPoints += std::uint64_t(to - from);
    // (The walk starts where this thread's previous piece ended.)
    fast::parallelFor(threads, std::size_t(to - from), [&](int k, std::size_t lo, std::size_t hi) {
      insertRange(*ins[k], W[k], from + int(lo), from + int(hi), i1, i2, false,
                  k == 0 ? every / std::size_t(threads) + 1 : std::size_t(-1), [&](int i) {
                    report(std::size_t(from) + std::size_t(i - from) * std::size_t(threads),
                           threads);
                  });
    });
    // The deferred insertions, by one thread, in their order (the lock of every triangle is free).
    std::vector<int> later;
    for (Worker& w : W) {
      later.insert(later.end(), w.deferred.begin(), w.deferred.end());
      w.deferred.clear();
    }
    std::sort(later.begin(), later.end());
    ps.deferred += later.size();
    for (int i : later)
      insertRange(*ins[0], W[0], i, i + 1, i1, i2, true, std::size_t(-1), [](int) {});
  }
  ps.parallelSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - tp).count();

  std::vector<std::pair<int, int>> dups;
  for (Worker& w : W) {
    res.stats.insertions += w.stats.insertions;
    res.stats.walkSteps += w.stats.walkSteps;
    res.stats.cavityFaces += w.stats.cavityFaces;
    res.stats.orient += w.stats.orient;
    res.stats.incircle += w.stats.incircle;
    dups.insert(dups.end(), w.dups.begin(), w.dups.end());
  }
  ins.clear();
  claims.clear();
  L.owner.reset();
  std::vector<int>().swap(S.A);
  fast::finish(S.V, std::size_t(S.count.load()), N, P, orig, dups, opt.insertionNumbering,
               threads, res);
  res.stats.insertSeconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() -
      res.stats.sortSeconds;
  if (pstats) *pstats = ps;
  return res;
}
//! [fastDelaunayParallel]

}  // namespace dt
