#pragma once
// Helpers shared by the warping tests (warp_*_test.cpp): corners of the root
// box and the domain edge between two facets.
#include <cstddef>

#include "pqmesh/domain.hpp"
#include "tet3d/points/grid_point.hpp"
#include "tree/tree.hpp"

namespace pqmesh::tet3d {

// Corner k (bit 0: x, bit 1: y, bit 2: z) of t's root box.
inline GridPoint corner_of(const OctTree& t, int k) { return key_corner(t.key(0), k); }

// The index of the last edge of d between facets f and g, -1 when there is none.
inline int edge_between(const Domain3& d, int f, int g) {
  int edge = -1;
  for (std::size_t e = 0; e < d.edges.size(); ++e) {
    const auto& fs = d.edges[e].facets;
    if ((fs[0] == f && fs[1] == g) || (fs[0] == g && fs[1] == f)) edge = static_cast<int>(e);
  }
  return edge;
}

}  // namespace pqmesh::tet3d
