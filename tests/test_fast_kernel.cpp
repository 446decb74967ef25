/// \file test_fast_kernel.cpp Tests of the fast kernel (code/fast/fast_delaunay.h): the same exact DT(S) as the corrected listings, on easy and degenerate inputs.
#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

#include <sys/mman.h>
#include <sys/utsname.h>

#include "check.h"
#include "delaunay.h"
#include "fast_delaunay.h"
#include "fast_ladder.h"
#include "fast_parallel.h"
#include "hilbert.h"
#include "huge_pages.h"
#include "predicates.h"
#include "support.h"

namespace {

using Tris = std::vector<dt::Tri>;

// Each triangle rotated to start at its smallest vertex, the list sorted: two triangulations
// are the same iff their canonical forms are equal.
Tris canonical(Tris t) {
  for (auto& f : t) std::rotate(f.begin(), std::min_element(f.begin(), f.end()), f.end());
  std::sort(t.begin(), t.end());
  return t;
}

// The corrected listings (delaunayTrglHull), triangles numbered as the input.
Tris listings(const dttest::XY& p) {
  dt::Triangulation T;
  std::vector<dt::Vertex*> S;
  for (std::size_t i = 0; i < p.size() / 2; ++i)
    S.push_back(T.addVertex(p[2 * i], p[2 * i + 1], long(i)));
  dt::delaunayTrglHull(T, S, dt::StartRule::LastCavity);
  const dt::PlainMesh m = dt::extractMesh(T, true);
  Tris out;
  for (const auto& f : m.tri) out.push_back({int(m.ids[f[0]]), int(m.ids[f[1]]), int(m.ids[f[2]])});
  return out;
}

// A kernel: fastDelaunay, or a rung of the optimisation ladder (the core with the listings'
// policies, fast_ladder.h, in the build for every x86-64 processor).
using Kernel = dt::FastResult (*)(const std::vector<double>&, const dt::FastOptions&);
namespace fast = dt::fast;
dt::FastResult library(const std::vector<double>& p, const dt::FastOptions& o) {
  return dt::fastDelaunay(p, o);
}
dt::FastResult called(const std::vector<double>& p, const dt::FastOptions& o) {
  return fast::withCalledPredicates<>(p, o, {false, true});
}
dt::FastResult calledLastCavity(const std::vector<double>& p, const dt::FastOptions& o) {
  return fast::withCalledPredicates<>(p, o, {false, false});
}
dt::FastResult centroid(const std::vector<double>& p, const dt::FastOptions& o) {
  return fast::withCalledPredicates<fast::CentroidWalk>(p, o, {false, false});
}
dt::FastResult mapCentroid(const std::vector<double>& p, const dt::FastOptions& o) {
  return fast::withCalledPredicates<fast::CentroidWalk, fast::MapLink>(p, o, {false, false});
}

// Runs the fast kernel (or a rung), checks the result exactly, and returns it.
dt::FastResult fastChecked(const dttest::XY& p, const dt::FastOptions& o = {},
                           Kernel kernel = library) {
  dt::FastResult r = kernel(p, o);
  std::vector<char> must(p.size() / 2, 1);
  for (const auto& d : r.duplicates) must[std::size_t(d.first)] = 0;
  const dt::CheckReport c = dt::checkDelaunay(p, r.tri, &must);
  INFO(c.error);
  CHECK(c.ok);
  return r;
}

struct Variant {
  dt::FastOptions opt;
  Kernel kernel;
};

std::vector<Variant> allVariants() {
  std::vector<Variant> v;
  for (dt::InsertionOrder ord : {dt::InsertionOrder::Brio, dt::InsertionOrder::BrioDoubling, dt::InsertionOrder::Hilbert,
                            dt::InsertionOrder::Input}) {
    dt::FastOptions o;
    o.order = ord;
    v.push_back({o, library});
  }
  dt::FastOptions o;
  o.rounds = 1;
  for (Kernel k : {library, called, calledLastCavity, centroid, mapCentroid}) v.push_back({o, k});
  return v;
}

}  // namespace

TEST_CASE("fast kernel gives the same DT(S) as the corrected listings on random points in every variant") {
  const dttest::XY p = dttest::uniformPoints(3000, 91);
  const Tris ref = canonical(listings(p));
  REQUIRE(ref.size() > 5900);  // 2(n-1) - n_h with n_h about 20 for 3000 uniform points
  for (const Variant& w : allVariants()) {
    const dt::FastResult r = fastChecked(p, w.opt, w.kernel);
    CHECK(canonical(r.tri) == ref);  // points in general position: DT(S) is unique
    CHECK(r.stats.insertions == 3000);
  }
}

TEST_CASE("fast kernel on grid and circle and collinear hull is valid with as many triangles as the listings") {
  std::vector<dttest::XY> inputs;
  inputs.push_back(dttest::gridPoints(40, 40));            // 4 cocircular points per square
  inputs.push_back(dttest::circlePoints(500));             // all nearly cocircular
  dttest::XY square;                                        // 61 collinear points per side
  for (int i = 0; i < 60; ++i)
    for (const auto& q : {std::array<int, 2>{i, 0}, {60, i}, {60 - i, 60}, {0, 60 - i}}) {
      square.push_back(q[0]);
      square.push_back(q[1]);
    }
  square.push_back(30.5);
  square.push_back(29.25);
  inputs.push_back(square);
  dttest::XY line = dttest::uniformPoints(300, 5);          // one point off a long line
  for (std::size_t i = 0; i < line.size(); i += 2) line[i + 1] = 3 * line[i] - 1;
  line.push_back(0.5);
  line.push_back(2);
  inputs.push_back(line);
  for (dttest::XY p : inputs) {
    dttest::shuffle(p, 7);
    const std::size_t nRef = listings(p).size();
    for (const Variant& w : allVariants()) CHECK(fastChecked(p, w.opt, w.kernel).tri.size() == nRef);
  }
}

TEST_CASE("fast kernel keeps the exact result on huge and tiny coordinates") {
  for (double scale : {1e300, 1e-300, 0x1p-1060}) {
    dttest::XY p = dttest::uniformPoints(400, 13);
    dttest::XY g = dttest::gridPoints(8, 8, 0.125);
    p.insert(p.end(), g.begin(), g.end());
    for (double& v : p) v *= scale;
    INFO("scale " << scale);
    const std::size_t nRef = listings(p).size();
    const dt::FastResult r = fastChecked(p);
    CHECK(r.tri.size() == nRef);
  }
}

TEST_CASE("fast kernel merges duplicates into the smallest-numbered equal point") {
  dttest::XY p = dttest::uniformPoints(200, 3);
  const dttest::XY base = p;
  // Points 200..399 repeat 0..199, and 400..409 repeat point 5 again.
  p.insert(p.end(), base.begin(), base.end());
  for (int k = 0; k < 10; ++k) {
    p.push_back(base[10]);
    p.push_back(base[11]);
  }
  for (dt::InsertionOrder ord : {dt::InsertionOrder::Brio, dt::InsertionOrder::Input}) {
    dt::FastOptions o;
    o.order = ord;
    const dt::FastResult r = fastChecked(p, o);
    REQUIRE(r.duplicates.size() == 210);
    for (const auto& [d, kept] : r.duplicates) {
      CHECK(d >= 200);
      CHECK(kept == (d < 400 ? d - 200 : 5));
    }
    CHECK(canonical(r.tri) == canonical(listings(base)));
  }
}

TEST_CASE("fast kernel refuses inputs without a triangulation") {
  CHECK_THROWS_AS(dt::fastDelaunay({0, 0, 1, 1, 2, 2, 3, 3}), dt::DegenerateInput);
  CHECK_THROWS_AS(dt::fastDelaunay({0, 0, 1, 1, 0, 0, 1, 1}), dt::DegenerateInput);
  CHECK_THROWS_AS(dt::fastDelaunay({0, 0, 1, 1}), dt::DegenerateInput);
  CHECK_THROWS_AS(dt::fastDelaunay({0, 0, 1, NAN, 2, 0}), std::invalid_argument);
  CHECK_THROWS_AS(dt::fastDelaunay({0, 0, 1, INFINITY, 2, 0}), std::invalid_argument);
  // Collinear points then one off the line: a triangulation exists.
  const dt::FastResult r = fastChecked({0, 0, 1, 1, 2, 2, 3, 3, 0, 1}, {});
  CHECK(r.tri.size() == 3);
}

TEST_CASE("fast kernel filters send exactly the degenerate tests to the exact stages") {
  // Random points: no test needs more than the filter.
  const dt::FastResult u = fastChecked(dttest::uniformPoints(5000, 17));
  CHECK(u.stats.incircle[dt::pred::kExact] == 0);
  CHECK(u.stats.orient[dt::pred::kExact] == 0);
  CHECK(u.stats.incircle.beyondFilter() == 0);  // the filter decides every test
  CHECK(u.stats.incircle.calls() > 5000);
  // A grid: its cocircular squares and collinear rows defeat the filter, and the small-integer
  // stage decides them all exactly (no GMP call), on unit and on scaled grids alike.
  for (double step : {1.0, 0x1p-40, 0x1p+150}) {
    const dt::FastResult g = fastChecked(dttest::gridPoints(50, 50, step));
    CHECK(g.stats.incircle[dt::pred::kExact] == 0);
    CHECK(g.stats.orient[dt::pred::kExact] == 0);
    CHECK(g.stats.incircle[dt::pred::kSmallInt] > 0);
    CHECK(g.tri.size() == 2 * 49 * 49);
  }
  // The same with the library's out-of-line predicates (the ladder's first rungs): one core, so
  // the filter fails as often, and the small-multiple stage again leaves nothing to GMP.
  dt::predicateCounters().reset();
  const dt::FastResult gc = fastChecked(dttest::gridPoints(50, 50, 1.0), {}, called);
  CHECK(dt::predicateCounters().incircle.beyondFilter() > 0);
  CHECK(dt::predicateCounters().incircle[dt::pred::kSmallInt] ==
        dt::predicateCounters().incircle.beyondFilter());
  CHECK(gc.stats.incircle[dt::pred::kExact] == 0);
  CHECK(gc.stats.orient[dt::pred::kExact] == 0);
  // One record: the run copies the library's counts of its calls, stage by stage.
  for (int s = 0; s < dt::pred::kStageCount; ++s)
    CHECK(gc.stats.incircle[s] == dt::predicateCounters().incircle[s]);
  // A grid of step 0.1 (not a power of two: rounded coordinates) still ends in GMP sometimes,
  // and nearly cocircular points on a circle do.
  const dt::FastResult d = fastChecked(dttest::gridPoints(40, 40, 0.1));
  CHECK(d.tri.size() == 2 * 39 * 39);
  const dt::FastResult c = fastChecked(dttest::circlePoints(2000));
  CHECK(c.stats.incircle[dt::pred::kExact] > 0);
  // The mean cavity of 5000 random points (ghost triangles and BRIO rounds included), measured
  // over seeds 10-19: 4.015 to 4.080. The bounds are that spread doubled around its middle.
  CHECK(double(u.stats.cavityFaces) / double(u.stats.insertions) == doctest::Approx(4.05).epsilon(0.02));
}

TEST_CASE("fast kernel delaunay2d --kernel fast (the default) and --kernel listings write the same DT(S)") {
  dttest::XY p = dttest::uniformPoints(3000, 23);
  const dttest::XY g = dttest::gridPoints(5, 5, 0.25);  // cocircular: counts must still agree
  p.insert(p.end(), g.begin(), g.end());
  p.insert(p.end(), {p[0], p[1], p[20], p[21]});          // two duplicates
  const std::string in = dttest::tmpPath("fastk.node");
  dttest::writeText(in, dttest::nodeText(p));
  Tris got[3];
  const char* args[3] = {"", " --kernel fast", " --kernel listings"};
  for (int k = 0; k < 3; ++k) {
    const std::string out = dttest::tmpPath("fastk_" + std::to_string(k));
    const dttest::CliResult r = dttest::runCli("'" + in + "' -o '" + out + "'" + args[k]);
    REQUIRE_MESSAGE(r.status == 0, r.err);
    got[k] = dttest::readEle(out + ".ele", 1);
    CHECK(dt::checkDelaunay(p, got[k]).ok);
  }
  CHECK(canonical(got[0]) == canonical(got[1]));
  CHECK(got[1].size() == got[2].size());
  // Off the cocircular grid the triangulation is unique: the two kernels agree triangle by
  // triangle on the first 3000 points' triangles.
  auto generic = [](const Tris& t) {
    Tris out;
    for (const auto& f : canonical(t))
      if (f[0] < 3000 && f[1] < 3000 && f[2] < 3000) out.push_back(f);
    return out;
  };
  CHECK(generic(got[1]) == generic(got[2]));
  CHECK(dttest::runCli("'" + in + "' -o x --kernel quick").status == 2);
}

TEST_CASE("fast kernel handles a cavity of hundreds of triangles (the centre of a circle inserted last)") {
  // Every triangle of the points on the circle has the centre strictly inside its circle: the
  // last insertion removes them all, and its boundary has 400 edges (a deep cavity search).
  dttest::XY p = dttest::circlePoints(400);
  p.push_back(0);
  p.push_back(0);
  dt::FastOptions o;
  o.order = dt::InsertionOrder::Input;
  const dt::FastResult r = fastChecked(p, o);
  CHECK(r.tri.size() == 400);  // the fan around the centre
  CHECK(r.stats.cavityFaces >= 398);
}

TEST_CASE("fast kernel starts each walk in the new triangle around the last point that faces the next one") {
  // The start changes where the walks go, not what they find: the same DT(S), and on uniform
  // points in BRIO order the walks visit far fewer triangles than from the last cavity's last
  // new triangle (Table 2.2's rule, a rung of the ladder), about half as many.
  const dttest::XY p = dttest::uniformPoints(20000, 17);
  const dt::FastResult a = fastChecked(p, {}, called), b = fastChecked(p, {}, calledLastCavity);
  CHECK(canonical(a.tri) == canonical(b.tri));
  REQUIRE(a.stats.insertions == b.stats.insertions);
  const double stepsFacing = double(a.stats.walkSteps) / double(a.stats.insertions);
  const double stepsLast = double(b.stats.walkSteps) / double(b.stats.insertions);
  CAPTURE(stepsFacing);
  CAPTURE(stepsLast);
  CHECK(stepsFacing < 0.7 * stepsLast);
  CHECK(a.stats.orient.calls() < b.stats.orient.calls());
}

TEST_CASE("fast kernel the ladder's out-of-line predicates record the same calls as the inlined ones stage by stage") {
  // One core: the ladder's first rung only moves the predicates out of line, so the run makes the
  // same tests in the same order, and its record (copied from the library's counters) must equal
  // the inlined run's own, stage by stage, on points that reach the exact stages.
  const dttest::XY p = dttest::gridPoints(30, 30, 0.1);
  const dt::FastResult in = fastChecked(p);
  const dt::FastResult out = fastChecked(p, {}, called);
  CHECK(in.stats.incircle.beyondFilter() > 0);
  for (int s = 0; s < dt::pred::kStageCount; ++s) {
    CAPTURE(dt::pred::kStageNames[s]);
    CHECK(out.stats.orient[s] == in.stats.orient[s]);
    CHECK(out.stats.incircle[s] == in.stats.incircle[s]);
  }
}

TEST_CASE("fast kernel dt::triangulate gives the same DT(S) with every kernel and method and order") {
  dttest::XY p = dttest::uniformPoints(2000, 5);
  // Three duplicates: points 2000 and 2002 of point 10, 2001 of point 3 (a triple: each is
  // reported against the first of the three, not against the one before it).
  p.insert(p.end(), {p[20], p[21], p[6], p[7], p[20], p[21]});
  const Tris ref = canonical(listings(std::vector<double>(p.begin(), p.end() - 6)));
  CHECK_THROWS_AS(dt::orderNamed("brio-coin"), std::invalid_argument);
  for (dt::KernelChoice k : {dt::KernelChoice::Fast, dt::KernelChoice::Listings})
    for (dt::BuildMethod m : {dt::BuildMethod::Hull, dt::BuildMethod::Super})
      for (const char* order : {"brio", "brio-doubling", "hilbert", "input"}) {
        CAPTURE(int(k));
        CAPTURE(int(m));
        CAPTURE(order);
        dt::TriangulateOptions o;
        o.kernel = k;
        o.method = m;
        o.order = dt::orderNamed(order);
        CHECK(std::string(dt::orderName(o.order)) == order);  // the words read back
        const dt::TriangulateResult r = dt::triangulate(p, o);
        CHECK(r.checked);
        Tris t = r.tri;  // in the input's numbering
        for (auto& f : t)
          for (int& v : f) v = r.input[std::size_t(v)];
        CHECK(canonical(t) == ref);
        CHECK(r.duplicates == std::vector<std::pair<int, int>>{{2000, 10}, {2001, 3}, {2002, 10}});
        CHECK(r.insertions == 2000);
      }
  CHECK_THROWS_AS(dt::orderNamed("random"), std::invalid_argument);
}

TEST_CASE("fast kernel --order brio means the same BRIO rounds for the fast kernel and the listings") {
  // One meaning per order name: both kernels insert in brioCoinOrder, so on the same points the
  // listings' walk visits the points in the fast kernel's insertion order (r.input, the order of
  // the fast kernel's points) and the listings' vertex order follows it.
  const dttest::XY p = dttest::uniformPoints(3000, 8);
  std::vector<std::size_t> coin = dt::brioCoinOrder(p, dt::FastOptions{}.seed, dt::FastOptions{}.rounds);
  dt::TriangulateOptions o;
  o.check = false;
  const dt::TriangulateResult fast = dt::triangulate(p, o);
  CHECK(std::equal(coin.begin(), coin.end(), fast.input.begin(), fast.input.end(),
                   [](std::size_t a, int b) { return a == std::size_t(b); }));
  // The listings record their insertion statistics on the same order: the same cavities, so the
  // same sum of cavity sizes (the walks differ: Listing 2.6 is another walk).
  o.kernel = dt::KernelChoice::Listings;
  const dt::TriangulateResult lst = dt::triangulate(p, o);
  CHECK(lst.cavityFaces == fast.cavityFaces);
}

// The Store's arrays are mapped in one call (huge_pages.h), or in one call per thread with
// several threads: every whole page inside the range is resident afterwards, the partly covered
// pages at both ends are left alone, whatever the pieces.
TEST_CASE("fast kernel populatePages maps exactly the whole pages of a range") {
  constexpr std::size_t kPage = 4096, kPages = 16;
  for (int threads : {1, 2, 3, 20}) {
    CAPTURE(threads);
    void* m = ::mmap(nullptr, kPages * kPage, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS,
                     -1, 0);
    REQUIRE(m != MAP_FAILED);
    auto* base = static_cast<unsigned char*>(m);
    ::madvise(m, kPages * kPage, MADV_NOHUGEPAGE);  // so that one fault maps one page
    unsigned char in[kPages];
    REQUIRE(::mincore(m, kPages * kPage, in) == 0);
    for (std::size_t k = 0; k < kPages; ++k) CHECK((in[k] & 1) == 0);  // nothing touched yet
    // From 100 bytes into page 0 to 100 bytes into page 15: pages 1..14 are whole.
    const bool done = dt::populatePages(base + 100, (kPages - 1) * kPage, threads);
    utsname u{};
    ::uname(&u);
    int major = 0, minor = 0;
    std::sscanf(u.release, "%d.%d", &major, &minor);
    if (major > 5 || (major == 5 && minor >= 14)) CHECK(done);  // MADV_POPULATE_WRITE exists
    REQUIRE(::mincore(m, kPages * kPage, in) == 0);
    for (std::size_t k = 0; k < kPages; ++k) {
      CAPTURE(k);
      CHECK((in[k] & 1) == ((done && k >= 1 && k + 1 < kPages) ? 1 : 0));
    }
    ::munmap(m, kPages * kPage);
  }
}

TEST_CASE("fast kernel the x86-64-v3 build and the baseline build make the same tests and give the same DT(S)") {
  // The insertion loops run in a second build for x86-64-v3 processors (fast_core.h, runV3).
  // Same code, same rounding (no fused multiply-add): the same predicate calls stage by stage
  // and the same triangles in the same order, on points that reach the exact stages, with
  // duplicates; in the sequential kernel and in the parallel kernel's core.
  dttest::XY p = dttest::gridPoints(30, 30, 0.1);
  const dttest::XY u = dttest::uniformPoints(2000, 41);
  p.insert(p.end(), u.begin(), u.end());
  p.insert(p.end(), {p[0], p[1], p[100], p[101]});
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
  const bool v3 = __builtin_cpu_supports("x86-64-v3");
#else
  const bool v3 = false;
#endif
  // (library build, build for every x86-64 processor) of each kernel
  using Run = dt::FastResult (*)(const dttest::XY&);
  const std::pair<Run, Run> runs[2] = {
      {[](const dttest::XY& q) { return dt::fastDelaunay(q); },
       [](const dttest::XY& q) { return fast::oneThread<fast::InlinePredicates>(q, {}, {false, true}); }},
      {[](const dttest::XY& q) { return dt::fastDelaunaySharedCoreAlone(q); },
       [](const dttest::XY& q) { return fast::sharedCoreAlone(q, {}, false); }}};
  for (const auto& [library, baseline] : runs) {
    const dt::FastResult a = library(p), b = baseline(p);
    CHECK(a.stats.x86_64_v3 == v3);
    CHECK_FALSE(b.stats.x86_64_v3);
    CHECK(dt::checkDelaunay(p, a.tri).ok);
    CHECK(a.tri == b.tri);
    CHECK(a.duplicates == b.duplicates);
    CHECK(a.duplicates.size() == 2);
    CHECK(a.stats.incircle.beyondFilter() > 0);
    for (int s = 0; s < dt::pred::kStageCount; ++s) {
      CAPTURE(dt::pred::kStageNames[s]);
      CHECK(a.stats.orient[s] == b.stats.orient[s]);
      CHECK(a.stats.incircle[s] == b.stats.incircle[s]);
    }
  }
  // Two threads (whatever the cost model would choose): the build reaches the threads' loops too.
  const auto Slabs = dt::ParallelClaim::Slabs;
  const auto Always = dt::ParallelMode::Always;
  CHECK(dt::fastDelaunayParallel(p, 2, {}, nullptr, 64, Slabs, Always).stats.x86_64_v3 == v3);
}
