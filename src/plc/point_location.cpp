#include "plc/point_location.hpp"

#include "plc/facet_geometry.hpp"
#include "plc/polygon2d.hpp"
#include "predicates/predicates.hpp"

namespace pqmesh::detail {

namespace {

// Sign of orient2d(U, W, P + (eps, eps^2)) in the (y, z) projection, where
// 2D x = 3D y and 2D y = 3D z. Expanding: orient2d(U, W, P)
// + eps * (U.y - W.y) + eps^2 * (W.x - U.x).
Sign perturbed_orient(Vec2 u, Vec2 w, Vec2 p) {
  const Sign s = orient2d(u, w, p);
  if (s != Sign::Zero) return s;
  if (u.y != w.y) return compare(u.y, w.y);
  return compare(w.x, u.x);
}

}  // namespace

bool point_on_triangle(Vec3 p, Vec3 a, Vec3 b, Vec3 c, int drop) {
  if (orient3d(a, b, c, p) != Sign::Zero) return false;
  return in_closed_triangle(project(p, drop), project(a, drop), project(b, drop), project(c, drop));
}

bool perturbed_ray_crosses(Vec3 p, Vec3 a, Vec3 b, Vec3 c) {
  const Vec2 A = project(a, 0), B = project(b, 0), C = project(c, 0), P = project(p, 0);
  const Sign s = orient2d(A, B, C);  // sign of the x component of the normal (b-a) x (c-a)
  if (s == Sign::Zero) return false; // parallel to the ray: p' is never on its projection
  if (perturbed_orient(A, B, P) != s || perturbed_orient(B, C, P) != s || perturbed_orient(C, A, P) != s)
    return false;
  // p + t e_x is on the plane at t = -n.(p - a) / n_x: forward iff the signs differ.
  return orient3d(a, b, c, p) == -s;
}

int triangle_drop(Vec3 a, Vec3 b, Vec3 c) { return choose_drop(a, b, c, cross(b - a, c - a)); }

SurfaceLocator::SurfaceLocator(const std::vector<Vec3>& vertices, std::vector<std::array<int, 3>> triangles)
    : vertices_(&vertices), triangles_(std::move(triangles)), grid_(vertices, triangles_) {
  drops_.reserve(triangles_.size());
  for (const auto& t : triangles_)
    drops_.push_back(static_cast<signed char>(triangle_drop(vertices[t[0]], vertices[t[1]], vertices[t[2]])));
}

Location SurfaceLocator::locate(Vec3 p) const {
  const auto& v = *vertices_;
  bool on = false;
  grid_.for_each_containing(p, [&](int t) {
    const auto& tri = triangles_[t];
    on = on || point_on_triangle(p, v[tri[0]], v[tri[1]], v[tri[2]], drops_[t]);
  });
  if (on) return Location::Boundary;
  bool inside = false;
  for_each_crossed(p, [](int) { return false; }, [&](int) { inside = !inside; });
  return inside ? Location::Inside : Location::Outside;
}

}  // namespace pqmesh::detail
