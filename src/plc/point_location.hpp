#pragma once
// Exact point location against a closed triangulated surface.
//
// Ray parity with a symbolic perturbation. The ray starts at
//   p' = p + (0, eps, eps^2)        (eps > 0 infinitesimal)
// and runs towards +x. A line in the (y, z) plane, a*y + b*z + c = 0 with
// (a, b) != (0, 0), never passes through p': the value at p' is
// (a*p.y + b*p.z + c) + a*eps + b*eps^2, not identically zero. So the ray
// misses every edge and vertex of every triangle, and crosses a triangle iff
// p' projects strictly inside the triangle's (y, z) projection and the plane
// of the triangle is met at positive x-distance. The sign of each perturbed
// orient2d is the first nonzero of: the exact orient2d at p, then the eps
// coefficient, then the eps^2 coefficient (coordinate differences, exact).
// When p is not on the surface, p and p' lie in the same component of the
// complement, so the parity of crossings decides inside/outside; and for a
// crossed triangle p itself is off the triangle's plane (p on the plane and in
// the closed projection would put p on the triangle), so the forward test
// needs no perturbation. Boundary is decided first, exactly.
#include <array>
#include <vector>

#include "plc/spatial_grid.hpp"
#include "pqmesh/domain.hpp"

namespace pqmesh::detail {

// p lies on the closed triangle abc; drop: an axis of non-degenerate projection.
bool point_on_triangle(Vec3 p, Vec3 a, Vec3 b, Vec3 c, int drop);

// The perturbed ray from p towards +x crosses triangle abc. Precondition: p is
// not on the triangle.
bool perturbed_ray_crosses(Vec3 p, Vec3 a, Vec3 b, Vec3 c);

// An axis along which the triangle projects non-degenerately.
int triangle_drop(Vec3 a, Vec3 b, Vec3 c);

// A located closed surface: triangles, their projection axes and a grid.
// Holds a reference to `vertices` (which must outlive it).
class SurfaceLocator {
 public:
  SurfaceLocator(const std::vector<Vec3>& vertices, std::vector<std::array<int, 3>> triangles);
  Location locate(Vec3 p) const;

  // f(t) for every triangle t crossed by the perturbed +x ray from p.
  // Precondition: p is on none of the triangles f is asked about (the caller
  // may pass `skip(t) == true` for triangles that p may lie on).
  template <class Skip, class F>
  void for_each_crossed(Vec3 p, Skip&& skip, F&& f) const {
    grid_.for_each_on_x_ray(p, [&](int t) {
      if (skip(t)) return;
      const auto& tri = triangles_[t];
      if (perturbed_ray_crosses(p, (*vertices_)[tri[0]], (*vertices_)[tri[1]], (*vertices_)[tri[2]])) f(t);
    });
  }

  const TriangleGrid& grid() const { return grid_; }
  const std::vector<std::array<int, 3>>& triangles() const { return triangles_; }
  int drop(int t) const { return drops_[t]; }

 private:
  const std::vector<Vec3>* vertices_;
  std::vector<std::array<int, 3>> triangles_;
  std::vector<signed char> drops_;
  TriangleGrid grid_;
};

// Builds a SurfaceLocator over a validated domain's facet triangles once and
// answers many queries fast (the public locate(Domain3, p) rebuilds nothing
// but scans every triangle). The domain must outlive the locator.
class DomainLocator3 {
 public:
  explicit DomainLocator3(const Domain3& domain) : surface_(domain.plc.vertices, domain.facet_triangles) {}
  Location locate(Vec3 p) const { return surface_.locate(p); }

 private:
  SurfaceLocator surface_;
};

}  // namespace pqmesh::detail
