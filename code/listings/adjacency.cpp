#include "adjacency.h"

#include <algorithm>
#include <cstdint>
#include <functional>
#include <map>
#include <stdexcept>
#include <utility>

namespace dt {

//! [computeAdjacencies]
// The map is a parameter only so that a test can count its operations and comparisons
// (CountingEdgeMap below); everywhere else it is the std::map of Listing 2.4.
template <class Map>
void computeAdjacenciesWith(std::vector<Face*>& cavity, Map& edgeToFace) {
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

void computeAdjacencies(std::vector<Face*>& cavity) {
  std::map<Edge, std::pair<int, Face*>> edgeToFace;
  computeAdjacenciesWith(cavity, edgeToFace);
}
//! [computeAdjacencies]

namespace {

// The listing's map with every search, insert, erase and key comparison counted: the
// operations the notes' "one search/insert per triangle" is about.
class CountingEdgeMap {
 public:
  explicit CountingEdgeMap(AdjacencyCounts& c)
      : c_(c), map_([&c](const Edge& a, const Edge& b) {
          ++c.comparisons;
          return a < b;
        }) {}
  using Map = std::map<Edge, std::pair<int, Face*>, std::function<bool(const Edge&, const Edge&)>>;
  Map::iterator find(const Edge& e) {
    ++c_.searches;
    return map_.find(e);
  }
  Map::iterator end() { return map_.end(); }
  std::pair<Map::iterator, bool> insert(const Map::value_type& v) {
    ++c_.inserts;
    auto r = map_.insert(v);
    c_.largest = std::max<std::uint64_t>(c_.largest, map_.size());
    return r;
  }
  void erase(Map::iterator it) {
    ++c_.erases;
    map_.erase(it);
  }

 private:
  AdjacencyCounts& c_;
  Map map_;
};

}  // namespace

void computeAdjacencies(std::vector<Face*>& cavity, AdjacencyCounts& counts) {
  CountingEdgeMap edgeToFace(counts);
  computeAdjacenciesWith(cavity, edgeToFace);
}

void computeAdjacencies(std::vector<Face*>& cavity, std::uint64_t& comparisons) {
  AdjacencyCounts counts;
  computeAdjacencies(cavity, counts);
  comparisons += counts.comparisons;
}

}  // namespace dt
