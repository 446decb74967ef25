#include "delaunay.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numeric>

#include "check.h"
#include "fast_delaunay.h"
#include "fast_parallel.h"
#include "flip.h"
#include "hilbert.h"
#include "triangulate.h"

#if defined(__unix__) && !defined(__EMSCRIPTEN__)
#include <sys/resource.h>
#define DT_HAVE_GETRUSAGE 1
#endif

namespace dt {

double systemSeconds() {
#ifdef DT_HAVE_GETRUSAGE
  struct rusage ru;
  if (getrusage(RUSAGE_SELF, &ru) == 0)
    return double(ru.ru_stime.tv_sec) + 1e-6 * double(ru.ru_stime.tv_usec);
#endif
  return -1;
}

namespace {

double since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

// The system's CPU time since systemSeconds() gave s0 (-1 where it is not known).
double systemSince(double s0) {
  const double s1 = systemSeconds();
  return s0 < 0 || s1 < 0 ? -1 : s1 - s0;
}

// The fast kernel: it orders the points itself, finds the duplicates as it meets them (no sort
// beforehand), and returns the triangles numbered in its insertion order with the points in
// that order: a check or a writer then reads memory in a spatially coherent order.
void fastKernel(std::vector<double>& xy, const TriangulateOptions& opt, TriangulateResult& r) {
  const std::size_t n = xy.size() / 2;
  FastOptions fo;
  fo.order = opt.order;
  if (opt.progress)
    fo.progress = [&](std::size_t done, std::size_t total, const FastStats& s) {
      opt.progress(done, total, s.walkSteps, s.cavityFaces);
    };
  fo.insertionNumbering = true;
  fo.progressEvery = 1024;
  if (opt.phase) opt.phase("triangulating " + std::to_string(n) + " points (fast kernel)", n);
  const auto t0 = std::chrono::steady_clock::now();
  const double sys0 = systemSeconds();
  ParallelStats ps;
  FastResult fr =
      fastDelaunayParallel(xy, fo.order == InsertionOrder::Brio ? opt.threads : 1, fo, &ps);
  r.seconds = since(t0);
  r.systemSeconds = systemSince(sys0);
  std::vector<double>().swap(xy);  // fr.points holds them, in insertion order
  r.tri = std::move(fr.tri);
  r.xy = std::move(fr.points);
  r.input = std::move(fr.inserted);
  r.insertions = fr.stats.insertions;
  r.walkSteps = fr.stats.walkSteps;
  r.cavityFaces = fr.stats.cavityFaces;
  r.duplicates = std::move(fr.duplicates);
  r.threadsUsed = ps.threadsUsed;
  r.threadsReason = parallelReasonName(opt.threads > 1 && fo.order != InsertionOrder::Brio
                                           ? ParallelReason::SequentialOnly
                                           : ps.reason);
  std::vector<char> isDup(n, 0);
  for (const auto& d : r.duplicates) isDup[std::size_t(d.first)] = 1;
  r.used.resize(n);
  for (std::size_t i = 0; i < n; ++i) r.used[i] = !isDup[std::size_t(r.input[i])];
}

// The input index of the point farthest from the origin (the one super-triangles cannot enclose).
std::size_t farthest(const std::vector<Vertex*>& S) {
  std::size_t best = 0;
  double m = -1;
  for (const Vertex* v : S) {
    const double a = std::max(std::fabs(v->x), std::fabs(v->y));
    if (a > m) m = a, best = std::size_t(v->id);
  }
  return best;
}

// The listings (triangulate.h), in chunks of insertions with progress reports between them.
void insertInChunks(Triangulation& T, const std::vector<Vertex*>& S, std::size_t from,
                    InsertionStats& st, const TriangulateOptions& opt) {
  const std::size_t chunk = 1024;
  for (std::size_t a = from; a < S.size(); a += chunk) {
    const std::vector<Vertex*> part(S.begin() + long(a),
                                    S.begin() + long(std::min(S.size(), a + chunk)));
    delaunayTrgl(T, part, StartRule::LastCavity, &st);
    if (opt.progress) opt.progress(a + part.size(), S.size(), st.searchSteps, st.cavityFaces);
  }
}

void listingsKernel(const std::vector<double>& xy, const TriangulateOptions& opt,
                    TriangulateResult& r) {
  const std::size_t n = xy.size() / 2;
  for (double v : xy)
    if (!std::isfinite(v)) throw std::invalid_argument("triangulate: a coordinate is not finite");
  // Duplicates: sort by (x, y); keep the first occurrence (smallest number).
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return xy[2 * a] < xy[2 * b] || (xy[2 * a] == xy[2 * b] && xy[2 * a + 1] < xy[2 * b + 1]);
  });
  std::vector<char> keep(n, 1);
  std::size_t runStart = n ? order[0] : 0;  // first occurrence of the current run of equals
  for (std::size_t k = 1; k < n; ++k) {
    const std::size_t a = order[k - 1], b = order[k];
    if (xy[2 * a] == xy[2 * b] && xy[2 * a + 1] == xy[2 * b + 1]) {
      keep[b] = 0;
      r.duplicates.emplace_back(int(b), int(runStart));
    } else {
      runStart = b;
    }
  }
  std::sort(r.duplicates.begin(), r.duplicates.end());
  Triangulation T;
  std::vector<Vertex*> S;
  S.reserve(n - r.duplicates.size());
  for (std::size_t i = 0; i < n; ++i)
    if (keep[i]) S.push_back(T.addVertex(xy[2 * i], xy[2 * i + 1], long(i)));
  const auto t0 = std::chrono::steady_clock::now();
  const double sys0 = systemSeconds();
  if (opt.order != InsertionOrder::Input && S.size() > 1) {
    // 2.3.5: with the walk started in the previous cavity, a Hilbert (or BRIO) order keeps the
    // walks short; in file order they can grow like sqrt(n). Timed with the insertions. BRIO is
    // the fast kernel's: the same rounds, whatever the kernel.
    std::vector<double> pts;
    pts.reserve(2 * S.size());
    for (const Vertex* v : S) pts.insert(pts.end(), {v->x, v->y});
    const FastOptions same;  // the fast kernel's seed and rounds
    const std::vector<std::size_t> idx =
        opt.order == InsertionOrder::Brio           ? brioCoinOrder(pts, same.seed, same.rounds)
        : opt.order == InsertionOrder::BrioDoubling ? brioOrder(pts, same.seed)
                                                    : hilbertOrder(pts);
    std::vector<Vertex*> sorted(S.size());
    for (std::size_t k = 0; k < idx.size(); ++k) sorted[k] = S[idx[k]];
    S.swap(sorted);
  }
  InsertionStats st;
  if (opt.method == BuildMethod::Super) {
    // 2.2.1: super-triangles around the box, DT(S0 u S), then the flips of 2.3.6. A flat or
    // collinear input is rejected as by the hull method (it has no DT(S)).
    if (S.size() < 3) throw DegenerateInput("fewer than 3 distinct points");
    bool flat = true;
    for (std::size_t i = 2; i < S.size() && flat; ++i) flat = orientationTest(S[0], S[1], S[i]) == 0;
    if (flat) throw DegenerateInput("all points are collinear");
    double x0 = S[0]->x, x1 = x0, y0 = S[0]->y, y1 = y0;
    for (const Vertex* v : S) {
      x0 = std::min(x0, v->x), x1 = std::max(x1, v->x);
      y0 = std::min(y0, v->y), y1 = std::max(y1, v->y);
    }
    // Any enclosing size gives the exact DT(S) (2.3.6); near the overflow threshold the default
    // factor 10 may not fit in doubles, so smaller ones are tried.
    for (double factor : {10.0, 2.0, 1.01}) {
      try {
        initSuperTriangles(T, x0, y0, x1, y1, factor);
        break;
      } catch (const DegenerateInput&) {
        if (factor == 1.01)
          throw UnsupportedInput(
              "--method super cannot enclose points this close to the overflow threshold "
              "(|x| or |y| near 1.8e308) in double super-triangles; use --method hull",
              farthest(S));
      }
    }
    if (opt.phase) opt.phase("inserting " + std::to_string(S.size()) + " points (listings)", S.size());
    insertInChunks(T, S, 0, st, opt);
    if (opt.phase) opt.phase("recovering DT(S) by flips", S.size());
    r.recoveryFlips = recoverDelaunay(T).flips;
  } else {
    // delaunayTrglHull on the shortest prefix of S that spans a triangle (on a collinear S it
    // throws DegenerateInput), then the other points in chunks.
    std::size_t k = 2;
    while (k < S.size() && orientationTest(S[0], S[1], S[k]) == 0) ++k;
    k = std::min(k + 1, S.size());
    delaunayTrglHull(T, std::vector<Vertex*>(S.begin(), S.begin() + long(k)), StartRule::LastCavity,
                     &st);
    if (opt.phase) opt.phase("inserting " + std::to_string(S.size()) + " points (listings)", S.size());
    insertInChunks(T, S, k, st, opt);
  }
  r.seconds = since(t0);
  r.systemSeconds = systemSince(sys0);
  r.insertions = st.insertions;
  r.walkSteps = st.searchSteps;
  r.cavityFaces = st.cavityFaces;
  PlainMesh m = extractMesh(T, true);
  if (m.ids.size() != S.size())
    throw std::logic_error("triangulate: the listings' mesh misses a point");
  r.xy = std::move(m.xy);
  r.tri = std::move(m.tri);
  r.input.assign(m.ids.begin(), m.ids.end());
}

}  // namespace

TriangulateResult triangulate(std::vector<double> xy, const TriangulateOptions& opt) {
  if (xy.size() % 2 != 0) throw std::invalid_argument("triangulate: odd number of coordinates");
  TriangulateResult r;
  if (opt.kernel == KernelChoice::Fast && opt.method == BuildMethod::Hull)
    fastKernel(xy, opt, r);
  else
    listingsKernel(xy, opt, r);
  if (opt.threads > 1 && !(opt.kernel == KernelChoice::Fast && opt.method == BuildMethod::Hull))
    r.threadsReason = parallelReasonName(ParallelReason::SequentialOnly);
  if (opt.check) {
    if (opt.phase) opt.phase("checking the result with exact predicates", r.xy.size() / 2);
    const CheckReport c = checkDelaunay(r.xy, r.tri, r.used.empty() ? nullptr : &r.used);
    if (!c.ok) throw std::logic_error("the result fails the exact check: " + c.error);
    r.checked = true;
  }
  return r;
}

BuildMethod methodNamed(const std::string& w) {
  if (w == "hull") return BuildMethod::Hull;
  if (w == "super") return BuildMethod::Super;
  throw std::invalid_argument("--method must be 'hull' or 'super'");
}

KernelChoice kernelNamed(const std::string& w) {
  if (w == "fast") return KernelChoice::Fast;
  if (w == "listings") return KernelChoice::Listings;
  throw std::invalid_argument("--kernel must be 'fast' or 'listings'");
}

}  // namespace dt
