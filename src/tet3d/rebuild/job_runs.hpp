#pragma once
// Running box jobs on an assembler (facet_boxes.cpp's passes and the
// rebuild loop's trials, worst_box_freeze.cpp): every job or a subset, always
// in job order, so that two runs on one table make the same tetrahedra from
// the same vertices.
#include <cstdint>
#include <memory>
#include <span>

#include "tet3d/boxes/box_assembler.hpp"

namespace pqmesh::tet3d {

// What every pass of one box meshing run shares.
struct BoxPass {
  const OctTree& tree;
  const CornerSet& corners;
  const Domain3& domain;
  std::span<const BoxJob> jobs;
  bool two_apex = false;   // BoxAssembler::allow_two_apex
  bool facet_fans = true;  // BoxAssembler::allow_facet_fans
  const EmptyCells* empty_cells = nullptr;  // BoxAssembler::set_empty_cells
};

void run_jobs(BoxAssembler& a, const OctTree& tree, std::span<const BoxJob> jobs);
// The jobs `scope` (ascending), as run_jobs would run them.
void run_jobs(BoxAssembler& a, const OctTree& tree, std::span<const BoxJob> jobs, std::span<const std::int32_t> scope);

// A collect-mode trial (BoxAssembler::collect_bad) on `warps` of every job,
// or of the jobs `scope` (ascending).
std::unique_ptr<BoxAssembler> full_trial(const BoxPass& pass, const WarpTable& warps);
std::unique_ptr<BoxAssembler> partial_trial(const BoxPass& pass, const WarpTable& warps,
                                            std::span<const std::int32_t> scope);

}  // namespace pqmesh::tet3d
