#pragma once
// Interfering points of one (V, E) pair and the eligible part of each
// interfering face (thesis §5.1 "Interfere", Theorem 21's hypotheses).
//
// A closed face G of dP interferes with E when G and E are disjoint. In a
// valid Domain2 two sides meet only at shared endpoints, so this is decided
// combinatorially by vertex ids: a vertex W interferes iff W is neither V nor
// U, a side iff it has neither V nor U as an endpoint.
//
// The eligible region of (V, E) is
//   D = closed disk |VW| <= L(E)   (r <= 1: E is the longest spoke, Thm 21)
//   H = closed half-plane |VW| <= |UW|   (W closer to V, Thm 21)
//   S = closed interior sector of P at V (W lies in the sector of some
//       triangle of every wedge at V; the proof of Thm 21 starts from it)
// A vertex is tested exactly. A side is clipped to D, H and S: whether each
// endpoint lies in each region is exact; the crossing parameters are
// floating-point constructions (a reflex S is a union of two half-planes, so a
// side may give two pieces).
#include <vector>

#include "nosteiner2d/spiral_frame.hpp"

namespace pqmesh::detail {

// Exact: vertex w (its id is not V or U) is eligible for the frame.
bool eligible_vertex(const SpiralFrame& frame, Vec2 w);

// A sub-segment A + t (B - A), t in [t0, t1], of an interfering side.
struct SidePiece {
  double t0 = 0, t1 = 1;
};

// The eligible pieces of side a -> b (which must interfere with E).
std::vector<SidePiece> eligible_pieces(const SpiralFrame& frame, Vec2 a, Vec2 b);

// The cheap part for one piece: its point of smallest phi (omega) and a lower
// bound on q = ln(r) / phi over the piece (+inf when no point has r < 1).
struct PieceStart {
  Vec2 min_phi_point;
  double min_phi = 0;
  double q_lower = 0;
};
PieceStart piece_start(const SpiralFrame& frame, Vec2 a, Vec2 b, SidePiece piece);

// The point of smallest q on the piece (the smallest shrinking factor
// s = exp(q) of a continuous spiral through a point of the piece). Returns
// false when no point of the piece has q < 0 (r < 1).
bool piece_min_q(const SpiralFrame& frame, Vec2 a, Vec2 b, SidePiece piece, Vec2& point, double& q);

}  // namespace pqmesh::detail
