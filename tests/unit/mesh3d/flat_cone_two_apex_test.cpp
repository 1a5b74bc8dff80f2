// Edge boxes whose apex on E has flat cones (edge_box.cpp flat_two_apex):
// on suite seed 175 with the facet fans off, the two-point construction is
// used and the worst aspect ratio x alpha is at most 3,390; with the fans on
// (the default) the worst is strictly lower. Meshes pass check_mesh.
#include <gtest/gtest.h>

#include <cstdint>

#include "pqmesh/domain.hpp"
#include "support/random_domains.hpp"
#include "warped_box_mesh.hpp"

namespace pqmesh {
namespace {

TEST(FlatConeTwoApex, ApexAlmostOnABoxFaceIsConedFromTwoPoints) {
  const Domain3 d = make_domain(test::random_polyhedron(175, test::suite_polyhedron_options()));
  tet3d::detail::BoxMeshTestHooks without_fans;
  without_fans.facet_fans = false;
  const tet3d::BoxMesh two_points = test::warped_box_run(d, test::warped_options(), without_fans).mesh;
  EXPECT_GT(two_points.stats.edge_two_apex_flat, 0);
  const double two_points_worst = test::valid_aspect_times_alpha(d, two_points);
  EXPECT_LE(two_points_worst, 3390.0);
  const tet3d::BoxMesh m = test::warped_box_mesh(d);
  EXPECT_LT(test::valid_aspect_times_alpha(d, m), two_points_worst);
}

}  // namespace
}  // namespace pqmesh
