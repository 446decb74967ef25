// The library's entry point: DT(S) of a point set, with the choices the command line offers
// (method, order, kernel, threads, check). The command line, the benchmarks and the tests call
// it; the chapters call the pieces (fast_delaunay.h, triangulate.h, flip.h) to show each one.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "order.h"
#include "tri.h"

namespace dt {

/// How DT(S) is built.
enum class BuildMethod {
  Hull,  ///< a first triangle closed by ghost faces, points outside the hull inserted directly (2.2.2)
  Super  ///< super-triangles, then DT(S) recovered from DT(S0 u S) by flips (2.2.1, 2.3.6); listings
};

/// Which data structure inserts.
enum class KernelChoice {
  Fast,     ///< fast_delaunay.h (index arrays, inlined predicates); fast_parallel.h if threads > 1
  Listings  ///< the corrected Listings 2.4-2.7 (triangulate.h); always used by BuildMethod::Super
};

/// Options of triangulate.
struct TriangulateOptions {
  BuildMethod method = BuildMethod::Hull;
  InsertionOrder order = InsertionOrder::Brio;
  KernelChoice kernel = KernelChoice::Fast;
  /// Threads of the fast kernel with InsertionOrder::Brio (1: the sequential kernel); more are
  /// used only where fast_parallel.h's cost model says they pay (TriangulateResult::threadsUsed).
  int threads = 1;
  /// Validate the result with checkDelaunay (exact); a failure throws std::logic_error.
  bool check = true;
  /// Called when a phase starts ("triangulating N points (fast kernel)", "checking ..."), with
  /// the number of points it concerns; not called if empty.
  std::function<void(const std::string& phase, std::size_t points)> phase;
  /// Called during the insertions with the points inserted so far, their total, and the sums of
  /// the walks' and the cavities' triangles so far; not called if empty.
  std::function<void(std::size_t done, std::size_t total, std::uint64_t walkSteps,
                     std::uint64_t cavityFaces)>
      progress;
};

/// The result. The triangles index `xy`, which holds the points in the kernel's order; `input`
/// maps them back to the input.
struct TriangulateResult {
  std::vector<double> xy;  ///< x0 y0 x1 y1 ...: the points in the mesh's numbering
  std::vector<Tri> tri;    ///< DT(S), counter-clockwise triangles indexing xy
  std::vector<int> input;  ///< input[i]: the input index of point i of xy
  /// used[i]: point i of xy is a vertex (a merged duplicate is not). Empty: every point is.
  std::vector<char> used;
  /// (input index of a merged duplicate, input index of the point kept), sorted; of equal
  /// points the smallest-numbered one is kept.
  std::vector<std::pair<int, int>> duplicates;
  std::uint64_t insertions = 0;   ///< points inserted (duplicates excluded)
  std::uint64_t walkSteps = 0;    ///< triangles visited by the walks, summed
  std::uint64_t cavityFaces = 0;  ///< triangles of the cavities, summed
  std::uint64_t recoveryFlips = 0;  ///< Super: the flips that recovered DT(S)
  double seconds = 0;  ///< points in memory to DT(S), the order's sort included (no check)
  /// Of `seconds`, the CPU time of the operating system for this process (in a fresh process
  /// mostly the mapping of new memory: page faults, pages cleared); -1 where it is not known.
  double systemSeconds = -1;
  bool checked = false;  ///< checkDelaunay passed (options.check)
  int threadsUsed = 1;   ///< threads that inserted (fast_parallel.h's cost model decides)
  /// Why that many: dt::parallelReasonName of the reason (fast_parallel.h).
  std::string threadsReason = "one_thread_requested";
};

/// The input is valid but the method cannot handle it (BuildMethod::Super on points too close to the
/// overflow threshold to be enclosed); `point` is the input index of the farthest point.
struct UnsupportedInput : std::runtime_error {
  UnsupportedInput(const std::string& what, std::size_t p) : std::runtime_error(what), point(p) {}
  std::size_t point;
};

/// DT(S) of the points xy = x0 y0 x1 y1 ... (moved in: its memory is reused for the result),
/// exact for every input of finite doubles. Duplicates are merged. Throws DegenerateInput
/// (triangulate.h) if there are fewer than three distinct points or all are collinear,
/// std::invalid_argument on non-finite coordinates, UnsupportedInput (above), and
/// std::logic_error if the check fails (a bug).
TriangulateResult triangulate(std::vector<double> xy, const TriangulateOptions& options = {});

/// The CPU time the operating system has spent for this process so far (ru_stime of getrusage),
/// in seconds; -1 where it is not known (WebAssembly). TriangulateResult::systemSeconds is a
/// difference of two readings.
double systemSeconds();

/// The option words of the command line: "hull"/"super", "fast"/"listings" (the orders' words:
/// order.h). Throws std::invalid_argument on any other word.
BuildMethod methodNamed(const std::string& word);
KernelChoice kernelNamed(const std::string& word);

}  // namespace dt
