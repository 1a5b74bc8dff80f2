#pragma once
// The ulp rule of docs/algorithm/quality.md "The validity checker" for points
// near a fixed plane, decided on two corners of the point's ulp box instead of
// eight.
//
// within_ulp_of_plane(p, a, b, c) (predicates.hpp) asks whether orient3d(a,
// b, c, x) takes one strict sign on all eight corners x of p's ulp box.
// orient3d(a, b, c, x) is the sign of an affine function of x whose gradient
// is +-n, n = (b - a) x (c - a) (the global sign depends only on orient3d's
// convention). Over a box it is largest at the corner taking the upper bound
// where n_i > 0 and the lower bound where n_i < 0 (either where n_i = 0), and
// smallest at the opposite corner (or the other way round). All eight corners
// are strictly on one side exactly when both extreme corners are strictly on
// that side. The signs of n's components are exact orient2d_projected values,
// computed once per plane, so the answer is the same exact answer. A plane
// normal to an axis needs no orient3d: one exact comparison of coordinates.
//
// The checker's boundary-face stage (check3d_facets.cpp) and the facet
// markers of mesh3d/boundary_faces.cpp use it: on slanted facets most of
// these orient3d calls reach the exact stages, and on the random polyhedra
// they would otherwise be the checker's largest cost.
#include <array>
#include <cmath>
#include <limits>

#include "pqmesh/vec.hpp"
#include "predicates/predicates.hpp"

namespace pqmesh::detail {

// Exact signs of the components of (b - a) x (c - a): component i is the
// orientation of a, b, c projected along axis i.
inline std::array<Sign, 3> plane_normal_signs(Vec3 a, Vec3 b, Vec3 c) {
  return {orient2d_projected(a, b, c, 0), orient2d_projected(a, b, c, 1), orient2d_projected(a, b, c, 2)};
}

// Equals within_ulp_of_plane(p, a, b, c) when normal == plane_normal_signs(a, b, c).
inline bool within_ulp_of_plane_at_extremes(Vec3 p, Vec3 a, Vec3 b, Vec3 c, const std::array<Sign, 3>& normal) {
  const double lo[3] = {next_down(p.x), next_down(p.y), next_down(p.z)};
  const double hi[3] = {next_up(p.x), next_up(p.y), next_up(p.z)};
  // A plane normal to axis i (n_j = n_k = 0 exactly, so a, b, c share their
  // exact i coordinate): the box meets it iff lo_i <= a_i <= hi_i. No
  // orient3d at all (axis-aligned facets, the common case).
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3, k = (i + 2) % 3;
    if (normal[static_cast<std::size_t>(i)] != Sign::Zero && normal[static_cast<std::size_t>(j)] == Sign::Zero &&
        normal[static_cast<std::size_t>(k)] == Sign::Zero) {
      const double ai = axis_coord(a, i);
      return lo[i] <= ai && ai <= hi[i];
    }
  }
  double up[3], down[3];
  for (int i = 0; i < 3; ++i) {
    const bool negative = normal[static_cast<std::size_t>(i)] == Sign::Negative;
    up[i] = negative ? lo[i] : hi[i];
    down[i] = negative ? hi[i] : lo[i];
  }
  const Sign s = orient3d(a, b, c, {up[0], up[1], up[2]});
  if (s == Sign::Zero) return true;
  return orient3d(a, b, c, {down[0], down[1], down[2]}) != s;
}

}  // namespace pqmesh::detail
