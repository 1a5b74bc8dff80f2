#pragma once
// Exact decisions for the shrink of Q to R (thesis §5.2, docs/DESIGN_RULES.md
// "Exact decisions"): the 3 pi / 4 test of the two vertex cases and the
// direction of a shrunk side. Both are evaluated on the exact binary values of
// the constructed doubles (GMP rationals), so they are decisions about the
// polygons as represented.
#include "pqmesh/vec.hpp"
#include "predicates/predicates.hpp"

namespace pqmesh::detail {

// Is the interior angle at v, measured counter-clockwise from v -> next to
// v -> prev (interior on the left of prev -> v -> next), at most 3 pi / 4?
// For an angle t in (0, pi): t <= 3 pi / 4  <=>  cos t + sin t >= 0, and
// |b||a| (cos t + sin t) = dot(b, a) + cross(b, a) with b = next - v,
// a = prev - v. Angles >= pi (cross <= 0, or straight) are never <= 3 pi / 4.
bool angle_at_most_three_quarter_pi(Vec2 prev, Vec2 v, Vec2 next);

// Sign of (b - a) . (d - c), exact.
Sign dot_sign_directions(Vec2 a, Vec2 b, Vec2 c, Vec2 d);

}  // namespace pqmesh::detail
