// The judge of scripts/exercise.sh grade: `judge ID SEED` calls the functions of exercise ID on
// inputs drawn from SEED and prints what they returned, one canonical line per fact, then
// "end ID". It is linked once with the teacher's solution (the reference) and once per student
// with the student's object, and run in the sandbox; a checker that never runs student code
// compares the two outputs. A student can print anything here, but only the right answers
// match the reference, which the sandbox never shows.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <map>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "adjacency.h"
#include "check.h"
#include "exercises.h"
#include "generators.h"
#include "predicates.h"
#include "star.h"
#include "stats.h"
#include "triangulate.h"

namespace {

// What a call did, in words that do not depend on the student's messages.
template <class F>
std::string outcome(F&& call) {
  try {
    call();
    return "returns";
  } catch (const std::logic_error&) {
    return "throws std::logic_error";
  } catch (...) {
    return "throws something else";
  }
}

// Every line starts with "tK ", K the test of exercises/exercises.txt (in its order) whose
// claim the line checks: the grader gives test K's column a pass only when its lines match.

// DT(S0 u S) of n uniform points on the super-triangles (the library's kernel, trusted here).
void mesh(dt::Triangulation& T, std::size_t n, std::uint64_t seed) {
  const dt::XY p = dt::uniformPoints(n, seed);
  std::vector<dt::Vertex*> S;
  for (std::size_t i = 0; i < p.size() / 2; ++i) S.push_back(T.addVertex(p[2 * i], p[2 * i + 1], long(i)));
  dt::initSuperTriangles(T, 0, 0, 1, 1);
  dt::delaunayTrgl(T, S, dt::StartRule::LastCavity);
}

// A link as the checker compares it: the index of the face in the list, "out" for a face
// outside it (by the index it had in the whole mesh), "null".
std::string linkName(const std::vector<dt::Face*>& list, const std::map<const dt::Face*, std::size_t>& whole,
                     const dt::Face* f) {
  if (f == nullptr) return "null";
  for (std::size_t i = 0; i < list.size(); ++i)
    if (list[i] == f) return "face " + std::to_string(i);
  const auto it = whole.find(f);
  return it == whole.end() ? "unknown" : "outside face " + std::to_string(it->second);
}

void printLinks(const char* what, const std::vector<dt::Face*>& list,
                const std::map<const dt::Face*, std::size_t>& whole) {
  for (std::size_t i = 0; i < list.size(); ++i)
    for (int k = 0; k < 3; ++k)
      std::printf("%s: face %zu edge %d (%ld -> %ld) links %s\n", what, i, k, list[i]->V[k]->id,
                  list[i]->V[(k + 1) % 3]->id, linkName(list, whole, list[i]->F[k]).c_str());
}

// 2.3.4-1: computeAdjacenciesSorted restores links, rejects non-manifold lists, keeps the links
// across unmatched edges.
void judgeAdjacencies(std::uint64_t seed) {
  dt::Triangulation T;
  mesh(T, 1500, seed);
  std::vector<dt::Face*> all;
  std::map<const dt::Face*, std::size_t> whole;
  for (dt::Face& f : T.faces()) whole[&f] = all.size(), all.push_back(&f);
  const std::vector<std::array<dt::Face*, 3>> keep = [&] {
    std::vector<std::array<dt::Face*, 3>> v;
    for (dt::Face* f : all) v.push_back({f->F[0], f->F[1], f->F[2]});
    return v;
  }();
  for (dt::Face* f : all) f->F[0] = f->F[1] = f->F[2] = nullptr;
  std::printf("t1 whole mesh: %s\n", outcome([&] { dt::computeAdjacenciesSorted(all); }).c_str());
  printLinks("t1 whole mesh", all, whole);
  for (std::size_t i = 0; i < all.size(); ++i)
    for (int k = 0; k < 3; ++k) all[i]->F[k] = keep[i][std::size_t(k)];

  // The balls of three vertices: the links inside are forgotten, those across the boundary stay.
  std::mt19937_64 pick(seed);
  for (int round = 0; round < 3; ++round) {
    const long vid = long(pick() % 1500);
    std::vector<dt::Face*> ball;
    for (dt::Face* f : all)
      if (f->V[0]->id == vid || f->V[1]->id == vid || f->V[2]->id == vid) ball.push_back(f);
    std::vector<std::array<dt::Face*, 3>> before;
    for (dt::Face* f : ball) before.push_back({f->F[0], f->F[1], f->F[2]});
    for (dt::Face* f : ball)
      for (int k = 0; k < 3; ++k)
        if (std::find(ball.begin(), ball.end(), f->F[k]) != ball.end()) f->F[k] = nullptr;
    const std::string what = "t3 ball of vertex " + std::to_string(vid);
    std::printf("%s: %s\n", what.c_str(), outcome([&] { dt::computeAdjacenciesSorted(ball); }).c_str());
    printLinks(what.c_str(), ball, whole);
    for (std::size_t i = 0; i < ball.size(); ++i)
      for (int k = 0; k < 3; ++k) ball[i]->F[k] = before[i][std::size_t(k)];
  }

  // A face turned over: its edges run the same way as in its neighbours.
  for (int round = 0; round < 2; ++round) {
    std::vector<dt::Face*> list = all;
    dt::Face* f = list[std::size_t(pick() % list.size())];
    std::swap(f->V[1], f->V[2]);
    std::printf("t2 face %zu turned over: %s\n", whole[f], outcome([&] { dt::computeAdjacenciesSorted(list); }).c_str());
    std::swap(f->V[1], f->V[2]);
  }

  // Three faces on one edge (a non-manifold list): two walk it one way, one the other.
  dt::Triangulation M;
  dt::Vertex* a = M.addVertex(0, 0, 0);
  dt::Vertex* b = M.addVertex(1, 0, 1);
  dt::Vertex* c = M.addVertex(0, 1, 2);
  dt::Vertex* d = M.addVertex(0, -1, 3);
  dt::Vertex* e = M.addVertex(1, 1, 4);
  std::vector<dt::Face*> three = {M.addFace(a, b, c), M.addFace(b, a, d), M.addFace(b, a, e)};
  std::printf("t4 three faces on the edge 0 - 1: %s\n", outcome([&] { dt::computeAdjacenciesSorted(three); }).c_str());
  std::vector<dt::Face*> twoOfThree = {three[0], three[2]};
  std::printf("t4 two of the three: %s\n", outcome([&] { dt::computeAdjacenciesSorted(twoOfThree); }).c_str());
  std::printf("t4 two of the three: face 0 edge 0 links %s\n", twoOfThree[0]->F[0] == twoOfThree[1] ? "face 1" : "another");
  std::vector<dt::Face*> two = {M.addFace(a, b, c), M.addFace(b, a, d)};
  std::printf("t2 two faces on the edge 0 - 1: %s\n", outcome([&] { dt::computeAdjacenciesSorted(two); }).c_str());
  std::printf("t2 two faces on the edge 0 - 1: face 0 edge 0 links %s, face 1 edge 0 links %s\n",
              two[0]->F[0] == two[1] ? "face 1" : "another", two[1]->F[0] == two[0] ? "face 0" : "another");
  std::vector<dt::Face*> none;
  std::printf("t1 an empty list: %s\n", outcome([&] { dt::computeAdjacenciesSorted(none); }).c_str());
}

// 2.1-1: polygonKernel and inOpenKernel on random star-shaped polygons and fixed hard ones.
std::vector<std::vector<dt::Point2>> polygons(std::uint64_t seed) {
  std::vector<std::vector<dt::Point2>> v;
  std::mt19937_64 r(seed);
  std::uniform_real_distribution<double> u(0.3, 1.0);
  for (int p = 0; p < 6; ++p) {
    const int m = 5 + int(r() % 12);
    std::vector<dt::Point2> poly;
    for (int k = 0; k < m; ++k) {
      const double a = 2 * M_PI * k / m, rad = k % 2 ? 1.0 : u(r);
      poly.push_back({rad * std::cos(a) + 0.125, rad * std::sin(a)});
    }
    v.push_back(poly);
  }
  v.push_back({{0, 0}, {3, 0}, {3, 1}, {1, 1}, {1, 3}, {0, 3}});
  v.push_back({{0, 0}, {1, 0}, {1, -1}, {4, -1}, {4, 0}, {3, 0}, {3, 1}, {0, 1}});  // a segment
  v.push_back({{0, 0}, {4, 0}, {4, 3}, {3, 3}, {3, 1}, {1, 1}, {1, 3}, {0, 3}});    // empty
  return v;
}

void judgeKernel(std::uint64_t seed) {
  const auto polys = polygons(seed);
  for (std::size_t p = 0; p < polys.size(); ++p) {
    double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
    for (const dt::Point2& q : polys[p])
      x0 = std::min(x0, q.x), y0 = std::min(y0, q.y), x1 = std::max(x1, q.x), y1 = std::max(y1, q.y);
    for (std::size_t r = 0; r < polys[p].size(); ++r) {
      std::vector<dt::Point2> P(polys[p].begin() + long(r), polys[p].end());
      P.insert(P.end(), polys[p].begin(), polys[p].begin() + long(r));
      std::vector<dt::Point2> K;
      const std::string did = outcome([&] { K = dt::polygonKernel(P); });
      double area = 0;
      for (std::size_t i = 0; i < K.size(); ++i)
        area += K[i].x * K[(i + 1) % K.size()].y - K[i].y * K[(i + 1) % K.size()].x;
      // The share of the box in hundredths: rounded corners move it far less, an uncut edge more.
      const double w = x1 - x0, h = y1 - y0;
      const long share = std::lround(100 * area / (2 * w * h));
      // A corner more than 1e-9 of the box right of an edge: an edge that did not cut.
      bool inner = true;
      for (std::size_t i = 0; i < P.size(); ++i) {
        const dt::Point2 a = P[i], c = P[(i + 1) % P.size()];
        const double len = std::hypot(c.x - a.x, c.y - a.y);
        for (const dt::Point2& q : K)
          inner = inner && ((c.x - a.x) * (q.y - a.y) - (c.y - a.y) * (q.x - a.x)) / len >= -1e-9 * std::max(w, h);
      }
      const bool flat = p + 2 >= polys.size();  // the segment and the empty kernel
      std::printf("t%d polygon %zu from corner %zu: kernel %s, %s\n", flat ? 4 : 3, p, r, did.c_str(),
                  K.empty() ? "empty" : ("area " + std::to_string(share) + "/100 of the box").c_str());
      if (!flat) std::printf("t2 polygon %zu from corner %zu: every corner on the inner side of every edge: %s\n", p, r,
                             inner ? "yes" : "no");
    }
    // The open kernel on a grid whose points fall on the lines of edges.
    std::string bits;
    for (int i = 0; i <= 40; ++i)
      for (int j = 0; j <= 40; ++j) {
        const dt::Point2 x{x0 + (x1 - x0) * i / 40, y0 + (y1 - y0) * j / 40};
        bool in = false;
        const std::string did = outcome([&] { in = dt::inOpenKernel(polys[p], x); });
        bits += did == "returns" ? (in ? '1' : '0') : 'x';
      }
    for (std::size_t row = 0; row < 41; ++row)
      std::printf("t1 polygon %zu open kernel at grid column %zu: %s\n", p, row, bits.substr(41 * row, 41).c_str());
  }
}

// 2.3.5-5: the branch-free Hilbert index of random cells (depth up to 8: test 1, beyond: test 2);
// the reference holds the teacher's values.
void judgeHilbert(std::uint64_t seed) {
  std::mt19937_64 r(seed);
  for (int depth : {1, 2, 3, 5, 8, 16, 31}) {
    const std::uint32_t cells = depth >= 32 ? 0xffffffffu : (1u << depth) - 1u;
    for (int k = 0; k < 40; ++k) {
      const std::uint32_t i = std::uint32_t(r()) & cells, j = std::uint32_t(r()) & cells;
      std::uint64_t key = 0;
      const std::string did = outcome([&] { key = dt::hilbertIndexBranchFree(i, j, depth); });
      std::printf("t%d depth %d cell (%u, %u): %s %llu\n", depth > 8 ? 2 : 1, depth, i, j, did.c_str(), (unsigned long long)key);
    }
  }
}

}  // namespace

// The other judges, by section (one translation unit: grade compiles and links one object).
#include "judge_2_1.h"
#include "judge_2_2.h"
#include "judge_2_3.h"

namespace {

const std::map<std::string, std::function<void(std::uint64_t)>>& judges() {
  static const std::map<std::string, std::function<void(std::uint64_t)>> j = {
      {"2.1-1", judgeKernel},           {"2.1-2", judgeCheckCavity},      {"2.2-1", judgeBowyerWatson},
      {"2.2-3", judgeHullEdges},        {"2.2.2-1", judgeOneEdgeRegion},  {"2.3.1-1", judgeOrientCanonical},
      {"2.3.1-2", judgeExactBits},      {"2.3.1-3", judgeSegments},       {"2.3.2-1", judgeGridCounts},
      {"2.3.2-2", judgeLowDegree},      {"2.3.3-1", judgeHalfEdge},       {"2.3.3-2", judgeVertexStar},
      {"2.3.4-1", judgeAdjacencies},    {"2.3.4-2", judgeBackwardMean},   {"2.3.5-5", judgeHilbert},
      {"2.3.6-1", judgeStuckRecovery}};
  return j;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc == 2 && std::string(argv[1]) == "--list") {
    for (const auto& j : judges()) std::printf("%s\n", j.first.c_str());
    return 0;
  }
  if (argc != 3) {
    std::fprintf(stderr, "usage: judge ID SEED | judge --list\n");
    return 2;
  }
  const auto it = judges().find(argv[1]);
  if (it == judges().end()) {
    std::fprintf(stderr, "judge: no judge for exercise %s\n", argv[1]);
    return 2;
  }
  it->second(std::strtoull(argv[2], nullptr, 10));
  std::printf("end %s\n", argv[1]);
  return std::fflush(stdout) == 0 ? 0 : 1;
}
