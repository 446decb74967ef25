/// \file test_2_2_2_hull.cpp Tests of section 2.2.2: insertion outside the current convex hull (ghost faces, visible edges, collinear starts, supporting lines) and delaunay2d --method.
#include <doctest/doctest.h>

#include <algorithm>
#include <set>

#include "flip.h"
#include "hull.h"
#include "predicates.h"
#include "support.h"

namespace {

using dt::XY;

// The hull read from the ghosts against brute force: every point on or left of every hull edge;
// consecutive edges chained and turning left or going straight; every point lying on the
// boundary is a hull vertex.
void checkHull(const dt::Triangulation& T, const std::vector<dt::Vertex*>& S) {
  const auto H = dt::hullEdges(T);
  REQUIRE(H.size() >= 3);
  std::set<std::pair<double, double>> hullV;  // by coordinates: duplicates are merged
  for (std::size_t i = 0; i < H.size(); ++i) {
    const auto& e = H[i];
    const auto& n = H[(i + 1) % H.size()];
    REQUIRE(e.b == n.a);
    CHECK(dt::orientationTest(e.a, e.b, n.b) >= 0);
    hullV.insert({e.a->x, e.a->y});
  }
  for (const dt::Vertex* v : S) {
    bool onBoundary = false;
    for (const auto& e : H) {
      const int o = dt::orientationTest(e.a, e.b, v);
      REQUIRE(o >= 0);
      if (o == 0) onBoundary = true;  // on the line of a hull edge, inside the hull: on it
    }
    if (onBoundary) CHECK(hullV.count({v->x, v->y}) == 1);
  }
}

}  // namespace

TEST_CASE("2.2.2 visible hull edges form one chain seen strictly and none is seen from inside") {
  dt::Triangulation T;
  const auto S = dt::addVertices(T, dt::uniformPoints(400, 222));
  dt::delaunayTrglHull(T, S, dt::StartRule::LastCavity);
  REQUIRE(dt::checkTriangulation(T).ok);
  checkHull(T, S);
  const auto H = dt::hullEdges(T);
  const XY probes = dt::uniformPoints(300, 9, -1, 2);
  int outside = 0;
  for (std::size_t i = 0; i < probes.size() / 2; ++i) {
    dt::Vertex q(probes[2 * i], probes[2 * i + 1]);
    const auto V = dt::visibleHullEdges(T, &q);
    std::size_t brute = 0;
    for (const auto& e : H) brute += dt::orientationTest(e.a, e.b, &q) < 0;
    CHECK(V.size() == brute);
    for (std::size_t k = 1; k < V.size(); ++k) CHECK(V[k - 1].b == V[k].a);  // contiguous
    outside += !V.empty();
  }
  CHECK(outside > 100);
  for (const dt::Vertex* v : S) CHECK(dt::visibleHullEdges(T, v).empty());
  // On the supporting line of a hull edge, beyond it: that edge is not seen. Integer points, so
  // that q = (8, 0) lies exactly on the line of the hull edge (0,0) -> (4,0).
  dt::Triangulation Q;
  const auto SQ = dt::addVertices(Q, {0, 0, 4, 0, 4, 4, 0, 4, 2, 1, 1, 3});
  dt::delaunayTrglHull(Q, SQ, dt::StartRule::LastCavity);
  REQUIRE(dt::checkTriangulation(Q).ok);
  for (const XY& qxy : {XY{8, 0}, XY{-3, 0}}) {
    CAPTURE(qxy[0]);
    dt::Vertex q(qxy[0], qxy[1]);
    REQUIRE(dt::orientationTest(SQ[0], SQ[1], &q) == 0);
    const auto V = dt::visibleHullEdges(Q, &q);
    REQUIRE(V.size() == 1);  // only the side x = 4 (from the right) or x = 0 (from the left)
    CHECK_FALSE(V[0].a == SQ[0]);
    CHECK(V[0].a->x == V[0].b->x);
    CHECK(V[0].a->x == (qxy[0] > 0 ? 4 : 0));
  }
}

TEST_CASE("2.2.2 every point outside the hull (lexicographic order) is inserted exactly") {
  XY p = dt::uniformPoints(3000, 17);
  std::vector<std::pair<double, double>> v;
  for (std::size_t i = 0; i < p.size() / 2; ++i) v.emplace_back(p[2 * i], p[2 * i + 1]);
  std::sort(v.begin(), v.end());
  dt::Triangulation T;
  std::vector<dt::Vertex*> S;
  for (std::size_t i = 0; i < v.size(); ++i) S.push_back(T.addVertex(v[i].first, v[i].second, long(i)));
  // Each point is outside the hull of the previous ones: count the visible edges on the way.
  dt::Triangulation W;
  std::vector<dt::Vertex*> SW;
  for (std::size_t i = 0; i < v.size(); ++i) SW.push_back(W.addVertex(v[i].first, v[i].second, long(i)));
  dt::delaunayTrglHull(W, {SW[0], SW[1], SW[2]}, dt::StartRule::LastCavity);
  dt::InsertionScratch scratch;
  dt::InsertionStats st;
  std::size_t visibleTotal = 0;
  for (std::size_t i = 3; i < SW.size(); ++i) {
    const auto vis = dt::visibleHullEdges(W, SW[i]);
    REQUIRE(!vis.empty());
    visibleTotal += vis.size();
    REQUIRE(dt::insertVertex(W, vis[0].ghost, SW[i], st, scratch) != nullptr);
  }
  const dt::CheckReport r = dt::checkTriangulation(W);
  CHECK_MESSAGE(r.ok, r.error);
  CHECK(r.nVertices == 3000);
  checkHull(W, SW);
  MESSAGE("mean visible hull edges per insertion: " << double(visibleTotal) / 2997);
  CHECK(visibleTotal >= 2997);
}

TEST_CASE("2.2.2 collinear starting points and points on hull supporting lines") {
  // 60 collinear points first (in shuffled order), then points on the same line beyond the
  // ends, then points on the supporting lines of the first triangle's edges, then the rest.
  XY line;
  for (int i = 0; i < 60; ++i) line.push_back(i), line.push_back(0.5 * i);
  dt::shufflePoints(line, 3);
  XY p = line;
  p.insert(p.end(), {10, 20});                            // the first point off the line
  p.insert(p.end(), {-10, -5, 100, 50, 200, 100});        // on the line, beyond its ends
  p.insert(p.end(), {10, 30, 10, -40, 15, 0, 300, 150});  // x = 10 line, y = 0 line, the line
  XY rest = dt::uniformPoints(200, 8, -20, 300);
  p.insert(p.end(), rest.begin(), rest.end());
  for (auto rule : {dt::StartRule::LastCavity, dt::StartRule::FirstFace}) {
    dt::Triangulation T;
    const auto S = dt::addVertices(T, p);
    dt::delaunayTrglHull(T, S, rule);
    const dt::CheckReport r = dt::checkTriangulation(T);
    CHECK_MESSAGE(r.ok, r.error);
    CHECK(r.nVertices == p.size() / 2);
    checkHull(T, S);
  }
  // Growing the hull along its own edges' lines: a square, then points on the lines of its
  // sides; every step is validated.
  dt::Triangulation T;
  const auto S = dt::addVertices(T, {0, 0, 1, 0, 1, 1, 0, 1, 2, 0, 3, 0, -1, 0, 1, 2, 1, -3, 0, 5,
                               0.5, 0, 3, 1, -1, 1, 3, 3});
  dt::delaunayTrglHull(T, {S[0], S[1], S[2], S[3]}, dt::StartRule::LastCavity);
  dt::InsertionScratch scratch;
  dt::InsertionStats st;
  for (std::size_t i = 4; i < S.size(); ++i) {
    CAPTURE(i);
    dt::insertVertex(T, dt::anyGhost(T), S[i], st, scratch);
    const dt::CheckReport r = dt::checkTriangulation(T);
    REQUIRE_MESSAGE(r.ok, r.error);
    std::vector<dt::Vertex*> sofar(S.begin(), S.begin() + long(i) + 1);
    checkHull(T, sofar);
  }
  // The hull of the 14 points, by brute force beside the test: (1,-3) pulls the bottom below
  // y = 0, so of the points on that line only (-1,0) and (3,0) remain on the hull.
  std::set<std::pair<double, double>> hull;
  for (const dt::Vertex* v : dt::convexHull(T)) hull.insert({v->x, v->y});
  const std::set<std::pair<double, double>> expected = {{-1, 0}, {-1, 1}, {0, 5}, {1, -3},
                                                        {3, 0},  {3, 1},  {3, 3}};
  CHECK(hull == expected);
}

TEST_CASE("2.2.2 the sweep triangulation (plain outside-hull insertions) is a valid triangulation") {
  XY col;  // a collinear start of 40 points, duplicates, then random points
  for (int i = 0; i < 40; ++i) col.push_back(0), col.push_back(i);
  col.insert(col.end(), {0, 3, 0, 3, 5, 5});
  XY r = dt::uniformPoints(500, 4, 0.5, 10);
  col.insert(col.end(), r.begin(), r.end());
  for (const XY& p : {col, dt::gridPoints(20, 20), dt::circlePoints(100)}) {
    dt::Triangulation T;
    const auto S = dt::addVertices(T, p);
    dt::SweepStats st;
    dt::sweepTriangulation(T, S, &st);
    std::set<std::pair<double, double>> distinct;
    for (std::size_t i = 0; i < p.size() / 2; ++i) distinct.insert({p[2 * i], p[2 * i + 1]});
    CHECK(st.duplicates == p.size() / 2 - distinct.size());
    std::vector<const dt::Vertex*> used;
    std::size_t finite = 0;
    for (const dt::Face& f : T.faces()) {
      REQUIRE(f.F[0] != nullptr);
      REQUIRE(f.F[1] != nullptr);
      REQUIRE(f.F[2] != nullptr);
      if (f.isGhost()) continue;
      ++finite;
      CHECK(dt::orientationTest(f.V[0], f.V[1], f.V[2]) > 0);
    }
    const auto H = dt::hullEdges(T);
    CHECK(finite == 2 * (distinct.size() - 1) - H.size());  // Euler: all points used
    checkHull(T, S);
    dt::lawsonFlip(T);
    const dt::CheckReport c = dt::checkTriangulation(T);
    CHECK_MESSAGE(c.ok, c.error);
  }
  dt::Triangulation T;
  CHECK_THROWS_AS(dt::sweepTriangulation(T, dt::addVertices(T, {0, 0, 1, 1, 2, 2, 3, 3})),
                  dt::DegenerateInput);
  dt::Triangulation U;
  const auto S = dt::addVertices(U, {0, 0, 1, 0, 0, 1});
  dt::sweepTriangulation(U, S);
  dt::Vertex inside(0.2, 0.2);
  CHECK_THROWS_AS(dt::insertOutsideHull(U, &inside, dt::anyGhost(U)), std::invalid_argument);
}

TEST_CASE("2.2.2 delaunay2d --method super and --method hull give the same exact DT(S)") {
  struct Case {
    std::string name;
    XY p;
  };
  XY bent;  // a flat arc: every hull triangle nearly flat (huge circumcircles)
  const XY u = dt::uniformPoints(300, 31);
  for (std::size_t i = 0; i < 300; ++i) bent.push_back(u[2 * i]), bent.push_back(1e-7 * u[2 * i] * (1 - u[2 * i]));
  const Case cases[] = {{"uniform", dt::uniformPoints(2000, 30)},
                        {"grid", dt::gridPoints(25, 25)},
                        {"circle", dt::circlePoints(300)},
                        {"bent", bent}};
  for (const Case& c : cases) {
    CAPTURE(c.name);
    std::vector<std::vector<std::array<int, 3>>> results;
    for (const char* method : {"hull", "super"}) {
      const std::string in = dttest::tmpPath("m222_" + c.name + ".node");
      const std::string out = dttest::tmpPath("m222_" + c.name + "_" + method);
      std::remove((out + ".ele").c_str());
      dttest::writeText(in, dttest::nodeText(c.p, 1));
      const dttest::CliResult r =
          dttest::runCli("'" + in + "' -o '" + out + "' --stats --method " + method);
      REQUIRE_MESSAGE(r.status == 0, r.err);
      auto tri = dttest::readEle(out + ".ele", 1);
      const dt::CheckReport ck = dt::checkDelaunay(c.p, tri);
      CHECK_MESSAGE(ck.ok, ck.error);
      CHECK(ck.nVertices == c.p.size() / 2);
      if (std::string(method) == "super")
        CHECK(r.out.find("recovery_flips: ") != std::string::npos);
      for (auto& t : tri) std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
      std::sort(tri.begin(), tri.end());
      results.push_back(tri);
    }
    // Generic inputs have one DT(S); the grid and the circle have cocircular points and several.
    if (c.name == "uniform" || c.name == "bent") CHECK(results[0] == results[1]);
    CHECK(results[0].size() == results[1].size());
  }
  const dttest::CliResult bad = dttest::runCli("x.node -o y --method fast");
  CHECK(bad.status == 2);
}
