// Algorithm 1 of the notes (section 2.2), corrected: the Bowyer-Watson algorithm on a plain list
// of triangles, testing every triangle at every insertion (O(n^2)); and a brute-force O(n^4)
// Delaunay triangulation of small sets, the reference for eq. (2.1).
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <vector>

#include "tri.h"

namespace dt {

/// What one application of the Delaunay kernel (2.1) did.
struct KernelStep {
  std::size_t cavity = 0;  ///< |C|: triangles removed
  std::size_t ball = 0;    ///< |B|: triangles added (|C| + 2 when p is inside the domain)
};

/// A circle test other than the exact one: true iff point `ip` is to be taken as inside the
/// circumcircle of triangle `t` (section 2.3's experiments; see CircleTest).
using InsideTest = std::function<bool(const Tri& t, int ip)>;

//! [delaunayKernelStepDecl]
/// Eq. (2.1) on a plain triangle list: DT_{n+1} = DT_n - C + B for the point `ip` of `xy`.
/// C is every triangle whose open circumdisk contains the point (each triangle is tested:
/// O(size of tri)); B is the fan joining the point to every edge of C not shared by two
/// triangles of C. Kept triangles stay in order, the ball is appended. If `incircleTests` is
/// given, each circle test made is counted in it. The test is the exact `incircle`, or
/// `inside` when one is given.
KernelStep delaunayKernelStep(const std::vector<double>& xy, std::vector<Tri>& tri, int ip,
                              std::uint64_t* incircleTests = nullptr,
                              const InsideTest& inside = nullptr);
//! [delaunayKernelStepDecl]

/// How Algorithm 1 decides that a triangle's circumcircle contains the new point.
enum class CircleTest {
  Exact,   ///< `incircle`, exact: the corrected algorithm
  Naive,   ///< `incircleNaive`, the determinant in floating point (2.3.1: invalid meshes)
  Stored,  ///< each triangle's centre and squared radius, computed in floating point once,
           ///< when the triangle is first tested, then compared with (2.3: "computed in advance")
};

/// The result of Algorithm 1: points (the four super-vertices first, ids -1..-4, then the input
/// points, ids 0..n-1) and the triangles of DT(S ∪ S0).
struct BowyerWatsonResult {
  std::vector<double> xy;
  std::vector<long> ids;
  std::vector<Tri> tri;
  std::uint64_t incircleTests = 0;  ///< incircle calls made, summed over insertions
  std::uint64_t cavityFaces = 0;    ///< sum of |C|
  std::uint64_t duplicates = 0;     ///< points skipped: they coincide with an earlier point
};

//! [bowyerWatsonDecl]
/// Algorithm 1 (2.2), corrected: DT_0 is the two super-triangles of initSuperTriangles with the
/// same `factor`, then the points are inserted in the given order by delaunayKernelStep.
/// Gives the same triangles as delaunayTrgl on the same input (compare with
/// canonicalTriangles). Throws std::out_of_range if a point is outside the super-triangles.
/// With a `test` other than Exact (section 2.3's experiments) every triangle is still tested at
/// every insertion, but the result may be no triangulation at all (check it with
/// checkDelaunay): a cavity that is not a disk gives a ball that overlaps the kept triangles, so
/// the insertions stop once the list holds more triangles than a triangulation of its points
/// can have.
BowyerWatsonResult bowyerWatson(const std::vector<double>& xy, double factor = 10.0,
                                CircleTest test = CircleTest::Exact);
//! [bowyerWatsonDecl]

/// Triangles named by point ids, each rotated to start at its smallest id (orientation kept),
/// sorted: two triangulations are the same iff these lists are equal.
std::vector<std::array<long, 3>> canonicalTriangles(const std::vector<long>& ids,
                                                    const std::vector<Tri>& tri);

//! [hullEdgesNotCovered]
/// Figure 2.6's test (2.2.1), exact: the edges of the convex hull Ω(S) of the points with
/// id >= 0 that no triangle free of super-vertices (id < 0) has. The list is empty iff the
/// triangles left after deleting those touching a super-vertex cover Ω(S), i.e. iff they can
/// be DT(S) (why: exercise 2.2-3).
std::vector<std::array<long, 2>> hullEdgesNotCovered(const std::vector<double>& xy,
                                                     const std::vector<long>& ids,
                                                     const std::vector<Tri>& tri);
//! [hullEdgesNotCovered]

/// Brute-force Delaunay triangulation of a small set in general position (no 4 points
/// cocircular, not all collinear): every counter-clockwise triple whose open circumdisk
/// contains no other point. O(n^4) exact predicates; meant for n up to about 40.
std::vector<Tri> bruteForceDelaunay(const std::vector<double>& xy);

}  // namespace dt
