#pragma once
// Which P edge do two facets share? Two facets of P meet only along the line
// of their planes (they are not coplanar, merge_coplanar.hpp), so a pair may
// share several collinear edges or none. The lookup answers with the lowest
// edge index on both, the one leaf_kind.hpp names as a TwoFacet leaf's edge.
// Built once from Domain3::edges; a lookup is a binary search.
#include <array>
#include <vector>

#include "pqmesh/domain.hpp"

namespace pqmesh::mv3d {

class FacetPairEdges {
 public:
  explicit FacetPairEdges(const Domain3& domain);
  // The lowest index into Domain3::edges of an edge on facets f and g (in
  // either order), or -1 when they share none.
  int edge_between(int f, int g) const;

 private:
  std::vector<std::array<int, 3>> pairs_;  // (min facet, max facet, edge), sorted
};

}  // namespace pqmesh::mv3d
