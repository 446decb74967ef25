#include "fast_parallel.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <exception>
#include <memory>
#include <stdexcept>
#include <string>
#include <thread>

#include "hilbert.h"
#include "predicates_inline.h"
#include "triangulate.h"

namespace dt {

namespace {

// ---------------------------------------------------------------------------------------------
// Shared state. The storage of fast_delaunay.cpp (V: vertices, A: half-edge adjacencies, vertex
// n = INF at position 2 of a ghost), reserved once for the 2n + 2 triangles a triangulation of
// n points can have: nothing reallocates while threads run. Every entry of V and A is read and
// written with relaxed atomic accesses (plain moves on x86), so a walk may read a triangle that
// another thread is rewriting without a data race; what the walk finds is only a hint, checked
// under a lock. owner[t] is the lock of triangle t: kFree, 2 id (locked by thread id), 2 id + 1
// (locked by thread id and in its cavity), or kFresh (a slot not yet handed out).
//! [parShared]
constexpr unsigned char kFree = 0, kFresh = 255;
constexpr int kMaxThreads = 64;  // 2 id + 1 < kFresh

struct Shared {
  const double* P = nullptr;  // the points in insertion order, and a dummy point for INF
  int INF = 0;
  std::vector<std::array<int, 3>> V;
  std::vector<int> A;
  std::unique_ptr<std::atomic<unsigned char>[]> owner;
  std::atomic<int> count{0};  // slots handed out; every slot below it is a live triangle
};
//! [parShared]

inline int ld(const int& x) { return __atomic_load_n(&x, __ATOMIC_RELAXED); }
inline void st(int& x, int v) { __atomic_store_n(&x, v, __ATOMIC_RELAXED); }

inline bool onOpenSegment(const double* a, const double* b, const double* p) {
  const int k = a[0] != b[0] ? 0 : 1;
  return (a[k] < p[k] && p[k] < b[k]) || (b[k] < p[k] && p[k] < a[k]);
}

// One thread's insertions: the kernel of fast_delaunay.cpp, with a try-lock on every triangle
// the cavity search reads, and an exit (Busy) where the sequential kernel could not fail.
class Inserter {
 public:
  enum Outcome { Inserted, Duplicate, Busy };

  Inserter(Shared& S, int id, FastStats& stats)
      : S_(S), tagLock_((unsigned char)(2 * id)), tagCav_((unsigned char)(2 * id + 1)),
        st_(stats) {}

  int last = 0;  // where the next walk starts

//! [parInsert]
  // Inserts vertex ip, or reports the vertex it duplicates, or Busy: a triangle it needed was
  // locked by another thread (then nothing changed and every lock it took is released).
  Outcome insert(int ip, int& dup) {
    const double* p = pt(ip);
    for (int attempt = 0; attempt < 3; ++attempt) {
      const int t = walk(p);
      if (t < 0 || !tryLock(t)) return Busy;
      // Under the lock, t is a live triangle whose vertices and links no one else changes.
      const int v0 = ld(S_.V[t][0]), v1 = ld(S_.V[t][1]), v2 = ld(S_.V[t][2]);
      if (v2 != S_.INF)
        for (int v : {v0, v1, v2})
          if (pt(v)[0] == p[0] && pt(v)[1] == p[1]) {
            dup = v;
            releaseAll();
            return Duplicate;
          }
      if (!conflict(t, p)) {  // the walk read a triangle being rewritten: walk again from t
        releaseAll();
        last = t;
        continue;
      }
      if (!cavity(t, p)) {
        releaseAll();
        return Busy;
      }
      if (bnd_.size() != cav_.size() + 2)  // Property 2.1.1: the cavity is a disk
        throw std::logic_error("fastDelaunayParallel: cavity boundary has " +
                               std::to_string(bnd_.size()) + " edges for " +
                               std::to_string(cav_.size()) + " triangles");
      st_.cavityFaces += cav_.size();
      ++st_.insertions;
      fill(ip);
      releaseAll();
      return Inserted;
    }
    return Busy;
  }
//! [parInsert]

 private:
  struct BoundaryEdge {
    int a, b, out, e1, e2;  // as in fast_delaunay.cpp
  };

  const double* pt(int v) const { return S_.P + 2 * std::size_t(v); }

  bool tryLock(int t) {
    unsigned char e = kFree;
    if (!S_.owner[t].compare_exchange_strong(e, tagLock_, std::memory_order_acquire,
                                             std::memory_order_relaxed))
      return false;
    locked_.push_back(t);
    return true;
  }
  void releaseAll() {
    for (int t : locked_) S_.owner[t].store(kFree, std::memory_order_release);
    locked_.clear();
  }

  int orient(const double* a, const double* b, const double* c) {
    int stage = pred::kFilter;
    const int s = pred::orient2d(a[0], a[1], b[0], b[1], c[0], c[1], stage);
    if (__builtin_expect(stage == pred::kExact, 0)) ++st_.exactOrient;
    return s;
  }
  bool conflict(int t, const double* p) {
    const int a = ld(S_.V[t][0]), b = ld(S_.V[t][1]), c = ld(S_.V[t][2]);
    if (c == S_.INF) {
      const int o = orient(pt(a), pt(b), p);
      return o > 0 || (o == 0 && onOpenSegment(pt(a), pt(b), p));
    }
    int stage = pred::kFilter;
    const double *x = pt(a), *y = pt(b), *z = pt(c);
    const int s = pred::incircle(x[0], x[1], y[0], y[1], z[0], z[1], p[0], p[1], stage);
    if (__builtin_expect(stage == pred::kExact, 0)) ++st_.exactIncircle;
    return s > 0;
  }

  // The visibility walk of fast_delaunay.cpp, on data that may change under it: it locks
  // nothing, so it may follow a stale link or read a half-written triangle (vertex indices stay
  // in range: every entry of V and A always holds some valid index). Returns a candidate seed,
  // or -1 after more steps than there are triangles.
  int walk(const double* p) {
    int t = last, from = -1;
    const std::size_t cap = std::size_t(S_.count.load(std::memory_order_relaxed)) + 1;
    for (std::size_t steps = 1; steps <= cap; ++steps) {
      const int v0 = ld(S_.V[t][0]), v1 = ld(S_.V[t][1]), v2 = ld(S_.V[t][2]);
      int k = -1;
      if (v2 == S_.INF) {
        if (from == 0 || conflict(t, p)) {
          st_.walkSteps += steps;
          return t;
        }
        k = 0;
      } else {
        const double *a = pt(v0), *b = pt(v1), *c = pt(v2);
        if (from != 0 && orient(a, b, p) < 0)
          k = 0;
        else if (from != 1 && orient(b, c, p) < 0)
          k = 1;
        else if (from != 2 && orient(c, a, p) < 0)
          k = 2;
        if (k < 0) {
          st_.walkSteps += steps;
          return t;
        }
      }
      const int h = ld(S_.A[3 * std::size_t(t) + k]);
      t = h / 3;
      from = h % 3;
    }
    return -1;
  }

//! [parCavity]
  // The cavity search of fast_delaunay.cpp, locking each neighbour before reading it. A
  // neighbour locked by another thread (or a slot not handed out yet) ends the search: false.
  bool cavity(int seed, const double* p) {
    cav_.clear();
    bnd_.clear();
    S_.owner[seed].store(tagCav_, std::memory_order_relaxed);
    cav_.push_back(seed);
    for (std::size_t i = 0; i < cav_.size(); ++i) {
      const int t = cav_[i];
      for (int k = 0; k < 3; ++k) {
        const int h = ld(S_.A[3 * std::size_t(t) + k]);
        const int n = h / 3;
        const unsigned char tag = S_.owner[n].load(std::memory_order_relaxed);
        if (tag == tagCav_) continue;  // an interior edge of the cavity
        if (tag != tagLock_) {         // not seen yet: lock it, then test it
          if (!tryLock(n)) return false;
          if (conflict(n, p)) {
            S_.owner[n].store(tagCav_, std::memory_order_relaxed);
            cav_.push_back(n);
            continue;
          }
        }
        bnd_.push_back({ld(S_.V[t][k]), ld(S_.V[t][(k + 1) % 3]), h, -1, -1});
      }
    }
    return true;
  }
//! [parCavity]

  void link(int h, int g) {
    st(S_.A[h], g);
    st(S_.A[g], h);
  }

  // fast_delaunay.cpp's fill: the new triangles in the cavity's slots and two fresh ones, which
  // this thread owns from the moment it is handed them (they are kFresh to everyone else).
  void fill(int ip) {
    const std::size_t nc = cav_.size();
    const int base = S_.count.fetch_add(2, std::memory_order_relaxed);
    for (int s : {base, base + 1}) {
      S_.owner[s].store(tagLock_, std::memory_order_relaxed);
      locked_.push_back(s);
    }
    for (std::size_t i = 0; i < bnd_.size(); ++i) {
      const int s = i < nc ? cav_[i] : base + int(i - nc);
      BoundaryEdge& e = bnd_[i];
      int k0, w[3];
      if (e.a != S_.INF && e.b != S_.INF) {
        w[0] = e.a, w[1] = e.b, w[2] = ip, k0 = 0;
      } else if (e.b == S_.INF) {
        w[0] = ip, w[1] = e.a, w[2] = S_.INF, k0 = 1;
      } else {
        w[0] = e.b, w[1] = ip, w[2] = S_.INF, k0 = 2;
      }
      for (int j = 0; j < 3; ++j) st(S_.V[s][j], w[j]);
      e.e1 = 3 * s + (k0 + 1) % 3;
      e.e2 = 3 * s + (k0 + 2) % 3;
      link(3 * s + k0, e.out);
    }
    const std::size_t m = bnd_.size();
    if (m <= 32) {
      for (const BoundaryEdge& e : bnd_) {
        std::size_t j = 0;
        while (j < m && bnd_[j].a != e.b) ++j;
        if (j == m) throw std::logic_error("fastDelaunayParallel: cavity boundary is not closed");
        link(e.e1, bnd_[j].e2);
      }
    } else {
      byStart_.clear();
      for (const BoundaryEdge& e : bnd_) byStart_.emplace_back(e.a, e.e2);
      std::sort(byStart_.begin(), byStart_.end());
      for (const BoundaryEdge& e : bnd_) {
        const auto it =
            std::lower_bound(byStart_.begin(), byStart_.end(), std::make_pair(e.b, -1));
        if (it == byStart_.end() || it->first != e.b)
          throw std::logic_error("fastDelaunayParallel: cavity boundary is not closed");
        link(e.e1, it->second);
      }
    }
    last = bnd_.back().e1 / 3;
  }

  Shared& S_;
  const unsigned char tagLock_, tagCav_;
  FastStats& st_;
  std::vector<int> locked_, cav_;
  std::vector<BoundaryEdge> bnd_;
  std::vector<std::pair<int, int>> byStart_;
};

struct Worker {
  FastStats stats;
  std::vector<std::pair<int, int>> dups;  // (point, vertex it duplicates), insertion numbers
  std::vector<int> deferred;
  std::exception_ptr error;
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

// body(k, lo, hi) on `threads` consecutive pieces [lo, hi) of [0, n), piece k by thread k.
template <class Body>
void parallelFor(int threads, std::size_t n, Body body) {
  auto piece = [&](int k) { body(k, n * std::size_t(k) / std::size_t(threads),
                                 n * std::size_t(k + 1) / std::size_t(threads)); };
  std::vector<std::thread> pool;
  for (int k = 1; k < threads; ++k) pool.emplace_back(piece, k);
  piece(0);
  for (std::thread& th : pool) th.join();
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
  threads = std::min(threads, kMaxThreads);
  ps.threads = threads;
  if (opt.order != FastOrder::RadixBrio || opt.ladderCallPredicates)
    throw std::invalid_argument(
        "fastDelaunayParallel: more than one thread needs the default order and predicates");
  if (xy.size() % 2 != 0)
    throw std::invalid_argument("fastDelaunayParallel: odd number of coordinates");
  const std::size_t n = xy.size() / 2;
  if (n > (std::size_t{1} << 28))
    throw std::invalid_argument("fastDelaunayParallel: more than 2^28 points");
  for (std::size_t i = 0; i < xy.size(); ++i)
    if (!std::isfinite(xy[i]))
      throw std::invalid_argument("fastDelaunayParallel: point " + std::to_string(i / 2) +
                                  " has a coordinate that is not finite");
  if (n < 3) throw DegenerateInput("fewer than 3 distinct points");
  FastResult res;
  const auto t0 = std::chrono::steady_clock::now();
  const int rounds = std::max(1, std::min(opt.rounds, 32));
  std::vector<int> orig;
  {
    const std::vector<std::size_t> o = brioCoinOrder(xy, opt.seed, rounds);
    orig.assign(o.begin(), o.end());
  }
  // Where each round starts in the order (the rounds are consecutive, first round first).
  // Counting the rounds' sizes and copying the points in insertion order are split too.
  std::vector<std::vector<int>> roundSize(std::size_t(threads), std::vector<int>(rounds, 0));
  std::vector<double> P(2 * n + 2, 0.0);  // + the dummy point of INF (a stale walk may read it)
  parallelFor(threads, n, [&](int k, std::size_t lo, std::size_t hi) {
    for (std::size_t i = lo; i < hi; ++i) {
      ++roundSize[std::size_t(k)][std::size_t(brioCoinRound(i, opt.seed, rounds))];
      if (i + 16 < hi) __builtin_prefetch(&xy[2 * std::size_t(orig[i + 16])]);
      P[2 * i] = xy[2 * std::size_t(orig[i])];
      P[2 * i + 1] = xy[2 * std::size_t(orig[i]) + 1];
    }
  });
  std::vector<int> roundStart(std::size_t(rounds) + 1, 0);
  for (int r = 0; r < rounds; ++r) {
    roundStart[r + 1] = roundStart[r];
    for (const std::vector<int>& c : roundSize) roundStart[r + 1] += c[std::size_t(r)];
  }
  res.stats.sortSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

  // The first triangle, as fastDelaunay chooses it.
  auto same = [&](int i, int j) { return P[2 * i] == P[2 * j] && P[2 * i + 1] == P[2 * j + 1]; };
  auto orient = [&](int a, int b, int c) {
    return orient2d(P[2 * a], P[2 * a + 1], P[2 * b], P[2 * b + 1], P[2 * c], P[2 * c + 1]);
  };
  const int N = int(n);
  int i1 = 1;
  while (i1 < N && same(0, i1)) ++i1;
  if (i1 >= N) throw DegenerateInput("fewer than 3 distinct points");
  int i2 = i1 + 1;
  while (i2 < N && orient(0, i1, i2) == 0) ++i2;
  if (i2 >= N) {
    bool distinct3 = false;
    for (int i = i1 + 1; i < N && !distinct3; ++i) distinct3 = !same(i, 0) && !same(i, i1);
    throw DegenerateInput(distinct3 ? "all points are collinear" : "fewer than 3 distinct points");
  }

  Shared S;
  S.P = P.data();
  S.INF = N;
  const std::size_t maxTri = 2 * n + 2;
  S.V.assign(maxTri, {0, 0, 0});
  S.A.assign(3 * maxTri, 0);
  const int links[12] = {3, 6, 9, 0, 11, 7, 1, 5, 10, 2, 8, 4};  // fast_delaunay.cpp's init()
  std::copy(links, links + 12, S.A.begin());
  S.owner.reset(new std::atomic<unsigned char>[maxTri]);
  for (std::size_t t = 0; t < maxTri; ++t) S.owner[t].store(t < 4 ? kFree : kFresh);
  const int a = 0, b = orient(0, i1, i2) > 0 ? i1 : i2, c = b == i1 ? i2 : i1;
  S.V[0] = {a, b, c};
  S.V[1] = {b, a, N};
  S.V[2] = {c, b, N};
  S.V[3] = {a, c, N};
  S.count = 4;
  res.stats.insertions = 3;

  std::vector<Worker> W(static_cast<std::size_t>(threads));
  std::vector<std::unique_ptr<Inserter>> ins;
  for (int k = 0; k < threads; ++k) ins.emplace_back(new Inserter(S, k + 1, W[k].stats));

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
    parallelFor(threads, std::size_t(to - from), [&](int k, std::size_t lo, std::size_t hi) {
      try {  // (the walk starts where this thread's previous piece ended)
        insertRange(*ins[k], W[k], from + int(lo), from + int(hi), i1, i2, false,
                    k == 0 ? every / std::size_t(threads) + 1 : std::size_t(-1), [&](int i) {
                      report(std::size_t(from) + std::size_t(i - from) * std::size_t(threads),
                             threads);
                    });
      } catch (...) {
        W[k].error = std::current_exception();
      }
    });
    for (Worker& w : W)
      if (w.error) std::rethrow_exception(w.error);
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

  // Duplicates: the smallest input number of equal points is kept (the swaps of fastDelaunay,
  // whose end result does not depend on the order they are made in).
  std::vector<std::pair<int, int>> dups;
  for (Worker& w : W) {
    res.stats.insertions += w.stats.insertions;
    res.stats.walkSteps += w.stats.walkSteps;
    res.stats.cavityFaces += w.stats.cavityFaces;
    res.stats.exactOrient += w.stats.exactOrient;
    res.stats.exactIncircle += w.stats.exactIncircle;
    for (auto [i, d] : w.dups) {
      if (orig[i] < orig[d]) std::swap(orig[i], orig[d]);
      dups.emplace_back(orig[i], d);
    }
  }
  // The output, as fastDelaunay makes it: the finite triangles renumbered as the input.
  ins.clear();
  S.owner.reset();
  std::vector<int>().swap(S.A);
  if (opt.insertionNumbering)
    P.resize(2 * n);  // the dummy point of INF goes
  else
    std::vector<double>().swap(P);
  // Renumbered (unless insertionNumbering) by pieces, each compacted in place, then the pieces
  // moved together.
  const bool renumber = !opt.insertionNumbering;
  std::vector<std::array<int, 3>>& V = S.V;
  V.resize(std::size_t(S.count.load()));
  std::vector<std::size_t> pieceLo(static_cast<std::size_t>(threads)), pieceLen(pieceLo);
  parallelFor(threads, V.size(), [&](int k, std::size_t lo, std::size_t hi) {
    std::size_t w = lo;
    for (std::size_t t = lo; t < hi; ++t)
      if (V[t][2] != N)
        V[w++] = renumber ? std::array<int, 3>{orig[V[t][0]], orig[V[t][1]], orig[V[t][2]]} : V[t];
    pieceLo[std::size_t(k)] = lo;
    pieceLen[std::size_t(k)] = w - lo;
  });
  std::size_t w = 0;
  for (int k = 0; k < threads; ++k) {
    std::move(V.begin() + long(pieceLo[k]), V.begin() + long(pieceLo[k] + pieceLen[k]),
              V.begin() + long(w));
    w += pieceLen[k];
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
  res.stats.insertSeconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() -
      res.stats.sortSeconds;
  if (pstats) *pstats = ps;
  return res;
}
//! [fastDelaunayParallel]

}  // namespace dt
