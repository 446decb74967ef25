// The native side of the browser test (web/test.js): hard inputs triangulated by the native
// library, written as a JavaScript file (window.DT_CASES) that the test page loads beside the
// WebAssembly build of the same library, which must give the same triangles, number for number.
//
//   web_native_cases OUT.js
#include <algorithm>
#include <array>
#include <chrono>
#include <cstdlib>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "check.h"
#include "fast_delaunay.h"
#include "generators.h"
#include "mesh.h"
#include "triangulate.h"

namespace {

struct Case {
  std::string name;
  std::vector<double> xy;
};

std::vector<Case> hardCases() {
  std::vector<Case> cs;
  // Exactly cocircular everywhere: a grid and a rotated grid, shuffled.
  dt::XY grid = dt::gridPoints(16, 16);
  dt::shufflePoints(grid, 7);
  cs.push_back({"cocircular grid 16x16", grid});
  cs.push_back({"rotated cocircular grid 9x9", dt::rotatedGridPoints(9, 9)});
  // Coordinates near 1e+300 and 1e-300, and exponents over the whole double range.
  dt::XY big = dt::uniformPoints(300, 11), tiny = big;
  for (double& v : big) v = 1e300 * (1 + v);
  for (double& v : tiny) v = 1e-300 * (1 + v);
  cs.push_back({"uniform near 1e+300", big});
  cs.push_back({"uniform near 1e-300", tiny});
  cs.push_back({"exponents -1070..1019", dt::exponentSpreadPoints(300, 12)});
  // Nearly collinear: points of the line y = x/3 rounded to doubles, a few ulps apart, and
  // three points off the line so that a triangulation exists.
  dt::XY line;
  for (int i = 0; i < 200; ++i) {
    const double x = 0.5 + i * 0x1p-40;
    line.push_back(x);
    line.push_back(x / 3);
  }
  for (double v : {0.0, 1.0, 1.0, 0.0, 0.5, 0.5}) line.push_back(v);
  dt::shufflePoints(line, 13);
  cs.push_back({"nearly collinear", line});
  // Duplicates and a large uniform set.
  dt::XY dup = dt::uniformPoints(100, 14);
  for (int i = 0; i < 40; ++i) dup.insert(dup.end(), {dup[2 * i], dup[2 * i + 1]});
  cs.push_back({"uniform with duplicates", dup});
  cs.push_back({"uniform 5000", dt::uniformPoints(5000, 15)});
  return cs;
}

void writeArray(std::FILE* f, const std::vector<double>& v) {
  std::fputc('[', f);
  for (std::size_t i = 0; i < v.size(); ++i) std::fprintf(f, "%s%.17g", i ? "," : "", v[i]);
  std::fputc(']', f);
}
template <class T>
void writeInts(std::FILE* f, const std::vector<T>& v) {
  std::fputc('[', f);
  for (std::size_t i = 0; i < v.size(); ++i) std::fprintf(f, "%s%ld", i ? "," : "", long(v[i]));
  std::fputc(']', f);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc == 3 && std::string(argv[1]) == "--bench") {
    // The native side of the speed comparison of the live page: dtw_bench_triangulate natively.
    const long n = std::atol(argv[2]);
    if (n < 3) {
      std::fprintf(stderr, "web_native_cases: --bench '%s': need at least 3 points\n", argv[2]);
      return 2;
    }
    const std::vector<double> xy = dt::uniformPoints(std::size_t(n), 1);
    const auto t0 = std::chrono::steady_clock::now();
    const dt::FastResult r = dt::fastDelaunay(xy);
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::printf("%.4f %zu\n", s, r.tri.size());
    return 0;
  }
  if (argc != 2) {
    std::fprintf(stderr, "usage: web_native_cases OUT.js | web_native_cases --bench N\n");
    return 2;
  }
  const std::string out = argv[1], tmp = out + ".tmp";
  std::FILE* f = std::fopen(tmp.c_str(), "w");
  if (!f) {
    std::fprintf(stderr, "web_native_cases: %s: cannot write\n", tmp.c_str());
    return 1;
  }
  std::fprintf(f, "// Written by web_native_cases (web/native_cases.cpp): native triangulations.\n");
  std::fprintf(f, "var DT_CASES = [\n");
  for (const Case& c : hardCases()) {
    // The fast kernel, as the command line runs it; checked exactly before it is written.
    const dt::FastResult r = dt::fastDelaunay(c.xy);
    const dt::CheckReport rep = dt::checkDelaunay(c.xy, r.tri);
    // The corrected listings (delaunayTrglHull, input order), canonical triples.
    dt::Triangulation T;
    dt::delaunayTrglHull(T, dt::addVertices(T, c.xy), dt::StartRule::LastCavity);
    const dt::CheckReport rep2 = dt::checkTriangulation(T);
    if (!rep.ok || !rep2.ok) {
      std::fprintf(stderr, "web_native_cases: %s: %s\n", c.name.c_str(),
                   (rep.ok ? rep2 : rep).error.c_str());
      std::fclose(f);
      std::remove(tmp.c_str());
      return 1;
    }
    std::vector<std::array<long, 3>> canon;
    for (const dt::Face* fc : T.finiteFaces()) {
      std::array<long, 3> t{fc->V[0]->id, fc->V[1]->id, fc->V[2]->id};
      std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
      canon.push_back(t);
    }
    std::sort(canon.begin(), canon.end());
    std::vector<int> fast, listings;
    for (const auto& t : r.tri) fast.insert(fast.end(), t.begin(), t.end());
    for (const auto& t : canon) listings.insert(listings.end(), t.begin(), t.end());
    std::fprintf(f, "{name: \"%s\", xy: ", c.name.c_str());
    writeArray(f, c.xy);
    std::fprintf(f, ",\n fast: ");
    writeInts(f, fast);
    std::fprintf(f, ",\n listings: ");
    writeInts(f, listings);
    std::fprintf(f, "},\n");
  }
  std::fprintf(f, "];\n");
  if (std::fclose(f) != 0 || std::rename(tmp.c_str(), out.c_str()) != 0) {
    std::fprintf(stderr, "web_native_cases: %s: cannot write\n", out.c_str());
    std::remove(tmp.c_str());
    return 1;
  }
  return 0;
}
