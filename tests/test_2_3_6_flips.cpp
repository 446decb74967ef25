/// \file test_2_3_6_flips.cpp Tests of section 2.3.6 (edge flip, Lawson, recovery of DT(S) from DT(S0 ∪ S)) and the flip claim of 2.3.3.
#include <doctest/doctest.h>

#include <algorithm>
#include <map>
#include <random>
#include <set>

#include "flip.h"
#include "hull.h"
#include "oracle.h"
#include "predicates.h"
#include "support.h"

namespace {

using dt::XY;

// Structural validity without the Delaunay property: every link symmetric and across the shared
// edge, every finite face strictly counter-clockwise (exact), and Euler's count n_f = 2(n-1) - n_h
// with n_h read from the ghost ring. Together with a convex hull ring this makes T a
// triangulation of the hull of its vertices.
std::string structure(const dt::Triangulation& T) {
  std::set<const dt::Vertex*> used;
  std::size_t nf = 0;
  for (const dt::Face& f : T.faces()) {
    if (f.deleted) return "deleted face";
    for (int k = 0; k < 3; ++k) {
      const dt::Face* g = f.F[k];
      if (g == nullptr) return "missing link";
      const int j = dt::neighbourIndex(g, &f);
      if (j < 0 || g->V[j] != f.V[(k + 1) % 3] || g->V[(j + 1) % 3] != f.V[k])
        return "bad link";
    }
    if (f.isGhost()) continue;
    ++nf;
    if (dt::orientationTest(f.V[0], f.V[1], f.V[2]) <= 0) return "face not counter-clockwise";
    for (const dt::Vertex* v : f.V) used.insert(v);
  }
  const auto hull = dt::hullEdges(T);
  for (std::size_t i = 0; i < hull.size(); ++i) {
    const auto& e = hull[i];
    const auto& n = hull[(i + 1) % hull.size()];
    if (e.b != n.a || dt::orientationTest(e.a, e.b, n.b) < 0) return "hull not convex";
  }
  const long n = long(used.size()), nh = long(hull.size());
  if (long(nf) != 2 * (n - 1) - nh) return "Euler count fails";
  return "";
}

// Number of finite faces around each vertex.
std::map<const dt::Vertex*, int> degrees(const dt::Triangulation& T) {
  std::map<const dt::Vertex*, int> deg;
  for (const dt::Face* f : T.finiteFaces())
    for (const dt::Vertex* v : f->V) ++deg[v];
  return deg;
}

// Sorted triangles as sorted triples of input ids: a canonical form to compare two DT(S).
std::vector<std::array<long, 3>> canonical(const dt::Triangulation& T) {
  std::vector<std::array<long, 3>> out;
  for (const dt::Face* f : T.finiteFaces()) {
    std::array<long, 3> t = {f->V[0]->id, f->V[1]->id, f->V[2]->id};
    std::sort(t.begin(), t.end());
    out.push_back(t);
  }
  std::sort(out.begin(), out.end());
  return out;
}

// DT(S0 ∪ S) with super-triangles `factor` times the bounding box.
void superDT(dt::Triangulation& T, const XY& p, double factor) {
  double x0 = p[0], x1 = p[0], y0 = p[1], y1 = p[1];
  for (std::size_t i = 0; i < p.size() / 2; ++i) {
    x0 = std::min(x0, p[2 * i]), x1 = std::max(x1, p[2 * i]);
    y0 = std::min(y0, p[2 * i + 1]), y1 = std::max(y1, p[2 * i + 1]);
  }
  dt::initSuperTriangles(T, x0, y0, x1, y1, factor);
  const auto S = dt::addVertices(T, p);
  dt::delaunayTrgl(T, S, dt::StartRule::LastCavity);
}

// DT(S0 ∪ S), then the recovery of DT(S).
dt::FlipStats superThenRecover(dt::Triangulation& T, const XY& p, double factor,
                               dt::RecoveryRule rule = dt::RecoveryRule::Full) {
  superDT(T, p, factor);
  return dt::recoverDelaunay(T, rule);
}

// Points on a slightly bent line (a flat parabolic arc): all are on the hull, every triangle is
// nearly flat and its huge circumcircle swallows any reasonable super vertex.
// Random abscissae, so that no four points are cocircular (a symmetric sample would have
// isosceles trapezoids, hence several Delaunay triangulations).
XY bentLine(std::size_t n, double bend, unsigned seed = 1) {
  const XY u = dt::uniformPoints(n, seed);
  XY p;
  for (std::size_t i = 0; i < n; ++i) {
    const double t = u[2 * i];
    p.push_back(t);
    p.push_back(bend * t * (1 - t));
  }
  return p;
}

// Points on a short arc of a huge circle (radius R), plus two inner points.
XY hugeCircleArc(std::size_t n, double R) {
  XY p;
  for (std::size_t i = 0; i < n; ++i) {
    const double t = -0.5e-3 + 1e-3 * double(i) / double(n - 1);
    p.push_back(R * std::sin(t));
    p.push_back(R * std::cos(t) - R);
  }
  p.push_back(0.0);
  p.push_back(-0.2 * R * 1e-3);
  p.push_back(0.1 * R * 1e-3);
  p.push_back(-0.1 * R * 1e-3);
  return p;
}

}  // namespace

TEST_CASE("2.3.6 a flip changes the degrees of its four vertices by -1 -1 +1 +1 (the claim of 2.3.3)") {
  dt::Triangulation T;
  const auto S = dt::addVertices(T, dt::uniformPoints(300, 2336));
  dt::delaunayTrglHull(T, S, dt::StartRule::LastCavity);
  REQUIRE(dt::checkTriangulation(T).ok);
  int flipped = 0, refused = 0;
  std::mt19937 rng(7);
  for (int trial = 0; trial < 400; ++trial) {  // book: s236.test_flip_trials
    std::vector<dt::Face*> live;
    for (dt::Face& f : T.faces())
      if (!f.isGhost()) live.push_back(&f);
    dt::Face* f = live[rng() % live.size()];
    const int k = int(rng() % 3);
    if (!dt::isFlippable(f, k)) {
      ++refused;
      continue;
    }
    const dt::Vertex* a = f->V[k];
    const dt::Vertex* b = f->V[(k + 1) % 3];
    const dt::Vertex* c = f->V[(k + 2) % 3];
    const dt::Face* g = f->F[k];
    const dt::Vertex* d = g->V[(dt::neighbourIndex(g, f) + 2) % 3];
    auto before = degrees(T);
    REQUIRE(dt::flipEdge(f, k));
    auto after = degrees(T);
    CHECK(after[a] == before[a] - 1);
    CHECK(after[b] == before[b] - 1);
    CHECK(after[c] == before[c] + 1);
    CHECK(after[d] == before[d] + 1);
    int changed = 0;
    for (const auto& [v, dv] : after) changed += (before[v] != dv);
    CHECK(changed == 4);  // nobody else
    REQUIRE(structure(T) == "");
    ++flipped;
  }
  CHECK(flipped > 100);
  CHECK(refused > 0);  // hull edges (next to ghosts) and reflex quadrilaterals are refused
  // The random flips left a valid but non-Delaunay triangulation; Lawson repairs it.
  CHECK_FALSE(dt::checkTriangulation(T).ok);
  const dt::FlipStats st = dt::lawsonFlip(T);
  CHECK(st.flips > 0);
  CHECK(dt::checkTriangulation(T).ok);
}

TEST_CASE("2.3.6 flipEdge refuses reflex or flat quadrilaterals and ghost edges and leaves them unchanged") {
  dt::Triangulation T;
  // a d b c with d inside triangle a b c's side so that a d b c is reflex at d.
  dt::Vertex* a = T.addVertex(0, 0, 0);
  dt::Vertex* b = T.addVertex(4, 0, 1);
  dt::Vertex* c = T.addVertex(2, 3, 2);
  dt::Vertex* d = T.addVertex(2, -1, 3);
  dt::Vertex* e = T.addVertex(1, 1, 4);  // inside a b c
  dt::delaunayTrglHull(T, {a, b, c, d, e}, dt::StartRule::LastCavity);
  REQUIRE(dt::checkTriangulation(T).ok);
  for (dt::Face& f : T.faces())
    for (int k = 0; k < 3; ++k) {
      const dt::Face* g = f.F[k];
      const bool ghostEdge = f.isGhost() || g->isGhost();
      const dt::Vertex* x = f.V[(k + 2) % 3];
      const dt::Vertex* y = g->V[(dt::neighbourIndex(g, &f) + 2) % 3];
      const bool convex = !ghostEdge &&
                          dt::orientationTest(x, f.V[k], y) > 0 &&
                          dt::orientationTest(y, f.V[(k + 1) % 3], x) > 0;
      CHECK(dt::isFlippable(&f, k) == convex);
      if (!convex) {
        const dt::Face copy = f;
        CHECK_FALSE(dt::flipEdge(&f, k));
        CHECK(std::equal(f.V, f.V + 3, copy.V));
        CHECK(std::equal(f.F, f.F + 3, copy.F));
      }
    }
  // Three collinear points: the quadrilateral (0,0) (1,0) (2,0) (1,1) is flat at (1,0).
  dt::Triangulation U;
  auto P = dt::addVertices(U, {0, 0, 2, 0, 1, 1, 1, 0});
  dt::delaunayTrglHull(U, P, dt::StartRule::LastCavity);
  REQUIRE(dt::checkTriangulation(U).ok);
  for (dt::Face& f : U.faces())
    for (int k = 0; k < 3; ++k) CHECK_FALSE(dt::isFlippable(&f, k));
}

TEST_CASE("2.3.6 Lawson's flips turn any triangulation into the Delaunay triangulation") {
  struct Family {
    std::string name;
    XY p;
  };
  XY grid = dt::gridPoints(15, 12);
  dt::shufflePoints(grid, 3);
  const Family fams[] = {
      {"uniform", dt::uniformPoints(2000, 11)},
      {"grid (cocircular)", grid},
      {"circle (all on the hull)", dt::circlePoints(200)},
      {"bent line", bentLine(300, 1e-6)},
      {"huge coordinates", dt::uniformPoints(500, 12, 1e150, 1.0000001e150)},
  };
  for (const Family& fam : fams) {
    CAPTURE(fam.name);
    dt::Triangulation T;
    const auto S = dt::addVertices(T, fam.p);
    dt::sweepTriangulation(T, S);
    REQUIRE(structure(T) == "");
    const std::size_t nf = T.numFiniteFaces();
    const dt::FlipStats st = dt::lawsonFlip(T);
    const dt::CheckReport r = dt::checkTriangulation(T);
    CHECK_MESSAGE(r.ok, r.error);
    CHECK(T.numFiniteFaces() == nf);  // flips keep the number of triangles
    // Every interior edge, (3 n_f - n_h) / 2 of them, is tested at least once.
    CHECK(st.tests >= (3 * nf - dt::hullEdges(T).size()) / 2);
  }
  // The sweep is not Delaunay on random points, so Lawson has real work to do.
  dt::Triangulation T;
  const auto S = dt::addVertices(T, dt::uniformPoints(1000, 5));
  dt::sweepTriangulation(T, S);
  CHECK_FALSE(dt::checkTriangulation(T).ok);
  CHECK(dt::lawsonFlip(T).flips > 500);
}

TEST_CASE("2.3.6 the recovery from DT(S0 ∪ S) gives DT(S) for super-triangles of any size") {
  XY grid = dt::gridPoints(12, 9, 0.5);
  dt::shufflePoints(grid, 4);
  XY circle = dt::circlePoints(120, 3);
  dt::shufflePoints(circle, 5);
  XY bent = bentLine(200, 1e-4);
  dt::shufflePoints(bent, 6);
  XY huge = hugeCircleArc(150, 1e6);
  dt::shufflePoints(huge, 7);
  struct Family {
    std::string name;
    XY p;
    bool generic;  // no four cocircular points on an empty circle: DT(S) is unique
  };
  const Family fams[] = {
      {"uniform", dt::uniformPoints(1500, 21), true},
      {"grid", grid, false},
      {"circle", circle, false},
      {"bent line", bent, true},
      {"huge circle arc", huge, true},
  };
  // Factors from "barely enclosing" to "far": 2.2.1 says no size is right a priori.
  // The smallest and the largest size are named for the book's claims table.
  for (double factor : {1.0001,  // book: s236.test_factor_lo
                        1.01, 1.5, 10.0, 10000.0}) {  // book: s236.test_factor_hi
    for (const Family& fam : fams) {
      CAPTURE(fam.name);
      CAPTURE(factor);
      dt::Triangulation T;
      const dt::FlipStats st = superThenRecover(T, fam.p, factor);
      const dt::CheckReport r = dt::checkTriangulation(T);
      REQUIRE_MESSAGE(r.ok, r.error);
      CHECK(r.nVertices == fam.p.size() / 2);
      CHECK(st.removedFaces == r.nHull + 4);  // n_f(S0 ∪ S) - n_f(S) = (2n+2) - (2n-2-n_h)
      // Same as the hull method (2.2.2).
      dt::Triangulation H;
      dt::delaunayTrglHull(H, dt::addVertices(H, fam.p), dt::StartRule::LastCavity);
      REQUIRE(dt::checkTriangulation(H).ok);
      if (fam.generic) CHECK(canonical(T) == canonical(H));
      CHECK(dt::convexHull(T).size() == dt::convexHull(H).size());
    }
  }
}

TEST_CASE("2.3.6 flat hull triangles put small super vertices inside circumcircles so the "
          "notes' flips alone fail and the completed rule does not") {
  // On the bent line every lower-hull triangle is nearly flat: its circumcircle is huge and
  // contains the super vertices unless they are very far.
  const XY p = bentLine(60, 1e-3);
  int notesFailures = 0, naiveFailures = 0;
  for (double factor : {1.01, 2.0, 10.0, 100.0}) {
    CAPTURE(factor);
    dt::Triangulation N;
    const dt::FlipStats sn = superThenRecover(N, p, factor, dt::RecoveryRule::NotesOnly);
    const dt::PlainMesh m = dt::extractMesh(N, true);
    notesFailures += !dt::checkDelaunay(m.xy, m.tri).ok;
    CHECK(sn.superOpposite + sn.superSuper + sn.realReal == 0);  // only 2.2.1's kind of flip
    // The naive removal (no flip at all).
    dt::Triangulation Z;
    superDT(Z, p, factor);
    const dt::PlainMesh z = dt::extractMesh(Z, true);
    naiveFailures += !dt::checkDelaunay(z.xy, z.tri).ok;
    dt::Triangulation F;
    superThenRecover(F, p, factor);
    CHECK(dt::checkTriangulation(F).ok);
  }
  MESSAGE("bent line: naive removal fails for " << naiveFailures << " of 4 sizes, the notes' "
          "flips alone for " << notesFailures);
  CHECK(naiveFailures == 4);   // removing the super faces never suffices here
  CHECK(notesFailures >= 1);   // and the notes' flips alone not always
}

TEST_CASE("2.3.6 superInCircle agrees with incircle on points of S and pushes super vertices away") {
  dt::Triangulation T;
  dt::Vertex* a = T.addVertex(0, 0, 0);
  dt::Vertex* b = T.addVertex(1, 0, 1);
  dt::Vertex* c = T.addVertex(0, 1, 2);
  dt::Vertex* in = T.addVertex(0.5, 0.5, 3);
  dt::Vertex* out = T.addVertex(2, 2, 4);
  dt::Vertex* on = T.addVertex(1, 1, 5);
  CHECK(dt::superInCircle(a, b, c, in) > 0);
  CHECK(dt::superInCircle(a, b, c, out) < 0);
  CHECK(dt::superInCircle(a, b, c, on) == 0);
  // A super vertex as the query is never in conflict, even when geometrically inside.
  dt::Vertex* s = T.addVertex(0.4, 0.4, -1);
  CHECK(dt::incircle(0, 0, 1, 0, 0, 1, 0.4, 0.4) > 0);
  CHECK(dt::superInCircle(a, b, c, s) < 0);
  // A super vertex of the triangle: the circle becomes the half-plane on its side of the
  // opposite edge.
  dt::Vertex* far = T.addVertex(0.5, 0.2, -2);  // triangle a b far, counter-clockwise
  CHECK(dt::superInCircle(a, b, far, T.addVertex(5, 0.001, 6)) > 0);   // above line a b
  CHECK(dt::superInCircle(a, b, far, T.addVertex(0.5, -1e-9, 7)) < 0); // below
  // Two super vertices: the one with the larger id (p_{-1} before p_{-2}) decides.
  CHECK(dt::superInCircle(a, far, c, s) < 0);  // s is the query and outranks far
}

TEST_CASE("2.3.6 superInCircle is the incircle test with super vertices at ever larger distances (exact oracle)") {
  // "p_{-1} infinitely farther than p_{-2}, ..., farther than every point of S", made finite:
  // p_{-m} = R_m (direction), with R_{-4} >> the points' coordinates and each R_{-m} far above
  // the square of the next one (R_{-1} = 2^400 >> R_{-2}^2 = 2^320, ...). Then the plain
  // incircle determinant of the actual coordinates, computed exactly with GMP rationals
  // (tests/oracle.h, no code of the predicate core), has the sign the symbolic rule gives. The
  // points of S lie on a small integer grid on the lines through the super vertices'
  // directions, so the first super vertex is often collinear with two others (ties that fall
  // to the next super vertex, or to the plain incircle test).
  dt::Triangulation T;
  std::vector<dt::Vertex*> pool;
  const int exps[4] = {400, 160, 60, 20};
  const double dirs[4][2] = {{-1, 0}, {1, 1}, {0, -1}, {-1, 2}};
  for (int m = 0; m < 4; ++m) {
    const double R = std::ldexp(1.0, exps[m]);
    pool.push_back(T.addVertex(dirs[m][0] * R, dirs[m][1] * R, -1 - m));
  }
  const int grid[][2] = {{0, 0}, {1, 0}, {2, 0}, {1, 1}, {2, 2}, {0, -1}, {0, 1}, {-1, 2},
                         {1, -2}, {2, 1}, {-1, -1}, {3, 2}};
  long id = 0;
  for (const auto& g : grid) pool.push_back(T.addVertex(g[0], g[1], id++));
  long compared = 0, wrong = 0, decidedBySecond = 0, superCount[5] = {0, 0, 0, 0, 0};
  for (dt::Vertex* a : pool)
    for (dt::Vertex* b : pool)
      for (dt::Vertex* c : pool) {
        if (a == b || b == c || a == c) continue;
        if (dtoracle::orientQ(a->x, a->y, b->x, b->y, c->x, c->y) <= 0) continue;
        for (dt::Vertex* d : pool) {
          if (d == a || d == b || d == c) continue;
          const double q[8] = {a->x, a->y, b->x, b->y, c->x, c->y, d->x, d->y};
          const int want = dtoracle::incircleQ(q);
          const int got = dt::superInCircle(a, b, c, d);
          ++compared;
          if (got != want) {
            ++wrong;
            if (wrong <= 5)
              MESSAGE("superInCircle(" << a->id << ", " << b->id << ", " << c->id << ", " << d->id
                                       << ") = " << got << ", oracle " << want);
          }
          const int supers = (a->id < 0) + (b->id < 0) + (c->id < 0) + (d->id < 0);
          ++superCount[supers];
          // The farthest super vertex present is collinear with the other three: a tie.
          const dt::Vertex* q4[4] = {a, b, c, d};
          const dt::Vertex* top = nullptr;
          int topIndex = -1;
          for (int i = 0; i < 4; ++i)
            if (q4[i]->id < 0 && (top == nullptr || q4[i]->id > top->id)) top = q4[i], topIndex = i;
          if (top != nullptr && supers >= 2) {
            const dt::Vertex* r[3];
            for (int i = 0, k = 0; i < 4; ++i)
              if (i != topIndex) r[k++] = q4[i];
            decidedBySecond += dtoracle::orientQ(r[0]->x, r[0]->y, r[1]->x, r[1]->y, r[2]->x, r[2]->y) == 0;
          }
        }
      }
  MESSAGE(compared << " quadruples, " << decidedBySecond << " with a tie at the farthest super vertex");
  CHECK(wrong == 0);
  for (int s = 0; s <= 4; ++s) CHECK(superCount[s] > 0);  // every number of super vertices
  CHECK(decidedBySecond > 0);
}

TEST_CASE("2.3.6 recoverDelaunay counts its flips by kind as its log shows them") {
  // The kinds of FlipStats (2.2.1's flips, super-real edges with a super opposite vertex,
  // super-super and real-real edges) recounted from the log of the flips themselves.
  std::uint64_t kinds[4] = {0, 0, 0, 0};
  for (double factor : {1.01, 10.0}) {
    for (const XY& p : {dt::uniformPoints(800, 61), bentLine(80, 1e-3, 62), dt::circlePoints(90, 63)}) {
      dt::Triangulation T;
      superDT(T, p, factor);
      std::vector<std::array<const dt::Vertex*, 4>> log;
      const dt::FlipStats st = dt::recoverDelaunay(T, dt::RecoveryRule::Full, &log);
      REQUIRE(dt::checkTriangulation(T).ok);
      auto super = [](const dt::Vertex* v) { return v->id < 0; };
      std::uint64_t notes = 0, opposite = 0, superSuper = 0, realReal = 0;
      for (const auto& f : log) {
        const int edgeSupers = super(f[0]) + super(f[1]);
        if (edgeSupers == 2) ++superSuper;
        else if (edgeSupers == 0) ++realReal;
        else if (super(f[2]) || super(f[3])) ++opposite;
        else ++notes;
      }
      CHECK(log.size() == st.flips);
      CHECK(st.notesFlips == notes);
      CHECK(st.superOpposite == opposite);
      CHECK(st.superSuper == superSuper);
      CHECK(st.realReal == realReal);
      kinds[0] += notes, kinds[1] += opposite, kinds[2] += superSuper, kinds[3] += realReal;
    }
  }
  MESSAGE("flips by kind: 2.2.1's " << kinds[0] << ", super opposite " << kinds[1]
          << ", super-super " << kinds[2] << ", real-real " << kinds[3]);
  CHECK(kinds[0] > 0);
  CHECK(kinds[1] > 0);
}
