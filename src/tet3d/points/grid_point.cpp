#include "tet3d/points/grid_point.hpp"

#include <algorithm>
#include <bit>
#include <string>

#include "pqmesh/errors.hpp"

namespace pqmesh::tet3d {

Vec3 grid_coordinates(const OctTree& tree, const GridPoint& p) {
  // Coarsest level L with every f_a a multiple of 2^(kTreeMaxLevel - L).
  int zeros = kTreeMaxLevel;
  for (const std::int64_t v : p.f)
    if (v != 0) zeros = std::min(zeros, std::countr_zero(static_cast<std::uint64_t>(v)));
  const std::int32_t level = kTreeMaxLevel - zeros;
  if (level > tree.max_level())
    throw InternalError("tet3d: grid point below the tree's exact level " + std::to_string(tree.max_level()));
  BoxKey<3> k;
  k.level = level;
  for (int a = 0; a < 3; ++a) k.q[a] = p.f[a] >> zeros;
  return {tree.key_plane(k, 0, false), tree.key_plane(k, 1, false), tree.key_plane(k, 2, false)};
}

}  // namespace pqmesh::tet3d
