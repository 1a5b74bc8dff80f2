#pragma once
// The table of warped grid points (thesis §4.3; built by warp.hpp): grid
// point -> moved coordinates, with the counts of the moves not made. Every
// mesh vertex named by a grid point resolves through it (point_book.hpp), so
// all boxes sharing a point see one moved copy.
#include <cstdint>
#include <unordered_map>

#include "pqmesh/vec.hpp"
#include "tet3d/grid_point.hpp"

namespace pqmesh::tet3d {

struct Warp {
  int facet = -1;  // the key's facet (the first close facet), -1 for none
  Vec3 at;
};

class WarpTable {
 public:
  const Warp* find(const GridPoint& p) const {
    const auto it = map_.find(p);
    return it == map_.end() ? nullptr : &it->second;
  }
  bool insert(const GridPoint& p, const Warp& w) { return map_.try_emplace(p, w).second; }
  std::size_t size() const { return map_.size(); }
  std::int64_t conflicts = 0;     // left: the move would change a side decision
  std::int64_t bisected = 0;      // moved onto the bisector of an acute wedge (among size())
  std::int64_t reflex_left = 0;   // left: close to both facets of a reflex edge (Fig. 4.7 copies not done)
  std::int64_t crowded_left = 0;  // left: close to two facets outside P / without a common edge / to three
  std::int64_t on_plane = 0;      // not moved: exactly on a facet plane
  std::int64_t first_pass = 0;     // moved with a first-pass part (among size())
  std::int64_t fallback = 0;       // moved by a fallback (first pass only / second only; among size())
  std::int64_t parallel = 0;       // first-pass moves of box-edge pieces parallel to E (among the moves)
  std::int64_t parallel_left = 0;  // first-pass moves not made: E on the box edge's line
  std::int64_t frozen_left = 0;   // left: in the caller's frozen set (their move inverted a tetrahedron)
  std::int64_t centres = 0;       // square centres carried with their corners (among size())
  std::int64_t shortened = 0;     // moved by 1/2..1/16 of a refused second-pass move (among size())

 private:
  std::unordered_map<GridPoint, Warp, GridPointHash> map_;
};

}  // namespace pqmesh::tet3d
