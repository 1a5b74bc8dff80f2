#pragma once
// The visiting order of the flip and improving-collapse passes (flips.hpp,
// improving_collapse.hpp): the live tetrahedra whose minimum dihedral angle is
// below kWorkBelowDihedral (smooth.hpp), smallest angle first, ties by id,
// fixed at the start of the pass. A tetrahedron that an earlier step of the
// pass removed is skipped at its turn; the tetrahedra the pass creates are not
// in the order (they wait for the next pass). Cost: O(T log T) for T
// tetrahedra ids, plus the visits.
#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>

#include "improve3d/collapse_mesh.hpp"
#include "improve3d/smooth.hpp"

namespace pqmesh::improve3d::detail {

// Calls step(t) for each tetrahedron t of the order that is alive at its turn
// (step may change mesh); returns how many calls returned true.
template <class Step>
std::int64_t visit_worst_first(const CollapseMesh& mesh, Step step) {
  std::vector<std::pair<double, int>> order;
  for (int t = 0; t < mesh.tet_count(); ++t)
    if (mesh.tet(t)[0] >= 0 && mesh.dihedral(t) < kWorkBelowDihedral) order.emplace_back(mesh.dihedral(t), t);
  std::sort(order.begin(), order.end());
  std::int64_t done = 0;
  for (const auto& [key, t] : order)
    if (mesh.tet(t)[0] >= 0 && step(t)) ++done;
  return done;
}

}  // namespace pqmesh::improve3d::detail
