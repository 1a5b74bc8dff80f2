#pragma once
// The angle bound of the 2D quadtree mesher (docs/ALGORITHM.md §8.8):
//     min angle >= min(kQuadMeshBoundC * alpha, kQuadMeshBoundTheta0Degrees)
// with alpha the smallest interior angle of the input polygon. The thesis
// proves a bound of this form with unstated constants; these are the constants
// we measured (over the data/2d corpus and 300 seeded random polygons with
// holes, worst case 0.157 * min(alpha, 60 deg)) and rounded down. The property
// tests assert the bound on every test input and the CLI prints it.
namespace pqmesh {

inline constexpr double kQuadMeshBoundC = 0.15;
inline constexpr double kQuadMeshBoundTheta0Degrees = 9.0;

// The bound for a given alpha, in degrees.
constexpr double quad_mesh_angle_bound(double alpha_degrees) {
  const double scaled = kQuadMeshBoundC * alpha_degrees;
  return scaled < kQuadMeshBoundTheta0Degrees ? scaled : kQuadMeshBoundTheta0Degrees;
}

}  // namespace pqmesh
