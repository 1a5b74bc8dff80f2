#pragma once
// The triangulation of a simple polygon with the largest smallest angle, for
// the removals of the 2D quality pass (quality_pass.hpp; docs/algorithm/improve2d.md
// "The pass"): the star polygon of a vertex re-triangulated without it.
#include <array>
#include <utility>
#include <vector>

#include "pqmesh/vec.hpp"

namespace pqmesh::detail {

// Scratch tables of best_triangulation, reused across calls (no allocation per star).
struct DpTables {
  std::vector<signed char> ok;
  std::vector<double> best;
  std::vector<int> arg;
  std::vector<std::pair<int, int>> todo;
};

// The triangulation of the simple CCW polygon q with the largest min angle
// (dynamic programming over the sub-polygons q[i..j] cut off by a diagonal
// or side ij; first maximum in k order), when that angle exceeds `floor`.
// Returns it (and the triangles, as indices into q, in `out`), or a value <=
// floor when no triangulation with every triangle strictly counter-clockwise
// has all its angles above floor. Diagonals are decided by exact orient2d.
// Cost: O(m^3) for m vertices in the worst case; pruning skips the splits
// that cannot win.
double best_triangulation(const std::vector<Vec2>& q, double floor, std::vector<std::array<int, 3>>& out,
                          DpTables& tables);

}  // namespace pqmesh::detail
