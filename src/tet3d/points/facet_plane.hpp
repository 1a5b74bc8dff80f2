#pragma once
// The plane of a P facet and the points constructed on it
// (docs/algorithm/tet3d_boxes.md "Exactness"). Decisions are exact orient3d
// signs against three vertices of one outward-oriented facet triangle;
// constructed points on the plane are rounded to doubles and then moved by
// single ulps until the plane meets their ulp box (within_ulp_of_plane,
// predicates.hpp), the 3D analogue of the 2D mesher's rule for points on
// slanted segments (docs/algorithm/quality.md "The validity checker",
// docs/algorithm/quad2d.md "Mesh vertices and warping").
#include <array>

#include "pqmesh/domain.hpp"
#include "pqmesh/vec.hpp"
#include "predicates/plane_side.hpp"
#include "predicates/predicates.hpp"

namespace pqmesh::tet3d {

class FacetPlane {
 public:
  // Facet `facet` of the domain (its first facet triangle spans the plane).
  FacetPlane(const Domain3& domain, int facet);
  FacetPlane(int facet, const std::array<Vec3, 3>& triangle);
  int facet() const { return facet_; }
  // Positive: p lies beyond the plane (outside P near the facet); Negative:
  // on P's side; Zero: on the plane.
  // (The sign of orient3d(a, b, c, p) through PlaneSide: the same exact
  // sign, with a cheaper exact stage for points near the plane.)
  Sign side(Vec3 p) const { return side_(p); }
  // The point of the segment [p, q] on the plane (p, q strictly on opposite
  // sides), within an ulp of the plane. Coordinates in which p and q agree
  // are kept exactly (a point on a box edge stays on that edge's lines, a
  // point of a box face on its plane); it is settled along the axis of p and
  // q's largest difference and must end strictly between them, else
  // InternalError (an end point within an ulp of F: warping's job, §4.3).
  Vec3 crossing(Vec3 p, Vec3 q) const;
  // Moves p along axis `axis` to a double whose ulp box the plane meets
  // (exact search: doubling steps, then bisection, all decided by orient3d;
  // the ulp box test is PlaneSide::meets_ulp_box, the same answer as
  // within_ulp_of_plane on two corners instead of eight).
  // Throws InternalError if F's normal has no component on that axis.
  Vec3 settle(Vec3 p, int axis) const;
  // Unit outward normal (a construction, for distances).
  Vec3 normal() const { return n_; }
  // Signed distance (construction): positive beyond the plane.
  double distance(Vec3 p) const { return dot(n_, p - a_); }

 private:
  int facet_ = -1;
  Vec3 a_, b_, c_, n_;
  PlaneSide side_;
};

}  // namespace pqmesh::tet3d
