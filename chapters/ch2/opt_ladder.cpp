// opt_ladder: from the corrected listings to the fast kernel, one change at a time, each step
// timed (CPU time) on the same 10^6 uniform random points in the same run (sorting included). Every step
// produces the same triangulation (checked: same triangle count, and the last step is validated
// exactly). Writes table_ladder.{md,csv,html} and ladder.dat, and draws fig_ladder_time.
//
//   opt_ladder [--out DIR] [--quick] [--max-n N] [--no-plot] [--reps R]
//     --quick    10^5 points, one repetition
//     --max-n N  the number of points (default 10^6)
//     --reps R   repetitions of each step, the fastest is kept (default 2)
#include <time.h>

#include <chrono>
#include <iostream>
#include <random>
#include <string>
#include <vector>

#include "check.h"
#include "common.h"
#include "timing.h"
#include "fast_delaunay.h"
#include "fast_ladder.h"
#include "hilbert.h"
#include "triangulate.h"

namespace {

// CPU time of this process (user + system): on a shared machine it counts only this process's
// work, so ratios measured in one run stay meaningful when other jobs compete for the cores.
double cpuSeconds() {
  timespec ts;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

// A rung of the fast kernel: the insertion core (fast_core.h) with some of the listings'
// features put back as its policies (fast_ladder.h), in one of its two builds.
using Kernel = dt::FastResult (*)(const std::vector<double>&, const dt::FastOptions&);

namespace fast = dt::fast;
constexpr fast::Build kBaseline{false, false};       // build for every x86-64, last-cavity start
constexpr fast::Build kBaselineNear{false, true};    // and the start near the last point

dt::FastResult mapCentroid(const std::vector<double>& xy, const dt::FastOptions& o) {
  return fast::withCalledPredicates<fast::CentroidWalk, fast::MapLink>(xy, o, kBaseline);
}
dt::FastResult centroid(const std::vector<double>& xy, const dt::FastOptions& o) {
  return fast::withCalledPredicates<fast::CentroidWalk>(xy, o, kBaseline);
}
dt::FastResult called(const std::vector<double>& xy, const dt::FastOptions& o) {
  return fast::withCalledPredicates<>(xy, o, kBaseline);
}
dt::FastResult calledNear(const std::vector<double>& xy, const dt::FastOptions& o) {
  return fast::withCalledPredicates<>(xy, o, kBaselineNear);
}
dt::FastResult inlined(const std::vector<double>& xy, const dt::FastOptions& o) {
  return fast::oneThread<fast::InlinePredicates>(xy, o, kBaselineNear);
}

struct Step {
  const char* name;    // short label (figure)
  const char* change;  // what this step changes
  bool listings;       // the pointer-based corrected listings
  dt::FastOptions opt;
  Kernel kernel;       // otherwise this rung of the fast kernel
};

struct Run {
  double seconds = 0;
  std::size_t triangles = 0;
  double walk = 0, cavity = 0;
};

Run runStep(const Step& s, const std::vector<double>& xy) {
  Run r;
  const double t0 = cpuSeconds();
  if (s.listings) {
    const std::vector<std::size_t> order = dt::hilbertOrder(xy);
    dt::Triangulation T;
    std::vector<dt::Vertex*> S;
    S.reserve(order.size());
    for (std::size_t i : order) S.push_back(T.addVertex(xy[2 * i], xy[2 * i + 1], long(i)));
    dt::InsertionStats st;
    dt::delaunayTrglHull(T, S, dt::StartRule::LastCavity, &st);
    r.seconds = cpuSeconds() - t0;
    r.triangles = T.numFiniteFaces();
    r.walk = st.meanSearch();
    r.cavity = st.meanCavity();
  } else {
    const dt::FastResult f = s.kernel(xy, s.opt);
    r.seconds = cpuSeconds() - t0;
    r.triangles = f.tri.size();
    r.walk = double(f.stats.walkSteps) / double(f.stats.insertions);
    r.cavity = double(f.stats.cavityFaces) / double(f.stats.insertions);
  }
  return r;
}

}  // namespace

int main(int argc, char** argv) {
  const ch::Program p{"opt_ladder", "The optimisation ladder of the fast kernel, one change per step.",
                      1000, 10000000, {"fig_ladder_time"},
                      {{"--reps", "N", "runs per step, their median kept (default 3, 1 with --quick)", 1, 1000}}};
  const ch::Options o = ch::parseOptions(argc, argv, p);
  const int reps = int(o.number("--reps", o.quick ? 1 : 3));
  const std::size_t n = o.maxN > 0 ? std::size_t(o.maxN) : (o.quick ? 100000 : 1000000);
  std::mt19937_64 rng(o.seed(2026));
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<double> xy(2 * n);
  for (double& v : xy) v = u(rng);

  std::vector<Step> steps;
  dt::FastOptions f;
  f.order = dt::InsertionOrder::Hilbert;
  // Every step in the build for every x86-64 processor but the last.
  steps.push_back({"listings", "corrected listings: pointers, std::map, centroid walk; Hilbert "
                   "order, walk from the last cavity (the setting of Table 2.2)", true, f, mapCentroid});
  steps.push_back({"arrays", "index-based triangles in contiguous arrays (3 vertices, 3 "
                   "neighbour half-edges: 24 bytes per triangle)", false, f, mapCentroid});
  steps.push_back({"no map", "no std::map: each new triangle finds its neighbour among the "
                   "few cavity boundary edges", false, f, centroid});
  steps.push_back({"walk", "orientation-only visibility walk that skips its entry edge (no "
                   "incircle, no centroid)", false, f, called});
  steps.push_back({"start", "each walk starts in the new triangle around the last point that "
                   "faces the next one, not in the last new triangle", false, f, calledNear});
  steps.push_back({"inline", "the predicate core (predicates_inline.h) inlined, without the "
                   "library's counters", false, f, inlined});
  f.order = dt::InsertionOrder::BrioDoubling;
  steps.push_back({"BRIO", "BRIO order (dt::brioOrder): no skinny hull triangles, smaller "
                   "cavities", false, f, inlined});
  f.order = dt::InsertionOrder::Brio;
  steps.push_back({"coin BRIO", "BRIO rounds by a biased coin (dt::brioCoinOrder: 3/4 of the "
                   "points in the last round; a coarser curve, dt::brioCoinDepth)", false, f, inlined});
  // The last step changes no line of the kernel: it is the library's fastDelaunay, whose
  // insertions run in their second build, for x86-64-v3 processors (code/fast/fast_core.h),
  // where this processor has it.
  const bool v3 = fast::hasV3();
  steps.push_back({"x86-64-v3", v3 ? "the same insertion loops compiled for x86-64-v3 processors "
                                     "(AVX2, BMI2; no fused multiply-add), chosen at run time"
                                   : "the build for x86-64-v3 processors, which this processor is "
                                     "not: the same build again",
                   false, f, dt::fastDelaunay});

  std::cout << "opt_ladder: " << n << " uniform random points, median of " << reps << "\n";
  ch::Progress progress("opt_ladder", steps.size() * std::size_t(reps));
  std::vector<Run> med(steps.size());
  std::uint64_t done = 0;
  for (std::size_t k = 0; k < steps.size(); ++k) {
    std::vector<double> seconds;
    for (int r = 0; r < reps; ++r) {
      const Run x = runStep(steps[k], xy);
      if (r == 0) med[k] = x;  // the counts are the same in every run
      seconds.push_back(x.seconds);
      progress.update(++done);
    }
    med[k].seconds = ch::median(seconds);
    std::cout << steps[k].name << ": " << ch::fmt("%.3f s", med[k].seconds) << "\n";
  }
  // The last step's triangulation, validated exactly; every step must agree on the count.
  const dt::FastResult last = steps.back().kernel(xy, steps.back().opt);
  const dt::CheckReport check = dt::checkDelaunay(xy, last.tri);
  bool same = check.ok;
  for (const Run& r : med) same = same && r.triangles == last.tri.size();
  if (!same) {
    std::cerr << "opt_ladder: the steps disagree or the result is invalid: " << check.error << "\n";
    return 1;
  }

  ch::Table t;
  t.caption = "The optimisation ladder: " + std::to_string(n) +
              " uniform random points, CPU time (user + system), sorting included, median of " +
              std::to_string(reps) +
              " runs, all steps in the same run (each row adds one change to the row above)";
  t.header = {"step", "change", "CPU time (s)", "speedup vs previous", "speedup vs listings",
              "walk steps", "cavity"};
  std::string dat = "# step name seconds speedup_total\n";
  for (std::size_t k = 0; k < steps.size(); ++k) {
    const double prev = med[k ? k - 1 : 0].seconds, first = med[0].seconds;
    t.add({std::to_string(k), steps[k].change, ch::fmt("%.3f", med[k].seconds),
           k ? ch::fmt("%.2f", prev / med[k].seconds) : "-",
           ch::fmt("%.2f", first / med[k].seconds), ch::fmt("%.2f", med[k].walk),
           ch::fmt("%.2f", med[k].cavity)});
    dat += std::to_string(k) + " \"" + steps[k].name + "\" " + ch::fmt("%.4f", med[k].seconds) +
           " " + ch::fmt("%.3f", first / med[k].seconds) + "\n";
  }
  t.emit(o, "table_ladder");
  ch::writeOut(o, "ladder.dat", dat);
  // What the fast-kernel page says of the steps, from this run: the walk step (3), its start
  // (4), the inlined predicates (5), the cavities before (5) and after (6) the BRIO order, and
  // the x86-64-v3 build (8).
  ch::Values v(o, "opt_ladder");
  v.num("ladder.reps", reps, "%.0f");  // the caption of fig_ladder_time cites it
  auto gainWord = [](double g, double band) {
    return g > 1 + band ? "a gain" : (g < 1 - band ? "a loss" : "about even");
  };
  const double walkGain = med[2].seconds / med[3].seconds;
  const double startGain = med[3].seconds / med[4].seconds;
  const double inlineGain = med[4].seconds / med[5].seconds;
  v.num("ladder.walk_speedup", walkGain, "%.2f");
  v.set("ladder.walk_verdict", gainWord(walkGain, 0.1));
  v.num("ladder.start_speedup", startGain, "%.2f");
  v.set("ladder.start_verdict", gainWord(startGain, 0.01));
  v.num("ladder.start_walk_before", med[3].walk, "%.2f");
  v.num("ladder.start_walk_after", med[4].walk, "%.2f");
  v.num("ladder.inline_speedup", inlineGain, "%.2f");
  v.verdict("ladder.inline_verdict", inlineGain < 1.1, "worth little", "worth having");
  v.num("ladder.hilbert_cavity", med[5].cavity, "%.2f");
  v.num("ladder.brio_cavity", med[6].cavity, "%.2f");
  const double v3Gain = med[7].seconds / med[8].seconds;
  v.num("ladder.v3_speedup", v3Gain, "%.2f");
  v.set("ladder.v3_verdict", !v3 ? "not available on this processor"
                                 : gainWord(v3Gain, 0.01));
  v.write();
  ch::runGnuplot(o, "fig_ladder_time.gp");
  return 0;
}
