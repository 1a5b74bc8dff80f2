#pragma once
// Where smoothing (smooth.hpp) may put a vertex of a slanted facet or of a
// slanted input edge. Such a point has no double coordinates in general; the
// checker accepts a vertex on facet F when F's plane meets the vertex's ulp
// box, and on edge ab when the segment does (docs/algorithm/quality.md
// "Rounded Steiner points"). The construction places its own points by the
// same rule (tet3d/points: FacetPlane::settle, round_onto_segment), and so
// does this: a candidate is projected (a construction) and then settled by
// exact searches until the checker's test holds.
#include <array>
#include <optional>
#include <vector>

#include "pqmesh/domain.hpp"
#include "pqmesh/vec.hpp"
#include "tet3d/points/facet_plane.hpp"

namespace pqmesh::improve3d::detail {

class BoundarySnap {
 public:
  explicit BoundarySnap(const Domain3& domain);

  // q moved onto facet `facet`'s plane: projected, then settled along the axis of the normal's
  // largest component (FacetPlane::settle: within_ulp_of_plane holds). nullopt when the exact
  // search fails (not expected). Cost: O(1) orient3d calls per bisection step, ~64 steps at most.
  std::optional<Vec3> onto_facet(int facet, Vec3 q);
  // q moved onto domain edge `edge` (round_onto_segment: within_ulp_of_segment holds), keeping
  // q's coordinate on the edge's dominant axis clamped to the edge; nullopt when that fails.
  std::optional<Vec3> onto_edge(int edge, Vec3 q) const;
  // The axis of facet `facet`'s normal's largest component: its triangles keep their
  // orientation in the projection that drops it (orient2d_projected).
  int drop_axis(int facet);

 private:
  const tet3d::FacetPlane& plane(int facet);

  const Domain3& domain_;
  std::vector<int> first_triangle_;  // per facet, its first facet triangle
  std::vector<std::optional<tet3d::FacetPlane>> planes_;
};

}  // namespace pqmesh::improve3d::detail
