// Edge boxes with flat cones from the apex on E fan F ∩ b and G ∩ b from
// points of their own facets (src/tet3d/boxes/edge_box_fans.cpp). Bounded seed 86
// through tet_mesh's pipeline and check_mesh: some edge box takes the fans
// and aspect x alpha <= 716.
#include <gtest/gtest.h>

#include "pqmesh/domain.hpp"
#include "support/random_domains.hpp"
#include "warped_box_mesh.hpp"

namespace pqmesh {
namespace {

TEST(EdgeFacetFans, FlatEdgeBoxGetsFacetFanPoints) {
  const Domain3 d = make_domain(test::random_polyhedron(86, test::bounded_feature_polyhedron_options()));
  const tet3d::BoxMesh m = test::warped_box_mesh(d);
  EXPECT_GT(m.stats.edge_facet_fans, 0);
  EXPECT_LE(test::valid_aspect_times_alpha(d, m), 716.0);
}

}  // namespace
}  // namespace pqmesh
