#pragma once
// Which box jobs a rebuilt warp table can change (the rebuild loop of
// facet_boxes.cpp). A job reads the table only at grid points of its closed
// box: its faces' ring points and square centres, and their Fig. 4.7 copies,
// all lie on the box's faces. So a job whose closed box holds none of the
// points whose entry changed makes the same tetrahedra, and the same
// reports, from both tables, and a trial pass after a rebuild need only run
// the jobs that hold a changed point. The loop still accepts a table only
// after a trial of every job, so a job that broke this rule could cost a
// round, never a wrong mesh.
#include <cstdint>
#include <span>
#include <vector>

#include "tet3d/facet_boxes.hpp"
#include "tet3d/points/grid_point.hpp"
#include "tet3d/warp/warp_table.hpp"

namespace pqmesh::tet3d {

// The grid points whose entry or Fig. 4.7 copy was added, removed or moved
// (coordinates or key facet) from `before` to `after`, sorted, without
// repeats.
std::vector<GridPoint> changed_points(const WarpTable& before, const WarpTable& after);

// The closed boxes of the jobs, in fine grid units: the leaf's cube, or the
// united 2x2x2 box of a vertex job.
class JobBoxes {
 public:
  JobBoxes(const OctTree& tree, std::span<const BoxJob> jobs);
  // The jobs, ascending, whose closed box holds a point of `points` (sorted
  // as changed_points returns them) or that are listed in `also`.
  std::vector<std::int32_t> touching(std::span<const GridPoint> points, std::span<const std::int32_t> also) const;
  // Whether job j's closed box holds p.
  bool holds(std::int32_t j, const GridPoint& p) const;

 private:
  std::vector<GridPoint> lo_, hi_;  // per job
};

}  // namespace pqmesh::tet3d
