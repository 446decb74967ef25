// bench_kernels: the corrected listings (Hilbert order), the fast kernel and, when it is
// installed, CGAL's Delaunay_triangulation_2, on the same point sets (uniform, clustered, grid,
// circle). Each run is a child process, so its peak memory (ru_maxrss) is its own; the CPU time
// covers everything from the coordinates to the triangulation (sorting included). Writes
// table_bench.{md,csv,html}.
//
//   bench_kernels [--out DIR] [--quick] [--max-n N] [--reps R]
//     --quick     10^4 and 10^5 points, one repetition
//     --max-n N   largest size (default 10^6; 10^7 adds the 10^7 row, several minutes)
//     --reps R    repetitions per run, the fastest is kept (default 3; 1 at 10^7)
#include <malloc.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <iostream>
#include <random>
#include <string>
#include <vector>

#include "common.h"
#include "fast_delaunay.h"
#include "hilbert.h"
#include "triangulate.h"

#ifdef DT_HAVE_CGAL
#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#endif

namespace {

// CPU time of this process (user + system): on a shared machine it counts only this process's
// work, so ratios measured in one run stay meaningful when other jobs compete for the cores.
double cpuSeconds() {
  timespec ts;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

enum class Family { Uniform, Clustered, Grid, Circle };
const char* familyName(Family f) {
  switch (f) {
    case Family::Uniform: return "uniform";
    case Family::Clustered: return "clustered";
    case Family::Grid: return "grid";
    default: return "circle";
  }
}

enum class Method { Listings, Fast, Cgal };
const char* methodName(Method m) {
  switch (m) {
    case Method::Listings: return "listings + Hilbert";
    case Method::Fast: return "fast kernel";
    default: return "CGAL 2D";
  }
}

// The point sets, from fixed seeds. Grid: the integer points of a square (about n of them,
// shuffled), all degenerate; circle: n points on the unit circle, rounded (nearly cocircular).
std::vector<double> makePoints(Family f, std::size_t n) {
  std::mt19937_64 rng(20260 + unsigned(f));
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<double> xy;
  xy.reserve(2 * n);
  if (f == Family::Uniform) {
    for (std::size_t i = 0; i < 2 * n; ++i) xy.push_back(u(rng));
  } else if (f == Family::Clustered) {  // 100 Gaussian clusters of width 0.002
    std::normal_distribution<double> g(0, 0.002);
    std::vector<double> c(200);
    for (double& v : c) v = u(rng);
    for (std::size_t i = 0; i < n; ++i) {
      const std::size_t k = std::size_t(u(rng) * 100) % 100;
      xy.push_back(c[2 * k] + g(rng));
      xy.push_back(c[2 * k + 1] + g(rng));
    }
  } else if (f == Family::Grid) {
    const long m = std::lround(std::sqrt(double(n)));
    std::vector<std::size_t> perm(std::size_t(m * m));
    for (std::size_t i = 0; i < perm.size(); ++i) perm[i] = i;
    std::shuffle(perm.begin(), perm.end(), rng);
    for (std::size_t k : perm) {
      xy.push_back(double(long(k) / m));
      xy.push_back(double(long(k) % m));
    }
  } else {
    for (std::size_t i = 0; i < n; ++i) {
      const double t = 2 * M_PI * double(i) / double(n);
      xy.push_back(std::cos(t));
      xy.push_back(std::sin(t));
    }
    // Shuffled, as a file would come; every method sorts anyway.
    for (std::size_t i = n; i > 1; --i) {
      const std::size_t j = std::uniform_int_distribution<std::size_t>(0, i - 1)(rng);
      std::swap(xy[2 * (i - 1)], xy[2 * j]);
      std::swap(xy[2 * (i - 1) + 1], xy[2 * j + 1]);
    }
  }
  return xy;
}

// One triangulation; returns the number of finite triangles.
long triangulate(Method m, const std::vector<double>& xy) {
  if (m == Method::Fast) return long(dt::fastDelaunay(xy).tri.size());
  if (m == Method::Listings) {
    const std::vector<std::size_t> order = dt::hilbertOrder(xy);
    dt::Triangulation T;
    std::vector<dt::Vertex*> S;
    S.reserve(order.size());
    for (std::size_t i : order) S.push_back(T.addVertex(xy[2 * i], xy[2 * i + 1], long(i)));
    dt::delaunayTrglHull(T, S, dt::StartRule::LastCavity);
    return long(T.numFiniteFaces());
  }
#ifdef DT_HAVE_CGAL
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  std::vector<K::Point_2> pts;
  pts.reserve(xy.size() / 2);
  for (std::size_t i = 0; i < xy.size(); i += 2) pts.emplace_back(xy[i], xy[i + 1]);
  CGAL::Delaunay_triangulation_2<K> cdt;
  cdt.insert(pts.begin(), pts.end());  // range insertion: CGAL's spatial sort, then insertion
  return long(cdt.number_of_faces());
#else
  return -1;
#endif
}

struct Measure {
  bool ok = false;
  double seconds = 0;
  long triangles = 0;
  long peakKB = 0;
  std::size_t points = 0;
};

// Runs one method in a child process: the child builds the points, triangulates, reports time
// and count through a pipe; the parent reads the child's peak resident memory from wait4.
Measure runChild(Method m, Family f, std::size_t n) {
  Measure r;
  int fd[2];
  if (pipe(fd) != 0) return r;
  std::cout.flush();
  const pid_t pid = fork();
  if (pid < 0) return r;
  if (pid == 0) {
    close(fd[0]);
    // A fixed mmap threshold: glibc otherwise raises it after each large free, and the next
    // arrays then land in a heap it does not return, which inflates the peak for every method.
    mallopt(M_MMAP_THRESHOLD, 128 * 1024);
    double out[3] = {0, -1, 0};
    try {
      const std::vector<double> xy = makePoints(f, n);
      const double t0 = cpuSeconds();
      const long tri = triangulate(m, xy);
      out[0] = cpuSeconds() - t0;
      out[1] = double(tri);
      out[2] = double(xy.size() / 2);
    } catch (const std::exception& e) {
      std::cerr << methodName(m) << " on " << familyName(f) << ": " << e.what() << "\n";
    }
    const ssize_t w = write(fd[1], out, sizeof out);
    _exit(w == ssize_t(sizeof out) ? 0 : 1);
  }
  close(fd[1]);
  double in[3] = {0, -1, 0};
  const ssize_t got = read(fd[0], in, sizeof in);
  close(fd[0]);
  int status = 0;
  struct rusage ru;
  std::memset(&ru, 0, sizeof ru);
  wait4(pid, &status, 0, &ru);
  r.ok = got == ssize_t(sizeof in) && WIFEXITED(status) && WEXITSTATUS(status) == 0 && in[1] >= 0;
  r.seconds = in[0];
  r.triangles = long(in[1]);
  r.points = std::size_t(in[2]);
  r.peakKB = ru.ru_maxrss;
  return r;
}

}  // namespace

int main(int argc, char** argv) {
  ch::Options o = ch::parseOptions(argc, argv);
  int reps = o.quick ? 1 : 3;
  for (std::size_t i = 0; i < o.rest.size(); ++i) {
    if (o.rest[i] == "--reps" && i + 1 < o.rest.size()) {
      reps = std::max(1, std::atoi(o.rest[++i].c_str()));
    } else {
      std::cerr << "bench_kernels: unknown option " << o.rest[i] << "\n";
      return 2;
    }
  }
  std::vector<std::size_t> sizes = o.quick ? std::vector<std::size_t>{10000, 100000}
                                           : std::vector<std::size_t>{100000, 1000000};
  const std::size_t maxN = o.maxN > 0 ? std::size_t(o.maxN) : (o.quick ? 100000 : 1000000);
  if (maxN >= 10000000) sizes.push_back(10000000);
  std::vector<Method> methods = {Method::Listings, Method::Fast};
#ifdef DT_HAVE_CGAL
  methods.push_back(Method::Cgal);
  const bool haveCgal = true;
  std::cout << "CGAL " << CGAL_VERSION_STR << " found: it is the reference of the ratios\n";
#else
  const bool haveCgal = false;
  std::cout << "CGAL not found at build time: ratios are to the corrected listings\n";
#endif

  ch::Table t;
  t.caption = std::string("Kernels on the same points, one process per run, best of ") +
              std::to_string(reps) +
              " (CPU time, user + system, from the coordinates to the triangles, sorting "
              "included; "
              "peak: the whole process, points included; ratios to " +
              (haveCgal ? "CGAL" : "the listings") + ")";
  t.header = {"points", "n", "kernel", "CPU time (s)", "time ratio", "peak (MB)", "peak ratio",
              "triangles", "same count"};
  const Family families[] = {Family::Uniform, Family::Clustered, Family::Grid, Family::Circle};
  // For the page's targets: at the largest n, the speed-up on uniform points, the worst time
  // and peak ratios of the fast kernel, and the listings' worst time ratio (all to CGAL).
  double uniformSpeedup = 0, worstFast = 0, worstPeak = 0, worstListings = 0;
  std::string worstListingsFamily, winsOn, losesOn;
  ch::Progress progress("bench_kernels", sizes.size() * 4 * methods.size());
  std::uint64_t done = 0;
  for (std::size_t n : sizes) {
    for (Family f : families) {
      std::vector<Measure> res;
      for (Method m : methods) {
        // The listings at 10^7 take minutes: once is enough.
        const int r = (n >= 10000000 || (m == Method::Listings && n >= 1000000)) ? 1 : reps;
        Measure best;
        for (int k = 0; k < r; ++k) {
          const Measure x = runChild(m, f, n);
          if (!x.ok) {
            best = x;
            break;
          }
          if (!best.ok || x.seconds < best.seconds) {
            const long peak = std::max(best.peakKB, x.peakKB);
            best = x;
            best.peakKB = peak;
          }
        }
        res.push_back(best);
        progress.update(++done);
      }
      const Measure& ref = res.back();  // CGAL if present, else the fast kernel's row below
      const Measure& base = haveCgal ? ref : res[0];
      for (std::size_t k = 0; k < methods.size(); ++k) {
        const Measure& x = res[k];
        bool same = x.ok;
        for (const Measure& y : res) same = same && y.ok && y.triangles == x.triangles;
        t.add({familyName(f), std::to_string(x.points), methodName(methods[k]),
               x.ok ? ch::fmt("%.3f", x.seconds) : "failed",
               x.ok && base.ok ? ch::fmt("%.2f", x.seconds / base.seconds) : "-",
               ch::fmt("%.0f", double(x.peakKB) / 1024),
               base.peakKB > 0 ? ch::fmt("%.2f", double(x.peakKB) / double(base.peakKB)) : "-",
               std::to_string(x.triangles), same ? "yes" : "NO"});
        if (haveCgal && n == sizes.back() && x.ok && base.ok && k + 1 < methods.size()) {
          const double tr = x.seconds / base.seconds;
          if (methods[k] == Method::Fast) {
            std::string& list = tr < 1.0 ? winsOn : losesOn;
            list += std::string(list.empty() ? "" : ", ") + familyName(f);
            if (f == Family::Uniform) uniformSpeedup = base.seconds / x.seconds;
            worstFast = std::max(worstFast, tr);
            if (base.peakKB > 0) worstPeak = std::max(worstPeak, double(x.peakKB) / double(base.peakKB));
          } else if (tr > worstListings) {
            worstListings = tr;
            worstListingsFamily = familyName(f);
          }
        }
        std::cout << familyName(f) << " n=" << x.points << " " << methodName(methods[k]) << ": "
                  << ch::fmt("%.3f s, %.0f MB", x.seconds, double(x.peakKB) / 1024) << "\n";
      }
    }
  }
  t.emit(o, "table_bench");
  ch::Values v(o, "bench_kernels");
  v.set("kernel.n", std::to_string(sizes.back()));
  if (haveCgal && uniformSpeedup > 0) {
    v.num("kernel.uniform_speedup", uniformSpeedup, "%.2f");
    v.verdict("kernel.speed_target", uniformSpeedup >= 2.0, "met", "missed");
    v.num("kernel.worst_peak", worstPeak, "%.2f");
    v.verdict("kernel.memory_target", worstPeak <= 0.5, "met", "missed");
    v.num("kernel.worst_time", worstFast, "%.2f");
    v.verdict("kernel.family_target", worstFast <= 1.2, "met", "missed");
    v.num("kernel.worst_listings", worstListings, "%.2f");
    v.set("kernel.worst_listings_family", worstListingsFamily);
    v.verdict("kernel.listings_target", worstListings <= 4.0, "met", "missed");
    v.set("kernel.wins_on", winsOn.empty() ? "none" : winsOn);
    v.set("kernel.loses_on", losesOn.empty() ? "none" : losesOn);
  } else {
    for (const char* k : {"kernel.uniform_speedup", "kernel.worst_peak", "kernel.worst_time",
                          "kernel.worst_listings", "kernel.worst_listings_family",
                          "kernel.wins_on", "kernel.loses_on"})
      v.set(k, "(not measured: CGAL was not found at build time)");
    for (const char* k : {"kernel.speed_target", "kernel.memory_target", "kernel.family_target",
                          "kernel.listings_target"})
      v.set(k, "not measured");
  }
  v.write();
  return 0;
}
