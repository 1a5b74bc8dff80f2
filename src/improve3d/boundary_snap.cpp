#include "improve3d/boundary_snap.hpp"

#include <cmath>
#include <cstddef>

#include "pqmesh/errors.hpp"
#include "tet3d/points/edge_point.hpp"

namespace pqmesh::improve3d::detail {

BoundarySnap::BoundarySnap(const Domain3& domain)
    : domain_(domain), first_triangle_(domain.plc.facets.size(), -1), planes_(domain.plc.facets.size()) {
  for (std::size_t t = domain.facet_triangles.size(); t-- > 0;)
    first_triangle_[static_cast<std::size_t>(domain.facet_triangle_owner[t])] = static_cast<int>(t);
}

const tet3d::FacetPlane& BoundarySnap::plane(int facet) {
  std::optional<tet3d::FacetPlane>& p = planes_[static_cast<std::size_t>(facet)];
  if (!p) {
    const auto& tri = domain_.facet_triangles[static_cast<std::size_t>(first_triangle_[static_cast<std::size_t>(facet)])];
    const auto vertex = [&](int i) { return domain_.plc.vertices[static_cast<std::size_t>(tri[static_cast<std::size_t>(i)])]; };
    p.emplace(facet, std::array<Vec3, 3>{vertex(0), vertex(1), vertex(2)});
  }
  return *p;
}

int BoundarySnap::drop_axis(int facet) {
  const Vec3 n = plane(facet).normal();
  int axis = 0;
  for (int a = 1; a < 3; ++a)
    if (std::fabs(axis_coord(n, a)) > std::fabs(axis_coord(n, axis))) axis = a;
  return axis;
}

std::optional<Vec3> BoundarySnap::onto_facet(int facet, Vec3 q) {
  const tet3d::FacetPlane& f = plane(facet);
  const Vec3 projected = q - f.distance(q) * f.normal();
  if (!std::isfinite(projected.x) || !std::isfinite(projected.y) || !std::isfinite(projected.z)) return std::nullopt;
  try {
    return f.settle(projected, drop_axis(facet));
  } catch (const InternalError&) {
    return std::nullopt;
  }
}

std::optional<Vec3> BoundarySnap::onto_edge(int edge, Vec3 q) const {
  const DomainEdge& e = domain_.edges[static_cast<std::size_t>(edge)];
  if (!std::isfinite(q.x) || !std::isfinite(q.y) || !std::isfinite(q.z)) return std::nullopt;
  try {
    return tet3d::round_onto_segment(domain_.plc.vertices[static_cast<std::size_t>(e.a)],
                                     domain_.plc.vertices[static_cast<std::size_t>(e.b)], q);
  } catch (const InternalError&) {
    return std::nullopt;
  }
}

}  // namespace pqmesh::improve3d::detail
