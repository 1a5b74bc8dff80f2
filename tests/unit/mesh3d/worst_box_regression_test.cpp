// Worst edge boxes of the random families (docs/algorithm/tet3d_warp.md), each
// through tet_mesh's pipeline (warped_box_mesh.hpp) and check_mesh.
// Bounded seeds 76 and 125 (P edge E clips a box edge / runs 0.002 h inside
// a box face): no warp frozen, no rebuild, aspect x alpha <= kAspectAlphaC.
#include <gtest/gtest.h>

#include <cstdint>

#include "pqmesh/domain.hpp"
#include "support/random_domains.hpp"
#include "warped_box_mesh.hpp"

namespace pqmesh {
namespace {

class WorstEdgeBox : public ::testing::TestWithParam<std::uint64_t> {};

TEST_P(WorstEdgeBox, ColumnIsWarpedAndTheBoundHolds) {
  const std::uint64_t seed = GetParam();
  const Domain3 d = make_domain(test::random_polyhedron(seed, test::bounded_feature_polyhedron_options()));
  const tet3d::BoxMesh m = test::warped_box_mesh(d);
  EXPECT_LE(test::valid_aspect_times_alpha(d, m), test::kAspectAlphaC) << "seed " << seed;
  EXPECT_EQ(m.warp_inverting_left, 0) << "seed " << seed << ": warps frozen by the rebuild loop";
  EXPECT_EQ(m.warp_rebuilds, 0) << "seed " << seed;
}

INSTANTIATE_TEST_SUITE_P(BoundedSeeds, WorstEdgeBox, ::testing::Values(76u, 125u));

// Suite seed 135 (E 2.1 deg off the edge box face x = 0, crossing its plane
// inside the box): the face takes part of its translation; no warp frozen,
// aspect x alpha <= 1,713.2.
TEST(WorstEdgeBoxSuite, FaceNearlyAlongEIsTranslatedPartly) {
  const Domain3 d = make_domain(test::random_polyhedron(135, test::suite_polyhedron_options()));
  const tet3d::BoxMesh m = test::warped_box_mesh(d);
  EXPECT_LE(test::valid_aspect_times_alpha(d, m), 1713.2);
  EXPECT_EQ(m.warp_inverting_left, 0) << "warps frozen by the rebuild loop";
}

// Every-run seed 36 (E 0.08 h above the bottom face of its edge box, whose
// corners the first pass moves h/4 along its normal): Case C is decided
// within the square (C1); aspect x alpha <= 1,000.
TEST(WorstEdgeBoxEveryRun, FaceMovedAlongItsNormalKeepsCaseC1) {
  const Domain3 d = make_domain(test::random_polyhedron(36, test::every_run_polyhedron_options()));
  EXPECT_LE(test::valid_aspect_times_alpha(d, test::warped_box_mesh(d)), 1000.0);
}

}  // namespace
}  // namespace pqmesh
