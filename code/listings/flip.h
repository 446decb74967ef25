// Section 2.3.6 (a TODO in the notes): the edge flip, Lawson's legalisation by flips, and the
// recovery of DT(S) from DT(S0 ∪ S) that section 2.2.1 sketches.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "mesh.h"

namespace dt {

//! [flippable]
/// True iff edge k of f (V[k] V[k+1]) can be flipped: both faces finite (a ghost face has no
/// second diagonal) and the quadrilateral they form strictly convex, decided exactly. Then both
/// new triangles are counter-clockwise and not flat.
bool isFlippable(const Face* f, int k);
//! [flippable]

/// The edge flip (2.3.3, 2.3.6): replaces the diagonal a b of the quadrilateral formed by
/// f = (a, b, c) (edge k) and its neighbour g = (b, a, d) by the other diagonal c d, in place:
/// f becomes (c, a, d) and g becomes (d, b, c). The six links that change (three in f, three
/// in g, two of them in the outer neighbours) are rewired. Returns false and changes nothing
/// if the edge is not flippable (isFlippable). Vertices a and b lose one adjacent triangle,
/// c and d gain one: the degrees change by -1, -1, +1, +1.
bool flipEdge(Face* f, int k);

/// Counters of a flip algorithm.
struct FlipStats {
  std::uint64_t tests = 0;   ///< edges tested (stale stack entries excluded)
  std::uint64_t flips = 0;   ///< flips done
  // Recovery only (recoverDelaunay): the flips by kind of the flipped edge p_i p_j and of its
  // two opposite vertices p_k p_l; "super" means a super-triangle corner p_{-m}.
  std::uint64_t notesFlips = 0;   ///< super-real edge, both opposite vertices real (2.2.1's rule)
  std::uint64_t superOpposite = 0;///< super-real edge with a super opposite vertex
  std::uint64_t superSuper = 0;   ///< edge between two super vertices
  std::uint64_t realReal = 0;     ///< edge between two points of S
  std::uint64_t removedFaces = 0; ///< faces incident to a super vertex, removed at the end
};

/// Lawson's algorithm: flips every finite edge that is not locally Delaunay (the opposite
/// vertex strictly inside the circumcircle, exact incircle) until none is left. Works from any
/// triangulation of a point set, with ghost faces or a plain boundary; edges next to a ghost
/// face or to the boundary are never flipped. An explicit stack of edges, no recursion.
/// Terminates: each flip strictly lowers the lifted surface (points lifted to z = x² + y²),
/// so no triangulation repeats, and there are finitely many (at most O(n²) flips). The result
/// has every interior edge locally Delaunay, hence is a Delaunay triangulation (Delaunay lemma).
FlipStats lawsonFlip(Triangulation& T);

/// How recoverDelaunay flips.
enum class RecoveryRule {
  /// Only 2.2.1's rule: flip an edge p_{-i} p_j whose opposite vertices p_k, p_l are both
  /// points of S when p_{-i} p_j crosses p_k p_l. Not enough when the super-triangles are too
  /// small; kept to measure that.
  NotesOnly,
  /// 2.2.1's rule completed: Lawson's algorithm where the super vertices are "infinitely far"
  /// (superInCircle). Always gives DT(S).
  Full
};

/// The incircle test with the super vertices p_{-m} pushed to infinity (2.2.1: "assume every
/// p_{-j} is far enough so that it does not fall into any circumcircle"). Lift the points to
/// z = x² + y², and lift each super vertex further by H_m, with H_{-1} >> H_{-2} >> H_{-3} >>
/// H_{-4} >> every finite height. The sign of "d below the plane through a, b, c" is then
/// decided by the highest super vertex present, from its barycentric sign alone (one exact
/// orientation test); if that is zero, by the next one; and only for four points of S (or
/// exhausted ties) by the ordinary incircle test. > 0: d is in conflict with (a, b, c), which
/// must be counter-clockwise.
int superInCircle(const Vertex* a, const Vertex* b, const Vertex* c, const Vertex* d);

/// Recovers DT(S) from T = DT(S0 ∪ S) (built with initSuperTriangles + delaunayTrgl):
/// flips edges by `rule`, then, for RecoveryRule::Full, removes every face incident to a super
/// vertex and closes the hull with ghost faces, so that T ends exactly like delaunayTrglHull's
/// result (checkTriangulation passes, more points may be inserted, even outside the hull).
/// With NotesOnly the super faces are left in place (extractMesh(T, true) drops them).
/// Precondition: the edges between points of S are locally Delaunay (true for DT(S0 ∪ S)), so
/// only the edges of faces touching a super vertex start on the stack.
/// If `log` is given, each flip is appended as {a, b, c, d}: edge a b replaced by c d.
FlipStats recoverDelaunay(Triangulation& T, RecoveryRule rule = RecoveryRule::Full,
                          std::vector<std::array<const Vertex*, 4>>* log = nullptr);

/// Removes the deleted faces from T.faces() (moving live faces down and re-linking them), so
/// that checkTriangulation, which rejects deleted faces, applies. Invalidates Face pointers.
void compactFaces(Triangulation& T);

}  // namespace dt
