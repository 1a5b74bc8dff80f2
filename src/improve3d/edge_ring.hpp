#pragma once
// The tetrahedra around an edge in rotational order, for edge removal
// (flips.hpp).
//
// For edge (a, b), every tetrahedron holding both is (a, b, x, y) up to an
// even permutation, so positively oriented in that order; the ring lists
// the x, y so that tets[i] = (a, b, ring[i], ring[i + 1]) with indices taken
// cyclically when the ring is closed (an interior edge: the tetrahedra go all
// the way round) and not when it is open (an edge on the boundary: the ring
// runs from one boundary triangle's third vertex, ring[0], to the other's).
#include <span>
#include <vector>

#include "improve3d/collapse_mesh.hpp"

namespace pqmesh::improve3d::detail {

struct EdgeRing {
  int a = -1, b = -1;
  std::vector<int> ring;  // closed: ring.size() == tets.size(); open: one more
  std::vector<int> tets;
  bool closed = false;
};

// tets_of_a: the live tetrahedra of a. Fills out and returns true when the
// tetrahedra holding a and b are at most max_tets and form one fan, closed or
// open (always so in a valid mesh); a closed ring starts at its smallest
// vertex id, so the result depends only on the mesh. Cost: O(|tets_of_a| +
// max_tets^2).
bool gather_edge_ring(const CollapseMesh& mesh, int a, int b, std::span<const int> tets_of_a, int max_tets,
                      EdgeRing& out);

}  // namespace pqmesh::improve3d::detail
