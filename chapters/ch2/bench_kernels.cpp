// bench_kernels: the corrected listings (Hilbert order), the fast kernel and, when it is
// installed, CGAL's Delaunay_triangulation_2, on the same point sets (uniform, clustered, grid,
// circle; one far outlier, a cluster of width 1e-9 beside uniform points, log-uniform radii
// (2.3.5, the adaptive order); exponents spread over the double range, 10^300 beside 10^-300
// (2.3.1, the extended-exponent stage)). Each run is a child process, so its peak memory (ru_maxrss) is its own; the CPU time
// covers everything from the coordinates to the triangulation (sorting included). Writes
// table_bench.{md,csv,html}.
//
// The fast kernel runs sequentially, with as many threads as the machine has where the cost
// model of code/fast/fast_parallel.h lets them run (what `--threads auto` does), and with them
// forced; CPU time sums the threads, so the parallel gain shows in the wall time. The methods
// run in turn, A B C D A B C D ..., so that a burst of load hits them all; each timing is the
// median of the runs with their spread (min-max), and the threads' ratios to one thread are
// taken run by run. Writes table_thread_model.{md,csv,html} too: the cost model's forecast
// and decision for each set beside the measured ratios. The fast kernels' results are
// validated exactly (dt::checkDelaunay, in the first repetition) after the timing; the peak
// is taken before the check.
//
//   bench_kernels [--out DIR] [--quick] [--max-n N] [--reps R]
//     --quick     10^4 and 10^5 points, three repetitions
//     --max-n N   largest size (default 10^6; 10^7 adds the 10^7 row, several minutes;
//                 10^8 adds uniform points at 10^8 for the fast kernels only, about 10 GB)
//     --reps R    repetitions per run, the median is kept (default 5; 1 from 10^7)
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
#include <iterator>
#include <random>
#include <string>
#include <vector>

#include "check.h"
#include "common.h"
#include "fast_delaunay.h"
#include "fast_parallel.h"
#include "generators.h"
#include "hilbert.h"
#include "triangulate.h"
#include "timing.h"

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

enum class Family { Uniform, Clustered, Grid, Circle, Outlier, ClusterBeside, LogRadius,
                    ExponentSpread, Mixed300 };
const char* familyName(Family f) {
  switch (f) {
    case Family::Uniform: return "uniform";
    case Family::Clustered: return "clustered";
    case Family::Grid: return "grid";
    case Family::Circle: return "circle";
    case Family::Outlier: return "outlier";
    case Family::ClusterBeside: return "cluster 1e-9";
    case Family::LogRadius: return "log radius";
    case Family::ExponentSpread: return "exponent spread";
    default: return "1e+-300";
  }
}
// Exponent spread: 2.3.1's GMP-heavy case; 20,000 points whatever the size asked.
constexpr std::size_t kSpreadPoints = 20000;  // the exponent spread's one size

std::size_t familySize(Family f, std::size_t n) {
  return f == Family::ExponentSpread ? std::min(n, kSpreadPoints) : n;
}

// Whether the set is measured at the size n of the run's sizes: every set at every size, but the
// exponent spread, whose size is fixed, once, at the first size that reaches it (or the last).
bool measuredAt(Family f, std::size_t n, const std::vector<std::size_t>& sizes) {
  if (f != Family::ExponentSpread) return true;
  for (std::size_t s : sizes)
    if (s >= kSpreadPoints || s == sizes.back()) return n == s;
  return false;
}

double wallSeconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

std::string loadAverage() {
  double a[3] = {0, 0, 0};
  if (FILE* f = std::fopen("/proc/loadavg", "r")) {
    if (std::fscanf(f, "%lf %lf %lf", &a[0], &a[1], &a[2]) != 3) a[0] = a[1] = a[2] = 0;
    std::fclose(f);
  }
  return ch::fmt("%.2f %.2f %.2f", a[0], a[1], a[2]);
}

enum class Method { Listings, Fast, FastParallel, FastForced, Cgal };
std::string methodName(Method m) {
  switch (m) {
    case Method::Listings: return "listings + Hilbert";
    case Method::Fast: return "fast kernel";
    case Method::FastParallel:
      return "fast kernel, up to " + std::to_string(dt::defaultThreadCount()) + " threads (cost model)";
    case Method::FastForced:
      return "fast kernel, " + std::to_string(dt::defaultThreadCount()) + " threads forced";
    default: return "CGAL 2D";
  }
}
bool isFast(Method m) {
  return m == Method::Fast || m == Method::FastParallel || m == Method::FastForced;
}

// The point sets, from fixed seeds. Grid: the integer points of a square (about n of them,
// shuffled), all degenerate; circle: n points on the unit circle, rounded (nearly cocircular).
std::vector<double> makePoints(Family f, std::size_t n) {
  const std::uint64_t seed = 20260 + unsigned(f);
  switch (f) {  // the families of generators.h
    case Family::Outlier: return dt::outlierPoints(n, seed, 1e12);
    case Family::ClusterBeside: return dt::clusterBesideUniform(n, seed, 1e-9);
    case Family::LogRadius: return dt::logRadiusPoints(n, seed, 1e-6, 1e6);
    case Family::ExponentSpread: return dt::exponentSpreadPoints(n, seed, -1070, 1019);
    case Family::Mixed300: {  // half uniform in [-1, 1)^2 10^300, half 10^-300, shuffled
      std::vector<double> p = dt::uniformPoints(n / 2, seed, -1e300, 1e300);
      const std::vector<double> q = dt::uniformPoints(n - n / 2, seed + 1, -1e-300, 1e-300);
      p.insert(p.end(), q.begin(), q.end());
      dt::shufflePoints(p, seed + 2);
      return p;
    }
    default: break;
  }
  std::mt19937_64 rng(seed);
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

// One triangulation; returns the number of finite triangles. The fast kernels' triangles go to
// `tri`, for the exact check after the timing, and what the threads did to `ps`.
long triangulate(Method m, const std::vector<double>& xy, std::vector<dt::Tri>& tri,
                 dt::ParallelStats& ps) {
  if (isFast(m)) {
    const int threads = m == Method::Fast ? 1 : dt::defaultThreadCount();
    const dt::ParallelMode mode =
        m == Method::FastForced ? dt::ParallelMode::Always : dt::ParallelMode::WherePays;
    tri = dt::fastDelaunayParallel(xy, threads, {}, &ps, 2048, dt::ParallelClaim::Parts, mode).tri;
    return long(tri.size());
  }
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
  double wall = 0;
  long triangles = 0;
  long peakKB = 0;
  std::size_t points = 0;
  int threadsUsed = 1;
  dt::ParallelReason reason = dt::ParallelReason::OneRequested;
  double cutShare = 0, cutRatio = 0;  // the cost model's forecast (0: not made)
  double decisionSeconds = 0;
};

// Runs one method in a child process: the child builds the points, triangulates, reports time
// and count through a pipe; the parent reads the child's peak resident memory from wait4.
constexpr int kOut = 10;
Measure runChild(Method m, Family f, std::size_t n, bool check) {
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
    double out[kOut] = {0, -1, 0, 0, 0, 1, 0, 0, 0, 0};
    try {
      const std::vector<double> xy = makePoints(f, n);
      std::vector<dt::Tri> tri;
      dt::ParallelStats ps;
      const double t0 = cpuSeconds(), w0 = wallSeconds();
      const long count = triangulate(m, xy, tri, ps);
      out[0] = cpuSeconds() - t0;
      out[3] = wallSeconds() - w0;
      out[4] = double(dt::peakResidentKB());
      out[2] = double(xy.size() / 2);
      out[5] = ps.threadsUsed;
      out[6] = double(int(ps.reason));
      // The forecast for the model's table even where the size decided first (after the clock).
      const dt::SplitForecast fc = m == Method::FastParallel && ps.forecast.cutShare == 0
                                       ? dt::forecastSplit(xy, std::max(2, dt::defaultThreadCount()))
                                       : ps.forecast;
      out[7] = fc.cutShare;
      out[8] = fc.ratio;
      out[9] = ps.decisionSeconds;
      if (check && isFast(m)) {
        const dt::CheckReport c = dt::checkDelaunay(xy, tri);
        if (!c.ok) throw std::runtime_error("exact check failed: " + c.error);
      }
      out[1] = double(count);
    } catch (const std::exception& e) {
      std::cerr << methodName(m) << " on " << familyName(f) << ": " << e.what() << "\n";
    }
    const ssize_t w = write(fd[1], out, sizeof out);
    _exit(w == ssize_t(sizeof out) ? 0 : 1);
  }
  close(fd[1]);
  double in[kOut] = {0, -1, 0, 0, 0, 1, 0, 0, 0, 0};
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
  r.wall = in[3];
  r.peakKB = in[4] > 0 ? long(in[4]) : ru.ru_maxrss;  // before the check when it was read
  r.threadsUsed = int(in[5]);
  r.reason = dt::ParallelReason(int(in[6]));
  r.cutShare = in[7];
  r.cutRatio = in[8];
  r.decisionSeconds = in[9];
  return r;
}

// The median of some values (timing.h) and their spread (common.h).
using ch::median;
using ch::spread;

// The runs of one method on one set: each run's measure, and their medians (peak: the largest).
struct Runs {
  std::vector<Measure> all;
  bool ok() const { return !all.empty() && all.back().ok; }
  std::vector<double> cpu() const {
    std::vector<double> v;
    for (const Measure& x : all) v.push_back(x.seconds);
    return v;
  }
  std::vector<double> wall() const {
    std::vector<double> v;
    for (const Measure& x : all) v.push_back(x.wall);
    return v;
  }
  Measure summary() const {
    Measure m = all.back();
    m.seconds = median(cpu());
    m.wall = median(wall());
    for (const Measure& x : all) m.peakKB = std::max(m.peakKB, x.peakKB);
    return m;
  }
};

// Run by run, the wall time of a against b (the same repetition: run next to each other).
std::vector<double> pairedRatios(const Runs& a, const Runs& b) {
  std::vector<double> r;
  for (std::size_t k = 0; k < a.all.size() && k < b.all.size(); ++k)
    if (a.all[k].ok && b.all[k].ok && b.all[k].wall > 0) r.push_back(a.all[k].wall / b.all[k].wall);
  return r;
}


// ---- the run's settings -------------------------------------------------------------------

// What every part of the run reads from the options.
struct Bench {
  const ch::Options& o;
  int reps;                        // runs per kernel, the median kept
  std::vector<std::size_t> sizes;
  std::vector<Method> methods;
  bool haveCgal;                   // CGAL is the reference of the ratios, else the listings
  int cores;
  std::size_t verdictN;            // the largest n below 10^8: the page's targets are judged there
};

Bench benchOf(const ch::Options& o) {
  const int reps = int(o.number("--reps", o.quick ? 3 : 5));
  std::vector<std::size_t> sizes = o.quick ? std::vector<std::size_t>{10000, 100000}
                                           : std::vector<std::size_t>{10000, 100000, 1000000};
  const std::size_t maxN = o.maxN > 0 ? std::size_t(o.maxN) : (o.quick ? 100000 : 1000000);
  if (maxN >= 10000000) sizes.push_back(10000000);
  if (maxN >= 100000000) sizes.push_back(100000000);
  std::vector<Method> methods = {Method::Listings, Method::Fast, Method::FastParallel,
                                 Method::FastForced};
#ifdef DT_HAVE_CGAL
  methods.push_back(Method::Cgal);
  const bool haveCgal = true;
  std::cout << "CGAL " << CGAL_VERSION_STR << " found: it is the reference of the ratios\n";
#else
  const bool haveCgal = false;
  std::cout << "CGAL not found at build time: ratios are to the corrected listings\n";
#endif
  const int cores = dt::defaultThreadCount();
  std::size_t verdictN = 0;
  for (std::size_t n : sizes)
    if (n < 100000000) verdictN = n;
  return {o, reps, sizes, methods, haveCgal, cores, verdictN};
}

const Family kFamilies[] = {Family::Uniform,   Family::Clustered,     Family::Grid,
                            Family::Circle,    Family::Outlier,       Family::ClusterBeside,
                            Family::LogRadius, Family::ExponentSpread, Family::Mixed300};
// The margin a ratio of the threads to one thread may exceed 1 by.
constexpr double kNoise = 1.05;
// The targets the verdicts compare with, named once: the book cites these same values.
constexpr double kSpeedBound = 2.0, kMemoryBound = 0.5, kFamilyBound = 1.2, kListingsBound = 4.0;

// What the page's values gather over all sets and sizes.
struct Tally {
  // The threads (as the model chose) against one thread: the runs in which they beat it, the
  // worst median ratio and where, the sets they lost on beyond the noise, the model's share of
  // the wall time on uniform points.
  std::size_t pairsBeat = 0, pairs = 0;
  double worstTwo = 0, decisionShare = 0;
  std::string worstTwoFamily, lostOn;
  // Where the model ran one thread, the same kernel ran in both columns: a ratio beyond the
  // noise there is the machine's, unless the decision itself (its forecast) cost that much. The
  // sets where that happened, and the largest share of the wall time a decision took there.
  std::string sameKernelOn;
  double worstOneDecision = 0;
  std::size_t worstTwoN = 0;
  // For the page's targets: at the largest n where CGAL runs (not at 10^8; a family measured
  // at one size only: there), the speed-up on uniform points, the worst time and peak ratios
  // of the fast kernel, and the listings' worst time ratio (all to CGAL).
  double uniformSpeedup = 0, worstFast = 0, worstPeak = 0, worstListings = 0;
  std::string worstListingsFamily, winsOn, losesOn, worstPeakFamily;
  long worstPeakN = 0, familiesCompared = 0;
};

// ---- the tables (table_bench, table_thread_model) ------------------------------------------

ch::Table benchTable(const Bench& b) {
  const int reps = b.reps;
  const bool haveCgal = b.haveCgal;
  ch::Table t;
  t.caption = std::string("Kernels on the same points, one process per run, the kernels in turn, "
                          "median of ") +
              std::to_string(reps) +
              " runs and their spread, min-max (the listings at 10^6 and beyond: one run; CPU "
              "time, user + system, from the coordinates to the triangles, sorting included; "
              "peak: the whole process, points included; ratios to " +
              (haveCgal ? "CGAL" : "the listings") +
              "; wall: elapsed time of the same run, load average " + loadAverage() +
              " at the start; the fast kernels' triangles are validated exactly)";
  t.header = {"points", "n", "kernel", "CPU time (s)", "CPU min-max", "time ratio", "wall (s)",
              "wall min-max", "wall ratio", "peak (MB)", "peak ratio", "threads used", "triangles",
              "same count"};
  // On the page, two tables of the same rows: fourteen columns were wider than the text column.
  t.htmlParts = {{0, 1, 2, 3, 4, 5, 6, 7, 8}, {0, 1, 2, 9, 10, 11, 12, 13}};
  return t;
}

// The cost model's table: its forecast and decision on each set, against the measured ratios.
ch::Table threadModelTable(const Bench& b) {
  const int cores = b.cores;
  ch::Table mt;
  mt.caption = "The cost model of the parallel kernel on bench_kernels' sets (this run): the share "
               "of a sample's vertices on a triangle across the parts' cut or on the hull, against uniform points "
               "(computed for every set; it decides only at the model's size and above), "
               "the threads it chose of " + std::to_string(cores) +
               " and why, and the wall time of " + std::to_string(cores) +
               " threads against one, median and spread of the runs paired in turn, forced and as "
               "the model chose. Where the model chose one thread, both columns ran the sequential "
               "kernel and only the decision differs: a ratio beyond the margin there is marked "
               "the same kernel (noise) when the decision took less than the margin of the wall "
               "time";
  mt.header = {"points", "n", "cut share", "against uniform", "threads used", "reason",
               "forced / 1 thread", "forced min-max", "model / 1 thread", "model min-max",
               "model slower than 1 thread by over 5 %"};
  return mt;
}

// One set (a family at a size): the runs of each kernel in `ran`, in turn (repetition k of every
// kernel before repetition k + 1 of any).
std::vector<Runs> runSet(const Bench& b, Family f, std::size_t n, const std::vector<Method>& ran,
                         ch::Progress& progress, std::uint64_t& done) {
  const int reps = b.reps;
  // In turn: repetition k of every method before repetition k + 1 of any.
  std::vector<Runs> runsOf(ran.size());
  for (int k = 0; k < reps; ++k)
    for (std::size_t j = 0; j < ran.size(); ++j) {
      const Method m = ran[j];
      // The listings at 10^6 and beyond take long, and everything at 10^7: once is enough.
      const int r = (n >= 10000000 || (m == Method::Listings && n >= 1000000)) ? 1 : reps;
      if (k >= r || (k > 0 && !runsOf[j].ok())) continue;
      if (n >= 100000000) std::cout << "running " << methodName(m) << " at 10^8..." << std::endl;
      // Validated once (the first repetition): the same points every time.
      runsOf[j].all.push_back(runChild(m, f, familySize(f, n), k == 0));
      if (k + 1 == std::min(r, reps) || !runsOf[j].ok()) progress.update(++done);
    }
  return runsOf;
}

// The set's rows of table_bench (medians, ratios to the reference) and the targets' tallies.
void addBenchRows(const Bench& b, Family f, std::size_t n, const std::vector<Method>& ran,
                  const std::vector<Runs>& runsOf, ch::Table& t, Tally& tally) {
  const bool haveCgal = b.haveCgal;
  const std::size_t verdictN = b.verdictN;
  std::vector<Measure> res;
  for (const Runs& r : runsOf) res.push_back(r.ok() ? r.summary() : r.all.back());
  // The reference: CGAL if present, else the listings; none at 10^8 (neither runs there).
  const Measure* base = nullptr;
  for (std::size_t k = 0; k < ran.size(); ++k)
    if (ran[k] == (haveCgal ? Method::Cgal : Method::Listings)) base = &res[k];
  const bool ratios = base && base->ok;
  for (std::size_t k = 0; k < ran.size(); ++k) {
    const Measure& x = res[k];
    bool same = x.ok;
    for (const Measure& y : res) same = same && y.ok && y.triangles == x.triangles;
    t.add({familyName(f), std::to_string(x.points), methodName(ran[k]),
           x.ok ? ch::fmt("%.3f", x.seconds) : "failed",
           x.ok ? spread(runsOf[k].cpu(), "%.3f") : "-",
           x.ok && ratios ? ch::fmt("%.2f", x.seconds / base->seconds) : "-",
           x.ok ? ch::fmt("%.3f", x.wall) : "-",
           x.ok ? spread(runsOf[k].wall(), "%.3f") : "-",
           x.ok && ratios ? ch::fmt("%.2f", x.wall / base->wall) : "-",
           ch::fmt("%.0f", double(x.peakKB) / 1024),
           ratios && base->peakKB > 0 ? ch::fmt("%.2f", double(x.peakKB) / double(base->peakKB))
                                      : "-",
           isFast(ran[k]) && x.ok ? std::to_string(x.threadsUsed) : "-",
           std::to_string(x.triangles), same ? "yes" : "NO"});
    const bool lastSize = n == verdictN || familySize(f, verdictN) < verdictN;
    if (haveCgal && lastSize && x.ok && ratios && ran[k] != Method::Cgal) {
      const double tr = x.seconds / base->seconds;
      if (ran[k] == Method::Fast) {
        std::string& list = tr < 1.0 ? tally.winsOn : tally.losesOn;
        list += std::string(list.empty() ? "" : ", ") + familyName(f);
        if (f == Family::Uniform) tally.uniformSpeedup = base->seconds / x.seconds;
        tally.worstFast = std::max(tally.worstFast, tr);
        ++tally.familiesCompared;
        if (base->peakKB > 0 && double(x.peakKB) / double(base->peakKB) > tally.worstPeak) {
          tally.worstPeak = double(x.peakKB) / double(base->peakKB);
          tally.worstPeakFamily = familyName(f);
          tally.worstPeakN = long(x.points);
        }
      } else if (ran[k] == Method::Listings && tr > tally.worstListings) {
        tally.worstListings = tr;
        tally.worstListingsFamily = familyName(f);
      }
    }
    std::cout << familyName(f) << " n=" << x.points << " " << methodName(ran[k]) << ": "
              << ch::fmt("%.3f s CPU, %.3f s wall, %.0f MB", x.seconds, x.wall,
                         double(x.peakKB) / 1024)
              << "\n";
  }
}

// The set's row of table_thread_model: the threads against one thread, run by run, as the model
// chose and forced.
void addThreadModelRow(const Bench& b, Family f, std::size_t n, const std::vector<Method>& ran,
                       const std::vector<Runs>& runsOf, ch::Table& mt, Tally& tally) {
  const std::size_t verdictN = b.verdictN;
  const double noise = kNoise;
  const Runs *one = nullptr, *model = nullptr, *forced = nullptr;
  for (std::size_t k = 0; k < ran.size(); ++k) {
    if (!runsOf[k].ok()) continue;
    if (ran[k] == Method::Fast) one = &runsOf[k];
    if (ran[k] == Method::FastParallel) model = &runsOf[k];
    if (ran[k] == Method::FastForced) forced = &runsOf[k];
  }
  if (one && model) {
    const std::vector<double> mr = pairedRatios(*model, *one);
    const std::vector<double> fr = forced ? pairedRatios(*forced, *one) : std::vector<double>{};
    for (double r : mr) tally.pairsBeat += r < 1.0;
    tally.pairs += mr.size();
    const double med = median(mr);
    const Measure& d = model->all.front();  // the decision is the same in every run
    if (med > tally.worstTwo) {
      tally.worstTwo = med;
      tally.worstTwoFamily = familyName(f);
      tally.worstTwoN = d.points;
    }
    std::vector<double> shares;
    for (const Measure& x : model->all) shares.push_back(x.decisionSeconds / x.wall);
    // One thread chosen: only the decision differs from the column of one thread.
    const bool sameKernel = d.threadsUsed == 1 && median(shares) < noise - 1;
    if (d.threadsUsed == 1) tally.worstOneDecision = std::max(tally.worstOneDecision, median(shares));
    std::string& list = sameKernel ? tally.sameKernelOn : tally.lostOn;
    if (med > noise)
      list += std::string(list.empty() ? "" : ", ") + familyName(f) + " at " + std::to_string(d.points);
    if (f == Family::Uniform && n == verdictN)
      tally.decisionShare = median([&] {
        std::vector<double> v;
        for (const Measure& x : model->all) v.push_back(x.decisionSeconds / x.wall);
        return v;
      }());
    // The points the set has (a grid has the square nearest n: fewer than n, perhaps).
    mt.add({familyName(f), std::to_string(d.points),
            d.cutShare > 0 ? ch::fmt("%.3f", d.cutShare) : "-",
            d.cutShare > 0 ? ch::fmt("%.2f", d.cutRatio) : "-",
            std::to_string(d.threadsUsed), dt::parallelReasonName(d.reason),
            fr.empty() ? "-" : ch::fmt("%.2f", median(fr)), spread(fr, "%.2f"),
            ch::fmt("%.2f", med), spread(mr, "%.2f"),
            med <= noise ? "no" : sameKernel ? "yes: the same kernel (noise)" : "yes"});
  }
}

  // The two rows of the threads: how often they beat one thread, and their worst median ratio.
void addThreadRows(ch::Table& t, const Tally& tally) {
  const std::string threadsName = methodName(Method::FastParallel);
  t.add({"all sets", "all sizes", threadsName + ": runs faster than 1 thread (wall)", "-", "-",
         "-", "-", "-",
         tally.pairs ? ch::fmt("%zu", tally.pairsBeat) + " of " + std::to_string(tally.pairs) : "-", "-", "-", "-",
         "-", "-"});
  t.add({"all sets", "all sizes", threadsName + ": worst median wall ratio to 1 thread", "-", "-",
         "-", "-", "-",
         tally.pairs ? ch::fmt("%.2f", tally.worstTwo) + " (" + tally.worstTwoFamily + ", " +
                     std::to_string(tally.worstTwoN) + ")"
               : "-",
         "-", "-", "-", "-", "-"});
}

void writeKernelValues(const Bench& b, const Tally& tally) {
  const ch::Options& o = b.o;
  const int reps = b.reps, cores = b.cores;
  const std::size_t verdictN = b.verdictN;
  const bool haveCgal = b.haveCgal;
  const double noise = kNoise, speedBound = kSpeedBound, memoryBound = kMemoryBound,
               familyBound = kFamilyBound, listingsBound = kListingsBound;
  ch::Values v(o, "bench_kernels");
  v.set("kernel.n", std::to_string(verdictN));
  v.num("kernel.speed_bound", speedBound, "%g");
  v.num("kernel.memory_bound", memoryBound, "%g");
  v.num("kernel.family_bound", familyBound, "%g");
  v.num("kernel.listings_bound", listingsBound, "%g");
  // The cost model's inputs (fast_parallel.h) and what it gave in this run.
  v.set("threads.cores", std::to_string(cores));
  v.set("threads.reps", std::to_string(reps));
  v.set("threads.min_points_per_thread", std::to_string(dt::ParallelModel::minPointsPerThread));
  v.set("threads.sample_size", std::to_string(dt::ParallelModel::sampleSize));
  v.num("threads.max_ratio", dt::ParallelModel::maxCutShareRatio, "%g");
  v.num("threads.uniform_cut_share",
        dt::forecastSplit(makePoints(Family::Uniform, 4096), std::max(2, cores)).uniformCutShare,
        "%.3f");
  v.num("threads.noise_percent", 100 * (noise - 1), "%.0f");
  v.set("threads.beat", std::to_string(tally.pairsBeat));
  v.set("threads.pairs", std::to_string(tally.pairs));
  v.num("threads.worst_ratio", tally.worstTwo, "%.2f");
  v.set("threads.worst_family", tally.worstTwoFamily.empty() ? "none" : tally.worstTwoFamily);
  v.set("threads.worst_n", std::to_string(tally.worstTwoN));
  v.num("threads.decision_percent", 100 * tally.decisionShare, "%.2f");
  v.set("threads.decision_n", std::to_string(verdictN));
  v.verdict("threads.lost_verdict", tally.lostOn.empty(),
            "never slower than one thread beyond the noise margin",
            "slower than one thread beyond the noise margin");
  v.set("threads.lost_on", tally.lostOn.empty() ? "none" : tally.lostOn);
  v.set("threads.same_kernel_on", tally.sameKernelOn.empty() ? "none" : tally.sameKernelOn);
  v.num("threads.one_decision_percent", 100 * tally.worstOneDecision, "%.2f");
  if (haveCgal && tally.uniformSpeedup > 0) {
    v.num("kernel.uniform_speedup", tally.uniformSpeedup, "%.2f");
    v.verdict("kernel.speed_target", tally.uniformSpeedup >= speedBound, "met", "missed");
    v.num("kernel.worst_peak", tally.worstPeak, "%.2f");
    v.set("kernel.worst_peak_family", tally.worstPeakFamily);
    v.set("kernel.worst_peak_n", std::to_string(tally.worstPeakN));
    v.set("kernel.families", std::to_string(tally.familiesCompared));
    v.verdict("kernel.memory_target", tally.worstPeak <= memoryBound, "met", "missed");
    v.num("kernel.worst_time", tally.worstFast, "%.2f");
    v.verdict("kernel.family_target", tally.worstFast <= familyBound, "met", "missed");
    v.num("kernel.worst_listings", tally.worstListings, "%.2f");
    v.set("kernel.worst_listings_family", tally.worstListingsFamily);
    v.verdict("kernel.listings_target", tally.worstListings <= listingsBound, "met", "missed");
    v.set("kernel.wins_on", tally.winsOn.empty() ? "none" : tally.winsOn);
    v.set("kernel.loses_on", tally.losesOn.empty() ? "none" : tally.losesOn);
  } else {
    for (const char* k : {"kernel.uniform_speedup", "kernel.worst_peak", "kernel.worst_time",
                          "kernel.worst_listings", "kernel.worst_listings_family",
                          "kernel.worst_peak_family", "kernel.worst_peak_n", "kernel.families",
                          "kernel.wins_on", "kernel.loses_on"})
      v.set(k, "(not measured: CGAL was not found at build time)");
    for (const char* k : {"kernel.speed_target", "kernel.memory_target", "kernel.family_target",
                          "kernel.listings_target"})
      v.set(k, "not measured");
  }
  v.write();
}

}  // namespace

int main(int argc, char** argv) {
  const ch::Program p{"bench_kernels",
                      "The kernels against CGAL on nine point families (no figure); --max-n 10000000 adds 10^7, 100000000 adds 10^8.",
                      1000, 100000000, {},
                      {{"--reps", "N", "runs per kernel, the median kept (default 5, 3 with --quick)", 1, 1000}}};
  const ch::Options o = ch::parseOptions(argc, argv, p);
  const Bench b = benchOf(o);
  ch::Table t = benchTable(b), mt = threadModelTable(b);
  Tally tally;
  std::uint64_t runs = 0;
  for (std::size_t n : b.sizes)
    for (Family f : kFamilies)
      if (measuredAt(f, n, b.sizes) && (n < 100000000 || f == Family::Uniform))
        runs += n >= 100000000 ? 2 : b.methods.size();
  ch::Progress progress("bench_kernels", runs);
  std::uint64_t done = 0;
  for (std::size_t n : b.sizes) {
    for (Family f : kFamilies) {
      if (!measuredAt(f, n, b.sizes)) continue;  // a set of one size: measured once
      // 10^8: the fast kernels on uniform points only (CGAL and the listings would take long).
      if (n >= 100000000 && f != Family::Uniform) continue;
      std::vector<Method> ran;
      for (Method m : b.methods)
        if (n < 100000000 || m == Method::Fast || m == Method::FastParallel) ran.push_back(m);
      const std::vector<Runs> runsOf = runSet(b, f, n, ran, progress, done);
      addBenchRows(b, f, n, ran, runsOf, t, tally);
      addThreadModelRow(b, f, n, ran, runsOf, mt, tally);
    }
  }
  addThreadRows(t, tally);
  t.emit(o, "table_bench");
  mt.emit(o, "table_thread_model");
  writeKernelValues(b, tally);
  return 0;
}
