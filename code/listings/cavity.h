// The Delaunay cavity (sections 2.1.2 and 2.3.4, Listing 2.5).
#pragma once

#include <vector>

#include "mesh.h"

namespace dt {

//! [delaunayCavityDecl]
/// Collects the Delaunay cavity of v (2.1.2): every face whose open circumdisk contains v,
/// found by a depth-first search from the seed f, which must itself contain v in its circle
/// (Listing 2.5). Outputs: the cavity faces (marked `deleted`), the boundary edges `bnd`
/// oriented as in their cavity face (so that (e.V[0], e.V[1], v) is counter-clockwise), and
/// the faces `otherSide` across those edges (also marked `deleted` to list each once; the
/// caller must clear that mark). Uses an explicit stack: no recursion, whatever the cavity size.
void delaunayCavity(Face* f, Vertex* v, std::vector<Face*>& cavity, std::vector<Edge>& bnd,
                    std::vector<Face*>& otherSide);
//! [delaunayCavityDecl]

}  // namespace dt
