#include "mesh.h"

#include "predicates.h"
#include "predicates_inline.h"

namespace dt {

int orientationTest(const Vertex* a, const Vertex* b, const Vertex* c) {
  return orient2d(a->x, a->y, b->x, b->y, c->x, c->y);
}

//! [inCircle]
bool Face::inCircle(const Vertex* c) const {
  const int i = infiniteIndex();
  if (i < 0)
    return incircle(V[0]->x, V[0]->y, V[1]->x, V[1]->y, V[2]->x, V[2]->y, c->x, c->y) > 0;
  // Ghost face (a, b, inf): its "circumcircle" is the limit of circles through a and b whose
  // centre goes to infinity on the outer side: the open half-plane left of a->b, plus the open
  // segment ab itself (the rule of predicates_inline.h, which the fast kernels use too).
  const Vertex* a = V[(i + 1) % 3];
  const Vertex* b = V[(i + 2) % 3];
  return pred::ghostConflict(orientationTest(a, b, c), a->x, a->y, b->x, b->y, c->x, c->y);
}
//! [inCircle]

Vertex Face::centroid() const {
  // Dividing first: the sum of three coordinates near 1e308 overflows to infinity, and the
  // walk's orientation tests would then get a non-finite point (found by fuzzing). The
  // rounding differs a little; lineSearch copes with a centroid slightly off the face.
  return Vertex(V[0]->x / 3 + V[1]->x / 3 + V[2]->x / 3, V[0]->y / 3 + V[1]->y / 3 + V[2]->y / 3);
}

Triangulation::Triangulation() : infinite_(0, 0, 0, -1000) { infinite_.infinite = true; }

Vertex* Triangulation::addVertex(double x, double y, long id) {
  vertices_.emplace_back(x, y, 0.0, id);
  return &vertices_.back();
}

Face* Triangulation::addFace(Vertex* a, Vertex* b, Vertex* c) {
  faces_.emplace_back(a, b, c);
  return &faces_.back();
}

std::vector<const Face*> Triangulation::finiteFaces() const {
  std::vector<const Face*> out;
  out.reserve(faces_.size());
  for (const Face& f : faces_)
    if (!f.deleted && !f.isGhost()) out.push_back(&f);
  return out;
}

std::size_t Triangulation::numFiniteFaces() const {
  std::size_t n = 0;
  for (const Face& f : faces_)
    if (!f.deleted && !f.isGhost()) ++n;
  return n;
}

}  // namespace dt
