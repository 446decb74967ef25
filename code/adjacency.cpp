#include "adjacency.h"

#include <cstdint>
#include <functional>
#include <map>
#include <stdexcept>
#include <utility>

namespace dt {

//! [computeAdjacencies]
// The map's order is a parameter only so that a test can count its comparisons (Less below is
// std::less<Edge>, Edge::operator<, everywhere else).
template <class Less>
void computeAdjacenciesBy(std::vector<Face*>& cavity, Less less) {
  std::map<Edge, std::pair<int, Face*>, Less> edgeToFace(less);
  // Listing 2.4 compared a signed int with size(); std::size_t avoids the mismatch.
  for (std::size_t iFace = 0; iFace < cavity.size(); iFace++) {
    for (int iEdge = 0; iEdge < 3; iEdge++) {
      Edge edge = cavity[iFace]->getEdge(iEdge);
      auto it = edgeToFace.find(edge);
      if (it == edgeToFace.end()) {
        // edge has not yet been touched, so create an entry
        edgeToFace.insert(std::make_pair(edge, std::make_pair(iEdge, cavity[iFace])));
      } else {
        // Two faces on the same side of an edge mean the cavity was not a manifold disk;
        // Listing 2.4 would silently link them.
        if (it->first.V[0] == edge.V[0])
          throw std::logic_error("computeAdjacencies: edge used twice with one orientation");
        // Connect the two neighboring triangles
        cavity[iFace]->F[iEdge] = it->second.second;
        it->second.second->F[it->second.first] = cavity[iFace];
        // Erase edge from the map: a third face on this edge would then be unmatched, so
        // a manifold input is assumed (2.3.3).
        edgeToFace.erase(it);
      }
    }
  }
}
//! [computeAdjacencies]

void computeAdjacencies(std::vector<Face*>& cavity) {
  computeAdjacenciesBy(cavity, std::less<Edge>());
}

void computeAdjacencies(std::vector<Face*>& cavity, std::uint64_t& comparisons) {
  computeAdjacenciesBy(cavity, [&comparisons](const Edge& a, const Edge& b) {
    ++comparisons;
    return a < b;
  });
}

}  // namespace dt
