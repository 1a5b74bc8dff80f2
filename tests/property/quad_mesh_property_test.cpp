// The 2D quadtree mesher over 300 seeded random polygons with holes
// (nonconvex, spikes down to ~1 degree, near-touching holes, coarse-grid
// snapped vertices; tests/support/random_domains.hpp): every mesh passes the
// checker, and the smallest angle meets the bound documented in
// docs/algorithm/quad2d.md "Angle bound", min angle >= min(C * alpha, THETA0),
// and 20 degrees when alpha >= 60 degrees (the default refinement pass,
// docs/algorithm/quad2d.md "Delaunay refinement pass").
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <iostream>
#include <numbers>

#include "pqmesh/alpha.hpp"
#include "pqmesh/check.hpp"
#include "pqmesh/domain.hpp"
#include "pqmesh/quadmesh.hpp"
#include "pqmesh/quadmesh_bound.hpp"
#include "pqmesh/quality.hpp"
#include "support/random_domains.hpp"

namespace pqmesh {
namespace {

constexpr int kPolygons = 300;

TEST(QuadMeshProperty, RandomPolygonsAreValidAndWellShaped) {
  double worst_ratio = 1e300, worst_angle = 1e300;
  std::uint64_t worst_seed = 0;
  std::int64_t triangles = 0;
  for (std::uint64_t seed = 1; seed <= kPolygons; ++seed) {
    const Domain2 d = make_domain(test::random_polygon_with_holes(seed));
    const QuadMeshResult r = quad_mesh(d);
    const CheckReport check = check_mesh(r.mesh, d);
    ASSERT_TRUE(check.valid()) << test::describe_polygon(seed) << "\n" << check.to_text();
    const double alpha = compute_alpha(d.pslg.vertices, d.loops).radians * 180 / std::numbers::pi;
    const double achieved = quality_report(r.mesh).min_angle.min;
    triangles += static_cast<std::int64_t>(r.mesh.triangles.size());
    const double ratio = achieved / std::min(alpha, 60.0);
    if (ratio < worst_ratio) {
      worst_ratio = ratio;
      worst_seed = seed;
    }
    worst_angle = std::min(worst_angle, achieved);
    EXPECT_GE(achieved, quad_mesh_angle_bound(alpha) - 1e-9) << test::describe_polygon(seed) << " alpha " << alpha;
    // Ruppert's guarantee for the refinement pass when no input angle is sharp
    // (measured in floating point here and in the refiner: a hair of slack).
    if (alpha >= 60) {
      EXPECT_GE(achieved, 20 - 1e-9) << test::describe_polygon(seed);
    }
  }
  std::cout << kPolygons << " polygons, " << triangles << " triangles; worst min angle / min(alpha, 60) = "
            << worst_ratio << " (seed " << worst_seed << "), smallest angle " << worst_angle << "\n";
}

// Harder generator settings: many holes with gaps down to 1e-5 of the part,
// spikes down to 0.5 degrees, vertices snapped to a coarse dyadic grid (so
// edges pass through box corners and along box sides). Validity only; the
// seeds include one (1130, many holes) whose warped corner near the origin
// needed many ulp steps to be rounded onto its segment.
TEST(QuadMeshProperty, HardGeneratorSettingsAreValid) {
  const auto settings = test::hard_polygon_options();
  int meshed = 0;
  for (const test::PolygonOptions& o : settings) {
    std::vector<std::uint64_t> seeds;
    for (std::uint64_t seed = 1; seed <= 30; ++seed) seeds.push_back(seed);
    if (&o == &settings[0]) seeds.push_back(1130);
    for (const std::uint64_t seed : seeds) {
      const Domain2 d = make_domain(test::random_polygon_with_holes(seed, o));
      const QuadMeshResult r = quad_mesh(d);
      const CheckReport check = check_mesh(r.mesh, d);
      ASSERT_TRUE(check.valid()) << test::describe_polygon(seed, o) << "\n" << check.to_text();
      ++meshed;
    }
  }
  EXPECT_EQ(meshed, 91);
}

}  // namespace
}  // namespace pqmesh
