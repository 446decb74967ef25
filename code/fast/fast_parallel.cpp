#include "fast_parallel.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <memory>
#include <mutex>
#include <stdexcept>

#include "fast_core.h"
#include "fast_split.h"
#include "generators.h"
#include "hilbert.h"
#include "errors.h"

namespace dt {

namespace {

// Several threads: the core with relaxed atomic access and a shared claim (slabs or try-locks,
// fast_core.h), on one shared Store. Every entry of V and A is read and written with relaxed
// atomic accesses, so a walk may read a triangle that another thread is rewriting without a
// data race; what the walk finds is only a hint, checked once the claim holds the triangle.
template <class Claim>
using InserterOf = fast::Inserter<fast::InlinePredicates, fast::RelaxedAccess, Claim>;

// One thread's state, on cache lines of its own: two threads' counters never share a line.
struct alignas(64) Worker {
  FastStats stats;
  std::vector<std::pair<int, int>> dups;  // (point, vertex it duplicates), insertion numbers
  std::vector<int> deferred;
  double busySeconds = 0;  // time inside this thread's pieces of the concurrent rounds
};

double secondsSince(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

// Inserts the points pick(from), ..., pick(to - 1) of the insertion order (skipping i1, i2, and
// the positions where pick gives -1: another thread's points) with
// one inserter; a Busy point goes to the deferred list, or is an error when the inserter must be
// alone. tick(j), if given, is called before the j-th point when j - from is a multiple of
// `every` (the progress report). v3: in the x86-64-v3 build (fast::hasV3).
template <class Inserter, class Pick, class Tick>
void insertRange(bool v3, Inserter& in, Worker& w, int from, int to, Pick pick, int i1, int i2,
                 bool alone, std::size_t every, Tick tick) {
  fast::inBuild(v3, [&] {
    std::size_t next = every;
    for (int j = from; j < to; ++j) {
      if (__builtin_expect(std::size_t(j - from) == next, 0)) {
        tick(j);
        next += every;
      }
      const int i = pick(j);
      if (i < 0 || i == i1 || i == i2) continue;
      int d = -1;
      const typename Inserter::Outcome o = in.insert(i, d);
      if (o == Inserter::Duplicate) {
        w.dups.emplace_back(i, d);
      } else if (o == Inserter::Busy) {
        if (alone) throw std::logic_error("fastDelaunayParallel: a lone insertion was refused");
        w.deferred.push_back(i);
      }
    }
  });
}

const auto kIdentity = [](int j) { return j; };

// The claims of the threads, and how a concurrent round is shared out among them: round()
// calls run(k, lo, hi, pick, step) for each thread k, where one position of [lo, hi) stands for
// `step` points of the round (for the progress report).
struct LockPolicy {
  using Claim = fast::LockClaim;
  fast::Locks L;
  LockPolicy(std::size_t slots) : L(slots, 4) {}
  std::unique_ptr<Claim> make(fast::Store& S, int k) { return std::unique_ptr<Claim>(new Claim(S, L, k + 1)); }
  void alone(Claim&) {}
  // Thread k takes the k-th of `threads` consecutive pieces of the round's Hilbert order.
  template <class Run>
  void round(const std::vector<double>&, int from, int to, int threads,
             std::vector<std::unique_ptr<Claim>>&, Run run) {
    fast::parallelFor(threads, std::size_t(to - from), [&](int k, std::size_t lo, std::size_t hi) {
      run(k, from + int(lo), from + int(hi), kIdentity, threads);
    });
  }
  void release() { L.owner.reset(); }
};

struct SlabPolicy {
  using Claim = fast::SlabClaim;
  std::vector<double> xs;
  SlabPolicy(std::size_t) {}
  std::unique_ptr<Claim> make(fast::Store& S, int) { return std::unique_ptr<Claim>(new Claim(S)); }
  void alone(Claim& c) { c.setAlone(); }
  // Thread k takes the round's points in the k-th slab of x, in their Hilbert order: it goes
  // through the whole round and skips the others' points (a comparison each, against an
  // insertion's hundreds of nanoseconds: no partition step runs on one thread). The slabs are
  // cut at x-quantiles of an evenly spaced sample of the round (at most about 4096 points), so
  // each gets about as many points.
  template <class Run>
  void round(const std::vector<double>& P, int from, int to, int threads,
             std::vector<std::unique_ptr<Claim>>& claims, Run run) {
    const std::size_t m = std::size_t(to - from), step = std::max<std::size_t>(1, m / 4096);
    xs.clear();
    for (std::size_t j = 0; j < m; j += step) xs.push_back(P[2 * (std::size_t(from) + j)]);
    std::vector<double> cut(std::size_t(threads) + 1);
    cut[0] = -HUGE_VAL;
    cut[std::size_t(threads)] = HUGE_VAL;
    for (int k = 1; k < threads; ++k) {
      auto q = xs.begin() + std::ptrdiff_t(xs.size() * std::size_t(k) / std::size_t(threads));
      std::nth_element(xs.begin(), q, xs.end());
      cut[std::size_t(k)] = *q;
    }
    for (int k = 0; k < threads; ++k) claims[std::size_t(k)]->setSlab(cut[std::size_t(k)], cut[std::size_t(k) + 1]);
    fast::parallelFor(threads, std::size_t(threads), [&](int, std::size_t lo, std::size_t hi) {
      for (std::size_t k = lo; k < hi; ++k) {
        const double a = cut[k], b = cut[k + 1];
        run(int(k), from, to, [&P, a, b](int j) {
          const double x = P[2 * std::size_t(j)];
          return x >= a && x < b ? j : -1;
        }, 1);
      }
    });
  }
  void release() {}
};

}  // namespace

int defaultThreadCount() { return std::max(1, int(std::thread::hardware_concurrency())); }

const char* parallelReasonName(ParallelReason r) {
  switch (r) {
    case ParallelReason::Concurrent: return "concurrent";
    case ParallelReason::OneRequested: return "one_thread_requested";
    case ParallelReason::OneCore: return "one_core";
    case ParallelReason::TooFewPoints: return "too_few_points";
    case ParallelReason::SlabsDoNotSplit: return "slabs_do_not_split";
    case ParallelReason::SequentialOnly: return "sequential_order_or_kernel";
    case ParallelReason::SeamNotMerged: return "seam_not_merged";
  }
  return "unknown";
}

namespace {

// The share of a sample's vertices that lie on a triangle no slab can take: one with vertices in
// two slabs (the slabs cut at the sample's x-quantiles, as SlabPolicy::round cuts a round), or
// a ghost (a hull edge: every point on a circle is one). A sample with no triangulation
// (collinear, fewer than three distinct points, or refused) counts as all cut.
double cutShareOf(const std::vector<double>& sample, int threads) {
  FastResult r;
  try {
    r = fastDelaunay(sample);
  } catch (const DegenerateInput&) {
    return 1;
  } catch (const std::invalid_argument&) {  // the whole input is refused in a moment, by the kernel
    return 1;
  }
  const std::size_t m = sample.size() / 2;
  std::vector<double> xs(m);
  for (std::size_t i = 0; i < m; ++i) xs[i] = sample[2 * i];
  std::vector<double> cut;
  for (int k = 1; k < threads; ++k) {
    auto q = xs.begin() + std::ptrdiff_t(m * std::size_t(k) / std::size_t(threads));
    std::nth_element(xs.begin(), q, xs.end());
    cut.push_back(*q);
  }
  std::sort(cut.begin(), cut.end());
  // A point's slab: the number of cuts at or left of it (slab k holds cut[k-1] <= x < cut[k]).
  auto slab = [&](int v) {
    return std::upper_bound(cut.begin(), cut.end(), sample[2 * std::size_t(v)]) - cut.begin();
  };
  std::vector<char> used(m, 0), onCut(m, 0);
  // In counter-clockwise triangles (v, a, b) an inner vertex's out-neighbours a and in-neighbours
  // b are the same vertices; a hull vertex lacks one of each, two different ones: sums differ.
  std::vector<std::int64_t> out(m, 0), in(m, 0);
  for (const Tri& t : r.tri) {
    const auto s0 = slab(t[0]);
    const bool across = slab(t[1]) != s0 || slab(t[2]) != s0;
    for (int k = 0; k < 3; ++k) {
      const std::size_t v = std::size_t(t[k]);
      used[v] = 1;
      if (across) onCut[v] = 1;
      out[v] += t[(k + 1) % 3];
      in[v] += t[(k + 2) % 3];
    }
  }
  for (std::size_t v = 0; v < m; ++v)
    if (out[v] != in[v]) onCut[v] = 1;
  const auto nUsed = std::count(used.begin(), used.end(), 1);
  return nUsed ? double(std::count(onCut.begin(), onCut.end(), 1)) / double(nUsed) : 1;
}

// Uniform points' cut share for a thread count: computed once per count (a fixed sample).
double uniformCutShare(int threads) {
  static std::mutex mu;
  static std::map<int, double> known;
  std::lock_guard<std::mutex> hold(mu);
  auto it = known.find(threads);
  if (it == known.end())
    it = known.emplace(threads, cutShareOf(uniformPoints(ParallelModel::sampleSize, 47), threads)).first;
  return it->second;
}

// The forecast from an evenly spaced sample of m points of the input (for a set given in any
// order, spread over all of it), against uniform points' share (uniformCutShare).
SplitForecast forecastOf(const std::vector<double>& xy, int threads, std::size_t m) {
  const std::size_t n = xy.size() / 2;
  std::vector<double> sample;
  sample.reserve(2 * m);
  for (std::size_t j = 0; j < m; ++j) {
    const std::size_t i = j * n / m;
    sample.push_back(xy[2 * i]);
    sample.push_back(xy[2 * i + 1]);
  }
  SplitForecast f;
  f.cutShare = cutShareOf(sample, threads);
  f.uniformCutShare = uniformCutShare(threads);
  f.ratio = f.cutShare / f.uniformCutShare;
  return f;
}

void requireDefaultOrder(const FastOptions& opt) {
  if (opt.order != InsertionOrder::Brio)
    throw std::invalid_argument("fastDelaunayParallel: more than one thread needs the default order");
}

}  // namespace

SplitForecast forecastSplit(const std::vector<double>& xy, int threads) {
  const std::size_t n = xy.size() / 2;
  // A glance first, on a smaller sample: an input hopeless at a glance (nearly every vertex on
  // the hull or across a cut, as on a circle, where every incircle test of the cocircular points
  // is decided by an exact stage: the dearest sample to triangulate) is judged from it, at a
  // fraction of the cost. (Its share is compared with the full sample's uniform share: at least
  // glanceHopeless of the vertices is far over the model's bound.)
  if (n > ParallelModel::sampleSize) {
    const SplitForecast g = forecastOf(xy, threads, ParallelModel::glanceSize);
    if (g.cutShare >= ParallelModel::glanceHopeless) return g;
  }
  return forecastOf(xy, threads, std::min(n, ParallelModel::sampleSize));
}

//! [decideThreads]
ThreadDecision decideThreads(const std::vector<double>& xy, int threads) {
  ThreadDecision d;
  if (threads <= 1) return d;
  if (defaultThreadCount() < 2) {
    d.reason = ParallelReason::OneCore;
    return d;
  }
  // No more threads than hardware threads: a round waits for its slowest slab.
  const std::size_t bySize = xy.size() / 2 / ParallelModel::minPointsPerThread;
  const int t = int(std::min<std::size_t>(std::size_t(std::min(threads, defaultThreadCount())), bySize));
  if (t < 2) {
    d.reason = ParallelReason::TooFewPoints;
    return d;
  }
  d.forecast = forecastSplit(xy, t);
  if (!(d.forecast.ratio <= ParallelModel::maxCutShareRatio)) {
    d.reason = ParallelReason::SlabsDoNotSplit;
    return d;
  }
  d.threads = t;
  d.reason = ParallelReason::Concurrent;
  return d;
}
//! [decideThreads]

//! [fastDelaunayParallel]
// The insertions after the sort, the same for both claims: the small first rounds by one thread,
// each larger round shared out by the policy, the deferred insertions of a round by one thread;
// then the output.
template <class Policy>
void insertRounds(const std::vector<double>& xy, std::vector<double>& P, std::vector<int>& orig,
                  const std::vector<int>& roundStart, int rounds, int threads,
                  const FastOptions& opt, int minPiece, ParallelStats& ps, FastResult& res,
                  std::chrono::steady_clock::time_point t0, fast::RawMemory memA) {
  const std::size_t n = xy.size() / 2;
  std::vector<Worker> W(static_cast<std::size_t>(threads));
  const int N = int(n);
  const fast::FirstTriangle f = fast::firstTriangle(P, N);
  const int i1 = f.i1, i2 = f.i2;
  const std::size_t slots = fast::slotsFor(n, threads);
  fast::Store S(P.data(), N, slots, threads, std::move(memA));
  if (f.ccw)
    S.init(0, i1, i2);
  else
    S.init(0, i2, i1);
  Policy policy(slots);
  std::vector<std::unique_ptr<typename Policy::Claim>> claims;
  std::vector<std::unique_ptr<InserterOf<typename Policy::Claim>>> ins;
  for (int k = 0; k < threads; ++k) {
    claims.push_back(policy.make(S, k));
    ins.emplace_back(new InserterOf<typename Policy::Claim>(S, *claims.back(), fast::InlinePredicates{&W[std::size_t(k)].stats},
                                                            W[std::size_t(k)].stats));
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
  const bool v3 = res.stats.x86_64_v3;  // the build runShared chose
  policy.alone(*claims[0]);
  const auto tl = std::chrono::steady_clock::now();
  insertRange(v3, *ins[0], W[0], 1, seqEnd, kIdentity, i1, i2, true, every,
              [&](int i) { report(std::size_t(i), 1); });
  ps.loneSeconds += secondsSince(tl);
  const auto tp = std::chrono::steady_clock::now();
  for (int r = r0; r < rounds; ++r) {
    const int from = std::max(seqEnd, roundStart[r]), to = roundStart[r + 1];
    if (from >= to) continue;
    ++ps.parallelRounds;
    ps.parallelPoints += std::uint64_t(to - from);
    // (The walk starts where this thread's previous piece ended.)
    const auto tc = std::chrono::steady_clock::now();
    policy.round(P, from, to, threads, claims, [&](int k, int lo, int hi, auto pick, int step) {
      const auto tb = std::chrono::steady_clock::now();
      insertRange(v3, *ins[std::size_t(k)], W[std::size_t(k)], lo, hi, pick, i1, i2, false,
                  k == 0 && opt.progress ? every / std::size_t(step) + 1 : std::size_t(-1), [&](int j) {
                    report(std::size_t(from) + std::size_t(j - lo) * std::size_t(step), threads);
                  });
      W[std::size_t(k)].busySeconds += secondsSince(tb);
    });
    ps.concurrentSeconds += secondsSince(tc);
    // The deferred insertions, by one thread, in their order (no other thread runs now).
    std::vector<int> later;
    for (Worker& w : W) {
      later.insert(later.end(), w.deferred.begin(), w.deferred.end());
      w.deferred.clear();
    }
    std::sort(later.begin(), later.end());
    ps.deferred += later.size();
    policy.alone(*claims[0]);
    const auto td = std::chrono::steady_clock::now();
    for (int i : later)
      insertRange(v3, *ins[0], W[0], i, i + 1, kIdentity, i1, i2, true, std::size_t(-1), [](int) {});
    ps.loneSeconds += secondsSince(td);
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
    ps.busySeconds += w.busySeconds;
  }
  ins.clear();
  claims.clear();
  policy.release();
  S.freeAdjacency();
  const auto tf = std::chrono::steady_clock::now();
  fast::finish(S.V, std::size_t(S.count.load()), N, P, orig, dups, opt.insertionNumbering,
               threads, res);
  ps.finishSeconds = secondsSince(tf);
  res.stats.insertSeconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() -
      res.stats.sortSeconds;
}

namespace {

// fastDelaunayParallel with threads >= 1 (1: fastDelaunaySharedCoreAlone); fills the run's
// part of ps.
FastResult runShared(const std::vector<double>& xy, int threads, const FastOptions& opt,
                     ParallelStats& ps, int minPiece, ParallelClaim claim, bool v3) {
  threads = std::min(threads, fast::kMaxThreads);
  ps.threadsUsed = threads;
  requireDefaultOrder(opt);
  fast::checkInput(xy, "fastDelaunayParallel");
  FastResult res;
  res.stats.x86_64_v3 = v3;
  const auto t0 = std::chrono::steady_clock::now();
  const int rounds = std::max(1, std::min(opt.rounds, 32));
  const std::size_t n = xy.size() / 2;
  // The adjacency array's memory first: the sort borrows it.
  fast::RawMemory memA = fast::adjacencyMemory(fast::slotsFor(n, threads), n, threads);
  std::vector<int> orig;
  {
    const std::size_t* o = brioCoinOrderInto(xy, opt.seed, rounds, memA.get(), true, threads);
    orig.assign(o, o + n);
  }
  std::vector<double> P = fast::pointsInOrder(xy, orig, threads);
  // Where each round starts in the order: the order is sorted by round first, so the rounds
  // are consecutive, first round first, and each start is found by bisection.
  std::vector<int> roundStart(std::size_t(rounds) + 1, 0);
  for (int r = 0; r < rounds; ++r)
    roundStart[r + 1] = int(std::partition_point(orig.begin() + roundStart[r], orig.end(),
                                                 [&](int i) {
                                                   return brioCoinRound(std::size_t(i), opt.seed,
                                                                        rounds) <= r;
                                                 }) -
                            orig.begin());
  res.stats.sortSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

  if (claim == ParallelClaim::Locks)
    insertRounds<LockPolicy>(xy, P, orig, roundStart, rounds, threads, opt, minPiece, ps, res, t0,
                             std::move(memA));
  else
    insertRounds<SlabPolicy>(xy, P, orig, roundStart, rounds, threads, opt, minPiece, ps, res, t0,
                             std::move(memA));
  return res;
}

}  // namespace

FastResult fastDelaunayParallel(const std::vector<double>& xy, int threads, const FastOptions& opt,
                                ParallelStats* pstats, int minPiece, ParallelClaim claim,
                                ParallelMode mode) {
  if (threads > 1) requireDefaultOrder(opt);  // whatever the model then decides
  ParallelStats ps;
  ps.threadsRequested = std::max(1, threads);
  ThreadDecision d;
  if (threads > 1 && mode == ParallelMode::Always) {
    d.threads = threads;
    d.reason = ParallelReason::Concurrent;
  } else if (threads > 1) {
    const auto t0 = std::chrono::steady_clock::now();
    d = decideThreads(xy, threads);
    ps.decisionSeconds = secondsSince(t0);
  }
  ps.reason = d.reason;
  ps.forecast = d.forecast;
  FastResult res;
  if (d.threads > 1 && claim == ParallelClaim::Parts) {
    fast::checkInput(xy, "fastDelaunayParallel");
    const int threadsUsed = std::min(d.threads, fast::kMaxThreads);
    fast::SplitReport rep;
    res = fast::splitAndMerge(xy, threadsUsed, opt, fast::hasV3(), rep);
    ps.concurrentSeconds = ps.parallelSeconds = rep.partsSeconds;
    ps.busySeconds = rep.busySeconds;
    ps.loneSeconds = rep.mergeSeconds;
    ps.finishSeconds = rep.finishSeconds;
    ps.borderPoints = rep.border;
    if (rep.merged) {
      ps.threadsUsed = threadsUsed;
      ps.parallelPoints = xy.size() / 2;
    } else {
      ps.reason = ParallelReason::SeamNotMerged;
      res = fastDelaunay(xy, opt);
    }
  } else if (d.threads > 1) {
    res = runShared(xy, d.threads, opt, ps, minPiece, claim, fast::hasV3());
  } else {
    res = fastDelaunay(xy, opt);
  }
  if (pstats) *pstats = ps;
  return res;
}
//! [fastDelaunayParallel]

FastResult fastDelaunaySharedCoreAlone(const std::vector<double>& xy, const FastOptions& opt,
                                       ParallelStats* pstats, ParallelClaim claim) {
  if (claim == ParallelClaim::Parts)
    throw std::invalid_argument("fastDelaunaySharedCoreAlone: the claim Parts shares no triangulation");
  ParallelStats ps;
  ps.reason = ParallelReason::Concurrent;  // the shared machinery's rounds, by one thread
  FastResult res = runShared(xy, 1, opt, ps, 2048, claim, fast::hasV3());
  if (pstats) *pstats = ps;
  return res;
}

namespace fast {

FastResult sharedCoreAlone(const std::vector<double>& xy, const FastOptions& opt, bool v3) {
  ParallelStats ps;
  return runShared(xy, 1, opt, ps, 2048, ParallelClaim::Slabs, v3);
}

}  // namespace fast

}  // namespace dt
