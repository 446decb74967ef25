// The listings' features as policies of the insertion core (fast_core.h), for the optimisation
// ladder: the library's out-of-line counted predicates, the walk of Listing 2.6 and the std::map
// adjacency of Listing 2.4. The library instantiates none of them; opt_ladder puts its rungs
// together from them, and the tests check that every rung gives the same exact triangulation.
// Internal header: included by opt_ladder and the tests.
#pragma once

#include <algorithm>
#include <map>
#include <stdexcept>
#include <utility>
#include <vector>

#include "fast_core.h"
#include "predicates.h"

namespace dt {
namespace fast {

/// Predicate policy: the library's out-of-line predicates (predicates.h), which count into the
/// global record; withCalledPredicates copies the run's part of it into FastStats.
struct CalledPredicates {
  int orient(const double* a, const double* b, const double* c) const {
    return orient2d(a[0], a[1], b[0], b[1], c[0], c[1]);
  }
  int incircle(const double* a, const double* b, const double* c, const double* d) const {
    return dt::incircle(a[0], a[1], b[0], b[1], c[0], c[1], d[0], d[1]);
  }
};

/// Walk policy: Listing 2.6 as corrected in search.cpp, an incircle test at every triangle,
/// then the half-open sector of the centroid's ray. One thread only.
struct CentroidWalk {
  template <class In>
  static int walk(In& in, const double* p, int& dup) {
    int t = in.last;
    const std::size_t cap = std::size_t(in.S_.count.load(std::memory_order_relaxed)) + 1;
    for (std::size_t steps = 1; steps <= cap; ++steps) {
      if (in.conflict(t, p)) {
        in.st_.walkSteps += steps;
        return t;
      }
      const Tri& v = in.S_.V[t];
      if (v[2] == in.S_.INF) {
        t = in.S_.A[3 * std::size_t(t)] / 3;
        continue;
      }
      auto pt = [&](int k) { return in.pt(v[k % 3]); };
      const double c[2] = {(pt(0)[0] + pt(1)[0] + pt(2)[0]) / 3, (pt(0)[1] + pt(1)[1] + pt(2)[1]) / 3};
      int next = -1;
      for (int k = 0; k < 3 && next < 0; ++k) {
        const double *a = pt(k), *b = pt(k + 1);
        if (in.pred_.orient(c, a, p) >= 0 && in.pred_.orient(c, b, p) < 0 &&
            in.pred_.orient(a, b, p) < 0)
          next = k;
      }
      for (int k = 0; k < 3 && next < 0; ++k)
        if (in.pred_.orient(pt(k), pt(k + 1), p) < 0) next = k;
      if (next < 0) {
        in.st_.walkSteps += steps;
        for (int j = 0; j < 3; ++j)
          if (pt(j)[0] == p[0] && pt(j)[1] == p[1]) {
            dup = v[j];
            return In::kDuplicate;
          }
        throw std::logic_error("fastDelaunay: point inside a triangle but outside its circle");
      }
      t = in.S_.A[3 * std::size_t(t) + next] / 3;
    }
    return -1;
  }
};

/// Link policy: Listing 2.4's std::map from edges to half-edges, over the new triangles and the
/// outer side of the cavity's boundary (nothing is linked while the triangles are written).
struct MapLink {
  template <class In>
  static void outer(In&, int, int) {}
  template <class In>
  static void ring(In& in) {
    std::map<std::pair<int, int>, int> edgeToHalf;
    auto key = [](int u, int v) { return std::make_pair(std::min(u, v), std::max(u, v)); };
    for (const auto& e : in.bnd_) edgeToHalf.emplace(key(e.a, e.b), e.out);
    for (const auto& e : in.bnd_) {
      const int s = e.e1 / 3;
      for (int k = 0; k < 3; ++k) {
        const auto q = key(in.S_.V[s][k], in.S_.V[s][In::kNext[k]]);
        auto it = edgeToHalf.find(q);
        if (it == edgeToHalf.end()) {
          edgeToHalf.emplace(q, 3 * s + k);
        } else {
          in.link(3 * s + k, it->second);
          edgeToHalf.erase(it);
        }
      }
    }
  }
};

/// The one-thread kernel with CalledPredicates and the policies Walk and Link; its record holds
/// the library's counts of the run's predicate calls, stage by stage.
template <class Walk = VisibilityWalk, class Link = RingLink>
FastResult withCalledPredicates(const std::vector<double>& xy, const FastOptions& opt,
                                const Build& how) {
  const PredicateCounters before = predicateCounters();
  FastResult res = oneThread<CalledPredicates, Walk, Link>(xy, opt, how);
  res.stats.orient = predicateCounters().orient - before.orient;
  res.stats.incircle = predicateCounters().incircle - before.incircle;
  return res;
}

}  // namespace fast
}  // namespace dt
