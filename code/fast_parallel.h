// Going further: the fast kernel on several cores, for inputs where one core's insertion time
// dominates. The same Bowyer-Watson insertion as fast_delaunay.h (one core, fast_core.h, with
// other policies), run by several threads on one shared triangulation. By default each thread
// owns a slab of the plane for the round and takes only the triangles with all three vertices
// in it, which no other thread can touch (no lock, no atomic read-modify-write); the other
// claim locks every triangle an insertion reads or writes with a try-lock. An insertion that
// cannot take a triangle it needs gives up and is redone after the round, alone. Why this
// gives DT(S): book/parallel.md.
#pragma once

#include <cstdint>
#include <vector>

#include "fast_delaunay.h"

namespace dt {

/// What the parallel run did, beside the FastStats of the result.
struct ParallelStats {
  int threads = 1;                    ///< threads used (1: the sequential kernel was called)
  std::uint64_t parallelPoints = 0;   ///< points handed to the concurrent rounds
  std::uint64_t deferred = 0;         ///< of those, insertions that met a lock and were redone alone
  int parallelRounds = 0;             ///< BRIO rounds inserted concurrently
  double parallelSeconds = 0;         ///< wall time of the concurrent rounds (deferred ones included)
  // Where the wall time goes (bench_parallel's budget table); with sortSeconds of the FastStats,
  // these add up to the run's time, up to the set-up of the arrays.
  double loneSeconds = 0;        ///< one thread alone: the small first rounds and the deferred insertions
  double concurrentSeconds = 0;  ///< wall time of the concurrent rounds' pieces (the slabs' cuts included)
  double busySeconds = 0;        ///< the threads' time inside their pieces, summed over the threads
  double finishSeconds = 0;      ///< the output (fast::finish)
};

/// How the threads of a concurrent round keep out of each other's triangles (parallel page).
enum class ParallelClaim {
  Slabs,  ///< each thread owns a slab of the plane and takes only triangles inside it: no atomics
  Locks,  ///< a try-lock (compare-and-swap) per triangle read or written
};

/// The number of threads `--threads` means by default: the machine's hardware threads (at least 1).
int defaultThreadCount();

/// Going further (parallel page): DT(S) of xy = x0 y0 x1 y1 ... with `threads` threads. threads
/// <= 1 calls fastDelaunay(xy, opt) itself. Otherwise the small first BRIO rounds (opt.order
/// must be FastOrder::RadixBrio) are inserted by one thread, and each larger round is shared
/// among `threads` threads (claim: Slabs, each thread the round's points in one slab of x, cut
/// at the x-quantiles of a sample of the round, in Hilbert order; Locks, consecutive pieces of the round's
/// Hilbert order), inserted concurrently; insertions that need another thread's triangles are
/// redone by one thread after the round. The result is the
/// exact DT(S) whenever it is unique (points in general position: then equal to fastDelaunay's),
/// otherwise a Delaunay triangulation of S (checkDelaunay validates it); duplicates are merged
/// into the smallest-numbered equal point, as fastDelaunay does; opt.insertionNumbering is
/// honoured, and opt.progress is called by the calling thread only (during a concurrent round
/// with estimated counts: its own piece's, times the number of threads). Same exceptions as
/// fastDelaunay, and std::invalid_argument for a ladder switch or another order when threads >
/// 1. A round is
/// inserted concurrently when each thread gets at least minPiece points of it (the tests make it
/// small, to make threads meet on small inputs).
FastResult fastDelaunayParallel(const std::vector<double>& xy, int threads,
                                const FastOptions& opt = {}, ParallelStats* pstats = nullptr,
                                int minPiece = 2048, ParallelClaim claim = ParallelClaim::Slabs);

/// The parallel kernel's machinery run by one thread, for measurement: the same rounds, relaxed
/// atomic access, claim (one slab, the whole plane, or the locks) and deferred insertions as
/// fastDelaunayParallel, with no second thread. Its time against fastDelaunay's is what sharing
/// costs by itself, apart from what a second thread adds (bench_parallel's budget table).
/// Same result and exceptions as fastDelaunayParallel.
FastResult fastDelaunaySharedCoreAlone(const std::vector<double>& xy, const FastOptions& opt = {},
                                       ParallelStats* pstats = nullptr,
                                       ParallelClaim claim = ParallelClaim::Slabs);

}  // namespace dt
