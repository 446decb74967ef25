// Section 2.3.4, "Algorithms": Figure 2.10 (a cavity, its ball and the updated adjacencies),
// Table 2.1 regenerated (N_search, N_cavity, time for 10^3..10^6 random points, the walk starting
// at the first face as Listing 2.7 does), the share of time in the orientation predicate, and the
// worst case: points on a parabola inserted in x order.
//
//   sec2_3_4_algorithms [--out DIR] [--quick] [--max-n N] [--no-plot] [--no-profile]
//
// --max-n bounds Table 2.1 (default 10^6, --quick 10^4); --no-profile skips the perf profile.
// Times are CPU seconds of this process (getrusage), so that other jobs on the machine do not
// inflate them; they are compared as ratios measured in the same run.
#include <sys/resource.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <memory>
#include <random>
#include <set>
#include <sstream>

#include "cavity.h"
#include "check.h"
#include "common.h"
#include "figure_data.h"
#include "generators.h"
#include "predicates.h"
#include "search.h"
#include "triangulate.h"

namespace {

double cpuSeconds() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return double(u.ru_utime.tv_sec) + double(u.ru_stime.tv_sec) +
         1e-6 * double(u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

void checkOrThrow(const dt::Triangulation& T, const std::string& what) {
  const dt::CheckReport r = dt::checkTriangulation(T);
  if (!r.ok) throw std::runtime_error(what + ": invalid triangulation: " + r.error);
}

// ---- Figure 2.10 --------------------------------------------------------------------------

std::string triangleBlock(const dt::Face* f) {
  std::string s;
  for (int k = 0; k <= 3; ++k) s += ch::fmt("%.17g %.17g\n", f->V[k % 3]->x, f->V[k % 3]->y);
  return s + "\n";
}

// An arrow from the centroid of f towards the shared edge with g, and back from g's centroid:
// the two half-arrows meet on the edge, so each link reads as a double arrow across it.
std::string linkArrows(const dt::Face* f, const dt::Face* g) {
  const dt::Vertex a = f->centroid(), b = g->centroid();
  const double mx = 0.5 * (a.x + b.x), my = 0.5 * (a.y + b.y);
  return ch::fmt("%.17g %.17g %.17g %.17g\n", a.x, a.y, 0.9 * (mx - a.x), 0.9 * (my - a.y)) +
         ch::fmt("%.17g %.17g %.17g %.17g\n", b.x, b.y, 0.9 * (mx - b.x), 0.9 * (my - b.y));
}

// The smallest angle of the triangle a b c, degrees.
double minAngleDeg(const dt::Vertex* a, const dt::Vertex* b, const dt::Vertex* c) {
  const dt::Vertex* v[3] = {a, b, c};
  double m = 180;
  for (int k = 0; k < 3; ++k) {
    const dt::Vertex *o = v[k], *u = v[(k + 1) % 3], *w = v[(k + 2) % 3];
    const double ux = u->x - o->x, uy = u->y - o->y, wx = w->x - o->x, wy = w->y - o->y;
    m = std::min(m, std::fabs(std::atan2(ux * wy - uy * wx, ux * wx + uy * wy)) * 180 / M_PI);
  }
  return m;
}

// Figure 2.10's score of a new point q: the smallest angle (degrees) of the triangles the figure
// draws to be seen (the cavity, the ball and the neighbours outside the cavity); 0 if the cavity
// is not 4 to 6 faces or touches the hull (every neighbour must be a triangle).
double figure210Score(const dt::Triangulation& T, const dt::Vertex& q) {
  std::vector<const dt::Face*> cav;
  for (const dt::Face& f : T.faces())
    if (!f.deleted && f.inCircle(&q)) {
      if (f.isGhost()) return 0;
      cav.push_back(&f);
    }
  if (cav.size() < 4 || cav.size() > 6) return 0;
  double m = 180;
  for (const dt::Face* f : cav) {
    m = std::min(m, minAngleDeg(f->V[0], f->V[1], f->V[2]));
    for (int k = 0; k < 3; ++k) {  // F[k] lies across the edge V[k] V[k+1]
      const dt::Face* g = f->F[k];
      if (std::find(cav.begin(), cav.end(), g) != cav.end()) continue;
      if (g == nullptr || g->isGhost()) return 0;
      m = std::min({m, minAngleDeg(g->V[0], g->V[1], g->V[2]), minAngleDeg(&q, f->V[k], f->V[(k + 1) % 3])});
    }
  }
  return m;
}

void figure210(const ch::Options& o) {
  // 18 random points in the unit square and a new point p at a grid position whose cavity has 4
  // to 6 faces, none of them on the hull (so every neighbour is a triangle): chosen by score
  // (figure210Score), so that no triangle drawn to be seen is a sliver (no angle under 12
  // degrees) and every link arrow starts inside a triangle a reader can see. Among the points
  // whose smallest angle reaches 15 degrees, the one with the largest cavity (by area: the
  // figure is about it), over 40 seeds from --seed (default 2010) on; if no point reaches 15
  // degrees, the largest smallest angle.
  const std::uint64_t first = o.seed(2010);
  std::uint64_t seed = first;
  double bx = 0.5, by = 0.5, best = -1, bestArea = -1;
  for (std::uint64_t s = first; s < first + 40; ++s) {
    dt::Triangulation U;
    dt::delaunayTrglHull(U, dt::addVertices(U, dt::uniformPoints(18, s)), dt::StartRule::LastCavity);
    for (int i = 0; i <= 40; ++i)
      for (int j = 0; j <= 40; ++j) {
        const dt::Vertex q(0.2 + 0.015 * i, 0.2 + 0.015 * j);
        const double score = std::min(15.0, figure210Score(U, q));
        if (score < best || score <= 0) continue;
        double area = 0;
        for (const dt::Face& f : U.faces())
          if (!f.deleted && !f.isGhost() && f.inCircle(&q))
            area += 0.5 * std::fabs((f.V[1]->x - f.V[0]->x) * (f.V[2]->y - f.V[0]->y) - (f.V[1]->y - f.V[0]->y) * (f.V[2]->x - f.V[0]->x));
        if (score > best || area > bestArea) best = score, bestArea = area, bx = q.x, by = q.y, seed = s;
      }
  }
  const std::vector<double> xy = dt::uniformPoints(18, seed);
  dt::Triangulation T;
  std::vector<dt::Vertex*> S = dt::addVertices(T, xy);
  dt::delaunayTrglHull(T, S, dt::StartRule::LastCavity);
  best = figure210Score(T, dt::Vertex(bx, by));  // the smallest angle drawn, for the log
  dt::Vertex* p = T.addVertex(bx, by, long(S.size()));
  // The cavity by brute force (every finite face whose circle holds p strictly: 2.1.2), and the
  // faces across its boundary; then the real insertion, whose result we compare with them.
  std::set<const dt::Face*> cavity, outer;
  std::string before, cav;
  // Each edge once (a closed triangle draws an inner edge twice, darker than a hull edge).
  auto edgesOf = [](const auto& faces) { return ch::gnuplotSegs(ch::faceSegs(faces)); };
  std::vector<const dt::Face*> beforeFaces;
  for (const dt::Face* f : T.finiteFaces()) {
    beforeFaces.push_back(f);
    if (f->inCircle(p)) {
      cavity.insert(f);
      cav += triangleBlock(f);
    }
  }
  before = edgesOf(beforeFaces);  // now: the insertion reuses the cavity's faces
  for (const dt::Face* f : cavity)
    for (const dt::Face* g : f->F)
      if (g != nullptr && !g->isGhost() && cavity.count(g) == 0) outer.insert(g);
  dt::InsertionStats st;
  dt::InsertionScratch scratch;
  dt::insertVertex(T, &T.faces().front(), p, st, scratch);
  checkOrThrow(T, "Figure 2.10");
  std::string after, ball, out, arrowsNew, arrowsOut;
  std::vector<const dt::Face*> ballFaces;
  for (const dt::Face* f : T.finiteFaces()) {
    if (f->V[0] == p || f->V[1] == p || f->V[2] == p) {
      ball += triangleBlock(f);
      ballFaces.push_back(f);
    }
  }
  if (ballFaces.size() != cavity.size() + 2)
    throw std::runtime_error("Figure 2.10: the ball does not have |C| + 2 faces");
  for (const dt::Face* f : outer) out += triangleBlock(f);
  for (const dt::Face* f : ballFaces)
    for (const dt::Face* g : f->F) {
      if (g == nullptr || g->isGhost()) continue;
      const bool isNew = std::find(ballFaces.begin(), ballFaces.end(), g) != ballFaces.end();
      if (isNew && g < f) continue;  // each new-new link once
      (isNew ? arrowsNew : arrowsOut) += linkArrows(f, g);
    }
  after = edgesOf(T.finiteFaces());
  ch::writeOut(o, "fig2_10_before.dat", before);
  ch::writeOut(o, "fig2_10_cavity.dat", cav);
  ch::writeOut(o, "fig2_10_after.dat", after);
  ch::writeOut(o, "fig2_10_ball.dat", ball);
  ch::writeOut(o, "fig2_10_outer.dat", out);
  ch::writeOut(o, "fig2_10_links_new.dat", arrowsNew);
  ch::writeOut(o, "fig2_10_links_outer.dat", arrowsOut);
  ch::writeOut(o, "fig2_10_point.dat", ch::fmt("%.17g %.17g\n", p->x, p->y));
  // Both panels laid out in pixels (fig2_10_view.gp: PA, PB; one view, 4.5 em below each for
  // the legend), and the label of p placed once, clear of what either panel draws.
  double x0 = p->x, x1 = p->x, y0 = p->y, y1 = p->y;
  for (const dt::Vertex* v : S) x0 = std::min(x0, v->x), x1 = std::max(x1, v->x), y0 = std::min(y0, v->y), y1 = std::max(y1, v->y);
  const double m = 0.04 * (x1 - x0);
  const ch::FigureSize fs = ch::figureSize("fig2_10");
  const double lw = std::max(1.5, fs.em / 18);
  const ch::Panel pa = ch::cellPanel(fs, 1, 2, 0, x0 - m, x1 + m, y0 - m, y1 + m, 4.5),
                  pb = ch::cellPanel(fs, 1, 2, 1, x0 - m, x1 + m, y0 - m, y1 + m, 4.5);
  ch::LabelPlacer placer(pa, fs.em);
  placer.segments(ch::faceSegs(beforeFaces), 1.2 * lw);
  placer.segments(ch::faceSegs(T.finiteFaces()), 1.2 * lw);
  for (const std::string* arrows : {&arrowsNew, &arrowsOut}) {
    std::istringstream in(*arrows);
    for (double ax, ay, dx, dy; in >> ax >> ay >> dx >> dy;) {
      placer.segment(ax, ay, ax + dx, ay + dy, 2 * lw);
      placer.marker(ax + dx, ay + dy, 0.007 * fs.W);  // the head: "size screen 0.007"
    }
  }
  for (const dt::Vertex* v : S) placer.marker(v->x, v->y, 0.5 * lw);
  placer.marker(p->x, p->y, ch::pointRadius(fs, 1.6));
  const auto [lx, ly] = placer.place(p->x, p->y, ch::mathText("p"));
  ch::writeOut(o, "fig2_10_label.dat", ch::fmt("%.17g %.17g\n", lx, ly));
  // The legend's words in the notes' notation (figures/ch2/notation.txt).
  const std::string B = ch::mathText("\\mathscr{B}");
  ch::writeOut(o, "fig2_10_view.gp",
               "PA = \"" + pa.gnuplot() + "\"\nPB = \"" + pb.gnuplot() + "\"\nT_CAVITY = \"" +
                   ch::mathText("\\mathscr{C}(\\mathrm{DT}_n, p)") + "\"\nT_BALL = \"" + ch::mathText("\\mathscr{B}(\\mathrm{DT}_n, p)") +
                   "\"\nT_NEWNEW = \"" + B + " – " + B + "\"\nT_NEWOUT = \"" + B + " – neighbour\"\n");
  std::cout << "Figure 2.10: seed " << seed << ", smallest angle drawn " << ch::fmt("%.1f", best) << " degrees, cavity of "
            << cavity.size() << " faces, ball of " << ballFaces.size() << " faces, " << outer.size() << " neighbours outside\n";
  ch::runGnuplot(o, "fig2_10.gp");
}

// ---- Table 2.1 ----------------------------------------------------------------------------

struct Run {
  long n = 0;
  double nSearch = 0, nCavity = 0, seconds = 0;
};

// Listing 2.7 on n random points (random order) in the super-triangles, the walk always starting
// at the first face T[0]. delaunayTrgl is called on slices of S so that progress can be shown;
// with StartRule::FirstFace this is the same computation as one call.
// `factor`: the super-square's width over the points' box (the library's default is 10).
Run table21Run(long n, bool check, double factor = 10.0, unsigned seed = 21u) {
  dt::Triangulation T;
  std::vector<dt::Vertex*> S = dt::addVertices(T, dt::uniformPoints(std::size_t(n), seed));
  dt::initSuperTriangles(T, 0, 0, 1, 1, factor);
  dt::InsertionStats st;
  ch::Progress prog(ch::fmt("Table 2.1, n = %ld", n), std::uint64_t(n));
  const std::size_t slice = std::max<std::size_t>(1000, std::size_t(n) / 200);
  const double t0 = cpuSeconds();
  for (std::size_t b = 0; b < S.size(); b += slice) {
    const std::vector<dt::Vertex*> part(S.begin() + long(b),
                                        S.begin() + long(std::min(S.size(), b + slice)));
    dt::delaunayTrgl(T, part, dt::StartRule::FirstFace, &st);
    prog.update(std::min(S.size(), b + slice));
  }
  Run r;
  r.seconds = cpuSeconds() - t0;
  r.n = n;
  r.nSearch = st.meanSearch();
  r.nCavity = st.meanCavity();
  if (check) checkOrThrow(T, ch::fmt("Table 2.1 n = %ld", n));
  return r;
}

void table21(const ch::Options& o, ch::Values& v) {
  const long maxN = o.maxN > 0 ? o.maxN : (o.quick ? 10000 : 1000000);
  // The notes' Table 2.1 (chapter 2, "Table 2.1: Results of the delaunayTrgl algorithm applied
  // to random points"), typed from the notes: N_search, N_cavity and t (s) at n = 10^3..10^6.
  // The notes' data, not measured here.
  const std::map<long, std::array<double, 3>> notes = {{1000, {19.8, 3.85, 0.012}},
                                                       {10000, {56.8, 3.97, 0.198}},
                                                       {100000, {161, 3.99, 4.85}},
                                                       {1000000, {503, 3.99, 172}}};
  std::vector<Run> runs;
  for (long n = 1000; n <= maxN; n *= 10) {
    runs.push_back(table21Run(n, true));
    std::cout << ch::fmt("n = %ld: N_search = %.2f, N_cavity = %.3f, %.3f s CPU\n", n,
                         runs.back().nSearch, runs.back().nCavity, runs.back().seconds);
  }
  ch::Table t;
  t.caption = "Table 2.1 regenerated: delaunayTrgl (Listing 2.7, super-triangles, walk from the "
              "first face T[0]) on n uniform random points in random order. N_search: faces "
              "visited by lineSearch per insertion, the face returned included. N_cavity: faces "
              "per Delaunay cavity. t: CPU seconds (ratio: to the previous n). Notes' values "
              "in brackets.";
  t.header = {"n", "N_search", "[notes]", "N_search/sqrt(n)", "N_cavity", "[notes]", "t (s)",
              "t ratio", "[notes' t]", "[notes' ratio]"};
  t.htmlParts = {{0, 1, 2, 3, 4, 5}, {6, 7, 8, 9}};  // ten columns do not fit the book's column
  std::string dat = "# n N_search N_cavity t notes_N_search\n";
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const Run& r = runs[i];
    const auto it = notes.find(r.n);
    const bool hasNotes = it != notes.end();
    const auto prevNotes = i > 0 ? notes.find(runs[i - 1].n) : notes.end();
    t.add({std::to_string(r.n), ch::fmt("%.1f", r.nSearch),
           hasNotes ? ch::fmt("%.3g", it->second[0]) : "-",
           ch::fmt("%.3f", r.nSearch / std::sqrt(double(r.n))), ch::fmt("%.3f", r.nCavity),
           hasNotes ? ch::fmt("%.3g", it->second[1]) : "-", ch::fmt("%.3g", r.seconds),
           i > 0 && runs[i - 1].seconds > 0 ? ch::fmt("%.1f", r.seconds / runs[i - 1].seconds) : "-",
           hasNotes ? ch::fmt("%.3g", it->second[2]) : "-",
           hasNotes && prevNotes != notes.end() ? ch::fmt("%.1f", it->second[2] / prevNotes->second[2])
                                                : "-"});
    dat += ch::fmt("%ld %.6g %.6g %.6g %.6g\n", r.n, r.nSearch, r.nCavity, r.seconds,
                   hasNotes ? it->second[0] : NAN);
  }
  t.emit(o, "table2_1");
  {
    // The largest n that the notes also measured: how far our N_search is from theirs.
    const Run* last = nullptr;
    for (const Run& r : runs)
      if (notes.count(r.n)) last = &r;
    if (last != nullptr) {
      const double theirs = notes.at(last->n)[0];
      const double rel = (last->nSearch - theirs) / theirs;
      v.set("s234.nsearch_cmp_n", std::to_string(last->n));
      v.num("s234.nsearch_ours", last->nSearch, "%.1f");
      v.num("s234.nsearch_notes", theirs, "%.3g");
      v.num("s234.nsearch_gap", 100 * std::fabs(rel), "%.0f%%");
      v.verdict("s234.nsearch_side", rel < 0, "below", "above");
    }
    v.num("s234.ncavity_last", runs.back().nCavity, "%.3f");
    v.set("s234.n_last", std::to_string(runs.back().n));
  }
  // Growth exponents of N_search and of t (least squares in logs), ours and the notes'.
  if (runs.size() >= 2) {
    auto slope = [](const std::vector<std::array<double, 2>>& pts) {
      double sx = 0, sy = 0, sxx = 0, sxy = 0;
      for (const auto& [n, v] : pts) {
        const double x = std::log(n), y = std::log(v);
        sx += x;
        sy += y;
        sxx += x * x;
        sxy += x * y;
      }
      const double m = double(pts.size());
      return (m * sxy - sx * sy) / (m * sxx - sx * sx);
    };
    std::vector<std::array<double, 2>> search, time, nSearch, nTime;
    for (const Run& r : runs) {
      search.push_back({double(r.n), r.nSearch});
      time.push_back({double(r.n), r.seconds});
      const auto it = notes.find(r.n);
      if (it == notes.end()) continue;
      nSearch.push_back({double(r.n), it->second[0]});
      nTime.push_back({double(r.n), it->second[2]});
    }
    ch::Table e;
    e.caption = ch::fmt("Growth of Table 2.1: least-squares exponent a in N ~ n^a over n = %ld..%ld",
                        runs.front().n, runs.back().n);
    e.header = {"quantity", "exponent (this run)", "exponent (notes' table, same n)",
                "the notes say"};
    e.add({"N_search", ch::fmt("%.3f", slope(search)), ch::fmt("%.3f", slope(nSearch)),
           "sqrt(n): 0.5"});
    v.num("s234.exp_search", slope(search), "%.2f");
    v.num("s234.exp_time", slope(time), "%.2f");
    const bool faster = slope(time) > 1.0 + slope(search);
    v.verdict("s234.exp_time_vs_steps", faster, "faster", "no faster");
    // What a step costs: CPU time per face the walk visits (the cavity and the ball are
    // charged to the walk too), at the smallest and the largest n. A rise shows that the time
    // outgrows the step count because each step gets dearer; what sets that cost is not measured.
    auto nsPerStep = [](const Run& r) { return 1e9 * r.seconds / (double(r.n) * r.nSearch); };
    const double nsFirst = nsPerStep(runs.front()), nsLast = nsPerStep(runs.back());
    v.set("s234.n_first", std::to_string(runs.front().n));
    v.num("s234.ns_step_first", nsFirst, "%.1f");
    v.num("s234.ns_step_last", nsLast, "%.1f");
    v.num("s234.ns_step_ratio", nsLast / nsFirst, "%.1f");
    // Three ways, since the cost per face can fall as well as rise between the two sizes.
    v.trend("s234.ns_step_trend", nsFirst, nsLast);
    v.verdict("s234.exp_time_comment", faster,
              "The time outgrows the step count because each step gets dearer, as the cost per face "
              "visited shows",
              "Up to this run's largest n the steps do not get dearer");
    e.add({"time", ch::fmt("%.3f", slope(time)), ch::fmt("%.3f", slope(nTime)), "n^1.5: 1.5"});
    e.emit(o, "table2_1_growth");
  }
  ch::writeOut(o, "table2_1.dat", dat);
  // The notes' N_search at all four sizes (the figure plots them whatever this run's sizes).
  std::string theirs = "# n notes_N_search (the notes' Table 2.1)\n";
  for (const auto& [n, row] : notes) theirs += ch::fmt("%ld %.6g\n", n, row[0]);
  ch::writeOut(o, "table2_1_notes.dat", theirs);
  // The sqrt(n) slope through the first measured point, over the notes' sizes (10^3..10^6), so
  // that the figure draws it even when the run has one n.
  std::string ref;
  for (const long n : {1000L, 1000000L})
    ref += ch::fmt("%ld %.6g\n", n, runs.front().nSearch * std::sqrt(double(n) / double(runs.front().n)));
  ch::writeOut(o, "table2_1_sqrt.dat", ref);
  ch::runGnuplot(o, "fig_table2_1_search.gp");
}

// What makes our N_search differ from the notes'? The notes give neither the size of their
// super-triangles nor whether the face their walk returns is counted. Table 2.1's run at one
// size, varied one thing at a time: the super-square factor, the count without the returned
// face, and another point set (seed).
void nsearchVariants(const ch::Options& o, ch::Values& v) {
  const long n = std::min<long>(o.maxN > 0 ? o.maxN : 100000, o.quick ? 10000 : 100000);
  const std::map<long, double> notes = {{1000, 19.8}, {10000, 56.8}, {100000, 161}, {1000000, 503}};
  ch::Table t;
  t.caption = ch::fmt("What N_search counts: Table 2.1's run at n = %ld (first-face walk), one thing "
                      "changed at a time. Notes: %s.", n,
                      notes.count(n) ? ch::fmt("%.3g", notes.at(n)).c_str() : "not measured at this n");
  t.header = {"variant", "N_search", "vs the notes"};
  auto row = [&](const std::string& what, double ns) {
    t.add({what, ch::fmt("%.1f", ns),
           notes.count(n) ? ch::fmt("%+.0f%%", 100 * (ns - notes.at(n)) / notes.at(n)) : "-"});
  };
  const Run base = table21Run(n, false);
  row("Table 2.1's setting: super-square 10 x the box, returned face counted", base.nSearch);
  row("returned face not counted", base.nSearch - 1.0);
  double lo = base.nSearch, hi = base.nSearch;
  for (double f : {1.5, 3.0, 100.0, 1000.0}) {
    const Run r = table21Run(n, false, f);
    row(ch::fmt("super-square %g x the box", f), r.nSearch);
    lo = std::min(lo, r.nSearch);
    hi = std::max(hi, r.nSearch);
  }
  const Run other = table21Run(n, false, 10.0, 7u);
  row("another point set (seed 7)", other.nSearch);
  t.emit(o, "table2_1_nsearch_variants");
  v.set("s234.var_n", std::to_string(n));
  v.num("s234.var_base", base.nSearch, "%.1f");
  v.num("s234.var_factor_lo", lo, "%.1f");
  v.num("s234.var_factor_hi", hi, "%.1f");
  v.num("s234.var_seed", other.nSearch, "%.1f");
  if (notes.count(n)) {
    const double theirs = notes.at(n);
    v.num("s234.var_notes", theirs, "%.3g");
    const bool covers = lo <= theirs && theirs <= hi;
    v.verdict("s234.var_factor_reaches", covers, "covers", "does not reach");
    v.verdict("s234.var_conclusion", covers,
              "The size of the super-triangles, which the notes do not give, can therefore account "
              "for the whole gap",
              "The size of the super-triangles alone therefore does not explain the gap");
  } else {
    v.set("s234.var_notes", "(not measured by the notes at this n)");
    v.set("s234.var_factor_reaches", "cannot be compared with");
    v.set("s234.var_conclusion", "The notes did not measure this size, so no conclusion is drawn");
  }
}

// ---- share of time in the orientation predicate --------------------------------------------

// Where the CPU time of one Table 2.1 run goes, sampled by perf (if available): self time per
// function, grouped. Returns false if perf could not be run; `orientShare` gets the fraction
// of the samples in the orientation predicate.
bool perfProfile(const ch::Options& o, long n, double& orientShare) {
  char self[4096] = {0};
  if (readlink("/proc/self/exe", self, sizeof self - 1) <= 0) return false;
  const std::string data = o.out + "/perf_2_3_4.data", rep = o.out + "/perf_2_3_4.txt";
  ch::ProcessIo quiet;
  quiet.stdoutPath = "/dev/null";
  quiet.stderrPath = "/dev/null";
  if (ch::runProgram({"perf", "record", "-q", "-F", "2000", "-o", data, "--", self, "--profile-child",
                      std::to_string(n)},
                     quiet) != 0)
    return false;
  ch::ProcessIo toFile = quiet;
  toFile.stdoutPath = rep;
  if (ch::runProgram({"perf", "report", "-i", data, "--no-children", "--sort", "symbol", "--stdio", "-q"},
                     toFile) != 0)
    return false;
  std::ifstream in(rep);
  std::map<std::string, double> group;
  std::string line;
  double total = 0;
  while (std::getline(in, line)) {
    double pc = 0;
    char sym[4096] = {0};
    if (std::sscanf(line.c_str(), " %lf%% [%*[^]]] %4095[^\n]", &pc, sym) != 2) continue;
    std::string s(sym);
    s = s.substr(0, s.find_last_not_of(" -") + 1);
    std::string g = "other (allocation, kernel, input)";
    if (s.find("orient") != std::string::npos) g = "orientation: orient2d, orientationTest";
    else if (s.find("ncircle") != std::string::npos || s.find("inCircle") != std::string::npos)
      g = "incircle: Face::inCircle, incircle (loads the face's vertices)";
    else if (s.find("lineSearch") != std::string::npos || s.find("centroid") != std::string::npos)
      g = "lineSearch itself (centroid, steps)";
    else if (s.find("Adjacenc") != std::string::npos || s.find("Rb_tree") != std::string::npos ||
             s.find("delaunayCavity") != std::string::npos || s.find("insertVertex") != std::string::npos)
      g = "cavity, ball, computeAdjacencies (std::map)";
    else if (s.find("mpz") != std::string::npos || s.find("gmp") != std::string::npos)
      g = "exact fallback (GMP)";
    group[g] += pc;
    total += pc;
  }
  ch::Table t;
  t.caption = ch::fmt("Where the time of Listing 2.7 goes, n = %ld random points (perf sampling, "
                      "self time per function, grouped; %.1f%% of samples classified)",
                      n, total);
  t.header = {"part", "share of CPU samples"};
  std::vector<std::pair<double, std::string>> rows;
  for (const auto& [g, pc] : group) rows.push_back({pc, g});
  std::sort(rows.rbegin(), rows.rend());
  for (const auto& [pc, g] : rows) t.add({g, ch::fmt("%.1f%%", pc)});
  t.emit(o, "table_orient_share_perf");
  orientShare = group["orientation: orient2d, orientationTest"] / 100.0;
  std::remove(data.c_str());
  return true;
}

// The counting estimate (no profiler needed): number of calls of each predicate in the run,
// times its cost per call measured on the same kind of arguments, over the run's CPU time.
// Returns the orientation predicate's share.
double countingEstimate(ch::Table& t, long n) {
  // Timings are the minimum over repetitions (the usual defence against other jobs): the
  // triangulation is repeated when it is short, each timed loop five times.
  const std::vector<double> xy = dt::uniformPoints(std::size_t(n), 21u);
  const int reps = n <= 10000 ? 5 : 1;
  double total = 1e300;
  std::unique_ptr<dt::Triangulation> T;  // the last repetition is kept for the replay below
  std::vector<dt::Vertex*> S;
  for (int r = 0; r < reps; ++r) {
    T = std::make_unique<dt::Triangulation>();
    S.clear();
    for (long i = 0; i < n; ++i) S.push_back(T->addVertex(xy[2 * i], xy[2 * i + 1], i));
    dt::initSuperTriangles(*T, 0, 0, 1, 1);
    dt::predicateCounters().reset();
    dt::InsertionStats st;
    const double t0 = cpuSeconds();
    dt::delaunayTrgl(*T, S, dt::StartRule::FirstFace, &st);
    total = std::min(total, cpuSeconds() - t0);
  }
  const dt::PredicateCounters c = dt::predicateCounters();
  // Per-call cost: the walk's orientation tests take a face centroid, a vertex of that face and
  // a far point; the incircle tests take a face and a far point. Replay such calls, built from
  // random faces of the final mesh and stored in one array, so the timed loops read from cache.
  std::vector<const dt::Face*> F = T->finiteFaces();
  std::mt19937_64 rng(5);
  // 4096 argument sets (256 KB, cache-resident) replayed 1000 times.
  const std::size_t distinct = 4096, rounds = 1000, calls = distinct * rounds;
  std::vector<std::array<double, 8>> args(distinct);
  for (auto& a : args) {
    const dt::Face* f = F[rng() % F.size()];
    const dt::Vertex c0 = f->centroid();
    const dt::Vertex* q = S[rng() % S.size()];
    a = {c0.x, c0.y, f->V[0]->x, f->V[0]->y, q->x, q->y, f->V[1]->x, f->V[1]->y};
  }
  long sink = 0;
  double tOrient = 1e300, tIncircle = 1e300;
  for (int r = 0; r < 5; ++r) {
    double ta = cpuSeconds();
    for (std::size_t k = 0; k < rounds; ++k)
      for (const auto& a : args) sink += dt::orient2d(a[0], a[1], a[2], a[3], a[4], a[5]);
    tOrient = std::min(tOrient, (cpuSeconds() - ta) / double(calls));
    ta = cpuSeconds();
    for (std::size_t k = 0; k < rounds; ++k)
      for (const auto& a : args) sink += dt::incircle(a[2], a[3], a[6], a[7], a[0], a[1], a[4], a[5]);
    tIncircle = std::min(tIncircle, (cpuSeconds() - ta) / double(calls));
  }
  const double shareO = double(c.orient.calls()) * tOrient / total;
  const double shareI = double(c.incircle.calls()) * tIncircle / total;
  t.add({std::to_string(n), "orient2d", ch::fmt("%.1f", double(c.orient.calls()) / double(n)),
         std::to_string(c.orient.beyondFilter()), ch::fmt("%.1f", 1e9 * tOrient), ch::fmt("%.3g", total),
         ch::fmt("%.1f%%", 100 * shareO)});
  t.add({std::to_string(n), "incircle", ch::fmt("%.1f", double(c.incircle.calls()) / double(n)),
         std::to_string(c.incircle.beyondFilter()), ch::fmt("%.1f", 1e9 * tIncircle), ch::fmt("%.3g", total),
         ch::fmt("%.1f%%", 100 * shareI)});
  if (sink == 42) std::cout << " ";  // keeps the timed loops from being optimised away
  return shareO;
}

void predicateShare(const ch::Options& o, bool profile, ch::Values& v) {
  const long n = o.quick ? 10000 : 100000;
  ch::Table t;
  t.caption = "Share of time in the predicates by counting: Listing 2.7 on n random points; calls "
              "x cost per call (measured on arguments already in cache) / the run's CPU time";
  t.header = {"n", "predicate", "calls per insertion", "exact fallbacks", "ns per call",
              "run (s CPU)", "share of the time"};
  const double small = countingEstimate(t, n / 10), large = countingEstimate(t, n);
  t.emit(o, "table_orient_share_count");
  // The page's sentences about the claim follow from these values.
  v.set("s234.share_n_small", std::to_string(n / 10));
  v.set("s234.share_n_large", std::to_string(n));
  v.num("s234.orient_count_small", 100 * small, "%.1f%%");
  v.num("s234.orient_count_large", 100 * large, "%.1f%%");
  v.verdict("s234.orient_count_trend", large > small, "rises", "falls");
  double perf = -1;
  const bool profiled = profile && perfProfile(o, n, perf);
  v.set("s234.orient_perf", profiled ? ch::fmt("%.1f%%", 100 * perf) : "not measured (no perf profile)");
  const bool countBelow = small < 0.5 && large < 0.5, perfBelow = perf < 0.5;
  std::string verdict;
  if (!profiled)
    verdict = countBelow ? "The count puts it below 50%: the claim is not confirmed on this machine"
                         : "The count puts it at 50% or more: the claim holds on this machine";
  else if (countBelow && perfBelow)
    verdict = "Both measurements put it below 50%: the claim is not confirmed on this machine";
  else if (!countBelow && !perfBelow)
    verdict = "Both measurements put it at 50% or more: the claim holds on this machine";
  else
    verdict = "The two measurements fall on different sides of 50%: the claim is undecided here";
  v.set("s234.orient_verdict", verdict);
  v.verdict("s234.count_vs_perf", !profiled || std::abs(perf - large) < 0.25 * std::max(perf, large),
            "are of the same size", "differ widely");
  if (!profiled) {
    // The book includes this table: say why it has no numbers rather than leave it missing.
    ch::Table none;
    none.caption = "No perf profile in this run";
    none.header = {"part", "share of CPU samples"};
    none.add({profile ? "perf could not be run on this machine" : "skipped (--no-profile)", "-"});
    none.emit(o, "table_orient_share_perf");
  }
}

// ---- the worst case: a parabola --------------------------------------------------------------

// Points (x, x^2), x integer (exact doubles), inserted in the two orders along the parabola
// (x = 1..n and x = -n..-1), with ghost faces (DT(S)) and with super-triangles; the table gives
// N_cavity and N_search of each. Why one order costs O(i) per insertion and the other does not
// is exercise 2.3.4-3 (the argument is in the teacher's solutions page, book/solutions.md).
void parabola(const ch::Options& o) {
  const std::vector<long> sizes = o.quick ? std::vector<long>{500, 1000, 2000}
                                          : std::vector<long>{1000, 2000, 4000, 8000};
  ch::Table t;
  t.caption = "Points on y = x^2 inserted in increasing x: away from the apex (x = 1..n) and "
              "towards it (x = -n..-1); Listing 2.7 in super-triangles (first-face walk), and "
              "DT(S) with ghost faces (walk from the previous ball). Every result checked exactly.";
  t.header = {"method", "order", "n", "N_cavity", "largest cavity", "N_search", "t (s)", "t ratio"};
  std::map<int, std::vector<std::uint64_t>> trace;  // cavity sizes, largest n, per variant
  const char* names[3] = {"super-triangles", "super-triangles", "ghost faces"};
  for (int variant = 0; variant < 3; ++variant) {
    const bool towards = variant > 0, ghosts = variant == 2;
    double prev = 0;
    for (long n : sizes) {
      dt::Triangulation T;
      std::vector<dt::Vertex*> S;
      for (long i = 1; i <= n; ++i) {
        const double x = towards ? double(i - n - 1) : double(i);
        S.push_back(T.addVertex(x, x * x, i - 1));
      }
      dt::InsertionStats st;
      dt::InsertionScratch scratch;
      std::size_t first = 0;
      const double t0 = cpuSeconds();
      dt::Face* start = nullptr;
      if (ghosts) {
        // DT of the first three points with its ghost faces; the rest one by one below.
        dt::delaunayTrglHull(T, {S[0], S[1], S[2]}, dt::StartRule::LastCavity, &st);
        start = &T.faces().front();
        first = 3;
      } else {
        dt::initSuperTriangles(T, towards ? -double(n) : 1, 1, towards ? -1 : double(n),
                               double(n) * double(n));
      }
      std::uint64_t largest = 0;
      const bool keep = n == sizes.back() && towards;
      ch::Progress prog(ch::fmt("parabola %s n = %ld", names[variant], n), std::uint64_t(n));
      for (std::size_t i = first; i < S.size(); ++i) {
        // Listing 2.7's loop body, one point at a time to record each cavity's size.
        const std::uint64_t before = st.cavityFaces;
        dt::Face* ball = dt::insertVertex(T, ghosts ? start : &T.faces().front(), S[i], st, scratch);
        if (ball != nullptr) start = ball;
        largest = std::max(largest, st.cavityFaces - before);
        if (keep) trace[variant].push_back(st.cavityFaces - before);
        if (i % 256 == 0) prog.update(i);
      }
      const double sec = cpuSeconds() - t0;
      prog.update(std::uint64_t(n));
      checkOrThrow(T, "parabola");
      t.add({names[variant], towards ? "towards the apex" : "away from the apex", std::to_string(n),
             ch::fmt("%.1f", st.meanCavity()), std::to_string(largest),
             ch::fmt("%.1f", st.meanSearch()), ch::fmt("%.3g", sec),
             prev > 0 ? ch::fmt("%.1f", sec / prev) : "-"});
      prev = sec;
    }
  }
  t.emit(o, "table_parabola");
  std::string dat = ch::fmt("# i cavity(super-triangles) cavity(ghost faces); x = -n..-1, n = %ld\n",
                            sizes.back());
  const std::vector<std::uint64_t>& a = trace[1];
  const std::vector<std::uint64_t>& b = trace[2];
  for (std::size_t i = 0; i < a.size(); ++i) {
    // the ghost-face run starts at the 4th point: align both on the point's index
    const long j = long(i) - 3;
    dat += ch::fmt("%zu %llu %s\n", i + 1, (unsigned long long)a[i],
                   j >= 0 && std::size_t(j) < b.size() ? std::to_string(b[std::size_t(j)]).c_str() : "NaN");
  }
  ch::writeOut(o, "parabola_cavity.dat", dat);
  ch::runGnuplot(o, "fig_parabola_cavity.gp");
}

}  // namespace

int main(int argc, char** argv) {
  // The child run profiled by perf: one Table 2.1 triangulation, nothing else.
  if (argc == 3 && std::string(argv[1]) == "--profile-child") {
    table21Run(std::atol(argv[2]), false);
    return 0;
  }
  const ch::Program p{"sec2_3_4_algorithms",
                      "Section 2.3.4: Figure 2.10, Table 2.1, the search variants, the parabola.",
                      1000, 10000000, {"fig2_10", "fig_table2_1_search", "fig_parabola_cavity"},
                      {{"--no-profile", "", "skip the perf profile of one Table 2.1 run"}}};
  return ch::runMain(argc, argv, p, [](const ch::Options& o) {
    const bool profile = !o.has("--no-profile");
    ch::Values v(o, "sec2_3_4_algorithms");
    if (o.wants("fig2_10")) figure210(o);
    if (o.wants("fig_table2_1_search")) table21(o, v);
    if (o.everything()) {
      nsearchVariants(o, v);
      predicateShare(o, profile, v);
    }
    if (o.wants("fig_parabola_cavity")) parabola(o);
    v.write();
  });
}
