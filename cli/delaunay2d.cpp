// delaunay2d: the Delaunay triangulation DT(S) of a point file, exact for every input.
//
//   delaunay2d points.node -o out [--method hull|super] [--order brio|hilbert|input] [--stats]
//              [--svg out.svg] [--msh out.msh] [--no-check]
//
// Reads a Triangle .node file or a plain "x y" file, writes out.ele (Triangle format,
// counter-clockwise triangles, vertices numbered as in the input). Exit status: 0 on success,
// 2 on bad input (message on stderr, nothing written), 1 on an internal error.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <numeric>
#include <stdexcept>
#include <string>
#include <vector>

#include <unistd.h>

#include "check.h"
#include "io.h"
#include "predicates.h"
#include "fast_delaunay.h"
#include "fast_parallel.h"
#include "flip.h"
#include "hilbert.h"
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
    "  --order O      insertion order (section 2.3.5): 'brio' (default; random rounds of\n"
    "                 doubling size, each Hilbert-sorted), 'hilbert' (one Hilbert sort: as\n"
    "                 fast on spread-out points, quadratic on points along a curve) or\n"
    "                 'input' (file order: walks grow like sqrt(n))\n"
    "  --kernel K     'fast' (default: code/fast_delaunay.h, index arrays, inlined filters,\n"
    "                 its own BRIO/Hilbert order) or 'listings' (the corrected Listings 2.4-2.7);\n"
    "                 both give the exact DT(S); --method super always uses the listings\n"
    "  --threads N    threads of the fast kernel with --order brio (default: all cores;\n"
    "                 1: the sequential kernel); the same exact DT(S), see the parallel page\n"
    "  --progress     report progress on stderr (default: only when stderr is a terminal)\n"
    "  --no-progress  never report progress\n"
    "  -h, --help     this help\n"
    "exit status: 0 success; 1 internal error or output not writable; 2 bad usage or bad\n"
    "input (message naming file, line and value; no output written)\n";

struct Options {
  std::string input, out, svg, msh;
  bool stats = false, check = true;
  bool superMethod = false;  // --method super
  bool fastKernel = true;    // --kernel fast (default) or listings
  // --order (2.3.5). BRIO by default: a plain Hilbert sort makes points along a curve (a
  // parabola) cost O(n) per insertion, BRIO's random rounds do not (sec2_3_5_hilbert).
  std::string order = "brio";
  int progress = -1;         // --progress 1, --no-progress 0, default -1: if stderr is a tty
  int threads = dt::defaultThreadCount();  // --threads N (fast kernel, BRIO order)
};

// Progress on stderr for long runs: the phase, and while the listings insert, the points
// inserted, the rate and the time left; on a terminal one line rewritten in place. Phases are
// shown for inputs of 100000 points or more, the insertion count after half a second.
class Progress {
 public:
  explicit Progress(int mode)  // 1: always, 0: never, -1: if stderr is a terminal
      : on_(mode == 1 || (mode == -1 && tty_)), forced_(mode == 1) {}
  void setTotal(std::size_t n) { total_ = n; }
  void phase(const std::string& what) {
    if (on_ && (forced_ || shown_ || total_ >= 100000)) show(what);
  }
  void startInsertion() {
    insertStart_ = std::chrono::steady_clock::now();
    lastShown_ = 0;
  }
  void update(std::size_t done) {
    if (!on_) return;
    const double t = since(insertStart_);
    if (t < 0.5 || t - lastShown_ < 0.25) return;
    // The rate of the last interval: in file order, insertion slows down as n grows.
    const double rate = lastShown_ > 0 ? double(done - lastDone_) / (t - lastShown_) : done / t;
    lastShown_ = t;
    lastDone_ = done;
    char buf[200];
    std::snprintf(buf, sizeof buf, "%zu of %zu points inserted (%.0f%%), %.0f points/s, about "
                  "%.0f s left", done, total_, total_ ? 100.0 * double(done) / double(total_) : 100.0,
                  rate, rate > 0 ? double(total_ - done) / rate : 0.0);
    show(buf);
  }
  // The last line (it ends the rewritten line on a terminal).
  void finish(std::size_t points) {
    if (!on_ || !(forced_ || shown_)) return;
    std::fprintf(stderr, "%sdelaunay2d: %zu points triangulated in %.1f s\n",
                 tty_ ? "\r\033[K" : "", points, since(start_));
  }

 private:
  void show(const std::string& what) {
    if (tty_)
      std::fprintf(stderr, "\rdelaunay2d: %s\033[K", what.c_str());
    else
      std::fprintf(stderr, "delaunay2d: %s\n", what.c_str());
    std::fflush(stderr);
    shown_ = true;
  }
  static double since(std::chrono::steady_clock::time_point t) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
  }
  bool tty_ = ::isatty(STDERR_FILENO) == 1;
  bool on_, forced_;
  bool shown_ = false;
  std::size_t total_ = 0, lastDone_ = 0;
  double lastShown_ = 0;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now(),
                                        insertStart_ = start_;
};

constexpr std::size_t kNamedDuplicates = 10;

// Valid input that the chosen method cannot handle (exit status 2, like bad input).
struct UnsupportedInput : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Inserts S[from..) with delaunayTrgl in chunks (the same insertions as one call), reporting
// progress between chunks.
void insertInChunks(dt::Triangulation& T, const std::vector<dt::Vertex*>& S, std::size_t from,
                    dt::InsertionStats& st, Progress& progress) {
  const std::size_t chunk = 4096;
  for (std::size_t a = from; a < S.size(); a += chunk) {
    const std::vector<dt::Vertex*> part(S.begin() + long(a),
                                        S.begin() + long(std::min(S.size(), a + chunk)));
    dt::delaunayTrgl(T, part, dt::StartRule::LastCavity, &st);
    progress.update(a + part.size());
  }
}

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
    } else if (a == "--order") {
      o.order = value("--order");
      if (o.order != "hilbert" && o.order != "brio" && o.order != "input")
        usageError("--order must be 'hilbert', 'brio' or 'input'");
    } else if (a == "--kernel") {
      const std::string k = value("--kernel");
      if (k != "fast" && k != "listings") usageError("--kernel must be 'fast' or 'listings'");
      o.fastKernel = k == "fast";
    } else if (a == "--progress" || a == "--no-progress") {
      o.progress = a == "--progress";
    } else if (a == "--threads") {
      const std::string v = value("--threads");
      char* end = nullptr;
      const long t = std::strtol(v.c_str(), &end, 10);
      if (v.empty() || *end != '\0' || t < 1 || t > 1024)
        usageError("--threads must be an integer from 1 to 1024, not '" + v + "'");
      o.threads = int(t);
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
  Progress progress(opt.progress);
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
        // The first few are named; a file of 10^6 copies must not print 10^6 lines.
        if (++nDup <= kNamedDuplicates)
          std::cerr << "delaunay2d: " << ps.path << ":" << ps.line[b] << ": point "
                    << ps.number[b] << " duplicates point " << ps.number[runStart] << " (line "
                    << ps.line[runStart] << "); merged\n";
      } else {
        runStart = b;
      }
    }
    if (nDup > kNamedDuplicates)
      std::cerr << "delaunay2d: " << ps.path << ": " << nDup - kNamedDuplicates
                << " more duplicate points merged (" << nDup << " in all)\n";
    dt::Triangulation T;
    std::vector<dt::Vertex*> S;
    S.reserve(n - nDup);
    for (std::size_t i = 0; i < n; ++i)
      if (keep[i]) S.push_back(T.addVertex(ps.xy[2 * i], ps.xy[2 * i + 1], long(i)));

    dt::InsertionStats st;
    progress.setTotal(S.size());
    const auto t0 = std::chrono::steady_clock::now();
    // --kernel fast: the distinct points go to fastDelaunay, which orders them itself.
    const bool useFast = opt.fastKernel && !opt.superMethod;
    dt::PlainMesh fastMesh;
    if (useFast) {
      dt::FastOptions fo;
      if (opt.order == "hilbert") fo.order = dt::FastOrder::Hilbert;
      if (opt.order == "input") fo.order = dt::FastOrder::Input;
      for (std::size_t i = 0; i < n; ++i)
        if (keep[i]) {
          fastMesh.xy.insert(fastMesh.xy.end(), {ps.xy[2 * i], ps.xy[2 * i + 1]});
          fastMesh.ids.push_back(long(i));
        }
      progress.phase("triangulating " + std::to_string(S.size()) + " points (fast kernel)");
      dt::FastResult fr = dt::fastDelaunayParallel(
          fastMesh.xy, fo.order == dt::FastOrder::RadixBrio ? opt.threads : 1, fo);
      fastMesh.tri = std::move(fr.tri);
      st.insertions = fr.stats.insertions;
      st.searchSteps = fr.stats.walkSteps;
      st.cavityFaces = fr.stats.cavityFaces;
    }
    if (!useFast && opt.order != "input" && S.size() > 1) {
      // 2.3.5: with the walk started in the previous cavity, a Hilbert (or BRIO) order keeps
      // the walks short; in file order they can grow like sqrt(n). Timed with the insertions.
      std::vector<double> xy;
      xy.reserve(2 * S.size());
      for (const dt::Vertex* v : S) xy.insert(xy.end(), {v->x, v->y});
      const std::vector<std::size_t> idx =
          opt.order == "brio" ? dt::brioOrder(xy, 1) : dt::hilbertOrder(xy);
      std::vector<dt::Vertex*> sorted(S.size());
      for (std::size_t k = 0; k < idx.size(); ++k) sorted[k] = S[idx[k]];
      S.swap(sorted);
    }
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
          // The input is valid, the method cannot hold it: a usage error (exit 2), not a bug.
          if (factor == 1.01) throw UnsupportedInput(
              "--method super cannot enclose points this close to the overflow threshold "
              "(|x| or |y| near 1.8e308) in double super-triangles; use --method hull");
        }
      }
      progress.phase("inserting " + std::to_string(S.size()) + " points (listings)");
      progress.startInsertion();
      insertInChunks(T, S, 0, st, progress);
      progress.phase("recovering DT(S) by flips");
      fs = dt::recoverDelaunay(T);
    } else if (!useFast) {
      // delaunayTrglHull on the shortest prefix of S that spans a triangle (on a collinear S
      // it throws DegenerateInput), then the other points in chunks.
      std::size_t k = 2;
      while (k < S.size() && dt::orientationTest(S[0], S[1], S[k]) == 0) ++k;
      k = std::min(k + 1, S.size());
      dt::delaunayTrglHull(T, std::vector<dt::Vertex*>(S.begin(), S.begin() + long(k)),
                           dt::StartRule::LastCavity, &st);
      progress.phase("inserting " + std::to_string(S.size()) + " points (listings)");
      progress.startInsertion();
      insertInChunks(T, S, k, st, progress);
    }
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

    dt::PlainMesh m = useFast ? std::move(fastMesh) : dt::extractMesh(T, true);
    if (opt.check) {
      progress.phase("checking the result with exact predicates");
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
    progress.phase("writing " + opt.out + ".ele");
    // All or nothing: if one output cannot be written, the ones already written are removed.
    std::vector<std::pair<std::string, std::string>> outputs = {
        {opt.out + ".ele", dt::eleText(m.tri, numbers, ps.firstIndex)}};
    if (!opt.svg.empty()) outputs.emplace_back(opt.svg, dt::svgText(m.xy, m.tri));
    if (!opt.msh.empty()) outputs.emplace_back(opt.msh, dt::mshText(m.xy, m.tri));
    for (std::size_t i = 0; i < outputs.size(); ++i) {
      try {
        dt::writeFileAtomic(outputs[i].first, outputs[i].second);
      } catch (const std::exception&) {
        for (std::size_t j = 0; j < i; ++j) std::remove(outputs[j].first.c_str());
        throw;
      }
    }
    progress.finish(S.size());
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
  } catch (const UnsupportedInput& e) {
    std::cerr << "delaunay2d: " << opt.input << ": " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "delaunay2d: error: " << e.what() << "\n";
    return 1;
  }
}
