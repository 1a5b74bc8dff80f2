#pragma once
// Helpers of the square triangulation tests (cut_square_test.cpp, §4.4 Case C;
// cut_square_edge_test.cpp, Cases B and D): a face square's corners and the
// checks every triangle of a square must pass. Plain double arithmetic on
// grid coordinates (exact for the dyadic corners) and on the book's points.
#include <array>
#include <cstdint>
#include <random>
#include <vector>

#include "pqmesh/vec.hpp"
#include "tet3d/squares/box_faces.hpp"
#include "tet3d/points/grid_point.hpp"
#include "tree/tree.hpp"

namespace pqmesh::test {

inline double coord(const Vec3& p, int a) { return a == 0 ? p.x : (a == 1 ? p.y : p.z); }

// An unbalanced octree of the unit cube: 30 times a random leaf (drawn from
// rng) is split unless it is at level 5.
inline OctTree random_tree(std::mt19937_64& rng) {
  OctTree t(RootCube<3>{{0, 0, 0}, 1});
  for (int i = 0; i < 30; ++i) {
    const std::vector<std::int32_t> leaves = t.leaves();
    const std::int32_t n = leaves[static_cast<std::size_t>(rng() % leaves.size())];
    if (t.level(n) < 5) t.split(n);
  }
  return t;
}

// The corners of square S: lo, lo + side u, lo + side (u + v), lo + side v.
inline std::array<Vec3, 4> square_corners(const OctTree& t, const tet3d::FaceSquare& s) {
  std::array<Vec3, 4> q;
  for (int k = 0; k < 4; ++k) {
    tet3d::GridPoint g = s.lo;
    g.f[s.u] += (k == 1 || k == 2) ? s.side : 0;
    g.f[s.v] += (k >= 2) ? s.side : 0;
    q[static_cast<std::size_t>(k)] = tet3d::grid_coordinates(t, g);
  }
  return q;
}

// x lies on the closed square with corners q (square_corners): on its plane
// x_n = q0_n exactly and within its u and v ranges.
inline bool on_closed_square(const Vec3& x, const std::array<Vec3, 4>& q, const tet3d::FaceSquare& s) {
  return coord(x, s.n) == coord(q[0], s.n) && coord(x, s.u) >= coord(q[0], s.u) && coord(x, s.u) <= coord(q[2], s.u) &&
         coord(x, s.v) >= coord(q[0], s.v) && coord(x, s.v) <= coord(q[2], s.v);
}

// Signed area of triangle p0 p1 p2 projected on the (u, v) plane.
inline double uv_area(const Vec3& p0, const Vec3& p1, const Vec3& p2, int u, int v) {
  return 0.5 * (coord(p1 - p0, u) * coord(p2 - p0, v) - coord(p2 - p0, u) * coord(p1 - p0, v));
}

}  // namespace pqmesh::test
