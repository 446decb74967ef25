// THE NOTES' CODE, NOT THE PROJECT'S: Listings 2.1-2.8 of section 2.3 as printed, made to
// compile with the fewest changes and nothing else, so that tests can run them and show where
// they fail (test_printed_listings.cpp). Every change is marked "FIX:" and is one of:
//  - a typesetting artefact of the text (`}>\mathrm{`, `}->>`, `double }X\mathrm{` ...);
//  - a missing brace, semicolon or #include; `T. push_back[newf]` called with brackets; `vl`
//    for `v1`; unqualified `swap` on doubles (no argument-dependent lookup finds std::swap);
//  - Listing 2.7 reads bnd[i].V[0] and bnd[i].V[1], members Listing 2.2's Edge does not have:
//    the only members it has, vmin and vmax, are used instead;
//  - the three functions the text assumes but never defines (Face::inCircle, Face::centroid,
//    orientationTest) are given the exact predicates of code/predicates/predicates.h, as the text asks
//    ("it assumes that a robust orientation test is available").
// Nothing else is corrected: the faults the errata page lists stay, on purpose.
// The project's corrected code is in code/ (mesh.h, adjacency.cpp, cavity.cpp, search.cpp,
// triangulate.cpp, hilbert.cpp).
#pragma once

#include <algorithm>  // FIX: std::min, std::max
#include <cstddef>    // FIX: NULL
#include <map>        // FIX: std::map
#include <utility>    // FIX: std::pair, std::swap
#include <vector>     // FIX: std::vector

#include "predicates.h"

// The printed loops compare int with size_t: kept as printed, the warning silenced here only.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wsign-compare"

namespace printed {

// Listing 2.1
struct Vertex {
  double x, y, z;
  Vertex(double X, double Y, double Z) :  // FIX: "double }X\mathrm{ , double Y"
    x(X), y(Y), z(Z) {}
};

// Listing 2.2
struct Edge {
  Vertex *vmin, *vmax;
  Edge(Vertex* v1, Vertex* v2) {  // FIX: the opening brace was missing
    vmin = std::min(v1, v2);
    vmax = std::max(v1, v2);  // FIX: "vl"
  }
  bool operator<(const Edge& other) const {
    if (vmin < other.vmin) return true;
    if (vmin > other.vmin) return false;
    if (vmax < other.vmax) return true;
    return false;
  }
};

// Listing 2.3
struct Face {  // FIX: the opening brace was missing
  Face* F[3];
  Vertex* V[3];
  bool deleted;
  Face(Vertex* v0, Vertex* v1, Vertex* v2) {
    V[0] = v0; V[1] = v1; V[2] = v2;
    F[0] = F[1] = F[2] = NULL;
    deleted = false;
  }
  Edge getEdge(int k) { return Edge(V[k], V[(k + 1) % 3]); }
  bool inCircle(Vertex* c);
  Vertex centroid();
};

// FIX: assumed by the text, never defined: the exact predicates.
inline bool Face::inCircle(Vertex* c) {
  return dt::incircle(V[0]->x, V[0]->y, V[1]->x, V[1]->y, V[2]->x, V[2]->y, c->x, c->y) > 0;
}
inline Vertex Face::centroid() {
  return Vertex((V[0]->x + V[1]->x + V[2]->x) / 3, (V[0]->y + V[1]->y + V[2]->y) / 3, 0);
}
inline int orientationTest(Vertex* a, Vertex* b, Vertex* c) {
  return dt::orient2d(a->x, a->y, b->x, b->y, c->x, c->y);
}

// Listing 2.4
inline void computeAdjacencies(std::vector<Face*>& cavity) {
  std::map<Edge, std::pair<int, Face*> > edgeToFace;
  for (int iFace = 0; iFace < cavity.size(); iFace++) {
    for (int iEdge = 0; iEdge < 3; iEdge++) {
      Edge edge = cavity[iFace]->getEdge(iEdge);
      std::map<Edge, std::pair<int, Face*> >::iterator it = edgeToFace.find(edge);
      if (it == edgeToFace.end()) {
        // edge has not yet been touched, so create an entry
        edgeToFace.insert(std::make_pair(edge, std::make_pair(iEdge, cavity[iFace])));
      } else {
        // Connect the two neighboring triangles
        cavity[iFace]->F[iEdge] = it->second.second;  // FIX: "}>\mathrm{ F[iEdge] = it }->>\mathrm{"
        it->second.second->F[it->second.first] = cavity[iFace];  // FIX: "}->>\mathrm{ second.second }>>F["
        // Erase edge from the map
        edgeToFace.erase(it);
      }
    }
  }
}

// Listing 2.5
inline void delaunayCavity(Face* f, Vertex* v, std::vector<Face*>& cavity, std::vector<Edge>& bnd,
                           std::vector<Face*>& otherSide) {
  if (f->deleted) return;
  f->deleted = true;  // Mark the triangle
  cavity.push_back(f);
  for (int iNeigh = 0; iNeigh < 3; iNeigh++) {
    if (f->F[iNeigh] == NULL) {
      bnd.push_back(f->getEdge(iNeigh));
    } else if (!f->F[iNeigh]->inCircle(v)) {
      bnd.push_back(f->getEdge(iNeigh));
      if (!f->F[iNeigh]->deleted) {
        otherSide.push_back(f->F[iNeigh]);
        f->F[iNeigh]->deleted = true;  // FIX: the semicolon was missing
      }
    } else
      delaunayCavity(f->F[iNeigh], v, cavity, bnd, otherSide);  // FIX: semicolon, "}>>F["
  }
}

// Listing 2.6
inline Face* lineSearch(Face* f, Vertex* v) {
  while (1) {
    if (f == NULL) return NULL;  // we should NEVER return here
    if (f->inCircle(v)) return f;
    Vertex c = f->centroid();
    for (int iNeigh = 0; iNeigh < 3; iNeigh++) {
      Edge e = f->getEdge(iNeigh);
      if (orientationTest(&c, v, e.vmin) * orientationTest(&c, v, e.vmax) < 0 &&
          orientationTest(e.vmin, e.vmax, &c) * orientationTest(e.vmin, e.vmax, v) < 0) {
        f = f->F[iNeigh];  // FIX: "}>>\textrm{F}[\textrm{iNeigh}]" and the semicolon
        break;
      }
    }
  }
}

// Listing 2.7
inline void delaunayTrgl(std::vector<Vertex*>& S, std::vector<Face*>& T) {
  for (int iP = 0; iP < S.size(); iP++) {
    Face* f = lineSearch(T[0], S[iP]);
    std::vector<Face*> cavity;
    std::vector<Edge> bnd;
    std::vector<Face*> otherSide;
    delaunayCavity(f, S[iP], cavity, bnd, otherSide);
    if (bnd.size() != cavity.size() + 2) throw;
    for (int i = 0; i < cavity.size(); i++) {
      // reuse memory slots of invalid elements
      cavity[i]->deleted = false;
      cavity[i]->F[0] = cavity[i]->F[1] = cavity[i]->F[2] = NULL;  // FIX: "}>>\textrm{F}[2]=\mathrm{ NULL"
      cavity[i]->V[0] = bnd[i].vmin;  // FIX: bnd[i].V[0]; Edge has no V
      cavity[i]->V[1] = bnd[i].vmax;  // FIX: bnd[i].V[1]
      cavity[i]->V[2] = S[iP];
    }
    unsigned int cSize = cavity.size();
    for (int i = cSize; i < cSize + 2; i++) {
      Face* newf = new Face(bnd[i].vmin, bnd[i].vmax, S[iP]);  // FIX: bnd[i].V[0], bnd[i].V[1]
      T.push_back(newf);  // FIX: "T. push_back[newf]"
      cavity.push_back(newf);
    }
    for (int i = 0; i < otherSide.size(); i++)
      if (otherSide[i]) cavity.push_back(otherSide[i]);
    computeAdjacencies(cavity);
  }
}  // FIX: the closing brace was printed after the listing

// Listing 2.8
using std::swap;  // FIX: the unqualified swap of doubles needs it
inline void HilbertCoord(double x, double y, double x0, double y0,  // FIX: "double }x\mathrm{ ,"
                         double xRed, double yRed, double xBlue, double yBlue, int d, int bits[]) {
  for (int i = 0; i < d; i++) {
    double coordRed = (x - x0) * xRed + (y - y0) * yRed;
    double coordBlue = (x - x0) * xBlue + (y - y0) * yBlue;
    xRed /= 2; yRed /= 2; xBlue /= 2; yBlue /= 2;
    if (coordRed <= 0 && coordBlue <= 0) {  // quadrant 0
      x0 -= (xBlue + xRed); y0 -= (yBlue + yRed);
      swap(xRed, xBlue); swap(yRed, yBlue);
      bits[i] = 0;
    } else if (coordRed <= 0 && coordBlue >= 0) {  // quadrant 1
      x0 += (xBlue - xRed); y0 += (yBlue - yRed);
      bits[i] = 1;
    } else if (coordRed >= 0 && coordBlue >= 0) {  // quadrant 2
      x0 += (xBlue + xRed); y0 += (yBlue + yRed);
      bits[i] = 2;
    } else if (coordRed >= 0 && coordBlue <= 0) {  // quadrant 3
      x0 += (-xBlue + xRed); y0 += (-yBlue + yRed);
      swap(xRed, xBlue); swap(yRed, yBlue);
      xBlue = -xBlue; yBlue = -yBlue;
      xRed = -xRed; yRed = -yRed;
      bits[i] = 3;
    }
  }
}

}  // namespace printed

#pragma GCC diagnostic pop
