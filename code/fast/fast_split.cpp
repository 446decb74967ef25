#include "fast_split.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <memory>
#include <unordered_map>
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

// One part: the points of the slab lo <= x < hi, triangulated alone; what the merge needs of it.
struct alignas(64) Part {
  double lo = 0, hi = 0;
  std::vector<double> Q;  // its points in its insertion order, and the dummy point of INF
  std::vector<int> inNo;  // the input number of each (of the kept one, for merged duplicates)
  std::size_t offset = 0;  // where its points start in the run's insertion order
  std::unique_ptr<Store> S;  // its triangulation T, kept until the output is written
  std::vector<unsigned char> safe;  // of each slot of T: a safe triangle (classifyPart)
  std::size_t safeCount = 0;
  FastStats stats;
  double sortSeconds = 0, busySeconds = 0;
  std::vector<std::pair<int, int>> named;  // (input number of a duplicate, vertex of Q kept)
  std::vector<std::uint64_t> seam;         // edgeKey(a, b) in input numbers: safe on the left only
  std::vector<int> border;                 // its vertices in B (vertices of Q)
  bool degenerate = false;                 // fewer than 3 points, or all on a line
};

//! [partSafe]
// The part's triangulation T, from its store, classified for the merge. A triangle of T is safe when
// its closed circumdisk lies inside the part's open slab: no point of another part is in it, so
// it is a triangle of DT(S). Every other face of T (a ghost too) puts its vertices in B (the
// part's list border, each vertex once). The safe triangles
// are kept, with their edges to a face that is not safe: the seam (book/parallel.md).
//
// Only the triangles near T's hull are tested. A triangle t whose closed circumdisk D meets the
// complement of the open slab (at a point q) is joined to the hull by triangles like it: walk
// from inside t to q. q is outside T's hull, or on it (a point on x = lo); each triangle the
// walk enters has q in its closed circumdisk too, since across a Delaunay edge the neighbour's
// disk holds the part of D beyond the edge. So a search from the ghosts' neighbours, which goes
// on only across the triangles diskInSlab does not call safe, meets every triangle that is not
// safe; those it never reaches are safe without a test. (diskInSlab never calls safe a disk
// that is not: the triangles it doubts are only more triangles the search crosses.)
void classifyPart(Part& part) {
  const Store& S = *part.S;
  const std::size_t count = std::size_t(S.count.load(std::memory_order_relaxed));
  const int INF = S.INF;
  auto pt = [&](int v) { return part.Q.data() + 2 * std::size_t(v); };
  std::vector<unsigned char> inB(part.inNo.size(), 0);
  auto toB = [&](const Tri& w) {
    for (int v : w)
      if (v != INF && !inB[std::size_t(v)]) {
        inB[std::size_t(v)] = 1;
        part.border.push_back(v);
      }
  };
  // safe[t]: 0 a face that is not safe (or an unused slot), 1 a triangle not reached (safe),
  // 2 a triangle tested and safe.
  part.safe.assign(count, 0);
  std::vector<int> unsafe;  // the faces that are not safe, ghosts included: few (near the cuts and the hull)
  std::vector<int> toTest;  // triangles to test: the ghosts' neighbours, then the neighbours of those not safe
  std::size_t triangles = 0, notSafe = 0;  // triangles of T; of them, those found not safe
  for (std::size_t t = 0; t < count; ++t) {
    const Tri& w = S.V[t];
    if (w[0] == INF) continue;  // a slot no triangle uses
    if (w[2] != INF) {
      part.safe[t] = 1;
      ++triangles;
    } else {
      toB(w);
      unsafe.push_back(int(t));
    }
  }
  auto reach = [&](int u) {
    for (int k = 0; k < 3; ++k) {
      const int nb = S.A[3 * std::size_t(u) + std::size_t(k)] / 3;
      if (part.safe[std::size_t(nb)] == 1) toTest.push_back(nb);
    }
  };
  for (int g : unsafe) reach(g);
  while (!toTest.empty()) {
    const int t = toTest.back();
    toTest.pop_back();
    if (part.safe[std::size_t(t)] != 1) continue;  // met twice
    const Tri& w = S.V[std::size_t(t)];
    if (diskInSlabInline(pt(w[0]), pt(w[1]), pt(w[2]), part.lo, part.hi)) {
      part.safe[std::size_t(t)] = 2;
    } else {
      part.safe[std::size_t(t)] = 0;
      ++notSafe;
      toB(w);
      unsafe.push_back(t);
      reach(t);
    }
  }
  part.safeCount = triangles - notSafe;
  const std::vector<int>& id = part.inNo;
  // The seam: each edge between a face that is not safe and a safe triangle, as the safe one
  // sees it (the reverse of the other's edge).
  for (int u : unsafe) {
    const Tri& w = S.V[std::size_t(u)];
    for (int k = 0; k < 3; ++k)
      if (part.safe[std::size_t(S.A[3 * std::size_t(u) + std::size_t(k)] / 3)])
        part.seam.push_back(edgeKey(id[std::size_t(w[std::size_t((k + 1) % 3)])], id[std::size_t(w[std::size_t(k)])]));
  }
}
//! [partSafe]

// Thread k's work: gather the slab's points, sort them (the one-thread kernel's order, in the
// memory of the adjacency array, as fastDelaunay does), triangulate them with the one-thread
// core, merge duplicates into the smallest input number, classify the triangles. tick(i, stats)
// reports progress (the calling thread's part only).
template <class Tick>
void runPart(Part& part, const std::vector<double>& xy, const FastOptions& opt, int threads, bool v3,
             std::size_t every, Tick tick) {
  const auto t0 = Clock::now();
  const std::size_t n = xy.size() / 2;
  std::vector<double> pts;
  std::vector<int> ids;
  pts.reserve(2 * (n / std::size_t(threads) + n / 16));
  ids.reserve(n / std::size_t(threads) + n / 16);
  for (std::size_t i = 0; i < n; ++i) {
    const double x = xy[2 * i];
    if (x >= part.lo && x < part.hi) {
      ids.push_back(int(i));
      pts.push_back(x);
      pts.push_back(xy[2 * i + 1]);
    }
  }
  const int m = int(ids.size());
  if (m < 3) {
    part.degenerate = true;
    return;
  }
  const std::size_t slots = slotsFor(std::size_t(m));
  RawMemory memA = adjacencyMemory(slots, std::size_t(m));
  std::vector<int> order;
  {
    const std::size_t* o = brioCoinOrderInto(pts, opt.seed, std::max(1, std::min(opt.rounds, 32)), memA.get());
    order.assign(o, o + m);
  }
  part.Q = pointsInOrder(pts, order, 1);
  part.inNo.resize(std::size_t(m));
  for (std::size_t j = 0; j < std::size_t(m); ++j) part.inNo[j] = ids[std::size_t(order[j])];
  std::vector<double>().swap(pts);
  std::vector<int>().swap(ids);
  std::vector<int>().swap(order);
  part.sortSeconds = secondsSince(t0);
  FirstTriangle f{};
  try {
    f = firstTriangle(part.Q, m);
  } catch (const DegenerateInput&) {
    part.degenerate = true;
    return;
  }
  part.S.reset(new Store(part.Q.data(), m, slots, 1, std::move(memA)));
  std::vector<std::pair<int, int>> dups;
  insertAlone<InlinePredicates>(*part.S, f, InlinePredicates{&part.stats}, Build{v3, true}, part.stats,
                                dups, every, [&](int i) { tick(i, part.stats); });
  // Equal points: the smallest input number names the vertex (fast::finish's rule).
  for (auto [i, d] : dups) {
    int& a = part.inNo[std::size_t(i)];
    int& b = part.inNo[std::size_t(d)];
    if (a < b) std::swap(a, b);
    part.named.emplace_back(a, d);
  }
  classifyPart(part);
  part.busySeconds = secondsSince(t0);
}

// Thread k's second task: its safe triangles, renumbered for the output, written at `at`; with
// insertion numbering, its points and input numbers too. Then its arrays are freed.
void writePart(Part& part, bool insertionNumbering, Tri* at, FastResult& res) {
  const Store& S = *part.S;
  const std::size_t count = part.safe.size();
  const int off = int(part.offset);
  for (std::size_t t = 0; t < count; ++t) {
    if (!part.safe[t]) continue;
    const Tri& w = S.V[t];
    *at++ = insertionNumbering ? Tri{off + w[0], off + w[1], off + w[2]}
                               : Tri{part.inNo[std::size_t(w[0])], part.inNo[std::size_t(w[1])],
                                     part.inNo[std::size_t(w[2])]};
  }
  if (insertionNumbering) {
    std::copy(part.Q.begin(), part.Q.end() - 2, res.points.begin() + 2 * std::ptrdiff_t(part.offset));
    std::copy(part.inNo.begin(), part.inNo.end(), res.inserted.begin() + std::ptrdiff_t(part.offset));
  }
  part.S.reset();
  std::vector<unsigned char>().swap(part.safe);
  std::vector<double>().swap(part.Q);
}

//! [mergeSeam]
// The triangles of DT(B) outside the safe triangles' union U, appended to out (input numbers);
// false if the seam does not separate DT(B) as it must (the caller then falls back). Each seam
// edge must be an edge of DT(B) (it is, unless the seam runs between cocircular points: checked
// here); the seam then cuts DT(B) into triangles inside U and outside: a triangle on the left of
// a seam edge a -> b is inside, one on its right outside, and the labels spread across the
// edges that are not on the seam (two labels for one triangle: false).
bool mergeSeam(const std::vector<double>& xy, std::vector<int> bid,
               const std::unordered_set<std::uint64_t>& seam, bool v3, FastStats& st,
               std::vector<Tri>& out) {
  const int m = int(bid.size());
  if (m < 3) return false;
  std::vector<double> Q;
  {
    std::vector<double> pts;
    pts.reserve(2 * bid.size());
    for (int j : bid) {
      pts.push_back(xy[2 * std::size_t(j)]);
      pts.push_back(xy[2 * std::size_t(j) + 1]);
    }
    const std::vector<std::size_t> o = brioCoinOrder(pts, 1);  // B's points, near ones together
    std::vector<int> order(o.begin(), o.end()), sorted(bid.size());
    for (std::size_t j = 0; j < sorted.size(); ++j) sorted[j] = bid[std::size_t(order[j])];
    bid.swap(sorted);
    Q = pointsInOrder(pts, order, 1);
  }
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

  // The slabs: cut at x-quantiles of an evenly spaced sample of the input (about 4096 points).
  std::vector<double> xs;
  for (std::size_t j = 0; j < n; j += std::max<std::size_t>(1, n / 4096)) xs.push_back(xy[2 * j]);
  std::vector<Part> parts(static_cast<std::size_t>(threads));
  std::vector<double> cut(std::size_t(threads) + 1, -HUGE_VAL);
  cut[std::size_t(threads)] = HUGE_VAL;
  for (int k = 1; k < threads; ++k) {
    auto q = xs.begin() + std::ptrdiff_t(xs.size() * std::size_t(k) / std::size_t(threads));
    std::nth_element(xs.begin(), q, xs.end());
    cut[std::size_t(k)] = *q;
    if (!(cut[std::size_t(k)] > cut[std::size_t(k) - 1])) return res;  // an empty slab: not merged
  }
  for (std::size_t k = 0; k < parts.size(); ++k) parts[k].lo = cut[k], parts[k].hi = cut[k + 1];

  // The parts, a thread each. Progress comes from the calling thread's part, scaled.
  const std::size_t every = opt.progress ? std::max<std::size_t>(1, opt.progressEvery) : std::size_t(-1);
  const auto tp = Clock::now();
  parallelFor(threads, std::size_t(threads), [&](int, std::size_t lo, std::size_t hi) {
    for (std::size_t k = lo; k < hi; ++k)
      runPart(parts[k], xy, opt, threads, v3, k == 0 ? every : std::size_t(-1),
              [&](int i, const FastStats& st) {
                FastStats scaled = st;
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
    res.stats.sortSeconds = std::max(res.stats.sortSeconds, part.sortSeconds);
  }
  for (std::size_t k = 1; k < parts.size(); ++k)
    parts[k].offset = parts[k - 1].offset + parts[k - 1].inNo.size();

  // The seam: B, its triangulation, the triangles of it outside the safe ones.
  const auto tm = Clock::now();
  std::vector<int> bid;  // input numbers
  std::unordered_map<int, int> number;  // with insertion numbering: B's points' numbers there
  for (const Part& part : parts)
    for (int v : part.border) {
      bid.push_back(part.inNo[std::size_t(v)]);
      if (opt.insertionNumbering) number[bid.back()] = int(part.offset) + v;
    }
  rep.border = bid.size();
  std::unordered_set<std::uint64_t> seam;
  for (Part& part : parts) {
    seam.insert(part.seam.begin(), part.seam.end());
    std::vector<std::uint64_t>().swap(part.seam);
  }
  std::vector<Tri> kept;
  if (!mergeSeam(xy, std::move(bid), seam, v3, res.stats, kept)) return res;
  if (opt.insertionNumbering)
    for (Tri& t : kept)
      for (int& v : t) v = number.at(v);
  rep.mergeSeconds = secondsSince(tm);

  // The output: the parts' safe triangles (each part writes its own, renumbered) and the kept.
  const auto tf = Clock::now();
  std::vector<std::size_t> at(parts.size() + 1, 0);
  for (std::size_t k = 0; k < parts.size(); ++k) at[k + 1] = at[k] + parts[k].safeCount;
  // The output's pages are mapped by the threads, a piece each, before it is written.
  auto sized = [threads](auto& v, std::size_t size) {
    v.reserve(size);
    populatePages(v.data(), size * sizeof(v[0]), threads);
    v.resize(size);
  };
  sized(res.tri, at.back() + kept.size());
  if (opt.insertionNumbering) {
    sized(res.points, 2 * n);
    sized(res.inserted, n);
  }
  parallelFor(threads, parts.size(), [&](int, std::size_t lo, std::size_t hi) {
    for (std::size_t k = lo; k < hi; ++k)
      writePart(parts[k], opt.insertionNumbering, res.tri.data() + at[k], res);
  });
  std::copy(kept.begin(), kept.end(), res.tri.begin() + std::ptrdiff_t(at.back()));
  for (const Part& part : parts) {
    res.stats.insertions += part.stats.insertions;
    res.stats.walkSteps += part.stats.walkSteps;
    res.stats.cavityFaces += part.stats.cavityFaces;
    res.stats.orient += part.stats.orient;
    res.stats.incircle += part.stats.incircle;
    for (const auto& [d, v] : part.named) res.duplicates.emplace_back(d, part.inNo[std::size_t(v)]);
  }
  std::sort(res.duplicates.begin(), res.duplicates.end());
  rep.finishSeconds = secondsSince(tf);
  rep.merged = true;
  res.stats.insertSeconds = secondsSince(t0) - res.stats.sortSeconds;
  return res;
}
//! [splitAndMerge]

}  // namespace fast
}  // namespace dt
