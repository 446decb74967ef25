// Section 2.3.5: Hilbert curves (Listing 2.8, corrected), the Hilbert sort of a point set, and
// BRIO (biased randomized insertion order), which the notes leave as "explain brio".
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace dt {

/// Listing 2.8: the first d Hilbert "coordinates" bits[0..d-1] (each 0..3) of the point (x, y),
/// in the quadrant of centre (x0, y0) whose half-sides are the orthogonal vectors
/// red = (xRed, yRed) and blue = (xBlue, yBlue). Quadrant 0 is x0 - (b+r)/2, 1 is x0 + (b-r)/2,
/// 2 is x0 + (b+r)/2, 3 is x0 + (r-b)/2 (r, b as half-sides). A point on a dividing line goes
/// to the lowest-numbered quadrant that touches it. Throws std::invalid_argument if a
/// coordinate is not finite or d < 0.
void HilbertCoord(double x, double y, double x0, double y0, double xRed, double yRed,
                  double xBlue, double yBlue, int d, int bits[]);

/// One node of the recursion of Listing 2.8: a quadrant's centre and half-side vectors.
struct HilbertFrame {
  double x0, y0, xRed, yRed, xBlue, yBlue;
};

/// The frame of sub-quadrant q (0..3) of f, exactly as HilbertCoord descends (Figure 2.11).
HilbertFrame hilbertChild(const HilbertFrame& f, int q);

/// Packs d base-4 digits (most significant first) into an integer: key = sum bits[i] 4^(d-1-i).
std::uint64_t hilbertPack(const int bits[], int d);

/// The Hilbert index, on the curve H_depth, of cell (i, j) of the 2^depth x 2^depth grid
/// (i along x, j along y; 0 <= i, j < 2^depth, depth <= 31), with the orientation of Listing
/// 2.8 started from red = +x, blue = +y. Integer only, hence exact; equal to
/// hilbertPack(HilbertCoord(cell centre)) for every cell.
std::uint64_t hilbertIndex(std::uint32_t i, std::uint32_t j, int depth);

/// The square box that hilbertKeys maps onto the grid: [xmin, xmin + side] x [ymin, ymin +
/// side], side the larger extent of the data. Throws std::invalid_argument on a non-finite
/// coordinate (NaN or infinity).
struct HilbertBox {
  double xmin, ymin;
  double halfSide;  ///< side / 2 (kept halved so that it never overflows, even for +-1e308)
};
HilbertBox hilbertBox(const std::vector<double>& xy);

/// The curve depth used when a caller passes depth = 0: ceil(log4 n) + 8 levels, at most 31.
/// log4 n levels would leave about one point per cell on uniform data; 8 more (a factor
/// 4^8 = 65536 in density) keep clustered data separated too (see the depth table of 2.3.5).
int hilbertAutoDepth(std::size_t n);

/// The curve depth of brioCoinOrder (the fast kernels' sort): ceil(log4 n) + 2 levels, at most
/// 31, about 16 cells a point on uniform data. Coarser than hilbertAutoDepth on purpose: the
/// adaptive refinement orders the few crowded cells, and every level fewer makes the keys
/// cheaper to compute and to sort (at 10^6 points, 24 key bits instead of 36: three radix
/// passes of 9 bits instead of three of 13, two table look-ups fewer per key).
int brioCoinDepth(std::size_t n);

/// Hilbert keys of the points xy = x0 y0 x1 y1 ... on H_depth (depth 1..31, 0 = auto): each
/// point is mapped to its cell of the 2^depth grid over hilbertBox(xy) (a monotone map, so
/// points on cell boundaries are assigned consistently), then to hilbertIndex. A key fits in
/// 62 bits. Throws std::invalid_argument on NaN/infinite coordinates or depth outside 0..31.
std::vector<std::uint64_t> hilbertKeys(const std::vector<double>& xy, int depth);

/// The same keys computed with Listing 2.8 itself (floating-point frames), for comparison and
/// timing. Points within rounding of a cell boundary may get the neighbouring cell's key.
std::vector<std::uint64_t> hilbertKeysListing(const std::vector<double>& xy, int depth);

/// The same keys as hilbertKeys, computed four curve levels per table look-up: what the sorts
/// below use (the tests check that they are equal).
std::vector<std::uint64_t> hilbertKeysFast(const std::vector<double>& xy, int depth = 0);

/// The Hilbert sort of 2.3.5: indices of the points ordered by Hilbert key. depth = 0 chooses
/// hilbertAutoDepth(n). One radix sort of (key, index) packed in 64 bits (a comparison sort when
/// they do not fit, beyond about 2^24 points). With `adaptive` (the default), the points
/// of a cell holding more than four are ordered again along the curve over their own bounding box,
/// recursively (keys refined where points are dense, so that a cluster or a far outlier does not
/// leave thousands of points in input order); equal points keep their input order. With
/// adaptive = false, the fixed grid of the notes: equal keys keep their input order.
/// Deterministic either way.
std::vector<std::size_t> hilbertOrder(const std::vector<double>& xy, int depth = 0,
                                      bool adaptive = true);

/// The work of hilbertOrder's fixed-grid sort, counted where it is done: the two sides of the
/// notes' "the main cost of sorting points is on the sorting algorithm itself and not on the
/// computation of the Hilbert curve coordinates" (2.3.5), at the same n.
struct HilbertWork {
  std::uint64_t keyLookups = 0;  ///< table look-ups made by the keys (up to 4 levels each)
  std::uint64_t keyBytes = 0;    ///< bytes the keys read (coordinates) and write (packed words)
  std::uint64_t sortPasses = 0;  ///< scatter passes of the radix sort
  std::uint64_t sortBytes = 0;   ///< bytes the sort reads and writes: histogram sweep, passes, unpacking
};

/// hilbertOrder(xy, depth, false) with its work added to `work`. Throws std::invalid_argument
/// where key and index do not fit one 64-bit word (beyond about 2^24 points), the one case in
/// which hilbertOrder uses a comparison sort instead of the radix sort counted here.
std::vector<std::size_t> hilbertOrder(const std::vector<double>& xy, int depth, HilbertWork& work);

/// Sizes of the BRIO rounds for n points, first round first: the last round holds the larger
/// half of the points, the one before half of the rest, and so on down to a first round of at
/// most `firstRound` points (Amenta, Choi, Rote 2003).
std::vector<std::size_t> brioRoundSizes(std::size_t n, std::size_t firstRound = 64);

/// BRIO: a random permutation (seeded, reproducible) cut into rounds of sizes brioRoundSizes(n),
/// each round then Hilbert-sorted on keys over the whole data box (equal keys by index). Returns
/// the insertion order; if roundStart is given it receives the index in that order where each
/// round starts. Sorted as hilbertOrder, on (round, key, index), adaptive (the points of one
/// round sharing a cell refined) unless adaptive = false.
std::vector<std::size_t> brioOrder(const std::vector<double>& xy, std::uint64_t seed,
                                   int depth = 0,
                                   std::vector<std::size_t>* roundStart = nullptr,
                                   bool adaptive = true);

/// BRIO with rounds drawn by biased coins (the fast kernel's default order): point i goes to the
/// last of `rounds` rounds with probability 3/4, to the one before with probability 3/16, and
/// so on (the ratio of CGAL's spatial sort; a hash of i and the seed plays the coin, so the
/// order is reproducible); each round in Hilbert order on the curve of brioCoinDepth(n) levels,
/// adaptive as hilbertOrder unless adaptive = false (then equal keys by index). When (round,
/// key, index) do not fit in 64 bits (beyond about 10^8 points) the curve is taken a few levels
/// coarser (the refinement makes up for it). With threads > 1 the same order, bit for bit, is
/// computed by that many threads: keys, the radix sort's passes and the refinement piece by
/// piece (the parallel kernel's sort).
std::vector<std::size_t> brioCoinOrder(const std::vector<double>& xy, std::uint64_t seed,
                                       int rounds = 8, bool adaptive = true, int threads = 1);

/// The bytes of memory brioCoinOrderInto needs for n points (three arrays of n words, at most).
std::size_t brioCoinScratchBytes(std::size_t n);

/// brioCoinOrder in memory the caller lends: `scratch` holds brioCoinScratchBytes(n) bytes,
/// aligned for 8-byte words, and the order is returned at its start (it lives there until the
/// caller reuses the memory). The fast kernels lend the memory of the adjacency array they fill
/// next: a fresh process then maps 24 bytes per point fewer new pages, which the operating
/// system must clear first (book/fast_kernel.md times that system time).
const std::size_t* brioCoinOrderInto(const std::vector<double>& xy, std::uint64_t seed,
                                     int rounds, void* scratch, bool adaptive = true,
                                     int threads = 1);

/// The round (0 = first, rounds - 1 = last) that brioCoinOrder(xy, seed, rounds) gives to point
/// i: the parallel kernel (fast_parallel.h) finds the rounds' boundaries in the order with it.
int brioCoinRound(std::size_t i, std::uint64_t seed, int rounds);

}  // namespace dt
