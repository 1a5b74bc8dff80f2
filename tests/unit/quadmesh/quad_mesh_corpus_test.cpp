// The 2D quadtree mesher on the data/2d corpus: every mesh passes the checker
// and meets the documented angle bound (docs/algorithm/quad2d.md "Angle
// bound").
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <numbers>
#include <string>

#include "support/paths.hpp"
#include "pqmesh/alpha.hpp"
#include "pqmesh/check.hpp"
#include "pqmesh/quadmesh.hpp"
#include "pqmesh/quadmesh_bound.hpp"
#include "pqmesh/quality.hpp"
#include "pqmesh/read_domain.hpp"

namespace pqmesh {
namespace {

class Corpus2d : public ::testing::TestWithParam<std::string> {};

TEST_P(Corpus2d, MeshIsValid) {
  const Domain2 d = make_domain(read_pslg(test::data_path("2d/" + GetParam())));
  const QuadMeshResult r = quad_mesh(d);
  const CheckReport check = check_mesh(r.mesh, d);
  EXPECT_TRUE(check.valid()) << check.to_text();
  const QualityReport q = quality_report(r.mesh);
  const double alpha = compute_alpha(d.pslg.vertices, d.loops).radians * 180 / std::numbers::pi;
  EXPECT_GE(q.min_angle.min, quad_mesh_angle_bound(alpha) - 1e-9);
  std::cout << GetParam() << ": " << r.mesh.triangles.size() << " triangles, min angle " << q.min_angle.min
            << " alpha " << alpha << " leaves " << r.stats.leaves << "\n";
}

INSTANTIATE_TEST_SUITE_P(All, Corpus2d,
                         ::testing::Values("square.poly", "l_shape.poly", "square_holes.poly", "comb.poly",
                                           "spike_10deg.poly", "spike_5deg.poly", "spike_1deg.poly", "regions.poly"),
                         [](const auto& param_info) {
                           std::string n = param_info.param.substr(0, param_info.param.find('.'));
                           return n;
                         });

}  // namespace
}  // namespace pqmesh
