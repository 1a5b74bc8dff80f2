// An edge box whose P edge E runs 3.5 deg off one of its faces (every-run
// seed 30): a point reported by the rebuild loop keeps its second-pass move
// within the box faces (WarpOptions::second_only, warp.hpp). Checked through tet_mesh's
// pipeline and check_mesh: aspect x alpha <= 2,500.
#include <gtest/gtest.h>

#include "pqmesh/domain.hpp"
#include "support/random_domains.hpp"
#include "warped_box_mesh.hpp"

namespace pqmesh {
namespace {

TEST(EdgeBoxApex, FrozenFacePointKeepsItsMoveWithinTheFace) {
  const Domain3 d = make_domain(test::random_polyhedron(30, test::every_run_polyhedron_options()));
  EXPECT_LE(test::valid_aspect_times_alpha(d, test::warped_box_mesh(d)), 2500.0);
}

}  // namespace
}  // namespace pqmesh
