// The vocabulary of the fast kernel: its options, counters and result. Apart from
// fast_delaunay.h so that the kernel's internals (fast_core.h) use them without including the
// entry points that include the internals.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <utility>
#include <vector>

#include "order.h"
#include "predicate_stages.h"
#include "tri.h"

namespace dt {

struct FastStats;

/// Options of fastDelaunay: what a user of the library chooses. The predicates, the walk, the
/// link step and the build are policies of the insertion core (fast_core.h), not options.
struct FastOptions {
  InsertionOrder order = InsertionOrder::Brio;
  int rounds = 8;                  ///< Brio: number of rounds (1 = a plain Hilbert sort)
  std::uint64_t seed = 1;          ///< seed of the BRIO rounds
  /// Called after every `progressEvery` insertions with the points handled so far, their number
  /// and the counters so far (the command line's progress report and its warning about long
  /// walks); not called if empty.
  std::function<void(std::size_t done, std::size_t total, const FastStats& st)> progress;
  std::size_t progressEvery = 4096;
  /// Number the output triangles' vertices in insertion order instead of as the input, and
  /// return the points in that order (FastResult::points, inserted): a check or a writer then
  /// reads memory in the kernel's spatially coherent order (the command line does).
  bool insertionNumbering = false;
};

/// Counters and timings of one run.
struct FastStats {
  std::uint64_t insertions = 0;   ///< points inserted (duplicates excluded)
  std::uint64_t walkSteps = 0;    ///< triangles visited by the walks, summed
  std::uint64_t cavityFaces = 0;  ///< triangles of the cavities, summed
  pred::StageCounts orient;       ///< orientation tests, by the stage that decided them
  pred::StageCounts incircle;     ///< incircle tests, by the stage that decided them
  double sortSeconds = 0;         ///< computing the insertion order
  double insertSeconds = 0;       ///< the insertions (and the output)
  bool x86_64_v3 = false;         ///< the insertions ran in the x86-64-v3 build (fast_core.h)
};

/// The result: counter-clockwise triangles as index triples into the input points.
struct FastResult {
  std::vector<Tri> tri;
  /// (duplicate, kept): every input point that was merged into an earlier-numbered equal point.
  std::vector<std::pair<int, int>> duplicates;
  FastStats stats;
  /// With FastOptions::insertionNumbering: the points in insertion order (x0 y0 x1 y1 ...) and
  /// the input number of each; the triangles index them. Otherwise empty.
  std::vector<double> points;
  std::vector<int> inserted;
};

}  // namespace dt
