// tet_mesh's pipeline up to the warped boxes, for the worst-box regression
// tests and the worst-box probe: the generic-grid octree with the separating
// splits, plan_all_kinds, mesh_boxes with warping. Every mesh made here is
// checked (valid_aspect_times_alpha, or the caller's check_mesh).
#pragma once

#include <gtest/gtest.h>

#include <memory>

#include "aspect_alpha_property.hpp"
#include "mesh3d/box_plan.hpp"
#include "mv3d/octree_builder.hpp"
#include "pqmesh/alpha.hpp"
#include "pqmesh/check.hpp"
#include "pqmesh/domain.hpp"
#include "pqmesh/quality.hpp"
#include "tet3d/facet_boxes.hpp"

namespace pqmesh::test {

// The pipeline's stages, for a caller that inspects the boxes (the probe).
struct WarpedBoxRun {
  std::unique_ptr<mv3d::OctreeBuilder> builder;
  mesh3d::BoxPlan plan;
  tet3d::BoxMesh mesh;
};

// tet_mesh's box options: warping on, the rest at their defaults.
inline tet3d::BoxMeshOptions warped_options() {
  tet3d::BoxMeshOptions bo;
  bo.warp = true;
  return bo;
}

// `hooks` turns off stages of mesh_boxes (tet_mesh never does).
inline WarpedBoxRun warped_box_run(const Domain3& d, const tet3d::BoxMeshOptions& bo = warped_options(),
                                   const tet3d::detail::BoxMeshTestHooks& hooks = {}) {
  mv3d::OctreeOptions oo;
  oo.separate = true;
  oo.generic_grid = true;
  WarpedBoxRun run;
  run.builder = std::make_unique<mv3d::OctreeBuilder>(d, oo);
  run.builder->build();
  run.plan = mesh3d::plan_all_kinds(*run.builder);
  const tet3d::CornerSet corners(*run.builder);
  run.mesh = tet3d::mesh_boxes(run.builder->tree(), corners, d, run.plan.jobs, bo, hooks);
  return run;
}

inline tet3d::BoxMesh warped_box_mesh(const Domain3& d) { return std::move(warped_box_run(d).mesh); }

// check_mesh must pass (a test failure otherwise); the mesh's worst aspect
// ratio times the domain's alpha in radians (the Theorem 7 product).
inline double valid_aspect_times_alpha(const Domain3& d, const tet3d::BoxMesh& m) {
  const CheckReport report = check_mesh(m.mesh, d);
  EXPECT_TRUE(report.valid()) << report.to_text();
  return aspect_times_alpha(quality_report(m.mesh).aspect_ratio.max, compute_alpha(d.plc).radians);
}

}  // namespace pqmesh::test
