// The judges of section 2.2's exercises, part of exercises/judge.cpp (one translation unit):
// see the comment at its top.
#pragma once

#include "bowyer_watson.h"

namespace {

// 2.2.2-1: oneEdgeRegionBounded on every edge of random convex polygons (corners on a circle),
// of polygons with parallel edges, and on input the contract refuses.
void judgeOneEdgeRegion(std::uint64_t seed) {
  std::vector<std::pair<std::string, std::vector<dt::Point2>>> polys = {
      {"square", {{0, 0}, {1, 0}, {1, 1}, {0, 1}}},
      {"flat triangle", {{0, 0}, {10, 0}, {5, 0.01}}},
      {"trapezoid", {{0, 0}, {4, 0}, {3, 1}, {1, 1}}},
      {"hexagon with parallel sides", {{0, 0}, {2, 0}, {3, 1}, {2, 2}, {0, 2}, {-1, 1}}},
      {"two corners", {{0, 0}, {1, 0}}},
      {"a straight corner", {{0, 0}, {1, 0}, {2, 0}, {1, 1}}}};
  std::mt19937_64 r(seed);
  std::uniform_real_distribution<double> angle(0, 2 * M_PI);
  for (int k = 0; k < 30; ++k) {
    const int m = 3 + k % 7;
    std::vector<double> t(std::size_t(m), 0.0);
    for (double& x : t) x = angle(r);
    std::sort(t.begin(), t.end());
    std::vector<dt::Point2> P;
    for (double x : t) P.push_back({std::cos(x), std::sin(x)});
    polys.push_back({"random " + std::to_string(k), P});
  }
  for (int m = 5; m <= 9; ++m) {  // regular polygons: every region bounded
    std::vector<dt::Point2> P;
    for (int k = 0; k < m; ++k) P.push_back({std::cos(2 * M_PI * k / m + 0.3), std::sin(2 * M_PI * k / m + 0.3)});
    polys.push_back({"regular " + std::to_string(m), P});
  }
  for (const auto& [name, P] : polys) {
    std::string bits;
    for (std::size_t i = 0; i <= P.size(); ++i) {  // i = P.size(): no such edge
      bool b = false;
      const std::string did = outcome([&] { b = dt::oneEdgeRegionBounded(P, i); });
      bits += did != "returns" ? " (" + did + ")" : b ? " bounded" : " unbounded";
    }
    std::printf("t%d %s, edges 0..%zu:%s\n", name.rfind("random", 0) == 0 ? 2 : 1, name.c_str(), P.size(), bits.c_str());
  }
}

// Sets of points for Algorithm 1: random, a shuffled grid (cocircular), a circle, duplicates.
std::vector<std::pair<std::string, dt::XY>> bowyerWatsonInputs(std::uint64_t seed) {
  std::vector<std::pair<std::string, dt::XY>> v = {{"uniform", dt::uniformPoints(80, seed)}};
  dt::XY g = dt::gridPoints(7, 6);
  dt::shufflePoints(g, seed);
  v.push_back({"grid", g});
  dt::XY c = dt::circlePoints(24);
  dt::shufflePoints(c, seed + 1);
  v.push_back({"circle", c});
  dt::XY d = dt::uniformPoints(40, seed + 2);
  for (std::size_t i = 0; i < 10; ++i) d.push_back(d[4 * i]), d.push_back(d[4 * i + 1]);  // 10 points twice
  v.push_back({"duplicates", d});
  return v;
}

// 2.2-1: bowyerWatson's triangles (as canonicalTriangles names them, so the order of the list
// and the first corner are free), its duplicates and cavity sizes; the count after k insertions.
void judgeBowyerWatson(std::uint64_t seed) {
  for (const auto& [name, p] : bowyerWatsonInputs(seed))
    for (double factor : {10.0, 1.5}) {
      dt::BowyerWatsonResult bw;
      const std::string did = outcome([&] { bw = dt::bowyerWatson(p, factor); });
      std::printf("t1 %s, factor %g: %s, %zu duplicates skipped, cavities of %llu faces in all\n", name.c_str(), factor,
                  did.c_str(), std::size_t(bw.duplicates), (unsigned long long)bw.cavityFaces);
      if (did != "returns") continue;
      bool valid = bw.ids.size() * 2 == bw.xy.size();
      for (const dt::Tri& t : bw.tri)
        for (int k : t) valid = valid && k >= 0 && std::size_t(k) < bw.ids.size();
      if (!valid) {
        std::printf("t1 %s, factor %g: a triangle names no point\n", name.c_str(), factor);
        continue;
      }
      for (const auto& t : dt::canonicalTriangles(bw.ids, bw.tri))
        std::printf("t1 %s, factor %g: triangle %ld %ld %ld\n", name.c_str(), factor, t[0], t[1], t[2]);
    }
  const dt::XY p = dt::uniformPoints(9, seed);
  for (std::size_t k = 1; k <= 9; ++k) {
    dt::BowyerWatsonResult bw;
    const std::string did = outcome([&] { bw = dt::bowyerWatson(dt::XY(p.begin(), p.begin() + long(2 * k)), 1.5); });
    std::printf("t2 after %zu insertions: %s, %zu triangles\n", k, did.c_str(), bw.tri.size());
  }
}

// 2.2-3: hullEdgesNotCovered after Algorithm 1 (the library's) with close super-triangles, on
// random sets and on grids (collinear hull points split the hull's edges); the list is sorted
// here, each edge kept in the direction the student gives.
void judgeHullEdges(std::uint64_t seed) {
  std::vector<std::pair<std::string, dt::XY>> in;
  for (int k = 0; k < 60; ++k) in.push_back({"10 random points " + std::to_string(k), dt::uniformPoints(10, seed * 1000 + std::uint64_t(k))});
  for (int k = 2; k <= 5; ++k) {
    dt::XY g = dt::gridPoints(k, 3);
    dt::shufflePoints(g, seed + std::uint64_t(k));
    in.push_back({"grid " + std::to_string(k) + " x 3", g});
  }
  for (const auto& [name, p] : in)
    for (double factor : {1.5, 1e6}) {
      const dt::BowyerWatsonResult bw = dt::bowyerWatson(p, factor);
      std::vector<std::array<long, 2>> e;
      const std::string did = outcome([&] { e = dt::hullEdgesNotCovered(bw.xy, bw.ids, bw.tri); });
      std::sort(e.begin(), e.end());
      std::string list;
      for (const auto& x : e) list += " " + std::to_string(x[0]) + "->" + std::to_string(x[1]);
      std::printf("t1 %s, factor %g: %s,%s\n", name.c_str(), factor, did.c_str(), e.empty() ? " none" : list.c_str());
    }
}

}  // namespace
