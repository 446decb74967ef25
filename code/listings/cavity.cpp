#include "cavity.h"

namespace dt {

//! [delaunayCavity]
void delaunayCavity(Face* f, Vertex* v, std::vector<Face*>& cavity, std::vector<Edge>& bnd,
                    std::vector<Face*>& otherSide) {
  // Listing 2.5 recursed once per cavity face: a cavity of 10^5 faces (points on a parabola,
  // section 2.3.4) overflows the call stack. An explicit stack visits the same faces.
  std::vector<Face*> stack;
  if (f->deleted) return;
  f->deleted = true;  // Mark the triangle
  cavity.push_back(f);
  stack.push_back(f);
  while (!stack.empty()) {
    Face* g = stack.back();
    stack.pop_back();
    for (int iNeigh = 0; iNeigh < 3; iNeigh++) {
      Face* n = g->F[iNeigh];
      if (n == nullptr) {
        bnd.push_back(g->getEdge(iNeigh));  // boundary of the domain (super-triangles)
      } else if (!n->inCircle(v)) {
        bnd.push_back(g->getEdge(iNeigh));
        if (!n->deleted) {
          otherSide.push_back(n);
          n->deleted = true;  // Listing 2.5 had no ';' here
        }
      } else if (!n->deleted) {
        n->deleted = true;
        cavity.push_back(n);
        stack.push_back(n);
      }
    }
  }
}
//! [delaunayCavity]

}  // namespace dt
