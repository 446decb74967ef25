/// \file generators.h
/// Point families with fixed seeds, shared by the chapter programs and the tests.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace dt {

struct Vertex;
class Triangulation;

/// Coordinates x0 y0 x1 y1 ... of a point set.
using XY = std::vector<double>;

// Every random family draws from std::mt19937_64(seed), whose output the standard fixes; the
// distributions are the standard library's, so a seed gives the same points on every run of
// one build. Each function's drawing order is part of its contract: the tables of the chapter
// programs are reproduced number for number from these seeds.

/// n points uniform in the square [lo, hi)^2 (x then y, point after point).
XY uniformPoints(std::size_t n, std::uint64_t seed, double lo = 0, double hi = 1);

/// n points uniform in the disk of radius R about the origin (r = sqrt(u), angle 2 pi u).
XY uniformDiskPoints(std::size_t n, std::uint64_t seed, double R = 1);

/// n points at uniform random angles on the unit circle (rounded cos, sin).
XY randomCirclePoints(std::size_t n, std::uint64_t seed);

/// n points in `clusters` Gaussian blobs whose centres are uniform in [0.1, 0.9]^2 and whose
/// widths range over a factor 50 (0.001 to 0.05), so that densities differ by about 2500.
XY gaussianClusters(std::size_t n, std::uint64_t seed, int clusters = 12);

/// The nx x ny grid (x0 + i step, y0 + j step), i outer, j inner: exactly cocircular
/// quadruples everywhere when the coordinates are exact.
XY gridPoints(int nx, int ny, double step = 1, double x0 = 0, double y0 = 0);

/// The integer nx x ny grid rotated exactly by the angle of cos = 3/5, sin = 4/5 (and scaled
/// by 5, so the coordinates stay integers): exactly cocircular, no edge axis-parallel.
XY rotatedGridPoints(int nx, int ny);

/// n points of a square grid of ceil(sqrt n) columns in [0, 1]^2, each moved by at most
/// `jitter` times the spacing, in random order: nearly cocircular quadruples everywhere.
XY jitteredGridPoints(std::size_t n, std::uint64_t seed, double jitter = 0.1);

/// n points on the circle of radius r about the origin at angles 2 pi k / n, rounded (so
/// nearly, not exactly, cocircular); point i is at k = (i * stride) mod n (stride coprime to
/// n gives the same points in another order).
XY circlePoints(std::size_t n, double r = 1, std::size_t stride = 1);

/// n points (x, x^2) with x uniform in [-1, 1): every point is on the hull of the others.
XY parabolaPoints(std::size_t n, std::uint64_t seed);

/// n - 1 points uniform in [0, 1)^2 and, at a seeded random position of the input, one far
/// outlier (far, far): the case that leaves a fixed-grid Hilbert order with one crowded cell
/// (section 2.3.5: the adaptive order's reason to exist).
XY outlierPoints(std::size_t n, std::uint64_t seed, double far = 1e12);

/// n points: 90 % uniform in [0, 1)^2, 10 % uniform in a square of side `width` about
/// (0.3, 0.7), in seeded random order (a dense cluster beside sparse data, 2.3.5).
XY clusterBesideUniform(std::size_t n, std::uint64_t seed, double width = 1e-9);

/// n points at uniform angles and radii log-uniform in [rmin, rmax] (radius drawn first):
/// densities over 24 orders of magnitude for the defaults (2.3.5).
XY logRadiusPoints(std::size_t n, std::uint64_t seed, double rmin = 1e-6, double rmax = 1e6);

/// n points whose coordinates are each +-(1/2 + U[0, 1)) 2^k, k uniform in [kmin, kmax], drawn
/// x then y as (k, U, sign): exponents spread over the whole double range for the defaults, the
/// inputs on which the filters overflow or underflow (2.3.1, the extended-exponent stage).
XY exponentSpreadPoints(std::size_t n, std::uint64_t seed, int kmin = -1070, int kmax = 1019);

/// Shuffles the points (not the coordinates) uniformly: Fisher-Yates, seeded.
void shufflePoints(XY& p, std::uint64_t seed);

/// Adds the points to T as vertices numbered 0, 1, ... in order; returns them (the input of
/// delaunayTrgl / delaunayTrglHull).
std::vector<Vertex*> addVertices(Triangulation& T, const XY& p);

}  // namespace dt
