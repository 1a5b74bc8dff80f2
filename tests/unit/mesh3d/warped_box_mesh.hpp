// tet_mesh's pipeline up to the warped boxes, for the worst-box regression
// tests and the worst-box probe: the generic-grid octree with the separating
// splits, plan_all_kinds, mesh_boxes with warping. Every mesh made here is
// checked (valid_aspect_times_alpha, or the caller's check_mesh). Also the
// lightest octree planned for tests that call mesh_boxes or the warp
// themselves, and the comparison of two box meshes.
#pragma once

#include <gtest/gtest.h>

#include <cstddef>
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

// tet_mesh's lightest octree (mesh3d.md "Light construction first"): the
// generic grid, extended boxes of margin 1, no separating splits.
inline mv3d::OctreeOptions lightest_octree_options() {
  mv3d::OctreeOptions oo;
  oo.generic_grid = true;
  oo.extended_margin = 1;
  oo.separate = false;
  return oo;
}

// An octree of d with its box plan and corner set, for tests that call
// mesh_boxes or the warp themselves.
struct PlannedOctree {
  std::unique_ptr<mv3d::OctreeBuilder> builder;
  mesh3d::BoxPlan plan;
  std::unique_ptr<tet3d::CornerSet> corners;
  const OctTree& tree() const { return builder->tree(); }
};

inline PlannedOctree planned_octree(const Domain3& d, const mv3d::OctreeOptions& oo) {
  PlannedOctree out;
  out.builder = std::make_unique<mv3d::OctreeBuilder>(d, oo);
  out.builder->build();
  out.plan = mesh3d::plan_all_kinds(*out.builder);
  out.corners = std::make_unique<tet3d::CornerSet>(*out.builder);
  return out;
}

// Two box meshes are the same vertex for vertex (coordinates and keys),
// tetrahedron for tetrahedron (with their jobs and leaves), with the same
// warp counts.
inline void expect_same_box_mesh(const tet3d::BoxMesh& a, const tet3d::BoxMesh& b) {
  ASSERT_EQ(a.mesh.vertices.size(), b.mesh.vertices.size());
  for (std::size_t i = 0; i < a.mesh.vertices.size(); ++i) {
    ASSERT_EQ(a.mesh.vertices[i], b.mesh.vertices[i]) << "vertex " << i;
    ASSERT_TRUE(a.keys[i] == b.keys[i]) << "vertex key " << i;
  }
  EXPECT_EQ(a.mesh.tetrahedra, b.mesh.tetrahedra);
  EXPECT_EQ(a.tet_job, b.tet_job);
  EXPECT_EQ(a.tet_leaf, b.tet_leaf);
  EXPECT_EQ(a.warped, b.warped);
  EXPECT_EQ(a.warp_conflicts, b.warp_conflicts);
  EXPECT_EQ(a.warp_centres, b.warp_centres);
  EXPECT_EQ(a.warp_inverting_left, b.warp_inverting_left);
  EXPECT_EQ(a.warp_rebuilds, b.warp_rebuilds);
  EXPECT_EQ(a.worst_box_rounds, b.worst_box_rounds);
  EXPECT_EQ(a.box_runs, b.box_runs);
  EXPECT_EQ(a.wider_table, b.wider_table);
  EXPECT_EQ(a.stats.edge_two_apex, b.stats.edge_two_apex);
}

// check_mesh must pass (a test failure otherwise); the mesh's worst aspect
// ratio times the domain's alpha in radians (the Theorem 7 product).
inline double valid_aspect_times_alpha(const Domain3& d, const tet3d::BoxMesh& m) {
  const CheckReport report = check_mesh(m.mesh, d);
  EXPECT_TRUE(report.valid()) << report.to_text();
  return aspect_times_alpha(quality_report(m.mesh).aspect_ratio.max, compute_alpha(d.plc).radians);
}

}  // namespace pqmesh::test
