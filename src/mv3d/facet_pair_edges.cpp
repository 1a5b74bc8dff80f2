#include "mv3d/facet_pair_edges.hpp"

#include <algorithm>

namespace pqmesh::mv3d {

FacetPairEdges::FacetPairEdges(const Domain3& domain) {
  pairs_.reserve(domain.edges.size());
  for (std::size_t e = 0; e < domain.edges.size(); ++e) {
    const auto [f, g] = std::minmax(domain.edges[e].facets[0], domain.edges[e].facets[1]);
    pairs_.push_back({f, g, static_cast<int>(e)});
  }
  std::sort(pairs_.begin(), pairs_.end());
}

int FacetPairEdges::edge_between(int f, int g) const {
  const auto [lo, hi] = std::minmax(f, g);
  const auto it = std::lower_bound(pairs_.begin(), pairs_.end(), std::array<int, 3>{lo, hi, -1});
  return it != pairs_.end() && (*it)[0] == lo && (*it)[1] == hi ? (*it)[2] : -1;
}

}  // namespace pqmesh::mv3d
