// The two-facet box's apex facet (§4.5.5; two_facet_box.cpp
// two_facet_apex): every-run seed 197, a two-facet box whose nearer facet
// F1 is a sliver along a box face. Checked through tet_mesh's pipeline and
// check_mesh: some box takes the farther plane's facet and aspect x alpha
// <= 1,000.
#include <gtest/gtest.h>

#include "pqmesh/domain.hpp"
#include "support/random_domains.hpp"
#include "warped_box_mesh.hpp"

namespace pqmesh {
namespace {

TEST(TwoFacetApex, SliverFacetAlongABoxFaceGivesTheApexToTheOtherFacet) {
  const Domain3 d = make_domain(test::random_polyhedron(197, test::every_run_polyhedron_options()));
  const tet3d::BoxMesh m = test::warped_box_mesh(d);
  EXPECT_LE(test::valid_aspect_times_alpha(d, m), 1000.0);
  EXPECT_GT(m.stats.two_facet_apex_farther, 0) << "no two-facet box took the farther plane's facet";
}

}  // namespace
}  // namespace pqmesh
