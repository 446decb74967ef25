/// \file test_degenerate.cpp Every triangulation method and the CLI, checked exactly on the degenerate families of degenerate.h (grids, cocircular, collinear, duplicates, 12 orders of magnitude, 1e+-300, few distinct points).
#include <doctest/doctest.h>

#include <algorithm>
#include <map>
#include <set>

#include "bowyer_watson.h"
#include "degenerate.h"
#include "fast_delaunay.h"
#include "flip.h"
#include "support.h"

using dtdeg::XY;

namespace {

using Tris = std::vector<std::array<int, 3>>;

// 1 for the first occurrence of each distinct point: the points DT(S) must use (every method
// keeps the first of equal points and merges the others into it).
std::vector<char> firstOccurrences(const XY& p, std::size_t* distinct = nullptr) {
  std::set<std::pair<double, double>> seen;
  std::vector<char> must(p.size() / 2, 0);
  for (std::size_t i = 0; i < p.size() / 2; ++i)
    must[i] = seen.emplace(p[2 * i], p[2 * i + 1]).second;
  if (distinct) *distinct = seen.size();
  return must;
}

// The exact check of a result given in input indices: DT(S), every distinct point used, no
// merged duplicate used.
void checkResult(const std::string& what, const XY& p, const Tris& tri) {
  const std::vector<char> must = firstOccurrences(p);
  std::size_t badIndex = 0, mergedUsed = 0;
  for (const auto& t : tri)
    for (int v : t) {
      if (v < 0 || v >= int(must.size()))
        ++badIndex;
      else
        mergedUsed += !must[v];
    }
  REQUIRE_MESSAGE(badIndex == 0, what);
  CHECK_MESSAGE(mergedUsed == 0, what << ": a merged duplicate is a vertex");
  const dt::CheckReport r = dt::checkDelaunay(p, tri, &must);
  CHECK_MESSAGE(r.ok, what << ": " << r.error);
}

std::vector<dt::Vertex*> addPoints(dt::Triangulation& T, const XY& p) {
  std::vector<dt::Vertex*> S;
  for (std::size_t i = 0; i < p.size() / 2; ++i)
    S.push_back(T.addVertex(p[2 * i], p[2 * i + 1], long(i)));
  return S;
}

// The finite faces without super vertices, in input indices (Vertex::id).
Tris inputTriangles(const dt::Triangulation& T) {
  const dt::PlainMesh m = dt::extractMesh(T, true);
  Tris out;
  for (const auto& t : m.tri)
    out.push_back({int(m.ids[t[0]]), int(m.ids[t[1]]), int(m.ids[t[2]])});
  return out;
}

void bbox(const XY& p, double& x0, double& y0, double& x1, double& y1) {
  x0 = x1 = p[0];
  y0 = y1 = p[1];
  for (std::size_t i = 0; i < p.size() / 2; ++i) {
    x0 = std::min(x0, p[2 * i]), x1 = std::max(x1, p[2 * i]);
    y0 = std::min(y0, p[2 * i + 1]), y1 = std::max(y1, p[2 * i + 1]);
  }
}

// Listing 2.7 from the two super-triangles of Algorithm 1: the result is DT(S0 ∪ S), checked
// as a whole (links included); it must use the 4 corners and every distinct point.
void superListing(const dtdeg::Family& f, dt::StartRule rule) {
  double x0, y0, x1, y1;
  bbox(f.points, x0, y0, x1, y1);
  dt::Triangulation T;
  dt::initSuperTriangles(T, x0, y0, x1, y1);
  const auto S = addPoints(T, f.points);
  dt::delaunayTrgl(T, S, rule);
  const dt::CheckReport r = dt::checkTriangulation(T);
  CHECK_MESSAGE(r.ok, f.name << " (super-triangles): " << r.error);
  std::size_t distinct = 0;
  firstOccurrences(f.points, &distinct);
  CHECK(r.nVertices == distinct + 4);
  CHECK(r.nHull == 4);
}

// Super-triangles, then the recovery of DT(S) by flips (2.3.6).
void superRecovered(const dtdeg::Family& f) {
  double x0, y0, x1, y1;
  bbox(f.points, x0, y0, x1, y1);
  dt::Triangulation T;
  dt::initSuperTriangles(T, x0, y0, x1, y1);
  const auto S = addPoints(T, f.points);
  dt::delaunayTrgl(T, S, dt::StartRule::LastCavity);
  dt::recoverDelaunay(T);
  checkResult(f.name + " (super + flips)", f.points, inputTriangles(T));
  dt::compactFaces(T);
  const dt::CheckReport r = dt::checkTriangulation(T);
  CHECK_MESSAGE(r.ok, f.name << " (super + flips, links): " << r.error);
}

// The hull method (2.2.2): ghost faces, no super-triangle.
Tris hullMethod(const dtdeg::Family& f, dt::StartRule rule) {
  dt::Triangulation T;
  const auto S = addPoints(T, f.points);
  dt::delaunayTrglHull(T, S, rule);
  const dt::CheckReport r = dt::checkTriangulation(T);
  CHECK_MESSAGE(r.ok, f.name << " (hull): " << r.error);
  const Tris tri = inputTriangles(T);
  checkResult(f.name + " (hull)", f.points, tri);
  return tri;
}

Tris fastMethod(const dtdeg::Family& f, dt::InsertionOrder order) {
  dt::FastOptions o;
  o.order = order;
  const dt::FastResult r = dt::fastDelaunay(f.points, o);
  checkResult(f.name + " (fast, order " + std::to_string(int(order)) + ")", f.points, r.tri);
  const std::vector<char> must = firstOccurrences(f.points);
  std::size_t badMerges = 0;  // a merged point that is a first occurrence, or not equal
  for (const auto& [dup, kept] : r.duplicates)
    badMerges += must[dup] || kept >= dup || f.points[2 * dup] != f.points[2 * kept] ||
                 f.points[2 * dup + 1] != f.points[2 * kept + 1];
  CHECK(badMerges == 0);
  CHECK(r.duplicates.size() + std::size_t(std::count(must.begin(), must.end(), 1)) ==
        must.size());
  return r.tri;
}

// The CLI with the given options; the .ele is read back and checked in input numbering.
void cli(const dtdeg::Family& f, const std::string& options, int index) {
  std::string tag = options;
  std::replace_if(tag.begin(), tag.end(), [](char c) { return c == ' ' || c == '-'; }, '_');
  const std::string base = "degenerate_" + std::to_string(index) + tag;
  const std::string in = dttest::tmpPath(base + ".node"), out = dttest::tmpPath(base + "_out");
  std::remove((out + ".ele").c_str());
  dttest::writeText(in, dttest::nodeText(f.points, 1));
  const dttest::CliResult r = dttest::runCli("'" + in + "' -o '" + out + "' " + options);
  REQUIRE_MESSAGE(r.status == 0, f.name << " (CLI " << options << "): " << r.err);
  checkResult(f.name + " (CLI " + options + ")", f.points, dttest::readEle(out + ".ele", 1));
}

// Sorted list of triangles, each rotated to start at its smallest index: equal iff same mesh.
std::vector<std::array<int, 3>> canonical(Tris tri) {
  for (auto& t : tri) std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
  std::sort(tri.begin(), tri.end());
  return tri;
}

}  // namespace

TEST_CASE("degenerate families Listing 2.7 with super-triangles gives a valid DT(S0 u S)") {
  for (const dtdeg::Family& f : dtdeg::families()) {
    CAPTURE(f.name);
    superListing(f, dt::StartRule::LastCavity);
  }
  // The printed start rule (always T[0]) walks far: smaller sets.
  for (const dtdeg::Family& f : dtdeg::families(true)) {
    CAPTURE(f.name);
    superListing(f, dt::StartRule::FirstFace);
  }
}

TEST_CASE("degenerate families super-triangles then flips (2.3.6) recover the exact DT(S)") {
  for (const dtdeg::Family& f : dtdeg::families()) {
    CAPTURE(f.name);
    superRecovered(f);
  }
}

TEST_CASE("degenerate families the hull method (2.2.2) gives the exact DT(S)") {
  for (const dtdeg::Family& f : dtdeg::families()) {
    CAPTURE(f.name);
    hullMethod(f, dt::StartRule::LastCavity);
  }
  for (const dtdeg::Family& f : dtdeg::families(true)) {
    CAPTURE(f.name);
    hullMethod(f, dt::StartRule::FirstFace);
  }
}

TEST_CASE("degenerate families the fast kernel gives the exact DT(S) in every order") {
  for (const dtdeg::Family& f : dtdeg::families()) {
    CAPTURE(f.name);
    for (dt::InsertionOrder o : {dt::InsertionOrder::Brio, dt::InsertionOrder::BrioDoubling,
                            dt::InsertionOrder::Hilbert, dt::InsertionOrder::Input})
      fastMethod(f, o);
  }
}

TEST_CASE("degenerate families Algorithm 1 (plain triangle list) gives a valid DT(S0 u S)") {
  for (const dtdeg::Family& f : dtdeg::families(true)) {
    CAPTURE(f.name);
    const dt::BowyerWatsonResult r = dt::bowyerWatson(f.points);
    const dt::CheckReport c = dt::checkDelaunay(r.xy, r.tri);
    CHECK_MESSAGE(c.ok, f.name << " (Algorithm 1): " << c.error);
    std::size_t distinct = 0;
    firstOccurrences(f.points, &distinct);
    CHECK(c.nVertices == distinct + 4);
  }
}

TEST_CASE("degenerate families the CLI writes the exact DT(S) with every method and kernel") {
  int i = 0;
  for (const dtdeg::Family& f : dtdeg::families()) {
    CAPTURE(f.name);
    cli(f, "--method hull", i);  // the fast kernel
    cli(f, "--method hull --kernel listings", i);
    cli(f, "--method super", i);
    ++i;
  }
}

TEST_CASE("degenerate families in general position give the same triangles with every method") {
  // Without 4 cocircular points DT(S) is unique, so all methods must agree triangle for
  // triangle (random points at 1e+-300 and in 12 nested scales are in general position with
  // overwhelming probability; the exact check above would catch a mesh that is not DT(S)).
  for (const dtdeg::Family& f : dtdeg::families()) {
    if (f.name.find("uniform") == std::string::npos && f.name.find("clusters") == std::string::npos)
      continue;
    CAPTURE(f.name);
    const auto ref = canonical(hullMethod(f, dt::StartRule::LastCavity));
    CHECK(canonical(fastMethod(f, dt::InsertionOrder::Brio)) == ref);
    double x0, y0, x1, y1;
    bbox(f.points, x0, y0, x1, y1);
    dt::Triangulation T;
    dt::initSuperTriangles(T, x0, y0, x1, y1);
    dt::delaunayTrgl(T, addPoints(T, f.points), dt::StartRule::LastCavity);
    dt::recoverDelaunay(T);
    CHECK(canonical(inputTriangles(T)) == ref);
  }
}

TEST_CASE("degenerate families include a huge input of few distinct points") {
  // 200000 points, 7 distinct: the duplicates must cost a walk each, not a failure.
  const dtdeg::Family f{"200000 copies of 7 points", dtdeg::fewDistinct(200000, 21)};
  const Tris hull = hullMethod(f, dt::StartRule::LastCavity);
  // The hull is (0,0) (1,0) (2,0.25) (-1,3): n_f = 2(n-1) - n_h = 2*6 - 4.
  CHECK(hull.size() == 8);
  fastMethod(f, dt::InsertionOrder::Brio);
  cli(f, "--method hull", 1000);
  cli(f, "--method hull --kernel listings --order input", 1000);
}

TEST_CASE("degenerate input without a triangulation is refused by every method") {
  const XY line = dtdeg::collinearThenOne(50);
  const XY collinear(line.begin(), line.end() - 2);  // without the point off the line
  const XY two = {0, 0, 1, 1, 0, 0, 1, 1, 1, 1};
  for (const XY& p : {collinear, two}) {
    dt::Triangulation T;
    CHECK_THROWS_AS(dt::delaunayTrglHull(T, addPoints(T, p), dt::StartRule::LastCavity),
                    dt::DegenerateInput);
    CHECK_THROWS_AS(dt::fastDelaunay(p), dt::DegenerateInput);
  }
}

TEST_CASE("degenerate coordinates near the overflow threshold: hull methods exact and super refused cleanly") {
  // Sums and differences of coordinates near DBL_MAX overflow; the hull method and the fast
  // kernel need neither (exact predicates, centroid computed without overflow). Super-triangles
  // 10x (or even 1.01x) the bounding box cannot be represented in doubles.
  dtdeg::Family f{"near DBL_MAX", dtdeg::scaledUniform(300, 1.7e308, 31)};
  f.points.insert(f.points.end(), {1.7976931348623157e308, 1.7976931348623157e308,
                                   -1.7976931348623157e308, 0, 0, -1.7976931348623157e308,
                                   0, 0, 5e-324, 0});
  hullMethod(f, dt::StartRule::LastCavity);
  fastMethod(f, dt::InsertionOrder::Brio);
  cli(f, "--method hull", 2000);
  cli(f, "--method hull --kernel listings", 2000);
  double x0, y0, x1, y1;
  bbox(f.points, x0, y0, x1, y1);
  dt::Triangulation T;
  CHECK_THROWS_AS(dt::initSuperTriangles(T, x0, y0, x1, y1), dt::DegenerateInput);
  const std::string in = dttest::tmpPath("near_max.node"), out = dttest::tmpPath("near_max_super");
  std::remove((out + ".ele").c_str());
  dttest::writeText(in, dttest::nodeText(f.points, 1));
  const dttest::CliResult r = dttest::runCli("'" + in + "' -o '" + out + "' --method super");
  CHECK(r.status == 2);
  CHECK(r.err.find("--method super cannot enclose points this close to the overflow threshold") !=
        std::string::npos);
  CHECK_FALSE(dttest::fileExists(out + ".ele"));
}
