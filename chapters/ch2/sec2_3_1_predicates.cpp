// Section 2.3.1, "Robust predicates": Figures 2.7 and 2.8 (the orientation map of Kettner et
// al.'s example, naive and robust, plus a zoom), the same maps for the incircle test on a
// near-cocircular configuration, the number of wrong cells of each map against the exact oracle,
// how O(a,b,c), O(c,b,a), O(b,c,a) really relate, counterexamples to the notes' static filters
// and to their 200-bit MPFR fallback, and a benchmark of the predicates (cost per call, share of
// exact evaluations during whole triangulations).
//
//   sec2_3_1_predicates [--out DIR] [--quick] [--max-n N] [--no-plot]
//
// --max-n bounds the point counts of the triangulations of the benchmark.
#include <cfloat>
#include <cmath>
#include <cstring>
#include <fstream>
#include <functional>
#include <random>

#include "check.h"
#include "colour_vision.h"
#include "common.h"
#include "generators.h"
#include "predicates.h"
#include "robustness.h"
#include "triangulate.h"

namespace {

using dt::SignMap;

// ---------------------------------------------------------------------------------------------
// Output helpers.

std::string hex(double x) { return ch::fmt("%a", x); }

std::string hexList(const double* v, int n) {
  std::string s = "(";
  for (int i = 0; i < n; ++i) s += (i ? (i % 2 ? ", " : "), (") : "") + hex(v[i]);
  return s + ")";
}

// A map as an n x n matrix for gnuplot's "matrix with image": row j holds cells (0..n-1, j).
void writeMap(const ch::Options& o, const std::string& name, const SignMap& m) {
  std::ostringstream s;
  for (int j = 0; j < m.n; ++j) {
    for (int i = 0; i < m.n; ++i) s << (i ? " " : "") << m.at(i, j);
    s << "\n";
  }
  ch::writeOut(o, name, s.str());
}

// Where a map is wrong: 0 right, 1 wrong zero, 2 flipped sign, 3 spurious nonzero.
void writeErrorMap(const ch::Options& o, const std::string& name, const SignMap& got,
                   const SignMap& exact) {
  std::ostringstream s;
  for (int j = 0; j < got.n; ++j) {
    for (int i = 0; i < got.n; ++i) {
      const int g = got.at(i, j), x = exact.at(i, j);
      s << (i ? " " : "") << (g == x ? 0 : g == 0 ? 1 : x == 0 ? 3 : 2);
    }
    s << "\n";
  }
  ch::writeOut(o, name, s.str());
}

void addErrorRow(ch::Table& t, const std::string& what, const dt::MapErrors& e) {
  t.add({what, std::to_string(e.cells), std::to_string(e.wrong), std::to_string(e.wrongZeros),
         std::to_string(e.flipped), std::to_string(e.spurious),
         e.farthest < 0 ? "-" : ch::fmt("%d (i=%d, j=%d)", e.farthest, e.fi, e.fj)});
}

ch::Table errorTable(const std::string& caption) {
  ch::Table t;
  t.caption = caption;
  t.header = {"map", "cells", "wrong", "wrong zeros", "flipped signs", "spurious nonzeros",
              "farthest wrong cell (cells off the diagonal)"};
  return t;
}

// ---------------------------------------------------------------------------------------------
// 0. What is computed, and the grid of Figure 2.7.

// The naive value with every intermediate forced through memory: what the source code spells,
// operation by operation. If the compiler contracted a*b - c*d into a fused multiply-add, the
// maps would differ from this reference.
double orientStepByStep(double ax, double ay, double bx, double by, double cx, double cy) {
  volatile double d1 = ax - cx, d2 = by - cy, d3 = ay - cy, d4 = bx - cx;
  volatile double l = d1 * d2, r = d3 * d4;
  return l - r;
}

long header(const ch::Options& o) {
  std::cout << "Section 2.3.1: robust predicates\n"
            << "  orientation O(a,b,c) = sign((xa-xc)(yb-yc) - (ya-yc)(xb-xc)), pivot c (the notes'"
               " formula, evaluated in this order)\n"
            << "  incircle InC(a,b,c,d) = sign(|a-d|^2 ((b-d)x(c-d)) + |b-d|^2 ((c-d)x(a-d)) +"
               " |c-d|^2 ((a-d)x(b-d))), pivot d\n"
            << "  floating point: binary64, round to nearest even, FLT_EVAL_METHOD = "
            << FLT_EVAL_METHOD << ", compiled with -ffp-contract=off (no fused multiply-add)";
#ifdef __FP_FAST_FMA
  std::cout << "; the target has a fast FMA, which contraction would use";
#endif
  std::cout << "\n";
  // Check that the build kept every rounding: the naive map equals the step-by-step one.
  using C = dt::Figure27;
  long differ = 0;
  for (int j = 0; j < C::n; ++j)
    for (int i = 0; i < C::n; ++i) {
      const double ax = C::x0 + i * C::eps, ay = C::y0 + j * C::eps;
      const double v1 = dt::orient2dNaiveValue(ax, ay, C::bx, C::by, C::cx, C::cy);
      const double v2 = orientStepByStep(ax, ay, C::bx, C::by, C::cx, C::cy);
      differ += std::memcmp(&v1, &v2, sizeof v1) != 0;
    }
  std::cout << "  contraction check: naive values that differ from the step-by-step evaluation"
               " on the 65536 cells: "
            << differ << (differ ? "  <-- the build contracts: results are not the notes'" : "")
            << "\n";
  // What the grid really holds: ulp(1/2) = 2^-53 = eps, so 1/2 + i eps is a double for every i.
  int distinct = 0, exact = 0;
  double prev = -1;
  for (int i = 0; i < C::n; ++i) {
    const double x = C::x0 + i * C::eps;
    distinct += x != prev;
    prev = x;
    exact += (x - C::x0) == i * C::eps;  // exact subtraction (Sterbenz)
  }
  std::cout << "  grid: eps = 2^-53 = ulp(1/2) (= " << hex(C::eps) << "); the 256 abscissas"
            << " 1/2 + i eps are " << distinct << " distinct doubles, " << exact
            << " of them exactly 1/2 + i eps (consecutive doubles: one cell = one ulp)\n";
  ch::writeOut(o, "sec2_3_1_setup.txt",
               ch::fmt("contraction_differences %ld\ndistinct_abscissas %d\nexact_abscissas %d\n",
                       differ, distinct, exact));
  return differ;
}

// ---------------------------------------------------------------------------------------------
// 1. The orientation maps (Figures 2.7, 2.8) and their relations.

int negNotes(double ax, double ay, double bx, double by, double cx, double cy) {
  return dt::orient2dNotes(-ax, -ay, -bx, -by, -cx, -cy);  // a half-turn keeps the orientation
}
int negNotesAbs(double ax, double ay, double bx, double by, double cx, double cy) {
  return dt::orient2dNotesAbs(-ax, -ay, -bx, -by, -cx, -cy);
}
constexpr double kTiny = 0x1p-534;  // Figure 2.7 scaled down: the products become subnormal
int tinyNotesAbs(double ax, double ay, double bx, double by, double cx, double cy) {
  return dt::orient2dNotesAbs(ax * kTiny, ay * kTiny, bx * kTiny, by * kTiny, cx * kTiny,
                              cy * kTiny);
}

void orientMaps(const ch::Options& o) {
  using dt::OrientOrder;
  const SignMap exABC = dt::orientMap(dt::orient2dExact, OrientOrder::ABC);
  const SignMap exCBA = dt::orientMap(dt::orient2dExact, OrientOrder::CBA);
  const SignMap exBCA = dt::orientMap(dt::orient2dExact, OrientOrder::BCA);
  const SignMap nvABC = dt::orientMap(dt::orient2dNaive, OrientOrder::ABC);
  const SignMap nvCBA = dt::orientMap(dt::orient2dNaive, OrientOrder::CBA);
  const SignMap nvBCA = dt::orientMap(dt::orient2dNaive, OrientOrder::BCA);
  const SignMap rbABC = dt::orientMap(dt::orient2d, OrientOrder::ABC);
  const SignMap rbCBA = dt::orientMap(dt::orient2d, OrientOrder::CBA);
  const SignMap noABC = dt::orientMap(dt::orient2dNotes, OrientOrder::ABC);
  const SignMap mpABC = dt::orientMap(dt::orient2dMPFR200, OrientOrder::ABC);
  const SignMap cnABC = dt::orientMap(dt::orient2dNaiveCanonical, OrientOrder::ABC);
  const SignMap cnCBA = dt::orientMap(dt::orient2dNaiveCanonical, OrientOrder::CBA);

  writeMap(o, "map_orient_naive_abc.dat", nvABC);
  writeMap(o, "map_orient_naive_cba.dat", nvCBA);
  writeMap(o, "map_orient_robust_abc.dat", rbABC);
  writeMap(o, "map_orient_robust_cba.dat", rbCBA);
  writeErrorMap(o, "err_orient_naive_abc.dat", nvABC, exABC);
  writeErrorMap(o, "err_orient_naive_cba.dat", nvCBA, exCBA);

  ch::Table t = errorTable(
      "Orientation maps of Figures 2.7-2.8 (b(12,12), c(24,24), a(1/2+i eps, 1/2+j eps), "
      "eps = 2^-53, 0 <= i,j < 256) against the exact sign of the same argument order");
  addErrorRow(t, "naive O(a,b,c) (Fig. 2.7 left)", dt::compareMaps(nvABC, exABC));
  addErrorRow(t, "naive O(c,b,a) (Fig. 2.7 right)", dt::compareMaps(nvCBA, exCBA));
  addErrorRow(t, "naive O(b,c,a)", dt::compareMaps(nvBCA, exBCA));
  addErrorRow(t, "canonical-order naive O(a,b,c) (exercise 1)", dt::compareMaps(cnABC, exABC));
  addErrorRow(t, "notes: filter 1e-15 + MPFR-200, O(a,b,c)", dt::compareMaps(noABC, exABC));
  addErrorRow(t, "MPFR-200 alone, O(a,b,c)", dt::compareMaps(mpABC, exABC));
  addErrorRow(t, "robust O(a,b,c) (Fig. 2.8)", dt::compareMaps(rbABC, exABC));
  addErrorRow(t, "robust O(c,b,a)", dt::compareMaps(rbCBA, exCBA));
  t.emit(o, "table_orient_maps");

  // How the three argument orders relate, measured cell by cell.
  using C = dt::Figure27;
  long negValue = 0;  // naive value of O(c,b,a) == -(naive value of O(b,c,a)), bit for bit
  for (int j = 0; j < C::n; ++j)
    for (int i = 0; i < C::n; ++i) {
      const double ax = C::x0 + i * C::eps, ay = C::y0 + j * C::eps;
      const double cba = dt::orient2dNaiveValue(C::cx, C::cy, C::bx, C::by, ax, ay);
      const double bca = -dt::orient2dNaiveValue(C::bx, C::by, C::cx, C::cy, ax, ay);
      negValue += std::memcmp(&cba, &bca, sizeof cba) == 0;
    }
  const long cells = long(C::n) * C::n;
  ch::Table r;
  r.caption = "How O(a,b,c), O(c,b,a) and O(b,c,a) relate on the 65536 cells of Figure 2.7";
  r.header = {"relation", "exact signs", "naive signs", "robust signs"};
  auto row = [&](const std::string& what, const SignMap& e1, const SignMap& e2,
                 const SignMap& n1, const SignMap& n2, const SignMap* r1, const SignMap* r2,
                 int f) {
    r.add({what, ch::fmt("%ld / %ld", dt::agreeingCells(e1, e2, f), cells),
           ch::fmt("%ld / %ld", dt::agreeingCells(n1, n2, f), cells),
           r1 ? ch::fmt("%ld / %ld", dt::agreeingCells(*r1, *r2, f), cells) : "-"});
  };
  row("O(c,b,a) = -O(a,b,c)", exCBA, exABC, nvCBA, nvABC, &rbCBA, &rbABC, -1);
  row("O(c,b,a) = +O(a,b,c) (the notes' sentence)", exCBA, exABC, nvCBA, nvABC, &rbCBA, &rbABC,
      +1);
  row("O(b,c,a) = O(a,b,c)", exBCA, exABC, nvBCA, nvABC, nullptr, nullptr, 1);
  row("O(c,b,a) = -O(b,c,a)", exCBA, exBCA, nvCBA, nvBCA, nullptr, nullptr, -1);
  r.add({"naive value of O(c,b,a) = -(value of O(b,c,a)), bit for bit", "-",
         ch::fmt("%ld / %ld", negValue, cells), "-"});
  r.add({"canonical-order naive: O(c,b,a) = -O(a,b,c) (exercise 1)", "-",
         ch::fmt("%ld / %ld", dt::agreeingCells(cnCBA, cnABC, -1), cells), "-"});
  r.emit(o, "table_orient_relations");

  // fig2_7_deuteranopia: Figure 2.7 as a deuteranope sees it (Machado et al. 2009, severity 1,
  // chapters/colour_vision.h). The map's only colours are the three signs; its text, axes and
  // background are black and white, which the simulation leaves as they are. So drawing the map
  // with the simulated sign colours is the simulation of the whole figure.
  {
    std::ifstream in(std::string(DT_SOURCE_DIR) + "/figures/ch2/style.gp");
    std::stringstream style;
    style << in.rdbuf();
    std::string gp = "# The sign colours of figures/ch2/style.gp as a deuteranope sees them (sec2_3_1_predicates).\n";
    for (const char* role : {"C_MINUS", "C_ZERO", "C_PLUS"})
      gp += std::string("D") + (role + 1) + " = \"" +
            ch::toHex(ch::simulate(ch::styleColour(style.str(), role), ch::Vision::Deuteranopia)) + "\"\n";
    ch::writeOut(o, "sign_colours_deuteranopia.gp", gp);
  }
  ch::runGnuplot(o, "fig2_7.gp");
  ch::runGnuplot(o, "fig2_8.gp");
}

// ---------------------------------------------------------------------------------------------
// 2. The incircle maps (new figures).

void incircleMaps(const ch::Options& o) {
  using dt::IncircleOrder;
  const SignMap ex1 = dt::incircleMap(dt::incircleExact, IncircleOrder::ABCD);
  const SignMap ex2 = dt::incircleMap(dt::incircleExact, IncircleOrder::DCBA);
  const SignMap nv1 = dt::incircleMap(dt::incircleNaive, IncircleOrder::ABCD);
  const SignMap nv2 = dt::incircleMap(dt::incircleNaive, IncircleOrder::DCBA);
  const SignMap rb1 = dt::incircleMap(dt::incircle, IncircleOrder::ABCD);
  const SignMap rb2 = dt::incircleMap(dt::incircle, IncircleOrder::DCBA);
  const SignMap no1 = dt::incircleMap(dt::incircleNotes, IncircleOrder::ABCD);
  const SignMap mp1 = dt::incircleMap(dt::incircleMPFR200, IncircleOrder::ABCD);
  writeMap(o, "map_incircle_naive_abcd.dat", nv1);
  writeMap(o, "map_incircle_naive_dcba.dat", nv2);
  writeMap(o, "map_incircle_robust_abcd.dat", rb1);
  writeMap(o, "map_incircle_robust_dcba.dat", rb2);

  ch::Table t = errorTable(
      "Incircle maps: a(1/2,-47/2), b(49/2,-47/2), c(49/2,1/2), d(1/2+i eps, 1/2+j eps), "
      "eps = 2^-53, 0 <= i,j < 256, against the exact sign of the same argument order");
  addErrorRow(t, "naive InC(a,b,c,d)", dt::compareMaps(nv1, ex1));
  addErrorRow(t, "naive InC(d,c,b,a)", dt::compareMaps(nv2, ex2));
  addErrorRow(t, "notes: filter 1e-11 + MPFR-200, InC(a,b,c,d)", dt::compareMaps(no1, ex1));
  addErrorRow(t, "MPFR-200 alone, InC(a,b,c,d)", dt::compareMaps(mp1, ex1));
  addErrorRow(t, "robust InC(a,b,c,d)", dt::compareMaps(rb1, ex1));
  addErrorRow(t, "robust InC(d,c,b,a)", dt::compareMaps(rb2, ex2));
  t.emit(o, "table_incircle_maps");
  const long cells = long(ex1.n) * ex1.n;
  long zeros = 0;
  for (auto v : ex1.s) zeros += v == 0;
  std::cout << "incircle: exact InC(d,c,b,a) = InC(a,b,c,d) on " << dt::agreeingCells(ex2, ex1, 1)
            << " / " << cells << " cells (an even permutation); naive: "
            << dt::agreeingCells(nv2, nv1, 1) << " / " << cells << "; exact zeros: " << zeros
            << " cell(s)\n";
  ch::runGnuplot(o, "fig_incircle_naive.gp");
  ch::runGnuplot(o, "fig_incircle_robust.gp");
}

// ---------------------------------------------------------------------------------------------
// 3. The notes' static filters: are they safe?

struct SearchResult {
  long trials = 0, wrong = 0;
  std::vector<double> first;  // the first counterexample
  int got = 0, exact = 0;
};

// Points near (1,1), (1,1) and (-1,-1): both products close to 4 = 4 max(|coords|)^2, where the
// rounding errors of the differences and products add up to about 24u max^2, above 1e-15 max^2.
SearchResult searchOrientAbs(long trials, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<int> k(-40, 40);
  SearchResult r;
  for (long t = 0; t < trials; ++t) {
    const double ax = std::nextafter(1.0, 0.0) - k(rng) * 0x1p-53, ay = 1 - k(rng) * 0x1p-53;
    const double bx = ax + k(rng) * 0x1p-52, by = ay + k(rng) * 0x1p-52;
    const double cx = -1 + (k(rng) + 40) * 0x1p-53, cy = -1 + (k(rng) + 40) * 0x1p-53;
    ++r.trials;
    const int e = dt::orient2dExact(ax, ay, bx, by, cx, cy);
    const int g = dt::orient2dNotesAbs(ax, ay, bx, by, cx, cy);
    if (e != g) {
      if (r.wrong++ == 0) r.first = {ax, ay, bx, by, cx, cy}, r.got = g, r.exact = e;
    }
  }
  return r;
}

// Random near-cocircular quadruples of several kinds, for the charitable incircle filter.
SearchResult searchIncircleAbs(long trials, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> ang(0, 2 * M_PI), u(-1, 1);
  std::uniform_int_distribution<int> k(-8, 8), sc(-60, 60);
  SearchResult r;
  for (long t = 0; t < trials; ++t) {
    const double s = std::ldexp(1.0, sc(rng)), cx = u(rng) * s, cy = u(rng) * s;
    const double rad = s * (0.5 + 0.5 * std::fabs(u(rng)));
    double v[8];
    for (int p = 0; p < 4; ++p) {
      const double a = ang(rng);
      v[2 * p] = cx + rad * std::cos(a);
      v[2 * p + 1] = cy + rad * std::sin(a);
    }
    for (int q = 6; q < 8; ++q)
      for (int z = k(rng); z != 0; z += z > 0 ? -1 : 1)
        v[q] = std::nextafter(v[q], z > 0 ? HUGE_VAL : -HUGE_VAL);
    ++r.trials;
    const int e = dt::incircleExact(v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7]);
    const int g = dt::incircleNotesAbs(v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7]);
    if (e != g) {
      if (r.wrong++ == 0) r.first.assign(v, v + 8), r.got = g, r.exact = e;
    }
  }
  return r;
}

// A quarter turn (x, y) -> (y, -x) keeps orientations and circles, and is exact; it brings every
// coordinate of the incircle configuration but d's abscissa to <= 0, so the signed max is 1/2.
int turnIncNotes(double ax, double ay, double bx, double by, double cx, double cy, double dx,
                 double dy) {
  return dt::incircleNotes(ay, -ax, by, -bx, cy, -cx, dy, -dx);
}
int turnIncNotesAbs(double ax, double ay, double bx, double by, double cx, double cy, double dx,
                    double dy) {
  return dt::incircleNotesAbs(ay, -ax, by, -bx, cy, -cx, dy, -dx);
}
// Scaled so that the degree-4 products are subnormal: the threshold 1e-11 max^4 underflows to 0.
constexpr double kTinyInc = 0x1p-273;
int tinyIncNotesAbs(double ax, double ay, double bx, double by, double cx, double cy, double dx,
                    double dy) {
  const double s = kTinyInc;
  return dt::incircleNotesAbs(ax * s, ay * s, bx * s, by * s, cx * s, cy * s, dx * s, dy * s);
}

void notesFilters(const ch::Options& o) {
  using dt::OrientOrder;
  using dt::IncircleOrder;
  ch::Table t;
  t.caption = "The notes' static filters |O| > 1e-15 max(...)^2 and |InC| > 1e-11 max(...)^4 "
              "(then 200-bit MPFR), as printed (signed max) and with the max of absolute values: "
              "wrong signs they let through";
  t.header = {"input", "rule", "wrong / tried", "example (hex), returned vs exact"};
  const SignMap exABC = dt::orientMap(dt::orient2dExact, OrientOrder::ABC);
  const SignMap exCBA = dt::orientMap(dt::orient2dExact, OrientOrder::CBA);
  auto mapRow = [&](const std::string& in, const std::string& rule, const SignMap& m,
                    const SignMap& ex) {
    const dt::MapErrors e = dt::compareMaps(m, ex);
    t.add({in, rule, ch::fmt("%ld / %ld cells", e.wrong, e.cells),
           e.wrong ? ch::fmt("cell i=%d, j=%d: %d vs %d", e.fi, e.fj, m.at(e.fi, e.fj),
                             ex.at(e.fi, e.fj))
                   : "-"});
  };
  auto orientRows = [&](const std::string& in, const std::string& rule, dt::OrientFn f) {
    mapRow(in + ", O(a,b,c)", rule, dt::orientMap(f, OrientOrder::ABC), exABC);
    mapRow(in + ", O(c,b,a)", rule, dt::orientMap(f, OrientOrder::CBA), exCBA);
  };
  orientRows("Figure 2.7 grid", "notes (signed max)", dt::orient2dNotes);
  orientRows("Figure 2.7 grid, all coordinates negated", "notes (signed max)", negNotes);
  orientRows("Figure 2.7 grid, all coordinates negated", "max of absolute values", negNotesAbs);
  orientRows("Figure 2.7 grid scaled by 2^-534 (subnormal products)", "max of absolute values",
             tinyNotesAbs);
  const long nOrient = o.quick ? 2000000 : 10000000;
  const SearchResult so = searchOrientAbs(nOrient, 20231);
  t.add({"a, b near (1,1), c near (-1,-1), random ulps (mixed signs)", "max of absolute values",
         ch::fmt("%ld / %ld", so.wrong, so.trials),
         so.wrong ? hexList(so.first.data(), 6) + ch::fmt(": %d vs %d", so.got, so.exact) : "-"});
  const SignMap ex1 = dt::incircleMap(dt::incircleExact, IncircleOrder::ABCD);
  const SignMap ex2 = dt::incircleMap(dt::incircleExact, IncircleOrder::DCBA);
  auto incircleRows = [&](const std::string& in, const std::string& rule, dt::IncircleFn f) {
    mapRow(in + ", InC(a,b,c,d)", rule, dt::incircleMap(f, IncircleOrder::ABCD), ex1);
    mapRow(in + ", InC(d,c,b,a)", rule, dt::incircleMap(f, IncircleOrder::DCBA), ex2);
  };
  incircleRows("incircle grid", "notes (signed max)", dt::incircleNotes);
  incircleRows("incircle grid turned by -90 degrees (max coordinate 1/2)", "notes (signed max)",
               turnIncNotes);
  incircleRows("incircle grid turned by -90 degrees", "max of absolute values", turnIncNotesAbs);
  incircleRows("incircle grid scaled by 2^-273 (subnormal products)", "max of absolute values",
               tinyIncNotesAbs);
  const long nInc = o.quick ? 200000 : 2000000;
  const SearchResult si = searchIncircleAbs(nInc, 20232);
  t.add({"random near-cocircular, centres and radii 2^-60..2^60, mixed signs", "max of absolute values",
         ch::fmt("%ld / %ld", si.wrong, si.trials),
         si.wrong ? hexList(si.first.data(), 8) + ch::fmt(": %d vs %d", si.got, si.exact) : "-"});
  t.emit(o, "table_filter_counterexamples");
}

// ---------------------------------------------------------------------------------------------
// 4. Is 200-bit MPFR exact?

void mpfr200(const ch::Options& o, ch::Values& v) {
  ch::Table t;
  t.caption = "Is 200-bit MPFR exact? Its sign against the exact one (GMP integers)";
  t.header = {"input", "predicate", "wrong zeros", "flipped", "spurious nonzeros", "tried",
              "bits needed (max)", "example (hex), MPFR-200 vs exact"};
  t.htmlParts = {{0, 1, 2, 3, 4, 5, 6}, {7}};  // the hex examples get a table of their own
  struct Tally {
    long wz = 0, fl = 0, sp = 0, n = 0;
    int bits = 0;
    std::string ex;
  };
  auto add = [&](const std::string& in, const std::string& pred, const Tally& y) {
    t.add({in, pred, std::to_string(y.wz), std::to_string(y.fl), std::to_string(y.sp),
           std::to_string(y.n), std::to_string(y.bits), y.ex.empty() ? "-" : y.ex});
  };
  auto tallyOne = [](Tally& y, int m, int e, const double* v, int nv, int bits) {
    ++y.n;
    y.bits = std::max(y.bits, bits);
    if (m == e) return;
    (m == 0 ? y.wz : e == 0 ? y.sp : y.fl)++;
    if (y.ex.empty() || (e != 0 && m != 0 && y.fl == 1))  // prefer a flipped sign as example
      y.ex = hexList(v, nv) + ch::fmt(": %d vs %d", m, e);
  };
  const long n = o.quick ? 100000 : 1000000;
  std::mt19937_64 rng(o.seed(231));
  {  // orient2d: a(1,1), b(2,2), c tiny: exact sign t' - t, but 1 - t needs ~250 bits
    Tally y;
    std::uniform_int_distribution<int> ex(150, 260), mm(1, 1 << 20), sg(0, 1);
    for (long i = 0; i < n; ++i) {
      double v[6] = {1, 1, 2, 2, 0, 0};
      for (int q = 4; q < 6; ++q) v[q] = (sg(rng) ? -1 : 1) * std::ldexp(double(mm(rng)), -ex(rng));
      tallyOne(y, dt::orient2dMPFR200(v[0], v[1], v[2], v[3], v[4], v[5]),
               dt::orient2dExact(v[0], v[1], v[2], v[3], v[4], v[5]), v, 6,
               dt::exactBitsOrient2d(v[0], v[1], v[2], v[3], v[4], v[5]));
    }
    add("a(1,1), b(2,2), c = (+-m 2^-e, +-m' 2^-e'), m < 2^20, 150 <= e <= 260", "orient2d", y);
  }
  {  // orient2d on doubles within 2^40 of each other: 200 bits are plenty (2B+3 <= 189)
    Tally y;
    std::uniform_real_distribution<double> u(-1, 1);
    std::uniform_int_distribution<int> sc(-20, 20);
    for (long i = 0; i < n; ++i) {
      double v[6];
      for (double& x : v) x = std::ldexp(u(rng), sc(rng));
      v[4] = v[0] + (v[2] - v[0]) * 0.375;  // near the line ab
      v[5] = v[1] + (v[3] - v[1]) * 0.375;
      tallyOne(y, dt::orient2dMPFR200(v[0], v[1], v[2], v[3], v[4], v[5]),
               dt::orient2dExact(v[0], v[1], v[2], v[3], v[4], v[5]), v, 6,
               dt::exactBitsOrient2d(v[0], v[1], v[2], v[3], v[4], v[5]));
    }
    add("near-collinear, coordinates in [-2^20, 2^20], mixed signs", "orient2d", y);
  }
  {  // incircle: exactly cocircular integer points of about 51 bits
    Tally y;
    const auto P = dt::cocircularIntegerPoints();
    std::uniform_int_distribution<std::size_t> pick(0, P.size() - 1);
    for (long i = 0; i < n / 10; ++i) {
      double v[8];
      for (int p = 0; p < 4; ++p) std::tie(v[2 * p], v[2 * p + 1]) = P[pick(rng)];
      tallyOne(y, dt::incircleMPFR200(v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7]),
               dt::incircleExact(v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7]), v, 8,
               dt::exactBitsIncircle(v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7]));
    }
    v.set("s231.cocircular_bits", std::to_string(y.bits));
    v.set("s231.cocircular_wrong", std::to_string(y.wz + y.fl + y.sp));
    v.set("s231.cocircular_tried", std::to_string(y.n));
    add(ch::fmt("exactly cocircular integers, x^2 + y^2 = (5^12 13^4 17^2)^2 (%zu points)",
                P.size()),
        "incircle", y);
  }
  {  // incircle: (3,4), (-5,0), (0,5), (4,-3) on x^2 + y^2 = 25, one zero coordinate made tiny
    Tally y;
    std::uniform_int_distribution<int> ex(150, 260), mm(1, 1 << 20), sg(0, 1), w(0, 1);
    for (long i = 0; i < n; ++i) {
      double v[8] = {3, 4, -5, 0, 0, 5, 4, -3};
      v[w(rng) ? 3 : 4] = (sg(rng) ? -1 : 1) * std::ldexp(double(mm(rng)), -ex(rng));
      tallyOne(y, dt::incircleMPFR200(v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7]),
               dt::incircleExact(v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7]), v, 8,
               dt::exactBitsIncircle(v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7]));
    }
    add("(3,4), (-5,0), (0,5), (4,-3), one zero coordinate -> +-m 2^-e, 150 <= e <= 260",
        "incircle", y);
  }
  t.emit(o, "table_mpfr200");
  {  // The student's edition of the book: without the column that answers exercise 2.3.1-2.
    ch::Table student = t;
    student.header.erase(student.header.begin() + 6);
    for (auto& r : student.rows) r.erase(r.begin() + 6);
    student.htmlParts = {{0, 1, 2, 3, 4, 5}, {6}};
    student.emit(o, "table_mpfr200_student");
  }
  // The simplest counterexample, spelled out.
  std::cout << "orient2d((1,1), (2,2), (2^-600, 0)): exact " << dt::orient2dExact(1, 1, 2, 2, 0x1p-600, 0)
            << ", MPFR-200 " << dt::orient2dMPFR200(1, 1, 2, 2, 0x1p-600, 0) << ", notes "
            << dt::orient2dNotes(1, 1, 2, 2, 0x1p-600, 0) << ", robust "
            << dt::orient2d(1, 1, 2, 2, 0x1p-600, 0) << "; MPFR with "
            << dt::exactBitsOrient2d(1, 1, 2, 2, 0x1p-600, 0) << " bits: "
            << dt::orient2dMPFR(dt::exactBitsOrient2d(1, 1, 2, 2, 0x1p-600, 0), 1, 1, 2, 2,
                                0x1p-600, 0)
            << "\n";
}

// ---------------------------------------------------------------------------------------------
// 5. Benchmark: cost per call, and the share of exact evaluations in whole triangulations.

volatile long g_sink;

template <class F>
double nsPerCall(long calls, F&& f) {
  const auto t0 = std::chrono::steady_clock::now();
  long sink = 0;
  for (long i = 0; i < calls; ++i) sink += f(i);
  const double s = ch::secondsSince(t0);
  g_sink = sink;  // the results are used: the loop cannot be optimised away
  return 1e9 * s / double(calls);
}

// The cost per call of f, robust to a shared machine: the number of calls grows until one
// measurement lasts about 30 ms, then the median of `reps` such measurements (one measurement
// alone was seen 10 times too slow while other jobs ran).
template <class F>
double medianNsPerCall(int reps, F&& f) {
  long calls = 256;
  while (calls < (1L << 30) && nsPerCall(calls, f) * double(calls) < 3e7) calls *= 4;
  std::vector<double> ns;
  for (int r = 0; r < reps; ++r) ns.push_back(nsPerCall(calls, f));
  std::sort(ns.begin(), ns.end());
  return ns[ns.size() / 2];
}

void benchmark(const ch::Options& o, ch::Values& v) {
  const int K = 4096;  // inputs reused cyclically (they stay in cache: we time the arithmetic)
  std::mt19937_64 rng(o.seed(2024));
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<double> gen(8 * K), deg(8 * K);
  for (double& x : gen) x = u(rng);
  using C = dt::Figure27;
  std::uniform_int_distribution<int> cell(0, C::n - 1);
  using IC = dt::IncircleConfig;
  for (int k = 0; k < K; ++k) {  // degenerate: cells of the two maps
    double* d = &deg[8 * k];
    d[0] = C::x0 + cell(rng) * C::eps, d[1] = C::y0 + cell(rng) * C::eps;
    d[2] = C::bx, d[3] = C::by, d[4] = C::cx, d[5] = C::cy;
  }
  std::vector<double> degI(8 * K);
  for (int k = 0; k < K; ++k) {
    double* d = &degI[8 * k];
    d[0] = IC::ax, d[1] = IC::ay, d[2] = IC::bx, d[3] = IC::by, d[4] = IC::cx, d[5] = IC::cy;
    d[6] = IC::x0 + cell(rng) * IC::eps, d[7] = IC::y0 + cell(rng) * IC::eps;
  }
  const int reps = o.quick ? 3 : 7;
  ch::Table t;
  t.caption = "Cost per call (ns) in this run, the median of " + std::to_string(reps) +
              " measurements of about 30 ms each, and ratio to the naive predicate on the same inputs";
  t.header = {"predicate", "inputs", "naive", "robust (filter + exact)", "exact only (GMP)",
              "notes (filter + MPFR-200)", "robust / naive", "exact / naive"};
  auto orientRow = [&](const std::string& what, const std::vector<double>& in) {
    auto at = [&](long i) { return &in[8 * (i % K)]; };
    const double nv = medianNsPerCall(reps, [&](long i) {
      const double* d = at(i);
      return dt::orient2dNaive(d[0], d[1], d[2], d[3], d[4], d[5]);
    });
    const double rb = medianNsPerCall(reps, [&](long i) {
      const double* d = at(i);
      return dt::orient2d(d[0], d[1], d[2], d[3], d[4], d[5]);
    });
    const double ex = medianNsPerCall(reps, [&](long i) {
      const double* d = at(i);
      return dt::orient2dExact(d[0], d[1], d[2], d[3], d[4], d[5]);
    });
    const double no = medianNsPerCall(reps, [&](long i) {
      const double* d = at(i);
      return dt::orient2dNotes(d[0], d[1], d[2], d[3], d[4], d[5]);
    });
    t.add({"orient2d", what, ch::fmt("%.1f", nv), ch::fmt("%.1f", rb), ch::fmt("%.1f", ex),
           ch::fmt("%.1f", no), ch::fmt("%.2f", rb / nv), ch::fmt("%.1f", ex / nv)});
  };
  auto incircleRow = [&](const std::string& what, const std::vector<double>& in) {
    auto at = [&](long i) { return &in[8 * (i % K)]; };
    const double nv = medianNsPerCall(reps, [&](long i) {
      const double* d = at(i);
      return dt::incircleNaive(d[0], d[1], d[2], d[3], d[4], d[5], d[6], d[7]);
    });
    const double rb = medianNsPerCall(reps, [&](long i) {
      const double* d = at(i);
      return dt::incircle(d[0], d[1], d[2], d[3], d[4], d[5], d[6], d[7]);
    });
    const double ex = medianNsPerCall(reps, [&](long i) {
      const double* d = at(i);
      return dt::incircleExact(d[0], d[1], d[2], d[3], d[4], d[5], d[6], d[7]);
    });
    const double no = medianNsPerCall(reps, [&](long i) {
      const double* d = at(i);
      return dt::incircleNotes(d[0], d[1], d[2], d[3], d[4], d[5], d[6], d[7]);
    });
    t.add({"incircle", what, ch::fmt("%.1f", nv), ch::fmt("%.1f", rb), ch::fmt("%.1f", ex),
           ch::fmt("%.1f", no), ch::fmt("%.2f", rb / nv), ch::fmt("%.1f", ex / nv)});
  };
  orientRow("uniform in the unit square", gen);
  orientRow("Figure 2.7 cells (near-collinear)", deg);
  incircleRow("uniform in the unit square", gen);
  incircleRow("incircle-map cells (near-cocircular)", degI);
  t.emit(o, "table_predicate_cost");

  // Share of calls that reach the exact stage during a full triangulation (hull method).
  long nMax = o.quick ? 10000 : 50000;  // random order: the walk makes this O(n^1.5)
  if (o.maxN > 0) nMax = std::min(nMax, o.maxN);
  ch::Table s;
  s.caption = "Calls of the robust predicates during DT(S) (delaunayTrglHull, random insertion "
              "order), and the share that reached the exact stage";
  s.header = {"input", "n", "orient2d calls", "exact", "share", "incircle calls", "exact",
              "share", "seconds"};
  auto run = [&](const std::string& what, std::vector<double> xy, const std::string& key = "") {
    dt::shufflePoints(xy, 7);
    dt::Triangulation T;
    const std::vector<dt::Vertex*> S = dt::addVertices(T, xy);
    dt::predicateCounters().reset();
    const auto t0 = std::chrono::steady_clock::now();
    dt::delaunayTrglHull(T, S, dt::StartRule::LastCavity);
    const double sec = ch::secondsSince(t0);
    const dt::PredicateCounters c = dt::predicateCounters();
    const dt::PlainMesh m = dt::extractMesh(T, true);
    const dt::CheckReport rep = dt::checkDelaunay(m.xy, m.tri);
    if (!rep.ok) throw std::runtime_error(what + ": invalid triangulation: " + rep.error);
    auto pct = [](std::uint64_t a, std::uint64_t b) {
      return b ? ch::fmt("%.3f%%", 100.0 * double(a) / double(b)) : std::string("-");
    };
    s.add({what, std::to_string(xy.size() / 2), std::to_string(c.orient.calls()),
           std::to_string(c.orient.beyondFilter()), pct(c.orient.beyondFilter(), c.orient.calls()),
           std::to_string(c.incircle.calls()), std::to_string(c.incircle.beyondFilter()),
           pct(c.incircle.beyondFilter(), c.incircle.calls()), ch::fmt("%.2f", sec)});
    if (!key.empty()) {  // the book cites these shares (2.3.1 page)
      v.set(key + "orient_share", pct(c.orient.beyondFilter(), c.orient.calls()));
      v.set(key + "incircle_share", pct(c.incircle.beyondFilter(), c.incircle.calls()));
    }
    std::cout << "  triangulated " << what << " (" << xy.size() / 2 << " points) in "
              << ch::fmt("%.2f", sec) << " s, checked exactly\n";
  };
  run("uniform in the unit square", dt::uniformPoints(std::size_t(nMax), 1));
  const int side = int(std::sqrt(double(nMax)));
  run(ch::fmt("%d x %d grid", side, side), dt::gridPoints(side, side), "s231.grid_");
  run("near-circle (rounded cos, sin)",
      dt::circlePoints(std::size_t(std::min<long>(nMax, o.quick ? 2000 : 20000))));
  s.emit(o, "table_exact_share");
}

}  // namespace

int main(int argc, char** argv) {
  // --max-n caps the benchmark's point count, which stops at 50000 anyway (10000 with --quick).
  const ch::Program p{"sec2_3_1_predicates",
                      "Section 2.3.1: robust predicates (Figures 2.7, 2.8, sign maps, filters, MPFR).",
                      1000, 1000000000,
                      {"fig2_7", "fig2_8", "fig_incircle_naive", "fig_incircle_robust"}, {}};
  return ch::runMain(argc, argv, p, [](const ch::Options& o) {
    const long contracted = header(o);
    if (o.wants("fig2_7") || o.wants("fig2_8")) orientMaps(o);
    if (o.wants("fig_incircle_naive") || o.wants("fig_incircle_robust")) incircleMaps(o);
    if (!o.everything()) return;
    notesFilters(o);
    ch::Values v(o, "sec2_3_1_predicates");
    v.set("s231.contraction_differences", std::to_string(contracted));
    mpfr200(o, v);
    benchmark(o, v);
    v.write();
  });
}
