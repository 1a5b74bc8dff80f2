#include "tet3d/points/facet_plane.hpp"

#include <cmath>
#include <limits>
#include <string>

#include "plc/facet_triangle_range.hpp"
#include "pqmesh/errors.hpp"

namespace pqmesh::tet3d {

namespace {

// The first facet triangle of `facet` (it spans the facet's plane).
std::array<Vec3, 3> first_triangle(const Domain3& domain, int facet) {
  for (const std::size_t t : pqmesh::detail::facet_triangle_range(domain, facet)) {
    const auto& tri = domain.facet_triangles[t];
    return {domain.plc.vertices[static_cast<std::size_t>(tri[0])],
            domain.plc.vertices[static_cast<std::size_t>(tri[1])],
            domain.plc.vertices[static_cast<std::size_t>(tri[2])]};
  }
  throw InternalError("tet3d: facet " + std::to_string(facet) + " has no triangle");
}

}  // namespace

FacetPlane::FacetPlane(const Domain3& domain, int facet) : FacetPlane(facet, first_triangle(domain, facet)) {}

FacetPlane::FacetPlane(int facet, const std::array<Vec3, 3>& triangle)
    : facet_(facet), a_(triangle[0]), b_(triangle[1]), c_(triangle[2]), side_(a_, b_, c_) {
  const Vec3 n = cross(b_ - a_, c_ - a_);
  n_ = (1.0 / norm(n)) * n;
}

Vec3 FacetPlane::settle(Vec3 p, int axis) const {
  // Along the line through p parallel to `axis` the plane is crossed at one
  // point (the normal's component on the axis is nonzero; else throw). Find
  // two doubles on either side of it by steps doubling from one ulp, then
  // bisect down to adjacent doubles: the plane then meets the ulp box of both,
  // within_ulp_of_plane holds. Every comparison is an exact orient3d.
  if (side_.meets_ulp_box(p)) return p;
  const double inf = std::numeric_limits<double>::infinity();
  const Sign s0 = side(p);
  const double na = axis_coord(n_, axis);
  if (na == 0) throw InternalError("tet3d: cannot settle along an axis parallel to facet " + std::to_string(facet_));
  const double dir = ((s0 == Sign::Positive) == (na < 0)) ? 1.0 : -1.0;
  const double x0 = axis_coord(p, axis);
  double near = x0, step = std::fabs(std::nextafter(x0, dir * inf) - x0);
  Vec3 q = p;
  for (int k = 0; k < 2100; ++k, step *= 2) {
    const double far = x0 + dir * step;
    axis_ref(q, axis) = far;
    const Sign s = side(q);
    if (s == Sign::Zero) return q;
    if (s != s0) {
      // Bisect [near, far] (in the order of the doubles).
      double lo = near, hi = far;
      for (int it = 0; it < 200; ++it) {
        const double mid = lo + (hi - lo) / 2;
        if (mid == lo || mid == hi) break;
        axis_ref(q, axis) = mid;
        const Sign sm = side(q);
        if (sm == Sign::Zero) return q;
        (sm == s0 ? lo : hi) = mid;
      }
      axis_ref(q, axis) = lo;
      if (side_.meets_ulp_box(q)) return q;
      axis_ref(q, axis) = hi;
      if (side_.meets_ulp_box(q)) return q;
      break;
    }
    near = far;
  }
  throw InternalError("tet3d: point does not settle on the plane of facet " + std::to_string(facet_));
}

Vec3 FacetPlane::crossing(Vec3 p, Vec3 q) const {
  // Parameter of the crossing from the signed distances (constructions).
  const double dp = distance(p), dq = distance(q);
  const double t = dp / (dp - dq);
  Vec3 x = p;
  int free_axis = 0;
  double best = -1;
  for (int a = 0; a < 3; ++a) {
    const double pa = axis_coord(p, a), qa = axis_coord(q, a);
    if (pa == qa) continue;  // kept exactly: the point stays on the segment's fixed planes
    axis_ref(x, a) = pa + t * (qa - pa);
    // The axis along which the plane's crossing is best conditioned: for a
    // box edge the only one that varies; for a warped ring segment (all
    // three may vary) the one with the largest |Δ_a n_a|, never an axis
    // parallel to the plane (settle needs n_a != 0).
    const double w = std::fabs((qa - pa) * axis_coord(n_, a));
    if (w > best) {
      best = w;
      free_axis = a;
    }
  }
  x = settle(x, free_axis);
  const double lo = std::fmin(axis_coord(p, free_axis), axis_coord(q, free_axis));
  const double hi = std::fmax(axis_coord(p, free_axis), axis_coord(q, free_axis));
  if (!(axis_coord(x, free_axis) > lo && axis_coord(x, free_axis) < hi))
    throw InternalError("tet3d: crossing of facet " + std::to_string(facet_) +
                        " within an ulp of a segment end (a box vertex this close must be warped, §4.3)");
  return x;
}

}  // namespace pqmesh::tet3d
