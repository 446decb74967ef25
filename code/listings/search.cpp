#include "search.h"

#include <stdexcept>

namespace dt {

//! [lineSearch]
Face* lineSearch(Face* f, Vertex* v, SearchInfo* info) {
  SearchInfo local;
  SearchInfo& out = info ? *info : local;
  std::uint64_t visited = 0;
  while (true) {
    if (f == nullptr) {  // the printed "we should NEVER return here": v is outside the domain
      out.outside = true;
      return nullptr;
    }
    ++out.steps;
    if (out.trace) out.trace->push_back(f);
    // A visibility walk on a Delaunay triangulation visits each face at most once; the cap
    // turns a corrupted mesh into an error instead of an endless loop.
    if (++visited > out.maxSteps) throw std::logic_error("lineSearch: walk does not terminate");
    if (f->inCircle(v)) return f;
    const int inf = f->infiniteIndex();
    if (inf >= 0) {  // a ghost face not in conflict: step into the hull through its real edge
      f = f->F[(inf + 1) % 3];
      continue;
    }
    // Listing 2.6 required the segment centroid->v to cross an edge strictly. When that line
    // passes through a vertex no edge qualifies and the printed loop spins forever. Here the
    // ray from the centroid c leaves through exactly one half-open sector [V[k], V[k+1]).
    const Vertex c = f->centroid();
    int next = -1;
    for (int k = 0; k < 3 && next < 0; k++) {
      Vertex* a = f->V[k];
      Vertex* b = f->V[(k + 1) % 3];
      if (orientationTest(&c, a, v) >= 0 && orientationTest(&c, b, v) < 0 &&
          orientationTest(a, b, v) < 0)
        next = k;
    }
    // The rounded centroid may sit on or outside a very flat face; then any edge that v lies
    // strictly beyond keeps the walk a visibility walk.
    for (int k = 0; k < 3 && next < 0; k++)
      if (orientationTest(f->V[k], f->V[(k + 1) % 3], v) < 0) next = k;
    if (next < 0) {
      // v is in the closed face but not strictly inside its circumcircle: v is a vertex of f.
      for (Vertex* w : f->V)
        if (w->x == v->x && w->y == v->y) {
          out.duplicate = w;
          return nullptr;
        }
      throw std::logic_error("lineSearch: point inside a face but outside its circumcircle");
    }
    f = f->F[next];
  }
}
//! [lineSearch]

}  // namespace dt
