// Regression test for edge boxes whose cones from the apex on E are flat,
// made with F ∩ b and G ∩ b fanned from points of their own facets
// (docs/ALGORITHM.md §12.5 "Facet fans in flat edge boxes";
// src/tet3d/edge_box_fans.cpp).
//
// Bounded seed 86 (alpha 42.97 deg, 357k tetrahedra) is the cheap input: its
// worst tetrahedron was the cone from the apex v on E (edge 11) over a small
// face triangle on face y = 1 of edge box leaf 4439 (h = 1/64), a chord of
// facet 5 (one of E's facets) and a warped corner, v 0.018 h from that face
// (aspect x alpha 1,791.7). One edge box takes the construction, and the
// worst is now a united vertex box's tetrahedron: measured 286.3. (Bounded
// seeds 126 and 172 go 2,800.2 -> 75.0 and 17,197.9 -> 1,482.4 the same way,
// at 7 and 46 s cpu.)
//
// The run goes through tet_mesh's pipeline (warped_box_mesh.hpp), then
// check_mesh. Bound: about the geometric mean of the two measurements,
// sqrt(1,791.7 x 286.3) = 716; without the construction the assertion fails
// (and the stat does not count).
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
