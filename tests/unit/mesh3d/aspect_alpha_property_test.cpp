// Theorem 7 (thesis ch. 4) on the fast corpus models: tet_mesh with its
// defaults, check_mesh valid, and max aspect ratio * alpha <= kAspectAlphaC
// (aspect_alpha_property.hpp; the same constant the random polyhedra of
// random_polyhedra_test.cpp are held to). The slow corpus models run with
// --gtest_also_run_disabled_tests (0.5-30 s each in Release, ALGORITHM.md §13).
#include <gtest/gtest.h>

#include <cstdio>
#include <numbers>
#include <string>

#include "aspect_alpha_property.hpp"
#include "pqmesh/alpha.hpp"
#include "pqmesh/check.hpp"
#include "pqmesh/domain.hpp"
#include "pqmesh/quality.hpp"
#include "pqmesh/read_domain.hpp"
#include "pqmesh/tetmesh.hpp"
#include "support/paths.hpp"

namespace pqmesh::test {
namespace {

class CorpusAspectAlpha : public ::testing::TestWithParam<const char*> {};

TEST_P(CorpusAspectAlpha, ValidWithAspectBelowCOverAlpha) {
  const Domain3 d = make_domain(read_plc(data_path(std::string("3d/") + GetParam())));
  const double alpha = compute_alpha(d.plc).radians;
  const TetMeshResult m = tet_mesh(d);
  const CheckReport c = check_mesh(m.mesh, d);
  ASSERT_TRUE(c.valid()) << GetParam() << "\n" << c.to_text();
  const double aspect = quality_report(m.mesh).aspect_ratio.max;
  std::printf("%-18s %zu tets, alpha %.2f deg, max aspect %.1f, aspect*alpha %.1f (C = %.0f)%s\n", GetParam(),
              m.mesh.tetrahedra.size(), alpha * 180 / std::numbers::pi, aspect, aspect_times_alpha(aspect, alpha),
              kAspectAlphaC, m.stats.warp_failure.empty() ? "" : ", unwarped fallback");
  EXPECT_LE(aspect_times_alpha(aspect, alpha), kAspectAlphaC)
      << GetParam() << ": max aspect " << aspect << " at alpha " << alpha << " rad";
}

INSTANTIATE_TEST_SUITE_P(Fast, CorpusAspectAlpha, ::testing::Values("cube.poly", "l_block.poly", "tuning_fork.poly"));
INSTANTIATE_TEST_SUITE_P(DISABLED_Slow, CorpusAspectAlpha,
                         ::testing::Values("star_vertex.poly", "schoenhardt.poly", "wedge_5deg.poly",
                                           "cube_cavity.poly", "plate_holes.poly", "box_with_hole.stl",
                                           "cube_through_hole.poly", "cube.obj"));

}  // namespace
}  // namespace pqmesh::test
