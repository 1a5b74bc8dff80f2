// A united vertex box at the tip of a narrow V notch (thesis §4.5.2): the two
// cap edges leaving the tip v pass through ONE square S of v's united box B,
// on either side of the notch, so S meets two P edges and three facets (the
// cap and both notch walls), a configuration §4.4's cases A-D do not list.
// The cells beyond S hold the two edges in two components (duplicates,
// §4.1.1), each an edge box triangulating S ∩ wedge(E) by Case B; B must
// build the same triangles: one Case B per edge (square_cases.cpp
// separate_edge_pieces). The configuration of bounded random polyhedron
// seed 37; checked on two prisms below.
#include <gtest/gtest.h>

#include <string>

#include "../plc/domain_fixtures.hpp"
#include "pqmesh/check.hpp"
#include "pqmesh/domain.hpp"
#include "pqmesh/tetmesh.hpp"

namespace pqmesh {
namespace {

// A prism z in [0.013, 0.311] over a quadrilateral-ish heptagon with a V
// notch cut from its top side: tip (tip_x, tip_y) on vertex 4 (bottom) and
// 11 (top), mouth half-width half_mouth at y = 0.97. Non-dyadic coordinates
// (general position with respect to the generic grid).
Plc3 notch_prism(double tip_x, double tip_y, double half_mouth) {
  return test::prism({{0.03, 0.02},
                      {0.97, 0.04},
                      {0.98, 0.96},
                      {tip_x + half_mouth, 0.97},
                      {tip_x, tip_y},
                      {tip_x - half_mouth, 0.97},
                      {0.01, 0.95}},
                     0.013, 0.311);
}

void expect_valid(const Plc3& plc, const char* what) {
  const Domain3 d = make_domain(plc);
  TetMeshResult m;
  ASSERT_NO_THROW(m = tet_mesh(d)) << what;
  EXPECT_TRUE(m.stats.warp_failure.empty()) << what << ": " << m.stats.warp_failure;
  const CheckReport c = check_mesh(m.mesh, d);
  EXPECT_TRUE(c.valid()) << what << ": " << c.to_text();
}

// Notch angles 2 atan(0.04 / 0.56) = 8.2 deg and 2 atan(0.03 / 0.47) = 7.3 deg.
TEST(VertexBoxNotchSquare, TwoNotchEdgesThroughOneSquareMeshValid) {
  expect_valid(notch_prism(0.503, 0.41, 0.04), "notch tip (0.503, 0.41)");
  expect_valid(notch_prism(0.497, 0.5, 0.03), "notch tip (0.497, 0.5)");
}

}  // namespace
}  // namespace pqmesh
