#pragma once
// The distance constructions of the local feature size in 2D (lfs2d.hpp) and
// 3D (lfs3d.hpp), one template for both, so that the brute force and the grid
// evaluator of either dimension compute bit-identical distances.
#include "pqmesh/vec.hpp"

namespace pqmesh::detail {

// The squared length of a cross product: a scalar in 2D, a vector in 3D.
inline double lfs_square(double c) { return c * c; }
inline double lfs_square(Vec3 c) { return dot(c, c); }

// Squared distance from x to the point p (a construction).
template <class V>
double lfs_dist2_point(V x, V p) {
  const V d = x - p;
  return dot(d, d);
}

// Squared distance from x to the closed segment ab (a construction). The
// clamped cases return exactly lfs_dist2_point of the endpoint, so a vertex
// and its incident edges give the same value when the endpoint is nearest,
// and 0 when x is the endpoint.
template <class V>
double lfs_dist2_segment(V x, V a, V b) {
  const V ab = b - a, ax = x - a;
  const double t = dot(ax, ab);
  if (t <= 0) return dot(ax, ax);
  const double l = dot(ab, ab);
  if (t >= l) return lfs_dist2_point(x, b);
  return lfs_square(cross(ab, ax)) / l;
}

}  // namespace pqmesh::detail
