#pragma once
// The angle bound of the 2D quadtree mesher with its default refinement pass
// (docs/algorithm/quad2d.md "Angle bound", "Delaunay refinement pass"):
//     min angle >= min(kQuadMeshBoundC * alpha, kQuadMeshBoundTheta0Degrees)
// with alpha the smallest interior angle of the input polygon, and 20 degrees
// (the refinement target) when alpha >= 60 degrees. The thesis proves a bound
// of the first form with unstated constants; these are the constants we
// measured over the data/2d corpus, 300 seeded random polygons with holes and
// 2,000 more under harder generator settings (worst: 0.545 alpha for small
// alpha, 16.5 degrees at alpha = 50 degrees), rounded down. The property tests
// assert the bound on every test input and the CLI prints it. Without the
// refinement pass (refine_angle_degrees = 0) the measured constants are
// 0.135 and 8.1 degrees.
namespace pqmesh {

// With refinement towards 20 degrees or more (the default).
inline constexpr double kQuadMeshBoundC = 0.5;
inline constexpr double kQuadMeshBoundTheta0Degrees = 16.0;
// Without refinement (refine_angle_degrees = 0): the quadtree mesh alone.
inline constexpr double kQuadMeshUnrefinedBoundC = 0.13;
inline constexpr double kQuadMeshUnrefinedBoundTheta0Degrees = 8.0;

// The bound for a given alpha, in degrees. Refinement targets between 0 and 20
// degrees were not measured; they get the unrefined constants. With
// refinement and alpha >= 60 degrees the bound is the 20-degree target.
// (Angles are floating-point measurements: compare with a 1e-9 slack.)
constexpr double quad_mesh_angle_bound(double alpha_degrees, double refine_angle_degrees = 20) {
  const bool refined = refine_angle_degrees >= 20;
  if (refined && alpha_degrees >= 60) return 20;
  const double c = refined ? kQuadMeshBoundC : kQuadMeshUnrefinedBoundC;
  const double theta0 = refined ? kQuadMeshBoundTheta0Degrees : kQuadMeshUnrefinedBoundTheta0Degrees;
  return c * alpha_degrees < theta0 ? c * alpha_degrees : theta0;
}

}  // namespace pqmesh
