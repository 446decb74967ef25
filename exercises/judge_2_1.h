// The judge of exercise 2.1-2, part of exercises/judge.cpp (one translation unit): see the
// comment at its top. (2.1-1's judge is in judge.cpp itself.)
#pragma once

namespace {

// What checkCavity said: whether the set is a cavity and, when it is, the counts the contract
// defines (they are fixed for a true cavity; a rejected set's counts may stop half-way).
std::string cavityVerdict(const std::vector<const dt::Face*>& C, const dt::Vertex* p) {
  dt::CavityReport rep;
  const std::string did = outcome([&] { rep = dt::checkCavity(C, p); });
  if (did != "returns") return did;
  if (!rep.ok) return "not a cavity";
  return "a cavity: " + std::to_string(rep.faces) + " faces, " + std::to_string(rep.boundaryEdges) +
         " boundary edges, " + std::to_string(rep.components) + " component(s), " + std::to_string(rep.innerVertices) +
         " inner vertices, winding " + std::to_string(rep.winding);
}

// 2.1-2: checkCavity on the true cavities (conflictFaces, the library's definition) of random
// points, points on grid lines and at grid points (cocircular, on edges, an existing vertex:
// an empty set), and on sets that are not cavities: a cavity with an outside neighbour added,
// with one face taken away, and the star of an interior vertex (the test's control).
void judgeCheckCavity(std::uint64_t seed) {
  std::mt19937_64 r(seed);
  for (int kind = 0; kind < 2; ++kind) {
    dt::Triangulation T;
    dt::XY p = kind == 0 ? dt::uniformPoints(300, seed) : dt::gridPoints(8, 8, 0.125);
    if (kind == 1) dt::shufflePoints(p, seed);
    const std::vector<dt::Vertex*> S = dt::addVertices(T, p);
    dt::initSuperTriangles(T, 0, 0, 1, 1);
    dt::delaunayTrgl(T, S, dt::StartRule::LastCavity);
    const char* what = kind == 0 ? "300 random points" : "an 8 x 8 grid";
    for (int k = 0; k < 40; ++k) {
      dt::Vertex q(0, 0);
      if (k % 4 == 0) q = dt::Vertex(double(r() % 17) / 16, double(r() % 17) / 16);  // grid lines, grid points
      else if (k % 4 == 1) q = dt::Vertex(S[r() % S.size()]->x, S[r() % S.size()]->y);  // an existing vertex
      else q = dt::Vertex(double(r() % 1000) / 1000, double(r() % 1000) / 1000);
      std::vector<dt::Face*> C = dt::conflictFaces(T, &q);
      std::vector<const dt::Face*> c(C.begin(), C.end());
      std::printf("t2 %s, p = (%a, %a): the cavity: %s\n", what, q.x, q.y, cavityVerdict(c, &q).c_str());
      if (C.empty()) continue;
      // One more face: a live finite neighbour of the cavity whose circle does not hold p.
      for (const dt::Face* f : C)
        for (const dt::Face* g : f->F)
          if (g != nullptr && !g->isGhost() && std::find(C.begin(), C.end(), g) == C.end() && c.size() == C.size()) {
            c.push_back(g);
            std::printf("t1 %s, p = (%a, %a): the cavity and a neighbour: %s\n", what, q.x, q.y, cavityVerdict(c, &q).c_str());
          }
      if (C.size() >= 2) {
        std::vector<const dt::Face*> less(C.begin(), C.end());
        less.erase(less.begin() + long(r() % less.size()));
        std::printf("t1 %s, p = (%a, %a): the cavity less a face: %s\n", what, q.x, q.y, cavityVerdict(less, &q).c_str());
      }
    }
  }
  // The star of the centre of a 3 x 3 grid, p beside the centre: an inner vertex.
  dt::Triangulation T;
  const std::vector<dt::Vertex*> S = dt::addVertices(T, dt::gridPoints(3, 3));
  dt::delaunayTrglHull(T, S, dt::StartRule::LastCavity);
  std::vector<const dt::Face*> star;
  for (const dt::Face& f : T.faces())
    if (!f.deleted && !f.isGhost() && (f.V[0] == S[4] || f.V[1] == S[4] || f.V[2] == S[4])) star.push_back(&f);
  dt::Vertex q(1.01, 1.02);
  dt::CavityReport rep;
  const std::string did = outcome([&] { rep = dt::checkCavity(star, &q); });
  std::printf("t1 the star of the centre of a 3 x 3 grid: %s, %s, inner vertices %s, boundary edges %s\n", did.c_str(),
              rep.ok ? "a cavity" : "not a cavity", rep.innerVertices == star.size() ? "one per face" : "not one per face",
              rep.boundaryEdges == star.size() ? "one per face" : "not one per face");
}

}  // namespace
