#include "triangulate.h"

#include <cmath>
#include <unordered_map>

#include "adjacency.h"
#include "cavity.h"
#include "predicates.h"
#include "search.h"

namespace dt {

//! [insertVertex]
Face* insertVertex(Triangulation& T, Face* start, Vertex* p, InsertionStats& stats,
                   InsertionScratch& scratch) {
  SearchInfo info;
  info.maxSteps = T.faces().size() + 1;
  Face* f = lineSearch(start, p, &info);
  stats.searchSteps += info.steps;
  if (f == nullptr) {
    if (info.duplicate != nullptr) {
      ++stats.duplicates;
      return nullptr;
    }
    throw std::out_of_range("point (" + std::to_string(p->x) + ", " + std::to_string(p->y) +
                            ") lies outside the super-triangles");
  }
  std::vector<Face*>& cavity = scratch.cavity;
  std::vector<Edge>& bnd = scratch.bnd;
  std::vector<Face*>& otherSide = scratch.otherSide;
  cavity.clear();
  bnd.clear();
  otherSide.clear();
  delaunayCavity(f, p, cavity, bnd, otherSide);
  // Property 2.1.1 (no vertex inside the cavity) makes the cavity a disk whose boundary has
  // |C| + 2 edges. Listing 2.7 wrote "throw;", which outside a handler calls std::terminate.
  if (bnd.size() != cavity.size() + 2)
    throw std::logic_error("delaunayTrgl: cavity boundary has " + std::to_string(bnd.size()) +
                           " edges for " + std::to_string(cavity.size()) + " faces");
  stats.cavityFaces += cavity.size();
  ++stats.insertions;
  const std::size_t cSize = cavity.size();
  for (std::size_t i = 0; i < cSize; i++) {
    // reuse memory slots of invalid elements
    Face* c = cavity[i];
    c->deleted = false;
    c->F[0] = c->F[1] = c->F[2] = nullptr;
    // Listing 2.7 read bnd[i].V[0], which its Edge (vmin, vmax) did not have; the sorted pair
    // would also lose the orientation and create clockwise triangles.
    c->V[0] = bnd[i].V[0];
    c->V[1] = bnd[i].V[1];
    c->V[2] = p;
  }
  for (std::size_t i = cSize; i < cSize + 2; i++) {
    // Listing 2.7 wrote T.push_back[newf] (brackets for parentheses).
    cavity.push_back(T.addFace(bnd[i].V[0], bnd[i].V[1], p));
  }
  for (Face* o : otherSide) {
    // Listing 2.7 left these faces marked deleted: the next cavity search then stopped at
    // them as if they had been visited.
    o->deleted = false;
    cavity.push_back(o);
  }
  computeAdjacencies(cavity);
  return cavity[0];
}
//! [insertVertex]

void initSuperTriangles(Triangulation& T, double xmin, double ymin, double xmax, double ymax,
                        double factor) {
  const double cx = 0.5 * xmin + 0.5 * xmax, cy = 0.5 * ymin + 0.5 * ymax;
  double half = 0.5 * std::max(xmax - xmin, ymax - ymin);
  if (!(half > 0)) half = std::max({std::fabs(cx), std::fabs(cy), 1.0});
  const double R = factor * half;
  const double xs[2] = {cx - R, cx + R}, ys[2] = {cy - R, cy + R};
  for (double v : {xs[0], xs[1], ys[0], ys[1]})
    if (!std::isfinite(v))
      throw DegenerateInput("super-triangles: corners overflow for this bounding box");
  if (!(xs[0] < xmin && xmax < xs[1] && ys[0] < ymin && ymax < ys[1]))
    throw DegenerateInput("super-triangles: corners do not strictly enclose the points");
  // p_{-3} is the upper-left corner and p_{-4} the lower-right one, so that both faces of
  // Algorithm 1, p_{-1} p_{-2} p_{-3} and p_{-2} p_{-1} p_{-4}, are counter-clockwise.
  Vertex* m1 = T.addVertex(xs[0], ys[0], -1);
  Vertex* m2 = T.addVertex(xs[1], ys[1], -2);
  Vertex* m3 = T.addVertex(xs[0], ys[1], -3);
  Vertex* m4 = T.addVertex(xs[1], ys[0], -4);
  std::vector<Face*> faces = {T.addFace(m1, m2, m3), T.addFace(m2, m1, m4)};
  computeAdjacencies(faces);
}

//! [delaunayTrgl]
void delaunayTrgl(Triangulation& T, const std::vector<Vertex*>& S, StartRule rule,
                  InsertionStats* stats) {
  InsertionStats local;
  InsertionStats& st = stats ? *stats : local;
  InsertionScratch scratch;
  Face* last = &T.faces().front();
  for (std::size_t iP = 0; iP < S.size(); iP++) {
    Face* start = rule == StartRule::FirstFace ? &T.faces().front() : last;
    Face* ball = insertVertex(T, start, S[iP], st, scratch);
    if (ball != nullptr) last = ball;
  }
}
//! [delaunayTrgl]

//! [delaunayTrglHull]
void delaunayTrglHull(Triangulation& T, const std::vector<Vertex*>& S, StartRule rule,
                      InsertionStats* stats) {
  // The first triangle: S[0], the first point distinct from it, the first point off their line.
  std::size_t i1 = 1;
  while (i1 < S.size() && S[i1]->x == S[0]->x && S[i1]->y == S[0]->y) ++i1;
  if (i1 >= S.size()) throw DegenerateInput("fewer than 3 distinct points");
  std::size_t i2 = i1 + 1;
  while (i2 < S.size() && orientationTest(S[0], S[i1], S[i2]) == 0) ++i2;
  if (i2 >= S.size()) {
    bool distinct3 = false;  // distinguish "2 distinct points" from "collinear"
    for (std::size_t i = i1 + 1; i < S.size() && !distinct3; ++i)
      distinct3 = !(S[i]->x == S[0]->x && S[i]->y == S[0]->y) &&
                  !(S[i]->x == S[i1]->x && S[i]->y == S[i1]->y);
    throw DegenerateInput(distinct3 ? "all points are collinear" : "fewer than 3 distinct points");
  }
  Vertex* a = S[0];
  Vertex* b = S[i1];
  Vertex* c = S[i2];
  if (orientationTest(a, b, c) < 0) std::swap(b, c);
  Vertex* inf = T.infiniteVertex();
  // One finite face and, across each of its edges u->v, the ghost face (v, u, inf).
  std::vector<Face*> faces = {T.addFace(a, b, c), T.addFace(b, a, inf), T.addFace(c, b, inf),
                              T.addFace(a, c, inf)};
  computeAdjacencies(faces);
  InsertionStats local;
  InsertionStats& st = stats ? *stats : local;
  st.insertions += 3;
  InsertionScratch scratch;
  Face* last = faces[0];
  for (std::size_t iP = 1; iP < S.size(); iP++) {
    if (iP == i1 || iP == i2) continue;
    Face* start = rule == StartRule::FirstFace ? &T.faces().front() : last;
    Face* ball = insertVertex(T, start, S[iP], st, scratch);
    if (ball != nullptr) last = ball;
  }
}
//! [delaunayTrglHull]

PlainMesh extractMesh(const Triangulation& T, bool dropSuperFaces) {
  PlainMesh m;
  std::unordered_map<const Vertex*, int> index;
  std::vector<const Face*> kept;
  for (const Face* f : T.finiteFaces()) {
    if (dropSuperFaces && (f->V[0]->id < 0 || f->V[1]->id < 0 || f->V[2]->id < 0)) continue;
    kept.push_back(f);
    for (const Vertex* v : f->V) index.emplace(v, -1);
  }
  for (const Vertex& v : T.vertices()) {
    auto it = index.find(&v);
    if (it == index.end()) continue;
    it->second = static_cast<int>(m.ids.size());
    m.ids.push_back(v.id);
    m.xy.push_back(v.x);
    m.xy.push_back(v.y);
  }
  m.tri.reserve(kept.size());
  for (const Face* f : kept)
    m.tri.push_back({index[f->V[0]], index[f->V[1]], index[f->V[2]]});
  return m;
}

}  // namespace dt
