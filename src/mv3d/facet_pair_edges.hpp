#pragma once
// Which P edge do two facets share? A pair may share none, or several (two
// facets in different planes along the line where the planes meet; coplanar
// neighbours that merge_coplanar.hpp left unmerged anywhere). The lookup
// answers with the lowest edge index on both, the edge leaf_kind.hpp names
// as a TwoFacet leaf's edge.
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
