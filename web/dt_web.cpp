// The binding layer of the live figures (book/live.md): a few extern "C" functions over the
// library of code/, compiled to WebAssembly by web/build_wasm.sh. Nothing geometric is decided
// here: every sign comes from the library's exact predicates, every triangle from its kernels.
// Results go into two buffers (doubles and ints) that web/dt.js reads after each call.
#include <algorithm>
#include <chrono>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <limits>
#include <vector>

#include "bowyer_watson.h"
#include "cavity.h"
#include "check.h"
#include "fast_delaunay.h"
#include "generators.h"
#include "flip.h"
#include "hilbert.h"
#include "mesh.h"
#include "predicate_stages.h"
#include "predicates.h"
#include "search.h"
#include "triangulate.h"

#ifdef __EMSCRIPTEN__
#include <emscripten/emscripten.h>
#define DTW_EXPORT extern "C" EMSCRIPTEN_KEEPALIVE
#else
#define DTW_EXPORT extern "C"
#endif

namespace {

std::vector<double> outD;  // doubles of the last call (coordinates)
std::vector<int> outI;     // ints of the last call (counts, indices, signs)
std::string outS;          // the sentence that says what the last call showed (aria-live text)
std::string lastError;

// The enumerations a figure shows, in the order of the values the binding returns; the page
// reads them through dtw_record, so its labels cannot drift from the C++.
constexpr const char* kMapKinds[] = {"O(a, b, c), Figure 2.7 (a)", "O(c, b, a), Figure 2.7 (b)",
                                     "InC(a, b, c, d), Figure 2.8"};
constexpr int kMapKindCount = 3;
constexpr const char* kSignNames[] = {"negative", "zero", "positive"};  // indexed by sign + 1

// printf into a std::string (the sentences of the figures).
template <class... A>
std::string format(const char* f, A... a) {
  char buf[512];
  std::snprintf(buf, sizeof buf, f, a...);
  return buf;
}
const char* signName(int s) { return kSignNames[s + 1]; }

// One scene: a triangulation kept between calls (2.1/2.4 drag, 2.5 steps, 2.3.6 flips).
struct Scene {
  std::unique_ptr<dt::Triangulation> T;
  std::vector<double> xy;  // the points of S
  std::size_t next = 0;    // 2.5: the next point to insert
  double factor = 10;      // of the super-triangles (mode 1)
  dt::Face* start = nullptr;
  dt::InsertionStats stats;
  dt::InsertionScratch scratch;
  // 2.3.6: the flips recoverDelaunay did on a copy, replayed here one at a time.
  std::vector<std::array<long, 4>> flips;  // vertex ids: edge a b becomes c d
  std::size_t flipsDone = 0;
  bool superRemoved = false;
  std::vector<std::array<long, 3>> recovered;  // canonical triangles of the copy's result
};
// The scenes of the figures on a page, by the id the page chose (dtw_scene_select): two live
// figures on one page each keep their own triangulation.
std::map<int, Scene> scenes;
Scene* current = &scenes[0];
Scene& sc() { return *current; }

const dt::Face* firstLiveFace(const dt::Triangulation& T) {
  for (const dt::Face& f : T.faces())
    if (!f.deleted) return &f;
  return nullptr;
}

void putFace(const dt::Face* f) {
  for (const dt::Vertex* v : f->V) {
    outD.push_back(v->x);
    outD.push_back(v->y);
  }
}

// Canonical (smallest id first, orientation kept), sorted triangles by vertex ids.
std::vector<std::array<long, 3>> canonical(const dt::Triangulation& T, bool dropSuper) {
  std::vector<std::array<long, 3>> out;
  for (const dt::Face* f : T.finiteFaces()) {
    std::array<long, 3> t{f->V[0]->id, f->V[1]->id, f->V[2]->id};
    if (dropSuper && (t[0] < 0 || t[1] < 0 || t[2] < 0)) continue;
    std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
    out.push_back(t);
  }
  std::sort(out.begin(), out.end());
  return out;
}

// Walk, cavity, boundary and ball of p in the scene, without changing it. Writes, in outI:
// [walk, walkFinite, cavity, cavityFinite, boundary, ball, ballFinite, duplicate, outside],
// and in outD the finite walk faces, the finite cavity faces, the boundary edges with a finite
// end pair, the finite ball triangles (6, 6, 4, 6 doubles each), then p.
void describe(double px, double py, std::vector<dt::Face*>* cavityOut) {
  if (!sc().T) throw std::logic_error("no scene: call dtw_scene_init first");
  dt::Vertex p(px, py, 0, -100);
  dt::SearchInfo info;
  std::vector<const dt::Face*> walk;
  info.trace = &walk;
  info.maxSteps = sc().T->faces().size() + 1;
  dt::Face* seed = dt::lineSearch(sc().start, &p, &info);
  std::vector<dt::Face*> cavity, otherSide;
  std::vector<dt::Edge> bnd;
  if (seed) {
    dt::delaunayCavity(seed, &p, cavity, bnd, otherSide);
    for (dt::Face* f : cavity) f->deleted = false;  // a query: leave the scene as it was
    for (dt::Face* f : otherSide) f->deleted = false;
  }
  auto finite = [](const dt::Face* f) { return !f->isGhost(); };
  std::size_t walkFinite = 0, cavFinite = 0, ballFinite = 0, bndFinite = 0;
  for (const dt::Face* f : walk) walkFinite += finite(f);
  for (const dt::Face* f : cavity) cavFinite += finite(f);
  // With ghost faces the walk never falls off the domain (info.outside stays false): p is
  // outside the hull when it lies strictly beyond the real edge of a ghost face it conflicts
  // with (on the edge itself it is on the hull, not outside).
  bool outside = false;
  for (const dt::Face* f : cavity) {
    const int i = f->infiniteIndex();
    if (i >= 0 && dt::orientationTest(f->V[(i + 1) % 3], f->V[(i + 2) % 3], &p) > 0) outside = true;
  }
  for (const dt::Edge& e : bnd) {
    const bool fin = !e.V[0]->infinite && !e.V[1]->infinite;
    ballFinite += fin;
    bndFinite += fin;
  }
  outI = {int(walk.size()), int(walkFinite), int(cavity.size()), int(cavFinite),
          int(bnd.size()), int(bnd.size()), int(ballFinite), info.duplicate != nullptr,
          outside || info.outside, int(bndFinite)};
  outD.clear();
  for (const dt::Face* f : walk)
    if (finite(f)) putFace(f);
  for (const dt::Face* f : cavity)
    if (finite(f)) putFace(f);
  for (const dt::Edge& e : bnd)
    if (!e.V[0]->infinite && !e.V[1]->infinite)
      outD.insert(outD.end(), {e.V[0]->x, e.V[0]->y, e.V[1]->x, e.V[1]->y});
  for (const dt::Edge& e : bnd)
    if (!e.V[0]->infinite && !e.V[1]->infinite)
      outD.insert(outD.end(), {e.V[0]->x, e.V[0]->y, e.V[1]->x, e.V[1]->y, px, py});
  outD.push_back(px);
  outD.push_back(py);
  if (cavityOut) *cavityOut = cavity;
  outS = format("p = (%.4g, %.4g). The walk to p visits %zu face%s.", px, py, walk.size(),
                walk.size() == 1 ? "" : "s");
  if (info.duplicate) {
    outS += " p is a vertex of the triangulation: no cavity, nothing to insert.";
    return;
  }
  outS += format(" Cavity |𝒞| = %zu triangles, boundary |∂𝒞| = %zu edges, ball |𝓑| = %zu new "
                 "triangles.", cavFinite, bndFinite, ballFinite);
  if (outside)
    outS += format(" p is outside the convex hull: the cavity also holds %zu ghost faces, "
                   "which are not drawn.", cavity.size() - cavFinite);
}

template <class F>
int guarded(F&& f) {
  try {
    lastError.clear();
    return f();
  } catch (const std::exception& e) {
    lastError = e.what();
    return -1;
  }
}

}  // namespace

/// Pointers and sizes of the result buffers, read by web/dt.js after each call.
DTW_EXPORT double* dtw_out_d() { return outD.data(); }
DTW_EXPORT int dtw_out_d_size() { return int(outD.size()); }
DTW_EXPORT int* dtw_out_i() { return outI.data(); }
DTW_EXPORT int dtw_out_i_size() { return int(outI.size()); }
DTW_EXPORT const char* dtw_error() { return lastError.c_str(); }
/// The sentence of the last call that shows something (a query, a step, a map, an order): what
/// the figure now shows, in words, for its aria-live region.
DTW_EXPORT const char* dtw_out_s() { return outS.c_str(); }

/// The one record of the enumerations the figures show, as JSON: the predicate stages in the
/// order of dt::pred::Stage (the values of lastPredicateStage and of dtw_predicate_map's
/// third int), the map kinds in the order of dtw_predicate_map's `kind`, the sign names
/// (indexed by sign + 1). The page draws stage s in the style's series colour s.
DTW_EXPORT const char* dtw_record() {
  auto list = [](const char* const* names, int n) {
    std::string r = "[";
    for (int i = 0; i < n; ++i) r += std::string(i ? ", \"" : "\"") + names[i] + "\"";
    return r + "]";
  };
  outS = "{\"stages\": " + list(dt::pred::kStageNames, dt::pred::kStageCount) +
         ", \"mapKinds\": " + list(kMapKinds, kMapKindCount) + ", \"signs\": " +
         list(kSignNames, 3) + "}";
  return outS.c_str();
}

/// DT(S) of n points xy (x0 y0 x1 y1 ...) by the fast kernel (dt::fastDelaunay, the command
/// line's default): outI receives the counter-clockwise index triples. Returns the number of
/// triangles, or -1 (dtw_error says why). With `check`, the result is validated exactly
/// (dt::checkDelaunay) and -1 returned if it fails.
DTW_EXPORT int dtw_triangulate(const double* xy, int n, int check) {
  return guarded([&] {
    std::vector<double> pts(xy, xy + 2 * std::size_t(n));
    dt::FastResult r = dt::fastDelaunay(pts);
#ifdef DT_WEB_PLANTED_DEFECT
    // The planted defect of the browser test's self-check (ctest web_browser_planted): one
    // triangle turned clockwise, in the WebAssembly build only. The test must notice.
    if (!r.tri.empty()) std::swap(r.tri[0][1], r.tri[0][2]);
#endif
    if (check) {
      const dt::CheckReport rep = dt::checkDelaunay(pts, r.tri);
      if (!rep.ok) throw std::runtime_error("checkDelaunay: " + rep.error);
    }
    outI.clear();
    for (const auto& t : r.tri) outI.insert(outI.end(), t.begin(), t.end());
    return int(r.tri.size());
  });
}

/// The same DT(S) by the corrected listings (dt::delaunayTrglHull, input order), as index
/// triples; -1 on error.
DTW_EXPORT int dtw_triangulate_listings(const double* xy, int n) {
  return guarded([&] {
    dt::Triangulation T;
    std::vector<dt::Vertex*> S;
    for (int i = 0; i < n; ++i) S.push_back(T.addVertex(xy[2 * i], xy[2 * i + 1], i));
    dt::delaunayTrglHull(T, S, dt::StartRule::LastCavity);
    const dt::CheckReport rep = dt::checkTriangulation(T);
    if (!rep.ok) throw std::runtime_error("checkTriangulation: " + rep.error);
    outI.clear();
    for (const auto& t : canonical(T, false)) outI.insert(outI.end(), t.begin(), t.end());
    return int(outI.size() / 3);
  });
}

/// Makes scene `id` the one the scene functions below work on (a new one is empty until
/// dtw_scene_init). Returns 0.
DTW_EXPORT int dtw_scene_select(int id) {
  current = &scenes[id];
  return 0;
}

/// Starts a scene on n points. mode 0: DT(S) with ghost faces (2.2.2), for the cavity and ball
/// of a moving point (2.1, 2.4); mode 1: the two super-triangles of 2.2.1 (`factor` times the
/// box of S), the points to be inserted one at a time by dtw_scene_step (2.5). Returns the
/// number of finite faces, -1 on error.
DTW_EXPORT int dtw_scene_init(const double* xy, int n, int mode, double factor) {
  return guarded([&] {
    sc() = Scene{};
    sc().T = std::make_unique<dt::Triangulation>();
    sc().xy.assign(xy, xy + 2 * std::size_t(n));
    std::vector<dt::Vertex*> S;
    for (int i = 0; i < n; ++i) S.push_back(sc().T->addVertex(xy[2 * i], xy[2 * i + 1], i));
    if (mode == 0) {
      dt::delaunayTrglHull(*sc().T, S, dt::StartRule::LastCavity);
    } else {
      const double inf = std::numeric_limits<double>::infinity();  // the points' bounding box
      double x0 = inf, x1 = -inf, y0 = inf, y1 = -inf;
      for (int i = 0; i < n; ++i) {
        x0 = std::min(x0, xy[2 * i]);
        x1 = std::max(x1, xy[2 * i]);
        y0 = std::min(y0, xy[2 * i + 1]);
        y1 = std::max(y1, xy[2 * i + 1]);
      }
      dt::initSuperTriangles(*sc().T, x0, y0, x1, y1, factor);
    }
    sc().factor = factor;
    sc().start = const_cast<dt::Face*>(firstLiveFace(*sc().T));
    outS = mode == 0 ? format("DT(S) of %d points.", n)
                     : format("DT_0: the two super-triangles; %d points to insert.", n);
    return int(sc().T->numFiniteFaces());
  });
}

/// The finite faces of the scene: outD receives 6 doubles per face, outI the vertex ids
/// (3 per face). Returns the number of faces.
DTW_EXPORT int dtw_scene_mesh() {
  outD.clear();
  outI.clear();
  if (!sc().T) return 0;
  const auto faces = sc().T->finiteFaces();
  for (const dt::Face* f : faces) {
    putFace(f);
    for (const dt::Vertex* v : f->V) outI.push_back(int(v->id));
  }
  return int(faces.size());
}

/// Walk, cavity, boundary and ball of the point (px, py) in the scene, which stays unchanged
/// (see describe for the layout of outI and outD). The walk starts at the scene's start face
/// (the last ball, as StartRule::LastCavity). Returns 0, -1 on error.
DTW_EXPORT int dtw_scene_query(double px, double py) {
  return guarded([&] {
    describe(px, py, nullptr);
    return 0;
  });
}

/// 2.5: inserts the next point of S with dt::insertVertex (Listing 2.7), after describing its
/// walk and cavity as dtw_scene_query does; outI[10] gets N_search of this insertion as the
/// kernel counted it (InsertionStats::searchSteps), outI[11] the index of the point. Returns
/// the number of points left, or -1 when none is left or on error.
DTW_EXPORT int dtw_scene_step() {
  return guarded([&] {
    if (sc().next >= sc().xy.size() / 2) throw std::out_of_range("no point left");
    const std::size_t i = sc().next++;
    const double px = sc().xy[2 * i], py = sc().xy[2 * i + 1];
    describe(px, py, nullptr);
    dt::Vertex* v = &sc().T->vertices()[i];
    const std::uint64_t before = sc().stats.searchSteps;
    dt::Face* f = dt::insertVertex(*sc().T, sc().start, v, sc().stats, sc().scratch);
    if (f) sc().start = f;
    outI.push_back(int(sc().stats.searchSteps - before));
    outI.push_back(int(i));
    outS = format("Point %zu of %zu inserted. ", i + 1, sc().xy.size() / 2) + outS +
           format(" N_search = %llu for this point, %llu summed over the %zu points inserted; "
                  "%zu left.", (unsigned long long)(sc().stats.searchSteps - before),
                  (unsigned long long)sc().stats.searchSteps, i + 1, sc().xy.size() / 2 - sc().next);
    return int(sc().xy.size() / 2 - sc().next);
  });
}

/// 2.3.6: after a mode-1 scene has all its points, runs dt::recoverDelaunay on a copy to get
/// the flips, which dtw_flip_step then replays on the scene one at a time. Returns the number
/// of flips.
DTW_EXPORT int dtw_flip_prepare() {
  return guarded([&] {
    if (sc().next < sc().xy.size() / 2) throw std::logic_error("insert every point first");
    dt::Triangulation copy;
    std::vector<dt::Vertex*> S;
    const std::size_t n = sc().xy.size() / 2;
    for (std::size_t i = 0; i < n; ++i)
      S.push_back(copy.addVertex(sc().xy[2 * i], sc().xy[2 * i + 1], long(i)));
    double x0 = sc().xy[0], x1 = x0, y0 = sc().xy[1], y1 = y0;
    for (std::size_t i = 0; i < n; ++i) {
      x0 = std::min(x0, sc().xy[2 * i]);
      x1 = std::max(x1, sc().xy[2 * i]);
      y0 = std::min(y0, sc().xy[2 * i + 1]);
      y1 = std::max(y1, sc().xy[2 * i + 1]);
    }
    dt::initSuperTriangles(copy, x0, y0, x1, y1, sc().factor);
    dt::delaunayTrgl(copy, S, dt::StartRule::LastCavity);
    if (canonical(copy, false) != canonical(*sc().T, false))
      throw std::logic_error("the copy of DT(S0 u S) differs from the scene");
    std::vector<std::array<const dt::Vertex*, 4>> log;
    dt::recoverDelaunay(copy, dt::RecoveryRule::Full, &log);
    sc().flips.clear();
    for (const auto& l : log) sc().flips.push_back({l[0]->id, l[1]->id, l[2]->id, l[3]->id});
    sc().flipsDone = 0;
    sc().superRemoved = false;
    sc().recovered = canonical(copy, true);
    outS = format("DT(S0 ∪ S), all %zu points inserted into the super-triangles: %zu flips "
                  "recover DT(S).", n, sc().flips.size());
    return int(sc().flips.size());
  });
}

/// Replays the next flip with dt::flipEdge on the scene: outD gets the old edge and the new
/// one (8 doubles). When every flip is done, one more call removes the faces touching a super
/// vertex (by comparison only: it checks that what is left is the copy's DT(S)) and returns 0.
/// Returns the number of flips left, or -1 on error.
DTW_EXPORT int dtw_flip_step() {
  return guarded([&] {
    outD.clear();
    outI.clear();
    if (sc().flipsDone == sc().flips.size()) {
      if (canonical(*sc().T, true) != sc().recovered)
        throw std::logic_error("replayed flips do not give recoverDelaunay's DT(S)");
      sc().superRemoved = true;
      outS = format("All %zu flips done: removing the faces that touch a super vertex leaves "
                    "DT(S), the same triangles as recoverDelaunay's.", sc().flips.size());
      return 0;
    }
    const auto& fl = sc().flips[sc().flipsDone];
    for (dt::Face& f : sc().T->faces()) {
      if (f.deleted) continue;
      for (int k = 0; k < 3; ++k)
        if (f.V[k]->id == fl[0] && f.V[(k + 1) % 3]->id == fl[1]) {
          const dt::Vertex *a = f.V[k], *b = f.V[(k + 1) % 3];
          if (!dt::flipEdge(&f, k)) throw std::logic_error("flip refused");
          const dt::Vertex* c = nullptr;
          const dt::Vertex* d = nullptr;
          for (const dt::Vertex* v : f.V)
            if (v != a && v != b) (c ? d : c) = v;
          outD = {a->x, a->y, b->x, b->y, c->x, c->y, d ? d->x : c->x, d ? d->y : c->y};
          outI = {int(a->id), int(b->id), int(fl[2]), int(fl[3])};
          ++sc().flipsDone;
          outS = format("Flip %zu of %zu: edge p%ld p%ld becomes p%ld p%ld (negative numbers are "
                        "super vertices).", sc().flipsDone, sc().flips.size(), a->id, b->id,
                        fl[2], fl[3]);
          return int(sc().flips.size() - sc().flipsDone);
        }
    }
    throw std::logic_error("flip edge not found");
  });
}

/// Orientation of a, b, c: outI = [naive sign, robust (exact) sign, stage that decided it
/// (dt::lastPredicateStage, a dt::pred::Stage: 0 filter, 1 small multiples, 2 wide integers,
/// 3 extended exponent, 4 GMP; dtw_record names them)]. Returns the exact sign.
DTW_EXPORT int dtw_orient(double ax, double ay, double bx, double by, double cx, double cy) {
  const int naive = dt::orient2dNaive(ax, ay, bx, by, cx, cy);
  const int exact = dt::orient2d(ax, ay, bx, by, cx, cy);
  outI = {naive, exact, dt::lastPredicateStage()};
  return exact;
}

/// incircle(a, b, c, d), same layout as dtw_orient.
DTW_EXPORT int dtw_incircle(double ax, double ay, double bx, double by, double cx, double cy,
                            double dx, double dy) {
  const int naive = dt::incircleNaive(ax, ay, bx, by, cx, cy, dx, dy);
  const int exact = dt::incircle(ax, ay, bx, by, cx, cy, dx, dy);
  outI = {naive, exact, dt::lastPredicateStage()};
  return exact;
}

namespace {
// One cell of a predicate map: the moving point m in predicate `kind` (see dtw_predicate_map);
// o gets naive sign, exact sign, stage.
void mapCell(int kind, double mx, double my, double bx, double by, double cx, double cy, double ex,
             double ey, int* o) {
  if (kind == 0) {
    o[0] = dt::orient2dNaive(mx, my, bx, by, cx, cy);
    o[1] = dt::orient2d(mx, my, bx, by, cx, cy);
  } else if (kind == 1) {
    o[0] = dt::orient2dNaive(cx, cy, bx, by, mx, my);
    o[1] = dt::orient2d(cx, cy, bx, by, mx, my);
  } else {
    o[0] = dt::incircleNaive(bx, by, cx, cy, ex, ey, mx, my);
    o[1] = dt::incircle(bx, by, cx, cy, ex, ey, mx, my);
  }
  o[2] = dt::lastPredicateStage();
}
}  // namespace

/// The predicate maps of Figures 2.7 / 2.8 (and of the incircle figure): the moving point
/// m = (x0 + i step, y0 + j step), 0 <= i, j < n (row j, column i), in O(m, b, c) (kind 0),
/// O(c, b, m) (kind 1) or InC(b, c, e, m) with e = (ex, ey) (kind 2). outI gets 3 ints per
/// cell (naive sign, exact sign, stage), then the number of cells each stage decided (in
/// stage order), then the number of cells where the naive sign is wrong; outS says so in
/// words. Returns n*n, or -1 for an unknown kind.
DTW_EXPORT int dtw_predicate_map(int kind, double x0, double y0, double step, int n, double bx,
                                 double by, double cx, double cy, double ex, double ey) {
  return guarded([&] {
    if (kind < 0 || kind >= kMapKindCount || n < 1) throw std::invalid_argument("bad map");
    const std::size_t cells = std::size_t(n) * n;
    outI.assign(3 * cells, 0);
    dt::pred::StageCounts stages;
    int wrong = 0;
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        int* o = &outI[3 * (std::size_t(j) * n + i)];
        mapCell(kind, x0 + i * step, y0 + j * step, bx, by, cx, cy, ex, ey, o);
        stages.add(o[2]);
        wrong += o[0] != o[1];
      }
    outS = format("%s with the cell %.6g × 2⁻⁵³ wide: the naive sign is wrong in %d of %zu "
                  "cells. Decided by:", kMapKinds[kind], std::ldexp(step, 53), wrong, cells);
    for (int s = 0; s < dt::pred::kStageCount; ++s) {
      outI.push_back(int(stages[s]));
      outS += format("%s %s %llu cells", s ? ";" : "", dt::pred::kStageNames[s],
                     (unsigned long long)stages[s]);
    }
    outI.push_back(wrong);
    outS += ".";
    return n * n;
  });
}

/// One cell of a map, for the reader's cursor: outI = naive sign, exact sign, stage (as
/// dtw_predicate_map); outS says it in words. Returns 0, or -1 for an unknown kind.
DTW_EXPORT int dtw_map_cell(int kind, int i, int j, double x0, double y0, double step, double bx,
                            double by, double cx, double cy, double ex, double ey) {
  return guarded([&] {
    if (kind < 0 || kind >= kMapKindCount) throw std::invalid_argument("bad map");
    outI.assign(3, 0);
    const double mx = x0 + i * step, my = y0 + j * step;
    mapCell(kind, mx, my, bx, by, cx, cy, ex, ey, outI.data());
    outS = format("Cell (%d, %d), the moving point at (%.17g, %.17g): naive sign %s, exact sign %s%s, "
                  "decided by the stage %s.", i, j, mx, my, signName(outI[0]), signName(outI[1]),
                  outI[0] != outI[1] ? " (the naive sign is wrong)" : "",
                  dt::pred::kStageNames[outI[2]]);
    return 0;
  });
}

/// 2.3.5: the Hilbert order of the points on the fixed curve of the given depth (1..31;
/// dt::hilbertOrder, not adaptive: the notes' grid), into outI. Returns n or -1.
DTW_EXPORT int dtw_hilbert_order(const double* xy, int n, int depth) {
  return guarded([&] {
    std::vector<double> pts(xy, xy + 2 * std::size_t(n));
    const auto ord = dt::hilbertOrder(pts, depth, false);
    outI.assign(ord.begin(), ord.end());
    outS = format("Hilbert order of %d points on the curve of depth %d (4^%d cells), drawn as one "
                  "polyline.", n, depth, depth);
    return n;
  });
}

/// 2.3.5: the BRIO order (dt::brioOrder: rounds of dt::brioRoundSizes, each Hilbert-sorted on
/// the curve of the given depth, 0 = auto): outI gets the n indices, then the start of each
/// round in that order. Returns the number of rounds or -1.
DTW_EXPORT int dtw_brio_order(const double* xy, int n, int seed, int depth) {
  return guarded([&] {
    std::vector<double> pts(xy, xy + 2 * std::size_t(n));
    std::vector<std::size_t> starts;
    const auto ord = dt::brioOrder(pts, std::uint64_t(seed), depth, &starts, false);
    outI.assign(ord.begin(), ord.end());
    outI.insert(outI.end(), starts.begin(), starts.end());
    outS = format("BRIO order of %d points: %zu rounds, of sizes", n, starts.size());
    for (std::size_t r = 0; r < starts.size(); ++r)
      outS += format("%s %zu", r ? "," : "", (r + 1 < starts.size() ? starts[r + 1] : std::size_t(n)) - starts[r]);
    outS += ", each in Hilbert order.";
    return int(starts.size());
  });
}

/// Speed (book/live.md): triangulates dt::uniformPoints(n, seed) with dt::fastDelaunay and
/// returns the seconds it took (points already in memory); outI gets the triangle count.
/// web_native_cases --bench runs the same function on the same points natively.
DTW_EXPORT double dtw_bench_triangulate(int n, int seed) {
  const std::vector<double> xy = dt::uniformPoints(std::size_t(n), std::uint64_t(seed));
  const auto t0 = std::chrono::steady_clock::now();
  const dt::FastResult r = dt::fastDelaunay(xy);
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  outI = {int(r.tri.size())};
  return s;
}
