// A block with a thin exterior V slot (the domain of
// tests/unit/tet3d/reflex_slot_copies_test.cpp), half-widths 0.027 and
// 0.041: CornerSet holds every united box's cell corners (box_faces.cpp),
// so no square centre is a ring point. Checked through tet_mesh: the warped
// run does not fail, moves vertices, passes check_mesh and keeps aspect x
// alpha <= kMeasuredAspectAlphaC. Cost: about 3 s cpu per width in Release.
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <vector>

#include "../plc/domain_fixtures.hpp"
#include "pqmesh/alpha.hpp"
#include "pqmesh/check.hpp"
#include "pqmesh/domain.hpp"
#include "pqmesh/quality.hpp"
#include "pqmesh/tetmesh.hpp"

namespace pqmesh {
namespace {

// Block [0.1, 0.9] (x) x [y0, y1] x [0.1, 0.9] (z) with a V slot from its top:
// apex (ax, az), opening 2w wide at z = 0.9 (as reflex_slot_copies_test.cpp).
Plc3 slotted_block(double ax, double az, double w, double y0, double y1) {
  return test::prism_xz({{0.1, 0.1}, {0.9, 0.1}, {0.9, 0.9}, {ax + w, 0.9}, {ax, az}, {ax - w, 0.9}, {0.1, 0.9}}, y0, y1);
}

class SlotSquareCentre : public ::testing::TestWithParam<double> {};

TEST_P(SlotSquareCentre, WarpedMeshIsValidAndBounded) {
  const double w = GetParam();
  const Domain3 d = make_domain(slotted_block(0.47, 0.31, w, 0.13, 0.87));
  const TetMeshResult r = tet_mesh(d);
  const CheckReport report = check_mesh(r.mesh, d);
  ASSERT_TRUE(report.valid()) << "w " << w << ": " << report.to_text();
  EXPECT_EQ(r.stats.warp_failure, "") << "w " << w << ": the warped run threw, the mesh is unwarped";
  EXPECT_GT(r.stats.warped, 0) << "w " << w;
  const double alpha = compute_alpha(d.plc).radians;
  const double aspect = quality_report(r.mesh).aspect_ratio.max;
  std::printf("slot half-width %.3f: %zu tetrahedra, max aspect %.3f, alpha %.4f rad, %lld warped\n", w,
              r.mesh.tetrahedra.size(), aspect, alpha, static_cast<long long>(r.stats.warped));
  EXPECT_LE(aspect * alpha, kMeasuredAspectAlphaC) << "w " << w << ": max aspect " << aspect;
}

INSTANTIATE_TEST_SUITE_P(HalfWidths, SlotSquareCentre, ::testing::Values(0.027, 0.041));

}  // namespace
}  // namespace pqmesh
