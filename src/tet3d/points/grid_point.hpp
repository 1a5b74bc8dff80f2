#pragma once
// Points of the octree's integer grid (docs/DESIGN_RULES.md "Exact decisions":
// "tree boxes live on an integer grid"), the identity of the mesh vertices that
// the box stage makes.
//
// A GridPoint is a point with coordinates root_origin + f_a * h(kTreeMaxLevel + 1),
// f_a integers ("fine units" of tree/key.hpp). Box corners, centres of box
// faces and centres of boxes are all such points (for boxes of level <= 49; the
// tree never comes close). Two vertices are the same vertex exactly when their
// GridPoints are equal: identification is by integer key, never by comparing
// rounded coordinates. Coordinates are computed from the key
// through Tree::key_plane, so they are exact doubles (root_cube.hpp).
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "pqmesh/vec.hpp"
#include "tree/tree.hpp"

namespace pqmesh::tet3d {

struct GridPoint {
  std::array<std::int64_t, 3> f{};
  // Field by field: the defaulted form compiles to a memcmp call, 2% of a
  // mesh run (hash-table probes, sorts).
  friend bool operator==(const GridPoint& a, const GridPoint& b) {
    return a.f[0] == b.f[0] && a.f[1] == b.f[1] && a.f[2] == b.f[2];
  }
  friend auto operator<=>(const GridPoint&, const GridPoint&) = default;
};

struct GridPointHash {
  std::size_t operator()(const GridPoint& p) const {
    std::uint64_t x = 0x9E3779B97F4A7C15ull;
    for (const std::int64_t v : p.f) {
      x ^= static_cast<std::uint64_t>(v) + 0x9E3779B97F4A7C15ull + (x << 6) + (x >> 2);
      x = (x ^ (x >> 31)) * 0xBF58476D1CE4E5B9ull;
    }
    return static_cast<std::size_t>(x ^ (x >> 29));
  }
};

namespace detail {

// Half the side of a level-`level` box in fine units, 2^(kTreeMaxLevel - level).
inline std::int64_t fine_half(std::int32_t level) { return std::int64_t{1} << (kTreeMaxLevel - level); }

}  // namespace detail

// Corner `k` of an aligned key (bit a of k: upper plane along axis a).
inline GridPoint key_corner(const BoxKey<3>& key, int k) {
  GridPoint p;
  for (int a = 0; a < 3; ++a) p.f[a] = key.fine_lo(a) + (((k >> a) & 1) ? key.fine_side() : 0);
  return p;
}

// Centre of the box of `key`.
inline GridPoint key_centre(const BoxKey<3>& key) {
  GridPoint p;
  for (int a = 0; a < 3; ++a) p.f[a] = key.fine_lo(a) + detail::fine_half(key.level);
  return p;
}

// The grid points inside the box of `key` at i/parts, j/parts, k/parts of
// its side (i, j, k in 1 .. parts - 1; i outermost, k innermost): the
// candidates for a second interior apex (edge_box.cpp, edge_box_fans.cpp).
// Empty when the side is not a multiple of `parts` fine units.
inline std::vector<GridPoint> interior_grid_points(const BoxKey<3>& key, std::int64_t parts) {
  const std::int64_t q = key.fine_side() / parts;
  if (q * parts != key.fine_side()) return {};
  std::vector<GridPoint> out;
  const GridPoint lo = key_corner(key, 0);
  for (std::int64_t i = 1; i < parts; ++i)
    for (std::int64_t j = 1; j < parts; ++j)
      for (std::int64_t k = 1; k < parts; ++k) {
        GridPoint g = lo;
        g.f[0] += i * q;
        g.f[1] += j * q;
        g.f[2] += k * q;
        out.push_back(g);
      }
  return out;
}

// Exact coordinates of a grid point of `tree` (Tree::key_plane of the coarsest
// level whose grid holds the coordinate). Throws InternalError if that level
// is deeper than tree.max_level() (the plane would not be an exact double).
Vec3 grid_coordinates(const OctTree& tree, const GridPoint& p);

}  // namespace pqmesh::tet3d
