// bench_parallel (going further: the parallel page). Two measurements of the fast kernel on
// uniform random points, each run in a child process of its own:
//  1. time against threads (code/fast/fast_parallel.h) at 10^6 points (and 10^7 with --max-n), wall
//     and CPU time, beside CGAL's Delaunay_triangulation_2 when it is installed; at the first n,
//     the time budget of two threads (table_parallel_budget: sort, one thread alone, concurrent
//     rounds, output, set-up) beside the sequential kernel and the parallel machinery run by
//     one thread (dt::fastDelaunaySharedCoreAlone);
//  2. time per point of the sequential kernel from 10^3 points to --max-n (default 10^6; up to
//     10^8 = 100000000), with the peak memory (VmHWM) of the triangulation and of the check.
// Every triangulation is validated exactly (dt::checkDelaunay). Writes table_parallel.*,
// table_time_per_point.*, time_per_point.dat, time_per_point_verdict.html, the cache markers
// (time_per_point_view.gp, time_per_point_cache_lines.dat, time_per_point_caches.dat: the data
// caches of /sys/devices/system/cpu/cpu0/cache, or of the directory --cache-dir names, in the
// same format; chapters/cache_sizes.h) and fig_time_per_point.{png,svg}; a run with
// --max-n >= 10^7 also writes time_per_point_large.dat, which later default runs plot as well.
//
//   bench_parallel [--out DIR] [--quick] [--max-n N] [--reps R] [--threads T1,T2,...]
//                  [--cache-dir DIR]
#include <sys/resource.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <iterator>
#include <set>
#include <sstream>
#include <string>
#include <thread>
#include <tuple>
#include <vector>

#include "cache_sizes.h"
#include "timing.h"
#include "check.h"
#include "common.h"
#include "fast_delaunay.h"
#include "fast_parallel.h"
#include "figure_data.h"
#include "generators.h"
#include "hilbert.h"

#ifdef DT_HAVE_CGAL
#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#endif

namespace {

double cpuNow() {  // this process, all its threads
  timespec ts;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}
double wallNow() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

// Peak resident memory so far (VmHWM), in MB; 0 if unreadable.
double peakMB() { return double(dt::peakResidentKB()) / 1024.0; }

std::string loadAverage() {
  std::ifstream f("/proc/loadavg");
  double a = 0, b = 0, c = 0;
  f >> a >> b >> c;
  return ch::fmt("%.2f %.2f %.2f", a, b, c);
}

// Runs job(out) in a child process: it fills up to 16 numbers, returned through a pipe; empty
// on failure (the child's exception message goes to stderr).
constexpr int kSlots = 16;
// The target for one thread against CGAL: at most this share of CGAL's CPU time (the page
// cites it as @{par.target1_bound}; the verdict par.target1 compares with the same number).
constexpr double kCpuTarget1 = 0.65;
// The target for two threads against one: at most this share of one thread's wall
// time (the page cites @{par.two_target}; the verdict par.two_target_verdict uses it).
constexpr double kTwoTarget = 0.6;
// Where Linux describes this machine's caches (chapters/cache_sizes.h); --cache-dir reads another.
constexpr const char* kSysCacheDir = "/sys/devices/system/cpu/cpu0/cache";
// The end of a timing table's caption: the machine's hardware threads and its load when the
// table was made (a loaded machine's ratios measure the waiting as much as the work).
std::string machineNote(int hw) {
  return " The machine has " + std::to_string(hw) + " hardware threads; load average at the end: " +
         loadAverage() + ".";
}

std::vector<double> inChild(const std::function<void(double*)>& job) {
  int fd[2];
  if (pipe(fd) != 0) return {};
  std::cout.flush();
  const pid_t pid = fork();
  if (pid < 0) return {};
  if (pid == 0) {
    close(fd[0]);
    double out[kSlots] = {};
    int rc = 0;
    try {
      job(out);
    } catch (const std::exception& e) {
      std::cerr << "bench_parallel: " << e.what() << "\n";
      rc = 1;
    }
    const ssize_t w = write(fd[1], out, sizeof out);
    _exit(rc == 0 && w == ssize_t(sizeof out) ? 0 : 1);
  }
  close(fd[1]);
  double in[kSlots] = {};
  const ssize_t got = read(fd[0], in, sizeof in);
  close(fd[0]);
  int status = 0;
  waitpid(pid, &status, 0);
  if (got != ssize_t(sizeof in) || !WIFEXITED(status) || WEXITSTATUS(status) != 0) return {};
  return std::vector<double>(in, in + kSlots);
}

// Validates a result exactly; throws if it is not DT(S).
void validate(const std::vector<double>& xy, const std::vector<dt::Tri>& tri) {
  const dt::CheckReport c = dt::checkDelaunay(xy, tri);
  if (!c.ok) throw std::runtime_error("the triangulation fails the exact check: " + c.error);
}

// One triangulation of n uniform points with `threads` threads (0: CGAL; a positive count: the
// parts and their seam, the default design; -3 and -4: 2 threads on one shared mesh, claiming
// triangles with locks or with slabs), validated if `check`.
// out: wall, CPU, triangles, deferred insertions, concurrent points, peak MB.
void threadsJob(std::size_t n, int threads, bool check, double* out) {
  const std::vector<double> xy = dt::uniformPoints(n, 2026);
  const double w0 = wallNow(), c0 = cpuNow();
  if (threads == 0) {
#ifdef DT_HAVE_CGAL
    using K = CGAL::Exact_predicates_inexact_constructions_kernel;
    std::vector<K::Point_2> pts;
    pts.reserve(n);
    for (std::size_t i = 0; i < n; ++i) pts.emplace_back(xy[2 * i], xy[2 * i + 1]);
    CGAL::Delaunay_triangulation_2<K> cdt;
    cdt.insert(pts.begin(), pts.end());
    out[0] = wallNow() - w0;
    out[1] = cpuNow() - c0;
    out[2] = double(cdt.number_of_faces());
    out[5] = peakMB();
#endif
    return;
  }
  // The concurrent rounds themselves, whatever the cost model would choose (Always): this
  // table measures what they cost and give.
  dt::ParallelStats ps;
  const dt::ParallelMode always = dt::ParallelMode::Always;
  const dt::FastResult r =
      threads == -3   ? dt::fastDelaunayParallel(xy, 2, {}, &ps, 2048, dt::ParallelClaim::Locks, always)
      : threads == -4 ? dt::fastDelaunayParallel(xy, 2, {}, &ps, 2048, dt::ParallelClaim::Slabs, always)
                      : dt::fastDelaunayParallel(xy, threads, {}, &ps, 2048, dt::ParallelClaim::Parts, always);
  out[0] = wallNow() - w0;
  out[1] = cpuNow() - c0;
  out[2] = double(r.tri.size());
  out[3] = double(ps.deferred);
  out[4] = double(ps.parallelPoints);
  out[5] = peakMB();
  if (check) validate(xy, r.tri);
}

// The cost model's constants (dt::ParallelModel), measured: n uniform points whose x coordinates
// are squeezed into [0, width) (width 1: the uniform square; a smaller width crowds the slabs'
// cut with triangles, by degrees), triangulated by the sequential kernel (threads 1) or by two
// threads' concurrent rounds, whatever the model would choose (threads 2). out: wall, CPU, and
// the forecast of the split for two threads (dt::forecastSplit: the share of a sample's vertices
// no slab can take, against uniform points), computed after the clock. Validated if `check`.
void modelJob(std::size_t n, double width, int threads, bool check, double* out) {
  std::vector<double> xy = dt::uniformPoints(n, 2028);
  for (std::size_t i = 0; i < xy.size(); i += 2) xy[i] *= width;
  const double w0 = wallNow(), c0 = cpuNow();
  const dt::FastResult r =
      threads == 1 ? dt::fastDelaunay(xy)
                   : dt::fastDelaunayParallel(xy, threads, {}, nullptr, 2048, dt::ParallelClaim::Parts,
                                              dt::ParallelMode::Always);
  out[0] = wallNow() - w0;
  out[1] = cpuNow() - c0;
  out[2] = dt::forecastSplit(xy, 2).ratio;
  if (check) validate(xy, r.tri);
}

// The machine's own ceiling for two threads: two sequential runs of threadsJob(n, 1) at once,
// each in a process of its own, started together. out: the later one's wall time, the CPU time
// of both, triangles, 0, 0, the larger peak. On two idle cores with nothing shared, each would
// take a lone run's time; what they take beyond it (memory bandwidth, the shared last-level
// cache, a hypervisor's other guests) no split of one triangulation between two threads avoids.
void pairJob(std::size_t n, double* out) {
  std::vector<double> a;
  std::thread other([&] { a = inChild([&](double* o) { threadsJob(n, 1, false, o); }); });
  const std::vector<double> b = inChild([&](double* o) { threadsJob(n, 1, false, o); });
  other.join();
  if (a.empty() || b.empty()) throw std::runtime_error("one of two runs at once failed");
  out[0] = std::max(a[0], b[0]);
  out[1] = a[1] + b[1];
  out[2] = a[2];
  out[5] = std::max(a[5], b[5]);
}

// The runs of the time budget (where the wall time goes, at the first n): the sequential
// kernel, the shared mesh's machinery on one thread (fastDelaunaySharedCoreAlone) with each
// claim, two threads with each claim, and two threads with the parts and their seam.
enum class Budget { Sequential, AloneSlabs, AloneLocks, TwoSlabs, TwoLocks, TwoParts };
constexpr Budget kBudgetRuns[] = {Budget::Sequential, Budget::AloneSlabs, Budget::AloneLocks,
                                  Budget::TwoSlabs, Budget::TwoLocks, Budget::TwoParts};
// Slots of budgetJob's out.
enum BudgetSlot { bWall, bCpu, bSort, bInsert, bLone, bConcurrent, bBusy, bFinish, bDeferred,
                  bParallelPoints, bTriangles, bWalkSteps, bInsertions };

// One triangulation of the n uniform points of threadsJob, timed in its parts: out[BudgetSlot]
// (the sequential kernel has no lone, concurrent, busy or finish time: left at -1).
void budgetJob(std::size_t n, Budget run, bool check, double* out) {
  const std::vector<double> xy = dt::uniformPoints(n, 2026);
  const dt::ParallelClaim claim = run == Budget::AloneLocks || run == Budget::TwoLocks
                                      ? dt::ParallelClaim::Locks
                                  : run == Budget::TwoParts ? dt::ParallelClaim::Parts
                                                            : dt::ParallelClaim::Slabs;
  dt::ParallelStats ps;
  const double w0 = wallNow(), c0 = cpuNow();
  const dt::FastResult r = run == Budget::Sequential ? dt::fastDelaunay(xy)
                           : run == Budget::AloneSlabs || run == Budget::AloneLocks
                               ? dt::fastDelaunaySharedCoreAlone(xy, {}, &ps, claim)
                               : dt::fastDelaunayParallel(xy, 2, {}, &ps, 2048, claim,
                                                          dt::ParallelMode::Always);
  out[bWall] = wallNow() - w0;
  out[bCpu] = cpuNow() - c0;
  out[bSort] = r.stats.sortSeconds;
  out[bInsert] = r.stats.insertSeconds;
  const bool shared = run != Budget::Sequential;
  out[bLone] = shared ? ps.loneSeconds : -1;
  out[bConcurrent] = shared ? ps.concurrentSeconds : -1;
  out[bBusy] = shared ? ps.busySeconds : -1;
  out[bFinish] = shared ? ps.finishSeconds : -1;
  out[bDeferred] = double(ps.deferred);
  out[bParallelPoints] = double(ps.parallelPoints);
  out[bTriangles] = double(r.tri.size());
  out[bWalkSteps] = double(r.stats.walkSteps);
  out[bInsertions] = double(r.stats.insertions);
  if (check) validate(xy, r.tri);
}

// The sequential kernel on n points, the median of `reps` runs (ch::median). out: wall, CPU, the
// CPU time of its sort (the same brioCoinOrder call, timed apart), the rest (CPU), all in seconds
// per run; peak MB after the triangulation, check seconds, peak MB after the check.
void perPointJob(std::size_t n, int reps, double* out) {
  const std::vector<double> xy = dt::uniformPoints(n, 2027);
  std::vector<dt::Tri> tri;  // the last run's triangles (one result alive at a time)
  std::vector<double> wall, cpu, sort;
  for (int k = 0; k < reps; ++k) {
    tri.clear();
    tri.shrink_to_fit();
    const double w0 = wallNow(), c0 = cpuNow();
    tri = dt::fastDelaunay(xy).tri;
    wall.push_back(wallNow() - w0);
    cpu.push_back(cpuNow() - c0);
    if (n >= 10000000) continue;  // the sort alone, timed apart (below 10^7: enough memory)
    const dt::FastOptions d;
    const double s0 = cpuNow();
    const std::vector<std::size_t> order = dt::brioCoinOrder(xy, d.seed, d.rounds);
    sort.push_back(cpuNow() - s0);
  }
  out[0] = ch::median(wall);
  out[1] = ch::median(cpu);
  if (!sort.empty()) out[2] = ch::median(sort);
  out[4] = peakMB();
  if (n >= 10000000) {  // now that the peak is read
    const dt::FastOptions d;
    const double s0 = cpuNow();
    const std::vector<std::size_t> order = dt::brioCoinOrder(xy, d.seed, d.rounds);
    out[2] = cpuNow() - s0;
  }
  out[3] = out[1] - out[2];
  const double t0 = wallNow();
  validate(xy, tri);
  out[5] = wallNow() - t0;
  out[6] = peakMB();
}

std::vector<int> parseList(const std::string& s) {
  std::vector<int> v;
  std::stringstream in(s);
  std::string item;
  while (std::getline(in, item, ',')) {
    const std::optional<long> t = ch::parseWhole(item);
    if (!t || *t < 1 || *t > 64) throw ch::UsageError("--threads: '" + item + "' is not a whole number from 1 to 64");
    v.push_back(int(*t));
  }
  if (v.empty()) throw ch::UsageError("--threads needs a list such as 1,2,4");
  return v;
}


// ---- the run's settings -------------------------------------------------------------------

// What every section reads from the options.
struct Run {
  const ch::Options& o;
  bool ownCaches;        // this machine's cache sizes, or those of --cache-dir
  std::string cacheDir;
  int reps;              // alternating runs: the median kept (the budget: the best)
  int hw;                // the machine's hardware threads
  std::vector<int> threadList;
  std::size_t maxN;
  bool haveCgal;
  std::vector<std::size_t> sizes;  // the sizes of the table against threads
  bool listsTwo() const { return std::count(threadList.begin(), threadList.end(), 2) > 0; }
};

Run runOf(const ch::Options& o) {
  // Where the cache sizes come from: this machine's, or a directory in the same format (the
  // figure test plants one whose caches all fall within its small run's sizes).
  const bool ownCaches = !o.has("--cache-dir");
  const std::string cacheDir = ownCaches ? std::string(kSysCacheDir) : o.extra.at("--cache-dir");
  const int reps = int(o.number("--reps", o.quick ? 1 : 5));
  const int hw = dt::defaultThreadCount();
  std::vector<int> threadList = {1, 2};
  if (hw > 2) threadList.push_back(hw);
  threadList.push_back(2 * std::max(2, hw));  // more threads than cores: how it degrades
  if (o.has("--threads")) threadList = parseList(o.extra.at("--threads"));
  const std::size_t maxN = o.maxN > 0 ? std::size_t(o.maxN) : (o.quick ? 100000 : 1000000);
#ifdef DT_HAVE_CGAL
  const bool haveCgal = true;
#else
  const bool haveCgal = false;
#endif
  std::vector<std::size_t> sizes = {std::min<std::size_t>(maxN, 1000000)};
  if (maxN >= 10000000) sizes.push_back(10000000);
  return {o, ownCaches, cacheDir, reps, hw, threadList, maxN, haveCgal, sizes};
}

// ---- 1. time against threads (table_parallel) ----------------------------------------------

using ch::median;

// One size of the table against threads: its runs (a thread count; -2 two sequential runs at
// once; -3 two threads with a lock per triangle; -4 with slabs; 0 CGAL), every repetition of
// each (all[j][k], in the order they ran) and the one with the median wall time (best[j]).
struct ThreadRuns {
  std::size_t n;
  std::vector<int> runs;
  std::vector<std::vector<double>> best;
  std::vector<std::vector<std::vector<double>>> all;
  std::size_t index(int run) const {
    for (std::size_t j = runs.size(); j-- > 0;)
      if (runs[j] == run) return j;
    return runs.size();
  }
  // The median run of a kind, or null when it did not run (the last, if listed twice).
  const std::vector<double>* of(int run) const {
    const std::size_t j = index(run);
    return j < runs.size() ? &best[j] : nullptr;
  }
  // The ratios of field f (0 wall, 1 CPU) of run a to run b, repetition by repetition: the two
  // ran one after the other in the same round, so a burst of load hits both. scale divides b.
  std::vector<double> paired(int a, int b, int f = 0, double scale = 1) const {
    const std::size_t i = index(a), j = index(b);
    std::vector<double> v;
    if (i == runs.size() || j == runs.size()) return v;
    for (std::size_t k = 0; k < all[i].size() && k < all[j].size(); ++k)
      v.push_back(all[i][k][std::size_t(f)] / (scale * all[j][k][std::size_t(f)]));
    return v;
  }
};

// "min-max" of some ratios.
std::string ratioSpread(const std::vector<double>& v) {
  if (v.empty()) return "-";
  return ch::fmt("%.2f", *std::min_element(v.begin(), v.end())) + "-" +
         ch::fmt("%.2f", *std::max_element(v.begin(), v.end()));
}

ThreadRuns measureThreads(const Run& s, std::size_t n) {
  const std::vector<int>& threadList = s.threadList;
  const bool haveCgal = s.haveCgal;
  const int reps = s.reps;
  std::vector<int> runs = threadList;
  // -2: two sequential runs at once (the machine's ceiling for two threads), when both one
  // and two threads are measured.
  const bool pair = std::count(runs.begin(), runs.end(), 1) && std::count(runs.begin(), runs.end(), 2);
  if (pair) runs.push_back(-2);
  if (pair) runs.push_back(-3);  // two threads on one shared mesh, a lock per triangle
  if (pair) runs.push_back(-4);  // two threads on one shared mesh, slabs
  if (haveCgal) runs.push_back(0);
  std::vector<std::vector<std::vector<double>>> all(runs.size());
  // Alternate the runs (all kernels once, then again): a burst of load hits them all.
  for (int k = 0; k < reps; ++k)
    for (std::size_t j = 0; j < runs.size(); ++j) {
      const std::vector<double> r = inChild([&](double* out) {
        if (runs[j] == -2)
          pairJob(n, out);
        else
          threadsJob(n, runs[j], k == 0, out);
      });
      if (r.empty()) throw std::runtime_error("a run failed (n = " + std::to_string(n) + ")");
      all[j].push_back(r);
    }
  // The run with the median wall time, with its CPU time, and the largest peak of all (every
  // run's triangles are the same: the first run's were validated).
  std::vector<std::vector<double>> best(runs.size());
  for (std::size_t j = 0; j < runs.size(); ++j) {
    std::vector<std::vector<double>> byWall = all[j];
    std::sort(byWall.begin(), byWall.end(),
              [](const std::vector<double>& a, const std::vector<double>& b) { return a[0] < b[0]; });
    best[j] = byWall[byWall.size() / 2];
    for (const std::vector<double>& r : all[j]) best[j][5] = std::max(best[j][5], r[5]);
  }
  return {n, runs, best, all};
}

// The verdicts on the speed targets at one size, as a paragraph (parallel_verdict.html).
void sayParallelVerdict(std::ostream& pv, const ThreadRuns& r) {
  const std::size_t n = r.n;
  const std::vector<double>*seq = r.of(1), *two = r.of(2), *pairRun = r.of(-2), *cg = r.of(0);
  if (seq && two) {
    const double wall2 = median(r.paired(2, 1));
    pv << "<p>Measured in this run at n&nbsp;=&nbsp;" << n << " (medians of the runs' ratios, "
       << "paired in turn): with 2 threads the wall time is " << ch::fmt("%.2f", wall2)
       << " of the sequential kernel's (a speedup of " << ch::fmt("%.2f", 1 / wall2)
       << "), and the CPU time " << ch::fmt("%.2f", median(r.paired(2, 1, 1))) << " of it.";
    if (pairRun) {
      const double ceiling = median(r.paired(-2, 1, 0, 2));
      pv << " Two sequential runs at once each took up to " << ch::fmt("%.2f", 2 * ceiling)
         << " times a lone run's wall time, so a perfect split of the work between the two "
            "cores could reach " << ch::fmt("%.2f", ceiling) << " of one thread's wall time on "
            "this machine (the target: at most " << ch::fmt("%.2f", kTwoTarget)
         << ", which this estimate " << (ceiling <= kTwoTarget ? "allows" : "puts out of easy reach")
         << "; the parallel kernel: " << ch::fmt("%.2f", wall2) << ", "
         << (wall2 <= kTwoTarget ? "met" : "missed") << ").";
    }
    if (cg) {
      const double w2 = (*two)[0] / (*cg)[0], c1 = (*seq)[1] / (*cg)[1];
      pv << " Against CGAL: 2 threads take " << ch::fmt("%.2f", w2)
         << " of its wall time (the target: at most 0.50, "
         << (w2 <= 0.5 ? "met" : "missed") << "); one thread takes " << ch::fmt("%.2f", c1)
         << " of its CPU time (target: at most " << ch::fmt("%.2f", kCpuTarget1) << ", "
         << (c1 <= kCpuTarget1 ? "met" : "missed")
         << ").";
    }
    pv << "</p>\n";
  }
}

// The page's values (par.*), from the largest size.
void setParallelValues(ch::Values& values, const ThreadRuns& r) {
  const std::size_t n = r.n;
  const std::vector<double>*seq = r.of(1), *two = r.of(2), *pairRun = r.of(-2), *lockRun = r.of(-3),
                            *slabRun = r.of(-4), *cg = r.of(0);
  const bool both = seq && two;
  // Ratios between kernels: the medians of the runs' ratios, paired in turn (ThreadRuns::paired).
  auto med = [&](int a, int b, int f = 0, double scale = 1) { return median(r.paired(a, b, f, scale)); };
  values.set("par.n", std::to_string(n));
  values.set("par.load", loadAverage());
  values.set("par.speedup2", both ? ch::fmt("%.2f", 1 / med(2, 1)) : "(not measured)");
  values.set("par.cpu_ratio2", both ? ch::fmt("%.2f", med(2, 1, 1)) : "(not measured)");
  values.set("par.two_verdict",
             !both ? "not measured"
                   : (med(2, 1) < 1 ? "faster than one thread" : "slower than one thread"));
  values.set("par.wall_ratio2_spread", both ? ratioSpread(r.paired(2, 1)) : "(not measured)");
  values.set("par.reps", std::to_string(both ? r.paired(2, 1).size() : 0));
  const bool ref = both && cg;
  const double w2 = ref ? med(2, 0) : 0, c1 = ref ? med(1, 0, 1) : 0;
  values.set("par.cgal_wall2", ref ? ch::fmt("%.2f", w2) : "(not measured)");
  values.set("par.cgal_cpu1", ref ? ch::fmt("%.2f", c1) : "(not measured)");
  values.set("par.target2", ref ? (w2 <= 0.5 ? "met" : "missed") : "not measured");
  values.set("par.target1", ref ? (c1 <= kCpuTarget1 ? "met" : "missed") : "not measured");
  values.num("par.target1_bound", kCpuTarget1, "%.2f");
  // The machine's ceiling for two threads, and the kernel against it.
  const bool ceil = pairRun && seq && two;
  const double ceiling = ceil ? med(-2, 1, 0, 2) : 0;
  const double wall2 = ceil ? med(2, 1) : 0;
  values.set("par.pair_slowdown", ceil ? ch::fmt("%.2f", med(-2, 1)) : "(not measured)");
  values.set("par.ceiling2", ceil ? ch::fmt("%.2f", ceiling) : "(not measured)");
  values.set("par.wall_ratio2", ceil ? ch::fmt("%.2f", wall2) : "(not measured)");
  values.num("par.two_target", kTwoTarget, "%.2f");
  values.set("par.two_target_verdict", !ceil ? "not measured" : wall2 <= kTwoTarget ? "met" : "missed");
  values.set("par.ceiling_verdict",
             !ceil ? "was not measured"
                   : ceiling <= kTwoTarget ? "allows it"
                                           : "makes it hard: two whole runs side by side already lose more");
  const bool lk = lockRun && seq;
  values.set("par.locks_wall_ratio2", lk ? ch::fmt("%.2f", med(-3, 1)) : "(not measured)");
  values.set("par.locks_cpu_extra2",
             lk ? ch::fmt("%.0f%%", 100 * (med(-3, 1, 1) - 1)) : "(not measured)");
  const bool sl = slabRun && seq;
  values.set("par.slabs_wall_ratio2", sl ? ch::fmt("%.2f", med(-4, 1)) : "(not measured)");
  values.set("par.slabs_vs_locks",
             !(lk && sl) ? "was not measured"
             : med(-4, -3, 1) < 1 ? "took less CPU time than the locks"
                                  : "did not take less CPU time than the locks");
  values.set("par.parts_vs_shared",
             !(lk && sl && two) ? "was not measured"
             : med(2, -4) < 1 && med(2, -3) < 1
                 ? "took less wall time than both designs of the shared mesh"
                 : "did not take less wall time than both designs of the shared mesh");
  values.set("par.cpu_extra2",
             ceil ? ch::fmt("%.0f%%", 100 * (med(2, 1, 1) - 1)) : "(not measured)");
}

// "min-max" of the wall times of a run's repetitions.
std::string wallSpread(const std::vector<std::vector<double>>& reps) {
  double lo = 1e300, hi = 0;
  for (const std::vector<double>& x : reps) lo = std::min(lo, x[0]), hi = std::max(hi, x[0]);
  return ch::fmt("%.3f", lo) + "-" + ch::fmt("%.3f", hi);
}

void addParallelRows(ch::Table& t, const ThreadRuns& rr) {
  const std::size_t n = rr.n;
  const std::vector<int>& runs = rr.runs;
  const std::vector<std::vector<double>>& best = rr.best;
  const std::vector<double>* cg = rr.of(0);
  for (std::size_t j = 0; j < runs.size(); ++j) {
    const std::vector<double>& r = best[j];
    const bool cgal = runs[j] == 0;
    const bool twice = runs[j] == -2, locks = runs[j] == -3, slabs = runs[j] == -4;
    t.add({std::to_string(n),
           cgal ? "CGAL 2D"
                : twice ? "fast (sequential): two runs at once"
                : locks ? "fast parallel, shared mesh, locks"
                : slabs ? "fast parallel, shared mesh, slabs"
                        : (runs[j] == 1 ? "fast (sequential)" : "fast parallel, parts and seam"),
           cgal ? "1" : twice ? "2 x 1" : locks || slabs ? "2" : std::to_string(runs[j]), ch::fmt("%.3f", r[0]),
           wallSpread(rr.all[j]), ch::fmt("%.3f", r[1]),
           rr.of(1) ? ch::fmt("%.2f", median(rr.paired(runs[j], 1))) : "-",
           rr.of(1) ? ch::fmt("%.2f", median(rr.paired(runs[j], 1, 1))) : "-",
           cg ? ch::fmt("%.2f", median(rr.paired(runs[j], 0))) : "-",
           cg ? ch::fmt("%.2f", median(rr.paired(runs[j], 0, 1))) : "-",
           cgal || twice || runs[j] == 1 ? "-" : ch::fmt("%.3f", 100 * r[3] / std::max(1.0, r[4])),
           ch::fmt("%.0f", r[5])});
  }
}

// The caption's words on the triangles of one size: the same number from every kernel, or the
// numbers, each kernel's first run validated exactly.
std::string trianglesSaid(const ThreadRuns& rr) {
  std::set<long> counts;
  for (const std::vector<double>& r : rr.best) counts.insert(long(r[2]));
  std::string out = "n = " + std::to_string(rr.n) + ": ";
  if (counts.size() == 1) return out + "every kernel gave " + std::to_string(*counts.begin()) + " triangles";
  out += "the kernels gave different numbers of triangles:";
  for (long c : counts) out += " " + std::to_string(c);
  return out;
}

void tableParallel(const Run& s, ch::Values& values) {
  const ch::Options& o = s.o;
  const int reps = s.reps, hw = s.hw;
  const std::string loadBefore = loadAverage();
  std::ostringstream pv;  // the verdicts on the speed targets, computed
  ch::Table t;
  t.header = {"n", "kernel", "threads", "wall (s)", "wall min-max (s)", "CPU (s)", "wall / 1 thread",
              "CPU / 1 thread", "wall / CGAL", "CPU / CGAL", "deferred (%)", "peak (MB)"};
  std::string triangles;  // the caption's words on the triangles of each size
  for (std::size_t n : s.sizes) {
    const ThreadRuns r = measureThreads(s, n);
    sayParallelVerdict(pv, r);
    if (n == s.sizes.back()) setParallelValues(values, r);
    addParallelRows(t, r);
    triangles += (triangles.empty() ? "" : "; ") + trianglesSaid(r);
  }
  t.caption = "Uniform random points, one process per run, runs alternated, the median wall time of " +
              std::to_string(reps) + " (with that run's CPU time, all threads) and the spread of the wall times; "
              "the ratios (to one thread, to CGAL) are the medians of the runs' ratios, paired round by round, "
              "not the ratios of the medians; the machine has " +
              std::to_string(hw) + " hardware threads; load average before / after: " +
              loadBefore + " / " + loadAverage() +
              ". Fast parallel, parts and seam: the default design, each thread triangulating one slab's "
              "points alone, then the seam merged by one thread (nothing is deferred). Shared "
              "mesh: the two earlier designs, all threads inserting into one triangulation. "
              "Deferred: concurrent insertions that met another thread's triangles (its lock, or a triangle "
              "outside the thread's slab) and were redone "
              "alone. Two runs at once: two processes of "
              "the sequential kernel started together, each on all n points; wall time of the "
              "later, CPU time of both. Triangles (each fast kernel's first run validated by "
              "dt::checkDelaunay): " + triangles + ".";
  t.emit(o, "table_parallel");
  ch::writeOut(o, "parallel_verdict.html", pv.str());
}

// ---- 1b. the time budget at the first n (table_parallel_budget) ----------------------------
  // Where the wall time goes: the sequential kernel, the parallel machinery on one thread
  // (what sharing costs with no second thread) and two threads, with each claim. Each run in
  // its own process, alternated, the best wall time of `reps` with that run's parts. The
  // two-thread runs only when --threads lists 2.
// The runs of kBudgetRuns, the best of each (empty when it did not run).
std::vector<std::vector<double>> measureBudget(const Run& s) {
  const std::size_t n = s.sizes.front();
  const bool withTwo = s.listsTwo();
  const int reps = s.reps;
  constexpr std::size_t kRuns = std::size(kBudgetRuns);
  std::vector<std::vector<double>> b(kRuns);
  for (int k = 0; k < reps; ++k)
    for (std::size_t j = 0; j < kRuns; ++j) {
      const Budget run = kBudgetRuns[j];
      if (!withTwo && (run == Budget::TwoSlabs || run == Budget::TwoLocks || run == Budget::TwoParts))
        continue;
      const std::vector<double> r = inChild([&](double* out) { budgetJob(n, run, k == 0, out); });
      if (r.empty()) throw std::runtime_error("a run of the time budget failed (n = " + std::to_string(n) + ")");
      if (b[j].empty() || r[bWall] < b[j][bWall]) b[j] = r;
    }
  return b;
}

void tableParallelBudget(const Run& s, const std::vector<std::vector<double>>& b) {
  const ch::Options& o = s.o;
  const std::size_t n = s.sizes.front();
  const int reps = s.reps, hw = s.hw;
  constexpr std::size_t kRuns = std::size(kBudgetRuns);
  const std::vector<double>& seq = b[0];
  const double seqInsertPerPoint = seq[bInsert] / double(n);
  ch::Table bt;
  bt.header = {"run", "wall (ms)", "sort (ms)", "after the sort (ms)", "lone (ms)", "concurrent rounds (ms)",
               "busy (ms)", "output (ms)", "the rest (ms)", "busy per point / sequential's",
               "walk steps per point", "deferred (%)"};
  bt.htmlParts = {{0, 1, 2, 3, 4, 5, 6}, {7, 8, 9, 10, 11}};
  // (No comma in a label or header: the .csv does not quote its cells.)
  const char* labels[] = {"sequential kernel", "shared core alone (slabs)", "shared core alone (locks)",
                          "two threads (slabs)", "two threads (locks)", "two threads (parts and seam)"};
  auto ms = [](double v) { return v < 0 ? std::string("-") : ch::fmt("%.1f", 1000 * v); };
  for (std::size_t j = 0; j < kRuns; ++j) {
    if (b[j].empty()) continue;
    const std::vector<double>& r = b[j];
    const bool shared = j > 0, concurrent = r[bParallelPoints] > 0;
    const bool parts = kBudgetRuns[j] == Budget::TwoParts;
    // The rest: what none of the kernel's clocks covers (the shared arrays' set-up, the
    // claims, the call itself). The parts sort inside their own time.
    const double rest = parts ? r[bWall] - r[bLone] - r[bConcurrent] - r[bFinish]
                        : shared ? r[bWall] - r[bSort] - r[bLone] - r[bConcurrent] - r[bFinish]
                                 : r[bWall] - r[bSort] - r[bInsert];
    bt.add({labels[j], ms(r[bWall]), ms(r[bSort]), ms(r[bInsert]), ms(r[bLone]), ms(r[bConcurrent]),
            ms(r[bBusy]), ms(r[bFinish]), ch::fmt("%.1f", 1000 * rest),
            !shared ? "1.00"
            : concurrent ? ch::fmt("%.2f", r[bBusy] / r[bParallelPoints] / seqInsertPerPoint)
                         : "-",
            ch::fmt("%.2f", r[bWalkSteps] / std::max(1.0, r[bInsertions])),
            concurrent ? ch::fmt("%.3f", 100 * r[bDeferred] / r[bParallelPoints]) : "-"});
  }
  bt.caption = "Where the wall time goes at n = " + std::to_string(n) +
               " (the uniform points of the table above): each run in its own process, runs "
               "alternated, the best wall time of " + std::to_string(reps) +
               " with that run's parts. Shared core alone: the parallel kernel's machinery "
               "(relaxed atomic access, claims, rounds, deferred insertions) run by one thread "
               "(dt::fastDelaunaySharedCoreAlone). After the sort: all the kernel does once "
               "the order is known. Lone: one thread alone, the small first rounds and the "
               "deferred insertions. Concurrent rounds: their wall time, the slabs' cuts "
               "included. Busy: the time the threads spent inside their pieces, summed over "
               "the threads. Output: the final compaction. The rest: the wall time minus sort, "
               "lone, concurrent rounds and output (the set-up of the shared arrays). Busy per "
               "point: busy time per point of the concurrent rounds, over the sequential "
               "kernel's time after the sort per point. Two threads (parts and seam): sort is the "
               "longest part's sort, inside the part's time; concurrent rounds is the parts' wall "
               "time (gathering, sorting, inserting, classifying the triangles), busy the threads' time "
               "in their parts, lone the seam (B and its triangulation, one thread), output the "
               "writing of the triangles." + machineNote(hw);
  bt.emit(o, "table_parallel_budget");
}

void setBudgetValues(const Run& s, const std::vector<std::vector<double>>& b, ch::Values& values) {
  const std::size_t n = s.sizes.front();
  const int hw = s.hw;
  const std::vector<double>&seq = b[0], &aloneS = b[1], &aloneL = b[2], &twoS = b[3], &twoL = b[4],
                            &twoP = b[5];
  // The budget's values. A perfect split: the concurrent rounds take the shared core's
  // one-thread busy time divided by the threads, everything else as measured with two
  // threads. With 4 or 8 threads this is a model, not a measurement.
  const std::string none = "(not measured)";
  auto pct = [](double x) { return ch::fmt("%.0f%%", 100 * x); };
  // (What the second thread adds and the perfect split need concurrent rounds, with one
  // thread and with two: none below a few thousand points.)
  const bool ranS = !twoS.empty(), ranL = !twoL.empty();
  const bool haveS = ranS && twoS[bParallelPoints] > 0 && aloneS[bBusy] > 0;
  const bool haveL = ranL && twoL[bParallelPoints] > 0 && aloneL[bBusy] > 0;
  auto split = [&](const std::vector<double>& two, const std::vector<double>& alone, double k) {
    return (two[bWall] - two[bConcurrent] + alone[bBusy] / k) / seq[bWall];
  };
  values.set("par.budget_n", std::to_string(n));
  // The parts and their seam: the wall ratio, the seam's share of the wall time, and a model of
  // 4 and 8 cores: the parts' busy time shared by k threads, the seam (one thread) grown with
  // the k - 1 cuts, the output shared by k threads.
  const bool ranP = !twoP.empty() && twoP[bParallelPoints] > 0;
  values.set("par.budget_wall2_parts", ranP ? ch::fmt("%.2f", twoP[bWall] / seq[bWall]) : none);
  values.set("par.budget_parts_target", !ranP ? "not measured"
                                        : twoP[bWall] / seq[bWall] <= kTwoTarget ? "met" : "missed");
  values.set("par.budget_seam_parts", ranP ? pct(twoP[bLone] / twoP[bWall]) : none);
  for (const auto& [k, key] : {std::pair{4.0, "par.budget_parts_k4"}, std::pair{8.0, "par.budget_parts_k8"}})
    values.set(key, ranP ? ch::fmt("%.2f", (twoP[bBusy] / k + twoP[bLone] * (k - 1) + twoP[bFinish] * 2 / k) /
                                               seq[bWall])
                         : none);
  values.set("par.hw_threads", std::to_string(hw));
  values.set("par.budget_share_cost", pct(aloneS[bInsert] / seq[bInsert] - 1));
  values.set("par.budget_share_cost_locks", pct(aloneL[bInsert] / seq[bInsert] - 1));
  // What the second thread adds to the busy time (signed: a second core brings its own
  // caches too, so it can be less).
  auto signedPct = [](double x) { return ch::fmt("%+.0f%%", 100 * x); };
  values.set("par.budget_second_thread", haveS ? signedPct(twoS[bBusy] / aloneS[bBusy] - 1) : none);
  values.set("par.budget_second_thread_locks", haveL ? signedPct(twoL[bBusy] / aloneL[bBusy] - 1) : none);
  values.set("par.budget_wall2", ranS ? ch::fmt("%.2f", twoS[bWall] / seq[bWall]) : none);
  values.set("par.budget_wall2_locks", ranL ? ch::fmt("%.2f", twoL[bWall] / seq[bWall]) : none);
  // The largest part outside the rounds: the sort, which two threads share too.
  values.set("par.budget_sort2", ranS ? ch::fmt("%.2f", twoS[bSort] / seq[bSort]) : none);
  values.set("par.budget_serial", ranS ? pct(1 - twoS[bConcurrent] / twoS[bWall]) : none);
  values.set("par.budget_serial_locks", ranL ? pct(1 - twoL[bConcurrent] / twoL[bWall]) : none);
  for (const auto& [k, key, keyLocks] : {std::tuple{2.0, "par.budget_best2", "par.budget_best2_locks"},
                                         std::tuple{4.0, "par.budget_k4", "par.budget_k4_locks"},
                                         std::tuple{8.0, "par.budget_k8", "par.budget_k8_locks"}}) {
    values.set(key, haveS ? ch::fmt("%.2f", split(twoS, aloneS, k)) : none);
    values.set(keyLocks, haveL ? ch::fmt("%.2f", split(twoL, aloneL, k)) : none);
  }
  // The verdicts against the target, with the claim that does better.
  auto meets = [&](double k) {
    return (haveS && split(twoS, aloneS, k) <= kTwoTarget) || (haveL && split(twoL, aloneL, k) <= kTwoTarget);
  };
  const char* either = haveS && haveL ? ", with either claim" : "";
  const std::string why = !ranS && !ranL ? "two threads were not measured"
                                         : "two threads had no concurrent round at this n";
  values.set("par.budget_best2_verdict",
             !haveS && !haveL ? "the budget cannot tell: " + why
             : meets(2) ? "a perfect split would meet it: what is missing is what the second thread adds"
                        : std::string("even a perfect split of the shared core would miss it") + either);
  values.set("par.budget_k_verdict",
             !haveS && !haveL ? "cannot be judged: " + why
             : meets(4)       ? std::string("would meet it with 4 cores")
             : meets(8)       ? std::string("would meet it with 8 cores, not with 4")
                              : std::string("would miss it even with 8 cores"));
}

// ---- 2. time per point (table_time_per_point, fig_time_per_point) --------------------------

// The curve of the chart: (n, CPU ns per point), and the peak memory at its largest n.
struct PerPoint {
  std::vector<std::pair<std::size_t, double>> curve;
  double lastPeakMB = 0;
};

PerPoint measurePerPoint(const Run& s, ch::Values& values) {
  const ch::Options& o = s.o;
  const std::size_t maxN = s.maxN;
  const int reps = s.reps;
  std::vector<std::size_t> pp;
  for (double e = 3; std::pow(10.0, e) <= double(maxN) * 1.0001; e += 0.5)
    pp.push_back(std::size_t(std::llround(std::pow(10.0, e))));
  ch::Table u;
  u.header = {"n", "CPU (ns/point)", "wall (ns/point)", "of which sort (CPU ns/point)",
              "the rest (CPU ns/point)", "peak (MB)", "peak (bytes/point)", "check, wall (s)",
              "peak with check (MB)"};
  std::ostringstream dat, large;
  dat << "# n cpu_ns wall_ns sort_ns insert_ns peakMB checkPeakMB\n";
  large << dat.str();
  std::vector<std::pair<std::size_t, double>> curve;
  double lastPeakMB = 0;
  int fewestRuns = 1 << 30;  // the least k of the chart's medians (its caption cites it)
  for (std::size_t n : pp) {
    // Small sizes are run more often, so that their median is of many short runs.
    const int r = n >= 10000000 ? 1 : std::max(reps, int(std::min<std::size_t>(200, 300000 / n)));
    fewestRuns = std::min(fewestRuns, r);
    const std::vector<double> x = inChild([&](double* out) { perPointJob(n, r, out); });
    if (x.empty()) throw std::runtime_error("time per point: the run at n = " + std::to_string(n) + " failed");
    const double k = 1e9 / double(n);
    u.add({std::to_string(n), ch::fmt("%.0f", x[1] * k), ch::fmt("%.0f", x[0] * k),
           ch::fmt("%.0f", x[2] * k), ch::fmt("%.0f", x[3] * k), ch::fmt("%.0f", x[4]),
           ch::fmt("%.0f", x[4] * 1048576.0 / double(n)), ch::fmt("%.2f", x[5]),
           ch::fmt("%.0f", x[6])});
    const std::string line = ch::fmt("%zu %.1f %.1f %.1f %.1f %.1f %.1f\n", n, x[1] * k, x[0] * k,
                                     x[2] * k, x[3] * k, x[4], x[6]);
    (n >= 10000000 ? large : dat) << line;
    curve.emplace_back(n, x[1] * k);
    lastPeakMB = x[4];
    std::cout << "n=" << n << ": " << ch::fmt("%.0f", x[1] * k) << " ns/point CPU, peak "
              << ch::fmt("%.0f", x[4]) << " MB\n";
  }
  u.caption = "The fast kernel (one thread) on uniform random points: time per point, sorting "
              "included (the median of several runs below 10^7), peak resident memory of the "
              "process (VmHWM, the points included) after the triangulation and after the exact "
              "check. Load average at the end: " + loadAverage() + ".";
  u.emit(o, "table_time_per_point");
  values.num("par.per_point_runs", fewestRuns, "%.0f");
  ch::writeOut(o, "time_per_point.dat", dat.str());
  if (maxN >= 10000000) ch::writeOut(o, "time_per_point_large.dat", large.str());
  return {curve, lastPeakMB};
}

// The cache markers of the chart and the paragraph's sentence on them: where the kernel's
// data outgrows each cache, placed in the pixels gnuplot draws (time_per_point_caches.dat,
// time_per_point_cache_lines.dat, time_per_point_view.gp).
void markCaches(const Run& s, const std::pair<std::size_t, double>& last, double lastPeakMB,
                std::ostream& v, ch::Values& values) {
  const ch::Options& o = s.o;
  const bool ownCaches = s.ownCaches;
  const std::string& cacheDir = s.cacheDir;
  // Where the kernel's memory outgrows each cache, from the bytes per point at the largest n:
  // the data and unified caches /sys (or --cache-dir) describes (sysconf's L3 size comes from
  // CPUID and on a virtual machine can be the host's), marked on the chart where they fall in
  // its n range.
  const double bytesPerPoint = lastPeakMB * 1048576.0 / double(last.first);
  const std::vector<ch::CacheSize> caches = ch::dataCaches(cacheDir);
  double nPlotted = double(last.first);  // the largest n the chart shows (an earlier large run too)
  {
    std::ifstream in(o.out + "/time_per_point_large.dat");
    for (std::string line; std::getline(in, line);)
      if (!line.empty() && line[0] != '#') nPlotted = std::max(nPlotted, std::atof(line.c_str()));
  }
  // The chart's x range (log scale): from half a decade below 10^3 to 6 % of the span beyond
  // the largest n it shows; where each marker's label goes is computed in that range.
  const double nChartLo = std::pow(10.0, 2.5);
  const double nChartHi = nPlotted * std::pow(nPlotted / nChartLo, 0.06);
  auto along = [&](double n) { return std::log(n / nChartLo) / std::log(nChartHi / nChartLo); };
  // The chart's plotting area in pixels: the script sets its margins at these screen
  // fractions (time_per_point_view.gp), so the labels are placed in the pixels gnuplot draws,
  // on both terminals. In em of the style's font (fig_em): left, the y label (centred 1 em
  // from the edge), the tick labels (up to four digits) and their tics; at the bottom, the
  // key's row (centred at 0.9 em), the x label (at 2.3 em) and the tick labels 10^k (whose
  // baseline the svg terminal sets 2.6 em under the axis); at the top, half a tick label.
  ch::FigureSize fs = ch::figureSize("fig_time_per_point");
  if (o.width > 0) fs = {double(o.width), double(o.height), fs.em / fs.W * o.width};  // --size: style.gp's em per width
  const double marginL = 5.6 * fs.em / fs.W, marginR = 1 - 0.8 * fs.em / fs.W;
  const double marginB = 6.0 * fs.em / fs.H, marginT = 1 - 0.8 * fs.em / fs.H;
  const double plotW = (marginR - marginL) * fs.W, plotH = (marginT - marginB) * fs.H;
  // The markers the chart draws: where the line is, the label, where the label is centred and
  // in which row above the lines it is (0 the lowest).
  struct Marker {
    double n;
    std::string label;
    double x;
    int row;
  };
  std::vector<Marker> markers;
  // The labels already in each row: from where to where each spans, as fractions of the width.
  std::vector<std::vector<std::pair<double, double>>> rows;
  std::vector<std::string> said;  // "11790 points (L2, 1 MiB)", one per cache
  const struct {
    int level;
    const char *kib, *n;
  } cacheKeys[] = {{1, "tpp.l1d_kib", "tpp.l1d_n"}, {2, "tpp.l2_kib", "tpp.l2_n"}, {3, "tpp.l3_kib", "tpp.l3_n"}};
  for (const auto& ck : cacheKeys) {
    const auto c = std::find_if(caches.begin(), caches.end(), [&](const ch::CacheSize& k) { return k.level == ck.level; });
    if (c == caches.end()) {
      values.set(ck.kib, "(not reported)");
      values.set(ck.n, "-");
      continue;
    }
    const double n = double(c->bytes) / bytesPerPoint;
    values.set(ck.kib, std::to_string(c->bytes / 1024));
    values.num(ck.n, n, "%.0f");
    said.push_back(ch::fmt("%.0f", n) + " points (" + c->label.substr(0, c->label.find(' ')) + ", " +
                   c->label.substr(c->label.find(' ') + 1) + ")");
    std::cout << c->label << ": the kernel's data fills it at about n = " << ch::fmt("%.0f", n) << "\n";
    if (n < nChartLo || n > nPlotted) continue;
    // The label's half width as a fraction of the chart's, with 0.3 em to spare: centred on
    // its line, moved inside the chart at its ends, in the lowest row where it meets no other
    // label (a new row when it meets one in every row: three caches close together).
    const double half = (0.5 * ch::textWidthEm(c->label) + 0.3) * fs.em / plotW;
    const double centre = std::clamp(along(n), half, 1 - half);
    auto fits = [&](const std::vector<std::pair<double, double>>& row) {
      return std::all_of(row.begin(), row.end(), [&](const std::pair<double, double>& s) {
        return centre + half < s.first || centre - half > s.second;
      });
    };
    std::size_t row = 0;
    while (row < rows.size() && !fits(rows[row])) ++row;
    if (row == rows.size()) rows.emplace_back();
    rows[row].emplace_back(centre - half, centre + half);
    markers.push_back({n, c->label, nChartLo * std::pow(nChartHi / nChartLo, centre), int(row)});
  }
  // Above the lines (y2 = 1) a band for the rows of labels, two at least (so that the chart
  // keeps its layout when the labels need one): gnuplot centres a label's ink from 0.45 em
  // above its anchor to 0.57 em below (the baseline 0.33 em below the anchor), so a row's
  // anchor is 0.9 em over the lines' top (0.33 em clear of it) and each next row 1.2 em
  // higher; y2 runs from 0 at the bottom to y2hi at the top of the plot.
  auto rowEm = [](int row) { return 0.9 + 1.2 * row; };
  const int rowCount = std::max(2, int(rows.size()));
  const double y2hi = 1 / (1 - (rowEm(rowCount - 1) + 0.45 + 0.2) * fs.em / plotH);
  std::ostringstream cacheLines, cacheLabels;
  cacheLines << "# one block per cache marker: n at y2 = 0 and at y2 = 1 (bench_parallel)\n";
  cacheLabels << "# n label y2 x (the kernel's data fills the cache at about n; its label is centred at x, "
                 "above the line's top, kept inside the chart; bench_parallel)\n";
  for (const Marker& m : markers) {
    cacheLines << ch::fmt("%.1f", m.n) << " 0\n" << ch::fmt("%.1f", m.n) << " 1\n\n";
    cacheLabels << ch::fmt("%.1f", m.n) << " \"" << m.label << "\" "
                << ch::fmt("%.4f", 1 + rowEm(m.row) * fs.em / plotH * y2hi) << " " << ch::fmt("%.1f", m.x) << "\n";
  }
  const int marked = int(markers.size());
  if (caches.empty()) {
    v << (ownCaches ? " This machine reported no cache sizes (" : " No cache sizes were read (")
      << cacheDir << " lists none), so the chart marks none.";
    values.set("tpp.caches", ownCaches ? "this machine reported no cache sizes, so the chart marks none"
                                       : "no cache sizes were read, so the chart marks none");
  } else {
    std::string list;
    for (std::size_t i = 0; i < said.size(); ++i)
      list += (i == 0 ? "" : i + 1 == said.size() ? " and " : ", ") + said[i];
    v << " At " << ch::fmt("%.0f", bytesPerPoint) << " bytes per point (the peak memory at n&nbsp;=&nbsp;"
      << last.first << "), " << (ownCaches ? "the caches of this machine (as " : "the caches (as ")
      << cacheDir << " describes them) hold the "
      << "kernel's data up to about " << list << ".";
    values.set("tpp.caches", "the caches hold the kernel's data up to about " + list);
  }
  values.num("tpp.bytes_per_point", bytesPerPoint, "%.0f");
  ch::writeOut(o, "time_per_point_cache_lines.dat", cacheLines.str());
  ch::writeOut(o, "time_per_point_caches.dat", cacheLabels.str());
  ch::writeOut(o, "time_per_point_view.gp",
               "# written by bench_parallel: the chart's x range, how many cache markers it draws, the\n"
               "# top of y2 (the lines reach 1, their labels are above) and the plot's margins (screen)\n"
               "nlo = " + ch::fmt("%.3f", nChartLo) + "\nnhi = " + ch::fmt("%.1f", nChartHi) +
                   "\nncaches = " + std::to_string(marked) + "\ny2hi = " + ch::fmt("%.4f", y2hi) +
                   "\nmarginL = " + ch::fmt("%.4f", marginL) + "\nmarginR = " + ch::fmt("%.4f", marginR) +
                   "\nmarginB = " + ch::fmt("%.4f", marginB) + "\nmarginT = " + ch::fmt("%.4f", marginT) + "\n");
}

// The chart's table, data and markers; returns its verdict (time_per_point_verdict.html).
std::string figTimePerPoint(const Run& s, ch::Values& values) {
  const PerPoint m = measurePerPoint(s, values);
  const std::vector<std::pair<std::size_t, double>>& curve = m.curve;

  // The verdict, computed: the largest n up to which the CPU time per point stays within 25 %
  // of its smallest value, and the ratio at the largest n measured.
  double lo = 1e300;
  for (const auto& c : curve) lo = std::min(lo, c.second);
  std::size_t flatUpTo = 0;
  for (const auto& c : curve) {
    if (c.second > 1.25 * lo) break;
    flatUpTo = c.first;
  }
  const auto& last = curve.back();
  std::ostringstream v;
  v << "<p>Measured in this run: the CPU time per point stays within 25&nbsp;% of its smallest "
       "value up to n&nbsp;=&nbsp;" << flatUpTo << "; at n&nbsp;=&nbsp;" << last.first
    << " it is " << ch::fmt("%.2f", last.second / lo) << " times the smallest value.";
  std::size_t steep = 1;  // the largest rise between neighbouring sizes
  for (std::size_t i = 2; i < curve.size(); ++i)
    if (curve[i].second / curve[i - 1].second > curve[steep].second / curve[steep - 1].second)
      steep = i;
  if (curve.size() > 1)
    v << " The largest rise between neighbouring sizes is a factor "
      << ch::fmt("%.2f", curve[steep].second / curve[steep - 1].second) << ", from n&nbsp;=&nbsp;"
      << curve[steep - 1].first << " to n&nbsp;=&nbsp;" << curve[steep].first << ".";
  markCaches(s, last, m.lastPeakMB, v, values);
  v << "</p>\n";
  values.set("tpp.flat_up_to", std::to_string(flatUpTo));
  values.set("tpp.n_last", std::to_string(last.first));
  values.num("tpp.ratio_last", last.second / lo, "%.2f");
  // The page's words for that ratio: computed here, with the same quarter as flat_up_to.
  values.verdict("tpp.trend", last.second > 1.25 * lo, "rises by more than a quarter",
                 "stays within a quarter of its smallest value");
  if (curve.size() > 1) {
    values.num("tpp.steep", curve[steep].second / curve[steep - 1].second, "%.2f");
    values.set("tpp.steep_from", std::to_string(curve[steep - 1].first));
    values.set("tpp.steep_to", std::to_string(curve[steep].first));
  } else {
    values.set("tpp.steep", "(one size only)");
    values.set("tpp.steep_from", "-");
    values.set("tpp.steep_to", "-");
  }
  return v.str();
}

// ---- 3. the cost model's constants, measured (table_thread_constants) ----------------------
  // (Last: its runs grow this process, and a child forked later starts from that size, so
  // the time-per-point chart's peak memory, whose bytes per point place the cache markers,
  // is measured before them.)
  // The two constants dt::ParallelModel decides with, measured here, where two threads (the
  // concurrent rounds, forced) run against the sequential kernel, in turn, paired run by run
  // (the median of the paired wall-time ratios, and their spread):
  //  - the break-even size: uniform points at sizes up to the largest n of section 1; the
  //    smallest size from which two threads beat one at that size and every larger one;
  //  - the bound on the forecast: points squeezed in x by degrees (modelJob) at that largest
  //    n; the largest forecast ratio up to which two threads beat one on every width.
  // Each against the constant of the code: the verdicts say whether the model's size and bound
  // are on the safe side of what this run measured. Only when --threads lists 2.
void tableThreadConstants(const Run& s, ch::Values& values) {
  if (!s.listsTwo()) {
    for (const char* k : {"model.n", "model.reps", "model.break_even_n", "model.break_even_per_thread",
                          "model.bound_measured", "model.first_loss", "model.size_verdict",
                          "model.bound_verdict"})
      values.set(k, "(not measured: --threads did not list 2)");
    values.set("model.code_size", std::to_string(2 * dt::ParallelModel::minPointsPerThread));
    values.num("model.code_bound", dt::ParallelModel::maxCutShareRatio, "%g");
    return;
  }
  const ch::Options& o = s.o;
  const int reps = s.reps, hw = s.hw;
  const std::size_t nTop = s.sizes.front();
  const int mreps = std::max(3, reps);
  std::vector<std::size_t> ladder;
  for (std::size_t n : {10000u, 30000u, 100000u, 200000u, 400000u, 600000u, 1000000u})
    if (n < nTop) ladder.push_back(n);
  ladder.push_back(nTop);
  const std::vector<double> widths = {1, 1e-1, 1e-2, 1e-3, 1e-4, 1e-6};
  // One case: (n, width); the runs of both kernels, alternated.
  struct Case {
    std::size_t n;
    double width;
    std::vector<double> ratios;  // wall, two threads / one thread, run by run
    double forecast = 0;
  };
  std::vector<Case> cases;
  for (std::size_t n : ladder) cases.push_back({n, 1.0, {}, 0});
  for (double w : widths)
    if (w < 1) cases.push_back({nTop, w, {}, 0});
  for (int k = 0; k < mreps; ++k)
    for (Case& c : cases) {
      std::vector<double> wall(3);
      for (int threads : {1, 2}) {
        const std::vector<double> r =
            inChild([&](double* out) { modelJob(c.n, c.width, threads, k == 0, out); });
        if (r.empty())
          throw std::runtime_error("a run of the model's constants failed (n = " + std::to_string(c.n) + ")");
        wall[std::size_t(threads)] = r[0];
        c.forecast = r[2];
      }
      c.ratios.push_back(wall[2] / wall[1]);
    }
  ch::Table mc;
  mc.header = {"measures", "n", "x squeezed to", "forecast / uniform", "2 threads / 1 (wall)",
               "min-max", "2 threads beat 1"};
  // The break-even: the smallest size of the ladder from which every median ratio is below 1.
  std::size_t breakEven = 0;
  for (std::size_t i = ladder.size(); i-- > 0;) {
    if (ch::median(cases[i].ratios) >= 1) break;
    breakEven = ladder[i];
  }
  // The bound: the largest forecast ratio up to which every width's median ratio is below 1
  // (the widths sorted by their forecast; the uniform set at nTop included).
  std::vector<const Case*> byForecast;
  for (const Case& c : cases)
    if (c.n == nTop) byForecast.push_back(&c);
  std::stable_sort(byForecast.begin(), byForecast.end(),
            [](const Case* a, const Case* b) { return a->forecast < b->forecast; });
  double bound = 0, firstLoss = 0;
  for (const Case* c : byForecast) {
    if (ch::median(c->ratios) >= 1) {
      firstLoss = c->forecast;
      break;
    }
    bound = c->forecast;
  }
  for (const Case& c : cases) {
    const double m = ch::median(c.ratios);
    mc.add({c.width == 1 && c.n != nTop ? "size" : c.width == 1 ? "size and split" : "split",
            std::to_string(c.n), c.width == 1 ? "1 (uniform)" : ch::fmt("%g", c.width),
            ch::fmt("%.2f", c.forecast), ch::fmt("%.2f", m), ch::spread(c.ratios, "%.2f"),
            m < 1 ? "yes" : "no"});
  }
  mc.caption = "The cost model's two constants, measured: two threads (the parts and their seam, "
               "whatever the model would choose) against the sequential kernel, each run in its "
               "own process, in turn, " + std::to_string(mreps) +
               " runs each; the median of the paired wall-time ratios and their spread "
               "(min-max). Size: uniform points in the unit square. Split: the same number "
               "of points with x squeezed into [0, w), so that more and more triangles cross "
               "the slabs' cut; forecast: dt::forecastSplit for two threads, the share of a "
               "sample's vertices on a triangle across the cut or on the hull over uniform points'." + machineNote(hw);
  mc.emit(o, "table_thread_constants");
  const std::size_t modelSize = 2 * dt::ParallelModel::minPointsPerThread;
  values.set("model.n", std::to_string(nTop));
  values.set("model.reps", std::to_string(mreps));
  values.set("model.break_even_n",
             breakEven ? std::to_string(breakEven) : "(not reached up to " + std::to_string(nTop) + ")");
  values.set("model.break_even_per_thread",
             breakEven ? std::to_string(breakEven / 2) : "(not reached)");
  values.set("model.code_size", std::to_string(modelSize));
  // (The page: "the model's size ... is @{model.size_verdict}", likewise for the bound.)
  values.set("model.size_verdict",
             breakEven == 0 ? (modelSize > nTop ? "not judged: two threads did not pay at any size measured, all below it"
                                                : "too small: two threads did not pay at any size measured, it included")
             : modelSize >= breakEven ? "on the safe side: at and above it, two threads paid"
                                      : "too small: between it and the measured break-even, two threads lost");
  values.set("model.bound_measured", bound > 0 ? ch::fmt("%.2f", bound) : "(none measured)");
  values.set("model.first_loss", firstLoss > 0 ? ch::fmt("%.2f", firstLoss) : "(none measured)");
  values.num("model.code_bound", dt::ParallelModel::maxCutShareRatio, "%g");
  const double codeBound = dt::ParallelModel::maxCutShareRatio;
  values.set("model.bound_verdict",
             bound == 0 ? "not judged: two threads did not pay even on uniform points at this size"
             : firstLoss > 0 && codeBound >= firstLoss
                 ? "too loose: a set whose forecast was within it was slower with two threads"
             : codeBound <= bound ? "on the safe side: every set whose forecast was within it was faster with two threads"
                                  : "not fully tested: no set measured had a forecast between the largest that paid and it, and none within it lost");
}

}  // namespace

int main(int argc, char** argv) {
  const ch::Program p{"bench_parallel",
                      "The parallel kernel against threads, and time per point (--max-n 100000000: up to 10^8).",
                      1000, 100000000, {"fig_time_per_point"},
                      {{"--reps", "N", "alternating runs: the median kept, the time budget the best (default 5, 1 with --quick)", 1, 1000},
                       {"--threads", "LIST", "thread counts to measure, e.g. 1,2,4 (each 1 to 64)"},
                       {"--cache-dir", "DIR",
                        "read the cache sizes the chart marks from DIR (index*/level, type, size, as Linux "
                        "writes them) instead of " + std::string(kSysCacheDir)}}};
  // The values of its own options, checked before --out is created.
  const auto check = [](const ch::Options& o) {
    if (o.has("--cache-dir") && !std::filesystem::is_directory(o.extra.at("--cache-dir")))
      throw ch::UsageError("--cache-dir: '" + o.extra.at("--cache-dir") + "' is not a directory");
    if (o.has("--threads")) parseList(o.extra.at("--threads"));
  };
  return ch::runMain(argc, argv, p, [&](const ch::Options& o) -> int {
    const Run s = runOf(o);
    ch::Values values(o, "bench_parallel");  // the values of the page's prose
    tableParallel(s, values);
    const std::vector<std::vector<double>> budget = measureBudget(s);
    tableParallelBudget(s, budget);
    setBudgetValues(s, budget, values);
    const std::string verdict = figTimePerPoint(s, values);
    tableThreadConstants(s, values);  // last: see its comment
    values.write();
    ch::writeOut(o, "time_per_point_verdict.html", verdict);
    ch::runGnuplot(o, "fig_time_per_point.gp");
    return 0;
  }, check);
}
