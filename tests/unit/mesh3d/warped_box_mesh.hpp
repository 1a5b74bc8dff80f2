// tet_mesh's pipeline up to the warped boxes, for the worst-box regression
// tests: the generic-grid octree with the separating splits, plan_all_kinds,
// mesh_boxes with warping. The caller runs check_mesh on the result.
#pragma once

#include "mesh3d/box_plan.hpp"
#include "mv3d/octree_builder.hpp"
#include "pqmesh/domain.hpp"
#include "tet3d/facet_boxes.hpp"

namespace pqmesh::test {

inline tet3d::BoxMesh warped_box_mesh(const Domain3& d) {
  mv3d::OctreeOptions oo;
  oo.separate = true;
  oo.generic_grid = true;
  mv3d::OctreeBuilder builder(d, oo);
  builder.build();
  const mesh3d::BoxPlan plan = mesh3d::plan_all_kinds(builder);
  const tet3d::CornerSet corners(builder);
  tet3d::BoxMeshOptions bo;
  bo.warp = true;
  return tet3d::mesh_boxes(builder.tree(), corners, d, plan.jobs, bo);
}

}  // namespace pqmesh::test
