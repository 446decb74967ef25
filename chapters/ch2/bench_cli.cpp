// bench_cli: the command line end to end. `delaunay2d` reads a .node file of
// uniform points, triangulates, checks the result exactly and writes the .ele; beside it, when
// CGAL is installed, a CGAL program reads the same file with iostreams and triangulates it
// (Delaunay_triangulation_2, range insertion). Runs alternate (CLI, CGAL, CLI, CGAL, ...), each
// a child process: wall time, CPU time (user + system) and peak resident memory (ru_maxrss,
// from wait4) are its own. Writes table_bench_cli.{md,csv,html}; the ratios are to CGAL.
// Then the triangulation alone, as each program times it itself in the same runs: delaunay2d's
// `triangulation_seconds` (--stats: the points in memory to DT(S), the sort included) against
// the CGAL program's range insertion (dt.insert, its spatial sort included):
// table_bench_cli_triangulation and values_bench_cli.txt (cli.*, cited by the fast kernel's
// page, with the target of at most half of CGAL's time and its computed verdict).
//
//   bench_cli [--out DIR] [--quick] [--max-n N] [--reps R]
//     --quick     10^5 points, one repetition
//     --max-n N   the number of points (default 10^6)
//     --reps R    runs of each program, alternating; the median is kept (default 5)
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

#include "common.h"
#include "delaunay.h"
#include "generators.h"
#include "timing.h"

#ifdef DT_HAVE_CGAL
#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#endif

namespace {

#ifdef DT_HAVE_CGAL
// The CGAL reference, run as `bench_cli --cgal-read FILE`: the .node file read with iostreams
// (header, then number x y [attributes] [marker]), the points triangulated by range insertion.
int cgalReadAndTriangulate(const char* path) {
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  std::ifstream in(path);
  long n = 0, dim = 0, nattr = 0, nmark = 0;
  if (!(in >> n >> dim >> nattr >> nmark) || dim != 2) return 2;
  std::vector<K::Point_2> pts;
  pts.reserve(std::size_t(n));
  for (long i = 0; i < n; ++i) {
    long num;
    double x, y, skip;
    if (!(in >> num >> x >> y)) return 2;
    for (long k = 0; k < nattr + nmark; ++k) in >> skip;
    pts.emplace_back(x, y);
  }
  CGAL::Delaunay_triangulation_2<K> dt;
  const double sys0 = dt::systemSeconds();
  const auto t0 = std::chrono::steady_clock::now();
  dt.insert(pts.begin(), pts.end());
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::printf("%zu faces\ninsert_seconds: %.6f\ninsert_system_seconds: %.6f\n",
              std::size_t(dt.number_of_faces()), s, dt::systemSeconds() - sys0);
  return 0;
}
#endif

// The target for the triangulation alone: at most this share of CGAL's time.
constexpr double kTriangulationBound = 0.5;

struct Run {
  bool ok = false;
  double wall = 0, cpu = 0;
  double peakMB = 0;
  double own = -1;  // the time the program reports for its triangulation (-1: none)
  double ownSystem = -1;  // of it, the system's CPU time, as the program reports it
};

// The number after `key` in the file at path (a line "key value"), or -1.
double reported(const std::string& path, const std::string& key) {
  std::ifstream in(path);
  std::string word;
  double v = -1;
  while (in >> word)
    if (word == key && in >> v) return v;
  return -1;
}

// Runs argv as a child process, its output to the file `capture`; measures it.
Run runChild(const std::vector<std::string>& args, const std::string& capture) {
  std::vector<char*> argv;
  for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  std::cout.flush();
  const auto t0 = std::chrono::steady_clock::now();
  const pid_t pid = fork();
  if (pid < 0) return {};
  if (pid == 0) {
    if (!std::freopen(capture.c_str(), "w", stdout)) _exit(127);
    execv(argv[0], argv.data());
    _exit(127);
  }
  int status = 0;
  struct rusage ru;
  std::memset(&ru, 0, sizeof ru);
  wait4(pid, &status, 0, &ru);
  Run r;
  r.wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  r.cpu = double(ru.ru_utime.tv_sec + ru.ru_stime.tv_sec) +
          1e-6 * double(ru.ru_utime.tv_usec + ru.ru_stime.tv_usec);
  r.peakMB = double(ru.ru_maxrss) / 1024.0;
  r.ok = WIFEXITED(status) && WEXITSTATUS(status) == 0;
  return r;
}

using ch::median;

std::string selfDir() {
  char buf[4096];
  const ssize_t k = readlink("/proc/self/exe", buf, sizeof buf - 1);
  if (k <= 0) return ".";
  std::string s(buf, std::size_t(k));
  return s.substr(0, s.rfind('/'));
}

}  // namespace

int main(int argc, char** argv) {
#ifdef DT_HAVE_CGAL
  if (argc == 3 && std::strcmp(argv[1], "--cgal-read") == 0) return cgalReadAndTriangulate(argv[2]);
  const bool haveCgal = true;
#else
  const bool haveCgal = false;
#endif
  const ch::Program p{"bench_cli", "delaunay2d end to end against a CGAL program (no figure).", 1000,
                      10000000, {}, {{"--reps", "N", "alternating runs of each program (default 5, 1 with --quick)", 1, 1000}}};
  return ch::runMain(argc, argv, p, [&](const ch::Options& o) {
    const int reps = int(o.number("--reps", o.quick ? 1 : 5));
    const std::size_t n = o.maxN > 0 ? std::size_t(o.maxN) : (o.quick ? 100000 : 1000000);
    const std::string cli = selfDir() + "/delaunay2d";
    const std::string input = o.out + "/bench_cli_points.node", out = o.out + "/bench_cli_out";
    {
      // The file a user would have: numbered points, coordinates written in full (%.17g).
      const std::vector<double> xy = dt::uniformPoints(n, 18);
      dt::OutputFiles f;
      dt::Writer& w = f.open(input);
      w.put(long(n)).put(" 2 0 0\n");
      for (std::size_t i = 0; i < n; ++i)
        w.put(long(i) + 1).put(' ').put(xy[2 * i], 17).put(' ').put(xy[2 * i + 1], 17).put('\n');
      f.commit();
    }
    struct Program {
      std::string name;
      std::vector<std::string> args;
      std::string ownKey;     // the line of its output that times its triangulation
      std::string systemKey;  // the line that gives the system's part of that time
      std::vector<Run> runs;
    };
    std::vector<Program> progs = {
        {"delaunay2d (exact check, .ele written)", {cli, input, "-o", out, "--no-progress"}, "", "", {}},
        {"delaunay2d --no-check", {cli, input, "-o", out, "--no-progress", "--no-check", "--stats"},
         "triangulation_seconds:", "triangulation_system_seconds:", {}}};
    if (haveCgal)
      progs.push_back({"CGAL: iostreams + Delaunay_triangulation_2",
                       {selfDir() + "/bench_cli", "--cgal-read", input}, "insert_seconds:",
                       "insert_system_seconds:", {}});
    const std::string capture = o.out + "/bench_cli_stdout.txt";
    std::cout << "bench_cli: " << n << " uniform points, " << reps << " alternating runs of "
              << progs.size() << " programs\n";
    for (int r = 0; r < reps; ++r)
      for (Program& p : progs) {
        Run x = runChild(p.args, capture);
        if (!x.ok) throw std::runtime_error(p.name + " failed");
        if (!p.ownKey.empty() && (x.own = reported(capture, p.ownKey)) < 0)
          throw std::runtime_error(p.name + " did not print " + p.ownKey);
        if (!p.systemKey.empty() && (x.ownSystem = reported(capture, p.systemKey)) < 0)
          throw std::runtime_error(p.name + " did not print " + p.systemKey);
        p.runs.push_back(x);
      }
    std::remove(input.c_str());
    std::remove((out + ".ele").c_str());
    std::remove(capture.c_str());
    auto med = [](const Program& p, double Run::*field) {
      std::vector<double> v;
      for (const Run& r : p.runs) v.push_back(r.*field);
      return median(v);
    };
    ch::Table t;
    t.caption = "The command line end to end, " + std::to_string(n) +
                " uniform points (.node file, medians of " + std::to_string(reps) +
                " alternating runs" + (haveCgal ? "; ratios to CGAL)" : "; CGAL not found)");
    t.header = {"Program", "Wall s", "CPU s", "Peak RSS MB", "Wall / CGAL", "CPU / CGAL",
                "RSS / CGAL"};
    const Program* ref = haveCgal ? &progs.back() : nullptr;
    for (const Program& p : progs) {
      const double w = med(p, &Run::wall), c = med(p, &Run::cpu), m = med(p, &Run::peakMB);
      auto ratio = [&](double v, double Run::*field) {
        return ref ? ch::fmt("%.2f", v / med(*ref, field)) : std::string("-");
      };
      t.add({p.name, ch::fmt("%.3f", w), ch::fmt("%.3f", c), ch::fmt("%.1f", m),
             ratio(w, &Run::wall), ratio(c, &Run::cpu), ratio(m, &Run::peakMB)});
    }
    t.emit(o, "table_bench_cli");

    // The triangulation alone: the times the two programs report, run by run (the same
    // alternating runs), and the ratio of each delaunay2d run to the CGAL run after it.
    ch::Values v(o, "bench_cli");
    v.set("cli.n", std::to_string(n));
    v.set("cli.reps", std::to_string(reps));
    v.num("cli.triangulation_bound", kTriangulationBound, "%.2f");
    const Program& mine = progs[1];
    if (ref) {
      // Run by run: the ratio, and the ratio of the times less the system's part (in a fresh
      // process mostly the mapping of new memory, which varies with the machine's state).
      std::vector<double> ratios, userRatios;
      for (std::size_t r = 0; r < std::size_t(reps); ++r) {
        const Run &x = mine.runs[r], &y = ref->runs[r];
        ratios.push_back(x.own / y.own);
        userRatios.push_back((x.own - x.ownSystem) / (y.own - y.ownSystem));
      }
      const double ratio = median(ratios), a = med(mine, &Run::own), b = med(*ref, &Run::own);
      const double as = med(mine, &Run::ownSystem), bs = med(*ref, &Run::ownSystem);
      ch::Table u;
      u.caption = "The triangulation alone, " + std::to_string(n) +
                  " uniform points: the seconds each program reports for it (delaunay2d's "
                  "triangulation_seconds, the sort included; CGAL's range insertion, its spatial "
                  "sort included) and, of them, the operating system's CPU time (mostly mapping "
                  "new memory), medians of the same " + std::to_string(reps) +
                  " alternating runs; the ratios are the medians of the run-by-run ratios, with their spread.";
      // The spread of the run-by-run ratios, and in how many runs the target held: the target
      // is meant for every run, not only the median.
      const double lo = *std::min_element(ratios.begin(), ratios.end());
      const double hi = *std::max_element(ratios.begin(), ratios.end());
      const long within = long(std::count_if(ratios.begin(), ratios.end(),
                                             [](double x) { return x <= kTriangulationBound; }));
      u.header = {"Program", "Triangulation (s)", "Of it, system (s)", "Ratio to CGAL",
                  "Ratio min-max", "Ratio, system's part left out"};
      u.add({"delaunay2d --no-check --stats", ch::fmt("%.3f", a), ch::fmt("%.3f", as),
             ch::fmt("%.2f", ratio), ch::fmt("%.2f", lo) + "-" + ch::fmt("%.2f", hi),
             ch::fmt("%.2f", median(userRatios))});
      u.add({"CGAL: Delaunay_triangulation_2::insert(first, last)", ch::fmt("%.3f", b),
             ch::fmt("%.3f", bs), "1.00", "-", "1.00"});
      u.emit(o, "table_bench_cli_triangulation");
      v.num("cli.triangulation_seconds", a, "%.3f");
      v.num("cli.cgal_insert_seconds", b, "%.3f");
      v.num("cli.triangulation_ratio", ratio, "%.2f");
      v.num("cli.triangulation_system_seconds", as, "%.3f");
      v.num("cli.cgal_insert_system_seconds", bs, "%.3f");
      v.num("cli.ratio_without_system", median(userRatios), "%.2f");
      v.verdict("cli.triangulation_target", ratio <= kTriangulationBound, "met", "missed");
      v.num("cli.ratio_min", lo, "%.2f");
      v.num("cli.ratio_max", hi, "%.2f");
      v.set("cli.runs_within", std::to_string(within));
      v.set("cli.every_run_target", within == long(reps) ? std::string("met in every run")
                                                         : "missed in " + std::to_string(long(reps) - within) +
                                                               " of " + std::to_string(reps) + " runs");
    } else {
      for (const char* k : {"cli.triangulation_seconds", "cli.cgal_insert_seconds", "cli.triangulation_ratio",
                            "cli.triangulation_system_seconds", "cli.cgal_insert_system_seconds",
                            "cli.ratio_without_system", "cli.ratio_min", "cli.ratio_max", "cli.runs_within"})
        v.set(k, "(not measured: CGAL was not found at build time)");
      v.set("cli.triangulation_target", "not measured");
      v.set("cli.every_run_target", "not measured");
    }
    v.write();
    return 0;
  });
}
