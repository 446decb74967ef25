// The one insertion core of the fast kernels (fast_delaunay.cpp, one thread; fast_parallel.cpp,
// several threads on one shared triangulation). Bowyer-Watson with ghost faces, as
// delaunayTrglHull (2.2.2, Listing 2.7), on index arrays. What differs between the two kernels
// is a policy of the one template:
//  - Access: how an entry of the arrays is read and written (plain, or relaxed atomic so that a
//    walk may read a triangle another thread is rewriting without a data race);
//  - Claim: how an insertion takes the triangles it reads and writes (a mark in a private array,
//    which cannot fail, or a try-lock per triangle, which can: the insertion is then "Busy"),
//    and where the two fresh slots of each insertion come from;
//  - Walk and Link: how the walk finds the first triangle of the cavity, and how the new
//    triangles are linked. The library uses VisibilityWalk and RingLink; the listings' walk and
//    std::map (fast_ladder.h) are for the optimisation ladder (opt_ladder) and the tests.
// Internal header: included by the two kernels, fast_ladder.h and the tests.
#pragma once

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <memory>
#include <new>
#include <stdexcept>
#include <string>
#include <thread>
#include <type_traits>
#include <utility>
#include <vector>

#include "fast_types.h"
#include "hilbert.h"
#include "huge_pages.h"
#include "parallel_for.h"
#include "predicates.h"
#include "predicates_inline.h"
#include "tri.h"

namespace dt {
namespace fast {

// ---------------------------------------------------------------------------------------------
// Predicates. The robust core of predicates_inline.h, inlined; each call's deciding stage is
// counted in the run's own record (FastStats), not in the library's global counters.
//! [fastPredicates]
struct InlinePredicates {
  FastStats* st;
  int orient(const double* a, const double* b, const double* c) const {
    int stage = pred::kFilter;
    const int s = pred::orient2d(a[0], a[1], b[0], b[1], c[0], c[1], stage);
    st->orient.add(stage);
    return s;
  }
  int incircle(const double* a, const double* b, const double* c, const double* d) const {
    int stage = pred::kFilter;
    const int s = pred::incircle(a[0], a[1], b[0], b[1], c[0], c[1], d[0], d[1], stage);
    st->incircle.add(stage);
    return s;
  }
};
//! [fastPredicates]

// ---------------------------------------------------------------------------------------------
// Access policies.
struct PlainAccess {
  static int ld(const int& x) { return x; }
  static void st(int& x, int v) { x = v; }
};
// Relaxed atomic loads and stores: plain moves on x86, but defined behaviour when another
// thread writes the same entry (what a reader finds is a hint, checked under a lock).
struct RelaxedAccess {
  static int ld(const int& x) { return __atomic_load_n(&x, __ATOMIC_RELAXED); }
  static void st(int& x, int v) { __atomic_store_n(&x, v, __ATOMIC_RELAXED); }
};

// ---------------------------------------------------------------------------------------------
// The storage. Triangle t has vertices V[t][0..2] (counter-clockwise) and, across its edge
// V[t][k] V[t][(k+1)%3], the neighbour half-edge A[3 t + k] = 3 t' + k' (the same edge seen
// from t'). Vertices are the points in insertion order, 0..n-1; INF = n is the vertex at
// infinity, always at position 2 of a ghost; P holds a dummy point for it (a stale walk of the
// parallel kernel may read it). Two arrays rather than one record: at the end A is freed and V,
// compacted in place, becomes the output. Everything is allocated once: nothing reallocates
// while an insertion (or a thread) holds a pointer into it. An entry of A is written before it
// is read, except by a walk of the parallel kernel that follows a link another thread is
// writing: so one thread leaves A as it finds it, several threads zero it first (in pieces, one
// thread a piece), so that a stale read is a half-edge, never garbage. A's memory is allocated
// before the sort, which borrows it (adjacencyMemory, below).

/// Raw memory, no objects in it yet, freed by operator delete.
struct FreeRaw {
  void operator()(void* p) const { ::operator delete(p); }
};
using RawMemory = std::unique_ptr<void, FreeRaw>;

/// The memory of the adjacency array A of `slots` triangles, allocated and mapped (in small
/// pages, in one call: Store says why) before the sort of the n points, which borrows it
/// (brioCoinOrderInto): a fresh process then maps 24 bytes per point fewer new pages than with
/// the sort's own arrays, pages that the operating system must clear first. With `threads`
/// threads, the threads map a piece each.
inline RawMemory adjacencyMemory(std::size_t slots, std::size_t n, int threads = 1) {
  const std::size_t bytes = std::max(3 * slots * sizeof(int), brioCoinScratchBytes(n));
  RawMemory m(::operator new(bytes));
  populatePages(m.get(), bytes, threads);
  return m;
}

//! [fastArrays]
struct Store {
  const double* P = nullptr;
  int INF = 0;
  std::vector<Tri> V;   // V[t]: the vertices of triangle t, counter-clockwise
  RawMemory memA;       // the memory of A (adjacencyMemory)
  int* A = nullptr;     // A[3 t + k] = 3 t' + k' (flat: linking needs no division)
  std::atomic<int> count{0};  // slots handed out; a slot below it that is not a triangle holds
                              // {INF, INF, INF} (compaction drops it with the ghosts)
//! [fastArrays]

  /// Room for `slots` triangles, A in `memory` (adjacencyMemory(slots, ...)); unused slots read
  /// as {INF, INF, INF}. threads > 1: A is zeroed, and the threads map V's pages a piece each.
  /// V is mapped at once in small pages (populatePages), as A, not in 2 MB pages (hugeVector):
  /// those can come cold from a VM's host (book/fast_kernel.md, "Against CGAL").
  Store(const double* points, int n, std::size_t slots, int threads, RawMemory memory)
      : P(points), INF(n), memA(std::move(memory)), A(::new (memA.get()) int[3 * slots]) {
    V.reserve(slots);
    populatePages(V.data(), slots * sizeof(Tri), threads);
    V.assign(slots, Tri{n, n, n});
    if (threads > 1)  // zeroed by the threads in pieces: a stale read must see a half-edge (above)
      parallelFor(threads, 3 * slots, [&](int, std::size_t lo, std::size_t hi) {
        std::fill(A + lo, A + hi, 0);
      });
  }

  /// Frees A (the end of a run: only V is kept).
  void freeAdjacency() {
    A = nullptr;
    memA.reset();
  }

  /// The first triangle a b c (counter-clockwise) and its three ghosts, in slots 0..3.
  void init(int a, int b, int c) {
    V[0] = {a, b, c};
    V[1] = {b, a, INF};
    V[2] = {c, b, INF};
    V[3] = {a, c, INF};
    const int links[12] = {3 * 1 + 0, 3 * 2 + 0, 3 * 3 + 0,   // a->b, b->c, c->a of 0
                           3 * 0 + 0, 3 * 3 + 2, 3 * 2 + 1,   // ghost b a
                           3 * 0 + 1, 3 * 1 + 2, 3 * 3 + 1,   // ghost c b
                           3 * 0 + 2, 3 * 2 + 2, 3 * 1 + 1};  // ghost a c
    std::copy(links, links + 12, A);
    count.store(4, std::memory_order_relaxed);
  }
};

// ---------------------------------------------------------------------------------------------
// Claim policies. Each answers, for a neighbour n met by the cavity search, whether it is in the
// cavity already (kInCavity), already tested and left out by this insertion (kHeld), or new; and
// takes a triangle for the insertion, or refuses it (another thread's). kLockFirst: the claim
// must hold a triangle before the insertion reads it (lock(t), a try-lock); otherwise the
// claim decides from the triangle's vertices, read first (takes(v)). Once taken, a triangle is
// written by this thread only, until the insertion ends: the inserter reads it (its vertices,
// its links) with plain loads (Inserter::own).

/// One thread: a mark per triangle. Claims cannot fail; marks are cleared after the fill.
class MarkClaim {
 public:
  static constexpr bool kShared = false;
  static constexpr bool kLockFirst = false;
  enum State { kNew, kInCavity, kHeld };
  explicit MarkClaim(Store& S) : S_(S), mark_(S.V.size(), 0) {}
  bool takes(const int (&)[3]) const { return true; }
  State state(int n) const { return mark_[std::size_t(n)] ? kInCavity : kNew; }
  void enterCavity(int n) { mark_[std::size_t(n)] = 1; }
  void releaseAll(const std::vector<int>& cav) {
    for (int t : cav) mark_[std::size_t(t)] = 0;
  }
  /// Two fresh slots for the two triangles an insertion adds.
  int newSlots() {
    const int base = S_.count.load(std::memory_order_relaxed);
    S_.count.store(base + 2, std::memory_order_relaxed);
    return base;
  }
  void freeMarks() { std::vector<unsigned char>().swap(mark_); }

 protected:
  Store& S_;

 private:
  std::vector<unsigned char> mark_;
};

/// Several threads: owner[t] is the lock of triangle t: kFree, 2 id (locked by thread id),
/// 2 id + 1 (locked by thread id and in its cavity), or kFresh (a slot not handed out). Fresh
/// slots come in blocks (SlotBlocks, below).
//! [parShared]
constexpr unsigned char kFree = 0, kFresh = 255;
constexpr int kMaxThreads = 64;  // 2 id + 1 < kFresh

struct Locks {
  std::unique_ptr<std::atomic<unsigned char>[]> owner;
  explicit Locks(std::size_t slots, std::size_t live) : owner(new std::atomic<unsigned char>[slots]) {
    for (std::size_t t = 0; t < slots; ++t) owner[t].store(t < live ? kFree : kFresh);
  }
};
//! [parShared]

/// Fresh slots for the threads: blocks of `block` slots taken from the shared counter at once,
/// so that the triangles one thread creates are neighbours in memory (and in the lock array),
/// not interleaved with the other threads' (the cache lines would then travel between cores).
class SlotBlocks {
 public:
  static constexpr int kBlock = 512;  // slots per block: 6 KB of V, 6 KB of A
  SlotBlocks(Store& S, int block) : S_(S), block_(block) {}
  /// Two fresh slots of this thread's block (a new block when it is used up).
  int take2() {
    if (next_ + 2 > end_) {
      next_ = S_.count.fetch_add(block_, std::memory_order_relaxed);
      end_ = next_ + block_;
      if (std::size_t(end_) > S_.V.size())
        throw std::logic_error("fastDelaunayParallel: out of triangle slots");
    }
    const int base = next_;
    next_ += 2;
    return base;
  }

 private:
  Store& S_;
  const int block_;
  int next_ = 0, end_ = 0;
};

/// The triangle slots of a run on n points: the 2(n + 1) - 4 faces of DT(S) and its ghosts on
/// the sphere, and two more; plus `blocks` blocks for the shared claims, whose threads each leave
/// a last block of fresh slots partly used.
inline std::size_t slotsFor(std::size_t n, int blocks = 0) {
  return 2 * n + 2 + std::size_t(blocks) * SlotBlocks::kBlock;
}

class LockClaim {
 public:
  static constexpr bool kShared = true;
  static constexpr bool kLockFirst = true;
  static constexpr int kBlock = SlotBlocks::kBlock;
  enum State { kNew, kInCavity, kHeld };
  LockClaim(Store& S, Locks& L, int id, int block = kBlock)
      : L_(L), tagLock_((unsigned char)(2 * id)), tagCav_((unsigned char)(2 * id + 1)),
        blocks_(S, block) {}
  bool lock(int t) {
    unsigned char e = kFree;
    if (!L_.owner[t].compare_exchange_strong(e, tagLock_, std::memory_order_acquire,
                                             std::memory_order_relaxed))
      return false;
    locked_.push_back(t);
    return true;
  }
  State state(int n) const {
    const unsigned char tag = L_.owner[n].load(std::memory_order_relaxed);
    return tag == tagCav_ ? kInCavity : tag == tagLock_ ? kHeld : kNew;
  }
  void enterCavity(int n) { L_.owner[n].store(tagCav_, std::memory_order_relaxed); }
  void releaseAll(const std::vector<int>&) {
    for (int t : locked_) L_.owner[t].store(kFree, std::memory_order_release);
    locked_.clear();
  }
  /// Two fresh slots from this thread's block. This thread owns them from the moment it takes
  /// them (they are kFresh to everyone else).
  int newSlots() {
    const int base = blocks_.take2();
    for (int s : {base, base + 1}) {
      L_.owner[s].store(tagLock_, std::memory_order_relaxed);
      locked_.push_back(s);
    }
    return base;
  }

 private:
  Locks& L_;
  const unsigned char tagLock_, tagCav_;
  SlotBlocks blocks_;
  std::vector<int> locked_;
};

/// Several threads without locks: during a concurrent round thread k owns a slab of the plane,
/// lo <= x < hi (the slabs of the threads do not overlap), and takes only the triangles whose
/// three vertices lie in its slab (never a ghost). No other thread writes such a triangle: the
/// other threads' cavities hold only their own slabs' triangles, and the triangles they build
/// (an edge of their cavity and their own point) lie in their slabs again; the triangles with
/// vertices in two slabs, and the ghosts, are left to the insertions redone alone after the
/// round. So a claim is a test of three coordinates, not a compare-and-swap. A triangle read
/// while another thread rewrites it has vertices of that thread's slab (or INF) in every
/// mixture, and is refused. Marks are private to the thread (MarkClaim's); fresh slots come
/// in blocks (SlotBlocks). Alone (after setAlone), it takes every triangle.
//! [slabClaim]
class SlabClaim : public MarkClaim {
 public:
  static constexpr bool kShared = true;
  static constexpr bool kLockFirst = false;
  static constexpr int kBlock = SlotBlocks::kBlock;
  explicit SlabClaim(Store& S, int block = kBlock) : MarkClaim(S), blocks_(S, block) {}
  void setSlab(double lo, double hi) { lo_ = lo, hi_ = hi, alone_ = false; }
  void setAlone() { alone_ = true; }
  /// Whether the triangle whose vertices read as v is this thread's. INF is at position 2 of a
  /// ghost and nowhere else, so a finite triangle has v[2] != INF; a read of a triangle that
  /// another thread is rewriting mixes vertices of its slab and INF (of a fresh slot), and its
  /// position 2 is INF or a vertex of that slab: refused either way.
  bool takes(const int (&v)[3]) const {
    return alone_ || (v[2] != S_.INF && mine(v[0]) && mine(v[1]) && mine(v[2]));
  }
  int newSlots() { return blocks_.take2(); }

 private:
  bool mine(int v) const {
    const double x = S_.P[2 * std::size_t(v)];
    return x >= lo_ && x < hi_;
  }
  SlotBlocks blocks_;
  double lo_ = 0, hi_ = 0;
  bool alone_ = true;
};
//! [slabClaim]

// ---------------------------------------------------------------------------------------------
/// The ghost rule of predicates_inline.h on the kernel's point array.
inline bool onOpenSegment(const double* a, const double* b, const double* p) {
  return pred::onOpenSegment(a[0], a[1], b[0], b[1], p[0], p[1]);
}

/// Walk policy of the library: the visibility walk (Inserter::walk).
struct VisibilityWalk {
  template <class In>
  static int walk(In& in, const double* p, int&) {
    return in.walk(p);
  }
};

/// Link policy of the library: each new triangle's outer edge is linked as it is written, and
/// its two inner edges around the ring (Inserter::linkAround).
struct RingLink {
  template <class In>
  static void outer(In& in, int h, int out) {
    in.link(h, out);
  }
  template <class In>
  static void ring(In& in) {
    in.linkAround();
  }
};

/// One inserter: the walk, the cavity, the fill. The policies Walk and Link are friends: they
/// read the inserter's store and call its steps.
template <class Pred, class Access, class Claim, class Walk = VisibilityWalk,
          class Link = RingLink>
class alignas(64) Inserter {  // aligned: two threads' inserters never share a cache line
  friend Walk;
  friend Link;

 public:
  enum Outcome { Inserted, Duplicate, Busy };

  Inserter(Store& S, Claim& claim, Pred pred, FastStats& st)
      : S_(S), claim_(claim), pred_(pred), st_(st) {}

  int last = 0;  // where the next walk starts: a triangle of the last cavity
  /// Whether a walk starts at the new triangle around the last point inserted that faces the
  /// next one (startNear), rather than at `last` (Table 2.2's rule, a rung of the ladder).
  bool ringStart = true;

  /// Inserts vertex ip; or sets dup to the vertex it duplicates (nothing changes); or, with a
  /// shared claim, reports Busy: a triangle it needed was another thread's (nothing changed and
  /// every lock it took is released).
//! [fastInsert]
  Outcome insert(int ip, int& dup) {
    const double* p = pt(ip);
    if (ringStart && ring_ >= 0) last = startNear(p);
    for (int attempt = 0; attempt < (Claim::kShared ? 3 : 1); ++attempt) {
      const int t = Walk::walk(*this, p, dup);
      if (t == kDuplicate) return Duplicate;
      if (t < 0) {
        if (!Claim::kShared) throw std::logic_error("fastDelaunay: walk does not terminate");
        return Busy;
      }
      int v[3];
      if (!take(t, v)) return Busy;
      // (With a shared claim: now t is a live triangle no one else changes.)
      if (v[2] != S_.INF)
        for (int j = 0; j < 3; ++j)
          if (pt(v[j])[0] == p[0] && pt(v[j])[1] == p[1]) {
            dup = v[j];
            claim_.releaseAll(cav_);
            return Duplicate;
          }
      // The walk read a triangle being rewritten: walk again from t. (One thread: a triangle
      // that contains p and does not have p as a vertex has p strictly inside its circle.)
      if (Claim::kShared && !seedHolds(v, p)) {
        claim_.releaseAll(cav_);
        last = t;
        continue;
      }
      if (!cavity(t, p)) {
        claim_.releaseAll(cav_);
        return Busy;
      }
      if (bnd_.size() != cav_.size() + 2)  // Property 2.1.1: the cavity is a disk
        throw std::logic_error("fastDelaunay: cavity boundary has " +
                               std::to_string(bnd_.size()) + " edges for " +
                               std::to_string(cav_.size()) + " triangles");
      st_.cavityFaces += cav_.size();
      ++st_.insertions;
      fill(ip);
      claim_.releaseAll(cav_);
      return Inserted;
    }
    return Busy;
  }
//! [fastInsert]

 private:
  struct BoundaryEdge {
    int a, b;  // the edge a -> b as the cavity triangle sees it
    int out;   // the half-edge of the triangle outside the cavity
    int e1;    // the half-edge b -> p of the new triangle a b p
    int e2;    // the half-edge p -> a of the new triangle a b p
  };
  static constexpr int kDuplicate = -2;
  static constexpr int kNext[3] = {1, 2, 0};

  static int ld(const int& x) { return Access::ld(x); }
  // An entry of a triangle this insertion has taken: no other thread writes it now (the claims
  // above), so a plain load races with nothing (other threads may only read it).
  static int own(const int& x) { return x; }
  const double* pt(int v) const { return S_.P + 2 * std::size_t(v); }

  // Reads the vertices of triangle t into v, once, and takes t for this insertion; false if the
  // claim refuses it (another thread's).
  __attribute__((always_inline)) bool take(int t, int (&v)[3]) {
    const Tri& w = S_.V[std::size_t(t)];
    if constexpr (Claim::kLockFirst) {
      if (!claim_.lock(t)) return false;
      for (int j = 0; j < 3; ++j) v[j] = own(w[j]);
      return true;
    } else {
      for (int j = 0; j < 3; ++j) v[j] = ld(w[j]);
      return claim_.takes(v);
    }
  }

  // Inlined by force: it is the innermost call of the walk and of the cavity search.
  __attribute__((always_inline)) bool conflict(const int (&v)[3], const double* p) const {
    const int a = v[0], b = v[1], c = v[2];
    if (c == S_.INF)  // ghost (a, b, inf): the rule of predicates_inline.h
      return pred::ghostConflict(pred_.orient(pt(a), pt(b), p), pt(a)[0], pt(a)[1], pt(b)[0],
                                 pt(b)[1], p[0], p[1]);
    return pred_.incircle(pt(a), pt(b), pt(c), p) > 0;
  }
  __attribute__((always_inline)) bool conflict(int t, const double* p) const {
    const int v[3] = {ld(S_.V[t][0]), ld(S_.V[t][1]), ld(S_.V[t][2])};
    return conflict(v, p);
  }

  // With a shared claim, whether the triangle t the walk ended in, taken with vertices v, is in
  // conflict with p (p not a vertex of it): the walk may have read t, or followed a link into it,
  // while another thread rewrote them. Locks: t may have changed between the walk's reads and
  // the lock, so the incircle test again. Slabs: t is this thread's, and no other thread wrote it
  // in the round, so the walk read these vertices; only the link it came by may have been stale,
  // so the edge it entered by, which the walk does not test, is tested now: p is then in the
  // closed triangle, strictly inside its circle. (Alone, every read is consistent.)
  bool seedHolds(const int (&v)[3], const double* p) const {
    if (Claim::kLockFirst) return conflict(v, p);
    if (from_ < 0 || v[2] == S_.INF) return true;
    return pred_.orient(pt(v[from_]), pt(v[kNext[from_]]), p) >= 0;
  }

//! [fastWalk]
  // A visibility walk by orientation tests, from `last` (see startNear), that does not test
  // the edge it came through. On a Delaunay triangulation it cannot cycle (Edelsbrunner). It
  // ends in a triangle that contains p or in a ghost that sees p; -1 after more steps than
  // there are triangles (one thread: a corrupted mesh; several: it read links being rewritten).
  int walk(const double* p) {
    int t = last, from = -1;
    const std::size_t cap = std::size_t(S_.count.load(std::memory_order_relaxed)) + 1;
    for (std::size_t steps = 1; steps <= cap; ++steps) {
      const int v0 = ld(S_.V[t][0]), v1 = ld(S_.V[t][1]), v2 = ld(S_.V[t][2]);
      int k = -1;
      if (v2 == S_.INF) {
        // Entered from its finite side: p is strictly beyond that hull edge, a conflict.
        if (from == 0 || conflict(t, p)) {
          st_.walkSteps += steps;
          from_ = from;
          return t;
        }
        k = 0;
      } else {
        const double *a = pt(v0), *b = pt(v1), *c = pt(v2);
        if (from != 0 && pred_.orient(a, b, p) < 0)
          k = 0;
        else if (from != 1 && pred_.orient(b, c, p) < 0)
          k = 1;
        else if (from != 2 && pred_.orient(c, a, p) < 0)
          k = 2;
        if (k < 0) {
          st_.walkSteps += steps;
          from_ = from;
          return t;
        }
      }
      const int h = ld(S_.A[3 * std::size_t(t) + k]);
      t = h / 3;
      from = h % 3;
    }
    return -1;
  }
//! [fastWalk]

//! [fastCavity]
  // Delaunay cavity (Listing 2.5) from a seed in conflict, depth first, each triangle's edges
  // taken counter-clockwise from the one it was entered by. Every vertex of the cavity is on
  // its boundary (a vertex inside would leave DT(S + p)), so its triangles form a tree across
  // their shared edges: the search crosses each shared edge once, from the side it reached
  // first, and lists the boundary edges in counter-clockwise order around the cavity, each
  // edge's end the next one's start. The fill then links the new triangles without searching
  // (a search's unpredictable branches cost more than the predicates). pending_ is a stack of
  // the half-edges still to cross, the next one on top. A neighbour the claim cannot take (another
  // thread's) ends the search: false.
  bool cavity(int seed, const double* p) {
    ring_ = -1;
    cav_.clear();
    bnd_.clear();
    claim_.enterCavity(seed);
    cav_.push_back(seed);
    std::size_t top = 3;  // pending_[0, top) is the stack: the seed's edges, edge 0 on top
    pending_[0] = 3 * seed + 2;
    pending_[1] = 3 * seed + 1;
    pending_[2] = 3 * seed;
    while (top > 0) {
      const int he = pending_[--top], t = he / 3, k = he - 3 * t;
      const int h = own(S_.A[std::size_t(he)]);  // t is in the cavity: taken
      const int n = h / 3;
      const typename Claim::State s = claim_.state(n);
      if (s == Claim::kInCavity)  // a shared edge met from its second side: not a tree
        throw std::logic_error("fastDelaunay: the cavity's triangles do not form a tree");
      if (s == Claim::kNew) {  // not seen yet: take it, then test it
        int v[3];
        if (!take(n, v)) return false;
        if (conflict(v, p)) {
          claim_.enterCavity(n);
          cav_.push_back(n);
          if (__builtin_expect(top + 2 > pending_.size(), 0)) pending_.resize(2 * pending_.size());
          const int k1 = kNext[h - 3 * n];  // n was entered by its edge h - 3 n
          pending_[top++] = 3 * n + kNext[k1];
          pending_[top++] = 3 * n + k1;
          continue;
        }
      }
      BoundaryEdge& e = bnd_.emplace_back();
      e.a = own(S_.V[t][k]);
      e.b = own(S_.V[t][kNext[k]]);
      e.out = h;
    }
    return true;
  }
//! [fastCavity]

//! [fastFill]
  void link(int h, int g) {  // half-edge h = 3 t + k is entry h of A: no division
    Access::st(S_.A[std::size_t(h)], g);
    Access::st(S_.A[std::size_t(g)], h);
  }

  // The Delaunay ball: triangle a b p on each boundary edge a -> b, in the slots of the cavity
  // and two fresh ones. Its edge b -> p meets the edge p -> b of the triangle built on the
  // boundary edge that leaves b (the boundary is one closed polygon, Property 2.1.1): the next
  // edge in the cavity search's order, with neither a map nor a search.
  void fill(int ip) {
    const std::size_t nc = cav_.size();
    const int base = claim_.newSlots();
    const int INF = S_.INF;
    for (std::size_t i = 0; i < bnd_.size(); ++i) {
      const int s = i < nc ? cav_[i] : base + int(i - nc);
      BoundaryEdge& e = bnd_[i];
      // The vertex at infinity stays at position 2 of a ghost: a b p, or p a inf, or b p inf.
      int w[3], k0;  // k0: the position of the edge a -> b in the new triangle
      if (__builtin_expect(e.a != INF && e.b != INF, 1)) {
        w[0] = e.a, w[1] = e.b, w[2] = ip, k0 = 0;
      } else if (e.b == INF) {
        w[0] = ip, w[1] = e.a, w[2] = INF, k0 = 1;
      } else {
        w[0] = e.b, w[1] = ip, w[2] = INF, k0 = 2;
      }
      for (int j = 0; j < 3; ++j) Access::st(S_.V[std::size_t(s)][j], w[j]);
      e.e1 = 3 * s + kNext[k0];
      e.e2 = 3 * s + kNext[kNext[k0]];
      Link::outer(*this, 3 * s + k0, e.out);
    }
    Link::ring(*this);
    last = bnd_.back().e1 / 3;
    ring_ = ip;
  }

//! [fastStart]
  // The new triangle around the last point inserted, q, whose angle at q holds the direction
  // from q to p (consecutive points are close, so the walk from there is short); `last` if the
  // ring meets a ghost or is long. Going counter-clockwise around q, the ring's vertices pass
  // from the right of the line from q along that direction to its left at the triangle sought:
  // vertex i not strictly left, vertex i + 1 strictly left (i < m - 1); where no such pair is
  // found, the wedge is the last one, from vertex m - 1 back to vertex 0.
  int startNear(const double* p) const {
    const std::size_t m = bnd_.size();
    if (m > 32) return last;
    const double* q = pt(ring_);
    const double dx = p[0] - q[0], dy = p[1] - q[1];
    std::uint32_t left = 0;
    for (std::size_t i = 0; i < m; ++i) {
      if (bnd_[i].a == S_.INF) return last;
      const double* a = pt(bnd_[i].a);
      left |= std::uint32_t(dx * (a[1] - q[1]) - dy * (a[0] - q[0]) > 0) << i;
    }
    const std::uint32_t pass = ~left & (left >> 1);
    return bnd_[pass ? std::size_t(__builtin_ctz(pass)) : m - 1].e1 / 3;
  }
//! [fastStart]

  // Edge i + 1 of the boundary starts where edge i ends (the cavity search's order): the new
  // triangle on edge i meets the one on edge i + 1, around the ring.
  void linkAround() {
    const std::size_t m = bnd_.size();
    for (std::size_t i = 0; i < m; ++i) {
      const std::size_t j = i + 1 == m ? 0 : i + 1;
      if (bnd_[j].a != bnd_[i].b)
        throw std::logic_error("fastDelaunay: the cavity boundary is not a ring in order");
      link(bnd_[i].e1, bnd_[j].e2);
    }
  }
//! [fastFill]

  Store& S_;
  Claim& claim_;
  Pred pred_;
  FastStats& st_;
  int ring_ = -1;  // the point the last fill inserted, while bnd_ holds its ring
  int from_ = -1;  // the edge by which the last walk entered its triangle (-1: it started there)
  std::vector<int> cav_;
  std::vector<BoundaryEdge> bnd_;
  std::vector<int> pending_ = std::vector<int>(64);  // the cavity search's stack (grows)
};

// ---------------------------------------------------------------------------------------------
// Two builds of the insertion loops: the library's, for every x86-64 processor, and one for
// x86-64-v3 (AVX2, BMI2), chosen at run time; opt_ladder's last step measures what it gains.
// flatten inlines everything the loop calls into runV3; what it cannot inline (the exact
// stages, the allocator) stays in the baseline build. Both round alike: no fused multiply-add
// (-ffp-contract=off, CMakeLists.txt), so the filters' error bounds hold. GCC on x86-64 only.
//! [twoBuilds]
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
#define DT_FAST_X86_64_V3 1
template <class F>
__attribute__((target("arch=x86-64-v3"), flatten, noinline)) void runV3(F& f) {
  f();
}
#endif

/// Whether the x86-64-v3 build can run here: the processor has it (the library then uses it).
inline bool hasV3() {
#ifdef DT_FAST_X86_64_V3
  return __builtin_cpu_supports("x86-64-v3");
#else
  return false;
#endif
}

/// f() in the x86-64-v3 build if v3 (see hasV3), else in the baseline build.
template <class F>
void inBuild(bool v3, F&& f) {
#ifdef DT_FAST_X86_64_V3
  if (v3) return runV3(f);
#else
  (void)v3;
#endif
  f();
}
//! [twoBuilds]

// ---------------------------------------------------------------------------------------------
// What both kernels do around the insertions.

/// The input checks: an even number of finite coordinates, at most 2^28 points, at least 3.
void checkInput(const std::vector<double>& xy, const char* who);

/// The points of xy in the order `orig` (orig[i]: input number of the i-th), contiguous, with
/// a dummy point at the end for the vertex at infinity. threads > 1 copies in pieces.
std::vector<double> pointsInOrder(const std::vector<double>& xy, const std::vector<int>& orig,
                                  int threads);

/// The first triangle: point 0, the first point distinct from it (i1), the first one off their
/// line (i2), as delaunayTrglHull chooses it; the points skipped on the way are inserted later.
/// Throws DegenerateInput when there is none. ccw: 0 i1 i2 turn counter-clockwise.
struct FirstTriangle {
  int i1, i2;
  bool ccw;
};
FirstTriangle firstTriangle(const std::vector<double>& P, int n);

using dt::parallelFor;  // parallel_for.h

/// The end of a run: the adjacencies and the marks are already freed; the slots [0, count) of
/// V hold the triangles, the ghosts and unused slots ({INF, INF, INF}). Keeps the finite
/// triangles, packed at the front (renumbered as the input unless res asks for insertion
/// numbering), in pieces over `threads` threads; fills res.tri, res.duplicates (from the pairs
/// (point, vertex it duplicates) in insertion numbers, keeping the smallest input number of
/// equal points), and res.points / res.inserted with insertion numbering.
void finish(std::vector<Tri>& V, std::size_t count, int INF, std::vector<double>& P,
            std::vector<int>& orig, const std::vector<std::pair<int, int>>& dups,
            bool insertionNumbering, int threads, FastResult& res);

/// The one-thread kernel's input in insertion order: orig[i] is the input number of the i-th
/// point, P the points in that order (pointsInOrder), memA the adjacency array's memory, which
/// the default order's sort borrowed (adjacencyMemory).
struct Ordered {
  std::vector<int> orig;
  std::vector<double> P;
  RawMemory memA;
};
Ordered orderOneThread(const std::vector<double>& xy, const FastOptions& opt);

/// What a run of the core fixes beyond FastOptions (a library user does not choose it): the
/// build of the insertion loops (v3: the x86-64-v3 one, where hasV3()) and where a walk starts
/// (Inserter::ringStart). fastDelaunay runs {hasV3(), true}; the ladder changes both.
struct Build {
  bool v3 = false;
  bool ringStart = true;
};

/// The one-thread kernel with the policies Pred, Walk and Link (Inserter): fastDelaunay is
/// oneThread<InlinePredicates>(xy, opt, {hasV3(), true}); opt_ladder puts its rungs together
/// from the policies of fast_ladder.h. Pred is built from the run's record if it counts there.
/// Whether the predicate policy Pred counts in the run's record (is built from a FastStats*).
template <class Pred>
constexpr auto countsInRecord(int) -> decltype(Pred{std::declval<FastStats*>()}, true) {
  return true;
}
template <class Pred>
constexpr bool countsInRecord(long) {
  return false;
}

/// The insertions of a one-thread run on the store S of n points (S.INF = n): the first
/// triangle f, then points 1..n-1 in order with the policies Pred, Walk and Link; a duplicate
/// goes to dups as (point, vertex it duplicates). tick(i) is called before point i when i is a
/// multiple of `every` (the progress report; every = -1: never). fastDelaunay's loop, and each
/// part's loop of the divide-and-merge kernel (fast_split.cpp).
template <class Pred, class Walk = VisibilityWalk, class Link = RingLink, class Tick>
void insertAlone(Store& S, const FirstTriangle& f, Pred pred, const Build& how, FastStats& st,
                 std::vector<std::pair<int, int>>& dups, std::size_t every, Tick tick) {
  if (f.ccw)
    S.init(0, f.i1, f.i2);
  else
    S.init(0, f.i2, f.i1);
  MarkClaim claim(S);  // its marks are freed on return
  Inserter<Pred, PlainAccess, MarkClaim, Walk, Link> K(S, claim, pred, st);
  K.ringStart = how.ringStart;
  st.insertions = 3;
  st.x86_64_v3 = how.v3;
  const int n = S.INF;
  std::size_t next = every;
  inBuild(how.v3, [&] {
    for (int i = 1; i < n; ++i) {
      if (__builtin_expect(std::size_t(i) == next, 0)) {
        tick(i);
        next += every;
      }
      if (i == f.i1 || i == f.i2) continue;
      int d = -1;
      if (K.insert(i, d) == decltype(K)::Duplicate) dups.emplace_back(i, d);
    }
  });
}

template <class Pred, class Walk = VisibilityWalk, class Link = RingLink>
FastResult oneThread(const std::vector<double>& xy, const FastOptions& opt, const Build& how) {
  checkInput(xy, "fastDelaunay");
  FastResult res;
  const auto t0 = std::chrono::steady_clock::now();
  Ordered o = orderOneThread(xy, opt);
  const auto t1 = std::chrono::steady_clock::now();
  res.stats.sortSeconds = std::chrono::duration<double>(t1 - t0).count();
  std::vector<double>& P = o.P;
  const int n = int(o.orig.size());
  const FirstTriangle f = firstTriangle(P, n);
  Store S(P.data(), n, slotsFor(std::size_t(n)), 1, std::move(o.memA));
  Pred pred = [&] {
    if constexpr (countsInRecord<Pred>(0))
      return Pred{&res.stats};
    else
      return Pred{};
  }();
  std::vector<std::pair<int, int>> dups;  // (point, vertex it duplicates), insertion numbers
  const std::size_t every = opt.progress ? std::max<std::size_t>(1, opt.progressEvery) : std::size_t(-1);
  insertAlone<Pred, Walk, Link>(S, f, pred, how, res.stats, dups, every, [&](int i) {
    opt.progress(std::size_t(i), std::size_t(n), res.stats);
  });
  // Only the vertices of the triangles are kept: they become the output.
  S.freeAdjacency();
  finish(S.V, std::size_t(S.count.load()), n, P, o.orig, dups, opt.insertionNumbering, 1, res);
  res.stats.insertSeconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t1).count();
  return res;
}

/// fastDelaunaySharedCoreAlone (fast_parallel.h) in the build v3 (the tests compare both).
FastResult sharedCoreAlone(const std::vector<double>& xy, const FastOptions& opt, bool v3);

}  // namespace fast
}  // namespace dt
