#pragma once
// Geometry of one planar facet (thesis §1.4): its plane, the coordinate axis
// dropped to work in 2D, and the exact turn of its loops in that projection.
//
// Dropping an axis is exact (the other two coordinates are copied), and for a
// plane not parallel to the dropped axis it is a bijection, so every 2D
// predicate on projected points decides the same question exactly in the plane.
#include <array>
#include <optional>
#include <vector>

#include "pqmesh/plc.hpp"
#include "predicates/predicates.hpp"

namespace pqmesh::detail {

// Projection dropping axis `drop`, keeping the cyclic order of the others
// (the convention of orient2d_projected).
inline Vec2 project(Vec3 p, int drop) {
  switch (drop) {
    case 0: return {p.y, p.z};
    case 1: return {p.z, p.x};
    default: return {p.x, p.y};
  }
}


// a, b, c lie on one line (exact: all three axis projections are degenerate).
bool collinear(Vec3 a, Vec3 b, Vec3 c);

// An axis such that the triangle abc (not collinear) projects to a
// non-degenerate triangle, preferring the axis where `hint` (e.g. an
// approximate normal) is largest in magnitude.
int choose_drop(Vec3 a, Vec3 b, Vec3 c, Vec3 hint);

// Newell's approximate normal of a loop (a construction; length = 2 * area).
Vec3 newell_normal(const std::vector<Vec3>& vertices, const std::vector<int>& loop);

struct FacetPlane {
  std::array<int, 3> basis{-1, -1, -1};  // three non-collinear vertex ids of the facet
  int drop = 2;                          // projection axis; the plane is not parallel to it
  // Exact turn of loops[0] in the projection. The facet's right-hand normal
  // (by the order of loops[0]) has a component along `drop` of this sign.
  Sign outer_turn = Sign::Zero;
};

// Three non-collinear vertices of the facet, or nullopt if all are collinear.
std::optional<std::array<int, 3>> find_basis(const std::vector<Vec3>& vertices, const Facet3& facet);

// Projected coordinates of every vertex id used by the facet, indexed by a
// local id; `local_of` maps the facet's loops to local ids.
struct ProjectedFacet {
  std::vector<Vec2> points;                  // by local id
  std::vector<int> vertex_of;                // local id -> vertex id
  std::vector<std::vector<int>> loops;       // loops in local ids
};
ProjectedFacet project_facet(const std::vector<Vec3>& vertices, const Facet3& facet, int drop);

}  // namespace pqmesh::detail
