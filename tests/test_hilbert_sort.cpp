/// \file test_hilbert_sort.cpp The one Hilbert sort (code/orders/hilbert.cpp): table keys and radix sort give the same orders as keys one level at a time and std::sort; the adaptive refinement keeps a far outlier or a dense cluster from leaving points in input order.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <utility>
#include <vector>

#include "generators.h"
#include "hilbert.h"
#include "support.h"

namespace {

using XY = dttest::XY;

// The orders as 2.3.5 first defined them: keys of hilbertIndex, sorted by (key, index).
void sortByKeyRef(std::vector<std::size_t>& idx, std::size_t lo, std::size_t hi,
                  const std::vector<std::uint64_t>& keys) {
  std::vector<std::pair<std::uint64_t, std::size_t>> kv;
  for (std::size_t k = lo; k < hi; ++k) kv.emplace_back(keys[idx[k]], idx[k]);
  std::sort(kv.begin(), kv.end());
  for (std::size_t k = lo; k < hi; ++k) idx[k] = kv[k - lo].second;
}

std::vector<std::size_t> hilbertOrderRef(const XY& xy, int depth) {
  const std::vector<std::uint64_t> keys = dt::hilbertKeys(xy, depth);
  std::vector<std::size_t> idx(keys.size());
  std::iota(idx.begin(), idx.end(), std::size_t{0});
  sortByKeyRef(idx, 0, idx.size(), keys);
  return idx;
}

std::uint64_t splitmixRef(std::uint64_t& s) {
  std::uint64_t z = (s += 0x9e3779b97f4a7c15ULL);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

std::vector<std::size_t> brioOrderRef(const XY& xy, std::uint64_t seed, int depth) {
  const std::vector<std::uint64_t> keys = dt::hilbertKeys(xy, depth);
  const std::size_t n = keys.size();
  std::vector<std::size_t> idx(n);
  std::iota(idx.begin(), idx.end(), std::size_t{0});
  std::uint64_t state = seed;
  for (std::size_t i = n; i > 1; --i) std::swap(idx[i - 1], idx[std::size_t(splitmixRef(state) % i)]);
  std::size_t start = 0;
  for (std::size_t size : dt::brioRoundSizes(n)) {
    sortByKeyRef(idx, start, start + size, keys);
    start += size;
  }
  return idx;
}

// Random points, a grid (points on cell boundaries, exact ties at low depth) and duplicates.
XY mixedPoints(std::size_t n, unsigned seed) {
  XY p = dttest::uniformPoints(n, seed, -3, 5);
  const XY g = dttest::gridPoints(30, 30, 0.25, -2, -1);
  p.insert(p.end(), g.begin(), g.end());
  p.insert(p.end(), g.begin(), g.begin() + 200);  // 100 duplicated points
  return p;
}

}  // namespace

TEST_CASE("Hilbert sort (2.3.5) table keys equal the keys of hilbertIndex one level at a time") {
  for (int depth : {1, 2, 3, 4, 5, 7, 8, 13, 16, 18, 21, 31}) {
    const XY p = mixedPoints(3000, unsigned(depth));
    INFO("depth " << depth);
    CHECK(dt::hilbertKeysFast(p, depth) == dt::hilbertKeys(p, depth));
  }
  const XY p = dttest::uniformPoints(50000, 4);
  CHECK(dt::hilbertKeysFast(p) == dt::hilbertKeys(p, 0));
  CHECK(dt::hilbertKeysFast({1, 2, 1, 2}) == dt::hilbertKeys({1, 2, 1, 2}, 0));
  CHECK_THROWS_AS(dt::hilbertKeysFast(p, 32), std::invalid_argument);
}

TEST_CASE("Hilbert sort (2.3.5) by radix gives the order of std::sort on key then index") {
  // depth 31 packs 62 key bits: with the index they exceed 64 bits (the comparison-sort path).
  // The fixed grid (adaptive = false): equal keys in index order.
  for (int depth : {0, 1, 3, 10, 20, 31}) {
    const XY p = mixedPoints(20000, 7 + unsigned(depth));
    INFO("depth " << depth);
    CHECK(dt::hilbertOrder(p, depth, false) == hilbertOrderRef(p, depth));
  }
  CHECK(dt::hilbertOrder({}).empty());
  CHECK(dt::hilbertOrder({2, 3}) == std::vector<std::size_t>{0});
}

TEST_CASE("Hilbert sort for BRIO in one sort gives the order of sorting each round by key then index") {
  for (int depth : {0, 2, 20, 31}) {
    const XY p = mixedPoints(20000, 17 + unsigned(depth));
    for (std::uint64_t seed : {1u, 5u}) {
      INFO("depth " << depth << " seed " << seed);
      CHECK(dt::brioOrder(p, seed, depth, nullptr, false) == brioOrderRef(p, seed, depth));
    }
  }
}

TEST_CASE("Hilbert sort for BRIO by biased coins (the fast kernel's order) puts 3/4 of the points in the last round and each round in Hilbert order") {
  const std::size_t n = 40000;
  const XY p = mixedPoints(n - 1000, 31);
  const std::vector<std::size_t> o = dt::brioCoinOrder(p, 3);
  std::vector<std::size_t> s = o;
  std::sort(s.begin(), s.end());
  std::vector<std::size_t> id(n);
  std::iota(id.begin(), id.end(), std::size_t{0});
  REQUIRE(s == id);
  // Rounds are runs of non-decreasing keys on the curve of brioCoinDepth levels (a crowded
  // cell's points are refined, so equal keys need not come in index order); a new round starts
  // where the key drops.
  const std::vector<std::uint64_t> keys = dt::hilbertKeys(p, dt::brioCoinDepth(n));
  std::vector<std::size_t> starts = {0};
  for (std::size_t k = 1; k < n; ++k)
    if (keys[o[k]] < keys[o[k - 1]]) starts.push_back(k);
  // 8 rounds, each one run; two consecutive runs merge when a round's last key happens to be
  // below the next round's first, which the first rounds (a few points each) may do.
  CHECK(starts.size() <= 8);
  CHECK(starts.size() >= 5);
  // The last round holds 3/4 of the points: binomial sd 0.0022, tolerance 0.01.
  CHECK(std::fabs(double(n - starts.back()) / double(n) - 0.75) < 0.01);
  CHECK(dt::brioCoinOrder(p, 3) == o);
  CHECK(dt::brioCoinOrder(p, 4) != o);
  // One round: the Hilbert sort on the same curve.
  CHECK(dt::brioCoinOrder(p, 3, 1) == dt::hilbertOrder(p, dt::brioCoinDepth(n)));
  CHECK(dt::brioCoinDepth(n) == 8 + 2);  // 4^8 = 65536 >= 40000
}

namespace {

// The length of the tour through the points in `order`, leaving out every step to or from a
// point outside [lo, hi]^2 (the outlier).
double tourWithin(const XY& p, const std::vector<std::size_t>& order, double lo, double hi) {
  auto in = [&](std::size_t i) {
    return p[2 * i] >= lo && p[2 * i] <= hi && p[2 * i + 1] >= lo && p[2 * i + 1] <= hi;
  };
  double len = 0;
  for (std::size_t k = 1; k < order.size(); ++k) {
    const std::size_t a = order[k - 1], b = order[k];
    if (in(a) && in(b)) len += std::hypot(p[2 * a] - p[2 * b], p[2 * a + 1] - p[2 * b + 1]);
  }
  return len;
}

bool isPermutation(std::vector<std::size_t> o, std::size_t n) {
  std::sort(o.begin(), o.end());
  for (std::size_t k = 0; k < o.size(); ++k)
    if (o[k] != k) return false;
  return o.size() == n;
}

}  // namespace

TEST_CASE("Hilbert sort (2.3.5) adaptive: still sorted by the fixed-grid key; equal points keep their input order") {
  for (int depth : {1, 3, 0}) {
    const XY p = mixedPoints(5000, 40 + unsigned(depth));
    const std::vector<std::size_t> o = dt::hilbertOrder(p, depth);
    const std::vector<std::uint64_t> keys = dt::hilbertKeys(p, depth);
    REQUIRE(isPermutation(o, keys.size()));
    INFO("depth " << depth);
    for (std::size_t k = 1; k < o.size(); ++k) {
      REQUIRE(keys[o[k - 1]] <= keys[o[k]]);
      if (p[2 * o[k - 1]] == p[2 * o[k]] && p[2 * o[k - 1] + 1] == p[2 * o[k] + 1])
        REQUIRE(o[k - 1] < o[k]);
    }
    // At depth 1 the 4 cells hold thousands of points each: the refinement reorders them.
    if (depth == 1) CHECK(o != dt::hilbertOrder(p, depth, false));
  }
}

TEST_CASE("Hilbert sort (2.3.5) adaptive: one far outlier leaves the others' tour as short as without it") {
  const std::size_t n = 20000;
  XY p = dt::outlierPoints(n, 5, 1e12);
  XY q;  // the same points without the outlier
  for (std::size_t i = 0; i < n; ++i)
    if (p[2 * i] < 2) q.insert(q.end(), {p[2 * i], p[2 * i + 1]});
  REQUIRE(q.size() == 2 * (n - 1));
  const double alone = tourWithin(q, dt::hilbertOrder(q), 0, 1);
  const double adaptive = tourWithin(p, dt::hilbertOrder(p), 0, 1);
  const double fixed = tourWithin(p, dt::hilbertOrder(p, 0, false), 0, 1);
  MESSAGE("tour of the uniform points: alone " << alone << ", with the outlier: adaptive "
          << adaptive << ", fixed grid " << fixed);
  CHECK(adaptive < 1.05 * alone);
  CHECK(fixed > 20 * alone);  // a random order: about n/2 against 0.98 sqrt(n)
  // The same for the orders the kernels use (BRIO's rounds lengthen every tour alike).
  const double coin = tourWithin(p, dt::brioCoinOrder(p, 1), 0, 1);
  const double coinAlone = tourWithin(q, dt::brioCoinOrder(q, 1), 0, 1);
  CHECK(coin < 1.2 * coinAlone);
  CHECK(tourWithin(p, dt::brioCoinOrder(p, 1, 8, false), 0, 1) > 10 * coinAlone);
  const double brio = tourWithin(p, dt::brioOrder(p, 1), 0, 1);
  CHECK(brio < 1.2 * tourWithin(q, dt::brioOrder(q, 1), 0, 1));
}

TEST_CASE("Hilbert sort (2.3.5) adaptive: a cluster of width 1e-9 beside uniform points is toured like uniform points") {
  const std::size_t n = 20000;
  const XY p = dt::clusterBesideUniform(n, 6, 1e-9);
  auto clusterTour = [&](const std::vector<std::size_t>& o) {
    std::vector<std::size_t> inCluster;
    for (std::size_t i : o)
      if (std::fabs(p[2 * i] - 0.3) < 1e-9 && std::fabs(p[2 * i + 1] - 0.7) < 1e-9)
        inCluster.push_back(i);
    double len = 0;
    for (std::size_t k = 1; k < inCluster.size(); ++k) {
      const std::size_t a = inCluster[k - 1], b = inCluster[k];
      len += std::hypot(p[2 * a] - p[2 * b], p[2 * a + 1] - p[2 * b + 1]);
    }
    return len;
  };
  // 2000 points in a square of side 1e-9: a Hilbert tour about 0.98 sqrt(2000) 1e-9 = 4.4e-8.
  const double adaptive = clusterTour(dt::hilbertOrder(p));
  const double fixed = clusterTour(dt::hilbertOrder(p, 0, false));
  MESSAGE("tour of the cluster: adaptive " << adaptive << ", fixed grid " << fixed);
  CHECK(adaptive < 1.2 * 0.98 * std::sqrt(2000.0) * 1e-9);
  CHECK(fixed > 10 * adaptive);
}

TEST_CASE("Hilbert sort (2.3.5) adaptive: points at every scale of the double range and duplicates terminate") {
  XY p = dt::exponentSpreadPoints(3000, 8);
  const XY d = dt::logRadiusPoints(3000, 9);
  p.insert(p.end(), d.begin(), d.end());
  p.insert(p.end(), d.begin(), d.begin() + 1000);  // 500 duplicated points
  for (int e = -1074; e <= 1023; ++e) p.insert(p.end(), {std::ldexp(1.0, e), 0.0});
  CHECK(isPermutation(dt::hilbertOrder(p), p.size() / 2));
  CHECK(isPermutation(dt::brioCoinOrder(p, 2), p.size() / 2));
}

TEST_CASE("Hilbert sort (2.3.5) adaptive: clusters nested two deep are toured like uniform points") {
  // 4000 uniform points in the unit square, 4000 in a square of side 1e-150 and, inside that,
  // 8000 in a square of side 1e-300: the innermost cluster is reached after two refinements.
  const std::size_t m = 8000;
  XY p = dt::uniformPoints(4000, 21);
  const XY mid = dt::uniformPoints(4000, 22, 0, 1e-150);  // at the origin: widths this small
  const XY in = dt::uniformPoints(m, 23, 0, 1e-300);      // need no large offset
  p.insert(p.end(), mid.begin(), mid.end());
  p.insert(p.end(), in.begin(), in.end());
  p.insert(p.end(), in.begin(), in.begin() + 400);  // 200 duplicated points
  dt::shufflePoints(p, 24);
  auto innerTour = [&](const std::vector<std::size_t>& o) {
    double len = 0;
    std::size_t prev = o.size();
    for (std::size_t i : o) {
      if (p[2 * i] > 1e-300 || p[2 * i + 1] > 1e-300) continue;
      if (prev != o.size())
        len += std::hypot(p[2 * i] - p[2 * prev], p[2 * i + 1] - p[2 * prev + 1]);
      prev = i;
    }
    return len / 1e-300;  // in units of the cluster's side
  };
  const std::vector<std::size_t> o = dt::hilbertOrder(p);
  REQUIRE(isPermutation(o, p.size() / 2));
  const double adaptive = innerTour(o), fixed = innerTour(dt::hilbertOrder(p, 0, false));
  MESSAGE("tour of the innermost cluster / side: adaptive " << adaptive << ", fixed grid "
          << fixed << ", sqrt(m) = " << std::sqrt(double(m)));
  // A Hilbert tour of m uniform points is about sqrt(m) sides long; a random order, m / 2.
  CHECK(adaptive < 1.3 * std::sqrt(double(m)));
  CHECK(fixed > 20 * std::sqrt(double(m)));
  // Equal points keep their input order.
  std::vector<std::size_t> pos(o.size());
  for (std::size_t k = 0; k < o.size(); ++k) pos[o[k]] = k;
  std::map<std::pair<double, double>, std::size_t> firstSeen;
  long misordered = 0, pairs = 0;
  for (std::size_t i = 0; i < o.size(); ++i) {
    const auto key = std::make_pair(p[2 * i], p[2 * i + 1]);
    const auto it = firstSeen.find(key);
    if (it == firstSeen.end()) {
      firstSeen.emplace(key, i);
    } else {
      ++pairs;
      misordered += pos[it->second] > pos[i];
    }
  }
  CHECK(pairs == 200);
  CHECK(misordered == 0);
}

namespace {

// ---- the frame a refined cell is sorted in, computed with Listing 2.8's floating frames ----
// (HilbertCoord and hilbertChild), not with the integer tables the sort uses.

// The frame of the cell of (x, y) `depth` levels below frame f.
dt::HilbertFrame cellFrame(dt::HilbertFrame f, double x, double y, int depth) {
  std::vector<int> bits(std::size_t(depth) + 1);
  dt::HilbertCoord(x, y, f.x0, f.y0, f.xRed, f.yRed, f.xBlue, f.yBlue, depth, bits.data());
  for (int l = 0; l < depth; ++l) f = dt::hilbertChild(f, bits[std::size_t(l)]);
  return f;
}

// f's orientation over the square box of the points `idx` (corner at their minima, side the
// larger extent): the frame the refinement sorts those points in.
dt::HilbertFrame boxFrame(const dt::HilbertFrame& f, const XY& p, const std::vector<std::size_t>& idx) {
  double x0 = p[2 * idx[0]], x1 = x0, y0 = p[2 * idx[0] + 1], y1 = y0;
  for (std::size_t i : idx) {
    x0 = std::min(x0, p[2 * i]), x1 = std::max(x1, p[2 * i]);
    y0 = std::min(y0, p[2 * i + 1]), y1 = std::max(y1, p[2 * i + 1]);
  }
  const double h = std::max(x1 / 2 - x0 / 2, y1 / 2 - y0 / 2);
  auto unit = [](double v) { return double((v > 0) - (v < 0)); };
  return {x0 + h, y0 + h, unit(f.xRed) * h, unit(f.yRed) * h, unit(f.xBlue) * h, unit(f.yBlue) * h};
}

std::uint64_t listingKey(const dt::HilbertFrame& f, double x, double y, int depth) {
  std::vector<int> bits(std::size_t(depth) + 1);
  dt::HilbertCoord(x, y, f.x0, f.y0, f.xRed, f.yRed, f.xBlue, f.yBlue, depth, bits.data());
  return dt::hilbertPack(bits.data(), depth);
}

bool sameOrientation(const dt::HilbertFrame& f, const dt::HilbertFrame& g) {
  auto sg = [](double v) { return (v > 0) - (v < 0); };
  return sg(f.xRed) == sg(g.xRed) && sg(f.yRed) == sg(g.yRed) && sg(f.xBlue) == sg(g.xBlue) &&
         sg(f.yBlue) == sg(g.yBlue);
}

// The points of `run` in the order o, in frame f at `depth`: their listing keys never decrease.
bool alongCurve(const XY& p, const std::vector<std::size_t>& o, const std::vector<std::size_t>& run,
                const dt::HilbertFrame& f, int depth) {
  std::vector<char> in(p.size() / 2, 0);
  for (std::size_t i : run) in[i] = 1;
  std::uint64_t last = 0;
  std::size_t seen = 0;
  for (std::size_t i : o) {
    if (!in[i]) continue;
    const std::uint64_t k = listingKey(f, p[2 * i], p[2 * i + 1], depth);
    if (seen++ > 0 && k < last) return false;
    last = k;
  }
  return seen == run.size();
}

}  // namespace

TEST_CASE("Hilbert sort (2.3.5) adaptive: a refined cell is ordered along the curve in the frame in which the curve enters it") {
  // 4000 uniform points; cluster A (5000 points, side 1e-8: refined by the radix branch) holding
  // cluster B (600 points, side 1e-13: refined again, inside A's refinement); cluster C (600
  // points, side 1e-6: the comparison-sort branch). A and B sit near the origin, where doubles
  // resolve their 43 levels of cells (the floating frames of the listing would not near 0.3). Each cluster sits in one cell of the grid
  // above it, whose curve frame is not the frame of the grid above: sorting it in the wrong
  // frame (the root's, or the parent cell's) visits it in another order.
  XY p = dt::uniformPoints(4000, 31);
  auto addCluster = [&p](std::size_t m, std::uint64_t seed, double x, double y, double side) {
    const XY c = dt::uniformPoints(m, seed, 0, side);
    std::vector<std::size_t> idx;
    for (std::size_t i = 0; i < m; ++i) {
      idx.push_back(p.size() / 2);
      p.insert(p.end(), {x + c[2 * i], y + c[2 * i + 1]});
    }
    return idx;
  };
  std::vector<std::size_t> A = addCluster(5000, 32, 1.1e-7, 2.3e-7, 1e-8);
  const std::vector<std::size_t> B = addCluster(600, 33, 1.1e-7 + 3.3e-9, 2.3e-7 + 6.1e-9, 1e-13);
  const std::vector<std::size_t> C = addCluster(600, 34, 0.4302, 0.6204, 1e-6);
  A.insert(A.end(), B.begin(), B.end());  // A's cell holds B

  const std::size_t n = p.size() / 2;
  const int top = dt::hilbertAutoDepth(n);
  const std::vector<std::uint64_t> keys = dt::hilbertKeys(p, 0);
  // The points of the top-level cell of a cluster (a uniform point could share it).
  auto cellOf = [&](const std::vector<std::size_t>& cl) {
    std::vector<std::size_t> run;
    for (std::size_t i = 0; i < n; ++i)
      if (keys[i] == keys[cl[0]]) run.push_back(i);
    return run;
  };
  const std::vector<std::size_t> runA = cellOf(A), runC = cellOf(C);
  REQUIRE(runA.size() >= A.size());
  REQUIRE(runA.size() >= 4096);  // the radix branch of the refinement
  REQUIRE(runC.size() >= C.size());
  REQUIRE(runC.size() < 4096);   // the std::sort branch

  const dt::HilbertBox box = dt::hilbertBox(p);
  const dt::HilbertFrame root = {box.xmin + box.halfSide, box.ymin + box.halfSide, box.halfSide, 0, 0,
                                 box.halfSide};
  const dt::HilbertFrame fA = boxFrame(cellFrame(root, p[2 * A[0]], p[2 * A[0] + 1], top), p, runA);
  const dt::HilbertFrame fC = boxFrame(cellFrame(root, p[2 * C[0]], p[2 * C[0] + 1], top), p, runC);
  // B inside A's refinement: A's grid has hilbertAutoDepth(|runA|) levels over A's box.
  const int depthA = dt::hilbertAutoDepth(runA.size());
  std::vector<std::size_t> runB;
  const std::uint64_t keyB = listingKey(fA, p[2 * B[0]], p[2 * B[0] + 1], depthA);
  for (std::size_t i : runA)
    if (listingKey(fA, p[2 * i], p[2 * i + 1], depthA) == keyB) runB.push_back(i);
  REQUIRE(runB.size() == B.size());
  const dt::HilbertFrame fB = boxFrame(cellFrame(fA, p[2 * B[0]], p[2 * B[0] + 1], depthA), p, runB);
  // The test means something only if the frames differ from the frame above them.
  REQUIRE_FALSE(sameOrientation(fA, root));
  REQUIRE_FALSE(sameOrientation(fC, root));
  REQUIRE_FALSE(sameOrientation(fB, fA));

  const std::vector<std::size_t> o = dt::hilbertOrder(p);
  REQUIRE(isPermutation(o, n));
  CHECK(alongCurve(p, o, runA, fA, depthA));
  CHECK(alongCurve(p, o, runB, fB, dt::hilbertAutoDepth(runB.size())));
  CHECK(alongCurve(p, o, runC, fC, dt::hilbertAutoDepth(runC.size())));
  // The same points in the root's frame are not in curve order: what a wrong frame gives.
  CHECK_FALSE(alongCurve(p, o, runC, boxFrame(root, p, runC), dt::hilbertAutoDepth(runC.size())));
}
