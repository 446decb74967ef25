// The judges of section 2.3's exercises, part of exercises/judge.cpp (one translation unit, so
// that grade compiles and links one object): see the comment at its top. Each line "tK ..."
// states one fact of test K on inputs drawn from the seed; the facts the contract leaves open
// (which low-degree vertex, where a closed star starts, the last bits of a double) are printed
// in a form every right answer shares.
#pragma once

#include <array>
#include <set>

#include "robustness.h"
#include "exercises.h"
#include "flip.h"
#include "predicates_demo.h"

namespace {

// A double as the checker compares it: 12 significant digits, so that a formula written in
// another order (a few units of the last place apart) prints the same.
std::string roughly(double x) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.12g", x);
  return buf;
}

// 2.3.1-3: segmentsIntersect on small integer coordinates (collinear, touching and zero-length
// segments are frequent), on segments along the line y = x with endpoints one ulp off it, and
// with the endpoints and the two segments swapped (the answer may not depend on the order).
void judgeSegments(std::uint64_t seed) {
  std::mt19937_64 r(seed);
  auto small = [&r] { return double(long(r() % 5)); };
  const double e = 0x1p-53;
  for (int k = 0; k < 400; ++k) {
    double s[8];
    if (k % 4 == 3) {  // on or one ulp beside the line y = x through (12, 12), (24, 24)
      for (int i = 0; i < 4; ++i) {
        const double t = 0.5 + double(r() % 4) * e * 2;
        s[2 * i] = t + (r() % 3 == 0 ? e * 2 : 0);
        s[2 * i + 1] = t;
      }
      if (k % 8 == 3) s[4] = 12, s[5] = 12, s[6] = 24, s[7] = 24;
    } else {
      for (double& x : s) x = small();
    }
    std::string bits;
    const int orders[4][8] = {{0, 1, 2, 3, 4, 5, 6, 7}, {2, 3, 0, 1, 4, 5, 6, 7}, {4, 5, 6, 7, 0, 1, 2, 3}, {6, 7, 4, 5, 2, 3, 0, 1}};
    for (const auto& o : orders) {
      bool yes = false;
      const std::string did = outcome([&] {
        yes = dt::segmentsIntersect(s[o[0]], s[o[1]], s[o[2]], s[o[3]], s[o[4]], s[o[5]], s[o[6]], s[o[7]]);
      });
      bits += did != "returns" ? " throws" : yes ? " meet" : " apart";
    }
    std::printf("t1 segments [(%a, %a), (%a, %a)] and [(%a, %a), (%a, %a)] in four orders:%s\n", s[0], s[1], s[2],
                s[3], s[4], s[5], s[6], s[7], bits.c_str());
  }
}

// 2.3.2-1: gridCounts on grids thin and wide; below 2 x 2 the contract asks for an exception.
void judgeGridCounts(std::uint64_t seed) {
  std::mt19937_64 r(seed);
  std::vector<std::array<long, 2>> sizes = {{2, 2}, {2, 9}, {9, 2}, {3, 3}, {5, 3}, {1, 5}, {5, 1}, {0, 0}};
  for (int k = 0; k < 40; ++k) sizes.push_back({2 + long(r() % 60), 2 + long(r() % 60)});
  for (const auto& s : sizes) {
    std::array<long, 4> c{};
    const std::string did = outcome([&] { c = dt::gridCounts(s[0], s[1]); });
    if (did != "returns")
      std::printf("t1 grid %ld x %ld: %s\n", s[0], s[1], did.c_str());
    else
      std::printf("t1 grid %ld x %ld: n %ld, n_h %ld, n_f %ld, n_e %ld\n", s[0], s[1], c[0], c[1], c[2], c[3]);
  }
}

// The triangles of DT(p) with ghost faces, counted by the library's meshCounts.
dt::MeshCounts countsOf(const dt::XY& p) {
  dt::Triangulation T;
  std::vector<dt::Vertex*> S;
  for (std::size_t i = 0; i < p.size() / 2; ++i) S.push_back(T.addVertex(p[2 * i], p[2 * i + 1], long(i)));
  dt::delaunayTrglHull(T, S, dt::StartRule::LastCavity);
  const dt::PlainMesh m = dt::extractMesh(T, true);
  return dt::meshCounts(m.xy.size() / 2, m.tri);
}

// 2.3.2-2: lowDegreeVertex may return any used vertex of at most 5 edges: the line says whether
// it did, checked on the counts (never the index). Made-up counts where no vertex qualifies, or
// only an unused one has few edges, must give -1.
void judgeLowDegree(std::uint64_t seed) {
  std::vector<std::pair<std::string, dt::XY>> in = {{"uniform", dt::uniformPoints(300, seed)},
                                                     {"circle", dt::circlePoints(40)}};
  dt::XY g = dt::gridPoints(7, 5);
  dt::shufflePoints(g, seed);
  in.push_back({"grid", g});
  dt::XY dup = dt::uniformPoints(60, seed + 1);
  for (std::size_t i = 0; i < 40; ++i) dup.push_back(dup[i]);
  in.push_back({"duplicates", dup});
  std::vector<std::pair<std::string, dt::MeshCounts>> cases;
  for (const auto& p : in) cases.push_back({p.first, countsOf(p.second)});
  dt::MeshCounts unused;  // only an unused vertex (a skipped duplicate) has few edges
  unused.vf = {0, 3, 2};
  unused.ve = {2, 6, 7};
  cases.push_back({"an unused vertex of 2 edges", unused});
  std::mt19937_64 r(seed);
  for (int k = 0; k < 12; ++k) {
    dt::MeshCounts c;
    const std::size_t n = 1 + r() % 8;
    for (std::size_t v = 0; v < n; ++v) {
      const bool used = r() % 4 != 0;
      c.vf.push_back(used ? 1 + long(r() % 8) : 0);
      c.ve.push_back(k % 2 ? 6 + long(r() % 3) : long(r() % 9));
      if (!used) c.ve.back() = long(r() % 3);  // an unused vertex with few edges: never the answer
    }
    cases.push_back({"made-up counts " + std::to_string(k), c});
  }
  for (const auto& c : cases) {
    int v = -2;
    const std::string did = outcome([&] { v = dt::lowDegreeVertex(c.second); });
    bool exists = false;
    for (std::size_t i = 0; i < c.second.ve.size(); ++i) exists = exists || (c.second.vf[i] > 0 && c.second.ve[i] <= 5);
    std::string said = did;
    if (did == "returns") {
      const std::size_t u = std::size_t(v);
      if (v == -1) said = "-1 (none)";
      else if (v >= 0 && u < c.second.ve.size() && c.second.vf[u] > 0 && c.second.ve[u] <= 5) said = "a used vertex of at most 5 edges";
      else said = "a vertex that is not a used vertex of at most 5 edges";
    }
    std::printf("t1 %s (%s): %s\n", c.first.c_str(), exists ? "one exists" : "none exists", said.c_str());
  }
}

// 2.3.3-1: halfEdgePointers with the notes' counts and the exact ones.
void judgeHalfEdge(std::uint64_t seed) {
  std::mt19937_64 r(seed);
  std::vector<std::array<double, 2>> at = {{1e6, 0}, {1000, 30}, {3, 3}, {12, 9}};
  for (int k = 0; k < 20; ++k) {
    const double n = double(4 + r() % 100000);
    at.push_back({n, double(3 + r() % std::uint64_t(n - 3))});
  }
  for (const auto& a : at)
    for (bool exact : {false, true}) {
      double v = 0;
      const std::string did = outcome([&] { v = dt::halfEdgePointers(a[0], a[1], exact); });
      std::printf("t1 n %.0f, n_h %.0f, %s: %s\n", a[0], a[1], exact ? "exact" : "the notes' counts",
                  did == "returns" ? roughly(v).c_str() : did.c_str());
    }
}

// 2.3.3-2: vertexStar from a random face of each vertex, with ghost faces and with
// super-triangles, on a grid (cocircular) and random points. Faces are named by their index
// in the mesh; a closed star's start is free, so it is printed from its smallest index.
void judgeVertexStar(std::uint64_t seed) {
  std::mt19937_64 r(seed);
  for (int method = 0; method < 2; ++method) {
    dt::Triangulation T;
    dt::XY p = dt::gridPoints(6, 5);
    const dt::XY u = dt::uniformPoints(40, seed, 0, 5);
    p.insert(p.end(), u.begin(), u.end());
    std::vector<dt::Vertex*> S;
    for (std::size_t i = 0; i < p.size() / 2; ++i) S.push_back(T.addVertex(p[2 * i], p[2 * i + 1], long(i)));
    if (method == 0) {
      dt::delaunayTrglHull(T, S, dt::StartRule::LastCavity);
    } else {
      dt::initSuperTriangles(T, 0, 0, 5, 5);
      dt::delaunayTrgl(T, S, dt::StartRule::LastCavity);
    }
    std::map<const dt::Face*, std::size_t> index;
    std::map<const dt::Vertex*, std::vector<dt::Face*>> of;
    for (dt::Face& f : T.faces()) {
      index[&f] = index.size();
      if (!f.deleted && !f.isGhost())
        for (const dt::Vertex* v : f.V) of[v].push_back(&f);
    }
    const char* how = method == 0 ? "with ghost faces" : "on super-triangles";
    for (const auto& [v, faces] : of) {
      // Closed: every edge of v has a finite face on both sides (the library's links, trusted).
      bool closed = true;
      for (const dt::Face* f : faces)
        for (int k = 0; k < 3; ++k)
          if ((f->V[k] == v || f->V[(k + 1) % 3] == v) && (f->F[k] == nullptr || f->F[k]->isGhost())) closed = false;
      dt::Face* start = faces[std::size_t(r() % faces.size())];
      std::vector<dt::Face*> star;
      const std::string did = outcome([&] { star = dt::vertexStar(start, v); });
      std::vector<std::size_t> names;
      for (const dt::Face* f : star) names.push_back(index.count(f) ? index[f] : std::size_t(-1));
      if (closed && !names.empty()) std::rotate(names.begin(), std::min_element(names.begin(), names.end()), names.end());
      std::string list;
      for (std::size_t k : names) list += " " + (k == std::size_t(-1) ? std::string("?") : std::to_string(k));
      std::printf("t1 %s, vertex %ld (%s star): %s,%s\n", how, v->id, closed ? "closed" : "open", did.c_str(), list.c_str());
    }
    const dt::Vertex stranger(100, 100);
    std::printf("t1 %s, a vertex not of the face: %s\n", how,
                outcome([&] { dt::vertexStar(of.begin()->second[0], &stranger); }).c_str());
  }
}

// 2.3.4-2: backwardCavityMean on meshes built on super-triangles: uniform points, a grid
// (cocircular), points given twice (a skipped duplicate is no vertex), a few points.
void judgeBackwardMean(std::uint64_t seed) {
  std::vector<std::pair<std::string, dt::XY>> in;
  for (std::size_t n : {3, 10, 150, 1000}) in.push_back({"uniform " + std::to_string(n), dt::uniformPoints(n, seed + n)});
  dt::XY g = dt::gridPoints(9, 7, 1.0 / 8);
  dt::shufflePoints(g, seed);
  in.push_back({"grid 9 x 7", g});
  dt::XY dup = dt::uniformPoints(100, seed);
  for (std::size_t i = 0; i < 60; ++i) dup.push_back(dup[i]);
  in.push_back({"100 points, 30 given twice", dup});
  for (const auto& [name, p] : in) {
    dt::Triangulation T;
    dt::initSuperTriangles(T, 0, 0, 1, 1);
    dt::delaunayTrgl(T, dt::addVertices(T, p), dt::StartRule::LastCavity);
    std::array<double, 2> m{};
    const std::string did = outcome([&] { m = dt::backwardCavityMean(T); });
    if (did != "returns") std::printf("t1 %s: %s\n", name.c_str(), did.c_str());
    else std::printf("t1 %s: mean %s, D %s\n", name.c_str(), roughly(m[0]).c_str(), roughly(m[1]).c_str());
  }
}

// 2.3.1-1: orient2dNaiveCanonical on Figure 2.7's grid (the counts of the test) and on random
// triples: the six orders agree bit for bit, and far from degenerate the sign is the exact one.
void judgeOrientCanonical(std::uint64_t seed) {
  dt::SignMap abc, cba, bca;
  const std::string maps = outcome([&] {
    abc = dt::orientMap(dt::orient2dNaiveCanonical, dt::OrientOrder::ABC);
    cba = dt::orientMap(dt::orient2dNaiveCanonical, dt::OrientOrder::CBA);
    bca = dt::orientMap(dt::orient2dNaiveCanonical, dt::OrientOrder::BCA);
  });
  const dt::SignMap ex = dt::orientMap(dt::orient2d, dt::OrientOrder::ABC);
  if (maps != "returns") std::printf("t1 Figure 2.7: %s\n", maps.c_str());
  else std::printf("t1 Figure 2.7: O(c,b,a) = -O(a,b,c) on %ld cells, O(b,c,a) = O(a,b,c) on %ld cells, %ld wrong cells\n",
                   dt::agreeingCells(cba, abc, -1), dt::agreeingCells(bca, abc, 1), dt::compareMaps(abc, ex).wrong);
  std::mt19937_64 r(seed);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int k = 0; k < 300; ++k) {
    double q[6];
    for (double& x : q) x = u(r);
    if (k % 2) q[4] = q[0] + 0.375 * (q[2] - q[0]), q[5] = q[1] + 0.375 * (q[3] - q[1]);  // nearly collinear
    if (k % 10 == 9) q[2] = q[0], q[3] = q[1];  // two points equal
    const int perm[6][3] = {{0, 1, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}, {1, 0, 2}, {0, 2, 1}};
    int s[6] = {};
    std::string did = "returns";
    for (int i = 0; i < 6; ++i) {
      const int* o = perm[i];
      const std::string d = outcome([&] {
        s[i] = dt::orient2dNaiveCanonical(q[2 * o[0]], q[2 * o[0] + 1], q[2 * o[1]], q[2 * o[1] + 1], q[2 * o[2]], q[2 * o[2] + 1]);
      });
      if (d != "returns") did = d;
    }
    bool consistent = true;
    for (int i = 0; i < 6; ++i) consistent = consistent && s[i] == (i < 3 ? s[0] : -s[0]);
    const int exact = dt::orient2d(q[0], q[1], q[2], q[3], q[4], q[5]);
    // Away from degenerate (the naive value far above its error), the sign must be exact.
    const double det = (q[0] - q[4]) * (q[3] - q[5]) - (q[1] - q[5]) * (q[2] - q[4]);
    const bool clear = std::fabs(det) > 1e-6;
    std::printf("t1 triple %d: %s, the six orders %s%s\n", k, did.c_str(), consistent ? "agree" : "disagree",
                clear ? (s[0] == exact ? ", the exact sign" : ", not the exact sign") : "");
  }
}

// The sign that `bits` bits of MPFR give, or why it was not asked (a precision MPFR refuses
// would end the judge, not the student's answer).
template <class F>
std::string signWith(int bits, int exact, F&& mpfr) {
  if (bits < 2 || bits > (1 << 16)) return "a precision out of range";
  return mpfr(bits) == exact ? "the exact sign" : "a wrong sign";
}

// 2.3.1-2: exactBitsOrient2d / exactBitsIncircle: any number of bits that makes MPFR exact is
// right, so the lines say whether the sign is exact (against the library's exact predicates),
// on random inputs spread over 2^-1000..2^1000, nearly collinear ones and the pinned
// counterexamples (test 2: more than 200 bits there); the test's one-binade counts are fixed.
void judgeExactBits(std::uint64_t seed) {
  std::mt19937_64 r(seed);
  std::uniform_real_distribution<double> m(1, 2);
  std::uniform_int_distribution<int> e(-1000, 1000);
  for (int k = 0; k < 200; ++k) {
    double v[8];
    for (double& x : v) x = std::ldexp(r() % 2 ? m(r) : -m(r), e(r));
    if (k % 2) v[4] = v[0] + 0.5 * (v[2] - v[0]), v[5] = v[1] + 0.5 * (v[3] - v[1]);
    int bo = 0, bi = 0;
    const std::string d1 = outcome([&] { bo = dt::exactBitsOrient2d(v[0], v[1], v[2], v[3], v[4], v[5]); });
    const std::string d2 = outcome([&] { bi = dt::exactBitsIncircle(v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7]); });
    const int eo = dt::orient2d(v[0], v[1], v[2], v[3], v[4], v[5]);
    const int ei = dt::incircle(v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7]);
    std::printf("t1 input %d: orient2d %s, incircle %s\n", k,
                d1 != "returns" ? d1.c_str() : signWith(bo, eo, [&](int b) { return dt::orient2dMPFR(b, v[0], v[1], v[2], v[3], v[4], v[5]); }).c_str(),
                d2 != "returns" ? d2.c_str() : signWith(bi, ei, [&](int b) { return dt::incircleMPFR(b, v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7]); }).c_str());
  }
  int b = 0;
  std::printf("t1 one binade: orient2d %s bits\n", outcome([&] { b = dt::exactBitsOrient2d(1.5, 1.25, 1.75, 1.125, 1.0, 1.875); }) == "returns" ? std::to_string(b).c_str() : "no");
  std::printf("t1 one binade: incircle %s bits\n", outcome([&] { b = dt::exactBitsIncircle(1.5, 1.25, 1.75, 1.125, 1.0, 1.875, 1.5, 1.5); }) == "returns" ? std::to_string(b).c_str() : "no");
  // The test's pinned counterexamples of 200-bit MPFR.
  const std::vector<std::array<double, 6>> o = {{1, 1, 2, 2, 0x1p-600, 0}, {1, 1, 2, 2, -0x1.a87dep-196, -0x1.93e94p-196}};
  for (const auto& q : o) {
    const std::string did = outcome([&] { b = dt::exactBitsOrient2d(q[0], q[1], q[2], q[3], q[4], q[5]); });
    std::printf("t2 orient2d (%a, %a): %s, %s, %s\n", q[4], q[5], did.c_str(), b > 200 ? "more than 200 bits" : "200 bits or fewer",
                signWith(b, dt::orient2d(q[0], q[1], q[2], q[3], q[4], q[5]), [&](int n) { return dt::orient2dMPFR(n, q[0], q[1], q[2], q[3], q[4], q[5]); }).c_str());
  }
  const std::vector<std::array<double, 8>> c = {
      {-0x1.d5c4532c089cp+46, -0x1.c9412a59424fp+50, -0x1.c7be1bb5b0b64p+50, -0x1.7ad5b19c0308p+47,
       -0x1.117aa79ef20f8p+49, 0x1.b5511f085e72p+50, 0x1.2f1a7b32911fcp+50, 0x1.579dbc83a81cp+50},
      {3, 4, -5, 0, 0x1.6a2p-196, 5, 4, -3}};
  for (const auto& q : c) {
    const std::string did = outcome([&] { b = dt::exactBitsIncircle(q[0], q[1], q[2], q[3], q[4], q[5], q[6], q[7]); });
    std::printf("t2 incircle (%a, %a): %s, %s, %s\n", q[0], q[4], did.c_str(), b > 200 ? "more than 200 bits" : "200 bits or fewer",
                signWith(b, dt::incircle(q[0], q[1], q[2], q[3], q[4], q[5], q[6], q[7]),
                         [&](int n) { return dt::incircleMPFR(n, q[0], q[1], q[2], q[3], q[4], q[5], q[6], q[7]); }).c_str());
  }
}

// 2.3.6-1: the example is the student's; the judge checks with the library what the test
// claims of it (no input is drawn: the seed changes nothing).
void judgeStuckRecovery(std::uint64_t) {
  dt::StuckRecovery ex;
  const std::string did = outcome([&] { ex = dt::stuckRecoveryExample(); });
  std::printf("t1 the example: %s, %zu coordinates\n", did.c_str(), ex.xy.size());
  if (did != "returns" || ex.xy.size() != 6) return;
  const double* p = ex.xy.data();
  // The library is run on the example: only finite numbers go in.
  bool finite = std::isfinite(ex.factor) && ex.factor > 0;
  for (double x : ex.xy) finite = finite && std::isfinite(x);
  std::printf("t1 the coordinates and the factor are finite and the factor positive: %s\n", finite ? "yes" : "no");
  if (!finite) return;
  std::printf("t1 the three points turn: %s\n", dt::orient2d(p[0], p[1], p[2], p[3], p[4], p[5]) != 0 ? "yes" : "no (collinear)");
  for (dt::RecoveryRule rule : {dt::RecoveryRule::NotesOnly, dt::RecoveryRule::Full}) {
    const char* name = rule == dt::RecoveryRule::Full ? "the full rule" : "the notes' rule";
    dt::Triangulation T;
    dt::FlipStats st;
    const std::string built = outcome([&] {
      double x0 = p[0], x1 = p[0], y0 = p[1], y1 = p[1];
      for (int i = 0; i < 6; i += 2) x0 = std::min(x0, p[i]), x1 = std::max(x1, p[i]), y0 = std::min(y0, p[i + 1]), y1 = std::max(y1, p[i + 1]);
      dt::initSuperTriangles(T, x0, y0, x1, y1, ex.factor);
      dt::delaunayTrgl(T, dt::addVertices(T, ex.xy), dt::StartRule::LastCavity);
      st = dt::recoverDelaunay(T, rule);
    });
    if (built != "returns") {
      std::printf("t1 %s: the library %s on the example\n", name, built.c_str());
      continue;
    }
    const dt::PlainMesh m = dt::extractMesh(T, true), all = dt::extractMesh(T, false);
    std::printf("t1 %s: %s, %zu triangles of S left\n", name, st.flips > 0 ? "flips" : "no flip", m.tri.size());
    // After the full rule the super faces are gone: one Delaunay triangle is all that is left.
    if (rule == dt::RecoveryRule::Full)
      std::printf("t1 %s: %zu finite faces, %s\n", name, all.tri.size(),
                  dt::checkTriangulation(T).ok && dt::checkDelaunay(all.xy, all.tri).ok ? "valid" : "not valid");
  }
}

}  // namespace
