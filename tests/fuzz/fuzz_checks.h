// The properties the fuzz harnesses check, as plain functions: the libFuzzer targets call them
// on generated inputs and abort on an error; tests/test_regressions.cpp replays the inputs the
// fuzzer once broke the code with. Each returns "" when every property holds, else what broke.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "bowyer_watson.h"
#include "check.h"
#include "fast_delaunay.h"
#include "flip.h"
#include "io.h"
#include "predicates.h"
#include "triangulate.h"

namespace dtfuzz {

using XY = std::vector<double>;

/// Largest point set the harnesses triangulate: bigger sets add little and slow the search.
constexpr std::size_t kMaxPoints = 100;

inline std::vector<char> firstOccurrences(const XY& p, std::size_t& distinct) {
  std::set<std::pair<double, double>> seen;
  std::vector<char> must(p.size() / 2, 0);
  for (std::size_t i = 0; i < p.size() / 2; ++i) must[i] = seen.emplace(p[2 * i], p[2 * i + 1]).second;
  distinct = seen.size();
  return must;
}

/// True iff the points have a triangulation: 3 distinct points not all collinear (exact).
inline bool hasTriangulation(const XY& p) {
  const std::size_t n = p.size() / 2;
  std::size_t i1 = 1;
  while (i1 < n && p[2 * i1] == p[0] && p[2 * i1 + 1] == p[1]) ++i1;
  for (std::size_t i = i1 + 1; i < n; ++i)
    if (dt::orient2dExact(p[0], p[1], p[2 * i1], p[2 * i1 + 1], p[2 * i], p[2 * i + 1]) != 0)
      return true;
  return false;
}

/// Triangles in input numbering, checked exactly: DT(S) using each distinct point once.
inline std::string checkInInput(const char* what, const XY& p,
                                const std::vector<std::array<int, 3>>& tri) {
  std::size_t distinct = 0;
  const std::vector<char> must = firstOccurrences(p, distinct);
  for (const auto& t : tri)
    for (int v : t)
      if (v < 0 || std::size_t(v) >= must.size() || !must[v])
        return std::string(what) + ": a triangle uses a bad index or a merged duplicate";
  const dt::CheckReport r = dt::checkDelaunay(p, tri, &must);
  if (!r.ok) return std::string(what) + ": " + r.error;
  return "";
}

inline std::vector<std::array<int, 3>> inputTriangles(const dt::Triangulation& T) {
  const dt::PlainMesh m = dt::extractMesh(T, true);
  std::vector<std::array<int, 3>> out;
  for (const auto& t : m.tri) out.push_back({int(m.ids[t[0]]), int(m.ids[t[1]]), int(m.ids[t[2]])});
  return out;
}

/// Every triangulation method on the points p (finite doubles), each result checked exactly;
/// on input without a triangulation, every method must refuse it with DegenerateInput.
inline std::string checkPointSet(const XY& p) {
  const bool possible = hasTriangulation(p);
  std::size_t distinct = 0;
  firstOccurrences(p, distinct);
  // 1. The hull method (2.2.2), both start rules.
  for (dt::StartRule rule : {dt::StartRule::LastCavity, dt::StartRule::FirstFace}) {
    dt::Triangulation T;
    std::vector<dt::Vertex*> S;
    for (std::size_t i = 0; i < p.size() / 2; ++i) S.push_back(T.addVertex(p[2 * i], p[2 * i + 1], long(i)));
    try {
      dt::delaunayTrglHull(T, S, rule);
    } catch (const dt::DegenerateInput&) {
      if (possible) return "hull: DegenerateInput on a set that has a triangulation";
      continue;
    }
    if (!possible) return "hull: triangulated a set without a triangulation";
    const dt::CheckReport r = dt::checkTriangulation(T);
    if (!r.ok) return "hull (links): " + r.error;
    const std::string e = checkInInput("hull", p, inputTriangles(T));
    if (!e.empty()) return e;
  }
  // 2. The fast kernel.
  try {
    const dt::FastResult r = dt::fastDelaunay(p);
    if (!possible) return "fast: triangulated a set without a triangulation";
    const std::string e = checkInInput("fast", p, r.tri);
    if (!e.empty()) return e;
  } catch (const dt::DegenerateInput&) {
    if (possible) return "fast: DegenerateInput on a set that has a triangulation";
  }
  if (!possible || p.empty()) return "";
  // 3. Super-triangles (Listing 2.7), then the recovery of DT(S) by flips (2.3.6). Near the
  // overflow threshold no enclosing square fits in doubles: initSuperTriangles says so.
  double x0 = p[0], x1 = p[0], y0 = p[1], y1 = p[1];
  for (std::size_t i = 0; i < p.size() / 2; ++i) {
    x0 = std::min(x0, p[2 * i]), x1 = std::max(x1, p[2 * i]);
    y0 = std::min(y0, p[2 * i + 1]), y1 = std::max(y1, p[2 * i + 1]);
  }
  dt::Triangulation T;
  bool fits = true;
  try {
    dt::initSuperTriangles(T, x0, y0, x1, y1);
  } catch (const dt::DegenerateInput&) {
    fits = false;
  }
  if (fits) {
    std::vector<dt::Vertex*> S;
    for (std::size_t i = 0; i < p.size() / 2; ++i) S.push_back(T.addVertex(p[2 * i], p[2 * i + 1], long(i)));
    dt::delaunayTrgl(T, S, dt::StartRule::LastCavity);
    const dt::CheckReport r = dt::checkTriangulation(T);
    if (!r.ok) return "super (DT(S0 u S)): " + r.error;
    if (r.nVertices != distinct + 4) return "super: a point is missing from DT(S0 u S)";
    dt::recoverDelaunay(T);
    const std::string e = checkInInput("super + flips", p, inputTriangles(T));
    if (!e.empty()) return e;
    // 4. Algorithm 1 on a plain triangle list: O(n^2), small sets only.
    if (p.size() / 2 <= 40) {
      const dt::BowyerWatsonResult b = dt::bowyerWatson(p);
      const dt::CheckReport c = dt::checkDelaunay(b.xy, b.tri);
      if (!c.ok) return "Algorithm 1: " + c.error;
    }
  }
  return "";
}

/// Points from fuzz bytes. The first byte picks a decoding; each aims at a kind of trouble:
///   0: raw doubles (16 bytes a point; non-finite values dropped): any exponent, subnormals;
///   1: a 16 x 16 integer grid (1 byte a point): duplicates, collinear and cocircular sets;
///   2: small integers times 2^E, E from the next 2 bytes (-1074..1023): a degenerate grid at
///      any scale, up to overflow of the sums and differences and underflow of the products;
///   3: int16 coordinates, each point scaled by 1e-300, 1 or 1e300 (3 scales in one set).
inline XY decodePoints(const std::uint8_t* data, std::size_t size) {
  XY p;
  if (size == 0) return p;
  const int mode = data[0] % 4;
  ++data, --size;
  if (mode == 0) {
    for (std::size_t i = 0; i + 16 <= size && p.size() / 2 < kMaxPoints; i += 16) {
      double x, y;
      std::memcpy(&x, data + i, 8);
      std::memcpy(&y, data + i + 8, 8);
      if (std::isfinite(x) && std::isfinite(y)) p.insert(p.end(), {x, y});
    }
  } else if (mode == 1) {
    for (std::size_t i = 0; i < size && p.size() / 2 < kMaxPoints; ++i)
      p.insert(p.end(), {double(data[i] >> 4), double(data[i] & 15)});
  } else if (mode == 2) {
    if (size < 2) return p;
    const int e = int((data[0] | (data[1] << 8)) % 2098) - 1074;
    for (std::size_t i = 2; i + 2 <= size && p.size() / 2 < kMaxPoints; i += 2)
      p.insert(p.end(), {std::ldexp(double(std::int8_t(data[i])), e),
                         std::ldexp(double(std::int8_t(data[i + 1])), e)});
  } else {
    const double scale[4] = {1e-300, 1, 1e300, 1};
    for (std::size_t i = 0; i + 5 <= size && p.size() / 2 < kMaxPoints; i += 5) {
      const double s = scale[data[i + 4] % 4];
      p.insert(p.end(), {s * double(std::int16_t(data[i] | (data[i + 1] << 8))),
                         s * double(std::int16_t(data[i + 2] | (data[i + 3] << 8)))});
    }
  }
  // ldexp overflows for big E: such points are not input (the parsers refuse infinities).
  XY finite;
  for (std::size_t i = 0; i + 1 < p.size(); i += 2)
    if (std::isfinite(p[i]) && std::isfinite(p[i + 1])) finite.insert(finite.end(), {p[i], p[i + 1]});
  return finite;
}

/// The .node and xy parsers on arbitrary text: either a clean InputError naming the file, or a
/// point set that is consistent (finite coordinates, numbers that follow on, increasing lines);
/// a small parsed set is then triangulated by every method.
inline std::string checkParse(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  for (int kind = 0; kind < 2; ++kind) {
    const std::string path = kind == 0 ? "fuzz.node" : "fuzz.xy";
    dt::PointSet ps;
    try {
      ps = kind == 0 ? dt::parseNode(text, path) : dt::parseXY(text, path);
    } catch (const dt::InputError& e) {
      const std::string m = e.what();
      if (m.compare(0, path.size() + 1, path + ":") != 0)
        return path + ": message does not start with the file name: " + m;
      continue;
    }
    if (ps.xy.size() % 2 != 0 || (ps.size() > 0 && ps.lineRuns.empty()))
      return path + ": inconsistent sizes";
    if (ps.firstIndex != 0 && ps.firstIndex != 1) return path + ": bad numbering base";
    for (std::size_t i = 0; i < ps.size(); ++i) {
      if (!std::isfinite(ps.xy[2 * i]) || !std::isfinite(ps.xy[2 * i + 1]))
        return path + ": a parsed coordinate is not finite";
      if (ps.number(i) != ps.firstIndex + long(i)) return path + ": point numbers do not follow on";
      if (i > 0 && ps.line(i) <= ps.line(i - 1)) return path + ": line numbers do not increase";
    }
    if (ps.size() <= 40) {
      const std::string e = checkPointSet(ps.xy);
      if (!e.empty()) return path + ": " + e;
    }
  }
  return "";
}

}  // namespace dtfuzz
