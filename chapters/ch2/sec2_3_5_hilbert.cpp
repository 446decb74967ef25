// Section 2.3.5: Hilbert curves, the Hilbert sort, Table 2.2, and BRIO.
//
// Regenerates Figure 2.11 (H1, H2 and the local frames x0, b, r of Listing 2.8), Figure 2.12
// (10^3 and 10^4 points joined in Hilbert order), Table 2.2 (delaunayTrgl on Hilbert-sorted
// random points, super-triangles, walk started in the previous cavity), the effect of the curve
// depth, the cost of the keys against the sort, BRIO against Hilbert-only and random order
// on four kinds of input, and the fixed grid against the adaptive order on a far outlier, a
// tiny cluster and log-uniform radii (the outlier figure).
//
//   sec2_3_5_hilbert [--out DIR] [--quick] [--max-n N] [--huge] [--no-plot]
//     --huge   add n = 10^7 to Table 2.2 (about 2 GB of memory and a minute or two)
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <iostream>
#include <numeric>
#include <sstream>
#include <string>
#include <vector>

#include "check.h"
#include "common.h"
#include "timing.h"
#include "generators.h"
#include "hilbert.h"
#include "triangulate.h"

namespace {

using Clock = std::chrono::steady_clock;
using dt::XY;

// ---- one measured triangulation ------------------------------------------------------------

enum class Order { Random, Hilbert, Brio, HilbertFixed };
const char* orderName(Order o) {
  return o == Order::Random ? "random"
                            : (o == Order::Hilbert ? "Hilbert"
                                                   : (o == Order::Brio ? "BRIO"
                                                                       : "Hilbert, fixed grid"));
}

struct Run {
  double tSort = 0, tTotal = 0;  // seconds: ordering, and ordering + insertions
  double nSearch = 0, nCavity = 0;
  bool checked = false;
};

// delaunayTrgl with two super-triangles (2.2.1) and the start rule LastCavity; the input order
// of `p` is already random, so Order::Random inserts the points as they come.
Run triangulate(const XY& p, Order order, int depth, bool check, std::uint64_t seed = 7) {
  Run r;
  const std::size_t n = p.size() / 2;
  const auto t0 = Clock::now();
  std::vector<std::size_t> idx;
  if (order == Order::Hilbert || order == Order::HilbertFixed) {
    idx = dt::hilbertOrder(p, depth, order == Order::Hilbert);
  } else if (order == Order::Brio) {
    idx = dt::brioOrder(p, seed, depth);
  } else {
    idx.resize(n);
    std::iota(idx.begin(), idx.end(), std::size_t{0});
  }
  r.tSort = ch::secondsSince(t0);
  double xmin = p[0], xmax = p[0], ymin = p[1], ymax = p[1];
  for (std::size_t i = 0; i < n; ++i) {
    xmin = std::min(xmin, p[2 * i]); xmax = std::max(xmax, p[2 * i]);
    ymin = std::min(ymin, p[2 * i + 1]); ymax = std::max(ymax, p[2 * i + 1]);
  }
  dt::Triangulation T;
  dt::initSuperTriangles(T, xmin, ymin, xmax, ymax);
  std::vector<dt::Vertex*> S;
  S.reserve(n);
  for (std::size_t k : idx) S.push_back(T.addVertex(p[2 * k], p[2 * k + 1], long(k)));
  dt::InsertionStats st;
  const auto t1 = Clock::now();
  dt::delaunayTrgl(T, S, dt::StartRule::LastCavity, &st);
  r.tTotal = r.tSort + ch::secondsSince(t1);
  r.nSearch = st.meanSearch();
  r.nCavity = st.meanCavity();
  if (check) {
    const dt::CheckReport rep = dt::checkTriangulation(T);
    if (!rep.ok || st.insertions + st.duplicates != n)
      throw std::runtime_error("exact check failed: " + rep.error);
    r.checked = true;
  }
  return r;
}

// The runs a chart's timing is the median of: 3, 1 with --quick (its caption cites the value
// s235.time_runs; figures/ch2/timings.txt).
int timingRuns(const ch::Options& o) { return o.quick ? 1 : 3; }

// triangulate `runs` times on the same points: the median of each timing (ch::median), the
// counts and the exact check of the first run (every run inserts in the same order).
Run medianRun(int runs, const XY& p, Order order, int depth, bool check) {
  Run r = triangulate(p, order, depth, check);
  std::vector<double> sort{r.tSort}, total{r.tTotal};
  for (int k = 1; k < runs; ++k) {
    const Run x = triangulate(p, order, depth, false);
    sort.push_back(x.tSort), total.push_back(x.tTotal);
  }
  r.tSort = ch::median(sort);
  r.tTotal = ch::median(total);
  return r;
}

std::string sci(std::size_t n) {
  const int e = int(std::lround(std::log10(double(n))));
  if (std::size_t(std::llround(std::pow(10.0, e))) == n) return "10^" + std::to_string(e);
  return std::to_string(n);
}

// ---- Figure 2.11 ---------------------------------------------------------------------------

void figure211(const ch::Options& o) {
  const dt::HilbertFrame root{0.5, 0.5, 0.5, 0, 0, 0.5};  // red = +x, blue = +y (half-sides)
  for (int k = 1; k <= 2; ++k) {
    const int m = 1 << k;
    struct Cell {
      std::uint64_t key;
      std::string row;
      double x, y;
    };
    std::vector<Cell> cells;
    int bits[2];
    for (int i = 0; i < m; ++i)
      for (int j = 0; j < m; ++j) {
        const double x = (i + 0.5) / m, y = (j + 0.5) / m;
        dt::HilbertCoord(x, y, root.x0, root.y0, root.xRed, root.yRed, root.xBlue, root.yBlue, k,
                         bits);
        std::ostringstream s;
        s << x << " " << y << " \"(" << bits[0];
        if (k == 2) s << ", " << bits[1];
        s << ")\"";
        cells.push_back({dt::hilbertPack(bits, k), s.str(), x, y});
      }
    std::sort(cells.begin(), cells.end(), [](const Cell& a, const Cell& b) { return a.key < b.key; });
    std::ostringstream curve;
    curve << "# x y label lx ly: cell centres of H" << k << " in the order of Listing 2.8, and where\n"
          << "# each cell's label goes: above or below its centre, away from its quadrant's centre\n"
          << "# (where the frame's arrows are); if the curve leaves the centre that way, beside the\n"
          << "# curve, away from the quadrant's centre. So no two cells' labels meet across a\n"
          << "# quadrant's side.\n";
    const double cs = 1.0 / m;  // a cell's side
    auto quadCentre = [&](double v) { return k == 1 ? 0.5 : std::floor(v * 2) / 2 + 0.25; };
    for (std::size_t c = 0; c < cells.size(); ++c) {
      const double x = cells[c].x, y = cells[c].y, sy = y > quadCentre(y) ? 1 : -1, sx = x > quadCentre(x) ? 1 : -1;
      bool blocked = false;  // the curve leaves (x, y) vertically towards the label
      for (const std::size_t nb : {c - 1, c + 1})
        if (nb < cells.size() && std::fabs(cells[nb].x - x) < 1e-9 && (cells[nb].y - y) * sy > 0) blocked = true;
      const double lx = blocked ? x + sx * 0.4 * cs : x, ly = y + sy * 0.28 * cs;
      curve << cells[c].row << " " << lx << " " << ly << "\n";
    }
    ch::writeOut(o, "fig2_11_h" + std::to_string(k) + ".dat", curve.str());
    // The frames that Listing 2.8 uses to number these cells: the root for H1, its four
    // children (hilbertChild, the same update as HilbertCoord) for H2.
    std::vector<dt::HilbertFrame> frames = {root};
    if (k == 2) frames = {dt::hilbertChild(root, 0), dt::hilbertChild(root, 1),
                          dt::hilbertChild(root, 2), dt::hilbertChild(root, 3)};
    std::ostringstream fr;
    fr << "# x0 y0 xRed yRed xBlue yBlue\n";
    for (const auto& f : frames)
      fr << f.x0 << " " << f.y0 << " " << f.xRed << " " << f.yRed << " " << f.xBlue << " "
         << f.yBlue << "\n";
    ch::writeOut(o, "fig2_11_frames" + std::to_string(k) + ".dat", fr.str());
  }
  ch::runGnuplot(o, "fig2_11.gp");
}

// ---- Figure 2.12 ---------------------------------------------------------------------------

void figure212(const ch::Options& o, ch::Values& v) {
  for (std::size_t n : {std::size_t(1000), std::size_t(10000)}) {
    const XY p = dt::uniformPoints(n, o.seed(2012 + n));
    const std::vector<std::size_t> idx = dt::hilbertOrder(p);
    // Tour lengths, sorted and in input order, for the page's sentence on Figure 2.12.
    double sorted = 0, input = 0;
    for (std::size_t r = 1; r < n; ++r) {
      sorted += std::hypot(p[2 * idx[r]] - p[2 * idx[r - 1]], p[2 * idx[r] + 1] - p[2 * idx[r - 1] + 1]);
      input += std::hypot(p[2 * r] - p[2 * r - 2], p[2 * r + 1] - p[2 * r - 1]);
    }
    if (n == 10000) {
      v.num("s235.tour_sqrt", sorted / std::sqrt(double(n)), "%.2f");
      v.num("s235.tour_input", input / double(n), "%.2f");
      v.set("s235.tour_n", sci(n));
    }
    std::ostringstream s;
    s << "# x y rank: " << n << " random points in Hilbert order (depth "
      << dt::hilbertAutoDepth(n) << ")\n";
    for (std::size_t r = 0; r < n; ++r)
      s << p[2 * idx[r]] << " " << p[2 * idx[r] + 1] << " " << r << "\n";
    ch::writeOut(o, "fig2_12_" + std::to_string(n) + ".dat", s.str());
  }
  ch::runGnuplot(o, "fig2_12.gp");
}

// ---- Table 2.2 -----------------------------------------------------------------------------

void table22(const ch::Options& o, const std::vector<std::size_t>& sizes,
             std::size_t checkLimit, ch::Values& v) {
  double nsLo = 1e300, nsHi = 0;
  std::vector<std::pair<std::size_t, double>> cav;
  std::vector<double> usPerPoint;  // the column t/n, for the prose's verdict on linear time
  struct NotesRow { double ns, nc, t; };
  const NotesRow notes[] = {{2.34, 4.06, 0.0097}, {2.46, 4.13, 0.090}, {2.50, 4.16, 0.92},
                            {2.50, 4.17, 9.2}};
  ch::Table tab;
  tab.caption = "Table 2.2 regenerated: delaunayTrgl on n uniform random points in the unit "
                "square, Hilbert-sorted (hilbertOrder, curve depth ceil(log4 n) + 8), two "
                "super-triangles, each walk started from a face of the previous cavity "
                "(StartRule::LastCavity). t = sort + insertions (wall clock, this machine); "
                "the notes' values on the right.";
  tab.header = {"n", "depth", "N_search", "N_cavity", "t (s)", "t sort (s)", "t/n (us)",
                "checked", "notes N_search", "notes N_cavity", "notes t (s)"};
  std::ostringstream dat;
  dat << "# n nsearch ncavity t tsort us_per_point\n";
  ch::Progress prog("Table 2.2", sizes.size());
  std::size_t done = 0;
  for (std::size_t n : sizes) {
    const XY p = dt::uniformPoints(n, 22 + n);
    const Run r = triangulate(p, Order::Hilbert, 0, n <= checkLimit);
    const int e = int(std::lround(std::log10(double(n))));
    std::vector<std::string> row = {sci(n), std::to_string(dt::hilbertAutoDepth(n)),
                                    ch::fmt("%.2f", r.nSearch), ch::fmt("%.2f", r.nCavity),
                                    ch::fmt("%.3g", r.tTotal), ch::fmt("%.3g", r.tSort),
                                    ch::fmt("%.2f", 1e6 * r.tTotal / double(n)),
                                    r.checked ? "exact" : "no"};
    if (e >= 3 && e <= 6 && sci(n).rfind("10^", 0) == 0) {
      const NotesRow& nr = notes[e - 3];
      row.insert(row.end(), {ch::fmt("%.2f", nr.ns), ch::fmt("%.2f", nr.nc), ch::fmt("%.3g", nr.t)});
    } else {
      row.insert(row.end(), {"", "", ""});
    }
    tab.add(row);
    dat << n << " " << r.nSearch << " " << r.nCavity << " " << r.tTotal << " " << r.tSort << " "
        << 1e6 * r.tTotal / double(n) << "\n";
    nsLo = std::min(nsLo, r.nSearch);
    nsHi = std::max(nsHi, r.nSearch);
    cav.push_back({n, r.nCavity});
    usPerPoint.push_back(1e6 * r.tTotal / double(n));
    prog.update(++done);
    if (n == sizes.back()) {
      // The notes: "sorting over a million points takes less than a second", and the sort's
      // n log n is negligible. Measured at the largest size of this run.
      const double bound = 1.0;  // seconds, the notes' bound
      v.set("s235.sort_n", sci(n));
      v.num("s235.sort_seconds", r.tSort, "%.3g");
      v.num("s235.sort_total_seconds", r.tTotal, "%.3g");
      v.num("s235.sort_share_of_total", 100 * r.tSort / r.tTotal, "%.1f%%");
      v.num("s235.sort_bound", bound, "%g");
      v.set("s235.sort_second_verdict",
            n < 1000000 ? std::string("not tested at a million points in this run (`--max-n 1000000` or the full run does)")
                        : r.tSort < bound ? std::string("confirmed") : std::string("not confirmed on this machine"));
      v.verdict("s235.sort_negligible", r.tSort < 0.1 * r.tTotal, "small beside the insertions (under a tenth)",
                "not small beside the insertions (a tenth or more)");
    }
  }
  if (!cav.empty()) {
    v.num("s235.t22_ns_lo", nsLo, "%.2f");
    v.num("s235.t22_ns_hi", nsHi, "%.2f");
    v.verdict("s235.t22_ns_verdict", nsHi < 1.5 * nsLo, "stays about constant", "grows");
    v.set("s235.t22_n_first", sci(cav.front().first));
    v.set("s235.t22_n_last", sci(cav.back().first));
    v.num("s235.t22_cav_first", cav.front().second, "%.2f");
    v.num("s235.t22_cav_last", cav.back().second, "%.2f");
    const double decades = std::log10(double(cav.back().first) / double(cav.front().first));
    v.num("s235.t22_cav_per_decade", decades > 0 ? (cav.back().second - cav.front().second) / decades : 0.0, "%.2f");
    v.verdict("s235.t22_cav_verdict", cav.front().second > 4.3, "does not stay", "stays");
    // Linear time keeps t/n constant; three ways, as the measured ratio says.
    const double usFirst = usPerPoint.front(), usLast = usPerPoint.back();
    v.num("s235.t22_us_first", usFirst, "%.2f");
    v.num("s235.t22_us_last", usLast, "%.2f");
    v.num("s235.t22_us_ratio", usLast / usFirst, "%.2f");
    v.trend("s235.t22_us_trend", usFirst, usLast);
  }
  tab.emit(o, "table2_2");
  ch::writeOut(o, "table2_2.dat", dat.str());
}

// ---- depth -----------------------------------------------------------------------------------

void depthTable(const ch::Options& o, std::size_t n) {
  const XY pu = dt::uniformPoints(n, 35);
  const XY pc = dt::gaussianClusters(n, 36);
  const int autoDepth = dt::hilbertAutoDepth(n);
  std::vector<int> depths = {2, 4, 6, 8, 10, 12, 31};
  if (std::find(depths.begin(), depths.end(), autoDepth) == depths.end()) depths.push_back(autoDepth);
  std::sort(depths.begin(), depths.end());
  ch::Table tab;
  tab.caption = "How the curve depth d changes the counts (n = " + sci(n) +
                ", Hilbert order on the fixed grid, without the adaptive refinement, "
                "super-triangles, LastCavity). With 4^d << n many points share a cell and keep "
                "their random order: the walks grow. The auto depth is " +
                std::to_string(autoDepth) + ".";
  tab.header = {"depth d", "4^d / n", "uniform N_search", "uniform N_cavity", "uniform t (s)",
                "clustered N_search", "clustered N_cavity", "clustered t (s)"};
  std::ostringstream dat;
  dat << "# depth nsU ncU tU nsC ncC tC\n";
  ch::Progress prog("depth table", depths.size());
  std::size_t done = 0;
  for (int d : depths) {
    const Run u = triangulate(pu, Order::HilbertFixed, d, true);
    const Run c = triangulate(pc, Order::HilbertFixed, d, true);
    tab.add({std::to_string(d) + (d == autoDepth ? " (auto)" : ""),
             ch::fmt("%.3g", std::pow(4.0, d) / double(n)), ch::fmt("%.2f", u.nSearch),
             ch::fmt("%.2f", u.nCavity), ch::fmt("%.3g", u.tTotal), ch::fmt("%.2f", c.nSearch),
             ch::fmt("%.2f", c.nCavity), ch::fmt("%.3g", c.tTotal)});
    dat << d << " " << u.nSearch << " " << u.nCavity << " " << u.tTotal << " " << c.nSearch << " "
        << c.nCavity << " " << c.tTotal << "\n";
    prog.update(++done);
  }
  tab.emit(o, "table_hilbert_depth");
  ch::writeOut(o, "hilbert_depth.dat", dat.str());
}

// ---- keys against sort -----------------------------------------------------------------------

// The parts are those of hilbertOrder itself (its keys are hilbertKeysFast's; the rest is the
// packing and the radix sort), so keys + rest = the whole; the other key and sort methods are
// timed as alternatives to the part they would replace.
void keysVersusSort(const ch::Options& o, std::size_t n, ch::Values& v) {
  const XY p = dt::uniformPoints(n, 44);
  const int depth = dt::hilbertAutoDepth(n);
  const int reps = 5;  // best of 5: the machine is shared
  double tFast = 1e30, tInt = 1e30, tList = 1e30, tSort = 1e30, tOrder = 1e30;
  std::size_t differ = 0;
  for (int r = 0; r < reps; ++r) {
    auto t0 = Clock::now();
    const std::vector<std::size_t> idx = dt::hilbertOrder(p, depth);
    tOrder = std::min(tOrder, ch::secondsSince(t0));
    t0 = Clock::now();
    const std::vector<std::uint64_t> k0 = dt::hilbertKeysFast(p, depth);
    tFast = std::min(tFast, ch::secondsSince(t0));
    t0 = Clock::now();
    const std::vector<std::uint64_t> k1 = dt::hilbertKeys(p, depth);
    tInt = std::min(tInt, ch::secondsSince(t0));
    t0 = Clock::now();
    const std::vector<std::uint64_t> k2 = dt::hilbertKeysListing(p, depth);
    tList = std::min(tList, ch::secondsSince(t0));
    differ = 0;
    for (std::size_t i = 0; i < n; ++i) differ += (k1[i] != k2[i]) + (k0[i] != k1[i]);
    std::vector<std::pair<std::uint64_t, std::size_t>> kv(n);
    for (std::size_t i = 0; i < n; ++i) kv[i] = {k1[i], i};
    t0 = Clock::now();
    std::sort(kv.begin(), kv.end());
    tSort = std::min(tSort, ch::secondsSince(t0));
  }
  // Each minimum is taken separately, so the rest is clamped at 0 if noise makes keys > whole.
  const double tRest = std::max(0.0, tOrder - tFast);
  auto share = [&](double t) { return ch::fmt("%.0f%%", 100 * t / tOrder); };
  auto times = [&](double t, double part) { return ch::fmt("%.1f x", t / part); };
  ch::Table tab;
  tab.caption = "The cost of the keys against the cost of the sort, n = " + sci(n) +
                " uniform points, depth " + std::to_string(depth) +
                " (best of 5 each). The notes: \"the main cost of sorting points is on the sorting "
                "algorithm itself and not on the computation of the Hilbert curve "
                "coordinates\".";
  tab.header = {"step", "t (s)", "share of hilbertOrder", "alternative / the part it replaces"};
  tab.add({"hilbertOrder (box + keys + sort)", ch::fmt("%.3g", tOrder), "100%", ""});
  tab.add({"its keys: hilbertKeysFast (4 levels per look-up)", ch::fmt("%.3g", tFast), share(tFast), ""});
  tab.add({"the rest: packing, radix sort, unpacking", ch::fmt("%.3g", tRest), share(tRest), ""});
  tab.add({"alternative keys: hilbertIndex (1 level per step)", ch::fmt("%.3g", tInt), "", times(tInt, tFast)});
  tab.add({"alternative keys: Listing 2.8 (HilbertCoord)", ch::fmt("%.3g", tList), "", times(tList, tFast)});
  tab.add({"alternative sort: std::sort of (key, index) pairs", ch::fmt("%.3g", tSort), "", times(tSort, std::max(tRest, 1e-9))});
  tab.add({"keys that differ between the three methods", std::to_string(differ), "", ""});
  tab.emit(o, "table_hilbert_keys");
  v.set("s235.keys_n", sci(n));
  // The notes: "sorting over a million points takes less than a second on a standard laptop".
  v.num("s235.order_seconds", tOrder, "%.3g");
  v.verdict("s235.order_under_a_second", tOrder < 1.0, "under a second", "over a second");
  v.num("s235.keys_share", 100 * tFast / tOrder, "%.0f%%");
  v.num("s235.sort_share", 100 * tRest / tOrder, "%.0f%%");
  v.verdict("s235.sort_vs_keys", tRest > tFast, "more", "less");
  v.verdict("s235.notes_keys_claim", tRest > tFast, "holds for hilbertOrder", "does not hold for hilbertOrder");
  v.num("s235.listing_keys_x", tList / tFast, "%.1f");
  v.num("s235.stdsort_x", tSort / std::max(tRest, 1e-9), "%.1f");
}

// ---- BRIO --------------------------------------------------------------------------------------

void brioFigure(const ch::Options& o) {
  const std::size_t n = 4000;
  const XY p = dt::uniformPoints(n, 77);
  std::vector<std::size_t> starts;
  const std::vector<std::size_t> idx = dt::brioOrder(p, 5, 0, &starts);
  std::ostringstream s;
  s << "# x y round: " << n << " uniform points in BRIO order; one block per round\n";
  starts.push_back(n);
  for (std::size_t r = 0; r + 1 < starts.size(); ++r) {
    for (std::size_t k = starts[r]; k < starts[r + 1]; ++k)
      s << p[2 * idx[k]] << " " << p[2 * idx[k] + 1] << " " << r << "\n";
    s << "\n\n";
  }
  ch::writeOut(o, "fig_brio_rounds.dat", s.str());
  std::ostringstream info;
  info << "rounds=" << starts.size() - 1 << "\n";
  for (std::size_t r = 0; r + 1 < starts.size(); ++r) info << starts[r + 1] - starts[r] << " ";
  info << "\n";
  ch::writeOut(o, "fig_brio_rounds.info", info.str());
  ch::runGnuplot(o, "fig_brio_rounds.gp");
}

void brioComparison(const ch::Options& o, const std::vector<std::size_t>& sizes,
                    std::size_t randomMax, std::size_t checkLimit, ch::Values& v) {
  // For the page: cavities and walks of Hilbert-only and BRIO on the spread-out inputs (all
  // sizes), and the parabola's Hilbert-only cavities.
  double hilCavLo = 1e300, hilCavHi = 0, brioCavLo = 1e300, brioCavHi = 0, brioParabola = 0;
  double walkDiffSum = 0, cavDiffSum = 0;
  double timeRatioLo = 1e300, timeRatioHi = 0;  // BRIO time / Hilbert-only time, spread-out rows
  int pairs = 0;
  std::string parabolaHilbert;
  struct Input { const char* name; XY (*make)(std::size_t, std::uint64_t); };
  const Input inputs[] = {
      {"uniform", [](std::size_t n, std::uint64_t s) { return dt::uniformPoints(n, s); }},
      {"clustered", [](std::size_t n, std::uint64_t s) { return dt::gaussianClusters(n, s); }},
      {"parabola", dt::parabolaPoints},
      {"jittered grid", [](std::size_t n, std::uint64_t s) { return dt::jitteredGridPoints(n, s); }},
      // Exercise 2.3.5-3: points on a circle (rounded, so only nearly cocircular); not part of
      // the page's values below.
      {"unit circle (random angles)", dt::randomCirclePoints}};
  constexpr int nInputs = sizeof(inputs) / sizeof(inputs[0]);
  // The largest size random order actually runs (the limit need not be one of the sizes).
  std::size_t randomTop = 0;
  for (std::size_t n : sizes)
    if (n <= randomMax) randomTop = std::max(randomTop, n);
  v.set("s235.brio_random_max", sci(randomTop));
  ch::Table tab;
  tab.caption = "BRIO against Hilbert-only and random insertion order: delaunayTrgl with "
                "super-triangles and LastCavity; t includes the ordering. Random order only up "
                "to n = " + sci(randomTop) + ": its walks grow like sqrt(n).";
  tab.header = {"input", "n", "order", "N_search", "N_cavity", "t (s)", "t/n (us)", "checked"};
  // One block of rows per (input, order), so that gnuplot joins each series.
  std::ostringstream dat[nInputs][3], stops;
  std::size_t total = 0, done = 0;
  for (std::size_t n : sizes) total += nInputs * (n <= randomMax ? 3 : 2);
  ch::Progress prog("BRIO comparison", total);
  for (int in = 0; in < nInputs; ++in) {
    // A series stops once N_search + N_cavity exceeds 200: the work per point grows like n
    // there (quadratic total), and the next size would take about 100 times longer.
    bool quadratic[3] = {false, false, false}, stopped[3] = {false, false, false};
    std::string lastRow[3];
    for (std::size_t n : sizes) {
      Run hilbertRun;  // the Hilbert-only run of the same points, for the BRIO comparison
      const XY p = inputs[in].make(n, 1000 + 10 * n + std::size_t(in));
      for (Order ord : {Order::Random, Order::Hilbert, Order::Brio}) {
        if (ord == Order::Random && n > randomMax) continue;
        const int k = int(ord);
        if (quadratic[k]) {
          tab.add({inputs[in].name, sci(n), orderName(ord), "", "", "skipped: quadratic", "", ""});
          if (!stopped[k] && in != nInputs - 1) stops << lastRow[k];  // the last size run
          stopped[k] = true;
          prog.update(++done);
          continue;
        }
        const Run r = medianRun(timingRuns(o), p, ord, 0, n <= checkLimit);
        quadratic[k] = r.nSearch + r.nCavity > 200;
        const bool spread = in == 0 || in == 1 || in == 3, parabola = in == 2;
        if (ord == Order::Hilbert) {
          if (spread) hilCavLo = std::min(hilCavLo, r.nCavity), hilCavHi = std::max(hilCavHi, r.nCavity);
          else if (parabola) parabolaHilbert += (parabolaHilbert.empty() ? "" : ", ") + ch::fmt("%.0f at \\f$n = ", r.nCavity) + sci(n) + "\\f$";
          hilbertRun = r;
        } else if (ord == Order::Brio) {
          if (spread) {
            brioCavLo = std::min(brioCavLo, r.nCavity), brioCavHi = std::max(brioCavHi, r.nCavity);
            if (hilbertRun.nCavity > 0) {  // the Hilbert-only run was not skipped
              walkDiffSum += r.nSearch - hilbertRun.nSearch;
              cavDiffSum += hilbertRun.nCavity - r.nCavity;
              const double ratio = r.tTotal / hilbertRun.tTotal;
              timeRatioLo = std::min(timeRatioLo, ratio), timeRatioHi = std::max(timeRatioHi, ratio);
              ++pairs;
            }
          } else if (parabola) {
            brioParabola = std::max(brioParabola, r.nCavity);
          }
        }
        tab.add({inputs[in].name, sci(n), orderName(ord), ch::fmt("%.2f", r.nSearch),
                 ch::fmt("%.2f", r.nCavity), ch::fmt("%.3g", r.tTotal),
                 ch::fmt("%.2f", 1e6 * r.tTotal / double(n)), r.checked ? "exact" : "no"});
        std::ostringstream row;
        row << in << " " << n << " " << k << " " << r.nSearch << " " << r.nCavity << " " << r.tTotal
            << " " << 1e6 * r.tTotal / double(n) << "\n";
        dat[in][k] << row.str();
        lastRow[k] = row.str();
        prog.update(++done);
      }
    }
  }
  tab.emit(o, "table_brio");
  {  // The student's edition of the book shows the table without the rows that answer 2.3.5-3.
    ch::Table student = tab;
    const std::string circle = inputs[nInputs - 1].name;
    student.rows.erase(std::remove_if(student.rows.begin(), student.rows.end(),
                                      [&](const std::vector<std::string>& r) { return r[0] == circle; }),
                       student.rows.end());
    student.emit(o, "table_brio_student");
  }
  v.num("s235.brio_cav_lo", brioCavLo, "%.1f");
  v.num("s235.brio_cav_hi", brioCavHi, "%.1f");
  v.num("s235.hil_cav_lo", hilCavLo, "%.1f");
  v.num("s235.hil_cav_hi", hilCavHi, "%.1f");
  v.num("s235.brio_walk_extra", pairs ? walkDiffSum / pairs : 0.0, "%.1f");
  v.num("s235.brio_cav_less", pairs ? cavDiffSum / pairs : 0.0, "%.1f");
  // BRIO's time over Hilbert-only's on the same points, over the spread-out rows.
  v.num("s235.brio_time_lo", pairs ? timeRatioLo : 0.0, "%.2f");
  v.num("s235.brio_time_hi", pairs ? timeRatioHi : 0.0, "%.2f");
  v.set("s235.brio_time_verdict",
        pairs == 0                                   ? "not measured"
        : timeRatioLo >= 0.8 && timeRatioHi <= 1.25  ? "about the same time on every row"
        : timeRatioHi < 1                            ? "BRIO is faster on every row"
        : timeRatioLo > 1                            ? "BRIO is slower on every row"
                                                     : "neither order is faster on every row");
  v.set("s235.parabola_hilbert", parabolaHilbert.empty() ? "not measured" : parabolaHilbert);
  v.num("s235.parabola_brio", brioParabola, "%.2f");  // as in table_brio
  std::string all = "# input(0 uniform,1 clustered,2 parabola,3 jittered grid,4 circle) n "
                    "order(0 random,1 Hilbert,2 BRIO) nsearch ncavity t us_per_point\n";
  // The circle's series (the answer to exercise 2.3.5-3) stays out of the figure's data: it
  // has a file of its own, with the same columns.
  std::string circleRows = all;
  for (int in = 0; in < nInputs; ++in)
    for (auto& series : dat[in]) (in == nInputs - 1 ? circleRows : all) += series.str();
  ch::writeOut(o, "brio_compare.dat", all);
  ch::writeOut(o, "brio_compare_circle.dat", circleRows);
  // The last row of each series stopped as quadratic (columns of brio_compare.dat), marked in
  // the figure.
  ch::writeOut(o, "brio_compare_stops.dat", stops.str().empty() ? "NaN NaN NaN NaN NaN NaN NaN\n" : stops.str());
  ch::runGnuplot(o, "fig_brio_compare.gp");
}

// ---- The fixed grid against the adaptive order --------------------------------------------------

// The outlier figure: uniform points plus one point at (1e12, 1e12). On the fixed grid all the
// uniform points share one cell and come in input (random) order, so the walks grow like
// sqrt(n); the adaptive order sorts that cell again over its own box. Then a table of the three
// families that defeat a fixed grid, at one size.
void outlierComparison(const ch::Options& o, const std::vector<std::size_t>& sizes,
                       std::size_t fixedMax, std::size_t tableN) {
  ch::Table tab;
  tab.caption = "Fixed grid against the adaptive Hilbert order (hilbertOrder(p, 0, false) and "
                "hilbertOrder(p)): delaunayTrgl with super-triangles and LastCavity, every "
                "triangulation checked exactly; t includes the ordering. The fixed grid only "
                "up to n = " + sci(fixedMax) + ": its walks grow like sqrt(n).";
  tab.header = {"input", "n", "order", "N_search", "N_cavity", "t (s)", "checked"};
  std::ostringstream dat;
  dat << "# outlier family: n order(0 fixed grid, 1 adaptive) nsearch ncavity t\n";
  std::size_t total = 3 * 2, done = 0;
  for (std::size_t n : sizes) total += n <= fixedMax ? 2 : 1;
  ch::Progress prog("fixed grid against adaptive", total);
  auto row = [&](const char* name, const XY& p, Order ord) {
    const Run r = medianRun(timingRuns(o), p, ord, 0, true);
    tab.add({name, sci(p.size() / 2), ord == Order::Hilbert ? "Hilbert, adaptive" : orderName(ord),
             ch::fmt("%.2f", r.nSearch),
             ch::fmt("%.2f", r.nCavity), ch::fmt("%.3g", r.tTotal), r.checked ? "exact" : "no"});
    prog.update(++done);
    return r;
  };
  for (Order ord : {Order::HilbertFixed, Order::Hilbert}) {
    for (std::size_t n : sizes) {
      if (ord == Order::HilbertFixed && n > fixedMax) continue;
      const Run r = row("uniform + outlier at (1e12, 1e12)", dt::outlierPoints(n, 1900 + n), ord);
      dat << n << " " << (ord == Order::Hilbert) << " " << r.nSearch << " " << r.nCavity << " "
          << r.tTotal << "\n";
    }
    dat << "\n\n";  // one gnuplot index per order
  }
  const XY cluster = dt::clusterBesideUniform(tableN, 1901);
  const XY logRadius = dt::logRadiusPoints(tableN, 1902);
  for (Order ord : {Order::HilbertFixed, Order::Hilbert})
    row("cluster of width 1e-9 beside uniform", cluster, ord);
  for (Order ord : {Order::HilbertFixed, Order::Hilbert})
    row("radii log-uniform in [1e-6, 1e6]", logRadius, ord);
  tab.emit(o, "table_outlier");
  ch::writeOut(o, "fig_outlier_walk.dat", dat.str());
  ch::runGnuplot(o, "fig_outlier_walk.gp");
}

}  // namespace

int main(int argc, char** argv) {
  const ch::Program p{"sec2_3_5_hilbert",
                      "Section 2.3.5: Hilbert curves, BRIO, Table 2.2 (Figures 2.11, 2.12).", 1000,
                      10000000,
                      {"fig2_11", "fig2_12", "fig_brio_rounds", "fig_brio_compare", "fig_outlier_walk"},
                      {{"--huge", "", "Table 2.2 up to 10^7 points (the default --max-n becomes 10^7)"}}};
  return ch::runMain(argc, argv, p, [&](const ch::Options& o) {
    const bool huge = o.has("--huge");
    const std::size_t maxN = o.maxN > 0 ? std::size_t(o.maxN)
                                        : (o.quick ? 10000 : (huge ? 10000000 : 1000000));
    auto upTo = [&](std::vector<std::size_t> v) {
      v.erase(std::remove_if(v.begin(), v.end(), [&](std::size_t n) { return n > maxN; }),
              v.end());
      return v;
    };
    ch::Values values(o, "sec2_3_5_hilbert");
    if (o.wants("fig2_11")) figure211(o);
    if (o.wants("fig2_12")) figure212(o, values);
    if (o.everything()) {
      // Every triangulation is checked exactly, outside the timings (about 2 s at 10^6).
      table22(o, upTo({1000, 10000, 100000, 1000000, 10000000}), 10000000, values);
      depthTable(o, std::min<std::size_t>(maxN, o.quick ? 10000 : 100000));
      keysVersusSort(o, std::min<std::size_t>(maxN, o.quick ? 100000 : 1000000), values);
    }
    if (o.wants("fig_brio_rounds")) brioFigure(o);
    if (o.wants("fig_brio_compare"))
      brioComparison(o, upTo({1000, 10000, 100000, 1000000}), o.quick ? 10000 : 30000, 1000000, values);
    if (o.wants("fig_brio_compare") || o.wants("fig_outlier_walk"))
      values.num("s235.time_runs", timingRuns(o), "%.0f");  // the charts' captions cite it
    if (o.wants("fig_outlier_walk"))
      outlierComparison(o, upTo({1000, 3000, 10000, 30000, 100000, 300000, 1000000}),
                        o.quick ? 10000 : 100000, o.quick ? 10000 : 100000);
    values.write();
    return 0;
  });
}
