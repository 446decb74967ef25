/// \file test_2_1_kernel.cpp Claim tests of section 2.1: eq. (2.1), the kernel of a polygon, Proposition 2.1.1, Property 2.1.1 and the Delaunay ball.
#include <doctest/doctest.h>

#include <cmath>
#include <random>
#include <string>

#include "bowyer_watson.h"
#include "cavity.h"
#include "check.h"
#include "predicates.h"
#include "star.h"
#include "support.h"
#include "triangulate.h"

namespace {

using dt::XY;

// All integer points of the circle x^2 + y^2 = R^2 with R = 5 13 17 29 (324 points, exactly
// cocircular: every incircle test among them is 0).
XY integerCirclePoints() {
  const long R = 5L * 13 * 17 * 29;
  XY p;
  for (long x = -R; x <= R; ++x) {
    const long y2 = R * R - x * x;
    const long y = std::lround(std::sqrt(double(y2)));
    for (long yy : {y - 1, y, y + 1})
      if (yy >= 0 && yy * yy == y2) {
        p.push_back(double(x));
        p.push_back(double(yy));
        if (yy > 0) {
          p.push_back(double(x));
          p.push_back(double(-yy));
        }
      }
  }
  return p;
}

double minOf(const XY& p, int c) {
  double m = p[c];
  for (std::size_t i = c; i < p.size(); i += 2) m = std::min(m, p[i]);
  return m;
}
double maxOf(const XY& p, int c) {
  double m = p[c];
  for (std::size_t i = c; i < p.size(); i += 2) m = std::max(m, p[i]);
  return m;
}

// Totals over all insertions of one input.
struct KernelRun {
  std::size_t insertions = 0, cavityFaces = 0, maxCavity = 0, fullChecks = 0;
  bool ok = true;
  std::string error;
};

// Inserts the points one by one into the two super-triangles. Before each insertion the cavity
// is computed by definition (every face tested) and checked exactly (Proposition 2.1.1,
// Property 2.1.1); after it, the ball must have |C| + 2 faces, and (every `fullEvery`
// insertions, and at the end) the whole triangulation is checked exactly to be Delaunay.
KernelRun runKernel(const XY& p, std::size_t fullEvery) {
  KernelRun run;
  dt::Triangulation T;
  dt::initSuperTriangles(T, minOf(p, 0), minOf(p, 1), maxOf(p, 0), maxOf(p, 1));
  dt::InsertionStats st;
  dt::InsertionScratch scratch;
  dt::Face* start = &T.faces().front();
  for (std::size_t i = 0; i < p.size() / 2 && run.ok; ++i) {
    dt::Vertex* v = T.addVertex(p[2 * i], p[2 * i + 1], long(i));
    const std::vector<dt::Face*> C = dt::conflictFaces(T, v);
    const dt::CavityReport rep = dt::checkCavity({C.begin(), C.end()}, v);
    if (!rep.ok) {
      run.ok = false;
      run.error = "point " + std::to_string(i) + ": " + rep.error;
      break;
    }
    const std::size_t facesBefore = T.numFiniteFaces();
    const std::uint64_t cavBefore = st.cavityFaces;
    dt::Face* ball = dt::insertVertex(T, start, v, st, scratch);
    if (ball == nullptr) {
      run.ok = false;
      run.error = "point " + std::to_string(i) + " was not inserted";
      break;
    }
    start = ball;
    // Listing 2.5's search found exactly the faces of the definition (it finds a subset).
    if (st.cavityFaces - cavBefore != C.size()) {
      run.ok = false;
      run.error = "delaunayCavity found " + std::to_string(st.cavityFaces - cavBefore) +
                  " faces, the definition " + std::to_string(C.size());
    }
    std::size_t fan = 0;
    for (const dt::Face& f : T.faces())
      if (!f.deleted && (f.V[0] == v || f.V[1] == v || f.V[2] == v)) ++fan;
    if (fan != C.size() + 2 || T.numFiniteFaces() != facesBefore + 2) {
      run.ok = false;
      run.error = "point " + std::to_string(i) + ": ball has " + std::to_string(fan) +
                  " faces for a cavity of " + std::to_string(C.size());
    }
    if (run.ok && ((i + 1) % fullEvery == 0 || i + 1 == p.size() / 2)) {
      const dt::CheckReport r = dt::checkTriangulation(T);
      ++run.fullChecks;
      if (!r.ok) {
        run.ok = false;
        run.error = "after point " + std::to_string(i) + ": " + r.error;
      }
    }
    ++run.insertions;
    run.cavityFaces += C.size();
    run.maxCavity = std::max(run.maxCavity, C.size());
  }
  return run;
}

// A point of the open unit square strictly inside a triangle of `tri` (so inside Ω(S_n)).
bool insideSome(const XY& xy, const std::vector<dt::Tri>& tri, double x, double y) {
  for (const dt::Tri& t : tri) {
    bool in = true;
    for (int k = 0; k < 3 && in; ++k) {
      const int a = t[k], b = t[(k + 1) % 3];
      in = dt::orient2d(xy[2 * a], xy[2 * a + 1], xy[2 * b], xy[2 * b + 1], x, y) > 0;
    }
    if (in) return true;
  }
  return false;
}

}  // namespace

TEST_CASE("2.1 eq. (2.1): DT_n - C + B is the brute-force DT(S_{n+1}) for p inside Omega(S_n)") {
  std::size_t trials = 0, cavitySum = 0;
  for (unsigned seed = 1; seed <= 60; ++seed) {
    const std::size_t n = 5 + seed % 20;
    XY xy = dt::uniformPoints(n, 1000 + seed);
    std::vector<dt::Tri> tri = dt::bruteForceDelaunay(xy);
    REQUIRE(dt::checkDelaunay(xy, tri).ok);  // general position: the brute force is a DT
    // p_{n+1}: the first random point strictly inside a triangle of DT_n.
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(0, 1);
    double px = 0, py = 0;
    bool found = false;
    for (int k = 0; k < 1000 && !found; ++k) {
      px = u(rng), py = u(rng);
      found = insideSome(xy, tri, px, py);
    }
    REQUIRE(found);
    xy.push_back(px);
    xy.push_back(py);
    const dt::KernelStep step = dt::delaunayKernelStep(xy, tri, int(n));
    CHECK(step.cavity >= 1);
    CHECK(step.ball == step.cavity + 2);
    std::vector<long> ids(n + 1);
    for (std::size_t i = 0; i <= n; ++i) ids[i] = long(i);
    const auto kernel = dt::canonicalTriangles(ids, tri);
    const auto brute = dt::canonicalTriangles(ids, dt::bruteForceDelaunay(xy));
    CHECK(kernel == brute);
    CHECK(dt::checkDelaunay(xy, tri).ok);
    // The library's insertVertex (Listings 2.5-2.7) gives the same triangles.
    dt::Triangulation T;
    std::vector<dt::Vertex*> S;
    for (std::size_t i = 0; i <= n; ++i) S.push_back(T.addVertex(xy[2 * i], xy[2 * i + 1], long(i)));
    dt::delaunayTrglHull(T, S, dt::StartRule::LastCavity);
    const dt::PlainMesh m = dt::extractMesh(T, false);
    CHECK(dt::canonicalTriangles(m.ids, m.tri) == brute);
    ++trials;
    cavitySum += step.cavity;
  }
  CHECK(trials == 60);
  CHECK(cavitySum > 60);  // some cavities have more than one triangle: the test is not trivial
}

TEST_CASE("2.1.1 ker(Sigma) is the intersection of the half-planes of the oriented edges") {
  // A star-shaped polygon (7 spikes) and a comb-like polygon whose kernel is empty.
  std::vector<dt::Point2> star;
  for (int k = 0; k < 14; ++k) {
    const double a = 2 * M_PI * k / 14, r = k % 2 ? 1.0 : 0.45 + 0.05 * (k % 3);
    star.push_back({r * std::cos(a) + 0.1, r * std::sin(a)});
  }
  const std::vector<dt::Point2> comb = {{0, 0}, {4, 0}, {4, 3}, {3, 3}, {3, 1},
                                        {1, 1}, {1, 3}, {0, 3}};
  const std::vector<dt::Point2> square = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  struct Case {
    const std::vector<dt::Point2>* poly;
    bool kernelEmpty;
  };
  for (const Case& c : {Case{&star, false}, Case{&comb, true}, Case{&square, false}}) {
    const auto& P = *c.poly;
    const std::vector<dt::Point2> K = dt::polygonKernel(P);
    CHECK(K.empty() == c.kernelEmpty);
    // Sample a 61 x 61 grid over the bounding box: grid points fall exactly on edge lines and
    // their extensions, where a rounded test would disagree.
    double x0 = P[0].x, x1 = x0, y0 = P[0].y, y1 = y0;
    for (const auto& q : P) {
      x0 = std::min(x0, q.x), x1 = std::max(x1, q.x);
      y0 = std::min(y0, q.y), y1 = std::max(y1, q.y);
    }
    std::size_t inKernel = 0, agree = 0, samples = 0;
    for (int i = 0; i <= 60; ++i)
      for (int j = 0; j <= 60; ++j) {
        const dt::Point2 x = {x0 + (x1 - x0) * i / 60, y0 + (y1 - y0) * j / 60};
        bool seesAll = true;
        for (std::size_t k = 0; k < P.size() && seesAll; ++k) seesAll = dt::seesCorner(P, x, k);
        const bool half = dt::inOpenKernel(P, x);
        agree += seesAll == half;
        inKernel += half;
        ++samples;
      }
    CHECK(agree == samples);
    CHECK((inKernel == 0) == c.kernelEmpty);
    if (!K.empty()) {
      // The computed kernel's centroid is in the open kernel.
      dt::Point2 g = {0, 0};
      for (const auto& q : K) g.x += q.x / double(K.size()), g.y += q.y / double(K.size());
      CHECK(dt::inOpenKernel(P, g));
    }
  }
  // The unit square is its own kernel.
  CHECK(dt::polygonKernel(square).size() == 4);
}

TEST_CASE("2.1.2 Prop. 2.1.1: the cavity is non-empty and edge-connected and star-shaped with p in its kernel") {
  // Checked exactly at every insertion; the cavity is computed by testing every face, so its
  // connectivity is a real check. Grids and exactly cocircular points are the hard cases.
  XY uniform = dt::uniformPoints(2000, dttest::variant(7));
  XY grid = dt::gridPoints(30, 30, 0.125);
  dt::shufflePoints(grid, dttest::variant(8));
  XY circle = dt::circlePoints(400);
  dt::shufflePoints(circle, dttest::variant(9));
  XY cocircular = integerCirclePoints();
  REQUIRE(cocircular.size() / 2 == 324);
  dt::shufflePoints(cocircular, dttest::variant(10));
  XY gridSorted = dt::gridPoints(20, 20);  // lexicographic order: long thin cavities
  std::size_t total = 0;
  for (const XY* p : {&uniform, &grid, &circle, &cocircular, &gridSorted}) {
    const KernelRun run = runKernel(*p, 1u << 30);
    INFO(run.error);
    CHECK(run.ok);
    CHECK(run.insertions == p->size() / 2);
    total += run.insertions;
  }
  CHECK(total == 2000 + 900 + 400 + 324 + 400);
}

TEST_CASE("2.1.2 Property 2.1.1: no point of S_n inside the cavity hence |bnd| = |C| + 2") {
  // checkCavity counts the vertices off the boundary and the boundary edges; a cavity that
  // violated Property 2.1.1 would show |bnd| = |C| + 2 - 2 (inner vertices).
  const KernelRun run = runKernel(dt::uniformPoints(500, dttest::variant(11)), 1u << 30);
  INFO(run.error);
  CHECK(run.ok);
  // Control: the star of an interior vertex s (all its faces) with p next to s is not a
  // cavity: s is an inner vertex and |bnd| = |C|. The check does see the difference.
  dt::Triangulation T;
  std::vector<dt::Vertex*> S;
  const XY g = dt::gridPoints(3, 3);
  for (std::size_t i = 0; i < 9; ++i) S.push_back(T.addVertex(g[2 * i], g[2 * i + 1], long(i)));
  dt::delaunayTrglHull(T, S, dt::StartRule::LastCavity);
  dt::Vertex* s = S[4];  // (1, 1), the centre of the 3 x 3 grid
  std::vector<const dt::Face*> starOfS;
  for (const dt::Face& f : T.faces())
    if (!f.deleted && !f.isGhost() && (f.V[0] == s || f.V[1] == s || f.V[2] == s))
      starOfS.push_back(&f);
  dt::Vertex p(1.01, 1.02);
  const dt::CavityReport rep = dt::checkCavity(starOfS, &p);
  CHECK_FALSE(rep.ok);
  CHECK(rep.innerVertices == starOfS.size());  // s counted once per face around it
  CHECK(rep.boundaryEdges == starOfS.size());
}

TEST_CASE("2.1.3 the ball has |C| + 2 triangles and DT_{n+1} is Delaunay") {
  // Full exact check after every insertion on smaller inputs (it costs O(n) each).
  XY grid = dt::gridPoints(12, 12);
  dt::shufflePoints(grid, 12);
  XY circle = dt::circlePoints(120);
  dt::shufflePoints(circle, 13);
  for (const XY* p : {&grid, &circle}) {
    const KernelRun run = runKernel(*p, 1);
    INFO(run.error);
    CHECK(run.ok);
    CHECK(run.fullChecks == p->size() / 2);
  }
  const KernelRun big = runKernel(dt::uniformPoints(400, 14), 1);
  INFO(big.error);
  CHECK(big.ok);
  CHECK(big.fullChecks == 400);
}

TEST_CASE("2.1.1 segmentsIntersect counts a touching endpoint of either segment") {
  // Each endpoint of each segment in turn lies on the other segment, the segments otherwise
  // apart: exactly one of the four "touching" clauses decides.
  const dt::Point2 a = {0, 1}, b = {1, 0}, c = {0, 0}, d = {2, 0};
  CHECK(dt::segmentsIntersect(a, b, c, d));  // b on cd
  CHECK(dt::segmentsIntersect(b, a, c, d));  // a's end b, given first
  CHECK(dt::segmentsIntersect(c, d, a, b));  // the second segment's end b on the first
  CHECK(dt::segmentsIntersect(c, d, b, a));
  CHECK_FALSE(dt::segmentsIntersect(a, {1, 0.5}, c, d));  // stops short of cd
}

TEST_CASE("2.1.1 insidePolygon counts a ray through a vertex once") {
  // The ray from x towards +x passes exactly through a corner of the polygon, where the
  // boundary goes on from below the ray to above it (and, for the outer point, through two
  // corners). The crossing number is half-open in y, so that corner is one crossing, not zero
  // and not two; a rule closed at the lower end counts the wrong edge at the corner.
  const std::vector<dt::Point2> diamond = {{0, -1}, {1, 0}, {0, 1}, {-1, 0}};
  CHECK(dt::insidePolygon(diamond, {0, 0}));          // the ray meets corner (1, 0)
  CHECK(dt::insidePolygon(diamond, {0.5, 0}));
  CHECK(dt::insidePolygon(diamond, {-0.5, 0}));
  CHECK_FALSE(dt::insidePolygon(diamond, {-2, 0}));   // through corners (-1, 0) and (1, 0)
  CHECK_FALSE(dt::insidePolygon(diamond, {2, 0}));
  CHECK_FALSE(dt::insidePolygon(diamond, {1, 0}));    // on the boundary
  // The same polygon clockwise: the same answers.
  const std::vector<dt::Point2> cw(diamond.rbegin(), diamond.rend());
  CHECK(dt::insidePolygon(cw, {0, 0}));
  CHECK_FALSE(dt::insidePolygon(cw, {-2, 0}));
}
