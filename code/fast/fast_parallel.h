// Going further: the fast kernel on several cores, for inputs where one core's insertion time
// dominates. By default (ParallelClaim::Parts, fast_split.h) each thread triangulates the points
// of one slab of x with the one-thread core, and one thread merges the parts along the cuts.
// Two earlier designs run the same Bowyer-Watson insertion (fast_core.h, with other policies)
// by several threads on one shared triangulation: each thread owns a slab of the plane for the
// round and takes only the triangles with all three vertices in it (no lock), or locks every
// triangle an insertion reads or writes with a try-lock; an insertion that cannot take a
// triangle it needs gives up and is redone after the round, alone. Why each gives DT(S):
// book/parallel.md.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "fast_delaunay.h"

namespace dt {

/// Why fastDelaunayParallel ran the number of threads it did (ParallelStats::reason). Its
/// name, for --stats and the tables: parallelReasonName.
enum class ParallelReason {
  Concurrent,      ///< "concurrent": the larger rounds were shared among the threads
  OneRequested,    ///< "one_thread_requested": one thread was asked for
  OneCore,         ///< "one_core": the machine has one hardware thread
  TooFewPoints,    ///< "too_few_points": fewer than ParallelModel::minPointsPerThread per thread
  SlabsDoNotSplit, ///< "slabs_do_not_split": a sample's triangles cross the slab cuts too often
  SequentialOnly,  ///< "sequential_order_or_kernel": an order or kernel that has no parallel form
  SeamNotMerged,   ///< "seam_not_merged": a part was degenerate or the seam did not merge; the
                   ///< sequential kernel ran after the parts (ParallelClaim::Parts)
};

/// The name of a reason: lower case, words joined by '_' (the enum's documentation gives each).
const char* parallelReasonName(ParallelReason r);

/// Whether the threads a call asks for are used whatever the input (the tests of the concurrent
/// rounds) or only where the cost model of ParallelModel says they pay (the default).
enum class ParallelMode {
  WherePays,  ///< the cost model decides: the sequential kernel below its size or on poor splits
  Always,     ///< the concurrent rounds, whatever the size and the input (tests, bench_parallel)
};

/// The cost model's inputs, measured on this project's benchmarks (the parallel page shows
/// them and the table that checks them). A second thread pays only when (1) each thread gets
/// at least minPointsPerThread points: below that the fixed costs of the threads (starting
/// them, gathering and sorting each part, the seam's triangulation, the output) outweigh the
/// shared insertions; and (2) the slabs split the mesh: a sample of sampleSize points is
/// triangulated by the sequential kernel and cut at the x-quantiles the parts would use, and
/// the share of its vertices on a triangle that crosses a cut or on the hull (a stand-in for
/// the seam's points B, which one thread triangulates again) is at most maxCutShareRatio times
/// what uniform points give.
struct ParallelModel {
  static constexpr std::size_t minPointsPerThread = 50000;
  static constexpr std::size_t sampleSize = 2048;
  /// A first sample of glanceSize points decides alone when at least glanceHopeless of its
  /// vertices are on a triangle across a cut or on the hull (uniform points: about a fifth).
  static constexpr std::size_t glanceSize = 256;
  static constexpr double glanceHopeless = 0.9;
  static constexpr double maxCutShareRatio = 6.0;
};

/// The predictor of how well slabs split a point set (ParallelModel, (2)).
struct SplitForecast {
  double cutShare = 0;         ///< share of the sample's vertices on a triangle across a cut
  double uniformCutShare = 0;  ///< the same for a uniform sample of the same size
  double ratio = 0;            ///< cutShare / uniformCutShare
};

/// The forecast for xy cut into `threads` slabs; a sample with no triangulation (all collinear,
/// fewer than three distinct points) gives cutShare 1.
SplitForecast forecastSplit(const std::vector<double>& xy, int threads);

/// What the cost model decides for xy with `threads` threads asked for (mode WherePays), and
/// the forecast it used (zero when the size or the cores decided first).
struct ThreadDecision {
  int threads = 1;
  ParallelReason reason = ParallelReason::OneRequested;
  SplitForecast forecast;
};
ThreadDecision decideThreads(const std::vector<double>& xy, int threads);

/// What the parallel run did, beside the FastStats of the result.
struct ParallelStats {
  int threadsRequested = 1;           ///< threads the call asked for
  int threadsUsed = 1;                ///< threads used (1: the sequential kernel was called)
  ParallelReason reason = ParallelReason::OneRequested;  ///< why threadsUsed threads
  SplitForecast forecast;             ///< the cost model's forecast, when it was made
  double decisionSeconds = 0;         ///< time the cost model took (the sample's triangulation)
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
  // Parts only: the seam's points (the set B of book/parallel.md) and the merge's wall time;
  // concurrentSeconds is then the parts' wall time, loneSeconds the merge's.
  std::uint64_t borderPoints = 0;  ///< points re-triangulated along the seams
};

/// How the threads share the work (parallel page). Parts, the default, is divide and merge;
/// Slabs and Locks are the two designs of one shared triangulation, kept for the comparison.
enum class ParallelClaim {
  Parts,  ///< each thread triangulates one slab's points alone; one thread merges the seams
  Slabs,  ///< shared: each thread owns a slab of the plane and takes only triangles inside it
  Locks,  ///< shared: a try-lock (compare-and-swap) per triangle read or written
};

/// The machine's hardware threads (at least 1): what `--threads auto` asks for, and the most the
/// cost model of fastDelaunayParallel uses.
int defaultThreadCount();

/// Going further (parallel page): DT(S) of xy = x0 y0 x1 y1 ... with up to `threads` threads.
/// With mode WherePays (the default) the cost model (decideThreads, ParallelModel) picks the
/// number: at most the machine's hardware threads, and the sequential kernel (fastDelaunay
/// itself) below the model's size or where the slabs would not split; pstats says which and
/// why. threads <= 1 calls fastDelaunay(xy, opt). opt.order must be InsertionOrder::Brio.
/// With more than one thread:
///  - claim Parts (the default): the points are cut into one slab of x per thread (at the
///    x-quantiles of a sample); each thread triangulates its slab's points, in the run's order,
///    with the one-thread core; the triangles whose circumdisk lies inside their slab are kept,
///    and one thread triangulates the vertices of the others (the set B) and keeps the triangles
///    of DT(B) outside the kept ones. If a slab's points are all on a line, or the seam does not
///    separate DT(B) as it must, the sequential kernel runs (reason SeamNotMerged);
///  - claims Slabs and Locks (one shared triangulation): the small first BRIO rounds are
///    inserted by one thread, and each larger round is shared among the threads (Slabs: each
///    thread the round's points in one slab of x; Locks: consecutive pieces of the round's
///    Hilbert order), inserted concurrently; insertions that need another thread's triangles
///    are redone by one thread after the round. A round is inserted concurrently when each
///    thread gets at least minPiece points of it (the tests make it small).
/// The result is the exact DT(S) whenever it is unique (points in general position: then the
/// same triangles as fastDelaunay's, perhaps in another order), otherwise a Delaunay
/// triangulation of S (checkDelaunay validates it); duplicates are merged into the
/// smallest-numbered equal point, as fastDelaunay does; opt.insertionNumbering is honoured, and
/// opt.progress is called by the calling thread only, with estimated counts (its own part's or
/// piece's, times the number of threads). Same exceptions as fastDelaunay, and
/// std::invalid_argument for another order when threads > 1. The mode Always runs the threads
/// whatever the size and the input (the tests, to make threads meet on small inputs).
FastResult fastDelaunayParallel(const std::vector<double>& xy, int threads,
                                const FastOptions& opt = {}, ParallelStats* pstats = nullptr,
                                int minPiece = 2048, ParallelClaim claim = ParallelClaim::Parts,
                                ParallelMode mode = ParallelMode::WherePays);

/// The parallel kernel's machinery run by one thread, for measurement: the same rounds, relaxed
/// atomic access, claim (one slab, the whole plane, or the locks) and deferred insertions as
/// fastDelaunayParallel, with no second thread. Its time against fastDelaunay's is what sharing
/// costs by itself, apart from what a second thread adds (bench_parallel's budget table).
/// Same result and exceptions as fastDelaunayParallel; claim Parts is refused
/// (std::invalid_argument: it has no shared machinery).
FastResult fastDelaunaySharedCoreAlone(const std::vector<double>& xy, const FastOptions& opt = {},
                                       ParallelStats* pstats = nullptr,
                                       ParallelClaim claim = ParallelClaim::Slabs);

}  // namespace dt
