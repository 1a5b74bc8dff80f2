#pragma once
// The vertex fan bound (docs/algorithm/nosteiner2d.md "The fan bound"): an
// upper bound on the min angle of every triangulation of P whose vertices on
// dP are exactly P's vertices, from the fan of triangles each input vertex V
// must carry.
//
// At V (interior angle alpha, sides of lengths L1 and L2) the triangles at V
// fill the corner: k triangles with angles theta_1..theta_k at V summing to
// alpha, whose spokes (edges at V) run from the side of length L1 to the
// side of length L2. If every triangle has min angle >= A, then A <= theta_i
// <= pi - 2A, and the shorter / longer spoke ratio a_i of triangle i
// satisfies a_i >= sin A / sin(theta_i + A) (its angle opposite the shorter
// spoke is >= A); since the spoke ratios multiply up to L2 / L1,
//   ln R <= sum_i h_A(theta_i),  h_A(t) = ln(sin(t + A) / sin A),  R = max(L1, L2) / min(L1, L2),
// and h_A is concave, so the equal split theta_i = alpha / k is the best for
// a given k. fan_bound(alpha, R) is the largest A for which some integer k in
// [alpha / (pi - 2A), alpha / A] gives k h_A(alpha / k) >= ln R (the set of
// such A is an interval [0, A*]; bisection, the upper end of the final
// bracket returned). It is <= alpha and <= pi/3.
//
// Floating point throughout (a measurement like every angle of the module).
// Cost: O(log(1/precision) log k) per vertex; the obstacle term adds one
// bucket-grid query per (vertex, side) over the disk of the side's length.
#include "pqmesh/domain.hpp"

namespace pqmesh::detail {

// The largest possible min angle of a fan of total angle alpha in (0, 2 pi)
// whose end spokes have length ratio ratio >= 1 (radians, an upper bound on
// the true value within 1e-12 relative).
double fan_bound(double alpha, double ratio);

// The obstacle fan bound (docs/algorithm/nosteiner2d.md "The fan bound",
// obstacles): the largest min angle a fan from a side of length L can have
// when a point of dP lies in its corner at angle omega from that side and
// distance r < L (ratio = L / r): some spoke or the far edge of the
// triangle containing that direction passes within r, and the spoke ratios
// up to there obey the same h_A. An upper bound within 1e-12 relative.
double obstacle_fan_bound(double omega, double ratio);

struct FanBound {
  double angle = 0;  // min over input vertices of fan_bound(alpha_V, R_V), radians
  int vertex = -1;   // the vertex realising it (first minimum, loop order)
  // min over (V, side E at V, vertex q of dP in V's closed sector with |Vq| < |E|)
  // of obstacle_fan_bound(angle from E to Vq, |E| / |Vq|), radians.
  double obstacle_angle = 0;
  int obstacle_vertex = -1, obstacle = -1;  // V and q realising it
};

// The smallest fan bound over the vertices of the domain's loops (alpha_V by
// atan2 of the two sides, the exact corner class fixing the branch: convex,
// straight or reflex).
FanBound vertex_fan_bound(const Domain2& domain);

}  // namespace pqmesh::detail
