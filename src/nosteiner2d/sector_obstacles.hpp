#pragma once
// The obstacles of a spiral frame (fan_bound.hpp "obstacle fan bound"): the
// boundary vertices q other than V and U strictly closer to V than |E| and in
// the closed interior sector at V (exact in_sector). Shared by the upper
// bound (fan_bound.cpp) and the seeds placed along those fans (seed_points.cpp).
#include <cstddef>
#include <vector>

#include "nosteiner2d/face_grid.hpp"
#include "nosteiner2d/spiral_frame.hpp"
#include "pqmesh/domain.hpp"

namespace pqmesh::detail {

// Calls visit(q, Q, r) for each obstacle of e (Q its point, r = |Q - V|), in the grid's order,
// until visit returns false; returns false then, true when every obstacle was visited.
// side_ids, vertex_ids: scratch. Cost: one grid query of radius |E|.
template <class Visit>
bool for_each_sector_obstacle(const Domain2& domain, const FaceGrid& grid, const SpiralFrame& e,
                              std::vector<int>& side_ids, std::vector<int>& vertex_ids, Visit visit) {
  grid.query(e.V, e.length, side_ids, vertex_ids);
  for (const int vi : vertex_ids) {
    const int q = grid.vertices()[static_cast<std::size_t>(vi)];
    if (q == e.v || q == e.u) continue;
    const Vec2 Q = domain.pslg.vertices[static_cast<std::size_t>(q)];
    const double r = norm(Q - e.V);
    if (!(r < e.length) || !e.in_sector(Q)) continue;
    if (!visit(q, Q, r)) return false;
  }
  return true;
}

}  // namespace pqmesh::detail
