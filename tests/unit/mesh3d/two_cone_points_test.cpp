// Edge boxes coned from two points (edge_box.cpp two_apex_box; the two
// runs of mesh_boxes): suite seed 67, whose P edge 7 runs 1.25 deg off the
// plane shared by two edge boxes of that edge. Checked: some edge box takes
// the construction and aspect x alpha <= 3,730 (check_mesh valid).
// Cost: about 6 s cpu in Release (954k tetrahedra, both runs).
#include <gtest/gtest.h>

#include <cstdint>

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

}  // namespace
}  // namespace pqmesh
