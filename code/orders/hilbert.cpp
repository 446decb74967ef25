#include "hilbert.h"

#include <algorithm>
#include <cmath>
#include <new>
#include <numeric>
#include <stdexcept>
#include <string>
#include <utility>

#include "huge_pages.h"
#include "parallel_for.h"

namespace dt {

//! [HilbertCoord]
void HilbertCoord(double x, double y, double x0, double y0, double xRed, double yRed,
                  double xBlue, double yBlue, int d, int bits[]) {
  // The printed listing let a NaN fail all four tests, so bits[i] was never written.
  if (!std::isfinite(x) || !std::isfinite(y))
    throw std::invalid_argument("HilbertCoord: coordinate is not finite");
  if (d < 0) throw std::invalid_argument("HilbertCoord: negative depth");
  for (int i = 0; i < d; i++) {
    const double coordRed = (x - x0) * xRed + (y - y0) * yRed;
    const double coordBlue = (x - x0) * xBlue + (y - y0) * yBlue;
    xRed /= 2; yRed /= 2; xBlue /= 2; yBlue /= 2;
    // Ties: the printed tests overlapped on the dividing lines (<= and >=) and only their
    // order decided. Here the chain is explicit: a point on a line goes to the lower quadrant,
    // and the last branch is unconditional, so every point gets exactly one quadrant.
    if (coordRed <= 0) {
      if (coordBlue <= 0) {  // quadrant 0: b <- r/2, r <- b/2
        x0 -= (xBlue + xRed); y0 -= (yBlue + yRed);
        std::swap(xRed, xBlue); std::swap(yRed, yBlue);
        bits[i] = 0;
      } else {               // quadrant 1: b <- b/2, r <- r/2
        x0 += (xBlue - xRed); y0 += (yBlue - yRed);
        bits[i] = 1;
      }
    } else {
      if (coordBlue >= 0) {  // quadrant 2: b <- b/2, r <- r/2
        x0 += (xBlue + xRed); y0 += (yBlue + yRed);
        bits[i] = 2;
      } else {               // quadrant 3: b <- -r/2, r <- -b/2
        x0 += (-xBlue + xRed); y0 += (-yBlue + yRed);
        std::swap(xRed, xBlue); std::swap(yRed, yBlue);
        xBlue = -xBlue; yBlue = -yBlue;
        xRed = -xRed; yRed = -yRed;
        bits[i] = 3;
      }
    }
  }
}
//! [HilbertCoord]

HilbertFrame hilbertChild(const HilbertFrame& f, int q) {
  if (q < 0 || q > 3) throw std::invalid_argument("hilbertChild: quadrant must be 0..3");
  HilbertFrame c = f;
  const double xr = f.xRed / 2, yr = f.yRed / 2, xb = f.xBlue / 2, yb = f.yBlue / 2;
  c.xRed = xr; c.yRed = yr; c.xBlue = xb; c.yBlue = yb;
  switch (q) {
    case 0:
      c.x0 -= xb + xr; c.y0 -= yb + yr;
      c.xRed = xb; c.yRed = yb; c.xBlue = xr; c.yBlue = yr;
      break;
    case 1: c.x0 += xb - xr; c.y0 += yb - yr; break;
    case 2: c.x0 += xb + xr; c.y0 += yb + yr; break;
    default:
      c.x0 += xr - xb; c.y0 += yr - yb;
      c.xRed = -xb; c.yRed = -yb; c.xBlue = -xr; c.yBlue = -yr;
      break;
  }
  return c;
}

std::uint64_t hilbertPack(const int bits[], int d) {
  std::uint64_t key = 0;
  for (int i = 0; i < d; ++i) key = (key << 2) | std::uint64_t(bits[i] & 3);
  return key;
}

//! [hilbertIndex]
namespace {

// Listing 2.8 on integers: the frame's state and the two bits of the cell at one level give
// the quadrant q and the next state; a table, built here from the listing's rules, replaces its
// branches.
// BEGIN SOLUTION 2.3.5-1 (remove)
// The state is s = 2 neg + swapped of the frame (red, blue): a 16-entry table.
// Why four states are enough (exercise 2.3.5-1): from the root (+x, +y) the frames take only
// four values, swapped or not, negated or not (quadrant 0 swaps, quadrant 3 swaps and negates,
// and both vectors always share a sign).
// END SOLUTION 2.3.5-1
struct HilbertTable {
  unsigned char next[16];  // (s << 2 | bx << 1 | by) -> (nextState << 2 | q)
  constexpr HilbertTable() : next() {
    for (int s = 0; s < 4; ++s)
      for (int bx = 0; bx < 2; ++bx)
        for (int by = 0; by < 2; ++by) {
          const bool swapped = (s & 1) != 0, neg = (s & 2) != 0;
          const bool plusRed = (swapped ? by : bx) != neg;   // red is +-x, or +-y if swapped
          const bool plusBlue = (swapped ? bx : by) != neg;
          const int q = plusRed ? (plusBlue ? 2 : 3) : (plusBlue ? 1 : 0);
          int t = s;
          if (q == 0) t ^= 1;  // b <- r/2, r <- b/2
          if (q == 3) t ^= 3;  // b <- -r/2, r <- -b/2
          next[s << 2 | bx << 1 | by] = static_cast<unsigned char>(t << 2 | q);
        }
  }
};
constexpr HilbertTable kHilbert;

}  // namespace

std::uint64_t hilbertIndex(std::uint32_t i, std::uint32_t j, int depth) {
  unsigned state = 0;  // the root frame: red = +x, blue = +y
  std::uint64_t key = 0;
  for (int s = depth - 1; s >= 0; --s) {
    const unsigned e = kHilbert.next[state << 2 | ((i >> s) & 1u) << 1 | ((j >> s) & 1u)];
    key = key << 2 | (e & 3u);
    state = e >> 2;
  }
  return key;
}
//! [hilbertIndex]

HilbertBox hilbertBox(const std::vector<double>& xy) {
  if (xy.size() % 2 != 0) throw std::invalid_argument("hilbertBox: odd number of coordinates");
  double xmin = 0, xmax = 0, ymin = 0, ymax = 0;
  for (std::size_t k = 0; k < xy.size(); k += 2) {
    const double x = xy[k], y = xy[k + 1];
    if (!std::isfinite(x) || !std::isfinite(y))
      throw std::invalid_argument("Hilbert sort: point " + std::to_string(k / 2) +
                                  " has a coordinate that is not finite");
    if (k == 0) {
      xmin = xmax = x;
      ymin = ymax = y;
    } else {
      xmin = std::min(xmin, x); xmax = std::max(xmax, x);
      ymin = std::min(ymin, y); ymax = std::max(ymax, y);
    }
  }
  // Halved differences: xmax - xmin overflows for coordinates near +-1e308, the halves do not.
  return {xmin, ymin, std::max(xmax / 2 - xmin / 2, ymax / 2 - ymin / 2)};
}

// ceil(log4 n), at most 31: the depth of about one point per cell on uniform data.
static int onePointPerCellDepth(std::size_t n) {
  int d = 0;
  while (d < 31 && (std::uint64_t{1} << (2 * d)) < n) ++d;
  return d;
}

int hilbertAutoDepth(std::size_t n) { return std::min(31, onePointPerCellDepth(n) + 8); }

int brioCoinDepth(std::size_t n) { return std::min(31, onePointPerCellDepth(n) + 2); }

namespace {

int checkedDepth(int depth, std::size_t n) {
  if (depth < 0 || depth > 31)
    throw std::invalid_argument("Hilbert sort: depth must be 0 (auto) .. 31, not " +
                                std::to_string(depth));
  return depth == 0 ? hilbertAutoDepth(n) : depth;
}

// Cell coordinate of v along one axis: floor(t 2^depth) with t = (v - lo) / side in [0, 1].
// Each operation rounds monotonically, so the map is monotone: equal inputs get equal cells
// and a point on a boundary lands on one side consistently.
std::uint32_t cellOf(double v, double lo, double halfSide, int depth) {
  if (!(halfSide > 0)) return 0;  // all points share this coordinate
  const double t = (v / 2 - lo / 2) / halfSide;  // in [0, 1] by construction of the box
  const double c = std::floor(std::ldexp(t, depth));
  const double top = std::ldexp(1.0, depth) - 1;
  return std::uint32_t(c < top ? c : top);
}

}  // namespace

std::vector<std::uint64_t> hilbertKeys(const std::vector<double>& xy, int depth) {
  const HilbertBox box = hilbertBox(xy);
  const std::size_t n = xy.size() / 2;
  depth = checkedDepth(depth, n);
  std::vector<std::uint64_t> keys(n);  // the reference: hilbertIndex, one level at a time
  for (std::size_t k = 0; k < n; ++k)
    keys[k] = hilbertIndex(cellOf(xy[2 * k], box.xmin, box.halfSide, depth),
                           cellOf(xy[2 * k + 1], box.ymin, box.halfSide, depth), depth);
  return keys;
}

std::vector<std::uint64_t> hilbertKeysListing(const std::vector<double>& xy, int depth) {
  const HilbertBox box = hilbertBox(xy);
  const std::size_t n = xy.size() / 2;
  depth = checkedDepth(depth, n);
  const double h = box.halfSide > 0 ? box.halfSide : 1;
  const double cx = box.xmin + h, cy = box.ymin + h;
  std::vector<std::uint64_t> keys(n);
  int bits[31];
  for (std::size_t k = 0; k < n; ++k) {
    HilbertCoord(xy[2 * k], xy[2 * k + 1], cx, cy, h, 0, 0, h, depth, bits);
    keys[k] = hilbertPack(bits, depth);
  }
  return keys;
}

// ---------------------------------------------------------------------------------------------
// The keys the sorts use: hilbertIndex four levels per table look-up. The state of its descent
// is the axis of "red" (blue is the other one) and the signs of red and blue: 8 states.
// four[state][4 bits of i, 4 bits of j] holds the 4 quadrant digits and the state after them;
// the tables are built once by running the listing's rules, so the keys are the same (the
// tests compare them with hilbertKeys).
namespace {

struct HilbertTables {
  std::uint16_t one[8][4];     // one level:  digit | next state << 8
  std::uint16_t four[8][256];  // four levels: 8 bits of key | next state << 8
  HilbertTables() {
    for (int s0 = 0; s0 < 8; ++s0)
      for (int in = 0; in < 256; ++in) {
        int s = s0, key = 0;
        for (int l = 3; l >= 0; --l) {
          const int d = step(s, (in >> (4 + l)) & 1, (in >> l) & 1);
          key = (key << 2) | (d & 3);
          s = d >> 8;
        }
        four[s0][in] = std::uint16_t(key | (s << 8));
        if (in < 4) one[s0][in] = std::uint16_t(step(s0, in >> 1, in & 1));
      }
  }
  // One level from state s for the bits bi (along x) and bj (along y).
  static int step(int s, int bi, int bj) {
    int redAxis = s & 1;
    bool redNeg = (s >> 1) & 1, blueNeg = (s >> 2) & 1;
    const int bit[2] = {bi, bj};
    const bool plusRed = (bit[redAxis] != 0) != redNeg;
    const bool plusBlue = (bit[1 - redAxis] != 0) != blueNeg;
    const int q = plusRed ? (plusBlue ? 2 : 3) : (plusBlue ? 1 : 0);
    if (q == 0 || q == 3) {
      redAxis = 1 - redAxis;
      std::swap(redNeg, blueNeg);
      if (q == 3) {
        redNeg = !redNeg;
        blueNeg = !blueNeg;
      }
    }
    return q | ((redAxis | int(redNeg) << 1 | int(blueNeg) << 2) << 8);
  }
};

// `lookups`, when given, counts the table look-ups (HilbertWork).
std::uint64_t hilbertIndexByTable(std::uint32_t i, std::uint32_t j, int depth, int& s,
                                  std::uint64_t* lookups = nullptr) {
  static const HilbertTables T;
  std::uint64_t key = 0;
  int l = depth;
  for (; l % 4 != 0; --l) {
    if (lookups) ++*lookups;
    const int d = T.one[s][(((i >> (l - 1)) & 1) << 1) | ((j >> (l - 1)) & 1)];
    key = (key << 2) | std::uint64_t(d & 3);
    s = d >> 8;
  }
  for (; l > 0; l -= 4) {
    if (lookups) ++*lookups;
    const int d = T.four[s][(((i >> (l - 4)) & 15) << 4) | ((j >> (l - 4)) & 15)];
    key = (key << 8) | std::uint64_t(d & 255);
    s = d >> 8;
  }
  return key;
}

// The cells of one box: cellOf with its powers of two computed once (t 2^depth is exact, so the
// cells are equal to cellOf's).
struct BoxCells {
  HilbertBox box;
  int depth;
  double scale, top;
  std::uint64_t* lookups = nullptr;  // counts the table look-ups when set (HilbertWork)
  BoxCells(const HilbertBox& b, int d)
      : box(b), depth(d), scale(std::ldexp(1.0, d)), top(std::ldexp(1.0, d) - 1) {}
  std::uint32_t cell(double v, double lo) const {
    if (!(box.halfSide > 0)) return 0;
    const double c = std::floor((v / 2 - lo / 2) / box.halfSide * scale);
    return std::uint32_t(c < top ? c : top);
  }
  // The key of point k on the curve that starts in `state`; `state` becomes the cell's state.
  std::uint64_t key(const std::vector<double>& xy, std::size_t k, int& state) const {
    return hilbertIndexByTable(cell(xy[2 * k], box.xmin), cell(xy[2 * k + 1], box.ymin), depth,
                               state, lookups);
  }
};

// Calls f(k, key of point k) for every point, keys equal to hilbertKeys'.
template <class F>
void forEachKey(const std::vector<double>& xy, int depth, F f, HilbertWork* work = nullptr) {
  BoxCells cells(hilbertBox(xy), depth);  // the box also refuses NaN and infinities
  if (work) cells.lookups = &work->keyLookups;
  const std::size_t n = xy.size() / 2;
  if (work) work->keyBytes += n * 2 * sizeof(double);  // each point's coordinates read once
  for (std::size_t k = 0; k < n; ++k) {
    int state = 0;  // red = +x, blue = +y
    f(k, cells.key(xy, k, state));
  }
}

int bitsFor(std::size_t n) {  // smallest b with n <= 2^b
  int b = 0;
  while ((std::size_t{1} << b) < n) ++b;
  return b;
}

// Stable least-significant-digit radix sort of the n words a on their bits [lo, hi), with b
// (n words) as the other buffer of the passes. Each pass keeps the order of equal digits, so
// words equal on [lo, hi) keep their input order. Returns the buffer, a or b, that holds the
// sorted words. `work`, when given, counts the passes and the bytes read and written.
std::uint64_t* radixSort(std::uint64_t* a, std::uint64_t* b, std::size_t n, int lo, int hi,
                         HilbertWork* work = nullptr) {
  if (hi <= lo || n < 2) return a;
  if (work) work->sortBytes += n * sizeof(std::uint64_t);  // the histogram sweep reads a
  const int passes = (hi - lo + 12) / 13;  // digits of at most 13 bits: 8192 counters fit L2
  const int digit = (hi - lo + passes - 1) / passes;
  const std::uint64_t mask = (std::uint64_t{1} << digit) - 1;
  std::vector<std::uint32_t> count(std::size_t(passes) << digit, 0);
  for (std::size_t k = 0; k < n; ++k)  // the histograms of all the passes in one sweep
    for (int q = 0; q < passes; ++q)
      ++count[(std::size_t(q) << digit) + ((a[k] >> (lo + digit * q)) & mask)];
  for (int q = 0; q < passes; ++q) {
    std::uint32_t* c = &count[std::size_t(q) << digit];
    std::uint32_t sum = 0;
    for (std::size_t d = 0; d <= mask; ++d) sum += std::exchange(c[d], sum);
    const int sh = lo + digit * q;
    for (std::size_t k = 0; k < n; ++k) b[c[(a[k] >> sh) & mask]++] = a[k];
    if (work) {
      ++work->sortPasses;
      work->sortBytes += 2 * n * sizeof(std::uint64_t);  // a read, b written
    }
    std::swap(a, b);
  }
  return a;
}

// radixSort of a whole vector, with a buffer of its own.
void radixSort(std::vector<std::uint64_t>& a, int lo, int hi, HilbertWork* work = nullptr) {
  if (hi <= lo || a.size() < 2) return;
  std::vector<std::uint64_t> b = hugeVector<std::uint64_t>(a.size());
  if (radixSort(a.data(), b.data(), a.size(), lo, hi, work) != a.data()) a.swap(b);
}

//! [adaptiveHilbert]
// The adaptive refinement. A fixed grid over the bounding box puts a dense cluster, or all the
// points but one far outlier, into a single cell, and a cell's points come in input order: a
// random order, for which walks are long. So every cell that holds more than a few points is
// ordered again, by the same curve over the bounding box of its own points, started in the state
// in which the curve enters the cell (so that it still enters and leaves on the right sides),
// and so on recursively: in effect, the keys are refined wherever points are dense.
// Termination: a refined cell's points span at most one cell, 2^-depth (depth >= 9) of the box
// they were sorted in, so every level shrinks the box by at least 2^8, and after a few hundred
// levels (the ratio of the largest to the smallest double, 2^2098) the box is flat: equal
// points, which keep their input order. Uniform data has almost no shared cells: it costs a scan.
// A cell of at most this many points keeps their input order: they are neighbours anyway, and
// points on a curve share cells two by two, where refining them would cost more than it saves.
constexpr std::size_t kSmallCell = 4;

// Orders idx[0..len) (one cell's points, curve state `state`) along the curve over their box.
void sortRun(const std::vector<double>& xy, std::size_t* idx, std::size_t len, int state) {
  HilbertBox b{xy[2 * idx[0]], xy[2 * idx[0] + 1], 0};
  double xmax = b.xmin, ymax = b.ymin;
  for (std::size_t k = 1; k < len; ++k) {
    const double x = xy[2 * idx[k]], y = xy[2 * idx[k] + 1];
    b.xmin = std::min(b.xmin, x); xmax = std::max(xmax, x);
    b.ymin = std::min(b.ymin, y); ymax = std::max(ymax, y);
  }
  b.halfSide = std::max(xmax / 2 - b.xmin / 2, ymax / 2 - b.ymin / 2);
  if (!(b.halfSide > 0)) return;  // all equal: input order
  const BoxCells cells(b, hilbertAutoDepth(len));
  std::vector<std::pair<std::size_t, std::size_t>> runs;  // [begin, end) of shared cells
  {  // scoped: the keys are freed before the recursion, which may go a few hundred levels deep
    // (key, position): stable. Most shared cells hold two or three points (points on a curve,
    // clusters): those stay on the stack.
    std::pair<std::uint64_t, std::size_t> kvSmall[16];
    std::size_t oldSmall[16];
    std::vector<std::pair<std::uint64_t, std::size_t>> kvBig(len <= 16 ? 0 : len);
    std::vector<std::size_t> oldBig(len <= 16 ? 0 : len);
    std::pair<std::uint64_t, std::size_t>* const kv = len <= 16 ? kvSmall : kvBig.data();
    const int posBits = bitsFor(len), keyBits = 2 * cells.depth;
    if (len >= 4096 && keyBits + posBits <= 64) {  // large runs (an outlier's): the radix sort
      std::vector<std::uint64_t> w(len);
      for (std::size_t k = 0; k < len; ++k) {
        int s = state;
        w[k] = cells.key(xy, idx[k], s) << posBits | k;
      }
      radixSort(w, posBits, posBits + keyBits);
      const std::uint64_t mask = (std::uint64_t{1} << posBits) - 1;
      for (std::size_t k = 0; k < len; ++k) kv[k] = {w[k] >> posBits, std::size_t(w[k] & mask)};
    } else {
      for (std::size_t k = 0; k < len; ++k) {
        int s = state;
        kv[k] = {cells.key(xy, idx[k], s), k};
      }
      std::sort(kv, kv + len);
    }
    std::size_t* const old = len <= 16 ? oldSmall : oldBig.data();
    std::copy(idx, idx + len, old);
    for (std::size_t k = 0; k < len; ++k) idx[k] = old[kv[k].second];
    if (kv[0].first == kv[len - 1].first) return;  // no split (cannot happen: safety)
    for (std::size_t a = 0, e; a < len; a = e) {
      for (e = a + 1; e < len && kv[e].first == kv[a].first;) ++e;
      if (e - a > kSmallCell) runs.emplace_back(a, e);
    }
  }
  for (const auto& r : runs) {
    int s = state;
    cells.key(xy, idx[r.first], s);  // the state of this cell
    sortRun(xy, idx + r.first, r.second - r.first, s);
  }
}

// Refines the runs of equal words (same cell of the grid of `cells`, same group) of a sorted
// order: `same(a, b)` says whether positions a and b of the order share a cell.
template <class Same>
void refineSorted(const std::vector<double>& xy, const BoxCells& cells, std::size_t* order,
                  std::size_t n, Same same) {
  for (std::size_t a = 0, e; a < n; a = e) {
    for (e = a + 1; e < n && same(a, e);) ++e;
    if (e - a <= kSmallCell) continue;
    int s = 0;
    cells.key(xy, order[a], s);
    sortRun(xy, order + a, e - a, s);
  }
}
//! [adaptiveHilbert]

// Sorts the points by (group, key, index), group[k] < 2^groupBits (none if groupBits = 0),
// with one radix sort of (group, key, index) packed in 64 bits when they fit, else std::sort.
std::vector<std::size_t> sortByGroupKeyIndex(const std::vector<double>& xy, int depth,
                                             const std::vector<std::uint32_t>& group,
                                             int groupBits, bool adaptive,
                                             HilbertWork* work = nullptr) {
  const std::size_t n = xy.size() / 2;
  const int idxBits = bitsFor(n);
  const int keyBits = 2 * depth;
  std::vector<std::size_t> order = hugeVector<std::size_t>(n);
  if (groupBits + keyBits + idxBits <= 64) {
    std::vector<std::uint64_t> w = hugeVector<std::uint64_t>(n);
    forEachKey(xy, depth, [&](std::size_t k, std::uint64_t key) {
      const std::uint64_t g = groupBits ? group[k] : 0;
      w[k] = (((g << keyBits) | key) << idxBits) | k;
    }, work);
    if (work) work->keyBytes += n * sizeof(std::uint64_t);  // the packed words written
    // The words are in index order and the sort is stable: the index bits need no pass.
    radixSort(w, idxBits, idxBits + keyBits + groupBits, work);
    const std::uint64_t idxMask = (std::uint64_t{1} << idxBits) - 1;
    for (std::size_t k = 0; k < n; ++k) order[k] = std::size_t(w[k] & idxMask);
    if (work) work->sortBytes += n * (sizeof(std::uint64_t) + sizeof(std::size_t));  // unpacked
    if (adaptive)
      refineSorted(xy, BoxCells(hilbertBox(xy), depth), order.data(), n,
                   [&](std::size_t a, std::size_t b) { return (w[a] >> idxBits) == (w[b] >> idxBits); });
    return order;
  }
  // More than 2^64 combinations (n beyond 2^24 or so at the auto depth): a comparison sort.
  struct Item {
    std::uint32_t g;
    std::uint64_t key;
    std::size_t k;
    bool operator<(const Item& o) const {
      return g != o.g ? g < o.g : (key != o.key ? key < o.key : k < o.k);
    }
  };
  std::vector<Item> items(n);
  forEachKey(xy, depth, [&](std::size_t k, std::uint64_t key) {
    items[k] = {groupBits ? group[k] : 0u, key, k};
  });
  std::sort(items.begin(), items.end());
  for (std::size_t k = 0; k < n; ++k) order[k] = items[k].k;
  if (adaptive)
    refineSorted(xy, BoxCells(hilbertBox(xy), depth), order.data(), n,
                 [&](std::size_t a, std::size_t b) {
                   return items[a].g == items[b].g && items[a].key == items[b].key;
                 });
  return order;
}

// radixSort with `threads` threads: the same passes, each over the whole array cut into
// consecutive chunks, one thread a chunk. Per pass, every thread counts the digits of its chunk;
// then element of digit d from chunk t goes after all the smaller digits and after digit d of
// the chunks before t, in chunk order: the pass is stable, as the sequential one, so the result
// is the same array.
std::uint64_t* radixSortParallel(std::uint64_t* a, std::uint64_t* b, std::size_t n, int lo,
                                 int hi, int threads) {
  if (hi <= lo || n < 2) return a;
  const int passes = (hi - lo + 12) / 13;
  const int digit = (hi - lo + passes - 1) / passes;
  const std::size_t radix = std::size_t{1} << digit, mask = radix - 1;
  const std::size_t T = std::size_t(threads);
  std::vector<std::uint32_t> count(T * radix);  // count[t radix + d]: digit d in chunk t
  for (int q = 0; q < passes; ++q) {
    const int sh = lo + digit * q;
    parallelFor(threads, n, [&](int t, std::size_t from, std::size_t to) {
      std::uint32_t* c = &count[std::size_t(t) * radix];
      std::fill(c, c + radix, 0u);
      for (std::size_t k = from; k < to; ++k) ++c[(a[k] >> sh) & mask];
    });
    std::uint32_t sum = 0;  // the chunks' starts, digit by digit, chunk by chunk
    for (std::size_t d = 0; d < radix; ++d)
      for (std::size_t t = 0; t < T; ++t) sum += std::exchange(count[t * radix + d], sum);
    parallelFor(threads, n, [&](int t, std::size_t from, std::size_t to) {
      std::uint32_t* c = &count[std::size_t(t) * radix];
      for (std::size_t k = from; k < to; ++k) b[c[(a[k] >> sh) & mask]++] = a[k];
    });
    std::swap(a, b);
  }
  return a;
}

// The twin of sortByGroupKeyIndex's packed path that computes the groups itself (groupOf(k),
// no array of them), drops levels of the curve until (group, key, index) fit in 64 bits (the
// key of a coarser curve: the same order up to more ties, broken by the refinement when
// `adaptive`, else by index), and with `threads` > 1 runs in parallel. Every step is cut into
// consecutive pieces, one thread a piece, and none changes the result:
// the words (group, key, index) are computed piece by piece, the radix sort is the sequential
// one's passes (radixSortParallel), and the refinement is cut only between runs of equal
// (group, key), each run refined as before. So the order is the sequential one, bit for bit
// (the fast kernel's tests compare them), whatever the number of threads.
// The n positions go to order, the words to w, and b is the radix sort's other buffer (n of
// each): the caller's memory (brioCoinOrder's own, or the fast kernel's, brioCoinOrderInto).
template <class GroupOf>
void sortByGroupKeyIndexThreads(const std::vector<double>& xy, int depth, GroupOf groupOf,
                                int groupBits, bool adaptive, int threads, std::size_t* order,
                                std::uint64_t* w, std::uint64_t* b) {
  const std::size_t n = xy.size() / 2;
  const int idxBits = bitsFor(n);
  depth = std::max(1, std::min(depth, (64 - groupBits - idxBits) / 2));
  const int keyBits = 2 * depth;
  const BoxCells cells(hilbertBox(xy), depth);
  parallelFor(threads, n, [&](int, std::size_t lo, std::size_t hi) {
    for (std::size_t k = lo; k < hi; ++k) {
      int s = 0;
      const std::uint64_t g = groupBits ? std::uint64_t(groupOf(k)) : 0;
      w[k] = (((g << keyBits) | cells.key(xy, k, s)) << idxBits) | k;
    }
  });
  // The words are in index order and the sort is stable: the index bits need no pass.
  w = threads > 1 ? radixSortParallel(w, b, n, idxBits, idxBits + keyBits + groupBits, threads)
                  : radixSort(w, b, n, idxBits, idxBits + keyBits + groupBits);  // (the same
                    // passes, their histograms counted in one sweep)
  const std::uint64_t idxMask = (std::uint64_t{1} << idxBits) - 1;
  parallelFor(threads, n, [&](int, std::size_t lo, std::size_t hi) {
    for (std::size_t k = lo; k < hi; ++k) order[k] = std::size_t(w[k] & idxMask);
  });
  if (!adaptive) return;
  auto same = [&](std::size_t a, std::size_t c) { return (w[a] >> idxBits) == (w[c] >> idxBits); };
  std::vector<std::size_t> cut(std::size_t(threads) + 1, n);  // piece t: [cut[t], cut[t + 1])
  for (int t = 0; t < threads; ++t) {
    std::size_t c = std::max(t ? cut[std::size_t(t) - 1] : 0, n * std::size_t(t) / std::size_t(threads));
    while (c > 0 && c < n && same(c - 1, c)) ++c;  // a piece starts where a run starts
    cut[std::size_t(t)] = c;
  }
  parallelFor(threads, std::size_t(threads), [&](int t, std::size_t, std::size_t) {
    const std::size_t from = cut[std::size_t(t)], len = cut[std::size_t(t) + 1] - from;
    refineSorted(xy, cells, order + from, len,
                 [&](std::size_t a, std::size_t c) { return same(from + a, from + c); });
  });
}

// splitmix64: a small, fully specified generator, so BRIO orders are the same everywhere.
std::uint64_t splitmix(std::uint64_t& s) {
  std::uint64_t z = (s += 0x9e3779b97f4a7c15ULL);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

}  // namespace

std::vector<std::uint64_t> hilbertKeysFast(const std::vector<double>& xy, int depth) {
  const std::size_t n = xy.size() / 2;
  depth = checkedDepth(depth, n);
  std::vector<std::uint64_t> keys(n);
  forEachKey(xy, depth, [&](std::size_t k, std::uint64_t key) { keys[k] = key; });
  return keys;
}

std::vector<std::size_t> hilbertOrder(const std::vector<double>& xy, int depth, bool adaptive) {
  if (xy.size() % 2 != 0) throw std::invalid_argument("hilbertBox: odd number of coordinates");
  return sortByGroupKeyIndex(xy, checkedDepth(depth, xy.size() / 2), {}, 0, adaptive);
}

std::vector<std::size_t> hilbertOrder(const std::vector<double>& xy, int depth, HilbertWork& work) {
  if (xy.size() % 2 != 0) throw std::invalid_argument("hilbertBox: odd number of coordinates");
  const std::size_t n = xy.size() / 2;
  depth = checkedDepth(depth, n);
  if (2 * depth + bitsFor(n) > 64)
    throw std::invalid_argument("hilbertOrder: the counted sort needs key and index in 64 bits");
  return sortByGroupKeyIndex(xy, depth, {}, 0, false, &work);
}

std::vector<std::size_t> brioRoundSizes(std::size_t n, std::size_t firstRound) {
  if (firstRound == 0) firstRound = 1;
  std::vector<std::size_t> sizes;  // last round first, reversed below
  while (n > firstRound) {
    const std::size_t last = n - n / 2;  // the larger half goes to the later round
    sizes.push_back(last);
    n -= last;
  }
  if (n > 0) sizes.push_back(n);
  std::reverse(sizes.begin(), sizes.end());
  return sizes;
}

//! [brioOrder]
std::vector<std::size_t> brioOrder(const std::vector<double>& xy, std::uint64_t seed, int depth,
                                   std::vector<std::size_t>* roundStart, bool adaptive) {
  if (xy.size() % 2 != 0) throw std::invalid_argument("hilbertBox: odd number of coordinates");
  const std::size_t n = xy.size() / 2;
  depth = checkedDepth(depth, n);
  std::vector<std::size_t> idx(n);
  std::iota(idx.begin(), idx.end(), std::size_t{0});
  // A uniform random permutation (Fisher-Yates), so each round is a random sample of the
  // points: the randomness that gives the expected O(n log n) bound whatever the input.
  std::uint64_t state = seed;
  for (std::size_t i = n; i > 1; --i) {
    const std::size_t j = std::size_t(splitmix(state) % i);  // bias below i / 2^64: negligible
    std::swap(idx[i - 1], idx[j]);
  }
  // Its first sizes[0] points form round 0, the next sizes[1] round 1, ... Then locality inside
  // each round: one sort by (round, Hilbert key over the whole data box, index).
  std::vector<std::uint32_t> round(n);
  if (roundStart) roundStart->clear();
  std::size_t start = 0;
  std::uint32_t r = 0;
  for (std::size_t size : brioRoundSizes(n)) {
    if (roundStart) roundStart->push_back(start);
    for (std::size_t k = start; k < start + size; ++k) round[idx[k]] = r;
    start += size;
    ++r;
  }
  return sortByGroupKeyIndex(xy, depth, round, bitsFor(r), adaptive);
}
//! [brioOrder]

int brioCoinRound(std::size_t i, std::uint64_t seed, int rounds) {
  // Pairs of zero bits of a hashed word: none w.p. 3/4 (last round), one w.p. 3/16, ...
  std::uint64_t s = seed ^ (0x632be59bd9b4e019ULL * (i + 1));
  const std::uint64_t h = splitmix(s);
  // z = the number of trailing zero pairs, at most rounds - 1 (h = 0 has them all).
  const int z = h == 0 ? rounds - 1 : std::min(rounds - 1, __builtin_ctzll(h) / 2);
  return rounds - 1 - z;
}

namespace {

// brioCoinOrder's checks, then its sort into the caller's memory.
void brioCoinSort(const std::vector<double>& xy, std::uint64_t seed, int rounds, bool adaptive,
                  int threads, std::size_t* order, std::uint64_t* w, std::uint64_t* b) {
  if (xy.size() % 2 != 0) throw std::invalid_argument("hilbertBox: odd number of coordinates");
  if (rounds < 1 || rounds > 32) throw std::invalid_argument("brioCoinOrder: rounds out of 1..32");
  const std::size_t n = xy.size() / 2;
  const int groupBits = rounds > 1 ? bitsFor(rounds) : 0;
  // One curve level at least must fit beside the round and the index: up to 2^57 points, far
  // more than an address space holds.
  if (groupBits + 2 + bitsFor(n) > 64)
    throw std::length_error("brioCoinOrder: more than 2^57 points");
  sortByGroupKeyIndexThreads(
      xy, brioCoinDepth(n), [&](std::size_t i) { return brioCoinRound(i, seed, rounds); },
      groupBits, adaptive, std::max(1, threads), order, w, b);
}

}  // namespace

std::vector<std::size_t> brioCoinOrder(const std::vector<double>& xy, std::uint64_t seed,
                                       int rounds, bool adaptive, int threads) {
  const std::size_t n = xy.size() / 2;
  // The order first, then the words: in the other order glibc's heap keeps more resident at
  // the command line's peak.
  std::vector<std::size_t> order = hugeVector<std::size_t>(n);
  std::vector<std::uint64_t> w = hugeVector<std::uint64_t>(n), b = hugeVector<std::uint64_t>(n);
  brioCoinSort(xy, seed, rounds, adaptive, threads, order.data(), w.data(), b.data());
  return order;
}

std::size_t brioCoinScratchBytes(std::size_t n) {
  return n * (sizeof(std::size_t) + 2 * sizeof(std::uint64_t)) + sizeof(std::uint64_t);
}

const std::size_t* brioCoinOrderInto(const std::vector<double>& xy, std::uint64_t seed,
                                     int rounds, void* scratch, bool adaptive, int threads) {
  const std::size_t n = xy.size() / 2;
  // Three arrays of trivial types begin their lifetimes in the lent memory (no initialisation):
  // the order at its start, then the words, aligned.
  std::size_t* order = ::new (scratch) std::size_t[n];
  const std::uintptr_t end = reinterpret_cast<std::uintptr_t>(order + n);
  const std::uintptr_t wAt = (end + alignof(std::uint64_t) - 1) & ~std::uintptr_t(alignof(std::uint64_t) - 1);
  std::uint64_t* w = ::new (reinterpret_cast<void*>(wAt)) std::uint64_t[2 * n];
  brioCoinSort(xy, seed, rounds, adaptive, threads, order, w, w + n);
  return order;
}

}  // namespace dt
