#pragma once
// The polar frame of one (vertex V, edge E = VU) pair (thesis §5.1,
// "Continuous spiral": origin at V, phi = 0 along E, phi growing through the
// interior of P up to the other edge F at V).
//
// Handedness: loops keep the interior on their left (Domain2), so at V the
// interior sector runs counter-clockwise from V -> next(V) to V -> prev(V).
// For E = V -> next(V) phi grows counter-clockwise (ccw = true); for
// E = V -> prev(V) it grows clockwise and every orientation below is negated.
#include "pqmesh/domain.hpp"
#include "pqmesh/vec.hpp"
#include "predicates/predicates.hpp"

namespace pqmesh::detail {

struct SpiralFrame {
  int v = -1, u = -1, f = -1;  // V, U (other end of E), far end of F
  Vec2 V, U, F;
  bool ccw = true;
  double length = 0;           // L(E)
  double alpha = 0;            // interior angle at V, radians in (0, 2 pi)
  Sign turn = Sign::Positive;  // exact: Positive alpha < pi, Zero alpha = pi, Negative reflex

  // orient2d with this frame's handedness (exact).
  Sign oriented(Vec2 a, Vec2 b, Vec2 c) const { return ccw ? orient2d(a, b, c) : -orient2d(a, b, c); }
  // Exact: w lies in the closed interior sector at V (phi in [0, alpha]).
  bool in_sector(Vec2 w) const;
  // Floating point: the polar angle of w in [0, alpha] (clamped to the sector:
  // callers pass points already known to lie in it, up to rounding).
  double phi(Vec2 w) const;
  // A point of the frame's polar coordinates (rho, phi) in the plane.
  Vec2 point_at(double rho, double angle) const;
};

// The frame of V = loops[loop][k] with E towards next(V) (ccw) or prev(V).
SpiralFrame make_frame(const Domain2& domain, int loop, int k, bool ccw);

}  // namespace pqmesh::detail
