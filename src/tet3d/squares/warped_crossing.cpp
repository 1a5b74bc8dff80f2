#include "tet3d/squares/warped_crossing.hpp"

#include <array>

#include "tet3d/points/edge_point.hpp"

namespace pqmesh::tet3d {

namespace {
}  // namespace

std::optional<Vec3> warped_square_crossing(Vec3 a, Vec3 b, const FaceSquare& s, const OctTree& tree,
                                           const WarpTable* warps) {
  if (warps == nullptr) return std::nullopt;
  // Corners counter-clockwise about +n: lo, lo+u, lo+u+v, lo+v.
  std::array<GridPoint, 4> g{s.lo, s.lo, s.lo, s.lo};
  g[1].f[static_cast<std::size_t>(s.u)] += s.side;
  g[2].f[static_cast<std::size_t>(s.u)] += s.side;
  g[2].f[static_cast<std::size_t>(s.v)] += s.side;
  g[3].f[static_cast<std::size_t>(s.v)] += s.side;
  std::array<Vec3, 4> c;
  bool moved = false;
  for (std::size_t i = 0; i < 4; ++i) {
    const Warp* w = warps->find(g[i]);
    moved = moved || w != nullptr;
    c[i] = w != nullptr ? w->at : grid_coordinates(tree, g[i]);
  }
  if (!moved) return std::nullopt;
  const Vec3 m = 0.25 * (c[0] + c[1] + c[2] + c[3]);
  const Vec3 n = cross(c[2] - c[0], c[3] - c[1]);
  const double den = dot(n, b - a);
  if (!(den != 0)) return std::nullopt;
  const double t = dot(n, m - a) / den;
  if (!(t > 0 && t < 1)) return std::nullopt;
  const Vec3 x = a + t * (b - a);
  const Vec3 lo = grid_coordinates(tree, g[0]), hi = grid_coordinates(tree, g[2]);
  for (const int w : {s.u, s.v})
    if (!(axis_coord(x, w) > axis_coord(lo, w) && axis_coord(x, w) < axis_coord(hi, w))) return std::nullopt;
  return round_onto_segment(a, b, x);
}

}  // namespace pqmesh::tet3d
