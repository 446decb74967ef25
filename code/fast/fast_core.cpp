#include "fast_core.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "errors.h"

namespace dt {
namespace fast {

void checkInput(const std::vector<double>& xy, const char* who) {
  if (xy.size() % 2 != 0) throw std::invalid_argument(std::string(who) + ": odd number of coordinates");
  const std::size_t n = xy.size() / 2;
  if (n > (std::size_t{1} << 28))
    throw std::invalid_argument(std::string(who) + ": more than 2^28 points");
  for (std::size_t i = 0; i < xy.size(); ++i)
    if (!std::isfinite(xy[i]))
      throw std::invalid_argument(std::string(who) + ": point " + std::to_string(i / 2) +
                                  " has a coordinate that is not finite");
  if (n < 3) throw DegenerateInput("fewer than 3 distinct points");
}

std::vector<double> pointsInOrder(const std::vector<double>& xy, const std::vector<int>& orig,
                                  int threads) {
  // The points in insertion order, contiguous: the walk and the cavity read neighbours. The
  // last one is the dummy point of the vertex at infinity.
  const std::size_t n = orig.size();
  std::vector<double> P = hugeVector<double>(2 * n + 2);
  parallelFor(threads, n, [&](int, std::size_t lo, std::size_t hi) {
    for (std::size_t i = lo; i < hi; ++i) {
      // The reads are scattered: ask for the point needed a few iterations ahead.
      if (i + 16 < hi) __builtin_prefetch(&xy[2 * std::size_t(orig[i + 16])]);
      P[2 * i] = xy[2 * std::size_t(orig[i])];
      P[2 * i + 1] = xy[2 * std::size_t(orig[i]) + 1];
    }
  });
  return P;
}

FirstTriangle firstTriangle(const std::vector<double>& P, int n) {
  auto same = [&](int i, int j) { return P[2 * i] == P[2 * j] && P[2 * i + 1] == P[2 * j + 1]; };
  // The robust predicate inlined, uncounted (the run's record counts the insertions' tests).
  auto orient = [&](int a, int b, int c) {
    int stage = pred::kFilter;
    return pred::orient2d(P[2 * a], P[2 * a + 1], P[2 * b], P[2 * b + 1], P[2 * c], P[2 * c + 1],
                          stage);
  };
  int i1 = 1;
  while (i1 < n && same(0, i1)) ++i1;
  if (i1 >= n) throw DegenerateInput("fewer than 3 distinct points");
  int i2 = i1 + 1;
  while (i2 < n && orient(0, i1, i2) == 0) ++i2;
  if (i2 >= n) {
    bool distinct3 = false;
    for (int i = i1 + 1; i < n && !distinct3; ++i) distinct3 = !same(i, 0) && !same(i, i1);
    throw DegenerateInput(distinct3 ? "all points are collinear" : "fewer than 3 distinct points");
  }
  return {i1, i2, orient(0, i1, i2) > 0};
}

void finish(std::vector<Tri>& V, std::size_t count, int INF, std::vector<double>& P,
            std::vector<int>& orig, const std::vector<std::pair<int, int>>& dups,
            bool insertionNumbering, int threads, FastResult& res) {
  // Duplicates: the smallest input number of equal points is kept. The swaps' end result does
  // not depend on the order they are made in.
  std::vector<std::pair<int, int>> named;  // (input number of the duplicate, vertex kept)
  named.reserve(dups.size());
  for (auto [i, d] : dups) {
    if (orig[std::size_t(i)] < orig[std::size_t(d)]) std::swap(orig[std::size_t(i)], orig[std::size_t(d)]);
    named.emplace_back(orig[std::size_t(i)], d);
  }
  // The output is the array of vertices itself: the finite triangles renumbered (unless
  // insertion numbering) and packed in place, by pieces, then the pieces moved together.
  if (insertionNumbering)
    P.resize(P.size() - 2);  // the dummy point of INF goes
  else
    std::vector<double>().swap(P);
  V.resize(count);
  const int pieces = count < 100000 ? 1 : threads;
  std::vector<std::size_t> pieceLo(static_cast<std::size_t>(pieces)), pieceLen(pieceLo);
  parallelFor(pieces, V.size(), [&](int k, std::size_t lo, std::size_t hi) {
    std::size_t w = lo;
    for (std::size_t t = lo; t < hi; ++t)
      if (V[t][2] != INF)
        V[w++] = insertionNumbering ? V[t]
                                    : Tri{orig[std::size_t(V[t][0])], orig[std::size_t(V[t][1])],
                                          orig[std::size_t(V[t][2])]};
    pieceLo[std::size_t(k)] = lo;
    pieceLen[std::size_t(k)] = w - lo;
  });
  std::size_t w = 0;
  for (int k = 0; k < pieces; ++k) {
    std::move(V.begin() + long(pieceLo[std::size_t(k)]),
              V.begin() + long(pieceLo[std::size_t(k)] + pieceLen[std::size_t(k)]),
              V.begin() + long(w));
    w += pieceLen[std::size_t(k)];
  }
  V.resize(w);
  res.tri = std::move(V);
  res.duplicates.reserve(named.size());
  for (const auto& [d, v] : named) res.duplicates.emplace_back(d, orig[std::size_t(v)]);
  std::sort(res.duplicates.begin(), res.duplicates.end());
  if (insertionNumbering) {
    res.points = std::move(P);
    res.inserted = std::move(orig);
  }
}

Ordered orderOneThread(const std::vector<double>& xy, const FastOptions& opt) {
  const std::size_t n = xy.size() / 2;
  Ordered o;
  o.orig.reserve(n);
  adviseHugePages(o.orig.data(), n * sizeof(int));
  if (opt.order == InsertionOrder::Input) {
    for (std::size_t i = 0; i < n; ++i) o.orig.push_back(int(i));
  } else if (opt.order == InsertionOrder::Brio) {  // hilbert.h: one sort for the whole library
    o.memA = adjacencyMemory(slotsFor(n), n);
    const std::size_t* r =
        brioCoinOrderInto(xy, opt.seed, std::max(1, std::min(opt.rounds, 32)), o.memA.get());
    o.orig.assign(r, r + n);
  } else {
    const std::vector<std::size_t> r =
        opt.order == InsertionOrder::BrioDoubling ? brioOrder(xy, opt.seed) : hilbertOrder(xy);
    o.orig.assign(r.begin(), r.end());
  }
  if (!o.memA) o.memA = adjacencyMemory(slotsFor(n), n);
  o.P = pointsInOrder(xy, o.orig, 1);
  return o;
}

}  // namespace fast
}  // namespace dt
