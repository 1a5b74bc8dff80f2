// Edge boxes coned from two points (edge_box.cpp two_apex_box; the two
// runs of mesh_boxes). Checked:
// - suite seed 67, whose P edge 7 runs 1.25 deg off the plane shared by two
//   edge boxes of that edge: some edge box takes the construction and
//   aspect x alpha <= 3,730 (check_mesh valid). About 6 s cpu in Release
//   (954k tetrahedra, both runs).
// - every-run seed 185 on tet_mesh's lightest octree, where the run with the
//   construction is made and loses: the first run's mesh remade from its
//   final warp table is the mesh of making the first run again whole
//   (vertices, keys, tetrahedra, jobs and counts equal). Under a second.
#include <gtest/gtest.h>

#include "pqmesh/check.hpp"
#include "pqmesh/domain.hpp"
#include "support/random_domains.hpp"
#include "warped_box_mesh.hpp"

namespace pqmesh {
namespace {

TEST(TwoConePoints, EdgeBoxAcrossAPushedFaceIsNotFrozen) {
  const Domain3 d = make_domain(test::random_polyhedron(67, test::suite_polyhedron_options()));
  const tet3d::BoxMesh m = test::warped_box_mesh(d);
  EXPECT_GT(m.stats.edge_two_apex, 0);
  EXPECT_LE(test::valid_aspect_times_alpha(d, m), 3730.0);
}

TEST(TwoConePoints, LostSecondRunRemakesTheFirstRunsMeshFromItsTable) {
  const Domain3 d = make_domain(test::random_polyhedron(185, test::every_run_polyhedron_options()));
  const test::PlannedOctree o = test::planned_octree(d, test::lightest_octree_options());
  tet3d::detail::BoxMeshTestHooks remade, rerun;
  rerun.remake_from_table = false;
  const tet3d::BoxMesh a = tet3d::mesh_boxes(o.tree(), *o.corners, d, o.plan.jobs, test::warped_options(), remade);
  const tet3d::BoxMesh b = tet3d::mesh_boxes(o.tree(), *o.corners, d, o.plan.jobs, test::warped_options(), rerun);
  ASSERT_EQ(a.box_runs, 3);  // the second run was made and lost
  ASSERT_EQ(b.box_runs, 3);
  test::expect_same_box_mesh(a, b);
  EXPECT_TRUE(check_mesh(a.mesh, d).valid());
}

}  // namespace
}  // namespace pqmesh
