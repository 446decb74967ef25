#include "fast_delaunay.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <stdexcept>
#include <string>

#include "hilbert.h"
#include "predicates.h"
#include "predicates_inline.h"
#include "triangulate.h"

namespace dt {

namespace {

// ---------------------------------------------------------------------------------------------
// The robust predicates of predicates_inline.h (the one core: filter, small-multiple stage,
// GMP), inlined, without the library's global counters; the kernel counts GMP calls itself.
//! [fastPredicates]
struct InlinePredicates {
  FastStats* st;
  int orient(const double* a, const double* b, const double* c) const {
    int stage = pred::kFilter;
    const int s = pred::orient2d(a[0], a[1], b[0], b[1], c[0], c[1], stage);
    if (__builtin_expect(stage == pred::kExact, 0)) ++st->exactOrient;
    if (__builtin_expect(stage == pred::kExtended, 0)) ++st->extendedOrient;
    return s;
  }
  int incircle(const double* a, const double* b, const double* c, const double* d) const {
    int stage = pred::kFilter;
    const int s = pred::incircle(a[0], a[1], b[0], b[1], c[0], c[1], d[0], d[1], stage);
    if (__builtin_expect(stage == pred::kExact, 0)) ++st->exactIncircle;
    if (__builtin_expect(stage == pred::kExtended, 0)) ++st->extendedIncircle;
    return s;
  }
};
//! [fastPredicates]

// The ladder's first rungs: the library's out-of-line predicates (with their counters).
struct CalledPredicates {
  FastStats* st;
  int orient(const double* a, const double* b, const double* c) const {
    return orient2d(a[0], a[1], b[0], b[1], c[0], c[1]);
  }
  int incircle(const double* a, const double* b, const double* c, const double* d) const {
    return dt::incircle(a[0], a[1], b[0], b[1], c[0], c[1], d[0], d[1]);
  }
};

// p on the open segment ab, given a, b, p collinear (comparisons only, hence exact).
inline bool onOpenSegment(const double* a, const double* b, const double* p) {
  const int k = a[0] != b[0] ? 0 : 1;
  return (a[k] < p[k] && p[k] < b[k]) || (b[k] < p[k] && p[k] < a[k]);
}

// ---------------------------------------------------------------------------------------------
// The kernel. Triangle t has vertices V[t][0..2] (counter-clockwise) and, across its edge
// V[t][k] V[t][(k+1)%3], the neighbour half-edge A[3 t + k] = 3 t' + k' (the same edge seen from t').
// Vertices are the points in insertion order, 0..n-1; INF = n is the vertex at infinity, always
// at position 2 of a ghost. Two arrays rather than one record: at the end A is freed and V,
// compacted in place, becomes the output, so the output costs no memory of its own.
template <class Pred, bool kMapAdjacency, bool kCentroidWalk>
class Kernel {
 public:
  Kernel(const double* P, int n, Pred pred, FastStats& st)
      : P_(P), INF(n), pred_(pred), st_(st) {
    const std::size_t maxTri = 2 * std::size_t(n) + 2;  // 2(n+1) - 4 faces on the sphere
    V_.reserve(maxTri);
    A_.reserve(3 * maxTri);
    mark_.assign(maxTri, 0);
  }

  /// The first triangle a b c (counter-clockwise) and its three ghosts.
  void init(int a, int b, int c) {
    V_ = {{a, b, c}, {b, a, INF}, {c, b, INF}, {a, c, INF}};
    A_ = {3 * 1 + 0, 3 * 2 + 0, 3 * 3 + 0,
          3 * 0 + 0, 3 * 3 + 2, 3 * 2 + 1,
          3 * 0 + 1, 3 * 1 + 2, 3 * 3 + 1,
          3 * 0 + 2, 3 * 2 + 2, 3 * 1 + 1};
    last_ = 0;
  }

  /// Inserts vertex ip. Returns -1, or the vertex that ip duplicates (then nothing changes).
//! [fastInsert]
  int insert(int ip) {
    const double* p = P_ + 2 * ip;
    int dup = -1;
    const int seed = kCentroidWalk ? walkCentroid(p, dup) : walk(p, dup);
    if (seed < 0) return dup;
    cavity(seed, p);
    if (bnd_.size() != cav_.size() + 2)  // Property 2.1.1: the cavity is a disk
      throw std::logic_error("fastDelaunay: cavity boundary has " +
                             std::to_string(bnd_.size()) + " edges for " +
                             std::to_string(cav_.size()) + " triangles");
    st_.cavityFaces += cav_.size();
    ++st_.insertions;
    fill(ip);
    return -1;
  }

//! [fastInsert]
  std::vector<std::array<int, 3>>& vertices() { return V_; }
  int infinite() const { return INF; }
  /// Frees everything but the vertices of the triangles.
  void releaseAllButVertices() {
    // (v = {} would keep the capacity: it assigns an empty list.)
    std::vector<unsigned char>().swap(mark_);
    std::vector<int>().swap(A_);
  }

 private:
  struct BoundaryEdge {
    int a, b;  // the edge a -> b as the cavity triangle sees it
    int out;   // the half-edge of the triangle outside the cavity
    int e1;    // the half-edge b -> p of the new triangle a b p
    int e2;    // the half-edge p -> a of the new triangle a b p
  };

  const double* pt(int v) const { return P_ + 2 * v; }
  static constexpr int kNext[3] = {1, 2, 0};

  // Inlined by force: it is the innermost call of the walk and of the cavity search.
  __attribute__((always_inline)) bool conflict(int t, const double* p) const {
    const int* v = V_[t].data();
    if (v[2] == INF) {  // ghost (a, b, inf): p strictly left of a->b, or on the open segment
      const int o = pred_.orient(pt(v[0]), pt(v[1]), p);
      return o > 0 || (o == 0 && onOpenSegment(pt(v[0]), pt(v[1]), p));
    }
    return pred_.incircle(pt(v[0]), pt(v[1]), pt(v[2]), p) > 0;
  }

//! [fastWalk]
  // A visibility walk by orientation tests, from the last triangle created, that does not test
  // the edge it came through. On a Delaunay triangulation it cannot cycle (Edelsbrunner); the
  // cap turns a corrupted mesh into an error. It ends in a triangle that contains p (whose
  // circle then contains p strictly unless p is one of its vertices) or in a ghost that sees p.
  int walk(const double* p, int& dup) {
    int t = last_, from = -1;
    const std::size_t cap = V_.size() + 1;
    for (std::size_t steps = 1;; ++steps) {
      if (steps > cap) throw std::logic_error("fastDelaunay: walk does not terminate");
      const int* v = V_[t].data();
      if (v[2] == INF) {
        // Entered from its finite side: p is strictly beyond that hull edge, a conflict.
        if (from == 0 || conflict(t, p)) {
          st_.walkSteps += steps;
          return t;
        }
        const int h = A_[3 * t + 0];
        t = h / 3;
        from = h % 3;
        continue;
      }
      const double *a = pt(v[0]), *b = pt(v[1]), *c = pt(v[2]);
      int k = -1;
      if (from != 0 && pred_.orient(a, b, p) < 0)
        k = 0;
      else if (from != 1 && pred_.orient(b, c, p) < 0)
        k = 1;
      else if (from != 2 && pred_.orient(c, a, p) < 0)
        k = 2;
      if (k < 0) {
        st_.walkSteps += steps;
        for (int j = 0; j < 3; ++j)
          if (pt(v[j])[0] == p[0] && pt(v[j])[1] == p[1]) {
            dup = v[j];
            return -1;
          }
        return t;
      }
      const int h = A_[3 * t + k];
      t = h / 3;
      from = h % 3;
    }
  }

//! [fastWalk]
  // The ladder's walk: Listing 2.6 as corrected in search.cpp (an incircle test at every
  // triangle, then the half-open sector of the centroid's ray).
  int walkCentroid(const double* p, int& dup) {
    int t = last_;
    const std::size_t cap = V_.size() + 1;
    for (std::size_t steps = 1;; ++steps) {
      if (steps > cap) throw std::logic_error("fastDelaunay: walk does not terminate");
      if (conflict(t, p)) {
        st_.walkSteps += steps;
        return t;
      }
      const int* v = V_[t].data();
      if (v[2] == INF) {
        t = A_[3 * t + 0] / 3;
        continue;
      }
      const double c[2] = {(pt(v[0])[0] + pt(v[1])[0] + pt(v[2])[0]) / 3,
                           (pt(v[0])[1] + pt(v[1])[1] + pt(v[2])[1]) / 3};
      int next = -1;
      for (int k = 0; k < 3 && next < 0; ++k) {
        const double *a = pt(v[k]), *b = pt(v[(k + 1) % 3]);
        if (pred_.orient(c, a, p) >= 0 && pred_.orient(c, b, p) < 0 && pred_.orient(a, b, p) < 0)
          next = k;
      }
      for (int k = 0; k < 3 && next < 0; ++k)
        if (pred_.orient(pt(v[k]), pt(v[(k + 1) % 3]), p) < 0) next = k;
      if (next < 0) {
        st_.walkSteps += steps;
        for (int j = 0; j < 3; ++j)
          if (pt(v[j])[0] == p[0] && pt(v[j])[1] == p[1]) {
            dup = v[j];
            return -1;
          }
        throw std::logic_error("fastDelaunay: point inside a triangle but outside its circle");
      }
      t = A_[3 * t + next] / 3;
    }
  }

//! [fastCavity]
  // Delaunay cavity (Listing 2.5) from a seed in conflict: the list of cavity triangles is its
  // own work queue, so there is neither recursion nor a separate stack.
  void cavity(int seed, const double* p) {
    cav_.clear();
    bnd_.clear();
    mark_[seed] = 1;
    cav_.push_back(seed);
    for (std::size_t i = 0; i < cav_.size(); ++i) {
      const int t = cav_[i];
      for (int k = 0; k < 3; ++k) {
        const int h = A_[3 * t + k];
        const int n = h / 3;
        if (mark_[n]) continue;  // inside the cavity: an interior edge
        if (conflict(n, p)) {
          mark_[n] = 1;
          cav_.push_back(n);
        } else {
          bnd_.push_back({V_[t][k], V_[t][(k + 1) % 3], h, -1, -1});
        }
      }
    }
  }

//! [fastCavity]
//! [fastFill]
  void link(int h, int g) {  // half-edge h = 3 t + k is entry h of A_: no division
    A_[h] = g;
    A_[g] = h;
  }

  // The Delaunay ball: triangle a b p on each boundary edge a -> b, in the slots of the cavity
  // and two new ones. Its edge b -> p meets the edge p -> b of the triangle built on the
  // boundary edge that leaves b (the boundary is one closed polygon, Property 2.1.1): a search
  // among the few boundary edges finds it, without a map.
  void fill(int ip) {
    const std::size_t nc = cav_.size();
    // The two new slots at once (the capacity is reserved: no reallocation).
    const int base = int(V_.size());
    V_.resize(V_.size() + (bnd_.size() - nc));
    A_.resize(A_.size() + 3 * (bnd_.size() - nc));
    for (std::size_t i = 0; i < bnd_.size(); ++i) {
      const int s = i < nc ? cav_[i] : base + int(i - nc);
      mark_[s] = 0;
      BoundaryEdge& e = bnd_[i];
      // The vertex at infinity stays at position 2 of a ghost: a b p, or p a inf, or b p inf.
      int k0;  // the position of the edge a -> b in the new triangle
      if (__builtin_expect(e.a != INF && e.b != INF, 1)) {
        V_[s] = {e.a, e.b, ip};
        k0 = 0;
      } else if (e.b == INF) {
        V_[s] = {ip, e.a, INF};
        k0 = 1;
      } else {
        V_[s] = {e.b, ip, INF};
        k0 = 2;
      }
      const int e0 = 3 * s + k0;
      e.e1 = 3 * s + kNext[k0];
      e.e2 = 3 * s + kNext[kNext[k0]];
      if (!kMapAdjacency) link(e0, e.out);
    }
    if (kMapAdjacency)
      linkWithMap();
    else
      linkAround();
    last_ = int(bnd_.back().e1 / 3);
  }

  void linkAround() {
    const std::size_t m = bnd_.size();
    if (m <= 32) {  // the usual case (about 6 edges): a plain search
      for (const BoundaryEdge& e : bnd_) {
        std::size_t j = 0;
        while (j < m && bnd_[j].a != e.b) ++j;
        if (j == m) throw std::logic_error("fastDelaunay: cavity boundary is not closed");
        link(e.e1, bnd_[j].e2);
      }
      return;
    }
    byStart_.clear();  // a large cavity (degenerate input): sort the edges by their start
    for (const BoundaryEdge& e : bnd_) byStart_.emplace_back(e.a, e.e2);
    std::sort(byStart_.begin(), byStart_.end());
    for (const BoundaryEdge& e : bnd_) {
      const auto it = std::lower_bound(byStart_.begin(), byStart_.end(), std::make_pair(e.b, -1));
      if (it == byStart_.end() || it->first != e.b)
        throw std::logic_error("fastDelaunay: cavity boundary is not closed");
      link(e.e1, it->second);
    }
  }

//! [fastFill]
  // The ladder's adjacency: Listing 2.4's std::map from edges to half-edges, over the new
  // triangles and the outer side of the boundary.
  void linkWithMap() {
    std::map<std::pair<int, int>, int> edgeToHalf;
    auto key = [](int u, int v) { return std::make_pair(std::min(u, v), std::max(u, v)); };
    for (const BoundaryEdge& e : bnd_) edgeToHalf.emplace(key(e.a, e.b), e.out);
    for (const BoundaryEdge& e : bnd_) {
      const int s = e.e1 / 3;
      for (int k = 0; k < 3; ++k) {
        const auto q = key(V_[s][k], V_[s][(k + 1) % 3]);
        auto it = edgeToHalf.find(q);
        if (it == edgeToHalf.end()) {
          edgeToHalf.emplace(q, 3 * s + k);
        } else {
          link(3 * s + k, it->second);
          edgeToHalf.erase(it);
        }
      }
    }
  }

  const double* P_;
  const int INF;
  Pred pred_;
  FastStats& st_;
//! [fastArrays]
  std::vector<std::array<int, 3>> V_;  // V_[t]: the vertices of triangle t, counter-clockwise
  std::vector<int> A_;  // A_[3 t + k] = 3 t' + k': the same edge seen from t' (flat: link needs no division)
//! [fastArrays]
  std::vector<unsigned char> mark_;  // in the current cavity
  std::vector<std::pair<int, int>> byStart_;  // large cavities: (start vertex, half-edge p -> a)
  std::vector<int> cav_;
  std::vector<BoundaryEdge> bnd_;
  int last_ = 0;
};

template <class Pred, bool kMap, bool kCentroid>
void run(std::vector<double>& P, std::vector<int>& orig, FastResult& res, Pred pred,
         const FastOptions& opt) {
  const int n = int(orig.size());
  auto same = [&](int i, int j) { return P[2 * i] == P[2 * j] && P[2 * i + 1] == P[2 * j + 1]; };
  // The first triangle: point 0, the first point distinct from it, the first one off their
  // line (as delaunayTrglHull does); the points skipped on the way are inserted later.
  int i1 = 1;
  while (i1 < n && same(0, i1)) ++i1;
  if (i1 >= n) throw DegenerateInput("fewer than 3 distinct points");
  int i2 = i1 + 1;
  while (i2 < n && pred.orient(&P[0], &P[2 * i1], &P[2 * i2]) == 0) ++i2;
  if (i2 >= n) {
    bool distinct3 = false;
    for (int i = i1 + 1; i < n && !distinct3; ++i) distinct3 = !same(i, 0) && !same(i, i1);
    throw DegenerateInput(distinct3 ? "all points are collinear" : "fewer than 3 distinct points");
  }
  Kernel<Pred, kMap, kCentroid> K(P.data(), n, pred, res.stats);
  if (pred.orient(&P[0], &P[2 * i1], &P[2 * i2]) > 0)
    K.init(0, i1, i2);
  else
    K.init(0, i2, i1);
  res.stats.insertions = 3;
  std::vector<std::pair<int, int>> dups;  // (input number, vertex kept)
  const std::size_t every = std::max<std::size_t>(1, opt.progressEvery);
  std::size_t nextReport = opt.progress ? every : std::size_t(-1);
  for (int i = 1; i < n; ++i) {
    if (__builtin_expect(std::size_t(i) == nextReport, 0)) {
      opt.progress(std::size_t(i), std::size_t(n), res.stats);
      nextReport += every;
    }
    if (i == i1 || i == i2) continue;
    const int d = K.insert(i);
    if (d < 0) continue;
    // Keep the smallest input number of the equal points.
    if (orig[i] < orig[d]) std::swap(orig[i], orig[d]);
    dups.emplace_back(orig[i], d);
  }
  // The output is the array of vertices itself: the adjacencies, the marks and the sorted
  // points are freed, the finite triangles renumbered as the input and packed at the front.
  K.releaseAllButVertices();
  std::vector<std::array<int, 3>>& V = K.vertices();
  std::size_t w = 0;
  if (opt.insertionNumbering) {
    for (const auto& t : V)
      if (t[2] != K.infinite()) V[w++] = t;
  } else {
    std::vector<double>().swap(P);
    for (const auto& t : V)
      if (t[2] != K.infinite()) V[w++] = {orig[t[0]], orig[t[1]], orig[t[2]]};
  }
  V.resize(w);
  res.tri = std::move(V);
  res.duplicates.reserve(dups.size());
  for (const auto& [d, v] : dups) res.duplicates.emplace_back(d, orig[v]);
  std::sort(res.duplicates.begin(), res.duplicates.end());
  if (opt.insertionNumbering) {
    res.points = std::move(P);
    res.inserted = std::move(orig);
  }
}

}  // namespace

std::vector<std::uint64_t> fastHilbertKeys(const std::vector<double>& xy, int depth) {
  if (depth == 0) depth = hilbertAutoDepth(xy.size() / 2);
  if (depth < 1 || depth > 31) throw std::invalid_argument("fastHilbertKeys: depth out of 1..31");
  return hilbertKeysFast(xy, depth);
}

//! [fastDelaunay]
FastResult fastDelaunay(const std::vector<double>& xy, const FastOptions& opt) {
  if (xy.size() % 2 != 0) throw std::invalid_argument("fastDelaunay: odd number of coordinates");
  const std::size_t n = xy.size() / 2;
  if (n > (std::size_t{1} << 28)) throw std::invalid_argument("fastDelaunay: more than 2^28 points");
  for (std::size_t i = 0; i < xy.size(); ++i)
    if (!std::isfinite(xy[i]))
      throw std::invalid_argument("fastDelaunay: point " + std::to_string(i / 2) +
                                  " has a coordinate that is not finite");
  if (n < 3) throw DegenerateInput("fewer than 3 distinct points");
  FastResult res;
  const auto t0 = std::chrono::steady_clock::now();
  std::vector<int> orig;  // orig[i]: input number of the i-th point inserted
  if (opt.order == FastOrder::Input) {
    orig.resize(n);
    for (std::size_t i = 0; i < n; ++i) orig[i] = int(i);
  } else {  // hilbert.h: one Hilbert sort for the whole library
    const std::vector<std::size_t> o =
        opt.order == FastOrder::RadixBrio
            ? brioCoinOrder(xy, opt.seed, std::max(1, std::min(opt.rounds, 32)))
            : (opt.order == FastOrder::Brio ? brioOrder(xy, opt.seed) : hilbertOrder(xy));
    orig.assign(o.begin(), o.end());
  }
  // The points in insertion order, contiguous: the walk and the cavity read neighbours.
  std::vector<double> P(2 * n);
  for (std::size_t i = 0; i < n; ++i) {
    // The reads are scattered: ask for the point needed a few iterations ahead.
    if (i + 16 < n) __builtin_prefetch(&xy[2 * std::size_t(orig[i + 16])]);
    P[2 * i] = xy[2 * std::size_t(orig[i])];
    P[2 * i + 1] = xy[2 * std::size_t(orig[i]) + 1];
  }
  const auto t1 = std::chrono::steady_clock::now();
  res.stats.sortSeconds = std::chrono::duration<double>(t1 - t0).count();
  if ((opt.ladderMapAdjacency && !opt.ladderCentroidWalk) ||
      (opt.ladderCentroidWalk && !opt.ladderCallPredicates))
    throw std::invalid_argument("fastDelaunay: the ladder switches are cumulative");
  if (opt.ladderCallPredicates) {
    const PredicateCounters before = predicateCounters();
    CalledPredicates pred{&res.stats};
    if (opt.ladderMapAdjacency)
      run<CalledPredicates, true, true>(P, orig, res, pred, opt);
    else if (opt.ladderCentroidWalk)
      run<CalledPredicates, false, true>(P, orig, res, pred, opt);
    else
      run<CalledPredicates, false, false>(P, orig, res, pred, opt);
    const PredicateCounters a = predicateCounters(), &b = before;  // GMP: the rest of exact
    res.stats.exactOrient = (a.orientExact - a.orientSmallInt - a.orientExtended) -
                            (b.orientExact - b.orientSmallInt - b.orientExtended);
    res.stats.exactIncircle = (a.incircleExact - a.incircleSmallInt - a.incircleExtended) -
                              (b.incircleExact - b.incircleSmallInt - b.incircleExtended);
    res.stats.extendedOrient = a.orientExtended - b.orientExtended;
    res.stats.extendedIncircle = a.incircleExtended - b.incircleExtended;
  } else {
    run<InlinePredicates, false, false>(P, orig, res, InlinePredicates{&res.stats}, opt);
  }
  res.stats.insertSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t1).count();
  return res;
}
//! [fastDelaunay]

}  // namespace dt
