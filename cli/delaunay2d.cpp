// delaunay2d: the Delaunay triangulation DT(S) of a point file, exact for every input.
//
//   delaunay2d points.node -o out [--method hull|super] [--stats] [--svg out.svg] [--msh out.msh]
//              [--no-check]
//
// Reads a Triangle .node file or a plain "x y" file, writes out.ele (Triangle format,
// counter-clockwise triangles, vertices numbered as in the input). Exit status: 0 on success,
// 2 on bad input (message on stderr, nothing written), 1 on an internal error.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <numeric>
#include <string>
#include <vector>

#include "check.h"
#include "io.h"
#include "predicates.h"
#include "flip.h"
#include "triangulate.h"

namespace {

const char* kUsage =
    "usage: delaunay2d INPUT -o OUT [options]\n"
    "  INPUT          Triangle .node file, or a text file of 'x y' lines\n"
    "  -o OUT         write OUT.ele (OUT may also end in .ele)\n"
    "  --stats        print points, triangles, triangulation_seconds, mean walk steps and\n"
    "                 mean cavity size, one per line, on stdout\n"
    "  --svg FILE     also write an SVG drawing of the mesh\n"
    "  --msh FILE     also write a Gmsh ASCII (2.2) mesh\n"
    "  --no-check     skip the exact validation of the result (on by default)\n"
    "  --method M     how DT(S) is built: 'hull' (default; ghost faces, points outside the\n"
    "                 hull inserted directly, section 2.2.2) or 'super' (super-triangles,\n"
    "                 then DT(S) recovered from DT(S0 u S) by flips, 2.2.1 and 2.3.6); both\n"
    "                 give the exact DT(S); with --stats, 'super' also prints recovery_flips\n"
    "  -h, --help     this help\n";

struct Options {
  std::string input, out, svg, msh;
  bool stats = false, check = true;
  bool superMethod = false;  // --method super
};

[[noreturn]] void usageError(const std::string& why) {
  std::cerr << "delaunay2d: " << why << "\n" << kUsage;
  std::exit(2);
}

Options parse(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&](const char* name) -> std::string {
      if (i + 1 >= argc) usageError(std::string(name) + " needs a value");
      return argv[++i];
    };
    if (a == "-h" || a == "--help") {
      std::cout << kUsage;
      std::exit(0);
    } else if (a == "-o") {
      o.out = value("-o");
    } else if (a == "--stats") {
      o.stats = true;
    } else if (a == "--svg") {
      o.svg = value("--svg");
    } else if (a == "--msh") {
      o.msh = value("--msh");
    } else if (a == "--method") {
      const std::string m = value("--method");
      if (m != "hull" && m != "super") usageError("--method must be 'hull' or 'super'");
      o.superMethod = m == "super";
    } else if (a == "--no-check") {
      o.check = false;
    } else if (!a.empty() && a[0] == '-' && a != "-") {
      usageError("unknown option '" + a + "'");
    } else if (o.input.empty()) {
      o.input = a;
    } else {
      usageError("more than one input file ('" + o.input + "' and '" + a + "')");
    }
  }
  if (o.input.empty()) usageError("no input file");
  if (o.out.empty()) usageError("no output name (-o OUT)");
  if (o.out.size() > 4 && o.out.compare(o.out.size() - 4, 4, ".ele") == 0)
    o.out.resize(o.out.size() - 4);
  return o;
}

}  // namespace

int main(int argc, char** argv) {
  const Options opt = parse(argc, argv);
  try {
    const dt::PointSet ps = dt::readPoints(opt.input);
    const std::size_t n = ps.size();
    // Duplicates: sort by (x, y); keep the first occurrence (smallest number).
    std::vector<std::size_t> order(n);
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
      return ps.xy[2 * a] < ps.xy[2 * b] ||
             (ps.xy[2 * a] == ps.xy[2 * b] && ps.xy[2 * a + 1] < ps.xy[2 * b + 1]);
    });
    std::vector<char> keep(n, 1);
    std::size_t nDup = 0;
    std::size_t runStart = n ? order[0] : 0;  // first occurrence of the current run of equals
    for (std::size_t k = 1; k < n; ++k) {
      const std::size_t a = order[k - 1], b = order[k];
      if (ps.xy[2 * a] == ps.xy[2 * b] && ps.xy[2 * a + 1] == ps.xy[2 * b + 1]) {
        keep[b] = 0;
        ++nDup;
        std::cerr << "delaunay2d: " << ps.path << ":" << ps.line[b] << ": point " << ps.number[b]
                  << " duplicates point " << ps.number[runStart] << " (line "
                  << ps.line[runStart] << "); merged\n";
      } else {
        runStart = b;
      }
    }
    dt::Triangulation T;
    std::vector<dt::Vertex*> S;
    S.reserve(n - nDup);
    for (std::size_t i = 0; i < n; ++i)
      if (keep[i]) S.push_back(T.addVertex(ps.xy[2 * i], ps.xy[2 * i + 1], long(i)));

    dt::InsertionStats st;
    const auto t0 = std::chrono::steady_clock::now();
    dt::FlipStats fs;
    if (opt.superMethod) {
      // 2.2.1: super-triangles around the box, DT(S0 u S), then the flips of 2.3.6. A flat or
      // collinear input is rejected as by the hull method (it has no DT(S)).
      if (S.size() < 3) throw dt::DegenerateInput("fewer than 3 distinct points");
      bool flat = true;
      for (std::size_t i = 2; i < S.size() && flat; ++i)
        flat = dt::orientationTest(S[0], S[1], S[i]) == 0;
      if (flat) throw dt::DegenerateInput("all points are collinear");
      double x0 = S[0]->x, x1 = x0, y0 = S[0]->y, y1 = y0;
      for (const dt::Vertex* v : S) {
        x0 = std::min(x0, v->x), x1 = std::max(x1, v->x);
        y0 = std::min(y0, v->y), y1 = std::max(y1, v->y);
      }
      // Any enclosing size gives the exact DT(S) (2.3.6); near the overflow threshold the
      // default factor 10 may not fit in doubles, so smaller ones are tried.
      for (double factor : {10.0, 2.0, 1.01}) {
        try {
          dt::initSuperTriangles(T, x0, y0, x1, y1, factor);
          break;
        } catch (const dt::DegenerateInput&) {
          if (factor == 1.01) throw std::runtime_error("super-triangles do not fit in doubles");
        }
      }
      dt::delaunayTrgl(T, S, dt::StartRule::LastCavity, &st);
      fs = dt::recoverDelaunay(T);
    } else {
      dt::delaunayTrglHull(T, S, dt::StartRule::LastCavity, &st);
    }
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

    dt::PlainMesh m = dt::extractMesh(T, true);
    if (opt.check) {
      std::vector<char> must(m.ids.size(), 1);
      const dt::CheckReport r = dt::checkDelaunay(m.xy, m.tri, &must);
      if (!r.ok || m.ids.size() != S.size()) {
        std::cerr << "delaunay2d: internal error: the result fails the exact check: "
                  << (r.ok ? "a point is missing" : r.error) << "\n";
        return 1;
      }
    }
    std::vector<long> numbers(m.ids.size());
    for (std::size_t i = 0; i < m.ids.size(); ++i) numbers[i] = ps.number[std::size_t(m.ids[i])];
    dt::writeFileAtomic(opt.out + ".ele", dt::eleText(m.tri, numbers, ps.firstIndex));
    if (!opt.svg.empty()) dt::writeFileAtomic(opt.svg, dt::svgText(m.xy, m.tri));
    if (!opt.msh.empty()) dt::writeFileAtomic(opt.msh, dt::mshText(m.xy, m.tri));
    if (opt.stats) {
      std::printf("points: %zu\ntriangles: %zu\ntriangulation_seconds: %.6f\n", n, m.tri.size(),
                  seconds);
      std::printf("duplicates: %zu\nmean_walk_steps: %.4f\nmean_cavity_size: %.4f\n", nDup,
                  st.meanSearch(), st.meanCavity());
      if (opt.superMethod)
        std::printf("recovery_flips: %llu\n", (unsigned long long)fs.flips);
    }
    return 0;
  } catch (const dt::InputError& e) {
    std::cerr << "delaunay2d: " << e.what() << "\n";
    return 2;
  } catch (const dt::DegenerateInput& e) {
    std::cerr << "delaunay2d: " << opt.input << ": " << e.what()
              << ": no triangulation exists\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "delaunay2d: error: " << e.what() << "\n";
    return 1;
  }
}
