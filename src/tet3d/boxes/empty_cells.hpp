#pragma once
// The empty boxes of one box meshing run (jobs of kind BoxKind::Empty: no P
// face meets the closed cube), looked up by centre and level. An empty box
// asks it whether the leaf across one of its faces is an empty box of its
// own size (empty_box.cpp, the Kuhn faces of docs/algorithm/tet3d_boxes.md
// "Empty boxes").
#include <cstdint>
#include <span>
#include <vector>

#include "tet3d/facet_boxes.hpp"
#include "tet3d/points/first_use_index.hpp"
#include "tet3d/points/grid_point.hpp"

namespace pqmesh::tet3d {

class EmptyCells {
 public:
  // The leaves of the jobs of kind Empty. Cost: O(jobs), one hash entry per
  // empty box.
  EmptyCells(const OctTree& tree, std::span<const BoxJob> jobs);
  // Whether an empty box of level `level` has centre `centre`. Two leaves
  // never share a centre (they would overlap), so the centre names the box;
  // the level tells a same-size box from a smaller one whose centre is there.
  bool holds(const GridPoint& centre, std::int32_t level) const {
    const int id = index_.find(centre);
    return id >= 0 && levels_[static_cast<std::size_t>(id)] == level;
  }

 private:
  // Lookups only, never iterated (first_use_index.hpp).
  FirstUseIndex<GridPoint, GridPointHash> index_;
  std::vector<std::int32_t> levels_;  // by id
};

}  // namespace pqmesh::tet3d
