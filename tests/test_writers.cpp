/// \file test_writers.cpp The mesh writers read back: Gmsh .msh and SVG are parsed by readers of their own here and checked against the input's geometry (coordinates, numbering, orientation), so that a mirrored or renumbered mesh fails, as .ele is checked against the triangulation.
#include <doctest/doctest.h>

#include <array>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "delaunay.h"
#include "predicates.h"
#include "support.h"
#include "writers.h"

namespace {

using Tris = std::vector<std::array<int, 3>>;

// A reader of the Gmsh ASCII 2.2 subset the writer promises (nodes, 3-node triangles), strict:
// any other section, element type or count mismatch fails the test.
struct Msh {
  std::vector<double> xy;
  Tris tri;
};
Msh readMsh(const std::string& text) {
  std::istringstream in(text);
  std::string word;
  Msh m;
  in >> word;
  REQUIRE(word == "$MeshFormat");
  double version = 0;
  int ascii = -1, size = 0;
  in >> version >> ascii >> size >> word;
  REQUIRE(version == 2.2);
  REQUIRE(ascii == 0);
  REQUIRE(word == "$EndMeshFormat");
  in >> word;
  REQUIRE(word == "$Nodes");
  long n = 0;
  in >> n;
  for (long i = 1; i <= n; ++i) {
    long id = 0;
    double x = 0, y = 0, z = 1;
    REQUIRE(bool(in >> id >> x >> y >> z));
    REQUIRE(id == i);  // numbered 1..n in order: node i is point i - 1
    CHECK(z == 0);
    m.xy.insert(m.xy.end(), {x, y});
  }
  in >> word;
  REQUIRE(word == "$EndNodes");
  in >> word;
  REQUIRE(word == "$Elements");
  long ne = 0;
  in >> ne;
  for (long e = 1; e <= ne; ++e) {
    long id = 0, type = 0, tags = 0;
    REQUIRE(bool(in >> id >> type >> tags));
    REQUIRE(id == e);
    REQUIRE(type == 2);  // the 3-node triangle
    for (long t = 0; t < tags; ++t) in >> word;
    std::array<long, 3> v{};
    REQUIRE(bool(in >> v[0] >> v[1] >> v[2]));
    for (long x : v) REQUIRE((x >= 1 && x <= n));
    m.tri.push_back({int(v[0] - 1), int(v[1] - 1), int(v[2] - 1)});
  }
  in >> word;
  REQUIRE(word == "$EndElements");
  CHECK(!(in >> word));  // nothing after
  return m;
}

// The polygons of an SVG written by writeSvg: each "points" attribute as three pixel points.
std::vector<std::array<double, 6>> readSvgPolygons(const std::string& text, int& width, int& height) {
  width = height = 0;
  const std::size_t s = text.find("<svg ");
  REQUIRE(s != std::string::npos);
  std::sscanf(text.c_str() + text.find("width=\"", s) + 7, "%d", &width);
  std::sscanf(text.c_str() + text.find("height=\"", s) + 8, "%d", &height);
  std::vector<std::array<double, 6>> out;
  for (std::size_t at = text.find("<polygon points=\""); at != std::string::npos;
       at = text.find("<polygon points=\"", at + 1)) {
    std::array<double, 6> p{};
    REQUIRE(std::sscanf(text.c_str() + at + 17, "%lf,%lf %lf,%lf %lf,%lf", &p[0], &p[1], &p[2], &p[3],
                        &p[4], &p[5]) == 6);
    out.push_back(p);
  }
  CHECK(text.find("</svg>") != std::string::npos);
  return out;
}

// A triangulation to write: not symmetric (a mirror image differs), with a hull and inside points.
struct Input {
  std::vector<double> xy;
  Tris tri;
};
Input input(std::size_t n, unsigned seed, double scale, double shiftX, double shiftY) {
  dt::XY p = dt::uniformPoints(n, seed);
  for (std::size_t i = 0; i < p.size(); i += 2) {
    p[i] = shiftX + scale * p[i];
    p[i + 1] = shiftY + 0.5 * scale * p[i + 1] * p[i + 1];  // denser near the bottom edge
  }
  const dt::TriangulateResult T = dt::triangulate(p);
  Input in{T.xy, {}};
  for (const auto& t : T.tri) in.tri.push_back({int(t[0]), int(t[1]), int(t[2])});
  return in;
}

double orient(const std::vector<double>& xy, const std::array<int, 3>& t) {
  auto X = [&](int i) { return xy[2 * std::size_t(i)]; };
  auto Y = [&](int i) { return xy[2 * std::size_t(i) + 1]; };
  return dt::orient2d(X(t[0]), Y(t[0]), X(t[1]), Y(t[1]), X(t[2]), Y(t[2]));
}

}  // namespace

TEST_CASE("writers the .msh with an index map numbers the nodes as the input without the merged points") {
  // The kernel's numbering (dt::triangulate: insertion order) mapped back through r.input, as
  // writeEle does; the merged duplicates (points 3 and 7 of the input) are no nodes.
  std::vector<double> p = dttest::uniformPoints(40, 9);
  p.insert(p.begin() + 6, {p[0], p[1]});
  p.insert(p.begin() + 14, {p[4], p[5]});
  const dt::TriangulateResult r = dt::triangulate(p);
  REQUIRE(r.duplicates.size() == 2);
  dt::Writer w;
  dt::writeMsh(w, r.xy, r.tri, r.input, r.used);
  const Msh m = readMsh(w.str());
  std::vector<double> kept;  // the input points without the merged ones, in input order
  for (std::size_t i = 0; i < p.size() / 2; ++i)
    if (i != std::size_t(r.duplicates[0].first) && i != std::size_t(r.duplicates[1].first))
      kept.insert(kept.end(), {p[2 * i], p[2 * i + 1]});
  CHECK(m.xy == kept);
  REQUIRE(m.tri.size() == r.tri.size());
  for (std::size_t t = 0; t < r.tri.size(); ++t)
    for (int k = 0; k < 3; ++k) {
      const std::size_t a = std::size_t(m.tri[t][std::size_t(k)]), b = std::size_t(r.tri[t][std::size_t(k)]);
      CHECK(m.xy[2 * a] == r.xy[2 * b]);
      CHECK(m.xy[2 * a + 1] == r.xy[2 * b + 1]);
    }
}

TEST_CASE("writers the .msh read back has the input's points in order and its triangles counter-clockwise") {
  for (const Input& in : {input(300, 5, 1.0, 0, 0), input(200, 6, 1e-7, 1e6, -3e5), input(50, 7, 3e200, -1e201, 0)}) {
    const Msh m = readMsh(dt::mshText(in.xy, in.tri));
    REQUIRE(m.xy.size() == in.xy.size());
    for (std::size_t i = 0; i < in.xy.size(); ++i) CHECK(m.xy[i] == in.xy[i]);  // 17 digits: exact
    REQUIRE(m.tri.size() == in.tri.size());
    for (std::size_t t = 0; t < in.tri.size(); ++t) {
      CHECK(m.tri[t] == in.tri[t]);
      CHECK(orient(m.xy, m.tri[t]) > 0);  // as Gmsh expects: a mirrored mesh would be clockwise
    }
  }
}

TEST_CASE("writers the SVG read back is the input scaled alike on both axes with y pointing down") {
  const int size = 640;
  for (const Input& in : {input(300, 8, 1.0, 0, 0), input(100, 9, 1e-9, 7, 7), input(60, 10, 1e300, -5e299, 1e299)}) {
    int width = 0, height = 0;
    const std::vector<std::array<double, 6>> poly = readSvgPolygons(dt::svgText(in.xy, in.tri, size), width, height);
    CHECK(width == size);
    CHECK(height == size);
    REQUIRE(poly.size() == in.tri.size());
    // The drawing's map: px = 10 + s (x - xmin), py = size - 10 - s (y - ymin), one s for both
    // axes, the larger span filling size - 20 pixels. Computed here from the input alone.
    double x0 = INFINITY, x1 = -INFINITY, y0 = INFINITY, y1 = -INFINITY;
    for (std::size_t i = 0; i < in.xy.size(); i += 2) {
      x0 = std::min(x0, in.xy[i]), x1 = std::max(x1, in.xy[i]);
      y0 = std::min(y0, in.xy[i + 1]), y1 = std::max(y1, in.xy[i + 1]);
    }
    const double span = std::max(x1 / 2 - x0 / 2, y1 / 2 - y0 / 2);  // halved: no overflow
    const double s = (size - 20) / span / 2;
    double worst = 0;
    for (std::size_t t = 0; t < poly.size(); ++t) {
      for (int k = 0; k < 3; ++k) {
        const int v = in.tri[t][std::size_t(k)];
        const double ex = 10 + s * (in.xy[2 * std::size_t(v)] / 2 - x0 / 2) * 2;
        const double ey = size - 10 - s * (in.xy[2 * std::size_t(v) + 1] / 2 - y0 / 2) * 2;
        worst = std::max({worst, std::fabs(poly[t][std::size_t(2 * k)] - ex), std::fabs(poly[t][std::size_t(2 * k + 1)] - ey)});
      }
      // y down: a counter-clockwise triangle is clockwise in pixels (a mirror would not be).
      const double a = (poly[t][2] - poly[t][0]) * (poly[t][5] - poly[t][1]) -
                       (poly[t][3] - poly[t][1]) * (poly[t][4] - poly[t][0]);
      CHECK(a <= 0);
    }
    MESSAGE("largest distance of a drawn vertex from the input's image: " << worst << " px");
    CHECK(worst <= 0.006);  // written with 2 decimals
  }
}
