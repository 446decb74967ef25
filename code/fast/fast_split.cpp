#include "fast_split.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <unordered_set>

#include "errors.h"
#include "fast_core.h"
#include "hilbert.h"

namespace dt {
namespace fast {

//! [diskInSlab]
// Whether the circle of centre o = (Nx, Ny) / D (relative to a point A) and radius |N| / |D|
// stays strictly before a cut at distance w from A along the direction of sign s (+1: the cut
// is at x = A_x + w, o_x counted +; -1: at A_x - w): w |D| - s sgn(D) Nx > |N|, squared, with a
// relative margin of 1e-8 on the squares, far above the rounding error (diskInSlab).
__attribute__((always_inline)) inline bool beforeCut(double w, double absD, double sNx, double N2) {
  const double L = w * absD - sNx;
  return L > 0 && L * L > N2 * (1 + 1e-8);
}

__attribute__((always_inline)) inline bool diskInSlabInline(const double* a, const double* b,
                                                            const double* c, double lo, double hi) {
  double bx = b[0] - a[0], by = b[1] - a[1], cx = c[0] - a[0], cy = c[1] - a[1];
  double wl = a[0] - lo, wh = hi - a[0];  // the cuts' distances from a
  const double m = std::max(std::max(std::fabs(bx), std::fabs(by)), std::max(std::fabs(cx), std::fabs(cy)));
  // Far from overflow and underflow (the products below reach m^6), the differences are used as
  // they are; otherwise everything is brought to the triangle's scale, a power of two (exact).
  if (!(m > 0x1p-160 && m < 0x1p160)) {
    if (!(m > 0) || !std::isfinite(m)) return false;
    int e = 0;
    std::frexp(m, &e);  // m = f 2^e with 1/2 <= f < 1
    bx = std::ldexp(bx, -e), by = std::ldexp(by, -e), cx = std::ldexp(cx, -e), cy = std::ldexp(cy, -e);
    wl = std::ldexp(wl, -e), wh = std::ldexp(wh, -e);
  }
  const double b2 = bx * bx + by * by, c2 = cx * cx + cy * cy, D = 2 * (bx * cy - by * cx);
  // The centre of a sliver moves far with a rounding of its corners: not judged (false). Else
  // the centre's rounding error is below 1e-12 of the radius (the angle at a has a sine of at
  // least 1e-3).
  if (!(D * D >= 4e-6 * (b2 * c2))) return false;
  const double Nx = cy * b2 - by * c2, Ny = bx * c2 - cx * b2, N2 = Nx * Nx + Ny * Ny;
  const double absD = std::fabs(D), sNx = D > 0 ? Nx : -Nx;
  return (lo == -HUGE_VAL || beforeCut(wl, absD, -sNx, N2)) &&
         (hi == HUGE_VAL || beforeCut(wh, absD, sNx, N2));  // false for a value that is not finite
}

bool diskInSlab(const double* a, const double* b, const double* c, double lo, double hi) {
  return diskInSlabInline(a, b, c, lo, hi);
}
//! [diskInSlab]

namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point t) {
  return std::chrono::duration<double>(Clock::now() - t).count();
}

std::uint64_t edgeKey(int a, int b) {
  return std::uint64_t(std::uint32_t(a)) << 32 | std::uint32_t(b);
}

// The points of P (the whole run's, in insertion order) whose numbers are listed in ids, in
// that order, and a dummy point for the vertex at infinity: a store's point array.
std::vector<double> pointsOf(const std::vector<double>& P, const std::vector<int>& ids) {
  std::vector<double> Q;
  Q.reserve(2 * ids.size() + 2);
  for (int j : ids) {
    Q.push_back(P[2 * std::size_t(j)]);
    Q.push_back(P[2 * std::size_t(j) + 1]);
  }
  Q.push_back(0);
  Q.push_back(0);
  return Q;
}

// One part: the points of the slab lo <= x < hi, triangulated alone; what the merge needs of it.
struct alignas(64) Part {
  double lo = 0, hi = 0;
  std::vector<int> ids;  // the part's points: their numbers in the run's insertion order
  FastStats stats;
  std::vector<std::pair<int, int>> dups;  // (point, vertex it duplicates), run's numbers
  std::vector<Tri> safe;                  // the safe triangles (below), run's numbers
  std::vector<std::uint64_t> seam;        // edgeKey(a, b): a safe triangle left of a -> b, none right
  bool degenerate = false;                // fewer than 3 points, or all on a line
  double busySeconds = 0;
};

//! [partSafe]
// The part's triangulation T, from its store, sorted for the merge. A triangle of T is safe when
// its closed circumdisk lies inside the part's open slab: no point of another part is in it, so
// it is a triangle of DT(S). Every other face of T (a ghost too) puts its vertices in B (inB,
// indexed by the run's numbers; each part writes its own points' entries). The safe triangles
// are kept, with their edges to a face that is not safe: the seam (book/parallel.md).
void sortPart(Part& part, const Store& S, const double* Q, std::vector<unsigned char>& inB) {
  const std::size_t count = std::size_t(S.count.load(std::memory_order_relaxed));
  const int INF = S.INF;
  const std::vector<int>& id = part.ids;
  auto pt = [Q](int v) { return Q + 2 * std::size_t(v); };
  auto toB = [&](const Tri& w) {
    for (int v : w)
      if (v != INF) inB[std::size_t(id[std::size_t(v)])] = 1;
  };
  std::vector<unsigned char> safe(count, 0);
  for (std::size_t t = 0; t < count; ++t) {
    const Tri& w = S.V[t];
    if (w[2] == INF)  // a ghost (or a slot no triangle uses, all INF)
      toB(w);
    else if (diskInSlabInline(pt(w[0]), pt(w[1]), pt(w[2]), part.lo, part.hi))
      safe[t] = 1;
    else
      toB(w);
  }
  part.safe.reserve(count);
  for (std::size_t t = 0; t < count; ++t) {
    if (!safe[t]) continue;
    const Tri& w = S.V[t];
    part.safe.push_back({id[std::size_t(w[0])], id[std::size_t(w[1])], id[std::size_t(w[2])]});
    for (int k = 0; k < 3; ++k)
      if (!safe[std::size_t(S.A[3 * t + std::size_t(k)] / 3)])
        part.seam.push_back(edgeKey(id[std::size_t(w[std::size_t(k)])], id[std::size_t(w[std::size_t((k + 1) % 3)])]));
  }
}
//! [partSafe]

// Thread k's work: gather the slab's points (in the run's order), triangulate them with the
// one-thread core, sort the triangles. tick(i, stats) reports progress (the calling thread's
// part only).
template <class Tick>
void runPart(Part& part, const std::vector<double>& P, int n, bool v3, std::size_t every,
             std::vector<unsigned char>& inB, Tick tick) {
  const auto t0 = Clock::now();
  for (int j = 0; j < n; ++j) {
    const double x = P[2 * std::size_t(j)];
    if (x >= part.lo && x < part.hi) part.ids.push_back(j);
  }
  const std::vector<double> Q = pointsOf(P, part.ids);
  const int m = int(part.ids.size());
  FirstTriangle f{};
  try {
    if (m < 3) throw DegenerateInput("fewer than 3 points in a part");
    f = firstTriangle(Q, m);
  } catch (const DegenerateInput&) {
    part.degenerate = true;
    return;
  }
  const std::size_t slots = slotsFor(std::size_t(m));
  Store S(Q.data(), m, slots, 1, adjacencyMemory(slots, std::size_t(m)));
  std::vector<std::pair<int, int>> dups;
  insertAlone<InlinePredicates>(S, f, InlinePredicates{&part.stats}, Build{v3, true}, part.stats,
                                dups, every, [&](int i) { tick(i, part.stats); });
  for (auto [i, d] : dups) part.dups.emplace_back(part.ids[std::size_t(i)], part.ids[std::size_t(d)]);
  sortPart(part, S, Q.data(), inB);
  part.busySeconds = secondsSince(t0);
}

//! [mergeSeam]
// The triangles of DT(B) outside the safe triangles' union U, appended to out (run's numbers);
// false if the seam does not separate DT(B) as it must (the caller then falls back). Every seam
// edge is an edge of DT(B) (sortPart), and cuts it into triangles inside U and outside: a
// triangle on the left of a seam edge a -> b is inside, one on its right outside, and the labels
// spread across the edges that are not on the seam.
bool mergeSeam(const std::vector<double>& P, const std::vector<int>& bid,
               const std::unordered_set<std::uint64_t>& seam, bool v3, FastStats& st,
               std::vector<Tri>& out) {
  const int m = int(bid.size());
  if (m < 3) return false;
  const std::vector<double> Q = pointsOf(P, bid);
  FirstTriangle f{};
  try {
    f = firstTriangle(Q, m);
  } catch (const DegenerateInput&) {
    return false;
  }
  const std::size_t slots = slotsFor(std::size_t(m));
  Store S(Q.data(), m, slots, 1, adjacencyMemory(slots, std::size_t(m)));
  std::vector<std::pair<int, int>> dups;
  FastStats own;  // B's insertions are not the run's insertions; their predicates are counted
  insertAlone<InlinePredicates>(S, f, InlinePredicates{&own}, Build{v3, true}, own, dups,
                                std::size_t(-1), [](int) {});
  st.walkSteps += own.walkSteps;
  st.cavityFaces += own.cavityFaces;
  st.orient += own.orient;
  st.incircle += own.incircle;
  if (!dups.empty()) return false;  // B holds vertices of triangulations: distinct points
  const std::size_t count = std::size_t(S.count.load(std::memory_order_relaxed));
  const int INF = S.INF;
  enum : unsigned char { kUnknown, kInside, kOutside };
  std::vector<unsigned char> label(count, kUnknown);
  std::vector<int> stack;
  std::unordered_set<std::uint64_t> met;  // the seam edges found in DT(B), as a -> b of the seam
  auto key = [&](const Tri& w, int k) {
    return edgeKey(bid[std::size_t(w[std::size_t(k)])], bid[std::size_t(w[std::size_t((k + 1) % 3)])]);
  };
  auto reverse = [](std::uint64_t e) { return e << 32 | e >> 32; };
  for (std::size_t t = 0; t < count; ++t) {
    const Tri& w = S.V[t];
    if (w[2] == INF) continue;
    for (int k = 0; k < 3; ++k) {
      const std::uint64_t e = key(w, k);
      unsigned char want = kUnknown;
      if (seam.count(e)) {
        want = kInside;
        met.insert(e);
      } else if (seam.count(reverse(e))) {
        want = kOutside;
        met.insert(reverse(e));
      }
      if (want == kUnknown) continue;
      if (label[t] != kUnknown && label[t] != want) return false;
      if (label[t] == kUnknown) stack.push_back(int(t));
      label[t] = want;
    }
  }
  if (met.size() != seam.size()) return false;  // a seam edge is not in DT(B)
  while (!stack.empty()) {
    const std::size_t t = std::size_t(stack.back());
    stack.pop_back();
    const Tri& w = S.V[t];
    for (int k = 0; k < 3; ++k) {
      const std::uint64_t e = key(w, k);
      if (seam.count(e) || seam.count(reverse(e))) continue;
      const std::size_t nb = std::size_t(S.A[3 * t + std::size_t(k)] / 3);
      if (S.V[nb][2] == INF) continue;
      if (label[nb] == kUnknown) {
        label[nb] = label[t];
        stack.push_back(int(nb));
      } else if (label[nb] != label[t]) {
        return false;
      }
    }
  }
  for (std::size_t t = 0; t < count; ++t) {
    const Tri& w = S.V[t];
    if (w[2] == INF) continue;
    if (label[t] == kUnknown && !seam.empty()) return false;  // a piece no seam edge reaches
    if (label[t] != kInside)
      out.push_back({bid[std::size_t(w[0])], bid[std::size_t(w[1])], bid[std::size_t(w[2])]});
  }
  return true;
}
//! [mergeSeam]

}  // namespace

//! [splitAndMerge]
FastResult splitAndMerge(const std::vector<double>& xy, int threads, const FastOptions& opt,
                         bool v3, SplitReport& rep) {
  rep = SplitReport{};
  FastResult res;
  res.stats.x86_64_v3 = v3;
  const auto t0 = Clock::now();
  const std::size_t n = xy.size() / 2;
  const int N = int(n);
  std::vector<int> orig;
  {
    RawMemory scratch(::operator new(brioCoinScratchBytes(n)));
    const std::size_t* o = brioCoinOrderInto(xy, opt.seed, std::max(1, std::min(opt.rounds, 32)),
                                             scratch.get(), true, threads);
    orig.assign(o, o + n);
  }
  std::vector<double> P = pointsInOrder(xy, orig, threads);
  res.stats.sortSeconds = secondsSince(t0);

  // The slabs: cut at x-quantiles of an evenly spaced sample of the order (about 4096 points).
  std::vector<double> xs;
  for (std::size_t j = 0; j < n; j += std::max<std::size_t>(1, n / 4096)) xs.push_back(P[2 * j]);
  std::vector<Part> parts(static_cast<std::size_t>(threads));
  std::vector<double> cut(std::size_t(threads) + 1, -HUGE_VAL);
  cut[std::size_t(threads)] = HUGE_VAL;
  for (int k = 1; k < threads; ++k) {
    auto q = xs.begin() + std::ptrdiff_t(xs.size() * std::size_t(k) / std::size_t(threads));
    std::nth_element(xs.begin(), q, xs.end());
    cut[std::size_t(k)] = *q;
    if (!(cut[std::size_t(k)] > cut[std::size_t(k) - 1])) return res;  // an empty slab: not merged
  }
  for (int k = 0; k < threads; ++k) {
    parts[std::size_t(k)].lo = cut[std::size_t(k)];
    parts[std::size_t(k)].hi = cut[std::size_t(k) + 1];
  }
  // The parts, a thread each. Progress comes from the calling thread's part, scaled.
  std::vector<unsigned char> inB(n, 0);
  const std::size_t every = opt.progress ? std::max<std::size_t>(1, opt.progressEvery) : std::size_t(-1);
  const auto tp = Clock::now();
  parallelFor(threads, std::size_t(threads), [&](int, std::size_t lo, std::size_t hi) {
    for (std::size_t k = lo; k < hi; ++k)
      runPart(parts[k], P, N, v3, k == 0 ? every : std::size_t(-1), inB, [&](int i, const FastStats& s) {
        FastStats scaled = s;
        scaled.insertions *= std::uint64_t(threads);
        scaled.walkSteps *= std::uint64_t(threads);
        scaled.cavityFaces *= std::uint64_t(threads);
        opt.progress(std::min(n, std::size_t(i) * std::size_t(threads)), n, scaled);
      });
  });
  rep.partsSeconds = secondsSince(tp);
  for (const Part& part : parts) {
    if (part.degenerate) return res;
    rep.busySeconds += part.busySeconds;
  }

  // The seam: B, its triangulation, the triangles of it outside the safe ones.
  const auto tm = Clock::now();
  std::vector<int> bid;
  for (int j = 0; j < N; ++j)
    if (inB[std::size_t(j)]) bid.push_back(j);
  std::vector<unsigned char>().swap(inB);
  rep.border = bid.size();
  std::unordered_set<std::uint64_t> seam;
  for (Part& part : parts) {
    seam.insert(part.seam.begin(), part.seam.end());
    std::vector<std::uint64_t>().swap(part.seam);
  }
  std::vector<Tri> kept;
  if (!mergeSeam(P, bid, seam, v3, res.stats, kept)) return res;
  rep.mergeSeconds = secondsSince(tm);

  // The output: the parts' safe triangles and the kept ones, through the kernels' finish.
  const auto tf = Clock::now();
  std::vector<std::size_t> at(parts.size() + 1, 0);
  for (std::size_t k = 0; k < parts.size(); ++k) at[k + 1] = at[k] + parts[k].safe.size();
  std::vector<Tri> V(at.back() + kept.size());
  parallelFor(threads, parts.size(), [&](int, std::size_t lo, std::size_t hi) {
    for (std::size_t k = lo; k < hi; ++k) {
      std::copy(parts[k].safe.begin(), parts[k].safe.end(), V.begin() + std::ptrdiff_t(at[k]));
      std::vector<Tri>().swap(parts[k].safe);
    }
  });
  std::copy(kept.begin(), kept.end(), V.begin() + std::ptrdiff_t(at.back()));
  std::vector<std::pair<int, int>> dups;
  for (const Part& part : parts) {
    res.stats.insertions += part.stats.insertions;
    res.stats.walkSteps += part.stats.walkSteps;
    res.stats.cavityFaces += part.stats.cavityFaces;
    res.stats.orient += part.stats.orient;
    res.stats.incircle += part.stats.incircle;
    dups.insert(dups.end(), part.dups.begin(), part.dups.end());
  }
  const std::size_t count = V.size();
  finish(V, count, N, P, orig, dups, opt.insertionNumbering, threads, res);
  rep.finishSeconds = secondsSince(tf);
  rep.merged = true;
  res.stats.insertSeconds = secondsSince(t0) - res.stats.sortSeconds;
  return res;
}
//! [splitAndMerge]

}  // namespace fast
}  // namespace dt
