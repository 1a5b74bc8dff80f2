#pragma once
// The segment-triangle bound (docs/algorithm/nosteiner2d.md "The segment
// bound"): an upper bound on the min angle of every triangulation of P whose
// vertices on dP are exactly P's vertices, from the one triangle each input
// segment ab must carry.
//
// For a side ab (interior of P on its left, H the open left half-plane of
// line ab) and a point q of dP in H, let
//   t(q) = max(angle qab, angle qba).
// The triangle abp on ab in such a triangulation has an open interior that
// meets no point of dP, so for every such q its angle at a is <= angle qab
// or its angle at b is <= angle qba; hence its min angle is at most
//   t*(ab) = min(pi/3, inf over q of t(q)),
// and the bound is the smallest t*(ab) over all sides. The value is sharp
// per side: the isosceles triangle on ab with base angles t*(ab) is empty of
// dP and lies in P.
//
// The infimum is taken over candidate points that are on dP (every one gives
// a valid bound): the vertices in H, and for each side cd where the line cd
// crosses the perpendicular bisector of ab in H, that crossing (where the
// growing isosceles triangle first touches cd when the contact is not at an
// end of cd; contacts at a or b along an adjacent side give that corner's
// angle, covered by the alpha term of NoSteinerStats::upper_bound).
// Decisions on which side of ab a vertex lies are exact (orient2d); angles
// are floating point (atan2), like every angle of the module; a crossing is
// a constructed point, so its angle is raised by a bound on the effect of
// its rounding (segment_bound.cpp) and the value stays an upper bound.
//
// Cost: one bucket-grid query per side over the bounding square of the
// equilateral triangle on it (only points inside it can give t < pi/3);
// near O(n) on inputs whose sides are not much longer than their neighbours'.
#include <vector>

#include "pqmesh/domain.hpp"
#include "pqmesh/vec.hpp"

namespace pqmesh::detail {

struct SegmentBound {
  double angle = 0;           // min over sides of t*(side), radians, <= pi/3
  int loop = -1, side = -1;   // the side realising it (first minimum, loop order); -1 when pi/3
  Vec2 witness{};             // the point of dP realising it (when side >= 0)
  // t*(side) per loop, side k = loop[k] -> loop[k + 1].
  std::vector<std::vector<double>> side_angle;
};

SegmentBound segment_bound(const Domain2& domain);

// t(q) = max(angle qab, angle qba) for q strictly left of a -> b (radians).
double segment_apex_angle(Vec2 a, Vec2 b, Vec2 q);

}  // namespace pqmesh::detail
